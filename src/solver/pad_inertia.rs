//! The inertia of a bearing's internal coordinates within a Newmark step
//! (a tilting pad's moment of inertia on its tilt, its mass on its pivot's
//! radial spring, [`Bearing::internal_mass`]).
//!
//! The balance of internal coordinate `i` with mass `M_i` is
//! `Q_i(q, q̇) − M_i p̈_i = 0`. Within a step of Newmark's average
//! acceleration (`ṗ = a1 (p − pₙ) − ṗₙ`, `p̈ = a0 (p − pₙ) − a2 ṗₙ − p̈ₙ`,
//! `a0 = a1²`, `a2 = 2 a1`) the acceleration is a function of the rate,
//! `p̈ = a1 (ṗ − ṗₙ) − p̈ₙ`, so the inertia is a force linear in the rate:
//! `−M_i p̈_i = −M_i a1 ṗ_i + M_i (a1 ṗₙ + p̈ₙ)`, with the damping `M_i a1`
//! (in the step's `K + a1 C` that is `a0 M`). [`InertialBearing`] adds both
//! to what its bearing gives while a step is open
//! ([`InertialBearing::begin_step`]), so every Newton path of the step (full,
//! condensed, the pads' own settle) integrates the pads' inertia without a
//! change; outside a step (the statics, outputs) and for massless
//! coordinates it is its bearing, bit for bit.

use crate::bearing::contact::ContactExtent;
use crate::bearing::{Bearing, BearingError, BearingEval, BearingReport};

/// A bearing with the inertia of its internal coordinates added within a
/// Newmark step (module docs).
#[derive(Debug)]
pub(super) struct InertialBearing {
    inner: Box<dyn Bearing>,
    /// The internal coordinates' masses (kg); empty when all are massless.
    mass: Vec<f64>,
    /// Newmark's `a1 = 2/h` of the open step; zero outside a step.
    a1: f64,
    /// Each coordinate's `M_i (a1 ṗₙ + p̈ₙ)` (N) of the open step.
    carried: Vec<f64>,
}

impl InertialBearing {
    /// `inner` with its internal coordinates' masses.
    pub fn new(inner: Box<dyn Bearing>) -> Self {
        let mass: Vec<f64> = (0..inner.internal_dofs())
            .map(|m| inner.internal_mass(m))
            .collect();
        let mass = if mass.iter().any(|&m| m != 0.0) {
            mass
        } else {
            Vec::new()
        };
        Self {
            carried: vec![0.0; mass.len()],
            inner,
            mass,
            a1: 0.0,
        }
    }

    /// Open a Newmark step with `a1 = 2/h` from the internal rates `pd`
    /// and accelerations `pdd` at its start (this bearing's slices).
    pub fn begin_step(&mut self, a1: f64, pd: &[f64], pdd: &[f64]) {
        if self.mass.is_empty() {
            return;
        }
        self.a1 = a1;
        for (i, c) in self.carried.iter_mut().enumerate() {
            *c = self.mass[i] * (a1 * pd[i] + pdd[i]);
        }
    }

    /// Close the step: the bearing alone again.
    pub fn end_step(&mut self) {
        self.a1 = 0.0;
    }

    fn active(&self) -> bool {
        self.a1 != 0.0
    }

    /// The inertia forces at the rates `qdot` into `out.force`.
    fn add_forces(&self, qdot: &[f64], out: &mut BearingEval) {
        for (i, &m) in self.mass.iter().enumerate() {
            out.force[2 + i] += self.carried[i] - m * self.a1 * qdot[2 + i];
        }
    }
}

