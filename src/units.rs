//! Unit systems of a scene file: SI (the default) and US customary (`units = "us"`).
//!
//! A scene in US customary units gives every length in inches (as ISLAB2000 and the AASHTO and
//! PCA examples take them), forces in lbf, pressures and moduli in psi, subgrade moduli in pci
//! (lbf/in³), forces per length and spring stiffnesses per bar in lbf/in, temperature
//! differences in °F and temperatures in °F, thermal expansion per °F. The file is converted to
//! SI before it is read ([`scene_to_si`]), so the dimensionless core and every check see SI;
//! the outputs show the scene's system ([`crate::output::chart::units::Units`]).
//!
//! The factors are exact by definition: the international inch is 0.0254 m (1959), the
//! pound-force is the avoirdupois pound 0.45359237 kg under standard gravity 9.80665 m/s²
//! (NIST SP 811, 2008, B.8), and a degree Fahrenheit is 5/9 of a kelvin.

use serde::{Deserialize, Serialize};
use serde_json::Value;

use crate::error::{Error, Result};
use crate::foundation::FoundationKind;

/// The international inch, m.
pub const INCH: f64 = 0.0254;
/// The pound-force, N: 0.45359237 kg × 9.80665 m/s².
pub const POUND_FORCE: f64 = 0.453_592_37 * 9.806_65;
/// The foot, m.
pub const FOOT: f64 = 12.0 * INCH;

/// The unit system of a scene file and of what liftoff reports for it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum UnitSystem {
    /// SI: m, N, Pa, N/m³, K (°C).
    #[default]
    Si,
    /// US customary: in, lbf, psi, pci, °F.
    Us,
}

crate::choice::names!(UnitSystem, Si => "si", Us => "us");

/// What a scene key measures: the kinds of quantity whose units differ between the systems.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// m | in.
    Length,
    /// N | lbf.
    Force,
    /// Pa | psi (pressures, moduli, stresses, joint stiffness per length of joint).
    Pressure,
    /// N/m³ | pci = lbf/in³ (subgrade modulus).
    SubgradeModulus,
    /// N/m | lbf/in (line loads, shear layers, a dowel's spring).
    ForcePerLength,
    /// N·m/m = N | lbf·in/in = lbf (moments per length, rotational joint stiffness).
    MomentPerLength,
    /// K | °F (a difference of temperatures).
    TemperatureDifference,
    /// °C | °F (a temperature).
    Temperature,
    /// 1/K | 1/°F.
    ThermalExpansion,
}

impl Quantity {
    /// SI value of `value` given in `system`.
    pub fn to_si(self, system: UnitSystem, value: f64) -> f64 {
        match (system, self) {
            (UnitSystem::Si, _) => value,
            (UnitSystem::Us, Quantity::Temperature) => (value - 32.0) * 5.0 / 9.0,
            (UnitSystem::Us, q) => value * q.us_factor(),
        }
    }

    /// The value in `system` of the SI value `si`.
    pub fn from_si(self, system: UnitSystem, si: f64) -> f64 {
        match (system, self) {
            (UnitSystem::Si, _) => si,
            (UnitSystem::Us, Quantity::Temperature) => si * 9.0 / 5.0 + 32.0,
            (UnitSystem::Us, q) => si / q.us_factor(),
        }
    }

    /// SI units per US unit (for a temperature, of its differences).
    fn us_factor(self) -> f64 {
        let psi = POUND_FORCE / (INCH * INCH);
        match self {
            Quantity::Length => INCH,
            Quantity::Force => POUND_FORCE,
            Quantity::Pressure => psi,
            Quantity::SubgradeModulus => psi / INCH,
            Quantity::ForcePerLength => POUND_FORCE / INCH,
            Quantity::MomentPerLength => POUND_FORCE,
            Quantity::TemperatureDifference | Quantity::Temperature => 5.0 / 9.0,
            Quantity::ThermalExpansion => 9.0 / 5.0,
        }
    }

    /// The unit's symbol in `system`.
    pub fn unit(self, system: UnitSystem) -> &'static str {
        let si = system == UnitSystem::Si;
        match self {
            Quantity::Length => pick(si, "m", "in"),
            Quantity::Force => pick(si, "N", "lbf"),
            Quantity::Pressure => pick(si, "Pa", "psi"),
            Quantity::SubgradeModulus => pick(si, "N/m³", "pci"),
            Quantity::ForcePerLength => pick(si, "N/m", "lbf/in"),
            Quantity::MomentPerLength => pick(si, "N·m/m", "lbf·in/in"),
            Quantity::TemperatureDifference => pick(si, "K", "°F"),
            Quantity::Temperature => pick(si, "°C", "°F"),
            Quantity::ThermalExpansion => pick(si, "1/K", "1/°F"),
        }
    }

    /// The quantity of a soil key from its SI unit as the soil lists it
    /// ([`crate::foundation::soil::SoilModel::SI_KEYS`]); None for a pure number or a word.
    pub fn of_si_unit(unit: &str) -> Option<Quantity> {
        match unit {
            "m" => Some(Quantity::Length),
            "N" => Some(Quantity::Force),
            "Pa" => Some(Quantity::Pressure),
            "N/m³" => Some(Quantity::SubgradeModulus),
            "N/m" => Some(Quantity::ForcePerLength),
            _ => None,
        }
    }
}

