//! Unbalanced magnetic pull (UMP) of a generator rotor in its stator bore: a
//! radial force toward the narrower air gap, growing as the gap closes — a
//! negative radial stiffness that appears when the field is excited.
//!
//! With the rotor centre at `q = (x, y)` relative to the stator centre, the
//! eccentricity ratio `ε = |q|/g` (`g` the radial air gap) and the air-gap
//! flux density of a simple permeance model `B(θ) = B₀ g/(g − e cos θ)`, the
//! Maxwell stress `B²/(2μ₀)` integrated over the rotor surface (radius `R`,
//! core length `L`) gives the pull on the rotor, along `q`:
//!
//! `F = k e / (1 − ε²)^{3/2}`, `k = π R L B₀² / (μ₀ g)`,
//!
//! (`∫ cos θ/(1 − ε cos θ)² dθ = 2π ε/(1 − ε²)^{3/2}`; the linear term is the
//! standard estimate of the pull stiffness, e.g. Lundström & Aidanpää,
//! *J. Sound Vib.* 301, 2007). The field scales it: `k_eff = k s²` with `s`
//! the excitation (0 with the field off, 1 at nominal flux; the flux and so
//! the pull follow the field current squared below saturation). In vector
//! form `F = k_eff φ(|q|²) q`, `φ(s) = (1 − s/g²)^{−3/2}`, so the Jacobian is
//! `∂F/∂q = k_eff (φ I + 2 φ' q qᵀ)` and `K = −∂F/∂q` is negative. Beyond
//! 95 % of the gap, where the permeance model means nothing, `φ` is
//! continued linearly in `|q|²` (C¹); at the gap the rotor touches the stator
//! through the contact law of a rub ([`super::contact`]).
//!
//! **Dynamic eccentricity.** A generator rotor whose geometric centre lies
//! `e_d` off its axis of rotation (rim ovality, a bent or unround rotor) sees
//! the air gap narrow where that centre points: the gap follows the rotor's
//! geometric centre `q + d(φ)`, `d = e_d (cos(φ + φ_d), sin(φ + φ_d))` turning
//! with the spin angle `φ`. At first order in the motion (`F ≈ k_eff (q + d)`)
//! that is the pull of the rotor's axis plus a force `k_eff d` of constant
//! magnitude `k s² e_d` rotating forward at 1× ([`MagneticPull::rotating_pull`];
//! applied with the loads, [`crate::rotor::Rotor::add_loads_at`]). The
//! neglected terms are `O(ε²)` relative: the slope of the law at `ε` is
//! `1 + 1.5 ε² + …` times `k`.
//!
//! ```
//! use rotor_bearing::bearing::contact::ContactLaw;
//! use rotor_bearing::bearing::magnetic_pull::MagneticPull;
//! use rotor_bearing::bearing::{Bearing, BearingEval};
//!
//! let pull = MagneticPull {
//!     stiffness: 2e8,      // N/m at nominal excitation
//!     gap: 0.02,           // m
//!     excitation: 1.0,
//!     contact: ContactLaw::steel(0.02, 2.0, 0.01),
//!     dynamic_eccentricity: 0.0,
//!     dynamic_phase: 0.0,
//! };
//! let mut eval = BearingEval::new(2);
//! pull.evaluate(&[1e-3, 0.0], &[0.0, 0.0], 15.7, &mut eval)?;
//! let e: f64 = 1e-3 / 0.02;
//! assert!((eval.force[0] - 2e8 * 1e-3 / (1.0 - e * e).powf(1.5)).abs() < 1e-6);
//! assert!(eval.k(0, 0) < 0.0); // a negative stiffness
//! # Ok::<(), rotor_bearing::bearing::BearingError>(())
//! ```

use nalgebra::{Matrix2, Vector2};

use super::contact::ContactLaw;
use super::plain::contact_friction_torque;
use super::{Bearing, BearingError, BearingEval, BearingForce, BearingReport, check_state};

/// Permeability of vacuum μ₀ (H/m).
pub const MU_0: f64 = 1.256_637_062_12e-6;

