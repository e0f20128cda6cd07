//! Newton iterations per step (issue 51): over a run of every shipped model
//! at its operating speed (`speed_rpm`; the torque-driven hydro unit through
//! its speed-driven twin), field off and on where the model has a magnetic
//! pull, and of a vertical rotor whose pads are all unpreloaded and nearly
//! unloaded (the vertical rotor with a tilting-pad bearing of preload 0 in
//! place of its plain one), the simulator's `StepStats` count the Newton
//! iterations a step at the FMU's defaults (accuracy-controlled steps at a
//! local error tolerance of 3e-3, at most 12 a revolution at the top speed). Each run starts from the static equilibrium
//! and is counted over the 10 s after its first second (the start
//! transient): the 10 s run; the whole file takes about 2 s.
//!
//! Target: at most 3 iterations a step on average. Measured over those
//! 10 s: before any rule, with the slow-contraction rule
//! (`solver/slow_pads.rs`), and now with each pad settled on its own
//! balance once an iteration contracts slowly (`solver/pad_balance.rs`):
//!
//! | run | before | Aitken rule | pads settled |
//! |---|---:|---:|---:|
//! | classic_disk_rotor, classic_disk_rotor_damped | 1.34, 1.00 | the same | the same |
//! | hydro_unit, hydro_unit_torque (speed-driven), hydro_unit_plain | 2.56, 2.56, 2.996 | the same | the same |
//! | hydro_unit_three_guide, jeffcott | 2.29, 2.00 | the same | the same |
//! | hydro_unit_three_guide_offset (turbine guide 0.12 mm off, added later) | – | – | 2.27 |
//! | hydro_unit_brackets, field off / on | 17.48 / 17.55 | 15.10 / 15.43 | 2.37 / 2.45 |
//! | vertical_rotor (plain bearing) | 4.83 | 4.83 | 4.83 |
//! | vertical rotor on unpreloaded pads | 14.26 | 12.71 | 3.95 |
//!
//! With the accuracy control's growth window and held plan
//! (`solver/adaptive.rs`) the vertical rotors take 4.45 and 3.81 (3083 and
//! 3266 steps); every other row stays at or below 3. With no chord
//! iteration tried for 16 steps after one is refused (`CHORD_PAUSE`,
//! `solver/newton.rs`) they take 3.89 and 3.65, the hydro unit on plain
//! bearings 2.70 (was 2.77); every other row is unchanged, bit for bit.
//!
//! The target is not met on the last two rows yet (issue 51 stays open for
//! them: the plain bearing's slow iterations are not the pads'):
//! `the_runs_not_yet_at_the_target_meet_it` states it and is ignored, and
//! `the_runs_not_yet_at_the_target_keep_the_rules_gain` holds each of them
//! within 5 % of its count now.

use std::path::PathBuf;

use rotor_bearing::model::{Drive, RotorModel};
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::time_step::{DEFAULT_LOCAL_ERROR_TOLERANCE, largest_adaptive_step};
use rotor_bearing::solver::{Simulator, SolverOptions};

/// Seconds counted, after the first second's start transient.
const COUNTED: f64 = 10.0;

/// The target: Newton iterations a step, on average.
const TARGET: f64 = 3.0;

/// Bounds of the runs not at the target yet (iterations a step): 5 % above
/// the counts measured with the pads settled on their own balance (module
/// docs).
const VERTICAL_PLAIN: f64 = 4.1;
const VERTICAL_PADS: f64 = 3.85;

fn model(name: &str) -> RotorModel {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("models/{name}.toml"));
    RotorModel::from_file(&path).unwrap()
}

/// The vertical rotor with its plain bearing replaced by eight unpreloaded
/// tilting pads of the same bore, length, clearance and oil: a vertical
/// shaft puts no static radial load on them, only the small unbalance does.
fn vertical_unpreloaded_pads() -> RotorModel {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/vertical_rotor.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let plain = "type = \"plain\"";
    assert!(text.contains(plain));
    let pads = "type = \"tilting_pad\"\npads = 8\nfirst_pivot_deg = 22.5\n\
                pad_arc_deg = 36.0\npivot_offset = 0.5\npreload = 0.0";
    // One file a call: the tests run in parallel.
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let file = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("vertical_pads_{}_{call}.toml", std::process::id()));
    std::fs::write(&file, text.replace(plain, pads)).unwrap();
    let model = RotorModel::from_file(&file).unwrap();
    std::fs::remove_file(&file).ok();
    model
}

