//! Scene files (TOML): the plate, its foundation, the loads, the mesh and the solver settings,
//! validated into a [`Problem`]: a method-free [`Model`] in the solver's unit system (see
//! [`crate::model`]) and the [`Method`] that solves it.
//!
//! Two equivalent forms are accepted. A *physical* scene gives `[plate]` and `[foundation]` in SI
//! units; a *dimensionless* scene gives the paper's groups in `[dimensionless]` (eq. 4.1) and
//! positions as (s, t) ∈ [−1, 1]². Both become the same [`Model`].
//!
//! * [`spec`]: the serde types of the sections, with their defaults;
//! * [`validate`]: one function per section;
//! * `bearing`: the bearing check's `allowable_pressure` and `bearing_length`;
//! * the soils read their own keys ([`crate::foundation::soil`]);
//! * `joints` and `panels`: `[[joint]]` and `[[panel]]` into the model's
//!   [`crate::layout::Layout`], and the loads a joint line would split;
//! * `outline`: `[plate] outline` and `[[opening]]` into the same layout, and the loads that
//!   would fall off the plate;
//! * [`builder`]: [`Model::builder`], the same validation from Rust without writing TOML.

mod bearing;
pub mod builder;
pub mod convert;
mod joints;
mod load_spec;
mod loads;
mod outline;
pub mod overrides;
mod panels;
pub mod plausible;
pub mod spec;
pub mod temperature;
pub mod validate;
pub mod vehicles;

pub use builder::ModelBuilder;
pub use loads::{DEFAULT_CASE, MAX_VOID_DEPTH_RATIO};
pub(crate) use outline::scene_shape;
pub use overrides::{Overrides, OPTIONS};
pub use spec::*;

use crate::error::{Error, Result};
use crate::method::{Method, Route};
use crate::model::Model;

/// One `[[combination]]` of a scene: its factors and the model of its factored loads (its own
/// P, so that it is exactly the scene those loads would make on their own).
#[derive(Debug, Clone)]
pub struct Combination {
    /// Name (a folder name).
    pub name: String,
    /// Factor per load case, as written.
    pub factors: Vec<(String, f64)>,
    /// The model of the factored loads.
    pub model: Model,
}

impl Combination {
    /// The scene's title, without the combination's name that the model's title carries.
    pub fn scene_title(&self) -> &str {
        scene_title(&self.model.title, &self.name)
    }
}

/// A combination model's title ("scene — NAME") without its combination's name.
pub fn scene_title<'a>(title: &'a str, combination: &str) -> &'a str {
    title
        .strip_suffix(&format!(" — {combination}"))
        .unwrap_or(title)
}

/// A validated scene: what to solve, how, and within how much memory.
#[derive(Debug, Clone)]
pub struct Problem {
    /// The model: all loads together, or with `[[combination]]`s the first combination's.
    pub model: Model,
    /// The combinations; empty when the scene has none (all loads act together).
    pub combinations: Vec<Combination>,
    /// The method of `[solver]`.
    pub method: Method,
    /// How the half-space penalty steps are solved (`[solver] route`).
    pub route: Route,
    /// Memory the solver may use, bytes.
    pub memory_limit: f64,
    /// Values that suggest a unit slip, each naming its key ([`plausible`]); the scene still
    /// solves.
    pub warnings: Vec<String>,
    /// The traffic, climate and fatigue relation of `liftoff damage` (None: the scene has no
    /// `[traffic]`/`[damage]`).
    pub damage: Option<crate::damage::plan::DamagePlan>,
    /// What the scene says the plate's ends across x are (`[plate] ends`; None: it says
    /// nothing, and a study takes its `[traffic]`'s or reads the plate whole, `study::ends`).
    pub ends: Option<crate::layout::Ends>,
}

