//! Unit tests of `analysis::spectrum` (the parent module's `mod tests`).

use super::*;

/// Samples `0, dt, …` up to `duration` (s), not a power of two in length.
fn times(duration: f64, dt: f64) -> Vec<f64> {
    (0..=(duration / dt).round() as usize)
        .map(|k| k as f64 * dt)
        .collect()
}

/// A synchronous elliptical orbit at constant `speed` (rad/s): forward
/// circle 10 µm, backward circle 3 µm, offset (−4, 7) µm.
fn synchronous(t: &[f64], speed: f64) -> (Vec<f64>, Vec<f64>) {
    t.iter()
        .map(|t| {
            let p = speed * t + 0.3;
            (
                -4e-6 + 1e-5 * p.cos() + 3e-6 * (-p).cos(),
                7e-6 + 1e-5 * p.sin() + 3e-6 * (-p).sin(),
            )
        })
        .unzip()
}

#[test]
fn forward_and_backward_circles_are_told_apart() {
    let t: Vec<f64> = (0..4000).map(|k| k as f64 * 1e-3).collect();
    // Forward circle 2e-5 m at 10 Hz plus backward circle 5e-6 m at 4 Hz.
    let x: Vec<f64> = t
        .iter()
        .map(|t| 2e-5 * (2.0 * PI * 10.0 * t).cos() + 5e-6 * (2.0 * PI * 4.0 * t).cos())
        .collect();
    let y: Vec<f64> = t
        .iter()
        .map(|t| 2e-5 * (2.0 * PI * 10.0 * t).sin() - 5e-6 * (2.0 * PI * 4.0 * t).sin())
        .collect();
    let freqs = frequency_grid(-20.0, 20.0, 801);
    let s = full_spectrum(&t, &x, &y, &freqs);
    let (f, a) = peak_frequency(&freqs, &s).unwrap();
    assert!(
        (f - 10.0).abs() < 0.01 && (a - 2e-5).abs() < 1e-7,
        "{f} {a}"
    );
    let back: Vec<f64> = freqs
        .iter()
        .zip(&s)
        .filter(|(f, _)| **f < 0.0)
        .map(|(_, a)| *a)
        .collect();
    let neg: Vec<f64> = freqs.iter().copied().filter(|f| *f < 0.0).collect();
    let (fb, ab) = peak_frequency(&neg, &back).unwrap();
    assert!(
        (fb + 4.0).abs() < 0.01 && (ab - 5e-6).abs() < 1e-7,
        "{fb} {ab}"
    );
    let real = amplitude_spectrum(&t, &x, &frequency_grid(9.0, 11.0, 201));
    let peak = real.iter().fold(0.0f64, |a, b| a.max(*b));
    assert!((peak - 2e-5).abs() < 2e-7, "{peak}");
}

#[test]
fn peak_of_an_off_grid_sinusoid_within_a_tenth_of_the_grid_spacing() {
    // 4 s at 1 kHz: resolution 1/T = 0.25 Hz; grid spacing 0.05 Hz.
    let t: Vec<f64> = (0..4000).map(|k| k as f64 * 1e-3).collect();
    let x: Vec<f64> = t
        .iter()
        .map(|t| 3e-6 * (2.0 * PI * 7.37 * t + 0.4).cos())
        .collect();
    let freqs = frequency_grid(0.0, 20.0, 401);
    let spacing = freqs[1] - freqs[0];
    let s = amplitude_spectrum(&t, &x, &freqs);
    let (f, a) = peak_frequency(&freqs, &s).unwrap();
    assert!((f - 7.37).abs() < 0.1 * spacing, "{f}");
    assert!((a - 3e-6).abs() < 0.05 * 3e-6, "{a}");
    assert!(peak_frequency(&[], &[]).is_none());
}

#[test]
fn refined_fft_peak_within_a_thousandth_of_the_resolution() {
    // 1.37 s every 0.7 ms (1958 samples): resolution 1/T = 0.73 Hz. Circles
    // of radius 5 µm at frequencies a tenth of a bin apart, both directions.
    let (dt, n) = (7e-4, 1958);
    let t: Vec<f64> = (0..n).map(|k| k as f64 * dt).collect();
    let resolution = 1.0 / (n as f64 * dt);
    for k in 0..10 {
        for sign in [1.0, -1.0] {
            let f = sign * (31.0 + 0.1 * k as f64) * resolution;
            let (x, y): (Vec<f64>, Vec<f64>) = t
                .iter()
                .map(|t| {
                    let p = 2.0 * PI * f * t;
                    (5e-6 * p.cos(), 5e-6 * p.sin())
                })
                .unzip();
            let peak = Spectrum::new(&x, &y, dt, ZERO_PADDING * n).peak().unwrap();
            assert!(
                (peak.frequency - f).abs() < 1e-3 * resolution,
                "{f} Hz: {} Hz",
                peak.frequency
            );
            assert!(
                (peak.amplitude - 5e-6).abs() < 1e-3 * 5e-6,
                "{f} Hz: {peak:?}"
            );
        }
    }
    assert!(Spectrum::new(&[0.0; 8], &[0.0; 8], dt, 64).peak().is_none());
}

