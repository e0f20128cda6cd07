//! The API 684/617 unbalance cases of a statically indeterminate rotor
//! (issue 48): a uniform Euler–Bernoulli steel shaft (`shear_deformation =
//! false`) of two equal spans `L` = 1 m on three stiff linear bearings
//! (1e12 N/m, about 2e4 times the span's `48EI/L³` = 4.9e7 N/m) under its own
//! weight `w = ρ A g`.
//!
//! **Three-moment closed form** (Clapeyron, rigid supports, the ends simply
//! supported): `M_A L + 2 M_B (L + L) + M_C L = −w L³/4 − w L³/4`, `M_A =
//! M_C = 0`, so `M_B = −w L²/8`; the end reactions `R_A = R_C = w L/2 + M_B/L
//! = 3 w L/8` and the middle one `R_B = 2 w L − 2 · 3 w L/8 = 5 w L/4`. As
//! static loads (kg): `3/8 ρ A L` at the ends and `5/4 ρ A L` in the middle.
//!
//! **Hand calculation of `U_b`** (`U_b = 6350 W/N` g·mm, `N` = 10 000 rpm):
//! the first mode of the stiffly supported two-span beam is the
//! antisymmetric one (each span a pinned–pinned beam), its largest orbit
//! within one span, so the mid-span plane's `W` is the load of that span's
//! two journals, `3/8 + 5/4 = 13/8 ρ A L` = 100.186 kg (`ρ A L` = 61.6538
//! kg), `U_b` = 6350 · 100.186/10000 = 63.618 g·mm; the quarter-span planes
//! (the second, symmetric mode; its largest orbit again in one span) weigh
//! 3/8 and 5/4 `ρ A L` = 23.120 and 77.067 kg, `U_b` = 14.681 and 48.938 g·mm,
//! at the quarter points of that span.

use rotor_bearing::analysis::api_unbalance::{
    ApiCaseKind, ApiRequest, api_cases, api_unbalance, api_unbalance_amount,
};
use rotor_bearing::analysis::speed_range::OperatingRange;
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;

const RPM: f64 = std::f64::consts::PI / 30.0;

/// `ρ A L` of one span (kg).
fn span_mass() -> f64 {
    7850.0 * std::f64::consts::FRAC_PI_4 * 0.1 * 0.1 * 1.0
}

fn model(bearings: &[usize]) -> String {
    let mut text = String::from(
        r#"name = "two_span_compressor"
machine = "compressor"
speed_rpm = 10000
max_speed_rpm = 14000
gravity = [0.0, -9.81, 0.0]
shear_deformation = false

[[materials]]
name = "steel"
youngs_modulus = 2.1e11
poisson_ratio = 0.3
density = 7850.0

[[shaft]]
length = 2.0
outer_diameter = 0.1
material = "steel"
elements = 16
"#,
    );
    for (k, node) in bearings.iter().enumerate() {
        text.push_str(&format!(
            "\n[[bearings]]\nname = \"b{k}\"\ntype = \"linear\"\nnode = {node}\nkxx = 1e12\nkyy = 1e12\ncxx = 2e4\ncyy = 2e4\n"
        ));
    }
    text
}

fn rotor(text: &str) -> Rotor {
    Rotor::new(RotorModel::from_toml(text, "line.toml").unwrap()).unwrap()
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * b.abs()
}

/// The journal loads equal the three-moment reactions within 1e-4 (the
/// supports' finite stiffness moves them by 7e-6 and 4e-6), and every plane's
/// `W` and `U_b` equal the hand calculation of the module's notes with
/// the same tolerance.
#[test]
fn three_bearing_loads_are_the_three_moment_reactions_and_w_is_the_modes_span() {
    let rotor = rotor(&model(&[1, 9, 17]));
    let mcs = 10000.0 * RPM;
    let (cases, loads) = api_cases(&rotor, mcs).unwrap();
    let m = span_mass();
    let expected = [3.0 / 8.0 * m, 5.0 / 4.0 * m, 3.0 / 8.0 * m];
    assert_eq!(loads.len(), 3);
    for (w, e) in loads.iter().zip(expected) {
        assert!(close(*w, e, 1e-4), "{loads:?} against {expected:?}");
    }
    println!("journal loads {loads:?} kg, three-moment {expected:?} kg");
    assert_eq!(cases.len(), 2, "no overhang: mid-span and quarter-span");
    // Mid-span: the antisymmetric first mode's largest orbit lies in one span.
    let (kind, planes) = &cases[0];
    assert_eq!(*kind, ApiCaseKind::MidSpan);
    assert_eq!(planes.len(), 1);
    let node = planes[0].node;
    assert!(
        (1..8).contains(&node) || (9..16).contains(&node),
        "node {node} inside a span"
    );
    let w = 13.0 / 8.0 * m;
    assert!(close(planes[0].weight, w, 1e-4), "{}", planes[0].weight);
    assert!(close(planes[0].amount, 6350.0 * w / 10000.0 * 1e-6, 1e-4));
    assert!(
        close(planes[0].amount, 63.618e-6, 1e-4),
        "{}",
        planes[0].amount
    );
    assert_eq!(planes[0].applied, 2.0 * planes[0].amount);
    // Quarter-span: the quarter points of one span, each its journal's load.
    let (kind, planes) = &cases[1];
    assert_eq!(*kind, ApiCaseKind::QuarterSpan);
    let nodes = [planes[0].node, planes[1].node];
    assert!(nodes == [2, 6] || nodes == [10, 14], "{nodes:?}");
    let (first, second) = if nodes == [2, 6] {
        (3.0 / 8.0 * m, 5.0 / 4.0 * m)
    } else {
        (5.0 / 4.0 * m, 3.0 / 8.0 * m)
    };
    assert!(close(planes[0].weight, first, 1e-4));
    assert!(close(planes[1].weight, second, 1e-4));
    assert!(close(
        planes[0].amount,
        api_unbalance_amount(planes[0].weight, 10000.0),
        1e-12
    ));
    assert!(close(planes[1].phase, std::f64::consts::PI, 1e-15));
}

/// The whole study runs on the three-bearing line (it was refused before)
/// and prints the three journal loads; two bearings still give their
/// two-bearing statics.
#[test]
fn a_three_bearing_compressor_gets_its_api_cases() {
    let rotor = rotor(&model(&[1, 9, 17]));
    let api = api_unbalance(
        &rotor,
        &ApiRequest {
            operating: OperatingRange {
                min: 9000.0 * RPM,
                max: 10000.0 * RPM,
            },
            max: 14000.0 * RPM,
            points: 60,
        },
    )
    .unwrap();
    assert_eq!(api.journal_loads.len(), 3);
    assert!(!api.cases[0].criticals.is_empty(), "{:?}", api.cases[0]);
    let text = rotor_bearing::report::text::api_unbalance(&api);
    let loads: Vec<String> = api
        .journal_loads
        .iter()
        .map(|w| format!("{} kg", rotor_bearing::report::text::short(*w)))
        .collect();
    assert!(
        text.contains(&format!(
            "journal static loads {}, {} and {}\n",
            loads[0], loads[1], loads[2]
        )),
        "{text}"
    );
    let two = rotor_bearing::analysis::api_unbalance::journal_static_loads(
        &self::rotor(&model(&[1, 17])).model,
        0,
        16,
    );
    let (_, loads) = api_cases(&self::rotor(&model(&[1, 17])), 10000.0 * RPM).unwrap();
    assert_eq!(loads, two.to_vec());
    assert!(close(two[0], span_mass(), 1e-12));
}
