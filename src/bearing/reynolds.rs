//! The finite-length Reynolds equation of an isoviscous, incompressible film
//! over (θ, z), solved by finite differences: the pressure field of a full
//! 360° film or of an arc (a pad), with the Gümbel (half-Sommerfeld) or the
//! Reynolds (Swift–Stieber) cavitation condition.
//!
//! With the film `h = C H`, `H = 1 − x cos θ − y sin θ` (`x = X/C`, `y = Y/C`,
//! the journal's — for a pad the *effective* — position over the clearance,
//! as in [`super::short_film`]) and `ζ = 2z/L`, Reynolds' equation
//! `(1/R²) ∂θ(h³ ∂θ p) + ∂z(h³ ∂z p) = 6μ S`, `S = ω ∂h/∂θ + 2 ∂h/∂t
//! = A sin θ − B cos θ` (the short film's source), is with `p = 6μ (R/C)² P`
//!
//! `∂θ(H³ ∂θ P) + (2R/L)² ∂ζ(H³ ∂ζ P) = (A sin θ − B cos θ)/C`,
//!
//! `P = 0` at the ends `ζ = ±1` and at the edges of an arc, periodic over a
//! full circle. The film is symmetric in `z` (an aligned journal), so only
//! `ζ ∈ [0, 1]` is meshed, with `∂ζ P = 0` at `ζ = 0`.
//!
//! **Mesh** ([`ReynoldsMesh`]): `n` equal intervals around the arc (nodes on
//! the edges of an arc; `n` nodes around a circle) and `m` equal intervals
//! over the half length; the five-point control-volume stencil with `H³` at
//! the midpoints between nodes (half volumes at `ζ = 0`), which keeps the
//! matrix symmetric and an M-matrix. Unknowns are ordered along `ζ` within a
//! column of constant `θ`; the columns of a circle alternate from both ends
//! (0, n−1, 1, n−2, …) so the periodic neighbour is at most two columns
//! away: a banded matrix of half-bandwidth `2m` (`m` for an arc), factored by
//! [`crate::linalg::BandMatrix::lu`].
//!
//! **Cavitation** ([`Cavitation`]): *Gümbel* solves the full film and sets
//! negative pressures to zero afterwards; *Swift–Stieber* solves the
//! complementarity problem `P ≥ 0`, `A P − f ≥ 0`, `Pᵀ(A P − f) = 0` (the
//! discrete Reynolds condition: `P = ∂P/∂n = 0` on the free boundary) by the
//! primal–dual active-set method (Hintermüller, Ito & Kunisch, SIAM J. Optim.
//! 13 (2003) 865–888): nodes with `P − λ/a_kk ≤ 0` are held at zero, the
//! rest solve the equation, until the set repeats — finitely many steps for
//! an M-matrix, each an exact banded solve, so the result is the discrete
//! problem's solution to round-off, not to an iteration tolerance.
//! *Full film* keeps the negative pressures (the full-Sommerfeld film).

use std::f64::consts::TAU;

use nalgebra::Vector2;

use crate::linalg::BandMatrix;

/// The cavitation condition of a [`crate::bearing::finite_film::FiniteFilm`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cavitation {
    /// Half-Sommerfeld: the full film with its negative pressures set to zero.
    Gumbel,
    /// Reynolds (Swift–Stieber): `p ≥ 0` with `∂p/∂n = 0` where the film ruptures.
    SwiftStieber,
    /// No cavitation: the full-Sommerfeld film, negative pressures kept.
    FullFilm,
}

impl Cavitation {
    /// The name used in model files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Cavitation::Gumbel => "gumbel",
            Cavitation::SwiftStieber => "swift_stieber",
            Cavitation::FullFilm => "full_film",
        }
    }
}

/// Intervals of the finite-difference mesh: `circumferential` around the
/// arc (or circle), `axial` over half the film's length.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ReynoldsMesh {
    pub circumferential: usize,
    pub axial: usize,
}