#[test]
fn pure_synchronous_response_is_one_times_running_speed_at_any_speed_and_length() {
    // (rpm, duration s, time step s): dyadic and non-dyadic lengths, 20.6 to 50 revolutions.
    for (rpm, duration, dt) in [
        (3000.0, 0.5, 1e-4),
        (3000.0, 1.0, 1e-4),
        (150.0, 8.25, 1e-3),
        (150.0, 12.0, 5e-3),
        (1234.0, 1.37, 7e-5),
        (9000.0, 0.137, 3e-5),
    ] {
        let speed = rpm * PI / 30.0;
        let t = times(duration, dt);
        let (x, y) = synchronous(&t, speed);
        let w = vec![speed; t.len()];
        let s = record_spectrum(&t, &x, &y, &w).unwrap();
        let order = s.order().unwrap();
        assert!(
            (order - 1.0).abs() < 1e-3,
            "{rpm} rpm {duration} s: {order}"
        );
        let amplitude = s.peak.unwrap().amplitude;
        assert!((amplitude - 1e-5).abs() < 2e-8, "{rpm} rpm: {amplitude}");
        let wf = waterfall(&t, &x, &y, &w, dt).unwrap();
        for row in &wf.rows {
            let order = row.peak_order().unwrap();
            assert!(
                (order - 1.0).abs() < 0.01,
                "{rpm} rpm {duration} s: {order}"
            );
            assert!(row.window.revolutions >= MIN_REVOLUTIONS, "{rpm}");
            assert!(row.window.subsynchronous_share < 1e-4, "{rpm}");
        }
    }
}

#[test]
fn half_speed_whirl_is_half_times_running_speed() {
    // 10 000 rpm for 0.2 s (33 revolutions): forward 0.5× whirl of 40 µm over a 1× of 10 µm.
    let speed = 10_000.0 * PI / 30.0;
    let t = times(0.2, 3e-5);
    let (x1, y1) = synchronous(&t, speed);
    let x: Vec<f64> = t
        .iter()
        .zip(&x1)
        .map(|(t, x)| x + 4e-5 * (0.5 * speed * t).cos())
        .collect();
    let y: Vec<f64> = t
        .iter()
        .zip(&y1)
        .map(|(t, y)| y + 4e-5 * (0.5 * speed * t).sin())
        .collect();
    let w = vec![speed; t.len()];
    let s = record_spectrum(&t, &x, &y, &w).unwrap();
    assert!((s.order().unwrap() - 0.5).abs() < 1e-3, "{:?}", s.order());
    // Energy 40² at 0.5× against 10² + 3² at ±1×.
    let expected = 1600.0 / (1600.0 + 100.0 + 9.0);
    assert!(
        (s.subsynchronous_share - expected).abs() < 2e-3,
        "{}",
        s.subsynchronous_share
    );
}

#[test]
fn subsynchronous_share_of_known_mixtures() {
    let speed_hz = 50.0;
    let t = times(0.6, 1e-4);
    let circle = |f: f64, r: f64| -> (Vec<f64>, Vec<f64>) {
        t.iter()
            .map(|t| (r * (2.0 * PI * f * t).cos(), r * (2.0 * PI * f * t).sin()))
            .unzip()
    };
    let (x1, y1) = circle(speed_hz, 1e-5);
    let (xh, yh) = circle(-0.4 * speed_hz, 1e-5);
    assert!(subsynchronous_share(&t, &x1, &y1, speed_hz) < 1e-4);
    assert!(subsynchronous_share(&t, &xh, &yh, speed_hz) > 1.0 - 1e-4);
    let x: Vec<f64> = x1.iter().zip(&xh).map(|(a, b)| a + b).collect();
    let y: Vec<f64> = y1.iter().zip(&yh).map(|(a, b)| a + b).collect();
    // Equal circles at 1× and at −0.4× (backward): half the energy each.
    let share = subsynchronous_share(&t, &x, &y, speed_hz);
    assert!((share - 0.5).abs() < 1e-3, "{share}");
    assert_eq!(
        subsynchronous_share(&t, &vec![1.0; t.len()], &vec![2.0; t.len()], 50.0),
        0.0
    );
}

