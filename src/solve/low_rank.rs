//! The half-space penalty step without a dense factorisation per step.
//!
//! Each step solves with S + Σ(P)/ε̄, where S = T + BᵀK⁻B is dense and fixed, and the penalty
//! Σ(P)/ε̄ = Σ_k d_k g_k g_kᵀ adds one rank-one term per penalised constraint point k (g_k the
//! row of G, d_k = c w_k / ε̄). Between steps only a few points change, so the matrix of a step is
//! a low-rank change of the last one factored, A = S + Σ_k d⁰_k g_k g_kᵀ:
//!
//! (A + U D Uᵀ)⁻¹ b = y − Z (D⁻¹ + Uᵀ Z)⁻¹ Uᵀ y,   y = A⁻¹ b,  Z = A⁻¹ U
//!
//! (Sherman–Morrison–Woodbury), with U the g_k of the points whose weight changed and D the
//! changes δ_k = d_k − d⁰_k (positive for points that entered, negative for points that left).
//! The columns A⁻¹ g_k depend only on A, so they are kept and reused by later steps; a step costs
//! the new columns (two triangular solves each) and a small dense LU, not an O(n³) factorisation.
//! When the changed set grows past [`max_rank`], or a weight changes by more than
//! [`MAX_WEIGHT_RATIO`] times the point's own stiffness (the update would cancel digits), the
//! current matrix is factored afresh.

use std::collections::HashMap;

use faer::Mat;

use super::linalg::{dense_cholesky, DenseLlt, SpdSolve};
use super::spring_factor::missing_keys;
use crate::error::{Error, Result};

/// Most changed points solved by an update: past n/8 columns the triangular solves cost about as
/// much as a new factorisation (2n²k against n³/3 flops, but the factorisation runs at BLAS-3
/// speed).
pub fn max_rank(n: usize) -> usize {
    (n / 8).max(16)
}

/// Largest weight change, relative to gᵀSg, that an update may apply (see `prepare`).
pub const MAX_WEIGHT_RATIO: f64 = 1e8;

/// A factor of S + Σ_k d⁰_k g_k g_kᵀ and the columns A⁻¹ g_k computed so far.
pub struct LowRankSchur {
    base: Option<Base>,
    /// Dense factorisations made (the first and every refresh).
    pub factorisations: usize,
    /// Steps solved by an update of the last factor.
    pub updates: usize,
}

struct Base {
    llt: DenseLlt,
    /// d⁰_k per constraint point (0 where not penalised).
    weights: Vec<f64>,
    /// Columns A⁻¹ g_k, by constraint point.
    columns: HashMap<usize, Vec<f64>>,
}

/// A solver for one step: the base factor plus the correction of the changed points.
pub struct Updated<'a> {
    base: &'a Base,
    /// (point, δ_k) of the changed points.
    changed: Vec<(usize, f64)>,
    rows: &'a [Vec<(usize, f64)>],
    /// LU of D⁻¹ + Uᵀ Z.
    small: Option<faer::linalg::solvers::PartialPivLu<f64>>,
}

impl LowRankSchur {
    /// Nothing factored yet.
    pub fn new() -> Self {
        Self {
            base: None,
            factorisations: 0,
            updates: 0,
        }
    }

