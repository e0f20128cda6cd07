//! Unit conversions used at the edges (model files, CLI, reports); everything
//! inside the crate is SI.

/// rpm per rad/s: `n [rpm] = Ω [rad/s] · 60 / (2π)`.
pub const RAD_S_TO_RPM: f64 = 60.0 / (2.0 * std::f64::consts::PI);
