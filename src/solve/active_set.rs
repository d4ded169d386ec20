//! The unbonded QP without any dense matrix: a primal active-set method with projected search,
//! its inner solves by projected PCG through the operators ([`super::iterative`]).
//!
//! The problem is the QP of [`super::qp`] with nodal constraints,
//!
//! min f(σ) = ½ σᵀSσ − hᵀσ   subject to   Cᵀσ = Rᵀf,   σ ≥ 0,
//!
//! S = T + BᵀK⁻B applied as one product with T (diagonal, dense, or by FFT) and one solve with
//! the plate factor — S is never formed. Its KKT conditions are the discrete unilateral
//! conditions: with α the rigid-body amplitudes, the gap g = Sσ − h − Cα satisfies g ≥ 0,
//! σ·g = 0.
//!
//! **The iteration.** Every iterate is feasible (σ ≥ 0 and on the equilibrium). At σ, with α
//! the least-squares multiplier on the points in contact (σᵢ > 0), the points held at zero are
//! those where σᵢ = 0 and the gap does not close, gᵢ ≥ −τ; the others are free.
//! 1. *Face solve*: σ* minimises f on the free points with the held ones at zero, on the
//!    equilibrium ([`IterativeSchur::solve_face`], warm-started at σ).
//! 2. *Step*: if σ* ≥ 0 it is the next iterate (the minimiser on that face). Otherwise the next
//!    iterate is the projection P(σ + t(σ* − σ)) onto {σ ≥ 0, Cᵀσ = Rᵀf} with the first
//!    t = 1, ½, ¼, … that decreases f enough (Armijo on the projected path). Clipping removes
//!    the negative pressures of σ* all at once (a penalty iteration's "lift these points"), and
//!    the projection's shift along C keeps the plate in equilibrium.
//! 3. Stop when the KKT conditions hold to the tolerance after a tight face solve:
//!    |min(σᵢ/σ_max, gᵢ/g_s)| ≤ τ at every point (the natural residual, g_s the largest
//!    of |Tσ|, |Sσ|, |h| and |Cα|, the terms of g) — exact complementarity to solver
//!    tolerance, no ε̄.
//!
//! Every iterate decreases f (the face solve from a point of its face cannot increase it, and
//! the projected search demands a decrease), so a set can never return: the iteration cannot
//! cycle, which the penalty iteration and a plain primal–dual active-set (semismooth Newton)
//! update can on a matrix that is not an M-matrix — and neither the 1/r flexibility nor the
//! plate is one. With the full step accepted (the usual case) one iteration is the penalty
//! iteration's "solve, then lift the points in tension" with ε̄ = 0. Face solves are loose
//! (the set only has to be found) until the held set repeats, then tight.
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

use super::bonded::{dot, finite};
use super::iterative::IterativeSchur;
use super::linalg::SmallSpd;
use super::{discrete_gap, Iteration, Solution, SolveInfo, Status, Timings};
use crate::error::{Error, Result};
use crate::foundation::Compliance;
use crate::method::{CgSettings, Method, QpSettings, QpSolver};
use crate::model::ConstraintPoints;
use crate::operators::Operators;

/// The KKT residuals of a QP solution, each relative to its scale.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct KktResiduals {
    /// max |min(σᵢ/σ_max, gᵢ/g_s)|: zero exactly when σ ≥ 0, g ≥ 0 and σ·g = 0.
    pub natural: f64,
    /// Largest |gᵢ| / g_s where σᵢ > 0 (the gap that should be closed).
    pub stationarity: f64,
    /// Largest −gᵢ / g_s where σᵢ = 0 (penetration of a lifted point).
    pub penetration: f64,
    /// max |σᵢ gᵢ| / (σ_max g_s).
    pub complementarity: f64,
    /// |Cᵀσ − Rᵀf|∞ / |Rᵀf|∞: the rigid-body equilibrium.
    pub equilibrium: f64,
}

/// The matrix-free solver's account of a solve.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ActiveSetDiagnostics {
    /// Outer (active-set) iterations: face solves.
    pub iterations: usize,
    /// Conjugate-gradient iterations over all face solves.
    pub cg_iterations: usize,
    /// Products with S (each one T product and one plate solve), CG and line search.
    pub products: usize,
    /// Preconditioner factorisations (one per new held set).
    pub factorisations: usize,
    /// Face steps that needed the projected search (σ* had negative pressures).
    pub projected_steps: usize,
    /// Objective ½σᵀSσ − hᵀσ at the solution.
    pub objective: f64,
    /// The KKT residuals at the solution.
    pub kkt: KktResiduals,
}

impl ActiveSetDiagnostics {
    /// (name, value) pairs, as in summary.json's `solver_info`.
    pub fn named(&self) -> Vec<(&'static str, f64)> {
        vec![
            ("outer_iterations", self.iterations as f64),
            ("cg_iterations", self.cg_iterations as f64),
            ("schur_products", self.products as f64),
            ("factorisations", self.factorisations as f64),
            ("projected_steps", self.projected_steps as f64),
            ("objective", self.objective),
            ("kkt_natural", self.kkt.natural),
            ("kkt_stationarity", self.kkt.stationarity),
            ("kkt_penetration", self.kkt.penetration),
            ("kkt_complementarity", self.kkt.complementarity),
            ("kkt_equilibrium", self.kkt.equilibrium),
        ]
    }
}

