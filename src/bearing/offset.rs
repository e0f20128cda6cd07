//! A bearing as installed off the nominal shaft axis: its housing centre
//! displaced by `o = (o_x, o_y)` (m, the frame of the journal coordinates;
//! for a horizontal machine with gravity along −y, `o_y` is the elevation).
//!
//! Every law of the bearing — film, contact, coefficients — sees the journal
//! relative to the displaced centre, `F(q − o, q̇)`: the wrapper subtracts
//! the offset from the journal coordinates it is handed and passes the rest
//! (pad tilts, rates, speed) through unchanged, so the Jacobians are the
//! bearing's own. It is the one place an offset enters a nonlinear bearing;
//! a bearing without an offset is never wrapped (its numbers stay bit for
//! bit what they were).

use super::{Bearing, BearingError, BearingEval, BearingReport, contact::ContactExtent};

/// Largest number of coordinates shifted on the stack: a journal and 18 pads
/// (the most pads a model may give); more would be shifted in a heap copy.
const ON_STACK: usize = 2 + 18;

/// `bearing` with its centre at `centre` (m).
#[derive(Debug)]
pub struct OffsetBearing {
    /// The bearing about its own centre.
    pub inner: Box<dyn Bearing>,
    /// Housing centre `(o_x, o_y)` (m) off the nominal axis.
    pub centre: [f64; 2],
}

/// `bearing` installed with its centre at `centre` (m): itself when the
/// offset is zero, otherwise wrapped in an [`OffsetBearing`].
pub fn installed(bearing: Box<dyn Bearing>, centre: [f64; 2]) -> Box<dyn Bearing> {
    if centre == [0.0, 0.0] {
        bearing
    } else {
        Box::new(OffsetBearing {
            inner: bearing,
            centre,
        })
    }
}

impl OffsetBearing {
    /// Call `f` with `q` relative to the centre (`q[0] − o_x`, `q[1] − o_y`,
    /// the internal coordinates unchanged).
    fn relative<R>(&self, q: &[f64], f: impl FnOnce(&[f64]) -> R) -> R {
        let shift = |buf: &mut [f64]| {
            if buf.len() >= 2 {
                buf[0] -= self.centre[0];
                buf[1] -= self.centre[1];
            }
        };
        if q.len() <= ON_STACK {
            let mut buf = [0.0; ON_STACK];
            let buf = &mut buf[..q.len()];
            buf.copy_from_slice(q);
            shift(buf);
            f(buf)
        } else {
            let mut buf = q.to_vec();
            shift(&mut buf);
            f(&buf)
        }
    }
}

impl Bearing for OffsetBearing {
    fn internal_dofs(&self) -> usize {
        self.inner.internal_dofs()
    }

    fn internal_mass(&self, m: usize) -> f64 {
        self.inner.internal_mass(m)
    }

    fn evaluate(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<(), BearingError> {
        self.relative(q, |q| self.inner.evaluate(q, qdot, speed, out))
    }

    fn is_linear(&self) -> bool {
        self.inner.is_linear()
    }

    fn guess_internal(&self, journal: [f64; 2], speed: f64, internal: &mut [f64]) {
        let relative = [journal[0] - self.centre[0], journal[1] - self.centre[1]];
        self.inner.guess_internal(relative, speed, internal);
    }

    fn reseat_internal(&self, q: &mut [f64], speed: f64) -> bool {
        let (x, y) = (q[0], q[1]);
        q[0] = x - self.centre[0];
        q[1] = y - self.centre[1];
        let moved = self.inner.reseat_internal(q, speed);
        // The journal as it was, bit for bit (not re-added).
        q[0] = x;
        q[1] = y;
        moved
    }

    fn resting_contact(&self, direction: [f64; 2]) -> Option<(f64, f64)> {
        self.inner.resting_contact(direction)
    }

    fn contact_extent(&self, q: &[f64], qdot: &[f64], speed: f64) -> Option<ContactExtent> {
        self.relative(q, |q| self.inner.contact_extent(q, qdot, speed))
    }

    /// The bearing's own start moved to the centre; without one, the journal
    /// at the displaced centre (the pads at their guess there).
    fn equilibrium_start(&self, load: [f64; 2], speed: f64) -> Option<Vec<f64>> {
        let mut q = self
            .inner
            .equilibrium_start(load, speed)
            .unwrap_or_else(|| {
                let mut q = vec![0.0; 2 + self.inner.internal_dofs()];
                self.inner.guess_internal([0.0, 0.0], speed, &mut q[2..]);
                q
            });
        q[0] += self.centre[0];
        q[1] += self.centre[1];
        Some(q)
    }

    fn report(&self, q: &[f64], qdot: &[f64], speed: f64, eval: &BearingEval) -> BearingReport {
        self.relative(q, |q| self.inner.report(q, qdot, speed, eval))
    }

    fn forces(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<(), BearingError> {
        self.relative(q, |q| self.inner.forces(q, qdot, speed, out))
    }

    fn cheap_forces(&self) -> bool {
        self.inner.cheap_forces()
    }

    fn internal_balance(
        &self,
        m: usize,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
    ) -> Option<Result<[f64; 3], BearingError>> {
        self.relative(q, |q| self.inner.internal_balance(m, q, qdot, speed))
    }

    fn output(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<BearingReport, BearingError> {
        self.relative(q, |q| self.inner.output(q, qdot, speed, out))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::{BearingKind, PlainBearing};

    fn plain() -> BearingKind {
        BearingKind::Plain(PlainBearing {
            radius: 0.05,
            length: 0.03,
            clearance: 1e-4,
            viscosity: 0.02,
            contact: None,
        })
    }

    /// The installed bearing at `q` gives what the bearing gives at `q − o`,
    /// bit for bit: force, Jacobians and report.
    #[test]
    fn the_film_sees_the_journal_relative_to_the_displaced_centre() {
        let o = [2e-5, -3e-5];
        let shifted = installed(plain().build(), o);
        let own = plain().build();
        let (q, qd) = ([1e-5, -7e-5], [1e-3, -2e-3]);
        let mut a = BearingEval::new(2);
        let mut b = BearingEval::new(2);
        shifted.evaluate(&q, &qd, 300.0, &mut a).unwrap();
        let rel = [q[0] - o[0], q[1] - o[1]];
        own.evaluate(&rel, &qd, 300.0, &mut b).unwrap();
        assert_eq!(a, b);
        assert_eq!(
            shifted.report(&q, &qd, 300.0, &a),
            own.report(&rel, &qd, 300.0, &b)
        );
        // The centred journal of the displaced bearing: ε = |o|/C.
        let r = shifted.report(&o, &[0.0; 2], 300.0, &{
            let mut e = BearingEval::new(2);
            shifted.evaluate(&o, &[0.0; 2], 300.0, &mut e).unwrap();
            e
        });
        assert_eq!(r.eccentricity, 0.0);
        let start = shifted.equilibrium_start([0.0, -100.0], 300.0).unwrap();
        assert_eq!(&start[..2], &o);
    }

    #[test]
    fn a_zero_offset_leaves_the_bearing_unwrapped() {
        let b = installed(plain().build(), [0.0, 0.0]);
        assert!(format!("{b:?}").starts_with("PlainBearing"));
    }
}
