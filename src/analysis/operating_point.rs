//! The operating point of every bearing at one speed: static load, journal
//! position, eccentricity, attitude angle, minimum film thickness, friction
//! and its power loss, and the synchronous stiffness and damping there.
//!
//! The rotor is put in static equilibrium under gravity at the speed
//! ([`line_equilibrium`], continued on the bearing offsets when Newton from
//! the straight shaft needs it); each fluid-film bearing then reports from its own
//! evaluation there ([`Bearing::report`](crate::bearing::Bearing::report)):
//! `ε = e/C`, the attitude angle from the load line to the eccentricity vector
//! in the spin direction, `h_min = C(1 − ε)` for a plain bearing (per pad for
//! tilting pads), the Petroff-corrected film friction torque `T` and the power
//! `P = T Ω`. The coefficients are those the linearized analyses use
//! ([`bearing_coefficients`], pad tilts condensed at `ω = Ω`). Linear bearings
//! report their load `−K u` at the static deflection and their own K and C.

use crate::bearing::BearingKind;
use crate::fe::{DOF_PER_NODE, DOF_X, DOF_Y};
use crate::rotor::{DOF_PER_PEDESTAL, Rotor};
use crate::solver::{Equilibrium, SolverError};

use super::held_equilibrium::held_equilibrium;

use super::linear::{LinearError, static_deflection};
use super::linearize::bearing_coefficients;

/// Why an operating point could not be found.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum OperatingPointError {
    /// No static equilibrium at that speed.
    #[error("operating point at {speed} rad/s: {source}")]
    Solver { speed: f64, source: SolverError },
    /// The static deflection of a linear rotor failed.
    #[error(transparent)]
    Linear(#[from] LinearError),
}

/// One pad of a tilting-pad bearing at the operating point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PadState {
    /// Pivot angle from +x toward +y (rad).
    pub pivot: f64,
    /// Tilt as the pad's surface displacement `η = ψ R` (m).
    pub tilt: f64,
    /// Tilt angle `ψ = η / R` (rad), counter-clockwise.
    pub tilt_angle: f64,
    /// Minimum film thickness on the pad (m).
    pub min_film_thickness: f64,
    /// Radial displacement `ξ` of the pad on its pivot spring, outward (m);
    /// `None` on a rigid pivot.
    pub radial: Option<f64>,
}

/// Fraction of the force a bearing's stiffness makes over one clearance,
/// `max|K_ij| C`, below which a static load is round-off (the pad forces of a
/// centred tilting-pad journal sum to 1e-16 of it): the journal is unloaded.
pub const ROUND_OFF_LOAD: f64 = 1e-9;

/// The film state of a fluid-film bearing at the operating point.
#[derive(Debug, Clone, PartialEq)]
pub struct FilmState {
    /// Radial clearance `C` (m): the assembled clearance for tilting pads.
    pub clearance: f64,
    /// Eccentricity ratio `ε = e/C` (`C` the assembled clearance for tilting pads).
    pub eccentricity: f64,
    /// Attitude angle (rad): from the load line to the eccentricity vector, in the spin direction.
    pub attitude_angle: f64,
    /// Minimum film thickness (m): `C(1 − ε)` for a plain bearing.
    pub min_film_thickness: f64,
    /// Friction torque on the journal (N·m): film shear plus contact friction `μ N R`.
    pub friction_torque: f64,
    /// Normal force of the journal's contact with its bushing or pads (N);
    /// zero while the film carries it (at standstill it carries the load).
    pub contact_force: f64,
    /// Power dissipated in the film, `T Ω` (W).
    pub power_loss: f64,
    /// Pads of a tilting-pad bearing, in model order (empty otherwise).
    pub pads: Vec<PadState>,
    /// The machined pad clearance `C_p` (m) of a tilting-pad bearing (its
    /// `clearance`, `C_b = C_p (1 − m)`), `None` for every other kind.
    pub pad_clearance: Option<f64>,
}

impl FilmState {
    /// `e/C_p`, the journal's offset over the machined pad clearance, of a
    /// tilting-pad bearing (whose [`eccentricity`](Self::eccentricity) is
    /// `e/C_b`); `None` for every other kind.
    pub fn eccentricity_over_pad_clearance(&self) -> Option<f64> {
        self.pad_clearance
            .map(|c_p| self.eccentricity * self.clearance / c_p)
    }

    /// Whether the bearing has a film geometry (a clearance): a table
    /// bearing has none, so its eccentricity, attitude angle and film
    /// thickness are not defined (reports leave them empty, not 0, which
    /// would read as metal contact).
    pub fn has_geometry(&self) -> bool {
        self.clearance > 0.0
    }
}

