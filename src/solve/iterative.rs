//! The half-space penalty step without dense matrices: preconditioned conjugate gradients on the
//! Schur system with the rigid-body equilibrium as constraints.
//!
//! Each step of the penalty iteration (and the bonded solve, its first step) solves
//!
//! A σ − C α = h,   Cᵀ σ = Rᵀ f,   A = T + BᵀK⁻B + Σ_k d_k g_k g_kᵀ,
//!
//! (h = BᵀK⁻f − g₀ with the voids' initial gap g₀, C = BᵀR, d_k = c w_k/ε̄ on the penalised points, [`super::bonded`]). A is never
//! formed: a product costs one FFT product with T ([`crate::foundation::fft`]), one solve with the
//! plate factor (K factored once with its rigid modes fixed, [`PlateInverse`]) and the sparse
//! penalty. The equality is kept by projected CG (Gould, Hribar & Nocedal 2001): the iterates
//! stay on Cᵀσ = Rᵀf, the preconditioned residual is projected onto Cᵀp = 0 in the
//! preconditioner's inner product, and α is the least-squares multiplier of the final residual.
//! On that subspace BᵀK⁻B does not depend on which generalised inverse K⁻ is (Bp is orthogonal to
//! the rigid modes), so the iteration sees the true plate compliance.
//!
//! **Preconditioner: the plate on springs** ([`super::springs`]): M = D + QᵀK_p⁻Q with D the
//! springs λ·diag(T) (a Winkler bed matched to the half-space's own point stiffness) plus the
//! penalty's diagonal, and K_p the plate — by default on a grid twice as coarse. M holds the
//! plate exactly at the long wavelengths where it dominates A (its free edges and its low
//! modes) and the penalty exactly where it is diagonal (nodal constraints), so only the
//! half-space's non-local part is left to the iteration; M⁻¹ is one sparse solve.
//!
//! Each step starts from the previous step's σ (warm start), so the later penalty steps, which
//! change a few points, take few iterations; steps whose set is still moving are solved to a
//! loose tolerance ([`CgSettings::loose_tolerance`]), and the penalty iteration confirms a set
//! only with a tight solve.
//!
//! **Face solves** ([`IterativeSchur::solve_face`]) serve the matrix-free QP
//! ([`super::active_set`]): the same system without penalty, with a set of pressures held at
//! zero (the lifted points). The iteration then runs on the free points only: the product, the
//! residual and the rigid-mode columns C are restricted to them, and the preconditioner drops
//! its springs there (1/D = 0, which makes the Woodbury solve exactly (M_FF)⁻¹). The free
//! points' columns of C can be dependent (a plate resting on one node); the small rigid-mode
//! systems are solved by pseudo-inverse ([`SmallSpd`]), which keeps the iterates on the
//! equilibrium the free points can carry.

use std::time::Instant;

use super::bonded::dot;
use super::linalg::{PlateInverse, SmallSpd, SparseFactor};
use super::springs::SpringPlate;
use crate::error::{Error, Result};
use crate::foundation::Compliance;
pub use crate::method::CgSettings;
use crate::operators::Operators;

/// How one linear solve went.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct CgReport {
    /// Conjugate-gradient iterations.
    pub iterations: usize,
    /// Final relative preconditioned residual.
    pub residual: f64,
    /// Relative residual ‖Aσ − Cα − h‖ / ‖h‖ of the returned solution, recomputed.
    pub true_residual: f64,
}

/// The solution of one linear step.
#[derive(Debug, Clone)]
pub struct Step {
    /// Plate dofs u = K⁻(f − Bσ) + Rα.
    pub u: Vec<f64>,
    /// Nodal pressures.
    pub sigma: Vec<f64>,
    /// Rigid-body amplitudes.
    pub alpha: Vec<f64>,
    /// How the conjugate gradients went.
    pub cg: CgReport,
}

/// The solution of a face solve: the pressures that minimise ½σᵀSσ − hᵀσ on the equilibrium
/// Cᵀσ = Rᵀf with the held points at zero.
#[derive(Debug, Clone)]
pub struct Face {
    /// Nodal pressures (zero on the held points).
    pub sigma: Vec<f64>,
    /// Rigid-body amplitudes: the least-squares multiplier on the free points.
    pub alpha: Vec<f64>,
    /// How the conjugate gradients went.
    pub cg: CgReport,
}

/// The preconditioner of one penalised set (and held set).
struct Preconditioner {
    /// 1/D per pressure node (0 on held points).
    inv_d: Vec<f64>,
    /// Factor of K_r + B_L D⁻¹ B_Lᵀ.
    factor: SparseFactor,
    /// The rigid-mode columns C restricted to the free points.
    c: Vec<Vec<f64>>,
    /// M⁻¹ C, one column per rigid mode.
    minv_c: Vec<Vec<f64>>,
    /// Pseudo-inverse of Cᵀ M⁻¹ C.
    small: SmallSpd,
    /// Pseudo-inverse of Cᵀ C.
    ctc: SmallSpd,
    /// The held points it was made for (empty: none).
    held: Vec<bool>,
}

