//! A slab fully in contact on Winkler soil, solved without the plate's own factor: where the
//! bonded answer from the plate on springs ([`bonded_from_springs`]) has no tension and closes
//! every gap, it satisfies the unilateral conditions and is the QP's unique solution. The
//! active-set iteration would reach it in one face solve, but only after factoring the plate
//! alone as well (for h = BᵀK⁻f and its products with S); this costs what the penalty's first
//! step costs, one factorisation.

use std::time::Instant;

use crate::error::Result;
use crate::method::{CgSettings, Method, QpSettings, QpSolver};
use crate::monitor::{Monitor, Progress, StepKind};
use crate::operators::Operators;
use crate::solve::checks::discrete_gap;
use crate::solve::diagnostics::{ActiveSetDiagnostics, KktResiduals};
use crate::solve::iterative::{bonded_from_springs, BondedBySprings};
use crate::solve::linalg::finite;
use crate::solve::solution::{Iteration, Solution, SolveInfo, Status, Timings};

/// What trying the bonded answer gave.
pub(super) enum Tried {
    /// The QP's solution.
    Solved(Box<Solution>),
    /// Not a solution (a point in tension, a gap the solve did not close to the tolerance) or
    /// not tried (another soil): the active-set iteration follows; `factored` says whether the
    /// plate on springs was factored for the try (it is the iteration's first preconditioner).
    NotInContact { factored: bool },
}

/// The QP's solution when the bonded answer from the plate on springs is one (see the module
/// notes), with the KKT residuals measured on it.
pub(super) fn solve(
    ops: &Operators,
    settings: &QpSettings,
    cg: CgSettings,
    t0: Instant,
    monitor: &Monitor<'_>,
) -> Result<Tried> {
    monitor.check("the matrix-free QP")?;
    let b = match bonded_from_springs(ops, cg)? {
        Ok(b) => b,
        Err(factored) => return Ok(Tried::NotInContact { factored }),
    };
    finite(&b.u, "matrix-free QP")?;
    let t_setup = t0.elapsed().as_secs_f64();
    let gap = discrete_gap(ops, &b.u, &b.sigma);
    let kkt = residuals(ops, &b, &gap);
    // The iteration's own stopping test (the natural residual), and a closed gap at every
    // point: all are in contact.
    let tol = settings.active_set.tolerance;
    if !(kkt.natural <= tol && kkt.stationarity <= tol && kkt.equilibrium <= tol) {
        return Ok(Tried::NotInContact {
            factored: b.factored,
        });
    }
    let min_pressure = b.sigma.iter().cloned().fold(f64::INFINITY, f64::min);
    let history = vec![Iteration {
        step: 1,
        epsilon: 0.0,
        penalised: 0,
        entered: 0,
        left: 0,
        min_pressure,
        cg: None,
    }];
    monitor.report(Progress::Step {
        method: StepKind::ActiveSet,
        step: 1,
        changes: 0,
    });
    let diagnostics = ActiveSetDiagnostics {
        iterations: 1,
        cg_iterations: 0,
        products: 0,
        factorisations: usize::from(b.factored),
        safeguard_steps: 0,
        projected_steps: 0,
        objective: None,
        kkt,
    };
    let total = t0.elapsed().as_secs_f64();
    Ok(Tried::Solved(Box::new(Solution {
        method: Method::Qp(QpSettings {
            solver: QpSolver::ActiveSet,
            ..settings.clone()
        }),
        u: b.u,
        sigma: b.sigma,
        gap,
        rigid: b.alpha,
        status: Status::Converged,
        iterations: 1,
        history,
        info: SolveInfo {
            timings: Timings {
                setup: Some(t_setup),
                solves: Some(total - t_setup),
                total,
                ..Timings::default()
            },
            cg_iterations: Some(0),
            active_set: Some(diagnostics),
            notes: vec![
                "fully in contact: the bonded answer of the plate on its springs has no tension, so it is the unilateral solution (one factorisation; the plate's own factor was not needed)".into(),
            ],
            ..SolveInfo::default()
        },
    })))
}

/// The KKT residuals of a bonded answer: as the iteration's ([`super::point`]), with the gap
/// g = Tσ − Bᵀu + g₀ measured from the displacements and its scale g_s the largest of the
/// terms it is made of, |Tσ|, |Bᵀu| and |g₀|.
fn residuals(ops: &Operators, b: &BondedBySprings, gap: &[f64]) -> KktResiduals {
    let inf = |v: &[f64]| v.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    let g_s = inf(&ops.t.apply(&b.sigma))
        .max(inf(&ops.bt_times(&b.u)))
        .max(inf(&ops.gap0))
        .max(f64::MIN_POSITIVE);
    super::point::residuals(&b.sigma, gap, g_s, &b.c, &b.rf)
}
