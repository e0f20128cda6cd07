//! The glue under the FMI 3.0 exports: the C-side component, the logger, the
//! pointer helpers (each a tiny `unsafe` step with its NULL check) and the
//! panic guard.

use std::sync::Arc;

use fmi_sys::fmi3::*;

use crate::fmi3::arrays::{ARRAY_BASE, Array};
use crate::fmu::description::LOG_CATEGORIES;
use crate::fmu::instance::{Instance, Status};

use crate::fmu::c_abi;
pub(super) use crate::fmu::c_abi::{
    Wrapper, free_state, into_state, null_argument, slice_from, slice_from_mut, snapshot_mut,
    string_from,
};

use super::intermediate::{Updates, refused};
pub(super) use super::logger::{log_to, status_code};

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

impl Wrapper for Component {
    fn instance(&mut self) -> &mut Instance {
        &mut self.instance
    }

    fn logging(&mut self) -> (&mut bool, &mut [bool; LOG_CATEGORIES.len()]) {
        (&mut self.logging_on, &mut self.categories)
    }

    fn log(&self, enabled: bool, status: Status, category: &str, text: &str) {
        log_to(
            self.logger,
            self.environment,
            enabled,
            status,
            category,
            text,
        );
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

/// Run `f` on the instance of `comp` (fmi3Error for NULL), catch panics, flush
/// the queued log messages ([`crate::fmu::c_abi::guarded`]).
pub(super) fn guarded(
    comp: Option<&mut Component>,
    f: impl FnOnce(&mut Instance) -> Status,
) -> fmi3Status {
    status_code(c_abi::guarded(comp, f))
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
