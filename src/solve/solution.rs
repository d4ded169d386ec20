//! What every method returns: the solution, its status, its history and how the solve went.

use super::diagnostics::{ActiveSetDiagnostics, CgReport, QpDiagnostics};
use crate::method::Method;

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
        /// Moment of that tension about the contact's centroid / (compressive resultant ×
        /// (the contact's radius of gyration + one element)): how far the tension moves the
        /// contact's resultant, relative to the contact's size.
        tension_moment: f64,
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

    /// Which kind of outcome, as the studies' CSV files name it.
    pub fn kind(&self) -> StatusKind {
        match self {
            Status::Converged => StatusKind::Converged,
            Status::Cycling { .. } => StatusKind::Cycling,
            Status::IterationLimit { .. } => StatusKind::IterationLimit,
            Status::PenaltyTooWeak { .. } => StatusKind::PenaltyTooWeak,
            Status::SolverFailure { .. } => StatusKind::SolverFailure,
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
                tension_moment,
                suggested_penalty,
            } => format!(
                "not converged: lifted points still carry tension (peak {tension_ratio:.1e} of the peak pressure, {:.2} % of the load, its moment shifting the contact's resultant by {:.2} % of the contact's size), so ε̄ is too large for this stiffness ratio; ε̄ = {suggested_penalty:.0e} or the QP should converge",
                100.0 * tension_share,
                100.0 * tension_moment
            ),
            Status::SolverFailure { detail } => format!("not converged: {detail}"),
        }
    }
}

/// The kinds of [`Status`], without their data.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum StatusKind {
    /// [`Status::Converged`].
    Converged,
    /// [`Status::Cycling`].
    Cycling,
    /// [`Status::IterationLimit`].
    IterationLimit,
    /// [`Status::PenaltyTooWeak`].
    PenaltyTooWeak,
    /// [`Status::SolverFailure`].
    SolverFailure,
}

crate::choice::names!(StatusKind, Converged => "converged", Cycling => "cycling",
    IterationLimit => "iteration-limit", PenaltyTooWeak => "penalty-too-weak",
    SolverFailure => "solver-failure");

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
    pub cg: Option<CgReport>,
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

/// One ε̄ of the penalty iteration (one stage of the automatic choice).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct PenaltyStage {
    /// ε̄ of the stage.
    pub epsilon: f64,
    /// Linear solves at this ε̄.
    pub steps: usize,
    /// How the stage ended ([`Status::kind`]).
    pub outcome: StatusKind,
}

/// How a solve went: timings and the external solver's diagnostics.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SolveInfo {
    /// Phase timings.
    pub timings: Timings,
    /// clarabel's diagnostics (QP by clarabel only).
    pub qp: Option<QpDiagnostics>,
    /// The matrix-free QP's diagnostics (QP by the active-set solver only).
    pub active_set: Option<ActiveSetDiagnostics>,
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
