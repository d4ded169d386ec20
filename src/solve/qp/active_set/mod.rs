//! The unbonded QP without any dense matrix: a primal–dual active-set method with a monotone
//! safeguard, its inner solves by projected PCG through the operators ([`crate::solve::iterative`]).
//!
//! The problem is the QP of [`super::clarabel_dense`] with nodal constraints,
//!
//! min f(σ) = ½ σᵀSσ − hᵀσ   subject to   Cᵀσ = Rᵀf,   σ ≥ 0,
//!
//! S = T + BᵀK⁻B applied as one product with T (diagonal, dense, or by FFT) and one solve with
//! the plate factor — S is never formed. Its KKT conditions are the discrete unilateral
//! conditions: with α the rigid-body amplitudes, the gap g = Sσ − h − Cα satisfies g ≥ 0,
//! σ·g = 0.
//!
//! **The iteration.** Two phases, both on face solves ([`IterativeSchur::solve_face`]: f
//! minimised on the equilibrium with a held set of points at zero, warm-started).
//! 1. *Primal–dual active set* (semismooth Newton on the natural residual): from the feasible
//!    point nearest σ = 0, hold the points at zero whose gap does not close, solve the face,
//!    then hold the free points whose pressure came out negative and release the held points
//!    whose gap came out negative. It is the penalty iteration with ε̄ = 0 — "solve, then lift
//!    the points in tension, put back those that penetrate" — and takes as few steps. Face
//!    solves are loose (the set only has to be found), 100× tighter each time the sets wander
//!    (a solve that could not move σ, a set met before), tight when a set repeats. When the
//!    set repeats after a tight solve, σ* is the solution.
//! 2. *Safeguard*: on a matrix that is not an M-matrix (neither the 1/r flexibility nor the
//!    plate is one) that update can cycle, like the penalty iteration. A set met before hands
//!    over to a primal active-set method on feasible points (σ ≥ 0 and on the equilibrium)
//!    with a ratio test ([`Run::feasible`]): f falls at every step, so no set can return and
//!    the iteration ends in finitely many steps, each a tight face solve.
//!
//! It stops when the KKT conditions hold to the tolerance: |min(σᵢ/σ_max, gᵢ/g_s)| ≤ τ at every
//! point (the natural residual, g_s the largest of |Tσ|, |Sσ|, |h| and |Cα|, the terms of g) —
//! exact complementarity to solver tolerance, no ε̄. Where the points in contact do not fix the
//! rigid modes (a plate balanced on one node), α is the face's multiplier, or the smallest turn
//! that keeps every lifted point above the soil ([`point`]).
//!
//! **Preconditioner.** On Winkler soil T is diagonal and the coupling lumped, so the
//! preconditioner of the iterative route, M = D + QᵀK⁻Q, with D = T and the model's own plate
//! is S itself: each face solve is one sparse factorisation of the plate on springs at the
//! free points (exactly a penalty step's) and a CG iteration or two for the equilibrium. On
//! the half-space (dense or FFT) it is the iterative route's coarse plate on λ·diag(T).
//!
//! **A slab fully in contact** on Winkler soil needs no iteration and no plate factor: the
//! bonded answer of the plate on springs (the bonded preconditioner's factor, from which σ, α
//! and u follow by Woodbury identities, [`crate::solve::iterative::bonded_from_springs`]) is
//! tried first; where it has no tension and closes every gap to the tolerance it is the
//! solution ([`full_contact`]), at the penalty's cost of one factorisation. Otherwise its
//! factor is the first face's preconditioner, and the plate alone is factored for S.
//!
//! **The projection** onto {σ ≥ 0, Cᵀσ = b} ([`project`]) is σ = max(0, y + Cλ) with λ (one value per rigid
//! mode) the maximiser of the concave dual −½|max(0, y + Cλ)|² + bᵀλ; Newton on λ with a line
//! search, m unknowns (three for a plate of one piece, the zero-energy modes of a jointed one).

mod full_contact;
mod point;
mod primal_dual;
mod run;
mod safeguard;

pub use crate::solve::projection::project;

use std::time::Instant;

