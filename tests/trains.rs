//! Couplings between the shafts of a train (issue 49, acceptance 4 and 5):
//! a misaligned rigid flange transfers the shear and moment of the
//! closed-form clamped–clamped Timoshenko beam; a misaligned flexible
//! coupling between two cantilevers loads them by its stiffness times the
//! misalignment less their relative deflection, the closed form of springs
//! in series; an aligned coupling of (nearly) infinite stiffness has the
//! modes of one continuous shaft; bad coupling keys are refused naming
//! file, line, field and value; models whose couplings are torsional only
//! assemble the lateral matrices they assembled before, bit for bit.

use nalgebra::{Matrix2, Vector2};

use rotor_bearing::analysis::linear::static_deflection;
use rotor_bearing::analysis::linearize::linearized;
use rotor_bearing::analysis::modal::{ModalOptions, modes};
use rotor_bearing::analysis::shaft_loads::{coupling_loads, section_loads};
use rotor_bearing::analysis::torsion::torsional_modes;
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::rotor::torsion::TorsionalRotor;
use rotor_bearing::solver::{SimState, Simulator, SolverOptions};

const E: f64 = 211e9;
const NU: f64 = 0.3;
const RHO: f64 = 7810.0;
const RPM: f64 = std::f64::consts::PI / 30.0;

fn header() -> String {
    format!(
        "name = \"train\"\ngravity = [0.0, 0.0, 0.0]\n[[materials]]\nname = \"steel\"\n\
         youngs_modulus = {E:e}\npoisson_ratio = {NU}\ndensity = {RHO}\n"
    )
}

fn shaft(length: f64, diameter: f64, elements: usize) -> String {
    format!(
        "[[shaft]]\nlength = {length}\nouter_diameter = {diameter}\nmaterial = \"steel\"\nelements = {elements}\n"
    )
}

fn clamp(node: usize) -> String {
    format!("[[supports]]\nnode = {node}\nfix = [\"clamped\"]\n")
}

/// Bending stiffness `EI` and shear flexibility `1/(κ G A)` of a solid
/// circular section (κ = 6(1 + ν)/(7 + 6ν)).
fn section(diameter: f64) -> (f64, f64) {
    let pi = std::f64::consts::PI;
    let area = pi * diameter * diameter / 4.0;
    let ei = E * pi * diameter.powi(4) / 64.0;
    let kappa = 6.0 * (1.0 + NU) / (7.0 + 6.0 * NU);
    let g = E / (2.0 * (1.0 + NU));
    (ei, 1.0 / (kappa * g * area))
}

