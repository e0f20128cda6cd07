//! The FMI 3.0 C ABI: every function of `fmi3Functions.h`, with the exact
//! signature of the official headers (types from bindgen via `fmi-sys`,
//! checked at compile time against the header's function typedefs). Each one
//! only turns its pointers into references and slices and calls a safe
//! [`Instance`](crate::fmu::instance::Instance) method; no panic unwinds
//! across the boundary (every call runs under `catch_unwind` and a panic
//! becomes fmi3Fatal). The Co-Simulation calls are provided; the rest answer
//! fmi3Error with a message (`unsupported.rs`).
//!
//! # Safety contract
//!
//! The functions are `unsafe extern "C"`: they are sound exactly when the
//! importer keeps the obligations FMI 3.0 puts on it (§2.2):
//!
//! - `instance` (`fmi3Instance`) is NULL or a value returned by
//!   `fmi3InstantiateCoSimulation` of this library and not yet passed to
//!   `fmi3FreeInstance`; calls on one instance are not made from two threads
//!   at the same time, and `fmi3FreeInstance` is called at most once per
//!   instance;
//! - every array argument (`valueReferences[]`, `values[]`, `categories[]`,
//!   `serializedState[]`) is NULL or holds at least the number of elements
//!   passed with it, and is valid (writable for outputs) during the call;
//! - every string (`fmi3String`) is NULL or NUL-terminated and valid during the
//!   call;
//! - every out-parameter (`size`, `FMUState`, the `fmi3DoStep` flags and
//!   `lastSuccessfulTime`) is NULL or points to writable memory of its type;
//! - an `fmi3FMUState` is NULL or was created by `fmi3GetFMUState` or
//!   `fmi3DeserializeFMUState` of this library and not yet freed by
//!   `fmi3FreeFMUState`;
//! - the logger given to `fmi3InstantiateCoSimulation` stays callable until
//!   `fmi3FreeInstance`.
//!
//! NULL is checked here everywhere and answered with fmi3Error and a message.
//! Each `unsafe` block covers only the pointer conversions and cites the
//! contract in its `// SAFETY:` comment; everything else is safe Rust.

#![allow(non_snake_case)]

mod fmu_state;
mod glue;
mod intermediate;
mod lifecycle;
mod logger;
mod unsupported;
mod values;

use fmi_sys::fmi3::*;
use fmu_state::*;
use lifecycle::*;
use unsupported::*;
use values::*;

/// Compile-time proof that every export has the header's exact signature.
macro_rules! same_signature {
    ($($name:ident : $ty:ident),* $(,)?) => {
        const _: () = { $( let _: $ty = Some($name); )* };
    };
}

