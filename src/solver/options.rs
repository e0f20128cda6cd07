//! The solver's settings ([`SolverOptions`]) and their ranges, checked
//! before a simulator takes them.

use crate::units::Short;

use super::error::SolverError;

/// Solver settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverOptions {
    /// Largest internal time step (s).
    pub time_step: f64,
    /// Relative tolerance on residual and increment (–).
    pub tolerance: f64,
    /// Newton iterations per attempt of a step.
    pub max_iterations: usize,
    /// Largest number of step halvings before giving up.
    pub max_step_cuts: usize,
    /// Time constant τ of the unbalance ramp `1 − e^{−t/τ}` (s); 0 for none.
    pub unbalance_ramp_time: f64,
    /// Apply gravity.
    pub gravity: bool,
    /// Local error tolerance of accuracy-controlled steps (–): the relative
    /// period error `(ωh)²/12` allowed to the motion of a step
    /// ([`super::adaptive`]); 0 for equal steps of `time_step`. With it,
    /// `time_step` is the largest step.
    pub local_error_tolerance: f64,
}

impl SolverOptions {
    /// Allowed internal time steps (s): below 1 µs a communication step would
    /// need millions of steps, above 1 s Newmark no longer resolves any mode.
    pub const TIME_STEP_RANGE: (f64, f64) = (1e-6, 1.0);
    /// Allowed relative tolerances (–).
    pub const TOLERANCE_RANGE: (f64, f64) = (1e-14, 1e-2);
    /// Allowed Newton iterations per step attempt.
    pub const MAX_ITERATIONS_RANGE: (usize, usize) = (1, 1000);
    /// Allowed step halvings.
    pub const MAX_STEP_CUTS_RANGE: (usize, usize) = (0, 20);
    /// Allowed unbalance ramp time constants (s).
    pub const RAMP_TIME_RANGE: (f64, f64) = (0.0, 1e6);
    /// Allowed local error tolerances (–) besides 0 (equal steps): below 1e-10
    /// the steps reach the Newton tolerance's noise, above 0.1 the period
    /// error of a step is no longer small.
    pub const LOCAL_ERROR_TOLERANCE_RANGE: (f64, f64) = (1e-10, 0.1);
    /// Most internal steps one [`Simulator::advance_to`] takes; a longer span
    /// is refused before it starts ([`SolverError::Budget`]).
    pub const MAX_STEPS_PER_CALL: usize = 200_000;
    /// Most step halvings one [`Simulator::advance_to`] may spend in all; past
    /// it the call stops with [`SolverError::Budget`].
    pub const MAX_CUTS_PER_CALL: usize = 2_000;
    /// Shortest span (s) [`Simulator::advance_to`] integrates; a shorter one is
    /// refused ([`SolverError::Input`]). Newmark's acceleration
    /// `ü = 4(u − uₙ)/h² − 4u̇ₙ/h − üₙ` divides the round-off and the Newton
    /// tolerance of `u` by `h²`: on the Jeffcott rotor one step of 1e-9 s
    /// moved the orbit 30 ms later by 1e-4 of its size, 1e-10 s by 7 %,
    /// 1e-11 s by more than its size, and 1e-13 s made Newton fail (1e-8 s:
    /// 1e-7 of it). Below about 1e-154 s, `4/h²` overflows. (A span of
    /// `MIN_SPAN` on a time grid, `(t + h) − t`, may fall short of it by
    /// round-off: up to 1e-6 of it is let through.)
    pub const MIN_SPAN: f64 = 1e-8;
}

impl Default for SolverOptions {
    fn default() -> Self {
        Self {
            time_step: 1e-4,
            tolerance: 1e-8,
            max_iterations: 50,
            max_step_cuts: 16,
            unbalance_ramp_time: 0.0,
            gravity: true,
            local_error_tolerance: 0.0,
        }
    }
}

pub(super) fn check_options(o: &SolverOptions) -> Result<(), SolverError> {
    let within = |what: &str, v: f64, (lo, hi): (f64, f64), unit: &str| {
        if v.is_finite() && (lo..=hi).contains(&v) {
            Ok(())
        } else {
            Err(SolverError::Input(format!(
                "solver option {what} = {} {unit} is outside [{lo}, {hi}] {unit}",
                Short(v)
            )))
        }
    };
    let as_f64 = |(lo, hi): (usize, usize)| (lo as f64, hi as f64);
    within(
        "time_step",
        o.time_step,
        SolverOptions::TIME_STEP_RANGE,
        "s",
    )?;
    within("tolerance", o.tolerance, SolverOptions::TOLERANCE_RANGE, "")?;
    within(
        "max_iterations",
        o.max_iterations as f64,
        as_f64(SolverOptions::MAX_ITERATIONS_RANGE),
        "",
    )?;
    within(
        "max_step_cuts",
        o.max_step_cuts as f64,
        as_f64(SolverOptions::MAX_STEP_CUTS_RANGE),
        "",
    )?;
    within(
        "unbalance_ramp_time",
        o.unbalance_ramp_time,
        SolverOptions::RAMP_TIME_RANGE,
        "s",
    )?;
    let (lo, hi) = SolverOptions::LOCAL_ERROR_TOLERANCE_RANGE;
    let tol = o.local_error_tolerance;
    if tol != 0.0 && !(tol.is_finite() && (lo..=hi).contains(&tol)) {
        return Err(SolverError::Input(format!(
            "solver option local_error_tolerance = {} is outside [{lo}, {hi}] (0 for equal steps)",
            Short(tol)
        )));
    }
    Ok(())
}
