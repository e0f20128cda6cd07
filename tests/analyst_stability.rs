//! `rotor stability` and `analysis::stability`: log decrements and the
//! threshold of cross-coupled stiffness, against the single-DOF closed form
//! `Q = c √(k/m)` and against modal analyses of the model with the
//! cross-coupling written as a linear bearing (an independent assembly path).

use std::f64::consts::PI;
use std::process::Command;

use rotor_bearing::analysis::modal::{ModalOptions, Whirl, modes};
use rotor_bearing::analysis::stability::{mid_span_node, stability};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;

#[path = "common/sdof.rs"]
mod sdof;
use sdof::{K_EACH, MASS, ZETA, sdof_model};

/// `text` with a linear bearing `[[0, q], [−q, 0]]` (N/m) at `node` (1-based).
fn with_cross_coupled_bearing(text: &str, node: usize, q: f64) -> Rotor {
    let extra = format!(
        "\n[[bearings]]\nname = \"cross_coupling\"\ntype = \"linear\"\nnode = {node}\nkxy = {q:?}\nkyx = {:?}\n",
        -q
    );
    Rotor::new(RotorModel::from_toml(&format!("{text}{extra}"), "q.toml").unwrap()).unwrap()
}

/// Smallest log decrement of the forward modes among the first 8.
fn least_forward_log_dec(rotor: &Rotor, speed: f64) -> f64 {
    modes(
        rotor,
        speed,
        &ModalOptions {
            modes: 8,
            ..Default::default()
        },
    )
    .unwrap()
    .iter()
    .filter(|m| m.whirl == Whirl::Forward)
    .map(|m| m.log_decrement)
    .fold(f64::INFINITY, f64::min)
}

#[test]
fn single_dof_threshold_is_c_times_the_natural_frequency() {
    let text = sdof_model();
    let rotor = Rotor::new(RotorModel::from_toml(&text, "sdof.toml").unwrap()).unwrap();
    let speed = 1000.0 * PI / 30.0;
    assert_eq!(mid_span_node(&rotor), 1);
    let result = stability(&rotor, speed, 2e5, 11, 6).unwrap();
    // No cross-coupling: δ = 2πζ/√(1 − ζ²) of the translational forward mode.
    let m0 = &result.curve[0].1;
    let identity = 2.0 * PI * m0.damping_ratio / (1.0 - m0.damping_ratio.powi(2)).sqrt();
    assert!((m0.log_decrement - identity).abs() < 1e-12 * identity);
    let analytic = 2.0 * PI * ZETA / (1.0 - ZETA * ZETA).sqrt();
    assert!(
        (m0.log_decrement / analytic - 1.0).abs() < 1e-4,
        "δ {}",
        m0.log_decrement
    );
    // m z̈ + c ż + (k − iQ) z = 0 loses stability at Q = c √(k/m) = 2ζ k.
    let k = 2.0 * K_EACH;
    let c = 2.0 * ZETA * (k * MASS).sqrt();
    let expected = c * (k / MASS).sqrt();
    let q = result.threshold.unwrap();
    eprintln!(
        "threshold {q} N/m, closed form {expected} N/m ({:.1e})",
        q / expected - 1.0
    );
    // Model error: the shaft's bending and shear flexibility between the disk and
    // the dampers (measured −8.5e-5).
    assert!((q / expected - 1.0).abs() < 2e-4);
    // Independent check: the cross-coupling assembled as a bearing at the disk.
    let at = |f: f64| least_forward_log_dec(&with_cross_coupled_bearing(&text, 2, f * q), speed);
    let (below, on, above) = (at(0.99), at(1.0), at(1.01));
    eprintln!("δ at 0.99, 1, 1.01 × threshold: {below:.3e}, {on:.3e}, {above:.3e}");
    assert!(on.abs() < 1e-4 && below > 0.0 && above < 0.0);
}

#[test]
fn command_threshold_on_the_damped_classic_rotor_is_where_the_log_dec_crosses_zero() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/models/classic_disk_rotor_damped.toml"
    );
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("stability");
    std::fs::create_dir_all(&dir).unwrap();
    let (csv, png) = (dir.join("s.csv"), dir.join("s.png"));
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(["stability", path, "--rpm", "3000", "--csv"])
        .arg(&csv)
        .arg("--png")
        .arg(&png)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // Printed log decrements agree with the printed damping ratios, δ = 2πζ/√(1 − ζ²),
    // to the 6 printed digits.
    let mut rows = 0;
    for line in stdout.lines().skip(2).take(8) {
        let c: Vec<f64> = line
            .split_whitespace()
            .take(4)
            .map(|v| v.parse().unwrap())
            .collect();
        let (zeta, delta) = (c[2], c[3]);
        let identity = 2.0 * PI * zeta / (1.0 - zeta * zeta).sqrt();
        assert!((delta - identity).abs() < 5e-6 * 2.0 * PI + 1e-6, "{line}");
        rows += 1;
    }
    assert_eq!(rows, 8);
    assert!(stdout.contains("at node 4 (mid-span"), "{stdout}");
    let line = stdout
        .lines()
        .find(|l| l.starts_with("threshold Q = "))
        .unwrap_or_else(|| panic!("{stdout}"));
    let q: f64 = line["threshold Q = ".len()..]
        .split_whitespace()
        .next()
        .unwrap()
        .parse()
        .unwrap();
    let text = std::fs::read_to_string(path).unwrap();
    let speed = 3000.0 * PI / 30.0;
    let at = |f: f64| least_forward_log_dec(&with_cross_coupled_bearing(&text, 4, f * q), speed);
    // The printed Q has 6 digits: |δ| at it is below 1e-4.
    let (below, on, above) = (at(0.99), at(1.0), at(1.01));
    eprintln!("threshold {q} N/m; δ at 0.99, 1, 1.01 ×: {below:.3e}, {on:.3e}, {above:.3e}");
    assert!(on.abs() < 1e-4 && below > 0.0 && above < 0.0);
    let table = std::fs::read_to_string(&csv).unwrap();
    assert!(
        table.starts_with("cross_coupling_N_m,damped_frequency_hz,damping_ratio,log_decrement\n")
    );
    assert_eq!(table.lines().count(), 22);
    // Its first row (Q = 0) is the least damped forward mode of the model itself.
    let first: Vec<f64> = table
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .map(|c| c.parse().unwrap())
        .collect();
    assert_eq!(first[0], 0.0);
    let rotor = Rotor::new(RotorModel::from_file(std::path::Path::new(path)).unwrap()).unwrap();
    assert!((first[3] - least_forward_log_dec(&rotor, speed)).abs() < 1e-12);
    assert_eq!(&std::fs::read(&png).unwrap()[..8], b"\x89PNG\r\n\x1a\n");
}

#[test]
fn a_standstill_or_a_bad_range_is_refused_by_name() {
    for (args, needle) in [
        (&["--rpm", "0"][..], "--rpm must be a nonzero speed"),
        (
            &["--rpm", "3000", "--cross-coupling-max=-5"][..],
            "--cross-coupling-max must be positive",
        ),
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
            .arg("stability")
            .args(args)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            !out.status.success() && stderr.contains(needle),
            "{args:?}: {stderr}"
        );
    }
}
