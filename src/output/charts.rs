//! Summary charts of parameter studies: log–log convergence charts with free-text notes, and
//! categorical maps of run outcomes over a parameter grid (SVG). The fit and the Pareto front
//! that go with them are in [`crate::metrics`].
//!
//! Text uses the embedded font registered by [`super::plot`], so the charts render the same
//! on machines without system fonts.

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::plot::{caption_size, ensure_font, plot_error, FONT};
use crate::error::{Error, Result};

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

/// Size of the log–log chart, pixels.
const LOGLOG_SIZE: (u32, u32) = (900, 650);

/// Series colours (the Tableau 10 palette), cycled in series order.
const SERIES_COLOURS: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

/// Fixed colours of the known run categories, in legend order.
const CATEGORY_COLOURS: [(&str, RGBColor); 9] = [
    ("converged", RGBColor(44, 160, 44)),
    ("cycling", RGBColor(255, 140, 0)),
    ("iteration-limit", RGBColor(220, 40, 40)),
    ("penalty-too-weak", RGBColor(140, 90, 190)),
    ("solver-failure", RGBColor(130, 10, 20)),
    ("infeasible", RGBColor(128, 128, 128)),
    ("too-large", RGBColor(205, 205, 205)),
    ("numerical", RGBColor(75, 50, 35)),
    ("not-run", RGBColor(255, 255, 255)),
];

/// Colours for categories not in [`CATEGORY_COLOURS`], chosen by a hash of the name.
const EXTRA_COLOURS: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(23, 190, 207),
    RGBColor(227, 119, 194),
    RGBColor(188, 189, 34),
    RGBColor(57, 59, 121),
    RGBColor(0, 128, 128),
    RGBColor(231, 186, 82),
    RGBColor(158, 202, 225),
    RGBColor(206, 109, 189),
    RGBColor(99, 121, 57),
];

/// Border colour of "not-run" cells and of the legend swatches.
const CELL_BORDER: RGBColor = RGBColor(150, 150, 150);

/// Colour of the major grid lines of the log–log chart.
const GRID_BOLD: RGBColor = RGBColor(215, 215, 215);

/// Colour of the minor grid lines of the log–log chart.
const GRID_LIGHT: RGBColor = RGBColor(240, 240, 240);

/// A drawing failure, as text (the backend error types differ between SVG and bitmap).
type DrawResult<T> = std::result::Result<T, String>;

/// Convert a plotters error into text.
fn txt<E: std::fmt::Display>(e: E) -> String {
    e.to_string()
}

/// Write `text` (an SVG document) to `path`.
fn write_file(path: &Path, text: String) -> Result<()> {
    std::fs::write(path, text).map_err(|source| Error::Io {
        path: path.display().to_string(),
        source,
    })
}

/// Whether (x, y) can be drawn on log–log axes.
fn valid_log_point(x: f64, y: f64) -> bool {
    x.is_finite() && y.is_finite() && x > 0.0 && y > 0.0
}

// ---------------------------------------------------------------------------------------------
// Log–log chart
// ---------------------------------------------------------------------------------------------

/// Log–log chart (both axes logarithmic) of several series with a legend and free-text notes
/// (e.g. "fitted slope 1.01") written in a box in the chart's upper-left corner.
/// Points with non-finite or non-positive coordinates are skipped; axis ranges fit the
/// remaining points with a small margin (at least one decade each); empty input draws empty
/// axes with the title. `reverse_x` draws x decreasing to the right (useful for ε̄ going to 0).
///
/// The chart is 900 × 650 pixels. Series are coloured in order from a ten-colour palette and
/// get different marker shapes (circle, triangle, square, diamond, cross); lines join the valid
/// points in the given order. The legend lists the series with non-empty names and is placed
/// in the corner (other than the notes' corner) that hides the fewest data. Ticks are labelled
/// at decades (also at 2 and 5 × 10ⁿ when the axis spans few decades), as plain numbers from
/// 0.01 to 1000 and as powers of ten otherwise.
///
/// # Errors
/// [`Error::Io`] if the file cannot be written or drawing fails.
pub fn write_loglog_svg(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series],
    notes: &[String],
    reverse_x: bool,
) -> Result<()> {
    ensure_font(path)?;
    let chart = LogLogChart {
        title,
        x_label,
        y_label,
        series,
        notes,
        reverse_x,
    };
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, LOGLOG_SIZE).into_drawing_area();
        draw_loglog(&root, &chart).map_err(|e| plot_error(path, e))?;
        root.present().map_err(|e| plot_error(path, e))?;
    }
    write_file(path, svg)
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

