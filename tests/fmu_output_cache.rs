//! The FMU evaluates its outputs once per change of the state and serves each
//! read from that evaluation (`src/fmu/instance/values.rs`). Reading the
//! outputs in any order, repeatedly, after a rollback with fmi2SetFMUstate
//! and after a set of a tunable parameter or an input gives, bit for bit, what
//! a fresh evaluation gives: each value read as the first read after a
//! rollback to the same state (so every value comes from its own
//! evaluation), and an instance that made the same change without reading
//! before it. On the shipped hydro units (tilting pads, pedestals, brackets,
//! a torque-driven shaft) and the three-guide-bearing unit.

use std::path::PathBuf;

use rotor_bearing::fmi2::instance::{Instance, Status};
use rotor_bearing::fmi2::variables::{Binding, Causality, Kind, Variable, variables};
use rotor_bearing::model::{Drive, RotorModel};

const COMM: f64 = 5e-3;

fn model(name: &str) -> RotorModel {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("models")
        .join(format!("{name}.toml"));
    RotorModel::from_file(&path).unwrap()
}

fn vr(vars: &[Variable], name: &str) -> u32 {
    vars.iter()
        .find(|v| v.name == name)
        .unwrap_or_else(|| panic!("no variable {name}"))
        .value_reference
}

/// An initialized instance of `m` at its rated speed (a torque-driven shaft
/// from its initial speed), 5 ms internal step, after `steps` steps.
fn running(m: &RotorModel, steps: usize) -> Instance {
    let vars = variables(m);
    let mut fmu = Instance::new("cache", m.clone()).unwrap();
    assert_eq!(
        fmu.set(vr(&vars, "solver.time_step"), Kind::Real, COMM),
        Status::Ok
    );
    let speed = if m.drive == Drive::Torque {
        "shaft.initial_speed"
    } else {
        "shaft.speed"
    };
    assert_eq!(
        fmu.set(vr(&vars, speed), Kind::Real, m.nominal_speed),
        Status::Ok
    );
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
    for k in 0..steps {
        assert_eq!(fmu.do_step(k as f64 * COMM, COMM), Status::Ok);
    }
    fmu
}

fn outputs(vars: &[Variable]) -> Vec<u32> {
    vars.iter()
        .filter(|v| v.causality == Causality::Output)
        .map(|v| v.value_reference)
        .collect()
}

fn read(fmu: &mut Instance, refs: &[u32]) -> Vec<u64> {
    refs.iter()
        .map(|&r| fmu.get(r, Kind::Real).unwrap().to_bits())
        .collect()
}

/// Each output read as the only read after a rollback to `snap`: one fresh
/// evaluation per value.
fn fresh_each(fmu: &mut Instance, refs: &[u32]) -> Vec<u64> {
    let snap = fmu.snapshot().unwrap();
    refs.iter()
        .map(|&r| {
            assert_eq!(fmu.restore(&snap), Status::Ok);
            fmu.get(r, Kind::Real).unwrap().to_bits()
        })
        .collect()
}

/// A fixed shuffle of `refs` (a multiplicative permutation of the indices).
fn shuffled(refs: &[u32]) -> Vec<u32> {
    let n = refs.len();
    let step = (1..n)
        .rev()
        .find(|s| gcd(*s, n) == 1 && *s > n / 3)
        .unwrap_or(1);
    (0..n).map(|k| refs[(k * step + 3) % n]).collect()
}

fn gcd(a: usize, b: usize) -> usize {
    if b == 0 { a } else { gcd(b, a % b) }
}

const MODELS: [&str; 5] = [
    "hydro_unit",
    "hydro_unit_plain",
    "hydro_unit_brackets",
    "hydro_unit_torque",
    "hydro_unit_three_guide",
];

