//! Speed against accuracy over meshes (`tradeoff`).

use std::time::Instant;

use serde::Serialize;

use super::RunOutcome;
use crate::error::{Error, Result};
use crate::method::{Method, MethodKind, PenaltySettings, Route};
use crate::metrics::{pareto_front, rel_l2};
use crate::model::Model;
use crate::monitor::{Cases, Monitor};
use crate::operators::Operators;
use crate::post;
use crate::scene::Problem;
use crate::solve::{self, Solution};

/// One point of the speed–accuracy chart.
#[derive(Debug, Clone, Serialize)]
pub struct TradeoffPoint {
    /// The method.
    pub method: MethodKind,
    /// Elements per side of the whole plate.
    pub mesh: usize,
    /// ε̄ (penalty) or NaN (QP).
    pub eps: f64,
    /// Assembly + solve wall time, s.
    pub time_s: f64,
    /// ‖V − V_ref‖ / ‖V_ref‖ (root mean square over a 21 × 21 grid of (s, t) points; a
    /// maximum would be dominated by the logarithmic shear singularity of a Mindlin plate
    /// under a point load, which no mesh converges).
    pub error: f64,
    /// Converged.
    pub converged: bool,
    /// Outcome kind.
    pub status: RunOutcome,
    /// On the Pareto front (no other point both faster and more accurate).
    pub pareto: bool,
}

/// Result of a tradeoff study.
#[derive(Debug, Clone, Serialize)]
pub struct Tradeoff {
    /// Points.
    pub points: Vec<TradeoffPoint>,
    /// What the errors are measured against.
    pub reference: String,
}

/// V on a 21 × 21 grid of (s, t) over the whole plate, for comparing meshes.
fn sample_v(model: &Model, ops: &Operators, sol: &Solution) -> Vec<f64> {
    let rep = post::report(model, ops, sol);
    let mut out = Vec::with_capacity(441);
    for j in 0..21 {
        for i in 0..21 {
            let s = -1.0 + 0.1 * i as f64;
            let t = -1.0 + 0.1 * j as f64;
            out.push(rep.field.interpolate(&rep.field.v, s, t));
        }
    }
    out
}

/// The model on n elements along x, the y count following μ (even when n is).
fn with_mesh(model: &Model, n: usize) -> Model {
    let mut m = model.clone();
    let ny = ((n as f64 * m.groups.mu).round() as usize).max(1);
    let ny = if !ny.is_multiple_of(2) && n.is_multiple_of(2) {
        ny + 1
    } else {
        ny
    };
    m.elements = [n, ny];
    m
}

/// A tradeoff point from a solve that ran, or from the error that stopped it.
fn tradeoff_point(
    method: MethodKind,
    mesh: usize,
    eps: f64,
    time_s: f64,
    outcome: std::result::Result<(f64, &Solution), &Error>,
) -> TradeoffPoint {
    match outcome {
        Ok((error, sol)) => TradeoffPoint {
            method,
            mesh,
            eps,
            time_s,
            error,
            converged: sol.status.converged(),
            status: RunOutcome::Solved(sol.status.kind()),
            pareto: false,
        },
        Err(e) => TradeoffPoint {
            method,
            mesh,
            eps,
            time_s,
            error: f64::NAN,
            converged: false,
            status: RunOutcome::Failed(e.kind()),
            pareto: false,
        },
    }
}

/// Each method at each mesh (and each ε̄ for the penalty): wall time against the error in V
/// relative to a reference: the QP on a mesh twice the finest, or — if that does not fit in
/// memory — the QP on the finest mesh (the `reference` field says which). The operators of
/// each mesh are assembled once and shared by the QP and every ε̄; a point's time is that
/// assembly plus its own solve.
pub fn tradeoff(
    problem: &Problem,
    meshes: &[usize],
    penalties: &[f64],
    monitor: &Monitor<'_>,
) -> Result<Tradeoff> {
    let cases = Cases::new(monitor, 1 + meshes.len() * (1 + penalties.len()));
    let finest = meshes
        .iter()
        .copied()
        .max()
        .ok_or_else(|| Error::invalid("meshes", "give at least one mesh"))?;
    let limit = problem.memory_limit;
    let qp = Method::qp();
    let penalty = Method::penalty();
    // Each mesh's operators on the route `auto` gives the QP and the penalty (the FFT T
    // beyond the dense size), so both methods reach every mesh.
    let prepare = |model: &Model| {
        crate::analysis::prepare_shared(model, &[&qp, &penalty], Route::Auto, limit)
    };
    let reference_at = |n: usize| -> Result<Vec<f64>> {
        let model = with_mesh(&problem.model, n);
        let ops = prepare(&model)?;
        let sol = solve::solve_with(&ops, &qp, None, &cases.inner())?;
        Ok(sample_v(&model, &ops, &sol))
    };
    cases.start(&format!(
        "reference: QP at {} elements per side",
        2 * finest
    ))?;
    let (reference, v_ref) = match reference_at(2 * finest) {
        Ok(v) => (
            format!(
                "QP on {} elements per side (twice the finest mesh)",
                2 * finest
            ),
            v,
        ),
        Err(Error::TooLarge { .. }) => {
            cases.start(&format!(
                "reference at {} does not fit; using the QP at {finest}",
                2 * finest
            ))?;
            (format!("QP on {finest} elements per side (the finest mesh; twice it does not fit in memory)"), reference_at(finest)?)
        }
        Err(e) => return Err(e),
    };
    let max_iterations = match &problem.method {
        Method::Penalty(s) => s.max_iterations,
        _ => PenaltySettings::default().max_iterations,
    };
    let mut points = Vec::new();
    for &n in meshes {
        let model = with_mesh(&problem.model, n);
        let t = Instant::now();
        let ops = prepare(&model);
        let assemble_s = t.elapsed().as_secs_f64();
        let run = |method: &Method, eps: f64| -> TradeoffPoint {
            let kind = if matches!(method, Method::Qp(_)) {
                MethodKind::Qp
            } else {
                MethodKind::Penalty
            };
            let t = Instant::now();
            let ops = match &ops {
                Ok(ops) => ops,
                Err(e) => return tradeoff_point(kind, n, eps, f64::NAN, Err(e)),
            };
            let sol = solve::solve_with(ops, method, None, &cases.inner());
            let time_s = assemble_s + t.elapsed().as_secs_f64();
            let outcome = sol
                .as_ref()
                .map(|sol| (rel_l2(&sample_v(&model, ops, sol), &v_ref), sol));
            tradeoff_point(kind, n, eps, time_s, outcome)
        };
        cases.start(&format!("QP at {n}"))?;
        points.push(run(&qp, f64::NAN));
        for &eps in penalties {
            cases.start(&format!("penalty at {n}, ε̄ = {eps:.0e}"))?;
            let method = Method::Penalty(PenaltySettings {
                max_iterations,
                ..PenaltySettings::fixed(eps)
            });
            points.push(run(&method, eps));
        }
    }
    // A point cut short by the cancel flag is not a point of the study.
    cases.inner().check("the tradeoff")?;
    let valid: Vec<usize> = (0..points.len())
        .filter(|&i| points[i].converged && points[i].error.is_finite() && points[i].error > 0.0)
        .collect();
    let xy: Vec<(f64, f64)> = valid
        .iter()
        .map(|&i| (points[i].time_s, points[i].error))
        .collect();
    for k in pareto_front(&xy) {
        points[valid[k]].pareto = true;
    }
    Ok(Tradeoff { points, reference })
}