/// A logarithmic axis, in log10 units: the range and the major (labelled) and minor ticks.
#[derive(Debug, Clone, PartialEq)]
struct LogAxis {
    lo: f64,
    hi: f64,
    bold: Vec<f64>,
    light: Vec<f64>,
}

/// Axis for the log10 `values` (finite): their range with a 5 % margin, widened to at least one
/// decade and kept within 10⁻³⁰⁷ to 10³⁰⁸ (normal floating-point numbers); (0, 1) — 1 to 10 —
/// without values.
fn log_axis(values: impl Iterator<Item = f64>) -> LogAxis {
    let (mut lo, mut hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| {
            (l.min(v), h.max(v))
        });
    if !(lo.is_finite() && hi.is_finite()) {
        lo = 0.0;
        hi = 1.0;
    } else {
        let pad = 0.05 * (hi - lo);
        lo -= pad;
        hi += pad;
        if hi - lo < 1.0 {
            let centre = 0.5 * (lo + hi);
            lo = centre - 0.5;
            hi = centre + 0.5;
        }
        lo = lo.clamp(-307.0, 307.0);
        hi = hi.clamp(lo + 1.0, 308.0);
    }
    let span = hi - lo;
    let first = lo.ceil() as i64;
    let last = hi.floor() as i64;
    let decades = (last - first + 1).max(0);
    let step = if decades > 12 { (decades + 9) / 10 } else { 1 };
    let eps = 1e-9;
    let inside = |v: f64| v >= lo - eps && v <= hi + eps;
    let mut bold = Vec::new();
    let mut light = Vec::new();
    // One decade below the first full one, for the partial decade at the low end.
    for k in (first - 1)..=last {
        let kf = k as f64;
        if inside(kf) {
            if k.rem_euclid(step) == 0 {
                bold.push(kf);
            } else {
                light.push(kf);
            }
        }
        if span <= 8.0 {
            for m in 2..=9 {
                let v = kf + f64::from(m).log10();
                if !inside(v) {
                    continue;
                }
                if span <= 2.5 && (m == 2 || m == 5) {
                    bold.push(v);
                } else {
                    light.push(v);
                }
            }
        }
    }
    LogAxis {
        lo,
        hi,
        bold,
        light,
    }
}

/// `n` with superscript digits and minus sign.
fn superscript(n: i64) -> String {
    n.to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            '0' => '⁰',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            '4' => '⁴',
            '5' => '⁵',
            '6' => '⁶',
            '7' => '⁷',
            '8' => '⁸',
            '9' => '⁹',
            other => other,
        })
        .collect()
}

/// Whether every major tick of `axis` lies between 0.01 and 1000 (labels as plain numbers).
fn plain_labels(axis: &LogAxis) -> bool {
    axis.bold
        .iter()
        .all(|v| (-2.0..4.0).contains(&(v + 1e-9).floor()))
}

/// Tick label of the log10 value `v`: a plain number if `plain` (see [`plain_labels`]),
/// otherwise "10ⁿ" or "m×10ⁿ".
fn log_tick_label(v: f64, plain: bool) -> String {
    if !v.is_finite() {
        return String::new();
    }
    let k = (v + 1e-9).floor();
    let m = 10f64.powf(v - k).round().max(1.0);
    let (k, m) = if m >= 10.0 {
        (k as i64 + 1, 1)
    } else {
        (k as i64, m as i64)
    };
    if plain && (-2..=3).contains(&k) {
        let decimals = usize::try_from(-k).unwrap_or(0);
        format!("{:.*}", decimals, m as f64 * 10f64.powi(k as i32))
    } else if m == 1 {
        format!("10{}", superscript(k))
    } else {
        format!("{m}×10{}", superscript(k))
    }
}

/// Marker shapes, cycled in series order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Shape {
    Circle,
    Triangle,
    Square,
    Diamond,
    Cross,
}

/// The marker shape of series number `k`.
fn shape_of(k: usize) -> Shape {
    [
        Shape::Circle,
        Shape::Triangle,
        Shape::Square,
        Shape::Diamond,
        Shape::Cross,
    ][k % 5]
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
                let stroke = $colour.stroke_width(2);
                let $mk = |at| EmptyElement::at(at) + Cross::new((0, 0), 4, stroke);
                $body
            }
        }
    }};
}

/// An axis-aligned pixel rectangle: left, top, right, bottom.
type Rect = (i32, i32, i32, i32);

/// Whether two rectangles overlap.
fn overlaps(a: Rect, b: Rect) -> bool {
    a.0 < b.2 && b.0 < a.2 && a.1 < b.3 && b.1 < a.3
}

