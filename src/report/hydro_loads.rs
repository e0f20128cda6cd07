//! The loads and losses of a hydraulic machine set on the design-review page
//! (issue 48): each thrust bearing at the operating speed (its axial load,
//! the film data of the model, friction torque and power loss,
//! [`ThrustBearing`](crate::bearing::thrust::ThrustBearing)) and the power
//! the guide bearings and thrust bearings dissipate together.

use crate::analysis::element_operating_point::ThrustOperatingPoint;
use crate::analysis::operating_point::BearingOperatingPoint;
use crate::model::RotorModel;
use crate::units::RAD_S_TO_RPM;

use super::html::{Block, Cell, Table};
use super::text::short;

/// The power the bearings dissipate at the operating speed.
#[derive(Debug, Clone, PartialEq)]
pub struct PowerLosses {
    /// Each guide bearing: name, friction torque (N·m) and power loss (W);
    /// `None` for linear coefficients (no film).
    pub guide: Vec<(String, Option<(f64, f64)>)>,
    /// Each thrust bearing: name, friction torque (N·m) and power loss (W).
    pub thrust: Vec<(String, f64, f64)>,
}

impl PowerLosses {
    /// The guide bearings' and thrust bearings' losses (W).
    pub fn total(&self) -> f64 {
        self.guide
            .iter()
            .filter_map(|g| g.1.map(|(_, p)| p))
            .sum::<f64>()
            + self.thrust.iter().map(|t| t.2).sum::<f64>()
    }
}

/// The losses of the guide bearings `guides` and thrust bearings `thrusts`.
pub fn power_losses(
    model: &RotorModel,
    guides: &[BearingOperatingPoint],
    thrusts: &[ThrustOperatingPoint],
) -> PowerLosses {
    PowerLosses {
        guide: guides
            .iter()
            .map(|g| {
                (
                    g.name.clone(),
                    g.film.as_ref().map(|f| (f.friction_torque, f.power_loss)),
                )
            })
            .collect(),
        thrust: thrusts
            .iter()
            .map(|t| {
                (
                    model.thrust_bearings[t.thrust].name.clone(),
                    t.friction_torque,
                    t.power_loss,
                )
            })
            .collect(),
    }
}

/// The section's tables: the thrust bearings (or a note that the model has
/// none) and the power losses with their total.
pub fn thrust_blocks(
    model: &RotorModel,
    speed: f64,
    thrusts: &[ThrustOperatingPoint],
    losses: &Result<PowerLosses, String>,
) -> Vec<Block> {
    let rpm = short(speed.abs() * RAD_S_TO_RPM);
    let mut blocks = Vec::new();
    if thrusts.is_empty() {
        blocks.push(Block::Text(
            "The model has no [[thrust_bearings]]: no thrust bearing's load or loss is reported."
                .into(),
        ));
    } else {
        let rows = thrusts
            .iter()
            .map(|t| {
                let placed = &model.thrust_bearings[t.thrust];
                let b = &placed.bearing;
                vec![
                    Cell::from(placed.name.clone()),
                    format!("{}", placed.node + 1).into(),
                    short(t.load).into(),
                    format!("{} – {}", short(b.inner_radius), short(b.outer_radius)).into(),
                    short(b.coverage).into(),
                    short(b.film_thickness * 1e6).into(),
                    short(b.viscosity).into(),
                    format!(
                        "{}{}",
                        short(b.breakaway_torque()),
                        if b.oil_lift { " (oil lift)" } else { "" }
                    )
                    .into(),
                    short(t.friction_torque).into(),
                    short(t.power_loss).into(),
                ]
            })
            .collect();
        blocks.push(Block::Table(Table {
            id: "thrust-bearings".into(),
            caption: format!(
                "thrust bearings at {rpm} rpm: film torque c (π μ ω/(2h)) (R_o⁴ − R_i⁴) (Petroff, flat pad ring) plus the boundary friction μ_b W R_m fading with the lift-off speed; power loss T ω"
            ),
            headers: [
                "thrust bearing",
                "node",
                "axial load W (N)",
                "pad ring R_i – R_o (m)",
                "pad coverage c",
                "film thickness h (µm)",
                "viscosity μ (Pa·s)",
                "breakaway torque (N·m)",
                "friction torque (N·m)",
                "power loss (W)",
            ]
            .iter()
            .map(|s| s.to_string())
            .collect(),
            rows,
        }));
    }
    match losses {
        Ok(l) => {
            let mut rows: Vec<Vec<Cell>> = l
                .guide
                .iter()
                .map(|(name, film)| match film {
                    Some((t, p)) => vec![
                        Cell::from(format!("guide bearing {name}")),
                        short(*t).into(),
                        short(*p).into(),
                    ],
                    None => vec![
                        Cell::from(format!("guide bearing {name}")),
                        "—".into(),
                        "— (linear coefficients: no film)".into(),
                    ],
                })
                .collect();
            rows.extend(l.thrust.iter().map(|(name, t, p)| {
                vec![
                    Cell::from(format!("thrust bearing {name}")),
                    short(*t).into(),
                    short(*p).into(),
                ]
            }));
            rows.push(vec![
                Cell::from("total (guide and thrust bearings)"),
                "—".into(),
                short(l.total()).into(),
            ]);
            blocks.push(Block::Table(Table {
                id: "power-losses".into(),
                caption: format!("bearing power losses at {rpm} rpm"),
                headers: vec![
                    "bearing".into(),
                    "friction torque (N·m)".into(),
                    "power loss (W)".into(),
                ],
                rows,
            }));
        }
        Err(e) => blocks.push(Block::Failure(format!("power losses: {e}"))),
    }
    blocks
}
