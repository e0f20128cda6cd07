//! Newmark integration of linear rotors against exact linear theory.

use nalgebra::{Complex, Matrix3, Vector3};

use rotor_bearing::analysis::linear::{node_xy, unbalance_response};
use rotor_bearing::analysis::modal::{ModalOptions, modes};
use rotor_bearing::model::{DEFAULT_MODEL_TOML, RotorModel};
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

const RPM: f64 = std::f64::consts::PI / 30.0;

/// Least-squares fit `a cos ωt + b sin ωt + c`: returns the complex amplitude
/// `X = a − i b` so that the signal is `Re(X e^{iωt}) + c`.
fn harmonic(ts: &[f64], xs: &[f64], omega: f64) -> Complex<f64> {
    let mut m = Matrix3::zeros();
    let mut r = Vector3::zeros();
    for (&t, &x) in ts.iter().zip(xs) {
        let v = Vector3::new((omega * t).cos(), (omega * t).sin(), 1.0);
        m += v * v.transpose();
        r += v * x;
    }
    let s = m.lu().solve(&r).unwrap();
    Complex::new(s[0], -s[1])
}

fn damped_classic(c: f64) -> Rotor {
    let text =
        DEFAULT_MODEL_TOML.replace("kyy = 1e6\n", &format!("kyy = 1e6\ncxx = {c}\ncyy = {c}\n"));
    Rotor::new(RotorModel::from_toml(&text, "classic_damped").unwrap()).unwrap()
}