/// Draw a box (`rect`) with one line of text per entry of `lines`; `swatch`
/// reserves room left of each line and is called with the line's left-centre point.
fn draw_text_box<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    rect: Rect,
    lines: &[String],
    style: &TextStyle,
    line_h: i32,
    swatch_w: i32,
    mut swatch: impl FnMut(usize, (i32, i32)) -> DrawResult<()>,
) -> DrawResult<()> {
    let (x0, y0, x1, y1) = rect;
    root.draw(&Rectangle::new(
        [(x0, y0), (x1, y1)],
        WHITE.mix(0.9).filled(),
    ))
    .map_err(txt)?;
    root.draw(&Rectangle::new([(x0, y0), (x1, y1)], BLACK.mix(0.5)))
        .map_err(txt)?;
    let style = style.pos(Pos::new(HPos::Left, VPos::Center));
    for (k, line) in lines.iter().enumerate() {
        let cy = y0 + BOX_PAD + line_h * k as i32 + line_h / 2;
        let x = x0 + BOX_PAD;
        if swatch_w > 0 {
            swatch(k, (x, cy))?;
        }
        root.draw_text(line, &style, (x + swatch_w, cy))
            .map_err(txt)?;
    }
    Ok(())
}

/// Inner padding of the notes and legend boxes, pixels.
const BOX_PAD: i32 = 8;

/// Size of a box holding `lines` (with `swatch_w` extra width per line).
fn text_box_size<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    lines: &[String],
    style: &TextStyle,
    line_h: i32,
    swatch_w: i32,
) -> (i32, i32) {
    let text_w = lines
        .iter()
        .map(|l| {
            root.estimate_text_size(l, style)
                .map_or(7 * l.chars().count() as i32, |(w, _)| w as i32)
        })
        .max()
        .unwrap_or(0);
    (
        text_w + swatch_w + 2 * BOX_PAD,
        line_h * lines.len() as i32 + 2 * BOX_PAD,
    )
}

