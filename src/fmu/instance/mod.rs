//! One FMU instance in safe Rust: get/set dispatch and steps of the FMI 2.0
//! Co-Simulation calls onto the [`Simulator`]. Each call first asks the state
//! table ([`super::states`]) whether it is allowed now; the FMU state lives in
//! [`super::snapshot`]. The C exports only translate pointers and call these
//! methods; messages for the logger are queued here. Reads are served by
//! `values.rs`: the outputs are evaluated once per change of the state into
//! an array indexed by value reference.
//!
//! ```
//! use rotor_bearing::fmi2::instance::{Instance, Status};
//! use rotor_bearing::fmi2::variables::{Kind, variables};
//! use rotor_bearing::model::RotorModel;
//!
//! let model = RotorModel::from_file("models/jeffcott.toml".as_ref()).unwrap();
//! let vr = |name: &str| {
//!     variables(&model)
//!         .iter()
//!         .find(|v| v.name == name)
//!         .map(|v| v.value_reference)
//!         .unwrap()
//! };
//! let (speed, x) = (vr("shaft.speed"), vr("bearings.left.x"));
//! let mut fmu = Instance::new("doc", model.clone()).unwrap();
//! assert_eq!(fmu.set(speed, Kind::Real, 100.0), Status::Ok);
//! assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
//! assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
//! assert_eq!(fmu.do_step(0.0, 0.01), Status::Ok);
//! let journal_x = fmu.get(x, Kind::Real).unwrap();
//! assert!(journal_x.is_finite());
//! assert_eq!(fmu.get(speed, Kind::Real), Ok(100.0));
//! ```

use crate::model::{DEFAULT_REDUCED_MODES, Drive, RotorModel};
use crate::rotor::Rotor;
use crate::solver::plausible::DisplacementLimits;
use crate::solver::reduction_check::ValidityWatch;
use crate::solver::{Simulator, SolverError, SolverOptions};
use crate::units::Short;

use super::snapshot::fingerprint;
use super::states::Call;
pub use super::states::{Phase, Version};
use super::variables::{
    Binding, Causality, DEFAULT_LOCAL_ERROR_TOLERANCE, DEFAULT_MAX_ITERATIONS, DEFAULT_TOLERANCE,
    Kind, START_SPEED, Variability, Variable, default_fmu_time_step, force_frequency_scale,
    variables,
};

mod fmu_state;
mod intermediate;
mod step;
mod values;

pub use intermediate::{Intermediate, IntermediateObserver};
use values::OutputCache;

/// FMI status codes (the subset an instance returns).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    /// fmi2OK.
    Ok,
    /// fmi2Warning.
    Warning,
    /// fmi2Discard.
    Discard,
    /// fmi2Error.
    Error,
    /// fmi2Fatal.
    Fatal,
}

/// Relative slack on the stop time of fmi2SetupExperiment, for communication
/// points the master accumulates in floating point.
const STOP_SLACK: f64 = 1e-9;

/// A message for the logger: status, category, text.
pub type LogMessage = (Status, &'static str, String);

/// Solver parameters held by the instance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Params {
    /// Internal step (s).
    pub(super) time_step: f64,
    /// Relative Newton tolerance.
    pub(super) tolerance: f64,
    /// Newton iterations per step attempt.
    pub(super) max_iterations: i32,
    /// Unbalance ramp time constant (s).
    pub(super) ramp_time: f64,
    /// Gravity on/off.
    pub(super) gravity: bool,
    /// Fixed-interface modes of the reduced rotor, 0 for the full rotor.
    pub(super) reduced_modes: i32,
    /// Initial speed of a torque-driven shaft (rad/s; `shaft.initial_speed`).
    pub(super) initial_speed: f64,
    /// Local error tolerance of accuracy-controlled steps, 0 for equal steps
    /// (`solver.local_error_tolerance`).
    pub(super) local_error_tolerance: f64,
}

