//! `[shaft_vibration_zones]`: the zone boundaries of shaft relative
//! displacement a hydro unit's design review judges its orbits by
//! ([`crate::analysis::shaft_orbits`]), given by the user from their copy of
//! the standard (ISO 20816-5 for hydraulic machine sets), with the source
//! named. The tool ships no values of its own: the standard's table could
//! not be sourced for it, and none are invented.

use serde::Deserialize;

use super::context::Ctx;
use super::error::FieldPath;
use super::machine_class::MachineClass;
use super::{ModelError, PlacedBearing};
use crate::units::Short;

/// `[shaft_vibration_zones]` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ShaftZonesEntry {
    /// Where the values come from (standard, edition, table, machine kind).
    pub source: String,
    /// Zone boundaries A/B, B/C, C/D of the peak-to-peak shaft displacement
    /// relative to the housing (µm), increasing.
    pub boundaries_um: Vec<f64>,
    /// The bearings they apply at, by name; default every bearing (not
    /// seals, rubs or magnetic pulls).
    pub bearings: Option<Vec<String>>,
}

/// The validated `[shaft_vibration_zones]`.
#[derive(Debug, Clone, PartialEq)]
pub struct ShaftZones {
    /// Where the values come from.
    pub source: String,
    /// Zone boundaries A/B, B/C, C/D (m, peak-to-peak).
    pub boundaries: [f64; 3],
    /// Model bearing indices they apply at.
    pub bearings: Vec<usize>,
}

/// Check `[shaft_vibration_zones]`: a hydro class only, a source named,
/// three increasing positive boundaries (at most 10 mm), bearings by name.
pub(super) fn validate(
    ctx: &Ctx,
    root: &FieldPath,
    raw: Option<ShaftZonesEntry>,
    class: MachineClass,
    bearings: &[PlacedBearing],
) -> Result<Option<ShaftZones>, ModelError> {
    let Some(raw) = raw else {
        return Ok(None);
    };
    let p = root.key("shaft_vibration_zones");
    if !class.is_hydro() {
        return Err(ctx.err(
            p.key("source"),
            &raw.source,
            "judges a hydraulic machine set's shaft orbits: give it with machine = \"hydro_generator\" or \"pump_turbine\"",
        ));
    }
    if raw.source.trim().is_empty() {
        return Err(ctx.err(
            p.key("source"),
            "\"\"",
            "name where the boundaries come from (standard, edition, table, machine kind)",
        ));
    }
    let b = &raw.boundaries_um;
    let shown = || {
        format!(
            "[{}]",
            b.iter()
                .map(|v| Short(*v).to_string())
                .collect::<Vec<_>>()
                .join(", ")
        )
    };
    let valid = b.len() == 3
        && b.iter().all(|v| v.is_finite() && *v > 0.0 && *v <= 1e4)
        && b[0] < b[1]
        && b[1] < b[2];
    if !valid {
        return Err(ctx.err(
            p.key("boundaries_um"),
            shown(),
            "must be the three zone boundaries A/B, B/C, C/D in µm peak-to-peak, increasing, each above 0 and at most 10 000",
        ));
    }
    let supports: Vec<usize> = (0..bearings.len())
        .filter(|&k| bearings[k].kind.is_bearing())
        .collect();
    let chosen = match raw.bearings {
        None => supports,
        Some(names) => {
            let mut chosen = Vec::with_capacity(names.len());
            for (i, name) in names.iter().enumerate() {
                let k = supports
                    .iter()
                    .copied()
                    .find(|&k| &bearings[k].name == name)
                    .ok_or_else(|| {
                        ctx.err(
                            p.key("bearings").index(i),
                            name,
                            "must name a bearing of the model (not a seal, rub or magnetic pull)",
                        )
                    })?;
                if chosen.contains(&k) {
                    return Err(ctx.err(p.key("bearings").index(i), name, "is named twice"));
                }
                chosen.push(k);
            }
            chosen
        }
    };
    Ok(Some(ShaftZones {
        source: raw.source,
        boundaries: [b[0] * 1e-6, b[1] * 1e-6, b[2] * 1e-6],
        bearings: chosen,
    }))
}
