//! The FMI 3.0 FMUs of every shipped model under FMPy (the project's venv, tests/python/test_fmi3.py):
//! FMPy's validation passes and simulate_fmu runs them; under the same inputs
//! their outputs equal the FMI 2.0 FMUs' to the bit (one simulator underneath,
//! the FMI 3.0 layer translating only); an FMU state saved, serialized and
//! deserialized into a second instance continues the run to the bit; an FMI
//! 2.0 FMU's state is refused; the intermediate-update example of
//! docs/fmu.md runs in FMPy. Needs the FMUs in out/ (scripts/test.sh runs
//! `fmu_pack.sh --fmi 2,3` for every model).

mod common;

#[test]
fn fmi3_fmus_validate_and_match_the_fmi2_fmus_to_the_bit() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    // Every shipped model.
    let mut stems: Vec<String> = std::fs::read_dir(root.join("models"))
        .unwrap()
        .filter_map(|e| {
            let name = e.unwrap().file_name().to_string_lossy().into_owned();
            name.strip_suffix(".toml").map(str::to_string)
        })
        .collect();
    stems.sort();
    assert!(stems.len() >= 2, "{stems:?}");
    let mut args: Vec<&std::path::Path> = vec![root];
    args.extend(stems.iter().map(std::path::Path::new));
    common::run_python(
        "tests/python/test_fmi3.py",
        &args,
        &["out/RotorBearing_fmi3.fmu", "out/jeffcott_fmi3.fmu"],
    );
}

/// The intermediate-update example of docs/fmu.md, run as written through
/// FMPy's `FMU3Slave` (tests/python/test_fmi3_intermediate.py): the callback
/// is told of every internal step, the early return it asks for trips the
/// drive there, and what it read equals a plain run's bits.
#[test]
fn the_intermediate_update_example_runs_in_fmpy() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    common::run_python(
        "tests/python/test_fmi3_intermediate.py",
        &[root],
        &["out/jeffcott_fmi3.fmu"],
    );
}
