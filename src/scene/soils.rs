//! The foundations of a scene, one function per soil: its groups from `[foundation]` in SI
//! units (`*_si`) and from `[dimensionless]`, each refusing the keys that belong to another
//! soil. A new soil is its two functions here and an arm in [`si`] and [`dimensionless`].

use super::numbers::{finite_positive, poisson};
use super::spec::{DimensionlessSpec, FoundationSpec};
use crate::error::{Error, Result};
use crate::foundation::layer::Base;
use crate::foundation::FoundationKind;
use crate::model::Groups;

/// The plate's groups Δ, μ and ν_p, which a soil completes.
#[derive(Debug, Clone, Copy)]
pub(super) struct PlateGroups {
    /// Δ.
    pub(super) delta: f64,
    /// μ.
    pub(super) mu: f64,
    /// ν_p.
    pub(super) nu: f64,
}

impl PlateGroups {
    /// The groups of this plate on `foundation` with Γ = `gamma`, none of the other soils'
    /// groups given.
    fn on(self, foundation: FoundationKind, gamma: f64) -> Groups {
        Groups {
            foundation,
            gamma,
            delta: self.delta,
            mu: self.mu,
            nu: self.nu,
            shear: None,
            depth: None,
            soil_nu: None,
            base: None,
            upper: None,
        }
    }
}

/// The groups of the soil of `[foundation]` (SI units) under a plate of half-length `l` (m)
/// and rigidity `d` (N·m).
pub(super) fn si(f: &FoundationSpec, plate: PlateGroups, l: f64, d: f64) -> Result<Groups> {
    if f.upper_modulus.is_some() && f.model != FoundationKind::Kerr {
        return Err(Error::invalid(
            "foundation.upper_modulus",
            format!(
                "belongs to model = \"kerr\"; a {} foundation has no upper springs (leave it out)",
                f.model.name()
            ),
        ));
    }
    match f.model {
        FoundationKind::Winkler => winkler_si(f, plate, l, d),
        FoundationKind::HalfSpace => half_space_si(f, plate, l, d),
        FoundationKind::Pasternak => pasternak_si(f, plate, l, d),
        FoundationKind::ElasticLayer => elastic_layer_si(f, plate, l, d),
        FoundationKind::Kerr => kerr_si(f, plate, l, d),
    }
}

/// The groups of the soil of `[dimensionless]`, its Γ = `gamma` already checked.
pub(super) fn dimensionless(
    g: &DimensionlessSpec,
    plate: PlateGroups,
    gamma: f64,
) -> Result<Groups> {
    if g.upper.is_some() && g.foundation != FoundationKind::Kerr {
        return Err(Error::invalid(
            "dimensionless.upper",
            format!("belongs to foundation = \"kerr\"; a {} foundation has no upper springs (leave it out)", g.foundation.name()),
        ));
    }
    match g.foundation {
        FoundationKind::Winkler => winkler_dimensionless(g, plate, gamma),
        FoundationKind::HalfSpace => half_space_dimensionless(g, plate, gamma),
        FoundationKind::Pasternak => pasternak_dimensionless(g, plate, gamma),
        FoundationKind::ElasticLayer => elastic_layer_dimensionless(g, plate, gamma),
        FoundationKind::Kerr => kerr_dimensionless(g, plate, gamma),
    }
}

/// Winkler springs of modulus k (N/m³): Γ_w = D / (k μ L⁴).
fn winkler_si(f: &FoundationSpec, p: PlateGroups, l: f64, d: f64) -> Result<Groups> {
    no_shear_layer_si(f)?;
    no_rigid_base_si(f)?;
    if f.youngs_modulus.is_some() || f.poissons_ratio.is_some() {
        return Err(Error::invalid(
            "foundation.youngs_modulus",
            "belongs to model = \"half-space\"; a Winkler foundation takes only `modulus` (N/m³)",
        ));
    }
    let k = positive_given(
        "foundation.modulus",
        f.modulus,
        "Winkler subgrade modulus K in N/m³",
        "N/m³",
    )?;
    Ok(p.on(FoundationKind::Winkler, d / (k * p.mu * l.powi(4))))
}

