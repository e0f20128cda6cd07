//! Force tables of the plain (360°) finite-length film: the Reynolds film
//! ([`super::reynolds`]) solved once per geometry on a grid of states and
//! interpolated by a smooth spline whose derivatives are the Jacobians, so a
//! finite film costs about what the short film costs in the time loop.
//!
//! **The reduction.** With the film `H = 1 − x cos θ − y sin θ` and the source
//! `s = (A, B)/C` ([`super::finite_film`]), the discrete operator depends on
//! `(x, y)` only and the right-hand side is linear in `s`; the Gümbel clip,
//! the Swift–Stieber complementarity problem and the full film are all
//! positively homogeneous of degree 1 in `s`. Rotating position and source
//! together by `φ` rotates the load integral `L` by `φ` (the film is a
//! circle). So with `x + i y = ε e^{iφ}` and `s = r e^{iψ}`,
//!
//! `L(x, y, s) = r R(ψ) H(ε, χ)`, `χ = ψ − φ`,
//!
//! with `H(ε, χ) = R(−χ) L(ε, 0, cos χ, sin χ)` the load in the frame of the
//! source, tabulated. On the mesh the rotation holds only for multiples of
//! `Δθ`; between them the difference is the mesh's own discretization error
//! (`tests/film_tables.rs` measures the reduction against direct solves at
//! arbitrary angles). At `ε = 0`, `H` does not depend on `χ`: that row is the
//! one solve at `χ = 0`.
//!
//! **The table.** `W = H (1 − ε²)^k`, `k = 2.5` (the growth of the squeeze
//! film, `(1 − ε²)^{−5/2}`, taken out), on nodes equally spaced in
//! `t = −ln(1 − ε)` from 0 to the saturated film's limit
//! [`FILM_SATURATION_LIMIT`] and in `χ` around the circle; between nodes the
//! tensor-product cubic Hermite interpolant whose nodal slopes `W_t`, `W_χ`,
//! `W_tχ` are those of the interpolating cubic splines (periodic in `χ`;
//! in `t` clamped to the four-point one-sided slopes at both ends): C¹
//! everywhere. The Jacobians are the analytic derivatives of this
//! interpolant through the chain rule:
//!
//! `∂L/∂x = r R(ψ) (cos φ H_ε + sin φ H_χ/ε)`,
//! `∂L/∂y = r R(ψ) (sin φ H_ε − cos φ H_χ/ε)`,
//! `∂L/∂s_j = R(ψ) (H ŝ_j + (J H + H_χ) ŝ⊥_j)`, `ŝ = (cos ψ, sin ψ)`,
//! `ŝ⊥ = (−sin ψ, cos ψ)`, `J` the quarter turn,
//!
//! with `H_χ/ε → H_εχ` as `ε → 0` (the `ε = 0` row is constant in `χ`).
//! The film force and its `K`, `C` follow as in [`super::finite_film`]:
//! `F = −6μ (R/C)² R L · L`, the source's dependence on the position
//! (`∂s/∂(X, Y) = ω/C`) and velocity (`∂(A, B)/∂(Ẋ, Ẏ) = 2 [[0, −1], [1, 0]]`)
//! included, times the saturation's Jacobian.
//!
//! Building is deterministic (one thread, a fixed order of solves): the same
//! geometry gives the same table to the bit. [`super::film_table_cache`]
//! stores it.

use std::f64::consts::TAU;

use nalgebra::{DMatrix, Matrix2, Vector2};

use super::finite_film::FiniteFilm;
use super::reynolds::{Cavitation, FilmProblem, ReynoldsError, ReynoldsMesh, direction_loads};
use super::short_film::{FILM_SATURATION_LIMIT, film_position};
use super::{BearingForce, JournalState};

/// Intervals of the table in `t = −ln(1 − ε)`.
pub const ECCENTRICITY_INTERVALS: usize = 64;
/// Nodes of the table around the circle of source directions `χ`.
pub const DIRECTIONS: usize = 192;
/// Exponent `k` of the factor `(1 − ε²)^k` taken out of the table.
pub(crate) const DECAY: f64 = 2.5;

