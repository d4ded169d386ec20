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
//! that keeps every lifted point above the soil ([`least_turn`]).
//!
//! **Preconditioner.** On Winkler soil T is diagonal and the coupling lumped, so the
//! preconditioner of the iterative route, M = D + QᵀK⁻Q, with D = T and the model's own plate
//! is S itself: each face solve is one sparse factorisation of the plate on springs at the
//! free points (exactly a penalty step's) and a CG iteration or two for the equilibrium. On
//! the half-space (dense or FFT) it is the iterative route's coarse plate on λ·diag(T).
//!
//! **The projection** onto {σ ≥ 0, Cᵀσ = b} is σ = max(0, y + Cλ) with λ (one value per rigid
//! mode) the maximiser of the concave dual −½|max(0, y + Cλ)|² + bᵀλ; Newton on λ with a line
//! search, m ≤ 3 unknowns.

use std::time::Instant;

use crate::error::{Error, Result};
use crate::foundation::Compliance;
use crate::method::{ActiveSetSettings, CgSettings, Method, QpSettings, QpSolver};
use crate::model::ConstraintPoints;
use crate::operators::Operators;
use crate::solve::checks::discrete_gap;
use crate::solve::diagnostics::{ActiveSetDiagnostics, CgReport, KktResiduals};
use crate::solve::iterative::{Face, IterativeSchur};
use crate::solve::linalg::SmallSpd;
use crate::solve::linalg::{dot, finite};
use crate::solve::solution::{Iteration, Solution, SolveInfo, Status, Timings};

/// A feasible iterate with the products the next step needs.
struct Point {
    sigma: Vec<f64>,
    /// T σ.
    t_sigma: Vec<f64>,
    /// S σ.
    s_sigma: Vec<f64>,
    /// f(σ) = ½ σᵀSσ − hᵀσ.
    f: f64,
    /// The rigid-body amplitudes of the face solve when σ is its minimiser: the multiplier of
    /// the equilibrium on the whole free set, where the points in contact alone may not fix
    /// it (a plate resting on one node can turn about it).
    alpha: Option<Vec<f64>>,
}

impl Point {
    fn new(sys: &mut IterativeSchur, ops: &Operators, sigma: Vec<f64>) -> Self {
        let (t_sigma, s_sigma) = sys.t_and_s_times(ops, &sigma);
        Self::with_products(sys, sigma, t_sigma, s_sigma)
    }

    fn with_products(
        sys: &IterativeSchur,
        sigma: Vec<f64>,
        t_sigma: Vec<f64>,
        s_sigma: Vec<f64>,
    ) -> Self {
        let f = 0.5 * dot(&sigma, &s_sigma) - dot(&sys.h, &sigma);
        Self {
            sigma,
            t_sigma,
            s_sigma,
            f,
            alpha: None,
        }
    }
}

/// The reduced gradient g = Sσ − h − Cα, and α: the face solve's multiplier where σ is that
/// face's minimiser, else the least-squares multiplier on the points in contact.
fn reduced_gradient(sys: &IterativeSchur, p: &Point) -> (Vec<f64>, Vec<f64>) {
    let grad: Vec<f64> = p.s_sigma.iter().zip(&sys.h).map(|(s, h)| s - h).collect();
    let alpha = match &p.alpha {
        Some(a) => a.clone(),
        None => support_multiplier(sys, p, &grad),
    };
    let mut g = grad;
    for (a, &al) in alpha.iter().enumerate() {
        for (gi, ci) in g.iter_mut().zip(&sys.c[a]) {
            *gi -= al * ci;
        }
    }
    (g, alpha)
}

