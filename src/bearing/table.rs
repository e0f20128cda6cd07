//! Bearings and seals given by their linear coefficients as a table over
//! speed — a vendor's bearing code, a seal code — interpolated with PCHIP
//! ([`crate::linalg::pchip`], as ROSS interpolates its tables) and held at the
//! end values outside the table:
//! `F = −K(Ω) q − C(Ω) q̇`, with `K`, `C` 2×2 and any sign (cross-coupled,
//! negative). A seal may also close on its stator: [`SealElement`] adds the
//! contact law of a rub at its clearance.
//!
//! ```
//! use rotor_bearing::bearing::table::{CoefficientTable, TableBearing};
//! use rotor_bearing::bearing::{Bearing, BearingEval};
//!
//! // kxx, kxy, kyx, kyy, cxx, cxy, cyx, cyy at 100 and 300 rad/s.
//! let mut columns: [Vec<f64>; 8] = Default::default();
//! columns[0] = vec![1e8, 3e8]; // kxx
//! columns[1] = vec![2e7, 6e7]; // kxy: cross-coupled
//! columns[2] = vec![-2e7, -6e7]; // kyx
//! columns[3] = vec![1e8, 3e8]; // kyy
//! for c in &mut columns[4..] {
//!     *c = vec![0.0; 2]; // no damping
//! }
//! let table = CoefficientTable::new(vec![100.0, 300.0], columns)?;
//! let bearing = TableBearing { table, added_mass: [[0.0; 2]; 2] };
//! let mut eval = BearingEval::new(2);
//! bearing.evaluate(&[1e-5, 0.0], &[0.0, 0.0], 200.0, &mut eval)?;
//! assert_eq!(eval.k(0, 0), 2e8); // halfway (two points: linear)
//! assert_eq!(eval.force[1], 4e7 * 1e-5); // −kyx x
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use nalgebra::{Matrix2, Vector2};

use super::contact::ContactLaw;
use super::plain::contact_friction_torque;
use super::{Bearing, BearingError, BearingEval, BearingForce, BearingReport, check_state};
use crate::linalg::pchip::{Pchip, PchipError};

/// Names of the eight coefficient columns, in table order.
pub const COLUMNS: [&str; 8] = ["kxx", "kxy", "kyx", "kyy", "cxx", "cxy", "cyx", "cyy"];

/// Why a coefficient table cannot be interpolated: the column and the reason.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("column {column}: {source}")]
pub struct TableError {
    /// Name of the column (one of [`COLUMNS`]).
    pub column: &'static str,
    /// What is wrong with it.
    pub source: PchipError,
}

/// Stiffness (N/m) and damping (N·s/m) over speed (rad/s).
#[derive(Debug, Clone, PartialEq)]
pub struct CoefficientTable {
    /// Speeds (rad/s), strictly increasing.
    pub speeds: Vec<f64>,
    /// The columns of [`COLUMNS`], one value per speed.
    pub columns: [Vec<f64>; 8],
    interpolants: Vec<Pchip>,
}

