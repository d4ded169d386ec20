//! A supernodal sparse factor A = Pᵀ L Lᵀ P solved one triangle at a time: the forward half
//! L⁻¹ P f, the backward half Pᵀ L⁻ᵀ g, and the forward solve of a unit vector along its path of
//! the elimination tree, kept sparse ([`ForwardColumn`]). The Woodbury updates of the Winkler
//! spring factor ([`super::spring_factor`]) split between the triangles with them.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::matmul::matmul;
use faer::linalg::triangular_solve::solve_lower_triangular_in_place;
use faer::sparse::linalg::cholesky::supernodal::SupernodalLltRef;
use faer::sparse::linalg::cholesky::SymbolicCholeskyRaw;
use faer::{Accum, Mat, MatMut, Par};

use super::linalg::{dot, SparseFactor};

/// A column of L⁻¹ P e_a for a supernodal factor A = Pᵀ L Lᵀ P (see
/// [`SparseFactor::forward_unit`]), kept sparse: the forward solve of a unit vector touches only
/// the supernodes on the path from the one holding P e_a to the root, so the column is the list
/// of those supernodes' rows (their first row in the factor's order, and the values), in order.
#[derive(Debug, Clone, PartialEq)]
pub struct ForwardColumn {
    parts: Vec<(usize, Vec<f64>)>,
}

impl ForwardColumn {
    /// The dot product of two columns: the sum over the supernodes on both paths.
    pub fn dot(&self, other: &ForwardColumn) -> f64 {
        let (mut i, mut j, mut sum) = (0, 0, 0.0);
        while i < self.parts.len() && j < other.parts.len() {
            let ((a, x), (b, y)) = (&self.parts[i], &other.parts[j]);
            match a.cmp(b) {
                std::cmp::Ordering::Less => i += 1,
                std::cmp::Ordering::Greater => j += 1,
                std::cmp::Ordering::Equal => {
                    sum += dot(x, y);
                    i += 1;
                    j += 1;
                }
            }
        }
        sum
    }

    /// The dot product with a dense vector in the factor's order.
    pub fn dot_dense(&self, v: &[f64]) -> f64 {
        self.parts
            .iter()
            .map(|(start, x)| dot(x, &v[*start..*start + x.len()]))
            .sum()
    }

    /// v += a · self, v dense in the factor's order.
    pub fn add_to(&self, a: f64, v: &mut [f64]) {
        for (start, x) in &self.parts {
            for (vi, xi) in v[*start..*start + x.len()].iter_mut().zip(x) {
                *vi += a * xi;
            }
        }
    }
}

impl SparseFactor {
    /// Whether the factor is supernodal (faer chooses by the pattern; a small or very sparse
    /// matrix gets a simplicial one), the form the one-sided solves below need.
    pub fn is_supernodal(&self) -> bool {
        matches!(self.symbolic.raw(), SymbolicCholeskyRaw::Supernodal(_))
    }

