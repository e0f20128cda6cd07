//! Newmark average-acceleration stepping (β = 1/4, γ = 1/2) and step control:
//! equal internal steps up to a target time, halving of failed steps, the
//! predictor, the Newmark rates and the residuals of a step (see
//! [`crate::solver`] for the equations).

use crate::fe::{DOF_X, DOF_Y};
use crate::linalg::BandMatrix;
use crate::units::{RAD_S_TO_RPM, Short};

use super::error::SolverError;
use super::factor_work::Factor;
use super::norm::inf_norm;
use super::observer::{StepFlow, StepObserver};
use super::options::SolverOptions;
use super::simulator::Simulator;

/// Where the displacement of a step comes from when its rates are formed.
#[derive(Debug, Clone, Copy)]
pub(super) enum Displacement {
    /// `newmark.u` as it stands (the Newton iterate).
    Iterate,
    /// `newmark.lin` (the condensed step's `A⁻¹ b`, corrected in place).
    Linear,
    /// `newmark.lin + newmark.mv` (`A⁻¹ b + A⁻¹ E F_b` by a second solve).
    LinearPlusCorrection,
}

/// How far the curvature term of a pad tilt's predictor may exceed its rate
/// term before it is left out ([`pad_predictor`]).
const PAD_CURVATURE_LIMIT: f64 = 10.0;

/// The predictor of a pad tilt, `η + h η̇ + h²/2 η̈`, without its last term
/// where that exceeds [`PAD_CURVATURE_LIMIT`] times the one before. A pad the
/// film has just unloaded has massless first-order dynamics whose `η̈` the
/// average-acceleration scheme leaves ringing; extrapolated, it throws the
/// start far from the pad's root, which sits near a double root of its moment
/// balance, where Newton only halves the error each iteration. A loaded pad
/// following the journal's orbit at `ω` has the ratio `ωh/2` (0.08 at 300 rpm
/// and 5 ms) and keeps its second-order predictor, bit for bit. On the unit on
/// brackets at 5 ms: 15 477 → 12 992 iterations in 4 s and no step halvings
/// instead of 3 (`tests/pad_predictor.rs`); the three-guide unit is unchanged.
fn pad_predictor(tilt: f64, rate: f64, acceleration: f64, h: f64) -> f64 {
    let (first, second) = (h * rate, 0.5 * h * h * acceleration);
    if second.abs() <= PAD_CURVATURE_LIMIT * first.abs() {
        tilt + first + second
    } else {
        tilt + first
    }
}

/// Newmark rates at the end of a step of size `h` that moves a coordinate
/// from `u0` (rate `ud0`, acceleration `udd0`) to `u`:
/// `u̇ = a1 (u − u₀) − u̇₀`, `ü = a0 (u − u₀) − a2 u̇₀ − ü₀`, with
/// `[a0, a1, a2] = [4/h², 2/h, 4/h]`.
#[inline]
pub(super) fn newmark_rates(
    [a0, a1, a2]: [f64; 3],
    u: f64,
    u0: f64,
    ud0: f64,
    udd0: f64,
) -> (f64, f64) {
    let d = u - u0;
    (a1 * d - ud0, a0 * d - a2 * ud0 - udd0)
}

impl Simulator {
    /// Newmark rates at the iterate `newmark.u`, `newmark.p` of a step of size `h`.
    pub(super) fn update_rates(&mut self, h: f64) {
        self.set_displacement_and_rates(h, Displacement::Iterate);
    }

    /// Set `newmark.u` from `from` and form the Newmark rates of the step,
    /// rotor and pads, in one pass: `u̇ = a1 (u − uₙ) − u̇ₙ`,
    /// `ü = a0 (u − uₙ) − a2 u̇ₙ − üₙ` (`a0 = 4/h²`, `a1 = 2/h`, `a2 = 4/h`).
    pub(super) fn set_displacement_and_rates(&mut self, h: f64, from: Displacement) {
        let (a0, a1, a2) = (4.0 / (h * h), 2.0 / h, 4.0 / h);
        let (s, w) = (&self.state, &mut self.newmark);
        for i in 0..s.u.len() {
            let u = match from {
                Displacement::Iterate => w.u[i],
                Displacement::Linear => w.lin[i],
                Displacement::LinearPlusCorrection => w.lin[i] + w.mv[i],
            };
            w.u[i] = u;
            (w.ud[i], w.udd[i]) = newmark_rates([a0, a1, a2], u, s.u[i], s.ud[i], s.udd[i]);
        }
        for i in 0..s.p.len() {
            (w.pd[i], w.pdd[i]) = newmark_rates([a0, a1, a2], w.p[i], s.p[i], s.pd[i], s.pdd[i]);
        }
    }

