//! Drives the FMU binary through its C ABI for a memory checker:
//! `valgrind --error-exitcode=99 fmu_smoke LIB.so RESOURCES_DIR`.
//! Instantiates two instances, initializes, steps, gets and sets values, saves,
//! serializes, restores and frees everything, including error paths.

use std::ffi::CString;

use fmi_sys::fmi2::*;

fn main() -> Result<(), String> {
    let args: Vec<String> = std::env::args().collect();
    if args.len() != 3 {
        return Err("usage: fmu_smoke LIB.so RESOURCES_DIR".into());
    }
    let model = rotor_bearing::model::RotorModel::from_file(
        &std::path::Path::new(&args[2]).join("model.toml"),
    )
    .map_err(|e| e.to_string())?;
    let (_, guid) = rotor_bearing::fmi2::xml::model_description(&model);
    let vars = rotor_bearing::fmi2::variables::variables(&model);
    let lib = unsafe { Fmi2Binding::new(&args[1]) }.map_err(|e| e.to_string())?;
    let callbacks = fmi2CallbackFunctions {
        logger: None,
        allocateMemory: None,
        freeMemory: None,
        stepFinished: None,
        componentEnvironment: std::ptr::null_mut(),
    };
    let guid = CString::new(guid).map_err(|e| e.to_string())?;
    let uri = CString::new(format!("file://{}", args[2])).map_err(|e| e.to_string())?;
    let outputs: Vec<u32> = vars
        .iter()
        .filter(|v| v.name.starts_with("bearings."))
        .map(|v| v.value_reference)
        .collect();
    let mut values = vec![0.0; outputs.len()];
    for name in ["a", "b"] {
        let cname = CString::new(name).map_err(|e| e.to_string())?;
        unsafe {
            let c = lib.fmi2Instantiate(
                cname.as_ptr(),
                fmi2Type_fmi2CoSimulation,
                guid.as_ptr(),
                uri.as_ptr(),
                &callbacks,
                0,
                0,
            );
            if c.is_null() {
                return Err("instantiation failed".into());
            }
            lib.fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0);
            lib.fmi2EnterInitializationMode(c);
            lib.fmi2ExitInitializationMode(c);
            let mut state: fmi2FMUstate = std::ptr::null_mut();
            for k in 0..5 {
                if lib.fmi2DoStep(c, k as f64 * 0.02, 0.02, 1) != fmi2Status_fmi2OK {
                    return Err("step failed".into());
                }
                lib.fmi2GetReal(c, outputs.as_ptr(), outputs.len(), values.as_mut_ptr());
                if k == 2 {
                    lib.fmi2GetFMUstate(c, &mut state);
                }
            }
            let mut size = 0;
            lib.fmi2SerializedFMUstateSize(c, state, &mut size);
            let mut bytes = vec![0 as fmi2Byte; size];
            lib.fmi2SerializeFMUstate(c, state, bytes.as_mut_ptr(), size);
            let mut copy: fmi2FMUstate = std::ptr::null_mut();
            lib.fmi2DeSerializeFMUstate(c, bytes.as_ptr(), size, &mut copy);
            lib.fmi2SetFMUstate(c, copy);
            lib.fmi2DoStep(c, 0.06, 0.02, 1);
            // Error paths: bad value reference, NaN, wrong state.
            let bad = 99_999u32;
            let nan = f64::NAN;
            lib.fmi2SetReal(c, &bad, 1, &nan);
            lib.fmi2Reset(c);
            lib.fmi2DoStep(c, 0.0, 0.1, 1);
            lib.fmi2FreeFMUstate(c, &mut state);
            lib.fmi2FreeFMUstate(c, &mut copy);
            lib.fmi2FreeInstance(c);
        }
    }
    println!("fmu_smoke: ok ({} outputs read)", values.len());
    Ok(())
}
