//! The shaft-orbit section of a hydro unit's design review: per case and
//! bearing, the shaft displacement relative to the housing
//! ([`crate::analysis::shaft_orbits`]) peak-to-peak in `x` and `y`, `S_max`
//! and `S_max` over the radial clearance the journal moves in. Judged only
//! by the zone boundaries the model gives (`[shaft_vibration_zones]`, from
//! the user's copy of ISO 20816-5): the larger of the two peak-to-peak
//! values against A/B, B/C, C/D, in the steady cases (not at runaway); zone
//! A or B passes. Without them the values are shown and the summary row says
//! "not judged": the tool ships no zone values, as the standard's table
//! could not be sourced.

use crate::analysis::housing_vibration::Zone;
use crate::analysis::shaft_orbits::{BearingOrbit, CaseOrbits};
use crate::model::shaft_zones::ShaftZones;

use super::html::{Block, Cell, Table, Verdict};
use super::text::short;

/// The zone of `orbit` (the larger peak-to-peak) where `zones` apply to it.
pub fn orbit_zone(zones: Option<&ShaftZones>, orbit: &BearingOrbit) -> Option<Zone> {
    let z = zones?;
    z.bearings.contains(&orbit.bearing).then(|| {
        Zone::of(
            orbit.peak_to_peak[0].max(orbit.peak_to_peak[1]),
            z.boundaries,
        )
    })
}

/// The table of every case's orbits and the note on the zones.
pub fn orbit_blocks(cases: &[CaseOrbits], zones: Option<&ShaftZones>) -> Vec<Block> {
    let um = |v: f64| short(v * 1e6);
    let rows = cases
        .iter()
        .flat_map(|c| {
            c.bearings.iter().map(move |b| {
                let zone = match orbit_zone(zones, b) {
                    Some(z) if c.case.steady => z.letter().to_string(),
                    Some(_) => "— (not steady)".to_string(),
                    None => "—".to_string(),
                };
                vec![
                    Cell::from(c.case.label.clone()),
                    b.name.clone().into(),
                    um(b.peak_to_peak[0]).into(),
                    um(b.peak_to_peak[1]).into(),
                    um(b.s_max).into(),
                    b.clearance
                        .map_or("—".to_string(), |cl| format!("{:.3}", b.s_max / cl))
                        .into(),
                    zone.into(),
                ]
            })
        })
        .collect();
    let note = match zones {
        Some(z) => format!(
            "S_max: the largest distance of the orbit from its mean position. Zones from the model's [shaft_vibration_zones] ({}): A/B, B/C, C/D at {} µm peak-to-peak, the larger of x and y judged in the steady cases (zone A or B passes), not at runaway.",
            z.source,
            z.boundaries.iter().map(|b| um(*b)).collect::<Vec<_>>().join(" / ")
        ),
        None => "S_max: the largest distance of the orbit from its mean position. Not judged: the model gives no [shaft_vibration_zones]; the tool ships no values of ISO 20816-5 for shaft relative displacement (its table could not be sourced), so they are the user's to give from their copy of the standard.".into(),
    };
    vec![
        Block::Table(Table {
            id: "shaft-orbits".into(),
            caption: "shaft displacement relative to the bearing housing (probes in x and y), from the nonlinear transient with the model's loads".into(),
            headers: [
                "case",
                "bearing",
                "x (µm pk-pk)",
                "y (µm pk-pk)",
                "S_max (µm)",
                "S_max / radial clearance",
                "zone",
            ]
            .iter()
            .map(|h| h.to_string())
            .collect(),
            rows,
        }),
        Block::Text(note),
    ]
}

/// The summary row of the shaft orbits: the worst zone over the steady
/// cases and the bearings the zones apply at, and the case and bearing that
/// govern; "not judged" without zones or orbits.
pub fn orbit_summary_row(
    orbits: &Result<&[CaseOrbits], String>,
    zones: Option<&ShaftZones>,
) -> Vec<Cell> {
    let check = "shaft relative displacement";
    let not_judged = |value: String, criterion: &str| {
        vec![
            check.into(),
            "—".into(),
            value.into(),
            criterion.into(),
            Cell::verdict(Verdict::NotJudged),
        ]
    };
    let orbits = match orbits {
        Ok(o) => o,
        Err(e) => return not_judged(format!("not computed: {e}"), "—"),
    };
    let Some(z) = zones else {
        return not_judged(
            "orbits shown, no zones given".into(),
            "zones of [shaft_vibration_zones] (ISO 20816-5, the user's values)",
        );
    };
    let worst = orbits
        .iter()
        .filter(|c| c.case.steady)
        .flat_map(|c| c.bearings.iter().map(move |b| (c, b)))
        .filter_map(|(c, b)| orbit_zone(Some(z), b).map(|zone| (zone, c, b)))
        .max_by(|a, b| {
            let pp = |o: &BearingOrbit| o.peak_to_peak[0].max(o.peak_to_peak[1]);
            (a.0, pp(a.2))
                .partial_cmp(&(b.0, pp(b.2)))
                .unwrap_or(std::cmp::Ordering::Equal)
        });
    let criterion = format!(
        "zone A or B ({}: B/C at {} µm pk-pk)",
        z.source,
        short(z.boundaries[1] * 1e6)
    );
    match worst {
        Some((zone, c, b)) => vec![
            check.into(),
            format!("{}, {}", c.case.label, b.name).into(),
            format!(
                "{} µm pk-pk, zone {}",
                short(b.peak_to_peak[0].max(b.peak_to_peak[1]) * 1e6),
                zone.letter()
            )
            .into(),
            criterion.into(),
            Cell::verdict(Verdict::of(zone.acceptable())),
        ],
        None => not_judged("no orbit at the zones' bearings".into(), &criterion),
    }
}

