//! Profile charts: V = D w / (P L²) (top row, axis pointing down: positive V is a downward
//! deflection) and σ = μ L² r / P (bottom row) along the plate's lines, with zero lines — or,
//! for a physical scene, the deflection w in mm and the contact pressure in kPa against the
//! position along the line in m.
//!
//! One chart serves two pictures:
//!
//! * [`write_profiles_svg`], the `profiles.svg` of a solve: one column over the whole lines
//!   (coordinate −1 to 1, or ± the half-length of the longest line in m), one curve per line;
//! * `write_profile_comparison` (`comparison.rs`), the paper's Figs. 3–5 and 7: one column per
//!   line over its half (coordinate 0 to 1, the plate being symmetric), one curve per solve.
//!
//! Both rows share their value range over all columns (so panels compare by eye); the legend
//! sits in the σ panel of the first column. A single column is drawn large (800 × 900), several
//! columns as small multiples (300 pixels per column, 760 high).

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::axis::{padded_range, tick_format};
use super::style::{self, DESC_FONT, LABEL_FONT, LINE_WIDTH};
use super::units::Units;
use super::{titled, txt, write_svg, DrawResult, Picture, FONT};
use crate::error::Result;
use crate::post::{Profile, ProfilePoint};

/// The runs of a profile's points between its gaps: a step along the line more than 1.5 times
/// the median step (a shaped plate's profile has no points over an opening).
fn runs(pts: Vec<(f64, f64)>) -> Vec<Vec<(f64, f64)>> {
    let mut steps: Vec<f64> = pts.windows(2).map(|w| (w[1].0 - w[0].0).abs()).collect();
    steps.sort_by(f64::total_cmp);
    let Some(&median) = steps.get(steps.len() / 2) else {
        return vec![pts];
    };
    let mut out: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
    for p in pts {
        let last = out.last().and_then(|r| r.last()).copied();
        if last.is_some_and(|q| (p.0 - q.0).abs() > 1.5 * median) {
            out.push(Vec::new());
        }
        if let Some(run) = out.last_mut() {
            run.push(p);
        }
    }
    out
}

/// Legend text of a profile line on a whole-line chart: where it runs, in s and t or in m.
fn line_label(line: &str, units: &Units) -> String {
    if let Some(ph) = units.physical() {
        let l = ph.half_length;
        let len = units.length();
        let m = |v: f64| format!("{} {}", super::plan::short(len.apply(v)), len.unit);
        return match line {
            "x-axis" => "x-axis (y = 0)".to_string(),
            "y-axis" => "y-axis (x = 0)".to_string(),
            "edge-x" => format!("edge-x (y = {})", m(units.mu() * l)),
            "edge-y" => format!("edge-y (x = {})", m(l)),
            other => other.to_string(),
        };
    }
    match line {
        "x-axis" => "x-axis (t = 0)".to_string(),
        "y-axis" => "y-axis (s = 0)".to_string(),
        "edge-x" => "edge-x (t = 1)".to_string(),
        "edge-y" => "edge-y (s = 1)".to_string(),
        other => other.to_string(),
    }
}

/// Shown length of a unit of a line's coordinate: L along x, μL along y, the half-diagonal
/// L √(1 + μ²) along the diagonal (in m; 1 for a dimensionless scene, whose coordinates are
/// s, t and the fraction of the half-diagonal).
fn line_length(line: &str, units: &Units) -> f64 {
    let mu = units.mu();
    if !units.is_physical() {
        return 1.0;
    }
    match line {
        "x-axis" | "edge-x" => units.from_l(1.0),
        "y-axis" | "edge-y" => units.from_l(mu),
        "diagonal" => units.from_l((1.0 + mu * mu).sqrt()),
        _ => 1.0,
    }
}

/// The coordinate along a line, as an axis description.
pub(super) fn line_coordinate(line: &str) -> &'static str {
    match line {
        "diagonal" => "fraction of the half-diagonal",
        "y-axis" | "edge-y" => "t",
        _ => "s",
    }
}