/// One bearing at the operating point.
#[derive(Debug, Clone, PartialEq)]
pub struct BearingOperatingPoint {
    /// Bearing index in the model.
    pub bearing: usize,
    /// Bearing name.
    pub name: String,
    /// Journal position `(x, y)` relative to the bearing centre as installed
    /// (m): to its housing for a bearing on a pedestal, less its offset
    /// (`offset_x`, `offset_y`).
    pub journal: [f64; 2],
    /// The housing, for a bearing on a pedestal; `None` on rigid ground.
    pub housing: Option<Housing>,
    /// Force of the bearing on the journal `(Fx, Fy)` (N).
    pub force: [f64; 2],
    /// Static load `|F|` (N).
    pub load: f64,
    /// Film state; `None` for a linear bearing.
    pub film: Option<FilmState>,
    /// Stiffness `K = −∂F/∂q` (N/m), row-major `[[kxx, kxy], [kyx, kyy]]`.
    pub stiffness: [[f64; 2]; 2],
    /// Damping `C = −∂F/∂q̇` (N·s/m), row-major.
    pub damping: [[f64; 2]; 2],
}

impl BearingOperatingPoint {
    /// Whether the static load is round-off ([`ROUND_OFF_LOAD`] of
    /// `max|K_ij| C`; exactly zero for a linear bearing): the journal of a
    /// vertical rotor sits centred and has no attitude angle.
    pub fn is_unloaded(&self) -> bool {
        let k = self
            .stiffness
            .iter()
            .flatten()
            .fold(0.0f64, |a, v| a.max(v.abs()));
        let clearance = self.film.as_ref().map_or(0.0, |f| f.clearance);
        self.load <= ROUND_OFF_LOAD * k * clearance
    }
}

/// The housing of a bearing on a pedestal at the operating point.
#[derive(Debug, Clone, PartialEq)]
pub struct Housing {
    /// Pedestal index in the model.
    pub pedestal: usize,
    /// Pedestal name.
    pub name: String,
    /// Displacement `(x, y)` (m), absolute.
    pub displacement: [f64; 2],
}

/// One pedestal at the operating point.
#[derive(Debug, Clone, PartialEq)]
pub struct PedestalOperatingPoint {
    /// Pedestal index in the model.
    pub pedestal: usize,
    /// Pedestal name.
    pub name: String,
    /// Static deflection `(x, y)` (m), absolute.
    pub deflection: [f64; 2],
    /// Load `(Fx, Fy)` (N) the pedestal puts on its support (ground, or the
    /// pedestal it stands on) through its spring: `K (q − q_on)`; statically
    /// its weight plus the bearing loads (and pedestals) it carries.
    pub load: [f64; 2],
}

/// The static state at `speed`: the displacement on all DOFs and, for a
/// rotor on nonlinear bearings, its equilibrium.
pub(super) fn static_state(
    rotor: &Rotor,
    speed: f64,
) -> Result<(Vec<f64>, Option<Equilibrium>), OperatingPointError> {
    if rotor.nonlinear_bearings.is_empty() {
        Ok((static_deflection(rotor)?, None))
    } else {
        let (eq, _) = held_equilibrium(rotor, speed, None)
            .map_err(|source| OperatingPointError::Solver { speed, source })?;
        Ok((rotor.dofs.expand(&eq.displacement), Some(eq)))
    }
}

/// Translation `k` of pedestal `p` in a vector on all DOFs.
pub(super) fn pedestal_at(rotor: &Rotor, all: &[f64], p: usize, k: usize) -> f64 {
    all[rotor.dofs.node_count() * DOF_PER_NODE + p * DOF_PER_PEDESTAL + k]
}

/// Every pedestal of `rotor` at the static equilibrium under gravity at
/// `speed` (rad/s): its deflection and the load it passes on.
pub fn pedestal_operating_points(
    rotor: &Rotor,
    speed: f64,
) -> Result<Vec<PedestalOperatingPoint>, OperatingPointError> {
    if rotor.model.pedestals.is_empty() {
        return Ok(Vec::new());
    }
    let (all, _) = static_state(rotor, speed)?;
    let at = |p: usize| {
        [
            pedestal_at(rotor, &all, p, 0),
            pedestal_at(rotor, &all, p, 1),
        ]
    };
    Ok(rotor
        .model
        .pedestals
        .iter()
        .enumerate()
        .map(|(p, pedestal)| {
            let q = at(p);
            let below = pedestal.on.map_or([0.0; 2], at);
            let o = pedestal.offset;
            let d = [q[0] - below[0] - o[0], q[1] - below[1] - o[1]];
            let k = &pedestal.stiffness;
            PedestalOperatingPoint {
                pedestal: p,
                name: pedestal.name.clone(),
                deflection: q,
                load: [
                    k[0][0] * d[0] + k[0][1] * d[1],
                    k[1][0] * d[0] + k[1][1] * d[1],
                ],
            }
        })
        .collect())
}