/// The elastic half-space of E_s (Pa) and ν_s: Γ_h = D (1 − ν_s²) / (π E_s μ L³).
fn half_space_si(f: &FoundationSpec, p: PlateGroups, l: f64, d: f64) -> Result<Groups> {
    no_shear_layer_si(f)?;
    no_rigid_base_si(f)?;
    let (gamma, _) = elastic_soil_si(f, p, l, d)?;
    Ok(p.on(FoundationKind::HalfSpace, gamma))
}

/// Pasternak springs k (N/m³) coupled by a shear layer G_p (N/m): Γ_w of the springs and
/// Γ_g = G_p L² / D.
fn pasternak_si(f: &FoundationSpec, p: PlateGroups, l: f64, d: f64) -> Result<Groups> {
    no_rigid_base_si(f)?;
    if f.youngs_modulus.is_some() || f.poissons_ratio.is_some() {
        return Err(Error::invalid(
            "foundation.youngs_modulus",
            "belongs to model = \"half-space\"; a Pasternak foundation takes `modulus` (N/m³) and `shear_modulus` (N/m)",
        ));
    }
    let k = positive_given(
        "foundation.modulus",
        f.modulus,
        "the Pasternak springs' modulus k in N/m³",
        "N/m³",
    )?;
    let g_p = positive_given(
        "foundation.shear_modulus",
        f.shear_modulus,
        "the Pasternak shear layer's modulus G_p in N/m (for G_p = 0 use model = \"winkler\")",
        "N/m",
    )?;
    let shear = pasternak_length(
        "foundation.shear_modulus",
        g_p * l * l / d,
        d / (k * p.mu * l.powi(4)),
        p.mu,
    )?;
    Ok(Groups {
        shear: Some(shear),
        ..p.on(FoundationKind::Pasternak, d / (k * p.mu * l.powi(4)))
    })
}

/// Kerr's soil: upper springs c (`upper_modulus`, N/m³) in series with a Pasternak soil of
/// springs k (`modulus`) and shear layer G (`shear_modulus`, N/m): Γ_w of k, Γ_g of G and
/// Γ_c = D/(c μ L⁴). Or, with `reissner = true`, Reissner's layer of `youngs_modulus` E_s,
/// `poissons_ratio` ν_s and `depth` H on a rigid base, which is the Kerr soil c₁ = E_oed/H,
/// c₂ = G_s H/3: k = 4c₁/3, c = 4c₁, G = 4c₂/3 (E_oed = E(1 − ν)/((1 + ν)(1 − 2ν)), so that a
/// long load settles p H/E_oed, as the layer does).
fn kerr_si(f: &FoundationSpec, p: PlateGroups, l: f64, d: f64) -> Result<Groups> {
    let (k, g_s, c) = if f.youngs_modulus.is_some() || f.depth.is_some() {
        if f.modulus.is_some() || f.shear_modulus.is_some() || f.upper_modulus.is_some() {
            return Err(Error::invalid(
                "foundation.modulus",
                "a Kerr soil takes either its three constants (modulus, shear_modulus, upper_modulus) or Reissner's layer (youngs_modulus, poissons_ratio, depth), not both",
            ));
        }
        if f.base.is_some() {
            return Err(Error::invalid(
                "foundation.base",
                "belongs to model = \"elastic-layer\"; Reissner's layer on a Kerr soil has its base fixed by its assumptions",
            ));
        }
        let (e, nu) = reissner_soil(f)?;
        let h = positive_given(
            "foundation.depth",
            f.depth,
            "the depth H of Reissner's layer, m",
            "m",
        )?;
        let e_oed = e * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
        let c1 = e_oed / h;
        let c2 = e / (2.0 * (1.0 + nu)) * h / 3.0;
        (4.0 * c1 / 3.0, 4.0 * c2 / 3.0, 4.0 * c1)
    } else {
        (
            positive_given(
                "foundation.modulus",
                f.modulus,
                "the Kerr soil's lower springs k in N/m³",
                "N/m³",
            )?,
            positive_given(
                "foundation.shear_modulus",
                f.shear_modulus,
                "the Kerr soil's shear layer G in N/m",
                "N/m",
            )?,
            positive_given(
                "foundation.upper_modulus",
                f.upper_modulus,
                "the Kerr soil's upper springs c in N/m³ (c → ∞ is the Pasternak soil)",
                "N/m³",
            )?,
        )
    };
    let gamma = d / (k * p.mu * l.powi(4));
    let shear = pasternak_length("foundation.shear_modulus", g_s * l * l / d, gamma, p.mu)?;
    Ok(Groups {
        shear: Some(shear),
        upper: Some(d / (c * p.mu * l.powi(4))),
        ..p.on(FoundationKind::Kerr, gamma)
    })
}

