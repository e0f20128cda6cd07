//! FMI 3.0 intermediate updates through the C ABI (the `fmi-sys` bindings of
//! the official headers, loading the cdylib): with an `intermediateUpdate`
//! callback, `fmi3DoStep` calls it after every internal step, at the internal
//! step's time (monotone, inside the communication step, the last one at its
//! end), with the flags of docs/fmu.md; the outputs the callback reads there
//! equal, bit for bit, those of a second instance stepped by the master to
//! exactly those times (one simulator underneath); the callback changes
//! nothing at the communication points; an early return it asks for ends the
//! step there (or at a later time it names), and the master continuing from
//! there follows the run that never stopped; every other call made from
//! inside the callback, and every bad `requiredIntermediateVariables`, gives
//! fmi3Error with a message, never a crash. Needs the cdylib (`cargo build
//! --lib`, which scripts/test.sh runs).

#![allow(non_snake_case)]

use std::cell::{Cell, RefCell};
use std::ffi::{CStr, CString, c_void};
use std::path::PathBuf;
use std::ptr::null_mut;

use fmi_sys::fmi3::*;

use rotor_bearing::fmi2::variables::{Causality, variables};
use rotor_bearing::fmi3::arrays::arrays;
use rotor_bearing::fmi3::xml::model_description;
use rotor_bearing::model::RotorModel;

/// What the callback does at an internal step.
#[derive(Clone, Copy, PartialEq)]
enum Act {
    /// Read `reads` and record them.
    Read,
    /// Also call functions that are not allowed there.
    Misuse,
}

/// One callback: time, the four flags, the status and values of the read.
type Update = (f64, [bool; 4], fmi3Status, Vec<f64>);

/// A point the master reached: time, whether by an early return, outputs.
type Point = (f64, bool, Vec<f64>);

