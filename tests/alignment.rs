//! Alignment of a statically indeterminate shaft line (issue 49, acceptance
//! 1): a straight uniform beam on three and four stiff linear bearings set
//! off the axis, under its own weight. Its bearing reactions
//! ([`alignment`](rotor_bearing::analysis::alignment::alignment)) are checked
//! against the closed-form flexibility solution written out below, for the
//! Euler–Bernoulli beam (`shear_deformation = false`) and for the Timoshenko
//! beam with its shear term; the reaction influence matrix against the same
//! closed form and against central differences of the statics.
//!
//! # The closed form (flexibility method)
//!
//! The shaft, `0 ≤ z ≤ L`, carries its weight `q = −ρ A g` (N/m, upward
//! positive) and the upward support forces `R_i` at `z_i`. Its deflection is
//! a rigid motion plus the deflection of the beam clamped at `z = 0` under all
//! these loads (which balance, so the clamp carries nothing):
//! `y(z) = a + b z + Σ_k R_k G(z, z_k) + v_q(z)`, with the cantilever's
//! influence function and weight deflection (bending `EI`, shear `κGA`):
//!
//! - `G(z, ζ) = z² (3ζ − z) / (6EI) + z/(κGA)` for `z ≤ ζ`,
//!   `ζ² (3z − ζ) / (6EI) + ζ/(κGA)` for `z ≥ ζ`;
//! - `v_q(z) = q z² (6L² − 4Lz + z²) / (24EI) + q (Lz − z²/2) / (κGA)`.
//!
//! (`1/(κGA) = 0` for Euler–Bernoulli.) A support of stiffness `k_i` whose
//! centre is raised by `o_i` pushes with `R_i = k_i (o_i − y(z_i))`. With the
//! two equilibrium equations `Σ R_i + q L = 0`, `Σ R_i z_i + q L²/2 = 0` this
//! is `n + 2` linear equations in `R_1 … R_n, a, b` — the compatibility
//! equations of the statically indeterminate beam (for rigid supports and
//! Euler–Bernoulli they are the three-moment equations in another basis).
//!
//! The Timoshenko element with its exact ("interdependent") shape functions
//! reproduces this solution at the nodes for nodal forces, and, its weight
//! being the consistent load of the same shape functions (Betti), for the
//! uniform weight too: the comparison holds to round-off, so the tolerance is
//! the issue's 1e-9 of the largest reaction. Cowper's shear factor of a solid
//! circle `κ = 6(1+ν)/(7+6ν)` and `G = E/(2(1+ν))` are the model's own.

use nalgebra::{DMatrix, DVector};
use rotor_bearing::analysis::alignment::{alignment, equal_specific_loads, offsets_for_loads};
use rotor_bearing::analysis::shaft_loads::section_loads;
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::SolverOptions;

const E: f64 = 211e9;
const NU: f64 = 0.3;
const RHO: f64 = 7810.0;
const G_ACC: f64 = 9.81;
const LENGTH: f64 = 3.0;
const DIAMETER: f64 = 0.1;
const ELEMENTS: usize = 30;
/// Support stiffness (N/m): about 5000 times the beam's own 48EI/L³.
const K_SUPPORT: f64 = 1e10;

/// A bearing of the line: its node (1-based) and offsets `(o_x, o_y)` (m).
struct Support {
    node: usize,
    offset: [f64; 2],
}

fn z_of(node: usize) -> f64 {
    LENGTH * (node - 1) as f64 / ELEMENTS as f64
}

fn model_text(supports: &[Support], shear: bool) -> String {
    let mut text = format!(
        r#"name = "line"
gravity = [0.0, -{G_ACC}, 0.0]
shear_deformation = {shear}
[[materials]]
name = "steel"
youngs_modulus = {E:e}
poisson_ratio = {NU}
density = {RHO}
[[shaft]]
length = {LENGTH}
outer_diameter = {DIAMETER}
material = "steel"
elements = {ELEMENTS}
"#
    );
    for (i, s) in supports.iter().enumerate() {
        text.push_str(&format!(
            "[[bearings]]\nname = \"b{i}\"\ntype = \"linear\"\nnode = {}\nkxx = {K_SUPPORT:e}\nkyy = {K_SUPPORT:e}\noffset_x = {:e}\noffset_y = {:e}\n",
            s.node, s.offset[0], s.offset[1]
        ));
    }
    text
}

