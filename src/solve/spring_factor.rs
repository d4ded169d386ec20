//! The Winkler spring system's numeric factor between penalty steps and between solves.
//!
//! A penalty step on Winkler with nodal constraints solves (K + diag(s)) u = f, where only the
//! springs s change from step to step (the soil's where it pushes, ε̄ times softer where it
//! would pull). A step whose springs differ from those of the last factor at k points is solved
//! from that factor by the Sherman–Morrison–Woodbury identity,
//!
//! (A + Σ_j δ_j e_j e_jᵀ)⁻¹ f = y − Z (diag(1/δ) + Uᵀ Z)⁻¹ Uᵀ y,   y = A⁻¹ f,  Z = A⁻¹ U,
//!
//! at the cost of the columns Z (two triangular solves each) and a dense k × k system, instead
//! of a new numeric factorisation. The columns depend only on the factor, so they are kept: the
//! next step, whose changed points mostly repeat this one's, computes only the new ones.
//! [`woodbury_limit`] says when a new factorisation is cheaper.
//!
//! **Between solves** ([`Carry`]): a pass of a load along a lane solves position after position
//! on the same operators; each position's lifted region differs from the last one's near its
//! edge only. The factor a solve ended with (and its columns) is handed to the next solve,
//! whose first step is then an update of it rather than a new factorisation wherever the sets
//! differ by few points. The answer does not depend on which factor a step starts from (each
//! step solves its own system exactly); only the cost does.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use faer::linalg::solvers::Solve;
use faer::Mat;

use super::linalg::{sparse_solve, SparseFactor};
use crate::error::{Error, Result};

/// Most changed springs a step solves by an update of the last factor. Measured on
/// `example:pavement-3x3` (19 809 equations, two cores): a numeric factorisation and its solve
/// take 17–23 ms, an update 3 ms plus 0.5 ms a new column, so updates pay up to about 30
/// columns there. A factorisation grows like n^1.5 on a plate's grid and a column like n, so the
/// break-even grows like √n: √n / 4, between 16 and 64.
pub fn woodbury_limit(n: usize) -> usize {
    ((n as f64).sqrt() / 4.0).clamp(16.0, 64.0) as usize
}

/// Most Woodbury columns kept for one factor: about 32 MB of them (200 at 19 809 equations),
/// never fewer than one step may need; past it only the current step's stay.
fn max_columns(n: usize) -> usize {
    (4_000_000 / n.max(1)).max(woodbury_limit(n))
}

/// A numeric factor of K + diag(springs on the pressure nodes' equations), with the Woodbury
/// columns A⁻¹ e_eq computed for it so far.
#[derive(Clone)]
pub(super) struct Factored {
    /// K's identity: a factor is only reused on the operators it was made for.
    pub k: Arc<sprs::CsMat<f64>>,
    pub factor: Arc<SparseFactor>,
    /// Spring stiffness per pressure node that the factor was made with.
    pub springs: Vec<f64>,
    /// Columns A⁻¹ e_eq, by equation.
    columns: HashMap<usize, Arc<Vec<f64>>>,
}

impl Factored {
    pub fn new(k: Arc<sprs::CsMat<f64>>, factor: Arc<SparseFactor>, springs: Vec<f64>) -> Self {
        Self {
            k,
            factor,
            springs,
            columns: HashMap::new(),
        }
    }

    /// Pressure nodes whose spring differs from the factor's.
    pub fn changed(&self, springs: &[f64]) -> Vec<usize> {
        self.springs
            .iter()
            .zip(springs)
            .enumerate()
            .filter(|(_, (a, b))| a != b)
            .map(|(j, _)| j)
            .collect()
    }

    /// Solve (A + Σ_j δ_j e_{i_j} e_{i_j}ᵀ) u = f with `updates` = (i_j, δ_j), from this factor of
    /// A by Sherman–Morrison–Woodbury (see the module's description); columns not yet known are
    /// computed together and kept.
    pub fn woodbury_solve(&mut self, f: &[f64], updates: &[(usize, f64)]) -> Result<Vec<f64>> {
        let n = f.len();
        let k = updates.len();
        let mut y = f.to_vec();
        sparse_solve(&self.factor, &mut y);
        if k == 0 {
            return Ok(y);
        }
        if self.columns.len() > max_columns(n) {
            // Keep memory bounded: the columns this step needs stay, the rest go.
            let wanted: std::collections::HashSet<usize> =
                updates.iter().map(|&(i, _)| i).collect();
            self.columns.retain(|i, _| wanted.contains(i));
        }
        let missing: Vec<usize> = updates
            .iter()
            .map(|&(i, _)| i)
            .filter(|i| !self.columns.contains_key(i))
            .collect();
        if !missing.is_empty() {
            let mut z = Mat::<f64>::zeros(n, missing.len());
            for (c, &i) in missing.iter().enumerate() {
                z[(i, c)] = 1.0;
            }
            self.factor.solve_in_place(z.as_mut());
            for (c, &i) in missing.iter().enumerate() {
                self.columns
                    .insert(i, Arc::new(z.col(c).iter().copied().collect()));
            }
        }
        let cols: Vec<Arc<Vec<f64>>> = updates
            .iter()
            .map(|(i, _)| {
                self.columns
                    .get(i)
                    .cloned()
                    .ok_or_else(|| Error::numerical("penalty (low-rank update)", "lost column"))
            })
            .collect::<Result<_>>()?;
        let m = Mat::<f64>::from_fn(k, k, |a, b| {
            cols[b][updates[a].0] + if a == b { 1.0 / updates[a].1 } else { 0.0 }
        });
        let mut rhs = Mat::<f64>::from_fn(k, 1, |a, _| y[updates[a].0]);
        let lu = m.partial_piv_lu();
        lu.solve_in_place(rhs.as_mut());
        for (c, col) in cols.iter().enumerate() {
            let r = rhs[(c, 0)];
            for (yi, zi) in y.iter_mut().zip(col.iter()) {
                *yi -= zi * r;
            }
        }
        if y.iter().any(|v| !v.is_finite()) {
            return Err(Error::numerical(
                "penalty (low-rank update)",
                "non-finite values",
            ));
        }
        Ok(y)
    }
}

