//! Torsional dynamics: modes against closed forms, and the torque-driven
//! simulator against the speed-driven one, energy and breakaway.

use rotor_bearing::analysis::torsion::torsional_modes;
use rotor_bearing::model::RotorModel;

/// Two disks (2 and 5 kg·m²) on a 1e5 N·m/rad coupling between the nodes
/// of a vanishing shaft.
const TWO_INERTIAS: &str = r#"
name = "two_inertias"
[[materials]]
name = "steel"
youngs_modulus = 211e9
poisson_ratio = 0.3
density = 7810.0
[[shaft]]
length = 0.001
outer_diameter = 0.001
material = "steel"
elements = 1
[[disks]]
node = 1
mass = 10.0
polar_inertia = 2.0
diametral_inertia = 1.0
[[disks]]
node = 2
mass = 10.0
polar_inertia = 5.0
diametral_inertia = 2.5
[[couplings]]
node = 1
torsional_stiffness = 1e5
[[bearings]]
type = "linear"
node = 1
kxx = 1e6
kyy = 1e6
[[bearings]]
type = "linear"
node = 2
kxx = 1e6
kyy = 1e6
"#;

/// Two disks (2 and 5 kg·m²) on a coupling of 1e5 N·m/rad joining two
/// nodes of a vanishing shaft (1 mm × 1 mm: its polar inertia is 1e-12 of
/// the disks'): the one torsional frequency is `√(k (J₁ + J₂)/(J₁ J₂))` to
/// 1e-9, and the disks twist against each other in the ratio `−J₁/J₂`.
#[test]
fn two_inertias_on_a_spring_have_the_closed_form_frequency() {
    let text = TWO_INERTIAS;
    let model = RotorModel::from_toml(text, "two.toml").unwrap();
    let modes = torsional_modes(&model, 3).unwrap();
    assert_eq!(
        modes.len(),
        1,
        "one elastic mode besides the rigid rotation"
    );
    let (j1, j2, k): (f64, f64, f64) = (2.0, 5.0, 1e5);
    let want = (k * (j1 + j2) / (j1 * j2)).sqrt();
    let got = modes[0].natural_frequency;
    assert!(
        (got / want - 1.0).abs() < 1e-9,
        "{got} against {want} rad/s"
    );
    let ratio = modes[0].shape[1] / modes[0].shape[0];
    assert!((ratio + j1 / j2).abs() < 1e-9, "shape ratio {ratio}");
}

/// A uniform steel shaft, 2 m × 80 mm, in `n` elements: free–free
/// (`ω_k = kπ/L √(G/ρ)`) and fixed–free (`ω_k = (2k−1)π/(2L) √(G/ρ)`, twist
/// held at node 1) frequencies of its first three modes; the error falls as
/// the element length squared (each halving divides it by 4 ± 5 %) and is
/// below 1e-3 at 80 elements.
#[test]
fn a_uniform_shaft_converges_to_the_analytic_torsional_frequencies() {
    let (length, g, rho): (f64, f64, f64) = (2.0, 81.2e9, 7810.0);
    let c = (g / rho).sqrt();
    let shaft = |n: usize, fixed: bool| {
        let support = if fixed {
            "[[supports]]\nnode = 1\nfix = [\"rz\"]\n"
        } else {
            ""
        };
        let text = format!(
            "name = \"uniform\"\n[[materials]]\nname = \"steel\"\nyoungs_modulus = 211e9\nshear_modulus = {g}\ndensity = {rho}\n\
             [[shaft]]\nlength = {length}\nouter_diameter = 0.08\nmaterial = \"steel\"\nelements = {n}\n\
             [[bearings]]\ntype = \"linear\"\nnode = 1\nkxx = 1e7\nkyy = 1e7\n\
             [[bearings]]\ntype = \"linear\"\nnode = {}\nkxx = 1e7\nkyy = 1e7\n{support}",
            n + 1
        );
        torsional_modes(&RotorModel::from_toml(&text, "uniform.toml").unwrap(), 3).unwrap()
    };
    for fixed in [false, true] {
        let exact = |k: usize| {
            let k = k as f64;
            if fixed {
                (2.0 * k - 1.0) * std::f64::consts::PI / (2.0 * length) * c
            } else {
                k * std::f64::consts::PI / length * c
            }
        };
        let errors: Vec<Vec<f64>> = [20, 40, 80]
            .iter()
            .map(|&n| {
                shaft(n, fixed)
                    .iter()
                    .enumerate()
                    .map(|(k, m)| (m.natural_frequency / exact(k + 1) - 1.0).abs())
                    .collect()
            })
            .collect();
        for k in 0..3 {
            for w in errors.windows(2) {
                let ratio = w[0][k] / w[1][k];
                assert!(
                    (ratio / 4.0 - 1.0).abs() < 0.05,
                    "fixed {fixed}, mode {}: {errors:?}",
                    k + 1
                );
            }
            assert!(
                errors[2][k] < 1e-3,
                "fixed {fixed}, mode {}: {errors:?}",
                k + 1
            );
        }
    }
}

