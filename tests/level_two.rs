//! API 617 Level II (issue 48): the log decrement of the first forward mode
//! at the maximum continuous speed with every element's coefficients, the
//! seals' cross-coupling included, against the closed form.
//!
//! On the rigid test compressor of `tests/data/api_compressor.toml` (a
//! uniform shaft a thousand times stiffer than steel on two identical damped
//! isotropic bearings, a seal at mid-span where the conical mode has its
//! node; `speed_rpm = 3000` and no `operating_rpm`, so the maximum
//! continuous speed is 3000 rpm), the first forward mode is the cylindrical
//! one, one degree of freedom `m s² + c s + (k − iQ) = 0` (`z = x + iy`, `Q`
//! the seal's `kxy = −kyx`, plus the anticipated `Q_A` at mid-span for the
//! second variant), whose forward root gives δ in closed form.

use std::process::Command;

use rotor_bearing::analysis::level_two::{LEVEL_II_MIN_LOG_DEC, level_two};
use rotor_bearing::analysis::stability::{MACHINE_STAGE, Stage, StageData};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;

const RPM: f64 = std::f64::consts::PI / 30.0;

/// The forward root's log decrement of `m s² + c s + k − iQ = 0`.
fn closed_form(q: f64) -> f64 {
    type C = nalgebra::Complex<f64>;
    let m = 7850.0 * std::f64::consts::FRAC_PI_4 * 0.1 * 0.1 * 1.0;
    let (k, c) = (2.0e7, 2.0 * 1756.0);
    let disc = (C::new(c * c - 4.0 * m * k, 4.0 * m * q)).sqrt();
    let roots = [(-c + disc) / (2.0 * m), (-c - disc) / (2.0 * m)];
    let s = roots.into_iter().find(|s| s.im > 0.0).unwrap();
    std::f64::consts::TAU * -s.re / s.im
}

/// The test compressor with a seal of cross-coupled stiffness `q` (N/m).
fn compressor(q: f64) -> String {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/api_compressor.toml"),
    )
    .unwrap()
    .replace(
        "kxx = [0.0, 0.0]",
        &format!(
            "kxx = [0.0, 0.0]\nkxy = [{q:e}, {q:e}]\nkyx = [{:e}, {:e}]",
            -q, -q
        ),
    );
    assert!(text.contains("kxy = "));
    text
}

/// Wachel's stage data giving `Q_A` = 3 × 1e5 W / (0.3 m × 0.02 m × 314.16
/// rad/s) = 159 155 N/m at 3000 rpm.
fn stage() -> Stage {
    Stage {
        name: MACHINE_STAGE.to_string(),
        data: StageData {
            power: 1e5,
            diameter: 0.3,
            width: 0.02,
            density_ratio: 1.0,
            stage_factor: 3.0,
        },
    }
}

/// δ of the first forward mode equals the closed form within 1e-3 (the
/// shaft's own flexibility leaves about 1e-4), with the seal's `Q` alone
/// and with `Q + Q_A` (`Q_A` = 159 155 N/m); the verdict turns across
/// δ = 0.1 as the closed form does: Q = 0 and 1e6 N/m pass both ways (δ
/// 0.315/0.290, 0.157/0.132 as built/with `Q_A`), 1.25e6 N/m passes as built
/// (0.118) and fails with `Q_A` (0.093), 1.5e6 N/m fails both (0.078/0.054).
/// Only the first forward mode is judged: every other forward mode lies
/// above the 50 Hz running frequency.
#[test]
fn level_two_log_decrement_is_the_closed_form_and_judged_at_0_1() {
    let qa = 3.0 * 1e5 / (0.3 * 0.02 * 3000.0 * RPM);
    let mut verdicts = Vec::new();
    for q in [0.0, 1.0e6, 1.25e6, 1.5e6] {
        let rotor = Rotor::new(RotorModel::from_toml(&compressor(q), "c.toml").unwrap()).unwrap();
        let l = level_two(&rotor, 3000.0 * RPM, &[stage()], 8).unwrap();
        assert!((l.speed - 3000.0 * RPM).abs() < 1e-12);
        assert!((l.frequency_limit - 3000.0 * RPM).abs() < 1e-12);
        assert_eq!(l.as_built.modes.len(), 1, "{:?}", l.as_built.modes);
        let built = l.as_built.governing().unwrap().log_decrement;
        let expected = closed_form(q);
        assert!(
            (built - expected).abs() < 1e-3,
            "Q = {q}: {built} against {expected}"
        );
        assert_eq!(
            l.as_built.pass(),
            expected >= LEVEL_II_MIN_LOG_DEC,
            "Q = {q}"
        );
        let (stages, why, with) = l.anticipated.as_ref().unwrap();
        assert_eq!(stages.len(), 1);
        assert!(why.contains("mid-span"), "{why}");
        assert_eq!(with.sites, vec![4]);
        assert!((with.cross_coupling / qa - 1.0).abs() < 1e-12);
        let coupled = with.governing().unwrap().log_decrement;
        let expected_a = closed_form(q + qa);
        assert!(
            (coupled - expected_a).abs() < 1e-3,
            "Q = {q} + Q_A: {coupled} against {expected_a}"
        );
        assert_eq!(
            with.pass(),
            expected_a >= LEVEL_II_MIN_LOG_DEC,
            "Q = {q} + Q_A"
        );
        verdicts.push((l.as_built.pass(), with.pass()));
    }
    let expected = [(true, true), (true, true), (true, false), (false, false)];
    assert_eq!(verdicts, expected);
}

