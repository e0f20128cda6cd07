//! Static equilibrium of a journal under a steady load, by Newton's method on the
//! closed-form bearing force and stiffness, and the linearized coefficients there.

use nalgebra::Vector2;

use super::{Bearing, BearingError, BearingForce, JournalState};

/// A converged equilibrium.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Equilibrium {
    /// Journal position (m).
    pub position: Vector2<f64>,
    /// Force and linearized stiffness/damping there.
    pub coefficients: BearingForce,
    /// Newton iterations used.
    pub iterations: usize,
}

/// Why no equilibrium was found.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EquilibriumError {
    /// The bearing could not be evaluated.
    #[error(transparent)]
    Bearing(#[from] BearingError),
    /// Newton's method did not converge.
    #[error(
        "journal equilibrium: no convergence after {iterations} iterations (residual {residual:.3e} N)"
    )]
    NotConverged { iterations: usize, residual: f64 },
    /// The stiffness is singular (e.g. zero speed: a squeeze film carries no static load).
    #[error(
        "journal equilibrium: singular bearing stiffness (a film at zero speed carries no static load)"
    )]
    Singular,
}

/// Journal position where the film force balances `load` (the steady force
/// applied to the journal, N): `F(q) + load = 0`, with zero journal velocity.
/// Newton steps `δ = K⁻¹ (F + load)` with backtracking keep the journal inside
/// the clearance `scale` and the residual decreasing; converged when
/// `|F + load| ≤ 1e-10 |load|`.
pub fn journal_equilibrium(
    bearing: &dyn Bearing,
    load: Vector2<f64>,
    speed: f64,
    scale: f64,
) -> Result<Equilibrium, EquilibriumError> {
    let eval = |position: Vector2<f64>| {
        bearing.force_and_jacobian(
            &JournalState {
                position,
                velocity: Vector2::zeros(),
            },
            speed,
        )
    };
    let tol = 1e-10 * load.norm().max(f64::MIN_POSITIVE);
    let mut position = Vector2::zeros();
    let mut current = eval(position)?;
    let mut residual = (current.force + load).norm();
    for iteration in 0..200 {
        if residual <= tol {
            return Ok(Equilibrium {
                position,
                coefficients: current,
                iterations: iteration,
            });
        }
        let step = current
            .stiffness
            .try_inverse()
            .ok_or(EquilibriumError::Singular)?
            * (current.force + load);
        let mut t = 1.0;
        let mut accepted = false;
        for _ in 0..60 {
            let trial = position + step * t;
            if trial.norm() < scale {
                if let Ok(next) = eval(trial) {
                    let r = (next.force + load).norm();
                    if r < residual {
                        position = trial;
                        current = next;
                        residual = r;
                        accepted = true;
                        break;
                    }
                }
            }
            t *= 0.5;
        }
        if !accepted {
            break;
        }
    }
    Err(EquilibriumError::NotConverged {
        iterations: 200,
        residual,
    })
}
