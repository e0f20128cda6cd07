//! Plain journal bearing in short-bearing (Ocvirk) theory with the Gümbel
//! π-film (half-Sommerfeld) cavitation condition: the film of
//! [`super::short_film`] over the whole circle, and the journal–bushing
//! contact law ([`super::contact`]) from `ε = 1` on.

use nalgebra::Vector2;

use super::contact::{ContactExtent, ContactLaw, ContactReport};
use super::short_film::ShortFilm;
use super::{
    Bearing, BearingError, BearingEval, BearingForce, BearingReport, JournalState, check_state,
};

/// Geometry and lubricant of a plain journal bearing (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlainBearing {
    /// Journal radius `R` (m).
    pub radius: f64,
    /// Bearing length `L` (m).
    pub length: f64,
    /// Radial clearance `C` (m).
    pub clearance: f64,
    /// Dynamic viscosity `μ` (Pa·s).
    pub viscosity: f64,
    /// Journal–bushing contact at `ε ≥ 1`; `None`: the steel default
    /// [`ContactLaw::steel`] for this geometry (gap = clearance).
    pub contact: Option<ContactLaw>,
}

impl PlainBearing {
    fn film(&self) -> ShortFilm {
        ShortFilm {
            radius: self.radius,
            length: self.length,
            clearance: self.clearance,
            viscosity: self.viscosity,
        }
    }

    /// The journal–bushing contact law (gap = the clearance).
    pub fn contact_law(&self) -> ContactLaw {
        self.contact
            .unwrap_or_else(|| ContactLaw::steel(self.clearance, self.radius, self.length))
    }

    /// Force on the journal and its 2×2 Jacobians at `state`, spin `speed` (rad/s).
    pub fn force_and_jacobian(
        &self,
        state: &JournalState,
        speed: f64,
    ) -> Result<BearingForce, BearingError> {
        super::journal_force(self, state, speed)
    }

    /// Eccentricity, attitude angle, film thickness, contact and friction at
    /// `state`, with `force` the bearing force there.
    pub fn journal_report(
        &self,
        state: &JournalState,
        speed: f64,
        force: &Vector2<f64>,
    ) -> BearingReport {
        let eccentricity = state.position.norm() / self.clearance;
        let law = self.contact_law();
        let (_, contact) = law.evaluate(state.position, state.velocity, speed);
        let film_torque = self.film().friction_torque(state, speed, None);
        BearingReport {
            eccentricity,
            attitude_angle: attitude_angle(&state.position, force),
            min_film_thickness: (self.clearance * (1.0 - eccentricity)).max(0.0),
            friction_torque: film_torque + contact_friction_torque(&law, &contact, speed),
            power_loss: film_torque * speed + law.friction_power(&contact),
            contact_force: contact.normal_force,
        }
    }
}

/// Coulomb friction torque `μ N R` of a contact, opposing the spin (signed with
/// `speed`; at standstill the breakaway torque the drive must overcome).
pub(crate) fn contact_friction_torque(
    law: &ContactLaw,
    contact: &ContactReport,
    speed: f64,
) -> f64 {
    let torque = law.friction * contact.normal_force * law.radius;
    if speed < 0.0 { -torque } else { torque }
}

