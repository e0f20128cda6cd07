//! The FMU's loads and drive: the magnetic pull's excitation (tunable, in
//! the FMU state), the force and port inputs with their derivatives, the
//! ports' motion, the power losses, and the torque-driven shaft (initial
//! speed, torque inputs, node speeds and element torques). Appended after
//! every earlier variable; their values equal the simulator's bit for bit,
//! and the torque-driven speed follows the rigid shaft's closed form.

use rotor_bearing::fmi2::instance::{Instance, Status};
use rotor_bearing::fmi2::variables::{Binding, Causality, Kind, Variability, Variable, variables};
use rotor_bearing::model::{DEFAULT_MODEL_TOML, RotorModel};
use rotor_bearing::rotor::Rotor;
use rotor_bearing::rotor::torsion::TorsionalRotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

#[path = "common/fmu.rs"]
mod fmu;
use fmu::{model, vr};

const RPM: f64 = std::f64::consts::PI / 30.0;

/// The hydro unit on its brackets (magnetic pull, vortex rope, radial
/// thrust) with a force port at the lower guide's node for an active bearing.
fn brackets_with_port() -> RotorModel {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/models/hydro_unit_brackets.toml"
    );
    let text = std::fs::read_to_string(path).unwrap() + "\n[[ports]]\nname = \"amb\"\nnode = 9\n";
    RotorModel::from_toml(&text, "brackets_port.toml").unwrap()
}

/// The damped classic rotor, torque-driven at both ends (`drive` at node 1,
/// `load` at node 7) with every element stiffened to 1e12 N·m/rad by a
/// coupling: a torsionally rigid shaft.
fn torque_driven_classic() -> RotorModel {
    let mut text = DEFAULT_MODEL_TOML
        .replace("kyy = 1e6\n", "kyy = 1e6\ncxx = 800.0\ncyy = 800.0\n")
        + "\n[torsion]\ndrive = \"torque\"\n[[torques]]\nname = \"drive\"\nnode = 1\n[[torques]]\nname = \"load\"\nnode = 7\n";
    for node in 1..=6 {
        text += &format!("[[couplings]]\nnode = {node}\ntorsional_stiffness = 1e12\n");
    }
    RotorModel::from_toml(&text, "torque.toml").unwrap()
}

fn start(fmu: &mut Instance) {
    assert_eq!(fmu.setup_experiment(0.0, None), Status::Ok);
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    assert_eq!(
        fmu.exit_initialization_mode(),
        Status::Ok,
        "{:?}",
        fmu.drain_messages()
    );
}

fn get(fmu: &mut Instance, m: &RotorModel, name: &str) -> f64 {
    fmu.get(vr(m, name), Kind::Real)
        .unwrap_or_else(|s| panic!("{name}: {s:?} {:?}", fmu.drain_messages()))
}