/// The Schur system of the half-space with a matrix-free T, ready for penalty steps.
pub struct IterativeSchur {
    settings: CgSettings,
    kinv: PlateInverse,
    /// h = BᵀK⁻f.
    pub h: Vec<f64>,
    /// C = BᵀR.
    pub c: Vec<Vec<f64>>,
    /// Rᵀf.
    pub rf: Vec<f64>,
    /// diag(T).
    t_diag: Vec<f64>,
    /// The preconditioner's plate on springs.
    springs: SpringPlate,
    /// The last step's σ, the next one's start.
    warm: Option<Vec<f64>>,
    /// The last face solve's preconditioner, reused while the held set stays.
    face_pre: Option<Preconditioner>,
    /// Seconds spent factoring the plate.
    pub time_plate: f64,
    /// Preconditioner factorisations made.
    pub factorisations: usize,
    /// Products with the Schur matrix made.
    pub products: usize,
}

impl IterativeSchur {
    /// Factor the plate, form h, C, Rᵀf and analyse the preconditioner's pattern, for the
    /// penalty steps of the iterative route (T must be the FFT operator).
    pub fn new(ops: &Operators, settings: CgSettings) -> Result<Self> {
        if !matches!(ops.t.as_ref(), Compliance::Toeplitz(_)) {
            return Err(Error::Unsupported(
                "the iterative route needs the half-space compliance as a Toeplitz operator (assemble with the iterative route)".into(),
            ));
        }
        Self::with_any_compliance(ops, settings)
    }

    /// As [`Self::new`] for any compliance: diagonal (Winkler), dense or FFT. Only products
    /// with T and its diagonal are used.
    pub fn with_any_compliance(ops: &Operators, settings: CgSettings) -> Result<Self> {
        let t0 = Instant::now();
        let kinv = PlateInverse::new(ops)?;
        let time_plate = t0.elapsed().as_secs_f64();
        // h = BᵀK⁻f − g₀: the voids' initial gap enters as g = Aσ − Cα − h.
        let h = ops
            .bt_times(&kinv.apply(&ops.f))
            .iter()
            .zip(&ops.gap0)
            .map(|(a, g)| a - g)
            .collect();
        let c: Vec<Vec<f64>> = ops.rigid.iter().map(|r| ops.bt_times(r)).collect();
        let rf = ops.rigid.iter().map(|r| dot(r, &ops.f)).collect();
        let springs = SpringPlate::new(ops, settings.coarse_plate)?;
        Ok(Self {
            settings,
            kinv,
            h,
            c,
            rf,
            t_diag: ops.t.diagonal(),
            springs,
            warm: None,
            face_pre: None,
            time_plate,
            factorisations: 0,
            products: 0,
        })
    }

    /// S p = T p + BᵀK⁻B p, the Schur matrix without penalty.
    pub fn s_times(&mut self, ops: &Operators, p: &[f64]) -> Vec<f64> {
        self.apply(ops, &[], &[], p)
    }

    /// A p = T p + BᵀK⁻B p + Σ_k d_k g_k g_kᵀ p.
    fn apply(
        &mut self,
        ops: &Operators,
        rows: &[Vec<(usize, f64)>],
        weights: &[f64],
        p: &[f64],
    ) -> Vec<f64> {
        self.products += 1;
        // The product with T and the plate solve are independent: one on each core.
        let kinv = &self.kinv;
        let (mut y, plate) = std::thread::scope(|s| {
            let t = s.spawn(|| ops.t.apply(p));
            let plate = ops.bt_times(&kinv.apply(&ops.b_times(p)));
            match t.join() {
                Ok(y) => (y, plate),
                Err(panic) => std::panic::resume_unwind(panic),
            }
        });
        for (yi, v) in y.iter_mut().zip(&plate) {
            *yi += v;
        }
        for (k, &d) in weights.iter().enumerate() {
            if d != 0.0 {
                let gp: f64 = rows[k].iter().map(|&(i, v)| v * p[i]).sum();
                for &(i, v) in &rows[k] {
                    y[i] += d * v * gp;
                }
            }
        }
        y
    }

