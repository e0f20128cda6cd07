//! Random call-sequence fuzzer of an unpacked FMU's C API, run as a child
//! process by `tests/fuzz.rs` (which enforces the timeout):
//!
//! `fmu_fuzz UNPACKED_FMU_DIR FIRST_SEED COUNT`
//!
//! Sequence `s` is replayed exactly by `fmu_fuzz DIR s 1`. It reads the
//! variables from the FMU's own `modelDescription.xml` (an outside importer's
//! view) and checks, per FMI 2.0 Co-Simulation:
//! - every status is one of the five the standard defines, and `fmi2DoStep` of
//!   a synchronous FMU never returns `fmi2Pending`;
//! - every value returned with `fmi2OK`/`fmi2Warning` is finite;
//! - calls the state machine forbids in the importer's current state (a
//!   `fmi2DoStep` before initialization, a second `fmi2SetupExperiment`, a set
//!   of a fixed parameter after initialization, of an output, of an unknown
//!   value reference, of NaN) return `fmi2Error`;
//! - a step past a defined stop time is refused, and so is a step too short to
//!   advance the time by the 1e-8 s the integrator resolves (down to 1e-300 s);
//! - the instance comes up from every spelling of the resource URI (scheme and
//!   host in any case, with a query or a fragment).
//!
//! A crash or hang is seen by the parent. Exit code 1 with the seed and the
//! call log on the first violation.

#![allow(non_snake_case)]

use std::ffi::{CStr, CString, c_char, c_void};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use fmi_sys::fmi2::*;

mod description;
mod invariants;
#[path = "../../tests/common/rng.rs"]
mod rng;
use description::{Var, read_description};
use rng::Rng;

/// Every message the instances of this process logged: status and text
/// (the rollback invariant compares a step's warnings with its replay's).
static LOG: Mutex<Vec<(fmi2Status, String)>> = Mutex::new(Vec::new());

/// Logger with the fixed arguments of the variadic `fmi2CallbackLogger` (the
/// FMU's messages carry no format arguments; extra variadic slots are ignored
/// by the C ABI).
extern "C" fn logger(
    _env: *mut c_void,
    _name: fmi2String,
    status: fmi2Status,
    _category: fmi2String,
    message: fmi2String,
) {
    if message.is_null() {
        return;
    }
    // SAFETY: the FMU passes a NUL-terminated message that lives for the call.
    let text = unsafe { CStr::from_ptr(message) };
    let text = text.to_string_lossy().replace("%%", "%");
    if let Ok(mut log) = LOG.lock() {
        log.push((status, text));
    }
}

/// The callbacks every instance gets: the logger above.
fn callbacks() -> fmi2CallbackFunctions {
    fmi2CallbackFunctions {
        // SAFETY: the same fixed-argument prefix as the variadic type; see `logger`.
        logger: unsafe {
            std::mem::transmute::<
                extern "C" fn(*mut c_void, fmi2String, fmi2Status, fmi2String, fmi2String),
                fmi2CallbackLogger,
            >(logger)
        },
        allocateMemory: None,
        freeMemory: None,
        stepFinished: None,
        componentEnvironment: std::ptr::null_mut::<c_void>(),
    }
}

/// The importer's view of the FMI 2.0 Co-Simulation state machine.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Phase {
    Instantiated,
    Initialization,
    StepComplete,
    StepFailed,
    Terminated,
    /// After `fmi2Error`: only reset, restore, get and free are meaningful.
    Error,
}

struct Fuzz<'a> {
    lib: &'a Fmi2Binding,
    c: fmi2Component,
    /// GUID and resource URI, for the fresh instances the state invariant
    /// restores into.
    guid: CString,
    uri: CString,
    vars: &'a [Var],
    rng: Rng,
    phase: Phase,
    time: f64,
    stop_time: Option<f64>,
    states: Vec<fmi2FMUstate>,
    /// The phase each state was saved in (restoring it restores the phase).
    state_phases: Vec<Phase>,
    log: Vec<String>,
    /// Print every call as it is made (set by `ROTOR_FUZZ_TRACE`, used by the
    /// parent to show the call a hang is stuck in).
    trace: bool,
}