/// After the housings come the pull's excitation, the force and port
/// inputs (in the order of `RotorModel::load_inputs`, starting at the model
/// file's values), the ports' motion, the pull's forces and the power
/// losses, the step control, then the seals' and the pull's power losses;
/// the variables before them are those of the model without pull, forces
/// and ports. A model with none of these gains only its power losses.
#[test]
fn load_variables_are_appended_in_channel_order() {
    let m = brackets_with_port();
    let vars = variables(&m);
    let mut bare = m.clone();
    bare.bearings.retain(|b| !b.kind.is_magnetic_pull());
    bare.forces.clear();
    bare.ports.clear();
    let old = variables(&bare);
    let first = vr(&m, "magnetic_pull.generator.excitation") as usize;
    assert_eq!(
        vars[first - 1].name,
        "seals.runner_seal.housing_vy",
        "appended after the housings"
    );
    for (a, b) in old[..first].iter().zip(&vars) {
        assert_eq!(
            (a.name.as_str(), a.value_reference),
            (b.name.as_str(), b.value_reference)
        );
    }
    let names: Vec<&str> = vars[first..].iter().map(|v| v.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "magnetic_pull.generator.excitation",
            "forces.vortex_rope.magnitude",
            "forces.hydraulic_thrust.fx",
            "forces.hydraulic_thrust.fy",
            "ports.amb.fx",
            "ports.amb.fy",
            "ports.amb.x",
            "ports.amb.y",
            "ports.amb.vx",
            "ports.amb.vy",
            "magnetic_pull.generator.fx",
            "magnetic_pull.generator.fy",
            "magnetic_pull.generator.contact_force",
            "bearings.upper_guide.power_loss",
            "bearings.lower_guide.power_loss",
            "bearings.turbine_guide.power_loss",
            "power_loss",
            "solver.local_error_tolerance",
            "seals.runner_seal.power_loss",
            "magnetic_pull.generator.power_loss",
            "bearings.upper_guide.offset_x",
            "bearings.upper_guide.offset_y",
            "bearings.lower_guide.offset_x",
            "bearings.lower_guide.offset_y",
            "bearings.turbine_guide.offset_x",
            "bearings.turbine_guide.offset_y",
            "seals.runner_seal.offset_x",
            "seals.runner_seal.offset_y",
            "magnetic_pull.generator.offset_x",
            "magnetic_pull.generator.offset_y",
            "magnetic_pull.generator.dynamic_eccentricity",
            "bearings.upper_guide.static_fx",
            "bearings.upper_guide.static_fy",
            "bearings.upper_guide.dynamic_fx",
            "bearings.upper_guide.dynamic_fy",
            "bearings.upper_guide.dynamic_load",
            "bearings.lower_guide.static_fx",
            "bearings.lower_guide.static_fy",
            "bearings.lower_guide.dynamic_fx",
            "bearings.lower_guide.dynamic_fy",
            "bearings.lower_guide.dynamic_load",
            "bearings.turbine_guide.static_fx",
            "bearings.turbine_guide.static_fy",
            "bearings.turbine_guide.dynamic_fx",
            "bearings.turbine_guide.dynamic_fy",
            "bearings.turbine_guide.dynamic_load",
            "forces.vortex_rope.ratio",
        ]
    );
    let channels = m.load_inputs();
    for v in &vars {
        if let Binding::Load(i) = v.binding {
            assert_eq!(v.name, channels[i].name);
            assert_eq!(v.start, Some(channels[i].start));
            let unit = if v.name.ends_with(".dynamic_eccentricity") {
                "m"
            } else {
                "N"
            };
            assert_eq!((v.causality, v.unit), (Causality::Input, Some(unit)));
        }
    }
    let excitation = &vars[first];
    assert_eq!(
        (excitation.causality, excitation.variability),
        (Causality::Parameter, Variability::Tunable)
    );
    assert_eq!(
        (excitation.start, excitation.min, excitation.max),
        (Some(0.0), Some(0.0), Some(2.0))
    );
    for v in vars[first + 6..].iter().filter(|v| {
        v.name != "solver.local_error_tolerance"
            && !matches!(v.binding, Binding::ForceFrequency(_))
            && !is_offset(v)
            && !v.name.ends_with(".dynamic_eccentricity")
    }) {
        let want = match v.name.rsplit('.').next().unwrap() {
            "x" | "y" => "m",
            "vx" | "vy" => "m/s",
            "power_loss" => "W",
            // The bearings' static and dynamic loads (issue 49), appended last.
            _ => "N",
        };
        assert_eq!(
            (v.causality, v.unit),
            (Causality::Output, Some(want)),
            "{}",
            v.name
        );
    }
    // The classic rotor: nothing but its two bearings' losses and the total.
    let classic = RotorModel::default_model();
    let names: Vec<String> = variables(&classic)
        .into_iter()
        .skip(vr(&classic, "solver.reduced_modes") as usize + 1)
        .map(|v| v.name)
        .collect();
    assert_eq!(
        names,
        [
            "bearings.drive_end.power_loss",
            "bearings.non_drive_end.power_loss",
            "power_loss",
            "solver.local_error_tolerance",
            "bearings.drive_end.offset_x",
            "bearings.drive_end.offset_y",
            "bearings.non_drive_end.offset_x",
            "bearings.non_drive_end.offset_y",
            "bearings.drive_end.static_fx",
            "bearings.drive_end.static_fy",
            "bearings.drive_end.dynamic_fx",
            "bearings.drive_end.dynamic_fy",
            "bearings.drive_end.dynamic_load",
            "bearings.non_drive_end.static_fx",
            "bearings.non_drive_end.static_fy",
            "bearings.non_drive_end.dynamic_fx",
            "bearings.non_drive_end.dynamic_fy",
            "bearings.non_drive_end.dynamic_load",
        ]
    );
}

