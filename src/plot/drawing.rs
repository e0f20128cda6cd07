//! Rotor drawing: shaft sections to scale, disks, bearings, probes, supports
//! and node numbers.

use std::path::Path;

use plotters::prelude::*;

use crate::model::RotorModel;

use super::{PlotError, failed};

/// Width of the drawing (pixels).
const WIDTH: u32 = 1400;

/// Radial scale of [`rotor_png`] relative to the axial one: 1 (true scale)
/// unless the rotor is so slender that it would be drawn thinner than a tenth
/// of its length, then the exaggeration that makes it a tenth.
pub fn radial_exaggeration(model: &RotorModel) -> f64 {
    let length = (model.node_z[model.node_count() - 1] - model.node_z[0]).max(1e-9);
    let diameter = largest_diameter(model).max(1e-9);
    (0.1 * length / diameter).max(1.0)
}

fn largest_diameter(model: &RotorModel) -> f64 {
    let shaft = model
        .elements
        .iter()
        .map(|e| e.element.section.outer_diameter)
        .fold(0.0, f64::max);
    model
        .disks
        .iter()
        .map(|d| d.disk.equivalent_solid_dimensions().0)
        .fold(shaft, f64::max)
}

/// Side view of `model` in the y–z plane: shaft elements as their outer (and
/// bore) outline, disks as the equivalent solid disk
/// ([`Disk::equivalent_solid_dimensions`](crate::fe::disk::Disk::equivalent_solid_dimensions)),
/// bearings as triangles under the shaft with their names, rub elements as
/// stator bars around it, probes as arrows
/// above it, supports as crosses, node numbers along the bottom. Axial and
/// radial scales are equal unless [`radial_exaggeration`] says otherwise (the
/// title then says by how much).
pub fn rotor_png(path: &Path, title: &str, model: &RotorModel) -> Result<(), PlotError> {
    let z0 = model.node_z[0];
    let z1 = model.node_z[model.node_count() - 1];
    let length = (z1 - z0).max(1e-9);
    let scale = radial_exaggeration(model);
    let r_max = 0.5 * largest_diameter(model) * scale;
    // Room for labels: 0.9 r_max above and below the rotor, and for the
    // pedestals below.
    let half = 1.9 * r_max.max(0.02 * length) + 0.3 * r_max * depth(model) as f64;
    let margin = 0.1 * length;
    let plot_w = f64::from(WIDTH - 120);
    let height = ((2.0 * half) / (length + 2.0 * margin) * plot_w) as u32 + 140;
    let root = BitMapBackend::new(path, (WIDTH, height.clamp(300, 1400))).into_drawing_area();
    root.fill(&WHITE).map_err(|e| failed(path, e))?;
    let caption = if scale > 1.0 {
        format!("{title} (radial scale ×{scale:.1})")
    } else {
        format!("{title} (to scale)")
    };
    let mut chart = ChartBuilder::on(&root)
        .caption(caption, ("sans-serif", 24))
        .margin(20)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d((z0 - margin)..(z1 + margin), -half..half)
        .map_err(|e| failed(path, e))?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc("z (m)")
        .y_desc(if scale > 1.0 {
            "radius (exaggerated)"
        } else {
            "radius (m)"
        })
        .label_style(("sans-serif", 14))
        .draw()
        .map_err(|e| failed(path, e))?;
    let steel = RGBColor(160, 170, 185);
    for e in &model.elements {
        let (za, zb) = (model.node_z[e.node], model.node_z[e.node + 1]);
        let ro = 0.5 * e.element.section.outer_diameter * scale;
        let ri = 0.5 * e.element.section.inner_diameter * scale;
        chart
            .draw_series([
                Rectangle::new([(za, -ro), (zb, ro)], steel.filled()),
                Rectangle::new([(za, -ro), (zb, ro)], BLACK.stroke_width(1)),
            ])
            .map_err(|e| failed(path, e))?;
        if ri > 0.0 {
            chart
                .draw_series([Rectangle::new([(za, -ri), (zb, ri)], WHITE.filled())])
                .map_err(|e| failed(path, e))?;
        }
    }
    chart
        .draw_series(DashedLineSeries::new(
            [(z0 - 0.5 * margin, 0.0), (z1 + 0.5 * margin, 0.0)],
            10,
            6,
            BLACK.stroke_width(1),
        ))
        .map_err(|e| failed(path, e))?;
    for d in &model.disks {
        let z = model.node_z[d.node];
        let (diameter, width) = d.disk.equivalent_solid_dimensions();
        let (r, w) = (0.5 * diameter * scale, width.max(0.004 * length));
        chart
            .draw_series([
                Rectangle::new(
                    [(z - w / 2.0, -r), (z + w / 2.0, r)],
                    RGBColor(90, 110, 160).filled(),
                ),
                Rectangle::new([(z - w / 2.0, -r), (z + w / 2.0, r)], BLACK.stroke_width(1)),
            ])
            .map_err(|e| failed(path, e))?;
        chart
            .draw_series([Text::new(
                format!("disk {}", d.name),
                (z + w, -r - 0.1 * r_max),
                ("sans-serif", 15),
            )])
            .map_err(|e| failed(path, e))?;
    }
    // Outer radius of the rotor at a node: its shaft sections and disks.
    let radius_at = |node: usize| -> f64 {
        let shaft = model
            .elements
            .iter()
            .filter(|e| e.node == node || e.node + 1 == node)
            .map(|e| 0.5 * e.element.section.outer_diameter * scale)
            .fold(0.0, f64::max);
        model
            .disks
            .iter()
            .filter(|d| d.node == node)
            .map(|d| 0.5 * d.disk.equivalent_solid_dimensions().0 * scale)
            .fold(shaft, f64::max)
    };
    let red = RGBColor(190, 30, 30);
    let purple = RGBColor(120, 40, 150);
    let teal = RGBColor(0, 120, 130);
    for b in &model.bearings {
        let z = model.node_z[b.node];
        if !b.kind.is_bearing() {
            // A stator ring: bars above and below the rotor at the node.
            let (color, what) = if b.kind.is_seal() {
                (teal, "seal")
            } else if b.kind.is_magnetic_pull() {
                (RGBColor(200, 120, 0), "magnetic pull")
            } else {
                (purple, "rub")
            };
            let r = radius_at(b.node) + 0.12 * r_max;
            for side in [1.0, -1.0] {
                chart
                    .draw_series(LineSeries::new(
                        [(z, side * r), (z, side * (r + 0.2 * r_max))],
                        color.stroke_width(5),
                    ))
                    .map_err(|e| failed(path, e))?;
            }
            chart
                .draw_series([EmptyElement::at((z, r + 0.2 * r_max))
                    + Text::new(
                        format!("{what} {}", b.name),
                        (-20, -20),
                        ("sans-serif", 15).into_font().color(&color),
                    )])
                .map_err(|e| failed(path, e))?;
            continue;
        }
        let y = -radius_at(b.node) - 0.25 * r_max;
        chart
            .draw_series([EmptyElement::at((z, y))
                + TriangleMarker::new((0, 0), 12, red.filled())
                + Text::new(
                    format!("bearing {}", b.name),
                    (-30, 14),
                    ("sans-serif", 15).into_font().color(&red),
                )])
            .map_err(|e| failed(path, e))?;
    }
    // Pedestals: each one a bar under the bearings it carries, hung on a
    // spring from them and standing on a spring to ground or to the pedestal
    // below (drawn lower still).
    let levels = pedestal_levels(model);
    let bearing_y = |node: usize| -radius_at(node) - 0.25 * r_max;
    let step = 0.3 * r_max;
    let lowest = model
        .bearings
        .iter()
        .map(|b| bearing_y(b.node))
        .fold(0.0, f64::min);
    let bar: Vec<(f64, f64, f64)> = levels
        .iter()
        .enumerate()
        .map(|(p, level)| {
            let (lo, hi) = bar_span(model, p);
            (lo, hi, lowest - step * (*level as f64 + 1.0))
        })
        .collect();
    let brown = RGBColor(130, 80, 30);
    let spring = |from: (f64, f64), to_y: f64| -> Vec<(f64, f64)> {
        // A zigzag from `from` down to `to_y`.
        let (z, y0) = from;
        let w = 0.006 * length;
        let mut points = vec![(z, y0)];
        for k in 1..8 {
            let y = y0 + (to_y - y0) * k as f64 / 8.0;
            points.push((z + if k % 2 == 0 { -w } else { w }, y));
        }
        points.push((z, to_y));
        points
    };
    for (p, pedestal) in model.pedestals.iter().enumerate() {
        let (lo, hi, y) = bar[p];
        let pad = 0.01 * length;
        for b in model.bearings.iter().filter(|b| b.pedestal == Some(p)) {
            let z = model.node_z[b.node];
            let top = bearing_y(b.node) - 0.05 * r_max;
            chart
                .draw_series(LineSeries::new(spring((z, top), y), brown.stroke_width(2)))
                .map_err(|e| failed(path, e))?;
        }
        chart
            .draw_series([Rectangle::new(
                [(lo - pad, y - 0.04 * r_max), (hi + pad, y)],
                brown.filled(),
            )])
            .map_err(|e| failed(path, e))?;
        chart
            .draw_series([EmptyElement::at((hi + pad, y))
                + Text::new(
                    format!("pedestal {}", pedestal.name),
                    (6, -6),
                    ("sans-serif", 14).into_font().color(&brown),
                )])
            .map_err(|e| failed(path, e))?;
        let mid = 0.5 * (lo + hi);
        let below = match pedestal.on {
            Some(q) => bar[q].2,
            None => y - 0.7 * step,
        };
        chart
            .draw_series(LineSeries::new(
                spring((mid, y - 0.04 * r_max), below),
                brown.stroke_width(2),
            ))
            .map_err(|e| failed(path, e))?;
        if pedestal.on.is_none() {
            // Ground: a hatched line.
            let w = 0.02 * length;
            chart
                .draw_series(LineSeries::new(
                    [(mid - w, below), (mid + w, below)],
                    BLACK.stroke_width(2),
                ))
                .map_err(|e| failed(path, e))?;
            for k in 0..5 {
                let z = mid - w + 2.0 * w * k as f64 / 4.0;
                chart
                    .draw_series(LineSeries::new(
                        [(z, below), (z - 0.4 * w, below - 0.1 * r_max)],
                        BLACK.stroke_width(1),
                    ))
                    .map_err(|e| failed(path, e))?;
            }
        }
    }
    for pm in &model.point_masses {
        let z = model.node_z[pm.node];
        let r = 0.35 * radius_at(pm.node).max(0.05 * r_max);
        chart
            .draw_series([Rectangle::new(
                [(z - 0.3 * r, -r), (z + 0.3 * r, r)],
                BLACK.filled(),
            )])
            .map_err(|e| failed(path, e))?;
        chart
            .draw_series([EmptyElement::at((z, r))
                + Text::new(format!("mass {}", pm.name), (4, -18), ("sans-serif", 14))])
            .map_err(|e| failed(path, e))?;
    }
    let green = RGBColor(20, 130, 60);
    for p in &model.probes {
        let z = model.node_z[p.node];
        let top = radius_at(p.node) + 0.45 * r_max;
        chart
            .draw_series(LineSeries::new(
                [(z, top), (z, radius_at(p.node) + 0.05 * r_max)],
                green.stroke_width(2),
            ))
            .map_err(|e| failed(path, e))?;
        chart
            .draw_series([EmptyElement::at((z, top))
                + Text::new(
                    format!("probe {}", p.name),
                    (-20, -20),
                    ("sans-serif", 15).into_font().color(&green),
                )])
            .map_err(|e| failed(path, e))?;
    }
    for s in &model.supports {
        let z = model.node_z[s.node];
        chart
            .draw_series([Cross::new((z, 0.0), 8, BLACK.stroke_width(3))])
            .map_err(|e| failed(path, e))?;
    }
    let y_nodes = -1.6 * r_max.max(0.02 * length) - 0.3 * r_max * depth(model) as f64;
    for (k, z) in model.node_z.iter().enumerate() {
        chart
            .draw_series([EmptyElement::at((*z, y_nodes))
                + Circle::new((0, 0), 2, BLACK.filled())
                + Text::new(format!("{}", k + 1), (-4, 6), ("sans-serif", 13))])
            .map_err(|e| failed(path, e))?;
    }
    root.present().map_err(|e| failed(path, e))?;
    Ok(())
}

