//! The unbonded QP of [`super::clarabel_dense`] without the dense Schur complement, for a diagonal
//! (Winkler) compliance T, in two exact reformulations solved by clarabel. Both keep every
//! matrix sparse, so memory grows like the plate's own factorisation instead of n_σ².
//!
//! **Lifted** (variables u, σ; the σ-QP with the plate kept as an equality):
//!
//! min ½uᵀKu + ½σᵀTσ   subject to   Ku + Bσ = f,   Gσ ≥ 0,   u = 0 on `ops.fixed`.
//!
//! With u pinned on the fixed dofs the equality has the unique solution u = K⁻(f − Bσ) exactly
//! when Rᵀ(f − Bσ) = 0, so uᵀKu = (f − Bσ)ᵀK⁻(f − Bσ) and the objective is the dense QP's
//! ½σᵀSσ − hᵀσ plus the constant ½fᵀK⁻f. (Without the pinning the u-block of the KKT matrix is
//! singular along the rigid modes.) In clarabel's form (Ax + s = b) the stationarity reads
//! K_f·u + (Kᵀy)_f = 0 and Tσ + Bᵀy − Gᵀλ = 0 for the multipliers y of the equality and λ ≥ 0
//! of Gσ ≥ 0: the first makes −y − u a rigid mode, the second then says that w = −y is the full
//! displacement (rigid part included) with gap Tσ − Bᵀw = Gᵀλ. We keep the deformation from
//! the primal u and take only the rigid amplitudes α from y on the fixed dofs, where u is zero.
//!
//! **Primal** (the Lagrange dual of the σ-QP; the pressures become multipliers). With nodal
//! constraints (G = I), variables (u, s):
//!
//! min ½uᵀKu − fᵀu + ½sᵀT⁻¹s   subject to   s − Bᵀu ≥ 0,
//!
//! whose Lagrangian with multiplier σ ≥ 0 gives Ku + Bσ = f, s = Tσ and σ·(Tσ − Bᵀu) = 0: the
//! discrete unilateral conditions, with the gap as the slack (so s = max(0, Bᵀu) at the optimum).
//! With Gauss-point constraints the general form has variables (u, z, s):
//!
//! min ½uᵀKu − fᵀu + ½sᵀT⁻¹s   subject to   s = Bᵀu + Gᵀz,   z ≥ 0.
//!
//! With multipliers μ of the equality and ν ≥ 0 of z ≥ 0 the Lagrangian gives Ku + Bμ = f,
//! T⁻¹s = μ and Gμ = ν: so σ = μ = T⁻¹s, the multiplier of z ≥ 0 is Gσ ≥ 0, the gap
//! Tσ − Bᵀu = Gᵀz with z ≥ 0 and z·Gσ = 0 — the Gauss-point conditions of the dense QP with z
//! its multiplier λ. Solved as written it converges slowly (AlmostSolved after 35 iterations on
//! a 16 × 16 half model, μ = 0.5, Γ = 0.75e-3), and with σ = T⁻¹s as the variable clarabel
//! stalls on soft soil (InsufficientProgress at 40 × 40, 200 iterations at 80 × 80 on the plate
//! of `examples/qp_forms.rs`): the equality carries T ≪ K next to the static regularisation.
//! So s is substituted, leaving a QP in (u, z) with only bounds,
//!
//! min ½uᵀKu − fᵀu + ½(Bᵀu + Gᵀz)ᵀT⁻¹(Bᵀu + Gᵀz)   subject to   z ≥ 0,
//!
//! whose u-block K + BT⁻¹Bᵀ is the (positive definite) bonded Winkler matrix; it converges in
//! 11–15 iterations there. σ = T⁻¹(Bᵀu + Gᵀz) and clarabel's multiplier of z ≥ 0 is Gσ.
//! (For nodal constraints the (u, s) form is kept: same iteration count, about 2.5× faster per
//! iteration at 120 × 120 than the substituted form.)
//!
//! The rigid modes need no pinning in the primal form: with nodal constraints K's null space is
//! held by the foundation term through the (strictly positive) interior-point scaling of the
//! constraint rows, with Gauss constraints by BT⁻¹Bᵀ, so the KKT matrix is quasi-definite
//! whenever contact is possible. Each interior-point step factors a matrix of K's size plus
//! 2 n_σ (nodal) or 2 n_c (Gauss) rows — about the cost of a penalty step.
//!
//! The lifted form has K both in P and in A, so its KKT matrix is about as ill-conditioned as
//! K²; its pressures are scaled to σ̂ = T^(1/2)σ so that T does not drown in clarabel's static
//! regularisation. Even so, on thin plates on soft soil clarabel cannot certify the default
//! tolerances: on the soft-soil plate of `examples/qp_forms.rs` it stops at AlmostSolved
//! (reported as a solver failure, σ still right to 6 digits) with one KKT solver at 40 × 40 and
//! with both from 80 × 80, and breaks down in its first iteration at 200 × 200. It is also
//! 5–10× slower than the primal form. Prefer the primal form.
//!
//! Only a diagonal T is accepted: a dense (half-space) T would make both forms dense again.

