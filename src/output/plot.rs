//! Charts: profiles of V and σ along the paper's lines (SVG) and the contact-pressure map
//! (SVG and PNG).
//!
//! Text is laid out with an embedded copy of DejaVu Sans (`assets/DejaVuSans.ttf`, Bitstream
//! Vera licence, see `assets/DejaVuSans-LICENSE.txt`), registered once with plotters as
//! `"sans-serif"`, so the charts render identically on machines without system fonts.

use std::path::Path;
use std::sync::OnceLock;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::FontStyle;

use crate::error::{Error, Result};
use crate::post::{FullField, Profile, CONTACT_THRESHOLD};

/// The embedded font.
static FONT_BYTES: &[u8] = include_bytes!("../../assets/DejaVuSans.ttf");

/// Font family name under which the embedded font is registered.
pub(crate) const FONT: &str = "sans-serif";

/// Size of the profile figure, pixels.
const PROFILE_SIZE: (u32, u32) = (800, 900);

/// Size of the contact map (SVG and PNG), pixels.
const MAP_SIZE: (u32, u32) = (900, 700);

/// Colours of the profile lines, in the order of [`crate::post::profiles`].
const LINE_COLOURS: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
];

/// Colour of lifted cells.
const LIFTED: RGBColor = RGBColor(215, 215, 215);

/// Colour of the contact boundary.
const BOUNDARY: RGBColor = RGBColor(20, 20, 20);

/// Sequential colour map (ColorBrewer YlOrRd without its palest class), low to high.
const RAMP: [(u8, u8, u8); 8] = [
    (255, 237, 160),
    (254, 217, 118),
    (254, 178, 76),
    (253, 141, 60),
    (252, 78, 42),
    (227, 26, 28),
    (189, 0, 38),
    (128, 0, 38),
];

/// Register the embedded font with plotters once; later calls return the first outcome.
pub(crate) fn ensure_font(path: &Path) -> Result<()> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        plotters::style::register_font(FONT, FontStyle::Normal, FONT_BYTES).is_ok()
    });
    if ok {
        Ok(())
    } else {
        Err(Error::Io {
            path: path.display().to_string(),
            source: std::io::Error::other("the embedded font DejaVuSans.ttf could not be loaded"),
        })
    }
}

/// Wrap a plotting-library failure as an I/O error on `path`.
pub(crate) fn plot_error(path: &Path, e: impl std::fmt::Display) -> Error {
    Error::Io {
        path: path.display().to_string(),
        source: std::io::Error::other(e.to_string()),
    }
}

/// A drawing failure, as text (the backend error types differ between SVG and bitmap).
type DrawResult<T> = std::result::Result<T, String>;

/// Convert a plotters error into text.
pub(crate) fn txt<E: std::fmt::Display>(e: E) -> String {
    e.to_string()
}

/// Finite range of `values` including `always` (if given), padded by 5 % on both sides and
/// never empty.
fn padded_range(values: impl Iterator<Item = f64>, always: Option<f64>) -> (f64, f64) {
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    for v in values.chain(always).filter(|v| v.is_finite()) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !lo.is_finite() || !hi.is_finite() {
        return (-1.0, 1.0);
    }
    let span = hi - lo;
    if span <= 1e-12 * hi.abs().max(lo.abs()).max(1e-300) {
        let d = if hi.abs() > 0.0 { 0.1 * hi.abs() } else { 1.0 };
        return (lo - d, hi + d);
    }
    (lo - 0.05 * span, hi + 0.05 * span)
}

/// Tick-label formatter for an axis spanning `lo`..`hi`: enough decimals for about ten ticks,
/// trailing zeros dropped, no "-0", scientific notation for very small or large magnitudes.
pub(crate) fn tick_format(lo: f64, hi: f64) -> impl Fn(&f64) -> String {
    let span = (hi - lo).abs();
    let mag = lo.abs().max(hi.abs());
    let step = if span > 0.0 && span.is_finite() {
        span / 10.0
    } else {
        1.0
    };
    let decimals = ((-step.log10()).ceil() as i32 + 1).clamp(0, 8) as usize;
    move |v: &f64| {
        let v = *v;
        if !v.is_finite() {
            return String::new();
        }
        if v.abs() <= 1e-9 * span.max(f64::MIN_POSITIVE) {
            return "0".to_string();
        }
        if !(1e-3..1e5).contains(&mag) {
            return format!("{v:.2e}");
        }
        let text = format!("{v:.decimals$}");
        let text = if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            text
        };
        if text == "-0" {
            "0".to_string()
        } else {
            text
        }
    }
}