/// A uniform 2 m, 100 mm shaft in 20 elements clamped at both ends, bolted
/// at z = 0.7 m by a rigid flange set off by `(δx, δy)` and slopes
/// `(αx, αy)`. Without the flange's stiffness in the way the shaft after
/// it is the clamped–clamped beam whose right end is displaced by
/// `−(δ + α (l − z_f))` and turned by `−α` against its stress-free line:
/// the exact Timoshenko end forces `F₁ = EI/(l³(1+φ)) (−12 v₂ + 6 l ψ₂)`,
/// `M₁ = EI/(l³(1+φ)) (−6 l v₂ + (2 − φ) l² ψ₂)`, `φ = 12 EI/(κ G A l²)`;
/// shear `V = F₁` everywhere and moment `M(z) = −M₁ + F₁ z`.
#[test]
fn a_misaligned_rigid_flange_transfers_the_closed_form_shear_and_moment() {
    let (l, d, n, flange_node) = (2.0, 0.1, 20, 8);
    let z_f = l * (flange_node - 1) as f64 / n as f64;
    let (delta, alpha) = ([2e-4, -1.5e-4], [1e-3, 6e-4]);
    let text = format!(
        "{}{}{}{}[[couplings]]\nname = \"flange\"\nnode = {flange_node}\n\
         parallel_offset = [{:e}, {:e}]\nangular_offset = [{:e}, {:e}]\n",
        header(),
        shaft(l, d, n),
        clamp(1),
        clamp(n + 1),
        delta[0],
        delta[1],
        alpha[0],
        alpha[1]
    );
    let rotor = Rotor::new(RotorModel::from_toml(&text, "flange.toml").unwrap()).unwrap();
    let all = static_deflection(&rotor).unwrap();
    let loads = section_loads(&rotor, &all, false);
    assert_eq!(loads.len(), 2 * n);
    let (ei, shear_flex) = section(d);
    let phi = 12.0 * ei * shear_flex / (l * l);
    let c = ei / (l.powi(3) * (1.0 + phi));
    let mut worst: f64 = 0.0;
    for plane in 0..2 {
        let v2 = -(delta[plane] + alpha[plane] * (l - z_f));
        let psi2 = -alpha[plane];
        let f1 = c * (-12.0 * v2 + 6.0 * l * psi2);
        let m1 = c * (-6.0 * l * v2 + (2.0 - phi) * l * l * psi2);
        let m_max = m1.abs().max((-m1 + f1 * l).abs());
        for s in &loads {
            let moment = -m1 + f1 * s.z;
            let dm = (s.moment[plane] - moment).abs() / m_max;
            let dv = (s.shear[plane] - f1).abs() / f1.abs();
            worst = worst.max(dm).max(dv);
            assert!(
                dm < 1e-9 && dv < 1e-9,
                "plane {plane}, node {} of element {}: M {} against {moment}, V {} against {f1}",
                s.node + 1,
                s.element + 1,
                s.moment[plane],
                s.shear[plane]
            );
        }
        // The offset does load the line (the check can fail).
        assert!(m_max > 100.0, "plane {plane}: largest moment {m_max} N·m");
    }
    // What the flange transmits: the line's section loads at it.
    let flange = &coupling_loads(&rotor, &all, false)[0];
    for plane in 0..2 {
        let v2 = -(delta[plane] + alpha[plane] * (l - z_f));
        let psi2 = -alpha[plane];
        let f1 = c * (-12.0 * v2 + 6.0 * l * psi2);
        let m1 = c * (-6.0 * l * v2 + (2.0 - phi) * l * l * psi2);
        let moment = -m1 + f1 * z_f;
        assert!((flange.moment[plane] - moment).abs() < 1e-9 * moment.abs().max(m1.abs()));
        assert!((flange.shear[plane] - f1).abs() < 1e-9 * f1.abs());
    }
    eprintln!("flange: worst relative difference {worst:e}");
}

/// Two cantilevers (1.0 m × 80 mm and 1.2 m × 60 mm, clamped at their far
/// ends) whose tips a flexible coupling joins with a misalignment `m`. With
/// the tip flexibilities `C = [[L³/3EI + L/κGA, ±L²/2EI], [±L²/2EI, L/EI]]`
/// (the sign flips for the cantilever free at its left end) the coupling's
/// load on the first shaft solves `(I + k (C_l + C_r)) f = −k m`,
/// `k = diag(k_l, k_a)`: its stiffness times the misalignment, less the
/// relative deflection it causes (`k m` itself on rigid shafts). Checked on
/// the first shaft's end forces (section loads) and on the coupling's
/// `k (q_r − q_l − m)`, in both planes.
#[test]
fn a_misaligned_flexible_coupling_loads_its_shafts_by_stiffness_times_misalignment() {
    let (kl, ka) = (5e6, 2e4);
    let (delta, alpha) = ([2e-4, -1e-4], [1e-3, 5e-4]);
    let (la, da, na, lb, db, nb) = (1.0, 0.08, 10, 1.2, 0.06, 12);
    let left_tip = na + 1;
    let right_tip = na + 2;
    let last = na + nb + 2;
    let coupling = format!(
        "[[couplings]]\nname = \"flexible\"\nnode = {left_tip}\nlateral_stiffness = {kl:e}\n\
         angular_stiffness = {ka:e}\nparallel_offset = [{:e}, {:e}]\nangular_offset = [{:e}, {:e}]\n",
        delta[0], delta[1], alpha[0], alpha[1]
    );
    let base = format!(
        "{}{}{}{}{}{}",
        header(),
        shaft(la, da, na),
        shaft(0.05, da, 1),
        shaft(lb, db, nb),
        clamp(1),
        clamp(last)
    );
    let rotor =
        Rotor::new(RotorModel::from_toml(&(base + &coupling), "couple.toml").unwrap()).unwrap();
    let all = static_deflection(&rotor).unwrap();
    let loads = section_loads(&rotor, &all, false);
    // The coupling is no shaft: one element fewer carries section loads.
    assert_eq!(loads.len(), 2 * (na + nb));
    let tip = loads
        .iter()
        .find(|s| s.element == na - 1 && s.node == na)
        .unwrap();
    let flexibility = |l: f64, d: f64, sign: f64| {
        let (ei, sf) = section(d);
        let b = sign * l * l / (2.0 * ei);
        Matrix2::new(l.powi(3) / (3.0 * ei) + l * sf, b, b, l / ei)
    };
    let k = Matrix2::new(kl, 0.0, 0.0, ka);
    let a = Matrix2::identity() + k * (flexibility(la, da, 1.0) + flexibility(lb, db, -1.0));
    let mut worst: f64 = 0.0;
    for plane in 0..2 {
        let m = Vector2::new(delta[plane], alpha[plane]);
        let f = -a.try_inverse().unwrap() * (k * m);
        // Beam coordinates (w, ψ): (x, θy) and (y, −θx).
        let q = |node: usize| {
            let base = 4 * (node - 1);
            if plane == 0 {
                Vector2::new(all[base], all[base + 3])
            } else {
                Vector2::new(all[base + 1], -all[base + 2])
            }
        };
        let spring = k * (q(right_tip) - q(left_tip) - m);
        let library = &coupling_loads(&rotor, &all, false)[0];
        let transmitted = Vector2::new(-library.shear[plane], library.moment[plane]);
        let shaft_end = Vector2::new(-tip.shear[plane], tip.moment[plane]);
        for (what, got) in [
            ("section loads", shaft_end),
            ("coupling", spring),
            ("coupling_loads", transmitted),
        ] {
            for i in 0..2 {
                let d = (got[i] - f[i]).abs() / f[i].abs();
                worst = worst.max(d);
                assert!(
                    d < 1e-9,
                    "plane {plane}, {what} [{i}]: {} against {}",
                    got[i],
                    f[i]
                );
            }
        }
        // The shafts give way: the load is well below k m (the check can fail).
        assert!(f[0].abs() < 0.9 * kl * m[0].abs(), "plane {plane}: {f}");
    }
    eprintln!("flexible coupling: worst relative difference {worst:e}");
}

