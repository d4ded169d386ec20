//! Thin wrappers over faer: sparse Cholesky with a reusable symbolic analysis (a supernodal
//! factor's two triangular halves apart are [`super::supernodal`]'s), the generalised inverse of
//! the free plate's stiffness, and dense Cholesky.

use std::cell::Cell;
use std::sync::Arc;

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::llt;
use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, LltRef, SymbolicCholesky, SymbolicCholeskyRaw, SymmetricOrdering,
};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
use faer::{Mat, MatMut, Par, Side};

use super::combiner::Combiner;
use crate::error::{Error, Result};
use crate::operators::Operators;

/// A faer view of an sprs CSC matrix (sorted, no duplicates, as `TriMat::to_csc` makes them).
pub fn faer_view(m: &sprs::CsMat<f64>) -> SparseColMatRef<'_, usize, f64> {
    let sym = SymbolicSparseColMatRef::new_checked(
        m.rows(),
        m.cols(),
        m.indptr().into_raw_storage(),
        None,
        m.indices(),
    );
    SparseColMatRef::new(sym, m.data())
}

/// Sparse LLᵀ whose symbolic analysis (ordering, elimination tree, supernodes) is done once and
/// reused for every matrix of the same pattern.
#[derive(Clone)]
pub struct SparseCholesky {
    symbolic: Arc<SymbolicCholesky<usize>>,
}

/// A numeric sparse Cholesky factor. Its values are shared, not copied, by its clones: a
/// cached factor (the bonded preconditioner kept per assembly and handed to every solve on it)
/// costs its memory once.
#[derive(Clone)]
pub struct SparseFactor {
    pub(super) symbolic: Arc<SymbolicCholesky<usize>>,
    pub(super) values: Arc<Vec<f64>>,
}

impl SparseCholesky {
    /// Analyse the pattern of `m` (lower triangle read) with faer's approximate minimum degree
    /// ordering.
    pub fn analyse(m: &sprs::CsMat<f64>) -> Result<Self> {
        Self::analyse_ordered(m, None)
    }

    /// Analyse with a fill-reducing ordering given as `order[new] = old` (e.g. the grid's nested
    /// dissection), or AMD when `None`.
    pub fn analyse_ordered(m: &sprs::CsMat<f64>, order: Option<&[usize]>) -> Result<Self> {
        let err = |e: faer::sparse::FaerError| {
            Error::numerical("sparse Cholesky analysis", format!("{e:?}"))
        };
        let symbolic = match order {
            Some(fwd) => {
                let mut inv = vec![0usize; fwd.len()];
                for (new, &old) in fwd.iter().enumerate() {
                    inv[old] = new;
                }
                let perm = faer::perm::PermRef::new_checked(fwd, &inv, fwd.len());
                factorize_symbolic_cholesky(
                    faer_view(m).symbolic(),
                    Side::Lower,
                    SymmetricOrdering::Custom(perm),
                    Default::default(),
                )
                .map_err(err)?
            }
            None => factorize_symbolic_cholesky(
                faer_view(m).symbolic(),
                Side::Lower,
                SymmetricOrdering::Amd,
                Default::default(),
            )
            .map_err(err)?,
        };
        Ok(Self {
            symbolic: Arc::new(symbolic),
        })
    }

    /// Whether the factors will be supernodal (faer's choice by the pattern's fill; see
    /// [`SparseFactor::is_supernodal`]).
    pub fn is_supernodal(&self) -> bool {
        matches!(self.symbolic.raw(), SymbolicCholeskyRaw::Supernodal(_))
    }