fn rotor(supports: &[Support], shear: bool) -> Rotor {
    let model = RotorModel::from_toml(&model_text(supports, shear), "line.toml").unwrap();
    Rotor::new(model).unwrap()
}

/// The closed-form reactions `R_i` (N, upward) of the beam on `supports` in
/// one plane: offsets `o` (m) in that plane, distributed load `q` (N/m).
fn closed_form(z: &[f64], o: &[f64], q: f64, shear: bool) -> Vec<f64> {
    let area = std::f64::consts::PI * DIAMETER * DIAMETER / 4.0;
    let ei = E * std::f64::consts::PI * DIAMETER.powi(4) / 64.0;
    let kappa = 6.0 * (1.0 + NU) / (7.0 + 6.0 * NU);
    let shear_flex = if shear {
        1.0 / (kappa * E / (2.0 * (1.0 + NU)) * area)
    } else {
        0.0
    };
    let l = LENGTH;
    let g = |z: f64, zeta: f64| {
        if z <= zeta {
            z * z * (3.0 * zeta - z) / (6.0 * ei) + z * shear_flex
        } else {
            zeta * zeta * (3.0 * z - zeta) / (6.0 * ei) + zeta * shear_flex
        }
    };
    let v_q = |z: f64| {
        q * z * z * (6.0 * l * l - 4.0 * l * z + z * z) / (24.0 * ei)
            + q * (l * z - z * z / 2.0) * shear_flex
    };
    let n = z.len();
    let mut a = DMatrix::zeros(n + 2, n + 2);
    let mut rhs = DVector::zeros(n + 2);
    for i in 0..n {
        // a + b z_i + Σ_k G(z_i, z_k) R_k + R_i / k_i = o_i − v_q(z_i).
        for k in 0..n {
            a[(i, k)] = g(z[i], z[k]);
        }
        a[(i, i)] += 1.0 / K_SUPPORT;
        a[(i, n)] = 1.0;
        a[(i, n + 1)] = z[i];
        rhs[i] = o[i] - v_q(z[i]);
    }
    for k in 0..n {
        a[(n, k)] = 1.0;
        a[(n + 1, k)] = z[k];
    }
    rhs[n] = -q * l;
    rhs[n + 1] = -q * l * l / 2.0;
    let x = a.lu().solve(&rhs).unwrap();
    x.as_slice()[..n].to_vec()
}

fn weight_per_length() -> f64 {
    RHO * std::f64::consts::PI * DIAMETER * DIAMETER / 4.0 * G_ACC
}

/// Largest reaction error relative to the largest reaction, both planes.
fn reaction_error(supports: &[Support], shear: bool) -> f64 {
    let line = rotor(supports, shear);
    let found = alignment(&line, 0.0, &SolverOptions::default()).unwrap();
    let z: Vec<f64> = supports.iter().map(|s| z_of(s.node)).collect();
    let ox: Vec<f64> = supports.iter().map(|s| s.offset[0]).collect();
    let oy: Vec<f64> = supports.iter().map(|s| s.offset[1]).collect();
    let rx = closed_form(&z, &ox, 0.0, shear);
    let ry = closed_form(&z, &oy, -weight_per_length(), shear);
    let scale = ry.iter().chain(&rx).fold(0.0_f64, |m, r| m.max(r.abs()));
    let mut worst = 0.0_f64;
    for (k, b) in found.bearings.iter().enumerate() {
        worst = worst
            .max((b.reaction[0] - rx[k]).abs() / scale)
            .max((b.reaction[1] - ry[k]).abs() / scale);
        // The load along the load direction (up) is the y reaction.
        assert_eq!(b.load, b.reaction[1]);
    }
    println!(
        "{} supports, shear {shear}: reactions y {:?} N (closed form {ry:?}), x {rx:?}; worst relative error {worst:.2e}",
        supports.len(),
        found
            .bearings
            .iter()
            .map(|b| b.reaction[1])
            .collect::<Vec<_>>()
    );
    worst
}

