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
    // The damped classic rotor's disk sits at mid-span, node 4.
    assert!(stdout.contains("at node 4 (disk disk)"), "{stdout}");
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

/// The pump with its plain bearings replaced by linear bearings of their
/// synchronous K and C at `rpm` (the library's operating point, written into
/// a model file): the rotor the stability analysis adds its cross-coupling
/// to, assembled on an independent path.
fn pump_on_linear_bearings(rpm: f64) -> String {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/my_pump.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let rotor = Rotor::new(RotorModel::from_toml(&text, "pump.toml").unwrap()).unwrap();
    let points =
        rotor_bearing::analysis::operating_point::operating_point(&rotor, rpm * PI / 30.0).unwrap();
    let (head, rest) = text.split_once("[[bearings]]").unwrap();
    let tail = &rest[rest.find("\n# The unbalance").unwrap()..];
    let mut bearings = String::new();
    for (p, b) in points.iter().zip(&rotor.model.bearings) {
        let (k, c) = (p.stiffness, p.damping);
        bearings.push_str(&format!(
            "[[bearings]]\nname = \"{}\"\ntype = \"linear\"\nnode = {}\nkxx = {:?}\nkxy = {:?}\nkyx = {:?}\nkyy = {:?}\ncxx = {:?}\ncxy = {:?}\ncyx = {:?}\ncyy = {:?}\n\n",
            b.name, b.node + 1, k[0][0], k[0][1], k[1][0], k[1][1], c[0][0], c[0][1], c[1][0], c[1][1]
        ));
    }
    format!("{head}{bearings}{tail}")
}

