//! Unbalance response over a speed range (Bode and polar plots), its peaks,
//! amplification factors and API 684 separation margins.
//!
//! At every speed `Ω` the steady synchronous response is
//! [`unbalance_response`](super::linear::unbalance_response),
//! `(K − Ω² M + iΩ (C + Ω G)) X = Ω² F_u`, `q(t) = Re(X e^{iΩt})`, with
//! fluid-film bearings first replaced by their synchronous coefficients at the
//! static equilibrium at that speed ([`linearized`]).
//!
//! The amplitude a peak is judged on is the **major semi-axis of the orbit** of
//! the node, `r_f + r_b` ([`orbit_radii`]): the largest displacement in any
//! direction (for an isotropic rotor, `|X|`). A peak is a local maximum on the
//! speed grid refined by golden-section search; its half-power speeds `N1 < Nc <
//! N2`, where the amplitude is `A_peak/√2`, are found by bisection, and the
//! amplification factor is `AF = Nc / (N2 − N1)` (API 684 §2.6.2, the half-power
//! method; `AF ≈ 1/(2ζ)` for a lightly damped mode).

use nalgebra::Complex;

use crate::linalg::LinalgError;
use crate::rotor::{AssemblyError, Rotor};

use super::linear::{LinearError, node_xy, unbalance_response};
use super::linearize::{LinearizeError, linearized};
use super::modal::orbit_radii;
pub use super::speed_range::OperatingRange;

type C64 = Complex<f64>;

