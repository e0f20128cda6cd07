//! The tables of complex modes and Campbell diagrams: modes, overdamped
//! roots, critical speeds and their separation margins, round-off as 0.

use std::fmt::Write;

use crate::analysis::campbell::{
    CampbellPoint, CampbellStudy, CriticalMargin, CriticalSpeed, OVERDAMPED_DAMPING_RATIO,
};
use crate::analysis::modal::{Mode, NON_OSCILLATING_DAMPING_RATIO, OverdampedRoot};
use crate::analysis::torsion::TorsionalMode;
use crate::analysis::unbalance::OperatingRange;
use crate::rotor::Rotor;
use crate::units::RAD_S_TO_RPM;

use super::short;

/// What `rotor campbell` prints (the report shows the same): the speed grid
/// and the origin of its top, the 1× critical speeds with their branch, whirl
/// and ζ, the overdamped crossings apart, the API 684 margins, and how many
/// non-oscillating roots the speeds had.
pub fn campbell_study(rotor: &Rotor, study: &CampbellStudy) -> String {
    let model = &rotor.model;
    let first = study.diagram.first().map_or(0.0, |p| p.speed);
    let origin = study
        .top_origin
        .map_or("--max-rpm".to_string(), |o| o.to_string());
    let mut s = format!(
        "speed grid of {}: {:.2} to {:.2} rpm in {} steps (top speed: {origin}{})\n",
        model.name,
        first * RAD_S_TO_RPM,
        study.top * RAD_S_TO_RPM,
        study.diagram.len().saturating_sub(1),
        if rotor.nonlinear_bearings.is_empty() {
            ""
        } else {
            "; fluid-film bearings: from 1 % of the top speed"
        }
    );
    let steps = study.diagram.len().saturating_sub(1);
    if steps != study.requested_steps {
        writeln!(
            s,
            "  (refined from the {} step{} asked for: a mode was not followed across a step)",
            study.requested_steps,
            if study.requested_steps == 1 { "" } else { "s" }
        )
        .ok();
    }
    for (speed, b) in &study.jumps {
        writeln!(
            s,
            "warning: branch {} jumps across the 1× line at {:.2} rpm instead of crossing it: modes may be mistracked; use more --steps",
            b + 1,
            speed * RAD_S_TO_RPM
        )
        .ok();
    }
    for (speed, a, b) in &study.repeated {
        writeln!(
            s,
            "warning: the critical speed {:.2} rpm appears on branches {} and {}: modes may be mistracked; use more --steps",
            speed * RAD_S_TO_RPM,
            a + 1,
            b + 1
        )
        .ok();
    }
    let line = |c: &CriticalSpeed| {
        format!(
            "  {:10.2} rpm ({:9.3} rad/s)  branch {}  {} whirl  ζ = {}\n",
            c.speed * RAD_S_TO_RPM,
            c.speed,
            c.branch + 1,
            c.whirl.label(),
            damping_ratio(c.damping_ratio)
        )
    };
    writeln!(
        s,
        "critical speeds of {} (1× unbalance excitation, ζ < {OVERDAMPED_DAMPING_RATIO}):",
        model.name
    )
    .ok();
    let (overdamped, critical): (Vec<_>, Vec<_>) =
        study.criticals.iter().partition(|c| c.is_overdamped());
    if critical.is_empty() {
        writeln!(s, "  none up to {:.2} rpm", study.top * RAD_S_TO_RPM).ok();
    }
    critical.into_iter().for_each(|c| s.push_str(&line(c)));
    if !overdamped.is_empty() {
        writeln!(
            s,
            "overdamped crossings of the 1× line (ζ ≥ {OVERDAMPED_DAMPING_RATIO}: no resonance peak, not critical speeds):"
        )
        .ok();
        overdamped.into_iter().for_each(|c| s.push_str(&line(c)));
    }
    if model.machine.is_hydro() {
        s.push_str(&runaway_verdict(
            study,
            model.max_speed,
            model.machine.name(),
        ));
    } else {
        s.push_str(&critical_margins(
            &study.margins,
            study.operating.as_ref(),
            study.max_speed,
        ));
    }
    s.push_str(&overdamped_summary(&study.diagram));
    if !study.torsional.is_empty() {
        let lines: Vec<String> = study
            .torsional
            .iter()
            .map(|m| {
                format!(
                    "{:.4} Hz",
                    m.natural_frequency / (2.0 * std::f64::consts::PI)
                )
            })
            .collect();
        writeln!(
            s,
            "torsional modes (horizontal lines, independent of the speed): {} (undamped)",
            lines.join(", ")
        )
        .ok();
    }
    s
}