/// Armijo's sufficient-decrease fraction.
const ARMIJO: f64 = 1e-4;

/// Halvings of the projected search before it gives up on a direction.
const MAX_HALVINGS: usize = 40;

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

    /// A point whose products are formed only when asked for ([`Self::ensure`]).
    fn bare(sigma: Vec<f64>) -> Self {
        Self {
            sigma,
            t_sigma: Vec::new(),
            s_sigma: Vec::new(),
            f: f64::NAN,
            alpha: None,
        }
    }

    /// Form the products of a bare point.
    fn ensure(&mut self, sys: &mut IterativeSchur, ops: &Operators) {
        if self.s_sigma.is_empty() {
            let sigma = std::mem::take(&mut self.sigma);
            *self = Self::new(sys, ops, sigma);
        }
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
/// Newton's method with a backtracking line search from λ = 0 (the answer when y is already
/// feasible, as a face solve's σ* is up to specks of tension). None when no λ balances b (no
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
    let mut lambda = vec![0.0; m];
    let mut sigma = sigma_of(&lambda);
    let (mut grad, mut rel) = residual(&sigma);
    for _ in 0..1000 {
        if rel <= 1e-13 {
            break;
        }
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
        if !accepted {
            // No decrease of ψ left to find: round-off has the last word.
            break;
        }
    }
    // ψ unbounded below (b out of reach), or a balance exact to round-off.
    (rel <= 1e-10).then_some(sigma)
}

/// Solve the unbonded QP by the matrix-free active-set method.
pub fn solve(ops: &Operators, settings: &QpSettings) -> Result<Solution> {
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
    let n = ops.n_sigma();
    let infeasible = || {
        Error::Infeasible(
            "no non-negative pressure balances the loads (the load resultant lies outside the reach of the plate's nodal pressures)".into(),
        )
    };
    let start = project(&vec![0.0; n], &sys.c, &sys.rf).ok_or_else(infeasible)?;
    // Its products are formed only if the first step needs them (a projected search).
    let mut point = Point::bare(start);

    let mut history: Vec<Iteration> = Vec::new();
    let mut prev_held: Option<Vec<bool>> = None;
    let mut last_tight = false;
    let mut projected_steps = 0;
    let mut cg_total = 0;
    let mut status = Status::IterationLimit {
        limit: s.max_iterations,
    };
    let mut alpha = vec![0.0; sys.c.len()];
    let mut residuals = KktResiduals::default();
    let mut iterations = 0;
    loop {
        // The reduced gradient and the KKT residuals (not needed before the first face).
        let mut g = Vec::new();
        if iterations > 0 {
            let (gr, a) = reduced_gradient(&sys, &point);
            g = gr;
            alpha = a;
            residuals = kkt(&sys, &point, &g, &alpha);
            if last_tight && residuals.natural > s.tolerance && point.alpha.is_some() {
                // The face's multiplier carries its CG's round-off; the one fitted to the
                // points in contact may meet the conditions where it did not.
                point.alpha = None;
                let (gr, a) = reduced_gradient(&sys, &point);
                let k = kkt(&sys, &point, &gr, &a);
                if k.natural <= s.tolerance {
                    (g, alpha, residuals) = (gr, a, k);
                }
            }
            if last_tight && residuals.natural <= s.tolerance {
                status = Status::Converged;
                break;
            }
        }
        if iterations >= s.max_iterations {
            break;
        }
        // The first face is the bonded problem (nothing held: any feasible point lies on it),
        // whose preconditioner was factored beside the plate.
        let held: Vec<bool> = if iterations == 0 {
            vec![false; n]
        } else {
            let g_s = gap_scale(&sys, &point, &alpha);
            point
                .sigma
                .iter()
                .zip(&g)
                .map(|(&sg, &gi)| sg == 0.0 && gi >= -s.tolerance * g_s)
                .collect()
        };
        let same = prev_held.as_ref() == Some(&held);
        if same && last_tight {
            // A tight solve on this set left the KKT residual above the tolerance and the set
            // did not move: round-off has the last word.
            status = Status::SolverFailure {
                detail: format!(
                    "the active-set QP stalled: the contact set is settled but the KKT residual {:.1e} stays above the tolerance {:.0e}",
                    residuals.natural, s.tolerance
                ),
            };
            break;
        }
        // Loose while the set moves, tight to confirm it — always tight where the
        // preconditioner is exact and a tight solve costs one CG iteration more.
        let tol = if same || sys.exact() {
            s.cg.tolerance
        } else {
            s.cg.loose_tolerance.max(s.cg.tolerance)
        };
        let face = sys.solve_face(ops, &held, &point.sigma, tol)?;
        // A loose solve that happened to meet the tight tolerance (one CG iteration with the
        // exact Winkler preconditioner) counts as tight.
        let tight = face.cg.residual <= s.cg.tolerance;
        finite(&face.sigma, "matrix-free QP")?;
        cg_total += face.cg.iterations;
        iterations += 1;
        let s_max = face.sigma.iter().cloned().fold(0.0_f64, f64::max);
        let min_free = face
            .sigma
            .iter()
            .zip(&held)
            .filter(|(_, &h)| !h)
            .map(|(&v, _)| v)
            .fold(f64::INFINITY, f64::min);
        let next = if min_free >= -s.tolerance * s_max {
            // The face minimiser is feasible up to round-off: take it, its specks of tension
            // projected away (it is its own projection when it has none).
            let x = project(&face.sigma, &sys.c, &sys.rf).ok_or_else(infeasible)?;
            let mut p = if x == face.sigma {
                Point::with_products(&sys, x, face.t_sigma, face.s_sigma)
            } else {
                Point::new(&mut sys, ops, x)
            };
            p.alpha = Some(face.alpha.clone());
            p
        } else {
            projected_steps += 1;
            point.ensure(&mut sys, ops);
            if g.is_empty() {
                g = reduced_gradient(&sys, &point).0;
            }
            projected_search(&mut sys, ops, &point, &g, &face.sigma)?
        };
        let lifted: Vec<bool> = next.sigma.iter().map(|&v| v == 0.0).collect();
        let was: Vec<bool> = point.sigma.iter().map(|&v| v == 0.0).collect();
        history.push(Iteration {
            step: iterations,
            epsilon: 0.0,
            penalised: lifted.iter().filter(|&&b| b).count(),
            entered: lifted.iter().zip(&was).filter(|(l, w)| **l && !**w).count(),
            left: lifted.iter().zip(&was).filter(|(l, w)| !**l && **w).count(),
            min_pressure: min_free,
            cg: Some(face.cg),
        });
        if lifted.iter().all(|&b| b) {
            return Err(infeasible());
        }
        point = next;
        prev_held = Some(held);
        last_tight = tight;
    }
    let sigma = point.sigma;
    let u = sys.displacements(ops, &sigma, &alpha);
    finite(&u, "matrix-free QP")?;
    let gap = discrete_gap(ops, &u, &sigma);
    let diagnostics = ActiveSetDiagnostics {
        iterations,
        cg_iterations: cg_total,
        products: sys.products,
        factorisations: sys.factorisations,
        projected_steps,
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
        iterations,
        history,
        info: SolveInfo {
            timings: Timings {
                plate_factor: Some(sys.time_plate),
                setup: Some(t_setup - sys.time_plate),
                solves: Some(total - t_setup),
                total,
                ..Timings::default()
            },
            cg_iterations: Some(cg_total),
            active_set: Some(diagnostics),
            ..SolveInfo::default()
        },
    })
}