/// `rotor stability` of the compressor prints the Level II section with its
/// verdicts, at the top of the operating range: `operating_rpm = [2000,
/// 3500]` moves the maximum continuous speed to 3500 rpm whatever `--rpm`.
#[test]
fn rotor_stability_prints_level_two_at_the_maximum_continuous_speed() {
    let dir = std::env::temp_dir().join(format!("level-two-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("c.toml");
    let text = compressor(1.5e6).replace(
        "max_speed_rpm = 7000",
        "max_speed_rpm = 7000\noperating_rpm = [2000.0, 3500.0]",
    );
    std::fs::write(&path, text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(["stability", path.to_str().unwrap(), "--rpm", "3000"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let printed = String::from_utf8(out.stdout).unwrap();
    assert!(
        printed.contains("API 617 Level II at the maximum continuous speed 3500 rpm"),
        "{printed}"
    );
    let rotor = Rotor::new(RotorModel::from_toml(&compressor(1.5e6), "c.toml").unwrap()).unwrap();
    let l = level_two(&rotor, 3500.0 * RPM, &[], 8).unwrap();
    let line = format!(
        "  Level II (model as built): least log dec {:.4} at",
        l.as_built.governing().unwrap().log_decrement
    );
    assert!(printed.contains(&line), "{line}\n{printed}");
    assert!(printed.contains("Hz: FAIL\n"), "{printed}");
    assert!(!printed.contains("with the anticipated"), "{printed}");
}

/// `rotor report` of the compressor (seal Q = 1.5e6 N/m, stage data,
/// `--operating-rpm 2000:3500`) carries the two Level II rows in its summary
/// with the findings and verdicts `rotor stability` prints for the same
/// range, and the section's table.
#[test]
fn the_report_summary_carries_the_commands_level_two() {
    let dir = std::env::temp_dir().join(format!("level-two-report-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("c.toml");
    std::fs::write(&path, compressor(1.5e6)).unwrap();
    let page = dir.join("report.html");
    let stages = [
        "--power",
        "1e5",
        "--impeller-diameter",
        "0.3",
        "--flow-width",
        "0.02",
        "--operating-rpm",
        "2000:3500",
    ];
    let run = |command: &str, extra: &[&str]| {
        let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
            .args([command, path.to_str().unwrap()])
            .args(stages)
            .args(extra)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8(out.stdout).unwrap()
    };
    let printed = run("stability", &[]);
    run("report", &["--out", page.to_str().unwrap()]);
    let html = std::fs::read_to_string(&page).unwrap();
    std::fs::remove_dir_all(&dir).ok();
    assert!(html.contains("id=\"level-two\""));
    for (row_name, prefix) in [
        (
            "stability (API 617 Level II)<",
            "  Level II (model as built): ",
        ),
        (
            "stability (API 617 Level II with Q_A)<",
            "  Level II with Q_A: ",
        ),
    ] {
        let line = printed
            .lines()
            .find_map(|l| l.strip_prefix(prefix))
            .unwrap_or_else(|| panic!("{printed}"));
        let (finding, verdict) = line.rsplit_once(": ").unwrap();
        assert_eq!(verdict, "FAIL", "{line}");
        let at = html.find(row_name).expect("a summary row");
        let row = &html[at..at + html[at..].find("</tr>").unwrap()];
        assert!(row.contains(finding), "{finding}\n{row}");
        assert!(row.contains("3500 rpm (MCS)"), "{row}");
        assert!(row.contains(">FAIL<"), "{row}");
    }
}

/// The Level II heading names the coefficients the model holds: with the
/// seal "the seals' with their cross-coupling", without it "(the model has
/// no seals)" and no word of a seal's cross-coupling.
#[test]
fn the_level_two_heading_says_what_the_model_contains() {
    let with_seal = compressor(1.0e6);
    let start = with_seal.find("[[seals]]").unwrap();
    let end = with_seal[start + 1..]
        .find("\n[[")
        .map_or(with_seal.len(), |k| start + 1 + k + 1);
    let without_seal = format!("{}{}", &with_seal[..start], &with_seal[end..]);
    assert!(!without_seal.contains("[[seals]]"));
    let dir = std::env::temp_dir().join(format!("level-two-words-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (name, text, has_seal) in [("seal", &with_seal, true), ("bare", &without_seal, false)] {
        let model = RotorModel::from_toml(text, "c.toml").unwrap();
        let words = rotor_bearing::report::text::level_two_elements(&model);
        let path = dir.join(format!("{name}.toml"));
        std::fs::write(&path, text).unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
            .args(["stability", path.to_str().unwrap(), "--rpm", "3000"])
            .output()
            .unwrap();
        assert!(out.status.success());
        let printed = String::from_utf8(out.stdout).unwrap();
        let heading = printed
            .lines()
            .find(|l| l.starts_with("API 617 Level II at"))
            .unwrap();
        assert!(heading.contains(&words), "{heading}");
        if has_seal {
            assert!(
                heading.contains("the seals' with their cross-coupling"),
                "{heading}"
            );
            assert!(!heading.contains("no seals"), "{heading}");
        } else {
            assert!(heading.contains("(the model has no seals)"), "{heading}");
            assert!(!heading.contains("seals' with"), "{heading}");
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `rotor stability --level-two-csv` writes Level II: a row per judged mode
/// of each case with the log decrement the closed form gives (to 1e-3, as
/// above) and the case's verdict (Q = 1.25e6 N/m: as built 0.118 passes,
/// with `Q_A` 0.093 fails).
#[test]
fn the_level_two_csv_holds_each_case_against_the_closed_form() {
    let q = 1.25e6;
    let qa = 3.0 * 1e5 / (0.3 * 0.02 * 3000.0 * RPM);
    let dir = std::env::temp_dir().join(format!("level-two-csv-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("c.toml");
    std::fs::write(&path, compressor(q)).unwrap();
    let csv = dir.join("level_two.csv");
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(["stability", path.to_str().unwrap(), "--rpm", "3000"])
        .args([
            "--power",
            "1e5",
            "--impeller-diameter",
            "0.3",
            "--flow-width",
            "0.02",
        ])
        .arg("--level-two-csv")
        .arg(&csv)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let table = std::fs::read_to_string(&csv).unwrap();
    std::fs::remove_dir_all(&dir).ok();
    let mut lines = table.lines();
    assert_eq!(
        lines.next().unwrap(),
        "case,speed_rpm,cross_coupling_N_m,mode,damped_frequency_hz,log_decrement,verdict"
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 2, "{table}");
    for (row, (case, added, verdict)) in rows
        .iter()
        .zip([("as_built", 0.0, "pass"), ("with_Q_A", qa, "FAIL")])
    {
        assert_eq!(row[0], case);
        assert!((row[1].parse::<f64>().unwrap() - 3000.0).abs() < 1e-9);
        let cross: f64 = row[2].parse().unwrap();
        assert!((cross - added).abs() <= 1e-9 * qa, "{row:?}");
        assert_eq!(row[3], "1");
        let delta: f64 = row[5].parse().unwrap();
        let expected = closed_form(q + added);
        assert!(
            (delta - expected).abs() < 1e-3,
            "{case}: {delta} against {expected}"
        );
        assert_eq!(row[6], verdict);
    }
}
