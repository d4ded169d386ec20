//! The checks of a `[damage]` coefficient for the relations ([`super::pca`], [`super::mepdg`],
//! [`super::faa`]): each error names the key as `damage.<key>`. A floor: it imports only
//! [`crate::error`].

use crate::error::{Error, Result};

/// `v` if it is finite, else an error naming `damage.<key>`.
/// `v` if it is finite, else an error naming `damage.<key>`.
pub(super) fn finite(key: &str, v: f64) -> Result<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(Error::invalid(
            format!("damage.{key}"),
            format!("must be a finite number, got {v}"),
        ))
    }
}

/// `v` if it is finite and positive, else an error naming `damage.<key>`.
pub(super) fn positive(key: &str, v: f64) -> Result<f64> {
    if finite(key, v)? > 0.0 {
        Ok(v)
    } else {
        Err(Error::invalid(
            format!("damage.{key}"),
            format!("must be positive, got {v}"),
        ))
    }
}

/// `v` if it is finite and not negative, else an error naming `damage.<key>`.
pub(super) fn non_negative(key: &str, v: f64) -> Result<f64> {
    if finite(key, v)? >= 0.0 {
        Ok(v)
    } else {
        Err(Error::invalid(
            format!("damage.{key}"),
            format!("must not be negative, got {v}"),
        ))
    }
}
