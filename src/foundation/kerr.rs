//! Kerr's three-parameter soil: springs c (upper) in series with a Pasternak soil (lower springs
//! k, shear layer G): compliance 1/c + 1/(k + Gξ²), a local part and the Pasternak kernel.
//! Reissner's continuum-derived foundation is one. In the unit system its groups are Γ_w of the
//! lower springs (in [`crate::model::Groups`]), Γ_g of the shear layer and Γ_c = D/(c μ L⁴) of
//! the upper springs (here).

use super::elastic_layer::oedometric;
use super::kernel::{generic_pair_block, local_weights, Kernel, Radial};
use super::pasternak::{decay_length, springs_and_shear, PasternakKernel};
use super::soil::{key, shear_layer, Key, PlateScale, SoilKeys, SoilModel, SoilNames};
use crate::error::{Error, Result};

/// The Kerr soil's own groups.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Kerr {
    /// The shear parameter Γ_g = G L²/D of its shear layer.
    pub shear: f64,
    /// Γ_c = D/(c μ L⁴) of its upper springs c.
    pub upper: f64,
}

impl SoilModel for Kerr {
    const LOCAL: bool = false;
    const NAMES: SoilNames = SoilNames {
        label: "Kerr soil",
        short: "Kerr",
        stem: "kerr",
    };
    const SI_KEYS: &'static [Key] = &[
        key("modulus", "N/m³"),
        key("shear_modulus", "N/m"),
        key("upper_modulus", "N/m³"),
        key("youngs_modulus", "Pa"),
        key("poissons_ratio", "–"),
        key("depth", "m"),
    ];
    const GROUP_KEYS: &'static [Key] = &[
        key("shear", "Γ_g = G L²/D"),
        key("upper", "Γ_c = D/(c μ L⁴)"),
    ];

    /// Its three constants (`modulus` k and `upper_modulus` c in N/m³, `shear_modulus` G in
    /// N/m) or Reissner's layer of `youngs_modulus` E_s, `poissons_ratio` ν_s and `depth` H on
    /// a rigid base, which is the Kerr soil c₁ = E_oed/H, c₂ = G_s H/3: k = 4c₁/3, c = 4c₁,
    /// G = 4c₂/3 (so that a long load settles p H/E_oed, as the layer does).
    fn from_si(keys: &SoilKeys<'_>, plate: &PlateScale) -> Result<(f64, Self)> {
        let (k, g_s, c) = if keys.has("youngs_modulus") || keys.has("depth") {
            if keys.has("modulus") || keys.has("shear_modulus") || keys.has("upper_modulus") {
                return Err(Error::invalid(
                    keys.field("modulus"),
                    "a Kerr soil takes either its three constants (modulus, shear_modulus, upper_modulus) or Reissner's layer (youngs_modulus, poissons_ratio, depth), not both",
                ));
            }
            let e = keys.positive(
                "youngs_modulus",
                "the layer's Young's modulus E_s in Pa",
                "Pa",
            )?;
            let nu = keys.poisson("poissons_ratio", "the layer's Poisson's ratio ν_s")?;
            let h = keys.positive("depth", "the depth H of Reissner's layer, m", "m")?;
            let c1 = oedometric(e, nu) / h;
            let c2 = e / (2.0 * (1.0 + nu)) * h / 3.0;
            (4.0 * c1 / 3.0, 4.0 * c2 / 3.0, 4.0 * c1)
        } else {
            (
                keys.positive("modulus", "the Kerr soil's lower springs k in N/m³", "N/m³")?,
                keys.positive(
                    "shear_modulus",
                    "the Kerr soil's shear layer G in N/m",
                    "N/m",
                )?,
                keys.positive(
                    "upper_modulus",
                    "the Kerr soil's upper springs c in N/m³ (c → ∞ is the Pasternak soil)",
                    "N/m³",
                )?,
            )
        };
        let (gamma, shear) = springs_and_shear(keys, plate, k, g_s)?;
        let upper = plate.spring_gamma(c);
        Ok((gamma, Kerr { shear, upper }))
    }

    fn from_groups(keys: &SoilKeys<'_>, plate: &PlateScale, gamma: f64) -> Result<Self> {
        let shear = keys.positive(
            "shear",
            "the Kerr soil's shear parameter Γ_g = G L²/D",
            "Γ_g = G L²/D",
        )?;
        let shear = shear_layer(&keys.field("shear"), shear, gamma, plate.mu)?;
        let upper = keys.positive(
            "upper",
            "the Kerr soil's upper springs Γ_c = D/(c μ L⁴)",
            "Γ_c = D/(c μ L⁴)",
        )?;
        Ok(Kerr { shear, upper })
    }

    fn stiffness_length(c: f64) -> f64 {
        c.powf(0.25)
    }

    fn kernel(&self, gamma: f64, mu: f64) -> Option<Kernel> {
        Some(Kernel::new(KerrKernel {
            lambda: decay_length(self.shear, gamma, mu),
            // The upper springs' compliance over the lower ones', k/c = Γ_c/Γ_w.
            local: self.upper / gamma,
        }))
    }

    /// Both spring layers in series (Γ_c beside Γ_w).
    fn settlement(&self, c: f64, mu: f64) -> f64 {
        4.0 * (c + mu * self.upper) / (4.0 * mu)
    }

    fn describe(&self, gamma: f64, mu: f64) -> String {
        format!(
            ", Γ_g = {:.4e}, λ/L = {:.4}, Γ_c = {:.4e}",
            self.shear,
            decay_length(self.shear, gamma, mu),
            self.upper
        )
    }

    fn decay_length(&self, gamma: f64, mu: f64) -> Option<f64> {
        Some(decay_length(self.shear, gamma, mu))
    }
}

/// Kerr's kernel: the Pasternak kernel of the lower springs k and shear layer G (λ = √(G/k),
/// c = 1/k) plus the upper springs' local part (k/c_u) δ(ρ): T = (1/k)·(Pasternak pairs +
/// (k/c_u) ∫ N_a N_b), the local part only in each element's pair with itself (the consistent
/// mass of the bilinear pressure).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KerrKernel {
    /// λ in the caller's length unit.
    pub lambda: f64,
    /// k/c_u.
    pub local: f64,
}

impl Radial for KerrKernel {
    fn value(&self, rho: f64) -> f64 {
        PasternakKernel {
            lambda: self.lambda,
        }
        .value(rho)
    }

    fn support(&self) -> Option<f64> {
        PasternakKernel {
            lambda: self.lambda,
        }
        .support()
    }

    fn scale(&self) -> f64 {
        self.lambda
    }

    fn pair_block(&self, di: usize, dj: usize, hx: f64, hy: f64) -> [[f64; 4]; 4] {
        let pasternak = PasternakKernel {
            lambda: self.lambda,
        };
        let mut block = generic_pair_block(&pasternak, di, dj, hx, hy);
        if di == 0 && dj == 0 {
            for (row, weights) in block.iter_mut().zip(local_weights()) {
                for (v, weight) in row.iter_mut().zip(weights) {
                    *v += self.local * weight * hx * hy / 36.0;
                }
            }
        }
        block
    }
}