    /// Numeric factorisation of a matrix with the analysed pattern.
    pub fn factor(&self, m: &sprs::CsMat<f64>, stage: &str) -> Result<SparseFactor> {
        let par = faer::get_global_parallelism();
        let mut values = vec![0.0; self.symbolic.len_val()];
        let req = self
            .symbolic
            .factorize_numeric_llt_scratch::<f64>(par, Default::default());
        let mut mem = MemBuffer::try_new(req)
            .map_err(|_| Error::numerical(stage, "out of memory for the factorisation"))?;
        self.symbolic
            .factorize_numeric_llt(
                &mut values,
                faer_view(m),
                Side::Lower,
                Default::default(),
                par,
                MemStack::new(&mut mem),
                Default::default(),
            )
            .map_err(|e| {
                Error::numerical(
                    stage,
                    format!(
                        "the matrix is not positive definite ({e:?}); the plate may be unsupported (check the foundation stiffness and the loads)"
                    ),
                )
            })?;
        Ok(SparseFactor {
            symbolic: self.symbolic.clone(),
            values: Arc::new(values),
        })
    }
}

impl SparseFactor {
    /// Solve A X = B in place for the columns of B.
    pub fn solve_in_place(&self, rhs: MatMut<'_, f64>) {
        self.solve_in_place_with(rhs, faer::get_global_parallelism());
    }

    /// [`SparseFactor::solve_in_place`] with the parallelism `par`.
    pub fn solve_in_place_with(&self, rhs: MatMut<'_, f64>, par: Par) {
        let mut mem = MemBuffer::new(
            self.symbolic
                .solve_in_place_scratch::<f64>(rhs.ncols(), par),
        );
        LltRef::<'_, usize, f64>::new(&self.symbolic, &self.values).solve_in_place_with_conj(
            faer::Conj::No,
            rhs,
            par,
            MemStack::new(&mut mem),
        );
    }
}

/// Solve in place with a sparse factor, one right-hand side.
pub fn sparse_solve(llt: &SparseFactor, rhs: &mut [f64]) {
    let n = rhs.len();
    llt.solve_in_place(MatMut::from_column_major_slice_mut(rhs, n, 1));
}

/// Position of each diagonal entry in the data array of a CSC matrix.
pub fn diagonal_positions(m: &sprs::CsMat<f64>) -> Result<Vec<usize>> {
    let indptr = m.indptr();
    let ptr = indptr.raw_storage();
    (0..m.cols())
        .map(|j| {
            (ptr[j]..ptr[j + 1])
                .find(|&p| m.indices()[p] == j)
                .ok_or_else(|| {
                    Error::numerical(
                        "assembly",
                        format!("stiffness has no diagonal entry in column {j}"),
                    )
                })
        })
        .collect()
}

/// The diagonal coupling of a Winkler model: for each pressure node, its w equation and ∫ f_j.
pub fn lumped_coupling(ops: &Operators) -> Result<Vec<(usize, f64)>> {
    ops.b
        .outer_iterator()
        .enumerate()
        .map(|(j, col)| {
            let mut it = col.iter();
            match (it.next(), it.next()) {
                (Some((i, &v)), None) => Ok((i, v)),
                _ => Err(Error::numerical(
                    "coupling",
                    format!("pressure node {j} is not lumped"),
                )),
            }
        })
        .collect()
}

/// K with the equations `fixed` removed, and the reduced index of each equation.
pub(crate) fn reduce(
    k: &sprs::CsMat<f64>,
    fixed: &[usize],
) -> (sprs::CsMat<f64>, Vec<Option<usize>>) {
    let n = k.rows();
    let mut is_fixed = vec![false; n];
    for &e in fixed {
        is_fixed[e] = true;
    }
    let mut map = vec![None; n];
    let mut n_red = 0;
    for (e, m) in map.iter_mut().enumerate() {
        if !is_fixed[e] {
            *m = Some(n_red);
            n_red += 1;
        }
    }
    let mut indptr = Vec::with_capacity(n_red + 1);
    let mut indices = Vec::with_capacity(k.nnz());
    let mut data = Vec::with_capacity(k.nnz());
    indptr.push(0);
    for (j, col) in k.outer_iterator().enumerate() {
        if map[j].is_none() {
            continue;
        }
        for (i, &v) in col.iter() {
            if let Some(r) = map[i] {
                indices.push(r);
                data.push(v);
            }
        }
        indptr.push(indices.len());
    }
    (
        sprs::CsMat::new_csc((n_red, n_red), indptr, indices, data),
        map,
    )
}

