//! Acceptance 2 of issue 49, its dynamic half: the rotor on three plain
//! (short-film) bearings of `tests/alignment.rs`, the middle bearing lowered
//! until it (nearly) carries nothing. The linear stability threshold speed at
//! the equilibrium the line statics find at each speed — the speed where the
//! least-damped forward mode of the rotor linearized there
//! ([`linearized`], [`least_stable_forward`]) has zero log decrement,
//! bracketed and refined by bisection — against the whirl onset of the
//! nonlinear transient (Newmark + Newton on the films), measured as in
//! `tests/finite_film_whirl.rs`: constant-speed runs 3 % below and above the
//! threshold, each kicked off its static equilibrium, the growth rate of the
//! whirl fitted to the logarithm of its peaks, the onset the zero of the
//! growth rate interpolated between the two.

use rotor_bearing::analysis::alignment::alignment;
use rotor_bearing::analysis::linearize::linearized;
use rotor_bearing::analysis::stability::least_stable_forward;
use rotor_bearing::solver::{Simulator, SolverOptions};

#[path = "common/film_line.rs"]
mod film_line;
use film_line::line;

/// Static loads (N) of the three bearings at `speed` (rad/s).
fn loads(middle: f64, speed: f64) -> Vec<f64> {
    alignment(&line(middle), speed, &SolverOptions::default())
        .unwrap()
        .loads()
}

/// The elevation (m) of the middle bearing at which it carries `target` (N)
/// at `speed`: Newton on the influence matrix' diagonal, step held to 20 µm.
fn elevation_for(target: f64, speed: f64) -> f64 {
    let mut elevation = 0.0;
    for _ in 0..40 {
        let a = alignment(&line(elevation), speed, &SolverOptions::default()).unwrap();
        let r = a.loads()[1] - target;
        if r.abs() < 1e-6 {
            return elevation;
        }
        elevation -= (r / a.load_influence()[(1, 1)]).clamp(-2e-5, 2e-5);
    }
    panic!("no elevation found for {target} N");
}

/// Growth rate (1/s) of the least stable forward mode of the line
/// linearized at its static equilibrium at `speed` (rad/s).
fn linear_growth(middle: f64, speed: f64) -> f64 {
    let rotor = line(middle);
    let linear = linearized(&rotor, speed, speed).unwrap();
    least_stable_forward(&linear, speed, 8)
        .unwrap()
        .eigenvalue
        .re
}

