//! Each journal bearing's static and dynamic load as FMU outputs (issue 49):
//! `bearings.NAME.static_fx`, `static_fy` (its force on the journal at the
//! static equilibrium of initialization), `dynamic_fx`, `dynamic_fy` (the
//! force minus the static load) and `dynamic_load` (its magnitude),
//! appended after every other variable. Checked on the shipped
//! turbine–generator train against the library's line statics (the
//! reactions `rotor alignment` reports), against the force balance with the
//! train's weight, against the alignment influence matrix for an offset
//! parameter changed before initialization, and along a run.

use rotor_bearing::analysis::alignment::alignment;
use rotor_bearing::fmi2::instance::{Instance, Status};
use rotor_bearing::fmi2::variables::{Binding, Causality, Kind, variables};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::SolverOptions;

#[path = "common/fmu.rs"]
mod fmu;
use fmu::{model, vr};

const RPM: f64 = std::f64::consts::PI / 30.0;
const SUFFIXES: [&str; 5] = [
    "static_fx",
    "static_fy",
    "dynamic_fx",
    "dynamic_fy",
    "dynamic_load",
];

fn get(fmu: &mut Instance, m: &RotorModel, name: &str) -> f64 {
    fmu.get(vr(m, name), Kind::Real)
        .unwrap_or_else(|s| panic!("{name}: {s:?} {:?}", fmu.drain_messages()))
}

fn set(fmu: &mut Instance, m: &RotorModel, name: &str, value: f64) {
    let kind = variables(m)[vr(m, name) as usize].kind;
    assert_eq!(
        fmu.set(vr(m, name), kind, value),
        Status::Ok,
        "{name}: {:?}",
        fmu.drain_messages()
    );
}

/// The train's FMU on the full rotor (no modal reduction, so its statics
/// are the line's own), initialized at 3000 rpm after `before` sets its
/// parameters.
fn train_at_speed(before: impl FnOnce(&mut Instance, &RotorModel)) -> (Instance, RotorModel) {
    let m = model("turbine_generator_train");
    let mut fmu = Instance::new("train", m.clone()).unwrap();
    assert_eq!(fmu.setup_experiment(0.0, None), Status::Ok);
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    set(&mut fmu, &m, "solver.reduced_modes", 0.0);
    set(&mut fmu, &m, "shaft.speed", 3000.0 * RPM);
    before(&mut fmu, &m);
    assert_eq!(
        fmu.exit_initialization_mode(),
        Status::Ok,
        "{:?}",
        fmu.drain_messages()
    );
    (fmu, m)
}

/// The static loads `[fx, fy]` the FMU reports, bearing by bearing.
fn static_loads(fmu: &mut Instance, m: &RotorModel) -> Vec<[f64; 2]> {
    m.bearings
        .iter()
        .filter(|b| b.kind.is_bearing())
        .map(|b| {
            let n = &b.name;
            [
                get(fmu, m, &format!("bearings.{n}.static_fx")),
                get(fmu, m, &format!("bearings.{n}.static_fy")),
            ]
        })
        .collect()
}

