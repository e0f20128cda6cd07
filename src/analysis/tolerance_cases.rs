//! The tolerance cases (`[cases]`, [`crate::model::tolerance_cases`]): the
//! criteria `rotor report` judges, evaluated on the nominal model and on
//! every combination of the oil temperature, clearance and preload ends,
//! each by the study its command runs with that command's defaults, and the
//! case that governs each criterion (its worst value over the cases).
//!
//! The criteria of one rotor ([`case_criteria`]); a hydro class
//! (`hydro_generator`, `pump_turbine`) is judged by the report's criteria of
//! its class instead of API 684/617's: the first critical speed (Campbell)
//! above the runaway speed `max_speed_rpm`, the least stable forward mode's
//! log decrement (> 0) and the film thickness — no separation margin, AF,
//! Level I/II or API clearance (its ISO 10816-5 housing zones, a nonlinear
//! transient per case, are not among the cases);
//! - separation margin: the least `SM − SM_required` of the Campbell
//!   study's criticals that need a margin (API 684); pass when every one has
//!   its margin;
//! - amplification factor: the largest AF of the unbalance response's peaks
//!   (the model's unbalance, else 1e-3 kg·m at mid-span, as `rotor report`);
//!   pass when every peak has its margin;
//! - log decrement: the least stable forward mode's, without cross-coupling;
//!   pass when it is positive;
//! - API 617 Level I (when the model states impeller stages): the log
//!   decrement at `Q_A`; pass on the ratio and the log decrement;
//! - API 617 Level II (API classes): the least log decrement of the judged
//!   forward modes at the maximum continuous speed (the operating range's
//!   top), as built and, with impeller stages, with `Q_A`
//!   ([`super::level_two`]); pass when ≥ 0.1;
//! - API clearance (API classes): the largest scaled response over its
//!   allowance of the API unbalance cases (API 684/617); pass when ≤ 1;
//! - film thickness: the least minimum film thickness of the fluid films at
//!   the operating speed; pass when no journal touches.

use crate::model::tolerance_cases::CaseSettings;
use crate::rotor::Rotor;
use crate::units::RAD_S_TO_RPM;

use super::api_unbalance::{ApiRequest, api_unbalance};
use super::campbell::{CampbellRequest, CampbellStudy, campbell_study};
use super::level_two::{LevelTwoCase, level_two};
use super::modal::ModalError;
use super::operating_point::operating_point;
use super::speed_range::OperatingRange;
use super::stability::{StabilityRequest, level_one_stages, mid_span_node, stability_study};
use super::unbalance::{DEFAULT_POINTS, UnbalanceRequest, unbalance_study, with_unbalance_at};

/// What is judged in every case.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Criterion {
    SeparationMargin,
    FirstCritical,
    AmplificationFactor,
    LogDecrement,
    LevelOne,
    LevelTwo,
    LevelTwoAnticipated,
    ApiClearance,
    FilmThickness,
}

impl Criterion {
    /// Its name in tables.
    pub fn label(self) -> &'static str {
        match self {
            Criterion::SeparationMargin => "separation margin surplus SM − SM_req (%)",
            Criterion::FirstCritical => "first critical speed (rpm) > runaway",
            Criterion::AmplificationFactor => "amplification factor (largest)",
            Criterion::LogDecrement => "log dec, least stable forward mode",
            Criterion::LevelOne => "log dec at Q_A (API 617 Level I)",
            Criterion::LevelTwo => "log dec at MCS (API 617 Level II)",
            Criterion::LevelTwoAnticipated => "log dec at MCS with Q_A (API 617 Level II)",
            Criterion::ApiClearance => "API scaled response / allowed clearance",
            Criterion::FilmThickness => "minimum film thickness (µm)",
        }
    }

    /// Whether the worst value is the smallest (else the largest).
    pub fn worst_is_least(self) -> bool {
        !matches!(
            self,
            Criterion::AmplificationFactor | Criterion::ApiClearance
        )
    }

    /// The value in the unit of its label.
    pub fn shown(self, value: f64) -> f64 {
        match self {
            Criterion::SeparationMargin => 100.0 * value,
            Criterion::FilmThickness => 1e6 * value,
            Criterion::FirstCritical => value * RAD_S_TO_RPM,
            _ => value,
        }
    }
}

