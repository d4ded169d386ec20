//! Where a nodal field exceeds a level: the area above it, its contour, and the part of each
//! element above it — the bearing check (contact pressure against the allowable one) and its
//! outline on the contact map.
//!
//! The field is the bilinear interpolant of nodal values on the whole-plate grid of a
//! [`FullField`], in its physical coordinates x, y, each element with its own corners: on a
//! plate cut by joints the two sides of a joint line are two edges with their own values, and
//! a contour ends on each side of the line.
//!
//! * **Area** ([`area_above`]): exact per element. {v > level} is the negative part of the
//!   bilinear field level − v, whose area [`negative_fraction`] integrates in closed form; the
//!   only error is round-off.
//! * **Contour** ([`level_contour`]): marching squares. Crossings on element edges are exact (the
//!   field is linear along an edge); inside an element the level set is a hyperbola arc, drawn as
//!   its chord (exact where the field is linear in the element). Each crossing is computed once
//!   per grid edge, so the segments of neighbouring elements share their end points bit for bit
//!   and chain into polylines.
//! * **Pieces** ([`pieces_above`]): the part of each element above the level, bounded by the same
//!   chords: the element minus the corners cut off below the level — a convex polygon — or, at
//!   a saddle whose centre lies below the level, two corner triangles. Their areas equal
//!   [`area_above`] where the field is linear in each element and differ by the chord-to-arc
//!   segments elsewhere (O(h³) per element the contour crosses).
//!
//! A node exactly at the level counts as not above it, as a lifted node counts as not in
//! contact; NaN values are never above.

use super::boundary::negative_fraction;
use super::field::FullField;
use crate::error::{Error, Result};

/// A point of the plate, (x, y) in the field's physical coordinates.
pub type Point = (f64, f64);

/// One element against the level.
struct Classified {
    /// Corners above the level.
    up: [bool; 4],
    /// The edges the level crosses, by edge number: grid edge index and crossing point.
    cross: [Option<(usize, Point)>; 4],
    /// Whether the element's centre lies above the level.
    centre: bool,
}

/// The grid of `field` with the nodal `values` and a `level`, checked to match.
struct Levelled<'a> {
    field: &'a FullField,
    values: &'a [f64],
    level: f64,
    /// On a jointed field: the edge number of each element edge (element ie + je nx, edge e),
    /// edges numbered by the pair of node copies they join, so that the two sides of a joint
    /// are two edges; empty on a plain grid (grid edges by arithmetic).
    edges: Vec<[usize; 4]>,
    /// The number of edges.
    n_edges: usize,
}

impl<'a> Levelled<'a> {
    /// Check that `values` and the coordinates of `field` cover its node copies.
    fn new(field: &'a FullField, values: &'a [f64], level: f64) -> Result<Self> {
        let nodes = field
            .nx
            .checked_add(1)
            .zip(field.ny.checked_add(1))
            .and_then(|(a, b)| a.checked_mul(b))
            .and_then(|g| g.checked_add(field.extra_grid.len()));
        let cells = field.nx.checked_mul(field.ny);
        let corners_ok = field
            .corners
            .as_ref()
            .is_none_or(|c| Some(c.len()) == cells && c.iter().flatten().all(|&k| Some(k) < nodes));
        match nodes {
            Some(n)
                if values.len() == n && field.x.len() == n && field.y.len() == n && corners_ok =>
            {
                let (edges, n_edges) = match &field.corners {
                    None => (
                        Vec::new(),
                        field.nx * (field.ny + 1) + (field.nx + 1) * field.ny,
                    ),
                    Some(corners) => {
                        let mut id = std::collections::HashMap::new();
                        let edges: Vec<[usize; 4]> = corners
                            .iter()
                            .map(|c| {
                                std::array::from_fn(|e| {
                                    let (a, b) = (c[e], c[(e + 1) % 4]);
                                    let next = id.len();
                                    *id.entry((a.min(b), a.max(b))).or_insert(next)
                                })
                            })
                            .collect();
                        (edges, id.len())
                    }
                };
                Ok(Self {
                    field,
                    values,
                    level,
                    edges,
                    n_edges,
                })
            }
            _ => Err(Error::invalid(
                "values",
                format!(
                    "{} nodal values and {} × {} coordinates do not cover the {} × {} element grid",
                    values.len(),
                    field.x.len(),
                    field.y.len(),
                    field.nx,
                    field.ny
                ),
            )),
        }
    }

