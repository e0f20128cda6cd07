//! One FMU instance in safe Rust: the FMI 2.0 Co-Simulation state machine on top
//! of the [`Simulator`]. The C exports ([`super::exports`]) only translate
//! pointers and call these methods; messages for the logger are queued here.

use crate::model::RotorModel;
use crate::rotor::Rotor;
use crate::solver::{Outputs, SimState, Simulator, SolverError, SolverOptions};

use super::variables::{
    Binding, Causality, DEFAULT_MAX_ITERATIONS, DEFAULT_TIME_STEP, DEFAULT_TOLERANCE, Kind,
    Variability, Variable, variables,
};

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

/// Where the instance is in the FMI 2.0 Co-Simulation state machine.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Phase {
    /// After fmi2Instantiate (and fmi2Reset).
    Instantiated,
    /// Between fmi2EnterInitializationMode and fmi2ExitInitializationMode.
    InitializationMode,
    /// Initialized; the last step (if any) completed.
    StepComplete,
    /// The last fmi2DoStep was discarded; only rollback, reset or terminate help.
    StepFailed,
    /// After fmi2Terminate.
    Terminated,
    /// After an fmi2Error: only reset or free.
    Error,
}

/// A message for the logger: status, category, text.
pub type LogMessage = (Status, &'static str, String);

/// Solver parameters held by the instance.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Params {
    time_step: f64,
    tolerance: f64,
    max_iterations: i32,
    ramp_time: f64,
    gravity: bool,
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
            ..SolverOptions::default()
        }
    }
}

impl Default for Params {
    fn default() -> Self {
        Self {
            time_step: DEFAULT_TIME_STEP,
            tolerance: DEFAULT_TOLERANCE,
            max_iterations: DEFAULT_MAX_ITERATIONS as i32,
            ramp_time: 0.0,
            gravity: true,
        }
    }
}

/// Everything `fmi2GetFMUstate` saves.
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    sim: SimState,
    params: Params,
    viscosity: Vec<f64>,
    phase: Phase,
}

/// An FMU instance.
#[derive(Debug)]
pub struct Instance {
    name: String,
    model: RotorModel,
    vars: Vec<Variable>,
    sim: Simulator,
    params: Params,
    viscosity: Vec<f64>,
    phase: Phase,
    start_time: f64,
    stop_time: Option<f64>,
    outputs: Option<Outputs>,
    messages: Vec<LogMessage>,
}

const MAGIC: &[u8; 8] = b"RBFMU01\0";

fn category(status: Status) -> &'static str {
    match status {
        Status::Ok => "logAll",
        Status::Warning => "logStatusWarning",
        Status::Discard => "logStatusDiscard",
        Status::Error => "logStatusError",
        Status::Fatal => "logStatusFatal",
    }
}

impl Instance {
    /// A new instance of `model`, named `name`.
    pub fn new(name: &str, model: RotorModel) -> Result<Self, String> {
        let vars = variables(&model);
        let viscosity = model
            .bearings
            .iter()
            .map(|b| b.kind.viscosity().unwrap_or(0.0))
            .collect();
        let sim = Self::fresh_simulator(&model)?;
        Ok(Self {
            name: name.to_string(),
            model,
            vars,
            sim,
            params: Params::default(),
            viscosity,
            phase: Phase::Instantiated,
            start_time: 0.0,
            stop_time: None,
            outputs: None,
            messages: Vec::new(),
        })
    }

    fn fresh_simulator(model: &RotorModel) -> Result<Simulator, String> {
        let rotor = Rotor::new(model.clone()).map_err(|e| e.to_string())?;
        let mut sim = Simulator::new(rotor, SolverOptions::default()).map_err(|e| e.to_string())?;
        sim.set_speed(model.nominal_speed, 0.0)
            .map_err(|e| e.to_string())?;
        Ok(sim)
    }

    /// Instance name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Current phase.
    pub fn phase(&self) -> Phase {
        self.phase
    }

    /// Take the queued log messages.
    pub fn drain_messages(&mut self) -> Vec<LogMessage> {
        std::mem::take(&mut self.messages)
    }

    /// Queue a message and return its status.
    pub fn report(&mut self, status: Status, text: String) -> Status {
        self.messages.push((status, category(status), text));
        if status == Status::Error {
            self.phase = Phase::Error;
        }
        status
    }

