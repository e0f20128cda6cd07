//! Bearings in series with pedestals (bearing supports): closed-form
//! two-degree-of-freedom frequencies, the rigid-support limit, the film on a
//! moving housing (relative kinematics, reaction, energy balance).

use rotor_bearing::analysis::linear::{node_xy, unbalance_response};
use rotor_bearing::analysis::modal::{ModalOptions, modes};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

const RPM: f64 = std::f64::consts::PI / 30.0;

/// A steel shaft of one element (0.2 m × 0.1 m) with two equal disks at its
/// ends, its end rotations held by supports, each end on a linear bearing
/// `k_b` standing on one shared pedestal: by symmetry the equal translation
/// of both ends (strain-free, the consistent mass summing to the shaft's
/// mass) is an exact mode shape together with the pedestal's translation.
fn rigid_rotor_on_frame(pedestal: &str) -> String {
    format!(
        r#"
name = "rigid_on_frame"
[[materials]]
name = "steel"
youngs_modulus = 211e9
poisson_ratio = 0.3
density = 7810.0
[[shaft]]
length = 0.2
outer_diameter = 0.1
material = "steel"
elements = 1
[[disks]]
node = 1
mass = 30.0
polar_inertia = 0.4
diametral_inertia = 0.25
[[disks]]
node = 2
mass = 30.0
polar_inertia = 0.4
diametral_inertia = 0.25
[[bearings]]
name = "left"
type = "linear"
node = 1
kxx = 1e7
kyy = 1e7
pedestal = "frame"
[[bearings]]
name = "right"
type = "linear"
node = 2
kxx = 1e7
kyy = 1e7
pedestal = "frame"
[[supports]]
node = 1
fix = ["rx", "ry"]
[[supports]]
node = 2
fix = ["rx", "ry"]
{pedestal}
"#
    )
}

/// The two natural frequencies (rad/s) of a mass `m` on a spring `k` to a
/// mass `m_p`, which stands on a spring `k_p` to ground: the roots of
/// `det([[k − ω² m, −k], [−k, k + k_p − ω² m_p]]) = 0`,
/// `m m_p ω⁴ − (k m_p + (k + k_p) m) ω² + k k_p = 0`.
fn two_dof(m: f64, k: f64, m_p: f64, k_p: f64) -> [f64; 2] {
    let a = m * m_p;
    let b = -(k * m_p + (k + k_p) * m);
    let c = k * k_p;
    let disc = (b * b - 4.0 * a * c).sqrt();
    // Stable forms of both roots.
    let big = (-b + disc) / (2.0 * a);
    let small = c / (a * big);
    [small.sqrt(), big.sqrt()]
}

/// A rigid rotor bouncing on its two bearings in series with a pedestal mass
/// and spring: its translational (bounce) frequencies in `x` and in `y` are
/// the closed-form two-degree-of-freedom values to 1e-9, with an anisotropic
/// pedestal (`kxx ≠ kyy`) separating the `x` and `y` pairs.
#[test]
fn bounce_frequencies_equal_the_two_degree_of_freedom_closed_form() {
    let (m_p, kxx_p, kyy_p) = (80.0, 3e7, 5e7);
    let text = rigid_rotor_on_frame(&format!(
        "[[pedestals]]\nname = \"frame\"\nmass = {m_p}\nkxx = {kxx_p}\nkyy = {kyy_p}\n"
    ));
    let model = RotorModel::from_toml(&text, "frame.toml").unwrap();
    let shaft_mass = 7810.0 * std::f64::consts::PI * 0.1f64.powi(2) / 4.0 * 0.2;
    let m = 60.0 + shaft_mass;
    let k = 2e7; // both bearings in parallel
    let rotor = Rotor::new(model).unwrap();
    assert_eq!(
        rotor.dof_count(),
        6,
        "two nodes × (x, y) + the pedestal's x, y"
    );
    let found = modes(
        &rotor,
        0.0,
        &ModalOptions {
            modes: 6,
            target_frequency: 0.0,
        },
    )
    .unwrap();
    let frequencies: Vec<f64> = found.iter().map(|m| m.natural_frequency).collect();
    for k_p in [kxx_p, kyy_p] {
        for want in two_dof(m, k, m_p, k_p) {
            let nearest = frequencies
                .iter()
                .map(|f| (f - want).abs() / want)
                .fold(f64::INFINITY, f64::min);
            assert!(
                nearest < 1e-9,
                "closed form {want} rad/s (k_p = {k_p}): nearest relative error {nearest:e} in {frequencies:?}"
            );
        }
    }
}

