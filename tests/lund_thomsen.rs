//! Issue 47, acceptance 1 (published cases of arcs): the finite-length film
//! over partial arcs against Lund & Thomsen's (1978) isoviscous tables
//! (`tests/data/lund_thomsen_1978.csv`, its origin in the header): the
//! two-axial-groove bearing, two fixed 160° arcs between 20° grooves at the
//! horizontal split, L/D 0.5 and 1, C = 100 µm; and the elliptical bearing,
//! the same arcs with each lobe's centre displaced away from it by the
//! preload 0.5 of the lobe clearance 200 µm (a preloaded arc, as a pad is),
//! L/D 1; Swift–Stieber cavitation, D = 100 mm, μ = 0.02 Pa·s, 3000 rpm. For each tabulated Sommerfeld
//! number the load `W = μ N L D (R/C)² / S` is carried by the two arcs
//! (`FiniteFilm::force_and_jacobian` over each arc, summed; Newton on the
//! journal position), and the eccentricity, attitude angle and the
//! dimensionless stiffness `K_ij C / W` and damping `c_ij C ω / W` at that
//! equilibrium are compared in their frame (x along the load, y horizontal
//! in the sense of rotation). Tolerances: ε within 0.01 and φ within 1°
//! (2.5° on the elliptical bearing, whose S = 0.161 row prints 83.29°
//! against its neighbours' trend near 85°, as ROSS's test notes; the table
//! prints ε to three decimals); each coefficient within 3 % of
//! the table, or within 1.5 % of the largest coefficient of its matrix where
//! the entry is small (a cross term near its sign change, printed to two
//! decimals; ROSS's own test allows 6 % and 0.06). Measured: ε within
//! 0.001, φ within 0.11° (1.99° on that row), the coefficients within 2.9 % (the small cross
//! terms `K_yx` within 1.1 % of their matrix's scale). Mesh: 96 × 16 per
//! arc, whose coefficients are within 0.5 % of 192 × 32 (checked on the
//! first row).

use nalgebra::{Matrix2, Vector2};

use rotor_bearing::bearing::JournalState;
use rotor_bearing::bearing::finite_film::FiniteFilm;
use rotor_bearing::bearing::reynolds::{Cavitation, ReynoldsMesh};

const DIAMETER: f64 = 0.1;
const CLEARANCE: f64 = 100e-6;
const VISCOSITY: f64 = 0.02;
const RPM: f64 = 3000.0;

struct Row {
    /// `two_axial_groove` or `elliptical`.
    kind: String,
    l_over_d: f64,
    sommerfeld: f64,
    eps: f64,
    phi_deg: f64,
    /// Kxx, Kxy, Kyx, Kyy.
    k: [f64; 4],
    /// Bxx, Bxy, Byy.
    b: [f64; 3],
}

fn rows() -> Vec<Row> {
    let text = include_str!("data/lund_thomsen_1978.csv");
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("kind"))
        .map(|l| {
            let (kind, rest) = l.split_once(',').unwrap();
            let v: Vec<f64> = rest.split(',').map(|x| x.trim().parse().unwrap()).collect();
            Row {
                kind: kind.to_string(),
                l_over_d: v[0],
                sommerfeld: v[1],
                eps: v[2],
                phi_deg: v[3],
                k: [v[4], v[5], v[6], v[7]],
                b: [v[8], v[9], v[10]],
            }
        })
        .collect()
}

/// The two arcs: 160° each, centred on the top (90°) and the bottom (270°).
const ARCS: [(f64, f64); 2] = [(10.0, 170.0), (190.0, 350.0)];

/// The lobes' centres of curvature (m): the bearing's centre for the
/// two-axial-groove bearing; for the elliptical one each lobe's centre
/// displaced vertically away from its arc by the preload times the lobe
/// clearance (the top lobe's downward), so the assembled clearance is
/// `C_p (1 − m)`.
fn centres(row: &Row) -> [Vector2<f64>; 2] {
    match row.kind.as_str() {
        "elliptical" => {
            let m = ELLIPTICAL_PRELOAD * clearance(row);
            [Vector2::new(0.0, -m), Vector2::new(0.0, m)]
        }
        _ => [Vector2::zeros(); 2],
    }
}

/// The lobe (pad) clearance `C_p` (m) every group of the table uses.
fn clearance(row: &Row) -> f64 {
    match row.kind.as_str() {
        "elliptical" => 200e-6,
        _ => CLEARANCE,
    }
}

const ELLIPTICAL_PRELOAD: f64 = 0.5;

/// Force and Jacobians of both arcs at journal position `p` (m), at rest,
/// each arc's film seeing the journal from its lobe's centre.
fn bearing(
    film: &FiniteFilm,
    p: Vector2<f64>,
    centres: &[Vector2<f64>; 2],
) -> (Vector2<f64>, Matrix2<f64>, Matrix2<f64>) {
    let speed = RPM * std::f64::consts::PI / 30.0;
    let mut out = (Vector2::zeros(), Matrix2::zeros(), Matrix2::zeros());
    for ((from, to), centre) in ARCS.into_iter().zip(centres) {
        let state = JournalState {
            position: p - centre,
            velocity: Vector2::zeros(),
        };
        let f = film
            .force_and_jacobian(&state, speed, Some((from.to_radians(), to.to_radians())))
            .unwrap();
        out.0 += f.force;
        out.1 += f.stiffness;
        out.2 += f.damping;
    }
    out
}

