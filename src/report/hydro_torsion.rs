//! The torsional modes of a hydraulic machine set on the design-review page
//! (issue 48): every torsional natural frequency up to the band of the
//! highest excitation ([`torsional_modes_up_to`]), judged against the running
//! speed (1x) and the electrical grid frequency and its double (the model's
//! `grid_frequency_hz`): each must keep the separation `torsional_margin`
//! (default [`DEFAULT_TORSIONAL_MARGIN`], an engineering assumption stated as
//! such) from each excitation, `|f_n − f_e| ≥ m f_e`. The governing mode of an
//! excitation is the one nearest it (smallest separation).
//!
//! [`DEFAULT_TORSIONAL_MARGIN`]: crate::model::machine_class::DEFAULT_TORSIONAL_MARGIN

use std::f64::consts::TAU;

use crate::analysis::torsion::{TorsionalMode, torsional_modes_up_to};
use crate::model::RotorModel;
use crate::model::machine_class::DEFAULT_TORSIONAL_MARGIN;

use super::html::{Block, Cell, Table, Verdict};
use super::text::short;

/// One excitation and the mode nearest it.
#[derive(Debug, Clone, PartialEq)]
pub struct TorsionCheck {
    /// What excites: "1x running speed", "1x grid frequency", "2x grid frequency".
    pub excitation: &'static str,
    /// Its frequency (Hz); `None`: the model gives no grid frequency.
    pub frequency: Option<f64>,
    /// The governing mode: its index (0-based), natural frequency (Hz) and
    /// separation `|f_n − f_e|/f_e`; `None` without a frequency or a mode.
    pub governing: Option<(usize, f64, f64)>,
}

impl TorsionCheck {
    /// Whether the governing mode keeps the margin (`None`: not judged).
    pub fn pass(&self, margin: f64) -> Option<bool> {
        self.frequency?;
        Some(self.governing.is_none_or(|(_, _, s)| s >= margin))
    }
}

/// The torsional modes of a hydro unit and their checks.
#[derive(Debug, Clone, PartialEq)]
pub struct TorsionStudy {
    /// Every elastic torsional mode up to the highest excitation's band and
    /// the first above it, ascending.
    pub modes: Vec<TorsionalMode>,
    /// The checks: 1x running speed, 1x and 2x grid frequency.
    pub checks: Vec<TorsionCheck>,
    /// The required separation (fraction).
    pub margin: f64,
    /// Whether the margin is the model's (`torsional_margin`) or the default.
    pub margin_stated: bool,
}

/// The torsional study of `model` running at `speed` (rad/s).
pub fn torsion_study(model: &RotorModel, speed: f64) -> Result<TorsionStudy, String> {
    let margin = model.torsional_margin.unwrap_or(DEFAULT_TORSIONAL_MARGIN);
    let running = speed.abs() / TAU;
    let grid = model.grid_frequency;
    let excitations = [
        ("1x running speed", Some(running)),
        ("1x grid frequency", grid),
        ("2x grid frequency", grid.map(|g| 2.0 * g)),
    ];
    let top = excitations.iter().filter_map(|e| e.1).fold(0.0, f64::max);
    let modes =
        torsional_modes_up_to(model, (1.0 + margin) * top * TAU).map_err(|e| e.to_string())?;
    let checks = excitations
        .iter()
        .map(|&(excitation, frequency)| TorsionCheck {
            excitation,
            frequency,
            governing: frequency.and_then(|f| {
                modes
                    .iter()
                    .enumerate()
                    .map(|(k, m)| {
                        let fn_hz = m.natural_frequency / TAU;
                        (k, fn_hz, (fn_hz - f).abs() / f)
                    })
                    .min_by(|a, b| a.2.total_cmp(&b.2))
            }),
        })
        .collect();
    Ok(TorsionStudy {
        modes,
        checks,
        margin,
        margin_stated: model.torsional_margin.is_some(),
    })
}

const CHECK: &str = "torsional natural frequencies";

/// The criterion's words: the separation and where it comes from.
fn criterion(study: &TorsionStudy) -> String {
    format!(
        "separation ≥ {} % ({})",
        short(study.margin * 100.0),
        if study.margin_stated {
            "torsional_margin"
        } else {
            "default torsional_margin, an engineering assumption"
        }
    )
}

/// The summary rows: one per excitation, its governing mode and verdict.
pub fn torsion_rows(study: &Result<TorsionStudy, String>) -> Vec<Vec<Cell>> {
    let study = match study {
        Ok(s) => s,
        Err(e) => {
            return vec![vec![
                CHECK.into(),
                "—".into(),
                format!("not computed: {e}").into(),
                "—".into(),
                Cell::verdict(Verdict::NotJudged),
            ]];
        }
    };
    study
        .checks
        .iter()
        .map(|c| {
            let Some(f) = c.frequency else {
                return vec![
                    CHECK.into(),
                    c.excitation.into(),
                    "not judged: no grid frequency".into(),
                    "give grid_frequency_hz".into(),
                    Cell::verdict(Verdict::NotJudged),
                ];
            };
            let value = match c.governing {
                Some((k, fn_hz, s)) => format!(
                    "mode {} at {} Hz: separation {} %",
                    k + 1,
                    short(fn_hz),
                    short(s * 100.0)
                ),
                None => "no torsional mode".to_string(),
            };
            vec![
                CHECK.into(),
                format!("{} {} Hz", c.excitation, short(f)).into(),
                value.into(),
                criterion(study).into(),
                Cell::verdict(Verdict::of(c.pass(study.margin).unwrap_or(true))),
            ]
        })
        .collect()
}

/// The section's table: each mode's natural frequency, damping ratio and
/// separation from each excitation.
pub fn torsion_blocks(study: &TorsionStudy) -> Vec<Block> {
    let rows = study
        .modes
        .iter()
        .enumerate()
        .map(|(k, m)| {
            let fn_hz = m.natural_frequency / TAU;
            let mut row = vec![
                Cell::from(format!("{}", k + 1)),
                short(fn_hz).into(),
                short(m.damping_ratio).into(),
            ];
            row.extend(study.checks.iter().map(|c| match c.frequency {
                Some(f) => {
                    let s = (fn_hz - f).abs() / f;
                    Cell::from(format!(
                        "{} %{}",
                        short(s * 100.0),
                        if s < study.margin {
                            " (inside the margin)"
                        } else {
                            ""
                        }
                    ))
                }
                None => Cell::from("—"),
            }));
            row
        })
        .collect();
    let mut headers = vec![
        "mode".to_string(),
        "f (Hz, undamped)".to_string(),
        "damping ratio".to_string(),
    ];
    headers.extend(study.checks.iter().map(|c| match c.frequency {
        Some(f) => format!("separation from {} ({} Hz)", c.excitation, short(f)),
        None => format!("separation from {} (no grid frequency)", c.excitation),
    }));
    vec![Block::Table(Table {
        id: "torsional-modes".into(),
        caption: format!(
            "torsional natural frequencies (as `rotor modes --torsional-modes` lists them) against the running speed and the grid frequency: {}",
            criterion(study)
        ),
        headers,
        rows,
    })]
}
