//! The FMU on a reduced rotor (issue 17): the `solver.reduced_modes`
//! parameter, its start value from the model's `[reduction]`, the log line
//! that says which rotor runs, rollback, and states restored across mode
//! counts (issue 22).

use rotor_bearing::fmi2::instance::{Instance, Phase, Status};
use rotor_bearing::fmi2::variables::{Kind, variables};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;

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

/// A model with `[reduction]` starts reduced, with as many modes as its speed
/// range needs (4 for the Jeffcott rotor at 3000 rpm: the first four, a
/// degenerate group at 2651.9 Hz, reach ten times 50 Hz), and 0 sets it back
/// to the full rotor; an input set before the change is kept.
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
    assert_eq!(var.start, Some(4.0));
    assert_eq!(Rotor::transient_modes(&m), Ok(4));
    let mut fmu = Instance::new("r", m.clone()).unwrap();
    let log: Vec<String> = fmu.drain_messages().into_iter().map(|m| m.2).collect();
    assert!(
        log[0].contains("4 fixed-interface modes up to 2651.9 Hz, valid for motion up to 265.2 Hz"),
        "{log:?}"
    );
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

/// An instance of `m` at `modes`, initialized at 150 rpm.
fn started(m: &RotorModel, modes: f64) -> Instance {
    let mut fmu = Instance::new("rb", m.clone()).unwrap();
    assert_eq!(
        fmu.set(vr(m, "solver.reduced_modes"), Kind::Integer, modes),
        Status::Ok
    );
    assert_eq!(
        fmu.set(vr(m, "shaft.speed"), Kind::Real, 15.708),
        Status::Ok
    );
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
    fmu.drain_messages();
    fmu
}

/// The outputs `x` after each of `steps` steps of 0.011 s from `t`.
fn continue_run(fmu: &mut Instance, x: u32, t: f64, steps: usize) -> Vec<u64> {
    (0..steps)
        .map(|k| {
            assert_eq!(fmu.do_step(t + k as f64 * 0.011, 0.011), Status::Ok);
            fmu.get(x, Kind::Real).unwrap().to_bits()
        })
        .collect()
}

/// Rollback on the reduced rotor repeats the run bit for bit.
#[test]
fn reduced_rollback_is_bit_exact() {
    let m = model("hydro_unit");
    let mut fmu = started(&m, 10.0);
    let x = vr(&m, "bearings.generator_guide.x");
    assert_eq!(fmu.do_step(0.0, 0.013), Status::Ok);
    let saved = fmu.snapshot().unwrap();
    let first = continue_run(&mut fmu, x, 0.013, 3);
    assert_eq!(fmu.restore(&saved), Status::Ok);
    assert_eq!(continue_run(&mut fmu, x, 0.013, 3), first);
}

