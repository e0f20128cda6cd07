//! Plain short bearing against the independent numerical-quadrature oracle in
//! `tests/data/` (see `tests/data/README.md`; forces from quadrature of the cavitated pressure field,
//! Jacobians from finite differences of those forces), against central finite
//! differences of our own force, and against the textbook closed forms.

use nalgebra::{Matrix2, Vector2};
use serde_json::Value;

#[path = "common/reference.rs"]
mod reference;
use reference::{mat, num, reference};

use rotor_bearing::bearing::equilibrium::journal_equilibrium;
use rotor_bearing::bearing::{Bearing, JournalState, PlainBearing};

fn bearing(p: &Value) -> (PlainBearing, f64) {
    (
        PlainBearing {
            radius: num(&p["R"]),
            length: num(&p["L"]),
            clearance: num(&p["C"]),
            viscosity: num(&p["mu"]),
            contact: None,
        },
        num(&p["omega"]),
    )
}

fn state(s: &Value) -> JournalState {
    JournalState {
        position: Vector2::new(num(&s["X"]), num(&s["Y"])),
        velocity: Vector2::new(num(&s["Xdot"]), num(&s["Ydot"])),
    }
}

/// Central finite differences of the force, step `h` in position and `hv` in velocity.
fn finite_difference(
    b: &PlainBearing,
    s: &JournalState,
    speed: f64,
) -> (Matrix2<f64>, Matrix2<f64>) {
    let h = 1e-7 * b.clearance;
    let hv = 1e-7 * (speed.abs() * b.clearance).max(s.velocity.norm()).max(1e-9);
    let f = |st: JournalState| b.force_and_jacobian(&st, speed).unwrap().force;
    let mut k = Matrix2::zeros();
    let mut c = Matrix2::zeros();
    for j in 0..2 {
        let (mut p, mut m) = (*s, *s);
        p.position[j] += h;
        m.position[j] -= h;
        k.set_column(j, &(-(f(p) - f(m)) / (2.0 * h)));
        let (mut p, mut m) = (*s, *s);
        p.velocity[j] += hv;
        m.velocity[j] -= hv;
        c.set_column(j, &(-(f(p) - f(m)) / (2.0 * hv)));
    }
    (k, c)
}

#[test]
fn forces_match_the_quadrature_oracle_at_every_state() {
    let r = reference("short_bearing_reference.json");
    let (b, speed) = bearing(&r["parameters"]);
    // Force scale: the load the bearing is designed for (W = 1000 N).
    let scale = num(&r["parameters"]["W"]);
    let states = r["states"].as_array().unwrap();
    assert_eq!(states.len(), 30);
    let mut worst: f64 = 0.0;
    for s in states {
        let out = b.force_and_jacobian(&state(s), speed).unwrap();
        let want = Vector2::new(num(&s["Fx"]), num(&s["Fy"]));
        let err = (out.force - want).norm() / scale.max(want.norm());
        worst = worst.max(err);
        assert!(
            err < 1e-6,
            "state {} ({}): {:?} vs {want:?}",
            s["id"],
            s["label"],
            out.force
        );
    }
    eprintln!("worst relative force error over 30 states: {worst:.2e}");
}

