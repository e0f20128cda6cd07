//! `rotor ucs` and `analysis::ucs`: the forward synchronous critical speeds
//! against support stiffness, checked at both ends of the map against closed
//! forms (pinned–pinned beam, rigid-body bounce and rocking) and in between
//! against the Campbell diagram's 1× crossings (a second implementation).

use std::f64::consts::PI;
use std::path::PathBuf;
use std::process::Command;

use rotor_bearing::analysis::campbell::{campbell, critical_speeds};
use rotor_bearing::analysis::modal::{ModalOptions, Whirl};
use rotor_bearing::analysis::ucs::{synchronous_critical_speeds, with_isotropic_supports};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;

const LENGTH: f64 = 1.0;
const DIAMETER: f64 = 0.01;
const E: f64 = 211e9;
const G: f64 = 81.2e9;
const RHO: f64 = 7810.0;

/// A slender uniform steel shaft (L/d = 100, 40 Timoshenko elements) on two
/// end bearings, no disks.
fn shaft_on_two_bearings() -> String {
    format!(
        r#"name = "uniform_shaft"
[[materials]]
name = "steel"
youngs_modulus = {E:?}
shear_modulus = {G:?}
density = {RHO:?}
[[shaft]]
length = {LENGTH:?}
outer_diameter = {DIAMETER:?}
material = "steel"
elements = 40
[[bearings]]
name = "left"
type = "linear"
node = 1
kxx = 1e6
kyy = 1e6
[[bearings]]
name = "right"
type = "linear"
node = 41
kxx = 1e6
kyy = 1e6
"#
    )
}

/// The map printed to CSV by the command: rows of (stiffness, criticals rpm).
fn map_csv(model: &str, args: &[&str], name: &str) -> Vec<Vec<f64>> {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::create_dir_all(&dir).unwrap();
    let (path, csv, png) = (dir.join("m.toml"), dir.join("m.csv"), dir.join("m.png"));
    std::fs::write(&path, model).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg("ucs")
        .arg(&path)
        .args(args)
        .arg("--csv")
        .arg(&csv)
        .arg("--png")
        .arg(&png)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(&std::fs::read(&png).unwrap()[..8], b"\x89PNG\r\n\x1a\n");
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    assert!(
        header.starts_with("support_stiffness_N_m,critical_1_rpm,")
            && header.ends_with(",statically_unstable_modes")
    );
    // Stiffness and critical speeds; the last column (no statically
    // unstable mode on these rotors) apart.
    lines
        .map(|l| {
            let (row, unstable) = l.rsplit_once(',').unwrap();
            assert_eq!(unstable, "0", "{l}");
            row.split(',').map(|c| c.parse().unwrap()).collect()
        })
        .collect()
}

#[test]
fn stiff_supports_give_the_pinned_pinned_beam_and_soft_ones_the_rigid_body_modes() {
    let rows = map_csv(
        &shaft_on_two_bearings(),
        &[
            "--min-stiffness",
            "1",
            "--max-stiffness",
            "1e12",
            "--points",
            "13",
            "--modes",
            "3",
        ],
        "ucs_uniform",
    );
    assert_eq!(rows.len(), 13);
    let area = PI * DIAMETER * DIAMETER / 4.0;
    let inertia = PI * DIAMETER.powi(4) / 64.0;
    let mass = RHO * area * LENGTH;
    let to_rpm = 30.0 / PI;

    // Very stiff supports (1e12 N/m, 1e7 × the shaft's 48EI/L³): the pinned–pinned
    // Euler–Bernoulli frequencies (nπ/L)² √(EI/ρA). Shear, rotary inertia and the
    // shaft's own gyroscopic stiffening at L/d = 100 stay below 0.1 %
    // (measured −6e-5, −2.4e-4, −5.3e-4).
    let stiff = &rows[12];
    for (n, critical) in stiff.iter().enumerate().skip(1) {
        let exact = (n as f64 * PI / LENGTH).powi(2) * (E * inertia / (RHO * area)).sqrt() * to_rpm;
        let err = critical / exact - 1.0;
        eprintln!("stiff: critical {n} {critical:.3} rpm vs pinned–pinned {exact:.3} ({err:.2e})");
        assert!(err.abs() < 0.01, "n = {n}: {err}");
    }

    // Very soft supports (1 N/m, 1e-5 × the shaft): a rigid rotor. Bounce
    // √(2k/m); forward synchronous rocking √(k L²/2 / (I_d − I_p)) with the
    // shaft's I_d = m(L²/12 + d²/16), I_p = m d²/8 (gyroscopic stiffening).
    let soft = &rows[0];
    let k = soft[0];
    let bounce = (2.0 * k / mass).sqrt() * to_rpm;
    let i_d = mass * (LENGTH * LENGTH / 12.0 + DIAMETER * DIAMETER / 16.0);
    let i_p = mass * DIAMETER * DIAMETER / 8.0;
    let rocking = (k * LENGTH * LENGTH / 2.0 / (i_d - i_p)).sqrt() * to_rpm;
    eprintln!(
        "soft: {:.6} rpm vs bounce {bounce:.6} ({:.1e}); {:.6} rpm vs rocking {rocking:.6} ({:.1e})",
        soft[1],
        soft[1] / bounce - 1.0,
        soft[2],
        soft[2] / rocking - 1.0
    );
    // The shaft's flexibility against the springs (k/48EI·L³ ≈ 1e-5) and its
    // bending under its own inertia move them by up to 1e-4 (measured −8e-5, −1e-5).
    assert!((soft[1] / bounce - 1.0).abs() < 2e-4);
    assert!((soft[2] / rocking - 1.0).abs() < 2e-4);
}

