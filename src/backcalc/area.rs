//! The AREA method (Ioannides 1989; Hall 1991; AASHTO Guide 1993, Part III): from a basin's
//! shape, the radius of relative stiffness ℓ of an infinite slab on a dense liquid or an elastic
//! solid, then from the centre deflection the subgrade's modulus and the slab's.
//!
//! AREA is the basin's area between the load and 914 mm (36 in), over the centre deflection,
//! by the trapezoid rule on the sensors at 0, 305, 610 and 914 mm (12 in apart: AREA =
//! 6 (1 + 2 d₁₂/d₀ + 2 d₂₄/d₀ + d₃₆/d₀) in, between 11.04 and 36 in). Where the literature maps
//! AREA to ℓ by Hall's regressions of the closed forms, here the closed forms themselves are
//! inverted: the model's AREA at ℓ, on the same sensors by the same rule, from the infinite
//! Kirchhoff plate under the load's own disk ([`super::infinite`]); it grows with ℓ, and the
//! measured AREA is matched by false position in ln ℓ. Then, with α = a/ℓ:
//!
//! - dense liquid: k = P f(0, α) / (d₀ ℓ²), E = 12 (1 − ν²) k ℓ⁴ / h³;
//! - elastic solid: C = P g(0, α) / (d₀ ℓ), E_s = 2 (1 − ν_s²) C, E = 12 (1 − ν²) C ℓ³ / h³.
//!
//! The method assumes an infinite slab bonded to its subgrade, the load far from any edge or
//! joint, and the slab flat at test time; `tests/circle_load.rs` and `tests/backcalc_fit.rs`
//! measure how far it is off at a free edge.
//!
//! **A finite slab** ([`finite_slab`], dense liquid only). A load at the centre of a square
//! slab of side L deflects it more, over a flatter bowl, than the infinite slab: the AREA
//! reads ℓ too long and, with d₀ too large, k too small. Crovetti (1994) fitted two factors
//! to finite-element runs of square slabs, in L/ℓ_est with ℓ_est the infinite slab's reading,
//!
//! - AF_d₀ = 1 − 1.15085 exp(−0.71878 (L/ℓ_est)^0.80151),
//! - AF_ℓ  = 1 − 0.89434 exp(−0.61662 (L/ℓ_est)^1.04831),
//!
//! and the slab's ℓ = AF_ℓ ℓ_est and the infinite slab's d₀ = AF_d₀ d₀ then give k and E by
//! the closed forms above; a rectangular L₁ × L₂ slab is taken as the square of equal area,
//! L = √(L₁ L₂). The constants are as Khazanovich, Tayabji and Darter (2001, FHWA-RD-00-086,
//! the LTPP backcalculation) quote them; the original report was not at hand, so
//! `tests/backcalc_area_finite.rs` checks them against liftoff's own finite slabs: from
//! L/ℓ = 3.5 to 10 the corrected reading is that of a slab of 20 ℓ within 1.1 % in ℓ, 3.6 % in
//! k and 1.7 % in E, where the uncorrected one was off by up to 12 % in ℓ and 34 % in k. It is
//! not applied below L/ℓ_est = 3, where the factors fall steeply (at 2.5 AF_d₀ = 0.75 and the
//! corrected reading was still 3 % off in ℓ, 5 % in k and 7 % in E). The factors are for a
//! load at the slab's centre; joints that transfer load make a panel act larger than itself,
//! and there the correction overshoots: the fit on the jointed model is the answer.

use super::infinite::{dimensionless_deflection, Subgrade};
use crate::error::{Error, Result};

/// The AREA method's sensor offsets, m: 0, 12, 24 and 36 in.
pub const AREA_OFFSETS: [f64; 4] = [0.0, 0.3048, 0.6096, 0.9144];

/// How far a sensor may sit from its AREA offset, m: the SHRP offsets (0, 305, 610, 914 mm)
/// are within 0.5 mm of 12-in multiples.
const OFFSET_TOLERANCE: f64 = 0.01;

/// One deflection basin.
#[derive(Debug, Clone, PartialEq)]
pub struct Basin {
    /// The drop's load, N.
    pub load: f64,
    /// The load plate's radius, m.
    pub radius: f64,
    /// Sensor offsets from the plate's centre, m.
    pub offsets: Vec<f64>,
    /// Deflections at the sensors, m, downward.
    pub deflections: Vec<f64>,
}