/// The multiplier of Sσ − h ≈ Cα on the points in contact: least squares where they fix every
/// rigid mode. Where they do not (a plate resting on one node, or on one line of nodes, can
/// turn about it) the free part β of α (α = α₀ + Nβ) is the smallest turn that keeps every
/// lifted point above the soil, min |β|² subject to gᵢ(β) ≥ 0 where σᵢ = 0: a QP in at most
/// two unknowns, solved by clarabel. If no turn does, the least-squares α₀ is returned and
/// the iteration frees the points that penetrate.
fn support_multiplier(sys: &IterativeSchur, p: &Point, grad: &[f64]) -> Vec<f64> {
    let m = sys.c.len();
    let on = |i: usize| p.sigma[i] > 0.0;
    let ctc = SmallSpd::new(m, |a, b| {
        (0..grad.len())
            .filter(|&i| on(i))
            .map(|i| sys.c[a][i] * sys.c[b][i])
            .sum()
    });
    let ctg: Vec<f64> = (0..m)
        .map(|a| {
            (0..grad.len())
                .filter(|&i| on(i))
                .map(|i| sys.c[a][i] * grad[i])
                .sum()
        })
        .collect();
    let alpha0 = ctc.solve(&ctg);
    let null = ctc.null_space();
    if null.is_empty() {
        return alpha0;
    }
    match least_turn(sys, p, grad, &alpha0, &null) {
        Some(beta) => {
            let mut alpha = alpha0;
            for (nv, b) in null.iter().zip(&beta) {
                for (a, v) in alpha.iter_mut().zip(nv) {
                    *a += b * v;
                }
            }
            // The dropped directions are null only to round-off: a large turn leaves a
            // residual on the points in contact, which one more least-squares pass removes.
            let rest: Vec<f64> = (0..m)
                .map(|a| {
                    (0..grad.len())
                        .filter(|&i| on(i))
                        .map(|i| {
                            let ca: f64 = (0..m).map(|b| sys.c[b][i] * alpha[b]).sum();
                            sys.c[a][i] * (grad[i] - ca)
                        })
                        .sum()
                })
                .collect();
            for (a, d) in alpha.iter_mut().zip(ctc.solve(&rest)) {
                *a += d;
            }
            alpha
        }
        None => alpha0,
    }
}

/// min ½|β|² subject to (CN)ᵢβ ≤ (Sσ − h − Cα₀)ᵢ on the points with σᵢ = 0 (gᵢ ≥ 0), by
/// clarabel; None if infeasible or not solved.
fn least_turn(
    sys: &IterativeSchur,
    p: &Point,
    grad: &[f64],
    alpha0: &[f64],
    null: &[Vec<f64>],
) -> Option<Vec<f64>> {
    use clarabel::algebra::CscMatrix;
    use clarabel::solver::{
        DefaultSettingsBuilder, DefaultSolver, IPSolver, SolverStatus, SupportedConeT,
    };
    let k = null.len();
    let m = sys.c.len();
    let zeros: Vec<usize> = (0..grad.len()).filter(|&i| p.sigma[i] == 0.0).collect();
    // Columns of C N, and g₀ = Sσ − h − Cα₀ on the zeros.
    let cn: Vec<Vec<f64>> = null
        .iter()
        .map(|nv| {
            zeros
                .iter()
                .map(|&i| (0..m).map(|a| sys.c[a][i] * nv[a]).sum())
                .collect()
        })
        .collect();
    let g0: Vec<f64> = zeros
        .iter()
        .map(|&i| grad[i] - (0..m).map(|a| sys.c[a][i] * alpha0[a]).sum::<f64>())
        .collect();
    // Scale β so that a unit turn moves the farthest point by about one unit of the gaps.
    let reach = cn
        .iter()
        .flat_map(|col| col.iter())
        .fold(0.0_f64, |a, v| a.max(v.abs()))
        .max(f64::MIN_POSITIVE);
    let gmax = g0
        .iter()
        .fold(0.0_f64, |a, v| a.max(v.abs()))
        .max(f64::MIN_POSITIVE);
    let unit = gmax / reach;
    let pmat = CscMatrix::new(k, k, (0..=k).collect(), (0..k).collect(), vec![1.0; k]);
    let mut colptr = vec![0];
    let mut rowval = Vec::new();
    let mut nzval = Vec::new();
    for col in &cn {
        for (r, &v) in col.iter().enumerate() {
            if v != 0.0 {
                rowval.push(r);
                nzval.push(v * unit / gmax);
            }
        }
        colptr.push(rowval.len());
    }
    let a = CscMatrix::new(zeros.len(), k, colptr, rowval, nzval);
    let b: Vec<f64> = g0.iter().map(|g| g / gmax).collect();
    let settings = DefaultSettingsBuilder::default()
        .verbose(false)
        .build()
        .ok()?;
    let cones = [SupportedConeT::NonnegativeConeT(zeros.len())];
    let mut solver = DefaultSolver::new(&pmat, &vec![0.0; k], &a, &b, &cones, settings).ok()?;
    solver.solve();
    (solver.solution.status == SolverStatus::Solved)
        .then(|| solver.solution.x.iter().map(|x| x * unit).collect())
}

