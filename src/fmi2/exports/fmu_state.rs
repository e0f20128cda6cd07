//! Exports of the FMU state: save, restore, free, serialize, deserialize,
//! written once for both versions ([`crate::fmu::c_abi::fmu_state_exports`]).

use fmi_sys::fmi2::*;

use crate::fmu::c_abi::fmu_state_exports;
use crate::fmu::instance::Status;
use crate::fmu::states::Call;

use super::glue::*;

fmu_state_exports!(
    instance: fmi2Component,
    state: fmi2FMUstate,
    byte: fmi2Byte,
    status: fmi2Status,
    get: fmi2GetFMUstate,
    set: fmi2SetFMUstate,
    free: fmi2FreeFMUstate,
    size: fmi2SerializedFMUstateSize,
    serialize: fmi2SerializeFMUstate,
    deserialize: fmi2DeSerializeFMUstate,
);
