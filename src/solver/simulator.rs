//! The time-domain simulator (see the module docs of [`crate::solver`]).

use crate::bearing::{Bearing, BearingError, BearingEval, BearingReport};
use crate::fe::{DOF_X, DOF_Y};
use crate::linalg::LinalgError;
use crate::rotor::Rotor;
use crate::units::Short;

use super::contact_watch::ContactWatch;
use super::factor::{Factor, FactorWork};
use super::newmark::NewmarkWork;
use super::newton::{CondensedWork, SchurSolve};
use super::sites::Sites;
use super::state::SimState;
use super::statics;

/// Solver settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverOptions {
    /// Largest internal time step (s).
    pub time_step: f64,
    /// Relative tolerance on residual and increment (–).
    pub tolerance: f64,
    /// Newton iterations per attempt of a step.
    pub max_iterations: usize,
    /// Largest number of step halvings before giving up.
    pub max_step_cuts: usize,
    /// Time constant τ of the unbalance ramp `1 − e^{−t/τ}` (s); 0 for none.
    pub unbalance_ramp_time: f64,
    /// Apply gravity.
    pub gravity: bool,
}

impl SolverOptions {
    /// Allowed internal time steps (s): below 1 µs a communication step would
    /// need millions of steps, above 1 s Newmark no longer resolves any mode.
    pub const TIME_STEP_RANGE: (f64, f64) = (1e-6, 1.0);
    /// Allowed relative tolerances (–).
    pub const TOLERANCE_RANGE: (f64, f64) = (1e-14, 1e-2);
    /// Allowed Newton iterations per step attempt.
    pub const MAX_ITERATIONS_RANGE: (usize, usize) = (1, 1000);
    /// Allowed step halvings.
    pub const MAX_STEP_CUTS_RANGE: (usize, usize) = (0, 20);
    /// Allowed unbalance ramp time constants (s).
    pub const RAMP_TIME_RANGE: (f64, f64) = (0.0, 1e6);
    /// Most internal steps one [`Simulator::advance_to`] takes; a longer span
    /// is refused before it starts ([`SolverError::Budget`]).
    pub const MAX_STEPS_PER_CALL: usize = 200_000;
    /// Most step halvings one [`Simulator::advance_to`] may spend in all; past
    /// it the call stops with [`SolverError::Budget`].
    pub const MAX_CUTS_PER_CALL: usize = 2_000;
    /// Shortest span (s) [`Simulator::advance_to`] integrates; a shorter one is
    /// refused ([`SolverError::Input`]). Newmark's acceleration
    /// `ü = 4(u − uₙ)/h² − 4u̇ₙ/h − üₙ` divides the round-off and the Newton
    /// tolerance of `u` by `h²`: on the Jeffcott rotor one step of 1e-9 s
    /// moved the orbit 30 ms later by 1e-4 of its size, 1e-10 s by 7 %,
    /// 1e-11 s by more than its size, and 1e-13 s made Newton fail (1e-8 s:
    /// 1e-7 of it). Below about 1e-154 s, `4/h²` overflows. (A span of
    /// `MIN_SPAN` on a time grid, `(t + h) − t`, may fall short of it by
    /// round-off: up to 1e-6 of it is let through.)
    pub const MIN_SPAN: f64 = 1e-8;
}

impl Default for SolverOptions {
    fn default() -> Self {
        Self {
            time_step: 1e-4,
            tolerance: 1e-8,
            max_iterations: 50,
            max_step_cuts: 16,
            unbalance_ramp_time: 0.0,
            gravity: true,
        }
    }
}

/// Counters of the work done, for reports.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StepStats {
    /// Accepted steps.
    pub steps: usize,
    /// Newton iterations.
    pub iterations: usize,
    /// Bearing-Jacobian refreshes after a stall.
    pub refreshes: usize,
    /// Step halvings.
    pub step_cuts: usize,
    /// Steps solved again by the damped Newton after plain Newton failed.
    pub retries: usize,
    /// Factorizations of the linear part.
    pub factorizations: usize,
}

