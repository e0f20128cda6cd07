//! The `rotor` command line, run as a user would.

use std::path::PathBuf;
use std::process::{Command, Stdio};

use rotor_bearing::model::RotorModel;

fn rotor() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rotor"))
}

/// The stdout of `command`, which must succeed (its stderr in the panic otherwise).
fn succeeded(command: &mut Command) -> String {
    let out = command.output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
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
    let stdout = succeeded(
        rotor()
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
            .arg(&png),
    );
    // The first critical speeds of the classic rotor sit at ≈116.4 rad/s (1111 rpm).
    assert!(stdout.contains("1111."), "{stdout}");
    assert!(
        stdout.contains(
            "speed grid of classic_disk_rotor: 0.00 to 6000.00 rpm in 12 steps (top speed: --max-rpm)"
        ),
        "{stdout}"
    );
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
    let stdout = succeeded(
        rotor()
            .arg("modes")
            .arg(&model)
            .args(["--rpm", "4000", "--modes", "4"]),
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
        // Fluid-film bearings need speed to carry load: the model's nominal
        // speed, else 3000 rpm.
        let nominal =
            RotorModel::from_file(&path).unwrap().nominal_speed * 30.0 / std::f64::consts::PI;
        let rpm = if nominal > 0.0 { nominal } else { 3000.0 }.to_string();
        let speed = ["--rpm", rpm.as_str()];
        for cmd in ["info", "static", "modes"] {
            let out = rotor()
                .arg(cmd)
                .arg(&path)
                .args(if cmd == "info" { &[][..] } else { &speed[..] })
                .output()
                .unwrap();
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert!(out.status.success(), "{cmd} {}: {stderr}", path.display());
            // Shipped models are plausible: no unit-slip warning (the
            // short film's validity warning, issue 47, is not one: the
            // Jeffcott and hydro bearings are longer than the short film's
            // range, and it says so).
            let plausibility = stderr
                .lines()
                .filter(|l| l.contains("warning:") && !l.contains("short film at"))
                .count();
            assert!(plausibility == 0, "{cmd} {}: {stderr}", path.display());
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
        + "\n[[bearings]]\nname = \"guide\"\ntype = \"tilting_pad\"\nnode = 4\nradius = 0.05\njournal_collar = true\nlength = 0.03\nclearance = 1e-4\nviscosity = 0.02\npads = 4\nfirst_pivot_deg = 45.0\npad_arc_deg = 80.0\n";
    std::fs::write(&path, text).unwrap();
    let stdout = succeeded(rotor().arg("coefficients").arg(&path).args([
        "--bearing",
        "guide",
        "--points",
        "12",
    ]));
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

/// Run `rotor simulate ARGS --plots DIR/NAME`; returns stdout and stderr.
fn simulate_with_plots(args: &[&str], name: &str) -> (String, String) {
    let prefix = out_dir("windows").join(name);
    let out = rotor()
        .arg("simulate")
        .args(args)
        .arg("--plots")
        .arg(&prefix)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "{args:?}: {stderr}");
    (String::from_utf8_lossy(&out.stdout).into_owned(), stderr)
}

/// The window table `rotor simulate --plots` prints: per window start_s, end_s,
/// revolutions, speed_rpm, dominant_Hz, ratio, amplitude_um, subsync_share.
fn window_table(stdout: &str) -> Vec<Vec<f64>> {
    stdout
        .lines()
        .skip_while(|l| !l.starts_with("window"))
        .skip(1)
        .take_while(|l| {
            l.split_whitespace()
                .next()
                .is_some_and(|w| w.parse::<usize>().is_ok())
        })
        .map(|l| {
            l.split_whitespace()
                .skip(1)
                .map(|v| v.parse().unwrap())
                .collect()
        })
        .collect()
}

#[test]
fn simulate_reports_a_pure_synchronous_response_as_one_times_running_speed() {
    // (model, rpm, duration s, step s, windows): 25, 28.2, 20 and 20.75 revolutions.
    for (model, rpm, duration, step, windows) in [
        ("jeffcott.toml", "3000", "0.5", "1e-4", 2),
        ("jeffcott.toml", "1500", "0.8", "1e-4", 1),
        ("jeffcott.toml", "1234", "1.37", "7e-5", 2),
        ("hydro_unit.toml", "150", "8.3", "1e-3", 2),
    ] {
        let model = models().join(model);
        let (stdout, _) = simulate_with_plots(
            &[
                model.to_str().unwrap(),
                "--rpm",
                rpm,
                "--duration",
                duration,
                "--step",
                step,
            ],
            "synchronous",
        );
        assert!(
            stdout.contains("spectra of probe "),
            "the table names the probe: {stdout}"
        );
        let rows = window_table(&stdout);
        assert_eq!(rows.len(), windows, "{stdout}");
        let f_spin = rpm.parse::<f64>().unwrap() / 60.0;
        for row in &rows {
            assert!(row[2] >= 20.0, "{stdout}");
            assert!((row[3] - f_spin * 60.0).abs() < 0.05, "{stdout}");
            assert!((row[4] - f_spin).abs() < 0.01 * f_spin, "{stdout}");
            assert!(
                (row[5] - 1.0).abs() <= 0.01,
                "{model:?} {rpm} rpm: {stdout}"
            );
        }
    }
}

#[test]
fn simulate_reports_oil_whirl_at_half_speed_with_the_sweeps_share() {
    // The Jeffcott rotor at 9000 rpm, above its oil-whirl threshold (≈ 8800 rpm):
    // 90 revolutions, ⌈70/10⌉ + 1 = 8 windows.
    let dir = out_dir("whirl");
    let csv = dir.join("whirl.csv");
    let (stdout, _) = simulate_with_plots(
        &[
            models().join("jeffcott.toml").to_str().unwrap(),
            "--rpm",
            "9000",
            "--duration",
            "0.6",
            // Outputs on a 0.1 ms grid: the windows' six-decimal times
            // select the same samples in sweep.py.
            "--step",
            "1e-4",
            "--csv",
            csv.to_str().unwrap(),
        ],
        "whirl",
    );
    let rows = window_table(&stdout);
    assert_eq!(rows.len(), 8, "{stdout}");
    let last = &rows[7];
    assert!((last[5] - 0.5).abs() <= 0.01, "{stdout}");
    assert!((last[4] - 75.0).abs() < 0.75, "{stdout}");
    assert!(last[7] > 0.99, "{stdout}");
    // The same windows of the CSV through system/sweep.py's whirl_metrics.
    let windows: Vec<String> = rows.iter().map(|r| format!("{}:{}", r[0], r[1])).collect();
    let script = r#"
import sys
import numpy as np
sys.path.insert(0, "system")
from sweep import whirl_metrics
d = np.genfromtxt(sys.argv[1], delimiter=",", names=True)
t = d["time_s"]
for w in sys.argv[2:]:
    a, b = (float(v) for v in w.split(":"))
    k = (t >= a - 1e-7) & (t <= b + 1e-7)
    m = whirl_metrics(t[k], d["disk_x_m"][k], d["disk_y_m"][k], d["speed_rpm"][k].mean() / 60.0)
    print(repr(m["subsync_share"]))
"#;
    let shares = python(script, &[csv.to_str().unwrap()], &windows);
    assert_eq!(shares.len(), rows.len());
    for (row, py) in rows.iter().zip(&shares) {
        // The table prints six decimals.
        assert!(
            (row[7] - py).abs() <= 5.1e-7,
            "CLI {} vs sweep.py {py}",
            row[7]
        );
    }
}

/// Run `.venv/bin/python -c SCRIPT ARGS…` from the repo root; its stdout as numbers.
fn python(script: &str, args: &[&str], more: &[String]) -> Vec<f64> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let python = root.join(".venv/bin/python");
    assert!(
        python.exists(),
        "{} missing: run scripts/python_env.sh",
        python.display()
    );
    let out = Command::new(python)
        .current_dir(&root)
        .arg("-c")
        .arg(script)
        .args(args)
        .args(more)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|l| l.parse().unwrap())
        .collect()
}