/// Generalised inverse K⁻ of the free (singular) plate stiffness: the equations in
/// `Operators::fixed` are set to zero and the rest of K, which is then positive definite, is
/// factored. K K⁻ K = K, and K⁻ r solves K u = r whenever r is orthogonal to the rigid modes.
pub struct PlateInverse {
    llt: SparseFactor,
    /// Reduced index of each equation (None for fixed ones).
    map: Vec<Option<usize>>,
    n_red: usize,
    /// Solves asked for at once by several threads (positions solved side by side on one
    /// assembly) run as one solve with several right-hand sides ([`Combiner`]).
    combiner: Combiner<Vec<f64>>,
}

impl PlateInverse {
    /// Factor K with the fixed equations removed.
    pub fn new(ops: &Operators) -> Result<Self> {
        let (kr, map) = reduce(&ops.k, &ops.fixed);
        let n_red = kr.rows();
        let order = crate::mesh::equation_order(&ops.mesh, &ops.dofs, |e| map[e].is_some());
        let chol = SparseCholesky::analyse_ordered(&kr, Some(&order))?;
        let llt = chol.factor(&kr, "plate stiffness (generalised inverse)")?;
        Ok(Self {
            llt,
            map,
            n_red,
            combiner: Combiner::default(),
        })
    }

    /// K⁻ r for one vector. On a pool built to share these solves ([`mark_sharing_thread`]: more
    /// positions side by side than cores) it is solved in one batch with the vectors other
    /// threads ask for at the same time; elsewhere alone: on a pool no wider than the cores the
    /// threads' solves run each on its own core, which a batch would only serialise (measured:
    /// 1.19× slower on two runs of the half-space lane).
    pub fn apply(&self, r: &[f64]) -> Vec<f64> {
        let mut red = vec![0.0; self.n_red];
        for (e, m) in self.map.iter().enumerate() {
            if let Some(i) = m {
                red[*i] = r[e];
            }
        }
        if in_sharing_pool() {
            red = self.combiner.run(red, |batch| self.solve_reduced(batch));
        } else {
            sparse_solve(&self.llt, &mut red);
        }
        let mut out = vec![0.0; r.len()];
        for (e, m) in self.map.iter().enumerate() {
            if let Some(i) = m {
                out[e] = red[*i];
            }
        }
        out
    }

    /// The reduced system solved for each vector of `batch`, all in one solve. Sequential
    /// whatever faer's global parallelism: a batch solved on rayon could, while waiting for a
    /// stolen half, itself steal another position's plate solve, which would wait for this
    /// batch — for itself.
    fn solve_reduced(&self, mut batch: Vec<Vec<f64>>) -> Vec<Vec<f64>> {
        let n = self.n_red;
        if let [one] = batch.as_mut_slice() {
            self.llt
                .solve_in_place_with(MatMut::from_column_major_slice_mut(one, n, 1), Par::Seq);
            return batch;
        }
        let mut block = Mat::<f64>::from_fn(n, batch.len(), |i, j| batch[j][i]);
        self.llt.solve_in_place_with(block.as_mut(), Par::Seq);
        for (j, v) in batch.iter_mut().enumerate() {
            for (i, x) in v.iter_mut().enumerate() {
                *x = block[(i, j)];
            }
        }
        batch
    }

    /// K⁻ R for the columns of a dense n_eq × m matrix, in place (rows of fixed equations are
    /// zeroed).
    pub fn apply_block(&self, block: &mut Mat<f64>) {
        let m = block.ncols();
        let mut red = Mat::<f64>::zeros(self.n_red, m);
        for (e, map) in self.map.iter().enumerate() {
            if let Some(i) = map {
                for j in 0..m {
                    red[(*i, j)] = block[(e, j)];
                }
            }
        }
        self.llt.solve_in_place(red.as_mut());
        for (e, map) in self.map.iter().enumerate() {
            for j in 0..m {
                block[(e, j)] = match map {
                    Some(i) => red[(*i, j)],
                    None => 0.0,
                };
            }
        }
    }
}

