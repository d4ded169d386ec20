//! The charts of `liftoff backcalc`: measured basins (markers) against the fitted ones (lines),
//! deflection drawn downward from the surface; and the backcalculated moduli drop by drop along
//! the survey, each with its 95 % interval.

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::axis::{padded_range, tick_format};
use super::loglog::draw_grid;
use super::style::{self, LINE_WIDTH};
use super::{titled, txt, write_png, write_svg, DrawResult, Picture};
use crate::error::Result;

/// One drop's basin in display units.
#[derive(Debug, Clone, PartialEq)]
pub struct BasinCurve {
    /// Legend text (the station and drop).
    pub label: String,
    /// (offset, deflection) measured.
    pub measured: Vec<(f64, f64)>,
    /// (offset, deflection) of the model at the fitted values (empty: none).
    pub fitted: Vec<(f64, f64)>,
}

/// The basins chart.
#[derive(Debug, Clone, PartialEq)]
pub struct BasinChart<'a> {
    /// Title.
    pub title: &'a str,
    /// x label (the offset and its unit).
    pub x_label: &'a str,
    /// y label (the deflection and its unit).
    pub y_label: &'a str,
    /// The drops drawn.
    pub curves: &'a [BasinCurve],
}

/// One modulus along the survey in display units.
#[derive(Debug, Clone, PartialEq)]
pub struct ModulusSeries<'a> {
    /// Panel title (what and its unit).
    pub label: &'a str,
    /// (drop's place in the survey from 1, value, interval).
    pub points: Vec<(f64, f64, Option<[f64; 2]>)>,
}

/// The moduli chart: one panel a modulus, the drops in survey order along x.
#[derive(Debug, Clone, PartialEq)]
pub struct ModuliChart<'a> {
    /// Title.
    pub title: &'a str,
    /// The panels.
    pub series: &'a [ModulusSeries<'a>],
    /// Each drop's station, in survey order: the x ticks' labels (at the whole places the
    /// axis ticks).
    pub stations: &'a [String],
}

/// Write the basins chart as SVG and PNG, 900 × 600 pixels.
///
/// # Errors
/// [`crate::Error::Io`] if a file cannot be written or drawing fails.
pub fn write_basins(svg: &Path, png: &Path, c: &BasinChart<'_>) -> Result<()> {
    write_svg(svg, c)?;
    write_png(png, c)
}

/// Write the moduli chart as SVG and PNG.
///
/// # Errors
/// [`crate::Error::Io`] if a file cannot be written or drawing fails.
pub fn write_moduli(svg: &Path, png: &Path, c: &ModuliChart<'_>) -> Result<()> {
    write_svg(svg, c)?;
    write_png(png, c)
}

