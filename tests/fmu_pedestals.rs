//! The FMU of a machine on pedestals with a seal and a coefficient table:
//! the appended variables (units, descriptions), their values equal to the
//! simulator's outputs, earlier value references unchanged, and the table's
//! clamping warning logged once.

use rotor_bearing::fmi2::instance::{Instance, Status};
use rotor_bearing::fmi2::variables::{Causality, Kind, Variable, variables};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

#[path = "common/fmu.rs"]
mod fmu;
use fmu::{model, vr};

const RPM: f64 = std::f64::consts::PI / 30.0;

/// Every bearing on a pedestal gains `x_rel`, `y_rel` and the housing's
/// `housing_x`, `housing_y` (m) and `housing_vx`, `housing_vy` (m/s), and the
/// seal `fx`, `fy`, `contact_force`, all after `solver.reduced_modes`; the
/// variables before it are those of the same machine on rigid ground.
#[test]
fn pedestal_and_seal_outputs_are_appended_after_the_existing_variables() {
    let m = model("hydro_unit_brackets");
    // The offset parameters (issue 49) come after everything checked here:
    // two per bearing, seal and pull, then the pulls' dynamic eccentricity
    // inputs (issue 48), then the bearings' static and dynamic loads (issue
    // 49), then the harmonic forces' frequencies (issue 48).
    let without_offsets = |mut vars: Vec<Variable>, model: &RotorModel| {
        let later = [
            ".ratio",
            ".frequency",
            ".dynamic_eccentricity",
            ".static_fx",
            ".static_fy",
            ".dynamic_fx",
            ".dynamic_fy",
            ".dynamic_load",
        ];
        while vars
            .last()
            .is_some_and(|v| later.iter().any(|s| v.name.ends_with(s)))
        {
            vars.pop();
        }
        let n = 2 * model.bearings.len();
        let tail = vars.split_off(vars.len() - n);
        assert!(
            tail.iter()
                .all(|v| v.name.ends_with("offset_x") || v.name.ends_with("offset_y"))
        );
        vars
    };
    let vars = without_offsets(variables(&m), &m);
    let last_old = vr(&m, "solver.reduced_modes") as usize;
    let mut rigid = m.clone();
    rigid.bearings.retain(|b| !b.kind.is_seal());
    rigid.pedestals.clear();
    for b in &mut rigid.bearings {
        b.pedestal = None;
    }
    let old = without_offsets(variables(&rigid), &rigid);
    // The machine on rigid ground has the same variables but for the 27 of
    // the seal and the housings (its loads and losses come after them) and
    // the seal's power loss, appended last.
    assert_eq!(old.len() + 28, vars.len());
    assert_eq!(
        vars.last().unwrap().name,
        "magnetic_pull.generator.power_loss"
    );
    assert_eq!(vars[vars.len() - 2].name, "seals.runner_seal.power_loss");
    for (a, b) in old[last_old + 1..old.len() - 1]
        .iter()
        .zip(&vars[last_old + 28..vars.len() - 2])
    {
        assert_eq!(a.name, b.name);
    }
    assert_eq!(
        old.last().unwrap().name,
        "magnetic_pull.generator.power_loss"
    );
    for (a, b) in old[..=last_old].iter().zip(&vars) {
        assert_eq!(
            (a.name.as_str(), a.value_reference),
            (b.name.as_str(), b.value_reference)
        );
    }
    let appended: Vec<&str> = vars[last_old + 1..]
        .iter()
        .map(|v| v.name.as_str())
        .collect();
    assert_eq!(
        &appended[..3],
        [
            "seals.runner_seal.fx",
            "seals.runner_seal.fy",
            "seals.runner_seal.contact_force"
        ]
    );
    assert_eq!(
        vars[last_old + 28].name,
        "magnetic_pull.generator.excitation",
        "{appended:?}"
    );
    for v in &vars[last_old + 1..last_old + 28] {
        assert_eq!(v.causality, Causality::Output);
        let unit = v.unit.unwrap();
        if v.name.contains("housing_v") {
            assert_eq!(unit, "m/s", "{}", v.name);
        } else if v.name.ends_with("rel") || v.name.contains("housing_") {
            assert_eq!(unit, "m", "{}", v.name);
        } else {
            assert_eq!(unit, "N", "{}", v.name);
        }
        assert!(!v.description.is_empty());
    }
    let xml = rotor_bearing::fmi2::xml::model_description(&m).0;
    assert!(xml.contains("<Unit name=\"m/s\">"), "m/s declared");
    assert!(
        !rotor_bearing::fmi2::xml::model_description(&rigid)
            .0
            .contains("m/s")
    );
}

