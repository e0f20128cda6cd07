//! Random call-sequence fuzzer of an unpacked FMI 3.0 FMU's C API, run as a
//! child process by `tests/fuzz3.rs` (which enforces the timeout):
//!
//! `fmu3_fuzz UNPACKED_FMU_DIR FIRST_SEED COUNT`
//!
//! Sequence `s` is replayed exactly by `fmu3_fuzz DIR s 1`. It reads the
//! variables from the FMU's own `modelDescription.xml` and drives random
//! sequences of the FMI 3.0 calls (sets of in-range, out-of-range and
//! non-finite values, reads, initialization, steps of every size including
//! zero, negative, NaN and 1e-300 s, early return allowed or not, FMU states
//! saved, serialized, corrupted and restored, reset, terminate, the calls the
//! FMU does not provide, NULL arguments), checking per FMI 3.0 Co-Simulation:
//! - every status is one of the five the standard defines;
//! - every value returned with fmi3OK/fmi3Warning is finite;
//! - calls the state machine forbids in the importer's current state, a
//!   non-finite set value, a step that is not positive, a corrupted state, a
//!   NULL argument and the functions the FMU does not provide return fmi3Error;
//! - a step that succeeds ends at its communication point, or earlier (in
//!   the step) only when early return was allowed and it says so;
//! - half the sequences instantiate with an `intermediateUpdate` callback
//!   ([`Updates`]): its times increase inside the step, up to its end, with
//!   set requested false and step finished true; in it, an output read gives
//!   fmi3OK and a finite value (or fmi3Error), a read of any other variable
//!   and every other call (a step, a set, terminate, reset, an FMU state,
//!   free) fmi3Error; it asks for early returns at random times (the
//!   internal step's, NaN, ±infinity, the step's start, middle and end).
//!
//! A crash or hang is seen by the parent. Exit code 1 with the seed and the
//! call log on the first violation.

#![allow(non_snake_case)]

use std::cell::{Cell, RefCell};
use std::ffi::{CString, c_void};
use std::path::Path;
use std::ptr::{null, null_mut};

use fmi_sys::fmi3::*;
use quick_xml::Reader;
use quick_xml::events::Event;

#[path = "../tests/common/rng.rs"]
mod rng;
use rng::Rng;

/// A variable as the FMI 3.0 model description declares it.
#[derive(Debug, Clone)]
struct Var {
    name: String,
    vr: u32,
    causality: String,
    variability: String,
    kind: String,
    min: Option<f64>,
    max: Option<f64>,
}

fn attr(e: &quick_xml::events::BytesStart, key: &[u8]) -> Option<String> {
    e.attributes()
        .flatten()
        .find(|a| a.key.as_ref() == key)
        .map(|a| String::from_utf8_lossy(&a.value).into_owned())
}

/// The instantiation token and the variables of a model description.
fn read_description(path: &Path) -> (String, Vec<Var>) {
    let text = std::fs::read_to_string(path).expect("modelDescription.xml");
    let mut reader = Reader::from_str(&text);
    let (mut token, mut vars) = (String::new(), Vec::new());
    loop {
        match reader.read_event().expect("well-formed XML") {
            Event::Start(e) | Event::Empty(e) => {
                let name = String::from_utf8_lossy(e.name().as_ref()).into_owned();
                if name == "fmiModelDescription" {
                    token = attr(&e, b"instantiationToken").unwrap_or_default();
                } else if ["Float64", "Int32", "Boolean"].contains(&name.as_str())
                    && let Some(vr) = attr(&e, b"valueReference")
                {
                    vars.push(Var {
                        name: attr(&e, b"name").unwrap_or_default(),
                        vr: vr.parse().unwrap(),
                        causality: attr(&e, b"causality").unwrap_or_default(),
                        variability: attr(&e, b"variability").unwrap_or_default(),
                        kind: name,
                        min: attr(&e, b"min").and_then(|s| s.parse().ok()),
                        max: attr(&e, b"max").and_then(|s| s.parse().ok()),
                    });
                }
            }
            Event::Eof => break,
            _ => {}
        }
    }
    (token, vars)
}

unsafe extern "C" fn logger(
    _env: fmi3InstanceEnvironment,
    _status: fmi3Status,
    _category: fmi3String,
    _message: fmi3String,
) {
}

