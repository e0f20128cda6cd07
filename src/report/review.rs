//! The design-review page's content as real tables: the tables of each
//! section (the first-page summary: [`super::review_summary`]). Every number is formatted by the same function as the command
//! that prints it ([`text::peak_cells`], [`text::margin_cells`], …), so the
//! page and the single commands agree cell for cell.

use crate::analysis::alignment::Alignment;
use crate::analysis::campbell::CampbellStudy;
use crate::analysis::modal::ModalResult;
use crate::analysis::operating_point::BearingOperatingPoint;
use crate::analysis::shaft_loads::CouplingLoad;
use crate::analysis::stability::Stability;
use crate::analysis::ucs::CriticalSpeedMap;
use crate::analysis::unbalance::UnbalanceStudy;
use crate::rotor::Rotor;
use crate::units::{Amplitude, RAD_S_TO_RPM};

use super::html::{Block, Cell, Table, Verdict};
use super::text::{self, short};

pub(super) fn headers(names: &[&str]) -> Vec<String> {
    names.iter().map(|s| s.to_string()).collect()
}

/// The verdict a command prints (`pass`, `FAIL`), else not judged.
fn verdict_of(text: &str) -> Verdict {
    match text {
        "pass" => Verdict::Pass,
        "FAIL" => Verdict::Fail,
        _ => Verdict::NotJudged,
    }
}

/// A verdict cell from a command's verdict text, keeping its words.
pub(crate) fn verdict_cell(text: &str) -> Cell {
    Cell {
        text: text.to_string(),
        verdict: Some(verdict_of(text)),
    }
}

/// The model as tables: its size, disks, bearings, unbalance planes, probes
/// and the node positions.
pub fn model_blocks(rotor: &Rotor) -> Vec<Block> {
    let m = &rotor.model;
    let mut out = vec![Block::Table(Table {
        id: "model-size".into(),
        caption: format!("model {}", m.name),
        headers: headers(&["quantity", "value"]),
        rows: vec![
            vec!["description".into(), m.description.clone().into()],
            vec!["nodes".into(), m.node_count().to_string().into()],
            vec!["shaft elements".into(), m.elements.len().to_string().into()],
            vec!["free DOFs".into(), rotor.dof_count().to_string().into()],
            vec![
                "length (m)".into(),
                short(m.node_z[m.node_z.len() - 1] - m.node_z[0]).into(),
            ],
            vec![
                "rotating mass (kg)".into(),
                format!("{:.3}", m.total_mass()).into(),
            ],
            vec![
                "gravity (m/s²)".into(),
                format!(
                    "({}, {}, {})",
                    short(m.gravity[0]),
                    short(m.gravity[1]),
                    short(m.gravity[2])
                )
                .into(),
            ],
            vec![
                "operating speed (rpm)".into(),
                short(m.nominal_speed * RAD_S_TO_RPM).into(),
            ],
            vec![
                "maximum speed (rpm)".into(),
                if m.max_speed_stated {
                    short(m.max_speed * RAD_S_TO_RPM).into()
                } else {
                    format!("{} (default)", short(m.max_speed * RAD_S_TO_RPM)).into()
                },
            ],
        ],
    })];
    let z = |node: usize| short(m.node_z[node]);
    let mut parts: Vec<Vec<Cell>> = Vec::new();
    for d in &m.disks {
        parts.push(vec![
            "disk".into(),
            d.name.clone().into(),
            (d.node + 1).to_string().into(),
            z(d.node).into(),
            format!(
                "m = {} kg, Ip = {} kg·m², Id = {} kg·m²",
                short(d.disk.mass),
                short(d.disk.polar_inertia),
                short(d.disk.diametral_inertia)
            )
            .into(),
        ]);
    }
    for b in &m.bearings {
        parts.push(vec![
            text::element_kind(&b.kind).into(),
            b.name.clone().into(),
            (b.node + 1).to_string().into(),
            z(b.node).into(),
            text::describe_bearing(&b.kind).into(),
        ]);
    }
    for p in &m.pedestals {
        parts.push(vec![
            "pedestal".into(),
            p.name.clone().into(),
            "—".into(),
            "—".into(),
            text::describe_pedestal(m, p).into(),
        ]);
    }
    for t in &m.thrust_bearings {
        parts.push(vec![
            "thrust bearing".into(),
            t.name.clone().into(),
            (t.node + 1).to_string().into(),
            z(t.node).into(),
            text::describe_thrust_bearing(t).into(),
        ]);
    }
    for f in &m.forces {
        parts.push(vec![
            "force".into(),
            f.name.clone().into(),
            (f.node + 1).to_string().into(),
            z(f.node).into(),
            text::describe_force(f).into(),
        ]);
    }
    for u in &m.unbalances {
        parts.push(vec![
            "unbalance".into(),
            u.name.clone().into(),
            (u.node + 1).to_string().into(),
            z(u.node).into(),
            format!(
                "{} kg·m at {}°",
                short(u.magnitude),
                short(u.phase.to_degrees())
            )
            .into(),
        ]);
    }
    for p in &m.probes {
        parts.push(vec![
            "probe".into(),
            p.name.clone().into(),
            (p.node + 1).to_string().into(),
            z(p.node).into(),
            "x, y displacement".into(),
        ]);
    }
    out.push(Block::Table(Table {
        id: "model-parts".into(),
        caption: "every element: disks, bearings, seals, rubs, magnetic pulls, pedestals, thrust bearings, forces, unbalance planes and probes".into(),
        headers: headers(&["kind", "name", "node", "z (m)", "data"]),
        rows: parts,
    }));
    out
}

