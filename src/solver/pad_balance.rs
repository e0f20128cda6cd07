//! Each pad's tilt settled on its own moment balance inside an iteration of
//! the condensed Newton (nonlinear elimination of the pads): a pad's balance
//! `Q_η(j, η, η̇) = 0` depends on the journal `j` and its own tilt only (its
//! rate `η̇ = a1 (η − η_n) − η̇_n` the step's Newmark rate), so with every pad
//! balanced at the journal iterate the condensed Newton is exact Newton on
//! the journals alone, `K_c = K_jj − K_jp K_pp⁻¹ K_pj` the exact derivative of
//! the eliminated system, and converges quadratically on them.
//!
//! Why: a pad the film has just unloaded sits near a double root of its
//! balance (`Q_η ≈ a e² − k_r η`, `solver/slow_pads.rs`), where Newton's
//! tilt increments only halve; the condensed Newton judged the pads by their
//! increments and paid a whole bearing pass for every halving (the unit on
//! brackets: 15 iterations a step). A pad is settled when its Newton
//! increment is within a hundredth of the Newton tolerance, or its residual
//! within `ε_F` (the caller's: `1e-9 · tol · s / G_max`, `s` the
//! displacement scale, `G_max` the largest diagonal entry of the step's
//! journal compliance `G = Eᵀ A⁻¹ E`, so `tol · s / G_max` is the force that
//! moves a journal by the tolerance). Looser, as the ill-conditioning of a
//! tilt near a double root would allow for the journal, was measured and
//! rejected: the tilt is a first-order state the next steps carry on
//! (`docs/solver.md`). The scalar
//! solve is Newton on `Q_η` with its derivative `−(K_ηη + a1 C_ηη)`,
//! bisection once a sign change brackets the root and Newton leaves the
//! bracket; each pass evaluates the one pad's film
//! ([`crate::bearing::Bearing::internal_balance`]), an eighth of a bearing
//! pass on an eight-pad bearing.

use crate::bearing::{Bearing, BearingError};

/// Film evaluations one pad may take in one settling.
pub(super) const MAX_EVALUATIONS: usize = 30;

/// A pad's Newmark tilt rate: `η̇ = a1 (η − η_n) − η̇_n`.
#[derive(Debug, Clone, Copy)]
pub(super) struct TiltRate {
    /// `2 / h`.
    pub a1: f64,
    /// Tilt at the start of the step, `η_n`.
    pub start: f64,
    /// Tilt rate at the start of the step, `η̇_n`.
    pub start_rate: f64,
}

impl TiltRate {
    fn at(&self, eta: f64) -> f64 {
        self.a1 * (eta - self.start) - self.start_rate
    }
}

/// How a pad's settling went: the film evaluations it took, and whether it
/// balanced within them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Settled {
    pub evaluations: usize,
    pub balanced: bool,
}

/// Settle internal coordinate `m` of `q` (entry `2 + m`, its rate in `qdot`
/// by `rate`) until its balance is within `force_tol` (N), or a Newton
/// increment within `tilt_tol` (m). `Ok(None)`: the bearing gives no
/// balance of its own ([`Bearing::internal_balance`]). A pad that does not
/// balance within [`MAX_EVALUATIONS`] is left where it started.
#[allow(clippy::too_many_arguments)]
pub(super) fn settle(
    bearing: &dyn Bearing,
    m: usize,
    q: &mut [f64],
    qdot: &mut [f64],
    speed: f64,
    rate: TiltRate,
    force_tol: f64,
    tilt_tol: f64,
) -> Result<Option<Settled>, BearingError> {
    let i = 2 + m;
    let (start, start_rate) = (q[i], qdot[i]);
    let mut eta = start;
    // Tilts where the balance was last found positive and negative.
    let (mut positive, mut negative): (Option<f64>, Option<f64>) = (None, None);
    for evaluation in 1..=MAX_EVALUATIONS {
        q[i] = eta;
        qdot[i] = rate.at(eta);
        let Some(balance) = bearing.internal_balance(m, q, qdot, speed) else {
            return Ok(None);
        };
        let [moment, k, c] = balance?;
        if moment.abs() <= force_tol {
            return Ok(Some(Settled {
                evaluations: evaluation,
                balanced: true,
            }));
        }
        if moment > 0.0 {
            positive = Some(eta);
        } else {
            negative = Some(eta);
        }
        let slope = k + rate.a1 * c;
        let mut next = eta + moment / slope;
        if let (Some(a), Some(b)) = (positive, negative) {
            let (lo, hi) = (a.min(b), a.max(b));
            if !(next > lo && next < hi) {
                next = 0.5 * (lo + hi);
            }
        } else if !next.is_finite() {
            break;
        }
        if (next - eta).abs() <= tilt_tol {
            q[i] = next;
            qdot[i] = rate.at(next);
            return Ok(Some(Settled {
                evaluations: evaluation,
                balanced: true,
            }));
        }
        eta = next;
    }
    q[i] = start;
    qdot[i] = start_rate;
    Ok(Some(Settled {
        evaluations: MAX_EVALUATIONS,
        balanced: false,
    }))
}

