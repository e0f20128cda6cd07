//! Every value that can enter the FMU is checked against its declared range and
//! every call's work is bounded (issue 13, defects 3 and 4), through the safe
//! instance behind the C exports; the fuzzers drive the C ABI itself.

use std::time::{Duration, Instant};

use rotor_bearing::fmi2::instance::{Instance, Status};
use rotor_bearing::fmi2::variables::{Kind, variables};
use rotor_bearing::model::RotorModel;
use rotor_bearing::solver::SolverOptions;

#[path = "common/fmu.rs"]
mod fmu;
use fmu::{model, vr};

fn started(model: &RotorModel) -> Instance {
    let mut fmu = Instance::new("limits", model.clone()).unwrap();
    assert_eq!(fmu.setup_experiment(0.0, None), Status::Ok);
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
    fmu
}

#[test]
fn declared_ranges_refuse_what_would_hang_or_mislead() {
    let m = model("jeffcott");
    // A refused set puts the instance in its error state (FMI 2.0): each value
    // gets a fresh instance.
    let refuses = |name: &str, kind: Kind, value: f64| -> bool {
        let mut fmu = Instance::new("ranges", m.clone()).unwrap();
        let status = fmu.set(vr(&m, name), kind, value);
        if status == Status::Error {
            let text = fmu.drain_messages().pop().unwrap().2;
            assert!(text.contains(name), "the refusal must name {name}: {text}");
        }
        status == Status::Error
    };
    // 1e-12 s and 1e-300 s made fmi2DoStep(0, 1e-4) run for longer than 20 s.
    for bad in [1e-12, 1e-300, 0.0, -1e-3, 10.0] {
        assert!(
            refuses("solver.time_step", Kind::Real, bad),
            "time step {bad}"
        );
    }
    assert!(!refuses("solver.time_step", Kind::Real, 1e-4));
    assert!(refuses("solver.tolerance", Kind::Real, 0.5));
    assert!(refuses("solver.tolerance", Kind::Real, 1e-20));
    assert!(refuses("solver.max_iterations", Kind::Integer, 1e6));
    assert!(refuses("bearings.left.viscosity", Kind::Real, -0.02));
    // 1e5 rad/s (955 000 rpm) was accepted and a 0.3 s step then took 41 s.
    assert!(refuses("shaft.speed", Kind::Real, 1e5));
    assert!(refuses("shaft.speed", Kind::Real, -1e5));
    assert!(
        !refuses("shaft.speed", Kind::Real, -500.0),
        "reverse rotation is physical"
    );
    assert!(refuses("unbalance.disk", Kind::Real, -1.0));
    // The declared ranges are the ones enforced.
    let vars = variables(&m);
    let ts = vars.iter().find(|v| v.name == "solver.time_step").unwrap();
    assert_eq!(
        (ts.min, ts.max),
        (
            Some(SolverOptions::TIME_STEP_RANGE.0),
            Some(SolverOptions::TIME_STEP_RANGE.1)
        )
    );
    let sp = vars.iter().find(|v| v.name == "shaft.speed").unwrap();
    assert_eq!((sp.min, sp.max), (Some(-m.max_speed), Some(m.max_speed)));
}

#[test]
fn every_do_step_is_bounded_in_work() {
    let m = model("jeffcott");
    let mut fmu = Instance::new("budget", m.clone()).unwrap();
    assert_eq!(
        fmu.set(vr(&m, "solver.time_step"), Kind::Real, 1e-6),
        Status::Ok
    );
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
    // 1 s at 1 µs would be 10⁶ internal steps: refused at once with a message.
    let start = Instant::now();
    assert_eq!(fmu.do_step(0.0, 1.0), Status::Discard);
    assert!(
        start.elapsed() < Duration::from_secs(5),
        "the refusal must not step first"
    );
    let text = fmu.drain_messages().pop().unwrap().2;
    assert!(text.contains("200000"), "{text}");
    assert_eq!(fmu.last_successful_time(), Ok(0.0));
    // A speed ramp that would end beyond the model's largest speed is refused too.
    let mut fmu = started(&m);
    let speed = vr(&m, "shaft.speed");
    assert_eq!(fmu.set_input_derivative(speed, 1, 1e6), Status::Ok);
    assert_eq!(fmu.do_step(0.0, 0.1), Status::Discard);
    assert!(
        fmu.drain_messages()
            .pop()
            .unwrap()
            .2
            .contains("max_speed_rpm")
    );
}

