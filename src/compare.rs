//! Both unbonded methods on one assembled `Operators`, side by side (`liftoff compare`).

use std::time::Instant;

use serde::Serialize;

use crate::analysis;
use crate::error::Result;
use crate::method::Method;
use crate::monitor::{Cases, Monitor};
use crate::scene::Problem;
use crate::summary::Summary;

/// Differences between the penalty and QP solutions.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Differences {
    /// max |σ_pen − σ_qp| over the nodes, dimensionless σ.
    pub max_abs_sigma: f64,
    /// max |V_pen − V_qp| over the nodes.
    pub max_abs_v: f64,
    /// max |Δσ| / max |σ_qp|.
    pub rel_sigma: f64,
    /// max |ΔV| / max |V_qp|.
    pub rel_v: f64,
    /// Nodes whose contact state differs.
    pub contact_nodes_differing: usize,
}

/// Result of `liftoff compare` (compare.json).
#[derive(Debug, Clone, Serialize)]
pub struct Comparison {
    /// Seconds spent assembling the shared operators.
    pub assemble_s: f64,
    /// Penalty summary.
    pub penalty: Summary,
    /// QP summary.
    pub qp: Summary,
    /// Differences.
    pub differences: Differences,
}

/// Run both unbonded methods (the penalty with the problem's settings when it names the
/// penalty, defaults otherwise; the QP with defaults) on one assembly of the model.
pub fn compare(problem: &Problem) -> Result<Comparison> {
    compare_with(problem, &Monitor::NONE)
}

/// [`compare`], watched by `monitor`: a [`crate::monitor::Progress::Case`] per method, the
/// cancel flag inside each.
pub fn compare_with(problem: &Problem, monitor: &Monitor<'_>) -> Result<Comparison> {
    let cases = Cases::new(monitor, 2);
    let penalty = match &problem.method {
        Method::Penalty(s) => Method::Penalty(*s),
        _ => Method::penalty(),
    };
    let qp = match &problem.method {
        Method::Qp(s) => Method::Qp(s.clone()),
        _ => Method::qp(),
    };
    // One assembly for both, on the route both can take.
    let t0 = Instant::now();
    let ops = analysis::prepare_shared(
        &problem.model,
        &[&penalty, &qp],
        problem.route,
        problem.memory_limit,
    )?;
    let assemble_s = t0.elapsed().as_secs_f64();
    cases.start("penalty")?;
    let pen = analysis::run_with(&problem.model, &ops, &penalty, assemble_s, &cases.inner())?;
    cases.start("QP")?;
    let qp = analysis::run_with(&problem.model, &ops, &qp, assemble_s, &cases.inner())?;
    let (pen_r, qp_r) = (&pen.report, &qp.report);
    let diff = |a: &[f64], b: &[f64]| {
        a.iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max)
    };
    let amax = |a: &[f64]| a.iter().map(|x| x.abs()).fold(0.0, f64::max);
    let ds = diff(&pen_r.field.sigma, &qp_r.field.sigma);
    let dv = diff(&pen_r.field.v, &qp_r.field.v);
    let differing = pen_r
        .field
        .contact
        .iter()
        .zip(&qp_r.field.contact)
        .filter(|(a, b)| a != b)
        .count();
    Ok(Comparison {
        assemble_s,
        differences: Differences {
            max_abs_sigma: ds,
            max_abs_v: dv,
            rel_sigma: ds / amax(&qp_r.field.sigma).max(f64::MIN_POSITIVE),
            rel_v: dv / amax(&qp_r.field.v).max(f64::MIN_POSITIVE),
            contact_nodes_differing: differing,
        },
        penalty: pen.summary,
        qp: qp.summary,
    })
}