    /// L⁻¹ P f in the factor's order, for A = Pᵀ L Lᵀ P; None for a simplicial factor.
    pub fn forward(&self, f: &[f64]) -> Option<Vec<f64>> {
        let SymbolicCholeskyRaw::Supernodal(sym) = self.symbolic.raw() else {
            return None;
        };
        let mut g: Vec<f64> = match self.symbolic.perm() {
            Some(perm) => perm.arrays().0.iter().map(|&old| f[old]).collect(),
            None => f.to_vec(),
        };
        let par = Par::Seq;
        let mut mem = MemBuffer::new(sym.solve_in_place_scratch::<f64>(1, par));
        let n = g.len();
        SupernodalLltRef::<'_, usize, f64>::new(sym, &self.values).l_solve_with_conj(
            faer::Conj::No,
            MatMut::from_column_major_slice_mut(&mut g, n, 1),
            par,
            MemStack::new(&mut mem),
        );
        Some(g)
    }

    /// Pᵀ L⁻ᵀ g in the original order, for g in the factor's order (the second half of a solve
    /// that [`forward`](Self::forward) began); None for a simplicial factor.
    pub fn backward(&self, mut g: Vec<f64>) -> Option<Vec<f64>> {
        let SymbolicCholeskyRaw::Supernodal(sym) = self.symbolic.raw() else {
            return None;
        };
        let par = Par::Seq;
        let mut mem = MemBuffer::new(sym.solve_in_place_scratch::<f64>(1, par));
        let n = g.len();
        SupernodalLltRef::<'_, usize, f64>::new(sym, &self.values).l_transpose_solve_with_conj(
            faer::Conj::No,
            MatMut::from_column_major_slice_mut(&mut g, n, 1),
            par,
            MemStack::new(&mut mem),
        );
        Some(match self.symbolic.perm() {
            Some(perm) => perm.arrays().1.iter().map(|&new| g[new]).collect(),
            None => g,
        })
    }

    /// L⁻¹ P e_a, the forward solve of the unit vector at equation `a` (see
    /// [`forward_units`](Self::forward_units)); None for a simplicial factor.
    pub fn forward_unit(&self, a: usize) -> Option<ForwardColumn> {
        self.forward_units(&[a])?.pop()
    }

    /// L⁻¹ P e_a for every equation a of `eqs`, solved together ([`forward_sparse`]
    /// (Self::forward_sparse) of unit vectors); None for a simplicial factor.
    pub fn forward_units(&self, eqs: &[usize]) -> Option<Vec<ForwardColumn>> {
        let units: Vec<Vec<(usize, f64)>> = eqs.iter().map(|&a| vec![(a, 1.0)]).collect();
        self.forward_sparse(&units)
    }

    /// L⁻¹ P v for sparse vectors v (their nonzero (equation, value) entries), solved together;
    /// None for a simplicial factor.
    ///
    /// The forward solve of a unit vector reaches only the supernodes on the path from the one
    /// holding P e_a to the root of the supernodal elimination tree (a supernode's parent holds
    /// the first row of its pattern; every row of the pattern lies on the path), and a sparse
    /// vector's the union of its entries' paths. The vectors are solved on the union of their
    /// paths, supernode after supernode in the factor's order (a child before its parent): at
    /// each, the vectors whose paths pass through it form a dense block, solved with the diagonal
    /// block and carried below by one product with the rows under it — so the supernodes near
    /// the root, which every path reaches and which hold most of the work, are read once for all
    /// the vectors instead of once a vector. A column is the full forward solve's to round-off
    /// (the sums run in another order).
    pub fn forward_sparse(&self, vectors: &[Vec<(usize, f64)>]) -> Option<Vec<ForwardColumn>> {
        let SymbolicCholeskyRaw::Supernodal(sym) = self.symbolic.raw() else {
            return None;
        };
        let n = sym.nrows();
        let n_sup = sym.n_supernodes();
        let (begin, end) = (sym.supernode_begin(), sym.supernode_end());
        let llt = SupernodalLltRef::<'_, usize, f64>::new(sym, &self.values);
        let mut owner = vec![0usize; n];
        for s in 0..n_sup {
            owner[begin[s]..end[s]].fill(s);
        }
        let parent = |s: usize| llt.supernode(s).pattern().first().map(|&row| owner[row]);
        let row = |a: usize| match self.symbolic.perm() {
            Some(perm) => perm.arrays().1.get(a).copied(),
            None => Some(a),
        };
        // The vectors passing through each supernode, in increasing order, and each vector's
        // supernodes (its paths' union).
        let mut active: Vec<Vec<usize>> = vec![Vec::new(); n_sup];
        let mut paths: Vec<Vec<usize>> = Vec::with_capacity(vectors.len());
        let mut mark = vec![usize::MAX; n_sup];
        for (c, vector) in vectors.iter().enumerate() {
            let mut path = Vec::new();
            for &(a, _) in vector {
                let mut s = Some(owner[row(a)?]);
                while let Some(t) = s {
                    if mark[t] == c {
                        break;
                    }
                    mark[t] = c;
                    active[t].push(c);
                    path.push(t);
                    s = parent(t);
                }
            }
            path.sort_unstable();
            paths.push(path);
        }
        let mut blocks: Vec<Option<Mat<f64>>> = (0..n_sup)
            .map(|s| {
                (!active[s].is_empty())
                    .then(|| Mat::<f64>::zeros(end[s] - begin[s], active[s].len()))
            })
            .collect();
        for (c, vector) in vectors.iter().enumerate() {
            for &(a, v) in vector {
                let p = row(a)?;
                let s = owner[p];
                let j = active[s].binary_search(&c).ok()?;
                blocks[s].as_mut()?[(p - begin[s], j)] += v;
            }
        }
        let mut below = Mat::<f64>::zeros(0, 0);
        let mut place: Vec<usize> = Vec::new();
        for s in 0..n_sup {
            let Some(mut x) = blocks[s].take() else {
                continue;
            };
            let node = llt.supernode(s);
            let (l, pattern) = (node.val(), node.pattern());
            let size = l.ncols();
            solve_lower_triangular_in_place(l.subrows(0, size), x.as_mut(), Par::Seq);
            if !pattern.is_empty() {
                below.resize_with(pattern.len(), x.ncols(), |_, _| 0.0);
                matmul(
                    below.as_mut(),
                    Accum::Replace,
                    l.subrows(size, pattern.len()),
                    x.as_ref(),
                    1.0,
                    Par::Seq,
                );
                // Carry into the ancestors' blocks; the pattern's rows run through them in order.
                let mut current = usize::MAX;
                for (idx, &row) in pattern.iter().enumerate() {
                    let t = owner[row];
                    if t != current {
                        current = t;
                        // Where each of this block's columns sits in t's block (a superset).
                        place.clear();
                        for &c in &active[s] {
                            place.push(active[t].binary_search(&c).ok()?);
                        }
                    }
                    let target = blocks[t].as_mut()?;
                    for (j, &q) in place.iter().enumerate() {
                        target[(row - begin[t], q)] -= below[(idx, j)];
                    }
                }
            }
            blocks[s] = Some(x);
        }
        paths
            .iter()
            .enumerate()
            .map(|(c, path)| {
                // The supernodes in order, so the parts are in the factor's order of rows.
                let parts: Vec<(usize, Vec<f64>)> = path
                    .iter()
                    .map(|&s| {
                        let j = active[s].binary_search(&c).ok()?;
                        let x = blocks[s].as_ref()?;
                        Some((begin[s], x.col(j).iter().copied().collect()))
                    })
                    .collect::<Option<_>>()?;
                Some(ForwardColumn { parts })
            })
            .collect()
    }
}
