//! Exports of the FMU state: save, restore, free, serialize, deserialize.

use fmi_sys::fmi2::*;

use crate::fmu::instance::Status;
use crate::fmu::states::Call;

use super::glue::*;

/// `fmi2GetFMUstate`: a new state, or the one in `*FMUstate` overwritten.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetFMUstate(
    c: fmi2Component,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    // SAFETY: `c` is live, `FMUstate` is NULL or writable (contract).
    let (comp, slot) = unsafe { (component(c), FMUstate.as_mut()) };
    guarded(comp, |i| {
        let Some(slot) = slot else {
            return null_argument(i, Call::GetFmuState);
        };
        match i.snapshot() {
            Ok(snap) => {
                // SAFETY: `*slot` is NULL or a live state of this library
                // (contract).
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

/// `fmi2SetFMUstate`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetFMUstate(c: fmi2Component, FMUstate: fmi2FMUstate) -> fmi2Status {
    // SAFETY: `c` is live, `FMUstate` is NULL or a live state (contract).
    let (comp, snap) = unsafe { (component(c), snapshot_mut(FMUstate)) };
    guarded(comp, |i| match snap {
        Some(snap) => i.restore(snap),
        None => null_argument(i, Call::SetFmuState),
    })
}

/// `fmi2FreeFMUstate`: frees `*FMUstate` and sets it to NULL.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeFMUstate(
    c: fmi2Component,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    // SAFETY: `c` is live, `FMUstate` is NULL or writable (contract).
    let (comp, slot) = unsafe { (component(c), FMUstate.as_mut()) };
    guarded(comp, |i| {
        let call = Call::FreeFmuState;
        if let Err(s) = i.check(call) {
            return s;
        }
        let Some(slot) = slot else {
            return null_argument(i, call);
        };
        if !slot.is_null() {
            // SAFETY: `*slot` is a live state of this library (contract); it
            // is cleared at once, so it is freed only once.
            unsafe { free_state(*slot) };
            *slot = std::ptr::null_mut();
        }
        Status::Ok
    })
}

/// `fmi2SerializedFMUstateSize`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SerializedFMUstateSize(
    c: fmi2Component,
    FMUstate: fmi2FMUstate,
    size: *mut usize,
) -> fmi2Status {
    // SAFETY: `c` is live, `FMUstate` is NULL or a live state, `size` is NULL
    // or writable (contract).
    let (comp, snap, size) = unsafe { (component(c), snapshot_mut(FMUstate), size.as_mut()) };
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

/// `fmi2SerializeFMUstate`: the byte image into a buffer of exactly its size.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SerializeFMUstate(
    c: fmi2Component,
    FMUstate: fmi2FMUstate,
    serializedState: *mut fmi2Byte,
    size: usize,
) -> fmi2Status {
    // SAFETY: `c` is live, `FMUstate` is NULL or a live state,
    // `serializedState` holds `size` writable bytes (contract).
    let (comp, snap, out) = unsafe {
        (
            component(c),
            snapshot_mut(FMUstate),
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
                    "fmi2SerializeFMUstate: buffer of {size} bytes, the state needs {}",
                    bytes.len()
                ),
            ),
            Err(s) => s,
        }
    })
}

/// `fmi2DeSerializeFMUstate`: a state from its byte image, into `*FMUstate`
/// (a state already there is freed).
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
    c: fmi2Component,
    serializedState: *const fmi2Byte,
    size: usize,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    // SAFETY: `c` is live, `serializedState` holds `size` bytes, `FMUstate` is
    // NULL or writable (contract).
    let (comp, bytes, slot) = unsafe {
        (
            component(c),
            slice_from(serializedState.cast::<u8>(), size),
            FMUstate.as_mut(),
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
