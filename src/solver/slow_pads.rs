//! Pads whose tilt the condensed Newton only converges linearly: a pad the
//! film has just unloaded sits near a double root of its moment balance
//! (`Q_η ≈ a e² − k_r η` a distance `e` from the tilt where its film stops
//! carrying load, `k_r` the pivot's weak rest stiffness,
//! [`crate::bearing::tilting_pad`]), where Newton's increments only halve:
//! `e − (a e² − c)/(2 a e) ≈ e/2` for `e² ≫ c/a`. On the unit on brackets
//! (eight unpreloaded pads per guide bearing, nearly unloaded) that took 17
//! iterations a 2 ms step: four to bring the journals and loaded pads within
//! 1e-4 of the clearance, then one pad after the other halving its way down
//! from 1e-5 to 1e-8 while the journals had long converged (their increments
//! 1e-13 to 1e-20 of the clearance), often ending with a jump of 1e-3 onto
//! the pad's resting root. The modified Newton's Jacobian refresh on a
//! stalled residual (ratio > 0.7) cannot help: these steps run on the
//! condensed path, where every iteration already takes fresh Jacobians (the
//! rotor's seals and pull are not `cheap_forces`, so no chord iterations),
//! and it is the exact Newton that contracts at 1/2.
//!
//! **The rule** (Aitken's Δ², after Schröder's multiple-root Newton): when
//! the iteration as a whole contracts slowly, `δ_k/δ_{k−1} > SLOW` (0.3),
//! each pad whose own increments contracted steadily, `ρ = d_k/d_{k−1}` and
//! `d_{k−1}/d_{k−2}` both within `[RATIO_MIN, RATIO_MAX]` = [0.3, 0.9]
//! (same sign) and within `STEADY` (0.1) of each other, is moved on by the
//! fraction `θ = DAMPING` (0.5) of the tail the geometric series would still
//! add, `θ ρ/(1 − ρ) d_k`: at `ρ = 1/2` the step becomes 1.5 `d_k`, short of
//! Schröder's `m d_k` for a root of multiplicity `m = 1/(1 − ρ)`. Short of
//! it so that the iterate stays on the side of the root it came from: there
//! the film still carries the pad, while beyond the unloading tilt only the
//! rest stiffness is left and Newton from there throws the pad onto its
//! other (resting) root. On `a e² − c` the rule takes `e` to about `e/4`
//! instead of `e/2`. A pad whose increment turns back after a move has
//! overshot: the rule leaves it alone for the rest of the step. Only the
//! iterate moves; the iteration after a move is judged by the plain
//! criterion (increment within the tolerance), since its contraction says
//! nothing about the error left.
//!
//! Measured on the unit on brackets (field on, 300 rpm, 10 s at 2 ms):
//! 84 034 → 72 730 iterations, no step halving; the journal orbits differ
//! from the old ones by 8.2e-4 of their range, and from a run of the old
//! code at a Newton tolerance of 1e-10 by 6.3e-4, what the old code at 1e-8
//! differs from it by (6.3e-4). `θ = 0.9` took 63 588 iterations but left
//! 4.7e-3, `θ = 0.75` 66 173 and 2.6e-3: moves that land pads past their
//! unloading tilt pick the other root, which the tolerance cannot tell apart
//! but the pads' first-order dynamics carry on. Where the iterations
//! contract fast (every other shipped model in steady running) the rule
//! never fires and nothing changes, bit for bit; run-ups from standstill,
//! whose pads are nearly unloaded at low speed, fire it (the hydro unit's
//! moves by 7.2e-4 of its range, within the 1.05e-2 its old run at a Newton
//! tolerance of 1e-8 lies from the same run at 1e-11: `docs/solver.md`).

/// Contraction `δ_k/δ_{k−1}` of the whole iteration above which it is slow.
const SLOW: f64 = 0.3;
/// Range of a pad's own contraction `d_k/d_{k−1}` taken as linear convergence.
const RATIO_MIN: f64 = 0.3;
const RATIO_MAX: f64 = 0.9;
/// Fraction of the geometric tail `ρ/(1 − ρ) d_k` added (module docs).
const DAMPING: f64 = 0.5;

/// Largest change between a pad's last two contractions for its
/// convergence to count as steady (a multiple root's ratio is constant; near a
/// simple root it falls towards zero).
const STEADY: f64 = 0.1;

/// The previous increment and contraction of every pad coordinate within a
/// step, and whether the rule moved it last or has overshot with it.
#[derive(Debug)]
pub(super) struct SlowPads {
    previous: Vec<f64>,
    ratio: Vec<f64>,
    moved: Vec<bool>,
    barred: Vec<bool>,
}

