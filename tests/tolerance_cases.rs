//! `[cases]` and `rotor cases` (issue 48): the tolerance cases run every
//! combination of the oil temperature, clearance and preload ends, and the
//! worst case printed for each criterion is the worst of the cases computed
//! here one by one — each case's model written out as its own model file
//! (the viscosity from the oil law, the clearance and the preload as keys),
//! judged by the library's studies, without the cases code.

use std::path::Path;
use std::process::Command;

use rotor_bearing::analysis::api_unbalance::{ApiRequest, api_unbalance};
use rotor_bearing::analysis::campbell::{CampbellRequest, campbell_study};
use rotor_bearing::analysis::level_two::level_two;
use rotor_bearing::analysis::operating_point::operating_point;
use rotor_bearing::analysis::speed_range::OperatingRange;
use rotor_bearing::analysis::stability::{StabilityRequest, stability_study};
use rotor_bearing::analysis::unbalance::{DEFAULT_POINTS, UnbalanceRequest, unbalance_study};
use rotor_bearing::bearing::oil::{CELSIUS_ZERO, Oil};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;

fn model_text() -> String {
    std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/cases_rotor.toml"),
    )
    .unwrap()
}

/// The model file without its `[cases]` section.
fn without_cases(text: &str) -> String {
    text.split("\n[cases]").next().unwrap().to_string()
}

