//! The FMI 2.0 C ABI: every `fmi2*` function of the standard, with the exact
//! signature of the official headers (types from bindgen via `fmi-sys`, checked
//! at compile time against the header's function-pointer typedefs). Each one
//! only translates pointers into calls on a safe [`Instance`]; no panic unwinds
//! across the boundary.

#![allow(non_snake_case)]
#![allow(clippy::missing_safety_doc)]

use std::ffi::{CStr, CString, c_char};
use std::panic::{AssertUnwindSafe, catch_unwind};

use fmi_sys::fmi2::*;

use super::instance::{Instance, Snapshot, Status};
use super::variables::Kind;
use super::xml::{LOG_CATEGORIES, model_description};
use crate::model::RotorModel;

/// The C-side wrapper of an instance.
struct Component {
    instance: Instance,
    name: CString,
    callbacks: fmi2CallbackFunctions,
    logging_on: bool,
    categories: [bool; LOG_CATEGORIES.len()],
}

fn status_code(s: Status) -> fmi2Status {
    match s {
        Status::Ok => fmi2Status_fmi2OK,
        Status::Warning => fmi2Status_fmi2Warning,
        Status::Discard => fmi2Status_fmi2Discard,
        Status::Error => fmi2Status_fmi2Error,
        Status::Fatal => fmi2Status_fmi2Fatal,
    }
}

/// Send a message to the master's logger (discards and errors always, others when enabled).
fn log_to(
    callbacks: &fmi2CallbackFunctions,
    name: &CStr,
    enabled: bool,
    status: Status,
    category: &str,
    text: &str,
) {
    let always = matches!(status, Status::Discard | Status::Error | Status::Fatal);
    if !(enabled || always) {
        return;
    }
    let Some(logger) = callbacks.logger else {
        return;
    };
    // The message is a printf format: escape '%'.
    let (Ok(cat), Ok(msg)) = (
        CString::new(category),
        CString::new(text.replace('%', "%%").replace('\0', " ")),
    ) else {
        return;
    };
    // SAFETY: the master supplied the logger for this instance's lifetime.
    unsafe {
        logger(
            callbacks.componentEnvironment,
            name.as_ptr(),
            status_code(status),
            cat.as_ptr(),
            msg.as_ptr(),
        )
    };
}

impl Component {
    fn flush(&mut self) {
        for (status, category, text) in self.instance.drain_messages() {
            let index = LOG_CATEGORIES.iter().position(|(c, _)| *c == category);
            let enabled = self.logging_on && index.is_none_or(|i| self.categories[i]);
            log_to(
                &self.callbacks,
                &self.name,
                enabled,
                status,
                category,
                &text,
            );
        }
    }
}

/// Run `f` on the component behind `c`, flush its messages, catch panics.
unsafe fn with(c: fmi2Component, f: impl FnOnce(&mut Instance) -> Status) -> fmi2Status {
    if c.is_null() {
        return fmi2Status_fmi2Error;
    }
    // SAFETY: non-null components come from fmi2Instantiate (Box<Component>).
    let comp = unsafe { &mut *(c as *mut Component) };
    let result = catch_unwind(AssertUnwindSafe(|| f(&mut comp.instance)));
    let status = match result {
        Ok(s) => s,
        Err(_) => {
            comp.instance.report(
                Status::Fatal,
                "internal error (panic caught at the FMI boundary)".into(),
            );
            Status::Fatal
        }
    };
    comp.flush();
    status_code(status)
}

unsafe fn slice<'a, T>(p: *const T, n: usize) -> Option<&'a [T]> {
    if n == 0 {
        Some(&[])
    } else if p.is_null() {
        None
    } else {
        // SAFETY: the master passes arrays of n elements.
        Some(unsafe { std::slice::from_raw_parts(p, n) })
    }
}

