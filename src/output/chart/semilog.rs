//! Charts with a logarithmic x axis and a linear y axis (a quantity against a stiffness
//! spanning decades: the load transfer efficiency of a joint against AGG/(kℓ)).

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::axis::{log_axis, log_tick_label, padded_range, plain_labels, tick_format};
use super::loglog::{draw_grid, legend_corner, Series};
use super::style::{self, LABEL_FONT, LINE_WIDTH};
use super::{titled, txt, write_png, write_svg, DrawResult, Picture, TextBox};
use crate::error::Result;

/// One series of a semi-log chart and how its line is drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct SemilogSeries {
    /// The points, legend name and whether a line and markers are drawn (as on a log–log
    /// chart).
    pub series: Series,
    /// Draw the line dashed (regressions, references) instead of solid.
    pub dashed: bool,
}

/// Write a chart of `series` against a logarithmic x axis and a linear y axis as SVG (`svg`)
/// and PNG (`png`), 900 × 600 pixels. Points with a non-finite coordinate or x ≤ 0 are
/// skipped. The y axis spans `y_range` when given, else the data with a 5 % margin. Series
/// take the chart palette in order; markers are filled circles; the legend (series with
/// non-empty names) sits in the corner of the plot that hides the fewest points.
///
/// # Errors
/// [`crate::Error::Io`] if a file cannot be written or drawing fails.
pub fn write_semilogx(
    svg: &Path,
    png: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    y_range: Option<(f64, f64)>,
    series: &[SemilogSeries],
) -> Result<()> {
    let chart = SemilogChart {
        title,
        x_label,
        y_label,
        y_range,
        series,
    };
    write_svg(svg, &chart)?;
    write_png(png, &chart)
}

/// Everything drawn on a semi-log chart.
struct SemilogChart<'a> {
    title: &'a str,
    x_label: &'a str,
    y_label: &'a str,
    y_range: Option<(f64, f64)>,
    series: &'a [SemilogSeries],
}

impl Picture for SemilogChart<'_> {
    fn size(&self) -> (u32, u32) {
        (900, 600)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<()> {
        let body = titled(root, self.title)?;
        let valid: Vec<Vec<(f64, f64)>> = self
            .series
            .iter()
            .map(|s| {
                s.series
                    .points
                    .iter()
                    .copied()
                    .filter(|&(x, y)| x.is_finite() && x > 0.0 && y.is_finite())
                    .collect()
            })
            .collect();
        let xa = log_axis(valid.iter().flatten().map(|p| p.0.log10()));
        let (y_lo, y_hi) = match self.y_range {
            Some((lo, hi)) if lo.is_finite() && hi.is_finite() && hi > lo => (lo, hi),
            _ => padded_range(valid.iter().flatten().map(|p| p.1), None),
        };
        let pow = |v: &[f64]| v.iter().map(|e| 10f64.powf(*e)).collect::<Vec<f64>>();
        let mut chart = ChartBuilder::on(&body)
            .margin(15)
            .margin_right(25)
            .x_label_area_size(50)
            .y_label_area_size(70)
            .build_cartesian_2d(
                (10f64.powf(xa.lo)..10f64.powf(xa.hi))
                    .log_scale()
                    .with_key_points(pow(&xa.bold))
                    .with_light_points(pow(&xa.light)),
                y_lo..y_hi,
            )
            .map_err(txt)?;
        let x_plain = plain_labels(&xa);
        let x_fmt = |v: &f64| log_tick_label(v.log10(), x_plain);
        let y_fmt = tick_format(y_lo, y_hi);
        draw_grid(&mut chart, (self.x_label, self.y_label), &x_fmt, &y_fmt)?;

        for (k, (s, pts)) in self.series.iter().zip(&valid).enumerate() {
            let colour = style::series_colour(k);
            let stroke = colour.stroke_width(LINE_WIDTH);
            if s.series.line && pts.len() > 1 {
                if s.dashed {
                    chart
                        .draw_series(DashedLineSeries::new(pts.iter().copied(), 8, 5, stroke))
                        .map_err(txt)?;
                } else {
                    chart
                        .draw_series(LineSeries::new(pts.iter().copied(), stroke))
                        .map_err(txt)?;
                }
            }
        }
        for (k, (s, pts)) in self.series.iter().zip(&valid).enumerate() {
            if s.series.markers || !s.series.line {
                let fill = style::series_colour(k).filled();
                chart
                    .draw_series(pts.iter().map(|&p| Circle::new(p, 4, fill)))
                    .map_err(txt)?;
            }
        }

        // Legend in the corner that hides the fewest data points (lower right on a tie).
        let entries: Vec<usize> = (0..self.series.len())
            .filter(|&k| !self.series[k].series.name.is_empty())
            .collect();
        if entries.is_empty() {
            return Ok(());
        }
        let lines: Vec<String> = entries
            .iter()
            .map(|&k| self.series[k].series.name.clone())
            .collect();
        let swatch_w = 40;
        let legend = TextBox {
            lines: &lines,
            font: LABEL_FONT,
            line_h: 20,
            swatch_w,
        };
        let pixels: Vec<(i32, i32)> = valid
            .iter()
            .flatten()
            .map(|p| chart.backend_coord(p))
            .collect();
        let plot = chart.plotting_area().get_pixel_range();
        let best = legend_corner(plot, legend.size(), &pixels, false);
        legend.draw(root, best, |i, (x, y)| {
            let k = entries[i];
            let s = &self.series[k];
            let colour = style::series_colour(k);
            if s.series.line {
                let end = x + swatch_w - 10;
                let segments: Vec<(i32, i32)> = if s.dashed {
                    vec![(x, x + 8), (x + 13, end)]
                } else {
                    vec![(x, end)]
                };
                for (a, e) in segments {
                    root.draw(&PathElement::new(
                        vec![(a, y), (e, y)],
                        colour.stroke_width(LINE_WIDTH),
                    ))
                    .map_err(txt)?;
                }
            }
            if s.series.markers || !s.series.line {
                root.draw(&Circle::new(
                    (x + (swatch_w - 10) / 2, y),
                    4,
                    colour.filled(),
                ))
                .map_err(txt)?;
            }
            Ok(())
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn semilog_chart_is_written_as_svg_and_png() {
        let dir = tempfile::tempdir().expect("tempdir");
        let (svg, png) = (dir.path().join("c.svg"), dir.path().join("c.png"));
        let f = [0.01, 0.1, 1.0, 10.0, 100.0];
        let series = vec![
            SemilogSeries {
                series: Series {
                    name: "computed".to_string(),
                    points: f.iter().map(|&x| (x, x / (1.0 + x))).collect(),
                    line: false,
                    markers: true,
                },
                dashed: false,
            },
            SemilogSeries {
                series: Series {
                    name: "fit".to_string(),
                    points: vec![(0.01, 0.02), (f64::NAN, 0.5), (-1.0, 0.1), (100.0, 0.98)],
                    line: true,
                    markers: false,
                },
                dashed: true,
            },
        ];
        write_semilogx(
            &svg,
            &png,
            "Semi-log title",
            "f",
            "LTE",
            Some((0.0, 1.0)),
            &series,
        )
        .expect("write");
        let text = std::fs::read_to_string(&svg).expect("svg");
        assert!(text.contains("Semi-log title") && text.contains("computed"));
        let bytes = std::fs::read(&png).expect("png");
        assert!(bytes.starts_with(&[0x89, b'P', b'N', b'G']));
        // No valid point: empty axes, still written.
        write_semilogx(&svg, &png, "Empty", "f", "LTE", None, &[]).expect("empty");
    }
}