/// The importer's side of one instance: the environment pointer of its
/// logger and callback (shared: the FMU may log while the callback runs).
struct Importer {
    lib: &'static Fmi3Binding,
    instance: Cell<fmi3Instance>,
    /// The value references the callback reads, and the values they hold
    /// (an array counts its elements).
    reads: Vec<u32>,
    n_values: usize,
    /// An input the misuse reads.
    input: u32,
    act: Cell<Act>,
    /// `Some(at)` for an internal step's time: the early return to ask for
    /// there (`NaN`: at the internal step itself).
    early: Box<dyn Fn(f64) -> Option<f64>>,
    /// Each callback: time, the four flags, the status and values of the read.
    calls: RefCell<Vec<Update>>,
    /// The statuses of the misuse calls.
    misuse: RefCell<Vec<(&'static str, fmi3Status)>>,
    messages: RefCell<Vec<String>>,
}

unsafe extern "C" fn logger(
    env: fmi3InstanceEnvironment,
    _status: fmi3Status,
    _category: fmi3String,
    message: fmi3String,
) {
    // SAFETY: the environment is the test's `Importer`, alive while its
    // instance is; the message is NUL-terminated and valid during the call.
    let (importer, text) = unsafe { (&*env.cast::<Importer>(), CStr::from_ptr(message)) };
    importer
        .messages
        .borrow_mut()
        .push(text.to_string_lossy().into_owned());
}

#[allow(clippy::too_many_arguments)]
unsafe extern "C" fn intermediate_update(
    env: fmi3InstanceEnvironment,
    time: fmi3Float64,
    set_requested: fmi3Boolean,
    get_allowed: fmi3Boolean,
    step_finished: fmi3Boolean,
    can_return_early: fmi3Boolean,
    early_return_requested: *mut fmi3Boolean,
    early_return_time: *mut fmi3Float64,
) {
    // SAFETY: the environment is the test's `Importer`; the out-parameters
    // point to the FMU's writable locals during the call.
    let (me, requested, at) = unsafe {
        (
            &*env.cast::<Importer>(),
            &mut *early_return_requested,
            &mut *early_return_time,
        )
    };
    let (lib, i) = (me.lib, me.instance.get());
    let mut values = vec![f64::NAN; me.n_values];
    // SAFETY: arrays of the lengths passed.
    let status = unsafe {
        lib.fmi3GetFloat64(
            i,
            me.reads.as_ptr(),
            me.reads.len(),
            values.as_mut_ptr(),
            values.len(),
        )
    };
    me.calls.borrow_mut().push((
        time,
        [set_requested, get_allowed, step_finished, can_return_early],
        status,
        values,
    ));
    if me.act.get() == Act::Misuse {
        me.act.set(Act::Read);
        let (mut e, mut t, mut r, mut last) = (false, false, false, 0.0);
        let mut state: fmi3FMUState = null_mut();
        let (mut one, mut int) = ([0.0], [0i32]);
        let vr = me.reads[0];
        // SAFETY: a live instance, arrays and out-parameters of the sizes
        // passed; each call must be refused without touching the instance.
        let results = unsafe {
            [
                (
                    "fmi3DoStep",
                    lib.fmi3DoStep(i, time, 1e-3, true, &mut e, &mut t, &mut r, &mut last),
                ),
                ("fmi3SetFloat64", lib.fmi3SetFloat64(i, &vr, 1, &1.0, 1)),
                (
                    "fmi3GetInt32",
                    lib.fmi3GetInt32(i, &vr, 1, int.as_mut_ptr(), 1),
                ),
                ("fmi3GetFMUState", lib.fmi3GetFMUState(i, &mut state)),
                ("fmi3Terminate", lib.fmi3Terminate(i)),
                ("fmi3Reset", lib.fmi3Reset(i)),
                (
                    "fmi3GetFloat64 of two values for one",
                    lib.fmi3GetFloat64(i, &vr, 1, [0.0; 2].as_mut_ptr(), 2),
                ),
                (
                    "fmi3GetFloat64 of the independent time",
                    lib.fmi3GetFloat64(i, &999_999_999, 1, one.as_mut_ptr(), 1),
                ),
                (
                    "fmi3GetFloat64 of an input",
                    lib.fmi3GetFloat64(i, &me.input, 1, one.as_mut_ptr(), 1),
                ),
                (
                    "fmi3GetFloat64 with NULL values",
                    lib.fmi3GetFloat64(i, &vr, 1, null_mut(), 1),
                ),
            ]
        };
        // SAFETY: must be refused: the instance is inside fmi3DoStep.
        unsafe { lib.fmi3FreeInstance(i) };
        me.misuse.borrow_mut().extend(results);
    }
    if let Some(when) = (me.early)(time) {
        *requested = true;
        *at = if when.is_nan() { time } else { when };
    }
}

fn library() -> &'static Fmi3Binding {
    let exe = std::env::current_exe().unwrap();
    let path = exe
        .parent()
        .unwrap()
        .parent()
        .unwrap()
        .join("librotor_bearing.so");
    // SAFETY: the library is this crate's cdylib; loading runs no initializer
    // beyond Rust's own.
    let lib =
        unsafe { Fmi3Binding::new(path) }.expect("librotor_bearing.so: run `cargo build --lib`");
    Box::leak(Box::new(lib))
}

fn model() -> (RotorModel, PathBuf) {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/jeffcott.toml");
    // The resources are written once per run: the tests run in parallel, and
    // a copy made while another test's instance reads `model.toml` let that
    // one read a truncated file (its instantiation failed now and then).
    static RESOURCES: std::sync::OnceLock<PathBuf> = std::sync::OnceLock::new();
    let dir = RESOURCES.get_or_init(|| {
        let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!(
            "fmi3_intermediate_resources_{}",
            std::process::id()
        ));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::copy(&path, dir.join("model.toml")).unwrap();
        dir
    });
    (RotorModel::from_file(&path).unwrap(), dir.clone())
}

fn vr(model: &RotorModel, name: &str) -> u32 {
    variables(model)
        .iter()
        .find(|v| v.name == name)
        .unwrap_or_else(|| panic!("{name}"))
        .value_reference
}

/// Every scalar output of `model`.
fn outputs(model: &RotorModel) -> Vec<u32> {
    variables(model)
        .iter()
        .filter(|v| v.causality == Causality::Output)
        .map(|v| v.value_reference)
        .collect()
}

/// An importer (boxed: its address is the environment) reading `reads`.
fn importer(reads: Vec<u32>, early: Box<dyn Fn(f64) -> Option<f64>>) -> Box<Importer> {
    let (model, _) = model();
    Box::new(Importer {
        lib: library(),
        instance: Cell::new(null_mut()),
        n_values: reads.len(),
        input: vr(&model, "shaft.speed"),
        reads,
        act: Cell::new(Act::Read),
        early,
        calls: RefCell::new(Vec::new()),
        misuse: RefCell::new(Vec::new()),
        messages: RefCell::new(Vec::new()),
    })
}

