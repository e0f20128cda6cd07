//! The time-domain simulator (see the module docs of [`crate::solver`]).

use crate::bearing::{Bearing, BearingEval};
use crate::rotor::Rotor;
use crate::units::Short;

use super::condensed_work::CondensedWork;
use super::contact_records::{ContactOnset, ContactWatch};
use super::error::SolverError;
use super::factor_work::{Factor, FactorWork};
use super::newmark_work::NewmarkWork;
use super::observed::observed_dofs;
use super::options::{SolverOptions, check_options};
use super::schur::SchurSolve;
use super::sites::Sites;
use super::state::SimState;
use super::statics;
use super::stats::StepStats;
use super::torsion_work::Torsion;
use super::warnings::{SolverWarning, Warnings};
use crate::model::Drive;

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
    pub(super) output_bearings: Vec<(Box<dyn Bearing>, Option<usize>)>,
    pub(super) factor: Option<Factor>,
    pub(super) factor_work: FactorWork,
    /// Evaluation buffers of every model bearing for [`Simulator::outputs`].
    pub(super) output_evals: Vec<BearingEval>,
    pub(super) output_q: Vec<f64>,
    pub(super) output_qd: Vec<f64>,
    /// Up to this many journal DOFs a speed change is refactored exactly (see
    /// [`Simulator::prepare_factor`]).
    pub(super) refactor_journal_limit: usize,
    pub(super) newmark: NewmarkWork,
    pub(super) schur: SchurSolve,
    pub(super) condensed: CondensedWork,
    pub(super) stats: StepStats,
    pub(super) warnings: Warnings,
    /// The twist of a torque-driven shaft; `None` when the speed is prescribed.
    pub(super) torsion: Option<Torsion>,
    /// Contacts reported beyond the limits of their law ([`super::contact_watch`]).
    pub(super) contact_watch: ContactWatch,
    /// Whether a call stops at the start of a contact ([`super::contact_onset`]).
    pub(super) contact_onset: ContactOnset,
    /// Where the last call stopped because a contact began, and which.
    pub(super) contact_began: Option<(f64, Vec<String>)>,
    /// The state a step starts from, kept to undo a rejected step
    /// (accuracy-controlled steps).
    pub(super) step_start: SimState,
    /// The coordinates the local error estimate looks at
    /// ([`observed_dofs`]).
    pub(super) error_dofs: Vec<usize>,
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
                let bearing = b.build();
                let site = if bearing.is_linear() && bearing.internal_dofs() == 0 {
                    None
                } else {
                    site_of.next().map(|(k, _)| k)
                };
                (bearing, site)
            })
            .collect();
        let n_internal = sites.n_internal;
        let torsion = (rotor.model.drive == Drive::Torque).then(|| {
            let nodes: Vec<usize> = sites
                .list
                .iter()
                .map(|s| rotor.model.bearings[s.index].node)
                .collect();
            let sizes: Vec<usize> = sites.list.iter().map(|s| s.eval.n()).collect();
            Torsion::new(&rotor, &nodes, &sizes)
        });
        let mut state = SimState {
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
            loads: rotor.model.load_inputs().iter().map(|l| l.start).collect(),
            load_rates: vec![0.0; rotor.model.load_inputs().len()],
            twist: Vec::new(),
            twist_rate: Vec::new(),
            twist_accel: Vec::new(),
            twist_torque: Vec::new(),
            stuck: 0.0,
            factor_step: 0.0,
            factor_speed: 0.0,
            udd_previous: Vec::new(),
            contact_reported: vec![0.0; 2 * sites.list.len()],
            table_warned: vec![0.0; rotor.model.bearings.len()],
            static_load: vec![0.0; 2 * rotor.model.bearings.len()],
            harmonic_phase: rotor.model.harmonic_forces().map(|h| h.1).collect(),
            harmonic_frequency: rotor.model.harmonic_forces().map(|h| h.2).collect(),
            step_proposal: 0.0,
            pad_balancing: 0.0,
            chord_pause: 0.0,
        };
        if let Some(t) = &torsion {
            let n = t.chain.dof_count();
            for v in [
                &mut state.twist,
                &mut state.twist_rate,
                &mut state.twist_accel,
                &mut state.twist_torque,
            ] {
                *v = vec![0.0; n];
            }
            // At rest, held by static friction until the drive breaks it away.
            state.stuck = 1.0;
        }
        let output_evals: Vec<BearingEval> = output_bearings
            .iter()
            .map(|(b, _)| BearingEval::new(2 + b.internal_dofs()))
            .collect();
        let widest = output_evals.iter().map(BearingEval::n).max().unwrap_or(2);
        let error_dofs = observed_dofs(&rotor);
        Ok(Self {
            step_start: state.clone(),
            error_dofs,
            factor: None,
            factor_work: FactorWork::new(&rotor),
            output_evals,
            output_q: vec![0.0; widest],
            output_qd: vec![0.0; widest],
            refactor_journal_limit: 8,
            newmark: NewmarkWork::new(n, n_internal, rotor.model.load_inputs().len()),
            schur: SchurSolve::new(n, &sites),
            condensed: CondensedWork::new(&sites),
            stats: StepStats::default(),
            warnings: Warnings::default(),
            torsion,
            contact_watch: ContactWatch::default(),
            contact_onset: ContactOnset::default(),
            contact_began: None,
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

    /// The warnings raised since the last call (each element warns once per
    /// simulator): e.g. a coefficient table asked for a speed outside its rows.
    pub fn take_warnings(&mut self) -> Vec<SolverWarning> {
        self.warnings.take()
    }

    /// Whether the shaft is torque-driven (`[torsion] drive = "torque"`): its
    /// speed then comes from the torque inputs.
    pub fn is_torque_driven(&self) -> bool {
        self.torsion.is_some()
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
            || state.loads.len() != s.loads.len()
            || state.load_rates.len() != s.load_rates.len()
            || state.twist.len() != s.twist.len()
            || state.twist_rate.len() != s.twist_rate.len()
            || state.twist_accel.len() != s.twist_accel.len()
            || state.twist_torque.len() != s.twist_torque.len()
            || state.contact_reported.len() != s.contact_reported.len()
            || state.table_warned.len() != s.table_warned.len()
            || state.static_load.len() != s.static_load.len()
            || state.harmonic_phase.len() != s.harmonic_phase.len()
            || state.harmonic_frequency.len() != s.harmonic_frequency.len()
            || !(state.udd_previous.is_empty() || state.udd_previous.len() == s.u.len())
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
        self.condensed.set_balancing(state.pad_balancing != 0.0);
        // A whole number within 0..=CHORD_PAUSE (`SimState::check`).
        self.condensed.set_chord_pause(state.chord_pause as u32);
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
    pub(super) fn rebase_inputs(&mut self) {
        let s = &mut self.state;
        let dt = s.time - s.speed_time;
        s.speed += s.speed_rate * dt;
        for (u, r) in s.unbalance.iter_mut().zip(&s.unbalance_rate) {
            *u = (*u + r * dt).max(0.0);
        }
        for (l, r) in s.loads.iter_mut().zip(&s.load_rates) {
            *l += r * dt;
        }
        s.speed_time = s.time;
    }

    /// Put the rotor in static equilibrium under gravity at the current speed
    /// (velocities and accelerations zero, nonlinear bearings included), by
    /// Newton with backtracking on the full static Jacobian
    /// ([`statics::equilibrium`](super::statics::equilibrium), started from the
    /// current displacement). Each bearing's force there is its static load
    /// ([`SimState::static_load`]).
    pub fn settle_static(&mut self) -> Result<(), SolverError> {
        let speed = self.speed_at(self.state.time);
        let time = self.state.time;
        self.warnings
            .check_tables(&self.rotor, &mut self.state.table_warned, speed, time);
        let mut sites = Sites::new(&self.rotor)?;
        let t = self.state.time;
        let loads: Vec<f64> = (0..self.state.loads.len())
            .map(|k| self.load_at(k, t))
            .collect();
        let f_ext = statics::static_load(&self.rotor, &self.options, &loads);
        let (u, p) = statics::settle(
            &self.rotor,
            &mut sites,
            speed,
            &self.options,
            t,
            (self.state.u.clone(), None),
            &f_ext,
        )?;
        self.state.u = u;
        self.state.p = p;
        self.state.ud.fill(0.0);
        self.state.udd.fill(0.0);
        self.state.pd.fill(0.0);
        self.state.pdd.fill(0.0);
        self.state.step_proposal = 0.0;
        self.state.udd_previous.clear();
        self.factor = None;
        self.record_factor();
        self.running_acceleration()?;
        self.take_static_load()
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
}
