//! Reduced-order (Craig–Bampton) rotor against the full model.

use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::{DEFAULT_REDUCED_MODES, Rotor, VALIDITY_FACTOR};
use rotor_bearing::solver::reduction_check::receptance_errors;
use rotor_bearing::solver::{Simulator, SolverOptions};

fn model(name: &str) -> RotorModel {
    let path = format!("{}/models/{name}.toml", env!("CARGO_MANIFEST_DIR"));
    RotorModel::from_file(std::path::Path::new(&path)).unwrap()
}

/// Probe and journal displacements over a transient: `[output][time] = (x, y)`.
fn run(rotor: Rotor, speed: f64, step: f64, duration: f64) -> Vec<Vec<(f64, f64)>> {
    let opts = SolverOptions {
        time_step: step,
        ..SolverOptions::default()
    };
    let mut sim = Simulator::new(rotor, opts).unwrap();
    sim.set_speed(speed, 0.0).unwrap();
    sim.settle_static().unwrap();
    let records = (duration / step).round() as usize;
    let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
    for k in 0..=records {
        if k > 0 {
            sim.advance_to(k as f64 * step).unwrap();
        }
        let o = sim.outputs().unwrap();
        let points: Vec<(f64, f64)> = o
            .bearings
            .iter()
            .map(|b| (b.x, b.y))
            .chain(o.probes.iter().map(|p| (p.x, p.y)))
            .collect();
        if out.is_empty() {
            out = vec![Vec::new(); points.len()];
        }
        for (series, p) in out.iter_mut().zip(points) {
            series.push(p);
        }
    }
    out
}

/// Largest distance between two runs at any output and time, over the largest
/// orbit radius about its mean.
fn orbit_error(full: &[Vec<(f64, f64)>], reduced: &[Vec<(f64, f64)>]) -> f64 {
    let mut diff: f64 = 0.0;
    let mut size: f64 = 0.0;
    for (a, b) in full.iter().zip(reduced) {
        let n = a.len() as f64;
        let (mx, my) = a
            .iter()
            .fold((0.0, 0.0), |s, p| (s.0 + p.0 / n, s.1 + p.1 / n));
        for (p, q) in a.iter().zip(b) {
            diff = diff.max((p.0 - q.0).hypot(p.1 - q.1));
            size = size.max((p.0 - mx).hypot(p.1 - my));
        }
    }
    diff / size
}

/// The shipped models with a transient that shows their orbit: time step (s)
/// and duration (s), at the nominal speed from the static equilibrium.
/// The table of docs/solver.md: orbit errors with 1, 4, 10 and 20 modes.
const SHIPPED: [(&str, f64, f64, [f64; 4]); 11] = [
    (
        "classic_disk_rotor",
        1e-4,
        0.3,
        [1.6e-1, 7.4e-3, 6.3e-4, 3.0e-6],
    ),
    (
        "classic_disk_rotor_damped",
        1e-4,
        0.5,
        [2.2e-1, 1.0e-2, 9.4e-4, 1.5e-5],
    ),
    ("compressor", 5e-5, 0.2, [3.7e-2, 1.9e-2, 4.5e-3, 1.3e-3]),
    ("jeffcott", 1e-4, 0.3, [9.0e-5, 6.2e-6, 1.1e-6, 5.0e-8]),
    (
        "vertical_rotor",
        5e-4,
        1.0,
        [2.7e-5, 5.6e-7, 1.1e-7, 7.2e-9],
    ),
    ("hydro_unit", 5e-3, 8.0, [2.5e-2, 3.3e-3, 8.6e-5, 5.3e-6]),
    (
        "hydro_unit_plain",
        5e-3,
        8.0,
        [4.7e-4, 1.0e-4, 1.5e-6, 1.3e-7],
    ),
    (
        "hydro_unit_brackets",
        5e-3,
        8.0,
        [1.1e-3, 1.4e-3, 6.4e-4, 8.3e-4],
    ),
    (
        "hydro_unit_three_guide",
        5e-3,
        4.0,
        [4.6e-3, 5.6e-5, 2.3e-5, 2.0e-6],
    ),
    (
        "hydro_unit_three_guide_offset",
        5e-3,
        4.0,
        [4.6e-3, 5.6e-5, 2.3e-5, 2.0e-6],
    ),
    (
        "turbine_generator_train",
        5e-4,
        1.0,
        [1.0e-2, 1.0e-2, 3.8e-3, 2.8e-4],
    ),
];

