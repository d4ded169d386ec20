//! Studies of the methods: the penalty limit ε̄ → 0 against the QP (`eps-sweep`), speed against
//! accuracy over meshes (`tradeoff`), and the regimes where each method breaks (`stability`).
//!
//! Every study assembles its operators once per model and hands the same value to both methods,
//! so differences between methods are differences of method, never of discretisation.

use std::time::Instant;

use serde::Serialize;

use crate::budget;
use crate::error::{Error, Result};
use crate::foundation::FoundationKind;
use crate::method::{Method, MethodKind, PenaltySettings};
use crate::metrics::{loglog_fit, max_abs_diff, pareto_front, rel_l2};
use crate::model::{ConstraintPoints, Load, Model};
use crate::operators::Operators;
use crate::post;
use crate::scene::Problem;
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
    pub status: String,
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

/// Logarithmically spaced values from `from` to `to` (inclusive), `points` ≥ 2 of them.
pub fn log_space(from: f64, to: f64, points: usize) -> Vec<f64> {
    let n = points.max(2);
    let (a, b) = (from.log10(), to.log10());
    (0..n)
        .map(|k| 10f64.powf(a + (b - a) * k as f64 / (n - 1) as f64))
        .collect()
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
    progress: &mut dyn FnMut(&str),
) -> Result<Sweep> {
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
        budget::check(&model, &Method::qp(), problem.memory_limit)?;
        let ops = Operators::assemble(&model);
        solve::check_feasible(&ops)?;
        progress(&format!("{}: QP reference", kind.name()));
        let t = Instant::now();
        let q = solve::solve(&ops, &Method::qp())?;
        qp_time_s.push((kind.name(), t.elapsed().as_secs_f64()));
        if !q.status.converged() {
            return Err(Error::numerical("QP reference", q.status.describe()));
        }
        let (vq, sq) = fields(&ops, &model, &q);
        for &eps in epsilons {
            progress(&format!("{}: penalty ε̄ = {eps:.1e}", kind.name()));
            let t = Instant::now();
            let r = solve::solve(
                &ops,
                &Method::Penalty(PenaltySettings {
                    max_iterations,
                    ..PenaltySettings::fixed(eps)
                }),
            );
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
                        status: sol.status.kind().into(),
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
                    status: e.kind().into(),
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
                    && (r.status == "converged" || r.status == "penalty-too-weak")
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
                    (!adequate_only || r.status == "converged")
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

/// One point of the speed–accuracy chart.
#[derive(Debug, Clone, Serialize)]
pub struct TradeoffPoint {
    /// "penalty" or "qp".
    pub method: &'static str,
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
    pub status: String,
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
    let ny = if ny % 2 == 1 && n % 2 == 0 {
        ny + 1
    } else {
        ny
    };
    m.elements = [n, ny];
    m
}

/// A tradeoff point from a solve that ran, or from the error that stopped it.
fn tradeoff_point(
    method: &'static str,
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
            status: sol.status.kind().into(),
            pareto: false,
        },
        Err(e) => TradeoffPoint {
            method,
            mesh,
            eps,
            time_s,
            error: f64::NAN,
            converged: false,
            status: e.kind().into(),
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
    progress: &mut dyn FnMut(&str),
) -> Result<Tradeoff> {
    let finest = meshes
        .iter()
        .copied()
        .max()
        .ok_or_else(|| Error::invalid("meshes", "give at least one mesh"))?;
    let limit = problem.memory_limit;
    let qp = Method::qp();
    let reference_at = |n: usize| -> Result<Vec<f64>> {
        let model = with_mesh(&problem.model, n);
        budget::check(&model, &qp, limit)?;
        let ops = Operators::assemble(&model);
        let sol = solve::solve(&ops, &qp)?;
        Ok(sample_v(&model, &ops, &sol))
    };
    progress(&format!(
        "reference: QP at {} elements per side",
        2 * finest
    ));
    let (reference, v_ref) = match reference_at(2 * finest) {
        Ok(v) => (
            format!(
                "QP on {} elements per side (twice the finest mesh)",
                2 * finest
            ),
            v,
        ),
        Err(Error::TooLarge { .. }) => {
            progress(&format!(
                "reference at {} does not fit; using the QP at {finest}",
                2 * finest
            ));
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
        let ops = Operators::assemble(&model);
        let assemble_s = t.elapsed().as_secs_f64();
        let run = |method: &Method, eps: f64| -> TradeoffPoint {
            let t = Instant::now();
            let sol = budget::check(&model, method, limit).and_then(|_| solve::solve(&ops, method));
            let time_s = assemble_s + t.elapsed().as_secs_f64();
            let outcome = sol
                .as_ref()
                .map(|sol| (rel_l2(&sample_v(&model, &ops, sol), &v_ref), sol));
            tradeoff_point(method.name(), n, eps, time_s, outcome)
        };
        progress(&format!("QP at {n}"));
        points.push(run(&qp, f64::NAN));
        for &eps in penalties {
            progress(&format!("penalty at {n}, ε̄ = {eps:.0e}"));
            let method = Method::Penalty(PenaltySettings {
                max_iterations,
                ..PenaltySettings::fixed(eps)
            });
            points.push(run(&method, eps));
        }
    }
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

/// The parameter a stability sweep varies around the base case.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum StabilityParam {
    /// Γ (plate-to-foundation stiffness).
    Gamma,
    /// ε̄ (penalty only).
    Penalty,
    /// A single point load at (s, s).
    Position,
    /// μ = width / length.
    Mu,
    /// Elements per side.
    Mesh,
}

crate::names!(StabilityParam, Gamma => "gamma", Penalty => "penalty", Position => "position", Mu => "mu", Mesh => "mesh");

impl StabilityParam {
    /// Every parameter, in the order of the CSV and the maps.
    pub const ALL: [StabilityParam; 5] = [
        StabilityParam::Gamma,
        StabilityParam::Penalty,
        StabilityParam::Position,
        StabilityParam::Mu,
        StabilityParam::Mesh,
    ];

    /// The values swept around the paper's base case (Γ = 0.25e-3, ε̄ = 1e-5, central point
    /// load, μ = 1, 16 × 16 elements).
    pub fn values(self, foundation: FoundationKind) -> Vec<f64> {
        match self {
            StabilityParam::Gamma => log_space(1e-10, 1e8, 10),
            StabilityParam::Penalty => log_space(1e-2, 1e-14, 13),
            StabilityParam::Position => vec![0.0, 0.25, 0.5, 0.75, 0.9, 1.0],
            StabilityParam::Mu => vec![0.1, 0.25, 0.5, 0.75, 1.0],
            StabilityParam::Mesh => match foundation {
                // Winkler: sparse penalty up to 512 per side; the dense QP is refused beyond
                // its limit.
                FoundationKind::Winkler => vec![8.0, 16.0, 32.0, 64.0, 128.0, 256.0, 512.0],
                // Half-space: dense for both methods; 512 per side is beyond memory for both.
                FoundationKind::HalfSpace => vec![8.0, 16.0, 32.0, 64.0, 128.0, 512.0],
            },
        }
    }

    /// The methods this parameter applies to (ε̄ is the penalty's alone).
    pub fn methods(self) -> &'static [MethodKind] {
        match self {
            StabilityParam::Penalty => &[MethodKind::Penalty],
            _ => &[MethodKind::Penalty, MethodKind::Qp],
        }
    }
}

/// One planned run of the stability sweep.
#[derive(Debug, Clone, Copy)]
pub struct StabilityCase<'a> {
    /// The base problem.
    pub base: &'a Problem,
    /// The swept parameter.
    pub param: StabilityParam,
    /// Its value.
    pub value: f64,
    /// The method.
    pub method: MethodKind,
}

/// Every run of `liftoff stability` over the base problems.
pub fn stability_plan(bases: &[Problem]) -> Vec<StabilityCase<'_>> {
    let mut plan = Vec::new();
    for base in bases {
        for param in StabilityParam::ALL {
            for value in param.values(base.model.groups.foundation) {
                for &method in param.methods() {
                    plan.push(StabilityCase {
                        base,
                        param,
                        value,
                        method,
                    });
                }
            }
        }
    }
    plan
}

