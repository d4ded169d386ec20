//! What a plan view draws over its colour map: the area where the pressure exceeds the allowable
//! one (hatched, outlined by a dashed contour), voids (dashed rectangles), soft or stiff zones
//! (dotted rectangles), line loads (thick lines), tire prints (thin rectangles) and, on a
//! critical search's maps, its positions (small dots) and the critical one (a ringed dot),
//! each named in the legend when present.

use plotters::coord::Shift;
use plotters::element::{DashedPathElement, DottedPathElement};
use plotters::prelude::*;

use super::axis::Plan;
use super::style;
use super::{txt, DrawResult};
use crate::post::exceed::{self, Point};
use crate::post::FullField;

/// What to draw over a plan view, in the plate's physical coordinates (those of
/// [`FullField::x`] and [`FullField::y`]). `Overlay::default()` draws nothing.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Overlay {
    /// Allowable pressure, in the units of [`FullField::pressure`] (Pa for a physical scene) —
    /// on a field map, in the units of the values drawn. The area above it is hatched and
    /// outlined.
    pub allowable_pressure: Option<f64>,
    /// Voids under the plate, as opposite corners [(x0, y0), (x1, y1)].
    pub voids: Vec<[(f64, f64); 2]>,
    /// Soft or stiff zones of the foundation, as opposite corners.
    pub zones: Vec<[(f64, f64); 2]>,
    /// Line loads, from one end to the other.
    pub lines: Vec<[(f64, f64); 2]>,
    /// The tire prints of the axles and gears, as opposite corners.
    pub prints: Vec<[(f64, f64); 2]>,
    /// Points drawn as small dots: the positions a critical search solved.
    pub dots: Vec<(f64, f64)>,
    /// Marked points, each with its legend text: a critical search's governing position.
    pub marks: Vec<((f64, f64), String)>,
    /// Parts of the plate mapped but not counted — the end panels of a lane the model cuts
    /// (`liftoff damage`, `[traffic] ends`) — as opposite corners: hatched grey.
    pub cut: Vec<[(f64, f64); 2]>,
}

impl Overlay {
    /// What a model has to show on its contact map, in the coordinates of its report's field
    /// (m for SI scenes; x = s, y = μt for dimensionless ones, i.e. the unit system's x, y):
    /// voids, zones, line loads and the bearing limit.
    pub fn for_model(model: &crate::model::Model, report: &crate::post::Report) -> Self {
        let l = model.physical.map_or(1.0, |p| p.half_length);
        let rect = |x: [f64; 2], y: [f64; 2]| [(x[0] * l, y[0] * l), (x[1] * l, y[1] * l)];
        Self {
            allowable_pressure: report.bearing.map(|b| b.allowable),
            voids: model.voids.iter().map(|v| rect(v.x, v.y)).collect(),
            zones: model.zones.iter().map(|z| rect(z.x, z.y)).collect(),
            lines: model
                .loads
                .iter()
                .filter_map(|ld| match *ld {
                    crate::model::Load::Line { from, to, .. } => {
                        Some([(from[0] * l, from[1] * l), (to[0] * l, to[1] * l)])
                    }
                    _ => None,
                })
                .collect(),
            prints: model
                .vehicles
                .iter()
                .flat_map(|v| &model.loads[v.loads.clone()])
                .filter_map(|ld| match *ld {
                    crate::model::Load::Patch { x, y, .. } => Some(rect(x, y)),
                    _ => None,
                })
                .collect(),
            dots: Vec::new(),
            marks: Vec::new(),
            cut: Vec::new(),
        }
    }

    /// True when there is nothing to draw.
    pub fn is_empty(&self) -> bool {
        self.allowable_pressure.is_none()
            && self.voids.is_empty()
            && self.zones.is_empty()
            && self.lines.is_empty()
            && self.prints.is_empty()
            && self.dots.is_empty()
            && self.marks.is_empty()
            && self.cut.is_empty()
    }
}