#[test]
fn restored_states_are_validated() {
    let m = model("jeffcott");
    let mut fmu = started(&m);
    assert_eq!(fmu.do_step(0.0, 0.01), Status::Ok);
    let good = fmu.snapshot().unwrap();
    let bytes = fmu.serialize(&good).unwrap();
    let read = |fmu: &mut Instance, b: &[u8]| fmu.deserialize(b);
    assert!(read(&mut fmu, &bytes).is_ok());
    // A state of another model of the same size is refused by its fingerprint.
    let other = model("classic_disk_rotor");
    let mut foreign = started(&other);
    assert!(read(&mut foreign, &bytes).is_err());
    // Field values a master could craft with a valid checksum are checked on
    // restore: time NaN, a time step of 1e-300 s, a negative viscosity. The
    // image: 8-byte magic, version, fingerprint, then the scalars (time first,
    // time_step sixth), the vectors (each a length, then its values: the
    // tuned viscosities, then the loads, their rates and the four twist
    // vectors, empty for this speed-driven unit without loads), FNV-1a of
    // all before it.
    let craft = |edit: &dyn Fn(&mut Vec<u8>)| -> Vec<u8> {
        let mut b = bytes.clone();
        b.truncate(b.len() - 8);
        edit(&mut b);
        let sum = b.iter().fold(0xcbf2_9ce4_8422_2325_u64, |h, &x| {
            (h ^ u64::from(x)).wrapping_mul(0x0000_0100_0000_01b3)
        });
        b.extend_from_slice(&sum.to_le_bytes());
        b
    };
    let put = |b: &mut Vec<u8>, at: usize, v: f64| b[at..at + 8].copy_from_slice(&v.to_le_bytes());
    let scalar = |k: usize| 24 + 8 * k;
    let untouched = craft(&|_| {});
    assert_eq!(untouched, bytes, "the test's reading of the image is wrong");
    for (what, image) in [
        ("time", craft(&|b| put(b, scalar(0), f64::NAN))),
        ("time_step", craft(&|b| put(b, scalar(5), 1e-300))),
        (
            "viscosity",
            craft(&|b| {
                // The last tuned value, before six empty vectors' lengths,
                // the previous accelerations of the accuracy-controlled
                // step taken (a length and one per rotor coordinate), the
                // contact flags (two per bearing), the table flags (one per
                // bearing), the full rotor's validity watch (four values)
                // and the static loads (two per bearing), then the harmonic
                // forces' phases and frequencies (two empty vectors' lengths).
                let n = rotor_bearing::rotor::Rotor::new(m.clone())
                    .unwrap()
                    .dof_count();
                let flags = 8 * (1 + 4) + 8 * (1 + 2) + 8 * (1 + 4) + 8 * (1 + 4);
                let at = b.len() - 16 - 6 * 8 - 8 * (1 + n) - flags - 2 * 8;
                put(b, at, -0.02)
            }),
        ),
    ] {
        let refused = match read(&mut fmu, &image) {
            Err(_) => true,
            Ok(snap) => fmu.restore(&snap) == Status::Error,
        };
        assert!(refused, "a state with a bad {what} was accepted");
        let text = fmu.drain_messages().pop().map(|m| m.2).unwrap_or_default();
        assert!(text.contains(what), "the refusal must name {what}: {text}");
        // Out of the error state by restoring a good state (FMI 2.0).
        assert_eq!(fmu.restore(&good), Status::Ok);
    }
    // After the refusals the instance holds the good state and steps on.
    assert_eq!(fmu.last_successful_time(), Ok(0.01));
    assert_eq!(fmu.do_step(0.01, 0.01), Status::Ok);
}