impl CoefficientTable {
    /// A table of `columns` (in the order of [`COLUMNS`]) at `speeds`; the
    /// error names the column.
    pub fn new(speeds: Vec<f64>, columns: [Vec<f64>; 8]) -> Result<Self, TableError> {
        let interpolants = columns
            .iter()
            .zip(COLUMNS)
            .map(|(c, name)| {
                Pchip::new(&speeds, c).map_err(|source| TableError {
                    column: name,
                    source,
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Self {
            speeds,
            columns,
            interpolants,
        })
    }

    /// The speed range of the table (rad/s).
    pub fn range(&self) -> (f64, f64) {
        (self.speeds[0], self.speeds[self.speeds.len() - 1])
    }

    /// Whether `speed` (rad/s) lies within the table (else its end values
    /// hold), to the round-off of a speed converted from rpm (1e-12 of the
    /// table's largest speed): a one-row table covers its own speed however
    /// the caller converted it.
    pub fn covers(&self, speed: f64) -> bool {
        let (lo, hi) = self.range();
        let slack = 1e-12 * lo.abs().max(hi.abs());
        (lo - slack..=hi + slack).contains(&speed)
    }

    /// What a front end says when the table is asked for `speed` (rad/s)
    /// outside its rows (the end values hold there).
    pub fn outside_message(&self, speed: f64) -> String {
        let (lo, hi) = self.range();
        let rpm = |w: f64| (w * 30.0 / std::f64::consts::PI * 1e3).round() / 1e3;
        format!(
            "speed {} rpm is outside its coefficient table ({} to {} rpm): the coefficients are held at the table's {} values",
            rpm(speed),
            rpm(lo),
            rpm(hi),
            if speed < lo { "first" } else { "last" }
        )
    }

    /// What a front end says, once for the whole analysis, when some of its
    /// `speeds` (rad/s) lie outside the table's rows: the range of those
    /// speeds on each side and the table's range (one speed alone:
    /// [`outside_message`](Self::outside_message)). `None` when the table
    /// covers every speed.
    pub fn outside_speeds_message(&self, speeds: &[f64]) -> Option<String> {
        let (lo, hi) = self.range();
        let rpm = |w: f64| (w * 30.0 / std::f64::consts::PI * 1e3).round() / 1e3;
        let side = |below: bool| {
            let mut out = speeds
                .iter()
                .copied()
                .filter(|&w| !self.covers(w) && (w < lo) == below);
            let first = out.next()?;
            Some(out.fold((first, first), |(a, b), w| (a.min(w), b.max(w))))
        };
        let (below, above) = (side(true), side(false));
        let ends = |(a, b): (f64, f64)| {
            if rpm(a) == rpm(b) {
                format!("{} rpm", rpm(a))
            } else {
                format!("{} to {} rpm", rpm(a), rpm(b))
            }
        };
        match (below, above) {
            (None, None) => None,
            (Some((a, b)), None) | (None, Some((a, b))) if rpm(a) == rpm(b) => {
                Some(self.outside_message(a))
            }
            (Some(r), None) => Some(format!(
                "speeds {} are below its coefficient table ({} to {} rpm): the coefficients are held at the table's first values there",
                ends(r),
                rpm(lo),
                rpm(hi)
            )),
            (None, Some(r)) => Some(format!(
                "speeds {} are above its coefficient table ({} to {} rpm): the coefficients are held at the table's last values there",
                ends(r),
                rpm(lo),
                rpm(hi)
            )),
            (Some(r), Some(t)) => Some(format!(
                "speeds {} and {} are outside its coefficient table ({} to {} rpm): the coefficients are held at the table's first and last values there",
                ends(r),
                ends(t),
                rpm(lo),
                rpm(hi)
            )),
        }
    }

    /// `K` and `C` at `speed` (rad/s), row-major.
    pub fn at(&self, speed: f64) -> ([[f64; 2]; 2], [[f64; 2]; 2]) {
        let v: [f64; 8] = std::array::from_fn(|k| self.interpolants[k].at(speed));
        ([[v[0], v[1]], [v[2], v[3]]], [[v[4], v[5]], [v[6], v[7]]])
    }

    /// The linear force `−K q − C q̇` of the table at `speed` and its Jacobians.
    fn force(&self, q: &[f64], qdot: &[f64], speed: f64) -> BearingForce {
        let (k, c) = self.at(speed);
        let stiffness = Matrix2::new(k[0][0], k[0][1], k[1][0], k[1][1]);
        let damping = Matrix2::new(c[0][0], c[0][1], c[1][0], c[1][1]);
        let (x, v) = (Vector2::new(q[0], q[1]), Vector2::new(qdot[0], qdot[1]));
        BearingForce {
            force: -(stiffness * x + damping * v),
            stiffness,
            damping,
        }
    }
}

/// A bearing given by its coefficient table.
#[derive(Debug, Clone, PartialEq)]
pub struct TableBearing {
    /// The coefficients over speed.
    pub table: CoefficientTable,
    /// Added mass (kg, row-major), constant over speed: assembled into the
    /// mass matrix, not part of [`Bearing::evaluate`].
    pub added_mass: [[f64; 2]; 2],
}

impl Bearing for TableBearing {
    fn evaluate(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<(), BearingError> {
        check_state(2, q, qdot, speed, out)?;
        out.clear();
        out.add_transformed(&self.table.force(q, qdot, speed), None);
        Ok(())
    }

    /// Linear in the state, but the coefficients change with speed: it is
    /// evaluated like a nonlinear bearing, at the current speed.
    fn is_linear(&self) -> bool {
        false
    }
}

/// A seal (annular liquid seal, labyrinth, wear ring): its coefficient table
/// and, when a clearance is given, the contact law of a rub at that radial
/// clearance, so that a seal that closes touches its stator.
#[derive(Debug, Clone, PartialEq)]
pub struct SealElement {
    /// The coefficients over speed.
    pub table: CoefficientTable,
    /// Added mass (kg, row-major), constant over speed (see [`TableBearing`]).
    pub added_mass: [[f64; 2]; 2],
    /// Contact with the stator at the seal clearance; `None`: never touches.
    pub contact: Option<ContactLaw>,
}

impl Bearing for SealElement {
    fn evaluate(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<(), BearingError> {
        check_state(2, q, qdot, speed, out)?;
        out.clear();
        out.add_transformed(&self.table.force(q, qdot, speed), None);
        if let Some(law) = &self.contact {
            let (force, _) = law.evaluate(
                Vector2::new(q[0], q[1]),
                Vector2::new(qdot[0], qdot[1]),
                speed,
            );
            out.add_transformed(&force, None);
        }
        Ok(())
    }

    fn is_linear(&self) -> bool {
        false
    }

    fn report(&self, q: &[f64], qdot: &[f64], speed: f64, _eval: &BearingEval) -> BearingReport {
        let Some(law) = &self.contact else {
            return BearingReport::default();
        };
        let (_, contact) = law.evaluate(
            Vector2::new(q[0], q[1]),
            Vector2::new(qdot[0], qdot[1]),
            speed,
        );
        let friction_torque = contact_friction_torque(law, &contact, speed);
        BearingReport {
            eccentricity: q[0].hypot(q[1]) / law.gap,
            friction_torque,
            power_loss: law.friction_power(&contact),
            contact_force: contact.normal_force,
            ..BearingReport::default()
        }
    }
}
