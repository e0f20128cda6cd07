//! Exports reading and writing variables: fmi2Get*/fmi2Set*, input
//! derivatives and the derivatives the FMU does not provide.

use fmi_sys::fmi2::*;

use crate::fmu::instance::Status;
use crate::fmu::states::Call;
use crate::fmu::variables::Kind;

use super::glue::*;

/// fmi2Get* of `refs` into `out`, each value converted from f64.
fn get_values<T>(
    comp: Option<&mut Component>,
    refs: Option<&[fmi2ValueReference]>,
    out: Option<&mut [T]>,
    kind: Kind,
    convert: impl Fn(f64) -> T,
) -> fmi2Status {
    guarded(comp, |i| {
        let (Some(refs), Some(out)) = (refs, out) else {
            let call = match kind {
                Kind::Real => Call::GetReal,
                Kind::Integer => Call::GetInteger,
                Kind::Boolean => Call::GetBoolean,
            };
            return null_argument(i, call);
        };
        for (r, o) in refs.iter().zip(out.iter_mut()) {
            match i.get(*r, kind) {
                Ok(v) => *o = convert(v),
                Err(s) => return s,
            }
        }
        Status::Ok
    })
}

/// fmi2Set* of `refs` to `values`, each converted to f64.
fn set_values<T: Copy>(
    comp: Option<&mut Component>,
    refs: Option<&[fmi2ValueReference]>,
    values: Option<&[T]>,
    kind: Kind,
    convert: impl Fn(T) -> f64,
) -> fmi2Status {
    guarded(comp, |i| {
        let (Some(refs), Some(values)) = (refs, values) else {
            let call = match kind {
                Kind::Real => Call::SetReal,
                Kind::Integer => Call::SetInteger,
                Kind::Boolean => Call::SetBoolean,
            };
            return null_argument(i, call);
        };
        for (r, v) in refs.iter().zip(values) {
            let s = i.set(*r, kind, convert(*v));
            if s != Status::Ok {
                return s;
            }
        }
        Status::Ok
    })
}

/// fmi2GetString / fmi2SetString: the FMU has no String variables.
fn no_strings(
    comp: Option<&mut Component>,
    refs: Option<&[fmi2ValueReference]>,
    call: Call,
) -> fmi2Status {
    guarded(comp, |i| {
        if let Err(s) = i.check(call) {
            return s;
        }
        match refs {
            Some([]) => Status::Ok,
            Some([first, ..]) => i.report(
                Status::Error,
                format!(
                    "{}: value reference {first}: the FMU has no String variables",
                    call.name()
                ),
            ),
            None => null_argument(i, call),
        }
    })
}

/// `fmi2GetReal`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetReal(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Real,
) -> fmi2Status {
    // SAFETY: `c` is live, `vr` and `value` hold `nvr` elements (contract).
    let (comp, refs, out) = unsafe {
        (
            component(c),
            slice_from(vr, nvr),
            slice_from_mut(value, nvr),
        )
    };
    get_values(comp, refs, out, Kind::Real, |v| v)
}

/// `fmi2GetInteger`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetInteger(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Integer,
) -> fmi2Status {
    // SAFETY: `c` is live, `vr` and `value` hold `nvr` elements (contract).
    let (comp, refs, out) = unsafe {
        (
            component(c),
            slice_from(vr, nvr),
            slice_from_mut(value, nvr),
        )
    };
    get_values(comp, refs, out, Kind::Integer, |v| v as fmi2Integer)
}

/// `fmi2GetBoolean`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetBoolean(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Boolean,
) -> fmi2Status {
    // SAFETY: `c` is live, `vr` and `value` hold `nvr` elements (contract).
    let (comp, refs, out) = unsafe {
        (
            component(c),
            slice_from(vr, nvr),
            slice_from_mut(value, nvr),
        )
    };
    get_values(comp, refs, out, Kind::Boolean, |v| {
        fmi2Boolean::from(v != 0.0)
    })
}