#[test]
fn subsynchronous_share_is_the_sweeps_definition() {
    use rotor_bearing::analysis::spectrum::subsynchronous_share;
    use std::f64::consts::PI;
    use std::fmt::Write;
    // 1× forward 10 µm, 0.43× backward 6 µm, 0.2× forward 3 µm, 2× 2 µm, an
    // offset and a slow drift; 3001 samples every 0.17 ms at 37.3 Hz running speed.
    let spin = 37.3;
    let t: Vec<f64> = (0..3001).map(|k| 0.02 + k as f64 * 1.7e-4).collect();
    let circle = |t: f64, order: f64, r: f64| {
        let p = 2.0 * PI * order * spin * t;
        (r * p.cos(), r * p.sin())
    };
    let (mut x, mut y) = (Vec::new(), Vec::new());
    for &t in &t {
        let parts = [
            circle(t, 1.0, 1e-5),
            circle(t, -0.43, 6e-6),
            circle(t, 0.2, 3e-6),
            circle(t, 2.0, 2e-6),
            (3e-6 + 1e-6 * t, -2e-6),
        ];
        x.push(parts.iter().map(|p| p.0).sum::<f64>());
        y.push(parts.iter().map(|p| p.1).sum::<f64>());
    }
    let rust = subsynchronous_share(&t, &x, &y, spin);
    assert!(rust > 0.2 && rust < 0.5, "{rust}");
    let csv = out_dir("share").join("orbit.csv");
    let mut text = String::from("time_s,x_m,y_m\n");
    for k in 0..t.len() {
        writeln!(text, "{:e},{:e},{:e}", t[k], x[k], y[k]).unwrap();
    }
    std::fs::write(&csv, text).unwrap();
    let script = r#"
import sys
import numpy as np
sys.path.insert(0, "system")
from sweep import whirl_metrics
d = np.genfromtxt(sys.argv[1], delimiter=",", names=True)
print(repr(whirl_metrics(d["time_s"], d["x_m"], d["y_m"], float(sys.argv[2]))["subsync_share"]))
"#;
    let py = python(script, &[csv.to_str().unwrap(), &format!("{spin:e}")], &[]);
    assert!(
        (rust - py[0]).abs() < 1e-9,
        "Rust {rust} vs sweep.py {}",
        py[0]
    );
}