unsafe fn slice_mut<'a, T>(p: *mut T, n: usize) -> Option<&'a mut [T]> {
    if n == 0 {
        Some(&mut [])
    } else if p.is_null() {
        None
    } else {
        // SAFETY: the master passes arrays of n elements.
        Some(unsafe { std::slice::from_raw_parts_mut(p, n) })
    }
}

fn null_argument(inst: &mut Instance, call: &str) -> Status {
    inst.report(
        Status::Error,
        format!("{call}: a required pointer argument is NULL"),
    )
}

/// `file:///path` (percent-encoded) → path.
fn resource_path(uri: &str) -> Option<std::path::PathBuf> {
    let rest = uri
        .strip_prefix("file://")
        .or_else(|| uri.strip_prefix("file:"))?;
    let rest = if rest.starts_with('/') {
        rest.to_string()
    } else {
        format!("/{rest}")
    };
    let bytes = rest.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' && i + 2 < bytes.len() {
            let hex = std::str::from_utf8(&bytes[i + 1..i + 3]).ok()?;
            out.push(u8::from_str_radix(hex, 16).ok()?);
            i += 3;
        } else {
            out.push(bytes[i]);
            i += 1;
        }
    }
    Some(std::path::PathBuf::from(String::from_utf8(out).ok()?))
}

const TYPES_PLATFORM: &CStr = c"default";
const VERSION: &CStr = c"2.0";

#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetTypesPlatform() -> *const c_char {
    TYPES_PLATFORM.as_ptr()
}

