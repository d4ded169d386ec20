//! A feasible iterate of the active-set method and what the KKT conditions say about it: the
//! reduced gradient, the rigid-body multiplier (the smallest turn where the contact does not
//! fix the rigid modes), the scale of the gaps and the KKT residuals.

use crate::operators::Operators;
use crate::solve::diagnostics::KktResiduals;
use crate::solve::iterative::IterativeSchur;
use crate::solve::linalg::{dot, SmallSpd};

/// A feasible iterate with the products the next step needs.
pub(super) struct Point {
    pub(super) sigma: Vec<f64>,
    /// T σ.
    pub(super) t_sigma: Vec<f64>,
    /// S σ.
    pub(super) s_sigma: Vec<f64>,
    /// f(σ) = ½ σᵀSσ − hᵀσ.
    pub(super) f: f64,
    /// The rigid-body amplitudes of the face solve when σ is its minimiser: the multiplier of
    /// the equilibrium on the whole free set, where the points in contact alone may not fix
    /// it (a plate resting on one node can turn about it).
    pub(super) alpha: Option<Vec<f64>>,
}

impl Point {
    pub(super) fn new(sys: &mut IterativeSchur, ops: &Operators, sigma: Vec<f64>) -> Self {
        let (t_sigma, s_sigma) = sys.t_and_s_times(ops, &sigma);
        Self::with_products(sys, sigma, t_sigma, s_sigma)
    }

    pub(super) fn with_products(
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
pub(super) fn reduced_gradient(sys: &IterativeSchur, p: &Point) -> (Vec<f64>, Vec<f64>) {
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
/// lifted point above the soil, min |β|² subject to gᵢ(β) ≥ 0 where σᵢ = 0: a QP in as many
/// unknowns as the contact leaves free (at most two on a plate of one piece; a jointed plate's
/// hanging panels add theirs), solved by clarabel. If no turn does, the least-squares α₀ is returned and
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
pub(super) fn gap_scale(sys: &IterativeSchur, p: &Point, alpha: &[f64]) -> f64 {
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
pub(super) fn kkt(sys: &IterativeSchur, p: &Point, g: &[f64], alpha: &[f64]) -> KktResiduals {
    residuals(&p.sigma, g, gap_scale(sys, p, alpha), &sys.c, &sys.rf)
}

/// The KKT residuals of pressures `sigma` with gaps `g` of scale `g_s`, and the rigid-body
/// equilibrium Cᵀσ = Rᵀf (`c`, `rf`), each relative to its scale.
pub(super) fn residuals(
    sigma: &[f64],
    g: &[f64],
    g_s: f64,
    c: &[Vec<f64>],
    rf: &[f64],
) -> KktResiduals {
    let s_max = sigma
        .iter()
        .cloned()
        .fold(0.0_f64, f64::max)
        .max(f64::MIN_POSITIVE);
    let mut k = KktResiduals::default();
    for (&s, &gi) in sigma.iter().zip(g) {
        k.natural = k.natural.max((s / s_max).min(gi / g_s).abs());
        if s > 0.0 {
            k.stationarity = k.stationarity.max(gi.abs() / g_s);
        } else {
            k.penetration = k.penetration.max(-gi / g_s);
        }
        k.complementarity = k.complementarity.max((s * gi).abs() / (s_max * g_s));
    }
    let b_max = rf.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
    k.equilibrium = c
        .iter()
        .zip(rf)
        .map(|(c, b)| (dot(c, sigma) - b).abs())
        .fold(0.0, f64::max)
        / b_max.max(f64::MIN_POSITIVE);
    k
}
