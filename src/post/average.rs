//! Averages of a nodal field over squares of the plate: the bearing check's pressure.
//!
//! The field is the bilinear interpolant of nodal values on the whole-plate grid of a
//! [`FullField`] (uniform elements, each with its own corners, so the two sides of a joint line
//! keep their own values). Its integral over any axis-parallel rectangle is exact up to
//! round-off: the mean of a bilinear function over a rectangle is its value at the rectangle's
//! centre, so each element contributes its area inside the rectangle times its value at the
//! centre of that piece. Summed-area tables of the elements' integrals and of their edge means
//! give the integral from the plate's lower left corner to any point, F(X, Y), in O(1), and
//! the integral over a rectangle as F(X₁, Y₁) − F(X₀, Y₁) − F(X₁, Y₀) + F(X₀, Y₀).
//!
//! [`largest_square_average`] tries one square of side a per grid node, centred at the node
//! and shifted inwards where it would cross the plate's edge (at a corner: the corner square),
//! so that every square lies wholly on the plate.

use super::field::FullField;
use crate::foundation::FoundationKind;

/// Integrals of the bilinear interpolant of nodal values over rectangles of a uniform grid.
pub struct RectIntegrals {
    nx: usize,
    ny: usize,
    x0: f64,
    y0: f64,
    hx: f64,
    hy: f64,
    /// Σ of the element means over elements ie < i, je < j, at i + j (nx + 1).
    full: Vec<f64>,
    /// Per element column i < nx: Σ over je < j of the mean of the left (`.0`) and right
    /// (`.1`) edges, at i + j nx, j ≤ ny.
    column: Vec<(f64, f64)>,
    /// Per element row j < ny: Σ over ie < i of the mean of the bottom and top edges, at
    /// i + j (nx + 1), i ≤ nx.
    row: Vec<(f64, f64)>,
    /// The four corner values of each element, counter-clockwise from its lower left.
    corners: Vec<[f64; 4]>,
}

impl RectIntegrals {
    /// The tables of `values` (one per node copy of `field`); None if the lengths do not
    /// match, the grid is empty, or the plate has no extent.
    pub fn new(field: &FullField, values: &[f64]) -> Option<Self> {
        let (nx, ny) = (field.nx, field.ny);
        if nx == 0
            || ny == 0
            || values.len() != field.n_nodes()
            || field.x.len() != values.len()
            || field.y.len() != values.len()
        {
            return None;
        }
        let n = nx + 1;
        let (x0, y0) = (field.x[0], field.y[0]);
        let hx = (field.x[nx] - x0) / nx as f64;
        let hy = (field.y[ny * n] - y0) / ny as f64;
        if !(hx > 0.0 && hy > 0.0) {
            return None;
        }
        let mut corners = Vec::with_capacity(nx * ny);
        for j in 0..ny {
            for i in 0..nx {
                let c = field.element_nodes(i, j);
                if c.iter().any(|&k| k >= values.len()) {
                    return None;
                }
                corners.push(c.map(|k| values[k]));
            }
        }
        let mut full = vec![0.0; n * (ny + 1)];
        for j in 0..ny {
            for i in 0..nx {
                let c = corners[i + j * nx];
                let mean = 0.25 * (c[0] + c[1] + c[2] + c[3]);
                full[i + 1 + (j + 1) * n] =
                    mean + full[i + (j + 1) * n] + full[i + 1 + j * n] - full[i + j * n];
            }
        }
        let mut column = vec![(0.0, 0.0); nx * (ny + 1)];
        for i in 0..nx {
            for j in 0..ny {
                let c = corners[i + j * nx];
                let (l, r) = column[i + j * nx];
                column[i + (j + 1) * nx] = (l + 0.5 * (c[0] + c[3]), r + 0.5 * (c[1] + c[2]));
            }
        }
        let mut row = vec![(0.0, 0.0); n * ny];
        for j in 0..ny {
            for i in 0..nx {
                let c = corners[i + j * nx];
                let (b, t) = row[i + j * n];
                row[i + 1 + j * n] = (b + 0.5 * (c[0] + c[1]), t + 0.5 * (c[3] + c[2]));
            }
        }
        Some(Self {
            nx,
            ny,
            x0,
            y0,
            hx,
            hy,
            full,
            column,
            row,
            corners,
        })
    }

