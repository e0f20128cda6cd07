//! Exports of the FMU state: save, restore, free, serialize, deserialize,
//! written once for both versions ([`crate::fmu::c_abi::fmu_state_exports`]).

use fmi_sys::fmi3::*;

use crate::fmu::c_abi::fmu_state_exports;
use crate::fmu::instance::Status;
use crate::fmu::states::Call;

use super::glue::*;

fmu_state_exports!(
    instance: fmi3Instance,
    state: fmi3FMUState,
    byte: fmi3Byte,
    status: fmi3Status,
    get: fmi3GetFMUState,
    set: fmi3SetFMUState,
    free: fmi3FreeFMUState,
    size: fmi3SerializedFMUStateSize,
    serialize: fmi3SerializeFMUState,
    deserialize: fmi3DeserializeFMUState,
);
