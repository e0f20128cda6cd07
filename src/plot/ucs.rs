//! Undamped critical speed map figure.

use std::path::Path;

use plotters::prelude::*;

use crate::analysis::ucs::CriticalSpeedMap;

use super::legend::{LEGEND_WIDTH, Swatch, draw_legend};
use super::{PlotError, RAD_S_TO_RPM, SERIES_COLORS, failed};

/// Log–log map: forward critical speeds (rpm) against the isotropic support
/// stiffness (N/m), one black line per critical; each bearing's kxx (solid)
/// and kyy (dashed) against speed in colour. Where a bearing curve crosses a
/// critical line the rotor on that bearing has that critical speed.
pub fn ucs_png(path: &Path, title: &str, map: &CriticalSpeedMap) -> Result<(), PlotError> {
    let root = BitMapBackend::new(path, (1100 + LEGEND_WIDTH, 800)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| failed(path, e))?;
    let root = root
        .titled(title, ("sans-serif", 24))
        .map_err(|e| failed(path, e))?;
    let (plot, side) = root.split_horizontally(1100);
    let mut legend = Vec::new();
    let k_min = map.stiffness.first().copied().unwrap_or(1.0);
    let k_max = map
        .stiffness
        .last()
        .copied()
        .unwrap_or(10.0)
        .max(k_min * 1.01);
    let rpm = map.speeds.iter().flatten().map(|s| s * RAD_S_TO_RPM);
    let (lo, hi) = rpm.fold((f64::INFINITY, 0.0f64), |(a, b), v| (a.min(v), b.max(v)));
    let (lo, hi) = if lo.is_finite() {
        (lo / 1.5, hi * 1.5)
    } else {
        (1.0, 10.0)
    };
    let mut chart = ChartBuilder::on(&plot)
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(80)
        .build_cartesian_2d((k_min..k_max).log_scale(), (lo..hi).log_scale())
        .map_err(|e| failed(path, e))?;
    chart
        .configure_mesh()
        .x_desc("support stiffness (N/m)")
        .y_desc("forward critical speed (rpm)")
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .y_label_formatter(&|v| format!("{v:.0}"))
        .label_style(("sans-serif", 15))
        .draw()
        .map_err(|e| failed(path, e))?;
    let count = map.speeds.iter().map(Vec::len).max().unwrap_or(0);
    for j in 0..count {
        let line: Vec<(f64, f64)> = map
            .stiffness
            .iter()
            .zip(&map.speeds)
            .filter_map(|(k, s)| s.get(j).map(|v| (*k, v * RAD_S_TO_RPM)))
            .collect();
        chart
            .draw_series(LineSeries::new(line, BLACK.stroke_width(2)))
            .map_err(|e| failed(path, e))?;
        if j == 0 {
            legend.push((
                Swatch::Line(BLACK, 2),
                "forward critical speeds".to_string(),
            ));
        }
    }
    for (i, b) in map.bearings.iter().enumerate() {
        let c = SERIES_COLORS[i % SERIES_COLORS.len()];
        let inside = |k: f64, s: f64| (k_min..=k_max).contains(&k) && (lo..=hi).contains(&s);
        let kxx: Vec<(f64, f64)> = b
            .points
            .iter()
            .map(|(s, k, _)| (*k, s * RAD_S_TO_RPM))
            .filter(|(k, s)| inside(*k, *s))
            .collect();
        let kyy: Vec<(f64, f64)> = b
            .points
            .iter()
            .map(|(s, _, k)| (*k, s * RAD_S_TO_RPM))
            .filter(|(k, s)| inside(*k, *s))
            .collect();
        chart
            .draw_series(LineSeries::new(kxx.clone(), c.stroke_width(3)))
            .map_err(|e| failed(path, e))?;
        legend.push((Swatch::LineDots(c, 3), format!("bearing {} kxx", b.name)));
        chart
            .draw_series(kxx.iter().map(|p| Circle::new(*p, 3, c.filled())))
            .map_err(|e| failed(path, e))?;
        chart
            .draw_series(DashedLineSeries::new(kyy.clone(), 8, 5, c.stroke_width(2)))
            .map_err(|e| failed(path, e))?;
        legend.push((
            Swatch::DashedTriangles(c, 2),
            format!("bearing {} kyy", b.name),
        ));
        chart
            .draw_series(kyy.iter().map(|p| TriangleMarker::new(*p, 4, c.filled())))
            .map_err(|e| failed(path, e))?;
    }
    draw_legend(&side, path, None, &legend)?;
    root.present().map_err(|e| failed(path, e))?;
    Ok(())
}
