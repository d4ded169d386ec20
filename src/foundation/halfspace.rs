//! Elastic half-space (Boussinesq): w_s(x) = c ∫ r(x') / |x − x'| dA', c = (1 − ν_s²)/(π E_s)
//! (paper eq. 2.6). The closed-form pair integrals are in [`super::boussinesq`], the table and
//! the dense scatter shared with the other kernels in [`super::pairs`]; this file is the
//! half-space's entry point.

pub use super::boussinesq::{element_potentials, pair_block, rectangle_potentials, NEAR_FIELD};
pub use super::pairs::{dense_bytes, reflect};

use super::kernel::Kernel;
use super::{pairs, Compliance};
use crate::mesh::Mesh;

/// Galerkin compliance of the half-space with constant `c` = (1 − ν_s²)/(π E_s) in the
/// caller's units, including mirror images on reduced models.
pub fn compliance(mesh: &Mesh, c: f64) -> Compliance {
    pairs::compliance(mesh, c, &Kernel::Boussinesq)
}

/// The dense matrix of [`compliance`].
pub fn dense_matrix(mesh: &Mesh, c: f64) -> faer::Mat<f64> {
    pairs::dense_matrix(mesh, c, &Kernel::Boussinesq)
}
