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

/// A rectangle in data coordinates: `z` and `y` ranges (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Area {
    /// Axial range.
    pub z: (f64, f64),
    /// Radial range.
    pub y: (f64, f64),
}

impl Area {
    fn overlaps(&self, other: &Area) -> bool {
        self.z.0 < other.z.1 && other.z.0 < self.z.1 && self.y.0 < other.y.1 && other.y.0 < self.y.1
    }

    fn inside(&self, bounds: &Area) -> bool {
        self.z.0 >= bounds.z.0
            && self.z.1 <= bounds.z.1
            && self.y.0 >= bounds.y.0
            && self.y.1 <= bounds.y.1
    }
}

/// A label of the drawing: its text, where it points (`z`, and `y` the edge
/// of the text nearest the rotor), which way it goes (`side` +1 above, −1
/// below) and its colour.
#[derive(Debug, Clone, PartialEq)]
pub struct Label {
    /// Text.
    pub text: String,
    /// Axial position it names (m).
    pub z: f64,
    /// Radial position of the text's edge nearest the rotor.
    pub y: f64,
    /// +1: the text goes upward from `y`; −1: downward.
    pub side: f64,
    /// Colour.
    pub color: RGBColor,
}

/// Where each label's text goes: centred on its `z` but moved inside
/// `bounds`, at its `y` or as many text rows further out as it takes to
/// overlap neither the `obstacles` nor the labels placed before it (`size`:
/// one character's width and one row's height in data units).
pub fn place_labels(
    labels: &[Label],
    obstacles: &[Area],
    bounds: Area,
    size: (f64, f64),
) -> Vec<Area> {
    let (cw, row) = size;
    let mut placed: Vec<Area> = Vec::new();
    for l in labels {
        let w = cw * l.text.chars().count() as f64;
        let lo = (l.z - 0.5 * w).clamp(bounds.z.0, (bounds.z.1 - w).max(bounds.z.0));
        let at = |k: usize| {
            let near = l.y + l.side * k as f64 * row;
            let (y0, y1) = if l.side > 0.0 {
                (near, near + row)
            } else {
                (near - row, near)
            };
            Area {
                z: (lo, lo + w),
                y: (y0, y1),
            }
        };
        let free =
            |a: &Area| a.inside(&bounds) && !obstacles.iter().chain(&placed).any(|o| a.overlaps(o));
        let chosen = (0..40).map(at).find(free).unwrap_or_else(|| at(0));
        placed.push(chosen);
    }
    placed
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
    // Room for labels: rows of them above and below the rotor, and for the
    // pedestals below.
    let half = 2.6 * r_max.max(0.02 * length) + 0.3 * r_max * depth(model) as f64;
    let margin = 0.1 * length;
    let plot_w = f64::from(WIDTH - 120);
    let height = (((2.0 * half) / (length + 2.0 * margin) * plot_w) as u32 + 140).clamp(300, 1400);
    let root = BitMapBackend::new(path, (WIDTH, height)).into_drawing_area();
    // Text size in data units: about 8.5 px per character and 19 px per
    // line of the 15 px font over the plotting area.
    let per_px_z = (length + 2.0 * margin) / f64::from(WIDTH - 100);
    let per_px_y = 2.0 * half / f64::from(height - 114);
    let mut labels: Vec<Label> = Vec::new();
    let mut obstacles: Vec<Area> = Vec::new();
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
        obstacles.push(Area {
            z: (z - w / 2.0, z + w / 2.0),
            y: (-r, r),
        });
        labels.push(Label {
            text: format!("disk {}", d.name),
            z,
            y: -r - 0.05 * r_max,
            side: -1.0,
            color: BLACK,
        });
    }
    for e in &model.elements {
        let ro = 0.5 * e.element.section.outer_diameter * scale;
        obstacles.push(Area {
            z: (model.node_z[e.node], model.node_z[e.node + 1]),
            y: (-ro, ro),
        });
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
            obstacles.push(Area {
                z: (z - 4.0 * per_px_z, z + 4.0 * per_px_z),
                y: (-(r + 0.2 * r_max), r + 0.2 * r_max),
            });
            labels.push(Label {
                text: format!("{what} {}", b.name),
                z,
                y: r + 0.25 * r_max,
                side: 1.0,
                color,
            });
            continue;
        }
        let y = -radius_at(b.node) - 0.25 * r_max;
        chart
            .draw_series([EmptyElement::at((z, y)) + TriangleMarker::new((0, 0), 12, red.filled())])
            .map_err(|e| failed(path, e))?;
        obstacles.push(Area {
            z: (z - 12.0 * per_px_z, z + 12.0 * per_px_z),
            y: (y - 12.0 * per_px_y, y + 12.0 * per_px_y),
        });
        labels.push(Label {
            text: format!("bearing {}", b.name),
            z,
            y: y - 14.0 * per_px_y,
            side: -1.0,
            color: red,
        });
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
        obstacles.push(Area {
            z: (z - 2.0 * per_px_z, z + 2.0 * per_px_z),
            y: (radius_at(p.node), top),
        });
        labels.push(Label {
            text: format!("probe {}", p.name),
            z,
            y: top + 4.0 * per_px_y,
            side: 1.0,
            color: green,
        });
    }
    let bounds = Area {
        z: (z0 - margin, z1 + margin),
        y: (-half, half),
    };
    let text_size = (8.5 * per_px_z, 19.0 * per_px_y);
    for (label, area) in labels
        .iter()
        .zip(place_labels(&labels, &obstacles, bounds, text_size))
    {
        // A label moved away from what it names gets a leader line to it.
        let near = if label.side > 0.0 { area.y.0 } else { area.y.1 };
        if (near - label.y).abs() > 1.5 * text_size.1 {
            let mid = 0.5 * (area.z.0 + area.z.1);
            chart
                .draw_series(LineSeries::new(
                    [(label.z, label.y), (mid, near)],
                    label.color.mix(0.6).stroke_width(1),
                ))
                .map_err(|e| failed(path, e))?;
        }
        chart
            .draw_series([Text::new(
                label.text.clone(),
                (area.z.0, area.y.1),
                ("sans-serif", 15).into_font().color(&label.color),
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The hydro unit's labels used to overlap its generator disk and run
    /// off the right edge: every label now lies inside the drawing, clear of
    /// the rotor and of every other label.
    #[test]
    fn labels_stay_inside_and_never_overlap() {
        let bounds = Area {
            z: (-2.0, 17.9),
            y: (-9.0, 9.0),
        };
        let obstacles = vec![
            Area {
                z: (1.9, 4.5),
                y: (-4.5, 4.5),
            }, // generator disk
            Area {
                z: (16.7, 17.7),
                y: (-2.5, 2.5),
            }, // runner
            Area {
                z: (0.0, 17.2),
                y: (-0.5, 0.5),
            }, // shaft
        ];
        let label = |text: &str, z: f64, y: f64, side: f64| Label {
            text: text.into(),
            z,
            y,
            side,
            color: BLACK,
        };
        let labels = vec![
            label("disk generator", 3.2, -4.6, -1.0),
            label("disk runner", 17.2, -2.6, -1.0),
            label("bearing generator_guide", 4.8, -1.8, -1.0),
            label("bearing turbine_guide", 14.8, -1.8, -1.0),
            label("probe pickup_1", 4.0, 2.6, 1.0),
            label("probe pickup_2", 8.8, 2.6, 1.0),
        ];
        let placed = place_labels(&labels, &obstacles, bounds, (0.13, 0.4));
        for (k, a) in placed.iter().enumerate() {
            assert!(a.inside(&bounds), "{k}: {a:?}");
            assert!(!obstacles.iter().any(|o| a.overlaps(o)), "{k}: {a:?}");
            for b in &placed[..k] {
                assert!(!a.overlaps(b), "{k}: {a:?} / {b:?}");
            }
        }
        // The runner's label, centred on z = 17.2, would end at 17.915, past
        // the right edge at 17.9: it is moved left to end inside.
        assert!(placed[1].z.1 <= 17.9 && placed[1].z.0 < 17.2 - 0.5 * 0.13 * 11.0);
    }
}