/// `(1 − ε²)^k` of `e2 = 1 − ε²`, `k` = [`DECAY`] = 5/2.
pub(crate) fn decay(e2: f64) -> f64 {
    e2 * e2 * e2.sqrt()
}
/// Below this eccentricity ratio `H_χ/ε` is taken as its limit `H_εχ`.
pub(crate) const CENTRE: f64 = 1e-7;

/// What a plain film's table depends on: the slenderness `(2R/L)²` of the
/// Reynolds problem, the mesh and the cavitation condition (the viscosity,
/// radius and clearance only scale the force).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TableGeometry {
    /// `(2R/L)²`, as [`FilmProblem::slenderness`].
    pub slenderness: f64,
    pub mesh: ReynoldsMesh,
    pub cavitation: Cavitation,
}

impl TableGeometry {
    /// The table geometry of a plain film.
    pub fn of(film: &FiniteFilm) -> Self {
        Self {
            slenderness: (2.0 * film.radius / film.length).powi(2),
            mesh: film.mesh,
            cavitation: film.cavitation,
        }
    }
}

/// The tabulated load of a plain film (see the module docs).
#[derive(Clone, PartialEq)]
pub struct FilmTable {
    geometry: TableGeometry,
    /// Nodes in `t` (`ECCENTRICITY_INTERVALS + 1`) and in `χ`.
    nt: usize,
    nc: usize,
    /// `t` at the last node.
    t_max: f64,
    /// `W` at node `(i, j)` (index `i nc + j`), then its slopes.
    values: Vec<[f64; 2]>,
    slope_t: Vec<[f64; 2]>,
    slope_c: Vec<[f64; 2]>,
    slope_tc: Vec<[f64; 2]>,
}

impl std::fmt::Debug for FilmTable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "FilmTable({:?}, {} × {} nodes)",
            self.geometry, self.nt, self.nc
        )
    }
}

/// `t = −ln(1 − ε)` at the table's last node.
pub(crate) fn t_limit() -> f64 {
    -(1.0 - FILM_SATURATION_LIMIT).ln()
}

impl FilmTable {
    /// Solve the film on every node (`(ECCENTRICITY_INTERVALS + 1) ×
    /// DIRECTIONS` sources; Gümbel and the full film one factorization per
    /// eccentricity) and fit the spline.
    pub fn build(geometry: TableGeometry) -> Result<Self, ReynoldsError> {
        let nt = ECCENTRICITY_INTERVALS + 1;
        let nc = DIRECTIONS;
        let t_max = t_limit();
        let directions: Vec<f64> = (0..nc).map(|j| j as f64 * TAU / nc as f64).collect();
        let mut values = Vec::with_capacity(nt * nc);
        for i in 0..nt {
            let t = t_max * i as f64 / (nt - 1) as f64;
            let eps = if i == 0 { 0.0 } else { -(-t).exp_m1() };
            let problem = FilmProblem {
                x: eps,
                y: 0.0,
                a: 0.0,
                b: 0.0,
                slenderness: geometry.slenderness,
                arc: None,
            };
            let g = decay(1.0 - eps * eps);
            if i == 0 {
                let load = direction_loads(&problem, geometry.mesh, geometry.cavitation, &[0.0])?;
                values.extend(std::iter::repeat_n([load[0].x, load[0].y], nc));
                continue;
            }
            let loads = direction_loads(&problem, geometry.mesh, geometry.cavitation, &directions)?;
            for (load, &chi) in loads.iter().zip(&directions) {
                let h = rotate(-chi) * load * g;
                values.push([h.x, h.y]);
            }
        }
        Ok(Self::from_values(geometry, nt, nc, values))
    }

