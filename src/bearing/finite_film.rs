//! The finite-length film on a journal: force and Jacobians of the
//! Reynolds pressure field ([`super::reynolds`]) of a full 360° film or of an
//! arc, at a journal state — the question the short film
//! ([`super::short_film::ShortFilm::force`]) answers, with the same film
//! `h = C − X cos θ − Y sin θ`, source `S = A sin θ − B cos θ`
//! (`A = ωX − 2Ẏ`, `B = ωY + 2Ẋ`) and the same saturated film position
//! near contact ([`super::short_film::film_position`]).
//!
//! The force on the journal is `F = −∫∫ p (cos θ, sin θ) R dθ dz
//! = −6μ (R/C)² R L ∫₀¹ dζ ∫ P (cos θ, sin θ) dθ`. Its Jacobians are central
//! differences of re-solved films: `K = −∂F/∂(X, Y)` with steps of
//! `10⁻⁵ C` in the (saturated) film position, times the saturation's
//! Jacobian as in the short film, and `C = −∂F/∂(Ẋ,Ẏ)` with steps of
//! `10⁻⁵ (|ω| C + 2|v|)` (at least `10⁻⁵ C/s`). Each solve is exact for the
//! discrete problem (banded LU, a finite active set), so the differences
//! carry round-off of about `10⁻¹²/10⁻⁵` of the force, far below the
//! discretization error.

use nalgebra::{Matrix2, Vector2};

use super::reynolds::{Cavitation, FilmProblem, ReynoldsError, ReynoldsMesh, solve_from};
use super::short_film::film_position;
use super::{BearingForce, JournalState};

/// A finite-length film of radius `R`, length `L`, clearance `C` and
/// viscosity `μ` (SI) on a mesh, with a cavitation condition.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FiniteFilm {
    /// Journal radius `R` (m).
    pub radius: f64,
    /// Film length `L` (m).
    pub length: f64,
    /// Radial clearance `C` (m) (a pad's machined clearance).
    pub clearance: f64,
    /// Dynamic viscosity `μ` (Pa·s).
    pub viscosity: f64,
    /// The finite-difference mesh.
    pub mesh: ReynoldsMesh,
    /// The cavitation condition.
    pub cavitation: Cavitation,
}

/// Relative step of the central differences (see the module docs).
const STEP: f64 = 1e-5;

impl FiniteFilm {
    /// `Err` for a geometry that is not positive and finite or a mesh out of range.
    pub fn check(&self) -> Result<(), ReynoldsError> {
        for (what, value) in [
            ("radius (m)", self.radius),
            ("length (m)", self.length),
            ("clearance (m)", self.clearance),
            ("viscosity (Pa·s)", self.viscosity),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(ReynoldsError::Input {
                    what,
                    value,
                    why: "is not positive and finite",
                });
            }
        }
        self.mesh.check()
    }

    /// Force on the journal (N) at `state`, spin `speed` (rad/s), over the
    /// arc `(from, to)` (rad; `None`: the full circle).
    pub fn force(
        &self,
        state: &JournalState,
        speed: f64,
        arc: Option<(f64, f64)>,
    ) -> Result<Vector2<f64>, ReynoldsError> {
        let (position, _) = film_position(state.position, self.clearance);
        Ok(self.force_at(position, state.velocity, speed, arc, None)?.0)
    }

    /// Force and Jacobians `K = −∂F/∂(X, Y)`, `C = −∂F/∂(Ẋ, Ẏ)` (see the
    /// module docs), the signs of [`BearingForce`].
    pub fn force_and_jacobian(
        &self,
        state: &JournalState,
        speed: f64,
        arc: Option<(f64, f64)>,
    ) -> Result<BearingForce, ReynoldsError> {
        let (position, saturation) = film_position(state.position, self.clearance);
        let v = state.velocity;
        let (force, held) = self.force_at(position, v, speed, arc, None)?;
        let start = held.as_deref();
        let dp = STEP * self.clearance;
        let dv = STEP * (speed.abs() * self.clearance + 2.0 * v.norm()).max(self.clearance);
        let mut stiffness = Matrix2::zeros();
        let mut damping = Matrix2::zeros();
        for j in 0..2 {
            let mut e = Vector2::zeros();
            e[j] = 1.0;
            let plus = self.force_at(position + e * dp, v, speed, arc, start)?.0;
            let minus = self.force_at(position - e * dp, v, speed, arc, start)?.0;
            stiffness.set_column(j, &(-(plus - minus) / (2.0 * dp)));
            let plus = self.force_at(position, v + e * dv, speed, arc, start)?.0;
            let minus = self.force_at(position, v - e * dv, speed, arc, start)?.0;
            damping.set_column(j, &(-(plus - minus) / (2.0 * dv)));
        }
        Ok(BearingForce {
            force,
            stiffness: stiffness * saturation,
            damping,
        })
    }

    /// `F` at the film position `position` (m) and velocity (m/s), with
    /// the Swift–Stieber active set it ended on (`start`: a neighbouring
    /// state's, [`solve_from`]).
    fn force_at(
        &self,
        position: Vector2<f64>,
        velocity: Vector2<f64>,
        speed: f64,
        arc: Option<(f64, f64)>,
        start: Option<&[bool]>,
    ) -> Result<(Vector2<f64>, Option<Vec<bool>>), ReynoldsError> {
        self.check()?;
        let cl = self.clearance;
        let a = (speed * position.x - 2.0 * velocity.y) / cl;
        let b = (speed * position.y + 2.0 * velocity.x) / cl;
        for (what, value) in [("source A/C (1/s)", a), ("source B/C (1/s)", b)] {
            if !value.is_finite() {
                return Err(ReynoldsError::Input {
                    what,
                    value,
                    why: "is not finite",
                });
            }
        }
        if a == 0.0 && b == 0.0 {
            return Ok((Vector2::zeros(), None));
        }
        let problem = FilmProblem {
            x: position.x / cl,
            y: position.y / cl,
            a,
            b,
            slenderness: (2.0 * self.radius / self.length).powi(2),
            arc,
        };
        let field = solve_from(&problem, self.mesh, self.cavitation, start)?;
        let scale = 6.0 * self.viscosity * (self.radius / cl).powi(2) * self.radius * self.length;
        Ok((
            -field.load_integral() * scale,
            field.cavitated().map(<[bool]>::to_vec),
        ))
    }
}
