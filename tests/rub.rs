//! Rub elements (`[[rubs]]`): energy bookkeeping of the contact law in a
//! transient, and friction acting along the sliding direction (dry whip).
//!
//! The rotor: a 0.4 m, 50 mm steel shaft with a 10 kg disk in the middle on
//! two undamped linear bearings, and a stator ring around the disk.

use rotor_bearing::bearing::BearingKind;
use rotor_bearing::bearing::contact::ContactLaw;
use rotor_bearing::fe::{DOF_X, DOF_Y};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

/// The test rotor with a rub of radial gap 100 µm at the disk; `rub` holds the
/// extra keys of the `[[rubs]]` entry.
fn rub_rotor(rub: &str, bearing_damping: f64) -> Rotor {
    let text = format!(
        r#"
name = "rub_test"
gravity = [0.0, 0.0, 0.0]

[[materials]]
name = "steel"
youngs_modulus = 210e9
poisson_ratio = 0.3
density = 7850.0

[[shaft]]
length = 0.4
outer_diameter = 0.05
material = "steel"
elements = 4

[[disks]]
node = 3
mass = 10.0
polar_inertia = 0.05
diametral_inertia = 0.03

[[bearings]]
name = "left"
type = "linear"
node = 1
kxx = 1e7
kyy = 1e7
cxx = {bearing_damping}
cyy = {bearing_damping}

[[bearings]]
name = "right"
type = "linear"
node = 5
kxx = 1e7
kyy = 1e7
cxx = {bearing_damping}
cyy = {bearing_damping}

[[rubs]]
name = "seal"
node = 3
gap = 100e-6
{rub}
"#
    );
    Rotor::new(RotorModel::from_toml(&text, "rub_test.toml").unwrap()).unwrap()
}

/// The contact law of the rotor's rub and its node.
fn rub_of(rotor: &Rotor) -> (ContactLaw, usize) {
    let b = rotor
        .model
        .bearings
        .iter()
        .find(|b| b.kind.is_rub())
        .unwrap();
    let BearingKind::Rub(r) = &b.kind else {
        unreachable!()
    };
    (r.contact, b.node)
}

/// Kinetic + elastic (shaft, bearings, contact) energy (J) of the state.
fn energy(sim: &Simulator) -> f64 {
    let rotor = sim.rotor();
    let s = sim.state();
    let n = rotor.dof_count();
    let (mut mv, mut ku) = (vec![0.0; n], vec![0.0; n]);
    rotor.mass.mul_vec(&s.ud, &mut mv);
    rotor.stiffness.mul_vec(&s.u, &mut ku);
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let (law, node) = rub_of(rotor);
    let (x, y) = rub_position(sim, node);
    0.5 * dot(&s.ud, &mv) + 0.5 * dot(&s.u, &ku) + law.potential_energy(x.0.hypot(y.0) - law.gap)
}

/// Position and velocity of `node`: `((x, ẋ), (y, ẏ))`.
fn rub_position(sim: &Simulator, node: usize) -> ((f64, f64), (f64, f64)) {
    let rotor = sim.rotor();
    let s = sim.state();
    let ix = rotor.dofs.free(node, DOF_X).unwrap();
    let iy = rotor.dofs.free(node, DOF_Y).unwrap();
    ((s.u[ix], s.ud[ix]), (s.u[iy], s.ud[iy]))
}