#[test]
fn outputs_read_in_any_order_and_repeatedly_equal_fresh_evaluations() {
    for name in MODELS {
        let m = model(name);
        let vars = variables(&m);
        let refs = outputs(&vars);
        let mut fmu = running(&m, 20);
        let fresh = fresh_each(&mut fmu, &refs);
        // In table order, twice, backwards and shuffled.
        assert_eq!(read(&mut fmu, &refs), fresh, "{name}: table order");
        assert_eq!(read(&mut fmu, &refs), fresh, "{name}: read again");
        let mut back = refs.clone();
        back.reverse();
        let mut expect: Vec<u64> = fresh.clone();
        expect.reverse();
        assert_eq!(read(&mut fmu, &back), expect, "{name}: backwards");
        let mixed = shuffled(&refs);
        let expect: Vec<u64> = mixed
            .iter()
            .map(|r| fresh[refs.iter().position(|q| q == r).unwrap()])
            .collect();
        assert_eq!(read(&mut fmu, &mixed), expect, "{name}: shuffled");
        // A second instance on the same path, reading only after its last
        // step, agrees: reads between steps change nothing.
        let mut quiet = running(&m, 20);
        assert_eq!(read(&mut quiet, &mixed), expect, "{name}: unread instance");
        // The motion outputs move from step to step: the cache follows them.
        assert_eq!(fmu.do_step(20.0 * COMM, COMM), Status::Ok);
        let x = vars
            .iter()
            .position(|v| matches!(v.binding, Binding::BearingX(0)))
            .unwrap();
        let after = read(&mut fmu, &refs);
        let k = refs.iter().position(|&r| r as usize == x).unwrap();
        assert_ne!(after[k], fresh[k], "{name}: journal x after a step");
        assert_eq!(after, fresh_each(&mut fmu, &refs), "{name}: after a step");
    }
}

#[test]
fn outputs_after_a_rollback_are_those_of_the_restored_state() {
    for name in MODELS {
        let m = model(name);
        let refs = outputs(&variables(&m));
        let mut fmu = running(&m, 10);
        let snap = fmu.snapshot().unwrap();
        let at_snap = read(&mut fmu, &refs);
        for k in 10..15 {
            assert_eq!(fmu.do_step(k as f64 * COMM, COMM), Status::Ok);
        }
        let later = read(&mut fmu, &refs);
        assert_ne!(later, at_snap, "{name}");
        assert_eq!(fmu.restore(&snap), Status::Ok);
        assert_eq!(read(&mut fmu, &refs), at_snap, "{name}: after rollback");
        // And the path from there is the one taken before.
        for k in 10..15 {
            assert_eq!(fmu.do_step(k as f64 * COMM, COMM), Status::Ok);
        }
        assert_eq!(read(&mut fmu, &refs), later, "{name}: replayed");
    }
}

#[test]
fn outputs_after_a_set_follow_the_new_value() {
    for name in MODELS {
        let m = model(name);
        let vars = variables(&m);
        let refs = outputs(&vars);
        let fx = vars
            .iter()
            .position(|v| matches!(v.binding, Binding::BearingFx(0)))
            .unwrap();
        let fx = refs.iter().position(|&r| r as usize == fx).unwrap();
        // A tunable parameter (the first bearing's viscosity or excitation)
        // and, on a speed-driven shaft, the speed input: both reach the
        // bearing forces at once.
        let mut changes: Vec<(u32, f64)> = Vec::new();
        if let Some(v) = vars.iter().find(|v| {
            matches!(v.binding, Binding::Viscosity(0) | Binding::Excitation(0))
                && v.causality == Causality::Parameter
        }) {
            let given = running(&m, 0).get(v.value_reference, Kind::Real).unwrap();
            changes.push((v.value_reference, 0.8 * given));
        }
        if m.drive == Drive::Speed {
            changes.push((vr(&vars, "shaft.speed"), 1.1 * m.nominal_speed));
        }
        assert!(!changes.is_empty(), "{name}");
        for (r, value) in changes {
            let mut read_first = running(&m, 10);
            let before = read(&mut read_first, &refs);
            let given = read_first.get(r, Kind::Real).unwrap();
            assert_eq!(read_first.set(r, Kind::Real, value), Status::Ok);
            let changed = read(&mut read_first, &refs);
            assert_ne!(changed[fx], before[fx], "{name}: vr {r} = {value}");
            // An instance that made the same change without reading before it.
            let mut unread = running(&m, 10);
            assert_eq!(unread.set(r, Kind::Real, value), Status::Ok);
            assert_eq!(read(&mut unread, &refs), changed, "{name}: vr {r}");
            assert_eq!(changed, fresh_each(&mut unread, &refs), "{name}: vr {r}");
            // Set back: the outputs are those before, bit for bit.
            assert_eq!(read_first.set(r, Kind::Real, given), Status::Ok);
            assert_eq!(read(&mut read_first, &refs), before, "{name}: vr {r} back");
        }
    }
}