/// Spacing of the hatch lines, pixels.
const HATCH_PX: f64 = 10.0;

/// One entry of a plan view's legend: what its swatch draws.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Swatch {
    /// The contact boundary: a solid dark line.
    Boundary,
    /// The area above the allowable pressure: hatching and its dashed outline.
    Exceeded,
    /// A void: a dashed rectangle.
    Void,
    /// A soft or stiff zone: a dotted rectangle.
    Zone,
    /// A line load: a thick line.
    LineLoad,
    /// A joint line of a kind: dashed as on the map.
    Joint(crate::layout::JointType),
    /// A grey cell: lifted off (or, on a stress map, no value).
    Lifted,
    /// A tire print: a thin solid rectangle.
    Print,
    /// A searched position: a small dot.
    Dot,
    /// A marked (critical) position: a ringed dot.
    Mark,
    /// A part mapped but not counted: grey hatch.
    Cut,
}

/// Width of a legend swatch, pixels.
pub(super) const SWATCH_W: i32 = 30;

impl Swatch {
    /// Draw the swatch with its left-centre point at (x, y), on any drawing area.
    pub(super) fn draw<DB: DrawingBackend>(
        self,
        area: &DrawingArea<DB, Shift>,
        (x, y): (i32, i32),
    ) -> DrawResult<()> {
        let w = SWATCH_W;
        let rect = [
            (x, y - 7),
            (x + w, y - 7),
            (x + w, y + 7),
            (x, y + 7),
            (x, y - 7),
        ];
        match self {
            Swatch::Boundary => area
                .draw(&PathElement::new(
                    [(x, y), (x + w, y)],
                    style::BOUNDARY.stroke_width(2),
                ))
                .map_err(txt),
            Swatch::Exceeded => {
                area.draw(&Rectangle::new(
                    [(x, y - 7), (x + w, y + 7)],
                    style::ramp(0.85).filled(),
                ))
                .map_err(txt)?;
                for k in 0..3 {
                    let x0 = x + 2 + 8 * k;
                    for (colour, width) in [(style::HATCH_HALO, 3), (style::EXCEEDED.to_rgba(), 1)]
                    {
                        area.draw(&PathElement::new(
                            [(x0, y + 7), (x0 + 12, y - 7)],
                            ShapeStyle::from(colour).stroke_width(width),
                        ))
                        .map_err(txt)?;
                    }
                }
                area.draw(&PathElement::new(
                    [(x, y + 7), (x + w, y + 7)],
                    style::HALO.stroke_width(4),
                ))
                .map_err(txt)?;
                for (a, b) in [(0, 9), (15, 24)] {
                    area.draw(&PathElement::new(
                        [(x + a, y + 7), (x + b, y + 7)],
                        style::EXCEEDED.stroke_width(2),
                    ))
                    .map_err(txt)?;
                }
                Ok(())
            }
            Swatch::Void => {
                let (dash, gap) = style::DASH;
                area.draw(&DashedPathElement::new(
                    rect,
                    dash,
                    gap,
                    style::VOID.stroke_width(2),
                ))
                .map_err(txt)
            }
            Swatch::Zone => area.draw(&dotted(rect)).map_err(txt),
            Swatch::Cut => {
                for k in 0..3 {
                    let x0 = x + 2 + 8 * k;
                    for (colour, width) in [(style::HATCH_HALO, 3), (style::CUT.to_rgba(), 1)] {
                        area.draw(&PathElement::new(
                            [(x0, y + 7), (x0 + 12, y - 7)],
                            ShapeStyle::from(colour).stroke_width(width),
                        ))
                        .map_err(txt)?;
                    }
                }
                Ok(())
            }
            Swatch::Print => area
                .draw(&PathElement::new(rect, style::PRINT.stroke_width(2)))
                .map_err(txt),
            Swatch::Lifted => area
                .draw(&Rectangle::new(
                    [(x, y - 7), (x + w, y + 7)],
                    style::LIFTED.filled(),
                ))
                .map_err(txt),
            Swatch::LineLoad => area
                .draw(&PathElement::new(
                    [(x, y), (x + w, y)],
                    style::LINE_LOAD.stroke_width(LINE_LOAD_W),
                ))
                .map_err(txt),
            Swatch::Dot => area.draw(&dot((x + w / 2, y))).map_err(txt),
            Swatch::Mark => {
                for part in mark((x + w / 2, y)) {
                    area.draw(&part).map_err(txt)?;
                }
                Ok(())
            }
            Swatch::Joint(kind) => {
                let ((dash, gap), colour) = style::joint(kind);
                area.draw(&DashedPathElement::new(
                    [(x, y), (x + w, y)],
                    dash,
                    gap,
                    colour.stroke_width(2),
                ))
                .map_err(txt)
            }
        }
    }
}