/// Why an unbalance response could not be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum UnbalanceError {
    /// The linear solve failed.
    #[error(transparent)]
    Linear(#[from] LinearError),
    /// Linearizing the fluid-film bearings failed.
    #[error(transparent)]
    Linearize(#[from] LinearizeError),
    /// The rotor with the chosen unbalance could not be assembled.
    #[error(transparent)]
    Assembly(#[from] AssemblyError),
    /// Bad input, naming the option and value.
    #[error("{0}")]
    Options(String),
}

/// A node whose response is reported: every probe, then every bearing journal.
#[derive(Debug, Clone, PartialEq)]
pub struct ResponsePoint {
    /// `probe NAME`, `bearing NAME` (rubs too) or `seal NAME`.
    pub label: String,
    /// Node index (0-based).
    pub node: usize,
}

/// The probes of the model, then its bearings.
pub fn response_points(rotor: &Rotor) -> Vec<ResponsePoint> {
    let m = &rotor.model;
    let probes = m.probes.iter().map(|p| ResponsePoint {
        label: format!("probe {}", p.name),
        node: p.node,
    });
    let bearings = m.bearings.iter().map(|b| ResponsePoint {
        label: format!(
            "{} {}",
            if b.kind.is_seal() {
                "seal"
            } else if b.kind.is_magnetic_pull() {
                "pull"
            } else if b.kind.is_rub() {
                "rub"
            } else {
                "bearing"
            },
            b.name
        ),
        node: b.node,
    });
    probes.chain(bearings).collect()
}

/// The rotor with its unbalance planes replaced by one plane of `unbalance`
/// (kg·m) at `node` (0-based), at phase 0 (along +x at spin angle 0).
pub fn with_unbalance_at(
    rotor: &Rotor,
    node: usize,
    unbalance: f64,
) -> Result<Rotor, UnbalanceError> {
    let nodes = rotor.model.node_count();
    if node >= nodes {
        return Err(UnbalanceError::Options(format!(
            "--node {} is outside the model's nodes 1..{nodes}",
            node + 1
        )));
    }
    if !(unbalance.is_finite() && unbalance > 0.0) {
        return Err(UnbalanceError::Options(format!(
            "--unbalance must be positive (kg·m), got {unbalance}"
        )));
    }
    let mut model = rotor.model.clone();
    model.unbalances = vec![crate::model::UnbalancePlane {
        name: format!("node{}", node + 1),
        node,
        magnitude: unbalance,
        phase: 0.0,
    }];
    Ok(Rotor::new(model)?)
}

/// Steady unbalance response on all DOFs (`4·node + k`, m) at `speed` (rad/s):
/// [`unbalance_response`] of the rotor, its fluid-film bearings linearized at
/// that speed with synchronous coefficients.
///
/// At an undamped critical speed the dynamic stiffness is singular and the
/// response unbounded; a speed that lands on one to working precision is
/// moved by [`UNBOUNDED_NUDGE`] of itself, so the response there is finite
/// but enormous, and the peak through it is reported as an undamped
/// resonance ([`Peak::is_undamped`]), as everywhere else near one.
pub fn response_at(rotor: &Rotor, speed: f64) -> Result<Vec<C64>, UnbalanceError> {
    let solve = |s: f64| -> Result<Vec<C64>, UnbalanceError> {
        if rotor.nonlinear_bearings.is_empty() {
            return Ok(unbalance_response(rotor, s)?);
        }
        let linear = linearized(rotor, s, s)?;
        Ok(unbalance_response(&linear, s)?)
    };
    match solve(speed) {
        Err(UnbalanceError::Linear(LinearError::Linalg {
            source: LinalgError::Singular { .. },
            ..
        })) if speed != 0.0 => solve(speed * (1.0 + UNBOUNDED_NUDGE)),
        other => other,
    }
}

/// Relative move off a speed where the unbalance response is singular (an
/// undamped critical speed hit to working precision).
pub const UNBOUNDED_NUDGE: f64 = 1e-9;

/// Response of a set of nodes over a speed grid.
#[derive(Debug, Clone, PartialEq)]
pub struct UnbalanceSweep {
    /// Spin speeds (rad/s), increasing.
    pub speeds: Vec<f64>,
    /// The nodes reported.
    pub points: Vec<ResponsePoint>,
    /// `response[k][p] = (X, Y)`: complex amplitudes (m) of point `p` at speed
    /// `k`, `x(t) = Re(X e^{iΩt}) = |X| cos(Ωt + arg X)`.
    pub response: Vec<Vec<(C64, C64)>>,
}

impl UnbalanceSweep {
    /// Major semi-axis of the orbit of point `p` at every speed (m).
    pub fn major(&self, p: usize) -> Vec<f64> {
        self.response
            .iter()
            .map(|r| major_semi_axis(r[p]))
            .collect()
    }
}

/// Major semi-axis of the elliptical orbit `(Re(X e^{iωt}), Re(Y e^{iωt}))`:
/// `r_f + r_b` with the forward and backward radii of [`orbit_radii`] (m).
pub fn major_semi_axis((x, y): (C64, C64)) -> f64 {
    let (f, b) = orbit_radii(x, y);
    f + b
}

/// Speed grid of `points` speeds from `min` to `max` (rad/s), both included.
pub fn speed_grid(min: f64, max: f64, points: usize) -> Result<Vec<f64>, UnbalanceError> {
    if !(min.is_finite() && max.is_finite() && min >= 0.0 && max > min) {
        return Err(UnbalanceError::Options(format!(
            "the speed range needs 0 ≤ --min-rpm < --max-rpm (got {} … {} rad/s)",
            min, max
        )));
    }
    if points < 3 {
        return Err(UnbalanceError::Options(format!(
            "--points must be at least 3, got {points}"
        )));
    }
    Ok((0..points)
        .map(|k| min + (max - min) * k as f64 / (points - 1) as f64)
        .collect())
}

/// The response of `points` at every speed of `speeds` (rad/s). A speed of 0 on
/// fluid-film bearings has no equilibrium: start such grids above zero.
pub fn sweep(
    rotor: &Rotor,
    speeds: &[f64],
    points: &[ResponsePoint],
) -> Result<UnbalanceSweep, UnbalanceError> {
    let response = speeds
        .iter()
        .map(|&s| {
            let q = response_at(rotor, s)?;
            Ok(points.iter().map(|p| node_xy(&q, p.node)).collect())
        })
        .collect::<Result<Vec<_>, UnbalanceError>>()?;
    Ok(UnbalanceSweep {
        speeds: speeds.to_vec(),
        points: points.to_vec(),
        response,
    })
}

/// Largest change (°) of the phase of a point's x or y response between
/// neighbouring speeds of a [`refined_sweep`].
pub const REFINE_ANGLE_DEG: f64 = 5.0;

/// Largest ratio of a point's major semi-axis between neighbouring speeds of
/// a [`refined_sweep`], where it is at least [`REFINE_FLOOR`] of its largest.
pub const REFINE_AMPLITUDE_RATIO: f64 = 1.2;

/// Amplitudes below this fraction of a point's largest are not refined (the
/// `Ω²` rise from standstill, a node that hardly moves).
pub const REFINE_FLOOR: f64 = 0.01;

/// Most speeds a [`refined_sweep`] evaluates.
pub const REFINE_MAX_SPEEDS: usize = 5000;

/// Narrowest interval (relative to the top speed) a [`refined_sweep`] splits.
const REFINE_MIN_WIDTH: f64 = 1e-9;

/// Phase change (°, in `[0, 180]`) from `a` to `b`; 0 when either is zero.
fn angle_step(a: C64, b: C64) -> f64 {
    if a.norm() == 0.0 || b.norm() == 0.0 {
        0.0
    } else {
        (b * a.conj()).arg().abs().to_degrees()
    }
}

/// Whether the interval from `k` to `k + 1` resolves the response of every
/// point: phase steps of x and y at most [`REFINE_ANGLE_DEG`], amplitude
/// ratio at most [`REFINE_AMPLITUDE_RATIO`], wherever the amplitude is above
/// [`REFINE_FLOOR`] of the point's largest.
fn resolved(sweep: &UnbalanceSweep, largest: &[f64], k: usize) -> bool {
    (0..sweep.points.len()).all(|p| {
        let (a, b) = (sweep.response[k][p], sweep.response[k + 1][p]);
        let (ma, mb) = (major_semi_axis(a), major_semi_axis(b));
        let floor = REFINE_FLOOR * largest[p];
        if ma.max(mb) <= floor || largest[p] == 0.0 {
            return true;
        }
        let ratio = ma.max(mb) / ma.min(mb).max(f64::MIN_POSITIVE);
        let significant = |z: C64| z.norm() > floor;
        let angle = |za: C64, zb: C64| {
            if significant(za) && significant(zb) {
                angle_step(za, zb)
            } else {
                0.0
            }
        };
        ratio <= REFINE_AMPLITUDE_RATIO
            && angle(a.0, b.0) <= REFINE_ANGLE_DEG
            && angle(a.1, b.1) <= REFINE_ANGLE_DEG
    })
}

/// [`sweep`] on `base` (rad/s, increasing), then refined where the response
/// changes fast: every interval that does not resolve it (phase steps above
/// [`REFINE_ANGLE_DEG`] or amplitude ratios above [`REFINE_AMPLITUDE_RATIO`])
/// is halved, again and again, until all do, the interval is
/// 1e-9 of the top speed, or [`REFINE_MAX_SPEEDS`] speeds are in hand. The
/// resonance loops of the polar plot and the peaks of the Bode plot are then
/// drawn from points a few degrees apart, however narrow the resonance.
pub fn refined_sweep(
    rotor: &Rotor,
    base: &[f64],
    points: &[ResponsePoint],
) -> Result<UnbalanceSweep, UnbalanceError> {
    let mut result = sweep(rotor, base, points)?;
    let top = base
        .last()
        .copied()
        .unwrap_or(0.0)
        .abs()
        .max(f64::MIN_POSITIVE);
    loop {
        let largest: Vec<f64> = (0..points.len())
            .map(|p| result.major(p).into_iter().fold(0.0, f64::max))
            .collect();
        let split: Vec<usize> = (0..result.speeds.len().saturating_sub(1))
            .filter(|&k| {
                result.speeds[k + 1] - result.speeds[k] > REFINE_MIN_WIDTH * top
                    && !resolved(&result, &largest, k)
            })
            .collect();
        let room = REFINE_MAX_SPEEDS.saturating_sub(result.speeds.len());
        if split.is_empty() || room == 0 {
            return Ok(result);
        }
        let mids: Vec<f64> = split
            .iter()
            .take(room)
            .map(|&k| 0.5 * (result.speeds[k] + result.speeds[k + 1]))
            .collect();
        let added = sweep(rotor, &mids, points)?;
        let mut merged: Vec<(f64, Vec<(C64, C64)>)> = result
            .speeds
            .into_iter()
            .zip(result.response)
            .chain(added.speeds.into_iter().zip(added.response))
            .collect();
        merged.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (speeds, response) = merged.into_iter().unzip();
        result = UnbalanceSweep {
            speeds,
            points: points.to_vec(),
            response,
        };
    }
}

/// The phase (°) of `values` unwrapped along the sweep: the first in
/// `(−180, 180]`, each next one within 180° of the one before (a jump of
/// exactly 180°, the sign change through an undamped resonance, as a lag).
/// Curves of all points are then continuous and comparable.
pub fn unwrapped_phase(values: &[C64]) -> Vec<f64> {
    let mut out: Vec<f64> = Vec::with_capacity(values.len());
    for z in values {
        let raw = z.arg().to_degrees();
        let next = match out.last() {
            None => raw,
            Some(&prev) => {
                let mut d = (raw - prev).rem_euclid(360.0);
                if d > 180.0 - 1e-6 {
                    d -= 360.0;
                }
                prev + d
            }
        };
        out.push(next);
    }
    out
}

/// Separation margin of one critical speed (fractions, 0.16 = 16 %).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeparationMargin {
    /// Required margin; `None` when `AF < 2.5` (critically damped: none required).
    pub required: Option<f64>,
    /// Actual margin: `(N_min − Nc)/Nc` below the range, `(Nc − N_max)/N_max`
    /// above it, negative (the distance into the range) inside it.
    pub actual: f64,
    /// `actual ≥ required`, or no margin required.
    pub pass: bool,
}

/// Required separation margin (fraction) of a critical speed with amplification
/// factor `af`, API 684 §2.6.2.10 (the rule ROSS `Report` applies): none when
/// `AF < 2.5`; below the operating range `min(16, 17 (1 − 1/(AF − 1.5)))` %,
/// above it `min(26, 10 + 17 (1 − 1/(AF − 1.5)))` %.
pub fn required_separation_margin(af: f64, below: bool) -> Option<f64> {
    if af.is_nan() || af < 2.5 {
        return None;
    }
    let s = 17.0 * (1.0 - 1.0 / (af - 1.5));
    let percent = if below {
        s.min(16.0)
    } else {
        (10.0 + s).min(26.0)
    };
    Some(percent / 100.0)
}

/// Separation margin of the critical speed `nc` (rad/s) with amplification
/// factor `af` from `range`; a critical inside the range counts as below it when
/// nearer its minimum.
pub fn separation_margin(nc: f64, af: f64, range: &OperatingRange) -> SeparationMargin {
    let below = if nc < range.min {
        true
    } else if nc > range.max {
        false
    } else {
        nc - range.min < range.max - nc
    };
    let actual = if nc < range.min {
        (range.min - nc) / nc
    } else if nc > range.max {
        (nc - range.max) / range.max
    } else if below {
        -(nc - range.min) / nc
    } else {
        -(range.max - nc) / range.max
    };
    let required = required_separation_margin(af, below);
    SeparationMargin {
        required,
        actual,
        pass: required.is_none_or(|r| actual >= r),
    }
}

/// The operating range of the model: its `operating_rpm`, else its
/// `speed_rpm` (a single speed), or none when the file gives neither.
pub fn model_operating_range(rotor: &Rotor) -> Option<OperatingRange> {
    if let Some([min, max]) = rotor.model.operating_range {
        return Some(OperatingRange { min, max });
    }
    let s = rotor.model.nominal_speed.abs();
    (s > 0.0).then_some(OperatingRange { min: s, max: s })
}

/// What an unbalance study sweeps and judges (speeds in rad/s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UnbalanceRequest {
    /// Lowest speed of the grid.
    pub min: f64,
    /// Highest speed; `None` for the model's default
    /// ([`default_top_speed`](super::speed_range::default_top_speed) with the
    /// operating range).
    pub max: Option<f64>,
    /// Speeds of the evenly spaced base grid, both ends included, before
    /// refinement ([`refined_sweep`]).
    pub points: usize,
    /// Operating range the separation margins are measured from.
    pub operating: Option<OperatingRange>,
}

