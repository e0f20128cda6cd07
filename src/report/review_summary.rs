//! The design-review page's first-page summary: one row per judged item
//! (critical speeds and their separation margins, unbalance response peaks
//! and AF, the stability margin, every bearing's film), each result the
//! verdict the single command prints, and the page's overall verdict.

use crate::analysis::api_unbalance::ApiUnbalance;
use crate::analysis::campbell::CampbellStudy;
use crate::analysis::operating_point::BearingOperatingPoint;
use crate::analysis::stability::Stability;
use crate::analysis::unbalance::UnbalanceStudy;
use crate::model::machine_class::MachineClass;
use crate::units::{Amplitude, RAD_S_TO_RPM};

use super::html::{Cell, Table, Verdict};
use super::hydro::HousingStudy;
use super::review::{headers, verdict_cell};
use super::text::{self, short};

/// What the summary is made from: each study, or why it could not be made.
pub struct SummaryInputs<'a> {
    /// The Campbell study.
    pub campbell: Result<&'a CampbellStudy, String>,
    /// The unbalance study.
    pub unbalance: Result<&'a UnbalanceStudy, String>,
    /// The stability study.
    pub stability: Result<&'a Stability, String>,
    /// The bearings at the operating speed.
    pub operating: Result<&'a [BearingOperatingPoint], String>,
    /// Amplitude convention.
    pub amplitude: Amplitude,
    /// The machine's class: a hydro class is judged by its own criteria
    /// ([`super::hydro`]), every other by API 684/617.
    pub machine: MachineClass,
    /// The runaway (largest) speed (rad/s), for a hydro class.
    pub runaway: f64,
    /// The housing vibration, for a hydro class.
    pub housing: Option<HousingStudy<'a>>,
    /// The API unbalance cases, for an API class ([`super::api`]).
    pub api: Option<Result<&'a ApiUnbalance, String>>,
}

