//! Unit conversions used at the edges (model files, CLI, reports); everything
//! inside the crate is SI. Also the short form a number takes in a message
//! and the convention a vibration amplitude is stated in.

use std::fmt;

/// rpm per rad/s: `n [rpm] = Ω [rad/s] · 60 / (2π)`.
pub const RAD_S_TO_RPM: f64 = 60.0 / (2.0 * std::f64::consts::PI);

/// Standard gravity g₀ (m/s², ISO 80000-3).
pub const STANDARD_GRAVITY: f64 = 9.80665;

/// How a vibration amplitude is stated: the orbit's semi-axis (zero to peak,
/// what the analyses compute) or twice it (peak to peak, what proximity-probe
/// readings and API 684 vibration limits use).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Amplitude {
    /// Zero to peak: the semi-axis of the orbit, the radius of a whirl.
    #[default]
    ZeroToPeak,
    /// Peak to peak: twice the zero-to-peak value.
    PeakToPeak,
}

impl Amplitude {
    /// The factor from a zero-to-peak value: 1 or 2.
    pub fn factor(self) -> f64 {
        match self {
            Self::ZeroToPeak => 1.0,
            Self::PeakToPeak => 2.0,
        }
    }

    /// The label on axes and table headings: `0-pk` or `pk-pk`.
    pub fn label(self) -> &'static str {
        match self {
            Self::ZeroToPeak => "0-pk",
            Self::PeakToPeak => "pk-pk",
        }
    }

    /// `0-pk` or `pk-pk` (the `--amplitude` option), else an error naming it.
    pub fn parse(text: &str) -> Result<Self, String> {
        match text {
            "0-pk" => Ok(Self::ZeroToPeak),
            "pk-pk" => Ok(Self::PeakToPeak),
            other => Err(format!(
                "--amplitude {other:?}: expected 0-pk (the orbit's semi-axis) or pk-pk (twice it)"
            )),
        }
    }
}

/// A number as messages print it: the shortest digits that read back to the
/// same value, in plain notation from 1e-4 up to 1e15 (`0.02`, `3000`) and in
/// exponent notation outside (`1e-154`, `1e300`), so that an absurd value
/// never prints as hundreds of digits.
///
/// ```
/// use rotor_bearing::units::Short;
/// assert_eq!(Short(0.02).to_string(), "0.02");
/// assert_eq!(Short(3000.0).to_string(), "3000");
/// assert_eq!(Short(1e-154).to_string(), "1e-154");
/// assert_eq!(Short(-2.5e300).to_string(), "-2.5e300");
/// assert_eq!(Short(f64::NAN).to_string(), "NaN");
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Short(pub f64);

impl fmt::Display for Short {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        if !x.is_finite() || x == 0.0 || (1e-4..1e15).contains(&x.abs()) {
            write!(f, "{x}")
        } else {
            write!(f, "{x:e}")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn amplitude_conventions() {
        assert_eq!(Amplitude::parse("pk-pk").unwrap().factor(), 2.0);
        assert_eq!(Amplitude::parse("0-pk").unwrap().label(), "0-pk");
        assert!(
            Amplitude::parse("rms")
                .unwrap_err()
                .contains("--amplitude \"rms\"")
        );
        assert_eq!(Amplitude::default(), Amplitude::ZeroToPeak);
    }
}