/// Reissner's layer's E_s and ν_s (`youngs_modulus`, `poissons_ratio`).
fn reissner_soil(f: &FoundationSpec) -> Result<(f64, f64)> {
    let e = positive_given(
        "foundation.youngs_modulus",
        f.youngs_modulus,
        "the layer's Young's modulus E_s in Pa",
        "Pa",
    )?;
    let nu = poisson(
        "foundation.poissons_ratio",
        given(
            "foundation.poissons_ratio",
            f.poissons_ratio,
            "the layer's Poisson's ratio ν_s",
        )?,
    )?;
    Ok((e, nu))
}

/// An elastic layer of E_s (Pa) and ν_s, `depth` h (m) down to a rigid `base`: the
/// half-space's Γ_h, h/L, ν_s and the base.
fn elastic_layer_si(f: &FoundationSpec, p: PlateGroups, l: f64, d: f64) -> Result<Groups> {
    no_shear_layer_si(f)?;
    let (gamma, soil_nu) = elastic_soil_si(f, p, l, d)?;
    let base = layer_base("foundation.base", f.base.as_deref())?;
    let h = positive_given(
        "foundation.depth",
        f.depth,
        "the elastic layer's depth h to the rigid base, in m",
        "m",
    )?;
    let depth = depth_ratio("foundation.depth", h / l)?;
    Ok(Groups {
        depth: Some(depth),
        soil_nu: Some(soil_nu),
        base: Some(base),
        ..p.on(FoundationKind::ElasticLayer, gamma)
    })
}

/// E_s and ν_s of a half-space or a layer: its Γ_h = D (1 − ν_s²) / (π E_s μ L³) and ν_s.
fn elastic_soil_si(f: &FoundationSpec, p: PlateGroups, l: f64, d: f64) -> Result<(f64, f64)> {
    if f.modulus.is_some() {
        return Err(Error::invalid(
            "foundation.modulus",
            "belongs to model = \"winkler\"; a half-space takes youngs_modulus (Pa) and poissons_ratio",
        ));
    }
    let es = positive_given(
        "foundation.youngs_modulus",
        f.youngs_modulus,
        "soil Young's modulus E_s in Pa",
        "Pa",
    )?;
    let nus = poisson(
        "foundation.poissons_ratio",
        given(
            "foundation.poissons_ratio",
            f.poissons_ratio,
            "soil Poisson's ratio ν_s",
        )?,
    )?;
    let gamma = d * (1.0 - nus * nus) / (std::f64::consts::PI * es * p.mu * l.powi(3));
    Ok((gamma, nus))
}

/// `value`, or an error naming `field` as missing, with `what` it is.
fn given(field: &str, value: Option<f64>, what: &str) -> Result<f64> {
    value.ok_or_else(|| Error::invalid(field, format!("missing: {what}")))
}

/// `value` given, finite and positive (in `unit`).
fn positive_given(field: &str, value: Option<f64>, what: &str, unit: &str) -> Result<f64> {
    finite_positive(field, given(field, value, what)?, unit)
}