use std::time::Instant;

use clarabel::algebra::CscMatrix;
use clarabel::solver::{DefaultSolver, SolverStatus, SupportedConeT};

use super::clarabel_dense::{clarabel_settings, diagnostics};
use crate::error::{Error, Result};
use crate::foundation::Compliance;
use crate::method::{Method, QpForm, QpSettings};
use crate::model::ConstraintPoints;
use crate::monitor::Monitor;
use crate::operators::Operators;
use crate::solve::checks::discrete_gap;
use crate::solve::linalg::finite;
use crate::solve::solution::{Solution, SolveInfo, Status, Timings};

/// Which sparse reformulation of the unbonded QP to build.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SparseForm {
    /// Variables (u, σ), the plate as an equality Ku + Bσ = f.
    Lifted,
    /// Variables (u, s) (nodal) or (u, z) (Gauss): the Lagrange dual, σ are its multipliers.
    Primal,
}

impl SparseForm {
    /// Lower-case name.
    pub fn name(self) -> &'static str {
        match self {
            SparseForm::Lifted => "lifted",
            SparseForm::Primal => "primal",
        }
    }
}

/// Solve the unbonded Winkler problem as a sparse QP in the given form.
pub fn solve_sparse(ops: &Operators, settings: &QpSettings, form: SparseForm) -> Result<Solution> {
    solve_sparse_with(ops, settings, form, &Monitor::NONE)
}

