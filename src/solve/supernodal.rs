//! A supernodal sparse factor A = Pᵀ L Lᵀ P solved one triangle at a time: the forward half
//! L⁻¹ P f, the backward half Pᵀ L⁻ᵀ g, and the forward solve of a unit vector along its path of
//! the elimination tree, kept sparse ([`ForwardColumn`]). The Woodbury updates of the Winkler
//! spring factor ([`super::spring_factor`]) split between the triangles with them.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::linalg::cholesky::supernodal::SupernodalLltRef;
use faer::sparse::linalg::cholesky::SymbolicCholeskyRaw;
use faer::{MatMut, Par};

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

    /// L⁻¹ P e_a, the forward solve of the unit vector at equation `a`, computed on the
    /// supernodes it reaches only (those whose rows are not all zero when their turn comes); None
    /// for a simplicial factor. The skipped supernodes would only add zeros: the column is the
    /// full forward solve's (to round-off: the sums run in another order).
    pub fn forward_unit(&self, a: usize) -> Option<ForwardColumn> {
        let SymbolicCholeskyRaw::Supernodal(sym) = self.symbolic.raw() else {
            return None;
        };
        let n = sym.nrows();
        let p = match self.symbolic.perm() {
            Some(perm) => perm.arrays().1[a],
            None => a,
        };
        let llt = SupernodalLltRef::<'_, usize, f64>::new(sym, &self.values);
        let mut x = vec![0.0; n];
        x[p] = 1.0;
        let mut parts = Vec::new();
        for s in 0..sym.n_supernodes() {
            let node = llt.supernode(s);
            let (start, l) = (node.start(), node.val());
            let size = l.ncols();
            // Before p's supernode, and off its path, the rows are zero: nothing to do.
            if start + size <= p || x[start..start + size].iter().all(|&v| v == 0.0) {
                continue;
            }
            // The diagonal block's forward solve, column by column (L is column-major).
            let mut top = x[start..start + size].to_vec();
            for j in 0..size {
                let col = l.col(j);
                let v = top[j] / col[j];
                top[j] = v;
                if v != 0.0 {
                    for (i, t) in top.iter_mut().enumerate().skip(j + 1) {
                        *t -= col[i] * v;
                    }
                }
            }
            // The rows below it: x[pattern] −= L_bot · top.
            let pattern = node.pattern();
            for (j, &v) in top.iter().enumerate() {
                if v == 0.0 {
                    continue;
                }
                let col = l.col(j);
                for (idx, &row) in pattern.iter().enumerate() {
                    x[row] -= col[size + idx] * v;
                }
            }
            x[start..start + size].copy_from_slice(&top);
            parts.push((start, top));
        }
        Some(ForwardColumn { parts })
    }
}
