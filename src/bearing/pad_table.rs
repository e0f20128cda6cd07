//! Force tables of a tilting pad's finite-length film: the Reynolds film
//! ([`super::reynolds`]) over one pad's arc, solved once per pad geometry on
//! a grid of states and interpolated by a smooth spline whose derivatives
//! are the Jacobians, as [`super::film_table`] does for the plain film.
//!
//! **The reduction.** A pad's film is the finite film at the pad's
//! effective journal state ([`super::TiltingPadBearing`]'s `pad_state`:
//! position `p_e`, velocity `v_e`) over the pad's arc `(α, α + β)`, `α` the
//! leading edge. With `H = 1 − x cos θ − y sin θ` the discrete operator
//! depends on the position `(x, y) = p_e/C` only and the right-hand side is
//! linear in the source `s = (A, B)/C` (`A = ωX_e − 2Ẏ_e`,
//! `B = ωY_e + 2Ẋ_e`, [`super::finite_film`]); the Gümbel clip and the
//! Swift–Stieber complementarity problem are positively homogeneous of
//! degree 1 in `s`. The mesh is laid from the leading edge, so turning
//! position, source and arc together by `−α` turns the discrete problem to
//! the arc `(0, β)` exactly (to round-off), whatever the pivot's angle and
//! offset: every pad of equal arc shares one table, keyed by its arc `β`
//! (and `(2R/L)²`, mesh, cavitation). With `R(α) p = ε (cos φ, sin φ)`
//! in that frame and `R(−α) s = r (cos ψ, sin ψ)`,
//!
//! `L(p, s) = r R(α) G(ε, φ, ψ)`,
//!
//! `G` the load of the unit source in the pad frame. Unlike the full circle
//! there is no rotation left to remove: `φ` stays an axis (`tests/pad_tables.rs`
//! verifies the reduction on direct solves).
//!
//! **The table.** `W = G (1 − ε²)^k`, `k = 2.5` as for the plain film, on
//! nodes equally spaced in `t = −ln(1 − ε)` from 0 to the saturated film's
//! limit, in `φ` and in `ψ` around their circles: [`T_INTERVALS`] ×
//! [`POSITION_ANGLES`] × [`SOURCE_DIRECTIONS`]. Between nodes the
//! tensor-product cubic Hermite interpolant whose nodal slopes `W_t`, `W_φ`,
//! `W_ψ`, `W_tφ`, `W_tψ`, `W_φψ`, `W_tφψ` are those of the interpolating
//! cubic splines along each axis (periodic in `φ` and `ψ`, clamped in `t`),
//! except that a node where `W = 0` next to another such node along an axis
//! (the pad unloaded: its film clipped or cavitated all over) has a zero
//! slope along it, so the interpolant is exactly zero where the film carries
//! nothing: an unloaded pad then feels no spurious moment from the spline's
//! ripple and parks on its pivot rest as with direct solves. Hermite
//! interpolation is C¹ whatever the nodal slopes. The Jacobians are its analytic derivatives:
//!
//! `∂L'/∂x = r (cos φ G_ε − sin φ G_φ/ε)`, `∂L'/∂y = r (sin φ G_ε + cos φ G_φ/ε)`,
//! `∂L'/∂s_x = cos ψ G − sin ψ G_ψ`, `∂L'/∂s_y = sin ψ G + cos ψ G_ψ`,
//!
//! turned back by `R(α)` (`∂L/∂p = R(α) ∂L'/∂p' R(−α)`), with `G_φ/ε →
//! G_εφ` as `ε → 0` (the `ε = 0` plane is constant in `φ`); force, `K` and
//! `C` follow as in [`super::film_table::FilmTable::force_and_jacobian`].
//!
//! **Cost.** Per position the Gümbel table takes one factorization and two
//! solves (the full-film fields of `s = e₁, e₂`; every `ψ` clips
//! `cos ψ P₁ + sin ψ P₂`, [`direction_loads`]); Swift–Stieber one
//! active-set solve per `(position, ψ)`, each started from the previous
//! direction's set. Building is deterministic (one thread, a fixed order).