/// The bearings' offset parameters (issue 49), appended after every other
/// variable.
fn is_offset(v: &Variable) -> bool {
    matches!(v.binding, Binding::OffsetX(_) | Binding::OffsetY(_))
}

/// The bearings' static and dynamic loads (issue 49), appended after every
/// other variable but the harmonic forces' frequencies (issue 48).
fn is_bearing_load(v: &Variable) -> bool {
    matches!(
        v.binding,
        Binding::StaticFx(_)
            | Binding::StaticFy(_)
            | Binding::DynamicFx(_)
            | Binding::DynamicFy(_)
            | Binding::DynamicLoad(_)
    )
}

/// The hydro unit on brackets at 300 rpm: the FMU's force, port and
/// excitation inputs (set between steps, with input derivatives) give the
/// simulator's run with the same loads, in the ports' motion, the pull's
/// forces and the power losses, to 1e-11 of each output's largest value
/// (bit for bit until the ramped port force; then the last bits part and
/// grow to 1e-12 at most, measured 9.7e-13 in the port velocity); with the
/// field off the pull vanishes.
#[test]
fn load_inputs_give_the_simulators_run() {
    let m = brackets_with_port();
    let mut fmu = Instance::new("loads", m.clone()).unwrap();
    let speed = 300.0 * RPM;
    assert_eq!(
        fmu.set(vr(&m, "shaft.speed"), Kind::Real, speed),
        Status::Ok
    );
    start(&mut fmu);
    // Built as the FMU builds its simulator: default options, then its own.
    let mut sim = Simulator::new(Rotor::new(m.clone()).unwrap(), SolverOptions::default()).unwrap();
    sim.set_options(SolverOptions {
        time_step: rotor_bearing::fmi2::variables::default_fmu_time_step(&m),
        local_error_tolerance: rotor_bearing::fmi2::variables::DEFAULT_LOCAL_ERROR_TOLERANCE,
        ..SolverOptions::default()
    })
    .unwrap();
    sim.set_speed(speed, 0.0).unwrap();
    sim.settle_static().unwrap();
    let channel = |name: &str| m.load_inputs().iter().position(|c| c.name == name).unwrap();
    let pull = m
        .bearings
        .iter()
        .position(|b| b.kind.is_magnetic_pull())
        .unwrap();
    // Largest difference and largest value of each output over the run.
    let mut series = std::collections::BTreeMap::<&str, (f64, f64)>::new();
    for step in 0..60 {
        let t = step as f64 * 0.01;
        // (input, value, rate) set at this step.
        let loads: &[(&str, f64, f64)] = match step {
            5 => &[
                ("forces.vortex_rope.magnitude", 2e4, 0.0),
                ("forces.hydraulic_thrust.fx", 0.0, 2e5),
            ],
            25 => &[("ports.amb.fx", 1e4, 0.0), ("ports.amb.fy", -5e3, -1e5)],
            _ => &[],
        };
        for &(name, value, rate) in loads {
            assert_eq!(fmu.set(vr(&m, name), Kind::Real, value), Status::Ok);
            if rate != 0.0 {
                assert_eq!(fmu.set_input_derivative(vr(&m, name), 1, rate), Status::Ok);
            }
            sim.set_load(channel(name), value, rate).unwrap();
        }
        // The field on (the unit synchronized) at once, off again at 0.4 s.
        if step == 0 || step == 40 {
            let field = if step == 0 { 1.0 } else { 0.0 };
            let e = vr(&m, "magnetic_pull.generator.excitation");
            assert_eq!(fmu.set(e, Kind::Real, field), Status::Ok);
            sim.set_excitation(pull, field).unwrap();
        }
        assert_eq!(
            fmu.do_step(t, 0.01),
            Status::Ok,
            "{:?}",
            fmu.drain_messages()
        );
        sim.advance_to(t + 0.01).unwrap();
        let out = sim.outputs().unwrap();
        let port = &out.ports[0];
        for (name, want) in [
            ("ports.amb.x", port.x),
            ("ports.amb.y", port.y),
            ("ports.amb.vx", port.vx),
            ("ports.amb.vy", port.vy),
            ("magnetic_pull.generator.fx", out.bearings[pull].fx),
            ("magnetic_pull.generator.fy", out.bearings[pull].fy),
            (
                "bearings.upper_guide.power_loss",
                out.bearings[0].report.power_loss,
            ),
            ("power_loss", out.power_loss),
            (
                "forces.hydraulic_thrust.fx",
                sim.load_at(channel("forces.hydraulic_thrust.fx"), t + 0.01),
            ),
        ] {
            let got = get(&mut fmu, &m, name);
            let (worst, largest) = series.entry(name).or_insert((0.0, 0.0));
            *worst = f64::max(*worst, (got - want).abs());
            *largest = f64::max(*largest, want.abs());
        }
        let pull_fx = get(&mut fmu, &m, "magnetic_pull.generator.fx");
        if step >= 40 {
            assert_eq!(pull_fx, 0.0);
            assert_eq!(get(&mut fmu, &m, "magnetic_pull.generator.fy"), 0.0);
        } else if step > 5 {
            assert!(pull_fx != 0.0, "the field pulls at {} s", t + 0.01);
        }
    }
    for (name, (worst, largest)) in series {
        assert!(
            worst <= 1e-11 * largest,
            "{name}: {worst:e} off, largest {largest:e}"
        );
    }
    // The port force ramps: 1e4 N held, −5e3 N falling at 1e5 N/s for 0.35 s.
    let fy = get(&mut fmu, &m, "ports.amb.fy");
    assert!((fy - (-5e3 - 1e5 * 0.35)).abs() < 1e-6, "{fy}");
    // The rotor moves under the port force.
    assert!(get(&mut fmu, &m, "ports.amb.x").abs() > 1e-7);
}

