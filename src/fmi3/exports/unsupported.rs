//! The functions of `fmi3Functions.h` this FMU does not provide: each one
//! answers fmi3Error with a log message saying why (the variable types the
//! FMU has none of, event and configuration mode, clocks, derivatives,
//! Model Exchange and Scheduled Execution). None touches its other arguments.

use fmi_sys::fmi3::*;

use super::glue::*;
use super::values::no_such_type;

/// An export that only says why it is not provided.
macro_rules! unsupported {
    ($name:ident ( $($arg:ident : $t:ty),* ) => $why:expr) => {
        #[doc = concat!("`", stringify!($name), "`: fmi3Error with the reason in the log.")]
        ///
        /// # Safety
        ///
        /// The importer keeps the safety contract of the `exports` module.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(instance: fmi3Instance $(, $arg: $t)*) -> fmi3Status {
            // SAFETY: `instance` is NULL or live (contract).
            let comp = unsafe { component(instance) };
            not_provided(comp, stringify!($name), $why)
        }
    };
}

/// A getter or setter of a type the FMU has no variable of: fmi3OK for no
/// value reference, else fmi3Error naming the first.
macro_rules! other_type {
    ($name:ident, $getter:expr, $values:ty $(, $extra:ident : $et:ty)*) => {
        #[doc = concat!("`", stringify!($name), "`: the FMU has no variable of this type.")]
        ///
        /// # Safety
        ///
        /// The importer keeps the safety contract of the `exports` module.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(
            instance: fmi3Instance,
            valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            $($extra: $et,)*
            _values: $values,
            _nValues: usize,
        ) -> fmi3Status {
            // SAFETY: `instance` is live, `valueReferences` holds
            // `nValueReferences` elements (contract).
            let (comp, refs) = unsafe {
                (component(instance), slice_from(valueReferences, nValueReferences))
            };
            no_such_type(comp, refs, stringify!($name), $getter)
        }
    };
}

other_type!(fmi3GetFloat32, true, *mut fmi3Float32);
other_type!(fmi3GetInt8, true, *mut fmi3Int8);
other_type!(fmi3GetUInt8, true, *mut fmi3UInt8);
other_type!(fmi3GetInt16, true, *mut fmi3Int16);
other_type!(fmi3GetUInt16, true, *mut fmi3UInt16);
other_type!(fmi3GetUInt32, true, *mut fmi3UInt32);
other_type!(fmi3GetInt64, true, *mut fmi3Int64);
other_type!(fmi3GetUInt64, true, *mut fmi3UInt64);
other_type!(fmi3GetString, true, *mut fmi3String);
other_type!(fmi3GetBinary, true, *mut fmi3Binary, _valueSizes: *mut usize);
other_type!(fmi3SetFloat32, false, *const fmi3Float32);
other_type!(fmi3SetInt8, false, *const fmi3Int8);
other_type!(fmi3SetUInt8, false, *const fmi3UInt8);
other_type!(fmi3SetInt16, false, *const fmi3Int16);
other_type!(fmi3SetUInt16, false, *const fmi3UInt16);
other_type!(fmi3SetUInt32, false, *const fmi3UInt32);
other_type!(fmi3SetInt64, false, *const fmi3Int64);
other_type!(fmi3SetUInt64, false, *const fmi3UInt64);
other_type!(fmi3SetString, false, *const fmi3String);
other_type!(fmi3SetBinary, false, *const fmi3Binary, _valueSizes: *const usize);

const NO_CLOCKS: &str = "this FMU has no clocks";
const NO_EVENT_MODE: &str = "this FMU has no event mode (hasEventMode = false)";
const CS_ONLY: &str = "this FMU supports Co-Simulation only";
const NO_STRUCTURAL: &str = "this FMU has no structural parameters (no configuration mode)";

