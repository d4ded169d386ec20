//! The linear solver of one penalty step: the bilateral problem with compliance T + Σ/ε̄ on the
//! shared operators, without re-assembly (see [`super::penalty`] for the iteration around it).
//! Winkler with nodal constraints keeps the sparse SPD form K + B (T + Σ/ε̄)⁻¹ Bᵀ (only diagonal
//! values change; the bonded factor of the first step is shared by every load combination and
//! later steps are Woodbury updates of the last factor); Winkler with Gauss constraints solves
//! the sparse saddle system by LU on a fixed pattern; the half-space either updates the dense
//! Schur factor by low rank or, on the iterative route, runs preconditioned CG.

use std::collections::HashMap;
use std::sync::Arc;

use faer::linalg::solvers::Solve;
use faer::sparse::linalg::solvers::{Lu, SymbolicLu};
use faer::Mat;

use super::bonded::{saddle_solve, SchurSystem};
use super::diagnostics::CgReport;
use super::iterative::{CgSettings, IterativeSchur};
use super::linalg::{diagonal_positions, lumped_coupling};
use super::linalg::{faer_view, SparseCholesky, SparseFactor};
use super::low_rank::LowRankSchur;
use super::rigid_split::{needs_split, RigidSplit};
use super::spring_factor::{woodbury_limit, Carry, Factored};
use crate::error::{Error, Result};
use crate::foundation::Compliance;
use crate::model::ConstraintPoints;
use crate::monitor::Monitor;
use crate::operators::Operators;

/// The analysed Winkler spring system (its symbolic factorisation), once per assembly.
struct SpringsAnalysis(SparseCholesky);

/// What the Winkler spring route reads of an assembly at every solve, found once per assembly:
/// the data position of each diagonal entry of K, each pressure node's w equation with its
/// ∫ f_j ([`lumped_coupling`]), and whether the bonded springs hold the plate so softly that
/// every step takes the split solve ([`needs_split`]).
pub(super) struct SpringsLayout {
    diag: Vec<usize>,
    coupling: Vec<(usize, f64)>,
    bonded_springs: Vec<(usize, f64)>,
    split: bool,
}

impl SpringsLayout {
    fn of(ops: &Operators, t: &[f64]) -> Result<Self> {
        let diag = diagonal_positions(&ops.k)?;
        let coupling = lumped_coupling(ops)?;
        let bonded_springs: Vec<(usize, f64)> = coupling
            .iter()
            .zip(t)
            .map(|(&(eq, b), &c)| (eq, b * b / c))
            .collect();
        let split = needs_split(ops, &bonded_springs);
        Ok(Self {
            diag,
            coupling,
            bonded_springs,
            split,
        })
    }
}

/// The bonded factor of the Winkler spring system (no penalty springs): where a cold penalty
/// iteration on an assembly starts.
struct SpringsStart {
    factor: Arc<SparseFactor>,
    springs: Vec<f64>,
}

/// Linear solver of one penalised bilateral problem.
pub(super) enum Backend {
    Springs {
        /// A working copy of K whose diagonal takes the springs of a new factorisation, made
        /// when a step first needs one (a step solved by an update of the carried factor reads
        /// nothing of K).
        k: Option<sprs::CsMat<f64>>,
        layout: Arc<SpringsLayout>,
        t: Vec<f64>,
        chol: SparseCholesky,
        /// The last numeric factor, the spring stiffness per pressure node it was made with and
        /// its Woodbury columns.
        factored: Option<Factored>,
        /// The split solve of a nearly rigid plate ([`RigidSplit`]), made when first needed.
        split: Option<Box<RigidSplit>>,
    },
    Saddle {
        m: sprs::CsMat<f64>,
        /// Data positions of the σσ block entries, keyed by (row, col) in σ numbering.
        sigma_pos: HashMap<(usize, usize), usize>,
        t: Vec<f64>,
        symbolic: SymbolicLu<usize>,
    },
    Schur(Box<SchurSystem>, LowRankSchur),
    /// Matrix-free T (FFT products) and conjugate gradients ([`super::iterative`]).
    Iterative(Box<IterativeSchur>),
}

