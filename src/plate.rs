//! The MITC4 Mindlin plate element on a rectangle and the global stiffness assembly.
//!
//! Strain energy (paper eq. 2.2):
//! U = ½ ∫ κᵀ D_b κ dA + ½ κ_s ∫ γᵀγ dA, with curvatures κ = (ψx,x, ψy,y, ψx,y + ψy,x),
//! D_b = D [[1, ν, 0], [ν, 1, 0], [0, 0, (1 − ν)/2]] and transverse shear strains
//! γ = (w,x − ψx, w,y − ψy), κ_s = χ G H.
//!
//! Bending is integrated with 2 × 2 Gauss points. The shear strains are not taken from the
//! displacement interpolation directly (that locks as H → 0) but from the MITC4 assumed field of
//! Bathe and Dvorkin: γxz is sampled at the mid-points of the two edges parallel to x and
//! interpolated linearly in η, γyz at the mid-points of the edges parallel to y and interpolated
//! linearly in ξ. On a rectangle this keeps exactly the three rigid-body modes of a free element
//! and passes the patch test.

use nalgebra::{SMatrix, SVector};

use crate::mesh::{Dof, DofMap, Mesh};
use crate::quadrature::GaussRule;

/// 12 × 12 element matrix (node-major (w, ψx, ψy)).
pub type ElementMatrix = SMatrix<f64, 12, 12>;
/// Element vector of 12 dofs.
pub type ElementVector = SVector<f64, 12>;

/// Local coordinates of the four element nodes, counter-clockwise from (−1, −1).
pub const NODE_XI: [f64; 4] = [-1.0, 1.0, 1.0, -1.0];
/// See [`NODE_XI`].
pub const NODE_ETA: [f64; 4] = [-1.0, -1.0, 1.0, 1.0];

/// Plate section constants in whatever consistent units the caller uses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Section {
    /// Flexural rigidity D = E H³ / (12 (1 − ν²)).
    pub bending: f64,
    /// Shear rigidity κ_s = χ G H.
    pub shear: f64,
    /// Poisson's ratio ν.
    pub poisson: f64,
}

/// Bilinear shape functions N_a(ξ, η).
pub fn shape(xi: f64, eta: f64) -> [f64; 4] {
    let mut n = [0.0; 4];
    for a in 0..4 {
        n[a] = 0.25 * (1.0 + NODE_XI[a] * xi) * (1.0 + NODE_ETA[a] * eta);
    }
    n
}

/// Derivatives (∂N_a/∂ξ, ∂N_a/∂η).
pub fn shape_derivatives(xi: f64, eta: f64) -> [[f64; 2]; 4] {
    let mut d = [[0.0; 2]; 4];
    for a in 0..4 {
        d[a][0] = 0.25 * NODE_XI[a] * (1.0 + NODE_ETA[a] * eta);
        d[a][1] = 0.25 * NODE_ETA[a] * (1.0 + NODE_XI[a] * xi);
    }
    d
}

/// Curvature–displacement matrix at (ξ, η) on an hx × hy rectangle.
pub fn bending_strain(xi: f64, eta: f64, hx: f64, hy: f64) -> SMatrix<f64, 3, 12> {
    let d = shape_derivatives(xi, eta);
    let mut b = SMatrix::<f64, 3, 12>::zeros();
    for a in 0..4 {
        let dx = d[a][0] * 2.0 / hx;
        let dy = d[a][1] * 2.0 / hy;
        b[(0, 3 * a + 1)] = dx;
        b[(1, 3 * a + 2)] = dy;
        b[(2, 3 * a + 1)] = dy;
        b[(2, 3 * a + 2)] = dx;
    }
    b
}

/// MITC4 assumed transverse shear strain–displacement matrix at (ξ, η).
///
/// Tying points: A = (0, −1) and C = (0, 1) for γxz, D = (−1, 0) and B = (1, 0) for γyz. Along
/// an edge w is linear, so its derivative along the edge is exact there, and the rotation is
/// the mean of the two edge nodes.
pub fn shear_strain(xi: f64, eta: f64, hx: f64, hy: f64) -> SMatrix<f64, 2, 12> {
    // γxz on the edge between nodes (p, q) with q to the right of p.
    let gxz = |p: usize, q: usize| {
        let mut r = SVector::<f64, 12>::zeros();
        r[3 * p] = -1.0 / hx;
        r[3 * q] = 1.0 / hx;
        r[3 * p + 1] = -0.5;
        r[3 * q + 1] = -0.5;
        r
    };
    // γyz on the edge between nodes (p, q) with q above p.
    let gyz = |p: usize, q: usize| {
        let mut r = SVector::<f64, 12>::zeros();
        r[3 * p] = -1.0 / hy;
        r[3 * q] = 1.0 / hy;
        r[3 * p + 2] = -0.5;
        r[3 * q + 2] = -0.5;
        r
    };
    let row_xz = gxz(0, 1) * (0.5 * (1.0 - eta)) + gxz(3, 2) * (0.5 * (1.0 + eta));
    let row_yz = gyz(0, 3) * (0.5 * (1.0 - xi)) + gyz(1, 2) * (0.5 * (1.0 + xi));
    let mut b = SMatrix::<f64, 2, 12>::zeros();
    b.set_row(0, &row_xz.transpose());
    b.set_row(1, &row_yz.transpose());
    b
}