fn status_name(s: fmi2Status) -> &'static str {
    match s {
        0 => "OK",
        1 => "Warning",
        2 => "Discard",
        3 => "Error",
        4 => "Fatal",
        5 => "Pending",
        _ => "INVALID",
    }
}

impl Fuzz<'_> {
    fn note(&mut self, entry: String) {
        if self.trace {
            eprintln!("{entry}");
        }
        self.log.push(entry);
    }

    fn calling(&self, call: &str) {
        if self.trace {
            eprintln!("calling {call} …");
        }
    }

    fn fail(&self, why: String) -> String {
        let tail: Vec<&String> = self.log.iter().rev().take(25).collect();
        let mut text = format!("{why}\nlast calls (newest first):\n");
        for line in tail {
            text.push_str("  ");
            text.push_str(line);
            text.push('\n');
        }
        if let Ok(log) = LOG.lock() {
            text.push_str("last messages the FMU logged (newest first):\n");
            for (s, m) in log.iter().rev().take(8) {
                text.push_str(&format!("  [{}] {m}\n", status_name(*s)));
            }
        }
        text
    }

    fn check_status(&self, call: &str, s: fmi2Status) -> Result<(), String> {
        if s > 4 || (s == 5 && call == "fmi2DoStep") {
            return Err(self.fail(format!("{call} returned status {s} ({})", status_name(s))));
        }
        Ok(())
    }

    /// A call the state machine forbids must give fmi2Error.
    fn expect_error(&self, call: &str, s: fmi2Status, why: &str) -> Result<(), String> {
        if s != fmi2Status_fmi2Error && s != fmi2Status_fmi2Fatal {
            return Err(self.fail(format!(
                "{call} returned {} but must return fmi2Error: {why}",
                status_name(s)
            )));
        }
        Ok(())
    }

    fn after(&mut self, s: fmi2Status) {
        if s == fmi2Status_fmi2Error || s == fmi2Status_fmi2Fatal {
            self.phase = Phase::Error;
        }
    }

    fn interesting_real(&mut self, var: &Var) -> f64 {
        let start = var.start.unwrap_or(1.0);
        // Inputs with a declared range (forces, ports, torques, excitations):
        // often a value within it, of any size down to a millionth of it.
        if let (Some(hi), true) = (var.max, self.rng.chance(0.4)) {
            let lo = var.min.unwrap_or(-hi);
            let size = hi.abs().max(lo.abs()) * self.rng.log_uniform(1e-6, 1.0);
            let signed = if lo < 0.0 && self.rng.chance(0.5) {
                -size
            } else {
                size
            };
            return signed.clamp(lo, hi);
        }
        match self.rng.below(14) {
            0 => f64::NAN,
            1 => f64::INFINITY,
            2 => -f64::INFINITY,
            3 => 0.0,
            4 => -start.abs().max(1.0),
            5 => 1e-300,
            6 => 1e300,
            7 => 1e5,
            8 => 1e-12,
            9 => 1e-7,
            _ => start * self.rng.log_uniform(0.25, 4.0),
        }
    }

    fn random_var(&mut self) -> &Var {
        let k = self.rng.below(self.vars.len());
        &self.vars[k]
    }

    fn set_real(&mut self) -> Result<(), String> {
        let unknown = self.rng.chance(0.05);
        let var = if unknown {
            Var {
                name: "<unknown>".into(),
                vr: 1_000_000 + self.rng.below(1000) as u32,
                causality: "none".into(),
                variability: "none".into(),
                kind: "Real",
                start: None,
                min: None,
                max: None,
            }
        } else {
            let v = self.random_var().clone();
            if v.kind != "Real" {
                return self.set_integer_or_boolean(&v);
            }
            v
        };
        let value = self.interesting_real(&var);
        let s = unsafe { self.lib.fmi2SetReal(self.c, &var.vr, 1, &value) };
        self.note(format!(
            "fmi2SetReal({} = {value:e}) → {}",
            var.name,
            status_name(s)
        ));
        self.check_status("fmi2SetReal", s)?;
        if self.phase != Phase::Error {
            let settable_now = match var.causality.as_str() {
                "input" => self.phase != Phase::Terminated,
                "parameter" => match self.phase {
                    Phase::Instantiated | Phase::Initialization => true,
                    Phase::StepComplete | Phase::StepFailed => var.variability == "tunable",
                    _ => false,
                },
                _ => false,
            };
            if unknown {
                self.expect_error("fmi2SetReal", s, "unknown value reference")?;
            } else if !settable_now {
                self.expect_error(
                    "fmi2SetReal",
                    s,
                    &format!(
                        "{} ({}, {}) is not settable in {:?}",
                        var.name, var.causality, var.variability, self.phase
                    ),
                )?;
            } else if value.is_nan() {
                self.expect_error("fmi2SetReal", s, "NaN is not a value")?;
            }
        }
        self.after(s);
        Ok(())
    }

    fn set_integer_or_boolean(&mut self, var: &Var) -> Result<(), String> {
        let s = if var.kind == "Integer" {
            let value: fmi2Integer = match self.rng.below(5) {
                0 => i32::MIN,
                1 => -1,
                2 => 0,
                3 => i32::MAX,
                _ => 1 + self.rng.below(100) as i32,
            };
            let s = unsafe { self.lib.fmi2SetInteger(self.c, &var.vr, 1, &value) };
            self.note(format!(
                "fmi2SetInteger({} = {value}) → {}",
                var.name,
                status_name(s)
            ));
            s
        } else {
            let value: fmi2Boolean = self.rng.below(3) as i32;
            let s = unsafe { self.lib.fmi2SetBoolean(self.c, &var.vr, 1, &value) };
            self.note(format!(
                "fmi2SetBoolean({} = {value}) → {}",
                var.name,
                status_name(s)
            ));
            s
        };
        self.check_status("fmi2Set", s)?;
        self.after(s);
        Ok(())
    }

    fn get_all(&mut self) -> Result<(), String> {
        let reals: Vec<&Var> = self.vars.iter().filter(|v| v.kind == "Real").collect();
        let refs: Vec<u32> = reals.iter().map(|v| v.vr).collect();
        let mut values = vec![0.0; refs.len()];
        let s = unsafe {
            self.lib
                .fmi2GetReal(self.c, refs.as_ptr(), refs.len(), values.as_mut_ptr())
        };
        self.note(format!("fmi2GetReal(all) → {}", status_name(s)));
        self.check_status("fmi2GetReal", s)?;
        self.after(s);
        if s <= fmi2Status_fmi2Warning {
            for (v, x) in reals.iter().zip(&values) {
                if !x.is_finite() {
                    return Err(self.fail(format!(
                        "fmi2GetReal gave {} = {x} with {}",
                        v.name,
                        status_name(s)
                    )));
                }
            }
            self.check_power_losses()?;
        }
        let mut t = 0.0;
        let s = unsafe {
            self.lib
                .fmi2GetRealStatus(self.c, fmi2StatusKind_fmi2LastSuccessfulTime, &mut t)
        };
        self.note(format!(
            "fmi2GetRealStatus(LastSuccessfulTime) = {t} → {}",
            status_name(s)
        ));
        self.check_status("fmi2GetRealStatus", s)?;
        self.after(s);
        if s <= fmi2Status_fmi2Warning && !t.is_finite() {
            return Err(self.fail(format!(
                "fmi2GetRealStatus(LastSuccessfulTime) = {t} with {}",
                status_name(s)
            )));
        }
        Ok(())
    }

    fn do_step(&mut self) -> Result<(), String> {
        let h = match self.rng.below(10) {
            0 => -1e-3,
            1 => 0.0,
            2 if self.rng.chance(0.2) => self.rng.log_uniform(1e-300, 0.99e-8),
            2 => self.rng.log_uniform(1e-8, 1e-5),
            3 => self.rng.log_uniform(0.05, 0.3),
            _ => self.rng.log_uniform(1e-4, 2e-2),
        };
        let t = if self.rng.chance(0.9) {
            self.time
        } else {
            self.time + self.rng.log_uniform(1e-6, 1.0)
        };
        let s = if self.phase == Phase::StepComplete
            && t == self.time
            && h >= 1e-6
            && self.rng.chance(0.25)
        {
            // Replayed from a state saved before it: the same step twice.
            self.replayed_step(t, h)?
        } else {
            self.calling(&format!("fmi2DoStep(t = {t}, h = {h:e})"));
            let s = unsafe { self.lib.fmi2DoStep(self.c, t, h, fmi2True as fmi2Boolean) };
            self.note(format!(
                "fmi2DoStep(t = {t}, h = {h:e}) → {}",
                status_name(s)
            ));
            self.check_status("fmi2DoStep", s)?;
            s
        };
        if self.phase != Phase::Error {
            if self.phase != Phase::StepComplete {
                self.expect_error(
                    "fmi2DoStep",
                    s,
                    &format!("no step is allowed in {:?}", self.phase),
                )?;
            } else if h < 0.0 {
                self.expect_error("fmi2DoStep", s, "negative communication step")?;
            } else if t == self.time && (t + h) - t < 1e-8 {
                self.expect_error(
                    "fmi2DoStep",
                    s,
                    "a step that does not advance the time by the 1e-8 s the integrator resolves",
                )?;
            } else if let Some(stop) = self.stop_time
                && t == self.time
                && t + h > stop * (1.0 + 1e-12) + 1e-12
            {
                self.expect_error(
                    "fmi2DoStep",
                    s,
                    &format!("t + h = {} is past the stop time {stop}", t + h),
                )?;
            }
        }
        match s {
            0 | 1 if self.phase == Phase::StepComplete => self.time = t + h,
            2 => self.phase = Phase::StepFailed,
            _ => self.after(s),
        }
        Ok(())
    }

    fn state_calls(&mut self) -> Result<(), String> {
        match self.rng.below(4) {
            0 => {
                let mut state: fmi2FMUstate = std::ptr::null_mut();
                let s = unsafe { self.lib.fmi2GetFMUstate(self.c, &mut state) };
                self.note(format!("fmi2GetFMUstate → {}", status_name(s)));
                self.check_status("fmi2GetFMUstate", s)?;
                if s == fmi2Status_fmi2OK && !state.is_null() {
                    self.states.push(state);
                    self.state_phases.push(self.phase);
                    self.check_restorable(state)?;
                }
                self.after(s);
            }
            1 if !self.states.is_empty() => {
                let k = self.rng.below(self.states.len());
                let s = unsafe { self.lib.fmi2SetFMUstate(self.c, self.states[k]) };
                self.note(format!("fmi2SetFMUstate(#{k}) → {}", status_name(s)));
                self.check_status("fmi2SetFMUstate", s)?;
                if s == fmi2Status_fmi2OK {
                    self.phase = self.state_phases[k];
                    self.time = self.restored_time();
                }
            }
            2 => self.serialize_round_trip()?,
            _ if !self.states.is_empty() => {
                let k = self.rng.below(self.states.len());
                let mut state = self.states.swap_remove(k);
                self.state_phases.swap_remove(k);
                let s = unsafe { self.lib.fmi2FreeFMUstate(self.c, &mut state) };
                self.note(format!("fmi2FreeFMUstate → {}", status_name(s)));
                self.check_status("fmi2FreeFMUstate", s)?;
            }
            _ => {}
        }
        Ok(())
    }

    /// The time of a state just restored: its last successful time where
    /// the status query is allowed, else the start (before initialization).
    fn restored_time(&mut self) -> f64 {
        if !matches!(
            self.phase,
            Phase::StepComplete | Phase::StepFailed | Phase::Terminated
        ) {
            return 0.0;
        }
        let mut t = 0.0;
        // SAFETY: `c` is live; `t` receives the time.
        unsafe {
            self.lib
                .fmi2GetRealStatus(self.c, fmi2StatusKind_fmi2LastSuccessfulTime, &mut t)
        };
        t
    }

    fn serialize_round_trip(&mut self) -> Result<(), String> {
        let Some(&state) = self.states.last() else {
            return Ok(());
        };
        let mut size = 0usize;
        let s = unsafe {
            self.lib
                .fmi2SerializedFMUstateSize(self.c, state, &mut size)
        };
        self.check_status("fmi2SerializedFMUstateSize", s)?;
        self.after(s);
        if s != fmi2Status_fmi2OK || size > 1 << 30 {
            return Ok(());
        }
        let mut bytes = vec![0 as c_char; size];
        let s = unsafe {
            self.lib
                .fmi2SerializeFMUstate(self.c, state, bytes.as_mut_ptr(), size)
        };
        self.check_status("fmi2SerializeFMUstate", s)?;
        self.after(s);
        let how = match self.rng.below(5) {
            0 => {
                let cut = self.rng.below(size.max(1));
                bytes.truncate(cut);
                format!("truncated to {cut}")
            }
            1 if size > 0 => {
                let bit = self.rng.below(size * 8);
                bytes[bit / 8] ^= (1u8 << (bit % 8)) as c_char;
                format!("bit {bit} flipped")
            }
            2 => {
                for b in bytes.iter_mut() {
                    *b = self.rng.next() as c_char;
                }
                "random bytes".to_string()
            }
            _ => "intact".to_string(),
        };
        let mut restored: fmi2FMUstate = std::ptr::null_mut();
        let s = unsafe {
            self.lib
                .fmi2DeSerializeFMUstate(self.c, bytes.as_ptr(), bytes.len(), &mut restored)
        };
        self.note(format!(
            "fmi2DeSerializeFMUstate({how}) → {}",
            status_name(s)
        ));
        self.check_status("fmi2DeSerializeFMUstate", s)?;
        self.after(s);
        if s == fmi2Status_fmi2OK && !restored.is_null() {
            self.states.push(restored);
            let phase = self.state_phases[self.state_phases.len() - 1];
            self.state_phases.push(phase);
        }
        Ok(())
    }

    fn lifecycle(&mut self) -> Result<(), String> {
        match self.rng.below(6) {
            0 => {
                let stop_defined = self.rng.chance(0.5);
                let stop = self.rng.log_uniform(0.01, 2.0);
                let s = unsafe {
                    self.lib
                        .fmi2SetupExperiment(self.c, 0, 0.0, 0.0, stop_defined as i32, stop)
                };
                self.note(format!(
                    "fmi2SetupExperiment(stop {stop_defined}: {stop}) → {}",
                    status_name(s)
                ));
                self.check_status("fmi2SetupExperiment", s)?;
                if self.phase != Phase::Error && self.phase != Phase::Instantiated {
                    self.expect_error(
                        "fmi2SetupExperiment",
                        s,
                        &format!("only before initialization, not in {:?}", self.phase),
                    )?;
                }
                if s == fmi2Status_fmi2OK && self.phase == Phase::Instantiated {
                    self.stop_time = stop_defined.then_some(stop);
                }
                self.after(s);
            }
            1 => {
                // SAFETY: `c` is a live instance of `lib`.
                let s = unsafe { self.lib.fmi2EnterInitializationMode(self.c) };
                self.transition(
                    "fmi2EnterInitializationMode",
                    s,
                    Phase::Instantiated,
                    Phase::Initialization,
                )?;
            }
            2 => {
                // SAFETY: as above.
                let s = unsafe { self.lib.fmi2ExitInitializationMode(self.c) };
                self.transition(
                    "fmi2ExitInitializationMode",
                    s,
                    Phase::Initialization,
                    Phase::StepComplete,
                )?;
            }
            3 => {
                let s = unsafe { self.lib.fmi2Terminate(self.c) };
                self.note(format!("fmi2Terminate → {}", status_name(s)));
                self.check_status("fmi2Terminate", s)?;
                if s <= fmi2Status_fmi2Warning
                    && matches!(self.phase, Phase::StepComplete | Phase::StepFailed)
                {
                    self.phase = Phase::Terminated;
                }
                self.after(s);
            }
            4 => {
                let s = unsafe { self.lib.fmi2Reset(self.c) };
                self.note(format!("fmi2Reset → {}", status_name(s)));
                self.check_status("fmi2Reset", s)?;
                if s <= fmi2Status_fmi2Warning {
                    self.phase = Phase::Instantiated;
                    self.time = 0.0;
                    self.stop_time = None;
                }
            }
            _ => self.input_derivative()?,
        }
        Ok(())
    }

    /// A phase change `from → to` answered with `s`: only allowed in `from`.
    fn transition(
        &mut self,
        call: &str,
        s: fmi2Status,
        from: Phase,
        to: Phase,
    ) -> Result<(), String> {
        self.note(format!("{call} → {}", status_name(s)));
        self.check_status(call, s)?;
        if self.phase != Phase::Error && self.phase != from {
            self.expect_error(call, s, &format!("not in {:?}", self.phase))?;
        }
        if s <= fmi2Status_fmi2Warning && self.phase == from {
            self.phase = to;
        }
        self.after(s);
        Ok(())
    }

    /// Initialize the normal way (most sequences should reach stepping).
    fn initialize(&mut self) -> Result<(), String> {
        let stop_defined = self.rng.chance(0.3);
        let stop = self.rng.log_uniform(0.02, 1.0);
        let s = unsafe {
            self.lib
                .fmi2SetupExperiment(self.c, 0, 0.0, 0.0, stop_defined as i32, stop)
        };
        self.note(format!(
            "fmi2SetupExperiment(stop {stop_defined}: {stop}) → {}",
            status_name(s)
        ));
        self.check_status("fmi2SetupExperiment", s)?;
        if s == fmi2Status_fmi2OK {
            self.stop_time = stop_defined.then_some(stop);
        }
        let s = unsafe { self.lib.fmi2EnterInitializationMode(self.c) };
        self.note(format!("fmi2EnterInitializationMode → {}", status_name(s)));
        self.check_status("fmi2EnterInitializationMode", s)?;
        self.phase = Phase::Initialization;
        if self.rng.chance(0.5) {
            self.set_real()?;
        }
        if self.phase == Phase::Error {
            return Ok(());
        }
        let s = unsafe { self.lib.fmi2ExitInitializationMode(self.c) };
        self.note(format!("fmi2ExitInitializationMode → {}", status_name(s)));
        self.check_status("fmi2ExitInitializationMode", s)?;
        self.phase = if s <= fmi2Status_fmi2Warning {
            Phase::StepComplete
        } else {
            Phase::Error
        };
        Ok(())
    }

    fn run(&mut self, calls: usize) -> Result<(), String> {
        if self.rng.chance(0.8) {
            self.initialize()?;
        }
        for _ in 0..calls {
            if self.phase == Phase::Error && self.rng.chance(0.5) {
                // The standard's ways out of an error: reset, or restore a state.
                if !self.states.is_empty() && self.rng.chance(0.5) {
                    let s = unsafe { self.lib.fmi2SetFMUstate(self.c, self.states[0]) };
                    self.note(format!(
                        "fmi2SetFMUstate(#0) after error → {}",
                        status_name(s)
                    ));
                    self.check_status("fmi2SetFMUstate", s)?;
                    if s == fmi2Status_fmi2OK {
                        self.phase = self.state_phases[0];
                        self.time = self.restored_time();
                    }
                } else {
                    let s = unsafe { self.lib.fmi2Reset(self.c) };
                    self.note(format!("fmi2Reset after error → {}", status_name(s)));
                    self.check_status("fmi2Reset", s)?;
                    if s == fmi2Status_fmi2OK {
                        self.phase = Phase::Instantiated;
                        self.time = 0.0;
                        self.stop_time = None;
                    }
                }
                continue;
            }
            match self.rng.below(20) {
                0..=6 => self.do_step()?,
                7..=10 => self.set_real()?,
                11..=13 => self.get_all()?,
                14..=16 => self.state_calls()?,
                _ => self.lifecycle()?,
            }
        }
        self.get_all()
    }
}