impl SceneFile {
    /// Parse TOML text. A scene in US customary units (`units = "us"`) is converted to SI
    /// first ([`convert::scene_to_si`]); one in SI is read directly, so that a parse error
    /// names its line.
    pub fn parse(text: &str) -> Result<Self> {
        let table: toml::Table = toml::from_str(text).map_err(|e| Error::Parse(e.to_string()))?;
        if !table.contains_key("units") {
            return toml::from_str(text).map_err(|e| Error::Parse(e.to_string()));
        }
        let value = serde_json::to_value(&table).map_err(|e| Error::Parse(e.to_string()))?;
        // The conversion changes numbers only: a file that does not fit the scene's types
        // fails the same way unconverted, where TOML's message names the key and its line.
        Self::from_value(value).map_err(|e| match toml::from_str::<SceneFile>(text) {
            Err(raw) => Error::Parse(raw.to_string()),
            Ok(_) => e,
        })
    }

    /// Parse a scene given as JSON with the scene file's keys (a Python dict, say).
    pub fn from_json(text: &str) -> Result<Self> {
        let value: serde_json::Value =
            serde_json::from_str(text).map_err(|e| Error::Parse(e.to_string()))?;
        Self::from_value(value)
    }

    /// A scene from its keys as a JSON value, in the unit system its `units` names.
    fn from_value(mut value: serde_json::Value) -> Result<Self> {
        let system = convert::scene_system(&value)?;
        convert::scene_to_si(&mut value, system)?;
        serde_json::from_value(value).map_err(|e| Error::Parse(e.to_string()))
    }

    /// A bundled scene (`example:NAME` on the command line), parsed.
    pub fn example(name: &str) -> Result<Self> {
        let text = crate::examples::scene(name).ok_or_else(|| {
            let names: Vec<&str> = crate::examples::SCENES.iter().map(|s| s.0).collect();
            Error::invalid(
                "scene",
                format!(
                    "no bundled example `{name}`; the examples are: {}",
                    names.join(", ")
                ),
            )
        })?;
        Self::parse(text)
    }

    /// Validate and convert to the unit system. A scene in US units is checked after its
    /// conversion to SI: a message that quotes SI values says so, naming the factor back.
    pub fn validate(&self) -> Result<Problem> {
        validate::problem(self).map_err(|e| match (self.units, e) {
            (crate::units::UnitSystem::Us, Error::Invalid { field, message })
                if quotes_si(&message) =>
            {
                Error::Invalid {
                    field,
                    message: format!(
                        "{message} (its numbers in SI: a US scene is checked after its conversion; 1 in = 0.0254 m, 1 lbf = 4.448 N, 1 psi = 6895 Pa)"
                    ),
                }
            }
            (_, e) => e,
        })
    }
}

/// Whether a message quotes a value in an SI unit: a digit, or a closing bracket after one,
/// then ` m`, ` Pa`, ` N`, ` kN`, ` MN/m³`, ` N/m³` or ` K` as a word of its own.
fn quotes_si(message: &str) -> bool {
    const UNITS: [&str; 7] = ["m", "Pa", "N", "kN", "MN/m³", "N/m³", "K"];
    let words: Vec<&str> = message.split(' ').collect();
    words.windows(2).any(|w| {
        let unit = w[1].trim_end_matches(|c: char| ",.:;)]".contains(c));
        let number = w[0].trim_end_matches(|c: char| ")]".contains(c));
        UNITS.contains(&unit) && number.ends_with(|c: char| c.is_ascii_digit())
    })
}

