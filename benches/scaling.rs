//! Scaling of the Newmark step with rotor size: rotor trains of 10 … 10 000
//! Timoshenko elements on 2 … 20 nonlinear plain bearings. Prints the time per
//! step against DOF count, the fitted exponent, the time of one triangular solve
//! of the same banded system (the floor for an implicit method) and the memory
//! per DOF (counted by a global allocator). `cargo bench --bench scaling`;
//! `SCALING_STATS=1` also prints the solver counters (steps, Newton iterations).

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

struct Counting;
static LIVE: AtomicUsize = AtomicUsize::new(0);
static CALLS: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        CALLS.fetch_add(1, Ordering::Relaxed);
        let now = LIVE.fetch_add(layout.size(), Ordering::Relaxed) + layout.size();
        PEAK.fetch_max(now, Ordering::Relaxed);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        LIVE.fetch_sub(layout.size(), Ordering::Relaxed);
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// A 20 m, 200 mm steel rotor train in `elements` Timoshenko elements with ten
/// 500 kg disks and `bearings` plain bearings evenly spaced (so the physics is the
/// same at every refinement and only the DOF count changes).
fn train(elements: usize, bearings: usize) -> RotorModel {
    let mut text = String::from(
        "name = \"train\"\ngravity = [0.0, -9.81, 0.0]\n[[materials]]\nname = \"steel\"\nyoungs_modulus = 211e9\nshear_modulus = 81.2e9\ndensity = 7810.0\n",
    );
    text += &format!(
        "[[shaft]]\nlength = 20.0\nouter_diameter = 0.2\nmaterial = \"steel\"\nelements = {elements}\n"
    );
    let node_at = |fraction: f64| 1 + (fraction * elements as f64).round() as usize;
    let mut taken = std::collections::HashSet::new();
    for k in 0..bearings {
        let node = node_at(k as f64 / (bearings - 1) as f64);
        taken.insert(node);
        text += &format!(
            "[[bearings]]\ntype = \"plain\"\nnode = {node}\nradius = 0.1\nlength = 0.1\nclearance = 1.5e-4\nviscosity = 0.03\n"
        );
    }
    for k in 0..10 {
        let node = node_at((k as f64 + 0.5) / 10.0);
        if !taken.contains(&node) {
            text += &format!(
                "[[disks]]\nnode = {node}\nmass = 500.0\npolar_inertia = 20.0\ndiametral_inertia = 10.0\n"
            );
        }
    }
    text += "[[unbalance]]\nnode = 2\nmagnitude = 0.01\n";
    RotorModel::from_toml(&text, "train.toml").unwrap()
}

struct Row {
    elements: usize,
    bearings: usize,
    dofs: usize,
    step_us: f64,
    solve_us: f64,
    bytes_per_dof: f64,
    allocations: f64,
}

fn measure(elements: usize, bearings: usize) -> Row {
    let model = train(elements, bearings);
    let base = LIVE.load(Ordering::Relaxed);
    PEAK.store(base, Ordering::Relaxed);
    let rotor = Rotor::new(model).unwrap();
    let dofs = rotor.dof_count();
    let h = 2e-4;
    let mut sim = Simulator::new(
        rotor,
        SolverOptions {
            time_step: h,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    sim.set_speed(3000.0 * std::f64::consts::PI / 30.0, 0.0)
        .unwrap();
    sim.settle_static().unwrap();
    sim.advance_to(20.0 * h).unwrap();
    // Five batches of steps; the median batch gives the time per step.
    let per_batch = (40_000 / elements).clamp(10, 800);
    let mut batches = Vec::with_capacity(5);
    let calls_before = CALLS.load(Ordering::Relaxed);
    let mut k = 20;
    for _ in 0..5 {
        let t0 = Instant::now();
        for _ in 0..per_batch {
            k += 1;
            sim.advance_to(k as f64 * h).unwrap();
        }
        batches.push(t0.elapsed().as_secs_f64() / per_batch as f64 * 1e6);
    }
    let step_us = median(&mut batches);
    let allocations =
        (CALLS.load(Ordering::Relaxed) - calls_before) as f64 / (5 * per_batch) as f64;
    if std::env::var("SCALING_STATS").is_ok() {
        eprintln!("{elements} elements: {:?}", sim.stats());
    }
    let bytes_per_dof = (PEAK.load(Ordering::Relaxed) - base) as f64 / dofs as f64;
    // Floor: one forward/back substitution with the factored banded matrix.
    let r = sim.rotor();
    let mut a = r.stiffness.clone();
    a.scale_add(4.0 / (h * h), &r.mass);
    let lu = a.lu().unwrap();
    let mut x = vec![1.0; dofs];
    let reps = (400_000 / dofs).clamp(10, 4_000);
    let mut batches = Vec::new();
    for _ in 0..5 {
        let t0 = Instant::now();
        for _ in 0..reps {
            lu.solve_in_place(std::hint::black_box(&mut x));
        }
        batches.push(t0.elapsed().as_secs_f64() / reps as f64 * 1e6);
    }
    let solve_us = median(&mut batches);
    Row {
        elements,
        bearings,
        dofs,
        step_us,
        solve_us,
        bytes_per_dof,
        allocations,
    }
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn fit(rows: &[Row]) -> f64 {
    let (n, sx, sy, sxx, sxy) =
        rows.iter()
            .fold((0.0, 0.0, 0.0, 0.0, 0.0), |(n, sx, sy, sxx, sxy), r| {
                let (x, y) = ((r.dofs as f64).ln(), r.step_us.ln());
                (n + 1.0, sx + x, sy + y, sxx + x * x, sxy + x * y)
            });
    (n * sxy - sx * sy) / (n * sxx - sx * sx)
}

fn main() {
    if std::env::args().any(|a| a == "--list") {
        return;
    }
    println!(
        "| elements | bearings | DOFs | µs per step | µs per banded solve | step / solve | peak bytes per DOF | allocations per step |"
    );
    println!("|---:|---:|---:|---:|---:|---:|---:|---:|");
    let mut series = Vec::new();
    for (elements, bearings) in [(10, 2), (10, 11), (100, 20), (1_000, 20), (10_000, 20)] {
        let r = measure(elements, bearings);
        println!(
            "| {} | {} | {} | {:.1} | {:.2} | {:.1} | {:.0} | {:.2} |",
            r.elements,
            r.bearings,
            r.dofs,
            r.step_us,
            r.solve_us,
            r.step_us / r.solve_us,
            r.bytes_per_dof,
            r.allocations
        );
        series.push(r);
    }
    let twenty: Vec<Row> = series.into_iter().filter(|r| r.bearings == 20).collect();
    println!(
        "\nfitted exponent of time per step against DOFs (20 bearings, 100–10 000 elements): {:.3}",
        fit(&twenty)
    );
}
