//! Nothing lost, nothing silent, round two (issue 46): the torque drive,
//! ports, forces and power losses under faults and bad input, through the
//! safe FMU instance. One test per defect:
//! - D1: a torque that would overspeed the shaft fails its step (fmi2Discard)
//!   with the state at or below `max_speed_rpm`, which the FMU restores, in
//!   this instance and a fresh one;
//! - D2: a shaft that static friction holds carries the torque of opposing
//!   inputs, `T` in every element between them, twisted by `T L / (G J_p)`;
//! - D3: equal internal steps cut a failing step like accuracy-controlled
//!   ones before they discard;
//! - D4: every part of the total power loss has an output, and they add up;
//! - D5: a contact warning is raised again after a rollback to a state
//!   before it (the warning is part of the FMU state);
//! - D6: an input derivative of order 2 is accepted and not used;
//! - D7: force and torque inputs declare a physical range, and a step that
//!   ends with a displacement no machine can have says so.

use rotor_bearing::fmi2::instance::{Instance, Status};
use rotor_bearing::fmi2::variables::{Causality, Kind, variables};
use rotor_bearing::model::RotorModel;

#[path = "common/fmu.rs"]
mod fmu;
use fmu::{model, vr};

const RPM: f64 = std::f64::consts::PI / 30.0;

/// `tests/data/torque_ports.toml`: the damped classic rotor torque-driven at
/// both ends, with a coupling, thrust bearing, port, magnetic pull and forces
/// (no `max_speed_rpm`: the default 60 000 rpm).
fn torque_ports() -> RotorModel {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/torque_ports.toml");
    RotorModel::from_file(std::path::Path::new(path)).unwrap()
}

fn start(fmu: &mut Instance) -> Status {
    assert_eq!(fmu.setup_experiment(0.0, None), Status::Ok);
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    fmu.exit_initialization_mode()
}

fn set(fmu: &mut Instance, m: &RotorModel, name: &str, value: f64) {
    let status = fmu.set(vr(m, name), Kind::Real, value);
    assert_eq!(status, Status::Ok, "{name}: {:?}", fmu.drain_messages());
}

fn get(fmu: &mut Instance, m: &RotorModel, name: &str) -> f64 {
    fmu.get(vr(m, name), Kind::Real)
        .unwrap_or_else(|s| panic!("{name}: {s:?} {:?}", fmu.drain_messages()))
}

fn texts(fmu: &mut Instance) -> Vec<String> {
    fmu.drain_messages().into_iter().map(|m| m.2).collect()
}

/// D1, D3: 1.2e6 N·m on the torque-ports rotor (polar inertia about
/// 0.34 kg·m²) takes it past 60 000 rpm within 5 ms. The step is discarded
/// near the crossing (steps are cut down to it, equal or accuracy-controlled),
/// the message speaks of the torque in rpm, and the state reached restores
/// in this and a fresh instance (serialized). From a running shaft too.
#[test]
fn an_overspeeding_torque_is_discarded_and_its_state_restores() {
    let m = torque_ports();
    let max_rpm = m.max_speed / RPM;
    for (initial_rpm, torque, equal_steps) in [
        (0.0, 1.2e6, false),
        (0.0, 1.2e6, true),
        (3000.0, 3e5, false),
        (3000.0, 3e5, true),
    ] {
        let case = format!("{initial_rpm} rpm, {torque} N·m, equal steps {equal_steps}");
        let mut fmu = Instance::new("d1", m.clone()).unwrap();
        set(&mut fmu, &m, "shaft.initial_speed", initial_rpm * RPM);
        if equal_steps {
            set(&mut fmu, &m, "solver.local_error_tolerance", 0.0);
            set(&mut fmu, &m, "solver.time_step", 1e-3);
        }
        assert_eq!(start(&mut fmu), Status::Ok, "{case}: {:?}", texts(&mut fmu));
        set(&mut fmu, &m, "torques.drive", torque);
        let mut t = 0.0;
        let status = loop {
            let status = fmu.do_step(t, 5e-3);
            if status != Status::Ok || t > 1.0 {
                break status;
            }
            t += 5e-3;
        };
        assert_eq!(status, Status::Discard, "{case}");
        let messages = texts(&mut fmu);
        let text = messages.join("\n");
        assert!(
            text.contains("torque inputs (net")
                && text.contains("rpm")
                && text.contains("max_speed_rpm (60000 rpm)"),
            "{case}: {text}"
        );
        // Cut down to the crossing: the reached mean speed is within 1 % of
        // the limit (a 1 ms step adds about 3 % of it at this torque).
        let reached = fmu.last_successful_time().unwrap();
        let speed = get(&mut fmu, &m, "shaft.speed") / RPM;
        assert!(speed <= max_rpm, "{case}: {speed} rpm at {reached} s");
        assert!(speed > 0.99 * max_rpm, "{case}: {speed} rpm at {reached} s");
        // The state at the discard restores here and in a fresh instance.
        let snap = fmu.snapshot().unwrap();
        assert_eq!(
            fmu.restore(&snap),
            Status::Ok,
            "{case}: {:?}",
            texts(&mut fmu)
        );
        let bytes = fmu.serialize(&snap).unwrap();
        let mut fresh = Instance::new("d1b", m.clone()).unwrap();
        assert_eq!(start(&mut fresh), Status::Ok);
        let snap = fresh.deserialize(&bytes).unwrap();
        assert_eq!(
            fresh.restore(&snap),
            Status::Ok,
            "{case}: {:?}",
            texts(&mut fresh)
        );
        assert_eq!(get(&mut fresh, &m, "shaft.speed") / RPM, speed, "{case}");
    }
}

