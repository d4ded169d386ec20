//! The iterative route's preconditioner: the plate on Winkler springs,
//!
//! M = D + QᵀK_p⁻Q,   M⁻¹ = D⁻¹ − D⁻¹Qᵀ (K_p,r + Q D⁻¹ Qᵀ)⁻¹ Q D⁻¹   (Woodbury),
//!
//! with D a positive diagonal over the pressure nodes (springs), K_p a plate stiffness with its
//! rigid modes fixed (K_p,r) and Q the lumped coupling from nodal pressures to the plate's
//! w-equations: Q[w_I, j] = ∫f_j · φ_I(x_j), φ_I the plate's bilinear function of node I.
//!
//! * **fine**: K_p = K, the model's own plate, Q = the lumped coupling (φ_I(x_j) = δ_Ij), so
//!   Q D⁻¹ Qᵀ is diagonal.
//! * **coarse**: K_p is the same plate on a grid twice as coarse (4× fewer equations, when the
//!   model's element counts are even), φ_I the coarse functions at the fine nodes (1, ½ or ¼),
//!   so Q D⁻¹ Qᵀ couples coarse nodes of one coarse element — inside K_p's own pattern. The
//!   plate dominates A only at low frequencies (well below the coarse grid's), and the solve
//!   with the smaller factor costs about a quarter. A jointed plate's coarse plate has the same
//!   joints (segments and dowels re-derived on the coarse grid) when they lie on its lines, and
//!   each pressure copy spreads over its own side's coarse element; otherwise the fine plate.
//!
//! The symbolic analysis is done once; each penalised set (a new D) costs one numeric
//! factorisation.

use crate::error::{Error, Result};
use crate::mesh::{Dof, DofMap, Mesh};
use crate::operators::Operators;
use faer::MatMut;

use crate::solve::linalg::{reduce, SparseCholesky, SparseFactor};

/// A plate on springs, ready to be factored for any spring diagonal D.
pub struct SpringPlate {
    /// K_p with the fixed equations removed (CSC, full symmetric pattern).
    k: sprs::CsMat<f64>,
    /// Its values without springs.
    base: Vec<f64>,
    chol: SparseCholesky,
    /// Per pressure node: the reduced plate equations it loads, with weights ∫f_j · φ_I(x_j).
    spread: Vec<Vec<(usize, f64)>>,
    /// Per pressure node: data positions in `k` of the pairs (a, b) of its `spread`, row-major.
    pairs: Vec<Vec<usize>>,
    /// "fine" or "coarse".
    pub kind: &'static str,
    /// The fine plate's reduced index of each of the model's equations (None where fixed);
    /// None for a coarse plate, whose equations are not the model's.
    equations: Option<Vec<Option<usize>>>,
}

/// Data position of entry (i, j) of a CSC matrix with sorted row indices.
fn position(m: &sprs::CsMat<f64>, i: usize, j: usize) -> Option<usize> {
    let ptr = m.indptr();
    let ptr = ptr.raw_storage();
    let rows = &m.indices()[ptr[j]..ptr[j + 1]];
    rows.binary_search(&i).ok().map(|p| ptr[j] + p)
}

/// The plate's radius of relative stiffness on the soil, in fine element sizes, below which the
/// preconditioner keeps the fine plate. Where ℓ is short against the coarse elements, the
/// plate's compliance exceeds the soil's at wavelengths the coarse plate cannot carry, so the
/// coarse preconditioner misses what dominates the Schur complement there: on a nearly membrane
/// plate (ℓ = 0.07 h: 0.05 m of 1 MPa on a 30 MPa half-space, 96 × 64 elements) conjugate
/// gradients stalled at 2000 iterations, and with the fine plate they take 134; at ℓ = 0.5 h
/// the coarse plate's penalty still cycled, at ℓ = h it converged in 6 steps (66 CG iterations
/// for the bonded solve, 42 with the fine plate: BENCHMARKS.md). So the coarse plate from one
/// element on, where it costs a quarter of the factorisation.
pub const COARSE_MIN_STIFFNESS_LENGTH: f64 = 1.0;

