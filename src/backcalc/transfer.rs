//! A joint drop's load transfer: the deflection LTE across the template's joint nearest the
//! drop, and the slab-bending correction B that the same two sensors read on the template's
//! slab without that joint, at the fitted moduli ([`load_transfer`]).

use super::basins::{Drop, Location};
use super::fit::{model_basin, prepare, Fit, FitOptions, Unknown};
use super::template::nearest_joint;
use crate::error::Result;
use crate::foundation::soil::KeyValue;
use crate::monitor::Monitor;
use crate::scene::SceneFile;

/// A joint drop's load transfer across the joint (see [`load_transfer`]).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct LoadTransfer {
    /// The joint (its name, or `joint[i]`).
    pub joint: String,
    /// The offset of the first sensor across the joint, m.
    pub sensor: f64,
    /// The deflection LTE: that sensor's deflection over the loaded one's.
    pub lte: f64,
    /// The slab-bending correction B = w(0)/w(sensor) of the same slab without the joint.
    pub bending: f64,
    /// LTE · B: 1 for a joint that transfers as the slab itself.
    pub corrected: f64,
    /// The LTE of the fitted model's basin (None without a fit).
    pub model: Option<f64>,
}

/// The load transfer of a joint drop (`joint-approach`, `joint-leave`) across the template's
/// joint nearest it: the deflection LTE of the first sensor across the joint over the loaded
/// sensor, and that LTE times the slab-bending correction B = w(0)/w(s) — the ratio the same
/// two sensors read with no joint, computed on the template's model without that joint at the
/// fitted moduli (the template's where none are fitted) — which the literature takes from an
/// interior drop's d₀/d₁₂ instead (AASHTO 1993, Part III). None for other drops, or a sensor
/// line that does not cross the joint.
pub fn load_transfer(
    template: &SceneFile,
    drop: &Drop,
    fit: Option<&Fit>,
    options: &FitOptions,
    monitor: &Monitor<'_>,
) -> Result<Option<LoadTransfer>> {
    if !matches!(
        drop.location,
        Location::JointApproach | Location::JointLeave
    ) {
        return Ok(None);
    }
    drop.check()?;
    let quiet = monitor.quiet();
    let forward = prepare(
        template,
        drop,
        &FitOptions {
            unknowns: vec![Unknown::Slab],
            ..options.clone()
        },
        &quiet,
    )?;
    let Some(at) = drop.at else { return Ok(None) };
    let Some((k, joint)) = nearest_joint(template, at) else {
        return Ok(None);
    };
    let side = |p: [f64; 2]| match (joint.x, joint.y) {
        (Some(x), _) => (p[0] - x).signum(),
        (None, Some(y)) => (p[1] - y).signum(),
        _ => 0.0,
    };
    let loaded = side(at);
    let Some(j) = forward.sensors.iter().position(|&p| side(p) == -loaded) else {
        return Ok(None);
    };
    let d = &drop.basin.deflections;
    // The slab without the joint, at the fitted moduli.
    let mut whole = template.clone();
    whole.joint.remove(k);
    if let Some(f) = fit {
        for e in &f.estimates {
            match e.unknown {
                Unknown::Subgrade => {
                    if let Some(soil) = whole.foundation.as_mut() {
                        let key = e.key.trim_start_matches("foundation.").to_string();
                        soil.soil.insert(key, KeyValue::Number(e.value));
                    }
                }
                Unknown::Slab => {
                    if let Some(p) = whole.plate.as_mut() {
                        p.youngs_modulus = e.value;
                    }
                }
                Unknown::Void | Unknown::Joint => {}
            }
        }
    }
    let plain = FitOptions {
        unknowns: vec![Unknown::Slab],
        ..options.clone()
    };
    let w = model_basin(&whole, drop, &plain, monitor)?;
    let (lte, bending) = (d[j] / d[0], w[0] / w[j]);
    Ok(Some(LoadTransfer {
        joint: joint.name.clone().unwrap_or_else(|| format!("joint[{k}]")),
        sensor: drop.basin.offsets[j],
        lte,
        bending,
        corrected: lte * bending,
        model: fit.map(|f| f.fitted[j] / f.fitted[0]),
    }))
}