/// D2: the torque-driven hydro unit at rest under +5 MN·m at the runner
/// (node 20) and −5 MN·m at the generator (node 5): the net torque is zero,
/// so static friction holds it, and every element from node 5 to node 20
/// carries 5 MN·m (those above carry none); the relative twist of the two
/// nodes is `T Σ L_e / (G J_p,e)` over those elements.
#[test]
fn a_stuck_shaft_carries_the_torque_of_opposing_inputs() {
    let m = model("hydro_unit_torque");
    let mut fmu = Instance::new("d2", m.clone()).unwrap();
    assert_eq!(start(&mut fmu), Status::Ok, "{:?}", texts(&mut fmu));
    let torque = 5e6;
    set(&mut fmu, &m, "torques.turbine", torque);
    set(&mut fmu, &m, "torques.generator", -torque);
    for k in 0..10 {
        assert_eq!(fmu.do_step(k as f64 * 0.01, 0.01), Status::Ok);
    }
    assert_eq!(get(&mut fmu, &m, "shaft.speed"), 0.0);
    for (k, e) in m.elements.iter().enumerate() {
        let value = get(&mut fmu, &m, &format!("shaft.torque[{}]", k + 1));
        // Elements are numbered from node k + 1 to k + 2 (1-based).
        let expected = if e.node >= 4 { torque } else { 0.0 };
        assert!(
            (value - expected).abs() <= 1e-9 * torque,
            "element {}: {value} N·m, expected {expected}",
            k + 1
        );
    }
    let compliance: f64 = m
        .elements
        .iter()
        .filter(|e| e.node >= 4)
        .map(|e| {
            e.element.length / (e.element.material.shear_modulus * e.element.section.polar_moment())
        })
        .sum();
    let twist =
        get(&mut fmu, &m, "torques.turbine.angle") - get(&mut fmu, &m, "torques.generator.angle");
    assert!(
        (twist - torque * compliance).abs() <= 1e-9 * torque * compliance,
        "twist {twist} rad against T L / (G J) = {}",
        torque * compliance
    );
}

/// The torque-ports rotor pushed into the stator of its magnetic pull by a
/// port force (5e4 N at node 3, within the declared 1000 g bound) while it
/// turns at 3000 rpm: the pull's stator contact dissipates power.
fn pull_contact() -> (RotorModel, Instance) {
    let m = torque_ports();
    let mut fmu = Instance::new("d4", m.clone()).unwrap();
    set(&mut fmu, &m, "shaft.initial_speed", 3000.0 * RPM);
    assert_eq!(start(&mut fmu), Status::Ok, "{:?}", texts(&mut fmu));
    set(&mut fmu, &m, "ports.amb.fx", 5e4);
    (m, fmu)
}