impl Params {
    /// The simulator options these parameters select.
    fn options(&self) -> SolverOptions {
        SolverOptions {
            time_step: self.time_step,
            tolerance: self.tolerance,
            max_iterations: self.max_iterations.max(1) as usize,
            unbalance_ramp_time: self.ramp_time,
            gravity: self.gravity,
            local_error_tolerance: self.local_error_tolerance,
            ..SolverOptions::default()
        }
    }
}

impl Params {
    /// The start values of `model`'s parameters.
    pub(super) fn start(model: &RotorModel) -> Self {
        Self {
            time_step: default_fmu_time_step(model),
            tolerance: DEFAULT_TOLERANCE,
            max_iterations: DEFAULT_MAX_ITERATIONS as i32,
            ramp_time: 0.0,
            gravity: true,
            reduced_modes: Rotor::transient_modes(model).unwrap_or(DEFAULT_REDUCED_MODES) as i32,
            initial_speed: START_SPEED,
            local_error_tolerance: DEFAULT_LOCAL_ERROR_TOLERANCE,
        }
    }
}

/// An FMU instance.
#[derive(Debug)]
pub struct Instance {
    name: String,
    model: RotorModel,
    /// The FMI version the instance speaks (it names the calls in messages).
    version: Version,
    guid: String,
    fingerprint: u64,
    vars: Vec<Variable>,
    sim: Simulator,
    params: Params,
    /// The tuned value of each model bearing ([`tuned`](crate::bearing::BearingKind::tuned); 0 where none).
    tuned: Vec<f64>,
    /// Each model bearing's offset as the model file gives it (`model`
    /// holds the ones a master set; a reset restores these).
    file_offsets: Vec<[f64; 2]>,
    phase: Phase,
    start_time: f64,
    stop_time: Option<f64>,
    outputs: OutputCache,
    messages: Vec<LogMessage>,
    step_statistics: bool,
    /// Whether the reduced rotor runs inside its validated range.
    watch: ValidityWatch,
    /// The outputs' displacement no machine can have, when they hold one
    /// ([`crate::solver::plausible`]): each step that ends so warns.
    implausible: Option<String>,
    /// The bounds of those displacements, found once.
    limits: DisplacementLimits,
    /// Whether steps stop where a contact begins ([`Instance::set_early_return`]).
    early_return: bool,
    /// Where the last step stopped because a contact began.
    early_return_at: Option<f64>,
}

fn category(status: Status) -> &'static str {
    match status {
        Status::Ok => "logAll",
        Status::Warning => "logStatusWarning",
        Status::Discard => "logStatusDiscard",
        Status::Error => "logStatusError",
        Status::Fatal => "logStatusFatal",
    }
}

/// The tuned value ([`tuned`](crate::bearing::BearingKind::tuned): viscosity or field excitation) of
/// each model bearing as the model file gives it (0 where the bearing has none).
fn model_tuned(model: &RotorModel) -> Vec<f64> {
    model
        .bearings
        .iter()
        .map(|b| b.kind.tuned().unwrap_or(0.0))
        .collect()
}

impl Instance {
    /// A new instance of `model`, named `name`, speaking FMI `version`, whose
    /// model description carries `token` (the FMI 2 `guid`, the FMI 3
    /// `instantiationToken`); the model's plausibility warnings are queued for
    /// the logger (`logStatusWarning`). The version layers build it:
    /// `Instance::new` (FMI 2.0, `crate::fmi2::resources`) and
    /// `Instance::new_fmi3` (FMI 3.0, `crate::fmi3::resources`).
    pub fn with_token(
        name: &str,
        model: RotorModel,
        version: Version,
        guid: String,
    ) -> Result<Self, String> {
        let warning = |w: crate::model::ModelWarning| {
            (Status::Warning, category(Status::Warning), w.to_string())
        };
        let messages = model
            .plausibility_warnings()
            .into_iter()
            .map(warning)
            .collect();
        let vars = variables(&model);
        let outputs = OutputCache::new(&vars);
        let tuned = model_tuned(&model);
        let params = Params::start(&model);
        let sim = Self::fresh_simulator(&model, params.reduced_modes)?;
        let mut messages: Vec<LogMessage> = messages;
        messages.push((Status::Ok, category(Status::Ok), sim.rotor().coordinates()));
        let watch = ValidityWatch::new(sim.rotor());
        Ok(Self {
            watch,
            name: name.to_string(),
            version,
            fingerprint: fingerprint(&guid),
            guid,
            vars,
            sim,
            params,
            tuned,
            file_offsets: model.bearings.iter().map(|b| b.offset).collect(),
            phase: Phase::Instantiated,
            start_time: 0.0,
            stop_time: None,
            outputs,
            messages,
            step_statistics: false,
            implausible: None,
            limits: DisplacementLimits::new(&model),
            early_return: false,
            early_return_at: None,
            model,
        })
    }