/// Newton iterations a step over the [`COUNTED`] seconds after the first of a run of `model` at
/// its operating speed from the static equilibrium, with every magnetic
/// pull at `excitation` (if given), and the step count.
fn iterations_per_step(mut model: RotorModel, excitation: Option<f64>) -> (f64, usize) {
    model.drive = Drive::Speed;
    if let Some(e) = excitation {
        let pulls = model
            .bearings
            .iter_mut()
            .filter_map(|b| b.kind.set_excitation(e).then_some(()))
            .count();
        assert!(pulls > 0);
    }
    let mut sim = settled_at_speed(model);
    sim.advance_to(1.0).unwrap();
    let before = sim.stats();
    sim.advance_to(1.0 + COUNTED).unwrap();
    let after = sim.stats();
    let steps = after.steps - before.steps;
    println!(
        "  {:.2} single-pad film evaluations a step (pads settled on their own balance)",
        (after.pad_evaluations - before.pad_evaluations) as f64 / steps as f64
    );
    (
        (after.iterations - before.iterations) as f64 / steps as f64,
        steps,
    )
}

/// A simulator of `model` at its operating speed at the FMU's defaults
/// (accuracy-controlled steps up to 12 a revolution at the top speed),
/// settled on its static equilibrium.
fn settled_at_speed(model: RotorModel) -> Simulator {
    let speed = model.nominal_speed;
    let mut sim = at_fmu_defaults(model);
    sim.set_speed(speed, 0.0).unwrap();
    sim.settle_static().unwrap();
    sim
}

/// A simulator of `model` at the FMU's defaults: accuracy-controlled steps
/// up to 12 a revolution at the top speed, the FMU's local error tolerance.
fn at_fmu_defaults(model: RotorModel) -> Simulator {
    let options = SolverOptions {
        time_step: largest_adaptive_step(&model, None),
        local_error_tolerance: DEFAULT_LOCAL_ERROR_TOLERANCE,
        ..SolverOptions::default()
    };
    Simulator::new(Rotor::new(model).unwrap(), options).unwrap()
}

/// Every shipped model's file name, and whether it has a magnetic pull.
fn shipped() -> Vec<(String, bool)> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models");
    let mut names: Vec<(String, bool)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| {
            let name = p.file_stem().unwrap().to_string_lossy().into_owned();
            let pull = model(&name)
                .bearings
                .iter()
                .any(|b| b.kind.clone().set_excitation(1.0));
            (name, pull)
        })
        .collect();
    names.sort();
    names
}

/// The runs that do not meet the target yet (issue 51 stays open): the
/// shipped vertical rotor on its plain bearing, and the vertical rotor on
/// unpreloaded pads.
const NOT_YET: [&str; 1] = ["vertical_rotor"];

/// Every run of the test: a name, the model, the field.
fn runs() -> Vec<(String, RotorModel, Option<f64>)> {
    let mut runs = Vec::new();
    for (name, pull) in shipped() {
        let fields: &[Option<f64>] = if pull {
            &[Some(0.0), Some(1.0)]
        } else {
            &[None]
        };
        for &field in fields {
            runs.push((name.clone(), model(&name), field));
        }
    }
    runs.push(("vertical_pads".into(), vertical_unpreloaded_pads(), None));
    runs
}

/// Newton iterations a step of every run whose name is (`slow`) or is not
/// in [`NOT_YET`] (the vertical rotor on pads counts as not yet).
fn counts(slow: bool) -> Vec<(String, Option<f64>, f64)> {
    runs()
        .into_iter()
        .filter(|(name, _, _)| {
            (NOT_YET.contains(&name.as_str()) || name == "vertical_pads") == slow
        })
        .map(|(name, model, field)| {
            let (per_step, steps) = iterations_per_step(model, field);
            println!(
                "{name} (field {field:?}): {per_step:.3} iterations a step over {steps} steps"
            );
            (name, field, per_step)
        })
        .collect()
}

