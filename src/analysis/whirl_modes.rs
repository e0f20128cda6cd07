//! Modes with tilting pads at each mode's own frequency (issue 45).
//!
//! The linear analyses condense the pad tilts of tilting-pad bearings at the
//! running speed (synchronous coefficients, [`super::linearize`]). A mode
//! whirling at another frequency sees the pads otherwise: the reduction
//! `Z_red(s) = Z_jj − Z_jp Z_pp⁻¹ Z_pj`, `Z = K + sC`, depends on `s`. Here
//! each mode is iterated to its own eigenvalue: starting from the
//! synchronous mode `λ₀`, the bearings are condensed at `s = λ_k`
//! ([`condensed_at`]: the real `K_eff`, `C_eff` with `K_eff + s C_eff =
//! Z_red(s)` exactly), the mode nearest `λ_k` of that linear rotor is
//! `λ_{k+1}`, until `|λ_{k+1} − λ_k| ≤ 1e-10 |λ_k|`. At the fixed point
//! `det(λ²M + λD + K + Z_red(λ)) = 0`: `λ` is an eigenvalue of the rotor
//! with the pad tilts as coordinates (massless pads, as in the transient),
//! so it agrees with the transient's ring-down by construction
//! (`tests/verdicts.rs`). A rotor without internal bearing coordinates
//! gets the synchronous modes unchanged.

use nalgebra::Complex;

type C64 = Complex<f64>;

use crate::bearing::equilibrium::condensed_at;
use crate::rotor::{JournalCoefficients, Rotor};
use crate::solver::Equilibrium;

use super::linearize::{LinearizeError, linearized_from};
use super::modal::mode_from_pair;
use super::modal::{ModalError, ModalOptions, ModalResult, Mode, modal_analysis};
use super::modal::{NON_OSCILLATING_DAMPING_RATIO, OverdampedRoot};
use super::pad_eigen::{PadEigenError, eigenvalues_of, rotor_vector, state_matrix_with_pads_and};

