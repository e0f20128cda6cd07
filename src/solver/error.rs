//! Why the solver stopped ([`SolverError`]).

use crate::bearing::BearingError;
use crate::linalg::LinalgError;

/// Why the solver stopped.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SolverError {
    /// Newton did not converge even with the smallest allowed step.
    #[error(
        "Newton–Raphson did not converge at t = {time:.6} s (step {step:.3e} s after {cuts} halvings; last relative residual or correction {residual:.3e})"
    )]
    NotConverged {
        time: f64,
        step: f64,
        cuts: usize,
        residual: f64,
    },
    /// A bearing could not give a force (e.g. the journal reached the clearance).
    #[error("bearing {name} at t = {time:.6} s: {source}")]
    Bearing {
        name: String,
        time: f64,
        source: BearingError,
    },
    /// The linear part could not be factored.
    #[error("linear algebra: {0}")]
    Linalg(#[from] LinalgError),
    /// Bad input or option.
    #[error("{0}")]
    Input(String),
    /// No static equilibrium was found.
    #[error("static equilibrium: {0}")]
    Static(String),
    /// The static equilibrium found is one the machine cannot hold: its net
    /// static stiffness is negative in some direction (`static_stability`).
    #[error("static equilibrium: {0}")]
    StaticallyUnstable(String),
    /// A call would exceed the work bound of one call (internal steps or step
    /// halvings, [`SolverOptions::MAX_STEPS_PER_CALL`], [`SolverOptions::MAX_CUTS_PER_CALL`]).
    #[error("{0}")]
    Budget(String),
}
