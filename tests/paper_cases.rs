//! The paper's validation cases (§4) as shipped models, checked from the
//! simulated data: frequencies from full spectra, amplitude ratios from orbits.

use std::path::PathBuf;

use rotor_bearing::analysis::modal::{ModalOptions, Whirl, modes};
use rotor_bearing::analysis::spectrum::{frequency_grid, full_spectrum, peak_frequency};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Outputs, Simulator, SolverOptions, SpeedProfile, record};

const RPM: f64 = std::f64::consts::PI / 30.0;

fn model(name: &str) -> RotorModel {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("models")
        .join(format!("{name}.toml"));
    RotorModel::from_file(&path).unwrap()
}

fn run(
    model: RotorModel,
    options: SolverOptions,
    profile: &SpeedProfile,
    seconds: f64,
    dt_out: f64,
) -> Vec<Outputs> {
    let mut sim = Simulator::new(Rotor::new(model).unwrap(), options).unwrap();
    sim.set_speed(profile.at(0.0).0, 0.0).unwrap();
    sim.settle_static().unwrap();
    record(&mut sim, profile, seconds, dt_out, |_, _| {}).unwrap()
}

/// Orbit `(t, x, y)` of probe `k` over the records in `[from, to)`, relative to its mean.
fn probe(records: &[Outputs], k: usize, from: f64, to: f64) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let sel: Vec<&Outputs> = records
        .iter()
        .filter(|o| o.time >= from && o.time < to)
        .collect();
    let n = sel.len() as f64;
    let mx = sel.iter().map(|o| o.probes[k].x).sum::<f64>() / n;
    let my = sel.iter().map(|o| o.probes[k].y).sum::<f64>() / n;
    (
        sel.iter().map(|o| o.time).collect(),
        sel.iter().map(|o| o.probes[k].x - mx).collect(),
        sel.iter().map(|o| o.probes[k].y - my).collect(),
    )
}

/// Largest full-spectrum component at or above `lo` Hz and below `hi` Hz (forward whirl).
fn component(t: &[f64], x: &[f64], y: &[f64], lo: f64, hi: f64) -> (f64, f64) {
    let f = frequency_grid(lo, hi, 400);
    peak_frequency(&f, &full_spectrum(t, x, y, &f)).unwrap()
}

fn jeffcott(rpm: f64, seconds: f64) -> Vec<Outputs> {
    let opts = SolverOptions {
        time_step: 1e-4,
        ..SolverOptions::default()
    };
    run(
        model("jeffcott"),
        opts,
        &SpeedProfile::Constant(rpm * RPM),
        seconds,
        2e-4,
    )
}

#[test]
fn jeffcott_below_threshold_is_synchronous() {
    let r = jeffcott(6000.0, 1.0);
    let (t, x, y) = probe(&r, 0, 0.5, 1.0);
    let f_spin = 100.0;
    let (f1, a1) = component(&t, &x, &y, 0.8 * f_spin, 1.2 * f_spin);
    let (_, sub) = component(&t, &x, &y, 5.0, 0.8 * f_spin);
    assert!((f1 / f_spin - 1.0).abs() < 0.01, "1× at {f1} Hz");
    assert!(sub < 0.05 * a1, "sub-synchronous {sub:e} vs 1× {a1:e}");
}

#[test]
fn jeffcott_above_threshold_whirls_at_half_speed() {
    let rpm = 10_000.0;
    let r = jeffcott(rpm, 1.2);
    let (t, x, y) = probe(&r, 0, 0.8, 1.2);
    let f_spin = rpm / 60.0;
    let (f_sub, a_sub) = component(&t, &x, &y, 5.0, 0.8 * f_spin);
    let (_, a1) = component(&t, &x, &y, 0.9 * f_spin, 1.1 * f_spin);
    let ratio = f_sub / f_spin;
    eprintln!(
        "oil whirl at {rpm} rpm: {f_sub:.2} Hz = {ratio:.3}×, {:.1} µm vs 1× {:.2} µm",
        a_sub * 1e6,
        a1 * 1e6
    );
    assert!((0.45..0.52).contains(&ratio), "whirl ratio {ratio}");
    assert!(a_sub > 5.0 * a1, "the whirl dominates: {a_sub:e} vs {a1:e}");
}

#[test]
fn jeffcott_run_up_past_twice_critical_locks_to_natural_frequency() {
    // First natural frequency with stiff supports (a whipping journal runs near the
    // clearance, where the film is very stiff): the same shaft, pinned at the bearings.
    let mut pinned = model("jeffcott");
    let nodes: Vec<usize> = pinned.bearings.iter().map(|b| b.node).collect();
    pinned.bearings.clear();
    for node in nodes {
        pinned.supports.push(rotor_bearing::model::Support {
            node,
            fixed: [true, true, false, false],
        });
    }
    let speed = 15_000.0 * RPM;
    let ms = modes(
        &Rotor::new(pinned).unwrap(),
        speed,
        &ModalOptions {
            modes: 2,
            target_frequency: 0.0,
        },
    )
    .unwrap();
    let natural = ms
        .iter()
        .find(|m| m.whirl == Whirl::Forward)
        .unwrap()
        .damped_frequency
        / (2.0 * std::f64::consts::PI);

    let opts = SolverOptions {
        time_step: 1e-4,
        ..SolverOptions::default()
    };
    let profile = SpeedProfile::Ramp {
        from: 11_000.0 * RPM,
        to: 16_500.0 * RPM,
        duration: 3.0,
    };
    let r = run(model("jeffcott"), opts, &profile, 3.0, 2e-4);
    let mut freqs = Vec::new();
    for window in [(2.0, 2.5), (2.5, 3.0)] {
        let (t, x, y) = probe(&r, 0, window.0, window.1);
        let speed = r
            .iter()
            .filter(|o| o.time >= window.0 && o.time < window.1)
            .map(|o| o.speed)
            .sum::<f64>()
            / t.len() as f64;
        let f_spin = speed / (2.0 * std::f64::consts::PI);
        let (f, _) = component(&t, &x, &y, 5.0, 0.8 * f_spin);
        eprintln!(
            "oil whip at {:.0} rpm: {f:.2} Hz = {:.3}× (first natural frequency {natural:.2} Hz)",
            speed / RPM,
            f / f_spin
        );
        assert!(f / f_spin < 0.45, "no longer half speed: {}", f / f_spin);
        assert!(
            (f / natural - 1.0).abs() < 0.03,
            "whip {f} Hz vs natural {natural} Hz"
        );
        freqs.push(f);
    }
    // Locked: the speed rose 9% between the windows, the whip frequency hardly moved.
    assert!((freqs[1] / freqs[0] - 1.0).abs() < 0.01, "{freqs:?}");
}

