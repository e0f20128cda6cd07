//! The consistency check of `rotor stability --verify`: each least-damped
//! mode's log decrement in the linear analysis beside its ring-down in the
//! nonlinear transient ([`crate::analysis::ring_down`]).

use std::fmt::Write;

use crate::analysis::ring_down::RingDown;

use super::short;

/// Largest relative difference of the two log decrements the check calls
/// agreement.
pub const RING_DOWN_AGREEMENT: f64 = 0.05;

/// The table of ring-downs, a line each, and the verdict: `DISAGREE` where
/// the two halves differ by more than [`RING_DOWN_AGREEMENT`].
pub fn ring_downs(checks: &[RingDown]) -> String {
    if checks.is_empty() {
        return String::new();
    }
    let mut s = format!(
        "consistency check: each mode rung down in the nonlinear transient from the equilibrium (12 periods, fitted after the first 2; agreement within {:.0} %):\n  f_d (Hz)  log dec (linear)  log dec (transient)  f_d transient (Hz)  difference  verdict\n",
        100.0 * RING_DOWN_AGREEMENT
    );
    let mut disagree = 0;
    for c in checks {
        let d = c.difference();
        let agree = d.abs() <= RING_DOWN_AGREEMENT;
        disagree += usize::from(!agree);
        writeln!(
            s,
            "  {:>8}  {:>16}  {:>19}  {:>18}  {:>9.1} %  {}",
            short(c.mode.damped_frequency / std::f64::consts::TAU),
            short(c.mode.log_decrement),
            short(c.log_decrement),
            short(c.frequency / std::f64::consts::TAU),
            100.0 * d,
            if agree { "agree" } else { "DISAGREE" }
        )
        .ok();
    }
    if disagree > 0 {
        writeln!(
            s,
            "DISAGREE: the linear analysis and the transient differ on {disagree} mode(s): the linear model reduces something the transient keeps (tilting pads condensed at the running speed), or the motion is not small; judge stability by the transient"
        )
        .ok();
    }
    s
}
