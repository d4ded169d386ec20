//! The iterative route's preconditioner: the plate on a sparse foundation,
//!
//! M = W⁻¹ + QᵀK_p⁻Q,   M⁻¹ = W − W Qᵀ (K_p,r + Q W Qᵀ)⁻¹ Q W   (Woodbury),
//!
//! with W a symmetric positive definite stiffness over the pressure nodes ([`Springs`]: a
//! diagonal — Winkler springs, W = D⁻¹ — and, for a shear layer, couplings along the element
//! edges, [`SpringPlate::links`]), K_p a plate stiffness with its rigid modes fixed (K_p,r) and Q
//! the lumped coupling from nodal pressures to the plate's w-equations:
//! Q[w_I, j] = ∫f_j · φ_I(x_j), φ_I the plate's bilinear function of node I.
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
//! The symbolic analysis is done once (with the links' couplings in the pattern when the plate
//! is made for a shear layer); each penalised set (a new W) costs one numeric factorisation.

use crate::error::{Error, Result};
use crate::mesh::{Dof, DofMap, Mesh};
use crate::operators::Operators;
use faer::MatMut;

use crate::solve::linalg::{reduce, SparseCholesky, SparseFactor};

/// The preconditioner's foundation W over the pressure nodes: W_jj, and W_ij on the plate's
/// links ([`SpringPlate::links`]; none: springs only, W = diag).
#[derive(Clone, Debug)]
pub struct Springs {
    /// W_jj (0 on held points).
    pub diag: Vec<f64>,
    /// W_ij per link (i, j) of the plate, in its order (empty: no link; 0: a cut link).
    pub off: Vec<f64>,
}

impl Springs {
    /// Springs only: W = diag(`diag`).
    pub fn diagonal(diag: Vec<f64>) -> Self {
        Self {
            diag,
            off: Vec::new(),
        }
    }
}

/// A coupling of two pressure nodes along an element edge.
#[derive(Clone, Debug)]
pub struct Link {
    /// The two pressure nodes.
    pub nodes: (usize, usize),
    /// 1/h² of the edge's length h: the link's weight in the graph Laplacian whose symbol is
    /// the five-point one, (4/hx²) sin²(ξx hx/2) + (4/hy²) sin²(ξy hy/2).
    pub weight: f64,
    /// Data positions in K_p of (a, b) and (b, a), for a of the first node's spread and b of
    /// the second's (row-major).
    pos: Vec<(usize, usize)>,
}