/// Whether a coarse preconditioner plate carries the plate where it matters: ℓ of the
/// reference plate on its soil at least [`COARSE_MIN_STIFFNESS_LENGTH`] fine elements (always
/// on a local soil, whose preconditioner is exact with the fine plate anyway).
pub fn coarse_resolves(ops: &Operators) -> bool {
    let ell = ops.foundation.stiffness_length(ops.foundation_constant);
    let h = ops.mesh.hx.max(ops.mesh.hy);
    ell >= COARSE_MIN_STIFFNESS_LENGTH * h
}

impl SpringPlate {
    /// The preconditioner's plate for `ops`: coarse when `coarse` is asked and the model's
    /// element counts are even, fine otherwise. (The Schur system asks for it only where the
    /// plate is stiff at the coarse grid's scale, [`coarse_resolves`].)
    pub fn new(ops: &Operators, coarse: bool) -> Result<Self> {
        let m = &ops.mesh;
        if m.topo.is_some() {
            return if coarse {
                Self::coarse_jointed(ops)
            } else {
                Self::fine(ops)
            };
        }
        if coarse && m.nx.is_multiple_of(2) && m.ny.is_multiple_of(2) && m.nx >= 2 && m.ny >= 2 {
            Self::coarse(ops)
        } else {
            Self::fine(ops)
        }
    }

    fn fine(ops: &Operators) -> Result<Self> {
        let (k, map) = reduce(&ops.k, &ops.fixed);
        let areas = crate::foundation::nodal_areas(&ops.mesh);
        let spread: Vec<Vec<(usize, f64)>> = (0..ops.n_sigma())
            .map(|j| {
                ops.dofs
                    .eq(j, Dof::W)
                    .and_then(|e| map[e])
                    .map(|r| vec![(r, areas[j])])
                    .unwrap_or_default()
            })
            .collect();
        let fixed = &ops.fixed;
        let order = crate::mesh::equation_order(&ops.mesh, &ops.dofs, |e| !fixed.contains(&e));
        let mut plate = Self::finish(k, spread, &order, "fine")?;
        plate.equations = Some(map);
        Ok(plate)
    }

    fn coarse(ops: &Operators) -> Result<Self> {
        let m = &ops.mesh;
        let full = m.full_elements();
        let cmesh = Mesh::new(
            m.hx * full[0] as f64,
            m.hy * full[1] as f64,
            [full[0] / 2, full[1] / 2],
            m.sym_x,
            m.sym_y,
        );
        // The halved whole-plate counts are odd when the model's are: then Mesh::new drops
        // the reduction; use the fine plate.
        if cmesh.sym_x != m.sym_x || cmesh.sym_y != m.sym_y {
            return Self::fine(ops);
        }
        let cdofs = DofMap::new(&cmesh);
        let kc = crate::plate::assemble_stiffness(&cmesh, &cdofs, &ops.section);
        let (_, cfixed) = crate::operators::rigid_modes(&cmesh, &cdofs);
        let (k, map) = reduce(&kc, &cfixed);
        let areas = crate::foundation::nodal_areas(m);
        let nx1 = m.nodes_x();
        let spread: Vec<Vec<(usize, f64)>> = (0..ops.n_sigma())
            .map(|j| {
                let (p, q) = (j % nx1, j / nx1);
                let along = |i: usize| -> Vec<(usize, f64)> {
                    if i.is_multiple_of(2) {
                        vec![(i / 2, 1.0)]
                    } else {
                        vec![(i / 2, 0.5), (i / 2 + 1, 0.5)]
                    }
                };
                let mut out = Vec::with_capacity(4);
                for (ci, wi) in along(p) {
                    for &(cj, wj) in &along(q) {
                        let node = cmesh.node(ci, cj);
                        if let Some(r) = cdofs.eq(node, Dof::W).and_then(|e| map[e]) {
                            out.push((r, areas[j] * wi * wj));
                        }
                    }
                }
                out
            })
            .collect();
        let order = crate::mesh::equation_order(&cmesh, &cdofs, |e| !cfixed.contains(&e));
        Self::finish(k, spread, &order, "coarse")
    }