use std::f64::consts::TAU;

use nalgebra::{Matrix2, Vector2};

use super::film_table::{
    CENTRE, DECAY, clamped_slopes, decay, film_force, film_source, hermite, periodic_slopes,
    rotate, t_limit,
};
use super::finite_film::FiniteFilm;
use super::reynolds::{Cavitation, FilmProblem, ReynoldsError, ReynoldsMesh, direction_loads};
use super::{BearingForce, JournalState};

/// Intervals of the table in `t = −ln(1 − ε)`.
pub const T_INTERVALS: usize = 32;
/// Nodes of the table around the circle of position angles `φ`.
pub const POSITION_ANGLES: usize = 64;
/// Nodes of the table around the circle of source directions `ψ`.
pub const SOURCE_DIRECTIONS: usize = 128;

/// What a pad's table depends on: the slenderness `(2R/L)²`, the pad's
/// arc `β`, the mesh (over the arc) and the cavitation condition (the
/// viscosity, radius and clearance only scale the force; the pivot's angle
/// and offset only turn the frame).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PadGeometry {
    /// `(2R/L)²`, as [`FilmProblem::slenderness`].
    pub slenderness: f64,
    /// The pad's arc `β` (rad).
    pub arc: f64,
    pub mesh: ReynoldsMesh,
    pub cavitation: Cavitation,
}

impl PadGeometry {
    /// The table geometry of a pad of arc `arc` (rad) on `film`.
    pub fn of(film: &FiniteFilm, arc: f64) -> Self {
        Self {
            slenderness: (2.0 * film.radius / film.length).powi(2),
            arc,
            mesh: film.mesh,
            cavitation: film.cavitation,
        }
    }
}

/// Interpolation coefficients of one node: `W` and its scaled slopes, index
/// `p + 2q + 4r` for the derivative orders `(p, q, r)` in `(t, φ, ψ)`, each
/// times `h_t^p h_φ^q h_ψ^r`.
type Node = [[f64; 2]; 8];

/// The tabulated load of a pad (see the module docs).
#[derive(Clone, PartialEq)]
pub struct PadTable {
    geometry: PadGeometry,
    /// Nodes in `t`, `φ`, `ψ`.
    nt: usize,
    np: usize,
    ns: usize,
    t_max: f64,
    /// `W` at node `(i, j, k)` (index `(i np + j) ns + k`).
    values: Vec<[f64; 2]>,
    nodes: Vec<Node>,
}

impl std::fmt::Debug for PadTable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "PadTable({:?}, {} × {} × {} nodes)",
            self.geometry, self.nt, self.np, self.ns
        )
    }
}

impl PadTable {
    /// The node counts `(t, φ, ψ)` of every pad table.
    pub const NODES: (usize, usize, usize) = (T_INTERVALS + 1, POSITION_ANGLES, SOURCE_DIRECTIONS);

    /// Solve the pad's film on every node and fit the spline.
    pub fn build(geometry: PadGeometry) -> Result<Self, ReynoldsError> {
        if !(geometry.arc.is_finite() && geometry.arc > 0.0 && geometry.arc <= TAU) {
            return Err(ReynoldsError::Input {
                what: "pad arc (rad)",
                value: geometry.arc,
                why: "is not in (0, 2π]",
            });
        }
        let (nt, np, ns) = Self::NODES;
        let t_max = t_limit();
        let psis: Vec<f64> = (0..ns).map(|k| k as f64 * TAU / ns as f64).collect();
        let mut values = Vec::with_capacity(nt * np * ns);
        for i in 0..nt {
            let t = t_max * i as f64 / (nt - 1) as f64;
            let eps = if i == 0 { 0.0 } else { -(-t).exp_m1() };
            let g = decay(1.0 - eps * eps);
            let mut centre = None;
            for j in 0..np {
                let phi = j as f64 * TAU / np as f64;
                let (sp, cp) = phi.sin_cos();
                let problem = FilmProblem {
                    x: eps * cp,
                    y: eps * sp,
                    a: 0.0,
                    b: 0.0,
                    slenderness: geometry.slenderness,
                    arc: Some((0.0, geometry.arc)),
                };
                let loads = match (&centre, i) {
                    (Some(row), 0) => Vec::clone(row),
                    _ => direction_loads(&problem, geometry.mesh, geometry.cavitation, &psis)?,
                };
                values.extend(loads.iter().map(|l| [l.x * g, l.y * g]));
                if i == 0 {
                    centre = Some(loads);
                }
            }
        }
        Ok(Self::from_values(geometry, values))
    }

