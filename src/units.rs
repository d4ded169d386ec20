//! Unit systems of a scene file: SI (the default) and US customary (`units = "us"`).
//!
//! A scene in US customary units gives every length in inches (as ISLAB2000 and the AASHTO and
//! PCA examples take them), forces in lbf, pressures and moduli in psi, subgrade moduli in pci
//! (lbf/in³), forces per length and spring stiffnesses per bar in lbf/in, temperature
//! differences in °F and temperatures in °F, thermal expansion per °F. The file is converted to
//! SI before it is read (`scene/convert.rs`), so the dimensionless core and every check see SI;
//! the outputs show the scene's system (the charts' and tables' `Units`). A floor: it imports
//! nothing of liftoff's but the names of its choices.
//!
//! The factors are exact by definition: the international inch is 0.0254 m (1959), the
//! pound-force is the avoirdupois pound 0.45359237 kg under standard gravity 9.80665 m/s²
//! (NIST SP 811, 2008, B.8), and a degree Fahrenheit is 5/9 of a kelvin.

use serde::{Deserialize, Serialize};

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
    /// K/m | °F/in (a temperature gradient through the slab's thickness).
    TemperatureGradient,
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
            Quantity::TemperatureGradient => 5.0 / 9.0 / INCH,
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
            Quantity::TemperatureGradient => pick(si, "K/m", "°F/in"),
        }
    }

    /// The quantity of a soil key from its SI unit as the soil lists it
    /// (each soil's `SI_KEYS`); None for a pure number or a word.
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

/// What a reported value measures — a column of a CSV file, a field of the VTU, a key of
/// summary.json: its unit in the scene's system, and in a dimensionless scene (no system) the
/// paper's scale it is given in (L the half side, P the load scale, D the plate's rigidity).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Measure {
    /// A position or a length: m | in | L.
    Length,
    /// A deflection or a gap: m | in | P L²/D.
    Deflection,
    /// A rotation: rad | rad | P L/D.
    Rotation,
    /// A pressure or a stress: Pa | psi | P/L².
    Pressure,
    /// A bending moment per length: N·m/m | lbf·in/in | P.
    MomentPerLength,
    /// A shear force per length: N/m | lbf/in | P/L.
    ForcePerLength,
    /// A force: N | lbf | P.
    Force,
    /// A bending rigidity or a moment: N·m | lbf·in | P L.
    Moment,
    /// An area: m² | in² | L².
    Area,
    /// An angle in degrees, the same in every system.
    Degrees,
    /// A pure number (a ratio, a dimensionless group, a count).
    Number,
}

impl Measure {
    /// The value in `system` (None: a dimensionless scene, whose values are already in the
    /// paper's scales) of `si`, a value in SI base units (or in those scales).
    pub fn from_si(self, system: Option<UnitSystem>, si: f64) -> f64 {
        match (system, self.quantity()) {
            (Some(s), Some(q)) => q.from_si(s, si),
            (Some(UnitSystem::Us), None) if self == Measure::Moment => si / (POUND_FORCE * INCH),
            (Some(UnitSystem::Us), None) if self == Measure::Area => si / (INCH * INCH),
            _ => si,
        }
    }

    /// The unit's symbol in `system`; in a dimensionless scene (None) the paper's scale, and
    /// "-" for a pure number.
    pub fn unit(self, system: Option<UnitSystem>) -> &'static str {
        match (system, self) {
            (_, Measure::Degrees) => "°",
            (_, Measure::Number) => "-",
            (Some(_), Measure::Rotation) => "rad",
            (Some(UnitSystem::Si), Measure::Moment) => "N·m",
            (Some(UnitSystem::Us), Measure::Moment) => "lbf·in",
            (Some(UnitSystem::Si), Measure::Area) => "m²",
            (Some(UnitSystem::Us), Measure::Area) => "in²",
            (Some(s), m) => m.quantity().map_or("-", |q| q.unit(s)),
            (None, Measure::Length) => "L",
            (None, Measure::Deflection) => "P·L²/D",
            (None, Measure::Rotation) => "P·L/D",
            (None, Measure::Pressure) => "P/L²",
            (None, Measure::MomentPerLength | Measure::Force) => "P",
            (None, Measure::ForcePerLength) => "P/L",
            (None, Measure::Moment) => "P·L",
            (None, Measure::Area) => "L²",
        }
    }

    /// A column's header: its name and, in brackets, its unit (`w [in]`, `V [-]`).
    pub fn header(self, name: &str, system: Option<UnitSystem>) -> String {
        format!("{name} [{}]", self.unit(system))
    }

    /// The scene quantity of the same unit, where there is one.
    fn quantity(self) -> Option<Quantity> {
        match self {
            Measure::Length | Measure::Deflection => Some(Quantity::Length),
            Measure::Pressure => Some(Quantity::Pressure),
            Measure::MomentPerLength => Some(Quantity::MomentPerLength),
            Measure::ForcePerLength => Some(Quantity::ForcePerLength),
            Measure::Force => Some(Quantity::Force),
            Measure::Rotation
            | Measure::Moment
            | Measure::Area
            | Measure::Degrees
            | Measure::Number => None,
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
        // 1 °F/in = (5/9) K per 0.0254 m = 21.872 265 966 754 16 K/m.
        assert!(close(
            Quantity::TemperatureGradient.to_si(us, 1.0),
            21.872_265_966_754_16,
            1e-14
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
            Quantity::TemperatureGradient,
        ] {
            let back = q.from_si(us, q.to_si(us, 123.456));
            assert!(close(back, 123.456, 1e-15), "{q:?} round trip {back}");
            assert_eq!(q.to_si(UnitSystem::Si, 7.5), 7.5);
        }
    }

    /// Reported values: a moment of 1 lbf·in is 0.112 984 829 N·m, a square inch 6.4516 cm²
    /// (definitions), a deflection of 1 mm is 0.039 370 in, and a dimensionless scene's values
    /// pass unchanged with the paper's scales as units.
    #[test]
    fn reported_values_convert_by_the_same_definitions() {
        let us = Some(UnitSystem::Us);
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs();
        assert!(close(
            Measure::Moment.from_si(us, 0.112_984_829_027_616_7),
            1.0
        ));
        assert!(close(Measure::Area.from_si(us, 6.4516e-4), 1.0));
        assert!(close(Measure::Deflection.from_si(us, 1e-3), 1.0 / 25.4));
        assert!(close(
            Measure::Pressure.from_si(us, 6_894.757_293_168_361),
            1.0
        ));
        assert_eq!(Measure::Rotation.from_si(us, 0.25), 0.25);
        assert_eq!(Measure::Pressure.from_si(None, 0.25), 0.25);
        assert_eq!(Measure::Deflection.header("w", us), "w [in]");
        assert_eq!(Measure::Pressure.header("sigma", None), "sigma [P/L²]");
        assert_eq!(Measure::Number.header("V", Some(UnitSystem::Si)), "V [-]");
        assert_eq!(Measure::MomentPerLength.unit(Some(UnitSystem::Si)), "N·m/m");
    }
}
