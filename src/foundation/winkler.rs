//! Winkler subgrade (paper eq. 2.8): settlement = pressure / K, point by point.
//!
//! With the lumped coupling B = diag(∫ f_i) the discrete gap Tσ − Bᵀu vanishes node by node
//! when σ_i = K w_i: the foundation is a bed of independent springs of stiffness K ∫ f_i, and
//! the bonded and penalised problems keep the sparsity of the plate stiffness. On a jointed plate
//! each node copy is one spring over its own side's tributary area.

use super::kernel::Kernel;
use super::soil::{key, Key, PlateScale, SoilKeys, SoilModel, SoilNames};
use super::{nodal_areas, Compliance};
use crate::error::Result;
use crate::mesh::Mesh;

/// The Winkler soil: Γ_w = D/(K μ L⁴) alone (in [`crate::model::Groups`]).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Winkler {}

impl SoilModel for Winkler {
    const LOCAL: bool = true;
    const NAMES: SoilNames = SoilNames {
        label: "Winkler subgrade",
        short: "Winkler",
        stem: "winkler",
    };
    const SI_KEYS: &'static [Key] = &[key("modulus", "N/m³")];
    const GROUP_KEYS: &'static [Key] = &[];

    /// Springs of modulus k (N/m³): Γ_w = D / (k μ L⁴).
    fn from_si(keys: &SoilKeys<'_>, plate: &PlateScale) -> Result<(f64, Self)> {
        let k = keys.positive("modulus", "Winkler subgrade modulus K in N/m³", "N/m³")?;
        Ok((plate.spring_gamma(k), Winkler {}))
    }

    fn from_groups(_: &SoilKeys<'_>, _: &PlateScale, _: f64) -> Result<Self> {
        Ok(Winkler {})
    }

    fn stiffness_length(c: f64) -> f64 {
        c.powf(0.25)
    }

    fn kernel(&self, _: f64, _: f64) -> Option<Kernel> {
        None
    }

    /// q/K: the unit resultant over the plate's area.
    fn settlement(&self, c: f64, mu: f64) -> f64 {
        4.0 * c / (4.0 * mu)
    }

    /// Sparse penalty up to 512 per side; the dense QP is refused beyond its limit.
    fn stability_meshes() -> Vec<f64> {
        vec![8.0, 16.0, 32.0, 64.0, 128.0, 256.0, 512.0]
    }
}

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
