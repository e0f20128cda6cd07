//! Dimensionless stiffness and damping of a fluid-film bearing against
//! eccentricity ratio (Lund's presentation; the paper's Fig. 3): equilibria under
//! a geometric sweep of the load, coefficients scaled by `K̄ = K C / W` and
//! `C̄ = C ω C / W`.

use super::equilibrium::{CoefficientPoint, EquilibriumError, coefficient_points};
use super::{Bearing, BearingKind};

/// Smallest dimensionless load `W / k0` of [`load_sweep`].
pub const LIGHTEST_LOAD: f64 = 0.08;
/// Ratio of the heaviest to the lightest load of [`load_sweep`]: `W / k0` from
/// 0.08 to 50, for a short bearing eccentricity ratios ε ≈ 0.1 … 0.9.
pub const LOAD_RATIO: f64 = 625.0;

/// One point of a dimensionless coefficient curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DimensionlessPoint {
    /// Load `W` (N), along −y.
    pub load: f64,
    /// Eccentricity ratio ε (–).
    pub eccentricity: f64,
    /// Attitude angle φ (rad).
    pub attitude_angle: f64,
    /// `K̄ = K C / W` (–), order xx, xy, yx, yy.
    pub stiffness: [f64; 4],
    /// `C̄ = C ω C / W` (–), order xx, xy, yx, yy.
    pub damping: [f64; 4],
}

impl DimensionlessPoint {
    /// Scale `point` at spin `speed` (rad/s) with radial clearance `clearance` (m).
    pub fn new(point: &CoefficientPoint, speed: f64, clearance: f64) -> Self {
        let k = point.stiffness * (clearance / point.load);
        let c = point.damping * (speed * clearance / point.load);
        Self {
            load: point.load,
            eccentricity: point.eccentricity,
            attitude_angle: point.attitude_angle,
            stiffness: [k[(0, 0)], k[(0, 1)], k[(1, 0)], k[(1, 1)]],
            damping: [c[(0, 0)], c[(0, 1)], c[(1, 0)], c[(1, 1)]],
        }
    }
}

/// `points` loads (N) spaced geometrically from `LIGHTEST_LOAD · k0` to
/// `LOAD_RATIO` times that, with `k0` the load scale (N) of
/// [`super::FilmGeometry::load_scale`]; `points ≥ 2`.
pub fn load_sweep(k0: f64, points: usize) -> Vec<f64> {
    (0..points)
        .map(|i| k0 * LIGHTEST_LOAD * LOAD_RATIO.powf(i as f64 / (points - 1) as f64))
        .collect()
}

/// Dimensionless coefficients of the fluid-film bearing `kind` at spin `speed`
/// (rad/s), pad tilts condensed for whirl at `whirl` (rad/s; `speed` for the
/// synchronous ones), over [`load_sweep`] of `points` loads, each load (N)
/// with its point or the reason it has no equilibrium (never dropped). `None`
/// for a linear bearing (its coefficients are constant).
pub fn dimensionless_curve(
    kind: &BearingKind,
    speeds: (f64, f64),
    points: usize,
) -> Option<Vec<(f64, Result<DimensionlessPoint, EquilibriumError>)>> {
    dimensionless_curve_of(kind, kind.build().as_ref(), speeds, points)
}

/// [`dimensionless_curve`] of `bearing`, a film model of the geometry of
/// `kind` (the short film `kind.build()`, or the finite-length film of
/// [`super::finite_bearing::FiniteFilmBearing::of`]): the same loads,
/// equilibria and scaling.
pub fn dimensionless_curve_of(
    kind: &BearingKind,
    bearing: &dyn Bearing,
    (speed, whirl): (f64, f64),
    points: usize,
) -> Option<Vec<(f64, Result<DimensionlessPoint, EquilibriumError>)>> {
    let film = kind.film_geometry()?;
    let loads = load_sweep(film.load_scale(speed), points);
    let curve = coefficient_points(bearing, (speed, whirl), film.clearance, &loads);
    Some(
        curve
            .into_iter()
            .map(|(w, p)| {
                (
                    w,
                    p.map(|p| DimensionlessPoint::new(&p, speed, film.clearance)),
                )
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::PlainBearing;

    #[test]
    fn sweep_spans_the_load_range_geometrically() {
        let loads = load_sweep(200.0, 5);
        assert_eq!(loads.len(), 5);
        assert!((loads[0] - 16.0).abs() < 1e-12);
        assert!((loads[4] - 10_000.0).abs() < 1e-9);
        let r = loads[1] / loads[0];
        assert!(loads.windows(2).all(|w| (w[1] / w[0] - r).abs() < 1e-12));
    }

    #[test]
    fn short_bearing_curve_covers_light_to_heavy_load() {
        let kind = BearingKind::Plain(PlainBearing {
            radius: 0.05,
            length: 0.03,
            clearance: 1e-4,
            viscosity: 0.02,
            contact: None,
        });
        let curve: Vec<DimensionlessPoint> = dimensionless_curve(&kind, (314.159, 314.159), 12)
            .unwrap()
            .into_iter()
            .map(|(w, p)| p.unwrap_or_else(|e| panic!("{w} N: {e}")))
            .collect();
        assert_eq!(curve.len(), 12);
        assert!(curve[0].eccentricity < 0.2 && curve[11].eccentricity > 0.8);
        assert!(
            curve
                .windows(2)
                .all(|w| w[1].eccentricity > w[0].eccentricity)
        );
        // Short bearing at light load: attitude angle near 90°, K̄yy > 0.
        assert!(curve[0].attitude_angle.to_degrees() > 70.0);
        assert!(
            curve
                .iter()
                .all(|p| p.stiffness[3] > 0.0 && p.damping[0] > 0.0)
        );
        let linear = BearingKind::Linear {
            stiffness: [[1e7, 0.0], [0.0, 1e7]],
            damping: [[0.0; 2]; 2],
        };
        assert!(dimensionless_curve(&linear, (314.159, 314.159), 12).is_none());
    }
}
