//! The assembled problem shared by every method: plate stiffness K, load vector f, coupling B,
//! foundation compliance T, constraint operator G with its weights, rigid-body basis R and the
//! dofs fixed to define a generalised inverse of K.
//!
//! Discrete equations (unit system of [`crate::scene`]):
//!
//! K u + B σ = f,   g = T σ − Bᵀ u,   and for unbonded contact  Gσ ≥ 0, g ≥ 0, σ·g = 0.
//!
//! Nothing here depends on the solution method; methods only read this value.

use crate::foundation::{self, fft, halfspace, winkler, Compliance, FoundationKind};
use crate::mesh::{Dof, DofMap, Mesh};
use crate::model::{ConstraintPoints, Load, Model};
use crate::plate::{self, Section};
use crate::quadrature::GaussRule;

/// Where σ ≥ 0 is imposed: rows of G (interpolation of nodal σ) and their area weights.
#[derive(Debug, Clone)]
pub struct Constraints {
    /// Which points.
    pub kind: ConstraintPoints,
    /// G (n_c × n_σ).
    pub g: sprs::CsMat<f64>,
    /// Area weight of each constraint point (∫ f_i for nodes, Gauss weight × area for Gauss).
    pub weights: Vec<f64>,
    /// (x, y) of each constraint point.
    pub points: Vec<(f64, f64)>,
}

/// Everything a method needs, assembled once.
#[derive(Debug, Clone)]
pub struct Operators {
    /// The model's grid.
    pub mesh: Mesh,
    /// Dof numbering.
    pub dofs: DofMap,
    /// Plate section in the unit system.
    pub section: Section,
    /// Foundation model.
    pub foundation: FoundationKind,
    /// Stiffness K (n_eq × n_eq, singular: free plate).
    pub k: sprs::CsMat<f64>,
    /// Load vector f (n_eq).
    pub f: Vec<f64>,
    /// Coupling B (n_eq × n_σ); diagonal in the w rows for Winkler (lumped).
    pub b: sprs::CsMat<f64>,
    /// Compliance T.
    pub t: Compliance,
    /// Constraint points.
    pub constraints: Constraints,
    /// Rigid-body modes of the model, each a vector over the equations.
    pub rigid: Vec<Vec<f64>>,
    /// Equations fixed to zero to define the generalised inverse K⁻ (one per rigid mode).
    pub fixed: Vec<usize>,
    /// Foundation constant c in the unit system (μΓ): scales the penalty compliance.
    pub foundation_constant: f64,
    /// Notes on modelling decisions (symmetry fall-backs …).
    pub notes: Vec<String>,
}

/// y = A x with sprs's product (CSC or CSR storage alike).
fn mat_vec(a: sprs::CsMatView<'_, f64>, x: &[f64]) -> Vec<f64> {
    let mut y = vec![0.0; a.rows()];
    if a.is_csc() {
        sprs::prod::mul_acc_mat_vec_csc(a, x, &mut y[..]);
    } else {
        sprs::prod::mul_acc_mat_vec_csr(a, x, &mut y[..]);
    }
    y
}

impl Operators {
    /// Assemble all operators of a model. Knows nothing of the method that will use them;
    /// check the memory budget ([`crate::budget::check`]) first for large models. A half-space
    /// T is dense; [`Operators::assemble_with`] chooses.
    pub fn assemble(model: &Model) -> Self {
        Self::assemble_with(model, false)
    }

    /// Assemble with the half-space T held as a dense matrix (`toeplitz` false) or as the
    /// matrix-free FFT operator of the iterative route (true; [`crate::method::Route`] decides
    /// from the size and the method). Winkler T is diagonal either way.
    pub fn assemble_with(model: &Model, toeplitz: bool) -> Self {
        let (mesh, notes) = model.plan_mesh();
        let g = &model.groups;
        let section = Section {
            bending: 1.0,
            shear: 1.0 / (g.mu * g.delta),
            poisson: g.nu,
        };
        let c = g.mu * g.gamma;
        let mut ops = Self::build_with(
            mesh,
            section,
            g.foundation,
            c,
            &model.loads,
            model.constraint,
            notes,
            toeplitz,
        );
        if toeplitz && g.foundation == FoundationKind::HalfSpace {
            ops.notes.push(format!(
                "iterative route: T applied by FFT on a {} × {} padded grid, penalty steps by preconditioned conjugate gradients",
                match &ops.t {
                    Compliance::Toeplitz(t) => t.padded()[0],
                    _ => 0,
                },
                match &ops.t {
                    Compliance::Toeplitz(t) => t.padded()[1],
                    _ => 0,
                }
            ));
        }
        ops
    }

    /// Assemble from parts: a mesh, a section, the foundation and its constant
    /// (1/K for Winkler, (1 − ν_s²)/(π E_s) for the half-space, in consistent units), whole-plate
    /// loads and the constraint points.
    pub fn build(
        mesh: Mesh,
        section: Section,
        foundation: FoundationKind,
        foundation_constant: f64,
        loads: &[Load],
        constraint: ConstraintPoints,
        notes: Vec<String>,
    ) -> Self {
        Self::build_with(
            mesh,
            section,
            foundation,
            foundation_constant,
            loads,
            constraint,
            notes,
            false,
        )
    }