#[test]
fn records_under_twenty_revolutions_are_refused() {
    // 3000 rpm for 0.39 s: 19.5 revolutions.
    let speed = 3000.0 * PI / 30.0;
    let t = times(0.39, 1e-4);
    let (x, y) = synchronous(&t, speed);
    let w = vec![speed; t.len()];
    let short = record_spectrum(&t, &x, &y, &w).unwrap_err();
    assert!((short.revolutions - 19.5).abs() < 1e-9, "{short:?}");
    assert_eq!(short.to_string(), "too short: 19.5 revolutions < 20");
    assert_eq!(waterfall(&t, &x, &y, &w, 1e-4).unwrap_err(), short);
    let almost = TooShort {
        revolutions: 19.97,
        needed: MIN_REVOLUTIONS,
    };
    assert_eq!(almost.to_string(), "too short: 19.9 revolutions < 20");
    // 1500 rpm for 0.8 s: 20 revolutions up to the round-off of the time steps.
    let slow = 1500.0 * PI / 30.0;
    let t20 = times(0.8, 1e-4);
    let (x20, y20) = synchronous(&t20, slow);
    let w20 = vec![slow; t20.len()];
    let s = record_spectrum(&t20, &x20, &y20, &w20).unwrap();
    assert!((s.revolutions - 20.0).abs() < 1e-9 && (s.order().unwrap() - 1.0).abs() < 1e-3);
    assert_eq!(
        waterfall(&t20, &x20, &y20, &w20, 1e-4).unwrap().rows.len(),
        1
    );
    let still = vec![0.0; t.len()];
    assert_eq!(
        record_spectrum(&t, &x, &y, &still).unwrap_err().revolutions,
        0.0
    );
}

#[test]
fn waterfall_windows_hold_twenty_revolutions_and_overlap_by_half() {
    // Constant 3000 rpm for 1 s: 50 revolutions, ⌈30/10⌉ + 1 = 4 windows.
    let speed = 3000.0 * PI / 30.0;
    let t = times(1.0, 1e-4);
    let (x, y) = synchronous(&t, speed);
    let w = vec![speed; t.len()];
    let wf = waterfall(&t, &x, &y, &w, 1e-4).unwrap();
    assert_eq!(wf.rows.len(), 4);
    assert_eq!(wf.freqs.len(), WATERFALL_FREQUENCIES);
    assert!((wf.freqs[WATERFALL_FREQUENCIES - 1] - 75.0).abs() < 1e-9);
    let starts: Vec<f64> = wf.rows.iter().map(|r| r.window.start).collect();
    for (k, s) in starts.iter().enumerate() {
        assert!((s - 0.2 * k as f64).abs() < 1.5e-4, "{starts:?}");
    }
    assert!((wf.rows[3].window.end - 1.0).abs() < 1e-12);
    for row in &wf.rows {
        assert!((row.window.revolutions - 20.0).abs() < 0.01, "{row:?}");
        let (_, a) = row.peak.unwrap();
        let shown = row.amplitudes.iter().fold(0.0f64, |m, v| m.max(*v));
        assert!(
            (a - 1e-5).abs() < 1e-8 && (shown - a).abs() < 1e-3 * a,
            "{a} {shown}"
        );
    }
    // Exactly 20 revolutions: one window, the whole run.
    let t = times(0.4, 1e-4);
    let (x, y) = synchronous(&t, speed);
    let wf = waterfall(&t, &x, &y, &w[..t.len()], 1e-4).unwrap();
    assert_eq!(wf.rows.len(), 1);
}

