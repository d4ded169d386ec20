//! Vehicle loads (`kind = "axle"`, `"gear"`): a truck's axle group or an aircraft gear placed by
//! a reference point and a heading, each tire a uniform pressure over a rectangle of its contact
//! area (its load over the tire pressure).
//!
//! Tire prints follow the Portland Cement Association's rectangle (PCA 1984; Huang, *Pavement
//! Analysis and Design*, 2004, §4.4): the print of area A is 0.8712 L along the travel by 0.6 L
//! across, L = √(A/0.5227) — or a square of the same area (`contact_shape = "square"`, and for
//! headings that are not a multiple of 90°, since the plate's load patches are rectangles along
//! its axes).

use super::spec::LoadSpec;
use crate::error::{Error, Result};
use crate::model::Load;

/// The plate in unit geometry, as the tire prints need it: metres to unit coordinates along x
/// and y, the half sides, and metres² to unit areas.
pub(super) struct Geometry {
    pub(super) scale_xy: [f64; 2],
    pub(super) half: [f64; 2],
    pub(super) area_scale: f64,
}

/// The patches of an `axle` or `gear` entry `k` (SI scenes only): one per tire, in unit
/// geometry, its pressure raw (N per unit area).
pub(super) fn patches(l: &LoadSpec, k: usize, si: bool, g: &Geometry) -> Result<Vec<Load>> {
    let field = |name: &str| format!("load[{k}].{name}");
    if !si {
        return Err(Error::invalid(
            field("kind"),
            format!(
                "kind = \"{}\" belongs to SI scenes ([plate] and [foundation]): its tires are given in metres and newtons",
                l.kind.name()
            ),
        ));
    }
    let axle = matches!(l.kind, super::spec::LoadKind::Axle);
    let mut out = Vec::new();
    for t in tires(l, k, axle)? {
        let to_unit = |centre: f64, side: f64, axis: usize| -> Result<[f64; 2]> {
            let (lo, hi) = (centre - side / 2.0, centre + side / 2.0);
            let (ulo, uhi) = (lo * g.scale_xy[axis], hi * g.scale_xy[axis]);
            let half = g.half[axis];
            if ulo < -half * (1.0 + 1e-9) || uhi > half * (1.0 + 1e-9) {
                return Err(Error::invalid(
                    field(if axis == 0 { "x" } else { "y" }),
                    format!(
                        "the tire print at ({:.3}, {:.3}) m reaches [{lo:.3}, {hi:.3}] m, off the plate (±{:.3} m): move the reference point or turn the heading",
                        t.centre[0],
                        t.centre[1],
                        half / g.scale_xy[axis]
                    ),
                ));
            }
            Ok([ulo.max(-half), uhi.min(half)])
        };
        let x = to_unit(t.centre[0], t.size[0], 0)?;
        let y = to_unit(t.centre[1], t.size[1], 1)?;
        out.push(Load::Patch {
            x,
            y,
            pressure: t.force / (t.size[0] * t.size[1]) * g.area_scale,
        });
    }
    Ok(out)
}

/// A bundled configuration: name, what it is, where its numbers come from, and the keys it sets.
pub struct Standard {
    /// Name (`standard = "…"`).
    pub name: &'static str,
    /// What it is.
    pub description: &'static str,
    /// Where its numbers come from.
    pub source: &'static str,
    /// Axle (true) or gear.
    pub axle: bool,
    configuration: &'static str,
    axle_load: f64,
    axle_spacing: f64,
    track: f64,
    dual_spacing: f64,
    wheels: &'static [[f64; 2]],
    wheel_load: f64,
    tire_pressure: f64,
}

