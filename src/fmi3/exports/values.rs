//! Exports reading and writing variables: fmi3GetFloat64/Int32/Boolean and
//! their setters over the table's Real, Integer and Boolean variables (plus
//! the independent variable `time`, read only, and the `fmi3Float64` arrays,
//! each read or written as its elements), and the other types, which the FMU
//! has no variable of.

use fmi_sys::fmi3::*;

use crate::fmi3::xml::TIME_VALUE_REFERENCE;
use crate::fmu::instance::{Instance, Status};
use crate::fmu::states::Call;
use crate::fmu::variables::Kind;

use super::glue::*;
use super::intermediate::get_float64;

fn get_call(kind: Kind) -> Call {
    match kind {
        Kind::Real => Call::GetReal,
        Kind::Integer => Call::GetInteger,
        Kind::Boolean => Call::GetBoolean,
    }
}

fn set_call(kind: Kind) -> Call {
    match kind {
        Kind::Real => Call::SetReal,
        Kind::Integer => Call::SetInteger,
        Kind::Boolean => Call::SetBoolean,
    }
}

/// fmi3Error unless `nValues` equals `nValueReferences` (every variable is a
/// scalar).
fn counts_match(
    i: &mut Instance,
    call: Call,
    n_refs: usize,
    n_values: usize,
) -> Result<(), Status> {
    if n_refs == n_values {
        return Ok(());
    }
    let name = call.name_in(i.version());
    Err(i.report(
        Status::Error,
        format!(
            "{name}: {n_values} values for {n_refs} scalar values (arrays counted by their elements)"
        ),
    ))
}

/// The value of `vr` as a `kind` (`time` for [`TIME_VALUE_REFERENCE`]).
fn get_one(i: &mut Instance, vr: u32, kind: Kind) -> Result<f64, Status> {
    if vr == TIME_VALUE_REFERENCE && kind == Kind::Real {
        i.check(Call::GetReal)?;
        return Ok(i.time());
    }
    i.get(vr, kind)
}

fn get_values<T>(
    comp: Option<&mut Component>,
    refs: Option<&[fmi3ValueReference]>,
    out: Option<&mut [T]>,
    n_values: usize,
    kind: Kind,
    convert: impl Fn(f64) -> T,
) -> fmi3Status {
    guarded(comp, |i| {
        let call = get_call(kind);
        let (Some(refs), Some(out)) = (refs, out) else {
            return null_argument(i, call);
        };
        if let Err(s) = counts_match(i, call, refs.len(), n_values) {
            return s;
        }
        for (r, o) in refs.iter().zip(out.iter_mut()) {
            match get_one(i, *r, kind) {
                Ok(v) => *o = convert(v),
                Err(s) => return s,
            }
        }
        Status::Ok
    })
}

fn set_values<T: Copy>(
    comp: Option<&mut Component>,
    refs: Option<&[fmi3ValueReference]>,
    values: Option<&[T]>,
    kind: Kind,
    convert: impl Fn(T) -> f64,
) -> fmi3Status {
    guarded(comp, |i| {
        let call = set_call(kind);
        let (Some(refs), Some(values)) = (refs, values) else {
            return null_argument(i, call);
        };
        for (r, v) in refs.iter().zip(values) {
            if *r == TIME_VALUE_REFERENCE {
                let name = call.name_in(i.version());
                return i.report(
                    Status::Error,
                    format!("{name}: time is the independent variable and cannot be set"),
                );
            }
            let s = i.set(*r, kind, convert(*v));
            if s != Status::Ok {
                return s;
            }
        }
        Status::Ok
    })
}

/// fmi3Error for a get or set of a type the FMU has no variable of (fmi3OK
/// for no value reference at all).
pub(super) fn no_such_type(
    comp: Option<&mut Component>,
    refs: Option<&[fmi3ValueReference]>,
    name: &str,
    getter: bool,
) -> fmi3Status {
    guarded(comp, |i| {
        let call = if getter { Call::GetReal } else { Call::SetReal };
        if let Err(s) = i.check(call) {
            return s;
        }
        let ty = name
            .trim_start_matches("fmi3Get")
            .trim_start_matches("fmi3Set");
        match refs {
            Some([]) => Status::Ok,
            Some([first, ..]) => i.report(
                Status::Error,
                format!("{name}: value reference {first}: the FMU has no {ty} variables"),
            ),
            None => i.report(
                Status::Error,
                format!("{name}: a required pointer argument is NULL"),
            ),
        }
    })
}