fn three() -> Vec<Support> {
    vec![
        Support {
            node: 1,
            offset: [0.0, 0.0],
        },
        Support {
            node: 13,
            offset: [5e-5, 2e-4],
        },
        Support {
            node: 31,
            offset: [-3e-5, -1e-4],
        },
    ]
}

fn four() -> Vec<Support> {
    vec![
        Support {
            node: 2,
            offset: [1e-5, -5e-5],
        },
        Support {
            node: 11,
            offset: [0.0, 1.5e-4],
        },
        Support {
            node: 23,
            offset: [-4e-5, 3e-4],
        },
        Support {
            node: 31,
            offset: [2e-5, 0.0],
        },
    ]
}

#[test]
fn reactions_of_a_beam_on_three_and_four_offset_bearings_match_the_closed_form() {
    for supports in [three(), four()] {
        for shear in [false, true] {
            let worst = reaction_error(&supports, shear);
            assert!(worst < 1e-9, "relative error {worst:e}");
        }
    }
    // The shear term matters at this tolerance: without it the Timoshenko
    // line misses the closed form (the check can fail).
    let line = rotor(&three(), true);
    let found = alignment(&line, 0.0, &SolverOptions::default()).unwrap();
    let z: Vec<f64> = three().iter().map(|s| z_of(s.node)).collect();
    let oy: Vec<f64> = three().iter().map(|s| s.offset[1]).collect();
    let euler = closed_form(&z, &oy, -weight_per_length(), false);
    let miss = (found.bearings[1].reaction[1] - euler[1]).abs() / euler[1].abs();
    assert!(miss > 1e-6, "shear correction only {miss:e}");
}

/// The bending moment and shear along the line (element end forces) against
/// the same closed form: `M(z) = Σ_{z_k > z} R_k (z_k − z) + q (L − z)²/2`
/// (`EI y'' = M`), `V = dM/dz`, with the closed-form reactions; the stress
/// is `|M| D / (2I)`.
#[test]
fn bending_moments_along_the_line_match_the_closed_form() {
    for supports in [three(), four()] {
        let line = rotor(&supports, true);
        let found = alignment(&line, 0.0, &SolverOptions::default()).unwrap();
        let all = line.dofs.expand(&found.equilibrium.displacement);
        let loads = section_loads(&line, &all, true);
        assert_eq!(loads.len(), 2 * ELEMENTS);
        let z: Vec<f64> = supports.iter().map(|s| z_of(s.node)).collect();
        let q = -weight_per_length();
        let planes = [
            closed_form(
                &z,
                &supports.iter().map(|s| s.offset[0]).collect::<Vec<_>>(),
                0.0,
                true,
            ),
            closed_form(
                &z,
                &supports.iter().map(|s| s.offset[1]).collect::<Vec<_>>(),
                q,
                true,
            ),
        ];
        let loads_of = [0.0, q];
        let (mut worst_m, mut worst_v, mut scale) = (0.0_f64, 0.0_f64, 0.0_f64);
        let inertia = std::f64::consts::PI * DIAMETER.powi(4) / 64.0;
        for (k, l) in loads.iter().enumerate() {
            let left_end = k % 2 == 0;
            for p in 0..2 {
                let (r, w) = (&planes[p], loads_of[p]);
                let m: f64 = z
                    .iter()
                    .zip(r)
                    .filter(|(zk, _)| **zk > l.z)
                    .map(|(zk, rk)| rk * (zk - l.z))
                    .sum::<f64>()
                    + w * (LENGTH - l.z).powi(2) / 2.0;
                // Shear just right of a left end, just left of a right end.
                let v = -z
                    .iter()
                    .zip(r)
                    .filter(|(zk, _)| {
                        if left_end {
                            **zk > l.z + 1e-12
                        } else {
                            **zk > l.z - 1e-12
                        }
                    })
                    .map(|(_, rk)| rk)
                    .sum::<f64>()
                    - w * (LENGTH - l.z);
                scale = scale.max(m.abs());
                worst_m = worst_m.max((l.moment[p] - m).abs());
                worst_v = worst_v.max((l.shear[p] - v).abs());
            }
            let stress = l.moment[0].hypot(l.moment[1]) * DIAMETER / (2.0 * inertia);
            assert!((l.stress - stress).abs() <= 1e-12 * stress.max(1.0));
        }
        println!(
            "{} supports: bending moment error {:.2e} of {scale:.4e} N·m, shear error {worst_v:.2e} N",
            supports.len(),
            worst_m / scale
        );
        assert!(worst_m < 1e-9 * scale, "{worst_m:e}");
        assert!(worst_v < 1e-9 * weight_per_length() * LENGTH, "{worst_v:e}");
    }
}

