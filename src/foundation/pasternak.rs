//! The two-parameter (Pasternak) soil k u − G_p ∇²u = p on the whole plane: springs k coupled
//! by a shear layer G_p. Its surface kernel is K₀(ρ/λ)/(2π G_p), λ = √(G_p/k): the soil outside
//! the plate deflects too, with no extra unknowns. In the unit system its groups are Γ_w of the
//! springs (in [`crate::model::Groups`]) and the shear parameter Γ_g = G_p L²/D (here).

use super::kernel::{bessel_k0, Kernel, Radial};
use super::soil::{key, shear_layer, Key, PlateScale, SoilKeys, SoilModel, SoilNames};
use crate::error::Result;

/// Beyond this many decay lengths a Pasternak kernel is below e⁻⁴⁰ ≈ 4e−18 of its value at one
/// decay length: pairs farther apart are exactly zero in double precision for any use.
pub const PASTERNAK_CUTOFF: f64 = 40.0;

/// The Pasternak soil's own group.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Pasternak {
    /// The shear parameter Γ_g = G_p L²/D.
    pub shear: f64,
}

/// Γ_w of springs `k` (N/m³) and the checked Γ_g = G L²/D of a shear layer `g` (N/m) under
/// `plate`: the SI groups of a Pasternak soil, and of a Kerr soil's lower part.
pub fn springs_and_shear(
    keys: &SoilKeys<'_>,
    plate: &PlateScale,
    k: f64,
    g: f64,
) -> Result<(f64, f64)> {
    let gamma = plate.spring_gamma(k);
    let l = plate.half_length;
    let shear = shear_layer(
        &keys.field("shear_modulus"),
        g * l * l / plate.rigidity,
        gamma,
        plate.mu,
    )?;
    Ok((gamma, shear))
}

/// The decay length λ/L = √(G_p/k)/L = √(Γ_g μ Γ_w) of a shear layer Γ_g on springs Γ_w.
pub fn decay_length(shear: f64, gamma: f64, mu: f64) -> f64 {
    (shear * mu * gamma).sqrt()
}

impl SoilModel for Pasternak {
    const LOCAL: bool = false;
    const NAMES: SoilNames = SoilNames {
        label: "Pasternak soil",
        short: "Pasternak",
        stem: "pasternak",
    };
    const SI_KEYS: &'static [Key] = &[key("modulus", "N/m³"), key("shear_modulus", "N/m")];
    const GROUP_KEYS: &'static [Key] = &[key("shear", "Γ_g = G_p L²/D")];

    /// Springs k (N/m³) coupled by a shear layer G_p (N/m): Γ_w of the springs and
    /// Γ_g = G_p L² / D.
    fn from_si(keys: &SoilKeys<'_>, plate: &PlateScale) -> Result<(f64, Self)> {
        let k = keys.positive(
            "modulus",
            "the Pasternak springs' modulus k in N/m³",
            "N/m³",
        )?;
        let g_p = keys.positive(
            "shear_modulus",
            "the Pasternak shear layer's modulus G_p in N/m (for G_p = 0 use model = \"winkler\")",
            "N/m",
        )?;
        let (gamma, shear) = springs_and_shear(keys, plate, k, g_p)?;
        Ok((gamma, Pasternak { shear }))
    }

    fn from_groups(keys: &SoilKeys<'_>, plate: &PlateScale, gamma: f64) -> Result<Self> {
        let shear = keys.positive(
            "shear",
            "the Pasternak shear parameter Γ_g = G_p L²/D (for Γ_g = 0 use foundation = \"winkler\")",
            "Γ_g = G_p L²/D",
        )?;
        let shear = shear_layer(&keys.field("shear"), shear, gamma, plate.mu)?;
        Ok(Pasternak { shear })
    }

    fn stiffness_length(c: f64) -> f64 {
        c.powf(0.25)
    }

    fn kernel(&self, gamma: f64, mu: f64) -> Option<Kernel> {
        Some(Kernel::new(PasternakKernel {
            lambda: decay_length(self.shear, gamma, mu),
        }))
    }

    /// Its springs' settlement q/k: an upper bound (the shear layer spreads the load).
    fn settlement(&self, c: f64, mu: f64) -> f64 {
        4.0 * c / (4.0 * mu)
    }

    fn describe(&self, gamma: f64, mu: f64) -> String {
        format!(
            ", Γ_g = {:.4e}, λ/L = {:.4}",
            self.shear,
            decay_length(self.shear, gamma, mu)
        )
    }

    fn decay_length(&self, gamma: f64, mu: f64) -> Option<f64> {
        Some(decay_length(self.shear, gamma, mu))
    }
}

/// The Pasternak kernel K(ρ) = K₀(ρ/λ)/(2πλ²), λ = √(G_p/k), c = 1/k. It has unit integral
/// over the plane, so as λ → 0 it tends to the Winkler law u = p/k.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PasternakKernel {
    /// λ in the caller's length unit.
    pub lambda: f64,
}

impl Radial for PasternakKernel {
    fn value(&self, rho: f64) -> f64 {
        let lambda = self.lambda;
        bessel_k0(rho / lambda) / (2.0 * std::f64::consts::PI * lambda * lambda)
    }

    fn support(&self) -> Option<f64> {
        Some(PASTERNAK_CUTOFF * self.lambda)
    }

    fn scale(&self) -> f64 {
        self.lambda
    }
}
