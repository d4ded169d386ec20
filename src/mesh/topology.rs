//! The topology of a jointed grid: node copies along the joint lines that cut the plate, the
//! corner table of the elements, the panels, the rigid pieces and their clusters, the joint
//! segments and the dowel springs.
//!
//! The grid stays the uniform one of the whole bounding box; a joint line that cuts the plate
//! (any kind but continuous) doubles the nodes on it, one copy per side (four at a crossing of
//! two such lines). A shaped plate (an outline, openings) keeps only the cells inside it: a
//! grid node that no plate cell touches has no copy at all. Node ids 0..N_p are the first
//! copies of the grid nodes a plate cell touches, in grid order (i + j(nx + 1) on a rectangle)
//! — at a joint the copy of the lower / left side — and N_p.. the extra copies, in the order
//! (grid node, side). Each copy is one plate node (w, ψx, ψy) and one pressure unknown.
//!
//! This file knows nothing of [`super::Mesh`]: it works on the plain numbers of a [`Grid`].

use std::sync::Arc;

use crate::layout::{Axis, JointKind, Layout};

/// The plain numbers of a model grid (possibly reduced by symmetry).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grid {
    /// Elements along x.
    pub nx: usize,
    /// Elements along y.
    pub ny: usize,
    /// Lower-left corner x.
    pub x0: f64,
    /// Lower-left corner y.
    pub y0: f64,
    /// Element size along x.
    pub hx: f64,
    /// Element size along y.
    pub hy: f64,
    /// Reduced about x = 0 (the model keeps x ≥ 0).
    pub sym_x: bool,
    /// Reduced about y = 0.
    pub sym_y: bool,
}

/// One element edge of a joint line in the model: the node copies on its two sides, each pair
/// ordered along the joint (increasing y for a line x = const, increasing x for y = const).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    /// Index of the joint in the layout.
    pub joint: usize,
    /// The copies on the − side (x < x_j or y < y_j) at the two ends.
    pub a: [usize; 2],
    /// The copies on the + side.
    pub b: [usize; 2],
    /// The element on the − side.
    pub minus: usize,
    /// The element on the + side.
    pub plus: usize,
    /// Family of the joint line (the rotation normal to it is ψx for Axis::X, ψy for Axis::Y).
    pub axis: Axis,
    /// Length of the edge.
    pub length: f64,
}

/// A dowel bar of the model as a point spring on one joint segment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DowelSpring {
    /// The segment it sits on.
    pub segment: usize,
    /// Its position on the segment, t ∈ [0, 1] from the segment's first end.
    pub t: f64,
    /// Its spring k̄_d, halved for a bar on a symmetry line of the model.
    pub k: f64,
    /// Index of the bar in its joint's positions.
    pub bar: usize,
}

/// Node copies, corner table, panels, pieces, clusters, joint segments and dowels of a model
/// grid with a layout.
#[derive(Debug, Clone, PartialEq)]
pub struct Topology {
    /// The whole-plate layout the topology was built from.
    pub layout: Arc<Layout>,
    /// Grid columns that carry a joint line or segment inside the model, with the joint's
    /// index (every kind), sorted by column (a column may carry several segments).
    pub lines_x: Vec<(usize, usize)>,
    /// Grid rows that carry a joint line inside the model, with the joint's index.
    pub lines_y: Vec<(usize, usize)>,
    /// The grid node of each extra copy (node id N_g + k).
    pub extra_grid: Vec<usize>,
    /// The node copy at each corner of each element (counter-clockwise from the lower left).
    pub corners: Vec<[usize; 4]>,
    /// The whole-plate panel of each model element ([`Layout::panel_id`]: column + row ·
    /// columns, then the regions).
    pub panel: Vec<u32>,
    /// The rigid piece of each model element: elements joined through edges that no joint cuts.
    pub piece: Vec<u32>,
    /// The cluster of each piece: pieces joined through joints that transfer load.
    pub cluster: Vec<u32>,
    /// Joint segments of every cutting joint (free ones included, whose springs are zero).
    pub segments: Vec<Segment>,
    /// Dowel springs of the model.
    pub dowels: Vec<DowelSpring>,
    /// Whether each model element is plate (a shaped plate's mask; all true otherwise).
    live: Vec<bool>,
    /// The first copy of each grid node, `usize::MAX` where no plate cell touches it.
    primary: Vec<usize>,
    /// The grid node of each first copy (node ids 0..N_p; extras follow).
    grid_node: Vec<usize>,
    /// Extra copies of each grid node: `extra_of[g]..extra_of[g + 1]` indexes `extra_list`.
    extra_of: Vec<usize>,
    extra_list: Vec<usize>,
    /// Elements and local corners of each node copy: `incident_of[n]..incident_of[n + 1]`.
    incident_of: Vec<usize>,
    incident: Vec<(usize, usize)>,
}

