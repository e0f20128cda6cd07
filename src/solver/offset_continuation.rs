//! The static equilibrium of a shaft line whose bearings are set off the
//! nominal axis, by continuation on the offsets when Newton from the
//! straight shaft does not find it (issue 49).
//!
//! A bearing raised by several clearances loads its neighbours and lifts
//! its journal far from where the straight shaft starts it: Newton on the
//! whole line then steps through films whose stiffness changes by orders of
//! magnitude and can stall. The continuation solves the aligned line first
//! (`s = 0`) and then the line with every offset scaled by `s`, `0 < s ≤ 1`,
//! each step started from the last equilibrium; a step that fails is halved.
//! On a model without offsets, or where Newton succeeds directly, it is
//! exactly [`equilibrium`].

use crate::rotor::Rotor;

use super::error::SolverError;
use super::options::SolverOptions;
use super::statics::{Equilibrium, equilibrium};

/// First continuation step on the offset scale `s`.
const FIRST_STEP: f64 = 0.25;

/// Smallest step before the continuation gives up.
const SMALLEST_STEP: f64 = 1.0 / 1024.0;

/// The static equilibrium of `rotor` at spin `speed` (rad/s): [`equilibrium`]
/// from `start`; when that fails on a model with offsets, continuation on
/// the offsets from the aligned line ([module](self)). A reduced rotor is
/// not continued (its basis belongs to its own offsets): its error stands.
pub fn line_equilibrium(
    rotor: &Rotor,
    speed: f64,
    options: &SolverOptions,
    start: Option<&Equilibrium>,
) -> Result<Equilibrium, SolverError> {
    let direct = equilibrium(rotor, speed, options, start);
    if direct.is_ok() || !rotor.model.has_offsets() || rotor.reduction.is_some() {
        return direct;
    }
    let scaled = |s: f64| -> Result<Rotor, SolverError> {
        Rotor::new(rotor.model.with_offsets_scaled(s))
            .map_err(|e| SolverError::Input(e.to_string()))
    };
    let Ok(mut last) = equilibrium(&scaled(0.0)?, speed, options, start) else {
        return direct;
    };
    let (mut s, mut step) = (0.0, FIRST_STEP);
    while s < 1.0 {
        let next = (s + step).min(1.0);
        let trial = if next == 1.0 {
            equilibrium(rotor, speed, options, Some(&last))
        } else {
            equilibrium(&scaled(next)?, speed, options, Some(&last))
        };
        match trial {
            Ok(found) => {
                last = found;
                s = next;
                step = (2.0 * step).min(FIRST_STEP);
            }
            Err(e) if step <= SMALLEST_STEP => {
                return Err(SolverError::Static(format!(
                    "continuation on the bearing offsets stalled at {:.4} of the offsets: {e}",
                    s
                )));
            }
            Err(_) => step *= 0.5,
        }
    }
    Ok(last)
}