/// One run of the stability sweep.
#[derive(Debug, Clone, Serialize)]
pub struct StabilityRow {
    /// Which parameter is swept.
    pub sweep: StabilityParam,
    /// Foundation.
    pub foundation: &'static str,
    /// Method.
    pub method: &'static str,
    /// Value of the swept parameter.
    pub value: f64,
    /// Outcome kind: converged, cycling, iteration-limit, penalty-too-weak, solver-failure,
    /// infeasible, too-large, numerical.
    pub outcome: String,
    /// Iterations (penalty steps or interior-point iterations).
    pub iterations: usize,
    /// |reaction − load| / load.
    pub equilibrium: f64,
    /// Minimum σ at the constraint points.
    pub min_pressure: f64,
    /// Minimum nodal gap (V units).
    pub min_gap: f64,
    /// Contact fraction.
    pub contact_fraction: f64,
    /// Wall time, s.
    pub time_s: f64,
    /// Error or status text.
    pub detail: String,
}

/// Run one configuration of the stability sweep. For the position sweep the loads are replaced
/// by one point load at (s, s).
pub fn stability_run(case: &StabilityCase<'_>) -> StabilityRow {
    let value = case.value;
    let mut model = case.base.model.clone();
    let mut method = match (case.method, &case.base.method) {
        (MethodKind::Penalty, Method::Penalty(s)) => Method::Penalty(*s),
        (kind, _) => Method::unbonded(kind),
    };
    match case.param {
        StabilityParam::Gamma => model.groups.gamma = value,
        StabilityParam::Penalty => {
            if let Method::Penalty(s) = &mut method {
                s.epsilon = value;
            }
        }
        StabilityParam::Position => {
            let mu = model.groups.mu;
            model.loads = vec![Load::Point {
                x: value,
                y: value * mu,
                force: 4.0,
            }];
        }
        StabilityParam::Mu => {
            // Keep the load where it was in (s, t): rescale y.
            let old = model.groups.mu;
            model.groups.mu = value;
            for l in &mut model.loads {
                if let Load::Point { y, .. } = l {
                    *y *= value / old;
                }
            }
        }
        StabilityParam::Mesh => {
            let n = value as usize;
            model.elements = [n, n];
        }
    }
    let foundation = model.groups.foundation.name();
    let t = Instant::now();
    let result = budget::check(&model, &method, case.base.memory_limit).and_then(|_| {
        let ops = Operators::assemble(&model);
        let sol = solve::solve(&ops, &method)?;
        let rep = post::report(&model, &ops, &sol);
        Ok((sol, rep))
    });
    let time_s = t.elapsed().as_secs_f64();
    let (sweep, method) = (case.param, case.method.name());
    match result {
        Ok((sol, rep)) => StabilityRow {
            sweep,
            foundation,
            method,
            value,
            outcome: sol.status.kind().into(),
            iterations: sol.iterations,
            equilibrium: rep.resultant.relative_error,
            min_pressure: rep.complementarity.min_pressure,
            min_gap: rep.complementarity.min_gap,
            contact_fraction: rep.contact_fraction,
            time_s,
            detail: sol.status.describe(),
        },
        Err(e) => StabilityRow {
            sweep,
            foundation,
            method,
            value,
            outcome: e.kind().into(),
            iterations: 0,
            equilibrium: f64::NAN,
            min_pressure: f64::NAN,
            min_gap: f64::NAN,
            contact_fraction: f64::NAN,
            time_s,
            detail: e.to_string(),
        },
    }
}
