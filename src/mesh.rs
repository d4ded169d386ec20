//! Structured rectangular grid of the plate model, symmetry reduction and degree-of-freedom map.
//!
//! Everything here is in the solver's unit system: lengths in units of L (half the plate side
//! along x), so the whole plate is [−1, 1] × [−μ, μ]. A model reduced by symmetry about x = 0
//! keeps x ≥ 0, one reduced about y = 0 keeps y ≥ 0; the symmetry lines are grid lines, so the
//! element counts of the whole plate must be even in the reduced directions.

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
        }
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

    /// Number of nodes in the model.
    pub fn n_nodes(&self) -> usize {
        self.nodes_x() * self.nodes_y()
    }

    /// Number of elements in the model.
    pub fn n_elements(&self) -> usize {
        self.nx * self.ny
    }

    /// Node index of grid position (i, j).
    pub fn node(&self, i: usize, j: usize) -> usize {
        i + j * self.nodes_x()
    }

    /// Coordinates of node n.
    pub fn node_xy(&self, n: usize) -> (f64, f64) {
        let i = n % self.nodes_x();
        let j = n / self.nodes_x();
        (self.x0 + i as f64 * self.hx, self.y0 + j as f64 * self.hy)
    }

    /// The four nodes of element e, counter-clockwise from the lower-left corner.
    pub fn element_nodes(&self, e: usize) -> [usize; 4] {
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
    pub fn locate(&self, x: f64, y: f64) -> Option<(usize, f64, f64)> {
        let fx = (x - self.x0) / self.hx;
        let fy = (y - self.y0) / self.hy;
        let tol = 1e-9;
        if !(fx >= -tol && fy >= -tol && fx <= self.nx as f64 + tol && fy <= self.ny as f64 + tol) {
            return None;
        }
        let ie = (fx.floor().max(0.0) as usize).min(self.nx - 1);
        let je = (fy.floor().max(0.0) as usize).min(self.ny - 1);
        let xi = 2.0 * (fx - ie as f64) - 1.0;
        let eta = 2.0 * (fy - je as f64) - 1.0;
        Some((ie + je * self.nx, xi.clamp(-1.0, 1.0), eta.clamp(-1.0, 1.0)))
    }

    /// Nodal values of `other`'s grid (same plate, any element counts and reduction) at this
    /// grid's nodes by bilinear interpolation; a node outside a reduced `other` takes the value
    /// of its mirror image (a reduced model's fields are symmetric).
    pub fn interpolate_from(&self, other: &Mesh, values: &[f64]) -> Vec<f64> {
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
                    let nodes = other.element_nodes(e);
                    // Corner order of `element_nodes`: (−,−), (+,−), (+,+), (−,+).
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
                })
            })
            .collect()
    }

    /// Area of one element.
    pub fn element_area(&self) -> f64 {
        self.hx * self.hy
    }
}