/// A plate on springs, ready to be factored for any foundation W ([`Springs`]).
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
    /// The element edges between pressure nodes (empty unless made for a shear layer).
    pub links: Vec<Link>,
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
    /// plate is stiff at the coarse grid's scale, [`coarse_resolves`].) With `shear`, its
    /// pattern also holds the couplings of a shear layer's links ([`Self::links`]).
    pub fn new(ops: &Operators, coarse: bool, shear: bool) -> Result<Self> {
        let m = &ops.mesh;
        let links = if shear { edge_links(m) } else { Vec::new() };
        if m.topo.is_some() {
            return if coarse {
                Self::coarse_jointed(ops, &links)
            } else {
                Self::fine(ops, &links)
            };
        }
        if coarse && m.nx.is_multiple_of(2) && m.ny.is_multiple_of(2) && m.nx >= 2 && m.ny >= 2 {
            Self::coarse(ops, &links)
        } else {
            Self::fine(ops, &links)
        }
    }

    fn fine(ops: &Operators, links: &[(usize, usize, f64)]) -> Result<Self> {
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
        let mut plate = Self::finish(k, spread, links, &order, "fine")?;
        plate.equations = Some(map);
        Ok(plate)
    }

    fn coarse(ops: &Operators, links: &[(usize, usize, f64)]) -> Result<Self> {
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
            return Self::fine(ops, links);
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
        Self::finish(k, spread, links, &order, "coarse")
    }

    /// The coarse plate of a plate with a layout: the same layout on the grid twice as coarse
    /// ([`Mesh::coarsened`]: when the joints stay on its lines; the fine plate otherwise), its
    /// panels' sections, joint elements and dowels, fixed by its own rigid modes; a pressure
    /// node spreads over the corners of the coarse element holding one of its fine elements,
    /// with the coarse bilinear weights at its position (so each side of a joint loads its own
    /// side's coarse plate). On a grid that no joint cuts these are the weights (1, ½, ¼) of
    /// [`Self::coarse`].
    fn coarse_jointed(ops: &Operators, links: &[(usize, usize, f64)]) -> Result<Self> {
        let m = &ops.mesh;
        let (Some(cmesh), Some(topo)) = (m.coarsened(), m.topo.as_ref()) else {
            return Self::fine(ops, links);
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
        Self::finish(k, spread, links, &order, "coarse")
    }

    fn finish(
        k: sprs::CsMat<f64>,
        spread: Vec<Vec<(usize, f64)>>,
        links: &[(usize, usize, f64)],
        order: &[usize],
        kind: &'static str,
    ) -> Result<Self> {
        // The links' couplings Q_a,i Q_b,j in the pattern (explicit zeros where K_p has none:
        // on the coarse plate a link can join coarse nodes two elements apart).
        let extra: Vec<(usize, usize)> = links
            .iter()
            .flat_map(|&(i, j, _)| {
                let (si, sj) = (&spread[i], &spread[j]);
                si.iter()
                    .flat_map(move |&(a, _)| sj.iter().flat_map(move |&(b, _)| [(a, b), (b, a)]))
            })
            .collect();
        let k = with_entries(&k, &extra);
        let outside = || {
            Error::numerical(
                "iterative preconditioner",
                "a spring coupling falls outside the plate's pattern",
            )
        };
        let links = links
            .iter()
            .map(|&(i, j, weight)| {
                let mut pos = Vec::with_capacity(spread[i].len() * spread[j].len());
                for &(a, _) in &spread[i] {
                    for &(b, _) in &spread[j] {
                        pos.push((
                            position(&k, a, b).ok_or_else(outside)?,
                            position(&k, b, a).ok_or_else(outside)?,
                        ));
                    }
                }
                Ok(Link {
                    nodes: (i, j),
                    weight,
                    pos,
                })
            })
            .collect::<Result<Vec<_>>>()?;
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
            links,
            kind,
            equations: None,
        })
    }

    /// Factor K_p,r + Q W Qᵀ for the foundation `w`.
    pub fn factor(&self, w: &Springs) -> Result<SparseFactor> {
        let mut k = self.k.clone();
        k.data_mut().copy_from_slice(&self.base);
        let data = k.data_mut();
        for (j, s) in self.spread.iter().enumerate() {
            let n = s.len();
            for a in 0..n {
                for b in 0..n {
                    data[self.pairs[j][a * n + b]] += s[a].1 * s[b].1 * w.diag[j];
                }
            }
        }
        // A link (i, j) adds Q_a,i W_ij Q_b,j at (a, b) and at (b, a) (twice where a = b).
        for (link, &g) in self.links.iter().zip(&w.off) {
            if g == 0.0 {
                continue;
            }
            let (si, sj) = (&self.spread[link.nodes.0], &self.spread[link.nodes.1]);
            let mut pos = link.pos.iter();
            for &(_, qa) in si {
                for &(_, qb) in sj {
                    if let Some(&(ab, ba)) = pos.next() {
                        data[ab] += qa * qb * g;
                        data[ba] += qa * qb * g;
                    }
                }
            }
        }
        self.chol
            .factor(&k, "iterative preconditioner (plate on springs)")
    }

    /// W r.
    pub fn apply(&self, w: &Springs, r: &[f64]) -> Vec<f64> {
        let mut out: Vec<f64> = r.iter().zip(&w.diag).map(|(a, b)| a * b).collect();
        for (link, &g) in self.links.iter().zip(&w.off) {
            if g != 0.0 {
                let (i, j) = link.nodes;
                out[i] += g * r[j];
                out[j] += g * r[i];
            }
        }
        out
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
        w: &Springs,
        factor: &SparseFactor,
        rs: &[R],
    ) -> (Vec<Vec<f64>>, Vec<f64>) {
        let n = self.k.rows();
        let zs: Vec<Vec<f64>> = rs.iter().map(|r| self.apply(w, r.as_ref())).collect();
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
                let back: Vec<f64> = self
                    .spread
                    .iter()
                    .map(|s| s.iter().map(|&(e, q)| q * red[e]).sum())
                    .collect();
                z.iter()
                    .zip(self.apply(w, &back))
                    .map(|(zj, wb)| zj - wb)
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

    /// M⁻¹ r = W r − W Qᵀ F⁻¹ Q W r with F the factor of [`Self::factor`].
    pub fn solve(&self, w: &Springs, factor: &SparseFactor, r: &[f64]) -> Vec<f64> {
        let (mut out, _) = self.solve_many(w, factor, &[r]);
        out.pop().unwrap_or_default()
    }
}