/// A state saved with the field at half excitation comes back with it: the
/// run continued from the restored state repeats the first continuation
/// bit for bit, and the parameter reads 0.5 again.
#[test]
fn the_excitation_is_part_of_the_fmu_state() {
    let m = model("hydro_unit_brackets");
    let e = vr(&m, "magnetic_pull.generator.excitation");
    let mut fmu = Instance::new("state", m.clone()).unwrap();
    assert_eq!(
        fmu.set(vr(&m, "shaft.speed"), Kind::Real, 300.0 * RPM),
        Status::Ok
    );
    start(&mut fmu);
    assert_eq!(fmu.set(e, Kind::Real, 0.5), Status::Ok);
    assert_eq!(fmu.do_step(0.0, 0.01), Status::Ok);
    let saved = fmu.snapshot().unwrap();
    let bytes = fmu.serialize(&saved).unwrap();
    let run = |fmu: &mut Instance, t: f64| {
        assert_eq!(fmu.do_step(t, 0.02), Status::Ok);
        get(fmu, &m, "magnetic_pull.generator.fx")
    };
    let first = run(&mut fmu, 0.01);
    let restored = fmu.deserialize(&bytes).unwrap();
    assert_eq!(fmu.restore(&restored), Status::Ok);
    assert_eq!(fmu.set(e, Kind::Real, 1.5), Status::Ok);
    assert_ne!(run(&mut fmu, 0.01), first);
    assert_eq!(fmu.restore(&restored), Status::Ok);
    assert_eq!(fmu.get(e, Kind::Real), Ok(0.5));
    assert_eq!(run(&mut fmu, 0.01), first);
    // Beyond the declared range: refused by name.
    assert_eq!(fmu.set(e, Kind::Real, 3.0), Status::Error);
    let text = fmu.drain_messages().pop().unwrap().2;
    assert!(
        text.contains("magnetic_pull.generator.excitation = 3: above the declared maximum 2"),
        "{text}"
    );
}

