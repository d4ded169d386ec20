//! Winkler subgrade (paper eq. 2.8): settlement = pressure / K, point by point.
//!
//! With the lumped coupling B = diag(∫ f_i) the discrete gap Tσ − Bᵀu vanishes node by node
//! when σ_i = K w_i: the foundation is a bed of independent springs of stiffness K ∫ f_i, and
//! the bonded and penalised problems keep the sparsity of the plate stiffness.

use super::{nodal_areas, Compliance};
use crate::mesh::Mesh;

/// T = (1/K) diag(∫ f_i) for a subgrade of modulus `k` (force / length³ in the caller's units).
pub fn compliance(mesh: &Mesh, k: f64) -> Compliance {
    Compliance::Diagonal(nodal_areas(mesh).into_iter().map(|a| a / k).collect())
}
