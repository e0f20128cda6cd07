//! The `rotor` command line, run as a user would.

use std::path::PathBuf;
use std::process::{Command, Stdio};

fn rotor() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rotor"))
}

fn models() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models")
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
        for cmd in ["info", "static", "modes"] {
            // Fluid-film bearings need speed to carry load.
            let out = rotor()
                .arg(cmd)
                .arg(&path)
                .args(if cmd == "info" {
                    &[][..]
                } else {
                    &["--rpm", "3000"][..]
                })
                .output()
                .unwrap();
            assert!(
                out.status.success(),
                "{cmd} {}: {}",
                path.display(),
                String::from_utf8_lossy(&out.stderr)
            );
        }
    }
}

#[test]
fn bearing_coefficients_table_csv_and_png() {
    let dir = out_dir("coefficients");
    let (csv, png) = (dir.join("coef.csv"), dir.join("coef.png"));
    let out = rotor()
        .args(["coefficients", "--points", "25", "--csv"])
        .arg(&csv)
        .arg("--png")
        .arg(&png)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&csv).unwrap();
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 25);
    // Interpolate K̄xx and C̄yy at ε = 0.58646 (reference equilibrium: 2.1081, 6.6230).
    let eps = 0.586_462_858;
    let i = rows.iter().position(|r| r[1] > eps).unwrap();
    let (a, b) = (&rows[i - 1], &rows[i]);
    let t = (eps - a[1]) / (b[1] - a[1]);
    let lerp = |k: usize| a[k] + t * (b[k] - a[k]);
    assert!((lerp(3) - 2.1081).abs() < 0.01, "K̄xx {}", lerp(3));
    assert!((lerp(10) - 6.6230).abs() < 0.05, "C̄yy {}", lerp(10));
    assert_eq!(&std::fs::read(&png).unwrap()[..4], b"\x89PNG");
}

#[test]
fn coefficients_of_a_tilting_pad_bearing_in_a_model() {
    let dir = out_dir("tilting_model");
    let path = dir.join("tp.toml");
    let text = rotor_bearing::model::DEFAULT_MODEL_TOML.to_string()
        + "\n[[bearings]]\nname = \"guide\"\ntype = \"tilting_pad\"\nnode = 4\nradius = 0.05\nlength = 0.03\nclearance = 1e-4\nviscosity = 0.02\npads = 4\nfirst_pivot_deg = 45.0\npad_arc_deg = 80.0\n";
    std::fs::write(&path, text).unwrap();
    let out = rotor()
        .arg("coefficients")
        .arg(&path)
        .args(["--bearing", "guide", "--points", "12"])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // Load between pads: no cross-coupled stiffness (columns 4 and 5 of the table).
    for line in stdout.lines().skip(2) {
        let v: Vec<f64> = line
            .split_whitespace()
            .map(|x| x.parse().unwrap())
            .collect();
        assert!(
            v[3].abs() < 1e-3 * v[2] && v[4].abs() < 1e-3 * v[2],
            "{line}"
        );
    }
    let missing = rotor()
        .arg("coefficients")
        .arg(&path)
        .args(["--bearing", "nope"])
        .output()
        .unwrap();
    assert!(!missing.status.success());
    assert!(String::from_utf8_lossy(&missing.stderr).contains("\"nope\""));
}

#[test]
fn simulate_follows_a_speed_table_and_reports_a_bad_line() {
    let dir = out_dir("speed_table");
    let table = dir.join("speed.csv");
    std::fs::write(&table, "time_s,speed_rpm\n# hold\n0,1200\n0.05,1200\n").unwrap();
    let csv = dir.join("sim.csv");
    let out = rotor()
        .args([
            "simulate",
            "--duration",
            "0.01",
            "--step",
            "1e-3",
            "--speed-csv",
        ])
        .arg(&table)
        .arg("--csv")
        .arg(&csv)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&csv).unwrap();
    let rows: Vec<&str> = text.lines().skip(1).collect();
    assert_eq!(rows.len(), 11);
    for row in rows {
        let rpm: f64 = row.split(',').nth(1).unwrap().parse().unwrap();
        assert!((rpm - 1200.0).abs() < 1e-9, "{row}");
    }

    std::fs::write(&table, "time_s,speed_rpm\n0,1200\n0.05;1200\n").unwrap();
    let out = rotor()
        .args(["simulate", "--duration", "0.01", "--speed-csv"])
        .arg(&table)
        .output()
        .unwrap();
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("speed.csv:3: expected two numbers time_s,speed_rpm, got \"0.05;1200\""),
        "{stderr}"
    );
}

#[test]
fn info_reads_like_engineering_units() {
    let out = rotor()
        .arg("info")
        .arg(models().join("jeffcott.toml"))
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    // jeffcott.toml: R = 20 mm, L = 20 mm, C = 100 µm, μ = 0.02 Pa·s, gravity −9.81 along y.
    assert!(
        text.contains("bearing left at node 1: plain short bearing, R = 20 mm, L = 20 mm, radial clearance C = 100 µm, μ = 0.02 Pa·s"),
        "{text}"
    );
    assert!(text.contains("gravity (0, -9.81, 0) m/s²"), "{text}");
    assert!(
        !text.contains("PlainBearing {") && !text.contains("0000000"),
        "{text}"
    );
}

#[test]
fn a_closed_pipe_ends_the_cli_quietly() {
    use std::io::Read;
    // 4000 coefficient rows (about 350 kB) overflow the 64 kB pipe buffer.
    let mut child = rotor()
        .args(["coefficients", "--points", "4000"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Read one byte, then close the pipe: the rest of the output has nowhere to go.
    let mut stdout = child.stdout.take().unwrap();
    let mut byte = [0u8; 1];
    stdout.read_exact(&mut byte).unwrap();
    drop(stdout);
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        !stderr.contains("panicked") && !stderr.contains("Broken pipe"),
        "{stderr}"
    );
}

/// The last row of a `simulate --csv` run: probe `disk` x and y (m).
fn last_probe(csv: &std::path::Path) -> (f64, f64) {
    let text = std::fs::read_to_string(csv).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let col = |name: &str| {
        header
            .iter()
            .position(|h| *h == name)
            .unwrap_or_else(|| panic!("{name} in {header:?}"))
    };
    let (x, y) = (col("disk_x_m"), col("disk_y_m"));
    let last: Vec<f64> = text
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|v| v.parse().unwrap())
        .collect();
    (last[x], last[y])
}

#[test]
fn a_run_without_settling_starts_from_consistent_accelerations() {
    // The classic rotor released from rest at its undeflected position under
    // gravity: with consistent initial accelerations Newmark converges at second
    // order (halving the step quarters the error); a zero start is first order.
    let dir = out_dir("no_settle");
    let run = |step: &str| {
        let csv = dir.join(format!("run_{step}.csv"));
        let out = rotor()
            .args([
                "simulate",
                "--rpm",
                "0",
                "--no-settle",
                "--duration",
                "0.0125",
            ])
            .args(["--step", step, "--output-step", "0.0125", "--csv"])
            .arg(&csv)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        last_probe(&csv)
    };
    let (a, b, c) = (run("0.0004"), run("0.0002"), run("0.0001"));
    let coarse = ((a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)).sqrt();
    let fine = ((b.0 - c.0).powi(2) + (b.1 - c.1).powi(2)).sqrt();
    let order = (coarse / fine).log2();
    assert!(
        order > 1.7,
        "observed order {order:.2} (differences {coarse:e}, {fine:e})"
    );
}