#[test]
fn every_shipped_model_takes_at_most_three_iterations_a_step() {
    let counted = counts(false);
    assert!(counted.len() >= 9, "{counted:?}");
    let over: Vec<_> = counted.iter().filter(|c| c.2 > TARGET).collect();
    assert!(over.is_empty(), "above {TARGET} a step: {over:?}");
}

/// What the settled pads gained where the target is not met yet: each run
/// within 5 % of its count now (module docs; the plain-bearing vertical
/// rotor, which the rule does not touch, is held where it is).
#[test]
fn the_runs_not_yet_at_the_target_keep_the_rules_gain() {
    let bound = |name: &str| match name {
        "vertical_rotor" => VERTICAL_PLAIN,
        _ => VERTICAL_PADS,
    };
    for (name, field, per_step) in counts(true) {
        assert!(
            per_step <= bound(&name),
            "{name} (field {field:?}): {per_step:.2}"
        );
    }
}

#[test]
#[ignore = "issue 51: the vertical rotors still take 3.89 and 3.65 iterations a step"]
fn the_runs_not_yet_at_the_target_meet_it() {
    let over: Vec<_> = counts(true).into_iter().filter(|c| c.2 > TARGET).collect();
    assert!(over.is_empty(), "above {TARGET} a step: {over:?}");
}

/// A start-up of every shipped model on tilting pads: from the static
/// equilibrium at standstill, a linear run-up to its operating speed in
/// 10 s at the FMU's defaults. Every step of a run-up changes the speed; a
/// unit with more than 8 journal DOFs used to take those steps on the stale
/// factorization, where no pad settles on its own balance: the unit on
/// brackets took 26.6 iterations a step (37 step halvings) and takes 2.17
/// now that pads refactor (`solver/factor.rs`).
#[test]
fn run_ups_on_pads_take_at_most_three_iterations_a_step() {
    let mut counted = Vec::new();
    for (name, _) in shipped() {
        let mut model = model(&name);
        let pads = model
            .bearings
            .iter()
            .any(|b| matches!(b.kind, rotor_bearing::bearing::BearingKind::TiltingPad(_)));
        if !pads {
            continue;
        }
        model.drive = Drive::Speed;
        let rated = model.nominal_speed;
        let mut sim = at_fmu_defaults(model);
        sim.set_speed(0.0, 0.0).unwrap();
        sim.settle_static().unwrap();
        sim.set_speed(0.0, rated / 10.0).unwrap();
        sim.advance_to(10.0).unwrap();
        let stats = sim.stats();
        let per_step = stats.iterations as f64 / stats.steps as f64;
        println!("{name}: run-up {per_step:.2} iterations a step, {stats:?}");
        assert_eq!(stats.step_cuts, 0, "{name}: {stats:?}");
        counted.push((name, per_step));
    }
    assert!(counted.len() >= 4, "{counted:?}");
    let over: Vec<_> = counted.iter().filter(|c| c.1 > TARGET).collect();
    assert!(over.is_empty(), "above {TARGET} a step: {over:?}");
}