/// The influence matrix: against the closed form (the reactions are linear
/// in the offsets: the closed form with unit offsets and no weight) and
/// against central differences of the statics, `h = 1 µm`.
#[test]
fn the_reaction_influence_matrix_matches_the_closed_form_and_finite_differences() {
    for supports in [three(), four()] {
        let n = supports.len();
        let line = rotor(&supports, true);
        let options = SolverOptions::default();
        let found = alignment(&line, 0.0, &options).unwrap();
        let s = &found.influence;
        let scale = s.amax();
        let z: Vec<f64> = supports.iter().map(|s| z_of(s.node)).collect();
        let (mut closed, mut fd) = (0.0_f64, 0.0_f64);
        for j in 0..n {
            let mut unit = vec![0.0; n];
            unit[j] = 1.0;
            let column = closed_form(&z, &unit, 0.0, true);
            for c in 0..2 {
                for i in 0..n {
                    closed = closed.max((s[(2 * i + c, 2 * j + c)] - column[i]).abs() / scale);
                    // No coupling between the planes of an isotropic line.
                    assert!(s[(2 * i + 1 - c, 2 * j + c)].abs() < 1e-12 * scale);
                }
                let h = 1e-6;
                let at = |delta: f64| {
                    let mut model = line.model.clone();
                    model.bearings[j].offset[c] += delta;
                    alignment(&Rotor::new(model).unwrap(), 0.0, &options).unwrap()
                };
                let (plus, minus) = (at(h), at(-h));
                for i in 0..n {
                    for a in 0..2 {
                        let d = (plus.bearings[i].reaction[a] - minus.bearings[i].reaction[a])
                            / (2.0 * h);
                        fd = fd.max((s[(2 * i + a, 2 * j + c)] - d).abs() / scale);
                    }
                }
            }
        }
        println!(
            "{n} supports: influence vs closed form {closed:.2e}, vs central differences {fd:.2e} (of max |S| = {scale:.4e} N/m)"
        );
        assert!(closed < 1e-9, "{closed:e}");
        assert!(fd < 1e-7, "{fd:e}");
    }
}

/// The three-bearing line with no offsets at all.
fn aligned_three() -> Vec<Support> {
    three()
        .into_iter()
        .map(|s| Support {
            node: s.node,
            offset: [0.0, 0.0],
        })
        .collect()
}

