//! Values that suggest a unit slip: warnings, never errors (a deliberately flexible plate, a
//! steel base plate on grout or a membrane on sand must still solve).
//!
//! The rules (README, "Units"), each naming the key and the likely slip:
//! - the plate's radius of relative stiffness on its soil is below its own thickness: the plate
//!   is a membrane to its soil — Young's modulus typed in psi or MPa where Pa was meant, or the
//!   soil's modulus far too stiff;
//! - a subgrade modulus (`modulus` of a Winkler, Pasternak or Kerr soil, or of a zone) outside
//!   5–500 MN/m³, the range from soft clay to a cement-treated base (AASHTO 1993, Part II,
//!   Fig. 3.3; PCA 1984, Table 1): typed in pci or MN/m³;
//! - a plate thicker than a fifth of its shorter side, or a side longer than 1 km: lengths typed
//!   in mm (or, in a US scene, in feet where inches were meant — the reverse slip reads as a
//!   very thin plate and is the first rule's);
//! - a traffic group's load level more than three times its axle's or gear's own load, or less
//!   than a twentieth of it ([`traffic`]): newtons typed in a US scene (4.45×), kN or kips typed
//!   where N or lbf were meant — an overloaded axle is rarely twice its legal load.

use super::spec::SceneFile;
use crate::damage::plan::DamagePlan;
use crate::foundation::soil::KeyValue;
use crate::model::Model;
use crate::units::{Quantity, UnitSystem};

/// The subgrade moduli of soils from soft clay to a cement-treated base, N/m³.
pub const SUBGRADE_RANGE: [f64; 2] = [5e6, 500e6];

/// The warnings of a validated scene (its `model`), worded in the file's unit system.
pub fn warnings(file: &SceneFile, model: &Model) -> Vec<String> {
    let (Some(plate), Some(physical)) = (&file.plate, model.physical) else {
        return Vec::new();
    };
    let system = file.units;
    let shown = |q: Quantity, si: f64| format!("{:.4} {}", q.from_si(system, si), q.unit(system));
    let mut out = Vec::new();
    // ℓ in the unit system of L = D = 1: the foundation constant c = μΓ (SoilModel).
    let g = &model.groups;
    let ell = g.foundation().stiffness_length(g.mu * g.gamma) * physical.half_length;
    if ell.is_finite() && ell < plate.thickness {
        out.push(format!(
            "plate.youngs_modulus: the plate's radius of relative stiffness on its soil, {}, is below its thickness {}: the plate acts as a membrane. If that is meant (a flexible sheet, a tank's bottom), ignore this; otherwise check the units of plate.youngs_modulus ({}: a value typed in {} or MPa reads a million times too soft) and of the soil's modulus",
            shown(Quantity::Length, ell),
            shown(Quantity::Length, plate.thickness),
            Quantity::Pressure.unit(system),
            if system == UnitSystem::Si { "psi" } else { "ksi" },
        ));
    }
    let subgrade = |key: &str, k: f64, out: &mut Vec<String>| {
        if k.is_finite() && !(SUBGRADE_RANGE[0]..=SUBGRADE_RANGE[1]).contains(&k) {
            let hint = match system {
                UnitSystem::Si => "typed in pci (1 pci = 271 447 N/m³) or MN/m³ (1e6 N/m³)?",
                UnitSystem::Us => "typed in MN/m³ or N/m³ where pci was meant?",
            };
            out.push(format!(
                "{key}: a subgrade modulus of {} lies outside {}–{} (soft clay to a cement-treated base): {hint} A stiff bed under a base plate is fine as it is",
                shown(Quantity::SubgradeModulus, k),
                shown(Quantity::SubgradeModulus, SUBGRADE_RANGE[0]),
                shown(Quantity::SubgradeModulus, SUBGRADE_RANGE[1]),
            ));
        }
    };
    if let Some(f) = &file.foundation {
        let is_subgrade = f
            .model
            .keys(false)
            .iter()
            .any(|k| k.name == "modulus" && k.unit == "N/m³");
        if let (Some(KeyValue::Number(k)), true) = (f.soil.get("modulus"), is_subgrade) {
            subgrade("foundation.modulus", *k, &mut out);
        }
        for (i, z) in f.zone.iter().enumerate() {
            if let Some(k) = z.modulus {
                subgrade(&format!("foundation.zone[{}].modulus", i + 1), k, &mut out);
            }
        }
    }
    let shorter = plate.length.min(plate.width);
    if plate.thickness > 0.2 * shorter {
        out.push(format!(
            "plate.thickness: {} is more than a fifth of the plate's shorter side {}: were the sides typed in {}?",
            shown(Quantity::Length, plate.thickness),
            shown(Quantity::Length, shorter),
            if system == UnitSystem::Si { "mm" } else { "feet" },
        ));
    }
    let longer = plate.length.max(plate.width);
    if longer > 1000.0 {
        out.push(format!(
            "plate.length: a side of {} is longer than a kilometre: were the lengths typed in {}?",
            shown(Quantity::Length, longer),
            if system == UnitSystem::Si {
                "mm"
            } else {
                "mils"
            },
        ));
    }
    out
}

/// The warnings of a damage scene's traffic: each group's load levels against its axle's or
/// gear's own load (the sum of its wheels' loads), worded in the file's unit system.
pub fn traffic(plan: &DamagePlan, model: &Model, system: UnitSystem) -> Vec<String> {
    let force = |si: f64| {
        format!(
            "{:.0} {}",
            Quantity::Force.from_si(system, si),
            Quantity::Force.unit(system)
        )
    };
    let mut out = Vec::new();
    for (g, group) in plan.groups.iter().enumerate() {
        let Some(vehicle) = model.vehicles.get(group.vehicle) else {
            continue;
        };
        let own: f64 = vehicle.wheels.iter().map(|w| w.force).sum();
        let Some(level) = (group.levels.iter())
            .map(|l| l.load)
            .find(|&l| own > 0.0 && !(own / 20.0..=3.0 * own).contains(&l))
        else {
            continue;
        };
        out.push(format!(
            "traffic.group[{g}].levels: a level of {} is {:.2}× `{}`'s own load of {}: the levels are the group's total load in {}{}",
            force(level),
            level / own,
            group.load,
            force(own),
            Quantity::Force.unit(system),
            match system {
                UnitSystem::Us => " (newtons typed where pounds were meant read 4.45 times too heavy)",
                UnitSystem::Si => " (kN typed where N was meant read a thousand times too light)",
            }
        ));
    }
    out
}
