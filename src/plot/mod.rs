//! PNG figures (plotters, bitmap backend): Campbell diagram, coefficient curves,
//! orbits, spectra and waterfalls here; the analyst toolkit figures in submodules.

use std::path::Path;

use plotters::prelude::*;

use crate::analysis::modal::Whirl;

pub use crate::units::RAD_S_TO_RPM;

/// Plotting failure (file or font problem), with the file named.
#[derive(Debug, thiserror::Error)]
#[error("cannot draw {file}: {message}")]
pub struct PlotError {
    file: String,
    message: String,
}

fn failed(path: &Path, e: impl std::fmt::Display) -> PlotError {
    PlotError {
        file: path.display().to_string(),
        message: e.to_string(),
    }
}

/// The legend box every figure uses, at `$position`.
macro_rules! legend {
    ($chart:expr, $position:expr, $path:expr) => {
        $chart
            .configure_series_labels()
            .position($position)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 16))
            .draw()
            .map_err(|e| failed($path, e))
    };
}

pub(crate) fn whirl_color(w: Whirl) -> RGBColor {
    match w {
        Whirl::Forward => RGBColor(200, 30, 30),
        Whirl::Backward => RGBColor(30, 60, 200),
        Whirl::Mixed => RGBColor(110, 110, 110),
    }
}

/// Dimensionless bearing coefficients against eccentricity ratio (the paper's
/// Fig. 3): `K̄ = K C/W` (left) and `C̄ = C ω C/W` (right), one line per entry.
pub fn coefficients_png(
    path: &Path,
    title: &str,
    eccentricity: &[f64],
    stiffness: &[(String, Vec<f64>)],
    damping: &[(String, Vec<f64>)],
) -> Result<(), PlotError> {
    let root = BitMapBackend::new(path, (1400, 640)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| failed(path, e))?;
    let root = root
        .titled(title, ("sans-serif", 26))
        .map_err(|e| failed(path, e))?;
    let panels = root.split_evenly((1, 2));
    let colors = [
        RGBColor(200, 30, 30),
        RGBColor(30, 60, 200),
        RGBColor(20, 140, 60),
        RGBColor(150, 60, 160),
    ];
    let e_min = eccentricity.iter().copied().fold(f64::INFINITY, f64::min);
    let e_max = eccentricity.iter().copied().fold(0.0, f64::max);
    for (panel, (series, label)) in panels.iter().zip([
        (stiffness, "stiffness K C / W"),
        (damping, "damping C ω C / W"),
    ]) {
        let values = series.iter().flat_map(|(_, v)| v.iter().copied());
        let (lo, hi) = values.fold((0.0f64, 0.0f64), |(a, b), v| (a.min(v), b.max(v)));
        let pad = 0.05 * (hi - lo).max(1e-9);
        let mut chart = ChartBuilder::on(panel)
            .margin(16)
            .x_label_area_size(44)
            .y_label_area_size(64)
            .build_cartesian_2d(e_min..e_max, (lo - pad)..(hi + pad))
            .map_err(|e| failed(path, e))?;
        chart
            .configure_mesh()
            .x_desc("eccentricity ratio ε")
            .y_desc(label)
            .label_style(("sans-serif", 16))
            .draw()
            .map_err(|e| failed(path, e))?;
        for (k, (name, v)) in series.iter().enumerate() {
            let color = colors[k % colors.len()];
            chart
                .draw_series(LineSeries::new(
                    eccentricity.iter().copied().zip(v.iter().copied()),
                    color.stroke_width(2),
                ))
                .map_err(|e| failed(path, e))?
                .label(name.clone())
                .legend(move |(x, y)| {
                    PathElement::new([(x, y), (x + 20, y)], color.stroke_width(2))
                });
        }
        legend!(chart, SeriesLabelPosition::UpperLeft, path)?;
    }
    root.present().map_err(|e| failed(path, e))?;
    Ok(())
}

const SERIES_COLORS: [RGBColor; 6] = [
    RGBColor(200, 30, 30),
    RGBColor(30, 60, 200),
    RGBColor(20, 140, 60),
    RGBColor(150, 60, 160),
    RGBColor(220, 130, 20),
    RGBColor(20, 150, 170),
];

mod campbell;
mod drawing;
pub mod legend;
mod shapes;
mod stability;
mod transient;
mod ucs;
mod unbalance;

pub use campbell::{campbell_png, critical_label};
pub use drawing::{radial_exaggeration, rotor_png};
pub use shapes::mode_shapes_png;
pub use stability::stability_png;
pub use transient::{
    OrbitPanel, WaterfallTrace, against_speed, orbits_png, panel_axes, scale_bar, spectrum_png,
    waterfall_png,
};
pub use ucs::ucs_png;
pub use unbalance::unbalance_png;