/// Refuse `shear_modulus` on a soil without a shear layer.
fn no_shear_layer_si(f: &FoundationSpec) -> Result<()> {
    if f.shear_modulus.is_some() {
        return Err(Error::invalid(
            "foundation.shear_modulus",
            format!("belongs to model = \"pasternak\"; a {} foundation has no shear layer (use model = \"pasternak\" with modulus and shear_modulus, or leave it out)", f.model.name()),
        ));
    }
    Ok(())
}

/// Refuse `depth` and `base` on a soil without a rigid base.
fn no_rigid_base_si(f: &FoundationSpec) -> Result<()> {
    for (key, given) in [
        ("foundation.depth", f.depth.is_some()),
        ("foundation.base", f.base.is_some()),
    ] {
        if given {
            return Err(Error::invalid(
                key,
                format!("belongs to model = \"elastic-layer\"; a {} foundation has no rigid base below it (use model = \"elastic-layer\" with youngs_modulus, poissons_ratio and depth, or leave it out)", f.model.name()),
            ));
        }
    }
    Ok(())
}

/// Winkler: Γ_w alone.
fn winkler_dimensionless(g: &DimensionlessSpec, p: PlateGroups, gamma: f64) -> Result<Groups> {
    no_shear_layer(g)?;
    no_rigid_base(g)?;
    Ok(p.on(FoundationKind::Winkler, gamma))
}

/// The half-space: Γ_h alone.
fn half_space_dimensionless(g: &DimensionlessSpec, p: PlateGroups, gamma: f64) -> Result<Groups> {
    no_shear_layer(g)?;
    no_rigid_base(g)?;
    Ok(p.on(FoundationKind::HalfSpace, gamma))
}

/// Pasternak: Γ_w of its springs and the shear parameter Γ_g = G_p L²/D.
fn pasternak_dimensionless(g: &DimensionlessSpec, p: PlateGroups, gamma: f64) -> Result<Groups> {
    let shear = positive_given(
        "dimensionless.shear",
        g.shear,
        "the Pasternak shear parameter Γ_g = G_p L²/D (for Γ_g = 0 use foundation = \"winkler\")",
        "Γ_g = G_p L²/D",
    )?;
    let shear = pasternak_length("dimensionless.shear", shear, gamma, p.mu)?;
    no_rigid_base(g)?;
    Ok(Groups {
        shear: Some(shear),
        ..p.on(FoundationKind::Pasternak, gamma)
    })
}

/// The elastic layer: Γ_h of its E_s and ν_s, the depth ratio h/L, ν_s and the base.
fn elastic_layer_dimensionless(
    g: &DimensionlessSpec,
    p: PlateGroups,
    gamma: f64,
) -> Result<Groups> {
    no_shear_layer(g)?;
    let depth = given("dimensionless.depth", g.depth, "the elastic layer's depth ratio h/L (depth to the rigid base over the plate's half-length)")?;
    let soil_nu = given("dimensionless.soil_nu", g.soil_nu, "the elastic layer's Poisson's ratio ν_s (its kernel depends on ν_s beyond the factor 1 − ν_s² in Γ_h)")?;
    let depth = depth_ratio("dimensionless.depth", depth)?;
    let soil_nu = poisson("dimensionless.soil_nu", soil_nu)?;
    let base = layer_base("dimensionless.base", g.base.as_deref())?;
    Ok(Groups {
        depth: Some(depth),
        soil_nu: Some(soil_nu),
        base: Some(base),
        ..p.on(FoundationKind::ElasticLayer, gamma)
    })
}

/// Refuse `shear` on a soil without a shear layer.
fn no_shear_layer(g: &DimensionlessSpec) -> Result<()> {
    if g.shear.is_some() {
        return Err(Error::invalid(
            "dimensionless.shear",
            format!("belongs to foundation = \"pasternak\"; a {} foundation has no shear layer (leave it out)", g.foundation.name()),
        ));
    }
    Ok(())
}