/// What the AREA method finds.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct AreaResult {
    /// The basin's AREA, m (÷ 0.0254 for inches).
    pub area: f64,
    /// The radius of relative stiffness, m.
    pub ell: f64,
    /// k (N/m³) on the dense liquid, E_s (Pa) on the elastic solid.
    pub subgrade_modulus: f64,
    /// The slab's Young's modulus, Pa.
    pub slab_modulus: f64,
    /// Crovetti's finite-slab correction, where it was applied ([`finite_slab`]): the values
    /// above are then the corrected ones.
    pub finite: Option<FiniteSlab>,
}

/// Crovetti's finite-slab correction of an AREA reading.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct FiniteSlab {
    /// The square slab's side L (√(L₁ L₂) of a rectangle), m.
    pub size: f64,
    /// AF_d₀: the infinite slab's centre deflection over the finite slab's.
    pub deflection_factor: f64,
    /// AF_ℓ: the slab's ℓ over the infinite slab's reading.
    pub ell_factor: f64,
    /// The infinite slab's reading it corrects: ℓ, m.
    pub infinite_ell: f64,
    /// The infinite slab's k, N/m³.
    pub infinite_subgrade_modulus: f64,
    /// The infinite slab's E, Pa.
    pub infinite_slab_modulus: f64,
}

/// Below this L/ℓ_est the finite-slab correction is not applied (see the module's text).
pub const FINITE_SLAB_MIN_RATIO: f64 = 3.0;

/// Crovetti's factors (AF_d₀, AF_ℓ) at L/ℓ_est = `ratio`.
pub fn crovetti_factors(ratio: f64) -> (f64, f64) {
    (
        1.0 - 1.15085 * (-0.71878 * ratio.powf(0.80151)).exp(),
        1.0 - 0.89434 * (-0.61662 * ratio.powf(1.04831)).exp(),
    )
}

/// The AREA of the deflections `d` at the sensors `at` (the four AREA sensors as placed), m.
fn area_of(at: &[f64; 4], d: &[f64; 4]) -> f64 {
    (0..3)
        .map(|i| (at[i + 1] - at[i]) * (d[i] + d[i + 1]) / 2.0)
        .sum::<f64>()
        / d[0]
}

/// The model's dimensionless basin at the sensors `at` for ℓ.
fn model_basin(subgrade: Subgrade, radius: f64, ell: f64, at: &[f64; 4]) -> [f64; 4] {
    at.map(|r| dimensionless_deflection(subgrade, r / ell, radius / ell))
}

/// Run the AREA method on `basin` for a slab of `thickness` (m) and Poisson's ratio `poisson`;
/// see the module's description. Errors name the field: a basin without the four AREA sensors,
/// a load or deflection that is not positive, deflections that grow away from the load, an
/// AREA outside what an infinite slab can give.
pub fn area_method(
    basin: &Basin,
    thickness: f64,
    poisson: f64,
    subgrade: Subgrade,
) -> Result<AreaResult> {
    infinite_slab(basin, thickness, poisson, subgrade).map(|(r, _)| r)
}

