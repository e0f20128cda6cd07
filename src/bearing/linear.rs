//! Linear bearing: constant stiffness and damping, cross-coupling allowed.

use nalgebra::Matrix2;

use super::{Bearing, BearingError, BearingEval, BearingForce, JournalState, check_state};

/// `F = −K q − C q̇` with constant 2×2 `K` (N/m) and `C` (N·s/m).
#[derive(Debug, Clone, PartialEq)]
pub struct LinearBearing {
    /// Stiffness.
    pub stiffness: Matrix2<f64>,
    /// Damping.
    pub damping: Matrix2<f64>,
}

impl LinearBearing {
    /// From row-major arrays `[[kxx, kxy], [kyx, kyy]]`.
    pub fn new(stiffness: [[f64; 2]; 2], damping: [[f64; 2]; 2]) -> Self {
        let m = |a: [[f64; 2]; 2]| Matrix2::new(a[0][0], a[0][1], a[1][0], a[1][1]);
        Self {
            stiffness: m(stiffness),
            damping: m(damping),
        }
    }
}

impl LinearBearing {
    /// Force on the journal and its (constant) Jacobians.
    pub fn force_and_jacobian(
        &self,
        state: &JournalState,
        speed: f64,
    ) -> Result<BearingForce, BearingError> {
        super::journal_force(self, state, speed)
    }
}

impl Bearing for LinearBearing {
    fn evaluate(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<(), BearingError> {
        check_state(2, q, qdot, speed, out)?;
        let state = JournalState::from_coordinates(q, qdot);
        let part = BearingForce {
            force: -(self.stiffness * state.position + self.damping * state.velocity),
            stiffness: self.stiffness,
            damping: self.damping,
        };
        out.clear();
        out.add_transformed(&part, None);
        Ok(())
    }

    fn is_linear(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2;

    #[test]
    fn force_opposes_displacement_and_matches_jacobians() {
        let b = LinearBearing::new([[1e6, 2e5], [-1e5, 2e6]], [[100.0, 5.0], [5.0, 300.0]]);
        let s = JournalState {
            position: Vector2::new(1e-5, -2e-5),
            velocity: Vector2::new(1e-3, 3e-3),
        };
        let f = b.force_and_jacobian(&s, 100.0).unwrap();
        assert!(
            (f.force.x - (-(1e6 * 1e-5 + 2e5 * -2e-5) - (100.0 * 1e-3 + 5.0 * 3e-3))).abs() < 1e-12
        );
        assert!(
            (f.force.y - (-(-1e5 * 1e-5 + 2e6 * -2e-5) - (5.0 * 1e-3 + 300.0 * 3e-3))).abs()
                < 1e-12
        );
        let bad = JournalState {
            position: Vector2::new(f64::NAN, 0.0),
            ..s
        };
        assert!(b.force_and_jacobian(&bad, 0.0).is_err());
    }
}
