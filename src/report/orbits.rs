//! The shaft-orbit section of a hydro unit's design review: per case and
//! bearing, the shaft displacement relative to the housing
//! ([`crate::analysis::shaft_orbits`]) peak-to-peak in `x` and `y`, `S_max`
//! and `S_max` over the radial clearance the journal moves in. Shown, not
//! judged: the zone boundaries of ISO 20816-5 (shaft relative displacement
//! of hydraulic machine sets) are not applied, as the standard's table could
//! not be sourced; the report says so rather than invent them.

use crate::analysis::shaft_orbits::CaseOrbits;

use super::html::{Block, Cell, Table};
use super::text::short;

/// The table of every case's orbits and the note on the zones.
pub fn orbit_blocks(cases: &[CaseOrbits]) -> Vec<Block> {
    let um = |v: f64| short(v * 1e6);
    let rows = cases
        .iter()
        .flat_map(|c| {
            c.bearings.iter().map(move |b| {
                vec![
                    Cell::from(c.case.label.clone()),
                    b.name.clone().into(),
                    um(b.peak_to_peak[0]).into(),
                    um(b.peak_to_peak[1]).into(),
                    um(b.s_max).into(),
                    b.clearance
                        .map_or("—".to_string(), |cl| format!("{:.3}", b.s_max / cl))
                        .into(),
                ]
            })
        })
        .collect();
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
            ]
            .iter()
            .map(|h| h.to_string())
            .collect(),
            rows,
        }),
        Block::Text(
            "S_max: the largest distance of the orbit from its mean position. The values are shown, not judged: the zone boundaries of ISO 20816-5 for shaft relative displacement are not applied (the standard's table could not be sourced for this tool)."
                .into(),
        ),
    ]
}

#[cfg(test)]
mod tests {
    use super::orbit_blocks;
    use crate::analysis::shaft_orbits::{BearingOrbit, CaseOrbits, OrbitCase};
    use crate::report::html::Block;

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
            },
            spin_angle: vec![],
            bearings: vec![orbit("upper", Some(2.5e-4)), orbit("lower", None)],
        };
        let blocks = orbit_blocks(&[case("operating"), case("runaway")]);
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
