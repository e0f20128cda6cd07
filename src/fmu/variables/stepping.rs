//! Appended after the drive: the accuracy control of the internal steps
//! (`solver.local_error_tolerance`, [`crate::solver::SolverOptions::local_error_tolerance`]).

use super::Causality::*;
use super::Kind::*;
use super::Variability::*;
use super::{Binding, DEFAULT_LOCAL_ERROR_TOLERANCE, Table};

/// Append the step-control variables to `t`.
pub(super) fn add(t: &mut Table) {
    t.push(
        "solver.local_error_tolerance".into(),
        "Local error tolerance of the internal Newmark steps: each step is judged by the Zienkiewicz-Xie estimate h^2/12 (a1 - a0) at the journals, housings, probes and unbalance planes relative to its displacement increment, the relative period error (omega h)^2/12 of the motion it resolves, and the next step is sized from it (up to solver.time_step, landing on every communication point); 0 for equal sub-steps no longer than solver.time_step".into(),
        Real,
        Parameter,
        Fixed,
        Some("1"),
        None,
        Some(DEFAULT_LOCAL_ERROR_TOLERANCE),
        Binding::LocalErrorTolerance,
    );
}
