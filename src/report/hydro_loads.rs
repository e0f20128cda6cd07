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

/// A bracket (pedestal) at the operating point: the load the rotor puts on
/// it through its bearings, its own weight, the load it passes on to its
/// support and its deflection.
#[derive(Debug, Clone, PartialEq)]
pub struct BracketLoad {
    /// Pedestal name.
    pub name: String,
    /// The bearings it carries.
    pub carries: Vec<String>,
    /// The force of the rotor on it through those bearings `(Fx, Fy)` (N):
    /// the bearings' reactions, reversed.
    pub reaction: [f64; 2],
    /// Its own weight `m g` in the lateral plane `(Fx, Fy)` (N).
    pub weight: [f64; 2],
    /// The load on its support `K (q − q_on)` (N): statically the reaction,
    /// its weight and whatever else stands on it (seals, other pedestals).
    pub load: [f64; 2],
    /// Its stiffness (N/m).
    pub stiffness: [[f64; 2]; 2],
    /// Its static deflection `(x, y)` (m), absolute.
    pub deflection: [f64; 2],
}

/// Every pedestal of `model` with the bearings' operating points `guides`
/// and the pedestals' `pedestals`.
pub fn bracket_loads(
    model: &RotorModel,
    guides: &[BearingOperatingPoint],
    pedestals: &[crate::analysis::operating_point::PedestalOperatingPoint],
) -> Vec<BracketLoad> {
    pedestals
        .iter()
        .map(|p| {
            let pedestal = &model.pedestals[p.pedestal];
            let carried: Vec<&BearingOperatingPoint> = guides
                .iter()
                .filter(|g| g.housing.as_ref().is_some_and(|h| h.pedestal == p.pedestal))
                .collect();
            let reaction = carried
                .iter()
                .fold([0.0; 2], |a, g| [a[0] - g.force[0], a[1] - g.force[1]]);
            BracketLoad {
                name: p.name.clone(),
                carries: carried.iter().map(|g| g.name.clone()).collect(),
                reaction,
                weight: [
                    pedestal.mass * model.gravity[0],
                    pedestal.mass * model.gravity[1],
                ],
                load: p.load,
                stiffness: pedestal.stiffness,
                deflection: p.deflection,
            }
        })
        .collect()
}

/// The brackets' table.
pub fn bracket_blocks(rpm: f64, brackets: &[BracketLoad]) -> Vec<Block> {
    let pair = |v: [f64; 2], scale: f64| {
        format!(
            "{} ({}, {})",
            short(v[0].hypot(v[1]) * scale),
            short(v[0] * scale),
            short(v[1] * scale)
        )
    };
    let rows = brackets
        .iter()
        .map(|b| {
            vec![
                Cell::from(b.name.clone()),
                if b.carries.is_empty() {
                    "—".to_string()
                } else {
                    b.carries.join(", ")
                }
                .into(),
                pair(b.reaction, 1.0).into(),
                pair(b.weight, 1.0).into(),
                pair(b.load, 1.0).into(),
                super::text::coefficient_matrix(&b.stiffness).into(),
                pair(b.deflection, 1e6).into(),
            ]
        })
        .collect();
    let mut blocks = Vec::new();
    if brackets
        .iter()
        .all(|b| b.load == [0.0; 2] && b.reaction == [0.0; 2])
    {
        blocks.push(Block::Text(
            "Every bracket load is zero: no static lateral load acts at this operating point (gravity along the shaft, no static lateral force or field in the model as written); the brackets' dynamic loads are the housing vibration's."
                .into(),
        ));
    }
    blocks.push(Block::Table(Table {
        id: "brackets".into(),
        caption: format!(
            "brackets (pedestals) at the static equilibrium at {} rpm: the rotor's force on each through its bearings, its weight, the load it passes on to its support K (q − q_on) and its deflection (magnitude (x, y))",
            short(rpm)
        ),
        headers: [
            "bracket",
            "carries",
            "bearing reaction (N)",
            "own weight (N)",
            "load on its support (N)",
            "stiffness K (N/m)",
            "deflection (µm)",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect(),
        rows,
    }));
    blocks
}
