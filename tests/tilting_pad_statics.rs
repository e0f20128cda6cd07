//! The rotor-level static equilibrium on tilting-pad bearings (issue 22):
//! four-pad bearings without preload, with the load on a pad and between two,
//! and five-, six- and eight-pad bearings with preload 0.25–0.5, each under its
//! share of a symmetric rotor's weight at 21 speeds from 2000 to 4000 rpm,
//! against the independent quadrature oracle
//! (`tests/data/tilting_pad_preload_oracle.py --speed-grid`, its output
//! `tests/data/tilting_pad_speed_grid.json`).
//!
//! The rotor: a 1 m, 50 mm steel shaft on two identical bearings at its ends
//! (their journals, of the oracle's radius `R`, collars on the shaft:
//! `journal_collar = true`) and a disk at mid-span whose mass makes each
//! bearing carry the oracle's load `W`: symmetric, so each reaction is exactly `W`.

use serde_json::Value;

#[path = "common/reference.rs"]
mod common_reference;
use common_reference::num;

use nalgebra::Vector2;
use rotor_bearing::bearing::equilibrium::journal_equilibrium;
use rotor_bearing::bearing::{Bearing, BearingKind};
use rotor_bearing::fe::{DOF_X, DOF_Y};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{SolverOptions, statics::equilibrium};

const GRAVITY: f64 = 9.81;
const SHAFT_MASS: f64 = 7850.0 * std::f64::consts::PI * 0.05 * 0.05 / 4.0;

/// The model file of the test rotor on two bearings of oracle case `case`.
fn model_text(case: &Value) -> String {
    let pads = case["pads"].as_array().unwrap();
    let pivots: Vec<String> = pads
        .iter()
        .map(|p| format!("{}", num(&p["pivot_deg"])))
        .collect();
    let disk = 2.0 * num(&case["W"]) / GRAVITY - SHAFT_MASS;
    let bearing = |name: &str, node: u32| {
        format!(
            "[[bearings]]\nname = \"{name}\"\ntype = \"tilting_pad\"\nnode = {node}\nradius = {}\njournal_collar = true\nlength = {}\nclearance = {}\nviscosity = {}\npivots_deg = [{}]\npad_arc_deg = {}\npivot_offset = {}\npreload = {}\n\n",
            num(&case["R"]),
            num(&case["L"]),
            num(&case["C"]),
            num(&case["mu"]),
            pivots.join(", "),
            num(&pads[0]["arc_deg"]),
            num(&pads[0]["offset"]),
            num(&pads[0]["preload"]),
        )
    };
    format!(
        "name = \"tilting_pad_rotor\"\nspeed_rpm = 3000\ngravity = [0.0, -{GRAVITY}, 0.0]\n\n[[materials]]\nname = \"steel\"\nyoungs_modulus = 210e9\npoisson_ratio = 0.3\ndensity = 7850.0\n\n[[shaft]]\nlength = 1.0\nouter_diameter = 0.05\nmaterial = \"steel\"\nelements = 10\n\n[[disks]]\nname = \"disk\"\nnode = 6\nmass = {disk}\npolar_inertia = 3.0\ndiametral_inertia = 1.6\n\n{}{}",
        bearing("left", 1),
        bearing("right", 11)
    )
}