/// Legend text of a profile line.
fn line_label(line: &str) -> String {
    match line {
        "x-axis" => "x-axis (t = 0)".to_string(),
        "y-axis" => "y-axis (s = 0)".to_string(),
        "edge-x" => "edge-x (t = 1)".to_string(),
        "edge-y" => "edge-y (s = 1)".to_string(),
        other => other.to_string(),
    }
}

/// Finite (coord, value) pairs of a profile.
fn series(profile: &Profile, value: fn(&crate::post::ProfilePoint) -> f64) -> Vec<(f64, f64)> {
    profile
        .points
        .iter()
        .map(|p| (p.coord, value(p)))
        .filter(|(c, v)| c.is_finite() && v.is_finite())
        .collect()
}

/// Caption font size that fits `title` on one line of a `width`-pixel chart (DejaVu Sans
/// averages about 0.56 em per character), between 10 and 24 px.
pub(crate) fn caption_size(title: &str, width: u32) -> u32 {
    let chars = title.chars().count().max(1) as f64;
    (0.92 * f64::from(width) / (0.56 * chars)).clamp(10.0, 24.0) as u32
}

/// Write the deflection and pressure profiles along the paper's lines as an SVG figure like
/// the paper's Figs. 3–5.
///
/// The top panel shows V = D w / (P L²) against the line coordinate ∈ [−1, 1] with the V axis
/// pointing down (positive V is a downward deflection), the bottom panel σ = μ L² r / P with a
/// zero line; each [`Profile`] is one coloured series, named in the legend. Empty profiles (or
/// an empty slice) give empty axes. Non-finite points are skipped.
///
/// # Errors
/// [`Error::Io`] if the file cannot be written or drawing fails.
pub fn write_profiles_svg(path: &Path, profiles: &[Profile], title: &str) -> Result<()> {
    ensure_font(path)?;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, PROFILE_SIZE).into_drawing_area();
        draw_profiles(&root, profiles, title).map_err(|e| plot_error(path, e))?;
        root.present().map_err(|e| plot_error(path, e))?;
    }
    std::fs::write(path, svg).map_err(|source| Error::Io {
        path: path.display().to_string(),
        source,
    })
}

