//! The tolerance cases on the design-review page (`[cases]`,
//! [`crate::analysis::tolerance_cases`]): one summary row per criterion
//! naming the case that governs it, and a section with the cases and each
//! criterion's value in every case, every cell formatted by the text
//! `rotor cases` prints ([`text::governing_cells`], [`text::case_value`]).

use crate::analysis::tolerance_cases::CasesStudy;

use super::html::{Block, Cell, Table, Verdict};
use super::review::verdict_cell;
use super::text;

/// The summary's rows: per criterion, its worst value over the cases and
/// the case that governs it (or a failure row).
pub fn summary_rows(study: &Result<&CasesStudy, String>) -> Vec<Vec<Cell>> {
    let study = match study {
        Ok(s) => s,
        Err(e) => {
            return vec![vec![
                "tolerance cases".into(),
                "—".into(),
                format!("not computed: {e}").into(),
                "—".into(),
                Cell::verdict(Verdict::NotJudged),
            ]];
        }
    };
    study
        .governing
        .iter()
        .map(|g| {
            let c = text::governing_cells(study, g);
            vec![
                "tolerance cases (worst case)".into(),
                c[0].clone().into(),
                format!("{} in case {}", c[1], c[2]).into(),
                format!(
                    "every one of the {} cases ({} failing)",
                    study.cases.len(),
                    c[3]
                )
                .into(),
                verdict_cell(&c[4]),
            ]
        })
        .collect()
}

/// The section's blocks: the cases and their settings, then each
/// criterion's value per case with the governing case.
pub fn cases_blocks(name: &str, study: &CasesStudy) -> Vec<Block> {
    let cases = Table {
        id: "tolerance-cases".into(),
        caption: "the cases: nominal and every combination of the ranges' ends".into(),
        headers: ["case", "ends", "settings"]
            .iter()
            .map(|s| s.to_string())
            .collect(),
        rows: study
            .cases
            .iter()
            .enumerate()
            .map(|(i, c)| {
                vec![
                    (i + 1).to_string().into(),
                    c.case.label.clone().into(),
                    c.case.describe().into(),
                ]
            })
            .collect(),
    };
    let mut headers = vec!["criterion".to_string()];
    headers.extend((1..=study.cases.len()).map(|i| format!("case {i}")));
    headers.extend(["worst (case)".to_string(), "result".to_string()]);
    let rows = study
        .governing
        .iter()
        .map(|g| {
            let c = text::governing_cells(study, g);
            let mut row: Vec<Cell> = vec![c[0].clone().into()];
            for case in &study.cases {
                let v = case
                    .outcome(g.criterion)
                    .map_or("—".into(), |o| text::case_value(g.criterion, o));
                row.push(v.into());
            }
            row.push(format!("{} ({})", c[1], c[2]).into());
            row.push(verdict_cell(&c[4]));
            row
        })
        .collect();
    vec![
        Block::Text(text::cases_heading(name, study)),
        Block::Table(cases),
        Block::Table(Table {
            id: "tolerance-criteria".into(),
            caption: "each criterion in every case and the case that governs it".into(),
            headers,
            rows,
        }),
    ]
}