/// Why the solver stopped.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SolverError {
    /// Newton did not converge even with the smallest allowed step.
    #[error(
        "Newton–Raphson did not converge at t = {time:.6} s (step {step:.3e} s after {cuts} halvings; last relative residual or correction {residual:.3e})"
    )]
    NotConverged {
        time: f64,
        step: f64,
        cuts: usize,
        residual: f64,
    },
    /// A bearing could not give a force (e.g. the journal reached the clearance).
    #[error("bearing {name} at t = {time:.6} s: {source}")]
    Bearing {
        name: String,
        time: f64,
        source: BearingError,
    },
    /// The linear part could not be factored.
    #[error("linear algebra: {0}")]
    Linalg(#[from] LinalgError),
    /// Bad input or option.
    #[error("{0}")]
    Input(String),
    /// No static equilibrium was found.
    #[error("static equilibrium: {0}")]
    Static(String),
    /// A call would exceed the work bound of one call (internal steps or step
    /// halvings, [`SolverOptions::MAX_STEPS_PER_CALL`], [`SolverOptions::MAX_CUTS_PER_CALL`]).
    #[error("{0}")]
    Budget(String),
}

/// Outputs of one bearing.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BearingOutput {
    /// Journal displacement (m).
    pub x: f64,
    /// Journal displacement (m).
    pub y: f64,
    /// Force of the bearing on the journal (N).
    pub fx: f64,
    /// Force of the bearing on the journal (N).
    pub fy: f64,
    /// Film reports (eccentricity, friction…).
    pub report: BearingReport,
}

/// Displacements of one probe.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ProbeOutput {
    /// Displacement (m).
    pub x: f64,
    /// Displacement (m).
    pub y: f64,
}

/// Everything a front end reports at the current time.
#[derive(Debug, Clone, PartialEq)]
pub struct Outputs {
    /// Time (s).
    pub time: f64,
    /// Spin speed (rad/s).
    pub speed: f64,
    /// Spin angle (rad).
    pub spin_angle: f64,
    /// One entry per model bearing, in model order.
    pub bearings: Vec<BearingOutput>,
    /// One entry per probe, in model order.
    pub probes: Vec<ProbeOutput>,
    /// Sum of the bearings' friction torques (N·m).
    pub friction_torque: f64,
}

/// Newmark/Newton–Raphson simulator of a rotor on nonlinear bearings.
///
/// ```
/// use rotor_bearing::model::RotorModel;
/// use rotor_bearing::rotor::Rotor;
/// use rotor_bearing::solver::{Simulator, SolverOptions};
///
/// let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/jeffcott.toml");
/// let model = RotorModel::from_file(std::path::Path::new(path))?;
/// let speed = model.nominal_speed;
/// let mut sim = Simulator::new(Rotor::new(model)?, SolverOptions::default())?;
/// sim.set_speed(speed, 0.0)?;
/// sim.settle_static()?; // start from the static equilibrium at that speed
/// sim.advance_to(0.01)?; // 10 ms in steps of at most 0.1 ms
/// let out = sim.outputs()?;
/// assert_eq!(out.time, 0.01);
/// assert!(out.bearings[0].report.eccentricity < 1.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct Simulator {
    pub(super) rotor: Rotor,
    pub(super) options: SolverOptions,
    pub(super) state: SimState,
    pub(super) sites: Sites,
    /// All model bearings (for outputs), with the site index of nonlinear ones.
    output_bearings: Vec<(Box<dyn Bearing>, Option<usize>)>,
    pub(super) factor: Option<Factor>,
    pub(super) factor_work: FactorWork,
    /// Evaluation buffers of every model bearing for [`Simulator::outputs`].
    output_evals: Vec<BearingEval>,
    output_q: Vec<f64>,
    output_qd: Vec<f64>,
    /// Up to this many journal DOFs a speed change is refactored exactly (see
    /// [`Simulator::prepare_factor`]).
    pub(super) refactor_journal_limit: usize,
    pub(super) newmark: NewmarkWork,
    pub(super) schur: SchurSolve,
    pub(super) condensed: CondensedWork,
    pub(super) stats: StepStats,
    /// Contacts reported beyond the limits of their law ([`super::contact_watch`]).
    pub(super) contact_watch: ContactWatch,
}