/// The default study: 0 to the default top speed, 200 base speeds, margins
/// from `operating`.
pub const DEFAULT_POINTS: usize = 200;

/// An unbalance study: the refined sweep, every peak of every point with its
/// separation margin, and the grid's origin.
#[derive(Debug, Clone, PartialEq)]
pub struct UnbalanceStudy {
    /// The refined sweep (a grid starting at 0 on fluid films skips 0).
    pub sweep: UnbalanceSweep,
    /// Every peak with its margin (`None` without an AF or a range).
    pub rows: Vec<(Peak, Option<SeparationMargin>)>,
    /// The operating range of the margins.
    pub operating: Option<OperatingRange>,
    /// Where the top speed came from (`None` when given).
    pub top_origin: Option<super::speed_range::TopSpeedOrigin>,
    /// Speeds of the base grid.
    pub base_points: usize,
}

/// The unbalance study `rotor unbalance` and the report run: the response of
/// every probe and bearing ([`response_points`]) on the refined grid, peaks
/// with amplification factors, and API 684 margins from the operating range.
pub fn unbalance_study(
    rotor: &Rotor,
    request: &UnbalanceRequest,
) -> Result<UnbalanceStudy, UnbalanceError> {
    let (max, top_origin) = match request.max {
        Some(m) => (m, None),
        None => {
            let (top, origin) =
                super::speed_range::default_top_speed(&rotor.model, request.operating.as_ref());
            (top, Some(origin))
        }
    };
    let mut speeds = speed_grid(request.min, max, request.points)?;
    // A fluid film at standstill carries no load: start the grid one step up.
    if !rotor.nonlinear_bearings.is_empty() && speeds[0] == 0.0 {
        speeds.remove(0);
    }
    let points = response_points(rotor);
    let sweep = refined_sweep(rotor, &speeds, &points)?;
    let mut rows = Vec::new();
    for p in 0..points.len() {
        for peak in peaks(rotor, &sweep, p)? {
            let margin = match (peak.amplification_factor, &request.operating) {
                (Some(af), Some(r)) => Some(separation_margin(peak.speed, af, r)),
                _ => None,
            };
            rows.push((peak, margin));
        }
    }
    Ok(UnbalanceStudy {
        sweep,
        rows,
        operating: request.operating,
        top_origin,
        base_points: request.points,
    })
}