    /// The table of nodal values `W` (`NODES`, index `(i np + j) ns + k`):
    /// the spline slopes fitted to them.
    pub(crate) fn from_values(geometry: PadGeometry, values: Vec<[f64; 2]>) -> Self {
        let (nt, np, ns) = Self::NODES;
        let t_max = t_limit();
        let h = [t_max / (nt - 1) as f64, TAU / np as f64, TAU / ns as f64];
        let dims = [nt, np, ns];
        let along_t = clamped_slopes(nt, h[0]);
        let along_p = periodic_slopes(np, h[1]);
        let along_s = periodic_slopes(ns, h[2]);
        let slope = |field: &[f64], axis: usize| -> Vec<f64> {
            let fit: &dyn Fn(&[f64]) -> Vec<f64> = match axis {
                0 => &along_t,
                1 => &along_p,
                _ => &along_s,
            };
            along_axis(field, dims, axis, fit)
        };
        let mut nodes = vec![[[0.0; 2]; 8]; nt * np * ns];
        for c in 0..2 {
            let mut fields: [Vec<f64>; 8] = Default::default();
            fields[0] = values.iter().map(|v| v[c]).collect();
            // Index p + 2q + 4r: each slope from one with that axis' bit clear.
            for idx in 1..8usize {
                let axis = idx.trailing_zeros() as usize;
                let from = idx & !(1 << axis);
                fields[idx] = slope(&fields[from], axis);
            }
            for (idx, field) in fields.iter().enumerate() {
                let scale = (0..3)
                    .filter(|a| idx & (1 << a) != 0)
                    .map(|a| h[a])
                    .product::<f64>();
                for (node, v) in nodes.iter_mut().zip(field) {
                    node[idx][c] = v * scale;
                }
            }
        }
        Self {
            geometry,
            nt,
            np,
            ns,
            t_max,
            values,
            nodes,
        }
    }

    /// What the table was built for.
    pub fn geometry(&self) -> PadGeometry {
        self.geometry
    }

    /// The nodal values `W` (index `(i np + j) ns + k`).
    pub fn values(&self) -> &[[f64; 2]] {
        &self.values
    }