/// The stiff coupling's train and one continuous shaft: a 1.0 m × 60 mm
/// shaft (disk at node 3, bearings at nodes 1 and 4) and a 1.2 m × 50 mm
/// one (disk at its node 3, bearings at its nodes 2 and 5).
fn stiff_train(coupled: bool) -> Rotor {
    let coupling = "[[couplings]]\nname = \"stiff\"\nnode = 5\nlateral_stiffness = 1e15\nangular_stiffness = 1e15\n";
    let text = train_text(coupled.then_some(coupling));
    Rotor::new(RotorModel::from_toml(&text, "stiff.toml").unwrap()).unwrap()
}

/// The two-shaft train's model file, with `coupling` (an entry at node 5)
/// in a 0.1 m element between the shafts, or the shafts meeting at a node.
fn train_text(coupling: Option<&str>) -> String {
    let coupled = coupling.is_some();
    let mut text = header() + &shaft(1.0, 0.06, 4);
    let offset = if coupled {
        text += &shaft(0.1, 0.06, 1);
        1
    } else {
        0
    };
    text += &shaft(1.2, 0.05, 4);
    for (name, node, k) in [
        ("a1", 1, 2e7),
        ("a2", 4, 2e7),
        ("b1", 6 + offset, 1.5e7),
        ("b2", 9 + offset, 1.5e7),
    ] {
        text += &format!(
            "[[bearings]]\nname = \"{name}\"\ntype = \"linear\"\nnode = {node}\nkxx = {k:e}\nkyy = {:e}\ncxx = 1500.0\ncyy = 1500.0\n",
            1.3 * k
        );
    }
    for (name, node, od, bore) in [
        ("disk_a", 3, 0.25, 0.06),
        ("disk_b", 7 + offset, 0.22, 0.05),
    ] {
        text += &format!(
            "[[disks]]\nname = \"{name}\"\nnode = {node}\nmaterial = \"steel\"\nouter_diameter = {od}\ninner_diameter = {bore}\nwidth = 0.05\n"
        );
    }
    if let Some(c) = coupling {
        text += c;
    }
    text
}

#[test]
fn an_aligned_infinitely_stiff_coupling_has_the_modes_of_one_continuous_shaft() {
    let (train, continuous) = (stiff_train(true), stiff_train(false));
    assert_eq!(train.dof_count(), continuous.dof_count() + 4);
    let options = ModalOptions {
        modes: 8,
        target_frequency: 0.0,
    };
    let mut worst: f64 = 0.0;
    for rpm in [0.0, 3000.0, 6000.0] {
        let speed = rpm * RPM;
        let of = |r: &Rotor| modes(&linearized(r, speed, speed).unwrap(), speed, &options).unwrap();
        let (a, b) = (of(&train), of(&continuous));
        assert_eq!(a.len(), 8);
        for (x, y) in a.iter().zip(&b) {
            let d = (x.eigenvalue - y.eigenvalue).norm() / y.eigenvalue.norm();
            worst = worst.max(d);
            assert!(
                d < 1e-6,
                "{rpm} rpm: {} against the continuous shaft's {}",
                x.eigenvalue,
                y.eigenvalue
            );
        }
    }
    eprintln!("stiff coupling against the continuous shaft: worst {worst:e}");
}

