//! The default internal time step of a transient, one rule for the CLI and
//! the FMU: [`STEPS_PER_REVOLUTION`] steps per revolution at the top speed,
//! at most [`MAX_DEFAULT_TIME_STEP`]. Newmark's period error at the spin
//! frequency is then `(Ω h)²/12 = (2π/60)²/12 ≈ 0.1 %`, and every slower
//! motion (oil whirl at 0.5×, the modes below the running speed) is resolved
//! better.

use crate::model::RotorModel;

/// Steps per revolution at the top speed.
pub const STEPS_PER_REVOLUTION: f64 = 60.0;

/// The largest default step (s), for slow machines and standstill.
pub const MAX_DEFAULT_TIME_STEP: f64 = 1e-3;

/// The default time step (s) for a run of `model` whose speed reaches
/// `run_peak` (rad/s; `None` when unknown in advance, as in an FMU): the
/// larger of the model's top speed and `run_peak` at
/// [`STEPS_PER_REVOLUTION`], at most [`MAX_DEFAULT_TIME_STEP`].
pub fn default_time_step(model: &RotorModel, run_peak: Option<f64>) -> f64 {
    let top = model
        .transient_top_speed()
        .unwrap_or(0.0)
        .max(run_peak.unwrap_or(0.0));
    if top > 0.0 {
        (std::f64::consts::TAU / (STEPS_PER_REVOLUTION * top)).min(MAX_DEFAULT_TIME_STEP)
    } else {
        MAX_DEFAULT_TIME_STEP
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
}
