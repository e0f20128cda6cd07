//! Spectra of simulated orbits.
//!
//! The *full spectrum* of an orbit treats `z = x + i y` as one complex signal:
//! positive frequencies are forward whirl (in the spin direction), negative ones
//! backward whirl. Amplitudes are Hann-windowed DFTs evaluated at any set of
//! frequencies (no power-of-two restriction), scaled so that a circular orbit of
//! radius `r` at frequency `f` shows a peak of height `r`.
//!
//! ```
//! use std::f64::consts::PI;
//! use rotor_bearing::analysis::spectrum::{frequency_grid, full_spectrum, peak_frequency};
//!
//! // A forward circular orbit of radius 10 µm at 25 Hz, sampled at 1 kHz for 2 s.
//! let t: Vec<f64> = (0..2000).map(|k| k as f64 * 1e-3).collect();
//! let x: Vec<f64> = t.iter().map(|t| 1e-5 * (2.0 * PI * 25.0 * t).cos()).collect();
//! let y: Vec<f64> = t.iter().map(|t| 1e-5 * (2.0 * PI * 25.0 * t).sin()).collect();
//! let freqs = frequency_grid(-50.0, 50.0, 401);
//! let amplitudes = full_spectrum(&t, &x, &y, &freqs);
//! let (f, a) = peak_frequency(&freqs, &amplitudes).unwrap();
//! assert!((f - 25.0).abs() < 0.01); // forward: positive frequency
//! assert!((a - 1e-5).abs() < 1e-7); // the orbit radius
//! ```

use std::f64::consts::PI;

use nalgebra::Complex;

/// Full-spectrum amplitude (m) of the orbit `(x, y)` sampled at uniform times
/// `t`, at each frequency of `freqs` (Hz, signed: positive = forward).
pub fn full_spectrum(t: &[f64], x: &[f64], y: &[f64], freqs: &[f64]) -> Vec<f64> {
    let n = t.len().min(x.len()).min(y.len());
    if n < 2 {
        return vec![0.0; freqs.len()];
    }
    let mean_x = x[..n].iter().sum::<f64>() / n as f64;
    let mean_y = y[..n].iter().sum::<f64>() / n as f64;
    let window: Vec<f64> = (0..n)
        .map(|k| 0.5 - 0.5 * (2.0 * PI * k as f64 / (n - 1) as f64).cos())
        .collect();
    let gain: f64 = window.iter().sum();
    freqs
        .iter()
        .map(|&f| {
            let w = -2.0 * PI * f;
            let mut acc = Complex::new(0.0, 0.0);
            for k in 0..n {
                let z = Complex::new(x[k] - mean_x, y[k] - mean_y);
                acc += z * window[k] * Complex::from_polar(1.0, w * (t[k] - t[0]));
            }
            acc.norm() / gain
        })
        .collect()
}

/// Amplitude (m) of a real signal `x` at each frequency (Hz, ≥ 0).
pub fn amplitude_spectrum(t: &[f64], x: &[f64], freqs: &[f64]) -> Vec<f64> {
    let zeros = vec![0.0; x.len()];
    // A real cosine of amplitude a is two counter-rotating circles of radius a/2.
    full_spectrum(t, x, &zeros, freqs)
        .into_iter()
        .map(|a| 2.0 * a)
        .collect()
}

/// The frequency (Hz) and amplitude of the largest amplitude of `spectrum` over
/// `freqs`, refined by a parabola through the peak and its neighbours: on a
/// grid finer than the record's resolution `1/T`, the frequency error is a
/// small fraction of the grid spacing. `None` for an empty spectrum.
pub fn peak_frequency(freqs: &[f64], spectrum: &[f64]) -> Option<(f64, f64)> {
    let (i, &a) = spectrum
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(b.1))?;
    if i == 0 || i + 1 >= spectrum.len() {
        return Some((freqs[i], a));
    }
    let (l, r) = (spectrum[i - 1], spectrum[i + 1]);
    let denom = l - 2.0 * a + r;
    let shift = if denom.abs() > 0.0 {
        0.5 * (l - r) / denom
    } else {
        0.0
    };
    let df = freqs[i + 1] - freqs[i];
    Some((freqs[i] + shift.clamp(-1.0, 1.0) * df, a))
}

/// `count` evenly spaced frequencies from `from` to `to` (Hz).
pub fn frequency_grid(from: f64, to: f64, count: usize) -> Vec<f64> {
    let count = count.max(2);
    (0..count)
        .map(|k| from + (to - from) * k as f64 / (count - 1) as f64)
        .collect()
}

/// A display frequency `f` (Hz) clamped to at least 1 Hz and at most the
/// Nyquist frequency `1 / (2 dt)` of the sampling interval `dt` (s).
pub fn band_limit(f: f64, dt: f64) -> f64 {
    f.max(1.0).min(0.5 / dt)
}