/// One criterion's value in one case and its verdict there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Judged {
    /// The value (SI: margins as fractions, film thickness in m).
    pub value: f64,
    /// Whether the case passes the criterion.
    pub pass: bool,
}

/// A criterion in one case: judged, not applicable (`Ok(None)`: no critical
/// needs a margin, no peak, no film), or the study's failure.
pub type Outcome = Result<Option<Judged>, String>;

/// One case and its criteria.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseResult {
    /// The case.
    pub case: CaseSettings,
    /// Each criterion, in [`case_criteria`]'s order.
    pub criteria: Vec<(Criterion, Outcome)>,
}

/// The case that governs one criterion.
#[derive(Debug, Clone, PartialEq)]
pub struct Governing {
    pub criterion: Criterion,
    /// Index of the governing case in [`CasesStudy::cases`] and its value;
    /// `None` when no case has a value.
    pub worst: Option<(usize, Judged)>,
    /// Cases that fail the criterion (or whose study failed).
    pub failing: Vec<usize>,
}

impl Governing {
    /// `pass` when every case passes (or none has anything to judge: no
    /// critical needing a margin, no peak, no film — as `rotor report`
    /// passes "no peak inside the speed range"), `FAIL` when one fails,
    /// `not judged` when a study failed and none fails.
    pub fn verdict(&self, cases: &[CaseResult]) -> &'static str {
        let failed_study = cases
            .iter()
            .any(|c| c.outcome(self.criterion).is_some_and(|o| o.is_err()));
        if self
            .failing
            .iter()
            .any(|&i| cases[i].outcome(self.criterion).is_some_and(|o| o.is_ok()))
        {
            "FAIL"
        } else if failed_study {
            "not judged"
        } else {
            "pass"
        }
    }
}

impl CaseResult {
    /// The case's outcome of `criterion`, `None` when it is not judged here.
    pub fn outcome(&self, criterion: Criterion) -> Option<&Outcome> {
        self.criteria
            .iter()
            .find(|(k, _)| *k == criterion)
            .map(|(_, o)| o)
    }
}

/// Every case's criteria and the governing case of each.
#[derive(Debug, Clone, PartialEq)]
pub struct CasesStudy {
    /// Operating speed (rad/s).
    pub speed: f64,
    /// Operating range of the margins.
    pub operating: OperatingRange,
    /// The nominal case first, then the combinations.
    pub cases: Vec<CaseResult>,
    /// One per criterion.
    pub governing: Vec<Governing>,
}

/// The least (or largest) of some values, `None` for none.
fn extreme(values: impl Iterator<Item = f64>, least: bool) -> Option<f64> {
    values.fold(None, |acc, v| match acc {
        None => Some(v),
        Some(a) if (least && v < a) || (!least && v > a) => Some(v),
        keep => keep,
    })
}

