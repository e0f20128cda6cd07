//! Exports of the instance life cycle: version, instantiation, logging,
//! initialization, steps, termination, reset and the status queries.

use std::ffi::{CStr, CString, c_char};
use std::panic::{AssertUnwindSafe, catch_unwind};

use fmi_sys::fmi2::*;

use crate::fmi2::resources;
use crate::fmu::description::LOG_CATEGORIES;
use crate::fmu::instance::{Instance, Status};
use crate::fmu::states::Call;

use super::glue::*;
use crate::fmu::c_abi::{instance_exports, set_debug_logging};

const TYPES_PLATFORM: &CStr = c"default";
const VERSION: &CStr = c"2.0";

/// `fmi2GetTypesPlatform`: `"default"`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetTypesPlatform() -> *const c_char {
    TYPES_PLATFORM.as_ptr()
}

/// `fmi2GetVersion`: `"2.0"`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetVersion() -> *const c_char {
    VERSION.as_ptr()
}

/// The checks and the instance behind `fmi2Instantiate`, with safe arguments.
fn instantiate(
    name: Option<String>,
    fmu_type: fmi2Type,
    guid: Option<String>,
    location: Option<String>,
    callbacks: fmi2CallbackFunctions,
    logging_on: bool,
) -> fmi2Component {
    let name = name.unwrap_or_default();
    let cname = CString::new(name.clone()).unwrap_or_default();
    let fail = |text: String| {
        log_to(
            &callbacks,
            &cname,
            true,
            Status::Error,
            "logStatusError",
            &format!("fmi2Instantiate: {text}"),
        );
        std::ptr::null_mut()
    };
    if name.is_empty() {
        return fail("the instance name must not be empty".into());
    }
    if fmu_type != fmi2Type_fmi2CoSimulation {
        return fail(format!(
            "{name}: this FMU supports Co-Simulation only (fmuType {fmu_type})"
        ));
    }
    let Some(location) = location else {
        return fail(format!("{name}: fmuResourceLocation is NULL"));
    };
    let guid = guid.unwrap_or_default();
    match resources::instantiate(&name, &guid, &location) {
        Ok(instance) => {
            let mut comp = Box::new(Component {
                instance,
                name: cname.clone(),
                callbacks,
                logging_on,
                categories: [true; LOG_CATEGORIES.len()],
            });
            comp.sync_step_statistics();
            Box::into_raw(comp).cast()
        }
        Err(e) => fail(format!("{name}: {e}")),
    }
}

/// `fmi2Instantiate`: a Co-Simulation instance of the model in the resources
/// (NULL with a logged message on failure).
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
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
    // SAFETY: the strings are NULL or NUL-terminated, `functions` is NULL or
    // points to the callback struct (contract); the struct is copied.
    let (name, guid, location, callbacks) = unsafe {
        (
            string_from(instanceName),
            string_from(fmuGUID),
            string_from(fmuResourceLocation),
            functions.as_ref().copied(),
        )
    };
    let Some(callbacks) = callbacks else {
        return std::ptr::null_mut();
    };
    catch_unwind(AssertUnwindSafe(|| {
        instantiate(name, fmuType, guid, location, callbacks, loggingOn != 0)
    }))
    .unwrap_or(std::ptr::null_mut())
}

/// `fmi2FreeInstance`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeInstance(c: fmi2Component) {
    if c.is_null() {
        return;
    }
    // SAFETY: `c` is the `Box<Component>` pointer fmi2Instantiate returned,
    // freed only once (contract).
    let comp = unsafe { Box::from_raw(c.cast::<Component>()) };
    let _ = catch_unwind(AssertUnwindSafe(move || drop(comp)));
}

/// `fmi2SetDebugLogging`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetDebugLogging(
    c: fmi2Component,
    loggingOn: fmi2Boolean,
    nCategories: usize,
    categories: *const fmi2String,
) -> fmi2Status {
    // SAFETY: `c` is live, `categories` holds `nCategories` strings (contract).
    let (comp, list) = unsafe { (component(c), slice_from(categories, nCategories)) };
    let Some(comp) = comp else {
        return fmi2Status_fmi2Error;
    };
    let names = list.map(|list| {
        list.iter()
            // SAFETY: each entry is NULL or NUL-terminated (contract).
            .map(|&p| unsafe { string_from(p) })
            .collect()
    });
    status_code(set_debug_logging(comp, loggingOn != 0, names))
}

/// `fmi2SetupExperiment`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetupExperiment(
    c: fmi2Component,
    _toleranceDefined: fmi2Boolean,
    _tolerance: fmi2Real,
    startTime: fmi2Real,
    stopTimeDefined: fmi2Boolean,
    stopTime: fmi2Real,
) -> fmi2Status {
    // SAFETY: `c` is NULL or live (contract).
    let comp = unsafe { component(c) };
    guarded(comp, |i| {
        i.setup_experiment(startTime, (stopTimeDefined != 0).then_some(stopTime))
    })
}

