//! The FMI 3.0 logger: a [`Status`] as an `fmi3Status` code and a message
//! sent to the importer's logger callback.

use std::ffi::CString;

use fmi_sys::fmi3::*;

use crate::fmu::instance::Status;

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
