//! Figures of a transient run: orbits (with the clearance circle, the
//! keyphasor marks and the whirl direction), the full spectrum and the
//! waterfall (against speed for a run-up or coast-down, against time when the
//! speed is constant or turns back, as a start–stop run does).

use std::path::Path;

use plotters::prelude::*;

use crate::analysis::modal::Whirl;
use crate::analysis::orbit::{keyphasor, whirl};
use crate::units::Amplitude;

use super::legend::{LEGEND_WIDTH, Swatch, draw_legend};
use super::{PlotError, SERIES_COLORS, failed, whirl_color};

/// One orbit panel: name, `x`, `y` (m) per record, and the radial clearance
/// (m) of a bearing journal.
#[derive(Debug, Clone, PartialEq)]
pub struct OrbitPanel {
    /// `bearing NAME` or `probe NAME`.
    pub name: String,
    /// x (m) per record.
    pub x: Vec<f64>,
    /// y (m) per record.
    pub y: Vec<f64>,
    /// Radial clearance (m) of a bearing: the panel is centred on the
    /// bearing and shows the clearance circle.
    pub clearance: Option<f64>,
}

/// The half-width (µm) and centre of a panel: a bearing's clearance circle
/// (×1.1) about its centre, else the orbit's extent (×1.15) about its mean.
pub fn panel_axes(panel: &OrbitPanel) -> ((f64, f64), f64) {
    let um = |v: &f64| v * 1e6;
    if let Some(c) = panel.clearance {
        let reach = panel
            .x
            .iter()
            .zip(&panel.y)
            .map(|(a, b)| a.hypot(*b) * 1e6)
            .fold(c * 1e6, f64::max);
        return ((0.0, 0.0), 1.1 * reach);
    }
    let mean = |v: &[f64]| v.iter().map(um).sum::<f64>() / v.len().max(1) as f64;
    let (cx, cy) = (mean(&panel.x), mean(&panel.y));
    let half = panel
        .x
        .iter()
        .map(|v| (um(v) - cx).abs())
        .chain(panel.y.iter().map(|v| (um(v) - cy).abs()))
        .fold(0.0f64, f64::max);
    ((cx, cy), (half * 1.15).max(1e-3))
}

