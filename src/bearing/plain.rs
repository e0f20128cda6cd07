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
}

/// Short-bearing film of radius `R`, length `L`, clearance `C`, viscosity `μ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ShortFilm {
    pub radius: f64,
    pub length: f64,
    pub clearance: f64,
    pub viscosity: f64,
}

/// An arc `[from, to]` of the film (rad) with the sines and cosines of its ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct FilmWindow {
    pub from: f64,
    pub to: f64,
    pub from_sc: (f64, f64),
    pub to_sc: (f64, f64),
}

impl FilmWindow {
    pub(crate) fn new(from: f64, to: f64) -> Self {
        Self {
            from,
            to,
            from_sc: from.sin_cos(),
            to_sc: to.sin_cos(),
        }
    }
}

impl ShortFilm {
    /// Force and Jacobians of the film over the positive-pressure part of the
    /// window (`None`: the whole circle, i.e. the π-film half circle).
    pub(crate) fn force(
        &self,
        state: &JournalState,
        speed: f64,
        window: Option<&FilmWindow>,
    ) -> Result<BearingForce, BearingError> {
        let cl = self.clearance;
        let (x, y) = (state.position.x / cl, state.position.y / cl);
        let eccentricity = x.hypot(y);
        if eccentricity >= 1.0 {
            return Err(BearingError::ClearanceExceeded { eccentricity });
        }
        let (a, b) = source_coefficients(state, speed);
        // The positive-pressure half circle [α, α + π], α = atan2(B, A) + π, has
        // its ends' sines and cosines without trigonometry:
        // (sin α, cos α) = −(B, A)/|(A, B)|. With S ≡ 0 there is no pressure; any
        // half circle gives the one-sided limit of the Jacobian (the force is
        // not differentiable there).
        let r = a.hypot(b);
        let pressure = !source_vanishes(state, speed, r);
        let start = || {
            if pressure {
                b.atan2(a) + PI
            } else {
                y.atan2(x) + 0.5 * PI
            }
        };
        let start_sc = if pressure {
            (-b / r, -a / r)
        } else {
            start().sin_cos()
        };
        let end_sc = (-start_sc.0, -start_sc.1);
        let f = match window {
            None => FilmIntegrals::from_potential(super::film::arc_potential_sc(
                x, y, PI, start_sc, end_sc,
            )),
            Some(w) => {
                let start = start();
                let mut sum = FilmIntegrals::default();
                for k in -2..=1 {
                    let from = start + 2.0 * PI * k as f64;
                    let to = from + PI;
                    let (lo, lo_sc) = if from >= w.from {
                        (from, start_sc)
                    } else {
                        (w.from, w.from_sc)
                    };
                    let (hi, hi_sc) = if to <= w.to {
                        (to, end_sc)
                    } else {
                        (w.to, w.to_sc)
                    };
                    if hi > lo {
                        sum = sum
                            + FilmIntegrals::from_potential(super::film::arc_potential_sc(
                                x,
                                y,
                                hi - lo,
                                lo_sc,
                                hi_sc,
                            ));
                    }
                }
                sum
            }
        };
        let c = self.viscosity * self.radius * self.length.powi(3) / (4.0 * cl.powi(3));
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
        let finite = out
            .force
            .iter()
            .chain(out.stiffness.iter())
            .chain(out.damping.iter())
            .all(|v| v.is_finite());
        if finite {
            Ok(out)
        } else {
            Err(BearingError::ClearanceExceeded { eccentricity })
        }
    }

