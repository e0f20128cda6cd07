//! Whether a reduced (Craig–Bampton) rotor is inside the range it was
//! validated for, and how far it is from the full one.
//!
//! The rule ([`VALIDITY_FACTOR`]): the kept fixed-interface modes must reach
//! ten times the highest frequency of the motion, the running speed and any
//! whirl. The error at a frequency is measured, not guessed: every force of
//! a transient acts on a kept node (bearings, rubs, unbalance planes; gravity
//! is static, and static condensation is exact) and every output is read
//! there (journals, probes), so the receptance `H(ω)` between the
//! translations of the kept nodes, `Z(ω) H = I`,
//! `Z(ω) = K + K_b − ω² M + iω (C + C_b + Ω G)` (`K_b`, `C_b` the bearings'
//! coefficients at the static equilibrium at spin `Ω`, pads condensed at `ω`),
//! is what the reduction approximates for motion at `ω`; its error is
//! `e(ω) = max |H_r − H_f| / max |H_f|` over the entries ([`receptance_errors`]).
//! During a run the frequency of the motion is followed by
//! [`MotionFrequency`].

use std::collections::VecDeque;

use nalgebra::Complex;

use crate::bearing::equilibrium::condensed_coefficients;
use crate::fe::{DOF_X, DOF_Y};
use crate::linalg::{BandMatrix, LinalgError, map_to_complex};
use crate::rotor::Rotor;
pub use crate::rotor::VALIDITY_FACTOR;

use super::error::SolverError;
use super::options::SolverOptions;
use super::state::SimState;
use super::statics::{Equilibrium, equilibrium};

/// Why the error of a reduction could not be measured.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ReductionCheckError {
    /// The second rotor is not a reduction of the first.
    #[error("{0}")]
    NotAReduction(String),
    /// No static equilibrium to linearize at.
    #[error("reduction error at {speed} rad/s: {source}")]
    Equilibrium { speed: f64, source: SolverError },
    /// The dynamic stiffness is singular (an unsupported rotor, an undamped resonance).
    #[error("reduction error at {frequency} rad/s: {source}")]
    Linalg { frequency: f64, source: LinalgError },
}

/// The relative receptance error `e(ω)` of `reduced` against `full` (the
/// rotor it was reduced from) at each excitation frequency of `frequencies`
/// (rad/s), spinning at `speed` (rad/s), the fluid-film bearings linearized
/// once at the static equilibrium at `speed` (the same for both rotors).
pub fn receptance_errors(
    full: &Rotor,
    reduced: &Rotor,
    speed: f64,
    frequencies: &[f64],
) -> Result<Vec<f64>, ReductionCheckError> {
    let Some(reduction) = reduced.reduction.as_ref() else {
        return Err(ReductionCheckError::NotAReduction(
            "the rotor to check is not reduced".into(),
        ));
    };
    if full.reduction.is_some() || full.dof_count() != reduction.full_map.free_count() {
        return Err(ReductionCheckError::NotAReduction(
            "the reference is not the full rotor the reduction was made from".into(),
        ));
    }
    let at = if full.nonlinear_bearings.is_empty() {
        None
    } else {
        let eq = equilibrium(full, speed, &SolverOptions::default(), None)
            .map_err(|source| ReductionCheckError::Equilibrium { speed, source })?;
        Some(eq)
    };
    // The translations of the kept nodes, in both numberings.
    let (full_dofs, reduced_dofs): (Vec<usize>, Vec<usize>) = reduction
        .kept_nodes
        .iter()
        .flat_map(|&node| [(node, DOF_X), (node, DOF_Y)])
        .filter_map(|(node, k)| Some((full.dofs.free(node, k)?, reduced.dofs.free(node, k)?)))
        .unzip();
    frequencies
        .iter()
        .map(|&w| {
            let hf = receptance(full, at.as_ref(), speed, w, &full_dofs)?;
            let hr = receptance(reduced, at.as_ref(), speed, w, &reduced_dofs)?;
            let size = hf.iter().fold(0.0f64, |m, h| m.max(h.norm()));
            let diff = hf
                .iter()
                .zip(&hr)
                .fold(0.0f64, |m, (a, b)| m.max((a - b).norm()));
            Ok(if size > 0.0 { diff / size } else { 0.0 })
        })
        .collect()
}

