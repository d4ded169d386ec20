//! Validation of the load-related sections of a scene: `[[load]]` with its cases, `[[void]]`,
//! the Winkler zones — in unit geometry with magnitudes not yet
//! divided by P, since every combination has its own P ([`super::validate`] does that).

use super::spec::{Coord, LoadKind, LoadSpec};
use super::temperature::Thermal;
use super::SceneFile;
use crate::check::{finite_positive, rect_range};
use crate::error::{Error, Result};
use crate::model::{Groups, Load, LoadReference, Void, Zone};

/// A load as written, in unit-system geometry, its magnitude not yet divided by P: newtons (SI
/// scenes: forces in N, patches in N per unit of (x/L)(y/L), lines in N per unit of length/L,
/// temperatures as D κ in N) or the loads' own relative unit (dimensionless scenes).
#[derive(Debug, Clone)]
pub(super) struct RawLoad {
    pub(super) load: Load,
    pub(super) case: String,
    /// The `[[load]]` entry it comes from (an axle or gear gives one per tire).
    pub(super) source: usize,
}

/// Name of the case of loads that name none.
pub const DEFAULT_CASE: &str = "default";

/// `[[load]]`: every load in unit geometry with its raw magnitude and its case; `plate` the
/// sides in metres (SI scenes).
pub(super) fn raw_loads(
    specs: &[LoadSpec],
    groups: &Groups,
    physical: Option<(f64, f64)>,
    thermal: Option<Thermal>,
    scale_xy: [f64; 2],
    plate: [f64; 2],
) -> Result<Vec<RawLoad>> {
    let mu = groups.mu;
    let mut loads = Vec::with_capacity(specs.len());
    if specs.is_empty() {
        return Err(Error::invalid(
            "load",
            "no [[load]] entries: add at least one point, patch, uniform or line load",
        ));
    }
    let (hx, hy) = (1.0, mu);
    let tol = 1e-9;
    let coord_unit = if physical.is_some() {
        "m"
    } else {
        "s or t, in [−1, 1]"
    };
    // Physical pressures are per m², unit geometry has areas in L²; lines per m, lengths in L.
    let (area_scale, length_scale) = match physical {
        Some((l, _)) => (l * l, l),
        None => (1.0 / mu, 1.0),
    };
    for (k, l) in specs.iter().enumerate() {
        let field = |name: &str| format!("load[{k}].{name}");
        let value = |name: &str, c: Option<Coord>, scale: f64, half: f64| -> Result<f64> {
            match c {
                Some(Coord::Value(v)) => {
                    if !v.is_finite() {
                        return Err(Error::invalid(
                            field(name),
                            format!("must be finite, got {v}"),
                        ));
                    }
                    let u = v * scale;
                    if u.abs() > half * (1.0 + tol) {
                        return Err(Error::invalid(
                            field(name),
                            format!(
                                "{v} {coord_unit} lies outside the plate (|{name}| ≤ {:.6})",
                                half / scale
                            ),
                        ));
                    }
                    Ok(u.clamp(-half, half))
                }
                Some(Coord::Range(_)) => Err(Error::invalid(
                    field(name),
                    "a point load takes a single coordinate, not a range",
                )),
                None => Err(Error::invalid(field(name), "missing: the load's position")),
            }
        };
        let range = |name: &str, c: Option<Coord>, scale: f64, half: f64| -> Result<[f64; 2]> {
            match c {
                Some(Coord::Range(r)) => rect_range(&field(name), r, scale, half, coord_unit),
                Some(Coord::Value(_)) => Err(Error::invalid(
                    field(name),
                    "a patch load takes a range [lo, hi]",
                )),
                None => Err(Error::invalid(
                    field(name),
                    "missing: the patch's extent [lo, hi]",
                )),
            }
        };
        let magnitude = |name: &str, v: Option<f64>| -> Result<f64> {
            let v = v.ok_or_else(|| Error::invalid(field(name), "missing"))?;
            if !v.is_finite() {
                return Err(Error::invalid(
                    field(name),
                    format!("must be finite, got {v}"),
                ));
            }
            Ok(v)
        };
        let forbid = |name: &str, present: bool, kind: &str| -> Result<()> {
            if present {
                Err(Error::invalid(
                    field(name),
                    format!("does not apply to a {kind} load"),
                ))
            } else {
                Ok(())
            }
        };
        let kind_name = l.kind.name();
        if let Some(key) = l.foreign_key() {
            forbid(key, true, kind_name)?;
        }
        // Fields that belong to other kinds.
        let line = matches!(l.kind, LoadKind::Line);
        let temp = matches!(
            l.kind,
            LoadKind::Temperature
                | LoadKind::TemperatureProfile
                | LoadKind::Moisture
                | LoadKind::BuiltInCurl
                | LoadKind::Axle
                | LoadKind::Gear
        );
        forbid("from", l.from.is_some() && !line, kind_name)?;
        forbid("to", l.to.is_some() && !line, kind_name)?;
        forbid(
            "force_per_length",
            l.force_per_length.is_some() && !line,
            kind_name,
        )?;
        forbid("difference", l.difference.is_some() && !temp, kind_name)?;
        forbid("curvature", l.curvature.is_some() && !temp, kind_name)?;
        if line || matches!(l.kind, LoadKind::Temperature) {
            forbid("x", l.x.is_some(), kind_name)?;
            forbid("y", l.y.is_some(), kind_name)?;
            forbid("force", l.force.is_some(), kind_name)?;
            forbid("pressure", l.pressure.is_some(), kind_name)?;
        }
        let case = match &l.case {
            Some(c) if c.trim().is_empty() => {
                return Err(Error::invalid(
                    field("case"),
                    "is empty: name the case (e.g. \"dead\") or leave it out for \"default\"",
                ))
            }
            Some(c) => c.trim().to_string(),
            None => DEFAULT_CASE.to_string(),
        };
        let load = match l.kind {
            LoadKind::TemperatureProfile
            | LoadKind::Moisture
            | LoadKind::BuiltInCurl
            | LoadKind::Axle
            | LoadKind::Gear => {
                let produced = match l.kind {
                    LoadKind::Axle | LoadKind::Gear => super::vehicles::patches(
                        l,
                        k,
                        physical.is_some(),
                        crate::vehicle::Frame {
                            scale_xy,
                            half: [hx, hy],
                            area_scale,
                            plate,
                        },
                    )?,
                    _ => super::temperature::loads(l, k, thermal, physical.map(|p| p.0))?,
                };
                for load in produced {
                    loads.push(RawLoad {
                        load,
                        case: case.clone(),
                        source: k,
                    });
                }
                continue;
            }
            LoadKind::Point => {
                forbid("pressure", l.pressure.is_some(), "point")?;
                Load::Point {
                    x: value("x", l.x, scale_xy[0], hx)?,
                    y: value("y", l.y, scale_xy[1], hy)?,
                    force: magnitude("force", l.force)?,
                }
            }
            LoadKind::Patch => {
                forbid("force", l.force.is_some(), "patch")?;
                Load::Patch {
                    x: range("x", l.x, scale_xy[0], hx)?,
                    y: range("y", l.y, scale_xy[1], hy)?,
                    pressure: magnitude("pressure", l.pressure)? * area_scale,
                }
            }
            LoadKind::Circle => {
                let (cx, cy) = (
                    value("x", l.x, scale_xy[0], hx)?,
                    value("y", l.y, scale_xy[1], hy)?,
                );
                let radius = match l.radius {
                    Some(r) if r.is_finite() && r > 0.0 => r,
                    Some(r) => {
                        return Err(Error::invalid(
                            field("radius"),
                            format!("must be a positive length, got {r}"),
                        ))
                    }
                    None => {
                        return Err(Error::invalid(
                            field("radius"),
                            "missing: the disk's radius",
                        ))
                    }
                };
                let area = std::f64::consts::PI * radius * radius;
                let pressure = match (l.force, l.pressure) {
                    (Some(_), Some(_)) => {
                        return Err(Error::invalid(
                            field("pressure"),
                            "give the disk's force or its pressure, not both",
                        ))
                    }
                    (Some(_), None) => magnitude("force", l.force)? / area,
                    (None, _) => magnitude("pressure", l.pressure)?,
                };
                for band in circle_bands(radius) {
                    let x = [cx + band.x[0] * scale_xy[0], cx + band.x[1] * scale_xy[0]];
                    // A disk in both directions: the radius in the plate's unit of x (m, or L in a
                    // dimensionless scene, whose y is t = y / (μL)).
                    let y = [cy + band.y[0] * scale_xy[0], cy + band.y[1] * scale_xy[0]];
                    if x[0] < -hx * (1.0 + tol)
                        || x[1] > hx * (1.0 + tol)
                        || y[0] < -hy * (1.0 + tol)
                        || y[1] > hy * (1.0 + tol)
                    {
                        return Err(Error::invalid(
                            field("radius"),
                            format!("the disk of radius {radius} about its centre reaches beyond the plate's edge: move it inward or make it smaller"),
                        ));
                    }
                    loads.push(RawLoad {
                        load: Load::Patch {
                            x: [x[0].max(-hx), x[1].min(hx)],
                            y: [y[0].max(-hy), y[1].min(hy)],
                            pressure: pressure * area_scale,
                        },
                        case: case.clone(),
                        source: k,
                    });
                }
                continue;
            }
            LoadKind::Uniform => {
                forbid("force", l.force.is_some(), "uniform")?;
                forbid("x", l.x.is_some(), "uniform")?;
                forbid("y", l.y.is_some(), "uniform")?;
                Load::Patch {
                    x: [-hx, hx],
                    y: [-hy, hy],
                    pressure: magnitude("pressure", l.pressure)? * area_scale,
                }
            }
            LoadKind::Line => {
                let end = |name: &str, p: Option<[f64; 2]>| -> Result<[f64; 2]> {
                    let p = p.ok_or_else(|| {
                        Error::invalid(field(name), "missing: the line's end point [x, y]")
                    })?;
                    let x = value(name, Some(Coord::Value(p[0])), scale_xy[0], hx)?;
                    let y = value(name, Some(Coord::Value(p[1])), scale_xy[1], hy)?;
                    Ok([x, y])
                };
                let (from, to) = (end("from", l.from)?, end("to", l.to)?);
                if (to[0] - from[0]).hypot(to[1] - from[1]) <= 1e-9 {
                    return Err(Error::invalid(
                        field("to"),
                        "the line's ends coincide: give a segment of non-zero length (or a point load)",
                    ));
                }
                Load::Line {
                    from,
                    to,
                    force_per_length: magnitude("force_per_length", l.force_per_length)?
                        * length_scale,
                }
            }
            LoadKind::Temperature => {
                let curvature = match (thermal, l.difference, l.curvature) {
                    (Some(th), Some(dt), None) => {
                        let dt = magnitude("difference", Some(dt))?;
                        let alpha = th.alpha.ok_or_else(|| {
                            Error::invalid(
                                "plate.thermal_expansion",
                                format!("missing: load[{k}] is a temperature load; give the plate's coefficient of thermal expansion in 1/K (concrete ≈ 1.0e-5)"),
                            )
                        })?;
                        th.rigidity * alpha * dt / th.thickness
                    }
                    (Some(_), _, Some(_)) => {
                        return Err(Error::invalid(
                            field("curvature"),
                            "belongs to dimensionless scenes; an SI scene gives `difference` in K",
                        ))
                    }
                    (None, Some(_), _) => {
                        return Err(Error::invalid(
                            field("difference"),
                            "belongs to SI scenes; a dimensionless scene gives `curvature` (∂²V/∂s² of free curling, in the loads' force unit)",
                        ))
                    }
                    (None, None, Some(c)) => magnitude("curvature", Some(c))?,
                    (_, None, None) => {
                        return Err(Error::invalid(
                            field("difference"),
                            "missing: the temperature difference top minus bottom, K (dimensionless scenes: `curvature`)",
                        ))
                    }
                };
                Load::Temperature { curvature }
            }
        };
        loads.push(RawLoad {
            load,
            case,
            source: k,
        });
    }
    Ok(loads)
}