/// The criteria of one rotor at `speed` (rad/s) with the margins measured
/// from `operating`, each by its command's study and defaults.
pub fn case_criteria(
    rotor: &Rotor,
    speed: f64,
    operating: OperatingRange,
) -> Vec<(Criterion, Outcome)> {
    let mut out = Vec::new();
    let campbell = campbell_study(rotor, &CampbellRequest::default_for(Some(operating)));
    let hydro = rotor.model.machine.is_hydro();
    if hydro {
        out.push((Criterion::FirstCritical, first_critical(rotor, campbell)));
        out.extend(stability_criteria(rotor, speed));
        out.push(film_criterion(rotor, speed));
        return out;
    }
    out.push((
        Criterion::SeparationMargin,
        campbell.map_err(|e| e.to_string()).map(|study| {
            let surplus = study.margins.iter().filter_map(|m| {
                let sm = m.margin.as_ref()?;
                Some(sm.actual - sm.required?)
            });
            extreme(surplus, true).map(|value| Judged {
                value,
                pass: study
                    .margins
                    .iter()
                    .all(|m| m.margin.as_ref().is_none_or(|sm| sm.pass)),
            })
        }),
    ));
    let excited;
    let unbalanced = if rotor.model.unbalances.is_empty() {
        match with_unbalance_at(rotor, mid_span_node(rotor), 1e-3) {
            Ok(r) => {
                excited = r;
                Ok(&excited)
            }
            Err(e) => Err(e.to_string()),
        }
    } else {
        Ok(rotor)
    };
    let unbalance = unbalanced.and_then(|r| {
        unbalance_study(
            r,
            &UnbalanceRequest {
                min: 0.0,
                max: None,
                points: DEFAULT_POINTS,
                operating: Some(operating),
            },
        )
        .map_err(|e| e.to_string())
    });
    let sweep_top = unbalance
        .as_ref()
        .ok()
        .and_then(|s| s.sweep.speeds.last().copied());
    out.push((
        Criterion::AmplificationFactor,
        unbalance.map(|study| {
            let afs = study
                .rows
                .iter()
                .filter_map(|(peak, _)| peak.amplification_factor);
            extreme(afs, false).map(|value| Judged {
                value,
                pass: study
                    .rows
                    .iter()
                    .all(|(_, m)| m.as_ref().is_none_or(|sm| sm.pass)),
            })
        }),
    ));
    out.extend(stability_criteria(rotor, speed));
    if rotor.model.machine.is_api() {
        let stages = level_one_stages(rotor, None);
        let level = level_two(
            rotor,
            operating.max,
            &stages,
            StabilityRequest::at(speed).modes,
        )
        .map_err(|e| e.to_string());
        let judged = |case: &LevelTwoCase| {
            Some(Judged {
                value: case.governing().map_or(0.0, |m| m.log_decrement),
                pass: case.pass(),
            })
        };
        out.push((
            Criterion::LevelTwo,
            level
                .as_ref()
                .map_err(Clone::clone)
                .map(|l| judged(&l.as_built)),
        ));
        if !stages.is_empty() {
            out.push((
                Criterion::LevelTwoAnticipated,
                level
                    .as_ref()
                    .map_err(Clone::clone)
                    .map(|l| l.anticipated.as_ref().and_then(|(_, _, case)| judged(case))),
            ));
        }
        let max = sweep_top.unwrap_or(operating.max * super::speed_range::TOP_SPEED_FACTOR);
        let api = api_unbalance(
            rotor,
            &ApiRequest {
                operating,
                max,
                points: DEFAULT_POINTS,
            },
        );
        out.push((
            Criterion::ApiClearance,
            api.map_err(|e| e.to_string()).map(|a| {
                let checks: Vec<_> = a
                    .cases
                    .iter()
                    .flat_map(|c| &c.criticals)
                    .flat_map(|c| &c.clearances)
                    .collect();
                extreme(checks.iter().map(|c| c.scaled / c.limit), false).map(|value| Judged {
                    value,
                    pass: checks.iter().all(|c| c.pass),
                })
            }),
        ));
    }
    out.push(film_criterion(rotor, speed));
    out
}

/// A hydro unit's first critical speed (`report::hydro`): the lowest
/// Campbell critical above the runaway speed (`max_speed_rpm`); with none,
/// the diagram's top when it reaches the runaway speed, else not judged.
fn first_critical(rotor: &Rotor, campbell: Result<CampbellStudy, ModalError>) -> Outcome {
    let runaway = rotor.model.max_speed.abs();
    let study = campbell.map_err(|e| e.to_string())?;
    match study.first_critical_speed() {
        Some(first) => Ok(Some(Judged {
            value: first,
            pass: first > runaway,
        })),
        None if study.top >= runaway => Ok(Some(Judged {
            value: study.top,
            pass: true,
        })),
        None => Err(format!(
            "no critical speed up to {:.1} rpm, below the runaway speed",
            study.top * RAD_S_TO_RPM
        )),
    }
}

