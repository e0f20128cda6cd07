//! Newmark/Newton–Raphson with nonlinear plain bearings against linear theory:
//! small-orbit forced response and the oil-whirl stability threshold.

use nalgebra::{Complex, Matrix2, Vector2};

use rotor_bearing::bearing::PlainBearing;
use rotor_bearing::bearing::equilibrium::journal_equilibrium;
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

const BEARING: PlainBearing = PlainBearing {
    radius: 0.05,
    length: 0.03,
    clearance: 1e-4,
    viscosity: 0.02,
    contact: None,
};

/// A rigid symmetric rotor of 203.87 kg (101.94 kg per bearing) on two plain
/// short bearings: a practically rigid, massless shaft with the mass in a central
/// disk whose diametral inertia keeps the conical mode well away.
fn rigid_rotor(unbalance: f64) -> Rotor {
    let mass = 2.0 * 101.936_799_184_505_6;
    let text = format!(
        r#"name = "rigid_rotor"
gravity = [0.0, -9.81, 0.0]
[[materials]]
name = "rigid"
youngs_modulus = 2e14
shear_modulus = 8e13
density = 1.0
[[shaft]]
length = 0.4
outer_diameter = 0.1
material = "rigid"
elements = 4
[[disks]]
node = 3
mass = {mass}
polar_inertia = 1.0
diametral_inertia = 1.0
[[bearings]]
type = "plain"
node = 1
radius = 0.05
length = 0.03
clearance = 1e-4
viscosity = 0.02
[[bearings]]
type = "plain"
node = 5
radius = 0.05
length = 0.03
clearance = 1e-4
viscosity = 0.02
[[unbalance]]
node = 3
magnitude = {unbalance}
[[probes]]
name = "disk"
node = 3
"#
    );
    Rotor::new(RotorModel::from_toml(&text, "rigid_rotor.toml").unwrap()).unwrap()
}