/// Issue 22: the FMU state includes the parameters (FMI 2.0 §2.1.8), so a
/// state saved with another `solver.reduced_modes` is restored with the
/// rotor it was saved on (rebuilt), in both directions, between the full and
/// a reduced rotor, in memory and serialized: the instance then runs exactly
/// as the one that saved it, reports the state's mode count, logs the rotor
/// it now runs, and is never left in the error state. (It was refused with
/// fmi2Error.)
#[test]
fn states_restore_across_mode_counts_in_both_directions() {
    let m = model("hydro_unit");
    let x = vr(&m, "bearings.generator_guide.x");
    let modes = vr(&m, "solver.reduced_modes");
    for (saved_with, running) in [(10.0, 4.0), (4.0, 10.0), (0.0, 10.0), (10.0, 0.0)] {
        let mut source = started(&m, saved_with);
        assert_eq!(source.do_step(0.0, 0.013), Status::Ok);
        let state = source.snapshot().unwrap();
        let bytes = source.serialize(&state).unwrap();
        let want = continue_run(&mut source, x, 0.013, 3);
        for serialized in [false, true] {
            let mut other = started(&m, running);
            assert_eq!(other.do_step(0.0, 0.005), Status::Ok);
            let state = if serialized {
                other.deserialize(&bytes).unwrap()
            } else {
                state.clone()
            };
            assert_eq!(
                other.restore(&state),
                Status::Ok,
                "{saved_with} → {running}: {:?}",
                other.drain_messages()
            );
            assert_eq!(other.phase(), Phase::StepComplete);
            assert_eq!(other.get(modes, Kind::Integer), Ok(saved_with));
            let log: Vec<String> = other.drain_messages().into_iter().map(|m| m.2).collect();
            let expected = if saved_with == 0.0 {
                "full rotor: 80 DOFs".to_string()
            } else {
                format!("{} fixed-interface modes", saved_with)
            };
            assert!(
                log.len() == 1 && log[0].contains(&expected),
                "{saved_with} → {running}: {log:?}"
            );
            assert_eq!(
                continue_run(&mut other, x, 0.013, 3),
                want,
                "{saved_with} → {running}, serialized {serialized}"
            );
            // And back: the instance's own earlier state brings its first rotor back.
            assert_eq!(other.restore(&state), Status::Ok);
        }
    }
    // A state saved before fmi2Reset and a change of the mode count.
    let mut fmu = started(&m, 10.0);
    let state = fmu.snapshot().unwrap();
    let want = continue_run(&mut fmu, x, 0.0, 2);
    assert_eq!(fmu.terminate(), Status::Ok);
    assert_eq!(fmu.reset(), Status::Ok);
    assert_eq!(fmu.set(modes, Kind::Integer, 4.0), Status::Ok);
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
    assert_eq!(fmu.restore(&state), Status::Ok);
    assert_eq!(continue_run(&mut fmu, x, 0.0, 2), want);
}

/// 999 and 1000 modes build the same rotor (the Jeffcott rotor's interior has
/// 24 DOFs): their states interoperate without a rebuild, and the restored
/// instance reports the state's count.
#[test]
fn mode_counts_that_build_the_same_rotor_interoperate() {
    let m = model("jeffcott");
    let x = vr(&m, "bearings.left.x");
    let modes = vr(&m, "solver.reduced_modes");
    for (saved_with, running) in [(1000.0, 999.0), (999.0, 1000.0), (24.0, 1000.0)] {
        let mut source = started(&m, saved_with);
        assert_eq!(source.do_step(0.0, 0.013), Status::Ok);
        let state = source.snapshot().unwrap();
        let bytes = source.serialize(&state).unwrap();
        let want = continue_run(&mut source, x, 0.013, 3);
        let mut other = started(&m, running);
        let state = other.deserialize(&bytes).unwrap();
        assert_eq!(other.restore(&state), Status::Ok);
        assert!(
            other.drain_messages().is_empty(),
            "the same rotor is not rebuilt"
        );
        assert_eq!(other.get(modes, Kind::Integer), Ok(saved_with));
        assert_eq!(continue_run(&mut other, x, 0.013, 3), want);
    }
}