/// The scale of the gaps: the largest of the terms g = Sσ − h − Cα is made of, |Tσ|, |Sσ|,
/// the plate's deflection under the loads |h| = |BᵀK⁻f − g₀| and the rigid-body part |Cα|
/// (the round-off of g is relative to the largest; a plate resting on a few nodes has gaps
/// far larger than its settlement).
fn gap_scale(sys: &IterativeSchur, p: &Point, alpha: &[f64]) -> f64 {
    let rigid = (0..p.sigma.len())
        .map(|i| {
            sys.c
                .iter()
                .zip(alpha)
                .map(|(c, a)| c[i] * a)
                .sum::<f64>()
                .abs()
        })
        .fold(0.0_f64, f64::max);
    p.t_sigma
        .iter()
        .chain(&p.s_sigma)
        .chain(&sys.h)
        .fold(rigid, |a, v| a.max(v.abs()))
        .max(f64::MIN_POSITIVE)
}

/// The KKT residuals at `p` with reduced gradient `g` and multiplier `alpha`.
fn kkt(sys: &IterativeSchur, p: &Point, g: &[f64], alpha: &[f64]) -> KktResiduals {
    let s_max = p
        .sigma
        .iter()
        .cloned()
        .fold(0.0_f64, f64::max)
        .max(f64::MIN_POSITIVE);
    let g_s = gap_scale(sys, p, alpha);
    let mut k = KktResiduals::default();
    for (&s, &gi) in p.sigma.iter().zip(g) {
        k.natural = k.natural.max((s / s_max).min(gi / g_s).abs());
        if s > 0.0 {
            k.stationarity = k.stationarity.max(gi.abs() / g_s);
        } else {
            k.penetration = k.penetration.max(-gi / g_s);
        }
        k.complementarity = k.complementarity.max((s * gi).abs() / (s_max * g_s));
    }
    let b_max = sys.rf.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
    k.equilibrium = sys
        .c
        .iter()
        .zip(&sys.rf)
        .map(|(c, b)| (dot(c, &p.sigma) - b).abs())
        .fold(0.0, f64::max)
        / b_max.max(f64::MIN_POSITIVE);
    k
}