/// One curve: a line's points in one colour.
pub(super) struct Line<'a> {
    pub(super) label: String,
    pub(super) colour: RGBColor,
    pub(super) dashed: bool,
    /// Shown position per unit of the points' coordinate.
    pub(super) length: f64,
    pub(super) points: &'a [ProfilePoint],
}

/// One column of panels (V above σ).
pub(super) struct Column<'a> {
    /// Caption above each of its panels.
    pub(super) caption: Option<String>,
    /// Description of the x axis.
    pub(super) x_desc: String,
    pub(super) lines: Vec<Line<'a>>,
}

/// Sizes and fonts of one of the two looks.
struct Look {
    size: (u32, u32),
    margin: u32,
    caption_font: u32,
    x_area: u32,
    /// Width of the y label area of the first column and of the others (no description).
    y_area: (u32, u32),
    label_font: u32,
    desc_font: u32,
    light_lines: usize,
    x_labels: usize,
    y_labels: usize,
}

/// The profile chart: columns of V and σ panels (or w and pressure) over the coordinate range
/// `x`.
pub(super) struct ProfileChart<'a> {
    pub(super) title: &'a str,
    /// Range of the points' own coordinate drawn.
    pub(super) coords: (f64, f64),
    /// Range of the x axis, shown units.
    pub(super) x: (f64, f64),
    pub(super) columns: Vec<Column<'a>>,
    /// How values are shown.
    pub(super) units: Units,
}

/// V and σ axis descriptions (on the first column).
const V_DESC: &str = "V = D w / (P L²), downward";
const SIGMA_DESC: &str = "σ = μ L² r / P";

impl ProfileChart<'_> {
    fn look(&self) -> Look {
        let n = self.columns.len() as u32;
        if n <= 1 {
            Look {
                size: (800, 900),
                margin: 12,
                caption_font: 16,
                x_area: 45,
                y_area: (80, 80),
                label_font: LABEL_FONT,
                desc_font: DESC_FONT,
                light_lines: 4,
                x_labels: 11,
                y_labels: 11,
            }
        } else {
            Look {
                size: (300 * n + 60, 760),
                margin: 8,
                caption_font: 15,
                x_area: 36,
                y_area: (62, 48),
                label_font: 12,
                desc_font: 13,
                light_lines: 2,
                x_labels: 6,
                y_labels: 8,
            }
        }
    }

    /// Finite (position, value) points of `line` inside the coordinate range, in shown units.
    fn points(&self, line: &Line<'_>, sigma: bool) -> Vec<(f64, f64)> {
        let (x0, x1) = self.coords;
        let u = &self.units;
        line.points
            .iter()
            .filter(|p| p.coord >= x0 - 1e-12 && p.coord <= x1 + 1e-12)
            .map(|p| {
                let value = if sigma {
                    u.from_sigma(p.sigma)
                } else {
                    u.from_v(p.v)
                };
                (p.coord * line.length, value)
            })
            .filter(|(c, v)| c.is_finite() && v.is_finite())
            .collect()
    }

    /// Value range of a row over every column, zero included.
    fn range(&self, sigma: bool) -> (f64, f64) {
        let values: Vec<f64> = self
            .columns
            .iter()
            .flat_map(|c| c.lines.iter())
            .flat_map(|l| self.points(l, sigma))
            .map(|p| p.1)
            .collect();
        padded_range(values.into_iter(), Some(0.0))
    }
}