impl Problem {
    /// Parse and validate scene text.
    pub fn from_toml(text: &str) -> Result<Self> {
        SceneFile::parse(text)?.validate()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{loads_symmetric, Load};

    const PHYSICAL: &str = r#"
[plate]
length = 6.0
width = 4.0
thickness = 0.25
youngs_modulus = 30e9
poissons_ratio = 0.2
[foundation]
model = "winkler"
modulus = 5e7
[[load]]
kind = "point"
x = 1.5
y = 1.0
force = 2.0e5
[[load]]
kind = "uniform"
pressure = 6.0e3
[mesh]
elements = [48, 32]
symmetry = "auto"
[solver]
contact = "unbonded"
method = "penalty"
penalty = 1e-5
constraint = "nodal"
"#;

    #[test]
    fn the_documented_physical_scene_parses() {
        let p = Problem::from_toml(PHYSICAL).unwrap().model;
        assert_eq!(p.elements, [48, 32]);
        assert!((p.groups.mu - 4.0 / 6.0).abs() < 1e-15);
        // Resultant 2e5 + 6e3 · 24 = 344 kN, so P = 86 kN and the loads sum to 4P.
        assert!((p.resultant() - 4.0).abs() < 1e-12);
        assert!((p.physical.unwrap().force - 86_000.0).abs() < 1e-6);
        // Γ_w = D / (K μ L⁴) with D = E H³ / (12 (1 − ν²)).
        let d = 30e9 * 0.25f64.powi(3) / (12.0 * (1.0 - 0.04));
        let gw = d / (5e7 * (4.0 / 6.0) * 3f64.powi(4));
        assert!((p.groups.gamma - gw).abs() < 1e-12 * gw);
    }

    #[test]
    fn the_paper_groups_match_eq_4_1() {
        // Eq. (4.1e) written out for the half-space and Winkler groups.
        let (e, nu, h, l, w) = (2.0e10, 0.3, 0.1, 1.0, 1.0);
        let (es, nus, k) = (3.0e7, 0.25, 4.0e7);
        let mu = w / l;
        let gh = 1.0 / (12.0 * std::f64::consts::PI) * (1.0 - nus * nus) / (1.0 - nu * nu) * e / es
            * (h / (mu * l))
            * (h / l).powi(2);
        let gw = 1.0 / (12.0 * (1.0 - nu * nu)) * e / (k * l) * (h / (mu * l)) * (h / l).powi(2);
        let delta = 1.0 / (6.0 * (5.0 / 6.0) * (1.0 - nu)) * (h / (mu * l)) * (h / l);
        let scene = |found: &str| {
            format!(
                "[plate]\nlength = {}\nwidth = {}\nthickness = {h}\nyoungs_modulus = {e}\npoissons_ratio = {nu}\n{found}\n[[load]]\nkind = \"point\"\nx = 0.0\ny = 0.0\nforce = 1.0\n",
                2.0 * l,
                2.0 * w
            )
        };
        let ph = Problem::from_toml(&scene(&format!(
            "[foundation]\nmodel = \"half-space\"\nyoungs_modulus = {es}\npoissons_ratio = {nus}"
        )))
        .unwrap()
        .model;
        let pw = Problem::from_toml(&scene(&format!(
            "[foundation]\nmodel = \"winkler\"\nmodulus = {k}"
        )))
        .unwrap()
        .model;
        assert!(
            (ph.groups.gamma - gh).abs() < 1e-12 * gh,
            "Γ_h {} vs eq. 4.1e {gh}",
            ph.groups.gamma
        );
        assert!(
            (pw.groups.gamma - gw).abs() < 1e-12 * gw,
            "Γ_w {} vs eq. 4.1e {gw}",
            pw.groups.gamma
        );
        assert!(
            (ph.groups.delta - delta).abs() < 1e-12 * delta,
            "Δ {} vs eq. 4.1d {delta}",
            ph.groups.delta
        );
        // The paper's own Δ for H/L = 0.1, ν = 0.3, χ = 5/6, μ = 1 is 0.002857.
        assert!((ph.groups.delta - 0.002857).abs() < 1e-6);
    }

    #[test]
    fn symmetry_of_load_sets() {
        let a = Load::Point {
            x: 0.5,
            y: 0.2,
            force: 1.0,
        };
        let b = Load::Point {
            x: -0.5,
            y: 0.2,
            force: 1.0,
        };
        assert!(loads_symmetric(&[a, b], true));
        assert!(!loads_symmetric(&[a, b], false));
        assert!(!loads_symmetric(&[a], true));
        let p = Load::Patch {
            x: [-1.0, 0.0],
            y: [-0.5, 0.5],
            pressure: 2.0,
        };
        let q = Load::Patch {
            x: [0.0, 1.0],
            y: [-0.5, 0.5],
            pressure: 2.0,
        };
        assert!(loads_symmetric(&[p, q], true) && loads_symmetric(&[p, q], false));
    }
}