#[test]
fn jacobians_match_oracle_and_own_finite_differences() {
    let r = reference("short_bearing_reference.json");
    let (b, speed) = bearing(&r["parameters"]);
    for s in r["states"].as_array().unwrap() {
        let st = state(s);
        let out = b.force_and_jacobian(&st, speed).unwrap();
        let (k_ref, c_ref) = (mat(&s["K"]), mat(&s["C"]));
        // Oracle coefficients are finite differences with known error estimates.
        let (ek, ec) = (
            mat(&s["fd_error_estimate_K"]),
            mat(&s["fd_error_estimate_C"]),
        );
        let (ks, cs) = (k_ref.amax(), c_ref.amax());
        for i in 0..2 {
            for j in 0..2 {
                let tol_k = 1e-6 * ks + 10.0 * ek[(i, j)];
                let tol_c = 1e-6 * cs + 10.0 * ec[(i, j)];
                assert!(
                    (out.stiffness[(i, j)] - k_ref[(i, j)]).abs() < tol_k,
                    "state {} K[{i}][{j}]: {} vs {}",
                    s["id"],
                    out.stiffness[(i, j)],
                    k_ref[(i, j)]
                );
                assert!(
                    (out.damping[(i, j)] - c_ref[(i, j)]).abs() < tol_c,
                    "state {} C[{i}][{j}]: {} vs {}",
                    s["id"],
                    out.damping[(i, j)],
                    c_ref[(i, j)]
                );
            }
        }
        // Centred at rest the force is not differentiable: skip the own-FD check there.
        if st.position.norm() == 0.0 && st.velocity.norm() == 0.0 {
            continue;
        }
        let (k_fd, c_fd) = finite_difference(&b, &st, speed);
        let dk = (out.stiffness - k_fd).amax() / out.stiffness.amax();
        let dc = (out.damping - c_fd).amax() / out.damping.amax();
        assert!(
            dk < 1e-5 && dc < 1e-5,
            "state {}: FD mismatch K {dk:e}, C {dc:e}",
            s["id"]
        );
    }
}

#[test]
fn static_journal_matches_textbook_closed_form() {
    // Ocvirk steady load: W = k0/4 · ε/(1−ε²)² · √(16ε² + π²(1−ε²)), tan φ = π√(1−ε²)/(4ε).
    let r = reference("short_bearing_reference.json");
    let (b, speed) = bearing(&r["parameters"]);
    let k0 = num(&r["parameters"]["k0"]);
    for row in r["static_closed_form_check"]["rows"].as_array().unwrap() {
        let eps = num(&row["eps"]);
        let angle = num(&row["journal_angle_deg"]).to_radians();
        let st = JournalState {
            position: Vector2::new(angle.cos(), angle.sin()) * eps * b.clearance,
            velocity: Vector2::zeros(),
        };
        let out = b.force_and_jacobian(&st, speed).unwrap();
        let w = k0 / 4.0 * eps / (1.0 - eps * eps).powi(2)
            * (16.0 * eps * eps + std::f64::consts::PI.powi(2) * (1.0 - eps * eps)).sqrt();
        let phi = (std::f64::consts::PI * (1.0 - eps * eps).sqrt() / (4.0 * eps)).atan();
        assert!(
            (out.force.norm() - w).abs() < 1e-9 * w,
            "ε = {eps}: {} vs {w}",
            out.force.norm()
        );
        let report = b.journal_report(&st, speed, &out.force);
        assert!(
            (report.attitude_angle - phi).abs() < 1e-9,
            "ε = {eps}: φ {} vs {phi}",
            report.attitude_angle
        );
        assert!((report.eccentricity - eps).abs() < 1e-12);
        assert!((report.min_film_thickness - b.clearance * (1.0 - eps)).abs() < 1e-15);
    }
}

#[test]
fn equilibrium_and_its_coefficients_match_the_reference() {
    let r = reference("short_bearing_reference.json");
    let (b, speed) = bearing(&r["parameters"]);
    let eq = &r["equilibrium"];
    let w = num(&eq["W"]);
    let sol = journal_equilibrium(&b, Vector2::new(0.0, -w), speed, b.clearance).unwrap();
    let report = b.report(&sol.q, &[0.0; 2], speed, &sol.eval);
    assert!(
        (report.eccentricity - num(&eq["eps"])).abs() < 1e-9,
        "ε {}",
        report.eccentricity
    );
    let att = report.attitude_angle.to_degrees();
    assert!((att - num(&eq["attitude_deg"])).abs() < 1e-7, "φ {att}");
    let co = &r["coefficients_at_equilibrium"];
    let (k, c) = (mat(&co["K"]), mat(&co["C"]));
    assert!(
        (sol.eval.journal().stiffness - k).amax() < 1e-7 * k.amax(),
        "{}",
        sol.eval.journal().stiffness
    );
    assert!(
        (sol.eval.journal().damping - c).amax() < 1e-7 * c.amax(),
        "{}",
        sol.eval.journal().damping
    );
}