/// ε (over `C_p`), φ (degrees), the dimensionless K (xx, xy, yx, yy) and B
/// (xx, xy, yy) in Lund & Thomsen's frame at the equilibrium under `load`
/// (N, along −y).
fn solve(
    film: &FiniteFilm,
    load: f64,
    centres: &[Vector2<f64>; 2],
) -> (f64, f64, [f64; 4], [f64; 3]) {
    let cp = film.clearance;
    let mut p = Vector2::new(0.1 * cp, -0.2 * cp);
    let external = Vector2::new(0.0, -load);
    for _ in 0..60 {
        let (force, k, _) = bearing(film, p, centres);
        let residual = force + external;
        // F(p + dp) ≈ F(p) − K dp = −external.
        let mut dp = k
            .lu()
            .solve(&residual)
            .unwrap_or_else(|| panic!("singular K {k} at {p}"));
        // Damped: every lobe's film stays open (the journal within 0.95 of
        // each lobe's clearance from its centre).
        while centres.iter().any(|c| (p + dp - c).norm() > 0.95 * cp) {
            dp *= 0.5;
        }
        p += dp;
        if dp.norm() < 1e-10 * cp {
            break;
        }
    }
    let (force, k, c) = bearing(film, p, centres);
    assert!((force + external).norm() < 1e-6 * load, "not balanced");
    let omega = RPM * std::f64::consts::PI / 30.0;
    let eps = p.norm() / cp;
    // The attitude angle from the load line (−y) toward the sense of rotation (+x).
    let phi = p.x.atan2(-p.y).to_degrees();
    // Their x is along the load (−y here), their y horizontal (+x here):
    // Kxx = k_yy, Kxy = −k_yx, Kyx = −k_xy, Kyy = k_xx.
    let s = cp / load;
    let kk = [k[(1, 1)] * s, -k[(1, 0)] * s, -k[(0, 1)] * s, k[(0, 0)] * s];
    let bb = [
        c[(1, 1)] * s * omega,
        -c[(1, 0)] * s * omega,
        c[(0, 0)] * s * omega,
    ];
    (eps, phi, kk, bb)
}

fn film(row: &Row, mesh: ReynoldsMesh) -> FiniteFilm {
    FiniteFilm {
        radius: 0.5 * DIAMETER,
        length: row.l_over_d * DIAMETER,
        clearance: clearance(row),
        viscosity: VISCOSITY,
        mesh,
        cavitation: Cavitation::SwiftStieber,
    }
}

fn load(row: &Row) -> f64 {
    let (r, l) = (0.5 * DIAMETER, row.l_over_d * DIAMETER);
    VISCOSITY * RPM / 60.0 * l * DIAMETER * (r / clearance(row)).powi(2) / row.sommerfeld
}

const MESH: ReynoldsMesh = ReynoldsMesh {
    circumferential: 96,
    axial: 16,
};

#[test]
fn two_arc_bearings_against_lund_and_thomsen() {
    let (mut relative, mut of_scale): (f64, f64) = (0.0, 0.0);
    for row in rows() {
        let (eps, phi, k, b) = solve(&film(&row, MESH), load(&row), &centres(&row));
        let label = format!("{} L/D {} S {}", row.kind, row.l_over_d, row.sommerfeld);
        println!(
            "{label}: eps {eps:.3} ({}), phi {phi:.2} ({}), K {k:.3?} ({:?}), B {b:.3?} ({:?})",
            row.eps, row.phi_deg, row.k, row.b
        );
        assert!(
            (eps - row.eps).abs() <= 0.01,
            "{label}: eps {eps} vs {}",
            row.eps
        );
        // The elliptical table's S = 0.161 row prints 83.29° where its
        // neighbours' smooth trend (and this solve) give about 85.3°.
        let phi_tolerance = if row.kind == "elliptical" { 2.5 } else { 1.0 };
        assert!(
            (phi - row.phi_deg).abs() <= phi_tolerance,
            "{label}: phi {phi} vs {}",
            row.phi_deg
        );
        let k_scale = row.k.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let b_scale = row.b.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        for (got, want, scale, name) in k
            .iter()
            .zip(&row.k)
            .map(|(g, w)| (*g, *w, k_scale, "K"))
            .chain(b.iter().zip(&row.b).map(|(g, w)| (*g, *w, b_scale, "B")))
        {
            let error = (got - want).abs();
            if error > 0.03 * want.abs() {
                of_scale = of_scale.max(error / scale);
            } else {
                relative = relative.max(error / want.abs());
            }
            assert!(
                error <= (0.03 * want.abs()).max(0.015 * scale),
                "{label}: {name} {got:.3} vs {want} (table)"
            );
        }
    }
    println!(
        "within 3 %: up to {relative:.4} relative; the others up to {of_scale:.4} of their matrix's scale"
    );
}

/// The mesh is converged for the comparison: 96 × 16 within 0.5 % of
/// 192 × 32 on every coefficient (scaled by its matrix's largest), first row.
#[test]
fn the_arc_mesh_is_converged() {
    let row = &rows()[0];
    let fine = ReynoldsMesh {
        circumferential: 192,
        axial: 32,
    };
    let (e1, p1, k1, b1) = solve(&film(row, MESH), load(row), &centres(row));
    let (e2, p2, k2, b2) = solve(&film(row, fine), load(row), &centres(row));
    assert!(
        (e1 - e2).abs() < 1e-3 && (p1 - p2).abs() < 0.2,
        "{e1} {e2} {p1} {p2}"
    );
    let ks = k2.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let bs = b2.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    for (a, b) in k1.iter().zip(&k2) {
        assert!((a - b).abs() < 5e-3 * ks, "K {a} vs {b}");
    }
    for (a, b) in b1.iter().zip(&b2) {
        assert!((a - b).abs() < 5e-3 * bs, "B {a} vs {b}");
    }
}
