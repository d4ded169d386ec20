//! Plan views of the plate drawn to equal scale on x and y, and the colour map they share: cells
//! coloured by a value, a colour bar, the contact boundary, an [`Overlay`] and its legend.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::axis::{finite_extent, tick_format, Plan, Ticked};
use super::overlay::{draw_exceedance, draw_features, draw_marks, Overlay, Swatch, SWATCH_W};
use super::style::{self, DESC_FONT, LABEL_FONT};
use super::units::Scale;
use super::{text_width, titled, txt, DrawResult, Picture, FONT};
use crate::layout::{Axis, JointType};
use crate::post::FullField;

/// Outer margin of a plan view, pixels.
pub(super) const MARGIN: i32 = 15;
/// Height of the x label area, pixels.
pub(super) const X_AREA: i32 = 50;
/// Width of the y label area, pixels.
pub(super) const Y_AREA: i32 = 70;

/// Axes for the rectangle [x0, x1] × [y0, y1] on `area` with equal scales on x and y, centred;
/// also returns the vertical room left above and below the drawing, pixels.
pub(super) fn plan_axes<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
    (x_desc, y_desc): (&str, &str),
    shown: f64,
) -> DrawResult<(Plan<'a, DB>, i32)> {
    let (aw, ah) = area.dim_in_pixel();
    let avail_w = (aw as i32 - 2 * MARGIN - Y_AREA).max(10) as f64;
    let avail_h = (ah as i32 - 2 * MARGIN - X_AREA).max(10) as f64;
    let px = (avail_w / (x1 - x0)).min(avail_h / (y1 - y0));
    let extra_w = ((avail_w - px * (x1 - x0)) / 2.0).max(0.0) as i32;
    let extra_h = ((avail_h - px * (y1 - y0)) / 2.0).max(0.0) as i32;
    let mut chart = ChartBuilder::on(area)
        .margin_left(MARGIN + extra_w)
        .margin_right(MARGIN + extra_w)
        .margin_top(MARGIN + extra_h)
        .margin_bottom(MARGIN + extra_h)
        .x_label_area_size(X_AREA)
        .y_label_area_size(Y_AREA)
        .build_cartesian_2d(Ticked::new(x0, x1, shown), Ticked::new(y0, y1, shown))
        .map_err(txt)?;
    // Ticks sit at round values of the shown unit (`shown` per field unit: 1 for metres,
    // 39.37 for inches), labelled in it.
    let (x_tick, y_tick) = (
        tick_format(x0 * shown, x1 * shown),
        tick_format(y0 * shown, y1 * shown),
    );
    let x_fmt = |v: &f64| x_tick(&(v * shown));
    let y_fmt = |v: &f64| y_tick(&(v * shown));
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .label_style((FONT, LABEL_FONT))
        .axis_desc_style((FONT, DESC_FONT))
        .draw()
        .map_err(txt)?;
    Ok((chart, extra_h))
}

/// Draw the outline of the rectangle [x0, x1] × [y0, y1].
pub(super) fn outline<DB: DrawingBackend>(
    chart: &mut Plan<'_, DB>,
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> DrawResult<()> {
    chart
        .draw_series(std::iter::once(PathElement::new(
            [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)],
            style::OUTLINE.stroke_width(1),
        )))
        .map_err(txt)?;
    Ok(())
}

/// Draw the contact boundary of `field` in `colour` and `width` (nothing if σ is nowhere
/// positive).
pub(super) fn boundary<DB: DrawingBackend>(
    chart: &mut Plan<'_, DB>,
    field: &FullField,
    colour: RGBColor,
    width: u32,
) -> DrawResult<()> {
    let segments = field.contact_boundary();
    chart
        .draw_series(
            segments
                .into_iter()
                .map(|s| PathElement::new(s.xy, colour.stroke_width(width))),
        )
        .map_err(txt)?;
    Ok(())
}