impl Backend {
    /// The backend of `ops`, for an iteration whose first penalised set has `lifted_at_start`
    /// points; on the Winkler spring route it starts from the factor `carry` holds when that was
    /// made for these operators (see [`Self::hand_over`]).
    pub(super) fn new(
        ops: &Operators,
        cg: CgSettings,
        lifted_at_start: usize,
        carry: Option<&Carry>,
    ) -> Result<Self> {
        match (ops.t.as_ref(), ops.constraints.kind) {
            (Compliance::Diagonal(t), ConstraintPoints::Nodal) => {
                let (layout, _) = ops.cache.get_or_try_init(|| SpringsLayout::of(ops, t))?;
                if layout.split {
                    // A nearly rigid plate: every step by the split solve, no plain factor.
                    let order = crate::mesh::equation_order(&ops.mesh, &ops.dofs, |_| true);
                    return Ok(Backend::Springs {
                        chol: SparseCholesky::analyse_ordered(&ops.k, Some(&order))?,
                        k: None,
                        layout,
                        t: t.clone(),
                        factored: None,
                        split: Some(Box::new(RigidSplit::new(ops)?)),
                    });
                }
                // The spring system is analysed once per assembly. Its bonded factor (step 1
                // from a cold start) does not depend on the loads: made once per assembly and
                // shared by every load combination, and updated by Woodbury where a start lifts
                // few points. A start that lifts more is factored afresh at its first step: the
                // bonded factor is then not made for it (though used if already made).
                let (analysis, _) = ops.cache.get_or_try_init(|| -> Result<SpringsAnalysis> {
                    let order = crate::mesh::equation_order(&ops.mesh, &ops.dofs, |_| true);
                    Ok(SpringsAnalysis(SparseCholesky::analyse_ordered(
                        &ops.k,
                        Some(&order),
                    )?))
                })?;
                let chol = analysis.0.clone();
                if let Some(carried) = carry.and_then(|c| c.take_for(&ops.k)) {
                    return Ok(Backend::Springs {
                        k: None,
                        layout,
                        t: t.clone(),
                        chol,
                        factored: Some(carried),
                        split: None,
                    });
                }
                let start = if lifted_at_start <= woodbury_limit(ops.k.rows(), chol.is_supernodal())
                {
                    let (start, _) = ops.cache.get_or_try_init(|| -> Result<SpringsStart> {
                        let springs: Vec<f64> =
                            layout.bonded_springs.iter().map(|&(_, s)| s).collect();
                        let mut bonded = (*ops.k).clone();
                        for &(eq, s) in &layout.bonded_springs {
                            bonded.data_mut()[layout.diag[eq]] += s;
                        }
                        let factor = Arc::new(chol.factor(&bonded, "bonded Winkler system")?);
                        Ok(SpringsStart { factor, springs })
                    })?;
                    Some(start)
                } else {
                    ops.cache.get::<SpringsStart>()
                };
                Ok(Backend::Springs {
                    k: None,
                    layout,
                    t: t.clone(),
                    chol,
                    factored: start
                        .map(|s| Factored::new(ops.k.clone(), s.factor.clone(), s.springs.clone())),
                    split: None,
                })
            }
            (Compliance::Diagonal(t), ConstraintPoints::Gauss) => {
                let n = ops.n_eq();
                let ns = ops.n_sigma();
                let mut tri = sprs::TriMat::new((n + ns, n + ns));
                for (j, col) in ops.k.outer_iterator().enumerate() {
                    for (i, &v) in col.iter() {
                        tri.add_triplet(i, j, v);
                    }
                }
                for (j, col) in ops.b.outer_iterator().enumerate() {
                    for (i, &v) in col.iter() {
                        tri.add_triplet(i, n + j, v);
                        tri.add_triplet(n + j, i, v);
                    }
                }
                // Every σσ entry a penalty can touch: couplings of nodes of one element.
                for e in ops.mesh.elements() {
                    for a in ops.mesh.element_nodes(e) {
                        for b in ops.mesh.element_nodes(e) {
                            tri.add_triplet(n + a, n + b, 0.0);
                        }
                    }
                }
                let m: sprs::CsMat<f64> = tri.to_csc();
                let mut sigma_pos = HashMap::new();
                let indptr = m.indptr();
                let ptr = indptr.raw_storage();
                for j in n..(n + ns) {
                    for p in ptr[j]..ptr[j + 1] {
                        let i = m.indices()[p];
                        if i >= n {
                            sigma_pos.insert((i - n, j - n), p);
                        }
                    }
                }
                let symbolic = SymbolicLu::try_new(faer_view(&m).symbolic()).map_err(|e| {
                    Error::numerical("penalty saddle system analysis", format!("{e:?}"))
                })?;
                Ok(Backend::Saddle {
                    m,
                    sigma_pos,
                    t: t.clone(),
                    symbolic,
                })
            }
            (Compliance::Toeplitz(_), _) => {
                Ok(Backend::Iterative(Box::new(IterativeSchur::new(ops, cg)?)))
            }
            (Compliance::Dense(_), _) => Ok(Backend::Schur(
                Box::new(SchurSystem::new(ops)?),
                LowRankSchur::new(),
            )),
        }
    }