/// Loads in units of P, and P (a quarter of the resultant, in the raw unit), for one set of
/// factored loads; `what` names the set in errors.
pub(super) fn normalise(
    raw: Vec<(usize, Load)>,
    what: &str,
) -> Result<(Vec<Load>, f64, LoadReference)> {
    let total: f64 = raw.iter().map(|(_, l)| l.resultant()).sum();
    let gross: f64 = raw.iter().map(|(_, l)| l.resultant().abs()).sum();
    let moments: Vec<f64> = raw
        .iter()
        .filter_map(|(_, l)| match l {
            Load::Temperature { curvature } => Some(*curvature),
            _ => None,
        })
        .collect();
    if !total.is_finite() || !gross.is_finite() || moments.iter().any(|m| !m.is_finite()) {
        return Err(Error::invalid(
            "load",
            format!(
                "{what}the load magnitudes overflow when added up: check their units (N and Pa)"
            ),
        ));
    }
    // Loads that add up to zero (to round-off of their sum) have no paper's P; a bonded plate
    // still carries them (curling, a self-equilibrated pair), against a stated reference. The
    // method decides whether such a model can be solved: `validate::problem` refuses it for
    // unbonded contact.
    let tiny = f64::MIN_POSITIVE;
    let (p_force, reference) = if total.abs() > 1e-12 * gross.max(tiny) {
        (total.abs() / 4.0, LoadReference::NetLoad)
    } else if gross / 8.0 >= tiny {
        // Half the gross load acts downward.
        (gross / 8.0, LoadReference::DownwardLoad)
    } else {
        let net: f64 = moments.iter().sum();
        let largest = moments.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
        let p = if net.abs() > 1e-12 * largest {
            net.abs()
        } else {
            largest
        };
        if p < tiny {
            return Err(Error::invalid(
                "load",
                format!("{what}the loads add up to zero (every magnitude is 0, or below 1e-308): give a load with a non-zero force, pressure or temperature difference"),
            ));
        }
        (p, LoadReference::ThermalMoment)
    };
    let mut loads = raw;
    for (k, l) in loads.iter_mut() {
        if let Load::FaceStress { top, bottom } = l {
            // Stresses of a temperature profile, raw σ L² in N: finite once finite in Pa.
            *top /= p_force;
            *bottom /= p_force;
            continue;
        }
        let (v, name) = match l {
            Load::FaceStress { .. } => continue,
            Load::Point { force, .. } => (force, "force"),
            Load::Patch { pressure, .. } => (pressure, "pressure"),
            Load::Line {
                force_per_length, ..
            } => (force_per_length, "force_per_length"),
            Load::Temperature { curvature } => (curvature, "difference"),
        };
        *v /= p_force;
        // A huge pressure on a vanishing patch has a finite resultant, but the pressure itself,
        // in units of the resultant per unit area, can overflow.
        if !v.is_finite() {
            return Err(Error::invalid(
                format!("load[{k}].{name}"),
                format!("{what}the magnitude overflows when expressed per unit of the total load: the patch or line is too small for its load (check its extent and units)"),
            ));
        }
    }
    Ok((
        loads.into_iter().map(|(_, l)| l).collect(),
        p_force,
        reference,
    ))
}