fn run_sequence(
    dir: &Path,
    lib: &Fmi2Binding,
    guid: &str,
    vars: &[Var],
    seed: u64,
) -> Result<(), String> {
    let name = CString::new(format!("fuzz{seed}")).unwrap();
    let guid = CString::new(guid).unwrap();
    // Every spelling of a local file URI an importer may pass: scheme and host
    // in any case, with or without an authority, a query or a fragment (which
    // are not part of the path).
    let scheme = [
        "file://",
        "FILE://",
        "file://localhost",
        "File://LocalHost",
        "file:",
    ];
    let tail = ["", "?fuzz=1", "#resources", "?a=b#c"];
    let uri = format!(
        "{}{}{}",
        scheme[(seed % 5) as usize],
        dir.join("resources").display(),
        tail[((seed / 5) % 4) as usize]
    );
    let uri = CString::new(uri).unwrap();
    let callbacks = callbacks();
    if let Ok(mut log) = LOG.lock() {
        log.clear();
    }
    // Logging on: the rollback invariant compares the warnings logged.
    let c = unsafe {
        lib.fmi2Instantiate(
            name.as_ptr(),
            fmi2Type_fmi2CoSimulation,
            guid.as_ptr(),
            uri.as_ptr(),
            &callbacks,
            0,
            1,
        )
    };
    if c.is_null() {
        return Err(format!("seed {seed}: fmi2Instantiate returned NULL"));
    }
    let mut rng = Rng(seed);
    let calls = 5 + rng.below(40);
    let mut fuzz = Fuzz {
        lib,
        c,
        guid: guid.clone(),
        uri: uri.clone(),
        vars,
        rng,
        phase: Phase::Instantiated,
        time: 0.0,
        stop_time: None,
        states: Vec::new(),
        state_phases: Vec::new(),
        log: Vec::new(),
        trace: std::env::var_os("ROTOR_FUZZ_TRACE").is_some(),
    };
    let result = fuzz.run(calls);
    for mut state in std::mem::take(&mut fuzz.states) {
        unsafe { lib.fmi2FreeFMUstate(c, &mut state) };
    }
    unsafe { lib.fmi2FreeInstance(c) };
    result.map_err(|e| format!("seed {seed}: {e}"))
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.len() != 4 {
        eprintln!("usage: fmu_fuzz UNPACKED_FMU_DIR FIRST_SEED COUNT");
        std::process::exit(2);
    }
    let dir = PathBuf::from(&args[1]);
    let first: u64 = args[2].parse().expect("FIRST_SEED");
    let count: u64 = args[3].parse().expect("COUNT");
    let (guid, vars) = read_description(&dir.join("modelDescription.xml")).unwrap_or_else(|e| {
        eprintln!("{e}");
        std::process::exit(2)
    });
    let so = std::fs::read_dir(dir.join("binaries/linux64"))
        .expect("binaries/linux64")
        .map(|e| e.unwrap().path())
        .find(|p| p.extension().is_some_and(|x| x == "so"))
        .expect("a shared library in binaries/linux64");
    let lib = unsafe { Fmi2Binding::new(&so) }.expect("load the FMU binary");
    for seed in first..first + count {
        // The parent reads the last seed printed to name a crash or a hang.
        println!("seed {seed}");
        if let Err(e) = run_sequence(&dir, &lib, &guid, &vars, seed) {
            eprintln!("{e}");
            std::process::exit(1);
        }
    }
}