    /// The table of nodal values `W` (`nt × nc`, row-major in `t`): the
    /// spline slopes fitted to them.
    pub(crate) fn from_values(
        geometry: TableGeometry,
        nt: usize,
        nc: usize,
        values: Vec<[f64; 2]>,
    ) -> Self {
        let t_max = t_limit();
        let ht = t_max / (nt - 1) as f64;
        let hc = TAU / nc as f64;
        let along_t = clamped_slopes(nt, ht);
        let along_c = periodic_slopes(nc, hc);
        let mut slope_t = vec![[0.0; 2]; nt * nc];
        let mut slope_c = vec![[0.0; 2]; nt * nc];
        let mut slope_tc = vec![[0.0; 2]; nt * nc];
        for k in 0..2 {
            for j in 0..nc {
                let column: Vec<f64> = (0..nt).map(|i| values[i * nc + j][k]).collect();
                for (i, s) in along_t(&column).into_iter().enumerate() {
                    slope_t[i * nc + j][k] = s;
                }
            }
            for i in 0..nt {
                let row: Vec<f64> = (0..nc).map(|j| values[i * nc + j][k]).collect();
                for (j, s) in along_c(&row).into_iter().enumerate() {
                    slope_c[i * nc + j][k] = s;
                }
                let row: Vec<f64> = (0..nc).map(|j| slope_t[i * nc + j][k]).collect();
                for (j, s) in along_c(&row).into_iter().enumerate() {
                    slope_tc[i * nc + j][k] = s;
                }
            }
        }
        Self {
            geometry,
            nt,
            nc,
            t_max,
            values,
            slope_t,
            slope_c,
            slope_tc,
        }
    }

    /// What the table was built for.
    pub fn geometry(&self) -> TableGeometry {
        self.geometry
    }

    /// Nodes in `t` and in `χ`.
    pub fn nodes(&self) -> (usize, usize) {
        (self.nt, self.nc)
    }

    /// The nodal values `W` (row-major in `t`).
    pub fn values(&self) -> &[[f64; 2]] {
        &self.values
    }

    /// `W`, `W_t`, `W_χ`, `W_tχ` of the interpolant at `(t, χ)`.
    fn interpolate(&self, t: f64, chi: f64) -> [Vector2<f64>; 4] {
        let ht = self.t_max / (self.nt - 1) as f64;
        let hc = TAU / self.nc as f64;
        let tt = (t / ht).clamp(0.0, (self.nt - 1) as f64);
        let i = (tt.floor() as usize).min(self.nt - 2);
        let u = tt - i as f64;
        let cc = chi.rem_euclid(TAU) / hc;
        let j = (cc.floor() as usize).min(self.nc - 1);
        let v = (cc - j as f64).clamp(0.0, 1.0);
        let (bu, du) = hermite(u);
        let (bv, dv) = hermite(v);
        let mut out = [Vector2::zeros(); 4];
        for (a, ia) in [(0, i), (1, i + 1)] {
            for (b, jb) in [(0, j), (1, (j + 1) % self.nc)] {
                let node = ia * self.nc + jb;
                let f = Vector2::from(self.values[node]);
                let ft = Vector2::from(self.slope_t[node]) * ht;
                let fc = Vector2::from(self.slope_c[node]) * hc;
                let ftc = Vector2::from(self.slope_tc[node]) * (ht * hc);
                // Basis functions: value (index a) and slope (2 + a).
                let term = |pu: &[f64; 4], pv: &[f64; 4]| {
                    f * (pu[a] * pv[b])
                        + ft * (pu[2 + a] * pv[b])
                        + fc * (pu[a] * pv[2 + b])
                        + ftc * (pu[2 + a] * pv[2 + b])
                };
                out[0] += term(&bu, &bv);
                out[1] += term(&du, &bv) / ht;
                out[2] += term(&bu, &dv) / hc;
                out[3] += term(&du, &dv) / (ht * hc);
            }
        }
        out
    }

