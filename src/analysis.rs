//! One call from a validated problem to everything a user sees: check the memory budget,
//! assemble, solve, post-process.

use std::time::Instant;

use crate::budget;
use crate::error::Result;
use crate::method::Method;
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
    let solution = solve::solve(ops, method)?;
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

/// Check the memory budget, assemble, solve with the problem's method and post-process.
pub fn analyse(problem: &Problem) -> Result<Analysis> {
    budget::check(&problem.model, &problem.method, problem.memory_limit)?;
    let t0 = Instant::now();
    let ops = Operators::assemble(&problem.model);
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