/// A void as written: unit geometry, depth raw (SI: d D / L² in N).
#[derive(Debug, Clone, Copy)]
pub(super) struct RawVoid {
    x: [f64; 2],
    y: [f64; 2],
    depth: f64,
    /// Depth as written (m or the scene's unit), for messages.
    written: f64,
}

/// `[[void]]`: rectangles on the plate with a positive depth.
pub(super) fn raw_voids(
    file: &SceneFile,
    groups: &Groups,
    physical: Option<(f64, f64)>,
    scale_xy: [f64; 2],
) -> Result<Vec<RawVoid>> {
    let unit = if physical.is_some() { "m" } else { "s or t" };
    let mut out = Vec::new();
    for (k, v) in file.void.iter().enumerate() {
        let x = rect_range(&format!("void[{k}].x"), v.x, scale_xy[0], 1.0, unit)?;
        let y = rect_range(&format!("void[{k}].y"), v.y, scale_xy[1], groups.mu, unit)?;
        let d = finite_positive(
            &format!("void[{k}].depth"),
            v.depth,
            if physical.is_some() {
                "m"
            } else {
                "the loads' unit of V"
            },
        )?;
        let depth = match physical {
            Some((l, rigidity)) => d * rigidity / (l * l),
            None => d,
        };
        out.push(RawVoid {
            x,
            y,
            depth,
            written: d,
        });
    }
    for a in 0..out.len() {
        for b in 0..a {
            if overlap(out[a].x, out[a].y, out[b].x, out[b].y) {
                return Err(Error::invalid(
                    format!("void[{a}]"),
                    format!("overlaps void[{b}]: give non-overlapping rectangles (split them where the depth changes)"),
                ));
            }
        }
    }
    Ok(out)
}

