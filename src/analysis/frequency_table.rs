//! The condensed coefficients of every fluid-film bearing at its operating
//! point over speeds × whirl frequencies (issue 45): the 8-coefficient view
//! vendors and ROSS give for tilting pads, with the frequency named. At each
//! speed `Ω` the rotor is put in the equilibrium the bearings hold
//! ([`held_equilibrium`]) and each bearing's pad tilts are condensed for
//! harmonic whirl at `ω = r Ω` for every ratio `r`
//! ([`bearing_coefficients`]: `Z_red = Z_jj − Z_jp Z_pp⁻¹ Z_pj`,
//! `Z = K + iωC`); `r = 1` gives the synchronous coefficients the operating
//! point prints, bit for bit. Plain bearings (no internal coordinates) give
//! the same K and C at every ratio.

use crate::rotor::Rotor;
use crate::solver::SolverError;

use super::held_equilibrium::held_equilibrium;
use super::linearize::bearing_coefficients;

/// One bearing at one speed and whirl frequency.
#[derive(Debug, Clone, PartialEq)]
pub struct FrequencyRow {
    /// Model index of the bearing.
    pub bearing: usize,
    /// Its name.
    pub name: String,
    /// Spin speed `Ω` (rad/s).
    pub speed: f64,
    /// Whirl frequency over spin speed `r`.
    pub ratio: f64,
    /// Stiffness `[[kxx, kxy], [kyx, kyy]]` (N/m).
    pub stiffness: [[f64; 2]; 2],
    /// Damping (N·s/m).
    pub damping: [[f64; 2]; 2],
}

/// Every fluid-film bearing of `rotor` at every speed of `speeds` (rad/s)
/// and every whirl ratio of `ratios` (see the module docs); rows by speed,
/// then ratio, then bearing. Empty for a rotor without fluid-film bearings.
pub fn frequency_table(
    rotor: &Rotor,
    speeds: &[f64],
    ratios: &[f64],
) -> Result<Vec<FrequencyRow>, SolverError> {
    let mut rows = Vec::new();
    if rotor.nonlinear_bearings.is_empty() {
        return Ok(rows);
    }
    for &speed in speeds {
        let (eq, _) = held_equilibrium(rotor, speed, None)?;
        for &ratio in ratios {
            for c in bearing_coefficients(&eq, ratio * speed) {
                let placed = &rotor.model.bearings[c.bearing];
                if !placed.kind.is_bearing() {
                    continue;
                }
                rows.push(FrequencyRow {
                    bearing: c.bearing,
                    name: placed.name.clone(),
                    speed,
                    ratio,
                    stiffness: c.stiffness,
                    damping: c.damping,
                });
            }
        }
    }
    Ok(rows)
}
