//! Intermediate updates (FMI 3.0 §4.2, Intermediate Update Mode): when the
//! importer instantiates with an `intermediateUpdate` callback, `fmi3DoStep`
//! calls it after every completed internal step
//! ([`crate::fmu::instance::Intermediate`]) with
//! `intermediateUpdateTime` = the step's time, `intermediateVariableSetRequested
//! = false` (inputs are held over the whole `fmi3DoStep`),
//! `intermediateVariableGetAllowed = true` (false only where the outputs could
//! not be evaluated), `intermediateStepFinished = true` (only accepted steps
//! are reported) and `canReturnEarly = earlyReturnAllowed`. An early return
//! the callback asks for ends the step at `earlyReturnTime`
//! (`Intermediate::ReturnAt`).
//!
//! During the callback the instance is inside `fmi3DoStep`, so nothing may
//! touch its component: the outputs at the internal step are copied into a
//! *window* (a process-wide list, keyed by the instance's address) before the
//! callback runs, `fmi3GetFloat64` of an intermediate variable is served from
//! the window without dereferencing the instance, and every other call on the
//! instance answers fmi3Error with a message (checked by address in
//! `component` and `fmi3FreeInstance`, before any reference is made).

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, MutexGuard};

use fmi_sys::fmi3::*;

use crate::fmi3::arrays::Array;
use crate::fmu::instance::{Instance, Intermediate, Status};
use crate::fmu::variables::Causality;
use crate::units::Short;

use super::logger::log_to;

/// The importer's intermediate updates of one instance.
#[derive(Debug)]
pub(super) struct Updates {
    /// The `intermediateUpdate` callback.
    callback: unsafe extern "C" fn(
        fmi3InstanceEnvironment,
        fmi3Float64,
        fmi3Boolean,
        fmi3Boolean,
        fmi3Boolean,
        fmi3Boolean,
        *mut fmi3Boolean,
        *mut fmi3Float64,
    ),
    /// `instanceEnvironment`, as an address (the window list is shared
    /// between threads).
    environment: usize,
    /// `logMessage`.
    logger: fmi3LogMessageCallback,
    /// `earlyReturnAllowed`: the callback may ask for an early return.
    can_return_early: bool,
    /// The table's value references the importer may read (sorted).
    readable: Vec<u32>,
    /// The output arrays it may read, each as its elements.
    arrays: Vec<Array>,
}

/// The intermediate updates asked for at instantiation: `None` without a
/// callback; an error when `required` names a variable that is not an output
/// (only outputs have `intermediateUpdate = "true"`), or names any without a
/// callback. An empty `required` lets the callback read every output.
pub(super) fn updates(
    instance: &Instance,
    arrays: &[Array],
    callback: fmi3IntermediateUpdateCallback,
    required: &[u32],
    early_return_allowed: bool,
    environment: fmi3InstanceEnvironment,
    logger: fmi3LogMessageCallback,
) -> Result<Option<Arc<Updates>>, String> {
    let Some(callback) = callback else {
        if required.is_empty() {
            return Ok(None);
        }
        return Err(format!(
            "requiredIntermediateVariables names {} variables, but the intermediateUpdate callback is NULL",
            required.len()
        ));
    };
    let vars = instance.variables();
    let outputs: Vec<&Array> = arrays
        .iter()
        .filter(|a| a.causality == Causality::Output)
        .collect();
    let mut readable = Vec::new();
    let mut readable_arrays = Vec::new();
    if required.is_empty() {
        readable.extend(
            vars.iter()
                .filter(|v| v.causality == Causality::Output)
                .map(|v| v.value_reference),
        );
        readable_arrays.extend(outputs.iter().map(|&a| a.clone()));
    }
    for &r in required {
        if let Some(a) = outputs.iter().find(|a| a.value_reference == r) {
            readable.extend_from_slice(&a.elements);
            readable_arrays.push((*a).clone());
            continue;
        }
        match vars.get(r as usize) {
            Some(v) if v.causality == Causality::Output => readable.push(r),
            Some(v) => {
                return Err(format!(
                    "requiredIntermediateVariables: {} (value reference {r}) is not an output; only outputs have intermediateUpdate = \"true\" (inputs are held over a step)",
                    v.name
                ));
            }
            None => {
                return Err(format!(
                    "requiredIntermediateVariables: value reference {r} is no output of the FMU"
                ));
            }
        }
    }
    readable.sort_unstable();
    readable.dedup();
    Ok(Some(Arc::new(Updates {
        callback,
        environment: environment as usize,
        logger,
        can_return_early: early_return_allowed,
        readable,
        arrays: readable_arrays,
    })))
}

/// An instance in Intermediate Update Mode: the outputs at the internal step
/// the callback is told of.
struct Window {
    /// The instance's address.
    instance: usize,
    updates: Arc<Updates>,
    /// The internal step's time (s).
    time: f64,
    /// The table's values there, by value reference (`None`: not evaluated).
    values: Option<Vec<f64>>,
}

/// Every window open now (one per instance inside its callback).
static WINDOWS: Mutex<Vec<Window>> = Mutex::new(Vec::new());

/// How many windows are open: the calls of an FMU without one (nearly all)
/// skip the lock.
static OPEN: AtomicUsize = AtomicUsize::new(0);