#[cfg(test)]
mod tests {
    use super::{MAX_EVALUATIONS, Settled, TiltRate, settle};
    use crate::bearing::{Bearing, BearingError, BearingEval};

    /// A pad near the tilt `η₀` where its film stops carrying it: the film's
    /// moment `a (η − η₀)²` beyond it, nothing before, and the pivot's rest
    /// moment `−k_r η` (the balance of `crate::bearing::tilting_pad` near
    /// unloading, rates left out): the loaded root is
    /// `η* = η₀ + √(k_r η*/a)`, a near-double root.
    #[derive(Debug)]
    struct NearDoubleRoot {
        a: f64,
        eta0: f64,
        k_rest: f64,
    }

    impl NearDoubleRoot {
        fn moment(&self, eta: f64) -> f64 {
            let e = (eta - self.eta0).max(0.0);
            self.a * e * e - self.k_rest * eta
        }
    }

    impl Bearing for NearDoubleRoot {
        fn internal_dofs(&self) -> usize {
            1
        }
        fn evaluate(
            &self,
            _: &[f64],
            _: &[f64],
            _: f64,
            _: &mut BearingEval,
        ) -> Result<(), BearingError> {
            unreachable!("the settling evaluates the pad alone")
        }
        fn is_linear(&self) -> bool {
            false
        }
        fn internal_balance(
            &self,
            _m: usize,
            q: &[f64],
            _qdot: &[f64],
            _speed: f64,
        ) -> Option<Result<[f64; 3], BearingError>> {
            let e = (q[2] - self.eta0).max(0.0);
            Some(Ok([self.moment(q[2]), self.k_rest - 2.0 * self.a * e, 0.0]))
        }
    }

    /// Started 1e3 times the root's distance from the unloading tilt away,
    /// where Newton halves its way down, the pad settles within the force
    /// tolerance on the loaded root (not the resting one at zero), within
    /// the tilt error that tolerance allows there, in the evaluations plain
    /// Newton takes (the scalar solve is Newton: what it saves is a bearing
    /// pass for each halving, each evaluation being this one pad's).
    #[test]
    fn a_pad_near_a_double_root_settles_on_its_loaded_root() {
        let pad = NearDoubleRoot {
            a: 1e12,
            eta0: 1e-6,
            k_rest: 1e-2,
        };
        // The loaded root: a e² = k_r (η₀ + e), e ≈ √(k_r η₀ / a) = 1e-10.
        let mut e: f64 = 1e-10;
        for _ in 0..50 {
            e = (pad.k_rest * (pad.eta0 + e) / pad.a).sqrt();
        }
        let root = pad.eta0 + e;
        let force_tol = 1e-12;
        let rate = TiltRate {
            a1: 0.0,
            start: 0.0,
            start_rate: 0.0,
        };
        let mut q = [0.0, 0.0, pad.eta0 + 1e3 * e];
        let mut qd = [0.0; 3];
        let settled = settle(&pad, 0, &mut q, &mut qd, 1.0, rate, force_tol, 0.0)
            .unwrap()
            .unwrap();
        assert!(settled.balanced && settled.evaluations <= 20, "{settled:?}");
        assert!(pad.moment(q[2]).abs() <= force_tol, "{}", pad.moment(q[2]));
        // The tilt error the force tolerance allows near the root: ε_F / Q'.
        let slope = 2.0 * pad.a * e - pad.k_rest;
        assert!(
            (q[2] - root).abs() <= 1.01 * force_tol / slope,
            "{} {root}",
            q[2]
        );
        // Plain Newton from the same start: as many evaluations.
        let mut eta = pad.eta0 + 1e3 * e;
        let mut plain = 0;
        while pad.moment(eta).abs() > force_tol {
            let d = (eta - pad.eta0).max(0.0);
            eta -= pad.moment(eta) / (2.0 * pad.a * d - pad.k_rest);
            plain += 1;
        }
        assert_eq!(plain, settled.evaluations - 1, "{settled:?}");
    }

