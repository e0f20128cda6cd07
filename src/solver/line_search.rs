//! The damped Newton of a step that plain Newton could not solve (see
//! [`crate::solver`]): Armijo backtracking on the condensed residual, and the
//! retry of the failed step with it before the step is cut.
//!
//! Full Newton on the step equations can fall into a cycle where a bearing
//! force turns over within a small change of its coordinates. The sharpest
//! such turn is regularized Coulomb friction, `μ N φ(v_s)` with
//! `φ(v) = v/√(v² + v_ε²)`: a rotor rolling on a rub ring (backward dry-friction
//! whirl locks onto `v_s = ṗ·t + Ω R ≈ 0`) or on its bushing sits right in it.
//! A step of size `h` maps the turn to a displacement of `v_ε h / 2`, and its
//! slope `a1 μ N / v_ε` (`a1 = 2/h`) exceeds the step's inertia `a0 M`
//! (`a0 = 4/h²`) whenever `h > 2 M v_ε / (μ N)`: Newton then jumps from one side
//! of the turn to the other and back. Halving the step does not cure it — the
//! ratio of the two falls only like `h` — so the step used to be cut ten times
//! and given up (`fmi2Discard`). The film near contact (the pressure arc
//! turning with the squeeze velocity at `ε → 1`) turns over the same way.
//!
//! Newton's direction `d` solves `R + J d = 0`, so along it the residual falls,
//! `‖R(x + α d)‖ ≈ (1 − α) ‖R(x)‖` for small `α`, in any norm. The damped
//! Newton takes the full step when its residual has fallen by the Armijo test
//! `‖R(x + α d)‖ ≤ (1 − 10⁻⁴ α) ‖R(x)‖` and halves `α` otherwise (at most
//! [`Backtrack::MAX_HALVINGS`] times, then the point is kept and Newton goes
//! on). Halving beats the minimum of a quadratic fitted to `‖R‖²` here: on the
//! 1e3 kg·m rub the fitted steps come out so short that the step runs out of
//! iterations, with five times the step cuts. The residual is the condensed one in metres: the journal equations
//! `j_lin − j + G (F_j + K_jp K_pp⁻¹ (−F_p))` and the pad corrections
//! `K_pp⁻¹ F_p` (largest entry).
//!
//! Plain Newton stays the first attempt of every step: where it converges the
//! result is what it always was. It gives up early when its increment has
//! failed to shrink [`Backtrack::STALLS`] times (a cycle; no step of the
//! shipped models' runs, run-ups and coast-downs has more than three such
//! iterations and still converges), and the step is then solved again from the
//! predictor by the damped Newton, on a factorization exact for the step,
//! before it is cut in half.

use super::error::SolverError;
use super::factor_work::Factor;
use super::simulator::Simulator;
use super::sites::Sites;

/// The last Newton increment, its line search and the stall count of plain
/// Newton.
#[derive(Debug)]
pub(super) struct Backtrack {
    /// Increment of the journal coordinates (m), site by site (`x`, `y`).
    pub journal: Vec<f64>,
    /// Increment of the pad coordinates (m).
    pub internal: Vec<f64>,
    /// Residual at the point the increment starts from (m).
    base: f64,
    /// Fraction of the increment taken.
    alpha: f64,
    halvings: usize,
    /// Largest entry of the previous increment (m) and how many increments
    /// have not been smaller than their predecessor.
    previous: f64,
    stalls: usize,
}

/// What the line search decides at a trial point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Trial {
    /// Keep the point and take the next Newton step from it.
    Accept,
    /// Move back along the increment by this multiple of it and evaluate again.
    Retreat(f64),
}

impl Backtrack {
    /// Most halvings of one increment: down to `2^-MAX_HALVINGS` of it.
    pub const MAX_HALVINGS: usize = 8;
    /// Increments not smaller than their predecessor after which plain Newton
    /// gives the step up to the damped one.
    pub const STALLS: usize = 5;
    /// Armijo constant: `‖R(x + α d)‖ ≤ (1 − ARMIJO α) ‖R(x)‖`.
    const ARMIJO: f64 = 1e-4;