    /// Whether node `k` lies strictly above the level.
    fn above(&self, k: usize) -> bool {
        self.values[k] > self.level
    }

    /// Corner nodes of element (i, j), counter-clockwise from (i, j): its own copies.
    fn cell(&self, i: usize, j: usize) -> [usize; 4] {
        self.field.element_nodes(i, j)
    }

    /// Number of edges: on a plain grid nx (ny + 1) along x, then (nx + 1) ny along y.
    fn n_edges(&self) -> usize {
        self.n_edges
    }

    /// Edge `e` of element (i, j) (0 bottom, 1 right, 2 top, 3 left: edge e runs from corner e
    /// to corner e + 1): its index and its end nodes in ascending order of the grid.
    fn edge(&self, i: usize, j: usize, e: usize) -> (usize, usize, usize) {
        let (nx, ny) = (self.field.nx, self.field.ny);
        if !self.edges.is_empty() {
            let c = self.cell(i, j);
            let (a, b) = if e < 2 {
                (c[e], c[e + 1])
            } else {
                (c[(e + 1) % 4], c[e])
            };
            return (self.edges[i + j * nx][e], a, b);
        }
        let n = nx + 1;
        let along_x = |i: usize, j: usize| (i + j * nx, i + j * n, i + 1 + j * n);
        let along_y = |i: usize, j: usize| (nx * (ny + 1) + i + j * n, i + j * n, i + (j + 1) * n);
        match e {
            0 => along_x(i, j),
            1 => along_y(i + 1, j),
            2 => along_x(i, j + 1),
            _ => along_y(i, j),
        }
    }

    /// Where the field reaches the level on the edge from node `a` to node `b` (one above it,
    /// one not): exact, the field being linear along the edge.
    fn crossing(&self, a: usize, b: usize) -> Point {
        let (va, vb) = (self.values[a], self.values[b]);
        let t = ((self.level - va) / (vb - va)).clamp(0.0, 1.0);
        let (x, y) = (&self.field.x, &self.field.y);
        (x[a] + t * (x[b] - x[a]), y[a] + t * (y[b] - y[a]))
    }

    /// Element (i, j) against the level.
    fn classify(&self, i: usize, j: usize) -> Classified {
        let c = self.cell(i, j);
        let up = c.map(|k| self.above(k));
        let mut cross = [None; 4];
        for (e, slot) in cross.iter_mut().enumerate() {
            if up[e] != up[(e + 1) % 4] {
                let (id, a, b) = self.edge(i, j, e);
                *slot = Some((id, self.crossing(a, b)));
            }
        }
        // The bilinear field's centre value is the mean of its corners.
        let centre = c.iter().map(|&k| self.values[k]).sum::<f64>() / 4.0 > self.level;
        Classified { up, cross, centre }
    }

    /// Corner `k` of element (i, j) as a point.
    fn corner(&self, i: usize, j: usize, k: usize) -> Point {
        let n = self.cell(i, j)[k];
        (self.field.x[n], self.field.y[n])
    }
}

/// Area where the bilinear interpolant of the nodal `values` on the grid of `field` exceeds
/// `level`, in the units of `field.x` × `field.y` (m² for a physical scene): exact per element,
/// up to round-off (module docs). For the bearing check, `values` is `field.pressure` and
/// `level` the allowable pressure in the same units.
///
/// # Errors
/// [`Error::Invalid`] if `values`, `field.x` or `field.y` do not have one entry per node copy.
pub fn area_above(field: &FullField, values: &[f64], level: f64) -> Result<f64> {
    let g = Levelled::new(field, values, level)?;
    let mut sum = 0.0;
    for j in 0..field.ny {
        for i in (0..field.nx).filter(|&i| field.is_plate(i, j)) {
            let c = g.cell(i, j);
            let (x0, y0) = g.corner(i, j, 0);
            let (x1, y1) = g.corner(i, j, 2);
            let area = ((x1 - x0) * (y1 - y0)).abs();
            sum += area * negative_fraction(c.map(|k| level - values[k]));
        }
    }
    Ok(sum)
}