impl ReynoldsMesh {
    /// Smallest and largest intervals around the arc.
    pub const CIRCUMFERENTIAL_RANGE: (usize, usize) = (8, 2048);
    /// Smallest and largest intervals over the half length.
    pub const AXIAL_RANGE: (usize, usize) = (2, 256);

    /// The default for a full 360° film: 144 × 16 (within 0.3 % of the
    /// converged load up to ε = 0.8, `docs/bearings.md`).
    pub const FULL_CIRCLE: ReynoldsMesh = ReynoldsMesh {
        circumferential: 144,
        axial: 16,
    };
    /// The default for a pad: 48 × 16.
    pub const PAD: ReynoldsMesh = ReynoldsMesh {
        circumferential: 48,
        axial: 16,
    };

    /// `Err` naming the count outside [`Self::CIRCUMFERENTIAL_RANGE`] or
    /// [`Self::AXIAL_RANGE`].
    pub fn check(&self) -> Result<(), ReynoldsError> {
        let (c0, c1) = Self::CIRCUMFERENTIAL_RANGE;
        let (a0, a1) = Self::AXIAL_RANGE;
        if !(c0..=c1).contains(&self.circumferential) {
            return Err(ReynoldsError::Mesh {
                what: "circumferential intervals",
                value: self.circumferential,
                range: (c0, c1),
            });
        }
        if !(a0..=a1).contains(&self.axial) {
            return Err(ReynoldsError::Mesh {
                what: "axial intervals",
                value: self.axial,
                range: (a0, a1),
            });
        }
        Ok(())
    }
}

/// Why the Reynolds equation was not solved.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ReynoldsError {
    /// A mesh count outside its range.
    #[error("Reynolds mesh: {what} = {value} is outside {}..={}", range.0, range.1)]
    Mesh {
        what: &'static str,
        value: usize,
        range: (usize, usize),
    },
    /// A geometry or state input that is not finite or out of range.
    #[error("Reynolds film: {what} = {value} {why}")]
    Input {
        what: &'static str,
        value: f64,
        why: &'static str,
    },
    /// The finite-difference matrix is singular (cannot happen for a film
    /// thinner nowhere than zero; reported rather than assumed).
    #[error("Reynolds film: singular finite-difference matrix")]
    Singular,
    /// The active set of the Swift–Stieber condition did not settle.
    #[error("Reynolds film: cavitation set not settled after {0} active-set steps")]
    NotSettled(usize),
}

/// One dimensionless film problem: position `(x, y)` over the clearance
/// (`x² + y² < 1`), the source `(A, B)/C` (1/s), the slenderness
/// `(2R/L)²` and the arc `(from, to)` (rad; `None`: the full circle).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmProblem {
    pub x: f64,
    pub y: f64,
    pub a: f64,
    pub b: f64,
    pub slenderness: f64,
    pub arc: Option<(f64, f64)>,
}

/// The mesh of one problem: its unknown columns (angles) and their order.
#[derive(Clone)]
struct Grid {
    /// Angle of each unknown column (rad).
    theta: Vec<f64>,
    /// Unknowns per column (`m`: `ζ_j = j/m`, `j < m`).
    m: usize,
    d_theta: f64,
    d_zeta: f64,
    periodic: bool,
    /// Position of column `c` in the unknowns' order.
    position: Vec<usize>,
    band: usize,
}

impl Grid {
    fn new(arc: Option<(f64, f64)>, mesh: ReynoldsMesh) -> Self {
        let n = mesh.circumferential;
        let m = mesh.axial;
        let (theta, d_theta, periodic) = match arc {
            None => {
                let d = TAU / n as f64;
                ((0..n).map(|i| i as f64 * d).collect::<Vec<_>>(), d, true)
            }
            Some((from, to)) => {
                let d = (to - from) / n as f64;
                (
                    (1..n).map(|i| from + i as f64 * d).collect::<Vec<_>>(),
                    d,
                    false,
                )
            }
        };
        let columns = theta.len();
        let position = if periodic {
            let half = columns.div_ceil(2);
            (0..columns)
                .map(|i| {
                    if i < half {
                        2 * i
                    } else {
                        2 * (columns - 1 - i) + 1
                    }
                })
                .collect()
        } else {
            (0..columns).collect()
        };
        Self {
            theta,
            m,
            d_theta,
            d_zeta: 1.0 / m as f64,
            periodic,
            position,
            band: if periodic { 2 * m } else { m },
        }
    }

