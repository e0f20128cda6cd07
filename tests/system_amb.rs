//! Issue 24, acceptance 3: a PD magnetic bearing (a pythonfmu FMU) closed
//! through the rotor FMU's force port under libcosim reproduces the same
//! rotor with the bearing built in, within a bound derived from the
//! communication step that halves with it; and the communication steps at
//! which the loop stays stable (system/test_amb.py).

mod common;

#[test]
fn magnetic_bearing_through_the_port_matches_the_built_in_bearing() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    common::run_python(
        "system/test_amb.py",
        &[root],
        &[
            "out/AmbController.fmu",
            "out/classic_disk_rotor_amb.fmu",
            "out/classic_disk_rotor_amb_reference.fmu",
            "out/classic_disk_rotor_damped.fmu",
        ],
    );
}
