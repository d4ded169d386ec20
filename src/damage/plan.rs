//! What a damage run sums over: the scene's `[traffic]` (design life, growth, axle groups with
//! their load spectra, lateral wander), `[climate]` (bins of temperature difference with their
//! share of the traffic) and `[damage]` (the fatigue relation, the modulus of rupture, the
//! positions of a pass). [`DamagePlan::new`] checks them against the model — every bad value an
//! error naming its key — and [`DamagePlan::bins`] lists the cases a run solves.
//!
//! **Lateral wander.** The outer tire's edge runs at a distance from the slab's edge that is
//! normally distributed (mean and standard deviation: the MEPDG's defaults are 18 in and 10 in,
//! NCHRP 1-37A Part 3 Ch. 4 — as the notes of issue 33 give them); `positions` lateral positions
//! take the mass of equal-width bands of ±2.5 standard deviations around the mean, each at its
//! band's centre, the weights normalised to one (a band that would put the outer tire off the
//! slab is moved to the edge). One position takes the mean with weight one.

use serde::Deserialize;

use crate::damage::strength::AgeSchedule;
use crate::error::{Error, Result};

/// How a climate bin's profile (depths, temperatures) splits: its equivalent linear difference
/// (K, top minus bottom) and its nonlinear part at the top and the bottom face (K).
pub type ProfileSplit<'a> = dyn Fn(&[f64], &[f64]) -> (f64, [f64; 2]) + 'a;

/// `[traffic]` of a scene.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TrafficSpec {
    /// Design life, years.
    pub design_life: f64,
    /// Yearly growth of every group's repetitions (0.02: 2 % a year, compound).
    #[serde(default)]
    pub growth: f64,
    /// Lateral wander of the outer tire.
    #[serde(default)]
    pub wander: WanderSpec,
    /// The edge the traffic runs along: `y-` (the default; travel along x) or `y+`.
    #[serde(default = "default_edge")]
    pub edge: String,
    /// Where that edge is, m: the line y = this, such as the joint between the lane and a tied
    /// shoulder (absent: the plate's own edge, y = ∓b/2). The lane lies on its +y side for
    /// `y-`, on its −y side for `y+`.
    #[serde(default)]
    pub edge_at: Option<f64>,
    /// What the plate's ends across the lane (x = ±a/2) are: `cut` (the default) — where the
    /// model cuts a lane that goes on, so that on a plate with transverse joints its end
    /// panels are the neighbours the inner ones need and count for nothing themselves (their
    /// damage is mapped, not summed into the governing places, the cracking or a design; the
    /// erosion at their outer corners likewise) — or `free`: the lane ends there (a bridge, a
    /// free end), and every element and corner counts.
    #[serde(default)]
    pub ends: Option<String>,
    /// The axle groups and gears with their load spectra.
    #[serde(default)]
    pub group: Vec<GroupSpec>,
}

fn default_edge() -> String {
    "y-".into()
}

/// `[traffic.wander]`: where the outer tire runs.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WanderSpec {
    /// Mean distance of the outer tire's edge from the slab's edge, m.
    pub mean: f64,
    /// Its standard deviation, m.
    pub deviation: f64,
    /// Lateral positions the distribution is split into.
    pub positions: usize,
}

impl Default for WanderSpec {
    /// The MEPDG's defaults, 18 in and 10 in, in three positions.
    fn default() -> Self {
        Self {
            mean: 18.0 * crate::units::INCH,
            deviation: 10.0 * crate::units::INCH,
            positions: 3,
        }
    }
}

/// `[[traffic.group]]`: one axle group or gear of the scene and its load spectrum.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GroupSpec {
    /// The `name` of the scene's `axle` or `gear` load whose wheels this group has.
    pub load: String,
    /// The group's total load at each level, N (the prints keep the scene's size; their
    /// pressure follows the level).
    pub levels: Vec<f64>,
    /// Repetitions in the first year at each level.
    pub repetitions: Vec<f64>,
}

/// `[climate]` of a scene.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ClimateSpec {
    /// The bins of temperature difference (top minus bottom) and their share of the traffic.
    #[serde(default)]
    pub bin: Vec<ClimateBinSpec>,
}

