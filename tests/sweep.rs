//! The Dask sweep tool (system/sweep.py): a 2-worker LocalCluster gives exactly
//! the serial numbers, and a failing point is reported in the table.

use std::path::PathBuf;
use std::process::Command;

#[test]
fn dask_sweep_matches_serial_and_reports_failures() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let python = root.join(".venv/bin/python");
    assert!(
        python.exists(),
        "{} missing: run scripts/python_env.sh",
        python.display()
    );
    assert!(
        root.join("out/jeffcott.fmu").exists(),
        "out/jeffcott.fmu missing: scripts/test.sh packs it"
    );
    let out = Command::new(python)
        .arg(root.join("system/test_sweep.py"))
        .arg(&root)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    eprintln!("{stdout}");
    assert!(
        out.status.success(),
        "sweep checks failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