/// Draw the edges of a shaped plate (its outline and its openings): every side of a plate
/// cell that borders a cell outside the plate or the box, as the plate's own edge (a thicker
/// line than the box's). Nothing on a plate that is its whole rectangle.
pub(super) fn shape<DB: DrawingBackend>(
    chart: &mut Plan<'_, DB>,
    field: &FullField,
) -> DrawResult<()> {
    if field.plate.is_empty() {
        return Ok(());
    }
    let (nx, ny) = (field.nx, field.ny);
    let n1 = nx + 1;
    let x = |i: usize| field.x[i];
    let y = |j: usize| field.y[j * n1];
    let plate = |i: isize, j: isize| {
        i >= 0
            && j >= 0
            && (i as usize) < nx
            && (j as usize) < ny
            && field.is_plate(i as usize, j as usize)
    };
    let mut edges: Vec<[(f64, f64); 2]> = Vec::new();
    for j in 0..ny {
        for i in (0..nx).filter(|&i| field.is_plate(i, j)) {
            let (ii, jj) = (i as isize, j as isize);
            if !plate(ii, jj - 1) {
                edges.push([(x(i), y(j)), (x(i + 1), y(j))]);
            }
            if !plate(ii + 1, jj) {
                edges.push([(x(i + 1), y(j)), (x(i + 1), y(j + 1))]);
            }
            if !plate(ii, jj + 1) {
                edges.push([(x(i), y(j + 1)), (x(i + 1), y(j + 1))]);
            }
            if !plate(ii - 1, jj) {
                edges.push([(x(i), y(j)), (x(i), y(j + 1))]);
            }
        }
    }
    chart
        .draw_series(
            edges
                .into_iter()
                .map(|e| PathElement::new(e, style::OUTLINE.stroke_width(2))),
        )
        .map_err(txt)?;
    Ok(())
}

/// Corner node copies of whole-plate element (i, j), counter-clockwise from (i, j): on a
/// jointed plate the element's own side of each joint.
pub(super) fn cell_nodes(field: &FullField, i: usize, j: usize) -> [usize; 4] {
    field.element_nodes(i, j)
}

/// Draw the joint lines of `field` across the plate (x0, x1) × (y0, y1): panel outlines, each
/// line dashed by its kind ([`style::joint`]) over a white halo.
pub(super) fn joints<DB: DrawingBackend>(
    chart: &mut Plan<'_, DB>,
    field: &FullField,
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> DrawResult<()> {
    for j in &field.joints {
        let ((dash, gap), colour) = style::joint(j.kind);
        for line in joint_pieces(field, j, (x0, x1), (y0, y1)) {
            chart
                .draw_series(std::iter::once(PathElement::new(
                    line,
                    style::HALO.stroke_width(4),
                )))
                .map_err(txt)?;
            chart
                .draw_series(DashedLineSeries::new(
                    line,
                    dash,
                    gap,
                    colour.stroke_width(2),
                ))
                .map_err(txt)?;
        }
    }
    Ok(())
}

/// The pieces of a joint line that run over the plate: the whole line across the box, or on a
/// shaped plate its runs of cell edges with plate on at least one side.
fn joint_pieces(
    field: &FullField,
    j: &crate::post::JointLine,
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> Vec<[(f64, f64); 2]> {
    let whole = match (j.axis, j.span) {
        (Axis::X, None) => [(j.at, y0), (j.at, y1)],
        (Axis::Y, None) => [(x0, j.at), (x1, j.at)],
        (Axis::X, Some([a, b])) => [(j.at, a), (j.at, b)],
        (Axis::Y, Some([a, b])) => [(a, j.at), (b, j.at)],
    };
    if field.plate.is_empty() {
        return vec![whole];
    }
    // A segment's extent along the line (the whole line's otherwise).
    let (lo, hi) = j
        .span
        .map_or((f64::NEG_INFINITY, f64::INFINITY), |[a, b]| (a, b));
    let (nx, ny) = (field.nx, field.ny);
    let n1 = nx + 1;
    // The grid line of the joint, and the cells on its two sides along it.
    let (count, coords, at): (usize, Vec<f64>, usize) = match j.axis {
        Axis::X => {
            let xs: Vec<f64> = (0..=nx).map(|i| field.x[i]).collect();
            let i = nearest(&xs, j.at);
            (ny, (0..=ny).map(|r| field.y[r * n1]).collect(), i)
        }
        Axis::Y => {
            let ys: Vec<f64> = (0..=ny).map(|r| field.y[r * n1]).collect();
            let r = nearest(&ys, j.at);
            (nx, (0..=nx).map(|i| field.x[i]).collect(), r)
        }
    };
    let on = |k: usize| {
        let mid = 0.5 * (coords[k] + coords[k + 1]);
        if mid < lo || mid > hi {
            return false;
        }
        let (a, b) = match j.axis {
            Axis::X => ((at.wrapping_sub(1), k), (at, k)),
            Axis::Y => ((k, at.wrapping_sub(1)), (k, at)),
        };
        let cell = |(i, r): (usize, usize)| i < nx && r < ny && field.is_plate(i, r);
        cell(a) || cell(b)
    };
    let mut out = Vec::new();
    let mut k = 0;
    while k < count {
        if !on(k) {
            k += 1;
            continue;
        }
        let start = k;
        while k < count && on(k) {
            k += 1;
        }
        let (s, e) = (coords[start], coords[k]);
        out.push(match j.axis {
            Axis::X => [(j.at, s), (j.at, e)],
            Axis::Y => [(s, j.at), (e, j.at)],
        });
    }
    out
}

/// The index of the value in `v` nearest `x`.
fn nearest(v: &[f64], x: f64) -> usize {
    (0..v.len())
        .min_by(|&a, &b| (v[a] - x).abs().total_cmp(&(v[b] - x).abs()))
        .unwrap_or(0)
}

/// Which colour table a [`ColourScale`] runs along.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Palette {
    /// Pale to dark from `lo` to `hi` (values ≥ 0).
    Sequential,
    /// Dark to pale from `lo` to `hi` (values ≤ 0: the largest magnitude darkest).
    Reversed,
    /// Blue below zero, white at zero, red above; `lo` = −`hi`.
    Diverging,
}

/// Fraction of the largest magnitude below which values of the other sign are ignored by
/// [`ColourScale::of`].
const ONE_SIGN: f64 = 1e-2;

/// Colours of values from `lo` to `hi`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct ColourScale {
    /// Value at the bottom of the colour bar.
    pub lo: f64,
    /// Value at its top.
    pub hi: f64,
    /// The colour table.
    pub palette: Palette,
}

