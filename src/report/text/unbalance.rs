//! The unbalance response tables: peaks, amplification factors and API 684
//! separation margins, amplitudes 0-pk or pk-pk.

use std::fmt::Write;

use crate::analysis::unbalance::{
    LevelKept, Peak, REFINE_AMPLITUDE_RATIO, REFINE_ANGLE_DEG, SeparationMargin, UnbalanceStudy,
    UnbalanceSweep,
};
use crate::units::{Amplitude, RAD_S_TO_RPM};

use super::short;

/// One row of the peak table, as the command prints it and the report shows
/// it: point, peak speed (rpm), amplitude (µm, `amplitude` convention), AF,
/// required and actual separation margins, verdict. An undamped resonance
/// ([`Peak::is_undamped`]) has amplitude "unbounded" and AF "∞".
pub fn peak_cells(
    sweep: &UnbalanceSweep,
    peak: &Peak,
    margin: Option<&SeparationMargin>,
    amplitude: Amplitude,
) -> [String; 7] {
    // An undamped resonance: infinite in theory, its numbers only the
    // refinement's resolution.
    let undamped = peak.is_undamped();
    let af = match peak.amplification_factor {
        _ if undamped => "∞".to_string(),
        Some(a) => format!("{a:.2}"),
        None => "—".to_string(),
    };
    let size = if undamped {
        "unbounded".to_string()
    } else {
        short(peak.amplitude * 1e6 * amplitude.factor())
    };
    let (required, actual, verdict) = match margin {
        Some(m) => (
            m.required
                .map_or("none".to_string(), |r| format!("{:.1} %", 100.0 * r)),
            format!("{:.1} %", 100.0 * m.actual),
            if m.pass { "pass" } else { "FAIL" }.to_string(),
        ),
        None if peak.amplification_factor.is_none() => (
            "—".into(),
            "—".into(),
            no_half_power(sweep, peak.level_kept),
        ),
        None => ("—".into(), "—".into(), "no operating range".into()),
    };
    [
        sweep.points[peak.point].label.clone(),
        format!("{:.1}", peak.speed * RAD_S_TO_RPM),
        size,
        af,
        required,
        actual,
        verdict,
    ]
}

/// Why a peak has no AF: on which side, and up to which end of the sweep,
/// the response stays above `1/√2` of the peak (the sweep's ends in rpm).
fn no_half_power(sweep: &UnbalanceSweep, kept: Option<LevelKept>) -> String {
    let rpm = |s: Option<&f64>| short(s.copied().unwrap_or(0.0) * RAD_S_TO_RPM);
    let (lo, hi) = (rpm(sweep.speeds.first()), rpm(sweep.speeds.last()));
    let hint = "a heavily damped mode, or a sweep that ends too soon";
    match kept {
        Some(LevelKept::Below) => format!(
            "no AF: below the peak the response stays above 1/√2 of it down to the sweep's start, {lo} rpm ({hint})"
        ),
        Some(LevelKept::Above) => format!(
            "no AF: above the peak the response stays above 1/√2 of it up to the sweep's end, {hi} rpm ({hint})"
        ),
        Some(LevelKept::Both) | None => format!(
            "no AF: the response stays above 1/√2 of the peak over the whole sweep, {lo} … {hi} rpm ({hint})"
        ),
    }
}

/// The table of unbalance response peaks `rotor unbalance` prints: point, peak
/// speed (rpm), major semi-axis (µm), amplification factor, required and actual
/// separation margins (%) and the verdict. An undamped resonance
/// ([`Peak::is_undamped`]) shows amplitude "unbounded" and AF "∞" (its margin
/// is the one required for any AF past the cap). A peak whose response stays
/// above its half-power level to an end of the sweep has no AF (and no
/// margin), and the row says on which side; a row with an AF but no margin
/// had no operating range to measure from.
pub fn peak_table(
    sweep: &UnbalanceSweep,
    rows: &[(Peak, Option<SeparationMargin>)],
    amplitude: Amplitude,
) -> String {
    let mut s = format!(
        "point                      speed (rpm) {:>15}        AF  required SM  actual SM  result\n",
        format!("µm {}", amplitude.label())
    );
    for (peak, margin) in rows {
        let c = peak_cells(sweep, peak, margin.as_ref(), amplitude);
        writeln!(
            s,
            "{:<26} {:>11} {:>15} {:>9} {:>12} {:>10}  {}",
            c[0], c[1], c[2], c[3], c[4], c[5], c[6]
        )
        .ok();
    }
    if rows.is_empty() {
        s.push_str("(no peak inside the speed range)\n");
    }
    s
}