#[test]
fn simulate_refuses_a_ratio_for_a_run_under_twenty_revolutions() {
    // 3000 rpm for 0.3 s: 15 revolutions.
    let prefix = out_dir("windows").join("short");
    let png = PathBuf::from(format!("{}_waterfall.png", prefix.display()));
    let _ = std::fs::remove_file(&png);
    let (stdout, stderr) = simulate_with_plots(
        &[
            models().join("jeffcott.toml").to_str().unwrap(),
            "--rpm",
            "3000",
            "--duration",
            "0.3",
        ],
        "short",
    );
    assert!(
        stdout.contains("too short: 15.0 revolutions < 20: no frequency ratio"),
        "{stdout}"
    );
    assert!(window_table(&stdout).is_empty(), "{stdout}");
    assert!(
        stderr.contains("warning: too short: 15.0 revolutions < 20"),
        "{stderr}"
    );
    assert!(!png.exists());
}

#[test]
fn campbell_refines_a_grid_too_coarse_to_follow_the_modes() {
    // One step from 0 to 20 000 rpm links the second backward mode's branch
    // to the second forward mode: its 4705.44 rpm found twice, the backward
    // 4165.40 rpm missed. The study doubles the steps to 8 and says so.
    let stdout = succeeded(rotor().args(["campbell", "--max-rpm", "20000", "--steps", "1"]));
    assert!(
        stdout.contains(
            "speed grid of classic_disk_rotor: 0.00 to 20000.00 rpm in 8 steps (top speed: --max-rpm)\n  (refined from the 1 step asked for: a mode was not followed across a step)"
        ),
        "{stdout}"
    );
    assert_eq!(stdout.matches("4705.44 rpm (").count(), 1, "{stdout}");
    assert!(
        stdout.contains("4165.40 rpm (  436.200 rad/s)  branch 4  backward whirl"),
        "{stdout}"
    );
    assert!(!stdout.contains("warning"), "{stdout}");
}