impl ColourScale {
    /// The scale of `values` (finite ones; zero always included): sequential from 0 to the
    /// largest value when none is negative, reversed from the smallest to 0 when none is
    /// positive, diverging and symmetric about 0 when they have both signs. Values of the
    /// minority sign within [`ONE_SIGN`] of the largest magnitude do not count (they take the
    /// colour of 0): the small tensions a penalty solution leaves on lifted nodes keep a
    /// pressure map sequential.
    pub(super) fn of(values: impl Iterator<Item = f64>) -> Self {
        let (lo, hi) = values
            .filter(|v| v.is_finite())
            .fold((0.0_f64, 0.0_f64), |(l, h), v| (l.min(v), h.max(v)));
        let (lo, hi) = if -lo <= ONE_SIGN * hi {
            (0.0, hi)
        } else if hi <= ONE_SIGN * -lo {
            (lo, 0.0)
        } else {
            (lo, hi)
        };
        let (lo, hi, palette) = if lo < 0.0 && hi > 0.0 {
            let m = hi.max(-lo);
            (-m, m, Palette::Diverging)
        } else if hi > 0.0 {
            (0.0, hi, Palette::Sequential)
        } else if lo < 0.0 {
            (lo, 0.0, Palette::Reversed)
        } else {
            (0.0, 1.0, Palette::Sequential)
        };
        Self { lo, hi, palette }
    }

    /// Colour at the normalised position `f` ∈ [0, 1] of the bar.
    pub(super) fn at(&self, f: f64) -> RGBColor {
        match self.palette {
            Palette::Sequential => style::ramp(f),
            Palette::Reversed => style::ramp(1.0 - f),
            Palette::Diverging => style::diverging(f),
        }
    }

    /// Colour of the value `v`.
    pub(super) fn colour(&self, v: f64) -> RGBColor {
        self.at((v - self.lo) / (self.hi - self.lo))
    }
}

/// One element of a colour map: opposite corners, and its value (None: drawn as lifted).
pub(super) type Cell = ([(f64, f64); 2], Option<f64>);

