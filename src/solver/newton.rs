//! Newton–Raphson on the bearing nonlinearity within a Newmark step: the
//! condensed Newton on the journal and pad coordinates (exact factorization)
//! and the modified Newton on the full residual (stale factorization), both
//! closing with a Schur complement on the bearing DOFs ([`super::schur`]; see
//! [`crate::solver`]).

use crate::bearing::Bearing;
use crate::linalg::LinalgError;

use super::dense::{lu_in_place, lu_solve};
use super::error::SolverError;
use super::factor_work::Factor;
use super::line_search::{Trial, condensed_residual, retreat};
use super::newmark::{Displacement, newmark_rates};
use super::pad_balance::{self, TiltRate};
use super::simulator::Simulator;

/// The condensed Newton has converged when its last relative increment
/// `δ_k` is within the tolerance, or (undamped) within ten times it while the
/// contraction `ρ = δ_k / δ_{k−1}` bounds what the iterations would still
/// add, `ρ/(1 − ρ) δ_k`, by the tolerance: near the solution Newton converges
/// quadratically, so an increment just above the tolerance leaves an iterate
/// whose error is of the order of the next increment, `ρ δ_k` (round-off on the
/// three-guide-bearing unit: the third increment it saves is 1e-16 of the
/// journal motion). `previous`: `δ_{k−1}`, infinite at the first iteration,
/// where there is no contraction to judge by.
fn converged(increment: f64, previous: f64, tol: f64, damped: bool) -> bool {
    if increment <= tol {
        return true;
    }
    let contraction = increment / previous;
    !damped
        && previous.is_finite()
        && increment <= 10.0 * tol
        && contraction < 1.0
        && contraction / (1.0 - contraction) * increment <= tol
}

/// Error a step may leave after an increment on the quadratic estimate, as
/// a fraction of the tolerance ([`quadratic_converged`]).
const QUADRATIC_ERROR: f64 = 1e-2;

/// With every pad settled on its own balance ([`super::pad_balance`]) the
/// condensed Newton is exact Newton on the journals and converges
/// quadratically, `e_{k+1} ≈ M e_k²`: with `M ≈ δ_k/δ_{k−1}²` the error the
/// increment `δ_k` leaves is about `δ_k³/δ_{k−1}²`, and the step ends when
/// that is within [`QUADRATIC_ERROR`] of the tolerance, on an increment that
/// contracted by [`NEWTON_CONTRACTION`] at least. The unit on brackets' steps
/// go 5.8e-4, 5.0e-7, 5.2e-13 (the estimate after the second: 3.7e-13).
fn quadratic_converged(increment: f64, previous: f64, tol: f64) -> bool {
    previous.is_finite()
        && increment <= NEWTON_CONTRACTION * previous
        && increment.powi(3) / (previous * previous) <= QUADRATIC_ERROR * tol
}

/// Largest relative increment after which the condensed Newton keeps its
/// Jacobians for the next iteration (a chord iteration). The three-guide
/// unit's first increments are 1e-5 to 3e-5 of its scale at equal 5 ms
/// steps, but 1e-4 to 1e-3 at the same 5 ms under accuracy-controlled steps
/// (the step-size changes of its start leave its higher modes ringing): at
/// 1e-4 nearly all of those steps took a second full iteration, at 1e-3 a
/// chord one; a chord that does not contract is not applied
/// ([`CHORD_CONTRACTION`]).
const CHORD_INCREMENT: f64 = 1e-3;

/// Contraction `δ_k / δ_{k−1}` a chord iteration must reach to be applied;
/// one that contracts less is not taken, and the step goes on with full
/// Newton.
const CHORD_CONTRACTION: f64 = 0.1;

/// Contraction `δ_k / δ_{k−1}` of the iteration before a chord iteration.
const NEWTON_CONTRACTION: f64 = 1e-2;