/// Least-norm offsets on linear bearings, checked against the influence
/// matrix arithmetic done here: the change of elevation is `S⁺ (t − R₀)`
/// (one Newton step is exact), it holds no rigid lift or tilt of the line
/// (`Σ Δ_i = 0`, `Σ Δ_i z_i = 0`: the pseudo-inverse's step lies in the
/// range of `Sᵀ`), a reachable target is met, and an unreachable one (equal
/// loads on three bearings: the loads must balance the weight and its
/// moment) is met in the least-squares sense with the residual it reports.
#[test]
fn least_norm_offsets_for_a_target_follow_the_influence_matrix_on_linear_bearings() {
    let options = SolverOptions::default();
    let line = rotor(&aligned_three(), true);
    let before = alignment(&line, 0.0, &options).unwrap();
    let weight: f64 = before.loads().iter().sum();
    // A reachable target: the loads of the line at the offsets of three().
    let target = alignment(&rotor(&three(), true), 0.0, &options)
        .unwrap()
        .loads();
    let found = offsets_for_loads(&line, 0.0, &options, &target, 1e-9 * weight, 5).unwrap();
    assert_eq!(found.iterations, 1);
    let s = before.load_influence();
    let residual = DVector::from_iterator(3, target.iter().zip(before.loads()).map(|(t, l)| t - l));
    let step = s.clone().pseudo_inverse(1e-9 * s.amax()).unwrap() * &residual;
    let z: Vec<f64> = three().iter().map(|s| z_of(s.node)).collect();
    let largest = step.amax();
    for (k, b) in found.achieved.bearings.iter().enumerate() {
        assert!((b.offset[1] - step[k]).abs() < 1e-9 * largest, "{k}");
        assert_eq!(b.offset[0], 0.0);
        assert!((b.load - target[k]).abs() < 1e-9 * weight, "{k}");
    }
    let lift: f64 = step.iter().sum();
    let tilt: f64 = step.iter().zip(&z).map(|(d, z)| d * z).sum();
    assert!(lift.abs() < 1e-9 * largest && tilt.abs() < 1e-9 * largest * LENGTH);
    assert!(found.unreachable < 1e-9 * weight);
    // Equal loads are out of reach on three bearings.
    let equal = equal_specific_loads(&before);
    assert!(
        equal
            .iter()
            .all(|l| (l - weight / 3.0).abs() < 1e-12 * weight)
    );
    let found = offsets_for_loads(&line, 0.0, &options, &equal, 1e-9 * weight, 5).unwrap();
    let residual = DVector::from_iterator(3, equal.iter().zip(before.loads()).map(|(t, l)| t - l));
    let reachable = &s * (s.clone().pseudo_inverse(1e-9 * s.amax()).unwrap() * &residual);
    let out_of_reach = (&residual - &reachable).norm();
    println!(
        "equal loads on three linear bearings: {:.3} N out of reach, achieved {:?}",
        found.unreachable,
        found.achieved.loads()
    );
    assert!(out_of_reach > 1.0);
    assert!((found.unreachable - out_of_reach).abs() < 1e-6 * out_of_reach);
    for (k, l) in found.achieved.loads().iter().enumerate() {
        assert!((l - before.loads()[k] - reachable[k]).abs() < 1e-9 * weight);
    }
    let total: f64 = found.achieved.loads().iter().sum();
    assert!((total - weight).abs() < 1e-9 * weight);
}

/// A rotor on three plain (short-film) bearings at 3000 rpm, the middle one
/// raised by `raise` (m): 1.2 m × 60 mm shaft, two 30 kg disks, R = L = 30 mm,
/// C = 80 µm, 0.02 Pa·s.
fn film_line(raise: f64) -> String {
    film_line_with(raise, 30.0)
}

/// [`film_line`] with the disk at node 10 of mass `second` (kg).
fn film_line_with(raise: f64, second: f64) -> String {
    let bearing = |name: &str, node: usize, o: f64| {
        format!(
            "[[bearings]]\nname = \"{name}\"\ntype = \"plain\"\nnode = {node}\nradius = 0.03\nlength = 0.03\nclearance = 80e-6\nviscosity = 0.02\noffset_y = {o:e}\n"
        )
    };
    let disk = |node: usize, mass: f64| {
        format!(
            "[[disks]]\nnode = {node}\nmass = {mass:?}\npolar_inertia = 0.2\ndiametral_inertia = 0.1\n"
        )
    };
    format!(
        "name = \"film3\"\nspeed_rpm = 3000\ngravity = [0.0, -9.81, 0.0]\n[[materials]]\nname = \"steel\"\nyoungs_modulus = 211e9\npoisson_ratio = 0.3\ndensity = 7810.0\n[[shaft]]\nlength = 1.2\nouter_diameter = 0.06\nmaterial = \"steel\"\nelements = 12\n{}{}{}{}{}",
        disk(4, 30.0),
        disk(10, second),
        bearing("left", 1, 0.0),
        bearing("middle", 7, raise),
        bearing("right", 13, 0.0)
    )
}

