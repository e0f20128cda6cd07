//! Newmark integration of linear rotors against exact linear theory.

use nalgebra::{Complex, Matrix3, Vector3};

use rotor_bearing::analysis::linear::{node_xy, unbalance_response};
use rotor_bearing::analysis::modal::{ModalOptions, modes};
use rotor_bearing::fe::assembly::Rotor;
use rotor_bearing::model::{DEFAULT_MODEL_TOML, RotorModel};
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
        r.mass.mul_vec(&s.ud, &mut mv).unwrap();
        let kinetic: f64 = 0.5 * s.ud.iter().zip(&mv).map(|(a, b)| a * b).sum::<f64>();
        r.stiffness.mul_vec(&s.u, &mut mv).unwrap();
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
        assert!(
            (1.9..2.1).contains(&order),
            "period errors {period_errors:?}, order {order}"
        );
    }
}
