//! Finite-element core against independent truth: analytic beam frequencies
//! (Euler–Bernoulli and the exact Timoshenko frequency equation) and published
//! natural frequencies of the classic disk-on-shaft rotor.

use rotor_bearing::analysis::campbell::{campbell, critical_speeds};
use rotor_bearing::analysis::linear::{node_xy, static_deflection, unbalance_response};
use rotor_bearing::analysis::modal::{ModalOptions, Mode, Whirl, modes};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;

const RPM: f64 = std::f64::consts::PI / 30.0;

fn rotor_from(text: &str) -> Rotor {
    Rotor::new(RotorModel::from_toml(text, "test.toml").unwrap()).unwrap()
}

fn uniform_shaft(length: f64, diameter: f64, elements: usize, ends: &str, flags: &str) -> Rotor {
    let supports = if ends.is_empty() {
        String::new()
    } else {
        format!(
            "[[supports]]\nnode = 1\nfix = [\"{ends}\"]\n[[supports]]\nnode = {}\nfix = [\"{ends}\"]\n",
            elements + 1
        )
    };
    rotor_from(&format!(
        r#"name = "beam"
{flags}
[[materials]]
name = "steel"
youngs_modulus = 211e9
shear_modulus = 81.2e9
density = 7810.0
[[shaft]]
length = {length}
outer_diameter = {diameter}
material = "steel"
elements = {elements}
{supports}"#
    ))
}

/// Distinct frequencies (rad/s) of planar pairs at zero speed, rigid-body modes dropped.
fn bending_frequencies(modes: &[Mode], floor: f64) -> Vec<f64> {
    let mut f: Vec<f64> = modes
        .iter()
        .map(|m| m.damped_frequency)
        .filter(|&w| w > floor)
        .collect();
    f.sort_by(f64::total_cmp);
    // x–z and y–z planes give equal pairs at zero speed.
    let mut distinct: Vec<f64> = Vec::new();
    for w in f {
        match distinct.last() {
            Some(&last) if (w - last).abs() < 1e-6 * w => {}
            _ => distinct.push(w),
        }
    }
    distinct
}

fn euler_bernoulli_scale(length: f64, diameter: f64) -> f64 {
    let (e, rho) = (211e9, 7810.0);
    let r = diameter / 2.0;
    // √(EI/(ρA)) / L² with I/A = r²/4.
    (e * r * r / 4.0 / rho).sqrt() / (length * length)
}

#[test]
fn pinned_pinned_slender_shaft_converges_to_euler_bernoulli() {
    // L/d = 100; Euler–Bernoulli element flags isolate the discretization error.
    let (l, d) = (1.0, 0.01);
    let rotor = uniform_shaft(
        l,
        d,
        20,
        "pinned",
        "shear_deformation = false\nrotary_inertia = false",
    );
    let ms = modes(
        &rotor,
        0.0,
        &ModalOptions {
            modes: 8,
            target_frequency: 0.0,
        },
    )
    .unwrap();
    let f = bending_frequencies(&ms, 0.0);
    let scale = euler_bernoulli_scale(l, d);
    for n in 1..=4 {
        let exact = (n as f64 * std::f64::consts::PI).powi(2) * scale;
        let err = (f[n - 1] - exact).abs() / exact;
        assert!(
            err < 1e-3,
            "mode {n}: FE {} vs EB {exact}: {err:e}",
            f[n - 1]
        );
    }
}

#[test]
fn free_free_slender_shaft_converges_to_euler_bernoulli() {
    let (l, d) = (1.0, 0.01);
    let rotor = uniform_shaft(
        l,
        d,
        20,
        "",
        "shear_deformation = false\nrotary_inertia = false",
    );
    let ms = modes(
        &rotor,
        0.0,
        &ModalOptions {
            modes: 12,
            target_frequency: 0.0,
        },
    )
    .unwrap();
    let scale = euler_bernoulli_scale(l, d);
    // Rigid-body modes (λ = 0) are dropped with a floor far below the first bending mode.
    let f = bending_frequencies(&ms, 0.1 * 22.37 * scale);
    let beta_l: [f64; 4] = [4.730_040_7, 7.853_204_6, 10.995_607_8, 14.137_165_5];
    for (n, bl) in beta_l.iter().enumerate() {
        let exact = bl * bl * scale;
        let err = (f[n] - exact).abs() / exact;
        assert!(
            err < 1e-3,
            "mode {}: FE {} vs EB {exact}: {err:e}",
            n + 1,
            f[n]
        );
    }
}