use rotor_bearing::model::DEFAULT_MODEL_TOML;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

/// The damped classic rotor driven by torques: `drive` at node 1 and `load`
/// at node 7, every element's torsional stiffness raised to 1e12 N·m/rad by
/// a coupling when `stiff` (a torsionally rigid shaft).
fn torque_driven_classic(stiff: bool) -> String {
    let mut text = DEFAULT_MODEL_TOML
        .replace("kyy = 1e6\n", "kyy = 1e6\ncxx = 800.0\ncyy = 800.0\n")
        + "\n[torsion]\ndrive = \"torque\"\n[[torques]]\nname = \"drive\"\nnode = 1\n[[torques]]\nname = \"load\"\nnode = 7\n";
    if stiff {
        for node in 1..=6 {
            text += &format!("[[couplings]]\nnode = {node}\ntorsional_stiffness = 1e12\n");
        }
    }
    text
}

/// The same machine run torque-driven (a 20 N·m drive at one end, a −5 N·m
/// load at the other, ramped in over 50 ms, 1.5 s from rest) and speed-driven with the torque run's mean speed
/// history given step by step (speed and rate, as a master's input
/// derivatives give it): on a torsionally rigid shaft the disk orbits agree
/// to 1e-9 of their size. Without unbalance (nothing else takes energy from
/// the shaft) the speed grows as the net torque over the polar inertia of
/// the whole rotor, the closed form of a rigid shaft, to 1e-9.
#[test]
fn a_torque_driven_rigid_shaft_reproduces_the_speed_driven_run() {
    let model = RotorModel::from_toml(&torque_driven_classic(true), "torque.toml").unwrap();
    let chain = rotor_bearing::rotor::torsion::TorsionalRotor::new(&model);
    let inertia = chain.total_inertia();
    let h = 1e-4;
    let options = SolverOptions {
        time_step: h,
        gravity: false,
        ..SolverOptions::default()
    };
    let first = model.first_torque_input();
    let run = |unbalance: f64, follow: bool| {
        let mut torque = Simulator::new(Rotor::new(model.clone()).unwrap(), options).unwrap();
        torque.set_unbalance(0, unbalance).unwrap();
        // Torques ramped in over 50 ms (a sudden torque would ring the
        // shaft's torsional modes), then held.
        torque.set_load(first, 0.0, 400.0).unwrap();
        torque.set_load(first + 1, 0.0, -100.0).unwrap();
        let mut speed_model = model.clone();
        speed_model.drive = rotor_bearing::model::Drive::Speed;
        let mut speed = Simulator::new(Rotor::new(speed_model).unwrap(), options).unwrap();
        speed.set_unbalance(0, unbalance).unwrap();
        let (mut worst, mut size) = (0.0_f64, 0.0_f64);
        let mut w_prev = 0.0;
        let mut at_half = 0.0;
        for n in 1..=15000 {
            let t = n as f64 * h;
            if n == 501 {
                torque.set_load(first, 20.0, 0.0).unwrap();
                torque.set_load(first + 1, -5.0, 0.0).unwrap();
            }
            torque.advance_to(t).unwrap();
            let a = torque.outputs().unwrap();
            if n == 5000 {
                at_half = a.speed;
            }
            if follow {
                speed.set_speed(w_prev, (a.speed - w_prev) / h).unwrap();
                speed.advance_to(t).unwrap();
                let b = speed.outputs().unwrap();
                let (pa, pb) = (a.probes[0], b.probes[0]);
                worst = worst.max((pa.x - pb.x).hypot(pa.y - pb.y));
                size = size.max(pa.x.hypot(pa.y));
            }
            w_prev = a.speed;
        }
        (at_half, w_prev, worst, size)
    };
    let (half, end, _, _) = run(0.0, false);
    // ∫ T dt = 15 N·m × (t − 25 ms) past the ramp.
    for (got, want) in [
        (half, 15.0 / inertia * 0.475),
        (end, 15.0 / inertia * 1.475),
    ] {
        assert!(
            (got / want - 1.0).abs() < 1e-9,
            "{got} against {want} rad/s"
        );
    }
    let (_, _, worst, size) = run(1e-3, true);
    assert!(
        size > 0.0 && worst < 1e-9 * size,
        "orbits differ by {worst:e} m of {size:e} m"
    );
}

