//! The records of a Campbell diagram: one speed's modes ([`CampbellPoint`],
//! [`ModeSummary`]) and a critical speed where a branch meets an excitation
//! line ([`CriticalSpeed`]).

use super::modal::{Mode, OverdampedRoot, Whirl};

/// Damping ratio from which a crossing of an excitation line is overdamped,
/// not a critical speed: the amplification `1/(2ζ)` is at most 1.
pub const OVERDAMPED_DAMPING_RATIO: f64 = 0.5;

/// One speed of a Campbell diagram: the modes sorted by damped frequency, each
/// with the branch it belongs to, and the non-oscillating roots apart.
#[derive(Debug, Clone, PartialEq)]
pub struct CampbellPoint {
    /// Spin speed (rad/s).
    pub speed: f64,
    /// Modes at that speed, by increasing damped frequency (shapes dropped).
    pub modes: Vec<ModeSummary>,
    /// Non-oscillating (overdamped) roots at that speed: never a branch.
    pub overdamped: Vec<OverdampedRoot>,
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
    /// The branch of the diagram the mode lies on (0-based), tracked from
    /// speed to speed by its shape ([`super::mode_tracking`]).
    pub branch: usize,
}

impl ModeSummary {
    pub(super) fn of(m: &Mode, branch: usize) -> Self {
        Self {
            damped_frequency: m.damped_frequency,
            damping_ratio: m.damping_ratio,
            log_decrement: m.log_decrement,
            whirl: m.whirl,
            branch,
        }
    }
}

/// A critical speed: branch `branch` meets `ω = harmonic·Ω`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CriticalSpeed {
    /// Spin speed (rad/s).
    pub speed: f64,
    /// Excitation order (1 for unbalance).
    pub harmonic: f64,
    /// Rank of the mode by frequency at that speed (0-based).
    pub rank: usize,
    /// The tracked branch (0-based, as [`ModeSummary::branch`]).
    pub branch: usize,
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
