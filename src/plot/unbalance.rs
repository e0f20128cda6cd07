//! Unbalance response figure: Bode diagram (amplitude and phase against speed)
//! and polar plot of every response point, with the peaks numbered and listed
//! in a legend panel of their own.

use std::path::Path;

use plotters::prelude::*;

use crate::analysis::unbalance::{UnbalanceStudy, major_semi_axis, unwrapped_phase};
use crate::units::Amplitude;

use super::legend::{Swatch, draw_legend};
use super::{PlotError, RAD_S_TO_RPM, SERIES_COLORS, failed};

/// The amplitude axis of a Bode plot: linear from 0, or logarithmic when a
/// peak is an undamped resonance (its amplitude only the grid's closeness to
/// the singular speed) — then topped at 10⁴ × the median amplitude, six
/// decades deep. Returns `(low, high, logarithmic)` in the plotted unit.
pub fn amplitude_axis(values: &[f64], undamped: bool) -> (f64, f64, bool) {
    let largest = values.iter().copied().fold(0.0, f64::max).max(1e-12);
    if !undamped {
        return (0.0, 1.1 * largest, false);
    }
    let mut positive: Vec<f64> = values.iter().copied().filter(|v| *v > 0.0).collect();
    positive.sort_by(f64::total_cmp);
    let median = positive.get(positive.len() / 2).copied().unwrap_or(largest);
    let high = largest.min(1e4 * median) * 1.5;
    (high * 1e-6, high, true)
}

/// A number for a legend: AF and amplitudes to three significant digits.
fn three(v: f64) -> String {
    if v >= 100.0 {
        format!("{v:.0}")
    } else if v >= 10.0 {
        format!("{v:.1}")
    } else {
        format!("{v:.2}")
    }
}

/// Legend text of peak `k` of `study`.
pub fn peak_label(k: usize, study: &UnbalanceStudy, amplitude: Amplitude) -> String {
    let (peak, margin) = &study.rows[k];
    let point = &study.sweep.points[peak.point].label;
    let mut s = format!("{}: {point}, {:.0} rpm, ", k + 1, peak.speed * RAD_S_TO_RPM);
    if peak.is_undamped() {
        s.push_str("unbounded (undamped resonance)");
    } else {
        s.push_str(&format!(
            "{} µm {}",
            three(peak.amplitude * 1e6 * amplitude.factor()),
            amplitude.label()
        ));
        if let Some(af) = peak.amplification_factor {
            s.push_str(&format!(", AF {}", three(af)));
        }
    }
    if let Some(m) = margin {
        let verdict = if m.pass { "pass" } else { "FAIL" };
        s.push_str(&format!(", SM {:.1} % {verdict}", 100.0 * m.actual));
    }
    s
}