/// [`solve_sparse`], stopped between interior-point iterations by `monitor`'s cancel flag.
pub fn solve_sparse_with(
    ops: &Operators,
    settings: &QpSettings,
    form: SparseForm,
    monitor: &Monitor<'_>,
) -> Result<Solution> {
    let t0 = Instant::now();
    let t = match ops.t.as_ref() {
        Compliance::Diagonal(t) => t,
        Compliance::Dense(_) | Compliance::Toeplitz(_) => {
            return Err(Error::Unsupported(
                "the sparse QP needs a diagonal (Winkler) compliance; the half-space compliance is dense, use the dense QP".into(),
            ))
        }
    };
    if let Some(j) = t.iter().position(|&v| !(v.is_finite() && v > 0.0)) {
        return Err(Error::numerical(
            "sparse QP",
            format!(
                "compliance {:e} at pressure node {j} is not positive and finite",
                t[j]
            ),
        ));
    }
    let nodal = ops.constraints.kind == ConstraintPoints::Nodal;
    let data = match form {
        SparseForm::Lifted => lifted(ops, t),
        SparseForm::Primal if nodal => primal_nodal(ops, t),
        SparseForm::Primal => primal_gauss(ops, t),
    };
    let t_assemble = t0.elapsed().as_secs_f64();

    let t1 = Instant::now();
    let mut solver = DefaultSolver::new(
        &data.p,
        &data.q,
        &data.a,
        &data.b,
        &data.cones,
        clarabel_settings(settings)?,
    )
    .map_err(|e| Error::numerical("clarabel setup", format!("{e:?}")))?;
    let t_setup = t1.elapsed().as_secs_f64();
    let t2 = Instant::now();
    super::clarabel_watched(&mut solver, monitor)?;
    let t_solve = t2.elapsed().as_secs_f64();
    let sol = &solver.solution;
    let status = match sol.status {
        SolverStatus::Solved => Status::Converged,
        SolverStatus::PrimalInfeasible
        | SolverStatus::AlmostPrimalInfeasible
        | SolverStatus::DualInfeasible
        | SolverStatus::AlmostDualInfeasible => {
            return Err(Error::Infeasible(format!(
                "clarabel proved the {} QP {:?}: no non-negative pressure balances the loads (the load resultant lies outside the plate, or the net load is upward)",
                form.name(),
                sol.status
            )))
        }
        other => Status::SolverFailure {
            detail: format!(
                "clarabel stopped with status {other:?} on the {} QP after {} iterations (primal residual {:.1e}, dual residual {:.1e})",
                form.name(),
                sol.iterations,
                sol.r_prim,
                sol.r_dual
            ),
        },
    };

    let n_eq = ops.n_eq();
    let n_sigma = ops.n_sigma();
    let n_c = ops.constraints.g.rows();
    // Each form yields (u, σ, α) and one consistency check between its primal and dual
    // estimates of the same quantity (relative): a cheap witness that the multipliers were
    // read with the right signs and that the tolerance was met.
    let (u, sigma, rigid, check) = match form {
        SparseForm::Lifted => {
            let (free, _) = free_columns(ops);
            let mut u = vec![0.0; n_eq];
            for (k, &e) in free.iter().enumerate() {
                u[e] = sol.x[k];
            }
            let sigma: Vec<f64> = sol.x[free.len()..]
                .iter()
                .zip(lifted_scaling(t))
                .map(|(x, d)| x * d)
                .collect();
            let w: Vec<f64> = sol.z[..n_eq].iter().map(|y| -y).collect();
            let alpha = rigid_amplitudes(ops, &w)?;
            add_rigid(ops, &mut u, &alpha);
            // The gap from the multipliers of Gσ ≥ 0 against T σ − Bᵀ u.
            let lambda = &sol.z[n_eq..n_eq + n_c];
            let gap_dual = gt_times(ops, lambda);
            let gap = discrete_gap(ops, &u, &sigma);
            let scale = max_abs(&ops.t.apply(&sigma)).max(f64::MIN_POSITIVE);
            (
                u,
                sigma,
                alpha,
                ("gap_mismatch", max_abs_diff(&gap, &gap_dual) / scale),
            )
        }
        SparseForm::Primal if nodal => {
            // σ is the multiplier of s − Bᵀu ≥ 0 (non-negative by construction); T⁻¹s is the
            // same at the optimum.
            let u = sol.x[..n_eq].to_vec();
            let from_s: Vec<f64> = sol.x[n_eq..].iter().zip(t).map(|(s, t)| s / t).collect();
            let sigma = sol.z[..n_sigma].to_vec();
            let mismatch = max_abs_diff(&sigma, &from_s) / max_abs(&sigma).max(f64::MIN_POSITIVE);
            let alpha = rigid_amplitudes(ops, &u)?;
            (u, sigma, alpha, ("sigma_mismatch", mismatch))
        }
        SparseForm::Primal => {
            // σ = T⁻¹(Bᵀu + Gᵀz); the multiplier of z ≥ 0 is Gσ.
            let u = sol.x[..n_eq].to_vec();
            let gtz = gt_times(ops, &sol.x[n_eq..]);
            let sigma: Vec<f64> = ops
                .bt_times(&u)
                .iter()
                .zip(&gtz)
                .zip(t)
                .zip(&ops.gap0)
                .map(|(((a, b), t), g0)| (a + b - g0) / t)
                .collect();
            let nu = &sol.z[..n_c];
            let mismatch =
                max_abs_diff(&ops.g_times(&sigma), nu) / max_abs(nu).max(f64::MIN_POSITIVE);
            let alpha = rigid_amplitudes(ops, &u)?;
            (u, sigma, alpha, ("sigma_mismatch", mismatch))
        }
    };
    finite(&sigma, "sparse QP solution")?;
    finite(&u, "sparse QP solution")?;
    let gap = discrete_gap(ops, &u, &sigma);
    Ok(Solution {
        method: Method::Qp(QpSettings {
            solver: crate::method::QpSolver::Clarabel,
            form: match form {
                SparseForm::Lifted => QpForm::Lifted,
                SparseForm::Primal => QpForm::Primal,
            },
            ..settings.clone()
        }),
        u,
        sigma,
        gap,
        rigid,
        status,
        iterations: sol.iterations as usize,
        history: Vec::new(),
        info: SolveInfo {
            timings: Timings {
                qp_setup: Some(t_assemble),
                clarabel_setup: Some(t_setup),
                clarabel: Some(t_solve),
                total: t0.elapsed().as_secs_f64(),
                ..Timings::default()
            },
            qp: Some(diagnostics(sol, Some(check))),
            ..SolveInfo::default()
        },
    })
}

