//! Reference run for the FMPy test: the Rust simulator driven directly the way
//! FMPy drives the FMU — start at `t = 0` in static equilibrium with default FMU
//! parameters, inputs held over each step at the value of the table row for the
//! step's start, `t_{n+1} = n_step·h` with steps `t_{n+1} − t_n`.
//!
//! `cargo run --example reference_run -- MODEL.toml INPUT.csv STOP STEP` where
//! INPUT.csv has rows `time,speed` (rad/s) at every communication point; prints
//! `time,<bearing x,y,fx,fy for every bearing>` with round-trip precision.

use std::path::Path;

use rotor_bearing::fmi2::variables::default_fmu_time_step;
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

fn main() -> Result<(), String> {
    let args: Vec<String> = std::env::args().collect();
    if args.len() != 5 {
        return Err("usage: reference_run MODEL.toml INPUT.csv STOP STEP".into());
    }
    let model = RotorModel::from_file(Path::new(&args[1])).map_err(|e| e.to_string())?;
    let table: Vec<(f64, f64)> = std::fs::read_to_string(&args[2])
        .map_err(|e| e.to_string())?
        .lines()
        .filter_map(|l| {
            let mut it = l.split(',').map(|v| v.trim().parse::<f64>());
            Some((it.next()?.ok()?, it.next()?.ok()?))
        })
        .collect();
    let stop: f64 = args[3].parse().map_err(|e| format!("{e}"))?;
    let h: f64 = args[4].parse().map_err(|e| format!("{e}"))?;
    let options = SolverOptions {
        time_step: default_fmu_time_step(&model),
        local_error_tolerance: rotor_bearing::fmi2::variables::DEFAULT_LOCAL_ERROR_TOLERANCE,
        ..SolverOptions::default()
    };
    let mut sim = Simulator::new(Rotor::new(model).map_err(|e| e.to_string())?, options)
        .map_err(|e| e.to_string())?;
    let speed_at = |t: f64| table.iter().find(|(ti, _)| *ti == t).map(|r| r.1);
    sim.set_speed(speed_at(0.0).ok_or("no input row at t = 0")?, 0.0)
        .map_err(|e| e.to_string())?;
    sim.settle_static().map_err(|e| e.to_string())?;
    let print = |sim: &mut Simulator, t: f64| -> Result<(), String> {
        let o = sim.outputs().map_err(|e| e.to_string())?;
        let mut row = format!("{t:?}");
        for b in &o.bearings {
            row += &format!(",{:?},{:?},{:?},{:?}", b.x, b.y, b.fx, b.fy);
        }
        println!("{row}");
        Ok(())
    };
    print(&mut sim, 0.0)?;
    let mut time = 0.0;
    let mut n = 0;
    while time < stop && (time - stop).abs() > 1e-12 {
        let next = (n + 1) as f64 * h;
        let w = speed_at(time).ok_or(format!("no input row at t = {time:?}"))?;
        sim.set_speed(w, 0.0).map_err(|e| e.to_string())?;
        sim.align_time(time).map_err(|e| e.to_string())?;
        sim.advance_to(time + (next - time))
            .map_err(|e| e.to_string())?;
        time = next;
        n += 1;
        print(&mut sim, time)?;
    }
    Ok(())
}
