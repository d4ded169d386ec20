//! Structured rectangular grid of the plate model, symmetry reduction and degree-of-freedom map.
//!
//! Everything here is in the solver's unit system: lengths in units of L (half the plate side
//! along x), so the whole plate is [−1, 1] × [−μ, μ]. A model reduced by symmetry about x = 0
//! keeps x ≥ 0, one reduced about y = 0 keeps y ≥ 0; the symmetry lines are grid lines, so the
//! element counts of the whole plate must be even in the reduced directions.
//!
//! A jointed plate keeps the same grid and gains a [`Topology`] ([`Mesh::with_layout`]): node
//! copies along the joint lines that cut it and a corner table, read through the same methods
//! ([`Mesh::n_nodes`], [`Mesh::element_nodes`], [`Mesh::node_xy`]). Without joints the
//! topology is `None` and every method is the plain grid's.

pub mod outline;
pub mod topology;

use std::sync::Arc;

use crate::layout::Layout;
pub use topology::{DowelSpring, Grid, Segment, Topology};

/// The three degrees of freedom of a plate node (Mindlin kinematics, eq. 2.1 of the paper).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dof {
    /// Deflection w, positive downward (into the foundation).
    W = 0,
    /// Rotation ψx: u_x = −z ψx, equal to ∂w/∂x when shear strains vanish.
    PsiX = 1,
    /// Rotation ψy: u_y = −z ψy, equal to ∂w/∂y when shear strains vanish.
    PsiY = 2,
}

/// Degrees of freedom per node.
pub const DOFS_PER_NODE: usize = 3;

/// A uniform grid over the modelled part of the plate.
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    /// Elements along x in the model.
    pub nx: usize,
    /// Elements along y in the model.
    pub ny: usize,
    /// x of the model's lower-left corner.
    pub x0: f64,
    /// y of the model's lower-left corner.
    pub y0: f64,
    /// Element size along x.
    pub hx: f64,
    /// Element size along y.
    pub hy: f64,
    /// The model keeps x ≥ 0 and mirrors about x = 0.
    pub sym_x: bool,
    /// The model keeps y ≥ 0 and mirrors about y = 0.
    pub sym_y: bool,
    /// Node copies and corner table of a jointed plate; `None` for a plate of one piece.
    pub topo: Option<Arc<Topology>>,
}

impl Mesh {
    /// The grid of a plate [−a/2, a/2] × [−b/2, b/2] with `full` = [nx, ny] elements over the
    /// whole plate, reduced about x = 0 and/or y = 0 as asked. Reduction in a direction needs an
    /// even element count there (checked by the caller; an odd count is refused here).
    pub fn new(a: f64, b: f64, full: [usize; 2], sym_x: bool, sym_y: bool) -> Self {
        let hx = a / full[0] as f64;
        let hy = b / full[1] as f64;
        let sym_x = sym_x && full[0].is_multiple_of(2);
        let sym_y = sym_y && full[1].is_multiple_of(2);
        Self {
            nx: if sym_x { full[0] / 2 } else { full[0] },
            ny: if sym_y { full[1] / 2 } else { full[1] },
            x0: if sym_x { 0.0 } else { -0.5 * a },
            y0: if sym_y { 0.0 } else { -0.5 * b },
            hx,
            hy,
            sym_x,
            sym_y,
            topo: None,
        }
    }

    /// The same grid with a whole-plate layout: node copies along the joint lines that cut
    /// the model, panels, segments and dowels ([`Topology::build`]). Each joint line is taken
    /// at its nearest grid line (validation puts every line on one); an empty layout leaves
    /// the plain grid.
    pub fn with_layout(mut self, layout: &Layout) -> Self {
        self.topo = (!layout.is_empty())
            .then(|| Arc::new(Topology::build(self.grid(), Arc::new(layout.clone()))));
        self
    }

    /// The plain numbers of the grid.
    pub fn grid(&self) -> Grid {
        Grid {
            nx: self.nx,
            ny: self.ny,
            x0: self.x0,
            y0: self.y0,
            hx: self.hx,
            hy: self.hy,
            sym_x: self.sym_x,
            sym_y: self.sym_y,
        }
    }

