//! Spectra of simulated orbits.
//!
//! The *full spectrum* of an orbit treats `z = x + i y` as one complex signal:
//! positive frequencies are forward whirl (in the spin direction), negative ones
//! backward whirl. Every spectrum here is one FFT (`rustfft`) of the record with
//! its mean removed, multiplied by a Hann window `w_k = ½ − ½ cos(2πk/(n−1))`
//! and zero-padded; amplitudes are `|Z(f)| / Σ w_k`, so that a circular orbit of
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
//!
//! **Order analysis.** A frequency is only reported as a multiple of the running
//! speed (an *order*, 1× for unbalance, ≈ 0.5× for oil whirl) from a record of
//! at least [`MIN_REVOLUTIONS`] revolutions: with the Hann window the resolution
//! is `1/T`, so 0.5× and 1× are then at least ten bins apart. A shorter record
//! is a [`TooShort`], never a number. [`record_spectrum`] analyses one record;
//! [`waterfall`] cuts a run into windows of [`MIN_REVOLUTIONS`] revolutions of
//! spin angle (so slow parts of a ramp get longer windows), overlapping by at
//! least half.
//!
//! ```
//! use std::f64::consts::PI;
//! use rotor_bearing::analysis::spectrum::record_spectrum;
//!
//! // Pure 1× response at 150 rpm (2.5 Hz), 10 s sampled every 3 ms: 25 revolutions.
//! let speed = 150.0 * PI / 30.0;
//! let t: Vec<f64> = (0..3334).map(|k| k as f64 * 3e-3).collect();
//! let x: Vec<f64> = t.iter().map(|t| 2e-5 * (speed * t).cos()).collect();
//! let y: Vec<f64> = t.iter().map(|t| 2e-5 * (speed * t).sin()).collect();
//! let w = vec![speed; t.len()];
//! let s = record_spectrum(&t, &x, &y, &w).unwrap();
//! assert!((s.order().unwrap() - 1.0).abs() < 1e-3);
//! // 4 s are only 10 revolutions: no ratio, a refusal that says why.
//! let short = record_spectrum(&t[..1335], &x[..1335], &y[..1335], &w[..1335]).unwrap_err();
//! assert_eq!(short.to_string(), "too short: 10.0 revolutions < 20");
//! ```

use std::f64::consts::PI;

use rustfft::FftPlanner;
use rustfft::num_complex::Complex;

/// Revolutions a record (or a waterfall window) must hold before a frequency is
/// reported as a multiple of the running speed: with a Hann window the
/// resolution is `1/T`, so 0.5× and 1× lie `MIN_REVOLUTIONS / 2` = 10 bins apart.
pub const MIN_REVOLUTIONS: f64 = 20.0;

/// The sub-synchronous band, in multiples of the running speed (both whirl
/// directions): see [`subsynchronous_share`].
pub const SUB_BAND: (f64, f64) = (0.05, 0.8);

/// Least zero-padding factor of the FFTs behind peaks and displayed spectra.
pub const ZERO_PADDING: usize = 8;

/// Largest number of windows of a [`waterfall`]; a longer run spreads them
/// further apart (they then overlap by less than half, or not at all).
pub const MAX_WINDOWS: usize = 60;

/// Number of frequencies of a [`waterfall`]'s display grid.
pub const WATERFALL_FREQUENCIES: usize = 801;

/// Largest FFT length used for display interpolation.
const MAX_FFT_LEN: usize = 1 << 21;

/// Hann window of length `n`, `½ − ½ cos(2πk/(n−1))` (NumPy's `hanning`).
fn hann(n: usize) -> Vec<f64> {
    if n == 1 {
        return vec![1.0];
    }
    (0..n)
        .map(|k| 0.5 - 0.5 * (2.0 * PI * k as f64 / (n - 1) as f64).cos())
        .collect()
}

/// The FFT of `len` points (`len ≥ n`, zero-padded) of the Hann-windowed orbit
/// `(x, y)` with its mean removed, divided by the window's sum.
fn windowed_fft(x: &[f64], y: &[f64], len: usize) -> Vec<Complex<f64>> {
    let n = x.len().min(y.len());
    let mut buffer = vec![Complex::new(0.0, 0.0); len.max(n)];
    if n == 0 {
        return buffer;
    }
    let mean_x = x[..n].iter().sum::<f64>() / n as f64;
    let mean_y = y[..n].iter().sum::<f64>() / n as f64;
    let window = hann(n);
    let gain: f64 = window.iter().sum();
    for k in 0..n {
        buffer[k] = Complex::new(x[k] - mean_x, y[k] - mean_y) * (window[k] / gain);
    }
    FftPlanner::new()
        .plan_fft_forward(buffer.len())
        .process(&mut buffer);
    buffer
}

