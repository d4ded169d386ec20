//! Log–log charts of several series with a legend and free-text notes (the ε̄ sweep, speed
//! against accuracy).

use std::ops::Range;
use std::path::Path;

use plotters::coord::ranged1d::ValueFormatter;
use plotters::coord::Shift;
use plotters::prelude::*;

use super::axis::{log_axis, log_tick_label, plain_labels};
use super::style::{self, shape_of, Shape, DESC_FONT, LABEL_FONT, LINE_WIDTH};
use super::{titled, txt, write_svg, DrawResult, Picture, TextBox, FONT};
use crate::error::Result;
use crate::metrics::is_loggable;

/// One data series of a chart.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Name shown in the legend; an empty name leaves the series out of the legend.
    pub name: String,
    /// The (x, y) points, drawn in this order.
    pub points: Vec<(f64, f64)>,
    /// Join consecutive (valid) points with a line.
    pub line: bool,
    /// Draw a marker at each (valid) point. A series with neither `line` nor `markers` is drawn
    /// with markers.
    pub markers: bool,
}

impl Series {
    /// Whether the series is drawn with markers.
    fn has_markers(&self) -> bool {
        self.markers || !self.line
    }
}

/// Height of one line of the notes and the legend, pixels.
const LINE_H: i32 = 20;

/// Log–log chart (both axes logarithmic) of several series with a legend and free-text notes
/// (e.g. "fitted slope 1.01") written in a box between the title and the plot, where they hide
/// no data. Points with non-finite or non-positive coordinates are skipped; axis ranges fit the
/// remaining points with a small margin (at least one decade each); empty input draws empty
/// axes with the title. `reverse_x` draws x decreasing to the right (useful for ε̄ going to 0).
///
/// The chart is 900 × 650 pixels. Series are coloured in order from a ten-colour palette and
/// get different marker shapes (circle, triangle, square, diamond, cross); lines join the valid
/// points in the given order. The legend lists the series with non-empty names and is placed
/// in the corner of the plot that hides the fewest data. Ticks are labelled at decades (also at
/// 2 and 5 × 10ⁿ when the axis spans few decades), as plain numbers from 0.01 to 1000 and as
/// powers of ten otherwise.
///
/// # Errors
/// [`crate::Error::Io`] if the file cannot be written or drawing fails.
pub fn write_loglog_svg(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series],
    notes: &[String],
    reverse_x: bool,
) -> Result<()> {
    let chart = LogLogChart {
        title,
        x_label,
        y_label,
        series,
        notes,
        reverse_x,
    };
    write_svg(path, &chart)
}

/// Everything drawn on a log–log chart.
struct LogLogChart<'a> {
    title: &'a str,
    x_label: &'a str,
    y_label: &'a str,
    series: &'a [Series],
    notes: &'a [String],
    reverse_x: bool,
}

/// Evaluate `$body` with `$mk` bound to a closure that builds the marker of `$shape` in
/// `$colour` centred at its argument (one closure type per shape, hence a macro).
macro_rules! with_marker {
    ($shape:expr, $colour:expr, |$mk:ident| $body:expr) => {{
        let fill = $colour.filled();
        match $shape {
            Shape::Circle => {
                let $mk = |at| EmptyElement::at(at) + Circle::new((0, 0), 4, fill);
                $body
            }
            Shape::Triangle => {
                let $mk = |at| EmptyElement::at(at) + TriangleMarker::new((0, 0), 5, fill);
                $body
            }
            Shape::Square => {
                let $mk = |at| EmptyElement::at(at) + Rectangle::new([(-4, -4), (4, 4)], fill);
                $body
            }
            Shape::Diamond => {
                let $mk = |at| {
                    EmptyElement::at(at)
                        + Polygon::new(vec![(0, -5), (5, 0), (0, 5), (-5, 0)], fill)
                };
                $body
            }
            Shape::Cross => {
                let stroke = $colour.stroke_width(LINE_WIDTH);
                let $mk = |at| EmptyElement::at(at) + Cross::new((0, 0), 4, stroke);
                $body
            }
        }
    }};
}

