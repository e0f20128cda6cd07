//! Unit tests of `bearing::contact` (the parent module's `mod tests`).

use super::*;
use std::f64::consts::FRAC_PI_2;

fn law() -> ContactLaw {
    ContactLaw {
        gap: 1e-4,
        stiffness: 2e9,
        damping: 3e4,
        friction: 0.3,
        radius: 0.05,
        smoothing: 1e-7,
        slip_velocity: 1e-3,
    }
}

fn at(angle: f64, radius: f64) -> Vector2<f64> {
    Vector2::new(radius * angle.cos(), radius * angle.sin())
}

/// Central differences of the force against the closed-form Jacobians.
fn check_jacobians(law: &ContactLaw, p: Vector2<f64>, v: Vector2<f64>, speed: f64) {
    let (f, _) = law.evaluate(p, v, speed);
    let scale = f.force.norm().max(1.0);
    let hp = 1e-11;
    let hv = 1e-7;
    for j in 0..2 {
        let mut e = Vector2::zeros();
        e[j] = 1.0;
        let (fp, _) = law.evaluate(p + e * hp, v, speed);
        let (fm, _) = law.evaluate(p - e * hp, v, speed);
        let (gp, _) = law.evaluate(p, v + e * hv, speed);
        let (gm, _) = law.evaluate(p, v - e * hv, speed);
        for i in 0..2 {
            let k_fd = -(fp.force[i] - fm.force[i]) / (2.0 * hp);
            let c_fd = -(gp.force[i] - gm.force[i]) / (2.0 * hv);
            let k = f.stiffness[(i, j)];
            let c = f.damping[(i, j)];
            assert!(
                (k - k_fd).abs() <= 1e-5 * (scale / law.smoothing) + 1e-6 * k.abs(),
                "K[{i}{j}] = {k:e}, finite differences {k_fd:e} at p = {p:?}, v = {v:?}"
            );
            assert!(
                (c - c_fd).abs() <= 1e-5 * (scale / law.slip_velocity) + 1e-6 * c.abs(),
                "C[{i}{j}] = {c:e}, finite differences {c_fd:e} at p = {p:?}, v = {v:?}"
            );
        }
    }
}

#[test]
fn edge_contact_jacobians_match_finite_differences() {
    let l = law();
    let normal = at(-1.9, 1.0);
    let along = at(-1.9 + FRAC_PI_2, 1.0);
    let cases = [
        (
            normal * (l.gap + 4e-7) + along * 2e-5,
            Vector2::new(1e-3, -2e-3),
            120.0,
        ),
        (
            normal * (l.gap + 5e-8) - along * 3e-5,
            Vector2::new(-3e-3, 1e-3),
            0.0,
        ),
    ];
    for (p, v, speed) in cases {
        let (f, rep) = l.evaluate_edge(normal, p, v, speed);
        assert!(rep.normal_force > 0.0);
        let scale = f.force.norm().max(1.0);
        for j in 0..2 {
            let mut e = Vector2::zeros();
            e[j] = 1.0;
            let d = |dp: f64, dv: f64| l.evaluate_edge(normal, p + e * dp, v + e * dv, speed).0;
            for i in 0..2 {
                let k_fd = -(d(1e-11, 0.0).force[i] - d(-1e-11, 0.0).force[i]) / 2e-11;
                let c_fd = -(d(0.0, 1e-7).force[i] - d(0.0, -1e-7).force[i]) / 2e-7;
                let (k, c) = (f.stiffness[(i, j)], f.damping[(i, j)]);
                assert!((k - k_fd).abs() <= 1e-5 * scale / l.smoothing + 1e-6 * k.abs());
                assert!((c - c_fd).abs() <= 1e-5 * scale / l.slip_velocity + 1e-6 * c.abs());
            }
        }
    }
    // Apart from the edge: nothing.
    let (f, rep) = l.evaluate_edge(normal, at(-1.9, 0.9 * l.gap), Vector2::zeros(), 10.0);
    assert_eq!(f.force, Vector2::zeros());
    assert!(rep.penetration < 0.0);
}