#[test]
fn ramp_windows_are_twenty_revolutions_so_slow_parts_last_longer() {
    // Run-up 600 → 6000 rpm over 2 s with a synchronous response.
    let dt = 1e-4;
    let t = times(2.0, dt);
    let speed: Vec<f64> = t.iter().map(|t| (600.0 + 2700.0 * t) * PI / 30.0).collect();
    let angle: Vec<f64> = t
        .iter()
        .map(|t| (600.0 * t + 1350.0 * t * t) * PI / 30.0)
        .collect();
    let x: Vec<f64> = angle.iter().map(|p| 1e-5 * p.cos()).collect();
    let y: Vec<f64> = angle.iter().map(|p| 1e-5 * p.sin()).collect();
    let wf = waterfall(&t, &x, &y, &speed, dt).unwrap();
    // 110 revolutions: ⌈90/10⌉ + 1 = 10 windows.
    assert_eq!(wf.rows.len(), 10);
    let first = &wf.rows[0].window;
    let last = &wf.rows[9].window;
    assert!(first.end - first.start > 2.0 * (last.end - last.start));
    for row in &wf.rows {
        assert!(row.window.revolutions >= MIN_REVOLUTIONS);
        let order = row.peak_order().unwrap();
        assert!(
            (order - 1.0).abs() < 0.02,
            "{} rpm: {order}",
            row.speed * 30.0 / PI
        );
    }
    assert!(wf.rows.windows(2).all(|p| p[1].speed > p[0].speed));
}

#[test]
fn a_long_run_is_spread_over_at_most_sixty_windows() {
    // 3000 rpm for 20 s: 1000 revolutions.
    let speed = 3000.0 * PI / 30.0;
    let t = times(20.0, 1e-3);
    let (x, y) = synchronous(&t, speed);
    let w = vec![speed; t.len()];
    let wf = waterfall(&t, &x, &y, &w, 1e-3).unwrap();
    assert_eq!(wf.rows.len(), MAX_WINDOWS);
    assert!((wf.rows[MAX_WINDOWS - 1].window.end - 20.0).abs() < 1e-9);
}

#[test]
fn band_limit_clamps_to_one_hertz_and_nyquist() {
    assert_eq!(band_limit(0.2, 1e-3), 1.0);
    assert_eq!(band_limit(120.0, 1e-3), 120.0);
    assert_eq!(band_limit(900.0, 1e-3), 500.0);
}

#[test]
fn a_drifting_rest_position_leaves_no_line_at_zero_hertz() {
    // 50 Hz spin for 2 s (100 revolutions): a 2 µm 1× orbit and a 1 µm
    // 0.5× whirl about a centre drifting by 30 µm along a curve.
    let t: Vec<f64> = (0..8000).map(|k| k as f64 * 2.5e-4).collect();
    let angle: Vec<f64> = t.iter().map(|t| 2.0 * PI * 50.0 * t).collect();
    // The centre moves by 30 µm over about half a second in mid-record,
    // as a whip's orbit centre does.
    let drift = |t: f64| 15e-6 * ((t - 1.0) / 0.3).tanh();
    let orbit = |t: f64, phase: f64| {
        2e-6 * (2.0 * PI * 50.0 * t + phase).cos() + 1e-6 * (2.0 * PI * 25.0 * t + phase).cos()
    };
    let x: Vec<f64> = t.iter().map(|&t| drift(t) + orbit(t, 0.0)).collect();
    let y: Vec<f64> = t
        .iter()
        .map(|&t| -0.5 * drift(t) + orbit(t, -0.5 * PI))
        .collect();
    let freqs = frequency_grid(-80.0, 80.0, 1601);
    let raw = full_spectrum(&t, &x, &y, &freqs);
    let (xc, yc) = (
        about_moving_centre(&x, &angle),
        about_moving_centre(&y, &angle),
    );
    let clean = full_spectrum(&t, &xc, &yc, &freqs);
    let at = |s: &[f64], f0: f64| {
        freqs
            .iter()
            .zip(s)
            .filter(|(f, _)| (**f - f0).abs() <= 1.0)
            .map(|(_, a)| *a)
            .fold(0.0, f64::max)
    };
    // Below 2.5 Hz (0.05×): the drift's line (8.2 µm) stood four times
    // above the orbit before; after, a twentieth of that (0.40 µm,
    // the running mean's lag on the steepest part of the move); 1× and
    // 0.5× pass within 1 %.
    let low = |s: &[f64]| {
        freqs
            .iter()
            .zip(s)
            .filter(|(f, _)| f.abs() <= 2.5)
            .map(|(_, a)| *a)
            .fold(0.0, f64::max)
    };
    assert!(low(&raw) > 4.0 * 2e-6, "{}", low(&raw));
    assert!(low(&clean) < 0.05 * low(&raw), "{}", low(&clean));
    assert!(low(&clean) < 0.25 * 2e-6, "{}", low(&clean));
    assert!((at(&clean, 50.0) / at(&raw, 50.0) - 1.0).abs() < 0.01);
    assert!((at(&clean, 25.0) / at(&raw, 25.0) - 1.0).abs() < 0.01);
}
