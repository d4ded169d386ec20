//! Plates of any outline on the structured grid. An outline is a polygon whose edges run along
//! the grid's lines; on the grid it is a mask of cells — a cell is plate when its centre is
//! inside the polygon — and openings remove the cells inside theirs. The scene checks the
//! polygons here ([`check_polygon`]) and the loads against the mask ([`CellMask::holds_point`],
//! [`CellMask::covers`]); the model's grid keeps the mask in its topology
//! ([`super::Topology`]). An edge that does not run along a
//! grid line would become a staircase of spurious re-entrant corners, so it is refused, naming
//! the mesh that would put it on one.
//!
//! Coordinates are the scene's: the plate's bounding box is [−a/2, a/2] × [−b/2, b/2] with
//! `elements` = [nx, ny] cells over it. Cells are numbered i + j nx from the lower left.

use crate::error::{Error, Result};
use crate::layout::Layout;

/// Which of the grid's cells are plate.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CellMask {
    /// Cells along x.
    pub nx: usize,
    /// Cells along y.
    pub ny: usize,
    /// `true` where the cell i + j nx is plate.
    pub plate: Vec<bool>,
}

/// The cells of `n` along one axis that the interval [f0, f1] (in cells) overlaps with positive
/// length.
fn overlapped(f: [f64; 2], n: usize) -> std::ops::Range<usize> {
    let tol = 1e-9;
    let lo = (f[0] + tol).floor().max(0.0) as usize;
    let hi = ((f[1] - tol).ceil().max(1.0) as usize).min(n);
    lo.min(n)..hi
}

/// The largest multiple of the element counts [`check_polygon`] tries when it names the mesh
/// that would put every vertex on a grid line.
const MAX_REFINEMENT: usize = 64;

impl CellMask {
    /// Every cell plate: the bounding rectangle.
    pub fn full(nx: usize, ny: usize) -> Self {
        Self {
            nx,
            ny,
            plate: vec![true; nx * ny],
        }
    }

    /// The cells whose centres lie inside the polygon `corners` (grid indices of its vertices,
    /// as [`check_polygon`] returns them): the even–odd rule, counting the polygon's vertical
    /// edges that a ray from the centre towards +x crosses.
    pub fn inside(nx: usize, ny: usize, corners: &[[usize; 2]]) -> Self {
        let n = corners.len();
        let mut plate = vec![false; nx * ny];
        for j in 0..ny {
            let yc = j as f64 + 0.5;
            for i in 0..nx {
                let xc = i as f64 + 0.5;
                let mut crossings = 0;
                for k in 0..n {
                    let [x0, y0] = corners[k];
                    let [x1, y1] = corners[(k + 1) % n];
                    if x0 == x1 {
                        let (lo, hi) = (y0.min(y1) as f64, y0.max(y1) as f64);
                        if lo < yc && yc < hi && (x0 as f64) > xc {
                            crossings += 1;
                        }
                    }
                }
                plate[i + j * nx] = crossings % 2 == 1;
            }
        }
        Self { nx, ny, plate }
    }

    /// The plate cells of a layout's outline and openings (unit system) on the whole plate
    /// [−1, 1] × [−μ, μ] of `elements` cells.
    pub fn of_layout(layout: &Layout, elements: [usize; 2], mu: f64) -> Self {
        let [nx, ny] = elements;
        let (hx, hy) = (2.0 / nx as f64, 2.0 * mu / ny as f64);
        let plate = (0..nx * ny)
            .map(|c| {
                let (i, j) = (c % nx, c / nx);
                layout.is_plate(-1.0 + (i as f64 + 0.5) * hx, -mu + (j as f64 + 0.5) * hy)
            })
            .collect();
        Self { nx, ny, plate }
    }

    /// True when cell (i, j) exists and is plate (false off the grid, so that a neighbour's
    /// index may run past an edge).
    pub fn at(&self, i: isize, j: isize) -> bool {
        i >= 0
            && j >= 0
            && (i as usize) < self.nx
            && (j as usize) < self.ny
            && self.plate[i as usize + j as usize * self.nx]
    }

    /// True when the mask is its own mirror image about the box's middle line x = const
    /// (`about_x`) or y = const.
    pub fn symmetric(&self, about_x: bool) -> bool {
        let (nx, ny) = (self.nx, self.ny);
        (0..nx * ny).all(|c| {
            let (i, j) = (c % nx, c / nx);
            let m = if about_x {
                (nx - 1 - i) + j * nx
            } else {
                i + (ny - 1 - j) * nx
            };
            self.plate[c] == self.plate[m]
        })
    }