#[test]
fn campbell_lists_overdamped_crossings_apart_from_critical_speeds() {
    // The Jeffcott rotor's rigid-body modes on the films cross the 1× line at
    // 419 rpm with ζ = 0.82: overdamped, no resonance peak.
    let csv = out_dir("campbell_jeffcott").join("c.csv");
    let stdout = succeeded(
        rotor()
            .arg("campbell")
            .arg(models().join("jeffcott.toml"))
            .arg("--csv")
            .arg(&csv),
    );
    // Default top speed 1.25 × speed_rpm 3000; fluid films from 1 % of it.
    assert!(
        stdout.contains(
            "speed grid of jeffcott: 37.50 to 3750.00 rpm in 40 steps (top speed: 1.25 × the model's speed_rpm 3000; fluid-film bearings: from 1 % of the top speed)"
        ),
        "{stdout}"
    );
    let zeta = |line: &str| -> f64 { line.rsplit("ζ = ").next().unwrap().parse().unwrap() };
    let (critical, overdamped) = stdout.split_once("overdamped crossings").unwrap();
    let critical: Vec<&str> = critical.lines().filter(|l| l.contains("ζ = ")).collect();
    let overdamped: Vec<&str> = overdamped.lines().filter(|l| l.contains("ζ = ")).collect();
    assert!(critical.iter().all(|l| zeta(l) < 0.5), "{stdout}");
    assert!(overdamped.iter().all(|l| zeta(l) >= 0.5), "{stdout}");
    assert!(
        critical
            .iter()
            .any(|l| l.contains("2675.11 rpm") && l.contains("ζ = 3.156e-1")),
        "{stdout}"
    );
    assert!(
        overdamped
            .iter()
            .any(|l| l.contains("419.27 rpm") && l.contains("ζ = 8.182e-1")),
        "{stdout}"
    );
}

#[test]
fn campbell_default_top_speed_follows_the_model() {
    let dir = out_dir("campbell_range");
    let base = rotor_bearing::model::DEFAULT_MODEL_TOML;
    let cases = [
        (
            base.to_string(),
            "0.00 to 1250.00 rpm in 40 steps (top speed: 1.25 × the model's speed_rpm 1000)",
        ),
        (
            base.replace("speed_rpm = 1000", "speed_rpm = 1000\nmax_speed_rpm = 2000"),
            "0.00 to 2500.00 rpm in 40 steps (top speed: 1.25 × the model's max_speed_rpm 2000)",
        ),
        (
            base.replace("speed_rpm = 1000", ""),
            "0.00 to 4000.00 rpm in 40 steps (top speed: the model states neither max_speed_rpm nor speed_rpm)",
        ),
    ];
    for (k, (text, grid)) in cases.iter().enumerate() {
        let path = dir.join(format!("m{k}.toml"));
        std::fs::write(&path, text).unwrap();
        let out = rotor()
            .arg("campbell")
            .arg(&path)
            .args(["--modes", "2", "--csv"])
            .arg(dir.join("c.csv"))
            .output()
            .unwrap();
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(
            stdout.contains(&format!("speed grid of classic_disk_rotor: {grid}")),
            "{stdout}"
        );
        // The classic rotor's first critical speeds (1111 rpm) are inside every range.
        assert!(stdout.contains("1111."), "{stdout}");
    }
}