/// The contour where the bilinear interpolant of `values` equals `level`, as polylines in the
/// field's (x, y): marching squares, one chord per element and branch (module docs). A closed
/// curve ends at its first point; an open one runs from plate edge to plate edge. A saddle
/// element is resolved by its centre value, as for the contact boundary.
///
/// # Errors
/// [`Error::Invalid`] if `values`, `field.x` or `field.y` do not have one entry per node copy.
pub fn level_contour(field: &FullField, values: &[f64], level: f64) -> Result<Vec<Vec<Point>>> {
    let g = Levelled::new(field, values, level)?;
    let n_edges = g.n_edges();
    let mut point: Vec<Option<Point>> = vec![None; n_edges];
    // Segments as pairs of edge indices, and up to two segments per edge.
    let mut segments: Vec<[usize; 2]> = Vec::new();
    const NONE: usize = usize::MAX;
    let mut at_edge = vec![[NONE; 2]; n_edges];
    for j in 0..field.ny {
        for i in (0..field.nx).filter(|&i| field.is_plate(i, j)) {
            let Classified { up, cross, centre } = g.classify(i, j);
            let mut pairs: Vec<(usize, usize)> = Vec::with_capacity(2);
            let crossed: Vec<usize> = (0..4).filter(|&e| cross[e].is_some()).collect();
            match crossed.as_slice() {
                &[a, b] => pairs.push((a, b)),
                [_, _, _, _] => {
                    // Saddle: cut off the corners whose state differs from the centre's.
                    for (k, &corner) in up.iter().enumerate() {
                        if corner != centre {
                            pairs.push(((k + 3) % 4, k));
                        }
                    }
                }
                _ => {}
            }
            for (a, b) in pairs {
                let (Some((ea, pa)), Some((eb, pb))) = (cross[a], cross[b]) else {
                    continue;
                };
                point[ea] = Some(pa);
                point[eb] = Some(pb);
                let s = segments.len();
                segments.push([ea, eb]);
                for e in [ea, eb] {
                    if let Some(slot) = at_edge[e].iter_mut().find(|x| **x == NONE) {
                        *slot = s;
                    }
                }
            }
        }
    }

    let mut used = vec![false; segments.len()];
    let mut lines = Vec::new();
    // Follow the chain from edge `start` through segment `first` until it ends or closes.
    let walk = |start: usize, first: usize, used: &mut Vec<bool>| {
        let mut pts: Vec<Point> = point[start].into_iter().collect();
        let (mut edge, mut seg) = (start, first);
        loop {
            used[seg] = true;
            let [a, b] = segments[seg];
            edge = if a == edge { b } else { a };
            pts.extend(point[edge]);
            match at_edge[edge]
                .iter()
                .find(|&&s| s != NONE && !used[s])
                .copied()
            {
                Some(next) => seg = next,
                None => break,
            }
        }
        pts
    };
    // Open curves first, from their ends on the plate's edge; then the closed ones.
    for e in 0..n_edges {
        let [s0, s1] = at_edge[e];
        if s0 != NONE && s1 == NONE && !used[s0] {
            lines.push(walk(e, s0, &mut used));
        }
    }
    for s in 0..segments.len() {
        if !used[s] {
            lines.push(walk(segments[s][0], s, &mut used));
        }
    }
    Ok(lines)
}