/// The next iterate along the face direction σ* − σ: the projection P(σ + t(σ* − σ)) at the
/// first t = 1, ½, … with Armijo's decrease, f(x) ≤ f(σ) + c gᵀ(x − σ). If no t gives it
/// (an inexact face solve can make the direction useless), the projected gradient −g.
fn projected_search(
    sys: &mut IterativeSchur,
    ops: &Operators,
    point: &Point,
    g: &[f64],
    target: &[f64],
) -> Result<Point> {
    let directions = [
        target
            .iter()
            .zip(&point.sigma)
            .map(|(a, b)| a - b)
            .collect::<Vec<f64>>(),
        g.iter().map(|v| -v).collect(),
    ];
    for d in &directions {
        let mut t = 1.0;
        for _ in 0..MAX_HALVINGS {
            let y: Vec<f64> = point
                .sigma
                .iter()
                .zip(d)
                .map(|(s, di)| s + t * di)
                .collect();
            if let Some(x) = project(&y, &sys.c, &sys.rf) {
                let change: f64 = g
                    .iter()
                    .zip(x.iter().zip(&point.sigma))
                    .map(|(gi, (xi, si))| gi * (xi - si))
                    .sum();
                let trial = Point::new(sys, ops, x);
                if trial.f < point.f && trial.f <= point.f + ARMIJO * change.min(0.0) {
                    return Ok(trial);
                }
            }
            t *= 0.5;
        }
    }
    Err(Error::numerical(
        "matrix-free QP (projected search)",
        "no step along the face direction or the projected gradient decreases the objective: the KKT system is too badly conditioned here; try qp_solver = \"clarabel\"",
    ))
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

    /// A balance no non-negative σ can give (the resultant outside the points' hull) is
    /// reported as None.
    #[test]
    fn projection_reports_an_unreachable_balance() {
        let c = vec![vec![1.0; 3], vec![-1.0, 0.0, 1.0]];
        let b = vec![1.0, 2.0]; // resultant at x = 2, outside [−1, 1]
        assert!(project(&[0.0; 3], &c, &b).is_none());
    }
}
