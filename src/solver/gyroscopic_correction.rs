//! The correction of a condensed step taken on a factorization made at a
//! speed `ΔΩ` off the step's own (within `factor_work::GYROSCOPIC_PHASE_BAND`): the
//! gyroscopic term `a1 ΔΩ G` that `A` leaves out (`docs/solver.md`).

use super::dense::lu_solve;
use super::factor_work::Factor;
use super::newmark::Displacement;
use super::simulator::Simulator;

impl Simulator {
    /// A factorization made at a speed `ΔΩ` off the step's `speed1` leaves
    /// the gyroscopic term `a1 ΔΩ G` out of `A`: the step put `−ΔΩ G u̇_p` in
    /// as a force at the predicted rates `u̇_p = u̇ₙ + h üₙ`, and the rest,
    /// `g = −ΔΩ G (u̇ − u̇_p)`, is added here as a linear correction with the
    /// bearings' condensed stiffness: the journals move by
    /// `δj = (I + G_j K_c)⁻¹ Eᵀ A⁻¹ g` (the step's factored Newton matrix), their
    /// forces by `−K_c δj`, the rotor by `A⁻¹ (g − E K_c δj)`; what is left
    /// is of second order in `ΔΩ`. One banded solve a step and `A⁻¹ E`'s
    /// columns where the factorization keeps them (else a second solve),
    /// against a factorization and a solve per journal DOF. A correction that moves a
    /// journal by more than the Newton tolerance sends the step back to a
    /// factorization at its own speed ([`CondensedWork::gyroscopic_excess`]).
    ///
    /// [`CondensedWork::gyroscopic_excess`]: super::condensed_work::CondensedWork
    pub(super) fn gyroscopic_correction(&mut self, h: f64, speed1: f64, f: &Factor) {
        let change = speed1 - f.speed;
        if change == 0.0 {
            return;
        }
        let (s, w, c) = (&self.state, &mut self.newmark, &mut self.condensed);
        for (d, (ud, (ud0, udd0))) in
            w.du.iter_mut()
                .zip(w.ud.iter().zip(s.ud.iter().zip(&s.udd)))
        {
            *d = ud - (ud0 + h * udd0);
        }
        w.mv.fill(0.0);
        self.rotor.gyroscopic.mul_add_vec(-change, &w.du, &mut w.mv);
        f.lu.solve_in_place(&mut w.mv);
        let sj = self.sites.n_journal;
        if sj > 0 {
            for (r, coordinate) in self.sites.coordinates.iter().enumerate() {
                c.cj_rhs[r] = coordinate.of(&w.mv);
            }
            lu_solve(&c.cj, sj, &c.cj_piv, &mut c.cj_rhs);
            let journal = c.cj_rhs.iter().fold(0.0_f64, |m, d| m.max(d.abs()));
            if journal > self.options.tolerance * self.sites.length_scale {
                c.gyroscopic_excess = true;
                return;
            }
            // `A⁻¹ E` by its columns where the factorization keeps them.
            let columns = !f.z.is_empty();
            let n = w.mv.len();
            w.du.fill(0.0);
            for (k, (coordinate, fk)) in self
                .sites
                .coordinates
                .iter()
                .zip(c.fj.iter_mut())
                .enumerate()
            {
                let (b, i) = (k / 2, k % 2);
                let kc = &c.kc[4 * b + 2 * i..4 * b + 2 * i + 2];
                let force = -kc[0] * c.cj_rhs[2 * b] - kc[1] * c.cj_rhs[2 * b + 1];
                *fk += force;
                if columns {
                    for (m, z) in w.mv.iter_mut().zip(&f.z[k * n..(k + 1) * n]) {
                        *m += z * force;
                    }
                } else {
                    coordinate.add(&mut w.du, force);
                }
            }
            if !columns {
                f.lu.solve_in_place(&mut w.du);
                for (m, d) in w.mv.iter_mut().zip(&w.du) {
                    *m += d;
                }
            }
        }
        for (u, d) in w.u.iter_mut().zip(&w.mv) {
            *u += d;
        }
        self.set_displacement_and_rates(h, Displacement::Iterate);
    }
}