/// D4: with the pull's rotor on its stator, the outputs named
/// `*.power_loss` add up to the total `power_loss`, the pull's own part
/// among them.
#[test]
fn the_power_losses_add_up_to_the_total() {
    let (m, mut fmu) = pull_contact();
    let parts: Vec<String> = variables(&m)
        .into_iter()
        .filter(|v| v.causality == Causality::Output && v.name.ends_with(".power_loss"))
        .map(|v| v.name)
        .collect();
    assert!(
        parts.contains(&"magnetic_pull.motor.power_loss".to_string()),
        "{parts:?}"
    );
    let mut seen_pull = false;
    for k in 0..20 {
        let status = fmu.do_step(k as f64 * 1e-3, 1e-3);
        assert!(
            matches!(status, Status::Ok | Status::Warning),
            "{:?}",
            texts(&mut fmu)
        );
        let total = get(&mut fmu, &m, "power_loss");
        let sum: f64 = parts.iter().map(|p| get(&mut fmu, &m, p)).sum();
        let pull = get(&mut fmu, &m, "magnetic_pull.motor.power_loss");
        seen_pull |= pull > 1.0 && get(&mut fmu, &m, "magnetic_pull.motor.contact_force") > 0.0;
        assert!(
            (sum - total).abs() <= 1e-12 * total.abs().max(1.0),
            "t = {} s: parts {sum} W, total {total} W",
            (k + 1) as f64 * 1e-3
        );
    }
    assert!(seen_pull, "the pull never touched its stator");
}

/// D5: the Jeffcott rotor at 3000 rpm with a port at node 2 pushed by
/// 1e5 N drives its left journal (contact stiffness 1e8 N/m) into the
/// bearing beyond the contact law's
/// range: that step returns fmi2Warning; rolled back (fmi2SetFMUstate, and
/// serialized into a fresh instance) and stepped again, it warns again,
/// with the same message and the same motion.
#[test]
fn a_contact_warning_is_raised_again_after_a_rollback() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/models/jeffcott.toml"
    ))
    .unwrap()
        + "\n[[rubs]]\nname = \"labyrinth\"\nnode = 5\ngap = 1e-4\ncontact_stiffness = 1e8\n\n[[ports]]\nname = \"push\"\nnode = 5\n";
    let m = RotorModel::from_toml(&text, "jeffcott_port.toml").unwrap();
    let begin = |name: &str| {
        let mut fmu = Instance::new(name, m.clone()).unwrap();
        set(&mut fmu, &m, "shaft.speed", 100.0 * RPM);
        assert_eq!(start(&mut fmu), Status::Ok, "{:?}", texts(&mut fmu));
        fmu
    };
    let contact = |fmu: &mut Instance| -> Vec<String> {
        texts(fmu)
            .into_iter()
            .filter(|t| t.contains("into its stator") || t.contains("contact force is"))
            .collect()
    };
    let mut fmu = begin("d5");
    set(&mut fmu, &m, "ports.push.fy", -1e5);
    let snap = fmu.snapshot().unwrap();
    let bytes = fmu.serialize(&snap).unwrap();
    let status = fmu.do_step(0.0, 0.02);
    assert_eq!(status, Status::Warning);
    let warned = contact(&mut fmu);
    assert!(!warned.is_empty());
    let force = get(&mut fmu, &m, "rubs.labyrinth.contact_force");
    // The same instance steps on without a second contact warning (once per
    // episode; the rub, 3.8 gaps deep, is still implausible).
    fmu.do_step(0.02, 0.02);
    assert!(contact(&mut fmu).is_empty());
    assert_eq!(fmu.restore(&snap), Status::Ok);
    assert_eq!(fmu.do_step(0.0, 0.02), Status::Warning);
    assert_eq!(contact(&mut fmu), warned);
    assert_eq!(get(&mut fmu, &m, "rubs.labyrinth.contact_force"), force);
    let mut fresh = begin("d5b");
    let snap = fresh.deserialize(&bytes).unwrap();
    assert_eq!(fresh.restore(&snap), Status::Ok);
    assert_eq!(fresh.do_step(0.0, 0.02), Status::Warning);
    assert_eq!(contact(&mut fresh), warned);
    assert_eq!(get(&mut fresh, &m, "rubs.labyrinth.contact_force"), force);
}

