//! The stiffness of a plate system: panels with their own sections, joined along joint lines by
//! joint elements and dowel springs.
//!
//! **Joint element.** Along an element edge of length h on a joint line, MITC4's w and rotations
//! are linear, so the jump w⁺ − w⁻ is linear too, and the spring energy ½∫c (w⁺ − w⁻)² ds is,
//! on (w_a₁, w_a₂, w_b₁, w_b₂) (a the − side, b the + side, each pair in order along the edge),
//!
//! K_c = c [M −M; −M M],   M = h/6 [2 1; 1 2]
//!
//! (the consistent mass of a linear segment). A tied joint adds the same matrix with c_r on the
//! rotation normal to the joint (ψx for a line x = const, ψy for y = const); no term holds the
//! tangential rotation (tie bars do not carry twist). A dowel at t ∈ [0, 1] along its edge is a
//! point spring on the interpolated jump, n = (1 − t, t): K_d = k_d [n nᵀ −n nᵀ; −n nᵀ n nᵀ],
//! its force F = k_d nᵀ(w_a − w_b) (positive when the − side pushes the + side down).

use crate::layout::{Axis, JointKind};
use crate::mesh::{Dof, DofMap, Mesh, Topology};
use crate::plate::{assemble_structured, element_stiffness, ElementMatrix, Section};

/// The section of every whole-plate panel of a mesh's layout (the reference section scaled by
/// the panel's bending and shear ratios; one entry, the reference, without a layout), indexed
/// as [`Mesh::panel_of`].
pub fn panel_sections(mesh: &Mesh, reference: &Section) -> Vec<Section> {
    match &mesh.topo {
        None => vec![*reference],
        Some(t) => t
            .layout
            .sections()
            .iter()
            .map(|p| Section {
                bending: reference.bending * p.bending,
                shear: reference.shear * p.shear,
                poisson: reference.poisson,
            })
            .collect(),
    }
}

/// The joint element of a shear spring c per unit length (or a rotational spring c_r) on an
/// edge of length `h`, on (a₁, a₂, b₁, b₂).
pub fn joint_element(c: f64, h: f64) -> [[f64; 4]; 4] {
    let m = [[2.0, 1.0], [1.0, 2.0]];
    let mut k = [[0.0; 4]; 4];
    for p in 0..4 {
        for q in 0..4 {
            let sign = if (p < 2) == (q < 2) { 1.0 } else { -1.0 };
            k[p][q] = sign * c * h / 6.0 * m[p % 2][q % 2];
        }
    }
    k
}

/// The point spring k_d of a dowel at t ∈ [0, 1] along its edge, on (a₁, a₂, b₁, b₂).
pub fn dowel_element(k_d: f64, t: f64) -> [[f64; 4]; 4] {
    let n = [1.0 - t, t];
    let mut k = [[0.0; 4]; 4];
    for p in 0..4 {
        for q in 0..4 {
            let sign = if (p < 2) == (q < 2) { 1.0 } else { -1.0 };
            k[p][q] = sign * k_d * n[p % 2] * n[q % 2];
        }
    }
    k
}

/// One spring matrix of the system: a 4 × 4 block on (a₁, a₂, b₁, b₂) and the dof it acts on.
pub struct JointBlock {
    /// The four node copies.
    pub nodes: [usize; 4],
    /// The dof: w, or the normal rotation of a tied joint.
    pub dof: Dof,
    /// The matrix.
    pub k: [[f64; 4]; 4],
}

/// Every spring block of a topology: per segment of an aggregate or tied joint its shear (and
/// rotational) element, per dowel its point spring. `unit` puts 1 for every constant (the
/// joints' pattern of zero energy, which does not depend on the constants' values).
pub fn joint_blocks(topo: &Topology, unit: bool) -> Vec<JointBlock> {
    let value = |v: f64| if unit { 1.0 } else { v };
    let mut out = Vec::new();
    for seg in &topo.segments {
        let nodes = [seg.a[0], seg.a[1], seg.b[0], seg.b[1]];
        let normal = match seg.axis {
            Axis::X => Dof::PsiX,
            Axis::Y => Dof::PsiY,
        };
        match topo.layout.joints[seg.joint].kind {
            JointKind::Aggregate { c } => out.push(JointBlock {
                nodes,
                dof: Dof::W,
                k: joint_element(value(c), seg.length),
            }),
            JointKind::Tied { c, c_r } => {
                out.push(JointBlock {
                    nodes,
                    dof: Dof::W,
                    k: joint_element(value(c), seg.length),
                });
                out.push(JointBlock {
                    nodes,
                    dof: normal,
                    k: joint_element(value(c_r), seg.length),
                });
            }
            _ => {}
        }
    }
    for d in &topo.dowels {
        let seg = &topo.segments[d.segment];
        out.push(JointBlock {
            nodes: [seg.a[0], seg.a[1], seg.b[0], seg.b[1]],
            dof: Dof::W,
            k: dowel_element(value(d.k), d.t),
        });
    }
    out
}

