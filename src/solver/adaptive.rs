//! Accuracy-controlled step size ([`SolverOptions::local_error_tolerance`]
//! `> 0`): each Newmark step is judged by the Zienkiewicz–Xie estimate of its
//! local displacement error and the next step is sized from it.
//!
//! # Estimate
//! For the average-acceleration scheme (β = 1/4) the local error of the
//! displacement is `e = (β − 1/6) h² (üₙ₊₁ − üₙ) = h²/12 (üₙ₊₁ − üₙ)`
//! (Zienkiewicz & Xie, "A simple error estimator and adaptive time stepping
//! procedure for dynamic analysis", Earthquake Eng. Struct. Dyn. 20, 1991).
//! The step is judged by it relative to the step's own displacement
//! increment, over the coordinates a user observes ([`observed_dofs`]:
//! journals, housings, probes, unbalance planes):
//!
//! `η = ‖e‖∞ / max(‖uₙ₊₁ − uₙ‖∞, 10⁻⁶ L)`,
//!
//! `L` the smallest bearing clearance. For a motion at angular frequency ω,
//! `η → (ωh)²/12`, the relative period error of the scheme at that frequency:
//! the tolerance is the relative frequency (phase-per-cycle) error allowed to
//! the motion that dominates the step. A motion below `10⁻⁶ L` per step is not
//! resolved for its own sake. The twist of a torque-driven shaft is not in
//! `η` (its rigid-body rotation dominates any increment); its step is the
//! lateral one.
//!
//! # Control
//! A step with `η > tol` is rejected (the state is restored) and retried at
//! `h · max(0.2, 0.9 √(tol/η))`. Each accepted step allows
//! `a = 0.9 √(tol/η)` (`η ∝ h²`): below 1 the proposal for the next call
//! shrinks to `h · a`; growth is decided over a window, the accepted steps
//! since the last decision, every [`GROWTH_WINDOW`] of them and at the
//! call's end: the proposal grows to `h · min(2, a_min)`, `a_min` the least
//! allowance of the window, when that is at least 1.25 (so a steady run
//! keeps one step and one factorization). A step that fails (Newton, the
//! torsional Newton of a torque-driven shaft, a bearing) is undone and
//! halved. Steps never exceed [`SolverOptions::time_step`] and never fall
//! below `time_step · 2^-max_step_cuts` (nor [`SolverOptions::MIN_SPAN`]): a
//! step at that floor is accepted whatever its estimate. Each call of
//! [`Simulator::advance_to`] ends exactly on its target: the span left is
//! split into equal steps no longer than the proposal, and that plan is held
//! until a step is rejected or fails, or the proposal grows; a shrink of an
//! accepted step waits for the next plan.
//!
//! Why the window and the held plan (issue 51): the estimate of an
//! undamped or lightly damped vibration swings over its cycle, so growing
//! on one step's allowance grew into the part of the cycle that rejects,
//! and re-splitting the span at every shrink gave each step a size of its
//! own, each a factorization. The classic disk rotor at 1000 rpm, 4 s with
//! communication every 5 ms, took 5578 steps, 1245 rejections and 3542
//! factorizations (+442 recalled); it takes 7678, 173 and 449 (+163); the
//! train of rotors at 3000 rpm 8942, 598 and 3639 (+398) against 9869, 20
//! and 87 (+95); both closer to a 0.05 ms-step run than before (largest
//! journal difference over the last 2 s 0.146 against 0.175 of the orbit,
//! the undamped rotor's drifting phase, and 2.5e-3 against 2.7e-3).
//! (`tests/adaptive.rs::a_vibration_does_not_make_the_steps_chatter`.)
//! The proposal is part of the state ([`SimState::step_proposal`]) and the
//! window and plan belong to one call, so a restored state continues bit
//! for bit.

use crate::units::Short;

use super::error::SolverError;
use super::observer::{StepFlow, StepObserver};
use super::options::SolverOptions;
use super::simulator::Simulator;
use super::state::SimState;

/// Safety factor on the step the estimate allows.
const SAFETY: f64 = 0.9;
/// Largest growth of the step from one step to the next.
const MAX_GROWTH: f64 = 2.0;
/// Smallest shrink of a rejected step.
const MAX_SHRINK: f64 = 0.2;
/// A proposal grows only past this factor over the step in hand.
const GROW_DEAD_BAND: f64 = 1.25;
/// Displacement increments below this fraction of the clearance are judged
/// against it.
const MOTION_FLOOR: f64 = 1e-6;
/// Accepted steps whose least allowance decides a growth (or the call's end,
/// if sooner).
const GROWTH_WINDOW: usize = 8;

