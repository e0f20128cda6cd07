//! The operating point of the elements that are not bearings (issue 48):
//! seals, rubs and magnetic pulls at the static equilibrium (their force on
//! the rotor there, evaluated afresh at the journal's position relative to
//! the element's centre, with zero rates), thrust bearings (axial load,
//! friction torque and power `P = T Ω` at the speed, [`ThrustBearing`]) and
//! the external forces (static, or harmonic with its frequency at the
//! speed).
//!
//! The equilibrium is the one the bearings hold
//! ([`super::held_equilibrium`]), as in [`super::operating_point`]: the
//! elements' forces and the bearings' together balance the rotor's lateral
//! loads.
//!
//! [`ThrustBearing`]: crate::bearing::thrust::ThrustBearing

use crate::bearing::BearingEval;
use crate::fe::{DOF_PER_NODE, DOF_X, DOF_Y};
use crate::model::{ForceKind, HarmonicFrequency};
use crate::rotor::Rotor;

use super::operating_point::{OperatingPointError, pedestal_at, static_state};

/// A seal, rub or magnetic pull at the static equilibrium.
#[derive(Debug, Clone, PartialEq)]
pub struct ElementOperatingPoint {
    /// Model index in `bearings`.
    pub element: usize,
    /// Its name.
    pub name: String,
    /// The rotor's displacement relative to the element's centre (its
    /// housing, less its offset) `(x, y)` (m).
    pub displacement: [f64; 2],
    /// Its force on the rotor `(Fx, Fy)` (N).
    pub force: [f64; 2],
}

/// A thrust bearing at the speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThrustOperatingPoint {
    /// Model index in `thrust_bearings`.
    pub thrust: usize,
    /// Axial load `W` (N).
    pub load: f64,
    /// Friction torque opposing the spin (N·m).
    pub friction_torque: f64,
    /// Power dissipated (W).
    pub power_loss: f64,
}

/// An external force at the speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ForceOperatingPoint {
    /// Constant `(Fx, Fy)` (N).
    Static([f64; 2]),
    /// Rotating or along a line, `magnitude` (N) at `frequency` (rad/s) at
    /// this speed.
    Harmonic { magnitude: f64, frequency: f64 },
}

/// Every seal, rub and magnetic pull of `rotor` at the static equilibrium at
/// `speed` (rad/s), in model order.
pub fn element_operating_points(
    rotor: &Rotor,
    speed: f64,
) -> Result<Vec<ElementOperatingPoint>, OperatingPointError> {
    let model = &rotor.model;
    if model.bearings.iter().all(|b| b.kind.is_bearing()) {
        return Ok(Vec::new());
    }
    let (all, _) = static_state(rotor, speed)?;
    let mut out = Vec::new();
    for (index, b) in model.bearings.iter().enumerate() {
        if b.kind.is_bearing() {
            continue;
        }
        let housing = b.pedestal.map_or([0.0; 2], |p| {
            [
                pedestal_at(rotor, &all, p, 0),
                pedestal_at(rotor, &all, p, 1),
            ]
        });
        let q = [
            all[b.node * DOF_PER_NODE + DOF_X] - housing[0] - b.offset[0],
            all[b.node * DOF_PER_NODE + DOF_Y] - housing[1] - b.offset[1],
        ];
        let element = b.kind.build();
        let n = 2 + element.internal_dofs();
        let mut state = vec![0.0; n];
        state[..2].copy_from_slice(&q);
        let mut eval = BearingEval::new(n);
        element
            .evaluate(&state, &vec![0.0; n], speed, &mut eval)
            .map_err(|e| OperatingPointError::Solver {
                speed,
                source: crate::solver::SolverError::Static(format!("{}: {e}", b.name)),
            })?;
        out.push(ElementOperatingPoint {
            element: index,
            name: b.name.clone(),
            displacement: q,
            force: [eval.force[0], eval.force[1]],
        });
    }
    Ok(out)
}

/// Every thrust bearing of `rotor` at `speed` (rad/s).
pub fn thrust_operating_points(rotor: &Rotor, speed: f64) -> Vec<ThrustOperatingPoint> {
    rotor
        .model
        .thrust_bearings
        .iter()
        .enumerate()
        .map(|(thrust, t)| ThrustOperatingPoint {
            thrust,
            load: t.bearing.load,
            friction_torque: t.bearing.friction_torque(speed).0,
            power_loss: t.bearing.power_loss(speed),
        })
        .collect()
}

/// Every external force of `rotor` at `speed` (rad/s).
pub fn force_operating_points(rotor: &Rotor, speed: f64) -> Vec<ForceOperatingPoint> {
    rotor
        .model
        .forces
        .iter()
        .map(|f| match f.kind {
            ForceKind::Static(xy) => ForceOperatingPoint::Static(xy),
            ForceKind::Harmonic {
                magnitude,
                frequency,
                ..
            } => ForceOperatingPoint::Harmonic {
                magnitude,
                frequency: match frequency {
                    HarmonicFrequency::Ratio(r) => r * speed,
                    HarmonicFrequency::Fixed(w) => w,
                },
            },
        })
        .collect()
}
