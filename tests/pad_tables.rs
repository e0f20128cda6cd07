//! Force tables of tilting pads' finite-length films (issue 47, acceptance
//! 4): the reduction they rest on (homogeneity in the source, the pad frame),
//! the table against direct Reynolds solves on 1000 random states, the
//! Jacobian against differences of the table force, and the cache.
//!
//! Coarse pad meshes keep the builds and the direct solves fast; the
//! reduction and the spline do not depend on the mesh's size.

#[path = "common/rng.rs"]
mod rng;
#[path = "common/table_cache.rs"]
mod table_cache;

use std::f64::consts::{PI, TAU};

use nalgebra::{Matrix2, Vector2};
use rotor_bearing::bearing::JournalState;
use rotor_bearing::bearing::film_table_cache::TableOrigin;
use rotor_bearing::bearing::finite_film::FiniteFilm;
use rotor_bearing::bearing::pad_table::{PadGeometry, PadTable};
use rotor_bearing::bearing::reynolds::{Cavitation, FilmProblem, ReynoldsMesh, solve};

/// 60° pads, L/D 0.45 (the compressor), on a coarse pad mesh.
const ARC: f64 = PI / 3.0;
const MESH: ReynoldsMesh = ReynoldsMesh {
    circumferential: 24,
    axial: 4,
};

fn film(cavitation: Cavitation) -> FiniteFilm {
    FiniteFilm {
        radius: 0.05,
        length: 0.045,
        clearance: 1e-4,
        viscosity: 0.02,
        mesh: MESH,
        cavitation,
    }
}

