//! Force tables of the plain finite film (issue 47, acceptance 4): the
//! reduction they rest on, the table against direct Reynolds solves on
//! 1000 random states, the Jacobian against differences of the table force,
//! and the cache (round trip, a corrupt or foreign file rebuilt).
//!
//! Small meshes keep the direct solves fast; the reduction and the spline do
//! not depend on the mesh's size.

#[path = "common/rng.rs"]
mod rng;
#[path = "common/table_cache.rs"]
mod table_cache;

use nalgebra::{Matrix2, Vector2};
use rotor_bearing::bearing::JournalState;
use rotor_bearing::bearing::film_table::{FilmTable, TableGeometry};
use rotor_bearing::bearing::film_table_cache::TableOrigin;
use rotor_bearing::bearing::finite_film::FiniteFilm;
use rotor_bearing::bearing::reynolds::{Cavitation, FilmProblem, ReynoldsMesh, solve};

const MESH: ReynoldsMesh = ReynoldsMesh {
    circumferential: 144,
    axial: 6,
};

fn film(cavitation: Cavitation, length_over_diameter: f64) -> FiniteFilm {
    FiniteFilm {
        radius: 0.05,
        length: 0.1 * length_over_diameter,
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

fn load(x: Vector2<f64>, s: Vector2<f64>, cavitation: Cavitation) -> Vector2<f64> {
    let p = FilmProblem {
        x: x.x,
        y: x.y,
        a: s.x,
        b: s.y,
        slenderness: 4.0,
        arc: None,
    };
    solve(&p, MESH, cavitation).unwrap().load_integral()
}

/// The reduction the table rests on, on direct solves: the load is
/// positively homogeneous of degree 1 in the source (to round-off: the
/// discrete problem is), and rotating position and source together rotates
/// it (to the mesh's discretization error: the nodes do not rotate; below
/// 0.1 % of the load on this mesh, inside the 0.5 % the table must meet
/// against direct solves).
#[test]
fn load_is_homogeneous_and_rotates_with_the_film() {
    let mut rng = rng::Rng(47);
    let mut worst_rotation = 0.0f64;
    for cavitation in [Cavitation::SwiftStieber, Cavitation::Gumbel] {
        for _ in 0..40 {
            let eps = 0.9 * rng.unit();
            let chi = std::f64::consts::TAU * rng.unit();
            let phi = std::f64::consts::TAU * rng.unit();
            let x0 = Vector2::new(eps, 0.0);
            let s0 = Vector2::new(chi.cos(), chi.sin());
            let base = load(x0, s0, cavitation);
            let scaled = load(x0, s0 * 3.7, cavitation);
            assert!(
                (scaled - base * 3.7).norm() <= 1e-10 * scaled.norm(),
                "{cavitation:?}: not homogeneous at ε = {eps}, χ = {chi}"
            );
            let turned = load(rotate(x0, phi), rotate(s0, phi), cavitation);
            let err = (turned - rotate(base, phi)).norm() / base.norm();
            worst_rotation = worst_rotation.max(err);
        }
    }
    assert!(worst_rotation < 1e-3, "rotation: {worst_rotation}");
    println!("worst relative rotation defect: {worst_rotation:.2e}");
}

/// A random journal state: ε ≤ 0.9 anywhere around the bushing, the
/// velocity in any direction, its size from rest to a few times `ω C`.
fn random_state(rng: &mut rng::Rng, speed: f64, clearance: f64) -> JournalState {
    let eps = 0.9 * rng.unit();
    let phi = std::f64::consts::TAU * rng.unit();
    let dir = std::f64::consts::TAU * rng.unit();
    let v = 2.0 * speed * clearance * rng.unit();
    JournalState {
        position: Vector2::new(phi.cos(), phi.sin()) * eps * clearance,
        velocity: Vector2::new(dir.cos(), dir.sin()) * v,
    }
}

fn max_abs(m: &Matrix2<f64>) -> f64 {
    m.iter().fold(0.0, |a, v| a.max(v.abs()))
}

/// Acceptance 4: on 1000 random states the table force is within 0.5 % of
/// the direct solve, and the table's Jacobian is the derivative of the table
/// force (central differences, 1e-6 relative).
#[test]
fn table_matches_direct_solves_and_its_jacobian_is_its_derivative() {
    let speed = 300.0;
    for cavitation in [Cavitation::SwiftStieber, Cavitation::Gumbel] {
        let film = film(cavitation, 0.5);
        let table = FilmTable::build(TableGeometry::of(&film)).unwrap();
        let mut rng = rng::Rng(4700 + cavitation as u64);
        let (mut worst_force, mut worst_k, mut worst_c) = (0.0f64, 0.0f64, 0.0f64);
        for _ in 0..1000 {
            let state = random_state(&mut rng, speed, film.clearance);
            let direct = film.force(&state, speed, None).unwrap();
            let tab = table.force_and_jacobian(&film, &state, speed).unwrap();
            let ef = (tab.force - direct).norm() / direct.norm();
            worst_force = worst_force.max(ef);
            let at = |position, velocity| {
                table
                    .force_and_jacobian(&film, &JournalState { position, velocity }, speed)
                    .unwrap()
                    .force
            };
            // The force turns with the position's angle, which a step `dp`
            // moves by `dp/(ε C)`: steps shrink with ε near the centre.
            let eps = state.position.norm() / film.clearance;
            let dp = 1e-6 * film.clearance * (eps / 1e-2).min(1.0);
            let dv = 1e-6 * speed * film.clearance;
            let (mut k, mut c) = (Matrix2::zeros(), Matrix2::zeros());
            for j in 0..2 {
                let mut e = Vector2::zeros();
                e[j] = 1.0;
                let (p, v) = (state.position, state.velocity);
                k.set_column(j, &(-(at(p + e * dp, v) - at(p - e * dp, v)) / (2.0 * dp)));
                c.set_column(j, &(-(at(p, v + e * dv) - at(p, v - e * dv)) / (2.0 * dv)));
            }
            let ek = max_abs(&(k - tab.stiffness)) / max_abs(&tab.stiffness);
            worst_k = worst_k.max(ek);
            worst_c = worst_c.max(max_abs(&(c - tab.damping)) / max_abs(&tab.damping));
        }
        println!("{cavitation:?}: force {worst_force:.2e}, K {worst_k:.2e}, C {worst_c:.2e}");
        assert!(
            worst_force <= 5e-3,
            "{cavitation:?}: force off by {worst_force}"
        );
        assert!(worst_k <= 1e-6, "{cavitation:?}: K off by {worst_k}");
        assert!(worst_c <= 1e-6, "{cavitation:?}: C off by {worst_c}");
    }
}

/// The cache: a file round-trips to the identical table; a corrupt file
/// (one flipped bit), a truncated one and one of another geometry are
/// detected and rebuilt, never used.
#[test]
fn cache_round_trips_and_rejects_bad_files() {
    let geometry = TableGeometry {
        slenderness: 4.0,
        mesh: ReynoldsMesh {
            circumferential: 24,
            axial: 2,
        },
        cavitation: Cavitation::Gumbel,
    };
    let other = TableGeometry {
        cavitation: Cavitation::SwiftStieber,
        ..geometry
    };
    let dir = std::env::temp_dir().join(format!("rotor-film-tables-{}", std::process::id()));
    table_cache::assert_round_trip(&geometry, &other, &dir);
}

/// The Jeffcott model (two plain bearings, L/D 0.5) on the finite film
/// (mesh 72 × 6, `cavitation`), with `film_tables = tables`, its tables
/// cached in `dir`.
fn jeffcott(
    cavitation: &str,
    tables: bool,
    dir: &std::path::Path,
) -> rotor_bearing::model::RotorModel {
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/jeffcott.toml");
    let text = std::fs::read_to_string(path).unwrap().replace(
        "type = \"plain\"\n",
        &format!(
            "type = \"plain\"\nfilm = \"finite\"\nfilm_mesh = [72, 6]\ncavitation = \"{cavitation}\"\nfilm_tables = {tables}\n"
        ),
    );
    rotor_bearing::model::RotorModel::from_toml_cached(&text, "jeffcott_tables.toml", Some(dir))
        .unwrap()
}

/// The journal's path (left bearing, m) every 0.25 ms over 40 ms at the
/// nominal speed, released at rest from the bushing's centre: the drop into
/// the film and the spiral onto the equilibrium under the unbalance.
fn drop_orbit(model: rotor_bearing::model::RotorModel) -> Vec<Vector2<f64>> {
    use rotor_bearing::solver::{Simulator, SolverOptions};
    let speed = model.nominal_speed;
    let mut sim = Simulator::new(
        rotor_bearing::rotor::Rotor::new(model).unwrap(),
        SolverOptions {
            time_step: 1e-4,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    sim.set_speed(speed, 0.0).unwrap();
    sim.consistent_acceleration().unwrap();
    (1..=160)
        .map(|k| {
            sim.advance_to(k as f64 * 2.5e-4).unwrap();
            let o = sim.outputs().unwrap();
            Vector2::new(o.bearings[0].x, o.bearings[0].y)
        })
        .collect()
}

/// Acceptance 4, transient: the Jeffcott rotor dropped into its films with
/// force tables follows the path of the same run with direct Reynolds
/// solves to 1e-3 of the orbit's size (the largest excursion from the
/// centre), Swift–Stieber and Gümbel; the tables are built once and read
/// from the cache by the second bearing.
#[test]
fn transient_with_tables_follows_the_direct_solves() {
    let dir = std::env::temp_dir().join(format!("rotor-film-transient-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    for cavitation in ["swift_stieber", "gumbel"] {
        let tabled = jeffcott(cavitation, true, &dir);
        let rotor_bearing::bearing::BearingKind::FiniteFilm(f) = &tabled.bearings[1].kind else {
            panic!("not a finite film")
        };
        assert!(
            matches!(f.table.as_deref().unwrap().origin, TableOrigin::Loaded(_)),
            "the second bearing of the same geometry reads the first one's table"
        );
        let with = drop_orbit(tabled);
        let without = drop_orbit(jeffcott(cavitation, false, &dir));
        let size = without.iter().map(|p| p.norm()).fold(0.0, f64::max);
        let worst = with
            .iter()
            .zip(&without)
            .map(|(a, b)| (a - b).norm())
            .fold(0.0, f64::max);
        println!(
            "{cavitation}: orbit {size:.3e} m, largest difference {:.2e} of it",
            worst / size
        );
        assert!(size > 2e-5, "{cavitation}: the journal drops {size} m");
        assert!(
            worst <= 1e-3 * size,
            "{cavitation}: {} of the orbit",
            worst / size
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `film_tables` in a model: refused without `film = "finite"`, the error
/// naming file, line, field and value; `false` is the direct film (tilting
/// pads' tables: `tests/pad_tables.rs`).
#[test]
fn film_tables_key_is_checked() {
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/jeffcott.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let with = |lines: &str| {
        text.replacen(
            "type = \"plain\"\n",
            &format!("type = \"plain\"\n{lines}\n"),
            1,
        )
    };
    let err = |t: &str| {
        rotor_bearing::model::RotorModel::from_toml_cached(t, "m.toml", None)
            .unwrap_err()
            .to_string()
    };
    let e = err(&with("film_tables = true"));
    assert!(
        e.starts_with("m.toml:34: bearings[0].film_tables = given:")
            && e.contains("finite film only"),
        "{e}"
    );
    let m = rotor_bearing::model::RotorModel::from_toml_cached(
        &with("film = \"finite\"\nfilm_tables = false"),
        "m.toml",
        None,
    )
    .unwrap();
    let rotor_bearing::bearing::BearingKind::FiniteFilm(f) = &m.bearings[0].kind else {
        panic!("not a finite film")
    };
    assert!(f.table.is_none());
}

/// The CLI and the FMU: reading a model with `film_tables = true` builds its
/// table once and says how long it took (a second read is silent: it reads
/// the cache); `rotor fmu-stage` puts the table in `resources/film_tables`,
/// where the FMU's instance reads it ([`rotor_bearing::fmu::resources`]):
/// the same table.
#[test]
fn fmu_carries_its_tables_in_resources() {
    let dir = std::env::temp_dir().join(format!("rotor-film-fmu-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/jeffcott.toml");
    let text = std::fs::read_to_string(path).unwrap().replace(
        "type = \"plain\"\n",
        "type = \"plain\"\nfilm = \"finite\"\nfilm_mesh = [48, 4]\ncavitation = \"gumbel\"\nfilm_tables = true\n",
    );
    let model = dir.join("jeffcott_tables.toml");
    std::fs::write(&model, text).unwrap();
    let stage = |to: &str| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
            .env("ROTOR_CACHE_DIR", dir.join("cache"))
            .args([
                "fmu-stage",
                model.to_str().unwrap(),
                dir.join(to).to_str().unwrap(),
            ])
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8_lossy(&out.stderr).into_owned()
    };
    let first = stage("a");
    assert!(
        first.contains(
            "bearing left: film table L/D = 0.5000, mesh 48 × 4, gumbel cavitation: built in"
        ) && first.contains("cached at"),
        "{first}"
    );
    assert!(!first.contains("bearing right: film table"), "{first}");
    let second = stage("b");
    assert!(!second.contains("film table"), "{second}");
    let resources = dir.join("b/resources");
    let files: Vec<_> =
        std::fs::read_dir(resources.join(rotor_bearing::fmu::resources::FILM_TABLES))
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
    assert_eq!(files.len(), 1, "{files:?}");
    let m = rotor_bearing::model::RotorModel::from_file_cached(
        &resources.join("model.toml"),
        Some(&resources.join(rotor_bearing::fmu::resources::FILM_TABLES)),
    )
    .unwrap();
    let cached = rotor_bearing::model::RotorModel::from_toml_cached(
        &std::fs::read_to_string(&model).unwrap(),
        "m.toml",
        Some(&dir.join("cache")),
    )
    .unwrap();
    for (b, c) in m.bearings.iter().zip(&cached.bearings) {
        let (
            rotor_bearing::bearing::BearingKind::FiniteFilm(f),
            rotor_bearing::bearing::BearingKind::FiniteFilm(g),
        ) = (&b.kind, &c.kind)
        else {
            panic!("not finite films")
        };
        let (t, u) = (f.table.as_deref().unwrap(), g.table.as_deref().unwrap());
        assert_eq!(t.origin, TableOrigin::Loaded(files[0].clone()));
        assert!(t.table == u.table);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