    /// Keep the Winkler spring route's last factor in `carry` for the next solve on the same
    /// operators (the other routes hand nothing over).
    pub(super) fn hand_over(self, carry: &Carry) {
        if let Backend::Springs {
            factored,
            split: None,
            ..
        } = self
        {
            carry.put(factored);
        }
    }

    /// The tolerances of the iterative route's steps while the set moves, in turn: loose, then
    /// medium once a loose step sees no change; empty on the direct routes, whose every step is
    /// exact.
    pub(super) fn levels(&self) -> Vec<f64> {
        match self {
            Backend::Iterative(sys) => {
                let s = sys.settings();
                let loose = sys.loose_tolerance();
                vec![loose, MEDIUM_TOLERANCE.clamp(s.tolerance, loose)]
            }
            _ => Vec::new(),
        }
    }

    /// u = K⁻(f − Bσ) + Rα of a step whose [`Backend::solve`] left it out (the iterative
    /// route); the other backends form it with σ.
    pub(super) fn displacements(
        &self,
        ops: &Operators,
        sigma: &[f64],
        alpha: &[f64],
    ) -> Result<Vec<f64>> {
        match self {
            Backend::Iterative(sys) => Ok(sys.displacements(ops, sigma, alpha)),
            _ => Err(Error::numerical(
                "penalty",
                "only the iterative route leaves the displacements to be formed",
            )),
        }
    }

    /// Start the iterative route's first step from the pressures `sigma` (the other backends
    /// solve directly and need no start).
    pub(super) fn warm_start(&mut self, sigma: &[f64]) {
        if let Backend::Iterative(sys) = self {
            sys.warm_start(sigma);
        }
    }

