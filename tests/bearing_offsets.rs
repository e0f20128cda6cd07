//! Bearings set off the nominal axis (`offset_x`, `offset_y`, issue 49): the
//! model file's keys and their errors and warnings, and the seam — every law
//! sees the journal relative to the displaced centre — checked on an exact
//! property: offsetting every bearing of a rotor by the same vector moves the
//! whole rotor rigidly by it (a rigid translation strains no shaft element),
//! for linear bearings (preload in the static load) and for fluid films
//! (the installed-bearing wrapper), in the statics and in time stepping.

use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::statics::equilibrium;
use rotor_bearing::solver::{Simulator, SolverOptions};

const RPM: f64 = std::f64::consts::PI / 30.0;

/// The Jeffcott rotor of `models/jeffcott.toml` (plain bearings at nodes 1
/// and 9, C = 100 µm) with `extra` added to both bearing entries.
fn jeffcott(extra: &str) -> String {
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/models/jeffcott.toml"))
            .unwrap();
    text.replace(
        "viscosity = 0.02            # Pa·s",
        &format!("viscosity = 0.02\n{extra}"),
    )
    .replace(
        "clearance = 100e-6\nviscosity = 0.02",
        &format!("clearance = 100e-6\nviscosity = 0.02\n{extra}"),
    )
}

/// The same rotor on linear bearings (1e8 N/m) with `extra` in each entry.
fn jeffcott_linear(extra: &str) -> String {
    let text = jeffcott("");
    let start = text.find("[[bearings]]").unwrap();
    let end = text.find("[[unbalance]]").unwrap();
    let bearing = |node: usize| {
        format!(
            "[[bearings]]\ntype = \"linear\"\nnode = {node}\nkxx = 1e8\nkyy = 1e8\ncxx = 1e3\ncyy = 1e3\n{extra}\n"
        )
    };
    format!(
        "{}{}{}{}",
        &text[..start],
        bearing(1),
        bearing(9),
        &text[end..]
    )
}

fn rotor(text: &str) -> Rotor {
    Rotor::new(RotorModel::from_toml(text, "m.toml").unwrap()).unwrap()
}

#[test]
fn a_non_finite_or_absurd_offset_is_refused_naming_file_line_field_and_value() {
    let text = jeffcott("offset_y = nan");
    let e = RotorModel::from_toml(&text, "m.toml")
        .unwrap_err()
        .to_string();
    let line = text
        .lines()
        .position(|l| l.starts_with("offset_y"))
        .unwrap()
        + 1;
    assert!(e.contains(&format!("m.toml:{line}")), "{e}");
    assert!(e.contains("bearings[0].offset_y"), "{e}");
    assert!(e.to_lowercase().contains("nan"), "{e}");
    let e = RotorModel::from_toml(&jeffcott("offset_x = 2.5"), "m.toml")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("bearings[0].offset_x") && e.contains("2.5"),
        "{e}"
    );
    // A pedestal's anchor, a rub's stator: the same checks.
    let rub = format!(
        "{}\n[[rubs]]\nnode = 5\ngap = 1e-3\noffset_x = inf\n",
        jeffcott("")
    );
    let e = RotorModel::from_toml(&rub, "m.toml")
        .unwrap_err()
        .to_string();
    assert!(e.contains("rubs[0].offset_x"), "{e}");
}

#[test]
fn an_offset_beyond_the_clearance_warns_that_the_journal_starts_in_contact() {
    let model = RotorModel::from_toml(&jeffcott("offset_y = 1.5e-4"), "m.toml").unwrap();
    let warnings: Vec<String> = model
        .plausibility_warnings()
        .iter()
        .map(|w| w.to_string())
        .collect();
    let offset: Vec<&String> = warnings.iter().filter(|w| w.contains("offset")).collect();
    assert_eq!(offset.len(), 2, "{warnings:?}");
    assert!(offset[0].starts_with("m.toml: bearings[0].offset_y = 0.00015"));
    assert!(offset[1].contains("bearings[1].offset_y") && offset[1].contains("contact"));
    // Within the clearance: no warning.
    let model = RotorModel::from_toml(&jeffcott("offset_y = 5e-5"), "m.toml").unwrap();
    assert!(
        !model
            .plausibility_warnings()
            .iter()
            .any(|w| w.field.contains("offset"))
    );
}

/// `u` (free DOFs, the Jeffcott rotor has no supports: 4 per node) less the
/// rigid translation `o` on every node's x and y.
fn less_translation(u: &[f64], o: [f64; 2]) -> Vec<f64> {
    u.iter()
        .enumerate()
        .map(|(i, v)| match i % 4 {
            0 => v - o[0],
            1 => v - o[1],
            _ => *v,
        })
        .collect()
}

fn largest_difference(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
}