/// Steady state of the linear rotor at constant speed equals the direct complex
/// solve of `(K − Ω²M + iΩ(C + ΩG)) X = Ω² F` (0.5% amplitude, 1° phase).
#[test]
fn steady_unbalance_response_matches_frequency_domain() {
    let rotor = damped_classic(2000.0);
    let speed = 3000.0 * RPM;
    let exact = unbalance_response(&rotor, speed).unwrap();
    // Slowest transient: the least-damped mode sets how long to wait.
    let ms = modes(
        &rotor,
        speed,
        &ModalOptions {
            modes: 4,
            target_frequency: 0.0,
        },
    )
    .unwrap();
    let decay = ms
        .iter()
        .map(|m| m.damping_ratio * m.natural_frequency)
        .fold(f64::INFINITY, f64::min);
    let settle = 12.0 / decay; // e^-12 of the start transient remains
    let mut sim = Simulator::new(
        rotor,
        SolverOptions {
            time_step: 2e-4,
            gravity: false,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    sim.set_speed(speed, 0.0).unwrap();
    let period = 2.0 * std::f64::consts::PI / speed;
    let (mut ts, mut xs, mut ys) = (Vec::new(), Vec::new(), Vec::new());
    sim.advance_to(settle).unwrap();
    let t_end = settle + 10.0 * period;
    while sim.time() < t_end - 1e-12 {
        let t = (sim.time() + period / 50.0).min(t_end);
        sim.advance_to(t).unwrap();
        let o = sim.outputs().unwrap();
        ts.push(o.time);
        xs.push(o.probes[0].x);
        ys.push(o.probes[0].y);
    }
    let (ex, ey) = node_xy(&exact, 3);
    for (got, want) in [
        (harmonic(&ts, &xs, speed), ex),
        (harmonic(&ts, &ys, speed), ey),
    ] {
        let amp = (got.norm() - want.norm()).abs() / want.norm();
        let phase = (got / want).arg().to_degrees().abs();
        eprintln!("steady orbit: amplitude error {amp:.2e}, phase error {phase:.3e}°");
        assert!(
            amp < 5e-3,
            "amplitude {} vs {} ({amp:e})",
            got.norm(),
            want.norm()
        );
        assert!(phase < 1.0, "phase error {phase}°");
    }
    assert!(sim.stats().factorizations <= 2, "{:?}", sim.stats());
}

/// Undamped, unforced rotor: average-acceleration Newmark conserves the energy
/// `½u̇ᵀMu̇ + ½uᵀKu` to round-off (also spinning: gyroscopic forces do no work),
/// and the period error of a mode falls at second order with the step
/// (theory: `ΔT/T ≈ (ωh)²/12`).
#[test]
fn energy_is_conserved_and_period_error_is_second_order() {
    for speed in [0.0, 2000.0 * RPM] {
        energy_and_period(speed);
    }
}

fn energy_and_period(speed: f64) {
    let model = RotorModel::default_model();
    let rotor = Rotor::new(model).unwrap();
    let ms = modes(
        &rotor,
        speed,
        &ModalOptions {
            modes: 2,
            target_frequency: 0.0,
        },
    )
    .unwrap();
    let omega = ms[0].damped_frequency;
    let shape: Vec<f64> = {
        // Real part of the first mode on the free DOFs (normalized to 1e-4 m).
        let full: Vec<f64> = ms[0].shape.iter().map(|c| c.re * 1e-4).collect();
        (0..rotor.dof_count())
            .map(|i| full[rotor.dofs.full(i)])
            .collect()
    };
    let energy = |sim: &Simulator| {
        let s = sim.state();
        let r = sim.rotor();
        let mut mv = vec![0.0; s.u.len()];
        r.mass.mul_vec(&s.ud, &mut mv);
        let kinetic: f64 = 0.5 * s.ud.iter().zip(&mv).map(|(a, b)| a * b).sum::<f64>();
        r.stiffness.mul_vec(&s.u, &mut mv);
        kinetic + 0.5 * s.u.iter().zip(&mv).map(|(a, b)| a * b).sum::<f64>()
    };
    let mut period_errors = Vec::new();
    for steps_per_period in [20.0, 40.0] {
        let h = 2.0 * std::f64::consts::PI / omega / steps_per_period;
        let mut sim = Simulator::new(
            Rotor::new(RotorModel::default_model()).unwrap(),
            SolverOptions {
                time_step: h,
                gravity: false,
                tolerance: 1e-12,
                ..SolverOptions::default()
            },
        )
        .unwrap();
        sim.set_unbalance(0, 0.0).unwrap();
        sim.set_speed(speed, 0.0).unwrap();
        let mut st = sim.state().clone();
        st.u = shape.clone();
        sim.set_state(st).unwrap();
        sim.consistent_acceleration().unwrap();
        let e0 = energy(&sim);
        let mut crossings = Vec::new();
        let dof = sim.rotor().dofs.free(3, 0).unwrap();
        let mut prev = (0.0, sim.state().u[dof]);
        let mut max_drift: f64 = 0.0;
        for k in 1..=(steps_per_period as usize * 8) {
            sim.advance_to(k as f64 * h).unwrap();
            let x = sim.state().u[dof];
            if prev.1 > 0.0 && x <= 0.0 {
                crossings.push(prev.0 + h * prev.1 / (prev.1 - x));
            }
            prev = (sim.time(), x);
            max_drift = max_drift.max((energy(&sim) - e0).abs() / e0);
        }
        eprintln!(
            "Ω = {speed:.1} rad/s, {steps_per_period} steps/period: energy drift {max_drift:.2e}"
        );
        assert!(max_drift < 1e-9, "energy drift {max_drift:e}");
        let measured =
            (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
        period_errors.push((measured * omega / (2.0 * std::f64::consts::PI) - 1.0).abs());
    }
    if speed == 0.0 {
        // A pure mode: the measured elongation follows (ωh)²/12 and second order.
        let theory = (2.0 * std::f64::consts::PI / 20.0).powi(2) / 12.0;
        assert!(
            (period_errors[0] / theory - 1.0).abs() < 0.1,
            "{period_errors:?} vs {theory}"
        );
        let order = (period_errors[0] / period_errors[1]).log2();
        eprintln!("period errors {period_errors:?} (theory {theory:.4e}), order {order:.3}");
        assert!(
            (1.9..2.1).contains(&order),
            "period errors {period_errors:?}, order {order}"
        );
    }
}

/// Run-up at constant angular acceleration α: the unbalance force of a plane is
/// `m e (Ω² cos φ + α sin φ, Ω² sin φ − α cos φ)` with `Ω = α t`, `φ = α t²/2`.
/// A rigid disk on isotropic springs (no damping) has the Duhamel solution
/// `x(t) = ∫ F(τ) sin(ω_n (t − τ)) dτ / (m ω_n)`, computed here by quadrature.
#[test]
fn run_up_unbalance_includes_the_angular_acceleration_term() {
    let (m, k, me, alpha) = (50.0, 2e6, 1e-3, 1e4);
    let text = format!(
        r#"name = "disk_on_springs"
[[materials]]
name = "rigid"
youngs_modulus = 2e15
shear_modulus = 8e14
density = 1e-6
[[shaft]]
length = 0.2
outer_diameter = 0.05
material = "rigid"
elements = 2
[[disks]]
node = 2
mass = {m}
polar_inertia = 0.5
diametral_inertia = 0.3
[[bearings]]
type = "linear"
node = 1
kxx = {k2}
kyy = {k2}
[[bearings]]
type = "linear"
node = 3
kxx = {k2}
kyy = {k2}
[[unbalance]]
node = 2
magnitude = {me}
"#,
        k2 = k / 2.0
    );
    let rotor = Rotor::new(RotorModel::from_toml(&text, "disk.toml").unwrap()).unwrap();
    let total_mass = rotor.model.total_mass();
    let mut sim = Simulator::new(
        rotor,
        SolverOptions {
            time_step: 5e-5,
            gravity: false,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    sim.set_speed(0.0, alpha).unwrap();
    let t_end = 0.03;
    sim.advance_to(t_end).unwrap();
    let o = sim.outputs().unwrap();
    assert!(
        (o.speed - alpha * t_end).abs() < 1e-9
            && (o.spin_angle - 0.5 * alpha * t_end * t_end).abs() < 1e-9
    );
    let wn = (k / total_mass).sqrt();
    let force = |tau: f64, with_alpha: bool| {
        let (w, phi) = (alpha * tau, 0.5 * alpha * tau * tau);
        let a = if with_alpha { alpha } else { 0.0 };
        (
            me * (w * w * phi.cos() + a * phi.sin()),
            me * (w * w * phi.sin() - a * phi.cos()),
        )
    };
    let duhamel = |with_alpha: bool| {
        let n = 200_000;
        let h = t_end / n as f64;
        let (mut x, mut y) = (0.0, 0.0);
        for i in 0..=n {
            let tau = i as f64 * h;
            let w = if i == 0 || i == n { 0.5 } else { 1.0 };
            let (fx, fy) = force(tau, with_alpha);
            let g = (wn * (t_end - tau)).sin() / (total_mass * wn);
            x += w * h * fx * g;
            y += w * h * fy * g;
        }
        (x, y)
    };
    let (ex, ey) = duhamel(true);
    let (nx, ny) = duhamel(false);
    let dof_x = sim.rotor().dofs.free(1, 0).unwrap();
    let dof_y = sim.rotor().dofs.free(1, 1).unwrap();
    let (sx, sy) = (sim.state().u[dof_x], sim.state().u[dof_y]);
    let scale = ex.hypot(ey);
    // Newmark's phase error (ωh)²/12 ≈ 2e-5 per cycle at the final speed, a few
    // cycles: 2e-3 leaves room without hiding a wrong force term (next assertion).
    assert!(
        (sx - ex).abs() < 2e-3 * scale && (sy - ey).abs() < 2e-3 * scale,
        "({sx:e}, {sy:e}) vs ({ex:e}, {ey:e})"
    );
    // Without the α term the answer would differ clearly: the test can tell.
    assert!((sx - nx).hypot(sy - ny) > 0.05 * scale);
}

/// Rollback: restoring a saved state and stepping again reproduces the outputs
/// bit for bit (also with nonlinear bearings and pad tilts).
#[test]
fn saved_state_rolls_back_bit_identically() {
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/hydro_unit.toml");
    let rotor = Rotor::new(RotorModel::from_file(&path).unwrap()).unwrap();
    let mut sim = Simulator::new(
        rotor,
        SolverOptions {
            time_step: 5e-3,
            unbalance_ramp_time: 1.0,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    sim.set_speed(150.0 * RPM, 0.0).unwrap();
    sim.settle_static().unwrap();
    sim.advance_to(1.0).unwrap();
    let saved = sim.state().clone();
    sim.advance_to(1.5).unwrap();
    let first = sim.outputs().unwrap();
    sim.set_state(saved).unwrap();
    sim.advance_to(1.5).unwrap();
    let again = sim.outputs().unwrap();
    assert_eq!(first, again);
    assert!(!sim.state().p.is_empty(), "pad tilts are part of the state");
}
