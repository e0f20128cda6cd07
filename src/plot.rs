//! PNG figures (plotters, bitmap backend): the Campbell diagram.

use std::path::Path;

use plotters::prelude::*;

use crate::analysis::campbell::{CampbellPoint, CriticalSpeed};
use crate::analysis::modal::Whirl;

/// rad/s → rpm.
pub const RAD_S_TO_RPM: f64 = 60.0 / (2.0 * std::f64::consts::PI);

/// Plotting failure (file or font problem), with the file named.
#[derive(Debug, thiserror::Error)]
#[error("cannot draw {file}: {message}")]
pub struct PlotError {
    file: String,
    message: String,
}

fn whirl_color(w: Whirl) -> RGBColor {
    match w {
        Whirl::Forward => RGBColor(200, 30, 30),
        Whirl::Backward => RGBColor(30, 60, 200),
        Whirl::Mixed => RGBColor(110, 110, 110),
    }
}

/// Campbell diagram: damped natural frequencies (Hz) against speed (rpm), markers
/// coloured by whirl (red forward, blue backward, grey mixed), the excitation
/// lines `ω = h Ω` for `harmonics`, and the critical speeds circled.
pub fn campbell_png(
    path: &Path,
    title: &str,
    diagram: &[CampbellPoint],
    harmonics: &[f64],
    criticals: &[CriticalSpeed],
) -> Result<(), PlotError> {
    let err = |e: &dyn std::fmt::Display| PlotError {
        file: path.display().to_string(),
        message: e.to_string(),
    };
    let hz = 1.0 / (2.0 * std::f64::consts::PI);
    let s_max = diagram
        .iter()
        .map(|p| p.speed)
        .fold(0.0, f64::max)
        .max(1e-9)
        * RAD_S_TO_RPM;
    let s_min = diagram
        .iter()
        .map(|p| p.speed)
        .fold(f64::INFINITY, f64::min)
        .min(s_max)
        * RAD_S_TO_RPM;
    let f_max = diagram
        .iter()
        .flat_map(|p| p.modes.iter().map(|m| m.damped_frequency * hz))
        .fold(0.0, f64::max)
        .max(1e-9)
        * 1.08;

    let root = BitMapBackend::new(path, (1100, 760)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 26))
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(70)
        .build_cartesian_2d(s_min..s_max, 0.0..f_max)
        .map_err(|e| err(&e))?;
    chart
        .configure_mesh()
        .x_desc("spin speed (rpm)")
        .y_desc("damped natural frequency (Hz)")
        .label_style(("sans-serif", 16))
        .x_label_formatter(&|v| format!("{v:.0}"))
        .y_label_formatter(&|v| format!("{v:.0}"))
        .draw()
        .map_err(|e| err(&e))?;

    let ranks = diagram.iter().map(|p| p.modes.len()).min().unwrap_or(0);
    for rank in 0..ranks {
        let line: Vec<(f64, f64)> = diagram
            .iter()
            .map(|p| (p.speed * RAD_S_TO_RPM, p.modes[rank].damped_frequency * hz))
            .collect();
        chart
            .draw_series(LineSeries::new(
                line,
                RGBColor(180, 180, 180).stroke_width(1),
            ))
            .map_err(|e| err(&e))?;
        chart
            .draw_series(diagram.iter().map(|p| {
                let m = &p.modes[rank];
                Circle::new(
                    (p.speed * RAD_S_TO_RPM, m.damped_frequency * hz),
                    3,
                    whirl_color(m.whirl).filled(),
                )
            }))
            .map_err(|e| err(&e))?;
    }
    for &h in harmonics {
        chart
            .draw_series(LineSeries::new(
                [(s_min, h * s_min / 60.0), (s_max, h * s_max / 60.0)],
                BLACK.stroke_width(2),
            ))
            .map_err(|e| err(&e))?
            .label(format!("{h}× excitation"))
            .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], BLACK.stroke_width(2)));
    }
    chart
        .draw_series(criticals.iter().map(|c| {
            Circle::new(
                (c.speed * RAD_S_TO_RPM, c.harmonic * c.speed * hz),
                8,
                BLACK.stroke_width(2),
            )
        }))
        .map_err(|e| err(&e))?
        .label("critical speed")
        .legend(|(x, y)| Circle::new((x + 10, y), 6, BLACK.stroke_width(2)));
    for (w, name) in [
        (Whirl::Forward, "forward whirl"),
        (Whirl::Backward, "backward whirl"),
        (Whirl::Mixed, "mixed / planar"),
    ] {
        chart
            .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())
            .map_err(|e| err(&e))?
            .label(name)
            .legend(move |(x, y)| Circle::new((x + 10, y), 4, whirl_color(w).filled()));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 16))
        .draw()
        .map_err(|e| err(&e))?;
    root.present().map_err(|e| err(&e))?;
    Ok(())
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
    let err = |e: &dyn std::fmt::Display| PlotError {
        file: path.display().to_string(),
        message: e.to_string(),
    };
    let root = BitMapBackend::new(path, (1400, 640)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let root = root
        .titled(title, ("sans-serif", 26))
        .map_err(|e| err(&e))?;
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
            .map_err(|e| err(&e))?;
        chart
            .configure_mesh()
            .x_desc("eccentricity ratio ε")
            .y_desc(label)
            .label_style(("sans-serif", 16))
            .draw()
            .map_err(|e| err(&e))?;
        for (k, (name, v)) in series.iter().enumerate() {
            let color = colors[k % colors.len()];
            chart
                .draw_series(LineSeries::new(
                    eccentricity.iter().copied().zip(v.iter().copied()),
                    color.stroke_width(2),
                ))
                .map_err(|e| err(&e))?
                .label(name.clone())
                .legend(move |(x, y)| {
                    PathElement::new([(x, y), (x + 20, y)], color.stroke_width(2))
                });
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperLeft)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 16))
            .draw()
            .map_err(|e| err(&e))?;
    }
    root.present().map_err(|e| err(&e))?;
    Ok(())
}
