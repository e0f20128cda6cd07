//! Spectra of simulated orbits.
//!
//! The *full spectrum* of an orbit treats `z = x + i y` as one complex signal:
//! positive frequencies are forward whirl (in the spin direction), negative ones
//! backward whirl. Amplitudes are Hann-windowed DFTs evaluated at any set of
//! frequencies (no power-of-two restriction), scaled so that a circular orbit of
//! radius `r` at frequency `f` shows a peak of height `r`.

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

/// The frequency (Hz) of the largest amplitude of `spectrum` over `freqs`,
/// refined by a parabola through the peak and its neighbours.
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
}