    /// [`Operators::build`] with the half-space T dense or as an FFT operator (`toeplitz`).
    #[allow(clippy::too_many_arguments)]
    pub fn build_with(
        mesh: Mesh,
        section: Section,
        foundation: FoundationKind,
        foundation_constant: f64,
        loads: &[Load],
        constraint: ConstraintPoints,
        notes: Vec<String>,
        toeplitz: bool,
    ) -> Self {
        let dofs = DofMap::new(&mesh);
        let k = plate::assemble_stiffness(&mesh, &dofs, &section);
        let f = load_vector(&mesh, &dofs, loads);
        let (b, t) = match foundation {
            FoundationKind::Winkler => (
                foundation::coupling(&mesh, &dofs, true),
                winkler::compliance(&mesh, 1.0 / foundation_constant),
            ),
            FoundationKind::HalfSpace => (
                foundation::coupling(&mesh, &dofs, false),
                if toeplitz {
                    Compliance::Toeplitz(Box::new(fft::ToeplitzCompliance::new(
                        &mesh,
                        foundation_constant,
                    )))
                } else {
                    halfspace::compliance(&mesh, foundation_constant)
                },
            ),
        };
        let constraints = constraint_points(&mesh, constraint);
        let (rigid, fixed) = rigid_modes(&mesh, &dofs);
        Self {
            mesh,
            dofs,
            section,
            foundation,
            k,
            f,
            b,
            t,
            constraints,
            rigid,
            fixed,
            foundation_constant,
            notes,
        }
    }

    /// Number of equations.
    pub fn n_eq(&self) -> usize {
        self.dofs.n_eq()
    }

    /// Number of pressure unknowns.
    pub fn n_sigma(&self) -> usize {
        self.mesh.n_nodes()
    }

    /// B σ.
    pub fn b_times(&self, sigma: &[f64]) -> Vec<f64> {
        mat_vec(self.b.view(), sigma)
    }

    /// Bᵀ u.
    pub fn bt_times(&self, u: &[f64]) -> Vec<f64> {
        mat_vec(self.b.transpose_view(), u)
    }

    /// K u.
    pub fn k_times(&self, u: &[f64]) -> Vec<f64> {
        mat_vec(self.k.view(), u)
    }

    /// G σ: pressure at the constraint points.
    pub fn g_times(&self, sigma: &[f64]) -> Vec<f64> {
        mat_vec(self.constraints.g.view(), sigma)
    }

    /// Total load on the model, Σ f over the w equations (the model's share of 4P).
    pub fn total_load(&self) -> f64 {
        (0..self.mesh.n_nodes())
            .filter_map(|n| self.dofs.eq(n, Dof::W))
            .map(|e| self.f[e])
            .sum()
    }

    /// Deflection w at every model node from a solution vector.
    pub fn node_w(&self, u: &[f64]) -> Vec<f64> {
        (0..self.mesh.n_nodes())
            .map(|n| self.dofs.eq(n, Dof::W).map_or(0.0, |e| u[e]))
            .collect()
    }
}