/// The Euclidean projection of `y` onto {σ ≥ 0, Cᵀσ = b}: σ = max(0, y + Cλ), with λ the
/// minimiser of the convex ψ(λ) = ½|max(0, y + Cλ)|² − bᵀλ (whose gradient is Cᵀσ − b), by
/// Newton's method with a backtracking line search. None when no λ balances b (no
/// non-negative σ is in equilibrium).
pub fn project(y: &[f64], c: &[Vec<f64>], b: &[f64]) -> Option<Vec<f64>> {
    let m = c.len();
    let sigma_of = |lam: &[f64]| -> Vec<f64> {
        (0..y.len())
            .map(|i| {
                let v = y[i] + (0..m).map(|a| c[a][i] * lam[a]).sum::<f64>();
                v.max(0.0)
            })
            .collect()
    };
    let psi = |sigma: &[f64], lam: &[f64]| 0.5 * dot(sigma, sigma) - dot(b, lam);
    let residual = |sigma: &[f64]| -> (Vec<f64>, f64) {
        let grad: Vec<f64> = (0..m).map(|a| dot(&c[a], sigma) - b[a]).collect();
        // Relative to the round-off of Cᵀσ: n terms of size |c||σ|, and to b.
        let scale = c
            .iter()
            .map(|col| {
                col.iter()
                    .zip(sigma)
                    .map(|(ci, si)| (ci * si).abs())
                    .sum::<f64>()
            })
            .fold(0.0, f64::max)
            + b.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        let rel = grad.iter().fold(0.0_f64, |a, v| a.max(v.abs())) / scale.max(f64::MIN_POSITIVE);
        (grad, rel)
    };
    // Start at λ = 0: y itself when it is feasible, as a face solve's σ* is up to specks of
    // tension, so that points at zero stay exactly at zero. Where y has no positive entry
    // (y = 0) Newton would have no curvature there: start from the unconstrained projection
    // onto Cᵀσ = b instead, σ = y + Cλ₀ with CᵀCλ₀ = b − Cᵀy.
    let mut lambda = vec![0.0; m];
    if y.iter().all(|&v| v <= 0.0) {
        let ctc = SmallSpd::new(m, |a, bb| dot(&c[a], &c[bb]));
        let shortfall: Vec<f64> = (0..m).map(|a| b[a] - dot(&c[a], y)).collect();
        lambda = ctc.solve(&shortfall);
    }
    let mut sigma = sigma_of(&lambda);
    let (mut grad, mut rel) = residual(&sigma);
    for _ in 0..1000 {
        if rel <= 1e-13 {
            break;
        }
        let before = rel;
        // Newton on ψ: Hessian Cᵀ diag(y + Cλ > 0) C; where it is singular (no point
        // positive along some combination) the pseudo-inverse and a gradient step take over.
        let pos: Vec<usize> = (0..y.len()).filter(|&i| sigma[i] > 0.0).collect();
        let hess = SmallSpd::new(m, |a, bb| pos.iter().map(|&i| c[a][i] * c[bb][i]).sum());
        let mut dir: Vec<f64> = hess.solve(&grad).iter().map(|v| -v).collect();
        if hess.rank() < m || dot(&dir, &grad) >= 0.0 {
            // Steepest descent scaled by the columns' size.
            let cc: f64 = (0..m).map(|a| dot(&c[a], &c[a])).sum::<f64>().max(1e-300);
            dir = grad.iter().map(|g| -g / cc).collect();
        }
        let f0 = psi(&sigma, &lambda);
        let slope = dot(&dir, &grad);
        let mut t = 1.0;
        let mut accepted = false;
        for _ in 0..60 {
            let trial: Vec<f64> = lambda.iter().zip(&dir).map(|(l, d)| l + t * d).collect();
            let s_trial = sigma_of(&trial);
            if psi(&s_trial, &trial) <= f0 + 1e-4 * t * slope {
                lambda = trial;
                sigma = s_trial;
                accepted = true;
                break;
            }
            t *= 0.5;
        }
        (grad, rel) = residual(&sigma);
        // No decrease of ψ left to find, or a residual at round-off that no longer falls
        // (the sums Cᵀσ over many points carry ~1e-13 of their size): done.
        if !accepted || (rel <= 1e-11 && rel > 0.5 * before) {
            break;
        }
    }
    // ψ unbounded below (b out of reach), or a balance exact to round-off.
    (rel <= 1e-10).then_some(sigma)
}