/// Pedestals of the Jeffcott rotor's two bearings, each of mass `mass` (kg)
/// and stiffness `k` (N/m) to ground.
fn jeffcott_on_pedestals(mass: f64, k: f64) -> RotorModel {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/jeffcott.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let text = text.replacen(
        "viscosity = 0.02            # Pa·s\n",
        "viscosity = 0.02            # Pa·s\npedestal = \"left\"\n",
        1,
    );
    let text = text.replacen(
        "clearance = 100e-6\nviscosity = 0.02\n",
        "clearance = 100e-6\nviscosity = 0.02\npedestal = \"right\"\n",
        1,
    );
    assert_eq!(text.matches("pedestal =").count(), 2);
    let mut text = text;
    for name in ["left", "right"] {
        text.push_str(&format!(
            "\n[[pedestals]]\nname = \"{name}\"\nmass = {mass}\nkxx = {k}\nkyy = {k}\ncxx = 100.0\ncyy = 100.0\n"
        ));
    }
    RotorModel::from_toml(&text, "jeffcott_on_pedestals.toml").unwrap()
}

fn jeffcott() -> RotorModel {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/jeffcott.toml");
    RotorModel::from_file(std::path::Path::new(path)).unwrap()
}

/// With 1e15 N/m pedestals the machine is the rigidly supported one: the
/// nonlinear plain-bearing transient (journal and disk orbits over 0.1 s at
/// 6000 rpm from the static equilibrium) agrees to 1e-6 of the orbit, and
/// the linearized modes at 6000 rpm to 1e-6.
#[test]
fn stiff_pedestals_reproduce_the_rigidly_supported_rotor() {
    let options = SolverOptions::default();
    let run = |model: RotorModel| {
        let speed = 6000.0 * RPM;
        let mut sim = Simulator::new(Rotor::new(model).unwrap(), options).unwrap();
        sim.set_speed(speed, 0.0).unwrap();
        sim.settle_static().unwrap();
        let mut orbit = Vec::new();
        for k in 1..=200 {
            sim.advance_to(k as f64 * 5e-4).unwrap();
            let out = sim.outputs().unwrap();
            orbit.push([
                out.bearings[0].x,
                out.bearings[0].y,
                out.probes[0].x,
                out.probes[0].y,
            ]);
        }
        orbit
    };
    let rigid = run(jeffcott());
    let stiff = run(jeffcott_on_pedestals(5.0, 1e15));
    let scale = rigid.iter().flatten().fold(0.0_f64, |a, v| a.max(v.abs()));
    let worst = rigid
        .iter()
        .flatten()
        .zip(stiff.iter().flatten())
        .fold(0.0_f64, |a, (r, s)| a.max((r - s).abs()));
    assert!(
        worst < 1e-6 * scale,
        "orbits differ by {worst:e} m of {scale:e} m"
    );

    let lin = |model: RotorModel| {
        let rotor = Rotor::new(model).unwrap();
        let linear =
            rotor_bearing::analysis::linearize::linearized(&rotor, 6000.0 * RPM, 6000.0 * RPM)
                .unwrap();
        let found = modes(
            &linear,
            6000.0 * RPM,
            &ModalOptions {
                modes: 6,
                target_frequency: 0.0,
            },
        )
        .unwrap();
        (
            found.iter().map(|m| m.eigenvalue).collect::<Vec<_>>(),
            unbalance_response(&linear, 6000.0 * RPM).unwrap(),
        )
    };
    let (rigid_modes, rigid_response) = lin(jeffcott());
    let (stiff_modes, stiff_response) = lin(jeffcott_on_pedestals(5.0, 1e15));
    for (r, s) in rigid_modes.iter().zip(&stiff_modes) {
        assert!((r - s).norm() < 1e-6 * r.norm(), "{r} against {s}");
    }
    for node in [0, 4] {
        let (rx, ry) = node_xy(&rigid_response, node);
        let (sx, sy) = node_xy(&stiff_response, node);
        let size = rx.norm().max(ry.norm());
        assert!(
            (rx - sx).norm().max((ry - sy).norm()) < 1e-6 * size,
            "node {node}: {rx} {ry} against {sx} {sy}"
        );
    }
}
