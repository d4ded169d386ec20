//! Checks of single numbers shared by the scene's readers ([`crate::scene`]) and the soils'
//! own keys ([`crate::foundation::soil`]): a floor below both.

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
