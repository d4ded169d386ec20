//! The penalty limit ε̄ → 0 against the QP (`eps-sweep`).

use std::time::Instant;

use serde::Serialize;

use super::RunOutcome;
use crate::error::{Error, Result};
use crate::method::{Method, PenaltySettings};
use crate::metrics::{loglog_fit, max_abs_diff, rel_l2};
use crate::model::{ConstraintPoints, Model};
use crate::monitor::{Cases, Monitor};
use crate::operators::Operators;
use crate::scene::Problem;
use crate::solve::StatusKind;
use crate::solve::{self, Solution};

/// Dimensionless nodal fields of a solution: (V at model nodes, σ at model nodes).
fn fields(ops: &Operators, model: &Model, sol: &Solution) -> (Vec<f64>, Vec<f64>) {
    let mu = model.groups.mu;
    (
        ops.node_w(&sol.u),
        sol.sigma.iter().map(|s| mu * s).collect(),
    )
}

/// One row of `eps_sweep.csv`.
#[derive(Debug, Clone, Serialize)]
pub struct SweepRow {
    /// Constraint points.
    pub constraint: &'static str,
    /// ε̄.
    pub eps: f64,
    /// Penalty steps.
    pub iterations: usize,
    /// Converged (set repeated and penalty strong enough).
    pub converged: bool,
    /// Outcome kind.
    pub status: RunOutcome,
    /// max |σ_pen − σ_qp| (dimensionless σ).
    pub max_abs_sigma_err: f64,
    /// max |V_pen − V_qp|.
    pub max_abs_v_err: f64,
    /// ‖σ_pen − σ_qp‖₂ / ‖σ_qp‖₂.
    pub rel_l2_sigma: f64,
    /// ‖V_pen − V_qp‖₂ / ‖V_qp‖₂.
    pub rel_l2_v: f64,
    /// Minimum σ at the constraint points.
    pub min_pressure: f64,
    /// Wall time of the penalty solve, s.
    pub time_s: f64,
}

