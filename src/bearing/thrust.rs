//! The friction torque of a thrust bearing (the axial bearing that carries a
//! vertical unit's weight): film shear when running, boundary friction at
//! standstill.
//!
//! - **Film** (Petroff's law for a flat pad ring, e.g. Khonsari & Booser,
//!   *Applied Tribology*, 2nd ed., §8 on thrust-bearing power loss): a film
//!   of thickness `h` between the pads (inner radius `R_i`, outer `R_o`,
//!   covering a fraction `c` of the ring) and the runner shears at
//!   `τ = μ r ω / h`, so `T_film = c (π μ ω / (2 h)) (R_o⁴ − R_i⁴)`.
//! - **Boundary friction** before the film lifts the pads: `μ_b W R_m` at
//!   rest (`R_m = (R_i + R_o)/2`, `W` the axial load): the breakaway torque,
//!   fading as `exp(−|ω|/ω_l)` with the lift-off speed `ω_l`; none with an
//!   oil lift (high-pressure oil injected at standstill).
//!
//! `T(ω) = T_film(ω) + μ_b W R_m φ(ω) exp(−|ω|/ω_l)`, opposing the spin,
//! with the sign of sliding regularized as the contact law's,
//! `φ(ω) = ω/√(ω² + ω_ε²)` (`ω_ε = 10⁻³ ω_l`), so the torque and its
//! derivative are continuous for Newton; at rest the solver's static
//! friction holds the shaft up to `μ_b W R_m` exactly.
//!
//! ```
//! use rotor_bearing::bearing::thrust::ThrustBearing;
//!
//! let thrust = ThrustBearing {
//!     load: 1.0e6, inner_radius: 0.6, outer_radius: 1.0, coverage: 0.8,
//!     film_thickness: 50e-6, viscosity: 0.03, boundary_friction: 0.15,
//!     lift_off_speed: 0.5, oil_lift: false,
//! };
//! assert!((thrust.breakaway_torque() - 0.15 * 1.0e6 * 0.8).abs() < 1e-6);
//! let (t, _) = thrust.friction_torque(31.4);
//! assert!(t > 0.0); // opposes forward spin
//! ```

/// The speed regularizing the sign of the boundary friction, as a fraction
/// of the lift-off speed.
pub const SIGN_SMOOTHING: f64 = 1e-3;

/// A thrust bearing's friction model (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThrustBearing {
    /// Axial load `W` (N).
    pub load: f64,
    /// Inner radius of the pad ring `R_i` (m).
    pub inner_radius: f64,
    /// Outer radius of the pad ring `R_o` (m).
    pub outer_radius: f64,
    /// Fraction of the ring covered by pads `c` (–).
    pub coverage: f64,
    /// Film thickness `h` at running speed (m).
    pub film_thickness: f64,
    /// Oil dynamic viscosity `μ` (Pa·s).
    pub viscosity: f64,
    /// Boundary friction coefficient `μ_b` (–).
    pub boundary_friction: f64,
    /// Lift-off speed `ω_l` (rad/s).
    pub lift_off_speed: f64,
    /// High-pressure oil lift: no boundary friction.
    pub oil_lift: bool,
}

impl ThrustBearing {
    /// Mean pad radius `R_m` (m).
    pub fn mean_radius(&self) -> f64 {
        0.5 * (self.inner_radius + self.outer_radius)
    }

    /// The torque it holds at rest, `μ_b W R_m` (N·m; 0 with an oil lift).
    pub fn breakaway_torque(&self) -> f64 {
        if self.oil_lift {
            0.0
        } else {
            self.boundary_friction * self.load * self.mean_radius()
        }
    }

    /// Film torque per rad/s, `c (π μ / (2 h)) (R_o⁴ − R_i⁴)` (N·m·s).
    pub fn film_coefficient(&self) -> f64 {
        self.coverage * std::f64::consts::PI * self.viscosity / (2.0 * self.film_thickness)
            * (self.outer_radius.powi(4) - self.inner_radius.powi(4))
    }

    /// Friction torque `T(ω)` (N·m, opposing the spin `ω` rad/s) and
    /// `dT/dω`; `T(0) = 0` (at rest the bearing holds up to
    /// [`Self::breakaway_torque`] instead).
    pub fn friction_torque(&self, speed: f64) -> (f64, f64) {
        let b = self.breakaway_torque();
        let c = self.film_coefficient();
        let wl = self.lift_off_speed;
        let eps = SIGN_SMOOTHING * wl;
        let root = (speed * speed + eps * eps).sqrt();
        let phi = speed / root;
        let dphi = eps * eps / (root * root * root);
        let fade = (-speed.abs() / wl).exp();
        let t = c * speed + b * phi * fade;
        let dt = c + b * fade * (dphi - phi.abs() / wl);
        (t, dt)
    }

    /// Power dissipated at spin `speed` (W).
    pub fn power_loss(&self, speed: f64) -> f64 {
        self.friction_torque(speed).0 * speed
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn thrust() -> ThrustBearing {
        ThrustBearing {
            load: 2.0e6,
            inner_radius: 0.5,
            outer_radius: 0.9,
            coverage: 0.85,
            film_thickness: 60e-6,
            viscosity: 0.04,
            boundary_friction: 0.12,
            lift_off_speed: 0.4,
            oil_lift: false,
        }
    }

    /// At running speed the torque is Petroff's film shear plus a faded
    /// boundary term; its derivative matches central differences; it is odd
    /// in the speed; an oil lift removes the breakaway torque.
    #[test]
    fn friction_torque_follows_its_law() {
        let t = thrust();
        let w = 31.4;
        let (tq, dt) = t.friction_torque(w);
        let film = 0.85 * std::f64::consts::PI * 0.04 / (2.0 * 60e-6)
            * (0.9f64.powi(4) - 0.5f64.powi(4))
            * w;
        let boundary = 0.12 * 2.0e6 * 0.7 * (-w / 0.4).exp();
        assert!((tq - film - boundary).abs() < 1e-9 * tq);
        let h = 1e-6;
        let fd = (t.friction_torque(w + h).0 - t.friction_torque(w - h).0) / (2.0 * h);
        assert!((fd - dt).abs() < 1e-6 * dt.abs());
        assert_eq!(t.friction_torque(-w).0, -tq);
        assert!((t.breakaway_torque() - 0.12 * 2.0e6 * 0.7).abs() < 1e-6);
        let lifted = ThrustBearing {
            oil_lift: true,
            ..t
        };
        assert_eq!(lifted.breakaway_torque(), 0.0);
        assert!((lifted.friction_torque(w).0 - film).abs() < 1e-9 * film);
    }
}
