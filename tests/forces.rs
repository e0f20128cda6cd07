//! Magnetic pull, external static and harmonic forces and force ports:
//! closed-form frequencies with pull, static instability, the steady
//! response to a harmonic force against the linear forced response, and the
//! energy balance of the external forces.

use nalgebra::{Complex, Matrix3, Vector3};

use rotor_bearing::analysis::forced::{forced_response, harmonic_force};
use rotor_bearing::analysis::linear::node_xy;
use rotor_bearing::analysis::linearize::linearized;
use rotor_bearing::analysis::modal::{ModalOptions, modes};
use rotor_bearing::model::{DEFAULT_MODEL_TOML, RotorModel};
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions, equilibrium};

const RPM: f64 = std::f64::consts::PI / 30.0;

/// A rigid rotor (one stiff element, end rotations held by supports) on two
/// linear bearings `k_b` (N/m), with `extra` appended: its translations
/// bounce with `m = ` the shaft's mass and nothing else.
fn rigid_rotor(k_b: f64, extra: &str) -> String {
    format!(
        r#"
name = "rigid"
[[materials]]
name = "steel"
youngs_modulus = 211e9
poisson_ratio = 0.3
density = 7810.0
[[shaft]]
length = 0.2
outer_diameter = 0.1
material = "steel"
elements = 1
[[bearings]]
name = "left"
type = "linear"
node = 1
kxx = {k_b:e}
kyy = {k_b:e}
[[bearings]]
name = "right"
type = "linear"
node = 2
kxx = {k_b:e}
kyy = {k_b:e}
[[supports]]
node = 1
fix = ["rx", "ry"]
[[supports]]
node = 2
fix = ["rx", "ry"]
{extra}
"#
    )
}

fn pulls(k_ump: f64) -> String {
    ["left", "right"]
        .iter()
        .enumerate()
        .map(|(k, name)| {
            format!(
                "[[magnetic_pull]]\nname = \"{name}_pull\"\nnode = {}\ngap = 0.01\nstiffness = {k_ump:e}\n",
                k + 1
            )
        })
        .collect()
}

fn rotor(text: &str) -> Rotor {
    Rotor::new(RotorModel::from_toml(text, "forces.toml").unwrap()).unwrap()
}

/// With a magnetic pull `k_ump` at each bearing the rigid rotor's bounce
/// frequency is `√(2 (k_b − k_ump)/m)` to 1e-9 (the pull linearized at the
/// centred rotor); its excitation scales the pull with its square; a pull
/// beyond the bearings is a static instability named by element and net
/// stiffness, in the statics, the simulator, `rotor modes` and the FMU's
/// `fmi2ExitInitializationMode`.
#[test]
fn magnetic_pull_lowers_the_frequency_and_past_the_bearings_diverges() {
    let k_b = 1e7;
    let m = 7810.0 * std::f64::consts::PI * 0.1f64.powi(2) / 4.0 * 0.2;
    let bounce = |text: &str| {
        let r = rotor(text);
        let linear = linearized(&r, 0.0, 0.0).unwrap();
        modes(
            &linear,
            0.0,
            &ModalOptions {
                modes: 2,
                target_frequency: 0.0,
            },
        )
        .unwrap()[0]
            .natural_frequency
    };
    for k_ump in [2e6, 6e6] {
        let want = (2.0 * (k_b - k_ump) / m).sqrt();
        let got = bounce(&rigid_rotor(k_b, &pulls(k_ump)));
        assert!(
            (got / want - 1.0).abs() < 1e-9,
            "k_ump = {k_ump}: {got} against {want} rad/s"
        );
    }
    // Half the field: a quarter of the pull.
    let half = rigid_rotor(
        k_b,
        &pulls(8e6).replace("stiffness = 8e6", "stiffness = 8e6\nexcitation = 0.5"),
    );
    let want = (2.0 * (k_b - 2e6) / m).sqrt();
    assert!((bounce(&half) / want - 1.0).abs() < 1e-9);

    let unstable = rigid_rotor(k_b, &pulls(1.5e7));
    let err = equilibrium(&rotor(&unstable), 0.0, &SolverOptions::default(), None)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("the net stiffness is -5000000 N/m")
            && err.contains("left_pull (-15000000 N/m), right_pull (-15000000 N/m)"),
        "{err}"
    );
    let mut sim = Simulator::new(rotor(&unstable), SolverOptions::default()).unwrap();
    assert!(sim.settle_static().is_err());
    let mut fmu = rotor_bearing::fmi2::instance::Instance::new(
        "pull",
        RotorModel::from_toml(&unstable, "forces.toml").unwrap(),
    )
    .unwrap();
    use rotor_bearing::fmi2::instance::Status;
    assert_eq!(fmu.setup_experiment(0.0, None), Status::Ok);
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    assert_eq!(fmu.exit_initialization_mode(), Status::Error);
    let messages: Vec<String> = fmu.drain_messages().into_iter().map(|m| m.2).collect();
    assert!(
        messages.iter().any(|m| m.contains("statically unstable")),
        "{messages:?}"
    );
}

