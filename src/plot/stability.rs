//! Stability figure: the least stable forward mode's logarithmic decrement against
//! the added cross-coupled stiffness.

use std::path::Path;

use plotters::prelude::*;

use crate::analysis::stability::Stability;

use super::{PlotError, failed};

/// Log decrement of the least stable forward mode against `Q` (N/m), the zero line
/// and the threshold `Q` circled.
pub fn stability_png(path: &Path, title: &str, result: &Stability) -> Result<(), PlotError> {
    let root = BitMapBackend::new(path, (1000, 650)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| failed(path, e))?;
    let q_max = result.curve.last().map_or(1.0, |c| c.0).max(1e-9);
    let (lo, hi) = result
        .curve
        .iter()
        .map(|(_, m)| m.log_decrement)
        .fold((0.0f64, 0.0f64), |(a, b), d| (a.min(d), b.max(d)));
    let pad = 0.08 * (hi - lo).max(1e-6);
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 24))
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(70)
        .build_cartesian_2d(0.0..q_max, (lo - pad)..(hi + pad))
        .map_err(|e| failed(path, e))?;
    chart
        .configure_mesh()
        .x_desc("cross-coupled stiffness Q at mid-span (N/m)")
        .y_desc("log decrement of the least stable forward mode")
        .x_label_formatter(&|v| format!("{v:.3e}"))
        .label_style(("sans-serif", 15))
        .draw()
        .map_err(|e| failed(path, e))?;
    chart
        .draw_series(LineSeries::new(
            [(0.0, 0.0), (q_max, 0.0)],
            BLACK.stroke_width(1),
        ))
        .map_err(|e| failed(path, e))?;
    chart
        .draw_series(LineSeries::new(
            result.curve.iter().map(|(q, m)| (*q, m.log_decrement)),
            RGBColor(200, 30, 30).stroke_width(2),
        ))
        .map_err(|e| failed(path, e))?;
    if let Some(q) = result.threshold {
        chart
            .draw_series([EmptyElement::at((q, 0.0))
                + Circle::new((0, 0), 8, BLACK.stroke_width(2))
                + Text::new(
                    format!("threshold {q:.4e} N/m"),
                    (10, -24),
                    ("sans-serif", 16),
                )])
            .map_err(|e| failed(path, e))?;
    }
    root.present().map_err(|e| failed(path, e))?;
    Ok(())
}