/// Steps after a refused chord iteration ([`CHORD_CONTRACTION`]) in which
/// the condensed Newton tries none: a refused chord iteration costs a force
/// pass and moves nothing, and where one is refused the next steps' are too
/// (the whirling vertical rotor on its plain bearing at ε ≈ 0.95: its first
/// increments are about 5e-4 of the clearance, within [`CHORD_INCREMENT`],
/// but its chord iterations contract by 0.25 to 0.35, every step). Newton
/// iterations a step, 10 s at the FMU's defaults (`tests/newton_iterations.rs`),
/// with a pause of 0 (none) / 1 / 8 / 16 / 32 / 64 / 256 steps: that rotor
/// 4.45 / 4.27 / 3.98 / 3.89 / 3.82 / 3.79 / 3.71, the vertical rotor on
/// unpreloaded pads 3.81 / 3.81 / 3.72 / 3.65 / 3.74 / 3.92 / 3.90, the hydro
/// unit on plain bearings 2.77 / 2.76 / 2.73 / 2.70 / 2.65 / 2.64 / 2.61; a
/// unit whose chord iterations are never refused is unchanged, bit for bit.
/// The pause goes with the state (`SimState::chord_pause`), so a restored
/// state continues bit for bit.
pub(super) const CHORD_PAUSE: u32 = 16;

/// Whether the condensed Newton's next iteration keeps this one's Jacobians
/// (evaluates the bearing forces alone and solves on the condensation and
/// factors it has). After an increment `δ_k` within [`CHORD_INCREMENT`] of
/// the displacement scale, the Jacobians at the iterate differ from those at
/// the solution by `O(δ_k)`, so a chord iteration contracts by `O(δ_k)`
/// (the hydro unit's first increments are about 1e-6 of its clearance: its
/// second iteration lands where Newton's does to about 1e-6 of the
/// tolerance). That holds where Newton converges quadratically, so the
/// increment must also have contracted by [`NEWTON_CONTRACTION`] on the one
/// before (`previous`: `δ_{k−1}`, infinite at the first iteration); pads
/// near a double root of their moment balance, whose increments halve, stay
/// on full Newton. `allowed`: no chord iteration of this step has contracted
/// by less; the damped retry never keeps them (nor, in the caller, a rotor
/// with a site whose forces are not cheaper than its evaluation).
fn keeps_jacobians(increment: f64, previous: f64, allowed: bool, damped: bool) -> bool {
    allowed && !damped && increment <= CHORD_INCREMENT && increment <= NEWTON_CONTRACTION * previous
}

/// Error a chord iterate may leave, as a fraction of the tolerance.
const CHORD_ERROR: f64 = 1e-2;

/// A chord iteration's iterate is taken when, besides [`converged`], the
/// error it leaves is within [`CHORD_ERROR`] of the tolerance `tol`: a chord
/// iteration contracts by about `ρ = 2 δ_k/δ_{k−1}` (twice the ratio of
/// Newton's increments after a fresh Jacobian; the ratio itself after a
/// chord iteration), so the error left is about `ρ δ_k`.
fn chord_converged(increment: f64, previous: f64, tol: f64) -> bool {
    2.0 * increment / previous * increment <= CHORD_ERROR * tol
}

/// Error a step that ends on its iterate may leave, as a fraction of the
/// tolerance.
const ITERATE_ERROR: f64 = 1e-3;

/// A step ends on the iterate of its first chord iteration, not applying the
/// chord increment `δ` (relative, `increment`), when `δ` is within
/// [`ITERATE_ERROR`] of the tolerance `tol`: the chord contracts by at least
/// [`CHORD_CONTRACTION`] there, so the iterate's error is about `δ`. The
/// iterate's force pass is then the one the outputs take. On the hydro unit at 5 ms
/// in steady running `δ` is 3e-4 to 1e-3 of the tolerance (99.5 % of the
/// steps end on their iterate); the bound is a tenth of [`CHORD_ERROR`]
/// because skipping `δ` errs the same way step after step (at 1e-2 the
/// plain-bearing unit's journals drifted by 1.8e-8 of their range from a run
/// at a tolerance of 1e-12; at 1e-3, 6.0e-10, as with `δ` applied).
fn ends_on_iterate(increment: f64, tol: f64) -> bool {
    increment <= ITERATE_ERROR * tol
}