/// `[[climate.bin]]`: a temperature difference or a gradient, with its share.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ClimateBinSpec {
    /// Temperature difference, top minus bottom, K (linear through the thickness).
    #[serde(default)]
    pub difference: Option<f64>,
    /// Or the gradient, top minus bottom over the thickness, K/m: the difference is the
    /// gradient times the slab's thickness, so it follows the thickness in a design search.
    #[serde(default)]
    pub gradient: Option<f64>,
    /// Or a temperature profile: depths from the top surface (m, from 0; read over the slab's
    /// thickness in proportion to the last, so that it follows the thickness in a design
    /// search) …
    #[serde(default)]
    pub depths: Option<Vec<f64>>,
    /// … and the temperatures there (°C): the equivalent linear difference curls the slab,
    /// the rest adds its own stress to the faces, as a `temperature-profile` load.
    #[serde(default)]
    pub temperatures: Option<Vec<f64>>,
    /// The Winkler soil's modulus in this bin, N/m³ (a month's, a season's; absent: the
    /// scene's). Its zones keep their ratio to it.
    #[serde(default)]
    pub subgrade_modulus: Option<f64>,
    /// Share of the traffic that passes in this bin (the shares add up to one).
    pub share: f64,
}

/// `[damage]` of a scene.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DamageSpec {
    /// The fatigue relation: `pca`, `mepdg` or `faa`.
    pub model: String,
    /// Modulus of rupture (flexural strength) of the concrete at 28 days, Pa.
    pub modulus_of_rupture: f64,
    /// How it grows with age: `none` (the default: one MR for the whole life) or `mepdg`
    /// (the MEPDG's strength gain, month by month: [`crate::damage::strength`]).
    #[serde(default)]
    pub rupture_growth: Option<String>,
    /// Positions of a pass along the lane (absent: one per element along x, so that every
    /// element's largest stress of the pass is taken within half an element of its peak).
    #[serde(default)]
    pub steps: Option<usize>,
    /// Reliability of the MEPDG's cracking (0.5 … 0.9999; absent: the mean).
    #[serde(default)]
    pub reliability: Option<f64>,
    /// The relation's coefficients for a local calibration (absent: the pinned edition's).
    #[serde(default)]
    pub coefficients: serde_json::Map<String, serde_json::Value>,
    /// Fill a level between two whose solutions have the same contact set by their linear
    /// interpolation, which is then exact (true, the default), or solve every level.
    #[serde(default = "yes")]
    pub interpolate: bool,
}

fn yes() -> bool {
    true
}

/// One group's load level: its total load (N) and repetitions in the first year.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Level {
    /// Total load of the group, N.
    pub load: f64,
    /// First-year repetitions.
    pub repetitions: f64,
}

/// One axle group or gear and its spectrum.
#[derive(Debug, Clone, PartialEq)]
pub struct Group {
    /// The scene load's name.
    pub load: String,
    /// Its index among the model's vehicles.
    pub vehicle: usize,
    /// The levels.
    pub levels: Vec<Level>,
}

/// A lateral position: the outer tire's edge at `offset` m from the slab's edge, taking
/// `weight` of the traffic.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lateral {
    /// Distance of the outer tire's edge from the slab's edge, m.
    pub offset: f64,
    /// Share of the traffic.
    pub weight: f64,
}

/// A climate bin: the temperature difference and its share.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Climate {
    /// Top minus bottom, K (a profile's equivalent linear difference).
    pub difference: f64,
    /// A profile's nonlinear part at the top and the bottom face, K ([0, 0] for a difference
    /// or a gradient): its self-equilibrated stress adds to the faces' stresses.
    pub nonlinear: [f64; 2],
    /// The Winkler soil's modulus in this bin, N/m³ (None: the scene's).
    pub subgrade_modulus: Option<f64>,
    /// Share of the traffic.
    pub share: f64,
}

/// One case of the sum: a group at a level, at a lateral position, in a climate bin, passing
/// once over the slab; `repetitions` such passes over the design life.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bin {
    /// Index into [`DamagePlan::groups`].
    pub group: usize,
    /// Index into the group's levels.
    pub level: usize,
    /// Index into [`DamagePlan::lateral`].
    pub lateral: usize,
    /// Index into [`DamagePlan::climate`].
    pub climate: usize,
    /// Passes over the design life.
    pub repetitions: f64,
}

