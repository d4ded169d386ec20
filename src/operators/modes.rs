//! The rigid-body modes of the model — the zero-energy modes of its stiffness K — and the
//! equations fixed to define a generalised inverse of K (one per mode).
//!
//! A plate of one piece has three (translation and two rotations; two or one on a model reduced
//! by symmetry). A jointed plate has those of its rigid pieces (the panels between the lines
//! that cut it) that its joints leave free: with the piece modes R (three per piece, fewer on a
//! symmetry line) and the joints' stiffness K_j, the modes are R·null(Rᵀ K_j R). Panels joined
//! only by shear springs keep hinge modes; free joints leave each piece its own three. The
//! count is computed, never assumed.

use nalgebra::{DMatrix, SymmetricEigen};

use crate::mesh::{Dof, DofMap, Mesh, Topology};
use crate::system::joint_blocks;

/// Rigid-body modes of the (reduced) free plate and the w-equations to fix for a generalised
/// inverse: translation w = 1 always; rotation w = x, ψx = 1 unless the model is reduced about
/// x = 0; rotation w = y, ψy = 1 unless reduced about y = 0.
pub fn rigid_modes(mesh: &Mesh, dofs: &DofMap) -> (Vec<Vec<f64>>, Vec<usize>) {
    let n_eq = dofs.n_eq();
    let mut modes = Vec::new();
    let mut translation = vec![0.0; n_eq];
    let mut rot_x = vec![0.0; n_eq];
    let mut rot_y = vec![0.0; n_eq];
    for n in 0..mesh.n_nodes() {
        let (x, y) = mesh.node_xy(n);
        if let Some(e) = dofs.eq(n, Dof::W) {
            translation[e] = 1.0;
            rot_x[e] = x;
            rot_y[e] = y;
        }
        if let Some(e) = dofs.eq(n, Dof::PsiX) {
            rot_x[e] = 1.0;
        }
        if let Some(e) = dofs.eq(n, Dof::PsiY) {
            rot_y[e] = 1.0;
        }
    }
    modes.push(translation);
    if !mesh.sym_x {
        modes.push(rot_x);
    }
    if !mesh.sym_y {
        modes.push(rot_y);
    }
    // Fixed nodes: corners far from the symmetry lines, non-collinear.
    let (i_max, j_max) = (mesh.nx, mesh.ny);
    let corners: Vec<(usize, usize)> = match (mesh.sym_x, mesh.sym_y) {
        (false, false) => vec![(0, 0), (i_max, 0), (0, j_max)],
        (true, false) => vec![(i_max, 0), (i_max, j_max)],
        (false, true) => vec![(0, j_max), (i_max, j_max)],
        (true, true) => vec![(i_max, j_max)],
    };
    let fixed = corners
        .into_iter()
        .filter_map(|(i, j)| dofs.eq(mesh.node(i, j), Dof::W))
        .collect();
    (modes, fixed)
}

/// The modes of one cluster and the equations fixed for them.
struct ClusterModes {
    modes: Vec<Vec<f64>>,
    fixed: Vec<usize>,
}

/// One piece's frame: centre and half-diagonal (so that the mode entries are O(1)), and which
/// rotations it keeps on a reduced model.
#[derive(Clone, Copy)]
struct Frame {
    centre: (f64, f64),
    scale: f64,
    /// Rotation about y (w = x, ψx = 1) kept: not a piece on the line x = 0 of a model
    /// reduced about it.
    turn_y: bool,
    /// Rotation about x (w = y, ψy = 1) kept.
    turn_x: bool,
}

impl Frame {
    /// (w, ψx, ψy) of the piece's mode `kind` (0 translation, 1 about y, 2 about x) at (x, y).
    fn value(&self, kind: usize, x: f64, y: f64) -> [f64; 3] {
        let s = self.scale;
        match kind {
            0 => [1.0, 0.0, 0.0],
            1 => [(x - self.centre.0) / s, 1.0 / s, 0.0],
            _ => [(y - self.centre.1) / s, 0.0, 1.0 / s],
        }
    }
}