/// The torsional modes `rotor modes` prints after the lateral ones, in the
/// same columns: the undamped natural frequency `ω` (rad/s, Hz), the damping
/// ratio `ζ = −Re s/|s|` of the damped eigenvalue `s` and its log decrement
/// `2πζ/√(1 − ζ²)`, then the damped frequency `Im s/2π` (Hz), labelled
/// "torsional". The header says which columns are undamped.
pub fn torsional_modes(modes: &[TorsionalMode]) -> String {
    if modes.is_empty() {
        return String::new();
    }
    let mut s = String::from(
        "torsional modes (twist about the shaft axis, independent of the speed; ω and f undamped, f_d damped, ζ from the damped eigenvalue):\n mode    ω (rad/s)      f (Hz)   damping ratio  log dec    f_d (Hz)   whirl\n",
    );
    for (k, m) in modes.iter().enumerate() {
        let z = m.damping_ratio;
        let (zeta, delta) = if z.abs() < ROUND_OFF_DAMPING_RATIO {
            ("0".to_string(), "0".to_string())
        } else {
            (
                format!("{z:.4e}"),
                format!(
                    "{:.4}",
                    2.0 * std::f64::consts::PI * z / (1.0 - z * z).sqrt()
                ),
            )
        };
        writeln!(
            s,
            "{:5} {:12.4} {:11.4} {:>14} {:>9} {:11.4} {:>9}",
            k + 1,
            m.natural_frequency,
            m.natural_frequency / (2.0 * std::f64::consts::PI),
            zeta,
            delta,
            m.damped_frequency() / (2.0 * std::f64::consts::PI),
            "torsional"
        )
        .ok();
    }
    s
}

pub use crate::analysis::modal::ROUND_OFF_DAMPING_RATIO;

/// `ζ` for a table: `{:.3e}`, or `0` below [`ROUND_OFF_DAMPING_RATIO`].
pub fn damping_ratio(z: f64) -> String {
    if z.abs() < ROUND_OFF_DAMPING_RATIO {
        "0".into()
    } else {
        format!("{z:.3e}")
    }
}

/// `ζ` and `δ` of a mode for the tables, round-off printed as 0 (`δ` of a
/// round-off `ζ` is round-off too; never `-0.0000`).
fn zeta_delta(m: &Mode, zeta_digits: usize, delta_digits: usize) -> (String, String) {
    if m.damping_ratio.abs() < ROUND_OFF_DAMPING_RATIO {
        ("0".into(), "0".into())
    } else {
        (
            format!("{:.*e}", zeta_digits, m.damping_ratio),
            format!("{:.*}", delta_digits, m.log_decrement),
        )
    }
}

/// `ζ` and `δ` of a mode as the modes table prints them (round-off as 0).
pub fn zeta_and_log_dec(m: &Mode) -> (String, String) {
    zeta_delta(m, 4, 4)
}

/// The modes table `rotor modes` prints: damped frequency (rad/s, Hz), damping
/// ratio, logarithmic decrement and whirl.
pub fn modes(name: &str, rpm: f64, modes: &[Mode]) -> String {
    let mut s = format!(
        "{name} at {rpm} rpm:\n mode  ω_d (rad/s)    f_d (Hz)   damping ratio  log dec   whirl\n"
    );
    for (k, m) in modes.iter().enumerate() {
        let (zeta, delta) = zeta_delta(m, 4, 4);
        writeln!(
            s,
            "{:5} {:12.4} {:11.4} {:>14} {:>9} {:>9}",
            k + 1,
            m.damped_frequency,
            m.damped_frequency / (2.0 * std::f64::consts::PI),
            zeta,
            delta,
            m.whirl.label()
        )
        .ok();
    }
    s
}

/// The non-oscillating roots of a modal analysis, apart from the modes: the
/// decay rate `−Re λ` (1/s) and time constant of each, or nothing when there
/// are none.
pub fn overdamped_roots(roots: &[OverdampedRoot]) -> String {
    let (growing, decaying): (Vec<&OverdampedRoot>, Vec<&OverdampedRoot>) =
        roots.iter().partition(|r| r.is_growing());
    let mut s = static_divergence(&growing);
    if decaying.is_empty() {
        return s;
    }
    s.push_str(&format!(
        "non-oscillating (overdamped) roots, not modes (ζ ≥ {NON_OSCILLATING_DAMPING_RATIO}, not counted in --modes):\n  decay rate (1/s)  time constant (s)\n"
    ));
    for (r, count) in repeated(&decaying) {
        writeln!(
            s,
            "  {:>16} {:>18}{}",
            short(r.decay_rate()),
            short(r.time_constant()),
            times(count)
        )
        .ok();
    }
    s
}