#[cfg(test)]
mod tests {
    use super::{orbit_blocks, orbit_summary_row};
    use crate::analysis::shaft_orbits::{BearingOrbit, CaseOrbits, OrbitCase};
    use crate::model::shaft_zones::ShaftZones;
    use crate::report::html::{Block, Verdict};

    fn orbit(bearing: usize, pp: [f64; 2]) -> BearingOrbit {
        BearingOrbit {
            bearing,
            name: format!("b{bearing}"),
            x: vec![],
            y: vec![],
            peak_to_peak: pp,
            s_max: 0.5 * pp[0].max(pp[1]),
            clearance: Some(2.5e-4),
        }
    }

    fn case(label: &str, steady: bool, bearings: Vec<BearingOrbit>) -> CaseOrbits {
        CaseOrbits {
            case: OrbitCase {
                label: label.into(),
                speed: 1.0,
                excitation: None,
                steady,
            },
            spin_angle: vec![],
            bearings,
        }
    }

    /// Zones 30 / 50 / 80 µm at bearing 0 only: 45 µm (the larger of x and
    /// y) is zone B and passes; 60 µm in a steady case is zone C and fails,
    /// naming its case and bearing; 200 µm at runaway and 300 µm at bearing 1
    /// (no zones there) are not judged; without zones the row is "not
    /// judged".
    #[test]
    fn the_worst_steady_orbit_governs_by_the_models_zones() {
        let zones = ShaftZones {
            source: "test table".into(),
            boundaries: [30e-6, 50e-6, 80e-6],
            bearings: vec![0],
        };
        let b = case(
            "operating",
            true,
            vec![orbit(0, [20e-6, 45e-6]), orbit(1, [300e-6, 1e-6])],
        );
        let runaway = case("runaway", false, vec![orbit(0, [200e-6, 1e-6])]);
        let cases = vec![b.clone(), runaway.clone()];
        let row = orbit_summary_row(&Ok(&cases), Some(&zones));
        let text: Vec<String> = row.iter().map(|c| c.text.clone()).collect();
        assert!(
            text[2].contains("45") && text[2].contains("zone B"),
            "{text:?}"
        );
        assert_eq!(row[4].text, Verdict::Pass.text());
        let field_on = case("field on", true, vec![orbit(0, [60e-6, 10e-6])]);
        let cases = vec![b, field_on, runaway];
        let row = orbit_summary_row(&Ok(&cases), Some(&zones));
        assert!(
            row[1].text.contains("field on") && row[1].text.contains("b0"),
            "{:?}",
            row[1]
        );
        assert!(row[2].text.contains("zone C"), "{:?}", row[2]);
        assert_eq!(row[4].text, Verdict::Fail.text());
        let row = orbit_summary_row(&Ok(&cases), None);
        assert_eq!(row[4].text, Verdict::NotJudged.text());
        let blocks = orbit_blocks(&cases, Some(&zones));
        let Block::Table(t) = &blocks[0] else {
            panic!("{blocks:?}")
        };
        let zones: Vec<String> = t.rows.iter().map(|r| r[6].text.clone()).collect();
        assert_eq!(zones, ["B", "—", "C", "— (not steady)"]);
    }

    /// One row per case and bearing, in µm, the ratio to the clearance to
    /// three decimals and a dash where the bearing has no clearance.
    #[test]
    fn every_case_and_bearing_gets_a_row_in_micrometres() {
        let orbit = |name: &str, clearance| BearingOrbit {
            bearing: 0,
            name: name.into(),
            x: vec![],
            y: vec![],
            peak_to_peak: [12e-6, 30e-6],
            s_max: 16e-6,
            clearance,
        };
        let case = |label: &str| CaseOrbits {
            case: OrbitCase {
                label: label.into(),
                speed: 1.0,
                excitation: None,
                steady: true,
            },
            spin_angle: vec![],
            bearings: vec![orbit("upper", Some(2.5e-4)), orbit("lower", None)],
        };
        let blocks = orbit_blocks(&[case("operating"), case("runaway")], None);
        let Block::Table(t) = &blocks[0] else {
            panic!("{blocks:?}")
        };
        assert_eq!(t.rows.len(), 4);
        let text: Vec<String> = t.rows[0].iter().map(|c| format!("{c:?}")).collect();
        for want in ["operating", "upper", "12", "30", "16", "0.064"] {
            assert!(text.iter().any(|c| c.contains(want)), "{want}: {text:?}");
        }
        assert!(format!("{:?}", t.rows[1][5]).contains('—'));
    }
}