    fn unknowns(&self) -> usize {
        self.theta.len() * self.m
    }

    fn index(&self, column: usize, j: usize) -> usize {
        self.position[column] * self.m + j
    }

    /// The columns left and right of `c` (`None`: an arc's edge, `P = 0`).
    fn neighbours(&self, c: usize) -> (Option<usize>, Option<usize>) {
        let n = self.theta.len();
        if self.periodic {
            (Some((c + n - 1) % n), Some((c + 1) % n))
        } else {
            (c.checked_sub(1), (c + 1 < n).then_some(c + 1))
        }
    }

    /// Quadrature weight of row `j` over `ζ ∈ [0, 1]`: the trapezoidal rule
    /// with its Euler–Maclaurin end correction `−(Δζ²/12) P′(1)`
    /// (`P′(0) = 0` by symmetry), `P′(1)` by the one-sided second-order
    /// difference `(3P_m − 4P_{m−1} + P_{m−2})/(2Δζ)`, `P_m = 0`: exact for the
    /// short film's parabola, fourth order for a smooth `P`.
    fn axial_weight(&self, j: usize) -> f64 {
        let dz = self.d_zeta;
        let mut w = if j == 0 { 0.5 * dz } else { dz };
        if j + 1 == self.m {
            w += dz / 6.0;
        }
        if j + 2 == self.m {
            w -= dz / 24.0;
        }
        w
    }

    /// Half-volume factor of row `j` (the control volume at `ζ = 0` is half)
    /// times the cell area: the right-hand side's weight.
    fn weight(&self, j: usize) -> f64 {
        let half = if j == 0 { 0.5 } else { 1.0 };
        half * self.d_theta * self.d_zeta
    }
}

/// A solved pressure field `P` (1/s; `p = 6μ (R/C)² P`) on its mesh.
pub struct PressureField {
    grid: Grid,
    pressure: Vec<f64>,
    /// Whether negative pressures count as zero (Gümbel).
    clipped: bool,
    /// The nodes held at `P = 0` (Swift–Stieber's final active set).
    held: Option<Vec<bool>>,
}