unsupported!(fmi3GetClock(_r: *const fmi3ValueReference, _n: usize, _v: *mut fmi3Clock) => NO_CLOCKS);
unsupported!(fmi3SetClock(_r: *const fmi3ValueReference, _n: usize, _v: *const fmi3Clock) => NO_CLOCKS);
unsupported!(fmi3GetIntervalDecimal(_r: *const fmi3ValueReference, _n: usize, _i: *mut fmi3Float64, _q: *mut fmi3IntervalQualifier) => NO_CLOCKS);
unsupported!(fmi3GetIntervalFraction(_r: *const fmi3ValueReference, _n: usize, _c: *mut fmi3UInt64, _s: *mut fmi3UInt64, _q: *mut fmi3IntervalQualifier) => NO_CLOCKS);
unsupported!(fmi3GetShiftDecimal(_r: *const fmi3ValueReference, _n: usize, _s: *mut fmi3Float64) => NO_CLOCKS);
unsupported!(fmi3GetShiftFraction(_r: *const fmi3ValueReference, _n: usize, _c: *mut fmi3UInt64, _s: *mut fmi3UInt64) => NO_CLOCKS);
unsupported!(fmi3SetIntervalDecimal(_r: *const fmi3ValueReference, _n: usize, _i: *const fmi3Float64) => NO_CLOCKS);
unsupported!(fmi3SetIntervalFraction(_r: *const fmi3ValueReference, _n: usize, _c: *const fmi3UInt64, _s: *const fmi3UInt64) => NO_CLOCKS);
unsupported!(fmi3SetShiftDecimal(_r: *const fmi3ValueReference, _n: usize, _s: *const fmi3Float64) => NO_CLOCKS);
unsupported!(fmi3SetShiftFraction(_r: *const fmi3ValueReference, _n: usize, _c: *const fmi3UInt64, _s: *const fmi3UInt64) => NO_CLOCKS);
unsupported!(fmi3ActivateModelPartition(_clock: fmi3ValueReference, _t: fmi3Float64) => NO_CLOCKS);
unsupported!(fmi3EnterEventMode() => NO_EVENT_MODE);
unsupported!(fmi3EnterStepMode() => NO_EVENT_MODE);
unsupported!(fmi3EvaluateDiscreteStates() => NO_EVENT_MODE);
unsupported!(fmi3UpdateDiscreteStates(_a: *mut fmi3Boolean, _b: *mut fmi3Boolean, _c: *mut fmi3Boolean, _d: *mut fmi3Boolean, _e: *mut fmi3Boolean, _t: *mut fmi3Float64) => NO_EVENT_MODE);
unsupported!(fmi3EnterConfigurationMode() => NO_STRUCTURAL);
unsupported!(fmi3ExitConfigurationMode() => NO_STRUCTURAL);
unsupported!(fmi3GetNumberOfVariableDependencies(_vr: fmi3ValueReference, _n: *mut usize) => "no per-element dependencies are provided (providesPerElementDependencies = false; the model description lists them)");
unsupported!(fmi3GetVariableDependencies(_vr: fmi3ValueReference, _a: *mut usize, _b: *mut fmi3ValueReference, _c: *mut usize, _d: *mut fmi3DependencyKind, _n: usize) => "no per-element dependencies are provided (providesPerElementDependencies = false; the model description lists them)");
unsupported!(fmi3GetDirectionalDerivative(_u: *const fmi3ValueReference, _nu: usize, _k: *const fmi3ValueReference, _nk: usize, _s: *const fmi3Float64, _ns: usize, _o: *mut fmi3Float64, _no: usize) => "no directional derivatives (providesDirectionalDerivatives = false)");
unsupported!(fmi3GetAdjointDerivative(_u: *const fmi3ValueReference, _nu: usize, _k: *const fmi3ValueReference, _nk: usize, _s: *const fmi3Float64, _ns: usize, _o: *mut fmi3Float64, _no: usize) => "no adjoint derivatives (providesAdjointDerivatives = false)");
unsupported!(fmi3GetOutputDerivatives(_r: *const fmi3ValueReference, _n: usize, _o: *const fmi3Int32, _v: *mut fmi3Float64, _nv: usize) => "no output derivatives (maxOutputDerivativeOrder = 0)");
unsupported!(fmi3EnterContinuousTimeMode() => CS_ONLY);
unsupported!(fmi3CompletedIntegratorStep(_no_set: fmi3Boolean, _e: *mut fmi3Boolean, _t: *mut fmi3Boolean) => CS_ONLY);
unsupported!(fmi3SetTime(_t: fmi3Float64) => CS_ONLY);
unsupported!(fmi3SetContinuousStates(_x: *const fmi3Float64, _n: usize) => CS_ONLY);
unsupported!(fmi3GetContinuousStateDerivatives(_x: *mut fmi3Float64, _n: usize) => CS_ONLY);
unsupported!(fmi3GetEventIndicators(_x: *mut fmi3Float64, _n: usize) => CS_ONLY);
unsupported!(fmi3GetContinuousStates(_x: *mut fmi3Float64, _n: usize) => CS_ONLY);
unsupported!(fmi3GetNominalsOfContinuousStates(_x: *mut fmi3Float64, _n: usize) => CS_ONLY);
unsupported!(fmi3GetNumberOfEventIndicators(_n: *mut usize) => CS_ONLY);
unsupported!(fmi3GetNumberOfContinuousStates(_n: *mut usize) => CS_ONLY);