use crate::error::{Error, Result};
use crate::foundation::Compliance;
use crate::method::{CgSettings, Method, QpSettings, QpSolver};
use crate::model::ConstraintPoints;
use crate::monitor::Monitor;
use crate::operators::Operators;
use crate::solve::checks::discrete_gap;
use crate::solve::diagnostics::ActiveSetDiagnostics;
use crate::solve::iterative::IterativeSchur;
use crate::solve::linalg::finite;
use crate::solve::solution::{Solution, SolveInfo, Timings};
use run::Run;

/// Solve the unbonded QP by the matrix-free active-set method, from `start` when given
/// (pressures at the nodes, e.g. a coarser grid's solution carried over: the first set is the
/// points it leaves at zero), else from the feasible point nearest σ = 0.
pub fn solve(ops: &Operators, settings: &QpSettings, start: Option<&[f64]>) -> Result<Solution> {
    solve_with(ops, settings, start, &Monitor::NONE)
}

/// [`solve`], watched by `monitor`: a progress event after every face solve, the cancel flag
/// checked before each and inside its conjugate gradients.
pub fn solve_with(
    ops: &Operators,
    settings: &QpSettings,
    start: Option<&[f64]>,
    monitor: &Monitor<'_>,
) -> Result<Solution> {
    let t0 = Instant::now();
    if ops.constraints.kind != ConstraintPoints::Nodal {
        return Err(Error::invalid(
            "solver.qp_solver",
            "the active-set QP imposes σ ≥ 0 at the nodes; with constraint = \"gauss\" use qp_solver = \"clarabel\" (or \"auto\"), or nodal constraints",
        ));
    }
    let s = settings.active_set;
    // On Winkler soil the iterative route's preconditioner with the springs T and the model's
    // own plate is S itself.
    let cg = match ops.t.as_ref() {
        Compliance::Diagonal(_) => CgSettings {
            spring_scale: 1.0,
            coarse_plate: false,
            ..s.cg
        },
        Compliance::Dense(_) | Compliance::Toeplitz(_) => s.cg,
    };
    // A slab fully in contact on Winkler soil: the bonded answer from the plate on springs has
    // no tension, so it is the solution — one factorisation, as the penalty's first step.
    // Otherwise its factor (counted here when it made it) is the first face's preconditioner.
    // A start with lifted points (a coarser grid's answer, a neighbour's) says the slab lifts:
    // then the plate's own factor is made beside the bonded preconditioner, one on each core.
    let lifts = start.is_some_and(|s| s.len() == ops.n_sigma() && s.iter().any(|&x| x <= 0.0));
    let tried = if lifts {
        0
    } else {
        match full_contact::solve(ops, settings, cg, t0, monitor)? {
            full_contact::Tried::Solved(solution) => return Ok(*solution),
            full_contact::Tried::NotInContact { factored } => usize::from(factored),
        }
    };
    let mut sys = IterativeSchur::with_any_compliance(ops, cg)?;
    let t_setup = t0.elapsed().as_secs_f64();
    let mut run = Run::new(s, *monitor);
    let end = match run.primal_dual(&mut sys, ops, start)? {
        Ok(end) => end,
        Err(last) => run.feasible(&mut sys, ops, &last)?,
    };
    let (point, alpha, residuals, status) = end;
    let sigma = point.sigma;
    let u = sys.displacements(ops, &sigma, &alpha);
    finite(&u, "matrix-free QP")?;
    let gap = discrete_gap(ops, &u, &sigma);
    let diagnostics = ActiveSetDiagnostics {
        iterations: run.iterations,
        cg_iterations: run.cg_total,
        products: sys.products,
        factorisations: sys.factorisations + tried,
        safeguard_steps: run.safeguard_steps,
        projected_steps: run.projected_steps,
        objective: Some(point.f),
        kkt: residuals,
    };
    let total = t0.elapsed().as_secs_f64();
    Ok(Solution {
        method: Method::Qp(QpSettings {
            solver: QpSolver::ActiveSet,
            ..settings.clone()
        }),
        u,
        sigma,
        gap,
        rigid: alpha,
        status,
        iterations: run.iterations,
        history: run.history,
        info: SolveInfo {
            timings: Timings {
                plate_factor: Some(sys.time_plate),
                setup: Some(t_setup - sys.time_plate),
                solves: Some(total - t_setup),
                total,
                ..Timings::default()
            },
            cg_iterations: Some(run.cg_total),
            active_set: Some(diagnostics),
            ..SolveInfo::default()
        },
    })
}