/// Radius of the dots of a zone outline, pixels.
const ZONE_DOT: i32 = 2;
/// Spacing of the dots of a zone outline, pixels.
const ZONE_SPACING: i32 = 6;
/// Stroke width of line loads, pixels.
const LINE_LOAD_W: u32 = 5;

/// Radius of a searched position's dot, pixels.
const DOT_R: i32 = 2;
/// Outer radius of a marked position's ring, pixels.
const MARK_R: i32 = 8;

/// A searched position's dot at `at` (any coordinates).
fn dot<C>(at: C) -> Circle<C, i32> {
    Circle::new(at, DOT_R, style::MARKER.mix(0.75).filled())
}

/// A marked position at `at`: a white disc ringed in black with a black centre — visible on
/// the pale and the dark end of the ramp.
fn mark<C: Clone>(at: C) -> [Circle<C, i32>; 3] {
    [
        Circle::new(at.clone(), MARK_R, style::HALO.filled()),
        Circle::new(at.clone(), MARK_R - 1, style::MARKER.stroke_width(2)),
        Circle::new(at, 3, style::MARKER.filled()),
    ]
}

/// The dots and the marks of `overlay` (drawn last, over the joint lines).
pub(super) fn draw_marks<DB: DrawingBackend>(
    chart: &mut Plan<'_, DB>,
    overlay: &Overlay,
) -> DrawResult<()> {
    chart
        .draw_series(overlay.dots.iter().map(|&p| dot(p)))
        .map_err(txt)?;
    for (p, _) in &overlay.marks {
        chart.draw_series(mark(*p)).map_err(txt)?;
    }
    Ok(())
}

/// A zone outline along `path`: dots [`ZONE_SPACING`] pixels apart.
fn dotted<I>(path: I) -> DottedPathElement<I::IntoIter, i32, Circle<(i32, i32), i32>>
where
    I: IntoIterator,
    I::IntoIter: Clone,
{
    DottedPathElement::new(path, 0, ZONE_SPACING, |c| {
        Circle::new(c, ZONE_DOT, style::ZONE.filled())
    })
}

/// The chord of the line x − y = `c` inside the convex polygon `poly`, if it crosses it.
pub(super) fn hatch_chord(poly: &[Point], c: f64) -> Option<[Point; 2]> {
    let n = poly.len();
    let mut ends: Vec<Point> = Vec::with_capacity(4);
    for k in 0..n {
        let (a, b) = (poly[k], poly[(k + 1) % n]);
        let (ua, ub) = (a.0 - a.1 - c, b.0 - b.1 - c);
        if (ua <= 0.0 && ub >= 0.0) || (ua >= 0.0 && ub <= 0.0) {
            if ua == ub {
                // The edge lies on the line: its ends are the chord's.
                ends.extend([a, b]);
            } else {
                let t = ua / (ua - ub);
                ends.push((a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)));
            }
        }
    }
    // Along the line x − y = c, points are ordered by x + y.
    let key = |p: &Point| p.0 + p.1;
    let lo = ends
        .iter()
        .copied()
        .min_by(|p, q| key(p).total_cmp(&key(q)))?;
    let hi = ends
        .iter()
        .copied()
        .max_by(|p, q| key(p).total_cmp(&key(q)))?;
    (key(&hi) > key(&lo)).then_some([lo, hi])
}

