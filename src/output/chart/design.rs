//! The design curve of `liftoff design`: the measure compared with the target (cracking in %,
//! or damage on a logarithmic axis) against the slab's thickness, the target as a dashed line
//! and the thickness found as a vertical one.

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::axis::{log_axis, log_tick_label, padded_range, plain_labels, tick_format, Ticked};
use super::loglog::draw_grid;
use super::style::{self, LINE_WIDTH};
use super::{titled, txt, write_png, write_svg, DrawResult, Picture};
use crate::error::Result;

/// What the design chart draws.
#[derive(Debug, Clone, PartialEq)]
pub struct DesignCurve<'a> {
    /// Title.
    pub title: &'a str,
    /// x axis label (the thickness and its unit).
    pub x_label: &'a str,
    /// y axis label.
    pub y_label: &'a str,
    /// (thickness, value) of the design curve, in order.
    pub curve: &'a [(f64, f64)],
    /// (thickness, value) of the search's runs that narrow the bracket.
    pub steps: &'a [(f64, f64)],
    /// The target.
    pub target: f64,
    /// The thickness found.
    pub found: Option<f64>,
    /// Draw the values' common logarithm (damage spanning decades).
    pub log: bool,
}

/// Write the design chart as SVG and PNG, 900 × 600 pixels.
///
/// # Errors
/// [`crate::Error::Io`] if a file cannot be written or drawing fails.
pub fn write_design_curve(svg: &Path, png: &Path, c: &DesignCurve<'_>) -> Result<()> {
    write_svg(svg, c)?;
    write_png(png, c)
}

impl Picture for DesignCurve<'_> {
    fn size(&self) -> (u32, u32) {
        (900, 600)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<()> {
        let body = titled(root, self.title)?;
        let y = |v: f64| if self.log { v.max(1e-300).log10() } else { v };
        let pts = |v: &[(f64, f64)]| -> Vec<(f64, f64)> {
            v.iter()
                .map(|&(x, v)| (x, y(v)))
                .filter(|p| p.0.is_finite() && p.1.is_finite())
                .collect()
        };
        let (curve, steps) = (pts(self.curve), pts(self.steps));
        let xs = curve.iter().chain(&steps).map(|p| p.0);
        let (x0, x1) = padded_range(xs, None);
        let ys = curve.iter().chain(&steps).map(|p| p.1);
        // Damage on a logarithmic axis: ticks at 1, 2, 5 × 10ⁿ labelled as numbers (the
        // values are drawn as their log10); cracking on a linear one.
        let log = self
            .log
            .then(|| log_axis(ys.clone().chain(std::iter::once(y(self.target)))));
        let (y0, y1) = match &log {
            Some(a) => (a.lo, a.hi),
            None => padded_range(ys, Some(y(self.target))),
        };
        let y_axis = match &log {
            Some(a) => Ticked::at(y0, y1, a.bold.clone()),
            None => Ticked::new(y0, y1, 1.0),
        };
        let mut chart = ChartBuilder::on(&body)
            .margin(15)
            .margin_right(25)
            .x_label_area_size(50)
            .y_label_area_size(80)
            .build_cartesian_2d(x0..x1, y_axis)
            .map_err(txt)?;
        let x_fmt = tick_format(x0, x1);
        let plain = tick_format(y0, y1);
        let y_fmt = |v: &f64| match &log {
            Some(a) => log_tick_label(*v, plain_labels(a)),
            None => plain(v),
        };
        draw_grid(&mut chart, (self.x_label, self.y_label), &x_fmt, &y_fmt)?;
        let target = y(self.target);
        chart
            .draw_series(DashedLineSeries::new(
                [(x0, target), (x1, target)],
                8,
                5,
                style::series_colour(1).stroke_width(LINE_WIDTH),
            ))
            .map_err(txt)?
            .label(format!("target {}", super::short(self.target)))
            .legend(|(x, y)| {
                PathElement::new(
                    vec![(x, y), (x + 20, y)],
                    style::series_colour(1).stroke_width(LINE_WIDTH),
                )
            });
        let colour = style::series_colour(0);
        chart
            .draw_series(LineSeries::new(
                curve.iter().copied(),
                colour.stroke_width(LINE_WIDTH),
            ))
            .map_err(txt)?
            .label("design curve")
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(LINE_WIDTH))
            });
        chart
            .draw_series(curve.iter().map(|&p| Circle::new(p, 4, colour.filled())))
            .map_err(txt)?;
        if !steps.is_empty() {
            let c2 = style::series_colour(2);
            chart
                .draw_series(
                    steps
                        .iter()
                        .map(|&p| TriangleMarker::new(p, 5, c2.filled())),
                )
                .map_err(txt)?
                .label("search step")
                .legend(move |(x, y)| TriangleMarker::new((x + 10, y), 5, c2.filled()));
        }
        if let Some(h) = self.found {
            let c3 = style::series_colour(3);
            chart
                .draw_series(LineSeries::new(
                    [(h, y0), (h, y1)],
                    c3.stroke_width(LINE_WIDTH),
                ))
                .map_err(txt)?
                // To the table's four decimals: three significant digits would show the
                // thickness a search step below (0.2775 m as 0.277).
                .label(format!("least thickness {h:.4}"))
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], c3.stroke_width(LINE_WIDTH))
                });
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font((super::FONT, style::LABEL_FONT))
            .position(SeriesLabelPosition::UpperRight)
            .draw()
            .map_err(txt)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Damage over two decades: the log axis is labelled with the values themselves at 1, 2,
    /// 5 × 10ⁿ (not their logarithms as "1e0.4"), and the target's line is among them.
    #[test]
    fn a_log_axis_is_labelled_with_values() {
        let dir = tempfile::tempdir().expect("tempdir");
        let (svg, png) = (dir.path().join("d.svg"), dir.path().join("d.png"));
        let curve = [(7.0, 4.6), (8.0, 1.8), (9.0, 0.77), (12.0, 0.067)];
        write_design_curve(
            &svg,
            &png,
            &DesignCurve {
                title: "Design",
                x_label: "slab thickness (in)",
                y_label: "largest Σ n/N (log scale)",
                curve: &curve,
                steps: &[],
                target: 1.0,
                found: Some(8.8),
                log: true,
            },
        )
        .expect("chart");
        let text = std::fs::read_to_string(&svg).expect("svg");
        let labels: Vec<&str> = text
            .split("</text>")
            .filter_map(|t| t.rsplit('>').next().map(str::trim))
            .collect();
        for want in ["0.1", "0.2", "0.5", "1", "2", "5"] {
            assert!(labels.contains(&want), "label {want}: {labels:?}");
        }
        assert!(!labels.iter().any(|l| l.starts_with("1e")), "{labels:?}");
    }
}
