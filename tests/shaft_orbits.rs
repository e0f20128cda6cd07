//! Shaft orbits of the design review (issue 48, `analysis::shaft_orbits`):
//! the transient's shaft displacement relative to the bearing housing
//! against the steady unbalance response of linear theory, and the cases a
//! hydro unit is shown in.

use rotor_bearing::analysis::linear::{node_xy, unbalance_response};
use rotor_bearing::analysis::shaft_orbits::{OrbitCase, hydro_cases, shaft_orbits};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;

const RPM: f64 = std::f64::consts::PI / 30.0;
const SETTLE: f64 = 1.0;

/// A rigid shaft of one element with two disks, its end rotations held, on
/// two damped linear bearings standing on one damped pedestal (the frame),
/// with an unbalance at the left end: a linear system whose steady
/// response is the frequency-domain unbalance response.
fn rotor_on_frame() -> Rotor {
    let text = r#"
name = "rotor_on_frame"
speed_rpm = 3000
max_speed_rpm = 3600
[[materials]]
name = "steel"
youngs_modulus = 211e9
poisson_ratio = 0.3
density = 7810.0
[[shaft]]
length = 0.2
outer_diameter = 0.1
material = "steel"
elements = 1
[[disks]]
node = 1
mass = 30.0
polar_inertia = 0.4
diametral_inertia = 0.25
[[disks]]
node = 2
mass = 30.0
polar_inertia = 0.4
diametral_inertia = 0.25
[[bearings]]
name = "left"
type = "linear"
node = 1
kxx = 1e7
kyy = 1.5e7
cxx = 2e4
cyy = 2e4
pedestal = "frame"
[[bearings]]
name = "right"
type = "linear"
node = 2
kxx = 1e7
kyy = 1.5e7
cxx = 2e4
cyy = 2e4
pedestal = "frame"
[[pedestals]]
name = "frame"
mass = 80.0
kxx = 3e7
kyy = 5e7
cxx = 3e4
cyy = 3e4
[[supports]]
node = 1
fix = ["rx", "ry"]
[[supports]]
node = 2
fix = ["rx", "ry"]
[[unbalance]]
name = "left"
node = 1
magnitude = 1e-4
phase_deg = 0.0
"#;
    Rotor::new(RotorModel::from_toml(text, "frame.toml").unwrap()).unwrap()
}

/// The transient's steady orbit of each journal relative to the frame has
/// the peak-to-peak displacements of linear theory, `2 |X_j − X_h|` in `x`
/// and in `y` (`X` the complex unbalance response of the journal node and
/// of the pedestal), and `S_max` the orbit's major semi-axis: within 5e-4
/// (128 samples a revolution, so the peak sampled within `1 − cos(π/128)`
/// = 3e-4 of itself; the average-acceleration rule's period error at the
/// 0.08 ms steps, 5e-5; what is left of the start after 1 s, 50
/// revolutions of the damped modes; measured 9e-6 to 8e-5). The orbits with the anisotropic frame are ellipses,
/// so `x` and `y` differ and `S_max` is the major semi-axis, not either.
#[test]
fn the_transients_orbit_is_the_linear_unbalance_response_relative_to_the_housing() {
    let rotor = rotor_on_frame();
    let speed = 3000.0 * RPM;
    let case = OrbitCase {
        label: "operating".into(),
        speed,
        excitation: None,
        steady: true,
    };
    let orbits = shaft_orbits(&rotor, &case, SETTLE, 0.1).unwrap();
    let response = unbalance_response(&rotor, speed).unwrap();
    let housing = (response[response.len() - 2], response[response.len() - 1]);
    assert_eq!(orbits.bearings.len(), 2);
    for (orbit, node) in orbits.bearings.iter().zip([0, 1]) {
        let (x, y) = node_xy(&response, node);
        let (rx, ry) = (x - housing.0, y - housing.1);
        let want = [2.0 * rx.norm(), 2.0 * ry.norm()];
        for (i, (got, want)) in orbit.peak_to_peak.iter().zip(want).enumerate() {
            let error = (got / want - 1.0).abs();
            assert!(
                error <= 5e-4,
                "{} {i}: {got} against {want} ({error:e})",
                orbit.name
            );
        }
        // The ellipse's major semi-axis: the largest |Re((rx, ry) e^{iθ})|.
        let major = (0..3600)
            .map(|k| {
                let e =
                    nalgebra::Complex::from_polar(1.0, k as f64 * std::f64::consts::TAU / 3600.0);
                (rx * e).re.hypot((ry * e).re)
            })
            .fold(0.0, f64::max);
        let error = (orbit.s_max / major - 1.0).abs();
        assert!(
            error <= 5e-4,
            "{}: S_max {} against {major} ({error:e})",
            orbit.name,
            orbit.s_max
        );
        assert!(
            (orbit.peak_to_peak[0] / orbit.peak_to_peak[1] - 1.0).abs() > 0.05,
            "{:?}",
            orbit.peak_to_peak
        );
    }
}

