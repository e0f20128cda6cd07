//! Shaft orbits at the bearings from the nonlinear transient, in the cases a
//! hydro unit's design review shows (issue 48): at the operating speed as
//! the model is given, with the generator's field on (a model with a
//! magnetic pull), and at the runaway speed with the field off (the unit
//! thrown off the grid is de-excited).
//!
//! Each orbit is the shaft's displacement relative to the bearing housing,
//! what a pair of proximity probes on the housing in `x` and `y` measures
//! (ISO 7919-1's shaft relative displacement): sampled after `settle`
//! seconds over `record` seconds at
//! [`super::housing_vibration::SAMPLES_PER_PERIOD`] samples per
//! period of the fastest forcing (1× or a harmonic force), as the housing
//! vibration of [`super::housing_vibration`] is. Per bearing it gives the
//! peak-to-peak displacement in `x` and in `y` (`max − min`) and `S_max`,
//! the largest distance of the orbit from its mean position.

use crate::rotor::Rotor;
use crate::solver::SolverError;

use super::housing_vibration::{report_spans, sampling_simulator};

/// A running condition of the orbit study.
#[derive(Debug, Clone, PartialEq)]
pub struct OrbitCase {
    /// What the case is, for tables and captions.
    pub label: String,
    /// Spin speed (rad/s).
    pub speed: f64,
    /// The field excitation given to every magnetic pull (0: field off, 1:
    /// nominal); `None` keeps the model's own.
    pub excitation: Option<f64>,
    /// Within the normal operating range, where zones of steady vibration
    /// apply (not at runaway, a transient condition).
    pub steady: bool,
}

/// The cases of a hydraulic unit: operating speed as given, operating speed
/// with the field on (1, nominal) where the model has a magnetic pull whose
/// own excitation is not already 1, and the runaway speed (the model's
/// `max_speed_rpm`, where it is above the operating speed) with the field
/// off.
pub fn hydro_cases(rotor: &Rotor, operating: f64) -> Vec<OrbitCase> {
    let model = &rotor.model;
    let excitations: Vec<f64> = model
        .bearings
        .iter()
        .filter_map(|b| b.kind.excitation())
        .collect();
    let mut cases = vec![OrbitCase {
        label: "operating speed, as modelled".into(),
        speed: operating,
        excitation: None,
        steady: true,
    }];
    if excitations.iter().any(|&e| e != 1.0) {
        cases.push(OrbitCase {
            label: "operating speed, field on (excitation 1)".into(),
            speed: operating,
            excitation: Some(1.0),
            steady: true,
        });
    }
    let runaway = model.max_speed;
    if runaway.abs() > operating.abs() {
        cases.push(OrbitCase {
            label: if excitations.is_empty() {
                "runaway speed".into()
            } else {
                "runaway speed, field off".into()
            },
            speed: if operating < 0.0 {
                -runaway.abs()
            } else {
                runaway.abs()
            },
            excitation: (!excitations.is_empty()).then_some(0.0),
            steady: false,
        });
    }
    cases
}

/// The orbit of one bearing's journal relative to its housing.
#[derive(Debug, Clone, PartialEq)]
pub struct BearingOrbit {
    /// Model bearing index.
    pub bearing: usize,
    /// Bearing name.
    pub name: String,
    /// Shaft displacement relative to the housing (m), per sample.
    pub x: Vec<f64>,
    /// Shaft displacement relative to the housing (m), per sample.
    pub y: Vec<f64>,
    /// Peak-to-peak displacement in `x` and in `y` (m).
    pub peak_to_peak: [f64; 2],
    /// The largest distance of the orbit from its mean position (m).
    pub s_max: f64,
    /// The radial clearance the journal moves in (m), where the bearing has
    /// one ([`crate::bearing::BearingKind::journal_clearance`]).
    pub clearance: Option<f64>,
}

/// The orbits of one case.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseOrbits {
    /// The case.
    pub case: OrbitCase,
    /// Spin angle (rad) per sample, for the keyphasor marks.
    pub spin_angle: Vec<f64>,
    /// One orbit per bearing (not seal, rub or magnetic pull).
    pub bearings: Vec<BearingOrbit>,
}

/// The shaft orbits of every bearing in `case`, from the transient with the
/// model's loads settled for `settle` s after the static equilibrium and
/// sampled over `record` s ([`report_spans`] gives the report's).
pub fn shaft_orbits(
    rotor: &Rotor,
    case: &OrbitCase,
    settle: f64,
    record: f64,
) -> Result<CaseOrbits, SolverError> {
    let model = &rotor.model;
    let bearings: Vec<usize> = (0..model.bearings.len())
        .filter(|&k| model.bearings[k].kind.is_bearing())
        .collect();
    let speed = case.speed;
    let (mut sim, dt) = sampling_simulator(rotor, speed)?;
    if let Some(e) = case.excitation {
        for (k, b) in model.bearings.iter().enumerate() {
            if b.kind.is_magnetic_pull() {
                sim.set_excitation(k, e)?;
            }
        }
    }
    sim.set_speed(speed, 0.0)?;
    sim.settle_static()?;
    sim.advance_to(settle)?;
    let samples = (record / dt).round().max(1.0) as usize;
    let mut spin_angle = Vec::with_capacity(samples);
    let mut xy = vec![(Vec::with_capacity(samples), Vec::with_capacity(samples)); bearings.len()];
    for s in 1..=samples {
        sim.advance_to(settle + s as f64 * dt)?;
        let out = sim.outputs()?;
        spin_angle.push(out.spin_angle);
        for ((x, y), &k) in xy.iter_mut().zip(&bearings) {
            let b = &out.bearings[k];
            x.push(b.x - b.housing.x);
            y.push(b.y - b.housing.y);
        }
    }
    let orbits = xy
        .into_iter()
        .zip(&bearings)
        .map(|((x, y), &k)| {
            let range = |v: &[f64]| {
                v.iter().fold(f64::NEG_INFINITY, |m, &a| m.max(a))
                    - v.iter().fold(f64::INFINITY, |m, &a| m.min(a))
            };
            let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
            let (mx, my) = (mean(&x), mean(&y));
            let s_max = x
                .iter()
                .zip(&y)
                .map(|(a, b)| (a - mx).hypot(b - my))
                .fold(0.0, f64::max);
            BearingOrbit {
                bearing: k,
                name: model.bearings[k].name.clone(),
                peak_to_peak: [range(&x), range(&y)],
                s_max,
                clearance: model.bearings[k].kind.journal_clearance(),
                x,
                y,
            }
        })
        .collect();
    Ok(CaseOrbits {
        case: case.clone(),
        spin_angle,
        bearings: orbits,
    })
}

/// The orbits of every case, each with the report's spans at its speed.
pub fn report_orbits(rotor: &Rotor, cases: &[OrbitCase]) -> Result<Vec<CaseOrbits>, SolverError> {
    cases
        .iter()
        .map(|case| {
            let (settle, record) = report_spans(rotor, case.speed);
            shaft_orbits(rotor, case, settle, record)
        })
        .collect()
}