/// A colour map of the plate, with its colour bar, the contact boundary if asked, an overlay
/// and (only when the overlay draws something) a legend below.
pub(super) struct ColourMap<'a> {
    /// Chart title.
    pub title: &'a str,
    /// Grid and coordinates.
    pub field: &'a FullField,
    /// The elements, in shown units.
    pub cells: Vec<Cell>,
    /// Their colours.
    pub scale: ColourScale,
    /// Caption above the colour bar.
    pub bar_caption: String,
    /// x and y axis descriptions.
    pub axes: (String, String),
    /// Shown length units per field length unit (the axes' tick labels).
    pub length_factor: f64,
    /// Draw the contact boundary of `field`.
    pub boundary: bool,
    /// What to draw over the map.
    pub overlay: &'a Overlay,
    /// Nodal values (field units) the overlay's allowable level applies to, and how they are
    /// shown; without them no level is drawn.
    pub levelled: Option<(&'a [f64], Scale)>,
    /// What a grey cell means, for the legend, where not the default (lifted off on a contact
    /// map, no value elsewhere).
    pub grey: Option<&'a str>,
}

/// Height of one legend row, pixels.
const LEGEND_ROW: i32 = 22;
/// Gap between legend entries on a row, pixels.
const LEGEND_GAP: i32 = 26;

impl ColourMap<'_> {
    /// The allowable level and the nodal values it applies to, if both are given.
    fn level(&self) -> Option<(f64, &[f64], Scale)> {
        let level = self.overlay.allowable_pressure?;
        let (values, shown) = self.levelled?;
        Some((level, values, shown))
    }

    /// Legend entries: empty when the overlay draws nothing and the plate has no joints.
    fn legend(&self) -> Vec<(Swatch, String)> {
        let o = self.overlay;
        let mut out = Vec::new();
        // Grey cells say what they are: lifted on a contact map (its boundary drawn), no value
        // elsewhere.
        if self.cells.iter().any(|c| c.1.is_none()) {
            let default = if self.boundary {
                "lifted off (no pressure)"
            } else {
                "no value"
            };
            out.push((Swatch::Lifted, self.grey.unwrap_or(default).to_string()));
        }
        // The joint lines of a jointed plate, one entry per kind, in the order first drawn.
        let mut kinds: Vec<JointType> = Vec::new();
        for j in &self.field.joints {
            if !kinds.contains(&j.kind) {
                kinds.push(j.kind);
            }
        }
        let joints = kinds.into_iter().map(|k| {
            let what = match k {
                JointType::Continuous => "panel boundary",
                JointType::Free => "free joint",
                JointType::Aggregate => "aggregate joint",
                JointType::Dowels => "doweled joint",
                JointType::Tied => "tied joint",
            };
            (Swatch::Joint(k), what.to_string())
        });
        if o.is_empty() {
            out.extend(joints);
            return out;
        }
        if self.boundary {
            out.push((Swatch::Boundary, "contact boundary".to_string()));
        }
        if let Some((level, values, shown)) = self.level() {
            let text = format!("{} {}", short(shown.apply(level)), shown.unit);
            let text = text.trim_end();
            out.push(if values.iter().any(|&v| v > level) {
                (Swatch::Exceeded, format!("pressure > allowable ({text})"))
            } else {
                (
                    Swatch::Exceeded,
                    format!("allowable pressure {text}: not exceeded"),
                )
            });
        }
        for (present, swatch, text) in [
            (!o.voids.is_empty(), Swatch::Void, "void"),
            (!o.zones.is_empty(), Swatch::Zone, "soft or stiff zone"),
            (!o.lines.is_empty(), Swatch::LineLoad, "line load"),
            (!o.prints.is_empty(), Swatch::Print, "tire print"),
            (!o.dots.is_empty(), Swatch::Dot, "searched position"),
            (
                !o.cut.is_empty(),
                Swatch::Cut,
                "not counted: the model cuts the lane here",
            ),
        ] {
            if present {
                out.push((swatch, text.to_string()));
            }
        }
        for (_, text) in &o.marks {
            out.push((Swatch::Mark, text.clone()));
        }
        out.extend(joints);
        out
    }

    /// Legend entries laid out in rows within `width` pixels: (entry, x, row).
    fn legend_layout(entries: &[(Swatch, String)], width: i32) -> Vec<(usize, i32, i32)> {
        let left = MARGIN + Y_AREA;
        let (mut x, mut row) = (left, 0);
        let mut out = Vec::with_capacity(entries.len());
        for (k, (_, text)) in entries.iter().enumerate() {
            let w = SWATCH_W + 8 + text_width(text, f64::from(LABEL_FONT));
            if x > left && x + w > width - MARGIN {
                x = left;
                row += 1;
            }
            out.push((k, x, row));
            x += w + LEGEND_GAP;
        }
        out
    }
}