/// A QP in clarabel's standard form: min ½xᵀPx + qᵀx subject to Ax + s = b, s ∈ cones.
struct QpData {
    p: CscMatrix<f64>,
    q: Vec<f64>,
    a: CscMatrix<f64>,
    b: Vec<f64>,
    cones: Vec<SupportedConeT<f64>>,
}

/// A CSC matrix built column by column, rows pushed in increasing order within a column.
struct Columns {
    rows: usize,
    colptr: Vec<usize>,
    rowval: Vec<usize>,
    nzval: Vec<f64>,
}

impl Columns {
    fn new(rows: usize, cols: usize, nnz: usize) -> Self {
        let mut colptr = Vec::with_capacity(cols + 1);
        colptr.push(0);
        Self {
            rows,
            colptr,
            rowval: Vec::with_capacity(nnz),
            nzval: Vec::with_capacity(nnz),
        }
    }

    fn push(&mut self, row: usize, value: f64) {
        self.rowval.push(row);
        self.nzval.push(value);
    }

    fn end_column(&mut self) {
        self.colptr.push(self.rowval.len());
    }

    fn finish(self) -> CscMatrix<f64> {
        let cols = self.colptr.len() - 1;
        CscMatrix::new(self.rows, cols, self.colptr, self.rowval, self.nzval)
    }
}

/// Equations that stay unknowns in the lifted form (all but `ops.fixed`), and for each equation
/// its position among them.
fn free_columns(ops: &Operators) -> (Vec<usize>, Vec<Option<usize>>) {
    let n = ops.n_eq();
    let mut map = vec![None; n];
    let mut is_fixed = vec![false; n];
    for &e in &ops.fixed {
        is_fixed[e] = true;
    }
    let mut free = Vec::with_capacity(n);
    for (e, m) in map.iter_mut().enumerate() {
        if !is_fixed[e] {
            *m = Some(free.len());
            free.push(e);
        }
    }
    (free, map)
}

/// Lifted form: x = (u_free, σ̂) with σ = d ⊙ σ̂ ([`lifted_scaling`]); rows Ku + Bσ = f (zero
/// cone), −Gσ + s = 0 (s ≥ 0).
fn lifted(ops: &Operators, t: &[f64]) -> QpData {
    let n_eq = ops.n_eq();
    let n_sigma = ops.n_sigma();
    let g = &ops.constraints.g;
    let n_c = g.rows();
    let (free, map) = free_columns(ops);
    let n_x = free.len() + n_sigma;
    let d = lifted_scaling(t);

    let mut p = Columns::new(n_x, n_x, ops.k.nnz() / 2 + n_eq + n_sigma);
    let mut a = Columns::new(n_eq + n_c, n_x, ops.k.nnz() + ops.b.nnz() + g.nnz());
    for &e in &free {
        if let Some(col) = ops.k.outer_view(e) {
            for (i, &v) in col.iter() {
                a.push(i, v);
                if let Some(r) = map[i] {
                    if i <= e {
                        p.push(r, v);
                    }
                }
            }
        }
        p.end_column();
        a.end_column();
    }
    for (j, &dj) in d.iter().enumerate() {
        // t_j d_j² = 1.
        p.push(free.len() + j, 1.0);
        p.end_column();
        if let Some(col) = ops.b.outer_view(j) {
            for (i, &v) in col.iter() {
                a.push(i, v * dj);
            }
        }
        if let Some(col) = g.outer_view(j) {
            for (c, &v) in col.iter() {
                a.push(n_eq + c, -v * dj);
            }
        }
        a.end_column();
    }
    let mut b = ops.f.clone();
    b.extend(std::iter::repeat_n(0.0, n_c));
    // The voids' initial gap adds g₀ᵀσ to the objective.
    let mut q = vec![0.0; free.len()];
    q.extend(ops.gap0.iter().zip(&d).map(|(g, d)| g * d));
    QpData {
        p: p.finish(),
        q,
        a: a.finish(),
        b,
        cones: vec![
            SupportedConeT::ZeroConeT(n_eq),
            SupportedConeT::NonnegativeConeT(n_c),
        ],
    }
}