/// Contraction `δ_k/δ_{k−1}` of the condensed Newton above which it is slow:
/// the step goes on with every pad settled on its own balance
/// ([`super::pad_balance`]), and so do the steps after it.
const SLOW: f64 = 0.3;

/// Fraction of the force that moves a journal by the Newton tolerance
/// within which a settled pad's balance must be ([`super::pad_balance`]).
const FORCE_FRACTION: f64 = 1e-9;

/// Film evaluations of a pad within which it counts as balanced already by
/// the condensed Newton's own increments: a step whose pads never took more
/// lets the next step go back to the plain iteration.
const BALANCED_EVALUATIONS: usize = 2;

impl Simulator {
    /// Newton–Raphson on the bearing coordinates alone, with an exact
    /// factorization of `A = K + a1 (C + Ω G) + a0 M`. The rotor equations of
    /// the step are `A u = b + E F` with the Newmark effective load
    /// `b = f + M (a0 u_n + a2 u̇_n + ü_n) + (C + Ω G)(a1 u_n + u̇_n)`, so
    /// `u = u_lin + A⁻¹ E F` with `u_lin = A⁻¹ b`: the journal coordinates
    /// `j = Eᵀ u` and the pad tilts `p` solve the small system
    /// `j − j_lin − G F_j(j, p) = 0`, `F_p(j, p) = 0` (`G = Eᵀ A⁻¹ E`).
    ///
    /// Full Newton on it: pads are condensed bearing by bearing,
    /// `K_c = K_jj − K_jp K_pp⁻¹ K_pj` (all `K` here are `K + a1 C`), leaving
    /// `(I + G K_c) δj = j_lin − j + G (F_j + K_jp K_pp⁻¹ (−F_p))`. The step stops
    /// when the correction is below the tolerance, or near it while the
    /// iterations contract fast enough that the rest is ([`converged`]); the journal forces there are
    /// taken to first order, `F_j − K_c δj + K_jp K_pp⁻¹ (−F_p)`, which satisfies
    /// the condensed equation exactly. A step costs two banded mat-vecs and two
    /// banded solves whatever the number of iterations.
    ///
    /// `damped`: Armijo backtracking on the condensed residual
    /// ([`super::line_search`]); plain Newton instead gives up once its
    /// increments keep failing to shrink.
    pub(super) fn newton_condensed(
        &mut self,
        h: f64,
        t1: f64,
        speed1: f64,
        f: &Factor,
        damped: bool,
    ) -> Result<Option<f64>, SolverError> {
        let (a0, a1, a2) = (4.0 / (h * h), 2.0 / h, 4.0 / h);
        let sj = self.sites.n_journal;
        {
            let (s, w) = (&self.state, &mut self.newmark);
            w.lin.copy_from_slice(&w.f_ext);
            crate::linalg::BandMatrix::mul_add_pair(
                &self.rotor.mass,
                &f.damping,
                &mut w.lin,
                |j| (a0 * s.u[j] + a2 * s.ud[j] + s.udd[j], a1 * s.u[j] + s.ud[j]),
            );
            let change = speed1 - f.speed;
            if change != 0.0 {
                // The gyroscopic force of the speed change at the predicted
                // rates, `−ΔΩ G u̇_p` with `u̇_p = u̇ₙ + h üₙ` (`gyroscopic_correction`).
                for (v, (ud, udd)) in w.mv.iter_mut().zip(s.ud.iter().zip(&s.udd)) {
                    *v = ud + h * udd;
                }
                self.rotor
                    .gyroscopic
                    .mul_add_vec(-change, &w.mv, &mut w.lin);
            }
            f.lu.solve_in_place(&mut w.lin);
        }
        if sj == 0 {
            self.stats.iterations += 1;
            self.set_displacement_and_rates(h, Displacement::Linear);
            self.gyroscopic_correction(h, speed1, f);
            return Ok(None);
        }
        let tol = self.options.tolerance;
        let singular = || SolverError::Linalg(LinalgError::Singular { column: 0 });
        let length_scale = self.sites.length_scale;
        let mut last = f64::INFINITY;
        // No chord iteration in the steps after one was refused (CHORD_PAUSE).
        let paused = self.condensed.chord_pause > 0;
        if paused && !damped {
            self.condensed.chord_pause -= 1;
        }
        let (mut chord, mut chord_allowed) = (false, !paused);
        let mut first_chord = true;
        // The slow-contraction rule moved a pad at the last iteration: the
        // contraction of the next increment says nothing about the error left.
        let mut moved = false;
        // Pads settled on their own balance ([`super::pad_balance`]): within
        // FORCE_FRACTION of `tol · s / G_max`, the force that moves a journal
        // by the tolerance, or on a tilt increment within 1e-2 `tol · s`.
        let mut balanced = !damped && self.condensed.balancing && self.sites.n_internal > 0;
        let compliance = (0..sj).map(|r| f.g[r * sj + r].abs()).fold(0.0, f64::max);
        let force_tol = FORCE_FRACTION * tol * length_scale / compliance;
        let tilt_tol = 1e-2 * tol * length_scale;
        let mut most_evaluations = 0;
        let mut gave_up = false;
        let report_ahead = self.condensed.last_on_iterate;
        self.condensed.last_on_iterate = false;
        self.condensed.search.reset();
        self.condensed.slow.reset();
        for _ in 0..self.options.max_iterations {
            self.stats.iterations += 1;
            // The step's first chord iteration keeps its force pass (with the
            // reports when the last step ended on its iterate), so that a step
            // that ends on its iterate has made its outputs' forces
            // ([`ends_on_iterate`]).
            let check = chord && first_chord && self.sites.on_ground;
            if chord {
                self.stats.chord_iterations += 1;
                first_chord = false;
            }
            let (s, w, c) = (&self.state, &mut self.newmark, &mut self.condensed);
            // A pad that did not balance sends the step back to the plain
            // iteration (its tilt left where it was).
            let mut unsettled = false;
            for (k, site) in self.sites.list.iter_mut().enumerate() {
                for (a, coordinate) in site.journal.iter().enumerate() {
                    let j = c.j[2 * k + a];
                    site.q[a] = j;
                    site.qd[a] = a1 * (j - coordinate.of(&s.u)) - coordinate.of(&s.ud);
                }
                for m in 0..site.internal {
                    let i = site.offset + m;
                    site.q[2 + m] = w.p[i];
                    site.qd[2 + m] = a1 * (w.p[i] - s.p[i]) - s.pd[i];
                }
                let bearing_error = |source| SolverError::Bearing {
                    name: site.name.clone(),
                    time: t1,
                    source,
                };
                for m in 0..site.internal.min(if balanced { usize::MAX } else { 0 }) {
                    let i = site.offset + m;
                    let rate = TiltRate {
                        a1,
                        start: s.p[i],
                        start_rate: s.pd[i],
                    };
                    let taken = pad_balance::settle(
                        &site.bearing,
                        m,
                        &mut site.q,
                        &mut site.qd,
                        speed1,
                        rate,
                        force_tol,
                        tilt_tol,
                    )
                    .map_err(bearing_error)?;
                    // A bearing without a balance of its own (the finite film's
                    // pads) keeps the plain iteration and its slow-pad rule.
                    let Some(taken) = taken else {
                        unsettled = true;
                        break;
                    };
                    self.stats.pad_evaluations += taken.evaluations;
                    most_evaluations = most_evaluations.max(taken.evaluations);
                    unsettled |= !taken.balanced;
                    w.p[i] = site.q[2 + m];
                }
                let wv = if chord {
                    let report = if check && report_ahead {
                        let report = site
                            .bearing
                            .output(&site.q, &site.qd, speed1, &mut site.eval);
                        Some(report.map_err(bearing_error)?)
                    } else {
                        site.bearing
                            .forces(&site.q, &site.qd, speed1, &mut site.eval)
                            .map_err(bearing_error)?;
                        None
                    };
                    if check {
                        site.memo
                            .store(&site.q, &site.qd, speed1, &site.eval.force, report);
                    }
                    site.condensation.load(&site.eval.force)
                } else {
                    site.bearing
                        .evaluate(&site.q, &site.qd, speed1, &mut site.eval)
                        .map_err(bearing_error)?;
                    let (kc, wv) = site
                        .condensation
                        .condense(&site.eval, a1)
                        .ok_or_else(singular)?;
                    c.kc[4 * k..4 * k + 4].copy_from_slice(&kc);
                    wv
                };
                c.fj[2 * k..2 * k + 2].copy_from_slice(&site.eval.force[..2]);
                c.wv[2 * k..2 * k + 2].copy_from_slice(&wv);
            }
            if unsettled {
                gave_up = true;
                balanced = false;
                c.balancing = false;
                last = f64::INFINITY;
            }
            for (r, coordinate) in self.sites.coordinates.iter().enumerate() {
                let g = &f.g[r * sj..(r + 1) * sj];
                let mut rhs = coordinate.of(&w.lin) - c.j[r];
                for (gc, (fc, wc)) in g.iter().zip(c.fj.iter().zip(&c.wv)) {
                    rhs += gc * (fc + wc);
                }
                c.cj_rhs[r] = rhs;
                if chord {
                    continue;
                }
                for k in 0..sj / 2 {
                    for i in 0..2 {
                        let mut v = if r == 2 * k + i { 1.0 } else { 0.0 };
                        for a in 0..2 {
                            v += g[2 * k + a] * c.kc[4 * k + 2 * a + i];
                        }
                        c.cj[r * sj + 2 * k + i] = v;
                    }
                }
            }
            let residual = if damped {
                condensed_residual(&self.sites, &c.cj_rhs)
            } else {
                0.0
            };
            if damped && let Trial::Retreat(back) = c.search.judge(residual) {
                retreat(&c.search, back, &mut c.j, &mut w.p);
                continue;
            }
            // A chord iteration solves with the factors of the last fresh one.
            if !chord && !lu_in_place(&mut c.cj, sj, &mut c.cj_piv) {
                return Err(singular());
            }
            lu_solve(&c.cj, sj, &c.cj_piv, &mut c.cj_rhs);
            let (mut inc, mut mag): (f64, f64) = (0.0, 0.0);
            for ((j, d), step) in c.j.iter().zip(&c.cj_rhs).zip(c.search.journal.iter_mut()) {
                inc = inc.max(d.abs());
                mag = mag.max(j.abs());
                *step = *d;
            }
            for (k, site) in self.sites.list.iter().enumerate() {
                let mi = site.internal;
                let (dx, dy) = (c.cj_rhs[2 * k], c.cj_rhs[2 * k + 1]);
                for m in 0..mi {
                    let x = &site.condensation.x;
                    let d = -x[2 * mi + m] - x[m] * dx - x[mi + m] * dy;
                    // Settled pads are judged by their settling, not this linear increment.
                    if !balanced {
                        inc = inc.max(d.abs());
                        mag = mag.max(w.p[site.offset + m].abs());
                    }
                    c.search.internal[site.offset + m] = d;
                }
            }
            let increment = inc / mag.max(length_scale);
            // A chord iteration that does not contract (a pad the film has just
            // loaded or unloaded) is not taken: the same iterate gets fresh Jacobians.
            if chord && increment > CHORD_CONTRACTION * last {
                chord = false;
                chord_allowed = false;
                c.chord_pause = CHORD_PAUSE;
                continue;
            }
            if check && ends_on_iterate(increment, tol) {
                // The forces at the iterate, its pads' residual condensed.
                for (fk, wk) in c.fj.iter_mut().zip(&c.wv) {
                    *fk += wk;
                }
                self.displacement_from_journal_forces(h, speed1, f);
                self.place_journals(h);
                self.stats.steps_on_iterate += 1;
                self.condensed.last_on_iterate = true;
                self.condensed.balancing = balanced && most_evaluations > BALANCED_EVALUATIONS;
                return Ok(None);
            }
            for (j, d) in c.j.iter_mut().zip(&c.search.journal) {
                *j += d;
            }
            for (p, d) in w.p.iter_mut().zip(&c.search.internal) {
                *p += d;
            }
            c.search.stepped(residual);
            let quadratic = balanced && !chord && quadratic_converged(increment, last, tol);
            if quadratic
                || converged(increment, last, tol, damped || moved)
                    && (!chord || chord_converged(increment, last, tol))
            {
                // u = u_lin + A⁻¹ E F_j with the first-order journal forces.
                for (k, fk) in c.fj.iter_mut().enumerate() {
                    let (b, i) = (k / 2, k % 2);
                    let kc = &c.kc[4 * b + 2 * i..4 * b + 2 * i + 2];
                    *fk += c.wv[k] - kc[0] * c.cj_rhs[2 * b] - kc[1] * c.cj_rhs[2 * b + 1];
                }
                self.displacement_from_journal_forces(h, speed1, f);
                if !damped {
                    self.condensed.balancing = balanced && most_evaluations > BALANCED_EVALUATIONS;
                }
                return Ok(None);
            }
            // Pads converging linearly (near a double root) move on by their
            // extrapolated tail when the iteration contracts slowly.
            let contraction = if chord || damped {
                0.0
            } else {
                increment / last
            };
            if !balanced && !gave_up && !damped && self.sites.n_internal > 0 && contraction > SLOW {
                // Slow: from here on every pad is settled on its own balance,
                // and the increments are the journals' alone.
                balanced = true;
                self.condensed.balancing = true;
                chord = false;
                last = f64::INFINITY;
                continue;
            }
            let count = if balanced {
                0
            } else {
                c.slow
                    .extrapolate(&c.search.internal, &mut w.p, contraction)
            };
            self.stats.extrapolations += count;
            moved = count > 0;
            chord =
                self.sites.cheap_forces && keeps_jacobians(increment, last, chord_allowed, damped);
            last = increment;
            if !damped && c.search.stalled(inc) {
                break;
            }
        }
        // A step that failed goes on (damped retry, halves) without settling.
        self.condensed.balancing = false;
        Ok(Some(last))
    }

