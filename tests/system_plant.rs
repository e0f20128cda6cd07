//! The plant scenarios of issues 24 and 25 under libcosim: the torque-driven
//! hydro unit (system/test_coupled_torque.py: start-up with breakaway and
//! synchronization, load rejection against the speed-driven plant with the
//! model's inertia, shut-down to rest, short circuit) and the whole machine on
//! its brackets (system/test_coupled_brackets.py: the field on at
//! synchronization, the part-load vortex rope), checked against the model's
//! own linear analyses computed here.

mod common;

use rotor_bearing::analysis::forced::{forced_response, harmonic_force};
use rotor_bearing::analysis::linear::node_xy;
use rotor_bearing::analysis::modal::orbit_radii;
use rotor_bearing::analysis::unbalance::response_at;
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;

const BRACKETS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/models/hydro_unit_brackets.toml");

/// The brackets unit with the field at `excitation` and the part-load forces
/// (2e4 N vortex rope, 4e4 N radial thrust along x) if `part_load`.
fn brackets(excitation: f64, part_load: bool) -> Rotor {
    let mut text = std::fs::read_to_string(BRACKETS)
        .unwrap()
        .replace("excitation = 0.0 ", &format!("excitation = {excitation:?} "));
    if part_load {
        text = text
            .replace("magnitude = 0.0              # N", "magnitude = 2.0e4 # N")
            .replace("fx = 0.0                     # N", "fx = 4.0e4 # N");
    }
    let model = RotorModel::from_toml(&text, "hydro_unit_brackets.toml").unwrap();
    Rotor::new(model).unwrap()
}

#[test]
fn torque_driven_plant_scenarios_behave_physically() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let rotor = std::path::Path::new(env!("CARGO_BIN_EXE_rotor"));
    common::run_python(
        "system/test_coupled_torque.py",
        &[root, rotor],
        &[
            "out/HydroPlantTorque.fmu",
            "out/HydroPlant.fmu",
            "out/hydro_unit_torque.fmu",
            "out/hydro_unit_torque_speed.fmu",
        ],
    );
}

#[test]
fn brackets_unit_synchronization_and_part_load_follow_the_linear_analyses() {
    let speed = 300.0 * std::f64::consts::PI / 30.0;
    // Synchronous response (forward radius) at the generator and runner probes
    // (nodes 3 and 11), field off and on.
    let mut unbalance = Vec::new();
    for excitation in [0.0, 1.0] {
        let r = brackets(excitation, false);
        let q = response_at(&r, speed).unwrap();
        for node in [2, 10] {
            unbalance.push(orbit_radii(node_xy(&q, node).0, node_xy(&q, node).1).0);
        }
    }
    // The vortex rope's forward line at the runner probe, field on, thrust on.
    let r = brackets(1.0, true);
    let index = harmonic_force(&r, "vortex_rope").unwrap();
    let (_, q) = forced_response(&r, index, speed).unwrap();
    let (x, y) = node_xy(&q, 10);
    let (forward, backward) = orbit_radii(x, y);
    let args: Vec<String> = unbalance
        .iter()
        .chain([forward, backward].iter())
        .map(|v| format!("{v:e}"))
        .collect();
    eprintln!("linear: unbalance forward radii (gen off, runner off, gen on, runner on) and rope {args:?}");
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let paths: Vec<&std::path::Path> = args.iter().map(std::path::Path::new).collect();
    let mut all = vec![root];
    all.extend(paths);
    common::run_python(
        "system/test_coupled_brackets.py",
        &all,
        &["out/HydroPlant.fmu", "out/hydro_unit_brackets.fmu"],
    );
}