/// Models whose transient halves a few steps (plain Newton giving up on a
/// slowly converging step) at other times in the full and the reduced runs:
/// their orbits then differ by about the floor given here whatever the mode
/// count — the time grids differ, not the rotors. The eight-pad guide
/// bearings without preload of the unit on brackets, nearly unloaded, take
/// about 18 Newton iterations a step.
const STEP_CUT_FLOOR: [(&str, f64); 1] = [("hydro_unit_brackets", 2e-3)];

/// Models whose error stays level over the first modes: the turbine–generator
/// train's fixed-interface modes 2–4 barely take part in its response to the
/// stages' and the generator body's unbalance, so with 4 modes its error is
/// that of 1 mode within 0.4 % (1.04e-2); it falls from there on. The factor
/// an error may exceed the one before it by.
const PLATEAU: [(&str, f64); 1] = [("turbine_generator_train", 1.01)];

/// Acceptance of issue 17: on every shipped model the orbits (journals and
/// probes, from the static equilibrium on) converge to the full model's as
/// modes are added, and are within 1 % with the first of the default 10 modes
/// and 20 whose validated range (a tenth of the highest kept mode) holds the
/// nominal speed (10 on every model but the compressor); a generator
/// runs synchronized (its magnetic pull at nominal field).
/// Each error is docs/solver.md's, as printed there to two digits (the last,
/// round-off-sized entry of the vertical rotor only in order of magnitude).
#[test]
fn reduced_orbits_converge_to_the_full_model_on_every_shipped_model() {
    let shipped = shipped();
    assert_eq!(
        shipped.len(),
        SHIPPED.len(),
        "a shipped model is missing here: {shipped:?}"
    );
    for (name, step, duration, readme) in SHIPPED {
        let mut m = model(name);
        // Running synchronized: every magnetic pull at nominal field.
        for b in &mut m.bearings {
            b.kind.set_excitation(1.0);
        }
        let speed = m.nominal_speed;
        assert!(speed > 0.0, "{name}");
        let full = run(Rotor::new(m.clone()).unwrap(), speed, step, duration);
        let mut errors = Vec::new();
        let mut held = None;
        for modes in [1, 4, 10, 20] {
            let rotor = Rotor::for_transients(m.clone(), modes).unwrap();
            let r = rotor.reduction.clone().unwrap();
            let error = orbit_error(&full, &run(rotor, speed, step, duration));
            println!(
                "{name}, {modes} modes: orbit error {error:.2e}; {}",
                r.describe()
            );
            // The first of the default 10 and 20 modes whose validated
            // range holds the nominal speed (20 for the compressor at
            // 11 500 rpm: 10 hold 10 756 rpm) is within 1 %.
            if modes >= 10 && held.is_none() && speed <= r.validated_frequency() {
                assert!(error < 0.01, "{name}: {error:.2e} with {modes} modes");
                held = Some(modes);
            }
            errors.push(error);
        }
        assert!(
            held.is_some(),
            "{name}: speed outside the validated range of 20 modes"
        );
        if let Some(&(_, floor)) = STEP_CUT_FLOOR.iter().find(|(n, _)| *n == name) {
            // Steps halved at other times in the two runs set the floor.
            assert!(errors.iter().all(|&e| e < floor), "{name}: {errors:?}");
            continue;
        }
        let level = PLATEAU
            .iter()
            .find(|(n, _)| *n == name)
            .map_or(1.0, |p| p.1);
        assert!(
            errors.windows(2).all(|w| w[1] < w[0] * level),
            "{name}: {errors:?}"
        );
        for (e, r) in errors.iter().zip(readme) {
            let printed_alike = if r < 1e-10 {
                (e / r).log10().abs() < 0.5
            } else {
                (e - r).abs() <= 0.05 * r + 1e-13
            };
            assert!(
                printed_alike,
                "{name}: {e:.2e} against docs/solver.md's {r:.1e}"
            );
        }
    }
}

/// With every fixed-interface mode kept, `T` is a change of basis: the
/// reduced transient is the full one up to round-off.
#[test]
fn keeping_every_mode_reproduces_the_full_model() {
    for (name, step, duration) in [
        ("jeffcott", 1e-4, 0.1),
        ("classic_disk_rotor_damped", 1e-4, 0.1),
    ] {
        let m = model(name);
        let full_rotor = Rotor::new(m.clone()).unwrap();
        let interior = full_rotor.dof_count() - 4 * full_rotor.kept_nodes().len();
        let reduced = full_rotor.reduced(interior).unwrap();
        assert_eq!(reduced.dof_count(), full_rotor.dof_count());
        let speed = m.nominal_speed;
        let error = orbit_error(
            &run(full_rotor, speed, step, duration),
            &run(reduced, speed, step, duration),
        );
        assert!(error < 1e-7, "{name}: {error:.2e}");
    }
}