/// `fmi2GetString`: the FMU has no String variables.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetString(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    _value: *mut fmi2String,
) -> fmi2Status {
    // SAFETY: `c` is live, `vr` holds `nvr` elements (contract).
    let (comp, refs) = unsafe { (component(c), slice_from(vr, nvr)) };
    no_strings(comp, refs, Call::GetString)
}

/// `fmi2SetReal`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetReal(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Real,
) -> fmi2Status {
    // SAFETY: `c` is live, `vr` and `value` hold `nvr` elements (contract).
    let (comp, refs, values) =
        unsafe { (component(c), slice_from(vr, nvr), slice_from(value, nvr)) };
    set_values(comp, refs, values, Kind::Real, |v| v)
}

/// `fmi2SetInteger`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetInteger(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Integer,
) -> fmi2Status {
    // SAFETY: `c` is live, `vr` and `value` hold `nvr` elements (contract).
    let (comp, refs, values) =
        unsafe { (component(c), slice_from(vr, nvr), slice_from(value, nvr)) };
    set_values(comp, refs, values, Kind::Integer, f64::from)
}

/// `fmi2SetBoolean`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetBoolean(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Boolean,
) -> fmi2Status {
    // SAFETY: `c` is live, `vr` and `value` hold `nvr` elements (contract).
    let (comp, refs, values) =
        unsafe { (component(c), slice_from(vr, nvr), slice_from(value, nvr)) };
    set_values(comp, refs, values, Kind::Boolean, |v| {
        f64::from(u8::from(v != 0))
    })
}

/// `fmi2SetString`: the FMU has no String variables.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetString(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    _value: *const fmi2String,
) -> fmi2Status {
    // SAFETY: `c` is live, `vr` holds `nvr` elements (contract).
    let (comp, refs) = unsafe { (component(c), slice_from(vr, nvr)) };
    no_strings(comp, refs, Call::SetString)
}

/// `fmi2GetDirectionalDerivative`: not provided.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetDirectionalDerivative(
    c: fmi2Component,
    _vUnknown_ref: *const fmi2ValueReference,
    _nUnknown: usize,
    _vKnown_ref: *const fmi2ValueReference,
    _nKnown: usize,
    _dvKnown: *const fmi2Real,
    _dvUnknown: *mut fmi2Real,
) -> fmi2Status {
    // SAFETY: `c` is NULL or live (contract).
    let comp = unsafe { component(c) };
    not_provided(
        comp,
        Call::GetDirectionalDerivative,
        "not provided (providesDirectionalDerivative = false)",
    )
}

/// `fmi2SetRealInputDerivatives` (first order).
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetRealInputDerivatives(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    order: *const fmi2Integer,
    value: *const fmi2Real,
) -> fmi2Status {
    // SAFETY: `c` is live, `vr`, `order` and `value` hold `nvr` elements
    // (contract).
    let (comp, refs, orders, values) = unsafe {
        (
            component(c),
            slice_from(vr, nvr),
            slice_from(order, nvr),
            slice_from(value, nvr),
        )
    };
    guarded(comp, |i| {
        let (Some(refs), Some(orders), Some(values)) = (refs, orders, values) else {
            return null_argument(i, Call::SetRealInputDerivatives);
        };
        for ((r, o), v) in refs.iter().zip(orders).zip(values) {
            let s = i.set_input_derivative(*r, *o, *v);
            if s != Status::Ok {
                return s;
            }
        }
        Status::Ok
    })
}

/// `fmi2GetRealOutputDerivatives`: not provided.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetRealOutputDerivatives(
    c: fmi2Component,
    _vr: *const fmi2ValueReference,
    _nvr: usize,
    _order: *const fmi2Integer,
    _value: *mut fmi2Real,
) -> fmi2Status {
    // SAFETY: `c` is NULL or live (contract).
    let comp = unsafe { component(c) };
    not_provided(
        comp,
        Call::GetRealOutputDerivatives,
        "not provided (maxOutputDerivativeOrder = 0)",
    )
}