    fn require(&mut self, call: &str, allowed: &[Phase]) -> Result<(), Status> {
        if allowed.contains(&self.phase) {
            Ok(())
        } else {
            let phase = self.phase;
            Err(self.report(
                Status::Error,
                format!("{call} is not allowed in state {phase:?} (allowed: {allowed:?})"),
            ))
        }
    }

    /// fmi2SetupExperiment.
    pub fn setup_experiment(&mut self, start: f64, stop: Option<f64>) -> Status {
        if let Err(s) = self.require("fmi2SetupExperiment", &[Phase::Instantiated]) {
            return s;
        }
        if !start.is_finite() || stop.is_some_and(|t| !(t.is_finite() && t >= start)) {
            return self.report(Status::Error, format!("fmi2SetupExperiment: start time {start} and stop time {stop:?} must be finite, stop ≥ start"));
        }
        self.start_time = start;
        self.stop_time = stop;
        Status::Ok
    }

    /// fmi2EnterInitializationMode.
    pub fn enter_initialization_mode(&mut self) -> Status {
        if let Err(s) = self.require("fmi2EnterInitializationMode", &[Phase::Instantiated]) {
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
        self.outputs = None;
        result.map_err(|e| {
            self.report(
                Status::Error,
                format!("initialization of {}: {e}", self.model.name),
            )
        })
    }

    /// fmi2ExitInitializationMode.
    pub fn exit_initialization_mode(&mut self) -> Status {
        if let Err(s) = self.require("fmi2ExitInitializationMode", &[Phase::InitializationMode]) {
            return s;
        }
        match self.settle() {
            Ok(()) => {
                self.phase = Phase::StepComplete;
                Status::Ok
            }
            Err(s) => s,
        }
    }

    fn variable(&mut self, vr: u32, kind: Kind, call: &str) -> Result<Variable, Status> {
        match self.vars.get(vr as usize) {
            Some(v) if v.kind == kind => Ok(v.clone()),
            Some(v) => Err(self.report(
                Status::Error,
                format!(
                    "{call}: value reference {vr} ({}) is a {:?}, not a {kind:?}",
                    v.name, v.kind
                ),
            )),
            None => Err(self.report(
                Status::Error,
                format!(
                    "{call}: unknown value reference {vr} (the FMU has {} variables)",
                    self.vars.len()
                ),
            )),
        }
    }

    fn current_outputs(&mut self) -> Result<&Outputs, Status> {
        if self.outputs.is_none() {
            match self.sim.outputs() {
                Ok(o) => self.outputs = Some(o),
                Err(e) => return Err(self.report(Status::Error, format!("outputs: {e}"))),
            }
        }
        self.outputs.as_ref().ok_or(Status::Error)
    }

    /// fmi2GetReal / fmi2GetInteger / fmi2GetBoolean: value of `vr` as f64.
    pub fn get(&mut self, vr: u32, kind: Kind) -> Result<f64, Status> {
        let call = "fmi2Get";
        self.require(
            call,
            &[
                Phase::InitializationMode,
                Phase::StepComplete,
                Phase::StepFailed,
                Phase::Terminated,
            ],
        )?;
        let v = self.variable(vr, kind, call)?;
        let s = self.sim.state();
        let p = self.params;
        let value = match v.binding {
            Binding::TimeStep => p.time_step,
            Binding::Tolerance => p.tolerance,
            Binding::MaxIterations => f64::from(p.max_iterations),
            Binding::RampTime => p.ramp_time,
            Binding::Gravity => f64::from(u8::from(p.gravity)),
            Binding::Viscosity(k) => self.viscosity[k],
            Binding::UnbalancePhase(k) => s.unbalance_phase[k],
            Binding::Speed => self.sim.speed_at(s.time),
            Binding::Unbalance(k) => s.unbalance[k] + s.unbalance_rate[k] * (s.time - s.speed_time),
            binding => {
                if self.phase == Phase::InitializationMode && self.outputs.is_none() {
                    self.settle()?;
                }
                let o = self.current_outputs()?;
                match binding {
                    Binding::BearingX(k) => o.bearings[k].x,
                    Binding::BearingY(k) => o.bearings[k].y,
                    Binding::BearingFx(k) => o.bearings[k].fx,
                    Binding::BearingFy(k) => o.bearings[k].fy,
                    Binding::BearingEccentricity(k) => o.bearings[k].report.eccentricity,
                    Binding::BearingFriction(k) => o.bearings[k].report.friction_torque,
                    Binding::ProbeX(k) => o.probes[k].x,
                    Binding::ProbeY(k) => o.probes[k].y,
                    Binding::SpinAngle => o.spin_angle,
                    Binding::FrictionTorque => o.friction_torque,
                    _ => f64::NAN,
                }
            }
        };
        if value.is_finite() {
            Ok(value)
        } else {
            Err(self.report(
                Status::Error,
                format!("{call}: {} is not finite ({value})", v.name),
            ))
        }
    }

    /// fmi2SetReal / fmi2SetInteger / fmi2SetBoolean.
    pub fn set(&mut self, vr: u32, kind: Kind, value: f64) -> Status {
        let call = "fmi2Set";
        let v = match self.variable(vr, kind, call) {
            Ok(v) => v,
            Err(s) => return s,
        };
        let allowed: &[Phase] = match (v.causality, v.variability) {
            (Causality::Output, _) => {
                return self.report(
                    Status::Error,
                    format!("{call}: {} is an output and cannot be set", v.name),
                );
            }
            (Causality::Parameter, Variability::Fixed) => {
                &[Phase::Instantiated, Phase::InitializationMode]
            }
            (Causality::Parameter, _) => &[
                Phase::Instantiated,
                Phase::InitializationMode,
                Phase::StepComplete,
            ],
            (Causality::Input, _) => &[
                Phase::Instantiated,
                Phase::InitializationMode,
                Phase::StepComplete,
            ],
        };
        if let Err(s) = self.require(&format!("{call} of {}", v.name), allowed) {
            return s;
        }
        if !value.is_finite() {
            return self.report(
                Status::Error,
                format!("{call}: {} = {value} is not finite", v.name),
            );
        }
        let positive = |x: f64| x > 0.0;
        let bad = |this: &mut Self, why: &str| {
            this.report(
                Status::Error,
                format!("{call}: {} = {value}: {why}", v.name),
            )
        };
        let result: Result<(), SolverError> = match v.binding {
            Binding::TimeStep if !positive(value) => return bad(self, "must be positive"),
            Binding::TimeStep => {
                self.params.time_step = value;
                Ok(())
            }
            Binding::Tolerance if !(value > 0.0 && value < 1.0) => {
                return bad(self, "must lie in (0, 1)");
            }
            Binding::Tolerance => {
                self.params.tolerance = value;
                Ok(())
            }
            Binding::MaxIterations if value < 1.0 => return bad(self, "must be at least 1"),
            Binding::MaxIterations => {
                self.params.max_iterations = value as i32;
                Ok(())
            }
            Binding::RampTime if value < 0.0 => return bad(self, "must not be negative"),
            Binding::RampTime => {
                self.params.ramp_time = value;
                Ok(())
            }
            Binding::Gravity => {
                self.params.gravity = value != 0.0;
                Ok(())
            }
            Binding::Viscosity(k) => {
                let r = self.sim.set_bearing_viscosity(k, value);
                if r.is_ok() {
                    self.viscosity[k] = value;
                }
                r
            }
            Binding::UnbalancePhase(k) => self.sim.set_unbalance_phase(k, value),
            Binding::Speed => self.sim.set_speed(value, 0.0),
            Binding::Unbalance(k) => self.sim.set_unbalance(k, value),
            _ => return bad(self, "cannot be set"),
        };
        self.outputs = None;
        match result {
            Ok(()) => Status::Ok,
            Err(e) => self.report(Status::Error, format!("{call}: {}: {e}", v.name)),
        }
    }

    /// fmi2SetRealInputDerivatives (first order: a ramp over the next step).
    pub fn set_input_derivative(&mut self, vr: u32, order: i32, value: f64) -> Status {
        let call = "fmi2SetRealInputDerivatives";
        if let Err(s) = self.require(call, &[Phase::InitializationMode, Phase::StepComplete]) {
            return s;
        }
        let v = match self.variable(vr, Kind::Real, call) {
            Ok(v) => v,
            Err(s) => return s,
        };
        if order != 1 {
            return self.report(
                Status::Error,
                format!(
                    "{call}: order {order} for {}: only first derivatives are supported",
                    v.name
                ),
            );
        }
        if !value.is_finite() {
            return self.report(
                Status::Error,
                format!("{call}: derivative of {} = {value} is not finite", v.name),
            );
        }
        let s = self.sim.state();
        let now = s.time;
        let result = match v.binding {
            Binding::Speed => {
                let w = self.sim.speed_at(now);
                self.sim.set_speed(w, value)
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
        self.outputs = None;
        match result {
            Ok(()) => Status::Ok,
            Err(e) => self.report(Status::Error, format!("{call}: {}: {e}", v.name)),
        }
    }

    /// fmi2DoStep.
    pub fn do_step(&mut self, current: f64, step: f64) -> Status {
        let call = "fmi2DoStep";
        if let Err(s) = self.require(call, &[Phase::StepComplete]) {
            return s;
        }
        let now = self.sim.time();
        if self.sim.align_time(current).is_err() {
            return self.report(
                Status::Error,
                format!(
                    "{call}: communication point {current} s differs from the FMU time {now} s"
                ),
            );
        }
        if !(step.is_finite() && step > 0.0) {
            return self.report(
                Status::Error,
                format!("{call}: communication step {step} s must be positive"),
            );
        }
        self.outputs = None;
        match self.sim.advance_to(current + step) {
            Ok(()) => match self.current_outputs() {
                Ok(_) => Status::Ok,
                Err(s) => s,
            },
            Err(e) => {
                self.phase = Phase::StepFailed;
                let reached = self.sim.time();
                self.report(
                    Status::Discard,
                    format!("{call} from {current} s by {step} s discarded at {reached} s: {e}. Roll back with fmi2SetFMUstate or reset."),
                )
            }
        }
    }

    /// fmi2GetRealStatus(fmi2LastSuccessfulTime).
    pub fn last_successful_time(&mut self) -> Result<f64, Status> {
        self.require(
            "fmi2GetRealStatus",
            &[Phase::StepComplete, Phase::StepFailed, Phase::Terminated],
        )?;
        Ok(self.sim.time())
    }

    /// fmi2Terminate.
    pub fn terminate(&mut self) -> Status {
        if let Err(s) = self.require("fmi2Terminate", &[Phase::StepComplete, Phase::StepFailed]) {
            return s;
        }
        self.phase = Phase::Terminated;
        Status::Ok
    }

    /// fmi2Reset: back to the state after instantiation.
    pub fn reset(&mut self) -> Status {
        match Self::fresh_simulator(&self.model) {
            Ok(sim) => {
                self.sim = sim;
                self.params = Params::default();
                self.phase = Phase::Instantiated;
                self.outputs = None;
                self.start_time = 0.0;
                self.stop_time = None;
                Status::Ok
            }
            Err(e) => self.report(Status::Fatal, format!("fmi2Reset: {e}")),
        }
    }

    /// fmi2GetFMUstate.
    pub fn snapshot(&mut self) -> Result<Snapshot, Status> {
        self.require(
            "fmi2GetFMUstate",
            &[
                Phase::Instantiated,
                Phase::InitializationMode,
                Phase::StepComplete,
                Phase::StepFailed,
                Phase::Terminated,
            ],
        )?;
        Ok(Snapshot {
            sim: self.sim.state().clone(),
            params: self.params,
            viscosity: self.viscosity.clone(),
            phase: self.phase,
        })
    }

    /// fmi2SetFMUstate.
    pub fn restore(&mut self, snap: &Snapshot) -> Status {
        if let Err(s) = self.require(
            "fmi2SetFMUstate",
            &[
                Phase::Instantiated,
                Phase::InitializationMode,
                Phase::StepComplete,
                Phase::StepFailed,
                Phase::Terminated,
                Phase::Error,
            ],
        ) {
            return s;
        }
        if snap.viscosity.len() != self.viscosity.len() {
            return self.report(
                Status::Error,
                "fmi2SetFMUstate: the state belongs to another model".into(),
            );
        }
        for (k, (&mu, &now)) in snap
            .viscosity
            .iter()
            .zip(self.viscosity.clone().iter())
            .enumerate()
        {
            if mu != now && mu > 0.0 {
                if let Err(e) = self.sim.set_bearing_viscosity(k, mu) {
                    return self.report(Status::Error, format!("fmi2SetFMUstate: {e}"));
                }
            }
        }
        let p = snap.params;
        let options = p.options();
        if let Err(e) = self
            .sim
            .set_options(options)
            .and_then(|()| self.sim.set_state(snap.sim.clone()))
        {
            return self.report(Status::Error, format!("fmi2SetFMUstate: {e}"));
        }
        self.params = snap.params;
        self.viscosity = snap.viscosity.clone();
        self.phase = snap.phase;
        self.outputs = None;
        Status::Ok
    }

    /// fmi2SerializeFMUstate: a self-describing little-endian byte image.
    pub fn serialize(snap: &Snapshot) -> Vec<u8> {
        let mut out = MAGIC.to_vec();
        let mut put = |v: f64| out.extend_from_slice(&v.to_le_bytes());
        let s = &snap.sim;
        for v in [s.time, s.spin_angle, s.speed, s.speed_rate, s.speed_time] {
            put(v);
        }
        let p = snap.params;
        for v in [
            p.time_step,
            p.tolerance,
            f64::from(p.max_iterations),
            p.ramp_time,
            f64::from(u8::from(p.gravity)),
        ] {
            put(v);
        }
        put(match snap.phase {
            Phase::Instantiated => 0.0,
            Phase::InitializationMode => 1.0,
            Phase::StepComplete => 2.0,
            Phase::StepFailed => 3.0,
            Phase::Terminated => 4.0,
            Phase::Error => 5.0,
        });
        for v in [
            &s.u,
            &s.ud,
            &s.udd,
            &s.p,
            &s.pd,
            &s.pdd,
            &s.unbalance,
            &s.unbalance_rate,
            &s.unbalance_phase,
            &snap.viscosity,
        ] {
            put(v.len() as f64);
            for x in v {
                put(*x);
            }
        }
        out
    }

    /// fmi2DeSerializeFMUstate: the inverse of [`Instance::serialize`], checked
    /// against this instance's model sizes.
    pub fn deserialize(&mut self, bytes: &[u8]) -> Result<Snapshot, Status> {
        let fail = |this: &mut Self, why: &str| {
            this.report(Status::Error, format!("fmi2DeSerializeFMUstate: {why}"))
        };
        if bytes.len() < MAGIC.len()
            || &bytes[..MAGIC.len()] != MAGIC
            || (bytes.len() - MAGIC.len()) % 8 != 0
        {
            return Err(fail(self, "not a serialized state of this FMU"));
        }
        let words: Vec<f64> = bytes[MAGIC.len()..]
            .chunks_exact(8)
            .map(|c| f64::from_le_bytes([c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]]))
            .collect();
        let mut it = words.into_iter();
        let mut scalars = [0.0; 11];
        for slot in &mut scalars {
            match it.next() {
                Some(v) => *slot = v,
                None => return Err(fail(self, "truncated state")),
            }
        }
        let mut vectors: Vec<Vec<f64>> = Vec::new();
        for _ in 0..10 {
            let Some(len) = it.next() else {
                return Err(fail(self, "truncated state"));
            };
            if !((0.0..=1e9).contains(&len) && len.fract() == 0.0) {
                return Err(fail(self, "corrupt vector length"));
            }
            let v: Vec<f64> = it.by_ref().take(len as usize).collect();
            if v.len() != len as usize {
                return Err(fail(self, "truncated state"));
            }
            vectors.push(v);
        }
        let current = self.sim.state();
        let expected = [
            current.u.len(),
            current.ud.len(),
            current.udd.len(),
            current.p.len(),
            current.pd.len(),
            current.pdd.len(),
            current.unbalance.len(),
            current.unbalance_rate.len(),
            current.unbalance_phase.len(),
            self.viscosity.len(),
        ];
        if vectors.iter().map(Vec::len).ne(expected.iter().copied()) || it.next().is_some() {
            return Err(fail(self, "the state belongs to a different model"));
        }
        let mut v = vectors.into_iter();
        let mut next = || v.next().unwrap_or_default();
        let sim = SimState {
            time: scalars[0],
            spin_angle: scalars[1],
            speed: scalars[2],
            speed_rate: scalars[3],
            speed_time: scalars[4],
            u: next(),
            ud: next(),
            udd: next(),
            p: next(),
            pd: next(),
            pdd: next(),
            unbalance: next(),
            unbalance_rate: next(),
            unbalance_phase: next(),
        };
        let viscosity = next();
        let phase = match scalars[10] as i32 {
            0 => Phase::Instantiated,
            1 => Phase::InitializationMode,
            2 => Phase::StepComplete,
            3 => Phase::StepFailed,
            4 => Phase::Terminated,
            _ => Phase::Error,
        };
        Ok(Snapshot {
            sim,
            params: Params {
                time_step: scalars[5],
                tolerance: scalars[6],
                max_iterations: scalars[7] as i32,
                ramp_time: scalars[8],
                gravity: scalars[9] != 0.0,
            },
            viscosity,
            phase,
        })
    }
}