    /// Buffers for `n_journal` journal and `n_internal` pad coordinates.
    pub fn new(n_journal: usize, n_internal: usize) -> Self {
        Self {
            journal: vec![0.0; n_journal],
            internal: vec![0.0; n_internal],
            base: f64::INFINITY,
            alpha: 1.0,
            halvings: 0,
            previous: f64::INFINITY,
            stalls: 0,
        }
    }

    /// Start the iterations of a step: the first point (the predictor) has no
    /// increment to judge.
    pub fn reset(&mut self) {
        self.base = f64::INFINITY;
        self.alpha = 1.0;
        self.halvings = 0;
        self.previous = f64::INFINITY;
        self.stalls = 0;
    }

    /// Judge the point reached, of residual `residual` (m).
    pub fn judge(&mut self, residual: f64) -> Trial {
        let enough = residual <= (1.0 - Self::ARMIJO * self.alpha) * self.base;
        if enough || self.halvings >= Self::MAX_HALVINGS {
            return Trial::Accept;
        }
        self.halvings += 1;
        let back = 0.5 * self.alpha;
        self.alpha -= back;
        Trial::Retreat(back)
    }

    /// A full Newton increment (stored in [`Backtrack::journal`] and
    /// [`Backtrack::internal`] by the caller) leaves the point of residual
    /// `residual` (m).
    pub fn stepped(&mut self, residual: f64) {
        self.base = residual;
        self.alpha = 1.0;
        self.halvings = 0;
    }

    /// Plain Newton took an increment of largest entry `increment` (m): has it
    /// failed to shrink [`Backtrack::STALLS`] times in this step?
    pub fn stalled(&mut self, increment: f64) -> bool {
        if increment >= self.previous {
            self.stalls += 1;
        }
        self.previous = increment;
        self.stalls >= Self::STALLS
    }
}

/// Newton-scaled residual of the condensed step (m): the largest entry of the
/// journal residual `rhs` and of the pad corrections `K_pp⁻¹ (−F_p)` of every
/// site.
pub(super) fn condensed_residual(sites: &Sites, rhs: &[f64]) -> f64 {
    let mut largest = rhs.iter().fold(0.0f64, |a, r| a.max(r.abs()));
    for site in &sites.list {
        let mi = site.internal;
        for x in &site.condensation.x[2 * mi..3 * mi] {
            largest = largest.max(x.abs());
        }
    }
    largest
}

/// Move the journal coordinates `j` (relative to their housings) and the pad
/// coordinates `p` back by `back` times the last increment of `search`.
pub(super) fn retreat(search: &Backtrack, back: f64, j: &mut [f64], p: &mut [f64]) {
    for (j, d) in j.iter_mut().zip(&search.journal) {
        *j -= back * d;
    }
    for (p, d) in p.iter_mut().zip(&search.internal) {
        *p -= back * d;
    }
}

