//! The FMI 3.0 C ABI of the library through an independent importer (the
//! `fmi-sys` bindings of the official FMI 3.0 headers, loaded with
//! libloading): a Co-Simulation run equals the safe FMI 2.0 instance to the
//! bit, the `fmi3DoStep` out-parameters say no event, no early return and the
//! communication point; with `earlyReturnAllowed`, a step inside which a
//! journal touches its bearing returns early at that internal step, and the
//! run continued from there follows the run that never stopped; misuse (wrong state, NULL, wrong token, counts that do
//! not match, NaN, a negative step, functions the FMU does not provide) gives
//! fmi3Error with a message, never a crash. Needs the cdylib
//! (`cargo build --lib`, which scripts/test.sh runs).

#![allow(non_snake_case)]

use std::ffi::{CStr, CString, c_char, c_void};
use std::path::PathBuf;
use std::ptr::{null, null_mut};
use std::sync::Mutex;

use fmi_sys::fmi3::*;

use rotor_bearing::fmi2::instance::{Instance, Status};
use rotor_bearing::fmi2::variables::{Causality, Kind, variables};
use rotor_bearing::fmi3::xml::{TIME_VALUE_REFERENCE, model_description};
use rotor_bearing::model::RotorModel;

/// Every message logged, with the environment (test tag) it was logged for.
static LOG: Mutex<Vec<(usize, u32, String)>> = Mutex::new(Vec::new());

unsafe extern "C" fn logger(
    env: fmi3InstanceEnvironment,
    status: fmi3Status,
    _category: fmi3String,
    message: fmi3String,
) {
    // SAFETY: the FMU passes a NUL-terminated message valid during the call.
    let text = unsafe { CStr::from_ptr(message) }
        .to_string_lossy()
        .into_owned();
    LOG.lock().unwrap().push((env as usize, status, text));
}

fn logged(tag: usize) -> Vec<String> {
    let log = LOG.lock().unwrap();
    log.iter()
        .filter(|m| m.0 == tag)
        .map(|m| m.2.clone())
        .collect()
}

fn library() -> Fmi3Binding {
    let exe = std::env::current_exe().unwrap();
    let path = exe
        .parent()
        .unwrap()
        .parent()
        .unwrap()
        .join("librotor_bearing.so");
    // SAFETY: the library is this crate's cdylib; loading runs no initializer
    // beyond Rust's own.
    unsafe { Fmi3Binding::new(path) }.expect("librotor_bearing.so: run `cargo build --lib`")
}

