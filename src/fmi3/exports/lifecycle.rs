//! Exports of the instance life cycle: version, instantiation, logging,
//! initialization, steps, termination and reset.

use std::ffi::{CStr, c_char};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::PathBuf;

use fmi_sys::fmi3::*;

use crate::fmi3::arrays::arrays;
use crate::fmi3::resources;
use crate::fmu::description::LOG_CATEGORIES;
use crate::fmu::instance::{Instance, Status};
use crate::fmu::states::Call;
use crate::units::Short;

use super::glue::*;
use super::intermediate::{refused, updates};
use crate::fmu::c_abi::{instance_exports, set_debug_logging};

const VERSION: &CStr = c"3.0";

/// `fmi3GetVersion`: `"3.0"`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3GetVersion() -> *const c_char {
    VERSION.as_ptr()
}

/// The safe arguments of `fmi3InstantiateCoSimulation`.
struct Request {
    name: Option<String>,
    token: Option<String>,
    resources: Option<String>,
    logging_on: bool,
    event_mode_used: bool,
    early_return_allowed: bool,
    environment: fmi3InstanceEnvironment,
    logger: fmi3LogMessageCallback,
    /// `requiredIntermediateVariables` (`None`: NULL with a count above 0).
    required: Option<Vec<u32>>,
    intermediate_update: fmi3IntermediateUpdateCallback,
}

/// The checks and the instance behind `fmi3InstantiateCoSimulation`.
fn instantiate(r: Request) -> fmi3Instance {
    let name = r.name.unwrap_or_default();
    let fail = |text: String| {
        let text = format!("fmi3InstantiateCoSimulation: {text}");
        log_to(
            r.logger,
            r.environment,
            true,
            Status::Error,
            "logStatusError",
            &text,
        );
        std::ptr::null_mut()
    };
    if name.is_empty() {
        return fail("the instance name must not be empty".into());
    }
    if r.event_mode_used {
        return fail(format!(
            "{name}: eventModeUsed = true, but this FMU has no event mode (hasEventMode = false)"
        ));
    }
    let Some(dir) = r.resources else {
        return fail(format!("{name}: resourcePath is NULL"));
    };
    let Some(required) = r.required.as_deref() else {
        return fail(format!(
            "{name}: requiredIntermediateVariables is NULL with nRequiredIntermediateVariables > 0"
        ));
    };
    let token = r.token.unwrap_or_default();
    match resources::instantiate(&name, &token, &PathBuf::from(dir)) {
        Ok(instance) => {
            let arrays = arrays(instance.variables());
            let updates = match updates(
                &instance,
                &arrays,
                r.intermediate_update,
                required,
                r.early_return_allowed,
                r.environment,
                r.logger,
            ) {
                Ok(u) => u,
                Err(e) => return fail(format!("{name}: {e}")),
            };
            let mut comp = Box::new(Component {
                updates,
                arrays,
                instance,
                environment: r.environment,
                logger: r.logger,
                logging_on: r.logging_on,
                categories: [true; LOG_CATEGORIES.len()],
            });
            comp.instance.set_early_return(r.early_return_allowed);
            comp.sync_step_statistics();
            comp.flush();
            Box::into_raw(comp).cast()
        }
        Err(e) => fail(format!("{name}: {e}")),
    }
}