fn rotate(v: Vector2<f64>, angle: f64) -> Vector2<f64> {
    let (s, c) = angle.sin_cos();
    Vector2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

fn load(x: Vector2<f64>, s: Vector2<f64>, arc: (f64, f64), cavitation: Cavitation) -> Vector2<f64> {
    let p = FilmProblem {
        x: x.x,
        y: x.y,
        a: s.x,
        b: s.y,
        slenderness: (2.0 / 0.9f64).powi(2),
        arc: Some(arc),
    };
    solve(&p, MESH, cavitation).unwrap().load_integral()
}

/// The reduction, on direct solves: a pad's load is positively homogeneous
/// of degree 1 in the source, and a pad whose leading edge is at `α`
/// (pivot anywhere) carries the load of the pad at `(0, β)` with position
/// and source turned by `−α`, turned back: both to round-off (1e-10),
/// since the mesh is laid from the leading edge. So `L = |s| R(α) G(ε, φ, ψ)`.
#[test]
fn pad_load_is_homogeneous_and_turns_with_the_pad() {
    let mut rng = rng::Rng(4747);
    let (mut worst_h, mut worst_r) = (0.0f64, 0.0f64);
    for cavitation in [Cavitation::SwiftStieber, Cavitation::Gumbel] {
        for _ in 0..40 {
            let eps = 0.9 * rng.unit();
            let phi = TAU * rng.unit();
            let psi = TAU * rng.unit();
            let alpha = TAU * rng.unit();
            let x = Vector2::new(phi.cos(), phi.sin()) * eps;
            let s = Vector2::new(psi.cos(), psi.sin());
            let base = load(x, s, (0.0, ARC), cavitation);
            if base.norm() == 0.0 {
                continue;
            }
            let scaled = load(x, s * 3.7, (0.0, ARC), cavitation);
            worst_h = worst_h.max((scaled - base * 3.7).norm() / scaled.norm());
            let turned = load(
                rotate(x, alpha),
                rotate(s, alpha),
                (alpha, alpha + ARC),
                cavitation,
            );
            worst_r = worst_r.max((turned - rotate(base, alpha)).norm() / base.norm());
        }
    }
    println!("homogeneity defect {worst_h:.2e}, pad-frame defect {worst_r:.2e}");
    assert!(worst_h < 1e-10, "not homogeneous: {worst_h}");
    assert!(
        worst_r < 1e-10,
        "not invariant under the pad frame: {worst_r}"
    );
}

/// A random pad state: the effective position at ε ≤ 0.9 in any direction,
/// the velocity in any direction, its size from rest to a few times `ω C`.
fn random_state(rng: &mut rng::Rng, speed: f64, clearance: f64) -> JournalState {
    let eps = 0.9 * rng.unit();
    let phi = TAU * rng.unit();
    let dir = TAU * rng.unit();
    let v = 2.0 * speed * clearance * rng.unit();
    JournalState {
        position: Vector2::new(phi.cos(), phi.sin()) * eps * clearance,
        velocity: Vector2::new(dir.cos(), dir.sin()) * v,
    }
}

fn max_abs(m: &Matrix2<f64>) -> f64 {
    m.iter().fold(0.0, |a, v| a.max(v.abs()))
}

/// Acceptance 4 for pads: on 1000 random states of a pad anywhere around the
/// journal (leading edge at a random angle) the table force is within 0.5 %
/// of the direct solve — relative to the direct force or, where the journal
/// leaves the pad and it carries less, to its nominal load (the concentric
/// pad's under the same source size) — and the table's Jacobian is the
/// derivative of the table force (central differences, 1e-6 relative).
/// Measured: 0.12 % (Gümbel) and 0.13 % (Swift–Stieber) on this mesh;
/// K, C within 1e-7.
#[test]
fn pad_table_matches_direct_solves_and_its_jacobian_is_its_derivative() {
    let speed = 300.0;
    for cavitation in [Cavitation::Gumbel, Cavitation::SwiftStieber] {
        let film = film(cavitation);
        let start = std::time::Instant::now();
        let table = PadTable::build(PadGeometry::of(&film, ARC)).unwrap();
        let built = start.elapsed().as_secs_f64();
        let mut rng = rng::Rng(4800 + cavitation as u64);
        let concentric = (0..64)
            .map(|k| {
                let psi = TAU * k as f64 / 64.0;
                load(
                    Vector2::zeros(),
                    Vector2::new(psi.cos(), psi.sin()),
                    (0.0, ARC),
                    cavitation,
                )
                .norm()
            })
            .fold(0.0, f64::max);
        let scale = 6.0
            * film.viscosity
            * (film.radius / film.clearance).powi(2)
            * film.radius
            * film.length;
        let (mut worst_force, mut worst_k, mut worst_c) = (0.0f64, 0.0f64, 0.0f64);
        let mut errors = Vec::new();
        for _ in 0..1000 {
            let state = random_state(&mut rng, speed, film.clearance);
            let lead = TAU * rng.unit();
            let arc = (lead, lead + ARC);
            let direct = film.force(&state, speed, Some(arc)).unwrap();
            let tab = table.force_and_jacobian(&film, &state, speed, arc).unwrap();
            // The pad's nominal load for this source: the concentric
            // pad's under the same |s| (a pad the journal leaves carries
            // nothing, so its error is judged against what it would carry).
            let v = state.velocity;
            let p = state.position;
            let s = Vector2::new(speed * p.x - 2.0 * v.y, speed * p.y + 2.0 * v.x).norm()
                / film.clearance;
            let nominal = s * concentric * scale;
            let ef = (tab.force - direct).norm() / direct.norm().max(nominal);
            errors.push((
                ef,
                direct.norm() / nominal,
                (tab.force - direct).norm() / direct.norm(),
            ));
            worst_force = worst_force.max(ef);
            let at = |position, velocity| {
                table
                    .force_and_jacobian(&film, &JournalState { position, velocity }, speed, arc)
                    .unwrap()
                    .force
            };
            let eps = state.position.norm() / film.clearance;
            let dp = 1e-7 * film.clearance * (eps / 1e-2).min(1.0);
            let dv = 1e-7 * speed * film.clearance;
            let (mut k, mut c) = (Matrix2::zeros(), Matrix2::zeros());
            for j in 0..2 {
                let mut e = Vector2::zeros();
                e[j] = 1.0;
                let (p, v) = (state.position, state.velocity);
                k.set_column(j, &(-(at(p + e * dp, v) - at(p - e * dp, v)) / (2.0 * dp)));
                c.set_column(j, &(-(at(p, v + e * dv) - at(p, v - e * dv)) / (2.0 * dv)));
            }
            if max_abs(&tab.stiffness) > 0.0 {
                worst_k = worst_k.max(max_abs(&(k - tab.stiffness)) / max_abs(&tab.stiffness));
                worst_c = worst_c.max(max_abs(&(c - tab.damping)) / max_abs(&tab.damping));
            }
        }
        let loaded = errors
            .iter()
            .filter(|e| e.1 >= 0.1)
            .map(|e| e.2)
            .fold(0.0, f64::max);
        println!(
            "{cavitation:?}: built in {built:.2} s; force {worst_force:.2e} (of the direct force where the pad carries at least 10 % of its nominal load: {loaded:.2e}), K {worst_k:.2e}, C {worst_c:.2e}"
        );
        assert!(
            worst_force <= 5e-3,
            "{cavitation:?}: force off by {worst_force}"
        );
        assert!(worst_k <= 1e-6, "{cavitation:?}: K off by {worst_k}");
        assert!(worst_c <= 1e-6, "{cavitation:?}: C off by {worst_c}");
    }
}

/// The cache holds pad tables beside plain ones (`pad-<key>.table`): a file
/// round-trips to the identical table; a corrupt file (one flipped bit), a
/// truncated one and one of another arc are detected and rebuilt.
#[test]
fn pad_cache_round_trips_and_rejects_bad_files() {
    let geometry = PadGeometry {
        slenderness: 4.0,
        arc: ARC,
        mesh: ReynoldsMesh {
            circumferential: 8,
            axial: 2,
        },
        cavitation: Cavitation::Gumbel,
    };
    let other = PadGeometry {
        arc: ARC * 1.1,
        ..geometry
    };
    let dir = std::env::temp_dir().join(format!("rotor-pad-tables-{}", std::process::id()));
    table_cache::assert_round_trip(&geometry, &other, &dir);
}

/// The hydro unit (two guide bearings of eight 36° pads) on finite pad films
/// (mesh 24 × 4, `cavitation`), with `film_tables = tables`, its tables
/// cached in `dir`.
fn hydro_unit(
    cavitation: &str,
    tables: bool,
    dir: &std::path::Path,
) -> rotor_bearing::model::RotorModel {
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/hydro_unit.toml");
    let text = std::fs::read_to_string(path)
        .unwrap()
        .replace(
            "type = \"tilting_pad\"\n",
            &format!(
                "type = \"tilting_pad\"\nfilm = \"finite\"\nfilm_mesh = [24, 4]\ncavitation = \"{cavitation}\"\nfilm_tables = {tables}\n"
            ),
        );
    rotor_bearing::model::RotorModel::from_toml_cached(&text, "hydro_unit_tables.toml", Some(dir))
        .unwrap()
}

/// The generator guide's journal path (m) every 2 ms over 0.4 s at the
/// nominal speed, released at rest from the centre: the unbalance drives
/// the journal into the pads.
fn run(model: rotor_bearing::model::RotorModel) -> Vec<[f64; 2]> {
    use rotor_bearing::solver::{Simulator, SolverOptions};
    let speed = model.nominal_speed;
    let mut sim = Simulator::new(
        rotor_bearing::rotor::Rotor::new(model).unwrap(),
        SolverOptions {
            time_step: 1e-3,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    sim.set_speed(speed, 0.0).unwrap();
    sim.consistent_acceleration().unwrap();
    (1..=200)
        .map(|k| {
            sim.advance_to(k as f64 * 2e-3).unwrap();
            let o = sim.outputs().unwrap();
            [o.bearings[0].x, o.bearings[0].y]
        })
        .collect()
}

/// Acceptance 4, transient, for pads: the shipped hydro unit on finite
/// tilting pads with tables follows the run with direct Reynolds solves to
/// 1e-3 of the orbit's size (measured 1.5e-4), Gümbel and Swift–Stieber. All
/// sixteen pads (one arc) share one table: built once, read from the cache
/// by the other bearing.
#[test]
fn pad_transient_with_tables_follows_the_direct_solves() {
    let dir = std::env::temp_dir().join(format!("rotor-pad-transient-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    for cavitation in ["gumbel", "swift_stieber"] {
        let tabled = hydro_unit(cavitation, true, &dir);
        let tables: Vec<_> = tabled
            .bearings
            .iter()
            .filter_map(|b| match &b.kind {
                rotor_bearing::bearing::BearingKind::FiniteFilm(f) => Some(f),
                _ => None,
            })
            .map(|f| {
                assert_eq!(f.pad_tables.len(), 1, "one arc, one table");
                f.pad_tables[0].origin.clone()
            })
            .collect();
        assert_eq!(tables.len(), 2);
        assert!(matches!(tables[1], TableOrigin::Loaded(_)), "{tables:?}");
        let with = run(tabled);
        let without = run(hydro_unit(cavitation, false, &dir));
        let size = without
            .iter()
            .map(|p| Vector2::from(*p).norm())
            .fold(0.0, f64::max);
        let worst = with
            .iter()
            .zip(&without)
            .map(|(a, b)| (Vector2::from(*a) - Vector2::from(*b)).norm())
            .fold(0.0, f64::max);
        println!(
            "{cavitation}: orbit {size:.3e} m, largest difference {:.2e} of it",
            worst / size
        );
        assert!(size > 4e-6, "{cavitation}: the journal moves {size} m");
        assert!(
            worst <= 1e-3 * size,
            "{cavitation}: {} of the orbit",
            worst / size
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The CLI and the FMU with pad tables: reading the hydro unit with
/// `film_tables = true` on its finite pads builds one table for both
/// bearings (all pads 36°) and says so with its time; `rotor fmu-stage`
/// writes it to `resources/film_tables`, where the FMU's model reading finds
/// it (read, not rebuilt, and equal to the cached one bit for bit).
#[test]
fn pad_tables_travel_in_the_fmu_resources() {
    let dir = std::env::temp_dir().join(format!("rotor-pad-fmu-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/hydro_unit.toml");
    let text = std::fs::read_to_string(path).unwrap().replace(
        "type = \"tilting_pad\"\n",
        "type = \"tilting_pad\"\nfilm = \"finite\"\nfilm_mesh = [12, 2]\ncavitation = \"gumbel\"\nfilm_tables = true\n",
    );
    let model = dir.join("hydro_pad_tables.toml");
    std::fs::write(&model, text).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
        .env("ROTOR_CACHE_DIR", dir.join("cache"))
        .args([
            "fmu-stage",
            model.to_str().unwrap(),
            dir.join("fmu").to_str().unwrap(),
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.contains("bearing generator_guide: film table pad arc 36.00°")
            && stderr.contains("mesh 12 × 2, gumbel cavitation: built in"),
        "{stderr}"
    );
    assert!(
        !stderr.contains("bearing turbine_guide: film table"),
        "{stderr}"
    );
    let resources = dir.join("fmu/resources");
    let tables = resources.join(rotor_bearing::fmu::resources::FILM_TABLES);
    let files: Vec<_> = std::fs::read_dir(&tables)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    assert_eq!(files.len(), 1, "{files:?}");
    assert!(
        files[0]
            .file_name()
            .unwrap()
            .to_string_lossy()
            .starts_with("pad-")
    );
    let m = rotor_bearing::model::RotorModel::from_file_cached(
        &resources.join("model.toml"),
        Some(&tables),
    )
    .unwrap();
    let cached = rotor_bearing::model::RotorModel::from_toml_cached(
        &std::fs::read_to_string(&model).unwrap(),
        "m.toml",
        Some(&dir.join("cache")),
    )
    .unwrap();
    let mut seen = 0;
    for (b, c) in m.bearings.iter().zip(&cached.bearings) {
        if let (
            rotor_bearing::bearing::BearingKind::FiniteFilm(f),
            rotor_bearing::bearing::BearingKind::FiniteFilm(g),
        ) = (&b.kind, &c.kind)
        {
            assert_eq!(
                f.pad_tables[0].origin,
                TableOrigin::Loaded(files[0].clone())
            );
            assert!(f.pad_tables[0].table == g.pad_tables[0].table);
            seen += 1;
        }
    }
    assert_eq!(seen, 2);
    std::fs::remove_dir_all(&dir).unwrap();
}