/// Solve the unbonded QP by the matrix-free active-set method, from `start` when given
/// (pressures at the nodes, e.g. a coarser grid's solution carried over: the first set is the
/// points it leaves at zero), else from the feasible point nearest σ = 0.
pub fn solve(ops: &Operators, settings: &QpSettings, start: Option<&[f64]>) -> Result<Solution> {
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
    let mut sys = IterativeSchur::with_any_compliance(ops, cg)?;
    let t_setup = t0.elapsed().as_secs_f64();
    let mut run = Run {
        settings: s,
        history: Vec::new(),
        iterations: 0,
        projected_steps: 0,
        safeguard_steps: 0,
        cg_total: 0,
    };
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
        factorisations: sys.factorisations,
        safeguard_steps: run.safeguard_steps,
        projected_steps: run.projected_steps,
        objective: point.f,
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

/// How a phase of the iteration ended: the point, its multiplier, its KKT residuals, status.
type End = (Point, Vec<f64>, KktResiduals, Status);

/// The iteration's bookkeeping.
struct Run {
    settings: ActiveSetSettings,
    history: Vec<Iteration>,
    iterations: usize,
    projected_steps: usize,
    safeguard_steps: usize,
    cg_total: usize,
}

fn infeasible() -> Error {
    Error::Infeasible(
        "no non-negative pressure balances the loads (the load resultant lies outside the reach of the plate's nodal pressures)".into(),
    )
}

impl Run {
    /// One face solve to relative residual `tol`, counted and checked.
    fn face(
        &mut self,
        sys: &mut IterativeSchur,
        ops: &Operators,
        held: &[bool],
        start: &[f64],
        tol: f64,
    ) -> Result<Face> {
        let face = sys.solve_face(ops, held, start, tol)?;
        finite(&face.sigma, "matrix-free QP")?;
        self.cg_total += face.cg.iterations;
        self.iterations += 1;
        Ok(face)
    }

    /// Record a step: the points at zero after it, against those before.
    fn record(&mut self, before: &[bool], after: &[bool], min_sigma: f64, cg: CgReport) {
        self.history.push(Iteration {
            step: self.iterations,
            epsilon: 0.0,
            penalised: after.iter().filter(|&&b| b).count(),
            entered: after
                .iter()
                .zip(before)
                .filter(|(a, b)| **a && !**b)
                .count(),
            left: after
                .iter()
                .zip(before)
                .filter(|(a, b)| !**a && **b)
                .count(),
            min_pressure: min_sigma,
            cg: Some(cg),
        });
    }

    /// The primal–dual active-set (semismooth Newton) iteration on sets: hold the lifted set
    /// at zero, solve the face, lift the free points whose pressure came out negative and
    /// release the held points whose gap came out negative; stop when nothing moves after a
    /// tight solve. It is the penalty iteration with ε̄ = 0 and as fast, but it can cycle on a
    /// matrix that is not an M-matrix: a set met before hands over to [`Self::feasible`]
    /// (`Err` with the last face's pressures, where it starts).
    fn primal_dual(
        &mut self,
        sys: &mut IterativeSchur,
        ops: &Operators,
        warm: Option<&[f64]>,
    ) -> Result<std::result::Result<End, Vec<f64>>> {
        let n = ops.n_sigma();
        let tol = self.settings.tolerance;
        let mut seen: Vec<Vec<bool>> = Vec::new();
        // The feasible point nearest σ = 0 (pressures linear over the points it keeps, as
        // under a rigid plate): the solution itself when it is the only feasible point (a
        // plate balanced on one node), and where the first set comes from — usually nothing
        // held, the bonded problem.
        let origin = project(&vec![0.0; n], &sys.c, &sys.rf).ok_or_else(infeasible)?;
        let p0 = Point::new(sys, ops, origin);
        let (g0, alpha0) = reduced_gradient(sys, &p0);
        let k0 = kkt(sys, &p0, &g0, &alpha0);
        if k0.natural <= tol {
            return Ok(Ok((p0, alpha0, k0, Status::Converged)));
        }
        // A start carried over from elsewhere, made feasible: its zeros whose gap does not
        // close are the first set. (Checked against n: a start of another grid is ignored.)
        let (p0, g0, alpha0) = match warm
            .filter(|w| w.len() == n)
            .and_then(|w| project(w, &sys.c, &sys.rf))
        {
            Some(x) => {
                let p = Point::new(sys, ops, x);
                let (g, alpha) = reduced_gradient(sys, &p);
                (p, g, alpha)
            }
            None => (p0, g0, alpha0),
        };
        let g_s = gap_scale(sys, &p0, &alpha0);
        let mut held: Vec<bool> = (0..n)
            .map(|i| p0.sigma[i] == 0.0 && g0[i] >= -tol * g_s)
            .collect();
        let mut start = p0.sigma;
        // The face solves' tolerance: loose while the sets move (they only have to be found),
        // 100× tighter each time the sets wander, tight when a set repeats: only a tight
        // solve can confirm a set. With the exact Winkler preconditioner a
        // tight solve costs a CG iteration or two: tight from the start.
        let cg = self.settings.cg;
        let tight_tol = cg.tolerance;
        let mut level = if sys.exact() {
            tight_tol
        } else {
            cg.loose_tolerance.max(tight_tol)
        };
        // (fewest points changed by a step so far, steps since).
        let mut wander = (usize::MAX, 0usize);
        while self.iterations < self.settings.max_iterations {
            let face = self.face(sys, ops, &held, &start, level)?;
            let tight = face.cg.residual <= tight_tol;
            // A loose solve that the warm start already satisfied has not moved σ: the sets it
            // suggests are stale.
            let stale = !tight && face.cg.iterations == 0;
            // The gap at σ* with the face's multiplier.
            let mut g: Vec<f64> = face
                .s_sigma
                .iter()
                .zip(&sys.h)
                .map(|(a, b)| a - b)
                .collect();
            for (c, a) in sys.c.iter().zip(&face.alpha) {
                for (gi, ci) in g.iter_mut().zip(c) {
                    *gi -= a * ci;
                }
            }
            let s_max = face.sigma.iter().cloned().fold(0.0_f64, f64::max);
            let point = Point::with_products(
                sys,
                face.sigma.clone(),
                face.t_sigma.clone(),
                face.s_sigma.clone(),
            );
            let g_s = gap_scale(sys, &point, &face.alpha);
            let next: Vec<bool> = (0..n)
                .map(|i| {
                    if held[i] {
                        g[i] >= -tol * g_s
                    } else {
                        face.sigma[i] < -tol * s_max
                    }
                })
                .collect();
            let min_free = (0..n)
                .filter(|&i| !held[i])
                .map(|i| face.sigma[i])
                .fold(f64::INFINITY, f64::min);
            self.record(&held, &next, min_free, face.cg);
            if next.iter().all(|&b| b) {
                return Err(infeasible());
            }
            if !tight && (next == held || stale || seen.contains(&next)) {
                // A set that repeats is confirmed or refuted by a tight solve; sets that
                // wander (a solve that could not move, a set met before) by a tighter one.
                level = if next == held {
                    tight_tol
                } else {
                    (level * 1e-2).max(tight_tol)
                };
                start = face.sigma;
                continue;
            }
            if next == held {
                // Settled: σ* with its specks of tension projected away.
                let x = project(&face.sigma, &sys.c, &sys.rf).ok_or_else(infeasible)?;
                let mut p = if x == face.sigma {
                    point
                } else {
                    Point::new(sys, ops, x)
                };
                p.alpha = Some(face.alpha);
                let (g, alpha) = reduced_gradient(sys, &p);
                let k = kkt(sys, &p, &g, &alpha);
                if k.natural <= tol {
                    return Ok(Ok((p, alpha, k, Status::Converged)));
                }
                return Ok(Err(p.sigma));
            }
            if seen.contains(&next) {
                // A cycle: hand over to the monotone method.
                return Ok(Err(face.sigma));
            }
            // Sets that wander without repeating (a soil whose gaps at the contact edge are
            // below what a loose solve resolves): 100× tighter when five steps have not
            // changed fewer points than the best so far; and at the tight tolerance, hand
            // over to the monotone method after twenty such steps.
            let changes = next.iter().zip(&held).filter(|(a, b)| a != b).count();
            if changes < wander.0 {
                wander = (changes, 0);
            } else {
                wander.1 += 1;
            }
            if wander.1 >= 5 && level > tight_tol {
                level = (level * 1e-2).max(tight_tol);
                wander = (changes, 0);
            } else if wander.1 >= 20 {
                return Ok(Err(face.sigma));
            }
            seen.push(held);
            held = next;
            start = face.sigma;
        }
        Ok(Err(start))
    }

    /// The safeguard: the primal active-set method (Nocedal & Wright, Numerical Optimization,
    /// Alg. 16.3) on feasible points (σ ≥ 0, in equilibrium) with a working set W of points
    /// held at zero. From a point that is not its face's minimiser, the face of W is solved
    /// tightly and the step goes along σ* − σ as far as σ ≥ 0 allows (the ratio test); the
    /// points it stops at join W. At a face's minimiser the multipliers are exact: if no point
    /// of W has a closing gap the KKT conditions hold, otherwise the points of W whose gap
    /// closes are released — all of them, or, when such a step cannot move (several released
    /// points pull each other down), only the one whose gap closes most, which the next face
    /// solve lifts off zero. f falls at every step, so no working set can return.
    fn feasible(&mut self, sys: &mut IterativeSchur, ops: &Operators, last: &[f64]) -> Result<End> {
        let n = ops.n_sigma();
        let tol = self.settings.tolerance;
        let start = project(last, &sys.c, &sys.rf).ok_or_else(infeasible)?;
        let mut point = Point::new(sys, ops, start);
        let mut held: Vec<bool> = point.sigma.iter().map(|&v| v == 0.0).collect();
        // Whether `point` minimises f on the face of `held` (its α is the face's multiplier).
        let mut stationary = false;
        let mut single = false;
        loop {
            let (g, alpha) = reduced_gradient(sys, &point);
            let k = kkt(sys, &point, &g, &alpha);
            if stationary && k.natural <= tol {
                return Ok((point, alpha, k, Status::Converged));
            }
            if self.iterations >= self.settings.max_iterations {
                let limit = self.settings.max_iterations;
                return Ok((point, alpha, k, Status::IterationLimit { limit }));
            }
            if stationary {
                let g_s = gap_scale(sys, &point, &alpha);
                let closing: Vec<usize> =
                    (0..n).filter(|&i| held[i] && g[i] < -tol * g_s).collect();
                let worst = closing
                    .iter()
                    .copied()
                    .min_by(|&a, &b| g[a].total_cmp(&g[b]));
                match worst {
                    Some(w) if single => held[w] = false,
                    Some(_) => closing.iter().for_each(|&i| held[i] = false),
                    // Every gap open and the face solved, yet the residual is above the
                    // tolerance: the face solve's own accuracy is the limit.
                    None => {
                        return Err(Error::numerical(
                            "matrix-free QP (primal active set)",
                            format!(
                                "the KKT residual stays at {:.1e} (tolerance {tol:.0e}) on the final contact set: the inner solves cannot go further here",
                                k.natural
                            ),
                        ))
                    }
                }
            }
            let face = self.face(sys, ops, &held, &point.sigma, self.settings.cg.tolerance)?;
            self.safeguard_steps += 1;
            let d: Vec<f64> = face
                .sigma
                .iter()
                .zip(&point.sigma)
                .map(|(a, b)| a - b)
                .collect();
            let s_max = face.sigma.iter().cloned().fold(0.0_f64, f64::max);
            let min_free = (0..n)
                .filter(|&i| !held[i])
                .map(|i| face.sigma[i])
                .fold(f64::INFINITY, f64::min);
            let before: Vec<bool> = point.sigma.iter().map(|&v| v == 0.0).collect();
            let next = if min_free >= -tol * s_max {
                // The face's minimiser is feasible (to round-off): take it.
                let x = project(&face.sigma, &sys.c, &sys.rf).ok_or_else(infeasible)?;
                let mut p = Point::new(sys, ops, x);
                p.alpha = Some(face.alpha.clone());
                stationary = true;
                single = false;
                p
            } else {
                self.projected_steps += 1;
                // Ratio test: the longest step along d that keeps σ ≥ 0.
                let (t, blocking) = (0..n)
                    .filter(|&i| !held[i] && d[i] < 0.0)
                    .map(|i| (point.sigma[i] / -d[i], i))
                    .fold(
                        (1.0_f64, None),
                        |(t, b), (ti, i)| {
                            if ti < t {
                                (ti, Some(i))
                            } else {
                                (t, b)
                            }
                        },
                    );
                if t <= 0.0 && stationary {
                    // The released points pull each other down: release one only.
                    if single {
                        return Err(Error::numerical(
                            "matrix-free QP (primal active set)",
                            "a face step cannot move from its point: the inner solves are not accurate enough for this contact set",
                        ));
                    }
                    single = true;
                    held = before;
                    continue;
                }
                let mut x: Vec<f64> = (0..n)
                    .map(|i| (point.sigma[i] + t * d[i]).max(0.0))
                    .collect();
                // The blocking point, and any other the step took to zero to round-off,
                // join the working set.
                if let Some(b) = blocking {
                    x[b] = 0.0;
                }
                for (i, xi) in x.iter_mut().enumerate() {
                    if d[i] < 0.0 && *xi <= 1e-14 * s_max {
                        *xi = 0.0;
                    }
                }
                let x = project(&x, &sys.c, &sys.rf).ok_or_else(infeasible)?;
                for (h, &xi) in held.iter_mut().zip(&x) {
                    *h |= xi == 0.0;
                }
                stationary = false;
                Point::new(sys, ops, x)
            };
            let after: Vec<bool> = next.sigma.iter().map(|&v| v == 0.0).collect();
            self.record(&before, &after, min_free, face.cg);
            if next.f > point.f + 1e-12 * point.f.abs() {
                return Err(Error::numerical(
                    "matrix-free QP (primal active set)",
                    "a step raised the objective: the inner solves are not accurate enough for this contact set",
                ));
            }
            point = next;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The projection is the nearest point of {σ ≥ 0, Cᵀσ = b}: it is feasible, and y − σ is
    /// a normal of the set there (y − σ = −Cλ − ν with ν ≥ 0 zero where σ > 0).
    #[test]
    fn projection_is_feasible_and_its_residual_is_normal() {
        let n = 40;
        let x: Vec<f64> = (0..n).map(|i| i as f64 / (n - 1) as f64 - 0.5).collect();
        let c = vec![vec![1.0; n], x.clone()];
        let b = vec![10.0, 1.5];
        let y: Vec<f64> = (0..n).map(|i| ((i * 7 % 11) as f64) - 5.0).collect();
        let s = project(&y, &c, &b).expect("feasible");
        assert!(s.iter().all(|&v| v >= 0.0), "σ ≥ 0");
        for a in 0..2 {
            let r = dot(&c[a], &s) - b[a];
            assert!(r.abs() < 1e-12, "equality {a}: residual {r}");
        }
        // σ − y = Cλ on the support (some λ), and σ − y ≥ Cλ where σ = 0: the normal cone.
        let support: Vec<usize> = (0..n).filter(|&i| s[i] > 0.0).collect();
        assert!(support.len() >= 2, "support {support:?}");
        let (i, j) = (support[0], support[support.len() - 1]);
        let det = c[0][i] * c[1][j] - c[0][j] * c[1][i];
        let l0 = ((s[i] - y[i]) * c[1][j] - (s[j] - y[j]) * c[1][i]) / det;
        let l1 = (c[0][i] * (s[j] - y[j]) - c[0][j] * (s[i] - y[i])) / det;
        for k in 0..n {
            let v = y[k] + l0 * c[0][k] + l1 * c[1][k];
            // σ = max(0, y + Cλ) exactly (the optimality condition of the projection).
            assert!(
                (s[k] - v.max(0.0)).abs() < 1e-10,
                "node {k}: {} vs {}",
                s[k],
                v
            );
        }
    }

    /// The safeguard on its own — the primal active-set method with its ratio test, started
    /// where the primal–dual phase starts — reaches the interior-point answer of the same QP
    /// (clarabel, dense Schur form; tolerance 1e-7 of the peak: both solvers stop at ~1e-13 of
    /// their scales, and the issue asks for 1e-6), through steps the ratio test cut short.
    #[test]
    fn the_safeguard_alone_reaches_the_interior_point_answer() {
        let text = crate::examples::scene("paper-halfspace")
            .expect("bundled")
            .replace("elements = [16, 16]", "elements = [24, 24]");
        let problem = crate::Problem::from_toml(&text).expect("scene");
        let ops = Operators::assemble(&problem.model);
        let settings = QpSettings::default();
        let reference = super::super::clarabel_dense::solve(&ops, &settings).expect("clarabel");
        let mut sys =
            IterativeSchur::with_any_compliance(&ops, settings.active_set.cg).expect("setup");
        let mut run = Run {
            settings: settings.active_set,
            history: Vec::new(),
            iterations: 0,
            projected_steps: 0,
            safeguard_steps: 0,
            cg_total: 0,
        };
        let (point, _, k, status) = run
            .feasible(&mut sys, &ops, &vec![0.0; ops.n_sigma()])
            .expect("safeguard");
        assert_eq!(status, Status::Converged, "{k:?}");
        assert!(run.projected_steps > 0, "the ratio test was exercised");
        let peak = reference.sigma.iter().cloned().fold(0.0_f64, f64::max);
        let diff = point
            .sigma
            .iter()
            .zip(&reference.sigma)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0_f64, f64::max);
        assert!(
            diff <= 1e-7 * peak,
            "σ differs by {:.1e} of the peak",
            diff / peak
        );
    }

    /// A balance no non-negative σ can give (the resultant outside the points' hull) is
    /// reported as None.
    #[test]
    fn projection_reports_an_unreachable_balance() {
        let c = vec![vec![1.0; 3], vec![-1.0, 0.0, 1.0]];
        let b = vec![1.0, 2.0]; // resultant at x = 2, outside [−1, 1]
        assert!(project(&[0.0; 3], &c, &b).is_none());
    }
}