/// A resonance peak of one response point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Peak {
    /// Index of the point in the sweep.
    pub point: usize,
    /// Peak speed `Nc` (rad/s).
    pub speed: f64,
    /// Major semi-axis there (m).
    pub amplitude: f64,
    /// Half-power speeds `(N1, N2)` (rad/s), when both lie inside the sweep.
    pub half_power: Option<(f64, f64)>,
    /// `Nc / (N2 − N1)`, when both half-power speeds were found; infinite when
    /// the refinement met the undamped resonance exactly (singular dynamic
    /// stiffness; `amplitude` is then the grid's largest).
    pub amplification_factor: Option<f64>,
    /// Where a peak without half-power speeds keeps above its half-power
    /// level `amplitude/√2` all the way to the end of the sweep; `None` when
    /// both half-power speeds were found (or the peak is undamped).
    pub level_kept: Option<LevelKept>,
}

/// The side(s) of a peak on which the response stays above the peak's
/// half-power level to the end of the sweep (a heavily damped mode, whose
/// response above the peak tends to `m e / M` without falling to `1/√2` of
/// the peak, or a sweep that ends too soon): no half-power speed there, so
/// no amplification factor.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LevelKept {
    /// From the peak down to the sweep's lowest speed.
    Below,
    /// From the peak up to the sweep's highest speed.
    Above,
    /// Over the whole sweep.
    Both,
}

