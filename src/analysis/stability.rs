//! Stability at an operating speed and its sensitivity to destabilizing
//! cross-coupled stiffness (API 684 Level I style).
//!
//! The rotor is linearized at the speed (fluid films: synchronous coefficients
//! at the static equilibrium, [`linearized`]); a cross-coupled stiffness
//! `K_Q = [[0, Q], [−Q, 0]]` (N/m, `K = −∂F/∂q` as for bearings) is added at the
//! node nearest mid-span between the outermost bearings. Its force
//! `F = (−Q y, Q x)` is tangential in the spin direction, so it feeds forward
//! whirl: for a rigid disk of mass `m` on isotropic springs `k` and dampers `c`,
//! `m z̈ + c ż + (k − iQ) z = 0` (`z = x + iy`) loses stability at
//! `Q = c √(k/m)`. The threshold `Q` where the logarithmic decrement of the
//! least stable forward mode ([`least_stable_forward`]) reaches zero is found
//! by the Illinois method.

use crate::fe::{DOF_X, DOF_Y};
use crate::rotor::{AssemblyError, Rotor};

use super::linearize::{LinearizeError, linearized};
use super::modal::{ModalError, ModalOptions, Mode, Whirl, modes};
use super::operating_point::{OperatingPointError, operating_point};