instance_exports!(
    instance: fmi2Component,
    status: fmi2Status;
    /// `fmi2EnterInitializationMode`.
    fmi2EnterInitializationMode => Instance::enter_initialization_mode;
    /// `fmi2ExitInitializationMode`.
    fmi2ExitInitializationMode => Instance::exit_initialization_mode;
    /// `fmi2Terminate`.
    fmi2Terminate => Instance::terminate;
    /// `fmi2Reset`.
    fmi2Reset => Instance::reset;
);

/// `fmi2DoStep`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2DoStep(
    c: fmi2Component,
    currentCommunicationPoint: fmi2Real,
    communicationStepSize: fmi2Real,
    _noSetFMUStatePriorToCurrentPoint: fmi2Boolean,
) -> fmi2Status {
    // SAFETY: `c` is NULL or live (contract).
    let comp = unsafe { component(c) };
    guarded(comp, |i| {
        i.do_step(currentCommunicationPoint, communicationStepSize)
    })
}

/// `fmi2CancelStep`: never allowed (no asynchronous steps).
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2CancelStep(c: fmi2Component) -> fmi2Status {
    // SAFETY: `c` is NULL or live (contract).
    let comp = unsafe { component(c) };
    not_provided(
        comp,
        Call::CancelStep,
        "no asynchronous step is running (canRunAsynchronuously = false)",
    )
}

/// `fmi2GetStatus`: no status kind provided (steps never pend).
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Status,
) -> fmi2Status {
    // SAFETY: `c` is live, `value` is NULL or writable (contract).
    let (comp, value) = unsafe { (component(c), value.as_mut()) };
    guarded(comp, |i| {
        let call = Call::GetStatus;
        if let Err(st) = i.check(call) {
            return st;
        }
        if value.is_none() {
            return null_argument(i, call);
        }
        if s == fmi2StatusKind_fmi2DoStepStatus {
            // Steps always complete synchronously: nothing is pending.
            return i.report(
                Status::Discard,
                "fmi2GetStatus(fmi2DoStepStatus): no asynchronous step (fmi2DoStep never \
                 returns fmi2Pending)"
                    .into(),
            );
        }
        status_not_provided(i, call, s)
    })
}

/// `fmi2GetRealStatus`: `fmi2LastSuccessfulTime`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetRealStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Real,
) -> fmi2Status {
    // SAFETY: `c` is live, `value` is NULL or writable (contract).
    let (comp, value) = unsafe { (component(c), value.as_mut()) };
    guarded(comp, |i| {
        let call = Call::GetRealStatus;
        if let Err(st) = i.check(call) {
            return st;
        }
        let Some(value) = value else {
            return null_argument(i, call);
        };
        if s != fmi2StatusKind_fmi2LastSuccessfulTime {
            return status_not_provided(i, call, s);
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

/// `fmi2GetIntegerStatus`: no status kind provided.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetIntegerStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    _value: *mut fmi2Integer,
) -> fmi2Status {
    // SAFETY: `c` is NULL or live (contract).
    let comp = unsafe { component(c) };
    guarded(comp, |i| {
        let call = Call::GetIntegerStatus;
        match i.check(call) {
            Ok(()) => status_not_provided(i, call, s),
            Err(st) => st,
        }
    })
}

/// `fmi2GetBooleanStatus`: `fmi2Terminated` (always false).
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetBooleanStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Boolean,
) -> fmi2Status {
    // SAFETY: `c` is live, `value` is NULL or writable (contract).
    let (comp, value) = unsafe { (component(c), value.as_mut()) };
    guarded(comp, |i| {
        let call = Call::GetBooleanStatus;
        if let Err(st) = i.check(call) {
            return st;
        }
        let Some(value) = value else {
            return null_argument(i, call);
        };
        if s == fmi2StatusKind_fmi2Terminated {
            // The FMU never asks the master to stop.
            *value = fmi2False as fmi2Boolean;
            return Status::Ok;
        }
        status_not_provided(i, call, s)
    })
}

/// `fmi2GetStringStatus`: no status kind provided.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetStringStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    _value: *mut fmi2String,
) -> fmi2Status {
    // SAFETY: `c` is NULL or live (contract).
    let comp = unsafe { component(c) };
    guarded(comp, |i| {
        let call = Call::GetStringStatus;
        match i.check(call) {
            Ok(()) => status_not_provided(i, call, s),
            Err(st) => st,
        }
    })
}