    /// Linear part of the dynamic residual at the iterate, `newmark.lin = f − M ü −
    /// (C + Ω G) u̇ − K u` (rates updated first); returns the largest force term (N).
    pub(super) fn linear_residual(&mut self, h: f64, speed1: f64) -> f64 {
        self.update_rates(h);
        let w = &mut self.newmark;
        w.lin.copy_from_slice(&w.f_ext);
        let mut scale = inf_norm(&w.f_ext);
        let terms: [(&BandMatrix<f64>, f64, u8); 4] = [
            (&self.rotor.mass, 1.0, 2),
            (&self.rotor.damping, 1.0, 1),
            (&self.rotor.gyroscopic, speed1, 1),
            (&self.rotor.stiffness, 1.0, 0),
        ];
        for (matrix, coef, which) in terms {
            if coef == 0.0 {
                continue;
            }
            let x = match which {
                2 => &w.udd,
                1 => &w.ud,
                _ => &w.u,
            };
            matrix.mul_vec(x, &mut w.mv);
            let mut norm: f64 = 0.0;
            for (r, m) in w.lin.iter_mut().zip(&w.mv) {
                *r -= coef * m;
                norm = norm.max((coef * m).abs());
            }
            scale = scale.max(norm);
        }
        scale
    }

    /// Full residual `newmark.r = newmark.lin + E F_b` and pad residual
    /// `newmark.rp` with the bearings evaluated at the iterate; returns it
    /// relative to the force scale (`scale` grows with the bearing forces).
    pub(super) fn residual_with_bearings(
        &mut self,
        t1: f64,
        speed1: f64,
        scale: &mut f64,
    ) -> Result<f64, SolverError> {
        let w = &mut self.newmark;
        w.r.copy_from_slice(&w.lin);
        let bearings = self
            .sites
            .add_forces(&w.u, &w.ud, &w.p, &w.pd, speed1, t1, &mut w.r, &mut w.rp)?;
        *scale = scale.max(bearings).max(f64::MIN_POSITIVE);
        Ok(inf_norm(&w.r).max(inf_norm(&w.rp)) / *scale)
    }

    /// External force at time `t` (s) and spin angle `spin_angle` (rad) into
    /// `newmark.f_ext`: gravity plus, per plane, the unbalance
    /// `m e (Ω² cos φ + Ω̇ sin φ, Ω² sin φ − Ω̇ cos φ)` times the ramp `1 − e^{−t/τ}`,
    /// plus the external static, harmonic and port forces of the load inputs
    /// ([`Rotor::add_loads_at`](crate::rotor::Rotor::add_loads_at)).
    pub(super) fn external_force(&mut self, t: f64, spin_angle: f64) {
        let w = &mut self.newmark;
        w.f_ext.fill(0.0);
        if self.options.gravity {
            w.f_ext.copy_from_slice(&self.rotor.gravity_load);
        }
        let speed = self.state.speed + self.state.speed_rate * (t - self.state.speed_time);
        let rate = self.state.speed_rate;
        let ramp = if self.options.unbalance_ramp_time > 0.0 {
            1.0 - (-t / self.options.unbalance_ramp_time).exp()
        } else {
            1.0
        };
        let since = t - self.state.speed_time;
        for (k, plane) in self.rotor.model.unbalances.iter().enumerate() {
            let me =
                (self.state.unbalance[k] + self.state.unbalance_rate[k] * since).max(0.0) * ramp;
            // A torque-driven shaft: the plane's node turns with its own
            // angle, speed and acceleration.
            let (angle, speed, rate) = match w.plane_motion.get(k) {
                Some(&[a, w, r]) => (a, w, r),
                None => (spin_angle, speed, rate),
            };
            let (s, c) = (angle + self.state.unbalance_phase[k]).sin_cos();
            let fx = me * (speed * speed * c + rate * s);
            let fy = me * (speed * speed * s - rate * c);
            if let Some(i) = self.rotor.dofs.free(plane.node, DOF_X) {
                w.f_ext[i] += fx;
            }
            if let Some(i) = self.rotor.dofs.free(plane.node, DOF_Y) {
                w.f_ext[i] += fy;
            }
        }
        if !self.state.loads.is_empty() {
            for (v, (l, r)) in w
                .load_values
                .iter_mut()
                .zip(self.state.loads.iter().zip(&self.state.load_rates))
            {
                *v = l + r * since;
            }
            let harmonic = (
                self.state.harmonic_phase.as_slice(),
                self.state.harmonic_frequency.as_slice(),
            );
            self.rotor
                .add_loads_at(&w.load_values, Some(harmonic), t, spin_angle, &mut w.f_ext);
        } else {
            // The preload of linear bearings and pedestals set off the axis
            // (in `add_loads_at` with the load inputs; nothing without offsets).
            self.rotor.add_offset_loads(&mut w.f_ext);
        }
    }