    /// The step's displacement `u = u_lin + A⁻¹ E F_j` and its Newmark rates,
    /// `F_j` the journal forces in `condensed.fj`.
    fn displacement_from_journal_forces(&mut self, h: f64, speed1: f64, f: &Factor) {
        let (w, c) = (&mut self.newmark, &self.condensed);
        if f.z.is_empty() {
            w.mv.fill(0.0);
            for (coordinate, fk) in self.sites.coordinates.iter().zip(&c.fj) {
                coordinate.add(&mut w.mv, *fk);
            }
            f.lu.solve_in_place(&mut w.mv);
            self.set_displacement_and_rates(h, Displacement::LinearPlusCorrection);
        } else {
            for (zc, fk) in f.z.chunks_exact(w.lin.len()).zip(&c.fj) {
                for (l, z) in w.lin.iter_mut().zip(zc) {
                    *l += z * fk;
                }
            }
            self.set_displacement_and_rates(h, Displacement::Linear);
        }
        self.gyroscopic_correction(h, speed1, f);
    }

    /// Put the journals (each one rotor DOF: [`Sites::on_ground`]) on the
    /// iterate `condensed.j` exactly, with their Newmark rates: the
    /// coordinates and rates the iterate's bearing pass saw, so that
    /// `Simulator::outputs` finds that pass in the sites' memos. They move
    /// by the condensed residual, within the chord increment.
    fn place_journals(&mut self, h: f64) {
        let a = [4.0 / (h * h), 2.0 / h, 4.0 / h];
        let (s, w) = (&self.state, &mut self.newmark);
        for (coordinate, j) in self.sites.coordinates.iter().zip(&self.condensed.j) {
            let i = coordinate.journal;
            w.u[i] = *j;
            (w.ud[i], w.udd[i]) = newmark_rates(a, *j, s.u[i], s.ud[i], s.udd[i]);
        }
    }

