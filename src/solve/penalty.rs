//! The paper's penalty iteration (eqs. 4.2–4.6).
//!
//! Step 1 is the bonded problem. At step i the constraint points where the previous pressure
//! was negative get an extra compliance Σ(σ^(i−1))/ε̄ with Σ = c Gᵀ diag(w_k [Gσ]_k < 0) G
//! (c the foundation constant μΓ, w_k the points' area weights: eq. 4.3–4.4), and the bilateral
//! problem with compliance T + Σ/ε̄ is solved again. Mechanically: soft springs, ε̄ times the
//! foundation's stiffness, replace the foundation where it would pull. The iteration stops when
//! the penalised set repeats; it is reported as cycling when it returns to an older set and as
//! not converged when the cap is reached. The error against the exact unilateral solution is
//! O(ε̄).
//!
//! The linear system of each step is solved on the shared operators without re-assembly:
//! Winkler with nodal constraints keeps the sparse SPD form K + B (T + Σ/ε̄)⁻¹ Bᵀ (only
//! diagonal values change; the symbolic Cholesky is reused); Winkler with Gauss constraints
//! solves the sparse saddle system [K B; Bᵀ −(T + Σ/ε̄)] by LU (pattern fixed, values change);
//! the half-space adds Σ/ε̄ to the Schur complement formed once, factors it densely once and
//! solves later steps by low-rank updates of that factor ([`super::low_rank`]).

use std::collections::HashMap;
use std::sync::Arc;
use std::time::Instant;

use faer::linalg::solvers::Solve;
use faer::sparse::linalg::solvers::{Lu, SymbolicLu};
use faer::Mat;

use super::bonded::finite;
use super::bonded::{diagonal_positions, lumped_coupling, saddle_solve, SchurSystem};
use super::linalg::{faer_view, sparse_solve, SparseCholesky, SparseFactor};
use super::low_rank::LowRankSchur;
use super::{discrete_gap, Iteration, PenaltyStage, Solution, SolveInfo, Status, Timings};
use crate::error::{Error, Result};
use crate::foundation::Compliance;
use crate::method::{Method, PenaltySettings};
use crate::model::ConstraintPoints;
use crate::operators::Operators;

/// Largest tension left at lifted points that a converged penalty solution may carry, relative
/// to the peak pressure and (as a force) to the compressive resultant. The penalty error is O(ε̄): on the paper's cases at ε̄ = 1e-5 the
/// ratio is ~1e-6; a ratio above 1e-4 means the penalty springs are not soft enough compared
/// with the plate (small Γ on the half-space), and the contact region is wrong.
pub const TENSION_TOLERANCE: f64 = 1e-4;

/// Largest share of the load that fictitious tension at lifted points may carry in a converged
/// penalty solution: 0.1 %. On the paper's cases at ε̄ = 1e-5 the share is ~1e-4 (about 10 ε̄);
/// a plate balanced on one corner node of a Winkler bed needs 3 %.
pub const TENSION_FORCE_TOLERANCE: f64 = 1e-3;

/// The analysed Winkler spring system and its bonded factor (no penalty springs): where every
/// penalty iteration on an assembly starts.
struct SpringsStart {
    chol: SparseCholesky,
    factor: Arc<SparseFactor>,
    springs: Vec<f64>,
}

/// Linear solver of one penalised bilateral problem.
enum Backend {
    Springs {
        k: sprs::CsMat<f64>,
        diag: Vec<usize>,
        base: Vec<f64>,
        coupling: Vec<(usize, f64)>,
        t: Vec<f64>,
        chol: SparseCholesky,
        /// The last numeric factor and the spring stiffness per pressure node it was made with.
        factored: Option<(Arc<SparseFactor>, Vec<f64>)>,
    },
    Saddle {
        m: sprs::CsMat<f64>,
        /// Data positions of the σσ block entries, keyed by (row, col) in σ numbering.
        sigma_pos: HashMap<(usize, usize), usize>,
        t: Vec<f64>,
        symbolic: SymbolicLu<usize>,
    },
    Schur(Box<SchurSystem>, LowRankSchur),
}