impl PressureField {
    /// `∫₀¹ dζ ∫ dθ P (cos θ, sin θ)` over the film; the force on the
    /// journal is `−6μ (R/C)² R L` times this. In `ζ` by `Grid::axial_weight`; in `θ`
    /// exact for the piecewise-linear interpolants of `P` and of
    /// `(cos θ, sin θ)` between nodes, with `P` clipped where it changes sign
    /// within an interval (Gümbel): second order, and continuous in the
    /// journal's state as a zero of `P` crosses a node, so the Jacobians by
    /// differences carry no `O(Δθ)` jumps.
    pub fn load_integral(&self) -> Vector2<f64> {
        let g = &self.grid;
        let columns = g.theta.len();
        let unit = |t: f64| {
            let (s, c) = t.sin_cos();
            Vector2::new(c, s)
        };
        // Intervals: (θ0, column or edge, θ1, column or edge).
        let mut intervals: Vec<(f64, Option<usize>, f64, Option<usize>)> = Vec::new();
        if g.periodic {
            for c in 0..columns {
                let next = (c + 1) % columns;
                intervals.push((g.theta[c], Some(c), g.theta[c] + g.d_theta, Some(next)));
            }
        } else {
            let first = g.theta[0] - g.d_theta;
            intervals.push((first, None, g.theta[0], Some(0)));
            for c in 0..columns {
                let next = (c + 1 < columns).then_some(c + 1);
                intervals.push((g.theta[c], Some(c), g.theta[c] + g.d_theta, next));
            }
        }
        let mut sum = Vector2::zeros();
        for j in 0..g.m {
            let w = g.axial_weight(j);
            let at = |c: Option<usize>| c.map_or(0.0, |c| self.pressure[g.index(c, j)]);
            for &(t0, c0, t1, c1) in &intervals {
                let (p0, p1) = (at(c0), at(c1));
                let (u0, u1) = (unit(t0), unit(t1));
                let d = t1 - t0;
                // ∫₀ˢ of the product of two linear functions f, g:
                // s/6 (2 f₀g₀ + f₀g₁ + f₁g₀ + 2 f₁g₁).
                let part = |f0: f64, f1: f64, g0: Vector2<f64>, g1: Vector2<f64>, s: f64| {
                    (g0 * (2.0 * f0 + f1) + g1 * (f0 + 2.0 * f1)) * (s / 6.0)
                };
                let value = if (p0 >= 0.0 && p1 >= 0.0) || (p0 <= 0.0 && p1 <= 0.0) {
                    if p0 + p1 < 0.0 && self.clipped {
                        Vector2::zeros()
                    } else {
                        part(p0, p1, u0, u1, d)
                    }
                } else if self.clipped {
                    // One end positive: integrate up to the zero.
                    let r = p0 / (p0 - p1);
                    let uz = u0 + (u1 - u0) * r;
                    if p0 > 0.0 {
                        part(p0, 0.0, u0, uz, r * d)
                    } else {
                        part(0.0, p1, uz, u1, (1.0 - r) * d)
                    }
                } else {
                    part(p0, p1, u0, u1, d)
                };
                sum += value * w;
            }
        }
        sum
    }

    /// The nodes held at zero pressure by the Swift–Stieber condition (its
    /// final active set; `None` for the other conditions): the start of
    /// [`solve_from`] for a nearby problem.
    pub fn cavitated(&self) -> Option<&[bool]> {
        self.held.as_deref()
    }

    /// The largest nodal pressure `P` (1/s; 0 when none is positive).
    pub fn peak(&self) -> f64 {
        self.pressure.iter().copied().fold(0.0, f64::max)
    }
}

/// The pressure field of `problem` on `mesh` under `cavitation`.
pub fn solve(
    problem: &FilmProblem,
    mesh: ReynoldsMesh,
    cavitation: Cavitation,
) -> Result<PressureField, ReynoldsError> {
    solve_from(problem, mesh, cavitation, None)
}

/// [`solve`], the Swift–Stieber active set started from `start` (the
/// [`PressureField::cavitated`] nodes of a nearby problem on the same
/// mesh and arc) instead of the full film's negative nodes. The discrete
/// problem has one solution (an M-matrix), and the field is the solve with
/// the final active set, so the start changes only how many steps reach
/// it (one or two from a neighbour's set, against several from the full
/// film: the central differences of the Jacobians start from the base
/// state's set); a start that does not settle falls back to the full film.
pub fn solve_from(
    problem: &FilmProblem,
    mesh: ReynoldsMesh,
    cavitation: Cavitation,
    start: Option<&[bool]>,
) -> Result<PressureField, ReynoldsError> {
    check_problem(problem, mesh)?;
    let grid = Grid::new(problem.arc, mesh);
    let (matrix, rhs) = assemble(problem, &grid);
    let start = start.filter(|s| s.len() == rhs.len());
    if cavitation == Cavitation::SwiftStieber {
        let warm = start.map(|held| active_set(&matrix, &rhs, held.to_vec()));
        let (pressure, held) = match warm {
            Some(Ok(solved)) => solved,
            _ => {
                let full = solve_masked(&matrix, &rhs, None)?;
                active_set(&matrix, &rhs, full.iter().map(|&p| p <= 0.0).collect())?
            }
        };
        return Ok(PressureField {
            grid,
            pressure,
            clipped: false,
            held: Some(held),
        });
    }
    let pressure = solve_masked(&matrix, &rhs, None)?;
    Ok(PressureField {
        grid,
        pressure,
        clipped: cavitation == Cavitation::Gumbel,
        held: None,
    })
}

