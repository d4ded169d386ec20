//! Solution methods and what they return.
//!
//! Every method takes the same [`Operators`] and returns a [`Solution`]. A method that ran but
//! did not reach an answer returns a `Solution` whose [`Status`] says so; only failures that
//! leave nothing to report (a factorisation breaking down, a problem too large) are errors.

pub mod active_set;
pub mod bonded;
pub mod iterative;
pub mod linalg;
pub mod low_rank;
pub mod penalty;
mod penalty_step;
pub mod qp;
pub mod sparse_qp;
pub mod springs;

use crate::error::{Error, Result};
use crate::foundation::Compliance;
use crate::method::{Method, QpForm, QpSettings, QpSolver};
use crate::model::ConstraintPoints;
use crate::operators::Operators;
use sparse_qp::SparseForm;

/// Outcome of a solve that ran.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum Status {
    /// The discrete conditions hold to the method's tolerance.
    Converged,
    /// The penalised set repeated an earlier set without settling (period in iterations).
    Cycling {
        /// Length of the cycle.
        period: usize,
    },
    /// The iteration cap was reached while the set was still changing.
    IterationLimit {
        /// The cap.
        limit: usize,
    },
    /// The penalised set settled, but the lifted points still carry more tension than the
    /// penalty can excuse: ε̄ is too large for this plate/foundation stiffness ratio.
    PenaltyTooWeak {
        /// |most negative pressure| / largest pressure at the constraint points.
        tension_ratio: f64,
        /// Tension force at lifted points / compressive resultant.
        tension_share: f64,
        /// A smaller ε̄ to try.
        suggested_penalty: f64,
    },
    /// The external solver stopped without a solution.
    SolverFailure {
        /// The solver's own status.
        detail: String,
    },
}

impl Status {
    /// True for [`Status::Converged`].
    pub fn converged(&self) -> bool {
        matches!(self, Status::Converged)
    }

    /// Short machine-readable kind, as in the studies' CSV files.
    pub fn kind(&self) -> &'static str {
        match self {
            Status::Converged => "converged",
            Status::Cycling { .. } => "cycling",
            Status::IterationLimit { .. } => "iteration-limit",
            Status::PenaltyTooWeak { .. } => "penalty-too-weak",
            Status::SolverFailure { .. } => "solver-failure",
        }
    }

    /// One-line description.
    pub fn describe(&self) -> String {
        match self {
            Status::Converged => "converged".into(),
            Status::Cycling { period } => format!(
                "not converged: the penalised set cycles with period {period} (contact set oscillates)"
            ),
            Status::IterationLimit { limit } => {
                format!("not converged: the penalised set was still changing after {limit} iterations")
            }
            Status::PenaltyTooWeak {
                tension_ratio,
                tension_share,
                suggested_penalty,
            } => format!(
                "not converged: lifted points still carry tension (peak {tension_ratio:.1e} of the peak pressure, {:.2} % of the load), so ε̄ is too large for this stiffness ratio; ε̄ = {suggested_penalty:.0e} or the QP should converge",
                100.0 * tension_share
            ),
            Status::SolverFailure { detail } => format!("not converged: {detail}"),
        }
    }
}

/// One step of an iterative method.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Iteration {
    /// Step number, from 1.
    pub step: usize,
    /// ε̄ of the step.
    pub epsilon: f64,
    /// Constraint points in the penalised (lifted) set after this step.
    pub penalised: usize,
    /// Points that entered the set in this step.
    pub entered: usize,
    /// Points that left the set in this step.
    pub left: usize,
    /// Most negative pressure at a constraint point.
    pub min_pressure: f64,
    /// The conjugate-gradient solve of the step (iterative route only).
    pub cg: Option<iterative::CgReport>,
}

/// Wall-clock times of a method's phases, seconds; a phase the method does not have is None.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Timings {
    /// Symbolic analysis of the sparse plate matrix (bonded Winkler).
    pub analyse: Option<f64>,
    /// Numeric factorisation of the bonded system.
    pub factor: Option<f64>,
    /// Factoring the plate with its rigid modes fixed (Schur routes).
    pub plate_factor: Option<f64>,
    /// Forming the Schur complement S = T + BᵀK⁻B.
    pub schur: Option<f64>,
    /// Setting up the penalty iteration's linear solver.
    pub setup: Option<f64>,
    /// The penalty iteration's linear solves.
    pub solves: Option<f64>,
    /// Building clarabel's sparse matrices (sparse QP forms).
    pub qp_setup: Option<f64>,
    /// clarabel's set-up: its KKT pattern and ordering (sparse QP forms).
    pub clarabel_setup: Option<f64>,
    /// clarabel's interior-point iterations (with its set-up, for the dense form).
    pub clarabel: Option<f64>,
    /// The whole method.
    pub total: f64,
}