/// `xᵀ A y` for a banded matrix.
fn quadratic(a: &rotor_bearing::linalg::BandMatrix<f64>, x: &[f64], y: &[f64]) -> f64 {
    let mut ay = vec![0.0; y.len()];
    a.mul_vec(y, &mut ay);
    x.iter().zip(&ay).map(|(p, q)| p * q).sum()
}

/// The torque-driven classic rotor with its flexible shaft, unbalance,
/// damped bearings and a damped coupling, driven by 20 N·m against −5 N·m:
/// the work of the input torques, `Σ ∫ T φ̇ dt`, equals the change of the
/// whole machine's energy — lateral kinetic and elastic, torsional kinetic
/// and elastic, and the unbalance mass's cross term `−m e φ̇ (ẋ sin φ −
/// ẏ cos φ)` — plus what the bearing and coupling dampers dissipate, to
/// 1e-6 of the work.
#[test]
fn the_input_torques_work_balances_the_energy() {
    let text = torque_driven_classic(false)
        + "[[couplings]]\nnode = 3\ntorsional_stiffness = 5e4\ntorsional_damping = 2.0\n";
    let model = RotorModel::from_toml(&text, "torque.toml").unwrap();
    let chain = rotor_bearing::rotor::torsion::TorsionalRotor::new(&model);
    let r = Rotor::new(model.clone()).unwrap();
    let (mass, stiffness, damping) = (r.mass.clone(), r.stiffness.clone(), r.damping.clone());
    let disk = [r.dofs.free(3, 0).unwrap(), r.dofs.free(3, 1).unwrap()];
    let (me, phase) = (model.unbalances[0].magnitude, model.unbalances[0].phase);
    let h = 1e-4;
    let mut sim = Simulator::new(
        r,
        SolverOptions {
            time_step: h,
            gravity: false,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    let first = model.first_torque_input();
    sim.set_load(first, 20.0, 0.0).unwrap();
    sim.set_load(first + 1, -5.0, 0.0).unwrap();
    let energy = |s: &rotor_bearing::solver::SimState| {
        let phi = s.twist[3] + phase;
        let cross = -me * s.twist_rate[3] * (s.ud[disk[0]] * phi.sin() - s.ud[disk[1]] * phi.cos());
        0.5 * quadratic(&mass, &s.ud, &s.ud)
            + 0.5 * quadratic(&stiffness, &s.u, &s.u)
            + 0.5 * quadratic(&chain.mass, &s.twist_rate, &s.twist_rate)
            + 0.5 * quadratic(&chain.stiffness, &s.twist, &s.twist)
            + cross
    };
    let mut state = sim.state().clone();
    let e0 = energy(&state);
    let (mut work, mut dissipated) = (0.0, 0.0);
    for n in 1..=10000 {
        sim.advance_to(n as f64 * h).unwrap();
        let next = sim.state().clone();
        work += 20.0 * (next.twist[0] - state.twist[0]) - 5.0 * (next.twist[6] - state.twist[6]);
        let v: Vec<f64> = state
            .ud
            .iter()
            .zip(&next.ud)
            .map(|(a, b)| 0.5 * (a + b))
            .collect();
        let w: Vec<f64> = state
            .twist_rate
            .iter()
            .zip(&next.twist_rate)
            .map(|(a, b)| 0.5 * (a + b))
            .collect();
        dissipated += h * (quadratic(&damping, &v, &v) + quadratic(&chain.damping, &w, &w));
        state = next;
    }
    let change = energy(&state) - e0;
    assert!(
        (work - change - dissipated).abs() < 1e-6 * work,
        "input work {work:e} J against energy change {change:e} J plus dissipation {dissipated:e} J"
    );
}

/// The hydro unit on its brackets, torque-driven: a turbine torque at the
/// runner, a generator torque at the generator, a thrust bearing carrying
/// the rotor's weight (R 0.6–1.0 m, μ_b 0.15).
fn torque_driven_hydro(oil_lift: bool) -> RotorModel {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/models/hydro_unit_brackets.toml"
    );
    let text = std::fs::read_to_string(path).unwrap()
        + &format!(
            "\n[torsion]\ndrive = \"torque\"\n[[torques]]\nname = \"turbine\"\nnode = 11\n[[torques]]\nname = \"generator\"\nnode = 3\n\
             [[thrust_bearings]]\nname = \"thrust\"\nnode = 2\ninner_radius = 0.6\nouter_radius = 1.0\nfilm_thickness = 60e-6\nviscosity = 0.03\noil_lift = {oil_lift}\n"
        );
    RotorModel::from_toml(&text, "hydro_torque.toml").unwrap()
}

/// Breakaway: the turbine torque ramps from 0 to 3e5 N·m over 2 s; the
/// shaft stays at exactly zero speed while the torque is within the thrust
/// bearing's `μ_b W R_m` (the guide bearings of a vertical shaft carry no
/// load at rest, so they add nothing), then runs up; with an oil lift it
/// breaks away at once. The thrust bearing's load is the rotor's weight.
#[test]
fn a_vertical_unit_breaks_away_at_the_thrust_bearings_friction() {
    for oil_lift in [false, true] {
        let model = torque_driven_hydro(oil_lift);
        let weight = model.total_mass() * 9.81;
        let thrust = &model.thrust_bearings[0].bearing;
        assert!((thrust.load / weight - 1.0).abs() < 1e-12);
        let breakaway = if oil_lift { 0.0 } else { 0.15 * weight * 0.8 };
        assert!((thrust.breakaway_torque() - breakaway).abs() < 1e-6 * weight);
        let turbine = model.first_torque_input();
        let h = 2e-3;
        let mut sim = Simulator::new(
            Rotor::new(model).unwrap(),
            SolverOptions {
                time_step: h,
                ..SolverOptions::default()
            },
        )
        .unwrap();
        sim.settle_static().unwrap();
        let rate = 1.5e5; // N·m/s
        sim.set_load(turbine, 0.0, rate).unwrap();
        let mut first_motion = None;
        for n in 1..=1000 {
            let t = n as f64 * h;
            sim.advance_to(t).unwrap();
            let out = sim.outputs().unwrap();
            match first_motion {
                None if out.speed != 0.0 => first_motion = Some(t),
                None => assert_eq!(out.speed, 0.0),
                Some(_) => assert!(out.speed > 0.0, "t = {t}: {} rad/s", out.speed),
            }
        }
        let started = first_motion.expect("the unit breaks away");
        // The first step whose end torque exceeds the breakaway torque.
        let want = ((breakaway / rate / h).floor() + 1.0) * h;
        assert!(
            (started - want).abs() < 1e-9,
            "oil lift {oil_lift}: moved at {started} s, torque reached μ W R_m at {} s",
            breakaway / rate
        );
    }
}

/// `rotor modes` lists the torsional modes after the lateral ones, labelled
/// "torsional" (the two-inertia frequency to the printed 4 decimals), writes
/// their shapes (twist ratio −J₁/J₂ to 1e-9), and `rotor campbell` names
/// them as horizontal lines.
#[test]
fn the_cli_lists_torsional_modes_and_their_shapes() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("torsion_cli");
    std::fs::create_dir_all(&dir).unwrap();
    let (model, csv) = (dir.join("two.toml"), dir.join("twist.csv"));
    std::fs::write(&model, TWO_INERTIAS).unwrap();
    let run = |args: &[&str]| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
            .args(args)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8(out.stdout).unwrap()
    };
    let m = model.to_str().unwrap();
    let out = run(&[
        "modes",
        m,
        "--torsional-modes",
        "2",
        "--torsional-shapes-csv",
        csv.to_str().unwrap(),
    ]);
    let want = (1e5f64 * 7.0 / 10.0).sqrt();
    let rows: Vec<Vec<&str>> = out
        .lines()
        .filter(|l| l.trim_end().ends_with("torsional"))
        .map(|l| l.split_whitespace().collect())
        .collect();
    assert_eq!(rows.len(), 1, "{out}");
    let hz: f64 = rows[0][2].parse().unwrap();
    assert!((hz - want / std::f64::consts::TAU).abs() < 5e-5, "{out}");
    assert_eq!(rows[0][3], "0", "an undamped coupling");
    let text = std::fs::read_to_string(&csv).unwrap();
    let twist: Vec<f64> = text
        .lines()
        .skip(1)
        .map(|l| l.rsplit(',').next().unwrap().parse().unwrap())
        .collect();
    assert_eq!(twist.len(), 2);
    assert!((twist[1] / twist[0] + 2.0 / 5.0).abs() < 1e-9, "{text}");
    let campbell = run(&["campbell", m, "--max-rpm", "3000", "--steps", "4"]);
    let line = format!(
        "torsional modes (horizontal lines, independent of the speed): {:.4} Hz",
        want / std::f64::consts::TAU
    );
    assert!(campbell.contains(&line), "{campbell}");
}