/// The Campbell study's tables: critical speeds with their margins, and
/// the overdamped crossings apart.
pub fn campbell_blocks(rotor: &Rotor, study: &CampbellStudy) -> Vec<Block> {
    let mut out = vec![Block::Text(
        text::campbell_study(rotor, study)
            .lines()
            .next()
            .unwrap_or_default()
            .to_string(),
    )];
    let rows = study
        .margins
        .iter()
        .enumerate()
        .map(|(k, m)| {
            let c = text::margin_cells(m);
            vec![
                (k + 1).to_string().into(),
                c[0].clone().into(),
                (m.critical.branch + 1).to_string().into(),
                m.critical.whirl.label().into(),
                text::damping_ratio(m.critical.damping_ratio).into(),
                c[1].clone().into(),
                c[2].clone().into(),
                c[3].clone().into(),
                c[4].clone().into(),
                verdict_cell(&c[5]),
            ]
        })
        .collect();
    out.push(Block::Table(Table {
        id: "critical-speeds".into(),
        caption:
            "critical speeds (1× excitation, ζ < 0.5) and API 684 separation margins, AF = 1/(2ζ)"
                .into(),
        headers: headers(&[
            "#",
            "speed (rpm)",
            "branch",
            "whirl",
            "ζ",
            "AF",
            "required SM",
            "actual SM",
            "from max speed",
            "result",
        ]),
        rows,
    }));
    let overdamped: Vec<Vec<Cell>> = study
        .criticals
        .iter()
        .filter(|c| c.is_overdamped())
        .map(|c| {
            vec![
                format!("{:.2}", c.speed * RAD_S_TO_RPM).into(),
                (c.branch + 1).to_string().into(),
                c.whirl.label().into(),
                text::damping_ratio(c.damping_ratio).into(),
            ]
        })
        .collect();
    if !overdamped.is_empty() {
        out.push(Block::Table(Table {
            id: "overdamped-crossings".into(),
            caption: "overdamped crossings of the 1× line (ζ ≥ 0.5: no resonance peak, not critical speeds)".into(),
            headers: headers(&["speed (rpm)", "branch", "whirl", "ζ"]),
            rows: overdamped,
        }));
    }
    out
}

