//! Elastic half-space (Boussinesq): w_s(x) = c ∫ r(x') / |x − x'| dA', c = (1 − ν_s²)/(π E_s)
//! (paper eq. 2.6). The closed-form pair integrals are in [`super::boussinesq`], the table and
//! the dense scatter shared with the other kernels in [`super::pairs`]; this file is the
//! half-space's entry point.

pub use super::boussinesq::{element_potentials, pair_block, rectangle_potentials, NEAR_FIELD};
pub use super::pairs::{dense_bytes, reflect};

use super::kernel::{Kernel, Radial};
use super::soil::{key, Key, PlateScale, SoilKeys, SoilModel, SoilNames};
use super::{pairs, Compliance};
use crate::error::Result;
use crate::mesh::Mesh;

/// The half-space soil: Γ_h = D (1 − ν_s²)/(π E_s μ L³) alone (in [`crate::model::Groups`]).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct HalfSpace {}

/// The keys of an elastic soil, E_s and ν_s (the half-space's; the elastic layer's with its
/// depth and base).
pub const ELASTIC_KEYS: [Key; 2] = [key("youngs_modulus", "Pa"), key("poissons_ratio", "–")];

/// Γ_h and ν_s of the elastic soil of `keys` (`youngs_modulus` E_s in Pa, `poissons_ratio`).
pub fn elastic_soil(keys: &SoilKeys<'_>, plate: &PlateScale) -> Result<(f64, f64)> {
    let e = keys.positive("youngs_modulus", "soil Young's modulus E_s in Pa", "Pa")?;
    let nu = keys.poisson("poissons_ratio", "soil Poisson's ratio ν_s")?;
    Ok((plate.elastic_gamma(e, nu), nu))
}

/// The mean settlement of a flexible uniform load on an elastic soil, the unit resultant over
/// the plate's area 4μ: ≈ 3 (1 − ν_s²) F / (π E_s √A) = 3 c F/√A (a flexible uniform square
/// load settles 0.95 q B (1 − ν_s²)/E_s on average).
pub fn elastic_settlement(c: f64, mu: f64) -> f64 {
    3.0 * c * 4.0 / (4.0 * mu).sqrt()
}

impl SoilModel for HalfSpace {
    const LOCAL: bool = false;
    const NAMES: SoilNames = SoilNames {
        label: "elastic half-space",
        short: "half-space",
        stem: "halfspace",
    };
    const SI_KEYS: &'static [Key] = &ELASTIC_KEYS;
    const GROUP_KEYS: &'static [Key] = &[];

    fn from_si(keys: &SoilKeys<'_>, plate: &PlateScale) -> Result<(f64, Self)> {
        let (gamma, _) = elastic_soil(keys, plate)?;
        Ok((gamma, HalfSpace {}))
    }

    fn from_groups(_: &SoilKeys<'_>, _: &PlateScale, _: f64) -> Result<Self> {
        Ok(HalfSpace {})
    }

    fn stiffness_length(c: f64) -> f64 {
        (2.0 * std::f64::consts::PI * c).cbrt()
    }

    fn kernel(&self, _: f64, _: f64) -> Option<Kernel> {
        Some(Kernel::new(Boussinesq))
    }

    fn settlement(&self, c: f64, mu: f64) -> f64 {
        elastic_settlement(c, mu)
    }
}

/// The half-space's kernel K(ρ) = 1/ρ (c = (1 − ν_s²)/(π E_s)), with its closed-form near
/// field ([`super::boussinesq::pair_block`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Boussinesq;

impl Radial for Boussinesq {
    fn value(&self, rho: f64) -> f64 {
        1.0 / rho
    }

    fn support(&self) -> Option<f64> {
        None
    }

    fn scale(&self) -> f64 {
        f64::INFINITY
    }

    fn pair_block(&self, di: usize, dj: usize, hx: f64, hy: f64) -> [[f64; 4]; 4] {
        super::boussinesq::pair_block(di, dj, hx, hy)
    }
}

/// Galerkin compliance of the half-space with constant `c` = (1 − ν_s²)/(π E_s) in the
/// caller's units, including mirror images on reduced models.
pub fn compliance(mesh: &Mesh, c: f64) -> Compliance {
    pairs::compliance(mesh, c, &Kernel::new(Boussinesq))
}

/// The dense matrix of [`compliance`].
pub fn dense_matrix(mesh: &Mesh, c: f64) -> faer::Mat<f64> {
    pairs::dense_matrix(mesh, c, &Kernel::new(Boussinesq))
}