fn film_rotor(raise: f64) -> Rotor {
    Rotor::new(RotorModel::from_toml(&film_line(raise), "film3.toml").unwrap()).unwrap()
}

/// On nonlinear films the influence matrix is the tangent at the
/// equilibrium: central differences of the statics (h = 10 nm, 1.25e-4 of
/// the clearance, the statics solved to 1e-13) agree to 1e-7 of its largest
/// entry, the issue's tolerance (the truncation error of the difference,
/// (h/C)² ≈ 1.6e-8 times the films' third derivatives, and the solve's
/// round-off divided by 2h; measured 2e-10).
#[test]
fn the_film_influence_matrix_is_the_tangent_of_the_statics() {
    let options = SolverOptions {
        tolerance: 1e-13,
        ..SolverOptions::default()
    };
    let speed = 3000.0 * std::f64::consts::PI / 30.0;
    let line = film_rotor(3e-5);
    let found = alignment(&line, speed, &options).unwrap();
    let s = &found.influence;
    let scale = s.amax();
    let h = 1e-8;
    let mut worst = 0.0_f64;
    for j in 0..3 {
        for c in 0..2 {
            let at = |delta: f64| {
                let mut model = line.model.clone();
                model.bearings[j].offset[c] += delta;
                alignment(&Rotor::new(model).unwrap(), speed, &options).unwrap()
            };
            let (plus, minus) = (at(h), at(-h));
            for i in 0..3 {
                for a in 0..2 {
                    let d =
                        (plus.bearings[i].reaction[a] - minus.bearings[i].reaction[a]) / (2.0 * h);
                    worst = worst.max((s[(2 * i + a, 2 * j + c)] - d).abs() / scale);
                }
            }
        }
    }
    println!("film influence vs central differences: {worst:.2e} of max |S| = {scale:.4e} N/m");
    assert!(worst < 1e-7, "{worst:e}");
}

/// Equal specific load on three plain bearings, the middle one raised by
/// 30 µm: by the line's symmetry the target is reachable; Newton with the
/// least-norm step finds offsets whose statics (solved again from scratch
/// here) carry the target to the stated tolerance, 1e-6 of the weight,
/// without rigid lift or tilt of the line; `rotor alignment` prints them,
/// and `rotor static --shaft-csv` writes the library's section loads.
#[test]
fn offsets_for_equal_specific_load_on_plain_bearings() {
    let options = SolverOptions::default();
    let speed = 3000.0 * std::f64::consts::PI / 30.0;
    let line = film_rotor(3e-5);
    let before = alignment(&line, speed, &options).unwrap();
    let weight: f64 = before.loads().iter().sum();
    let target = equal_specific_loads(&before);
    let found = offsets_for_loads(&line, speed, &options, &target, 1e-6 * weight, 20).unwrap();
    let mut model = line.model.clone();
    for (b, o) in found.achieved.bearings.iter().zip(&found.offsets) {
        model.bearings[b.bearing].offset = *o;
    }
    let again = alignment(&Rotor::new(model).unwrap(), speed, &options).unwrap();
    let change: Vec<f64> = found
        .offsets
        .iter()
        .zip(&before.bearings)
        .map(|(o, b)| o[1] - b.offset[1])
        .collect();
    println!(
        "equal specific load on plain bearings: {} steps, loads {:?} N (target {target:?}), elevation changes {change:?} m",
        found.iterations,
        again.loads()
    );
    for (l, t) in again.loads().iter().zip(&target) {
        assert!((l - t).abs() < 1e-6 * weight, "{l} vs {t}");
    }
    let largest = change.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
    let lift: f64 = change.iter().sum();
    let tilt: f64 = change.iter().zip([0.0, 0.6, 1.2]).map(|(d, z)| d * z).sum();
    assert!(lift.abs() < 1e-9 * largest && tilt.abs() < 1e-9 * largest);
    // The CLI formats the same numbers.
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("alignment");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("film3.toml");
    std::fs::write(&path, film_line(3e-5)).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(["alignment", path.to_str().unwrap()])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        stdout.contains("reaction influence") && stdout.contains("offsets for equal specific load")
    );
    let row = stdout
        .lines()
        .skip_while(|l| !l.starts_with("offsets for"))
        .find(|l| l.starts_with("middle"))
        .unwrap();
    let achieved: f64 = row.split_whitespace().last().unwrap().parse().unwrap();
    assert!((achieved - target[1]).abs() < 0.1, "{row}");
    // `rotor static --shaft-csv` writes the library's section loads.
    let csv = dir.join("shaft.csv");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(["static", path.to_str().unwrap(), "--rpm", "3000"])
        .arg("--shaft-csv")
        .arg(&csv)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let all = line.dofs.expand(&before.equilibrium.displacement);
    let loads = section_loads(&line, &all, true);
    let text = std::fs::read_to_string(&csv).unwrap();
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), loads.len());
    // The CLI's speed is 3000 rpm / (30/π), ours 3000 π/30: equal to the
    // last bit or so, hence the round-off tolerance.
    let worst = rotor_bearing::analysis::shaft_loads::largest_stress(&loads).unwrap();
    let (m, sigma) = (worst.moment_magnitude, worst.stress);
    for (row, l) in rows.iter().zip(&loads) {
        assert_eq!(row[2], l.z);
        assert!((row[3] - l.moment[0]).abs() < 1e-9 * m);
        assert!((row[4] - l.moment[1]).abs() < 1e-9 * m);
        assert!((row[8] - l.stress).abs() < 1e-9 * sigma);
    }
    let stdout = String::from_utf8_lossy(&out.stdout);
    let printed = stdout
        .split("bending stress ")
        .nth(1)
        .and_then(|r| r.split(" Pa").next())
        .and_then(|v| v.parse::<f64>().ok())
        .unwrap_or_else(|| panic!("{stdout}"));
    assert!((printed - sigma).abs() < 1e-4 * sigma, "{stdout}");
}

