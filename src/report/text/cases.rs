//! `rotor cases`: every tolerance case's criteria as a table and the case
//! that governs each criterion ([`crate::analysis::tolerance_cases`]).

use std::fmt::Write;

use crate::analysis::tolerance_cases::{CasesStudy, Criterion, Governing, Outcome};
use crate::units::RAD_S_TO_RPM;

use super::short;

/// One criterion's value in one case as printed: the value in the label's
/// unit (`FAIL` appended when the case fails it), `—` when not applicable,
/// `error` when its study failed.
pub fn case_value(criterion: Criterion, outcome: &Outcome) -> String {
    match outcome {
        Ok(Some(j)) => {
            let v = short(criterion.shown(j.value));
            if j.pass { v } else { format!("{v} FAIL") }
        }
        Ok(None) => "—".into(),
        Err(_) => "error".into(),
    }
}

/// The governing row of a criterion: its label, the worst value, the
/// governing case (`3: T max, C min, m max`), the failing cases' count and
/// the verdict over every case.
pub fn governing_cells(study: &CasesStudy, g: &Governing) -> [String; 5] {
    let (value, case) = match g.worst {
        Some((i, j)) => (
            short(g.criterion.shown(j.value)),
            format!("{}: {}", i + 1, study.cases[i].case.label),
        ),
        None => ("—".into(), "—".into()),
    };
    [
        g.criterion.label().to_string(),
        value,
        case,
        format!("{} of {}", g.failing.len(), study.cases.len()),
        g.verdict(&study.cases).to_string(),
    ]
}

/// The first line: the model, speed, operating range and the case count.
pub fn cases_heading(name: &str, study: &CasesStudy) -> String {
    let n = study.cases.len();
    format!(
        "Tolerance cases of {name} at {} rpm, margins against {} to {} rpm: {n} cases (the nominal model and the {} combinations of the ranges' ends).",
        short(study.speed * RAD_S_TO_RPM),
        short(study.operating.min * RAD_S_TO_RPM),
        short(study.operating.max * RAD_S_TO_RPM),
        n - 1
    )
}

/// The whole printout: the cases, each criterion's value per case, the
/// governing case of each, and any study that failed.
pub fn tolerance_cases(name: &str, study: &CasesStudy) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}", cases_heading(name, study));
    let _ = writeln!(s);
    let _ = writeln!(s, "{:>4}  {:<22}  settings", "case", "ends");
    for (i, c) in study.cases.iter().enumerate() {
        let _ = writeln!(
            s,
            "{:>4}  {:<22}  {}",
            i + 1,
            c.case.label,
            c.case.describe()
        );
    }
    for g in &study.governing {
        let _ = writeln!(s);
        let _ = writeln!(s, "{}", g.criterion.label());
        let values: Vec<String> = study
            .cases
            .iter()
            .enumerate()
            .map(|(i, c)| {
                let v = c
                    .outcome(g.criterion)
                    .map_or("—".into(), |o| case_value(g.criterion, o));
                format!("{}: {v}", i + 1)
            })
            .collect();
        let _ = writeln!(s, "  {}", values.join("   "));
    }
    let _ = writeln!(s);
    let _ = writeln!(s, "Governing case of each criterion:");
    let _ = writeln!(
        s,
        "{:<44}  {:>12}  {:<26}  {:>8}  result",
        "criterion", "worst", "case", "failing"
    );
    for g in &study.governing {
        let c = governing_cells(study, g);
        let _ = writeln!(
            s,
            "{:<44}  {:>12}  {:<26}  {:>8}  {}",
            c[0], c[1], c[2], c[3], c[4]
        );
    }
    for (i, c) in study.cases.iter().enumerate() {
        for (k, o) in &c.criteria {
            if let Err(e) = o {
                let _ = writeln!(s, "case {} ({}): {}: {e}", i + 1, c.case.label, k.label());
            }
        }
    }
    s
}
