//! Reverse rotation (a pump-turbine in pumping mode) is physical: under the
//! mirror `x → −x` a journal bearing spun at `−ω` is the bearing spun at `ω`, so
//! forces, Jacobians and static equilibria must mirror the forward case.

use nalgebra::Vector2;

use rotor_bearing::bearing::tilting_pad::{Pad, TiltingPadBearing};
use rotor_bearing::bearing::{Bearing, BearingEval, PlainBearing};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

/// The mirror `M = diag(−1, 1, −1, …)` on journal coordinates and the pad
/// tilts of a mirror-symmetric pad set (pad `k` ↔ pad `partner[k]`, tilt sign
/// flipped because the counter-clockwise rotation becomes clockwise).
fn mirror_q(q: &[f64], partner: &[usize]) -> Vec<f64> {
    let mut out = vec![-q[0], q[1]];
    out.extend(partner.iter().map(|&p| -q[2 + p]));
    out
}

fn check_mirror(bearing: &dyn Bearing, partner: &[usize], states: &[(Vec<f64>, Vec<f64>, f64)]) {
    let n = 2 + partner.len();
    for (q, qd, speed) in states {
        let mut fwd = BearingEval::new(n);
        let mut rev = BearingEval::new(n);
        bearing.evaluate(q, qd, *speed, &mut fwd).unwrap();
        bearing
            .evaluate(
                &mirror_q(q, partner),
                &mirror_q(qd, partner),
                -speed,
                &mut rev,
            )
            .unwrap();
        let mirrored_force = mirror_q(&fwd.force, partner);
        let scale = fwd.force.iter().fold(1e-9_f64, |m, f| m.max(f.abs()));
        for (i, (r, m)) in rev.force.iter().zip(&mirrored_force).enumerate() {
            assert!(
                (r - m).abs() <= 1e-10 * scale,
                "force {i}: reverse {r:.6e}, mirrored forward {m:.6e} at q = {q:?}"
            );
        }
        // Jacobians: K_rev = M K M with M the mirror (and pad permutation).
        let sign = |i: usize| if i == 0 || i >= 2 { -1.0 } else { 1.0 };
        let map = |i: usize| if i < 2 { i } else { 2 + partner[i - 2] };
        let kscale = fwd.stiffness.iter().fold(1e-9_f64, |m, k| m.max(k.abs()));
        let cscale = fwd.damping.iter().fold(1e-9_f64, |m, c| m.max(c.abs()));
        for i in 0..n {
            for j in 0..n {
                let k = sign(i) * sign(j) * fwd.k(map(i), map(j));
                let c = sign(i) * sign(j) * fwd.c(map(i), map(j));
                assert!((rev.k(i, j) - k).abs() <= 1e-9 * kscale, "K[{i}{j}]");
                assert!((rev.c(i, j) - c).abs() <= 1e-9 * cscale, "C[{i}{j}]");
            }
        }
    }
}

#[test]
fn plain_bearing_forces_mirror_under_reverse_spin() {
    let b = PlainBearing {
        radius: 0.05,
        length: 0.03,
        clearance: 1e-4,
        viscosity: 0.02,
        contact: None,
    };
    let states = [
        (vec![2e-5, -5e-5], vec![0.0, 0.0], 314.16),
        (vec![-3e-5, 1e-5], vec![1e-3, -2e-3], 100.0),
        (vec![6e-5, 4e-5], vec![-5e-3, 1e-3], 500.0),
        (vec![1e-6, -8e-5], vec![0.0, 4e-3], 50.0),
    ];
    check_mirror(&b, &[], &states);
}

#[test]
fn symmetric_tilting_pads_mirror_under_reverse_spin() {
    // Pivots at 45°, 135°, 225°, 315°, centred: the mirror x → −x maps the pad
    // at θ to the pad at π − θ and leading edges to trailing edges.
    let pivots = [45.0_f64, 135.0, 225.0, 315.0];
    let partner = [1, 0, 3, 2];
    let b = TiltingPadBearing {
        radius: 0.05,
        length: 0.03,
        clearance: 1e-4,
        viscosity: 0.02,
        pads: pivots
            .iter()
            .map(|p| Pad::new(p.to_radians(), 80f64.to_radians(), 0.5, 0.2))
            .collect(),
        contact: None,
        support: Default::default(),
    };
    let states = [
        (
            vec![1e-5, -4e-5, 3e-6, -2e-6, 1e-6, 4e-6],
            vec![0.0; 6],
            314.16,
        ),
        (
            vec![-2e-5, -3e-5, -1e-6, 2e-6, 5e-6, -3e-6],
            vec![1e-3, -1e-3, 2e-4, 0.0, -1e-4, 3e-4],
            200.0,
        ),
    ];
    check_mirror(&b, &partner, &states);
}

#[test]
fn rotor_static_equilibrium_mirrors_under_reverse_spin() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("models/jeffcott.toml");
    let settle = |speed: f64| -> (Vec<f64>, Vec<Vector2<f64>>) {
        let rotor = Rotor::new(RotorModel::from_file(&path).unwrap()).unwrap();
        let mut sim = Simulator::new(rotor, SolverOptions::default()).unwrap();
        sim.set_speed(speed, 0.0).unwrap();
        sim.settle_static().unwrap();
        let u = sim.rotor().dofs.expand(&sim.state().u);
        let out = sim.outputs().unwrap();
        let forces = out
            .bearings
            .iter()
            .map(|b| Vector2::new(b.fx, b.fy))
            .collect();
        (u, forces)
    };
    let speed = 3000.0 * std::f64::consts::PI / 30.0;
    let (u_fwd, f_fwd) = settle(speed);
    let (u_rev, f_rev) = settle(-speed);
    let scale = u_fwd.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    assert!(
        scale > 1e-7,
        "the forward equilibrium must move the journals"
    );
    for (i, (a, b)) in u_fwd.iter().zip(&u_rev).enumerate() {
        // x and θy flip sign under x → −x; y and θx do not.
        let sign = match i % 4 {
            0 | 3 => -1.0,
            _ => 1.0,
        };
        assert!(
            (b - sign * a).abs() <= 1e-9 * scale,
            "DOF {i}: reverse {b:.6e}, mirrored forward {:.6e}",
            sign * a
        );
    }
    let x_fwd = u_fwd[0];
    assert!(
        x_fwd.abs() > 1e-3 * scale,
        "attitude angle puts the journal off the load line"
    );
    for (a, b) in f_fwd.iter().zip(&f_rev) {
        assert!((b.x + a.x).abs() <= 1e-8 * a.norm() && (b.y - a.y).abs() <= 1e-8 * a.norm());
    }
}
