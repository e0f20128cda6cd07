//! The API 684/617 unbalance cases of an API machine (issue 48, acceptance
//! 2) against a hand calculation: `tests/data/api_compressor.toml` is a
//! practically rigid uniform shaft on two identical damped isotropic
//! bearings, so its first forward mode is the cylindrical rigid-body mode, a
//! one-degree-of-freedom oscillator at the mid-span node (where the conical
//! mode has its node):
//!
//! - `M = 7850 · π/4 · 0.1² · 1.0 = 61.653756` kg, `K = 2 · 1e7` N/m,
//!   `C = 2 · 1756` N·s/m;
//! - `ω_n = √(K/M) = 569.55442` rad/s, `ζ = C/(2√(K M)) = 0.050006878`;
//! - response to an unbalance `U` at the centre: `|X| = (U/M) r²/√((1 − r²)² + (2ζr)²)`,
//!   `r = Ω/ω_n`; its peak at `r_p = 1/√(1 − 2ζ²) = 1.0025101`
//!   (`N_c = 5452.4962` rpm) is `(U/M) A_p`, `A_p = 1/(2ζ√(1 − ζ²)) = 10.011150`;
//! - half-power ratios, the roots of `(1 − a) s² + (2a − 4aζ²) s − a = 0`,
//!   `s = r²`, `a = A_p²/2`: `r_1 = 0.95568617`, `r_2 = 1.0569679`, so
//!   `AF = r_p/(r_2 − r_1) = 9.8982328`;
//! - the sweeps reach 1.25 × `max_speed_rpm` = 8750 rpm, past the critical
//!   whatever the operating range;
//! - required separation margins: `17 (1 − 1/(AF − 1.5)) = 14.975765` %
//!   below the range, `min(26, 10 + 14.975765) = 24.975765` % above it.
//!
//! The shaft is a thousand times stiffer than steel, not infinitely stiff:
//! its bending stiffness `48 E I/L³ = 4.9e10` N/m against the bearings' 2e7
//! moves the mode by a few 1e-4 (the centre moves 4e-4 more than the
//! journals), the tolerance of the amplitudes and speeds below (1e-3).

use rotor_bearing::analysis::api_unbalance::{
    ApiCaseKind, ApiRequest, ApiUnbalance, api_cases, api_unbalance, journal_static_loads,
    overhung_mass,
};
use rotor_bearing::analysis::speed_range::default_top_speed;
use rotor_bearing::analysis::unbalance::{OperatingRange, model_operating_range};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;

const RPM: f64 = std::f64::consts::PI / 30.0;
const MODEL: &str = include_str!("data/api_compressor.toml");
const MASS: f64 = 61.653_755_826_699_69;
const NC_RPM: f64 = 5_452.496_188_632_287;
const AF: f64 = 9.898_232_768_724_718;
const A_P: f64 = 10.011_149_738_022_297;

fn rotor(text: &str) -> Rotor {
    let model = RotorModel::from_toml(text, "api_compressor.toml").unwrap();
    Rotor::new(model).unwrap()
}

fn run(rotor: &Rotor, operating: OperatingRange) -> ApiUnbalance {
    let (max, _) = default_top_speed(&rotor.model, Some(&operating));
    let request = ApiRequest {
        operating,
        max,
        points: 80,
    };
    api_unbalance(rotor, &request).unwrap()
}

fn range(min_rpm: f64, max_rpm: f64) -> OperatingRange {
    OperatingRange {
        min: min_rpm * RPM,
        max: max_rpm * RPM,
    }
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs()
}

