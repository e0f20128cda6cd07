//! The rotor-bearing FMU coupled to a governor/turbine/generator FMU (pythonfmu)
//! by libcosim (libcosimpy): start-up, load rejection and a run-up through a
//! critical speed, checked for physics (system/test_coupled.py).

mod common;

#[test]
fn coupled_plant_and_rotor_behave_physically() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    common::run_python(
        "system/test_coupled.py",
        &[root],
        &["out/HydroPlant.fmu", "out/RotorBearing.fmu"],
    );
}