same_signature!(
    fmi3GetVersion: fmi3GetVersionTYPE,
    fmi3SetDebugLogging: fmi3SetDebugLoggingTYPE,
    fmi3InstantiateModelExchange: fmi3InstantiateModelExchangeTYPE,
    fmi3InstantiateCoSimulation: fmi3InstantiateCoSimulationTYPE,
    fmi3InstantiateScheduledExecution: fmi3InstantiateScheduledExecutionTYPE,
    fmi3FreeInstance: fmi3FreeInstanceTYPE,
    fmi3EnterInitializationMode: fmi3EnterInitializationModeTYPE,
    fmi3ExitInitializationMode: fmi3ExitInitializationModeTYPE,
    fmi3EnterEventMode: fmi3EnterEventModeTYPE,
    fmi3Terminate: fmi3TerminateTYPE,
    fmi3Reset: fmi3ResetTYPE,
    fmi3GetFloat32: fmi3GetFloat32TYPE,
    fmi3GetFloat64: fmi3GetFloat64TYPE,
    fmi3GetInt8: fmi3GetInt8TYPE,
    fmi3GetUInt8: fmi3GetUInt8TYPE,
    fmi3GetInt16: fmi3GetInt16TYPE,
    fmi3GetUInt16: fmi3GetUInt16TYPE,
    fmi3GetInt32: fmi3GetInt32TYPE,
    fmi3GetUInt32: fmi3GetUInt32TYPE,
    fmi3GetInt64: fmi3GetInt64TYPE,
    fmi3GetUInt64: fmi3GetUInt64TYPE,
    fmi3GetBoolean: fmi3GetBooleanTYPE,
    fmi3GetString: fmi3GetStringTYPE,
    fmi3GetBinary: fmi3GetBinaryTYPE,
    fmi3GetClock: fmi3GetClockTYPE,
    fmi3SetFloat32: fmi3SetFloat32TYPE,
    fmi3SetFloat64: fmi3SetFloat64TYPE,
    fmi3SetInt8: fmi3SetInt8TYPE,
    fmi3SetUInt8: fmi3SetUInt8TYPE,
    fmi3SetInt16: fmi3SetInt16TYPE,
    fmi3SetUInt16: fmi3SetUInt16TYPE,
    fmi3SetInt32: fmi3SetInt32TYPE,
    fmi3SetUInt32: fmi3SetUInt32TYPE,
    fmi3SetInt64: fmi3SetInt64TYPE,
    fmi3SetUInt64: fmi3SetUInt64TYPE,
    fmi3SetBoolean: fmi3SetBooleanTYPE,
    fmi3SetString: fmi3SetStringTYPE,
    fmi3SetBinary: fmi3SetBinaryTYPE,
    fmi3SetClock: fmi3SetClockTYPE,
    fmi3GetNumberOfVariableDependencies: fmi3GetNumberOfVariableDependenciesTYPE,
    fmi3GetVariableDependencies: fmi3GetVariableDependenciesTYPE,
    fmi3GetFMUState: fmi3GetFMUStateTYPE,
    fmi3SetFMUState: fmi3SetFMUStateTYPE,
    fmi3FreeFMUState: fmi3FreeFMUStateTYPE,
    fmi3SerializedFMUStateSize: fmi3SerializedFMUStateSizeTYPE,
    fmi3SerializeFMUState: fmi3SerializeFMUStateTYPE,
    fmi3DeserializeFMUState: fmi3DeserializeFMUStateTYPE,
    fmi3GetDirectionalDerivative: fmi3GetDirectionalDerivativeTYPE,
    fmi3GetAdjointDerivative: fmi3GetAdjointDerivativeTYPE,
    fmi3EnterConfigurationMode: fmi3EnterConfigurationModeTYPE,
    fmi3ExitConfigurationMode: fmi3ExitConfigurationModeTYPE,
    fmi3GetIntervalDecimal: fmi3GetIntervalDecimalTYPE,
    fmi3GetIntervalFraction: fmi3GetIntervalFractionTYPE,
    fmi3GetShiftDecimal: fmi3GetShiftDecimalTYPE,
    fmi3GetShiftFraction: fmi3GetShiftFractionTYPE,
    fmi3SetIntervalDecimal: fmi3SetIntervalDecimalTYPE,
    fmi3SetIntervalFraction: fmi3SetIntervalFractionTYPE,
    fmi3SetShiftDecimal: fmi3SetShiftDecimalTYPE,
    fmi3SetShiftFraction: fmi3SetShiftFractionTYPE,
    fmi3EvaluateDiscreteStates: fmi3EvaluateDiscreteStatesTYPE,
    fmi3UpdateDiscreteStates: fmi3UpdateDiscreteStatesTYPE,
    fmi3EnterContinuousTimeMode: fmi3EnterContinuousTimeModeTYPE,
    fmi3CompletedIntegratorStep: fmi3CompletedIntegratorStepTYPE,
    fmi3SetTime: fmi3SetTimeTYPE,
    fmi3SetContinuousStates: fmi3SetContinuousStatesTYPE,
    fmi3GetContinuousStateDerivatives: fmi3GetContinuousStateDerivativesTYPE,
    fmi3GetEventIndicators: fmi3GetEventIndicatorsTYPE,
    fmi3GetContinuousStates: fmi3GetContinuousStatesTYPE,
    fmi3GetNominalsOfContinuousStates: fmi3GetNominalsOfContinuousStatesTYPE,
    fmi3GetNumberOfEventIndicators: fmi3GetNumberOfEventIndicatorsTYPE,
    fmi3GetNumberOfContinuousStates: fmi3GetNumberOfContinuousStatesTYPE,
    fmi3EnterStepMode: fmi3EnterStepModeTYPE,
    fmi3GetOutputDerivatives: fmi3GetOutputDerivativesTYPE,
    fmi3DoStep: fmi3DoStepTYPE,
    fmi3ActivateModelPartition: fmi3ActivateModelPartitionTYPE,
);