/// Amplification factor above which a peak is an undamped resonance
/// (`AF = 1/(2ζ)` for `ζ < 10⁻⁶`): its amplitude and width are set by the
/// refinement's resolution, not by the rotor.
pub const UNDAMPED_AMPLIFICATION: f64 = 5e5;

impl Peak {
    /// Whether the peak is an undamped resonance (see [`UNDAMPED_AMPLIFICATION`]).
    pub fn is_undamped(&self) -> bool {
        self.amplification_factor
            .is_some_and(|af| af > UNDAMPED_AMPLIFICATION)
    }
}

/// Golden-section refinement ratio `(√5 − 1)/2`.
const GOLDEN: f64 = 0.618_033_988_749_894_9;

/// The peaks of point `p` of `sweep`: interior local maxima of the major
/// semi-axis on the grid, refined by golden-section search between the grid
/// neighbours to `1e-10` of the speed, with their half-power speeds by bisection
/// to `1e-12` relative (each evaluation a full [`response_at`]).
pub fn peaks(rotor: &Rotor, sweep: &UnbalanceSweep, p: usize) -> Result<Vec<Peak>, UnbalanceError> {
    let node = sweep.points[p].node;
    let amp = |s: f64| -> Result<f64, UnbalanceError> {
        Ok(major_semi_axis(node_xy(&response_at(rotor, s)?, node)))
    };
    // Inside a bracket whose ends solved, a singular dynamic stiffness is the
    // undamped resonance itself: the amplitude there is unbounded.
    let amp_or_resonance = |s: f64| -> Result<f64, UnbalanceError> {
        match amp(s) {
            Err(UnbalanceError::Linear(LinearError::Linalg {
                source: LinalgError::Singular { .. },
                ..
            })) => Ok(f64::INFINITY),
            other => other,
        }
    };
    let a = sweep.major(p);
    let s = &sweep.speeds;
    let mut found = Vec::new();
    for k in 1..s.len().saturating_sub(1) {
        if !(a[k] >= a[k - 1] && a[k] > a[k + 1]) {
            continue;
        }
        let (mut lo, mut hi) = (s[k - 1], s[k + 1]);
        let mut x1 = hi - GOLDEN * (hi - lo);
        let mut x2 = lo + GOLDEN * (hi - lo);
        let (mut f1, mut f2) = (amp_or_resonance(x1)?, amp_or_resonance(x2)?);
        while hi - lo > 1e-10 * hi && f1.is_finite() && f2.is_finite() {
            if f1 > f2 {
                hi = x2;
                x2 = x1;
                f2 = f1;
                x1 = hi - GOLDEN * (hi - lo);
                f1 = amp_or_resonance(x1)?;
            } else {
                lo = x1;
                x1 = x2;
                f1 = f2;
                x2 = lo + GOLDEN * (hi - lo);
                f2 = amp_or_resonance(x2)?;
            }
        }
        let (speed, amplitude) = if f1 > f2 { (x1, f1) } else { (x2, f2) };
        if amplitude.is_infinite() {
            // Met the resonance exactly: the largest amplitude solved on the
            // grid stands for it, and the peak has no width.
            found.push(Peak {
                point: p,
                speed,
                amplitude: a[k],
                half_power: None,
                amplification_factor: Some(f64::INFINITY),
                level_kept: None,
            });
            continue;
        }
        let level = amplitude / std::f64::consts::SQRT_2;
        // Nearest grid speeds outside the peak where the amplitude is below the level.
        let below = (0..k).rev().find(|&j| a[j] < level);
        let above = (k + 1..s.len()).find(|&j| a[j] < level);
        let half_power = match (below, above) {
            (Some(j1), Some(j2)) => {
                let n1 = bisect(&amp, level, (s[j1], speed))?;
                let n2 = bisect(&amp, level, (speed, s[j2]))?;
                Some((n1, n2))
            }
            _ => None,
        };
        let level_kept = match (below, above) {
            (None, None) => Some(LevelKept::Both),
            (None, Some(_)) => Some(LevelKept::Below),
            (Some(_), None) => Some(LevelKept::Above),
            (Some(_), Some(_)) => None,
        };
        found.push(Peak {
            point: p,
            speed,
            amplitude,
            half_power,
            amplification_factor: half_power.map(|(n1, n2)| speed / (n2 - n1)),
            level_kept,
        });
    }
    Ok(found)
}