/// Bad coupling keys name the file, line, field and value.
#[test]
fn bad_coupling_keys_name_file_line_and_field() {
    let base = header() + &shaft(1.0, 0.05, 4) + "[[couplings]]\nnode = 2\n";
    let cases: [(&str, &str); 9] = [
        (
            "lateral_stiffness = 1e6\n",
            "couplings[0].lateral_stiffness = 1000000: a flexible coupling needs angular_stiffness too",
        ),
        (
            "angular_stiffness = 1e4\n",
            "couplings[0].angular_stiffness = 10000: a flexible coupling needs lateral_stiffness too",
        ),
        (
            "lateral_stiffness = -1e6\nangular_stiffness = 1e4\n",
            "couplings[0].lateral_stiffness = -1000000: must be a finite number greater than zero",
        ),
        (
            "lateral_stiffness = 1e6\nangular_stiffness = 1e20\n",
            "couplings[0].angular_stiffness = 1e20: ",
        ),
        (
            "lateral_stiffness = 1e6\nangular_stiffness = 1e4\nangular_damping = -2.0\n",
            "couplings[0].angular_damping = -2: must be a finite number not less than zero",
        ),
        (
            "torsional_stiffness = 1e5\nlateral_damping = 10.0\n",
            "couplings[0].lateral_damping = 10: a rigid flange has no damping",
        ),
        (
            "parallel_offset = [0.0, 2.5]\n",
            "couplings[0].parallel_offset[1] = 2.5: ",
        ),
        (
            "angular_offset = [0.3, 0.0]\n",
            "couplings[0].angular_offset[0] = 0.3: ",
        ),
        (
            "torsional_damping = 5.0\n",
            "couplings[0].torsional_damping = 5: needs torsional_stiffness",
        ),
    ];
    let header_lines = base.lines().count();
    for (extra, want) in cases {
        let text = base.clone() + extra;
        let e = RotorModel::from_toml(&text, "m.toml")
            .unwrap_err()
            .to_string();
        assert!(e.contains(want), "{extra}\ngave: {e}\nwant: {want}");
        // The field's line: the last line of the entry that names it.
        let field = want.split(['[', '=', '.']).nth(2).unwrap().trim();
        let key = field.split(['[', ' ']).next().unwrap();
        let line = header_lines
            + 1
            + extra
                .lines()
                .position(|l| l.starts_with(key))
                .unwrap_or_else(|| panic!("{key} in {extra}"));
        assert!(
            e.starts_with(&format!("m.toml:{line}: ")),
            "{e} (line {line})"
        );
    }
    let e = RotorModel::from_toml(&base, "m.toml")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("couplings[0].torsional_stiffness = none: a coupling needs"),
        "{e}"
    );
}

/// A torsional-only coupling leaves the lateral rotor as it was, bit for
/// bit, and a misaligned rigid flange leaves the matrices (so the linear
/// dynamics) as they were and changes the statics only.
#[test]
fn couplings_without_the_lateral_keys_leave_the_lateral_rotor_bit_identical() {
    let base = header() + &shaft(1.0, 0.05, 4) + &clamp(1) + &clamp(5);
    let plain = Rotor::new(RotorModel::from_toml(&base, "a.toml").unwrap()).unwrap();
    let torsional = base.clone() + "[[couplings]]\nnode = 2\ntorsional_stiffness = 1e5\n";
    let flange = base.clone() + "[[couplings]]\nnode = 2\nparallel_offset = [1e-4, 0.0]\n";
    let plain_static = static_deflection(&plain).unwrap();
    for (text, same_statics) in [(torsional, true), (flange, false)] {
        let r = Rotor::new(RotorModel::from_toml(&text, "b.toml").unwrap()).unwrap();
        for (a, b) in [
            (&r.mass, &plain.mass),
            (&r.stiffness, &plain.stiffness),
            (&r.damping, &plain.damping),
            (&r.gyroscopic, &plain.gyroscopic),
        ] {
            assert_eq!(a.to_dense(), b.to_dense());
        }
        let s = static_deflection(&r).unwrap();
        assert_eq!(s == plain_static, same_statics);
    }
}