    /// The preconditioner for penalty weights on `rows` and the points `held` at zero (empty:
    /// none).
    fn preconditioner(
        &mut self,
        rows: &[Vec<(usize, f64)>],
        weights: &[f64],
        held: &[bool],
    ) -> Result<Preconditioner> {
        let mut d: Vec<f64> = self
            .t_diag
            .iter()
            .map(|t| self.settings.spring_scale * t)
            .collect();
        for (k, &w) in weights.iter().enumerate() {
            if w != 0.0 {
                for &(i, v) in &rows[k] {
                    d[i] += w * v * v;
                }
            }
        }
        let is_held = |i: usize| held.get(i).copied().unwrap_or(false);
        let inv_d: Vec<f64> = d
            .iter()
            .enumerate()
            .map(|(i, v)| if is_held(i) { 0.0 } else { 1.0 / v })
            .collect();
        let factor = self.springs.factor(&inv_d)?;
        self.factorisations += 1;
        let c: Vec<Vec<f64>> = self
            .c
            .iter()
            .map(|col| {
                col.iter()
                    .enumerate()
                    .map(|(i, &v)| if is_held(i) { 0.0 } else { v })
                    .collect()
            })
            .collect();
        let minv_c: Vec<Vec<f64>> = c
            .iter()
            .map(|col| self.springs.solve(&inv_d, &factor, col))
            .collect();
        let m = c.len();
        let small = SmallSpd::new(m, |a, b| dot(&c[a], &minv_c[b]));
        let ctc = SmallSpd::new(m, |a, b| dot(&c[a], &c[b]));
        Ok(Preconditioner {
            inv_d,
            factor,
            c,
            minv_c,
            small,
            ctc,
            held: held.to_vec(),
        })
    }

    /// The projected preconditioned residual: M⁻¹r − M⁻¹C (CᵀM⁻¹C)⁻¹ CᵀM⁻¹r, which satisfies
    /// Cᵀz = 0. The projection is applied twice: the second pass removes the round-off of the
    /// first (Gould, Hribar & Nocedal's iterative refinement), which otherwise lets Cᵀσ drift.
    fn project(&self, pre: &Preconditioner, r: &[f64]) -> Vec<f64> {
        let mut z = self.springs.solve(&pre.inv_d, &pre.factor, r);
        for _ in 0..2 {
            let ctz: Vec<f64> = pre.c.iter().map(|c| dot(c, &z)).collect();
            let s = pre.small.solve(&ctz);
            for (a, &sa) in s.iter().enumerate() {
                for (zi, ci) in z.iter_mut().zip(&pre.minv_c[a]) {
                    *zi -= sa * ci;
                }
            }
        }
        z
    }

    /// r − C (CᵀC)⁻¹ Cᵀ r: the residual without its component along C, which the multiplier α
    /// absorbs. The projected preconditioner ignores that component in exact arithmetic, but it
    /// is large (Cα) and would cancel the digits of rᵀz.
    fn deflate(pre: &Preconditioner, r: &mut [f64]) {
        for _ in 0..2 {
            let ctr: Vec<f64> = pre.c.iter().map(|c| dot(c, r)).collect();
            let s = pre.ctc.solve(&ctr);
            for (a, &sa) in s.iter().enumerate() {
                for (ri, ci) in r.iter_mut().zip(&pre.c[a]) {
                    *ri -= sa * ci;
                }
            }
        }
    }

    /// Zero the held points of `v`.
    fn mask(pre: &Preconditioner, v: &mut [f64]) {
        for (x, &h) in v.iter_mut().zip(&pre.held) {
            if h {
                *x = 0.0;
            }
        }
    }