fn pick(si: bool, a: &'static str, b: &'static str) -> &'static str {
    if si {
        a
    } else {
        b
    }
}

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
        ("plate", "length" | "width" | "thickness") => Some(Length),
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
        ("joint", "x" | "y" | "spacing" | "offset" | "positions" | "diameter" | "opening") => {
            Some(Length)
        }
        ("joint", "stiffness" | "youngs_modulus") => Some(Pressure),
        ("joint", "rotational_stiffness") => Some(MomentPerLength),
        ("joint", "support_modulus") => Some(SubgradeModulus),
        ("joint", "dowel_stiffness") => Some(ForcePerLength),
        ("panel", "at" | "thickness") => Some(Length),
        ("panel", "youngs_modulus") => Some(Pressure),
        ("load", "x" | "y" | "from" | "to" | "depths" | "depth" | "wheels") => Some(Length),
        ("load", "axle_spacing" | "track" | "dual_spacing") => Some(Length),
        ("load", "force" | "axle_load" | "wheel_load") => Some(Force),
        ("load", "pressure" | "tire_pressure") => Some(Pressure),
        ("load", "force_per_length") => Some(ForcePerLength),
        ("load", "difference") => match load_kind {
            Some("temperature" | "built-in-curl") => Some(TemperatureDifference),
            _ => None,
        },
        ("load", "temperatures") => Some(Temperature),
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
            "void" | "joint" | "panel" | "load" => {
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

    /// The factors against their definitions, written out independently: 1 psi = 6894.757 Pa,
    /// 1 pci = 271.447 kN/m³ (AASHTO 1993 and PCA's tables print 1 pci = 0.2714 MN/m³), 1 lbf =
    /// 4.448222 N, 1 in = 25.4 mm, and 9 °F = 5 K.
    #[test]
    fn the_factors_are_their_definitions() {
        let us = UnitSystem::Us;
        let close = |a: f64, b: f64, tol: f64| (a - b).abs() <= tol * b.abs();
        assert_eq!(Quantity::Length.to_si(us, 1.0), 0.0254);
        assert!(close(
            Quantity::Force.to_si(us, 1.0),
            4.448_221_615_260_5,
            1e-15
        ));
        // 6894.757 293 168 361 Pa (NIST SP 811 B.8: 6.894 757 E+03).
        assert!(close(
            Quantity::Pressure.to_si(us, 1.0),
            6_894.757_293_168_361,
            1e-15
        ));
        assert!(close(
            Quantity::SubgradeModulus.to_si(us, 1.0),
            271_447.137_526_313_4,
            1e-14
        ));
        assert!(close(
            Quantity::ForcePerLength.to_si(us, 1.0),
            175.126_835_246_476,
            1e-14
        ));
        assert!(close(
            Quantity::TemperatureDifference.to_si(us, 9.0),
            5.0,
            1e-15
        ));
        assert_eq!(Quantity::Temperature.to_si(us, 212.0), 100.0);
        assert_eq!(Quantity::Temperature.to_si(us, 32.0), 0.0);
        assert!(close(
            Quantity::ThermalExpansion.to_si(us, 5e-6),
            9e-6,
            1e-15
        ));
        for q in [
            Quantity::Length,
            Quantity::Force,
            Quantity::Pressure,
            Quantity::SubgradeModulus,
            Quantity::ForcePerLength,
            Quantity::MomentPerLength,
            Quantity::TemperatureDifference,
            Quantity::Temperature,
            Quantity::ThermalExpansion,
        ] {
            let back = q.from_si(us, q.to_si(us, 123.456));
            assert!(close(back, 123.456, 1e-15), "{q:?} round trip {back}");
            assert_eq!(q.to_si(UnitSystem::Si, 7.5), 7.5);
        }
    }

    #[test]
    fn a_us_scene_converts_every_dimensioned_key_and_nothing_else() {
        let mut scene: Value = serde_json::json!({
            "units": "us",
            "plate": {"length": 168.0, "width": 144.0, "thickness": 9.0,
                      "youngs_modulus": 5e6, "poissons_ratio": 0.15, "thermal_expansion": 5e-6},
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