#[test]
fn implausible_values_are_warned_by_every_command() {
    let dir = out_dir("plausibility");
    let path = dir.join("cst.toml");
    let text = std::fs::read_to_string(models().join("jeffcott.toml"))
        .unwrap()
        .replacen("viscosity = 0.02 ", "viscosity = 32.0 ", 1);
    std::fs::write(&path, text).unwrap();
    let model = path.to_str().unwrap();
    let stage = dir.join("stage");
    let csv = dir.join("out.csv");
    let csv = csv.to_str().unwrap();
    let commands: [&[&str]; 7] = [
        &["info", model],
        &["static", model, "--rpm", "3000"],
        &["modes", model, "--rpm", "3000", "--modes", "2"],
        &[
            "campbell", model, "--steps", "1", "--modes", "2", "--csv", csv,
        ],
        &["coefficients", model, "--points", "3", "--csv", csv],
        &[
            "simulate",
            model,
            "--rpm",
            "3000",
            "--duration",
            "0.001",
            "--csv",
            csv,
        ],
        &["fmu-stage", model, stage.to_str().unwrap()],
    ];
    let expected = format!(
        "warning: {model}: bearings[0].viscosity = 32: dynamic viscosity outside the plausible 1e-4 to 1 Pa·s"
    );
    for args in commands {
        let out = rotor().args(args).output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(&expected), "{args:?}: {stderr}");
    }
}

/// `simulate` says which rotor it runs on; `--reduced-modes` runs the
/// Craig–Bampton rotor (the disk, where the unbalance and probe are, kept
/// physical) and its disk orbit ends within 1 % of the full model's; a
/// `[reduction]` section in the model selects it without the flag, and
/// `--reduced-modes 0` forces the full rotor.
#[test]
fn simulate_says_which_rotor_runs_and_reduces_on_request() {
    let dir = out_dir("reduced_cli");
    let damped = models().join("classic_disk_rotor_damped.toml");
    let run = |model: &std::path::Path, extra: &[&str], name: &str| {
        let csv = dir.join(name);
        let out = rotor()
            .args([
                "simulate",
                model.to_str().unwrap(),
                "--rpm",
                "1000",
                "--duration",
                "0.3",
            ])
            .args(["--csv", csv.to_str().unwrap()])
            .args(extra)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr).to_string();
        assert!(out.status.success(), "{stderr}");
        (stderr, last_probe(&csv))
    };
    let (stderr, full) = run(&damped, &[], "full.csv");
    assert!(stderr.contains("full rotor: 28 DOFs"), "{stderr}");
    let (stderr, reduced) = run(&damped, &["--reduced-modes", "10"], "reduced.csv");
    assert!(
        stderr.contains("reduced rotor (Craig–Bampton): 14 coordinates for 28 DOFs — 4 physical at nodes 4 + 10 fixed-interface modes up to 1113.5 Hz"),
        "{stderr}"
    );
    let radius = full.0.hypot(full.1);
    let d = (full.0 - reduced.0).hypot(full.1 - reduced.1);
    assert!(
        radius > 1e-6 && d < 0.01 * radius,
        "{d:e} against {radius:e}"
    );

    let text = std::fs::read_to_string(&damped).unwrap();
    let with_section = dir.join("with_reduction.toml");
    std::fs::write(&with_section, format!("{text}\n[reduction]\nmodes = 10\n")).unwrap();
    let (stderr, again) = run(&with_section, &[], "section.csv");
    assert!(stderr.contains("14 coordinates for 28 DOFs"), "{stderr}");
    assert_eq!(again, reduced);
    let (stderr, forced) = run(&with_section, &["--reduced-modes", "0"], "forced.csv");
    assert!(stderr.contains("full rotor: 28 DOFs"), "{stderr}");
    assert_eq!(forced, full);
}

