//! The API 617 Level II analysis as `rotor stability` prints it and the
//! report's rows take it.

use std::fmt::Write;

use crate::analysis::level_two::{LEVEL_II_MIN_LOG_DEC, LevelTwo, LevelTwoCase};
use crate::model::RotorModel;
use crate::units::RAD_S_TO_RPM;

use super::short;

/// What one Level II case found, in a few words: the least log decrement
/// of the judged modes and its frequency, or the divergence.
pub fn level_two_finding(case: &LevelTwoCase) -> String {
    if let Some(root) = case.diverging.first() {
        return format!(
            "STATICALLY UNSTABLE: a non-oscillating root grows at {} 1/s",
            short(-root.decay_rate())
        );
    }
    match case.governing() {
        Some(m) if m.is_undamped() => format!(
            "least log dec 0 (no damping) at {} Hz",
            short(m.damped_frequency / std::f64::consts::TAU)
        ),
        Some(m) => format!(
            "least log dec {:.4} at {} Hz",
            m.log_decrement,
            short(m.damped_frequency / std::f64::consts::TAU)
        ),
        None => "no forward mode".to_string(),
    }
}

/// `pass` or `FAIL` of one case.
pub fn level_two_verdict(case: &LevelTwoCase) -> &'static str {
    if case.pass() { "pass" } else { "FAIL" }
}

fn mode_rows(s: &mut String, case: &LevelTwoCase) {
    for (k, m) in case.modes.iter().enumerate() {
        writeln!(
            s,
            "    {:3} {:10.4} {:>10}",
            k + 1,
            m.damped_frequency / std::f64::consts::TAU,
            if m.is_undamped() {
                "0".to_string()
            } else {
                format!("{:.4}", m.log_decrement)
            }
        )
        .ok();
    }
}

/// Which coefficients Level II holds, by what `model` contains: the
/// bearings', the seals' with their cross-coupling, the magnetic pulls'.
pub fn level_two_elements(model: &RotorModel) -> String {
    let count = |pick: &dyn Fn(&crate::bearing::BearingKind) -> bool| {
        model.bearings.iter().filter(|b| pick(&b.kind)).count()
    };
    let (seals, pulls) = (count(&|k| k.is_seal()), count(&|k| k.is_magnetic_pull()));
    let mut parts = vec!["the bearings'".to_string()];
    if seals > 0 {
        parts.push("the seals' with their cross-coupling".into());
    }
    if pulls > 0 {
        parts.push("the magnetic pulls'".into());
    }
    let mut s = format!("every element's coefficients: {}", parts.join(", "));
    if seals == 0 {
        s.push_str(" (the model has no seals)");
    }
    s
}

/// The Level II section of `rotor stability`: the maximum continuous speed,
/// the frequency limit, each case's judged modes and verdict. `sites` labels
/// the anticipated cross-coupling's nodes; `model` says which elements'
/// coefficients it holds ([`level_two_elements`]).
pub fn level_two(l: &LevelTwo, sites: &[String], model: &RotorModel) -> String {
    let rpm = l.speed.abs() * RAD_S_TO_RPM;
    let mut s = format!(
        "API 617 Level II at the maximum continuous speed {} rpm (the top of the operating range), {}:\n",
        short(rpm),
        level_two_elements(model)
    );
    writeln!(
        s,
        "  forward modes judged: the first and every one below {} Hz (the running frequency at {} rpm); log dec at least {LEVEL_II_MIN_LOG_DEC} required",
        short(l.frequency_limit / std::f64::consts::TAU),
        short(rpm)
    )
    .ok();
    writeln!(s, "    mode   f_d (Hz)    log dec").ok();
    mode_rows(&mut s, &l.as_built);
    writeln!(
        s,
        "  Level II (model as built): {}: {}",
        level_two_finding(&l.as_built),
        level_two_verdict(&l.as_built)
    )
    .ok();
    if let Some((stages, why, case)) = &l.anticipated {
        writeln!(
            s,
            "  with the anticipated cross-coupling Q_A = {} N/m (the {} stage(s)' Wachel q_A at {} rpm) at {} ({why}):",
            short(case.cross_coupling),
            stages.len(),
            short(rpm),
            sites.join(", ")
        )
        .ok();
        writeln!(s, "    mode   f_d (Hz)    log dec").ok();
        mode_rows(&mut s, case);
        writeln!(
            s,
            "  Level II with Q_A: {}: {}",
            level_two_finding(case),
            level_two_verdict(case)
        )
        .ok();
    }
    s
}