/// The bundled configurations.
pub const STANDARDS: &[Standard] = &[
    Standard {
        name: "esal-single-dual",
        description: "80 kN (18 kip) single axle with dual tires: duals 0.305 m apart, wheel sets 1.83 m apart, 827 kPa",
        source: "AASHTO 18-kip equivalent single axle load; 12 in dual spacing and 120 psi tire pressure as AASHTOWare Pavement ME's defaults; 72 in between dual-set centres as Yoder & Witczak (1975) and Huang (2004)",
        axle: true,
        configuration: "single",
        axle_load: 80.0e3,
        axle_spacing: 0.0,
        track: 1.83,
        dual_spacing: 0.3048,
        wheels: &[],
        wheel_load: 0.0,
        tire_pressure: 827.4e3,
    },
    Standard {
        name: "tandem-dual",
        description: "151 kN (34 kip) tandem of two axles 1.31 m apart, dual tires as the ESAL axle",
        source: "34 kip: the US federal tandem limit (23 CFR 658.17); 51.6 in axle spacing as AASHTOWare Pavement ME's default",
        axle: true,
        configuration: "tandem",
        axle_load: 75.6e3,
        axle_spacing: 1.311,
        track: 1.83,
        dual_spacing: 0.3048,
        wheels: &[],
        wheel_load: 0.0,
        tire_pressure: 827.4e3,
    },
    Standard {
        name: "tridem-dual",
        description: "187 kN (42 kip) tridem of three axles 1.25 m apart, dual tires as the ESAL axle",
        source: "42 kip from the federal bridge formula for three axles 8.2 ft apart; 49.2 in axle spacing as AASHTOWare Pavement ME's default",
        axle: true,
        configuration: "tridem",
        axle_load: 62.27e3,
        axle_spacing: 1.25,
        track: 1.83,
        dual_spacing: 0.3048,
        wheels: &[],
        wheel_load: 0.0,
        tire_pressure: 827.4e3,
    },
    Standard {
        name: "b737-800-main",
        description: "one main gear of a Boeing 737-800 at 79.2 t: two wheels 0.864 m apart, 184.6 kN each, 1.41 MPa",
        source: "Boeing 737 airplane characteristics for airport planning (D6-58325-6): 174 700 lb maximum taxi weight, 95 % on the two main gears (FAA AC 150/5320-6), H44.5x16.5-21 tires at 204 psi, 34 in between the wheels of a gear",
        axle: false,
        configuration: "",
        axle_load: 0.0,
        axle_spacing: 0.0,
        track: 0.0,
        dual_spacing: 0.0,
        wheels: &[[0.0, -0.432], [0.0, 0.432]],
        wheel_load: 184.56e3,
        tire_pressure: 1.4065e6,
    },
];

/// One tire's print on the plate: its centre (m), its sides along x and y (m) and its load (N).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tire {
    /// Centre (x, y), m.
    pub centre: [f64; 2],
    /// Sides along x and y, m.
    pub size: [f64; 2],
    /// Load, N.
    pub force: f64,
}