/// Static condensation is exact at the kept nodes: the static equilibrium on
/// nonlinear bearings (plain and tilting-pad, gravity across and along the
/// shaft) is the full model's, whatever the mode count.
#[test]
fn static_equilibrium_on_the_bearings_is_exact() {
    for name in ["jeffcott", "hydro_unit", "vertical_rotor"] {
        let m = model(name);
        let speed = m.nominal_speed;
        let full = run(Rotor::new(m.clone()).unwrap(), speed, 1e-4, 0.0);
        for modes in [1, 3] {
            let reduced = run(
                Rotor::for_transients(m.clone(), modes).unwrap(),
                speed,
                1e-4,
                0.0,
            );
            for (a, b) in full.iter().zip(&reduced) {
                let scale = a[0].0.hypot(a[0].1).max(1e-9);
                let d = (a[0].0 - b[0].0).hypot(a[0].1 - b[0].1);
                assert!(
                    d <= 1e-9 * scale,
                    "{name}, {modes} modes: {:?} against {:?}",
                    a[0],
                    b[0]
                );
            }
        }
    }
}

/// The shipped speed-driven models: their file stems. These tests prescribe
/// the speed, so a torque-driven model is left out (`hydro_unit_torque` is
/// hydro_unit's lateral rotor with torque inputs and a thrust bearing that
/// acts on the twist only).
fn shipped() -> Vec<String> {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/models");
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| {
            let text = std::fs::read_to_string(p).unwrap();
            RotorModel::from_toml(&text, &p.to_string_lossy())
                .unwrap()
                .drive
                != rotor_bearing::model::Drive::Torque
        })
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// Models where a tenth of the highest kept mode falls next to a lightly
/// damped critical speed of the coupled rotor, and the bound of their
/// receptance error there: the compressor's 3 and 4 modes (highest 5116
/// rad/s) put a tenth of it at 511.6 rad/s, 3 % below its first critical
/// (527–532 rad/s, ζ 0.13–0.15), where the receptance's slope amplifies the
/// reduced rotor's small shift of that mode: 5.7e-2 and 3.8e-2 while
/// spinning at 11 500 rpm (1.8e-2, 1.0e-2 synchronous); every other count of
/// it is within 1 % (`docs/solver.md`).
const NEAR_CRITICAL: [(&str, f64); 1] = [("compressor", 6e-2)];

/// Issue 22: the rule that holds. The receptance between the kept nodes'
/// translations (every force acts there and every output is read there) of
/// the reduced rotor against the full one, bearings linearized at the static
/// equilibrium, on every shipped model with 1 to 24 fixed-interface modes:
/// within 1 % while the excitation stays below a tenth of the highest kept
/// mode ([`VALIDITY_FACTOR`]), at the running speed itself and at any
/// frequency while spinning at the nominal speed, but next to a lightly
/// damped critical ([`NEAR_CRITICAL`]); beyond, the error grows to
/// over 50 % at half the highest mode, where the old rule of docs/solver.md (modes
/// above the excitation) still called the rotor valid. Prints the table of
/// the worst errors docs/solver.md gives.
#[test]
fn the_validity_rule_is_the_measured_one() {
    let ratios = [0.02, 0.05, 0.1, 0.2, 0.3, 0.5];
    let mut worst = vec![(0.0f64, String::new()); ratios.len()];
    for name in shipped() {
        let m = model(&name);
        let full = Rotor::new(m.clone()).unwrap();
        for modes in 1..=24 {
            let reduced = full.reduced(modes).unwrap();
            let r = reduced.reduction.as_ref().unwrap();
            if r.modes < modes {
                break;
            }
            let top = r.highest_frequency();
            for (k, ratio) in ratios.iter().enumerate() {
                let w = ratio * top;
                if w > m.max_speed {
                    continue;
                }
                let synchronous = receptance_errors(&full, &reduced, w, &[w]).unwrap()[0];
                let at_speed =
                    receptance_errors(&full, &reduced, m.nominal_speed, &[w]).unwrap()[0];
                let e = synchronous.max(at_speed);
                if let Some(&(_, bound)) = NEAR_CRITICAL.iter().find(|(n, _)| *n == name)
                    && *ratio <= 1.0 / VALIDITY_FACTOR
                {
                    assert!(
                        e < bound,
                        "{name}, {modes} modes: {e:.2e} at {ratio} × {top}"
                    );
                    continue;
                }
                if e > worst[k].0 {
                    worst[k] = (e, format!("{name}, {modes} modes"));
                }
            }
        }
    }
    println!("frequency / highest kept mode | worst receptance error (shipped models, 1–24 modes)");
    for (r, (e, at)) in ratios.iter().zip(&worst) {
        println!("{r} | {e:.1e} ({at})");
    }
    for (r, (e, at)) in ratios.iter().zip(&worst) {
        if *r <= 1.0 / VALIDITY_FACTOR {
            assert!(*e < 1e-2, "{e:.2e} at {r} × the highest mode ({at})");
        }
    }
    assert!(worst[5].0 > 0.5, "half the highest mode: {:?}", worst[5]);
    assert!(
        worst[3].0 > 0.05,
        "a fifth of the highest mode: {:?}",
        worst[3]
    );
}

