//! The real-arithmetic shift-invert Arnoldi of `analysis::modal` (one real
//! banded factorization per speed, real Krylov basis) against two independent
//! truths:
//!
//! 1. each mode refined by nonlinear inverse iteration on the quadratic
//!    eigenproblem `Q(λ) x = (K + λD + λ²M) x = 0` (Ruhe, SIAM J. Numer. Anal.
//!    10, 1973): `u = Q(λ)⁻¹ Q'(λ) x`, `λ ← λ − cᴴx / cᴴu`, `x ← u / cᴴu`, a
//!    complex banded factorization at every iterate, quadratically convergent
//!    and free of the first-order form's rounding;
//! 2. the Campbell diagrams computed by the previous implementation (complex
//!    Arnoldi on the same operator), stored in `tests/data/campbell_reference/`,
//!    on the classic rotor, the Jeffcott rotor (plain bearings, linearized), the
//!    hydro unit (tilting pads) and a 3 m shaft in 120 elements.

use std::path::{Path, PathBuf};

use nalgebra::Complex;
use rotor_bearing::analysis::campbell::{CampbellPoint, campbell};
use rotor_bearing::analysis::linearize::linearized;
use rotor_bearing::analysis::modal::{ModalOptions, Mode, NON_OSCILLATING_DAMPING_RATIO, modes};
use rotor_bearing::linalg::{BandMatrix, map_to_complex};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;

type C64 = Complex<f64>;

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/campbell_reference")
        .join(name)
}

fn rotor(name: &str) -> Rotor {
    let path = match name {
        "long_shaft_120" => data("long_shaft_120.toml"),
        _ => Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("models/{name}.toml")),
    };
    Rotor::new(RotorModel::from_file(&path).unwrap()).unwrap()
}

/// One row of a stored diagram: speed (rad/s), rank, frequency, ζ, whirl.
struct Row {
    speed: f64,
    rank: usize,
    frequency: f64,
    damping_ratio: f64,
    whirl: String,
}

/// The stored diagram without its non-oscillating roots (ζ ≥
/// [`NON_OSCILLATING_DAMPING_RATIO`]: the hydro unit's film roots, which the
/// previous implementation listed as modes), ranks counted again per speed.
fn reference(name: &str) -> Vec<Row> {
    let text = std::fs::read_to_string(data(&format!("{name}.csv"))).unwrap();
    let mut rows: Vec<Row> = text
        .lines()
        .skip(1)
        .map(|line| {
            let f: Vec<&str> = line.split(',').collect();
            Row {
                speed: f[1].parse().unwrap(),
                rank: f[2].parse::<usize>().unwrap() - 1,
                frequency: f[3].parse().unwrap(),
                damping_ratio: f[5].parse().unwrap(),
                whirl: f[7].to_string(),
            }
        })
        .filter(|r| r.damping_ratio < NON_OSCILLATING_DAMPING_RATIO)
        .collect();
    let mut last = f64::NAN;
    let mut rank = 0;
    for r in &mut rows {
        if r.speed != last {
            (last, rank) = (r.speed, 0);
        }
        r.rank = rank;
        rank += 1;
    }
    rows
}

fn speeds(rows: &[Row]) -> Vec<f64> {
    let mut s: Vec<f64> = rows.iter().map(|r| r.speed).collect();
    s.dedup();
    s
}

/// `λ` refined by nonlinear inverse iteration on `(K + λD + λ²M) x = 0`.
fn refined(linear: &Rotor, speed: f64, mode: &Mode) -> C64 {
    let mut d = linear.damping.clone();
    d.scale_add(speed, &linear.gyroscopic);
    let (k, d, m) = (
        map_to_complex(&linear.stiffness),
        map_to_complex(&d),
        map_to_complex(&linear.mass),
    );
    let n = linear.dof_count();
    let mut x: Vec<C64> = (0..n).map(|i| mode.shape[linear.dofs.full(i)]).collect();
    let c = x.clone();
    let dot = |a: &[C64], b: &[C64]| {
        a.iter()
            .zip(b)
            .fold(C64::default(), |s, (p, q)| s + p.conj() * q)
    };
    let scale = dot(&c, &x);
    x.iter_mut().for_each(|z| *z /= scale);
    let mut lambda = mode.eigenvalue;
    for _ in 0..6 {
        let mut q: BandMatrix<C64> = k.clone();
        q.scale_add(lambda, &d);
        q.scale_add(lambda * lambda, &m);
        let mut dq = d.clone();
        dq.scale_add(2.0 * lambda, &m);
        let mut u = vec![C64::default(); n];
        dq.mul_vec(&x, &mut u);
        match q.lu() {
            Ok(lu) => lu.solve_in_place(&mut u),
            Err(_) => break, // λ is an eigenvalue to working precision
        }
        let cu = dot(&c, &u);
        let step = dot(&c, &x) / cu;
        lambda -= step;
        x = u.iter().map(|z| z / cu).collect();
        if step.norm() <= 1e-15 * lambda.norm() {
            break;
        }
    }
    lambda
}