    /// Advance to time `t_end` (s) in equal internal steps no longer than the
    /// configured time step; a span shorter than [`SolverOptions::MIN_SPAN`]
    /// is refused.
    pub fn advance_to(&mut self, t_end: f64) -> Result<(), SolverError> {
        self.advance(t_end, None)
    }

    /// [`Simulator::advance_to`], with the observer of each internal step
    /// when there is one ([`super::observer`]).
    pub(super) fn advance(
        &mut self,
        t_end: f64,
        mut observer: Option<StepObserver<'_>>,
    ) -> Result<(), SolverError> {
        if !t_end.is_finite() {
            return Err(SolverError::Input(format!(
                "target time {} is not finite",
                Short(t_end)
            )));
        }
        let span = t_end - self.state.time;
        if span < 0.0 {
            return Err(SolverError::Input(format!(
                "cannot step backwards from {} s to {} s",
                Short(self.state.time),
                Short(t_end)
            )));
        }
        if span == 0.0 {
            return Ok(());
        }
        if span < SolverOptions::MIN_SPAN * (1.0 - 1e-6) {
            return Err(SolverError::Input(format!(
                "a step of {} s is shorter than the {} s the integrator resolves (round-off in the Newmark accelerations grows as 1/h²)",
                Short(span),
                Short(SolverOptions::MIN_SPAN)
            )));
        }
        let steps = (span / self.options.time_step - 1e-9).ceil().max(1.0);
        if steps > SolverOptions::MAX_STEPS_PER_CALL as f64 {
            return Err(SolverError::Budget(format!(
                "advancing {} s in internal steps of at most {} s takes {} steps, more than the {} one call may take: advance in shorter spans or raise the time step",
                Short(span),
                Short(self.options.time_step),
                Short(steps),
                SolverOptions::MAX_STEPS_PER_CALL
            )));
        }
        let max = self.rotor.model.max_speed;
        let end_speed = self.speed_at(t_end);
        // A torque-driven shaft has no ramp: each step checks its own speed
        // (`Simulator::check_overspeed`).
        if self.torsion.is_none() && end_speed.abs() > max {
            return Err(SolverError::Budget(format!(
                "the speed ramp reaches {} rpm at {} s, beyond the model's max_speed_rpm ({} rpm)",
                Short(end_speed * RAD_S_TO_RPM),
                Short(t_end),
                Short(max * RAD_S_TO_RPM)
            )));
        }
        // Speeds vary linearly within a call: its ends bound them.
        let start_speed = self.speed_at(self.state.time);
        let now = self.state.time;
        let warned = &mut self.state.table_warned;
        self.warnings
            .check_tables(&self.rotor, warned, start_speed, now);
        self.warnings
            .check_tables(&self.rotor, warned, end_speed, t_end);
        self.contact_onset_start();
        if self.options.local_error_tolerance > 0.0 {
            return self.advance_adaptive(t_end, observer);
        }
        let count = steps as usize;
        let h = span / count as f64;
        let cuts_before = self.stats.step_cuts;
        for k in 0..count {
            self.step_with_cuts(h, 0)?;
            let last = k + 1 == count;
            if last {
                self.state.time = t_end;
            }
            let began = !last && self.contact_began_now();
            let flow = self.observe(&mut observer);
            if began || (!last && flow == StepFlow::Stop) {
                return Ok(());
            }
            let cuts = self.stats.step_cuts - cuts_before;
            if cuts > SolverOptions::MAX_CUTS_PER_CALL {
                return Err(SolverError::Budget(format!(
                    "{cuts} step halvings by t = {} s, more than the {} one call may spend: the bearings keep Newton from converging",
                    self.state.time,
                    SolverOptions::MAX_CUTS_PER_CALL
                )));
            }
        }
        Ok(())
    }