/// Least-squares fit of `a cos ωt + b sin ωt + c`: the complex amplitude
/// `X = a − i b`, so that the signal is `Re(X e^{iωt}) + c`.
fn harmonic(ts: &[f64], xs: &[f64], omega: f64) -> Complex<f64> {
    let mut m = Matrix3::zeros();
    let mut r = Vector3::zeros();
    for (&t, &x) in ts.iter().zip(xs) {
        let v = Vector3::new((omega * t).cos(), (omega * t).sin(), 1.0);
        m += v * v.transpose();
        r += v * x;
    }
    let s = m.lu().solve(&r).unwrap();
    Complex::new(s[0], -s[1])
}

/// The damped classic rotor (bearings 4000 N·s/m, no unbalance) with a
/// harmonic force at the disk.
fn classic_with_force(force: &str) -> String {
    DEFAULT_MODEL_TOML
        .replace("kyy = 1e6\n", "kyy = 1e6\ncxx = 4000.0\ncyy = 4000.0\n")
        .replace("magnitude = 0.001", "magnitude = 0.0")
        + &format!(
            "\n[[forces]]\nname = \"excitation\"\nnode = 4\nmagnitude = 50.0\nphase_deg = 30.0\n{force}\n"
        )
}

/// A 0.3× forward harmonic force, a 0.3× backward one and a fixed-direction
/// one at 37 Hz on the linear rotor at 3000 rpm: once the start transient has
/// decayed the simulated disk orbit holds a line at the force's frequency
/// whose complex amplitude (x and y) equals the linear forced response to
/// 1e-6 of its size (Newmark's frequency error at 1e-5 s steps is 1e-7), and
/// the forward force whirls the disk forward, the backward one backward.
#[test]
fn harmonic_forces_give_the_linear_forced_response() {
    let speed = 3000.0 * RPM;
    for (force, omega) in [
        ("ratio = 0.3\ndirection = \"forward\"", 0.3 * speed),
        ("ratio = 0.3\ndirection = \"backward\"", 0.3 * speed),
        (
            "frequency_hz = 12.0\ndirection = \"fixed\"\nangle_deg = 60.0",
            12.0 * std::f64::consts::TAU,
        ),
    ] {
        let r = rotor(&classic_with_force(force));
        let index = harmonic_force(&r, "excitation").unwrap();
        let (w, exact) = forced_response(&r, index, speed).unwrap();
        assert!((w - omega).abs() < 1e-12 * omega);
        let (ex, ey) = node_xy(&exact, 3);
        let h = 1e-5;
        let mut sim = Simulator::new(
            r,
            SolverOptions {
                time_step: h,
                gravity: false,
                ..SolverOptions::default()
            },
        )
        .unwrap();
        sim.set_speed(speed, 0.0).unwrap();
        // The slowest mode decays as e^{-σt}, σ ≈ 5 /s: 4 s leaves e^{-20}.
        let settle = 4.0;
        for k in 1..=8 {
            sim.advance_to(settle * k as f64 / 8.0).unwrap();
        }
        let (mut ts, mut xs, mut ys) = (Vec::new(), Vec::new(), Vec::new());
        let period = std::f64::consts::TAU / omega;
        let samples = 4000;
        for k in 1..=samples {
            let t = settle + 10.0 * period * k as f64 / samples as f64;
            sim.advance_to(t).unwrap();
            let out = sim.outputs().unwrap();
            ts.push(t);
            xs.push(out.probes[0].x);
            ys.push(out.probes[0].y);
        }
        let (sx, sy) = (harmonic(&ts, &xs, omega), harmonic(&ts, &ys, omega));
        let size = ex.norm().max(ey.norm());
        let d = (sx - ex).norm().max((sy - ey).norm()) / size;
        assert!(
            d < 1e-6,
            "{force}: simulated ({sx}, {sy}) against linear ({ex}, {ey}): {d:e}"
        );
        let (f, b) = rotor_bearing::analysis::modal::orbit_radii(ex, ey);
        if force.contains("\"forward\"") {
            assert!(f > 10.0 * b, "forward force: r_f {f}, r_b {b}");
        } else if force.contains("\"backward\"") {
            assert!(b > 10.0 * f, "backward force: r_f {f}, r_b {b}");
        }
    }
}

