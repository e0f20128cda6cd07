//! Metal-to-metal contact of a journal (or a rotor section) with a stator surface
//! at a radial gap: a penalty normal force and Coulomb friction along the sliding
//! direction, regularized so that force and Jacobians are continuous (Newton–
//! Raphson with closed-form Jacobians, as for the film forces).
//!
//! With the journal centre at `p = (x, y)` relative to the stator centre,
//! `r = |p|`, outward normal `n = p/r`, tangent `t = (−n_y, n_x)` (the spin
//! direction at the contact point) and penetration `δ = r − g` (`g` the radial
//! gap):
//!
//! - **Normal force** (magnitude, acting along `−n` on the journal)
//!   `N = max(0, k s(δ) + c w(δ) δ̇)`, with `δ̇ = n·ṗ` and the C¹ penalty
//!   `s(δ) = δ²/(2δ₀)` for `0 < δ < δ₀`, `δ − δ₀/2` beyond; the damping weight
//!   `w(δ) = min(δ/δ₀, 1)` fades the damping in at first touch, and the `max`
//!   keeps the damping from ever pulling the surfaces together.
//! - **Friction** (Coulomb, along the sliding direction): the journal surface at
//!   the contact point slides over the stator at `v_s = ṗ·t + Ω R` (whirl
//!   velocity plus surface speed), and the friction force on the journal is
//!   `−μ N φ(v_s) t` with the smooth sign `φ(v) = v/√(v² + v_ε²)`.
//! - **Friction torque** on the journal about the shaft axis, opposing the spin:
//!   `T_f = μ N R φ(v_s)`; the breakaway torque at standstill is `μ N R`.
//!
//! The elastic part is conservative (potential `k ∫ s dδ`); the damping and the
//! friction only dissipate (`F·ṗ − T_f Ω ≤ 0` for their part).
//!
//! **Where the law means something.** A penalty stands for the elastic
//! deformation of the two surfaces, so it describes a real contact only while
//! (1) the penetration stays below [`ContactLaw::PENETRATION_LIMIT`] = 10 % of
//! the radial gap — no elastic deformation of steel surfaces reaches a tenth
//! of a bearing clearance or seal gap; a journal deeper "in" its stator is
//! an artefact of the penalty — and (2) the normal force stays below
//! [`ContactLaw::yield_force`], where the peak Hertz pressure of the
//! conformal line contact (journal radius `R` in a bore of radius `R + g`,
//! `R* = R (R + g)/g`, contact length `L = k / ((π/4) E*)` from the law's
//! stiffness) reaches the yield onset of steel, `p_y = 1.67 σ_y` with
//! `σ_y = 250 MPa`: `F_y = π L R* p_y² / E*` (Johnson, *Contact Mechanics*,
//! §4.2 and §6.2). Beyond either the surfaces yield or the journal would be
//! through the stator; the simulator reports it ([`ContactExtent`]).

use nalgebra::{Matrix2, Vector2};

use super::BearingForce;

/// Parameters of the contact law (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLaw {
    /// Radial gap `g` (m) at which the surfaces touch.
    pub gap: f64,
    /// Penalty stiffness `k` (N/m).
    pub stiffness: f64,
    /// Contact damping `c` (N·s/m), active only while in contact.
    pub damping: f64,
    /// Coulomb friction coefficient `μ` (–).
    pub friction: f64,
    /// Radius `R` (m) of the rotating surface at the contact (journal radius).
    pub radius: f64,
    /// Length `δ₀` (m) over which the penalty and the damping fade in.
    pub smoothing: f64,
    /// Sliding velocity `v_ε` (m/s) that regularizes the sign of the friction.
    pub slip_velocity: f64,
}

/// What a contact evaluation reports besides the force.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactReport {
    /// Penetration `δ = r − g` (m); negative while the surfaces are apart.
    pub penetration: f64,
    /// Normal contact force `N ≥ 0` (N).
    pub normal_force: f64,
    /// Sliding velocity `v_s` of the rotating surface over the stator (m/s).
    pub sliding_velocity: f64,
    /// Friction torque on the rotor opposing the spin (N·m).
    pub friction_torque: f64,
}