    /// True when a joint cuts the model (node copies exist).
    pub fn is_jointed(&self) -> bool {
        self.topo.as_ref().is_some_and(|t| t.cuts())
    }

    /// Size of the whole plate along x and y.
    pub fn plate_size(&self) -> [f64; 2] {
        let full = self.full_elements();
        [self.hx * full[0] as f64, self.hy * full[1] as f64]
    }

    /// The same plate and layout on a grid twice as coarse, with the same symmetry reduction,
    /// when the model's element counts and the grid lines of every joint are even (the joints
    /// stay on grid lines); `None` otherwise.
    pub fn coarsened(&self) -> Option<Mesh> {
        if !(self.nx.is_multiple_of(2) && self.ny.is_multiple_of(2) && self.nx >= 2 && self.ny >= 2)
        {
            return None;
        }
        let full = self.full_elements();
        let [a, b] = self.plate_size();
        let coarse = Mesh::new(a, b, [full[0] / 2, full[1] / 2], self.sym_x, self.sym_y);
        if coarse.sym_x != self.sym_x || coarse.sym_y != self.sym_y {
            return None;
        }
        let Some(topo) = &self.topo else {
            return Some(coarse);
        };
        let even = |lines: &[(usize, usize)]| lines.iter().all(|&(i, _)| i.is_multiple_of(2));
        let mu = 0.5 * b;
        let fits = even(&topo.lines_x)
            && even(&topo.lines_y)
            && topo.layout.fits([full[0] / 2, full[1] / 2], mu)
            && topo.layout.shapes_fit([full[0] / 2, full[1] / 2], mu);
        if !fits {
            return None;
        }
        Some(coarse.with_layout(&topo.layout))
    }

    /// The whole plate's grid with the same layout (no symmetry reduction).
    pub fn whole(&self) -> Mesh {
        let [a, b] = self.plate_size();
        let whole = Mesh::new(a, b, self.full_elements(), false, false);
        match &self.topo {
            Some(t) => whole.with_layout(&t.layout),
            None => whole,
        }
    }

    /// The grid node of node copy `n` (itself without joints).
    pub fn grid_of(&self, n: usize) -> usize {
        match &self.topo {
            Some(t) => t.grid_of(n),
            None => n,
        }
    }

    /// Grid position (i, j) of node copy `n`.
    pub fn node_ij(&self, n: usize) -> (usize, usize) {
        let g = self.grid_of(n);
        (g % self.nodes_x(), g / self.nodes_x())
    }

    /// The extra copies of grid node `g` across the joints through it (empty without joints).
    pub fn extra_copies(&self, g: usize) -> &[usize] {
        match &self.topo {
            Some(t) => t.extras(g),
            None => &[],
        }
    }

    /// The whole-plate panel (column + row · columns) of element e; 0 without a layout.
    pub fn panel_of(&self, e: usize) -> usize {
        self.topo.as_ref().map_or(0, |t| t.panel[e] as usize)
    }

    /// Element counts of the whole plate.
    pub fn full_elements(&self) -> [usize; 2] {
        [
            if self.sym_x { 2 * self.nx } else { self.nx },
            if self.sym_y { 2 * self.ny } else { self.ny },
        ]
    }

    /// How many copies of the model make the whole plate (1, 2 or 4).
    pub fn copies(&self) -> usize {
        (if self.sym_x { 2 } else { 1 }) * (if self.sym_y { 2 } else { 1 })
    }