impl Simulator {
    /// A simulator at rest (zero state, zero speed) for `rotor`.
    pub fn new(rotor: Rotor, options: SolverOptions) -> Result<Self, SolverError> {
        check_options(&options)?;
        let n = rotor.dof_count();
        let sites = Sites::new(&rotor)?;
        let mut site_of = sites.list.iter().enumerate();
        let output_bearings: Vec<(Box<dyn Bearing>, Option<usize>)> = rotor
            .model
            .bearings
            .iter()
            .map(|b| {
                let bearing = b.kind.build();
                let site = if bearing.is_linear() && bearing.internal_dofs() == 0 {
                    None
                } else {
                    site_of.next().map(|(k, _)| k)
                };
                (bearing, site)
            })
            .collect();
        let n_internal = sites.n_internal;
        let state = SimState {
            time: 0.0,
            u: vec![0.0; n],
            ud: vec![0.0; n],
            udd: vec![0.0; n],
            p: vec![0.0; n_internal],
            pd: vec![0.0; n_internal],
            pdd: vec![0.0; n_internal],
            spin_angle: 0.0,
            speed: 0.0,
            speed_rate: 0.0,
            speed_time: 0.0,
            unbalance: rotor.model.unbalances.iter().map(|u| u.magnitude).collect(),
            unbalance_rate: vec![0.0; rotor.model.unbalances.len()],
            unbalance_phase: rotor.model.unbalances.iter().map(|u| u.phase).collect(),
            factor_step: 0.0,
            factor_speed: 0.0,
        };
        let output_evals: Vec<BearingEval> = output_bearings
            .iter()
            .map(|(b, _)| BearingEval::new(2 + b.internal_dofs()))
            .collect();
        let widest = output_evals.iter().map(BearingEval::n).max().unwrap_or(2);
        Ok(Self {
            factor: None,
            factor_work: FactorWork::new(&rotor),
            output_evals,
            output_q: vec![0.0; widest],
            output_qd: vec![0.0; widest],
            refactor_journal_limit: 8,
            newmark: NewmarkWork::new(n, n_internal),
            schur: SchurSolve::new(n, &sites),
            condensed: CondensedWork::new(&sites),
            stats: StepStats::default(),
            contact_watch: ContactWatch::new(sites.list.len()),
            rotor,
            options,
            state,
            sites,
            output_bearings,
        })
    }

    /// The assembled rotor.
    pub fn rotor(&self) -> &Rotor {
        &self.rotor
    }

    /// Solver options.
    pub fn options(&self) -> &SolverOptions {
        &self.options
    }

    /// Change solver options (takes effect at the next step).
    pub fn set_options(&mut self, options: SolverOptions) -> Result<(), SolverError> {
        check_options(&options)?;
        self.options = options;
        self.factor = None;
        self.record_factor();
        Ok(())
    }

    /// Work counters since creation.
    pub fn stats(&self) -> StepStats {
        self.stats
    }

    /// The complete state (for rollback and serialization).
    pub fn state(&self) -> &SimState {
        &self.state
    }