/// The tires of an `axle` or `gear` entry `k`, in metres about the plate's centre.
pub fn tires(spec: &LoadSpec, k: usize, axle: bool) -> Result<Vec<Tire>> {
    let field = |n: &str| format!("load[{k}].{n}");
    let standard = match &spec.standard {
        Some(name) => {
            let s = STANDARDS.iter().find(|s| s.name == name).ok_or_else(|| {
                let names: Vec<&str> = STANDARDS.iter().map(|s| s.name).collect();
                Error::invalid(
                    field("standard"),
                    format!(
                        "no bundled configuration `{name}`; they are: {}",
                        names.join(", ")
                    ),
                )
            })?;
            if s.axle != axle {
                let kind = if s.axle { "axle" } else { "gear" };
                return Err(Error::invalid(
                    field("standard"),
                    format!("`{name}` is a configuration of kind = \"{kind}\""),
                ));
            }
            Some(s)
        }
        None => None,
    };
    let positive = |name: &str, given: Option<f64>, default: Option<f64>| -> Result<f64> {
        let v = given.or(default).ok_or_else(|| {
            Error::invalid(field(name), "missing (or give a `standard` configuration)")
        })?;
        if v.is_finite() && v > 0.0 {
            Ok(v)
        } else {
            Err(Error::invalid(
                field(name),
                format!("must be a finite positive number, got {v}"),
            ))
        }
    };
    let coordinate = |name: &str, given: Option<f64>| -> Result<f64> {
        let v = given.ok_or_else(|| {
            Error::invalid(
                field(name),
                "missing: the reference point (the centre of the axle group or gear), m",
            )
        })?;
        if v.is_finite() {
            Ok(v)
        } else {
            Err(Error::invalid(
                field(name),
                format!("must be finite, got {v}"),
            ))
        }
    };
    let x0 = coordinate("x", spec.x.as_ref().and_then(|c| c.value()))?;
    let y0 = coordinate("y", spec.y.as_ref().and_then(|c| c.value()))?;
    let heading = spec.heading.unwrap_or(0.0);
    if !heading.is_finite() {
        return Err(Error::invalid(
            field("heading"),
            format!("must be finite, got {heading}"),
        ));
    }
    let pressure = positive(
        "tire_pressure",
        spec.tire_pressure,
        standard.map(|s| s.tire_pressure),
    )?;
    // (along, across) positions of the tires in the vehicle's frame, and the load of each.
    let mut wheels: Vec<([f64; 2], f64)> = Vec::new();
    if axle {
        let configuration = spec
            .configuration
            .as_deref()
            .or(standard.map(|s| s.configuration))
            .unwrap_or("single");
        let axles = match configuration {
            "single" => 1,
            "tandem" => 2,
            "tridem" => 3,
            other => {
                return Err(Error::invalid(
                    field("configuration"),
                    format!("`{other}` is not one of single, tandem, tridem"),
                ))
            }
        };
        let load = positive("axle_load", spec.axle_load, standard.map(|s| s.axle_load))?;
        let spacing = if axles > 1 {
            positive(
                "axle_spacing",
                spec.axle_spacing,
                standard.map(|s| s.axle_spacing).filter(|&v| v > 0.0),
            )?
        } else {
            0.0
        };
        let track = positive("track", spec.track, standard.map(|s| s.track))?;
        let dual = match spec.tires.as_deref() {
            Some("single") => false,
            Some("dual") | None => spec.tires.is_some() || standard.is_some(),
            Some(other) => {
                return Err(Error::invalid(
                    field("tires"),
                    format!("`{other}` is not one of single, dual"),
                ))
            }
        };
        let dual_spacing = if dual {
            positive(
                "dual_spacing",
                spec.dual_spacing,
                standard.map(|s| s.dual_spacing),
            )?
        } else {
            0.0
        };
        if dual && dual_spacing >= track {
            return Err(Error::invalid(
                field("dual_spacing"),
                format!("{dual_spacing} m is not smaller than the track {track} m: the two dual sets would overlap"),
            ));
        }
        let per_tire = load / if dual { 4.0 } else { 2.0 };
        for a in 0..axles {
            let along = (a as f64 - (axles - 1) as f64 / 2.0) * spacing;
            for side in [-1.0, 1.0] {
                let centre = side * track / 2.0;
                if dual {
                    for d in [-1.0, 1.0] {
                        wheels.push(([along, centre + d * dual_spacing / 2.0], per_tire));
                    }
                } else {
                    wheels.push(([along, centre], per_tire));
                }
            }
        }
    } else {
        let list = spec
            .wheels
            .as_deref()
            .or(standard.map(|s| s.wheels))
            .filter(|w| !w.is_empty())
            .ok_or_else(|| {
                Error::invalid(field("wheels"), "missing: the wheel positions [[along, across], …] relative to the reference point, m")
            })?;
        if let Some(w) = list.iter().find(|w| !w[0].is_finite() || !w[1].is_finite()) {
            return Err(Error::invalid(
                field("wheels"),
                format!("must be finite, got {w:?}"),
            ));
        }
        let load = positive(
            "wheel_load",
            spec.wheel_load,
            standard.map(|s| s.wheel_load),
        )?;
        wheels.extend(list.iter().map(|&w| (w, load)));
    }
    let shape = spec.contact_shape.as_deref().unwrap_or("pca");
    if !matches!(shape, "pca" | "square") {
        return Err(Error::invalid(
            field("contact_shape"),
            format!("`{shape}` is not one of pca, square"),
        ));
    }
    let (s, c) = heading.to_radians().sin_cos();
    let quarter = (heading / 90.0).round();
    let axis_aligned = (heading / 90.0 - quarter).abs() < 1e-9;
    let across_x = axis_aligned && (quarter as i64).rem_euclid(2) == 1;
    let tires: Vec<Tire> = wheels
        .iter()
        .map(|&([u, v], force)| {
            let area = force / pressure;
            let size = if shape == "square" || !axis_aligned {
                [area.sqrt(); 2]
            } else {
                let l = (area / 0.5227).sqrt();
                let (along, across) = (0.8712 * l, 0.6 * l);
                if across_x {
                    [across, along]
                } else {
                    [along, across]
                }
            };
            Tire {
                centre: [x0 + u * c - v * s, y0 + u * s + v * c],
                size,
                force,
            }
        })
        .collect();
    // Two prints must not overlap: the loads would add where the tires cannot.
    for (i, a) in tires.iter().enumerate() {
        for b in &tires[i + 1..] {
            let gap_x = (a.centre[0] - b.centre[0]).abs() - (a.size[0] + b.size[0]) / 2.0;
            let gap_y = (a.centre[1] - b.centre[1]).abs() - (a.size[1] + b.size[1]) / 2.0;
            if gap_x < -1e-9 && gap_y < -1e-9 {
                return Err(Error::invalid(
                    field("tire_pressure"),
                    format!("two tire prints overlap (at ({:.3}, {:.3}) and ({:.3}, {:.3}) m): the pressure is too low for the spacing, or the wheels too close", a.centre[0], a.centre[1], b.centre[0], b.centre[1]),
                ));
            }
        }
    }
    Ok(tires)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::spec::{Coord, LoadKind};

    fn at(kind: LoadKind, x: f64, y: f64) -> LoadSpec {
        LoadSpec {
            x: Some(Coord::Value(x)),
            y: Some(Coord::Value(y)),
            ..LoadSpec::new(kind)
        }
    }

    /// The ESAL axle heading along x: four tires of 20 kN at across-positions ±0.915 ± 0.152 m,
    /// each a PCA print of 20 000/827 400 = 0.02417 m²: 0.1874 m along x by 0.1290 m across.
    #[test]
    fn the_esal_axle_has_four_pca_prints() {
        let spec = LoadSpec {
            standard: Some("esal-single-dual".into()),
            ..at(LoadKind::Axle, 1.0, 0.5)
        };
        let t = tires(&spec, 0, true).expect("tires");
        assert_eq!(t.len(), 4);
        let mut ys: Vec<f64> = t.iter().map(|t| t.centre[1] - 0.5).collect();
        ys.sort_by(f64::total_cmp);
        let want = [
            -0.915 - 0.1524,
            -0.915 + 0.1524,
            0.915 - 0.1524,
            0.915 + 0.1524,
        ];
        for (y, w) in ys.iter().zip(want) {
            assert!((y - w).abs() < 1e-12, "{ys:?}");
        }
        for tire in &t {
            assert!((tire.force - 20e3).abs() < 1e-9 && (tire.centre[0] - 1.0).abs() < 1e-12);
            let area = tire.size[0] * tire.size[1];
            assert!((area - 20e3 / 827.4e3).abs() < 1e-4 * area, "area {area}");
            assert!((tire.size[0] - 0.1874).abs() < 5e-4 && (tire.size[1] - 0.1290).abs() < 5e-4);
        }
    }

    /// Heading 90° turns the axle: the tires line up along x, the prints' long sides along y;
    /// a tandem's axles sit ±0.6555 m along the travel.
    #[test]
    fn heading_turns_the_group() {
        let spec = LoadSpec {
            standard: Some("tandem-dual".into()),
            heading: Some(90.0),
            ..at(LoadKind::Axle, 0.0, 0.0)
        };
        let t = tires(&spec, 0, true).expect("tires");
        assert_eq!(t.len(), 8);
        for tire in &t {
            assert!((tire.centre[1].abs() - 0.6555).abs() < 1e-9, "{tire:?}");
            assert!(
                tire.size[1] > tire.size[0],
                "long side along the travel (y): {tire:?}"
            );
        }
        let total: f64 = t.iter().map(|t| t.force).sum();
        assert!((total - 151.2e3).abs() < 1e-6);
        // Off the axes: squares of the same area.
        let skew = LoadSpec {
            heading: Some(30.0),
            ..spec
        };
        for tire in tires(&skew, 0, true).expect("tires") {
            assert!((tire.size[0] - tire.size[1]).abs() < 1e-15);
        }
    }

    #[test]
    fn bad_configurations_name_their_key() {
        let gear_on_axle = LoadSpec {
            standard: Some("b737-800-main".into()),
            ..at(LoadKind::Axle, 0.0, 0.0)
        };
        let e = tires(&gear_on_axle, 2, true).err().map(|e| e.to_string());
        assert!(e.is_some_and(|m| m.contains("load[2].standard")));
        let crowded = LoadSpec {
            axle_load: Some(80e3),
            track: Some(1.8),
            tires: Some("dual".into()),
            dual_spacing: Some(0.1),
            tire_pressure: Some(100e3),
            ..at(LoadKind::Axle, 0.0, 0.0)
        };
        let e = tires(&crowded, 0, true).err().map(|e| e.to_string());
        assert!(
            e.is_some_and(|m| m.contains("overlap")),
            "overlapping prints refused"
        );
    }
}