/// The speed (rad/s) where [`linear_growth`] crosses zero: a scan in steps
/// of 10 % from `from`, then bisection to 1e-6.
fn linear_threshold(middle: f64, from: f64) -> f64 {
    let mut lo = from;
    assert!(
        linear_growth(middle, lo) < 0.0,
        "unstable at {lo} rad/s already"
    );
    let mut hi = lo * 1.1;
    while linear_growth(middle, hi) < 0.0 {
        lo = hi;
        hi *= 1.1;
        assert!(hi < 1e4, "stable up to 1e4 rad/s");
    }
    while hi - lo > 1e-6 * hi {
        let mid = 0.5 * (lo + hi);
        if linear_growth(middle, mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Growth rate (1/s) of a small whirl in the nonlinear transient at `speed`
/// and the three journals' peak deviations from equilibrium over the last
/// window, as fractions of the clearance.
fn transient_growth(middle: f64, speed: f64, seconds: f64) -> (f64, [f64; 3]) {
    let mut sim = Simulator::new(
        line(middle),
        SolverOptions {
            time_step: 1e-4,
            ..SolverOptions::default()
        },
    )
    .unwrap();
    sim.set_speed(speed, 0.0).unwrap();
    sim.settle_static().unwrap();
    let eq = sim.outputs().unwrap().bearings;
    let mut st = sim.state().clone();
    for (i, v) in st.ud.iter_mut().enumerate() {
        if sim.rotor().dofs.full(i) % 4 == 0 {
            *v = 2e-4;
        }
    }
    sim.set_state(st).unwrap();
    sim.consistent_acceleration().unwrap();
    let window = 2.0 * 2.0 * std::f64::consts::PI / (0.5 * speed);
    let dt = 2.5e-4;
    let mut peaks: Vec<(f64, f64)> = Vec::new();
    let (mut start, mut peak) = (0.0, [0.0f64; 3]);
    let mut last = [0.0; 3];
    let mut k = 0;
    while sim.time() < seconds {
        k += 1;
        sim.advance_to(k as f64 * dt).unwrap();
        let o = sim.outputs().unwrap();
        for b in 0..3 {
            let d = (o.bearings[b].x - eq[b].x).hypot(o.bearings[b].y - eq[b].y);
            peak[b] = peak[b].max(d);
        }
        if o.time - start >= window {
            let total = peak.iter().map(|p| p * p).sum::<f64>().sqrt();
            peaks.push((start + 0.5 * window, total.ln()));
            last = peak.map(|p| p / 80e-6);
            start = o.time;
            peak = [0.0; 3];
        }
    }
    let tail: Vec<(f64, f64)> = peaks
        .iter()
        .copied()
        .filter(|(t, _)| *t > 0.5 * seconds)
        .collect();
    let n = tail.len() as f64;
    let (mt, my) = tail
        .iter()
        .fold((0.0, 0.0), |(a, b), (t, y)| (a + t / n, b + y / n));
    let (sxy, sxx) = tail.iter().fold((0.0, 0.0), |(a, b), (t, y)| {
        (a + (t - mt) * (y - my), b + (t - mt) * (t - mt))
    });
    (sxy / sxx, last)
}

/// The middle bearing's elevation (m) that unloads it at the linear
/// threshold speed, and that speed (rad/s): the threshold depends on the
/// elevation and the unloading elevation on the speed (the end journals
/// rise with it), so the two are iterated to a fixed point, 1e-6 of the
/// speed, started from the elevation that unloads it at 3000 rpm.
fn unloaded_at_threshold() -> (f64, f64) {
    let mut speed = 3000.0 * std::f64::consts::PI / 30.0;
    for _ in 0..20 {
        let elevation = elevation_for(0.0, speed);
        let threshold = linear_threshold(elevation, 50.0);
        if (threshold - speed).abs() < 1e-6 * threshold {
            return (elevation, threshold);
        }
        speed = threshold;
    }
    panic!("no fixed point of elevation and threshold");
}

/// The middle bearing lowered until it carries nothing at the threshold
/// speed (its residual load below 1e-6 of the weight): the transient's whirl
/// onset, the zero of its growth rate interpolated between 3 % below and
/// 3 % above the linear threshold, equals that threshold within 1 % (the
/// issue's acceptance; measured 0.07 %), the transient's growth rates have
/// the linear ones' signs, and the orbit that grows is the unloaded middle
/// journal's (its peak deviation at the end of the run above three times
/// either end journal's). Aligned (no offset) the middle carries the most
/// load and the threshold is higher (measured 863 against 594 rad/s):
/// at 1.03 × the unloaded threshold the aligned line's kick dies out.
#[test]
fn the_unloaded_middle_bearing_whirls_at_the_linear_threshold() {
    let (elevation, threshold) = unloaded_at_threshold();
    let at = loads(elevation, threshold);
    let weight: f64 = at.iter().sum();
    assert!(at[1].abs() < 1e-6 * weight, "middle carries {} N", at[1]);
    let (below, above) = (0.97 * threshold, 1.03 * threshold);
    let ((g_below, _), (g_above, orbits)) = (
        transient_growth(elevation, below, 1.2),
        transient_growth(elevation, above, 1.2),
    );
    let (l_below, l_above) = (
        linear_growth(elevation, below),
        linear_growth(elevation, above),
    );
    let onset = below + (above - below) * (-g_below) / (g_above - g_below);
    let error = (onset - threshold) / threshold;
    let aligned = linear_threshold(0.0, 50.0);
    let (_, aligned_orbits) = transient_growth(0.0, above, 1.2);
    println!(
        "middle lowered {:.2} µm (load {:.1e} N; ends {:.3} and {:.3} N): linear threshold \
         {threshold:.3} rad/s; growth rate at 0.97×: transient {g_below:.3} 1/s, linear \
         {l_below:.3} 1/s; at 1.03×: transient {g_above:.3} 1/s, linear {l_above:.3} 1/s; \
         transient onset {onset:.3} rad/s ({:+.3} %); orbits at the end of the 1.03× run \
         (left, middle, right, fractions of C) {orbits:.3?}; aligned threshold {aligned:.3} rad/s, \
         its orbits at 1.03× the unloaded threshold {aligned_orbits:?}",
        -elevation * 1e6,
        at[1],
        at[0],
        at[2],
        100.0 * error
    );
    assert!(g_below < 0.0 && g_above > 0.0, "{g_below} {g_above}");
    assert!(l_below < 0.0 && l_above > 0.0, "{l_below} {l_above}");
    assert!(error.abs() < 0.01, "{error}");
    assert!(
        orbits[1] > 3.0 * orbits[0] && orbits[1] > 3.0 * orbits[2],
        "{orbits:?}"
    );
    assert!(aligned > 1.2 * threshold, "{aligned} vs {threshold}");
    assert!(
        aligned_orbits.iter().all(|&o| o < 1e-6),
        "{aligned_orbits:?}"
    );
}