/// Consistent load vector of whole-plate loads on the (possibly reduced) model. A reduced model
/// carries the loads on its side of each symmetry line and half of those on the line.
pub fn load_vector(mesh: &Mesh, dofs: &DofMap, loads: &[Load]) -> Vec<f64> {
    let mut f = vec![0.0; dofs.n_eq()];
    let tol = 1e-9;
    let x_lo = mesh.x0;
    let x_hi = mesh.x0 + mesh.nx as f64 * mesh.hx;
    let y_lo = mesh.y0;
    let y_hi = mesh.y0 + mesh.ny as f64 * mesh.hy;
    let mut add = |node: usize, v: f64| {
        if let Some(e) = dofs.eq(node, Dof::W) {
            f[e] += v;
        }
    };
    for load in loads {
        match *load {
            Load::Point { x, y, force } => {
                let mut weight = 1.0;
                if mesh.sym_x {
                    if x < -tol {
                        continue;
                    }
                    if x.abs() <= tol {
                        weight *= 0.5;
                    }
                }
                if mesh.sym_y {
                    if y < -tol {
                        continue;
                    }
                    if y.abs() <= tol {
                        weight *= 0.5;
                    }
                }
                if let Some((e, xi, eta)) = mesh.locate(x, y) {
                    let n = plate::shape(xi, eta);
                    for (a, node) in mesh.element_nodes(e).into_iter().enumerate() {
                        add(node, weight * force * n[a]);
                    }
                }
            }
            Load::Patch { x, y, pressure } => {
                let (ax, bx) = (x[0].max(x_lo), x[1].min(x_hi));
                let (ay, by) = (y[0].max(y_lo), y[1].min(y_hi));
                if bx <= ax || by <= ay {
                    continue;
                }
                let rule = GaussRule::new(2);
                let i0 = (((ax - x_lo) / mesh.hx).floor().max(0.0) as usize).min(mesh.nx - 1);
                let i1 = (((bx - x_lo) / mesh.hx).ceil() as usize).clamp(i0 + 1, mesh.nx);
                let j0 = (((ay - y_lo) / mesh.hy).floor().max(0.0) as usize).min(mesh.ny - 1);
                let j1 = (((by - y_lo) / mesh.hy).ceil() as usize).clamp(j0 + 1, mesh.ny);
                for je in j0..j1 {
                    for ie in i0..i1 {
                        let ex0 = x_lo + ie as f64 * mesh.hx;
                        let ey0 = y_lo + je as f64 * mesh.hy;
                        let (cx0, cx1) = (ax.max(ex0), bx.min(ex0 + mesh.hx));
                        let (cy0, cy1) = (ay.max(ey0), by.min(ey0 + mesh.hy));
                        if cx1 <= cx0 || cy1 <= cy0 {
                            continue;
                        }
                        let e = ie + je * mesh.nx;
                        let nodes = mesh.element_nodes(e);
                        for (px, wx) in rule.on_interval(cx0, cx1) {
                            for (py, wy) in rule.on_interval(cy0, cy1) {
                                let n = plate::shape(
                                    2.0 * (px - ex0) / mesh.hx - 1.0,
                                    2.0 * (py - ey0) / mesh.hy - 1.0,
                                );
                                for a in 0..4 {
                                    add(nodes[a], pressure * wx * wy * n[a]);
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    f
}

/// Constraint operator G and weights for nodal or Gauss-point constraints.
pub fn constraint_points(mesh: &Mesh, kind: ConstraintPoints) -> Constraints {
    let n = mesh.n_nodes();
    match kind {
        ConstraintPoints::Nodal => {
            let g = sprs::CsMat::eye(n);
            let weights = foundation::nodal_areas(mesh);
            let points = (0..n).map(|i| mesh.node_xy(i)).collect();
            Constraints {
                kind,
                g,
                weights,
                points,
            }
        }
        ConstraintPoints::Gauss => {
            let rule = GaussRule::new(2);
            let ne = mesh.n_elements();
            let mut tri = sprs::TriMat::new((4 * ne, n));
            let mut weights = Vec::with_capacity(4 * ne);
            let mut points = Vec::with_capacity(4 * ne);
            let det = 0.25 * mesh.hx * mesh.hy;
            for e in 0..ne {
                let nodes = mesh.element_nodes(e);
                let (xc, yc) = mesh.element_centre(e);
                for (&eta, &wy) in rule.points.iter().zip(&rule.weights) {
                    for (&xi, &wx) in rule.points.iter().zip(&rule.weights) {
                        let row = weights.len();
                        let sh = plate::shape(xi, eta);
                        for a in 0..4 {
                            tri.add_triplet(row, nodes[a], sh[a]);
                        }
                        weights.push(wx * wy * det);
                        points.push((xc + 0.5 * xi * mesh.hx, yc + 0.5 * eta * mesh.hy));
                    }
                }
            }
            Constraints {
                kind,
                g: tri.to_csc(),
                weights,
                points,
            }
        }
    }
}

/// Rigid-body modes of the (reduced) free plate and the w-equations to fix for a generalised
/// inverse: translation w = 1 always; rotation w = x, ψx = 1 unless the model is reduced about
/// x = 0; rotation w = y, ψy = 1 unless reduced about y = 0.
pub fn rigid_modes(mesh: &Mesh, dofs: &DofMap) -> (Vec<Vec<f64>>, Vec<usize>) {
    let n_eq = dofs.n_eq();
    let mut modes = Vec::new();
    let mut translation = vec![0.0; n_eq];
    let mut rot_x = vec![0.0; n_eq];
    let mut rot_y = vec![0.0; n_eq];
    for n in 0..mesh.n_nodes() {
        let (x, y) = mesh.node_xy(n);
        if let Some(e) = dofs.eq(n, Dof::W) {
            translation[e] = 1.0;
            rot_x[e] = x;
            rot_y[e] = y;
        }
        if let Some(e) = dofs.eq(n, Dof::PsiX) {
            rot_x[e] = 1.0;
        }
        if let Some(e) = dofs.eq(n, Dof::PsiY) {
            rot_y[e] = 1.0;
        }
    }
    modes.push(translation);
    if !mesh.sym_x {
        modes.push(rot_x);
    }
    if !mesh.sym_y {
        modes.push(rot_y);
    }
    // Fixed nodes: corners far from the symmetry lines, non-collinear.
    let (i_max, j_max) = (mesh.nx, mesh.ny);
    let corners: Vec<(usize, usize)> = match (mesh.sym_x, mesh.sym_y) {
        (false, false) => vec![(0, 0), (i_max, 0), (0, j_max)],
        (true, false) => vec![(i_max, 0), (i_max, j_max)],
        (false, true) => vec![(0, j_max), (i_max, j_max)],
        (true, true) => vec![(i_max, j_max)],
    };
    let fixed = corners
        .into_iter()
        .filter_map(|(i, j)| dofs.eq(mesh.node(i, j), Dof::W))
        .collect();
    (modes, fixed)
}