/// Scale of the lifted form's pressure variables: σ = d ⊙ σ̂ with d = T^(−1/2), so that the
/// σ̂-block of P is the identity. Unscaled, T (1e-9 on soft soil in the unit system) sits below
/// clarabel's static regularisation (1e-8) and the answer loses digits (σ_max off by 1e-4 on
/// the 40 × 40 soft-soil plate; exact to 7 digits scaled).
fn lifted_scaling(t: &[f64]) -> Vec<f64> {
    t.iter().map(|t| 1.0 / t.sqrt()).collect()
}

/// Upper triangle of K in the first n_eq columns of `p`.
fn push_stiffness(ops: &Operators, p: &mut Columns) {
    for (j, col) in ops.k.outer_iterator().enumerate() {
        for (i, &v) in col.iter() {
            if i <= j {
                p.push(i, v);
            }
        }
        p.end_column();
    }
}

/// Primal form, nodal constraints: x = (u, s); rows Bᵀu − s + slack = 0, slack ≥ 0.
fn primal_nodal(ops: &Operators, t: &[f64]) -> QpData {
    let n_eq = ops.n_eq();
    let n_sigma = ops.n_sigma();
    let n_x = n_eq + n_sigma;
    let bt = ops.b.transpose_view().to_csc();

    let mut p = Columns::new(n_x, n_x, ops.k.nnz() / 2 + n_eq + n_sigma);
    let mut a = Columns::new(n_sigma, n_x, ops.b.nnz() + n_sigma);
    push_stiffness(ops, &mut p);
    for j in 0..n_eq {
        if let Some(col) = bt.outer_view(j) {
            for (k, &v) in col.iter() {
                a.push(k, v);
            }
        }
        a.end_column();
    }
    for (k, &tk) in t.iter().enumerate() {
        p.push(n_eq + k, 1.0 / tk);
        p.end_column();
        a.push(k, -1.0);
        a.end_column();
    }
    let mut q: Vec<f64> = ops.f.iter().map(|v| -v).collect();
    q.extend(std::iter::repeat_n(0.0, n_sigma));
    QpData {
        p: p.finish(),
        q,
        a: a.finish(),
        // s − Bᵀu + g₀ ≥ 0: the gap with the voids' initial gap.
        b: ops.gap0.clone(),
        cones: vec![SupportedConeT::NonnegativeConeT(n_sigma)],
    }
}