fn overlap(xa: [f64; 2], ya: [f64; 2], xb: [f64; 2], yb: [f64; 2]) -> bool {
    let tol = 1e-12;
    xa[0] < xb[1] - tol && xb[0] < xa[1] - tol && ya[0] < yb[1] - tol && yb[0] < ya[1] - tol
}

/// Deepest void, in multiples of the mean settlement under the loads, that is accepted: a void
/// that deep never closes, and deeper ones change nothing.
pub const MAX_VOID_DEPTH_RATIO: f64 = 1e3;

/// Voids of one load set in the unit system, checked against the mean settlement under it:
/// Winkler q/K, half-space ≈ 3 (1 − ν_s²) F / (π E_s √A) (the mean settlement of a flexible
/// uniform square load is 0.95 q B (1 − ν_s²)/E_s).
pub(super) fn voids_for(
    raw: &[RawVoid],
    groups: &Groups,
    p_force: f64,
    physical: Option<(f64, f64)>,
    what: &str,
) -> Result<Vec<Void>> {
    let c = groups.mu * groups.gamma;
    let settlement = groups.soil.settlement(c, groups.mu);
    raw.iter()
        .enumerate()
        .map(|(k, v)| {
            let depth = v.depth / p_force;
            if depth > MAX_VOID_DEPTH_RATIO * settlement {
                let (scale, unit) = match physical {
                    Some((l, d)) => (p_force * l * l / d, "m"),
                    None => (p_force, "(loads' unit of V)"),
                };
                return Err(Error::invalid(
                    format!("void[{k}].depth"),
                    format!(
                        "{what}{} {unit} is {:.0} times the mean settlement under the loads ({:.3e} {unit}): a void that deep never closes and acts like one {MAX_VOID_DEPTH_RATIO:.0} times the settlement; check the units or give at most {:.3e} {unit}",
                        v.written,
                        depth / settlement,
                        settlement * scale,
                        MAX_VOID_DEPTH_RATIO * settlement * scale
                    ),
                ));
            }
            Ok(Void {
                x: v.x,
                y: v.y,
                depth,
            })
        })
        .collect()
}