    /// Couette (Petroff-corrected) friction torque of the film over the window
    /// (`None`: the whole circle),
    /// shear `μωR/h` on the journal surface: `T = (μωR³L/C) ∫ dθ/H` (N·m). The
    /// cavitated film is taken to carry shear too (striated oil).
    pub(crate) fn friction_torque(
        &self,
        state: &JournalState,
        speed: f64,
        window: Option<&FilmWindow>,
    ) -> f64 {
        let (x, y) = (
            state.position.x / self.clearance,
            state.position.y / self.clearance,
        );
        if x.hypot(y) >= 1.0 {
            return f64::INFINITY;
        }
        // Over the whole circle the antiderivative's atan terms cancel:
        // `∫₀^{2π} dθ/H = 2π/√(1 − ε²)`.
        let phi = match window {
            None => 2.0 * PI / (1.0 - x * x - y * y).sqrt(),
            Some(w) => {
                super::film::arc_potential_sc(x, y, w.to - w.from, w.from_sc, w.to_sc).value()
            }
        };
        self.viscosity * speed * self.radius.powi(3) * self.length / self.clearance * phi
    }
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

    /// Force on the journal and its 2×2 Jacobians at `state`, spin `speed` (rad/s).
    pub fn force_and_jacobian(
        &self,
        state: &JournalState,
        speed: f64,
    ) -> Result<BearingForce, BearingError> {
        super::journal_force(self, state, speed)
    }

    /// Eccentricity, attitude angle, film thickness and friction at `state`, with
    /// `force` the film force there.
    pub fn journal_report(
        &self,
        state: &JournalState,
        speed: f64,
        force: &Vector2<f64>,
    ) -> BearingReport {
        let eccentricity = state.position.norm() / self.clearance;
        let friction_torque = self.film().friction_torque(state, speed, None);
        BearingReport {
            eccentricity,
            attitude_angle: attitude_angle(&state.position, force),
            min_film_thickness: self.clearance * (1.0 - eccentricity),
            friction_torque,
            power_loss: friction_torque * speed,
        }
    }
}

/// Start of the positive-pressure half circle `[α, α + π]` (rad), or `None` when
/// `S ≡ 0` (no pressure anywhere: journal centred at rest, or whirling about the
/// centre at exactly ω/2).
pub fn pressure_arc_start(state: &JournalState, speed: f64) -> Option<f64> {
    let (a, b) = source_coefficients(state, speed);
    if source_vanishes(state, speed, a.hypot(b)) {
        None
    } else {
        Some(b.atan2(a) + PI)
    }
}

/// `S ≡ 0` to round-off: `|(A, B)|` (given) below 1e-14 of its terms' size.
fn source_vanishes(state: &JournalState, speed: f64, magnitude: f64) -> bool {
    let scale = (speed * state.position.x).abs()
        + (speed * state.position.y).abs()
        + 2.0 * state.velocity.x.abs()
        + 2.0 * state.velocity.y.abs();
    magnitude <= 1e-14 * scale || magnitude == 0.0
}

/// `A = ωX − 2Ẏ`, `B = ωY + 2Ẋ` (m/s): `S(θ) = A sin θ − B cos θ`.
fn source_coefficients(state: &JournalState, speed: f64) -> (f64, f64) {
    let (p, v) = (state.position, state.velocity);
    (speed * p.x - 2.0 * v.y, speed * p.y + 2.0 * v.x)
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
        Ok(())
    }

    fn is_linear(&self) -> bool {
        false
    }

    fn report(&self, q: &[f64], speed: f64, eval: &BearingEval) -> BearingReport {
        let state = JournalState {
            position: Vector2::new(q[0], q[1]),
            velocity: Vector2::zeros(),
        };
        self.journal_report(&state, speed, &eval.journal().force)
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Petroff with the film-thickness correction: the full-circle Couette torque is
    /// `2π μ ω R³ L / (C √(1 − ε²))` (Hamrock, Fundamentals of Fluid Film Lubrication, eq. 8.58 without the pressure term).
    #[test]
    fn friction_torque_is_petroff_corrected_for_eccentricity() {
        let b = PlainBearing {
            radius: 0.05,
            length: 0.03,
            clearance: 1e-4,
            viscosity: 0.02,
        };
        let speed = 314.16;
        for eps in [0.0, 0.3, 0.8, 0.99] {
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