    /// A simulator at standstill on the rotor `reduced_modes` selects (0: full).
    fn fresh_simulator(model: &RotorModel, reduced_modes: i32) -> Result<Simulator, String> {
        let modes = usize::try_from(reduced_modes)
            .map_err(|_| format!("solver.reduced_modes = {reduced_modes} must not be negative"))?;
        let rotor = Rotor::for_transients(model.clone(), modes).map_err(|e| e.to_string())?;
        let mut sim = Simulator::new(rotor, SolverOptions::default()).map_err(|e| e.to_string())?;
        // The machine starts at standstill (the start value of `shaft.speed`).
        sim.set_speed(START_SPEED, 0.0).map_err(|e| e.to_string())?;
        Ok(sim)
    }

    /// Rebuild the simulator on the rotor `modes` selects (0: full), carrying
    /// the inputs, their rates and the tuned viscosities and excitations over; the choice is
    /// logged (`logAll`).
    fn rebuild_simulator(&mut self, modes: i32) -> Result<(), SolverError> {
        let mut sim = Self::fresh_simulator(&self.model, modes).map_err(SolverError::Input)?;
        let old = self.sim.state();
        let mut state = sim.state().clone();
        state.time = old.time;
        state.spin_angle = old.spin_angle;
        state.speed = old.speed;
        state.speed_rate = old.speed_rate;
        state.speed_time = old.speed_time;
        state.unbalance.clone_from(&old.unbalance);
        state.unbalance_rate.clone_from(&old.unbalance_rate);
        state.unbalance_phase.clone_from(&old.unbalance_phase);
        state.loads.clone_from(&old.loads);
        state.load_rates.clone_from(&old.load_rates);
        state.harmonic_phase.clone_from(&old.harmonic_phase);
        state.harmonic_frequency.clone_from(&old.harmonic_frequency);
        sim.set_state(state)?;
        if self.model.drive == Drive::Torque {
            sim.set_speed(self.params.initial_speed, 0.0)?;
        }
        let model = model_tuned(&self.model);
        for (k, (&value, &given)) in self.tuned.iter().zip(&model).enumerate() {
            if value != given {
                sim.set_bearing_tuned(k, value)?;
            }
        }
        self.watch = ValidityWatch::new(sim.rotor());
        self.sim = sim;
        self.sim.set_stop_at_contact(self.early_return);
        self.params.reduced_modes = modes;
        let line = self.sim.rotor().coordinates();
        self.messages.push((Status::Ok, category(Status::Ok), line));
        Ok(())
    }

    /// Instance name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The token (FMI 2 GUID, FMI 3 instantiation token) of the model
    /// description of this instance's model.
    pub fn guid(&self) -> &str {
        &self.guid
    }

    /// The variable table of the instance's model.
    pub fn variables(&self) -> &[Variable] {
        &self.vars
    }

    /// The FMI version the instance speaks.
    pub fn version(&self) -> Version {
        self.version
    }

    /// The simulator's time (s): after a step, the time it reached (the
    /// communication point, or where a discarded step stopped).
    pub fn time(&self) -> f64 {
        self.sim.time()
    }

    /// Current phase.
    pub fn phase(&self) -> Phase {
        self.phase
    }

    /// Take the queued log messages.
    pub fn drain_messages(&mut self) -> Vec<LogMessage> {
        std::mem::take(&mut self.messages)
    }

