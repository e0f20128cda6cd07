//! Bearing-housing vibration of a hydraulic machine set judged by ISO
//! 10816-5 (*Mechanical vibration — Evaluation of machine vibration by
//! measurements on non-rotating parts — Part 5: Machine sets in hydraulic
//! power generating and pumping plants*, 2000, Annex A, Tables A.2 to A.4;
//! the values are in `tests/data/iso_10816_5_annex_a.csv`, with their source).
//!
//! The housings' motion comes from the nonlinear transient at the operating
//! speed with every load of the model (unbalance, harmonic and static forces,
//! magnetic pull with its dynamic eccentricity): after `settle` seconds the
//! housing of each bearing on a pedestal is sampled over `record` seconds,
//! and its r.m.s. velocity (`√(mean v²)`) and peak-to-peak displacement
//! (`max − min`) are taken in each of `x` and `y`, the larger of the two
//! judged. Zone A: newly commissioned; B: unrestricted long-term operation;
//! C: unsatisfactory for long-term continuous operation; D: severe enough to
//! cause damage.

use crate::model::machine_class::HousingGroup;
use crate::rotor::Rotor;
use crate::solver::{Simulator, SolverError, SolverOptions};

/// Zone boundaries A/B, B/C and C/D of one measurement location.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZoneBoundaries {
    /// Peak-to-peak housing displacement (m), where the standard gives it
    /// (not for group 2).
    pub displacement_pp: Option<[f64; 3]>,
    /// R.m.s. housing velocity (m/s).
    pub velocity_rms: [f64; 3],
}

/// ISO 10816-5:2000 Annex A boundaries of `group` at a bearing whose housing
/// is braced against the generator stator (`stator_braced`: group 4's
/// measurement location 1) or at another main bearing.
pub fn iso_10816_5_boundaries(group: HousingGroup, stator_braced: bool) -> ZoneBoundaries {
    const UM: f64 = 1e-6;
    const MM_S: f64 = 1e-3;
    let foundation = ZoneBoundaries {
        displacement_pp: Some([30.0 * UM, 50.0 * UM, 80.0 * UM]),
        velocity_rms: [1.6 * MM_S, 2.5 * MM_S, 4.0 * MM_S],
    };
    match group {
        HousingGroup::HorizontalOnCasing => ZoneBoundaries {
            displacement_pp: None,
            velocity_rms: [2.5 * MM_S, 4.0 * MM_S, 6.4 * MM_S],
        },
        HousingGroup::VerticalOnFoundation => foundation,
        HousingGroup::VerticalUpperOnStator if stator_braced => ZoneBoundaries {
            displacement_pp: Some([65.0 * UM, 100.0 * UM, 160.0 * UM]),
            velocity_rms: [2.5 * MM_S, 4.0 * MM_S, 6.4 * MM_S],
        },
        HousingGroup::VerticalUpperOnStator => foundation,
    }
}

/// An evaluation zone of ISO 10816-5.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Zone {
    /// Newly commissioned machines.
    A,
    /// Unrestricted long-term operation.
    B,
    /// Unsatisfactory for long-term continuous operation.
    C,
    /// Severe enough to cause damage.
    D,
}

impl Zone {
    /// The zone of `value` against the boundaries A/B, B/C, C/D: at or below
    /// a boundary is the zone below it.
    pub fn of(value: f64, boundaries: [f64; 3]) -> Zone {
        match boundaries.iter().position(|&b| value <= b) {
            Some(0) => Zone::A,
            Some(1) => Zone::B,
            Some(2) => Zone::C,
            _ => Zone::D,
        }
    }

    /// Its letter.
    pub fn letter(self) -> &'static str {
        match self {
            Zone::A => "A",
            Zone::B => "B",
            Zone::C => "C",
            Zone::D => "D",
        }
    }

    /// Acceptable for long-term operation (A or B).
    pub fn acceptable(self) -> bool {
        self <= Zone::B
    }
}

/// The vibration of one bearing's housing over the recorded span.
#[derive(Debug, Clone, PartialEq)]
pub struct HousingVibration {
    /// Model bearing index.
    pub bearing: usize,
    /// Bearing name.
    pub name: String,
    /// R.m.s. velocity (m/s), the larger of `x` and `y`.
    pub velocity_rms: f64,
    /// Peak-to-peak displacement (m), the larger of `x` and `y`.
    pub displacement_pp: f64,
    /// Whether its pedestal is braced against the generator stator
    /// (`on_stator`, or it carries a magnetic pull's stator): group 4's
    /// measurement location 1.
    pub stator_braced: bool,
}

/// Samples per period of the fastest forcing (1× or a harmonic force).
pub const SAMPLES_PER_PERIOD: f64 = 128.0;

