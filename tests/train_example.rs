//! The shipped turbine–generator train (`models/turbine_generator_train.toml`,
//! issue 49): a turbine on two plain bearings, a flexible spacer
//! coupling with its residual misalignment, a generator on two plain
//! bearings and an exciter bolted to it by a rigid flange with its runout,
//! on one plain bearing. Its bearings are stated on the catenary at
//! 3000 rpm: the elevations at which every rotor carries the loads it
//! carries with the flexible coupling cut and the flange true (the
//! generator–exciter line on straight stiff supports). There the flexible
//! coupling transmits (almost) nothing: checked against that cut line
//! computed here from the same file. The train's Campbell diagram, modes,
//! unbalance response and transients run (`rotor` on the file).

use std::path::PathBuf;
use std::process::Command;

use rotor_bearing::analysis::alignment::alignment;
use rotor_bearing::analysis::shaft_loads::coupling_loads;
use rotor_bearing::model::{CouplingJoint, RotorModel};
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::SolverOptions;

const RPM: f64 = std::f64::consts::PI / 30.0;

fn path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/turbine_generator_train.toml")
}

/// The file with its bearings on straight stiff linear supports (1e10 N/m),
/// the flexible coupling cut (1e-3 N/m, N·m/rad, aligned) and the flange
/// true (the shaft itself).
fn cut_line(text: &str) -> String {
    let mut out = String::new();
    let mut entry = "";
    let mut skip = false;
    for line in text.lines() {
        if line.starts_with("[[") {
            entry = line;
            skip = false;
        }
        let key = line.split('=').next().unwrap_or("").trim();
        if entry == "[[couplings]]" && line.starts_with("name = \"generator_exciter\"") {
            // Drop the flange's entry: its header is already written.
            out.truncate(out.trim_end().len() - "[[couplings]]".len());
            skip = true;
        }
        if skip {
            continue;
        }
        match (entry, key) {
            ("[[couplings]]", "lateral_stiffness" | "angular_stiffness") => {
                out += &format!("{key} = 1e-3\n")
            }
            ("[[couplings]]", "parallel_offset" | "angular_offset") => {}
            ("[[bearings]]", "type") => out += "type = \"linear\"\nkxx = 1e10\nkyy = 1e10\n",
            ("[[bearings]]", "radius" | "length" | "clearance" | "viscosity" | "offset_y") => {}
            _ => out += &format!("{line}\n"),
        }
    }
    out
}

#[test]
fn the_shipped_train_sits_on_its_catenary() {
    let text = std::fs::read_to_string(path()).unwrap();
    let train = Rotor::new(RotorModel::from_toml(&text, "train.toml").unwrap()).unwrap();
    let model = &train.model;
    assert_eq!(model.couplings.len(), 2);
    assert_eq!(model.bearings.len(), 5);
    assert!(matches!(model.couplings[1].joint, CouplingJoint::Flange));
    let cut = RotorModel::from_toml(&cut_line(&text), "cut.toml").unwrap();
    assert_eq!(cut.couplings.len(), 1);
    let cut = Rotor::new(cut).unwrap();
    let options = SolverOptions::default();
    let target = alignment(&cut, 0.0, &options).unwrap();
    let weight: f64 = target.loads().iter().sum();
    let speed = 3000.0 * RPM;
    // The flexible coupling's load k (q_r − q_l − m) on the shaft after it,
    // vertical plane: lateral (N) and angular (N·m).
    let coupling_load = |rotor: &Rotor| {
        let found = alignment(rotor, speed, &options).unwrap();
        let all = rotor.dofs.expand(&found.equilibrium.displacement);
        let c = &rotor.model.couplings[0];
        let CouplingJoint::Flexible { lateral, angular } = c.joint else {
            panic!("the first coupling is flexible")
        };
        let l = 4 * rotor.model.elements[c.element].node;
        let r = l + 4;
        let shear = lateral[0] * (all[r + 1] - all[l + 1] - c.misalignment[1]);
        let moment = angular[0] * (all[r + 2] - all[l + 2] - c.misalignment[2]);
        // The library's coupling loads say the same (the y–z plane's beam
        // rotation is −θx, its shear −k_l Δw).
        let library = &coupling_loads(rotor, &all, true)[0];
        assert!((library.shear[1] + shear).abs() <= 1e-12 * shear.abs().max(1.0));
        assert!((library.moment[1] + moment).abs() <= 1e-12 * moment.abs().max(1.0));
        (found.loads(), shear, moment)
    };
    let (loads, shear, moment) = coupling_load(&train);
    for (i, (got, want)) in loads.iter().zip(target.loads()).enumerate() {
        assert!(
            (got - want).abs() < 1e-4 * weight,
            "bearing {}: {got} N against the cut line's {want} N",
            model.bearings[i].name
        );
    }
    assert!(
        shear.abs() < 1e-4 * weight && moment.abs() < 1.0,
        "the coupling carries {shear} N and {moment} N·m"
    );
    // Off its catenary (the bearings in a straight line) the coupling is
    // loaded: the check can fail.
    let straight: String = text
        .lines()
        .filter(|l| !l.starts_with("offset_y"))
        .map(|l| format!("{l}\n"))
        .collect();
    let straight = Rotor::new(RotorModel::from_toml(&straight, "straight.toml").unwrap()).unwrap();
    let (_, shear_straight, moment_straight) = coupling_load(&straight);
    assert!(
        shear_straight.abs() > 100.0 * shear.abs().max(1e-2) && moment_straight.abs() > 10.0,
        "straight: {shear_straight} N, {moment_straight} N·m"
    );
    eprintln!(
        "catenary: coupling {shear:.3e} N, {moment:.3e} N·m (straight line: {shear_straight:.1} N, {moment_straight:.1} N·m), weight {weight:.1} N"
    );
}

fn rotor_cli(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(args)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout).to_string();
    assert!(
        out.status.success(),
        "rotor {args:?}: {}\n{stdout}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        !stdout.contains("NaN") && !stdout.contains("inf "),
        "{stdout}"
    );
    stdout
}

#[test]
fn the_shipped_train_runs_modes_unbalance_and_transients() {
    let file = path();
    let file = file.to_str().unwrap();
    let modes = rotor_cli(&["modes", file, "--rpm", "3000"]);
    assert!(modes.contains("torsional modes"), "{modes}");
    assert!(!modes.contains("UNSTABLE"), "{modes}");
    let unbalance = rotor_cli(&[
        "unbalance",
        file,
        "--min-rpm",
        "2500",
        "--max-rpm",
        "3500",
        "--points",
        "6",
    ]);
    assert!(!unbalance.is_empty());
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("train_example");
    std::fs::create_dir_all(&dir).unwrap();
    let csv = dir.join("train.csv");
    rotor_cli(&[
        "simulate",
        file,
        "--rpm",
        "3000",
        "--duration",
        "0.05",
        "--csv",
        csv.to_str().unwrap(),
    ]);
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert!(rows.len() > 10);
    assert!((rows.last().unwrap()[0] - 0.05).abs() < 1e-9);
    for name in [
        "turbine_front",
        "turbine_rear",
        "generator_front",
        "generator_rear",
        "exciter",
    ] {
        let k = header
            .iter()
            .position(|h| *h == format!("{name}_eccentricity"))
            .unwrap();
        for row in &rows {
            assert!(
                row.iter().all(|v| v.is_finite()),
                "a non-finite output at {} s",
                row[0]
            );
            assert!(
                row[k] > 0.0 && row[k] < 0.6,
                "{name}: ε = {} at {} s",
                row[k],
                row[0]
            );
        }
    }
}
