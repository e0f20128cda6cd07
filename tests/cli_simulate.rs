//! `rotor simulate` as a user meets it: a summary on the terminal instead of
//! the table, one default time step rule shared with the FMU, speed limits
//! checked before the run and reported in rpm, and a failed run's rows kept.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn rotor() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rotor"))
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn dir(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn text(o: &Output) -> (String, String) {
    (
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

fn csv(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let t = std::fs::read_to_string(path).unwrap();
    let mut lines = t.lines();
    let header = lines
        .next()
        .unwrap()
        .split(',')
        .map(str::to_string)
        .collect();
    let rows = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    (header, rows)
}

/// Without `--csv` the terminal gets a few lines, not 20 000 rows; every
/// number in them is the CSV's (same run, same default step).
#[test]
fn without_csv_the_terminal_gets_a_summary_of_the_run() {
    let pump = root().join("examples/my_pump.toml");
    let args = [
        "simulate",
        pump.to_str().unwrap(),
        "--rpm",
        "3600",
        "--duration",
        "0.2",
    ];
    let out = rotor().args(args).output().unwrap();
    let (stdout, stderr) = text(&out);
    assert!(out.status.success(), "{stderr}");
    assert!(stdout.lines().count() < 10, "{stdout}");
    assert!(stdout.ends_with('\n'));
    let path = dir("simulate_summary").join("run.csv");
    let with = rotor().args(args).arg("--csv").arg(&path).output().unwrap();
    assert!(with.status.success());
    let (header, rows) = csv(&path);
    assert!(stdout.starts_with(&format!(
        "my_pump: {} records from t = 0 to 0.2 s, 3600 → 3600 rpm (--csv FILE writes them all)\n",
        rows.len()
    )), "{stdout}");
    let col = |n: &str| header.iter().position(|h| h == n).unwrap();
    let largest = |x: &str, y: &str| {
        rows.iter()
            .map(|r| r[col(x)].hypot(r[col(y)]))
            .fold(0.0, f64::max)
    };
    let short = rotor_bearing::report::text::short;
    let probe = largest("impeller_x_m", "impeller_y_m");
    let line = stdout
        .lines()
        .find(|l| l.contains("probe impeller"))
        .unwrap();
    assert!(
        line.contains(&format!("{} µm", short(probe * 1e6))),
        "{line}"
    );
    let journal = largest("drive_end_x_m", "drive_end_y_m");
    let eps = rows
        .iter()
        .map(|r| r[col("drive_end_eccentricity")])
        .fold(0.0, f64::max);
    let line = stdout
        .lines()
        .find(|l| l.contains("bearing drive_end"))
        .unwrap();
    assert!(
        line.contains(&format!("{} µm", short(journal * 1e6))),
        "{line}"
    );
    assert!(
        line.contains(&format!("eccentricity ratio up to {}", short(eps))),
        "{line}"
    );
    // The film thickness is the plain bearing's C(1 − ε), at the largest ε.
    let h = 60e-6 * (1.0 - eps);
    assert!(
        line.contains(&format!("film down to {} µm", short(h * 1e6))),
        "{line}"
    );
}

/// The default steps: accuracy-controlled (local error tolerance 0.003) of at
/// most 12 per revolution at the top speed (the run's or the model's
/// max_speed_rpm, whichever is larger), at most 20 ms — the FMU's
/// `solver.time_step` and `solver.local_error_tolerance` start values follow
/// the same rule; `--local-error-tolerance 0` gives equal steps of 60 per
/// revolution, at most 1 ms.
#[test]
fn default_time_step_is_one_rule_for_the_cli_and_the_fmu() {
    let run = |args: &[&str]| {
        let out = rotor().arg("simulate").args(args).output().unwrap();
        let (stdout, stderr) = text(&out);
        assert!(out.status.success(), "{stderr}");
        (stdout, stderr)
    };
    let pump = root().join("examples/my_pump.toml");
    let pump = pump.to_str().unwrap();
    for rpm in ["3600", "1000"] {
        // max_speed_rpm 4000: 66.7 Hz, 1/800 s at most — whatever the run's
        // speed below it; the records follow the largest step.
        let (stdout, stderr) = run(&[pump, "--rpm", rpm, "--duration", "0.05"]);
        assert!(
            stderr.contains(
                "accuracy-controlled steps: local error tolerance 0.003, steps up to 0.00125 s (12 per revolution at 4000 rpm; --step for equal steps)"
            ),
            "{stderr}"
        );
        assert!(stdout.contains("41 records"), "{stdout}");
        // Equal steps: 1/4000 s.
        let (stdout, stderr) = run(&[
            pump,
            "--rpm",
            rpm,
            "--duration",
            "0.05",
            "--local-error-tolerance",
            "0",
        ]);
        assert!(
            stderr.contains(
                "time step 0.00025 s (60 steps per revolution at 4000 rpm; --step to choose)"
            ),
            "{stderr}"
        );
        assert!(stdout.contains("201 records"), "{stdout}");
    }
    // Jeffcott rotor (speed_rpm 3000, no max_speed_rpm) run at 6000 rpm:
    // the run's speed sets it, 1/1200 s (equal steps 1/6000 s).
    let jeffcott = root().join("models/jeffcott.toml");
    let jeffcott = jeffcott.to_str().unwrap();
    let (_, stderr) = run(&[jeffcott, "--rpm", "6000", "--duration", "0.01"]);
    assert!(
        stderr.contains("steps up to 0.000833333 s (12 per revolution at 6000 rpm"),
        "{stderr}"
    );
    let (_, stderr) = run(&[
        jeffcott,
        "--rpm",
        "6000",
        "--duration",
        "0.01",
        "--local-error-tolerance",
        "0",
    ]);
    assert!(
        stderr.contains("time step 0.000166667 s (60 steps per revolution at 6000 rpm"),
        "{stderr}"
    );
    // The classic rotor at 1000 rpm: equal steps of 1 ms; the hydro unit at
    // 150 rpm: accuracy-controlled steps of at most 20 ms.
    let (_, stderr) = run(&[
        "--rpm",
        "1000",
        "--duration",
        "0.01",
        "--local-error-tolerance",
        "0",
    ]);
    assert!(
        stderr.contains("time step 0.001 s (at most 1 ms; 1000 rpm needs no finer"),
        "{stderr}"
    );
    let hydro = root().join("models/hydro_unit.toml");
    let (_, stderr) = run(&[
        hydro.to_str().unwrap(),
        "--rpm",
        "150",
        "--duration",
        "0.04",
    ]);
    assert!(
        stderr.contains("steps up to 0.02 s (at most 20 ms; 150 rpm; --step for equal steps)"),
        "{stderr}"
    );
    // The FMU of each model starts with the same rule at the model's speed.
    for (model, start) in [
        ("models/jeffcott.toml", 1.0 / 600.0),
        ("models/hydro_unit.toml", 0.02),
        ("examples/my_pump.toml", 1.0 / 800.0),
    ] {
        let stage = dir(&format!("stage_{}", model.replace(['/', '.'], "_")));
        let out = rotor()
            .arg("fmu-stage")
            .arg(root().join(model))
            .arg(&stage)
            .output()
            .unwrap();
        assert!(out.status.success(), "{}", text(&out).1);
        let xml = std::fs::read_to_string(stage.join("modelDescription.xml")).unwrap();
        let start_of = |name: &str| -> f64 {
            let var = xml.split(&format!("name=\"{name}\"")).nth(1).unwrap();
            var.split("start=\"")
                .nth(1)
                .unwrap()
                .split('"')
                .next()
                .unwrap()
                .parse()
                .unwrap()
        };
        let value = start_of("solver.time_step");
        assert!((value - start).abs() < 1e-15, "{model}: {value}");
        assert_eq!(start_of("solver.local_error_tolerance"), 0.003, "{model}");
    }
}

/// A ramp past `max_speed_rpm` is refused before anything runs, in rpm with
/// the file named (it used to run 5.6 s and then fail in rad/s).
#[test]
fn a_ramp_past_max_speed_is_refused_before_the_run_in_rpm() {
    let pump = root().join("examples/my_pump.toml");
    let path = dir("simulate_ramp").join("r.csv");
    let _ = std::fs::remove_file(&path);
    let out = rotor()
        .args([
            "simulate",
            pump.to_str().unwrap(),
            "--ramp-rpm",
            "0:5000",
            "--duration",
            "30",
            "--csv",
        ])
        .arg(&path)
        .output()
        .unwrap();
    let (_, stderr) = text(&out);
    assert!(!out.status.success());
    assert!(
        stderr.contains(&format!(
            "the speed profile reaches 5000 rpm, above {}: max_speed_rpm = 4000: nothing was run",
            pump.display()
        )),
        "{stderr}"
    );
    assert!(
        !stderr.contains("simulated") && !stderr.contains("rad/s"),
        "{stderr}"
    );
    assert!(!path.exists());
    // Without max_speed_rpm the default limit (60 000 rpm) is named as such.
    let out = rotor()
        .args(["simulate", "--rpm", "70000", "--duration", "0.01"])
        .output()
        .unwrap();
    assert!(
        text(&out)
            .1
            .contains("reaches 70000 rpm, above the default max_speed_rpm 60000")
    );
}

/// A stiff seal rub (1e15 N/m, 0.1 mm gap) on the damped classic rotor with a
/// 1 kg·m unbalance at the disk: the model the two tests below fail on.
/// (A 10⁶ kg·m unbalance on the Jeffcott rotor failed before the damped
/// Newton of issue 22b; it now runs through.)
fn rub_model(d: &Path) -> PathBuf {
    let model = d.join("rub.toml");
    let text_in = std::fs::read_to_string(root().join("models/classic_disk_rotor_damped.toml"))
        .unwrap()
        .replace("magnitude = 0.001 ", "magnitude = 1.0 ");
    assert!(text_in.contains("magnitude = 1.0 "));
    std::fs::write(
        &model,
        format!(
            "{text_in}\n[[rubs]]\nname = \"seal\"\nnode = 4\ngap = 1e-4\ncontact_stiffness = 1e15\n"
        ),
    )
    .unwrap();
    model
}

/// A run that fails (the rub above at 3000 rpm in equal steps: Newton does
/// not converge after 16 halvings; accuracy-controlled steps get through) keeps its rows up to the failure in the CSV and says
/// where they are and when it stopped; the contact warnings come first.
#[test]
fn a_failed_run_keeps_its_rows() {
    let d = dir("simulate_failure");
    let model = rub_model(&d);
    let path = d.join("partial.csv");
    let _ = std::fs::remove_file(&path);
    let out = rotor()
        .arg("simulate")
        .arg(&model)
        .args([
            "--rpm",
            "3000",
            "--no-gravity",
            "--duration",
            "0.5",
            "--local-error-tolerance",
            "0",
            "--csv",
        ])
        .arg(&path)
        .output()
        .unwrap();
    let (_, stderr) = text(&out);
    assert!(!out.status.success(), "{stderr}");
    let (_, rows) = csv(&path);
    assert!(rows.len() > 10, "{}", rows.len());
    let reached = rows.last().unwrap()[0];
    assert!(reached > 0.0 && reached < 0.5);
    let short = rotor_bearing::report::text::short;
    assert!(
        stderr.contains(&format!(
            "(failed after t = {} s of 0.5 s; the {} rows up to t = {} s are in {})",
            short(reached),
            rows.len(),
            short(reached),
            path.display()
        )),
        "{stderr}"
    );
    let failure = stderr
        .find("did not converge")
        .unwrap_or_else(|| panic!("{stderr}"));
    let contact = stderr.find("warning: rub seal: at t = ").unwrap();
    assert!(contact < failure, "{stderr}");
}

/// A reduced run that fails still warns about the motion that left the range
/// the reduced rotor is validated for (the watch runs in the same progress
/// callback that keeps the rows): the rub model on 4 modes (valid up to
/// 11.1 Hz) chatters at the rub (an RMS frequency far above 11.1 Hz) while
/// spinning at 334 rpm, and fails later in the run (the chattering run is
/// chaotic: only the order of the messages and the kept rows are checked).
#[test]
fn a_failed_reduced_run_still_warns_about_its_motion() {
    let d = dir("simulate_reduced_failure");
    let model = rub_model(&d);
    let speeds = d.join("speeds.csv");
    std::fs::write(
        &speeds,
        "time_s,speed_rpm\n0,334\n0.45,334\n0.5,100\n0.9,100\n0.95,334\n1,334\n",
    )
    .unwrap();
    let path = d.join("partial.csv");
    let _ = std::fs::remove_file(&path);
    let out = rotor()
        .arg("simulate")
        .arg(&model)
        .arg("--speed-csv")
        .arg(&speeds)
        .args(["--no-gravity", "--duration", "1", "--step", "1e-3"])
        .args(["--reduced-modes", "4", "--csv"])
        .arg(&path)
        .output()
        .unwrap();
    let (_, stderr) = text(&out);
    assert!(!out.status.success(), "{stderr}");
    let warning = stderr
        .find("the motion at the kept nodes (RMS frequency")
        .unwrap_or_else(|| panic!("{stderr}"));
    let failure = stderr.find("did not converge").unwrap();
    assert!(warning < failure, "{stderr}");
    assert!(stderr.contains("above the 11.1 Hz (668 rpm)"), "{stderr}");
    let (_, rows) = csv(&path);
    let reached = rows.last().unwrap()[0];
    assert!(reached > 0.361 && reached < 1.0, "{reached}");
    assert!(
        stderr.contains(&format!(
            "(failed after t = {} s of 1 s; the {} rows",
            rotor_bearing::report::text::short(reached),
            rows.len()
        )),
        "{stderr}"
    );
}
