//! Bearings: the force the supporting element exerts on a journal, and its
//! Jacobians, as pure functions of the journal state and the spin speed.
//!
//! Every bearing kind implements [`Bearing`]; the assembly and the solvers only
//! see that trait. Sign conventions: the force acts **on the journal**;
//! `K = −∂F/∂(x, y)` and `C = −∂F/∂(ẋ, ẏ)`, so a plain spring has positive `K`.

pub mod equilibrium;
pub mod film;
pub mod linear;
pub mod plain;

use nalgebra::{Matrix2, Vector2};

pub use linear::LinearBearing;
pub use plain::PlainBearing;

/// Position and velocity of a journal centre relative to the bearing centre.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct JournalState {
    /// Displacement (m), `(x, y)`.
    pub position: Vector2<f64>,
    /// Velocity (m/s), `(ẋ, ẏ)`.
    pub velocity: Vector2<f64>,
}

/// Force on the journal with its stiffness and damping Jacobians.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BearingForce {
    /// Force on the journal (N).
    pub force: Vector2<f64>,
    /// `K = −∂F/∂(x, y)` (N/m), `K[(i, j)] = −∂F_i/∂x_j`.
    pub stiffness: Matrix2<f64>,
    /// `C = −∂F/∂(ẋ, ẏ)` (N·s/m).
    pub damping: Matrix2<f64>,
}

/// Why a bearing cannot give a force for a state.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum BearingError {
    /// An input was NaN or infinite.
    #[error("bearing input {what} is not finite ({value})")]
    NotFinite { what: &'static str, value: f64 },
    /// The journal reached or passed the clearance circle, where the film model
    /// has no meaning (journal–bearing contact).
    #[error(
        "journal at eccentricity ratio {eccentricity:.6} reached the clearance circle (ε ≥ 1): the oil film has broken down (contact)"
    )]
    ClearanceExceeded { eccentricity: f64 },
}

/// Quantities a bearing reports besides its force (for outputs and coupling).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BearingReport {
    /// Eccentricity ratio `ε = e/C` (–); zero for bearings without a clearance.
    pub eccentricity: f64,
    /// Attitude angle (rad): from the load line to the eccentricity vector, in the spin direction.
    pub attitude_angle: f64,
    /// Minimum film thickness `C (1 − ε)` (m); zero without a film.
    pub min_film_thickness: f64,
    /// Viscous friction torque on the journal, opposing the spin (N·m).
    pub friction_torque: f64,
    /// Power dissipated in the film (W).
    pub power_loss: f64,
}

/// A bearing kind: force and Jacobians from the journal state and spin speed.
pub trait Bearing: Send + Sync + std::fmt::Debug {
    /// Force on the journal and its Jacobians at `state`, spin speed `speed` (rad/s).
    fn force_and_jacobian(
        &self,
        state: &JournalState,
        speed: f64,
    ) -> Result<BearingForce, BearingError>;

    /// True when the force is linear in the state and independent of speed, so it
    /// can be assembled once into the global matrices.
    fn is_linear(&self) -> bool;

    /// Eccentricity, attitude angle, film thickness and friction at `state`, with
    /// `force` the film force there (from [`Bearing::force_and_jacobian`]).
    fn report(&self, _state: &JournalState, _speed: f64, _force: &Vector2<f64>) -> BearingReport {
        BearingReport::default()
    }
}

/// Bearing type and parameters as given in a model file (plain data).
#[derive(Debug, Clone, PartialEq)]
pub enum BearingKind {
    /// Linear spring–damper: `F = −K q − C q̇`.
    Linear {
        /// Stiffness (N/m), row-major `[[kxx, kxy], [kyx, kyy]]`.
        stiffness: [[f64; 2]; 2],
        /// Damping (N·s/m), row-major.
        damping: [[f64; 2]; 2],
    },
    /// Plain journal bearing, short-bearing theory with π-film cavitation.
    Plain(PlainBearing),
}

impl BearingKind {
    /// The bearing model for these parameters.
    pub fn build(&self) -> Box<dyn Bearing> {
        match self {
            BearingKind::Linear { stiffness, damping } => {
                Box::new(LinearBearing::new(*stiffness, *damping))
            }
            BearingKind::Plain(b) => Box::new(*b),
        }
    }
}

/// Reject a non-finite journal state or speed.
pub(crate) fn check_finite(state: &JournalState, speed: f64) -> Result<(), BearingError> {
    let items = [
        ("x", state.position.x),
        ("y", state.position.y),
        ("vx", state.velocity.x),
        ("vy", state.velocity.y),
        ("speed", speed),
    ];
    for (what, value) in items {
        if !value.is_finite() {
            return Err(BearingError::NotFinite { what, value });
        }
    }
    Ok(())
}