/// Instantiate for `importer`, with the callback or without, naming
/// `required` (NULL with `n_required` when `None`).
fn instantiate(
    importer: &Importer,
    callback: bool,
    early_return_allowed: bool,
    required: Option<&[u32]>,
    n_required: usize,
) -> fmi3Instance {
    let (model, dir) = model();
    let (_, token) = model_description(&model);
    let name = CString::new("intermediate").unwrap();
    let token = CString::new(token).unwrap();
    let resources = CString::new(format!("{}/", dir.display())).unwrap();
    let (refs, n) = match required {
        Some(r) => (r.as_ptr(), r.len()),
        None => (std::ptr::null(), n_required),
    };
    // SAFETY: NUL-terminated strings valid during the call, the importer
    // outlives the instance, `refs` holds `n` references or is NULL.
    let i = unsafe {
        importer.lib.fmi3InstantiateCoSimulation(
            name.as_ptr(),
            token.as_ptr(),
            resources.as_ptr(),
            false,
            true,
            false,
            early_return_allowed,
            refs,
            n,
            (importer as *const Importer).cast_mut().cast::<c_void>(),
            Some(logger),
            if callback {
                Some(intermediate_update)
            } else {
                None
            },
        )
    };
    importer.instance.set(i);
    i
}

/// The Jeffcott rotor at 3000 rpm with 0.05 kg·m of unbalance (its journals
/// stay clear of their bearings: no early return at a contact), on
/// `time_step` internal steps or accuracy-controlled ones, initialized.
fn start(importer: &Importer, model: &RotorModel, time_step: f64, local_error_tolerance: f64) {
    let i = importer.instance.get();
    let names = [
        "shaft.speed",
        "unbalance.disk",
        "solver.local_error_tolerance",
        "solver.time_step",
    ];
    let refs: Vec<u32> = names.iter().map(|n| vr(model, n)).collect();
    let values = [
        3000.0 * std::f64::consts::PI / 30.0,
        0.05,
        local_error_tolerance,
        time_step,
    ];
    // SAFETY: a live instance, arrays of the lengths passed.
    unsafe {
        assert_eq!(
            importer
                .lib
                .fmi3SetFloat64(i, refs.as_ptr(), 4, values.as_ptr(), 4),
            fmi3Status_fmi3OK
        );
        assert_eq!(
            importer
                .lib
                .fmi3EnterInitializationMode(i, false, 0.0, 0.0, false, 0.0),
            fmi3Status_fmi3OK
        );
        assert_eq!(
            importer.lib.fmi3ExitInitializationMode(i),
            fmi3Status_fmi3OK
        );
    }
}

/// `fmi3DoStep`: status, early return, last successful time.
fn do_step(importer: &Importer, t: f64, h: f64) -> (fmi3Status, bool, f64) {
    let (mut event, mut terminate, mut early, mut last) = (true, true, true, f64::NAN);
    // SAFETY: a live instance and writable out-parameters.
    let s = unsafe {
        importer.lib.fmi3DoStep(
            importer.instance.get(),
            t,
            h,
            true,
            &mut event,
            &mut terminate,
            &mut early,
            &mut last,
        )
    };
    assert!(!event && !terminate);
    (s, early, last)
}

fn get(importer: &Importer, refs: &[u32]) -> Vec<f64> {
    let mut out = vec![f64::NAN; refs.len()];
    // SAFETY: arrays of the lengths passed.
    let s = unsafe {
        importer.lib.fmi3GetFloat64(
            importer.instance.get(),
            refs.as_ptr(),
            refs.len(),
            out.as_mut_ptr(),
            out.len(),
        )
    };
    assert_eq!(s, fmi3Status_fmi3OK, "{:?}", importer.messages.borrow());
    out
}

fn free(importer: &Importer) {
    // SAFETY: a live instance, freed once.
    unsafe { importer.lib.fmi3FreeInstance(importer.instance.get()) };
}

