//! The units a solve is drawn and printed in.
//!
//! A scene given in SI units ([`Physical`] scales known) is reported in engineering units:
//! lengths in m, deflections in mm, pressures in kPa, moments in kN·m/m, shear forces in kN/m,
//! forces in kN. A dimensionless scene keeps the paper's V = D w / (P L²) and σ = μ L² r / P.
//!
//! The post-processed fields ([`crate::post::FullField`], [`crate::post::ElementField`]) hold
//! physical quantities in SI for a physical scene and in the unit system L = P = D = 1 for a
//! dimensionless one; each [`Scale`] turns such a field value into the value shown. In the unit
//! system a deflection is V already, and a pressure r becomes σ = μ r.

use crate::model::Physical;
use crate::units::{UnitSystem, FOOT, INCH, POUND_FORCE};

/// The US customary scale that stands for an SI engineering unit: lengths in inches (feet for
/// plan areas), deflections in mils, pressures and stresses in psi, moments in lbf·in/in,
/// shear forces in lbf/in, forces in lbf.
fn us(si: &str) -> Option<Scale> {
    let psi = POUND_FORCE / (INCH * INCH);
    let (unit, factor) = match si {
        "m" => ("in", 1.0 / INCH),
        "m²" => ("ft²", 1.0 / (FOOT * FOOT)),
        "mm" => ("mils", 1.0 / (1e-3 * INCH)),
        "kPa" | "MPa" => ("psi", 1.0 / psi),
        "kN·m/m" => ("lbf·in/in", 1.0 / POUND_FORCE),
        "kN/m" => ("lbf/in", INCH / POUND_FORCE),
        "kN" => ("lbf", 1.0 / POUND_FORCE),
        _ => return None,
    };
    Some(Scale { unit, factor })
}

/// How one quantity is shown: shown value = field value × `factor`, followed by `unit`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scale {
    /// Unit text ("kPa", "mm", …; empty for a dimensionless quantity such as V or σ).
    pub unit: &'static str,
    /// Multiplier from the field's units to the shown ones.
    pub factor: f64,
}

impl Scale {
    /// The shown value of a field value.
    pub fn apply(&self, value: f64) -> f64 {
        value * self.factor
    }

    /// An axis or colour-bar label: `name (unit)`, or `name` alone without a unit.
    pub fn label(&self, name: &str) -> String {
        if self.unit.is_empty() {
            name.to_string()
        } else {
            format!("{name} ({})", self.unit)
        }
    }
}

/// The units of one solve's charts and tables: engineering units for a physical scene, the
/// paper's dimensionless ones otherwise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Units {
    physical: Option<Physical>,
    mu: f64,
}

impl Units {
    /// Units of a scene with the physical scales `physical` (None: a dimensionless scene) and
    /// aspect ratio μ (`Model.groups.mu`, `Summary.dimensionless.mu`).
    pub fn new(physical: Option<Physical>, mu: f64) -> Self {
        Self { physical, mu }
    }

    /// Units for values already in SI base units (Pa, m, N — a moving load's search, a damage
    /// run), shown in `system`'s engineering units.
    pub fn of_si(system: crate::units::UnitSystem) -> Self {
        Self::new(
            Some(Physical {
                half_length: 1.0,
                force: 1.0,
                rigidity: 1.0,
                units: system,
            }),
            1.0,
        )
    }

    /// The paper's dimensionless units (V, σ, lengths in L).
    pub fn dimensionless(mu: f64) -> Self {
        Self::new(None, mu)
    }

    /// Whether values are shown in engineering units.
    pub fn is_physical(&self) -> bool {
        self.physical.is_some()
    }

    /// The physical scales, if any.
    pub fn physical(&self) -> Option<Physical> {
        self.physical
    }

    /// μ, the plate's aspect ratio.
    pub fn mu(&self) -> f64 {
        self.mu
    }

    /// Scale of the engineering unit (`unit`, `factor` from SI), or the dimensionless one. A
    /// scene written in US customary units shows the US unit of the same quantity instead
    /// ([`us`]).
    fn pick(&self, unit: &'static str, factor: f64, dimensionless: Scale) -> Scale {
        match self.physical.map(|p| p.units) {
            Some(UnitSystem::Si) => Scale { unit, factor },
            Some(UnitSystem::Us) => us(unit).unwrap_or(Scale { unit, factor }),
            None => dimensionless,
        }
    }

    /// The unit system values are shown in (SI for a dimensionless scene's physical output).
    pub fn system(&self) -> UnitSystem {
        self.physical.map_or(UnitSystem::Si, |p| p.units)
    }

    /// Lengths and coordinates (FullField x, y): m; in units of L for a dimensionless scene.
    pub fn length(&self) -> Scale {
        self.pick(
            "m",
            1.0,
            Scale {
                unit: "",
                factor: 1.0,
            },
        )
    }

    /// Areas: m²; in units of L².
    pub fn area(&self) -> Scale {
        self.pick(
            "m²",
            1.0,
            Scale {
                unit: "L²",
                factor: 1.0,
            },
        )
    }

    /// Deflections (FullField w): mm; V for a dimensionless scene.
    pub fn deflection(&self) -> Scale {
        self.pick(
            "mm",
            1e3,
            Scale {
                unit: "",
                factor: 1.0,
            },
        )
    }