/// `H(ω)` between the coordinates `dofs` of `rotor` (row-major), its
/// nonlinear bearings replaced by their coefficients at `at`.
fn receptance(
    rotor: &Rotor,
    at: Option<&Equilibrium>,
    speed: f64,
    w: f64,
    dofs: &[usize],
) -> Result<Vec<Complex<f64>>, ReductionCheckError> {
    let mut k = rotor.stiffness.clone();
    let mut d = rotor.damping.clone();
    for (bearing, eval) in at.map_or(&[][..], |eq| &eq.bearings[..]) {
        let (kb, cb) = condensed_coefficients(eval, w);
        let node = rotor.model.bearings[*bearing].node;
        let journal = [rotor.dofs.free(node, DOF_X), rotor.dofs.free(node, DOF_Y)];
        for (a, ja) in journal.iter().enumerate() {
            for (b, jb) in journal.iter().enumerate() {
                if let (Some(i), Some(j)) = (ja, jb) {
                    k.add(*i, *j, kb[(a, b)]);
                    d.add(*i, *j, cb[(a, b)]);
                }
            }
        }
    }
    d.scale_add(speed, &rotor.gyroscopic);
    let mut z: BandMatrix<Complex<f64>> = map_to_complex(&k);
    z.scale_add(Complex::new(-w * w, 0.0), &map_to_complex(&rotor.mass));
    z.scale_add(Complex::new(0.0, w), &map_to_complex(&d));
    let lu = z.lu().map_err(|source| ReductionCheckError::Linalg {
        frequency: w,
        source,
    })?;
    let mut h = Vec::with_capacity(dofs.len() * dofs.len());
    let mut column = vec![Complex::new(0.0, 0.0); rotor.dof_count()];
    for &j in dofs {
        column.fill(Complex::new(0.0, 0.0));
        column[j] = Complex::new(1.0, 0.0);
        lu.solve_in_place(&mut column);
        h.extend(dofs.iter().map(|&i| column[i]));
    }
    Ok(h)
}

/// Fewest samples [`MotionFrequency`] averages over.
pub const MOTION_SAMPLES: usize = 8;
/// Revolutions of the running speed [`MotionFrequency`] averages over, so
/// that a start from rest (velocities zero, accelerations not) is averaged
/// into the motion that follows; the window is kept within
/// [`MOTION_WINDOW`].
pub const MOTION_REVOLUTIONS: f64 = 2.0;
/// Shortest and longest averaging window of [`MotionFrequency`] (s).
pub const MOTION_WINDOW: (f64, f64) = (0.01, 1.0);

/// The RMS frequency of the motion at the kept nodes of a reduced rotor,
/// `ω = √(∫|ü|² dt / ∫|u̇|² dt)` over their translations and the last
/// [`MOTION_REVOLUTIONS`] revolutions (at least [`MOTION_SAMPLES`] samples of
/// the state): exactly `ω` for harmonic motion at `ω` (circular orbits at
/// any sample, elliptic ones on average), and for a mixture the frequency of
/// the components that carry the accelerations, whatever the static offset:
/// the running speed for a synchronous response, the whirl frequency of oil
/// whirl or whip, the dry-whip frequency of a rub, the natural frequencies
/// ringing after a start.
#[derive(Debug, Clone)]
pub struct MotionFrequency {
    dofs: Vec<usize>,
    /// `(t, |u̇|², |ü|²)` of each sample.
    samples: VecDeque<(f64, f64, f64)>,
    /// Trapezoidal `∫|u̇|² dt` and `∫|ü|² dt` over the samples.
    integrals: (f64, f64),
    window: f64,
}