/// The rigid pieces' frames of a jointed mesh.
fn frames(mesh: &Mesh, topo: &Topology) -> Vec<Frame> {
    let n = topo.n_pieces();
    let mut bounds = vec![
        [
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY
        ];
        n
    ];
    for e in mesh.elements() {
        let (xc, yc) = mesh.element_centre(e);
        let b = &mut bounds[topo.piece[e] as usize];
        b[0] = b[0].min(xc - 0.5 * mesh.hx);
        b[1] = b[1].max(xc + 0.5 * mesh.hx);
        b[2] = b[2].min(yc - 0.5 * mesh.hy);
        b[3] = b[3].max(yc + 0.5 * mesh.hy);
    }
    // A piece touches a symmetry line when its lower bound is the model's first grid line.
    let on = |lo: f64, origin: f64, h: f64| (lo - origin).abs() <= 1e-9 * h;
    bounds
        .iter()
        .map(|b| Frame {
            centre: (0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3])),
            scale: 0.5 * (b[1] - b[0]).hypot(b[3] - b[2]),
            turn_y: !(mesh.sym_x && on(b[0], mesh.x0, mesh.hx)),
            turn_x: !(mesh.sym_y && on(b[2], mesh.y0, mesh.hy)),
        })
        .collect()
}

/// Relative size below which an eigenvalue of Rᵀ K_j R counts as zero: the joints' matrix has
/// unit constants (its null space is that of any positive constants), entries of the order of
/// the joints' length and the piece modes O(1), so the nonzero eigenvalues are O(h) at worst
/// while the zero ones are round-off, ~1e-16 of the largest.
pub const NULL_TOLERANCE: f64 = 1e-10;

/// Rigid modes of a jointed mesh and the equations fixed for them, cluster by cluster (pieces
/// joined by transferring joints): the piece modes R_c of the cluster, the joints' stiffness
/// with unit constants K_j, and the null space N_c of G_c = R_cᵀ K_j R_c (eigenvalues at most
/// [`NULL_TOLERANCE`] of max(λ_max, 1)); the modes are R_c N_c. Per cluster, the fixed equations
/// are chosen by greedy pivoting on the rows of R_c N_c over the cluster's w-equations (the
/// largest row, then that direction projected out of all rows, m_c times; ties to the lowest
/// equation), so that (R N)[fixed, :] is nonsingular and K with those equations removed is
/// positive definite. Also returns each mode's cluster. On a mesh no joint cuts these are
/// [`rigid_modes`]' (one cluster).
pub fn jointed_rigid_modes(mesh: &Mesh, dofs: &DofMap) -> (Vec<Vec<f64>>, Vec<usize>, Vec<usize>) {
    let Some(topo) = mesh.topo.as_ref().filter(|t| t.cuts() || t.is_shaped()) else {
        let (modes, fixed) = rigid_modes(mesh, dofs);
        let clusters = vec![0; modes.len()];
        return (modes, fixed, clusters);
    };
    let frames = frames(mesh, topo);
    // Columns: (piece, kind) with kind 0 translation, 1 about y, 2 about x; numbered per
    // cluster.
    let n_clusters = topo.n_clusters();
    let mut columns: Vec<Vec<(usize, usize)>> = vec![Vec::new(); n_clusters];
    let mut column_of = vec![[usize::MAX; 3]; topo.n_pieces()];
    for (p, f) in frames.iter().enumerate() {
        let c = topo.cluster[p] as usize;
        for (kind, keep) in [(0, true), (1, f.turn_y), (2, f.turn_x)] {
            if keep {
                column_of[p][kind] = columns[c].len();
                columns[c].push((p, kind));
            }
        }
    }
    let piece_of = |n: usize| -> usize {
        topo.incident(n)
            .first()
            .map_or(0, |&(e, _)| topo.piece[e] as usize)
    };
    // Joint energy in the piece modes, per cluster (a spring joins pieces of one cluster).
    let mut g: Vec<DMatrix<f64>> = columns
        .iter()
        .map(|c| DMatrix::zeros(c.len(), c.len()))
        .collect();
    for blk in joint_blocks(topo, true) {
        let c = topo.cluster[piece_of(blk.nodes[0])] as usize;
        // Row of each node: its mode values of the block's dof over the cluster's columns.
        let rows: Vec<Vec<(usize, f64)>> = blk
            .nodes
            .iter()
            .map(|&n| {
                if dofs.eq(n, blk.dof).is_none() {
                    return Vec::new();
                }
                let p = piece_of(n);
                let (x, y) = mesh.node_xy(n);
                (0..3)
                    .filter(|&k| column_of[p][k] != usize::MAX)
                    .map(|k| (column_of[p][k], frames[p].value(k, x, y)[blk.dof as usize]))
                    .collect()
            })
            .collect();
        for p in 0..4 {
            for q in 0..4 {
                for &(i, vi) in &rows[p] {
                    for &(j, vj) in &rows[q] {
                        g[c][(i, j)] += blk.k[p][q] * vi * vj;
                    }
                }
            }
        }
    }
    // The cluster's node copies.
    let mut nodes: Vec<Vec<usize>> = vec![Vec::new(); n_clusters];
    for n in 0..mesh.n_nodes() {
        nodes[topo.cluster[piece_of(n)] as usize].push(n);
    }
    let (mut modes, mut fixed, mut cluster) = (Vec::new(), Vec::new(), Vec::new());
    for c in 0..n_clusters {
        let cm = cluster_modes(
            mesh,
            dofs,
            &frames,
            &columns[c],
            &g[c],
            &nodes[c],
            &piece_of,
        );
        cluster.extend(std::iter::repeat_n(c, cm.modes.len()));
        modes.extend(cm.modes);
        fixed.extend(cm.fixed);
    }
    (modes, fixed, cluster)
}