    /// Whether each fmi2DoStep queues its step statistics (internal steps,
    /// Newton iterations, step cuts) as a `logAll` message; the C layer turns it
    /// on when the master enables that category.
    pub fn set_step_statistics(&mut self, on: bool) {
        self.step_statistics = on;
    }

    /// Queue a message and return its status.
    pub fn report(&mut self, status: Status, text: String) -> Status {
        self.messages.push((status, category(status), text));
        if status == Status::Error {
            self.phase = Phase::Error;
        }
        status
    }

    /// `Ok` if `call` is allowed in the current phase (the table in
    /// [`super::states`]), else fmi2Error with a message.
    pub fn check(&mut self, call: Call) -> Result<(), Status> {
        call.check_in(self.phase, self.version)
            .map_err(|text| self.report(Status::Error, text))
    }

    /// fmi2SetupExperiment.
    pub fn setup_experiment(&mut self, start: f64, stop: Option<f64>) -> Status {
        if let Err(s) = self.check(Call::SetupExperiment) {
            return s;
        }
        if !start.is_finite() || stop.is_some_and(|t| !(t.is_finite() && t >= start)) {
            let stop = stop.map_or("none".to_string(), |t| Short(t).to_string());
            return self.report(
                Status::Error,
                format!(
                    "{}: start time {} and stop time {stop} must be finite, stop ≥ start",
                    self.version.setup_call(),
                    Short(start)
                ),
            );
        }
        self.start_time = start;
        self.stop_time = stop;
        Status::Ok
    }

    /// fmi2EnterInitializationMode.
    pub fn enter_initialization_mode(&mut self) -> Status {
        if let Err(s) = self.check(Call::EnterInitializationMode) {
            return s;
        }
        self.phase = Phase::InitializationMode;
        Status::Ok
    }

    /// Apply the parameters and put the rotor in static equilibrium at the start
    /// speed (at fmi2ExitInitializationMode, and when outputs are read during
    /// Initialization Mode).
    fn settle(&mut self) -> Result<(), Status> {
        let p = self.params;
        let options = p.options();
        let mut state = self.sim.state().clone();
        state.time = self.start_time;
        state.speed_time = self.start_time;
        let result = self
            .sim
            .set_options(options)
            .and_then(|()| self.sim.set_state(state))
            .and_then(|()| self.sim.settle_static());
        self.outputs.invalidate();
        for w in self.sim.take_warnings() {
            self.messages
                .push((Status::Warning, category(Status::Warning), w.to_string()));
        }
        result.map_err(|e| {
            self.report(
                Status::Error,
                format!("initialization of {}: {e}", self.model.name),
            )
        })
    }

    /// fmi2ExitInitializationMode.
    pub fn exit_initialization_mode(&mut self) -> Status {
        if let Err(s) = self.check(Call::ExitInitializationMode) {
            return s;
        }
        match self.settle() {
            Ok(()) => {
                self.phase = Phase::StepComplete;
                match self.refresh_outputs() {
                    Ok(()) => {
                        let call = Call::ExitInitializationMode.name_in(self.version);
                        self.warn_implausible(call, Status::Ok)
                    }
                    Err(s) => s,
                }
            }
            Err(s) => s,
        }
    }

    fn variable(&mut self, vr: u32, kind: Kind, call: &str) -> Result<Variable, Status> {
        match self.vars.get(vr as usize) {
            Some(v) if v.kind == kind => Ok(v.clone()),
            _ => Err(self.wrong_variable(vr, kind, call)),
        }
    }