    /// Restore a state obtained from [`Simulator::state`] of a simulator of the
    /// same rotor, with the factorization it was stepping with (refactored at
    /// exactly its step and speed when the one in hand differs), so that the
    /// continuation repeats the original run bit for bit.
    pub fn set_state(&mut self, state: SimState) -> Result<(), SolverError> {
        let s = &self.state;
        if state.u.len() != s.u.len()
            || state.ud.len() != s.ud.len()
            || state.udd.len() != s.udd.len()
            || state.p.len() != s.p.len()
            || state.pd.len() != s.pd.len()
            || state.pdd.len() != s.pdd.len()
            || state.unbalance.len() != s.unbalance.len()
            || state.unbalance_rate.len() != s.unbalance_rate.len()
            || state.unbalance_phase.len() != s.unbalance_phase.len()
        {
            return Err(SolverError::Input(
                "state does not belong to this rotor (sizes differ)".into(),
            ));
        }
        state.check(self.rotor.model.max_speed)?;
        let (step, speed) = (state.factor_step, state.factor_speed);
        // A factor is made for a sub-step: at most max_step_cuts halvings below the time step.
        let smallest = SolverOptions::TIME_STEP_RANGE.0
            * 0.5f64.powi(SolverOptions::MAX_STEP_CUTS_RANGE.1 as i32);
        let step_ok = step == 0.0 || (smallest..=SolverOptions::TIME_STEP_RANGE.1).contains(&step);
        if !(step_ok && speed.is_finite() && speed.abs() <= self.rotor.model.max_speed) {
            return Err(SolverError::Input(format!(
                "state factorization step {} s or speed {} rad/s is invalid",
                Short(step),
                Short(speed)
            )));
        }
        let held = self.factor.as_ref().map(|f| (f.step, f.speed));
        if step == 0.0 {
            self.factor = None;
        } else if held
            .is_none_or(|(h, w)| h.to_bits() != step.to_bits() || w.to_bits() != speed.to_bits())
        {
            let reuse = self.factor.take();
            match self.dynamic_factor(step, speed, reuse) {
                Ok(f) => self.factor = Some(f),
                Err(e) => {
                    self.record_factor();
                    return Err(e.into());
                }
            }
        }
        self.schur.ready = false;
        self.state = state;
        Ok(())
    }

    /// Record the step and speed of the factorization in hand in the state.
    pub(super) fn record_factor(&mut self) {
        (self.state.factor_step, self.state.factor_speed) = self
            .factor
            .as_ref()
            .map_or((0.0, 0.0), |f| (f.step, f.speed));
    }

    /// Current time (s).
    pub fn time(&self) -> f64 {
        self.state.time
    }

    /// Adopt a master's clock `t` that differs from the current time only by
    /// rounding (≤ 1e-9 relative), so that repeated `t + h` sums cannot drift.
    pub fn align_time(&mut self, t: f64) -> Result<(), SolverError> {
        let now = self.state.time;
        if !(t.is_finite() && (t - now).abs() <= 1e-9 * now.abs().max(1.0)) {
            return Err(SolverError::Input(format!(
                "time {} s is not the simulator's time {} s",
                Short(t),
                Short(now)
            )));
        }
        self.state.time = t;
        Ok(())
    }

    /// Spin speed at time `t` (rad/s).
    pub fn speed_at(&self, t: f64) -> f64 {
        self.state.speed + self.state.speed_rate * (t - self.state.speed_time)
    }

    /// Re-base the linearly extrapolated inputs to the current time.
    fn rebase_inputs(&mut self) {
        let s = &mut self.state;
        let dt = s.time - s.speed_time;
        s.speed += s.speed_rate * dt;
        for (u, r) in s.unbalance.iter_mut().zip(&s.unbalance_rate) {
            *u = (*u + r * dt).max(0.0);
        }
        s.speed_time = s.time;
    }

    /// Set the spin speed (rad/s) now and its rate of change (rad/s²) from now on.
    pub fn set_speed(&mut self, speed: f64, rate: f64) -> Result<(), SolverError> {
        if !speed.is_finite() || !rate.is_finite() {
            return Err(SolverError::Input(format!(
                "speed {} rad/s and its rate {} rad/s² must be finite",
                Short(speed),
                Short(rate)
            )));
        }
        let max = self.rotor.model.max_speed;
        if speed.abs() > max {
            return Err(SolverError::Input(format!(
                "speed {} rad/s exceeds the model's max_speed_rpm ({max} rad/s)",
                Short(speed)
            )));
        }
        self.rebase_inputs();
        self.state.speed = speed;
        self.state.speed_rate = rate;
        Ok(())
    }

    /// Set the unbalance (kg·m) of plane `plane` (model order), constant from now on.
    pub fn set_unbalance(&mut self, plane: usize, magnitude: f64) -> Result<(), SolverError> {
        self.set_unbalance_ramp(plane, magnitude, 0.0)
    }

