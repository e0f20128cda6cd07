//! The `rotor` command line, run as a user would.

use std::path::PathBuf;
use std::process::Command;

fn rotor() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rotor"))
}

fn out_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn campbell_writes_csv_and_png() {
    let dir = out_dir("campbell");
    let (csv, png) = (dir.join("campbell.csv"), dir.join("campbell.png"));
    let _ = std::fs::remove_file(&png);
    let out = rotor()
        .args([
            "campbell",
            "--max-rpm",
            "6000",
            "--steps",
            "12",
            "--modes",
            "6",
            "--csv",
        ])
        .arg(&csv)
        .arg("--png")
        .arg(&png)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // The first critical speeds of the classic rotor sit at ≈116.4 rad/s (1111 rpm).
    assert!(stdout.contains("1111."), "{stdout}");
    let text = std::fs::read_to_string(&csv).unwrap();
    assert_eq!(text.lines().count(), 1 + 13 * 6);
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    assert!(
        bytes.len() > 10_000,
        "PNG suspiciously small: {} bytes",
        bytes.len()
    );
}

#[test]
fn modes_of_a_model_file() {
    let model = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/classic_disk_rotor.toml");
    let out = rotor()
        .arg("modes")
        .arg(&model)
        .args(["--rpm", "4000", "--modes", "4"])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        stdout.contains("437.3") && stdout.contains("488.7"),
        "{stdout}"
    );
    assert!(
        stdout.contains("backward") && stdout.contains("forward"),
        "{stdout}"
    );
}

#[test]
fn bad_model_file_gives_a_clear_error_and_exit_code() {
    let dir = out_dir("bad_model");
    let path = dir.join("bad.toml");
    let text =
        rotor_bearing::model::DEFAULT_MODEL_TOML.replace("density = 7810.0", "density = -1.0");
    std::fs::write(&path, text).unwrap();
    let out = rotor().arg("static").arg(&path).output().unwrap();
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("bad.toml:") && stderr.contains("materials[0].density = -1"),
        "{stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
}

#[test]
fn static_and_info_run_on_every_shipped_model() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models");
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        for cmd in ["info", "modes"] {
            let out = rotor().arg(cmd).arg(&path).output().unwrap();
            assert!(
                out.status.success(),
                "{cmd} {}: {}",
                path.display(),
                String::from_utf8_lossy(&out.stderr)
            );
        }
    }
}