/// Hatch lines x − y = k `spacing` (k integer) over the convex `pieces`: one chord per line and
/// piece, so the lines run on unbroken across neighbouring pieces.
pub(super) fn hatch(pieces: &[Vec<Point>], spacing: f64) -> Vec<[Point; 2]> {
    let mut out = Vec::new();
    if !(spacing > 0.0 && spacing.is_finite()) {
        return out;
    }
    for poly in pieces {
        let (lo, hi) = poly
            .iter()
            .map(|p| p.0 - p.1)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), u| {
                (l.min(u), h.max(u))
            });
        if !(lo.is_finite() && hi.is_finite()) {
            continue;
        }
        let first = (lo / spacing).ceil() as i64;
        let last = (hi / spacing).floor() as i64;
        for k in first..=last {
            out.extend(hatch_chord(poly, k as f64 * spacing));
        }
    }
    out
}

/// The point `p` clamped to the plate (x0, x1) × (y0, y1).
fn clamp(p: Point, (x0, x1): (f64, f64), (y0, y1): (f64, f64)) -> Point {
    (
        p.0.clamp(x0.min(x1), x0.max(x1)),
        p.1.clamp(y0.min(y1), y0.max(y1)),
    )
}

/// The rectangle with corners `r`, clamped to the plate, as a closed path.
fn rectangle(r: &[(f64, f64); 2], xr: (f64, f64), yr: (f64, f64)) -> [Point; 5] {
    let (a, b) = (clamp(r[0], xr, yr), clamp(r[1], xr, yr));
    [a, (b.0, a.1), b, (a.0, b.1), a]
}

/// The area above `level` of the nodal `values`: its pieces hatched and its contour dashed over
/// a white halo. Returns whether anything lies above the level.
pub(super) fn draw_exceedance<DB: DrawingBackend>(
    chart: &mut Plan<'_, DB>,
    field: &FullField,
    values: &[f64],
    level: f64,
) -> DrawResult<bool> {
    let pieces = exceed::pieces_above(field, values, level).map_err(txt)?;
    if pieces.is_empty() {
        return Ok(false);
    }
    // Hatch spacing in plate units: HATCH_PX pixels along x (the plan is drawn to equal scale).
    let (x0, x1) = (field.x.first().copied(), field.x.last().copied());
    let spacing = match (x0, x1) {
        (Some(a), Some(b)) if b != a => {
            let pa = chart.backend_coord(&(a, 0.0)).0;
            let pb = chart.backend_coord(&(b, 0.0)).0;
            let px = f64::from((pb - pa).abs()) / (b - a).abs();
            HATCH_PX / px
        }
        _ => f64::NAN,
    };
    // Magenta on a thin white band: visible on the pale and the dark end of the ramp.
    let lines = hatch(&pieces, spacing);
    chart
        .draw_series(
            lines
                .iter()
                .map(|s| PathElement::new(*s, style::HATCH_HALO.stroke_width(3))),
        )
        .map_err(txt)?;
    chart
        .draw_series(
            lines
                .iter()
                .map(|s| PathElement::new(*s, style::EXCEEDED.stroke_width(1))),
        )
        .map_err(txt)?;
    let contour = exceed::level_contour(field, values, level).map_err(txt)?;
    chart
        .draw_series(
            contour
                .iter()
                .map(|l| PathElement::new(l.clone(), style::HALO.stroke_width(4))),
        )
        .map_err(txt)?;
    let (dash, gap) = style::DASH;
    for line in contour {
        chart
            .draw_series(DashedLineSeries::new(
                line,
                dash,
                gap,
                style::EXCEEDED.stroke_width(2),
            ))
            .map_err(txt)?;
    }
    Ok(true)
}