/// The checked inputs of a damage run.
#[derive(Debug, Clone, PartialEq)]
pub struct DamagePlan {
    /// Design life, years.
    pub design_life: f64,
    /// Yearly growth.
    pub growth: f64,
    /// The lane lies on the +y side of its outer edge (false: on the −y side).
    pub lower_edge: bool,
    /// The outer edge's y, m (None: the plate's edge on that side).
    pub edge_at: Option<f64>,
    /// The groups.
    pub groups: Vec<Group>,
    /// The lateral positions.
    pub lateral: Vec<Lateral>,
    /// The climate bins (one bin of the scene's own temperature loads when `[climate]` has
    /// none).
    pub climate: Vec<Climate>,
    /// The fatigue relation.
    pub model: crate::damage::relations::DamageModel,
    /// Modulus of rupture (at 28 days where it grows), Pa.
    pub rupture: f64,
    /// The months of the life with the MR's growth (None: one MR for the whole life).
    pub ages: Option<AgeSchedule>,
    /// Positions of a pass (None: one per element along x).
    pub steps: Option<usize>,
    /// The MEPDG's reliability, if given.
    pub reliability: Option<f64>,
    /// Interpolate between levels with the same contact set ([`DamageSpec::interpolate`]).
    pub interpolate: bool,
    /// The plate's ends across the lane cut a lane that goes on ([`TrafficSpec::ends`]).
    pub cut: bool,
    /// The free-curling curvature of one kelvin of difference in the model's units (κ D / P
    /// per K, [`crate::model::Load::Temperature`]): what a climate bin's difference becomes.
    /// None where the plate has no thermal expansion (then the bins must keep the scene's own
    /// temperature loads).
    pub curvature_per_kelvin: Option<f64>,
    /// The face stress of one kelvin of a profile's nonlinear part in the model's units
    /// (−E α/(1 − ν) L²/P, [`crate::model::Load::FaceStress`]); None as above.
    pub stress_per_kelvin: Option<f64>,
    /// The scene's unit system, in which the run names its passes in words (progress, errors);
    /// None: not known (the values above are SI either way).
    pub units: Option<crate::units::UnitSystem>,
}