/// A value with three significant digits, trailing zeros dropped.
pub(crate) fn short(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let mag = v.abs().log10().floor() as i32;
    if !(-3..5).contains(&mag) {
        return format!("{v:.2e}");
    }
    let decimals = (2 - mag).max(0) as usize;
    let text = format!("{v:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

impl Picture for ColourMap<'_> {
    fn size(&self) -> (u32, u32) {
        (900, 700)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<()> {
        let field = self.field;
        let mut body = titled(root, self.title)?;
        let (body_w, body_h) = body.dim_in_pixel();

        // Room for a legend below the map, only when there is something to name.
        let entries = self.legend();
        let layout = Self::legend_layout(&entries, body_w as i32);
        if let Some(rows) = layout.iter().map(|l| l.2 + 1).max() {
            let h = (rows * LEGEND_ROW + 6).min(body_h as i32 / 3).max(0) as u32;
            body = body.split_vertically(body_h.saturating_sub(h)).0;
        }

        let bar_w = 130_u32.min(body_w / 3);
        let (map_area, bar_area) = body.split_horizontally(body_w.saturating_sub(bar_w));
        let (xr, yr) = (finite_extent(&field.x), finite_extent(&field.y));
        let (mut chart, extra_h) = plan_axes(
            &map_area,
            xr,
            yr,
            (self.axes.0.as_str(), self.axes.1.as_str()),
            self.length_factor,
        )?;
        chart
            .draw_series(self.cells.iter().map(|&(corners, value)| {
                let colour = value.map_or(style::LIFTED, |v| self.scale.colour(v));
                Rectangle::new(corners, colour.filled())
            }))
            .map_err(txt)?;
        let level = self.level();
        if let Some((level, values, _)) = level {
            draw_exceedance(&mut chart, field, values, level)?;
        }
        if self.boundary {
            boundary(&mut chart, field, style::BOUNDARY, 2)?;
        }
        if !self.overlay.is_empty() {
            draw_features(&mut chart, self.overlay, xr, yr)?;
        }
        joints(&mut chart, field, xr, yr)?;
        outline(&mut chart, xr, yr)?;
        shape(&mut chart, field)?;
        draw_marks(&mut chart, self.overlay)?;

        // Colour bar, its ends level with the map's (up to a quarter of the height).
        let (lo, hi) = (self.scale.lo, self.scale.hi);
        let (_, ah) = map_area.dim_in_pixel();
        let inset = MARGIN + extra_h.min(ah as i32 / 4);
        let mut bar = ChartBuilder::on(&bar_area)
            .margin_top(inset)
            .margin_bottom(inset + X_AREA)
            .margin_left(10)
            .margin_right(5)
            .right_y_label_area_size(75)
            .build_cartesian_2d(0.0..1.0, lo..hi)
            .map_err(txt)?;
        let bar_fmt = tick_format(lo, hi);
        bar.configure_mesh()
            .disable_mesh()
            .disable_x_axis()
            .y_label_formatter(&bar_fmt)
            .label_style((FONT, LABEL_FONT))
            .axis_desc_style((FONT, DESC_FONT))
            .draw()
            .map_err(txt)?;
        let steps = 100;
        bar.draw_series((0..steps).map(|k| {
            let a = k as f64 / steps as f64;
            let b = (k + 1) as f64 / steps as f64;
            Rectangle::new(
                [(0.0, lo + a * (hi - lo)), (1.0, lo + b * (hi - lo))],
                self.scale.at((a + b) / 2.0).filled(),
            )
        }))
        .map_err(txt)?;
        bar.draw_series(std::iter::once(Rectangle::new(
            [(0.0, lo), (1.0, hi)],
            style::OUTLINE.stroke_width(1),
        )))
        .map_err(txt)?;
        // The allowable level across the bar.
        if let Some((level, _, shown)) = level {
            let v = shown.apply(level);
            if v >= lo && v <= hi {
                bar.draw_series([
                    PathElement::new([(0.0, v), (1.0, v)], style::HALO.stroke_width(5)),
                    PathElement::new([(0.0, v), (1.0, v)], style::EXCEEDED.stroke_width(2)),
                ])
                .map_err(txt)?;
            }
        }
        // Bar caption, centred above the bar: smaller if it would not fit beside the map, and
        // cut into lines at spaces, the last just above the bar, so that no word leaves the
        // picture (a long title was cut at its right edge).
        let (bar_x, bar_y) = bar.plotting_area().get_pixel_range();
        let size = if text_width(&self.bar_caption, 18.0) <= 170 {
            18
        } else {
            14
        };
        let lines = wrap(&self.bar_caption, size as f64, 170);
        let text =
            TextStyle::from((FONT, size).into_font()).pos(Pos::new(HPos::Center, VPos::Bottom));
        let step = size + 3;
        for (k, line) in lines.iter().rev().enumerate() {
            root.draw_text(
                line,
                &text,
                (
                    (bar_x.start + bar_x.end) / 2,
                    bar_y.start - 6 - step * k as i32,
                ),
            )
            .map_err(txt)?;
        }

        // The legend just below the x axis description (the room reserved above keeps it
        // inside the picture).
        let text =
            TextStyle::from((FONT, LABEL_FONT).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
        let top = chart.plotting_area().get_pixel_range().1.end + X_AREA;
        for (k, x, row) in layout {
            let (swatch, label) = &entries[k];
            let y = top + LEGEND_ROW / 2 + row * LEGEND_ROW;
            swatch.draw(root, (x, y))?;
            root.draw_text(label, &text, (x + SWATCH_W + 8, y))
                .map_err(txt)?;
        }
        Ok(())
    }
}

/// `text` cut at spaces into lines no wider than `width` pixels at font `size` (a word wider
/// than that stands on its own line).
fn wrap(text: &str, size: f64, width: i32) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split(' ') {
        match lines.last_mut() {
            Some(line) if text_width(&format!("{line} {word}"), size) <= width => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colour_scales_follow_the_signs_of_the_values() {
        let s = ColourScale::of([1.0, 3.0, f64::NAN].into_iter());
        assert_eq!((s.lo, s.hi, s.palette), (0.0, 3.0, Palette::Sequential));
        let s = ColourScale::of([-1.0, 3.0].into_iter());
        assert_eq!((s.lo, s.hi, s.palette), (-3.0, 3.0, Palette::Diverging));
        assert_eq!(s.colour(0.0), style::diverging(0.5), "zero is the middle");
        let s = ColourScale::of([-1e-3, 3.0].into_iter());
        assert_eq!(
            (s.lo, s.hi, s.palette),
            (0.0, 3.0, Palette::Sequential),
            "round-off"
        );
        assert_eq!(s.colour(-1e-3), style::ramp(0.0), "clamped to the pale end");
        let s = ColourScale::of([-2.0, -1.0].into_iter());
        assert_eq!((s.lo, s.hi, s.palette), (-2.0, 0.0, Palette::Reversed));
        assert_eq!(
            s.colour(-2.0),
            style::ramp(1.0),
            "largest magnitude darkest"
        );
        let s = ColourScale::of(std::iter::empty());
        assert_eq!((s.lo, s.hi), (0.0, 1.0));
    }

    #[test]
    fn short_numbers_keep_three_significant_digits() {
        assert_eq!(short(120.0), "120");
        assert_eq!(short(53.24), "53.2");
        assert_eq!(short(0.012345), "0.0123");
        assert_eq!(short(1.5e6), "1.50e6");
        assert_eq!(short(0.0), "0");
    }

    /// The caption that was cut at the picture's edge wraps into lines that each fit the bar's
    /// 170 pixels, keep every word in order, and a short caption stays one line.
    #[test]
    fn a_long_bar_caption_wraps_within_the_bar() {
        let caption = "largest principal stress at the bottom (MPa)";
        let lines = wrap(caption, 14.0, 170);
        assert!(lines.len() >= 2, "{lines:?}");
        assert!(
            lines.iter().all(|l| text_width(l, 14.0) <= 170),
            "{lines:?}"
        );
        assert_eq!(lines.join(" "), caption);
        assert_eq!(wrap("σ₁ bottom (psi)", 18.0, 170), vec!["σ₁ bottom (psi)"]);
    }
}