#[test]
fn no_force_while_the_surfaces_are_apart() {
    let l = law();
    let (f, rep) = l.evaluate(at(0.7, 0.999 * l.gap), Vector2::new(3.0, -2.0), 300.0);
    assert_eq!(f.force, Vector2::zeros());
    assert_eq!(f.stiffness, Matrix2::zeros());
    assert_eq!(rep.normal_force, 0.0);
    assert!(rep.penetration < 0.0);
}

#[test]
fn static_penetration_gives_the_penalty_force_along_the_normal() {
    let mut l = law();
    l.friction = 0.0;
    let delta = 5e-7; // beyond δ₀: N = k (δ − δ₀/2)
    let angle = -1.2;
    let (f, rep) = l.evaluate(at(angle, l.gap + delta), Vector2::zeros(), 0.0);
    let expected = l.stiffness * (delta - 0.5 * l.smoothing);
    assert!((rep.normal_force - expected).abs() < 1e-9 * expected);
    let n = at(angle, 1.0);
    assert!((f.force + n * expected).norm() < 1e-9 * expected);
    // Radial stiffness k, tangential stiffness N/r (the normal turns with p).
    let t = Vector2::new(-n.y, n.x);
    let k_nn = n.dot(&(f.stiffness * n));
    let k_tt = t.dot(&(f.stiffness * t));
    assert!((k_nn - l.stiffness).abs() < 1e-9 * l.stiffness);
    assert!((k_tt - expected / (l.gap + delta)).abs() < 1e-6 * k_tt);
}

#[test]
fn jacobians_match_finite_differences() {
    let l = law();
    let states = [
        (at(0.3, l.gap + 3e-7), Vector2::new(1e-3, 2e-3), 100.0),
        (at(2.0, l.gap + 5e-8), Vector2::new(-4e-3, 1e-3), 50.0),
        (at(-2.5, l.gap + 2e-6), Vector2::new(2e-4, -3e-4), 0.0),
        (at(4.0, l.gap + 8e-7), Vector2::new(-1e-2, 5e-3), -80.0),
        // Sliding velocity near zero: the regularized sign is steep there.
        (
            at(1.0, l.gap + 4e-7),
            Vector2::new(0.0, 0.0),
            1e-3 / 0.05 * 0.3,
        ),
        // Near-zero sliding while the journal moves along the normal.
        (
            at(1.0, l.gap + 4e-7),
            at(1.0, 2e-3) + at(1.0 + FRAC_PI_2, -0.1 * 0.05 + 2e-4),
            0.1,
        ),
    ];
    for (p, v, speed) in states {
        check_jacobians(&l, p, v, speed);
    }
}

#[test]
fn force_is_continuous_at_first_touch_and_at_the_end_of_smoothing() {
    let l = law();
    let v = Vector2::new(1e-3, 0.0);
    for edge in [l.gap, l.gap + l.smoothing] {
        let (below, _) = l.evaluate(at(0.0, edge * (1.0 - 1e-12)), v, 10.0);
        let (above, _) = l.evaluate(at(0.0, edge * (1.0 + 1e-12)), v, 10.0);
        let jump = (below.force - above.force).norm();
        assert!(
            jump < 1e-3 * (1.0 + above.force.norm()),
            "jump {jump} at r = {edge}"
        );
    }
}

#[test]
fn damping_never_pulls_the_surfaces_together() {
    let l = law();
    let p = at(0.0, l.gap + 2e-7);
    // Receding fast: k s + c δ̇ < 0, the normal force is zero, not a pull.
    let (f, rep) = l.evaluate(p, Vector2::new(-10.0, 0.0), 0.0);
    assert_eq!(rep.normal_force, 0.0);
    assert_eq!(f.force, Vector2::zeros());
    // Approaching: damping adds to the penalty.
    let (_, fast) = l.evaluate(p, Vector2::new(1e-2, 0.0), 0.0);
    let (_, still) = l.evaluate(p, Vector2::zeros(), 0.0);
    assert!(fast.normal_force > still.normal_force);
}