/// The torque-driven hydro unit coasting from its operating speed (no torque
/// inputs, the bearings' and thrust bearing's friction slowing it): every
/// step changes the speed, so each lateral solve refactors, and the lateral
/// and torsional steps are iterated on their coupling torques. The second
/// lateral solve of each step, for a coupling change that calls for about
/// 3e-13 rad of twist, is taken by the torsional correction instead
/// (`solver/torsion.rs`, `absorb_coupling_change`): 4.0 iterations and 2.0
/// factorizations a step before, 2.0 and 1.0 then. A speed change within
/// a gyroscopic phase `|ΔΩ| h` of 1e-3 of the factorization's is now not
/// refactored but corrected for its gyroscopic term (`solver/factor.rs`,
/// `GYROSCOPIC_PHASE_BAND`): 0.007 factorizations a step (bound 0.1; 0.043
/// with the relative band of 1e-4 before it). The run agrees with one at a Newton
/// tolerance of 1e-12 (where the correction is seldom small enough and the
/// coupling is iterated, 4.8 iterations a step, and the gyroscopic
/// correction, moving a journal by more than that tolerance, mostly sends the
/// step back to a factorization at its speed): displacements within 1e-7 of
/// their range (3.1e-8 measured; 3.7e-9 with the relative band, 2.4e-9
/// refactoring every step), the speed within 1e-10 of itself (8.7e-12).
#[test]
fn a_torque_driven_coast_takes_one_lateral_solve_a_step() {
    let run = |tolerance: f64| {
        let model = model("hydro_unit_torque");
        assert_eq!(model.drive, Drive::Torque);
        let speed = model.nominal_speed;
        let options = SolverOptions {
            time_step: largest_adaptive_step(&model, None),
            local_error_tolerance: DEFAULT_LOCAL_ERROR_TOLERANCE,
            tolerance,
            ..SolverOptions::default()
        };
        let mut sim = Simulator::new(Rotor::new(model).unwrap(), options).unwrap();
        sim.set_speed(speed, 0.0).unwrap();
        sim.settle_static().unwrap();
        let mut trace = Vec::new();
        let mut counted = None;
        for k in 1..=600 {
            sim.advance_to(k as f64 * 5e-3).unwrap();
            if k == 200 {
                counted = Some(sim.stats());
            }
            let s = sim.state();
            trace.push((s.u.clone(), s.twist_rate.iter().sum::<f64>()));
        }
        let (before, after) = (counted.unwrap(), sim.stats());
        let steps = (after.steps - before.steps) as f64;
        (
            trace,
            (after.iterations - before.iterations) as f64 / steps,
            (after.factorizations - before.factorizations) as f64 / steps,
        )
    };
    let (fast, iterations, factorizations) = run(SolverOptions::default().tolerance);
    println!("{iterations:.3} iterations, {factorizations:.3} factorizations a step");
    assert!(iterations <= 2.2, "{iterations}");
    assert!(factorizations <= 0.1, "{factorizations}");
    let (tight, tight_iterations, _) = run(1e-12);
    println!("at a tolerance of 1e-12: {tight_iterations:.3} iterations a step");
    let n = fast[0].0.len();
    let range = |trace: &[(Vec<f64>, f64)], i: usize| {
        let (lo, hi) = trace
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), t| {
                (l.min(t.0[i]), h.max(t.0[i]))
            });
        hi - lo
    };
    let mut worst = 0.0_f64;
    for i in 0..n {
        let r = range(&tight, i);
        if r > 0.0 {
            let d = fast
                .iter()
                .zip(&tight)
                .fold(0.0_f64, |m, (a, b)| m.max((a.0[i] - b.0[i]).abs()));
            worst = worst.max(d / r);
        }
    }
    let speed = fast
        .iter()
        .zip(&tight)
        .fold(0.0_f64, |m, (a, b)| m.max(((a.1 - b.1) / b.1).abs()));
    println!("against 1e-12: displacements {worst:.2e} of their range, speed {speed:.2e}");
    assert!(worst <= 1e-7, "{worst:e}");
    assert!(speed <= 1e-10, "{speed:e}");
}

/// The pause of chord iterations after a refused one goes with the state:
/// the whirling vertical rotor, stopped where a pause is running, saved,
/// run on, restored and run on again, ends bit for bit where it ended the
/// first time; a state whose pause is not a whole number of steps within
/// the rule's is refused by name.
#[test]
fn a_restored_state_keeps_its_chord_pause() {
    let mut model = model("vertical_rotor");
    model.drive = Drive::Speed;
    let mut sim = settled_at_speed(model);
    let mut t = 1.0;
    sim.advance_to(t).unwrap();
    // A communication point inside a pause (every step of this rotor refuses one).
    while sim.state().chord_pause == 0.0 {
        t += 1e-3;
        sim.advance_to(t).unwrap();
    }
    let saved = sim.state().clone();
    sim.advance_to(t + 0.2).unwrap();
    let first = sim.state().u.clone();
    let mut restored = saved.clone();
    sim.set_state(restored.clone()).unwrap();
    sim.advance_to(t + 0.2).unwrap();
    assert_eq!(first, sim.state().u, "the restored run left the first");
    // The same state with no pause runs on other iterates (not bit for bit):
    // the pause is what the state carried.
    restored.chord_pause = 0.0;
    sim.set_state(restored.clone()).unwrap();
    sim.advance_to(t + 0.2).unwrap();
    assert_ne!(first, sim.state().u);
    for bad in [0.5, -1.0, 17.0] {
        restored.chord_pause = bad;
        let e = sim.set_state(restored.clone()).unwrap_err().to_string();
        assert!(e.contains("chord_pause"), "{e}");
    }
}