/// The time domain agrees: the hydro unit on 4 modes (highest 61.5 Hz) run to
/// a steady unbalance response at a tenth of the highest mode stays within
/// 1 % of the full rotor's orbits, at 0.3× it is several per cent off, and
/// the receptance error at the speed says so.
#[test]
fn transient_orbits_follow_the_rule() {
    let m = model("hydro_unit");
    let full = Rotor::new(m.clone()).unwrap();
    let top = full
        .reduced(4)
        .unwrap()
        .reduction
        .unwrap()
        .highest_frequency();
    let steady = |rotor: Rotor, speed: f64| {
        let opts = SolverOptions {
            time_step: 2e-3,
            unbalance_ramp_time: 1.0,
            ..SolverOptions::default()
        };
        let mut sim = Simulator::new(rotor, opts).unwrap();
        sim.set_speed(speed, 0.0).unwrap();
        sim.settle_static().unwrap();
        let end = 60.0 * std::f64::consts::TAU / speed;
        let steps = (end / 2e-3).round() as usize;
        let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
        for k in 1..=steps {
            sim.advance_to(k as f64 * 2e-3).unwrap();
            if k > steps / 2 {
                let o = sim.outputs().unwrap();
                let p: Vec<(f64, f64)> = o.bearings.iter().map(|b| (b.x, b.y)).collect();
                if out.is_empty() {
                    out = vec![Vec::new(); p.len()];
                }
                for (s, q) in out.iter_mut().zip(p) {
                    s.push(q);
                }
            }
        }
        out
    };
    for (ratio, inside) in [(0.1, true), (0.3, false)] {
        let w = ratio * top;
        let reference = steady(Rotor::new(m.clone()).unwrap(), w);
        let reduced = full.reduced(4).unwrap();
        let estimate = receptance_errors(&full, &reduced, w, &[w]).unwrap()[0];
        let error = orbit_error(&reference, &steady(reduced, w));
        println!(
            "{ratio} × the highest mode: orbit error {error:.2e}, receptance error {estimate:.2e}"
        );
        if inside {
            assert!(error < 1e-2 && estimate < 1e-2, "{error:e} {estimate:e}");
        } else {
            assert!(error > 2e-2 && estimate > 2e-2, "{error:e} {estimate:e}");
        }
    }
}