/// What one penalty solve hands the next on the same operators (see the module's description):
/// the Winkler spring system's last factor and its columns. Empty on every other route. One
/// `Carry` serves one sequence of solves; solves running side by side each need their own.
#[derive(Default)]
pub struct Carry(Mutex<Option<Factored>>);

impl Carry {
    /// An empty carry: the first solve factors as it would without one.
    pub fn new() -> Self {
        Self::default()
    }

    /// Another carry holding what this one holds (the factor and its columns shared, not
    /// copied): two sequences of solves that start from the same solve's factor.
    pub fn share(&self) -> Carry {
        let slot = self.0.lock().unwrap_or_else(|p| p.into_inner());
        Carry(Mutex::new(slot.clone()))
    }

    /// The carried factor, if it was made for the stiffness `k`.
    pub(super) fn take_for(&self, k: &Arc<sprs::CsMat<f64>>) -> Option<Factored> {
        let mut slot = self.0.lock().unwrap_or_else(|p| p.into_inner());
        slot.take().filter(|f| Arc::ptr_eq(&f.k, k))
    }

    /// Move what this carry holds into a new one, leaving this one empty.
    pub fn take(&self) -> Carry {
        let mut slot = self.0.lock().unwrap_or_else(|p| p.into_inner());
        Carry(Mutex::new(slot.take()))
    }

    /// Take what `other` holds (the factor a solve started from `other` ended with).
    pub fn put_from(&self, other: Carry) {
        let taken = other.0.into_inner().unwrap_or_else(|p| p.into_inner());
        self.put(taken);
    }

    /// Keep `factored` for the next solve.
    pub(super) fn put(&self, factored: Option<Factored>) {
        let mut slot = self.0.lock().unwrap_or_else(|p| p.into_inner());
        *slot = factored;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solve::linalg::SparseCholesky;

    /// A 1-D chain of springs (tridiagonal SPD) with extra diagonal springs: the update from the
    /// factor of one diagonal equals a direct factorisation of the other, column cache or not.
    #[test]
    fn an_update_equals_a_new_factorisation_and_reuses_its_columns() {
        let n = 40;
        let matrix = |extra: &[f64]| -> sprs::CsMat<f64> {
            let mut t = sprs::TriMat::new((n, n));
            for i in 0..n {
                t.add_triplet(i, i, 2.0 + extra[i]);
                if i + 1 < n {
                    t.add_triplet(i, i + 1, -1.0);
                    t.add_triplet(i + 1, i, -1.0);
                }
            }
            t.to_csc()
        };
        let base: Vec<f64> = (0..n).map(|i| 0.1 + 0.01 * i as f64).collect();
        let a = matrix(&base);
        let chol = SparseCholesky::analyse_ordered(&a, None).expect("analysis");
        let factor = Arc::new(chol.factor(&a, "test").expect("factor"));
        let k = Arc::new(a);
        let mut f = Factored::new(k, factor, base.clone());
        let rhs: Vec<f64> = (0..n).map(|i| (i as f64 * 0.3).sin()).collect();
        // Two successive changes, the second overlapping the first (its columns are reused).
        for changed in [vec![3usize, 17, 30], vec![3, 17, 31, 38]] {
            let mut springs = base.clone();
            for &i in &changed {
                springs[i] = if i % 2 == 0 { 1e-6 } else { 5.0 };
            }
            let updates: Vec<(usize, f64)> = f
                .changed(&springs)
                .into_iter()
                .map(|j| (j, springs[j] - base[j]))
                .collect();
            assert_eq!(updates.len(), changed.len());
            let u = f.woodbury_solve(&rhs, &updates).expect("update");
            let direct = chol.factor(&matrix(&springs), "test").expect("factor");
            let mut v = rhs.clone();
            sparse_solve(&direct, &mut v);
            // Condition number of these matrices is below 1e4: agreement to 1e-10 relative
            // leaves six digits of margin over double precision's round-off.
            let scale = v.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
            for (p, q) in u.iter().zip(&v) {
                assert!((p - q).abs() <= 1e-10 * scale, "{p} vs {q}");
            }
        }
        // 3, 17, 30, 31, 38: five columns computed, 3 and 17 once.
        assert_eq!(f.columns.len(), 5);
    }
}