/// Why the modes could not be found.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum WhirlModesError {
    /// The rotor could not be linearized.
    #[error(transparent)]
    Linearize(#[from] LinearizeError),
    /// A modal analysis failed.
    #[error(transparent)]
    Modal(#[from] ModalError),
    /// A rotor with the pads condensed at a mode's eigenvalue could not be
    /// assembled.
    #[error("pads condensed at a mode's eigenvalue: {0}")]
    Assembly(#[from] crate::rotor::AssemblyError),
    /// The eigenvalues with the pad coordinates could not be found.
    #[error(transparent)]
    PadEigen(#[from] PadEigenError),
}

/// Iterations allowed per mode.
const MAX_ITERATIONS: usize = 40;
/// Convergence of a mode's eigenvalue (relative).
const TOLERANCE: f64 = 1e-10;

/// Every bearing at `equilibrium`, pads condensed at `s`.
pub fn coefficients_at(equilibrium: &Equilibrium, s: Complex<f64>) -> Vec<JournalCoefficients> {
    equilibrium
        .bearings
        .iter()
        .map(|(bearing, eval)| {
            let (k, c) = condensed_at(eval, s);
            JournalCoefficients {
                bearing: *bearing,
                stiffness: [[k[(0, 0)], k[(0, 1)]], [k[(1, 0)], k[(1, 1)]]],
                damping: [[c[(0, 0)], c[(0, 1)]], [c[(1, 0)], c[(1, 1)]]],
            }
        })
        .collect()
}

/// The modes of `rotor` at `speed` (rad/s) as [`modal_analysis`] lists them
/// (`options`), each with the pads condensed at its own eigenvalue (see the
/// module docs), by increasing damped frequency.
pub fn modes_at_own_frequency(
    rotor: &Rotor,
    speed: f64,
    options: &ModalOptions,
) -> Result<Vec<Mode>, WhirlModesError> {
    Ok(modal_analysis_own(rotor, speed, options)?.modes)
}

/// [`modal_analysis`] of `rotor` linearized at `speed` (rad/s), its modes
/// with the pads condensed at their own eigenvalues, held against every
/// eigenvalue with the pad coordinates ([`reconcile`]). What `rotor modes`, the
/// report and the stability study list.
pub fn modal_analysis_own(
    rotor: &Rotor,
    speed: f64,
    options: &ModalOptions,
) -> Result<ModalResult, WhirlModesError> {
    if rotor.nonlinear_bearings.is_empty() {
        return Ok(modal_analysis(rotor, speed, options)?);
    }
    let (linear, equilibrium) = linearized_from(rotor, speed, speed, None)?;
    let ModalResult {
        modes: synchronous,
        overdamped,
    } = modal_analysis(&linear, speed, options)?;
    let Some(eq) = with_pads(equilibrium) else {
        return Ok(ModalResult {
            modes: synchronous,
            overdamped,
        });
    };
    let linear_at = |s: Complex<f64>| -> Result<Rotor, WhirlModesError> {
        Ok(rotor.with_bearing_coefficients(&coefficients_at(&eq, s))?)
    };
    let mut out = Vec::with_capacity(synchronous.len());
    for start in synchronous {
        out.push(own_frequency(&linear_at, speed, start)?);
    }
    out.sort_by(|a, b| a.damped_frequency.total_cmp(&b.damped_frequency));
    reconcile(
        ModalResult {
            modes: out,
            overdamped,
        },
        (rotor, &eq, speed),
        &linear_at,
    )
}

/// The equilibrium, when one of its bearings has internal coordinates (pad
/// tilts) that a condensation depends on the frequency through.
pub fn with_pads(equilibrium: Option<Equilibrium>) -> Option<Equilibrium> {
    equilibrium.filter(|e| e.bearings.iter().any(|(_, eval)| eval.n() > 2))
}

/// `mode` iterated to its own eigenvalue: `linear_at(s)` is the linear
/// rotor with the pads condensed at `s` (and whatever else the analysis
/// adds), the mode nearest `λ_k` of `linear_at(λ_k)` is `λ_{k+1}`.
pub fn own_frequency<E>(
    linear_at: &dyn Fn(Complex<f64>) -> Result<Rotor, E>,
    speed: f64,
    mode: Mode,
) -> Result<Mode, E>
where
    E: From<ModalError>,
{
    let mut current = mode;
    for _ in 0..MAX_ITERATIONS {
        let lambda = current.eigenvalue;
        let linear = linear_at(lambda)?;
        let near = ModalOptions {
            modes: 3,
            target_frequency: lambda.im.abs(),
        };
        let Some(next) = modal_analysis(&linear, speed, &near)?
            .modes
            .into_iter()
            .min_by(|a, b| {
                (a.eigenvalue - lambda)
                    .norm()
                    .total_cmp(&(b.eigenvalue - lambda).norm())
            })
        else {
            return Ok(current);
        };
        let step = (next.eigenvalue - lambda).norm();
        current = next;
        if step <= TOLERANCE * lambda.norm() {
            break;
        }
    }
    Ok(current)
}

/// `result` (modes iterated to their own frequencies, `linear_at(s)` the
/// rotor with the pads condensed at `s`) held against every eigenvalue of
/// the rotor with the pad coordinates at `equilibrium` ([`pad_eigen`]): its
/// non-oscillating roots become the exact ones (every growing one, and the
/// decaying ones no farther from the origin than the last listed mode); a
/// root two seeds were iterated to is listed once, the other seed's place
/// taken by the unmatched exact root nearest it, and every growing
/// oscillating root no listed mode matches (1e-6 relative) is added, each
/// with its exact vector: no instability of the transient's linearization
/// goes unlisted.
pub fn reconcile<E>(
    result: ModalResult,
    at: (&Rotor, &Equilibrium, f64),
    linear_at: &dyn Fn(C64) -> Result<Rotor, E>,
) -> Result<ModalResult, E>
where
    E: From<ModalError> + From<PadEigenError>,
{
    reconcile_and(result, at, linear_at, &|_| {})
}

/// [`reconcile`] with `adjust` applied to the linear rotor of the exact
/// eigenproblem ([`super::pad_eigen::state_matrix_with_pads_and`]): what
/// `linear_at` adds besides the pads (a stability study's cross-coupling).
pub fn reconcile_and<E>(
    result: ModalResult,
    (rotor, equilibrium, speed): (&Rotor, &Equilibrium, f64),
    linear_at: &dyn Fn(C64) -> Result<Rotor, E>,
    adjust: &dyn Fn(&mut Rotor),
) -> Result<ModalResult, E>
where
    E: From<ModalError> + From<PadEigenError>,
{
    let ModalResult { modes, .. } = result;
    let f = state_matrix_with_pads_and(rotor, equilibrium, speed, adjust)?;
    let exact = eigenvalues_of(&f)?;
    let real_part = (1.0 - NON_OSCILLATING_DAMPING_RATIO.powi(2)).sqrt();
    let scale = exact.iter().fold(0.0_f64, |a, l| a.max(l.norm()));
    let oscillating = |l: &C64| l.im > real_part * l.norm() + 1e-12 * scale;
    let reach = modes
        .iter()
        .map(|m| m.eigenvalue.norm())
        .fold(0.0, f64::max);
    let mut overdamped: Vec<OverdampedRoot> = exact
        .iter()
        .filter(|l| {
            l.im.abs() <= real_part * l.norm() + 1e-12 * scale
                && (l.im >= 0.0 || l.im.abs() <= 1e-12 * scale)
                && l.norm() > 1e-12 * scale
                && (l.re > 0.0 || modes.is_empty() || l.norm() <= reach)
        })
        .map(|&eigenvalue| OverdampedRoot { eigenvalue })
        .collect();
    overdamped.sort_by(|a, b| a.eigenvalue.norm().total_cmp(&b.eigenvalue.norm()));
    // Two seeds iterated to one root list it once; the root the second one
    // missed is the unmatched exact root nearest it.
    let matched = |list: &[C64], l: &C64| list.iter().any(|m| (m - l).norm() <= 1e-6 * l.norm());
    let mut kept: Vec<Mode> = Vec::with_capacity(modes.len());
    let mut lost: Vec<C64> = Vec::new();
    for m in modes {
        let listed: Vec<C64> = kept.iter().map(|k| k.eigenvalue).collect();
        if matched(&listed, &m.eigenvalue) {
            lost.push(m.eigenvalue);
        } else {
            kept.push(m);
        }
    }
    let mut modes = kept;
    let mut taken: Vec<C64> = modes.iter().map(|m| m.eigenvalue).collect();
    let mut missing: Vec<C64> = Vec::new();
    for l in exact.iter().filter(|l| oscillating(l) && l.re > 0.0) {
        if !matched(&taken, l) {
            taken.push(*l);
            missing.push(*l);
        }
    }
    for seed in lost {
        let Some(l) = exact
            .iter()
            .filter(|l| oscillating(l) && !matched(&taken, l))
            .min_by(|a, b| (**a - seed).norm().total_cmp(&(**b - seed).norm()))
        else {
            continue;
        };
        taken.push(*l);
        missing.push(*l);
    }
    let n = rotor.dof_count();
    for lambda in missing {
        let Some(x) = rotor_vector(&f, n, lambda) else {
            continue;
        };
        modes.push(mode_from_pair(&linear_at(lambda)?, speed, lambda, &x));
    }
    modes.sort_by(|a, b| a.damped_frequency.total_cmp(&b.damped_frequency));
    Ok(ModalResult { modes, overdamped })
}
