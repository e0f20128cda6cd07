//! A tilting-pad bearing's report summed over its pads: film friction and
//! contact friction torque, power loss, the contact resultant and the
//! thinnest film.

use nalgebra::Vector2;

use super::contact::{ContactLaw, ContactReport};
use super::plain::{attitude_angle, contact_friction_torque};
use super::{BearingEval, BearingForce, BearingReport};

/// Friction, power loss, contact resultant and thinnest film summed over pads.
#[derive(Debug)]
pub(super) struct PadTally {
    friction_torque: f64,
    power_loss: f64,
    pub(super) min_film: f64,
    contact_resultant: Vector2<f64>,
}

impl Default for PadTally {
    fn default() -> Self {
        Self {
            friction_torque: 0.0,
            power_loss: 0.0,
            min_film: f64::INFINITY,
            contact_resultant: Vector2::zeros(),
        }
    }
}

impl PadTally {
    /// Add a pad's film friction torque and its contact, if any.
    pub(super) fn add(
        &mut self,
        law: &ContactLaw,
        film_torque: f64,
        contact: Option<&(BearingForce, ContactReport)>,
        speed: f64,
    ) {
        match contact {
            Some((contact, report)) => {
                self.friction_torque += film_torque + contact_friction_torque(law, report, speed);
                self.power_loss += film_torque * speed + law.friction_power(report);
                self.contact_resultant += contact.force;
            }
            None => {
                self.friction_torque += film_torque;
                self.power_loss += film_torque * speed;
            }
        }
    }

    /// The bearing's report from the pads' tally and the journal force in
    /// `eval`, the eccentricity over the assembled clearance `clearance`.
    pub(super) fn report(&self, q: &[f64], eval: &BearingEval, clearance: f64) -> BearingReport {
        let position = Vector2::new(q[0], q[1]);
        let force = Vector2::new(eval.force[0], eval.force[1]);
        BearingReport {
            eccentricity: position.norm() / clearance,
            attitude_angle: attitude_angle(&position, &force),
            min_film_thickness: self.min_film.max(0.0),
            friction_torque: self.friction_torque,
            power_loss: self.power_loss,
            contact_force: self.contact_resultant.norm(),
        }
    }
}