/// Without `modes`, `[reduction]` keeps as many modes as the speed range
/// needs by the rule: the smallest count (a degenerate pair kept whole)
/// whose highest mode reaches ten times the top speed (the model's
/// `max_speed_rpm` if stated, else `speed_rpm`); on every shipped model the
/// orbits are then within 1 % of the full rotor's. A model with no speed
/// keeps the fixed default.
#[test]
fn the_default_mode_count_follows_the_speed_range() {
    for name in shipped() {
        let path = format!("{}/models/{name}.toml", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(path).unwrap();
        let m = RotorModel::from_toml(&format!("{text}\n[reduction]\n"), "r.toml").unwrap();
        let modes = Rotor::transient_modes(&m).unwrap();
        let full = Rotor::new(m.clone()).unwrap();
        let f = full.fixed_interface_frequencies(modes + 4).unwrap();
        // The top speed: `max_speed_rpm` if stated, else `speed_rpm`.
        let top = if m.max_speed_stated {
            m.max_speed
        } else {
            m.nominal_speed
        };
        let target = VALIDITY_FACTOR * top;
        // The first mode to reach the target, and its degenerate partners.
        let first = f.iter().position(|&w| w >= target).unwrap();
        let group = f[first..]
            .iter()
            .take_while(|&&w| w <= f[first] * (1.0 + 1e-6))
            .count();
        assert_eq!(modes, first + group, "{name}: {f:?} against {target}");
        let (step, duration) = SHIPPED
            .iter()
            .find(|s| s.0 == name)
            .map(|s| (s.1, s.2))
            .unwrap();
        let reduced = Rotor::for_transients(m.clone(), modes).unwrap();
        let error = orbit_error(
            &run(full, m.nominal_speed, step, duration),
            &run(reduced, m.nominal_speed, step, duration),
        );
        println!("{name}: {modes} modes by the speed range, orbit error {error:.2e}");
        assert!(error < 1e-2, "{name}: {error:.2e} with {modes} modes");
    }
    // A stated max_speed_rpm sets the range: more modes for a faster machine.
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/models/jeffcott.toml"))
            .unwrap();
    let fast = RotorModel::from_toml(
        &format!("max_speed_rpm = 30000\n{text}\n[reduction]\n"),
        "f.toml",
    )
    .unwrap();
    let modes = Rotor::transient_modes(&fast).unwrap();
    let f = Rotor::new(fast.clone())
        .unwrap()
        .fixed_interface_frequencies(modes)
        .unwrap();
    assert!(
        modes > 4 && f[modes - 1] >= VALIDITY_FACTOR * fast.max_speed,
        "{modes}: {f:?}"
    );
    let still = text.replace("speed_rpm = 3000", "");
    let still = RotorModel::from_toml(&format!("{still}\n[reduction]\n"), "s.toml").unwrap();
    assert_eq!(Rotor::transient_modes(&still), Ok(DEFAULT_REDUCED_MODES));
}

/// Journals of linear bearings stay in the matrices and off the kept nodes;
/// their outputs come through the basis and agree with the full model's.
#[test]
fn linear_bearing_outputs_come_through_the_basis() {
    let m = model("classic_disk_rotor_damped");
    let rotor = Rotor::for_transients(m.clone(), 10).unwrap();
    assert_eq!(rotor.kept_nodes(), vec![3]);
    let speed = m.nominal_speed;
    let full = run(Rotor::new(m).unwrap(), speed, 1e-4, 0.2);
    let reduced = run(rotor, speed, 1e-4, 0.2);
    for (a, b) in full[..2].iter().zip(&reduced[..2]) {
        let size = a.iter().fold(0.0f64, |s, p| s.max(p.0.hypot(p.1)));
        assert!(size > 1e-6);
        let d = a
            .iter()
            .zip(b)
            .fold(0.0f64, |s, (p, q)| s.max((p.0 - q.0).hypot(p.1 - q.1)));
        assert!(d < 0.01 * size, "{d} against {size}");
    }
}

/// Asking for too much or too little is a clear error; a count above the
/// interior's is clamped and said.
#[test]
fn reduction_requests_are_checked() {
    let rotor = Rotor::new(model("jeffcott")).unwrap();
    let e = rotor.reduced(0).unwrap_err().to_string();
    assert!(
        e.contains("jeffcott") && e.contains("reduced_modes = 0"),
        "{e}"
    );
    let reduced = rotor.reduced(500).unwrap();
    let r = reduced.reduction.as_ref().unwrap();
    assert_eq!(r.physical + r.modes, rotor.dof_count());
    assert!(
        r.describe().contains("500 asked, all the interior has"),
        "{}",
        r.describe()
    );
    // A fresh copy of a reduced rotor is reduced again with the count asked.
    let copy = reduced.clone_model().unwrap();
    assert_eq!(copy.reduction.as_ref().unwrap().requested, 500);
    assert_eq!(copy.mass.to_dense(), reduced.mass.to_dense());
    let e = reduced.reduced(4).unwrap_err().to_string();
    assert!(e.contains("already reduced"), "{e}");
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/models/classic_disk_rotor.toml"
    ))
    .unwrap();
    let bare: String = text.split("[[unbalance]]").next().unwrap().to_string();
    let e = Rotor::new(RotorModel::from_toml(&bare, "bare.toml").unwrap())
        .unwrap()
        .reduced(4)
        .unwrap_err()
        .to_string();
    assert!(e.contains("no node to keep"), "{e}");
    // Every node kept: nothing left to reduce, the rotor is the full one.
    let both_ends =
        format!("{bare}[[probes]]\nname = \"a\"\nnode = 1\n[[probes]]\nname = \"b\"\nnode = 7\n");
    let short = both_ends
        .replace("elements = 6", "elements = 1")
        .replace("node = 4", "node = 2")
        .replace("node = 7", "node = 2");
    let full = Rotor::new(RotorModel::from_toml(&short, "short.toml").unwrap()).unwrap();
    let all = full.reduced(3).unwrap();
    let r = all.reduction.as_ref().unwrap();
    assert_eq!((r.physical, r.modes), (full.dof_count(), 0));
    assert_eq!(all.mass.to_dense(), full.mass.to_dense());
}