/// Linear bearings: the offsets enter as the preload `K o` of the static
/// load; the linear solve is exact, so the shift is exact to round-off.
#[test]
fn equal_offsets_of_linear_bearings_translate_the_rotor_rigidly() {
    let o = [3e-5, -4e-4];
    let aligned = rotor(&jeffcott_linear(""));
    let shifted = rotor(&jeffcott_linear(&format!(
        "offset_x = {}\noffset_y = {}",
        o[0], o[1]
    )));
    let options = SolverOptions::default();
    let a = equilibrium(&aligned, 0.0, &options, None).unwrap();
    let b = equilibrium(&shifted, 0.0, &options, None).unwrap();
    let d = largest_difference(&less_translation(&b.displacement, o), &a.displacement);
    assert!(d < 1e-12 * 4e-4, "{d:e}");
    let lin = rotor_bearing::analysis::linear::static_deflection(&shifted).unwrap();
    let lin0 = rotor_bearing::analysis::linear::static_deflection(&aligned).unwrap();
    let d = largest_difference(&less_translation(&lin, o), &lin0);
    assert!(d < 1e-12 * 4e-4, "{d:e}");
    // Time stepping carries the same preload: from the shifted equilibrium
    // the rotor stays (without it, it would fall back by 400 µm).
    let mut sim = Simulator::new(shifted, options).unwrap();
    sim.set_unbalance(0, 0.0).unwrap();
    sim.settle_static().unwrap();
    let before = sim.state().u.clone();
    sim.advance_to(0.01).unwrap();
    let moved = largest_difference(&sim.state().u, &before);
    assert!(moved < 1e-12, "{moved:e}");
}

/// Fluid films: every film sees `q − o`, so the equilibrium of the shifted
/// line is the aligned one moved by `o` (to the statics' tolerance); a
/// transient started there stays (the time stepping sees the same centres).
#[test]
fn equal_offsets_of_film_bearings_translate_the_rotor_rigidly() {
    let o = [2e-5, 6e-5];
    let aligned = rotor(&jeffcott(""));
    let text = jeffcott(&format!("offset_x = {}\noffset_y = {}", o[0], o[1]));
    let shifted = rotor(&text);
    let options = SolverOptions::default();
    let speed = 3000.0 * RPM;
    let a = equilibrium(&aligned, speed, &options, None).unwrap();
    let b = equilibrium(&shifted, speed, &options, None).unwrap();
    let d = largest_difference(&less_translation(&b.displacement, o), &a.displacement);
    // The static Newton stops at a relative residual of 1e-10 (default
    // tolerance) of a ~100 N load on films of ~1e7 N/m: ~1e-15 m; allow 1e-12 m.
    assert!(d < 1e-12, "{d:e}");
    for ((_, ea), (_, eb)) in a.bearings.iter().zip(&b.bearings) {
        let df = (ea.force[0] - eb.force[0]).hypot(ea.force[1] - eb.force[1]);
        assert!(df < 1e-6 * ea.force[1].abs(), "{df:e}");
    }
    // Time stepping from the shifted equilibrium: the journals stay there.
    let mut sim = Simulator::new(shifted, options).unwrap();
    sim.set_speed(speed, 0.0).unwrap();
    sim.set_unbalance(0, 0.0).unwrap();
    sim.settle_static().unwrap();
    let before = sim.outputs().unwrap();
    sim.advance_to(0.01).unwrap();
    let after = sim.outputs().unwrap();
    for (p, q) in before.bearings.iter().zip(&after.bearings) {
        let moved = (p.x - q.x).hypot(p.y - q.y);
        assert!(moved < 1e-9, "{moved:e}");
        // Outputs: absolute journal; the film's report relative to the centre.
        let e = (p.x - o[0]).hypot(p.y - o[1]) / 100e-6;
        assert!((p.report.eccentricity - e).abs() < 1e-9, "{e}");
    }
}

