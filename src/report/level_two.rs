//! The API 617 Level II analysis of an API machine on the design-review
//! page: the command's text as the stability section's table and one
//! summary row per eigenproblem (as built, with `Q_A`), each cell the text
//! `rotor stability` prints ([`text::level_two`]).

use crate::analysis::level_two::{LEVEL_II_MIN_LOG_DEC, LevelTwo};
use crate::units::RAD_S_TO_RPM;

use super::html::{Block, Cell, Table, Verdict};
use super::text;

/// The stability section's Level II table: the lines `rotor stability`
/// prints, one a row. `sites` labels the anticipated cross-coupling's nodes.
pub fn level_two_blocks(
    l: &LevelTwo,
    sites: &[String],
    model: &crate::model::RotorModel,
) -> Vec<Block> {
    let printed = text::level_two(l, sites, model);
    vec![Block::Table(Table {
        id: "level-two".into(),
        caption: "API 617 Level II: log decrements at the maximum continuous speed with every element's coefficients".into(),
        headers: vec!["finding".to_string()],
        rows: printed
            .lines()
            .map(|line| vec![Cell::from(line.trim())])
            .collect(),
    })]
}

/// The summary's rows: the model as built and, with stage data, with `Q_A`
/// (or the failure of the study).
pub fn level_two_summary_rows(l: &Result<&LevelTwo, String>) -> Vec<Vec<Cell>> {
    let l = match l {
        Ok(l) => l,
        Err(e) => {
            return vec![vec![
                "stability (API 617 Level II)".into(),
                "—".into(),
                format!("not computed: {e}").into(),
                "—".into(),
                Cell::verdict(Verdict::NotJudged),
            ]];
        }
    };
    let rpm = text::short(l.speed.abs() * RAD_S_TO_RPM);
    let limit = text::short(l.frequency_limit / std::f64::consts::TAU);
    let mut rows = vec![vec![
        "stability (API 617 Level II)".into(),
        format!("model as built at {rpm} rpm (MCS), first forward mode and forward modes below {limit} Hz").into(),
        text::level_two_finding(&l.as_built).into(),
        format!("log dec ≥ {LEVEL_II_MIN_LOG_DEC}").into(),
        Cell::verdict(Verdict::of(l.as_built.pass())),
    ]];
    if let Some((_, _, case)) = &l.anticipated {
        rows.push(vec![
            "stability (API 617 Level II with Q_A)".into(),
            format!(
                "with Q_A = {} N/m at {rpm} rpm (MCS)",
                text::short(case.cross_coupling)
            )
            .into(),
            text::level_two_finding(case).into(),
            format!("log dec ≥ {LEVEL_II_MIN_LOG_DEC}").into(),
            Cell::verdict(Verdict::of(case.pass())),
        ]);
    }
    rows
}