fn model() -> (RotorModel, PathBuf) {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/jeffcott.toml");
    // Written once per run: a copy made while a parallel test's instance
    // reads `model.toml` would hand it a truncated file.
    static RESOURCES: std::sync::OnceLock<PathBuf> = std::sync::OnceLock::new();
    let dir = RESOURCES.get_or_init(|| {
        let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
            .join(format!("fmi3_abi_resources_{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::copy(&path, dir.join("model.toml")).unwrap();
        dir
    });
    (RotorModel::from_file(&path).unwrap(), dir.clone())
}

fn instantiate(lib: &Fmi3Binding, token: &str, dir: &std::path::Path, tag: usize) -> fmi3Instance {
    instantiate_with(lib, token, dir, tag, false)
}

fn instantiate_with(
    lib: &Fmi3Binding,
    token: &str,
    dir: &std::path::Path,
    tag: usize,
    early_return_allowed: bool,
) -> fmi3Instance {
    let name = CString::new("abi").unwrap();
    let token = CString::new(token).unwrap();
    let resources = CString::new(format!("{}/", dir.display())).unwrap();
    // SAFETY: NUL-terminated strings valid during the call, a logger that
    // stays callable, no intermediate variables.
    unsafe {
        lib.fmi3InstantiateCoSimulation(
            name.as_ptr(),
            token.as_ptr(),
            resources.as_ptr(),
            false,
            true,
            false,
            early_return_allowed,
            null(),
            0,
            tag as *mut c_void,
            Some(logger),
            None,
        )
    }
}

/// `fmi3DoStep` with its out-parameters.
fn do_step(
    lib: &Fmi3Binding,
    i: fmi3Instance,
    t: f64,
    h: f64,
) -> (fmi3Status, bool, bool, bool, f64) {
    let (mut event, mut terminate, mut early, mut last) = (true, true, true, f64::NAN);
    // SAFETY: a live instance and writable out-parameters.
    let s = unsafe {
        lib.fmi3DoStep(
            i,
            t,
            h,
            true,
            &mut event,
            &mut terminate,
            &mut early,
            &mut last,
        )
    };
    (s, event, terminate, early, last)
}

fn get(lib: &Fmi3Binding, i: fmi3Instance, refs: &[u32]) -> (fmi3Status, Vec<f64>) {
    let mut out = vec![f64::NAN; refs.len()];
    // SAFETY: arrays of the lengths passed.
    let s =
        unsafe { lib.fmi3GetFloat64(i, refs.as_ptr(), refs.len(), out.as_mut_ptr(), out.len()) };
    (s, out)
}

fn set(lib: &Fmi3Binding, i: fmi3Instance, refs: &[u32], values: &[f64]) -> fmi3Status {
    // SAFETY: arrays of the lengths passed.
    unsafe { lib.fmi3SetFloat64(i, refs.as_ptr(), refs.len(), values.as_ptr(), values.len()) }
}

#[test]
fn a_run_through_the_fmi3_abi_equals_the_fmi2_instance_to_the_bit() {
    let lib = library();
    let (model, dir) = model();
    let (_, token) = model_description(&model);
    let vars = variables(&model);
    let speed = vars
        .iter()
        .find(|v| v.name == "shaft.speed")
        .unwrap()
        .value_reference;
    let outputs: Vec<u32> = vars
        .iter()
        .filter(|v| v.causality == Causality::Output)
        .map(|v| v.value_reference)
        .collect();
    let i = instantiate(&lib, &token, &dir, 1);
    assert!(!i.is_null(), "{:?}", logged(1));
    let mut reference = Instance::new("fmi2", model.clone()).unwrap();
    assert_eq!(set(&lib, i, &[speed], &[300.0]), fmi3Status_fmi3OK);
    assert_eq!(reference.set(speed, Kind::Real, 300.0), Status::Ok);
    // SAFETY: a live instance.
    let s = unsafe { lib.fmi3EnterInitializationMode(i, false, 0.0, 0.0, true, 1.0) };
    assert_eq!(s, fmi3Status_fmi3OK);
    // SAFETY: a live instance.
    assert_eq!(
        unsafe { lib.fmi3ExitInitializationMode(i) },
        fmi3Status_fmi3OK
    );
    assert_eq!(reference.setup_experiment(0.0, Some(1.0)), Status::Ok);
    assert_eq!(reference.enter_initialization_mode(), Status::Ok);
    assert_eq!(reference.exit_initialization_mode(), Status::Ok);
    let h = 0.01;
    for k in 0..10 {
        let t = k as f64 * h;
        let w = 300.0 + 10.0 * t;
        assert_eq!(set(&lib, i, &[speed], &[w]), fmi3Status_fmi3OK);
        assert_eq!(reference.set(speed, Kind::Real, w), Status::Ok);
        let (s, event, terminate, early, last) = do_step(&lib, i, t, h);
        assert_eq!(s, fmi3Status_fmi3OK, "{:?}", logged(1));
        assert!(!event && !terminate && !early);
        assert_eq!(last, t + h);
        assert_eq!(reference.do_step(t, h), Status::Ok);
        let (s, values) = get(&lib, i, &outputs);
        assert_eq!(s, fmi3Status_fmi3OK);
        for (vr, value) in outputs.iter().zip(&values) {
            let expected = reference.get(*vr, Kind::Real).unwrap();
            assert_eq!(value.to_bits(), expected.to_bits(), "vr {vr} at step {k}");
        }
        assert_eq!(get(&lib, i, &[TIME_VALUE_REFERENCE]).1[0], t + h);
    }
    // SAFETY: a live instance, terminated and freed once.
    unsafe {
        assert_eq!(lib.fmi3Terminate(i), fmi3Status_fmi3OK);
        lib.fmi3FreeInstance(i);
    }
}

#[test]
fn misuse_gives_fmi3_error_with_a_message() {
    let lib = library();
    let (model, dir) = model();
    let (_, token) = model_description(&model);
    let speed = variables(&model)
        .iter()
        .find(|v| v.name == "shaft.speed")
        .unwrap()
        .value_reference;
    let last = |tag: usize| logged(tag).last().cloned().unwrap_or_default();

    // Another token, or the FMI 2.0 GUID: no instance, a message naming it.
    let (_, guid) = rotor_bearing::fmi2::xml::model_description(&model);
    assert!(instantiate(&lib, &guid, &dir, 10).is_null());
    assert!(
        last(10).contains(&format!("instantiationToken {guid} does not match")),
        "{}",
        last(10)
    );
    // SAFETY: NULL strings are allowed and answered with NULL.
    let me = unsafe {
        lib.fmi3InstantiateModelExchange(
            null(),
            null(),
            null(),
            false,
            false,
            11 as *mut c_void,
            Some(logger),
        )
    };
    assert!(me.is_null());
    assert!(last(11).contains("Co-Simulation only"), "{}", last(11));

    let i = instantiate(&lib, &token, &dir, 12);
    assert!(!i.is_null());
    let error = fmi3Status_fmi3Error;
    // A step before initialization.
    assert_eq!(do_step(&lib, i, 0.0, 0.01).0, error);
    assert!(
        last(12).contains("fmi3DoStep is not allowed in state Instantiated"),
        "{}",
        last(12)
    );
    let reset = || {
        // SAFETY: a live instance.
        assert_eq!(unsafe { lib.fmi3Reset(i) }, fmi3Status_fmi3OK);
    };
    reset();
    // NaN, an unknown reference, counts that do not match, NULL values.
    assert_eq!(set(&lib, i, &[speed], &[f64::NAN]), error);
    assert!(
        last(12).contains("fmi3SetFloat64: shaft.speed = NaN is not finite"),
        "{}",
        last(12)
    );
    reset();
    assert_eq!(set(&lib, i, &[123_456], &[1.0]), error);
    assert!(
        last(12).contains("unknown value reference 123456"),
        "{}",
        last(12)
    );
    reset();
    let mut two = [0.0; 2];
    // SAFETY: one reference, two writable values.
    let s = unsafe { lib.fmi3GetFloat64(i, [speed].as_ptr(), 1, two.as_mut_ptr(), 2) };
    assert_eq!(s, error);
    assert!(
        last(12).contains("2 values for 1 scalar values"),
        "{}",
        last(12)
    );
    reset();
    // SAFETY: NULL values with one reference: refused, not read.
    let s = unsafe { lib.fmi3SetFloat64(i, [speed].as_ptr(), 1, null(), 1) };
    assert_eq!(s, error);
    assert!(
        last(12).contains("fmi3SetFloat64: a required pointer argument is NULL"),
        "{}",
        last(12)
    );
    reset();
    // Types the FMU has no variable of: fine for none, fmi3Error for one.
    let mut f = [0f32; 1];
    // SAFETY: empty and one-element arrays.
    unsafe {
        assert_eq!(
            lib.fmi3GetFloat32(i, null(), 0, f.as_mut_ptr(), 0),
            error,
            "before initialization"
        );
    }
    reset();
    // SAFETY: a live instance.
    unsafe {
        assert_eq!(
            lib.fmi3EnterInitializationMode(i, false, 0.0, 0.0, false, 0.0),
            fmi3Status_fmi3OK
        );
        assert_eq!(
            lib.fmi3GetFloat32(i, null(), 0, f.as_mut_ptr(), 0),
            fmi3Status_fmi3OK
        );
        assert_eq!(
            lib.fmi3GetFloat32(i, [0].as_ptr(), 1, f.as_mut_ptr(), 1),
            error
        );
    }
    assert!(
        last(12).contains("fmi3GetFloat32: value reference 0: the FMU has no Float32 variables"),
        "{}",
        last(12)
    );
    reset();
    // SAFETY: a live instance.
    unsafe {
        assert_eq!(
            lib.fmi3EnterInitializationMode(i, false, 0.0, 0.0, false, 0.0),
            fmi3Status_fmi3OK
        );
        assert_eq!(lib.fmi3ExitInitializationMode(i), fmi3Status_fmi3OK);
    }
    // A negative step, NULL out-parameters, unsupported calls.
    assert_eq!(do_step(&lib, i, 0.0, -0.01).0, error);
    assert!(
        last(12).contains("fmi3DoStep: communication step -0.01 s must be positive"),
        "{}",
        last(12)
    );
    reset();
    // SAFETY: a live instance.
    unsafe {
        assert_eq!(
            lib.fmi3EnterInitializationMode(i, false, 0.0, 0.0, false, 0.0),
            fmi3Status_fmi3OK
        );
        assert_eq!(lib.fmi3ExitInitializationMode(i), fmi3Status_fmi3OK);
        let s = lib.fmi3DoStep(
            i,
            0.0,
            0.01,
            true,
            null_mut(),
            null_mut(),
            null_mut(),
            null_mut(),
        );
        assert_eq!(s, error);
    }
    assert!(
        last(12).contains("fmi3DoStep: a required pointer argument is NULL"),
        "{}",
        last(12)
    );
    // SAFETY: a live instance; then NULL instances, answered without a crash.
    unsafe {
        assert_eq!(lib.fmi3EnterEventMode(i), error);
        assert!(
            last(12).contains("fmi3EnterEventMode: this FMU has no event mode"),
            "{}",
            last(12)
        );
        assert_eq!(lib.fmi3GetClock(i, null(), 0, null_mut()), error);
        assert!(
            last(12).contains("fmi3GetClock: this FMU has no clocks"),
            "{}",
            last(12)
        );
        assert_eq!(lib.fmi3Terminate(null_mut()), error);
        lib.fmi3FreeInstance(i);
        lib.fmi3FreeInstance(null_mut());
        let version = CStr::from_ptr(lib.fmi3GetVersion() as *const c_char);
        assert_eq!(version.to_str().unwrap(), "3.0");
    }
}

/// The Jeffcott rotor at 3000 rpm with 0.5 kg·m of unbalance on equal 1 ms
/// internal steps: its orbit grows from the equilibrium until the journals
/// reach their bearings at 42 ms, inside a 10 ms communication step.
fn start_rub(lib: &Fmi3Binding, i: fmi3Instance, model: &RotorModel) {
    let vr = |name: &str| {
        variables(model)
            .iter()
            .find(|v| v.name == name)
            .unwrap()
            .value_reference
    };
    let names = [
        "shaft.speed",
        "unbalance.disk",
        "solver.local_error_tolerance",
        "solver.time_step",
    ];
    let refs: Vec<u32> = names.iter().map(|n| vr(n)).collect();
    let values = [3000.0 * std::f64::consts::PI / 30.0, 0.5, 0.0, 1e-3];
    assert_eq!(set(lib, i, &refs, &values), fmi3Status_fmi3OK);
    // SAFETY: a live instance.
    unsafe {
        assert_eq!(
            lib.fmi3EnterInitializationMode(i, false, 0.0, 0.0, false, 0.0),
            fmi3Status_fmi3OK
        );
        assert_eq!(lib.fmi3ExitInitializationMode(i), fmi3Status_fmi3OK);
    }
}

#[test]
fn a_step_returns_early_where_a_journal_touches_its_bearing() {
    let lib = library();
    let (model, dir) = model();
    let (_, token) = model_description(&model);
    let vars = variables(&model);
    let outputs: Vec<u32> = vars
        .iter()
        .filter(|v| v.causality == Causality::Output)
        .map(|v| v.value_reference)
        .collect();
    let contact: Vec<u32> = vars
        .iter()
        .filter(|v| v.name.ends_with(".contact_force"))
        .map(|v| v.value_reference)
        .collect();
    let stop = 0.1;

    // The run that never stops, one internal step a communication step: the
    // first step that ends in contact.
    let a = instantiate_with(&lib, &token, &dir, 20, false);
    start_rub(&lib, a, &model);
    let mut never = vec![get(&lib, a, &outputs).1];
    let mut touch = None;
    for k in 0..100 {
        let t = k as f64 * 1e-3;
        let (s, _, _, early, _) = do_step(&lib, a, t, 1e-3);
        assert_eq!(s, fmi3Status_fmi3OK, "{:?}", logged(20));
        assert!(!early, "no early return unless allowed");
        never.push(get(&lib, a, &outputs).1);
        if touch.is_none() && get(&lib, a, &contact).1.iter().any(|&f| f > 0.0) {
            touch = Some(t + 1e-3);
        }
    }
    let touch = touch.expect("the journals reach their bearings within 0.1 s");

    // Early return allowed, 10 ms communication steps.
    let b = instantiate_with(&lib, &token, &dir, 21, true);
    start_rub(&lib, b, &model);
    let (mut t, mut first, mut returns) = (0.0f64, None, 0);
    let mut worst = 0.0f64;
    while t < stop - 1e-12 {
        let next = ((t / 0.01 + 1e-9).floor() + 1.0) * 0.01;
        let (s, event, terminate, early, last) = do_step(&lib, b, t, next - t);
        assert_eq!(s, fmi3Status_fmi3OK, "{:?}", logged(21));
        assert!(!event && !terminate);
        let forces = get(&lib, b, &contact).1;
        if early {
            returns += 1;
            assert!(
                last < next && last > t,
                "early return at {last} in ({t}, {next})"
            );
            assert!(forces.iter().any(|&f| f > 0.0), "in contact at {last}");
            first.get_or_insert(last);
        } else {
            assert!((last - next).abs() < 1e-12, "{last} vs {next}");
        }
        // Where the run that never stopped has a point, the outputs agree.
        let k = (last / 1e-3).round() as usize;
        if (last - k as f64 * 1e-3).abs() < 1e-9 {
            for (j, (x, y)) in get(&lib, b, &outputs).1.iter().zip(&never[k]).enumerate() {
                let scale = never.iter().map(|row| row[j].abs()).fold(1e-12, f64::max);
                worst = worst.max((x - y).abs() / scale);
            }
        }
        t = last;
    }
    let first = first.expect("a step returned early");
    eprintln!(
        "journal touches at {touch} s (1 ms steps); first early return at {first} s; {returns} early returns in {stop} s; worst output difference {worst:.2e} of each output's largest value"
    );
    assert!(
        (first - touch).abs() <= 1e-3 * (1.0 + 1e-9),
        "{first} vs {touch}"
    );
    assert!(
        logged(21)
            .iter()
            .any(|m| m.contains("returns early at") && m.contains("contact begins at")),
        "{:?}",
        logged(21)
    );
    // The continued run takes the same internal steps up to round-off in
    // their times (measured 1.2e-11).
    assert!(worst < 1e-9, "{worst}");
    // SAFETY: live instances, freed once.
    unsafe {
        lib.fmi3FreeInstance(a);
        lib.fmi3FreeInstance(b);
    }
}

#[test]
fn an_input_array_writes_its_elements_and_an_output_array_reads_them() {
    let lib = library();
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/torque_ports.toml");
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fmi3_abi_ports");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::copy(&path, dir.join("model.toml")).unwrap();
    let model = RotorModel::from_file(&path).unwrap();
    let (_, token) = model_description(&model);
    let vars = variables(&model);
    let list = rotor_bearing::fmi3::arrays::arrays(&vars);
    let array = |name: &str| list.iter().find(|a| a.name == name).unwrap().clone();
    let i = instantiate(&lib, &token, &dir, 30);
    assert!(!i.is_null(), "{:?}", logged(30));
    // ports.fx = [ports.amb.fx]: a write through the array is the scalar's.
    let fx = array("ports.fx");
    assert_eq!(
        set(&lib, i, &[fx.value_reference], &[12.5]),
        fmi3Status_fmi3OK
    );
    // SAFETY: a live instance.
    unsafe {
        assert_eq!(
            lib.fmi3EnterInitializationMode(i, false, 0.0, 0.0, false, 0.0),
            fmi3Status_fmi3OK
        );
    }
    assert_eq!(get(&lib, i, &fx.elements).1, vec![12.5]);
    // SAFETY: a live instance.
    unsafe { assert_eq!(lib.fmi3ExitInitializationMode(i), fmi3Status_fmi3OK) };
    assert_eq!(
        do_step(&lib, i, 0.0, 0.01).0,
        fmi3Status_fmi3OK,
        "{:?}",
        logged(30)
    );
    // bearings.x and a scalar beside it in one call: the array's elements
    // in model order, then the scalar.
    let x = array("bearings.x");
    assert_eq!(x.elements.len(), 2);
    let mut out = [f64::NAN; 3];
    let refs = [x.value_reference, x.elements[0]];
    // SAFETY: two references, three writable values (the array has two).
    let s = unsafe { lib.fmi3GetFloat64(i, refs.as_ptr(), 2, out.as_mut_ptr(), 3) };
    assert_eq!(s, fmi3Status_fmi3OK);
    let scalars = get(&lib, i, &x.elements).1;
    assert_eq!(out[..2], scalars[..]);
    assert_eq!(out[2], scalars[0]);
    assert!(
        scalars.iter().all(|v| v.is_finite() && *v != 0.0),
        "{scalars:?}"
    );
    // SAFETY: a live instance, freed once.
    unsafe { lib.fmi3FreeInstance(i) };
}