/// The part of each element where the bilinear interpolant of `values` exceeds `level`, as
/// convex polygons in the field's (x, y), counter-clockwise, bounded by the chords of
/// [`level_contour`] (module docs): for tinting or hatching the area above the level.
///
/// # Errors
/// [`Error::Invalid`] if `values`, `field.x` or `field.y` do not have one entry per node copy.
pub fn pieces_above(field: &FullField, values: &[f64], level: f64) -> Result<Vec<Vec<Point>>> {
    let g = Levelled::new(field, values, level)?;
    let mut out = Vec::new();
    for j in 0..field.ny {
        for i in (0..field.nx).filter(|&i| field.is_plate(i, j)) {
            let Classified { up, cross, centre } = g.classify(i, j);
            if !up.iter().any(|&u| u) {
                continue;
            }
            let saddle = cross.iter().all(Option::is_some);
            if saddle && !centre {
                // Two corner triangles around the corners above the level.
                for k in (0..4).filter(|&k| up[k]) {
                    if let (Some((_, p)), Some((_, q))) = (cross[(k + 3) % 4], cross[k]) {
                        out.push(vec![p, g.corner(i, j, k), q]);
                    }
                }
                continue;
            }
            // Walk the boundary counter-clockwise: corners above, and crossings between.
            let mut poly = Vec::with_capacity(6);
            for k in 0..4 {
                if up[k] {
                    poly.push(g.corner(i, j, k));
                }
                if let Some((_, p)) = cross[k] {
                    poly.push(p);
                }
            }
            out.push(poly);
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A grid of nx × ny elements over [−1, 1] × [−1, 1] with nodal values f(x, y).
    fn grid(nx: usize, ny: usize, f: impl Fn(f64, f64) -> f64) -> (FullField, Vec<f64>) {
        let mut field = crate::post::test_fixtures::bump().0;
        field.nx = nx;
        field.ny = ny;
        field.x.clear();
        field.y.clear();
        let mut v = Vec::new();
        for j in 0..=ny {
            for i in 0..=nx {
                let x = -1.0 + 2.0 * i as f64 / nx as f64;
                let y = -1.0 + 2.0 * j as f64 / ny as f64;
                field.x.push(x);
                field.y.push(y);
                v.push(f(x, y));
            }
        }
        (field, v)
    }

    /// Shoelace area of a polygon.
    fn polygon_area(p: &[Point]) -> f64 {
        let n = p.len();
        0.5 * (0..n)
            .map(|k| {
                let (a, b) = (p[k], p[(k + 1) % n]);
                a.0 * b.1 - b.0 * a.1
            })
            .sum::<f64>()
    }

    /// x + y > ½ on [−1, 1]²: the corner triangle with legs 1.5, area 1.125. The field is linear,
    /// so the pieces (chords) are exact too and each is counter-clockwise (positive area).
    #[test]
    fn area_and_pieces_of_a_linear_field_are_the_corner_triangle() {
        let (f, v) = grid(5, 7, |x, y| x + y);
        let a = area_above(&f, &v, 0.5).expect("area");
        assert!((a - 1.125).abs() < 1e-14, "area_above: {a}");
        let pieces = pieces_above(&f, &v, 0.5).expect("pieces");
        assert!(pieces.iter().all(|p| polygon_area(p) > 0.0), "orientation");
        let b: f64 = pieces.iter().map(|p| polygon_area(p)).sum();
        assert!((b - 1.125).abs() < 1e-14, "pieces_above: {b}");
    }

    /// x y > c on [−1, 1]² (bilinear in every element, so the interpolant is x y itself): two
    /// quadrants of area 1 − c + c ln c each.
    #[test]
    fn area_above_a_hyperbola_is_the_closed_form() {
        for (n, c) in [(4, 0.3_f64), (7, 0.05), (10, 0.6)] {
            let (f, v) = grid(n, n, |x, y| x * y);
            let exact = 2.0 * (1.0 - c + c * c.ln());
            let a = area_above(&f, &v, c).expect("area");
            assert!(
                (a - exact).abs() < 1e-13,
                "{n}×{n}, x y > {c}: {a} vs {exact}"
            );
            // The chords cut the convex side of the arcs: the pieces miss a little area.
            let b: f64 = pieces_above(&f, &v, c)
                .expect("pieces")
                .iter()
                .map(|p| polygon_area(p))
                .sum();
            assert!(b < a && b > a - 0.05, "{n}×{n}: pieces {b} vs {a}");
        }
    }

    /// Contour points lie on grid edges, where the bilinear field is exact: x y = c there to
    /// round-off, and the two branches are open curves from plate edge to plate edge.
    #[test]
    fn contour_of_a_bilinear_field_lies_on_the_level() {
        let (f, v) = grid(6, 6, |x, y| x * y);
        let lines = level_contour(&f, &v, 0.2).expect("contour");
        assert_eq!(lines.len(), 2, "two branches of x y = 0.2");
        for line in &lines {
            assert!(line.len() >= 3, "{line:?}");
            for &(x, y) in line {
                // A few ulps of O(1) numbers.
                assert!((x * y - 0.2).abs() < 1e-14, "({x}, {y}) off the level");
            }
            let (first, last) = (line[0], line[line.len() - 1]);
            let on_edge = |p: Point| p.0.abs() == 1.0 || p.1.abs() == 1.0;
            assert!(on_edge(first) && on_edge(last), "{first:?} {last:?}");
        }
    }

    /// A bump's level curve closes: one polyline whose last point is its first.
    #[test]
    fn contour_of_a_bump_is_one_closed_curve() {
        let (f, v) = grid(8, 8, |x, y| 1.0 - x * x - y * y);
        let lines = level_contour(&f, &v, 0.5).expect("contour");
        assert_eq!(lines.len(), 1);
        let l = &lines[0];
        assert_eq!(l.first(), l.last(), "closed");
        // Every point is a crossing of the linear interpolant along a grid edge, which lies below
        // the concave field by at most h² max|f''| / 8 = 0.25² · 2 / 8 = 1/64: so
        // ½ − 1/64 ≤ x² + y² ≤ ½ (plus round-off).
        for &(x, y) in l {
            let r2 = x * x + y * y;
            assert!(
                (0.5 - 1.0 / 64.0 - 1e-14..=0.5 + 1e-14).contains(&r2),
                "({x}, {y}): r² = {r2}"
            );
        }
    }

    #[test]
    fn nothing_above_gives_nothing_and_bad_lengths_are_errors() {
        let (f, v) = grid(3, 2, |x, _| x);
        assert_eq!(area_above(&f, &v, 2.0).expect("area"), 0.0);
        assert!(level_contour(&f, &v, 2.0).expect("contour").is_empty());
        assert!(pieces_above(&f, &v, 2.0).expect("pieces").is_empty());
        assert_eq!(area_above(&f, &v, -2.0).expect("area"), 4.0, "all above");
        assert!(area_above(&f, &v[1..], 0.0).is_err());
        assert!(level_contour(&f, &v[1..], 0.0).is_err());
        assert!(pieces_above(&f, &[], 0.0).is_err());
    }

    /// A field that steps at a joint: s on the grid nodes, 1 on the + side's copies of the line
    /// s = 0 (the jointed 4 × 2 fixture over x = 2s ∈ [−2, 2], y = t ∈ [−1, 1]). Above 0.75:
    /// on the + side, element column 2 falls from 1 to 0.5 (above it for s < 0.25, x < 0.5)
    /// and column 3 rises from 0.5 to 1 (above it for s > 0.75, x > 1.5): two strips 0.5 wide,
    /// area 2, and two open contours at x = 0.5 and x = 1.5, each from edge to edge — where the
    /// same values read through the grid alone (no joint) give one strip, area 1.
    #[test]
    fn a_jointed_field_is_read_element_by_element() {
        let (mut f, _) = crate::post::test_fixtures::jointed();
        let n_grid = f.n_grid();
        let v: Vec<f64> = (0..f.n_nodes())
            .map(|k| if k < n_grid { f.s[k] } else { 1.0 })
            .collect();
        // Linear along each element: exact to round-off.
        let area = area_above(&f, &v, 0.75).expect("area");
        assert!((area - 2.0).abs() < 1e-14, "jointed area {area}");
        let mut lines = level_contour(&f, &v, 0.75).expect("contour");
        lines.sort_by(|a, b| a[0].0.total_cmp(&b[0].0));
        assert_eq!(lines.len(), 2, "{lines:?}");
        for (line, x) in lines.iter().zip([0.5, 1.5]) {
            assert!(line.iter().all(|p| (p.0 - x).abs() < 1e-14), "{line:?}");
            let ys: Vec<f64> = line.iter().map(|p| p.1).collect();
            assert!(
                ys.contains(&-1.0) && ys.contains(&1.0),
                "edge to edge: {ys:?}"
            );
        }
        let pieces: f64 = pieces_above(&f, &v, 0.75)
            .expect("pieces")
            .iter()
            .map(|p| polygon_area(p))
            .sum();
        assert!((pieces - 2.0).abs() < 1e-14, "pieces {pieces}");
        // The grid alone.
        f.corners = None;
        f.extra_grid.clear();
        f.x.truncate(n_grid);
        f.y.truncate(n_grid);
        let area = area_above(&f, &v[..n_grid], 0.75).expect("area");
        assert!((area - 1.0).abs() < 1e-14, "plain area {area}");
    }
}