/// The first-page summary: one row per judged item (check, item, value,
/// criterion, result), each result the verdict the single command prints.
pub fn summary(inputs: &SummaryInputs) -> Table {
    let mut rows: Vec<Vec<Cell>> = Vec::new();
    let failed = |rows: &mut Vec<Vec<Cell>>, check: &str, why: &str| {
        rows.push(vec![
            check.into(),
            "—".into(),
            format!("not computed: {why}").into(),
            "—".into(),
            Cell::verdict(Verdict::NotJudged),
        ]);
    };
    let hydro = inputs.machine.is_hydro();
    match &inputs.campbell {
        Ok(study) if hydro => rows.push(super::hydro::critical_row(study, inputs.runaway)),
        Ok(study) if study.margins.is_empty() => rows.push(vec![
            "critical speeds (Campbell)".into(),
            "—".into(),
            format!("none up to {} rpm", short(study.top * RAD_S_TO_RPM)).into(),
            "API 684 separation margin".into(),
            Cell::verdict(Verdict::Pass),
        ]),
        Ok(study) => {
            for m in &study.margins {
                let c = text::margin_cells(m);
                rows.push(vec![
                    "critical speed (Campbell)".into(),
                    format!(
                        "branch {}, {} whirl",
                        m.critical.branch + 1,
                        m.critical.whirl.label()
                    )
                    .into(),
                    format!(
                        "{} rpm, ζ = {}, AF {}",
                        c[0],
                        text::damping_ratio(m.critical.damping_ratio),
                        c[1]
                    )
                    .into(),
                    format!("SM {} ≥ {} (API 684)", c[3], c[2]).into(),
                    verdict_cell(&c[5]),
                ]);
            }
        }
        Err(e) => failed(&mut rows, "critical speeds (Campbell)", e),
    }
    match &inputs.unbalance {
        // A hydro unit's peaks are its critical speeds, judged against the
        // runaway speed above; the unbalance section shows them.
        Ok(_) if hydro => {}
        Ok(study) => {
            for (peak, margin) in &study.rows {
                let c = text::peak_cells(&study.sweep, peak, margin.as_ref(), inputs.amplitude);
                rows.push(vec![
                    "unbalance response peak".into(),
                    c[0].clone().into(),
                    if peak.is_undamped() {
                        format!("{} rpm, unbounded (undamped resonance)", c[1])
                    } else {
                        format!(
                            "{} rpm, {} µm {}, AF {}",
                            c[1],
                            c[2],
                            inputs.amplitude.label(),
                            c[3]
                        )
                    }
                    .into(),
                    format!("SM {} ≥ {} (API 684)", c[5], c[4]).into(),
                    verdict_cell(&c[6]),
                ]);
            }
            if study.rows.is_empty() {
                rows.push(vec![
                    "unbalance response peak".into(),
                    "—".into(),
                    "no peak inside the speed range".into(),
                    "—".into(),
                    Cell::verdict(Verdict::Pass),
                ]);
            }
        }
        Err(e) => failed(&mut rows, "unbalance response", e),
    }
    if let Some(api) = &inputs.api {
        rows.extend(super::api::summary_rows(api));
    }
    match &inputs.stability {
        Ok(s) => {
            if let Some(root) = s.diverging.first() {
                rows.push(vec![
                    "static stability".into(),
                    format!(
                        "{} non-oscillating root(s) growing (divergence)",
                        s.diverging.len()
                    )
                    .into(),
                    format!("growth rate {} 1/s", short(-root.decay_rate())).into(),
                    "no growing root".into(),
                    Cell::verdict(Verdict::Fail),
                ]);
            }
            let least = &s.curve[0].1;
            let delta = if least.is_undamped() {
                "log dec 0 (no damping)".to_string()
            } else {
                format!("log dec {:.4}", least.log_decrement)
            };
            rows.push(vec![
                "stability without cross-coupling".into(),
                format!(
                    "least stable forward mode, {} Hz",
                    short(least.damped_frequency / std::f64::consts::TAU)
                )
                .into(),
                delta.into(),
                "log dec > 0".into(),
                Cell::verdict(Verdict::of(text::log_dec_holds(least))),
            ]);
            match &s.level_one {
                // API 617's Level I screening is not written for hydro units.
                _ if hydro => {}
                Some(l) => {
                    let ratio = match l.ratio {
                        Some(r) => format!("{r:.2}"),
                        None => format!("> {:.2}", s.q_max / l.anticipated),
                    };
                    rows.push(vec![
                        "stability margin (API 617 Level I)".into(),
                        format!("Q_A = {} N/m (Wachel)", short(l.anticipated)).into(),
                        format!(
                            "Q0/Q_A = {ratio}, log dec at Q_A = {:.4}",
                            l.mode_at_anticipated.log_decrement
                        )
                        .into(),
                        "Q0/Q_A ≥ 2 and log dec ≥ 0.1".into(),
                        Cell::verdict(Verdict::of(l.pass())),
                    ]);
                }
                None => rows.push(vec![
                    "stability margin (API 617 Level I)".into(),
                    "Q_A not given".into(),
                    match s.threshold {
                        Some(q) => format!("threshold Q0 = {} N/m", short(q)),
                        None => format!("no threshold up to {} N/m", short(s.q_max)),
                    }
                    .into(),
                    "--power, --impeller-diameter, --flow-width for Q_A".into(),
                    Cell::verdict(Verdict::NotJudged),
                ]),
            }
        }
        Err(e) => failed(&mut rows, "stability", e),
    }
    match &inputs.operating {
        Ok(points) => {
            for p in points.iter() {
                let Some(f) = &p.film else {
                    continue;
                };
                let contact = f.contact_force > 0.0;
                rows.push(vec![
                    "bearing film".into(),
                    p.name.clone().into(),
                    format!(
                        "h_min = {} µm, power loss {} W (temperature-free)",
                        short(f.min_film_thickness * 1e6),
                        short(f.power_loss)
                    )
                    .into(),
                    "journal lifted off (no contact)".into(),
                    Cell::verdict(Verdict::of(!contact)),
                ]);
            }
        }
        Err(e) => failed(&mut rows, "bearings", e),
    }
    if let Some(housing) = inputs.housing.as_ref().filter(|_| hydro) {
        rows.extend(super::hydro::housing_rows(housing));
    }
    Table {
        id: "summary-table".into(),
        caption: "summary".into(),
        headers: headers(&["check", "item", "value", "criterion", "result"]),
        rows,
    }
}

/// The worst verdict of a table's verdict cells: FAIL if any fails, else
/// not judged if any is, else pass.
pub fn overall(table: &Table) -> Verdict {
    let verdicts: Vec<Verdict> = table
        .rows
        .iter()
        .flatten()
        .filter_map(|c| c.verdict)
        .collect();
    if verdicts.contains(&Verdict::Fail) {
        Verdict::Fail
    } else if verdicts.contains(&Verdict::NotJudged) {
        Verdict::NotJudged
    } else {
        Verdict::Pass
    }
}