/// The power each bearing dissipates is its friction torque times the spin
/// speed while no journal touches (the hydro unit's tilting pads at 150
/// rpm), and the total is the sum.
#[test]
fn power_loss_is_friction_torque_times_speed() {
    let m = model("hydro_unit");
    let mut fmu = Instance::new("power", m.clone()).unwrap();
    let speed = 150.0 * RPM;
    assert_eq!(
        fmu.set(vr(&m, "shaft.speed"), Kind::Real, speed),
        Status::Ok
    );
    start(&mut fmu);
    assert_eq!(fmu.do_step(0.0, 0.2), Status::Ok);
    let mut total = 0.0;
    for b in ["generator_guide", "turbine_guide"] {
        let loss = get(&mut fmu, &m, &format!("bearings.{b}.power_loss"));
        let torque = get(&mut fmu, &m, &format!("bearings.{b}.friction_torque"));
        assert_eq!(
            get(&mut fmu, &m, &format!("bearings.{b}.contact_force")),
            0.0
        );
        assert!(loss > 0.0, "{b}: {loss} W");
        assert!(
            (loss - torque * speed).abs() < 1e-12 * loss,
            "{b}: {loss} W vs {torque} N·m"
        );
        total += loss;
    }
    let sum = get(&mut fmu, &m, "power_loss");
    assert!((sum - total).abs() < 1e-12 * total, "{sum} vs {total}");
}