/// The least stable forward mode's log decrement (every class) and, with
/// impeller stages, the Level I log decrement at `Q_A`.
fn stability_criteria(rotor: &Rotor, speed: f64) -> Vec<(Criterion, Outcome)> {
    let mut out = Vec::new();
    let stability = stability_study(
        rotor,
        &StabilityRequest {
            stages: level_one_stages(rotor, None),
            ..StabilityRequest::at(speed)
        },
    )
    .map_err(|e| e.to_string());
    out.push((
        Criterion::LogDecrement,
        stability.as_ref().map_err(Clone::clone).map(|s| {
            let least = &s.curve[0].1;
            Some(Judged {
                value: if least.is_undamped() {
                    0.0
                } else {
                    least.log_decrement
                },
                pass: !least.is_undamped() && least.log_decrement > 0.0,
            })
        }),
    ));
    if let Ok(Some(l)) = stability.as_ref().map(|s| s.level_one.as_ref()) {
        out.push((
            Criterion::LevelOne,
            Ok(Some(Judged {
                value: l.mode_at_anticipated.log_decrement,
                pass: l.pass(),
            })),
        ));
    }
    out
}

/// The least minimum film thickness of the fluid films at `speed`.
fn film_criterion(rotor: &Rotor, speed: f64) -> (Criterion, Outcome) {
    (
        Criterion::FilmThickness,
        operating_point(rotor, speed)
            .map_err(|e| e.to_string())
            .map(|points| {
                let films: Vec<_> = points.iter().filter_map(|p| p.film.as_ref()).collect();
                extreme(films.iter().map(|f| f.min_film_thickness), true).map(|value| Judged {
                    value,
                    pass: films.iter().all(|f| f.contact_force <= 0.0),
                })
            }),
    )
}

/// What stops the cases.
#[derive(Debug, thiserror::Error)]
pub enum CasesError {
    #[error("{0}: the model has no [cases] section")]
    NoCases(String),
    #[error("case {label}: {message}")]
    Assembly { label: String, message: String },
}

/// Every tolerance case of the model (nominal and combinations) judged at
/// `speed` (rad/s) against `operating`, and the governing case of each
/// criterion.
pub fn tolerance_cases(
    rotor: &Rotor,
    speed: f64,
    operating: OperatingRange,
) -> Result<CasesStudy, CasesError> {
    let model = &rotor.model;
    let Some(ranges) = &model.tolerance_cases else {
        return Err(CasesError::NoCases(model.source.clone()));
    };
    let mut cases = Vec::new();
    for case in ranges.cases() {
        let criteria = if case.temperature.is_none()
            && case.clearance_factor.is_none()
            && case.preload.is_none()
        {
            case_criteria(rotor, speed, operating)
        } else {
            let r = Rotor::new(model.with_case(&case)).map_err(|e| CasesError::Assembly {
                label: case.label.clone(),
                message: e.to_string(),
            })?;
            case_criteria(&r, speed, operating)
        };
        cases.push(CaseResult { case, criteria });
    }
    let governing = governing(&cases);
    Ok(CasesStudy {
        speed,
        operating,
        cases,
        governing,
    })
}

/// The governing case of each criterion any case has: the first case of
/// the worst value, and every failing case.
pub fn governing(cases: &[CaseResult]) -> Vec<Governing> {
    let mut criteria: Vec<Criterion> = Vec::new();
    for c in cases {
        for (k, _) in &c.criteria {
            if !criteria.contains(k) {
                criteria.push(*k);
            }
        }
    }
    criteria
        .into_iter()
        .map(|criterion| {
            let least = criterion.worst_is_least();
            let mut worst: Option<(usize, Judged)> = None;
            let mut failing = Vec::new();
            for (i, c) in cases.iter().enumerate() {
                match c.outcome(criterion) {
                    Some(Ok(Some(j))) => {
                        if !j.pass {
                            failing.push(i);
                        }
                        let worse = match worst {
                            None => true,
                            Some((_, w)) => {
                                (least && j.value < w.value) || (!least && j.value > w.value)
                            }
                        };
                        if worse {
                            worst = Some((i, *j));
                        }
                    }
                    Some(Err(_)) => failing.push(i),
                    _ => {}
                }
            }
            Governing {
                criterion,
                worst,
                failing,
            }
        })
        .collect()
}
