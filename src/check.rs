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