/// A hydro unit's cases: the operating speed as modelled, with the field on
/// where its pull's own excitation is not 1, and the runaway speed with the
/// field off; a unit without a pull has no field case, and a model whose top
/// speed is its operating speed no runaway case.
#[test]
fn a_hydro_unit_is_shown_at_its_operating_speed_field_on_and_at_runaway() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("models/hydro_unit_brackets.toml");
    let model = RotorModel::from_file(&path).unwrap();
    let rotor = Rotor::new(model.clone()).unwrap();
    let cases = hydro_cases(&rotor, model.nominal_speed);
    let speeds: Vec<(f64, Option<f64>)> = cases
        .iter()
        .map(|c| (c.speed / RPM, c.excitation))
        .collect();
    assert_eq!(cases.len(), 3, "{cases:?}");
    assert!((speeds[0].0 - 300.0).abs() < 1e-9 && speeds[0].1.is_none());
    assert!((speeds[1].0 - 300.0).abs() < 1e-9 && speeds[1].1 == Some(1.0));
    assert!((speeds[2].0 - 600.0).abs() < 1e-9 && speeds[2].1 == Some(0.0));
    let steady: Vec<bool> = cases.iter().map(|c| c.steady).collect();
    assert_eq!(
        steady,
        [true, true, false],
        "runaway is no steady condition"
    );
    let plain = rotor_on_frame();
    let cases = hydro_cases(&plain, 3000.0 * RPM);
    assert_eq!(cases.len(), 2, "no pull: no field case; {cases:?}");
    assert_eq!(cases[1].excitation, None);
    assert!((cases[1].speed / RPM - 3600.0).abs() < 1e-9);
}

/// `[shaft_vibration_zones]`: the user's zone boundaries from their copy of
/// the standard, in µm, at the named bearings (default every bearing, not
/// the seal or the pull); a bad entry names file, line, field and value.
#[test]
fn shaft_vibration_zones_are_read_and_bad_ones_named() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("models/hydro_unit_brackets.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let with = |section: &str| format!("{text}\n{section}\n");
    let model = RotorModel::from_toml(
        &with("[shaft_vibration_zones]\nsource = \"my copy, table X\"\nboundaries_um = [65.0, 100.0, 160.0]\nbearings = [\"upper_guide\"]"),
        "unit.toml",
    )
    .unwrap();
    let zones = model.shaft_zones.clone().unwrap();
    assert_eq!(zones.source, "my copy, table X");
    for (got, want) in zones.boundaries.iter().zip([65e-6, 100e-6, 160e-6]) {
        assert!((got / want - 1.0).abs() < 1e-15, "{:?}", zones.boundaries);
    }
    let upper = model
        .bearings
        .iter()
        .position(|b| b.name == "upper_guide")
        .unwrap();
    assert_eq!(zones.bearings, [upper]);
    let info = rotor_bearing::report::text::model_summary(&Rotor::new(model.clone()).unwrap());
    assert!(
        info.contains("shaft vibration zones: A/B, B/C, C/D at 65 / 100 / 160 µm pk-pk at upper_guide (my copy, table X)"),
        "{info}"
    );
    let all = RotorModel::from_toml(
        &with("[shaft_vibration_zones]\nsource = \"s\"\nboundaries_um = [1.0, 2.0, 3.0]"),
        "unit.toml",
    )
    .unwrap();
    let bearings: Vec<&str> = all
        .shaft_zones
        .as_ref()
        .unwrap()
        .bearings
        .iter()
        .map(|&k| all.bearings[k].name.as_str())
        .collect();
    assert_eq!(bearings, ["upper_guide", "lower_guide", "turbine_guide"]);
    assert!(RotorModel::from_file(&path).unwrap().shaft_zones.is_none());
    for (section, field, value) in [
        (
            "source = \"s\"\nboundaries_um = [100.0, 65.0, 160.0]",
            "shaft_vibration_zones.boundaries_um",
            "[100, 65, 160]",
        ),
        (
            "source = \"s\"\nboundaries_um = [65.0, 100.0]",
            "shaft_vibration_zones.boundaries_um",
            "[65, 100]",
        ),
        (
            "source = \" \"\nboundaries_um = [65.0, 100.0, 160.0]",
            "shaft_vibration_zones.source",
            "\"\"",
        ),
        (
            "source = \"s\"\nboundaries_um = [65.0, 100.0, 160.0]\nbearings = [\"runner_seal\"]",
            "shaft_vibration_zones.bearings[0]",
            "runner_seal",
        ),
    ] {
        let e = RotorModel::from_toml(
            &with(&format!("[shaft_vibration_zones]\n{section}")),
            "unit.toml",
        )
        .unwrap_err()
        .to_string();
        assert!(
            e.contains("unit.toml") && e.contains(field) && e.contains(value),
            "{e}"
        );
        let line = e.split(':').nth(1).unwrap_or("");
        assert!(
            line.parse::<usize>().is_ok_and(|l| l > 200),
            "the line of the section: {e}"
        );
    }
    // A class other than a hydro one has no such zones.
    let jeffcott = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("models/jeffcott.toml"),
    )
    .unwrap();
    let e = RotorModel::from_toml(
        &format!("{jeffcott}\n[shaft_vibration_zones]\nsource = \"s\"\nboundaries_um = [65.0, 100.0, 160.0]\n"),
        "j.toml",
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("shaft_vibration_zones.source") && e.contains("hydro_generator"),
        "{e}"
    );
}
