//! Plain journal bearing in short-bearing (Ocvirk) theory with the Gümbel π-film
//! (half-Sommerfeld) cavitation condition (paper §3, eqs. 6–18, re-derived).
//!
//! Film `h = C − X cos θ − Y sin θ`; the short-bearing Reynolds equation gives
//! `p = (3μ/h³)(z² − L²/4) S(θ)` with the film "source"
//! `S = ω ∂h/∂θ + 2 ∂h/∂t = A sin θ − B cos θ`, `A = ωX − 2Ẏ`, `B = ωY + 2Ẋ`.
//! Pressure is positive where `S < 0`: exactly the half circle
//! `θ ∈ [α, α + π]`, `α = atan2(B, A) + π`, which moves with the journal's
//! velocity. Integrating over `z` and the arc, the force on the journal is
//!
//! `F = (μRL³/2C³) ∫_α^{α+π} S t / H³ dθ`, `t = (cos θ, sin θ)`, `H = h/C`,
//!
//! i.e. with [`FilmIntegrals`] and `c = μRL³/(4C³)`:
//! `F_x = c (A Φ_xy − B Φ_xx)`, `F_y = c (A Φ_yy − B Φ_xy)`.
//! Because `S = 0` at both arc ends, moving ends add nothing to the derivatives:
//! `C = 2c [[Φ_xx, Φ_xy], [Φ_xy, Φ_yy]]` (symmetric) and
//! `−K_x· = c [ω Φ_xy + (A Φ_xxy − B Φ_xxx)/C, −ω Φ_xx + (A Φ_xyy − B Φ_xxy)/C]`,
//! `−K_y· = c [ω Φ_yy + (A Φ_xyy − B Φ_xxy)/C, −ω Φ_xy + (A Φ_yyy − B Φ_xyy)/C]`.
//! Nothing divides by ω: at ω = 0 this is the pure squeeze film.
//!
//! At and beyond the clearance circle (`ε ≥ 1`) the film has no meaning: the
//! bearing reports [`BearingError::ClearanceExceeded`] instead of a number.

use std::f64::consts::PI;

use nalgebra::{Matrix2, Vector2};

use super::film::FilmIntegrals;
use super::{Bearing, BearingError, BearingForce, BearingReport, JournalState, check_finite};

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
}

impl PlainBearing {
    /// `c = μ R L³ / (4 C³)` (N·s/m).
    fn force_constant(&self) -> f64 {
        self.viscosity * self.radius * self.length.powi(3) / (4.0 * self.clearance.powi(3))
    }

    /// Start of the positive-pressure half circle `[α, α + π]` (rad), or `None` when
    /// `S ≡ 0` (no pressure anywhere: journal centred at rest, or whirling about the
    /// centre at exactly ω/2).
    pub fn pressure_arc_start(&self, state: &JournalState, speed: f64) -> Option<f64> {
        let (a, b) = source_coefficients(state, speed);
        let scale = (speed * state.position.x).abs()
            + (speed * state.position.y).abs()
            + 2.0 * state.velocity.x.abs()
            + 2.0 * state.velocity.y.abs();
        if a.hypot(b) <= 1e-14 * scale || (a == 0.0 && b == 0.0) {
            None
        } else {
            Some(b.atan2(a) + PI)
        }
    }
}

/// `A = ωX − 2Ẏ`, `B = ωY + 2Ẋ` (m/s): `S(θ) = A sin θ − B cos θ`.
fn source_coefficients(state: &JournalState, speed: f64) -> (f64, f64) {
    let (p, v) = (state.position, state.velocity);
    (speed * p.x - 2.0 * v.y, speed * p.y + 2.0 * v.x)
}

impl Bearing for PlainBearing {
    fn force_and_jacobian(
        &self,
        state: &JournalState,
        speed: f64,
    ) -> Result<BearingForce, BearingError> {
        check_finite(state, speed)?;
        let cl = self.clearance;
        let (x, y) = (state.position.x / cl, state.position.y / cl);
        let eccentricity = x.hypot(y);
        if eccentricity >= 1.0 {
            return Err(BearingError::ClearanceExceeded { eccentricity });
        }
        let (a, b) = source_coefficients(state, speed);
        // With S ≡ 0 there is no force; any half circle gives the one-sided limit
        // of the Jacobian (the force is not differentiable there).
        let start = self
            .pressure_arc_start(state, speed)
            .unwrap_or_else(|| y.atan2(x) + 0.5 * PI);
        let f = FilmIntegrals::over_arc(x, y, start, start + PI);
        let c = self.force_constant();
        let force = Vector2::new(c * (a * f.xy - b * f.xx), c * (a * f.yy - b * f.xy));
        let dfx_dx = c * (speed * f.xy + (a * f.xxy - b * f.xxx) / cl);
        let dfx_dy = c * (-speed * f.xx + (a * f.xyy - b * f.xxy) / cl);
        let dfy_dx = c * (speed * f.yy + (a * f.xyy - b * f.xxy) / cl);
        let dfy_dy = c * (-speed * f.xy + (a * f.yyy - b * f.xyy) / cl);
        let out = BearingForce {
            force,
            stiffness: -Matrix2::new(dfx_dx, dfx_dy, dfy_dx, dfy_dy),
            damping: Matrix2::new(f.xx, f.xy, f.xy, f.yy) * (2.0 * c),
        };
        if out
            .force
            .iter()
            .chain(out.stiffness.iter())
            .chain(out.damping.iter())
            .all(|v| v.is_finite())
        {
            Ok(out)
        } else {
            Err(BearingError::ClearanceExceeded { eccentricity })
        }
    }

    fn is_linear(&self) -> bool {
        false
    }

    fn report(&self, state: &JournalState, speed: f64, force: &Vector2<f64>) -> BearingReport {
        let e = state.position / self.clearance;
        let eccentricity = e.norm();
        // Couette shear over the whole circumference (the cavitated film still
        // carries striated oil), Petroff-corrected: T = 2π μ ω R³ L / (C √(1 − ε²)).
        let m = (1.0 - eccentricity * eccentricity).max(0.0);
        let friction_torque = if m > 0.0 {
            2.0 * PI * self.viscosity * speed * self.radius.powi(3) * self.length
                / (self.clearance * m.sqrt())
        } else {
            f64::INFINITY
        };
        BearingReport {
            eccentricity,
            attitude_angle: attitude_angle(&state.position, force),
            min_film_thickness: self.clearance * (1.0 - eccentricity),
            friction_torque,
            power_loss: friction_torque * speed,
        }
    }
}

/// Angle from the load line (the direction of `−F`, the load the film carries) to
/// the journal's eccentricity vector, positive in the spin direction, in (−π, π].
pub fn attitude_angle(position: &Vector2<f64>, force: &Vector2<f64>) -> f64 {
    if position.norm() == 0.0 || force.norm() == 0.0 {
        return 0.0;
    }
    let d = position.y.atan2(position.x) - (-force.y).atan2(-force.x);
    d.sin().atan2(d.cos())
}