/// A zero-padded full spectrum on its FFT grid: bin `j` of `len` is frequency
/// `k / (len·dt)` with `k ≡ j (mod len)` in `[−len/2, len/2)`.
#[derive(Debug, Clone, PartialEq)]
pub struct Spectrum {
    /// Sampling interval (s).
    pub dt: f64,
    /// Amplitude (m) per FFT bin, in FFT order.
    pub amplitudes: Vec<f64>,
}

impl Spectrum {
    /// The full spectrum of `(x, y)` sampled every `dt` (s), zero-padded to
    /// `len` points (at least the record length).
    pub fn new(x: &[f64], y: &[f64], dt: f64, len: usize) -> Self {
        let amplitudes = windowed_fft(x, y, len).iter().map(|c| c.norm()).collect();
        Self { dt, amplitudes }
    }

    /// Bin spacing (Hz).
    pub fn resolution(&self) -> f64 {
        1.0 / (self.amplitudes.len() as f64 * self.dt)
    }

    /// Amplitude at `f` (Hz, signed), linear between bins; frequencies alias
    /// into `[−1/(2dt), 1/(2dt))` as sampling folds them.
    pub fn at(&self, f: f64) -> f64 {
        let m = self.amplitudes.len();
        let p = f / self.resolution();
        let j = p.floor();
        let frac = p - j;
        let bin = |k: f64| self.amplitudes[(k as i64).rem_euclid(m as i64) as usize];
        (1.0 - frac) * bin(j) + frac * bin(j + 1.0)
    }

    /// The largest component: the top bin refined by a parabola through the
    /// logarithms of it and its neighbours. With the Hann window and at least
    /// [`ZERO_PADDING`]× padding the frequency is within 1e-3 of the record's
    /// resolution `1/T` and the amplitude within 0.1 % for an isolated sinusoid
    /// (unit test). `None` when the spectrum is zero.
    pub fn peak(&self) -> Option<Peak> {
        let m = self.amplitudes.len();
        let (j, &top) = self
            .amplitudes
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(b.1))?;
        if !(top > 0.0 && top.is_finite()) {
            return None;
        }
        let k = if j >= m.div_ceil(2) {
            j as f64 - m as f64
        } else {
            j as f64
        };
        let ln = |i: usize| self.amplitudes[i].max(f64::MIN_POSITIVE).ln();
        let (a, b, c) = (ln((j + m - 1) % m), ln(j), ln((j + 1) % m));
        let denom = a - 2.0 * b + c;
        let shift = if denom < 0.0 {
            (0.5 * (a - c) / denom).clamp(-0.5, 0.5)
        } else {
            0.0
        };
        Some(Peak {
            frequency: (k + shift) * self.resolution(),
            amplitude: (b - 0.25 * (a - c) * shift).exp(),
        })
    }
}

/// A spectral peak.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Peak {
    /// Frequency (Hz, signed: positive = forward whirl).
    pub frequency: f64,
    /// Amplitude (m): the radius of the circular component.
    pub amplitude: f64,
}

/// FFT length for a record of `n` samples every `dt` (s) shown on a grid of
/// spacing `spacing` (Hz): at least [`ZERO_PADDING`]`·n` and four bins per grid step.
fn padded_len(n: usize, dt: f64, spacing: f64) -> usize {
    let display = if spacing > 0.0 && dt > 0.0 {
        (4.0 / (dt * spacing)).ceil().min(MAX_FFT_LEN as f64) as usize
    } else {
        0
    };
    (ZERO_PADDING * n).max(display).max(1)
}

/// Sampling interval of uniform times `t` (s).
fn interval(t: &[f64]) -> f64 {
    match t.len() {
        0 | 1 => 1.0,
        n => (t[n - 1] - t[0]) / (n - 1) as f64,
    }
}