/// Map from node degrees of freedom to equation numbers; symmetry conditions remove the rotation
/// normal to a symmetry line (ψx = 0 on x = 0, ψy = 0 on y = 0).
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
            let i = n % mesh.nodes_x();
            let j = n / mesh.nodes_x();
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
/// this is the optimal fill-reducing order (George 1973): O(n log n) fill, O(n^1.5) work.
pub fn nested_dissection(mesh: &Mesh) -> Vec<usize> {
    fn recurse(mesh: &Mesh, i0: usize, i1: usize, j0: usize, j1: usize, out: &mut Vec<usize>) {
        if i0 > i1 || j0 > j1 {
            return;
        }
        let (w, h) = (i1 - i0 + 1, j1 - j0 + 1);
        if w * h <= 16 {
            for j in j0..=j1 {
                for i in i0..=i1 {
                    out.push(mesh.node(i, j));
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
                out.push(mesh.node(m, j));
            }
        } else {
            let m = j0 + h / 2;
            if m > j0 {
                recurse(mesh, i0, i1, j0, m - 1, out);
            }
            recurse(mesh, i0, i1, m + 1, j1, out);
            for i in i0..=i1 {
                out.push(mesh.node(i, m));
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
mod tests {
    use super::*;

    #[test]
    fn quarter_mesh_of_an_even_grid_has_half_the_elements_each_way() {
        let m = Mesh::new(2.0, 1.0, [8, 6], true, true);
        assert_eq!((m.nx, m.ny), (4, 3));
        assert_eq!(m.full_elements(), [8, 6]);
        assert_eq!(m.copies(), 4);
        assert_eq!(m.node_xy(m.node(4, 3)), (1.0, 0.5));
    }

    #[test]
    fn odd_counts_are_not_reduced() {
        let m = Mesh::new(2.0, 2.0, [7, 8], true, true);
        assert!(!m.sym_x && m.sym_y);
        assert_eq!(m.symmetry_name(), "half-y");
    }

    #[test]
    fn locate_finds_element_and_local_coordinates() {
        let m = Mesh::new(2.0, 2.0, [4, 4], false, false);
        let (e, xi, eta) = m.locate(-0.75, 0.25).unwrap();
        assert_eq!(m.element_ij(e), (0, 2));
        assert!(
            xi.abs() < 1e-12 && eta.abs() < 1e-12,
            "centre of element (0, 2)"
        );
        assert!(m.locate(1.0 + 1e-3, 0.0).is_none());
        assert!(
            m.locate(1.0, 1.0).is_some(),
            "corner on the boundary is inside"
        );
    }

    #[test]
    fn nested_dissection_is_a_permutation() {
        for (nx, ny) in [(1, 1), (7, 3), (40, 25)] {
            let m = Mesh::new(2.0, 1.0, [nx, ny], false, false);
            let mut order = nested_dissection(&m);
            assert_eq!(order.len(), m.n_nodes(), "{nx} × {ny}");
            order.sort_unstable();
            assert!(
                order.iter().enumerate().all(|(i, &n)| i == n),
                "{nx} × {ny}: every node once"
            );
        }
    }

    #[test]
    fn symmetry_lines_lose_their_normal_rotation() {
        let m = Mesh::new(2.0, 2.0, [4, 4], true, true);
        let d = DofMap::new(&m);
        // 9 nodes × 3 dofs, minus ψx on the 3 nodes of x = 0 and ψy on the 3 nodes of y = 0.
        assert_eq!(d.n_eq(), 27 - 6);
        assert!(d.eq(m.node(0, 1), Dof::PsiX).is_none());
        assert!(d.eq(m.node(0, 1), Dof::PsiY).is_some());
        assert!(d.eq(m.node(1, 0), Dof::PsiY).is_none());
    }

    /// Bilinear interpolation reproduces a bilinear field exactly on any finer or coarser
    /// grid, and a reduced grid's field is read through its mirror images.
    #[test]
    fn interpolation_is_exact_for_bilinear_fields_and_mirrors_reduced_grids() {
        let f = |x: f64, y: f64| 1.0 + 2.0 * x - 3.0 * y + 0.5 * x * y;
        let coarse = Mesh::new(2.0, 1.5, [6, 4], false, false);
        let values: Vec<f64> = (0..coarse.n_nodes())
            .map(|n| {
                let (x, y) = coarse.node_xy(n);
                f(x, y)
            })
            .collect();
        let fine = Mesh::new(2.0, 1.5, [14, 10], false, false);
        let got = fine.interpolate_from(&coarse, &values);
        for (n, v) in got.iter().enumerate() {
            let (x, y) = fine.node_xy(n);
            // Linear in each direction within a coarse element: exact to round-off.
            assert!(
                (v - f(x, y)).abs() < 1e-13,
                "at ({x}, {y}): {v} vs {}",
                f(x, y)
            );
        }
        // A field even in x and y held on a quarter grid, read on the whole plate.
        let g = |x: f64, y: f64| 2.0 + x.abs() + 0.25 * y.abs();
        let quarter = Mesh::new(2.0, 1.5, [8, 6], true, true);
        let q: Vec<f64> = (0..quarter.n_nodes())
            .map(|n| {
                let (x, y) = quarter.node_xy(n);
                g(x, y)
            })
            .collect();
        let whole = Mesh::new(2.0, 1.5, [8, 6], false, false);
        for (n, v) in whole.interpolate_from(&quarter, &q).iter().enumerate() {
            let (x, y) = whole.node_xy(n);
            assert!((v - g(x, y)).abs() < 1e-13);
        }
    }
}