/// Equal roots (1e-6 relative, e.g. the like pads of one bearing) once each,
/// with their count.
fn repeated<'a>(roots: &[&'a OverdampedRoot]) -> Vec<(&'a OverdampedRoot, usize)> {
    let mut out: Vec<(&OverdampedRoot, usize)> = Vec::new();
    for r in roots {
        match out
            .iter_mut()
            .find(|(q, _)| (q.eigenvalue - r.eigenvalue).norm() <= 1e-6 * r.eigenvalue.norm())
        {
            Some((_, count)) => *count += 1,
            None => out.push((r, 1)),
        }
    }
    out
}

/// ` (×n)` for a root found `n > 1` times.
fn times(count: usize) -> String {
    if count > 1 {
        format!("  (×{count})")
    } else {
        String::new()
    }
}

/// The growing non-oscillating roots of a linearization, as what they are:
/// a static divergence, never "overdamped roots" (nothing when none).
pub fn static_divergence(growing: &[&OverdampedRoot]) -> String {
    if growing.is_empty() {
        return String::new();
    }
    let mut s = format!(
        "STATICALLY UNSTABLE: {} non-oscillating root(s) grow (divergence): the equilibrium this linearization is taken about is not one the bearings can hold (a magnetic pull stiffer than its unloaded films, a negative-stiffness seal); the transient leaves it\n  growth rate (1/s)  doubling time (s)\n",
        growing.len()
    );
    for (r, count) in repeated(growing) {
        writeln!(
            s,
            "  {:>17} {:>17}{}",
            short(-r.decay_rate()),
            short(std::f64::consts::LN_2 / -r.decay_rate()),
            times(count)
        )
        .ok();
    }
    s
}

/// How many non-oscillating roots the speeds of a Campbell diagram had (they
/// are not branches), or nothing when none.
pub fn overdamped_summary(diagram: &[CampbellPoint]) -> String {
    // Growing roots first: speeds at which the linearization diverges.
    let unstable: Vec<&CampbellPoint> = diagram
        .iter()
        .filter(|p| p.overdamped.iter().any(|r| r.is_growing()))
        .collect();
    let mut divergence = String::new();
    if let (Some(first), Some(last)) = (unstable.first(), unstable.last()) {
        divergence = format!(
            "STATICALLY UNSTABLE at {} of {} speeds ({} to {} rpm): a non-oscillating root grows (divergence), the linearization's equilibrium is not one the bearings can hold; the modes there describe no running machine\n",
            unstable.len(),
            diagram.len(),
            short(first.speed * RAD_S_TO_RPM),
            short(last.speed * RAD_S_TO_RPM)
        );
    }
    divergence + &decaying_summary(diagram)
}

/// How many decaying non-oscillating roots the speeds had.
fn decaying_summary(diagram: &[CampbellPoint]) -> String {
    let counts: Vec<usize> = diagram
        .iter()
        .map(|p| p.overdamped.iter().filter(|r| !r.is_growing()).count())
        .collect();
    let (lo, hi) = (
        counts.iter().copied().min().unwrap_or(0),
        counts.iter().copied().max().unwrap_or(0),
    );
    match (lo, hi) {
        (_, 0) => String::new(),
        (lo, hi) if lo == hi => format!(
            "non-oscillating (overdamped) roots: {hi} at every speed, below the listed modes; not branches\n"
        ),
        (lo, hi) => format!(
            "non-oscillating (overdamped) roots: {lo} to {hi} per speed, below the listed modes; not branches\n"
        ),
    }
}