    /// The load integral `L` at the position `(x, y)` over the clearance
    /// and the source `s = (A, B)/C` (1/s), with `∂L/∂(x, y)` and `∂L/∂s`
    /// (columns per variable): the module docs' formulas.
    pub fn load(
        &self,
        position: Vector2<f64>,
        source: Vector2<f64>,
    ) -> (Vector2<f64>, Matrix2<f64>, Matrix2<f64>) {
        let eps = position.norm();
        let phi = position.y.atan2(position.x);
        let r = source.norm();
        let psi = source.y.atan2(source.x);
        let chi = psi - phi;
        let t = -(-eps).ln_1p();
        let [w, w_t, w_c, w_tc] = self.interpolate(t, chi);
        let e2 = 1.0 - eps * eps;
        let g = decay(e2);
        let h = w / g;
        let h_eps = (w_t / (1.0 - eps) + w * (2.0 * DECAY * eps / e2)) / g;
        let h_chi = w_c / g;
        let q = if eps < CENTRE { w_tc / g } else { h_chi / eps };
        let turn = rotate(psi);
        let (sp, cp) = phi.sin_cos();
        let d_pos = Matrix2::from_columns(&[
            turn * (h_eps * cp + q * sp) * r,
            turn * (h_eps * sp - q * cp) * r,
        ]);
        let (ss, cs) = psi.sin_cos();
        let jh = Vector2::new(-h.y, h.x);
        let d_src = Matrix2::from_columns(&[
            turn * (h * cs - (jh + h_chi) * ss),
            turn * (h * ss + (jh + h_chi) * cs),
        ]);
        (turn * h * r, d_pos, d_src)
    }

    /// Force and Jacobians of `film` (whose [`TableGeometry`] this table
    /// was built for) at `state` and spin `speed`: what
    /// [`FiniteFilm::force_and_jacobian`] answers over the full circle.
    pub fn force_and_jacobian(
        &self,
        film: &FiniteFilm,
        state: &JournalState,
        speed: f64,
    ) -> Result<BearingForce, ReynoldsError> {
        let at = film_source(film, state, speed)?;
        let dimensionless = self.load(at.position / film.clearance, at.source);
        Ok(film_force(film, speed, at.saturation, dimensionless))
    }
}

/// A journal state as a film table reads it: the saturated film position
/// (m, [`film_position`]), the saturation's Jacobian and the source
/// `s = (A, B)/C` (1/s, module docs).
pub(crate) struct FilmSource {
    pub position: Vector2<f64>,
    pub saturation: Matrix2<f64>,
    pub source: Vector2<f64>,
}

/// The [`FilmSource`] of `film` at the journal `state` and spin `speed`;
/// an error when the source is not finite.
pub(crate) fn film_source(
    film: &FiniteFilm,
    state: &JournalState,
    speed: f64,
) -> Result<FilmSource, ReynoldsError> {
    let cl = film.clearance;
    let (position, saturation) = film_position(state.position, cl);
    let v = state.velocity;
    let source = Vector2::new(
        speed * position.x - 2.0 * v.y,
        speed * position.y + 2.0 * v.x,
    ) / cl;
    for (what, value) in [
        ("source A/C (1/s)", source.x),
        ("source B/C (1/s)", source.y),
    ] {
        if !value.is_finite() {
            return Err(ReynoldsError::Input {
                what,
                value,
                why: "is not finite",
            });
        }
    }
    Ok(FilmSource {
        position,
        saturation,
        source,
    })
}

/// The film force and its `K`, `C` from the dimensionless load `L` and its
/// derivatives by position and source (module docs): `F = −6μ (R/C)² R L ·
/// L`, `K = (∂L/∂x + ω ∂L/∂s) · scale/C` times the saturation's Jacobian,
/// `C = ∂L/∂s J · 2 scale/C`.
pub(crate) fn film_force(
    film: &FiniteFilm,
    speed: f64,
    saturation: Matrix2<f64>,
    (load, d_pos, d_src): (Vector2<f64>, Matrix2<f64>, Matrix2<f64>),
) -> BearingForce {
    let cl = film.clearance;
    let scale = 6.0 * film.viscosity * (film.radius / cl).powi(2) * film.radius * film.length;
    let quarter = Matrix2::new(0.0, -1.0, 1.0, 0.0);
    BearingForce {
        force: -load * scale,
        stiffness: (d_pos + d_src * speed) * (scale / cl) * saturation,
        damping: d_src * quarter * (2.0 * scale / cl),
    }
}

/// The rotation by `angle` (rad).
pub(crate) fn rotate(angle: f64) -> Matrix2<f64> {
    let (s, c) = angle.sin_cos();
    Matrix2::new(c, -s, s, c)
}