impl Timings {
    /// (name, seconds) of the phases present, as in summary.json's `method_time_s`.
    pub fn named(&self) -> Vec<(&'static str, f64)> {
        let phases = [
            ("analyse", self.analyse),
            ("factor", self.factor),
            ("plate factor", self.plate_factor),
            ("schur", self.schur),
            ("setup", self.setup),
            ("solves", self.solves),
            ("qp setup", self.qp_setup),
            ("clarabel setup", self.clarabel_setup),
            ("clarabel", self.clarabel),
            ("total", Some(self.total)),
        ];
        phases
            .into_iter()
            .filter_map(|(n, v)| v.map(|v| (n, v)))
            .collect()
    }
}

/// clarabel's account of a QP solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QpDiagnostics {
    /// Primal residual.
    pub primal_residual: f64,
    /// Dual residual.
    pub dual_residual: f64,
    /// Objective value.
    pub objective: f64,
    /// |primal − dual objective|.
    pub duality_gap: f64,
    /// The sparse forms' consistency check: (name, relative mismatch) of two ways to read the
    /// answer (`gap_mismatch` lifted, `sigma_mismatch` primal).
    pub form_check: Option<(&'static str, f64)>,
}

impl QpDiagnostics {
    /// (name, value) pairs, as in summary.json's `solver_info`.
    pub fn named(&self) -> Vec<(&'static str, f64)> {
        let mut v = vec![
            ("primal_residual", self.primal_residual),
            ("dual_residual", self.dual_residual),
            ("objective", self.objective),
            ("duality_gap", self.duality_gap),
        ];
        v.extend(self.form_check);
        v
    }
}

/// One ε̄ of the penalty iteration (one stage of the automatic choice).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct PenaltyStage {
    /// ε̄ of the stage.
    pub epsilon: f64,
    /// Linear solves at this ε̄.
    pub steps: usize,
    /// How the stage ended ([`Status::kind`]).
    pub outcome: &'static str,
}

/// How a solve went: timings and the external solver's diagnostics.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SolveInfo {
    /// Phase timings.
    pub timings: Timings,
    /// clarabel's diagnostics (QP by clarabel only).
    pub qp: Option<QpDiagnostics>,
    /// The matrix-free QP's diagnostics (QP by the active-set solver only).
    pub active_set: Option<active_set::ActiveSetDiagnostics>,
    /// The stages of the penalty iteration, one per ε̄ (penalty only).
    pub penalty_stages: Vec<PenaltyStage>,
    /// What the method decided on its own (a fall-back, say), for the report's notes.
    pub notes: Vec<String>,
    /// Conjugate-gradient iterations over all linear solves (iterative route; each step's count
    /// and residual are in the history).
    pub cg_iterations: Option<usize>,
}

/// What every method returns.
#[derive(Debug, Clone)]
pub struct Solution {
    /// The method (with its settings) that produced this solution.
    pub method: Method,
    /// Plate dofs (unit system).
    pub u: Vec<f64>,
    /// Nodal pressures (unit system; the paper's σ is μ times these).
    pub sigma: Vec<f64>,
    /// Discrete gap T σ − Bᵀ u (weighted by the pressure shape functions).
    pub gap: Vec<f64>,
    /// Rigid-body amplitudes α (QP and half-space bonded; empty otherwise).
    pub rigid: Vec<f64>,
    /// Outcome.
    pub status: Status,
    /// Linear solves or solver iterations.
    pub iterations: usize,
    /// Per-step history of iterative methods.
    pub history: Vec<Iteration>,
    /// Timings and diagnostics.
    pub info: SolveInfo,
}

/// Solve the assembled operators with a method: bonded contact directly, unbonded contact (after
/// a feasibility check) by the penalty iteration or the QP. Every solution's reaction is
/// checked against the load.
pub fn solve(ops: &Operators, method: &Method) -> Result<Solution> {
    solve_from(ops, method, None)
}

