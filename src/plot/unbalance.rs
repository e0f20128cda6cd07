//! Unbalance response figure: Bode diagram (amplitude and phase against speed)
//! and polar plot of every response point.

use std::path::Path;

use plotters::prelude::*;

use crate::analysis::unbalance::{Peak, UnbalanceSweep, major_semi_axis};

use super::{PlotError, RAD_S_TO_RPM, SERIES_COLORS, failed};

/// Bode diagram and polar plot of `sweep`: top left the major semi-axis of
/// every point's orbit (µm) against speed (rpm) with the `peaks` marked and the
/// operating range `operating` (rad/s) shaded; bottom left the phase of the x
/// response (°, `x = |X| cos(Ωt + φ)`); right the x response in the complex
/// plane (µm), speed increasing along each curve from its dot.
pub fn unbalance_png(
    path: &Path,
    title: &str,
    sweep: &UnbalanceSweep,
    peaks: &[Peak],
    operating: Option<(f64, f64)>,
) -> Result<(), PlotError> {
    let root = BitMapBackend::new(path, (1600, 900)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| failed(path, e))?;
    let root = root
        .titled(title, ("sans-serif", 26))
        .map_err(|e| failed(path, e))?;
    let (left, right) = root.split_horizontally(960);
    let (top, bottom) = left.split_vertically(480);
    let rpm: Vec<f64> = sweep.speeds.iter().map(|s| s * RAD_S_TO_RPM).collect();
    let (s_min, s_max) = (rpm[0], rpm[rpm.len() - 1]);
    let color = |p: usize| SERIES_COLORS[p % SERIES_COLORS.len()];

    let majors: Vec<Vec<f64>> = (0..sweep.points.len())
        .map(|p| sweep.major(p).iter().map(|a| a * 1e6).collect())
        .collect();
    let a_max = majors
        .iter()
        .flatten()
        .copied()
        .fold(0.0, f64::max)
        .max(1e-9)
        * 1.1;
    let mut chart = ChartBuilder::on(&top)
        .margin(14)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(s_min..s_max, 0.0..a_max)
        .map_err(|e| failed(path, e))?;
    chart
        .configure_mesh()
        .x_desc("spin speed (rpm)")
        .y_desc("orbit major semi-axis (µm)")
        .label_style(("sans-serif", 15))
        .draw()
        .map_err(|e| failed(path, e))?;
    if let Some((lo, hi)) = operating {
        let (lo, hi) = (lo * RAD_S_TO_RPM, hi * RAD_S_TO_RPM);
        let width = (hi - lo).max(1e-3 * (s_max - s_min));
        chart
            .draw_series([Rectangle::new(
                [(lo, 0.0), (lo + width, a_max)],
                RGBColor(120, 200, 120).mix(0.3).filled(),
            )])
            .map_err(|e| failed(path, e))?
            .label("operating range")
            .legend(|(x, y)| {
                Rectangle::new(
                    [(x, y - 6), (x + 20, y + 6)],
                    RGBColor(120, 200, 120).filled(),
                )
            });
    }
    for (p, m) in majors.iter().enumerate() {
        let c = color(p);
        chart
            .draw_series(LineSeries::new(
                rpm.iter().copied().zip(m.iter().copied()),
                c.stroke_width(2),
            ))
            .map_err(|e| failed(path, e))?
            .label(sweep.points[p].label.clone())
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], c.stroke_width(2)));
    }
    for peak in peaks {
        let (x, y) = (peak.speed * RAD_S_TO_RPM, peak.amplitude * 1e6);
        let text = match peak.amplification_factor {
            Some(af) => format!("{x:.0} rpm, AF {af:.1}"),
            None => format!("{x:.0} rpm"),
        };
        chart
            .draw_series([EmptyElement::at((x, y))
                + Circle::new((0, 0), 6, BLACK.stroke_width(2))
                + Text::new(text, (8, -18), ("sans-serif", 15))])
            .map_err(|e| failed(path, e))?;
        if let Some((n1, n2)) = peak.half_power {
            let level = y / std::f64::consts::SQRT_2;
            chart
                .draw_series(LineSeries::new(
                    [(n1 * RAD_S_TO_RPM, level), (n2 * RAD_S_TO_RPM, level)],
                    BLACK.stroke_width(1),
                ))
                .map_err(|e| failed(path, e))?;
        }
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 15))
        .draw()
        .map_err(|e| failed(path, e))?;

    let mut chart = ChartBuilder::on(&bottom)
        .margin(14)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(s_min..s_max, -180.0..180.0)
        .map_err(|e| failed(path, e))?;
    chart
        .configure_mesh()
        .x_desc("spin speed (rpm)")
        .y_desc("phase of x (°)")
        .label_style(("sans-serif", 15))
        .draw()
        .map_err(|e| failed(path, e))?;
    for p in 0..sweep.points.len() {
        chart
            .draw_series(PointSeries::of_element(
                rpm.iter()
                    .zip(&sweep.response)
                    .map(|(s, r)| (*s, r[p].0.arg().to_degrees())),
                2,
                color(p).filled(),
                &|c, s, st| Circle::new(c, s, st),
            ))
            .map_err(|e| failed(path, e))?;
    }

    let reach = sweep
        .response
        .iter()
        .flat_map(|r| {
            r.iter()
                .map(|&(x, y)| major_semi_axis((x, y)).max(x.norm()))
        })
        .fold(0.0, f64::max)
        .max(1e-12)
        * 1e6
        * 1.1;
    let mut chart = ChartBuilder::on(&right)
        .caption(
            "polar plot of x (speed rising from the dot)",
            ("sans-serif", 18),
        )
        .margin(14)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(-reach..reach, -reach..reach)
        .map_err(|e| failed(path, e))?;
    chart
        .configure_mesh()
        .x_desc("Re X (µm)")
        .y_desc("Im X (µm)")
        .label_style(("sans-serif", 15))
        .draw()
        .map_err(|e| failed(path, e))?;
    for p in 0..sweep.points.len() {
        let c = color(p);
        let line: Vec<(f64, f64)> = sweep
            .response
            .iter()
            .map(|r| (r[p].0.re * 1e6, r[p].0.im * 1e6))
            .collect();
        chart
            .draw_series([Circle::new(line[0], 5, c.filled())])
            .map_err(|e| failed(path, e))?;
        chart
            .draw_series(LineSeries::new(line, c.stroke_width(2)))
            .map_err(|e| failed(path, e))?;
    }
    root.present().map_err(|e| failed(path, e))?;
    Ok(())
}
