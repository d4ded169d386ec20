//! Checks of single numbers shared by the scene's readers ([`crate::scene`]) and the soils'
//! own keys ([`crate::foundation::soil`]), and of the ranges of rectangles: a floor below both.

use crate::error::{Error, Result};

/// `v` if it is finite and positive, else an error naming `field` and the `unit` expected.
pub(crate) fn finite_positive(field: &str, v: f64, unit: &str) -> Result<f64> {
    if !v.is_finite() {
        return Err(Error::invalid(
            field,
            format!("must be a finite number, got {v}"),
        ));
    }
    if v <= 0.0 {
        return Err(Error::invalid(
            field,
            format!("must be positive ({unit}), got {v}"),
        ));
    }
    Ok(v)
}

/// `v` if it is a Poisson's ratio, in (−1, 0.5), else an error naming `field`.
pub(crate) fn poisson(field: &str, v: f64) -> Result<f64> {
    if !v.is_finite() || v <= -1.0 || v >= 0.5 {
        return Err(Error::invalid(
            field,
            format!("Poisson's ratio must lie in (−1, 0.5), got {v}"),
        ));
    }
    Ok(v)
}

/// A range [lo, hi] of a rectangle, checked to be finite, increasing and on the plate, in unit
/// geometry.
pub(crate) fn rect_range(
    field: &str,
    r: [f64; 2],
    scale: f64,
    half: f64,
    unit: &str,
) -> Result<[f64; 2]> {
    let [a, b] = r;
    let tol = 1e-9;
    if !a.is_finite() || !b.is_finite() {
        return Err(Error::invalid(field, "range ends must be finite"));
    }
    if a >= b {
        return Err(Error::invalid(
            field,
            format!("range [{a}, {b}] must be increasing"),
        ));
    }
    let (ua, ub) = (a * scale, b * scale);
    if ua < -half * (1.0 + tol) || ub > half * (1.0 + tol) {
        return Err(Error::invalid(
            field,
            format!(
                "range [{a}, {b}] {unit} leaves the plate (±{:.6})",
                half / scale
            ),
        ));
    }
    Ok([ua.max(-half), ub.min(half)])
}

/// A temperature profile's points (a `temperature-profile` load, a climate bin): at least two
/// depths, one finite temperature each, the depths increasing from 0 (the top surface) — to
/// `bottom` when it is given (the plate's thickness), both ends to 1e-6 of the last depth.
/// `field` names the key: `field("depths")`, `field("temperatures")`.
pub(crate) fn profile(
    field: &dyn Fn(&str) -> String,
    depths: &[f64],
    temps: &[f64],
    bottom: Option<f64>,
) -> Result<()> {
    if depths.len() != temps.len() || depths.len() < 2 {
        return Err(Error::invalid(
            field("temperatures"),
            format!(
                "give one temperature per depth, at least two: {} depths, {} temperatures",
                depths.len(),
                temps.len()
            ),
        ));
    }
    if let Some(t) = temps.iter().find(|t| !t.is_finite()) {
        return Err(Error::invalid(
            field("temperatures"),
            format!("must be finite, got {t}"),
        ));
    }
    let last = depths[depths.len() - 1];
    let tol = 1e-6 * bottom.unwrap_or(last).abs();
    let ends = depths[0].abs() <= tol && bottom.is_none_or(|h| (last - h).abs() <= tol);
    if !depths.iter().all(|d| d.is_finite()) || depths.windows(2).any(|w| w[1] <= w[0]) || !ends {
        let to = bottom.map_or(String::new(), |h| {
            format!(" to the plate's thickness {h} m")
        });
        return Err(Error::invalid(
            field("depths"),
            format!("must increase from 0 (the top surface){to}, got {depths:?}"),
        ));
    }
    Ok(())
}
