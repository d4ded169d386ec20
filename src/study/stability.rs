//! The regimes where each method breaks (`stability`): one parameter at a time swept around a
//! base case.

use std::time::Instant;

use serde::Serialize;

use super::log_space;
use super::RunOutcome;
use crate::error::Result;
use crate::foundation::FoundationKind;
use crate::method::{Method, MethodKind, PenaltySettings};
use crate::model::Load;
use crate::monitor::{Cases, Monitor};
use crate::post;
use crate::scene::Problem;
use crate::solve;

/// The parameter a stability sweep varies around the base case.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum StabilityParam {
    /// Γ (plate-to-foundation stiffness).
    Gamma,
    /// Γ again, on the iterative route (T by FFT, conjugate gradients: what meshes beyond
    /// 1 500 pressure nodes take) at [`ITERATIVE_MESH`] elements per side.
    GammaIterative,
    /// ε̄ (penalty only).
    Penalty,
    /// A single point load at (s, s).
    Position,
    /// μ = width / length.
    Mu,
    /// Elements per side.
    Mesh,
}

crate::choice::names!(StabilityParam, Gamma => "gamma", GammaIterative => "gamma-iterative", Penalty => "penalty", Position => "position", Mu => "mu", Mesh => "mesh");

impl StabilityParam {
    /// Every parameter, in the order of the CSV and the maps.
    pub const ALL: [StabilityParam; 6] = [
        StabilityParam::Gamma,
        StabilityParam::GammaIterative,
        StabilityParam::Penalty,
        StabilityParam::Position,
        StabilityParam::Mu,
        StabilityParam::Mesh,
    ];

    /// The values swept around the paper's base case (Γ = 0.25e-3, ε̄ = 1e-5, central point
    /// load, μ = 1, 16 × 16 elements).
    pub fn values(self, foundation: FoundationKind) -> Vec<f64> {
        match self {
            // From nearly membranes (a steel tank bottom on sand is Γ ≈ 1e-9) to nearly rigid
            // plates, two decades beyond each end of the paper's range.
            StabilityParam::Gamma | StabilityParam::GammaIterative => log_space(1e-12, 1e10, 12),
            StabilityParam::Penalty => log_space(1e-2, 1e-14, 13),
            StabilityParam::Position => vec![0.0, 0.25, 0.5, 0.75, 0.9, 1.0],
            StabilityParam::Mu => vec![0.1, 0.25, 0.5, 0.75, 1.0],
            StabilityParam::Mesh => foundation.stability_meshes(),
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

/// The bundled base scenes of `liftoff stability` without scenes of its own, one per soil: the
/// paper's plate on Winkler springs and the half-space, the slab-on-grade bay on the Pasternak
/// soil, the elastic layer and Reissner's (Kerr) layer.
pub const DEFAULT_BASES: [&str; 5] = [
    "paper-winkler",
    "paper-halfspace",
    "slab-pasternak",
    "slab-clay-layer",
    "slab-kerr",
];

/// Elements per side of the Γ sweep on the iterative route: large enough for the coarse
/// preconditioner plate and the nested start to take part (64 per side, a quarter model of
/// 33 × 33 nodes), small enough for a map of runs.
pub const ITERATIVE_MESH: usize = 64;

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
            for value in param.values(base.model.groups.foundation()) {
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
    pub foundation: FoundationKind,
    /// Method.
    pub method: MethodKind,
    /// Value of the swept parameter.
    pub value: f64,
    /// Outcome kind: converged, cycling, iteration-limit, penalty-too-weak, solver-failure,
    /// infeasible, too-large, numerical.
    pub outcome: RunOutcome,
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
        // The map shows what a user gets by default: the automatic ε̄ from the scene's ε̄ (the
        // ε̄ sweep itself fixes ε̄ below).
        (MethodKind::Penalty, Method::Penalty(s)) => {
            Method::Penalty(PenaltySettings { auto: true, ..*s })
        }
        (kind, _) => Method::unbonded(kind),
    };
    match case.param {
        StabilityParam::Gamma => model.groups.gamma = value,
        StabilityParam::GammaIterative => {
            model.groups.gamma = value;
            model.elements = [ITERATIVE_MESH, ITERATIVE_MESH];
        }
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
    let foundation = model.groups.foundation();
    let t = Instant::now();
    let route = if case.param == StabilityParam::GammaIterative {
        crate::method::Route::Iterative
    } else {
        crate::method::Route::Auto
    };
    let result =
        crate::analysis::prepare(&model, &method, route, case.base.memory_limit).and_then(|ops| {
            // As a user's solve runs: from the coarser grid's answer where the method's start is
            // nested (the default), so the map shows the default path's failures.
            let sol = solve::solve_nested(&model, &ops, &method, &crate::monitor::Monitor::NONE)?;
            let rep = post::report(&model, &ops, &sol);
            Ok((sol, rep))
        });
    let time_s = t.elapsed().as_secs_f64();
    let (sweep, method) = (case.param, case.method);
    match result {
        Ok((sol, rep)) => StabilityRow {
            sweep,
            foundation,
            method,
            value,
            outcome: RunOutcome::Solved(sol.status.kind()),
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
            outcome: RunOutcome::Failed(e.kind()),
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

/// Run every case of a stability plan in order; `monitor` hears of each run before it starts
/// and can stop the sweep between runs.
pub fn stability_sweep(
    plan: &[StabilityCase<'_>],
    monitor: &Monitor<'_>,
) -> Result<Vec<StabilityRow>> {
    let cases = Cases::new(monitor, plan.len());
    plan.iter()
        .map(|case| {
            cases.start(&format!(
                "{} {} = {:.2e} ({})",
                case.base.model.groups.foundation().name(),
                case.param.name(),
                case.value,
                case.method.name()
            ))?;
            Ok(stability_run(case))
        })
        .collect()
}