fn run(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

fn number_after(text: &str, key: &str) -> f64 {
    let at = text.find(key).unwrap_or_else(|| panic!("{key} in {text}")) + key.len();
    text[at..]
        .split(|c: char| c.is_whitespace() || c == ':')
        .find(|w| !w.is_empty())
        .unwrap()
        .parse()
        .unwrap_or_else(|e| panic!("{key} in {text}: {e}"))
}

/// Acceptance (issue 27): the Level I screening of the documented example —
/// the quick start's pump at 3600 rpm, 150 kW through one impeller of
/// D = 0.3 m with a 20 mm restrictive width, liquid (ρd/ρs = 1), centrifugal
/// (B = 3) — against a hand calculation from the stated formula, in SI and in
/// API 617's US form, and its verdict from the criteria.
#[test]
fn level_one_of_the_documented_pump_matches_the_hand_calculation() {
    let pump = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/my_pump.toml");
    let stdout = run(&[
        "stability",
        pump,
        "--rpm",
        "3600",
        "--power",
        "150e3",
        "--impeller-diameter",
        "0.3",
        "--flow-width",
        "0.02",
    ]);
    // Hand calculation: Q_A = B P (ρd/ρs) / (D H Ω), Ω = 3600 · 2π/60.
    let omega = 3600.0 * PI / 30.0;
    let qa = 3.0 * 150e3 * 1.0 / (0.3 * 0.02 * omega);
    assert!((qa - 198_943.678_9).abs() < 1e-3, "{qa}");
    // API 617's US form, q_A = B_c C HP / (D_c H_c N) in klbf/in with C = 63.
    let (hp, inch) = (150e3 / 745.699_872, 0.0254);
    let us = 3.0 * 63.0 * hp / ((0.3 / inch) * (0.02 / inch) * 3600.0); // klbf/in
    let us_si = us * 4_448.221_615 / inch; // N/m
    assert!((us_si / qa - 1.0).abs() < 2e-3, "{us_si} vs {qa}");
    let printed = number_after(
        &stdout,
        "= 3 × 150000 W × 1 / (0.3 m × 0.02 m × 376.991 rad/s) = ",
    );
    assert!((printed / qa - 1.0).abs() < 5e-6, "{stdout}");
    // Q0 and δ at Q_A, each checked independently: the cross-coupling
    // written as a linear bearing at the impeller (node 6).
    let q0 = number_after(&stdout, "threshold Q = ");
    let text = pump_on_linear_bearings(3600.0);
    let delta_at = |q: f64| least_forward_log_dec(&with_cross_coupled_bearing(&text, 6, q), omega);
    assert!(delta_at(0.99 * q0) > 0.0 && delta_at(1.01 * q0) < 0.0);
    let delta_a = number_after(&stdout, "log dec at Q_A = ");
    assert!(
        (delta_at(qa) - delta_a).abs() < 5e-5 + 1e-4 * delta_a.abs(),
        "{stdout}"
    );
    let ratio = number_after(&stdout, "stability margin Q0/Q_A = ");
    assert!((ratio - q0 / qa).abs() < 0.006, "{ratio} vs {}", q0 / qa);
    let pass = q0 / qa >= 2.0 && delta_a >= 0.1;
    let verdict = stdout
        .lines()
        .find(|l| l.starts_with("  Level I: "))
        .unwrap();
    assert_eq!(verdict == "  Level I: pass", pass, "{stdout}");
    // The criteria lines carry their own verdicts.
    assert!(stdout.contains(&format!(
        "(at least 2 required): {}",
        if q0 / qa >= 2.0 { "pass" } else { "FAIL" }
    )));
    assert!(stdout.contains(&format!(
        "(at least 0.1 required): {}",
        if delta_a >= 0.1 { "pass" } else { "FAIL" }
    )));
    // Default range with stage data: 0 … 10 Q_A.
    let csv_dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("level_one");
    std::fs::create_dir_all(&csv_dir).unwrap();
    let csv = csv_dir.join("q.csv");
    run(&[
        "stability",
        pump,
        "--rpm",
        "3600",
        "--power",
        "150e3",
        "--impeller-diameter",
        "0.3",
        "--flow-width",
        "0.02",
        "--csv",
        csv.to_str().unwrap(),
    ]);
    let last: f64 = std::fs::read_to_string(&csv)
        .unwrap()
        .lines()
        .last()
        .unwrap()
        .split(',')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!((last / (10.0 * qa) - 1.0).abs() < 1e-12);
}

/// `--at` places the cross-coupling at named nodes, split equally: two
/// linear bearings of Q/2 each at nodes 3 and 9 cross zero at the printed
/// threshold; a disk's name means its node; bad names are refused.
#[test]
fn cross_coupling_at_named_nodes() {
    let pump = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/my_pump.toml");
    let stdout = run(&[
        "stability",
        pump,
        "--rpm",
        "3600",
        "--at",
        "3,9",
        "--cross-coupling-max",
        "3e6",
    ]);
    assert!(
        stdout.contains("split equally over node 3, node 9"),
        "{stdout}"
    );
    let q0 = number_after(&stdout, "threshold Q = ");
    let text = pump_on_linear_bearings(3600.0);
    let omega = 3600.0 * PI / 30.0;
    let two = |q: f64| {
        let extra = |name: &str, node: usize| {
            format!(
                "\n[[bearings]]\nname = \"{name}\"\ntype = \"linear\"\nnode = {node}\nkxy = {:?}\nkyx = {:?}\n",
                q / 2.0,
                -q / 2.0
            )
        };
        let model = format!("{text}{}{}", extra("q3", 3), extra("q9", 9));
        least_forward_log_dec(
            &Rotor::new(RotorModel::from_toml(&model, "q.toml").unwrap()).unwrap(),
            omega,
        )
    };
    assert!(two(0.99 * q0) > 0.0 && two(1.01 * q0) < 0.0, "{q0}");
    let named = run(&["stability", pump, "--rpm", "3600", "--at", "impeller"]);
    assert!(named.contains("at node 6 (disk impeller)"), "{named}");
    let default = run(&["stability", pump, "--rpm", "3600"]);
    assert_eq!(
        named.replace(
            "(disk impeller)",
            "(disk impeller) (API 617: mid-span, the rotor's impellers lie between its bearings)"
        ),
        default,
        "the impeller at mid-span is API 617's site of a between-bearing pump"
    );
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(["stability", pump, "--rpm", "3600", "--at", "runner"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        !out.status.success()
            && stderr.contains(
                "--at \"runner\": not a node number or a disk name (disks: [\"impeller\"])"
            ),
        "{stderr}"
    );
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(["stability", pump, "--rpm", "3600", "--power", "1e5"])
        .output()
        .unwrap();
    assert!(
        String::from_utf8_lossy(&out.stderr)
            .contains("needs --power, --impeller-diameter and --flow-width together")
    );
}

/// API 617's placement of the anticipated cross-coupling (7th ed., 2.6.5):
/// mid-span for a rotor between bearings, seals or not; on an overhung rotor
/// the overhung impellers, each at once, the disks tagged
/// `role = "impeller"` when any is, else every overhung disk; the earlier
/// default (disks and seals) kept for the placement note. A 1 m shaft in 10
/// elements on bearings at nodes 2 and 8 (z = 0.1, 0.7 m).
#[test]
fn the_default_cross_coupling_sits_where_api_617_places_it() {
    use rotor_bearing::analysis::stability::{
        api617_placement, default_sites, disks_and_seals, site_label,
    };
    let rotor_with = |disks: &str| {
        let text = format!(
            "name = \"placement\"\nspeed_rpm = 3000\n[[materials]]\nname = \"steel\"\nyoungs_modulus = 2.1e11\npoisson_ratio = 0.3\ndensity = 7850.0\n[[shaft]]\nlength = 1.0\nouter_diameter = 0.05\nmaterial = \"steel\"\nelements = 10\n[[bearings]]\nname = \"a\"\ntype = \"linear\"\nnode = 2\nkxx = 1e7\nkyy = 1e7\n[[bearings]]\nname = \"b\"\ntype = \"linear\"\nnode = 8\nkxx = 1e7\nkyy = 1e7\n[[seals]]\nname = \"eye\"\nnode = 4\nspeeds_rpm = [0.0, 5000.0]\nkxx = 1e5\nkyy = 1e5\nkxy = 2e4\nkyx = -2e4\n{disks}"
        );
        Rotor::new(RotorModel::from_toml(&text, "placement.toml").unwrap()).unwrap()
    };
    let disk = |name: &str, node: usize, role: &str| {
        format!(
            "[[disks]]\nname = \"{name}\"\nnode = {node}\nmass = 10.0\npolar_inertia = 0.1\ndiametral_inertia = 0.05\n{role}"
        )
    };
    let impeller = "role = \"impeller\"\n";
    // Between bearings (a disk at node 4, a seal at node 4): mid-span, node 5.
    let between = rotor_with(&disk("wheel", 4, impeller));
    let (sites, why) = api617_placement(&between);
    assert_eq!(sites, [5 - 1]);
    assert!(why.contains("mid-span"), "{why}");
    assert_eq!(
        site_label(&between, 4),
        "node 5 (mid-span between the bearings)"
    );
    assert_eq!(disks_and_seals(&between), [3]);
    // Single overhung: the tagged impeller at node 11, not the coupling hub
    // at node 1 (overhung too, but not an impeller) nor the seal.
    let single = rotor_with(&(disk("hub", 1, "") + &disk("stage", 11, impeller)));
    let (sites, why) = api617_placement(&single);
    assert_eq!(sites, [10]);
    assert!(why.contains("overhung impellers"), "{why}");
    // Double overhung: both impellers at once.
    let double = rotor_with(&(disk("one", 1, impeller) + &disk("two", 11, impeller)));
    assert_eq!(default_sites(&double), [0, 10]);
    // Nothing tagged: every overhung disk, said so.
    let untagged = rotor_with(&(disk("one", 1, "") + &disk("mid", 5, "")));
    let (sites, why) = api617_placement(&untagged);
    assert_eq!(sites, [0]);
    assert!(why.contains("no disk has role"), "{why}");
    // A role the file cannot have is refused, naming the field.
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/models/classic_disk_rotor_damped.toml"
    ))
    .unwrap()
    .replacen("[[disks]]", "[[disks]]\nrole = \"propeller\"", 1);
    let err = RotorModel::from_toml(&text, "bad.toml")
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("bad.toml") && err.contains("disks[0].role") && err.contains("\"propeller\""),
        "{err}"
    );
    // The verdict states the placement.
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args([
            "stability",
            concat!(env!("CARGO_MANIFEST_DIR"), "/models/hydro_unit.toml"),
        ])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains("split equally over node 5 (disk generator), node 20 (disk runner) (API 617: at the overhung disks"),
        "{stdout}"
    );
}