impl ContactReport {
    /// Apart or just touching: penetration `delta` (m), no force.
    fn penetration(delta: f64) -> Self {
        Self {
            penetration: delta,
            ..Self::default()
        }
    }
}

/// How deep and how hard a contact is, against the limits of the law (see the
/// module docs): the worst over a bearing's contacts.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactExtent {
    /// Penetration `δ` (m).
    pub penetration: f64,
    /// The largest penetration the law stands for, `PENETRATION_LIMIT · g` (m).
    pub penetration_limit: f64,
    /// Normal force `N` (N).
    pub force: f64,
    /// The force where the surfaces start to yield, [`ContactLaw::yield_force`] (N).
    pub force_limit: f64,
}

impl ContactExtent {
    /// The worse of two extents, limit by limit (relative to its limit).
    pub fn worst(self, other: Self) -> Self {
        let deeper =
            other.penetration * self.penetration_limit > self.penetration * other.penetration_limit;
        let harder = other.force * self.force_limit > self.force * other.force_limit;
        Self {
            penetration: if deeper {
                other.penetration
            } else {
                self.penetration
            },
            penetration_limit: if deeper {
                other.penetration_limit
            } else {
                self.penetration_limit
            },
            force: if harder { other.force } else { self.force },
            force_limit: if harder {
                other.force_limit
            } else {
                self.force_limit
            },
        }
    }
}

/// Zero force and Jacobians (no contact).
fn no_force() -> BearingForce {
    BearingForce {
        force: Vector2::zeros(),
        stiffness: Matrix2::zeros(),
        damping: Matrix2::zeros(),
    }
}

/// Why a contact law's parameters are not physical.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ContactError {
    /// A parameter is out of its range.
    #[error("contact {field} = {value} is not valid: {expected}")]
    Parameter {
        field: &'static str,
        value: f64,
        expected: &'static str,
    },
}

impl ContactLaw {
    /// Default smoothing length as a fraction of the gap.
    pub const SMOOTHING_PER_GAP: f64 = 1e-3;
    /// Default regularization velocity of the friction sign (m/s).
    pub const SLIP_VELOCITY: f64 = 1e-2;
    /// Default contact time constant `c/k` (s) of the contact damping.
    pub const DAMPING_TIME: f64 = 1e-5;
    /// Largest penetration, as a fraction of the gap, for which the law stands
    /// for an elastic contact (see the module docs).
    pub const PENETRATION_LIMIT: f64 = 0.1;
    /// Yield onset of the peak Hertz pressure, `1.67 σ_y` with `σ_y = 250 MPa`
    /// (structural steel) (Pa).
    pub const YIELD_PRESSURE: f64 = 1.67 * 250e6;
    /// Plane-strain modulus of steel on steel, `E* = E / (2 (1 − ν²))` with
    /// `E = 210 GPa`, `ν = 0.3` (Pa): the modulus the default stiffness and the
    /// yield force use.
    pub const STEEL_MODULUS: f64 = 2.1e11 / (2.0 * (1.0 - 0.3 * 0.3));

    /// The documented default law of a steel journal of radius `radius` and
    /// length `length` (m) touching a steel bore at radial gap `gap` (m): the
    /// linearized Hertz line-contact stiffness `k = (π/4) E* L` with
    /// `E* = E / (2 (1 − ν²))`, `E = 2.1e11 Pa`, `ν = 0.3`; damping with time
    /// constant [`Self::DAMPING_TIME`]; friction `μ = 0.2` (dry steel on steel /
    /// babbitt); smoothing `δ₀ = 1e-3 g`.
    pub fn steel(gap: f64, radius: f64, length: f64) -> Self {
        let stiffness = std::f64::consts::FRAC_PI_4 * Self::STEEL_MODULUS * length;
        Self {
            gap,
            stiffness,
            damping: Self::DAMPING_TIME * stiffness,
            friction: 0.2,
            radius,
            smoothing: Self::SMOOTHING_PER_GAP * gap,
            slip_velocity: Self::SLIP_VELOCITY,
        }
    }

