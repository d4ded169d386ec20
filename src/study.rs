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
            // The sweep studies a fixed ε̄, as in the paper.
            if let Method::Penalty(s) = &mut method {
                s.epsilon = value;
                s.auto = false;
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

/// Run every case of a stability plan in order; `progress` receives one line before each run.
pub fn stability_sweep(
    plan: &[StabilityCase<'_>],
    progress: &mut dyn FnMut(&str),
) -> Vec<StabilityRow> {
    plan.iter()
        .map(|case| {
            progress(&format!(
                "{} {} = {:.2e} ({})",
                case.base.model.groups.foundation.name(),
                case.param.name(),
                case.value,
                case.method.name()
            ));
            stability_run(case)
        })
        .collect()
}

/// Which constraint points an ε̄ sweep compares; each kind gets its own assembly and QP
/// reference.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum ConstraintVariants {
    /// σ ≥ 0 at the nodes.
    #[default]
    Nodal,
    /// σ ≥ 0 at the Gauss points.
    Gauss,
    /// Nodal, then Gauss.
    Both,
}

crate::names!(ConstraintVariants, Nodal => "nodal", Gauss => "gauss", Both => "both");

impl ConstraintVariants {
    /// The constraint points swept, in order.
    pub fn points(self) -> &'static [ConstraintPoints] {
        match self {
            ConstraintVariants::Nodal => &[ConstraintPoints::Nodal],
            ConstraintVariants::Gauss => &[ConstraintPoints::Gauss],
            ConstraintVariants::Both => &[ConstraintPoints::Nodal, ConstraintPoints::Gauss],
        }
    }
}

/// Options of an ε̄ sweep ([`eps_sweep`]): which ε̄ and which constraint points. Field names
/// are the names of the errors [`EpsSweepOptions::validate`] returns.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EpsSweepOptions {
    /// Largest ε̄, in (0, 1).
    pub from: f64,
    /// Smallest ε̄, in (0, 1).
    pub to: f64,
    /// Number of log-spaced ε̄ values from `from` to `to`, 2..=[`EpsSweepOptions::MAX_POINTS`].
    pub points: usize,
    /// Constraint points.
    pub constraints: ConstraintVariants,
}

impl Default for EpsSweepOptions {
    fn default() -> Self {
        Self {
            from: 1e-1,
            to: 1e-12,
            points: 12,
            constraints: ConstraintVariants::Nodal,
        }
    }
}

impl EpsSweepOptions {
    /// Most ε̄ values one sweep takes.
    pub const MAX_POINTS: usize = 200;

    /// Check the options; an [`Error::Invalid`] names the offending field.
    pub fn validate(&self) -> Result<()> {
        for (field, eps) in [("from", self.from), ("to", self.to)] {
            if !(eps.is_finite() && eps > 0.0 && eps < 1.0) {
                return Err(Error::invalid(
                    field,
                    format!("must be a positive ε̄ below 1, got {eps}"),
                ));
            }
        }
        if !(2..=Self::MAX_POINTS).contains(&self.points) {
            return Err(Error::invalid(
                "points",
                format!("must lie in 2..={}, got {}", Self::MAX_POINTS, self.points),
            ));
        }
        Ok(())
    }

    /// The ε̄ values, log-spaced from `from` to `to`.
    pub fn epsilons(&self) -> Vec<f64> {
        log_space(self.from, self.to, self.points)
    }

    /// The ε̄ window [lo, hi] the slope fit may use: the whole sweep.
    pub fn fit_window(&self) -> [f64; 2] {
        [self.to.min(self.from), self.from.max(self.to)]
    }

    /// How many progress lines [`EpsSweepOptions::run`] sends: one QP reference and one line
    /// per ε̄, per constraint kind.
    pub fn progress_steps(&self) -> usize {
        self.constraints.points().len() * (self.points + 1)
    }

    /// Validate, then run [`eps_sweep`] on `problem`.
    pub fn run(&self, problem: &Problem, progress: &mut dyn FnMut(&str)) -> Result<Sweep> {
        self.validate()?;
        eps_sweep(
            problem,
            &self.epsilons(),
            self.constraints.points(),
            self.fit_window(),
            progress,
        )
    }
}

/// Options of a speed–accuracy study ([`tradeoff`]). Field names are the names of the errors
/// [`TradeoffOptions::validate`] returns.
#[derive(Debug, Clone, PartialEq)]
pub struct TradeoffOptions {
    /// Elements per side of the whole plate along x (y follows μ), each in
    /// [`TradeoffOptions::MESH_RANGE`]; at least one.
    pub meshes: Vec<usize>,
    /// ε̄ values of the penalty method, each in (0, 1).
    pub penalties: Vec<f64>,
}

impl Default for TradeoffOptions {
    fn default() -> Self {
        Self {
            meshes: vec![8, 16, 32, 64],
            penalties: vec![1e-2, 1e-4, 1e-6, 1e-8],
        }
    }
}

impl TradeoffOptions {
    /// Element counts per side a tradeoff mesh may have.
    pub const MESH_RANGE: std::ops::RangeInclusive<usize> = 2..=2048;