/// The importer's side of one sequence's intermediate updates (the
/// environment of its callback and logger): what it reads and calls from
/// inside the step, and what broke the rules there.
struct Updates {
    lib: *const Fmi3Binding,
    instance: Cell<fmi3Instance>,
    /// The callback's own random stream (SplitMix64 state).
    rng: Cell<u64>,
    /// Scalar Float64 outputs, and the other variables.
    outputs: Vec<u32>,
    others: Vec<u32>,
    /// The step's start and end, and the last update's time in it.
    window: Cell<(f64, f64, f64)>,
    calls: Cell<usize>,
    violations: RefCell<Vec<String>>,
}

impl Updates {
    fn below(&self, n: usize) -> usize {
        let mut r = Rng(self.rng.get());
        let x = r.next();
        self.rng.set(r.0);
        (x % n as u64) as usize
    }

    fn bad(&self, why: String) {
        self.violations.borrow_mut().push(why);
    }
}

#[allow(clippy::too_many_arguments)]
unsafe extern "C" fn intermediate_update(
    env: fmi3InstanceEnvironment,
    time: fmi3Float64,
    set_requested: fmi3Boolean,
    get_allowed: fmi3Boolean,
    step_finished: fmi3Boolean,
    _can_return_early: fmi3Boolean,
    early_return_requested: *mut fmi3Boolean,
    early_return_time: *mut fmi3Float64,
) {
    // SAFETY: the environment is the sequence's `Updates`, alive while its
    // instance is; the fuzzer's library outlives every instance; the
    // out-parameters point to the FMU's writable locals.
    let (u, lib, requested, at) = unsafe {
        let u = &*env.cast::<Updates>();
        (
            u,
            &*u.lib,
            &mut *early_return_requested,
            &mut *early_return_time,
        )
    };
    let i = u.instance.get();
    u.calls.set(u.calls.get() + 1);
    let (start, end, last) = u.window.get();
    if !(time > last && time > start && time <= end) || set_requested || !step_finished {
        u.bad(format!(
            "intermediate update at {time} after {last} in ({start}, {end}], set requested {set_requested}, finished {step_finished}"
        ));
    }
    u.window.set((start, end, time));
    let mut one = [f64::NAN];
    match u.below(8) {
        0..=2 if !u.outputs.is_empty() => {
            let vr = u.outputs[u.below(u.outputs.len())];
            // SAFETY: a live instance, one reference, one value.
            let s = unsafe { lib.fmi3GetFloat64(i, &vr, 1, one.as_mut_ptr(), 1) };
            let fine = (s == fmi3Status_fmi3OK && one[0].is_finite())
                || s == fmi3Status_fmi3Error
                || !get_allowed;
            if !fine {
                u.bad(format!(
                    "intermediate read of output {vr}: status {s}, value {}",
                    one[0]
                ));
            }
        }
        3 if !u.others.is_empty() => {
            let vr = u.others[u.below(u.others.len())];
            // SAFETY: a live instance, one reference, one value.
            let s = unsafe { lib.fmi3GetFloat64(i, &vr, 1, one.as_mut_ptr(), 1) };
            if s != fmi3Status_fmi3Error {
                u.bad(format!("intermediate read of non-output {vr}: status {s}"));
            }
        }
        4 | 5 => {
            let (mut e, mut t, mut r, mut l) = (false, false, false, 0.0);
            let mut state: fmi3FMUState = null_mut();
            let which = u.below(6);
            // SAFETY: a live instance, writable out-parameters; each call
            // must be refused without touching the instance.
            let s = unsafe {
                match which {
                    0 => lib.fmi3DoStep(i, time, 1e-3, false, &mut e, &mut t, &mut r, &mut l),
                    1 => lib.fmi3SetFloat64(i, &0, 1, &1.0, 1),
                    2 => lib.fmi3Terminate(i),
                    3 => lib.fmi3Reset(i),
                    4 => lib.fmi3GetFMUState(i, &mut state),
                    _ => {
                        lib.fmi3FreeInstance(i);
                        fmi3Status_fmi3Error
                    }
                }
            };
            if s != fmi3Status_fmi3Error || !state.is_null() {
                u.bad(format!(
                    "call {which} inside the intermediate update: status {s}"
                ));
            }
        }
        _ => {}
    }
    if u.below(6) == 0 {
        *requested = true;
        *at = [
            time,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            start,
            0.5 * (time + end),
            end,
            time + 1e-12,
        ][u.below(8)];
    }
}

/// Where the importer believes the instance is.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Phase {
    Instantiated,
    Initialization,
    Step,
    StepFailed,
    Terminated,
    Error,
}