/// The drawing level of each pedestal: 0 for one that carries only
/// bearings, one more than the highest of the pedestals standing on it.
fn pedestal_levels(model: &RotorModel) -> Vec<usize> {
    fn level(model: &RotorModel, p: usize) -> usize {
        (0..model.pedestals.len())
            .filter(|&q| model.pedestals[q].on == Some(p))
            .map(|q| level(model, q) + 1)
            .max()
            .unwrap_or(0)
    }
    (0..model.pedestals.len())
        .map(|p| level(model, p))
        .collect()
}

/// Levels of pedestals drawn under the rotor (0 without pedestals).
fn depth(model: &RotorModel) -> usize {
    pedestal_levels(model)
        .iter()
        .map(|l| l + 2)
        .max()
        .unwrap_or(0)
}

/// The axial span (m) of the bearings standing directly on pedestal `p`
/// (its own position when it carries only other pedestals: theirs).
fn bar_span(model: &RotorModel, p: usize) -> (f64, f64) {
    let zs: Vec<f64> = model
        .bearings
        .iter()
        .filter(|b| b.pedestal == Some(p))
        .map(|b| model.node_z[b.node])
        .chain(
            (0..model.pedestals.len())
                .filter(|&q| model.pedestals[q].on == Some(p))
                .flat_map(|q| {
                    let (a, b) = bar_span(model, q);
                    [a, b]
                }),
        )
        .collect();
    zs.iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), z| {
            (a.min(*z), b.max(*z))
        })
}