#[test]
fn intermediate_updates_come_at_each_internal_step_with_its_outputs() {
    let (model, _) = model();
    let outs = outputs(&model);
    // The outputs, and the array bearings.x read as its elements.
    let x = arrays(&variables(&model))
        .into_iter()
        .find(|a| a.name == "bearings.x")
        .unwrap();
    let mut reads = outs.clone();
    reads.push(x.value_reference);
    let n = outs.len();

    // A: 10 ms communication steps with the callback; B: no callback, the
    // master stepping to each time A's callback reported; C: no callback,
    // A's communication steps.
    let mut a = importer(reads.clone(), Box::new(|_| None));
    a.n_values = n + x.elements.len();
    assert!(!instantiate(&a, true, false, Some(&[]), 0).is_null());
    start(&a, &model, 1e-3, 0.0);
    let b = importer(vec![], Box::new(|_| None));
    assert!(!instantiate(&b, false, false, Some(&[]), 0).is_null());
    start(&b, &model, 1e-3, 0.0);
    let c = importer(vec![], Box::new(|_| None));
    assert!(!instantiate(&c, false, false, Some(&[]), 0).is_null());
    start(&c, &model, 1e-3, 0.0);

    let (h, steps) = (0.01, 10);
    let (mut tb, mut seen) = (0.0, 0);
    for k in 0..steps {
        let t = k as f64 * h;
        let (s, early, last) = do_step(&a, t, h);
        assert_eq!(s, fmi3Status_fmi3OK, "{:?}", a.messages.borrow());
        assert!(!early);
        assert_eq!(last, t + h);
        assert_eq!(do_step(&c, t, h).0, fmi3Status_fmi3OK);
        // The communication points: the callback changes nothing.
        let (ya, yc) = (get(&a, &outs), get(&c, &outs));
        for (p, q) in ya.iter().zip(&yc) {
            assert_eq!(p.to_bits(), q.to_bits(), "at {} s", t + h);
        }
        let calls = a.calls.borrow();
        let mine = &calls[seen..];
        // Ten internal steps of 1 ms, monotone, inside (t, t + h], the last at t + h.
        assert_eq!(
            mine.len(),
            10,
            "{:?}",
            mine.iter().map(|c| c.0).collect::<Vec<_>>()
        );
        assert_eq!(mine.last().unwrap().0, t + h);
        let mut before = t;
        for (time, flags, status, values) in mine {
            assert!(*time > before && *time <= t + h, "{time} after {before}");
            assert!(
                (time - before - 1e-3).abs() < 1e-12,
                "{time} after {before}"
            );
            before = *time;
            assert_eq!(*flags, [false, true, true, false]);
            assert_eq!(*status, fmi3Status_fmi3OK, "{:?}", a.messages.borrow());
            // B, stepped to exactly this time, reads the same bits.
            assert_eq!(do_step(&b, tb, time - tb).0, fmi3Status_fmi3OK);
            assert_eq!(tb + (time - tb), *time);
            tb = *time;
            let yb = get(&b, &outs);
            for (j, (p, q)) in values[..n].iter().zip(&yb).enumerate() {
                assert_eq!(p.to_bits(), q.to_bits(), "output {} at {time} s", outs[j]);
            }
            // The array's elements, after the scalars.
            assert_eq!(values[n..], get(&b, &x.elements)[..]);
        }
        seen = calls.len();
    }
    eprintln!(
        "{} intermediate updates in {steps} communication steps of {h} s (1 ms internal steps)",
        seen
    );
    assert_eq!(seen, 100);

    // Accuracy-controlled steps: the accepted steps only, monotone, the last
    // at the communication point, and again nothing changes there.
    let d = importer(outs.clone(), Box::new(|_| None));
    assert!(!instantiate(&d, true, true, Some(&outs[..3]), 3).is_null());
    start(&d, &model, 1e-3, 1e-4);
    let e = importer(vec![], Box::new(|_| None));
    assert!(!instantiate(&e, false, true, Some(&[]), 0).is_null());
    start(&e, &model, 1e-3, 1e-4);
    let mut seen = 0;
    for k in 0..steps {
        let t = k as f64 * h;
        assert_eq!(do_step(&d, t, h), (fmi3Status_fmi3OK, false, t + h));
        assert_eq!(do_step(&e, t, h), (fmi3Status_fmi3OK, false, t + h));
        assert_eq!(
            get(&d, &outs)
                .iter()
                .map(|v| v.to_bits())
                .collect::<Vec<_>>(),
            get(&e, &outs)
                .iter()
                .map(|v| v.to_bits())
                .collect::<Vec<_>>()
        );
        let calls = d.calls.borrow();
        let mine = &calls[seen..];
        assert!(!mine.is_empty());
        assert_eq!(mine.last().unwrap().0, t + h);
        assert!(mine.windows(2).all(|w| w[0].0 < w[1].0));
        assert!(mine[0].0 > t);
        // canReturnEarly = earlyReturnAllowed; only the three required
        // outputs may be read.
        assert!(mine.iter().all(|c| c.1 == [false, true, true, true]));
        assert!(mine.iter().all(|c| c.2 == fmi3Status_fmi3Error));
        seen = calls.len();
    }
    assert!(
        d.messages
            .borrow()
            .iter()
            .any(|m| m.contains("is not an intermediate variable of this instance")),
        "{:?}",
        d.messages.borrow()
    );
    eprintln!("{seen} intermediate updates with accuracy-controlled steps (local error 1e-4)");
    for i in [&a, &b, &c, &d, &e] {
        free(i);
    }
}