/// Tolerance on positions, in element sizes, for lines and bars that fall on grid lines.
const ON_LINE: f64 = 1e-6;

/// Union–find root with path halving.
fn root(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

impl Topology {
    /// Build the topology of `grid` with a whole-plate `layout`. A joint line is taken at the
    /// nearest grid line of the model (validation guarantees that it lies on one, see
    /// [`crate::scene`]); lines outside the model or on its boundary (the mirrored half of a
    /// reduced model, a continuous joint on a symmetry line) do not enter it.
    pub fn build(grid: Grid, layout: Arc<Layout>) -> Self {
        let Grid { nx, ny, .. } = grid;
        let (nx1, ny1) = (nx + 1, ny + 1);
        let n_grid = nx1 * ny1;
        let line = |at: f64, origin: f64, h: f64, n: usize| -> Option<usize> {
            let f = (at - origin) / h;
            let i = f.round();
            (i >= 1.0 && i <= n as f64 - 1.0).then_some(i as usize)
        };
        let mut lines_x = Vec::new();
        let mut lines_y = Vec::new();
        for (k, j) in layout.joints.iter().enumerate() {
            let (list, at) = match j.axis {
                Axis::X => (&mut lines_x, line(j.at, grid.x0, grid.hx, nx)),
                Axis::Y => (&mut lines_y, line(j.at, grid.y0, grid.hy, ny)),
            };
            if let Some(i) = at {
                list.push((i, k));
            }
        }
        lines_x.sort_unstable();
        lines_y.sort_unstable();
        // The cells along a joint's line that its extent covers, in the model: all of them for
        // a line across the plate, a segment's own (possibly none: on a mirrored half).
        let extent = |k: usize| -> std::ops::Range<usize> {
            let j = &layout.joints[k];
            let (origin, h, n) = match j.axis {
                Axis::X => (grid.y0, grid.hy, ny),
                Axis::Y => (grid.x0, grid.hx, nx),
            };
            match j.span {
                None => 0..n,
                Some([a, b]) => {
                    let at = |v: f64| ((v - origin) / h).round().clamp(0.0, n as f64) as usize;
                    at(a)..at(b)
                }
            }
        };
        // Which element edges a cutting joint runs along: the vertical edge (column i, row j)
        // at i + j (nx + 1), the horizontal edge (column i, row j) at i + j nx.
        let mut cut_v = vec![false; (nx + 1) * ny];
        let mut cut_h = vec![false; nx * (ny + 1)];
        for &(i, k) in &lines_x {
            if layout.joints[k].kind.doubles() {
                for j in extent(k) {
                    cut_v[i + j * (nx + 1)] = true;
                }
            }
        }
        for &(j, k) in &lines_y {
            if layout.joints[k].kind.doubles() {
                for i in extent(k) {
                    cut_h[i + j * nx] = true;
                }
            }
        }
        let vertical = |i: usize, j: usize| cut_v[i + j * (nx + 1)];
        let horizontal = |i: usize, j: usize| cut_h[i + j * nx];

        // The plate's cells: every one of a rectangle, those inside the outline and outside
        // every opening of a shaped plate (each cell by its centre).
        let live: Vec<bool> = (0..nx * ny)
            .map(|e| {
                let (ie, je) = (e % nx, e / nx);
                layout.is_plate(
                    grid.x0 + (ie as f64 + 0.5) * grid.hx,
                    grid.y0 + (je as f64 + 0.5) * grid.hy,
                )
            })
            .collect();
        // (element, the node's corner in it) of grid node (i, j), in the order LL, LR, UL, UR,
        // plate cells only.
        let slots_of = |i: usize, j: usize| -> [Option<(usize, usize)>; 4] {
            let cell = |ok: bool, ie: usize, je: usize, c: usize| {
                (ok && live[ie + je * nx]).then_some((ie + je * nx, c))
            };
            [
                cell(i > 0 && j > 0, i.wrapping_sub(1), j.wrapping_sub(1), 2),
                cell(i < nx && j > 0, i, j.wrapping_sub(1), 3),
                cell(i > 0 && j < ny, i.wrapping_sub(1), j, 1),
                cell(i < nx && j < ny, i, j, 0),
            ]
        };
        // The first copy of each grid node a plate cell touches, numbered in grid order; a
        // node no plate cell touches does not exist.
        let mut primary = vec![usize::MAX; n_grid];
        let mut grid_node = Vec::with_capacity(n_grid);
        for j in 0..ny1 {
            for i in 0..nx1 {
                if slots_of(i, j).iter().any(Option::is_some) {
                    primary[i + j * nx1] = grid_node.len();
                    grid_node.push(i + j * nx1);
                }
            }
        }
        let n_primary = grid_node.len();

        // Node copies: per grid node, its ≤ 4 elements joined across edges no joint cuts;
        // each group of elements is one copy, the first group keeps the node's first id.
        let mut corners = vec![[usize::MAX; 4]; nx * ny];
        let mut extra_grid = Vec::new();
        let mut extra_of = Vec::with_capacity(n_grid + 1);
        extra_of.push(0);
        let mut extra_list = Vec::new();
        for j in 0..ny1 {
            for i in 0..nx1 {
                let g = i + j * nx1;
                let slots = slots_of(i, j);
                let mut parent = [0, 1, 2, 3];
                let mut join = |a: usize, b: usize| {
                    if slots[a].is_some() && slots[b].is_some() {
                        let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
                        parent[ra.max(rb)] = ra.min(rb);
                    }
                };
                // LL–LR share the vertical edge below the node, UL–UR the one above; LL–UL the
                // horizontal edge left of it, LR–UR the one right (join checks both exist).
                if j > 0 && i <= nx && !vertical(i, j - 1) {
                    join(0, 1);
                }
                if j < ny && !vertical(i, j) {
                    join(2, 3);
                }
                if i > 0 && !horizontal(i - 1, j) {
                    join(0, 2);
                }
                if i < nx && !horizontal(i, j) {
                    join(1, 3);
                }
                let mut id_of_root = [usize::MAX; 4];
                let mut first = true;
                for s in 0..4 {
                    let Some((e, c)) = slots[s] else { continue };
                    let r = root(&mut parent, s);
                    if id_of_root[r] == usize::MAX {
                        id_of_root[r] = if first {
                            primary[g]
                        } else {
                            extra_grid.push(g);
                            extra_list.push(n_primary + extra_grid.len() - 1);
                            n_primary + extra_grid.len() - 1
                        };
                        first = false;
                    }
                    corners[e][c] = id_of_root[r];
                }
                extra_of.push(extra_list.len());
            }
        }
        let n_nodes = n_primary + extra_grid.len();
        let mut counts = vec![0usize; n_nodes + 1];
        for c in corners.iter().filter(|c| c[0] != usize::MAX) {
            for &n in c {
                counts[n + 1] += 1;
            }
        }
        for k in 0..n_nodes {
            counts[k + 1] += counts[k];
        }
        let incident_of = counts.clone();
        let mut incident = vec![(0, 0); incident_of[n_nodes]];
        let mut next = counts;
        for (e, c) in corners
            .iter()
            .enumerate()
            .filter(|(_, c)| c[0] != usize::MAX)
        {
            for (a, &n) in c.iter().enumerate() {
                incident[next[n]] = (e, a);
                next[n] += 1;
            }
        }

        // Panels by every line of the whole plate; pieces: plate cells joined through edges
        // that no cutting joint runs along (numbered by their first cell).
        let mut panel = Vec::with_capacity(nx * ny);
        for je in 0..ny {
            for ie in 0..nx {
                let xc = grid.x0 + (ie as f64 + 0.5) * grid.hx;
                let yc = grid.y0 + (je as f64 + 0.5) * grid.hy;
                panel.push(layout.panel_id(xc, yc) as u32);
            }
        }
        let mut parent: Vec<usize> = (0..nx * ny).collect();
        for je in 0..ny {
            for ie in 0..nx {
                let e = ie + je * nx;
                if !live[e] {
                    continue;
                }
                for (ok, n) in [
                    (ie + 1 < nx && !vertical(ie + 1, je), e + 1),
                    (je + 1 < ny && !horizontal(ie, je + 1), e + nx),
                ] {
                    if ok && live[n] {
                        let (ra, rb) = (root(&mut parent, e), root(&mut parent, n));
                        parent[ra.max(rb)] = ra.min(rb);
                    }
                }
            }
        }
        let mut piece = vec![u32::MAX; nx * ny];
        let mut n_pieces = 0;
        for e in (0..nx * ny).filter(|&e| live[e]) {
            let r = root(&mut parent, e);
            if piece[r] == u32::MAX {
                piece[r] = n_pieces;
                n_pieces += 1;
            }
            piece[e] = piece[r];
        }
        let n_pieces = n_pieces as usize;

        // Segments of every cutting joint where plate lies on both sides (a joint ends where
        // it meets an opening or the outline), then the bars on them; `along` keeps, per
        // joint line, the segment of each cell along it.
        let mut segments = Vec::new();
        let mut along: Vec<(usize, Vec<Option<usize>>)> = Vec::new();
        for &(i, k) in &lines_x {
            if !layout.joints[k].kind.doubles() {
                continue;
            }
            let mut cells = vec![None; ny];
            for (je, cell) in cells.iter_mut().enumerate() {
                let (m, p) = ((i - 1) + je * nx, i + je * nx);
                if !extent(k).contains(&je) {
                    continue;
                }
                if !(live[m] && live[p]) {
                    continue;
                }
                *cell = Some(segments.len());
                segments.push(Segment {
                    joint: k,
                    a: [corners[m][1], corners[m][2]],
                    b: [corners[p][0], corners[p][3]],
                    minus: m,
                    plus: p,
                    axis: Axis::X,
                    length: grid.hy,
                });
            }
            along.push((k, cells));
        }
        for &(j, k) in &lines_y {
            if !layout.joints[k].kind.doubles() {
                continue;
            }
            let mut cells = vec![None; nx];
            for (ie, cell) in cells.iter_mut().enumerate() {
                let (m, p) = (ie + (j - 1) * nx, ie + j * nx);
                if !extent(k).contains(&ie) {
                    continue;
                }
                if !(live[m] && live[p]) {
                    continue;
                }
                *cell = Some(segments.len());
                segments.push(Segment {
                    joint: k,
                    a: [corners[m][3], corners[m][2]],
                    b: [corners[p][0], corners[p][1]],
                    minus: m,
                    plus: p,
                    axis: Axis::Y,
                    length: grid.hx,
                });
            }
            along.push((k, cells));
        }
        let mut dowels = Vec::new();
        for (joint, cells) in &along {
            let JointKind::Dowels { k, positions, .. } = &layout.joints[*joint].kind else {
                continue;
            };
            let (origin, h, n, sym) = match layout.joints[*joint].axis {
                Axis::X => (grid.y0, grid.hy, ny, grid.sym_y),
                Axis::Y => (grid.x0, grid.hx, nx, grid.sym_x),
            };
            for (bar, &p) in positions.iter().enumerate() {
                let f = (p - origin) / h;
                if f < -ON_LINE || f > n as f64 + ON_LINE {
                    continue; // on the mirrored half of a reduced model
                }
                let f = f.clamp(0.0, n as f64);
                let cell = (f.floor() as usize).min(n - 1);
                let on_mirror = sym && p.abs() <= ON_LINE * h;
                // A bar where the joint has no plate on one side (validation refuses it).
                let Some(segment) = cells[cell] else { continue };
                dowels.push(DowelSpring {
                    segment,
                    t: (f - cell as f64).clamp(0.0, 1.0),
                    k: if on_mirror { 0.5 * k } else { *k },
                    bar,
                });
            }
        }

        // Clusters: pieces joined by the springs of transferring joints.
        let mut parent: Vec<usize> = (0..n_pieces).collect();
        let mut join = |a: usize, b: usize| {
            let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
            parent[ra.max(rb)] = ra.min(rb);
        };
        for seg in &segments {
            if matches!(
                layout.joints[seg.joint].kind,
                JointKind::Aggregate { .. } | JointKind::Tied { .. }
            ) {
                join(piece[seg.minus] as usize, piece[seg.plus] as usize);
            }
        }
        for d in &dowels {
            let seg = &segments[d.segment];
            join(piece[seg.minus] as usize, piece[seg.plus] as usize);
        }
        let mut label = vec![u32::MAX; n_pieces];
        let mut cluster = Vec::with_capacity(n_pieces);
        let mut next_label = 0;
        for p in 0..n_pieces {
            let r = root(&mut parent, p);
            if label[r] == u32::MAX {
                label[r] = next_label;
                next_label += 1;
            }
            cluster.push(label[r]);
        }

        Self {
            layout,
            lines_x,
            lines_y,
            extra_grid,
            corners,
            panel,
            piece,
            cluster,
            segments,
            dowels,
            live,
            primary,
            grid_node,
            extra_of,
            extra_list,
            incident_of,
            incident,
        }
    }

    /// Number of node copies (first copies and extras).
    pub fn n_nodes(&self) -> usize {
        self.grid_node.len() + self.extra_grid.len()
    }

    /// The grid node of node copy `n`.
    pub fn grid_of(&self, n: usize) -> usize {
        match self.grid_node.get(n) {
            Some(&g) => g,
            None => self.extra_grid[n - self.grid_node.len()],
        }
    }

    /// The first copy of grid node `g`, `None` where no plate cell touches it.
    pub fn primary(&self, g: usize) -> Option<usize> {
        self.primary.get(g).copied().filter(|&n| n != usize::MAX)
    }

    /// True when model element `e` is plate (inside the outline, outside every opening).
    pub fn is_live(&self, e: usize) -> bool {
        self.live[e]
    }

    /// True when some cell of the model is not plate.
    pub fn is_shaped(&self) -> bool {
        self.live.iter().any(|&l| !l)
    }

    /// The extra copies of grid node `g` (its own id not included).
    pub fn extras(&self, g: usize) -> &[usize] {
        &self.extra_list[self.extra_of[g]..self.extra_of[g + 1]]
    }

    /// The elements holding node copy `n`, with its local corner in each.
    pub fn incident(&self, n: usize) -> &[(usize, usize)] {
        &self.incident[self.incident_of[n]..self.incident_of[n + 1]]
    }

    /// Number of rigid pieces.
    pub fn n_pieces(&self) -> usize {
        self.cluster.len()
    }

    /// Number of clusters.
    pub fn n_clusters(&self) -> usize {
        self.cluster
            .iter()
            .map(|&c| c as usize + 1)
            .max()
            .unwrap_or(0)
    }

    /// True when some joint line cuts the model (node copies exist).
    pub fn cuts(&self) -> bool {
        !self.extra_grid.is_empty()
    }
}