/// The friction power is what the friction force and torque take out of
/// the whirl and the spin: `μ N |v_s| = −F_t (ṗ·t) + T_f Ω` (the sign's
/// regularization aside: 1e-6 at `|v_s| ≫ v_ε`), with the whirl against
/// or along the spin.
#[test]
fn friction_power_is_the_work_rate_of_the_friction_force_and_torque() {
    let l = law();
    let angle = 1.1;
    let p = at(angle, l.gap + 2e-6);
    let n = at(angle, 1.0);
    let t = Vector2::new(-n.y, n.x);
    for (speed, whirl) in [(300.0, 4.0), (300.0, -25.0), (-150.0, 2.0)] {
        let (f, rep) = l.evaluate(p, t * whirl, speed);
        let sliding = whirl + speed * l.radius;
        assert!((rep.sliding_velocity - sliding).abs() < 1e-12);
        let power = l.friction_power(&rep);
        assert!((power - l.friction * rep.normal_force * sliding.abs()).abs() <= 1e-12 * power);
        let phi = sliding / (sliding * sliding + l.slip_velocity.powi(2)).sqrt();
        let torque = l.friction * rep.normal_force * l.radius * phi;
        let friction_force = f.force.dot(&t);
        let taken = -friction_force * whirl + torque * speed;
        assert!((taken - power).abs() < 1e-6 * power, "{taken} {power}");
    }
    let (_, apart) = l.evaluate(at(angle, 0.5 * l.gap), t, 300.0);
    assert_eq!(l.friction_power(&apart), 0.0);
}

#[test]
fn friction_opposes_sliding_and_gives_the_coulomb_torque() {
    let l = law();
    let angle = 0.4;
    let p = at(angle, l.gap + 1e-6);
    let n = at(angle, 1.0);
    let t = Vector2::new(-n.y, n.x);
    for speed in [300.0, -300.0] {
        let (f, rep) = l.evaluate(p, Vector2::zeros(), speed);
        let tangential = f.force.dot(&t);
        let normal = -f.force.dot(&n);
        assert!((normal - rep.normal_force).abs() < 1e-9 * normal);
        // Fully sliding (|v_s| = 15 m/s ≫ v_ε): |F_t| = μ N, against v_s.
        assert!((tangential.abs() - l.friction * normal).abs() < 1e-8 * normal);
        assert!(tangential * rep.sliding_velocity < 0.0);
        let coulomb = l.friction * normal * l.radius;
        assert!((rep.friction_torque - coulomb * speed.signum()).abs() < 1e-8 * coulomb);
    }
    // The whirl velocity counts: a journal rolling without slip (ṗ·t = −Ω R)
    // feels no friction.
    let speed = 200.0;
    let rolling = t * (-speed * l.radius);
    let (f, rep) = l.evaluate(p, rolling, speed);
    assert!(rep.sliding_velocity.abs() < 1e-12);
    assert!(f.force.dot(&t).abs() < 1e-9 * rep.normal_force);
}

#[test]
fn elastic_part_is_conservative_and_the_rest_dissipates() {
    let mut l = law();
    // Work of the force along a closed path inside the contact zone is zero
    // without damping and friction: the penalty derives from a potential.
    l.damping = 0.0;
    l.friction = 0.0;
    let steps = 20_000;
    let mut work = 0.0;
    let path = |s: f64| {
        let a = 2.0 * std::f64::consts::PI * s;
        at(0.5 * a.sin(), l.gap + 3e-7 + 2.5e-7 * a.cos())
    };
    let mut max_force: f64 = 0.0;
    for i in 0..steps {
        let (s0, s1) = (i as f64 / steps as f64, (i + 1) as f64 / steps as f64);
        let (p0, p1) = (path(s0), path(s1));
        let (f, _) = l.evaluate(0.5 * (p0 + p1), Vector2::zeros(), 0.0);
        work += f.force.dot(&(p1 - p0));
        max_force = max_force.max(f.force.norm());
    }
    assert!(
        work.abs() < 1e-7 * max_force * 5e-7,
        "closed-path work {work}"
    );
    // The potential is the work done against the penalty on a radial path.
    let delta = 4e-7;
    let mut radial_work = 0.0;
    for i in 0..steps {
        let (d0, d1) = (
            delta * i as f64 / steps as f64,
            delta * (i + 1) as f64 / steps as f64,
        );
        let (f, _) = l.evaluate(at(1.0, l.gap + 0.5 * (d0 + d1)), Vector2::zeros(), 0.0);
        radial_work -= f.force.dot(&at(1.0, d1 - d0));
    }
    let v = l.potential_energy(delta);
    assert!((radial_work - v).abs() < 1e-6 * v, "{radial_work} vs {v}");

    // With damping and friction, the power of the dissipative part is ≤ 0.
    let full = law();
    for (p, v, speed) in [
        (at(0.2, full.gap + 4e-7), Vector2::new(2e-3, -1e-3), 150.0),
        (at(2.2, full.gap + 6e-8), Vector2::new(-3e-3, 4e-3), -60.0),
    ] {
        let (f, rep) = full.evaluate(p, v, speed);
        let n = p / p.norm();
        let elastic = -n * (full.stiffness * full.penalty(rep.penetration).0);
        let power = (f.force - elastic).dot(&v) - rep.friction_torque * speed;
        assert!(power <= 1e-12, "dissipative power {power} > 0");
    }
}