/// Draw the log–log chart on `root`.
fn draw_loglog<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    c: &LogLogChart<'_>,
) -> DrawResult<()> {
    root.fill(&WHITE).map_err(txt)?;
    let body = root
        .titled(
            c.title,
            (FONT, caption_size(c.title, root.dim_in_pixel().0)),
        )
        .map_err(txt)?;

    // Valid points per series.
    let logs: Vec<Vec<(f64, f64)>> = c
        .series
        .iter()
        .map(|s| {
            s.points
                .iter()
                .copied()
                .filter(|&(x, y)| valid_log_point(x, y))
                .collect()
        })
        .collect();
    let xa = log_axis(logs.iter().flatten().map(|p| p.0.log10()));
    let ya = log_axis(logs.iter().flatten().map(|p| p.1.log10()));
    let pow = |v: &[f64]| v.iter().map(|e| 10f64.powf(*e)).collect::<Vec<f64>>();
    let (x_lo, x_hi) = (10f64.powf(xa.lo), 10f64.powf(xa.hi));
    let x_range = if c.reverse_x { x_hi..x_lo } else { x_lo..x_hi };

    let mut chart = ChartBuilder::on(&body)
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
    chart
        .configure_mesh()
        .x_desc(c.x_label)
        .y_desc(c.y_label)
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .label_style((FONT, 14))
        .axis_desc_style((FONT, 16))
        .bold_line_style(GRID_BOLD)
        .light_line_style(GRID_LIGHT)
        .draw()
        .map_err(txt)?;

    // Series: lines first, then markers on top.
    for (k, pts) in logs.iter().enumerate() {
        let colour = SERIES_COLOURS[k % SERIES_COLOURS.len()];
        if c.series[k].line && pts.len() > 1 {
            chart
                .draw_series(LineSeries::new(pts.iter().copied(), colour.stroke_width(2)))
                .map_err(txt)?;
        }
    }
    for (k, pts) in logs.iter().enumerate() {
        let colour = SERIES_COLOURS[k % SERIES_COLOURS.len()];
        let s = &c.series[k];
        if s.markers || !s.line {
            with_marker!(shape_of(k), colour, |mk| chart
                .draw_series(pts.iter().map(|&p| mk(p)))
                .map(|_| ()))
            .map_err(txt)?;
        }
    }

    // Data in pixels (points and samples along lines), to place the legend where it hides least.
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

    let (px_range, py_range) = chart.plotting_area().get_pixel_range();
    let inset = 10;
    let style = TextStyle::from((FONT, 14).into_font());
    let line_h = 20;

    // Notes, upper left.
    let notes: Vec<String> = c.notes.to_vec();
    let mut notes_rect = None;
    if !notes.is_empty() {
        let (w, h) = text_box_size(root, &notes, &style, line_h, 0);
        let x0 = px_range.start + inset;
        let y0 = py_range.start + inset;
        let rect = (x0, y0, x0 + w, y0 + h);
        draw_text_box(root, rect, &notes, &style, line_h, 0, |_, _| Ok(()))?;
        notes_rect = Some(rect);
    }

    // Legend, in the corner hiding the fewest samples.
    let entries: Vec<(usize, String)> = c
        .series
        .iter()
        .enumerate()
        .filter(|(_, s)| !s.name.is_empty())
        .map(|(k, s)| (k, s.name.clone()))
        .collect();
    if !entries.is_empty() {
        let lines: Vec<String> = entries.iter().map(|(_, n)| n.clone()).collect();
        let swatch_w = 40;
        let (w, h) = text_box_size(root, &lines, &style, line_h, swatch_w);
        let (l, r) = (px_range.start + inset, px_range.end - inset - w);
        let (t, b) = (py_range.start + inset, py_range.end - inset - h);
        let mut corners = vec![(r, t), (l, b), (r, b)];
        if notes_rect.is_none() {
            corners.push((l, t));
        }
        let score = |&(x, y): &(i32, i32)| {
            let rect = (x, y, x + w, y + h);
            let hidden = samples
                .iter()
                .filter(|&&(sx, sy)| sx >= rect.0 && sx <= rect.2 && sy >= rect.1 && sy <= rect.3)
                .count();
            let clash = notes_rect.is_some_and(|n| overlaps(n, rect));
            hidden + if clash { 1_000_000 } else { 0 }
        };
        let mut best = corners[0];
        let mut best_score = score(&best);
        for corner in &corners[1..] {
            let s = score(corner);
            if s < best_score {
                best = *corner;
                best_score = s;
            }
        }
        let rect = (best.0, best.1, best.0 + w, best.1 + h);
        let series = c.series;
        draw_text_box(root, rect, &lines, &style, line_h, swatch_w, |i, (x, y)| {
            let k = entries[i].0;
            let s = &series[k];
            let colour = SERIES_COLOURS[k % SERIES_COLOURS.len()];
            if s.line {
                root.draw(&PathElement::new(
                    vec![(x, y), (x + swatch_w - 10, y)],
                    colour.stroke_width(2),
                ))
                .map_err(txt)?;
            }
            if s.markers || !s.line {
                let at = (x + (swatch_w - 10) / 2, y);
                with_marker!(shape_of(k), colour, |mk| root.draw(&mk(at))).map_err(txt)?;
            }
            Ok(())
        })?;
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Category map
// ---------------------------------------------------------------------------------------------

/// Categorical map: a grid of cells, rows and columns labelled, each cell coloured by its
/// category with an optional short text (e.g. an iteration count) inside, and a legend of the
/// categories with their colours. `cells` are (row, col, category, text).
///
/// Known categories have fixed colours: "converged" green, "cycling" orange, "iteration-limit"
/// red, "penalty-too-weak" purple, "solver-failure" dark red, "infeasible" grey, "too-large"
/// light grey, "numerical" dark brown, "not-run" white with a grey border; any other category
/// gets a palette colour chosen deterministically from its name (different names may share a
/// colour). Row 0 is drawn at the top, column 0 at the left; the grid has
/// `row_labels.len()` rows and `col_labels.len()` columns, and cells outside it are ignored
/// (a later cell at the same position is drawn over an earlier one). Positions without a cell
/// stay blank. The legend lists the categories that occur, known ones first in the order
/// above, then the others alphabetically. The cell text is written in black or white, whichever
/// contrasts with the cell, at a size that fits the cell (left out when it cannot be legible);
/// column labels are turned vertical when they do not fit side by side. The picture size grows
/// with the grid (about 60 × 34 pixels per cell, between 640 × 420 and 2000 × 1400 pixels).
///
/// # Errors
/// [`Error::Io`] if the file cannot be written or drawing fails.
pub fn write_category_map_svg(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    col_labels: &[String],
    row_labels: &[String],
    cells: &[(usize, usize, String, String)],
) -> Result<()> {
    ensure_font(path)?;
    let map = CategoryMap {
        title,
        x_label,
        y_label,
        col_labels,
        row_labels,
        cells,
    };
    let layout = map_layout(&map);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, layout.size).into_drawing_area();
        draw_category_map(&root, &map, &layout).map_err(|e| plot_error(path, e))?;
        root.present().map_err(|e| plot_error(path, e))?;
    }
    write_file(path, svg)
}