    /// Contact pressures (FullField pressure): kPa; σ = μ r for a dimensionless scene.
    pub fn pressure(&self) -> Scale {
        self.pick(
            "kPa",
            1e-3,
            Scale {
                unit: "",
                factor: self.mu,
            },
        )
    }

    /// Moments per unit length (ElementField mx, my, mxy): kN·m/m; in units of P.
    pub fn moment(&self) -> Scale {
        self.pick(
            "kN·m/m",
            1e-3,
            Scale {
                unit: "P",
                factor: 1.0,
            },
        )
    }

    /// Surface stresses (ElementField bottom, top; FullField s1_bottom, s1_top): MPa; in units
    /// of P/L².
    pub fn stress(&self) -> Scale {
        self.pick(
            "MPa",
            1e-6,
            Scale {
                unit: "P/L²",
                factor: 1.0,
            },
        )
    }

    /// Shear forces per unit length (ElementField qx, qy): kN/m; in units of P/L.
    pub fn shear(&self) -> Scale {
        self.pick(
            "kN/m",
            1e-3,
            Scale {
                unit: "P/L",
                factor: 1.0,
            },
        )
    }

    /// Forces (load and reaction resultants): kN; in units of P.
    pub fn force(&self) -> Scale {
        self.pick(
            "kN",
            1e-3,
            Scale {
                unit: "P",
                factor: 1.0,
            },
        )
    }

    /// Symbol of the shown deflection: w (physical) or V.
    pub fn deflection_symbol(&self) -> &'static str {
        if self.is_physical() {
            "w"
        } else {
            "V"
        }
    }

    /// Symbol of the shown pressure: r (physical) or σ.
    pub fn pressure_symbol(&self) -> &'static str {
        if self.is_physical() {
            "r"
        } else {
            "σ"
        }
    }

    /// The shown deflection of a dimensionless V: w = V P L² / D in the shown unit (mm or
    /// mils), or V itself.
    pub fn from_v(&self, v: f64) -> f64 {
        match self.physical {
            Some(ph) => self.deflection().apply(v * ph.deflection()),
            None => v,
        }
    }

    /// The shown pressure of a dimensionless σ: r = σ / μ · P / L² in the shown unit (kPa or
    /// psi), or σ itself.
    pub fn from_sigma(&self, sigma: f64) -> f64 {
        match self.physical {
            Some(ph) => self.pressure().apply(sigma / self.mu * ph.pressure()),
            None => sigma,
        }
    }

    /// The shown length of a length in units of L: metres (inches), or unchanged.
    pub fn from_l(&self, length: f64) -> f64 {
        match self.physical {
            Some(ph) => self.length().apply(length * ph.half_length),
            None => length,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 12 m × 8 m plate (L = 6 m, μ = 2/3) with P = 100 kN and D = 20 MN·m.
    fn slab() -> Units {
        Units::new(
            Some(Physical {
                half_length: 6.0,
                force: 1e5,
                rigidity: 2e7,
                units: crate::units::UnitSystem::Si,
            }),
            2.0 / 3.0,
        )
    }

    /// Conversions by hand: w = V P L² / D = V · 1e5 · 36 / 2e7 m = 0.18 V m = 180 V mm;
    /// r = σ P / (μ L²) = σ · 1e5 / (24) Pa = 4.1667 σ kPa.
    #[test]
    fn physical_units_convert_the_paper_groups_by_hand() {
        let u = slab();
        assert!(u.is_physical());
        assert!((u.from_v(0.01) - 1.8).abs() < 1e-12, "w of V = 0.01");
        assert!(
            (u.from_sigma(2.4) - 10.0).abs() < 1e-12,
            "r of σ = 2.4: 2.4 · 1e5 / 24 Pa = 10 kPa"
        );
        assert!((u.from_l(0.5) - 3.0).abs() < 1e-15, "half of L = 3 m");
        // One rounded multiplication each: a few ulps.
        assert!(
            (u.pressure().apply(53_200.0) - 53.2).abs() < 1e-13,
            "53 200 Pa in kPa"
        );
        assert!(
            (u.deflection().apply(0.001_774) - 1.774).abs() < 1e-14,
            "1.774 mm"
        );
        assert_eq!(u.moment().label("mx"), "mx (kN·m/m)");
        assert_eq!(u.shear().label("qx"), "qx (kN/m)");
        assert_eq!(u.length().label("x"), "x (m)");
        assert_eq!((u.deflection_symbol(), u.pressure_symbol()), ("w", "r"));
    }

    /// Dimensionless scenes keep V and σ: V passes through, the unit system's r becomes μ r.
    #[test]
    fn dimensionless_units_keep_v_and_sigma() {
        let u = Units::dimensionless(0.5);
        assert!(!u.is_physical());
        assert_eq!(u.from_v(0.25), 0.25);
        assert_eq!(u.from_sigma(0.25), 0.25);
        assert_eq!(u.from_l(0.25), 0.25);
        assert_eq!(u.pressure().apply(3.0), 1.5, "σ = μ r");
        assert_eq!(u.length().label("x"), "x");
        assert_eq!(u.pressure().label("σ"), "σ");
        assert_eq!(u.moment().label("mx"), "mx (P)");
        assert_eq!((u.deflection_symbol(), u.pressure_symbol()), ("V", "σ"));
    }
}