/// Range of a zone's compliance ratio (subgrade modulus over the zone's): beyond 1e6 either way
/// the spring system loses its digits (a zone 1e30 times stiffer breaks the Cholesky factor).
pub const ZONE_RATIO_RANGE: [f64; 2] = [1e-6, 1e6];

/// `[[foundation.zone]]` / `[[dimensionless.zone]]`: Winkler patches with their compliance
/// ratio (reference modulus over the zone's).
pub(super) fn zones(file: &SceneFile, groups: &Groups, scale_xy: [f64; 2]) -> Result<Vec<Zone>> {
    let (specs, reference, prefix, physical) = match (&file.foundation, &file.dimensionless) {
        (Some(f), _) => (&f.zone, f.number("modulus"), "foundation.zone", true),
        (None, Some(d)) => (&d.zone, Some(groups.gamma), "dimensionless.zone", false),
        (None, None) => return Ok(Vec::new()),
    };
    if specs.is_empty() {
        return Ok(Vec::new());
    }
    if !groups.foundation().is_local() {
        return Err(Error::invalid(
            format!("{prefix}[0]"),
            "zones of another modulus apply to a Winkler subgrade only; a half-space, a Pasternak soil or an elastic layer is homogeneous (model the soft patch with a Winkler foundation, or leave the zone out)",
        ));
    }
    let unit = if physical { "m" } else { "s or t" };
    let mut out: Vec<Zone> = Vec::new();
    for (k, z) in specs.iter().enumerate() {
        let field = |n: &str| format!("{prefix}[{k}].{n}");
        let x = rect_range(&field("x"), z.x, scale_xy[0], 1.0, unit)?;
        let y = rect_range(&field("y"), z.y, scale_xy[1], groups.mu, unit)?;
        let ratio = match (physical, z.modulus, z.gamma) {
            (true, Some(m), None) => {
                let m = finite_positive(&field("modulus"), m, "N/m³")?;
                reference.unwrap_or(m) / m
            }
            (false, None, Some(g)) => finite_positive(&field("gamma"), g, "Γ_w of the zone")? / groups.gamma,
            (true, _, _) => {
                return Err(Error::invalid(
                    field("modulus"),
                    "give the zone's Winkler modulus in N/m³ (and no `gamma`, which belongs to dimensionless scenes)",
                ))
            }
            (false, _, _) => {
                return Err(Error::invalid(
                    field("gamma"),
                    "give the zone's Γ_w (and no `modulus`, which belongs to SI scenes)",
                ))
            }
        };
        let [lo, hi] = ZONE_RATIO_RANGE;
        if !(lo..=hi).contains(&ratio) {
            let name = if physical { "modulus" } else { "gamma" };
            return Err(Error::invalid(
                field(name),
                format!("the zone is {:.1e} times as stiff as the rest of the subgrade; give a modulus within a factor {hi:.0e} of it (a softer zone than that carries nothing: model it as a void)", 1.0 / ratio),
            ));
        }
        for (b, o) in out.iter().enumerate() {
            if overlap(x, y, o.x, o.y) {
                return Err(Error::invalid(
                    format!("{prefix}[{k}]"),
                    format!("overlaps {prefix}[{b}]: give non-overlapping rectangles"),
                ));
            }
        }
        out.push(Zone {
            x,
            y,
            compliance_ratio: ratio,
        });
    }
    Ok(out)
}