impl Picture for ProfileChart<'_> {
    fn size(&self) -> (u32, u32) {
        self.look().size
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<()> {
        let body = titled(root, self.title)?;
        let look = self.look();
        let n = self.columns.len();
        if n == 0 {
            return Ok(());
        }
        let panels = body.split_evenly((2, n));
        let (v_lo, v_hi) = self.range(false);
        let (s_lo, s_hi) = self.range(true);
        let (x0, x1) = self.x;
        let x_fmt = tick_format(x0, x1);
        let v_fmt = tick_format(v_lo, v_hi);
        let s_fmt = tick_format(s_lo, s_hi);
        for (row, sigma) in [(0, false), (1, true)] {
            for (col, column) in self.columns.iter().enumerate() {
                let Some(area) = panels.get(row * n + col) else {
                    return Err("could not split the drawing area".into());
                };
                // V is drawn downward: its range runs from the largest V at the bottom.
                let (lo, hi) = if sigma { (s_lo, s_hi) } else { (v_hi, v_lo) };
                let mut builder = ChartBuilder::on(area);
                builder.margin(look.margin);
                if let Some(caption) = &column.caption {
                    builder.caption(caption, (FONT, look.caption_font));
                }
                let y_area = if col == 0 {
                    look.y_area.0
                } else {
                    look.y_area.1
                };
                let mut chart = builder
                    .x_label_area_size(look.x_area)
                    .y_label_area_size(y_area)
                    .build_cartesian_2d(x0..x1, lo..hi)
                    .map_err(txt)?;
                let mut mesh = chart.configure_mesh();
                mesh.x_desc(column.x_desc.as_str())
                    .x_label_formatter(&x_fmt)
                    .y_label_formatter(if sigma { &s_fmt } else { &v_fmt })
                    .label_style((FONT, look.label_font))
                    .axis_desc_style((FONT, look.desc_font))
                    .bold_line_style(style::GRID_MAJOR)
                    .light_line_style(style::GRID_MINOR)
                    .max_light_lines(look.light_lines)
                    .x_labels(look.x_labels)
                    .y_labels(look.y_labels);
                if col == 0 {
                    let (w_desc, pressure_desc) = (
                        format!("deflection w ({}), downward", self.units.deflection().unit),
                        format!("contact pressure ({})", self.units.pressure().unit),
                    );
                    mesh.y_desc(match (sigma, self.units.is_physical()) {
                        (true, false) => SIGMA_DESC,
                        (false, false) => V_DESC,
                        (true, true) => pressure_desc.as_str(),
                        (false, true) => w_desc.as_str(),
                    });
                }
                mesh.draw().map_err(txt)?;
                chart
                    .draw_series(LineSeries::new(
                        [(x0, 0.0), (x1, 0.0)],
                        style::REFERENCE.stroke_width(1),
                    ))
                    .map_err(txt)?;
                let legend = row == 1 && col == 0;
                for line in &column.lines {
                    let pts = self.points(line, sigma);
                    let stroke = line.colour.stroke_width(LINE_WIDTH);
                    // A profile across an opening is drawn in runs, broken where it has no
                    // points; the first run, drawn last, carries the legend's label.
                    let mut runs = runs(pts);
                    let first = if runs.is_empty() {
                        Vec::new()
                    } else {
                        runs.remove(0)
                    };
                    let (dash, gap) = style::DASH;
                    for rest in runs {
                        if line.dashed {
                            chart
                                .draw_series(DashedLineSeries::new(rest, dash, gap, stroke))
                                .map_err(txt)?;
                        } else {
                            chart
                                .draw_series(LineSeries::new(rest, stroke))
                                .map_err(txt)?;
                        }
                    }
                    let drawn = if line.dashed {
                        chart
                            .draw_series(DashedLineSeries::new(first, dash, gap, stroke))
                            .map_err(txt)?
                    } else {
                        chart
                            .draw_series(LineSeries::new(first, stroke))
                            .map_err(txt)?
                    };
                    if legend {
                        // A 24-pixel sample of two strokes: a gap between them if dashed.
                        let gap = if line.dashed { 6 } else { 0 };
                        drawn.label(line.label.as_str()).legend(move |(x, y)| {
                            EmptyElement::at((x, y))
                                + PathElement::new([(0, 0), (9, 0)], stroke)
                                + PathElement::new([(9 + gap, 0), (24, 0)], stroke)
                        });
                    }
                }
                if legend && !column.lines.is_empty() {
                    chart
                        .configure_series_labels()
                        .position(SeriesLabelPosition::UpperRight)
                        .label_font((FONT, look.label_font))
                        .background_style(style::BOX_FILL)
                        .border_style(style::BOX_BORDER)
                        .draw()
                        .map_err(txt)?;
                }
            }
        }
        Ok(())
    }
}

