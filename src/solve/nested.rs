//! The nested start of the iterative methods: on a large grid, the same model solved first on
//! a grid twice as coarse (recursively), its pressures the fine solve's start — the penalty's
//! first lifted set (and its ε̄ where the automatic choice lowered it on the coarse grid), the
//! active-set QP's first iterate.

use super::dispatch::{solve_with, takes_start};
use super::solution::Solution;
use crate::error::{Error, Result};
use crate::foundation::Compliance;
use crate::method::{Method, Start};
use crate::model::Model;
use crate::monitor::Monitor;
use crate::operators::Operators;

/// Pressure nodes from which the penalty and the matrix-free active-set QP start from a coarser
/// grid's answer: below, a cold start takes few steps and a coarse assembly would not pay.
pub const NESTED_MIN_NODES: usize = 4096;

/// Solve; where the penalty or the matrix-free active-set QP runs on a large grid with
/// `start = "nested"`, first solve the same model on a grid twice as coarse (the same way,
/// recursively) and start from its pressures. From a cold start the contact edge moves by a
/// ring of nodes per step, so the steps grow with the grid; from the coarse answer only the
/// rings near the edge remain to be settled. The answer is the same (the QP's solution is
/// unique, the penalised problem strictly convex); a coarse solve that fails or does
/// not converge is dropped for a cold start, and so is a jointed plate whose joints would not
/// lie on the coarse grid's lines.
pub fn solve_nested(
    model: &Model,
    ops: &Operators,
    method: &Method,
    monitor: &Monitor<'_>,
) -> Result<Solution> {
    let nested = match method {
        Method::Penalty(s) => s.start == Start::Nested,
        Method::Qp(s) => s.start == Start::Nested,
        Method::Bonded => false,
    };
    if !nested || !takes_start(ops, method) || ops.n_sigma() < NESTED_MIN_NODES {
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
    let (start, fine) = match solve_nested(&coarse, &coarse_ops, method, &monitor.quiet()) {
        Err(e @ Error::Cancelled(_)) => return Err(e),
        Ok(c) if c.status.converged() => {
            let start = edge_start(ops, &coarse_ops, &c);
            // The penalty continues at the ε̄ the coarse grid ended at (the automatic choice
            // lowers it where a stage leaves tension; the fine grid needs the same).
            let fine = match (method, &c.method) {
                (Method::Penalty(s), Method::Penalty(reached)) if s.auto => {
                    Method::Penalty(crate::method::PenaltySettings {
                        epsilon: reached.epsilon.min(s.epsilon),
                        ..*s
                    })
                }
                _ => method.clone(),
            };
            (Some(start), fine)
        }
        _ => (None, method.clone()),
    };
    let mut sol = solve_with(ops, &fine, start.as_deref(), monitor)?;
    if start.is_some() {
        let what = match method {
            Method::Penalty(_) => "penalty iteration started from the lifted set",
            _ => "active-set QP started from the pressures",
        };
        sol.info.notes.push(format!(
            "{what} of the same plate on {} × {} elements (solved the same way; its time is in the solve's)",
            coarse.elements[0], coarse.elements[1]
        ));
    }
    Ok(sol)
}

/// The fine grid's start from the coarse answer: its pressures interpolated, set to zero where
/// the contact-edge function [`edge_function`], interpolated, says the plate lifts — the
/// penalty's first penalised set, the active-set QP's first held set (which it makes feasible
/// on that face: projected onto the whole feasible set, the shift to equilibrium brought the
/// cut ring back into contact, and it took 18–30 face solves instead of 4–8).
fn edge_start(ops: &Operators, coarse_ops: &Operators, coarse: &Solution) -> Vec<f64> {
    let sigma = ops.mesh.interpolate_from(&coarse_ops.mesh, &coarse.sigma);
    match edge_function(coarse_ops, coarse) {
        Some(phi) => {
            let phi = ops.mesh.interpolate_from(&coarse_ops.mesh, &phi);
            sigma
                .iter()
                .zip(&phi)
                .map(|(&s, &p)| if p < 0.0 { 0.0 } else { s })
                .collect()
        }
        None => sigma,
    }
}

/// The coarse answer as one field that changes sign at the contact edge: σ − g/T_ii (the
/// pressure where the plate touches, minus the pressure its gap would take on the soil's own
/// node stiffness where it lifts). Interpolated, its zero falls between the coarse nodes where
/// the edge is; the pressure alone, zero on the lifted side, would mark every fine node of a
/// coarse element touching the contact region as in contact — a ring of fine nodes too many,
/// for the fine steps to lift again. None where the gap is not at the nodes (Gauss-point
/// constraints).
fn edge_function(ops: &Operators, coarse: &Solution) -> Option<Vec<f64>> {
    let n = ops.n_sigma();
    if coarse.gap.len() != n || coarse.sigma.len() != n {
        return None;
    }
    let t = ops.t.diagonal();
    Some(
        coarse
            .sigma
            .iter()
            .zip(&coarse.gap)
            .zip(&t)
            .map(|((&s, &g), &c)| if c > 0.0 { s - g.max(0.0) / c } else { s })
            .collect(),
    )
}