    /// Modified Newton–Raphson on the full residual of a step with a possibly
    /// stale factorization: `J = A + E (K_b + a1 C_b) Eᵀ` (plus pad blocks)
    /// through [`SchurSolve`]; the bearing Jacobian is taken again at the first
    /// corrected iterate and when the residual stops contracting (ratio > 0.7),
    /// and `A` is refactored at the exact speed once per step on such a stall.
    /// `Ok(None)`: converged; `Ok(Some(residual))`: not within the iterations.
    pub(super) fn newton(
        &mut self,
        h: f64,
        t1: f64,
        speed1: f64,
        factor: &mut Option<Factor>,
    ) -> Result<Option<f64>, SolverError> {
        let a1 = 2.0 / h;
        let tol = self.options.tolerance;
        let mut last = f64::INFINITY;
        let mut refreshed = false;
        let mut jacobian_current = false;
        let mut increment_ok = false;
        let mut scale = self.linear_residual(h, speed1);
        let mut residual = self.residual_with_bearings(t1, speed1, &mut scale)?;
        for iteration in 0..self.options.max_iterations {
            self.stats.iterations += 1;
            if residual <= tol && increment_ok {
                return Ok(None);
            }
            let stalled = iteration > 0 && residual > 0.7 * last;
            last = residual;
            // The predictor can be far from the solution: take the Jacobian once more
            // at the first corrected iterate, then keep it (modified Newton).
            if iteration == 1 {
                jacobian_current = false;
            }
            // A stalled modified Newton gets the current bearing Jacobian (cheap: it
            // lives on the few bearing DOFs) and, once per step, `A` at the current speed.
            let mut refresh_now = false;
            if stalled {
                refresh_now = !refreshed;
                refreshed = true;
                jacobian_current = false;
                self.stats.refreshes += 1;
            }
            // `prepare_factor` has refactored for a new step size or speed band;
            // here only a refresh moves `A` to the exact speed.
            let rebuild = factor
                .as_ref()
                .is_none_or(|f| refresh_now && f.speed != speed1);
            if rebuild {
                *factor = Some(self.dynamic_factor(h, speed1, factor.take())?);
                self.schur.ready = false;
            }
            if !jacobian_current {
                self.schur.ready = false;
                for site in &mut self.sites.list {
                    site.jk.copy_from_slice(&site.eval.stiffness);
                    site.jc.copy_from_slice(&site.eval.damping);
                }
                jacobian_current = true;
            }
            let Some(f) = factor.as_ref() else {
                return Err(SolverError::Input("internal: no factorization".into()));
            };
            // Step sizes that differ by rounding only count as exact (the error is
            // of the order of the round-off of the solve itself).
            let exact = (f.step - h).abs() <= 1e-12 * h && f.speed == speed1;
            let w = &mut self.newmark;
            w.du.copy_from_slice(&w.r);
            w.dp.copy_from_slice(&w.rp);
            self.schur
                .solve(&self.sites, f, a1, false, &mut w.du, &mut w.dp)?;
            let mut inc: f64 = 0.0;
            let mut mag: f64 = 0.0;
            for (i, d) in w.du.iter().enumerate() {
                if self.rotor.dofs.is_displacement(i) {
                    inc = inc.max(d.abs());
                    mag = mag.max(w.u[i].abs());
                }
            }
            for (d, v) in w.dp.iter().zip(&w.p) {
                inc = inc.max(d.abs());
                mag = mag.max(v.abs());
            }
            increment_ok = inc <= tol * mag.max(self.sites.length_scale);
            for (u, d) in w.u.iter_mut().zip(&w.du) {
                *u += d;
            }
            for (p, d) in w.p.iter_mut().zip(&w.dp) {
                *p += d;
            }
            if exact {
                // With the exact A, A δu = r − E f and r = lin + E F_b, so the new
                // linear residual is E (f − F_b): it lives on the journal DOFs only.
                self.update_rates(h);
                let w = &mut self.newmark;
                w.lin.fill(0.0);
                for (k, site) in self.sites.list.iter().enumerate() {
                    for (a, coordinate) in site.journal.iter().enumerate() {
                        coordinate.add(&mut w.lin, self.schur.rhs[2 * k + a] - site.eval.force[a]);
                    }
                }
            } else {
                scale = scale.max(self.linear_residual(h, speed1));
            }
            residual = self.residual_with_bearings(t1, speed1, &mut scale)?;
        }
        Ok(Some(last))
    }
}

