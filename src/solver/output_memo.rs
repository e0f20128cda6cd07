//! The force pass a Newton step has already made for one bearing:
//! `Bearing::forces` at the coordinates, rates and speed it was called with,
//! or `Bearing::output` there (the same forces and the report). Both are pure
//! functions of those inputs, and `report` on `forces` gives `output`'s report
//! bit for bit, so when the state's coordinates equal the key bit for bit,
//! `Simulator::outputs` takes the force (and the report, else makes it on that
//! force): the bits of `output` (a restored state, which finds no memo, calls
//! `output` and gets them).

use crate::bearing::BearingReport;

/// The last `forces` of one site and the inputs it was called with (none
/// while `q` is empty: a bearing has at least its two journal coordinates).
#[derive(Debug, Clone, Default)]
pub(super) struct OutputMemo {
    q: Vec<f64>,
    qd: Vec<f64>,
    speed: f64,
    force: Vec<f64>,
    report: Option<BearingReport>,
}

impl OutputMemo {
    /// Remember `forces(q, qd, speed) = force`, with the report when the
    /// pass was `output`.
    pub fn store(
        &mut self,
        q: &[f64],
        qd: &[f64],
        speed: f64,
        force: &[f64],
        report: Option<BearingReport>,
    ) {
        for (memo, value) in [
            (&mut self.q, q),
            (&mut self.qd, qd),
            (&mut self.force, force),
        ] {
            memo.clear();
            memo.extend_from_slice(value);
        }
        self.speed = speed;
        self.report = report;
    }

    /// Forget it (the bearing's parameters changed).
    pub fn clear(&mut self) {
        self.q.clear();
    }

    /// The remembered force and report (if made) when `q`, `qd` and `speed`
    /// are the key bit for bit.
    pub fn recall(
        &self,
        q: &[f64],
        qd: &[f64],
        speed: f64,
    ) -> Option<(&[f64], Option<BearingReport>)> {
        let same = |a: &[f64], b: &[f64]| {
            a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
        };
        (!self.q.is_empty()
            && speed.to_bits() == self.speed.to_bits()
            && same(q, &self.q)
            && same(qd, &self.qd))
        .then_some((&self.force, self.report))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recalls_only_its_own_inputs_bit_for_bit() {
        let mut memo = OutputMemo::default();
        let (q, qd) = ([1e-5, -2e-5, 3e-4], [0.1, 0.2, -0.3]);
        assert!(memo.recall(&q, &qd, 15.7).is_none());
        let report = BearingReport {
            eccentricity: 0.4,
            ..BearingReport::default()
        };
        for kept in [None, Some(report)] {
            memo.store(&q, &qd, 15.7, &[10.0, -20.0, 0.5], kept);
            let (force, got) = memo.recall(&q, &qd, 15.7).unwrap();
            assert_eq!(force, &[10.0, -20.0, 0.5]);
            assert_eq!(got, kept);
        }
        // One bit off anywhere, or −0 for +0, is another input.
        let bumped = |v: f64| f64::from_bits(v.to_bits() + 1);
        assert!(memo.recall(&q, &qd, bumped(15.7)).is_none());
        for i in 0..3 {
            let mut other = q;
            other[i] = bumped(other[i]);
            assert!(memo.recall(&other, &qd, 15.7).is_none());
            let mut other = qd;
            other[i] = bumped(other[i]);
            assert!(memo.recall(&q, &other, 15.7).is_none());
        }
        memo.store(&[0.0, 0.0], &[0.0, 0.0], 1.0, &[0.0, 0.0], None);
        assert!(memo.recall(&[-0.0, 0.0], &[0.0, 0.0], 1.0).is_none());
        assert!(memo.recall(&q, &qd, 15.7).is_none());
        memo.clear();
        assert!(memo.recall(&[0.0, 0.0], &[0.0, 0.0], 1.0).is_none());
    }
}