impl Picture for BasinChart<'_> {
    fn size(&self) -> (u32, u32) {
        (900, 600)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<()> {
        let body = titled(root, self.title)?;
        let all = || {
            self.curves
                .iter()
                .flat_map(|c| c.measured.iter().chain(&c.fitted))
        };
        let (x0, x1) = padded_range(all().map(|p| p.0), Some(0.0));
        let (y0, y1) = padded_range(all().map(|p| p.1), Some(0.0));
        // Deflection downward: the axis runs from the largest at the bottom to 0 at the top.
        let mut chart = ChartBuilder::on(&body)
            .margin(15)
            .margin_right(25)
            .x_label_area_size(50)
            .y_label_area_size(80)
            .build_cartesian_2d(x0..x1, y1..y0)
            .map_err(txt)?;
        let x_fmt = tick_format(x0, x1);
        let y_fmt = tick_format(y0, y1);
        draw_grid(&mut chart, (self.x_label, self.y_label), &x_fmt, &y_fmt)?;
        for (k, c) in self.curves.iter().enumerate() {
            let colour = style::series_colour(k);
            if !c.fitted.is_empty() {
                chart
                    .draw_series(LineSeries::new(
                        c.fitted.iter().copied(),
                        colour.stroke_width(LINE_WIDTH),
                    ))
                    .map_err(txt)?;
            }
            chart
                .draw_series(
                    c.measured
                        .iter()
                        .map(|&p| Circle::new(p, 4, colour.filled())),
                )
                .map_err(txt)?
                .label(c.label.clone())
                .legend(move |(x, y)| {
                    EmptyElement::at((x + 10, y))
                        + Circle::new((0, 0), 4, colour.filled())
                        + PathElement::new(vec![(-10, 0), (10, 0)], colour.stroke_width(LINE_WIDTH))
                });
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font((super::FONT, style::LABEL_FONT))
            .position(SeriesLabelPosition::LowerRight)
            .draw()
            .map_err(txt)
    }
}

impl Picture for ModuliChart<'_> {
    fn size(&self) -> (u32, u32) {
        (900, 300 + 250 * self.series.len().max(1) as u32)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<()> {
        let body = titled(root, self.title)?;
        let panels = body.split_evenly((self.series.len().max(1), 1));
        let n = self
            .series
            .iter()
            .flat_map(|s| s.points.iter().map(|p| p.0))
            .fold(1.0_f64, f64::max);
        for (s, area) in self.series.iter().zip(&panels) {
            let ys = s
                .points
                .iter()
                .flat_map(|&(_, v, i)| std::iter::once(v).chain(i.into_iter().flatten()));
            let (y0, y1) = padded_range(ys, Some(0.0));
            let mut chart = ChartBuilder::on(area)
                .margin(15)
                .margin_right(25)
                .x_label_area_size(45)
                .y_label_area_size(80)
                .build_cartesian_2d(0.5..n + 0.5, y0..y1)
                .map_err(txt)?;
            let stations = self.stations;
            let x_fmt = move |x: &f64| {
                let i = x.round();
                if (x - i).abs() < 1e-9 && i >= 1.0 {
                    stations.get(i as usize - 1).cloned().unwrap_or_default()
                } else {
                    String::new()
                }
            };
            let y_fmt = tick_format(y0, y1);
            draw_grid(
                &mut chart,
                ("station (one point a drop)", s.label),
                &x_fmt,
                &y_fmt,
            )?;
            let colour = style::series_colour(0);
            chart
                .draw_series(s.points.iter().filter_map(|&(x, _, i)| {
                    i.map(|[lo, hi]| {
                        PathElement::new(vec![(x, lo), (x, hi)], colour.stroke_width(LINE_WIDTH))
                    })
                }))
                .map_err(txt)?;
            chart
                .draw_series(
                    s.points
                        .iter()
                        .map(|&(x, v, _)| Circle::new((x, v), 4, colour.filled())),
                )
                .map_err(txt)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_charts_are_written_and_name_their_drops() {
        let dir = tempfile::tempdir().expect("tempdir");
        let (svg, png) = (dir.path().join("b.svg"), dir.path().join("b.png"));
        let curves = [BasinCurve {
            label: "station 0+100, drop 2".into(),
            measured: vec![(0.0, 100.0), (305.0, 80.0), (610.0, 60.0)],
            fitted: vec![(0.0, 101.0), (305.0, 79.0), (610.0, 60.5)],
        }];
        write_basins(
            &svg,
            &png,
            &BasinChart {
                title: "Basins",
                x_label: "offset [mm]",
                y_label: "deflection [µm]",
                curves: &curves,
            },
        )
        .expect("basins");
        let text = std::fs::read_to_string(&svg).expect("svg");
        assert!(text.contains("station 0+100, drop 2") && text.contains("offset [mm]"));
        let series = [ModulusSeries {
            label: "k [MPa/m]",
            points: vec![(1.0, 80.0, Some([75.0, 85.0])), (2.0, 82.0, None)],
        }];
        let stations = ["0+100".to_string(), "0+100".to_string()];
        write_moduli(
            &svg,
            &png,
            &ModuliChart {
                title: "Moduli",
                series: &series,
                stations: &stations,
            },
        )
        .expect("moduli");
        let text = std::fs::read_to_string(&svg).expect("svg");
        assert!(text.contains("k [MPa/m]") && text.contains("0+100"));
        assert!(std::fs::read(&png)
            .expect("png")
            .starts_with(&[0x89, b'P', b'N', b'G']));
    }
}