/// Two disks (2 and 5 kg·m²) joined by a flexible coupling with lateral,
/// angular and torsional stiffness (1e5 N·m/rad) in place of a 0.2 m
/// element: the coupling has no inertia of its own, so the one torsional
/// frequency is `√(k (J₁ + J₂)/(J₁ J₂))` exactly (to 1e-9).
#[test]
fn a_flexible_coupling_keeps_the_torsional_closed_form() {
    let text = header()
        + &shaft(0.2, 0.05, 1)
        + "[[disks]]\nnode = 1\nmass = 10.0\npolar_inertia = 2.0\ndiametral_inertia = 1.0\n\
           [[disks]]\nnode = 2\nmass = 10.0\npolar_inertia = 5.0\ndiametral_inertia = 2.5\n\
           [[couplings]]\nnode = 1\ntorsional_stiffness = 1e5\nlateral_stiffness = 1e7\nangular_stiffness = 1e5\n\
           [[bearings]]\ntype = \"linear\"\nnode = 1\nkxx = 1e6\nkyy = 1e6\n\
           [[bearings]]\ntype = \"linear\"\nnode = 2\nkxx = 1e6\nkyy = 1e6\n";
    let model = RotorModel::from_toml(&text, "two.toml").unwrap();
    let modes = torsional_modes(&model, 3).unwrap();
    assert_eq!(modes.len(), 1);
    let (j1, j2, k): (f64, f64, f64) = (2.0, 5.0, 1e5);
    let want = (k * (j1 + j2) / (j1 * j2)).sqrt();
    let got = modes[0].natural_frequency;
    assert!(
        (got / want - 1.0).abs() < 1e-9,
        "{got} against {want} rad/s"
    );
}

/// `xᵀ A y` for a banded matrix.
fn quadratic(a: &rotor_bearing::linalg::BandMatrix<f64>, x: &[f64], y: &[f64]) -> f64 {
    let mut ay = vec![0.0; y.len()];
    a.mul_vec(y, &mut ay);
    x.iter().zip(&ay).map(|(p, q)| p * q).sum()
}