    /// True when some plate cell's closure holds the point (fx, fy), given in cells from the
    /// box's lower-left corner (a tolerance of 1e-9 cells: a point on the outline is on the
    /// plate).
    pub fn holds_point(&self, fx: f64, fy: f64) -> bool {
        let tol = 1e-9;
        let range = |f: f64, n: usize| {
            let lo = (f - tol).floor().max(0.0) as usize;
            let hi = ((f + tol).floor().max(0.0) as usize).min(n - 1);
            lo.min(n - 1)..=hi
        };
        range(fx, self.nx).any(|i| range(fy, self.ny).any(|j| self.plate[i + j * self.nx]))
    }

    /// True when every cell that the rectangle [fx0, fx1] × [fy0, fy1] (in cells from the box's
    /// lower-left corner) overlaps with positive area is plate.
    pub fn covers(&self, fx: [f64; 2], fy: [f64; 2]) -> bool {
        let (xs, ys) = (overlapped(fx, self.nx), overlapped(fy, self.ny));
        xs.into_iter()
            .all(|i| ys.clone().all(|j| self.plate[i + j * self.nx]))
    }

    /// [`Self::covers`] for the rectangle x × y in the unit system of a whole plate [−1, 1] ×
    /// [−μ, μ] of `elements` cells, read from a layout's shape cell by cell (by the cells'
    /// centres, as [`Self::of_layout`]) without building the whole mask: the cells under a
    /// tire print, for a load moved over many positions.
    pub fn layout_covers(
        layout: &Layout,
        elements: [usize; 2],
        mu: f64,
        x: [f64; 2],
        y: [f64; 2],
    ) -> bool {
        let [nx, ny] = elements;
        let (hx, hy) = (2.0 / nx as f64, 2.0 * mu / ny as f64);
        let f = |v: [f64; 2], lo: f64, h: f64| [(v[0] - lo) / h, (v[1] - lo) / h];
        let ys = overlapped(f(y, -mu, hy), ny);
        overlapped(f(x, -1.0, hx), nx).all(|i| {
            ys.clone()
                .all(|j| layout.is_plate(-1.0 + (i as f64 + 0.5) * hx, -mu + (j as f64 + 0.5) * hy))
        })
    }

    /// The plate's cells as rectangles [i0, i1) × [j0, j1) of cells: runs along each row,
    /// a run extended upwards while the next row has the same run (so a rectangle is one).
    pub fn rectangles(&self) -> Vec<[usize; 4]> {
        let mut done: Vec<[usize; 4]> = Vec::new();
        let mut open: Vec<[usize; 4]> = Vec::new();
        for j in 0..self.ny {
            let mut runs = Vec::new();
            let mut i = 0;
            while i < self.nx {
                if !self.plate[i + j * self.nx] {
                    i += 1;
                    continue;
                }
                let start = i;
                while i < self.nx && self.plate[i + j * self.nx] {
                    i += 1;
                }
                runs.push((start, i));
            }
            let mut next = Vec::with_capacity(runs.len());
            for (i0, i1) in runs {
                match open.iter().position(|r| r[0] == i0 && r[1] == i1) {
                    Some(k) => {
                        let mut r = open.swap_remove(k);
                        r[3] = j + 1;
                        next.push(r);
                    }
                    None => next.push([i0, i1, j, j + 1]),
                }
            }
            done.append(&mut open);
            open = next;
        }
        done.append(&mut open);
        done.sort_unstable_by_key(|r| (r[2], r[0]));
        done
    }

    /// This mask without the cells of `opening` (a mask of the same grid).
    pub fn without(&self, opening: &CellMask) -> Self {
        Self {
            plate: self
                .plate
                .iter()
                .zip(&opening.plate)
                .map(|(&p, &o)| p && !o)
                .collect(),
            ..self.clone()
        }
    }

    /// The number of plate cells.
    pub fn count(&self) -> usize {
        self.plate.iter().filter(|&&p| p).count()
    }