/// Everything drawn on a category map.
struct CategoryMap<'a> {
    title: &'a str,
    x_label: &'a str,
    y_label: &'a str,
    col_labels: &'a [String],
    row_labels: &'a [String],
    cells: &'a [(usize, usize, String, String)],
}

/// Colour of a category.
fn category_colour(name: &str) -> RGBColor {
    if let Some((_, c)) = CATEGORY_COLOURS.iter().find(|(n, _)| *n == name) {
        return *c;
    }
    // FNV-1a: stable across runs and Rust versions.
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in name.bytes() {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    EXTRA_COLOURS[(h % EXTRA_COLOURS.len() as u64) as usize]
}

/// Categories occurring in the grid, in legend order.
fn legend_categories(map: &CategoryMap<'_>) -> Vec<String> {
    let (nr, nc) = (map.row_labels.len(), map.col_labels.len());
    let mut present: Vec<&str> = map
        .cells
        .iter()
        .filter(|(r, c, _, _)| *r < nr && *c < nc)
        .map(|(_, _, cat, _)| cat.as_str())
        .collect();
    present.sort_unstable();
    present.dedup();
    let mut out: Vec<String> = CATEGORY_COLOURS
        .iter()
        .filter(|(n, _)| present.contains(n))
        .map(|(n, _)| n.to_string())
        .collect();
    out.extend(
        present
            .into_iter()
            .filter(|p| !CATEGORY_COLOURS.iter().any(|(n, _)| n == p))
            .map(str::to_string),
    );
    out
}

/// Pixel layout of a category map.
#[derive(Debug, Clone)]
struct MapLayout {
    /// Picture size.
    size: (u32, u32),
    /// Widest row label and widest column label at 14 px.
    row_label_w: i32,
    col_label_w: i32,
    /// Widest legend entry text.
    legend_text_w: i32,
    /// Legend entries.
    legend: Vec<String>,
}

/// Width of `text` in the embedded font at `size` px (estimated if the font fails).
fn text_width(text: &str, size: f64) -> i32 {
    (FONT, size).into_font().box_size(text).map_or(
        (0.6 * size * text.chars().count() as f64) as i32,
        |(w, _)| w as i32,
    )
}

/// Label font size of the category map, px.
const MAP_FONT: f64 = 14.0;
/// Gap between the grid, its labels and the legend, px.
const MAP_GAP: i32 = 8;
/// Outer margin, px.
const MAP_MARGIN: i32 = 15;
/// Height of the title band (see `DrawingArea::titled`), px.
const TITLE_BAND: i32 = 40;
/// Height of one legend entry, px.
const LEGEND_LINE: i32 = 24;
/// Size of a legend colour swatch, px.
const SWATCH: i32 = 16;
/// Room for an axis description (one line of 16 px text), px.
const DESC_BAND: i32 = 24;

/// Choose the picture size of a category map from its labels and texts.
fn map_layout(map: &CategoryMap<'_>) -> MapLayout {
    let nc = map.col_labels.len().max(1) as i32;
    let nr = map.row_labels.len().max(1) as i32;
    let widest =
        |v: &mut dyn Iterator<Item = &str>| v.map(|t| text_width(t, MAP_FONT)).max().unwrap_or(0);
    let row_label_w = widest(&mut map.row_labels.iter().map(String::as_str));
    let col_label_w = widest(&mut map.col_labels.iter().map(String::as_str));
    let cell_text_w = widest(&mut map.cells.iter().map(|c| c.3.as_str()));
    let legend = legend_categories(map);
    let legend_text_w = widest(&mut legend.iter().map(String::as_str));

    let cell_w = 60.max(cell_text_w + 10).min(160);
    let cell_h = 34;
    let legend_w = if legend.is_empty() {
        0
    } else {
        MAP_GAP * 2 + SWATCH + MAP_GAP + legend_text_w
    };
    let bottom = MAP_GAP + col_label_w.clamp(20, 200) + DESC_BAND;
    let left = DESC_BAND + row_label_w + MAP_GAP;
    let w = 2 * MAP_MARGIN + left + nc * cell_w + legend_w;
    let legend_h = LEGEND_LINE * legend.len() as i32;
    let h = TITLE_BAND + 2 * MAP_MARGIN + bottom + (nr * cell_h).max(legend_h);
    MapLayout {
        size: (w.clamp(640, 2000) as u32, h.clamp(420, 1400) as u32),
        row_label_w,
        col_label_w,
        legend_text_w,
        legend,
    }
}

/// Relative luminance-like brightness of a colour, 0–255.
fn brightness(c: RGBColor) -> f64 {
    0.299 * f64::from(c.0) + 0.587 * f64::from(c.1) + 0.114 * f64::from(c.2)
}

/// Draw the category map on `root`.
fn draw_category_map<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    map: &CategoryMap<'_>,
    layout: &MapLayout,
) -> DrawResult<()> {
    root.fill(&WHITE).map_err(txt)?;
    let body = root
        .titled(
            map.title,
            (FONT, caption_size(map.title, root.dim_in_pixel().0)),
        )
        .map_err(txt)?;
    let (bx, by) = body.get_pixel_range();
    let (nr, nc) = (map.row_labels.len(), map.col_labels.len());

    // Horizontal budget: margin, y description, row labels, gap, grid, legend, margin.
    let legend_w = if layout.legend.is_empty() {
        0
    } else {
        MAP_GAP * 2 + SWATCH + MAP_GAP + layout.legend_text_w
    };
    let max_label_w = (bx.end - bx.start) / 3;
    let row_label_w = layout.row_label_w.min(max_label_w);
    let gx0 = bx.start + MAP_MARGIN + DESC_BAND + row_label_w + MAP_GAP;
    let gx1 = (bx.end - MAP_MARGIN - legend_w).max(gx0 + 10);
    let cell_w = f64::from(gx1 - gx0) / nc.max(1) as f64;

    // Column labels side by side if they fit, vertical otherwise.
    let vertical = nc > 0 && f64::from(layout.col_label_w) > cell_w - 6.0;
    let col_band = if vertical {
        layout
            .col_label_w
            .clamp(20, ((by.end - by.start) / 3).max(20))
    } else {
        20
    };
    let gy0 = by.start + MAP_MARGIN;
    let gy1 = (by.end - MAP_MARGIN - DESC_BAND - MAP_GAP - col_band).max(gy0 + 10);
    let cell_h = f64::from(gy1 - gy0) / nr.max(1) as f64;
    let xpix = |c: usize| gx0 + (c as f64 * cell_w).round() as i32;
    let ypix = |r: usize| gy0 + (r as f64 * cell_h).round() as i32;

    // Blank grid, then the cells.
    for r in 0..nr {
        for c in 0..nc {
            let rect = [(xpix(c), ypix(r)), (xpix(c + 1), ypix(r + 1))];
            root.draw(&Rectangle::new(rect, RGBColor(235, 235, 235)))
                .map_err(txt)?;
        }
    }
    let text_size = (cell_h * 0.5).min(14.0);
    for (r, c, category, text) in map.cells {
        let (r, c) = (*r, *c);
        if r >= nr || c >= nc {
            continue;
        }
        let colour = category_colour(category);
        let (x0, y0, x1, y1) = (xpix(c), ypix(r), xpix(c + 1), ypix(r + 1));
        root.draw(&Rectangle::new([(x0, y0), (x1, y1)], colour.filled()))
            .map_err(txt)?;
        root.draw(&Rectangle::new([(x0, y0), (x1, y1)], WHITE))
            .map_err(txt)?;
        if category == "not-run" {
            // Inset, so that the white borders of neighbours drawn later do not hide it.
            root.draw(&Rectangle::new(
                [(x0 + 2, y0 + 2), (x1 - 2, y1 - 2)],
                CELL_BORDER,
            ))
            .map_err(txt)?;
        }
        if text.is_empty() {
            continue;
        }
        // Shrink the text to the cell width; leave it out below 7 px.
        let w14 = f64::from(text_width(text, 14.0).max(1));
        let size = text_size.min(14.0 * (cell_w - 6.0) / w14);
        if size < 7.0 {
            continue;
        }
        let ink = if brightness(colour) > 140.0 {
            BLACK
        } else {
            WHITE
        };
        let style = TextStyle::from((FONT, size).into_font())
            .color(&ink)
            .pos(Pos::new(HPos::Center, VPos::Center));
        root.draw_text(text, &style, ((x0 + x1) / 2, (y0 + y1) / 2))
            .map_err(txt)?;
    }
    // Frame (also around an empty grid).
    root.draw(&Rectangle::new(
        [(gx0, gy0), (xpix(nc.max(1)), ypix(nr.max(1)))],
        BLACK.mix(0.6),
    ))
    .map_err(txt)?;

    // Row labels, right-aligned left of the grid, shrunk to the row height.
    let label_size = MAP_FONT.min(cell_h * 0.8);
    if label_size >= 6.0 {
        let style = TextStyle::from((FONT, label_size).into_font())
            .pos(Pos::new(HPos::Right, VPos::Center));
        for (r, label) in map.row_labels.iter().enumerate() {
            let y = (ypix(r) + ypix(r + 1)) / 2;
            root.draw_text(label, &style, (gx0 - MAP_GAP, y))
                .map_err(txt)?;
        }
    }
    // Column labels below the grid.
    let grid_bottom = ypix(nr.max(1));
    let col_size = if vertical {
        MAP_FONT.min(cell_w * 0.8)
    } else {
        MAP_FONT
    };
    if col_size >= 6.0 {
        let style = TextStyle::from((FONT, col_size).into_font());
        let style = if vertical {
            style
                .transform(FontTransform::Rotate270)
                .pos(Pos::new(HPos::Right, VPos::Center))
        } else {
            style.pos(Pos::new(HPos::Center, VPos::Top))
        };
        for (c, label) in map.col_labels.iter().enumerate() {
            let x = (xpix(c) + xpix(c + 1)) / 2;
            root.draw_text(label, &style, (x, grid_bottom + MAP_GAP))
                .map_err(txt)?;
        }
    }
    // Axis descriptions.
    let desc = TextStyle::from((FONT, 16).into_font());
    let grid_mid_x = (gx0 + gx1) / 2;
    let grid_mid_y = (gy0 + ypix(nr.max(1))) / 2;
    root.draw_text(
        map.x_label,
        &desc.pos(Pos::new(HPos::Center, VPos::Bottom)),
        (grid_mid_x, by.end - MAP_MARGIN),
    )
    .map_err(txt)?;
    root.draw_text(
        map.y_label,
        &desc
            .transform(FontTransform::Rotate270)
            .pos(Pos::new(HPos::Center, VPos::Top)),
        (bx.start + MAP_MARGIN, grid_mid_y),
    )
    .map_err(txt)?;

    // Legend, right of the grid, from its top.
    let lx = gx1 + 2 * MAP_GAP;
    let style =
        TextStyle::from((FONT, MAP_FONT).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
    for (k, category) in layout.legend.iter().enumerate() {
        let cy = gy0 + LEGEND_LINE * k as i32 + LEGEND_LINE / 2;
        let sq = [(lx, cy - SWATCH / 2), (lx + SWATCH, cy + SWATCH / 2)];
        root.draw(&Rectangle::new(sq, category_colour(category).filled()))
            .map_err(txt)?;
        root.draw(&Rectangle::new(sq, CELL_BORDER)).map_err(txt)?;
        root.draw_text(category, &style, (lx + SWATCH + MAP_GAP, cy))
            .map_err(txt)?;
    }
    Ok(())
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

    /// A cell of a category map: (row, col, category, text).
    type Cell = (usize, usize, String, String);

    fn demo_cells() -> (Vec<String>, Vec<String>, Vec<Cell>) {
        let cols: Vec<String> = ["1e-1", "1e-2", "1e-3", "1e-4", "1e-5", "1e-6"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        let rows: Vec<String> = ["h/L = 0.01", "h/L = 0.05", "h/L = 0.1", "h/L = 0.2"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        let cats = [
            "converged",
            "cycling",
            "iteration-limit",
            "penalty-too-weak",
            "solver-failure",
            "infeasible",
            "too-large",
            "numerical",
            "not-run",
            "something-new",
        ];
        let mut cells = Vec::new();
        for r in 0..rows.len() {
            for c in 0..cols.len() {
                let k = (r * cols.len() + c) % cats.len();
                let text = if cats[k] == "not-run" {
                    String::new()
                } else {
                    format!("{}", 3 + 7 * k)
                };
                cells.push((r, c, cats[k].to_string(), text));
            }
        }
        cells.push((99, 0, "converged".to_string(), "x".to_string()));
        cells.push((0, 99, "converged".to_string(), "x".to_string()));
        (cols, rows, cells)
    }

    #[test]
    fn log_axis_spans_a_decade_and_labels() {
        let a = log_axis([0.2_f64.log10(), 0.3_f64.log10()].into_iter());
        assert!(a.hi - a.lo >= 1.0 - 1e-12);
        assert!(!a.bold.is_empty());
        let e = log_axis(std::iter::empty());
        assert_eq!((e.lo, e.hi), (0.0, 1.0));
        assert!(plain_labels(&a) && plain_labels(&e));
        assert!(!plain_labels(&log_axis([-4.0, -1.0].into_iter())));
        assert_eq!(log_tick_label(0.0, true), "1");
        assert_eq!(log_tick_label(-2.0, true), "0.01");
        assert_eq!(log_tick_label(5f64.log10() - 2.0, true), "0.05");
        assert_eq!(log_tick_label(3.0, true), "1000");
        assert_eq!(log_tick_label(3.0, false), "10³");
        assert_eq!(log_tick_label(0.0, false), "10⁰");
        assert_eq!(log_tick_label(-6.0, true), "10⁻⁶");
        assert_eq!(log_tick_label(2f64.log10() - 5.0, false), "2×10⁻⁵");
        assert_eq!(log_tick_label(12.0, false), "10¹²");
        // Very wide ranges keep a bounded number of labels.
        let w = log_axis([-300.0, 300.0].into_iter());
        assert!(w.bold.len() <= 13, "{}", w.bold.len());
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
    fn category_map_svg_is_written() {
        let dir = tempfile::tempdir().expect("tempdir");
        let path = dir.path().join("map.svg");
        let (cols, rows, cells) = demo_cells();
        write_category_map_svg(&path, "Outcome map title", "ε̄", "h/L", &cols, &rows, &cells)
            .expect("write");
        let text = std::fs::read_to_string(&path).expect("read");
        assert!(text.contains("<svg"));
        assert!(text.contains("Outcome map title"));
        assert!(text.contains("penalty-too-weak"));
        assert!(text.contains("something-new"));
        assert!(text.contains("h/L = 0.05"));
    }

    #[test]
    fn category_map_handles_degenerate_input() {
        let dir = tempfile::tempdir().expect("tempdir");
        let path = dir.path().join("empty.svg");
        write_category_map_svg(&path, "Empty map", "x", "y", &[], &[], &[]).expect("empty");
        let text = std::fs::read_to_string(&path).expect("read");
        assert!(text.contains("<svg") && text.contains("Empty map"));

        // Labels but no cells, cells all outside, and a huge grid with long labels.
        let cols: Vec<String> = (0..3).map(|c| format!("c{c}")).collect();
        let rows: Vec<String> = (0..2).map(|r| format!("r{r}")).collect();
        let outside = vec![(5, 5, "converged".to_string(), "1".to_string())];
        write_category_map_svg(&path, "No cells", "x", "y", &cols, &rows, &outside)
            .expect("outside");
        assert!(std::fs::read_to_string(&path)
            .expect("read")
            .contains("No cells"));

        let cols: Vec<String> = (0..80)
            .map(|c| format!("a long column label {c}"))
            .collect();
        let rows: Vec<String> = (0..120).map(|r| format!("row {r}")).collect();
        let cells: Vec<_> = (0..120)
            .flat_map(|r| {
                (0..80).map(move |c| (r, c, format!("cat{}", (r + c) % 13), "12345".to_string()))
            })
            .collect();
        write_category_map_svg(&path, "Huge", "x", "y", &cols, &rows, &cells).expect("huge");
        assert!(std::fs::read_to_string(&path)
            .expect("read")
            .contains("Huge"));
    }

    #[test]
    fn category_colours_are_fixed_and_deterministic() {
        assert_eq!(category_colour("converged"), RGBColor(44, 160, 44));
        assert_eq!(category_colour("not-run"), WHITE);
        assert_eq!(category_colour("brand-new"), category_colour("brand-new"));
        let (cols, rows, cells) = demo_cells();
        let map = CategoryMap {
            title: "",
            x_label: "",
            y_label: "",
            col_labels: &cols,
            row_labels: &rows,
            cells: &cells,
        };
        let legend = legend_categories(&map);
        assert_eq!(legend.first().map(String::as_str), Some("converged"));
        assert_eq!(legend.last().map(String::as_str), Some("something-new"));
        assert_eq!(legend.len(), 10);
    }

    /// Render both charts through the bitmap backend (same drawing code as the SVG files).
    fn render_pngs(dir: &Path) {
        ensure_font(dir).expect("font");
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
        let png = dir.join("loglog.png");
        {
            let root = BitMapBackend::new(&png, LOGLOG_SIZE).into_drawing_area();
            draw_loglog(&root, &chart).expect("draw loglog");
            root.present().expect("present");
        }
        let (cols, rows, cells) = demo_cells();
        let map = CategoryMap {
            title: "Outcome of the penalty iteration",
            x_label: "ε̄",
            y_label: "thickness",
            col_labels: &cols,
            row_labels: &rows,
            cells: &cells,
        };
        let layout = map_layout(&map);
        let png = dir.join("map.png");
        {
            let root = BitMapBackend::new(&png, layout.size).into_drawing_area();
            draw_category_map(&root, &map, &layout).expect("draw map");
            root.present().expect("present");
        }
    }

    #[test]
    fn charts_render_to_png() {
        let dir = tempfile::tempdir().expect("tempdir");
        render_pngs(dir.path());
        for name in ["loglog.png", "map.png"] {
            let bytes = std::fs::read(dir.path().join(name)).expect("read png");
            assert!(bytes.starts_with(&[0x89, b'P', b'N', b'G']));
        }
    }
}