/// The unbalance study's table of peaks.
pub fn unbalance_blocks(study: &UnbalanceStudy, amplitude: Amplitude) -> Vec<Block> {
    let rows = study
        .rows
        .iter()
        .map(|(peak, margin)| {
            let c = text::peak_cells(&study.sweep, peak, margin.as_ref(), amplitude);
            let mut row: Vec<Cell> = c[..6].iter().map(|v| v.clone().into()).collect();
            row.push(verdict_cell(&c[6]));
            row
        })
        .collect();
    vec![Block::Table(Table {
        id: "unbalance-peaks".into(),
        caption: "unbalance response peaks, amplification factors and API 684 separation margins"
            .into(),
        headers: vec![
            "point".into(),
            "speed (rpm)".into(),
            format!("amplitude (µm {})", amplitude.label()),
            "AF".into(),
            "required SM".into(),
            "actual SM".into(),
            "result".into(),
        ],
        rows,
    })]
}

/// Every bearing's operating point: load, film, friction and coefficients.
pub fn operating_blocks(points: &[BearingOperatingPoint]) -> Vec<Block> {
    let rows = points
        .iter()
        .map(|p| {
            let film = p.film.as_ref();
            // A table bearing has no eccentricity, attitude or film thickness.
            let geometry = film.filter(|f| f.has_geometry());
            let dash = || Cell::from("—");
            let (load, attitude) = if p.is_unloaded() {
                ("0 (unloaded)".to_string(), "—".to_string())
            } else {
                (
                    short(p.load),
                    geometry.map_or("—".into(), |f| short(f.attitude_angle.to_degrees())),
                )
            };
            vec![
                p.name.clone().into(),
                load.into(),
                // A tilting pad's ε is over the assembled (bearing) clearance.
                geometry.map_or_else(dash, |f| match f.eccentricity_over_pad_clearance() {
                    Some(over_pad) => format!(
                        "{} (e/C_b, bearing clearance; e/C_p {} over the pad clearance)",
                        short(f.eccentricity),
                        short(over_pad)
                    )
                    .into(),
                    None => short(f.eccentricity).into(),
                }),
                attitude.into(),
                geometry.map_or_else(dash, |f| short(f.min_film_thickness * 1e6).into()),
                film.map_or_else(dash, |f| short(f.friction_torque).into()),
                film.map_or_else(dash, |f| short(f.power_loss).into()),
                text::coefficient_matrix(&p.stiffness).into(),
                text::coefficient_matrix(&p.damping).into(),
            ]
        })
        .collect();
    vec![Block::Table(Table {
        id: "operating-point".into(),
        caption: "bearings at the operating speed (synchronous coefficients, pads condensed)"
            .into(),
        headers: headers(&[
            "bearing",
            "load (N)",
            "ε",
            "attitude (°)",
            "h_min (µm)",
            "friction torque (N·m)",
            "power loss (W)",
            "K (N/m)",
            "C (N·s/m)",
        ]),
        rows,
    })]
}

/// The modes at the speed and the non-oscillating roots apart.
pub fn modes_blocks(result: &ModalResult) -> Vec<Block> {
    let rows = result
        .modes
        .iter()
        .enumerate()
        .map(|(k, m)| {
            let (zeta, delta) = text::zeta_and_log_dec(m);
            vec![
                (k + 1).to_string().into(),
                format!("{:.4}", m.damped_frequency / std::f64::consts::TAU).into(),
                format!("{:.4}", m.damped_frequency).into(),
                zeta.into(),
                delta.into(),
                m.whirl.label().into(),
            ]
        })
        .collect();
    let mut out = vec![Block::Table(Table {
        id: "modes".into(),
        caption: "damped modes".into(),
        headers: headers(&["mode", "f_d (Hz)", "ω_d (rad/s)", "ζ", "log dec", "whirl"]),
        rows,
    })];
    if !result.overdamped.is_empty() {
        out.push(Block::Table(Table {
            id: "overdamped-roots".into(),
            caption: "non-oscillating (overdamped) roots, not modes".into(),
            headers: headers(&["decay rate (1/s)", "time constant (s)"]),
            rows: result
                .overdamped
                .iter()
                .map(|r| {
                    vec![
                        short(r.decay_rate()).into(),
                        short(r.time_constant()).into(),
                    ]
                })
                .collect(),
        }));
    }
    out
}