/// The case's own model file: every bearing's `viscosity`, `clearance` and
/// `preload` rewritten.
fn case_file(text: &str, viscosity: f64, clearance: f64, preload: f64) -> String {
    without_cases(text)
        .lines()
        .map(|l| {
            if l.starts_with("viscosity = ") {
                format!("viscosity = {viscosity:e}")
            } else if l.starts_with("clearance = ") {
                format!("clearance = {clearance:e}")
            } else if l.starts_with("preload = ") {
                format!("preload = {preload:e}")
            } else {
                l.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The five criteria computed here for one case at 3000 rpm (the operating
/// range that speed alone): the least stable forward mode's log decrement,
/// the largest amplification factor of the unbalance response, the least
/// minimum film thickness (µm), the least separation margin surplus
/// `SM − SM_required` (%) of the Campbell criticals that need one (+∞ when
/// none does) and the largest API scaled response over its allowed
/// clearance, and API 617 Level II's least log decrement of the judged
/// forward modes at the maximum continuous speed (3000 rpm, the range's top).
fn criteria(text: &str) -> [f64; 6] {
    let rotor = Rotor::new(RotorModel::from_toml(text, "case.toml").unwrap()).unwrap();
    let speed = 3000.0 * std::f64::consts::PI / 30.0;
    let range = OperatingRange {
        min: speed,
        max: speed,
    };
    let campbell = campbell_study(&rotor, &CampbellRequest::default_for(Some(range))).unwrap();
    let surplus = campbell
        .margins
        .iter()
        .filter_map(|m| {
            let sm = m.margin.as_ref()?;
            Some(100.0 * (sm.actual - sm.required?))
        })
        .fold(f64::INFINITY, f64::min);
    let s = stability_study(&rotor, &StabilityRequest::at(speed)).unwrap();
    let log_dec = s.curve[0].1.log_decrement;
    let u = unbalance_study(
        &rotor,
        &UnbalanceRequest {
            min: 0.0,
            max: None,
            points: DEFAULT_POINTS,
            operating: Some(range),
        },
    )
    .unwrap();
    let af = u
        .rows
        .iter()
        .filter_map(|(p, _)| p.amplification_factor)
        .fold(f64::NEG_INFINITY, f64::max);
    let h = operating_point(&rotor, speed)
        .unwrap()
        .iter()
        .filter_map(|p| p.film.as_ref().map(|f| f.min_film_thickness))
        .fold(f64::INFINITY, f64::min);
    let api = api_unbalance(
        &rotor,
        &ApiRequest {
            operating: range,
            max: *u.sweep.speeds.last().unwrap(),
            points: DEFAULT_POINTS,
        },
    )
    .unwrap();
    let clearance = api
        .cases
        .iter()
        .flat_map(|c| &c.criticals)
        .flat_map(|c| &c.clearances)
        .map(|c| c.scaled / c.limit)
        .fold(f64::NEG_INFINITY, f64::max);
    let level = level_two(&rotor, range.max, &[], 8).unwrap();
    let level_two = level.as_built.governing().unwrap().log_decrement;
    [log_dec, af, 1e6 * h, surplus, clearance, level_two]
}

/// The governing row `rotor cases` prints for a criterion: worst value and case number.
fn governing(out: &str, label: &str) -> (f64, usize) {
    let block = out
        .split("Governing case of each criterion:")
        .nth(1)
        .unwrap();
    let line = block
        .lines()
        .find(|l| l.starts_with(label))
        .unwrap_or_else(|| panic!("no governing row {label} in\n{out}"));
    let rest = line[label.len()..].trim_start();
    let mut words = rest.split_whitespace();
    let value: f64 = words.next().unwrap().parse().unwrap();
    let case: usize = words.next().unwrap().trim_end_matches(':').parse().unwrap();
    (value, case)
}

#[test]
fn rotor_cases_runs_every_combination_and_its_worst_case_is_the_worst_of_them() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/cases_rotor.toml");
    let out = rotor_cases(&path);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let out = String::from_utf8(out.stdout).unwrap();
    assert!(
        out.contains(": 5 cases (the nominal model and the 4 combinations"),
        "{out}"
    );

    // The cases, written out one by one: nominal, then T × C (min before max).
    let text = model_text();
    let oil = Oil::iso_vg(32).unwrap();
    let mut files = vec![without_cases(&text)];
    for t in [35.0, 55.0] {
        let mu = oil.dynamic_viscosity(CELSIUS_ZERO + t).unwrap();
        for f in [0.9, 1.1] {
            files.push(case_file(&text, mu, 100e-6 * f, 0.0));
        }
    }
    let results: Vec<[f64; 6]> = files.iter().map(|f| criteria(f)).collect();
    // The cases differ: the check could not pass by one case standing for all.
    let spread = |k: usize| {
        let v: Vec<f64> = results.iter().map(|r| r[k]).collect();
        v.iter().copied().fold(f64::NEG_INFINITY, f64::max)
            - v.iter().copied().fold(f64::INFINITY, f64::min)
    };
    assert!(
        spread(0) > 1e-3 && spread(1) > 1e-3 && spread(2) > 0.1,
        "{results:?}"
    );

    // Every printed value is short()'s 6 significant digits.
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-5 * b.abs().max(1e-12);
    let argext = |k: usize, least: bool| {
        let mut best = 0;
        for (i, r) in results.iter().enumerate() {
            if (least && r[k] < results[best][k]) || (!least && r[k] > results[best][k]) {
                best = i;
            }
        }
        best
    };
    for (label, k, least) in [
        ("log dec, least stable forward mode", 0, true),
        ("amplification factor (largest)", 1, false),
        ("minimum film thickness (µm)", 2, true),
        ("separation margin surplus SM − SM_req (%)", 3, true),
        ("API scaled response / allowed clearance", 4, false),
        ("log dec at MCS (API 617 Level II)", 5, true),
    ] {
        let (value, case) = governing(&out, label);
        let i = argext(k, least);
        assert!(
            close(value, results[i][k]),
            "{label}: printed {value}, the worst of the cases is {} (case {})\n{out}",
            results[i][k],
            i + 1
        );
        assert_eq!(case, i + 1, "{label}\n{out}");
    }
}

#[test]
fn a_model_without_the_section_is_unchanged() {
    let text = model_text();
    let with = RotorModel::from_toml(&text, "m.toml").unwrap();
    let mut without = RotorModel::from_toml(&without_cases(&text), "m.toml").unwrap();
    assert!(with.tolerance_cases.is_some() && without.tolerance_cases.is_none());
    // The nominal case is the model as written.
    let cases = with.tolerance_cases.as_ref().unwrap().cases();
    assert_eq!(cases.len(), 5);
    assert_eq!(with.with_case(&cases[0]), with);
    without.tolerance_cases = with.tolerance_cases.clone();
    assert_eq!(without, with);
    // `rotor cases` on a model without the section says so.
    let dir = std::env::temp_dir().join(format!("tolerance-cases-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("plain.toml");
    std::fs::write(&file, without_cases(&text)).unwrap();
    let out = rotor_cases(&file);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("plain.toml: the model has no [cases] section"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// The right bearing as four tilting pads, preload 0.25, with a preload range.
fn pads_text() -> String {
    model_text()
        .replace(
            "type = \"plain\"\nnode = 9\nradius = 0.02\nlength = 0.02\nclearance = 100e-6\nviscosity = 0.02\n",
            "type = \"tilting_pad\"\nnode = 9\nradius = 0.02\nlength = 0.02\nclearance = 100e-6\nviscosity = 0.02\npads = 4\nfirst_pivot_deg = 45.0\npad_arc_deg = 80.0\npreload = 0.25\n",
        )
        .replace(
            "clearance_factor = [0.9, 1.1]\n",
            "clearance_factor = [0.9, 1.1]\npreload = [0.15, 0.35]\n",
        )
}

/// With all three ranges there are 8 combinations and the nominal case, and
/// each case's model is the model file written with that case's viscosity,
/// clearances and preload — compared whole, field by field.
#[test]
fn three_ranges_give_eight_combinations_each_the_model_written_out() {
    let text = pads_text();
    assert!(text.contains("type = \"tilting_pad\"") && text.contains("preload = [0.15"));
    let model = RotorModel::from_toml(&text, "m.toml").unwrap();
    let cases = model.tolerance_cases.as_ref().unwrap().cases();
    assert_eq!(cases.len(), 9);
    let labels: Vec<&str> = cases.iter().map(|c| c.label.as_str()).collect();
    assert_eq!(labels[0], "nominal");
    assert_eq!(labels[1], "T min, C min, m min");
    assert_eq!(labels[8], "T max, C max, m max");
    let oil = Oil::iso_vg(32).unwrap();
    let mut k = 1;
    for t in [35.0, 55.0] {
        let mu = oil.dynamic_viscosity(CELSIUS_ZERO + t).unwrap();
        for f in [0.9, 1.1] {
            for m in [0.15, 0.35] {
                // The written file's pads section keeps `preload = 0.25`
                // rewritten; the [cases] section goes.
                let written = case_file(&text, mu, 100e-6 * f, m);
                let mut expected = RotorModel::from_toml(&written, "m.toml").unwrap();
                expected.tolerance_cases = model.tolerance_cases.clone();
                let case = &cases[k];
                assert_eq!(case.temperature.unwrap().1, mu);
                assert_eq!(model.with_case(case), expected, "case {}", case.label);
                k += 1;
            }
        }
    }
}

#[test]
fn bad_cases_name_file_line_field_and_value() {
    let base = without_cases(&model_text());
    for (section, line, field, value, words) in [
        (
            "[cases]\niso_vg = 32\noil_temperature_c = [55.0, 35.0]\n",
            3,
            "cases.oil_temperature_c",
            "[55.0, 35.0]",
            "min ≤ max",
        ),
        (
            "[cases]\niso_vg = 150\noil_temperature_c = [35.0, 55.0]\n",
            2,
            "cases.iso_vg",
            "150",
            "22, 32, 46, 68",
        ),
        (
            "[cases]\niso_vg = 46\noil_temperature_c = [-300.0, 50.0]\n",
            3,
            "cases.oil_temperature_c[0]",
            "-300",
            "below absolute zero",
        ),
        (
            "[cases]\niso_vg = 46\noil_temperature_c = [35.0, 2000.0]\n",
            3,
            "cases.oil_temperature_c[1]",
            "2000",
            "[-50, 200] °C",
        ),
        (
            "[cases]\nclearance_factor = [1.1, 0.9]\n",
            2,
            "cases.clearance_factor",
            "[1.1, 0.9]",
            "min ≤ max",
        ),
        (
            "[cases]\npreload = [0.2, 0.3]\n",
            2,
            "cases.preload",
            "[0.2, 0.3]",
            "no tilting-pad bearing",
        ),
        (
            "[cases]\nclearance_factor = [0.0, 1.1]\n",
            2,
            "cases.clearance_factor[0]",
            "0",
            "(0, 2]",
        ),
        (
            "[cases]\noil_temperature_c = [35.0, 55.0]\n",
            2,
            "cases.oil_temperature_c",
            "[35.0, 55.0]",
            "needs the oil",
        ),
    ] {
        let text = format!("{base}\n{section}");
        let first = base.lines().count() + 2;
        let err = RotorModel::from_toml(&text, "bad.toml")
            .unwrap_err()
            .to_string();
        let expected = format!("bad.toml:{}: {field} = {value}", first + line - 1);
        assert!(
            err.starts_with(&expected) && err.contains(words),
            "{err}\nexpected {expected} … {words}"
        );
    }
}

/// Every event of the page, or the parser's complaint: the page is XML.
fn parses_as_xml(html: &str) {
    let mut reader = quick_xml::Reader::from_str(html);
    loop {
        match reader.read_event() {
            Ok(quick_xml::events::Event::Eof) => break,
            Ok(_) => {}
            Err(e) => panic!("the report is not XML at {}: {e}", reader.buffer_position()),
        }
    }
}

/// `rotor cases MODEL`.
fn rotor_cases(model: &Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(["cases", model.to_str().unwrap()])
        .output()
        .unwrap()
}

fn report(model: &Path, page: &Path) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args([
            "report",
            model.to_str().unwrap(),
            "--out",
            page.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let html = std::fs::read_to_string(page).unwrap();
    parses_as_xml(&html);
    html
}

/// `rotor report` of a model with the section: a summary row per criterion
/// with the governing case `rotor cases` prints, and the cases' section;
/// without the section neither.
#[test]
fn the_report_summarizes_the_governing_cases() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/cases_rotor.toml");
    let printed = String::from_utf8(rotor_cases(&path).stdout).unwrap();
    let dir = std::env::temp_dir().join(format!("tolerance-report-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let html = report(&path, &dir.join("with.html"));
    assert!(html.contains("id=\"tolerance-criteria\""));
    let rows: Vec<&str> = html
        .split("<tr>")
        .filter(|r| r.contains(">tolerance cases (worst case)<"))
        .collect();
    let labels = [
        "separation margin surplus SM − SM_req (%)",
        "amplification factor (largest)",
        "log dec, least stable forward mode",
        "log dec at MCS (API 617 Level II)",
        "API scaled response / allowed clearance",
        "minimum film thickness (µm)",
    ];
    assert_eq!(rows.len(), labels.len(), "{rows:?}");
    for label in labels {
        let (value, case) = governing(&printed, label);
        let row = rows.iter().find(|r| r.contains(label)).unwrap();
        let line = printed
            .lines()
            .skip_while(|l| !l.starts_with("Governing case"))
            .find(|l| l.starts_with(label))
            .unwrap();
        let verdict = line.split_whitespace().last().unwrap();
        assert!(
            row.contains(&format!(">{} in case {case}: ", short(value))),
            "{label}: {row}"
        );
        assert!(row.contains(&format!(">{verdict}<")), "{label}: {row}");
    }
    let plain = dir.join("plain.toml");
    std::fs::write(&plain, without_cases(&model_text())).unwrap();
    let html = report(&plain, &dir.join("without.html"));
    assert!(html.contains("id=\"summary-table\""));
    assert!(!html.contains(">tolerance cases (worst case)<") && !html.contains("id=\"cases\""));
    std::fs::remove_dir_all(&dir).ok();
}

/// The printed value as `rotor cases` prints it (`report::text::short`).
fn short(x: f64) -> String {
    rotor_bearing::report::text::short(x)
}

/// A hydro class is judged by its own criteria in every case (issue 48):
/// `rotor cases` on the test rotor as a `hydro_generator` with runaway speed
/// 6000 rpm prints the first critical speed against the runaway speed, the
/// log decrement and the film thickness — no API 684 margin, AF or API
/// criterion — and each case's first critical (and verdict) is that of the
/// case's model written out and run through the Campbell study: the
/// nominal case's 2675 rpm fails, the cold tight case's 6058 rpm passes.
#[test]
fn a_hydro_unit_cases_are_judged_by_its_class_criteria() {
    use rotor_bearing::analysis::tolerance_cases::{Criterion, tolerance_cases};
    let text = model_text().replace("machine = \"compressor\"", "machine = \"hydro_generator\"");
    assert!(text.contains("hydro_generator") && text.contains("max_speed_rpm = 6000"));
    let rotor = Rotor::new(RotorModel::from_toml(&text, "hydro.toml").unwrap()).unwrap();
    let speed = 3000.0 * std::f64::consts::PI / 30.0;
    let range = OperatingRange {
        min: speed,
        max: speed,
    };
    let study = tolerance_cases(&rotor, speed, range).unwrap();
    let kinds: Vec<Criterion> = study.governing.iter().map(|g| g.criterion).collect();
    assert_eq!(
        kinds,
        [
            Criterion::FirstCritical,
            Criterion::LogDecrement,
            Criterion::FilmThickness
        ]
    );
    let oil = Oil::iso_vg(32).unwrap();
    let mut files = vec![without_cases(&text)];
    for t in [35.0, 55.0] {
        let mu = oil.dynamic_viscosity(CELSIUS_ZERO + t).unwrap();
        for f in [0.9, 1.1] {
            files.push(case_file(&text, mu, 100e-6 * f, 0.0));
        }
    }
    let runaway = 6000.0 * std::f64::consts::PI / 30.0;
    let mut verdicts = Vec::new();
    for (case, file) in study.cases.iter().zip(&files) {
        let r = Rotor::new(RotorModel::from_toml(file, "case.toml").unwrap()).unwrap();
        let first = campbell_study(&r, &CampbellRequest::default_for(Some(range)))
            .unwrap()
            .first_critical_speed()
            .unwrap();
        let judged = case
            .outcome(Criterion::FirstCritical)
            .unwrap()
            .clone()
            .unwrap()
            .unwrap();
        assert!(
            (judged.value / first - 1.0).abs() < 1e-12,
            "{}: {} against {first}",
            case.case.label,
            judged.value
        );
        assert_eq!(judged.pass, first > runaway);
        verdicts.push(judged.pass);
    }
    assert_eq!(verdicts, [false, true, false, false, false]);
    let dir = std::env::temp_dir().join(format!("tolerance-hydro-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("hydro.toml");
    std::fs::write(&path, &text).unwrap();
    let out = String::from_utf8(rotor_cases(&path).stdout).unwrap();
    std::fs::remove_dir_all(&dir).ok();
    let (value, case) = governing(&out, "first critical speed (rpm) > runaway");
    assert_eq!(case, 1, "{out}");
    let nominal = study.cases[0].outcome(Criterion::FirstCritical).unwrap();
    let rpm = nominal.clone().unwrap().unwrap().value * 30.0 / std::f64::consts::PI;
    assert!((value - rpm).abs() <= 1e-5 * rpm, "{value} against {rpm}");
    for api in ["separation margin", "amplification factor", "API"] {
        assert!(!out.contains(api), "{api} in\n{out}");
    }
}

/// With an impeller's stage data the API 617 Level II with the anticipated
/// cross-coupling is a criterion of every case: each case's value is the
/// least log decrement `level_two` gives on that case's model written out,
/// with the impeller's `Q_A` at the maximum continuous speed, and the
/// governing case the one of the least.
#[test]
fn level_two_with_q_a_is_judged_in_every_case() {
    use rotor_bearing::analysis::stability::impeller_stages;
    use rotor_bearing::analysis::tolerance_cases::{Criterion, tolerance_cases};
    let text = model_text().replace(
        "[[disks]]\nname = \"disk\"\nnode = 5\n",
        "[[disks]]\nname = \"disk\"\nrole = \"impeller\"\nstage_power = 2e4\nimpeller_diameter = 0.2\nflow_width = 0.01\nnode = 5\n",
    );
    assert!(text.contains("role = \"impeller\""));
    let rotor = Rotor::new(RotorModel::from_toml(&text, "impeller.toml").unwrap()).unwrap();
    let speed = 3000.0 * std::f64::consts::PI / 30.0;
    let range = OperatingRange {
        min: speed,
        max: speed,
    };
    let study = tolerance_cases(&rotor, speed, range).unwrap();
    let oil = Oil::iso_vg(32).unwrap();
    let mut files = vec![without_cases(&text)];
    for t in [35.0, 55.0] {
        let mu = oil.dynamic_viscosity(CELSIUS_ZERO + t).unwrap();
        for f in [0.9, 1.1] {
            files.push(case_file(&text, mu, 100e-6 * f, 0.0));
        }
    }
    let mut values = Vec::new();
    for (case, file) in study.cases.iter().zip(&files) {
        let r = Rotor::new(RotorModel::from_toml(file, "case.toml").unwrap()).unwrap();
        let l = level_two(&r, range.max, &impeller_stages(&r), 8).unwrap();
        let (_, _, with) = l.anticipated.as_ref().unwrap();
        let expected = with.governing().unwrap().log_decrement;
        let judged = case
            .outcome(Criterion::LevelTwoAnticipated)
            .unwrap()
            .clone()
            .unwrap()
            .unwrap();
        assert!(
            (judged.value - expected).abs() <= 1e-12 * expected.abs(),
            "{}: {} against {expected}",
            case.case.label,
            judged.value
        );
        assert_eq!(judged.pass, expected >= 0.1);
        values.push(expected);
    }
    let least = (0..values.len())
        .min_by(|&a, &b| values[a].total_cmp(&values[b]))
        .unwrap();
    let g = study
        .governing
        .iter()
        .find(|g| g.criterion == Criterion::LevelTwoAnticipated)
        .unwrap();
    assert_eq!(g.worst.unwrap().0, least, "{values:?}");
    println!("Level II with Q_A per case: {values:?}");
}
