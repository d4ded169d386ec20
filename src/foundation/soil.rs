//! What every soil knows, as one trait: [`SoilModel`]. A soil is a value (its own constants as
//! dimensionless groups beside the Γ of [`crate::model::Groups`]) and one file under
//! `foundation/` that implements this trait — its scene keys with their units, their validation
//! (SI and dimensionless), its kernel or compliance, its settlement estimate, its names and its
//! line in the solve table, its meshes in the stability study — and one line in the `soils!`
//! list of `foundation/mod.rs`, which makes the [`super::Soil`] and [`super::FoundationKind`]
//! enums and their dispatch.
//!
//! The scene's `[foundation]` and `[dimensionless]` sections hand a soil its keys as a map
//! ([`SoilKeys`]): the soil reads the ones it declares and refuses the others, naming the soil
//! they belong to.

use std::collections::BTreeMap;

use serde::Deserialize;

use super::kernel::Kernel;
use super::FoundationKind;
use crate::check::{finite_positive, poisson};
use crate::error::{Error, Result};

/// One value of a soil's key in a scene: a number or a word (the elastic layer's base), or
/// something else, kept to be refused by the soil with the key's name (an array, a table, …).
#[derive(Debug, Clone, PartialEq)]
pub enum KeyValue {
    /// A number (TOML integers too).
    Number(f64),
    /// A word.
    Word(String),
    /// Any other value: what it is ("a boolean", "an array", …).
    Other(&'static str),
}

impl<'de> Deserialize<'de> for KeyValue {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        d.deserialize_any(KeyValueVisitor)
    }
}

/// Reads any value into a [`KeyValue`], so that a wrong type is refused by the soil that reads
/// the key, naming it, rather than by serde at the section.
struct KeyValueVisitor;

impl<'de> serde::de::Visitor<'de> for KeyValueVisitor {
    type Value = KeyValue;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a number or a word")
    }

    fn visit_f64<E>(self, v: f64) -> std::result::Result<KeyValue, E> {
        Ok(KeyValue::Number(v))
    }

    fn visit_i64<E>(self, v: i64) -> std::result::Result<KeyValue, E> {
        Ok(KeyValue::Number(v as f64))
    }

    fn visit_u64<E>(self, v: u64) -> std::result::Result<KeyValue, E> {
        Ok(KeyValue::Number(v as f64))
    }

    fn visit_str<E>(self, v: &str) -> std::result::Result<KeyValue, E> {
        Ok(KeyValue::Word(v.to_string()))
    }

    fn visit_bool<E>(self, _: bool) -> std::result::Result<KeyValue, E> {
        Ok(KeyValue::Other("a boolean"))
    }

    fn visit_unit<E>(self) -> std::result::Result<KeyValue, E> {
        Ok(KeyValue::Other("nothing"))
    }

    fn visit_seq<A: serde::de::SeqAccess<'de>>(
        self,
        mut seq: A,
    ) -> std::result::Result<KeyValue, A::Error> {
        while seq.next_element::<serde::de::IgnoredAny>()?.is_some() {}
        Ok(KeyValue::Other("an array"))
    }

    fn visit_map<A: serde::de::MapAccess<'de>>(
        self,
        mut map: A,
    ) -> std::result::Result<KeyValue, A::Error> {
        while map
            .next_entry::<serde::de::IgnoredAny, serde::de::IgnoredAny>()?
            .is_some()
        {}
        Ok(KeyValue::Other("a table"))
    }
}

impl From<f64> for KeyValue {
    fn from(v: f64) -> Self {
        KeyValue::Number(v)
    }
}

impl From<&str> for KeyValue {
    fn from(v: &str) -> Self {
        KeyValue::Word(v.to_string())
    }
}

/// The soil's keys of one scene section, by name.
pub type KeyMap = BTreeMap<String, KeyValue>;

/// A key a soil reads, with its unit as written in messages and the README.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Key {
    /// Its name in the section.
    pub name: &'static str,
    /// Its unit (SI), or what the dimensionless group is.
    pub unit: &'static str,
}

/// A key `name` in `unit`.
pub const fn key(name: &'static str, unit: &'static str) -> Key {
    Key { name, unit }
}

