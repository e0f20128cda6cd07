//! Torsional modes that drop none (issue 45, acceptance 4): uniform shafts
//! against their exact discrete eigenvalues, two and three inertias on a
//! shaft against the continuum frequency equation and the massless closed
//! forms, at meshes from 2 to 1000 elements and densities from 0.01 to
//! 8000 kg/m³, each mode counted; damped eigenvalues against closed forms and
//! an independent dense complex solve.

use std::f64::consts::PI;

use rotor_bearing::analysis::torsion::{TorsionalMode, torsional_modes};
use rotor_bearing::model::{ModelError, RotorModel};

/// Steel-like shear modulus (Pa): `E = 210 GPa`, `ν = 0.3`.
const G: f64 = 210e9 / 2.6;

/// Meshes: every one from 2 to 24, then a sample up to 1000 (9, 180 and
/// 1000 among them).
fn meshes() -> Vec<usize> {
    let mut m: Vec<usize> = (2..=24).collect();
    m.extend([33, 50, 64, 90, 128, 180, 256, 400, 512, 700, 1000]);
    m
}

const DENSITIES: [f64; 5] = [0.01, 1.0, 100.0, 1000.0, 8000.0];

/// A shaft of `length` × `diameter` in `n` elements, a material of
/// `density`, `extra` appended (disks, supports, torsion keys).
fn shaft(length: f64, diameter: f64, n: usize, density: f64, extra: &str) -> String {
    format!(
        "name = \"chain\"\n[[materials]]\nname = \"m\"\nyoungs_modulus = 210e9\npoisson_ratio = 0.3\ndensity = {density}\n\
         [[shaft]]\nlength = {length}\nouter_diameter = {diameter}\nmaterial = \"m\"\nelements = {n}\n\
         [[bearings]]\ntype = \"linear\"\nnode = 1\nkxx = 1e7\nkyy = 1e7\n\
         [[bearings]]\ntype = \"linear\"\nnode = {}\nkxx = 1e7\nkyy = 1e7\n{extra}",
        n + 1
    )
}

fn disk(node: usize, polar: f64) -> String {
    format!(
        "[[disks]]\nnode = {node}\nmass = 1.0\npolar_inertia = {polar}\ndiametral_inertia = 0.5\n"
    )
}

fn modes_of(text: &str, count: usize) -> Vec<TorsionalMode> {
    let model = RotorModel::from_toml(text, "chain.toml").unwrap();
    torsional_modes(&model, count).unwrap()
}

/// A uniform shaft in `n` equal elements (stiffness `k = G J/L_e`, consistent
/// mass `m = ρ J L_e`) has, in closed form, the discrete eigenvalues
/// `ω_j² = (6k/m)(1 − cos θ_j)/(2 + cos θ_j)` (the twist `cos(i θ)` free–free,
/// `θ_j = jπ/n`; `sin(i θ)` fixed–free, `θ_j = (2j − 1)π/(2n)`: insert it in
/// any row of `K − ω² M`). They converge to `jπ/L √(G/ρ)` and
/// `(2j − 1)π/(2L) √(G/ρ)` as `1 + θ²/24`. The first three modes (fewer where
/// the mesh has fewer) match them at every mesh and density to 1e-9: the
/// eigensolvers are backward stable, so `ω²` carries an absolute error of
/// a few `ε λ_max`; with `λ_max/λ_1 ≤ 12 n²/π² ≈ 1.2e6` at 1000 elements
/// that is below 1e-9 of `ω` (measured: 7.6e-11 at worst).
#[test]
fn uniform_shafts_have_their_exact_discrete_frequencies_at_every_mesh_and_density() {
    let (length, diameter) = (2.0, 0.08);
    let mut worst: f64 = 0.0;
    for n in meshes() {
        for density in DENSITIES {
            for fixed in [false, true] {
                let support = if fixed {
                    "[[supports]]\nnode = 1\nfix = [\"rz\"]\n"
                } else {
                    ""
                };
                let modes = modes_of(&shaft(length, diameter, n, density, support), 3);
                // n elastic modes either way: n + 1 free DOFs less the
                // rigid rotation, or n free DOFs.
                assert_eq!(modes.len(), 3.min(n), "n {n}, ρ {density}, fixed {fixed}");
                let le = length / n as f64;
                for (j, m) in modes.iter().enumerate() {
                    let theta = if fixed {
                        (2 * j + 1) as f64 * PI / (2 * n) as f64
                    } else {
                        (j + 1) as f64 * PI / n as f64
                    };
                    // 1 − cos θ = 2 sin²(θ/2), without cancellation.
                    let half = (0.5 * theta).sin();
                    let want = (6.0 * G / (density * le * le) * 2.0 * half * half
                        / (2.0 + theta.cos()))
                    .sqrt();
                    let err = (m.natural_frequency / want - 1.0).abs();
                    worst = worst.max(err);
                    assert!(
                        err < 1e-9,
                        "n {n}, ρ {density}, fixed {fixed}, mode {}: {} against {want}",
                        j + 1,
                        m.natural_frequency
                    );
                    assert_eq!(m.damping_ratio, 0.0);
                }
            }
        }
    }
    eprintln!("uniform shafts: worst relative error {worst:.2e}");
}

