//! Winkler subgrade (paper eq. 2.8): settlement = pressure / K, point by point.
//!
//! With the lumped coupling B = diag(∫ f_i) the discrete gap Tσ − Bᵀu vanishes node by node
//! when σ_i = K w_i: the foundation is a bed of independent springs of stiffness K ∫ f_i, and
//! the bonded and penalised problems keep the sparsity of the plate stiffness. On a jointed plate
//! each node copy is one spring over its own side's tributary area.

use super::{nodal_areas, Compliance};
use crate::mesh::Mesh;

/// T = (1/K) diag(∫ f_i) for a subgrade of modulus `k` (force / length³ in the caller's units).
pub fn compliance(mesh: &Mesh, k: f64) -> Compliance {
    Compliance::Diagonal(nodal_areas(mesh).into_iter().map(|a| a / k).collect())
}

/// A patch of Winkler subgrade with another modulus.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Zone {
    /// [x0, x1] / L.
    pub x: [f64; 2],
    /// [y0, y1] / L.
    pub y: [f64; 2],
    /// Reference modulus over the zone's modulus: the factor on the compliance inside it.
    pub compliance_ratio: f64,
}

/// T with zones of another modulus: T_ii = (1/K) ∫ f_i r(x) dA, where r is the reference
/// modulus over the local one (1 outside the zones). The integral is exact for rectangular
/// zones, so a zone boundary between nodes shares a node's spring between the two moduli by
/// area instead of snapping to the nearest node. Zones must not overlap.
pub fn zoned_compliance(mesh: &Mesh, k: f64, zones: &[Zone]) -> Compliance {
    let mut t: Vec<f64> = nodal_areas(mesh);
    for z in zones {
        for (node, a) in crate::integrals::patch_integrals(mesh, z.x, z.y) {
            t[node] += (z.compliance_ratio - 1.0) * a;
        }
    }
    Compliance::Diagonal(t.into_iter().map(|a| a / k).collect())
}