    /// Check every parameter; the error names the field and the value.
    pub fn validate(&self) -> Result<(), ContactError> {
        let checks: [(&'static str, f64, bool, &'static str); 7] = [
            ("gap", self.gap, self.gap > 0.0, "finite and > 0 (m)"),
            (
                "stiffness",
                self.stiffness,
                self.stiffness > 0.0,
                "finite and > 0 (N/m)",
            ),
            (
                "damping",
                self.damping,
                self.damping >= 0.0,
                "finite and ≥ 0 (N·s/m)",
            ),
            (
                "friction",
                self.friction,
                self.friction >= 0.0,
                "finite and ≥ 0",
            ),
            (
                "radius",
                self.radius,
                self.radius > 0.0,
                "finite and > 0 (m)",
            ),
            (
                "smoothing",
                self.smoothing,
                self.smoothing > 0.0,
                "finite and > 0 (m)",
            ),
            (
                "slip_velocity",
                self.slip_velocity,
                self.slip_velocity > 0.0,
                "finite and > 0 (m/s)",
            ),
        ];
        for (field, value, ok, expected) in checks {
            if !(value.is_finite() && ok) {
                return Err(ContactError::Parameter {
                    field,
                    value,
                    expected,
                });
            }
        }
        Ok(())
    }

    /// Penalty shape `s(δ)` and its slope `s'(δ)` (C¹ at `0` and at `δ₀`).
    fn penalty(&self, delta: f64) -> (f64, f64) {
        let d0 = self.smoothing;
        if delta <= 0.0 {
            (0.0, 0.0)
        } else if delta < d0 {
            (delta * delta / (2.0 * d0), delta / d0)
        } else {
            (delta - 0.5 * d0, 1.0)
        }
    }

    /// Damping weight `w(δ)` and its slope.
    fn damping_weight(&self, delta: f64) -> (f64, f64) {
        let d0 = self.smoothing;
        if delta <= 0.0 {
            (0.0, 0.0)
        } else if delta < d0 {
            (delta / d0, 1.0 / d0)
        } else {
            (1.0, 0.0)
        }
    }

    /// The normal force at which the surfaces start to yield (N):
    /// `F_y = π L R* p_y² / E*` with `R* = R (R + g)/g`, `L = k / ((π/4) E*)`
    /// (see the module docs).
    pub fn yield_force(&self) -> f64 {
        let e = Self::STEEL_MODULUS;
        let length = self.stiffness / (std::f64::consts::FRAC_PI_4 * e);
        let relative = self.radius * (self.radius + self.gap) / self.gap;
        std::f64::consts::PI * length * relative * Self::YIELD_PRESSURE.powi(2) / e
    }

    /// The extent of a contact of penetration `report.penetration` and normal
    /// force `report.normal_force` against this law's limits; `None` while
    /// the surfaces are apart.
    pub fn extent(&self, report: &ContactReport) -> Option<ContactExtent> {
        (report.penetration > 0.0).then(|| ContactExtent {
            penetration: report.penetration,
            penetration_limit: Self::PENETRATION_LIMIT * self.gap,
            force: report.normal_force,
            force_limit: self.yield_force(),
        })
    }

    /// Elastic energy stored at penetration `δ` (J): `k ∫₀^δ s`.
    pub fn potential_energy(&self, delta: f64) -> f64 {
        let d0 = self.smoothing;
        let integral = if delta <= 0.0 {
            0.0
        } else if delta < d0 {
            delta.powi(3) / (6.0 * d0)
        } else {
            d0 * d0 / 6.0 + 0.5 * (delta - 0.5 * d0).powi(2) - d0 * d0 / 8.0
        };
        self.stiffness * integral
    }

    /// Power (W) the contact friction dissipates: `μ N |v_s|`, the Coulomb
    /// force at the sliding velocity of the rotating surface over the stator
    /// (spin `Ω R` plus the whirl's tangential velocity); zero while apart.
    pub fn friction_power(&self, contact: &ContactReport) -> f64 {
        self.friction * contact.normal_force * contact.sliding_velocity.abs()
    }

