//! Real-time factors (simulated seconds per wall-clock second) of the simulator
//! the FMU drives, with communication points every 5 ms (or every internal
//! step if longer) and the outputs read at each, as the plant loop of
//! `bench/plant_loop.py` does: the hydro unit on tilting pads at the paper's
//! 5 ms step and at 0.1 ms, the three-guide-bearing unit (28 pads) at 5 ms, and
//! the Jeffcott rotor on plain bearings, each on the full rotor and on the
//! reduced one (10 fixed-interface modes); medians of three runs.
//! `cargo bench --bench realtime`.

use std::path::PathBuf;
use std::time::Instant;

use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

fn realtime(name: &str, modes: usize, step: f64, seconds: f64) -> (f64, f64) {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("models")
        .join(format!("{name}.toml"));
    let model = RotorModel::from_file(&path).unwrap();
    let mut sim = Simulator::new(
        Rotor::for_transients(model.clone(), modes).unwrap(),
        SolverOptions {
            time_step: step,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    sim.set_speed(model.nominal_speed, 0.0).unwrap();
    sim.settle_static().unwrap();
    sim.advance_to(0.1 * seconds).unwrap();
    let t0 = Instant::now();
    // Communication points every 5 ms, as a plant study calls fmi2DoStep.
    let comm = 0.005f64.max(step);
    let start = sim.time();
    let count = (seconds / comm).round() as usize;
    for k in 1..=count {
        sim.advance_to(start + k as f64 * comm).unwrap();
        std::hint::black_box(sim.outputs().unwrap());
    }
    let wall = t0.elapsed().as_secs_f64();
    (seconds / wall, wall / (seconds / step) * 1e6)
}

fn main() {
    if std::env::args().any(|a| a == "--list") {
        return;
    }
    println!("| model | rotor | internal step | real-time factor | µs per step |");
    println!("|---|---|---:|---:|---:|");
    for (name, step, seconds) in [
        ("hydro_unit", 5e-3, 60.0),
        ("hydro_unit", 1e-4, 4.0),
        ("hydro_unit_plain", 5e-3, 60.0),
        ("hydro_unit_three_guide", 5e-3, 30.0),
        ("jeffcott", 1e-4, 4.0),
    ] {
        for modes in [0, 10] {
            // Median of three runs.
            let mut runs: Vec<(f64, f64)> = (0..3)
                .map(|_| realtime(name, modes, step, seconds))
                .collect();
            runs.sort_by(|a, b| a.0.total_cmp(&b.0));
            let (factor, per_step) = runs[1];
            let rotor = if modes == 0 {
                "full".to_string()
            } else {
                format!("reduced, {modes} modes")
            };
            println!("| {name} | {rotor} | {step} s | {factor:.0}× | {per_step:.1} |");
        }
    }
}