/// Five outputs a journal bearing, in N, after every earlier variable
/// (the offsets and the pulls' dynamic eccentricity before them, the harmonic
/// forces' frequencies of issue 48 after them); the
/// dynamic ones depend directly on the speed input like the force itself.
#[test]
fn load_outputs_are_appended_after_every_other_variable() {
    for name in [
        "turbine_generator_train",
        "hydro_unit_brackets",
        "classic_disk_rotor",
    ] {
        let m = model(name);
        let mut vars = variables(&m);
        // The harmonic forces' frequencies (issue 48) come after them.
        while vars
            .last()
            .is_some_and(|v| matches!(v.binding, Binding::ForceFrequency(_)))
        {
            vars.pop();
        }
        let journal: Vec<&str> = m
            .bearings
            .iter()
            .filter(|b| b.kind.is_bearing())
            .map(|b| b.name.as_str())
            .collect();
        let n = 5 * journal.len();
        let (before, tail) = vars.split_at(vars.len() - n);
        let want: Vec<String> = journal
            .iter()
            .flat_map(|b| SUFFIXES.iter().map(move |s| format!("bearings.{b}.{s}")))
            .collect();
        let got: Vec<&str> = tail.iter().map(|v| v.name.as_str()).collect();
        assert_eq!(got, want, "{name}");
        assert!(
            before.iter().all(|v| !matches!(
                v.binding,
                Binding::StaticFx(_)
                    | Binding::StaticFy(_)
                    | Binding::DynamicFx(_)
                    | Binding::DynamicFy(_)
                    | Binding::DynamicLoad(_)
            )),
            "{name}"
        );
        let last = before.last().unwrap();
        assert!(
            matches!(last.binding, Binding::OffsetY(_))
                || last.name.ends_with(".dynamic_eccentricity"),
            "{name}: {}",
            last.name
        );
        for v in tail {
            assert_eq!((v.causality, v.unit), (Causality::Output, Some("N")));
            assert_eq!(
                v.feedthrough_speed,
                v.name.contains(".dynamic_"),
                "{}",
                v.name
            );
        }
    }
}

/// At 3000 rpm the static loads equal the reactions of the library's line
/// statics (`rotor alignment`'s) to 1e-6 of the train's weight (both
/// Newton solutions at relative tolerance 1e-8, from different starts),
/// and they balance the weight: `Σ F_y = M g`, `Σ F_x = 0` to 1e-6 of it.
/// At initialization the dynamic loads are zero (the same force).
#[test]
fn static_loads_are_the_line_statics_and_balance_the_weight() {
    let (mut fmu, m) = train_at_speed(|_, _| {});
    let got = static_loads(&mut fmu, &m);
    let rotor = Rotor::new(m.clone()).unwrap();
    let line = alignment(&rotor, 3000.0 * RPM, &SolverOptions::default()).unwrap();
    let weight = m.total_mass() * 9.81;
    assert_eq!(got.len(), line.bearings.len());
    for (g, b) in got.iter().zip(&line.bearings) {
        for (a, (f, r)) in g.iter().zip(&b.reaction).enumerate() {
            assert!(
                (f - r).abs() < 1e-6 * weight,
                "{} {a}: FMU {f} N, statics {r} N",
                b.name
            );
        }
        // Every bearing carries a real share of the train.
        assert!(g[1] > 0.01 * weight, "{}: {g:?}", b.name);
    }
    let sum = got
        .iter()
        .fold([0.0, 0.0], |s, g| [s[0] + g[0], s[1] + g[1]]);
    assert!(sum[0].abs() < 1e-6 * weight, "{sum:?} vs {weight}");
    assert!(
        (sum[1] - weight).abs() < 1e-6 * weight,
        "{sum:?} vs {weight}"
    );
    for b in m.bearings.iter().filter(|b| b.kind.is_bearing()) {
        let n = &b.name;
        for s in ["dynamic_fx", "dynamic_fy", "dynamic_load"] {
            assert_eq!(get(&mut fmu, &m, &format!("bearings.{n}.{s}")), 0.0);
        }
    }
}