    /// A step of size `h` (s), halved recursively on failure down to
    /// `max_step_cuts` halvings (`depth` counts the halvings so far), and
    /// never below [`SolverOptions::MIN_SPAN`].
    ///
    /// A step that fails with an error (a singular matrix, a bearing or the
    /// torsional Newton giving up, an overspeed) is cut like one whose Newton
    /// did not converge, as accuracy-controlled steps do; at the last
    /// halving its error is the call's.
    fn step_with_cuts(&mut self, h: f64, depth: usize) -> Result<(), SolverError> {
        // Never below the shortest span the integrator resolves.
        let floor = depth >= self.options.max_step_cuts || 0.5 * h < SolverOptions::MIN_SPAN;
        let outcome = match self.try_step(h) {
            Ok(outcome) => outcome,
            Err(e) if floor => return Err(e),
            Err(_) => Some(f64::INFINITY),
        };
        match outcome {
            None => Ok(()),
            Some(residual) => {
                if floor {
                    return Err(SolverError::NotConverged {
                        time: self.state.time,
                        step: h,
                        cuts: depth,
                        residual,
                    });
                }
                self.stats.step_cuts += 1;
                self.step_with_cuts(h / 2.0, depth + 1)?;
                self.step_with_cuts(h / 2.0, depth + 1)
            }
        }
    }

    /// Predictor `u + h u̇ + h²/2 ü` into `newmark.u` and `newmark.p` (the pad
    /// tilts by [`pad_predictor`]): the
    /// condensed Newton only needs it on the journal coordinates (relative to
    /// their housings, into `condensed.j`) and the pads (`journals_only`).
    pub(super) fn predict(&mut self, h: f64, journals_only: bool) {
        let (s, w) = (&self.state, &mut self.newmark);
        let predict = |i: usize| s.u[i] + h * s.ud[i] + 0.5 * h * h * s.udd[i];
        if journals_only {
            // The journal relative to its housing, as the bearings see it.
            for (j, c) in self.condensed.j.iter_mut().zip(&self.sites.coordinates) {
                *j = match c.housing {
                    None => predict(c.journal),
                    Some(h) => predict(c.journal) - predict(h),
                };
            }
        } else {
            for (i, u) in w.u.iter_mut().enumerate() {
                *u = predict(i);
            }
        }
        for i in 0..s.p.len() {
            w.p[i] = pad_predictor(s.p[i], s.pd[i], s.pdd[i], h);
        }
    }

    /// One Newmark step of size `h`. `Ok(None)`: converged, state advanced;
    /// `Ok(Some(residual))`: Newton failed, state untouched. A bearing error
    /// (journal beyond the clearance) at an iterate counts as a failure of the
    /// step, so a smaller step is tried before giving up. A torque-driven
    /// shaft steps its twist and its lateral motion together
    /// ([`Simulator::try_coupled_step`]).
    pub(super) fn try_step(&mut self, h: f64) -> Result<Option<f64>, SolverError> {
        // Sub-steps of communication intervals differ from the factored step by
        // the round-off of the time grid (1e-11 relative at t = 20 s): take the
        // factored step itself (the grid moves by ~1e-15 s, and `advance_to`
        // ends exactly on the communication point).
        let h = match self.factor.as_ref() {
            Some(f) if (f.step - h).abs() <= 1e-9 * h => f.step,
            _ => h,
        };
        if self.torsion.is_some() {
            return self.try_coupled_step(h);
        }
        let outcome = self.solve_lateral_step(h)?;
        if outcome.is_none() {
            self.commit_lateral_step(h);
        }
        Ok(outcome)
    }