impl Bearing for InertialBearing {
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
        self.inner.evaluate(q, qdot, speed, out)?;
        if self.active() {
            self.add_forces(qdot, out);
            let n = out.n();
            for (i, &m) in self.mass.iter().enumerate() {
                out.damping[(2 + i) * n + 2 + i] += m * self.a1;
            }
        }
        Ok(())
    }

    fn is_linear(&self) -> bool {
        self.inner.is_linear()
    }

    fn internal_balance(
        &self,
        m: usize,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
    ) -> Option<Result<[f64; 3], BearingError>> {
        let balance = self.inner.internal_balance(m, q, qdot, speed)?;
        if !self.active() {
            return Some(balance);
        }
        Some(balance.map(|[f, k, c]| {
            let mass = self.mass[m];
            [
                f + self.carried[m] - mass * self.a1 * qdot[2 + m],
                k,
                c + mass * self.a1,
            ]
        }))
    }

    fn guess_internal(&self, journal: [f64; 2], speed: f64, internal: &mut [f64]) {
        self.inner.guess_internal(journal, speed, internal);
    }

    fn reseat_internal(&self, q: &mut [f64], speed: f64) -> bool {
        self.inner.reseat_internal(q, speed)
    }

    fn resting_contact(&self, direction: [f64; 2]) -> Option<(f64, f64)> {
        self.inner.resting_contact(direction)
    }

    fn contact_extent(&self, q: &[f64], qdot: &[f64], speed: f64) -> Option<ContactExtent> {
        self.inner.contact_extent(q, qdot, speed)
    }

    fn equilibrium_start(&self, load: [f64; 2], speed: f64) -> Option<Vec<f64>> {
        self.inner.equilibrium_start(load, speed)
    }

    fn report(&self, q: &[f64], qdot: &[f64], speed: f64, eval: &BearingEval) -> BearingReport {
        self.inner.report(q, qdot, speed, eval)
    }

    fn forces(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<(), BearingError> {
        self.inner.forces(q, qdot, speed, out)?;
        if self.active() {
            self.add_forces(qdot, out);
        }
        Ok(())
    }

    fn cheap_forces(&self) -> bool {
        self.inner.cheap_forces()
    }

    fn output(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<BearingReport, BearingError> {
        let report = self.inner.output(q, qdot, speed, out)?;
        if self.active() {
            self.add_forces(qdot, out);
        }
        Ok(report)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A massive internal coordinate on a linear spring `k`: the Newmark
    /// residual `−k p − M p̈` with `p̈` from Newmark's rates equals what the
    /// wrapper's force gives at the Newmark rate, and its damping `M a1`
    /// is the derivative of that force along the rate.
    #[derive(Debug)]
    struct Spring;
    impl Bearing for Spring {
        fn internal_dofs(&self) -> usize {
            1
        }
        fn internal_mass(&self, _m: usize) -> f64 {
            2.5
        }
        fn evaluate(
            &self,
            q: &[f64],
            _qdot: &[f64],
            _speed: f64,
            out: &mut BearingEval,
        ) -> Result<(), BearingError> {
            out.force.fill(0.0);
            out.stiffness.fill(0.0);
            out.damping.fill(0.0);
            out.force[2] = -1e3 * q[2];
            out.stiffness[8] = 1e3;
            Ok(())
        }
        fn is_linear(&self) -> bool {
            false
        }
    }

    #[test]
    fn the_inertia_force_is_minus_mass_times_the_newmark_acceleration() {
        let mut b = InertialBearing::new(Box::new(Spring));
        let h = 1e-3;
        let (a0, a1, a2) = (4.0 / (h * h), 2.0 / h, 4.0 / h);
        let (p0, pd0, pdd0) = (1e-5, 3e-3, -0.7);
        let p = 1.2e-5;
        let pd = a1 * (p - p0) - pd0;
        let pdd = a0 * (p - p0) - a2 * pd0 - pdd0;
        let mut out = BearingEval::new(3);
        let q = [0.0, 0.0, p];
        let qd = [0.0, 0.0, pd];
        b.evaluate(&q, &qd, 10.0, &mut out).unwrap();
        assert_eq!(out.force[2], -1e3 * p, "outside a step: the bearing alone");
        b.begin_step(a1, &[pd0], &[pdd0]);
        b.evaluate(&q, &qd, 10.0, &mut out).unwrap();
        let want = -1e3 * p - 2.5 * pdd;
        assert!(
            (out.force[2] - want).abs() <= 1e-9 * want.abs(),
            "{} {want}",
            out.force[2]
        );
        assert_eq!(out.damping[8], 2.5 * a1);
        assert!(b.internal_balance(0, &q, &qd, 10.0).is_none());
        b.end_step();
        b.evaluate(&q, &qd, 10.0, &mut out).unwrap();
        assert_eq!(out.force[2], -1e3 * p);
    }
}