/// The plate's groups Δ, μ and ν_p, which a soil completes, and in SI scenes the plate's
/// half-length L (m) and rigidity D (N·m) that make the soil's constants dimensionless.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlateScale {
    /// Δ.
    pub delta: f64,
    /// μ.
    pub mu: f64,
    /// ν_p.
    pub nu: f64,
    /// L, m (SI scenes; 1 in dimensionless ones).
    pub half_length: f64,
    /// D, N·m (SI scenes; 1 in dimensionless ones).
    pub rigidity: f64,
}

impl PlateScale {
    /// Γ_w = D / (k μ L⁴) of springs of modulus `k` (N/m³).
    pub fn spring_gamma(&self, k: f64) -> f64 {
        self.rigidity / (k * self.mu * self.half_length.powi(4))
    }

    /// Γ_h = D (1 − ν_s²) / (π E_s μ L³) of an elastic soil of E_s (Pa) and ν_s.
    pub fn elastic_gamma(&self, e: f64, nu: f64) -> f64 {
        self.rigidity * (1.0 - nu * nu)
            / (std::f64::consts::PI * e * self.mu * self.half_length.powi(3))
    }
}

/// How a soil is named in the paper's outputs: a label for text, a short one for legends and a
/// file-name stem.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SoilNames {
    /// "elastic half-space".
    pub label: &'static str,
    /// "half-space".
    pub short: &'static str,
    /// "halfspace".
    pub stem: &'static str,
}

/// A scene section's keys as one soil reads them: the section's name (`foundation` or
/// `dimensionless`), the soil chosen and the keys given.
#[derive(Debug, Clone, Copy)]
pub struct SoilKeys<'a> {
    /// "foundation" or "dimensionless".
    pub section: &'static str,
    /// The soil the section names.
    pub kind: FoundationKind,
    /// The keys given beyond the section's common ones.
    pub keys: &'a KeyMap,
}

impl SoilKeys<'_> {
    /// `section.name`.
    pub fn field(&self, name: &str) -> String {
        format!("{}.{name}", self.section)
    }

    /// The key that chooses the soil: `model` in `[foundation]`, `foundation` in
    /// `[dimensionless]`.
    fn chooser(&self) -> &'static str {
        if self.section == "foundation" {
            "model"
        } else {
            "foundation"
        }
    }

    /// Whether `name` is given.
    pub fn has(&self, name: &str) -> bool {
        self.keys.contains_key(name)
    }

    /// The number `name`, if given (an error if it is a word).
    pub fn number(&self, name: &str) -> Result<Option<f64>> {
        match self.keys.get(name) {
            None => Ok(None),
            Some(KeyValue::Number(v)) => Ok(Some(*v)),
            Some(KeyValue::Word(w)) => Err(Error::invalid(
                self.field(name),
                format!("must be a number, got \"{w}\""),
            )),
            Some(KeyValue::Other(what)) => Err(Error::invalid(
                self.field(name),
                format!("must be a number, got {what}"),
            )),
        }
    }

    /// The word `name`, if given (an error if it is a number).
    pub fn word(&self, name: &str) -> Result<Option<&str>> {
        match self.keys.get(name) {
            None => Ok(None),
            Some(KeyValue::Word(w)) => Ok(Some(w)),
            Some(KeyValue::Number(v)) => Err(Error::invalid(
                self.field(name),
                format!("must be a word (in quotes), got {v}"),
            )),
            Some(KeyValue::Other(what)) => Err(Error::invalid(
                self.field(name),
                format!("must be a word (in quotes), got {what}"),
            )),
        }
    }

    /// The number `name`, or an error naming it as missing, with `what` it is.
    pub fn given(&self, name: &str, what: &str) -> Result<f64> {
        self.number(name)?
            .ok_or_else(|| Error::invalid(self.field(name), format!("missing: {what}")))
    }

    /// The number `name` given, finite and positive (in `unit`).
    pub fn positive(&self, name: &str, what: &str, unit: &str) -> Result<f64> {
        finite_positive(&self.field(name), self.given(name, what)?, unit)
    }

    /// The Poisson's ratio `name`, given.
    pub fn poisson(&self, name: &str, what: &str) -> Result<f64> {
        poisson(&self.field(name), self.given(name, what)?)
    }

    /// Refuse every key not in `allowed`, naming the soil it belongs to (the first of
    /// [`FoundationKind::ALL`] that reads it) or, for a key no soil reads, the keys this one
    /// takes. `allowed` are this soil's keys of this section.
    pub fn only(&self, allowed: &[Key]) -> Result<()> {
        let dimensionless = self.section != "foundation";
        // The keys every soil reads, in the soils' order: a refused key is named in that order
        // (not the map's alphabetical one), so `youngs_modulus` before `poissons_ratio`.
        let known: Vec<&str> = <FoundationKind as crate::choice::Choice>::ALL
            .iter()
            .flat_map(|f| f.keys(dimensionless).iter().map(|k| k.name))
            .collect();
        let rank = |k: &str| known.iter().position(|n| *n == k).unwrap_or(usize::MAX);
        let Some(name) = self
            .keys
            .keys()
            .filter(|k| !allowed.iter().any(|a| a.name == k.as_str()))
            .min_by_key(|k| rank(k))
        else {
            return Ok(());
        };
        let takes = if allowed.is_empty() {
            format!("a {} foundation takes no keys of its own here", self.kind)
        } else {
            format!(
                "a {} foundation takes {}",
                self.kind,
                allowed
                    .iter()
                    .map(|k| format!("`{}` ({})", k.name, k.unit))
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        };
        let owner = <FoundationKind as crate::choice::Choice>::ALL
            .iter()
            .copied()
            .find(|f| {
                f.keys(dimensionless)
                    .iter()
                    .any(|k| k.name == name.as_str())
            });
        Err(Error::invalid(
            self.field(name),
            match owner {
                Some(owner) => format!(
                    "belongs to {} = \"{owner}\"; {takes} (leave it out, or choose {} = \"{owner}\")",
                    self.chooser(),
                    self.chooser()
                ),
                None => format!(
                    "unknown field `{name}`: {takes}, beside {}`allowable_pressure`, `bearing_length` and `zone`",
                    if dimensionless { "`foundation`, `gamma`, `delta`, `mu`, `nu`, " } else { "`model`, " }
                ),
            },
        ))
    }
}