/// Number of frequencies of a [`waterfall`]'s grid.
pub const WATERFALL_FREQUENCIES: usize = 801;

/// One window of a waterfall: the full spectrum of a stretch of the run.
#[derive(Debug, Clone, PartialEq)]
pub struct WaterfallRow {
    /// Mean spin speed over the window (rad/s).
    pub speed: f64,
    /// Full-spectrum amplitudes (m) on the waterfall's frequency grid.
    pub amplitudes: Vec<f64>,
    /// Dominant component: frequency (Hz, signed) and amplitude (m), from
    /// [`peak_frequency`].
    pub peak: Option<(f64, f64)>,
}

impl WaterfallRow {
    /// The dominant frequency as a multiple of the spin frequency, `2π f / Ω`.
    pub fn peak_order(&self) -> Option<f64> {
        self.peak.map(|(f, _)| f * 2.0 * PI / self.speed)
    }
}

/// Full spectra of consecutive windows of an orbit.
#[derive(Debug, Clone, PartialEq)]
pub struct Waterfall {
    /// Frequency grid (Hz, symmetric about zero).
    pub freqs: Vec<f64>,
    /// One row per window, in time order.
    pub rows: Vec<WaterfallRow>,
}

/// Waterfall of the orbit `(x, y)` (m) sampled every `dt` (s) at times `t` with
/// spin speed `speed` (rad/s) per sample: `min(40, n/64)` (at least one) equal
/// consecutive windows (a remainder at the end is dropped), each analysed by
/// [`full_spectrum`] on [`WATERFALL_FREQUENCIES`] frequencies spanning ±1.5 ×
/// the top spin frequency (see [`band_limit`]).
pub fn waterfall(t: &[f64], x: &[f64], y: &[f64], speed: &[f64], dt: f64) -> Waterfall {
    let n = t.len().min(x.len()).min(y.len()).min(speed.len());
    let windows = 40.min(n / 64).max(1);
    let len = n / windows;
    let top_speed = speed[..n].iter().map(|w| w.abs()).fold(0.0, f64::max);
    let f_top = band_limit(1.5 * top_speed / (2.0 * PI), dt);
    let freqs = frequency_grid(-f_top, f_top, WATERFALL_FREQUENCIES);
    let rows = (0..windows)
        .map(|w| {
            let r = w * len..(w + 1) * len;
            let amplitudes = full_spectrum(&t[r.clone()], &x[r.clone()], &y[r.clone()], &freqs);
            let speed = speed[r].iter().sum::<f64>() / len as f64;
            let peak = peak_frequency(&freqs, &amplitudes);
            WaterfallRow {
                speed,
                amplitudes,
                peak,
            }
        })
        .collect();
    Waterfall { freqs, rows }
}

#[cfg(test)]
mod tests {
    use super::*;

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
    fn band_limit_clamps_to_one_hertz_and_nyquist() {
        assert_eq!(band_limit(0.2, 1e-3), 1.0);
        assert_eq!(band_limit(120.0, 1e-3), 120.0);
        assert_eq!(band_limit(900.0, 1e-3), 500.0);
    }

    #[test]
    fn waterfall_follows_a_speed_step() {
        // 2 s at 2 kHz: synchronous forward circle, spin 20 Hz then 40 Hz.
        let dt = 5e-4;
        let t: Vec<f64> = (0..4000).map(|k| k as f64 * dt).collect();
        let speed: Vec<f64> = t
            .iter()
            .map(|&t| 2.0 * PI * if t < 1.0 { 20.0 } else { 40.0 })
            .collect();
        let mut angle = 0.0;
        let (mut x, mut y) = (Vec::new(), Vec::new());
        for w in &speed {
            x.push(1e-5 * f64::cos(angle));
            y.push(1e-5 * f64::sin(angle));
            angle += w * dt;
        }
        let wf = waterfall(&t, &x, &y, &speed, dt);
        assert_eq!(wf.rows.len(), 40);
        assert_eq!(wf.freqs.len(), WATERFALL_FREQUENCIES);
        assert!((wf.freqs[WATERFALL_FREQUENCIES - 1] - 60.0).abs() < 1e-9);
        let spacing = wf.freqs[1] - wf.freqs[0];
        for (k, row) in wf.rows.iter().enumerate() {
            let f_spin = if k < 20 { 20.0 } else { 40.0 };
            assert!((row.speed - 2.0 * PI * f_spin).abs() < 1e-9, "{k}");
            let (f, _) = row.peak.unwrap();
            assert!((f - f_spin).abs() < spacing, "window {k}: {f} Hz");
            assert!((row.peak_order().unwrap() - 1.0).abs() < 0.02, "{k}");
        }
    }
}