    /// The lateral Newmark step of size `h` from the current state at the
    /// current speed profile, into `newmark` (the state is not touched).
    pub(super) fn solve_lateral_step(&mut self, h: f64) -> Result<Option<f64>, SolverError> {
        let t1 = self.state.time + h;
        let speed0 = self.speed_at(self.state.time);
        let speed1 = self.speed_at(t1);
        let spin1 = self.state.spin_angle + 0.5 * (speed0 + speed1) * h;
        self.external_force(t1, spin1);
        self.sites
            .begin_step(2.0 / h, &self.state.pd, &self.state.pdd);
        let mut factor = self.factor.take();
        let exact = self.prepare_factor(h, speed1, &mut factor);
        self.predict(h, matches!(exact, Ok(true)));
        let mut outcome = match exact {
            Ok(true) => match factor.as_ref() {
                Some(f) => self.newton_condensed(h, t1, speed1, f, false),
                None => Err(SolverError::Input("internal: no factorization".into())),
            },
            Ok(false) => self.newton(h, t1, speed1, &mut factor),
            Err(e) => Err(e),
        };
        if std::mem::take(&mut self.condensed.gyroscopic_excess) {
            // The step again, on a factorization at its own speed.
            outcome = self.exact_factor_step(h, t1, speed1, &mut factor, false);
        }
        // Plain Newton failed: the damped Newton gets the step before it is cut.
        let outcome = match outcome {
            Ok(Some(_)) => self.retry_damped(h, t1, speed1, &mut factor),
            other => other,
        };
        self.factor = factor;
        self.record_factor();
        self.sites.end_step();
        outcome
    }

    /// The condensed step from the predictor on a factorization made at
    /// exactly `speed1` (refactored into `factor` if the one in hand is
    /// not), `damped` or plain (`Simulator::newton_condensed`).
    pub(super) fn exact_factor_step(
        &mut self,
        h: f64,
        t1: f64,
        speed1: f64,
        factor: &mut Option<Factor>,
        damped: bool,
    ) -> Result<Option<f64>, SolverError> {
        self.exact_factor(h, speed1, factor)?;
        self.predict(h, true);
        match factor.as_ref() {
            Some(f) => self.newton_condensed(h, t1, speed1, f, damped),
            None => Err(SolverError::Input("internal: no factorization".into())),
        }
    }

    /// Take the solved lateral step of size `h` from `newmark` into the state.
    pub(super) fn commit_lateral_step(&mut self, h: f64) {
        let t1 = self.state.time + h;
        let speed0 = self.speed_at(self.state.time);
        let speed1 = self.speed_at(t1);
        let spin1 = self.state.spin_angle + 0.5 * (speed0 + speed1) * h;
        self.state.pad_balancing = f64::from(u8::from(self.condensed.balancing()));
        self.state.chord_pause = f64::from(self.condensed.chord_pause());
        let (s, w) = (&mut self.state, &mut self.newmark);
        std::mem::swap(&mut s.u, &mut w.u);
        std::mem::swap(&mut s.ud, &mut w.ud);
        std::mem::swap(&mut s.udd, &mut w.udd);
        std::mem::swap(&mut s.p, &mut w.p);
        std::mem::swap(&mut s.pd, &mut w.pd);
        std::mem::swap(&mut s.pdd, &mut w.pdd);
        s.time = t1;
        s.spin_angle = spin1;
        self.stats.steps += 1;
        self.watch_contacts(t1, speed1);
    }
}

#[cfg(test)]
mod tests {
    use crate::model::RotorModel;
    use crate::rotor::Rotor;
    use crate::solver::{Simulator, SolverOptions};

    fn jeffcott() -> Simulator {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/jeffcott.toml");
        let model = RotorModel::from_file(std::path::Path::new(path)).unwrap();
        let speed = model.nominal_speed;
        let mut sim = Simulator::new(Rotor::new(model).unwrap(), SolverOptions::default()).unwrap();
        sim.set_speed(speed, 0.0).unwrap();
        sim.settle_static().unwrap();
        sim.set_speed(speed, 200.0).unwrap();
        sim
    }