    /// Solve with the penalty compliance of the `penalised` constraint points at ε̄ = `epsilon`;
    /// the iterative route to the relative tolerance `level` (None: its tight tolerance), the
    /// direct ones exactly.
    pub(super) fn solve(
        &mut self,
        ops: &Operators,
        rows: &[Vec<(usize, f64)>],
        penalised: &[bool],
        epsilon: f64,
        level: Option<f64>,
        monitor: &Monitor<'_>,
    ) -> Result<StepOut> {
        if let Backend::Iterative(sys) = self {
            let weights = penalty_weights(ops, penalised, epsilon);
            let (sigma, alpha, cg) = sys.solve_pressures(ops, rows, &weights, level, monitor)?;
            return Ok((None, sigma, alpha, Some(cg)));
        }
        if let Backend::Schur(sys, low_rank) = self {
            let weights = penalty_weights(ops, penalised, epsilon);
            let solver = low_rank.prepare(&sys.s, rows, &weights)?;
            let (sigma, alpha) = saddle_solve(&solver, &sys.h, &sys.c, &sys.rf)?;
            let u = sys.displacements(ops, &sigma, &alpha);
            return Ok((Some(u), sigma, alpha, None));
        }
        let extra = penalty_entries(ops, rows, penalised, epsilon);
        let extra = &extra[..];
        match self {
            Backend::Springs {
                k,
                layout,
                t,
                chol,
                factored,
                split,
            } => {
                let coupling = &layout.coupling;
                let mut comp = t.clone();
                for &(i, j, v) in extra {
                    if i == j {
                        comp[i] += v;
                    }
                }
                let springs: Vec<f64> = coupling
                    .iter()
                    .zip(&comp)
                    .map(|(&(_, b), &c)| b * b / c)
                    .collect();
                // The voids' initial gap: σ_j = (b_j u_j − g₀_j) / c_j, so the springs pull
                // with b_j g₀_j / c_j.
                let mut rhs = ops.f.clone();
                for ((&(eq, b), &c), &g0) in coupling.iter().zip(&comp).zip(&ops.gap0) {
                    rhs[eq] += b * g0 / c;
                }
                let on_eqs: Vec<(usize, f64)> = coupling
                    .iter()
                    .zip(&springs)
                    .map(|(&(eq, _), &s)| (eq, s))
                    .collect();
                let u = if needs_split(ops, &on_eqs) {
                    if split.is_none() {
                        *split = Some(Box::new(RigidSplit::new(ops)?));
                    }
                    match split {
                        Some(sp) => sp.solve(ops, &on_eqs, &rhs)?,
                        None => return Err(Error::numerical("penalty", "no split solver")),
                    }
                } else {
                    let limit = woodbury_limit(ops.k.rows(), chol.is_supernodal());
                    match factored {
                        Some(f) if f.changed(&springs).len() <= limit => {
                            let updates: Vec<(usize, f64)> = f
                                .changed(&springs)
                                .into_iter()
                                .map(|j| (coupling[j].0, springs[j] - f.springs[j]))
                                .collect();
                            f.woodbury_solve(&rhs, &updates)?
                        }
                        _ => {
                            let k = k.get_or_insert_with(|| (*ops.k).clone());
                            k.data_mut().copy_from_slice(ops.k.data());
                            for (j, &(eq, _)) in coupling.iter().enumerate() {
                                k.data_mut()[layout.diag[eq]] += springs[j];
                            }
                            let llt = chol.factor(k, "penalised Winkler system")?;
                            // Solved as an update of nothing: a supernodal factor keeps the
                            // forward half of f for the next steps and solves.
                            let mut fresh =
                                Factored::new(ops.k.clone(), Arc::new(llt), springs.clone());
                            let u = fresh.woodbury_solve(&rhs, &[])?;
                            *factored = Some(fresh);
                            u
                        }
                    }
                };
                let sigma = coupling
                    .iter()
                    .zip(&comp)
                    .zip(&ops.gap0)
                    .map(|((&(eq, b), &c), &g0)| (b * u[eq] - g0) / c)
                    .collect();
                Ok((Some(u), sigma, Vec::new(), None))
            }
            Backend::Saddle {
                m,
                sigma_pos,
                t,
                symbolic,
            } => {
                let n = ops.n_eq();
                for (j, &tj) in t.iter().enumerate() {
                    if let Some(&p) = sigma_pos.get(&(j, j)) {
                        m.data_mut()[p] = -tj;
                    }
                }
                for (&(i, j), &p) in sigma_pos.iter() {
                    if i != j {
                        m.data_mut()[p] = 0.0;
                    }
                }
                for &(i, j, v) in extra {
                    let p = sigma_pos.get(&(i, j)).ok_or_else(|| {
                        Error::numerical("penalty", "penalty entry outside the element pattern")
                    })?;
                    m.data_mut()[*p] -= v;
                }
                let lu =
                    Lu::try_new_with_symbolic(symbolic.clone(), faer_view(m)).map_err(|e| {
                        Error::numerical("penalised saddle system (LU)", format!("{e:?}"))
                    })?;
                let total = m.rows();
                let mut rhs = Mat::<f64>::zeros(total, 1);
                for (i, &fi) in ops.f.iter().enumerate() {
                    rhs[(i, 0)] = fi;
                }
                // Bᵀu − (T + Σ/ε̄)σ = g₀.
                for (j, &g0) in ops.gap0.iter().enumerate() {
                    rhs[(n + j, 0)] = g0;
                }
                lu.solve_in_place(rhs.as_mut());
                let u = (0..n).map(|i| rhs[(i, 0)]).collect();
                let sigma = (n..total).map(|i| rhs[(i, 0)]).collect();
                Ok((Some(u), sigma, Vec::new(), None))
            }
            Backend::Schur(..) | Backend::Iterative(..) => Err(Error::numerical(
                "penalty",
                "the Schur and iterative backends are solved above",
            )),
        }
    }
}