/// Root of `f(s) = level` on `(a, b)` where `f − level` changes sign, by bisection.
fn bisect(
    f: &impl Fn(f64) -> Result<f64, UnbalanceError>,
    level: f64,
    (mut a, mut b): (f64, f64),
) -> Result<f64, UnbalanceError> {
    let fa = f(a)? - level;
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if b - a <= 1e-12 * b {
            break;
        }
        if (f(m)? - level).signum() == fa.signum() {
            a = m;
        } else {
            b = m;
        }
    }
    Ok(0.5 * (a + b))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The API 684 rule at its corners: nothing below AF = 2.5, the caps of 16 %
    /// and 26 % for large AF, and a hand value at AF = 3.5.
    #[test]
    fn required_margin_follows_api_684() {
        assert_eq!(required_separation_margin(2.49, true), None);
        assert_eq!(required_separation_margin(2.49, false), None);
        // AF = 3.5: 17 (1 − 1/2) = 8.5 %; above: 18.5 %.
        assert!((required_separation_margin(3.5, true).unwrap() - 0.085).abs() < 1e-15);
        assert!((required_separation_margin(3.5, false).unwrap() - 0.185).abs() < 1e-15);
        assert_eq!(required_separation_margin(1e6, true), Some(0.16));
        assert_eq!(required_separation_margin(1e6, false), Some(0.26));
    }

    #[test]
    fn actual_margin_is_measured_from_the_nearer_end_of_the_range() {
        let range = OperatingRange {
            min: 100.0,
            max: 120.0,
        };
        let below = separation_margin(80.0, 10.0, &range);
        assert!((below.actual - 0.25).abs() < 1e-15);
        assert!(below.pass, "{below:?}");
        let above = separation_margin(130.0, 10.0, &range);
        assert!((above.actual - 10.0 / 120.0).abs() < 1e-15);
        assert!(!above.pass, "needs {:?}", above.required);
        let inside = separation_margin(105.0, 10.0, &range);
        assert!(inside.actual < 0.0 && !inside.pass);
        assert!(separation_margin(105.0, 2.0, &range).pass);
    }
}