/// `fmi3InstantiateCoSimulation`: a Co-Simulation instance of the model in
/// the resources folder (NULL with a logged message on failure). With
/// `earlyReturnAllowed`, `fmi3DoStep` returns early where a contact begins
/// (`mightReturnEarlyFromDoStep`) and where the intermediate-update callback
/// asks for it; with a callback, `fmi3DoStep` calls it after every internal
/// step, and the importer may read the outputs named in
/// `requiredIntermediateVariables` there (every output when none is named;
/// [`super::intermediate`]).
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3InstantiateCoSimulation(
    instanceName: fmi3String,
    instantiationToken: fmi3String,
    resourcePath: fmi3String,
    _visible: fmi3Boolean,
    loggingOn: fmi3Boolean,
    eventModeUsed: fmi3Boolean,
    earlyReturnAllowed: fmi3Boolean,
    requiredIntermediateVariables: *const fmi3ValueReference,
    nRequiredIntermediateVariables: usize,
    instanceEnvironment: fmi3InstanceEnvironment,
    logMessage: fmi3LogMessageCallback,
    intermediateUpdate: fmi3IntermediateUpdateCallback,
) -> fmi3Instance {
    // SAFETY: the strings are NULL or NUL-terminated, the value references
    // NULL or `nRequiredIntermediateVariables` elements (contract).
    let (name, token, resources, required) = unsafe {
        (
            string_from(instanceName),
            string_from(instantiationToken),
            string_from(resourcePath),
            slice_from(
                requiredIntermediateVariables,
                nRequiredIntermediateVariables,
            ),
        )
    };
    let request = Request {
        name,
        token,
        resources,
        logging_on: loggingOn,
        event_mode_used: eventModeUsed,
        early_return_allowed: earlyReturnAllowed,
        environment: instanceEnvironment,
        logger: logMessage,
        required: required.map(<[u32]>::to_vec),
        intermediate_update: intermediateUpdate,
    };
    catch_unwind(AssertUnwindSafe(|| instantiate(request))).unwrap_or(std::ptr::null_mut())
}

/// Log that the FMU offers no interface `kind` and return NULL.
fn no_interface(
    kind: &str,
    logger: fmi3LogMessageCallback,
    environment: fmi3InstanceEnvironment,
) -> fmi3Instance {
    let text = format!("fmi3Instantiate{kind}: this FMU supports Co-Simulation only");
    let _ = catch_unwind(AssertUnwindSafe(|| {
        log_to(
            logger,
            environment,
            true,
            Status::Error,
            "logStatusError",
            &text,
        )
    }));
    std::ptr::null_mut()
}

/// `fmi3InstantiateModelExchange`: NULL (Co-Simulation only).
#[unsafe(no_mangle)]
pub extern "C" fn fmi3InstantiateModelExchange(
    _instanceName: fmi3String,
    _instantiationToken: fmi3String,
    _resourcePath: fmi3String,
    _visible: fmi3Boolean,
    _loggingOn: fmi3Boolean,
    instanceEnvironment: fmi3InstanceEnvironment,
    logMessage: fmi3LogMessageCallback,
) -> fmi3Instance {
    no_interface("ModelExchange", logMessage, instanceEnvironment)
}

/// `fmi3InstantiateScheduledExecution`: NULL (Co-Simulation only).
#[unsafe(no_mangle)]
pub extern "C" fn fmi3InstantiateScheduledExecution(
    _instanceName: fmi3String,
    _instantiationToken: fmi3String,
    _resourcePath: fmi3String,
    _visible: fmi3Boolean,
    _loggingOn: fmi3Boolean,
    instanceEnvironment: fmi3InstanceEnvironment,
    logMessage: fmi3LogMessageCallback,
    _clockUpdate: fmi3ClockUpdateCallback,
    _lockPreemption: fmi3LockPreemptionCallback,
    _unlockPreemption: fmi3UnlockPreemptionCallback,
) -> fmi3Instance {
    no_interface("ScheduledExecution", logMessage, instanceEnvironment)
}

/// `fmi3FreeInstance`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3FreeInstance(instance: fmi3Instance) {
    if instance.is_null() || refused(instance as usize, "fmi3FreeInstance") {
        return;
    }
    // SAFETY: `instance` is the `Box<Component>` pointer
    // fmi3InstantiateCoSimulation returned, freed only once (contract).
    let comp = unsafe { Box::from_raw(instance.cast::<Component>()) };
    let _ = catch_unwind(AssertUnwindSafe(move || drop(comp)));
}

/// `fmi3SetDebugLogging`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SetDebugLogging(
    instance: fmi3Instance,
    loggingOn: fmi3Boolean,
    nCategories: usize,
    categories: *const fmi3String,
) -> fmi3Status {
    // SAFETY: `instance` is live, `categories` holds `nCategories` strings (contract).
    let (comp, list) = unsafe { (component(instance), slice_from(categories, nCategories)) };
    let Some(comp) = comp else {
        return fmi3Status_fmi3Error;
    };
    let names = list.map(|list| {
        list.iter()
            // SAFETY: each entry is NULL or NUL-terminated (contract).
            .map(|&p| unsafe { string_from(p) })
            .collect()
    });
    status_code(set_debug_logging(comp, loggingOn, names))
}