/// Full-spectrum amplitude (m) of the orbit `(x, y)` sampled at uniform times
/// `t`, at each frequency of `freqs` (Hz, signed: positive = forward):
/// interpolated from a zero-padded FFT with at least four bins per grid step.
pub fn full_spectrum(t: &[f64], x: &[f64], y: &[f64], freqs: &[f64]) -> Vec<f64> {
    let n = t.len().min(x.len()).min(y.len());
    if n < 2 {
        return vec![0.0; freqs.len()];
    }
    let dt = interval(&t[..n]);
    let spacing = freqs
        .windows(2)
        .map(|p| (p[1] - p[0]).abs())
        .filter(|s| *s > 0.0)
        .fold(f64::INFINITY, f64::min);
    let spacing = if spacing.is_finite() { spacing } else { 0.0 };
    let s = Spectrum::new(&x[..n], &y[..n], dt, padded_len(n, dt, spacing));
    freqs.iter().map(|&f| s.at(f)).collect()
}

/// Revolutions of the running mean [`about_moving_centre`] removes: its
/// transfer function `sinc(f·T)` is zero at every multiple of 1/20 of the
/// running speed (0.5×, 1×, … pass unchanged) and below 4 % between the
/// multiples of 0.05× above 0.45×.
pub const CENTRE_REVOLUTIONS: f64 = 20.0;