/// Draw the two profile panels on `root`.
fn draw_profiles<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    profiles: &[Profile],
    title: &str,
) -> DrawResult<()> {
    root.fill(&WHITE).map_err(txt)?;
    let body = root
        .titled(title, (FONT, caption_size(title, root.dim_in_pixel().0)))
        .map_err(txt)?;
    let panels = body.split_evenly((2, 1));
    let (Some(top), Some(bottom)) = (panels.first(), panels.get(1)) else {
        return Err("could not split the drawing area".to_string());
    };

    let v_of = |p: &crate::post::ProfilePoint| p.v;
    let s_of = |p: &crate::post::ProfilePoint| p.sigma;
    let all = |f: fn(&crate::post::ProfilePoint) -> f64| {
        profiles
            .iter()
            .flat_map(move |pr| pr.points.iter().map(f))
            .collect::<Vec<f64>>()
    };
    let (v_lo, v_hi) = padded_range(all(v_of).into_iter(), Some(0.0));
    let (s_lo, s_hi) = padded_range(all(s_of).into_iter(), Some(0.0));
    let x_desc = "s, t or diagonal fraction";
    let x_fmt = tick_format(-1.0, 1.0);
    let v_fmt = tick_format(v_lo, v_hi);
    let s_fmt = tick_format(s_lo, s_hi);

    // Top: V, drawn downward (range from the largest V at the bottom to the smallest at the top).
    let mut chart = ChartBuilder::on(top)
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(80)
        .build_cartesian_2d(-1.0..1.0, v_hi..v_lo)
        .map_err(txt)?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc("V = D w / (P L²)")
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&v_fmt)
        .label_style((FONT, 14))
        .axis_desc_style((FONT, 16))
        .light_line_style(RGBColor(235, 235, 235))
        .max_light_lines(4)
        .draw()
        .map_err(txt)?;
    chart
        .draw_series(LineSeries::new(
            [(-1.0, 0.0), (1.0, 0.0)],
            BLACK.mix(0.6).stroke_width(1),
        ))
        .map_err(txt)?;
    for (k, profile) in profiles.iter().enumerate() {
        let colour = LINE_COLOURS[k % LINE_COLOURS.len()];
        chart
            .draw_series(LineSeries::new(
                series(profile, v_of),
                colour.stroke_width(2),
            ))
            .map_err(txt)?;
    }

    // Bottom: σ with its zero line and the legend.
    let mut chart = ChartBuilder::on(bottom)
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(80)
        .build_cartesian_2d(-1.0..1.0, s_lo..s_hi)
        .map_err(txt)?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc("σ = μ L² r / P")
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&s_fmt)
        .label_style((FONT, 14))
        .axis_desc_style((FONT, 16))
        .light_line_style(RGBColor(235, 235, 235))
        .max_light_lines(4)
        .draw()
        .map_err(txt)?;
    chart
        .draw_series(LineSeries::new(
            [(-1.0, 0.0), (1.0, 0.0)],
            BLACK.mix(0.6).stroke_width(1),
        ))
        .map_err(txt)?;
    for (k, profile) in profiles.iter().enumerate() {
        let colour = LINE_COLOURS[k % LINE_COLOURS.len()];
        chart
            .draw_series(LineSeries::new(
                series(profile, s_of),
                colour.stroke_width(2),
            ))
            .map_err(txt)?
            .label(line_label(profile.line))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 24, y)], colour.stroke_width(2)));
    }
    if !profiles.is_empty() {
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .label_font((FONT, 14))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK.mix(0.5))
            .draw()
            .map_err(txt)?;
    }
    Ok(())
}

/// Write a filled colour map of the dimensionless contact pressure σ over the plate, once as SVG
/// (`svg`) and once as PNG (`png`, 900 × 700 pixels, drawn by the same code).
///
/// Each grid cell is a rectangle in physical (x, y) coordinates, drawn to equal scale, coloured
/// by the mean σ of its four nodes on a sequential yellow-to-red scale from 0 to the largest cell
/// mean (see the colour bar); lifted cells (mean σ ≤ 0, or no node in contact) are light grey.
/// The contact boundary, the level σ = [`CONTACT_THRESHOLD`] × max σ of the bilinear σ field
/// (marching squares), is drawn as a dark line, the plate outline as a thin one.
///
/// The PNG path must end in `.png` (the encoder is chosen by the extension).
///
/// # Errors
/// [`Error::Io`] if a file cannot be written or drawing fails, or if the arrays of `field` do
/// not all have (nx + 1)(ny + 1) entries.
pub fn write_contact_map(svg: &Path, png: &Path, field: &FullField, title: &str) -> Result<()> {
    ensure_font(svg)?;
    check_field(svg, field)?;

    let mut text = String::new();
    {
        let root = SVGBackend::with_string(&mut text, MAP_SIZE).into_drawing_area();
        draw_contact_map(&root, field, title).map_err(|e| plot_error(svg, e))?;
        root.present().map_err(|e| plot_error(svg, e))?;
    }
    std::fs::write(svg, text).map_err(|source| Error::Io {
        path: svg.display().to_string(),
        source,
    })?;

    let root = BitMapBackend::new(png, MAP_SIZE).into_drawing_area();
    draw_contact_map(&root, field, title).map_err(|e| plot_error(png, e))?;
    root.present().map_err(|e| plot_error(png, e))?;
    Ok(())
}

