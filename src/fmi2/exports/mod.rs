//! The FMI 2.0 C ABI: every `fmi2*` function of the standard, with the exact
//! signature of the official headers (types from bindgen via `fmi-sys`, checked
//! at compile time against the header's function-pointer typedefs). Each one
//! only turns its pointers into references and slices and calls a safe
//! [`Instance`](crate::fmu::instance::Instance) method; no panic unwinds
//! across the boundary (every call runs under `catch_unwind` and a panic
//! becomes fmi2Fatal).
//!
//! # Safety contract
//!
//! The functions are `unsafe extern "C"`: they are sound exactly when the
//! importer keeps the obligations FMI 2.0 puts on it (§2.1, §2.1.5, §2.1.8):
//!
//! - `c` (`fmi2Component`) is NULL or a value returned by `fmi2Instantiate` of
//!   this library and not yet passed to `fmi2FreeInstance`; calls on one
//!   instance are not made from two threads at the same time, and
//!   `fmi2FreeInstance` is called at most once per instance;
//! - every array argument (`vr[]`, `value[]`, `order[]`, `categories[]`,
//!   `serializedState[]`) is NULL or holds at least the number of elements
//!   passed with it, and is valid (writable for outputs) during the call;
//! - every string (`fmi2String`) is NULL or NUL-terminated and valid during the
//!   call;
//! - every out-parameter (`size`, `value`, `FMUstate`) is NULL or points to
//!   writable memory of its type;
//! - an `fmi2FMUstate` is NULL or was created by `fmi2GetFMUstate` or
//!   `fmi2DeSerializeFMUstate` of this library and not yet freed by
//!   `fmi2FreeFMUstate`;
//! - the callback functions given to `fmi2Instantiate` stay callable until
//!   `fmi2FreeInstance`.
//!
//! NULL is checked here everywhere and answered with fmi2Error and a message.
//! Each `unsafe` block covers only the pointer conversions and cites the
//! contract in its `// SAFETY:` comment; everything else is safe Rust.

#![allow(non_snake_case)]

mod fmu_state;
mod glue;
mod lifecycle;
mod values;

use fmi_sys::fmi2::*;
use fmu_state::*;
use lifecycle::*;
use values::*;

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