/// Trapezoidal integrals of `|u̇|²` and `|ü|²` between samples `p` and `q`.
fn trapezoid(p: &(f64, f64, f64), q: &(f64, f64, f64)) -> (f64, f64) {
    let dt = q.0 - p.0;
    (0.5 * dt * (p.1 + q.1), 0.5 * dt * (p.2 + q.2))
}

impl MotionFrequency {
    /// A monitor of the translations of `rotor`'s kept nodes (none for the
    /// full rotor, which needs no monitor).
    pub fn new(rotor: &Rotor) -> Self {
        let dofs = rotor.reduction.as_ref().map_or(Vec::new(), |r| {
            r.kept_nodes
                .iter()
                .flat_map(|&node| [DOF_X, DOF_Y].map(|k| rotor.dofs.free(node, k)))
                .flatten()
                .collect()
        });
        Self {
            dofs,
            samples: VecDeque::new(),
            integrals: (0.0, 0.0),
            window: MOTION_WINDOW.1,
        }
    }

    /// Add the state reached while spinning at `speed` (rad/s).
    pub fn push(&mut self, state: &SimState, speed: f64) {
        if self.dofs.is_empty() {
            return;
        }
        let sum = |v: &[f64]| self.dofs.iter().map(|&i| v[i] * v[i]).sum::<f64>();
        let revolutions = MOTION_REVOLUTIONS * std::f64::consts::TAU / speed.abs();
        self.window = revolutions.clamp(MOTION_WINDOW.0, MOTION_WINDOW.1);
        let sample = (state.time, sum(&state.ud), sum(&state.udd));
        if let Some(last) = self.samples.back() {
            let (v, a) = trapezoid(last, &sample);
            self.integrals = (self.integrals.0 + v, self.integrals.1 + a);
        }
        self.samples.push_back(sample);
        while self.samples.len() > MOTION_SAMPLES && state.time - self.samples[1].0 >= self.window {
            if let Some(first) = self.samples.pop_front() {
                let (v, a) = trapezoid(&first, &self.samples[0]);
                self.integrals = (self.integrals.0 - v, self.integrals.1 - a);
            }
        }
    }

    /// Forget the samples (after a rollback or a jump of the state).
    pub fn clear(&mut self) {
        self.samples.clear();
        self.integrals = (0.0, 0.0);
    }

    /// The RMS frequency (rad/s), once the samples cover the window (and
    /// at least [`MOTION_SAMPLES`] of them) and the kept nodes move at all.
    pub fn frequency(&self) -> Option<f64> {
        let (first, last) = (self.samples.front()?, self.samples.back()?);
        if self.samples.len() < MOTION_SAMPLES || last.0 - first.0 < self.window * (1.0 - 1e-9) {
            return None;
        }
        let (v2, a2) = self.integrals;
        (v2 > 0.0 && a2.is_finite()).then(|| (a2.max(0.0) / v2).sqrt())
    }
}

/// What left the validated range of a reduced rotor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Excursion {
    /// The running speed (rad/s).
    Speed(f64),
    /// The frequency of the motion at the kept nodes (rad/s, [`MotionFrequency`]).
    Motion(f64),
}

impl Excursion {
    /// The frequency that left the range (rad/s).
    pub fn frequency(&self) -> f64 {
        match *self {
            Excursion::Speed(w) | Excursion::Motion(w) => w,
        }
    }
}

/// Watches a run on a reduced rotor: [`ValidityWatch::check`] reports the
/// running speed or the motion's frequency leaving the validated range
/// (the highest kept mode over [`VALIDITY_FACTOR`]) once per excursion; back
/// below half the limit, the next excursion is reported again. Motion
/// within 5 % of the running speed is the speed's excursion.
#[derive(Debug, Clone)]
pub struct ValidityWatch {
    limit: f64,
    motion: MotionFrequency,
    outside: bool,
}