impl Picture for LogLogChart<'_> {
    fn size(&self) -> (u32, u32) {
        (900, 650)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<()> {
        let c = self;
        let body = titled(root, c.title)?;
        let notes = TextBox {
            lines: c.notes,
            font: LABEL_FONT,
            line_h: LINE_H,
            swatch_w: 0,
        };
        // The notes get a band of their own above the plot.
        let (band_top, plot_area) = if c.notes.is_empty() {
            (None, body)
        } else {
            let top = body.get_pixel_range().1.start + 6;
            let (_, plot) = body.split_vertically(notes.size().1 + 6);
            (Some(top), plot)
        };

        // Valid points per series.
        let logs: Vec<Vec<(f64, f64)>> = c
            .series
            .iter()
            .map(|s| {
                s.points
                    .iter()
                    .copied()
                    .filter(|&p| is_loggable(p))
                    .collect()
            })
            .collect();
        let xa = log_axis(logs.iter().flatten().map(|p| p.0.log10()));
        let ya = log_axis(logs.iter().flatten().map(|p| p.1.log10()));
        let pow = |v: &[f64]| v.iter().map(|e| 10f64.powf(*e)).collect::<Vec<f64>>();
        let (x_lo, x_hi) = (10f64.powf(xa.lo), 10f64.powf(xa.hi));
        let x_range = if c.reverse_x { x_hi..x_lo } else { x_lo..x_hi };

        let mut chart = ChartBuilder::on(&plot_area)
            .margin(15)
            .margin_right(25)
            .x_label_area_size(50)
            .y_label_area_size(80)
            .build_cartesian_2d(
                x_range
                    .log_scale()
                    .with_key_points(pow(&xa.bold))
                    .with_light_points(pow(&xa.light)),
                (10f64.powf(ya.lo)..10f64.powf(ya.hi))
                    .log_scale()
                    .with_key_points(pow(&ya.bold))
                    .with_light_points(pow(&ya.light)),
            )
            .map_err(txt)?;
        let (x_plain, y_plain) = (plain_labels(&xa), plain_labels(&ya));
        let x_fmt = |v: &f64| log_tick_label(v.log10(), x_plain);
        let y_fmt = |v: &f64| log_tick_label(v.log10(), y_plain);
        draw_grid(&mut chart, (c.x_label, c.y_label), &x_fmt, &y_fmt)?;

        // Series: lines first, then markers on top.
        for (k, pts) in logs.iter().enumerate() {
            let colour = style::series_colour(k);
            if c.series[k].line && pts.len() > 1 {
                chart
                    .draw_series(LineSeries::new(
                        pts.iter().copied(),
                        colour.stroke_width(LINE_WIDTH),
                    ))
                    .map_err(txt)?;
            }
        }
        for (k, pts) in logs.iter().enumerate() {
            let colour = style::series_colour(k);
            if c.series[k].has_markers() {
                with_marker!(shape_of(k), colour, |mk| chart
                    .draw_series(pts.iter().map(|&p| mk(p)))
                    .map(|_| ()))
                .map_err(txt)?;
            }
        }

        let (px_range, py_range) = chart.plotting_area().get_pixel_range();
        if let Some(top) = band_top {
            notes.draw(root, (px_range.start, top), |_, _| Ok(()))?;
        }

        // Data in pixels (points and samples along lines), to place the legend where it hides
        // least.
        let mut samples: Vec<(i32, i32)> = Vec::new();
        for (k, pts) in logs.iter().enumerate() {
            let px: Vec<(i32, i32)> = pts.iter().map(|p| chart.backend_coord(p)).collect();
            samples.extend(px.iter().copied());
            if c.series[k].line {
                for w in px.windows(2) {
                    let (a, b) = (w[0], w[1]);
                    let len = (a.0 - b.0).abs().max((a.1 - b.1).abs());
                    let n = (len / 4).clamp(1, 500);
                    for i in 1..n {
                        let t = f64::from(i) / f64::from(n);
                        samples.push((
                            a.0 + (t * f64::from(b.0 - a.0)).round() as i32,
                            a.1 + (t * f64::from(b.1 - a.1)).round() as i32,
                        ));
                    }
                }
            }
        }

        // Legend, in the corner hiding the fewest samples (upper right on a tie).
        let entries: Vec<usize> = (0..c.series.len())
            .filter(|&k| !c.series[k].name.is_empty())
            .collect();
        if entries.is_empty() {
            return Ok(());
        }
        let lines: Vec<String> = entries.iter().map(|&k| c.series[k].name.clone()).collect();
        let swatch_w = 40;
        let legend = TextBox {
            lines: &lines,
            font: LABEL_FONT,
            line_h: LINE_H,
            swatch_w,
        };
        let best = legend_corner((px_range, py_range), legend.size(), &samples, true);
        legend.draw(root, best, |i, (x, y)| {
            let k = entries[i];
            let s = &c.series[k];
            let colour = style::series_colour(k);
            if s.line {
                root.draw(&PathElement::new(
                    vec![(x, y), (x + swatch_w - 10, y)],
                    colour.stroke_width(LINE_WIDTH),
                ))
                .map_err(txt)?;
            }
            if s.has_markers() {
                let at = (x + (swatch_w - 10) / 2, y);
                with_marker!(shape_of(k), colour, |mk| root.draw(&mk(at))).map_err(txt)?;
            }
            Ok(())
        })
    }
}