/// The name (a prefix) of the threads of a pool built to solve positions side by side on one
/// assembly: a label for profilers and debuggers; what marks such a thread is
/// [`mark_sharing_thread`].
pub const SHARING_POOL: &str = "liftoff-shared-solves";

thread_local! {
    /// Whether this thread is one of a pool built to solve positions side by side on one
    /// assembly, whose plate solves [`PlateInverse::apply`] batches.
    static SHARING: Cell<bool> = const { Cell::new(false) };
}

/// Marks this thread as one of a sharing pool's (its start handler calls this on each of its
/// threads): from then on its plate solves batch with the other threads'.
pub(crate) fn mark_sharing_thread() {
    SHARING.with(|s| s.set(true));
}

/// Whether this thread was marked by [`mark_sharing_thread`].
pub(crate) fn in_sharing_pool() -> bool {
    SHARING.with(Cell::get)
}

/// A dense Cholesky factor L (A = L Lᵀ) with the parallelism it was made with.
pub struct DenseLlt {
    l: Mat<f64>,
    par: Par,
}

/// Parallelism for a dense factorisation of size n: large ones use every core (BLAS-3 work
/// scales); small ones stay sequential, where threads cost more than they save.
fn dense_par(n: usize) -> Par {
    if n >= 512 {
        Par::rayon(0)
    } else {
        Par::Seq
    }
}

/// Something that solves A X = B in place for a fixed A.
pub trait SpdSolve {
    /// Overwrite `rhs` with A⁻¹ rhs.
    fn solve_in_place(&self, rhs: MatMut<'_, f64>);
}

impl SpdSolve for DenseLlt {
    fn solve_in_place(&self, rhs: MatMut<'_, f64>) {
        let mut stack = MemBuffer::new(llt::solve::solve_in_place_scratch::<f64>(
            self.l.nrows(),
            rhs.ncols(),
            self.par,
        ));
        llt::solve::solve_in_place(self.l.as_ref(), rhs, self.par, MemStack::new(&mut stack));
    }
}

/// Dense Cholesky with a stage name in the error. The parallelism is passed explicitly (see
/// `dense_par`), never through faer's global setting, so concurrent solves do not interfere.
pub fn dense_cholesky(a: &Mat<f64>, stage: &str) -> Result<DenseLlt> {
    let n = a.nrows();
    let par = dense_par(n);
    let mut l = a.clone();
    let mut stack = MemBuffer::new(llt::factor::cholesky_in_place_scratch::<f64>(
        n,
        par,
        Default::default(),
    ));
    llt::factor::cholesky_in_place(
        l.as_mut(),
        Default::default(),
        par,
        MemStack::new(&mut stack),
        Default::default(),
    )
    .map_err(|e| {
        Error::numerical(
            stage,
            format!("matrix is not positive definite ({e:?}): the problem is too badly conditioned at this mesh and stiffness ratio"),
        )
    })?;
    Ok(DenseLlt { l, par })
}

/// Schur complement S = T + Bᵀ K⁻ B (dense, n_σ × n_σ), computed in column blocks so K⁻B is
/// never held whole.
pub fn schur_complement(ops: &Operators, kinv: &PlateInverse) -> Mat<f64> {
    let n_sigma = ops.n_sigma();
    let n_eq = ops.n_eq();
    // A Toeplitz T is assembled densely here: the routes that call this are budgeted for it.
    let mut s = ops.t.to_dense();
    let block = 256;
    let mut start = 0;
    while start < n_sigma {
        let width = block.min(n_sigma - start);
        let mut x = Mat::<f64>::zeros(n_eq, width);
        for jj in 0..width {
            let col = ops.b.outer_view(start + jj);
            if let Some(col) = col {
                for (i, &v) in col.iter() {
                    x[(i, jj)] = v;
                }
            }
        }
        kinv.apply_block(&mut x);
        // S[:, start..] += Bᵀ X
        for (i, col) in ops.b.outer_iterator().enumerate() {
            for jj in 0..width {
                let mut acc = 0.0;
                for (r, &v) in col.iter() {
                    acc += v * x[(r, jj)];
                }
                s[(i, start + jj)] += acc;
            }
        }
        start += width;
    }
    // Symmetrise the round-off of the block products.
    for j in 0..n_sigma {
        for i in (j + 1)..n_sigma {
            let v = 0.5 * (s[(i, j)] + s[(j, i)]);
            s[(i, j)] = v;
            s[(j, i)] = v;
        }
    }
    s
}

/// A small symmetric positive semi-definite system (the rigid modes' m × m: 3 or fewer for a
/// plate of one piece, as many as a jointed plate's zero-energy modes) solved by
/// its pseudo-inverse: eigenvalues below 1e-12 of the largest are dropped. The rigid-mode
/// columns restricted to a few contact points can be dependent (a plate resting on one node or
/// one line of nodes); the pseudo-inverse then gives the least-squares, minimum-norm answer
/// where a Cholesky factorisation would fail.
#[derive(Debug, Clone)]
pub struct SmallSpd {
    vectors: nalgebra::DMatrix<f64>,
    inverse_values: Vec<f64>,
}

impl SmallSpd {
    /// The pseudo-inverse of the symmetric matrix `a(i, j)` of size m.
    pub fn new(m: usize, a: impl Fn(usize, usize) -> f64) -> Self {
        let mat = nalgebra::DMatrix::from_fn(m, m, |i, j| 0.5 * (a(i, j) + a(j, i)));
        let eig = nalgebra::SymmetricEigen::new(mat);
        let top = eig.eigenvalues.iter().cloned().fold(0.0_f64, f64::max);
        let inverse_values = eig
            .eigenvalues
            .iter()
            .map(|&l| {
                if top > 0.0 && l > 1e-12 * top {
                    1.0 / l
                } else {
                    0.0
                }
            })
            .collect();
        Self {
            vectors: eig.eigenvectors,
            inverse_values,
        }
    }

