//! A Newmark step's cost tied to its floor (issue 51): for every shipped
//! model at the FMU's defaults (accuracy-controlled steps, at most 12 a
//! revolution at the top speed, the local error tolerance of the FMU),
//! communication every 5 ms, the wall-clock time per internal step against
//! the floor of that unit measured in the same run at the same state: one
//! force-and-Jacobian pass of every nonlinear element
//! (`Simulator::force_and_jacobian_pass`) plus one banded solve with the
//! steps' factorization (`Simulator::banded_solve`). Runs:
//!
//! - steady running: rated speed from the static equilibrium, measured over
//!   the 4 s after the first second;
//! - start-up from rest: the static equilibrium at standstill (a horizontal
//!   rotor's journals resting on their bearings' contact law, a vertical
//!   unit's pads unloaded), then a linear run-up to rated speed in 10 s,
//!   measured over its first 4 s;
//! - field switching (units with a magnetic pull): steady running with the
//!   field off, then excitation 1 at once, measured over the 2 s after the
//!   switch;
//! - contact: steady running with every unbalance ten times the model's,
//!   measured over 2 s after the first second (the rows say whether a
//!   journal touched its bearing: film down to 0).
//!
//! Each window in five segments, the floor measured after each at the
//! state it ends on; medians over the segments (the ratio the median of
//! the segments' ratios). The table also gives the internal steps a
//! communication point takes and the floor of a point, `steps a point ×
//! (pass + solve)`: what a point costs at that step count even if every step
//! were one pass and one solve, the bound below any plant-loop cost at the
//! FMU's default accuracy. `cargo bench --bench step_floor`.

use std::path::PathBuf;
use std::time::Instant;

use rotor_bearing::model::{Drive, RotorModel};
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::time_step::{DEFAULT_LOCAL_ERROR_TOLERANCE, largest_adaptive_step};
use rotor_bearing::solver::{Simulator, SolverOptions};

const COMM: f64 = 5e-3;

fn shipped() -> Vec<(String, RotorModel)> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models");
    let mut models: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| {
            let name = p.file_stem().unwrap().to_string_lossy().into_owned();
            (name, RotorModel::from_file(&p).unwrap())
        })
        .collect();
    models.sort_by(|a, b| a.0.cmp(&b.0));
    models
}

fn simulator(model: &RotorModel) -> Simulator {
    let options = SolverOptions {
        time_step: largest_adaptive_step(model, None),
        local_error_tolerance: DEFAULT_LOCAL_ERROR_TOLERANCE,
        ..SolverOptions::default()
    };
    Simulator::new(Rotor::new(model.clone()).unwrap(), options).unwrap()
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Cost of the steps over `[from, to]` at communication points every
/// [`COMM`] against the floor: the window in five segments, each followed by
/// the floor measured at the state it ends on (so that a load on the machine
/// weighs on both); returns the medians over the segments of µs per step,
/// µs per force-and-Jacobian pass, µs per banded solve and their ratio, the
/// Newton iterations a step, the steps and the steps a communication point.
fn measure(sim: &mut Simulator, from: f64, to: f64) -> [f64; 7] {
    sim.advance_to(from).unwrap();
    let before = sim.stats();
    let count = ((to - from) / COMM).round() as usize;
    let segments = 5;
    let (mut step, mut pass, mut solve, mut ratio) = (vec![], vec![], vec![], vec![]);
    let mut k = 0;
    for segment in 1..=segments {
        let start = sim.stats().steps;
        let t0 = Instant::now();
        while k < count * segment / segments {
            k += 1;
            sim.advance_to(from + k as f64 * COMM).unwrap();
            std::hint::black_box(sim.outputs().unwrap());
        }
        let n = (sim.stats().steps - start).max(1);
        let per_step = t0.elapsed().as_secs_f64() / n as f64 * 1e6;
        let (p, q) = floor(sim);
        step.push(per_step);
        pass.push(p);
        solve.push(q);
        ratio.push(per_step / (p + q));
    }
    let after = sim.stats();
    let n = after.steps - before.steps;
    [
        median(step),
        median(pass),
        median(solve),
        median(ratio),
        (after.iterations - before.iterations) as f64 / n as f64,
        n as f64,
        n as f64 / count as f64,
    ]
}

/// µs of one force-and-Jacobian pass and of one banded solve at the state in
/// hand (batches of 400, the faster of two).
fn floor(sim: &mut Simulator) -> (f64, f64) {
    let reps = 400;
    let (mut pass, mut solve) = (f64::INFINITY, f64::INFINITY);
    for _ in 0..2 {
        let t0 = Instant::now();
        for _ in 0..reps {
            std::hint::black_box(sim.force_and_jacobian_pass().unwrap());
        }
        pass = pass.min(t0.elapsed().as_secs_f64() / reps as f64 * 1e6);
        let t0 = Instant::now();
        for _ in 0..reps {
            assert!(sim.banded_solve());
        }
        solve = solve.min(t0.elapsed().as_secs_f64() / reps as f64 * 1e6);
    }
    (pass, solve)
}

/// A table row; the floor of a communication point is its steps' floors,
/// `steps a point × (pass + solve)`.
fn row(name: &str, run: &str, [step, pass, solve, ratio, newton, n, per_point]: [f64; 7]) {
    let floor_point = per_point * (pass + solve);
    println!(
        "| {name} | {run} | {n} | {per_point:.2} | {newton:.2} | {step:.1} | {pass:.2} | {solve:.2} | **{ratio:.1}** | {floor_point:.1} |"
    );
}

fn main() {
    if std::env::args().any(|a| a == "--list") {
        return;
    }
    println!(
        "| model | run | steps | steps a point | Newton it/step | µs per step | µs per force-and-Jacobian pass | µs per banded solve | **step / (pass + solve)** | floor of a point, µs |"
    );
    println!("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    for (name, mut model) in shipped() {
        model.drive = Drive::Speed;
        let rated = model.nominal_speed;
        // Steady running.
        let mut sim = simulator(&model);
        sim.set_speed(rated, 0.0).unwrap();
        sim.settle_static().unwrap();
        row(&name, "steady", measure(&mut sim, 1.0, 5.0));
        // Start-up from rest.
        let mut sim = simulator(&model);
        sim.set_speed(0.0, 0.0).unwrap();
        sim.settle_static().unwrap();
        sim.set_speed(0.0, rated / 10.0).unwrap();
        row(&name, "start-up from rest", measure(&mut sim, 0.0, 4.0));
        // Field switching.
        let pulls: Vec<usize> = (0..model.bearings.len())
            .filter(|&k| model.bearings[k].kind.clone().set_excitation(1.0))
            .collect();
        if !pulls.is_empty() {
            let mut sim = simulator(&model);
            for &k in &pulls {
                sim.set_excitation(k, 0.0).unwrap();
            }
            sim.set_speed(rated, 0.0).unwrap();
            sim.settle_static().unwrap();
            sim.advance_to(1.0).unwrap();
            for &k in &pulls {
                sim.set_excitation(k, 1.0).unwrap();
            }
            row(&name, "field switched on", measure(&mut sim, 1.0, 3.0));
        }
        // Contact: ten times the unbalance.
        let mut heavy = model.clone();
        for u in &mut heavy.unbalances {
            u.magnitude *= 10.0;
        }
        let mut sim = simulator(&heavy);
        sim.set_speed(rated, 0.0).unwrap();
        sim.settle_static().unwrap();
        row(&name, "10x unbalance", measure(&mut sim, 1.0, 3.0));
    }
}