#[cfg(test)]
mod tests {
    use super::{chord_converged, converged, keeps_jacobians};

    /// A chord iteration follows an increment within 1e-3 of the scale that
    /// contracted by 1e-2 on the one before (any at the first iteration),
    /// never in the damped retry nor once a chord iteration of the step has
    /// failed; its iterate is taken when `2 δ_k²/δ_{k−1}` is within 1e-2 of
    /// the tolerance.
    #[test]
    fn chord_iterations_follow_fast_contraction_only() {
        let inf = f64::INFINITY;
        // The hydro unit's first increment, about 1e-6 of its clearance.
        assert!(keeps_jacobians(1e-6, inf, true, false));
        assert!(!keeps_jacobians(1e-6, inf, true, true));
        assert!(!keeps_jacobians(1e-6, inf, false, false));
        // The three-guide unit's first increments under accuracy-controlled
        // steps, up to about 1e-3 of its clearance: chord; beyond, Newton.
        assert!(keeps_jacobians(8e-4, inf, true, false));
        assert!(!keeps_jacobians(2e-3, inf, true, false));
        // Pads near a double root halve their increments: full Newton.
        assert!(!keeps_jacobians(1e-6, 2e-6, true, false));
        assert!(keeps_jacobians(1e-6, 1e-4, true, false));
        let tol = 1e-8;
        // 1e-9 after 1e-6 leaves 2e-12; 5e-9 after 1e-6 leaves 5e-11.
        assert!(chord_converged(1e-9, 1e-6, tol));
        assert!(chord_converged(5e-9, 1e-6, tol));
        // After the plain-bearing unit's 1.7e-7, 1e-8 would leave 1.2e-9.
        assert!(!chord_converged(1e-8, 1.7e-7, tol));
        assert!(chord_converged(2.4e-9, 1.7e-7, tol));
    }

    /// Within the tolerance always; just above it only on evidence of fast
    /// contraction, never at the first iteration, never damped, never when
    /// the iterations contract slowly (a double root halves its error).
    #[test]
    fn an_increment_just_above_the_tolerance_needs_a_fast_contraction() {
        let tol = 1e-8;
        assert!(converged(0.9e-8, f64::INFINITY, tol, false));
        assert!(converged(0.9e-8, 1e-9, tol, true));
        // The three-guide unit's second iterations: 1.3e-8 after 9e-5.
        assert!(converged(1.3e-8, 9e-5, tol, false));
        assert!(!converged(1.3e-8, 9e-5, tol, true));
        assert!(!converged(1.3e-8, f64::INFINITY, tol, false));
        // ρ = 0.5: what is left is as large as the increment.
        assert!(!converged(1.3e-8, 2.6e-8, tol, false));
        // Ten times the tolerance is the limit whatever the contraction.
        assert!(converged(9e-8, 1.0, tol, false));
        assert!(!converged(1.1e-7, 1.0, tol, false));
        // Growing increments are not converging.
        assert!(!converged(2e-8, 1e-8, tol, false));
    }
}