/// D6: `fmi2SetRealInputDerivatives` of order 2 (even 0.0) is accepted and
/// not used: the instance steps on exactly as without it.
#[test]
fn a_second_order_input_derivative_is_accepted_and_ignored() {
    let m = torque_ports();
    let mut runs = Vec::new();
    for second in [false, true] {
        let mut fmu = Instance::new("d6", m.clone()).unwrap();
        assert_eq!(start(&mut fmu), Status::Ok);
        let port = vr(&m, "ports.amb.fy");
        assert_eq!(fmu.set_input_derivative(port, 1, 100.0), Status::Ok);
        if second {
            assert_eq!(fmu.set_input_derivative(port, 2, 0.0), Status::Ok);
            assert_eq!(fmu.set_input_derivative(port, 2, 5e3), Status::Ok);
            assert_eq!(
                fmu.set_input_derivative(vr(&m, "torques.drive"), 3, 1.0),
                Status::Ok
            );
            assert!(
                texts(&mut fmu)
                    .iter()
                    .any(|t| t.contains("order 2 derivative"))
            );
        }
        assert_eq!(fmu.do_step(0.0, 0.01), Status::Ok, "{:?}", texts(&mut fmu));
        runs.push(get(&mut fmu, &m, "ports.amb.y"));
    }
    assert_eq!(runs[0].to_bits(), runs[1].to_bits());
    // Order 0 is no derivative: refused.
    let mut fmu = Instance::new("d6", m.clone()).unwrap();
    assert_eq!(start(&mut fmu), Status::Ok);
    assert_eq!(
        fmu.set_input_derivative(vr(&m, "ports.amb.fy"), 0, 1.0),
        Status::Error
    );
}

/// D7: force, port and torque inputs declare `±1000 g m` (N) and
/// `± J Ω_max / 1 ms` (N·m); 1e10 N is refused with the bound named; a
/// force within it that pushes a journal on linear bearings further than the
/// shaft's diameter returns fmi2Warning saying so, at initialization and at
/// every step that ends so.
#[test]
fn inputs_have_a_physical_range_and_implausible_displacements_warn() {
    let m = torque_ports();
    let force = 1000.0 * 9.80665 * m.total_mass();
    // The polar inertia in its closed form: shaft ρ π D⁴/32 L plus the disk's.
    let shaft = 7810.0 * std::f64::consts::PI * 0.05f64.powi(4) / 32.0 * 1.5;
    let disk = 7810.0 * std::f64::consts::PI * (0.28f64.powi(4) - 0.05f64.powi(4)) / 32.0 * 0.07;
    let torque = (shaft + disk) * m.max_speed / 1e-3;
    let close = |a: Option<f64>, b: f64| a.is_some_and(|a| (a - b).abs() <= 1e-12 * b.abs());
    for v in variables(&m) {
        let expected = match v.name.as_str() {
            "forces.thrust.fx" | "forces.thrust.fy" | "ports.amb.fx" | "ports.amb.fy" => {
                Some((-force, force))
            }
            "forces.blade_pass.magnitude" => Some((0.0, force)),
            "torques.drive" | "torques.load" => Some((-torque, torque)),
            _ => None,
        };
        if let Some((lo, hi)) = expected {
            let low = if lo == 0.0 {
                v.min == Some(0.0)
            } else {
                close(v.min, lo)
            };
            assert!(
                low && close(v.max, hi),
                "{}: {:?} {:?}",
                v.name,
                v.min,
                v.max
            );
        }
    }
    let mut fmu = Instance::new("d7", m.clone()).unwrap();
    assert_eq!(
        fmu.set(vr(&m, "forces.thrust.fy"), Kind::Real, 1e10),
        Status::Error
    );
    assert!(
        texts(&mut fmu)
            .iter()
            .any(|t| t.contains("above the declared maximum"))
    );
    // Within the bound, but 0.4 MN on 1e6 N/m bearings: decimetres.
    let mut fmu = Instance::new("d7", m.clone()).unwrap();
    set(&mut fmu, &m, "forces.thrust.fy", -4e5);
    assert_eq!(start(&mut fmu), Status::Warning);
    let text = texts(&mut fmu).join("\n");
    assert!(
        text.contains("no machine moves so") && text.contains("outer diameter"),
        "{text}"
    );
    assert_eq!(fmu.do_step(0.0, 0.01), Status::Warning);
    assert!(
        texts(&mut fmu)
            .iter()
            .any(|t| t.contains("no machine moves so"))
    );
    // A model file with such a force is refused, naming the field.
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/torque_ports.toml"
    ))
    .unwrap()
    .replace("fy = -100.0", "fy = -1e10");
    let e = RotorModel::from_toml(&text, "big.toml")
        .unwrap_err()
        .to_string();
    assert!(e.contains("forces[0].fy") && e.contains("1000 g"), "{e}");
    // The shipped models stay plausible at initialization.
    for name in [
        "hydro_unit",
        "hydro_unit_brackets",
        "hydro_unit_torque",
        "jeffcott",
    ] {
        let m = model(name);
        let mut fmu = Instance::new(name, m).unwrap();
        assert_eq!(start(&mut fmu), Status::Ok, "{name}: {:?}", texts(&mut fmu));
    }
}