/// The stability study: threshold and, with stage data, the Level I rows.
pub fn stability_blocks(result: &Stability, sites: &[String]) -> Vec<Block> {
    let printed = text::stability(result, sites);
    let tail: Vec<&str> = printed
        .lines()
        .skip(2 + result.modes.len())
        .map(str::trim)
        .collect();
    vec![Block::Table(Table {
        id: "stability".into(),
        caption: "cross-coupled stiffness and the API 617 / API 684 Level I screening".into(),
        headers: headers(&["finding"]),
        rows: tail.iter().map(|l| vec![Cell::from(*l)]).collect(),
    })]
}

/// Every few rows of the critical speed map.
pub fn ucs_blocks(map: &CriticalSpeedMap) -> Vec<Block> {
    let count = map.speeds.iter().map(Vec::len).max().unwrap_or(0);
    let mut head = vec!["support stiffness (N/m)".to_string()];
    head.extend((1..=count).map(|k| format!("critical {k} (rpm)")));
    let rows = map
        .stiffness
        .iter()
        .zip(&map.speeds)
        .step_by(3)
        .map(|(k, s)| {
            let mut row: Vec<Cell> = vec![format!("{k:.3e}").into()];
            row.extend(
                s.iter()
                    .map(|v| Cell::from(format!("{:.1}", v * RAD_S_TO_RPM))),
            );
            row
        })
        .collect();
    vec![Block::Table(Table {
        id: "ucs".into(),
        caption: "forward undamped critical speeds against isotropic support stiffness".into(),
        headers: head,
        rows,
    })]
}

/// The alignment of a shaft line at its offsets (issue 49): each bearing's
/// centre offset and the reaction it carries, and what each coupling
/// transmits between its shafts (shear and bending moment in both planes).
pub fn alignment_blocks(line: &Alignment, couplings: &[CouplingLoad]) -> Vec<Block> {
    let rows = line
        .bearings
        .iter()
        .map(|b| {
            vec![
                b.name.clone().into(),
                short(b.offset[0] * 1e6).into(),
                short(b.offset[1] * 1e6).into(),
                short(b.reaction[0]).into(),
                short(b.reaction[1]).into(),
                short(b.load).into(),
                b.area
                    .map_or("—".to_string(), |a| short(b.load / a * 1e-3))
                    .into(),
            ]
        })
        .collect();
    let mut blocks = vec![Block::Table(Table {
        id: "alignment".into(),
        caption:
            "bearing offsets and the reactions they carry (the static line at the operating speed)"
                .into(),
        headers: headers(&[
            "bearing",
            "offset x (µm)",
            "offset y (µm)",
            "reaction x (N)",
            "reaction y (N)",
            "load along gravity (N)",
            "specific load W/LD (kPa)",
        ]),
        rows,
    })];
    if !couplings.is_empty() {
        let rows = couplings
            .iter()
            .map(|c| {
                vec![
                    c.name.clone().into(),
                    format!("{}–{}", c.node + 1, c.node + 2).into(),
                    short(c.shear[0]).into(),
                    short(c.shear[1]).into(),
                    short(c.moment[0]).into(),
                    short(c.moment[1]).into(),
                ]
            })
            .collect();
        blocks.push(Block::Table(Table {
            id: "coupling-loads".into(),
            caption: "what each coupling transmits between its shafts at the static line".into(),
            headers: headers(&[
                "coupling",
                "nodes",
                "shear x (N)",
                "shear y (N)",
                "moment x–z (N·m)",
                "moment y–z (N·m)",
            ]),
            rows,
        }));
    }
    blocks
}
