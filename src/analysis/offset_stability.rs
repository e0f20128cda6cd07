//! The sensitivity of a shaft line's stability to each bearing's offset
//! (issue 49, alignment tools): the logarithmic decrement `δ` of the least
//! stable forward mode of the line linearized at its static equilibrium at
//! the speed ([`linearized`], [`least_stable_forward`] over the first
//! [`MODES`] modes), and its derivatives `∂δ/∂o_x`, `∂δ/∂o_y` with respect to
//! each fluid-film bearing's centre offset by central differences of step
//! `h = STEP × C` (`C` the bearing's clearance): how much a bearing set
//! higher or lower stabilizes the line or brings it toward whirl. Only the
//! nonlinear films make the stability depend on the offsets (a linear
//! bearing's offset is a preload that leaves every matrix as it is, so the
//! line's sensitivity to it is zero).

use crate::model::RotorModel;
use crate::rotor::Rotor;

use super::linearize::linearized;
use super::stability::{StabilityError, least_stable_forward};

/// Modes searched for the least stable forward one.
pub const MODES: usize = 8;
/// Difference step as a fraction of the bearing's clearance.
pub const STEP: f64 = 1e-2;

/// One bearing's influence on the line's stability.
#[derive(Debug, Clone, PartialEq)]
pub struct OffsetSensitivity {
    /// Model bearing index.
    pub bearing: usize,
    /// Bearing name.
    pub name: String,
    /// `∂δ/∂o_x`, `∂δ/∂o_y` (1/m).
    pub log_decrement_slope: [f64; 2],
    /// The difference step (m).
    pub step: f64,
}

/// The least stable forward mode's log decrement of `model` at `speed`.
fn least_log_decrement(model: RotorModel, speed: f64) -> Result<f64, StabilityError> {
    let rotor = Rotor::new(model).map_err(|e| StabilityError::Options(e.to_string()))?;
    let linear = linearized(&rotor, speed, speed)?;
    Ok(least_stable_forward(&linear, speed, MODES)?.log_decrement)
}

/// The log decrement of the least stable forward mode of `rotor` at `speed`
/// (rad/s) and its slope with respect to the offset of every fluid-film
/// bearing (plain or tilting pad, either film).
pub fn offset_sensitivity(
    rotor: &Rotor,
    speed: f64,
) -> Result<(f64, Vec<OffsetSensitivity>), StabilityError> {
    let model = &rotor.model;
    let base = least_log_decrement(model.clone(), speed)?;
    let mut out = Vec::new();
    for (b, placed) in model.bearings.iter().enumerate() {
        let Some(clearance) = placed
            .kind
            .journal_clearance()
            .filter(|_| placed.kind.is_bearing() && placed.kind.is_nonlinear())
        else {
            continue;
        };
        let h = STEP * clearance;
        let mut slope = [0.0; 2];
        for (k, s) in slope.iter_mut().enumerate() {
            let at = |d: f64| {
                let mut m = model.clone();
                m.bearings[b].offset[k] += d;
                least_log_decrement(m, speed)
            };
            *s = (at(h)? - at(-h)?) / (2.0 * h);
        }
        out.push(OffsetSensitivity {
            bearing: b,
            name: placed.name.clone(),
            log_decrement_slope: slope,
            step: h,
        });
    }
    Ok((base, out))
}