    /// `W` and its derivatives in `t`, `φ`, `ψ` at `(t, φ, ψ)`.
    fn interpolate(&self, t: f64, phi: f64, psi: f64) -> [Vector2<f64>; 4] {
        let ht = self.t_max / (self.nt - 1) as f64;
        let hp = TAU / self.np as f64;
        let hs = TAU / self.ns as f64;
        let tt = (t / ht).clamp(0.0, (self.nt - 1) as f64);
        let i = (tt.floor() as usize).min(self.nt - 2);
        let u = tt - i as f64;
        let locate = |angle: f64, h: f64, n: usize| {
            let a = angle.rem_euclid(TAU) / h;
            let j = (a.floor() as usize).min(n - 1);
            (j, (a - j as f64).clamp(0.0, 1.0))
        };
        let (j, v) = locate(phi, hp, self.np);
        let (k, w) = locate(psi, hs, self.ns);
        let (bu, du) = hermite(u);
        let (bv, dv) = hermite(v);
        let (bw, dw) = hermite(w);
        // Contracted one axis at a time (ψ, then φ, then t): index
        // `2p + a` of a basis is the order-`p` function of end `a`.
        let mut out = [[0.0f64; 2]; 4];
        for a in 0..2 {
            // Over φ and ψ at this t end: per t order p, the value and its
            // φ and ψ derivatives.
            let mut along = [[[0.0f64; 2]; 3]; 2];
            for b in 0..2 {
                let jb = (j + b) % self.np;
                // Over ψ at this (t, φ) end: per (p, q), value and ψ slope.
                let mut sw = [[[0.0f64; 2]; 2]; 4];
                for c in 0..2 {
                    let kc = (k + c) % self.ns;
                    let node = &self.nodes[((i + a) * self.np + jb) * self.ns + kc];
                    for pq in 0..4 {
                        for r in 0..2 {
                            let coef = node[pq + 4 * r];
                            let (fb, fd) = (bw[2 * r + c], dw[2 * r + c]);
                            for m in 0..2 {
                                sw[pq][0][m] += coef[m] * fb;
                                sw[pq][1][m] += coef[m] * fd;
                            }
                        }
                    }
                }
                for p in 0..2 {
                    for q in 0..2 {
                        let [val, dpsi] = sw[p + 2 * q];
                        let (fb, fd) = (bv[2 * q + b], dv[2 * q + b]);
                        for m in 0..2 {
                            along[p][0][m] += val[m] * fb;
                            along[p][1][m] += val[m] * fd;
                            along[p][2][m] += dpsi[m] * fb;
                        }
                    }
                }
            }
            for (p, [val, dphi, dpsi]) in along.iter().enumerate() {
                let (fb, fd) = (bu[2 * p + a], du[2 * p + a]);
                for m in 0..2 {
                    out[0][m] += val[m] * fb;
                    out[1][m] += val[m] * fd;
                    out[2][m] += dphi[m] * fb;
                    out[3][m] += dpsi[m] * fb;
                }
            }
        }
        [
            Vector2::from(out[0]),
            Vector2::from(out[1]) / ht,
            Vector2::from(out[2]) / hp,
            Vector2::from(out[3]) / hs,
        ]
    }

    /// The load integral `L'` in the pad frame (arc `(0, β)`) at the
    /// position `(x, y)` over the clearance and the source `s` (1/s), with
    /// `∂L'/∂(x, y)` and `∂L'/∂s` (columns per variable): the module docs'
    /// formulas.
    pub fn load(
        &self,
        position: Vector2<f64>,
        source: Vector2<f64>,
    ) -> (Vector2<f64>, Matrix2<f64>, Matrix2<f64>) {
        let eps = position.norm();
        let phi = position.y.atan2(position.x);
        let r = source.norm();
        let psi = source.y.atan2(source.x);
        let t = -(-eps).ln_1p();
        let [w, w_t, w_p, w_s] = self.interpolate(t, phi, psi);
        let e2 = 1.0 - eps * eps;
        let g = decay(e2);
        let h = w / g;
        let h_eps = (w_t / (1.0 - eps) + w * (2.0 * DECAY * eps / e2)) / g;
        let h_psi = w_s / g;
        let q = if eps < CENTRE {
            // G_φ/ε → G_εφ (W_φ = 0 on the ε = 0 plane): taken at ε = CENTRE,
            // continuous across the switch.
            self.interpolate(-(-CENTRE).ln_1p(), phi, psi)[2] / g / CENTRE
        } else {
            w_p / g / eps
        };
        let (sp, cp) = phi.sin_cos();
        let d_pos = Matrix2::from_columns(&[(h_eps * cp - q * sp) * r, (h_eps * sp + q * cp) * r]);
        let (ss, cs) = psi.sin_cos();
        let d_src = Matrix2::from_columns(&[h * cs - h_psi * ss, h * ss + h_psi * cs]);
        (h * r, d_pos, d_src)
    }