/// Issue 22: a size no machine has (a disk 1e300 m wide) stops every command
/// with the file, line, field, value and range, and a non-zero exit; none
/// prints a NaN (`rotor static` printed a table of NaN and exited 0).
#[test]
fn absurd_sizes_stop_every_command() {
    let dir = out_dir("absurd");
    let path = dir.join("wide.toml");
    let text = std::fs::read_to_string(models().join("jeffcott.toml")).unwrap();
    let text = format!(
        "{text}\n[[disks]]\nname = \"ring\"\nnode = 3\nmaterial = \"steel\"\nouter_diameter = 0.3\nwidth = 1e300\n"
    );
    let line = text.lines().position(|l| l == "width = 1e300").unwrap() + 1;
    std::fs::write(&path, text).unwrap();
    let model = path.to_str().unwrap();
    let file = |name: &str| dir.join(name).to_str().unwrap().to_string();
    let (png, csv, html, stage) = (file("x.png"), file("x.csv"), file("x.html"), file("stage"));
    let commands: [&[&str]; 13] = [
        &["info", model],
        &["draw", model, "--png", &png],
        &["static", model],
        &["modes", model, "--rpm", "3000"],
        &["campbell", model, "--steps", "2"],
        &["coefficients", model, "--points", "3"],
        &["simulate", model, "--rpm", "3000", "--duration", "0.01"],
        &["unbalance", model, "--points", "3"],
        &["operating-point", model, "--rpm", "3000", "--csv", &csv],
        &["ucs", model, "--points", "3"],
        &["stability", model, "--rpm", "3000", "--points", "3"],
        &["report", model, "--rpm", "3000", "--out", &html],
        &["fmu-stage", model, &stage],
    ];
    let expected = format!("{model}:{line}: disks[1].width = 1e300: must lie in [1e-6, 1000] m");
    for args in commands {
        let out = rotor().args(args).output().unwrap();
        let (stdout, stderr) = (
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr),
        );
        assert!(!out.status.success(), "{args:?} exited 0: {stdout}");
        assert!(stderr.contains(&expected), "{args:?}: {stderr}");
        assert!(!stdout.to_lowercase().contains("nan"), "{args:?}: {stdout}");
    }
}

/// Issue 22: a reduced run says how far it is from the full rotor at its top
/// speed, and warns when the speed leaves the validated range (a tenth of
/// the highest kept mode). The hydro unit on one mode (22.2 Hz) at 2.4 times
/// that mode ran silently, 210 % off.
#[test]
fn simulate_on_a_reduced_rotor_estimates_its_error_and_warns_outside_its_range() {
    let dir = out_dir("reduced_range");
    let hydro = models().join("hydro_unit.toml");
    let run = |rpm: &str, modes: &str| {
        let out = rotor()
            .args(["simulate", hydro.to_str().unwrap(), "--rpm", rpm])
            .args([
                "--duration",
                "0.05",
                "--step",
                "1e-3",
                "--reduced-modes",
                modes,
            ])
            .args(["--csv", dir.join("x.csv").to_str().unwrap()])
            .output()
            .unwrap();
        assert!(out.status.success());
        String::from_utf8_lossy(&out.stderr).to_string()
    };
    let stderr = run("150", "10");
    assert!(
        stderr.contains("reduced rotor at the top speed 150 rpm: at 2.5 Hz its response at the kept nodes differs from the full rotor's by")
            // No warning but the short film's validity (issue 47).
            && !stderr
                .lines()
                .any(|l| l.contains("warning") && !l.contains("short film at")),
        "{stderr}"
    );
    let stderr = run("3197", "1");
    assert!(
        stderr.contains("warning: hydro_unit: top speed 3197 rpm: the running speed 3197 rpm (53.3 Hz) is above the 2.2 Hz (133 rpm) the reduced rotor is validated for"),
        "{stderr}"
    );
    let estimate: f64 = stderr
        .split("differs from the full rotor's by ")
        .nth(1)
        .and_then(|s| s.split_whitespace().next())
        .and_then(|s| s.parse().ok())
        .unwrap();
    assert!(estimate > 0.1, "{stderr}");
}