    /// The coarse plate of a plate with a layout: the same layout on the grid twice as coarse
    /// ([`Mesh::coarsened`]: when the joints stay on its lines; the fine plate otherwise), its
    /// panels' sections, joint elements and dowels, fixed by its own rigid modes; a pressure
    /// node spreads over the corners of the coarse element holding one of its fine elements,
    /// with the coarse bilinear weights at its position (so each side of a joint loads its own
    /// side's coarse plate). On a grid that no joint cuts these are the weights (1, ½, ¼) of
    /// [`Self::coarse`].
    fn coarse_jointed(ops: &Operators) -> Result<Self> {
        let m = &ops.mesh;
        let (Some(cmesh), Some(topo)) = (m.coarsened(), m.topo.as_ref()) else {
            return Self::fine(ops);
        };
        let cdofs = DofMap::new(&cmesh);
        let kc = crate::system::assemble_system(&cmesh, &cdofs, &ops.sections);
        let (_, cfixed, _) = crate::operators::jointed_rigid_modes(&cmesh, &cdofs);
        let (k, map) = reduce(&kc, &cfixed);
        let areas = crate::foundation::nodal_areas(m);
        let spread: Vec<Vec<(usize, f64)>> = (0..ops.n_sigma())
            .map(|j| {
                let Some(&(e, _)) = topo.incident(j).first() else {
                    return Vec::new();
                };
                let (ie, je) = m.element_ij(e);
                let (ci, cj) = (ie / 2, je / 2);
                let (x, y) = m.node_xy(j);
                let xi = 2.0 * (x - cmesh.x0) / cmesh.hx - 2.0 * ci as f64 - 1.0;
                let eta = 2.0 * (y - cmesh.y0) / cmesh.hy - 2.0 * cj as f64 - 1.0;
                let weights = crate::plate::shape(xi, eta);
                cmesh
                    .element_nodes(ci + cj * cmesh.nx)
                    .into_iter()
                    .zip(weights)
                    // Round-off weights at the far corners of a coarse element: dropped.
                    .filter(|&(_, w)| w.abs() > 1e-12)
                    .filter_map(|(node, w)| {
                        cdofs
                            .eq(node, Dof::W)
                            .and_then(|e| map[e])
                            .map(|r| (r, areas[j] * w))
                    })
                    .collect()
            })
            .collect();
        let order = crate::mesh::equation_order(&cmesh, &cdofs, |e| !cfixed.contains(&e));
        Self::finish(k, spread, &order, "coarse")
    }

    fn finish(
        k: sprs::CsMat<f64>,
        spread: Vec<Vec<(usize, f64)>>,
        order: &[usize],
        kind: &'static str,
    ) -> Result<Self> {
        let mut pairs = Vec::with_capacity(spread.len());
        for s in &spread {
            let mut p = Vec::with_capacity(s.len() * s.len());
            for &(a, _) in s {
                for &(b, _) in s {
                    p.push(position(&k, a, b).ok_or_else(|| {
                        Error::numerical(
                            "iterative preconditioner",
                            "a spring coupling falls outside the plate's pattern",
                        )
                    })?);
                }
            }
            pairs.push(p);
        }
        let chol = SparseCholesky::analyse_ordered(&k, Some(order))?;
        Ok(Self {
            base: k.data().to_vec(),
            k,
            chol,
            spread,
            pairs,
            kind,
            equations: None,
        })
    }

