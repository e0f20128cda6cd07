//! Campbell diagram (damped natural frequencies against spin speed) and critical
//! speeds, where a frequency branch meets an excitation line `ω = h·Ω`.
//!
//! A crossing by a mode with damping ratio `ζ ≥` [`OVERDAMPED_DAMPING_RATIO`]
//! is not a critical speed: the resonance amplification `1/(2ζ)` is at most 1,
//! so the response has no peak there (rigid-body modes on fluid films at low
//! speed cross the 1× line with ζ ≈ 0.8).

use crate::model::RotorModel;
use crate::rotor::Rotor;
use crate::units::RAD_S_TO_RPM;

/// Damping ratio from which a crossing of an excitation line is overdamped,
/// not a critical speed: the amplification `1/(2ζ)` is at most 1.
pub const OVERDAMPED_DAMPING_RATIO: f64 = 0.5;

/// Top speed (rpm) of a Campbell diagram of a model that states neither
/// `max_speed_rpm` nor `speed_rpm`.
pub const FALLBACK_TOP_RPM: f64 = 4000.0;

/// Start of the speed grid of a model with fluid-film bearings, as a fraction
/// of the top speed: a film carries load only when turning.
pub const FILM_START_FRACTION: f64 = 0.01;

/// Default top speed (rad/s) of a Campbell diagram of `model`: 1.25 × its
/// `max_speed_rpm` when the file states it, else 1.25 × its `speed_rpm` when
/// not zero, else [`FALLBACK_TOP_RPM`].
pub fn default_top_speed(model: &RotorModel) -> f64 {
    if model.max_speed_stated {
        1.25 * model.max_speed
    } else if model.nominal_speed != 0.0 {
        1.25 * model.nominal_speed.abs()
    } else {
        FALLBACK_TOP_RPM / RAD_S_TO_RPM
    }
}

/// The `steps + 1` speeds (rad/s) of a Campbell diagram up to `top` (rad/s):
/// evenly spaced from 0 for linear bearings, from [`FILM_START_FRACTION`] ×
/// `top` when the rotor has fluid-film bearings.
pub fn speed_grid(rotor: &Rotor, top: f64, steps: usize) -> Vec<f64> {
    let first = if rotor.nonlinear_bearings.is_empty() {
        0.0
    } else {
        FILM_START_FRACTION * top
    };
    let steps = steps.max(1);
    (0..=steps)
        .map(|k| first + (top - first) * k as f64 / steps as f64)
        .collect()
}

use super::modal::{ModalError, ModalOptions, Mode, Whirl, modes_at};

/// One speed of a Campbell diagram: the modes sorted by damped frequency.
#[derive(Debug, Clone, PartialEq)]
pub struct CampbellPoint {
    /// Spin speed (rad/s).
    pub speed: f64,
    /// Modes at that speed, by increasing damped frequency (shapes dropped).
    pub modes: Vec<ModeSummary>,
}

/// A mode without its shape.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModeSummary {
    /// Damped natural frequency (rad/s).
    pub damped_frequency: f64,
    /// Damping ratio.
    pub damping_ratio: f64,
    /// Logarithmic decrement.
    pub log_decrement: f64,
    /// Whirl direction.
    pub whirl: Whirl,
}

impl From<&Mode> for ModeSummary {
    fn from(m: &Mode) -> Self {
        Self {
            damped_frequency: m.damped_frequency,
            damping_ratio: m.damping_ratio,
            log_decrement: m.log_decrement,
            whirl: m.whirl,
        }
    }
}

/// A critical speed: branch `rank` (0-based, by frequency) meets `ω = harmonic·Ω`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CriticalSpeed {
    /// Spin speed (rad/s).
    pub speed: f64,
    /// Excitation order (1 for unbalance).
    pub harmonic: f64,
    /// Branch rank at that speed.
    pub rank: usize,
    /// Whirl of the mode there.
    pub whirl: Whirl,
    /// Damping ratio there.
    pub damping_ratio: f64,
}

impl CriticalSpeed {
    /// Whether the mode is overdamped there (`ζ ≥` [`OVERDAMPED_DAMPING_RATIO`]):
    /// a crossing without a resonance peak, not a critical speed.
    pub fn is_overdamped(&self) -> bool {
        self.damping_ratio >= OVERDAMPED_DAMPING_RATIO
    }
}

/// Modes at every speed of `speeds` (rad/s, increasing); nonlinear bearings are
/// linearized about the static equilibrium at each speed.
pub fn campbell(
    rotor: &Rotor,
    speeds: &[f64],
    options: &ModalOptions,
) -> Result<Vec<CampbellPoint>, ModalError> {
    speeds
        .iter()
        .map(|&speed| {
            Ok(CampbellPoint {
                speed,
                modes: modes_at(rotor, speed, options)?
                    .iter()
                    .map(ModeSummary::from)
                    .collect(),
            })
        })
        .collect()
}

/// Critical speeds within the range of `diagram`: roots of `ω_k(Ω) − h Ω` for every
/// branch rank `k`, bracketed on the grid and refined by the secant/bisection
/// (Illinois) method to `1e-8` relative.
pub fn critical_speeds(
    rotor: &Rotor,
    diagram: &[CampbellPoint],
    harmonic: f64,
    options: &ModalOptions,
) -> Result<Vec<CriticalSpeed>, ModalError> {
    let ranks = diagram.iter().map(|p| p.modes.len()).min().unwrap_or(0);
    let mut found = Vec::new();
    for rank in 0..ranks {
        let g = |p: &CampbellPoint| p.modes[rank].damped_frequency - harmonic * p.speed;
        for pair in diagram.windows(2) {
            let (ga, gb) = (g(&pair[0]), g(&pair[1]));
            if ga == 0.0 || ga.signum() == gb.signum() {
                continue;
            }
            let branch = |speed: f64| -> Result<(f64, Mode), ModalError> {
                let ms = modes_at(rotor, speed, options)?;
                let m = ms.get(rank).cloned().ok_or_else(|| {
                    ModalError::Options(format!("branch {rank} vanished at {speed} rad/s"))
                })?;
                Ok((m.damped_frequency - harmonic * speed, m))
            };
            let (speed, mode) = illinois(branch, (pair[0].speed, ga), (pair[1].speed, gb))?;
            found.push(CriticalSpeed {
                speed,
                harmonic,
                rank,
                whirl: mode.whirl,
                damping_ratio: mode.damping_ratio,
            });
        }
    }
    found.sort_by(|a, b| a.speed.total_cmp(&b.speed));
    Ok(found)
}

/// Illinois regula falsi on a bracket `(a, f(a))`, `(b, f(b))` with a sign change.
fn illinois(
    mut f: impl FnMut(f64) -> Result<(f64, Mode), ModalError>,
    (mut a, mut fa): (f64, f64),
    (mut b, mut fb): (f64, f64),
) -> Result<(f64, Mode), ModalError> {
    let mut side = 0;
    let mut last = None;
    for _ in 0..60 {
        let c = (a * fb - b * fa) / (fb - fa);
        let (fc, mode) = f(c)?;
        last = Some((c, mode));
        if fc == 0.0 || (b - a).abs() <= 1e-8 * c.abs().max(1e-12) {
            break;
        }
        if fc.signum() == fb.signum() {
            b = c;
            fb = fc;
            if side == -1 {
                fa /= 2.0;
            }
            side = -1;
        } else {
            a = c;
            fa = fc;
            if side == 1 {
                fb /= 2.0;
            }
            side = 1;
        }
    }
    last.ok_or_else(|| ModalError::Options("critical speed search did not start".into()))
}