/// `fmi3EnterInitializationMode`: the start and stop times (FMI 2.0's
/// fmi2SetupExperiment), then Initialization Mode. The tolerance is not used
/// (`solver.tolerance` is a parameter).
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3EnterInitializationMode(
    instance: fmi3Instance,
    _toleranceDefined: fmi3Boolean,
    _tolerance: fmi3Float64,
    startTime: fmi3Float64,
    stopTimeDefined: fmi3Boolean,
    stopTime: fmi3Float64,
) -> fmi3Status {
    // SAFETY: `instance` is NULL or live (contract).
    let comp = unsafe { component(instance) };
    guarded(comp, |i| {
        match i.setup_experiment(startTime, stopTimeDefined.then_some(stopTime)) {
            Status::Ok => i.enter_initialization_mode(),
            s => s,
        }
    })
}

instance_exports!(
    instance: fmi3Instance,
    status: fmi3Status;
    /// `fmi3ExitInitializationMode`: the rotor settles in static equilibrium;
    /// Step Mode follows (no event mode).
    fmi3ExitInitializationMode => Instance::exit_initialization_mode;
    /// `fmi3Terminate`.
    fmi3Terminate => Instance::terminate;
    /// `fmi3Reset`.
    fmi3Reset => Instance::reset;
);

/// `fmi3DoStep`: the same step as fmi2DoStep. It never asks for event
/// handling or the end of the simulation; with `earlyReturnAllowed` it
/// returns early (`earlyReturn = true`) after the first internal step at
/// which a bearing's or rub's contact begins, or where the intermediate-update
/// callback, called after every internal step when the importer gave one,
/// asks for it. The last successful time is where the simulator stands (the
/// communication point, the early return's time, or where a discarded step
/// stopped).
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3DoStep(
    instance: fmi3Instance,
    currentCommunicationPoint: fmi3Float64,
    communicationStepSize: fmi3Float64,
    _noSetFMUStatePriorToCurrentPoint: fmi3Boolean,
    eventHandlingNeeded: *mut fmi3Boolean,
    terminateSimulation: *mut fmi3Boolean,
    earlyReturn: *mut fmi3Boolean,
    lastSuccessfulTime: *mut fmi3Float64,
) -> fmi3Status {
    // SAFETY: `instance` is live, the out-parameters are NULL or writable
    // (contract).
    let (comp, event, terminate, early, last) = unsafe {
        (
            component(instance),
            eventHandlingNeeded.as_mut(),
            terminateSimulation.as_mut(),
            earlyReturn.as_mut(),
            lastSuccessfulTime.as_mut(),
        )
    };
    let updates = comp.as_ref().and_then(|c| c.updates.clone());
    guarded(comp, |i| {
        let (Some(event), Some(terminate), Some(early), Some(last)) =
            (event, terminate, early, last)
        else {
            return null_argument(i, Call::DoStep);
        };
        let (t, h) = (currentCommunicationPoint, communicationStepSize);
        let status = match &updates {
            None => i.do_step(t, h),
            Some(u) => {
                let mut ignored = None;
                let me = instance as usize;
                let mut observer =
                    |time, values: Option<&[f64]>| u.update(me, time, values, &mut ignored);
                let status = i.do_step_observed(t, h, &mut observer);
                match ignored {
                    Some(at) => {
                        let text = format!(
                            "fmi3DoStep: the intermediate update at {} s asked for an early return, but canReturnEarly was false (earlyReturnAllowed = false at instantiation): ignored",
                            Short(at)
                        );
                        i.report(Status::Warning, text);
                        if status == Status::Ok {
                            Status::Warning
                        } else {
                            status
                        }
                    }
                    None => status,
                }
            }
        };
        *event = false;
        *terminate = false;
        *early = matches!(status, Status::Ok | Status::Warning) && i.early_return_at().is_some();
        *last = i.time();
        status
    })
}
