//! Exports of the FMU state: save, restore, free, serialize, deserialize.

use fmi_sys::fmi3::*;

use crate::fmu::instance::Status;
use crate::fmu::states::Call;

use super::glue::*;

/// `fmi3GetFMUState`: a new state, or the one in `*FMUState` overwritten.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetFMUState(
    c: fmi3Instance,
    FMUState: *mut fmi3FMUState,
) -> fmi3Status {
    // SAFETY: `c` is live, `FMUState` is NULL or writable (contract).
    let (comp, slot) = unsafe { (component(c), FMUState.as_mut()) };
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

/// `fmi3SetFMUState`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SetFMUState(c: fmi3Instance, FMUState: fmi3FMUState) -> fmi3Status {
    // SAFETY: `c` is live, `FMUState` is NULL or a live state (contract).
    let (comp, snap) = unsafe { (component(c), snapshot_mut(FMUState)) };
    guarded(comp, |i| match snap {
        Some(snap) => i.restore(snap),
        None => null_argument(i, Call::SetFmuState),
    })
}

/// `fmi3FreeFMUState`: frees `*FMUState` and sets it to NULL.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3FreeFMUState(
    c: fmi3Instance,
    FMUState: *mut fmi3FMUState,
) -> fmi3Status {
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
            // SAFETY: `*slot` is a live state of this library (contract); it
            // is cleared at once, so it is freed only once.
            unsafe { free_state(*slot) };
            *slot = std::ptr::null_mut();
        }
        Status::Ok
    })
}

/// `fmi3SerializedFMUStateSize`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SerializedFMUStateSize(
    c: fmi3Instance,
    FMUState: fmi3FMUState,
    size: *mut usize,
) -> fmi3Status {
    // SAFETY: `c` is live, `FMUState` is NULL or a live state, `size` is NULL
    // or writable (contract).
    let (comp, snap, size) = unsafe { (component(c), snapshot_mut(FMUState), size.as_mut()) };
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

/// `fmi3SerializeFMUState`: the byte image into a buffer of exactly its size.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SerializeFMUState(
    c: fmi3Instance,
    FMUState: fmi3FMUState,
    serializedState: *mut fmi3Byte,
    size: usize,
) -> fmi3Status {
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
                    "fmi3SerializeFMUState: buffer of {size} bytes, the state needs {}",
                    bytes.len()
                ),
            ),
            Err(s) => s,
        }
    })
}

/// `fmi3DeserializeFMUState`: a state from its byte image, into `*FMUState`
/// (a state already there is freed).
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3DeserializeFMUState(
    c: fmi3Instance,
    serializedState: *const fmi3Byte,
    size: usize,
    FMUState: *mut fmi3FMUState,
) -> fmi3Status {
    // SAFETY: `c` is live, `serializedState` holds `size` bytes, `FMUState` is
    // NULL or writable (contract).
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
