//! Vehicle loads (`kind = "axle"`, `"gear"`) as a scene writes them: a truck's axle group or an
//! aircraft gear placed by a reference point and a heading, each tire a uniform pressure over a
//! rectangle of its contact area (its load over the tire pressure). This module reads the
//! `[[load]]` entry (its standard configuration, wheels and loads) into a [`Vehicle`]; the
//! prints' shapes and their placing are [`crate::vehicle`]'s.

use super::spec::LoadSpec;
use crate::error::{Error, Result};
use crate::model::Load;
pub use crate::vehicle::Tire;
use crate::vehicle::{Frame, Vehicle, Wheel};

/// The patches of an `axle` or `gear` entry `k` (SI scenes only): one per tire, in unit
/// geometry, its pressure raw (N per unit area).
pub(super) fn patches(l: &LoadSpec, k: usize, si: bool, frame: Frame) -> Result<Vec<Load>> {
    if !si {
        return Err(Error::invalid(
            format!("load[{k}].kind"),
            format!(
                "kind = \"{}\" belongs to SI scenes ([plate] and [foundation]): its tires are given in metres and newtons",
                l.kind.name()
            ),
        ));
    }
    let axle = matches!(l.kind, super::spec::LoadKind::Axle);
    let v = vehicle(l, k, axle, frame, String::new())?;
    Ok(v.prints(v.at)?
        .into_iter()
        .map(|p| Load::Patch {
            x: p.x,
            y: p.y,
            pressure: p.pressure,
        })
        .collect())
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

/// The tires of an `axle` or `gear` entry `k`, in metres about the plate's centre.
pub fn tires(spec: &LoadSpec, k: usize, axle: bool) -> Result<Vec<Tire>> {
    let frame = Frame {
        scale_xy: [1.0; 2],
        half: [f64::INFINITY; 2],
        area_scale: 1.0,
        plate: [f64::INFINITY; 2],
    };
    let v = vehicle(spec, k, axle, frame, String::new())?;
    v.tires(v.at)
}

/// The `axle` (`axle` true) or `gear` entry `k` of case `case` as a [`Vehicle`] on the plate
/// `frame`, standing where the entry puts it: its wheels (from its `standard` configuration and
/// the keys that override it), tire pressure and print shape, checked.
pub fn vehicle(
    spec: &LoadSpec,
    k: usize,
    axle: bool,
    frame: Frame,
    case: String,
) -> Result<Vehicle> {
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
        if let (Some(std), Some(own)) = (standard, spec.configuration.as_deref()) {
            if own != std.configuration && axles > 1 && spec.axle_spacing.is_none() {
                let fits: Vec<&str> = STANDARDS
                    .iter()
                    .filter(|s| s.axle && s.configuration == own)
                    .map(|s| s.name)
                    .collect();
                return Err(Error::invalid(
                    field("configuration"),
                    format!(
                        "`{own}` changes the standard `{}`, a {} axle, which has no axle spacing for it: give axle_spacing (m) with it, or take a {own} standard ({})",
                        std.name,
                        std.configuration,
                        fits.join(", ")
                    ),
                ));
            }
        }
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
    let vehicle = Vehicle {
        name: spec.name.clone(),
        entry: k,
        case,
        axle,
        at: [x0, y0, heading],
        wheels: wheels
            .into_iter()
            .map(|(offset, force)| Wheel { offset, force })
            .collect(),
        pressure,
        square: shape == "square",
        frame,
        factor: 1.0,
        loads: 0..0,
    };
    // The prints where the entry puts them: two must not overlap.
    vehicle.tires(vehicle.at)?;
    Ok(vehicle)
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

    /// A load, a tire pressure or a track must be a finite positive number: a negative axle
    /// load, a zero tire pressure and an infinite track over the ESAL standard's own values
    /// are each refused naming their field.
    #[test]
    fn vehicle_sizes_must_be_finite_and_positive() {
        let esal = || LoadSpec {
            standard: Some("esal-single-dual".into()),
            ..at(LoadKind::Axle, 1.0, 0.5)
        };
        for (spec, name) in [
            (
                LoadSpec {
                    axle_load: Some(-80e3),
                    ..esal()
                },
                "axle_load",
            ),
            (
                LoadSpec {
                    tire_pressure: Some(0.0),
                    ..esal()
                },
                "tire_pressure",
            ),
            (
                LoadSpec {
                    track: Some(f64::INFINITY),
                    ..esal()
                },
                "track",
            ),
        ] {
            let e = tires(&spec, 0, true);
            let want = format!("load[0].{name}");
            assert!(
                matches!(&e, Err(Error::Invalid { field, .. }) if *field == want),
                "{name}: {e:?}"
            );
        }
    }
}