    /// The plate's pieces: cells joined through a shared edge, each piece's cells in
    /// increasing order, the pieces by their first cell. Two cells that touch at a corner
    /// only are not joined (they would share one node: a hinge, not a slab).
    pub fn pieces(&self) -> Vec<Vec<usize>> {
        let (nx, ny) = (self.nx, self.ny);
        let mut piece = vec![usize::MAX; nx * ny];
        let mut out: Vec<Vec<usize>> = Vec::new();
        for start in 0..nx * ny {
            if !self.plate[start] || piece[start] != usize::MAX {
                continue;
            }
            let id = out.len();
            let mut cells = vec![start];
            piece[start] = id;
            let mut k = 0;
            while k < cells.len() {
                let c = cells[k];
                let (i, j) = (c % nx, c / nx);
                let mut next = Vec::with_capacity(4);
                if i > 0 {
                    next.push(c - 1);
                }
                if i + 1 < nx {
                    next.push(c + 1);
                }
                if j > 0 {
                    next.push(c - nx);
                }
                if j + 1 < ny {
                    next.push(c + nx);
                }
                for m in next {
                    if self.plate[m] && piece[m] == usize::MAX {
                        piece[m] = id;
                        cells.push(m);
                    }
                }
                k += 1;
            }
            cells.sort_unstable();
            out.push(cells);
        }
        out
    }
}

/// The grid indices of a polygon's vertices, after checking that it is a simple polygon with
/// edges along the grid's lines inside the plate's bounding box [−a/2, a/2] × [−b/2, b/2]
/// (`size` = [a, b]) of `elements` = [nx, ny] cells. A closing vertex equal to the first is
/// dropped. Errors name `field` (`plate.outline`, `opening[2].outline`) and the fix, and give
/// lengths in `unit` (`Some("m")`; None where the coordinates have none, as a dimensionless
/// scene's s and t).
pub fn check_polygon(
    vertices: &[[f64; 2]],
    size: [f64; 2],
    elements: [usize; 2],
    field: &str,
    unit: Option<&str>,
) -> Result<Vec<[usize; 2]>> {
    let unit = unit.map_or(String::new(), |u| format!(" {u}"));
    let mut v: Vec<[f64; 2]> = vertices.to_vec();
    if v.len() > 1 && v.first() == v.last() {
        v.pop();
    }
    if v.len() < 4 {
        return Err(Error::invalid(
            field,
            format!(
                "an outline along the grid's lines has at least 4 corners, got {}",
                v.len()
            ),
        ));
    }
    let [a, b] = size;
    let [nx, ny] = elements;
    // Each vertex as a fraction of the box, then as grid indices.
    let frac = |p: [f64; 2]| [(p[0] + a / 2.0) / a, (p[1] + b / 2.0) / b];
    for (k, &p) in v.iter().enumerate() {
        let [fx, fy] = frac(p);
        let tol = 1e-9;
        let inside = (-tol..=1.0 + tol).contains(&fx) && (-tol..=1.0 + tol).contains(&fy);
        if !(p[0].is_finite() && p[1].is_finite() && inside) {
            return Err(Error::invalid(
                format!("{field}[{k}]"),
                format!(
                    "({}, {}){unit} lies outside the plate's {a} × {b}{unit} box [{}, {}] × [{}, {}]",
                    p[0],
                    p[1],
                    -a / 2.0,
                    a / 2.0,
                    -b / 2.0,
                    b / 2.0
                ),
            ));
        }
    }
    let on = |f: f64, n: usize| (f * n as f64 - (f * n as f64).round()).abs() < 1e-6;
    if let Some(k) = v
        .iter()
        .position(|&p| !(on(frac(p)[0], nx) && on(frac(p)[1], ny)))
    {
        // The least refinement of each count that puts every vertex on a grid line.
        let fits = |n: usize, axis: usize| {
            (1..=MAX_REFINEMENT)
                .map(|m| m * n)
                .find(|&m| v.iter().all(|&p| on(frac(p)[axis], m)))
        };
        let hint = match (fits(nx, 0), fits(ny, 1)) {
            (Some(mx), Some(my)) => format!(
                "a mesh of [{mx}, {my}] elements puts every corner on a grid line"
            ),
            _ => format!(
                "no mesh of up to {MAX_REFINEMENT} times [{nx}, {ny}] elements does: put the corners on a common grid"
            ),
        };
        return Err(Error::invalid(
            format!("{field}[{k}]"),
            format!(
                "({}, {}){unit} is not on a grid line of the [{nx}, {ny}] mesh (cells {} × {}{unit}); an edge off the grid would become a staircase of false re-entrant corners; {hint}",
                v[k][0],
                v[k][1],
                a / nx as f64,
                b / ny as f64
            ),
        ));
    }
    let corners: Vec<[usize; 2]> = v
        .iter()
        .map(|&p| {
            let [fx, fy] = frac(p);
            [
                (fx * nx as f64).round() as usize,
                (fy * ny as f64).round() as usize,
            ]
        })
        .collect();
    let n = corners.len();
    for k in 0..n {
        let (p, q) = (corners[k], corners[(k + 1) % n]);
        if p == q {
            return Err(Error::invalid(
                format!("{field}[{k}]"),
                "repeats the corner before it: give each corner once",
            ));
        }
        if p[0] != q[0] && p[1] != q[1] {
            return Err(Error::invalid(
                format!("{field}[{k}]"),
                format!(
                    "the edge from ({}, {}) to ({}, {}) runs along neither x nor y: an outline on the structured grid has edges along its lines only",
                    v[k][0],
                    v[k][1],
                    v[(k + 1) % n][0],
                    v[(k + 1) % n][1]
                ),
            ));
        }
    }
    // Simple: no two edges meet except adjacent ones at their shared corner, and adjacent
    // ones do not fold back onto each other.
    let edge = |k: usize| (corners[k], corners[(k + 1) % n]);
    for k in 0..n {
        for m in k + 1..n {
            let adjacent = m == k + 1 || (k == 0 && m == n - 1);
            let (p, q) = (edge(k), edge(m));
            let touch = segments_touch(p, q);
            let folds = adjacent && overlap_length(p, q) > 0;
            if (!adjacent && touch) || folds {
                return Err(Error::invalid(
                    field,
                    format!(
                        "edges {k} and {m} {}: the outline must be a simple polygon (one boundary that does not cross or touch itself)",
                        if folds { "fold back onto each other" } else { "cross or touch" }
                    ),
                ));
            }
        }
    }
    Ok(corners)
}