/// [`area_method`]'s reading with the centre deflection d₀ it read (m).
fn infinite_slab(
    basin: &Basin,
    thickness: f64,
    poisson: f64,
    subgrade: Subgrade,
) -> Result<(AreaResult, f64)> {
    if !(basin.load.is_finite() && basin.load > 0.0) {
        return Err(Error::invalid(
            "basin.load",
            format!("must be a positive force, got {}", basin.load),
        ));
    }
    if !(basin.radius.is_finite() && basin.radius > 0.0) {
        return Err(Error::invalid(
            "basin.radius",
            format!("must be a positive length, got {}", basin.radius),
        ));
    }
    if !(thickness > 0.0 && (0.0..0.5).contains(&poisson)) {
        return Err(Error::invalid(
            "plate",
            "the AREA method needs the slab's thickness (> 0) and Poisson's ratio (0 … 0.5)",
        ));
    }
    if basin.offsets.len() != basin.deflections.len() {
        return Err(Error::invalid(
            "basin.deflections",
            format!(
                "{} deflections for {} sensor offsets",
                basin.deflections.len(),
                basin.offsets.len()
            ),
        ));
    }
    let mut d = [0.0; 4];
    // Where the four sensors are: the model's AREA is taken there too, so that SHRP's offsets
    // (305, 610, 914 mm) give the same ℓ as exact 12-in multiples would.
    let mut at = [0.0; 4];
    for (k, &want) in AREA_OFFSETS.iter().enumerate() {
        let found = basin
            .offsets
            .iter()
            .position(|&o| (o - want).abs() <= OFFSET_TOLERANCE)
            .ok_or_else(|| {
                Error::invalid(
                    "basin.offsets",
                    format!(
                        "the AREA method needs sensors at 0, 305, 610 and 914 mm; none within 10 mm of {:.0} mm",
                        want * 1e3
                    ),
                )
            })?;
        d[k] = basin.deflections[found];
        at[k] = basin.offsets[found];
    }
    if !d.iter().all(|v| v.is_finite() && *v > 0.0) {
        return Err(Error::invalid(
            "basin.deflections",
            format!("must be positive (downward) at the AREA sensors, got {d:?} m"),
        ));
    }
    if let Some(k) = (0..3).find(|&k| d[k + 1] > d[k]) {
        return Err(Error::invalid(
            "basin.deflections",
            format!(
                "grow away from the load ({:.1} µm at {:.0} mm, {:.1} µm at {:.0} mm): a basin falls from the plate outward (check the sensor order and units)",
                d[k] * 1e6,
                AREA_OFFSETS[k] * 1e3,
                d[k + 1] * 1e6,
                AREA_OFFSETS[k + 1] * 1e3
            ),
        ));
    }
    let area = area_of(&at, &d);
    let model_area = |ell: f64| area_of(&at, &model_basin(subgrade, basin.radius, ell, &at));
    // ℓ from a tenth of the plate's radius (α = 10) to 100 m: AREA spans 11–36 in over it.
    let (lo, hi) = (basin.radius / 10.0, 100.0);
    let (a_lo, a_hi) = (model_area(lo), model_area(hi));
    if !(a_lo..=a_hi).contains(&area) {
        return Err(Error::invalid(
            "basin.deflections",
            format!(
                "AREA {:.2} in lies outside what an infinite slab gives under a {:.0} mm plate ({:.2} … {:.2} in): the basin is not a slab's on this subgrade",
                area / 0.0254,
                basin.radius * 1e3,
                a_lo / 0.0254,
                a_hi / 0.0254
            ),
        ));
    }
    // The root of AREA(ℓ) = AREA in ln ℓ by false position with the Illinois modification
    // (Dowell & Jarratt 1971): the bracket [lo, hi] holds it throughout, and the end that stays
    // has its value halved, so that convergence is superlinear (some ten evaluations of the
    // model's AREA, against the fifty a bisection to the same 1e-14 needed).
    let (mut a, mut b) = (lo.ln(), hi.ln());
    let (mut fa, mut fb) = (a_lo - area, a_hi - area);
    let mut kept = 0i8;
    let mut c = 0.5 * (a + b);
    for _ in 0..100 {
        if fb == fa {
            break;
        }
        let next = ((a * fb - b * fa) / (fb - fa)).clamp(a.min(b), a.max(b));
        let done = (next - c).abs() <= 1e-14 * next.abs().max(1.0);
        c = next;
        let fc = model_area(c.exp()) - area;
        if fc == 0.0 || done {
            break;
        }
        if (fc > 0.0) == (fb > 0.0) {
            b = c;
            fb = fc;
            if kept == -1 {
                fa *= 0.5;
            }
            kept = -1;
        } else {
            a = c;
            fa = fc;
            if kept == 1 {
                fb *= 0.5;
            }
            kept = 1;
        }
    }
    let ell = c.exp();
    let (subgrade_modulus, slab_modulus) = moduli(basin, d[0], ell, thickness, poisson, subgrade);
    Ok((
        AreaResult {
            area,
            ell,
            subgrade_modulus,
            slab_modulus,
            finite: None,
        },
        d[0],
    ))
}