impl DamagePlan {
    /// Check the three sections against the vehicles of the model (`names`: each vehicle's
    /// name, in the model's order); None when the scene has none of them. `thickness`: the
    /// slab's (m; None in a dimensionless scene), for the gradients; `split`: a profile's
    /// equivalent linear difference and its nonlinear part at the faces from its depths and
    /// temperatures (the scene's `temperature-profile` rule). The curvature and stress per
    /// kelvin are the caller's to set ([`Self::curvature_per_kelvin`]).
    pub fn new(
        traffic: Option<&TrafficSpec>,
        climate: Option<&ClimateSpec>,
        damage: Option<&DamageSpec>,
        names: &[Option<&str>],
        thickness: Option<f64>,
        split: &ProfileSplit<'_>,
    ) -> Result<Option<Self>> {
        let (traffic, damage) = match (traffic, damage) {
            (None, None) if climate.is_none() => return Ok(None),
            (Some(t), Some(d)) => (t, d),
            (None, _) => {
                return Err(Error::invalid(
                    "traffic",
                    "missing: a damage run needs [traffic] (design_life and [[traffic.group]]) beside [damage]",
                ))
            }
            (Some(_), None) => {
                return Err(Error::invalid(
                    "damage",
                    "missing: [traffic] needs [damage] (model = \"pca\", \"mepdg\" or \"faa\", and modulus_of_rupture)",
                ))
            }
        };
        positive("traffic.design_life", traffic.design_life, "years")?;
        if !(traffic.growth.is_finite() && traffic.growth > -1.0) {
            return Err(Error::invalid(
                "traffic.growth",
                format!(
                    "must be a yearly fraction above −1 (0.02 for 2 % a year), got {}",
                    traffic.growth
                ),
            ));
        }
        let lower_edge = match traffic.edge.as_str() {
            "y-" => true,
            "y+" => false,
            other => {
                return Err(Error::invalid(
                    "traffic.edge",
                    format!("`{other}` is not an edge the traffic runs along: write \"y-\" (y = −b/2, the default) or \"y+\"; the lane runs along x"),
                ))
            }
        };
        let cut = match traffic.ends.as_deref() {
            None | Some("cut") => true,
            Some("free") => false,
            Some(other) => {
                return Err(Error::invalid(
                    "traffic.ends",
                    format!("`{other}` is not what the plate's ends are: write \"cut\" (the default: the model cuts a lane that goes on) or \"free\" (the lane ends there)"),
                ))
            }
        };
        if let Some(e) = traffic.edge_at.filter(|e| !e.is_finite()) {
            return Err(Error::invalid(
                "traffic.edge_at",
                format!("must be the y of the lane's outer edge, m, got {e}"),
            ));
        }
        let w = &traffic.wander;
        if !(w.mean.is_finite() && w.mean >= 0.0) {
            return Err(Error::invalid(
                "traffic.wander.mean",
                format!(
                    "must be a distance ≥ 0 from the slab's edge, m, got {}",
                    w.mean
                ),
            ));
        }
        if !(w.deviation.is_finite() && w.deviation >= 0.0) {
            return Err(Error::invalid(
                "traffic.wander.deviation",
                format!("must be ≥ 0, m, got {}", w.deviation),
            ));
        }
        if !(1..=15).contains(&w.positions) {
            return Err(Error::invalid(
                "traffic.wander.positions",
                format!("must be 1 … 15 lateral positions, got {}", w.positions),
            ));
        }
        if traffic.group.is_empty() {
            return Err(Error::invalid(
                "traffic.group",
                "missing: give at least one [[traffic.group]] (load = the name of an axle or gear of the scene, levels in N, repetitions per year)",
            ));
        }
        let mut groups = Vec::new();
        for (g, spec) in traffic.group.iter().enumerate() {
            let field = |k: &str| format!("traffic.group[{g}].{k}");
            let Some(vehicle) = names.iter().position(|n| *n == Some(spec.load.as_str())) else {
                let known: Vec<&str> = names.iter().flatten().copied().collect();
                return Err(Error::invalid(
                    field("load"),
                    format!(
                        "no axle or gear named `{}` in the scene; named axles and gears: {}",
                        spec.load,
                        if known.is_empty() {
                            "none (give the axle or gear load a `name`)".to_string()
                        } else {
                            known.join(", ")
                        }
                    ),
                ));
            };
            if spec.levels.is_empty() || spec.levels.len() != spec.repetitions.len() {
                return Err(Error::invalid(
                    field("repetitions"),
                    format!(
                        "give one yearly repetition count per level: {} levels, {} counts",
                        spec.levels.len(),
                        spec.repetitions.len()
                    ),
                ));
            }
            let mut levels = Vec::new();
            for (k, (&load, &reps)) in spec.levels.iter().zip(&spec.repetitions).enumerate() {
                positive(&format!("{}[{k}]", field("levels")), load, "N")?;
                if !(reps.is_finite() && reps >= 0.0) {
                    return Err(Error::invalid(
                        format!("{}[{k}]", field("repetitions")),
                        format!("must be a count ≥ 0 per year, got {reps}"),
                    ));
                }
                levels.push(Level {
                    load,
                    repetitions: reps,
                });
            }
            groups.push(Group {
                load: spec.load.clone(),
                vehicle,
                levels,
            });
        }
        let climate = match climate {
            Some(c) if !c.bin.is_empty() => {
                let mut bins = Vec::new();
                for (k, b) in c.bin.iter().enumerate() {
                    let field = |key: &str| format!("climate.bin[{k}].{key}");
                    let profile = match (&b.depths, &b.temperatures) {
                        (None, None) => None,
                        (Some(d), Some(t)) => Some((d, t)),
                        (Some(_), None) => {
                            return Err(Error::invalid(
                                field("temperatures"),
                                "missing: a profile gives the temperatures at its depths",
                            ))
                        }
                        (None, Some(_)) => {
                            return Err(Error::invalid(
                                field("depths"),
                                "missing: a profile gives the depths of its temperatures, m from the top surface",
                            ))
                        }
                    };
                    if profile.is_some() && (b.difference.is_some() || b.gradient.is_some()) {
                        return Err(Error::invalid(
                            format!("climate.bin[{k}]"),
                            "give a difference (K), a gradient (K/m) or a profile (depths and temperatures), one of them",
                        ));
                    }
                    let mut nonlinear = [0.0; 2];
                    let difference = match (b.difference, b.gradient, thickness, profile) {
                        (_, _, _, Some((depths, temps))) => {
                            crate::check::profile(&field, depths, temps, None)?;
                            let (d, nl) = split(depths, temps);
                            nonlinear = nl;
                            d
                        }
                        (Some(d), None, _, _) if d.is_finite() => d,
                        (Some(d), None, _, _) => {
                            return Err(Error::invalid(
                                format!("climate.bin[{k}].difference"),
                                format!("must be finite, K, got {d}"),
                            ))
                        }
                        (None, Some(g), Some(h), _) if g.is_finite() => g * h,
                        (None, Some(g), Some(_), _) => {
                            return Err(Error::invalid(
                                format!("climate.bin[{k}].gradient"),
                                format!("must be finite, K/m, got {g}"),
                            ))
                        }
                        (None, Some(_), None, _) => {
                            return Err(Error::invalid(
                                format!("climate.bin[{k}].gradient"),
                                "a gradient needs the slab's thickness: give the scene as [plate] (or the bin as a difference)",
                            ))
                        }
                        (Some(_), Some(_), _, _) => {
                            return Err(Error::invalid(
                                format!("climate.bin[{k}]"),
                                "give a difference (K) or a gradient (K/m), not both",
                            ))
                        }
                        (None, None, _, _) => {
                            return Err(Error::invalid(
                                format!("climate.bin[{k}].difference"),
                                "missing: give the bin's temperature difference, top minus bottom (K), its gradient (K/m) or its profile (depths and temperatures)",
                            ))
                        }
                    };
                    if !(b.share.is_finite() && b.share >= 0.0) {
                        return Err(Error::invalid(
                            format!("climate.bin[{k}].share"),
                            format!("must be a share ≥ 0 of the traffic, got {}", b.share),
                        ));
                    }
                    if let Some(m) = b.subgrade_modulus {
                        positive(&field("subgrade_modulus"), m, "N/m³")?;
                    }
                    bins.push(Climate {
                        difference,
                        nonlinear,
                        subgrade_modulus: b.subgrade_modulus,
                        share: b.share,
                    });
                }
                let total: f64 = bins.iter().map(|b| b.share).sum();
                if (total - 1.0).abs() > 1e-6 {
                    return Err(Error::invalid(
                        "climate.bin",
                        format!(
                            "the shares add up to {total}, not 1: every pass happens in one bin"
                        ),
                    ));
                }
                bins
            }
            _ => vec![Climate {
                difference: f64::NAN,
                nonlinear: [0.0; 2],
                subgrade_modulus: None,
                share: 1.0,
            }],
        };
        let mut coefficients = damage.coefficients.clone();
        coefficients.insert("model".into(), damage.model.clone().into());
        let model: crate::damage::relations::DamageModel =
            serde_json::from_value(serde_json::Value::Object(coefficients)).map_err(|e| {
                let text = e.to_string();
                Error::invalid(
                    if text.contains("unknown field") {
                        "damage.coefficients"
                    } else {
                        "damage.model"
                    },
                    format!(
                        "{text}: write model = \"pca\", \"mepdg\" or \"faa\", and in [damage.coefficients] only that relation's coefficients"
                    ),
                )
            })?;
        model.validate()?;
        positive("damage.modulus_of_rupture", damage.modulus_of_rupture, "Pa")?;
        let ages = match damage.rupture_growth.as_deref() {
            None | Some("none") => None,
            Some("mepdg") => Some(AgeSchedule::mepdg(traffic.design_life, traffic.growth)),
            Some(other) => {
                return Err(Error::invalid(
                    "damage.rupture_growth",
                    format!("`{other}` is not a growth of the modulus of rupture: write \"mepdg\" (the MEPDG's strength gain with age) or \"none\" (one MR for the whole life, the default)"),
                ))
            }
        };
        if let Some(steps) = damage.steps.filter(|s| !(2..=401).contains(s)) {
            return Err(Error::invalid(
                "damage.steps",
                format!("must be 2 … 401 positions of a pass, got {steps}"),
            ));
        }
        if let Some(r) = damage.reliability {
            if !(0.5..1.0).contains(&r) {
                return Err(Error::invalid(
                    "damage.reliability",
                    format!("must be in [0.5, 1) (0.9 for 90 %), got {r}"),
                ));
            }
        }
        Ok(Some(Self {
            design_life: traffic.design_life,
            growth: traffic.growth,
            lower_edge,
            edge_at: traffic.edge_at,
            groups,
            lateral: lateral(w),
            climate,
            model,
            rupture: damage.modulus_of_rupture,
            ages,
            steps: damage.steps,
            reliability: damage.reliability,
            interpolate: damage.interpolate,
            cut,
            curvature_per_kelvin: None,
            stress_per_kelvin: None,
            units: None,
        }))
    }