/// Bode diagram and polar plot of `study`: top left the major semi-axis of
/// every point's orbit against speed (rpm) with the peaks numbered and the
/// operating range shaded; bottom left the phase of the x response (°,
/// `x = |X| cos(Ωt + φ)`, unwrapped along speed); right the x response in
/// the complex plane, speed increasing along each curve from its dot;
/// amplitudes `amplitude` (0-pk or pk-pk) on every axis; the legend and the
/// list of peaks in a panel under the polar plot.
pub fn unbalance_png(
    path: &Path,
    title: &str,
    study: &UnbalanceStudy,
    amplitude: Amplitude,
) -> Result<(), PlotError> {
    let sweep = &study.sweep;
    let factor = amplitude.factor() * 1e6;
    let unit = format!("µm {}", amplitude.label());
    let root = BitMapBackend::new(path, (1600, 980)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| failed(path, e))?;
    let root = root
        .titled(title, ("sans-serif", 26))
        .map_err(|e| failed(path, e))?;
    let (left, right) = root.split_horizontally(960);
    let (top, bottom) = left.split_vertically(500);
    let (polar, side) = right.split_vertically(600);
    let rpm: Vec<f64> = sweep.speeds.iter().map(|s| s * RAD_S_TO_RPM).collect();
    let (s_min, s_max) = (rpm[0], rpm[rpm.len() - 1].max(rpm[0] + 1e-9));
    let color = |p: usize| SERIES_COLORS[p % SERIES_COLORS.len()];
    let band = RGBColor(120, 200, 120);
    let mut legend = Vec::new();

    let majors: Vec<Vec<f64>> = (0..sweep.points.len())
        .map(|p| sweep.major(p).iter().map(|a| a * factor).collect())
        .collect();
    let undamped = study.rows.iter().any(|(p, _)| p.is_undamped());
    let all: Vec<f64> = majors.iter().flatten().copied().collect();
    let (a_lo, a_hi, log) = amplitude_axis(&all, undamped);
    let clamp = |v: f64| v.clamp(a_lo, a_hi);
    let desc = format!("orbit major semi-axis ({unit})");
    // The chart is built twice over (linear or log axis) through one closure.
    macro_rules! bode {
        ($chart:expr) => {{
            let mut chart = $chart;
            chart
                .configure_mesh()
                .x_desc("spin speed (rpm)")
                .y_desc(desc.as_str())
                .label_style(("sans-serif", 15))
                .draw()
                .map_err(|e| failed(path, e))?;
            if let Some(r) = &study.operating {
                let (lo, hi) = (r.min * RAD_S_TO_RPM, r.max * RAD_S_TO_RPM);
                let pad = if hi > lo { 0.0 } else { 2e-3 * (s_max - s_min) };
                chart
                    .draw_series([Rectangle::new(
                        [(lo - pad, a_lo), (hi + pad, a_hi)],
                        band.mix(0.35).filled(),
                    )])
                    .map_err(|e| failed(path, e))?;
            }
            for (p, m) in majors.iter().enumerate() {
                chart
                    .draw_series(LineSeries::new(
                        rpm.iter().copied().zip(m.iter().map(|v| clamp(*v))),
                        color(p).stroke_width(2),
                    ))
                    .map_err(|e| failed(path, e))?;
            }
            for (k, (peak, _)) in study.rows.iter().enumerate() {
                let x = peak.speed * RAD_S_TO_RPM;
                let y = clamp(if peak.is_undamped() {
                    a_hi
                } else {
                    peak.amplitude * factor
                });
                let dy = if k % 2 == 0 { -24 } else { 8 };
                chart
                    .draw_series([EmptyElement::at((x, y))
                        + Circle::new((0, 0), 6, BLACK.stroke_width(2))
                        + Text::new(format!("{}", k + 1), (8, dy), ("sans-serif", 16))])
                    .map_err(|e| failed(path, e))?;
                if let (Some((n1, n2)), false) = (peak.half_power, peak.is_undamped()) {
                    let level = clamp(y / std::f64::consts::SQRT_2);
                    chart
                        .draw_series(LineSeries::new(
                            [(n1 * RAD_S_TO_RPM, level), (n2 * RAD_S_TO_RPM, level)],
                            BLACK.stroke_width(1),
                        ))
                        .map_err(|e| failed(path, e))?;
                }
            }
        }};
    }
    if log {
        bode!(
            ChartBuilder::on(&top)
                .margin(14)
                .x_label_area_size(40)
                .y_label_area_size(76)
                .build_cartesian_2d(s_min..s_max, (a_lo..a_hi).log_scale())
                .map_err(|e| failed(path, e))?
        );
    } else {
        bode!(
            ChartBuilder::on(&top)
                .margin(14)
                .x_label_area_size(40)
                .y_label_area_size(76)
                .build_cartesian_2d(s_min..s_max, a_lo..a_hi)
                .map_err(|e| failed(path, e))?
        );
    }

    // Phase, unwrapped along speed, on an axis of whole quarter turns.
    let phases: Vec<Vec<f64>> = (0..sweep.points.len())
        .map(|p| unwrapped_phase(&sweep.response.iter().map(|r| r[p].0).collect::<Vec<_>>()))
        .collect();
    let (p_lo, p_hi) = phases
        .iter()
        .flatten()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(*v), b.max(*v))
        });
    let (p_lo, p_hi) = if p_lo.is_finite() {
        (
            (p_lo / 90.0).floor() * 90.0 - 10.0,
            (p_hi / 90.0).ceil() * 90.0 + 10.0,
        )
    } else {
        (-190.0, 190.0)
    };
    let mut chart = ChartBuilder::on(&bottom)
        .margin(14)
        .x_label_area_size(40)
        .y_label_area_size(76)
        .build_cartesian_2d(s_min..s_max, p_lo..p_hi)
        .map_err(|e| failed(path, e))?;
    chart
        .configure_mesh()
        .x_desc("spin speed (rpm)")
        .y_desc("phase of x (°), unwrapped")
        .label_style(("sans-serif", 15))
        .draw()
        .map_err(|e| failed(path, e))?;
    if let Some(r) = &study.operating {
        let (lo, hi) = (r.min * RAD_S_TO_RPM, r.max * RAD_S_TO_RPM);
        let pad = if hi > lo { 0.0 } else { 2e-3 * (s_max - s_min) };
        chart
            .draw_series([Rectangle::new(
                [(lo - pad, p_lo), (hi + pad, p_hi)],
                band.mix(0.35).filled(),
            )])
            .map_err(|e| failed(path, e))?;
    }
    for (p, phase) in phases.iter().enumerate() {
        chart
            .draw_series(LineSeries::new(
                rpm.iter().copied().zip(phase.iter().copied()),
                color(p).stroke_width(2),
            ))
            .map_err(|e| failed(path, e))?;
    }

    // Polar plot of the x response, on equal axes, clipped like the Bode plot.
    let reach = sweep
        .response
        .iter()
        .flat_map(|r| {
            r.iter()
                .map(|&(x, y)| major_semi_axis((x, y)).max(x.norm()))
        })
        .map(|v| v * factor)
        .fold(0.0, f64::max)
        .min(a_hi)
        .max(1e-9)
        * 1.1;
    let mut chart = ChartBuilder::on(&polar)
        .caption(
            format!("polar plot of x ({unit}), speed rising from the dot"),
            ("sans-serif", 18),
        )
        .margin(14)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(-reach..reach, -reach..reach)
        .map_err(|e| failed(path, e))?;
    chart
        .configure_mesh()
        .x_desc(format!("Re X ({unit})"))
        .y_desc(format!("Im X ({unit})"))
        .label_style(("sans-serif", 15))
        .draw()
        .map_err(|e| failed(path, e))?;
    for p in 0..sweep.points.len() {
        let c = color(p);
        let line: Vec<(f64, f64)> = sweep
            .response
            .iter()
            .map(|r| (r[p].0.re * factor, r[p].0.im * factor))
            .collect();
        chart
            .draw_series([Circle::new(line[0], 5, c.filled())])
            .map_err(|e| failed(path, e))?;
        // Only segments inside the axes: an undamped resonance leaves them.
        let inside = |q: &(f64, f64)| q.0.abs() <= reach && q.1.abs() <= reach;
        for run in line.split(|q| !inside(q)).filter(|r| r.len() > 1) {
            chart
                .draw_series(LineSeries::new(run.iter().copied(), c.stroke_width(2)))
                .map_err(|e| failed(path, e))?;
        }
        chart
            .draw_series(
                line.iter()
                    .filter(|q| inside(q))
                    .map(|q| Circle::new(*q, 1, c.filled())),
            )
            .map_err(|e| failed(path, e))?;
    }

    for (p, point) in sweep.points.iter().enumerate() {
        legend.push((Swatch::Line(color(p), 2), point.label.clone()));
    }
    if let Some(r) = &study.operating {
        let (lo, hi) = (r.min * RAD_S_TO_RPM, r.max * RAD_S_TO_RPM);
        legend.push((
            Swatch::Band(band),
            if hi > lo {
                format!("operating range {lo:.0} … {hi:.0} rpm")
            } else {
                format!("operating speed {lo:.0} rpm")
            },
        ));
    }
    legend.push((
        Swatch::Line(BLACK, 1),
        "half-power band (AF = Nc/(N2 − N1))".into(),
    ));
    for k in 0..study.rows.len() {
        legend.push((Swatch::Ring(BLACK), peak_label(k, study, amplitude)));
    }
    if study.rows.is_empty() {
        legend.push((Swatch::Ring(WHITE), "no peak inside the speed range".into()));
    }
    draw_legend(&side, path, Some("legend and peaks"), &legend)?;
    root.present().map_err(|e| failed(path, e))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn amplitude_axis_is_linear_unless_a_resonance_is_undamped() {
        let values = [0.0, 1.0, 3.0, 10.0, 2.0];
        assert_eq!(amplitude_axis(&values, false), (0.0, 11.0, false));
        // An undamped spike of 1e9 is cut at 1.5 × 10⁴ × the median (3).
        let spiky = [0.0, 1.0, 2.0, 3.0, 1e9];
        let (lo, hi, log) = amplitude_axis(&spiky, true);
        assert!(log && (hi - 4.5e4).abs() < 1e-9 && (lo - 4.5e-2).abs() < 1e-12);
    }
}