    /// Projected PCG from `sigma` (made feasible first) to the relative tolerance `tol`;
    /// returns σ, α and the account.
    fn cg(
        &mut self,
        ops: &Operators,
        pre: &Preconditioner,
        rows: &[Vec<(usize, f64)>],
        weights: &[f64],
        mut sigma: Vec<f64>,
        tol: f64,
        stage: &str,
    ) -> Result<(Vec<f64>, Vec<f64>, CgReport)> {
        let n = ops.n_sigma();
        Self::mask(pre, &mut sigma);
        // Start: σ moved onto Cᵀσ = Rᵀf along M⁻¹C.
        {
            let defect: Vec<f64> = (0..pre.c.len())
                .map(|a| self.rf[a] - dot(&pre.c[a], &sigma))
                .collect();
            let s = pre.small.solve(&defect);
            for (a, &sa) in s.iter().enumerate() {
                for (x, ci) in sigma.iter_mut().zip(&pre.minv_c[a]) {
                    *x += sa * ci;
                }
            }
        }
        let mut h = self.h.clone();
        Self::mask(pre, &mut h);
        let h_norm = dot(&h, &h).max(f64::MIN_POSITIVE).sqrt();
        let scale = {
            let z = self.project(pre, &h);
            dot(&h, &z).max(f64::MIN_POSITIVE).sqrt()
        };
        let mut r: Vec<f64> = self
            .apply(ops, rows, weights, &sigma)
            .iter()
            .zip(&self.h)
            .map(|(a, b)| a - b)
            .collect();
        Self::mask(pre, &mut r);
        Self::deflate(pre, &mut r);
        let mut z = self.project(pre, &r);
        let mut rz = dot(&r, &z);
        let mut p: Vec<f64> = z.iter().map(|v| -v).collect();
        let mut iterations = 0;
        let mut residual = rz.max(0.0).sqrt() / scale;
        while residual > tol {
            if iterations >= self.settings.max_iterations {
                return Err(Error::numerical(
                    stage,
                    format!(
                        "no convergence in {} iterations (relative residual {residual:.1e}): the system is too badly conditioned for the iterative route; use solver.route = \"dense\"",
                        self.settings.max_iterations
                    ),
                ));
            }
            let mut ap = self.apply(ops, rows, weights, &p);
            Self::mask(pre, &mut ap);
            let pap = dot(&p, &ap);
            if pap.is_nan() || pap <= 0.0 {
                return Err(Error::numerical(
                    stage,
                    format!("the Schur system is not positive definite on the equilibrium subspace (pᵀAp = {pap:e})"),
                ));
            }
            let step = rz / pap;
            for i in 0..n {
                sigma[i] += step * p[i];
                r[i] += step * ap[i];
            }
            Self::deflate(pre, &mut r);
            z = self.project(pre, &r);
            let rz_new = dot(&r, &z);
            let beta = rz_new / rz;
            rz = rz_new;
            for i in 0..n {
                p[i] = -z[i] + beta * p[i];
            }
            iterations += 1;
            residual = rz.max(0.0).sqrt() / scale;
        }
        // α: least-squares multiplier of the recomputed residual on the free points,
        // Aσ − h ≈ Cα.
        let mut res: Vec<f64> = self
            .apply(ops, rows, weights, &sigma)
            .iter()
            .zip(&self.h)
            .map(|(a, b)| a - b)
            .collect();
        Self::mask(pre, &mut res);
        let ctr: Vec<f64> = pre.c.iter().map(|c| dot(c, &res)).collect();
        let alpha = pre.ctc.solve(&ctr);
        for (a, &al) in alpha.iter().enumerate() {
            for (x, ci) in res.iter_mut().zip(&pre.c[a]) {
                *x -= al * ci;
            }
        }
        let true_residual = dot(&res, &res).sqrt() / h_norm;
        Ok((
            sigma,
            alpha,
            CgReport {
                iterations,
                residual,
                true_residual,
            },
        ))
    }

    /// Solve one penalised step: `weights[k]` = d_k on constraint point k (0 if not penalised),
    /// `rows[k]` = g_k. Returns u, σ, α and the CG account.
    pub fn solve(
        &mut self,
        ops: &Operators,
        rows: &[Vec<(usize, f64)>],
        weights: &[f64],
        loose: bool,
    ) -> Result<Step> {
        let pre = self.preconditioner(rows, weights, &[])?;
        let start = self
            .warm
            .clone()
            .unwrap_or_else(|| vec![0.0; ops.n_sigma()]);
        let tol = if loose {
            self.settings.loose_tolerance.max(self.settings.tolerance)
        } else {
            self.settings.tolerance
        };
        let (sigma, alpha, cg) = self.cg(
            ops,
            &pre,
            rows,
            weights,
            start,
            tol,
            "iterative penalty step (conjugate gradients)",
        )?;
        let u = self.displacements(ops, &sigma, &alpha);
        self.warm = Some(sigma.clone());
        Ok(Step {
            u,
            sigma,
            alpha,
            cg,
        })
    }

    /// Minimise ½σᵀSσ − hᵀσ subject to Cᵀσ = Rᵀf and σ = 0 on the `held` points, from
    /// `start`, to the relative tolerance `tol`. The preconditioner of the last face solve is
    /// reused while the held set is the same.
    pub fn solve_face(
        &mut self,
        ops: &Operators,
        held: &[bool],
        start: &[f64],
        tol: f64,
    ) -> Result<Face> {
        let pre = match self.face_pre.take() {
            Some(pre) if pre.held == held => pre,
            _ => self.preconditioner(&[], &[], held)?,
        };
        let out = self.cg(
            ops,
            &pre,
            &[],
            &[],
            start.to_vec(),
            tol,
            "matrix-free QP (conjugate gradients on the free points)",
        );
        self.face_pre = Some(pre);
        let (sigma, alpha, cg) = out?;
        Ok(Face { sigma, alpha, cg })
    }

    /// u = K⁻(f − Bσ) + Rα.
    pub fn displacements(&self, ops: &Operators, sigma: &[f64], alpha: &[f64]) -> Vec<f64> {
        super::bonded::displacements(ops, &self.kinv, sigma, alpha)
    }

    /// "fine" or "coarse": the preconditioner's plate.
    pub fn preconditioner_plate(&self) -> &'static str {
        self.springs.kind
    }
}