impl Backend {
    fn new(ops: &Operators) -> Result<Self> {
        match (ops.t.as_ref(), ops.constraints.kind) {
            (Compliance::Diagonal(t), ConstraintPoints::Nodal) => {
                let k = (*ops.k).clone();
                let diag = diagonal_positions(&k)?;
                let base = k.data().to_vec();
                let coupling = lumped_coupling(ops)?;
                // The bonded system of step 1 does not depend on the loads: analysed and
                // factored once per assembly, shared by every load combination.
                let (start, _) = ops.cache.get_or_try_init(|| -> Result<SpringsStart> {
                    let order = crate::mesh::equation_order(&ops.mesh, &ops.dofs, |_| true);
                    let chol = SparseCholesky::analyse_ordered(&k, Some(&order))?;
                    let springs: Vec<f64> = coupling
                        .iter()
                        .zip(t)
                        .map(|(&(_, b), &c)| b * b / c)
                        .collect();
                    let mut bonded = k.clone();
                    for (j, &(eq, _)) in coupling.iter().enumerate() {
                        bonded.data_mut()[diag[eq]] += springs[j];
                    }
                    let factor = Arc::new(chol.factor(&bonded, "bonded Winkler system")?);
                    Ok(SpringsStart {
                        chol,
                        factor,
                        springs,
                    })
                })?;
                Ok(Backend::Springs {
                    k,
                    diag,
                    base,
                    coupling,
                    t: t.clone(),
                    chol: start.chol.clone(),
                    factored: Some((start.factor.clone(), start.springs.clone())),
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
                for e in 0..ops.mesh.n_elements() {
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
            (Compliance::Dense(_), _) => Ok(Backend::Schur(
                Box::new(SchurSystem::new(ops)?),
                LowRankSchur::new(),
            )),
        }
    }

    /// Solve with the penalty compliance of the `penalised` constraint points at ε̄ = `epsilon`.
    fn solve(
        &mut self,
        ops: &Operators,
        rows: &[Vec<(usize, f64)>],
        penalised: &[bool],
        epsilon: f64,
    ) -> Result<(Vec<f64>, Vec<f64>, Vec<f64>)> {
        if let Backend::Schur(sys, low_rank) = self {
            let scale = ops.foundation_constant / epsilon;
            let weights: Vec<f64> = penalised
                .iter()
                .zip(&ops.constraints.weights)
                .map(|(&p, &w)| if p { w * scale } else { 0.0 })
                .collect();
            let solver = low_rank.prepare(&sys.s, rows, &weights)?;
            let (sigma, alpha) = saddle_solve(&solver, &sys.h, &sys.c, &sys.rf)?;
            let u = sys.displacements(ops, &sigma, &alpha);
            return Ok((u, sigma, alpha));
        }
        let extra = penalty_entries(ops, rows, penalised, epsilon);
        let extra = &extra[..];
        match self {
            Backend::Springs {
                k,
                diag,
                base,
                coupling,
                t,
                chol,
                factored,
            } => {
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
                let u = match factored {
                    Some((factor, old)) if changed(old, &springs).len() <= WOODBURY_MAX_RANK => {
                        let idx = changed(old, &springs);
                        woodbury_solve(
                            factor,
                            &rhs,
                            &idx.iter()
                                .map(|&j| (coupling[j].0, springs[j] - old[j]))
                                .collect::<Vec<_>>(),
                        )?
                    }
                    _ => {
                        k.data_mut().copy_from_slice(base);
                        for (j, &(eq, _)) in coupling.iter().enumerate() {
                            k.data_mut()[diag[eq]] += springs[j];
                        }
                        let llt = chol.factor(k, "penalised Winkler system")?;
                        let mut u = rhs;
                        sparse_solve(&llt, &mut u);
                        *factored = Some((Arc::new(llt), springs.clone()));
                        u
                    }
                };
                let sigma = coupling
                    .iter()
                    .zip(&comp)
                    .zip(&ops.gap0)
                    .map(|((&(eq, b), &c), &g0)| (b * u[eq] - g0) / c)
                    .collect();
                Ok((u, sigma, Vec::new()))
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
                Ok((u, sigma, Vec::new()))
            }
            Backend::Schur(..) => Err(Error::numerical(
                "penalty",
                "the Schur backend is solved above",
            )),
        }
    }
}

/// Up to this many changed springs since the last factorisation, a step is solved with the old
/// factor and a Woodbury correction (k + 1 solves with the factor and a dense k × k system)
/// instead of a new numeric factorisation.
pub const WOODBURY_MAX_RANK: usize = 64;

/// Indices whose spring stiffness changed.
fn changed(old: &[f64], new: &[f64]) -> Vec<usize> {
    old.iter()
        .zip(new)
        .enumerate()
        .filter(|(_, (a, b))| a != b)
        .map(|(j, _)| j)
        .collect()
}

/// Solve (A + Σ_j δ_j e_{i_j} e_{i_j}ᵀ) u = f from a factor of A (Sherman–Morrison–Woodbury):
/// u = y − Z (diag(1/δ) + Uᵀ Z)⁻¹ Uᵀ y with y = A⁻¹ f, Z = A⁻¹ U.
fn woodbury_solve(factor: &SparseFactor, f: &[f64], updates: &[(usize, f64)]) -> Result<Vec<f64>> {
    let n = f.len();
    let k = updates.len();
    let mut y = f.to_vec();
    sparse_solve(factor, &mut y);
    if k == 0 {
        return Ok(y);
    }
    let mut z = Mat::<f64>::zeros(n, k);
    for (c, &(i, _)) in updates.iter().enumerate() {
        z[(i, c)] = 1.0;
    }
    factor.solve_in_place(z.as_mut());
    let m = Mat::<f64>::from_fn(k, k, |a, b| {
        z[(updates[a].0, b)] + if a == b { 1.0 / updates[a].1 } else { 0.0 }
    });
    let mut rhs = Mat::<f64>::from_fn(k, 1, |a, _| y[updates[a].0]);
    let lu = m.partial_piv_lu();
    lu.solve_in_place(rhs.as_mut());
    for (i, yi) in y.iter_mut().enumerate() {
        let corr: f64 = (0..k).map(|c| z[(i, c)] * rhs[(c, 0)]).sum();
        *yi -= corr;
    }
    if y.iter().any(|v| !v.is_finite()) {
        return Err(Error::numerical(
            "penalty (low-rank update)",
            "non-finite values",
        ));
    }
    Ok(y)
}

/// Rows of G as (σ index, value) lists.
fn constraint_rows(ops: &Operators) -> Vec<Vec<(usize, f64)>> {
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

/// Smallest ε̄ the automatic choice goes down to: below it the penalised system loses the
/// digits the tension criteria need (the penalty springs are 1e14 times softer than the soil).
pub const MIN_AUTO_EPSILON: f64 = 1e-14;

/// Most continuation stages of the automatic choice of ε̄.
pub const MAX_AUTO_STAGES: usize = 8;

/// What one ε̄ of the iteration ended with.
struct StageEnd {
    status: Status,
    u: Vec<f64>,
    sigma: Vec<f64>,
    alpha: Vec<f64>,
    penalised: Vec<bool>,
}

/// Iterate at one ε̄ from the penalised set `start` until the set repeats, cycles or `cap`
/// steps are taken; steps are appended to `history`.
#[allow(clippy::too_many_arguments)]
fn stage(
    ops: &Operators,
    backend: &mut Backend,
    rows: &[Vec<(usize, f64)>],
    start: Vec<bool>,
    epsilon: f64,
    cap: usize,
    history: &mut Vec<Iteration>,
    t_solves: &mut f64,
) -> Result<StageEnd> {
    let n_c = start.len();
    let mut penalised = start;
    let mut seen: Vec<Vec<bool>> = vec![penalised.clone()];
    let mut status = Status::IterationLimit { limit: cap };
    let mut last = None;
    for _ in 0..cap {
        let ts = Instant::now();
        let (u, sigma, alpha) = backend.solve(ops, rows, &penalised, epsilon)?;
        *t_solves += ts.elapsed().as_secs_f64();
        finite(&u, "penalty iteration")?;
        finite(&sigma, "penalty iteration")?;
        let gs = ops.g_times(&sigma);
        let next: Vec<bool> = gs.iter().map(|&v| v < 0.0).collect();
        let entered = next
            .iter()
            .zip(&penalised)
            .filter(|(n, p)| **n && !**p)
            .count();
        let left = next
            .iter()
            .zip(&penalised)
            .filter(|(n, p)| !**n && **p)
            .count();
        let count = next.iter().filter(|&&b| b).count();
        history.push(Iteration {
            step: history.len() + 1,
            epsilon,
            penalised: count,
            entered,
            left,
            min_pressure: gs.iter().cloned().fold(f64::INFINITY, f64::min),
        });
        last = Some((u, sigma, alpha));
        if count == n_c {
            return Err(Error::Infeasible(
                "the penalty iteration lifted every constraint point: no part of the plate stays in contact (are the loads pulling the plate up?)".into(),
            ));
        }
        if next == penalised {
            status = Status::Converged;
            break;
        }
        if let Some(pos) = seen.iter().position(|s| *s == next) {
            status = Status::Cycling {
                period: seen.len() - pos,
            };
            penalised = next;
            break;
        }
        seen.push(next.clone());
        penalised = next;
    }
    let (u, sigma, alpha) =
        last.ok_or_else(|| Error::numerical("penalty iteration", "no iteration was run"))?;
    if status == Status::Converged {
        status = tension_check(ops, &sigma, epsilon);
    }
    Ok(StageEnd {
        status,
        u,
        sigma,
        alpha,
        penalised,
    })
}

/// A settled penalised set is a solution only if the tension left at lifted points is within
/// [`TENSION_TOLERANCE`] of the peak pressure and [`TENSION_FORCE_TOLERANCE`] of the load: O(ε̄)
/// when the penalty is adequate; finite when the springs hold the plate down (an infeasible
/// discrete problem) or are too stiff compared with the plate.
fn tension_check(ops: &Operators, sigma: &[f64], epsilon: f64) -> Status {
    let gs = ops.g_times(sigma);
    let w = &ops.constraints.weights;
    let pull: f64 = gs.iter().zip(w).map(|(g, w)| (-g).max(0.0) * w).sum();
    let push: f64 = gs
        .iter()
        .zip(w)
        .map(|(g, w)| g.max(0.0) * w)
        .sum::<f64>()
        .max(f64::MIN_POSITIVE);
    let peak = gs
        .iter()
        .cloned()
        .fold(0.0_f64, f64::max)
        .max(f64::MIN_POSITIVE);
    let tension = -gs.iter().cloned().fold(0.0_f64, f64::min);
    let ratio = tension / peak;
    let force_ratio = pull / push;
    if ratio > TENSION_TOLERANCE || force_ratio > TENSION_FORCE_TOLERANCE {
        // The tension falls like ε̄: aim a hundred times below the tolerance.
        let shrink = (1e-2 * TENSION_TOLERANCE / ratio)
            .min(1e-2 * TENSION_FORCE_TOLERANCE / force_ratio)
            .min(0.1);
        Status::PenaltyTooWeak {
            tension_ratio: ratio,
            tension_share: force_ratio,
            suggested_penalty: epsilon * shrink,
        }
    } else {
        Status::Converged
    }
}

/// Run the penalty iteration on the shared operators. With a fixed ε̄ this is the paper's
/// iteration. With `auto`, it starts at `epsilon` and, while a stage settles with lifted points
/// that keep more tension than the criteria allow, continues at the smaller ε̄ they suggest
/// from the last penalised set, on the same backend: the symbolic factorisation (and the last
/// numeric factor, for Woodbury updates) is reused across stages.
pub fn solve(ops: &Operators, settings: &PenaltySettings) -> Result<Solution> {
    let t0 = Instant::now();
    let mut backend = Backend::new(ops)?;
    let t_setup = t0.elapsed().as_secs_f64();
    let rows = constraint_rows(ops);
    let n_c = ops.constraints.g.rows();
    let mut history = Vec::new();
    let mut stages = Vec::new();
    let mut t_solves = 0.0;
    let mut epsilon = settings.epsilon;
    let mut start = vec![false; n_c];
    let end = loop {
        let from = history.len();
        let end = stage(
            ops,
            &mut backend,
            &rows,
            start,
            epsilon,
            settings.max_iterations,
            &mut history,
            &mut t_solves,
        )?;
        stages.push(PenaltyStage {
            epsilon,
            steps: history.len() - from,
            outcome: end.status.kind(),
        });
        // Only a settled set whose lifted points keep tension asks for a smaller ε̄; a cycle
        // or the step cap is reported as it is.
        let next = match end.status {
            Status::PenaltyTooWeak {
                suggested_penalty, ..
            } => Some(suggested_penalty),
            _ => None,
        };
        match next {
            Some(e) if settings.auto && e >= MIN_AUTO_EPSILON && stages.len() < MAX_AUTO_STAGES => {
                epsilon = e;
                start = end.penalised.clone();
            }
            _ => break end,
        }
    };
    let gap = discrete_gap(ops, &end.u, &end.sigma);
    Ok(Solution {
        method: Method::Penalty(PenaltySettings {
            epsilon,
            ..*settings
        }),
        u: end.u,
        sigma: end.sigma,
        gap,
        rigid: end.alpha,
        status: end.status,
        iterations: history.len(),
        history,
        info: SolveInfo {
            timings: Timings {
                setup: Some(t_setup),
                solves: Some(t_solves),
                total: t0.elapsed().as_secs_f64(),
                ..Timings::default()
            },
            qp: None,
            penalty_stages: stages,
            notes: Vec::new(),
        },
    })
}
