//! A magnetic pull's dynamic (rotating) eccentricity (issue 48, acceptance
//! 3): the 1× force `k s² e_d` it adds turns with the shaft and equals a
//! `[[forces]]` 1× forward force of that magnitude and phase in a transient,
//! on the rotor and in the pull's force output; the FMU takes it as an input
//! that switches it on during a run; bad values are errors naming the field.

use rotor_bearing::fmi2::instance::{Instance, Status};
use rotor_bearing::fmi2::variables::{Causality, Kind, variables};
use rotor_bearing::model::{DEFAULT_MODEL_TOML, RotorModel};
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

#[path = "common/fmu.rs"]
#[allow(dead_code)] // only `vr` is used here
mod fmu;
use fmu::vr;

const RPM: f64 = std::f64::consts::PI / 30.0;

/// The damped classic rotor with a generator pull at the disk (node 4):
/// `k` 2e5 N/m at nominal field, excitation 0.8, an air gap of 1 m so wide
/// that the pull's law is linear to 1e-12 over the orbit (the rotating part
/// is its first-order term), and `extra` keys on the pull.
fn classic_with_pull(pull_keys: &str, extra: &str) -> RotorModel {
    let text = DEFAULT_MODEL_TOML
        .replace("kyy = 1e6\n", "kyy = 1e6\ncxx = 4000.0\ncyy = 4000.0\n")
        .replace("magnitude = 0.001", "magnitude = 0.0")
        + &format!(
            "\n[[magnetic_pull]]\nname = \"generator\"\nnode = 4\ngap = 1.0\nstiffness = 2e5\nexcitation = 0.8\n{pull_keys}\n{extra}"
        );
    RotorModel::from_toml(&text, "pull.toml").unwrap()
}

