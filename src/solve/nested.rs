//! The nested start of the matrix-free active-set QP: on a large grid, the same model solved
//! first on a grid twice as coarse, its pressures the fine solve's first iterate.

use super::dispatch::{solve_with, takes_start};
use super::solution::Solution;
use crate::error::{Error, Result};
use crate::foundation::Compliance;
use crate::method::Method;
use crate::model::Model;
use crate::monitor::Monitor;
use crate::operators::Operators;

/// Pressure nodes from which the matrix-free active-set QP starts from a coarser grid's
/// answer: below, a cold start takes few face solves and a coarse assembly would not pay.
pub const NESTED_MIN_NODES: usize = 4096;

/// Solve; where the matrix-free active-set QP runs on a large grid, first solve the same model
/// on a grid twice as coarse (the same way, recursively) and start from its pressures. From a
/// cold start the contact edge moves by a ring of nodes per face solve, so the face solves grow
/// with the grid; from the coarse answer only the rings near the edge remain to be settled.
/// The answer is the same (the QP's solution is unique); a coarse solve that fails or does
/// not converge is dropped for a cold start, and so is a jointed plate whose joints would not
/// lie on the coarse grid's lines.
pub fn solve_nested(
    model: &Model,
    ops: &Operators,
    method: &Method,
    monitor: &Monitor<'_>,
) -> Result<Solution> {
    if !takes_start(ops, method) || ops.n_sigma() < NESTED_MIN_NODES {
        return solve_with(ops, method, None, monitor);
    }
    let mut coarse = model.clone();
    // Even counts, so that the coarse grid keeps the fine one's symmetry reduction.
    coarse.elements = model.elements.map(|n| 2 * n.div_ceil(4).max(1));
    // A jointed plate starts from a coarse grid only when its joints stay on grid lines there
    // (each side of a joint then starts from its own side's pressures).
    if !model.layout.fits(coarse.elements, model.groups.mu) {
        return solve_with(ops, method, None, monitor);
    }
    let toeplitz = matches!(ops.t.as_ref(), Compliance::Toeplitz(_));
    let coarse_ops = Operators::assemble_with(&coarse, toeplitz);
    monitor.check("the coarse-grid start")?;
    // The coarse solves' steps are not the fine solve's: only the flag reaches them.
    let start = match solve_nested(&coarse, &coarse_ops, method, &monitor.quiet()) {
        Err(e @ Error::Cancelled(_)) => return Err(e),
        Ok(c) if c.status.converged() => {
            Some(ops.mesh.interpolate_from(&coarse_ops.mesh, &c.sigma))
        }
        _ => None,
    };
    let mut sol = solve_with(ops, method, start.as_deref(), monitor)?;
    if start.is_some() {
        sol.info.notes.push(format!(
            "active-set QP started from the pressures of the same plate on {} × {} elements (solved the same way; its time is in the solve's)",
            coarse.elements[0], coarse.elements[1]
        ));
    }
    Ok(sol)
}
