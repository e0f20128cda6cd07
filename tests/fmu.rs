//! The FMU binary (`librotor_bearing.so`) loaded and driven through its C ABI by an
//! independent importer (`fmi-sys`' libloading bindings), as a master would.

#![allow(non_snake_case)]

use std::collections::{BTreeSet, HashSet};
use std::ffi::{CStr, CString, c_char, c_void};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use fmi_sys::fmi2::*;
use quick_xml::Reader;
use quick_xml::events::Event;

use rotor_bearing::fmi2::xml::model_description;
use rotor_bearing::model::RotorModel;
use rotor_bearing::solver::{Simulator, SolverOptions};

#[path = "common/fmi2_functions.rs"]
mod fmi2_functions;
use fmi2_functions::FMI2_CS_FUNCTIONS;

/// Every message logged, by every test's instances (never cleared: tests run
/// in parallel and read the part logged since they started).
static LOG: Mutex<Vec<(u32, String)>> = Mutex::new(Vec::new());

/// Logger with the fixed arguments of the variadic `fmi2CallbackLogger` (the
/// messages carry no format arguments; extra variadic slots are ignored by the C ABI).
extern "C" fn logger(
    _env: *mut c_void,
    _name: fmi2String,
    status: fmi2Status,
    _category: fmi2String,
    message: fmi2String,
) {
    let text = unsafe { CStr::from_ptr(message) }
        .to_string_lossy()
        .replace("%%", "%");
    LOG.lock().unwrap().push((status, text));
}

fn callbacks() -> fmi2CallbackFunctions {
    fmi2CallbackFunctions {
        // SAFETY: same fixed-argument prefix; see `logger`.
        logger: unsafe {
            std::mem::transmute::<
                extern "C" fn(*mut c_void, fmi2String, fmi2Status, fmi2String, fmi2String),
                fmi2CallbackLogger,
            >(logger)
        },
        allocateMemory: None,
        freeMemory: None,
        stepFinished: None,
        componentEnvironment: std::ptr::null_mut(),
    }
}

fn library_path() -> PathBuf {
    let exe = std::env::current_exe().unwrap();
    exe.parent()
        .unwrap()
        .parent()
        .unwrap()
        .join("librotor_bearing.so")
}

fn model_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/hydro_unit.toml")
}

/// A resources directory holding the model, as inside an unpacked FMU.
fn resources(tag: &str, model: &Path) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("fmu_resources_{tag}"));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::copy(model, dir.join("model.toml")).unwrap();
    // Its film tables (the compressor's), as `rotor fmu-stage` stages them:
    // the debug library would otherwise build them at every instantiation.
    let m = RotorModel::from_file(model).unwrap();
    rotor_bearing::fmu::resources::write_film_tables(&m, &dir).unwrap();
    dir
}

struct Fmu {
    lib: Fmi2Binding,
    c: fmi2Component,
    vars: Vec<rotor_bearing::fmi2::variables::Variable>,
    _callbacks: Box<fmi2CallbackFunctions>,
}

impl Fmu {
    fn new(name: &str) -> Self {
        Self::try_new(name, None).unwrap_or_else(|| panic!("instantiation failed: {}", last_log()))
    }

    fn try_new(name: &str, guid: Option<&str>) -> Option<Self> {
        Self::try_new_of(name, guid, &model_path())
    }

    /// An instance of the model file `path`.
    fn of_model(name: &str, path: &Path) -> Self {
        Self::try_new_of(name, None, path).expect("instantiation failed")
    }

    fn try_new_of(name: &str, guid: Option<&str>, path: &Path) -> Option<Self> {
        let lib = unsafe { Fmi2Binding::new(library_path()) }.expect("load librotor_bearing.so");
        let model = RotorModel::from_file(path).unwrap();
        let (_, real_guid) = model_description(&model);
        let guid = CString::new(guid.unwrap_or(&real_guid)).unwrap();
        let uri = CString::new(format!("file://{}", resources(name, path).display())).unwrap();
        let cname = CString::new(name).unwrap();
        let cb = Box::new(callbacks());
        let c = unsafe {
            lib.fmi2Instantiate(
                cname.as_ptr(),
                fmi2Type_fmi2CoSimulation,
                guid.as_ptr(),
                uri.as_ptr(),
                &*cb,
                0,
                1,
            )
        };
        if c.is_null() {
            return None;
        }
        Some(Self {
            lib,
            c,
            vars: rotor_bearing::fmi2::variables::variables(&model),
            _callbacks: cb,
        })
    }

    fn vr(&self, name: &str) -> u32 {
        self.vars
            .iter()
            .find(|v| v.name == name)
            .unwrap_or_else(|| panic!("no variable {name}"))
            .value_reference
    }

    fn init(&self) {
        unsafe {
            assert_eq!(
                self.lib.fmi2SetupExperiment(self.c, 0, 0.0, 0.0, 0, 0.0),
                fmi2Status_fmi2OK
            );
            assert_eq!(
                self.lib.fmi2EnterInitializationMode(self.c),
                fmi2Status_fmi2OK
            );
            assert_eq!(
                self.lib.fmi2ExitInitializationMode(self.c),
                fmi2Status_fmi2OK,
                "{}",
                last_log()
            );
        }
    }

    fn set(&self, name: &str, value: f64) -> fmi2Status {
        let vr = self.vr(name);
        unsafe { self.lib.fmi2SetReal(self.c, &vr, 1, &value) }
    }

