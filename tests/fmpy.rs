//! FMPy (the project's venv) validates every packed FMU and simulates the default
//! FMU with a speed-ramp input; the outputs must equal the Rust simulator's.
//! Needs the FMUs in out/ (scripts/test.sh runs fmu_pack.sh for each model).

use std::path::PathBuf;
use std::process::Command;

#[test]
fn fmpy_validates_and_matches_the_rust_simulator() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let python = root.join(".venv/bin/python");
    assert!(
        python.exists(),
        "{} missing: run scripts/python_env.sh",
        python.display()
    );
    let exe = std::env::current_exe().unwrap();
    let reference = exe
        .parent()
        .unwrap()
        .parent()
        .unwrap()
        .join("examples/reference_run");
    assert!(
        reference.exists(),
        "{} missing: cargo test builds the examples",
        reference.display()
    );
    let out = Command::new(python)
        .arg(root.join("tests/python/test_fmpy.py"))
        .arg(&root)
        .arg(&reference)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    eprintln!("{stdout}");
    assert!(
        out.status.success(),
        "FMPy test failed:\n{stdout}\n{stderr}"
    );
}
