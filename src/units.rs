//! Unit conversions used at the edges (model files, CLI, reports); everything
//! inside the crate is SI. Also the short form a number takes in a message.

use std::fmt;

/// rpm per rad/s: `n [rpm] = Ω [rad/s] · 60 / (2π)`.
pub const RAD_S_TO_RPM: f64 = 60.0 / (2.0 * std::f64::consts::PI);

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
