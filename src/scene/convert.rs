//! A scene file written in US customary units (`units = "us"`), converted to SI before it is
//! read: which key measures what ([`quantity`]), and the conversion of the file's values
//! ([`scene_to_si`]). The factors are [`crate::units`]'.

use serde_json::Value;

use crate::error::{Error, Result};
use crate::foundation::FoundationKind;
use crate::units::{Quantity, UnitSystem};

/// The quantity of key `key` in section `section` of a physical scene (`load_kind` the
/// `kind` of a `[[load]]`, `soil` the `model` of `[foundation]`); None for pure numbers,
/// words, angles and mesh or solver settings.
pub fn quantity(
    section: &str,
    key: &str,
    load_kind: Option<&str>,
    soil: Option<FoundationKind>,
) -> Option<Quantity> {
    use Quantity::*;
    match (section, key) {
        ("plate", "length" | "width" | "thickness" | "outline") => Some(Length),
        ("opening", "x" | "y" | "outline") => Some(Length),
        ("plate", "youngs_modulus") => Some(Pressure),
        ("plate", "thermal_expansion") => Some(ThermalExpansion),
        ("foundation", "allowable_pressure") => Some(Pressure),
        ("foundation", "bearing_length") => Some(Length),
        ("foundation", k) => soil.and_then(|s| {
            s.keys(false)
                .iter()
                .find(|c| c.name == k)
                .and_then(|c| Quantity::of_si_unit(c.unit))
        }),
        ("zone", "x" | "y") => Some(Length),
        ("zone", "modulus") => Some(SubgradeModulus),
        ("void", "x" | "y" | "depth") => Some(Length),
        (
            "joint",
            "x" | "y" | "from" | "to" | "spacing" | "offset" | "positions" | "diameter" | "opening",
        ) => Some(Length),
        ("joint", "stiffness" | "youngs_modulus") => Some(Pressure),
        ("joint", "rotational_stiffness") => Some(MomentPerLength),
        ("joint", "support_modulus") => Some(SubgradeModulus),
        ("joint", "dowel_stiffness") => Some(ForcePerLength),
        ("panel", "at" | "x" | "y" | "outline" | "thickness") => Some(Length),
        ("panel", "youngs_modulus") => Some(Pressure),
        ("load", "x" | "y" | "from" | "to" | "depths" | "depth" | "wheels") => Some(Length),
        ("load", "axle_spacing" | "track" | "dual_spacing" | "radius") => Some(Length),
        ("load", "force" | "axle_load" | "wheel_load") => Some(Force),
        ("load", "pressure" | "tire_pressure") => Some(Pressure),
        ("load", "force_per_length") => Some(ForcePerLength),
        ("load", "difference") => match load_kind {
            Some("temperature" | "built-in-curl") => Some(TemperatureDifference),
            _ => None,
        },
        ("load", "temperatures") => Some(Temperature),
        ("traffic", "edge_at") => Some(Length),
        ("traffic.wander", "mean" | "deviation") => Some(Length),
        ("traffic.group", "levels") => Some(Force),
        ("climate.bin", "difference") => Some(TemperatureDifference),
        ("climate.bin", "gradient") => Some(TemperatureGradient),
        ("climate.bin", "depths") => Some(Length),
        ("climate.bin", "temperatures") => Some(Temperature),
        ("climate.bin", "subgrade_modulus") => Some(SubgradeModulus),
        ("damage", "modulus_of_rupture") => Some(Pressure),
        _ => None,
    }
}

/// The unit system a scene file (as a JSON value) names: its top-level `units`, SI without one.
pub fn scene_system(scene: &Value) -> Result<UnitSystem> {
    match scene.get("units") {
        None => Ok(UnitSystem::Si),
        Some(Value::String(s)) => <UnitSystem as crate::choice::Choice>::from_name(s).ok_or_else(|| {
            Error::invalid(
                "units",
                format!("`{s}` is not a unit system: write units = \"si\" (m, N, Pa, N/m³, °C) or \"us\" (in, lbf, psi, pci, °F)"),
            )
        }),
        Some(other) => Err(Error::invalid(
            "units",
            format!("must be \"si\" or \"us\", not {other}"),
        )),
    }
}

/// Convert every dimensioned value of a scene file given in `system` to SI in place (the
/// `units` key stays, so that the outputs know the system). Keys liftoff does not know are left
/// for the scene's own check to name; a `[dimensionless]` scene has no units to convert.
pub fn scene_to_si(scene: &mut Value, system: UnitSystem) -> Result<()> {
    if system == UnitSystem::Si {
        return Ok(());
    }
    if scene.get("dimensionless").is_some() {
        return Err(Error::invalid(
            "units",
            "a [dimensionless] scene is given in the paper's groups, which have no units: remove `units`, or give the scene as [plate] and [foundation]",
        ));
    }
    let soil = scene
        .get("foundation")
        .and_then(|f| f.get("model"))
        .and_then(Value::as_str)
        .and_then(<FoundationKind as crate::choice::Choice>::from_name);
    let Some(obj) = scene.as_object_mut() else {
        return Ok(());
    };
    for (section, value) in obj.iter_mut() {
        match section.as_str() {
            "plate" => table(value, "plate", None, soil, system),
            "foundation" => {
                table(value, "foundation", None, soil, system);
                if let Some(zones) = value.get_mut("zone") {
                    each(zones, |z| table(z, "zone", None, soil, system));
                }
            }
            "traffic" => {
                table(value, "traffic", None, soil, system);
                if let Some(w) = value.get_mut("wander") {
                    table(w, "traffic.wander", None, soil, system);
                }
                if let Some(groups) = value.get_mut("group") {
                    each(groups, |g| table(g, "traffic.group", None, soil, system));
                }
            }
            "climate" => {
                if let Some(bins) = value.get_mut("bin") {
                    each(bins, |b| table(b, "climate.bin", None, soil, system));
                }
            }
            "damage" => table(value, "damage", None, soil, system),
            "void" | "joint" | "panel" | "opening" | "load" => {
                each(value, |entry| {
                    let kind = entry
                        .get("kind")
                        .and_then(Value::as_str)
                        .map(str::to_string);
                    table(entry, section, kind.as_deref(), soil, system);
                });
            }
            _ => {}
        }
    }
    Ok(())
}