/// The two-shaft train torque-driven (20 N·m at the first shaft's free end
/// against −5 N·m at the second's), its flexible coupling damped laterally,
/// angularly and torsionally, an unbalance on the first shaft's disk: over
/// 0.5 s from rest the work of the torques equals the change of the whole
/// train's energy (lateral, torsional, the unbalance's cross term) plus what
/// the bearings and the coupling dissipate, to 1e-6 of the work — the
/// coupling's spring–damper is in the same `M`, `K`, `C` the transient
/// steps, and the torsion runs through it.
#[test]
fn a_torque_driven_train_keeps_its_torsion() {
    let coupling = "[[couplings]]\nname = \"flexible\"\nnode = 5\nlateral_stiffness = 2e7\n\
                    angular_stiffness = 5e4\nlateral_damping = 300.0\nangular_damping = 20.0\n\
                    torsional_stiffness = 3e4\ntorsional_damping = 2.0\n\
                    [torsion]\ndrive = \"torque\"\n[[torques]]\nname = \"drive\"\nnode = 1\n\
                    [[torques]]\nname = \"load\"\nnode = 10\n\
                    [[unbalance]]\nnode = 3\nmagnitude = 1e-3\n";
    let model = RotorModel::from_toml(&train_text(Some(coupling)), "torque.toml").unwrap();
    let chain = TorsionalRotor::new(&model);
    let r = Rotor::new(model.clone()).unwrap();
    let (mass, stiffness, damping) = (r.mass.clone(), r.stiffness.clone(), r.damping.clone());
    let disk = [r.dofs.free(2, 0).unwrap(), r.dofs.free(2, 1).unwrap()];
    let (me, phase) = (model.unbalances[0].magnitude, model.unbalances[0].phase);
    let h = 1e-4;
    let mut sim = Simulator::new(
        r,
        SolverOptions {
            time_step: h,
            gravity: false,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    let first = model.first_torque_input();
    sim.set_load(first, 20.0, 0.0).unwrap();
    sim.set_load(first + 1, -5.0, 0.0).unwrap();
    let energy = |s: &SimState| {
        let phi = s.twist[2] + phase;
        let cross = -me * s.twist_rate[2] * (s.ud[disk[0]] * phi.sin() - s.ud[disk[1]] * phi.cos());
        0.5 * quadratic(&mass, &s.ud, &s.ud)
            + 0.5 * quadratic(&stiffness, &s.u, &s.u)
            + 0.5 * quadratic(&chain.mass, &s.twist_rate, &s.twist_rate)
            + 0.5 * quadratic(&chain.stiffness, &s.twist, &s.twist)
            + cross
    };
    let mut state = sim.state().clone();
    let e0 = energy(&state);
    let (mut work, mut dissipated) = (0.0, 0.0);
    for n in 1..=5000 {
        sim.advance_to(n as f64 * h).unwrap();
        let next = sim.state().clone();
        work += 20.0 * (next.twist[0] - state.twist[0]) - 5.0 * (next.twist[9] - state.twist[9]);
        let mid = |a: &[f64], b: &[f64]| -> Vec<f64> {
            a.iter().zip(b).map(|(p, q)| 0.5 * (p + q)).collect()
        };
        let v = mid(&state.ud, &next.ud);
        let w = mid(&state.twist_rate, &next.twist_rate);
        dissipated += h * (quadratic(&damping, &v, &v) + quadratic(&chain.damping, &w, &w));
        state = next;
    }
    let change = energy(&state) - e0;
    let speed = state.twist_rate[0];
    assert!(speed > 10.0, "the train spun up to {speed} rad/s");
    assert!(
        (work - change - dissipated).abs() < 1e-6 * work,
        "input work {work:e} J against energy change {change:e} J plus dissipation {dissipated:e} J"
    );
    eprintln!(
        "torque-driven train: work {work:e} J, balance {:e} of it, {speed:.1} rad/s",
        (work - change - dissipated).abs() / work
    );
}

/// The alignment tables of `rotor report` (issue 49): the two-shaft train
/// under its weight on linear bearings, its flexible coupling set off by
/// 0.1 mm: one row per bearing with its reaction, one per coupling with
/// what it transmits — the line's section loads at the shaft before it
/// (the shear and moment are continuous through the coupling, 1e-9).
#[test]
fn the_report_tables_the_alignment_and_the_coupling_loads() {
    use rotor_bearing::analysis::alignment::alignment;
    use rotor_bearing::report::html::Block;
    use rotor_bearing::report::review::alignment_blocks;
    use rotor_bearing::report::text::short;
    let coupling = "[[couplings]]\nname = \"flexible\"\nnode = 5\nlateral_stiffness = 2e7\n\
                    angular_stiffness = 5e4\nparallel_offset = [0.0, 1e-4]\n";
    let text = train_text(Some(coupling))
        .replace("gravity = [0.0, 0.0, 0.0]", "gravity = [0.0, -9.81, 0.0]");
    let rotor = Rotor::new(RotorModel::from_toml(&text, "train.toml").unwrap()).unwrap();
    let options = SolverOptions::default();
    let line = alignment(&rotor, 0.0, &options).unwrap();
    let all = rotor.dofs.expand(&line.equilibrium.displacement);
    let loads = coupling_loads(&rotor, &all, true);
    assert_eq!(loads.len(), 1);
    // Continuity: the shaft before the coupling ends with what it transmits.
    let sections = section_loads(&rotor, &all, true);
    let before = sections
        .iter()
        .find(|s| s.element == 3 && s.node == 4)
        .unwrap();
    for plane in 0..2 {
        let scale = loads[0].shear[1].abs();
        assert!((before.shear[plane] - loads[0].shear[plane]).abs() < 1e-9 * scale);
        assert!(
            (before.moment[plane] - loads[0].moment[plane]).abs()
                < 1e-9 * loads[0].moment[1].abs().max(1.0)
        );
    }
    assert!(loads[0].shear[1].abs() > 10.0, "{:?}", loads[0]);
    let blocks = alignment_blocks(&line, &loads);
    let tables: Vec<_> = blocks
        .iter()
        .filter_map(|b| match b {
            Block::Table(t) => Some(t),
            _ => None,
        })
        .collect();
    assert_eq!(tables.len(), 2);
    assert_eq!(tables[0].id, "alignment");
    assert_eq!(tables[0].rows.len(), 4);
    assert_eq!(tables[1].id, "coupling-loads");
    assert_eq!(tables[1].rows[0][3].text, short(loads[0].shear[1]));
    assert_eq!(tables[1].rows[0][5].text, short(loads[0].moment[1]));
}
