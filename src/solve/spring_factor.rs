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
//! **On a supernodal factor** A = Pᵀ L Lᵀ P (faer's choice for a plate's grid) the identity is
//! split between the two triangles: with g = L⁻¹ P f and W = L⁻¹ P U,
//!
//! u = Pᵀ L⁻ᵀ (g − W r),   (diag(1/δ) + Wᵀ W) r = Wᵀ g,
//!
//! one solve's two halves (the forward half once for the steps of a solve, which share f) and,
//! per changed point, a forward solve of a unit vector, which touches only the supernodes on
//! its path to the root instead of two full triangular solves of the whole factor. The new
//! columns of a step are solved together ([`SparseFactor::forward_units`]): the supernodes near
//! the root, which every path reaches and which hold most of a column's work, are then read
//! once a step, not once a column (a damage run's columns: 12 % of its time one at a time, 3 %
//! together, session 24's profile). The columns of W and their dot products are kept as Z's are.
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
use super::supernodal::ForwardColumn;
use crate::error::{Error, Result};

/// Most changed springs a step solves by an update of the last factor. Measured on
/// `example:pavement-3x3` (19 809 equations, two cores): a numeric factorisation and its solve
/// take 17–23 ms, an update 3 ms plus 0.5 ms a new full column, so updates pay up to about 30
/// columns there. A factorisation grows like n^1.5 on a plate's grid and a column like n, so the
/// break-even grows like √n: √n / 4, between 16 and 64, on a simplicial factor. On a supernodal
/// one a column is a forward solve along one path of the elimination tree, a small part of a
/// solve (see the module's description), and updates pay up to about √n points: on a damage run
/// of 1 800 positions (session 18, pairs) √n took 0.88× the time of √n / 2, and 2√n 1.07–1.14×
/// that of √n (the k × k system's factorisation grows like k³); √n, between 16 and 256.
pub fn woodbury_limit(n: usize, supernodal: bool) -> usize {
    let root = (n as f64).sqrt();
    if supernodal {
        root.clamp(16.0, 256.0) as usize
    } else {
        (root / 4.0).clamp(16.0, 64.0) as usize
    }
}

/// Most Woodbury columns kept for one factor: about 32 MB of full columns (200 at 19 809
/// equations; the supernodal factor's forward columns are shorter), never fewer than one step
/// may need; past it only the current step's stay.
fn max_columns(n: usize, supernodal: bool) -> usize {
    (4_000_000 / n.max(1)).max(woodbury_limit(n, supernodal))
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
    /// Columns A⁻¹ e_eq, by equation (a simplicial factor).
    columns: HashMap<usize, Arc<Vec<f64>>>,
    /// Columns L⁻¹ P e_eq, by equation, and their dot products by (smaller, larger) equation
    /// (a supernodal factor).
    forward: HashMap<usize, Arc<ForwardColumn>>,
    dots: HashMap<(usize, usize), f64>,
    /// The last right-hand side f and its L⁻¹ P f (a supernodal factor): the steps of one solve
    /// share f, so only the first of them solves forward.
    last_rhs: Option<(Vec<f64>, Vec<f64>)>,
}