    /// Human name of the reduction.
    pub fn symmetry_name(&self) -> &'static str {
        match (self.sym_x, self.sym_y) {
            (false, false) => "full",
            (true, false) => "half-x",
            (false, true) => "half-y",
            (true, true) => "quarter",
        }
    }

    /// Nodes along x.
    pub fn nodes_x(&self) -> usize {
        self.nx + 1
    }

    /// Nodes along y.
    pub fn nodes_y(&self) -> usize {
        self.ny + 1
    }

    /// Number of nodes in the model: the grid's, and the extra copies along cutting joints
    /// (each one pressure unknown).
    pub fn n_nodes(&self) -> usize {
        match &self.topo {
            Some(t) => t.n_nodes(),
            None => self.nodes_x() * self.nodes_y(),
        }
    }

    /// Number of elements in the model.
    pub fn n_elements(&self) -> usize {
        self.nx * self.ny
    }

    /// Node index of grid position (i, j): its first copy. On a shaped plate a grid node that
    /// no plate cell touches has none and this is `usize::MAX`; [`Self::live_node`] says so.
    pub fn node(&self, i: usize, j: usize) -> usize {
        self.live_node(i, j).unwrap_or(usize::MAX)
    }

    /// The first copy of grid position (i, j), `None` where no plate cell touches it.
    pub fn live_node(&self, i: usize, j: usize) -> Option<usize> {
        let g = i + j * self.nodes_x();
        match &self.topo {
            Some(t) => t.primary(g),
            None => Some(g),
        }
    }

    /// True when element e is plate (always, on a plate that is its whole rectangle).
    pub fn is_live(&self, e: usize) -> bool {
        self.topo.as_ref().is_none_or(|t| t.is_live(e))
    }

    /// The plate's elements: every one of a rectangle, those inside the outline and outside
    /// the openings of a shaped plate.
    pub fn elements(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.n_elements()).filter(|&e| self.is_live(e))
    }

    /// Coordinates of node n (the copies of a grid node share them).
    pub fn node_xy(&self, n: usize) -> (f64, f64) {
        let n = self.grid_of(n);
        let i = n % self.nodes_x();
        let j = n / self.nodes_x();
        (self.x0 + i as f64 * self.hx, self.y0 + j as f64 * self.hy)
    }

    /// The four nodes of element e, counter-clockwise from the lower-left corner (on a jointed
    /// plate, the copies on the element's own side).
    pub fn element_nodes(&self, e: usize) -> [usize; 4] {
        if let Some(t) = &self.topo {
            return t.corners[e];
        }
        let ie = e % self.nx;
        let je = e / self.nx;
        [
            self.node(ie, je),
            self.node(ie + 1, je),
            self.node(ie + 1, je + 1),
            self.node(ie, je + 1),
        ]
    }

    /// Centre of element e.
    pub fn element_centre(&self, e: usize) -> (f64, f64) {
        let ie = e % self.nx;
        let je = e / self.nx;
        (
            self.x0 + (ie as f64 + 0.5) * self.hx,
            self.y0 + (je as f64 + 0.5) * self.hy,
        )
    }

    /// Grid position (ie, je) of element e.
    pub fn element_ij(&self, e: usize) -> (usize, usize) {
        (e % self.nx, e / self.nx)
    }

    /// The element containing (x, y) and the local coordinates (ξ, η) ∈ [−1, 1]² there, or
    /// `None` outside the model (a tolerance of 1e-9 element sizes admits points on its edge).
    /// On a shaped plate the element is a plate cell: a point on the edge between a plate cell
    /// and a cell outside is found in the plate cell, and a point in no plate cell's closure
    /// is `None`.
    pub fn locate(&self, x: f64, y: f64) -> Option<(usize, f64, f64)> {
        let fx = (x - self.x0) / self.hx;
        let fy = (y - self.y0) / self.hy;
        let tol = 1e-9;
        if !(fx >= -tol && fy >= -tol && fx <= self.nx as f64 + tol && fy <= self.ny as f64 + tol) {
            return None;
        }
        let cell = |f: f64, n: usize| (f.floor().max(0.0) as usize).min(n - 1);
        let (ie, je) = (cell(fx, self.nx), cell(fy, self.ny));
        // The cells whose closure holds the point: the one below / left of it too when it lies
        // on a grid line (to the tolerance above).
        let near = |f: f64, i: usize| {
            let back = i > 0 && (f - i as f64).abs() <= tol;
            let fwd = (f - (i + 1) as f64).abs() <= tol;
            [Some(i), back.then(|| i - 1), fwd.then_some(i + 1)]
        };
        let (ie, je) = if self.is_live(ie + je * self.nx) {
            (ie, je)
        } else {
            let found = near(fx, ie).into_iter().flatten().find_map(|i| {
                near(fy, je)
                    .into_iter()
                    .flatten()
                    .find(|&j| i < self.nx && j < self.ny && self.is_live(i + j * self.nx))
                    .map(|j| (i, j))
            });
            found?
        };
        let xi = 2.0 * (fx - ie as f64) - 1.0;
        let eta = 2.0 * (fy - je as f64) - 1.0;
        Some((ie + je * self.nx, xi.clamp(-1.0, 1.0), eta.clamp(-1.0, 1.0)))
    }

    /// Nodal values of `other`'s grid (same plate, any element counts and reduction) at this
    /// grid's nodes by bilinear interpolation; a node outside a reduced `other` takes the value
    /// of its mirror image (a reduced model's fields are symmetric). On jointed grids (the same
    /// layout) each node copy reads the field on its own side of the joints: it is located from
    /// a point nudged towards the centre of one of its elements, and interpolated at its own
    /// position in the element found.
    pub fn interpolate_from(&self, other: &Mesh, values: &[f64]) -> Vec<f64> {
        if self.topo.is_none() && other.topo.is_none() {
            return self.interpolate_plain(other, values);
        }
        (0..self.n_nodes())
            .map(|n| {
                let (x, y) = self.node_xy(n);
                let (mut xs, mut ys) = (x, y);
                if let Some(&(e, _)) = self.topo.as_ref().and_then(|t| t.incident(n).first()) {
                    let (xc, yc) = self.element_centre(e);
                    xs += 1e-6 * (xc - x);
                    ys += 1e-6 * (yc - y);
                }
                let fold = |v: f64, sym: bool| if sym { v.abs() } else { v };
                let (x, y) = (fold(x, other.sym_x), fold(y, other.sym_y));
                let (xs, ys) = (fold(xs, other.sym_x), fold(ys, other.sym_y));
                other.locate(xs, ys).map_or(0.0, |(e, _, _)| {
                    let (ie, je) = other.element_ij(e);
                    let xi = (2.0 * ((x - other.x0) / other.hx - ie as f64) - 1.0).clamp(-1.0, 1.0);
                    let eta =
                        (2.0 * ((y - other.y0) / other.hy - je as f64) - 1.0).clamp(-1.0, 1.0);
                    bilinear(&other.element_nodes(e), xi, eta, values)
                })
            })
            .collect()
    }

    /// [`Self::interpolate_from`] between plain grids.
    fn interpolate_plain(&self, other: &Mesh, values: &[f64]) -> Vec<f64> {
        (0..self.n_nodes())
            .map(|n| {
                let (mut x, mut y) = self.node_xy(n);
                if other.sym_x {
                    x = x.abs();
                }
                if other.sym_y {
                    y = y.abs();
                }
                other.locate(x, y).map_or(0.0, |(e, xi, eta)| {
                    bilinear(&other.element_nodes(e), xi, eta, values)
                })
            })
            .collect()
    }

    /// Area of one element.
    pub fn element_area(&self) -> f64 {
        self.hx * self.hy
    }
}