/// Whether `method` on `ops` runs the matrix-free active-set QP, the one method that takes a
/// start ([`solve_from`]).
pub fn takes_start(ops: &Operators, method: &Method) -> bool {
    match method {
        Method::Qp(s) => {
            let toeplitz = matches!(ops.t.as_ref(), Compliance::Toeplitz(_));
            s.resolve(ops.foundation, ops.constraints.kind, toeplitz) == QpSolver::ActiveSet
                && ops.constraints.kind == ConstraintPoints::Nodal
        }
        _ => false,
    }
}

/// [`solve`], with the nodal pressures `start` as the matrix-free active-set QP's first
/// iterate where it runs ([`takes_start`]); the other methods ignore it. The answer does not
/// depend on the start (the QP's solution is unique), only the number of face solves does.
pub fn solve_from(ops: &Operators, method: &Method, start: Option<&[f64]>) -> Result<Solution> {
    method.validate()?;
    let sol = match method {
        Method::Bonded => {
            if ops.gap0.iter().any(|&g| g != 0.0) {
                return Err(Error::Unsupported(
                    "voids need unbonded contact: bonded contact would glue the plate to the lowered soil surface".into(),
                ));
            }
            bonded::solve(ops)?
        }
        Method::Penalty(settings) => {
            check_feasible(ops)?;
            penalty::solve(ops, settings)?
        }
        Method::Qp(settings) => {
            check_feasible(ops)?;
            solve_qp(ops, settings, start)?
        }
    };
    check_equilibrium(ops, &sol)?;
    Ok(sol)
}

/// The QP by the solver its settings resolve to on these operators. Under `qp_solver = auto`
/// a clarabel solve that stops without a solution is solved again by the active-set method
/// where it can be (nodal constraints), and the notes say so.
fn solve_qp(ops: &Operators, settings: &QpSettings, start: Option<&[f64]>) -> Result<Solution> {
    let toeplitz = matches!(ops.t.as_ref(), Compliance::Toeplitz(_));
    let solver = settings.resolve(ops.foundation, ops.constraints.kind, toeplitz);
    if solver == QpSolver::ActiveSet {
        return active_set::solve(ops, settings, start);
    }
    let sol = match settings.form.resolve(&ops.t) {
        QpForm::Lifted => sparse_qp::solve_sparse(ops, settings, SparseForm::Lifted)?,
        QpForm::Primal => {
            let sol = sparse_qp::solve_sparse(ops, settings, SparseForm::Primal)?;
            if settings.form == QpForm::Auto
                && !sol.status.converged()
                && ops.n_sigma() <= DENSE_FALLBACK_NODES
            {
                dense_fallback(ops, settings, &sol)?
            } else {
                sol
            }
        }
        _ => qp::solve(ops, settings)?,
    };
    let retry = settings.solver == QpSolver::Auto
        && !sol.status.converged()
        && ops.constraints.kind == ConstraintPoints::Nodal;
    if !retry {
        return Ok(sol);
    }
    let mut again = active_set::solve(ops, settings, start)?;
    again.info.notes.push(format!(
        "clarabel stopped ({}); solved again by the matrix-free active-set method",
        sol.status.describe()
    ));
    again.iterations += sol.iterations;
    Ok(again)
}

/// Largest model (pressure nodes) on which the automatic QP form retries a failed primal solve
/// with the dense Schur form: about 1.3 GB of dense matrices at 4096 nodes.
pub const DENSE_FALLBACK_NODES: usize = 4096;

/// The primal form has a set of minimisers, not one, when the contact set cannot hold the
/// plate's rigid modes on its own (a plate balanced on one node can turn about it): clarabel
/// may then stop without progress although the pressures are unique. The σ-form (dense Schur)
/// has the unique σ as its minimiser; solve it, and say so.
fn dense_fallback(
    ops: &Operators,
    settings: &crate::method::QpSettings,
    primal: &Solution,
) -> Result<Solution> {
    let mut sol = qp::solve(ops, settings)?;
    sol.info.notes.push(format!(
        "the sparse (primal) QP stopped ({}); solved again in the dense Schur form",
        primal.status.describe()
    ));
    sol.iterations += primal.iterations;
    Ok(sol)
}

/// Largest relative equilibrium error accepted: |∫σ − ∫q| / |∫q|. Well-posed problems reach
/// 1e-12; thin plates on soft soil lose a few digits to K's row-sum round-off (≈ 1e-9 for
/// H = ℓ/100); beyond 1e-6 the linear algebra has broken down.
pub const EQUILIBRIUM_TOLERANCE: f64 = 1e-6;

