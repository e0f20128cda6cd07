//! The glue under the exports: the C-side component, the logger, the pointer
//! helpers (each a tiny `unsafe` step with its NULL check) and the panic guard.

use std::ffi::{CStr, CString};
use std::panic::{AssertUnwindSafe, catch_unwind};

use fmi_sys::fmi2::*;

use crate::fmu::description::LOG_CATEGORIES;
use crate::fmu::instance::{Instance, Status};
use crate::fmu::snapshot::Snapshot;
use crate::fmu::states::Call;

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

impl Component {
    /// Tell the instance whether step statistics are wanted: logging on and the
    /// `logAll` category enabled.
    pub(super) fn sync_step_statistics(&mut self) {
        let all = LOG_CATEGORIES.iter().position(|(c, _)| *c == "logAll");
        let on = self.logging_on && all.is_none_or(|i| self.categories[i]);
        self.instance.set_step_statistics(on);
    }

    pub(super) fn flush(&mut self) {
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

/// The `n` elements at `p`: empty for `n = 0`, `None` for NULL otherwise.
///
/// # Safety
///
/// `p` is NULL or points to `n` initialized elements valid for `'a` (module
/// contract).
pub(super) unsafe fn slice_from<'a, T>(p: *const T, n: usize) -> Option<&'a [T]> {
    if n == 0 {
        Some(&[])
    } else if p.is_null() {
        None
    } else {
        // SAFETY: non-null, and the importer passes arrays of `n` elements
        // (contract).
        Some(unsafe { std::slice::from_raw_parts(p, n) })
    }
}

/// The `n` writable elements at `p`: empty for `n = 0`, `None` for NULL
/// otherwise.
///
/// # Safety
///
/// `p` is NULL or points to `n` writable elements valid for `'a` and not
/// aliased (module contract).
pub(super) unsafe fn slice_from_mut<'a, T>(p: *mut T, n: usize) -> Option<&'a mut [T]> {
    if n == 0 {
        Some(&mut [])
    } else if p.is_null() {
        None
    } else {
        // SAFETY: non-null, and the importer passes writable arrays of `n`
        // elements (contract).
        Some(unsafe { std::slice::from_raw_parts_mut(p, n) })
    }
}

/// The text of a C string (lossy UTF-8); `None` for NULL.
///
/// # Safety
///
/// `p` is NULL or a NUL-terminated string valid during the call (module
/// contract).
pub(super) unsafe fn string_from(p: fmi2String) -> Option<String> {
    if p.is_null() {
        return None;
    }
    // SAFETY: non-null and NUL-terminated (contract).
    let text = unsafe { CStr::from_ptr(p) };
    Some(text.to_string_lossy().into_owned())
}

/// The snapshot behind an FMU state; `None` for NULL.
///
/// # Safety
///
/// `s` is NULL or a live state of this library (module contract), not
/// otherwise borrowed during `'a`.
pub(super) unsafe fn snapshot_mut<'a>(s: fmi2FMUstate) -> Option<&'a mut Snapshot> {
    // SAFETY: a non-null state is the `Box<Snapshot>` pointer `into_state`
    // made, not yet freed (contract).
    unsafe { s.cast::<Snapshot>().as_mut() }
}

/// A snapshot handed to the importer as an FMU state (freed by `free_state`).
pub(super) fn into_state(snap: Snapshot) -> fmi2FMUstate {
    Box::into_raw(Box::new(snap)).cast()
}

/// Free an FMU state made by [`into_state`].
///
/// # Safety
///
/// `s` came from [`into_state`] and is freed only once (module contract).
pub(super) unsafe fn free_state(s: fmi2FMUstate) {
    // SAFETY: `s` is a `Box<Snapshot>` pointer from `into_state`, not yet
    // freed (contract).
    drop(unsafe { Box::from_raw(s.cast::<Snapshot>()) });
}

/// Run `f` on the instance of `comp` (fmi2Error for NULL), catch panics, flush
/// the queued log messages.
pub(super) fn guarded(
    comp: Option<&mut Component>,
    f: impl FnOnce(&mut Instance) -> Status,
) -> fmi2Status {
    let Some(comp) = comp else {
        return fmi2Status_fmi2Error;
    };
    let status = match catch_unwind(AssertUnwindSafe(|| f(&mut comp.instance))) {
        Ok(s) => s,
        Err(_) => comp.instance.report(
            Status::Fatal,
            "internal error (panic caught at the FMI boundary)".into(),
        ),
    };
    comp.flush();
    status_code(status)
}

/// fmi2Error with a message for a NULL argument of `call`.
pub(super) fn null_argument(inst: &mut Instance, call: Call) -> Status {
    inst.report(
        Status::Error,
        format!("{}: a required pointer argument is NULL", call.name()),
    )
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