/// The load integrals ([`PressureField::load_integral`]) of `problem`'s
/// film (its `a`, `b` ignored) under the unit sources `(A, B)/C = (cos χ,
/// sin χ)` for each `χ` of `directions`: each the [`solve`] of that source
/// to round-off. The matrix does not depend on the source, so Gümbel and the
/// full film factor it once and combine the two unit fields; Swift–Stieber
/// starts each direction's active set from the previous direction's.
pub fn direction_loads(
    problem: &FilmProblem,
    mesh: ReynoldsMesh,
    cavitation: Cavitation,
    directions: &[f64],
) -> Result<Vec<Vector2<f64>>, ReynoldsError> {
    check_problem(problem, mesh)?;
    let grid = Grid::new(problem.arc, mesh);
    let unit = |a, b| FilmProblem { a, b, ..*problem };
    let (matrix, f_a) = assemble(&unit(1.0, 0.0), &grid);
    let (_, f_b) = assemble(&unit(0.0, 1.0), &grid);
    let field = |pressure, clipped| PressureField {
        grid: grid.clone(),
        pressure,
        clipped,
        held: None,
    };
    let mut loads = Vec::with_capacity(directions.len());
    if cavitation == Cavitation::SwiftStieber {
        let mut start: Option<Vec<bool>> = None;
        for &chi in directions {
            let (s, c) = chi.sin_cos();
            let rhs: Vec<f64> = f_a.iter().zip(&f_b).map(|(a, b)| c * a + s * b).collect();
            let warm = start.take().map(|held| active_set(&matrix, &rhs, held));
            let (pressure, held) = match warm {
                Some(Ok(solved)) => solved,
                _ => {
                    let full = solve_masked(&matrix, &rhs, None)?;
                    active_set(&matrix, &rhs, full.iter().map(|&p| p <= 0.0).collect())?
                }
            };
            loads.push(field(pressure, false).load_integral());
            start = Some(held);
        }
        return Ok(loads);
    }
    let lu = matrix.lu().map_err(|_| ReynoldsError::Singular)?;
    let mut p_a = f_a;
    let mut p_b = f_b;
    lu.solve_in_place(&mut p_a);
    lu.solve_in_place(&mut p_b);
    for &chi in directions {
        let (s, c) = chi.sin_cos();
        let pressure = p_a.iter().zip(&p_b).map(|(a, b)| c * a + s * b).collect();
        loads.push(field(pressure, cavitation == Cavitation::Gumbel).load_integral());
    }
    Ok(loads)
}

/// `Err` for a mesh out of range, a closed film (`ε ≥ 1`), a slenderness
/// that is not positive and finite or an arc outside `(0, 2π]`.
fn check_problem(problem: &FilmProblem, mesh: ReynoldsMesh) -> Result<(), ReynoldsError> {
    mesh.check()?;
    let eps2 = problem.x * problem.x + problem.y * problem.y;
    if eps2.is_nan() || eps2 >= 1.0 {
        return Err(ReynoldsError::Input {
            what: "eccentricity ratio",
            value: eps2.sqrt(),
            why: "is not below 1 (the film closes)",
        });
    }
    if !(problem.slenderness.is_finite() && problem.slenderness > 0.0) {
        return Err(ReynoldsError::Input {
            what: "(2R/L)²",
            value: problem.slenderness,
            why: "is not positive and finite",
        });
    }
    if let Some((from, to)) = problem.arc {
        if !(from.is_finite() && to.is_finite() && to > from && to - from <= TAU) {
            return Err(ReynoldsError::Input {
                what: "arc extent (rad)",
                value: to - from,
                why: "is not in (0, 2π]",
            });
        }
    }
    Ok(())
}