/// The mid-span case at N = 6000 rpm, the critical (5452 rpm) inside the
/// range 5000 … 6000 rpm: every number against the hand calculation.
#[test]
fn mid_span_case_equals_the_hand_calculation() {
    let api = run(&rotor(MODEL), range(5000.0, 6000.0));
    // A_vl = 25.4 √(12000/6000) = 35.92 µm, capped at 25.4 µm.
    assert!((api.vibration_limit - 25.4e-6).abs() < 1e-15);
    let case = &api.cases[0];
    assert_eq!(case.kind, ApiCaseKind::MidSpan);
    // W = M (both journals, 30.826878 kg each); U_b = 6350 · 61.653756/6000
    // = 65.250225 g·mm; applied twice that, at the largest modal
    // displacement: the centre (node 5) of the slightly bending shaft.
    let p = case.planes[0];
    assert_eq!(p.node, 4);
    assert!(close(p.weight, MASS, 1e-12));
    assert!(close(p.amount, 6.525_022_491_659_05e-5, 1e-12));
    assert!(close(p.applied, 2.0 * 6.525_022_491_659_05e-5, 1e-12));
    assert_eq!(case.criticals.len(), 1, "{:?}", case.criticals);
    let c = &case.criticals[0];
    assert!(
        close(c.peak.speed, NC_RPM * RPM, 1e-3),
        "{}",
        c.peak.speed / RPM
    );
    let af = c.peak.amplification_factor.unwrap();
    assert!(close(af, AF, 1e-3), "AF {af}");
    // A_1 = 2 (U/M) A_p = 2 · 2 · 65.250225e-6/61.653756 · 10.011150 = 42.380534 µm pk-pk.
    let a1 = 2.0 * 2.0 * 6.525_022_491_659_05e-5 / MASS * A_P;
    assert!(close(a1, 42.380_533_890_961e-6, 1e-9));
    assert!(close(c.a1, a1, 1e-3), "A1 {}", c.a1);
    // S_cc = 25.4/42.380534 = 0.59933176.
    assert!(close(c.scale_factor, 0.599_331_760_787_877, 1e-3));
    // Inside the range, nearer its minimum: required 14.975765 %, actual
    // −(5452.4962 − 5000)/5452.4962 = −8.2988813 %: FAIL.
    let m = c.margin.unwrap();
    assert!(close(m.required.unwrap(), 0.149_757_646, 1e-3));
    assert!(close(m.actual, -0.082_988_813_376, 2e-3), "{}", m.actual);
    assert!(!m.pass);
    // The seal at the centre: scaled response S_cc A_1 = A_vl = 25.4 µm
    // against 0.75 · 2 · 200 µm = 300 µm.
    let seal = &c.clearances[0];
    assert_eq!(seal.label, "seal balance_piston");
    assert!(close(seal.scaled, 25.4e-6, 1e-9), "{}", seal.scaled);
    assert!(close(seal.limit, 300e-6, 1e-12) && seal.pass);
    // The quarter-spans, out of phase: nodes 3 and 7 (z = 0.25, 0.75 m), each
    // W = M/2, at 0° and 180°; the conical mode they excite (about 9400 rpm,
    // `rotor modes`) lies above the sweep (8750 rpm).
    let q = api.cases.last().unwrap();
    assert_eq!(q.kind, ApiCaseKind::QuarterSpan);
    assert_eq!([q.planes[0].node, q.planes[1].node], [2, 6]);
    assert!(close(q.planes[0].weight, MASS / 2.0, 1e-12));
    assert!((q.planes[1].phase - std::f64::consts::PI).abs() < 1e-15);
    assert!(q.criticals.is_empty(), "{:?}", q.criticals);
    assert_eq!(api.cases.len(), 2, "no overhang: no overhung case");
}

/// Without `--operating-rpm` the range is `speed_rpm` = 3000: the same
/// critical passes (24.975765 % required above the range, actual
/// (5452.4962 − 3000)/3000 = 81.749873 %); N = 3000 rpm doubles U_b, A_1 =
/// 84.761068 µm, and A_vl/A_1 = 0.29967 is raised to S_cc = 0.5.
#[test]
fn the_same_critical_passes_without_the_range() {
    let rotor = rotor(MODEL);
    let operating = model_operating_range(&rotor).unwrap();
    assert!(close(operating.max, 3000.0 * RPM, 1e-15));
    let api = run(&rotor, operating);
    let c = &api.cases[0].criticals[0];
    let m = c.margin.unwrap();
    assert!(close(m.required.unwrap(), 0.249_757_646, 1e-3));
    assert!(close(m.actual, 0.817_498_729_5, 2e-3), "{}", m.actual);
    assert!(m.pass);
    assert!(close(c.a1, 84.761_067_781_922e-6, 1e-3), "{}", c.a1);
    assert_eq!(c.scale_factor, 0.5);
    assert!(close(c.clearances[0].scaled, 0.5 * c.a1, 1e-9));
}