/// Fraction of the air gap beyond which the law is continued linearly.
pub const SATURATION: f64 = 0.95;

/// The pull stiffness `k = π R L B² / (μ₀ g)` (N/m) of a rotor of radius `R`
/// (m) and core length `L` (m) at mean air-gap flux density `B` (T) and
/// radial air gap `g` (m).
pub fn pull_stiffness(radius: f64, core_length: f64, flux_density: f64, gap: f64) -> f64 {
    std::f64::consts::PI * radius * core_length * flux_density * flux_density / (MU_0 * gap)
}

/// The pull of a generator rotor in its stator, with the stator contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MagneticPull {
    /// Pull stiffness `k` at nominal excitation (N/m, > 0).
    pub stiffness: f64,
    /// Radial air gap `g` (m).
    pub gap: f64,
    /// Field excitation `s` (0–1): the pull goes with `s²`.
    pub excitation: f64,
    /// Contact of rotor and stator at the air gap.
    pub contact: ContactLaw,
    /// Dynamic eccentricity `e_d` (m): the rotor's geometric centre off its
    /// axis of rotation, turning with it (0: none).
    pub dynamic_eccentricity: f64,
    /// Its direction `φ_d` (rad) at spin angle 0.
    pub dynamic_phase: f64,
}

impl MagneticPull {
    /// `φ(s)` and `φ'(s)` of the law at `s = |q|²` (m²), continued linearly
    /// beyond [`SATURATION`] of the gap.
    fn factor(&self, s: f64) -> (f64, f64) {
        let g2 = self.gap * self.gap;
        let law = |s: f64| {
            let u = 1.0 - s / g2;
            (u.powf(-1.5), 1.5 / g2 * u.powf(-2.5))
        };
        let s_max = SATURATION * SATURATION * g2;
        if s <= s_max {
            law(s)
        } else {
            let (phi, dphi) = law(s_max);
            (phi + dphi * (s - s_max), dphi)
        }
    }

    /// The rotating pull `k s² e_d (cos(φ + φ_d), sin(φ + φ_d))` (N, on the
    /// rotor) of a dynamic eccentricity `e_d` (m) at spin angle `φ` (rad).
    pub fn rotating_pull(&self, dynamic_eccentricity: f64, spin_angle: f64) -> [f64; 2] {
        let a = self.stiffness * self.excitation * self.excitation * dynamic_eccentricity;
        let (s, c) = (spin_angle + self.dynamic_phase).sin_cos();
        [a * c, a * s]
    }

    /// The pull alone (no contact) at `q` (m): force on the rotor and its
    /// Jacobians.
    pub fn pull(&self, q: Vector2<f64>) -> BearingForce {
        let k = self.stiffness * self.excitation * self.excitation;
        let (phi, dphi) = self.factor(q.norm_squared());
        let jacobian = k * (Matrix2::identity() * phi + 2.0 * dphi * q * q.transpose());
        BearingForce {
            force: k * phi * q,
            stiffness: -jacobian,
            damping: Matrix2::zeros(),
        }
    }
}