/// Orbits in µm, one panel each on equal axes: bearing journals inside their
/// clearance circle, the once-per-revolution samples of `spin_angle` (rad) as
/// black dots (the keyphasor), an arrow in the direction of motion, and the
/// whirl relative to the spin of sign `speed` in each panel's caption.
pub fn orbits_png(
    path: &Path,
    title: &str,
    panels: &[OrbitPanel],
    spin_angle: &[f64],
    speed: f64,
) -> Result<(), PlotError> {
    let count = panels.len().max(1);
    let cols = count.min(3);
    let rows = count.div_ceil(cols);
    let root =
        BitMapBackend::new(path, (480 * cols as u32, 520 * rows as u32 + 80)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| failed(path, e))?;
    let root = root
        .titled(
            &format!("{title}; dots: once per revolution (keyphasor), arrow: direction of motion"),
            ("sans-serif", 20),
        )
        .map_err(|e| failed(path, e))?;
    let marks = keyphasor(spin_angle);
    for (k, (area, p)) in root
        .split_evenly((rows, cols))
        .iter()
        .zip(panels)
        .enumerate()
    {
        let ((cx, cy), r) = panel_axes(p);
        let direction = whirl(&p.x, &p.y, speed);
        let caption = match (p.clearance, direction) {
            (Some(c), Whirl::Mixed) => format!("{}: clearance {:.0} µm", p.name, c * 1e6),
            (Some(c), w) => format!(
                "{}: {} whirl, clearance {:.0} µm",
                p.name,
                w.label(),
                c * 1e6
            ),
            (None, Whirl::Mixed) => p.name.clone(),
            (None, w) => format!("{}: {} whirl", p.name, w.label()),
        };
        let mut chart = ChartBuilder::on(area)
            .caption(caption, ("sans-serif", 17))
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
        if let Some(c) = p.clearance {
            let circle: Vec<(f64, f64)> = (0..=360)
                .map(|i| {
                    let a = (i as f64).to_radians();
                    (c * 1e6 * a.cos(), c * 1e6 * a.sin())
                })
                .collect();
            chart
                .draw_series(LineSeries::new(circle, BLACK.stroke_width(2)))
                .map_err(|e| failed(path, e))?;
        }
        let color = SERIES_COLORS[k % SERIES_COLORS.len()];
        let points: Vec<(f64, f64)> =
            p.x.iter()
                .zip(&p.y)
                .map(|(a, b)| (a * 1e6, b * 1e6))
                .collect();
        chart
            .draw_series(LineSeries::new(
                points.iter().copied(),
                color.stroke_width(1),
            ))
            .map_err(|e| failed(path, e))?;
        chart
            .draw_series(
                marks
                    .iter()
                    .filter_map(|&i| points.get(i))
                    .map(|q| Circle::new(*q, 3, BLACK.filled())),
            )
            .map_err(|e| failed(path, e))?;
        // The arrow: along the motion at the last keyphasor mark (else the end).
        let at = marks
            .last()
            .copied()
            .filter(|&i| i + 1 < points.len())
            .unwrap_or(points.len().saturating_sub(2));
        if points.len() >= 2 {
            let (a, b) = (points[at], points[at + 1]);
            let (dx, dy) = (b.0 - a.0, b.1 - a.1);
            let len = dx.hypot(dy);
            if len > 0.0 {
                let s = 0.12 * r / len;
                let tip = (a.0 + dx * s, a.1 + dy * s);
                let back = |turn: f64| {
                    let (c, sn) = (turn.cos(), turn.sin());
                    let (ux, uy) = (-dx * s * 0.4, -dy * s * 0.4);
                    (tip.0 + c * ux - sn * uy, tip.1 + sn * ux + c * uy)
                };
                let arrow = whirl_color(direction);
                chart
                    .draw_series([
                        PathElement::new([a, tip], arrow.stroke_width(3)),
                        PathElement::new([back(0.5), tip, back(-0.5)], arrow.stroke_width(3)),
                    ])
                    .map_err(|e| failed(path, e))?;
            }
        }
    }
    root.present().map_err(|e| failed(path, e))?;
    Ok(())
}