/// What `rotor unbalance` prints (the report shows the same): the excitation
/// and speed range with the origin of its top, the refined grid, the
/// operating range, and the table of peaks ([`peak_table`]).
pub fn unbalance_study(
    name: &str,
    excitation: &str,
    study: &UnbalanceStudy,
    amplitude: Amplitude,
) -> String {
    let mut s = unbalance_heading(name, excitation, study);
    match &study.operating {
        Some(r) => writeln!(
            s,
            "operating range {:.1} … {:.1} rpm (API 684 separation margins)",
            r.min * RAD_S_TO_RPM,
            r.max * RAD_S_TO_RPM
        ),
        None => writeln!(
            s,
            "no operating range (speed_rpm or --operating-rpm): margins not judged"
        ),
    }
    .ok();
    s.push_str(&peak_table(&study.sweep, &study.rows, amplitude));
    s
}

/// The first lines of [`unbalance_study`]: the excitation, the speed range
/// with the origin of its top, and the refined grid.
pub fn unbalance_heading(name: &str, excitation: &str, study: &UnbalanceStudy) -> String {
    let speeds = &study.sweep.speeds;
    let (lo, hi) = (
        speeds.first().copied().unwrap_or(0.0),
        speeds.last().copied().unwrap_or(0.0),
    );
    let mut s = format!(
        "unbalance response of {name} to {excitation}, {} … {} rpm",
        short(lo * RAD_S_TO_RPM),
        short(hi * RAD_S_TO_RPM)
    );
    if let Some(origin) = &study.top_origin {
        write!(s, " (top speed: {origin})").ok();
    }
    writeln!(
        s,
        ":\n{} speeds: {} evenly spaced, refined where the response turns faster than {}° or grows by {}× between neighbours",
        speeds.len(),
        study.base_points,
        REFINE_ANGLE_DEG,
        REFINE_AMPLITUDE_RATIO
    )
    .ok();
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn peak_table_prints_every_column_and_the_verdict() {
        use crate::analysis::unbalance::{ResponsePoint, UnbalanceSweep};
        let sweep = UnbalanceSweep {
            speeds: vec![0.0, 6000.0 / RAD_S_TO_RPM],
            points: vec![ResponsePoint {
                label: "probe disk".into(),
                node: 3,
            }],
            response: vec![],
        };
        let peak = Peak {
            point: 0,
            speed: 1000.0 / RAD_S_TO_RPM,
            amplitude: 12.5e-6,
            half_power: Some((1.0, 2.0)),
            amplification_factor: Some(4.0),
            level_kept: None,
        };
        let margin = SeparationMargin {
            required: Some(0.16),
            actual: 0.125,
            pass: false,
        };
        let no_af = Peak {
            amplification_factor: None,
            half_power: None,
            level_kept: Some(LevelKept::Above),
            ..peak
        };
        let rows = [(peak, Some(margin)), (peak, None), (no_af, None)];
        let table = peak_table(&sweep, &rows, Amplitude::ZeroToPeak);
        let pk_pk = peak_table(&sweep, &rows, Amplitude::PeakToPeak);
        assert!(table.starts_with("point                      speed (rpm)         µm 0-pk "));
        assert!(pk_pk.lines().next().unwrap().contains("µm pk-pk"));
        assert_eq!(
            pk_pk.lines().nth(1).unwrap().split_whitespace().nth(3),
            Some("25")
        );
        let lines: Vec<&str> = table.lines().collect();
        let cells: Vec<&str> = lines[1].split_whitespace().collect();
        assert_eq!(
            cells,
            [
                "probe", "disk", "1000.0", "12.5", "4.00", "16.0", "%", "12.5", "%", "FAIL"
            ]
        );
        assert!(lines[2].ends_with("no operating range"), "{}", lines[2]);
        assert!(
            lines[3].ends_with(
                "no AF: above the peak the response stays above 1/√2 of it up to the sweep's end, 6000 rpm (a heavily damped mode, or a sweep that ends too soon)"
            ),
            "{}",
            lines[3]
        );
    }
}
