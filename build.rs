//! Build script: tells Cargo which inputs outside `src/` the crate embeds.
//! The FMI interface is generated the other way round — `modelDescription.xml`
//! comes from the variable table in `src/fmu/variables/`, and the test
//! `tests/fmu.rs` proves the file at the repo root is exactly that output.
//!
//! It also records the source tree's `git describe --always --dirty --tags`
//! as `ROTOR_GIT_DESCRIBE` (empty outside git), the version a signed report
//! states; the HEAD, the ref it names and the index trigger a rerun.

use std::process::Command;

fn git(args: &[&str]) -> Option<String> {
    let out = Command::new("git").args(args).output().ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// Rerun when `path` changes; a missing file is left out (Cargo would rerun
/// the script at every build).
fn watch(path: &str) {
    if std::path::Path::new(path).exists() {
        println!("cargo:rerun-if-changed={path}");
    }
}

fn main() {
    println!("cargo:rerun-if-changed=models/classic_disk_rotor.toml");
    println!("cargo:rerun-if-changed=modelDescription.xml");
    let described = git(&["describe", "--always", "--dirty", "--tags"]).unwrap_or_default();
    println!("cargo:rustc-env=ROTOR_GIT_DESCRIBE={described}");
    if let Some(dir) = git(&["rev-parse", "--absolute-git-dir"]) {
        watch(&format!("{dir}/HEAD"));
        watch(&format!("{dir}/index"));
        if let Some(head) = git(&["symbolic-ref", "-q", "HEAD"]) {
            let common = git(&["rev-parse", "--path-format=absolute", "--git-common-dir"])
                .unwrap_or(dir.clone());
            watch(&format!("{common}/{head}"));
            watch(&format!("{common}/packed-refs"));
        }
    }
}