    /// The Newmark rate follows the tilt; a bearing without a balance of its
    /// own gives `None`; a balance that cannot be met leaves the tilt where
    /// it started and says so.
    #[test]
    fn the_rate_follows_and_failures_leave_the_pad_alone() {
        #[derive(Debug)]
        struct NoBalance;
        impl Bearing for NoBalance {
            fn evaluate(
                &self,
                _: &[f64],
                _: &[f64],
                _: f64,
                _: &mut BearingEval,
            ) -> Result<(), BearingError> {
                Ok(())
            }
            fn is_linear(&self) -> bool {
                false
            }
        }
        let rate = TiltRate {
            a1: 400.0,
            start: 1e-6,
            start_rate: 2e-4,
        };
        let (mut q, mut qd) = ([0.0, 0.0, 3e-6], [0.0; 3]);
        assert_eq!(
            settle(&NoBalance, 0, &mut q, &mut qd, 1.0, rate, 1.0, 0.0).unwrap(),
            None
        );
        // Linear balance Q = 5 − 1e6 η (no rate term): root 5e-6.
        #[derive(Debug)]
        struct Spring;
        impl Bearing for Spring {
            fn evaluate(
                &self,
                _: &[f64],
                _: &[f64],
                _: f64,
                _: &mut BearingEval,
            ) -> Result<(), BearingError> {
                Ok(())
            }
            fn is_linear(&self) -> bool {
                false
            }
            fn internal_balance(
                &self,
                _: usize,
                q: &[f64],
                _: &[f64],
                _: f64,
            ) -> Option<Result<[f64; 3], BearingError>> {
                Some(Ok([5.0 - 1e6 * q[2], 1e6, 0.0]))
            }
        }
        let settled = settle(&Spring, 0, &mut q, &mut qd, 1.0, rate, 1e-9, 0.0)
            .unwrap()
            .unwrap();
        assert!(settled.balanced);
        assert!(
            (q[2] - 5e-6).abs() <= 1e-15 && (qd[2] - (400.0 * (q[2] - 1e-6) - 2e-4)).abs() <= 1e-18
        );
        // A balance that never vanishes: the pad left alone.
        #[derive(Debug)]
        struct Pushed;
        impl Bearing for Pushed {
            fn evaluate(
                &self,
                _: &[f64],
                _: &[f64],
                _: f64,
                _: &mut BearingEval,
            ) -> Result<(), BearingError> {
                Ok(())
            }
            fn is_linear(&self) -> bool {
                false
            }
            fn internal_balance(
                &self,
                _: usize,
                q: &[f64],
                _: &[f64],
                _: f64,
            ) -> Option<Result<[f64; 3], BearingError>> {
                Some(Ok([1.0 + q[2] * q[2], 1e-3, 0.0]))
            }
        }
        let (mut q, mut qd) = ([0.0, 0.0, 3e-6], [0.0, 0.0, 7.0]);
        let settled = settle(&Pushed, 0, &mut q, &mut qd, 1.0, rate, 1e-9, 0.0)
            .unwrap()
            .unwrap();
        assert_eq!(
            settled,
            Settled {
                evaluations: MAX_EVALUATIONS,
                balanced: false
            }
        );
        assert_eq!((q[2], qd[2]), (3e-6, 7.0));
    }
}
