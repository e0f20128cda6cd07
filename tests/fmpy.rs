//! FMPy (the project's venv) validates every packed FMU and simulates the default
//! FMU with a speed-ramp input; the outputs must equal the Rust simulator's.
//! Needs the FMUs in out/ (scripts/test.sh runs fmu_pack.sh for each model).

mod common;

#[test]
fn fmpy_validates_and_matches_the_rust_simulator() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let exe = std::env::current_exe().unwrap();
    let reference = exe
        .parent()
        .unwrap()
        .parent()
        .unwrap()
        .join("examples/reference_run");
    assert!(
        reference.exists(),
        "{} missing: run `cargo build --examples` (scripts/test.sh does)",
        reference.display()
    );
    common::run_python(
        "tests/python/test_fmpy.py",
        &[root, &reference],
        &["out/RotorBearing.fmu"],
    );
}
