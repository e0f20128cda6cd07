//! The glue under the exports: the C-side component, the logger, the pointer
//! helpers (each a tiny `unsafe` step with its NULL check) and the panic guard.

use std::ffi::{CStr, CString};

use fmi_sys::fmi2::*;

use crate::fmu::description::LOG_CATEGORIES;
use crate::fmu::instance::{Instance, Status};
use crate::fmu::states::Call;

use crate::fmu::c_abi;
pub(super) use crate::fmu::c_abi::{
    Wrapper, free_state, into_state, null_argument, slice_from, slice_from_mut, snapshot_mut,
    string_from,
};

/// The C-side wrapper of an instance.
pub(super) struct Component {
    pub(super) instance: Instance,
    pub(super) name: CString,
    pub(super) callbacks: fmi2CallbackFunctions,
    pub(super) logging_on: bool,
    pub(super) categories: [bool; LOG_CATEGORIES.len()],
}

pub(super) fn status_code(s: Status) -> fmi2Status {
    match s {
        Status::Ok => fmi2Status_fmi2OK,
        Status::Warning => fmi2Status_fmi2Warning,
        Status::Discard => fmi2Status_fmi2Discard,
        Status::Error => fmi2Status_fmi2Error,
        Status::Fatal => fmi2Status_fmi2Fatal,
    }
}

/// Send a message to the master's logger (discards and errors always, others when enabled).
pub(super) fn log_to(
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
    // SAFETY: the importer keeps its logger callable while the instance lives
    // (contract); the strings are NUL-terminated and outlive the call, and the
    // format has no conversions left ('%' escaped), so no variadic argument is read.
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

impl Wrapper for Component {
    fn instance(&mut self) -> &mut Instance {
        &mut self.instance
    }

    fn logging(&mut self) -> (&mut bool, &mut [bool; LOG_CATEGORIES.len()]) {
        (&mut self.logging_on, &mut self.categories)
    }

    fn log(&self, enabled: bool, status: Status, category: &str, text: &str) {
        log_to(&self.callbacks, &self.name, enabled, status, category, text);
    }
}

/// The component behind `c`; `None` for NULL.
///
/// # Safety
///
/// `c` is NULL or a live component of this library, not in use elsewhere
/// during `'a` (module contract).
pub(super) unsafe fn component<'a>(c: fmi2Component) -> Option<&'a mut Component> {
    // SAFETY: a non-null `c` is the `Box<Component>` pointer fmi2Instantiate
    // returned, not yet freed and not aliased during the call (contract).
    unsafe { c.cast::<Component>().as_mut() }
}

/// Run `f` on the instance of `comp` (fmi2Error for NULL), catch panics, flush
/// the queued log messages ([`crate::fmu::c_abi::guarded`]).
pub(super) fn guarded(
    comp: Option<&mut Component>,
    f: impl FnOnce(&mut Instance) -> Status,
) -> fmi2Status {
    status_code(c_abi::guarded(comp, f))
}

/// fmi2Error with a message for a capability the FMU does not declare.
pub(super) fn not_provided(comp: Option<&mut Component>, call: Call, why: &str) -> fmi2Status {
    guarded(comp, |i| {
        if let Err(s) = i.check(call) {
            return s;
        }
        i.report(Status::Error, format!("{}: {why}", call.name()))
    })
}

/// fmi2Discard with a message for a status kind the FMU does not provide.
pub(super) fn status_not_provided(i: &mut Instance, call: Call, kind: fmi2StatusKind) -> Status {
    i.report(
        Status::Discard,
        format!("{}: status kind {kind} is not provided", call.name()),
    )
}