/// Lower root of the exact Timoshenko frequency equation of a simply supported
/// beam, mode `n`: `(ρAω² − κGAk²)(ρIω² − EIk² − κGA) = (κGAk)²`, `k = nπ/L`.
fn timoshenko_pinned(n: usize, length: f64, diameter: f64) -> f64 {
    let (e, g, rho) = (211e9, 81.2e9, 7810.0);
    let nu = e / (2.0 * g) - 1.0;
    let kappa = 6.0 * (1.0 + nu) / (7.0 + 6.0 * nu);
    let a = std::f64::consts::PI * diameter * diameter / 4.0;
    let i = std::f64::consts::PI * diameter.powi(4) / 64.0;
    let k = n as f64 * std::f64::consts::PI / length;
    let kga = kappa * g * a;
    // α (ω²)² + β ω² + γ = 0
    let alpha = rho * a * rho * i;
    let beta = -(rho * a * (e * i * k * k + kga) + rho * i * kga * k * k);
    let gamma = kga * k * k * (e * i * k * k + kga) - (kga * k).powi(2);
    let disc = (beta * beta - 4.0 * alpha * gamma).sqrt();
    ((-beta - disc) / (2.0 * alpha)).sqrt()
}

#[test]
fn stubby_shaft_matches_timoshenko_frequency_equation() {
    // L/d = 5: shear and rotary inertia lower the frequencies markedly. The FE
    // frequencies converge to the exact Timoshenko values at second order in the
    // element length (the shear parameter φ grows as elements shrink), so the check
    // is convergence: 80 elements within 0.1%, and the error falls ≈4× per halving.
    let (l, d) = (0.5, 0.1);
    let errors = |elements: usize| -> Vec<f64> {
        let rotor = uniform_shaft(l, d, elements, "pinned", "");
        let ms = modes(
            &rotor,
            0.0,
            &ModalOptions {
                modes: 8,
                target_frequency: 0.0,
            },
        )
        .unwrap();
        let f = bending_frequencies(&ms, 0.0);
        (1..=4)
            .map(|n| {
                let exact = timoshenko_pinned(n, l, d);
                let eb = (n as f64 * std::f64::consts::PI).powi(2) * euler_bernoulli_scale(l, d);
                // The shear reduction is real: at least 3% below Euler–Bernoulli.
                assert!(
                    f[n - 1] < 0.97 * eb,
                    "mode {n}: {} not below EB {eb}",
                    f[n - 1]
                );
                (f[n - 1] - exact) / exact
            })
            .collect()
    };
    let (e40, e80) = (errors(40), errors(80));
    for n in 0..4 {
        assert!(
            e80[n].abs() < 1e-3,
            "mode {}: error {:e} with 80 elements",
            n + 1,
            e80[n]
        );
        let order = (e40[n] / e80[n]).log2();
        assert!(
            (1.8..2.3).contains(&order),
            "mode {}: convergence order {order}",
            n + 1
        );
    }
}

fn classic() -> Rotor {
    Rotor::new(RotorModel::default_model()).unwrap()
}

/// Published values (ROSS rotordynamics package, Cowper shear, rotary inertia and
/// gyroscopic terms), quoted in the FE-core issue.
#[test]
fn classic_rotor_damped_natural_frequencies() {
    let rotor = classic();
    let opts = ModalOptions {
        modes: 8,
        target_frequency: 0.0,
    };
    let cases: [(f64, &[f64]); 2] = [
        (0.0, &[116.38, 116.38, 464.27, 464.27]),
        (
            4000.0,
            &[
                116.35, 116.41, 437.36, 488.72, 741.59, 742.81, 1395.1, 1682.1,
            ],
        ),
    ];
    for (rpm, expect) in cases {
        let ms = modes(&rotor, rpm * RPM, &opts).unwrap();
        for (k, &e) in expect.iter().enumerate() {
            let got = ms[k].damped_frequency;
            // The references carry 5 significant digits (rounding ≤ 4.3e-5 relative);
            // the issue asks for 0.5%, the element reproduces them to 1e-4.
            assert!(
                (got - e).abs() < 1e-4 * e,
                "{rpm} rpm mode {}: {got} vs {e}",
                k + 1
            );
            assert!(ms[k].residual < 1e-8, "residual {}", ms[k].residual);
            assert!(
                ms[k].damping_ratio.abs() < 1e-8,
                "undamped rotor has ζ = {}",
                ms[k].damping_ratio
            );
        }
    }
}