fn windows() -> MutexGuard<'static, Vec<Window>> {
    WINDOWS.lock().unwrap_or_else(|e| e.into_inner())
}

impl Updates {
    /// Log `text` as an error (always sent) to the importer's logger (called
    /// with no window list held: the logger may call the FMU).
    fn error(&self, text: &str) {
        log_to(
            self.logger,
            self.environment as fmi3InstanceEnvironment,
            true,
            Status::Error,
            "logStatusError",
            text,
        );
    }

    /// The callback for the internal step at `time` of the instance at
    /// address `instance`, with the table's values there: what it asks of
    /// the step. A request for an early return is honoured when
    /// `canReturnEarly` was true (else it is ignored and `ignored` says when).
    pub(super) fn update(
        self: &Arc<Self>,
        instance: usize,
        time: f64,
        values: Option<&[f64]>,
        ignored: &mut Option<f64>,
    ) -> Intermediate {
        let readable = values.is_some();
        windows().push(Window {
            instance,
            updates: Arc::clone(self),
            time,
            values: values.map(<[f64]>::to_vec),
        });
        OPEN.fetch_add(1, Ordering::SeqCst);
        let (mut requested, mut at) = (false, time);
        let environment = self.environment as fmi3InstanceEnvironment;
        // SAFETY: the importer's callback, callable while the instance lives
        // (contract); its two out-parameters point to locals.
        unsafe {
            (self.callback)(
                environment,
                time,
                false,
                readable,
                true,
                self.can_return_early,
                &mut requested,
                &mut at,
            )
        };
        let mut open = windows();
        if let Some(k) = open.iter().rposition(|w| w.instance == instance) {
            open.remove(k);
            OPEN.fetch_sub(1, Ordering::SeqCst);
        }
        drop(open);
        match (requested, self.can_return_early) {
            (false, _) => Intermediate::Continue,
            (true, false) => {
                ignored.get_or_insert(time);
                Intermediate::Continue
            }
            // A time that is not a number: here.
            (true, true) if at.is_nan() => Intermediate::ReturnAt(time),
            (true, true) => Intermediate::ReturnAt(at),
        }
    }
}

/// Whether the instance at `instance` is in Intermediate Update Mode; if so,
/// `call` is refused with fmi3Error and a message to its logger.
pub(super) fn refused(instance: usize, call: &str) -> bool {
    if OPEN.load(Ordering::SeqCst) == 0 {
        return false;
    }
    let open = windows();
    let Some(w) = open.iter().rev().find(|w| w.instance == instance) else {
        return false;
    };
    let updates = Arc::clone(&w.updates);
    let time = w.time;
    drop(open);
    updates.error(&format!(
        "{call}: not allowed in Intermediate Update Mode (inside the intermediateUpdate callback at {} s); only fmi3GetFloat64 of the intermediate variables is",
        Short(time)
    ));
    true
}

/// `fmi3GetFloat64` of the instance at `instance` in Intermediate Update
/// Mode, from its window: `None` when it is not in that mode. Arrays read as
/// their elements; each value must be one the importer may read.
pub(super) fn get_float64(
    instance: usize,
    refs: Option<&[u32]>,
    out: Option<&mut [f64]>,
    n_values: usize,
) -> Option<fmi3Status> {
    if OPEN.load(Ordering::SeqCst) == 0 {
        return None;
    }
    let open = windows();
    let w = open.iter().rev().find(|w| w.instance == instance)?;
    let updates = Arc::clone(&w.updates);
    let result = read(w, refs, out, n_values);
    drop(open);
    Some(match result {
        Ok(()) => fmi3Status_fmi3OK,
        Err(text) => {
            updates.error(&format!(
                "fmi3GetFloat64 (Intermediate Update Mode): {text}"
            ));
            fmi3Status_fmi3Error
        }
    })
}

/// The values of `refs` from window `w` into `out`.
fn read(
    w: &Window,
    refs: Option<&[u32]>,
    out: Option<&mut [f64]>,
    n_values: usize,
) -> Result<(), String> {
    let (Some(refs), Some(out)) = (refs, out) else {
        return Err("a required pointer argument is NULL".into());
    };
    let mut scalars = Vec::with_capacity(refs.len());
    for &r in refs {
        match w.updates.arrays.iter().find(|a| a.value_reference == r) {
            Some(a) => scalars.extend_from_slice(&a.elements),
            None => scalars.push(r),
        }
    }
    if scalars.len() != n_values {
        return Err(format!(
            "{n_values} values for {} scalar values (arrays counted by their elements)",
            scalars.len()
        ));
    }
    let Some(values) = &w.values else {
        return Err(format!(
            "the outputs at {} s could not be evaluated (intermediateVariableGetAllowed = false)",
            Short(w.time)
        ));
    };
    for (&r, o) in scalars.iter().zip(out.iter_mut()) {
        if w.updates.readable.binary_search(&r).is_err() {
            return Err(format!(
                "value reference {r} is not an intermediate variable of this instance (an output with intermediateUpdate = \"true\" named in requiredIntermediateVariables, or any output when none is named)"
            ));
        }
        let v = values[r as usize];
        if !v.is_finite() {
            return Err(format!(
                "value reference {r} is not finite ({}) at {} s",
                Short(v),
                Short(w.time)
            ));
        }
        *o = v;
    }
    Ok(())
}