fn vertical(speed: f64, dt: f64, seconds: f64) -> Vec<Outputs> {
    let opts = SolverOptions {
        time_step: dt,
        unbalance_ramp_time: 1.0,
        ..SolverOptions::default()
    };
    run(
        model("vertical_rotor"),
        opts,
        &SpeedProfile::Constant(speed),
        seconds,
        2e-3,
    )
}

/// Lima's vertical rotor at 30 and 100 rad/s: the paper's Δt = 2 ms works and
/// gives the orbits of a 10× smaller step; at 100 rad/s the unloaded bearing whirls
/// at half speed inside the clearance.
#[test]
fn vertical_rotor_with_the_papers_large_step() {
    for (speed, seconds) in [(30.0, 10.0), (100.0, 10.0)] {
        let coarse = vertical(speed, 2e-3, seconds);
        let fine = vertical(speed, 2e-4, seconds);
        let peak = |r: &[Outputs]| {
            r.iter()
                .filter(|o| o.time > seconds - 2.0)
                .map(|o| o.probes[0].x.hypot(o.probes[0].y))
                .fold(0.0, f64::max)
        };
        let (pc, pf) = (peak(&coarse), peak(&fine));
        eprintln!(
            "vertical rotor at {speed} rad/s: bearing orbit radius {:.3} µm (Δt 2 ms) vs {:.3} µm (0.2 ms)",
            pc * 1e6,
            pf * 1e6
        );
        assert!(
            (pc / pf - 1.0).abs() < 0.02,
            "Δt = 2 ms: {pc:e} vs 0.2 ms: {pf:e}"
        );
        let ecc = coarse
            .iter()
            .map(|o| o.bearings[0].report.eccentricity)
            .fold(0.0, f64::max);
        assert!(ecc < 1.0, "journal inside the clearance, ε = {ecc}");
        if speed == 100.0 {
            let (t, x, y) = probe(&coarse, 0, seconds - 4.0, seconds);
            let f_spin = speed / (2.0 * std::f64::consts::PI);
            let (f, _) = component(&t, &x, &y, 0.1, 0.9 * f_spin);
            assert!((f / f_spin - 0.5).abs() < 0.01, "whirl at {}×", f / f_spin);
        }
    }
}

/// The hydro unit at 150 rpm with 15 kg·m at the generator: on tilting pads the
/// response is synchronous (2.5 Hz); on plain bearings it is several times larger
/// with a sub-synchronous component near 1.25 Hz.
#[test]
fn hydro_unit_tilting_pad_versus_plain_bearings() {
    let opts = SolverOptions {
        time_step: 5e-3,
        unbalance_ramp_time: 2.0,
        ..SolverOptions::default()
    };
    let profile = SpeedProfile::Constant(150.0 * RPM);
    let tp = run(model("hydro_unit"), opts, &profile, 40.0, 5e-3);
    let plain = run(model("hydro_unit_plain"), opts, &profile, 40.0, 5e-3);
    for k in 0..3 {
        let (t, x, y) = probe(&tp, k, 20.0, 40.0);
        let (f1, a1) = component(&t, &x, &y, 2.0, 3.0);
        let (_, sub) = component(&t, &x, &y, 0.3, 2.0);
        assert!((f1 - 2.5).abs() < 0.02, "TP pickup {}: 1× at {f1}", k + 1);
        assert!(
            sub < 0.05 * a1,
            "TP pickup {}: sub-synchronous {sub:e} vs {a1:e}",
            k + 1
        );
        let (t, x, y) = probe(&plain, k, 20.0, 40.0);
        let (fs, a_sub) = component(&t, &x, &y, 0.3, 2.0);
        assert!(
            (fs - 1.25).abs() < 0.05,
            "plain pickup {}: sub-synchronous at {fs} Hz",
            k + 1
        );
        let radius = |r: &[Outputs]| {
            r.iter()
                .filter(|o| o.time > 20.0)
                .map(|o| o.probes[k].x.hypot(o.probes[k].y))
                .fold(0.0, f64::max)
        };
        let (r_tp, r_plain) = (radius(&tp), radius(&plain));
        eprintln!(
            "hydro pickup {}: TP orbit {:.2} µm (1×), plain {:.1} µm with {:.1} µm at {fs:.3} Hz",
            k + 1,
            r_tp * 1e6,
            r_plain * 1e6,
            a_sub * 1e6
        );
        assert!(
            r_plain > 3.0 * r_tp,
            "plain orbit {r_plain:e} vs TP {r_tp:e}"
        );
    }
}