/// Issue 22: the reduced rotor says when it leaves the range it is validated
/// for. The hydro unit on 6 modes (its pairs at 22.2, 61.5 and 70.4 Hz,
/// valid up to 7.0 Hz = 422 rpm) runs at 300 rpm without a word; at 600 rpm the step returns
/// fmi2Warning once, with the speed, the limit, the error estimate there and
/// the mode count that would reach it; back at 150 rpm (below half the limit)
/// it is re-armed, and the next excursion is reported again.
#[test]
fn leaving_the_validated_range_is_an_fmi2_warning_once_per_excursion() {
    let m = model("hydro_unit");
    let speed = vr(&m, "shaft.speed");
    let mut fmu = Instance::new("range", m.clone()).unwrap();
    assert_eq!(
        fmu.set(vr(&m, "solver.reduced_modes"), Kind::Integer, 6.0),
        Status::Ok
    );
    assert_eq!(
        fmu.set(speed, Kind::Real, 300.0 * std::f64::consts::PI / 30.0),
        Status::Ok
    );
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
    fmu.drain_messages();
    let run = |fmu: &mut Instance, rpm: f64, steps: usize| -> Vec<(Status, String)> {
        assert_eq!(
            fmu.set(speed, Kind::Real, rpm * std::f64::consts::PI / 30.0),
            Status::Ok
        );
        let mut warnings = Vec::new();
        for _ in 0..steps {
            let t = fmu.last_successful_time().unwrap();
            let status = fmu.do_step(t, 0.01);
            assert!(
                matches!(status, Status::Ok | Status::Warning),
                "{status:?}: {:?}",
                fmu.drain_messages()
            );
            let logged: Vec<String> = fmu
                .drain_messages()
                .into_iter()
                .filter(|m| m.0 == Status::Warning)
                .map(|m| {
                    assert_eq!(m.1, "logStatusWarning");
                    m.2
                })
                .collect();
            assert_eq!(status == Status::Warning, !logged.is_empty());
            warnings.extend(logged.into_iter().map(|text| (status, text)));
        }
        warnings
    };
    let first = run(&mut fmu, 300.0, 100);
    assert!(first.is_empty(), "{first:#?}");
    let out = run(&mut fmu, 600.0, 100);
    assert_eq!(out.len(), 1, "{out:#?}");
    let text = &out[0].1;
    for part in [
        "the running speed 600 rpm (10.0 Hz) is above the 7.0 Hz (422 rpm) the reduced rotor is validated for (its highest kept mode, 70.4 Hz, over 10)",
        "its response at the kept nodes differs from the full rotor's by",
        "fixed-interface modes reach it",
        "solver.reduced_modes = 6 (0 runs the full rotor)",
    ] {
        assert!(text.contains(part), "{part}\n{text}");
    }
    assert!(run(&mut fmu, 150.0, 50).is_empty());
    assert_eq!(run(&mut fmu, 600.0, 50).len(), 1);
    // The full rotor never warns.
    let mut full = Instance::new("full", m.clone()).unwrap();
    assert_eq!(full.set(speed, Kind::Real, 62.8), Status::Ok);
    assert_eq!(full.enter_initialization_mode(), Status::Ok);
    assert_eq!(full.exit_initialization_mode(), Status::Ok);
    assert!(run(&mut full, 600.0, 50).is_empty());
}

/// The motion itself is watched: the damped classic rotor on 4 modes (valid
/// up to 11.1 Hz) at 334 rpm (5.6 Hz) rings at its first natural frequency
/// (about 18 Hz) after the start, and the reduced rotor's orbits are then far
/// from the full rotor's: a warning names the motion's frequency.
#[test]
fn motion_beyond_the_validated_range_is_warned() {
    let m = model("classic_disk_rotor_damped");
    let mut fmu = Instance::new("motion", m.clone()).unwrap();
    assert_eq!(
        fmu.set(vr(&m, "solver.reduced_modes"), Kind::Integer, 4.0),
        Status::Ok
    );
    assert_eq!(fmu.set(vr(&m, "shaft.speed"), Kind::Real, 35.0), Status::Ok);
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
    fmu.drain_messages();
    let mut warnings = Vec::new();
    for k in 0..500 {
        if fmu.do_step(k as f64 * 1e-3, 1e-3) == Status::Warning {
            warnings.extend(
                fmu.drain_messages()
                    .into_iter()
                    .filter(|m| m.0 == Status::Warning),
            );
        }
    }
    assert_eq!(warnings.len(), 1, "{warnings:#?}");
    assert!(
        warnings[0]
            .2
            .contains("the motion at the kept nodes (RMS frequency")
            && warnings[0].2.contains("above the 11.1 Hz (668 rpm)"),
        "{}",
        warnings[0].2
    );
}
