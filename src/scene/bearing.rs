//! The bearing check's keys, common to every soil: `allowable_pressure` (the pressure the soil
//! may take) and `bearing_length` (the side of the square over which the contact pressure is
//! averaged before it is compared with it; default the plate's thickness, README "bearing").

use super::SceneFile;
use crate::check::finite_positive;
use crate::error::{Error, Result};
use crate::model::Groups;

/// Allowable pressure, raw (SI: r L² in N; dimensionless: in the units of patch pressures).
pub(super) fn raw_allowable(
    file: &SceneFile,
    groups: &Groups,
    physical: Option<(f64, f64)>,
) -> Result<Option<f64>> {
    let (value, field) = match (&file.foundation, &file.dimensionless) {
        (Some(f), _) => (f.allowable_pressure, "foundation.allowable_pressure"),
        (None, Some(d)) => (d.allowable_pressure, "dimensionless.allowable_pressure"),
        (None, None) => (None, ""),
    };
    value
        .map(|v| {
            let v = finite_positive(
                field,
                v,
                if physical.is_some() {
                    "Pa"
                } else {
                    "the units of patch pressures"
                },
            )?;
            Ok(match physical {
                Some((l, _)) => v * l * l,
                None => v / groups.mu,
            })
        })
        .transpose()
}

/// The side of the bearing check's averaging square in units of L: `bearing_length` (m in SI
/// scenes, units of L in dimensionless ones), or by default the plate's thickness H (SI: the
/// `[plate]`'s; dimensionless: the H/L that Δ gives with χ = 5/6), at most the plate's smaller
/// side. A given length must be finite, positive and no larger than the smaller side (E67).
pub(super) fn bearing_length(
    file: &SceneFile,
    groups: &Groups,
    physical: Option<(f64, f64)>,
) -> Result<f64> {
    // The plate's smaller side and its thickness, in units of L, and L in the key's unit.
    let smaller = 2.0 * groups.mu.min(1.0);
    let (value, field, thickness, unit_l, unit) = match (&file.plate, &file.foundation, physical) {
        (Some(p), Some(f), Some((l, _))) => (
            f.bearing_length,
            "foundation.bearing_length",
            p.thickness / l,
            l,
            " m",
        ),
        _ => (
            file.dimensionless.as_ref().and_then(|d| d.bearing_length),
            "dimensionless.bearing_length",
            (5.0 * (1.0 - groups.nu) * groups.mu * groups.delta).sqrt(),
            1.0,
            " L",
        ),
    };
    let Some(a) = value else {
        return Ok(thickness.min(smaller));
    };
    if !(a.is_finite() && a > 0.0 && a / unit_l <= smaller * (1.0 + 1e-12)) {
        return Err(Error::invalid(
            field,
            format!(
                "must be a finite, positive length no larger than the plate's smaller side ({}{unit}), got {a}: it is the side of the square over which the bearing check averages the contact pressure (leave it out for the default, the plate's thickness {}{unit})",
                round(smaller * unit_l),
                round(thickness.min(smaller) * unit_l)
            ),
        ));
    }
    Ok((a / unit_l).min(smaller))
}

/// `v` to 6 significant digits, for messages.
fn round(v: f64) -> f64 {
    format!("{v:.6e}").parse().unwrap_or(v)
}