/// The bilinear interpolant of nodal `values` at (ξ, η) of an element with these nodes (corner
/// order of [`Mesh::element_nodes`]: (−,−), (+,−), (+,+), (−,+)).
fn bilinear(nodes: &[usize; 4], xi: f64, eta: f64, values: &[f64]) -> f64 {
    let w = [
        (1.0 - xi) * (1.0 - eta),
        (1.0 + xi) * (1.0 - eta),
        (1.0 + xi) * (1.0 + eta),
        (1.0 - xi) * (1.0 + eta),
    ];
    nodes
        .iter()
        .zip(w)
        .map(|(&k, w)| 0.25 * w * values[k])
        .sum()
}

/// Map from node degrees of freedom to equation numbers; symmetry conditions remove the rotation
/// normal to a symmetry line (ψx = 0 on x = 0, ψy = 0 on y = 0) — of every copy there, such as
/// the two sides of a joint y = const where it meets the line x = 0.
#[derive(Debug, Clone)]
pub struct DofMap {
    eq: Vec<Option<usize>>,
    n_eq: usize,
}

impl DofMap {
    /// The map of a mesh: node-major numbering, constrained dofs skipped.
    pub fn new(mesh: &Mesh) -> Self {
        let mut eq = Vec::with_capacity(mesh.n_nodes() * DOFS_PER_NODE);
        let mut n_eq = 0;
        for n in 0..mesh.n_nodes() {
            let (i, j) = mesh.node_ij(n);
            for d in [Dof::W, Dof::PsiX, Dof::PsiY] {
                let fixed = (mesh.sym_x && i == 0 && d == Dof::PsiX)
                    || (mesh.sym_y && j == 0 && d == Dof::PsiY);
                if fixed {
                    eq.push(None);
                } else {
                    eq.push(Some(n_eq));
                    n_eq += 1;
                }
            }
        }
        Self { eq, n_eq }
    }