/// The run A of the Jeffcott rotor (1 ms steps, 10 ms communication
/// steps) with its callback asking, through `early`, for early returns; the
/// master continues from each early return to the next communication point.
/// Returns the importer and the outputs at each point it stopped at, with
/// the time.
fn run_with_returns(
    early: Box<dyn Fn(f64) -> Option<f64>>,
    stop: f64,
) -> (Box<Importer>, Vec<Point>) {
    let (model, _) = model();
    let outs = outputs(&model);
    let a = importer(outs.clone(), early);
    assert!(!instantiate(&a, true, true, Some(&[]), 0).is_null());
    start(&a, &model, 1e-3, 0.0);
    let mut t = 0.0f64;
    let mut points = Vec::new();
    while t < stop - 1e-12 {
        let next = ((t / 0.01 + 1e-9).floor() + 1.0) * 0.01;
        let (s, early, last) = do_step(&a, t, next - t);
        assert_eq!(s, fmi3Status_fmi3OK, "{:?}", a.messages.borrow());
        assert!(last > t && last <= next);
        assert_eq!(early, last < next, "{last} vs {next}");
        points.push((last, early, get(&a, &outs)));
        t = last;
    }
    (a, points)
}

#[test]
fn an_early_return_asked_for_in_an_intermediate_update_stops_the_step_there() {
    let stop = 0.1;
    let (never, straight) = run_with_returns(Box::new(|_| None), stop);
    // Every internal step of the uninterrupted run: the reference.
    let reference: Vec<(f64, Vec<f64>)> = never
        .calls
        .borrow()
        .iter()
        .map(|c| (c.0, c.3.clone()))
        .collect();
    assert_eq!(reference.len(), 100);
    assert!(straight.iter().all(|p| !p.1));
    // Ask at the internal steps at 23 ms, 57 ms and 58 ms (two in a row).
    let asked = [reference[22].0, reference[56].0, reference[57].0];
    let (a, points) = run_with_returns(
        Box::new(move |t| asked.contains(&t).then_some(f64::NAN)),
        stop,
    );
    let early: Vec<f64> = points.iter().filter(|p| p.1).map(|p| p.0).collect();
    assert_eq!(early, asked, "early returns at the asked internal steps");
    // Each point of the run with early returns, and each intermediate
    // update, against the uninterrupted run at the same time.
    let scale: Vec<f64> = (0..reference[0].1.len())
        .map(|j| reference.iter().map(|r| r.1[j].abs()).fold(1e-12, f64::max))
        .collect();
    let mut worst = 0.0f64;
    let mut compare = |time: f64, values: &[f64]| {
        let k = reference
            .iter()
            .position(|r| (r.0 - time).abs() < 1e-12)
            .unwrap_or_else(|| panic!("{time} is no internal step of the uninterrupted run"));
        for (j, (x, y)) in values.iter().zip(&reference[k].1).enumerate() {
            worst = worst.max((x - y).abs() / scale[j]);
        }
    };
    for (time, _, values) in &points {
        compare(*time, values);
    }
    let calls = a.calls.borrow();
    assert_eq!(calls.len(), 100, "each internal step told once");
    for c in calls.iter() {
        compare(c.0, &c.3);
    }
    eprintln!(
        "early returns at {early:?} s as asked; {} intermediate updates; largest output difference from the uninterrupted run {worst:.2e} of each output's largest value",
        calls.len()
    );
    // The continued steps are the same steps: the same factored step size
    // (sub-steps within 1e-9 of it take it), the times accumulated from the
    // same internal times; measured bit-identical.
    assert_eq!(worst, 0.0);
    assert!(
        a.messages
            .borrow()
            .iter()
            .any(|m| m.contains("returns early at") && m.contains("asked for it")),
        "{:?}",
        a.messages.borrow()
    );
    drop(calls);

    // A later time inside the step: the step ends exactly there (a shorter
    // last step); a time at or before the internal step: at that step.
    let (b, points) = run_with_returns(
        Box::new(|t| {
            if (t - 0.031).abs() < 1e-12 {
                Some(0.0335)
            } else if (t - 0.071).abs() < 1e-12 {
                Some(0.0705)
            } else {
                None
            }
        }),
        stop,
    );
    let early: Vec<f64> = points.iter().filter(|p| p.1).map(|p| p.0).collect();
    assert_eq!(early.len(), 2, "{early:?}");
    assert_eq!(early[0], 0.0335);
    assert!((early[1] - 0.071).abs() < 1e-12, "{early:?}");
    free(&b);
    free(&a);
    free(&never);

    // earlyReturnAllowed = false: canReturnEarly is false and a request is
    // ignored with a warning; the step completes.
    let (model, _) = model();
    let c = importer(outputs(&model), Box::new(|_| Some(f64::NAN)));
    assert!(!instantiate(&c, true, false, Some(&[]), 0).is_null());
    start(&c, &model, 1e-3, 0.0);
    assert_eq!(
        do_step(&c, 0.0, 0.01),
        (fmi3Status_fmi3Warning, false, 0.01)
    );
    assert!(c.calls.borrow().iter().all(|call| !call.1[3]));
    assert!(
        c.messages
            .borrow()
            .iter()
            .any(|m| m.contains("canReturnEarly was false") && m.contains("ignored")),
        "{:?}",
        c.messages.borrow()
    );
    free(&c);
}