/// The diagram of `name` on the stored grid, the worst differences to the
/// refined modes (frequency relative, ζ absolute), and the refined eigenvalues
/// by speed and rank.
fn diagram_against_refinement(name: &str) -> (Vec<CampbellPoint>, f64, f64, Vec<C64>) {
    let rotor = rotor(name);
    let rows = reference(name);
    let options = ModalOptions::default();
    let grid = speeds(&rows);
    let diagram = campbell(&rotor, &grid, &options).unwrap();
    let (mut worst_f, mut worst_z) = (0.0f64, 0.0f64);
    let mut refined_all = Vec::new();
    for &speed in &grid {
        let linear = if rotor.nonlinear_bearings.is_empty() {
            rotor.clone_model().unwrap()
        } else {
            linearized(&rotor, speed, speed).unwrap()
        };
        for mode in modes(&linear, speed, &options).unwrap() {
            let truth = refined(&linear, speed, &mode);
            refined_all.push(truth);
            let zeta = -truth.re / truth.norm();
            worst_f = worst_f.max((mode.damped_frequency / truth.im - 1.0).abs());
            worst_z = worst_z.max((mode.damping_ratio - zeta).abs());
        }
    }
    (diagram, worst_f, worst_z, refined_all)
}

#[test]
fn campbell_modes_match_refined_eigenvalues_and_previous_implementation() {
    for name in [
        "classic_disk_rotor",
        "jeffcott",
        "hydro_unit",
        "long_shaft_120",
    ] {
        let (diagram, truth_f, truth_z, truth) = diagram_against_refinement(name);
        assert!(
            truth_f < 1e-11 && truth_z < 1e-11,
            "{name}: against refinement: frequency {truth_f:e}, ζ {truth_z:e}"
        );
        let rows = reference(name);
        let modes: Vec<_> = diagram
            .iter()
            .flat_map(|p| {
                p.modes
                    .iter()
                    .enumerate()
                    .map(move |(k, m)| (p.speed, k, m))
            })
            .collect();
        assert_eq!(modes.len(), truth.len(), "{name}: number of modes");
        // Every stored oscillating mode is in the diagram, at its speed and
        // rank; where the stored list lost slots to non-oscillating roots the
        // diagram lists the next modes as well.
        let stored: Vec<_> = modes
            .iter()
            .zip(&truth)
            .filter(|((speed, rank, _), _)| {
                rows.iter().any(|r| (r.speed, r.rank) == (*speed, *rank))
            })
            .collect();
        assert_eq!(stored.len(), rows.len(), "{name}: number of stored modes");
        if name != "hydro_unit" {
            assert_eq!(modes.len(), rows.len(), "{name}: no root was dropped");
        }
        let (mut worst_f, mut worst_z, mut old_f, mut old_z) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
        for (r, ((speed, rank, m), t)) in rows.iter().zip(stored) {
            assert_eq!((r.speed, r.rank), (*speed, *rank), "{name}: grid");
            assert_eq!(
                m.whirl.label(),
                r.whirl,
                "{name}: whirl at {speed} rad/s, rank {rank}"
            );
            // Unchanged to 1e-9, or by no more than the previous
            // implementation's own error against the refined eigenvalue.
            let df = (m.damped_frequency / r.frequency - 1.0).abs();
            let dz = (m.damping_ratio - r.damping_ratio).abs();
            let own_f = (r.frequency / t.im - 1.0).abs();
            let own_z = (r.damping_ratio + t.re / t.norm()).abs();
            assert!(
                df <= 1e-9 || df <= own_f + 1e-11,
                "{name}: {speed} rad/s, rank {rank}: {df:e}"
            );
            assert!(
                dz <= 1e-9 || dz <= own_z + 1e-11,
                "{name}: {speed} rad/s, rank {rank}: ζ {dz:e}"
            );
            (worst_f, worst_z) = (worst_f.max(df), worst_z.max(dz));
            (old_f, old_z) = (old_f.max(own_f), old_z.max(own_z));
        }
        eprintln!(
            "{name}: against refinement: frequency {truth_f:.1e}, ζ {truth_z:.1e}; against the previous \
             implementation: frequency {worst_f:.1e}, ζ {worst_z:.1e}, whose own error is {old_f:.1e}, ζ {old_z:.1e}"
        );
    }
}