/// `xᵀ A y` for a banded matrix.
fn quadratic(a: &rotor_bearing::linalg::BandMatrix<f64>, x: &[f64], y: &[f64]) -> f64 {
    let mut ay = vec![0.0; y.len()];
    a.mul_vec(y, &mut ay);
    x.iter().zip(&ay).map(|(p, q)| p * q).sum()
}

/// The work of a port force (ramped within each step, as
/// `fmi2SetRealInputDerivatives` gives it) and of a 0.3× harmonic force on
/// the linear rotor at 2000 rpm equals the change of its kinetic and
/// elastic energy plus the bearings' dissipation, to 1e-9 of the energy
/// exchanged — the trapezoidal rule's exact balance, so every load acts
/// where and when its law says.
#[test]
fn port_and_harmonic_forces_balance_the_energy() {
    let text = classic_with_force("ratio = 0.3\ndirection = \"forward\"")
        + "\n[[ports]]\nname = \"amb\"\nnode = 2\n";
    let model = RotorModel::from_toml(&text, "forces.toml").unwrap();
    let inputs = model.load_inputs();
    assert_eq!(
        inputs.iter().map(|l| l.name.as_str()).collect::<Vec<_>>(),
        [
            "forces.excitation.magnitude",
            "ports.amb.fx",
            "ports.amb.fy"
        ]
    );
    let r = Rotor::new(model).unwrap();
    let (mass, stiffness, damping) = (r.mass.clone(), r.stiffness.clone(), r.damping.clone());
    let disk = [r.dofs.free(3, 0).unwrap(), r.dofs.free(3, 1).unwrap()];
    let port = [r.dofs.free(1, 0).unwrap(), r.dofs.free(1, 1).unwrap()];
    let h = 2e-4;
    let mut sim = Simulator::new(
        r,
        SolverOptions {
            time_step: h,
            gravity: false,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    sim.set_speed(2000.0 * RPM, 0.0).unwrap();
    let force = |sim: &mut Simulator| {
        let t = sim.time();
        let out = sim.outputs().unwrap();
        let mut f = vec![0.0; sim.rotor().dof_count()];
        let (a, theta) = (50.0, 30f64.to_radians() + 0.3 * out.spin_angle);
        f[disk[0]] += a * theta.cos();
        f[disk[1]] += a * theta.sin();
        f[port[0]] += sim.load_at(1, t);
        f[port[1]] += sim.load_at(2, t);
        f
    };
    let energy = |s: &rotor_bearing::solver::SimState| {
        0.5 * quadratic(&mass, &s.ud, &s.ud) + 0.5 * quadratic(&stiffness, &s.u, &s.u)
    };
    sim.set_load(1, 0.0, 300.0).unwrap();
    sim.set_load(2, -25.0, 150.0).unwrap();
    // Start from accelerations that balance the loads at t = 0.
    sim.consistent_acceleration().unwrap();
    let (mut state, mut f) = (sim.state().clone(), force(&mut sim));
    let e0 = energy(&state);
    let (mut work, mut exchanged) = (0.0, 0.0);
    for n in 1..=2000 {
        if n % 100 == 0 {
            // New port inputs every 20 ms, ramped within the interval.
            let k = n as f64;
            sim.set_load(1, 40.0 * (0.01 * k).sin(), 300.0 * (0.02 * k).cos())
                .unwrap();
            sim.set_load(2, -25.0, 150.0).unwrap();
            // (The state at the step's start balances the loads before the
            // change: those are its f_n.)
        }
        sim.advance_to(n as f64 * h).unwrap();
        let next = sim.state().clone();
        let f1 = force(&mut sim);
        let v: Vec<f64> = state
            .ud
            .iter()
            .zip(&next.ud)
            .map(|(a, b)| 0.5 * (a + b))
            .collect();
        let external: f64 = next
            .u
            .iter()
            .zip(&state.u)
            .zip(f.iter().zip(&f1))
            .map(|((a, b), (p, q))| (a - b) * 0.5 * (p + q))
            .sum();
        let dissipated = h * quadratic(&damping, &v, &v);
        work += external - dissipated;
        exchanged += external.abs() + dissipated;
        state = next;
        f = f1;
    }
    let change = energy(&state) - e0;
    assert!(
        (change - work).abs() < 1e-9 * exchanged,
        "energy change {change:e} J against net work {work:e} J (exchanged {exchanged:e} J)"
    );
}

/// `rotor response --force NAME` writes the linear forced response the
/// library computes (every speed, the disk probe's x amplitude and phase, to
/// 1e-12), the force's frequency (0.3× the speed), and prints each point's
/// largest orbit with its speed; `--magnitude` scales the response
/// linearly; an unknown force is refused naming the harmonic ones.
#[test]
fn the_response_command_writes_the_linear_forced_response() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("response_cli");
    std::fs::create_dir_all(&dir).unwrap();
    let text = classic_with_force("ratio = 0.3\ndirection = \"forward\"");
    let (model, csv) = (dir.join("forced.toml"), dir.join("response.csv"));
    std::fs::write(&model, &text).unwrap();
    let run = |extra: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
            .arg("response")
            .arg(&model)
            .args([
                "--force",
                "excitation",
                "--min-rpm",
                "1000",
                "--max-rpm",
                "6000",
            ])
            .args(["--points", "11", "--csv"])
            .arg(&csv)
            .args(extra)
            .output()
            .unwrap()
    };
    let read = || -> Vec<Vec<f64>> {
        std::fs::read_to_string(&csv)
            .unwrap()
            .lines()
            .skip(1)
            .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
            .collect()
    };
    let out = run(&[]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let rows = read();
    let r = rotor(&text);
    let index = harmonic_force(&r, "excitation").unwrap();
    let mut largest = (0.0f64, 0.0);
    for row in &rows {
        let speed = row[1];
        let (omega, q) = forced_response(&r, index, speed).unwrap();
        assert!((row[2] - omega / std::f64::consts::TAU).abs() < 1e-12 * row[2]);
        assert!((omega - 0.3 * speed).abs() < 1e-12 * omega);
        let (x, _) = node_xy(&q, 3);
        assert!((row[3] - x.norm()).abs() <= 1e-12 * x.norm(), "{row:?}");
        assert!((row[4] - x.arg().to_degrees()).abs() < 1e-9, "{row:?}");
        if row[7] > largest.0 {
            largest = (row[7], row[0]);
        }
    }
    let stdout = String::from_utf8_lossy(&out.stdout);
    let line = stdout
        .lines()
        .find(|l| l.starts_with("probe disk"))
        .unwrap_or_else(|| panic!("{stdout}"));
    let cols: Vec<&str> = line.split_whitespace().collect();
    let printed: f64 = cols[2].parse().unwrap();
    assert!(
        (printed - largest.0 * 1e6).abs() <= 1e-5 * printed,
        "{line} vs {largest:?}"
    );
    assert_eq!(cols[3].parse::<f64>().unwrap(), largest.1);
    // Twice the amplitude, twice the response.
    assert!(run(&["--magnitude", "100"]).status.success());
    for (a, b) in rows.iter().zip(read()) {
        assert!((b[3] - 2.0 * a[3]).abs() <= 1e-12 * b[3]);
    }
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg("response")
        .arg(&model)
        .args(["--force", "rope", "--max-rpm", "3000"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        !out.status.success()
            && err.contains("has no harmonic force \"rope\" (its harmonic forces: excitation)"),
        "{err}"
    );
}
