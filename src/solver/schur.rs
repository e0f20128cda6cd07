//! Schur solve of the step's linear system bordered by the frozen bearing
//! blocks: the full-residual (modified) Newton's linear solve and the static
//! solve's (see [`crate::solver`]).

use crate::linalg::LinalgError;

use super::dense::{lu_in_place, lu_solve};
use super::error::SolverError;
use super::factor_work::Factor;
use super::sites::Sites;

/// Schur solve of a factored `A` bordered by the frozen bearing blocks, on the
/// `s = s_j + s_p` bearing DOFs (journal, then pad).
#[derive(Debug)]
pub(super) struct SchurSolve {
    /// LU of the dense bearing-sized system (row-major `s × s`).
    matrix: Vec<f64>,
    /// `matrix` holds the LU factors for the current Jacobians and factorization.
    pub ready: bool,
    /// Right-hand side, then solution: journal forces `f`, then pad increments.
    pub rhs: Vec<f64>,
    pivots: Vec<usize>,
    /// `Eᵀ y`: the journal entries of `A⁻¹ y`.
    ey: Vec<f64>,
    /// `A⁻¹ E f` (length `n`).
    correction: Vec<f64>,
}

impl SchurSolve {
    /// Buffers for `n` rotor DOFs and the bearings `sites`.
    pub fn new(n: usize, sites: &Sites) -> Self {
        let s = sites.n_journal + sites.n_internal;
        Self {
            matrix: vec![0.0; s * s],
            ready: false,
            rhs: vec![0.0; s],
            pivots: vec![0; s],
            ey: vec![0.0; sites.n_journal],
            correction: vec![0.0; n],
        }
    }

    /// Solve `J [δu; δp] = [y; dp]` in place, `J` = factored `A` plus the frozen
    /// bearing blocks `(K_b + a1 C_b)` of `sites` (`jk`, `jc`); with
    /// `journal_in_a` only the pad blocks are added (the journal blocks are
    /// already in `A`). Eliminating `δu = A⁻¹ (y − E f)` leaves the dense system
    /// `f + ΔK_jj G f − K_jp δp = ΔK_jj Eᵀ A⁻¹ y`,
    /// `−K_pj G f + K_pp δp = dp − K_pj Eᵀ A⁻¹ y` (`G = Eᵀ A⁻¹ E`), factored once
    /// per Jacobian refresh.
    pub fn solve(
        &mut self,
        sites: &Sites,
        factor: &Factor,
        a1: f64,
        journal_in_a: bool,
        y: &mut [f64],
        dp: &mut [f64],
    ) -> Result<(), SolverError> {
        let sj = sites.n_journal;
        let s = sj + sites.n_internal;
        factor.lu.solve_in_place(y);
        if s == 0 {
            return Ok(());
        }
        for (e, c) in self.ey.iter_mut().zip(&sites.coordinates) {
            *e = c.of(y);
        }
        // The matrix depends only on the frozen Jacobians and G: factor it once per
        // refresh (modified Newton), then only the right-hand side changes.
        if !self.ready {
            let small = &mut self.matrix;
            small.fill(0.0);
            for (k, site) in sites.list.iter().enumerate() {
                let n2 = site.eval.n();
                let jac = |i: usize, j: usize| site.jk[i * n2 + j] + a1 * site.jc[i * n2 + j];
                let jr = 2 * k;
                let pr = sj + site.offset;
                for i in 0..2 {
                    // Rows of f: f + ΔK_jj G f − K_jp δp = ΔK_jj Eᵀy.
                    small[(jr + i) * s + jr + i] += 1.0;
                    if !journal_in_a {
                        for a in 0..2 {
                            let kia = jac(i, a);
                            for c in 0..sj {
                                small[(jr + i) * s + c] += kia * factor.g[(jr + a) * sj + c];
                            }
                        }
                    }
                    for m in 0..site.internal {
                        small[(jr + i) * s + pr + m] -= jac(i, 2 + m);
                    }
                }
                for m in 0..site.internal {
                    // Rows of δp: −K_pj G f + K_pp δp = r_p − K_pj Eᵀy.
                    let row = pr + m;
                    for a in 0..2 {
                        let kma = jac(2 + m, a);
                        for c in 0..sj {
                            small[row * s + c] -= kma * factor.g[(jr + a) * sj + c];
                        }
                    }
                    for l in 0..site.internal {
                        small[row * s + pr + l] += jac(2 + m, 2 + l);
                    }
                }
            }
            if !lu_in_place(small, s, &mut self.pivots) {
                return Err(SolverError::Linalg(LinalgError::Singular { column: 0 }));
            }
            self.ready = true;
        }
        self.rhs.fill(0.0);
        for (k, site) in sites.list.iter().enumerate() {
            let n2 = site.eval.n();
            let jac = |i: usize, j: usize| site.jk[i * n2 + j] + a1 * site.jc[i * n2 + j];
            let jr = 2 * k;
            if !journal_in_a {
                for i in 0..2 {
                    for a in 0..2 {
                        self.rhs[jr + i] += jac(i, a) * self.ey[jr + a];
                    }
                }
            }
            for m in 0..site.internal {
                let row = sj + site.offset + m;
                for a in 0..2 {
                    self.rhs[row] -= jac(2 + m, a) * self.ey[jr + a];
                }
                self.rhs[row] += dp[site.offset + m];
            }
        }
        lu_solve(&self.matrix, s, &self.pivots, &mut self.rhs);
        // δu = A⁻¹ r − A⁻¹ E f: a second solve with the journal forces f.
        if sj > 0 {
            let z = &mut self.correction;
            z.fill(0.0);
            for (c, f) in sites.coordinates.iter().zip(&self.rhs) {
                c.add(z, *f);
            }
            factor.lu.solve_in_place(z);
            for (yi, zi) in y.iter_mut().zip(z.iter()) {
                *yi -= zi;
            }
        }
        dp.copy_from_slice(&self.rhs[sj..]);
        Ok(())
    }
}