    /// fmi2SetReal / fmi2SetInteger / fmi2SetBoolean.
    pub fn set(&mut self, vr: u32, kind: Kind, value: f64) -> Status {
        let call = match kind {
            Kind::Real => Call::SetReal,
            Kind::Integer => Call::SetInteger,
            Kind::Boolean => Call::SetBoolean,
        };
        if let Err(s) = self.check(call) {
            return s;
        }
        let call = call.name_in(self.version);
        let v = match self.variable(vr, kind, call) {
            Ok(v) => v,
            Err(s) => return s,
        };
        match (v.causality, v.variability) {
            (Causality::Output, _) => {
                return self.report(
                    Status::Error,
                    format!("{call}: {} is an output and cannot be set", v.name),
                );
            }
            (Causality::Parameter, Variability::Fixed) => {
                if let Err(s) = self.check(Call::SetFixedParameter) {
                    return s;
                }
            }
            (Causality::Parameter | Causality::Input, _) => {}
        }
        if !value.is_finite() {
            return self.report(
                Status::Error,
                format!("{call}: {} = {} is not finite", v.name, Short(value)),
            );
        }
        let bad = |this: &mut Self, why: &str| {
            this.report(
                Status::Error,
                format!("{call}: {} = {}: {why}", v.name, Short(value)),
            )
        };
        if let Some(min) = v.min.filter(|&m| value < m) {
            return bad(self, &format!("below the declared minimum {min}"));
        }
        if let Some(max) = v.max.filter(|&m| value > m) {
            return bad(self, &format!("above the declared maximum {max}"));
        }
        let result: Result<(), SolverError> = match v.binding {
            Binding::TimeStep => {
                self.params.time_step = value;
                Ok(())
            }
            Binding::LocalErrorTolerance => {
                let (lo, _) = SolverOptions::LOCAL_ERROR_TOLERANCE_RANGE;
                if value != 0.0 && value < lo {
                    return bad(self, &format!("must be 0 (equal steps) or at least {lo}"));
                }
                self.params.local_error_tolerance = value;
                Ok(())
            }
            Binding::Tolerance => {
                self.params.tolerance = value;
                Ok(())
            }
            Binding::MaxIterations => {
                self.params.max_iterations = value as i32;
                Ok(())
            }
            Binding::RampTime => {
                self.params.ramp_time = value;
                Ok(())
            }
            Binding::Gravity => {
                self.params.gravity = value != 0.0;
                Ok(())
            }
            Binding::ReducedModes if value as i32 == self.params.reduced_modes => Ok(()),
            Binding::ReducedModes => self.rebuild_simulator(value as i32),
            Binding::Viscosity(k) | Binding::Excitation(k) => {
                let r = self.sim.set_bearing_tuned(k, value);
                if r.is_ok() {
                    self.tuned[k] = value;
                }
                r
            }
            Binding::OffsetX(k) | Binding::OffsetY(k) => {
                let axis = usize::from(matches!(v.binding, Binding::OffsetY(_)));
                if self.model.bearings[k].offset[axis] == value {
                    Ok(())
                } else {
                    self.model.bearings[k].offset[axis] = value;
                    self.limits = DisplacementLimits::new(&self.model);
                    self.rebuild_simulator(self.params.reduced_modes)
                }
            }
            Binding::UnbalancePhase(k) => self.sim.set_unbalance_phase(k, value),
            Binding::ForceFrequency(h) => self
                .sim
                .set_force_frequency(h, value * force_frequency_scale(&self.model, h)),
            Binding::Speed => self.sim.set_speed(value, 0.0),
            Binding::Unbalance(k) => self.sim.set_unbalance(k, value),
            Binding::Load(i) => self.sim.set_load(i, value, 0.0),
            Binding::InitialSpeed => {
                let r = self.sim.set_speed(value, 0.0);
                if r.is_ok() {
                    self.params.initial_speed = value;
                }
                r
            }
            _ => return bad(self, "cannot be set"),
        };
        self.outputs.invalidate();
        match result {
            Ok(()) => Status::Ok,
            Err(e) => self.report(Status::Error, format!("{call}: {}: {e}", v.name)),
        }
    }