    /// A⁺ b.
    pub fn solve(&self, b: &[f64]) -> Vec<f64> {
        let m = b.len();
        let mut out = vec![0.0; m];
        for (k, &il) in self.inverse_values.iter().enumerate() {
            if il == 0.0 {
                continue;
            }
            let proj: f64 = (0..m).map(|i| self.vectors[(i, k)] * b[i]).sum();
            for (i, o) in out.iter_mut().enumerate() {
                *o += il * proj * self.vectors[(i, k)];
            }
        }
        out
    }

    /// Unit vectors spanning the directions dropped (the null space, up to round-off).
    pub fn null_space(&self) -> Vec<Vec<f64>> {
        let m = self.inverse_values.len();
        (0..m)
            .filter(|&k| self.inverse_values[k] == 0.0)
            .map(|k| (0..m).map(|i| self.vectors[(i, k)]).collect())
            .collect()
    }

    /// The rank kept.
    pub fn rank(&self) -> usize {
        self.inverse_values.iter().filter(|&&v| v != 0.0).count()
    }
}

/// Displacements from pressures and rigid amplitudes: u = K⁻(f − Bσ) + Rα.
pub fn displacements(
    ops: &Operators,
    kinv: &PlateInverse,
    sigma: &[f64],
    alpha: &[f64],
) -> Vec<f64> {
    let bs = ops.b_times(sigma);
    let r: Vec<f64> = ops.f.iter().zip(&bs).map(|(f, b)| f - b).collect();
    let mut u = kinv.apply(&r);
    for (mode, &a) in ops.rigid.iter().zip(alpha) {
        for (ui, ri) in u.iter_mut().zip(mode) {
            *ui += a * ri;
        }
    }
    u
}

/// Dot product.
pub fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Error if any entry is not finite.
pub fn finite(v: &[f64], stage: &str) -> Result<()> {
    match v.iter().position(|x| !x.is_finite()) {
        Some(i) => Err(Error::numerical(
            stage,
            format!("non-finite value at unknown {i}: the system is singular or overflowed"),
        )),
        None => Ok(()),
    }
}