/// Write the deflection and pressure profiles of one solve along the paper's lines as an SVG
/// figure like the paper's Figs. 3–5, in `units`.
///
/// Dimensionless scene: the top panel shows V = D w / (P L²) against the line coordinate
/// ∈ [−1, 1] (s, t, or the fraction of the half-diagonal) with the V axis pointing down
/// (positive V is a downward deflection), the bottom panel σ = μ L² r / P with a zero line.
/// Physical scene: the deflection w in mm (pointing down) and the contact pressure in kPa
/// against the position along the line from the plate's centre in m (x along x-lines, y along
/// y-lines, the distance along the diagonal). Each [`Profile`] is one coloured series, named in
/// the legend. Empty profiles (or an empty slice) give empty axes. Non-finite points are
/// skipped.
///
/// # Errors
/// [`crate::Error::Io`] if the file cannot be written or drawing fails.
pub fn write_profiles_svg(
    path: &Path,
    profiles: &[Profile],
    title: &str,
    units: &Units,
) -> Result<()> {
    let lines: Vec<Line<'_>> = profiles
        .iter()
        .enumerate()
        .map(|(k, p)| Line {
            label: line_label(p.line, units),
            colour: style::series_colour(k),
            dashed: false,
            length: line_length(p.line, units),
            points: &p.points,
        })
        .collect();
    let (x, x_desc) = if units.is_physical() {
        let half = lines.iter().map(|l| l.length).fold(0.0_f64, f64::max);
        let half = if half > 0.0 && half.is_finite() {
            half
        } else {
            1.0
        };
        (
            (-half, half),
            format!(
                "x, y or distance along the diagonal, from the centre ({})",
                units.length().unit
            ),
        )
    } else {
        ((-1.0, 1.0), "s, t or diagonal fraction".to_string())
    };
    let chart = ProfileChart {
        title,
        coords: (-1.0, 1.0),
        x,
        columns: vec![Column {
            caption: None,
            x_desc,
            lines,
        }],
        units: *units,
    };
    write_svg(path, &chart)
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    /// Five lines of made-up profiles (shared with the comparison chart's test).
    pub(in crate::output::chart) fn profiles() -> Vec<Profile> {
        let names = ["x-axis", "y-axis", "edge-x", "edge-y", "diagonal"];
        names
            .iter()
            .enumerate()
            .map(|(k, &line)| Profile {
                line,
                points: (0..21)
                    .map(|m| {
                        let c = -1.0 + m as f64 / 10.0;
                        ProfilePoint {
                            coord: c,
                            s: c,
                            t: 0.0,
                            v: 0.1 * (1.0 - c * c) - 0.01 * k as f64,
                            sigma: (1.0 - c * c - 0.2 * k as f64).max(0.0),
                        }
                    })
                    .collect(),
            })
            .collect()
    }

    fn unitless() -> Units {
        Units::dimensionless(0.5)
    }

    /// L = 6 m, μ = 2/3, P = 100 kN, D = 20 MN·m: w = 180 V mm, r = 4.1667 σ kPa (see
    /// `units.rs`).
    fn slab() -> Units {
        Units::new(
            Some(crate::model::Physical {
                half_length: 6.0,
                force: 1e5,
                rigidity: 2e7,
                units: crate::units::UnitSystem::Si,
            }),
            2.0 / 3.0,
        )
    }

    /// Physical profiles: axes in m, mm and kPa, edges named by their position, and the points
    /// converted: the diagonal's end at L √(1 + μ²) = 2 √13 m, its σ = 1 at the centre shown as
    /// 1e5 / 24 Pa = 4.1667 kPa.
    #[test]
    fn physical_profiles_are_drawn_in_metres_mm_and_kpa() {
        let dir = tempfile::tempdir().expect("tempdir");
        let path = dir.path().join("p.svg");
        let u = slab();
        write_profiles_svg(&path, &profiles(), "physical", &u).expect("write");
        let text = std::fs::read_to_string(&path).expect("read");
        for needle in [
            "deflection w (mm), downward",
            "contact pressure (kPa)",
            "edge-x (y = 4 m)",
            "edge-y (x = 6 m)",
            "from the centre (m)",
        ] {
            assert!(text.contains(needle), "physical profiles lack {needle:?}");
        }
        let p = profiles();
        let line = Line {
            label: String::new(),
            colour: style::SERIES[0],
            dashed: false,
            length: line_length("diagonal", &u),
            points: &p[4].points,
        };
        let chart = ProfileChart {
            title: "",
            coords: (-1.0, 1.0),
            x: (-1.0, 1.0),
            columns: Vec::new(),
            units: u,
        };
        let pts = chart.points(&line, true);
        let end = 2.0 * 13.0_f64.sqrt();
        assert!(
            (pts[20].0 - end).abs() < 1e-12,
            "diagonal end {}",
            pts[20].0
        );
        // σ at the centre of the diagonal profile: (1 − 0 − 0.8)⁺ = 0.2 → 0.2 · 1e5 / 24 Pa.
        let want = 0.2 * 1e5 / 24.0 * 1e-3;
        assert!((pts[10].1 - want).abs() < 1e-12, "{} vs {want}", pts[10].1);
        let v = chart.points(&line, false);
        // V at the centre: 0.1 − 0.04 = 0.06 → 180 · 0.06 mm.
        assert!((v[10].1 - 10.8).abs() < 1e-12, "{}", v[10].1);
    }

    #[test]
    fn profiles_svg_is_written() {
        let dir = tempfile::tempdir().expect("tempdir");
        let path = dir.path().join("profiles.svg");
        write_profiles_svg(&path, &profiles(), "Profiles test title", &unitless()).expect("write");
        let text = std::fs::read_to_string(&path).expect("read");
        assert!(text.contains("<svg"));
        assert!(text.contains("Profiles test title"));
        assert!(text.contains("edge-y (s = 1)"));
    }

    #[test]
    fn profiles_svg_handles_degenerate_input() {
        let dir = tempfile::tempdir().expect("tempdir");
        let empty = dir.path().join("empty.svg");
        write_profiles_svg(&empty, &[], "empty", &unitless()).expect("no profiles");
        assert!(std::fs::metadata(&empty).expect("meta").len() > 0);

        let flat = vec![
            Profile {
                line: "x-axis",
                points: vec![],
            },
            Profile {
                line: "y-axis",
                points: (0..5)
                    .map(|m| ProfilePoint {
                        coord: -1.0 + 0.5 * m as f64,
                        s: 0.0,
                        t: 0.0,
                        v: 0.0,
                        sigma: 0.0,
                    })
                    .collect(),
            },
        ];
        let path = dir.path().join("flat.svg");
        write_profiles_svg(&path, &flat, "flat", &unitless()).expect("flat profiles");
        assert!(std::fs::read_to_string(&path)
            .expect("read")
            .contains("<svg"));
    }

    #[test]
    fn half_lines_keep_coordinates_from_zero() {
        let p = profiles();
        let chart = ProfileChart {
            title: "",
            coords: (0.0, 1.0),
            x: (0.0, 1.0),
            columns: Vec::new(),
            units: Units::dimensionless(1.0),
        };
        let line = Line {
            label: String::new(),
            colour: style::SERIES[0],
            dashed: false,
            length: 1.0,
            points: &p[0].points,
        };
        let pts = chart.points(&line, true);
        // Coordinates −1, −0.9, …, 1: the eleven from 0 on.
        assert_eq!(pts.len(), 11);
        assert!(pts.iter().all(|&(c, _)| (0.0..=1.0).contains(&c)));
        assert_eq!(pts[0], (0.0, 1.0), "σ at the centre of the x-axis profile");
    }
}