    /// Check the options; an [`Error::Invalid`] names the offending field.
    pub fn validate(&self) -> Result<()> {
        if self.meshes.is_empty() || self.meshes.iter().any(|n| !Self::MESH_RANGE.contains(n)) {
            return Err(Error::invalid(
                "meshes",
                format!(
                    "takes element counts between {} and {}",
                    Self::MESH_RANGE.start(),
                    Self::MESH_RANGE.end()
                ),
            ));
        }
        if self.penalties.iter().any(|&e| !(e > 0.0 && e < 1.0)) {
            return Err(Error::invalid("penalties", "takes ε̄ values in (0, 1)"));
        }
        Ok(())
    }

    /// How many progress lines [`TradeoffOptions::run`] sends when the reference fits: one for
    /// the reference, then per mesh one for the QP and one per ε̄ (one more if the reference
    /// falls back to the finest mesh).
    pub fn progress_steps(&self) -> usize {
        1 + self.meshes.len() * (1 + self.penalties.len())
    }

    /// Validate, then run [`tradeoff`] on `problem`.
    pub fn run(&self, problem: &Problem, progress: &mut dyn FnMut(&str)) -> Result<Tradeoff> {
        self.validate()?;
        tradeoff(problem, &self.meshes, &self.penalties, progress)
    }
}

#[cfg(test)]
mod options_tests {
    use super::*;

    fn field_of(r: Result<()>) -> Option<String> {
        match r {
            Err(Error::Invalid { field, .. }) => Some(field),
            _ => None,
        }
    }

    /// The defaults are valid and give the documented sweep: 12 values from 1e-1 to 1e-12,
    /// one decade apart (log10 steps of (−12 + 1)/11 = −1).
    #[test]
    fn eps_sweep_defaults_are_valid_and_one_decade_apart() {
        let o = EpsSweepOptions::default();
        assert!(o.validate().is_ok(), "EpsSweepOptions::default validates");
        let eps = o.epsilons();
        assert_eq!(eps.len(), 12, "EpsSweepOptions::default: 12 values");
        for (k, e) in eps.iter().enumerate() {
            let want = 10f64.powi(-1 - k as i32);
            // log_space evaluates 10^(a + (b − a)k/(n − 1)) in floating point: a few ulps.
            assert!(
                (e / want - 1.0).abs() < 1e-12,
                "EpsSweepOptions::epsilons[{k}] = {e}, want {want}"
            );
        }
        assert_eq!(o.fit_window(), [1e-12, 1e-1], "EpsSweepOptions::fit_window");
        assert_eq!(
            o.progress_steps(),
            13,
            "EpsSweepOptions::progress_steps, nodal"
        );
    }

    /// Each out-of-range value is refused with the field that holds it.
    #[test]
    fn eps_sweep_options_name_the_bad_field() {
        let base = EpsSweepOptions::default();
        let cases = [
            (EpsSweepOptions { from: 1.0, ..base }, "from"),
            (
                EpsSweepOptions {
                    from: f64::NAN,
                    ..base
                },
                "from",
            ),
            (EpsSweepOptions { to: 0.0, ..base }, "to"),
            (EpsSweepOptions { to: 2.0, ..base }, "to"),
            (
                EpsSweepOptions {
                    to: f64::INFINITY,
                    ..base
                },
                "to",
            ),
            (EpsSweepOptions { points: 1, ..base }, "points"),
            (
                EpsSweepOptions {
                    points: 201,
                    ..base
                },
                "points",
            ),
        ];
        for (o, field) in cases {
            assert_eq!(
                field_of(o.validate()).as_deref(),
                Some(field),
                "EpsSweepOptions::validate({o:?})"
            );
        }
        let edge = EpsSweepOptions {
            points: 200,
            constraints: ConstraintVariants::Both,
            ..base
        };
        assert!(edge.validate().is_ok(), "200 points are allowed");
        assert_eq!(edge.progress_steps(), 2 * 201, "two kinds × (QP + 200 ε̄)");
    }

    #[test]
    fn constraint_variants_list_their_points() {
        assert_eq!(
            ConstraintVariants::Nodal.points(),
            &[ConstraintPoints::Nodal]
        );
        assert_eq!(
            ConstraintVariants::Gauss.points(),
            &[ConstraintPoints::Gauss]
        );
        assert_eq!(
            ConstraintVariants::Both.points(),
            &[ConstraintPoints::Nodal, ConstraintPoints::Gauss]
        );
    }

    #[test]
    fn tradeoff_options_name_the_bad_field() {
        assert!(
            TradeoffOptions::default().validate().is_ok(),
            "TradeoffOptions::default validates"
        );
        let with = |meshes: Vec<usize>, penalties: Vec<f64>| TradeoffOptions { meshes, penalties };
        let cases = [
            (with(vec![], vec![1e-5]), "meshes"),
            (with(vec![1], vec![1e-5]), "meshes"),
            (with(vec![8, 2049], vec![1e-5]), "meshes"),
            (with(vec![8], vec![1.0]), "penalties"),
            (with(vec![8], vec![0.0]), "penalties"),
            (with(vec![8], vec![1e-3, f64::NAN]), "penalties"),
        ];
        for (o, field) in cases {
            assert_eq!(
                field_of(o.validate()).as_deref(),
                Some(field),
                "TradeoffOptions::validate({o:?})"
            );
        }
        let ok = with(vec![2, 2048], vec![]);
        assert!(
            ok.validate().is_ok(),
            "mesh range ends and no ε̄ are allowed"
        );
        assert_eq!(ok.progress_steps(), 3, "reference + one QP per mesh");
    }
}