/// The null space of one cluster's G as modes over the equations, and their fixed equations.
fn cluster_modes(
    mesh: &Mesh,
    dofs: &DofMap,
    frames: &[Frame],
    columns: &[(usize, usize)],
    g: &DMatrix<f64>,
    nodes: &[usize],
    piece_of: &impl Fn(usize) -> usize,
) -> ClusterModes {
    let m = columns.len();
    let sym = DMatrix::from_fn(m, m, |i, j| 0.5 * (g[(i, j)] + g[(j, i)]));
    let eig = SymmetricEigen::new(sym);
    let top = eig.eigenvalues.iter().cloned().fold(1.0_f64, f64::max);
    let null: Vec<usize> = (0..m)
        .filter(|&k| eig.eigenvalues[k] <= NULL_TOLERANCE * top)
        .collect();
    // Column index of (piece, kind) within the cluster.
    let local = |p: usize, kind: usize| columns.iter().position(|&c| c == (p, kind));
    let mut modes = vec![vec![0.0; dofs.n_eq()]; null.len()];
    // Rows of R N over the cluster's w-equations, for the pivoting.
    let mut w_rows: Vec<(usize, Vec<f64>)> = Vec::new();
    for &n in nodes {
        let p = piece_of(n);
        let (x, y) = mesh.node_xy(n);
        let idx: Vec<(usize, [f64; 3])> = (0..3)
            .filter_map(|kind| local(p, kind).map(|i| (i, frames[p].value(kind, x, y))))
            .collect();
        for d in [Dof::W, Dof::PsiX, Dof::PsiY] {
            let Some(eq) = dofs.eq(n, d) else { continue };
            let row: Vec<f64> = null
                .iter()
                .map(|&k| {
                    idx.iter()
                        .map(|&(i, v)| eig.eigenvectors[(i, k)] * v[d as usize])
                        .sum()
                })
                .collect();
            for (mode, &v) in modes.iter_mut().zip(&row) {
                mode[eq] = v;
            }
            if d == Dof::W {
                w_rows.push((eq, row));
            }
        }
    }
    w_rows.sort_by_key(|r| r.0);
    let mut fixed = Vec::with_capacity(null.len());
    for _ in 0..null.len() {
        let mut best: Option<(usize, f64)> = None;
        for (k, (_, row)) in w_rows.iter().enumerate() {
            let norm: f64 = row.iter().map(|v| v * v).sum();
            // Ties (to round-off) go to the lowest equation.
            if best.is_none_or(|(_, b)| norm > b * (1.0 + 1e-9)) {
                best = Some((k, norm));
            }
        }
        let Some((k, norm)) = best.filter(|&(_, n)| n > 0.0) else {
            break;
        };
        fixed.push(w_rows[k].0);
        let dir: Vec<f64> = w_rows[k].1.iter().map(|v| v / norm.sqrt()).collect();
        for (_, row) in &mut w_rows {
            let along: f64 = row.iter().zip(&dir).map(|(a, b)| a * b).sum();
            for (r, d) in row.iter_mut().zip(&dir) {
                *r -= along * d;
            }
        }
    }
    ClusterModes { modes, fixed }
}
