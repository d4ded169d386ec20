//! The assembled problem shared by every method: plate stiffness K, load vector f, coupling B,
//! foundation compliance T, constraint operator G with its weights, rigid-body basis R and the
//! dofs fixed to define a generalised inverse of K.
//!
//! Discrete equations (unit system of [`crate::scene`]):
//!
//! K u + B σ = f,   g = T σ − Bᵀ u,   and for unbonded contact  Gσ ≥ 0, g ≥ 0, σ·g = 0.
//!
//! Nothing here depends on the solution method; methods only read this value.

pub mod modes;

use std::sync::Arc;

use crate::foundation::kernel::Kernel;
use crate::foundation::{self, fft, pairs, winkler, Compliance, FoundationKind};
use crate::integrals::{line_integrals, patch_integrals};
use crate::mesh::{Dof, DofMap, Mesh};
use crate::model::{ConstraintPoints, Load, Model, Void, Zone};
use crate::plate::{self, Section};
use crate::quadrature::GaussRule;
pub use modes::{jointed_rigid_modes, rigid_modes};

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

/// Load-independent products of the operators that a method computes once and every copy of
/// the operators made by [`Operators::loaded`] reuses (the half-space Schur complement
/// S = T + BᵀK⁻B with the plate factor behind it, the bonded Winkler spring factor that starts
/// the penalty iteration), one per type. Type-erased so that this module need not know the
/// solver's types.
#[derive(Clone, Default)]
pub struct SharedCache(Arc<std::sync::Mutex<SharedSlots>>);

/// One value per type.
type SharedSlots =
    std::collections::HashMap<std::any::TypeId, Arc<dyn std::any::Any + Send + Sync>>;

impl std::fmt::Debug for SharedCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("SharedCache")
    }
}

impl SharedCache {
    /// The cached value of type `T`, if one was computed.
    pub fn get<T: Send + Sync + 'static>(&self) -> Option<Arc<T>> {
        Self::find(&self.slots())
    }

    fn slots(&self) -> std::sync::MutexGuard<'_, SharedSlots> {
        match self.0.lock() {
            Ok(g) => g,
            Err(poisoned) => poisoned.into_inner(),
        }
    }

    fn find<T: Send + Sync + 'static>(slots: &SharedSlots) -> Option<Arc<T>> {
        let key = std::any::TypeId::of::<T>();
        slots.get(&key).and_then(|v| v.clone().downcast::<T>().ok())
    }

    /// The cached value of type `T`, computing it with `init` the first time (other threads
    /// asking at the same time wait for it). Returns whether it was computed by this call. A
    /// failed `init` stores nothing. `init` must not use the cache itself (one lock guards all
    /// types, and it is not re-entrant).
    pub fn get_or_try_init<T: Send + Sync + 'static, E>(
        &self,
        init: impl FnOnce() -> Result<T, E>,
    ) -> Result<(Arc<T>, bool), E> {
        let mut slots = self.slots();
        if let Some(v) = Self::find::<T>(&slots) {
            return Ok((v, false));
        }
        let v = Arc::new(init()?);
        slots.insert(std::any::TypeId::of::<T>(), v.clone());
        Ok((v, true))
    }
}