/// A torque-driven shaft: `shaft.speed` (same value reference) is the output
/// of its mean speed, `shaft.initial_speed` the fixed parameter it starts
/// from, `torques.<t>` the inputs. Driven by 20 N·m against −5 N·m from
/// 100 rad/s, the rigid shaft (no unbalance, frictionless linear bearings)
/// accelerates as the net torque over its polar inertia, to 1e-9; every
/// node turns at that speed; the FMU equals the simulator bit for bit.
#[test]
fn a_torque_driven_fmu_accelerates_as_its_net_torque_over_its_inertia() {
    let mut m = torque_driven_classic();
    m.unbalances.clear();
    let speed_mode = {
        let mut s = m.clone();
        s.drive = rotor_bearing::model::Drive::Speed;
        s.torques.clear();
        variables(&s)
            .into_iter()
            .filter(|v| !is_offset(v) && !is_bearing_load(v))
            .collect::<Vec<_>>()
    };
    let vars = variables(&m);
    // Every variable before the step control (appended last of all, after
    // the drive's) keeps its value reference.
    let before_step_control = speed_mode.len() - 1;
    assert_eq!(
        speed_mode[before_step_control].name,
        "solver.local_error_tolerance"
    );
    for (a, b) in speed_mode[..before_step_control].iter().zip(&vars) {
        assert_eq!((&a.name, a.value_reference), (&b.name, b.value_reference));
    }
    let speed = &vars[vr(&m, "shaft.speed") as usize];
    assert_eq!((speed.causality, speed.start), (Causality::Output, None));
    let inertia = TorsionalRotor::new(&m).total_inertia();
    let mut fmu = Instance::new("torque", m.clone()).unwrap();
    assert_eq!(
        fmu.set(vr(&m, "shaft.initial_speed"), Kind::Real, 100.0),
        Status::Ok
    );
    start(&mut fmu);
    assert_eq!(get(&mut fmu, &m, "shaft.speed"), 100.0);
    let mut sim = Simulator::new(
        Rotor::new(m.clone()).unwrap(),
        SolverOptions {
            time_step: rotor_bearing::fmi2::variables::default_fmu_time_step(&m),
            local_error_tolerance: rotor_bearing::fmi2::variables::DEFAULT_LOCAL_ERROR_TOLERANCE,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    sim.set_speed(100.0, 0.0).unwrap();
    sim.settle_static().unwrap();
    let first = m.first_torque_input();
    // Ramped in over 50 ms (a step torque would ring the stiff couplings).
    for (name, k, rate) in [("torques.drive", 0, 400.0), ("torques.load", 1, -100.0)] {
        assert_eq!(fmu.set_input_derivative(vr(&m, name), 1, rate), Status::Ok);
        sim.set_load(first + k, 0.0, rate).unwrap();
    }
    let h = 0.01;
    for step in 0..30 {
        let t = step as f64 * h;
        if step == 5 {
            for (name, k, value) in [("torques.drive", 0, 20.0), ("torques.load", 1, -5.0)] {
                assert_eq!(fmu.set(vr(&m, name), Kind::Real, value), Status::Ok);
                assert_eq!(fmu.set_input_derivative(vr(&m, name), 1, 0.0), Status::Ok);
                sim.set_load(first + k, value, 0.0).unwrap();
            }
        }
        assert_eq!(fmu.do_step(t, h), Status::Ok, "{:?}", fmu.drain_messages());
        sim.advance_to(t + h).unwrap();
        let out = sim.outputs().unwrap();
        assert_eq!(get(&mut fmu, &m, "shaft.speed"), out.speed);
        assert_eq!(
            get(&mut fmu, &m, "torques.drive.speed"),
            out.torques[0].speed
        );
        assert_eq!(
            get(&mut fmu, &m, "torques.load.angle"),
            out.torques[1].angle
        );
        assert_eq!(get(&mut fmu, &m, "shaft.torque[3]"), out.shaft_torques[2]);
    }
    let mut other = Instance::new("torque", m.clone()).unwrap();
    assert_eq!(
        other.set(vr(&m, "shaft.speed"), Kind::Real, 5.0),
        Status::Error
    );
    let text = other.drain_messages().pop().unwrap().2;
    assert!(text.contains("shaft.speed is an output"), "{text}");
    // 15 N·m net, ramped over the first 50 ms (mean 7.5 N·m there).
    let t = 0.3;
    let want = 100.0 + (15.0 * (t - 0.05) + 7.5 * 0.05) / inertia;
    for name in ["shaft.speed", "torques.drive.speed", "torques.load.speed"] {
        let w = get(&mut fmu, &m, name);
        assert!(
            (w - want).abs() < 1e-9 * want,
            "{name}: {w} vs {want} rad/s"
        );
    }
}

/// A non-finite port force, force magnitude or torque is refused with
/// fmi2Error naming the variable (and the state machine says so).
#[test]
fn non_finite_load_inputs_are_errors() {
    for (m, name) in [
        (brackets_with_port(), "ports.amb.fx"),
        (brackets_with_port(), "forces.vortex_rope.magnitude"),
        (torque_driven_classic(), "torques.drive"),
    ] {
        for bad in [f64::NAN, f64::INFINITY] {
            let mut fmu = Instance::new("nan", m.clone()).unwrap();
            assert_eq!(fmu.set(vr(&m, name), Kind::Real, bad), Status::Error);
            let text = fmu.drain_messages().pop().unwrap().2;
            assert!(
                text.contains(&format!("{name} = ")) && text.contains("is not finite"),
                "{text}"
            );
        }
    }
}

/// A harmonic force's frequency is tunable (issue 48: the vortex rope's
/// ratio from the plant): `forces.vortex_rope.ratio` set to 0.27 at
/// t = 0.05 s turns the rope (2e4 N, part load) at 0.27 × the running speed from there, its
/// angle going on without a jump. Truth: a second FMU whose model file has
/// the ratio 0.27 and the phase `φ₀ + (0.3 − 0.27) φ_c` (`φ_c` the spin
/// angle at the change), both with the rope's amplitude held at 0 until the
/// change (so that the two runs are the same until then): the runs agree
/// bit for bit afterwards, in every output. The ratio is in the FMU state
/// (a rollback brings back the old one, and the run repeats bit for bit),
/// reads back as set, and a value beyond its declared range is refused.
#[test]
fn a_harmonic_forces_ratio_is_tunable_without_a_jump() {
    use rotor_bearing::model::{ForceKind, HarmonicFrequency};
    let m = model("hydro_unit_brackets");
    let rope = m
        .forces
        .iter()
        .position(|f| f.name == "vortex_rope")
        .unwrap();
    let ForceKind::Harmonic {
        magnitude,
        phase,
        frequency: HarmonicFrequency::Ratio(r0),
        ..
    } = m.forces[rope].kind
    else {
        panic!("the vortex rope is a harmonic force with a ratio")
    };
    assert_eq!((r0, magnitude), (0.3, 0.0));
    // Part load (the model file's comment): the rope at 2e4 N.
    let magnitude = 2e4;
    let ratio = vr(&m, "forces.vortex_rope.ratio");
    let amplitude = vr(&m, "forces.vortex_rope.magnitude");
    let outputs: Vec<u32> = variables(&m)
        .iter()
        .filter(|v| v.causality == Causality::Output && v.kind == Kind::Real)
        .map(|v| v.value_reference)
        .collect();
    let begin = |model: &RotorModel, name: &str| {
        let mut fmu = Instance::new(name, model.clone()).unwrap();
        assert_eq!(
            fmu.set(vr(model, "shaft.speed"), Kind::Real, 300.0 * RPM),
            Status::Ok
        );
        assert_eq!(fmu.set(amplitude, Kind::Real, 0.0), Status::Ok);
        start(&mut fmu);
        fmu
    };
    let trace = |fmu: &mut Instance, from: usize, to: usize| {
        let mut values = Vec::new();
        for k in from..to {
            assert_eq!(fmu.do_step(k as f64 * 5e-3, 5e-3), Status::Ok);
            values.extend(
                outputs
                    .iter()
                    .map(|&r| fmu.get(r, Kind::Real).unwrap().to_bits()),
            );
        }
        values
    };
    let mut a = begin(&m, "tuned");
    assert_eq!(a.get(ratio, Kind::Real), Ok(0.3));
    trace(&mut a, 0, 10);
    let spin = a.get(vr(&m, "shaft.spin_angle"), Kind::Real).unwrap();
    assert!(spin > 1.0, "{spin}");
    let saved = a.snapshot().unwrap();
    assert_eq!(a.set(ratio, Kind::Real, 0.27), Status::Ok);
    assert_eq!(a.get(ratio, Kind::Real), Ok(0.27));
    assert_eq!(a.set(amplitude, Kind::Real, magnitude), Status::Ok);
    let tuned = trace(&mut a, 10, 60);

    let mut shifted = m.clone();
    if let ForceKind::Harmonic {
        phase: p,
        frequency: f,
        ..
    } = &mut shifted.forces[rope].kind
    {
        *p = phase + (r0 - 0.27) * spin;
        *f = HarmonicFrequency::Ratio(0.27);
    }
    let mut b = begin(&shifted, "shifted");
    let before_b = trace(&mut b, 0, 10);
    assert_eq!(b.set(amplitude, Kind::Real, magnitude), Status::Ok);
    assert!(
        tuned == trace(&mut b, 10, 60),
        "the tuned ratio is not the shifted model's"
    );
    assert!(!before_b.is_empty());

    // The old ratio comes back with the state, and the run repeats.
    assert_eq!(a.restore(&saved), Status::Ok);
    assert_eq!(a.get(ratio, Kind::Real), Ok(0.3));
    let bytes = a.serialize(&saved).unwrap();
    assert_eq!(a.set(amplitude, Kind::Real, magnitude), Status::Ok);
    let untuned = trace(&mut a, 10, 60);
    assert!(untuned != tuned);
    let restored = a.deserialize(&bytes).unwrap();
    assert_eq!(a.restore(&restored), Status::Ok);
    assert_eq!(a.set(amplitude, Kind::Real, magnitude), Status::Ok);
    assert!(
        trace(&mut a, 10, 60) == untuned,
        "the serialized state's run differs"
    );
    // Beyond the declared range: refused by name.
    assert_eq!(a.set(ratio, Kind::Real, 2000.0), Status::Error);
    let text = a.drain_messages().pop().unwrap().2;
    assert!(text.contains("forces.vortex_rope.ratio = 2000"), "{text}");
}
