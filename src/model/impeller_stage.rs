//! A stage's data for Wachel's anticipated cross-coupling, given on its
//! impeller (`[[disks]] role = "impeller"` with `stage_power`,
//! `impeller_diameter`, `flow_width`, `density_ratio`, `stage_factor`): the
//! API 617 Level I screening sums the stages' `q_A` (issue 48).

/// One stage's rated power `P` (W), impeller diameter `D` and restrictive
/// flow width `H` (m), discharge over suction density `ρ_d/ρ_s` and stage
/// factor `B` (3 centrifugal, 1.5 axial), in SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpellerStage {
    /// Rated power of the stage (W).
    pub power: f64,
    /// Impeller diameter (m).
    pub diameter: f64,
    /// Restrictive flow width (m).
    pub width: f64,
    /// `ρ_d/ρ_s` (1 for a liquid).
    pub density_ratio: f64,
    /// Stage factor `B`.
    pub stage_factor: f64,
}

/// Default `density_ratio` of a stage: a liquid's.
pub const DEFAULT_DENSITY_RATIO: f64 = 1.0;

/// Default `stage_factor` of a stage: Wachel's centrifugal impeller.
pub const DEFAULT_STAGE_FACTOR: f64 = 3.0;
