//! Linearization of the nonlinear bearings about the rotor's static equilibrium,
//! for modal analysis, Campbell diagrams and unbalance response of rotors on
//! fluid-film bearings.

use crate::bearing::equilibrium::condensed_coefficients;
use crate::bearing::{BearingEval, BearingKind};
use crate::rotor::{AssemblyError, Rotor};
use crate::solver::{Simulator, SolverError, SolverOptions};

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

/// The rotor with every nonlinear bearing replaced by its stiffness and damping
/// at the static equilibrium under gravity at `speed` (rad/s), internal
/// coordinates (pad tilts) condensed for harmonic motion at `frequency` (rad/s;
/// the spin speed for synchronous coefficients). Linear rotors come back as they are.
pub fn linearized(rotor: &Rotor, speed: f64, frequency: f64) -> Result<Rotor, LinearizeError> {
    let mut model = rotor.model.clone();
    if rotor.nonlinear_bearings.is_empty() {
        return Rotor::new(model).map_err(|source| LinearizeError::Assembly { speed, source });
    }
    let solver = |source| LinearizeError::Solver { speed, source };
    let mut sim = Simulator::new(
        Rotor::new(model.clone()).map_err(|source| LinearizeError::Assembly { speed, source })?,
        SolverOptions::default(),
    )
    .map_err(solver)?;
    sim.set_speed(speed, 0.0).map_err(solver)?;
    sim.settle_static().map_err(solver)?;
    let state = sim.state().clone();
    let mut offset = 0;
    for placed in &mut model.bearings {
        let bearing = placed.kind.build();
        if bearing.is_linear() && bearing.internal_dofs() == 0 {
            continue;
        }
        let internal = bearing.internal_dofs();
        let dofs = &rotor.dofs;
        let at = |k: usize| dofs.free(placed.node, k).map_or(0.0, |i| state.u[i]);
        let mut q = vec![at(0), at(1)];
        q.extend_from_slice(&state.p[offset..offset + internal]);
        offset += internal;
        let mut eval = BearingEval::new(q.len());
        bearing
            .evaluate(&q, &vec![0.0; q.len()], speed, &mut eval)
            .map_err(|e| {
                solver(SolverError::Bearing {
                    name: placed.name.clone(),
                    time: 0.0,
                    source: e,
                })
            })?;
        let (k, c) = condensed_coefficients(&eval, frequency);
        placed.kind = BearingKind::Linear {
            stiffness: [[k[(0, 0)], k[(0, 1)]], [k[(1, 0)], k[(1, 1)]]],
            damping: [[c[(0, 0)], c[(0, 1)]], [c[(1, 0)], c[(1, 1)]]],
        };
    }
    Rotor::new(model).map_err(|source| LinearizeError::Assembly { speed, source })
}
