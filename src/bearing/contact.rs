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
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    fn law() -> ContactLaw {
        ContactLaw {
            gap: 1e-4,
            stiffness: 2e9,
            damping: 3e4,
            friction: 0.3,
            radius: 0.05,
            smoothing: 1e-7,
            slip_velocity: 1e-3,
        }
    }

    fn at(angle: f64, radius: f64) -> Vector2<f64> {
        Vector2::new(radius * angle.cos(), radius * angle.sin())
    }

    /// Central differences of the force against the closed-form Jacobians.
    fn check_jacobians(law: &ContactLaw, p: Vector2<f64>, v: Vector2<f64>, speed: f64) {
        let (f, _) = law.evaluate(p, v, speed);
        let scale = f.force.norm().max(1.0);
        let hp = 1e-11;
        let hv = 1e-7;
        for j in 0..2 {
            let mut e = Vector2::zeros();
            e[j] = 1.0;
            let (fp, _) = law.evaluate(p + e * hp, v, speed);
            let (fm, _) = law.evaluate(p - e * hp, v, speed);
            let (gp, _) = law.evaluate(p, v + e * hv, speed);
            let (gm, _) = law.evaluate(p, v - e * hv, speed);
            for i in 0..2 {
                let k_fd = -(fp.force[i] - fm.force[i]) / (2.0 * hp);
                let c_fd = -(gp.force[i] - gm.force[i]) / (2.0 * hv);
                let k = f.stiffness[(i, j)];
                let c = f.damping[(i, j)];
                assert!(
                    (k - k_fd).abs() <= 1e-5 * (scale / law.smoothing) + 1e-6 * k.abs(),
                    "K[{i}{j}] = {k:e}, finite differences {k_fd:e} at p = {p:?}, v = {v:?}"
                );
                assert!(
                    (c - c_fd).abs() <= 1e-5 * (scale / law.slip_velocity) + 1e-6 * c.abs(),
                    "C[{i}{j}] = {c:e}, finite differences {c_fd:e} at p = {p:?}, v = {v:?}"
                );
            }
        }
    }

    #[test]
    fn edge_contact_jacobians_match_finite_differences() {
        let l = law();
        let normal = at(-1.9, 1.0);
        let along = at(-1.9 + FRAC_PI_2, 1.0);
        let cases = [
            (
                normal * (l.gap + 4e-7) + along * 2e-5,
                Vector2::new(1e-3, -2e-3),
                120.0,
            ),
            (
                normal * (l.gap + 5e-8) - along * 3e-5,
                Vector2::new(-3e-3, 1e-3),
                0.0,
            ),
        ];
        for (p, v, speed) in cases {
            let (f, rep) = l.evaluate_edge(normal, p, v, speed);
            assert!(rep.normal_force > 0.0);
            let scale = f.force.norm().max(1.0);
            for j in 0..2 {
                let mut e = Vector2::zeros();
                e[j] = 1.0;
                let d = |dp: f64, dv: f64| l.evaluate_edge(normal, p + e * dp, v + e * dv, speed).0;
                for i in 0..2 {
                    let k_fd = -(d(1e-11, 0.0).force[i] - d(-1e-11, 0.0).force[i]) / 2e-11;
                    let c_fd = -(d(0.0, 1e-7).force[i] - d(0.0, -1e-7).force[i]) / 2e-7;
                    let (k, c) = (f.stiffness[(i, j)], f.damping[(i, j)]);
                    assert!((k - k_fd).abs() <= 1e-5 * scale / l.smoothing + 1e-6 * k.abs());
                    assert!((c - c_fd).abs() <= 1e-5 * scale / l.slip_velocity + 1e-6 * c.abs());
                }
            }
        }
        // Apart from the edge: nothing.
        let (f, rep) = l.evaluate_edge(normal, at(-1.9, 0.9 * l.gap), Vector2::zeros(), 10.0);
        assert_eq!(f.force, Vector2::zeros());
        assert!(rep.penetration < 0.0);
    }

    #[test]
    fn no_force_while_the_surfaces_are_apart() {
        let l = law();
        let (f, rep) = l.evaluate(at(0.7, 0.999 * l.gap), Vector2::new(3.0, -2.0), 300.0);
        assert_eq!(f.force, Vector2::zeros());
        assert_eq!(f.stiffness, Matrix2::zeros());
        assert_eq!(rep.normal_force, 0.0);
        assert!(rep.penetration < 0.0);
    }

    #[test]
    fn static_penetration_gives_the_penalty_force_along_the_normal() {
        let mut l = law();
        l.friction = 0.0;
        let delta = 5e-7; // beyond δ₀: N = k (δ − δ₀/2)
        let angle = -1.2;
        let (f, rep) = l.evaluate(at(angle, l.gap + delta), Vector2::zeros(), 0.0);
        let expected = l.stiffness * (delta - 0.5 * l.smoothing);
        assert!((rep.normal_force - expected).abs() < 1e-9 * expected);
        let n = at(angle, 1.0);
        assert!((f.force + n * expected).norm() < 1e-9 * expected);
        // Radial stiffness k, tangential stiffness N/r (the normal turns with p).
        let t = Vector2::new(-n.y, n.x);
        let k_nn = n.dot(&(f.stiffness * n));
        let k_tt = t.dot(&(f.stiffness * t));
        assert!((k_nn - l.stiffness).abs() < 1e-9 * l.stiffness);
        assert!((k_tt - expected / (l.gap + delta)).abs() < 1e-6 * k_tt);
    }

    #[test]
    fn jacobians_match_finite_differences() {
        let l = law();
        let states = [
            (at(0.3, l.gap + 3e-7), Vector2::new(1e-3, 2e-3), 100.0),
            (at(2.0, l.gap + 5e-8), Vector2::new(-4e-3, 1e-3), 50.0),
            (at(-2.5, l.gap + 2e-6), Vector2::new(2e-4, -3e-4), 0.0),
            (at(4.0, l.gap + 8e-7), Vector2::new(-1e-2, 5e-3), -80.0),
            // Sliding velocity near zero: the regularized sign is steep there.
            (
                at(1.0, l.gap + 4e-7),
                Vector2::new(0.0, 0.0),
                1e-3 / 0.05 * 0.3,
            ),
            // Near-zero sliding while the journal moves along the normal.
            (
                at(1.0, l.gap + 4e-7),
                at(1.0, 2e-3) + at(1.0 + FRAC_PI_2, -0.1 * 0.05 + 2e-4),
                0.1,
            ),
        ];
        for (p, v, speed) in states {
            check_jacobians(&l, p, v, speed);
        }
    }

    #[test]
    fn force_is_continuous_at_first_touch_and_at_the_end_of_smoothing() {
        let l = law();
        let v = Vector2::new(1e-3, 0.0);
        for edge in [l.gap, l.gap + l.smoothing] {
            let (below, _) = l.evaluate(at(0.0, edge * (1.0 - 1e-12)), v, 10.0);
            let (above, _) = l.evaluate(at(0.0, edge * (1.0 + 1e-12)), v, 10.0);
            let jump = (below.force - above.force).norm();
            assert!(
                jump < 1e-3 * (1.0 + above.force.norm()),
                "jump {jump} at r = {edge}"
            );
        }
    }

    #[test]
    fn damping_never_pulls_the_surfaces_together() {
        let l = law();
        let p = at(0.0, l.gap + 2e-7);
        // Receding fast: k s + c δ̇ < 0, the normal force is zero, not a pull.
        let (f, rep) = l.evaluate(p, Vector2::new(-10.0, 0.0), 0.0);
        assert_eq!(rep.normal_force, 0.0);
        assert_eq!(f.force, Vector2::zeros());
        // Approaching: damping adds to the penalty.
        let (_, fast) = l.evaluate(p, Vector2::new(1e-2, 0.0), 0.0);
        let (_, still) = l.evaluate(p, Vector2::zeros(), 0.0);
        assert!(fast.normal_force > still.normal_force);
    }

    #[test]
    fn friction_opposes_sliding_and_gives_the_coulomb_torque() {
        let l = law();
        let angle = 0.4;
        let p = at(angle, l.gap + 1e-6);
        let n = at(angle, 1.0);
        let t = Vector2::new(-n.y, n.x);
        for speed in [300.0, -300.0] {
            let (f, rep) = l.evaluate(p, Vector2::zeros(), speed);
            let tangential = f.force.dot(&t);
            let normal = -f.force.dot(&n);
            assert!((normal - rep.normal_force).abs() < 1e-9 * normal);
            // Fully sliding (|v_s| = 15 m/s ≫ v_ε): |F_t| = μ N, against v_s.
            assert!((tangential.abs() - l.friction * normal).abs() < 1e-8 * normal);
            assert!(tangential * rep.sliding_velocity < 0.0);
            let coulomb = l.friction * normal * l.radius;
            assert!((rep.friction_torque - coulomb * speed.signum()).abs() < 1e-8 * coulomb);
        }
        // The whirl velocity counts: a journal rolling without slip (ṗ·t = −Ω R)
        // feels no friction.
        let speed = 200.0;
        let rolling = t * (-speed * l.radius);
        let (f, rep) = l.evaluate(p, rolling, speed);
        assert!(rep.sliding_velocity.abs() < 1e-12);
        assert!(f.force.dot(&t).abs() < 1e-9 * rep.normal_force);
    }

    #[test]
    fn elastic_part_is_conservative_and_the_rest_dissipates() {
        let mut l = law();
        // Work of the force along a closed path inside the contact zone is zero
        // without damping and friction: the penalty derives from a potential.
        l.damping = 0.0;
        l.friction = 0.0;
        let steps = 20_000;
        let mut work = 0.0;
        let path = |s: f64| {
            let a = 2.0 * std::f64::consts::PI * s;
            at(0.5 * a.sin(), l.gap + 3e-7 + 2.5e-7 * a.cos())
        };
        let mut max_force: f64 = 0.0;
        for i in 0..steps {
            let (s0, s1) = (i as f64 / steps as f64, (i + 1) as f64 / steps as f64);
            let (p0, p1) = (path(s0), path(s1));
            let (f, _) = l.evaluate(0.5 * (p0 + p1), Vector2::zeros(), 0.0);
            work += f.force.dot(&(p1 - p0));
            max_force = max_force.max(f.force.norm());
        }
        assert!(
            work.abs() < 1e-7 * max_force * 5e-7,
            "closed-path work {work}"
        );
        // The potential is the work done against the penalty on a radial path.
        let delta = 4e-7;
        let mut radial_work = 0.0;
        for i in 0..steps {
            let (d0, d1) = (
                delta * i as f64 / steps as f64,
                delta * (i + 1) as f64 / steps as f64,
            );
            let (f, _) = l.evaluate(at(1.0, l.gap + 0.5 * (d0 + d1)), Vector2::zeros(), 0.0);
            radial_work -= f.force.dot(&at(1.0, d1 - d0));
        }
        let v = l.potential_energy(delta);
        assert!((radial_work - v).abs() < 1e-6 * v, "{radial_work} vs {v}");

        // With damping and friction, the power of the dissipative part is ≤ 0.
        let full = law();
        for (p, v, speed) in [
            (at(0.2, full.gap + 4e-7), Vector2::new(2e-3, -1e-3), 150.0),
            (at(2.2, full.gap + 6e-8), Vector2::new(-3e-3, 4e-3), -60.0),
        ] {
            let (f, rep) = full.evaluate(p, v, speed);
            let n = p / p.norm();
            let elastic = -n * (full.stiffness * full.penalty(rep.penetration).0);
            let power = (f.force - elastic).dot(&v) - rep.friction_torque * speed;
            assert!(power <= 1e-12, "dissipative power {power} > 0");
        }
    }

    #[test]
    fn default_steel_law_is_valid_and_bad_parameters_are_named() {
        let l = ContactLaw::steel(1e-4, 0.05, 0.03);
        l.validate().unwrap();
        // (π/4) E* L with E* = 2.1e11 / (2 · 0.91) Pa, L = 0.03 m.
        assert!((l.stiffness - 2.718e9).abs() < 1e-3 * 2.718e9);
        let mut bad = l;
        bad.friction = -0.1;
        let msg = bad.validate().unwrap_err().to_string();
        assert!(msg.contains("friction") && msg.contains("-0.1"), "{msg}");
        bad = l;
        bad.gap = f64::NAN;
        assert!(bad.validate().unwrap_err().to_string().contains("gap"));
    }

    /// The limits of the law: 10 % of the gap, and the force where the peak
    /// Hertz pressure of the conformal line contact reaches 1.67 σ_y. For the
    /// steel law of a 50 mm journal, 30 mm long, in a 0.1 mm clearance:
    /// `R* = 0.05 · 0.0501 / 1e-4 = 25.05 m`, `F_y = π L R* p_y² / E*`
    /// = π · 0.03 · 25.05 · (417.5 MPa)² / 115.4 GPa = 3.57 MN.
    #[test]
    fn the_limits_of_the_law_are_a_tenth_of_the_gap_and_the_yield_force() {
        let l = ContactLaw::steel(1e-4, 0.05, 0.03);
        let e_star = 2.1e11 / 1.82;
        let hand = std::f64::consts::PI * 0.03 * 25.05 * 417.5e6f64.powi(2) / e_star;
        assert!(
            (l.yield_force() - hand).abs() < 1e-12 * hand,
            "{}",
            l.yield_force()
        );
        assert!((hand - 3.57e6).abs() < 0.01e6, "{hand}");
        let apart = l.evaluate(at(0.3, 0.9e-4), Vector2::zeros(), 100.0).1;
        assert_eq!(l.extent(&apart), None);
        let pressed = l.evaluate(at(0.3, 1.2e-4), Vector2::zeros(), 100.0).1;
        let extent = l.extent(&pressed).unwrap();
        assert!((extent.penetration - 0.2e-4).abs() < 1e-15);
        assert_eq!(extent.penetration_limit, 1e-5);
        assert_eq!(
            (extent.force, extent.force_limit),
            (pressed.normal_force, l.yield_force())
        );
        // The worst of two contacts, limit by limit relative to each limit.
        let deep = ContactExtent {
            penetration: 3e-5,
            penetration_limit: 1e-5,
            force: 1.0,
            force_limit: 100.0,
        };
        let hard = ContactExtent {
            penetration: 1e-6,
            penetration_limit: 1e-6,
            force: 90.0,
            force_limit: 10.0,
        };
        let worst = deep.worst(hard);
        assert_eq!((worst.penetration, worst.penetration_limit), (3e-5, 1e-5));
        assert_eq!((worst.force, worst.force_limit), (90.0, 10.0));
        assert_eq!(hard.worst(deep), worst);
    }
}
