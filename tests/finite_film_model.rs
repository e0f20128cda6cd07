//! `film = "finite"` in a model file (issue 47): the entry builds the
//! finite-film bearing, the analyses use it through the `Bearing` seam (the
//! operating point equals the bearing's own equilibrium under the same
//! load, and differs from the short film's), bad values are errors naming
//! file, line, field and value, and a short film beyond its range is told
//! once per bearing with its ratios at the operating point.

use std::path::PathBuf;

use nalgebra::Vector2;

use rotor_bearing::analysis::film_validity::short_film_warnings;
use rotor_bearing::analysis::operating_point::operating_point;
use rotor_bearing::bearing::BearingKind;
use rotor_bearing::bearing::equilibrium::journal_equilibrium;
use rotor_bearing::bearing::reynolds::Cavitation;
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;

fn jeffcott_text() -> String {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/jeffcott.toml");
    std::fs::read_to_string(path).unwrap()
}

/// The Jeffcott model with `lines` added after each bearing's `type`.
fn jeffcott_with(lines: &str) -> String {
    jeffcott_text().replace(
        "type = \"plain\"\n",
        &format!("type = \"plain\"\n{lines}\n"),
    )
}

fn model(text: &str) -> RotorModel {
    RotorModel::from_toml(text, "jeffcott_finite.toml").unwrap()
}

fn error(text: &str) -> String {
    RotorModel::from_toml(text, "jeffcott_finite.toml")
        .unwrap_err()
        .to_string()
}

/// The key builds the finite-film bearing with its mesh and cavitation;
/// `film = "short"` is the default, bit for bit.
#[test]
fn the_key_builds_the_finite_film_bearing() {
    let m = model(&jeffcott_with(
        "film = \"finite\"\nfilm_mesh = [96, 8]\ncavitation = \"gumbel\"",
    ));
    for b in &m.bearings {
        let BearingKind::FiniteFilm(f) = &b.kind else {
            panic!("{:?}", b.kind)
        };
        assert_eq!((f.mesh.circumferential, f.mesh.axial), (96, 8));
        assert_eq!(f.cavitation, Cavitation::Gumbel);
        assert!(matches!(f.short_kind(), BearingKind::Plain(_)));
    }
    let default = model(&jeffcott_with("film = \"finite\""));
    let BearingKind::FiniteFilm(f) = &default.bearings[0].kind else {
        panic!()
    };
    assert_eq!(f.cavitation, Cavitation::SwiftStieber);
    assert_eq!((f.mesh.circumferential, f.mesh.axial), (144, 16));
    let short = model(&jeffcott_with("film = \"short\""));
    let plain = model(&jeffcott_text());
    assert_eq!(short.bearings[0].kind, plain.bearings[0].kind);
}

/// Bad values name the file, the line, the field and the value.
#[test]
fn bad_values_are_errors_naming_the_field() {
    let cases = [
        (
            jeffcott_with("film = \"long\""),
            "jeffcott_finite.toml:34: bearings[0].film = \"long\"",
        ),
        (
            jeffcott_with("film_mesh = [96, 8]"),
            "bearings[0].film_mesh = given: belongs to the finite film only",
        ),
        (
            jeffcott_with("film = \"finite\"\ncavitation = \"elrod\""),
            "bearings[0].cavitation = \"elrod\"",
        ),
        (
            jeffcott_with("film = \"finite\"\nfilm_mesh = [4, 8]"),
            "bearings[0].film_mesh[0] = 4: must be from 8 to 2048",
        ),
        (
            jeffcott_with("film = \"finite\"\nfilm_mesh = [96]"),
            "bearings[0].film_mesh = [96]",
        ),
        (
            jeffcott_with("film = \"finite\"").replace("length = 0.02 ", "length = 0.2 "),
            "bearings[0].length = 0.2: L/D = 5.0000 is outside 0.05–4",
        ),
    ];
    for (text, expected) in cases {
        let e = error(&text);
        assert!(e.contains(expected), "{e}\nexpected: {expected}");
    }
    // A pad arc outside 10°–180° on the finite film (pads of 5°, short
    // enough that their L/(R β) = 2.9 is in range).
    let pads = jeffcott_text()
        .replace(
            "type = \"plain\"\n",
            "type = \"tilting_pad\"\npads = 4\npad_arc_deg = 5.0\nfilm = \"finite\"\n",
        )
        .replace("length = 0.02", "length = 0.005");
    let e = error(&pads);
    assert!(
        e.contains("bearings[0].pad_arc_deg = 5") && e.contains("10–180°"),
        "{e}"
    );
}