/// Bending constitutive matrix D_b.
pub fn bending_constitutive(section: &Section) -> SMatrix<f64, 3, 3> {
    let d = section.bending;
    let nu = section.poisson;
    SMatrix::<f64, 3, 3>::new(
        d,
        d * nu,
        0.0,
        d * nu,
        d,
        0.0,
        0.0,
        0.0,
        d * 0.5 * (1.0 - nu),
    )
}

/// Bending part of the element stiffness (2 × 2 Gauss, exact for the rectangle).
pub fn bending_stiffness(section: &Section, hx: f64, hy: f64) -> ElementMatrix {
    let db = bending_constitutive(section);
    let rule = GaussRule::new(2);
    let det = 0.25 * hx * hy;
    let mut k = ElementMatrix::zeros();
    for (&xi, &wx) in rule.points.iter().zip(&rule.weights) {
        for (&eta, &wy) in rule.points.iter().zip(&rule.weights) {
            let b = bending_strain(xi, eta, hx, hy);
            k += b.transpose() * db * b * (wx * wy * det);
        }
    }
    k
}

/// MITC4 shear part of the element stiffness (2 × 2 Gauss, exact for the assumed strains).
pub fn shear_stiffness(section: &Section, hx: f64, hy: f64) -> ElementMatrix {
    let rule = GaussRule::new(2);
    let det = 0.25 * hx * hy;
    let mut k = ElementMatrix::zeros();
    for (&xi, &wx) in rule.points.iter().zip(&rule.weights) {
        for (&eta, &wy) in rule.points.iter().zip(&rule.weights) {
            let b = shear_strain(xi, eta, hx, hy);
            k += b.transpose() * b * (section.shear * wx * wy * det);
        }
    }
    k
}

/// Full MITC4 element stiffness.
pub fn element_stiffness(section: &Section, hx: f64, hy: f64) -> ElementMatrix {
    bending_stiffness(section, hx, hy) + shear_stiffness(section, hx, hy)
}

/// Global stiffness of the model in CSC form over the free equations of `dofs`. Every element
/// of the uniform grid has the same matrix, so it is computed once. The sparsity pattern of a
/// structured grid is known in advance (a node couples with its 3 × 3 neighbourhood), so the
/// columns are laid out first and the element values added into place, without triplets.
pub fn assemble_stiffness(mesh: &Mesh, dofs: &DofMap, section: &Section) -> sprs::CsMat<f64> {
    let ke = element_stiffness(section, mesh.hx, mesh.hy);
    assemble_structured(mesh, dofs, |_| &ke)
}

/// The structured assembly with element e's matrix `ke_of(e)` (a grid without node copies).
pub(crate) fn assemble_structured<'a>(
    mesh: &Mesh,
    dofs: &DofMap,
    ke_of: impl Fn(usize) -> &'a ElementMatrix,
) -> sprs::CsMat<f64> {
    let n = dofs.n_eq();
    let (nnx, nny) = (mesh.nodes_x(), mesh.nodes_y());
    // Column pattern: equations of the neighbouring nodes, sorted (node-major numbering makes
    // equation order follow node order).
    let mut col_of_eq: Vec<(usize, usize)> = vec![(0, 0); n];
    for node in 0..mesh.n_nodes() {
        for d in [Dof::W, Dof::PsiX, Dof::PsiY] {
            if let Some(e) = dofs.eq(node, d) {
                col_of_eq[e] = (node, d as usize);
            }
        }
    }
    let mut indptr = Vec::with_capacity(n + 1);
    let mut indices = Vec::with_capacity(n * 27);
    indptr.push(0);
    for &(node, _) in &col_of_eq {
        let i = node % nnx;
        let j = node / nnx;
        for jj in j.saturating_sub(1)..=(j + 1).min(nny - 1) {
            for ii in i.saturating_sub(1)..=(i + 1).min(nnx - 1) {
                let m = mesh.node(ii, jj);
                for d in [Dof::W, Dof::PsiX, Dof::PsiY] {
                    if let Some(e) = dofs.eq(m, d) {
                        indices.push(e);
                    }
                }
            }
        }
        indptr.push(indices.len());
    }
    let mut data = vec![0.0; indices.len()];
    for e in mesh.elements() {
        let ke = ke_of(e);
        let eqs = dofs.element_eqs(&mesh.element_nodes(e));
        for (b, eb) in eqs.iter().enumerate() {
            let Some(col) = *eb else { continue };
            let rows = &indices[indptr[col]..indptr[col + 1]];
            for (a, ea) in eqs.iter().enumerate() {
                let Some(row) = *ea else { continue };
                // Element couplings are within a node's 3 × 3 neighbourhood, so always found.
                let found = rows.binary_search(&row);
                debug_assert!(
                    found.is_ok(),
                    "element coupling outside the structured pattern"
                );
                if let Ok(k) = found {
                    data[indptr[col] + k] += ke[(a, b)];
                }
            }
        }
    }
    sprs::CsMat::new_csc((n, n), indptr, indices, data)
}