/// Above 12000 rpm the limit falls: N = 15000 rpm, A_vl = 25.4 √0.8 =
/// 22.718451 µm; U_b = 6350 · 61.653756/15000 = 26.100090 g·mm, A_1 =
/// 16.952214 µm, S_cc = 1.3401466; the critical below the range 12000 …
/// 15000 rpm by (12000 − 5452.4962)/5452.4962 = 120.08 % passes.
#[test]
fn the_limit_and_scale_factor_above_12000_rpm() {
    let api = run(&rotor(MODEL), range(12000.0, 15000.0));
    assert!(close(api.vibration_limit, 22.718_450_651_397_86e-6, 1e-12));
    let case = &api.cases[0];
    assert!(close(case.planes[0].amount, 26.100_089_966_636_2e-6, 1e-12));
    let c = &case.criticals[0];
    assert!(close(c.a1, 16.952_213_556_384_42e-6, 1e-3), "{}", c.a1);
    assert!(close(c.scale_factor, 1.340_146_558_196_337, 1e-3));
    let m = c.margin.unwrap();
    assert!(close(m.actual, 1.200_826_847_9, 1e-3) && m.pass);
}

/// A seal whose clearance is 15 µm: 75 % of its 30 µm diametral clearance
/// is 22.5 µm, below the scaled response A_vl = 25.4 µm: FAIL. (Without
/// gravity: the journals' 30 µm sag would close so tight a seal; the API
/// weights are masses, not the gravity load, and do not change.)
#[test]
fn a_tight_seal_fails_the_clearance_check() {
    let text = MODEL
        .replace("clearance = 200e-6", "clearance = 15e-6")
        .replace("gravity = [0.0, -9.81, 0.0]", "gravity = [0.0, 0.0, 0.0]");
    let api = run(&rotor(&text), range(5000.0, 6000.0));
    let seal = &api.cases[0].criticals[0].clearances[0];
    assert!(close(seal.limit, 22.5e-6, 1e-12));
    assert!(close(seal.scaled, 25.4e-6, 1e-9));
    assert!(!seal.pass);
}

/// The overhung case and two-bearing statics: the right bearing moved to
/// node 7 (z = 0.75 m) and a 10 kg coupling hub at the free end (node 9,
/// z = 1.0 m). Shaft elements of M/8 = 7.7067195 kg at their midpoints:
/// `W_right = (M · 0.5 + 10 · 1.0)/0.75 = 54.435837` kg, `W_left = M + 10 −
/// W_right = 17.217919` kg; outboard of the right bearing two elements and
/// the hub, `2 M/8 + 10 = 25.413439` kg, placed at the hub;
/// U_b = 6350 · 25.413439/6000 = 26.895890 g·mm.
#[test]
fn overhung_weight_and_journal_loads_by_statics() {
    let text = MODEL.replace("node = 9\nkxx", "node = 7\nkxx")
        + "\n[[disks]]\nname = \"coupling\"\nnode = 9\nmass = 10.0\npolar_inertia = 0.01\ndiametral_inertia = 0.005\n";
    let rotor = rotor(&text);
    let loads = journal_static_loads(&rotor.model, 0, 6);
    assert!(close(loads[0], 17.217_918_608_899_9, 1e-12), "{loads:?}");
    assert!(close(loads[1], 54.435_837_217_799_8, 1e-12));
    assert!(close(
        overhung_mass(&rotor.model, 6, true),
        25.413_438_956_674_92,
        1e-12
    ));
    assert_eq!(overhung_mass(&rotor.model, 0, false), 0.0);
    let (cases, _) = api_cases(&rotor, 6000.0 * RPM).unwrap();
    let (kind, planes) = &cases[1];
    assert_eq!(*kind, ApiCaseKind::Overhung { last_end: true });
    assert_eq!(planes[0].node, 8);
    assert!(close(planes[0].amount, 26.895_889_562_480e-6, 1e-9));
    assert_eq!(cases.len(), 3);
}

