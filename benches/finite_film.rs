//! The cost of the finite-length film in the time loop (issue 47): µs per
//! Newmark step of the same rotor with its plain or tilting-pad bearings on
//! the short film and on the finite film (`film = "finite"`, default mesh,
//! Swift–Stieber), and their ratio, in one run: the Jeffcott rotor (two
//! plain bearings) at 0.1 ms steps and the hydro unit (two tilting-pad
//! guide bearings) at its 5 ms step, each at its nominal speed from its
//! static equilibrium. The finite film solves Reynolds' equation directly at
//! every evaluation (no force tables yet). `cargo bench --bench finite_film`.

use std::path::PathBuf;
use std::time::Instant;

use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

/// The model file with `film = "finite"` after the `type` of every plain
/// and tilting-pad bearing.
fn finite(text: &str) -> String {
    let mut out = String::new();
    for line in text.lines() {
        out.push_str(line);
        out.push('\n');
        let t = line.split('#').next().unwrap_or("").trim();
        if t == "type = \"plain\"" || t == "type = \"tilting_pad\"" {
            out.push_str("film = \"finite\"\n");
        }
    }
    out
}

/// µs per step over `steps` steps of `step` s after settling.
fn per_step(text: &str, step: f64, steps: usize) -> f64 {
    let model = RotorModel::from_toml(text, "bench.toml").unwrap();
    let mut sim = Simulator::new(
        Rotor::new(model.clone()).unwrap(),
        SolverOptions {
            time_step: step,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    sim.set_speed(model.nominal_speed, 0.0).unwrap();
    sim.settle_static().unwrap();
    sim.advance_to(5.0 * step).unwrap();
    let start = sim.time();
    let t0 = Instant::now();
    sim.advance_to(start + steps as f64 * step).unwrap();
    std::hint::black_box(sim.outputs().unwrap());
    t0.elapsed().as_secs_f64() / steps as f64 * 1e6
}

fn main() {
    if std::env::args().any(|a| a == "--list") {
        return;
    }
    println!("| model | step | short film µs/step | finite film µs/step | ratio |");
    println!("|---|---:|---:|---:|---:|");
    for (name, step, steps) in [("jeffcott", 1e-4, 400), ("hydro_unit", 5e-3, 40)] {
        let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("models")
            .join(format!("{name}.toml"));
        let text = std::fs::read_to_string(path).unwrap();
        let short = per_step(&text, step, steps * 10);
        let long = per_step(&finite(&text), step, steps);
        println!(
            "| {name} | {step} s | {short:.1} | {long:.0} | {:.0} |",
            long / short
        );
    }
}