/// Bands across a disk: a disk's load becomes this many strips, each the height 2r/N of its band
/// and as wide as the band's area over its height, centred on the disk's axis.
pub const CIRCLE_BANDS: usize = 32;

/// One band of a disk of radius `r` about the origin, as the rectangle that carries its load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Band {
    /// [x0, x1] about the disk's centre, in the disk's unit.
    pub x: [f64; 2],
    /// [y0, y1].
    pub y: [f64; 2],
}

/// The disk of radius `r` as [`CIRCLE_BANDS`] rectangles of the disk's own pressure: the band
/// between y0 and y1 carries exactly the disk's area in that band (A(y) = y√(r² − y²) +
/// r² asin(y/r) from the centre), spread uniformly over its width. The total force, its centre
/// and the load's distribution across y (band by band) are those of the disk exactly; only
/// the distribution along x inside a band is the rectangle's, a difference of at most the
/// band's chord — 1/16 of the radius near the centre — whose effect on the deflection a
/// radius away is of the order of (r/N)² of the load's.
pub fn circle_bands(r: f64) -> Vec<Band> {
    let n = CIRCLE_BANDS;
    let below = |y: f64| -> f64 {
        let y = y.clamp(-r, r);
        y * (r * r - y * y).max(0.0).sqrt() + r * r * (y / r).clamp(-1.0, 1.0).asin()
    };
    (0..n)
        .map(|i| {
            let y0 = -r + 2.0 * r * i as f64 / n as f64;
            let y1 = -r + 2.0 * r * (i + 1) as f64 / n as f64;
            let area = below(y1) - below(y0);
            let half = area / (y1 - y0) / 2.0;
            Band {
                x: [-half, half],
                y: [y0, y1],
            }
        })
        .collect()
}
