//! Linearization of the nonlinear bearings about the rotor's static equilibrium,
//! for modal analysis, Campbell diagrams and unbalance response of rotors on
//! fluid-film bearings. Per speed it costs one static equilibrium
//! ([`equilibrium`], to the default relative residual 1e-8) and the condensed
//! coefficients of each bearing there; the linear rotor is the assembled one
//! with 2×2 blocks added at the journals ([`Rotor::with_bearing_coefficients`]).
//!
//! The analyses start every equilibrium from the undeflected rotor. Started
//! from the equilibrium at the previous speed ([`linearized_from`]), Newton
//! stops at another point within the tolerance, and the damped frequencies
//! move by up to 2e-9 relative (Jeffcott rotor, 6000 rpm), more than the
//! 1e-9 the analyses are held to.

use crate::bearing::equilibrium::condensed_coefficients;
use crate::rotor::{AssemblyError, JournalCoefficients, Rotor};
use crate::solver::{Equilibrium, SolverError};

use super::held_equilibrium::held_equilibrium;

/// Why a rotor could not be linearized.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LinearizeError {
    /// No static equilibrium (e.g. zero speed on plain bearings under load).
    #[error("linearizing at {speed} rad/s: {source}")]
    Solver { speed: f64, source: SolverError },
    /// The linearized model could not be assembled.
    #[error("linearizing at {speed} rad/s: {source}")]
    Assembly { speed: f64, source: AssemblyError },
}

/// Stiffness and damping of every nonlinear bearing at `equilibrium`, internal
/// coordinates (pad tilts) condensed for harmonic motion at `frequency` (rad/s),
/// `Z_red = Z_jj − Z_jp Z_pp⁻¹ Z_pj` with `Z = K + iωC`
/// ([`condensed_coefficients`]).
pub fn bearing_coefficients(equilibrium: &Equilibrium, frequency: f64) -> Vec<JournalCoefficients> {
    equilibrium
        .bearings
        .iter()
        .map(|(bearing, eval)| {
            let (k, c) = condensed_coefficients(eval, frequency);
            JournalCoefficients {
                bearing: *bearing,
                stiffness: [[k[(0, 0)], k[(0, 1)]], [k[(1, 0)], k[(1, 1)]]],
                damping: [[c[(0, 0)], c[(0, 1)]], [c[(1, 0)], c[(1, 1)]]],
            }
        })
        .collect()
}

/// The rotor with every nonlinear bearing replaced by its stiffness and damping
/// at the static equilibrium under gravity at `speed` (rad/s) that the
/// bearings hold ([`held_equilibrium`]: off a statically unstable centre), internal
/// coordinates (pad tilts) condensed for harmonic motion at `frequency` (rad/s;
/// the spin speed for synchronous coefficients), and that equilibrium. `start`
/// is a nearby equilibrium to start Newton from (see the module docs for what
/// that changes). Linear rotors come back as copies, without an equilibrium.
pub fn linearized_from(
    rotor: &Rotor,
    speed: f64,
    frequency: f64,
    start: Option<&Equilibrium>,
) -> Result<(Rotor, Option<Equilibrium>), LinearizeError> {
    let assembly = |source| LinearizeError::Assembly { speed, source };
    if rotor.nonlinear_bearings.is_empty() {
        return Ok((
            rotor.with_bearing_coefficients(&[]).map_err(assembly)?,
            None,
        ));
    }
    let (at, _) = held_equilibrium(rotor, speed, start)
        .map_err(|source| LinearizeError::Solver { speed, source })?;
    let linear = rotor
        .with_bearing_coefficients(&bearing_coefficients(&at, frequency))
        .map_err(assembly)?;
    Ok((linear, Some(at)))
}

/// [`linearized_from`] started from the undeflected rotor.
pub fn linearized(rotor: &Rotor, speed: f64, frequency: f64) -> Result<Rotor, LinearizeError> {
    Ok(linearized_from(rotor, speed, frequency, None)?.0)
}
