//! Each pad's tilt settled on its own moment balance inside an iteration of
//! the condensed Newton (nonlinear elimination of the pads): a pad's balance
//! `Q_η(j, η, η̇) = 0` depends on the journal `j` and its own tilt only (its
//! rate `η̇ = a1 (η − η_n) − η̇_n` the step's Newmark rate), so with every pad
//! balanced at the journal iterate the condensed Newton is exact Newton on
//! the journals alone, `K_c = K_jj − K_jp K_pp⁻¹ K_pj` the exact derivative of
//! the eliminated system, and converges quadratically on them.
//!
//! Why: a pad the film has just unloaded sits near a double root of its
//! balance (`Q_η ≈ a e² − k_r η`, `solver/slow_pads.rs`), where Newton's
//! tilt increments only halve; the condensed Newton judged the pads by their
//! increments and paid a whole bearing pass for every halving (the unit on
//! brackets: 15 iterations a step). Near a double root the tilt is
//! ill-conditioned, but what it does to the journal is not: its force on
//! the journal is of the order of its moment residual. So a pad is balanced
//! when its residual is within the force tolerance `ε_F = tol · s / G_max`
//! (`s` the displacement scale of the increments, `G_max` the largest
//! diagonal entry of the step's journal compliance `G = Eᵀ A⁻¹ E`): a force
//! that moves no journal by more than the Newton tolerance. The scalar
//! solve is Newton on `Q_η` with its derivative `−(K_ηη + a1 C_ηη)`,
//! bisection once a sign change brackets the root and Newton leaves the
//! bracket; each pass evaluates the one pad's film
//! ([`crate::bearing::Bearing::internal_balance`]), an eighth of a bearing
//! pass on an eight-pad bearing.

use crate::bearing::{Bearing, BearingError};

/// Film evaluations one pad may take in one settling.
pub(super) const MAX_EVALUATIONS: usize = 30;

/// A pad's Newmark tilt rate: `η̇ = a1 (η − η_n) − η̇_n`.
#[derive(Debug, Clone, Copy)]
pub(super) struct TiltRate {
    /// `2 / h`.
    pub a1: f64,
    /// Tilt at the start of the step, `η_n`.
    pub start: f64,
    /// Tilt rate at the start of the step, `η̇_n`.
    pub start_rate: f64,
}

impl TiltRate {
    fn at(&self, eta: f64) -> f64 {
        self.a1 * (eta - self.start) - self.start_rate
    }
}

/// How a pad's settling went: the film evaluations it took, and whether it
/// balanced within them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Settled {
    pub evaluations: usize,
    pub balanced: bool,
}

/// Settle internal coordinate `m` of `q` (entry `2 + m`, its rate in `qdot`
/// by `rate`) until its balance is within `force_tol` (N), or a Newton
/// increment within `tilt_tol` (m). `Ok(None)`: the bearing gives no
/// balance of its own ([`Bearing::internal_balance`]). A pad that does not
/// balance within [`MAX_EVALUATIONS`] is left where it started.
#[allow(clippy::too_many_arguments)]
pub(super) fn settle(
    bearing: &dyn Bearing,
    m: usize,
    q: &mut [f64],
    qdot: &mut [f64],
    speed: f64,
    rate: TiltRate,
    force_tol: f64,
    tilt_tol: f64,
) -> Result<Option<Settled>, BearingError> {
    let i = 2 + m;
    let (start, start_rate) = (q[i], qdot[i]);
    let mut eta = start;
    // Tilts where the balance was last found positive and negative.
    let (mut positive, mut negative): (Option<f64>, Option<f64>) = (None, None);
    for evaluation in 1..=MAX_EVALUATIONS {
        q[i] = eta;
        qdot[i] = rate.at(eta);
        let Some(balance) = bearing.internal_balance(m, q, qdot, speed) else {
            return Ok(None);
        };
        let [moment, k, c] = balance?;
        if moment.abs() <= force_tol {
            return Ok(Some(Settled {
                evaluations: evaluation,
                balanced: true,
            }));
        }
        if moment > 0.0 {
            positive = Some(eta);
        } else {
            negative = Some(eta);
        }
        let slope = k + rate.a1 * c;
        let mut next = eta + moment / slope;
        if let (Some(a), Some(b)) = (positive, negative) {
            let (lo, hi) = (a.min(b), a.max(b));
            if !(next > lo && next < hi) {
                next = 0.5 * (lo + hi);
            }
        } else if !next.is_finite() {
            break;
        }
        if (next - eta).abs() <= tilt_tol {
            q[i] = next;
            qdot[i] = rate.at(next);
            return Ok(Some(Settled {
                evaluations: evaluation,
                balanced: true,
            }));
        }
        eta = next;
    }
    q[i] = start;
    qdot[i] = start_rate;
    Ok(Some(Settled {
        evaluations: MAX_EVALUATIONS,
        balanced: false,
    }))
}