/// Wachel per impeller (issue 48): stage data on the impellers
/// (`[[disks]] role = "impeller"`, `stage_power`, `impeller_diameter`,
/// `flow_width`, `density_ratio`, `stage_factor`) give each impeller's
/// `q_A` and their sum `Q_A`, against a hand calculation; the documented
/// pump's data on its impeller give the screening `--power …` gives, number
/// for number; the flags, when given, stand for the whole machine; bad stage
/// data name file, line and field.
#[test]
fn level_one_sums_wachel_over_the_impellers() {
    let pump = include_str!("../examples/my_pump.toml");
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("wachel_impellers");
    std::fs::create_dir_all(&dir).unwrap();
    let write = |name: &str, text: &str| {
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        path.to_string_lossy().into_owned()
    };
    let disk = "[[disks]]\nname = \"impeller\"\nnode = 6";
    assert!(pump.contains(disk));
    let one = write(
        "one.toml",
        &pump.replace(
            disk,
            &format!("{disk}\nrole = \"impeller\"\nstage_power = 150e3\nimpeller_diameter = 0.3\nflow_width = 0.02"),
        ),
    );
    let by_model = run(&["stability", &one, "--rpm", "3600"]);
    let by_flags = run(&[
        "stability",
        &one,
        "--rpm",
        "3600",
        "--power",
        "150e3",
        "--impeller-diameter",
        "0.3",
        "--flow-width",
        "0.02",
    ]);
    let omega = 3600.0 * PI / 30.0;
    let qa = 3.0 * 150e3 / (0.3 * 0.02 * omega);
    let printed = number_after(
        &by_model,
        "impeller: 3 × 150000 W × 1 / (0.3 m × 0.02 m × 376.991 rad/s) = ",
    );
    assert!((printed / qa - 1.0).abs() < 5e-6, "{by_model}");
    assert!(
        by_flags.contains("Q_A = B P (ρd/ρs) / (D H Ω) = 3 × 150000 W"),
        "{by_flags}"
    );
    for key in [
        "threshold Q = ",
        "log dec at Q_A = ",
        "stability margin Q0/Q_A = ",
    ] {
        assert_eq!(
            number_after(&by_model, key),
            number_after(&by_flags, key),
            "{key}"
        );
    }
    let verdict = |t: &str| {
        t.lines()
            .find(|l| l.starts_with("  Level I: "))
            .map(str::to_owned)
    };
    assert_eq!(verdict(&by_model), verdict(&by_flags));
    // Two impellers: the pump's and a second stage (an axial one, a gas).
    let two = write(
        "two.toml",
        &format!(
            "{}\n[[disks]]\nname = \"second\"\nnode = 6\nmass = 1.0\npolar_inertia = 0.0\ndiametral_inertia = 0.0\nrole = \"impeller\"\nstage_power = 50e3\nimpeller_diameter = 0.25\nflow_width = 0.015\ndensity_ratio = 1.2\nstage_factor = 1.5\n",
            std::fs::read_to_string(&one).unwrap()
        ),
    );
    let stdout = run(&["stability", &two, "--rpm", "3600"]);
    let q2 = 1.5 * 50e3 * 1.2 / (0.25 * 0.015 * omega);
    let printed2 = number_after(
        &stdout,
        "second: 1.5 × 50000 W × 1.2 / (0.25 m × 0.015 m × 376.991 rad/s) = ",
    );
    assert!((printed2 / q2 - 1.0).abs() < 5e-6, "{stdout}");
    let total = number_after(&stdout, "Q_A = the sum over the 2 impellers = ");
    assert!((total / (qa + q2) - 1.0).abs() < 5e-6, "{stdout}");
    // Bad stage data: named by file, line and field.
    let bad = |name: &str, text: &str, field: &str| {
        let path = write(name, text);
        let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
            .args(["stability", &path, "--rpm", "3600"])
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{name}");
        // `file:LINE: disks[k].field = value: why`.
        let at = err
            .find(&format!("{name}:"))
            .unwrap_or_else(|| panic!("{err}"));
        let line = err[at + name.len() + 1..].split(':').next().unwrap();
        assert!(
            line.parse::<usize>().is_ok() && err.contains(field),
            "{err}"
        );
    };
    bad(
        "not_impeller.toml",
        &pump.replace(disk, &format!("{disk}\nstage_power = 150e3")),
        "stage_power",
    );
    bad(
        "no_width.toml",
        &pump.replace(
            disk,
            &format!("{disk}\nrole = \"impeller\"\nstage_power = 150e3\nimpeller_diameter = 0.3"),
        ),
        "flow_width",
    );
    std::fs::remove_dir_all(&dir).ok();
}