/// `fmi3GetFloat64`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetFloat64(
    instance: fmi3Instance,
    valueReferences: *const fmi3ValueReference,
    nValueReferences: usize,
    values: *mut fmi3Float64,
    nValues: usize,
) -> fmi3Status {
    // SAFETY: `valueReferences` holds `nValueReferences` and `values`
    // `nValues` elements (contract).
    let (refs, mut out) = unsafe {
        (
            slice_from(valueReferences, nValueReferences),
            slice_from_mut(values, nValues),
        )
    };
    // Inside the intermediate-update callback: from the window, without
    // touching the component fmi3DoStep holds.
    if let Some(status) = get_float64(instance as usize, refs, out.as_deref_mut(), nValues) {
        return status;
    }
    // SAFETY: `instance` is NULL or live (contract).
    let comp = unsafe { component(instance) };
    let expanded = expand(&comp, refs);
    let refs = expanded.as_deref().or(refs);
    get_values(comp, refs, out, nValues, Kind::Real, |v| v)
}

/// `fmi3GetInt32`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetInt32(
    instance: fmi3Instance,
    valueReferences: *const fmi3ValueReference,
    nValueReferences: usize,
    values: *mut fmi3Int32,
    nValues: usize,
) -> fmi3Status {
    // SAFETY: `instance` is live, `valueReferences` holds `nValueReferences`
    // and `values` `nValues` elements (contract).
    let (comp, refs, out) = unsafe {
        (
            component(instance),
            slice_from(valueReferences, nValueReferences),
            slice_from_mut(values, nValues),
        )
    };
    get_values(comp, refs, out, nValues, Kind::Integer, |v| v as i32)
}

/// `fmi3GetBoolean`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetBoolean(
    instance: fmi3Instance,
    valueReferences: *const fmi3ValueReference,
    nValueReferences: usize,
    values: *mut fmi3Boolean,
    nValues: usize,
) -> fmi3Status {
    // SAFETY: `instance` is live, `valueReferences` holds `nValueReferences`
    // and `values` `nValues` elements (contract).
    let (comp, refs, out) = unsafe {
        (
            component(instance),
            slice_from(valueReferences, nValueReferences),
            slice_from_mut(values, nValues),
        )
    };
    get_values(comp, refs, out, nValues, Kind::Boolean, |v| v != 0.0)
}

/// `fmi3SetFloat64`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SetFloat64(
    instance: fmi3Instance,
    valueReferences: *const fmi3ValueReference,
    nValueReferences: usize,
    values: *const fmi3Float64,
    nValues: usize,
) -> fmi3Status {
    // SAFETY: `instance` is live, `valueReferences` holds `nValueReferences`
    // and `values` `nValues` elements (contract).
    let (comp, refs, vals) = unsafe {
        (
            component(instance),
            slice_from(valueReferences, nValueReferences),
            slice_from(values, nValues),
        )
    };
    let expanded = expand(&comp, refs);
    let refs = expanded.as_deref().or(refs);
    set_checked(comp, refs, vals, Kind::Real, |v| v)
}

/// `fmi3SetInt32`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SetInt32(
    instance: fmi3Instance,
    valueReferences: *const fmi3ValueReference,
    nValueReferences: usize,
    values: *const fmi3Int32,
    nValues: usize,
) -> fmi3Status {
    // SAFETY: `instance` is live, `valueReferences` holds `nValueReferences`
    // and `values` `nValues` elements (contract).
    let (comp, refs, vals) = unsafe {
        (
            component(instance),
            slice_from(valueReferences, nValueReferences),
            slice_from(values, nValues),
        )
    };
    set_checked(comp, refs, vals, Kind::Integer, f64::from)
}

/// `fmi3SetBoolean`.
///
/// # Safety
///
/// The importer keeps the safety contract of the `exports` module.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SetBoolean(
    instance: fmi3Instance,
    valueReferences: *const fmi3ValueReference,
    nValueReferences: usize,
    values: *const fmi3Boolean,
    nValues: usize,
) -> fmi3Status {
    // SAFETY: `instance` is live, `valueReferences` holds `nValueReferences`
    // and `values` `nValues` elements (contract).
    let (comp, refs, vals) = unsafe {
        (
            component(instance),
            slice_from(valueReferences, nValueReferences),
            slice_from(values, nValues),
        )
    };
    set_checked(comp, refs, vals, Kind::Boolean, |b| f64::from(u8::from(b)))
}

/// [`set_values`] after checking that there is one value per reference.
fn set_checked<T: Copy>(
    comp: Option<&mut Component>,
    refs: Option<&[fmi3ValueReference]>,
    values: Option<&[T]>,
    kind: Kind,
    convert: impl Fn(T) -> f64,
) -> fmi3Status {
    let (n_refs, n_values) = (refs.map(<[_]>::len), values.map(<[_]>::len));
    match (n_refs, n_values) {
        (Some(a), Some(b)) if a != b => guarded(comp, |i| {
            counts_match(i, set_call(kind), a, b)
                .err()
                .unwrap_or(Status::Error)
        }),
        _ => set_values(comp, refs, values, kind, convert),
    }
}
