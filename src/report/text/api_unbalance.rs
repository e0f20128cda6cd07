//! The API 684/617 unbalance cases of an API machine as text: each case's
//! planes (static weight, `U_b = 4W/N`, applied unbalance), and per critical
//! the AF, separation margins, `A_1`, `S_cc` and the close-clearance check.

use std::fmt::Write;

use crate::analysis::api_unbalance::{
    APPLIED_FACTOR, ApiCase, ApiCritical, ApiUnbalance, CLEARANCE_FRACTION,
};
use crate::units::RAD_S_TO_RPM;

use super::short;

/// Verdict of one critical: `FAIL` when its separation margin or a
/// clearance fails, `pass` when both pass (or no margin is required), else
/// why the margin is not judged.
pub fn api_verdict(c: &ApiCritical) -> String {
    let clear = c.clearances.iter().all(|k| k.pass);
    match &c.margin {
        Some(m) if !m.pass => "FAIL".into(),
        _ if !clear => "FAIL".into(),
        Some(_) => "pass".into(),
        None => "no AF: margin not judged".into(),
    }
}

/// The worst clearance of a critical: `label: scaled/limit µm pk-pk (ratio %)`,
/// or `—` without close clearances.
pub fn worst_clearance(c: &ApiCritical) -> String {
    c.clearances
        .iter()
        .max_by(|a, b| (a.scaled / a.limit).total_cmp(&(b.scaled / b.limit)))
        .map_or("—".into(), |k| {
            format!(
                "{} {}/{} µm ({:.0} %)",
                k.label,
                short(k.scaled * 1e6),
                short(k.limit * 1e6),
                100.0 * k.scaled / k.limit
            )
        })
}

/// One row of a case's criticals: point, speed (rpm), `A_1` (µm pk-pk), AF,
/// required SM, actual SM, `S_cc`, worst clearance, verdict.
pub fn api_critical_cells(c: &ApiCritical) -> [String; 9] {
    let af = match c.peak.amplification_factor {
        _ if c.peak.is_undamped() => "∞".to_string(),
        Some(a) => format!("{a:.2}"),
        None => "—".into(),
    };
    let (required, actual) = match &c.margin {
        Some(m) => (
            m.required
                .map_or("none".to_string(), |r| format!("{:.1} %", 100.0 * r)),
            format!("{:.1} %", 100.0 * m.actual),
        ),
        None => ("—".into(), "—".into()),
    };
    [
        c.point.clone(),
        format!("{:.1}", c.peak.speed * RAD_S_TO_RPM),
        short(c.a1 * 1e6),
        af,
        required,
        actual,
        format!("{:.3}", c.scale_factor),
        worst_clearance(c),
        api_verdict(c),
    ]
}

/// A case's planes: `node N: W = … kg, U_b = … g·mm, applied … g·mm at …°`.
pub fn case_planes(case: &ApiCase) -> String {
    case.planes
        .iter()
        .map(|p| {
            format!(
                "node {}: W = {} kg, U_b = {} g·mm, applied {} g·mm at {}°",
                p.node + 1,
                short(p.weight),
                short(p.amount * 1e6),
                short(p.applied * 1e6),
                short(p.phase.to_degrees())
            )
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// `a kg and b kg`, `a kg, b kg and c kg`, … (by axial position).
fn journal_loads(loads: &[f64]) -> String {
    let each: Vec<String> = loads.iter().map(|w| format!("{} kg", short(*w))).collect();
    match each.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
        Some((last, _)) => last.clone(),
        None => String::new(),
    }
}

/// What `rotor unbalance` and the report print for an API machine: the
/// speeds and limits, then each case's planes and criticals with every
/// close clearance.
pub fn api_unbalance(api: &ApiUnbalance) -> String {
    let n = api.mcs * RAD_S_TO_RPM;
    let mut s = format!(
        "API 684/617 unbalance cases: maximum continuous speed N = {} rpm (operating range {} … {} rpm); U_b = 6350 W/N g·mm (4W/N oz·in), {}× U_b applied per plane; journal static loads {}\n",
        short(n),
        short(api.operating.min * RAD_S_TO_RPM),
        short(n),
        short(APPLIED_FACTOR),
        journal_loads(&api.journal_loads)
    );
    writeln!(
        s,
        "A_vl = 25.4 √(12000/N) µm, at most 25.4 µm: {} µm pk-pk; S_cc = A_vl/A_1 within 0.5 … 6; scaled response ≤ {:.0} % of the diametral running clearance",
        short(api.vibration_limit * 1e6),
        100.0 * CLEARANCE_FRACTION
    )
    .ok();
    for case in &api.cases {
        writeln!(s, "\ncase {}: {}", case.kind.label(), case_planes(case)).ok();
        s.push_str(
            "point                      speed (rpm)  A1 µm pk-pk        AF  required SM  actual SM    S_cc  result\n",
        );
        for c in &case.criticals {
            let r = api_critical_cells(c);
            writeln!(
                s,
                "{:<26} {:>11} {:>12} {:>9} {:>12} {:>10} {:>7}  {}",
                r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[8]
            )
            .ok();
            for k in &c.clearances {
                writeln!(
                    s,
                    "    {:<28} C = {} µm: scaled {} µm pk-pk against {} µm: {}",
                    k.label,
                    short(k.clearance * 1e6),
                    short(k.scaled * 1e6),
                    short(k.limit * 1e6),
                    if k.pass { "pass" } else { "FAIL" }
                )
                .ok();
            }
        }
        if case.criticals.is_empty() {
            s.push_str("(no peak inside the speed range)\n");
        }
    }
    s
}