/// `v` less its running mean over [`CENTRE_REVOLUTIONS`] revolutions of
/// `spin_angle` (rad, monotone) centred on each sample (shortened at the
/// ends): the motion about the orbit's moving centre. The slow drift of a
/// journal's rest position over a run-up (the film's equilibrium moves with
/// speed, a whip shifts the orbit's centre) would otherwise stand in a
/// spectrum as a line at 0 Hz.
pub fn about_moving_centre(v: &[f64], spin_angle: &[f64]) -> Vec<f64> {
    let n = v.len().min(spin_angle.len());
    let half = 0.5 * CENTRE_REVOLUTIONS * 2.0 * PI;
    let mut prefix = vec![0.0; n + 1];
    for k in 0..n {
        prefix[k + 1] = prefix[k] + v[k];
    }
    let (mut lo, mut hi) = (0, 0);
    (0..n)
        .map(|k| {
            while spin_angle[lo] < spin_angle[k] - half {
                lo += 1;
            }
            while hi < n && spin_angle[hi] <= spin_angle[k] + half {
                hi += 1;
            }
            v[k] - (prefix[hi] - prefix[lo]) / (hi - lo) as f64
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

/// The sub-synchronous share of the orbit `(x, y)` at uniform times `t` (s)
/// running at `spin_hz` (Hz): the fraction of its spectral energy at
/// `|f|` in [`SUB_BAND`] × `spin_hz` (both whirl directions, band ends
/// included), between 0 and 1 (0 for a motionless orbit).
///
/// The spectrum is the unpadded `n`-point FFT of `z = x + i y`, mean removed,
/// Hann-windowed; its energy is the squared amplitude per bin without the
/// zero-frequency bin, at bin frequencies `k / (n·dt)` with
/// `dt = (t_last − t_first)/(n − 1)`. `system/sweep.py` (`whirl_metrics`)
/// computes the same number; a test feeds both the same orbit.
pub fn subsynchronous_share(t: &[f64], x: &[f64], y: &[f64], spin_hz: f64) -> f64 {
    let n = t.len().min(x.len()).min(y.len());
    if n < 2 {
        return 0.0;
    }
    let dt = interval(&t[..n]);
    let spectrum = windowed_fft(&x[..n], &y[..n], n);
    let step = 1.0 / (n as f64 * dt);
    let (lo, hi) = (SUB_BAND.0 * spin_hz.abs(), SUB_BAND.1 * spin_hz.abs());
    let (mut band, mut total) = (0.0, 0.0);
    for (j, c) in spectrum.iter().enumerate().skip(1) {
        let k = if j < n.div_ceil(2) {
            j as f64
        } else {
            j as f64 - n as f64
        };
        let f = (k * step).abs();
        let energy = c.norm_sqr();
        total += energy;
        if f >= lo && f <= hi {
            band += energy;
        }
    }
    if total > 0.0 { band / total } else { 0.0 }
}

/// A record too short for an order: it holds `revolutions` < `needed`
/// (displayed rounded down to 0.1, so 19.97 reads 19.9).
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("too short: {:.1} revolutions < {needed}", (revolutions * 10.0 + 1e-6).floor() / 10.0)]
pub struct TooShort {
    /// Revolutions of the shaft over the record.
    pub revolutions: f64,
    /// Revolutions an order needs ([`MIN_REVOLUTIONS`]).
    pub needed: f64,
}

/// Whether a record of `revolutions` is too short for an order: fewer than
/// [`MIN_REVOLUTIONS`], up to the round-off of summing time steps.
fn too_short(revolutions: f64) -> bool {
    revolutions < MIN_REVOLUTIONS * (1.0 - 1e-9)
}

/// Spin angle (rad) at each sample: the trapezoidal integral of `|speed|`.
fn spin_angle(t: &[f64], speed: &[f64]) -> Vec<f64> {
    let mut angle = Vec::with_capacity(t.len());
    let mut acc = 0.0;
    for k in 0..t.len() {
        if k > 0 {
            acc += 0.5 * (speed[k].abs() + speed[k - 1].abs()) * (t[k] - t[k - 1]);
        }
        angle.push(acc);
    }
    angle
}

/// Signed mean speed (rad/s) of samples `r`: trapezoidal integral over the time span.
fn mean_speed(t: &[f64], speed: &[f64], r: std::ops::Range<usize>) -> f64 {
    let (a, b) = (r.start, r.end - 1);
    if b <= a {
        return speed[a];
    }
    let integral: f64 = (a..b)
        .map(|k| 0.5 * (speed[k] + speed[k + 1]) * (t[k + 1] - t[k]))
        .sum();
    integral / (t[b] - t[a])
}

/// The spectrum of one record (or window) of a run, with its order.
#[derive(Debug, Clone, PartialEq)]
pub struct RecordSpectrum {
    /// Time of its first sample (s).
    pub start: f64,
    /// Time of its last sample (s).
    pub end: f64,
    /// Revolutions of the shaft over it.
    pub revolutions: f64,
    /// Mean spin speed (rad/s, signed).
    pub speed: f64,
    /// Dominant component, `None` for a motionless orbit.
    pub peak: Option<Peak>,
    /// [`subsynchronous_share`] at the mean spin speed.
    pub subsynchronous_share: f64,
    /// The zero-padded full spectrum.
    pub spectrum: Spectrum,
}

impl RecordSpectrum {
    /// The dominant frequency as a multiple of the spin frequency, `2π f / Ω`.
    pub fn order(&self) -> Option<f64> {
        self.peak.map(|p| p.frequency * 2.0 * PI / self.speed)
    }
}

/// Analyse samples `r` of a run (uniform times `t`, orbit `x`, `y`, spin speed
/// `speed` in rad/s and spin angle `angle` in rad per sample), zero-padded for
/// display on a grid of spacing `spacing` (Hz, 0 for none).
fn analyse(
    t: &[f64],
    x: &[f64],
    y: &[f64],
    speed: &[f64],
    angle: &[f64],
    r: std::ops::Range<usize>,
    spacing: f64,
) -> RecordSpectrum {
    let (a, b) = (r.start, r.end - 1);
    let dt = interval(&t[r.clone()]);
    let speed = mean_speed(t, speed, r.clone());
    let len = padded_len(r.len(), dt, spacing);
    let spectrum = Spectrum::new(&x[r.clone()], &y[r.clone()], dt, len);
    RecordSpectrum {
        start: t[a],
        end: t[b],
        revolutions: (angle[b] - angle[a]) / (2.0 * PI),
        speed,
        peak: spectrum.peak(),
        subsynchronous_share: subsynchronous_share(
            &t[r.clone()],
            &x[r.clone()],
            &y[r],
            speed / (2.0 * PI),
        ),
        spectrum,
    }
}

/// The spectrum and order of a whole record: the orbit `(x, y)` (m) at uniform
/// times `t` (s) with spin speed `speed` (rad/s) per sample. A record of fewer
/// than [`MIN_REVOLUTIONS`] revolutions is a [`TooShort`].
pub fn record_spectrum(
    t: &[f64],
    x: &[f64],
    y: &[f64],
    speed: &[f64],
) -> Result<RecordSpectrum, TooShort> {
    let n = t.len().min(x.len()).min(y.len()).min(speed.len());
    let angle = spin_angle(&t[..n], &speed[..n]);
    let revolutions = angle.last().copied().unwrap_or(0.0) / (2.0 * PI);
    if n < 2 || too_short(revolutions) {
        return Err(TooShort {
            revolutions,
            needed: MIN_REVOLUTIONS,
        });
    }
    Ok(analyse(t, x, y, speed, &angle, 0..n, 0.0))
}

/// Sample ranges of the waterfall windows of a run with spin angle `angle`
/// (rad, non-decreasing) of `revolutions` in all (≥ [`MIN_REVOLUTIONS`]):
/// windows of [`MIN_REVOLUTIONS`] revolutions from the first sample to the last,
/// as many as a hop of at most half a window needs (at most [`MAX_WINDOWS`]),
/// evenly spread. Each range runs from the last sample at or before its start
/// angle to the first at or after its end angle.
fn window_ranges(angle: &[f64], revolutions: f64) -> Vec<std::ops::Range<usize>> {
    let half = 0.5 * MIN_REVOLUTIONS;
    let extra = revolutions - MIN_REVOLUTIONS;
    let count = (((extra / half) - 1e-9).ceil().max(0.0) as usize + 1).min(MAX_WINDOWS);
    let hop = if count > 1 {
        extra / (count - 1) as f64
    } else {
        0.0
    };
    let n = angle.len();
    (0..count)
        .map(|w| {
            let from = 2.0 * PI * w as f64 * hop;
            let to = from + 2.0 * PI * MIN_REVOLUTIONS;
            let a = angle.partition_point(|&p| p <= from).saturating_sub(1);
            let b = if w + 1 == count {
                n - 1
            } else {
                angle.partition_point(|&p| p < to).min(n - 1)
            };
            a..b + 1
        })
        .collect()
}

/// One window of a waterfall: the full spectrum of a stretch of the run.
#[derive(Debug, Clone, PartialEq)]
pub struct WaterfallRow {
    /// Spectrum, peak, order and sub-synchronous share of the window.
    pub window: RecordSpectrum,
    /// Mean spin speed over the window (rad/s).
    pub speed: f64,
    /// Full-spectrum amplitudes (m) on the waterfall's frequency grid.
    pub amplitudes: Vec<f64>,
    /// Dominant component: frequency (Hz, signed) and amplitude (m).
    pub peak: Option<(f64, f64)>,
}

impl WaterfallRow {
    /// The dominant frequency as a multiple of the spin frequency, `2π f / Ω`.
    pub fn peak_order(&self) -> Option<f64> {
        self.window.order()
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
/// spin speed `speed` (rad/s) per sample.
///
/// Windows hold [`MIN_REVOLUTIONS`] revolutions of spin angle each (so their
/// duration follows the speed: a ramp's slow part gets longer windows); the
/// first starts with the run, the last ends with it, and consecutive ones
/// overlap by at least half a window (fewer than half when [`MAX_WINDOWS`]
/// would be exceeded). A constant-speed run of `R` revolutions has
/// `⌈(R − 20)/10⌉ + 1` windows. Each window is analysed as by
/// [`record_spectrum`] (Hann window, mean removed, zero-padded FFT, refined
/// peak) and shown on [`WATERFALL_FREQUENCIES`] frequencies spanning ±1.5 × the
/// top spin frequency (see [`band_limit`]). A run of fewer than
/// [`MIN_REVOLUTIONS`] revolutions is a [`TooShort`].
pub fn waterfall(
    t: &[f64],
    x: &[f64],
    y: &[f64],
    speed: &[f64],
    dt: f64,
) -> Result<Waterfall, TooShort> {
    let n = t.len().min(x.len()).min(y.len()).min(speed.len());
    let angle = spin_angle(&t[..n], &speed[..n]);
    let revolutions = angle.last().copied().unwrap_or(0.0) / (2.0 * PI);
    if n < 2 || too_short(revolutions) {
        return Err(TooShort {
            revolutions,
            needed: MIN_REVOLUTIONS,
        });
    }
    let top_speed = speed[..n].iter().map(|w| w.abs()).fold(0.0, f64::max);
    let f_top = band_limit(1.5 * top_speed / (2.0 * PI), dt);
    let freqs = frequency_grid(-f_top, f_top, WATERFALL_FREQUENCIES);
    let spacing = freqs[1] - freqs[0];
    let rows = window_ranges(&angle, revolutions)
        .into_iter()
        .map(|r| {
            let window = analyse(t, x, y, speed, &angle, r, spacing);
            WaterfallRow {
                speed: window.speed,
                amplitudes: freqs.iter().map(|&f| window.spectrum.at(f)).collect(),
                peak: window.peak.map(|p| (p.frequency, p.amplitude)),
                window,
            }
        })
        .collect();
    Ok(Waterfall { freqs, rows })
}

#[cfg(test)]
mod tests;