/// Why a stability check failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StabilityError {
    /// Linearizing the fluid-film bearings failed.
    #[error(transparent)]
    Linearize(#[from] LinearizeError),
    /// Copying the linear rotor failed.
    #[error(transparent)]
    Assembly(#[from] AssemblyError),
    /// The eigen-solve failed.
    #[error(transparent)]
    Modal(#[from] ModalError),
    /// The bearings' coefficients could not be found.
    #[error(transparent)]
    OperatingPoint(#[from] OperatingPointError),
    /// Bad input or no forward mode.
    #[error("{0}")]
    Options(String),
}

/// The node nearest the middle between the outermost bearings (the shaft's
/// middle with fewer than two bearings).
pub fn mid_span_node(rotor: &Rotor) -> usize {
    let m = &rotor.model;
    let zs: Vec<f64> = m.bearings.iter().map(|b| m.node_z[b.node]).collect();
    let (lo, hi) = if zs.len() >= 2 {
        (
            zs.iter().copied().fold(f64::INFINITY, f64::min),
            zs.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        )
    } else {
        (m.node_z[0], m.node_z[m.node_count() - 1])
    };
    let mid = 0.5 * (lo + hi);
    (0..m.node_count())
        .min_by(|&a, &b| {
            (m.node_z[a] - mid)
                .abs()
                .total_cmp(&(m.node_z[b] - mid).abs())
        })
        .unwrap_or(0)
}

/// Default largest cross-coupled stiffness (N/m): a tenth of the largest
/// direct bearing stiffness at `speed` (rad/s) (thresholds are a few ζ times
/// the support stiffness), or 1e6 N/m without bearings.
pub fn default_cross_coupling_max(rotor: &Rotor, speed: f64) -> Result<f64, StabilityError> {
    let k = operating_point(rotor, speed)?
        .iter()
        .map(|p| p.stiffness[0][0].abs().max(p.stiffness[1][1].abs()))
        .fold(0.0, f64::max);
    Ok(if k > 0.0 { 0.1 * k } else { 1e6 })
}

/// A copy of the linear rotor `linear` with `[[0, q], [−q, 0]]` (N/m) added to
/// the stiffness at the x, y DOFs of `node`.
pub fn with_cross_coupling(linear: &Rotor, node: usize, q: f64) -> Result<Rotor, StabilityError> {
    let mut out = linear.with_bearing_coefficients(&[])?;
    match (linear.dofs.free(node, DOF_X), linear.dofs.free(node, DOF_Y)) {
        (Some(ix), Some(iy)) => {
            out.stiffness.add(ix, iy, q);
            out.stiffness.add(iy, ix, -q);
            Ok(out)
        }
        _ => Err(StabilityError::Options(format!(
            "node {} is fixed by a support: no cross-coupled stiffness can act there",
            node + 1
        ))),
    }
}

/// The forward mode of least logarithmic decrement among the first `count`
/// modes of the linear rotor at `speed` (rad/s): the one cross-coupling turns
/// unstable first. (On fluid films the lowest forward mode by frequency can be
/// a heavily damped rigid-body mode, so "first" is taken as "least stable".)
pub fn least_stable_forward(
    linear: &Rotor,
    speed: f64,
    count: usize,
) -> Result<Mode, StabilityError> {
    let options = ModalOptions {
        modes: count,
        ..ModalOptions::default()
    };
    modes(linear, speed, &options)?
        .into_iter()
        .filter(|m| m.whirl == Whirl::Forward)
        .min_by(|a, b| a.log_decrement.total_cmp(&b.log_decrement))
        .ok_or_else(|| {
            StabilityError::Options(format!(
                "no forward mode among the first {count} at {speed} rad/s (a spinning rotor is needed: give a speed)"
            ))
        })
}

/// Result of a stability check.
#[derive(Debug, Clone, PartialEq)]
pub struct Stability {
    /// Spin speed (rad/s).
    pub speed: f64,
    /// Node of the cross-coupled stiffness (0-based).
    pub node: usize,
    /// The first `count` modes without cross-coupling.
    pub modes: Vec<Mode>,
    /// `(Q, least stable forward mode)` over `0 … Q_max` (N/m).
    pub curve: Vec<(f64, Mode)>,
    /// `Q` (N/m) where that mode's log decrement is zero: `Some(0)`
    /// when it is unstable already, `None` when stable up to `Q_max`.
    pub threshold: Option<f64>,
    /// That mode at the threshold.
    pub threshold_mode: Option<Mode>,
}

/// Stability at `speed` (rad/s): the first `count` modes, the least stable
/// forward mode over `points` values of `Q` from 0 to `q_max` (N/m), and the threshold
/// `Q`, refined by the Illinois method until `|δ| < 1e-9` or the bracket is
/// `1e-12` of `Q`.
pub fn stability(
    rotor: &Rotor,
    speed: f64,
    q_max: f64,
    points: usize,
    count: usize,
) -> Result<Stability, StabilityError> {
    if !(q_max.is_finite() && q_max > 0.0) || points < 2 {
        return Err(StabilityError::Options(format!(
            "--cross-coupling-max must be positive (got {q_max} N/m) with at least 2 points (got {points})"
        )));
    }
    let linear = linearized(rotor, speed, speed)?;
    let node = mid_span_node(rotor);
    let options = ModalOptions {
        modes: count,
        ..ModalOptions::default()
    };
    let at_zero = modes(&linear, speed, &options)?;
    let forward = |q: f64| -> Result<Mode, StabilityError> {
        least_stable_forward(&with_cross_coupling(&linear, node, q)?, speed, count)
    };
    let mut curve = Vec::with_capacity(points);
    for k in 0..points {
        let q = q_max * k as f64 / (points - 1) as f64;
        curve.push((q, forward(q)?));
    }
    let mut threshold = None;
    let mut threshold_mode = None;
    if curve[0].1.log_decrement <= 0.0 {
        threshold = Some(0.0);
        threshold_mode = Some(curve[0].1.clone());
    } else if let Some(w) = curve
        .windows(2)
        .find(|w| w[0].1.log_decrement > 0.0 && w[1].1.log_decrement <= 0.0)
    {
        let (mut a, mut fa) = (w[0].0, w[0].1.log_decrement);
        let (mut b, mut fb) = (w[1].0, w[1].1.log_decrement);
        let mut best = (b, w[1].1.clone());
        let mut side = 0;
        for _ in 0..100 {
            let c = (a * fb - b * fa) / (fb - fa);
            let m = forward(c)?;
            let fc = m.log_decrement;
            best = (c, m);
            if fc.abs() < 1e-9 || (b - a).abs() <= 1e-12 * c.abs() {
                break;
            }
            if fc > 0.0 {
                a = c;
                fa = fc;
                if side == 1 {
                    fb /= 2.0;
                }
                side = 1;
            } else {
                b = c;
                fb = fc;
                if side == -1 {
                    fa /= 2.0;
                }
                side = -1;
            }
        }
        threshold = Some(best.0);
        threshold_mode = Some(best.1);
    }
    Ok(Stability {
        speed,
        node,
        modes: at_zero,
        curve,
        threshold,
        threshold_mode,
    })
}
