//! What the FMI 2.0 and FMI 3.0 C exports share: the pointer helpers (each a
//! tiny `unsafe` step with its NULL check), the FMU state handed to the
//! importer as a pointer, the C-side wrapper of an instance ([`Wrapper`]: the
//! panic guard, the log flush, `SetDebugLogging`), the messages for NULL
//! arguments and unknown log categories, and the exports that are one call on the instance
//! ([`instance_exports`]) and the six FMU-state exports
//! ([`fmu_state_exports`]), written once and instantiated by each version
//! under its own names and types. The two C types of a pointer (`fmi2String` and
//! `fmi3String`, `fmi2FMUstate` and `fmi3FMUState`) are the same Rust types,
//! `*const c_char` and `*mut c_void`.
//!
//! # Safety contract
//!
//! As the `exports` modules of both versions state it: arrays hold the number
//! of elements passed with them, strings are NUL-terminated, an FMU state is
//! NULL or one this library made and has not freed, all valid during the call.

use std::ffi::{CStr, c_char, c_void};
use std::panic::{AssertUnwindSafe, catch_unwind};

use super::description::LOG_CATEGORIES;
use super::instance::{Instance, Status};
use super::snapshot::Snapshot;
use super::states::Call;

/// The `n` elements at `p`: empty for `n = 0`, `None` for NULL otherwise.
///
/// # Safety
///
/// `p` is NULL or points to `n` initialized elements valid for `'a` (module
/// contract).
pub unsafe fn slice_from<'a, T>(p: *const T, n: usize) -> Option<&'a [T]> {
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
pub unsafe fn slice_from_mut<'a, T>(p: *mut T, n: usize) -> Option<&'a mut [T]> {
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
pub unsafe fn string_from(p: *const c_char) -> Option<String> {
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
pub unsafe fn snapshot_mut<'a>(s: *mut c_void) -> Option<&'a mut Snapshot> {
    // SAFETY: a non-null state is the `Box<Snapshot>` pointer `into_state`
    // made, not yet freed (contract).
    unsafe { s.cast::<Snapshot>().as_mut() }
}

/// A snapshot handed to the importer as an FMU state (freed by `free_state`).
pub fn into_state(snap: Snapshot) -> *mut c_void {
    Box::into_raw(Box::new(snap)).cast()
}

/// Free an FMU state made by [`into_state`].
///
/// # Safety
///
/// `s` came from [`into_state`] and is freed only once (module contract).
pub unsafe fn free_state(s: *mut c_void) {
    // SAFETY: `s` is a `Box<Snapshot>` pointer from `into_state`, not yet
    // freed (contract).
    drop(unsafe { Box::from_raw(s.cast::<Snapshot>()) });
}

/// The C-side wrapper of an instance, in either version: the instance, the
/// logging switches, and the version's logger.
pub trait Wrapper {
    /// The instance.
    fn instance(&mut self) -> &mut Instance;

    /// Whether logging is on, and which categories are enabled (in
    /// [`LOG_CATEGORIES`] order).
    fn logging(&mut self) -> (&mut bool, &mut [bool; LOG_CATEGORIES.len()]);

    /// Send one message to the importer's logger (discards and errors always,
    /// others when `enabled`).
    fn log(&self, enabled: bool, status: Status, category: &str, text: &str);

    /// Tell the instance whether step statistics are wanted: logging on and
    /// the `logAll` category enabled.
    fn sync_step_statistics(&mut self) {
        let all = LOG_CATEGORIES.iter().position(|(c, _)| *c == "logAll");
        let (on, categories) = self.logging();
        let on = *on && all.is_none_or(|i| categories[i]);
        self.instance().set_step_statistics(on);
    }

    /// Send the instance's queued messages to the logger, each when logging
    /// is on and its category enabled.
    fn flush(&mut self) {
        for (status, category, text) in self.instance().drain_messages() {
            let index = LOG_CATEGORIES.iter().position(|(c, _)| *c == category);
            let (on, categories) = self.logging();
            let enabled = *on && index.is_none_or(|i| categories[i]);
            self.log(enabled, status, category, &text);
        }
    }
}

/// Run `f` on the instance of `comp` (an error for NULL), catch panics (a
/// fatal error with a message), flush the queued log messages.
pub fn guarded<C: Wrapper>(
    comp: Option<&mut C>,
    f: impl FnOnce(&mut Instance) -> Status,
) -> Status {
    let Some(comp) = comp else {
        return Status::Error;
    };
    let status = match catch_unwind(AssertUnwindSafe(|| f(comp.instance()))) {
        Ok(s) => s,
        Err(_) => comp.instance().report(
            Status::Fatal,
            "internal error (panic caught at the FMI boundary)".into(),
        ),
    };
    comp.flush();
    status
}

/// `SetDebugLogging` of either version: logging `on`, the categories
/// [`debug_categories`] finds in `names`; then the step statistics follow and
/// the messages are flushed.
pub fn set_debug_logging<C: Wrapper>(
    comp: &mut C,
    on: bool,
    names: Option<Vec<Option<String>>>,
) -> Status {
    let result = catch_unwind(AssertUnwindSafe(|| {
        *comp.logging().0 = on;
        match debug_categories(comp.instance(), names) {
            Ok(enabled) => {
                *comp.logging().1 = enabled;
                Status::Ok
            }
            Err(s) => s,
        }
    }));
    let status = result.unwrap_or(Status::Fatal);
    comp.sync_step_statistics();
    comp.flush();
    status
}

/// fmi2Error / fmi3Error with a message for a NULL argument of `call`.
pub fn null_argument(inst: &mut Instance, call: Call) -> Status {
    let name = call.name_in(inst.version());
    inst.report(
        Status::Error,
        format!("{name}: a required pointer argument is NULL"),
    )
}

/// The log categories `SetDebugLogging` enables: every one for an empty list,
/// else those named (`names`: each entry's text, `None` for a NULL entry; the
/// whole list `None` for a NULL array with a count above zero); an error
/// with a message for a NULL and for an unknown name.
pub fn debug_categories(
    inst: &mut Instance,
    names: Option<Vec<Option<String>>>,
) -> Result<[bool; LOG_CATEGORIES.len()], Status> {
    let call = Call::SetDebugLogging;
    inst.check(call)?;
    let Some(names) = names else {
        return Err(null_argument(inst, call));
    };
    if names.is_empty() {
        return Ok([true; LOG_CATEGORIES.len()]);
    }
    let mut enabled = [false; LOG_CATEGORIES.len()];
    for name in names {
        let Some(name) = name else {
            return Err(null_argument(inst, call));
        };
        match LOG_CATEGORIES.iter().position(|(c, _)| *c == name) {
            Some(i) => enabled[i] = true,
            None => {
                let text = format!(
                    "{}: unknown log category {name:?}",
                    call.name_in(inst.version())
                );
                return Err(inst.report(Status::Error, text));
            }
        }
    }
    Ok(enabled)
}

/// The six FMU-state exports of one FMI version under its names and C types:
/// get (a new state, or the one in `*FMUState` overwritten), set, free
/// (`*FMUState` freed and set to NULL), the serialized size, serialize (the
/// byte image into a buffer of exactly its size), deserialize (a state from
/// its byte image into `*FMUState`, a state already there freed). Expanded in
/// the version's `exports::fmu_state`, where `component`, `guarded`,
/// `status`-returning helpers and these module's functions are in scope; the
/// export signatures are checked against the official headers there.
macro_rules! fmu_state_exports {
    (
        instance: $instance:ty,
        state: $state:ty,
        byte: $byte:ty,
        status: $status:ty,
        get: $get:ident,
        set: $set:ident,
        free: $free:ident,
        size: $size:ident,
        serialize: $serialize:ident,
        deserialize: $deserialize:ident $(,)?
    ) => {
        #[doc = concat!("`", stringify!($get), "`: a new state, or the one in `*FMUState` overwritten.")]
        ///
        /// # Safety
        ///
        /// The importer keeps the safety contract of the `exports` module.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $get(c: $instance, FMUState: *mut $state) -> $status {
            // SAFETY: `c` is live, `FMUState` is NULL or writable (contract).
            let (comp, slot) = unsafe { (component(c), FMUState.as_mut()) };
            guarded(comp, |i| {
                let Some(slot) = slot else {
                    return null_argument(i, Call::GetFmuState);
                };
                match i.snapshot() {
                    Ok(snap) => {
                        // SAFETY: `*slot` is NULL or a live state of this
                        // library (contract).
                        match unsafe { snapshot_mut(*slot) } {
                            Some(old) => *old = snap,
                            None => *slot = into_state(snap),
                        }
                        Status::Ok
                    }
                    Err(s) => s,
                }
            })
        }

        #[doc = concat!("`", stringify!($set), "`.")]
        ///
        /// # Safety
        ///
        /// The importer keeps the safety contract of the `exports` module.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $set(c: $instance, FMUState: $state) -> $status {
            // SAFETY: `c` is live, `FMUState` is NULL or a live state (contract).
            let (comp, snap) = unsafe { (component(c), snapshot_mut(FMUState)) };
            guarded(comp, |i| match snap {
                Some(snap) => i.restore(snap),
                None => null_argument(i, Call::SetFmuState),
            })
        }

        #[doc = concat!("`", stringify!($free), "`: frees `*FMUState` and sets it to NULL.")]
        ///
        /// # Safety
        ///
        /// The importer keeps the safety contract of the `exports` module.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $free(c: $instance, FMUState: *mut $state) -> $status {
            // SAFETY: `c` is live, `FMUState` is NULL or writable (contract).
            let (comp, slot) = unsafe { (component(c), FMUState.as_mut()) };
            guarded(comp, |i| {
                let call = Call::FreeFmuState;
                if let Err(s) = i.check(call) {
                    return s;
                }
                let Some(slot) = slot else {
                    return null_argument(i, call);
                };
                if !slot.is_null() {
                    // SAFETY: `*slot` is a live state of this library
                    // (contract); it is cleared at once, so it is freed only
                    // once.
                    unsafe { free_state(*slot) };
                    *slot = std::ptr::null_mut();
                }
                Status::Ok
            })
        }

        #[doc = concat!("`", stringify!($size), "`.")]
        ///
        /// # Safety
        ///
        /// The importer keeps the safety contract of the `exports` module.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $size(c: $instance, FMUState: $state, size: *mut usize) -> $status {
            // SAFETY: `c` is live, `FMUState` is NULL or a live state, `size`
            // is NULL or writable (contract).
            let (comp, snap, size) =
                unsafe { (component(c), snapshot_mut(FMUState), size.as_mut()) };
            guarded(comp, |i| {
                let (Some(snap), Some(size)) = (snap, size) else {
                    return null_argument(i, Call::SerializedFmuStateSize);
                };
                match i.serialized_size(snap) {
                    Ok(n) => {
                        *size = n;
                        Status::Ok
                    }
                    Err(s) => s,
                }
            })
        }

        #[doc = concat!("`", stringify!($serialize), "`: the byte image into a buffer of exactly its size.")]
        ///
        /// # Safety
        ///
        /// The importer keeps the safety contract of the `exports` module.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $serialize(
            c: $instance,
            FMUState: $state,
            serializedState: *mut $byte,
            size: usize,
        ) -> $status {
            // SAFETY: `c` is live, `FMUState` is NULL or a live state,
            // `serializedState` holds `size` writable bytes (contract).
            let (comp, snap, out) = unsafe {
                (
                    component(c),
                    snapshot_mut(FMUState),
                    slice_from_mut(serializedState.cast::<u8>(), size),
                )
            };
            guarded(comp, |i| {
                let (Some(snap), Some(out)) = (snap, out) else {
                    return null_argument(i, Call::SerializeFmuState);
                };
                match i.serialize(snap) {
                    Ok(bytes) if bytes.len() == out.len() => {
                        out.copy_from_slice(&bytes);
                        Status::Ok
                    }
                    Ok(bytes) => i.report(
                        Status::Error,
                        format!(
                            "{}: buffer of {size} bytes, the state needs {}",
                            stringify!($serialize),
                            bytes.len()
                        ),
                    ),
                    Err(s) => s,
                }
            })
        }

        #[doc = concat!("`", stringify!($deserialize), "`: a state from its byte image, into `*FMUState` (a state already there is freed).")]
        ///
        /// # Safety
        ///
        /// The importer keeps the safety contract of the `exports` module.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $deserialize(
            c: $instance,
            serializedState: *const $byte,
            size: usize,
            FMUState: *mut $state,
        ) -> $status {
            // SAFETY: `c` is live, `serializedState` holds `size` bytes,
            // `FMUState` is NULL or writable (contract).
            let (comp, bytes, slot) = unsafe {
                (
                    component(c),
                    slice_from(serializedState.cast::<u8>(), size),
                    FMUState.as_mut(),
                )
            };
            guarded(comp, |i| {
                let (Some(bytes), Some(slot)) = (bytes, slot) else {
                    return null_argument(i, Call::DeSerializeFmuState);
                };
                match i.deserialize(bytes) {
                    Ok(snap) => {
                        if !slot.is_null() {
                            // SAFETY: `*slot` is a live state of this library
                            // (contract); it is overwritten at once.
                            unsafe { free_state(*slot) };
                        }
                        *slot = into_state(snap);
                        Status::Ok
                    }
                    Err(s) => s,
                }
            })
        }
    };
}

pub(crate) use fmu_state_exports;

/// Exports that are one call of an [`Instance`] method on the instance (each
/// `name => method`, with its doc comment), of one FMI version's instance
/// and status types. Expanded in the version's `exports::lifecycle`, where
/// `component` and `guarded` are in scope.
macro_rules! instance_exports {
    (
        instance: $instance:ty,
        status: $status:ty;
        $( $(#[$doc:meta])* $name:ident => $method:path; )*
    ) => {
        $(
            $(#[$doc])*
            ///
            /// # Safety
            ///
            /// The importer keeps the safety contract of the `exports` module.
            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn $name(instance: $instance) -> $status {
                // SAFETY: `instance` is NULL or live (contract).
                let comp = unsafe { component(instance) };
                guarded(comp, $method)
            }
        )*
    };
}

pub(crate) use instance_exports;