#[test]
fn default_steel_law_is_valid_and_bad_parameters_are_named() {
    let l = ContactLaw::steel(1e-4, 0.05, 0.03);
    l.validate().unwrap();
    // (π/4) E* L with E* = 2.1e11 / (2 · 0.91) Pa, L = 0.03 m.
    assert!((l.stiffness - 2.718e9).abs() < 1e-3 * 2.718e9);
    let mut bad = l;
    bad.friction = -0.1;
    let msg = bad.validate().unwrap_err().to_string();
    assert!(msg.contains("friction") && msg.contains("-0.1"), "{msg}");
    bad = l;
    bad.gap = f64::NAN;
    assert!(bad.validate().unwrap_err().to_string().contains("gap"));
}

/// The limits of the law: 10 % of the gap, and the force where the peak
/// Hertz pressure of the conformal line contact reaches 1.67 σ_y. For the
/// steel law of a 50 mm journal, 30 mm long, in a 0.1 mm clearance:
/// `R* = 0.05 · 0.0501 / 1e-4 = 25.05 m`, `F_y = π L R* p_y² / E*`
/// = π · 0.03 · 25.05 · (417.5 MPa)² / 115.4 GPa = 3.57 MN.
#[test]
fn the_limits_of_the_law_are_a_tenth_of_the_gap_and_the_yield_force() {
    let l = ContactLaw::steel(1e-4, 0.05, 0.03);
    let e_star = 2.1e11 / 1.82;
    let hand = std::f64::consts::PI * 0.03 * 25.05 * 417.5e6f64.powi(2) / e_star;
    assert!(
        (l.yield_force() - hand).abs() < 1e-12 * hand,
        "{}",
        l.yield_force()
    );
    assert!((hand - 3.57e6).abs() < 0.01e6, "{hand}");
    let apart = l.evaluate(at(0.3, 0.9e-4), Vector2::zeros(), 100.0).1;
    assert_eq!(l.extent(&apart), None);
    let pressed = l.evaluate(at(0.3, 1.2e-4), Vector2::zeros(), 100.0).1;
    let extent = l.extent(&pressed).unwrap();
    assert!((extent.penetration - 0.2e-4).abs() < 1e-15);
    assert_eq!(extent.penetration_limit, 1e-5);
    assert_eq!(
        (extent.force, extent.force_limit),
        (pressed.normal_force, l.yield_force())
    );
    // The worst of two contacts, limit by limit relative to each limit.
    let deep = ContactExtent {
        penetration: 3e-5,
        penetration_limit: 1e-5,
        force: 1.0,
        force_limit: 100.0,
    };
    let hard = ContactExtent {
        penetration: 1e-6,
        penetration_limit: 1e-6,
        force: 90.0,
        force_limit: 10.0,
    };
    let worst = deep.worst(hard);
    assert_eq!((worst.penetration, worst.penetration_limit), (3e-5, 1e-5));
    assert_eq!((worst.force, worst.force_limit), (90.0, 10.0));
    assert_eq!(hard.worst(deep), worst);
}
