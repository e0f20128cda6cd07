//! The torsional modes of a hydro unit in its report (issue 48): two
//! inertias `J₁`, `J₂` on a light shaft of torsional stiffness `k = G J_p/L`
//! have the one elastic frequency `f = (1/2π) √(k (J₁ + J₂)/(J₁ J₂))` (the
//! shaft's own inertia `ρ J_p L` is 3e-8 of the lighter disk's, so the
//! massless closed form holds to 1e-7). Placed inside the
//! band `|f − f_e| < m f_e` of an excitation (running speed, grid frequency,
//! twice the grid frequency) the report's row FAILS, outside it passes, with
//! the separation the closed form gives; without `grid_frequency_hz` the grid
//! rows are not judged; the report's frequency is the one `rotor modes`
//! prints; the keys are validated.

use std::f64::consts::{PI, TAU};
use std::process::Command;

use rotor_bearing::model::RotorModel;
use rotor_bearing::report::html::Verdict;
use rotor_bearing::report::hydro_torsion::{torsion_rows, torsion_study};

mod report_page;
use report_page::{report_page, table_rows};

/// Shear modulus of the material (Pa): `E = 210 GPa`, `ν = 0.3`.
const G: f64 = 210e9 / 2.6;
/// Shaft length (m) and diameter (m); disk inertias (kg·m²).
const L: f64 = 1.0;
const D: f64 = 0.5;
const J1: f64 = 2000.0;
const J2: f64 = 5000.0;

/// The closed-form torsional frequency (Hz).
fn closed_form() -> f64 {
    let k = G * PI * D.powi(4) / 32.0 / L;
    (k * (J1 + J2) / (J1 * J2)).sqrt() / TAU
}

/// The two-inertia hydro unit at `rpm` with the top-level `keys`.
fn model_text(rpm: f64, keys: &str) -> String {
    format!(
        "name = \"two_inertia\"\nmachine = \"hydro_generator\"\nspeed_rpm = {rpm}\nmax_speed_rpm = 9000\n{keys}\
         [[materials]]\nname = \"m\"\nyoungs_modulus = 210e9\npoisson_ratio = 0.3\ndensity = 0.01\n\
         [[shaft]]\nlength = {L}\nouter_diameter = {D}\nmaterial = \"m\"\nelements = 4\n\
         [[disks]]\nname = \"generator\"\nnode = 1\nmass = 2000.0\npolar_inertia = {J1}\ndiametral_inertia = 1000.0\n\
         [[disks]]\nname = \"runner\"\nnode = 5\nmass = 2000.0\npolar_inertia = {J2}\ndiametral_inertia = 2500.0\n\
         [[bearings]]\ntype = \"linear\"\nnode = 1\nkxx = 1e8\nkyy = 1e8\ncxx = 1e5\ncyy = 1e5\n\
         [[bearings]]\ntype = \"linear\"\nnode = 5\nkxx = 1e8\nkyy = 1e8\ncxx = 1e5\ncyy = 1e5\n"
    )
}

fn model(rpm: f64, keys: &str) -> RotorModel {
    RotorModel::from_toml(&model_text(rpm, keys), "two_inertia.toml").unwrap()
}

/// The verdicts of the three rows (running speed, 1x grid, 2x grid).
fn verdicts(m: &RotorModel, rpm: f64) -> Vec<Verdict> {
    torsion_rows(&torsion_study(m, rpm * PI / 30.0))
        .iter()
        .map(|r| r[4].verdict.unwrap())
        .collect()
}