/// Kerr: Γ_w of its lower springs, Γ_g of its shear layer and Γ_c = D/(c μ L⁴) of its upper
/// springs (`upper`).
fn kerr_dimensionless(g: &DimensionlessSpec, p: PlateGroups, gamma: f64) -> Result<Groups> {
    no_rigid_base(g)?;
    let shear = positive_given(
        "dimensionless.shear",
        g.shear,
        "the Kerr soil's shear parameter Γ_g = G L²/D",
        "Γ_g = G L²/D",
    )?;
    let shear = pasternak_length("dimensionless.shear", shear, gamma, p.mu)?;
    let upper = positive_given(
        "dimensionless.upper",
        g.upper,
        "the Kerr soil's upper springs Γ_c = D/(c μ L⁴)",
        "Γ_c = D/(c μ L⁴)",
    )?;
    Ok(Groups {
        shear: Some(shear),
        upper: Some(upper),
        ..p.on(FoundationKind::Kerr, gamma)
    })
}

/// Refuse `depth`, `soil_nu` and `base` on a soil without a rigid base.
fn no_rigid_base(g: &DimensionlessSpec) -> Result<()> {
    for (key, given) in [
        ("dimensionless.depth", g.depth.is_some()),
        ("dimensionless.soil_nu", g.soil_nu.is_some()),
        ("dimensionless.base", g.base.is_some()),
    ] {
        if given {
            return Err(Error::invalid(
                key,
                format!("belongs to foundation = \"elastic-layer\"; a {} foundation has no rigid base below it (leave it out)", g.foundation.name()),
            ));
        }
    }
    Ok(())
}

/// Upper limit of the Pasternak decay length λ/L = √(Γ_g μ Γ_w). Beyond it the shear layer
/// spreads a load over more than a thousand plate lengths: the kernel is then a large constant
/// plus a small logarithmic variation over the plate, and T loses the digits that tell its
/// entries apart — the soil acts like a membrane of tension G_p, better modelled as such.
pub const MAX_PASTERNAK_LENGTH: f64 = 1e3;

/// Check the decay length the shear parameter `shear` = Γ_g gives with Γ_w = `gamma`, and
/// return Γ_g.
fn pasternak_length(field: &str, shear: f64, gamma: f64, mu: f64) -> Result<f64> {
    let lambda = (shear * mu * gamma).sqrt();
    if !(lambda.is_finite() && lambda > 0.0) || lambda > MAX_PASTERNAK_LENGTH {
        return Err(Error::invalid(
            field,
            format!("gives the decay length λ = √(G_p/k) = {lambda:e} half-lengths L of the plate, outside (0, {MAX_PASTERNAK_LENGTH:e}]: check the units (G_p in N/m, k in N/m³) or lower the shear modulus"),
        ));
    }
    Ok(shear)
}

/// Range of the elastic layer's depth ratio h/L. Deeper layers are the half-space to within
/// e^{−2·1e4}; thinner ones than 1e−4 L put the whole kernel (40 depths) below the radial
/// quadrature's innermost panel of an element pair, and are a Winkler bed k = E_oed/h anyway.
pub const LAYER_DEPTH_RANGE: [f64; 2] = [1e-4, 1e4];

/// Check the layer depth ratio h/L against [`LAYER_DEPTH_RANGE`], and return it.
fn depth_ratio(field: &str, h: f64) -> Result<f64> {
    let [lo, hi] = LAYER_DEPTH_RANGE;
    if !(h.is_finite() && (lo..=hi).contains(&h)) {
        return Err(Error::invalid(
            field,
            format!("gives the layer depth h = {h:e} half-lengths L of the plate, outside [{lo:e}, {hi:e}]: check the units (m); a deeper layer is a half-space (model = \"half-space\"), a thinner one a Winkler bed of modulus E_oed/h (model = \"winkler\")"),
        ));
    }
    Ok(h)
}

/// A layer's base by name ("rough" when not given).
fn layer_base(field: &str, base: Option<&str>) -> Result<Base> {
    match base {
        None => Ok(Base::Rough),
        Some(name) => Base::parse(name).ok_or_else(|| {
            Error::invalid(
                field,
                format!("\"{name}\" is not a base: give \"rough\" (the layer bonded to the rigid base, the default) or \"smooth\" (frictionless)"),
            )
        }),
    }
}
