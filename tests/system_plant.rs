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

const BRACKETS: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/models/hydro_unit_brackets.toml"
);

/// The brackets unit with the field at `excitation` and the part-load forces
/// (2e4 N vortex rope, 4e4 N radial thrust along x) if `part_load`.
fn brackets(excitation: f64, part_load: bool) -> Rotor {
    let mut text = std::fs::read_to_string(BRACKETS).unwrap().replace(
        "excitation = 0.0 ",
        &format!("excitation = {excitation:?} "),
    );
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
    eprintln!(
        "linear: unbalance forward radii (gen off, runner off, gen on, runner on) and rope {args:?}"
    );
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

/// `rotor info` of a torque-driven shaft gives what a plant model needs: the
/// polar inertia of shaft and disks, against the hand sum `Σ I_p + Σ ρ J_p L`
/// (tubes `J_p = π (D⁴ − d⁴)/32`) of models/hydro_unit_torque.toml, and the
/// thrust bearing's load (the rotor weight `m g`, `m` = disks + `ρ A L`) and
/// breakaway torque `μ_b W R_m` (μ_b = 0.15, R_m = 1.3 m), to the six digits
/// printed (5e-6), the inertia to its printed 0.1 kg·m².
#[test]
fn rotor_info_gives_the_torque_driven_units_inertia_and_breakaway_torque() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/hydro_unit_torque.toml");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(["info", path])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    let pi = std::f64::consts::PI;
    let rho = 7850.0;
    let tubes: [(f64, f64, f64); 3] = [(0.9, 0.2, 4.8), (1.0, 0.25, 10.0), (1.0, 0.25, 2.4)];
    let polar: f64 = tubes
        .iter()
        .map(|(od, id, l)| rho * pi * (od.powi(4) - id.powi(4)) / 32.0 * l)
        .sum();
    let mass: f64 = tubes
        .iter()
        .map(|(od, id, l)| rho * pi * (od * od - id * id) / 4.0 * l)
        .sum::<f64>()
        + 4.5e5
        + 6.0e4;
    let inertia = 4.5e6 + 1.9e5 + polar;
    let weight = mass * 9.81;
    let line = text
        .lines()
        .find(|l| l.contains("torque drive:"))
        .unwrap_or_else(|| panic!("no torque drive line in\n{text}"));
    assert!(
        line.contains("turbine at node 20, generator at node 5")
            && line.contains(&format!("polar inertia {inertia:.1} kg·m²")),
        "{line}: want {inertia:.1} kg·m²"
    );
    let thrust = text
        .lines()
        .find(|l| l.contains("thrust bearing thrust at node 5"))
        .unwrap_or_else(|| panic!("no thrust bearing line in\n{text}"));
    let number = |key: &str| -> f64 {
        let rest = &thrust[thrust.find(key).unwrap() + key.len()..];
        rest.split_whitespace().next().unwrap().parse().unwrap()
    };
    assert!(
        (number("load W = ") / weight - 1.0).abs() < 5e-6,
        "{thrust}"
    );
    assert!((number("R_m = ") - 1.3).abs() < 1e-12, "{thrust}");
    assert!(
        (number("μ_b W R_m = ") / (0.15 * weight * 1.3) - 1.0).abs() < 5e-6,
        "{thrust}"
    );
}