impl Factored {
    pub fn new(k: Arc<sprs::CsMat<f64>>, factor: Arc<SparseFactor>, springs: Vec<f64>) -> Self {
        Self {
            k,
            factor,
            springs,
            columns: HashMap::new(),
            forward: HashMap::new(),
            dots: HashMap::new(),
            last_rhs: None,
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
        if self.factor.is_supernodal() {
            return self.woodbury_split(f, updates);
        }
        let n = f.len();
        let k = updates.len();
        let mut y = f.to_vec();
        sparse_solve(&self.factor, &mut y);
        if k == 0 {
            return Ok(y);
        }
        if self.columns.len() > max_columns(n, false) {
            // Keep memory bounded: the columns this step needs stay, the rest go.
            let wanted: std::collections::HashSet<usize> =
                updates.iter().map(|&(i, _)| i).collect();
            self.columns.retain(|i, _| wanted.contains(i));
        }
        let missing = missing_keys(updates, &self.columns);
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

impl Factored {
    /// [`woodbury_solve`](Self::woodbury_solve) on a supernodal factor, split between its
    /// triangles (see the module's description).
    fn woodbury_split(&mut self, f: &[f64], updates: &[(usize, f64)]) -> Result<Vec<f64>> {
        let n = f.len();
        let lost = || Error::numerical("penalty (low-rank update)", "not a supernodal factor");
        let mut g = match &self.last_rhs {
            Some((rhs, g)) if rhs.as_slice() == f => g.clone(),
            last => {
                // A load moved along a lane changes f where it was and where it is only: then
                // L⁻¹ P f is the last one's plus the forward solve of the sparse difference.
                let moved = last.as_ref().and_then(|(rhs, g)| {
                    let delta = sparse_difference(f, rhs, n / SPARSE_SHARE)?;
                    let mut column = self.factor.forward_sparse(&[delta])?;
                    let mut g = g.clone();
                    column.pop()?.add_to(1.0, &mut g);
                    Some(g)
                });
                let g = match moved {
                    Some(g) => g,
                    None => self.factor.forward(f).ok_or_else(lost)?,
                };
                self.last_rhs = Some((f.to_vec(), g.clone()));
                g
            }
        };
        let k = updates.len();
        if k > 0 {
            if self.forward.len() > max_columns(n, true) {
                // Keep memory bounded: the columns this step needs stay, the rest go.
                let wanted: std::collections::HashSet<usize> =
                    updates.iter().map(|&(i, _)| i).collect();
                self.forward.retain(|i, _| wanted.contains(i));
                self.dots
                    .retain(|(a, b), _| wanted.contains(a) && wanted.contains(b));
            }
            let missing = missing_keys(updates, &self.forward);
            if !missing.is_empty() {
                let columns = self.factor.forward_units(&missing).ok_or_else(lost)?;
                for (i, column) in missing.into_iter().zip(columns) {
                    self.forward.insert(i, Arc::new(column));
                }
            }
            let cols: Vec<Arc<ForwardColumn>> = updates
                .iter()
                .map(|(i, _)| self.forward.get(i).cloned().ok_or_else(lost))
                .collect::<Result<_>>()?;
            let mut m = Mat::<f64>::zeros(k, k);
            for a in 0..k {
                for b in a..k {
                    let (i, j) = (updates[a].0, updates[b].0);
                    let key = (i.min(j), i.max(j));
                    let d = match self.dots.get(&key) {
                        Some(&d) => d,
                        None => {
                            let d = cols[a].dot(&cols[b]);
                            self.dots.insert(key, d);
                            d
                        }
                    };
                    m[(a, b)] = d;
                    m[(b, a)] = d;
                }
                m[(a, a)] += 1.0 / updates[a].1;
            }
            let mut rhs = Mat::<f64>::from_fn(k, 1, |a, _| cols[a].dot_dense(&g));
            m.partial_piv_lu().solve_in_place(rhs.as_mut());
            for (a, col) in cols.iter().enumerate() {
                col.add_to(-rhs[(a, 0)], &mut g);
            }
        }
        let u = self.factor.backward(g).ok_or_else(lost)?;
        if u.iter().any(|v| !v.is_finite()) {
            return Err(Error::numerical(
                "penalty (low-rank update)",
                "non-finite values",
            ));
        }
        Ok(u)
    }
}

/// The indices of `updates` (index, value) that `have` holds no column for, in their order.
pub(super) fn missing_keys<V>(updates: &[(usize, f64)], have: &HashMap<usize, V>) -> Vec<usize> {
    updates
        .iter()
        .map(|&(i, _)| i)
        .filter(|i| !have.contains_key(i))
        .collect()
}

/// A right-hand side that differs from the last one's in at most n / `SPARSE_SHARE` equations
/// has its forward half updated by a sparse forward solve of the difference (the union of its
/// entries' paths), not solved afresh: an axle moved to its next position changes a few hundred
/// of a slab's twenty thousand equations. A bound, not a measured break-even: entries scattered
/// over a twentieth of the equations reach most supernodes, and the full forward solve is then
/// no dearer.
const SPARSE_SHARE: usize = 20;

/// The entries of f − last that are not zero, if there are at most `limit` of them.
fn sparse_difference(f: &[f64], last: &[f64], limit: usize) -> Option<Vec<(usize, f64)>> {
    let mut delta = Vec::new();
    for (i, (a, b)) in f.iter().zip(last).enumerate() {
        if a != b {
            if delta.len() == limit {
                return None;
            }
            delta.push((i, a - b));
        }
    }
    Some(delta)
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

    /// A 1-D chain of springs (tridiagonal SPD) with extra diagonal springs, factored
    /// simplicially: the update from the factor of one diagonal equals a direct factorisation of
    /// the other, column cache or not.
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
        // A chain is factored simplicially: this test holds the full columns' path.
        assert!(!factor.is_supernodal());
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

    /// A plate-like grid (three unknowns a node, a 9-point stencil on 50 × 50 nodes, every
    /// unknown of a node coupled to every unknown of its neighbours, SPD by its diagonal), whose
    /// factor faer makes supernodal: the update split between the triangles equals a direct
    /// factorisation of the changed matrix, for springs added and springs taken away, and its
    /// forward columns are those of the full forward solve.
    #[test]
    fn a_split_update_on_a_supernodal_factor_equals_a_new_factorisation() {
        let side = 50;
        let n = 3 * side * side;
        let matrix = |extra: &[f64]| -> sprs::CsMat<f64> {
            let mut t = sprs::TriMat::new((n, n));
            for i in 0..side {
                for j in 0..side {
                    let a = i * side + j;
                    for da in 0..3 {
                        t.add_triplet(3 * a + da, 3 * a + da, 8.5 + extra[3 * a + da]);
                        for db in (da + 1)..3 {
                            t.add_triplet(3 * a + da, 3 * a + db, -0.1);
                            t.add_triplet(3 * a + db, 3 * a + da, -0.1);
                        }
                    }
                    for (di, dj) in [(0, 1), (1, -1), (1, 0), (1, 1)] {
                        let (p, q) = (i as i64 + di, j as i64 + dj);
                        if p < side as i64 && (0..side as i64).contains(&q) {
                            let b = p as usize * side + q as usize;
                            for da in 0..3 {
                                for db in 0..3 {
                                    t.add_triplet(3 * a + da, 3 * b + db, -1.0 / 3.0);
                                    t.add_triplet(3 * b + db, 3 * a + da, -1.0 / 3.0);
                                }
                            }
                        }
                    }
                }
            }
            t.to_csc()
        };
        let base: Vec<f64> = (0..n).map(|i| 0.5 + 0.001 * (i % 7) as f64).collect();
        let a = matrix(&base);
        let chol = SparseCholesky::analyse_ordered(&a, None).expect("analysis");
        let factor = Arc::new(chol.factor(&a, "test").expect("factor"));
        assert!(factor.is_supernodal(), "the test needs a supernodal factor");
        // A forward column from the unit vector alone is the full forward solve's column.
        for eq in [0, 777, n - 1] {
            let mut e = vec![0.0; n];
            e[eq] = 1.0;
            let full = factor.forward(&e).expect("supernodal");
            let column = factor.forward_unit(eq).expect("supernodal");
            let mut sparse = vec![0.0; n];
            column.add_to(1.0, &mut sparse);
            // Round-off of a few hundred products of entries below 1 in size: 1e-13.
            for (p, q) in sparse.iter().zip(&full) {
                assert!((p - q).abs() <= 1e-13, "{p} vs {q}");
            }
            assert!((column.dot(&column) - crate::solve::linalg::dot(&full, &full)).abs() < 1e-13);
        }
        // Columns solved together (paths that share the supernodes near the root, neighbouring
        // equations among them, given out of order) are each the full forward solve's column,
        // to the same round-off.
        let eqs = [777, 0, 778, n - 1, 1351];
        let together = factor.forward_units(&eqs).expect("supernodal");
        assert_eq!(together.len(), eqs.len());
        for (&eq, column) in eqs.iter().zip(&together) {
            let mut e = vec![0.0; n];
            e[eq] = 1.0;
            let full = factor.forward(&e).expect("supernodal");
            let mut sparse = vec![0.0; n];
            column.add_to(1.0, &mut sparse);
            for (p, q) in sparse.iter().zip(&full) {
                assert!((p - q).abs() <= 1e-13, "{p} vs {q}");
            }
        }
        // A sparse vector's forward solve is the dense one's.
        let entries = vec![(3, 0.5), (1200, -2.0), (n - 2, 1.5)];
        let mut dense = vec![0.0; n];
        for &(i, v) in &entries {
            dense[i] = v;
        }
        let full = factor.forward(&dense).expect("supernodal");
        let column = factor
            .forward_sparse(&[entries])
            .expect("supernodal")
            .remove(0);
        let mut sparse = vec![0.0; n];
        column.add_to(1.0, &mut sparse);
        for (p, q) in sparse.iter().zip(&full) {
            assert!((p - q).abs() <= 1e-13, "{p} vs {q}");
        }
        let mut f = Factored::new(Arc::new(a), factor, base.clone());
        let rhs: Vec<f64> = (0..n).map(|i| (i as f64 * 0.37).cos()).collect();
        for changed in [vec![5usize, 400, 401, 1210], vec![5, 400, 999, 2699, 1351]] {
            let mut springs = base.clone();
            for &i in &changed {
                // Springs added (×40) and nearly removed (×1e-6), as a penalty step does.
                springs[i] = if i % 2 == 0 { 20.0 } else { 5e-7 };
            }
            let updates: Vec<(usize, f64)> = f
                .changed(&springs)
                .into_iter()
                .map(|j| (j, springs[j] - base[j]))
                .collect();
            let u = f.woodbury_solve(&rhs, &updates).expect("update");
            let direct = chol.factor(&matrix(&springs), "test").expect("factor");
            let mut v = rhs.clone();
            sparse_solve(&direct, &mut v);
            // Condition number below 1e3 (diagonal 8.5 + springs against off-diagonal sums of
            // 8): 1e-11 relative is three orders above double precision's round-off through it.
            let scale = v.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
            for (p, q) in u.iter().zip(&v) {
                assert!((p - q).abs() <= 1e-11 * scale, "{p} vs {q}");
            }
        }
        // A load moved: f differs from the last one in a few equations, and the forward half is
        // updated by the difference's sparse solve (n / SPARSE_SHARE = 375 entries allowed).
        let mut moved = rhs.clone();
        for i in [10, 11, 1500, 2650] {
            moved[i] += 3.0;
        }
        assert!(sparse_difference(&moved, &rhs, n / SPARSE_SHARE).is_some());
        let mut springs = base.clone();
        springs[5] = 20.0;
        let u = f
            .woodbury_solve(&moved, &[(5, springs[5] - base[5])])
            .expect("update");
        let direct = chol.factor(&matrix(&springs), "test").expect("factor");
        let mut v = moved.clone();
        sparse_solve(&direct, &mut v);
        let scale = v.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
        for (p, q) in u.iter().zip(&v) {
            assert!((p - q).abs() <= 1e-11 * scale, "{p} vs {q}");
        }
        // Seven distinct points: seven forward columns, 5 and 400 computed once.
        assert_eq!(f.forward.len(), 7);
        assert!(f.columns.is_empty());
    }
}