/// Check that every nodal array of `field` covers the grid.
fn check_field(path: &Path, field: &FullField) -> Result<()> {
    let n = field
        .nx
        .checked_add(1)
        .zip(field.ny.checked_add(1))
        .and_then(|(a, b)| a.checked_mul(b));
    let ok = n.is_some_and(|n| {
        field.x.len() == n
            && field.y.len() == n
            && field.sigma.len() == n
            && field.contact.len() == n
    });
    if ok {
        Ok(())
    } else {
        Err(Error::Io {
            path: path.display().to_string(),
            source: std::io::Error::new(
                std::io::ErrorKind::InvalidInput,
                format!(
                    "field arrays do not match the {} × {} element grid",
                    field.nx, field.ny
                ),
            ),
        })
    }
}

/// Colour of the normalised value `f` ∈ [0, 1] on [`RAMP`].
fn ramp(f: f64) -> RGBColor {
    let f = if f.is_finite() {
        f.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let pos = f * (RAMP.len() - 1) as f64;
    let k = (pos.floor() as usize).min(RAMP.len() - 2);
    let a = pos - k as f64;
    let (r0, g0, b0) = RAMP[k];
    let (r1, g1, b1) = RAMP[k + 1];
    let mix = |u: u8, v: u8| (f64::from(u) * (1.0 - a) + f64::from(v) * a).round() as u8;
    RGBColor(mix(r0, r1), mix(g0, g1), mix(b0, b1))
}

/// One cell of the map: its corner node indices (counter-clockwise from (i, j)).
fn cell_nodes(field: &FullField, i: usize, j: usize) -> [usize; 4] {
    let n = field.nx + 1;
    [
        i + j * n,
        i + 1 + j * n,
        i + 1 + (j + 1) * n,
        i + (j + 1) * n,
    ]
}

/// Segments of the level set σ = `level` of the bilinear σ field, by marching squares.
pub(crate) fn contour(field: &FullField, level: f64) -> Vec<[(f64, f64); 2]> {
    let mut segments = Vec::new();
    for j in 0..field.ny {
        for i in 0..field.nx {
            let c = cell_nodes(field, i, j);
            let f = c.map(|k| field.sigma[k] - level);
            let inside = f.map(|v| v > 0.0);
            // Crossing point on edge e (between corners e and e + 1), if any.
            let cross = |e: usize| -> Option<(f64, f64)> {
                let (a, b) = (e, (e + 1) % 4);
                if inside[a] == inside[b] {
                    return None;
                }
                // Signs differ, so f[a] − f[b] ≠ 0.
                let t = (f[a] / (f[a] - f[b])).clamp(0.0, 1.0);
                let (na, nb) = (c[a], c[b]);
                Some((
                    field.x[na] + t * (field.x[nb] - field.x[na]),
                    field.y[na] + t * (field.y[nb] - field.y[na]),
                ))
            };
            let edges: Vec<(usize, (f64, f64))> =
                (0..4).filter_map(|e| cross(e).map(|p| (e, p))).collect();
            match edges.as_slice() {
                [(_, p), (_, q)] => segments.push([*p, *q]),
                [_, _, _, _] => {
                    // Saddle: cut off the corners whose state differs from the cell centre.
                    let centre = f.iter().sum::<f64>() / 4.0 > 0.0;
                    for (k, &corner) in inside.iter().enumerate() {
                        if corner != centre {
                            let before = (k + 3) % 4;
                            if let (Some(p), Some(q)) = (cross(before), cross(k)) {
                                segments.push([p, q]);
                            }
                        }
                    }
                }
                _ => {}
            }
        }
    }
    segments
}

/// Draw the contact map on `root`.
fn draw_contact_map<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    field: &FullField,
    title: &str,
) -> DrawResult<()> {
    root.fill(&WHITE).map_err(txt)?;
    let body = root
        .titled(title, (FONT, caption_size(title, root.dim_in_pixel().0)))
        .map_err(txt)?;
    let (body_w, _) = body.dim_in_pixel();
    let bar_w = 130_u32.min(body_w / 3);
    let (map_area, bar_area) = body.split_horizontally(body_w.saturating_sub(bar_w));

    // Cells: mean σ and whether lifted.
    let mut cells = Vec::with_capacity(field.nx * field.ny);
    for j in 0..field.ny {
        for i in 0..field.nx {
            let c = cell_nodes(field, i, j);
            let mean = c.iter().map(|&k| field.sigma[k]).sum::<f64>() / 4.0;
            let lifted = mean.is_nan() || mean <= 0.0 || c.iter().all(|&k| !field.contact[k]);
            cells.push((c, mean, lifted));
        }
    }
    let top = cells
        .iter()
        .filter(|(_, m, lifted)| !lifted && m.is_finite())
        .map(|(_, m, _)| *m)
        .fold(0.0_f64, f64::max);
    let scale = if top > 0.0 { top } else { 1.0 };

    // Plate extent.
    let finite = |v: &[f64]| -> (f64, f64) {
        let (lo, hi) = v
            .iter()
            .filter(|a| a.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &a| {
                (l.min(a), h.max(a))
            });
        if lo.is_finite() && hi > lo {
            (lo, hi)
        } else if lo.is_finite() {
            (lo - 1.0, lo + 1.0)
        } else {
            (-1.0, 1.0)
        }
    };
    let (x0, x1) = finite(&field.x);
    let (y0, y1) = finite(&field.y);

    // Margins giving equal scales on x and y.
    let (margin, x_lab, y_lab) = (15_i32, 50_i32, 70_i32);
    let (aw, ah) = map_area.dim_in_pixel();
    let avail_w = (aw as i32 - 2 * margin - y_lab).max(10) as f64;
    let avail_h = (ah as i32 - 2 * margin - x_lab).max(10) as f64;
    let px = (avail_w / (x1 - x0)).min(avail_h / (y1 - y0));
    let extra_w = ((avail_w - px * (x1 - x0)) / 2.0).max(0.0) as i32;
    let extra_h = ((avail_h - px * (y1 - y0)) / 2.0).max(0.0) as i32;

    let x_fmt = tick_format(x0, x1);
    let y_fmt = tick_format(y0, y1);
    let bar_fmt = tick_format(0.0, scale);
    let mut chart = ChartBuilder::on(&map_area)
        .margin_left(margin + extra_w)
        .margin_right(margin + extra_w)
        .margin_top(margin + extra_h)
        .margin_bottom(margin + extra_h)
        .x_label_area_size(x_lab)
        .y_label_area_size(y_lab)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(txt)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc("x")
        .y_desc("y")
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .label_style((FONT, 14))
        .axis_desc_style((FONT, 16))
        .draw()
        .map_err(txt)?;

    chart
        .draw_series(cells.iter().map(|&(c, mean, lifted)| {
            let colour = if lifted { LIFTED } else { ramp(mean / scale) };
            Rectangle::new(
                [
                    (field.x[c[0]], field.y[c[0]]),
                    (field.x[c[2]], field.y[c[2]]),
                ],
                colour.filled(),
            )
        }))
        .map_err(txt)?;

    // Contact boundary.
    let peak = field
        .sigma
        .iter()
        .cloned()
        .filter(|v| v.is_finite())
        .fold(0.0_f64, f64::max);
    if peak > 0.0 {
        let segments = contour(field, CONTACT_THRESHOLD * peak);
        chart
            .draw_series(
                segments
                    .into_iter()
                    .map(|s| PathElement::new(s, BOUNDARY.stroke_width(2))),
            )
            .map_err(txt)?;
    }
    // Plate outline.
    chart
        .draw_series(std::iter::once(PathElement::new(
            [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)],
            BLACK.mix(0.7).stroke_width(1),
        )))
        .map_err(txt)?;

    // Colour bar.
    let mut bar = ChartBuilder::on(&bar_area)
        .margin_top(margin + extra_h.min(ah as i32 / 4))
        .margin_bottom(margin + extra_h.min(ah as i32 / 4) + x_lab)
        .margin_left(10)
        .margin_right(5)
        .right_y_label_area_size(75)
        .build_cartesian_2d(0.0..1.0, 0.0..scale)
        .map_err(txt)?;
    bar.configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_label_formatter(&bar_fmt)
        .label_style((FONT, 14))
        .axis_desc_style((FONT, 16))
        .draw()
        .map_err(txt)?;
    let steps = 100;
    bar.draw_series((0..steps).map(|k| {
        let a = k as f64 / steps as f64;
        let b = (k + 1) as f64 / steps as f64;
        Rectangle::new(
            [(0.0, a * scale), (1.0, b * scale)],
            ramp((a + b) / 2.0).filled(),
        )
    }))
    .map_err(txt)?;
    bar.draw_series(std::iter::once(Rectangle::new(
        [(0.0, 0.0), (1.0, scale)],
        BLACK.mix(0.7).stroke_width(1),
    )))
    .map_err(txt)?;
    // Bar caption, centred above the bar.
    let (bar_x, bar_y) = bar.plotting_area().get_pixel_range();
    let style = TextStyle::from((FONT, 18).into_font()).pos(Pos::new(HPos::Center, VPos::Bottom));
    root.draw_text(
        "σ",
        &style,
        ((bar_x.start + bar_x.end) / 2, bar_y.start - 6),
    )
    .map_err(txt)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::post::ProfilePoint;

    /// The shared 4 × 2 test plate without its element field.
    fn bump_field() -> FullField {
        crate::post::test_fixtures::bump().0
    }

    fn profiles() -> Vec<Profile> {
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

    #[test]
    fn profiles_svg_is_written() {
        let dir = tempfile::tempdir().expect("tempdir");
        let path = dir.path().join("profiles.svg");
        write_profiles_svg(&path, &profiles(), "Profiles test title").expect("write");
        let text = std::fs::read_to_string(&path).expect("read");
        assert!(text.contains("<svg"));
        assert!(text.contains("Profiles test title"));
        assert!(text.contains("edge-y (s = 1)"));
    }

    #[test]
    fn profiles_svg_handles_degenerate_input() {
        let dir = tempfile::tempdir().expect("tempdir");
        let empty = dir.path().join("empty.svg");
        write_profiles_svg(&empty, &[], "empty").expect("no profiles");
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
        write_profiles_svg(&path, &flat, "flat").expect("flat profiles");
        assert!(std::fs::read_to_string(&path)
            .expect("read")
            .contains("<svg"));
    }

    #[test]
    fn contact_map_is_written() {
        let dir = tempfile::tempdir().expect("tempdir");
        let svg = dir.path().join("contact.svg");
        let png = dir.path().join("contact.png");
        write_contact_map(&svg, &png, &bump_field(), "Contact map title").expect("write");
        let text = std::fs::read_to_string(&svg).expect("read svg");
        assert!(text.contains("<svg"));
        assert!(text.contains("Contact map title"));
        let bytes = std::fs::read(&png).expect("read png");
        assert!(bytes.starts_with(&[0x89, b'P', b'N', b'G', 0x0D, 0x0A, 0x1A, 0x0A]));
    }

    #[test]
    fn contact_map_handles_degenerate_input() {
        let dir = tempfile::tempdir().expect("tempdir");
        let svg = dir.path().join("c.svg");
        let png = dir.path().join("c.png");

        // All σ zero, nothing in contact.
        let mut f = bump_field();
        f.sigma.iter_mut().for_each(|s| *s = 0.0);
        f.contact.iter_mut().for_each(|c| *c = false);
        write_contact_map(&svg, &png, &f, "zero").expect("all zero");

        // All σ equal and in contact.
        f.sigma.iter_mut().for_each(|s| *s = 0.5);
        f.contact.iter_mut().for_each(|c| *c = true);
        write_contact_map(&svg, &png, &f, "uniform").expect("uniform");

        // Inconsistent arrays: an error, not a panic.
        f.sigma.pop();
        assert!(write_contact_map(&svg, &png, &f, "bad").is_err());

        // No cells at all.
        let mut g = bump_field();
        g.nx = 0;
        g.ny = 0;
        for v in [&mut g.x, &mut g.y, &mut g.sigma] {
            v.truncate(1);
        }
        g.contact.truncate(1);
        write_contact_map(&svg, &png, &g, "point").expect("single node");
    }

    #[test]
    fn contour_crosses_between_nodes() {
        let f = bump_field();
        let segs = contour(&f, 0.01);
        assert!(!segs.is_empty());
        for [p, q] in segs {
            for (x, y) in [p, q] {
                assert!((-2.0..=2.0).contains(&x) && (-1.0..=1.0).contains(&y));
            }
        }
    }
}