/// Natural frequencies (rad/s, ascending, the first `count`) of disks `J_i`
/// at `z_i` on a continuous uniform free–free shaft of `length`, torsional
/// rigidity `gj = G J` and polar inertia per length `rho_j = ρ J`: the
/// roots of the end torque of the transfer matrices (shaft segment
/// `θ(l) = θ cos βl + T sin βl/(GJ β)`, `T(l) = −GJ β θ sin βl + T cos βl`,
/// `β = ω √(ρ/G)`; disk `T⁺ = T⁻ − J ω² θ`) from `θ = 1`, `T = 0` at the
/// left end. A geometric scan (ratio 1.002) brackets each sign change and
/// bisection closes it to adjacent doubles.
fn continuum_frequencies(
    length: f64,
    gj: f64,
    rho_j: f64,
    disks: &[(f64, f64)],
    count: usize,
) -> Vec<f64> {
    let end_torque = |w: f64| {
        let beta = w * (rho_j / gj).sqrt();
        let (mut theta, mut torque, mut z) = (1.0, 0.0, 0.0);
        let segment = |l: f64, theta: &mut f64, torque: &mut f64| {
            let x = beta * l;
            let sinc = if x == 0.0 { 1.0 } else { x.sin() / x };
            let (t0, q0) = (*theta, *torque);
            *theta = t0 * x.cos() + q0 * l / gj * sinc;
            *torque = -gj * beta * beta * l * sinc * t0 + q0 * x.cos();
        };
        for &(zd, j) in disks {
            segment(zd - z, &mut theta, &mut torque);
            z = zd;
            torque -= j * w * w * theta;
        }
        segment(length - z, &mut theta, &mut torque);
        torque
    };
    let mut roots = Vec::new();
    let mut w = 1e-3;
    let mut f = end_torque(w);
    while roots.len() < count {
        let next = w * 1.002;
        let g = end_torque(next);
        if f.signum() != g.signum() {
            let (mut lo, mut hi) = (w, next);
            loop {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                if end_torque(mid).signum() == f.signum() {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            roots.push(0.5 * (lo + hi));
        }
        (w, f) = (next, g);
        assert!(w < 1e12, "no root below 1e12 rad/s");
    }
    roots
}

/// Disks on a free–free shaft at every mesh and density: three modes are
/// asked for and all three (as many as the mesh has) listed; the disk modes
/// (and with two disks the first two shaft modes, well apart — with three,
/// the shaft's two spans give a near-double pair, left out) equal the continuum's roots
/// within the finite-element error. The consistent-mass elements are a
/// Rayleigh–Ritz approximation, so each `ω_h ≥ ω` (to round-off, 1e-9 as
/// in the uniform test); above, the error of a uniform shaft's mode is
/// `ω_h/ω − 1 = θ²/24 + O(θ⁴)`, `θ = β L_e` (the exact discrete form above),
/// and the bound `θ²/12` is allowed. Light shafts make the disk modes far
/// slower than the elements (`θ` ≈ 1e-7 at ρ = 0.01), where the old
/// element-scaled shift and filter lost them. At ρ = 0.01 the shaft's inertia
/// is below 1e-10 of the lightest disk's, and the disk modes also equal the
/// massless closed forms to 1e-9: two inertias `ω² = k (J₁ + J₂)/(J₁ J₂)`,
/// three the roots of `ω⁴ − (k₁ (J₁+J₂)/(J₁J₂) + k₂ (J₂+J₃)/(J₂J₃)) ω² +
/// k₁ k₂ (J₁+J₂+J₃)/(J₁J₂J₃) = 0`, `k_i = G J/l_i`.
fn disks_on_a_shaft(inertias: &[f64]) {
    let (length, diameter): (f64, f64) = (1.0, 0.1);
    let polar = PI * diameter.powi(4) / 32.0;
    let mut worst: f64 = 0.0;
    for n in meshes() {
        // Disks at the ends (and the node nearest mid-span).
        let nodes: Vec<usize> = match inertias.len() {
            2 => vec![0, n],
            _ => vec![0, n / 2, n],
        };
        let extra: String = nodes
            .iter()
            .zip(inertias)
            .map(|(&i, &j)| disk(i + 1, j))
            .collect();
        let at: Vec<(f64, f64)> = nodes
            .iter()
            .zip(inertias)
            .map(|(&i, &j)| (length * i as f64 / n as f64, j))
            .collect();
        for density in DENSITIES {
            let modes = modes_of(&shaft(length, diameter, n, density, &extra), 3);
            let compared = if inertias.len() == 2 { 3 } else { 2 };
            let want = continuum_frequencies(length, G * polar, density * polar, &at, compared);
            assert_eq!(modes.len(), 3.min(n), "n {n}, ρ {density}: a mode missing");
            let le = length / n as f64;
            for (k, (m, w)) in modes.iter().zip(&want).enumerate() {
                let theta = w * (density / G).sqrt() * le;
                let err = m.natural_frequency / w - 1.0;
                assert!(
                    err > -1e-9 && err < theta * theta / 12.0 + 1e-9,
                    "n {n}, ρ {density}, mode {}: {} against {w} (θ {theta:.2e})",
                    k + 1,
                    m.natural_frequency
                );
            }
            if density == 0.01 {
                let closed = massless(G * polar, &at);
                for (k, w) in closed.iter().enumerate() {
                    let got = modes[k].natural_frequency;
                    worst = worst.max((got / w - 1.0).abs());
                    assert!(
                        (got / w - 1.0).abs() < 1e-9,
                        "n {n}: mode {} {got} against the closed form {w}",
                        k + 1
                    );
                    assert!((want[k] / w - 1.0).abs() < 1e-9, "the continuum roots");
                }
            }
        }
    }
    eprintln!(
        "{} disks: worst relative error against the massless closed form {worst:.2e}",
        inertias.len()
    );
}

/// The massless-shaft closed forms for two or three disks `(z, J)` on a shaft
/// of rigidity `gj`.
fn massless(gj: f64, disks: &[(f64, f64)]) -> Vec<f64> {
    let j: Vec<f64> = disks.iter().map(|d| d.1).collect();
    let k: Vec<f64> = disks.windows(2).map(|w| gj / (w[1].0 - w[0].0)).collect();
    if j.len() == 2 {
        return vec![(k[0] * (j[0] + j[1]) / (j[0] * j[1])).sqrt()];
    }
    let b = k[0] * (j[0] + j[1]) / (j[0] * j[1]) + k[1] * (j[1] + j[2]) / (j[1] * j[2]);
    let c = k[0] * k[1] * (j[0] + j[1] + j[2]) / (j[0] * j[1] * j[2]);
    let disc = (b * b - 4.0 * c).sqrt();
    // The smaller root as c/(larger): no cancellation.
    let big = 0.5 * (b + disc);
    vec![(c / big).sqrt(), big.sqrt()]
}

#[test]
fn two_inertias_hold_at_every_mesh_and_density() {
    disks_on_a_shaft(&[2.0e3, 5.0e3]);
}

#[test]
fn three_inertias_hold_at_every_mesh_and_density() {
    disks_on_a_shaft(&[16360.0, 5964.0, 16360.0]);
}

/// The case of issue 45: a torsional train of heavy inertias (16 360, 5 964
/// and 16 360 kg·m² at the ends and mid-span) on a 1 m × 100 mm steel shaft
/// (ρ = 7850): the massless closed form gives 9.8457 and 25.0755 rad/s, and
/// the shaft's inertia (0.077 kg·m², 1.3e-5 of the middle disk) lowers them
/// by less than 1e-5. Both modes lead the list at 9, 90, 180 and 1000
/// elements (the old element-scaled shift and filter listed 25.075 rad/s as
/// mode 1 from 57 elements on and lost both from 143: mode 1 was then the
/// shaft's own, 20 155 rad/s).
#[test]
fn heavy_inertias_on_a_fine_steel_mesh_keep_their_first_mode() {
    let (length, diameter, rho): (f64, f64, f64) = (1.0, 0.1, 7850.0);
    let gj = G * PI * diameter.powi(4) / 32.0;
    let closed = massless(gj, &[(0.0, 16360.0), (0.5, 5964.0), (1.0, 16360.0)]);
    for n in [9, 90, 180, 1000] {
        let mid = n / 2;
        let extra = disk(1, 16360.0) + &disk(mid + 1, 5964.0) + &disk(n + 1, 16360.0);
        let modes = modes_of(&shaft(length, diameter, n, rho, &extra), 3);
        assert_eq!(modes.len(), 3, "n {n}");
        let want = massless(
            gj,
            &[
                (0.0, 16360.0),
                (mid as f64 / n as f64, 5964.0),
                (1.0, 16360.0),
            ],
        );
        for k in 0..2 {
            let got = modes[k].natural_frequency;
            assert!(
                (got / want[k] - 1.0).abs() < 1e-5,
                "n {n}, mode {}: {got} against {} rad/s",
                k + 1,
                want[k]
            );
        }
        // The third is the shaft's own, thousands of rad/s up.
        assert!(modes[2].natural_frequency > 1e3, "n {n}: {:?}", modes[2]);
    }
    assert!((closed[0] - 9.846).abs() < 1e-3 && (closed[1] - 25.075).abs() < 1e-3);
}

/// The same train with a stiff flexible coupling (1e9 N·m/rad) in place of
/// the second element: the coupling's frequency scale, not the mesh, set the
/// old shift and filter, which lost the first disk mode (10.38 rad/s here)
/// already at 9 elements, listing 27.60 rad/s as mode 1, and both at 40. With the coupling's compliance in series,
/// `1/k₁ = (m − 1) L_e/(G J) + 1/k_c` over the `m` elements to mid-span, the
/// massless closed form holds to 1e-5 (the shaft's inertia, as above) at
/// 9, 40 and 180 elements.
#[test]
fn a_stiff_coupling_on_a_coarse_mesh_keeps_the_disk_modes() {
    let (length, diameter, rho, kc): (f64, f64, f64, f64) = (1.0, 0.1, 7850.0, 1e9);
    let gj = G * PI * diameter.powi(4) / 32.0;
    let (j1, j2, j3) = (16360.0, 5964.0, 16360.0);
    for n in [9, 40, 180] {
        let mid = n / 2;
        let le = length / n as f64;
        let extra = disk(1, j1)
            + &disk(mid + 1, j2)
            + &disk(n + 1, j3)
            + &format!("[[couplings]]\nnode = 2\ntorsional_stiffness = {kc}\n");
        let modes = modes_of(&shaft(length, diameter, n, rho, &extra), 3);
        assert_eq!(modes.len(), 3, "n {n}");
        let k1 = 1.0 / ((mid - 1) as f64 * le / gj + 1.0 / kc);
        let k2 = gj / ((n - mid) as f64 * le);
        let b = k1 * (j1 + j2) / (j1 * j2) + k2 * (j2 + j3) / (j2 * j3);
        let c = k1 * k2 * (j1 + j2 + j3) / (j1 * j2 * j3);
        let big = 0.5 * (b + (b * b - 4.0 * c).sqrt());
        for (k, want) in [(c / big).sqrt(), big.sqrt()].iter().enumerate() {
            let got = modes[k].natural_frequency;
            assert!(
                (got / want - 1.0).abs() < 1e-5,
                "n {n}, mode {}: {got} against {want} rad/s",
                k + 1
            );
        }
    }
}

/// Two disks `J₁`, `J₂` on a coupling of stiffness `k` and viscous damping
/// `c` (on a vanishing shaft, 1e-12 of their inertia): the relative twist
/// obeys `J_r θ̈ + c θ̇ + k θ = 0`, `J_r = J₁J₂/(J₁ + J₂)`, so the damped
/// eigenvalue is `s = (−c + i √(4 k J_r − c²))/(2 J_r)` to 1e-9, and the
/// printed damping ratio `c/(2 √(k J_r))`.
#[test]
fn a_damped_coupling_gives_the_two_inertia_characteristic_roots() {
    let (j1, j2, k) = (2.0, 5.0, 1e5);
    for c in [0.0, 1.0, 30.0, 400.0] {
        let text = format!(
            "{}{}{}[[couplings]]\nnode = 1\ntorsional_stiffness = {k}\ntorsional_damping = {c}\n",
            shaft(0.001, 0.001, 1, 7810.0, ""),
            disk(1, j1),
            disk(2, j2)
        );
        let modes = modes_of(&text, 3);
        assert_eq!(modes.len(), 1);
        let jr = j1 * j2 / (j1 + j2);
        let want_re = -c / (2.0 * jr);
        let want_im = (4.0 * k * jr - c * c).sqrt() / (2.0 * jr);
        let s = modes[0].eigenvalue;
        let scale = (want_re * want_re + want_im * want_im).sqrt();
        assert!(
            (s.re - want_re).abs() < 1e-9 * scale && (s.im - want_im).abs() < 1e-9 * scale,
            "c {c}: {s} against {want_re} + {want_im}i"
        );
        let zeta = c / (2.0 * (k * jr).sqrt());
        assert!((modes[0].damping_ratio - zeta).abs() < 1e-9, "c {c}");
        assert!(((modes[0].natural_frequency / (k / jr).sqrt()) - 1.0).abs() < 1e-9);
    }
}

/// A modal damping ratio alone (`[torsion] damping_ratio = ζ`) damps each
/// listed mode by exactly `ζ`: `s = ω (−ζ + i √(1 − ζ²))` to 1e-9, on a
/// uniform fixed–free shaft.
#[test]
fn a_modal_damping_ratio_gives_each_mode_exactly_that_ratio() {
    for zeta in [0.02, 0.3] {
        let extra =
            format!("[[supports]]\nnode = 1\nfix = [\"rz\"]\n[torsion]\ndamping_ratio = {zeta}\n");
        let modes = modes_of(&shaft(2.0, 0.08, 40, 7850.0, &extra), 4);
        assert_eq!(modes.len(), 4);
        for m in &modes {
            let w = m.natural_frequency;
            let s = m.eigenvalue;
            assert!((s.re + zeta * w).abs() < 1e-9 * w, "{s} at {w}");
            assert!(
                (s.im - w * (1.0 - zeta * zeta).sqrt()).abs() < 1e-9 * w,
                "{s} at {w}"
            );
            assert!((m.damping_ratio - zeta).abs() < 1e-9);
        }
    }
}

/// Three disks on a damped shaft (section damping 20 N·m·s/rad), a damped
/// coupling in it and a modal ratio of 0.05 on the four listed modes: each
/// damped eigenvalue equals, to 1e-9, an eigenvalue of the first-order form
/// solved independently and densely: `M = L Lᵀ` (Cholesky), the undamped
/// modes of `L⁻¹ K L⁻ᵀ` (symmetric eigen, all of them, the rigid rotation
/// too), `C` built from the dampers and `Σ 2 ζ ω_j (M φ_j)(M φ_j)ᵀ` over the
/// four lowest elastic ones, and the state matrix `[[0, Ω], [−Ω, −Φᵀ C Φ]]`
/// in those modal coordinates (norm `ω_max` rather than `ω_max²`, so the
/// dense QR's round-off stays near 1e-12 of the lowest roots).
#[test]
fn damped_eigenvalues_equal_an_independent_dense_complex_solve() {
    use nalgebra::DMatrix;
    use rotor_bearing::rotor::torsion::TorsionalRotor;
    let zeta = 0.05;
    let extra = format!(
        "{}{}{}[[couplings]]\nnode = 3\ntorsional_stiffness = 2e4\ntorsional_damping = 5.0\n[torsion]\ndamping_ratio = {zeta}\n",
        disk(1, 1.0),
        disk(6, 0.5),
        disk(11, 2.0)
    );
    let text = shaft(1.0, 0.05, 10, 7850.0, &extra).replace(
        "elements = 10\n",
        "elements = 10\ntorsional_damping = 20.0\n",
    );
    let model = RotorModel::from_toml(&text, "damped.toml").unwrap();
    let modes = torsional_modes(&model, 4).unwrap();
    assert_eq!(modes.len(), 4);
    let chain = TorsionalRotor::new(&model);
    let n = chain.dof_count();
    let dense =
        |a: &rotor_bearing::linalg::BandMatrix<f64>| DMatrix::from_fn(n, n, |i, j| a.get(i, j));
    let (m, k, c) = (
        dense(&chain.mass),
        dense(&chain.stiffness),
        dense(&chain.damping),
    );
    let l = m.clone().cholesky().unwrap().l();
    let li = l.clone().try_inverse().unwrap();
    let eig = (&li * &k * li.transpose()).symmetric_eigen();
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| eig.eigenvalues[a].total_cmp(&eig.eigenvalues[b]));
    // M-orthonormal undamped modes, ascending; the first is the rigid rotation.
    let phi = DMatrix::from_fn(n, n, |i, j| {
        (li.transpose() * eig.eigenvectors.column(order[j]))[i]
    });
    let omega: Vec<f64> = order
        .iter()
        .map(|&j| eig.eigenvalues[j].max(0.0).sqrt())
        .collect();
    let mut damping = c.clone();
    // The four lowest elastic modes (after the rigid rotation).
    for (j, w) in omega.iter().enumerate().skip(1).take(4) {
        let mphi = &m * phi.column(j);
        damping += (&mphi * mphi.transpose()) * (2.0 * zeta * w);
    }
    let modal = phi.transpose() * damping * &phi;
    let mut state = DMatrix::<f64>::zeros(2 * n, 2 * n);
    for j in 0..n {
        state[(j, n + j)] = omega[j];
        state[(n + j, j)] = -omega[j];
        for i in 0..n {
            state[(n + i, n + j)] = -modal[(i, j)];
        }
    }
    let roots = state.complex_eigenvalues();
    let mut worst: f64 = 0.0;
    for (j, mode) in modes.iter().enumerate() {
        let s = mode.eigenvalue;
        let nearest = roots
            .iter()
            .map(|r| (r - s).norm())
            .fold(f64::INFINITY, f64::min);
        worst = worst.max(nearest / s.norm());
        assert!(
            nearest < 1e-9 * s.norm(),
            "mode {}: {s}, nearest root {nearest:.2e} away",
            j + 1
        );
        assert!(
            s.re < 0.0 && mode.damping_ratio > zeta,
            "mode {}: {s}",
            j + 1
        );
        assert!((mode.natural_frequency / omega[j + 1] - 1.0).abs() < 1e-9);
    }
    eprintln!("damped: worst relative distance to the dense roots {worst:.2e}");
}

/// The damping keys are validated like every key: the file, the line, the
/// field and the value are named.
#[test]
fn torsional_damping_keys_are_validated() {
    let bad = |text: &str, field: &str, value: &str| match RotorModel::from_toml(text, "bad.toml")
        .unwrap_err()
    {
        ModelError::Invalid {
            file,
            line,
            field: f,
            value: v,
            problem,
        } => {
            assert_eq!(
                (file.as_str(), f.as_str(), v.as_str()),
                ("bad.toml", field, value),
                "{problem}"
            );
            let at = text
                .lines()
                .position(|l| l.starts_with(field.rsplit('.').next().unwrap()));
            assert_eq!(line, at.map(|i| i + 1), "{problem}");
        }
        other => panic!("{other}"),
    };
    let negative = shaft(1.0, 0.05, 4, 7850.0, "")
        .replace("elements = 4\n", "elements = 4\ntorsional_damping = -2.5\n");
    bad(&negative, "shaft[0].torsional_damping", "-2.5");
    let critical = shaft(1.0, 0.05, 4, 7850.0, "[torsion]\ndamping_ratio = 1.0\n");
    bad(&critical, "torsion.damping_ratio", "1");
    let negative_ratio = shaft(1.0, 0.05, 4, 7850.0, "[torsion]\ndamping_ratio = -0.1\n");
    bad(&negative_ratio, "torsion.damping_ratio", "-0.1");
}

/// `rotor modes` prints, for a damped coupling between two disks, the
/// undamped frequency, the damping ratio `c/(2√(k J_r))` and the damped
/// frequency `√(4 k J_r − c²)/(4π J_r)` (to the printed digits), under a
/// header that says which are undamped; the shapes CSV carries both.
#[test]
fn the_cli_prints_undamped_and_damped_torsional_frequencies() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("torsion_modes_cli");
    std::fs::create_dir_all(&dir).unwrap();
    let (path, csv) = (dir.join("damped.toml"), dir.join("twist.csv"));
    let (j1, j2, k, c) = (2.0, 5.0, 1e5, 30.0);
    let text = format!(
        "{}{}{}[[couplings]]\nnode = 1\ntorsional_stiffness = {k}\ntorsional_damping = {c}\n",
        shaft(0.001, 0.001, 1, 7810.0, ""),
        disk(1, j1),
        disk(2, j2)
    );
    std::fs::write(&path, text).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(["modes", path.to_str().unwrap(), "--torsional-modes", "2"])
        .args(["--torsional-shapes-csv", csv.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert!(stdout.contains("ω and f undamped, f_d damped"), "{stdout}");
    let row: Vec<f64> = stdout
        .lines()
        .find(|l| l.trim_end().ends_with("torsional"))
        .unwrap()
        .split_whitespace()
        .take(6)
        .map(|x| x.parse().unwrap())
        .collect();
    let jr = j1 * j2 / (j1 + j2);
    let (wn, zeta) = ((k / jr).sqrt(), c / (2.0 * (k * jr).sqrt()));
    let fd = (4.0 * k * jr - c * c).sqrt() / (2.0 * jr) / (2.0 * PI);
    assert!((row[2] - wn / (2.0 * PI)).abs() < 5e-5, "{stdout}");
    assert!((row[3] / zeta - 1.0).abs() < 5e-5, "{stdout}");
    assert!((row[5] - fd).abs() < 5e-5, "{stdout}");
    let shapes = std::fs::read_to_string(&csv).unwrap();
    let first: Vec<f64> = shapes
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect();
    assert!((first[3] / fd - 1.0).abs() < 1e-9, "{shapes}");
    assert!(
        (first[1] / (wn / (2.0 * PI)) - 1.0).abs() < 1e-9,
        "{shapes}"
    );
}