/// Whether two axis-parallel segments of grid indices share a point.
fn segments_touch(p: ([usize; 2], [usize; 2]), q: ([usize; 2], [usize; 2])) -> bool {
    let span = |s: ([usize; 2], [usize; 2]), d: usize| (s.0[d].min(s.1[d]), s.0[d].max(s.1[d]));
    (0..2).all(|d| {
        let (a0, a1) = span(p, d);
        let (b0, b1) = span(q, d);
        a0 <= b1 && b0 <= a1
    })
}

/// The length two collinear axis-parallel segments share (0 when they are not collinear).
fn overlap_length(p: ([usize; 2], [usize; 2]), q: ([usize; 2], [usize; 2])) -> usize {
    for d in 0..2 {
        let o = 1 - d;
        let (pc, qc) = (p.0[o] == p.1[o], q.0[o] == q.1[o]);
        if pc && qc && p.0[o] == q.0[o] {
            let (a0, a1) = (p.0[d].min(p.1[d]), p.0[d].max(p.1[d]));
            let (b0, b1) = (q.0[d].min(q.1[d]), q.0[d].max(q.1[d]));
            return a1.min(b1).saturating_sub(a0.max(b0));
        }
    }
    0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An L of a 4 × 4 box with its upper-right quarter cut away, on an 8 × 8 grid.
    const L: [[f64; 2]; 6] = [
        [-2.0, -2.0],
        [2.0, -2.0],
        [2.0, 0.0],
        [0.0, 0.0],
        [0.0, 2.0],
        [-2.0, 2.0],
    ];

    fn field(r: Result<Vec<[usize; 2]>>) -> (String, String) {
        match r {
            Err(Error::Invalid { field, message }) => (field, message),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn an_l_is_three_quarters_of_its_box_in_one_piece() {
        let corners = check_polygon(&L, [4.0, 4.0], [8, 8], "plate.outline", Some("m")).expect("L");
        let m = CellMask::inside(8, 8, &corners);
        assert_eq!(m.count(), 48);
        // The cut-away quarter: cells i, j ≥ 4.
        assert!(!m.plate[5 + 5 * 8] && m.plate[5 + 2 * 8] && m.plate[2 + 5 * 8]);
        assert_eq!(m.pieces().len(), 1);
        // The L as the box less a square opening over the cut-away quarter: the same cells.
        let square = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
        let hole =
            check_polygon(&square, [4.0, 4.0], [8, 8], "opening[0]", Some("m")).expect("square");
        assert_eq!(
            CellMask::full(8, 8).without(&CellMask::inside(8, 8, &hole)),
            m
        );
    }

    /// The L's cells are two rectangles: the lower half and the upper-left quarter, which
    /// cover each cell once.
    #[test]
    fn an_l_is_two_rectangles() {
        let corners = check_polygon(&L, [4.0, 4.0], [8, 8], "plate.outline", Some("m")).expect("L");
        let m = CellMask::inside(8, 8, &corners);
        assert_eq!(m.rectangles(), vec![[0, 8, 0, 4], [0, 4, 4, 8]]);
        assert_eq!(CellMask::full(3, 2).rectangles(), vec![[0, 3, 0, 2]]);
    }

    #[test]
    fn an_opening_across_the_plate_leaves_two_pieces() {
        let slot = [[-0.5, -2.0], [0.5, -2.0], [0.5, 2.0], [-0.5, 2.0]];
        let hole = check_polygon(&slot, [4.0, 4.0], [8, 8], "opening[0]", Some("m")).expect("slot");
        let m = CellMask::full(8, 8).without(&CellMask::inside(8, 8, &hole));
        let pieces = m.pieces();
        assert_eq!(pieces.len(), 2);
        assert_eq!(pieces[0].len() + pieces[1].len(), 48);
        // Two cells that touch at a corner only are two pieces.
        let mut diagonal = CellMask::full(2, 2);
        diagonal.plate = vec![true, false, false, true];
        assert_eq!(diagonal.pieces().len(), 2);
    }

    #[test]
    fn bad_outlines_are_refused_naming_the_corner_and_the_fix() {
        let size = [4.0, 4.0];
        // Off the grid: 0.3 is not a multiple of 0.5; a 40 × 8 mesh puts it on one.
        let mut off = L;
        off[2] = [2.0, 0.3];
        off[3] = [0.0, 0.3];
        let (f, m) = field(check_polygon(
            &off,
            size,
            [8, 8],
            "plate.outline",
            Some("m"),
        ));
        assert_eq!(f, "plate.outline[2]");
        assert!(m.contains("a mesh of [8, 40] elements"), "{m}");
        // A diagonal edge.
        let tri = [[-2.0, -2.0], [2.0, -2.0], [2.0, 2.0], [0.0, 2.0]];
        let (f, m) = field(check_polygon(
            &tri,
            size,
            [8, 8],
            "plate.outline",
            Some("m"),
        ));
        assert_eq!(f, "plate.outline[3]");
        assert!(m.contains("runs along neither x nor y"), "{m}");
        // A bow tie of axis-parallel edges: edges 1 and 4 cross.
        let bow = [
            [-2.0, -2.0],
            [0.0, -2.0],
            [0.0, 2.0],
            [1.0, 2.0],
            [1.0, 0.0],
            [-2.0, 0.0],
        ];
        let (f, m) = field(check_polygon(
            &bow,
            size,
            [8, 8],
            "plate.outline",
            Some("m"),
        ));
        assert_eq!(f, "plate.outline");
        assert!(m.contains("cross or touch"), "{m}");
        // Outside the box, and too few corners.
        let mut out = L;
        out[0] = [-2.5, -2.0];
        let (f, m) = field(check_polygon(
            &out,
            size,
            [8, 8],
            "plate.outline",
            Some("m"),
        ));
        assert_eq!(f, "plate.outline[0]");
        assert!(
            m.starts_with("(-2.5, -2) m lies outside the plate's 4 × 4 m box"),
            "{m}"
        );
        // Coordinates without a unit (a dimensionless scene's) are given bare.
        let (_, m) = field(check_polygon(
            &out,
            size,
            [8, 8],
            "dimensionless.outline",
            None,
        ));
        assert!(
            m.starts_with("(-2.5, -2) lies outside the plate's 4 × 4 box"),
            "{m}"
        );
        assert!(field(check_polygon(
            &L[..3],
            size,
            [8, 8],
            "plate.outline",
            Some("m")
        ))
        .1
        .contains("at least 4 corners"));
        // A closing corner equal to the first is the same outline.
        let mut closed = L.to_vec();
        closed.push(L[0]);
        assert_eq!(
            check_polygon(&closed, size, [8, 8], "plate.outline", Some("m")).expect("closed"),
            check_polygon(&L, size, [8, 8], "plate.outline", Some("m")).expect("open")
        );
    }
}