    /// Set the unbalance (kg·m) of plane `plane` now and its rate of change (kg·m/s).
    pub fn set_unbalance_ramp(
        &mut self,
        plane: usize,
        magnitude: f64,
        rate: f64,
    ) -> Result<(), SolverError> {
        if !(magnitude.is_finite() && magnitude >= 0.0 && rate.is_finite()) {
            return Err(SolverError::Input(format!(
                "unbalance {} kg·m must be finite and not negative, its rate {} kg·m/s finite",
                Short(magnitude),
                Short(rate)
            )));
        }
        self.rebase_inputs();
        *plane_slot(&mut self.state.unbalance, plane)? = magnitude;
        *plane_slot(&mut self.state.unbalance_rate, plane)? = rate;
        Ok(())
    }

    /// Change the oil viscosity (Pa·s) of fluid-film bearing `index` (model order).
    pub fn set_bearing_viscosity(
        &mut self,
        index: usize,
        viscosity: f64,
    ) -> Result<(), SolverError> {
        if !(viscosity.is_finite() && viscosity > 0.0) {
            return Err(SolverError::Input(format!(
                "viscosity {} Pa·s must be finite and positive",
                Short(viscosity)
            )));
        }
        let placed = self
            .rotor
            .model
            .bearings
            .get_mut(index)
            .ok_or_else(|| SolverError::Input(format!("no bearing {index}")))?;
        if !placed.kind.set_viscosity(viscosity) {
            return Err(SolverError::Input(format!(
                "bearing {} is linear: it has no oil viscosity",
                placed.name
            )));
        }
        let (output, site) = &mut self.output_bearings[index];
        *output = placed.kind.build();
        if let Some(k) = site {
            self.sites.list[*k].bearing = placed.kind.build();
        }
        Ok(())
    }

    /// Set the angular position (rad) of plane `plane` at spin angle zero.
    pub fn set_unbalance_phase(&mut self, plane: usize, phase: f64) -> Result<(), SolverError> {
        if !phase.is_finite() {
            return Err(SolverError::Input(format!(
                "unbalance phase {} must be finite",
                Short(phase)
            )));
        }
        *plane_slot(&mut self.state.unbalance_phase, plane)? = phase;
        Ok(())
    }

    /// Put the rotor in static equilibrium under gravity at the current speed
    /// (velocities and accelerations zero, nonlinear bearings included), by
    /// Newton with backtracking on the full static Jacobian
    /// ([`statics::equilibrium`](super::statics::equilibrium), started from the
    /// current displacement).
    pub fn settle_static(&mut self) -> Result<(), SolverError> {
        let speed = self.speed_at(self.state.time);
        let mut sites = Sites::new(&self.rotor)?;
        let (u, p) = statics::settle(
            &self.rotor,
            &mut sites,
            speed,
            &self.options,
            self.state.time,
            self.state.u.clone(),
            None,
        )?;
        self.state.u = u;
        self.state.p = p;
        self.state.ud.fill(0.0);
        self.state.udd.fill(0.0);
        self.state.pd.fill(0.0);
        self.state.pdd.fill(0.0);
        self.factor = None;
        self.record_factor();
        Ok(())
    }

    /// Make the accelerations consistent with the equations of motion at the
    /// current displacements and velocities: `M ü = f(t) + E F_b − (C + ΩG) u̇ − K u`
    /// (pad rates are left as they are). Call after setting an arbitrary state.
    pub fn consistent_acceleration(&mut self) -> Result<(), SolverError> {
        let t = self.state.time;
        let speed = self.speed_at(t);
        self.external_force(t, self.state.spin_angle);
        let w = &mut self.newmark;
        w.r.copy_from_slice(&w.f_ext);
        for (matrix, coef, x) in [
            (&self.rotor.damping, 1.0, &self.state.ud),
            (&self.rotor.gyroscopic, speed, &self.state.ud),
            (&self.rotor.stiffness, 1.0, &self.state.u),
        ] {
            matrix.mul_vec(x, &mut w.mv);
            for (r, m) in w.r.iter_mut().zip(&w.mv) {
                *r -= coef * m;
            }
        }
        let s = &self.state;
        self.sites
            .add_forces(&s.u, &s.ud, &s.p, &s.pd, speed, t, &mut w.r, &mut w.rp)?;
        let lu = self.rotor.mass.lu()?;
        let mut acc = w.r.clone();
        lu.solve_in_place(&mut acc);
        self.state.udd = acc;
        Ok(())
    }