    fn get(&self, names: &[&str]) -> Vec<f64> {
        let refs: Vec<u32> = names.iter().map(|n| self.vr(n)).collect();
        let mut out = vec![0.0; refs.len()];
        let s = unsafe {
            self.lib
                .fmi2GetReal(self.c, refs.as_ptr(), refs.len(), out.as_mut_ptr())
        };
        assert_eq!(s, fmi2Status_fmi2OK);
        out
    }

    fn step(&self, t: f64, h: f64) -> fmi2Status {
        unsafe { self.lib.fmi2DoStep(self.c, t, h, 1) }
    }
}

impl Drop for Fmu {
    fn drop(&mut self) {
        unsafe { self.lib.fmi2FreeInstance(self.c) };
    }
}

const OUTPUTS: [&str; 6] = [
    "bearings.generator_guide.x",
    "bearings.generator_guide.y",
    "bearings.generator_guide.fx",
    "bearings.turbine_guide.fy",
    "probes.pickup_2.x",
    "friction_torque",
];

#[test]
fn model_description_at_repo_root_is_the_generated_one() {
    let model = RotorModel::from_file(&model_path()).unwrap();
    let (xml, _) = model_description(&model);
    let file = std::fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("modelDescription.xml"),
    )
    .unwrap();
    assert!(
        xml == file,
        "modelDescription.xml is stale: regenerate it with `rotor fmu-stage models/hydro_unit.toml DIR`"
    );
}

#[test]
fn model_description_is_consistent() {
    let model = RotorModel::from_file(&model_path()).unwrap();
    let (xml, guid) = model_description(&model);
    let mut reader = Reader::from_str(&xml);
    let (mut vrs, mut names, mut units, mut used) =
        (Vec::new(), HashSet::new(), HashSet::new(), BTreeSet::new());
    let mut display = HashSet::new();
    loop {
        match reader.read_event().unwrap() {
            Event::Eof => break,
            Event::Start(e) | Event::Empty(e) => {
                let attr = |k: &str| {
                    e.try_get_attribute(k).unwrap().map(|a| {
                        a.normalized_value(quick_xml::XmlVersion::Explicit1_0)
                            .unwrap()
                            .into_owned()
                    })
                };
                match e.name().as_ref() {
                    b"ScalarVariable" => {
                        vrs.push(attr("valueReference").unwrap().parse::<u32>().unwrap());
                        assert!(names.insert(attr("name").unwrap()), "duplicate name");
                        assert!(!attr("description").unwrap().is_empty());
                    }
                    b"Unit" => {
                        units.insert(attr("name").unwrap());
                    }
                    b"DisplayUnit" => {
                        display.insert(attr("name").unwrap());
                    }
                    b"Real" => {
                        if let Some(u) = attr("unit") {
                            used.insert(u);
                        }
                        if let Some(d) = attr("displayUnit") {
                            assert!(display.contains(&d), "display unit {d} not declared");
                        }
                    }
                    b"fmiModelDescription" => assert_eq!(attr("guid").unwrap(), guid),
                    _ => {}
                }
            }
            _ => {}
        }
    }
    assert_eq!(
        vrs,
        (0..vrs.len() as u32).collect::<Vec<_>>(),
        "value references are 0..n in order"
    );
    for u in &used {
        assert!(units.contains(u), "unit {u} not declared");
    }
}

#[test]
fn exports_every_fmi2_function() {
    let lib = unsafe { libloading::Library::new(library_path()) }.unwrap();
    for name in FMI2_CS_FUNCTIONS {
        let sym: Result<libloading::Symbol<*const c_void>, _> = unsafe { lib.get(name.as_bytes()) };
        assert!(sym.is_ok(), "{name} is not exported");
    }
    let version: libloading::Symbol<unsafe extern "C" fn() -> *const c_char> =
        unsafe { lib.get(b"fmi2GetVersion") }.unwrap();
    assert_eq!(
        unsafe { CStr::from_ptr(version()) }.to_str().unwrap(),
        "2.0"
    );
}