/// Raising the exciter bearing by 10 µm through its offset parameter before
/// initialization moves the static loads to the line statics of the model
/// with that offset (1e-6 of the weight) and, to first order, as the
/// alignment influence matrix predicts: `ΔR ≈ (∂R/∂o) Δo` within 1 % of the
/// largest change (95 N at the generator's rear bearing; measured 0.12 %,
/// the films' second-order part).
#[test]
fn an_offset_parameter_moves_the_static_loads_as_the_alignment_predicts() {
    let raise = 10e-6;
    let exciter = "bearings.exciter.offset_y";
    let (mut fmu, m) = train_at_speed(|_, _| {});
    let before = static_loads(&mut fmu, &m);
    let given = get(&mut fmu, &m, exciter);
    let (mut moved, _) = train_at_speed(|fmu, m| set(fmu, m, exciter, given + raise));
    let after = static_loads(&mut moved, &m);
    let rotor = Rotor::new(m.clone()).unwrap();
    let options = SolverOptions::default();
    let line = alignment(&rotor, 3000.0 * RPM, &options).unwrap();
    let mut raised = m.clone();
    let k = raised
        .bearings
        .iter()
        .position(|b| b.name == "exciter")
        .unwrap();
    raised.bearings[k].offset[1] += raise;
    let nonlinear = alignment(&Rotor::new(raised).unwrap(), 3000.0 * RPM, &options).unwrap();
    let weight = m.total_mass() * 9.81;
    let j = line.bearings.iter().position(|b| b.bearing == k).unwrap();
    let change: Vec<[f64; 2]> = after
        .iter()
        .zip(&before)
        .map(|(a, b)| [a[0] - b[0], a[1] - b[1]])
        .collect();
    let largest = change
        .iter()
        .flat_map(|c| c.iter().map(|v| v.abs()))
        .fold(0.0, f64::max);
    let own = before[j][1];
    assert!(largest > 0.1 * own, "{largest} N, exciter {own} N");
    for (i, (c, b)) in change.iter().zip(&nonlinear.bearings).enumerate() {
        for a in 0..2 {
            assert!(
                (after[i][a] - b.reaction[a]).abs() < 1e-6 * weight,
                "{} {a}: FMU {} N, statics {} N",
                b.name,
                after[i][a],
                b.reaction[a]
            );
            let predicted = line.influence[(2 * i + a, 2 * j + 1)] * raise;
            assert!(
                (c[a] - predicted).abs() < 0.01 * largest,
                "{} {a}: change {} N, predicted {predicted} N",
                b.name,
                c[a]
            );
        }
    }
}

/// Along a run with the unbalance at speed, each dynamic load is the force
/// minus the static load exactly, its magnitude their hypotenuse, and the
/// static load stays the one of initialization (also after the speed input
/// changes); a reset and a new initialization take it again.
#[test]
fn dynamic_load_is_the_force_minus_the_static_load_along_a_run() {
    let (mut fmu, m) = train_at_speed(|_, _| {});
    let start = static_loads(&mut fmu, &m);
    let names: Vec<String> = m
        .bearings
        .iter()
        .filter(|b| b.kind.is_bearing())
        .map(|b| b.name.clone())
        .collect();
    let mut largest: f64 = 0.0;
    let h = 5e-4;
    for step in 0..40 {
        if step == 20 {
            set(&mut fmu, &m, "shaft.speed", 2900.0 * RPM);
        }
        let t = f64::from(step) * h;
        assert_eq!(fmu.do_step(t, h), Status::Ok, "{:?}", fmu.drain_messages());
        assert_eq!(static_loads(&mut fmu, &m), start);
        for n in &names {
            let b = |s: &str| format!("bearings.{n}.{s}");
            let (fx, fy) = (get(&mut fmu, &m, &b("fx")), get(&mut fmu, &m, &b("fy")));
            let (sx, sy) = (
                get(&mut fmu, &m, &b("static_fx")),
                get(&mut fmu, &m, &b("static_fy")),
            );
            let (dx, dy) = (
                get(&mut fmu, &m, &b("dynamic_fx")),
                get(&mut fmu, &m, &b("dynamic_fy")),
            );
            assert_eq!((dx, dy), (fx - sx, fy - sy), "{n} at step {step}");
            assert_eq!(get(&mut fmu, &m, &b("dynamic_load")), dx.hypot(dy));
            largest = largest.max(dx.hypot(dy));
        }
    }
    // The run moves the journals: the dynamic loads are not all zero.
    assert!(largest > 1.0, "{largest} N");
    assert_eq!(fmu.reset(), Status::Ok);
    assert_eq!(fmu.setup_experiment(0.0, None), Status::Ok);
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    set(&mut fmu, &m, "solver.reduced_modes", 0.0);
    set(&mut fmu, &m, "shaft.speed", 3000.0 * RPM);
    assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
    let again = static_loads(&mut fmu, &m);
    let weight = m.total_mass() * 9.81;
    for (a, b) in again.iter().zip(&start) {
        assert!((a[0] - b[0]).abs() < 1e-9 * weight && (a[1] - b[1]).abs() < 1e-9 * weight);
    }
}