/// Static forces reach the statics of a linear model: a 4 m, 80 mm steel
/// shaft on two stiff linear bearings (1e9 N/m) with a static 1000 N at
/// mid-span, gravity off, deflects there by the Timoshenko beam's closed form
/// `F L³/(48 E I) + F L/(4 κ G A)` plus the bearings' `F/(2k)` (the
/// two-node elements are exact at their nodes for point loads), and each
/// bearing carries 500 N in the operating point.
#[test]
fn static_forces_load_the_statics_of_a_linear_model() {
    use rotor_bearing::analysis::linear::static_deflection;
    use rotor_bearing::analysis::operating_point::operating_point;
    use rotor_bearing::rotor::Rotor;
    let text = r#"
name = "beam"
gravity = [0.0, 0.0, 0.0]
[[materials]]
name = "steel"
youngs_modulus = 211e9
shear_modulus = 81.2e9
density = 7810.0
[[shaft]]
length = 4.0
outer_diameter = 0.08
material = "steel"
elements = 8
[[bearings]]
name = "a"
type = "linear"
node = 1
kxx = 1e9
kyy = 1e9
[[bearings]]
name = "b"
type = "linear"
node = 9
kxx = 1e9
kyy = 1e9
[[forces]]
name = "load"
node = 5
fy = 1000.0
"#;
    let m = RotorModel::from_toml(text, "beam.toml").unwrap();
    let rotor = Rotor::new(m.clone()).unwrap();
    let q = static_deflection(&rotor).unwrap();
    let (f, l, e, g, d): (f64, f64, f64, f64, f64) = (1000.0, 4.0, 211e9, 81.2e9, 0.08);
    let (i, a) = (
        std::f64::consts::PI * d.powi(4) / 64.0,
        std::f64::consts::PI * d * d / 4.0,
    );
    let nu = e / (2.0 * g) - 1.0;
    let kappa = 6.0 * (1.0 + nu) / (7.0 + 6.0 * nu);
    let expected = f * l.powi(3) / (48.0 * e * i) + f * l / (4.0 * kappa * g * a) + f / (2.0 * 1e9);
    let mid = q[4 * 4 + 1];
    assert!(
        (mid - expected).abs() <= 1e-9 * expected,
        "mid-span {mid} m against {expected} m"
    );
    for point in operating_point(&rotor, 0.0).unwrap() {
        assert!(
            (point.load - 500.0).abs() <= 1e-9 * 500.0,
            "{}: {} N",
            point.name,
            point.load
        );
    }
}

/// A one-row coefficient table at 3000 rpm covers 3000 rpm however a front
/// end converted it to rad/s (`rpm π/30` in the model, `rpm / (60/2π)` in
/// the CLI differ by an ulp): no "outside its coefficient table" warning at
/// its own speed; one at 3100 rpm.
#[test]
fn a_one_row_table_covers_its_own_speed() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/models/jeffcott.toml"
    ))
    .unwrap()
        + "\n[[seals]]\nname = \"wear_ring\"\nnode = 5\nspeeds_rpm = [3000]\nkxx = 1e5\nkyy = 1e5\nkxy = 2e4\nkyx = -2e4\n";
    let m = RotorModel::from_toml(&text, "one_row.toml").unwrap();
    let by_cli = 3000.0 / rotor_bearing::units::RAD_S_TO_RPM;
    let by_model = 3000.0 * std::f64::consts::PI / 30.0;
    assert_ne!(by_cli.to_bits(), by_model.to_bits());
    assert!(m.table_speed_warnings(&[by_cli, by_model]).is_empty());
    let off = m.table_speed_warnings(&[3100.0 / rotor_bearing::units::RAD_S_TO_RPM]);
    assert_eq!(off.len(), 1);
    assert!(
        off[0].to_string().contains("(3000 to 3000 rpm)"),
        "{}",
        off[0]
    );
}