fn simulator(rotor: Rotor, speed: f64, step: f64) -> Simulator {
    let mut sim = Simulator::new(
        rotor,
        SolverOptions {
            time_step: step,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    sim.set_speed(speed, 0.0).unwrap();
    sim.settle_static().unwrap();
    sim
}

#[test]
fn static_equilibrium_matches_the_single_bearing_equilibrium() {
    let speed = 314.16;
    let mut sim = simulator(rigid_rotor(0.0), speed, 1e-4);
    // Half the weight per bearing (the near-massless shaft adds 0.003 kg).
    let load = sim.rotor().model.total_mass() * 9.81 / 2.0;
    let o = sim.outputs().unwrap();
    let eq = journal_equilibrium(&BEARING, Vector2::new(0.0, -load), speed, 1e-4).unwrap();
    for b in &o.bearings {
        assert!(
            (b.x - eq.q[0]).abs() < 1e-7 * 1e-4 && (b.y - eq.q[1]).abs() < 1e-7 * 1e-4,
            "{b:?}"
        );
        assert!((b.fy - load).abs() < 1e-6 * load, "{}", b.fy);
        assert!(b.fx.abs() < 1e-6 * load, "{}", b.fx);
    }
    assert!((o.bearings[0].report.eccentricity - 0.586_462_858).abs() < 1e-4);
}

/// Deviation of bearing 0 from equilibrium over time.
fn deviation_history(speed: f64, seconds: f64) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let mut sim = simulator(rigid_rotor(0.0), speed, 1e-4);
    let eq = sim.outputs().unwrap().bearings[0];
    // Kick: a small lateral velocity of the whole rotor.
    let mut st = sim.state().clone();
    for (i, v) in st.ud.iter_mut().enumerate() {
        if sim.rotor().dofs.full(i) % 4 == 0 {
            *v = 2e-4;
        }
    }
    sim.set_state(st).unwrap();
    sim.consistent_acceleration().unwrap();
    let (mut t, mut dx, mut dy) = (Vec::new(), Vec::new(), Vec::new());
    let dt = 2.5e-4;
    let mut k = 0;
    while sim.time() < seconds {
        k += 1;
        sim.advance_to(k as f64 * dt).unwrap();
        let o = sim.outputs().unwrap();
        t.push(o.time);
        dx.push(o.bearings[0].x - eq.x);
        dy.push(o.bearings[0].y - eq.y);
    }
    (t, dx, dy)
}

fn window_peak(t: &[f64], x: &[f64], y: &[f64], from: f64, to: f64) -> f64 {
    t.iter()
        .zip(x.iter().zip(y))
        .filter(|(ti, _)| **ti >= from && **ti < to)
        .map(|(_, (a, b))| a.hypot(*b))
        .fold(0.0, f64::max)
}

/// Linear theory (`stability.example_rotor` of the short-bearing reference): the
/// threshold is 797.1 rad/s. 3% below, a perturbation decays; 3% above it grows
/// into a whirl at about 0.52× the spin speed.
#[test]
fn onset_of_oil_whirl_matches_linear_stability_threshold() {
    let threshold = 797.115_851_293;
    let (t, x, y) = deviation_history(0.97 * threshold, 1.2);
    let (early, late) = (
        window_peak(&t, &x, &y, 0.05, 0.25),
        window_peak(&t, &x, &y, 1.0, 1.2),
    );
    eprintln!("3% below: peak deviation {early:.3e} → {late:.3e} m");
    assert!(
        late < 0.8 * early,
        "3% below threshold: {early:e} → {late:e} should decay"
    );

    let (t, x, y) = deviation_history(1.03 * threshold, 1.2);
    let (early, late) = (
        window_peak(&t, &x, &y, 0.05, 0.25),
        window_peak(&t, &x, &y, 1.0, 1.2),
    );
    eprintln!("3% above: peak deviation {early:.3e} → {late:.3e} m");
    assert!(
        late > 1.25 * early,
        "3% above threshold: {early:e} → {late:e} should grow"
    );
    // Whirl frequency from upward zero crossings of x over the last 0.4 s.
    let crossings: Vec<f64> = (1..t.len())
        .filter(|&i| t[i] > 0.8 && x[i - 1] < 0.0 && x[i] >= 0.0)
        .map(|i| t[i - 1] + (t[i] - t[i - 1]) * (-x[i - 1]) / (x[i] - x[i - 1]))
        .collect();
    let period = (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
    let ratio = 2.0 * std::f64::consts::PI / period / (1.03 * threshold);
    eprintln!("whirl frequency ratio {ratio:.4}");
    assert!(
        (ratio - 0.524).abs() < 0.02,
        "whirl frequency ratio {ratio}"
    );
}

/// Small unbalance below the threshold: the orbit about the equilibrium is the
/// linear forced response with the bearing coefficients at equilibrium (2%).
#[test]
fn small_orbit_matches_linearized_forced_response() {
    let speed = 314.16;
    let unbalance = 2e-5; // 2 N at 314 rad/s on a 2000 N rotor
    let mut sim = simulator(rigid_rotor(unbalance), speed, 1e-4);
    let eq = sim.outputs().unwrap().bearings[0];
    // Linearized rigid rotor, translational motion: per bearing half the mass and
    // half the unbalance force, (K − Ω² m + iΩ C) X = m e Ω² (1, −i) / 2.
    let e = journal_equilibrium(&BEARING, Vector2::new(0.0, -1000.0), speed, 1e-4).unwrap();
    let j = e.eval.journal();
    let m = 101.936_799_184_505_6;
    let z = j.stiffness.map(|v| Complex::new(v, 0.0))
        + j.damping.map(|v| Complex::new(0.0, speed * v))
        - Matrix2::<f64>::identity().map(|v| Complex::new(v * m * speed * speed, 0.0));
    let fu = unbalance * speed * speed / 2.0;
    let f = nalgebra::Vector2::new(Complex::new(fu, 0.0), Complex::new(0.0, -fu));
    let x = z.lu().solve(&f).unwrap();
    let (want_x, want_y) = (x[0].norm(), x[1].norm());
    // Let the start transient (ζ ≈ 0.3 of a ~300 rad/s mode) die out, then measure.
    sim.advance_to(0.5).unwrap();
    let period = 2.0 * std::f64::consts::PI / speed;
    let (mut max_x, mut min_x, mut max_y, mut min_y) = (f64::MIN, f64::MAX, f64::MIN, f64::MAX);
    let t0 = sim.time();
    let mut k = 0;
    while sim.time() < t0 + 5.0 * period {
        k += 1;
        sim.advance_to(t0 + k as f64 * period / 200.0).unwrap();
        let o = sim.outputs().unwrap().bearings[0];
        max_x = max_x.max(o.x - eq.x);
        min_x = min_x.min(o.x - eq.x);
        max_y = max_y.max(o.y - eq.y);
        min_y = min_y.min(o.y - eq.y);
    }
    let (got_x, got_y) = ((max_x - min_x) / 2.0, (max_y - min_y) / 2.0);
    eprintln!("orbit {got_x:.4e} × {got_y:.4e} m vs linear {want_x:.4e} × {want_y:.4e} m");
    assert!(
        (got_x / want_x - 1.0).abs() < 0.02,
        "x amplitude {got_x:e} vs linear {want_x:e}"
    );
    assert!(
        (got_y / want_y - 1.0).abs() < 0.02,
        "y amplitude {got_y:e} vs linear {want_y:e}"
    );
}
