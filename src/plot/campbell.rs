//! Campbell diagram figure: tracked branches, excitation lines, critical
//! speeds with their separation margins, the operating range and the maximum
//! (trip or runaway) speed; the legend in a panel beside the chart.

use std::path::Path;

use plotters::prelude::*;

use crate::analysis::campbell::{
    CampbellStudy, CriticalMargin, OVERDAMPED_DAMPING_RATIO, branch, branch_count,
};
use crate::analysis::modal::Whirl;

use super::legend::{LEGEND_WIDTH, Swatch, draw_legend};
use super::{PlotError, RAD_S_TO_RPM, failed, whirl_color};

/// Legend line of one critical speed: number, speed, whirl, ζ, AF, margin.
pub fn critical_label(k: usize, m: &CriticalMargin) -> String {
    let c = &m.critical;
    let mut s = format!(
        "{}: {:.0} rpm, {}, ζ {:.3}",
        k + 1,
        c.speed * RAD_S_TO_RPM,
        c.whirl.label(),
        c.damping_ratio
    );
    if let Some(sm) = &m.margin {
        let verdict = if sm.pass { "pass" } else { "FAIL" };
        match sm.required {
            Some(r) => s.push_str(&format!(
                ", SM {:.1} % (≥ {:.1} %) {verdict}",
                100.0 * sm.actual,
                100.0 * r
            )),
            None => s.push_str(&format!(", SM {:.1} % (none required)", 100.0 * sm.actual)),
        }
    }
    if let Some(d) = m.from_max_speed {
        s.push_str(&format!(", {:+.1} % from max speed", 100.0 * d));
    }
    s
}