#[test]
fn classic_rotor_whirl_directions_at_speed() {
    // Each pair splits into a backward (lower) and a forward (higher) whirl.
    let ms = modes(&classic(), 4000.0 * RPM, &ModalOptions::default()).unwrap();
    for pair in ms.chunks(2) {
        assert_eq!(
            pair[0].whirl,
            Whirl::Backward,
            "{:?}",
            pair[0].damped_frequency
        );
        assert_eq!(
            pair[1].whirl,
            Whirl::Forward,
            "{:?}",
            pair[1].damped_frequency
        );
    }
}

#[test]
fn campbell_backward_falls_forward_rises() {
    let rotor = classic();
    let opts = ModalOptions {
        modes: 4,
        target_frequency: 0.0,
    };
    let speeds: Vec<f64> = (0..=8).map(|k| k as f64 * 500.0 * RPM).collect();
    let diagram = campbell(&rotor, &speeds, &opts).unwrap();
    for pair in diagram.windows(2).skip(1) {
        let (a, b) = (&pair[0].modes, &pair[1].modes);
        assert!(
            b[2].damped_frequency < a[2].damped_frequency,
            "backward branch must fall"
        );
        assert!(
            b[3].damped_frequency > a[3].damped_frequency,
            "forward branch must rise"
        );
        assert_eq!(b[2].whirl, Whirl::Backward);
        assert_eq!(b[3].whirl, Whirl::Forward);
    }
    // The first pair crosses the 1× line near 116.4 rad/s (1111 rpm).
    let crit = critical_speeds(&rotor, &diagram, 1.0, &opts).unwrap();
    assert!(crit.len() >= 2, "{crit:?}");
    for c in &crit[..2] {
        assert!((c.speed - 116.4).abs() < 0.1, "{c:?}");
        let at = modes(&rotor, c.speed, &opts).unwrap();
        assert!((at[c.rank].damped_frequency - c.speed).abs() < 1e-6 * c.speed);
    }
}

#[test]
fn static_deflection_matches_hand_calculation() {
    // Rigid-bearing-dominated check: the bearings' share is W/(2k) per bearing.
    let rotor = classic();
    let q = static_deflection(&rotor).unwrap();
    let weight = rotor.model.total_mass() * 9.81;
    let (_, y_bearing) = node_xy(&q, 0);
    assert!((y_bearing + weight / 2.0 / 1e6).abs() < 1e-9, "{y_bearing}");
    // Disk node: bearing sag plus shaft bending of a simply supported beam under a
    // central load P = disk weight (PL³/48EI) and its own weight (5wL⁴/384EI).
    let ei = 211e9 * std::f64::consts::PI * 0.05f64.powi(4) / 64.0;
    let l: f64 = 1.5;
    let w_shaft = 7810.0 * std::f64::consts::PI * 0.025f64.powi(2) * 9.81;
    let p_disk = 32.5897 * 9.81;
    let bending = p_disk * l.powi(3) / (48.0 * ei) + 5.0 * w_shaft * l.powi(4) / (384.0 * ei);
    let (_, y_mid) = node_xy(&q, 3);
    let expect = -(weight / 2.0 / 1e6 + bending);
    // Shear deformation adds P L/(4κGA) ≈ 0.1% to the bending: allow 0.5%.
    assert!(
        (y_mid - expect).abs() < 5e-3 * expect.abs(),
        "{y_mid} vs {expect}"
    );
}

#[test]
fn unbalance_response_peaks_at_the_critical_speed() {
    // Lightly damped bearings: amplitude at the 1st critical dwarfs the off-resonance ones.
    let text = rotor_bearing::model::DEFAULT_MODEL_TOML
        .replace("kyy = 1e6\n", "kyy = 1e6\ncxx = 50.0\ncyy = 50.0\n");
    let rotor = rotor_from(&text);
    let amp = |rpm: f64| {
        let x = unbalance_response(&rotor, rpm * RPM).unwrap();
        let (xd, yd) = node_xy(&x, 3);
        // Isotropic rotor: circular forward orbit, |x| = |y|.
        assert!((xd.norm() - yd.norm()).abs() < 1e-6 * xd.norm());
        xd.norm()
    };
    let peak = amp(116.38 / RPM);
    assert!(
        peak > 20.0 * amp(600.0) && peak > 20.0 * amp(2000.0),
        "{peak}"
    );
}

