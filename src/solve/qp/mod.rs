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
/// `monitor`'s flag stops the active-set solver between face solves and clarabel between its
/// interior-point iterations ([`clarabel_watched`]).
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
        QpForm::Lifted => {
            clarabel_sparse::solve_sparse_with(ops, settings, SparseForm::Lifted, monitor)?
        }
        QpForm::Primal => {
            let sol =
                clarabel_sparse::solve_sparse_with(ops, settings, SparseForm::Primal, monitor)?;
            if settings.form == QpForm::Auto
                && !sol.status.converged()
                && ops.n_sigma() <= DENSE_FALLBACK_NODES
            {
                dense_fallback(ops, settings, &sol, monitor)?
            } else {
                sol
            }
        }
        _ => clarabel_dense::solve_with(ops, settings, monitor)?,
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
fn dense_fallback(
    ops: &Operators,
    settings: &QpSettings,
    primal: &Solution,
    monitor: &Monitor<'_>,
) -> Result<Solution> {
    let mut sol = clarabel_dense::solve_with(ops, settings, monitor)?;
    sol.info.notes.push(format!(
        "the sparse (primal) QP stopped ({}); solved again in the dense Schur form",
        primal.status.describe()
    ));
    sol.iterations += primal.iterations;
    Ok(sol)
}

/// How often the watcher of [`clarabel_watched`] looks at the monitor's flag.
const WATCH: std::time::Duration = std::time::Duration::from_millis(20);

/// Run clarabel's interior-point loop so that `monitor`'s cancel flag stops it between two
/// iterations: clarabel's termination callback must own what it reads (`'static`), so it reads
/// a flag of its own, which a watcher thread sets from the monitor's while the loop runs (every
/// [`WATCH`]; woken at once when the loop ends). A stopped loop is [`crate::Error::Cancelled`].
/// Without a cancel flag the loop just runs.
pub(crate) fn clarabel_watched(
    solver: &mut clarabel::solver::DefaultSolver<f64>,
    monitor: &Monitor<'_>,
) -> Result<()> {
    use clarabel::solver::IPSolver;
    use std::sync::atomic::{AtomicBool, Ordering};
    if !monitor.can_cancel() {
        solver.solve();
        return Ok(());
    }
    let stop = std::sync::Arc::new(AtomicBool::new(false));
    let seen = stop.clone();
    solver.set_termination_callback(move |_: &clarabel::solver::DefaultInfo<f64>| {
        seen.load(Ordering::Relaxed)
    });
    let done = AtomicBool::new(false);
    std::thread::scope(|scope| {
        let watcher = scope.spawn(|| {
            while !done.load(Ordering::Acquire) {
                if monitor.cancelled() {
                    stop.store(true, Ordering::Relaxed);
                    break;
                }
                std::thread::park_timeout(WATCH);
            }
        });
        solver.solve();
        done.store(true, Ordering::Release);
        watcher.thread().unpark();
    });
    solver.unset_termination_callback();
    monitor.check("the QP (clarabel's interior-point iterations)")
}