/// A short-circuit torque on a two-inertia shaft (acceptance 4 of issue 25):
/// the generator's electromagnetic torque rises linearly to `T` over `t_r`
/// and stays (the envelope of a three-phase fault's torque). The twist
/// `θ = φ₁ − φ₂` obeys `θ̈ + ω² θ = T(t)/J₁`, so the shaft torque `k θ`
/// peaks at `T J₂/(J₁ + J₂) (1 + 2 |sin(ω t_r/2)|/(ω t_r))`: the torque-driven
/// simulator's peak (parabola through the three samples around it) matches to
/// 1e-6 at a 2 µs step (Newmark's error is `O((ω h)²)` ≈ 3e-7 here).
#[test]
fn a_short_circuit_torque_peaks_as_the_two_inertia_closed_form() {
    let text = TWO_INERTIAS.to_string()
        + "\n[torsion]\ndrive = \"torque\"\n[[torques]]\nname = \"generator\"\nnode = 1\n";
    let model = RotorModel::from_toml(&text, "two_torque.toml").unwrap();
    let (j1, j2, k, torque, rise): (f64, f64, f64, f64, f64) = (2.0, 5.0, 1e5, 1e4, 2e-3);
    let omega = (k * (j1 + j2) / (j1 * j2)).sqrt();
    let want =
        torque * j2 / (j1 + j2) * (1.0 + 2.0 * (omega * rise / 2.0).sin().abs() / (omega * rise));
    let h = 2e-6;
    let mut sim = Simulator::new(
        Rotor::new(model.clone()).unwrap(),
        SolverOptions {
            time_step: h,
            gravity: false,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    sim.set_speed(100.0, 0.0).unwrap();
    sim.settle_static().unwrap();
    let input = model.first_torque_input();
    sim.set_load(input, 0.0, torque / rise).unwrap();
    let mut series = Vec::new();
    let steps = (0.03 / h) as usize;
    for n in 1..=steps {
        let t = n as f64 * h;
        if n == (rise / h).round() as usize + 1 {
            sim.set_load(input, torque, 0.0).unwrap();
        }
        sim.advance_to(t).unwrap();
        series.push(sim.section_torque(0).unwrap().abs());
    }
    let i = (1..series.len() - 1)
        .max_by(|&a, &b| series[a].total_cmp(&series[b]))
        .unwrap();
    let (a, b, c) = (series[i - 1], series[i], series[i + 1]);
    let peak = b + 0.125 * (a - c).powi(2) / (a - 2.0 * b + c).abs();
    assert!(
        (peak / want - 1.0).abs() < 1e-6,
        "shaft torque peak {peak} N·m against {want} N·m"
    );
}

/// `rotor simulate --torque NAME=VALUE` drives a torque-driven shaft: from
/// `--rpm` 600 (its initial speed) the rigid classic rotor without unbalance
/// accelerates as the net 15 N·m over its polar inertia (the CSV's mean
/// speed to 1e-9; each torque node's to 1e-4, as the torques applied at
/// once ring the stiff couplings); the CSV has the torque nodes'
/// speeds and angles and the elements' torques. A wrong name, a value that
/// is not a number, `--torque` on a speed-driven model and a speed ramp on
/// a torque-driven one are refused by name.
#[test]
fn the_cli_simulates_a_torque_driven_shaft() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("torsion_simulate");
    std::fs::create_dir_all(&dir).unwrap();
    let (model, csv) = (dir.join("torque.toml"), dir.join("run.csv"));
    let text = torque_driven_classic(true).replace("magnitude = 0.001", "magnitude = 0.0");
    std::fs::write(&model, &text).unwrap();
    let m = model.to_str().unwrap();
    let rotor = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
            .args(args)
            .output()
            .unwrap()
    };
    let out = rotor(&[
        "simulate",
        m,
        "--torque",
        "drive=20",
        "--torque",
        "load=-5",
        "--rpm",
        "600",
        "--duration",
        "0.3",
        "--step",
        "1e-4",
        "--output-step",
        "0.01",
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let table = std::fs::read_to_string(&csv).unwrap();
    let header: Vec<&str> = table.lines().next().unwrap().split(',').collect();
    let last: Vec<f64> = table
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|v| v.parse().unwrap())
        .collect();
    let col = |name: &str| {
        header
            .iter()
            .position(|h| *h == name)
            .unwrap_or_else(|| panic!("{name}: {header:?}"))
    };
    let parsed = RotorModel::from_toml(&text, "torque.toml").unwrap();
    let inertia = rotor_bearing::rotor::torsion::TorsionalRotor::new(&parsed).total_inertia();
    let rpm = 30.0 / std::f64::consts::PI;
    let want = 600.0 + 15.0 / inertia * 0.3 * rpm;
    for (name, tolerance) in [
        ("speed_rpm", 1e-9),
        ("drive_speed_rpm", 1e-4),
        ("load_speed_rpm", 1e-4),
    ] {
        let got = last[col(name)];
        assert!(
            (got / want - 1.0).abs() < tolerance,
            "{name}: {got} vs {want} rpm"
        );
    }
    assert!(header.contains(&"load_angle_rad") && header.contains(&"shaft_torque_6_Nm"));
    for (args, needle) in [
        (
            vec!["--torque", "turbine=3"],
            "\"turbine\" is not a torque node of",
        ),
        (
            vec!["--torque", "drive=lots"],
            "\"lots\" is not a finite number",
        ),
        (
            vec!["--ramp-rpm", "0:600"],
            "is torque-driven: its speed comes from the torques",
        ),
    ] {
        let mut all = vec!["simulate", m, "--duration", "0.01"];
        all.extend(args);
        let out = rotor(&all);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success() && err.contains(needle), "{err}");
    }
    let out = rotor(&[
        "simulate",
        "--torque",
        "drive=1",
        "--rpm",
        "100",
        "--duration",
        "0.01",
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        !out.status.success() && err.contains("--torque: the shaft of"),
        "{err}"
    );
}

/// A coast to rest: the unit of the breakaway test turning at 0.5 rad/s with
/// no input torque slows on its bearings' friction, and once its mean speed
/// reaches zero with no torque to break it away it sticks: every later
/// output is exactly zero speed (the sites' breakaway torque is taken where
/// the speed reaches or crosses zero).
#[test]
fn a_coasting_unit_sticks_at_rest() {
    let model = torque_driven_hydro(false);
    let h = 2e-3;
    let mut sim = Simulator::new(
        Rotor::new(model).unwrap(),
        SolverOptions {
            time_step: h,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    sim.set_speed(0.5, 0.0).unwrap();
    sim.settle_static().unwrap();
    let mut stopped = None;
    for n in 1..=2000 {
        let t = n as f64 * h;
        sim.advance_to(t).unwrap();
        let speed = sim.outputs().unwrap().speed;
        match stopped {
            None if speed == 0.0 => stopped = Some(t),
            None => assert!(speed > 0.0, "t = {t}: {speed} rad/s"),
            Some(_) => assert_eq!(speed, 0.0, "t = {t}"),
        }
    }
    let stopped = stopped.expect("the unit coasts to rest");
    println!("stopped at {stopped} s");
    assert!(stopped < 3.0, "{stopped}");
}