    /// The plate's extent: [x_min, x_max] and [y_min, y_max].
    pub fn extent(&self) -> ([f64; 2], [f64; 2]) {
        (
            [self.x0, self.x0 + self.nx as f64 * self.hx],
            [self.y0, self.y0 + self.ny as f64 * self.hy],
        )
    }

    /// The element index along one axis holding coordinate `v` and the fraction of it below
    /// `v` (`v` clamped to the plate).
    fn locate(v: f64, lo: f64, h: f64, n: usize) -> (usize, f64) {
        let f = ((v - lo) / h).clamp(0.0, n as f64);
        let k = (f.floor() as usize).min(n - 1);
        (k, (f - k as f64).clamp(0.0, 1.0))
    }

    /// ∫ over [x_min, X] × [y_min, Y] of the interpolant.
    fn cumulative(&self, x: f64, y: f64) -> f64 {
        let (i, u) = Self::locate(x, self.x0, self.hx, self.nx);
        let (j, v) = Self::locate(y, self.y0, self.hy, self.ny);
        let n = self.nx + 1;
        // Whole elements below and to the left.
        let mut sum = self.full[i + j * n];
        // Column i below row j: the strip [0, u] of each element, its mean over the strip's
        // width at ξ = u/2 of the left and right edge means.
        let (l, r) = self.column[i + j * self.nx];
        sum += u * ((1.0 - 0.5 * u) * l + 0.5 * u * r);
        // Row j left of column i: the strip [0, v].
        let (b, t) = self.row[i + j * n];
        sum += v * ((1.0 - 0.5 * v) * b + 0.5 * v * t);
        // Element (i, j) itself over [0, u] × [0, v]: its value at (u/2, v/2).
        let c = self.corners[i + j * self.nx];
        let (a, b) = (0.5 * u, 0.5 * v);
        let centre = c[0] * (1.0 - a) * (1.0 - b)
            + c[1] * a * (1.0 - b)
            + c[2] * a * b
            + c[3] * (1.0 - a) * b;
        sum += u * v * centre;
        sum * self.hx * self.hy
    }

    /// ∫ of the interpolant over the part of [x0, x1] × [y0, y1] on the plate.
    pub fn integral(&self, x: [f64; 2], y: [f64; 2]) -> f64 {
        self.cumulative(x[1], y[1]) - self.cumulative(x[0], y[1]) - self.cumulative(x[1], y[0])
            + self.cumulative(x[0], y[0])
    }
}

/// The largest average of the interpolant of `values` over a square of side `side` lying on the
/// plate, over the squares centred at the grid nodes (shifted inwards at the edges: module
/// docs), and the centre of that square. None when the tables cannot be built, the side is not
/// positive or exceeds a side of the plate, or every average is NaN.
pub fn largest_square_average(
    field: &FullField,
    values: &[f64],
    side: f64,
) -> Option<(f64, [f64; 2])> {
    let t = RectIntegrals::new(field, values)?;
    let ([xa, xb], [ya, yb]) = t.extent();
    let slack = 1e-12 * (xb - xa).max(yb - ya);
    if !(side > 0.0 && side <= (xb - xa).min(yb - ya) + slack) {
        return None;
    }
    let half = 0.5 * side;
    // The centre of a square on the plate nearest to `v` along one axis.
    let inside = |v: f64, lo: f64, hi: f64| {
        if hi - lo <= side {
            0.5 * (lo + hi)
        } else {
            v.clamp(lo + half, hi - half)
        }
    };
    let mut best: Option<(f64, [f64; 2])> = None;
    for k in 0..field.n_grid() {
        let cx = inside(field.x[k], xa, xb);
        let cy = inside(field.y[k], ya, yb);
        let mean = t.integral([cx - half, cx + half], [cy - half, cy + half]) / (side * side);
        if best.is_none_or(|(b, _)| mean > b) && !mean.is_nan() {
            best = Some((mean, [cx, cy]));
        }
    }
    best
}

