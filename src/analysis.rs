//! One call from a validated problem to everything a user sees: check the memory budget,
//! assemble, solve, post-process.

use std::time::Instant;

use crate::budget;
use crate::error::Result;
use crate::method::{Method, Route};
use crate::model::Model;
use crate::monitor::Monitor;
use crate::operators::Operators;
use crate::post::{self, Report};
use crate::scene::Problem;
use crate::solve::{self, Solution};
use crate::summary::{Summary, Times};

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
pub struct MethodRun {
    /// The method's solution.
    pub solution: Solution,
    /// Post-processed fields.
    pub report: Report,
    /// Summary (summary.json).
    pub summary: Summary,
}

/// Solve assembled operators with one method and post-process; `assemble_s` is the time the
/// operators took, reported beside the method's own.
pub fn run(model: &Model, ops: &Operators, method: &Method, assemble_s: f64) -> Result<MethodRun> {
    run_with(model, ops, method, assemble_s, &Monitor::NONE)
}

/// [`run`], watched by `monitor` (the method's steps, the cancel flag).
pub fn run_with(
    model: &Model,
    ops: &Operators,
    method: &Method,
    assemble_s: f64,
    monitor: &Monitor<'_>,
) -> Result<MethodRun> {
    run_from(model, ops, method, assemble_s, None, monitor)
}

/// [`run_with`], started from the nodal pressures `start` of a related solve on the same
/// operators (a neighbouring load position, another combination): the penalty's first lifted
/// set and the active-set QP's first iterate; without one, a large active-set QP starts from a
/// coarser grid ([`solve::solve_nested`]). The answer does not depend on the start.
pub fn run_from(
    model: &Model,
    ops: &Operators,
    method: &Method,
    assemble_s: f64,
    start: Option<&[f64]>,
    monitor: &Monitor<'_>,
) -> Result<MethodRun> {
    run_carried(model, ops, method, assemble_s, start, None, monitor)
}

/// [`run_from`], with the last factor of the solve before it on the same operators handed over
/// by `carry` ([`solve::Carry`]: a load moved along a lane, position after position).
pub fn run_carried(
    model: &Model,
    ops: &Operators,
    method: &Method,
    assemble_s: f64,
    start: Option<&[f64]>,
    carry: Option<&solve::Carry>,
    monitor: &Monitor<'_>,
) -> Result<MethodRun> {
    let t = Instant::now();
    let solution = match start {
        Some(s) => solve::solve_carried(ops, method, Some(s), carry, monitor)?,
        None => solve::solve_nested(model, ops, method, monitor)?,
    };
    let solve_s = t.elapsed().as_secs_f64();
    let report = post::report(model, ops, &solution);
    let times = Times {
        assemble: assemble_s,
        solve: solve_s,
        total: assemble_s + t.elapsed().as_secs_f64(),
    };
    let summary = Summary::new(model, ops, &solution, &report, times);
    Ok(MethodRun {
        solution,
        report,
        summary,
    })
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
    analyse_with(problem, &Monitor::NONE)
}

/// [`analyse`], watched by `monitor`.
pub fn analyse_with(problem: &Problem, monitor: &Monitor<'_>) -> Result<Analysis> {
    let t0 = Instant::now();
    let ops = prepare(
        &problem.model,
        &problem.method,
        problem.route,
        problem.memory_limit,
    )?;
    let assemble_s = t0.elapsed().as_secs_f64();
    monitor.check("the assembly")?;
    let MethodRun {
        solution,
        report,
        summary,
    } = run_with(&problem.model, &ops, &problem.method, assemble_s, monitor)?;
    Ok(Analysis {
        ops,
        solution,
        report,
        summary,
    })
}