/// Refuse a solution whose reaction does not balance the load.
pub fn check_equilibrium(ops: &Operators, sol: &Solution) -> Result<()> {
    let areas = crate::foundation::nodal_areas(&ops.mesh);
    let reaction: f64 = sol.sigma.iter().zip(&areas).map(|(s, a)| s * a).sum();
    let load = ops.total_load();
    // Relative to the model's share of 4P: the net load, or the stated reference when the
    // loads add up to zero (a bonded plate under curling alone), where |load| is round-off.
    let rel = (reaction - load).abs() / load.abs().max(4.0 / ops.mesh.copies() as f64);
    if rel.is_nan() || rel > EQUILIBRIUM_TOLERANCE {
        return Err(Error::numerical(
            format!("{} solve", sol.method.name()),
            format!(
                "the reaction misses the load by {rel:.1e} (relative): the system is too badly conditioned for this plate-to-foundation stiffness ratio; try the QP method, a coarser mesh, or check the units of the moduli"
            ),
        ));
    }
    Ok(())
}

/// A tensionless foundation can only balance a net downward load whose line of action passes
/// through the plate: check the rigid-body components of the load before solving.
pub fn check_feasible(ops: &Operators) -> Result<()> {
    let rf: Vec<f64> = ops.rigid.iter().map(|r| linalg::dot(r, &ops.f)).collect();
    let total = rf[0];
    let scale: f64 = ops.f.iter().map(|v| v.abs()).sum();
    if total <= 1e-12 * scale {
        return Err(Error::Infeasible(format!(
            "the net load is upward or zero ({:.3e} in units of P on the model): a foundation that cannot pull cannot hold the plate down; bonded contact can",
            total
        )));
    }
    // Resultant position, where the model keeps that rotation (x: mode 1 unless reduced about
    // x = 0; y: the next mode unless reduced about y = 0). A non-negative nodal pressure σ_j
    // acts at the centroid of its shape function (coupling B), so with nodal constraints the
    // reachable resultants are the bounding box of those centroids — for the consistent
    // (half-space) coupling a third of an element inside the plate edge.
    let c: Vec<Vec<f64>> = ops.rigid.iter().map(|r| ops.bt_times(r)).collect();
    let nodal = ops.constraints.kind == ConstraintPoints::Nodal;
    let m = &ops.mesh;
    let bounds = |k: usize, lo: f64, hi: f64| {
        if nodal {
            let (mut a, mut b) = (f64::INFINITY, f64::NEG_INFINITY);
            for j in 0..c[0].len() {
                if c[0][j] > 0.0 {
                    let x = c[k][j] / c[0][j];
                    a = a.min(x);
                    b = b.max(x);
                }
            }
            (a, b)
        } else {
            (lo, hi)
        }
    };
    let tol = 1e-9;
    let mut k = 1;
    if !m.sym_x {
        let (lo, hi) = bounds(k, m.x0, m.x0 + m.nx as f64 * m.hx);
        let xbar = rf[k] / total;
        k += 1;
        if xbar < lo - tol || xbar > hi + tol {
            return Err(Error::Infeasible(format!(
                "the load resultant acts at x = {xbar:.4} L, outside [{lo:.4}, {hi:.4}] L where non-negative nodal pressures can balance it (the plate would tip over; a resultant on the very edge needs pressure concentrated on the edge, which bilinear pressures reach only to within a third of an element)"
            )));
        }
    }
    if !m.sym_y {
        let (lo, hi) = bounds(k, m.y0, m.y0 + m.ny as f64 * m.hy);
        let ybar = rf[k] / total;
        if ybar < lo - tol || ybar > hi + tol {
            return Err(Error::Infeasible(format!(
                "the load resultant acts at y = {ybar:.4} L, outside [{lo:.4}, {hi:.4}] L where non-negative nodal pressures can balance it (the plate would tip over; a resultant on the very edge needs pressure concentrated on the edge, which bilinear pressures reach only to within a third of an element)"
            )));
        }
    }
    Ok(())
}

/// Nodal gap and residual bookkeeping shared by the methods: g = T σ − Bᵀ u + g₀ (g₀ the
/// voids' initial gap).
pub fn discrete_gap(ops: &Operators, u: &[f64], sigma: &[f64]) -> Vec<f64> {
    let ts = ops.t.apply(sigma);
    let btu = ops.bt_times(u);
    ts.iter()
        .zip(&btu)
        .zip(&ops.gap0)
        .map(|((a, b), g0)| a - b + g0)
        .collect()
}