/// Voids (dashed), zones (dotted), line loads (thick) and the parts not counted (grey hatch)
/// of `overlay`, clamped to the plate (x0, x1) × (y0, y1).
pub(super) fn draw_features<DB: DrawingBackend>(
    chart: &mut Plan<'_, DB>,
    overlay: &Overlay,
    xr: (f64, f64),
    yr: (f64, f64),
) -> DrawResult<()> {
    if !overlay.cut.is_empty() {
        // Hatch spacing in plate units: HATCH_PX pixels along x (equal scales).
        let pa = chart.backend_coord(&(xr.0, yr.0)).0;
        let pb = chart.backend_coord(&(xr.1, yr.0)).0;
        let spacing = HATCH_PX * (xr.1 - xr.0).abs() / f64::from((pb - pa).abs().max(1));
        let pieces: Vec<Vec<Point>> = (overlay.cut.iter())
            .map(|r| {
                let [(a, b), (c, d)] = r.map(|p| clamp(p, xr, yr));
                vec![(a, b), (c, b), (c, d), (a, d)]
            })
            .collect();
        let lines = hatch(&pieces, spacing);
        for (colour, width) in [(style::HATCH_HALO, 3), (style::CUT.to_rgba(), 1)] {
            chart
                .draw_series(
                    (lines.iter()).map(|s| {
                        PathElement::new(*s, ShapeStyle::from(colour).stroke_width(width))
                    }),
                )
                .map_err(txt)?;
        }
    }
    chart
        .draw_series(overlay.zones.iter().map(|z| dotted(rectangle(z, xr, yr))))
        .map_err(txt)?;
    let (dash, gap) = style::DASH;
    for v in &overlay.voids {
        chart
            .draw_series(DashedLineSeries::new(
                rectangle(v, xr, yr),
                dash,
                gap,
                style::VOID.stroke_width(2),
            ))
            .map_err(txt)?;
    }
    chart
        .draw_series(overlay.lines.iter().map(|l| {
            PathElement::new(
                l.map(|p| clamp(p, xr, yr)),
                style::LINE_LOAD.stroke_width(LINE_LOAD_W),
            )
        }))
        .map_err(txt)?;
    chart
        .draw_series(
            overlay
                .prints
                .iter()
                .map(|r| PathElement::new(rectangle(r, xr, yr), style::PRINT.stroke_width(2))),
        )
        .map_err(txt)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Chords of x − y = c across the unit square: through its middle (c = 0) the diagonal,
    /// off it a shorter parallel one, outside it nothing.
    #[test]
    fn hatch_chords_of_the_unit_square() {
        let sq = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
        let d = hatch_chord(&sq, 0.0).expect("diagonal");
        assert_eq!(d, [(0.0, 0.0), (1.0, 1.0)]);
        let c = hatch_chord(&sq, 0.5).expect("chord");
        assert_eq!(c, [(0.5, 0.0), (1.0, 0.5)]);
        assert!(hatch_chord(&sq, 1.5).is_none(), "outside");
        assert!(hatch_chord(&sq, 1.0).is_none(), "touches a corner only");
        // Spacing 0.25: lines c = −0.75 … 0.75 cross the square's interior, ±1 touch corners.
        assert_eq!(hatch(&[sq.to_vec()], 0.25).len(), 7);
        assert!(hatch(&[sq.to_vec()], f64::NAN).is_empty());
    }

    #[test]
    fn features_are_clamped_to_the_plate() {
        let r = rectangle(&[(-3.0, 0.5), (0.5, 9.0)], (-1.0, 1.0), (-2.0, 2.0));
        assert_eq!(
            r,
            [
                (-1.0, 0.5),
                (0.5, 0.5),
                (0.5, 2.0),
                (-1.0, 2.0),
                (-1.0, 0.5)
            ]
        );
    }

    #[test]
    fn default_overlay_is_empty() {
        assert!(Overlay::default().is_empty());
        let o = Overlay {
            lines: vec![[(0.0, 0.0), (1.0, 0.0)]],
            ..Overlay::default()
        };
        assert!(!o.is_empty());
    }
}
