//! Solution methods and what they return.
//!
//! Every method takes the same [`Operators`] and returns a [`Solution`]. A method that ran but
//! did not reach an answer returns a `Solution` whose [`Status`] says so; only failures that
//! leave nothing to report (a factorisation breaking down, a problem too large) are errors.

pub mod active_set;
pub mod bonded;
mod checks;
mod diagnostics;
pub mod iterative;
pub mod linalg;
pub mod low_rank;
pub mod penalty;
mod penalty_step;
pub mod qp;
mod solution;
pub mod sparse_qp;
pub mod springs;

pub use checks::{check_equilibrium, check_feasible, discrete_gap, EQUILIBRIUM_TOLERANCE};
pub use diagnostics::{ActiveSetDiagnostics, CgReport, KktResiduals, QpDiagnostics};
pub use solution::{Iteration, PenaltyStage, Solution, SolveInfo, Status, Timings};

use crate::error::{Error, Result};
use crate::foundation::Compliance;
use crate::method::{Method, QpForm, QpSettings, QpSolver};
use crate::model::ConstraintPoints;
use crate::operators::Operators;
use sparse_qp::SparseForm;

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