#[test]
fn misuse_in_and_around_intermediate_updates_gives_fmi3_error() {
    let (model, _) = model();
    let outs = outputs(&model);
    let speed = vr(&model, "shaft.speed");

    // Calls from inside the callback: each refused with a message, the
    // instance untouched (the step completes and the run goes on).
    let a = importer(outs.clone(), Box::new(|_| None));
    assert!(!instantiate(&a, true, true, Some(&[]), 0).is_null());
    start(&a, &model, 1e-3, 0.0);
    a.act.set(Act::Misuse);
    assert_eq!(do_step(&a, 0.0, 0.01), (fmi3Status_fmi3OK, false, 0.01));
    let misuse = a.misuse.borrow();
    assert_eq!(misuse.len(), 10);
    for (call, status) in misuse.iter() {
        assert_eq!(*status, fmi3Status_fmi3Error, "{call}");
    }
    let messages = a.messages.borrow().join("\n");
    assert_eq!(
        messages
            .matches("not allowed in Intermediate Update Mode")
            .count(),
        7,
        "{messages}"
    );
    for text in [
        "fmi3FreeInstance: not allowed in Intermediate Update Mode",
        "2 values for 1 scalar values",
        "value reference 999999999 is not an intermediate variable",
        format!("value reference {speed} is not an intermediate variable").as_str(),
        "a required pointer argument is NULL",
    ] {
        assert!(messages.contains(text), "{text}: {messages}");
    }
    drop(misuse);
    assert_eq!(do_step(&a, 0.01, 0.01), (fmi3Status_fmi3OK, false, 0.02));
    assert!(get(&a, &outs).iter().all(|v| v.is_finite()));
    free(&a);

    // Bad requiredIntermediateVariables: no instance, a message naming why.
    let cases: [(bool, Option<&[u32]>, usize, &str); 4] = [
        (
            true,
            Some(&[speed]),
            1,
            "shaft.speed (value reference 8) is not an output",
        ),
        (
            true,
            Some(&[123_456]),
            1,
            "value reference 123456 is no output",
        ),
        (true, None, 2, "requiredIntermediateVariables is NULL"),
        (
            false,
            Some(&outs[..1]),
            1,
            "the intermediateUpdate callback is NULL",
        ),
    ];
    for (callback, required, n, text) in cases {
        let b = importer(vec![], Box::new(|_| None));
        assert!(instantiate(&b, callback, true, required, n).is_null());
        let messages = b.messages.borrow().join("\n");
        assert!(messages.contains(text), "{text}: {messages}");
    }
}
