//! Counters of the solver's work ([`StepStats`]), for run summaries and
//! benchmarks.

/// Counters of the work done, for reports.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StepStats {
    /// Accepted steps.
    pub steps: usize,
    /// Newton iterations.
    pub iterations: usize,
    /// Bearing-Jacobian refreshes after a stall.
    pub refreshes: usize,
    /// Iterations of the condensed Newton on the Jacobians of the iteration
    /// before (the bearing forces alone evaluated).
    pub chord_iterations: usize,
    /// Steps that ended on the iterate of their first chord iteration, its
    /// bearing pass the outputs' one.
    pub steps_on_iterate: usize,
    /// Bearing outputs `Simulator::outputs` took from the last step's pass
    /// instead of evaluating them.
    pub outputs_recalled: usize,
    /// Pad tilts moved on by their extrapolated tail where the condensed
    /// Newton contracted slowly (`solver::slow_pads`).
    pub extrapolations: usize,
    /// Film evaluations of single pads settling their own balance
    /// (`solver::pad_balance`); a pass over a bearing of `n` pads counts `n`.
    pub pad_evaluations: usize,
    /// Step halvings.
    pub step_cuts: usize,
    /// Steps solved again by the damped Newton after plain Newton failed.
    pub retries: usize,
    /// Factorizations of the linear part.
    pub factorizations: usize,
    /// Factorizations recalled for exactly their step and speed instead of
    /// being formed again (not in `factorizations`).
    pub factors_recalled: usize,
    /// Steps rejected by the local error estimate (accuracy-controlled steps).
    pub rejections: usize,
}