/// Issue 22: a communication step too short to advance the time by what the
/// integrator resolves is refused at once with fmi2Error (it was fmi2Discard
/// "non-finite value" below 1e-154 s, with h printed in hundreds of digits,
/// and steps of 1e-10 to 1e-13 s returned fmi2OK and silently corrupted the
/// orbit). A step of the shortest span left is harmless.
#[test]
fn steps_too_short_to_advance_time_are_refused_upfront() {
    let m = model("jeffcott");
    let start = |t0: f64| {
        let mut fmu = Instance::new("short", m.clone()).unwrap();
        assert_eq!(
            fmu.set(vr(&m, "shaft.speed"), Kind::Real, 314.0),
            Status::Ok
        );
        assert_eq!(fmu.setup_experiment(t0, None), Status::Ok);
        assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
        assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
        fmu
    };
    for t0 in [0.0, 0.01, 1e9] {
        for h in [
            1e-300, 1e-200, 1e-154, 1e-100, 1e-20, 1e-13, 1e-11, 1e-9, 9.9e-9,
        ] {
            let mut fmu = start(t0);
            let begun = Instant::now();
            assert_eq!(fmu.do_step(t0, h), Status::Error, "t = {t0} s, h = {h:e} s");
            assert!(
                begun.elapsed() < Duration::from_millis(200),
                "refused before stepping"
            );
            let text = fmu.drain_messages().pop().unwrap().2;
            assert!(
                text.contains(&format!("communication step {h:e} s from")),
                "{text}"
            );
            let why = if t0 + h == t0 {
                "does not advance the time"
            } else {
                "shorter than the 1e-8 s the integrator resolves"
            };
            assert!(text.contains(why) && text.len() < 240, "{text}");
            assert_eq!(fmu.phase(), rotor_bearing::fmi2::instance::Phase::Error);
        }
    }
    // At 1e9 s the time resolves 1.2e-7 s: a 1e-6 s step advances by eight of them.
    let mut fmu = start(1e9);
    assert_eq!(fmu.do_step(1e9, 1e-6), Status::Ok);
    // The shortest step allowed leaves the orbit where it would have been,
    // within what the accuracy-controlled steps (the FMU's default, local
    // error tolerance 3e-3) carry: a different step sequence after the
    // tiny step moves `x` at 30 ms by the integration error (measured
    // 2.0e-5 of it; the plain runs of the step control before and after
    // its growth window differ by 9.0e-6).
    let x = vr(&m, "bearings.left.x");
    let orbit = |tiny: f64| {
        let mut fmu = start(0.0);
        let mut t = 0.0;
        for k in 0..30 {
            if k == 10 && tiny > 0.0 {
                assert_eq!(fmu.do_step(t, tiny), Status::Ok);
                t += tiny;
            }
            assert_eq!(fmu.do_step(t, 1e-3), Status::Ok);
            t += 1e-3;
        }
        fmu.get(x, Kind::Real).unwrap()
    };
    let (plain, with_tiny) = (orbit(0.0), orbit(SolverOptions::MIN_SPAN));
    assert!(
        (plain - with_tiny).abs() < 1e-4 * plain.abs(),
        "{plain:e} against {with_tiny:e}"
    );
}

/// Messages print numbers in their short form: an absurd value is a few
/// characters, never hundreds of digits.
#[test]
fn messages_print_numbers_short() {
    let m = model("jeffcott");
    for (name, kind, value, shown) in [
        ("shaft.speed", Kind::Real, 1e300, "1e300"),
        ("solver.time_step", Kind::Real, 1e-300, "1e-300"),
        ("unbalance_ramp_time", Kind::Real, 1e200, "1e200"),
    ] {
        let mut fmu = Instance::new("short", m.clone()).unwrap();
        assert_eq!(fmu.set(vr(&m, name), kind, value), Status::Error);
        let text = fmu.drain_messages().pop().unwrap().2;
        assert!(
            text.contains(&format!("{name} = {shown}:")) && text.len() < 200,
            "{text}"
        );
    }
    let mut fmu = Instance::new("short", m.clone()).unwrap();
    assert_eq!(fmu.setup_experiment(0.0, Some(-1e250)), Status::Error);
    let text = fmu.drain_messages().pop().unwrap().2;
    assert!(
        text.contains("stop time -1e250") && text.len() < 200,
        "{text}"
    );
}