    /// fmi2SetRealInputDerivatives (first order: a ramp over the next step;
    /// higher orders are accepted and not used).
    pub fn set_input_derivative(&mut self, vr: u32, order: i32, value: f64) -> Status {
        if let Err(s) = self.check(Call::SetRealInputDerivatives) {
            return s;
        }
        let call = Call::SetRealInputDerivatives.name_in(self.version);
        let v = match self.variable(vr, Kind::Real, call) {
            Ok(v) => v,
            Err(s) => return s,
        };
        if order < 1 {
            return self.report(
                Status::Error,
                format!(
                    "{call}: order {order} for {}: derivative orders start at 1",
                    v.name
                ),
            );
        }
        if !value.is_finite() {
            return self.report(
                Status::Error,
                format!(
                    "{call}: derivative of {} = {} is not finite",
                    v.name,
                    Short(value)
                ),
            );
        }
        if v.causality != Causality::Input {
            return self.report(
                Status::Error,
                format!("{call}: {} is not a continuous input", v.name),
            );
        }
        if order > 1 {
            // The inputs are interpolated linearly within a step: a higher
            // derivative is accepted and not used (FMI 2.0, 4.2.1).
            self.messages.push((
                Status::Ok,
                category(Status::Ok),
                format!(
                    "{call}: order {order} derivative of {} = {} ignored: inputs are interpolated to first order within a step",
                    v.name,
                    Short(value)
                ),
            ));
            return Status::Ok;
        }
        let s = self.sim.state();
        let now = s.time;
        let result = match v.binding {
            Binding::Speed => {
                let w = self.sim.speed_at(now);
                self.sim.set_speed(w, value)
            }
            Binding::Load(i) => {
                let load = self.sim.load_at(i, now);
                self.sim.set_load(i, load, value)
            }
            Binding::Unbalance(k) => {
                let me = s.unbalance[k] + s.unbalance_rate[k] * (now - s.speed_time);
                self.sim.set_unbalance_ramp(k, me, value)
            }
            _ => {
                return self.report(
                    Status::Error,
                    format!("{call}: {} is not a continuous input", v.name),
                );
            }
        };
        self.outputs.invalidate();
        match result {
            Ok(()) => Status::Ok,
            Err(e) => self.report(Status::Error, format!("{call}: {}: {e}", v.name)),
        }
    }

    /// fmi2Terminate.
    pub fn terminate(&mut self) -> Status {
        if let Err(s) = self.check(Call::Terminate) {
            return s;
        }
        self.phase = Phase::Terminated;
        Status::Ok
    }

    /// fmi2Reset: back to the state after instantiation.
    pub fn reset(&mut self) -> Status {
        if let Err(s) = self.check(Call::Reset) {
            return s;
        }
        let params = Params::start(&self.model);
        for (b, o) in self.model.bearings.iter_mut().zip(&self.file_offsets) {
            b.offset = *o;
        }
        self.limits = DisplacementLimits::new(&self.model);
        match Self::fresh_simulator(&self.model, params.reduced_modes) {
            Ok(sim) => {
                self.watch = ValidityWatch::new(sim.rotor());
                self.sim = sim;
                self.sim.set_stop_at_contact(self.early_return);
                self.params = params;
                self.tuned = model_tuned(&self.model);
                self.phase = Phase::Instantiated;
                self.outputs.invalidate();
                self.start_time = 0.0;
                self.stop_time = None;
                Status::Ok
            }
            Err(e) => self.report(
                Status::Fatal,
                format!("{}: {e}", Call::Reset.name_in(self.version)),
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plausibility_warnings_are_queued_for_the_logger() {
        let text = format!(
            "{}\n[[bearings]]\nname = \"guide\"\ntype = \"plain\"\nnode = 2\nradius = 0.025\n\
             length = 0.02\nclearance = 5e-5\nviscosity = 32.0\n",
            crate::model::DEFAULT_MODEL_TOML
        );
        let model = RotorModel::from_toml(&text, "m.toml").unwrap();
        let mut instance = Instance::new("i", model).unwrap();
        let mut messages = instance.drain_messages();
        messages.retain(|m| m.0 == Status::Warning);
        assert_eq!(messages.len(), 1, "{messages:?}");
        let (status, category, text) = &messages[0];
        assert_eq!((*status, *category), (Status::Warning, "logStatusWarning"));
        assert!(
            text.starts_with("m.toml: bearings[2].viscosity = 32: "),
            "{text}"
        );
        let mut plain = Instance::new("i", RotorModel::default_model()).unwrap();
        let messages = plain.drain_messages();
        assert!(messages.iter().all(|m| m.0 == Status::Ok), "{messages:?}");
        assert_eq!(messages[0].2, "full rotor: 28 DOFs");
    }
}