/// Primal form with s = Bᵀu + Gᵀz substituted: x = (u, z), objective
/// ½uᵀKu − fᵀu + ½(Bᵀu + Gᵀz)ᵀT⁻¹(Bᵀu + Gᵀz), rows −z + slack = 0, slack ≥ 0.
fn primal_gauss(ops: &Operators, t: &[f64]) -> QpData {
    let n_eq = ops.n_eq();
    let n_sigma = ops.n_sigma();
    let g = &ops.constraints.g;
    let n_c = g.rows();
    let n_x = n_eq + n_c;
    let bt = ops.b.transpose_view().to_csc();
    let gt = g.transpose_view().to_csc();
    let scale: Vec<f64> = t.iter().map(|t| 1.0 / t.sqrt()).collect();
    // J = T^(−1/2) [Bᵀ Gᵀ] (n_σ × n_x).
    let mut j = Columns::new(n_sigma, n_x, ops.b.nnz() + g.nnz());
    for m in [&bt, &gt] {
        for col in m.outer_iterator() {
            for (k, &v) in col.iter() {
                j.push(k, v * scale[k]);
            }
            j.end_column();
        }
    }
    let j = sprs::CsMat::new_csc((n_sigma, n_x), j.colptr, j.rowval, j.nzval);
    let jtj: sprs::CsMat<f64> = &j.transpose_view() * &j;
    let jtj = jtj.to_csc();
    let mut indptr = ops.k.indptr().to_proper().to_vec();
    let last = indptr.last().copied().unwrap_or(0);
    indptr.resize(n_x + 1, last);
    let k = sprs::CsMat::new_csc(
        (n_x, n_x),
        indptr,
        ops.k.indices().to_vec(),
        ops.k.data().to_vec(),
    );
    let m: sprs::CsMat<f64> = &k + &jtj;
    let mut p = Columns::new(n_x, n_x, m.nnz() / 2 + n_x);
    for (jj, col) in m.outer_iterator().enumerate() {
        for (i, &v) in col.iter() {
            if i <= jj {
                p.push(i, v);
            }
        }
        p.end_column();
    }
    let mut a = Columns::new(n_c, n_x, n_c);
    for _ in 0..n_eq {
        a.end_column();
    }
    for c in 0..n_c {
        a.push(c, -1.0);
        a.end_column();
    }
    // With voids s = Bᵀu + Gᵀz − g₀: the objective gains −xᵀ[B; G]T⁻¹g₀.
    let tg: Vec<f64> = ops.gap0.iter().zip(t).map(|(g, t)| g / t).collect();
    let mut q: Vec<f64> = ops
        .f
        .iter()
        .zip(ops.b_times(&tg))
        .map(|(f, v)| -f - v)
        .collect();
    q.extend(ops.g_times(&tg).iter().map(|v| -v));
    QpData {
        p: p.finish(),
        q,
        a: a.finish(),
        b: vec![0.0; n_c],
        cones: vec![SupportedConeT::NonnegativeConeT(n_c)],
    }
}

/// Rigid amplitudes α with u = K⁻(f − Bσ) + Rα, read on the fixed equations where K⁻ is zero:
/// R[fixed, :] α = v[fixed] (a square system: one fixed equation per mode, chosen so that it is
/// nonsingular — non-collinear corners of a plate of one piece, pivoted rows of a jointed one).
fn rigid_amplitudes(ops: &Operators, v: &[f64]) -> Result<Vec<f64>> {
    let m = ops.rigid.len();
    let r = nalgebra::DMatrix::from_fn(m, m, |i, k| ops.rigid[k][ops.fixed[i]]);
    let rhs = nalgebra::DVector::from_fn(m, |i, _| v[ops.fixed[i]]);
    r.lu()
        .solve(&rhs)
        .map(|a| a.iter().copied().collect())
        .ok_or_else(|| {
            Error::numerical(
                "sparse QP",
                "the fixed equations do not determine the rigid modes",
            )
        })
}

/// u += Rα.
fn add_rigid(ops: &Operators, u: &mut [f64], alpha: &[f64]) {
    for (mode, &a) in ops.rigid.iter().zip(alpha) {
        for (ui, ri) in u.iter_mut().zip(mode) {
            *ui += a * ri;
        }
    }
}

/// Gᵀλ.
fn gt_times(ops: &Operators, lambda: &[f64]) -> Vec<f64> {
    ops.constraints
        .g
        .outer_iterator()
        .map(|col| col.iter().map(|(c, &v)| v * lambda[c]).sum())
        .collect()
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |m: f64, x| m.max(x.abs()))
}

fn max_abs_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .fold(0.0, |m: f64, (x, y)| m.max((x - y).abs()))
}
