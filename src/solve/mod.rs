//! Solution methods and what they return.
//!
//! Every method takes the same [`Operators`] and returns a [`Solution`]. A method that ran but
//! did not reach an answer returns a `Solution` whose [`Status`] says so; only failures that
//! leave nothing to report (a factorisation breaking down, a problem too large) are errors.

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

pub use checks::{check_equilibrium, check_feasible, discrete_gap, EQUILIBRIUM_TOLERANCE};
pub use diagnostics::{ActiveSetDiagnostics, CgReport, KktResiduals, QpDiagnostics};
pub use solution::{Iteration, PenaltyStage, Solution, SolveInfo, Status, Timings};

use crate::error::{Error, Result};
use crate::foundation::Compliance;
use crate::method::{Method, QpSolver};
use crate::model::ConstraintPoints;
use crate::operators::Operators;

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
            qp::solve_qp(ops, settings, start)?
        }
    };
    check_equilibrium(ops, &sol)?;
    Ok(sol)
}
