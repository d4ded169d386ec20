//! One call from a validated problem to everything a user sees: check the memory budget,
//! assemble, solve, post-process.

use std::time::Instant;

use crate::budget;
use crate::error::Result;
use crate::foundation::Compliance;
use crate::method::{Method, Route};
use crate::model::Model;
use crate::post::{self, Report};
use crate::scene::Problem;
use crate::solve::{self, Solution};
use crate::summary::{Summary, Times};
use crate::Operators;

/// Operators, solution, report and summary of one solve.
pub struct Analysis {
    /// The assembled operators.
    pub ops: Operators,
    /// The method's solution.
    pub solution: Solution,
    /// Post-processed fields.
    pub report: Report,
    /// Summary (summary.json).
    pub summary: Summary,
}

/// A solved method on shared operators: solution, report and summary.
pub struct Outcome {
    /// The method's solution.
    pub solution: Solution,
    /// Post-processed fields.
    pub report: Report,
    /// Summary (summary.json).
    pub summary: Summary,
}

/// Solve assembled operators with one method and post-process; `assemble_s` is the time the
/// operators took, reported beside the method's own.
pub fn run(model: &Model, ops: &Operators, method: &Method, assemble_s: f64) -> Result<Outcome> {
    let t = Instant::now();
    let solution = solve_nested(model, ops, method)?;
    let solve_s = t.elapsed().as_secs_f64();
    let report = post::report(model, ops, &solution);
    let times = Times {
        assemble: assemble_s,
        solve: solve_s,
        total: assemble_s + t.elapsed().as_secs_f64(),
    };
    let summary = Summary::new(model, ops, &solution, &report, times);
    Ok(Outcome {
        solution,
        report,
        summary,
    })
}

/// Pressure nodes from which the matrix-free active-set QP starts from a coarser grid's
/// answer: below, a cold start takes few face solves and a coarse assembly would not pay.
pub const NESTED_MIN_NODES: usize = 4096;

/// Solve; where the matrix-free active-set QP runs on a large grid, first solve the same model
/// on a grid twice as coarse (the same way, recursively) and start from its pressures. From a
/// cold start the contact edge moves by a ring of nodes per face solve, so the face solves grow
/// with the grid; from the coarse answer only the rings near the edge remain to be settled.
/// The answer is the same (the QP's solution is unique); a coarse solve that fails or does
/// not converge is dropped for a cold start.
fn solve_nested(model: &Model, ops: &Operators, method: &Method) -> Result<Solution> {
    if !solve::takes_start(ops, method) || ops.n_sigma() < NESTED_MIN_NODES {
        return solve::solve(ops, method);
    }
    let mut coarse = model.clone();
    // Even counts, so that the coarse grid keeps the fine one's symmetry reduction.
    coarse.elements = model.elements.map(|n| 2 * n.div_ceil(4).max(1));
    let toeplitz = matches!(ops.t.as_ref(), Compliance::Toeplitz(_));
    let coarse_ops = Operators::assemble_with(&coarse, toeplitz);
    let start = match solve_nested(&coarse, &coarse_ops, method) {
        Ok(c) if c.status.converged() => {
            Some(ops.mesh.interpolate_from(&coarse_ops.mesh, &c.sigma))
        }
        _ => None,
    };
    let mut sol = solve::solve_from(ops, method, start.as_deref())?;
    if start.is_some() {
        sol.info.notes.push(format!(
            "active-set QP started from the pressures of the same plate on {} × {} elements (solved the same way; its time is in the solve's)",
            coarse.elements[0], coarse.elements[1]
        ));
    }
    Ok(sol)
}

/// Check the memory budget of `method` on `route` and assemble the operators that route needs
/// (a dense or an FFT half-space T).
pub fn prepare(model: &Model, method: &Method, route: Route, limit: f64) -> Result<Operators> {
    let toeplitz = budget::check_route(model, method, route, limit)?;
    Ok(Operators::assemble_with(model, toeplitz))
}

/// Check the memory budget of every method and assemble one set of operators they all can
/// use: T as an FFT operator where every one of them takes the iterative route on `route`
/// (the penalty, bonded contact and the matrix-free QP beyond the dense size under `auto`),
/// dense otherwise (clarabel's Schur form needs it).
pub fn prepare_shared(
    model: &Model,
    methods: &[&Method],
    route: Route,
    limit: f64,
) -> Result<Operators> {
    let mut toeplitz = true;
    for m in methods {
        toeplitz &= budget::toeplitz(model, m, route)?;
    }
    for m in methods {
        if toeplitz {
            budget::check_route(model, m, Route::Iterative, limit)?;
        } else {
            budget::check(model, m, limit)?;
        }
    }
    Ok(Operators::assemble_with(model, toeplitz))
}

/// Check the memory budget, assemble, solve with the problem's method and post-process.
pub fn analyse(problem: &Problem) -> Result<Analysis> {
    let t0 = Instant::now();
    let ops = prepare(
        &problem.model,
        &problem.method,
        problem.route,
        problem.memory_limit,
    )?;
    let assemble_s = t0.elapsed().as_secs_f64();
    let Outcome {
        solution,
        report,
        summary,
    } = run(&problem.model, &ops, &problem.method, assemble_s)?;
    Ok(Analysis {
        ops,
        solution,
        report,
        summary,
    })
}