/// Full spectra `(name, amplitude m)` over `freqs` (Hz, signed), in µm of
/// `amplitude`, with vertical markers at the given `(label, frequency)`; the
/// legend beside the chart.
pub fn spectrum_png(
    path: &Path,
    title: &str,
    freqs: &[f64],
    spectra: &[(String, Vec<f64>)],
    markers: &[(String, f64)],
    amplitude: Amplitude,
) -> Result<(), PlotError> {
    let root = BitMapBackend::new(path, (1100 + LEGEND_WIDTH, 620)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| failed(path, e))?;
    let root = root
        .titled(title, ("sans-serif", 24))
        .map_err(|e| failed(path, e))?;
    let (plot, side) = root.split_horizontally(1100);
    let f0 = freqs.first().copied().unwrap_or(0.0);
    let f1 = freqs.last().copied().unwrap_or(1.0);
    let factor = 1e6 * amplitude.factor();
    let top = spectra
        .iter()
        .flat_map(|(_, a)| a.iter())
        .fold(0.0f64, |a, v| a.max(*v))
        * factor
        * 1.12;
    let mut chart = ChartBuilder::on(&plot)
        .margin(16)
        .x_label_area_size(44)
        .y_label_area_size(64)
        .build_cartesian_2d(f0..f1, 0.0..top.max(1e-9))
        .map_err(|e| failed(path, e))?;
    chart
        .configure_mesh()
        .x_desc("frequency (Hz), positive = forward whirl")
        .y_desc(format!("amplitude (µm {})", amplitude.label()))
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
    let mut legend = Vec::new();
    for (k, (name, amps)) in spectra.iter().enumerate() {
        let color = SERIES_COLORS[k % SERIES_COLORS.len()];
        chart
            .draw_series(LineSeries::new(
                freqs.iter().zip(amps).map(|(f, a)| (*f, a * factor)),
                color.stroke_width(2),
            ))
            .map_err(|e| failed(path, e))?;
        legend.push((Swatch::Line(color, 2), name.clone()));
    }
    legend.push((
        Swatch::Line(RGBColor(153, 153, 153), 1),
        "orders of the mean running speed".into(),
    ));
    draw_legend(&side, path, None, &legend)?;
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

/// One waterfall row: the window's mid time (s), mean speed (rpm) and its
/// full spectrum (m) on the waterfall's frequency grid.
#[derive(Debug, Clone, PartialEq)]
pub struct WaterfallTrace {
    /// Mid time of the window (s).
    pub time: f64,
    /// Mean speed of the window (rpm).
    pub rpm: f64,
    /// Amplitudes (m).
    pub amplitudes: Vec<f64>,
}

/// Whether a waterfall's traces go against speed: when the speed runs one
/// way (strictly up or strictly down from window to window) over at least 5 %
/// of its largest value. A constant speed or one that turns back (a start–
/// stop run) is drawn against time instead.
pub fn against_speed(traces: &[WaterfallTrace]) -> bool {
    let rpm: Vec<f64> = traces.iter().map(|t| t.rpm).collect();
    let (lo, hi) = rpm
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(*v), b.max(*v))
        });
    let span = hi - lo;
    let up = rpm.windows(2).all(|w| w[1] > w[0]);
    let down = rpm.windows(2).all(|w| w[1] < w[0]);
    rpm.len() >= 2 && (up || down) && span >= 0.05 * hi.abs().max(lo.abs())
}

