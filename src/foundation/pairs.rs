//! The per-offset pair table of any surface kernel and the dense T scattered from it.
//!
//! On the uniform grid an element pair's 4 × 4 block depends only on the offset between the
//! two elements, so the blocks are tabulated once per offset (and per mirror image, which maps
//! to the mirrored offset with the local nodes reflected) and scattered into the dense matrix.
//! The FFT route ([`super::fft`]) reads the same table.
//!
//! The blocks are element-pair 4 × 4 corner blocks, scattered through [`Mesh::element_nodes`]:
//! on a jointed plate, whose elements hold the node copies of their own side, that is the exact
//! Galerkin T of a pressure bilinear per element and discontinuous across the joints, over one
//! soil surface (the cell-corner form) — with no change here.
//!
//! On a symmetry-reduced model the pressure is extended by mirror images to the whole plate, so
//! T includes the settlement caused by the images: the quarter model's quadratic form is exactly
//! a quarter of the whole plate's for symmetric pressures.

use super::kernel::Kernel;
use super::Compliance;
use crate::mesh::Mesh;

/// Local node index reflected about the element's vertical mid-line (x ↦ −x).
pub(crate) const MIRROR_X: [usize; 4] = [1, 0, 3, 2];
/// Local node index reflected about the element's horizontal mid-line (y ↦ −y).
pub(crate) const MIRROR_Y: [usize; 4] = [3, 2, 1, 0];

/// Local nodes (a, b) of an element pair at signed offset (di, dj), reflected so that the pair
/// is read from the block of the offset (|di|, |dj|) ([`Kernel::pair_block`]).
pub fn reflect(di: isize, dj: isize, a: usize, b: usize) -> (usize, usize) {
    let (mut a, mut b) = (a, b);
    if di < 0 {
        a = MIRROR_X[a];
        b = MIRROR_X[b];
    }
    if dj < 0 {
        a = MIRROR_Y[a];
        b = MIRROR_Y[b];
    }
    (a, b)
}

/// Pair blocks for every non-negative offset on a grid of `full` elements (the whole plate).
/// Shared by the dense T and the matrix-free one ([`super::fft`]).
pub(crate) struct PairTable {
    ny: usize,
    blocks: Vec<[[f64; 4]; 4]>,
}

impl PairTable {
    /// Tabulate [`Kernel::pair_block`] for every offset (di, dj) with 0 ≤ di < full[0],
    /// 0 ≤ dj < full[1].
    pub(crate) fn new(full: [usize; 2], hx: f64, hy: f64, kernel: &Kernel) -> Self {
        let mut blocks = Vec::with_capacity(full[0] * full[1]);
        for di in 0..full[0] {
            for dj in 0..full[1] {
                blocks.push(kernel.pair_block(di, dj, hx, hy));
            }
        }
        Self {
            ny: full[1],
            blocks,
        }
    }

    /// Block entry for a signed offset, reflecting local nodes for negative offsets.
    pub(crate) fn get(&self, di: isize, dj: isize, a: usize, b: usize) -> f64 {
        let (a, b) = reflect(di, dj, a, b);
        self.blocks[di.unsigned_abs() * self.ny + dj.unsigned_abs()][a][b]
    }
}

/// Bytes the dense T of a mesh will take.
pub fn dense_bytes(mesh: &Mesh) -> usize {
    mesh.n_nodes() * mesh.n_nodes() * std::mem::size_of::<f64>()
}

/// Galerkin compliance of a kernel with constant `c` in the caller's units, including mirror
/// images on reduced models.
pub fn compliance(mesh: &Mesh, c: f64, kernel: &Kernel) -> Compliance {
    Compliance::Dense(dense_matrix(mesh, c, kernel))
}

/// The dense matrix of [`compliance`].
pub fn dense_matrix(mesh: &Mesh, c: f64, kernel: &Kernel) -> faer::Mat<f64> {
    let full = mesh.full_elements();
    let table = PairTable::new(full, mesh.hx, mesh.hy, kernel);
    let n = mesh.n_nodes();
    let mut t = faer::Mat::<f64>::zeros(n, n);
    // Full-plate element index of a model element.
    let shift_x = if mesh.sym_x { mesh.nx } else { 0 } as isize;
    let shift_y = if mesh.sym_y { mesh.ny } else { 0 } as isize;
    let full_x = full[0] as isize;
    let full_y = full[1] as isize;
    let mut images: Vec<(bool, bool)> = vec![(false, false)];
    if mesh.sym_x {
        images.push((true, false));
    }
    if mesh.sym_y {
        images.push((false, true));
    }
    if mesh.sym_x && mesh.sym_y {
        images.push((true, true));
    }
    let live: Vec<usize> = mesh.elements().collect();
    let ne = live.len();
    let nodes: Vec<[usize; 4]> = live.iter().map(|&e| mesh.element_nodes(e)).collect();
    let pos: Vec<(isize, isize)> = live
        .iter()
        .map(|&e| {
            let (i, j) = mesh.element_ij(e);
            (i as isize + shift_x, j as isize + shift_y)
        })
        .collect();
    for e1 in 0..ne {
        let (gi1, gj1) = pos[e1];
        for &(mx, my) in &images {
            let ii = if mx { full_x - 1 - gi1 } else { gi1 };
            let jj = if my { full_y - 1 - gj1 } else { gj1 };
            let map = |b: usize| {
                let b = if mx { MIRROR_X[b] } else { b };
                if my {
                    MIRROR_Y[b]
                } else {
                    b
                }
            };
            let bmap = [map(0), map(1), map(2), map(3)];
            for e0 in 0..ne {
                let (gi0, gj0) = pos[e0];
                let di = ii - gi0;
                let dj = jj - gj0;
                for b in 0..4 {
                    let col = nodes[e1][b];
                    for a in 0..4 {
                        let row = nodes[e0][a];
                        t[(row, col)] += c * table.get(di, dj, a, bmap[b]);
                    }
                }
            }
        }
    }
    // Symmetrise away the last round-off of the quadrature.
    for j in 0..n {
        for i in (j + 1)..n {
            let s = 0.5 * (t[(i, j)] + t[(j, i)]);
            t[(i, j)] = s;
            t[(j, i)] = s;
        }
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The estimate is the size of the matrix it estimates: n_nodes² doubles, on a whole plate
    /// and on a quarter model (whose nodes are the model's, mirror images folded in).
    #[test]
    fn dense_bytes_is_the_size_of_the_dense_matrix() {
        for (sym_x, sym_y) in [(false, false), (true, true)] {
            let mesh = Mesh::new(2.0, 1.5, [6, 4], sym_x, sym_y);
            let t = dense_matrix(
                &mesh,
                1.0,
                &Kernel::new(crate::foundation::halfspace::Boussinesq),
            );
            assert_eq!(t.nrows(), mesh.n_nodes());
            assert_eq!(
                dense_bytes(&mesh),
                t.nrows() * t.ncols() * std::mem::size_of::<f64>()
            );
        }
    }
}
