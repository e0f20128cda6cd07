//! Mode shape figure: each mode's orbit ellipses along the shaft in an oblique
//! 3-D view, with the bearings and disks of the model.

use std::path::Path;

use plotters::prelude::*;

use crate::analysis::modal::Mode;
use crate::analysis::shapes::node_orbits;
use crate::model::RotorModel;

use super::{PlotError, failed};

/// Oblique projection: the x displacement is drawn into the page at this slope
/// (screen y per unit x) and with this axial shift (fraction of the shaft length
/// per unit x).
const DEPTH_Y: f64 = 0.3;
const DEPTH_Z: f64 = 0.06;

/// One panel per mode (at most 8, two columns): the shaft axis along z (m),
/// every node's orbit ellipse of the normalized shape (largest translation 1)
/// in an oblique view (y up, x into the page), red where the node whirls
/// forward, blue backward, grey on a straight line; the shape at `t = 0` in
/// black; bearings as triangles under the axis, disks as grey bars.
pub fn mode_shapes_png(
    path: &Path,
    title: &str,
    model: &RotorModel,
    modes: &[Mode],
) -> Result<(), PlotError> {
    let shown = &modes[..modes.len().min(8)];
    let cols = if shown.len() > 1 { 2 } else { 1 };
    let rows = shown.len().div_ceil(cols).max(1);
    let root =
        BitMapBackend::new(path, (720 * cols as u32, 380 * rows as u32 + 60)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| failed(path, e))?;
    let root = root
        .titled(title, ("sans-serif", 24))
        .map_err(|e| failed(path, e))?;
    let z0 = model.node_z[0];
    let z1 = model.node_z[model.node_count() - 1];
    let length = (z1 - z0).max(1e-9);
    let shift = DEPTH_Z * length;
    let project = |z: f64, x: f64, y: f64| (z + shift * x, y + DEPTH_Y * x);
    for (k, (panel, mode)) in root
        .split_evenly((rows, cols))
        .iter()
        .zip(shown)
        .enumerate()
    {
        let caption = format!(
            "mode {}: {:.2} Hz, {} whirl, log dec {:.4}",
            k + 1,
            mode.damped_frequency / std::f64::consts::TAU,
            mode.whirl.label(),
            mode.log_decrement
        );
        let mut chart = ChartBuilder::on(panel)
            .caption(caption, ("sans-serif", 18))
            .margin(10)
            .x_label_area_size(36)
            .y_label_area_size(48)
            .build_cartesian_2d((z0 - 0.1 * length)..(z1 + 0.1 * length), -1.5..1.5)
            .map_err(|e| failed(path, e))?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("z (m)")
            .y_desc("y (normalized)")
            .label_style(("sans-serif", 13))
            .draw()
            .map_err(|e| failed(path, e))?;
        let grey = RGBColor(150, 150, 150);
        chart
            .draw_series(LineSeries::new(
                [(z0, 0.0), (z1, 0.0)],
                grey.stroke_width(1),
            ))
            .map_err(|e| failed(path, e))?;
        // The x direction, drawn into the page at the left end.
        chart
            .draw_series(LineSeries::new(
                [
                    project(z0 - 0.06 * length, 0.0, 0.0),
                    project(z0 - 0.06 * length, 1.0, 0.0),
                ],
                BLACK.stroke_width(1),
            ))
            .map_err(|e| failed(path, e))?;
        chart
            .draw_series([Text::new(
                "x",
                project(z0 - 0.06 * length, 1.1, 0.05),
                ("sans-serif", 14),
            )])
            .map_err(|e| failed(path, e))?;
        for d in &model.disks {
            let z = model.node_z[d.node];
            chart
                .draw_series([Rectangle::new(
                    [(z - 0.006 * length, -0.45), (z + 0.006 * length, 0.45)],
                    RGBColor(170, 170, 170).filled(),
                )])
                .map_err(|e| failed(path, e))?;
        }
        for b in &model.bearings {
            let z = model.node_z[b.node];
            chart
                .draw_series([TriangleMarker::new((z, -1.3), 9, BLACK.filled())])
                .map_err(|e| failed(path, e))?;
        }
        let orbits = node_orbits(model, mode);
        for o in &orbits {
            let color = match o.direction() {
                "forward" => RGBColor(200, 30, 30),
                "backward" => RGBColor(30, 60, 200),
                _ => grey,
            };
            let ellipse: Vec<(f64, f64)> = (0..=64)
                .map(|i| {
                    let e =
                        nalgebra::Complex::from_polar(1.0, i as f64 * std::f64::consts::TAU / 64.0);
                    project(o.z, (o.x * e).re, (o.y * e).re)
                })
                .collect();
            chart
                .draw_series(LineSeries::new(ellipse, color.stroke_width(2)))
                .map_err(|e| failed(path, e))?;
        }
        let line: Vec<(f64, f64)> = orbits
            .iter()
            .map(|o| project(o.z, o.x.re, o.y.re))
            .collect();
        chart
            .draw_series(LineSeries::new(line.clone(), BLACK.stroke_width(2)))
            .map_err(|e| failed(path, e))?;
        chart
            .draw_series(line.into_iter().map(|p| Circle::new(p, 3, BLACK.filled())))
            .map_err(|e| failed(path, e))?;
    }
    root.present().map_err(|e| failed(path, e))?;
    Ok(())
}
