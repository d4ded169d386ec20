//! The unbonded problem as a QP in the contact pressures, by three solvers: clarabel on the
//! dense Schur form ([`clarabel_dense`]), clarabel on the sparse Winkler forms
//! ([`clarabel_sparse`]), and the matrix-free active-set method ([`active_set`]). This module
//! picks one for the settings and the operators, and falls back to another where one stops.

pub mod active_set;
pub mod clarabel_dense;
pub mod clarabel_sparse;

use crate::error::Result;
use crate::foundation::Compliance;
use crate::method::{QpForm, QpSettings, QpSolver};
use crate::model::ConstraintPoints;
use crate::monitor::Monitor;
use crate::operators::Operators;
use crate::solve::solution::Solution;
use clarabel_sparse::SparseForm;

/// The QP by the solver its settings resolve to on these operators. Under `qp_solver = auto`
/// a clarabel solve that stops without a solution is solved again by the active-set method
/// where it can be (nodal constraints), and the notes say so.
/// `monitor` watches the active-set solver's face solves; clarabel's interior-point iterations
/// run to their end.
pub(crate) fn solve_qp(
    ops: &Operators,
    settings: &QpSettings,
    start: Option<&[f64]>,
    monitor: &Monitor<'_>,
) -> Result<Solution> {
    let toeplitz = matches!(ops.t.as_ref(), Compliance::Toeplitz(_));
    let solver = settings.resolve(ops.foundation, ops.constraints.kind, toeplitz);
    if solver == QpSolver::ActiveSet {
        return active_set::solve_with(ops, settings, start, monitor);
    }
    let sol = match settings.form.resolve(&ops.t) {
        QpForm::Lifted => clarabel_sparse::solve_sparse(ops, settings, SparseForm::Lifted)?,
        QpForm::Primal => {
            let sol = clarabel_sparse::solve_sparse(ops, settings, SparseForm::Primal)?;
            if settings.form == QpForm::Auto
                && !sol.status.converged()
                && ops.n_sigma() <= DENSE_FALLBACK_NODES
            {
                dense_fallback(ops, settings, &sol)?
            } else {
                sol
            }
        }
        _ => clarabel_dense::solve(ops, settings)?,
    };
    let retry = settings.solver == QpSolver::Auto
        && !sol.status.converged()
        && ops.constraints.kind == ConstraintPoints::Nodal;
    if !retry {
        return Ok(sol);
    }
    monitor.check("the QP")?;
    let mut again = active_set::solve_with(ops, settings, start, monitor)?;
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
fn dense_fallback(ops: &Operators, settings: &QpSettings, primal: &Solution) -> Result<Solution> {
    let mut sol = clarabel_dense::solve(ops, settings)?;
    sol.info.notes.push(format!(
        "the sparse (primal) QP stopped ({}); solved again in the dense Schur form",
        primal.status.describe()
    ));
    sol.iterations += primal.iterations;
    Ok(sol)
}