    /// Factor K_p,r + Q D⁻¹ Qᵀ for the springs 1/D (`inv_d`).
    pub fn factor(&self, inv_d: &[f64]) -> Result<SparseFactor> {
        let mut k = self.k.clone();
        k.data_mut().copy_from_slice(&self.base);
        let data = k.data_mut();
        for (j, s) in self.spread.iter().enumerate() {
            let n = s.len();
            for a in 0..n {
                for b in 0..n {
                    data[self.pairs[j][a * n + b]] += s[a].1 * s[b].1 * inv_d[j];
                }
            }
        }
        self.chol
            .factor(&k, "iterative preconditioner (plate on springs)")
    }

    /// F⁻¹ p for each load `p` of `loads` on the model's equations, in one block solve, F the
    /// factor of [`Self::factor`]: the fine plate on the springs 1/D with its rigid modes fixed
    /// (zero on the fixed equations). None on a coarse plate.
    pub fn plate_solves(&self, factor: &SparseFactor, loads: &[Vec<f64>]) -> Option<Vec<Vec<f64>>> {
        let map = self.equations.as_ref()?;
        let n = self.k.rows();
        let mut block = vec![0.0; n * loads.len()];
        for (col, p) in block.chunks_mut(n.max(1)).zip(loads) {
            for (e, m) in map.iter().enumerate() {
                if let Some(r) = m {
                    col[*r] = p[e];
                }
            }
        }
        factor.solve_in_place(MatMut::from_column_major_slice_mut(
            &mut block,
            n,
            loads.len(),
        ));
        (0..loads.len()).map(|k| self.to_model(&block, k)).collect()
    }

    /// M⁻¹ r for each r of `rs` ([`Self::solve`]), in one block solve; also the plate's part
    /// F⁻¹QD⁻¹r of each, on the reduced equations (column-major, one column per r).
    pub fn solve_many<R: AsRef<[f64]>>(
        &self,
        inv_d: &[f64],
        factor: &SparseFactor,
        rs: &[R],
    ) -> (Vec<Vec<f64>>, Vec<f64>) {
        let n = self.k.rows();
        let zs: Vec<Vec<f64>> = rs
            .iter()
            .map(|r| r.as_ref().iter().zip(inv_d).map(|(a, b)| a * b).collect())
            .collect();
        let mut block = vec![0.0; n * rs.len()];
        for (col, z) in block.chunks_mut(n.max(1)).zip(&zs) {
            for (j, s) in self.spread.iter().enumerate() {
                for &(e, w) in s {
                    col[e] += w * z[j];
                }
            }
        }
        factor.solve_in_place(MatMut::from_column_major_slice_mut(&mut block, n, rs.len()));
        let out = zs
            .iter()
            .zip(block.chunks(n.max(1)))
            .map(|(z, red)| {
                z.iter()
                    .enumerate()
                    .map(|(j, &zj)| {
                        let back: f64 = self.spread[j].iter().map(|&(e, w)| w * red[e]).sum();
                        zj - inv_d[j] * back
                    })
                    .collect()
            })
            .collect();
        (out, block)
    }

    /// Column `k` of a reduced block of [`Self::solve_many`] on the model's equations (zero on
    /// the fixed ones); None on a coarse plate or past the block's end.
    pub fn to_model(&self, block: &[f64], k: usize) -> Option<Vec<f64>> {
        let map = self.equations.as_ref()?;
        let n = self.k.rows();
        let col = block.get(k * n..(k + 1) * n)?;
        Some(map.iter().map(|m| m.map_or(0.0, |r| col[r])).collect())
    }