impl SimState {
    /// Copy every field of `other` (of the same rotor) into `self` without
    /// allocating (`Vec::clone_from` reuses the storage); the exhaustive
    /// pattern makes a field added to the state a compile error here.
    pub(super) fn copy_from(&mut self, other: &SimState) {
        let SimState {
            time,
            u,
            ud,
            udd,
            p,
            pd,
            pdd,
            spin_angle,
            speed,
            speed_rate,
            speed_time,
            unbalance,
            unbalance_rate,
            unbalance_phase,
            loads,
            load_rates,
            twist,
            twist_rate,
            twist_accel,
            twist_torque,
            stuck,
            factor_step,
            factor_speed,
            udd_previous,
            step_proposal,
            contact_reported,
            table_warned,
            static_load,
            pad_balancing,
            chord_pause,
            harmonic_phase,
            harmonic_frequency,
        } = other;
        for (dst, src) in [
            (&mut self.u, u),
            (&mut self.ud, ud),
            (&mut self.udd, udd),
            (&mut self.p, p),
            (&mut self.pd, pd),
            (&mut self.pdd, pdd),
            (&mut self.unbalance, unbalance),
            (&mut self.unbalance_rate, unbalance_rate),
            (&mut self.unbalance_phase, unbalance_phase),
            (&mut self.loads, loads),
            (&mut self.load_rates, load_rates),
            (&mut self.twist, twist),
            (&mut self.twist_rate, twist_rate),
            (&mut self.twist_accel, twist_accel),
            (&mut self.twist_torque, twist_torque),
            (&mut self.udd_previous, udd_previous),
            (&mut self.contact_reported, contact_reported),
            (&mut self.table_warned, table_warned),
            (&mut self.static_load, static_load),
            (&mut self.harmonic_phase, harmonic_phase),
            (&mut self.harmonic_frequency, harmonic_frequency),
        ] {
            dst.clone_from(src);
        }
        for (dst, src) in [
            (&mut self.time, time),
            (&mut self.spin_angle, spin_angle),
            (&mut self.speed, speed),
            (&mut self.speed_rate, speed_rate),
            (&mut self.speed_time, speed_time),
            (&mut self.stuck, stuck),
            (&mut self.factor_step, factor_step),
            (&mut self.factor_speed, factor_speed),
            (&mut self.step_proposal, step_proposal),
            (&mut self.pad_balancing, pad_balancing),
            (&mut self.chord_pause, chord_pause),
        ] {
            *dst = *src;
        }
    }
}

impl Simulator {
    /// The coordinates (free DOF indices) the local error estimate of
    /// accuracy-controlled steps watches ([`observed_dofs`]).
    pub fn observed_coordinates(&self) -> &[usize] {
        &self.error_dofs
    }

    /// The estimate `η` of the step just taken from `self.step_start` to the
    /// state in hand, of size `h` (see the module docs).
    pub(super) fn local_error(&self, h: f64) -> f64 {
        let (a, b) = (&self.step_start, &self.state);
        // The acceleration change over the mean of two steps where the step
        // before is known (module docs: unresolved modes alternate); the
        // previous accelerations are empty before the first such step.
        let two_step = a.udd_previous.len() == a.udd.len();
        let (mut accel, mut motion) = (0.0_f64, 0.0_f64);
        for &i in &self.error_dofs {
            let change = if two_step {
                0.5 * (b.udd[i] - a.udd_previous[i])
            } else {
                b.udd[i] - a.udd[i]
            };
            accel = accel.max(change.abs());
            motion = motion.max((b.u[i] - a.u[i]).abs());
        }
        h * h / 12.0 * accel / motion.max(MOTION_FLOOR * self.sites.length_scale)
    }

