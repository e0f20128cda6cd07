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

/// Orbits `(name, x, y)` in µm, one panel each, on equal axes.
pub fn orbits_png(
    path: &Path,
    title: &str,
    orbits: &[(String, Vec<f64>, Vec<f64>)],
    clearance: Option<f64>,
) -> Result<(), PlotError> {
    let count = orbits.len().max(1);
    let cols = count.min(3);
    let rows = count.div_ceil(cols);
    let root =
        BitMapBackend::new(path, (460 * cols as u32, 500 * rows as u32 + 50)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| failed(path, e))?;
    let root = root
        .titled(title, ("sans-serif", 24))
        .map_err(|e| failed(path, e))?;
    let panels = root.split_evenly((rows, cols));
    for (k, (panel, (name, x, y))) in panels.iter().zip(orbits).enumerate() {
        // Equal axes centred on the orbit's mean position.
        let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len().max(1) as f64 * 1e6;
        let (cx, cy) = (mean(x), mean(y));
        let half = x
            .iter()
            .map(|v| (v * 1e6 - cx).abs())
            .chain(y.iter().map(|v| (v * 1e6 - cy).abs()))
            .fold(0.0f64, f64::max);
        let r = (half * 1.15).max(1e-3);
        let mut chart = ChartBuilder::on(panel)
            .caption(name, ("sans-serif", 18))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(56)
            .build_cartesian_2d((cx - r)..(cx + r), (cy - r)..(cy + r))
            .map_err(|e| failed(path, e))?;
        chart
            .configure_mesh()
            .x_desc("x (µm)")
            .y_desc("y (µm)")
            .label_style(("sans-serif", 14))
            .draw()
            .map_err(|e| failed(path, e))?;
        let color = SERIES_COLORS[k % SERIES_COLORS.len()];
        chart
            .draw_series(LineSeries::new(
                x.iter().zip(y).map(|(a, b)| (a * 1e6, b * 1e6)),
                color.stroke_width(1),
            ))
            .map_err(|e| failed(path, e))?;
        if let Some(c) = clearance.filter(|c| c * 1e6 <= r + cx.hypot(cy)) {
            let circle: Vec<(f64, f64)> = (0..=180)
                .map(|i| {
                    let a = i as f64 * std::f64::consts::PI / 90.0;
                    (c * 1e6 * a.cos(), c * 1e6 * a.sin())
                })
                .collect();
            chart
                .draw_series(LineSeries::new(circle, BLACK.stroke_width(1)))
                .map_err(|e| failed(path, e))?;
        }
    }
    root.present().map_err(|e| failed(path, e))?;
    Ok(())
}

/// Full spectra `(name, amplitude m)` over `freqs` (Hz, signed), in µm, with
/// vertical markers at the given `(label, frequency)`.
pub fn spectrum_png(
    path: &Path,
    title: &str,
    freqs: &[f64],
    spectra: &[(String, Vec<f64>)],
    markers: &[(String, f64)],
) -> Result<(), PlotError> {
    let root = BitMapBackend::new(path, (1100, 600)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| failed(path, e))?;
    let f0 = freqs.first().copied().unwrap_or(0.0);
    let f1 = freqs.last().copied().unwrap_or(1.0);
    let top = spectra
        .iter()
        .flat_map(|(_, a)| a.iter())
        .fold(0.0f64, |a, v| a.max(*v))
        * 1e6
        * 1.1;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 24))
        .margin(16)
        .x_label_area_size(44)
        .y_label_area_size(64)
        .build_cartesian_2d(f0..f1, 0.0..top.max(1e-9))
        .map_err(|e| failed(path, e))?;
    chart
        .configure_mesh()
        .x_desc("frequency (Hz), positive = forward whirl")
        .y_desc("amplitude (µm)")
        .label_style(("sans-serif", 16))
        .draw()
        .map_err(|e| failed(path, e))?;
    for (label, f) in markers {
        chart
            .draw_series(LineSeries::new(
                [(*f, 0.0), (*f, top)],
                BLACK.mix(0.4).stroke_width(1),
            ))
            .map_err(|e| failed(path, e))?;
        chart
            .draw_series(std::iter::once(Text::new(
                label.clone(),
                (*f, top * 0.97),
                ("sans-serif", 14),
            )))
            .map_err(|e| failed(path, e))?;
    }
    for (k, (name, amps)) in spectra.iter().enumerate() {
        let color = SERIES_COLORS[k % SERIES_COLORS.len()];
        chart
            .draw_series(LineSeries::new(
                freqs.iter().zip(amps).map(|(f, a)| (*f, a * 1e6)),
                color.stroke_width(2),
            ))
            .map_err(|e| failed(path, e))?
            .label(name.clone())
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], color.stroke_width(2)));
    }
    legend!(chart, SeriesLabelPosition::UpperRight, path)?;
    root.present().map_err(|e| failed(path, e))?;
    Ok(())
}

