//! The default internal time step of a transient, one rule for the CLI and
//! the FMU: [`STEPS_PER_REVOLUTION`] steps per revolution at the top speed,
//! at most [`MAX_DEFAULT_TIME_STEP`]. Newmark's period error at the spin
//! frequency is then `(Ω h)²/12 = (2π/60)²/12 ≈ 0.1 %`, and every slower
//! motion (oil whirl at 0.5×, the modes below the running speed) is resolved
//! better.
//!
//! Accuracy-controlled steps ([`crate::solver::SolverOptions::local_error_tolerance`])
//! size themselves; their largest step is
//! [`ADAPTIVE_STEPS_PER_REVOLUTION`] per revolution at the top speed, at most
//! [`MAX_ADAPTIVE_TIME_STEP`] ([`largest_adaptive_step`]), a bound the
//! estimate rarely reaches in running (12 steps per revolution is a period
//! error of 2.3 % at the spin frequency) but that holds at standstill.

use crate::model::RotorModel;

/// Steps per revolution at the top speed.
pub const STEPS_PER_REVOLUTION: f64 = 60.0;

/// The largest default step (s), for slow machines and standstill.
pub const MAX_DEFAULT_TIME_STEP: f64 = 1e-3;

/// Default local error tolerance of accuracy-controlled steps (–), the
/// CLI's and the FMU's: on the shipped hydro units the journal orbits then
/// stay within 1 % of a 0.05 ms reference (measured 0.64 % on
/// `hydro_unit`, 0.14 % on `hydro_unit_three_guide`; `tests/adaptive.rs`).
pub const DEFAULT_LOCAL_ERROR_TOLERANCE: f64 = 3e-3;

/// Steps per revolution at the top speed that bound accuracy-controlled steps.
pub const ADAPTIVE_STEPS_PER_REVOLUTION: f64 = 12.0;

/// The largest accuracy-controlled step (s), for slow machines and standstill.
pub const MAX_ADAPTIVE_TIME_STEP: f64 = 0.02;

/// The default time step (s) for a run of `model` whose speed reaches
/// `run_peak` (rad/s; `None` when unknown in advance, as in an FMU): the
/// larger of the model's top speed and `run_peak` at
/// [`STEPS_PER_REVOLUTION`], at most [`MAX_DEFAULT_TIME_STEP`].
pub fn default_time_step(model: &RotorModel, run_peak: Option<f64>) -> f64 {
    per_revolution(model, run_peak, STEPS_PER_REVOLUTION, MAX_DEFAULT_TIME_STEP)
}

/// The default largest accuracy-controlled step (s) for a run of `model`
/// whose speed reaches `run_peak` (rad/s): [`ADAPTIVE_STEPS_PER_REVOLUTION`]
/// at the top speed, at most [`MAX_ADAPTIVE_TIME_STEP`].
pub fn largest_adaptive_step(model: &RotorModel, run_peak: Option<f64>) -> f64 {
    per_revolution(
        model,
        run_peak,
        ADAPTIVE_STEPS_PER_REVOLUTION,
        MAX_ADAPTIVE_TIME_STEP,
    )
}

/// `steps` steps per revolution at the larger of the model's top speed and
/// `run_peak`, at most `largest` (s).
fn per_revolution(model: &RotorModel, run_peak: Option<f64>, steps: f64, largest: f64) -> f64 {
    let top = model
        .transient_top_speed()
        .unwrap_or(0.0)
        .max(run_peak.unwrap_or(0.0));
    if top > 0.0 {
        (std::f64::consts::TAU / (steps * top)).min(largest)
    } else {
        largest
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::units::RAD_S_TO_RPM;

    #[test]
    fn sixty_steps_per_revolution_at_most_a_millisecond() {
        let mut m = RotorModel::default_model();
        // speed_rpm 1000: 16.7 Hz, 1 ms at most.
        assert_eq!(default_time_step(&m, None), 1e-3);
        // A run to 3600 rpm: 60 Hz → 1/3600 s.
        let run = 3600.0 / RAD_S_TO_RPM;
        assert!((default_time_step(&m, Some(run)) - 1.0 / 3600.0).abs() < 1e-15);
        m.max_speed_stated = true;
        m.max_speed = 6000.0 / RAD_S_TO_RPM;
        assert!((default_time_step(&m, None) - 1.0 / 6000.0).abs() < 1e-15);
        assert!((default_time_step(&m, Some(run)) - 1.0 / 6000.0).abs() < 1e-15);
        m.max_speed_stated = false;
        m.nominal_speed = 0.0;
        assert_eq!(default_time_step(&m, None), MAX_DEFAULT_TIME_STEP);
    }

    #[test]
    fn twelve_adaptive_steps_per_revolution_at_most_twenty_milliseconds() {
        let mut m = RotorModel::default_model();
        // 1000 rpm: 1/200 s.
        assert!((largest_adaptive_step(&m, None) - 1.0 / 200.0).abs() < 1e-15);
        // 50 rpm would be 0.1 s: 20 ms at most.
        let slow = 50.0 / RAD_S_TO_RPM;
        m.nominal_speed = slow;
        assert_eq!(
            largest_adaptive_step(&m, Some(slow)),
            MAX_ADAPTIVE_TIME_STEP
        );
        let run = 6000.0 / RAD_S_TO_RPM;
        assert!((largest_adaptive_step(&m, Some(run)) - 1.0 / 1200.0).abs() < 1e-15);
    }
}