impl Simulator {
    /// Solve the step of size `h` to `t1` at speed `speed1` again, after plain
    /// Newton failed: from the predictor, by the damped condensed Newton, on a
    /// factorization exact for the step (refactored into `factor` if the one
    /// in hand is not). Same result convention as the Newton solvers.
    pub(super) fn retry_damped(
        &mut self,
        h: f64,
        t1: f64,
        speed1: f64,
        factor: &mut Option<Factor>,
    ) -> Result<Option<f64>, SolverError> {
        self.stats.retries += 1;
        self.exact_factor_step(h, t1, speed1, factor, true)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::RotorModel;
    use crate::rotor::Rotor;
    use crate::solver::SolverOptions;

    /// Where plain Newton converges the damped one is never called, so those
    /// results are what they were before it existed: the shipped Jeffcott
    /// rotor at 3000 rpm and at 9000 rpm (oil whirl), run up from rest, and
    /// the hydro unit on its tilting pads.
    #[test]
    fn steps_that_plain_newton_solves_are_not_retried() {
        for (name, from, to) in [
            ("jeffcott", 3000.0, 3000.0),
            ("jeffcott", 9000.0, 9000.0),
            ("jeffcott", 0.0, 3000.0),
            ("hydro_unit", 150.0, 150.0),
        ] {
            let path = format!("{}/models/{name}.toml", env!("CARGO_MANIFEST_DIR"));
            let model = RotorModel::from_file(std::path::Path::new(&path)).unwrap();
            let mut sim =
                Simulator::new(Rotor::new(model).unwrap(), SolverOptions::default()).unwrap();
            let rpm = std::f64::consts::PI / 30.0;
            sim.set_speed(from * rpm, 0.0).unwrap();
            sim.settle_static().unwrap();
            sim.set_speed(from * rpm, (to - from) * rpm / 0.2).unwrap();
            sim.advance_to(0.2).unwrap();
            let stats = sim.stats();
            assert!(stats.steps >= 2000, "{name}: {stats:?}");
            assert_eq!(
                (stats.retries, stats.step_cuts),
                (0, 0),
                "{name} {from}→{to} rpm: {stats:?}"
            );
        }
    }

    /// A scalar step residual `a v + b φ(v) − c` dominated by regularized
    /// friction (`b / (a v_ε) = 10⁵`: the friction's slope at its turn against
    /// the step's inertia): plain Newton cycles between the two sides of the
    /// friction turn, Newton with this line search converges.
    #[test]
    fn backtracking_breaks_the_newton_cycle_of_a_step_like_friction_force() {
        let eps = 1e-2;
        let (a, b, c) = (1.0, 1e3, 300.0);
        let phi = |v: f64| v / (v * v + eps * eps).sqrt();
        let dphi = |v: f64| eps * eps / (v * v + eps * eps).powf(1.5);
        let r = |v: f64| a * v + b * phi(v) - c;
        let dr = |v: f64| a + b * dphi(v);
        let solve = |damped: bool| {
            let mut v = 0.1;
            let mut search = Backtrack::new(1, 0);
            search.reset();
            for k in 0..200 {
                let res = r(v).abs();
                if damped {
                    if let Trial::Retreat(back) = search.judge(res) {
                        v -= back * search.journal[0];
                        continue;
                    }
                }
                let d = -r(v) / dr(v);
                if d.abs() < 1e-13 {
                    return Some(k);
                }
                search.journal[0] = d;
                search.stepped(res);
                v += d;
            }
            None
        };
        assert_eq!(solve(false), None, "plain Newton cycles");
        let iterations = solve(true).expect("damped Newton converges");
        assert!(iterations < 60, "{iterations} evaluations");
    }

    #[test]
    fn the_line_search_halves_until_the_residual_falls_and_plain_newton_stalls_on_a_cycle() {
        let mut search = Backtrack::new(2, 0);
        search.reset();
        assert_eq!(search.judge(1.0), Trial::Accept, "the predictor");
        search.stepped(1.0);
        assert_eq!(search.judge(2.0), Trial::Retreat(0.5));
        assert_eq!(search.judge(1.0), Trial::Retreat(0.25));
        // Armijo at α = 1/4 asks for 1 − 10⁻⁴/4 of the starting residual.
        assert_eq!(search.judge(1.0 - 1e-5), Trial::Retreat(0.125));
        assert_eq!(search.judge(0.99), Trial::Accept);
        for _ in 0..Backtrack::MAX_HALVINGS {
            search.stepped(1.0);
            for _ in 0..Backtrack::MAX_HALVINGS {
                assert!(matches!(search.judge(3.0), Trial::Retreat(_)));
            }
            assert_eq!(search.judge(3.0), Trial::Accept, "after the last halving");
        }
        search.reset();
        let cycle = [1.0, 0.5, 0.5, 0.6, 0.6, 0.6, 0.6];
        let stalls: Vec<bool> = cycle.iter().map(|&inc| search.stalled(inc)).collect();
        assert_eq!(stalls, [false, false, false, false, false, false, true]);
    }
}
