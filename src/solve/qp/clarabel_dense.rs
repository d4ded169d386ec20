//! The unbonded problem as a convex QP in the contact pressures, solved by clarabel.
//!
//! With K⁻ a generalised inverse of the free plate, R its rigid modes, S = T + BᵀK⁻B,
//! h = BᵀK⁻f and C = BᵀR:
//!
//! min ½ σᵀSσ − hᵀσ   subject to   Cᵀσ = Rᵀf  (rigid-body equilibrium),   Gσ ≥ 0.
//!
//! In clarabel's form (Ax + s = b, s ∈ K): P = S (upper triangle), q = −h, A = [Cᵀ; −G],
//! b = [Rᵀf; 0], cones (Zero(n_r), Nonnegative(n_c)). Its KKT conditions
//! Sσ − h + C y = Gᵀz, z ≥ 0, z·Gσ = 0 are the discrete unilateral conditions with the gap
//! g = Sσ − h − Cα = Gᵀz and the rigid-body amplitudes α = −y; the plate follows as
//! u = K⁻(f − Bσ) + Rα.
//!
//! P is dense. clarabel's faer supernodal LDLᵀ ("faer") is chosen explicitly: on dense KKT
//! systems it is about 3× faster than the default QDLDL here (BENCHMARKS.md).

use std::time::Instant;

use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSettings, DefaultSettingsBuilder, DefaultSolver, SolverStatus, SupportedConeT,
};

use crate::error::{Error, Result};
use crate::method::{Method, QpForm, QpSettings, QpSolver};
use crate::monitor::Monitor;
use crate::operators::Operators;
use crate::solve::bonded::SchurSystem;
use crate::solve::checks::discrete_gap;
use crate::solve::diagnostics::QpDiagnostics;
use crate::solve::linalg::finite;
use crate::solve::solution::{Solution, SolveInfo, Status, Timings};

/// clarabel's settings for `settings`: quiet, with its tolerances, iteration cap and KKT solver.
/// Shared with the sparse forms ([`super::clarabel_sparse`]).
pub(crate) fn clarabel_settings(settings: &QpSettings) -> Result<DefaultSettings<f64>> {
    DefaultSettingsBuilder::default()
        .verbose(false)
        .tol_gap_abs(settings.tol_gap_abs)
        .tol_gap_rel(settings.tol_gap_rel)
        .tol_feas(settings.tol_feas)
        .max_iter(settings.max_iter)
        .direct_solve_method(settings.kkt.name().to_string())
        .build()
        .map_err(|e| Error::numerical("clarabel settings", format!("{e:?}")))
}

/// clarabel's account of a solve, with the sparse forms' consistency check.
pub(crate) fn diagnostics(
    sol: &clarabel::solver::DefaultSolution<f64>,
    form_check: Option<(&'static str, f64)>,
) -> QpDiagnostics {
    QpDiagnostics {
        primal_residual: sol.r_prim,
        dual_residual: sol.r_dual,
        objective: sol.obj_val,
        duality_gap: (sol.obj_val - sol.obj_val_dual).abs(),
        form_check,
    }
}

/// Solve the unbonded problem as a QP.
pub fn solve(ops: &Operators, settings: &QpSettings) -> Result<Solution> {
    solve_with(ops, settings, &Monitor::NONE)
}

/// [`solve`], stopped between interior-point iterations by `monitor`'s cancel flag.
pub fn solve_with(
    ops: &Operators,
    settings: &QpSettings,
    monitor: &Monitor<'_>,
) -> Result<Solution> {
    let t0 = Instant::now();
    let sys = SchurSystem::new(ops)?;
    let t_schur = t0.elapsed().as_secs_f64();
    let n = ops.n_sigma();
    let n_r = sys.c.len();
    let g = &ops.constraints.g;
    let n_c = g.rows();

    // P: upper triangle of S, column by column.
    let mut colptr = Vec::with_capacity(n + 1);
    let mut rowval = Vec::with_capacity(n * (n + 1) / 2);
    let mut nzval = Vec::with_capacity(n * (n + 1) / 2);
    colptr.push(0);
    for j in 0..n {
        for i in 0..=j {
            rowval.push(i);
            nzval.push(sys.s[(i, j)]);
        }
        colptr.push(rowval.len());
    }
    let p = CscMatrix::new(n, n, colptr, rowval, nzval);
    let q: Vec<f64> = sys.h.iter().map(|v| -v).collect();

    // A = [Cᵀ; −G].
    let mut colptr = Vec::with_capacity(n + 1);
    let mut rowval = Vec::new();
    let mut nzval = Vec::new();
    colptr.push(0);
    for j in 0..n {
        for (r, c) in sys.c.iter().enumerate() {
            if c[j] != 0.0 {
                rowval.push(r);
                nzval.push(c[j]);
            }
        }
        if let Some(col) = g.outer_view(j) {
            for (i, &v) in col.iter() {
                rowval.push(n_r + i);
                nzval.push(-v);
            }
        }
        colptr.push(rowval.len());
    }
    let a = CscMatrix::new(n_r + n_c, n, colptr, rowval, nzval);
    let mut b = sys.rf.clone();
    b.extend(std::iter::repeat_n(0.0, n_c));
    let cones = [
        SupportedConeT::ZeroConeT(n_r),
        SupportedConeT::NonnegativeConeT(n_c),
    ];

    let cl_settings = clarabel_settings(settings)?;
    let t1 = Instant::now();
    let mut solver = DefaultSolver::new(&p, &q, &a, &b, &cones, cl_settings)
        .map_err(|e| Error::numerical("clarabel setup", format!("{e:?}")))?;
    super::clarabel_watched(&mut solver, monitor)?;
    let t_qp = t1.elapsed().as_secs_f64();
    let sol = &solver.solution;
    let status = match sol.status {
        SolverStatus::Solved => Status::Converged,
        SolverStatus::PrimalInfeasible | SolverStatus::AlmostPrimalInfeasible => {
            return Err(Error::Infeasible(
                "clarabel proved the QP primal infeasible: no non-negative pressure balances the loads (the load resultant lies outside the plate, or the net load is upward)".into(),
            ))
        }
        other => Status::SolverFailure {
            detail: format!(
                "clarabel stopped with status {other:?} after {} iterations (primal residual {:.1e}, dual residual {:.1e})",
                sol.iterations, sol.r_prim, sol.r_dual
            ),
        },
    };
    let sigma = sol.x.clone();
    finite(&sigma, "QP solution")?;
    let alpha: Vec<f64> = sol.z[..n_r].iter().map(|y| -y).collect();
    let u = sys.displacements(ops, &sigma, &alpha);
    let gap = discrete_gap(ops, &u, &sigma);
    Ok(Solution {
        method: Method::Qp(QpSettings {
            form: QpForm::Schur,
            solver: QpSolver::Clarabel,
            ..settings.clone()
        }),
        u,
        sigma,
        gap,
        rigid: alpha,
        status,
        iterations: sol.iterations as usize,
        history: Vec::new(),
        info: SolveInfo {
            timings: Timings {
                plate_factor: Some(sys.time_plate),
                schur: Some(t_schur - sys.time_plate),
                clarabel: Some(t_qp),
                total: t0.elapsed().as_secs_f64(),
                ..Timings::default()
            },
            qp: Some(diagnostics(sol, None)),
            ..SolveInfo::default()
        },
    })
}
