//! The homogeneous elastic layer of depth h on a rigid base (rough or smooth): the half-space's
//! kernel minus a smooth correction from Burmister's symbol, tabulated in [`super::layer`]. In
//! the unit system its groups are the half-space's Γ_h of its E_s and ν_s (in
//! [`crate::model::Groups`]), the depth ratio h/L, ν_s (which shapes the kernel beyond the
//! factor 1 − ν_s² in Γ_h) and the base (here).

use std::sync::Arc;

use super::halfspace::{elastic_settlement, elastic_soil, ELASTIC_KEYS};
use super::kernel::{Kernel, Radial};
use super::layer::{Base, LayerTable, LAYER_CUTOFF};
use super::soil::{key, Key, PlateScale, SoilKeys, SoilModel, SoilNames};
use crate::check::poisson;
use crate::error::{Error, Result};

/// The elastic layer's own groups.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct ElasticLayer {
    /// The depth ratio h/L (layer depth over the plate's half-length).
    pub depth: f64,
    /// The layer's Poisson's ratio ν_s.
    pub soil_nu: f64,
    /// Its rigid base, rough or smooth.
    pub base: Base,
}

/// The oedometric modulus E_oed = E(1 − ν)/((1 + ν)(1 − 2ν)) of a soil of E, ν: a long load on
/// a layer of depth h settles p h/E_oed.
pub fn oedometric(e: f64, nu: f64) -> f64 {
    e * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu))
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

/// The layer's `base` ("rough" when not given).
fn layer_base(keys: &SoilKeys<'_>) -> Result<Base> {
    match keys.word("base")? {
        None => Ok(Base::Rough),
        Some(name) => Base::parse(name).ok_or_else(|| {
            Error::invalid(
                keys.field("base"),
                format!("\"{name}\" is not a base: give \"rough\" (the layer bonded to the rigid base, the default) or \"smooth\" (frictionless)"),
            )
        }),
    }
}

impl SoilModel for ElasticLayer {
    const LOCAL: bool = false;
    const NAMES: SoilNames = SoilNames {
        label: "elastic layer",
        short: "elastic layer",
        stem: "layer",
    };
    const SI_KEYS: &'static [Key] = &[
        ELASTIC_KEYS[0],
        ELASTIC_KEYS[1],
        key("depth", "m"),
        key("base", "\"rough\" or \"smooth\""),
    ];
    const GROUP_KEYS: &'static [Key] = &[
        key("depth", "h/L"),
        key("soil_nu", "ν_s"),
        key("base", "\"rough\" or \"smooth\""),
    ];

    /// E_s (Pa) and ν_s, `depth` h (m) down to a rigid `base`: the half-space's Γ_h, h/L, ν_s
    /// and the base.
    fn from_si(keys: &SoilKeys<'_>, plate: &PlateScale) -> Result<(f64, Self)> {
        let (gamma, soil_nu) = elastic_soil(keys, plate)?;
        let base = layer_base(keys)?;
        let h = keys.positive(
            "depth",
            "the elastic layer's depth h to the rigid base, in m",
            "m",
        )?;
        let depth = depth_ratio(&keys.field("depth"), h / plate.half_length)?;
        Ok((
            gamma,
            ElasticLayer {
                depth,
                soil_nu,
                base,
            },
        ))
    }

    fn from_groups(keys: &SoilKeys<'_>, _: &PlateScale, _: f64) -> Result<Self> {
        let depth = keys.given("depth", "the elastic layer's depth ratio h/L (depth to the rigid base over the plate's half-length)")?;
        let soil_nu = keys.given("soil_nu", "the elastic layer's Poisson's ratio ν_s (its kernel depends on ν_s beyond the factor 1 − ν_s² in Γ_h)")?;
        let depth = depth_ratio(&keys.field("depth"), depth)?;
        let soil_nu = poisson(&keys.field("soil_nu"), soil_nu)?;
        let base = layer_base(keys)?;
        Ok(ElasticLayer {
            depth,
            soil_nu,
            base,
        })
    }

    fn stiffness_length(c: f64) -> f64 {
        (2.0 * std::f64::consts::PI * c).cbrt()
    }

    fn kernel(&self, _: f64, _: f64) -> Option<Kernel> {
        Some(Kernel::new(LayerKernel {
            depth: self.depth,
            table: LayerTable::shared(self.soil_nu, self.base),
        }))
    }

    /// The half-space's estimate, an upper bound (the base stiffens the layer).
    fn settlement(&self, c: f64, mu: f64) -> f64 {
        elastic_settlement(c, mu)
    }

    fn describe(&self, _: f64, _: f64) -> String {
        format!(
            ", h/L = {:.4}, ν_s = {}, {} base",
            self.depth,
            self.soil_nu,
            self.base.name()
        )
    }
}

/// The layer's kernel K(ρ) = 1/ρ − F(ρ/h)/h (the half-space minus a smooth correction,
/// [`super::layer`]), c = (1 − ν_s²)/(π E_s) as for the half-space. Zero beyond
/// [`LAYER_CUTOFF`] depths.
#[derive(Debug, Clone)]
pub struct LayerKernel {
    /// h in the caller's length unit.
    pub depth: f64,
    /// The correction F of the layer's Poisson's ratio and base.
    pub table: Arc<LayerTable>,
}

impl Radial for LayerKernel {
    fn value(&self, rho: f64) -> f64 {
        self.table.kernel(rho, self.depth)
    }

    fn support(&self) -> Option<f64> {
        Some(LAYER_CUTOFF * self.depth)
    }

    fn scale(&self) -> f64 {
        self.depth
    }
}
