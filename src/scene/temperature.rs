//! Temperature and moisture through the thickness (`kind = "temperature-profile"`,
//! `"moisture"`, `"built-in-curl"`): what curls the plate is the equivalent linear gradient
//! that keeps the profile's moment; what is left of the profile has no resultant and no moment,
//! bends nothing and adds its own stress to the surface stresses.
//!
//! With z from the mid-plane (positive up) and T(z) through the thickness H:
//! T₀ = (1/H)∫T dz (free expansion: no stress in a plate free to slide),
//! ΔT_eq = (12/H²)∫T z dz (top minus bottom),
//! T_nl = T − T₀ − ΔT_eq z/H, σ_nl = −E α T_nl/(1 − ν) (tension positive).

use super::spec::LoadSpec;
use crate::error::{Error, Result};
use crate::model::Load;

/// What turns SI temperature differences into curvatures and stresses: α (if given), H, D, ν.
#[derive(Debug, Clone, Copy)]
pub(super) struct Thermal {
    pub(super) alpha: Option<f64>,
    pub(super) thickness: f64,
    pub(super) rigidity: f64,
    pub(super) poisson: f64,
}

/// The loads of a `temperature-profile`, `moisture` or `built-in-curl` entry `k` (SI scenes
/// only; `length` is L, m): curvatures D κ (N, as `kind = "temperature"`) and face stresses
/// σ L² (N), raw (not yet divided by P).
pub(super) fn loads(
    l: &LoadSpec,
    k: usize,
    thermal: Option<Thermal>,
    length: Option<f64>,
) -> Result<Vec<Load>> {
    let field = |name: &str| format!("load[{k}].{name}");
    let (Some(th), Some(length)) = (thermal, length) else {
        return Err(Error::invalid(
            field("kind"),
            format!(
                "kind = \"{}\" belongs to SI scenes ([plate] and [foundation]): it needs the plate's thickness, moduli and α",
                l.kind.name()
            ),
        ));
    };
    let a = th.alpha.ok_or_else(|| {
        Error::invalid(
            "plate.thermal_expansion",
            format!("missing: load[{k}] is a {} load; give the plate's coefficient of thermal expansion in 1/K (concrete ≈ 1.0e-5)", l.kind.name()),
        )
    })?;
    let curvature = |dt: f64| Load::Temperature {
        curvature: th.rigidity * a * dt / th.thickness,
    };
    let finite = |name: &str, v: Option<f64>| -> Result<f64> {
        let v = v.ok_or_else(|| Error::invalid(field(name), "missing"))?;
        if v.is_finite() {
            Ok(v)
        } else {
            Err(Error::invalid(
                field(name),
                format!("must be finite, got {v}"),
            ))
        }
    };
    match l.kind {
        super::spec::LoadKind::TemperatureProfile => {
            let parts = profile(l, k, th.thickness)?;
            // σ_nl = −E α T_nl/(1 − ν), E/(1 − ν) = 12 D (1 + ν)/H³; raw σ L².
            let e_over = 12.0 * th.rigidity * (1.0 + th.poisson) / th.thickness.powi(3);
            let stress = |t: f64| -e_over * a * t * length * length;
            Ok(vec![
                curvature(parts.gradient),
                Load::FaceStress {
                    top: stress(parts.nonlinear[0]),
                    bottom: stress(parts.nonlinear[1]),
                },
            ])
        }
        super::spec::LoadKind::Moisture => {
            let eps = finite("shrinkage", l.shrinkage)?;
            let depth = finite("depth", l.depth)?;
            if depth <= 0.0 || depth > th.thickness {
                return Err(Error::invalid(
                    field("depth"),
                    format!(
                        "the drying layer's depth {depth} m must lie in (0, {}] (the thickness)",
                        th.thickness
                    ),
                ));
            }
            Ok(vec![curvature(moisture_gradient(
                eps,
                depth,
                th.thickness,
                a,
            ))])
        }
        _ => Ok(vec![curvature(finite("difference", l.difference)?)]),
    }
}

/// A profile split into its three parts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProfileParts {
    /// T₀, the mean temperature.
    pub mean: f64,
    /// ΔT_eq, the equivalent linear difference top minus bottom, K.
    pub gradient: f64,
    /// T_nl at the top and at the bottom face, K.
    pub nonlinear: [f64; 2],
}