/// At every speed of every case the static solve converges, each pad carries
/// the oracle's film force (within 1e-4 W), the journal sits where the
/// oracle has it along the load (1e-4 C) — and across it (1e-3 C) wherever
/// two pads or more carry load: with one loaded pad and no preload, nothing
/// but the pivots' weak rest moment fixes the journal sideways, and any
/// position within a band is an equilibrium — and no pad is left carrying
/// nothing where a loaded zero-moment tilt exists.
#[test]
fn the_rotor_sits_on_the_oracle_equilibrium_at_every_speed_and_pads_carry_its_loads() {
    let grid = common_reference::reference("tilting_pad_speed_grid.json");
    let cases = grid["cases"].as_array().unwrap();
    assert_eq!(cases.len(), 5);
    let options = SolverOptions::default();
    for case in cases {
        let name = case["name"].as_str().unwrap();
        let model = RotorModel::from_toml(&model_text(case), name).unwrap();
        let rotor = Rotor::new(model).unwrap();
        let w = num(&case["W"]);
        let weight: f64 = (0..rotor.dof_count())
            .filter(|&i| rotor.dofs.full(i) % 4 == DOF_Y)
            .map(|i| -rotor.gravity_load[i])
            .sum();
        assert!(
            (0.5 * weight - w).abs() < 1e-9 * w,
            "{name}: each bearing carries {} N, the oracle {w} N",
            0.5 * weight
        );
        let BearingKind::TiltingPad(pad_bearing) = &rotor.model.bearings[0].kind else {
            panic!("{name}: not a tilting-pad bearing")
        };
        let c = pad_bearing.clearance;
        let n_pads = pad_bearing.pads.len();
        let node = rotor.model.bearings[0].node;
        let points = case["points"].as_array().unwrap();
        assert_eq!(points.len(), 21);
        let mut worst = (0.0f64, 0.0f64);
        for point in points {
            let (rpm, speed) = (num(&point["rpm"]), num(&point["omega"]));
            let eq = equilibrium(&rotor, speed, &options, None)
                .unwrap_or_else(|e| panic!("{name} at {rpm} rpm: {e}"));
            let at = |dof| eq.displacement[rotor.dofs.free(node, dof).unwrap()];
            let mut q = vec![at(DOF_X), at(DOF_Y)];
            q.extend_from_slice(&eq.tilts[..n_pads]);
            let rates = vec![0.0; q.len()];
            let mut loaded = 0;
            for (k, oracle) in point["pad_forces"].as_array().unwrap().iter().enumerate() {
                let f = pad_bearing.pad_force(k, &q, &rates, speed).unwrap();
                let (fx, fy) = (num(&oracle[0]), num(&oracle[1]));
                let off = (f.x - fx).hypot(f.y - fy);
                worst.0 = worst.0.max(off / w);
                assert!(
                    off <= 1e-4 * w,
                    "{name} at {rpm} rpm, pad {k}: ({:.3}, {:.3}) N, oracle ({fx:.3}, {fy:.3}) N",
                    f.x,
                    f.y
                );
                if fx.hypot(fy) > 1e-3 * w {
                    loaded += 1;
                }
            }
            let (x, y) = (num(&point["X"]), num(&point["Y"]));
            worst.1 = worst.1.max((q[1] - y).abs() / c);
            assert!(
                (q[1] - y).abs() <= 1e-4 * c,
                "{name} at {rpm} rpm: journal y {:.6} C, oracle {:.6} C",
                q[1] / c,
                y / c
            );
            if loaded >= 2 {
                assert!(
                    (q[0] - x).abs() <= 1e-3 * c,
                    "{name} at {rpm} rpm: journal x {:.6} C, oracle {:.6} C",
                    q[0] / c,
                    x / c
                );
            }
            let mut reseated = q.clone();
            assert!(
                !pad_bearing.reseat_internal(&mut reseated, speed),
                "{name} at {rpm} rpm: a pad carries nothing where a loaded tilt exists: {:?} → {:?}",
                &q[2..],
                &reseated[2..]
            );
        }
        eprintln!(
            "{name}: largest pad-force difference {:.2e} W, journal y {:.2e} C",
            worst.0, worst.1
        );
    }
}

/// `rotor static`, `operating-point` and `modes` start from the same static
/// solve: on the four-pad rotor without preload, load on a pad, at 3000 rpm
/// (one of the speeds where the solve used to stall) all three finish.
#[test]
fn static_operating_point_and_modes_run_on_the_unpreloaded_four_pad_rotor() {
    let grid = common_reference::reference("tilting_pad_speed_grid.json");
    let case = grid["cases"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["name"] == "lop4_m0")
        .unwrap();
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("tilting_pad_statics");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("lop4_m0.toml");
    std::fs::write(&path, model_text(case)).unwrap();
    for command in ["static", "operating-point", "modes"] {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
            .arg(command)
            .arg(&path)
            .args(["--rpm", "3000"])
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "rotor {command}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

/// The bearing on its own (`journal_equilibrium`, what the rotor-level solve
/// starts from when its direct start fails): on every case and speed it
/// converges and its pads carry the oracle's forces (1e-4 W). Pads without
/// preload around a centred journal carry nothing at any small tilt, so the
/// centred start is degenerate: it used to stall on the four-pad, load-on-pad
/// bearing at every speed of the grid.
#[test]
fn the_bearing_level_equilibrium_carries_the_oracle_pad_loads_at_every_speed() {
    let grid = common_reference::reference("tilting_pad_speed_grid.json");
    for case in grid["cases"].as_array().unwrap() {
        let name = case["name"].as_str().unwrap();
        let rotor = Rotor::new(RotorModel::from_toml(&model_text(case), name).unwrap()).unwrap();
        let BearingKind::TiltingPad(b) = &rotor.model.bearings[0].kind else {
            unreachable!()
        };
        let w = num(&case["W"]);
        for point in case["points"].as_array().unwrap() {
            let (rpm, speed) = (num(&point["rpm"]), num(&point["omega"]));
            let eq = journal_equilibrium(b, Vector2::new(0.0, -w), speed, b.clearance)
                .unwrap_or_else(|e| panic!("{name} at {rpm} rpm: {e}"));
            let rates = vec![0.0; eq.q.len()];
            for (k, oracle) in point["pad_forces"].as_array().unwrap().iter().enumerate() {
                let f = b.pad_force(k, &eq.q, &rates, speed).unwrap();
                let off = (f.x - num(&oracle[0])).hypot(f.y - num(&oracle[1]));
                assert!(
                    off <= 1e-4 * w,
                    "{name} at {rpm} rpm, pad {k}: off by {off} N"
                );
            }
        }
    }
}
