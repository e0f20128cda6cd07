//! The FMU on a reduced rotor (issue 17): the `solver.reduced_modes`
//! parameter, its start value from the model's `[reduction]`, the log line
//! that says which rotor runs, rollback and the refusal of foreign states.

use rotor_bearing::fmi2::instance::{Instance, Status};
use rotor_bearing::fmi2::variables::{Kind, variables};
use rotor_bearing::model::{DEFAULT_REDUCED_MODES, RotorModel};

#[path = "common/fmu.rs"]
mod fmu;
use fmu::{model, vr};

/// Journal x, y of the first bearing every 1 ms over 0.2 s at 3000 rpm,
/// with `modes` set before initialization (`None`: left at its start value),
/// and the log lines of `logAll`.
fn journal_orbit(m: &RotorModel, modes: Option<f64>) -> (Vec<(f64, f64)>, Vec<String>) {
    let mut fmu = Instance::new("reduced", m.clone()).unwrap();
    if let Some(k) = modes {
        assert_eq!(
            fmu.set(vr(m, "solver.reduced_modes"), Kind::Integer, k),
            Status::Ok
        );
    }
    assert_eq!(
        fmu.set(vr(m, "shaft.speed"), Kind::Real, 314.159),
        Status::Ok
    );
    assert_eq!(fmu.setup_experiment(0.0, None), Status::Ok);
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
    let (x, y) = (vr(m, "bearings.left.x"), vr(m, "bearings.left.y"));
    let mut orbit = Vec::new();
    for k in 0..200 {
        assert_eq!(fmu.do_step(k as f64 * 1e-3, 1e-3), Status::Ok);
        orbit.push((
            fmu.get(x, Kind::Real).unwrap(),
            fmu.get(y, Kind::Real).unwrap(),
        ));
    }
    let log = fmu
        .drain_messages()
        .into_iter()
        .filter(|m| m.1 == "logAll")
        .map(|m| m.2)
        .collect();
    (orbit, log)
}

/// The parameter exists with the model's start value, selects the reduced
/// rotor, says so in the log, and the journal orbit stays within 1 % of the
/// full model's; after initialization it is fixed.
#[test]
fn reduced_modes_parameter_selects_and_reports_the_reduced_rotor() {
    let m = model("jeffcott");
    let var = variables(&m)
        .into_iter()
        .find(|v| v.name == "solver.reduced_modes")
        .unwrap();
    assert_eq!(
        (var.kind, var.start, var.min, var.max),
        (Kind::Integer, Some(0.0), Some(0.0), Some(1000.0))
    );
    let (full, log) = journal_orbit(&m, None);
    assert_eq!(log, vec!["full rotor: 36 DOFs".to_string()]);
    let (reduced, log) = journal_orbit(&m, Some(10.0));
    assert_eq!(log.len(), 2, "{log:?}");
    assert!(
        log[1].starts_with("reduced rotor (Craig–Bampton): 22 coordinates for 36 DOFs"),
        "{log:?}"
    );
    let size = full.iter().fold(0.0f64, |s, p| {
        s.max((p.0 - full[0].0).hypot(p.1 - full[0].1))
    });
    let diff = full
        .iter()
        .zip(&reduced)
        .fold(0.0f64, |s, (p, q)| s.max((p.0 - q.0).hypot(p.1 - q.1)));
    assert!(
        size > 1e-6 && diff < 0.01 * size,
        "{diff:e} against {size:e}"
    );

    let mut fmu = Instance::new("fixed", m.clone()).unwrap();
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
    assert_eq!(
        fmu.set(vr(&m, "solver.reduced_modes"), Kind::Integer, 4.0),
        Status::Error
    );
    let mut fmu = Instance::new("range", m.clone()).unwrap();
    assert_eq!(
        fmu.set(vr(&m, "solver.reduced_modes"), Kind::Integer, -1.0),
        Status::Error
    );
    let text = fmu.drain_messages().pop().unwrap().2;
    assert!(
        text.contains("solver.reduced_modes") && text.contains("-1"),
        "{text}"
    );
}

/// A model with `[reduction]` starts reduced (start value 10, the default),
/// and 0 sets it back to the full rotor; an input set before the change is kept.
#[test]
fn a_model_with_a_reduction_section_starts_reduced() {
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/models/jeffcott.toml"))
            .unwrap();
    let m =
        RotorModel::from_toml(&format!("{text}\n[reduction]\n"), "jeffcott_reduced.toml").unwrap();
    let var = variables(&m)
        .into_iter()
        .find(|v| v.name == "solver.reduced_modes")
        .unwrap();
    assert_eq!(var.start, Some(DEFAULT_REDUCED_MODES as f64));
    let mut fmu = Instance::new("r", m.clone()).unwrap();
    let log: Vec<String> = fmu.drain_messages().into_iter().map(|m| m.2).collect();
    assert!(log[0].contains("10 fixed-interface modes"), "{log:?}");
    assert_eq!(
        fmu.set(vr(&m, "shaft.speed"), Kind::Real, 200.0),
        Status::Ok
    );
    assert_eq!(
        fmu.set(vr(&m, "solver.reduced_modes"), Kind::Integer, 0.0),
        Status::Ok
    );
    let log: Vec<String> = fmu.drain_messages().into_iter().map(|m| m.2).collect();
    assert_eq!(log, vec!["full rotor: 36 DOFs".to_string()]);
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    assert_eq!(fmu.get(vr(&m, "shaft.speed"), Kind::Real), Ok(200.0));
    assert_eq!(
        fmu.get(vr(&m, "solver.reduced_modes"), Kind::Integer),
        Ok(0.0)
    );
}

/// Rollback on the reduced rotor repeats the run bit for bit; a state saved
/// with another mode count is refused with both counts named.
#[test]
fn reduced_rollback_is_bit_exact_and_foreign_states_are_refused() {
    let m = model("hydro_unit");
    let start = |modes: f64| {
        let mut fmu = Instance::new("rb", m.clone()).unwrap();
        assert_eq!(
            fmu.set(vr(&m, "solver.reduced_modes"), Kind::Integer, modes),
            Status::Ok
        );
        assert_eq!(
            fmu.set(vr(&m, "shaft.speed"), Kind::Real, 15.708),
            Status::Ok
        );
        assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
        assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
        fmu
    };
    let mut fmu = start(10.0);
    let x = vr(&m, "bearings.generator_guide.x");
    assert_eq!(fmu.do_step(0.0, 0.013), Status::Ok);
    let saved = fmu.snapshot().unwrap();
    let bytes = fmu.serialize(&saved).unwrap();
    assert_eq!(fmu.do_step(0.013, 0.037), Status::Ok);
    let first = fmu.get(x, Kind::Real).unwrap();
    assert_eq!(fmu.restore(&saved), Status::Ok);
    assert_eq!(fmu.do_step(0.013, 0.037), Status::Ok);
    assert_eq!(fmu.get(x, Kind::Real).unwrap().to_bits(), first.to_bits());

    let mut other = start(4.0);
    assert!(other.deserialize(&bytes).is_err());
    let text = other.drain_messages().pop().unwrap().2;
    assert!(
        text.contains("solver.reduced_modes = 10") && text.contains("runs 4"),
        "{text}"
    );
    assert_eq!(other.restore(&saved), Status::Error);
}