/// The subgrade's modulus and the slab's from ℓ and the centre deflection `d0` by the closed
/// forms (the module's text).
fn moduli(
    basin: &Basin,
    d0: f64,
    ell: f64,
    thickness: f64,
    poisson: f64,
    subgrade: Subgrade,
) -> (f64, f64) {
    let centre = dimensionless_deflection(subgrade, 0.0, basin.radius / ell);
    let bending = 12.0 * (1.0 - poisson * poisson) / thickness.powi(3);
    match subgrade {
        Subgrade::DenseLiquid => {
            let k = basin.load * centre / (d0 * ell * ell);
            (k, bending * k * ell.powi(4))
        }
        Subgrade::ElasticSolid { poisson: nu_s } => {
            let c = basin.load * centre / (d0 * ell);
            (2.0 * (1.0 - nu_s * nu_s) * c, bending * c * ell.powi(3))
        }
    }
}

/// The AREA method on a square slab of side `size` (m; √(L₁ L₂) of a rectangle) on a dense
/// liquid, the load at its centre: [`area_method`]'s infinite-slab reading with Crovetti's
/// correction (the module's text). Where L/ℓ_est is below [`FINITE_SLAB_MIN_RATIO`] the
/// reading is returned uncorrected (`finite` None): the factors were not checked there.
pub fn finite_slab(basin: &Basin, thickness: f64, poisson: f64, size: f64) -> Result<AreaResult> {
    if !(size.is_finite() && size > 0.0) {
        return Err(Error::invalid(
            "slab_size",
            format!("must be the slab's positive side length (m), got {size}"),
        ));
    }
    let (infinite, d0) = infinite_slab(basin, thickness, poisson, Subgrade::DenseLiquid)?;
    let ratio = size / infinite.ell;
    if ratio < FINITE_SLAB_MIN_RATIO {
        return Ok(infinite);
    }
    let (af_d0, af_ell) = crovetti_factors(ratio);
    let ell = af_ell * infinite.ell;
    let (subgrade_modulus, slab_modulus) = moduli(
        basin,
        af_d0 * d0,
        ell,
        thickness,
        poisson,
        Subgrade::DenseLiquid,
    );
    Ok(AreaResult {
        area: infinite.area,
        ell,
        subgrade_modulus,
        slab_modulus,
        finite: Some(FiniteSlab {
            size,
            deflection_factor: af_d0,
            ell_factor: af_ell,
            infinite_ell: infinite.ell,
            infinite_subgrade_modulus: infinite.subgrade_modulus,
            infinite_slab_modulus: infinite.slab_modulus,
        }),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Basins from the closed forms themselves at a known slab come back: ℓ, k (or E_s) and E
    /// to 1e-9 (the root-finding ends at 1e-14 in ln ℓ; the closed forms are smooth in ℓ).
    #[test]
    fn closed_form_basins_come_back() {
        let (h, nu, e) = (0.25, 0.15, 30e9);
        let d = e * h * h * h / (12.0 * (1.0 - nu * nu));
        for (subgrade, modulus) in [
            (Subgrade::DenseLiquid, 8.0e7_f64),
            (Subgrade::ElasticSolid { poisson: 0.4 }, 1.0e8),
        ] {
            let ell = match subgrade {
                Subgrade::DenseLiquid => (d / modulus).powf(0.25),
                Subgrade::ElasticSolid { poisson } => {
                    (d * 2.0 * (1.0 - poisson * poisson) / modulus).powf(1.0 / 3.0)
                }
            };
            let unit = match subgrade {
                Subgrade::DenseLiquid => 40e3 / (modulus * ell * ell),
                Subgrade::ElasticSolid { poisson } => {
                    40e3 / (modulus / (2.0 * (1.0 - poisson * poisson)) * ell)
                }
            };
            let basin = Basin {
                load: 40e3,
                radius: 0.15,
                offsets: vec![0.0, 0.203, 0.305, 0.457, 0.610, 0.914, 1.219],
                deflections: [0.0, 0.203, 0.305, 0.457, 0.610, 0.914, 1.219]
                    .iter()
                    .map(|&r| unit * dimensionless_deflection(subgrade, r / ell, 0.15 / ell))
                    .collect(),
            };
            let r = area_method(&basin, h, nu, subgrade).expect("area");
            let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * b;
            assert!(close(r.ell, ell), "{subgrade:?}: ℓ {} vs {ell}", r.ell);
            assert!(
                close(r.subgrade_modulus, modulus),
                "{subgrade:?}: {}",
                r.subgrade_modulus
            );
            assert!(
                close(r.slab_modulus, e),
                "{subgrade:?}: E {}",
                r.slab_modulus
            );
        }
    }
}
