//! The verdict lines of `rotor unbalance` and `rotor stability` for a hydro
//! class (`machine = "hydro_generator" | "pump_turbine"`): the criteria the
//! report judges such a unit by ([`crate::report::hydro`]) in place of API
//! 684's separation margins and API 617's Level I screening, which are not
//! written for hydraulic machine sets. Every other class keeps the API lines.

use std::fmt::Write;

use crate::analysis::modal::Mode;
use crate::analysis::stability::Stability;
use crate::analysis::unbalance::{Peak, SeparationMargin, UnbalanceSweep};
use crate::units::{Amplitude, RAD_S_TO_RPM};

use super::{peak_cells, short};

/// The stability criterion of a hydro unit, the report's "stability without
/// cross-coupling" row: the least stable forward mode is damped, `δ > 0`.
pub fn log_dec_holds(least: &Mode) -> bool {
    !least.is_undamped() && least.log_decrement > 0.0
}

/// The peak table of `rotor unbalance` for a hydro class: point, peak speed
/// (rpm), amplitude (`amplitude` convention), AF, and whether the peak lies
/// above the runaway speed `runaway` (rad/s, `max_speed_rpm`), then the
/// verdict on the lowest peak, as `rotor campbell` judges the first critical
/// speed ([`super::modal::runaway_verdict`]). `top` is the sweep's top
/// speed (rad/s): no peak below a top under the runaway speed is not judged.
pub fn unbalance_runaway(
    sweep: &UnbalanceSweep,
    rows: &[(Peak, Option<SeparationMargin>)],
    amplitude: Amplitude,
    runaway: f64,
    machine: &str,
) -> String {
    let runaway_rpm = short(runaway * RAD_S_TO_RPM);
    let mut s = format!(
        "runaway speed {runaway_rpm} rpm (machine = {machine}: every response peak above it; API 684 separation margins not applied)\n"
    );
    writeln!(
        s,
        "point                      speed (rpm) {:>15}        AF  result",
        format!("µm {}", amplitude.label())
    )
    .ok();
    for (peak, _) in rows {
        let c = peak_cells(sweep, peak, None, amplitude);
        let result = if peak.speed > runaway {
            "above the runaway speed: pass"
        } else {
            "below the runaway speed: FAIL"
        };
        writeln!(
            s,
            "{:<26} {:>11} {:>15} {:>9}  {result}",
            c[0], c[1], c[2], c[3]
        )
        .ok();
    }
    if rows.is_empty() {
        s.push_str("(no peak inside the speed range)\n");
    }
    let top = sweep.speeds.last().copied().unwrap_or(0.0);
    let lowest = rows.iter().map(|(p, _)| p.speed).min_by(f64::total_cmp);
    match lowest {
        Some(first) => writeln!(
            s,
            "first response peak {} rpm against the runaway speed {runaway_rpm} rpm (machine = {machine}: above it): {}",
            short(first * RAD_S_TO_RPM),
            if first > runaway { "pass" } else { "FAIL" }
        ),
        None => writeln!(
            s,
            "no response peak up to {} rpm, the runaway speed {runaway_rpm} rpm (machine = {machine}: the first peak above it): {}",
            short(top * RAD_S_TO_RPM),
            if top >= runaway {
                "pass"
            } else {
                "not judged: the sweep stops below the runaway speed"
            }
        ),
    }
    .ok();
    s
}

/// The verdict of `rotor stability` for a hydro class: the least stable
/// forward mode without cross-coupling must be damped ([`log_dec_holds`]),
/// and no non-oscillating root may grow; API 617's Level I screening is not
/// applied (the command does not compute it for such a class).
pub fn stability_verdict(result: &Stability, machine: &str) -> String {
    let mut s = format!(
        "machine = {machine}: judged by the least stable forward mode without cross-coupling (log dec > 0); API 617 Level I screening not applied\n"
    );
    if !result.diverging.is_empty() {
        writeln!(
            s,
            "stability: FAIL (statically unstable at {} rpm)",
            short(result.speed.abs() * RAD_S_TO_RPM)
        )
        .ok();
        return s;
    }
    let Some((_, least)) = result.curve.first() else {
        s.push_str("stability: not judged (no forward mode)\n");
        return s;
    };
    let delta = if least.is_undamped() {
        "0 (no damping)".to_string()
    } else {
        format!("{:.4}", least.log_decrement)
    };
    writeln!(
        s,
        "stability: least stable forward mode {} Hz, log dec {delta}: {}",
        short(least.damped_frequency / std::f64::consts::TAU),
        if log_dec_holds(least) { "pass" } else { "FAIL" }
    )
    .ok();
    s
}