/// u, σ, α of a penalty step and, on the iterative route, its CG account. u is None on the
/// iterative route, where it costs a plate solve that only the step the iteration ends on
/// needs: [`Backend::displacements`] forms it from σ and α (it is affine in them).
type StepOut = (Option<Vec<f64>>, Vec<f64>, Vec<f64>, Option<CgReport>);

/// d_k = c w_k / ε̄ on the penalised constraint points, 0 elsewhere.
pub(super) fn penalty_weights(ops: &Operators, penalised: &[bool], epsilon: f64) -> Vec<f64> {
    let scale = ops.foundation_constant / epsilon;
    penalised
        .iter()
        .zip(&ops.constraints.weights)
        .map(|(&p, &w)| if p { w * scale } else { 0.0 })
        .collect()
}

/// The relative CG tolerance of the penalty steps between the loose ones and the confirming
/// tight ones (iterative route).
pub const MEDIUM_TOLERANCE: f64 = 1e-7;

/// Rows of G as (σ index, value) lists, made once per assembly ([`constraint_rows`]).
pub(super) struct ConstraintRows(pub Vec<Vec<(usize, f64)>>);

/// [`constraint_rows`] of `ops`, kept in its cache: every solve on one assembly reads the same.
pub(super) fn cached_constraint_rows(ops: &Operators) -> Arc<ConstraintRows> {
    match ops
        .cache
        .get_or_try_init::<_, std::convert::Infallible>(|| Ok(ConstraintRows(constraint_rows(ops))))
    {
        Ok((rows, _)) => rows,
        Err(never) => match never {},
    }
}

/// Rows of G as (σ index, value) lists.
pub(super) fn constraint_rows(ops: &Operators) -> Vec<Vec<(usize, f64)>> {
    let g = &ops.constraints.g;
    let mut rows: Vec<Vec<(usize, f64)>> = vec![Vec::new(); g.rows()];
    for (j, col) in g.outer_iterator().enumerate() {
        for (i, &v) in col.iter() {
            rows[i].push((j, v));
        }
    }
    rows
}

/// Penalty compliance Σ(P)/ε̄ = (c/ε̄) Gᵀ diag(w_k [k ∈ P]) G of a penalised set as σ-index
/// triplets (duplicates are summed by the consumers).
fn penalty_entries(
    ops: &Operators,
    rows: &[Vec<(usize, f64)>],
    penalised: &[bool],
    epsilon: f64,
) -> Vec<(usize, usize, f64)> {
    let scale = ops.foundation_constant / epsilon;
    let mut out = Vec::new();
    for (k, _) in penalised.iter().enumerate().filter(|(_, &p)| p) {
        let w = ops.constraints.weights[k] * scale;
        for &(a, va) in &rows[k] {
            for &(b, vb) in &rows[k] {
                out.push((a, b, w * va * vb));
            }
        }
    }
    out
}