/// Cubic Hermite basis on `[0, 1]` (`h00, h01, h10, h11`) and its derivatives.
pub(crate) fn hermite(u: f64) -> ([f64; 4], [f64; 4]) {
    let u2 = u * u;
    let u3 = u2 * u;
    (
        [
            2.0 * u3 - 3.0 * u2 + 1.0,
            -2.0 * u3 + 3.0 * u2,
            u3 - 2.0 * u2 + u,
            u3 - u2,
        ],
        [
            6.0 * u2 - 6.0 * u,
            -6.0 * u2 + 6.0 * u,
            3.0 * u2 - 4.0 * u + 1.0,
            3.0 * u2 - 2.0 * u,
        ],
    )
}

/// Slopes of the periodic interpolating cubic spline on `n` nodes spaced
/// `h`: `s_{j−1} + 4 s_j + s_{j+1} = 3 (f_{j+1} − f_{j−1})/h`, cyclic.
pub(crate) fn periodic_slopes(n: usize, h: f64) -> impl Fn(&[f64]) -> Vec<f64> {
    let mut m = DMatrix::<f64>::zeros(n, n);
    for j in 0..n {
        m[(j, j)] += 4.0;
        m[(j, (j + 1) % n)] += 1.0;
        m[(j, (j + n - 1) % n)] += 1.0;
    }
    let inverse = m.try_inverse().expect("diagonally dominant");
    move |f: &[f64]| {
        let rhs = nalgebra::DVector::<f64>::from_fn(n, |j, _| {
            3.0 * (f[(j + 1) % n] - f[(j + n - 1) % n]) / h
        });
        (&inverse * rhs).iter().copied().collect()
    }
}

/// Slopes of the interpolating cubic spline on `n ≥ 4` nodes spaced `h`,
/// clamped at both ends to the four-point one-sided slopes
/// `(−11 f₀ + 18 f₁ − 9 f₂ + 2 f₃)/(6h)`.
pub(crate) fn clamped_slopes(n: usize, h: f64) -> impl Fn(&[f64]) -> Vec<f64> {
    let mut m = DMatrix::<f64>::zeros(n, n);
    m[(0, 0)] = 1.0;
    m[(n - 1, n - 1)] = 1.0;
    for i in 1..n - 1 {
        m[(i, i - 1)] = 1.0;
        m[(i, i)] = 4.0;
        m[(i, i + 1)] = 1.0;
    }
    let inverse = m.try_inverse().expect("diagonally dominant");
    move |f: &[f64]| {
        let rhs = nalgebra::DVector::<f64>::from_fn(n, |i, _| {
            if i == 0 {
                (-11.0 * f[0] + 18.0 * f[1] - 9.0 * f[2] + 2.0 * f[3]) / (6.0 * h)
            } else if i == n - 1 {
                (11.0 * f[n - 1] - 18.0 * f[n - 2] + 9.0 * f[n - 3] - 2.0 * f[n - 4]) / (6.0 * h)
            } else {
                3.0 * (f[i + 1] - f[i - 1]) / h
            }
        });
        (&inverse * rhs).iter().copied().collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The spline slopes reproduce a cubic's (clamped) and a trigonometric
    /// polynomial's (periodic) derivatives: the fit is the one the docs state.
    #[test]
    fn spline_slopes_are_exact_on_their_polynomials() {
        let h = 0.1;
        let f: Vec<f64> = (0..12)
            .map(|i| (i as f64 * h).powi(3) - 2.0 * i as f64 * h)
            .collect();
        let s = clamped_slopes(12, h)(&f);
        for (i, s) in s.iter().enumerate() {
            let x = i as f64 * h;
            assert!((s - (3.0 * x * x - 2.0)).abs() < 1e-12, "{i}: {s}");
        }
        let n = 64;
        let hc = TAU / n as f64;
        let f: Vec<f64> = (0..n).map(|j| (j as f64 * hc).sin()).collect();
        let s = periodic_slopes(n, hc)(&f);
        for (j, s) in s.iter().enumerate() {
            assert!((s - (j as f64 * hc).cos()).abs() < 1e-5, "{j}: {s}");
        }
    }
}