#[test]
fn map_equals_the_forward_campbell_crossings_of_the_classic_rotor() {
    let rotor = Rotor::new(RotorModel::default_model()).unwrap();
    let sprung = with_isotropic_supports(&rotor, 1e6).unwrap();
    let map = synchronous_critical_speeds(&sprung, 3).unwrap();
    let options = ModalOptions {
        modes: 8,
        ..Default::default()
    };
    let speeds: Vec<f64> = (0..=40).map(|k| 800.0 * k as f64 / 40.0).collect();
    let diagram = campbell(&rotor, &speeds, &options).unwrap();
    let forward: Vec<f64> = critical_speeds(&rotor, &diagram, 1.0, &options)
        .unwrap()
        .into_iter()
        .filter(|c| c.whirl == Whirl::Forward)
        .map(|c| c.speed)
        .collect();
    eprintln!("map {map:?} rad/s; Campbell forward 1× crossings {forward:?}");
    assert_eq!(forward.len(), 3);
    for (a, b) in map.iter().zip(&forward) {
        // The Campbell roots are refined to 1e-8 (measured agreement 6e-12).
        assert!((a / b - 1.0).abs() < 1e-8, "{a} vs {b}");
    }
}

#[test]
fn bad_ranges_are_refused_by_name() {
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(["ucs", "--min-stiffness", "1e9", "--max-stiffness", "1e6"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        !out.status.success() && stderr.contains("--min-stiffness < --max-stiffness"),
        "{stderr}"
    );
}

/// The bearings' stiffness table: constant for linear bearings, and for the
/// plain bearings of the Jeffcott rotor the synchronous K of the operating point.
#[test]
fn bearing_stiffness_table_is_the_operating_point_stiffness() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("ucs_bearings");
    std::fs::create_dir_all(&dir).unwrap();
    let model = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/jeffcott.toml");
    let csv = dir.join("b.csv");
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg("ucs")
        .arg(&model)
        .args([
            "--points",
            "3",
            "--max-rpm",
            "6000",
            "--speeds",
            "2",
            "--bearings-csv",
        ])
        .arg(&csv)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("bearing,speed_rpm,kxx_N_m,kyy_N_m"));
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 4);
    let rotor = Rotor::new(RotorModel::from_file(&model).unwrap()).unwrap();
    for row in &rows {
        let rpm: f64 = row[1].parse().unwrap();
        let points =
            rotor_bearing::analysis::operating_point::operating_point(&rotor, rpm * PI / 30.0)
                .unwrap();
        let b = points.iter().find(|p| p.name == row[0]).unwrap();
        let (kxx, kyy): (f64, f64) = (row[2].parse().unwrap(), row[3].parse().unwrap());
        assert!((kxx / b.stiffness[0][0] - 1.0).abs() < 1e-12, "{row:?}");
        assert!((kyy / b.stiffness[1][1] - 1.0).abs() < 1e-12, "{row:?}");
    }
    assert!((rows[1][1].parse::<f64>().unwrap() - 6000.0).abs() < 1e-9);
}
