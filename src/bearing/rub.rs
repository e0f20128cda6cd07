//! A rub element: a stator surface (seal, labyrinth, generator air gap) at a
//! radial gap around a rotor node, acting only through the contact law of
//! [`super::contact`] — penalty normal force, damping that never pulls, Coulomb
//! friction along the sliding direction `v_s = ṗ·t + Ω R`.
//!
//! ```
//! use rotor_bearing::bearing::contact::ContactLaw;
//! use rotor_bearing::bearing::rub::RubElement;
//! use rotor_bearing::bearing::{Bearing, BearingEval};
//!
//! let rub = RubElement { contact: ContactLaw::steel(2e-4, 0.05, 0.01) };
//! let mut eval = BearingEval::new(2);
//! // Clear of the stator: no force.
//! rub.evaluate(&[1e-4, 0.0], &[0.0, 0.0], 100.0, &mut eval)?;
//! assert_eq!(eval.force[0], 0.0);
//! // Pressed 10 µm into it: pushed back, and dragged against the spin.
//! rub.evaluate(&[0.0, -2.1e-4], &[0.0, 0.0], 100.0, &mut eval)?;
//! assert!(eval.force[1] > 0.0 && eval.force[0] < 0.0);
//! # Ok::<(), rotor_bearing::bearing::BearingError>(())
//! ```

use nalgebra::Vector2;

use super::contact::{ContactExtent, ContactLaw};
use super::plain::contact_friction_torque;
use super::{Bearing, BearingError, BearingEval, BearingReport, check_state};

/// A stator ring around a rotor node: its contact law (gap = radial clearance).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RubElement {
    /// Contact law; `gap` is the radial clearance (m), `radius` the rotor's
    /// surface radius at the rub (m).
    pub contact: ContactLaw,
}

impl Bearing for RubElement {
    fn evaluate(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<(), BearingError> {
        check_state(2, q, qdot, speed, out)?;
        let (force, _) = self.contact.evaluate(
            Vector2::new(q[0], q[1]),
            Vector2::new(qdot[0], qdot[1]),
            speed,
        );
        out.clear();
        out.add_transformed(&force, None);
        Ok(())
    }

    fn is_linear(&self) -> bool {
        false
    }

    fn contact_extent(&self, q: &[f64], qdot: &[f64], speed: f64) -> Option<ContactExtent> {
        let (_, report) = self.contact.evaluate(
            Vector2::new(q[0], q[1]),
            Vector2::new(qdot[0], qdot[1]),
            speed,
        );
        self.contact.extent(&report)
    }

    fn report(&self, q: &[f64], qdot: &[f64], speed: f64, _eval: &BearingEval) -> BearingReport {
        let (_, contact) = self.contact.evaluate(
            Vector2::new(q[0], q[1]),
            Vector2::new(qdot[0], qdot[1]),
            speed,
        );
        let friction_torque = contact_friction_torque(&self.contact, &contact, speed);
        BearingReport {
            eccentricity: q[0].hypot(q[1]) / self.contact.gap,
            friction_torque,
            power_loss: friction_torque * speed,
            contact_force: contact.normal_force,
            ..BearingReport::default()
        }
    }
}