/// Stress resultants at an element centre, per unit length, from the element's 12 dofs.
///
/// Moments are reported positive when they put the bottom face (the soil side, +z, the side
/// w points to) in tension — the sagging convention of reinforced-concrete design:
/// mx = −D(ψx,x + ν ψy,y), my = −D(ψy,y + ν ψx,x), mxy = −D (1 − ν)/2 (ψx,y + ψy,x).
/// Shear forces are qx = κ_s γxz, qy = κ_s γyz from the MITC4 assumed strains.
pub fn centre_resultants(section: &Section, hx: f64, hy: f64, ue: &ElementVector) -> [f64; 5] {
    let curv = bending_strain(0.0, 0.0, hx, hy) * ue;
    let m = bending_constitutive(section) * curv;
    let g = shear_strain(0.0, 0.0, hx, hy) * ue;
    [
        -m[0],
        -m[1],
        -m[2],
        section.shear * g[0],
        section.shear * g[1],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn section() -> Section {
        Section {
            bending: 1.0,
            shear: 50.0,
            poisson: 0.3,
        }
    }

    #[test]
    fn shape_functions_are_a_partition_of_unity_with_kronecker_property() {
        for &(xi, eta) in &[(0.3, -0.7), (-1.0, 1.0), (0.0, 0.0), (0.9, 0.2)] {
            let s: f64 = shape(xi, eta).iter().sum();
            assert!(
                (s - 1.0).abs() < 1e-14,
                "partition of unity at ({xi}, {eta})"
            );
        }
        for a in 0..4 {
            let n = shape(NODE_XI[a], NODE_ETA[a]);
            for (b, v) in n.iter().enumerate() {
                let expect = if a == b { 1.0 } else { 0.0 };
                assert!((v - expect).abs() < 1e-14, "N_{b} at node {a}");
            }
        }
    }

    #[test]
    fn structured_assembly_equals_triplet_assembly() {
        use crate::mesh::{DofMap, Mesh};
        for (sx, sy) in [(false, false), (true, true), (true, false)] {
            let mesh = Mesh::new(2.0, 1.2, [6, 4], sx, sy);
            let dofs = DofMap::new(&mesh);
            let k = assemble_stiffness(&mesh, &dofs, &section());
            let ke = element_stiffness(&section(), mesh.hx, mesh.hy);
            let mut tri = sprs::TriMat::new((dofs.n_eq(), dofs.n_eq()));
            for e in mesh.elements() {
                let eqs = dofs.element_eqs(&mesh.element_nodes(e));
                for (a, ea) in eqs.iter().enumerate() {
                    for (b, eb) in eqs.iter().enumerate() {
                        if let (Some(r), Some(c)) = (ea, eb) {
                            tri.add_triplet(*r, *c, ke[(a, b)]);
                        }
                    }
                }
            }
            let reference: sprs::CsMat<f64> = tri.to_csc();
            let diff = (&k - &reference)
                .data()
                .iter()
                .fold(0.0_f64, |m, v| m.max(v.abs()));
            assert!(
                diff < 1e-12,
                "structured assembly ({sx}, {sy}) differs by {diff}"
            );
        }
    }

    #[test]
    fn element_stiffness_is_symmetric() {
        let k = element_stiffness(&section(), 0.7, 0.4);
        assert!((k - k.transpose()).abs().max() < 1e-12 * k.abs().max());
    }
}
