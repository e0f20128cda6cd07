//! Steady response to a harmonic external force (`[[forces]]`: a vortex rope
//! at 0.3× running speed, blade passing at n×, a fixed-frequency excitation),
//! the generalization of the unbalance response to any frequency and
//! direction.
//!
//! At spin `Ω` the force of frequency `ω` (`r Ω` or fixed) and complex
//! amplitude `F̂` ([`Rotor::harmonic_load`]) drives
//! `(K − ω² M + iω (C + Ω G)) X = F̂`, `q(t) = Re(X e^{iωt})`, with the
//! nonlinear bearings linearized about the static equilibrium at `Ω` and
//! their internal coordinates (pad tilts) condensed at `ω`
//! ([`linearized_from`]). A backward force (or any negative `ω`) is solved at
//! the negative frequency, which is what it is.

use nalgebra::Complex;

use crate::linalg::{LinalgError, map_to_complex};
use crate::rotor::Rotor;

use super::linear::node_xy;
use super::linearize::{LinearizeError, linearized_from};
use super::modal::damping_at_speed;
use super::unbalance::{ResponsePoint, UnbalanceSweep};

type C64 = Complex<f64>;

/// Why a forced response could not be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ForcedError {
    /// No such harmonic force.
    #[error("{0}")]
    Force(String),
    /// The rotor could not be linearized.
    #[error(transparent)]
    Linearize(#[from] LinearizeError),
    /// The dynamic stiffness is singular (an undamped resonance exactly).
    #[error("forced response at {speed} rad/s: {source}")]
    Linalg { speed: f64, source: LinalgError },
}

/// The index of the harmonic force named `name` in the model's `[[forces]]`.
pub fn harmonic_force(rotor: &Rotor, name: &str) -> Result<usize, ForcedError> {
    let forces = &rotor.model.forces;
    let harmonic: Vec<&str> = forces
        .iter()
        .filter(|f| matches!(f.kind, crate::model::ForceKind::Harmonic { .. }))
        .map(|f| f.name.as_str())
        .collect();
    forces
        .iter()
        .position(|f| f.name == name)
        .filter(|&k| matches!(forces[k].kind, crate::model::ForceKind::Harmonic { .. }))
        .ok_or_else(|| {
            ForcedError::Force(format!(
                "model {} has no harmonic force {name:?} (its harmonic forces: {})",
                rotor.model.name,
                if harmonic.is_empty() {
                    "none".to_string()
                } else {
                    harmonic.join(", ")
                }
            ))
        })
}

/// The frequency (rad/s) and the steady response on all DOFs (`4·node + k`,
/// m) of harmonic force `index` at its model amplitude, at spin `speed`.
pub fn forced_response(
    rotor: &Rotor,
    index: usize,
    speed: f64,
) -> Result<(f64, Vec<C64>), ForcedError> {
    let magnitude = match rotor.model.forces[index].kind {
        crate::model::ForceKind::Harmonic { magnitude, .. } => magnitude,
        crate::model::ForceKind::Static(_) => {
            return Err(ForcedError::Force(format!(
                "force {} is static: it has no frequency response",
                rotor.model.forces[index].name
            )));
        }
    };
    let Some((omega, load)) = rotor.harmonic_load(index, magnitude, speed) else {
        unreachable!("a harmonic force has a harmonic load");
    };
    let (linear, _) = linearized_from(rotor, speed, omega, None)?;
    let lin = |source| ForcedError::Linalg { speed, source };
    let mut z = map_to_complex(&linear.stiffness);
    z.scale_add(C64::new(-omega * omega, 0.0), &map_to_complex(&linear.mass));
    z.scale_add(
        C64::new(0.0, omega),
        &map_to_complex(&damping_at_speed(&linear, speed)),
    );
    let lu = z.lu().map_err(lin)?;
    let mut x = load;
    lu.solve_in_place(&mut x);
    Ok((omega, linear.dofs.expand(&x)))
}

/// The response of `points` to harmonic force `index` at every speed of
/// `speeds` (rad/s): `response[k][p] = (X, Y)` at the force's frequency.
pub fn forced_sweep(
    rotor: &Rotor,
    index: usize,
    speeds: &[f64],
    points: &[ResponsePoint],
) -> Result<(Vec<f64>, UnbalanceSweep), ForcedError> {
    let mut frequencies = Vec::with_capacity(speeds.len());
    let mut response = Vec::with_capacity(speeds.len());
    for &s in speeds {
        let (omega, q) = forced_response(rotor, index, s)?;
        frequencies.push(omega);
        response.push(points.iter().map(|p| node_xy(&q, p.node)).collect());
    }
    Ok((
        frequencies,
        UnbalanceSweep {
            speeds: speeds.to_vec(),
            points: points.to_vec(),
            response,
        },
    ))
}
