//! What a transient orbit shows beyond its shape: the direction it is
//! traversed in relative to the spin (forward or backward whirl), and the
//! once-per-revolution (keyphasor) samples, where the spin angle passes a
//! whole turn.

use super::modal::Whirl;

/// Twice the signed area swept by the orbit `(x, y)` about its mean,
/// `Σ (x_k y_{k+1} − x_{k+1} y_k)`: positive for counter-clockwise motion
/// (from +x toward +y, the direction of positive spin).
pub fn swept_area(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len().min(y.len());
    if n < 2 {
        return 0.0;
    }
    let mx = x[..n].iter().sum::<f64>() / n as f64;
    let my = y[..n].iter().sum::<f64>() / n as f64;
    (0..n - 1)
        .map(|k| (x[k] - mx) * (y[k + 1] - my) - (x[k + 1] - mx) * (y[k] - my))
        .sum()
}

/// Whirl of an orbit relative to a spin of sign `speed`: forward when it
/// turns with the spin, backward against it, `Mixed` when it sweeps no area
/// (a straight line or no motion: below 1e-9 of the orbit's extent squared
/// per sample).
pub fn whirl(x: &[f64], y: &[f64], speed: f64) -> Whirl {
    let area = swept_area(x, y);
    let extent = x
        .iter()
        .chain(y)
        .fold(0.0f64, |a, v| a.max(v.abs()))
        .powi(2);
    if speed == 0.0 || area.abs() <= 1e-9 * extent * x.len() as f64 {
        return Whirl::Mixed;
    }
    if (area > 0.0) == (speed > 0.0) {
        Whirl::Forward
    } else {
        Whirl::Backward
    }
}

/// The samples where the spin angle (rad, monotone) completes a turn: the
/// first sample at or past each whole multiple of 2π (the keyphasor notch at
/// angle 0), after the first sample.
pub fn keyphasor(spin_angle: &[f64]) -> Vec<usize> {
    let turn = std::f64::consts::TAU;
    let mut out = Vec::new();
    for k in 1..spin_angle.len() {
        let (a, b) = (spin_angle[k - 1] / turn, spin_angle[k] / turn);
        if b.floor() > a.floor() {
            out.push(k);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    #[test]
    fn forward_and_backward_circles_and_a_line() {
        let t: Vec<f64> = (0..200).map(|k| k as f64 / 100.0).collect();
        let (cx, cy) = (3e-5, -2e-5);
        let x: Vec<f64> = t.iter().map(|t| cx + 1e-5 * (TAU * t).cos()).collect();
        let y: Vec<f64> = t.iter().map(|t| cy + 1e-5 * (TAU * t).sin()).collect();
        assert_eq!(whirl(&x, &y, 100.0), Whirl::Forward);
        assert_eq!(whirl(&x, &y, -100.0), Whirl::Backward);
        let back: Vec<f64> = y.iter().map(|v| 2.0 * cy - v).collect();
        assert_eq!(whirl(&x, &back, 100.0), Whirl::Backward);
        // Two turns of radius 1e-5 about the mean: 2 × 2π r², less the
        // polygon's shortfall (100 sides a turn) and the one open segment.
        let area = swept_area(&x, &y);
        assert!((area / (2.0 * TAU * 1e-10) - 1.0).abs() < 1e-2, "{area}");
        let line: Vec<f64> = x.iter().map(|v| 2.0 * v).collect();
        assert_eq!(whirl(&x, &line, 100.0), Whirl::Mixed);
    }

    #[test]
    fn once_per_revolution() {
        // 3.5 revolutions in 70 samples: turns complete at samples 20, 40, 60.
        let angle: Vec<f64> = (0..70).map(|k| TAU * k as f64 / 20.0).collect();
        assert_eq!(keyphasor(&angle), [20, 40, 60]);
        // Between samples: the first one past the turn.
        let angle: Vec<f64> = (0..10).map(|k| TAU * (0.15 + 0.3 * k as f64)).collect();
        assert_eq!(keyphasor(&angle), [3, 7]);
    }
}