struct Fuzz<'a> {
    lib: &'a Fmi3Binding,
    vars: &'a [Var],
    rng: Rng,
    i: fmi3Instance,
    phase: Phase,
    time: f64,
    early_allowed: bool,
    log: Vec<String>,
    /// Steps that advanced the time, and of those that returned early.
    steps: usize,
    early_returns: usize,
    /// Whether this sequence runs a rub ([`Fuzz::rub`]): it then mostly steps.
    rubbing: bool,
    /// The intermediate updates, when the sequence asked for them.
    updates: Option<&'a Updates>,
}

impl Fuzz<'_> {
    /// Record a call and its status; a status outside the standard's five is
    /// a violation.
    fn status(&mut self, call: String, s: fmi3Status) -> Result<fmi3Status, String> {
        self.log.push(format!("{call} -> {s}"));
        if s > fmi3Status_fmi3Fatal {
            return Err(format!("{call} returned status {s}"));
        }
        if s == fmi3Status_fmi3Error || s == fmi3Status_fmi3Fatal {
            self.phase = Phase::Error;
        }
        Ok(s)
    }

    fn expect_error(&mut self, call: String, s: fmi3Status) -> Result<(), String> {
        let s = self.status(call.clone(), s)?;
        if s != fmi3Status_fmi3Error {
            return Err(format!("{call} returned {s}, not fmi3Error"));
        }
        Ok(())
    }

    fn var(&mut self) -> Var {
        self.vars[self.rng.below(self.vars.len())].clone()
    }

    fn value(&mut self, v: &Var) -> f64 {
        match self.rng.below(40) {
            0 => f64::NAN,
            1 => f64::INFINITY,
            2 => 1e300,
            3 | 4 => v.min.unwrap_or(-1.0),
            5 | 6 => v.max.unwrap_or(1.0),
            _ => {
                let (lo, hi) = (v.min.unwrap_or(-10.0), v.max.unwrap_or(10.0));
                let hi = if hi - lo > 1e6 { lo + 1e6 } else { hi };
                lo + (hi - lo) * self.rng.unit()
            }
        }
    }

    fn set(&mut self) -> Result<(), String> {
        let v = self.var();
        let value = self.value(&v);
        let refs = [v.vr];
        let s = match v.kind.as_str() {
            "Float64" => {
                // SAFETY: one reference, one value.
                unsafe {
                    self.lib
                        .fmi3SetFloat64(self.i, refs.as_ptr(), 1, [value].as_ptr(), 1)
                }
            }
            "Int32" => {
                let x = if value.is_finite() {
                    value.clamp(-1e9, 1e9) as i32
                } else {
                    -1
                };
                // SAFETY: one reference, one value.
                unsafe {
                    self.lib
                        .fmi3SetInt32(self.i, refs.as_ptr(), 1, [x].as_ptr(), 1)
                }
            }
            _ => {
                // SAFETY: one reference, one value.
                unsafe {
                    self.lib
                        .fmi3SetBoolean(self.i, refs.as_ptr(), 1, [value > 0.5].as_ptr(), 1)
                }
            }
        };
        let call = format!("set {} {} = {value}", v.kind, v.vr);
        let forbidden = matches!(
            self.phase,
            Phase::StepFailed | Phase::Terminated | Phase::Error
        ) || v.causality == "output"
            || v.causality == "independent"
            || (v.variability == "fixed" && self.phase == Phase::Step);
        if forbidden || (v.kind == "Float64" && !value.is_finite()) {
            return self.expect_error(call, s);
        }
        self.status(call, s).map(|_| ())
    }

    fn get(&mut self) -> Result<(), String> {
        let n = 1 + self.rng.below(4);
        let mut refs: Vec<u32> = (0..n).map(|_| self.var().vr).collect();
        if self.rng.chance(0.1) {
            refs.push(123_456_789);
        }
        let mut out = vec![0.0f64; refs.len()];
        let floats = refs
            .iter()
            .all(|r| self.vars.iter().any(|v| v.vr == *r && v.kind == "Float64"));
        // SAFETY: arrays of the lengths passed.
        let s = unsafe {
            self.lib.fmi3GetFloat64(
                self.i,
                refs.as_ptr(),
                refs.len(),
                out.as_mut_ptr(),
                out.len(),
            )
        };
        let call = format!("getFloat64 {refs:?}");
        if !floats || self.phase == Phase::Instantiated {
            return self.expect_error(call, s);
        }
        let s = self.status(call.clone(), s)?;
        if (s == fmi3Status_fmi3OK || s == fmi3Status_fmi3Warning)
            && out.iter().any(|x| !x.is_finite())
        {
            return Err(format!("{call} returned {out:?} with status {s}"));
        }
        Ok(())
    }

    fn step(&mut self) -> Result<(), String> {
        let h = [
            1e-3,
            1e-2,
            0.05,
            0.0,
            -1e-3,
            1e-300,
            f64::NAN,
            2e-3,
            1e-2,
            1e-3,
            5e-3,
            2e-2,
        ][self.rng.below(12)];
        let t = if self.rng.chance(0.05) {
            self.time + 1.0
        } else {
            self.time
        };
        let (mut event, mut terminate, mut early, mut last) = (false, false, false, f64::NAN);
        if let Some(u) = self.updates {
            u.window.set((t, t + h, t));
        }
        // SAFETY: a live instance, writable out-parameters.
        let s = unsafe {
            self.lib.fmi3DoStep(
                self.i,
                t,
                h,
                false,
                &mut event,
                &mut terminate,
                &mut early,
                &mut last,
            )
        };
        let call = format!("doStep({t}, {h})");
        if let Some(u) = self.updates {
            let violations = u.violations.take();
            if !violations.is_empty() {
                return Err(format!("{call}: {}", violations.join("; ")));
            }
        }
        if self.phase != Phase::Step || !(h.is_finite() && h > 0.0) || h < 1e-8 || t != self.time {
            return self.expect_error(call, s);
        }
        let s = self.status(call.clone(), s)?;
        if s == fmi3Status_fmi3Discard {
            self.phase = Phase::StepFailed;
        }
        if s == fmi3Status_fmi3OK || s == fmi3Status_fmi3Warning {
            let end = t + h;
            let fine = if early {
                self.early_allowed && last > t && last < end
            } else {
                last == end
            };
            if !fine || event || terminate {
                return Err(format!(
                    "{call}: early {early} (allowed {}), last {last}, event {event}, terminate {terminate}",
                    self.early_allowed
                ));
            }
            self.time = last;
            self.steps += 1;
            self.early_returns += usize::from(early);
        }
        Ok(())
    }

    fn states(&mut self) -> Result<(), String> {
        let mut state: fmi3FMUState = null_mut();
        // SAFETY: a live instance, a writable state slot.
        let s = unsafe { self.lib.fmi3GetFMUState(self.i, &mut state) };
        if self.status("getFMUState".into(), s)? != fmi3Status_fmi3OK {
            return Ok(());
        }
        let mut size = 0usize;
        // SAFETY: a live state, a writable size.
        let s = unsafe {
            self.lib
                .fmi3SerializedFMUStateSize(self.i, state, &mut size)
        };
        self.status("serializedFMUStateSize".into(), s)?;
        let mut bytes = vec![0u8; size];
        // SAFETY: a buffer of `size` bytes.
        let s = unsafe {
            self.lib
                .fmi3SerializeFMUState(self.i, state, bytes.as_mut_ptr(), size)
        };
        self.status("serializeFMUState".into(), s)?;
        let corrupt = self.rng.chance(0.3) && !bytes.is_empty();
        if corrupt {
            let k = self.rng.below(bytes.len());
            bytes[k] ^= 1 << self.rng.below(8);
        }
        let mut back: fmi3FMUState = null_mut();
        // SAFETY: `bytes.len()` bytes, a writable state slot.
        let s = unsafe {
            self.lib
                .fmi3DeserializeFMUState(self.i, bytes.as_ptr(), bytes.len(), &mut back)
        };
        let call = format!("deserializeFMUState (corrupted: {corrupt})");
        if corrupt {
            self.expect_error(call, s)?;
        } else if self.status(call, s)? == fmi3Status_fmi3OK {
            let phase = self.phase;
            // SAFETY: a live state of this instance.
            let s = unsafe { self.lib.fmi3SetFMUState(self.i, back) };
            if self.status("setFMUState".into(), s)? == fmi3Status_fmi3OK {
                self.phase = phase;
            }
        }
        // SAFETY: the states made above, freed once (NULL slots are skipped).
        unsafe {
            if !back.is_null() {
                self.lib.fmi3FreeFMUState(self.i, &mut back);
            }
            self.lib.fmi3FreeFMUState(self.i, &mut state);
        }
        Ok(())
    }

    /// A machine running into its bearings: 3000 rpm and 0.5 kg·m in every
    /// unbalance plane (the Jeffcott rotor's journals touch at 42 ms), so
    /// that steps return early.
    fn rub(&mut self) -> Result<(), String> {
        for v in self.vars {
            if v.causality != "input" {
                continue;
            }
            let value = if v.name == "shaft.speed" {
                314.159
            } else if v.name.starts_with("unbalance.") && !v.name.ends_with(".phase") {
                0.5
            } else {
                continue;
            };
            // SAFETY: one reference, one value.
            let s = unsafe {
                self.lib
                    .fmi3SetFloat64(self.i, [v.vr].as_ptr(), 1, [value].as_ptr(), 1)
            };
            self.status(format!("rub: set {} = {value}", v.name), s)?;
        }
        self.rubbing = true;
        Ok(())
    }

    fn action(&mut self) -> Result<(), String> {
        // An importer mostly recovers from an error by a reset, and mostly
        // initializes a fresh instance.
        if self.phase == Phase::Error && self.rng.chance(0.7) {
            // SAFETY: a live instance.
            let s = unsafe { self.lib.fmi3Reset(self.i) };
            self.status("reset".into(), s)?;
            self.phase = Phase::Instantiated;
            self.time = 0.0;
            if self.rubbing {
                self.rub()?;
            }
            return Ok(());
        }
        if self.phase == Phase::Instantiated && self.rng.chance(0.5) {
            // SAFETY: a live instance.
            let s = unsafe {
                self.lib
                    .fmi3EnterInitializationMode(self.i, false, 0.0, 0.0, false, 0.0)
            };
            if self.status("enterInitializationMode".into(), s)? == fmi3Status_fmi3OK {
                self.phase = Phase::Initialization;
            }
            return Ok(());
        }
        if self.phase == Phase::Initialization && self.rng.chance(0.6) {
            // SAFETY: a live instance.
            let s = unsafe { self.lib.fmi3ExitInitializationMode(self.i) };
            let s = self.status("exitInitializationMode".into(), s)?;
            if s == fmi3Status_fmi3OK || s == fmi3Status_fmi3Warning {
                self.phase = Phase::Step;
            }
            return Ok(());
        }
        if self.rubbing && self.phase == Phase::Step && self.rng.chance(0.8) {
            return self.step();
        }
        match self.rng.below(14) {
            0..=2 => self.set(),
            3 | 4 => self.get(),
            5..=7 | 12 | 13 => self.step(),
            8 => {
                // SAFETY: a live instance.
                let s = unsafe {
                    self.lib
                        .fmi3EnterInitializationMode(self.i, false, 0.0, 0.0, false, 0.0)
                };
                if self.phase != Phase::Instantiated {
                    return self.expect_error("enterInitializationMode".into(), s);
                }
                if self.status("enterInitializationMode".into(), s)? == fmi3Status_fmi3OK {
                    self.phase = Phase::Initialization;
                }
                Ok(())
            }
            9 => {
                // SAFETY: a live instance.
                let s = unsafe { self.lib.fmi3ExitInitializationMode(self.i) };
                if self.phase != Phase::Initialization {
                    return self.expect_error("exitInitializationMode".into(), s);
                }
                let s = self.status("exitInitializationMode".into(), s)?;
                if s == fmi3Status_fmi3OK || s == fmi3Status_fmi3Warning {
                    self.phase = Phase::Step;
                }
                Ok(())
            }
            10 => self.states(),
            _ => match self.rng.below(5) {
                0 => {
                    // SAFETY: a live instance.
                    let s = unsafe { self.lib.fmi3Reset(self.i) };
                    self.status("reset".into(), s)?;
                    self.phase = Phase::Instantiated;
                    self.time = 0.0;
                    Ok(())
                }
                1 => {
                    // SAFETY: a live instance.
                    let s = unsafe { self.lib.fmi3Terminate(self.i) };
                    if !matches!(self.phase, Phase::Step | Phase::StepFailed) {
                        return self.expect_error("terminate".into(), s);
                    }
                    if self.status("terminate".into(), s)? == fmi3Status_fmi3OK {
                        self.phase = Phase::Terminated;
                    }
                    Ok(())
                }
                2 => {
                    // SAFETY: a live instance.
                    let s = unsafe { self.lib.fmi3EnterEventMode(self.i) };
                    self.expect_error("enterEventMode".into(), s)
                }
                3 => {
                    // SAFETY: NULL values with one reference: refused, not read.
                    let s = unsafe { self.lib.fmi3SetFloat64(self.i, [0].as_ptr(), 1, null(), 1) };
                    self.expect_error("setFloat64(NULL)".into(), s)
                }
                _ => {
                    // SAFETY: NULL out-parameters: refused, not written.
                    let s = unsafe {
                        self.lib.fmi3DoStep(
                            self.i,
                            self.time,
                            1e-3,
                            false,
                            null_mut(),
                            null_mut(),
                            null_mut(),
                            null_mut(),
                        )
                    };
                    self.expect_error("doStep(NULL)".into(), s)
                }
            },
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let [_, dir, first, count] = args.as_slice() else {
        eprintln!("usage: fmu3_fuzz UNPACKED_FMU_DIR FIRST_SEED COUNT");
        std::process::exit(2);
    };
    let dir = Path::new(dir);
    let (token, vars) = read_description(&dir.join("modelDescription.xml"));
    let so = dir.join("binaries/x86_64-linux/RotorBearing.so");
    // SAFETY: the FMU's own library.
    let lib = unsafe { Fmi3Binding::new(&so) }.unwrap_or_else(|e| panic!("{}: {e}", so.display()));
    let (first, count): (u64, u64) = (first.parse().unwrap(), count.parse().unwrap());
    let name = CString::new("fuzz").unwrap();
    let token = CString::new(token).unwrap();
    let resources = CString::new(format!("{}/", dir.join("resources").display())).unwrap();
    for seed in first..first + count {
        println!("seed {seed}");
        // SplitMix64's states of consecutive seeds are one stream shifted by
        // a call: start from a mixed state so that sequences are unrelated.
        let mut rng = Rng(Rng(seed).next());
        let early_allowed = rng.chance(0.5);
        let updates = rng.chance(0.5).then(|| Updates {
            lib: &lib,
            instance: Cell::new(null_mut()),
            rng: Cell::new(rng.next()),
            outputs: vars
                .iter()
                .filter(|v| v.causality == "output" && v.kind == "Float64")
                .map(|v| v.vr)
                .collect(),
            others: vars
                .iter()
                .filter(|v| v.causality != "output")
                .map(|v| v.vr)
                .collect(),
            window: Cell::new((0.0, 0.0, 0.0)),
            calls: Cell::new(0),
            violations: RefCell::new(Vec::new()),
        });
        let env = updates.as_ref().map_or(null_mut(), |u| {
            (u as *const Updates).cast_mut().cast::<c_void>()
        });
        // SAFETY: NUL-terminated strings, a logger that stays callable, the
        // callback's environment alive while the instance is.
        let i = unsafe {
            lib.fmi3InstantiateCoSimulation(
                name.as_ptr(),
                token.as_ptr(),
                resources.as_ptr(),
                false,
                false,
                false,
                early_allowed,
                null(),
                0,
                env,
                Some(logger),
                updates.as_ref().map(|_| intermediate_update as _),
            )
        };
        if i.is_null() {
            eprintln!("seed {seed}: instantiation failed");
            std::process::exit(1);
        }
        let mut fuzz = Fuzz {
            lib: &lib,
            vars: &vars,
            rng,
            i,
            phase: Phase::Instantiated,
            time: 0.0,
            early_allowed,
            log: Vec::new(),
            steps: 0,
            early_returns: 0,
            rubbing: false,
            updates: updates.as_ref(),
        };
        if let Some(u) = &updates {
            u.instance.set(i);
        }
        if fuzz.rng.chance(0.3)
            && let Err(why) = fuzz.rub()
        {
            eprintln!("seed {seed}: {why}");
            std::process::exit(1);
        }
        for _ in 0..60 {
            if let Err(why) = fuzz.action() {
                eprintln!("seed {seed}: {why}\ncalls:\n{}", fuzz.log.join("\n"));
                std::process::exit(1);
            }
        }
        let calls = updates.as_ref().map_or(0, |u| u.calls.get());
        println!(
            "steps {} early {} updates {calls}",
            fuzz.steps, fuzz.early_returns
        );
        if std::env::var_os("ROTOR_FUZZ_TRACE").is_some() {
            println!("{}", fuzz.log.join("\n"));
        }
        // SAFETY: the instance made above, freed once.
        unsafe { lib.fmi3FreeInstance(i) };
    }
}