/// Everything a method needs, assembled once.
#[derive(Debug, Clone)]
pub struct Operators {
    /// The model's grid.
    pub mesh: Mesh,
    /// Dof numbering.
    pub dofs: DofMap,
    /// Plate section in the unit system (the reference plate's).
    pub section: Section,
    /// The section of every whole-plate panel ([`crate::system::panel_sections`]; one entry,
    /// the reference, without a layout).
    pub sections: Vec<Section>,
    /// Foundation model.
    pub foundation: FoundationKind,
    /// Its surface kernel (None for the local Winkler soil).
    pub kernel: Option<Kernel>,
    /// Stiffness K (n_eq × n_eq, singular: free plate). Shared (not copied) by the operators
    /// of every load combination.
    pub k: Arc<sprs::CsMat<f64>>,
    /// Load vector f (n_eq).
    pub f: Vec<f64>,
    /// Coupling B (n_eq × n_σ); diagonal in the w rows for Winkler (lumped).
    pub b: Arc<sprs::CsMat<f64>>,
    /// Compliance T.
    pub t: Arc<Compliance>,
    /// Initial gap g₀ (n_σ) of the voids: g = Tσ − Bᵀu + g₀ with g₀_i = ∫ f_i d, d the void
    /// depth; all zero without voids.
    pub gap0: Vec<f64>,
    /// Constraint points.
    pub constraints: Constraints,
    /// Rigid-body modes of the model, each a vector over the equations.
    pub rigid: Vec<Vec<f64>>,
    /// Equations fixed to zero to define the generalised inverse K⁻ (one per rigid mode).
    pub fixed: Vec<usize>,
    /// The cluster of each rigid mode: pieces of a jointed plate joined by transferring joints
    /// (all 0 on a plate of one piece).
    pub rigid_clusters: Vec<usize>,
    /// Foundation constant c in the unit system (μΓ): scales the penalty compliance.
    pub foundation_constant: f64,
    /// Notes on modelling decisions (symmetry fall-backs …).
    pub notes: Vec<String>,
    /// Load-independent products shared by every load combination (see [`SharedCache`]). They
    /// hold for the K, B, T, constraints and rigid modes above: whoever replaces one of those
    /// must give the operators a fresh `SharedCache::default()`.
    pub cache: SharedCache,
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
        Self::assemble_shared(std::slice::from_ref(model))
    }

    /// Assemble with the half-space T held as a dense matrix (`toeplitz` false) or as the
    /// matrix-free FFT operator of the iterative route (true; [`crate::method::Route`] decides
    /// from the size and the method, [`crate::budget::check_route`] checks the memory). Winkler
    /// T is diagonal either way.
    pub fn assemble_with(model: &Model, toeplitz: bool) -> Self {
        Self::assemble_shared_with(std::slice::from_ref(model), toeplitz)
    }

    /// Assemble once for several models of the same plate, foundation and mesh that differ in
    /// their loads and voids (the combinations of a scene), on the grid all of them allow
    /// ([`crate::model::plan_shared_mesh`]), loaded with the first model; [`Self::loaded`] gives
    /// the others' operators without re-assembly. An empty slice is a caller error and yields
    /// an empty model's operators.
    pub fn assemble_shared(models: &[Model]) -> Self {
        Self::assemble_shared_with(models, false)
    }

    /// [`Self::assemble_shared`] with the half-space T dense or as an FFT operator (`toeplitz`).
    pub fn assemble_shared_with(models: &[Model], toeplitz: bool) -> Self {
        let (mesh, notes) = crate::model::plan_shared_mesh(models);
        let Some(model) = models.first() else {
            return Self::build(
                mesh,
                Section {
                    bending: 1.0,
                    shear: 1.0,
                    poisson: 0.0,
                },
                FoundationKind::Winkler,
                None,
                1.0,
                &[],
                ConstraintPoints::Nodal,
                notes,
            );
        };
        let g = &model.groups;
        let section = Section {
            bending: 1.0,
            shear: 1.0 / (g.mu * g.delta),
            poisson: g.nu,
        };
        let c = g.mu * g.gamma;
        let mut ops = Self::build_all(
            mesh,
            section,
            g.foundation(),
            g.kernel(),
            c,
            &model.zones,
            &model.loads,
            model.constraint,
            notes,
            toeplitz,
        );
        ops.gap0 = void_gap(&ops.mesh, &model.voids);
        ops
    }

    /// The same operators with another model's loads and voids (its f and g₀): K, B and T are
    /// shared, not copied. The model must be one of those the operators were assembled for.
    pub fn loaded(&self, model: &Model) -> Self {
        Self {
            f: load_vector_with(&self.mesh, &self.dofs, &self.section, &model.loads),
            gap0: void_gap(&self.mesh, &model.voids),
            ..self.clone()
        }
    }

    /// Assemble from parts: a mesh, a section, the foundation with its kernel (None for the
    /// local Winkler soil; [`crate::model::Groups::kernel`]) and its constant (1/K for Winkler,
    /// (1 − ν_s²)/(π E_s) for the half-space, in consistent units), whole-plate loads and the
    /// constraint points.
    #[allow(clippy::too_many_arguments)]
    pub fn build(
        mesh: Mesh,
        section: Section,
        foundation: FoundationKind,
        kernel: Option<Kernel>,
        foundation_constant: f64,
        loads: &[Load],
        constraint: ConstraintPoints,
        notes: Vec<String>,
    ) -> Self {
        Self::build_all(
            mesh,
            section,
            foundation,
            kernel,
            foundation_constant,
            &[],
            loads,
            constraint,
            notes,
            false,
        )
    }

    /// [`Self::build`] with Winkler zones of another modulus, and a non-local T dense or,
    /// `toeplitz`, as the FFT operator of the iterative route ([`fft::ToeplitzCompliance`]).
    #[allow(clippy::too_many_arguments)]
    pub fn build_all(
        mesh: Mesh,
        section: Section,
        foundation: FoundationKind,
        kernel: Option<Kernel>,
        foundation_constant: f64,
        zones: &[Zone],
        loads: &[Load],
        constraint: ConstraintPoints,
        mut notes: Vec<String>,
        toeplitz: bool,
    ) -> Self {
        debug_assert_eq!(
            foundation.is_local(),
            kernel.is_none(),
            "a local soil has no kernel, every other one has"
        );
        let dofs = DofMap::new(&mesh);
        let sections = crate::system::panel_sections(&mesh, &section);
        let k = match mesh.topo {
            Some(_) => crate::system::assemble_system(&mesh, &dofs, &sections),
            None => plate::assemble_stiffness(&mesh, &dofs, &section),
        };
        let f = load_vector_with(&mesh, &dofs, &section, loads);
        let (b, t) = match &kernel {
            None => (
                foundation::coupling(&mesh, &dofs, true),
                winkler::zoned_compliance(&mesh, 1.0 / foundation_constant, zones),
            ),
            Some(kernel) if toeplitz => {
                let t = fft::ToeplitzCompliance::with_kernel(&mesh, foundation_constant, kernel);
                notes.push(format!(
                    "iterative route: T applied by FFT on a {} × {} padded grid, penalty steps by preconditioned conjugate gradients",
                    t.padded()[0],
                    t.padded()[1]
                ));
                (
                    foundation::coupling(&mesh, &dofs, false),
                    Compliance::Toeplitz(Box::new(t)),
                )
            }
            Some(kernel) => (
                foundation::coupling(&mesh, &dofs, false),
                pairs::compliance(&mesh, foundation_constant, kernel),
            ),
        };
        let constraints = constraint_points(&mesh, constraint);
        let (rigid, fixed, rigid_clusters) = jointed_rigid_modes(&mesh, &dofs);
        let gap0 = vec![0.0; mesh.n_nodes()];
        Self {
            mesh,
            dofs,
            section,
            sections,
            foundation,
            kernel,
            k: Arc::new(k),
            f,
            b: Arc::new(b),
            t: Arc::new(t),
            gap0,
            constraints,
            rigid,
            fixed,
            rigid_clusters,
            foundation_constant,
            notes,
            cache: SharedCache::default(),
        }
    }

    /// The section of model element e (its panel's).
    pub fn section_of(&self, e: usize) -> Section {
        let p = self.mesh.panel_of(e);
        self.sections.get(p).copied().unwrap_or(self.section)
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

/// Consistent load vector of whole-plate force loads on the (possibly reduced) model (see
/// [`load_vector_with`]; temperature loads need the section and are skipped here).
pub fn load_vector(mesh: &Mesh, dofs: &DofMap, loads: &[Load]) -> Vec<f64> {
    let section = Section {
        bending: 1.0,
        shear: 1.0,
        poisson: 0.0,
    };
    let forces: Vec<Load> = loads
        .iter()
        .filter(|l| !matches!(l, Load::Temperature { .. } | Load::FaceStress { .. }))
        .copied()
        .collect();
    load_vector_with(mesh, dofs, &section, &forces)
}

/// Consistent load vector of whole-plate loads on the (possibly reduced) model. A reduced model
/// carries the loads on its side of each symmetry line and half of those on the line;
/// distributed loads are integrated over the model's part of the plate.
///
/// A temperature load is the initial curvature κ₀ = κ (1, 1, 0): its nodal vector is
/// ∫ B_bᵀ D_b κ₀ dA element by element, the consistent equivalent of the thermal moment
/// m_T = D (1 + ν) κ along the free edges. On a plate with panels of their own section each
/// panel takes its D_p and the free curvature κ H/H_p of its thickness.
pub fn load_vector_with(mesh: &Mesh, dofs: &DofMap, section: &Section, loads: &[Load]) -> Vec<f64> {
    let mut f = vec![0.0; dofs.n_eq()];
    let tol = 1e-9;
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
                        if let Some(q) = dofs.eq(node, Dof::W) {
                            f[q] += weight * force * n[a];
                        }
                    }
                }
            }
            Load::Patch { x, y, pressure } => {
                for (node, v) in patch_integrals(mesh, x, y) {
                    if let Some(q) = dofs.eq(node, Dof::W) {
                        f[q] += pressure * v;
                    }
                }
            }
            Load::Line {
                from,
                to,
                force_per_length,
            } => {
                for (node, v) in line_integrals(mesh, from, to) {
                    if let Some(q) = dofs.eq(node, Dof::W) {
                        f[q] += force_per_length * v;
                    }
                }
            }
            // A face stress bends nothing: it has no nodal load.
            Load::FaceStress { .. } => {}
            Load::Temperature { curvature } => {
                // Per panel: its bending section and its free curvature κ H/H_p (the same
                // ΔT curls a thinner panel more); one entry without a layout.
                let sections = crate::system::panel_sections(mesh, section);
                let ratios = mesh.topo.as_ref().map(|t| t.layout.sections());
                let rule = GaussRule::new(2);
                let det = 0.25 * mesh.hx * mesh.hy;
                let fes: Vec<plate::ElementVector> = sections
                    .iter()
                    .enumerate()
                    .map(|(p, sec)| {
                        let kappa = curvature / ratios.as_ref().map_or(1.0, |r| r[p].thickness);
                        let m = plate::bending_constitutive(sec)
                            * nalgebra::Vector3::new(kappa, kappa, 0.0);
                        let mut fe = plate::ElementVector::zeros();
                        for (&xi, &wx) in rule.points.iter().zip(&rule.weights) {
                            for (&eta, &wy) in rule.points.iter().zip(&rule.weights) {
                                let b = plate::bending_strain(xi, eta, mesh.hx, mesh.hy);
                                fe += b.transpose() * m * (wx * wy * det);
                            }
                        }
                        fe
                    })
                    .collect();
                for e in mesh.elements() {
                    let fe = &fes[mesh.panel_of(e).min(fes.len() - 1)];
                    for (a, node) in mesh.element_nodes(e).into_iter().enumerate() {
                        for (k, dof) in [Dof::W, Dof::PsiX, Dof::PsiY].into_iter().enumerate() {
                            if let Some(q) = dofs.eq(node, dof) {
                                f[q] += fe[3 * a + k];
                            }
                        }
                    }
                }
            }
        }
    }
    f
}

/// Initial gap of the voids on the model: g₀_i = Σ_voids depth ∫_void f_i dA.
pub fn void_gap(mesh: &Mesh, voids: &[Void]) -> Vec<f64> {
    let mut g = vec![0.0; mesh.n_nodes()];
    for v in voids {
        for (node, a) in patch_integrals(mesh, v.x, v.y) {
            g[node] += v.depth * a;
        }
    }
    g
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
            let ne = mesh.elements().count();
            let mut tri = sprs::TriMat::new((4 * ne, n));
            let mut weights = Vec::with_capacity(4 * ne);
            let mut points = Vec::with_capacity(4 * ne);
            let det = 0.25 * mesh.hx * mesh.hy;
            for e in mesh.elements() {
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