/// Axial load (paper eq. 1, last term): a pinned-pinned Euler–Bernoulli beam under
/// tension P has `ω_n² = (EI k⁴ + P k²)/(ρA)`, `k = nπ/L`; compression lowers the
/// frequencies and the first vanishes at the Euler load `π² EI / L²`.
#[test]
fn axial_load_stiffens_in_tension_and_softens_in_compression() {
    let (l, d, e, rho): (f64, f64, f64, f64) = (1.0, 0.01, 211e9, 7810.0);
    let i = std::f64::consts::PI * d.powi(4) / 64.0;
    let a = std::f64::consts::PI * d * d / 4.0;
    let euler = std::f64::consts::PI.powi(2) * e * i / l / l;
    for p in [2.0 * euler, -0.5 * euler] {
        let rotor = uniform_shaft(
            l,
            d,
            20,
            "pinned",
            &format!("shear_deformation = false\nrotary_inertia = false\naxial_force = {p}"),
        );
        let ms = modes(
            &rotor,
            0.0,
            &ModalOptions {
                modes: 8,
                target_frequency: 0.0,
            },
        )
        .unwrap();
        let f = bending_frequencies(&ms, 0.0);
        for n in 1..=4 {
            let k = n as f64 * std::f64::consts::PI / l;
            let exact = ((e * i * k.powi(4) + p * k * k) / (rho * a)).sqrt();
            let err = (f[n - 1] - exact).abs() / exact;
            assert!(
                err < 1e-3,
                "P = {p}: mode {n}: FE {} vs {exact}: {err:e}",
                f[n - 1]
            );
        }
    }
}

/// A long rotor train: 4000 elements (16,000 DOF) on linear bearings at every
/// 400th node. The lowest modes come out by shift-invert Arnoldi on banded
/// storage and agree with a coarser mesh of the same spans (50 elements per span:
/// its discretization error, second order in the element length, is ≈3e-6).
#[test]
fn long_rotor_train_modes_are_found_with_banded_shift_invert() {
    let train = |elements_per_span: usize| {
        let spans = 10;
        let mut text = String::from(
            "name = \"train\"\n[[materials]]\nname = \"steel\"\nyoungs_modulus = 211e9\nshear_modulus = 81.2e9\ndensity = 7810.0\n",
        );
        for _ in 0..spans {
            text += &format!(
                "[[shaft]]\nlength = 2.0\nouter_diameter = 0.2\nmaterial = \"steel\"\nelements = {elements_per_span}\n"
            );
        }
        for s in 0..=spans {
            text += &format!(
                "[[bearings]]\ntype = \"linear\"\nnode = {}\nkxx = 1e9\nkyy = 1.5e9\ncxx = 1e4\ncyy = 1e4\n",
                s * elements_per_span + 1
            );
        }
        rotor_from(&text)
    };
    let fine = train(400);
    assert_eq!(fine.dof_count(), 4 * 4001);
    let opts = ModalOptions {
        modes: 6,
        target_frequency: 0.0,
    };
    let speed = 3000.0 * RPM;
    let fine_modes = modes(&fine, speed, &opts).unwrap();
    let coarse_modes = modes(&train(50), speed, &opts).unwrap();
    for m in &fine_modes {
        eprintln!("{} {:e}", m.damped_frequency, m.residual);
    }
    for (f, c) in fine_modes.iter().zip(&coarse_modes) {
        // Backward error of the real-arithmetic Arnoldi vectors on this
        // 16 004-DOF train: up to 1.2e-8 (the complex process gave 3e-9; the
        // frequencies of both agree to 5e-14, tests/modal_reference.rs).
        assert!(f.residual < 2e-8, "residual {}", f.residual);
        let rel = (f.damped_frequency - c.damped_frequency).abs() / f.damped_frequency;
        assert!(
            rel < 1e-5,
            "{} vs {}",
            f.damped_frequency,
            c.damped_frequency
        );
    }
}