    /// Repetitions over the design life per first-year repetition: Σ (1 + g)^t over the years
    /// (a fractional last year counts its fraction).
    pub fn life_factor(&self) -> f64 {
        let g = self.growth;
        let n = self.design_life;
        if g.abs() < 1e-12 {
            n
        } else {
            ((1.0 + g).powf(n) - 1.0) / g
        }
    }

    /// The cycles of tensile stress `stress` (Pa) the slab allows over its life: the
    /// relation's N at the modulus of rupture, or, where the MR grows with age, 1 / the
    /// average damage of a cycle over the months ([`AgeSchedule::damage_per_cycle`]) — so
    /// that n / this is the damage of n cycles spread over the life as the traffic is.
    /// Unlimited (infinite) for `stress` ≤ 0.
    pub fn allowed(&self, stress: f64) -> f64 {
        if stress.is_nan() || stress <= 0.0 {
            return f64::INFINITY;
        }
        match &self.ages {
            None => self.model.allowed_repetitions(stress, self.rupture),
            Some(ages) => {
                let per_cycle = ages
                    .damage_per_cycle(|r| self.model.allowed_repetitions(stress, self.rupture * r));
                if per_cycle > 0.0 {
                    1.0 / per_cycle
                } else {
                    f64::INFINITY
                }
            }
        }
    }