    /// Outputs at the current state.
    pub fn outputs(&mut self) -> Result<Outputs, SolverError> {
        let t = self.state.time;
        let speed = self.speed_at(t);
        let mut bearings = Vec::with_capacity(self.output_bearings.len());
        let mut friction_torque = 0.0;
        for (k, (bearing, site)) in self.output_bearings.iter().enumerate() {
            let node = self.rotor.model.bearings[k].node;
            let at = |dof: usize, v: &[f64]| self.rotor.node_value(node, dof, v);
            let (x, y) = (at(DOF_X, &self.state.u), at(DOF_Y, &self.state.u));
            let (vx, vy) = (at(DOF_X, &self.state.ud), at(DOF_Y, &self.state.ud));
            let internal = bearing.internal_dofs();
            let eval = &mut self.output_evals[k];
            let (q, qd) = (
                &mut self.output_q[..2 + internal],
                &mut self.output_qd[..2 + internal],
            );
            (q[0], q[1], qd[0], qd[1]) = (x, y, vx, vy);
            if let Some(si) = site {
                let s = &self.sites.list[*si];
                q[2..].copy_from_slice(&self.state.p[s.offset..s.offset + internal]);
                qd[2..].copy_from_slice(&self.state.pd[s.offset..s.offset + internal]);
            }
            bearing
                .evaluate(q, qd, speed, eval)
                .map_err(|source| SolverError::Bearing {
                    name: self.rotor.model.bearings[k].name.clone(),
                    time: t,
                    source,
                })?;
            let report = bearing.report(q, qd, speed, eval);
            friction_torque += report.friction_torque;
            bearings.push(BearingOutput {
                x,
                y,
                fx: eval.force[0],
                fy: eval.force[1],
                report,
            });
        }
        let probes = self
            .rotor
            .model
            .probes
            .iter()
            .map(|p| ProbeOutput {
                x: self.rotor.node_value(p.node, DOF_X, &self.state.u),
                y: self.rotor.node_value(p.node, DOF_Y, &self.state.u),
            })
            .collect();
        Ok(Outputs {
            time: t,
            speed,
            spin_angle: self.state.spin_angle,
            bearings,
            probes,
            friction_torque,
        })
    }
}

fn plane_slot(values: &mut [f64], plane: usize) -> Result<&mut f64, SolverError> {
    let count = values.len();
    values.get_mut(plane).ok_or_else(|| {
        SolverError::Input(format!(
            "no unbalance plane {plane} (the model has {count})"
        ))
    })
}

/// Largest absolute entry of `v` (0 when empty).
pub(super) fn inf_norm(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |a, x| a.max(x.abs()))
}

fn check_options(o: &SolverOptions) -> Result<(), SolverError> {
    let within = |what: &str, v: f64, (lo, hi): (f64, f64), unit: &str| {
        if v.is_finite() && (lo..=hi).contains(&v) {
            Ok(())
        } else {
            Err(SolverError::Input(format!(
                "solver option {what} = {} {unit} is outside [{lo}, {hi}] {unit}",
                Short(v)
            )))
        }
    };
    let as_f64 = |(lo, hi): (usize, usize)| (lo as f64, hi as f64);
    within(
        "time_step",
        o.time_step,
        SolverOptions::TIME_STEP_RANGE,
        "s",
    )?;
    within("tolerance", o.tolerance, SolverOptions::TOLERANCE_RANGE, "")?;
    within(
        "max_iterations",
        o.max_iterations as f64,
        as_f64(SolverOptions::MAX_ITERATIONS_RANGE),
        "",
    )?;
    within(
        "max_step_cuts",
        o.max_step_cuts as f64,
        as_f64(SolverOptions::MAX_STEP_CUTS_RANGE),
        "",
    )?;
    within(
        "unbalance_ramp_time",
        o.unbalance_ramp_time,
        SolverOptions::RAMP_TIME_RANGE,
        "s",
    )
}