impl ValidityWatch {
    /// A watch for `rotor` (never reports for the full rotor).
    pub fn new(rotor: &Rotor) -> Self {
        Self {
            limit: rotor
                .reduction
                .as_ref()
                .map_or(f64::INFINITY, |r| r.validated_frequency()),
            motion: MotionFrequency::new(rotor),
            outside: false,
        }
    }

    /// The highest frequency of motion (rad/s) the rotor is valid for.
    pub fn limit(&self) -> f64 {
        self.limit
    }

    /// Start over (after a rollback): samples forgotten, re-armed.
    pub fn reset(&mut self) {
        self.motion.clear();
        self.outside = false;
    }

    /// The watch as numbers, for the FMU state (a restored state then warns
    /// exactly as the run that saved it): whether it is outside (1) or not
    /// (0), the motion window (s), the two integrals, then `(t, |u̇|², |ü|²)`
    /// of each sample.
    pub fn image(&self) -> Vec<f64> {
        let m = &self.motion;
        let mut out = vec![
            f64::from(u8::from(self.outside)),
            m.window,
            m.integrals.0,
            m.integrals.1,
        ];
        for &(t, v, a) in &m.samples {
            out.extend_from_slice(&[t, v, a]);
        }
        out
    }

    /// Why `image` is not one [`ValidityWatch::image`] gives, if it is not:
    /// its length, a non-finite or negative value, a flag other than 0 or 1,
    /// or times out of order.
    pub fn check_image(image: &[f64]) -> Result<(), String> {
        if image.len() < 4 || (image.len() - 4) % 3 != 0 {
            return Err(format!(
                "validity watch of {} values (4 plus 3 per sample)",
                image.len()
            ));
        }
        if image[0] != 0.0 && image[0] != 1.0 {
            return Err(format!("validity watch flag {}", image[0]));
        }
        if let Some(x) = image.iter().find(|x| !x.is_finite()) {
            return Err(format!("validity watch value {x}"));
        }
        let samples: Vec<&[f64]> = image[4..].chunks(3).collect();
        if samples.windows(2).any(|w| w[1][0] < w[0][0]) {
            return Err("validity watch samples out of time order".into());
        }
        Ok(())
    }

    /// Take the watch of `image` (checked by [`ValidityWatch::check_image`]).
    pub fn set_image(&mut self, image: &[f64]) -> Result<(), String> {
        Self::check_image(image)?;
        self.outside = image[0] == 1.0;
        let m = &mut self.motion;
        m.window = image[1];
        m.integrals = (image[2], image[3]);
        m.samples = image[4..].chunks(3).map(|s| (s[0], s[1], s[2])).collect();
        Ok(())
    }

    /// Add the state reached at spin `speed` (rad/s); `Some` when the speed
    /// or the motion's frequency has just left the validated range.
    pub fn check(&mut self, speed: f64, state: &SimState) -> Option<Excursion> {
        if !self.limit.is_finite() {
            return None;
        }
        self.motion.push(state, speed);
        let motion = self.motion.frequency().unwrap_or(0.0);
        let highest = speed.abs().max(motion);
        if self.outside {
            self.outside = highest > 0.5 * self.limit;
            return None;
        }
        if highest <= self.limit {
            return None;
        }
        self.outside = true;
        Some(if motion <= 1.05 * speed.abs() {
            Excursion::Speed(speed.abs())
        } else {
            Excursion::Motion(motion)
        })
    }
}

/// One sentence for the CLI and the FMU log: how far `reduced` is from
/// `full` (the rotor it was reduced from) for motion at `frequency` (rad/s)
/// while spinning at `speed` (rad/s), from [`receptance_errors`].
pub fn error_estimate(full: &Rotor, reduced: &Rotor, speed: f64, frequency: f64) -> String {
    let hz = frequency.abs() / std::f64::consts::TAU;
    match receptance_errors(full, reduced, speed, &[frequency.abs()]) {
        Ok(e) => format!(
            "at {hz:.1} Hz its response at the kept nodes differs from the full rotor's by {:.1e} (receptance, bearings linearized at the static equilibrium at {:.0} rpm)",
            e[0],
            speed.abs() * 30.0 / std::f64::consts::PI
        ),
        Err(e) => format!("no error estimate at {hz:.1} Hz ({e})"),
    }
}