/// Why the nodal peak pressure at the plate's edge on `kind` is not a design number, or None
/// where it is one (Winkler springs, and Kerr's soil, whose upper springs keep the pressure
/// bounded: c times a jump between two continuous deflections). `length` names the bearing
/// check's averaging square (already in words with its unit).
pub fn edge_note(kind: FoundationKind, length: &str) -> Option<String> {
    let why = edge_singularity(kind)?;
    Some(format!(
        "the contact pressure on the {} {why}: the nodal peak pressure at the edge grows as the mesh is refined and is not a design number; the bearing check uses the pressure averaged over squares of side {length} (bearing_length)",
        kind.names().label
    ))
}

/// How the contact pressure on `kind` is singular at the plate's edge, in words; None where it
/// is bounded ([`edge_note`]).
pub fn edge_singularity(kind: FoundationKind) -> Option<&'static str> {
    Some(match kind {
        FoundationKind::HalfSpace | FoundationKind::ElasticLayer => {
            "is singular at the plate's edge — integrable, like a rigid punch's ~ r^(−1/2) at a distance r from the edge (Boussinesq 1885; Sadowsky 1928; Johnson, Contact Mechanics, 1985, the flat-ended punch)"
        }
        FoundationKind::Pasternak => {
            "carries a concentrated line reaction at the plate's edge, where the shear layer's slope jumps (Kerr 1964) — integrable, but spread by the mesh over one element"
        }
        FoundationKind::Winkler | FoundationKind::Kerr => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A grid of nx × ny elements over [x0, x0 + lx] × [y0, y0 + ly] with nodal values f.
    fn grid(
        nx: usize,
        ny: usize,
        (x0, lx, y0, ly): (f64, f64, f64, f64),
        f: impl Fn(f64, f64) -> f64,
    ) -> (FullField, Vec<f64>) {
        let mut field = crate::post::test_fixtures::bump().0;
        field.nx = nx;
        field.ny = ny;
        field.x.clear();
        field.y.clear();
        field.extra_grid.clear();
        field.corners = None;
        let mut v = Vec::new();
        for j in 0..=ny {
            for i in 0..=nx {
                let x = x0 + lx * i as f64 / nx as f64;
                let y = y0 + ly * j as f64 / ny as f64;
                field.x.push(x);
                field.y.push(y);
                v.push(f(x, y));
            }
        }
        (field, v)
    }

    /// A brute-force reference: each element's piece of the rectangle by a 2 × 2 Gauss rule
    /// (exact for a bilinear function), the element's value from its own corners.
    fn gauss(field: &FullField, values: &[f64], x: [f64; 2], y: [f64; 2]) -> f64 {
        let n = field.nx + 1;
        let g = 0.5 / 3f64.sqrt();
        let mut sum = 0.0;
        for j in 0..field.ny {
            for i in 0..field.nx {
                let c = field.element_nodes(i, j);
                let (ex0, ey0) = (field.x[i], field.y[j * n]);
                let (ex1, ey1) = (field.x[i + 1], field.y[(j + 1) * n]);
                let (ax, bx) = (x[0].max(ex0), x[1].min(ex1));
                let (ay, by) = (y[0].max(ey0), y[1].min(ey1));
                if bx <= ax || by <= ay {
                    continue;
                }
                for px in [0.5 - g, 0.5 + g] {
                    for py in [0.5 - g, 0.5 + g] {
                        let xx = ax + px * (bx - ax);
                        let yy = ay + py * (by - ay);
                        let (a, b) = ((xx - ex0) / (ex1 - ex0), (yy - ey0) / (ey1 - ey0));
                        let v = values[c[0]] * (1.0 - a) * (1.0 - b)
                            + values[c[1]] * a * (1.0 - b)
                            + values[c[2]] * a * b
                            + values[c[3]] * (1.0 - a) * b;
                        sum += 0.25 * (bx - ax) * (by - ay) * v;
                    }
                }
            }
        }
        sum
    }

    /// A linear field's average over a square is its value at the square's centre — whatever
    /// the grid, and wherever the square's sides fall inside elements. The largest over the
    /// plate is the corner square at the field's highest corner.
    #[test]
    fn a_linear_field_averages_to_its_value_at_the_centre() {
        let f = |x: f64, y: f64| 3.0 + 2.0 * x - 0.7 * y;
        let (field, v) = grid(7, 5, (-6.0, 12.0, -4.0, 8.0), f);
        let t = RectIntegrals::new(&field, &v).expect("tables");
        for (cx, cy, a) in [(0.3, -1.1, 0.5), (-5.6, 3.55, 0.8), (4.1, 0.0, 2.9)] {
            let h = 0.5 * a;
            let mean = t.integral([cx - h, cx + h], [cy - h, cy + h]) / (a * a);
            assert!(
                (mean - f(cx, cy)).abs() < 1e-12,
                "({cx}, {cy}, {a}): {mean}"
            );
        }
        let (mean, at) = largest_square_average(&field, &v, 1.0).expect("largest");
        assert_eq!(at, [5.5, -3.5], "the corner square at (+x, −y)");
        assert!((mean - f(5.5, -3.5)).abs() < 1e-12, "{mean}");
    }

    /// x y over [0, 2]² (bilinear in each element, so the interpolant is x y itself): its
    /// integral over [a, b] × [c, d] is (b² − a²)(d² − c²)/4 by hand.
    #[test]
    fn a_bilinear_field_integrates_by_hand() {
        let (field, v) = grid(6, 4, (0.0, 2.0, 0.0, 2.0), |x, y| x * y);
        let t = RectIntegrals::new(&field, &v).expect("tables");
        for (x, y) in [([0.1, 1.7], [0.35, 1.2]), ([0.0, 2.0], [0.0, 2.0])] {
            let exact = (x[1] * x[1] - x[0] * x[0]) * (y[1] * y[1] - y[0] * y[0]) / 4.0;
            let got = t.integral(x, y);
            assert!(
                (got - exact).abs() < 1e-13,
                "{x:?} × {y:?}: {got} vs {exact}"
            );
        }
    }

    /// Any nodal field, jointed (each side of the joint its own values): the tables agree with
    /// element-by-element Gauss integration to round-off.
    #[test]
    fn the_tables_agree_with_gauss_on_a_jointed_field() {
        let (field, _) = crate::post::test_fixtures::jointed();
        let n_grid = field.n_grid();
        let v: Vec<f64> = (0..field.n_nodes())
            .map(|k| {
                if k < n_grid {
                    (k as f64 * 0.37).sin()
                } else {
                    5.0 + k as f64
                }
            })
            .collect();
        let t = RectIntegrals::new(&field, &v).expect("tables");
        for (x, y) in [
            ([-1.9, 1.3], [-0.8, 0.9]),
            ([-0.4, 0.7], [-1.0, 1.0]),
            ([0.0, 2.0], [-1.0, 0.25]),
            ([-2.0, 2.0], [-1.0, 1.0]),
        ] {
            let (a, b) = (t.integral(x, y), gauss(&field, &v, x, y));
            assert!((a - b).abs() < 1e-13, "{x:?} × {y:?}: {a} vs {b}");
        }
    }

    #[test]
    fn a_side_off_the_plate_or_a_short_field_gives_none() {
        let (field, v) = grid(4, 2, (0.0, 4.0, 0.0, 2.0), |x, _| x);
        assert!(largest_square_average(&field, &v, 0.0).is_none());
        assert!(largest_square_average(&field, &v, 2.5).is_none());
        assert!(largest_square_average(&field, &v[1..], 1.0).is_none());
        // The whole width: the square at the right end.
        let (mean, at) = largest_square_average(&field, &v, 2.0).expect("largest");
        assert_eq!(at, [3.0, 1.0]);
        assert!((mean - 3.0).abs() < 1e-14);
    }
}