    /// Every case of the sum, in the order group, level, lateral position, climate bin.
    pub fn bins(&self) -> Vec<Bin> {
        let life = self.life_factor();
        let mut out = Vec::new();
        for (g, group) in self.groups.iter().enumerate() {
            for (l, level) in group.levels.iter().enumerate() {
                for (p, lat) in self.lateral.iter().enumerate() {
                    for (c, clim) in self.climate.iter().enumerate() {
                        out.push(Bin {
                            group: g,
                            level: l,
                            lateral: p,
                            climate: c,
                            repetitions: level.repetitions * life * lat.weight * clim.share,
                        });
                    }
                }
            }
        }
        out
    }
}

fn positive(field: &str, v: f64, unit: &str) -> Result<()> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(Error::invalid(
            field,
            format!("must be positive and finite, {unit}, got {v}"),
        ))
    }
}

/// The lateral positions of the module's description.
fn lateral(w: &WanderSpec) -> Vec<Lateral> {
    let n = w.positions;
    if n == 1 || w.deviation == 0.0 {
        return vec![Lateral {
            offset: w.mean,
            weight: 1.0,
        }];
    }
    let span = 2.5;
    let width = 2.0 * span / n as f64;
    let mut out: Vec<Lateral> = (0..n)
        .map(|i| {
            let lo = -span + i as f64 * width;
            let hi = lo + width;
            Lateral {
                offset: (w.mean + w.deviation * (lo + hi) / 2.0).max(0.0),
                weight: normal_cdf(hi) - normal_cdf(lo),
            }
        })
        .collect();
    let total: f64 = out.iter().map(|l| l.weight).sum();
    for l in &mut out {
        l.weight /= total;
    }
    out
}

/// The standard normal distribution function Φ(z) = erfc(−z/√2)/2 (libm's erfc).
fn normal_cdf(z: f64) -> f64 {
    0.5 * libm::erfc(-z / std::f64::consts::SQRT_2)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Φ at tabulated points (any normal table: Φ(1) = 0.841345, Φ(1.96) = 0.975002,
    /// Φ(−2.5) = 0.006210, six decimals).
    #[test]
    fn the_normal_distribution_function_is_the_tables() {
        for (z, p) in [
            (0.0, 0.5),
            (1.0, 0.841_345),
            (1.96, 0.975_002),
            (-2.5, 0.006_210),
        ] {
            assert!(
                (normal_cdf(z) - p).abs() < 1e-6,
                "Φ({z}) = {}",
                normal_cdf(z)
            );
        }
    }

    /// Three positions of the MEPDG's wander: symmetric about the mean, weights adding up to
    /// one, the middle band's Φ(5/6) − Φ(−5/6) = 0.5953 of the ±2.5σ mass (0.98758).
    #[test]
    fn wander_positions_take_the_normal_weights() {
        let w = WanderSpec::default();
        let l = lateral(&w);
        assert_eq!(l.len(), 3);
        let sum: f64 = l.iter().map(|p| p.weight).sum();
        assert!((sum - 1.0).abs() < 1e-12);
        assert!((l[0].weight - l[2].weight).abs() < 1e-12);
        assert!((l[1].weight - 0.595_35 / 0.987_58).abs() < 1e-4, "{:?}", l);
        assert!((l[1].offset - w.mean).abs() < 1e-12);
        assert!((l[2].offset - (w.mean + w.deviation * 5.0 / 3.0)).abs() < 1e-12);
        // The lower band would run off the slab (18 − 16.7 in > 0 here: it stays).
        assert!(l[0].offset > 0.0);
    }
}
