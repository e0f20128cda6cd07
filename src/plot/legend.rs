//! Legends drawn in a panel of their own beside the chart, so they never
//! cover data or labels, each swatch drawn with the style of its series.

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::{PlotError, failed};

/// How a legend entry's series is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Swatch {
    /// A solid line of the colour and width.
    Line(RGBColor, u32),
    /// A dashed line of the colour and width.
    Dashed(RGBColor, u32),
    /// A solid line with filled circles on it.
    LineDots(RGBColor, u32),
    /// A dashed line with filled triangles on it.
    DashedTriangles(RGBColor, u32),
    /// A filled dot.
    Dot(RGBColor),
    /// An open circle.
    Ring(RGBColor),
    /// A cross.
    Cross(RGBColor),
    /// A shaded band.
    Band(RGBColor),
}

/// Width (px) of a legend panel.
pub const LEGEND_WIDTH: u32 = 300;

/// Height (px) of one legend row.
const ROW: i32 = 24;

/// Characters per legend line before a label wraps, in a panel `width` px
/// wide (16 px sans-serif: about 9 px per character, the text 52 px in).
pub fn wrap_width(width: u32) -> usize {
    ((width.saturating_sub(60)) / 9).max(12) as usize
}

/// `label` broken into lines of at most `wrap` characters at spaces.
pub fn wrapped(label: &str, wrap: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in label.split(' ') {
        match lines.last_mut() {
            Some(line) if line.chars().count() + 1 + word.chars().count() <= wrap => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

/// Height (px) the legend of `entries` takes in a panel `width` px wide,
/// with an optional heading.
pub fn legend_height(width: u32, heading: Option<&str>, entries: &[(Swatch, String)]) -> i32 {
    let wrap = wrap_width(width);
    let rows: usize = entries.iter().map(|(_, l)| wrapped(l, wrap).len()).sum();
    ROW * (rows as i32 + i32::from(heading.is_some())) + 16
}

/// Draw `entries` top down in `area` (a panel beside the chart), under
/// `heading` if given, wrapped to the panel's width. Entries that do not fit
/// its height are counted in a last line instead.
pub fn draw_legend(
    area: &DrawingArea<BitMapBackend, Shift>,
    path: &Path,
    heading: Option<&str>,
    entries: &[(Swatch, String)],
) -> Result<(), PlotError> {
    let font = ("sans-serif", 16).into_font();
    let (width, height) = area.dim_in_pixel();
    let wrap = wrap_width(width);
    let mut y = 12;
    if let Some(h) = heading {
        area.draw(&Text::new(
            h.to_string(),
            (10, y),
            font.clone().style(FontStyle::Bold),
        ))
        .map_err(|e| failed(path, e))?;
        y += ROW;
    }
    for (k, (swatch, label)) in entries.iter().enumerate() {
        let lines = wrapped(label, wrap);
        if y + ROW * (lines.len() as i32 + 1) > height as i32 {
            area.draw(&Text::new(
                format!("… {} more (see the table)", entries.len() - k),
                (10, y),
                font.clone(),
            ))
            .map_err(|e| failed(path, e))?;
            break;
        }
        let mid = y + 8;
        let (x0, x1) = (10, 44);
        match *swatch {
            Swatch::Line(c, w) | Swatch::LineDots(c, w) => {
                area.draw(&PathElement::new([(x0, mid), (x1, mid)], c.stroke_width(w)))
                    .map_err(|e| failed(path, e))?;
                if matches!(swatch, Swatch::LineDots(..)) {
                    area.draw(&Circle::new((27, mid), 3, c.filled()))
                        .map_err(|e| failed(path, e))?;
                }
            }
            Swatch::Dashed(c, w) | Swatch::DashedTriangles(c, w) => {
                for k in 0..3 {
                    let a = x0 + 13 * k;
                    area.draw(&PathElement::new(
                        [(a, mid), ((a + 8).min(x1), mid)],
                        c.stroke_width(w),
                    ))
                    .map_err(|e| failed(path, e))?;
                }
                if matches!(swatch, Swatch::DashedTriangles(..)) {
                    area.draw(&TriangleMarker::new((27, mid), 4, c.filled()))
                        .map_err(|e| failed(path, e))?;
                }
            }
            Swatch::Dot(c) => area
                .draw(&Circle::new((27, mid), 4, c.filled()))
                .map_err(|e| failed(path, e))?,
            Swatch::Ring(c) => area
                .draw(&Circle::new((27, mid), 6, c.stroke_width(2)))
                .map_err(|e| failed(path, e))?,
            Swatch::Cross(c) => area
                .draw(&Cross::new((27, mid), 6, c.stroke_width(2)))
                .map_err(|e| failed(path, e))?,
            Swatch::Band(c) => area
                .draw(&Rectangle::new(
                    [(x0, mid - 7), (x1, mid + 7)],
                    c.mix(0.35).filled(),
                ))
                .map_err(|e| failed(path, e))?,
        }
        for line in lines {
            area.draw(&Text::new(line, (52, y), font.clone()))
                .map_err(|e| failed(path, e))?;
            y += ROW;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_labels_wrap_at_spaces_and_short_ones_stay() {
        let wrap = wrap_width(LEGEND_WIDTH);
        assert_eq!(wrap, 26);
        assert_eq!(wrapped("forward whirl", wrap), ["forward whirl"]);
        let lines = wrapped("overdamped crossing (ζ ≥ 0.5), not a critical speed", wrap);
        assert_eq!(lines.len(), 2, "{lines:?}");
        assert!(lines.iter().all(|l| l.chars().count() <= wrap));
        assert_eq!(
            lines.join(" "),
            "overdamped crossing (ζ ≥ 0.5), not a critical speed"
        );
        let entries = [(Swatch::Dot(BLACK), "a".to_string())];
        assert_eq!(
            legend_height(LEGEND_WIDTH, Some("h"), &entries),
            2 * ROW + 16
        );
    }
}
