//! The API 684/617 unbalance cases of an API machine on the design-review
//! page: the limits, each case's planes, the criticals' table and one
//! summary row per critical, every cell formatted by the text the command
//! prints ([`text::api_critical_cells`]).

use crate::analysis::api_unbalance::ApiUnbalance;

use super::html::{Block, Cell, Table, Verdict};
use super::text;

/// A verdict cell from the command's verdict text.
fn verdict_cell(words: &str) -> Cell {
    let verdict = match words {
        "pass" => Verdict::Pass,
        "FAIL" => Verdict::Fail,
        _ => Verdict::NotJudged,
    };
    Cell {
        text: words.to_string(),
        verdict: Some(verdict),
    }
}

/// The section's blocks: the command's header and planes as text, then the
/// table of every case's criticals with their worst clearance.
pub fn api_blocks(api: &ApiUnbalance) -> Vec<Block> {
    let printed = text::api_unbalance(api);
    let header: Vec<&str> = printed.lines().take(2).collect();
    let mut blocks = vec![Block::Text(header.join(" "))];
    for case in &api.cases {
        blocks.push(Block::Text(format!(
            "Case {}: {}.",
            case.kind.label(),
            text::case_planes(case)
        )));
    }
    let mut rows = Vec::new();
    for case in &api.cases {
        for c in &case.criticals {
            let cells = text::api_critical_cells(c);
            let mut row: Vec<Cell> = vec![case.kind.label().into()];
            row.extend(cells[..8].iter().map(|v| Cell::from(v.clone())));
            row.push(verdict_cell(&cells[8]));
            rows.push(row);
        }
        if case.criticals.is_empty() {
            let mut row: Vec<Cell> = vec![
                case.kind.label().into(),
                "no peak inside the speed range".into(),
            ];
            row.extend((0..7).map(|_| Cell::from("—")));
            row.push(Cell::verdict(Verdict::Pass));
            rows.push(row);
        }
    }
    blocks.push(Block::Table(Table {
        id: "api-unbalance".into(),
        caption: "API 684/617 unbalance cases: amplification factors, separation margins, scale factors and the scaled response at the closest clearance (75 % of the diametral running clearance)".into(),
        headers: [
            "case",
            "point",
            "speed (rpm)",
            "A1 (µm pk-pk)",
            "AF",
            "required SM",
            "actual SM",
            "S_cc",
            "worst clearance (scaled/allowed)",
            "result",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect(),
        rows,
    }));
    blocks
}

/// The summary's rows: one per critical of each case (or a failure row).
pub fn summary_rows(api: &Result<&ApiUnbalance, String>) -> Vec<Vec<Cell>> {
    let api = match api {
        Ok(a) => a,
        Err(e) => {
            return vec![vec![
                "API unbalance cases".into(),
                "—".into(),
                format!("not computed: {e}").into(),
                "—".into(),
                Cell::verdict(Verdict::NotJudged),
            ]];
        }
    };
    let mut rows = Vec::new();
    for case in &api.cases {
        for c in &case.criticals {
            let cells = text::api_critical_cells(c);
            rows.push(vec![
                "API unbalance case".into(),
                format!("{}, {}", case.kind.label(), cells[0]).into(),
                format!(
                    "{} rpm, A1 {} µm pk-pk, AF {}, S_cc {}; {}",
                    cells[1], cells[2], cells[3], cells[6], cells[7]
                )
                .into(),
                format!(
                    "SM {} ≥ {}; scaled response ≤ 75 % of the clearance (API 684/617)",
                    cells[5], cells[4]
                )
                .into(),
                verdict_cell(&cells[8]),
            ]);
        }
    }
    rows
}
