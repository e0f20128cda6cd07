//! The floor a Newmark step's cost is tied to (issue 51,
//! `benches/step_floor.rs`): one force-and-Jacobian pass of every nonlinear
//! element at the state in hand, and one forward and back substitution with
//! the banded factorization the steps solve with. A step that converges in
//! one iteration costs about one of each; the benchmark prints a step's cost
//! over their sum.

use super::error::SolverError;
use super::simulator::Simulator;

impl Simulator {
    /// One force-and-Jacobian pass: every nonlinear bearing, seal, pull and
    /// rub evaluated (force and Jacobians) at the current rotor state `u`,
    /// `u̇`, pad state `p`, `ṗ` and speed, its journal forces added into a
    /// zeroed residual, as a Newton iteration evaluates them. Works on the
    /// step's scratch buffers only: the state and the next step are not
    /// touched. Returns the largest force term (N).
    pub fn force_and_jacobian_pass(&mut self) -> Result<f64, SolverError> {
        let speed = self.speed_at(self.state.time);
        let (s, w) = (&self.state, &mut self.newmark);
        w.r.fill(0.0);
        self.sites
            .add_forces(&s.u, &s.ud, &s.p, &s.pd, speed, s.time, &mut w.r, &mut w.rp)
    }

    /// One forward and back substitution with the banded factorization in
    /// hand (the last step's), on a scratch vector; `false` before the first
    /// step made one.
    pub fn banded_solve(&mut self) -> bool {
        match self.factor.as_ref() {
            Some(f) => {
                self.newmark.mv.fill(1.0);
                f.lu.solve_in_place(&mut self.newmark.mv);
                true
            }
            None => false,
        }
    }
}