    /// During a run-up the speed changes every step. The condensed Newton on an
    /// exact refactorization at every step, the same on a factorization kept
    /// within `GYROSCOPIC_PHASE_BAND` and corrected for the gyroscopic term,
    /// and the full-residual Newton on a factorization held within the ±2 %
    /// speed band solve the same equations: their orbits agree to the Newton
    /// tolerance (1e-8 of the clearance) over the run.
    #[test]
    fn condensed_and_full_residual_newton_agree_on_a_run_up() {
        let mut exact = jeffcott();
        exact.factor_work.phase_band = 0.0;
        let mut corrected = jeffcott();
        let mut banded = jeffcott();
        banded.refactor_journal_limit = 0;
        banded.factor_work.phase_band = 0.0;
        let clearance = exact.sites.length_scale;
        let (mut worst, mut worst_corrected): (f64, f64) = (0.0, 0.0);
        for k in 1..=200 {
            let t = k as f64 * 2.5e-4;
            exact.advance_to(t).unwrap();
            corrected.advance_to(t).unwrap();
            banded.advance_to(t).unwrap();
            for c in &exact.sites.coordinates {
                let u = c.of(&exact.state.u);
                worst = worst.max((u - c.of(&banded.state.u)).abs());
                worst_corrected = worst_corrected.max((u - c.of(&corrected.state.u)).abs());
            }
        }
        assert!(worst < 1e-8 * clearance, "orbits differ by {worst:e} m");
        assert!(
            worst_corrected < 1e-8 * clearance,
            "orbits differ by {worst_corrected:e} m"
        );
        // The paths really differ: a factorization every step against one
        // for the run (the speed moves 10 rad/s over it, 0.8 mrad of
        // gyroscopic phase at its steps), and the full-residual Newton on
        // the stale matrix takes more iterations.
        assert!(exact.stats().factorizations >= 600, "{:?}", exact.stats());
        assert!(
            corrected.stats().factorizations < 10,
            "{:?}",
            corrected.stats()
        );
        assert!(banded.stats().factorizations < 10, "{:?}", banded.stats());
        assert!(banded.stats().iterations > exact.stats().iterations);
    }

    /// On the path that holds a factorization within the ±2 % speed band (as
    /// with more than 8 journal DOFs), and on the condensed path keeping its
    /// factorization within `GYROSCOPIC_PHASE_BAND`, a state saved mid
    /// run-up continues bit for bit after `set_state`, in the same simulator
    /// and in a fresh one, with sub-steps of 0.003 s / 30 that are not
    /// binary fractions.
    #[test]
    fn restored_state_continues_bit_for_bit_on_the_banded_path() {
        let banded = || {
            let mut sim = jeffcott();
            sim.refactor_journal_limit = 0;
            sim.factor_work.phase_band = 0.0;
            sim
        };
        for (path, make) in [
            ("banded", &banded as &dyn Fn() -> Simulator),
            ("corrected", &jeffcott),
        ] {
            let t = |k: usize| k as f64 * 0.003;
            let mut run = make();
            for k in 1..=5 {
                run.advance_to(t(k)).unwrap();
            }
            let saved = run.state().clone();
            let want: Vec<_> = (6..=10)
                .map(|k| {
                    run.advance_to(t(k)).unwrap();
                    run.state().clone()
                })
                .collect();
            // The corrected path keeps the factorization of the run's start.
            assert!(run.stats().factorizations < 5, "{path}: {:?}", run.stats());
            let mut fresh = make();
            fresh.set_state(saved.clone()).unwrap();
            run.set_state(saved).unwrap();
            for (k, want) in (6..=10).zip(&want) {
                run.advance_to(t(k)).unwrap();
                fresh.advance_to(t(k)).unwrap();
                assert_eq!(run.state(), want, "{path}: rollback, t = {} s", t(k));
                assert_eq!(
                    fresh.state(),
                    want,
                    "{path}: fresh simulator, t = {} s",
                    t(k)
                );
            }
        }
    }
}
