//! The cost of the finite-length film in the time loop (issue 47): µs per
//! Newmark step of the same rotor with its plain or tilting-pad bearings on
//! the short film and on the finite film (`film = "finite"`, default mesh,
//! Swift–Stieber), and their ratio, in one run: the Jeffcott rotor (two
//! plain bearings) at 0.1 ms steps and the hydro unit (two tilting-pad
//! guide bearings) at its 5 ms step, each at its nominal speed from its
//! static equilibrium. The finite film solves Reynolds' equation directly at
//! every evaluation; plain films with `film_tables = true` interpolate their
//! force tables (built here once into a scratch cache, and timed). `cargo
//! bench --bench finite_film` (`-- --tables-only`: the tabled row alone).

use std::path::PathBuf;
use std::time::Instant;

use rotor_bearing::bearing::BearingKind;
use rotor_bearing::bearing::film_table::{FilmTable, TableGeometry};
use rotor_bearing::bearing::film_table_cache;
use rotor_bearing::bearing::reynolds::Cavitation;
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

/// The model file with `film = "finite"` and `extra` (for plain bearings)
/// after the `type` of every plain and tilting-pad bearing.
fn finite(text: &str, extra: &str) -> String {
    let mut out = String::new();
    for line in text.lines() {
        out.push_str(line);
        out.push('\n');
        let t = line.split('#').next().unwrap_or("").trim();
        if t == "type = \"plain\"" || t == "type = \"tilting_pad\"" {
            out.push_str("film = \"finite\"\n");
        }
        if t == "type = \"plain\"" {
            out.push_str(extra);
        }
    }
    out
}

/// The bench's own table cache (emptied at the start, so the first read of
/// a tabled model builds its table once and every later one reads it).
fn cache() -> PathBuf {
    std::env::temp_dir().join(format!("rotor-bench-film-tables-{}", std::process::id()))
}

/// µs per step over `steps` steps of `step` s after settling.
fn per_step(text: &str, step: f64, steps: usize) -> f64 {
    let model = RotorModel::from_toml_cached(text, "bench.toml", Some(&cache())).unwrap();
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
    let read = |name: &str| {
        let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("models")
            .join(format!("{name}.toml"));
        std::fs::read_to_string(path).unwrap()
    };
    // `-- --tables-only`: the tabled row alone (the direct rows take minutes).
    let direct = if std::env::args().any(|a| a == "--tables-only") {
        &[][..]
    } else {
        &[("jeffcott", 1e-4, 400), ("hydro_unit", 5e-3, 40)][..]
    };
    for &(name, step, steps) in direct {
        let text = read(name);
        let short = per_step(&text, step, steps * 10);
        let long = per_step(&finite(&text, ""), step, steps);
        println!(
            "| {name} | {step} s | {short:.1} | {long:.0} | {:.0} |",
            long / short
        );
    }
    // Force tables: the same run, short and tabled films alternated three
    // times (the median ratio), and the table's build for the geometry.
    let text = read("jeffcott");
    let tabled = finite(&text, "film_tables = true\n");
    let _ = std::fs::remove_dir_all(cache());
    let model = RotorModel::from_toml_cached(&tabled, "bench.toml", Some(&cache())).unwrap();
    let BearingKind::FiniteFilm(f) = &model.bearings[0].kind else {
        panic!("not a finite film")
    };
    let build = f.table.as_deref().unwrap().build_seconds;
    let mut ratios: Vec<(f64, f64, f64)> = (0..3)
        .map(|_| {
            let short = per_step(&text, 1e-4, 4000);
            let long = per_step(&tabled, 1e-4, 4000);
            (long / short, short, long)
        })
        .collect();
    ratios.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (ratio, short, long) = ratios[1];
    println!();
    println!(
        "| model | step | short film µs/step | tabled finite film µs/step | ratio | table build (one geometry) |"
    );
    println!("|---|---:|---:|---:|---:|---:|");
    println!(
        "| jeffcott, film_tables = true ({}) | 0.0001 s | {short:.2} | {long:.2} | {ratio:.2} | {build:.1} s |",
        film_table_cache::describe(&TableGeometry::of(&f.film()))
    );
    let _ = std::fs::remove_dir_all(cache());
    let gumbel = TableGeometry {
        cavitation: Cavitation::Gumbel,
        ..TableGeometry::of(&f.film())
    };
    let t0 = Instant::now();
    std::hint::black_box(FilmTable::build(gumbel).unwrap());
    println!(
        "\nTable build, {}: {:.2} s",
        film_table_cache::describe(&gumbel),
        t0.elapsed().as_secs_f64()
    );
    pad_table_estimate();
}

/// What a pad's table would cost: one Swift–Stieber solve of a 60° pad on
/// the default pad mesh (48 × 16), timed over 200 states, times the solves
/// of a 4-D table — the film position `(ξ, η)` on 33 × 33 nodes and the
/// direction of `(ω, ξ̇, η̇)` on 24 × 48 nodes of the sphere (the load is
/// homogeneous of degree 1 in them), the resolution the plain table needs
/// per angle.
fn pad_table_estimate() {
    use nalgebra::Vector2;
    use rotor_bearing::bearing::JournalState;
    use rotor_bearing::bearing::finite_film::FiniteFilm;
    use rotor_bearing::bearing::reynolds::ReynoldsMesh;
    let film = FiniteFilm {
        radius: 0.25,
        length: 0.2,
        clearance: 2e-4,
        viscosity: 0.03,
        mesh: ReynoldsMesh::PAD,
        cavitation: Cavitation::SwiftStieber,
    };
    let half = std::f64::consts::FRAC_PI_6;
    let arc = Some((-half, half));
    let t0 = Instant::now();
    let n = 200;
    for k in 0..n {
        let a = k as f64 / n as f64;
        let state = JournalState {
            position: Vector2::new(1e-4 * (0.2 + 0.6 * a), 3e-5 * (a - 0.5)),
            velocity: Vector2::new(1e-3 * (a - 0.5), 2e-3 * a),
        };
        std::hint::black_box(film.force(&state, 50.0, arc).unwrap());
    }
    let solve = t0.elapsed().as_secs_f64() / n as f64;
    let solves = 33.0 * 33.0 * 24.0 * 48.0;
    println!(
        "\nPad (60°, mesh 48 × 16, Swift–Stieber): {:.2} ms per solve; a 4-D table of 33 × 33 positions × 24 × 48 directions ({solves:.2e} solves) would take {:.0} min per pad geometry",
        solve * 1e3,
        solves * solve / 60.0
    );
}