/// The FMU and the Rust simulator driven directly with the same inputs (a speed
/// ramp through input derivatives) give the same numbers.
#[test]
fn fmu_equals_the_direct_simulator() {
    let fmu = Fmu::new("direct");
    fmu.init();
    let model = RotorModel::from_file(&model_path()).unwrap();
    // The FMU's defaults: accuracy-controlled steps up to solver.time_step.
    let mut sim = Simulator::new(
        rotor_bearing::rotor::Rotor::new(model.clone()).unwrap(),
        SolverOptions {
            time_step: rotor_bearing::fmi2::variables::default_fmu_time_step(&model),
            local_error_tolerance: rotor_bearing::fmi2::variables::DEFAULT_LOCAL_ERROR_TOLERANCE,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    // The FMU starts at standstill (shaft.speed start value 0).
    sim.set_speed(0.0, 0.0).unwrap();
    sim.settle_static().unwrap();
    let speed_vr = fmu.vr("shaft.speed");
    let h = 0.01;
    for _ in 0..50 {
        let t = sim.time();
        let rate = 2.0; // rad/s² ramp
        let order = 1;
        assert_eq!(
            unsafe {
                fmu.lib
                    .fmi2SetRealInputDerivatives(fmu.c, &speed_vr, 1, &order, &rate)
            },
            fmi2Status_fmi2OK
        );
        sim.set_speed(sim.speed_at(t), rate).unwrap();
        assert_eq!(fmu.step(t, h), fmi2Status_fmi2OK);
        sim.advance_to(t + h).unwrap();
        let got = fmu.get(&OUTPUTS);
        let o = sim.outputs().unwrap();
        let want = [
            o.bearings[0].x,
            o.bearings[0].y,
            o.bearings[0].fx,
            o.bearings[1].fy,
            o.probes[1].x,
            o.friction_torque,
        ];
        for (g, w) in got.iter().zip(want) {
            assert!(
                (g - w).abs() <= 1e-12 * w.abs().max(1e-30),
                "t = {}: {g} vs {w}",
                t + h
            );
        }
    }
    let speed = fmu.get(&["shaft.speed"])[0];
    assert!((speed - 2.0 * 0.5).abs() < 1e-12, "{speed}");
}

/// Outputs at common times do not depend on the communication step.
#[test]
fn results_do_not_depend_on_the_communication_step() {
    let run = |h: f64| {
        let fmu = Fmu::new(&format!("comm{h}"));
        fmu.init();
        let mut out = Vec::new();
        let n = (0.2 / h).round() as usize;
        for k in 0..n {
            assert_eq!(fmu.step(k as f64 * h, h), fmi2Status_fmi2OK);
            let t = (k + 1) as f64 * h;
            if ((t / 0.05).round() * 0.05 - t).abs() < 1e-9 {
                out.push(fmu.get(&OUTPUTS));
            }
        }
        out
    };
    let (a, b, c) = (run(0.001), run(0.01), run(0.05));
    assert_eq!(a.len(), 4);
    for ((x, y), z) in a.iter().zip(&b).zip(&c) {
        for i in 0..OUTPUTS.len() {
            let scale = x[i].abs().max(1e-12);
            assert!(
                (x[i] - y[i]).abs() <= 1e-8 * scale && (x[i] - z[i]).abs() <= 1e-8 * scale,
                "{}: {} {} {}",
                OUTPUTS[i],
                x[i],
                y[i],
                z[i]
            );
        }
    }
}

#[test]
fn rollback_and_serialized_state_continue_identically() {
    let fmu = Fmu::new("rollback");
    fmu.init();
    assert_eq!(fmu.step(0.0, 0.1), fmi2Status_fmi2OK);
    let mut state: fmi2FMUstate = std::ptr::null_mut();
    assert_eq!(
        unsafe { fmu.lib.fmi2GetFMUstate(fmu.c, &mut state) },
        fmi2Status_fmi2OK
    );
    assert_eq!(fmu.step(0.1, 0.1), fmi2Status_fmi2OK);
    let first = fmu.get(&OUTPUTS);
    let restored = unsafe { fmu.lib.fmi2SetFMUstate(fmu.c, state) };
    assert_eq!(restored, fmi2Status_fmi2OK, "{}", last_log());
    assert_eq!(fmu.step(0.1, 0.1), fmi2Status_fmi2OK);
    let second = fmu.get(&OUTPUTS);
    assert_eq!(
        first.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
        second.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
    );

    // Serialize, deserialize into a fresh instance, continue there.
    let mut size = 0usize;
    assert_eq!(
        unsafe { fmu.lib.fmi2SerializedFMUstateSize(fmu.c, state, &mut size) },
        fmi2Status_fmi2OK
    );
    let mut bytes = vec![0 as c_char; size];
    assert_eq!(
        unsafe {
            fmu.lib
                .fmi2SerializeFMUstate(fmu.c, state, bytes.as_mut_ptr(), size)
        },
        fmi2Status_fmi2OK
    );
    let fresh = Fmu::new("fresh");
    let mut restored: fmi2FMUstate = std::ptr::null_mut();
    assert_eq!(
        unsafe {
            fresh
                .lib
                .fmi2DeSerializeFMUstate(fresh.c, bytes.as_ptr(), size, &mut restored)
        },
        fmi2Status_fmi2OK
    );
    assert_eq!(
        unsafe { fresh.lib.fmi2SetFMUstate(fresh.c, restored) },
        fmi2Status_fmi2OK
    );
    assert_eq!(fresh.step(0.1, 0.1), fmi2Status_fmi2OK);
    assert_eq!(fresh.get(&OUTPUTS), first);
    // A corrupted image is refused with a message, not a crash.
    let mut junk: fmi2FMUstate = std::ptr::null_mut();
    let bad = [7 as c_char; 40];
    assert_eq!(
        unsafe {
            fresh
                .lib
                .fmi2DeSerializeFMUstate(fresh.c, bad.as_ptr(), bad.len(), &mut junk)
        },
        fmi2Status_fmi2Error
    );
    unsafe {
        fmu.lib.fmi2FreeFMUstate(fmu.c, &mut state);
        fresh.lib.fmi2FreeFMUstate(fresh.c, &mut restored);
    }
    assert!(state.is_null());
}

/// Bits of every real output of `fmu`.
fn real_output_bits(fmu: &Fmu) -> Vec<u64> {
    let names: Vec<&str> = fmu
        .vars
        .iter()
        .filter(|v| {
            v.causality == rotor_bearing::fmi2::variables::Causality::Output
                && v.kind == rotor_bearing::fmi2::variables::Kind::Real
        })
        .map(|v| v.name.as_str())
        .collect();
    fmu.get(&names).iter().map(|v| v.to_bits()).collect()
}

/// The ramped input of `run_steps`: the speed (rad/s per unit rate) or, on a
/// torque-driven shaft, its first torque input (1e5 N·m/s per unit rate).
fn ramped_input(fmu: &Fmu) -> (u32, f64) {
    match fmu.vars.iter().find(|v| {
        v.name.starts_with("torques.")
            && v.causality == rotor_bearing::fmi2::variables::Causality::Input
    }) {
        Some(v) => (fmu.vr(&v.name), 1e5),
        None => (fmu.vr("shaft.speed"), 1.0),
    }
}

/// Steps `k0..k1` of 0.01 s (at speed rate `rate`, rad/s², or torque rate
/// `1e5 rate` N·m/s on a torque-driven shaft), with the real outputs after each.
fn run_steps(fmu: &Fmu, k0: usize, k1: usize, rate: f64) -> Vec<Vec<u64>> {
    let (input_vr, scale) = ramped_input(fmu);
    let rate = rate * scale;
    (k0..k1)
        .map(|k| {
            let order = 1;
            let status = unsafe {
                fmu.lib
                    .fmi2SetRealInputDerivatives(fmu.c, &input_vr, 1, &order, &rate)
            };
            assert_eq!(status, fmi2Status_fmi2OK);
            assert_eq!(
                fmu.step(k as f64 * 0.01, 0.01),
                fmi2Status_fmi2OK,
                "{}",
                last_log()
            );
            real_output_bits(fmu)
        })
        .collect()
}

/// On every shipped model, with a communication step of 0.01 s and equal
/// internal steps that do not divide it in binary (1e-3 s), with the default
/// accuracy-controlled steps and with a tight tolerance (1e-4, steps of at
/// most 1e-3 s), with and without a speed ramp (a torque ramp on a
/// torque-driven shaft, spinning):
/// after fmi2SetFMUstate, in the same instance and in a fresh one from the
/// serialized image, every step repeats the uninterrupted run bit for bit.
#[test]
fn rollback_is_bit_identical_on_every_model_and_step() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models");
    let mut paths: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    paths.sort();
    assert!(paths.len() >= 6, "{paths:?}");
    let mut failures = Vec::new();
    for path in &paths {
        let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
        for (internal, tolerance, rate) in [
            (Some(1e-3), Some(0.0), 0.0),
            (Some(1e-3), Some(0.0), 5.0),
            (None, None, 0.0),
            (None, None, 5.0),
            (Some(1e-3), Some(1e-4), 5.0),
        ] {
            let tag = format!("bits_{stem}_{internal:?}_{tolerance:?}_{rate}");
            let make = |which: &str| {
                let fmu = Fmu::of_model(&format!("{tag}_{which}"), path);
                if let Some(h) = internal {
                    assert_eq!(fmu.set("solver.time_step", h), fmi2Status_fmi2OK);
                }
                if let Some(t) = tolerance {
                    assert_eq!(
                        fmu.set("solver.local_error_tolerance", t),
                        fmi2Status_fmi2OK
                    );
                }
                // A torque-driven shaft runs from 10 rad/s (at rest it would
                // only be held by its thrust bearing).
                if fmu.vars.iter().any(|v| v.name == "shaft.initial_speed") {
                    assert_eq!(fmu.set("shaft.initial_speed", 10.0), fmi2Status_fmi2OK);
                }
                fmu.init();
                fmu
            };
            let plain = make("plain");
            let want = run_steps(&plain, 0, 40, rate);

            let fmu = make("rollback");
            run_steps(&fmu, 0, 20, rate);
            let mut state: fmi2FMUstate = std::ptr::null_mut();
            assert_eq!(
                unsafe { fmu.lib.fmi2GetFMUstate(fmu.c, &mut state) },
                fmi2Status_fmi2OK
            );
            let mut size = 0usize;
            assert_eq!(
                unsafe { fmu.lib.fmi2SerializedFMUstateSize(fmu.c, state, &mut size) },
                fmi2Status_fmi2OK
            );
            let mut bytes = vec![0 as c_char; size];
            assert_eq!(
                unsafe {
                    fmu.lib
                        .fmi2SerializeFMUstate(fmu.c, state, bytes.as_mut_ptr(), size)
                },
                fmi2Status_fmi2OK
            );
            run_steps(&fmu, 20, 40, rate);
            assert_eq!(
                unsafe { fmu.lib.fmi2SetFMUstate(fmu.c, state) },
                fmi2Status_fmi2OK,
                "{}",
                last_log()
            );
            let again = run_steps(&fmu, 20, 40, rate);
            unsafe { fmu.lib.fmi2FreeFMUstate(fmu.c, &mut state) };

            let fresh = make("fresh");
            let mut restored: fmi2FMUstate = std::ptr::null_mut();
            assert_eq!(
                unsafe {
                    fresh
                        .lib
                        .fmi2DeSerializeFMUstate(fresh.c, bytes.as_ptr(), size, &mut restored)
                },
                fmi2Status_fmi2OK
            );
            assert_eq!(
                unsafe { fresh.lib.fmi2SetFMUstate(fresh.c, restored) },
                fmi2Status_fmi2OK
            );
            let continued = run_steps(&fresh, 20, 40, rate);
            unsafe { fresh.lib.fmi2FreeFMUstate(fresh.c, &mut restored) };

            for (what, got) in [("rollback", &again), ("fresh instance", &continued)] {
                let worst = want[20..]
                    .iter()
                    .zip(got)
                    .flat_map(|(a, b)| a.iter().zip(b))
                    .map(|(&a, &b)| {
                        let (a, b) = (f64::from_bits(a), f64::from_bits(b));
                        if a == b {
                            0.0
                        } else {
                            (a - b).abs() / a.abs().max(b.abs())
                        }
                    })
                    .fold(0.0, f64::max);
                if want[20..] != got[..] {
                    failures.push(format!(
                        "{stem}, internal step {internal:?}, tolerance {tolerance:?}, ramp {rate} rad/s², {what}: max relative difference {worst:e}"
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn instances_are_independent_across_threads() {
    let run = |name: String, unbalance: f64| {
        let fmu = Fmu::new(&name);
        assert_eq!(fmu.set("unbalance.generator", unbalance), fmi2Status_fmi2OK);
        // At 150 rpm (the FMU starts at standstill, where unbalance has no effect).
        assert_eq!(
            fmu.set("shaft.speed", 5.0 * std::f64::consts::PI),
            fmi2Status_fmi2OK
        );
        fmu.init();
        for k in 0..20 {
            assert_eq!(fmu.step(k as f64 * 0.01, 0.01), fmi2Status_fmi2OK);
        }
        fmu.get(&OUTPUTS)
    };
    let alone_a = run("alone_a".into(), 15.0);
    let alone_b = run("alone_b".into(), 40.0);
    assert_ne!(alone_a, alone_b);
    let ta = std::thread::spawn(move || run("thread_a".into(), 15.0));
    let tb = std::thread::spawn(move || run("thread_b".into(), 40.0));
    assert_eq!(ta.join().unwrap(), alone_a);
    assert_eq!(tb.join().unwrap(), alone_b);
}

/// The last warning or error logged (informative `logAll` messages such as
/// step statistics of concurrently running tests are skipped).
fn last_log() -> String {
    LOG.lock()
        .unwrap()
        .iter()
        .rev()
        .find(|(status, _)| *status != fmi2Status_fmi2OK)
        .map(|(_, m)| m.clone())
        .unwrap_or_default()
}

/// Wrong call sequences and bad inputs: the prescribed status and a message.
#[test]
fn wrong_calls_and_bad_inputs_are_reported() {
    assert!(Fmu::try_new("wrong_guid", Some("{bad}")).is_none());
    assert!(last_log().contains("GUID"), "{}", last_log());

    let fmu = Fmu::new("checks");
    assert_eq!(
        fmu.step(0.0, 0.1),
        fmi2Status_fmi2Error,
        "DoStep before initialization"
    );
    assert!(
        last_log().contains("fmi2DoStep is not allowed"),
        "{}",
        last_log()
    );
    unsafe { fmu.lib.fmi2Reset(fmu.c) };
    let bad_vr = 9999u32;
    let mut v = 0.0;
    assert_eq!(
        unsafe { fmu.lib.fmi2SetReal(fmu.c, &bad_vr, 1, &v) },
        fmi2Status_fmi2Error
    );
    assert!(
        last_log().contains("unknown value reference 9999"),
        "{}",
        last_log()
    );
    unsafe { fmu.lib.fmi2Reset(fmu.c) };
    assert_eq!(fmu.set("shaft.speed", f64::NAN), fmi2Status_fmi2Error);
    assert!(last_log().contains("not finite"), "{}", last_log());
    unsafe { fmu.lib.fmi2Reset(fmu.c) };
    assert_eq!(
        fmu.set("bearings.generator_guide.x", 1.0),
        fmi2Status_fmi2Error
    );
    assert!(last_log().contains("is an output"), "{}", last_log());
    unsafe { fmu.lib.fmi2Reset(fmu.c) };
    fmu.init();
    assert_eq!(
        fmu.set("solver.time_step", 1e-4),
        fmi2Status_fmi2Error,
        "fixed parameter after initialization"
    );
    assert_eq!(unsafe { fmu.lib.fmi2Reset(fmu.c) }, fmi2Status_fmi2OK);
    fmu.init();
    assert_eq!(fmu.step(0.0, -0.1), fmi2Status_fmi2Error);
    assert!(last_log().contains("must be positive"), "{}", last_log());
    unsafe { fmu.lib.fmi2Reset(fmu.c) };
    fmu.init();
    assert_eq!(
        fmu.step(0.5, 0.1),
        fmi2Status_fmi2Error,
        "communication point mismatch"
    );
    unsafe { fmu.lib.fmi2Reset(fmu.c) };
    fmu.init();
    let mut t = -1.0;
    assert_eq!(
        unsafe {
            fmu.lib
                .fmi2GetRealStatus(fmu.c, fmi2StatusKind_fmi2LastSuccessfulTime, &mut t)
        },
        fmi2Status_fmi2OK
    );
    assert_eq!(t, 0.0);
    assert_eq!(
        unsafe { fmu.lib.fmi2CancelStep(fmu.c) },
        fmi2Status_fmi2Error
    );
    assert!(
        last_log().contains("no asynchronous step"),
        "{}",
        last_log()
    );

    // A genuine solver failure: an absurd unbalance (1e9 kg·m, 2.5e11 N at
    // 150 rpm) would press the journal metres deep into its pads, where Newton
    // no longer converges within the step cuts. (A rub within reason continues
    // in contact: tests/operating_envelope.rs.)
    unsafe { fmu.lib.fmi2Reset(fmu.c) };
    assert_eq!(
        fmu.set("shaft.speed", 5.0 * std::f64::consts::PI),
        fmi2Status_fmi2OK
    );
    fmu.init();
    assert_eq!(fmu.step(0.0, 0.1), fmi2Status_fmi2OK);
    let mut state: fmi2FMUstate = std::ptr::null_mut();
    assert_eq!(
        unsafe { fmu.lib.fmi2GetFMUstate(fmu.c, &mut state) },
        fmi2Status_fmi2OK
    );
    assert_eq!(fmu.set("unbalance.generator", 1e9), fmi2Status_fmi2OK);
    assert_eq!(fmu.step(0.1, 1.0), fmi2Status_fmi2Discard);
    assert!(last_log().contains("discarded"), "{}", last_log());
    assert_eq!(
        unsafe {
            fmu.lib
                .fmi2GetRealStatus(fmu.c, fmi2StatusKind_fmi2LastSuccessfulTime, &mut t)
        },
        fmi2Status_fmi2OK
    );
    assert!((0.1..1.1).contains(&t), "{t}");
    assert_eq!(
        fmu.step(t, 0.1),
        fmi2Status_fmi2Error,
        "no stepping after a discard without rollback"
    );
    // Rollback (allowed even after fmi2Error) makes the instance usable again.
    let restored = unsafe { fmu.lib.fmi2SetFMUstate(fmu.c, state) };
    assert_eq!(restored, fmi2Status_fmi2OK, "{}", last_log());
    assert_eq!(fmu.set("unbalance.generator", 15.0), fmi2Status_fmi2OK);
    assert_eq!(fmu.step(0.1, 0.1), fmi2Status_fmi2OK);
    assert_eq!(unsafe { fmu.lib.fmi2Terminate(fmu.c) }, fmi2Status_fmi2OK);
    unsafe { fmu.lib.fmi2FreeFMUstate(fmu.c, &mut state) };
    let _ = &mut v;
}

/// A rub and bearing contact at once (issue 22): the Jeffcott rotor with a rub
/// ring at the disk (gap 200 µm) and a 1e3 kg·m unbalance at 3000 rpm used to
/// return fmi2Discard at the first communication step, at the FMU's then
/// internal step (equal steps of 1/3000 s) and at 0.1 ms. Every 10 ms step
/// now completes: 1 s at 1/3000 s, 0.2 s at 0.1 ms, the disk on the ring and
/// the journals in contact with their bushings (tests/operating_envelope.rs
/// checks the orbit). That journal contact is the coarse step's: it shrinks
/// as the step is refined (1.1e6 N at 1/3000 s, 5.6e5 N at 0.1 ms, 1.1e5 N at
/// 25 µs over 1 s) and accuracy-controlled steps (local error tolerance
/// 3e-4, 0.2 s) keep the journals off their bushings, the disk on the ring. The disk
/// goes centimetres "into" the ring at forces far past yield: each contact
/// and limit is logged once per episode as fmi2Warning, with fmi2Warning
/// returned by the step that found it, and again after fmi2Reset; every
/// step that ends with the disk that far in returns fmi2Warning too.
#[test]
fn a_rub_with_the_journals_in_contact_is_not_discarded_and_its_contact_is_flagged() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fmu_rub_model");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("jeffcott_seal.toml");
    let text = std::fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/jeffcott.toml"),
    )
    .unwrap()
        + "\n[[rubs]]\nname = \"seal\"\nnode = 5\ngap = 200e-6\n";
    std::fs::write(&path, text).unwrap();
    let rub_warnings = |from: usize| -> Vec<(u32, String)> {
        LOG.lock().unwrap()[from..]
            .iter()
            .filter(|(_, m)| m.starts_with("rub seal: "))
            .cloned()
            .collect()
    };
    let fmu = Fmu::of_model("rub_contact", &path);
    for (k, (time_step, tolerance, duration)) in [
        (Some(1.0 / 3000.0), 0.0, 1.0),
        (Some(1e-4), 0.0, 0.2),
        (None, 3e-4, 0.2),
    ]
    .into_iter()
    .enumerate()
    {
        let logged = LOG.lock().unwrap().len();
        if k > 0 {
            unsafe { fmu.lib.fmi2Reset(fmu.c) };
        }
        if let Some(h) = time_step {
            assert_eq!(fmu.set("solver.time_step", h), fmi2Status_fmi2OK);
        }
        assert_eq!(
            fmu.set("solver.local_error_tolerance", tolerance),
            fmi2Status_fmi2OK
        );
        assert_eq!(
            fmu.set("shaft.speed", 100.0 * std::f64::consts::PI),
            fmi2Status_fmi2OK
        );
        fmu.init();
        assert_eq!(fmu.set("unbalance.disk", 1e3), fmi2Status_fmi2OK);
        let (mut rub, mut journal, mut warned) = (0.0f64, 0.0f64, 0);
        let steps = (duration / 0.01) as usize;
        for k in 0..steps {
            let t = k as f64 * 0.01;
            let before = LOG.lock().unwrap().len();
            let status = fmu.step(t, 0.01);
            assert!(
                status == fmi2Status_fmi2OK || status == fmi2Status_fmi2Warning,
                "time step {time_step:?}, t = {t} s: {status} {}",
                last_log()
            );
            // A step that found a contact beyond its law returns fmi2Warning;
            // so does one that ends with the disk far into the ring (a
            // displacement no machine has), and no other.
            let contact = !rub_warnings(before).is_empty();
            let implausible = LOG.lock().unwrap()[before..]
                .iter()
                .any(|(s, m)| *s == fmi2Status_fmi2Warning && m.contains("no machine moves so"));
            assert_eq!(
                status == fmi2Status_fmi2Warning,
                contact || implausible,
                "t = {t} s"
            );
            if contact {
                warned += 1;
            }
            let out = fmu.get(&["rubs.seal.contact_force", "bearings.left.contact_force"]);
            rub = rub.max(out[0]);
            journal = journal.max(out[1]);
        }
        let mut t = 0.0;
        assert_eq!(
            unsafe {
                fmu.lib
                    .fmi2GetRealStatus(fmu.c, fmi2StatusKind_fmi2LastSuccessfulTime, &mut t)
            },
            fmi2Status_fmi2OK
        );
        assert!((t - duration).abs() < 1e-9, "reached {t} s");
        assert!(
            rub > 1e7 && (journal > 0.0) == (tolerance == 0.0),
            "time step {time_step:?}, tolerance {tolerance}: rub {rub} N, journal {journal} N"
        );
        let warnings = rub_warnings(logged);
        assert_eq!(warnings.len(), 2, "time step {time_step:?}: {warnings:#?}");
        assert!(warnings.iter().all(|(s, _)| *s == fmi2Status_fmi2Warning));
        assert!(warnings.iter().any(|(_, m)| m.contains("into its stator")));
        assert!(
            warnings
                .iter()
                .any(|(_, m)| m.contains("yield onset of steel"))
        );
        assert!(
            (1..=2).contains(&warned),
            "{warned} steps found a contact beyond its law"
        );
    }
}

/// A missing or broken model in the resources gives a logged error and NULL.
#[test]
fn broken_resources_give_null_and_a_message() {
    let lib = unsafe { Fmi2Binding::new(library_path()) }.unwrap();
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fmu_broken");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(
        dir.join("model.toml"),
        "name = \"x\"\n[[shaft]]\nlength = -1\n",
    )
    .unwrap();
    let cb = callbacks();
    let name = CString::new("broken").unwrap();
    let guid = CString::new("{x}").unwrap();
    let uri = CString::new(format!("file://{}", dir.display())).unwrap();
    let c = unsafe {
        lib.fmi2Instantiate(
            name.as_ptr(),
            fmi2Type_fmi2CoSimulation,
            guid.as_ptr(),
            uri.as_ptr(),
            &cb,
            0,
            1,
        )
    };
    assert!(c.is_null());
    assert!(
        LOG.lock()
            .unwrap()
            .iter()
            .any(|(_, m)| m.contains("model.toml")),
        "{:?}",
        LOG.lock().unwrap()
    );
    let missing = CString::new("file:///no/such/dir").unwrap();
    let c = unsafe {
        lib.fmi2Instantiate(
            name.as_ptr(),
            fmi2Type_fmi2CoSimulation,
            guid.as_ptr(),
            missing.as_ptr(),
            &cb,
            0,
            1,
        )
    };
    assert!(c.is_null());
    let me = unsafe {
        lib.fmi2Instantiate(
            name.as_ptr(),
            fmi2Type_fmi2ModelExchange,
            guid.as_ptr(),
            uri.as_ptr(),
            &cb,
            0,
            1,
        )
    };
    assert!(me.is_null());
    let _ = Path::new("");
}

/// Calls outside the states the FMI 2.0 Co-Simulation state table allows them
/// in give fmi2Error and a message naming the call and the state; the calls the
/// standard allows after an error (state save, reset) still work.
#[test]
fn calls_in_forbidden_states_are_refused() {
    let logged = |text: &str| LOG.lock().unwrap().iter().any(|(_, m)| m.contains(text));
    let fmu = Fmu::new("forbidden");
    let speed = fmu.vr("shaft.speed");
    let mut v = 0.0;
    let mut t = 0.0;
    unsafe {
        assert_eq!(
            fmu.lib.fmi2GetReal(fmu.c, &speed, 1, &mut v),
            fmi2Status_fmi2Error
        );
        assert!(logged("fmi2GetReal is not allowed in state Instantiated"));
        assert_eq!(fmu.lib.fmi2Reset(fmu.c), fmi2Status_fmi2OK);
        assert_eq!(
            fmu.lib.fmi2ExitInitializationMode(fmu.c),
            fmi2Status_fmi2Error
        );
        assert!(logged(
            "fmi2ExitInitializationMode is not allowed in state Instantiated (allowed: InitializationMode)"
        ));
        assert_eq!(fmu.lib.fmi2Reset(fmu.c), fmi2Status_fmi2OK);
        assert_eq!(
            fmu.lib
                .fmi2GetRealStatus(fmu.c, fmi2StatusKind_fmi2LastSuccessfulTime, &mut t),
            fmi2Status_fmi2Error
        );
        assert!(logged(
            "fmi2GetRealStatus is not allowed in state Instantiated"
        ));
        assert_eq!(fmu.lib.fmi2Reset(fmu.c), fmi2Status_fmi2OK);
        fmu.init();
        assert_eq!(
            fmu.lib.fmi2SetupExperiment(fmu.c, 0, 0.0, 0.0, 0, 0.0),
            fmi2Status_fmi2Error
        );
        assert!(logged(
            "fmi2SetupExperiment is not allowed in state StepComplete"
        ));
        assert_eq!(fmu.lib.fmi2Reset(fmu.c), fmi2Status_fmi2OK);
        fmu.init();
        assert_eq!(fmu.lib.fmi2Terminate(fmu.c), fmi2Status_fmi2OK);
        assert_eq!(fmu.step(0.0, 0.1), fmi2Status_fmi2Error);
        assert!(logged("fmi2DoStep is not allowed in state Terminated"));
        // In the error state: saving the state and reset are allowed.
        let mut state: fmi2FMUstate = std::ptr::null_mut();
        assert_eq!(
            fmu.lib.fmi2GetFMUstate(fmu.c, &mut state),
            fmi2Status_fmi2OK
        );
        assert_eq!(fmu.set("shaft.speed", 50.0), fmi2Status_fmi2Error);
        assert!(logged("fmi2SetReal is not allowed in state Error"));
        assert_eq!(fmu.lib.fmi2Reset(fmu.c), fmi2Status_fmi2OK);
        assert_eq!(fmu.set("shaft.speed", 50.0), fmi2Status_fmi2OK);
        assert_eq!(
            fmu.lib.fmi2FreeFMUstate(fmu.c, &mut state),
            fmi2Status_fmi2OK
        );
    }
}

/// With a stop time set in fmi2SetupExperiment, a step ending past it is an
/// error (FMI 2.0 §4.2.4); a step ending at it is fine.
#[test]
fn steps_past_the_stop_time_are_errors() {
    let fmu = Fmu::new("stop_time");
    unsafe {
        assert_eq!(
            fmu.lib.fmi2SetupExperiment(fmu.c, 0, 0.0, 0.0, 1, 1.0),
            fmi2Status_fmi2OK
        );
        assert_eq!(
            fmu.lib.fmi2EnterInitializationMode(fmu.c),
            fmi2Status_fmi2OK
        );
        assert_eq!(fmu.lib.fmi2ExitInitializationMode(fmu.c), fmi2Status_fmi2OK);
    }
    assert_eq!(fmu.step(0.0, 0.5), fmi2Status_fmi2OK);
    assert_eq!(fmu.step(0.5, 1.5), fmi2Status_fmi2Error);
    assert!(
        LOG.lock()
            .unwrap()
            .iter()
            .any(|(_, m)| m.contains("past the stop time 1 s")),
        "{:?}",
        LOG.lock().unwrap()
    );
}

/// fmi2Reset restores the model's viscosity: a tuned value does not survive it.
#[test]
fn reset_restores_the_model_viscosity() {
    let fmu = Fmu::new("reset_viscosity");
    let name = "bearings.generator_guide.viscosity";
    let read = || unsafe {
        assert_eq!(
            fmu.lib.fmi2EnterInitializationMode(fmu.c),
            fmi2Status_fmi2OK
        );
        fmu.get(&[name])[0]
    };
    let model = read();
    assert_eq!(model, 0.03);
    unsafe { assert_eq!(fmu.lib.fmi2Reset(fmu.c), fmi2Status_fmi2OK) };
    assert_eq!(fmu.set(name, 0.05), fmi2Status_fmi2OK);
    assert_eq!(read(), 0.05);
    unsafe { assert_eq!(fmu.lib.fmi2Reset(fmu.c), fmi2Status_fmi2OK) };
    assert_eq!(read(), model);
}

/// With logging on and `logAll` enabled, every fmi2DoStep logs its step
/// statistics; with `logAll` disabled it does not.
#[test]
fn step_statistics_are_logged_under_log_all() {
    let logged = |text: &str| LOG.lock().unwrap().iter().any(|(_, m)| m.contains(text));
    let fmu = Fmu::new("statistics");
    fmu.init();
    assert_eq!(fmu.step(0.0, 0.0375), fmi2Status_fmi2OK);
    let message = LOG
        .lock()
        .unwrap()
        .iter()
        .find(|(_, m)| m.starts_with("fmi2DoStep from 0 s by 0.0375 s: "))
        .map(|(_, m)| m.clone())
        .expect("step statistics logged");
    let counts: Vec<usize> = message["fmi2DoStep from 0 s by 0.0375 s: ".len()..]
        .split(|c: char| !c.is_ascii_digit())
        .filter_map(|w| w.parse().ok())
        .collect();
    // Steps, rejections, iterations, cuts, damped retries, refreshes,
    // factorizations; steps of at most solver.time_step (20 ms).
    assert_eq!(counts.len(), 7, "{message}");
    let (steps, iterations) = (counts[0], counts[2]);
    assert!(steps >= 2, "{message}");
    assert!(iterations > 0, "{message}");
    assert!(message.contains("internal steps") && message.contains("step cuts"));
    assert!(
        message.contains("rejected by the error estimate"),
        "{message}"
    );
    let errors = CString::new("logStatusError").unwrap();
    let list = [errors.as_ptr()];
    unsafe {
        assert_eq!(
            fmu.lib.fmi2SetDebugLogging(fmu.c, 1, 1, list.as_ptr()),
            fmi2Status_fmi2OK
        );
    }
    assert_eq!(fmu.step(0.0375, 0.0375), fmi2Status_fmi2OK);
    assert!(!logged("fmi2DoStep from 0.0375 s by 0.0375 s"));
}