/// Every bearing of `rotor` at the static equilibrium under gravity at `speed`
/// (rad/s). Rub elements and seals are not bearings and are left out (their
/// contact forces are outputs of the transient simulator and the FMU).
pub fn operating_point(
    rotor: &Rotor,
    speed: f64,
) -> Result<Vec<BearingOperatingPoint>, OperatingPointError> {
    let model = &rotor.model;
    let (displacement, at) = static_state(rotor, speed)?;
    let housing_of = |b: &crate::model::PlacedBearing| {
        b.pedestal.map(|p| Housing {
            pedestal: p,
            name: model.pedestals[p].name.clone(),
            displacement: [
                pedestal_at(rotor, &displacement, p, 0),
                pedestal_at(rotor, &displacement, p, 1),
            ],
        })
    };
    // Relative to the bearing's centre: its housing, less its offset.
    let journal = |b: &crate::model::PlacedBearing| {
        let h = housing_of(b).map_or([0.0; 2], |h| h.displacement);
        [
            displacement[b.node * DOF_PER_NODE + DOF_X] - h[0] - b.offset[0],
            displacement[b.node * DOF_PER_NODE + DOF_Y] - h[1] - b.offset[1],
        ]
    };
    let mut out = Vec::with_capacity(model.bearings.len());
    let mut tilt_offset = 0;
    let film_coefficients = at
        .as_ref()
        .map(|eq| bearing_coefficients(eq, speed))
        .unwrap_or_default();
    for (index, b) in model.bearings.iter().enumerate() {
        if !b.kind.is_bearing() {
            continue;
        }
        let j = journal(b);
        let housing = housing_of(b);
        let point = match &b.kind {
            BearingKind::Linear { stiffness, damping } => {
                let f = [
                    -(stiffness[0][0] * j[0] + stiffness[0][1] * j[1]),
                    -(stiffness[1][0] * j[0] + stiffness[1][1] * j[1]),
                ];
                BearingOperatingPoint {
                    bearing: index,
                    name: b.name.clone(),
                    journal: j,
                    housing,
                    force: f,
                    load: f[0].hypot(f[1]),
                    film: None,
                    stiffness: *stiffness,
                    damping: *damping,
                }
            }
            kind => {
                let eq = at
                    .as_ref()
                    .expect("a film bearing makes the rotor nonlinear");
                let eval = &eq
                    .bearings
                    .iter()
                    .find(|(i, _)| *i == index)
                    .expect("the equilibrium evaluates every film bearing")
                    .1;
                let coefficients = film_coefficients
                    .iter()
                    .find(|c| c.bearing == index)
                    .expect("coefficients of every film bearing");
                let bearing = kind.build();
                let n_pads = bearing.internal_dofs();
                let tilts = &eq.tilts[tilt_offset..tilt_offset + n_pads];
                tilt_offset += n_pads;
                let q: Vec<f64> = j.iter().chain(tilts).copied().collect();
                let report = bearing.report(&q, &vec![0.0; q.len()], speed, eval);
                let pad_clearance = match kind.short_film().as_ref() {
                    BearingKind::TiltingPad(tp) => Some(tp.clearance),
                    _ => None,
                };
                let pads = match kind.short_film().as_ref() {
                    BearingKind::TiltingPad(tp) => tp
                        .pads
                        .iter()
                        .enumerate()
                        .map(|(k, pad)| PadState {
                            pivot: pad.pivot(),
                            tilt: tilts[k],
                            tilt_angle: tilts[k] / tp.radius,
                            radial: tp.support.pivot_stiffness.map(|_| tilts[tp.pads.len() + k]),
                            min_film_thickness: tp.pad_min_film_thickness(k, &q),
                        })
                        .collect(),
                    _ => Vec::new(),
                };
                let f = eval.journal().force;
                BearingOperatingPoint {
                    bearing: index,
                    name: b.name.clone(),
                    journal: j,
                    housing,
                    force: [f.x, f.y],
                    load: f.norm(),
                    film: Some(FilmState {
                        clearance: kind.journal_clearance().unwrap_or(0.0),
                        eccentricity: report.eccentricity,
                        attitude_angle: report.attitude_angle,
                        min_film_thickness: report.min_film_thickness,
                        friction_torque: report.friction_torque,
                        contact_force: report.contact_force,
                        power_loss: report.power_loss,
                        pads,
                        pad_clearance,
                    }),
                    stiffness: coefficients.stiffness,
                    damping: coefficients.damping,
                }
            }
        };
        out.push(point);
    }
    Ok(out)
}
