//! One call from a validated problem to everything a user sees: assemble, solve, post-process.

use std::time::Instant;

use crate::error::Result;
use crate::output::summary::{Summary, Times};
use crate::post::{self, Report};
use crate::scene::Problem;
use crate::solve::{self, Solution};
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

/// Assemble, solve with the problem's settings and post-process.
pub fn analyse(problem: &Problem) -> Result<Analysis> {
    let t0 = Instant::now();
    let ops = Operators::assemble(problem)?;
    let t_asm = t0.elapsed().as_secs_f64();
    let solution = solve::solve(&ops, &problem.solver)?;
    let t_solve = t0.elapsed().as_secs_f64() - t_asm;
    let report = post::report(problem, &ops, &solution);
    let times = Times {
        assemble: t_asm,
        solve: t_solve,
        total: t0.elapsed().as_secs_f64(),
    };
    let summary = Summary::new(problem, &ops, &solution, &report, times);
    Ok(Analysis {
        ops,
        solution,
        report,
        summary,
    })
}