/// One sentence for the CLI and the FMU log on an [`Excursion`] of
/// `reduced` spinning at `speed` (rad/s): what left the validated range, the
/// error estimate there, and the mode count that would reach it.
pub fn excursion_report(full: &Rotor, reduced: &Rotor, speed: f64, excursion: Excursion) -> String {
    let hz = |w: f64| w / std::f64::consts::TAU;
    let rpm = |w: f64| w * 30.0 / std::f64::consts::PI;
    let w = excursion.frequency();
    let what = match excursion {
        Excursion::Speed(_) => format!("the running speed {:.0} rpm ({:.1} Hz)", rpm(w), hz(w)),
        Excursion::Motion(_) => format!(
            "the motion at the kept nodes (RMS frequency {:.1} Hz, {:.2}× the running speed)",
            hz(w),
            w / speed.abs().max(f64::MIN_POSITIVE)
        ),
    };
    let (limit, highest, modes) = reduced.reduction.as_ref().map_or((0.0, 0.0, 0), |r| {
        (r.validated_frequency(), r.highest_frequency(), r.modes)
    });
    let needed = match full.modes_for(w) {
        Ok(m) if m > modes => format!("; {m} fixed-interface modes reach it"),
        Ok(_) => "; the interior has no more modes: run the full rotor".into(),
        Err(e) => format!("; ({e})"),
    };
    format!(
        "{what} is above the {:.1} Hz ({:.0} rpm) the reduced rotor is validated for (its highest kept mode, {:.1} Hz, over {VALIDITY_FACTOR}): {}{needed}",
        hz(limit),
        rpm(limit),
        hz(highest),
        error_estimate(full, reduced, speed, w)
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::RotorModel;

    /// The Jeffcott rotor reduced to 4 modes (kept: nodes 1, 5, 9).
    fn reduced() -> Rotor {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/jeffcott.toml");
        let model = RotorModel::from_file(std::path::Path::new(path)).unwrap();
        Rotor::new(model).unwrap().reduced(4).unwrap()
    }

    /// A state whose kept translations move as `x + i y = Σ a_k e^{i ω_k t}`
    /// (plus an elliptic part `b cos ωt` in x only for the first term).
    fn state(rotor: &Rotor, t: f64, parts: &[(f64, f64)], ellipse: f64) -> SimState {
        let n = rotor.dof_count();
        let mut s = SimState {
            time: t,
            u: vec![1e-4; n],
            ud: vec![0.0; n],
            udd: vec![0.0; n],
            p: vec![],
            pd: vec![],
            pdd: vec![],
            spin_angle: 0.0,
            speed: 0.0,
            speed_rate: 0.0,
            speed_time: 0.0,
            unbalance: vec![],
            unbalance_rate: vec![],
            unbalance_phase: vec![],
            loads: vec![],
            load_rates: vec![],
            twist: vec![],
            twist_rate: vec![],
            twist_accel: vec![],
            twist_torque: vec![],
            stuck: 0.0,
            factor_step: 0.0,
            factor_speed: 0.0,
            udd_previous: vec![],
            contact_reported: vec![],
            table_warned: vec![],
            static_load: vec![],
            harmonic_phase: vec![],
            harmonic_frequency: vec![],
            step_proposal: 0.0,
            pad_balancing: 0.0,
            chord_pause: 0.0,
        };
        for &node in &rotor.reduction.as_ref().unwrap().kept_nodes {
            let (ix, iy) = (
                rotor.dofs.free(node, DOF_X).unwrap(),
                rotor.dofs.free(node, DOF_Y).unwrap(),
            );
            for (k, &(a, w)) in parts.iter().enumerate() {
                let (sn, cs) = (w * t).sin_cos();
                let bx = if k == 0 { ellipse } else { 0.0 };
                s.ud[ix] += -(a + bx) * w * sn;
                s.ud[iy] += a * w * cs;
                s.udd[ix] += -(a + bx) * w * w * cs;
                s.udd[iy] += -a * w * w * sn;
            }
        }
        s
    }

    /// Harmonic motion at ω reads ω: a circular orbit at once, an elliptic
    /// one over the window (to the sampling's quadrature error); a mixture
    /// reads `√(Σ a²ω⁴ / Σ a²ω²)`; the window is two revolutions.
    #[test]
    fn the_motion_frequency_of_known_motions() {
        let rotor = reduced();
        let speed = 300.0;
        let dt = 1e-4;
        for (parts, ellipse, expected, tol) in [
            (vec![(1e-5, 300.0)], 0.0, 300.0, 1e-12),
            (vec![(1e-5, 150.0)], 0.5e-5, 150.0, 2e-3),
            // The cross terms of a mixture average out over the window only
            // to about 1/(Δω T) = 1.4 % of themselves.
            (vec![(1e-5, 300.0), (2e-6, 2000.0)], 0.0, f64::NAN, 1e-2),
        ] {
            let mut m = MotionFrequency::new(&rotor);
            let window = 2.0 * std::f64::consts::TAU / speed;
            let mut k = 0;
            while (k as f64) * dt < window * 0.99 {
                m.push(&state(&rotor, k as f64 * dt, &parts, ellipse), speed);
                assert_eq!(m.frequency(), None, "no estimate before the window is full");
                k += 1;
            }
            for _ in 0..400 {
                m.push(&state(&rotor, k as f64 * dt, &parts, ellipse), speed);
                k += 1;
            }
            let expected = if expected.is_nan() {
                let (num, den) = parts.iter().fold((0.0, 0.0), |(n, d), &(a, w)| {
                    (n + a * a * w.powi(4), d + a * a * w * w)
                });
                (num / den).sqrt()
            } else {
                expected
            };
            let got = m.frequency().unwrap();
            assert!(
                (got - expected).abs() <= tol * expected,
                "{parts:?}: {got} against {expected}"
            );
        }
        // The full rotor has nothing to watch.
        let full = Rotor::new(reduced().model.clone()).unwrap();
        let mut m = MotionFrequency::new(&full);
        m.push(&state(&rotor, 0.0, &[(1e-5, 1.0)], 0.0), 1.0);
        assert_eq!(m.frequency(), None);
    }

    /// The watch reports the speed leaving the validated range once, stays
    /// quiet while it is outside, and is re-armed below half the limit.
    #[test]
    fn the_watch_reports_each_excursion_once() {
        let rotor = reduced();
        let limit = rotor.reduction.as_ref().unwrap().validated_frequency();
        let mut watch = ValidityWatch::new(&rotor);
        assert_eq!(watch.limit(), limit);
        let at = |t: f64, w: f64| state(&rotor, t, &[(1e-6, w)], 0.0);
        let mut t = 0.0;
        let mut step = |watch: &mut ValidityWatch, speed: f64| {
            t += 1e-4;
            watch.check(speed, &at(t, speed))
        };
        assert_eq!(step(&mut watch, 0.9 * limit), None);
        assert_eq!(
            step(&mut watch, 1.1 * limit),
            Some(Excursion::Speed(1.1 * limit))
        );
        assert_eq!(step(&mut watch, 2.0 * limit), None);
        assert_eq!(step(&mut watch, 0.6 * limit), None);
        assert_eq!(step(&mut watch, 1.2 * limit), None);
        assert_eq!(step(&mut watch, 0.4 * limit), None);
        assert_eq!(
            step(&mut watch, 1.3 * limit),
            Some(Excursion::Speed(1.3 * limit))
        );
        watch.reset();
        assert_eq!(
            step(&mut watch, 1.3 * limit),
            Some(Excursion::Speed(1.3 * limit))
        );
    }
}