/// (disk x, disk y, pull fx, pull fy) every 2 ms over 0.3 s at 3000 rpm.
fn run(model: RotorModel) -> Vec<[f64; 4]> {
    let mut sim = Simulator::new(
        Rotor::new(model).unwrap(),
        SolverOptions {
            time_step: 1e-4,
            gravity: false,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    sim.set_speed(3000.0 * RPM, 0.0).unwrap();
    (1..=150)
        .map(|k| {
            sim.advance_to(2e-3 * k as f64).unwrap();
            let out = sim.outputs().unwrap();
            let pull = out.bearings.len() - 1;
            [
                out.probes[0].x,
                out.probes[0].y,
                out.bearings[pull].fx,
                out.bearings[pull].fy,
            ]
        })
        .collect()
}

/// `e_d` = 0.1 mm at 30°: the disk's transient equals that of the same
/// rotor with a 1× forward `[[forces]]` entry of `k s² e_d` = 12.8 N at
/// phase 30° to 1e-9 of the orbit, and the pull's output force exceeds the
/// plain pull's by exactly that rotating force (1e-9 of it).
#[test]
fn the_rotating_pull_is_a_synchronous_forward_force_of_k_s2_e_d() {
    let eccentric = run(classic_with_pull(
        "dynamic_eccentricity = 1e-4\ndynamic_phase_deg = 30.0",
        "",
    ));
    let magnitude = 2e5 * 0.8 * 0.8 * 1e-4;
    let forced = run(classic_with_pull(
        "",
        &format!(
            "[[forces]]\nname = \"rim\"\nnode = 4\nmagnitude = {magnitude:e}\nphase_deg = 30.0\nratio = 1.0\ndirection = \"forward\"\n"
        ),
    ));
    let orbit = eccentric
        .iter()
        .map(|r| r[0].hypot(r[1]))
        .fold(0.0, f64::max);
    assert!(
        orbit > 1e-6,
        "the rotating pull drives the disk: {orbit:e} m"
    );
    let spin = |k: usize| 3000.0 * RPM * 2e-3 * (k + 1) as f64;
    for (k, (a, b)) in eccentric.iter().zip(&forced).enumerate() {
        for i in 0..2 {
            assert!(
                (a[i] - b[i]).abs() < 1e-9 * orbit,
                "step {k}: disk {i} {} against {}",
                a[i],
                b[i]
            );
        }
        let theta = spin(k) + 30f64.to_radians();
        let (fx, fy) = (magnitude * theta.cos(), magnitude * theta.sin());
        assert!((a[2] - b[2] - fx).abs() < 1e-9 * magnitude, "step {k}: fx");
        assert!((a[3] - b[3] - fy).abs() < 1e-9 * magnitude, "step {k}: fy");
    }
}

/// The FMU: `magnetic_pull.generator.dynamic_eccentricity` is an input in
/// metres from 0 to the air gap, starting at the model file's value;
/// switched on after 0.1 s it gives the simulator's run with the same
/// eccentricity set at that time (to 1e-11: the last bits of the step's
/// start time part); above the gap it is refused by name.
#[test]
fn the_fmu_takes_the_dynamic_eccentricity_as_an_input() {
    let m = classic_with_pull("", "");
    let name = "magnetic_pull.generator.dynamic_eccentricity";
    let var = variables(&m).into_iter().find(|v| v.name == name).unwrap();
    assert_eq!(
        (var.causality, var.unit, var.start, var.min, var.max),
        (Causality::Input, Some("m"), Some(0.0), Some(0.0), Some(1.0))
    );
    let speed = 3000.0 * RPM;
    let mut fmu = Instance::new("pull", m.clone()).unwrap();
    assert_eq!(
        fmu.set(vr(&m, "shaft.speed"), Kind::Real, speed),
        Status::Ok
    );
    assert_eq!(fmu.setup_experiment(0.0, None), Status::Ok);
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
    let mut sim = Simulator::new(Rotor::new(m.clone()).unwrap(), SolverOptions::default()).unwrap();
    sim.set_options(SolverOptions {
        time_step: rotor_bearing::fmi2::variables::default_fmu_time_step(&m),
        local_error_tolerance: rotor_bearing::fmi2::variables::DEFAULT_LOCAL_ERROR_TOLERANCE,
        ..SolverOptions::default()
    })
    .unwrap();
    sim.set_speed(speed, 0.0).unwrap();
    sim.settle_static().unwrap();
    let channel = m.load_inputs().iter().position(|c| c.name == name).unwrap();
    let rotating = 2e5 * 0.64 * 2e-4;
    let mut orbit: f64 = 0.0;
    for step in 0..30 {
        let t = step as f64 * 0.01;
        if step == 10 {
            assert_eq!(fmu.set(vr(&m, name), Kind::Real, 2e-4), Status::Ok);
            sim.set_load(channel, 2e-4, 0.0).unwrap();
        }
        assert_eq!(
            fmu.do_step(t, 0.01),
            Status::Ok,
            "{:?}",
            fmu.drain_messages()
        );
        sim.advance_to(t + 0.01).unwrap();
        let out = sim.outputs().unwrap();
        let got = fmu
            .get(vr(&m, "magnetic_pull.generator.fx"), Kind::Real)
            .unwrap();
        assert!(
            (got - out.bearings[2].fx).abs() <= 1e-11 * rotating,
            "step {step}: {got} against {}",
            out.bearings[2].fx
        );
        let x = fmu.get(vr(&m, "probes.disk.x"), Kind::Real).unwrap();
        orbit = orbit.max(out.probes[0].x.abs());
        assert!(
            (x - out.probes[0].x).abs() <= 1e-11 * orbit.max(1e-12),
            "step {step}: disk x {x} against {}",
            out.probes[0].x
        );
    }
    let out = sim.outputs().unwrap();
    assert!(orbit > 1e-7, "the disk moves: {orbit:e} m");
    assert!(
        out.bearings[2].fx.hypot(out.bearings[2].fy) > 0.5 * rotating,
        "the pull turns"
    );
    assert_eq!(fmu.set(vr(&m, name), Kind::Real, 1.5), Status::Error);
    let text = format!("{:?}", fmu.drain_messages());
    assert!(text.contains(name) && text.contains("maximum"), "{text}");
}

/// A dynamic eccentricity outside `[0, gap)` names file, field and value.
#[test]
fn a_dynamic_eccentricity_beyond_the_gap_is_refused() {
    for (value, why) in [
        (
            "1.0",
            "dynamic_eccentricity = 1: must lie in [0, gap = 1) m",
        ),
        (
            "-1e-3",
            "dynamic_eccentricity = -0.001: must lie in [0, gap = 1) m",
        ),
    ] {
        let text = DEFAULT_MODEL_TOML.to_string()
            + &format!(
                "\n[[magnetic_pull]]\nnode = 4\ngap = 1.0\nstiffness = 2e5\ndynamic_eccentricity = {value}\n"
            );
        let e = RotorModel::from_toml(&text, "pull.toml")
            .unwrap_err()
            .to_string();
        assert!(e.contains("pull.toml") && e.contains(why), "{e}");
    }
}

/// `rotor info` and the report describe the pull with its rotating part:
/// 0.1 mm at 30°, `k e_d` = 2e5 × 1e-4 = 20 N at nominal field.
#[test]
fn the_model_description_names_the_rotating_part() {
    let m = classic_with_pull("dynamic_eccentricity = 1e-4\ndynamic_phase_deg = 30.0", "");
    let text = rotor_bearing::report::text::describe_bearing(&m.bearings[2].kind);
    assert!(
        text.contains("dynamic eccentricity 0.1 mm at 30° (1× pull 20 N at nominal field)"),
        "{text}"
    );
    let plain = classic_with_pull("", "");
    let text = rotor_bearing::report::text::describe_bearing(&plain.bearings[2].kind);
    assert!(!text.contains("dynamic"), "{text}");
}