/// What every soil knows. Implemented once per soil, in its own file under `foundation/`.
pub trait SoilModel: Sized + Copy {
    /// True for a local soil (T diagonal: Winkler springs); every other soil is a non-local
    /// surface kernel with a dense (or FFT-applied) T.
    const LOCAL: bool;

    /// Its names in the paper's outputs.
    const NAMES: SoilNames;

    /// The keys of `[foundation]` it reads (SI), beyond `model`, `allowable_pressure`,
    /// `bearing_length`, `zone`.
    const SI_KEYS: &'static [Key];

    /// The keys of `[dimensionless]` it reads, beyond `foundation`, `gamma`, `delta`, `mu`,
    /// `nu`, `allowable_pressure`, `bearing_length`, `zone`.
    const GROUP_KEYS: &'static [Key];

    /// The soil and its Γ from `[foundation]` in SI units under `plate`.
    fn from_si(keys: &SoilKeys<'_>, plate: &PlateScale) -> Result<(f64, Self)>;

    /// The soil from `[dimensionless]`, its Γ = `gamma` already checked.
    fn from_groups(keys: &SoilKeys<'_>, plate: &PlateScale, gamma: f64) -> Result<Self>;

    /// Its surface kernel in the unit system (L = D = 1) for Γ = `gamma` and aspect `mu`; None
    /// for a local soil.
    fn kernel(&self, gamma: f64, mu: f64) -> Option<Kernel>;

    /// The mean settlement, in units of V, under a unit load resultant (4P = 4) spread over the
    /// plate of area 4μ, with foundation constant `c` = μΓ: the scale against which a void's
    /// depth is checked.
    fn settlement(&self, c: f64, mu: f64) -> f64;

    /// The plate's radius of relative stiffness on this soil in the unit system (L = D = 1),
    /// for the foundation constant `c` = μΓ: the length below which the plate's bending
    /// compliance exceeds the soil's (a pressure wave of wavenumber ξ > 1/ℓ is carried by the
    /// soil's compliance less than by the plate's). Springs: ℓ⁴ = D/k = c; elastic soils:
    /// ℓ³ = 2(1 − ν_s²)D/E_s = 2πc.
    fn stiffness_length(c: f64) -> f64;

    /// What the solve table adds after Γ (", Γ_g = …"); empty for a soil of Γ alone.
    fn describe(&self, gamma: f64, mu: f64) -> String {
        let _ = (gamma, mu);
        String::new()
    }

    /// A length the soil derives that summary.json reports (the Pasternak decay length λ/L).
    fn decay_length(&self, gamma: f64, mu: f64) -> Option<f64> {
        let _ = (gamma, mu);
        None
    }

    /// Elements per side of the stability study's mesh sweep on this soil.
    fn stability_meshes() -> Vec<f64> {
        // Non-local soils: the dense QP is refused at 512 per side; the penalty takes the
        // iterative route there (`Route::Auto`) and solves it.
        vec![8.0, 16.0, 32.0, 64.0, 128.0, 512.0]
    }
}

/// Upper limit of the Pasternak decay length λ/L = √(Γ_g μ Γ_w). Beyond it the shear layer
/// spreads a load over more than a thousand plate lengths: the kernel is then a large constant
/// plus a small logarithmic variation over the plate, and T loses the digits that tell its
/// entries apart — the soil acts like a membrane of tension G_p, better modelled as such.
pub const MAX_PASTERNAK_LENGTH: f64 = 1e3;

/// Check the decay length the shear parameter `shear` = Γ_g gives with Γ_w = `gamma`, and
/// return Γ_g (the shear layer of a Pasternak or a Kerr soil).
pub fn shear_layer(field: &str, shear: f64, gamma: f64, mu: f64) -> Result<f64> {
    let lambda = (shear * mu * gamma).sqrt();
    if !(lambda.is_finite() && lambda > 0.0) || lambda > MAX_PASTERNAK_LENGTH {
        return Err(Error::invalid(
            field,
            format!("gives the decay length λ = √(G_p/k) = {lambda:e} half-lengths L of the plate, outside (0, {MAX_PASTERNAK_LENGTH:e}]: check the units (G_p in N/m, k in N/m³) or lower the shear modulus"),
        ));
    }
    Ok(shear)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::choice::Choice;

    /// Every soil refuses every key it does not read, naming a soil that reads it — the
    /// registry's refusal, checked across the whole list rather than case by case — and reads
    /// its own keys without that refusal.
    #[test]
    fn each_soil_refuses_the_keys_of_the_others_naming_their_owner() {
        for dimensionless in [false, true] {
            let section = if dimensionless {
                "dimensionless"
            } else {
                "foundation"
            };
            for &kind in FoundationKind::ALL {
                let own = kind.keys(dimensionless);
                for &other in FoundationKind::ALL {
                    for k in other.keys(dimensionless) {
                        let keys: KeyMap = [(k.name.to_string(), KeyValue::Number(1.0))].into();
                        let given = SoilKeys {
                            section,
                            kind,
                            keys: &keys,
                        };
                        let read = own.iter().any(|o| o.name == k.name);
                        match (given.only(own), read) {
                            (Ok(()), true) => {}
                            (Err(Error::Invalid { field, message }), false) => {
                                assert_eq!(field, format!("{section}.{}", k.name));
                                let owner = FoundationKind::ALL.iter().find(|f| {
                                    message.starts_with("belongs to ")
                                        && message.contains(&format!("= \"{f}\";"))
                                });
                                assert!(
                                    owner.is_some_and(|f| f
                                        .keys(dimensionless)
                                        .iter()
                                        .any(|x| x.name == k.name)),
                                    "{kind} refusing {section}.{}: {message}",
                                    k.name
                                );
                            }
                            (r, _) => panic!("{kind} given {section}.{}: {r:?}", k.name),
                        }
                    }
                }
            }
        }
    }

    /// A key no soil reads is called unknown, with the keys this soil takes.
    #[test]
    fn an_unknown_key_lists_the_soils_own() {
        let keys: KeyMap = [("modulsu".to_string(), KeyValue::Number(1.0))].into();
        let given = SoilKeys {
            section: "foundation",
            kind: FoundationKind::Winkler,
            keys: &keys,
        };
        match given.only(FoundationKind::Winkler.keys(false)) {
            Err(Error::Invalid { field, message }) => {
                assert_eq!(field, "foundation.modulsu");
                assert!(
                    message.contains("unknown field") && message.contains("`modulus` (N/m³)"),
                    "{message}"
                );
            }
            r => panic!("{r:?}"),
        }
    }
}