    /// Advance to `t_end` (checked by [`Simulator::advance_to`]) in steps sized
    /// by the local error estimate (module docs).
    pub(super) fn advance_adaptive(
        &mut self,
        t_end: f64,
        mut observer: Option<StepObserver<'_>>,
    ) -> Result<(), SolverError> {
        let tol = self.options.local_error_tolerance;
        let largest = self.options.time_step;
        let smallest =
            (largest * 0.5f64.powi(self.options.max_step_cuts as i32)).max(SolverOptions::MIN_SPAN);
        let mut proposal = match self.state.step_proposal {
            p if p > 0.0 => p.clamp(smallest, largest),
            _ => largest,
        };
        let mut attempts = 0usize;
        let cuts_before = self.stats.step_cuts;
        // The equal steps the span left is split into, held while they pass.
        let mut planned: Option<f64> = None;
        // The smallest growth the accepted steps since the last change allow,
        // and how many they are.
        let mut window = (0usize, f64::INFINITY);
        while self.state.time < t_end {
            let remaining = t_end - self.state.time;
            let count = match planned {
                Some(count) => count,
                None => (remaining / proposal - 1e-9).ceil().max(1.0),
            };
            planned = Some(count);
            let last = count == 1.0;
            let h = if last { remaining } else { remaining / count };
            attempts += 1;
            if attempts > SolverOptions::MAX_STEPS_PER_CALL {
                return Err(SolverError::Budget(format!(
                    "{attempts} step attempts by t = {} s, more than the {} one call may take: the local error tolerance {} needs steps near {} s",
                    Short(self.state.time),
                    SolverOptions::MAX_STEPS_PER_CALL,
                    Short(tol),
                    Short(h)
                )));
            }
            self.step_start.copy_from(&self.state);
            let floor = h <= smallest * (1.0 + 1e-9);
            // A step that fails (Newton, the torsional Newton, a bearing) is
            // tried smaller; at the floor its error is the call's.
            let outcome = match self.try_step(h) {
                Ok(outcome) => outcome,
                Err(e) if floor => {
                    self.restore_step_start();
                    return Err(e);
                }
                Err(_) => Some(f64::INFINITY),
            };
            if let Some(residual) = outcome {
                self.restore_step_start();
                if floor {
                    return Err(SolverError::NotConverged {
                        time: self.state.time,
                        step: h,
                        cuts: self.options.max_step_cuts,
                        residual,
                    });
                }
                self.stats.step_cuts += 1;
                if self.stats.step_cuts - cuts_before > SolverOptions::MAX_CUTS_PER_CALL {
                    return Err(SolverError::Budget(format!(
                        "{} step halvings by t = {} s, more than the {} one call may spend: the bearings keep Newton from converging",
                        self.stats.step_cuts - cuts_before,
                        Short(self.state.time),
                        SolverOptions::MAX_CUTS_PER_CALL
                    )));
                }
                proposal = (0.5 * h).max(smallest);
                planned = None;
                window = (0, f64::INFINITY);
                continue;
            }
            let eta = self.local_error(h);
            let allowed = if eta > 0.0 {
                SAFETY * (tol / eta).sqrt()
            } else {
                MAX_GROWTH
            };
            if eta > tol && !floor {
                self.restore_step_start();
                self.stats.steps -= 1;
                self.stats.rejections += 1;
                proposal = (h * allowed.max(MAX_SHRINK)).max(smallest);
                planned = None;
                window = (0, f64::INFINITY);
                continue;
            }
            if last {
                self.state.time = t_end;
            }
            self.state.udd_previous.clone_from(&self.step_start.udd);
            planned = planned.map(|c| c - 1.0);
            window = (window.0 + 1, window.1.min(allowed));
            if last || window.0 >= GROWTH_WINDOW {
                let (_, least) = window;
                if least >= GROW_DEAD_BAND {
                    proposal = proposal.max(h * least.min(MAX_GROWTH)).min(largest);
                    planned = None;
                }
                window = (0, f64::INFINITY);
            }
            if allowed < 1.0 {
                proposal = proposal.min(h * allowed).max(smallest);
            }
            self.state.step_proposal = proposal;
            let began = !last && self.contact_began_now();
            let flow = self.observe(&mut observer);
            if began || (!last && flow == StepFlow::Stop) {
                return Ok(());
            }
        }
        Ok(())
    }

    /// Undo a step: the state it started from, with the factorization in hand
    /// recorded in it.
    fn restore_step_start(&mut self) {
        self.state.copy_from(&self.step_start);
        self.record_factor();
        // The contact warnings of the undone step go with it (its state
        // raises them again where the step is taken anew).
        self.drop_contact_warnings_after(self.state.time);
    }
}