/// Campbell diagram: damped natural frequencies (Hz) against speed (rpm), one
/// grey line per tracked branch with markers coloured by whirl (red forward,
/// blue backward, grey mixed), the excitation lines `ω = h Ω` for `harmonics`,
/// the critical speeds circled and numbered, the overdamped crossings
/// ([`is_overdamped`](crate::analysis::campbell::CriticalSpeed::is_overdamped)) as grey crosses, the operating range
/// and the model's maximum speed, the critical speeds' margins listed beside
/// the chart. Non-oscillating roots are not drawn.
pub fn campbell_png(path: &Path, title: &str, study: &CampbellStudy) -> Result<(), PlotError> {
    let diagram = &study.diagram;
    let criticals = &study.criticals;
    let harmonics = [1.0];
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

    let root = BitMapBackend::new(path, (1100 + LEGEND_WIDTH, 760)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| failed(path, e))?;
    let root = root
        .titled(title, ("sans-serif", 26))
        .map_err(|e| failed(path, e))?;
    let (plot, side) = root.split_horizontally(1100);
    let mut chart = ChartBuilder::on(&plot)
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(70)
        .build_cartesian_2d(s_min..s_max, 0.0..f_max)
        .map_err(|e| failed(path, e))?;
    chart
        .configure_mesh()
        .x_desc("spin speed (rpm)")
        .y_desc("damped natural frequency (Hz)")
        .label_style(("sans-serif", 16))
        .x_label_formatter(&|v| format!("{v:.0}"))
        .y_label_formatter(&|v| format!("{v:.0}"))
        .draw()
        .map_err(|e| failed(path, e))?;

    let mut legend = Vec::new();
    let band = RGBColor(120, 200, 120);
    if let Some(r) = &study.operating {
        let (lo, hi) = (r.min * RAD_S_TO_RPM, r.max * RAD_S_TO_RPM);
        // A single speed is drawn as a thin band, 0.4 % of the axis wide.
        let pad = if hi > lo { 0.0 } else { 2e-3 * (s_max - s_min) };
        chart
            .draw_series([Rectangle::new(
                [(lo - pad, 0.0), (hi + pad, f_max)],
                band.mix(0.35).filled(),
            )])
            .map_err(|e| failed(path, e))?;
        let text = if hi > lo {
            format!("operating range {lo:.0} … {hi:.0} rpm")
        } else {
            format!("operating speed {lo:.0} rpm")
        };
        legend.push((Swatch::Band(band), text));
    }
    let dark = RGBColor(90, 40, 20);
    if let Some(m) = study.max_speed {
        let m = m * RAD_S_TO_RPM;
        if m <= s_max {
            chart
                .draw_series(DashedLineSeries::new(
                    [(m, 0.0), (m, f_max)],
                    10,
                    6,
                    dark.stroke_width(2),
                ))
                .map_err(|e| failed(path, e))?;
        }
        legend.push((
            Swatch::Dashed(dark, 2),
            format!("maximum (trip or runaway) speed {m:.0} rpm"),
        ));
    }

    for b in 0..branch_count(diagram) {
        let points = branch(diagram, b);
        chart
            .draw_series(LineSeries::new(
                points
                    .iter()
                    .map(|(s, m)| (s * RAD_S_TO_RPM, m.damped_frequency * hz)),
                RGBColor(180, 180, 180).stroke_width(1),
            ))
            .map_err(|e| failed(path, e))?;
        chart
            .draw_series(points.iter().map(|(s, m)| {
                Circle::new(
                    (s * RAD_S_TO_RPM, m.damped_frequency * hz),
                    3,
                    whirl_color(m.whirl).filled(),
                )
            }))
            .map_err(|e| failed(path, e))?;
    }
    for &h in &harmonics {
        chart
            .draw_series(LineSeries::new(
                [(s_min, h * s_min / 60.0), (s_max, h * s_max / 60.0)],
                BLACK.stroke_width(2),
            ))
            .map_err(|e| failed(path, e))?;
        legend.push((Swatch::Line(BLACK, 2), format!("{h}× excitation")));
    }
    for (k, c) in criticals.iter().filter(|c| !c.is_overdamped()).enumerate() {
        // Numbers alternate above and below, so neighbours do not overlap.
        let dy = if k % 2 == 0 { -26 } else { 12 };
        chart
            .draw_series([
                EmptyElement::at((c.speed * RAD_S_TO_RPM, c.harmonic * c.speed * hz))
                    + Circle::new((0, 0), 8, BLACK.stroke_width(2))
                    + Text::new(format!("{}", k + 1), (6, dy), ("sans-serif", 16)),
            ])
            .map_err(|e| failed(path, e))?;
    }
    legend.push((Swatch::Ring(BLACK), "critical speed (numbered)".into()));
    let grey = RGBColor(120, 120, 120);
    let overdamped: Vec<_> = criticals.iter().filter(|c| c.is_overdamped()).collect();
    chart
        .draw_series(overdamped.iter().map(|c| {
            Cross::new(
                (c.speed * RAD_S_TO_RPM, c.harmonic * c.speed * hz),
                7,
                grey.stroke_width(2),
            )
        }))
        .map_err(|e| failed(path, e))?;
    if !overdamped.is_empty() {
        legend.push((
            Swatch::Cross(grey),
            format!("overdamped crossing (ζ ≥ {OVERDAMPED_DAMPING_RATIO}), not a critical speed"),
        ));
    }
    for (w, name) in [
        (Whirl::Forward, "forward whirl"),
        (Whirl::Backward, "backward whirl"),
        (Whirl::Mixed, "mixed / planar"),
    ] {
        legend.push((Swatch::Dot(whirl_color(w)), name.into()));
    }
    // Torsional modes: horizontal lines (the twist has no gyroscopic term).
    let torsion = RGBColor(150, 60, 170);
    for m in &study.torsional {
        let f = m.natural_frequency * hz;
        if f <= f_max {
            chart
                .draw_series(DashedLineSeries::new(
                    [(s_min, f), (s_max, f)],
                    4,
                    4,
                    torsion.stroke_width(2),
                ))
                .map_err(|e| failed(path, e))?;
        }
        let shown = if f <= f_max { "" } else { ", above the chart" };
        legend.push((
            Swatch::Dashed(torsion, 2),
            format!("torsional mode {f:.2} Hz (undamped){shown}"),
        ));
    }
    for (k, m) in study.margins.iter().enumerate() {
        legend.push((Swatch::Ring(BLACK), critical_label(k, m)));
    }
    draw_legend(&side, path, None, &legend)?;
    root.present().map_err(|e| failed(path, e))?;
    Ok(())
}