/// Acceptance 2 of issue 49, its static half: on three plain bearings the
/// middle one set off the axis until it carries nothing — lowered, since
/// raising it loads it — by Newton on its elevation with the influence
/// matrix' diagonal. The other two then carry the line as a statically
/// determinate beam: their loads are the direct force balance of the
/// weight (shaft `ρ A L g` at mid-span, disks 30 and 45 kg at 0.3 and
/// 0.9 m, computed here by hand) about the two end journals, to 1e-8 of
/// the weight (the middle's residual load is below 1e-10 of it).
#[test]
fn the_middle_bearing_lowered_until_it_unloads_leaves_the_force_balance() {
    let options = SolverOptions::default();
    let speed = 3000.0 * std::f64::consts::PI / 30.0;
    let (m1, m2) = (30.0, 45.0);
    let shaft = 7810.0 * std::f64::consts::PI * 0.06 * 0.06 / 4.0 * 1.2 * 9.81;
    let parts = [(shaft, 0.6), (m1 * 9.81, 0.3), (m2 * 9.81, 0.9)];
    let weight: f64 = parts.iter().map(|(w, _)| w).sum();
    let moment: f64 = parts.iter().map(|(w, z)| w * z).sum();
    let right = moment / 1.2;
    let left = weight - right;
    let mut elevation = 0.0;
    let mut middle = f64::INFINITY;
    let mut found = None;
    for _ in 0..30 {
        let model = RotorModel::from_toml(&film_line_with(elevation, m2), "film3.toml").unwrap();
        let line = alignment(&Rotor::new(model).unwrap(), speed, &options).unwrap();
        middle = line.bearings[1].load;
        if middle.abs() < 1e-10 * weight {
            found = Some(line);
            break;
        }
        let slope = line.load_influence()[(1, 1)];
        // Newton, its step held to 20 µm (a quarter of the clearance).
        elevation -= (middle / slope).clamp(-2e-5, 2e-5);
    }
    let line = found.unwrap_or_else(|| panic!("middle load still {middle} N"));
    let loads = line.loads();
    println!(
        "middle lowered by {:.2} µm unloads it ({:.2e} N); ends carry {:.6} and {:.6} N, force balance {left:.6} and {right:.6} N",
        -elevation * 1e6,
        loads[1],
        loads[0],
        loads[2]
    );
    assert!(
        elevation < -8e-5,
        "lowered beyond the clearance: {elevation}"
    );
    assert!(
        (loads[0] - left).abs() < 1e-8 * weight,
        "{} vs {left}",
        loads[0]
    );
    assert!(
        (loads[2] - right).abs() < 1e-8 * weight,
        "{} vs {right}",
        loads[2]
    );
}