/// The element edges of `mesh` between pressure nodes, once each, with 1/h² of their length.
/// A joint's two sides are not linked: each panel's edges join its own node copies.
fn edge_links(mesh: &Mesh) -> Vec<(usize, usize, f64)> {
    let (wx, wy) = (1.0 / (mesh.hx * mesh.hx), 1.0 / (mesh.hy * mesh.hy));
    let mut seen = std::collections::BTreeSet::new();
    let mut links = Vec::new();
    for e in mesh.elements() {
        let n = mesh.element_nodes(e);
        // Counter-clockwise from the lower-left corner: edges 0–1 and 3–2 along x.
        for (a, b, w) in [
            (n[0], n[1], wx),
            (n[3], n[2], wx),
            (n[0], n[3], wy),
            (n[1], n[2], wy),
        ] {
            let key = (a.min(b), a.max(b));
            if a != b && seen.insert(key) {
                links.push((key.0, key.1, w));
            }
        }
    }
    links
}

/// `k` with explicit zeros added at the entries `extra` it does not hold.
fn with_entries(k: &sprs::CsMat<f64>, extra: &[(usize, usize)]) -> sprs::CsMat<f64> {
    if extra.iter().all(|&(i, j)| position(k, i, j).is_some()) {
        return k.clone();
    }
    let n = k.cols();
    let mut cols: Vec<Vec<(usize, f64)>> = k
        .outer_iterator()
        .map(|col| col.iter().map(|(i, &v)| (i, v)).collect())
        .collect();
    for &(i, j) in extra {
        cols[j].push((i, 0.0));
    }
    let (mut indptr, mut indices, mut data) = (vec![0], Vec::new(), Vec::new());
    for col in &mut cols {
        col.sort_by_key(|e| e.0);
        col.dedup_by(|b, a| {
            // Equal rows: summed (the added entries are zeros).
            a.0 == b.0 && {
                a.1 += b.1;
                true
            }
        });
        for &(i, v) in col.iter() {
            indices.push(i);
            data.push(v);
        }
        indptr.push(indices.len());
    }
    sprs::CsMat::new_csc((k.rows(), n), indptr, indices, data)
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

    /// M (M⁻¹ r) = r with M = W⁻¹ + QᵀK_p,r⁻¹Q formed densely from the plate's own matrix:
    /// checks the Woodbury solve, the spread weights and the spring positions, for both plates,
    /// with springs alone and with a shear layer's links (some of them cut).
    #[test]
    fn woodbury_solve_inverts_the_dense_preconditioner() {
        let ops = ops(8);
        for coarse in [false, true] {
            for shear in [false, true] {
                let sp = SpringPlate::new(&ops, coarse, shear).expect("springs");
                assert_eq!(sp.kind, if coarse { "coarse" } else { "fine" });
                assert_eq!(sp.links.is_empty(), !shear);
                woodbury_check(&ops, &sp);
            }
        }
    }

    /// The links of a plain grid: nx (ny + 1) edges along x and (nx + 1) ny along y, each
    /// once, with 1/h² of its length.
    #[test]
    fn a_grid_has_one_link_per_element_edge() {
        let ops = ops(8);
        let sp = SpringPlate::new(&ops, false, true).expect("springs");
        let m = &ops.mesh;
        assert_eq!(sp.links.len(), m.nx * (m.ny + 1) + (m.nx + 1) * m.ny);
        for l in &sp.links {
            let ((xa, ya), (xb, yb)) = (m.node_xy(l.nodes.0), m.node_xy(l.nodes.1));
            let h = (xa - xb).hypot(ya - yb);
            assert!((l.weight * h * h - 1.0).abs() < 1e-12, "{:?}", l.nodes);
        }
    }

    /// A foundation over `n` nodes for `sp`: positive springs and, on its links, couplings of a
    /// diagonally dominant W (every third link cut), so W is SPD.
    fn test_springs(sp: &SpringPlate, n: usize) -> Springs {
        let mut diag: Vec<f64> = (0..n).map(|j| 1.0 + 0.1 * (j % 7) as f64).collect();
        let off: Vec<f64> = sp
            .links
            .iter()
            .enumerate()
            .map(|(l, link)| {
                if l % 3 == 2 {
                    return 0.0;
                }
                let g = 0.2 + 0.05 * (l % 5) as f64;
                diag[link.nodes.0] += g;
                diag[link.nodes.1] += g;
                -g
            })
            .collect();
        Springs { diag, off }
    }

    /// M (M⁻¹ r) = r for one plate on springs: W⁻¹z + QᵀK⁻¹Qz = r, checked as
    /// z + W QᵀK⁻¹Q z = W r (W sparse, no inverse needed).
    fn woodbury_check(ops: &Operators, sp: &SpringPlate) {
        let n = ops.n_sigma();
        {
            let w = test_springs(sp, n);
            let factor = sp.factor(&w).expect("factor");
            let r: Vec<f64> = (0..n).map(|j| ((j * 37 % 11) as f64) - 5.0).collect();
            let z = sp.solve(&w, &factor, &r);
            let wr = sp.apply(&w, &r);
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
            let scale = wr.iter().map(|v| v.abs()).fold(0.0, f64::max);
            let back: Vec<f64> = (0..n)
                .map(|j| (0..m).map(|e| q[(e, j)] * qz[(e, 0)]).sum())
                .collect();
            let w_back = sp.apply(&w, &back);
            for j in 0..n {
                let lhs = z[j] + w_back[j];
                assert!(
                    (lhs - wr[j]).abs() < 1e-9 * scale,
                    "{} plate, {} links, node {j}: (W M M⁻¹ r) = {lhs} vs W r = {}",
                    sp.kind,
                    sp.links.len(),
                    wr[j]
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
            SpringPlate::new(&plain, true, false).expect("springs"),
            SpringPlate::new(&uncut, true, false).expect("springs"),
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
        let sp = SpringPlate::new(&cut, true, false).expect("springs");
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
        // With a shear layer: each panel's links, none across the cut joints.
        let sp = SpringPlate::new(&cut, true, true).expect("springs");
        let panel = |j: usize| {
            cut.mesh
                .panel_of(cut.mesh.topo.as_ref().map_or(0, |t| t.incident(j)[0].0))
        };
        assert!(sp
            .links
            .iter()
            .all(|l| panel(l.nodes.0) == panel(l.nodes.1)));
        woodbury_check(&cut, &sp);
    }

    /// The coarse plate has a quarter of the elements and the coarse weights of each pressure
    /// node sum to its area (the coarse functions are a partition of unity).
    #[test]
    fn coarse_spread_is_a_partition_of_the_nodal_areas() {
        let ops = ops(16);
        let sp = SpringPlate::new(&ops, true, false).expect("springs");
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