    /// Force and Jacobians of the pad film `film` (whose [`PadGeometry`]
    /// with the pad's arc this table was built for) over the arc `arc`
    /// (rad, from the leading edge) at the pad's effective journal `state`
    /// and spin `speed`: what [`FiniteFilm::force_and_jacobian`] answers.
    pub fn force_and_jacobian(
        &self,
        film: &FiniteFilm,
        state: &JournalState,
        speed: f64,
        arc: (f64, f64),
    ) -> Result<BearingForce, ReynoldsError> {
        let at = film_source(film, state, speed)?;
        let back = rotate(arc.0);
        let into = back.transpose();
        let (load, d_pos, d_src) = self.load(into * at.position / film.clearance, into * at.source);
        let turned = (back * load, back * d_pos * into, back * d_src * into);
        Ok(film_force(film, speed, at.saturation, turned))
    }
}

/// The spline slopes `fit` of `field` (dimensions `dims`, row-major) along
/// `axis`, line by line.
fn along_axis(
    field: &[f64],
    dims: [usize; 3],
    axis: usize,
    fit: &dyn Fn(&[f64]) -> Vec<f64>,
) -> Vec<f64> {
    let stride = match axis {
        0 => dims[1] * dims[2],
        1 => dims[2],
        _ => 1,
    };
    let n = dims[axis];
    let mut out = vec![0.0; field.len()];
    for start in 0..field.len() {
        // The first node of each line: its index along `axis` is zero.
        if (start / stride) % n != 0 {
            continue;
        }
        let line: Vec<f64> = (0..n).map(|m| field[start + m * stride]).collect();
        let periodic = axis != 0;
        for (m, s) in fit(&line).into_iter().enumerate() {
            // An unloaded stretch (the film clipped or cavitated over the
            // whole pad: W = 0 exactly) keeps a zero slope, so the
            // interpolant is exactly zero there as the film's load is.
            let neighbour = |d: isize| {
                let k = m as isize + d;
                if periodic {
                    Some(line[k.rem_euclid(n as isize) as usize])
                } else {
                    usize::try_from(k).ok().and_then(|k| line.get(k).copied())
                }
            };
            let unloaded =
                line[m] == 0.0 && (neighbour(-1) == Some(0.0) || neighbour(1) == Some(0.0));
            out[start + m * stride] = if unloaded { 0.0 } else { s };
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The 3-D spline reproduces a function that is cubic in `t` and a
    /// trigonometric polynomial in `φ` and `ψ` with its derivatives (to the
    /// periodic spline's accuracy): the axes, strides and scalings agree.
    #[test]
    fn spline_reproduces_a_smooth_field_and_its_derivatives() {
        let (nt, np, ns) = PadTable::NODES;
        let t_max = t_limit();
        let f = |t: f64, p: f64, s: f64| {
            let a = 0.3 * t * t - 0.05 * t * t * t + 1.0;
            [a * p.sin() * (2.0 * s).cos(), a + p.cos() * s.sin()]
        };
        let mut values = Vec::new();
        for i in 0..nt {
            for j in 0..np {
                for k in 0..ns {
                    let t = t_max * i as f64 / (nt - 1) as f64;
                    values.push(f(t, j as f64 * TAU / np as f64, k as f64 * TAU / ns as f64));
                }
            }
        }
        let geometry = PadGeometry {
            slenderness: 1.0,
            arc: 1.0,
            mesh: ReynoldsMesh::PAD,
            cavitation: Cavitation::Gumbel,
        };
        let table = PadTable::from_values(geometry, values);
        let (t, p, s) = (1.234, 2.345, 4.567);
        let [w, w_t, w_p, w_s] = table.interpolate(t, p, s);
        let d = 1e-6;
        let exact = |t, p, s| Vector2::from(f(t, p, s));
        let diff = |a: Vector2<f64>, b: Vector2<f64>| (a - b) / (2.0 * d);
        assert!((w - exact(t, p, s)).norm() < 1e-4, "{w}");
        assert!((w_t - diff(exact(t + d, p, s), exact(t - d, p, s))).norm() < 1e-3);
        assert!((w_p - diff(exact(t, p + d, s), exact(t, p - d, s))).norm() < 1e-3);
        assert!((w_s - diff(exact(t, p, s + d), exact(t, p, s - d))).norm() < 1e-3);
    }
}
