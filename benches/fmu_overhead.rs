//! What the FMU layer adds to the simulator it drives, per communication
//! point of a plant loop (fmi2DoStep every 5 ms with one 5 ms internal step,
//! with equal steps, then every output read): the bare `Simulator::advance_to`, the
//! `Instance::do_step` around it, and one read of all outputs, for the
//! shipped hydro unit and the three-guide-bearing unit; medians of five
//! batches. `cargo bench --bench fmu_overhead`.

use std::path::PathBuf;
use std::time::Instant;

use rotor_bearing::fmi2::instance::{Instance, Status};
use rotor_bearing::fmi2::variables::{Causality, Kind, variables};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

const COMM: f64 = 5e-3;
const WARM: usize = 200;
const BATCH: usize = 400;

fn model(name: &str) -> RotorModel {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("models")
        .join(format!("{name}.toml"));
    RotorModel::from_file(&path).unwrap()
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// µs per 5 ms step of the bare simulator, and of it with `Simulator::outputs`.
fn simulator(model: &RotorModel) -> (f64, f64) {
    let modes = Rotor::transient_modes(model).unwrap();
    let rotor = Rotor::for_transients(model.clone(), modes).unwrap();
    let options = SolverOptions {
        time_step: COMM,
        ..SolverOptions::default()
    };
    let mut sim = Simulator::new(rotor, options).unwrap();
    sim.set_speed(model.nominal_speed, 0.0).unwrap();
    sim.settle_static().unwrap();
    let mut t = 0.0;
    for _ in 0..WARM {
        t += COMM;
        sim.advance_to(t).unwrap();
    }
    let mut bare = Vec::new();
    let mut with_outputs = Vec::new();
    for _ in 0..5 {
        let t0 = Instant::now();
        for _ in 0..BATCH {
            t += COMM;
            sim.advance_to(t).unwrap();
        }
        bare.push(t0.elapsed().as_secs_f64() / BATCH as f64 * 1e6);
        let t0 = Instant::now();
        for _ in 0..BATCH {
            t += COMM;
            sim.advance_to(t).unwrap();
            std::hint::black_box(sim.outputs().unwrap());
        }
        with_outputs.push(t0.elapsed().as_secs_f64() / BATCH as f64 * 1e6);
    }
    (median(bare), median(with_outputs))
}

/// µs per fmi2DoStep, per read of every output one value at a time, and the
/// output count.
fn instance(model: &RotorModel) -> (f64, f64, usize) {
    let vars = variables(model);
    let vr = |name: &str| {
        vars.iter()
            .find(|v| v.name == name)
            .unwrap()
            .value_reference
    };
    let outputs: Vec<u32> = vars
        .iter()
        .filter(|v| v.causality == Causality::Output)
        .map(|v| v.value_reference)
        .collect();
    let mut fmu = Instance::new("bench", model.clone()).unwrap();
    assert_eq!(
        fmu.set(vr("solver.time_step"), Kind::Real, COMM),
        Status::Ok
    );
    // Equal steps, as the simulator above takes.
    assert_eq!(
        fmu.set(vr("solver.local_error_tolerance"), Kind::Real, 0.0),
        Status::Ok
    );
    assert_eq!(
        fmu.set(vr("shaft.speed"), Kind::Real, model.nominal_speed),
        Status::Ok
    );
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
    let mut t = 0.0;
    for _ in 0..WARM {
        assert_eq!(fmu.do_step(t, COMM), Status::Ok);
        t += COMM;
    }
    let (mut steps, mut reads) = (Vec::new(), Vec::new());
    for _ in 0..5 {
        let t0 = Instant::now();
        for _ in 0..BATCH {
            fmu.do_step(t, COMM);
            t += COMM;
        }
        steps.push(t0.elapsed().as_secs_f64() / BATCH as f64 * 1e6);
        let t0 = Instant::now();
        for _ in 0..BATCH {
            for &r in &outputs {
                std::hint::black_box(fmu.get(r, Kind::Real).unwrap());
            }
        }
        reads.push(t0.elapsed().as_secs_f64() / BATCH as f64 * 1e6);
        fmu.drain_messages();
    }
    (median(steps), median(reads), outputs.len())
}

fn main() {
    if std::env::args().any(|a| a == "--list") {
        return;
    }
    println!(
        "| model | simulator step | + Simulator::outputs | fmi2DoStep | read of all outputs | outputs |"
    );
    println!("|---|---:|---:|---:|---:|---:|");
    for name in ["hydro_unit", "hydro_unit_three_guide"] {
        let m = model(name);
        let (bare, with_outputs) = simulator(&m);
        let (step, read, n) = instance(&m);
        println!(
            "| {name} | {bare:.1} µs | {with_outputs:.1} µs | {step:.1} µs | {read:.2} µs | {n} |"
        );
    }
}