/// Result of an ε̄ sweep.
#[derive(Debug, Clone, Serialize)]
pub struct Sweep {
    /// Rows, per constraint kind, ε̄ decreasing.
    pub rows: Vec<SweepRow>,
    /// Per constraint kind: the fitted log–log slope of rel_l2_sigma against ε̄ and the ε̄ range
    /// [lo, hi] of the points it used.
    pub slopes: Vec<(&'static str, Option<f64>, [f64; 2])>,
    /// The ε̄ window [lo, hi] the fit was allowed to use.
    pub fit_window: [f64; 2],
    /// QP time per constraint kind, s.
    pub qp_time_s: Vec<(&'static str, f64)>,
}

/// Solve the scene with the QP once and with the penalty method at each ε̄, for each constraint
/// kind, on one assembly per kind. The slope is fitted over the points in `fit_window` where the
/// penalty converged (or, if fewer than three, where the penalised set settled), from the
/// largest ε̄ down to where the curve flattens (round-off and the QP's own tolerance).
pub fn eps_sweep(
    problem: &Problem,
    epsilons: &[f64],
    constraints: &[ConstraintPoints],
    fit_window: [f64; 2],
    monitor: &Monitor<'_>,
) -> Result<Sweep> {
    let cases = Cases::new(monitor, constraints.len() * (1 + epsilons.len()));
    let mut rows = Vec::new();
    let mut slopes = Vec::new();
    let mut qp_time_s = Vec::new();
    let max_iterations = match &problem.method {
        Method::Penalty(s) => s.max_iterations,
        _ => PenaltySettings::default().max_iterations,
    };
    for &kind in constraints {
        let mut model = problem.model.clone();
        model.constraint = kind;
        // The QP reference and every penalty run on one assembly, on the problem's route.
        let ops = crate::analysis::prepare_shared(
            &model,
            &[&Method::qp(), &Method::penalty()],
            problem.route,
            problem.memory_limit,
        )?;
        solve::check_feasible(&ops)?;
        cases.start(&format!("{}: QP reference", kind.name()))?;
        let t = Instant::now();
        let q = solve::solve_with(&ops, &Method::qp(), None, &cases.inner())?;
        qp_time_s.push((kind.name(), t.elapsed().as_secs_f64()));
        if !q.status.converged() {
            return Err(Error::numerical("QP reference", q.status.describe()));
        }
        let (vq, sq) = fields(&ops, &model, &q);
        // Each ε̄ starts from the last converged one's lifted set: the same operators, a nearby
        // answer (the penalised problem has one solution whatever the start).
        let mut warm: Option<Vec<f64>> = None;
        for &eps in epsilons {
            cases.start(&format!("{}: penalty ε̄ = {eps:.1e}", kind.name()))?;
            let t = Instant::now();
            let r = solve::solve_with(
                &ops,
                &Method::Penalty(PenaltySettings {
                    max_iterations,
                    ..PenaltySettings::fixed(eps)
                }),
                warm.as_deref(),
                &cases.inner(),
            );
            if let Err(e @ Error::Cancelled(_)) = r {
                return Err(e);
            }
            if let Ok(sol) = &r {
                if sol.status.converged() {
                    warm = Some(sol.sigma.clone());
                }
            }
            let time_s = t.elapsed().as_secs_f64();
            let row = match r {
                Ok(sol) => {
                    let (v, s) = fields(&ops, &model, &sol);
                    let gs = ops.g_times(&sol.sigma);
                    let row = SweepRow {
                        constraint: kind.name(),
                        eps,
                        iterations: sol.iterations,
                        converged: sol.status.converged(),
                        status: RunOutcome::Solved(sol.status.kind()),
                        max_abs_sigma_err: max_abs_diff(&s, &sq),
                        max_abs_v_err: max_abs_diff(&v, &vq),
                        rel_l2_sigma: rel_l2(&s, &sq),
                        rel_l2_v: rel_l2(&v, &vq),
                        min_pressure: model.groups.mu
                            * gs.iter().cloned().fold(f64::INFINITY, f64::min),
                        time_s,
                    };
                    row
                }
                Err(e) => SweepRow {
                    constraint: kind.name(),
                    eps,
                    iterations: 0,
                    converged: false,
                    status: RunOutcome::Failed(e.kind()),
                    max_abs_sigma_err: f64::NAN,
                    max_abs_v_err: f64::NAN,
                    rel_l2_sigma: f64::NAN,
                    rel_l2_v: f64::NAN,
                    min_pressure: f64::NAN,
                    time_s,
                },
            };
            rows.push(row);
        }
        let mine: Vec<&SweepRow> = rows
            .iter()
            // The penalised set settled (a too-weak penalty still gives a valid point of the
            // ε̄ → 0 curve; only cycling and the iteration cap do not).
            .filter(|r| {
                r.constraint == kind.name()
                    && (r.status == RunOutcome::CONVERGED
                        || r.status == RunOutcome::Solved(StatusKind::PenaltyTooWeak))
                    && r.rel_l2_sigma.is_finite()
            })
            .collect();
        // The asymptotic range: starting from the largest ε̄, the run of consecutive points
        // whose local log–log slope stays above 1/2 — it ends where round-off and the QP's own
        // tolerance flatten the curve. Prefer points where the penalty is adequate; fall back to
        // every settled point when that leaves fewer than three.
        let run_of = |adequate_only: bool| -> Vec<(f64, f64)> {
            let mut pts: Vec<(f64, f64)> = mine
                .iter()
                .filter(|r| {
                    (!adequate_only || r.status == RunOutcome::CONVERGED)
                        && r.eps >= fit_window[0]
                        && r.eps <= fit_window[1]
                        && r.rel_l2_sigma > 0.0
                })
                .map(|r| (r.eps, r.rel_l2_sigma))
                .collect();
            pts.sort_by(|a, b| b.0.total_cmp(&a.0));
            let mut run: Vec<(f64, f64)> = Vec::new();
            for p in pts {
                if let Some(&(e0, r0)) = run.last() {
                    if (r0 / p.1).ln() / (e0 / p.0).ln() < 0.5 {
                        break;
                    }
                }
                run.push(p);
            }
            run
        };
        let adequate = run_of(true);
        let fit = if adequate.len() >= 3 {
            adequate
        } else {
            run_of(false)
        };
        let range = [
            fit.iter().map(|p| p.0).fold(f64::INFINITY, f64::min),
            fit.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max),
        ];
        slopes.push((kind.name(), loglog_fit(&fit).map(|(s, _)| s), range));
    }
    Ok(Sweep {
        rows,
        slopes,
        fit_window,
        qp_time_s,
    })
}