/// A simulator of `rotor` at spin `speed`, every lateral DOF displaced by
/// `(0, y0)` (m) and moving at the velocity `(vx, vy)` (m/s).
fn thrown(rotor: Rotor, speed: f64, y0: f64, (vx, vy): (f64, f64), step: f64) -> Simulator {
    let dofs = rotor.dofs.clone();
    let n = rotor.dof_count();
    let mut sim = Simulator::new(
        rotor,
        SolverOptions {
            time_step: step,
            tolerance: 1e-12,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    sim.set_speed(speed, 0.0).unwrap();
    let mut state = sim.state().clone();
    for i in 0..n {
        state.ud[i] = match dofs.full(i) % 4 {
            DOF_X => vx,
            DOF_Y => vy,
            _ => 0.0,
        };
        if dofs.full(i) % 4 == DOF_Y {
            state.u[i] = y0;
        }
    }
    sim.set_state(state).unwrap();
    sim.consistent_acceleration().unwrap();
    sim
}

/// Frictionless, undamped contact: the rotor bounces off the stator several
/// times and its mechanical energy (kinetic + shaft and bearing strain +
/// contact potential) stays constant to the integration error of the
/// average-acceleration rule on the penalty law (3.4e-4 relative measured at
/// 10 µs steps over 30 ms; bound 1e-3).
#[test]
fn frictionless_undamped_bounce_conserves_energy() {
    let rotor = rub_rotor(
        "contact_stiffness = 1e8\ncontact_damping = 0.0\nfriction_coefficient = 0.0",
        0.0,
    );
    let (law, node) = rub_of(&rotor);
    let mut sim = thrown(rotor, 0.0, 0.0, (0.18, -0.24), 1e-5);
    let e0 = energy(&sim);
    let (mut worst, mut contact_steps) = (0.0f64, 0);
    for k in 1..=3000 {
        sim.advance_to(k as f64 * 1e-5).unwrap();
        let ((x, _), (y, _)) = rub_position(&sim, node);
        if x.hypot(y) > law.gap {
            contact_steps += 1;
        }
        worst = worst.max((energy(&sim) - e0).abs() / e0);
    }
    eprintln!("energy drift {worst:e} of {e0} J over {contact_steps} steps in contact");
    assert!(contact_steps > 100, "only {contact_steps} steps in contact");
    assert!(worst < 1e-3, "energy drift {worst:e} of {e0} J");
}

/// With friction (and no spin, so the friction only opposes the whirl), the
/// energy lost equals the friction work `∫ μ N φ(v_s) v_s dt` integrated along
/// the run (trapezoidal, as the Newmark velocities are), to 1 %.
#[test]
fn energy_lost_to_friction_equals_the_friction_work() {
    let keys = "contact_stiffness = 1e8\ncontact_damping = 0.0\nfriction_coefficient = 0.3";
    let rotor = rub_rotor(keys, 0.0);
    let (law, node) = rub_of(&rotor);
    // Thrown at the stator obliquely: it slides along it while in contact.
    let mut sim = thrown(rotor, 0.0, 6e-5, (0.3, 0.0), 1e-5);
    let e0 = energy(&sim);
    let power = |sim: &Simulator| {
        let ((x, vx), (y, vy)) = rub_position(sim, node);
        let (_, report) = law.evaluate(
            nalgebra::Vector2::new(x, y),
            nalgebra::Vector2::new(vx, vy),
            0.0,
        );
        let v = report.sliding_velocity;
        let phi = v / (v * v + law.slip_velocity * law.slip_velocity).sqrt();
        law.friction * report.normal_force * phi * v
    };
    let (mut work, mut last) = (0.0, power(&sim));
    for k in 1..=3000 {
        sim.advance_to(k as f64 * 1e-5).unwrap();
        let p = power(&sim);
        work += 0.5 * (last + p) * 1e-5;
        last = p;
    }
    let lost = e0 - energy(&sim);
    eprintln!("energy lost {lost} J, friction work {work} J, of {e0} J");
    assert!(
        work > 0.05 * e0,
        "friction work {work} J of {e0} J: no sliding contact"
    );
    assert!(
        (lost - work).abs() < 0.01 * work,
        "energy lost {lost} J, friction work {work} J"
    );
}

/// Mean whirl rate (rad/s, positive = forward, with the spin) of the rub node
/// and the fraction of steps in contact, over the second half of a 0.4 s run
/// of the rotor (bearing damping 2000 N·s/m) spinning at 500 rad/s, thrown
/// radially onto the stator at 0.3 m/s.
fn whirl_after_impact(friction: f64) -> (f64, f64) {
    let keys = format!("contact_stiffness = 1e8\nfriction_coefficient = {friction}");
    let rotor = rub_rotor(&keys, 2000.0);
    let (law, node) = rub_of(&rotor);
    let mut sim = thrown(rotor, 500.0, 0.0, (0.0, -0.3), 1e-5);
    let (mut angle, mut last, mut contact, mut count) = (0.0, None::<f64>, 0, 0);
    for k in 1..=40_000 {
        sim.advance_to(k as f64 * 1e-5).unwrap();
        if k < 20_000 {
            continue;
        }
        let ((x, _), (y, _)) = rub_position(&sim, node);
        let a = y.atan2(x);
        if let Some(l) = last {
            let d = a - l;
            angle += d.sin().atan2(d.cos());
        }
        last = Some(a);
        count += 1;
        if x.hypot(y) > law.gap {
            contact += 1;
        }
    }
    (angle / 0.2, contact as f64 / count as f64)
}

/// Friction acts along the sliding direction: on a spinning rotor it pushes the
/// contact point against the surface speed, so a high friction coefficient
/// drives sustained backward whirl in full annular contact (dry whip), at about
/// the backward frequency of the rotor on its bearings plus the contact,
/// √((2·10⁷ + 10⁸) N/m / 16 kg) ≈ 2700 rad/s; a low coefficient lets the rotor
/// bounce off and stay clear.
#[test]
fn high_friction_drives_dry_whip_backward_and_low_friction_does_not() {
    let (whirl, contact) = whirl_after_impact(0.4);
    assert!(
        contact == 1.0 && whirl < -2000.0,
        "μ = 0.4: whirl {whirl} rad/s, in contact {contact}"
    );
    let (whirl, contact) = whirl_after_impact(0.02);
    assert!(
        contact == 0.0,
        "μ = 0.02: whirl {whirl} rad/s, in contact {contact}"
    );
}

/// A rub is declared in the model file, checked like every key, described by
/// `rotor info`'s text, and reported by the FMU as `rubs.NAME.contact_force`
/// (N) and `rubs.NAME.friction_torque` (N·m), not as a bearing.
#[test]
fn rubs_are_read_checked_and_reported_as_rubs() {
    let rotor = rub_rotor("friction_coefficient = 0.25", 0.0);
    let (law, node) = rub_of(&rotor);
    assert_eq!(node, 2);
    assert_eq!((law.gap, law.friction), (100e-6, 0.25));
    // Default radius: the shaft's outer radius at the node; default stiffness:
    // the steel line contact of a 10 mm ring, (π/4) E/(2(1 − ν²)) · 0.01 m.
    assert_eq!(law.radius, 0.025);
    let steel = std::f64::consts::FRAC_PI_4 * 2.1e11 / (2.0 * (1.0 - 0.09)) * 0.01;
    assert!((law.stiffness - steel).abs() < 1e-9 * steel);
    let text = rotor_bearing::report::text::model_summary(&rotor);
    assert!(text.contains("rub element, radial gap 100 µm"), "{text}");
    let vars = rotor_bearing::fmi2::variables::variables(&rotor.model);
    let unit = |name: &str| vars.iter().find(|v| v.name == name).map(|v| v.unit);
    assert_eq!(unit("rubs.seal.contact_force"), Some(Some("N")));
    assert_eq!(unit("rubs.seal.friction_torque"), Some(Some("N.m")));
    assert!(!vars.iter().any(|v| v.name.starts_with("bearings.seal.")));
    for (keys, field) in [
        ("gap = -1e-4", "rubs[0].gap"),
        (
            "friction_coefficient = -0.1",
            "rubs[0].friction_coefficient",
        ),
        ("contact_stiffness = 0.0", "rubs[0].contact_stiffness"),
    ] {
        let text = format!(
            "name = \"r\"\n[[materials]]\nname = \"steel\"\nyoungs_modulus = 2e11\npoisson_ratio = 0.3\ndensity = 7850.0\n[[shaft]]\nlength = 0.4\nouter_diameter = 0.05\nmaterial = \"steel\"\nelements = 4\n[[rubs]]\nnode = 3\n{}\n",
            if keys.starts_with("gap") {
                keys.to_string()
            } else {
                format!("gap = 1e-4\n{keys}")
            }
        );
        let e = RotorModel::from_toml(&text, "r.toml")
            .unwrap_err()
            .to_string();
        assert!(e.contains(field), "{keys}: {e}");
    }
}

/// The operating point lists the bearings only: a rub element is not a bearing.
#[test]
fn the_operating_point_lists_bearings_not_rubs() {
    let rotor = rub_rotor("", 0.0);
    let points = rotor_bearing::analysis::operating_point::operating_point(&rotor, 100.0).unwrap();
    let names: Vec<&str> = points.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names, ["left", "right"]);
}

/// Dry whip on fluid-film bearings (issue 22): the Jeffcott rotor with 1 kg·m
/// at its disk, at 3000 rpm, thrown onto a seal of gap 200 µm around the disk.
/// Friction drives the disk backward until it rolls on the stator: the sliding
/// velocity `v_s = ṗ·t + Ω R` settles at zero, and the whirl rate `ψ̇` follows
/// the rolling kinematics `ψ̇ = −Ω R / r` (r the orbit radius). At `v_s ≈ 0`
/// the friction's sign turns within `v_ε`, and plain Newton cycles between its
/// two sides: the run used to take over 24 000 step halvings in 0.2 s. The
/// damped Newton solves every step of 0.1 ms without one.
#[test]
fn a_disk_rolling_on_its_seal_whirls_backward_at_the_rolling_rate_without_step_cuts() {
    let text = include_str!("../models/jeffcott.toml")
        .replace("magnitude = 2e-5", "magnitude = 1.0")
        + "\n[[rubs]]\nname = \"seal\"\nnode = 5\ngap = 200e-6\n";
    let rotor = Rotor::new(RotorModel::from_toml(&text, "jeffcott_seal.toml").unwrap()).unwrap();
    let (law, node) = rub_of(&rotor);
    let speed = 3000.0 * std::f64::consts::PI / 30.0;
    let mut sim = Simulator::new(rotor, SolverOptions::default()).unwrap();
    sim.set_speed(speed, 0.0).unwrap();
    sim.settle_static().unwrap();
    // Over the second half: the instantaneous whirl rate (p × ṗ)/r², the
    // rolling rate −Ω R / r and the sliding velocity.
    let (mut whirl, mut rolling, mut sliding, mut count) = (0.0, 0.0, 0.0f64, 0);
    for k in 1..=5000 {
        sim.advance_to(k as f64 * 1e-4).unwrap();
        if k <= 2500 {
            continue;
        }
        let ((x, vx), (y, vy)) = rub_position(&sim, node);
        let (_, report) = law.evaluate(
            nalgebra::Vector2::new(x, y),
            nalgebra::Vector2::new(vx, vy),
            speed,
        );
        assert!(
            report.normal_force > 0.0,
            "off the seal at t = {} s",
            sim.time()
        );
        let r2 = x * x + y * y;
        whirl += (x * vy - y * vx) / r2;
        rolling += -speed * law.radius / r2.sqrt();
        sliding = sliding.max(report.sliding_velocity.abs());
        count += 1;
    }
    let (whirl, rolling) = (whirl / count as f64, rolling / count as f64);
    let stats = sim.stats();
    eprintln!(
        "whirl {whirl} rad/s, rolling {rolling} rad/s, largest |v_s| {sliding} m/s, {stats:?}"
    );
    assert!(
        sliding < 0.01 * speed * law.radius,
        "largest sliding velocity {sliding} m/s: not rolling"
    );
    assert!(
        whirl < 0.0 && (whirl - rolling).abs() < 0.01 * rolling.abs(),
        "whirl {whirl} rad/s, rolling {rolling} rad/s"
    );
    assert_eq!(stats.step_cuts, 0, "{stats:?}");
    assert!(stats.retries > 0, "{stats:?}");
}

/// What [`thrown_and_watched`] saw: the deepest penetration (m), the first
/// step (time, value) past 10 % of the gap and past the yield force, and the
/// warnings the simulator raised.
struct Watched {
    deepest: f64,
    deep: Option<(f64, f64)>,
    hard: Option<(f64, f64)>,
    warnings: Vec<rotor_bearing::solver::ContactWarning>,
}

/// Contact far outside its law is reported (issue 22): the test rotor
/// (contact `keys`) displaced by `y0` (m) and thrown at the stator at
/// `speed_in` m/s, its contact checked from the state after every 10 µs step.
fn thrown_and_watched(keys: &str, y0: f64, speed_in: f64) -> Watched {
    let rotor = rub_rotor(keys, 0.0);
    let (law, node) = rub_of(&rotor);
    let mut sim = thrown(rotor, 0.0, y0, (0.0, -speed_in), 1e-5);
    let (mut deepest, mut deep, mut hard) = (0.0f64, None, None);
    let mut warnings = Vec::new();
    for k in 1..=2000 {
        sim.advance_to(k as f64 * 1e-5).unwrap();
        let ((x, vx), (y, vy)) = rub_position(&sim, node);
        let (_, report) = law.evaluate(
            nalgebra::Vector2::new(x, y),
            nalgebra::Vector2::new(vx, vy),
            0.0,
        );
        deepest = deepest.max(report.penetration);
        if deep.is_none() && report.penetration > 0.1 * law.gap {
            deep = Some((sim.time(), report.penetration));
        }
        if hard.is_none() && report.normal_force > law.yield_force() {
            hard = Some((sim.time(), report.normal_force));
        }
        warnings.extend(sim.take_contact_warnings());
    }
    Watched {
        deepest,
        deep,
        hard,
        warnings,
    }
}

/// The limits of the contact law are watched at every step: a rotor thrown
/// at its seal so hard that it goes seven gaps "into" the stator gets one
/// warning for the penetration (beyond 10 % of the gap) and one for the force
/// (beyond the yield onset of the contact, `F_y = π L R* p_y²/E*`), each at the
/// first step past the limit and never again; a gentle throw that stays within
/// both gets none.
#[test]
fn contact_beyond_the_limits_of_its_law_is_reported_once_per_run() {
    let keys = "contact_stiffness = 1e8\ncontact_damping = 0.0\nfriction_coefficient = 0.0";
    // The yield force by hand: L = k / ((π/4) E*), R* = R (R + g)/g.
    let e_star = 2.1e11 / (2.0 * (1.0 - 0.09));
    let length = 1e8 / (std::f64::consts::FRAC_PI_4 * e_star);
    let relative = 0.025 * (0.025 + 100e-6) / 100e-6;
    let yield_force = std::f64::consts::PI * length * relative * (1.67 * 250e6f64).powi(2) / e_star;
    let (law, _) = rub_of(&rub_rotor(keys, 0.0));
    assert!((law.yield_force() - yield_force).abs() < 1e-12 * yield_force);

    let Watched {
        deepest,
        deep,
        hard,
        warnings,
    } = thrown_and_watched(keys, 0.0, 2.0);
    eprintln!("thrown at 2 m/s: deepest {deepest:e} m; {warnings:#?}");
    let (t_deep, deep) = deep.expect("beyond 10 % of the gap");
    let (t_hard, hard) = hard.expect("beyond the yield force");
    assert!(deepest > 1.5 * law.gap, "{deepest:e} m");
    assert_eq!(warnings.len(), 2, "{warnings:#?}");
    let by = |limit| warnings.iter().find(|w| w.limit == limit).unwrap();
    let p = by(rotor_bearing::solver::ContactLimit::Penetration);
    // The step's time, to the round-off of the time grid.
    assert!(
        (p.time - t_deep).abs() < 1e-15,
        "{} s vs {t_deep} s",
        p.time
    );
    assert_eq!((p.value, p.bound), (deep, 0.1 * law.gap));
    assert!(
        p.message.starts_with("rub seal: at t = ") && p.message.contains("10 % of the gap"),
        "{}",
        p.message
    );
    let f = by(rotor_bearing::solver::ContactLimit::Force);
    assert!(
        (f.time - t_hard).abs() < 1e-15,
        "{} s vs {t_hard} s",
        f.time
    );
    assert_eq!(f.value, hard);
    assert!((f.bound - yield_force).abs() < 1e-12 * yield_force);
    assert!(
        f.message.contains("yield onset of steel (418 MPa)"),
        "{}",
        f.message
    );

    let Watched {
        deepest,
        deep,
        hard,
        warnings,
    } = thrown_and_watched(keys, -100e-6, 0.02);
    assert!(
        deepest > 0.0 && deep.is_none() && hard.is_none(),
        "{deepest:e} m"
    );
    assert!(warnings.is_empty(), "{warnings:#?}");
}
