//! The operating speed range and the default top speed of every speed sweep
//! (Campbell diagram, unbalance response, the bearings' curves of the critical
//! speed map): one rule from the model, so every command and the report sweep the same range.

use std::fmt;

use crate::model::RotorModel;
use crate::units::RAD_S_TO_RPM;

/// Operating speed range (rad/s) a separation margin is measured from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OperatingRange {
    /// Minimum operating speed (rad/s).
    pub min: f64,
    /// Maximum continuous speed (rad/s).
    pub max: f64,
}

/// A sweep reaches this factor above the highest speed the machine runs at.
pub const TOP_SPEED_FACTOR: f64 = 1.25;

/// Top speed (rpm) of a sweep of a model that states neither `max_speed_rpm`
/// nor `speed_rpm`, and is given no operating range.
pub const FALLBACK_TOP_RPM: f64 = 4000.0;

/// Where a default top speed came from (speeds in rad/s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TopSpeedOrigin {
    /// The model's `max_speed_rpm`.
    MaxSpeed(f64),
    /// The model's `speed_rpm`.
    NominalSpeed(f64),
    /// The top of the operating range asked for.
    Operating(f64),
    /// Nothing to go by: [`FALLBACK_TOP_RPM`].
    Fallback,
}

/// `rpm` rounded to 1e-6 rpm: the value a model file gave, without the
/// round-off of its conversion to rad/s and back.
fn rounded(speed: f64) -> f64 {
    (speed * RAD_S_TO_RPM * 1e6).round() / 1e6
}

impl fmt::Display for TopSpeedOrigin {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::MaxSpeed(s) => write!(
                f,
                "{TOP_SPEED_FACTOR} × the model's max_speed_rpm {}",
                rounded(*s)
            ),
            Self::NominalSpeed(s) => write!(
                f,
                "{TOP_SPEED_FACTOR} × the model's speed_rpm {}",
                rounded(*s)
            ),
            Self::Operating(s) => write!(
                f,
                "{TOP_SPEED_FACTOR} × the operating speed {}",
                rounded(*s)
            ),
            Self::Fallback => f.write_str("the model states neither max_speed_rpm nor speed_rpm"),
        }
    }
}

/// Default top speed (rad/s) of a sweep of `model` and where it came from:
/// [`TOP_SPEED_FACTOR`] × the largest of the model's `max_speed_rpm` (when the
/// file states it), its `speed_rpm` and the top of `operating`; else
/// [`FALLBACK_TOP_RPM`].
pub fn default_top_speed(
    model: &RotorModel,
    operating: Option<&OperatingRange>,
) -> (f64, TopSpeedOrigin) {
    let candidates = [
        model
            .max_speed_stated
            .then(|| TopSpeedOrigin::MaxSpeed(model.max_speed.abs())),
        (model.nominal_speed != 0.0)
            .then(|| TopSpeedOrigin::NominalSpeed(model.nominal_speed.abs())),
        operating.map(|r| TopSpeedOrigin::Operating(r.max.abs())),
    ];
    let speed = |o: &TopSpeedOrigin| match o {
        TopSpeedOrigin::MaxSpeed(s)
        | TopSpeedOrigin::NominalSpeed(s)
        | TopSpeedOrigin::Operating(s) => *s,
        TopSpeedOrigin::Fallback => 0.0,
    };
    // The largest; on a tie the first (max_speed_rpm, then speed_rpm).
    let best =
        candidates
            .into_iter()
            .flatten()
            .fold(None::<TopSpeedOrigin>, |best, o| match best {
                Some(b) if speed(&b) >= speed(&o) => Some(b),
                _ => Some(o),
            });
    match best {
        Some(o) if speed(&o) > 0.0 => (TOP_SPEED_FACTOR * speed(&o), o),
        _ => (FALLBACK_TOP_RPM / RAD_S_TO_RPM, TopSpeedOrigin::Fallback),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_largest_speed_the_machine_runs_at_sets_the_top() {
        let rpm = |v: f64| v / RAD_S_TO_RPM;
        let mut m = RotorModel::default_model(); // speed_rpm 1000
        let (top, origin) = default_top_speed(&m, None);
        assert!((top - rpm(1250.0)).abs() < 1e-12);
        assert_eq!(origin.to_string(), "1.25 × the model's speed_rpm 1000");
        let op = OperatingRange {
            min: rpm(1500.0),
            max: rpm(1800.0),
        };
        let (top, origin) = default_top_speed(&m, Some(&op));
        assert!((top - rpm(2250.0)).abs() < 1e-12);
        assert_eq!(origin.to_string(), "1.25 × the operating speed 1800");
        m.max_speed_stated = true;
        m.max_speed = rpm(2000.0);
        let (top, origin) = default_top_speed(&m, Some(&op));
        assert!((top - rpm(2500.0)).abs() < 1e-12);
        assert_eq!(origin.to_string(), "1.25 × the model's max_speed_rpm 2000");
        m.max_speed_stated = false;
        m.nominal_speed = 0.0;
        let (top, origin) = default_top_speed(&m, None);
        assert!((top - rpm(FALLBACK_TOP_RPM)).abs() < 1e-12);
        assert_eq!(origin, TopSpeedOrigin::Fallback);
    }
}