/// `rotor unbalance` on the model written to a temporary directory.
fn cli(text: &str, tag: &str, args: &[&str]) -> String {
    let dir = std::env::temp_dir().join(format!("api_unbalance_{}_{tag}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("api_compressor.toml");
    std::fs::write(&path, text).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg("unbalance")
        .arg(&path)
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    std::fs::remove_dir_all(&dir).ok();
    String::from_utf8(out.stdout).unwrap()
}

/// The command prints the library's cases: the mid-span critical FAILS with
/// `--operating-rpm 5000:6000` and passes against `speed_rpm`; as `generic`
/// (and without the key) the output is today's, byte for byte, with no API
/// case.
#[test]
fn the_command_prints_the_cases_for_api_classes_only() {
    let row = |out: &str| {
        let at = out.find("case mid-span").expect("the mid-span case");
        out[at..].lines().nth(2).unwrap().to_string()
    };
    let fail = cli(MODEL, "range", &["--operating-rpm", "5000:6000"]);
    let r = row(&fail);
    assert!(r.starts_with("probe mid") && r.ends_with("FAIL"), "{r}");
    assert!(r.contains(" 42.39"), "A1 printed as the library's: {r}");
    assert!(fail.contains("applied 130.5 g·mm at 0°"), "{fail}");
    let pass = cli(MODEL, "speed", &[]);
    assert!(row(&pass).ends_with("pass"), "{pass}");
    let generic = cli(
        &MODEL.replace("machine = \"compressor\"", "machine = \"generic\""),
        "generic",
        &["--operating-rpm", "5000:6000"],
    );
    let none = cli(
        &MODEL.replace("machine = \"compressor\"\n", ""),
        "none",
        &["--operating-rpm", "5000:6000"],
    );
    assert_eq!(generic, none);
    assert!(!generic.contains("API 684/617 unbalance cases"));
    assert!(fail.starts_with(&generic), "the API cases are appended");
    for class in ["steam_turbine", "pump"] {
        let out = cli(
            &MODEL.replace("\"compressor\"", &format!("\"{class}\"")),
            class,
            &["--operating-rpm", "5000:6000"],
        );
        assert_eq!(row(&out), r, "{class}");
    }
}

/// The report's summary rows and table cells say what the command prints.
#[test]
fn the_report_rows_are_the_commands_cells() {
    use rotor_bearing::report::api::summary_rows;
    use rotor_bearing::report::text::api_critical_cells;
    let api = run(&rotor(MODEL), range(5000.0, 6000.0));
    let rows = summary_rows(&Ok(&api));
    let c = &api.cases[0].criticals[0];
    let cells = api_critical_cells(c);
    assert_eq!(rows.len(), 1);
    assert_eq!(rows[0][4].text, cells[8]);
    assert_eq!(cells[8], "FAIL");
    assert!(
        rows[0][2]
            .text
            .contains(&format!("A1 {} µm pk-pk", cells[2]))
    );
}

/// On fluid films the first forward modes at 3000 rpm are the films' own,
/// heavily damped (ζ 0.98 and 0.73 on `models/jeffcott.toml`, `rotor
/// modes`): the mid-span plane goes where the first mode that can resonate
/// (ζ 0.26, the disk bouncing on the bent shaft) moves most, the disk at
/// node 5, not a journal; W = 7850 · π/4 · 0.04² · 0.5 + 20 = 24.932375 kg.
#[test]
fn the_mid_span_plane_skips_the_films_overdamped_modes() {
    let text = include_str!("../models/jeffcott.toml").replacen(
        "speed_rpm = 3000",
        "machine = \"compressor\"\nspeed_rpm = 3000",
        1,
    );
    let (cases, loads) = api_cases(&rotor(&text), 3000.0 * RPM).unwrap();
    let (kind, planes) = &cases[0];
    assert_eq!(*kind, ApiCaseKind::MidSpan);
    assert_eq!(planes[0].node, 4);
    let w = 7850.0 * std::f64::consts::PI / 4.0 * 0.04 * 0.04 * 0.5 + 20.0;
    assert!(close(planes[0].weight, w, 1e-12), "{}", planes[0].weight);
    assert!(close(loads[0], w / 2.0, 1e-12) && close(loads[1], w / 2.0, 1e-12));
    // The quarter-spans, out of phase, leave the disk's probe on the node of
    // what they excite: its round-off (1e-18 m) makes no criticals; the
    // mid-span case has the one peak of the disk (no AF: the sweep ends at
    // 3750 rpm above it, as `rotor unbalance` says).
    let api = run(&rotor(&text), range(2500.0, 3000.0));
    for case in &api.cases {
        for c in &case.criticals {
            assert!(c.a1 > 1e-6, "{:?}: {c:?}", case.kind);
        }
    }
    assert_eq!(api.cases[0].criticals.len(), 1);
    assert_eq!(api.cases[0].criticals[0].point, "probe disk");
}

/// `rotor report` of the compressor with the range: its unbalance section has
/// the cases' table, and its summary the mid-span critical's FAIL row with
/// the command's numbers.
#[test]
fn the_report_of_a_compressor_judges_its_api_cases() {
    let dir = std::env::temp_dir().join(format!("api_unbalance_report_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let page = dir.join("report.html");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args([
            "report",
            "tests/data/api_compressor.toml",
            "--operating-rpm",
        ])
        .arg("5000:6000")
        .arg("--out")
        .arg(&page)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let html = std::fs::read_to_string(&page).unwrap();
    std::fs::remove_dir_all(&dir).ok();
    assert!(html.contains("id=\"api-unbalance\""));
    let at = html.find(">API unbalance case<").expect("a summary row");
    let row = &html[at..at + html[at..].find("</tr>").unwrap()];
    assert!(
        row.contains("mid-span (1st mode, in phase), probe mid"),
        "{row}"
    );
    assert!(row.contains("A1 42.39"), "{row}");
    assert!(row.contains("FAIL"), "{row}");
}

/// A seal standing on a pedestal is judged by the journal's motion relative
/// to its housing: with the seal's 1e6 N/m coupling a 50 kg pedestal on
/// 1e6 N/m, the scaled response is `S_cc · 2 r` of `X_journal − X_housing`
/// (the pedestal's translations follow the nodes' DOFs on all DOFs), not of
/// the journal alone.
#[test]
fn a_seal_on_a_pedestal_is_judged_relative_to_its_housing() {
    use rotor_bearing::analysis::linear::node_xy;
    use rotor_bearing::analysis::unbalance::{major_semi_axis, response_at};
    use rotor_bearing::model::UnbalancePlane;
    let text = MODEL.replace(
        "kxx = [0.0, 0.0]",
        "kxx = [1e6, 1e6]\nkyy = [1e6, 1e6]\npedestal = \"casing\"",
    ) + "\n[[pedestals]]\nname = \"casing\"\nmass = 50.0\nkxx = 1e6\nkyy = 1e6\ncxx = 500.0\ncyy = 500.0\n";
    let rotor = rotor(&text);
    let api = run(&rotor, range(5000.0, 6000.0));
    let case = &api.cases[0];
    let c = &case.criticals[0];
    let mut model = rotor.model.clone();
    model.unbalances = case
        .planes
        .iter()
        .map(|p| UnbalancePlane {
            name: "u".into(),
            node: p.node,
            magnitude: p.applied,
            phase: p.phase,
        })
        .collect();
    let excited = Rotor::new(model).unwrap();
    let q = response_at(&excited, c.peak.speed).unwrap();
    let (x, y) = node_xy(&q, 4);
    let at = 4 * rotor.model.node_count();
    let relative = major_semi_axis((x - q[at], y - q[at + 1]));
    let absolute = major_semi_axis((x, y));
    let seal = &c.clearances[0];
    assert!(close(seal.scaled, c.scale_factor * 2.0 * relative, 1e-12));
    assert!(
        (relative / absolute - 1.0).abs() > 0.01,
        "the housing moves: {relative} against {absolute}"
    );
}
