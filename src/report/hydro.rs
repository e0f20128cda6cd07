//! The criteria of a hydraulic machine set (`machine = "hydro_generator"` or
//! `"pump_turbine"`) on the design-review page: the first critical speed
//! against the runaway speed (the model's `max_speed_rpm`) in place of API
//! 684's separation margins, and the bearing-housing vibration zones of ISO
//! 10816-5 ([`crate::analysis::housing_vibration`]) in place of API 617's
//! Level I screening, which is not written for such machines.

use crate::analysis::campbell::CampbellStudy;
use crate::analysis::housing_vibration::{HousingVibration, Zone, iso_10816_5_boundaries};
use crate::model::machine_class::HousingGroup;
use crate::units::RAD_S_TO_RPM;

use super::html::{Block, Cell, Table, Verdict};
use super::text::short;

/// The housing vibration study of a hydro unit: its ISO 10816-5 group (none
/// when the model names none) and the vibration, or why it was not made.
pub struct HousingStudy<'a> {
    /// The machine group (`housing_group`).
    pub group: Option<HousingGroup>,
    /// The housings' vibration at the operating speed.
    pub vibration: Result<&'a [HousingVibration], String>,
}

/// The summary row of the critical speeds: the lowest (not overdamped)
/// critical speed must lie above the runaway speed `runaway` (rad/s).
pub fn critical_row(study: &CampbellStudy, runaway: f64) -> Vec<Cell> {
    let criterion = format!(
        "above the runaway speed {} rpm",
        short(runaway * RAD_S_TO_RPM)
    );
    if let Some(lowest) = study.first_critical_speed() {
        vec![
            "first critical speed (Campbell)".into(),
            "—".into(),
            format!("{} rpm", short(lowest * RAD_S_TO_RPM)).into(),
            criterion.into(),
            Cell::verdict(Verdict::of(lowest > runaway)),
        ]
    } else {
        vec![
            "first critical speed (Campbell)".into(),
            "—".into(),
            format!("none up to {} rpm", short(study.top * RAD_S_TO_RPM)).into(),
            criterion.into(),
            // A diagram that stops below the runaway speed cannot tell.
            Cell::verdict(if study.top >= runaway {
                Verdict::Pass
            } else {
                Verdict::NotJudged
            }),
        ]
    }
}

/// The zone of one housing: the worse of its velocity zone and (where the
/// group gives one) its displacement zone.
pub fn housing_zone(group: HousingGroup, h: &HousingVibration) -> Zone {
    let b = iso_10816_5_boundaries(group, h.stator_braced);
    let by_velocity = Zone::of(h.velocity_rms, b.velocity_rms);
    match b.displacement_pp {
        Some(d) => by_velocity.max(Zone::of(h.displacement_pp, d)),
        None => by_velocity,
    }
}

/// The summary rows of the housing vibration: one per bearing on a
/// pedestal, pass in zones A and B.
pub fn housing_rows(study: &HousingStudy) -> Vec<Vec<Cell>> {
    let check = "housing vibration (ISO 10816-5)";
    let not_judged = |value: String, criterion: &str| {
        vec![vec![
            check.into(),
            "—".into(),
            value.into(),
            criterion.into(),
            Cell::verdict(Verdict::NotJudged),
        ]]
    };
    let vibration = match &study.vibration {
        Ok(v) => *v,
        Err(e) => return not_judged(format!("not computed: {e}"), "—"),
    };
    let Some(group) = study.group else {
        return not_judged(
            "no machine group".to_string(),
            "give housing_group = 2, 3 or 4 (ISO 10816-5 Annex A)",
        );
    };
    if vibration.is_empty() {
        return not_judged(
            "no bearing stands on a pedestal".to_string(),
            "model the housings as [[pedestals]]",
        );
    }
    vibration
        .iter()
        .map(|h| {
            let zone = housing_zone(group, h);
            vec![
                check.into(),
                h.name.clone().into(),
                format!(
                    "{} mm/s r.m.s., {} µm pk-pk: zone {}",
                    short(h.velocity_rms * 1e3),
                    short(h.displacement_pp * 1e6),
                    zone.letter()
                )
                .into(),
                format!("zone A or B (group {})", group.number()).into(),
                Cell::verdict(Verdict::of(zone.acceptable())),
            ]
        })
        .collect()
}

/// The section's table: each housing's velocity and displacement with the
/// boundaries of its group and location.
pub fn housing_blocks(study: &HousingStudy) -> Vec<Block> {
    let (Ok(vibration), Some(group)) = (&study.vibration, study.group) else {
        return Vec::new();
    };
    let rows = vibration
        .iter()
        .map(|h| {
            let b = iso_10816_5_boundaries(group, h.stator_braced);
            let list = |v: [f64; 3], scale: f64| {
                v.iter()
                    .map(|x| short(x * scale))
                    .collect::<Vec<_>>()
                    .join(" / ")
            };
            vec![
                Cell::from(h.name.clone()),
                short(h.velocity_rms * 1e3).into(),
                list(b.velocity_rms, 1e3).into(),
                short(h.displacement_pp * 1e6).into(),
                b.displacement_pp
                    .map_or("—".to_string(), |d| list(d, 1e6))
                    .into(),
                housing_zone(group, h).letter().into(),
            ]
        })
        .collect();
    vec![Block::Table(Table {
        id: "housing-vibration".into(),
        caption: format!(
            "bearing-housing vibration at the operating speed, ISO 10816-5:2000 group {} (zone boundaries A/B / B/C / C/D)",
            group.number()
        ),
        headers: [
            "bearing",
            "velocity (mm/s r.m.s.)",
            "boundaries (mm/s)",
            "displacement (µm pk-pk)",
            "boundaries (µm)",
            "zone",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect(),
        rows,
    })]
}