/// Stiffness of the plate system: the MITC4 elements of every panel with its own section
/// (`sections` as [`panel_sections`]), and on a jointed mesh the joint elements of its
/// segments and dowels. On a mesh no joint cuts this is the structured assembly of
/// [`crate::plate::assemble_stiffness`] (bitwise equal to it when every panel has the
/// reference section).
pub fn assemble_system(mesh: &Mesh, dofs: &DofMap, sections: &[Section]) -> sprs::CsMat<f64> {
    let kes: Vec<ElementMatrix> = sections
        .iter()
        .map(|s| element_stiffness(s, mesh.hx, mesh.hy))
        .collect();
    let last = kes.len().saturating_sub(1);
    let ke_of = |e: usize| &kes[mesh.panel_of(e).min(last)];
    match &mesh.topo {
        Some(t) if t.cuts() || t.is_shaped() => assemble_jointed(mesh, dofs, t, ke_of),
        _ => assemble_structured(mesh, dofs, ke_of),
    }
}

/// The assembly of a jointed mesh: the pattern of each node copy is the copies of its elements
/// and its partners through the springs, the values added into place.
fn assemble_jointed<'a>(
    mesh: &Mesh,
    dofs: &DofMap,
    topo: &Topology,
    ke_of: impl Fn(usize) -> &'a ElementMatrix,
) -> sprs::CsMat<f64> {
    let blocks = joint_blocks(topo, false);
    let n_nodes = mesh.n_nodes();
    let mut near: Vec<Vec<usize>> = vec![Vec::new(); n_nodes];
    for e in mesh.elements() {
        let c = mesh.element_nodes(e);
        for &p in &c {
            near[p].extend_from_slice(&c);
        }
    }
    for b in &blocks {
        for &p in &b.nodes {
            near[p].extend_from_slice(&b.nodes);
        }
    }
    for v in &mut near {
        v.sort_unstable();
        v.dedup();
    }
    let n = dofs.n_eq();
    let mut node_of_eq = vec![0; n];
    for node in 0..n_nodes {
        for d in [Dof::W, Dof::PsiX, Dof::PsiY] {
            if let Some(e) = dofs.eq(node, d) {
                node_of_eq[e] = node;
            }
        }
    }
    // Node-major numbering: equations follow node order, so rows come out sorted.
    let mut indptr = Vec::with_capacity(n + 1);
    let mut indices = Vec::new();
    indptr.push(0);
    for &node in &node_of_eq {
        for &m in &near[node] {
            for d in [Dof::W, Dof::PsiX, Dof::PsiY] {
                if let Some(e) = dofs.eq(m, d) {
                    indices.push(e);
                }
            }
        }
        indptr.push(indices.len());
    }
    let mut data = vec![0.0; indices.len()];
    let mut add = |row: usize, col: usize, v: f64| {
        let rows = &indices[indptr[col]..indptr[col + 1]];
        // Every coupling is in the pattern by construction.
        if let Ok(k) = rows.binary_search(&row) {
            data[indptr[col] + k] += v;
        }
    };
    for e in mesh.elements() {
        let ke = ke_of(e);
        let eqs = dofs.element_eqs(&mesh.element_nodes(e));
        for (b, eb) in eqs.iter().enumerate() {
            let Some(col) = *eb else { continue };
            for (a, ea) in eqs.iter().enumerate() {
                if let Some(row) = *ea {
                    add(row, col, ke[(a, b)]);
                }
            }
        }
    }
    for blk in &blocks {
        let eqs = blk.nodes.map(|p| dofs.eq(p, blk.dof));
        for (q, eq) in eqs.iter().enumerate() {
            let Some(col) = *eq else { continue };
            for (p, ep) in eqs.iter().enumerate() {
                if let Some(row) = *ep {
                    add(row, col, blk.k[p][q]);
                }
            }
        }
    }
    sprs::CsMat::new_csc((n, n), indptr, indices, data)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The joint element is the energy ½∫c (jump)² ds of a linear jump, integrated here with
    /// a 3-point Gauss rule (exact for the quadratic integrand), for random end values; the
    /// dowel element is the point spring on the interpolated jump.
    #[test]
    fn joint_and_dowel_elements_are_their_energies() {
        let (c, h) = (3.7, 0.45);
        let k = joint_element(c, h);
        let gauss = [
            (-(0.6f64).sqrt(), 5.0 / 9.0),
            (0.0, 8.0 / 9.0),
            ((0.6f64).sqrt(), 5.0 / 9.0),
        ];
        for v in [
            [0.3, -1.2, 0.7, 2.1],
            [1.0, 1.0, 1.0, 1.0],
            [0.0, 1.0, 0.5, -0.25],
        ] {
            let quad: f64 = gauss
                .iter()
                .map(|&(x, w)| {
                    let s = 0.5 * (1.0 + x);
                    let jump = (1.0 - s) * (v[2] - v[0]) + s * (v[3] - v[1]);
                    0.5 * w * 0.5 * h * c * jump * jump
                })
                .sum();
            let mut quadratic = 0.0;
            for p in 0..4 {
                for q in 0..4 {
                    quadratic += 0.5 * v[p] * k[p][q] * v[q];
                }
            }
            // Two sums of a handful of terms of O(1): round-off.
            assert!((quad - quadratic).abs() < 1e-14, "{quad} vs {quadratic}");
            let (kd, t) = (2.5, 0.3);
            let d = dowel_element(kd, t);
            let jump = (1.0 - t) * (v[2] - v[0]) + t * (v[3] - v[1]);
            let mut e = 0.0;
            for p in 0..4 {
                for q in 0..4 {
                    e += 0.5 * v[p] * d[p][q] * v[q];
                }
            }
            assert!((e - 0.5 * kd * jump * jump).abs() < 1e-14);
        }
    }
}