/// The continuation on the offsets (`solver::offset_continuation`): a stiff
/// line (150 mm shaft) on three four-pad tilting-pad bearings (R = 75 mm,
/// C = 150 µm, preload 0.2) at 3000 rpm, the middle raised by 2 mm (13
/// clearances): Newton from the straight shaft stalls, the continuation from
/// the aligned line finds the equilibrium. It is one: the bearing forces
/// (up to 1.2e5 N: the raised middle pulls the ends onto their top pads)
/// balance the weight and its moment computed here by hand to 1e-10 of the
/// largest (the statics solved to a relative residual of 1e-12 of their
/// force scale), and Newton started there stays (to 1e-12 m).
#[test]
fn continuation_on_the_offsets_finds_the_line_newton_misses() {
    use rotor_bearing::solver::{equilibrium, line_equilibrium};
    let options = SolverOptions {
        tolerance: 1e-12,
        ..SolverOptions::default()
    };
    let speed = 3000.0 * std::f64::consts::PI / 30.0;
    let text = film_line(2e-3)
        .replace("outer_diameter = 0.06", "outer_diameter = 0.15")
        .replace("radius = 0.03", "radius = 0.075")
        .replace("clearance = 80e-6", "clearance = 150e-6")
        .replace(
            "type = \"plain\"",
            "type = \"tilting_pad\"\npads = 4\nfirst_pivot_deg = 45.0\npad_arc_deg = 70.0\npreload = 0.2",
        );
    let line = Rotor::new(RotorModel::from_toml(&text, "pads.toml").unwrap()).unwrap();
    let direct = equilibrium(&line, speed, &options, None);
    assert!(
        direct.is_err(),
        "Newton now solves this line directly: give the continuation a harder case"
    );
    let found = line_equilibrium(&line, speed, &options, None).unwrap();
    let shaft = 7810.0 * std::f64::consts::PI * 0.15 * 0.15 / 4.0 * 1.2 * 9.81;
    let parts = [(shaft, 0.6), (30.0 * 9.81, 0.3), (30.0 * 9.81, 0.9)];
    let weight: f64 = parts.iter().map(|(w, _)| w).sum();
    let moment: f64 = parts.iter().map(|(w, z)| w * z).sum();
    let z = [0.0, 0.6, 1.2];
    let (mut fx, mut fy, mut m) = (0.0, 0.0, 0.0);
    for ((_, eval), z) in found.bearings.iter().zip(z) {
        fx += eval.force[0];
        fy += eval.force[1];
        m += eval.force[1] * z;
    }
    let loads: Vec<f64> = found.bearings.iter().map(|(_, e)| e.force[1]).collect();
    println!(
        "continued: loads {loads:?} N, weight {weight} N; ΣFx {fx:.2e}, ΣFy − W {:.2e}, ΣM − M {:.2e}",
        fy - weight,
        m - moment
    );
    let largest = loads.iter().fold(0.0_f64, |a, l| a.max(l.abs()));
    assert!(largest > 10.0 * weight);
    assert!(fx.abs() < 1e-10 * largest);
    assert!((fy - weight).abs() < 1e-10 * largest);
    assert!((m - moment).abs() < 1e-10 * largest);
    let again = equilibrium(&line, speed, &options, Some(&found)).unwrap();
    let moved = again
        .displacement
        .iter()
        .zip(&found.displacement)
        .fold(0.0_f64, |a, (p, q)| a.max((p - q).abs()));
    assert!(moved < 1e-12, "{moved:e}");
}
