//! The glue under the FMI 3.0 exports: the C-side component, the logger, the
//! pointer helpers (each a tiny `unsafe` step with its NULL check) and the
//! panic guard.

use std::ffi::{CStr, CString};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::Arc;

use fmi_sys::fmi3::*;

use crate::fmi3::arrays::{ARRAY_BASE, Array};
use crate::fmu::description::LOG_CATEGORIES;
use crate::fmu::instance::{Instance, Status};
use crate::fmu::snapshot::Snapshot;
use crate::fmu::states::Call;

use super::intermediate::{Updates, refused};

/// The C-side wrapper of an instance.
pub(super) struct Component {
    pub(super) instance: Instance,
    /// The `fmi3Float64` arrays over the table ([`crate::fmi3::arrays`]).
    pub(super) arrays: Vec<Array>,
    pub(super) environment: fmi3InstanceEnvironment,
    pub(super) logger: fmi3LogMessageCallback,
    pub(super) logging_on: bool,
    pub(super) categories: [bool; LOG_CATEGORIES.len()],
    /// The importer's intermediate updates, when it gave a callback.
    pub(super) updates: Option<Arc<Updates>>,
}

pub(super) fn status_code(s: Status) -> fmi3Status {
    match s {
        Status::Ok => fmi3Status_fmi3OK,
        Status::Warning => fmi3Status_fmi3Warning,
        Status::Discard => fmi3Status_fmi3Discard,
        Status::Error => fmi3Status_fmi3Error,
        Status::Fatal => fmi3Status_fmi3Fatal,
    }
}

/// Send a message to the master's logger (discards and errors always, others
/// when enabled). FMI 3.0's logger takes the message as it is (no format).
pub(super) fn log_to(
    logger: fmi3LogMessageCallback,
    environment: fmi3InstanceEnvironment,
    enabled: bool,
    status: Status,
    category: &str,
    text: &str,
) {
    let always = matches!(status, Status::Discard | Status::Error | Status::Fatal);
    if !(enabled || always) {
        return;
    }
    let Some(logger) = logger else {
        return;
    };
    let (Ok(cat), Ok(msg)) = (
        CString::new(category),
        CString::new(text.replace('\0', " ")),
    ) else {
        return;
    };
    // SAFETY: the importer keeps its logger callable while the instance lives
    // (contract); the strings are NUL-terminated and outlive the call.
    unsafe { logger(environment, status_code(status), cat.as_ptr(), msg.as_ptr()) };
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
                self.logger,
                self.environment,
                enabled,
                status,
                category,
                &text,
            );
        }
    }
}

/// The component behind `c`; `None` for NULL, and for an instance inside
/// its intermediate-update callback (whose component `fmi3DoStep` holds: the
/// call is refused with a message, [`super::intermediate`]).
///
/// # Safety
///
/// `c` is NULL or a live component of this library, not in use elsewhere
/// during `'a` (module contract).
pub(super) unsafe fn component<'a>(c: fmi3Instance) -> Option<&'a mut Component> {
    if refused(c as usize, "this function") {
        return None;
    }
    // SAFETY: a non-null `c` is the `Box<Component>` pointer
    // fmi3InstantiateCoSimulation returned, not yet freed and not aliased
    // during the call (contract).
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
pub(super) unsafe fn string_from(p: fmi3String) -> Option<String> {
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
pub(super) unsafe fn snapshot_mut<'a>(s: fmi3FMUState) -> Option<&'a mut Snapshot> {
    // SAFETY: a non-null state is the `Box<Snapshot>` pointer `into_state`
    // made, not yet freed (contract).
    unsafe { s.cast::<Snapshot>().as_mut() }
}

/// A snapshot handed to the importer as an FMU state (freed by `free_state`).
pub(super) fn into_state(snap: Snapshot) -> fmi3FMUState {
    Box::into_raw(Box::new(snap)).cast()
}

/// Free an FMU state made by [`into_state`].
///
/// # Safety
///
/// `s` came from [`into_state`] and is freed only once (module contract).
pub(super) unsafe fn free_state(s: fmi3FMUState) {
    // SAFETY: `s` is a `Box<Snapshot>` pointer from `into_state`, not yet
    // freed (contract).
    drop(unsafe { Box::from_raw(s.cast::<Snapshot>()) });
}

/// Run `f` on the instance of `comp` (fmi3Error for NULL), catch panics, flush
/// the queued log messages.
pub(super) fn guarded(
    comp: Option<&mut Component>,
    f: impl FnOnce(&mut Instance) -> Status,
) -> fmi3Status {
    let Some(comp) = comp else {
        return fmi3Status_fmi3Error;
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

/// fmi3Error with a message for a NULL argument of `call`.
pub(super) fn null_argument(inst: &mut Instance, call: Call) -> Status {
    let name = call.name_in(inst.version());
    inst.report(
        Status::Error,
        format!("{name}: a required pointer argument is NULL"),
    )
}

/// fmi3Error with a message for a function of FMI 3.0 this FMU does not
/// provide (`name`, and why).
pub(super) fn not_provided(comp: Option<&mut Component>, name: &str, why: &str) -> fmi3Status {
    guarded(comp, |i| i.report(Status::Error, format!("{name}: {why}")))
}

/// `refs` with every array's reference replaced by its elements' (`None`
/// when `refs` names no array: they stand as they are).
pub(super) fn expand(comp: &Option<&mut Component>, refs: Option<&[u32]>) -> Option<Vec<u32>> {
    let (comp, refs) = (comp.as_deref()?, refs?);
    if refs.iter().all(|&r| r < ARRAY_BASE) {
        return None;
    }
    let mut out = Vec::with_capacity(refs.len());
    for &r in refs {
        match comp.arrays.iter().find(|a| a.value_reference == r) {
            Some(a) => out.extend_from_slice(&a.elements),
            None => out.push(r),
        }
    }
    Some(out)
}