/// Split a piecewise-linear profile: `depths` from the top (0 … H), `temps` at them.
pub fn piecewise_linear(depths: &[f64], temps: &[f64]) -> ProfileParts {
    let h = depths[depths.len() - 1];
    let z = |d: f64| h / 2.0 - d;
    let (mut area, mut moment) = (0.0, 0.0);
    for k in 0..depths.len() - 1 {
        let (z1, z2) = (z(depths[k]), z(depths[k + 1]));
        let (t1, t2) = (temps[k], temps[k + 1]);
        // ∫ over [z2, z1] (z decreases with depth) of the linear interpolant.
        let dz = z1 - z2;
        area += dz * (t1 + t2) / 2.0;
        moment += dz / 6.0 * (t1 * (2.0 * z1 + z2) + t2 * (z1 + 2.0 * z2));
    }
    let mean = area / h;
    let gradient = 12.0 * moment / (h * h);
    let top = temps[0] - mean - gradient / 2.0;
    let bottom = temps[temps.len() - 1] - mean + gradient / 2.0;
    ProfileParts {
        mean,
        gradient,
        nonlinear: [top, bottom],
    }
}

/// Split the quadratic through T_top, T_mid, T_bot: T₀ = T_mid + c/6, ΔT_eq = T_top − T_bot,
/// T_nl(±H/2) = c/3 with c = T_top + T_bot − 2T_mid (closed forms of the integrals).
pub fn quadratic(top: f64, mid: f64, bottom: f64) -> ProfileParts {
    let c = top + bottom - 2.0 * mid;
    ProfileParts {
        mean: mid + c / 6.0,
        gradient: top - bottom,
        nonlinear: [c / 3.0, c / 3.0],
    }
}

/// The equivalent temperature difference (top minus bottom) of a drying shrinkage ε falling
/// linearly from `shrinkage` at the top surface to zero at `depth`, in a plate of thickness
/// `h`: the moment of ε/α, ΔT = 6 ε h_s (H/2 − h_s/3)/(α H²). A shrinking top (ε < 0) acts as a
/// cooler top: the plate curls up.
pub fn moisture_gradient(shrinkage: f64, depth: f64, h: f64, alpha: f64) -> f64 {
    6.0 * shrinkage * depth * (h / 2.0 - depth / 3.0) / (alpha * h * h)
}