/// The FMU's pedestal, seal and relative outputs equal the simulator's, bit
/// for bit, over a run at 300 rpm.
#[test]
fn pedestal_outputs_equal_the_simulator() {
    let m = model("hydro_unit_brackets");
    let mut fmu = Instance::new("brackets", m.clone()).unwrap();
    let speed = 300.0 * RPM;
    assert_eq!(
        fmu.set(vr(&m, "shaft.speed"), Kind::Real, speed),
        Status::Ok
    );
    assert_eq!(fmu.setup_experiment(0.0, None), Status::Ok);
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
    let mut sim = Simulator::new(
        Rotor::new(m.clone()).unwrap(),
        SolverOptions {
            time_step: rotor_bearing::fmi2::variables::default_fmu_time_step(&m),
            local_error_tolerance: rotor_bearing::fmi2::variables::DEFAULT_LOCAL_ERROR_TOLERANCE,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    sim.set_speed(speed, 0.0).unwrap();
    sim.settle_static().unwrap();
    let names: Vec<(String, usize, &str)> = ["upper_guide", "lower_guide", "turbine_guide"]
        .iter()
        .enumerate()
        .flat_map(|(k, b)| {
            [
                "x_rel",
                "y_rel",
                "housing_x",
                "housing_y",
                "housing_vx",
                "housing_vy",
            ]
            .map(|s| (format!("bearings.{b}.{s}"), k, s))
        })
        .collect();
    for step in 0..100 {
        let t = step as f64 * 0.01;
        assert_eq!(fmu.do_step(t, 0.01), Status::Ok);
        // The FMU adopts the master's clock (fmi2DoStep's current time).
        sim.align_time(t).unwrap();
        sim.advance_to(t + 0.01).unwrap();
        let out = sim.outputs().unwrap();
        for (name, k, what) in &names {
            let b = &out.bearings[*k];
            let want = match *what {
                "x_rel" => b.relative().0,
                "y_rel" => b.relative().1,
                "housing_x" => b.housing.x,
                "housing_y" => b.housing.y,
                "housing_vx" => b.housing.vx,
                _ => b.housing.vy,
            };
            assert_eq!(
                fmu.get(vr(&m, name), Kind::Real).unwrap(),
                want,
                "{name} at {t} s"
            );
        }
        let seal = &out.bearings[3];
        assert_eq!(
            fmu.get(vr(&m, "seals.runner_seal.fx"), Kind::Real).unwrap(),
            seal.fx
        );
        assert_eq!(
            fmu.get(vr(&m, "seals.runner_seal.fy"), Kind::Real).unwrap(),
            seal.fy
        );
    }
    // The housings do move.
    let vx = fmu
        .get(vr(&m, "bearings.upper_guide.housing_vx"), Kind::Real)
        .unwrap();
    assert!(vx.abs() > 0.0);
}

/// Speeding past the seal table's last row (600 rpm, the runaway speed)
/// logs one fmi2Warning naming the seal, the speed and the table's range.
#[test]
fn a_speed_past_the_table_logs_one_warning() {
    let mut m = model("hydro_unit_brackets");
    m.max_speed = 700.0 * RPM;
    let mut fmu = Instance::new("brackets", m.clone()).unwrap();
    assert_eq!(
        fmu.set(vr(&m, "shaft.speed"), Kind::Real, 590.0 * RPM),
        Status::Ok
    );
    assert_eq!(fmu.setup_experiment(0.0, None), Status::Ok);
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
    fmu.drain_messages();
    for step in 0..20 {
        let rpm = 590.0 + 2.0 * step as f64;
        assert_eq!(
            fmu.set(vr(&m, "shaft.speed"), Kind::Real, rpm * RPM),
            Status::Ok
        );
        assert_eq!(fmu.do_step(step as f64 * 0.01, 0.01), Status::Ok);
    }
    let warnings: Vec<String> = fmu
        .drain_messages()
        .into_iter()
        .filter(|m| m.0 == Status::Warning)
        .map(|m| m.2)
        .collect();
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert!(
        warnings[0]
            .contains("runner_seal: speed 602 rpm is outside its coefficient table (0 to 600 rpm)"),
        "{}",
        warnings[0]
    );
}