    /// Equation number of a node's dof, `None` where a symmetry condition fixes it.
    pub fn eq(&self, node: usize, dof: Dof) -> Option<usize> {
        self.eq[node * DOFS_PER_NODE + dof as usize]
    }

    /// Equation numbers of the 12 element dofs (node-major, (w, ψx, ψy) per node).
    pub fn element_eqs(&self, nodes: &[usize; 4]) -> [Option<usize>; 12] {
        let mut out = [None; 12];
        for (a, &n) in nodes.iter().enumerate() {
            for d in 0..DOFS_PER_NODE {
                out[a * DOFS_PER_NODE + d] = self.eq[n * DOFS_PER_NODE + d];
            }
        }
        out
    }

    /// Number of equations (free dofs).
    pub fn n_eq(&self) -> usize {
        self.n_eq
    }
}

/// Nested-dissection order of the grid's nodes: split the node rectangle across its longer
/// side by a grid line, order both halves recursively, the separating line last. For a 2-D grid
/// this is the optimal fill-reducing order (George 1973): O(n log n) fill, O(n^1.5) work. On a
/// jointed grid each grid node is followed by its extra copies.
pub fn nested_dissection(mesh: &Mesh) -> Vec<usize> {
    fn push(mesh: &Mesh, i: usize, j: usize, out: &mut Vec<usize>) {
        if let Some(n) = mesh.live_node(i, j) {
            out.push(n);
            out.extend_from_slice(mesh.extra_copies(i + j * mesh.nodes_x()));
        }
    }
    fn recurse(mesh: &Mesh, i0: usize, i1: usize, j0: usize, j1: usize, out: &mut Vec<usize>) {
        if i0 > i1 || j0 > j1 {
            return;
        }
        let (w, h) = (i1 - i0 + 1, j1 - j0 + 1);
        if w * h <= 16 {
            for j in j0..=j1 {
                for i in i0..=i1 {
                    push(mesh, i, j, out);
                }
            }
            return;
        }
        if w >= h {
            let m = i0 + w / 2;
            if m > i0 {
                recurse(mesh, i0, m - 1, j0, j1, out);
            }
            recurse(mesh, m + 1, i1, j0, j1, out);
            for j in j0..=j1 {
                push(mesh, m, j, out);
            }
        } else {
            let m = j0 + h / 2;
            if m > j0 {
                recurse(mesh, i0, i1, j0, m - 1, out);
            }
            recurse(mesh, i0, i1, m + 1, j1, out);
            for i in i0..=i1 {
                push(mesh, i, m, out);
            }
        }
    }
    let mut out = Vec::with_capacity(mesh.n_nodes());
    recurse(mesh, 0, mesh.nx, 0, mesh.ny, &mut out);
    out
}

/// Equations in nested-dissection order (`order[new] = old`), skipping those for which
/// `keep` is false and renumbering the rest consecutively.
pub fn equation_order(mesh: &Mesh, dofs: &DofMap, keep: impl Fn(usize) -> bool) -> Vec<usize> {
    let mut renumber = vec![None; dofs.n_eq()];
    let mut next = 0;
    for (e, r) in renumber.iter_mut().enumerate() {
        if keep(e) {
            *r = Some(next);
            next += 1;
        }
    }
    let mut order = Vec::with_capacity(next);
    for node in nested_dissection(mesh) {
        for d in [Dof::W, Dof::PsiX, Dof::PsiY] {
            if let Some(r) = dofs.eq(node, d).and_then(|e| renumber[e]) {
                order.push(r);
            }
        }
    }
    order
}

#[cfg(test)]
mod tests;