/// Length (m) and label of the amplitude scale bar for traces whose largest
/// amplitude is `peak` (m): the largest 1, 2 or 5 × 10ᵏ µm not above it.
pub fn scale_bar(peak: f64) -> (f64, String) {
    let um = peak * 1e6;
    if !(um > 0.0 && um.is_finite()) {
        return (1e-6, "1 µm".to_string());
    }
    let k = um.log10().floor() as i32;
    let decade = 10f64.powi(k);
    let mantissa = [5.0, 2.0, 1.0]
        .into_iter()
        .find(|m| m * decade <= um * (1.0 + 1e-12))
        .unwrap_or(1.0);
    let value = mantissa * decade;
    let label = if k >= 0 {
        format!("{value:.0} µm")
    } else {
        format!("{value:.*} µm", (-k) as usize)
    };
    (value * 1e-6, label)
}

/// Waterfall: one full spectrum per row (amplitude in m, on the frequency grid
/// `freqs` in Hz), each drawn at its spin speed (rpm) with its height
/// proportional to amplitude; a scale bar ([`scale_bar`]) gives the amplitude
/// a trace height stands for, and the 1× and 0.5× lines are drawn.
pub fn waterfall_png(
    path: &Path,
    title: &str,
    freqs: &[f64],
    rows: &[(f64, Vec<f64>)],
) -> Result<(), PlotError> {
    let root = BitMapBackend::new(path, (1100, 800)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| failed(path, e))?;
    let (f0, f1) = (freqs[0], freqs[freqs.len() - 1]);
    let s_min = rows.iter().map(|r| r.0).fold(f64::INFINITY, f64::min);
    let s_max = rows.iter().map(|r| r.0).fold(0.0, f64::max);
    let spacing = (s_max - s_min).max(1.0) / rows.len().max(1) as f64;
    let peak = rows
        .iter()
        .flat_map(|r| r.1.iter())
        .fold(0.0f64, |a, v| a.max(*v))
        .max(f64::MIN_POSITIVE);
    let scale = 4.0 * spacing / peak;
    let (bar, bar_label) = scale_bar(peak);
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 24))
        .margin(16)
        .x_label_area_size(44)
        .y_label_area_size(70)
        .build_cartesian_2d(f0..f1, (s_min - spacing)..(s_max + 5.0 * spacing))
        .map_err(|e| failed(path, e))?;
    chart
        .configure_mesh()
        .x_desc("frequency (Hz), positive = forward whirl")
        .y_desc(format!(
            "spin speed (rpm); trace height = amplitude, bar = {bar_label}"
        ))
        .label_style(("sans-serif", 16))
        .draw()
        .map_err(|e| failed(path, e))?;
    let bar_x = f1 - 0.06 * (f1 - f0);
    let bar_y = s_max + 0.5 * spacing;
    chart
        .draw_series(LineSeries::new(
            [(bar_x, bar_y), (bar_x, bar_y + bar * scale)],
            BLACK.stroke_width(4),
        ))
        .map_err(|e| failed(path, e))?;
    chart
        .draw_series([Text::new(
            bar_label,
            (bar_x - 0.12 * (f1 - f0), bar_y + 0.5 * bar * scale),
            ("sans-serif", 16),
        )])
        .map_err(|e| failed(path, e))?;
    for (order, color) in [(1.0, RGBColor(200, 30, 30)), (0.5, RGBColor(30, 60, 200))] {
        chart
            .draw_series(LineSeries::new(
                [(order * s_min / 60.0, s_min), (order * s_max / 60.0, s_max)],
                color.mix(0.5).stroke_width(1),
            ))
            .map_err(|e| failed(path, e))?
            .label(format!("{order}×"))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], color.stroke_width(2)));
    }
    for (speed, amps) in rows {
        chart
            .draw_series(LineSeries::new(
                freqs.iter().zip(amps).map(|(f, a)| (*f, speed + a * scale)),
                BLACK.stroke_width(1),
            ))
            .map_err(|e| failed(path, e))?;
    }
    legend!(chart, SeriesLabelPosition::UpperLeft, path)?;
    root.present().map_err(|e| failed(path, e))?;
    Ok(())
}

mod campbell;
mod drawing;
pub mod legend;
mod shapes;
mod stability;
mod ucs;
mod unbalance;

pub use campbell::{campbell_png, critical_label};
pub use drawing::{radial_exaggeration, rotor_png};
pub use shapes::mode_shapes_png;
pub use stability::stability_png;
pub use ucs::ucs_png;
pub use unbalance::unbalance_png;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scale_bar_is_a_round_amplitude_not_above_the_peak() {
        for (peak, length, text) in [
            (18.4e-6, 10e-6, "10 µm"),
            (260.7e-6, 200e-6, "200 µm"),
            (5e-6, 5e-6, "5 µm"),
            (0.63e-6, 0.5e-6, "0.5 µm"),
            (2e-8, 2e-8, "0.02 µm"),
        ] {
            let (v, label) = scale_bar(peak);
            assert!((v - length).abs() < 1e-9 * length, "{peak}: {v}");
            assert_eq!(label, text, "{peak}");
        }
    }
}