    /// Contact force on the journal with `K = −∂F/∂p`, `C = −∂F/∂ṗ`, at position
    /// `position` (m) and velocity `velocity` (m/s) relative to the stator
    /// centre and spin `speed` (rad/s): contact with the circle of radius `gap`.
    pub fn evaluate(
        &self,
        position: Vector2<f64>,
        velocity: Vector2<f64>,
        speed: f64,
    ) -> (BearingForce, ContactReport) {
        let r = position.norm();
        if r <= self.gap {
            return (no_force(), ContactReport::penetration(r - self.gap));
        }
        self.evaluate_on(position / r, r - self.gap, 1.0 / r, velocity, speed)
    }

    /// Contact with a straight stator edge of outward normal `normal` (unit) at
    /// distance `gap` from the centre: penetration `δ = n·p − g`, the normal
    /// does not turn with `p` (a pad's leading or trailing edge).
    pub fn evaluate_edge(
        &self,
        normal: Vector2<f64>,
        position: Vector2<f64>,
        velocity: Vector2<f64>,
        speed: f64,
    ) -> (BearingForce, ContactReport) {
        let delta = normal.dot(&position) - self.gap;
        if delta <= 0.0 {
            return (no_force(), ContactReport::penetration(delta));
        }
        self.evaluate_on(normal, delta, 0.0, velocity, speed)
    }

    /// The contact law at penetration `delta > 0` along the outward normal `n`
    /// of a surface of curvature `kappa` (1/m; `1/r` for the circle, 0 for a
    /// flat edge), so that `∂n/∂p = κ t tᵀ` and `∂t/∂p = −κ n tᵀ`.
    fn evaluate_on(
        &self,
        n: Vector2<f64>,
        delta: f64,
        kappa: f64,
        velocity: Vector2<f64>,
        speed: f64,
    ) -> (BearingForce, ContactReport) {
        let zero = no_force();
        let mut report = ContactReport::penetration(delta);
        let t = Vector2::new(-n.y, n.x);
        let delta_rate = n.dot(&velocity);
        let (s, ds) = self.penalty(delta);
        let (w, dw) = self.damping_weight(delta);
        let normal = self.stiffness * s + self.damping * w * delta_rate;
        let v_t = velocity.dot(&t);
        let v_n = delta_rate;
        let sliding = v_t + speed * self.radius;
        report.sliding_velocity = sliding;
        if normal <= 0.0 {
            return (zero, report);
        }
        let eps2 = self.slip_velocity * self.slip_velocity;
        let root = (sliding * sliding + eps2).sqrt();
        let phi = sliding / root;
        let dphi = eps2 / (root * root * root);
        let mu = self.friction;

        // F = −N (n + μ φ t).
        let dir = n + t * (mu * phi);
        let force = -dir * normal;
        // ∂N/∂p = (k s' + c w' δ̇) nᵀ + c w κ (ṗ·t) tᵀ,  ∂N/∂ṗ = c w nᵀ.
        let dn_dp = n.transpose() * (self.stiffness * ds + self.damping * dw * delta_rate)
            + t.transpose() * (self.damping * w * v_t * kappa);
        let dn_dv = n.transpose() * (self.damping * w);
        // ∂n/∂p = κ t tᵀ, ∂t/∂p = −κ n tᵀ, ∂v_s/∂p = −κ (ṗ·n) tᵀ, ∂v_s/∂ṗ = tᵀ.
        let ttt = t * t.transpose();
        let ddir_dp =
            ttt * kappa - n * t.transpose() * (mu * phi * kappa) - ttt * (mu * dphi * v_n * kappa);
        let ddir_dv = ttt * (mu * dphi);
        let df_dp = -(dir * dn_dp) - ddir_dp * normal;
        let df_dv = -(dir * dn_dv) - ddir_dv * normal;

        report.normal_force = normal;
        report.friction_torque = mu * normal * self.radius * phi;
        (
            BearingForce {
                force,
                stiffness: -df_dp,
                damping: -df_dv,
            },
            report,
        )
    }
}

#[cfg(test)]
mod tests;