impl Bearing for MagneticPull {
    fn evaluate(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<(), BearingError> {
        check_state(2, q, qdot, speed, out)?;
        let (p, v) = (Vector2::new(q[0], q[1]), Vector2::new(qdot[0], qdot[1]));
        out.clear();
        out.add_transformed(&self.pull(p), None);
        let (contact, _) = self.contact.evaluate(p, v, speed);
        out.add_transformed(&contact, None);
        Ok(())
    }

    fn is_linear(&self) -> bool {
        false
    }

    fn report(&self, q: &[f64], qdot: &[f64], speed: f64, _eval: &BearingEval) -> BearingReport {
        let (_, contact) = self.contact.evaluate(
            Vector2::new(q[0], q[1]),
            Vector2::new(qdot[0], qdot[1]),
            speed,
        );
        let friction_torque = contact_friction_torque(&self.contact, &contact, speed);
        BearingReport {
            eccentricity: q[0].hypot(q[1]) / self.gap,
            friction_torque,
            power_loss: self.contact.friction_power(&contact),
            contact_force: contact.normal_force,
            ..BearingReport::default()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pull() -> MagneticPull {
        MagneticPull {
            stiffness: 3e8,
            gap: 0.015,
            excitation: 0.8,
            contact: ContactLaw::steel(0.015, 2.2, 0.01),
            dynamic_eccentricity: 1e-3,
            dynamic_phase: 0.5,
        }
    }

    /// At five eccentricities in any direction the force is the stated law
    /// `k s² e/(1 − ε²)^{3/2}` along `q` to 1e-12, and its Jacobian equals
    /// central differences of the force (1e-7); past 95 % of the gap the
    /// continuation is C¹.
    #[test]
    fn pull_follows_its_law_and_its_jacobian() {
        let p = pull();
        let k = 3e8 * 0.64;
        for (eps, angle) in [
            (0.01, 0.3),
            (0.2, 1.7),
            (0.45, -2.2),
            (0.7, 3.0),
            (0.9, -0.4),
        ] {
            let e = eps * p.gap;
            let q = Vector2::new(e * f64::cos(angle), e * f64::sin(angle));
            let f = p.pull(q);
            let want = k * e / (1.0 - eps * eps).powf(1.5);
            assert!((f.force.norm() / want - 1.0).abs() < 1e-12, "ε = {eps}");
            assert!(
                (f.force.normalize() - q.normalize()).norm() < 1e-12,
                "along q"
            );
            let h = 1e-7 * p.gap;
            for j in 0..2 {
                let mut dq = Vector2::zeros();
                dq[j] = h;
                let fd = (p.pull(q + dq).force - p.pull(q - dq).force) / (2.0 * h);
                for i in 0..2 {
                    let exact = -f.stiffness[(i, j)];
                    assert!(
                        (fd[i] - exact).abs() < 1e-7 * f.stiffness.norm(),
                        "ε = {eps}: ∂F{i}/∂q{j}"
                    );
                }
            }
        }
        // C¹ across the continuation.
        let at = |eps: f64| p.pull(Vector2::new(eps * p.gap, 0.0));
        let (a, b) = (at(SATURATION - 1e-9), at(SATURATION + 1e-9));
        assert!((a.force - b.force).norm() < 1e-6 * a.force.norm());
        assert!((a.stiffness - b.stiffness).norm() < 1e-6 * a.stiffness.norm());
        assert!(at(1.2).force.norm().is_finite());
    }

    /// The rotating pull is the law's first-order term at the geometric
    /// centre: `k s² d` with `d = e_d (cos(φ + φ_d), sin(φ + φ_d))`, i.e. the
    /// difference `F(q + d) − F(q)` of the law about the centred rotor to
    /// `O(ε²)` (`1.5 ε²` relative: checked at ε = 1e-5 to 1e-9), turning
    /// forward once per revolution.
    #[test]
    fn rotating_pull_is_the_pull_of_the_geometric_centre() {
        let p = pull();
        let k = 3e8 * 0.64;
        for spin in [0.0, 1.0, 2.5, -4.0] {
            let e = 1e-5 * p.gap;
            let [fx, fy] = p.rotating_pull(e, spin);
            assert!((fx.hypot(fy) / (k * e) - 1.0).abs() < 1e-14);
            let angle = fy.atan2(fx);
            let want = (spin + 0.5).sin().atan2((spin + 0.5).cos());
            assert!((angle - want).abs() < 1e-12, "turns with the spin");
            let d = Vector2::new(fx, fy) / k;
            let diff = p.pull(d).force;
            assert!((diff - Vector2::new(fx, fy)).norm() < 1e-9 * k * e);
        }
    }

    /// The linear estimate from the machine's data.
    #[test]
    fn stiffness_from_geometry_and_flux() {
        // R = 2.2 m, L = 1.6 m, B = 0.85 T, g = 15 mm.
        let k = pull_stiffness(2.2, 1.6, 0.85, 0.015);
        let want =
            std::f64::consts::PI * 2.2 * 1.6 * 0.85 * 0.85 / (4e-7 * std::f64::consts::PI * 0.015);
        assert!((k / want - 1.0).abs() < 1e-9, "{k} against {want}");
    }
}