/// A `temperature-profile` entry, checked and split: `k` its index, `h` the plate's thickness.
pub(super) fn profile(spec: &LoadSpec, k: usize, h: f64) -> Result<ProfileParts> {
    let field = |n: &str| format!("load[{k}].{n}");
    let depths = spec.depths.as_deref().ok_or_else(|| {
        Error::invalid(field("depths"), "missing: the depths of the temperatures, m from the top surface, from 0 to the plate's thickness")
    })?;
    let temps = spec.temperatures.as_deref().ok_or_else(|| {
        Error::invalid(
            field("temperatures"),
            "missing: the temperatures at `depths`, °C",
        )
    })?;
    crate::check::profile(&field, depths, temps, Some(h))?;
    let tol = 1e-6 * h;
    // The last depth is the thickness to round-off: take it exactly.
    let mut d = depths.to_vec();
    d[0] = 0.0;
    let last = d.len() - 1;
    d[last] = h;
    match spec.interpolation.as_deref().unwrap_or("linear") {
        "linear" => Ok(piecewise_linear(&d, temps)),
        "quadratic" => {
            if d.len() != 3 || (d[1] - h / 2.0).abs() > tol {
                return Err(Error::invalid(
                    field("depths"),
                    format!("a quadratic profile takes three values, at the top, the middle and the bottom: depths = [0, {}, {h}]", h / 2.0),
                ));
            }
            Ok(quadratic(temps[0], temps[1], temps[2]))
        }
        other => Err(Error::invalid(
            field("interpolation"),
            format!("`{other}` is not one of linear, quadratic"),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A linear profile has no nonlinear part and its gradient is top minus bottom; the mean of
    /// 20…35 °C is 27.5.
    #[test]
    fn a_linear_profile_is_all_gradient() {
        let p = piecewise_linear(&[0.0, 0.1, 0.25], &[35.0, 29.0, 20.0]);
        assert!((p.gradient - 15.0).abs() < 1e-12, "{p:?}");
        assert!((p.mean - 27.5).abs() < 1e-12, "{p:?}");
        assert!(p.nonlinear.iter().all(|t| t.abs() < 1e-12), "{p:?}");
    }

    /// The quadratic through (35, 24, 20) °C: T₀ = 24 + 7/6, ΔT = 15, T_nl(±H/2) = 7/3 — the
    /// closed forms against the moments of the same quadratic by Simpson's rule, which is exact
    /// for cubics: ∫T dz and ∫T z dz over [−H/2, H/2].
    #[test]
    fn quadratic_closed_forms_against_simpson() {
        let (t, m, b, h) = (35.0, 24.0, 20.0, 0.25);
        let p = quadratic(t, m, b);
        // T(z) through (H/2, t), (0, m), (−H/2, b).
        let temp = |z: f64| m + (t - b) * z / h + 2.0 * (t + b - 2.0 * m) * z * z / (h * h);
        let simpson = |f: &dyn Fn(f64) -> f64| h / 6.0 * (f(-h / 2.0) + 4.0 * f(0.0) + f(h / 2.0));
        let mean = simpson(&temp) / h;
        let gradient = 12.0 * simpson(&|z| temp(z) * z) / (h * h);
        assert!((p.mean - mean).abs() < 1e-12, "T₀ {} vs {mean}", p.mean);
        assert!(
            (p.gradient - gradient).abs() < 1e-12,
            "ΔT {} vs {gradient}",
            p.gradient
        );
        let top = temp(h / 2.0) - mean - gradient / 2.0;
        assert!((p.nonlinear[0] - top).abs() < 1e-12 && (top - 7.0 / 3.0).abs() < 1e-12);
        // The same three values read piecewise linearly: T_nl = c/4, not c/3.
        let lin = piecewise_linear(&[0.0, h / 2.0, h], &[t, m, b]);
        assert!((lin.nonlinear[0] - 7.0 / 4.0).abs() < 1e-12, "{lin:?}");
        assert!((lin.gradient - 15.0).abs() < 1e-12, "{lin:?}");
    }

    /// The nonlinear part has no resultant and no moment: for a night profile 12/16/19/20 °C at
    /// 0/0.05/0.125/0.25 m, ∫T_nl dz = ∫T_nl z dz = 0 (piecewise-linear integrals again).
    #[test]
    fn the_nonlinear_part_carries_no_force_and_no_moment() {
        let d = [0.0, 0.05, 0.125, 0.25];
        let t = [12.0, 16.0, 19.0, 20.0];
        let p = piecewise_linear(&d, &t);
        let h = 0.25;
        let nl: Vec<f64> = d
            .iter()
            .zip(&t)
            .map(|(&di, &ti)| ti - p.mean - p.gradient * (h / 2.0 - di) / h)
            .collect();
        let q = piecewise_linear(&d, &nl);
        assert!(q.mean.abs() < 1e-12 && q.gradient.abs() < 1e-12, "{q:?}");
        assert!((p.gradient - (-7.04)).abs() < 0.005, "ΔT_eq {}", p.gradient);
    }

    /// Shrinkage −200 µε over the top 50 mm of a 0.25 m slab with α = 1e-5: the moment of ε/α
    /// by quadrature against the closed form (−10.4 K).
    #[test]
    fn moisture_gradient_keeps_the_moment() {
        let (eps, hs, h, a) = (-200e-6, 0.05, 0.25, 1e-5);
        let n = 20000;
        let mut moment = 0.0;
        for i in 0..n {
            let d = hs * (i as f64 + 0.5) / n as f64;
            let strain = eps * (1.0 - d / hs);
            moment += strain / a * (h / 2.0 - d) * hs / n as f64;
        }
        let want = 12.0 * moment / (h * h);
        let got = moisture_gradient(eps, hs, h, a);
        assert!((got - want).abs() < 1e-6 * want.abs(), "{got} vs {want}");
        assert!((got + 10.4).abs() < 0.05, "{got}");
    }

    /// A quadratic profile is read through three values at the top, the middle and the bottom
    /// (the closed forms above assume them there): three depths with the middle one off H/2,
    /// and four depths, are refused naming `depths`; the three at 0, H/2, H are taken.
    #[test]
    fn a_quadratic_profile_needs_the_top_middle_and_bottom() {
        let h = 0.25;
        let spec = |depths: Vec<f64>| {
            let temps = vec![20.0; depths.len()];
            LoadSpec {
                depths: Some(depths),
                temperatures: Some(temps),
                interpolation: Some("quadratic".into()),
                ..LoadSpec::new(crate::scene::spec::LoadKind::TemperatureProfile)
            }
        };
        for depths in [vec![0.0, 0.1, h], vec![0.0, 0.125, 0.2, h]] {
            let e = profile(&spec(depths.clone()), 0, h);
            assert!(
                matches!(&e, Err(Error::Invalid { field, .. }) if field == "load[0].depths"),
                "{depths:?}: {e:?}"
            );
        }
        assert!(profile(&spec(vec![0.0, h / 2.0, h]), 0, h).is_ok());
    }
}