/// The housing vibration of every bearing (not seal, rub or stator) on a
/// pedestal at spin `speed`
/// (rad/s), from the transient with the model's loads: settled for `settle`
/// s after the static equilibrium, then sampled over `record` s. Empty when
/// no bearing stands on a pedestal.
pub fn housing_vibration(
    rotor: &Rotor,
    speed: f64,
    settle: f64,
    record: f64,
) -> Result<Vec<HousingVibration>, SolverError> {
    let model = &rotor.model;
    let on_pedestals: Vec<usize> = (0..model.bearings.len())
        .filter(|&k| {
            let kind = &model.bearings[k].kind;
            // Bearings only: seals, rubs and stators have no bearing housing.
            model.bearings[k].pedestal.is_some()
                && !(kind.is_magnetic_pull() || kind.is_seal() || kind.is_rub())
        })
        .collect();
    if on_pedestals.is_empty() {
        return Ok(Vec::new());
    }
    let (mut sim, dt) = sampling_simulator(rotor, speed)?;
    sim.set_speed(speed, 0.0)?;
    sim.settle_static()?;
    sim.advance_to(settle)?;
    let samples = (record / dt).round().max(1.0) as usize;
    // Per bearing: sums of vx², vy² and the extremes of x and y.
    let mut stats =
        vec![([0.0f64; 2], [f64::INFINITY; 2], [f64::NEG_INFINITY; 2]); on_pedestals.len()];
    for s in 1..=samples {
        sim.advance_to(settle + s as f64 * dt)?;
        let out = sim.outputs()?;
        for (st, &k) in stats.iter_mut().zip(&on_pedestals) {
            let h = &out.bearings[k].housing;
            for (i, (v, x)) in [(h.vx, h.x), (h.vy, h.y)].into_iter().enumerate() {
                st.0[i] += v * v;
                st.1[i] = st.1[i].min(x);
                st.2[i] = st.2[i].max(x);
            }
        }
    }
    let stator_pedestals: Vec<usize> = model
        .bearings
        .iter()
        .filter(|b| b.kind.is_magnetic_pull())
        .filter_map(|b| b.pedestal)
        .collect();
    Ok(stats
        .iter()
        .zip(&on_pedestals)
        .map(|((v2, lo, hi), &k)| {
            let b = &model.bearings[k];
            HousingVibration {
                bearing: k,
                name: b.name.clone(),
                velocity_rms: (v2[0].max(v2[1]) / samples as f64).sqrt(),
                displacement_pp: (hi[0] - lo[0]).max(hi[1] - lo[1]),
                stator_braced: b
                    .pedestal
                    .is_some_and(|p| model.pedestals[p].on_stator || stator_pedestals.contains(&p)),
            }
        })
        .collect())
}

/// The simulator the report's sampled transients run on at spin `speed`
/// (rad/s; not yet set), with fixed steps of at most the default one and
/// no unbalance ramp, and the sampling interval (s):
/// [`SAMPLES_PER_PERIOD`] samples a period of the fastest forcing (1× or a
/// harmonic force).
pub fn sampling_simulator(rotor: &Rotor, speed: f64) -> Result<(Simulator, f64), SolverError> {
    let fastest = forcing_frequencies(rotor, speed).fold(speed.abs(), f64::max);
    if fastest.is_nan() || fastest <= 0.0 {
        return Err(SolverError::Input(
            "a sampled transient needs a spin or a harmonic force".into(),
        ));
    }
    let dt = std::f64::consts::TAU / fastest / SAMPLES_PER_PERIOD;
    let own = Rotor::new(rotor.model.clone()).map_err(|e| SolverError::Input(e.to_string()))?;
    let sim = Simulator::new(
        own,
        SolverOptions {
            time_step: dt.min(SolverOptions::default().time_step),
            unbalance_ramp_time: 0.0,
            ..SolverOptions::default()
        },
    )?;
    Ok((sim, dt))
}

/// The spans (s) the report settles and records over at spin `speed`
/// (rad/s): 20 revolutions (at least 2 s) to settle, then 10 revolutions or
/// 3 periods of the slowest harmonic force, whichever is longer.
pub fn report_spans(rotor: &Rotor, speed: f64) -> (f64, f64) {
    let turn = std::f64::consts::TAU / speed.abs();
    let slowest = forcing_frequencies(rotor, speed)
        .filter(|&w| w > 0.0)
        .fold(f64::INFINITY, f64::min);
    let record = (10.0 * turn).max(3.0 * std::f64::consts::TAU / slowest);
    let record = if record.is_finite() {
        record
    } else {
        10.0 * turn
    };
    ((20.0 * turn).max(2.0), record)
}

/// The frequency (rad/s) of each harmonic force of the model at spin `speed`.
fn forcing_frequencies(rotor: &Rotor, speed: f64) -> impl Iterator<Item = f64> + '_ {
    rotor.model.forces.iter().filter_map(move |f| match f.kind {
        crate::model::ForceKind::Harmonic { frequency, .. } => Some(match frequency {
            crate::model::HarmonicFrequency::Ratio(r) => (r * speed).abs(),
            crate::model::HarmonicFrequency::Fixed(w) => w.abs(),
        }),
        crate::model::ForceKind::Static(_) => None,
    })
}
