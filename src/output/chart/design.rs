//! The design curve of `liftoff design`: the measure compared with the target (cracking in %,
//! or damage on a logarithmic axis) against the slab's thickness, the target as a dashed line
//! and the thickness found as a vertical one.

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::axis::{padded_range, tick_format};
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
        let (y0, y1) = padded_range(ys, Some(y(self.target)));
        let mut chart = ChartBuilder::on(&body)
            .margin(15)
            .margin_right(25)
            .x_label_area_size(50)
            .y_label_area_size(80)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(txt)?;
        let x_fmt = tick_format(x0, x1);
        let plain = tick_format(y0, y1);
        let y_fmt = |v: &f64| {
            if self.log {
                format!("1e{}", plain(v))
            } else {
                plain(v)
            }
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
