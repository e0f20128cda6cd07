//! Shared helper of the tests that drive Python tools in the project's venv.

use std::path::{Path, PathBuf};
use std::process::Command;

/// Run `.venv/bin/python SCRIPT ARGS…` from the repo root after checking that the
/// files it needs (relative to the root) exist; fails the test with its output.
pub fn run_python(script: &str, args: &[&Path], needs: &[&str]) -> String {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let python = root.join(".venv/bin/python");
    assert!(
        python.exists(),
        "{} missing: run scripts/python_env.sh",
        python.display()
    );
    for need in needs {
        assert!(
            root.join(need).exists(),
            "{need} missing: scripts/test.sh builds it"
        );
    }
    let out = Command::new(python)
        .arg(root.join(script))
        .args(args)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    eprintln!("{stdout}");
    let stderr: Vec<&str> = std::str::from_utf8(&out.stderr)
        .unwrap_or("")
        .lines()
        .filter(|l| !l.contains("[debug]") && !l.contains("[info]"))
        .collect();
    assert!(
        out.status.success(),
        "{script} failed:\n{stdout}\n{}",
        stderr.join("\n")
    );
    stdout
}