fn each(value: &mut Value, mut f: impl FnMut(&mut Value)) {
    if let Value::Array(items) = value {
        items.iter_mut().for_each(&mut f);
    }
}

/// Convert the keys of one table (section or array entry).
fn table(
    value: &mut Value,
    section: &str,
    kind: Option<&str>,
    soil: Option<FoundationKind>,
    system: UnitSystem,
) {
    if let Value::Object(map) = value {
        for (key, v) in map.iter_mut() {
            if let Some(q) = quantity(section, key, kind, soil) {
                numbers(v, q, system);
            }
        }
    }
}

/// Convert a number, or every number of a (nested) array, in place.
fn numbers(value: &mut Value, q: Quantity, system: UnitSystem) {
    match value {
        Value::Number(n) => {
            if let Some(x) = n.as_f64() {
                if let Some(si) = serde_json::Number::from_f64(q.to_si(system, x)) {
                    *value = Value::Number(si);
                }
            }
        }
        Value::Array(items) => items.iter_mut().for_each(|v| numbers(v, q, system)),
        _ => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_us_scene_converts_every_dimensioned_key_and_nothing_else() {
        let mut scene: Value = serde_json::json!({
            "units": "us",
            "plate": {"length": 168.0, "width": 144.0, "thickness": 9.0,
                      "youngs_modulus": 5e6, "poissons_ratio": 0.15, "thermal_expansion": 5e-6,
                      "outline": [[-84.0, -72.0], [84.0, -72.0], [84.0, 72.0], [-84.0, 72.0]]},
            "opening": [{"x": [0.0, 12.0], "y": [-12.0, 12.0]}],
            "panel": [{"outline": [[-24.0, 0.0], [0.0, 0.0], [0.0, 24.0], [-24.0, 24.0]],
                       "thickness": 12.0, "thickness_ratio": 1.5}],
            "joint": [{"from": [36.0, -72.0], "to": [36.0, 0.0], "kind": "aggregate"}],
            "foundation": {"model": "winkler", "modulus": 200.0,
                           "zone": [{"x": [0.0, 12.0], "y": [0.0, 12.0], "modulus": 100.0}]},
            "load": [{"kind": "temperature", "difference": 27.0},
                     {"kind": "point", "x": 12.0, "y": [0.0, 6.0], "force": 9000.0},
                     {"kind": "temperature-profile", "depths": [0.0, 9.0], "temperatures": [50.0, 32.0]}],
            "mesh": {"elements": [28, 24]}
        });
        scene_to_si(&mut scene, UnitSystem::Us).expect("converts");
        let n = |p: &str| scene.pointer(p).and_then(Value::as_f64).expect(p);
        assert!((n("/plate/length") - 4.2672).abs() < 1e-12);
        assert!((n("/plate/youngs_modulus") - 5e6 * 6_894.757_293_168_361).abs() < 1e-3);
        assert_eq!(n("/plate/poissons_ratio"), 0.15);
        assert!((n("/foundation/modulus") - 200.0 * 271_447.137_526_313_4).abs() < 1e-6);
        assert!((n("/foundation/zone/0/modulus") - 100.0 * 271_447.137_526_313_4).abs() < 1e-6);
        assert!((n("/foundation/zone/0/x/1") - 0.3048).abs() < 1e-15);
        assert!((n("/load/0/difference") - 15.0).abs() < 1e-12);
        assert!((n("/load/1/y/1") - 0.1524).abs() < 1e-15);
        assert!((n("/load/2/temperatures/0") - 10.0).abs() < 1e-12);
        assert!((n("/load/2/depths/1") - 0.2286).abs() < 1e-15);
        assert!((n("/plate/outline/1/0") - 84.0 * 0.0254).abs() < 1e-15);
        assert!((n("/opening/0/y/0") + 0.3048).abs() < 1e-15);
        assert!((n("/panel/0/outline/2/1") - 0.6096).abs() < 1e-15);
        assert!((n("/panel/0/thickness") - 0.3048).abs() < 1e-15);
        assert_eq!(n("/panel/0/thickness_ratio"), 1.5);
        assert!((n("/joint/0/from/0") - 0.9144).abs() < 1e-15);
        assert!((n("/joint/0/to/1")).abs() < 1e-15);
        assert_eq!(
            scene.pointer("/mesh/elements/0"),
            Some(&serde_json::json!(28))
        );
    }

    #[test]
    fn units_are_refused_on_dimensionless_scenes_and_unknown_systems() {
        let mut s = serde_json::json!({"units": "us", "dimensionless": {"gamma": 1.0}});
        let e = scene_to_si(&mut s, UnitSystem::Us).expect_err("refused");
        assert!(e.to_string().contains("units"), "{e}");
        let e = scene_system(&serde_json::json!({"units": "imperial"})).expect_err("refused");
        assert!(e.to_string().contains("\"us\""), "{e}");
    }
}