    /// A solver for S + Σ_k d_k g_k g_kᵀ, `rows[k]` = g_k as (σ index, value), `weights[k]` = d_k.
    pub fn prepare<'a>(
        &'a mut self,
        s: &Mat<f64>,
        rows: &'a [Vec<(usize, f64)>],
        weights: &[f64],
    ) -> Result<Updated<'a>> {
        let n = s.nrows();
        let changed: Option<Vec<(usize, f64)>> = self.base.as_ref().map(|b| {
            weights
                .iter()
                .zip(&b.weights)
                .enumerate()
                .filter(|(_, (d, d0))| d != d0)
                .map(|(k, (d, d0))| (k, d - d0))
                .collect()
        });
        // An update by a weight d much larger than the point's own stiffness gᵀSg computes the
        // point's O(1/d) pressure as the difference of O(1) terms, losing about
        // log₁₀(d / gᵀSg) digits (removing such a weight cancels it against A⁻¹'s 1/d as
        // well); past 1e8 the matrix is factored afresh.
        let cancels = |c: &[(usize, f64)]| {
            c.iter().any(|&(k, delta)| {
                let own: f64 = rows[k].iter().map(|&(i, v)| v * v * s[(i, i)]).sum();
                delta.abs() > MAX_WEIGHT_RATIO * own
            })
        };
        let refactor = match &changed {
            None => true,
            Some(c) => c.len() > max_rank(n) || cancels(c),
        };
        if refactor {
            let mut a = s.clone();
            for (k, &d) in weights.iter().enumerate() {
                if d != 0.0 {
                    for &(i, vi) in &rows[k] {
                        for &(j, vj) in &rows[k] {
                            a[(i, j)] += d * vi * vj;
                        }
                    }
                }
            }
            let llt = dense_cholesky(&a, "penalised Schur complement")?;
            self.factorisations += 1;
            self.base = Some(Base {
                llt,
                weights: weights.to_vec(),
                columns: HashMap::new(),
            });
        } else {
            self.updates += 1;
        }
        let changed = if refactor {
            Vec::new()
        } else {
            changed.unwrap_or_default()
        };
        let base = self
            .base
            .as_mut()
            .ok_or_else(|| Error::numerical("penalty (low-rank update)", "no factor"))?;
        // New columns A⁻¹ g_k, solved together.
        let missing = missing_keys(&changed, &base.columns);
        if !missing.is_empty() {
            let mut z = Mat::<f64>::zeros(n, missing.len());
            for (c, &k) in missing.iter().enumerate() {
                for &(i, v) in &rows[k] {
                    z[(i, c)] = v;
                }
            }
            base.llt.solve_in_place(z.as_mut());
            for (c, &k) in missing.iter().enumerate() {
                base.columns.insert(k, z.col(c).iter().copied().collect());
            }
        }
        let base = &*base;
        let small = if changed.is_empty() {
            None
        } else {
            let m = changed.len();
            let mat = Mat::<f64>::from_fn(m, m, |a, b| {
                let (ka, da) = changed[a];
                let zb = &base.columns[&changed[b].0];
                let dot: f64 = rows[ka].iter().map(|&(i, v)| v * zb[i]).sum();
                dot + if a == b { 1.0 / da } else { 0.0 }
            });
            Some(mat.partial_piv_lu())
        };
        Ok(Updated {
            base,
            changed,
            rows,
            small,
        })
    }
}

impl Default for LowRankSchur {
    fn default() -> Self {
        Self::new()
    }
}

impl SpdSolve for Updated<'_> {
    fn solve_in_place(&self, mut rhs: faer::MatMut<'_, f64>) {
        self.base.llt.solve_in_place(rhs.as_mut());
        let Some(lu) = &self.small else {
            return;
        };
        let m = self.changed.len();
        for c in 0..rhs.ncols() {
            // w = (D⁻¹ + UᵀZ)⁻¹ Uᵀ y; y −= Z w.
            let mut w = Mat::<f64>::from_fn(m, 1, |a, _| {
                self.rows[self.changed[a].0]
                    .iter()
                    .map(|&(i, v)| v * rhs[(i, c)])
                    .sum()
            });
            faer::linalg::solvers::SolveCore::solve_in_place_with_conj(
                lu,
                faer::Conj::No,
                w.as_mut(),
            );
            for (a, &(k, _)) in self.changed.iter().enumerate() {
                let z = &self.base.columns[&k];
                let wa = w[(a, 0)];
                for (i, zi) in z.iter().enumerate() {
                    rhs[(i, c)] -= zi * wa;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every prepare either factors afresh or updates the last factor, and the counters say
    /// which: the first call factors, a change of one weight is an update (rank 1 ≤ 16), and the
    /// updated solve equals the solve of the matrix formed and factored directly (to 1e-12:
    /// Woodbury on a well-conditioned 6 × 6 system, condition ≤ 3).
    #[test]
    fn prepare_counts_factorisations_and_updates() {
        let n = 6;
        let s = Mat::<f64>::from_fn(n, n, |i, j| {
            if i == j {
                2.0
            } else if i.abs_diff(j) == 1 {
                -0.5
            } else {
                0.0
            }
        });
        let rows: Vec<Vec<(usize, f64)>> = (0..n).map(|k| vec![(k, 1.0)]).collect();
        let mut lr = LowRankSchur::new();
        let mut weights = vec![0.0; n];
        lr.prepare(&s, &rows, &weights).expect("first");
        assert_eq!((lr.factorisations, lr.updates), (1, 0));
        weights[2] = 0.75;
        let rhs: Vec<f64> = (0..n).map(|i| 1.0 + i as f64).collect();
        let mut x = rhs.clone();
        lr.prepare(&s, &rows, &weights)
            .expect("update")
            .solve_in_place(faer::MatMut::from_column_major_slice_mut(&mut x, n, 1));
        assert_eq!((lr.factorisations, lr.updates), (1, 1));
        let mut a = s.clone();
        a[(2, 2)] += 0.75;
        let mut y = rhs.clone();
        dense_cholesky(&a, "test")
            .expect("direct")
            .solve_in_place(faer::MatMut::from_column_major_slice_mut(&mut y, n, 1));
        for (p, q) in x.iter().zip(&y) {
            assert!((p - q).abs() <= 1e-12, "{x:?} vs {y:?}");
        }
    }
}