#[test]
fn zero_speed_squeeze_film_matches_oracle() {
    let r = reference("short_bearing_zero_speed.json");
    for s in r["states"].as_array().unwrap() {
        let (b, speed) = bearing(s);
        assert_eq!(speed, 0.0);
        let st = state(s);
        let out = b.force_and_jacobian(&st, speed).unwrap();
        let want = Vector2::new(num(&s["Fx"]), num(&s["Fy"]));
        assert!(
            (out.force - want).norm() < 1e-6 * want.norm(),
            "{:?} vs {want:?}",
            out.force
        );
        let (k, c) = (mat(&s["K"]), mat(&s["C_damp"]));
        assert!(
            (out.stiffness - k).amax() < 1e-6 * k.amax(),
            "{} vs {k}",
            out.stiffness
        );
        assert!(
            (out.damping - c).amax() < 1e-6 * c.amax(),
            "{} vs {c}",
            out.damping
        );
    }
}

#[test]
fn degenerate_half_speed_whirl_has_no_force() {
    let r = reference("short_bearing_reference.json");
    let (b, speed) = bearing(&r["parameters"]);
    let d = &r["degenerate_state"];
    let out = b.force_and_jacobian(&state(d), speed).unwrap();
    assert!(out.force.norm() < 1e-9, "{:?}", out.force);
    assert!(
        out.stiffness
            .iter()
            .chain(out.damping.iter())
            .all(|v| v.is_finite())
    );
}

/// Property test: any finite state, floating or in contact (ε up to 1.2), gives
/// finite forces, Jacobians and report, never NaN, never an error or a panic
/// (deterministic xorshift sampling, 200 000 states).
#[test]
fn no_nan_and_no_panic_for_any_finite_state() {
    let b = PlainBearing {
        radius: 0.05,
        length: 0.03,
        clearance: 1e-4,
        viscosity: 0.02,
        contact: None,
    };
    let mut seed: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut next = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let (mut floating, mut contact) = (0, 0);
    for k in 0..200_000 {
        // Eccentricities 0 … 1.2 with a dense band near 1; velocities up to 10 ωC; speeds ±.
        let eps = if k % 4 == 0 {
            1.0 - 10f64.powf(-12.0 * next())
        } else {
            1.2 * next()
        };
        let angle = 2.0 * std::f64::consts::PI * next();
        let speed = 600.0 * (next() - 0.5) * if k % 10 == 0 { 0.0 } else { 1.0 };
        let vscale = 10.0 * 314.0 * b.clearance * next().powi(3);
        let st = JournalState {
            position: Vector2::new(angle.cos(), angle.sin()) * eps * b.clearance,
            velocity: Vector2::new(next() - 0.5, next() - 0.5) * vscale,
        };
        let out = b
            .force_and_jacobian(&st, speed)
            .unwrap_or_else(|e| panic!("error {e} at {st:?}, ω = {speed}"));
        assert!(
            out.force
                .iter()
                .chain(out.stiffness.iter())
                .chain(out.damping.iter())
                .all(|v| v.is_finite()),
            "non-finite output at {st:?}, ω = {speed}"
        );
        let rep = b.journal_report(&st, speed, &out.force);
        assert!(rep.attitude_angle.is_finite() && rep.eccentricity.is_finite());
        assert!(rep.friction_torque.is_finite() && rep.min_film_thickness >= 0.0);
        if eps > 1.0 {
            contact += 1;
        } else {
            floating += 1;
            assert_eq!(
                rep.contact_force, 0.0,
                "contact while floating at ε = {eps}"
            );
        }
    }
    assert!(
        floating > 100_000 && contact > 10_000,
        "{floating} floating, {contact} in contact"
    );
}