#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetVersion() -> *const c_char {
    VERSION.as_ptr()
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2Instantiate(
    instanceName: fmi2String,
    fmuType: fmi2Type,
    fmuGUID: fmi2String,
    fmuResourceLocation: fmi2String,
    functions: *const fmi2CallbackFunctions,
    _visible: fmi2Boolean,
    loggingOn: fmi2Boolean,
) -> fmi2Component {
    let result = catch_unwind(AssertUnwindSafe(|| {
        if functions.is_null() {
            return std::ptr::null_mut();
        }
        // SAFETY: checked non-null; the struct is copied.
        let callbacks = unsafe { *functions };
        let cstr = |p: fmi2String| {
            if p.is_null() {
                None
            } else {
                Some(unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned())
            }
        };
        let name = cstr(instanceName).unwrap_or_default();
        let cname = CString::new(name.clone()).unwrap_or_default();
        let fail = |text: String| {
            log_to(
                &callbacks,
                &cname,
                true,
                Status::Error,
                "logStatusError",
                &text,
            );
            std::ptr::null_mut()
        };
        if name.is_empty() {
            return fail("fmi2Instantiate: the instance name must not be empty".into());
        }
        if fmuType != fmi2Type_fmi2CoSimulation {
            return fail(format!(
                "fmi2Instantiate: {name}: this FMU supports Co-Simulation only (fmuType {fmuType})"
            ));
        }
        let Some(location) = cstr(fmuResourceLocation) else {
            return fail(format!(
                "fmi2Instantiate: {name}: fmuResourceLocation is NULL"
            ));
        };
        let Some(dir) = resource_path(&location) else {
            return fail(format!(
                "fmi2Instantiate: {name}: fmuResourceLocation {location:?} is not a file URI"
            ));
        };
        let model = match RotorModel::from_file(&dir.join("model.toml")) {
            Ok(m) => m,
            Err(e) => return fail(format!("fmi2Instantiate: {name}: {e}")),
        };
        let (_, guid) = model_description(&model);
        let given = cstr(fmuGUID).unwrap_or_default();
        if given != guid {
            return fail(format!(
                "fmi2Instantiate: {name}: GUID {given} does not match the model in the resources ({guid})"
            ));
        }
        match Instance::new(&name, model) {
            Ok(instance) => Box::into_raw(Box::new(Component {
                instance,
                name: cname.clone(),
                callbacks,
                logging_on: loggingOn != 0,
                categories: [true; LOG_CATEGORIES.len()],
            })) as fmi2Component,
            Err(e) => fail(format!("fmi2Instantiate: {name}: {e}")),
        }
    }));
    result.unwrap_or(std::ptr::null_mut())
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeInstance(c: fmi2Component) {
    if !c.is_null() {
        let _ = catch_unwind(AssertUnwindSafe(|| {
            // SAFETY: created by Box::into_raw in fmi2Instantiate, freed once.
            drop(unsafe { Box::from_raw(c as *mut Component) });
        }));
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetDebugLogging(
    c: fmi2Component,
    loggingOn: fmi2Boolean,
    nCategories: usize,
    categories: *const fmi2String,
) -> fmi2Status {
    if c.is_null() {
        return fmi2Status_fmi2Error;
    }
    // SAFETY: see `with`.
    let comp = unsafe { &mut *(c as *mut Component) };
    let result = catch_unwind(AssertUnwindSafe(|| {
        comp.logging_on = loggingOn != 0;
        let Some(list) = (unsafe { slice(categories, nCategories) }) else {
            return null_argument(&mut comp.instance, "fmi2SetDebugLogging");
        };
        if list.is_empty() {
            comp.categories = [true; LOG_CATEGORIES.len()];
            return Status::Ok;
        }
        comp.categories = [false; LOG_CATEGORIES.len()];
        for &p in list {
            if p.is_null() {
                return null_argument(&mut comp.instance, "fmi2SetDebugLogging");
            }
            let name = unsafe { CStr::from_ptr(p) }.to_string_lossy();
            match LOG_CATEGORIES.iter().position(|(c, _)| *c == name) {
                Some(i) => comp.categories[i] = true,
                None => {
                    return comp.instance.report(
                        Status::Error,
                        format!("fmi2SetDebugLogging: unknown log category {name:?}"),
                    );
                }
            }
        }
        Status::Ok
    }));
    let status = result.unwrap_or(Status::Fatal);
    comp.flush();
    status_code(status)
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetupExperiment(
    c: fmi2Component,
    _toleranceDefined: fmi2Boolean,
    _tolerance: fmi2Real,
    startTime: fmi2Real,
    stopTimeDefined: fmi2Boolean,
    stopTime: fmi2Real,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            i.setup_experiment(startTime, (stopTimeDefined != 0).then_some(stopTime))
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2EnterInitializationMode(c: fmi2Component) -> fmi2Status {
    unsafe { with(c, Instance::enter_initialization_mode) }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2ExitInitializationMode(c: fmi2Component) -> fmi2Status {
    unsafe { with(c, Instance::exit_initialization_mode) }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2Terminate(c: fmi2Component) -> fmi2Status {
    unsafe { with(c, Instance::terminate) }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2Reset(c: fmi2Component) -> fmi2Status {
    unsafe { with(c, Instance::reset) }
}

unsafe fn get_values<T: Copy>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut T,
    kind: Kind,
    convert: impl Fn(f64) -> T,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            let (Some(refs), Some(out)) = (slice(vr, nvr), slice_mut(value, nvr)) else {
                return null_argument(i, "fmi2Get");
            };
            for (r, o) in refs.iter().zip(out.iter_mut()) {
                match i.get(*r, kind) {
                    Ok(v) => *o = convert(v),
                    Err(s) => return s,
                }
            }
            Status::Ok
        })
    }
}

unsafe fn set_values<T: Copy>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const T,
    kind: Kind,
    convert: impl Fn(T) -> f64,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            let (Some(refs), Some(vals)) = (slice(vr, nvr), slice(value, nvr)) else {
                return null_argument(i, "fmi2Set");
            };
            for (r, v) in refs.iter().zip(vals) {
                let s = i.set(*r, kind, convert(*v));
                if s != Status::Ok {
                    return s;
                }
            }
            Status::Ok
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetReal(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Real,
) -> fmi2Status {
    unsafe { get_values(c, vr, nvr, value, Kind::Real, |v| v) }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetInteger(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Integer,
) -> fmi2Status {
    unsafe { get_values(c, vr, nvr, value, Kind::Integer, |v| v as fmi2Integer) }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetBoolean(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Boolean,
) -> fmi2Status {
    unsafe {
        get_values(c, vr, nvr, value, Kind::Boolean, |v| {
            fmi2Boolean::from(v != 0.0)
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetString(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    _value: *mut fmi2String,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            if nvr == 0 {
                return Status::Ok;
            }
            let first = slice(vr, nvr).and_then(|r| r.first().copied()).unwrap_or(0);
            i.report(
                Status::Error,
                format!("fmi2GetString: value reference {first}: the FMU has no String variables"),
            )
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetReal(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Real,
) -> fmi2Status {
    unsafe { set_values(c, vr, nvr, value, Kind::Real, |v| v) }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetInteger(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Integer,
) -> fmi2Status {
    unsafe { set_values(c, vr, nvr, value, Kind::Integer, f64::from) }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetBoolean(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Boolean,
) -> fmi2Status {
    unsafe {
        set_values(c, vr, nvr, value, Kind::Boolean, |v| {
            f64::from(u8::from(v != 0))
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetString(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    _value: *const fmi2String,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            if nvr == 0 {
                return Status::Ok;
            }
            let first = slice(vr, nvr).and_then(|r| r.first().copied()).unwrap_or(0);
            i.report(
                Status::Error,
                format!("fmi2SetString: value reference {first}: the FMU has no String variables"),
            )
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetFMUstate(
    c: fmi2Component,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            if FMUstate.is_null() {
                return null_argument(i, "fmi2GetFMUstate");
            }
            match i.snapshot() {
                Ok(snap) => {
                    let slot = &mut *FMUstate;
                    if slot.is_null() {
                        *slot = Box::into_raw(Box::new(snap)) as fmi2FMUstate;
                    } else {
                        // Reuse the state the master passes back in.
                        *(*slot as *mut Snapshot) = snap;
                    }
                    Status::Ok
                }
                Err(s) => s,
            }
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetFMUstate(c: fmi2Component, FMUstate: fmi2FMUstate) -> fmi2Status {
    unsafe {
        with(c, |i| {
            if FMUstate.is_null() {
                return null_argument(i, "fmi2SetFMUstate");
            }
            let snap = &*(FMUstate as *const Snapshot);
            i.restore(snap)
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeFMUstate(
    c: fmi2Component,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            if FMUstate.is_null() {
                return null_argument(i, "fmi2FreeFMUstate");
            }
            let slot = &mut *FMUstate;
            if !slot.is_null() {
                drop(Box::from_raw(*slot as *mut Snapshot));
                *slot = std::ptr::null_mut();
            }
            Status::Ok
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SerializedFMUstateSize(
    c: fmi2Component,
    FMUstate: fmi2FMUstate,
    size: *mut usize,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            if FMUstate.is_null() || size.is_null() {
                return null_argument(i, "fmi2SerializedFMUstateSize");
            }
            *size = Instance::serialize(&*(FMUstate as *const Snapshot)).len();
            Status::Ok
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SerializeFMUstate(
    c: fmi2Component,
    FMUstate: fmi2FMUstate,
    serializedState: *mut fmi2Byte,
    size: usize,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            if FMUstate.is_null() || serializedState.is_null() {
                return null_argument(i, "fmi2SerializeFMUstate");
            }
            let bytes = Instance::serialize(&*(FMUstate as *const Snapshot));
            if bytes.len() != size {
                return i.report(
                    Status::Error,
                    format!(
                        "fmi2SerializeFMUstate: buffer of {size} bytes, the state needs {}",
                        bytes.len()
                    ),
                );
            }
            std::ptr::copy_nonoverlapping(bytes.as_ptr(), serializedState as *mut u8, size);
            Status::Ok
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
    c: fmi2Component,
    serializedState: *const fmi2Byte,
    size: usize,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            if FMUstate.is_null() {
                return null_argument(i, "fmi2DeSerializeFMUstate");
            }
            let Some(bytes) = slice(serializedState as *const u8, size) else {
                return null_argument(i, "fmi2DeSerializeFMUstate");
            };
            match i.deserialize(bytes) {
                Ok(snap) => {
                    let slot = &mut *FMUstate;
                    if !slot.is_null() {
                        drop(Box::from_raw(*slot as *mut Snapshot));
                    }
                    *slot = Box::into_raw(Box::new(snap)) as fmi2FMUstate;
                    Status::Ok
                }
                Err(s) => s,
            }
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetDirectionalDerivative(
    c: fmi2Component,
    _vUnknown_ref: *const fmi2ValueReference,
    _nUnknown: usize,
    _vKnown_ref: *const fmi2ValueReference,
    _nKnown: usize,
    _dvKnown: *const fmi2Real,
    _dvUnknown: *mut fmi2Real,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            i.report(Status::Error, "fmi2GetDirectionalDerivative: not provided (providesDirectionalDerivative = false)".into())
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetRealInputDerivatives(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    order: *const fmi2Integer,
    value: *const fmi2Real,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            let (Some(refs), Some(orders), Some(vals)) =
                (slice(vr, nvr), slice(order, nvr), slice(value, nvr))
            else {
                return null_argument(i, "fmi2SetRealInputDerivatives");
            };
            for ((r, o), v) in refs.iter().zip(orders).zip(vals) {
                let s = i.set_input_derivative(*r, *o, *v);
                if s != Status::Ok {
                    return s;
                }
            }
            Status::Ok
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetRealOutputDerivatives(
    c: fmi2Component,
    _vr: *const fmi2ValueReference,
    _nvr: usize,
    _order: *const fmi2Integer,
    _value: *mut fmi2Real,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            i.report(
                Status::Error,
                "fmi2GetRealOutputDerivatives: not provided (maxOutputDerivativeOrder = 0)".into(),
            )
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2DoStep(
    c: fmi2Component,
    currentCommunicationPoint: fmi2Real,
    communicationStepSize: fmi2Real,
    _noSetFMUStatePriorToCurrentPoint: fmi2Boolean,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            i.do_step(currentCommunicationPoint, communicationStepSize)
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2CancelStep(c: fmi2Component) -> fmi2Status {
    unsafe {
        with(c, |i| {
            i.report(
                Status::Error,
                "fmi2CancelStep: no asynchronous step is running (canRunAsynchronuously = false)"
                    .into(),
            )
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Status,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            if value.is_null() {
                return null_argument(i, "fmi2GetStatus");
            }
            if s == fmi2StatusKind_fmi2DoStepStatus {
                // Steps always complete synchronously: nothing is pending.
                return i.report(Status::Discard, "fmi2GetStatus(fmi2DoStepStatus): no asynchronous step (fmi2DoStep never returns fmi2Pending)".into());
            }
            i.report(
                Status::Discard,
                format!("fmi2GetStatus: status kind {s} is not provided"),
            )
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetRealStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Real,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            if value.is_null() {
                return null_argument(i, "fmi2GetRealStatus");
            }
            if s != fmi2StatusKind_fmi2LastSuccessfulTime {
                return i.report(
                    Status::Discard,
                    format!("fmi2GetRealStatus: status kind {s} is not provided"),
                );
            }
            match i.last_successful_time() {
                Ok(t) => {
                    *value = t;
                    Status::Ok
                }
                Err(st) => st,
            }
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetIntegerStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    _value: *mut fmi2Integer,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            i.report(
                Status::Discard,
                format!("fmi2GetIntegerStatus: status kind {s} is not provided"),
            )
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetBooleanStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Boolean,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            if value.is_null() {
                return null_argument(i, "fmi2GetBooleanStatus");
            }
            if s == fmi2StatusKind_fmi2Terminated {
                // The FMU never asks the master to stop.
                *value = fmi2False as fmi2Boolean;
                return Status::Ok;
            }
            i.report(
                Status::Discard,
                format!("fmi2GetBooleanStatus: status kind {s} is not provided"),
            )
        })
    }
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetStringStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    _value: *mut fmi2String,
) -> fmi2Status {
    unsafe {
        with(c, |i| {
            i.report(
                Status::Discard,
                format!("fmi2GetStringStatus: status kind {s} is not provided"),
            )
        })
    }
}

/// Compile-time proof that every export has the header's exact signature.
const _: () = {
    let _: fmi2GetTypesPlatformTYPE = Some(fmi2GetTypesPlatform);
    let _: fmi2GetVersionTYPE = Some(fmi2GetVersion);
    let _: fmi2SetDebugLoggingTYPE = Some(fmi2SetDebugLogging);
    let _: fmi2InstantiateTYPE = Some(fmi2Instantiate);
    let _: fmi2FreeInstanceTYPE = Some(fmi2FreeInstance);
    let _: fmi2SetupExperimentTYPE = Some(fmi2SetupExperiment);
    let _: fmi2EnterInitializationModeTYPE = Some(fmi2EnterInitializationMode);
    let _: fmi2ExitInitializationModeTYPE = Some(fmi2ExitInitializationMode);
    let _: fmi2TerminateTYPE = Some(fmi2Terminate);
    let _: fmi2ResetTYPE = Some(fmi2Reset);
    let _: fmi2GetRealTYPE = Some(fmi2GetReal);
    let _: fmi2GetIntegerTYPE = Some(fmi2GetInteger);
    let _: fmi2GetBooleanTYPE = Some(fmi2GetBoolean);
    let _: fmi2GetStringTYPE = Some(fmi2GetString);
    let _: fmi2SetRealTYPE = Some(fmi2SetReal);
    let _: fmi2SetIntegerTYPE = Some(fmi2SetInteger);
    let _: fmi2SetBooleanTYPE = Some(fmi2SetBoolean);
    let _: fmi2SetStringTYPE = Some(fmi2SetString);
    let _: fmi2GetFMUstateTYPE = Some(fmi2GetFMUstate);
    let _: fmi2SetFMUstateTYPE = Some(fmi2SetFMUstate);
    let _: fmi2FreeFMUstateTYPE = Some(fmi2FreeFMUstate);
    let _: fmi2SerializedFMUstateSizeTYPE = Some(fmi2SerializedFMUstateSize);
    let _: fmi2SerializeFMUstateTYPE = Some(fmi2SerializeFMUstate);
    let _: fmi2DeSerializeFMUstateTYPE = Some(fmi2DeSerializeFMUstate);
    let _: fmi2GetDirectionalDerivativeTYPE = Some(fmi2GetDirectionalDerivative);
    let _: fmi2SetRealInputDerivativesTYPE = Some(fmi2SetRealInputDerivatives);
    let _: fmi2GetRealOutputDerivativesTYPE = Some(fmi2GetRealOutputDerivatives);
    let _: fmi2DoStepTYPE = Some(fmi2DoStep);
    let _: fmi2CancelStepTYPE = Some(fmi2CancelStep);
    let _: fmi2GetStatusTYPE = Some(fmi2GetStatus);
    let _: fmi2GetRealStatusTYPE = Some(fmi2GetRealStatus);
    let _: fmi2GetIntegerStatusTYPE = Some(fmi2GetIntegerStatus);
    let _: fmi2GetBooleanStatusTYPE = Some(fmi2GetBooleanStatus);
    let _: fmi2GetStringStatusTYPE = Some(fmi2GetStringStatus);
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn resource_uris_decode() {
        assert_eq!(
            resource_path("file:///tmp/a%20b/res").unwrap(),
            std::path::PathBuf::from("/tmp/a b/res")
        );
        assert_eq!(
            resource_path("file:/tmp/x").unwrap(),
            std::path::PathBuf::from("/tmp/x")
        );
        assert!(resource_path("http://x").is_none());
    }
}