    /// M⁻¹ r = D⁻¹r − D⁻¹Qᵀ F⁻¹ Q D⁻¹ r with F the factor of [`Self::factor`].
    pub fn solve(&self, inv_d: &[f64], factor: &SparseFactor, r: &[f64]) -> Vec<f64> {
        let (mut out, _) = self.solve_many(inv_d, factor, &[r]);
        out.pop().unwrap_or_default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ops(n: usize) -> Operators {
        let text = crate::examples::scene("paper-halfspace").unwrap_or_default();
        let p = crate::scene::Problem::from_toml(
            &text.replace("elements = [16, 16]", &format!("elements = [{n}, {n}]")),
        )
        .expect("paper scene");
        Operators::assemble(&p.model)
    }

    /// M (M⁻¹ r) = r with M = D + QᵀK_p,r⁻¹Q formed densely from the plate's own matrix: checks
    /// the Woodbury solve, the spread weights and the spring positions, for both plates.
    #[test]
    fn woodbury_solve_inverts_the_dense_preconditioner() {
        let ops = ops(8);
        for coarse in [false, true] {
            let sp = SpringPlate::new(&ops, coarse).expect("springs");
            assert_eq!(sp.kind, if coarse { "coarse" } else { "fine" });
            woodbury_check(&ops, &sp);
        }
    }

    /// M (M⁻¹ r) = r for one plate on springs.
    fn woodbury_check(ops: &Operators, sp: &SpringPlate) {
        let n = ops.n_sigma();
        {
            let inv_d: Vec<f64> = (0..n).map(|j| 1.0 + 0.1 * (j % 7) as f64).collect();
            let factor = sp.factor(&inv_d).expect("factor");
            let r: Vec<f64> = (0..n).map(|j| ((j * 37 % 11) as f64) - 5.0).collect();
            let z = sp.solve(&inv_d, &factor, &r);
            // Dense K_p,r and Q.
            let m = sp.k.rows();
            let mut k = faer::Mat::<f64>::zeros(m, m);
            for (j, col) in sp.k.outer_iterator().enumerate() {
                for (i, &v) in col.iter() {
                    k[(i, j)] = v;
                }
            }
            let mut q = faer::Mat::<f64>::zeros(m, n);
            for (j, s) in sp.spread.iter().enumerate() {
                for &(e, w) in s {
                    q[(e, j)] += w;
                }
            }
            // M z = D z + Qᵀ K⁻¹ (Q z).
            let llt = crate::solve::linalg::dense_cholesky(&k, "test K").expect("SPD");
            let mut qz = faer::Mat::<f64>::from_fn(m, 1, |e, _| {
                (0..n).map(|j| q[(e, j)] * z[j]).sum::<f64>()
            });
            crate::solve::linalg::SpdSolve::solve_in_place(&llt, qz.as_mut());
            let scale = r.iter().map(|v| v.abs()).fold(0.0, f64::max);
            for j in 0..n {
                let back: f64 = (0..m).map(|e| q[(e, j)] * qz[(e, 0)]).sum();
                let mz = z[j] / inv_d[j] + back;
                assert!(
                    (mz - r[j]).abs() < 1e-9 * scale,
                    "{} plate, node {j}: (M M⁻¹ r) = {mz} vs r = {}",
                    sp.kind,
                    r[j]
                );
            }
        }
    }

    fn jointed_ops(joints: &str, n: usize) -> Operators {
        let text = crate::examples::scene("paper-halfspace").unwrap_or_default();
        let text = text.replace("elements = [16, 16]", &format!("elements = [{n}, {n}]"));
        let text = text.replace("[mesh]", &format!("{joints}\n[mesh]"));
        let p = crate::scene::Problem::from_toml(&text).expect("jointed paper scene");
        Operators::assemble(&p.model)
    }

    /// The jointed coarse plate: on a layout that cuts nothing (a continuous line) it is the
    /// plain coarse plate, weights and matrix; on a cut one the weights of each pressure node
    /// (copies included) sum to its area, each copy loads only its own side's coarse nodes, and
    /// the Woodbury solve inverts the dense preconditioner.
    #[test]
    fn jointed_coarse_plate() {
        let plain = ops(16);
        let uncut = jointed_ops(
            "[[joint]]\nx = 0.5\nkind = \"continuous\"\n[[joint]]\nx = -0.5\nkind = \"continuous\"",
            16,
        );
        let (a, b) = (
            SpringPlate::new(&plain, true).expect("springs"),
            SpringPlate::new(&uncut, true).expect("springs"),
        );
        assert_eq!(b.kind, "coarse");
        assert_eq!(a.k.indices(), b.k.indices());
        for (x, y) in a.k.data().iter().zip(b.k.data()) {
            assert!((x - y).abs() <= 1e-14 * x.abs().max(1.0));
        }
        for (sa, sb) in a.spread.iter().zip(&b.spread) {
            let mut sa = sa.clone();
            let mut sb = sb.clone();
            sa.sort_by_key(|p| p.0);
            sb.sort_by_key(|p| p.0);
            assert_eq!(sa.len(), sb.len());
            for (p, q) in sa.iter().zip(&sb) {
                assert_eq!(p.0, q.0);
                assert!((p.1 - q.1).abs() <= 1e-15 * p.1.abs().max(1e-3));
            }
        }
        let cut = jointed_ops("[[joint]]\nx = 0.5\nkind = \"aggregate\"\nstiffness = 10.0\n[[joint]]\nx = -0.5\nkind = \"aggregate\"\nstiffness = 10.0\n[[joint]]\ny = 0.5\nkind = \"free\"\n[[joint]]\ny = -0.5\nkind = \"free\"", 16);
        assert!(cut.mesh.is_jointed());
        let sp = SpringPlate::new(&cut, true).expect("springs");
        assert_eq!(sp.kind, "coarse");
        let areas = crate::foundation::nodal_areas(&cut.mesh);
        let inside = |j: usize| {
            let (x, y) = cut.mesh.node_xy(j);
            x.abs() < 0.99 && y.abs() < 0.99
        };
        for (j, s) in sp.spread.iter().enumerate() {
            let sum: f64 = s.iter().map(|&(_, w)| w).sum();
            // Equal to the area, or less next to a fixed coarse equation, whose share drops.
            assert!(sum <= areas[j] * (1.0 + 1e-14), "node {j}");
            if inside(j) && s.len() == 4 {
                assert!(
                    (sum - areas[j]).abs() < 1e-14,
                    "node {j}: {sum} vs {}",
                    areas[j]
                );
            }
        }
        woodbury_check(&cut, &sp);
    }

    /// The coarse plate has a quarter of the elements and the coarse weights of each pressure
    /// node sum to its area (the coarse functions are a partition of unity).
    #[test]
    fn coarse_spread_is_a_partition_of_the_nodal_areas() {
        let ops = ops(16);
        let sp = SpringPlate::new(&ops, true).expect("springs");
        let areas = crate::foundation::nodal_areas(&ops.mesh);
        // Quarter of 16 × 16: 8 × 8 fine elements, 4 × 4 coarse ones on 5 × 5 nodes: w on 25,
        // ψx off the line x = 0 on 20, ψy off y = 0 on 20, less the fixed corner's w.
        assert_eq!(sp.k.rows(), 25 + 20 + 20 - 1, "coarse equations");
        for (j, s) in sp.spread.iter().enumerate() {
            let sum: f64 = s.iter().map(|&(_, w)| w).sum();
            // Equal to the area, or less next to the fixed corner, whose share is dropped.
            assert!(
                sum <= areas[j] * (1.0 + 1e-14),
                "node {j}: {sum} > {}",
                areas[j]
            );
        }
        let interior = ops.mesh.node(3, 3);
        let s: f64 = sp.spread[interior].iter().map(|&(_, w)| w).sum();
        assert!(
            (s - areas[interior]).abs() < 1e-15,
            "interior node: {s} vs {}",
            areas[interior]
        );
    }
}