/// Waterfall: one full spectrum per window, each drawn at its speed (rpm) or
/// time (s) — see [`against_speed`] — with its height proportional to
/// amplitude; a scale bar ([`scale_bar`]) of amplitude `amplitude`, and the
/// 1× and 0.5× orders of each window's speed drawn through the traces, the
/// legend beside the chart.
pub fn waterfall_png(
    path: &Path,
    title: &str,
    freqs: &[f64],
    traces: &[WaterfallTrace],
    amplitude: Amplitude,
) -> Result<(), PlotError> {
    let root = BitMapBackend::new(path, (1100 + LEGEND_WIDTH, 820)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| failed(path, e))?;
    let root = root
        .titled(title, ("sans-serif", 24))
        .map_err(|e| failed(path, e))?;
    let (plot, side) = root.split_horizontally(1100);
    let (f0, f1) = (freqs[0], freqs[freqs.len() - 1]);
    let by_speed = against_speed(traces);
    let level = |t: &WaterfallTrace| if by_speed { t.rpm } else { t.time };
    let lo = traces.iter().map(level).fold(f64::INFINITY, f64::min);
    let hi = traces.iter().map(level).fold(f64::NEG_INFINITY, f64::max);
    let spacing = ((hi - lo) / traces.len().max(1) as f64).max(1e-9);
    let peak = traces
        .iter()
        .flat_map(|r| r.amplitudes.iter())
        .fold(0.0f64, |a, v| a.max(*v))
        .max(f64::MIN_POSITIVE);
    let scale = 4.0 * spacing / peak;
    let (bar, bar_label) = scale_bar(peak * amplitude.factor());
    let bar_label = format!("{bar_label} {}", amplitude.label());
    let (y0, y1) = if hi > lo {
        (lo - spacing, hi + 5.0 * spacing)
    } else {
        (lo - 1.0, lo + 5.0)
    };
    let mut chart = ChartBuilder::on(&plot)
        .margin(16)
        .x_label_area_size(44)
        .y_label_area_size(70)
        .build_cartesian_2d(f0..f1, y0..y1)
        .map_err(|e| failed(path, e))?;
    let axis = if by_speed {
        "spin speed (rpm)"
    } else {
        "time (s), window middle"
    };
    chart
        .configure_mesh()
        .x_desc("frequency (Hz), positive = forward whirl")
        .y_desc(format!("{axis}; trace height = amplitude"))
        .label_style(("sans-serif", 16))
        .draw()
        .map_err(|e| failed(path, e))?;
    let bar_x = f1 - 0.06 * (f1 - f0);
    let bar_y = hi + 0.5 * spacing;
    let bar_len = bar / amplitude.factor() * scale;
    chart
        .draw_series(LineSeries::new(
            [(bar_x, bar_y), (bar_x, bar_y + bar_len)],
            BLACK.stroke_width(4),
        ))
        .map_err(|e| failed(path, e))?;
    let mut legend = vec![(Swatch::Line(BLACK, 4), format!("scale bar: {bar_label}"))];
    for (order, color) in [(1.0, RGBColor(200, 30, 30)), (0.5, RGBColor(30, 60, 200))] {
        // The order line through every window's speed, at the trace's level.
        let line: Vec<(f64, f64)> = traces
            .iter()
            .map(|t| (order * t.rpm / 60.0, level(t)))
            .collect();
        chart
            .draw_series(LineSeries::new(line, color.mix(0.6).stroke_width(2)))
            .map_err(|e| failed(path, e))?;
        legend.push((Swatch::Line(color, 2), format!("{order}× running speed")));
    }
    for t in traces {
        chart
            .draw_series(LineSeries::new(
                freqs
                    .iter()
                    .zip(&t.amplitudes)
                    .map(|(f, a)| (*f, level(t) + a * scale)),
                BLACK.stroke_width(1),
            ))
            .map_err(|e| failed(path, e))?;
    }
    if !by_speed {
        let (s_lo, s_hi) = traces
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), t| {
                (a.min(t.rpm), b.max(t.rpm))
            });
        legend.push((
            Swatch::Band(WHITE),
            if s_hi - s_lo < 0.05 * s_hi.abs().max(1.0) {
                format!("constant speed {:.0} rpm", 0.5 * (s_lo + s_hi))
            } else {
                format!(
                    "speed {:.0} … {:.0} rpm (not one way: against time)",
                    s_lo, s_hi
                )
            },
        ));
    }
    draw_legend(&side, path, None, &legend)?;
    root.present().map_err(|e| failed(path, e))?;
    Ok(())
}

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

    fn traces(rpm: &[f64]) -> Vec<WaterfallTrace> {
        rpm.iter()
            .enumerate()
            .map(|(k, &r)| WaterfallTrace {
                time: k as f64,
                rpm: r,
                amplitudes: vec![],
            })
            .collect()
    }

    #[test]
    fn waterfalls_go_against_speed_only_one_way() {
        assert!(against_speed(&traces(&[1000.0, 2000.0, 3000.0])));
        assert!(against_speed(&traces(&[3000.0, 2000.0, 1000.0])));
        // Constant (299.8 … 301.2 rpm) and start–stop: against time.
        assert!(!against_speed(&traces(&[299.8, 300.4, 301.2])));
        assert!(!against_speed(&traces(&[0.0, 1500.0, 3000.0, 1500.0, 0.0])));
    }

    #[test]
    fn bearing_panels_show_the_clearance_circle() {
        let mut p = OrbitPanel {
            name: "bearing b".into(),
            x: vec![10e-6, 20e-6],
            y: vec![-30e-6, -25e-6],
            clearance: Some(100e-6),
        };
        let ((cx, cy), r) = panel_axes(&p);
        assert_eq!((cx, cy), (0.0, 0.0));
        assert!((r - 110.0).abs() < 1e-9, "{r}");
        // A journal beyond its clearance (in contact) stays in view.
        p.x[1] = 150e-6;
        assert!(panel_axes(&p).1 > 150.0 * 1.09);
        // A probe: centred on its orbit's mean.
        p.clearance = None;
        let ((cx, _), _) = panel_axes(&p);
        assert!((cx - 80.0).abs() < 1e-9);
    }
}