impl Bearing for PlainBearing {
    fn evaluate(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<(), BearingError> {
        check_state(2, q, qdot, speed, out)?;
        let state = JournalState::from_coordinates(q, qdot);
        let part = self.film().force(&state, speed, None)?;
        out.clear();
        out.add_transformed(&part, None);
        let (contact, _) = self
            .contact_law()
            .evaluate(state.position, state.velocity, speed);
        out.add_transformed(&contact, None);
        Ok(())
    }

    fn is_linear(&self) -> bool {
        false
    }

    fn resting_contact(&self, _direction: [f64; 2]) -> Option<(f64, f64)> {
        let law = self.contact_law();
        Some((law.gap, law.stiffness))
    }

    fn contact_extent(&self, q: &[f64], qdot: &[f64], speed: f64) -> Option<ContactExtent> {
        let law = self.contact_law();
        let state = JournalState::from_coordinates(q, qdot);
        let (_, report) = law.evaluate(state.position, state.velocity, speed);
        law.extent(&report)
    }

    fn report(&self, q: &[f64], qdot: &[f64], speed: f64, eval: &BearingEval) -> BearingReport {
        let state = JournalState {
            position: Vector2::new(q[0], q[1]),
            velocity: Vector2::new(qdot[0], qdot[1]),
        };
        self.journal_report(&state, speed, &eval.journal().force)
    }

    /// The film force without its Jacobians ([`ShortFilm::force_only`]).
    fn forces(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<(), BearingError> {
        check_state(2, q, qdot, speed, out)?;
        let state = JournalState::from_coordinates(q, qdot);
        let (film, _) = self.film().force_only(&state, speed, None)?;
        out.force.fill(0.0);
        out.add_force(&film, None);
        let (contact, _) = self
            .contact_law()
            .evaluate(state.position, state.velocity, speed);
        out.add_force(&contact.force, None);
        Ok(())
    }

    /// The film force without its Jacobians is about half the work.
    fn cheap_forces(&self) -> bool {
        true
    }

    /// [`Bearing::forces`], then the report on that force.
    fn output(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<BearingReport, BearingError> {
        self.forces(q, qdot, speed, out)?;
        let state = JournalState::from_coordinates(q, qdot);
        let force = Vector2::new(out.force[0], out.force[1]);
        Ok(self.journal_report(&state, speed, &force))
    }
}

/// Angle from the load line (the direction of `−F`, the load the film carries) to
/// the journal's eccentricity vector, positive in the spin direction, in (−π, π]:
/// with `l = −F`, `atan2(l × e, l · e)`, one `atan2` (0 where either vector is 0).
pub fn attitude_angle(position: &Vector2<f64>, force: &Vector2<f64>) -> f64 {
    if position.norm() == 0.0 || force.norm() == 0.0 {
        return 0.0;
    }
    let load = -force;
    let angle = load.perp(position).atan2(load.dot(position));
    if angle == -std::f64::consts::PI {
        std::f64::consts::PI
    } else {
        angle
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::short_film::{FILM_SATURATION_LIMIT, FILM_SATURATION_START, film_position};
    use nalgebra::Matrix2;
    use std::f64::consts::PI;

    /// The front ends' pass gives the force and report of `evaluate` then
    /// `report`, and the chord iterations' pass (`forces`) that force, bit
    /// for bit, from the centre through saturation into contact, at rest,
    /// squeezing and whirling, and in reverse.
    #[test]
    fn output_is_evaluate_then_report() {
        let b = PlainBearing {
            radius: 0.05,
            length: 0.03,
            clearance: 1e-4,
            viscosity: 0.02,
            contact: None,
        };
        let (mut full, mut single) = (BearingEval::new(2), BearingEval::new(2));
        for speed in [0.0, 40.0, 314.0, -150.0] {
            for eps in [0.0, 0.3, 0.9, 0.99, 1.02] {
                for angle in [-100.0f64, 10.0, 135.0] {
                    for rate in [0.0, 0.01, -0.02] {
                        let (s, c) = angle.to_radians().sin_cos();
                        let q = [eps * 1e-4 * c, eps * 1e-4 * s];
                        let qd = [rate * c - 0.5 * rate * s, rate * s];
                        b.evaluate(&q, &qd, speed, &mut full).unwrap();
                        let report = b.report(&q, &qd, speed, &full);
                        let got = b.output(&q, &qd, speed, &mut single).unwrap();
                        assert_eq!(single.force, full.force);
                        b.forces(&q, &qd, speed, &mut single).unwrap();
                        assert_eq!(single.force, full.force);
                        assert_eq!(got, report);
                    }
                }
            }
        }
    }

    /// The film is continuous through the start of its saturation and finite at
    /// and beyond contact, and its closed-form stiffness there still matches
    /// central differences of the force.
    #[test]
    fn film_saturates_continuously_and_stays_differentiable_into_contact() {
        let b = PlainBearing {
            radius: 0.05,
            length: 0.03,
            clearance: 1e-4,
            viscosity: 0.02,
            contact: None,
        };
        let film = b.film();
        let speed = 314.16;
        let dir = Vector2::new(0.28, -0.96);
        let v = Vector2::new(2e-4, -1e-4);
        let at = |eps: f64, dp: Vector2<f64>| {
            let state = JournalState {
                position: dir * eps * b.clearance + dp,
                velocity: v,
            };
            film.force(&state, speed, None).unwrap()
        };
        let a = FILM_SATURATION_START;
        let below = at(a * (1.0 - 1e-12), Vector2::zeros()).force;
        let above = at(a * (1.0 + 1e-12), Vector2::zeros()).force;
        assert!((below - above).norm() < 1e-8 * below.norm());
        let mut previous = 0.0;
        for eps in [0.98, 1.0, 1.01, 1.5, 10.0] {
            let f = at(eps, Vector2::zeros());
            let size = f.force.norm();
            assert!(size.is_finite() && size >= previous, "ε = {eps}: {size}");
            previous = size;
            // A step 1e-6 C: round-off of forces of ~1e5 N is still 1e-6 below the change.
            let h = 1e-10;
            for j in 0..2 {
                let mut e = Vector2::zeros();
                e[j] = h;
                let fd = -(at(eps, e).force - at(eps, -e).force) / (2.0 * h);
                for i in 0..2 {
                    let k = f.stiffness[(i, j)];
                    assert!(
                        (k - fd[i]).abs() < 1e-5 * f.stiffness.norm(),
                        "ε = {eps}: K[{i}{j}] = {k:e} vs {:e}",
                        fd[i]
                    );
                }
            }
        }
        // The saturated position stays within the limit, and is the identity below ε_a.
        let (p, _) = film_position(dir * 1.2 * b.clearance, b.clearance);
        assert!(p.norm() < FILM_SATURATION_LIMIT * b.clearance);
        let (p, _) = film_position(dir * 100.0 * b.clearance, b.clearance);
        assert!(p.norm() <= FILM_SATURATION_LIMIT * b.clearance * (1.0 + 1e-15));
        let (p, j) = film_position(dir * 0.5 * b.clearance, b.clearance);
        assert_eq!((p, j), (dir * 0.5 * b.clearance, Matrix2::identity()));
    }

    /// Petroff with the film-thickness correction: the full-circle Couette torque is
    /// `2π μ ω R³ L / (C √(1 − ε²))` (Hamrock, Fundamentals of Fluid Film Lubrication, eq. 8.58 without the pressure term).
    #[test]
    fn friction_torque_is_petroff_corrected_for_eccentricity() {
        let b = PlainBearing {
            radius: 0.05,
            length: 0.03,
            clearance: 1e-4,
            viscosity: 0.02,
            contact: None,
        };
        let speed = 314.16;
        for eps in [0.0, 0.3, 0.8, 0.97] {
            let state = JournalState {
                position: Vector2::new(0.6, -0.8) * eps * b.clearance,
                velocity: Vector2::zeros(),
            };
            let f = b.force_and_jacobian(&state, speed).unwrap();
            let rep = b.journal_report(&state, speed, &f.force);
            let petroff = 2.0 * PI * b.viscosity * speed * b.radius.powi(3) * b.length
                / (b.clearance * (1.0 - eps * eps).sqrt());
            assert!(
                (rep.friction_torque - petroff).abs() < 1e-12 * petroff,
                "ε = {eps}"
            );
            assert!((rep.power_loss - petroff * speed).abs() < 1e-9 * petroff * speed);
            // The same shear integrated numerically over the film, and the
            // closed-form film potential over a whole turn split into two arcs.
            let (x, y) = (
                state.position.x / b.clearance,
                state.position.y / b.clearance,
            );
            let n = 20_000;
            let quad: f64 = (0..n)
                .map(|k| {
                    let t = 2.0 * PI * (k as f64 + 0.5) / n as f64;
                    2.0 * PI / n as f64 / (1.0 - x * t.cos() - y * t.sin())
                })
                .sum();
            let split = super::super::film::arc_potential(x, y, 0.3, 2.0).value()
                + super::super::film::arc_potential(x, y, 2.0, 0.3 + 2.0 * PI).value();
            let scale = b.viscosity * speed * b.radius.powi(3) * b.length / b.clearance;
            for phi in [quad, split] {
                assert!(
                    (rep.friction_torque - scale * phi).abs() < 1e-10 * petroff,
                    "ε = {eps}: {} vs {}",
                    rep.friction_torque,
                    scale * phi
                );
            }
        }
    }
}