/// One row of the critical speeds' margins, as the command prints it and the
/// report shows it: speed (rpm), AF, required and actual margins, distance
/// from the maximum speed, verdict.
pub fn margin_cells(m: &CriticalMargin) -> [String; 6] {
    let af = if m.amplification_factor.is_finite() {
        format!("{:.2}", m.amplification_factor)
    } else {
        "∞".into()
    };
    let (required, actual, verdict) = match &m.margin {
        Some(sm) => (
            sm.required
                .map_or("none".to_string(), |r| format!("{:.1} %", 100.0 * r)),
            format!("{:.1} %", 100.0 * sm.actual),
            match (sm.pass, m.unbalance_peak) {
                // API 684: a backward crossing unbalance does not excite.
                (true, Some(false)) => "pass (backward, no unbalance peak)",
                (true, _) => "pass",
                (false, _) => "FAIL",
            },
        ),
        None => ("—".into(), "—".into(), "not judged"),
    };
    let from_max = m
        .from_max_speed
        .map_or("—".to_string(), |d| format!("{:+.1} %", 100.0 * d));
    [
        format!("{:.2}", m.critical.speed * RAD_S_TO_RPM),
        af,
        required,
        actual,
        from_max,
        verdict.to_string(),
    ]
}

/// A hydro unit's verdict on its critical speeds (`machine` a hydro class):
/// the first critical speed must lie above the runaway speed `runaway`
/// (rad/s, `max_speed_rpm`); API 684's separation margins are not its
/// criterion.
pub fn runaway_verdict(study: &CampbellStudy, runaway: f64, machine: &str) -> String {
    let runaway_rpm = short(runaway * RAD_S_TO_RPM);
    match study.first_critical_speed() {
        Some(first) => format!(
            "first critical speed {} rpm against the runaway speed {runaway_rpm} rpm (machine = {machine}: above it): {}\n",
            short(first * RAD_S_TO_RPM),
            if first > runaway { "pass" } else { "FAIL" }
        ),
        None => format!(
            "no critical speed up to {} rpm, the runaway speed {runaway_rpm} rpm (machine = {machine}: the first critical above it): {}\n",
            short(study.top * RAD_S_TO_RPM),
            if study.top >= runaway {
                "pass"
            } else {
                "not judged: the diagram stops below the runaway speed"
            }
        ),
    }
}

/// API 684 separation margins of the critical speeds of a Campbell diagram
/// (amplification factor `1/(2ζ)`) from the operating range, and their
/// distance from the maximum speed.
pub fn critical_margins(
    margins: &[CriticalMargin],
    range: Option<&OperatingRange>,
    max_speed: Option<f64>,
) -> String {
    if margins.is_empty() {
        return String::new();
    }
    let mut s = match range {
        Some(r) if r.min == r.max => format!(
            "separation margins (API 684, AF = 1/(2ζ)) from the operating speed {} rpm",
            short(r.min * RAD_S_TO_RPM)
        ),
        Some(r) => format!(
            "separation margins (API 684, AF = 1/(2ζ)) from the operating range {} … {} rpm",
            short(r.min * RAD_S_TO_RPM),
            short(r.max * RAD_S_TO_RPM)
        ),
        None => {
            "critical speeds (no operating speed: speed_rpm or --operating-rpm; margins not judged)"
                .to_string()
        }
    };
    if let Some(m) = max_speed {
        write!(s, ", maximum speed {} rpm", short(m * RAD_S_TO_RPM)).ok();
    }
    s.push_str(":\n   speed (rpm)        AF  required SM  actual SM  from max speed  result\n");
    for m in margins {
        let c = margin_cells(m);
        writeln!(
            s,
            "  {:>12} {:>9} {:>12} {:>10} {:>15}  {}",
            c[0], c[1], c[2], c[3], c[4], c[5]
        )
        .ok();
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::RotorModel;

    /// A critical speed left on two branches after the grid's refinement, and
    /// a branch that jumps across the 1× line, are printed as warnings with
    /// their speeds (rpm) and branches (1-based).
    #[test]
    fn a_repeated_critical_speed_is_a_warning() {
        let rotor = Rotor::new(RotorModel::default_model()).unwrap();
        let study = CampbellStudy {
            diagram: Vec::new(),
            criticals: Vec::new(),
            margins: Vec::new(),
            top: 2000.0,
            top_origin: None,
            operating: None,
            max_speed: None,
            diagram_seconds: 0.0,
            requested_steps: 0,
            repeated: vec![(100.0, 2, 5)],
            jumps: vec![(200.0, 4)],
            torsional: Vec::new(),
        };
        let text = campbell_study(&rotor, &study);
        assert!(
            text.contains(
                "warning: the critical speed 954.93 rpm appears on branches 3 and 6: modes may be mistracked; use more --steps\n"
            ),
            "{text}"
        );
        assert!(
            text.contains(
                "warning: branch 5 jumps across the 1× line at 1909.86 rpm instead of crossing it: modes may be mistracked; use more --steps\n"
            ),
            "{text}"
        );
        assert!(!text.contains("refined from"), "{text}");
    }
}