impl SlowPads {
    /// Buffers for `n` pad coordinates.
    pub fn new(n: usize) -> Self {
        Self {
            previous: vec![0.0; n],
            ratio: vec![f64::NAN; n],
            moved: vec![false; n],
            barred: vec![false; n],
        }
    }

    /// Start the iterations of a step: no increment to compare with.
    pub fn reset(&mut self) {
        self.previous.fill(0.0);
        self.ratio.fill(f64::NAN);
        self.moved.fill(false);
        self.barred.fill(false);
    }

    /// After the plain Newton increments `d` of the pad coordinates `p` have
    /// been applied (and did not converge), with the whole iteration having
    /// contracted by `contraction`, move each pad converging steadily and
    /// linearly on by its extrapolated tail (module docs). A pad whose
    /// increment turns back after such a move has overshot its root: the
    /// rule leaves it alone for the rest of the step. Returns how many pads
    /// moved.
    pub fn extrapolate(&mut self, d: &[f64], p: &mut [f64], contraction: f64) -> usize {
        let mut count = 0;
        let slow = contraction > SLOW && contraction.is_finite();
        let linear = |r: f64| (RATIO_MIN..=RATIO_MAX).contains(&r);
        for (i, (d, p)) in d.iter().zip(p.iter_mut()).enumerate() {
            let rho = d / self.previous[i];
            if self.moved[i] && rho.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
                self.barred[i] = true;
            }
            let steady =
                linear(rho) && linear(self.ratio[i]) && (rho - self.ratio[i]).abs() <= STEADY;
            self.moved[i] = slow && steady && !self.barred[i];
            if self.moved[i] {
                *p += DAMPING * rho / (1.0 - rho) * d;
                count += 1;
            }
            self.previous[i] = *d;
            self.ratio[i] = rho;
        }
        count
    }
}

#[cfg(test)]
mod tests {
    use super::SlowPads;

    /// Newton on the double root of `a e² − c` halves `e`; with the rule the
    /// pad reaches the tolerance in fewer iterations, from the side it came
    /// from (`e > 0` throughout).
    #[test]
    fn a_double_root_converges_in_a_few_iterations() {
        let (a, c): (f64, f64) = (1.0, 1e-12); // root at e* = 1e-6
        let root = (c / a).sqrt();
        let solve = |accelerate: bool| {
            let mut slow = SlowPads::new(1);
            let mut e = [1e-2];
            let mut last = f64::INFINITY;
            for k in 1..200 {
                let d = [-(a * e[0] * e[0] - c) / (2.0 * a * e[0])];
                e[0] += d[0];
                assert!(e[0] > 0.0);
                if d[0].abs() <= 1e-8 * root {
                    return k;
                }
                let contraction = d[0].abs() / last;
                last = d[0].abs();
                if accelerate {
                    slow.extrapolate(&d, &mut e, contraction);
                }
            }
            panic!("no convergence");
        };
        let (plain, fast) = (solve(false), solve(true));
        println!("plain {plain}, accelerated {fast}");
        // Measured: 18 and 15 (a move every third iteration: the one after
        // a move contracts by 1/4, and two steady ratios are needed again).
        assert!(plain >= 17, "{plain}");
        assert!(fast <= 15, "{fast}");
    }

    /// Fast (quadratic) contraction never fires the rule; nor does a pad
    /// whose increment changed sign.
    #[test]
    fn fast_or_alternating_increments_are_left_alone() {
        let mut slow = SlowPads::new(2);
        let mut p = [1.0, 1.0];
        assert_eq!(slow.extrapolate(&[1e-3, 1e-3], &mut p, f64::INFINITY), 0);
        assert_eq!(slow.extrapolate(&[1e-6, 5e-4], &mut p, 1e-3), 0);
        assert_eq!(slow.extrapolate(&[5e-7, -2.5e-4], &mut p, 0.5), 0);
        // The second steady halving moves the pad, not the alternating one.
        assert_eq!(slow.extrapolate(&[2.5e-7, 1.25e-4], &mut p, 0.5), 1);
        assert!(
            (p[0] - (1.0 + 0.5 * 2.5e-7)).abs() < 1e-18 && p[1] == 1.0,
            "{p:?}"
        );
        // Overshot (the increment turns back): barred for the step.
        assert_eq!(slow.extrapolate(&[-1e-8, -6e-5], &mut p, 0.5), 0);
        assert_eq!(slow.extrapolate(&[-5e-9, 3e-5], &mut p, 0.5), 0);
        assert_eq!(slow.extrapolate(&[-2.5e-9, -1.5e-5], &mut p, 0.5), 0);
        slow.reset();
        assert_eq!(slow.extrapolate(&[1e-6, 0.0], &mut p, 0.5), 0);
    }
}