/// Draw the grid, the tick labels (`x_fmt`, `y_fmt`) and the axis titles `(x, y)` of a chart
/// in the style of the log charts (major and minor grid lines).
pub(super) fn draw_grid<DB, X, Y>(
    chart: &mut ChartContext<'_, DB, Cartesian2d<X, Y>>,
    (x_desc, y_desc): (&str, &str),
    x_fmt: &dyn Fn(&X::ValueType) -> String,
    y_fmt: &dyn Fn(&Y::ValueType) -> String,
) -> DrawResult<()>
where
    DB: DrawingBackend,
    X: Ranged + ValueFormatter<X::ValueType>,
    Y: Ranged + ValueFormatter<Y::ValueType>,
{
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_label_formatter(x_fmt)
        .y_label_formatter(y_fmt)
        .label_style((FONT, LABEL_FONT))
        .axis_desc_style((FONT, DESC_FONT))
        .bold_line_style(style::GRID_MAJOR)
        .light_line_style(style::GRID_MINOR)
        .draw()
        .map_err(txt)
}

/// The top-left pixel of a legend of `(w, h)` pixels in the corner of the plot (pixel ranges
/// `(px, py)`, 10 pixels in) that hides the fewest `samples` (data in pixels); on a tie the
/// right corner at the top (`top_first`) or at the bottom, then the opposite corner.
pub(super) fn legend_corner(
    (px, py): (Range<i32>, Range<i32>),
    (w, h): (i32, i32),
    samples: &[(i32, i32)],
    top_first: bool,
) -> (i32, i32) {
    let inset = 10;
    let (l, r) = (px.start + inset, px.end - inset - w);
    let (t, b) = (py.start + inset, py.end - inset - h);
    let (first, second) = if top_first { (t, b) } else { (b, t) };
    let hidden = |&(x, y): &(i32, i32)| {
        samples
            .iter()
            .filter(|&&(sx, sy)| sx >= x && sx <= x + w && sy >= y && sy <= y + h)
            .count()
    };
    let corners = [(r, first), (l, second), (r, second), (l, first)];
    // min_by_key keeps the first of equal counts: the order above breaks ties.
    corners.into_iter().min_by_key(hidden).unwrap_or((r, first))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn demo_series() -> Vec<Series> {
        let eps = [1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 3e-4, 1e-4];
        vec![
            Series {
                name: "penalty, Winkler".to_string(),
                points: eps.iter().map(|&e| (e, 2.0 * e)).collect(),
                line: true,
                markers: true,
            },
            Series {
                name: "penalty, half-space".to_string(),
                points: eps.iter().map(|&e| (e, 0.5 * e.powf(1.02))).collect(),
                line: true,
                markers: true,
            },
            Series {
                name: "O(ε̄) reference".to_string(),
                points: vec![(1e-1, 1e-1), (1e-4, 1e-4)],
                line: true,
                markers: false,
            },
            Series {
                name: "QP".to_string(),
                points: vec![(1e-4, 3e-6), (f64::NAN, 1.0), (-1.0, 2.0), (1e-3, 0.0)],
                line: false,
                markers: true,
            },
        ]
    }

    #[test]
    fn loglog_svg_is_written() {
        let dir = tempfile::tempdir().expect("tempdir");
        let path = dir.path().join("conv.svg");
        let notes = vec!["fitted slope 1.01".to_string(), "second note".to_string()];
        write_loglog_svg(
            &path,
            "Convergence test title",
            "ε̄",
            "error",
            &demo_series(),
            &notes,
            true,
        )
        .expect("write");
        let text = std::fs::read_to_string(&path).expect("read");
        assert!(text.contains("<svg"));
        assert!(text.contains("Convergence test title"));
        assert!(text.contains("fitted slope 1.01"));
        assert!(text.contains("penalty, half-space"));
    }

    #[test]
    fn loglog_svg_handles_degenerate_input() {
        let dir = tempfile::tempdir().expect("tempdir");
        let path = dir.path().join("empty.svg");
        write_loglog_svg(&path, "Empty chart", "x", "y", &[], &[], false).expect("empty");
        let text = std::fs::read_to_string(&path).expect("read");
        assert!(text.contains("<svg") && text.contains("Empty chart"));

        let bad = [
            Series {
                name: "nan".to_string(),
                points: vec![(f64::NAN, f64::NAN), (0.0, 1.0), (1.0, f64::INFINITY)],
                line: true,
                markers: true,
            },
            Series {
                name: String::new(),
                points: vec![(2.0, 2.0)],
                line: false,
                markers: false,
            },
            Series {
                name: "tiny".to_string(),
                points: vec![(f64::MIN_POSITIVE, 1e-300), (f64::MAX, 1e300)],
                line: true,
                markers: true,
            },
        ];
        for (k, series) in [&bad[..1], &bad[..2], &bad[..]].iter().enumerate() {
            let path = dir.path().join(format!("bad{k}.svg"));
            let title = format!("NaN chart {k}");
            write_loglog_svg(&path, &title, "x", "y", series, &["n".to_string()], k == 1)
                .expect("nan points");
            let text = std::fs::read_to_string(&path).expect("read");
            assert!(text.contains("<svg") && text.contains(&title));
        }
    }

    #[test]
    fn loglog_renders_to_png() {
        // The bitmap backend runs the same drawing code as the SVG file.
        let dir = tempfile::tempdir().expect("tempdir");
        let notes = vec!["fitted slope 1.01".to_string(), "QP: 1 point".to_string()];
        let series = demo_series();
        let chart = LogLogChart {
            title: "Convergence of the penalty iteration as ε̄ → 0",
            x_label: "ε̄",
            y_label: "relative error in max V",
            series: &series,
            notes: &notes,
            reverse_x: true,
        };
        let png = dir.path().join("loglog.png");
        super::super::write_png(&png, &chart).expect("png");
        let bytes = std::fs::read(&png).expect("read png");
        assert!(bytes.starts_with(&[0x89, b'P', b'N', b'G']));
    }
}
