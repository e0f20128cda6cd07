//! Mode shapes as orbits: the ellipse each node describes in a mode.
//!
//! A mode's shape ([`Mode::shape`]) is scaled so that its largest translation
//! (x or y over all nodes) is exactly `1 + 0i`; node `k` then moves as
//! `x(t) = Re(X e^{iωt})`, `y(t) = Re(Y e^{iωt})`, an ellipse. Writing
//! `x + iy = A e^{iωt} + B e^{−iωt}` with `A = (X + iY)/2`,
//! `B = conj(X − iY)/2`, the forward radius is `|A|`, the backward radius `|B|`
//! ([`orbit_radii`]), the semi-axes are `|A| + |B|` and `||A| − |B||`, and the
//! major axis points at `(arg A + arg B)/2` from +x toward +y.

use nalgebra::Complex;

use crate::fe::{DOF_PER_NODE, DOF_X, DOF_Y};
use crate::model::RotorModel;

use super::modal::{Mode, orbit_radii};

type C64 = Complex<f64>;

/// Orbit of one node in a mode (normalized shape: dimensionless).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NodeOrbit {
    /// Node index (0-based).
    pub node: usize,
    /// Axial position (m).
    pub z: f64,
    /// Complex x amplitude.
    pub x: C64,
    /// Complex y amplitude.
    pub y: C64,
    /// Forward whirl radius `|A|`.
    pub forward: f64,
    /// Backward whirl radius `|B|`.
    pub backward: f64,
    /// Major semi-axis `|A| + |B|`.
    pub major: f64,
    /// Minor semi-axis `||A| − |B||`.
    pub minor: f64,
    /// Direction of the major axis from +x toward +y (rad).
    pub major_angle: f64,
}

impl NodeOrbit {
    /// `forward` or `backward` relative to the axes (`forward` when the node
    /// turns from +x toward +y, the spin direction of positive speeds), `planar`
    /// for a straight-line orbit (radii within 1 %) or no motion.
    pub fn direction(&self) -> &'static str {
        if self.forward > 1.01 * self.backward {
            "forward"
        } else if self.backward > 1.01 * self.forward {
            "backward"
        } else {
            "planar"
        }
    }
}

/// The orbit of every node of `model` in `mode`.
pub fn node_orbits(model: &RotorModel, mode: &Mode) -> Vec<NodeOrbit> {
    let i = C64::new(0.0, 1.0);
    (0..model.node_count())
        .map(|node| {
            let x = mode.shape[node * DOF_PER_NODE + DOF_X];
            let y = mode.shape[node * DOF_PER_NODE + DOF_Y];
            let (forward, backward) = orbit_radii(x, y);
            let a = (x + i * y) / 2.0;
            let b = (x - i * y).conj() / 2.0;
            NodeOrbit {
                node,
                z: model.node_z[node],
                x,
                y,
                forward,
                backward,
                major: forward + backward,
                minor: (forward - backward).abs(),
                major_angle: 0.5 * (a.arg() + b.arg()),
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The semi-axes and direction of the ellipse against a sampled orbit.
    #[test]
    fn ellipse_axes_match_a_sampled_orbit() {
        let (x, y) = (C64::new(0.3, -0.8), C64::new(0.5, 0.2));
        let model = RotorModel::default_model();
        let mut shape = vec![C64::new(0.0, 0.0); DOF_PER_NODE * model.node_count()];
        shape[DOF_X] = x;
        shape[DOF_Y] = y;
        let mode = Mode {
            eigenvalue: C64::new(0.0, 1.0),
            natural_frequency: 1.0,
            damped_frequency: 1.0,
            damping_ratio: 0.0,
            log_decrement: 0.0,
            whirl: super::super::modal::Whirl::Mixed,
            shape,
            residual: 0.0,
        };
        let o = node_orbits(&model, &mode)[0];
        let (mut r_max, mut r_min, mut at) = (0.0f64, f64::INFINITY, 0.0);
        let mut turning = 0.0;
        for k in 0..100_000 {
            let t = k as f64 * std::f64::consts::TAU / 100_000.0;
            let e = C64::from_polar(1.0, t);
            let (px, py) = ((x * e).re, (y * e).re);
            let r = px.hypot(py);
            if r > r_max {
                r_max = r;
                at = py.atan2(px);
            }
            r_min = r_min.min(r);
            let e2 = C64::from_polar(1.0, t + 1e-3);
            turning += px * (y * e2).re - py * (x * e2).re;
        }
        assert!((o.major - r_max).abs() < 1e-9, "{} vs {r_max}", o.major);
        assert!((o.minor - r_min).abs() < 1e-9, "{} vs {r_min}", o.minor);
        // The major axis is a line: compare directions modulo π.
        let d = (o.major_angle - at).rem_euclid(std::f64::consts::PI);
        assert!(
            d.min(std::f64::consts::PI - d) < 1e-3,
            "{} vs {at}",
            o.major_angle
        );
        assert_eq!(
            o.direction(),
            if turning > 0.0 { "forward" } else { "backward" }
        );
    }
}