#[test]
fn a_torsional_frequency_inside_the_band_of_an_excitation_fails() {
    let f = closed_form();
    // The chain's frequency equals the closed form.
    let m = model(300.0, "grid_frequency_hz = 50\n");
    let study = torsion_study(&m, 300.0 * PI / 30.0).unwrap();
    let got = study.modes[0].natural_frequency / TAU;
    assert!((got / f - 1.0).abs() < 1e-7, "{got} against {f}");
    // The list reaches past the highest band: the next mode lies above it.
    assert!(study.modes.last().unwrap().natural_frequency / TAU > 1.1 * 100.0);

    // Twice the grid 5 % above f: inside the default 10 % → FAIL; 1x grid
    // and the running speed far away → pass.
    let grid = 1.05 * f / 2.0;
    let m = model(300.0, &format!("grid_frequency_hz = {grid}\n"));
    assert_eq!(
        verdicts(&m, 300.0),
        [Verdict::Pass, Verdict::Pass, Verdict::Fail]
    );
    let study = torsion_study(&m, 300.0 * PI / 30.0).unwrap();
    let (mode, _, separation) = study.checks[2].governing.unwrap();
    assert_eq!(mode, 0);
    let want = (f - 2.0 * grid).abs() / (2.0 * grid);
    assert!(
        (separation - want).abs() < 1e-7,
        "{separation} against {want}"
    );
    // 15 % away: outside the band → pass.
    let m = model(300.0, &format!("grid_frequency_hz = {}\n", 1.15 * f / 2.0));
    assert_eq!(verdicts(&m, 300.0), [Verdict::Pass; 3]);
    // ... unless the model asks for 20 %.
    let m = model(
        300.0,
        &format!(
            "grid_frequency_hz = {}\ntorsional_margin = 0.2\n",
            1.15 * f / 2.0
        ),
    );
    assert_eq!(
        verdicts(&m, 300.0),
        [Verdict::Pass, Verdict::Pass, Verdict::Fail]
    );
    // The 1x grid frequency 8 % below f → FAIL on that row.
    let m = model(300.0, &format!("grid_frequency_hz = {}\n", f / 1.08));
    assert_eq!(
        verdicts(&m, 300.0),
        [Verdict::Pass, Verdict::Fail, Verdict::Pass]
    );
    // Running at f (1x) → FAIL; no grid frequency → not judged.
    let rpm = f * 60.0 * 0.97;
    let m = model(rpm, "");
    let rows = torsion_rows(&torsion_study(&m, rpm * PI / 30.0));
    assert_eq!(
        rows.iter()
            .map(|r| r[4].verdict.unwrap())
            .collect::<Vec<_>>(),
        [Verdict::Fail, Verdict::NotJudged, Verdict::NotJudged]
    );
    assert_eq!(rows[1][2].text, "not judged: no grid frequency");
}

#[test]
fn the_report_row_is_the_frequency_rotor_modes_prints() {
    let f = closed_form();
    let text = model_text(300.0, &format!("grid_frequency_hz = {}\n", 1.05 * f / 2.0));
    let rows = table_rows(&report_page(&text, "hydro_torsion"), "summary-table");
    let torsion: Vec<&Vec<String>> = rows
        .iter()
        .filter(|r| r[0] == "torsional natural frequencies")
        .collect();
    assert_eq!(torsion.len(), 3, "{rows:?}");
    let verdicts: Vec<&str> = torsion.iter().map(|r| r[4].as_str()).collect();
    assert_eq!(verdicts, ["pass", "pass", "FAIL"]);
    assert!(torsion[2][1].starts_with("2x grid frequency"));
    // "mode 1 at <f> Hz: separation <s> %"
    let value = &torsion[2][2];
    let reported: f64 = value
        .strip_prefix("mode 1 at ")
        .and_then(|v| v.split(" Hz").next())
        .unwrap()
        .parse()
        .unwrap();
    // `rotor modes` prints the same mode (f in Hz, 4 decimals).
    let dir = std::env::temp_dir().join(format!("hydro-torsion-modes-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("two_inertia.toml");
    std::fs::write(&file, &text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(["modes", file.to_str().unwrap(), "--torsional-modes", "1"])
        .output()
        .unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert!(out.status.success());
    let printed = String::from_utf8(out.stdout).unwrap();
    let line = printed
        .lines()
        .find(|l| l.trim_end().ends_with("torsional"))
        .expect("a torsional mode line");
    let printed_f: f64 = line.split_whitespace().nth(2).unwrap().parse().unwrap();
    assert!(
        (reported - printed_f).abs() <= 5e-5 + 1e-5 * printed_f,
        "report {reported} Hz, rotor modes {printed_f} Hz"
    );
    assert!((reported / f - 1.0).abs() < 1e-5, "{reported} against {f}");
}

#[test]
fn the_torsional_criteria_keys_are_validated() {
    let bad = [
        ("grid_frequency_hz = -50\n", "grid_frequency_hz", "-50"),
        ("grid_frequency_hz = 5000\n", "grid_frequency_hz", "5000"),
        ("grid_frequency_hz = 1e300\n", "grid_frequency_hz", "1e300"),
        ("torsional_margin = 1.5\n", "torsional_margin", "1.5"),
        ("torsional_margin = -0.1\n", "torsional_margin", "-0.1"),
    ];
    for (keys, field, value) in bad {
        let e = RotorModel::from_toml(&model_text(300.0, keys), "two_inertia.toml")
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("two_inertia.toml") && e.contains(field) && e.contains(value),
            "{e}"
        );
    }
    // Only a hydro class is judged by them.
    let generic = model_text(300.0, "grid_frequency_hz = 50\n").replace(
        "machine = \"hydro_generator\"\n",
        "machine = \"compressor\"\n",
    );
    let e = RotorModel::from_toml(&generic, "two_inertia.toml")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("grid_frequency_hz") && e.contains("hydro_generator"),
        "{e}"
    );
}
