//! The cost of the finite-length film in the time loop (issue 47): µs per
//! Newmark step of the same rotor with its plain or tilting-pad bearings on
//! the short film and on the finite film (`film = "finite"`, default mesh,
//! Swift–Stieber), and their ratio, in one run: the Jeffcott rotor (two
//! plain bearings) at 0.1 ms steps and the hydro unit (two tilting-pad
//! guide bearings) at its 5 ms step, each at its nominal speed from its
//! static equilibrium. The finite film solves Reynolds' equation directly at
//! every evaluation; plain films and tilting pads with `film_tables = true`
//! interpolate their force tables (built here once into a scratch cache,
//! and timed). `cargo bench --bench finite_film` (`-- --tables-only`: the
//! tabled rows alone; `-- --pads-only`: the pads' row alone).

use std::path::PathBuf;
use std::time::Instant;

use rotor_bearing::bearing::BearingKind;
use rotor_bearing::bearing::film_table::{FilmTable, TableGeometry};
use rotor_bearing::bearing::film_table_cache;
use rotor_bearing::bearing::reynolds::Cavitation;
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

/// The model file with `film = "finite"` and `extra` (for plain bearings),
/// `pad_extra` (for tilting pads) after the `type` of every plain and
/// tilting-pad bearing.
fn finite(text: &str, extra: &str, pad_extra: &str) -> String {
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
        if t == "type = \"tilting_pad\"" {
            out.push_str(pad_extra);
        }
    }
    out
}

/// The bench's own table cache (emptied at the start, so the first read of
/// a tabled model builds its table once and every later one reads it).
fn cache() -> PathBuf {
    std::env::temp_dir().join(format!("rotor-bench-film-tables-{}", std::process::id()))
}

/// The short and the tabled model run alternately three times, `steps`
/// steps of `h` each: the median ratio tabled / short, with its two µs per
/// step.
fn median_ratio(short: &str, tabled: &str, h: f64, steps: usize) -> (f64, f64, f64) {
    let mut ratios: Vec<(f64, f64, f64)> = (0..3)
        .map(|_| {
            let s = per_step(short, h, steps);
            let t = per_step(tabled, h, steps);
            (t / s, s, t)
        })
        .collect();
    ratios.sort_by(|a, b| a.0.total_cmp(&b.0));
    ratios[1]
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
    // `-- --pads-only`: the tilting pads' tables alone.
    if std::env::args().any(|a| a == "--pads-only") {
        pad_tables();
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
        let long = per_step(&finite(&text, "", ""), step, steps);
        println!(
            "| {name} | {step} s | {short:.1} | {long:.0} | {:.0} |",
            long / short
        );
    }
    // Force tables: the same run, short and tabled films alternated three
    // times (the median ratio), and the table's build for the geometry.
    let text = read("jeffcott");
    let tabled = finite(&text, "film_tables = true\n", "");
    let _ = std::fs::remove_dir_all(cache());
    let model = RotorModel::from_toml_cached(&tabled, "bench.toml", Some(&cache())).unwrap();
    let BearingKind::FiniteFilm(f) = &model.bearings[0].kind else {
        panic!("not a finite film")
    };
    let build = f.table.as_deref().unwrap().build_seconds;
    let (ratio, short, long) = median_ratio(&text, &tabled, 1e-4, 4000);
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
    pad_tables();
}

/// Tilting pads' force tables: the hydro unit (two guide bearings of eight
/// 36° pads, L/(Rβ) = 1.1) on the short film and on tabled finite pads
/// (`film_tables = true`, default pad mesh 48 × 16, Swift–Stieber),
/// alternated three times (the median ratio), with the pad table's build,
/// and the build of the same pad's Gümbel table.
fn pad_tables() {
    use rotor_bearing::bearing::pad_table::{PadGeometry, PadTable};
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/hydro_unit.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let tabled = finite(&text, "", "film_tables = true\n");
    let _ = std::fs::remove_dir_all(cache());
    let model = RotorModel::from_toml_cached(&tabled, "bench.toml", Some(&cache())).unwrap();
    let BearingKind::FiniteFilm(f) = &model.bearings[0].kind else {
        panic!("not a finite film")
    };
    let table = &f.pad_tables[0];
    let build = table.build_seconds;
    let geometry = table.table.geometry();
    let (ratio, short, long) = median_ratio(&text, &tabled, 5e-3, 400);
    println!();
    println!(
        "| model | step | short pads µs/step | tabled finite pads µs/step | ratio | pad table build (one arc) |"
    );
    println!("|---|---:|---:|---:|---:|---:|");
    println!(
        "| hydro_unit, film_tables = true ({}) | 0.005 s | {short:.2} | {long:.2} | {ratio:.2} | {build:.0} s |",
        film_table_cache::describe(&geometry)
    );
    let _ = std::fs::remove_dir_all(cache());
    let gumbel = PadGeometry {
        cavitation: Cavitation::Gumbel,
        ..geometry
    };
    let t0 = Instant::now();
    std::hint::black_box(PadTable::build(gumbel).unwrap());
    println!(
        "\nPad table build, {}: {:.2} s",
        film_table_cache::describe(&gumbel),
        t0.elapsed().as_secs_f64()
    );
}