/// The discrete operator `A` (minus the stencil, so that `A` is an M-matrix)
/// and right-hand side `f = −s ΔθΔζ w_j` of `A P = f`.
fn assemble(problem: &FilmProblem, grid: &Grid) -> (BandMatrix<f64>, Vec<f64>) {
    let n = grid.unknowns();
    let mut a = BandMatrix::new(n, grid.band, grid.band);
    let mut f = vec![0.0; n];
    let film = |t: f64| {
        let (s, c) = t.sin_cos();
        1.0 - problem.x * c - problem.y * s
    };
    let (dt, dz) = (grid.d_theta, grid.d_zeta);
    for (c, &t) in grid.theta.iter().enumerate() {
        let h_left = film(t - 0.5 * dt).powi(3);
        let h_right = film(t + 0.5 * dt).powi(3);
        let h_here = film(t).powi(3);
        let (s, co) = t.sin_cos();
        let source = problem.a * s - problem.b * co;
        let (left, right) = grid.neighbours(c);
        for j in 0..grid.m {
            let k = grid.index(c, j);
            let half = if j == 0 { 0.5 } else { 1.0 };
            let g_theta = half * dz / dt;
            a.add(k, k, g_theta * (h_left + h_right));
            if let Some(l) = left {
                a.add(k, grid.index(l, j), -g_theta * h_left);
            }
            if let Some(r) = right {
                a.add(k, grid.index(r, j), -g_theta * h_right);
            }
            let g_zeta = problem.slenderness * dt / dz * h_here;
            if j == 0 {
                a.add(k, k, g_zeta);
            } else {
                a.add(k, k, 2.0 * g_zeta);
                a.add(k, grid.index(c, j - 1), -g_zeta);
            }
            if j + 1 < grid.m {
                a.add(k, grid.index(c, j + 1), -g_zeta);
            }
            f[k] = -source * grid.weight(j);
        }
    }
    (a, f)
}

/// `A P = f` with the rows of `held` (if any) replaced by `P_k = 0`.
fn solve_masked(
    a: &BandMatrix<f64>,
    f: &[f64],
    held: Option<&[bool]>,
) -> Result<Vec<f64>, ReynoldsError> {
    let mut rhs = f.to_vec();
    let lu = match held {
        None => a.lu(),
        Some(held) => {
            let mut m = a.clone();
            let n = a.n();
            for (k, _) in held.iter().enumerate().filter(|(_, h)| **h) {
                let lo = k.saturating_sub(a.kl());
                let hi = (k + a.ku()).min(n - 1);
                for j in lo..=hi {
                    m.set(k, j, 0.0);
                }
                m.set(k, k, 1.0);
                rhs[k] = 0.0;
            }
            m.lu()
        }
    }
    .map_err(|_| ReynoldsError::Singular)?;
    lu.solve_in_place(&mut rhs);
    Ok(rhs)
}

/// Most active-set steps of the Swift–Stieber solve.
const ACTIVE_SET_STEPS: usize = 200;

/// The complementarity problem `P ≥ 0`, `λ = A P − f ≥ 0`, `P λ = 0` by the
/// primal–dual active-set method from the nodes `held` at zero (see the
/// module docs): the field and its final active set.
fn active_set(
    a: &BandMatrix<f64>,
    f: &[f64],
    mut held: Vec<bool>,
) -> Result<(Vec<f64>, Vec<bool>), ReynoldsError> {
    let n = f.len();
    let mut lambda = vec![0.0; n];
    for _ in 0..ACTIVE_SET_STEPS {
        let p = solve_masked(a, f, Some(&held))?;
        a.mul_vec(&p, &mut lambda);
        let mut next = vec![false; n];
        for k in 0..n {
            next[k] = if held[k] {
                lambda[k] - f[k] >= 0.0
            } else {
                p[k] <= 0.0
            };
        }
        if next == held {
            return Ok((p, held));
        }
        held = next;
    }
    Err(ReynoldsError::NotSettled(ACTIVE_SET_STEPS))
}
