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

use std::time::Instant;

use faer::Mat;

use super::bonded::dot;
use super::linalg::{dense_cholesky, PlateInverse, SpdSolve};
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

/// The preconditioner of one penalised set.
struct Preconditioner {
    /// 1/D per pressure node.
    inv_d: Vec<f64>,
    /// Factor of K_r + B_L D⁻¹ B_Lᵀ.
    factor: super::linalg::SparseFactor,
    /// M⁻¹ C, one column per rigid mode.
    minv_c: Vec<Vec<f64>>,
    /// Factor of Cᵀ M⁻¹ C.
    small: super::linalg::DenseLlt,
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
    /// Seconds spent factoring the plate.
    pub time_plate: f64,
    /// Preconditioner factorisations made.
    pub factorisations: usize,
}

impl IterativeSchur {
    /// Factor the plate, form h, C, Rᵀf and analyse the preconditioner's pattern.
    pub fn new(ops: &Operators, settings: CgSettings) -> Result<Self> {
        if !matches!(ops.t.as_ref(), Compliance::Toeplitz(_)) {
            return Err(Error::Unsupported(
                "the iterative route needs the half-space compliance as a Toeplitz operator (assemble with the iterative route)".into(),
            ));
        }
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
            time_plate,
            factorisations: 0,
        })
    }

    /// A p = T p + BᵀK⁻B p + Σ_k d_k g_k g_kᵀ p.
    fn apply(
        &self,
        ops: &Operators,
        rows: &[Vec<(usize, f64)>],
        weights: &[f64],
        p: &[f64],
    ) -> Vec<f64> {
        // The FFT product and the plate solve are independent: one on each core.
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

    fn preconditioner(
        &mut self,
        rows: &[Vec<(usize, f64)>],
        weights: &[f64],
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
        let inv_d: Vec<f64> = d.iter().map(|v| 1.0 / v).collect();
        let factor = self.springs.factor(&inv_d)?;
        self.factorisations += 1;
        let minv_c: Vec<Vec<f64>> = self
            .c
            .iter()
            .map(|c| self.spring_solve(&inv_d, &factor, c))
            .collect();
        let m = self.c.len();
        let ctmc = Mat::<f64>::from_fn(m, m, |a, b| dot(&self.c[a], &minv_c[b]));
        let small = dense_cholesky(&ctmc, "iterative preconditioner (Cᵀ M⁻¹ C)")?;
        Ok(Preconditioner {
            inv_d,
            factor,
            minv_c,
            small,
        })
    }

    /// M⁻¹ r.
    fn precondition(&self, pre: &Preconditioner, r: &[f64]) -> Vec<f64> {
        self.spring_solve(&pre.inv_d, &pre.factor, r)
    }

    /// M⁻¹ r ([`SpringPlate::solve`]).
    fn spring_solve(
        &self,
        inv_d: &[f64],
        factor: &super::linalg::SparseFactor,
        r: &[f64],
    ) -> Vec<f64> {
        self.springs.solve(inv_d, factor, r)
    }

    /// The projected preconditioned residual: M⁻¹r − M⁻¹C (CᵀM⁻¹C)⁻¹ CᵀM⁻¹r, which satisfies
    /// Cᵀz = 0. The projection is applied twice: the second pass removes the round-off of the
    /// first (Gould, Hribar & Nocedal's iterative refinement), which otherwise lets Cᵀσ drift.
    fn project(&self, pre: &Preconditioner, r: &[f64]) -> Vec<f64> {
        let mut z = self.precondition(pre, r);
        let m = self.c.len();
        for _ in 0..2 {
            let mut rhs = Mat::<f64>::from_fn(m, 1, |a, _| dot(&self.c[a], &z));
            pre.small.solve_in_place(rhs.as_mut());
            for a in 0..m {
                let s = rhs[(a, 0)];
                for (zi, ci) in z.iter_mut().zip(&pre.minv_c[a]) {
                    *zi -= s * ci;
                }
            }
        }
        z
    }

    /// r − C (CᵀC)⁻¹ Cᵀ r: the residual without its component along C, which the multiplier α
    /// absorbs. The projected preconditioner ignores that component in exact arithmetic, but it
    /// is large (Cα) and would cancel the digits of rᵀz.
    fn deflate(&self, ctc: &super::linalg::DenseLlt, r: &mut [f64]) {
        let m = self.c.len();
        for _ in 0..2 {
            let mut rhs = Mat::<f64>::from_fn(m, 1, |a, _| dot(&self.c[a], r));
            ctc.solve_in_place(rhs.as_mut());
            for a in 0..m {
                let s = rhs[(a, 0)];
                for (ri, ci) in r.iter_mut().zip(&self.c[a]) {
                    *ri -= s * ci;
                }
            }
        }
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
        let pre = self.preconditioner(rows, weights)?;
        let n = ops.n_sigma();
        let m = self.c.len();
        // Start: the last σ, moved onto Cᵀσ = Rᵀf along M⁻¹C.
        let mut sigma = self.warm.clone().unwrap_or_else(|| vec![0.0; n]);
        {
            let mut rhs = Mat::<f64>::from_fn(m, 1, |a, _| self.rf[a] - dot(&self.c[a], &sigma));
            pre.small.solve_in_place(rhs.as_mut());
            for a in 0..m {
                let s = rhs[(a, 0)];
                for (x, ci) in sigma.iter_mut().zip(&pre.minv_c[a]) {
                    *x += s * ci;
                }
            }
        }
        let scale = {
            let z = self.project(&pre, &self.h);
            dot(&self.h, &z).max(f64::MIN_POSITIVE).sqrt()
        };
        let ctc = Mat::<f64>::from_fn(m, m, |a, b| dot(&self.c[a], &self.c[b]));
        let ctc = dense_cholesky(&ctc, "rigid-body multipliers (CᵀC)")?;
        let mut r: Vec<f64> = self
            .apply(ops, rows, weights, &sigma)
            .iter()
            .zip(&self.h)
            .map(|(a, b)| a - b)
            .collect();
        self.deflate(&ctc, &mut r);
        let mut z = self.project(&pre, &r);
        let mut rz = dot(&r, &z);
        let mut p: Vec<f64> = z.iter().map(|v| -v).collect();
        let tol = if loose {
            self.settings.loose_tolerance.max(self.settings.tolerance)
        } else {
            self.settings.tolerance
        };
        let mut iterations = 0;
        let mut residual = rz.max(0.0).sqrt() / scale;
        while residual > tol {
            if iterations >= self.settings.max_iterations {
                return Err(Error::numerical(
                    "iterative penalty step (conjugate gradients)",
                    format!(
                        "no convergence in {} iterations (relative residual {residual:.1e}): the system is too badly conditioned for the iterative route; use solver.route = \"dense\"",
                        self.settings.max_iterations
                    ),
                ));
            }
            let ap = self.apply(ops, rows, weights, &p);
            let pap = dot(&p, &ap);
            if pap.is_nan() || pap <= 0.0 {
                return Err(Error::numerical(
                    "iterative penalty step (conjugate gradients)",
                    format!("the Schur system is not positive definite on the equilibrium subspace (pᵀAp = {pap:e})"),
                ));
            }
            let step = rz / pap;
            for i in 0..n {
                sigma[i] += step * p[i];
                r[i] += step * ap[i];
            }
            self.deflate(&ctc, &mut r);
            z = self.project(&pre, &r);
            let rz_new = dot(&r, &z);
            let beta = rz_new / rz;
            rz = rz_new;
            for i in 0..n {
                p[i] = -z[i] + beta * p[i];
            }
            iterations += 1;
            residual = rz.max(0.0).sqrt() / scale;
        }
        // α: least-squares multiplier of the recomputed residual, Aσ − h ≈ Cα.
        let mut res: Vec<f64> = self
            .apply(ops, rows, weights, &sigma)
            .iter()
            .zip(&self.h)
            .map(|(a, b)| a - b)
            .collect();
        let mut rhs = Mat::<f64>::from_fn(m, 1, |a, _| dot(&self.c[a], &res));
        ctc.solve_in_place(rhs.as_mut());
        let alpha: Vec<f64> = (0..m).map(|a| rhs[(a, 0)]).collect();
        for (a, &al) in alpha.iter().enumerate() {
            for (x, ci) in res.iter_mut().zip(&self.c[a]) {
                *x -= al * ci;
            }
        }
        let true_residual =
            dot(&res, &res).sqrt() / dot(&self.h, &self.h).max(f64::MIN_POSITIVE).sqrt();
        let u = self.displacements(ops, &sigma, &alpha);
        self.warm = Some(sigma.clone());
        Ok(Step {
            u,
            sigma,
            alpha,
            cg: CgReport {
                iterations,
                residual,
                true_residual,
            },
        })
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