/// The operating point of the rotor on finite films is each bearing's own
/// equilibrium (the `FiniteFilmBearing` under the bearing's static load)
/// and not the short film's; the warning of the short film names both
/// Jeffcott bearings (L/D 0.5) with ratios near 1.05 at this light load,
/// and no bearing on the finite film or with L/D ≤ 0.2 is warned about.
#[test]
fn analyses_use_the_finite_film_and_the_short_one_is_told() {
    let speed = 6000.0 * std::f64::consts::PI / 30.0;
    let finite = Rotor::new(model(&jeffcott_with("film = \"finite\""))).unwrap();
    let short = Rotor::new(model(&jeffcott_text())).unwrap();
    let op = operating_point(&finite, speed).unwrap();
    let op_short = operating_point(&short, speed).unwrap();
    for (b, s) in op.iter().zip(&op_short) {
        let kind = &finite.model.bearings[b.bearing].kind;
        let bearing = kind.build();
        let load = -Vector2::new(b.force[0], b.force[1]);
        let eq = journal_equilibrium(bearing.as_ref(), load, speed, 1e-4).unwrap();
        let k = eq.eval.journal().stiffness;
        for i in 0..2 {
            assert!(
                (eq.q[i] - b.journal[i]).abs() < 1e-9,
                "{:?} {:?}",
                eq.q,
                b.journal
            );
            for j in 0..2 {
                let d = (k[(i, j)] - b.stiffness[i][j]).abs();
                assert!(d < 1e-6 * k.norm(), "K {k} vs {:?}", b.stiffness);
            }
        }
        let e = b.film.as_ref().unwrap().eccentricity;
        let e_short = s.film.as_ref().unwrap().eccentricity;
        println!("{}: ε {e:.4} (finite) vs {e_short:.4} (short)", b.name);
        assert!(e > 1.03 * e_short, "{e} {e_short}");
    }
    let warnings = short_film_warnings(&short, speed).unwrap();
    assert_eq!(warnings.len(), 2, "{warnings:?}");
    for w in &warnings {
        let text = w.to_string();
        println!("{text}");
        assert!(text.contains("L/D = 0.500") && text.contains("film = \"finite\""));
        let (k, c) = (w.stiffness_ratio.unwrap(), w.damping_ratio.unwrap());
        assert!(
            (1.0..1.2).contains(&k) && (1.0..1.2).contains(&c),
            "{k} {c}"
        );
    }
    assert!(short_film_warnings(&finite, speed).unwrap().is_empty());
    let slim = jeffcott_text().replace("length = 0.02", "length = 0.006");
    let slim = Rotor::new(model(&slim)).unwrap();
    assert!(short_film_warnings(&slim, speed).unwrap().is_empty());
}

/// The CLI prints the warning once per bearing, and not for the finite
/// film; `rotor coefficients` sweeps the model's own film.
#[test]
fn the_cli_warns_once_per_short_bearing() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let finite = dir.join("jeffcott_finite_film.toml");
    std::fs::write(&finite, jeffcott_with("film = \"finite\"")).unwrap();
    let run = |path: &std::path::Path| {
        std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
            .args(["operating-point"])
            .arg(path)
            .args(["--rpm", "6000"])
            .output()
            .unwrap()
    };
    let short = run(&PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/jeffcott.toml"));
    assert!(short.status.success());
    let stderr = String::from_utf8_lossy(&short.stderr);
    let lines: Vec<&str> = stderr
        .lines()
        .filter(|l| l.contains("short film at"))
        .collect();
    assert_eq!(lines.len(), 2, "{stderr}");
    assert!(lines[0].contains("bearing left") && lines[1].contains("bearing right"));
    let long = run(&finite);
    assert!(long.status.success(), "{long:?}");
    assert!(!String::from_utf8_lossy(&long.stderr).contains("short film at"));
    // `rotor coefficients` sweeps the bearing's own film by default.
    let sweep = |film: &str| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
            .arg("coefficients")
            .arg(&finite)
            .args(["--points", "2", "--film", film])
            .output()
            .unwrap();
        assert!(out.status.success(), "{out:?}");
        String::from_utf8_lossy(&out.stdout)
            .lines()
            .next()
            .unwrap()
            .to_string()
    };
    assert!(sweep("model").contains("finite-length film (swift_stieber)"));
    assert!(!sweep("short").contains("finite-length film"));
}