/// The FMU's offset parameters (`bearings.<name>.offset_x`, `offset_y`, m):
/// appended after every earlier variable (only the bearings' loads come
/// after them), fixed (set before
/// initialization), and an FMU whose master sets them runs bit for bit as
/// the FMU of the model file that gives them; a reset restores the file's.
#[test]
fn fmu_offset_parameters_are_appended_fixed_and_act_as_the_model_file() {
    use rotor_bearing::fmi2::instance::{Instance, Status};
    use rotor_bearing::fmi2::variables::{Binding, Causality, Kind, Variability, variables};
    let plain = RotorModel::from_toml(&jeffcott(""), "m.toml").unwrap();
    let vars = variables(&plain);
    // Only the bearings' static and dynamic loads, five a bearing, come after.
    let end = vars.len() - 5 * plain.bearings.len();
    assert!(
        vars[end..]
            .iter()
            .all(|v| v.name.contains(".static_") || v.name.contains(".dynamic_"))
    );
    let names: Vec<&str> = vars[end - 4..end].iter().map(|v| v.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "bearings.left.offset_x",
            "bearings.left.offset_y",
            "bearings.right.offset_x",
            "bearings.right.offset_y"
        ]
    );
    let earlier = vars
        .iter()
        .take(end - 4)
        .all(|v| !matches!(v.binding, Binding::OffsetX(_) | Binding::OffsetY(_)));
    assert!(earlier);
    for v in &vars[end - 4..end] {
        assert_eq!(
            (v.causality, v.variability, v.unit, v.start),
            (
                Causality::Parameter,
                Variability::Fixed,
                Some("m"),
                Some(0.0)
            )
        );
        assert_eq!((v.min, v.max), (Some(-1.0), Some(1.0)));
    }
    let vr = |name: &str| {
        vars.iter()
            .find(|v| v.name == name)
            .unwrap()
            .value_reference
    };
    let offsets = [
        ("bearings.left.offset_x", 1e-5),
        ("bearings.left.offset_y", 2e-5),
        ("bearings.right.offset_y", -1e-5),
    ];
    let outputs = [
        "bearings.left.x",
        "bearings.left.y",
        "bearings.left.fx",
        "bearings.left.fy",
        "bearings.left.eccentricity",
        "bearings.right.y",
        "bearings.right.fy",
        "probes.disk.y",
    ];
    let run = |fmu: &mut Instance, set: &[(&str, f64)]| -> Vec<f64> {
        assert_eq!(
            fmu.set(vr("shaft.speed"), Kind::Real, 3000.0 * RPM),
            Status::Ok
        );
        for (name, value) in set {
            assert_eq!(fmu.set(vr(name), Kind::Real, *value), Status::Ok);
        }
        assert_eq!(fmu.setup_experiment(0.0, None), Status::Ok);
        assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
        assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
        assert_eq!(fmu.do_step(0.0, 0.005), Status::Ok);
        outputs
            .iter()
            .map(|name| fmu.get(vr(name), Kind::Real).unwrap())
            .collect()
    };
    let mut tuned = Instance::new("tuned", plain.clone()).unwrap();
    let by_parameter = run(&mut tuned, &offsets);
    let text = jeffcott("")
        .replacen(
            "name = \"left\"",
            "name = \"left\"\noffset_x = 1e-5\noffset_y = 2e-5",
            1,
        )
        .replacen("name = \"right\"", "name = \"right\"\noffset_y = -1e-5", 1);
    let filed = RotorModel::from_toml(&text, "m.toml").unwrap();
    assert_eq!(filed.bearings[0].offset, [1e-5, 2e-5]);
    assert_eq!(filed.bearings[1].offset, [0.0, -1e-5]);
    let mut from_file = Instance::new("file", filed).unwrap();
    let by_file = run(&mut from_file, &[]);
    assert_eq!(by_parameter, by_file);
    // The offsets moved the journals: not the aligned run.
    let mut aligned = Instance::new("aligned", plain.clone()).unwrap();
    let straight = run(&mut aligned, &[]);
    assert_ne!(straight, by_file);
    assert_eq!(
        tuned.get(vr("bearings.left.offset_y"), Kind::Real),
        Ok(2e-5)
    );
    // Fixed: refused once initialized; a reset restores the file's values.
    assert_eq!(
        tuned.set(vr("bearings.left.offset_y"), Kind::Real, 0.0),
        Status::Error
    );
    assert_eq!(tuned.reset(), Status::Ok);
    assert_eq!(run(&mut tuned, &[]), straight);
    assert_eq!(tuned.get(vr("bearings.left.offset_y"), Kind::Real), Ok(0.0));
    assert_eq!(tuned.reset(), Status::Ok);
    assert_eq!(
        tuned.set(vr("bearings.left.offset_y"), Kind::Real, 2.0),
        Status::Error,
        "beyond the declared maximum"
    );
}

/// The largest offset the FMU accepts (1 m, ten thousand clearances): the
/// initialization settles the journal onto its bushing or says it cannot,
/// in bounded time — never a panic or a hang (the FMU fuzzer's concern for
/// the new parameters, checked here on the safe instance).
#[test]
fn an_extreme_fmu_offset_is_settled_or_refused_quickly() {
    use rotor_bearing::fmi2::instance::{Instance, Status};
    use rotor_bearing::fmi2::variables::{Kind, variables};
    let plain = RotorModel::from_toml(&jeffcott(""), "m.toml").unwrap();
    let vars = variables(&plain);
    let vr = |name: &str| {
        vars.iter()
            .find(|v| v.name == name)
            .unwrap()
            .value_reference
    };
    for (speed, offset) in [(0.0, 1.0), (3000.0 * RPM, 1.0), (3000.0 * RPM, -1.0)] {
        let start = std::time::Instant::now();
        let mut fmu = Instance::new("extreme", plain.clone()).unwrap();
        assert_eq!(fmu.set(vr("shaft.speed"), Kind::Real, speed), Status::Ok);
        assert_eq!(
            fmu.set(vr("bearings.left.offset_y"), Kind::Real, offset),
            Status::Ok
        );
        assert_eq!(fmu.setup_experiment(0.0, None), Status::Ok);
        assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
        let status = fmu.exit_initialization_mode();
        let outcome = if status == Status::Ok {
            fmu.do_step(0.0, 0.001)
        } else {
            status
        };
        println!(
            "speed {speed}, offset {offset}: {status:?} then {outcome:?} in {:?}: {:?}",
            start.elapsed(),
            fmu.drain_messages().last()
        );
        assert!(start.elapsed() < std::time::Duration::from_secs(20));
        assert!(matches!(
            outcome,
            Status::Ok | Status::Warning | Status::Error | Status::Discard
        ));
    }
}
