//! Whether unbalance excites a backward-whirl critical speed (API 684 2nd
//! ed. §2.6.2.10 and Annex: a backward crossing of the 1× line that the
//! unbalance response shows no peak at is listed but not judged by its
//! separation margin). On isotropic supports a backward mode whirls in
//! circles against the spin and a forward-rotating unbalance force does no
//! work on it; anisotropic supports make its orbits elliptic, and the
//! response peaks there.
//!
//! Criterion: the unbalance response of the model's unbalance planes, over
//! `Nc (1 ± 5 %)` on a grid refined near resonances
//! ([`super::unbalance::refined_sweep`]), has a peak at some response point
//! (probe, bearing) within `max(2ζ, 0.5 %)` of `Nc` — the half-power band
//! of the mode.

use crate::rotor::Rotor;

use super::unbalance::{peaks, refined_sweep, response_points, speed_grid};

/// Half-width of the window searched, relative to the critical speed.
const WINDOW: f64 = 0.05;
/// Base speeds over the window before refinement.
const WINDOW_POINTS: usize = 21;
/// The smallest distance (relative) within which a peak belongs to the critical.
const MIN_BAND: f64 = 0.005;

/// `Some(true)` when the unbalance response of `rotor` peaks at the
/// critical speed `speed` (rad/s) of a mode with damping ratio
/// `damping_ratio`, `Some(false)` when it does not, `None` when the model has
/// no unbalance or the response could not be computed (then the critical is
/// judged as any other).
pub fn unbalance_peak_at(rotor: &Rotor, speed: f64, damping_ratio: f64) -> Option<bool> {
    if rotor.model.unbalances.is_empty() || !(speed.is_finite() && speed > 0.0) {
        return None;
    }
    let grid = speed_grid(
        speed * (1.0 - WINDOW),
        speed * (1.0 + WINDOW),
        WINDOW_POINTS,
    )
    .ok()?;
    let points = response_points(rotor);
    let sweep = refined_sweep(rotor, &grid, &points).ok()?;
    let band = (2.0 * damping_ratio.abs()).max(MIN_BAND) * speed;
    for p in 0..points.len() {
        let found = peaks(rotor, &sweep, p).ok()?;
        if found.iter().any(|peak| (peak.speed - speed).abs() <= band) {
            return Some(true);
        }
    }
    Some(false)
}
