//! Scene files (TOML): the plate, its foundation, the loads, the mesh and the solver settings,
//! and their validation into a [`Problem`] in the solver's unit system.
//!
//! Two equivalent forms are accepted. A *physical* scene gives `[plate]` and `[foundation]` in SI
//! units; a *dimensionless* scene gives the paper's groups in `[dimensionless]` (eq. 4.1) and
//! positions as (s, t) ∈ [−1, 1]². Both become the same [`Problem`]:
//!
//! * lengths in units of L (half the side along x): the plate is [−1, 1] × [−μ, μ];
//! * forces in units of P, where 4P is the resultant of the loads;
//! * flexural rigidity D = 1, so deflections are the paper's V = D w / (P L²);
//! * shear rigidity κ_s = χ G H L² / D = 1 / (μ Δ);
//! * Winkler modulus K L⁴ / D = 1 / (μ Γ_w); half-space constant
//!   (1 − ν_s²) D / (π E_s L³) = μ Γ_h.
//!
//! The paper's dimensionless pressure is σ = μ L² r / P = μ r in these units.

use serde::Deserialize;

use crate::error::{Error, Result};
use crate::foundation::FoundationKind;

/// Contact law between plate and foundation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Contact {
    /// Bilateral: the foundation may pull (gap = 0 everywhere).
    Bonded,
    /// Unilateral, tensionless: pressure ≥ 0, gap ≥ 0, pressure · gap = 0.
    Unbonded,
}

/// Solution method for unbonded contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum MethodKind {
    /// The paper's penalty iteration (eqs. 4.5–4.6).
    Penalty,
    /// Convex QP in the contact pressures (Schur complement on the plate), solved by clarabel.
    Qp,
}

/// Where σ ≥ 0 is imposed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum ConstraintPoints {
    /// At the nodes (σ ≥ 0 everywhere for bilinear σ).
    Nodal,
    /// At the 2 × 2 Gauss points of each element (the paper's eqs. 4.3–4.4).
    Gauss,
}

/// Whether to reduce the model by symmetry.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SymmetryMode {
    /// Model a half or a quarter when the loads allow it.
    Auto,
    /// Always model the whole plate.
    None,
}

macro_rules! names {
    ($t:ty, $($v:ident => $s:literal),+) => {
        impl $t {
            /// Name as written in scene files and reports.
            pub fn name(self) -> &'static str {
                match self { $(Self::$v => $s),+ }
            }
        }
        impl std::fmt::Display for $t {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str(self.name())
            }
        }
    };
}
names!(Contact, Bonded => "bonded", Unbonded => "unbonded");
names!(MethodKind, Penalty => "penalty", Qp => "qp");
names!(ConstraintPoints, Nodal => "nodal", Gauss => "gauss");
names!(SymmetryMode, Auto => "auto", None => "none");

/// `[plate]` in SI units.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlateSpec {
    /// Full side along x, m.
    pub length: f64,
    /// Full side along y, m.
    pub width: f64,
    /// Thickness H, m.
    pub thickness: f64,
    /// E_p, Pa.
    pub youngs_modulus: f64,
    /// ν_p.
    pub poissons_ratio: f64,
    /// χ, default 5/6.
    #[serde(default)]
    pub shear_correction: Option<f64>,
}

/// `[foundation]` in SI units.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FoundationSpec {
    /// "winkler" or "half-space".
    pub model: FoundationKind,
    /// Winkler subgrade modulus K, N/m³.
    #[serde(default)]
    pub modulus: Option<f64>,
    /// Half-space E_s, Pa.
    #[serde(default)]
    pub youngs_modulus: Option<f64>,
    /// Half-space ν_s.
    #[serde(default)]
    pub poissons_ratio: Option<f64>,
}

/// `[dimensionless]`: the paper's groups (eq. 4.1).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DimensionlessSpec {
    /// "winkler" or "half-space".
    pub foundation: FoundationKind,
    /// Γ_w or Γ_h.
    pub gamma: f64,
    /// Δ.
    pub delta: f64,
    /// μ = width / length.
    pub mu: f64,
    /// ν_p.
    pub nu: f64,
}

/// A coordinate: a number (point loads) or a range [lo, hi] (patch loads).
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(untagged)]
pub enum Coord {
    /// A single value.
    Value(f64),
    /// A closed interval.
    Range([f64; 2]),
}

/// Kind of a load entry.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum LoadKind {
    /// Concentrated force at (x, y).
    Point,
    /// Uniform pressure over the rectangle x = [x0, x1], y = [y0, y1].
    Patch,
    /// Uniform pressure over the whole plate (self-weight, surcharge).
    Uniform,
}

/// One `[[load]]` entry.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LoadSpec {
    /// point | patch | uniform.
    pub kind: LoadKind,
    /// x (point) or [x0, x1] (patch); m, or s in a dimensionless scene.
    #[serde(default)]
    pub x: Option<Coord>,
    /// y (point) or [y0, y1] (patch); m, or t in a dimensionless scene.
    #[serde(default)]
    pub y: Option<Coord>,
    /// Point force, N downward (relative in a dimensionless scene).
    #[serde(default)]
    pub force: Option<f64>,
    /// Pressure, Pa downward (relative in a dimensionless scene).
    #[serde(default)]
    pub pressure: Option<f64>,
}

/// `[mesh]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MeshSpec {
    /// Elements [nx, ny] over the whole plate.
    #[serde(default = "default_elements")]
    pub elements: Vec<i64>,
    /// "auto" or "none".
    #[serde(default = "default_symmetry")]
    pub symmetry: SymmetryMode,
}

fn default_elements() -> Vec<i64> {
    vec![16, 16]
}
fn default_symmetry() -> SymmetryMode {
    SymmetryMode::Auto
}

impl Default for MeshSpec {
    fn default() -> Self {
        Self {
            elements: default_elements(),
            symmetry: default_symmetry(),
        }
    }
}

/// `[solver]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SolverSpec {
    /// "bonded" or "unbonded" (default).
    #[serde(default = "default_contact")]
    pub contact: Contact,
    /// "penalty" (default) or "qp".
    #[serde(default = "default_method")]
    pub method: MethodKind,
    /// Dimensionless penalty ε̄ (eq. 4.1f), default 1e-5 as in the paper.
    #[serde(default = "default_penalty")]
    pub penalty: f64,
    /// "nodal" (default) or "gauss".
    #[serde(default = "default_constraint")]
    pub constraint: ConstraintPoints,
    /// Cap on penalty iterations, default 50.
    #[serde(default = "default_max_iterations")]
    pub max_iterations: i64,
    /// Memory the solver may use, GiB; default 3/4 of the machine's memory.
    #[serde(default)]
    pub memory_limit_gib: Option<f64>,
}

fn default_contact() -> Contact {
    Contact::Unbonded
}
fn default_method() -> MethodKind {
    MethodKind::Penalty
}
fn default_penalty() -> f64 {
    1e-5
}
fn default_constraint() -> ConstraintPoints {
    ConstraintPoints::Nodal
}
fn default_max_iterations() -> i64 {
    50
}

impl Default for SolverSpec {
    fn default() -> Self {
        Self {
            contact: default_contact(),
            method: default_method(),
            penalty: default_penalty(),
            constraint: default_constraint(),
            max_iterations: default_max_iterations(),
            memory_limit_gib: None,
        }
    }
}

/// A scene file as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    /// Free text shown in reports.
    #[serde(default)]
    pub title: Option<String>,
    /// Physical plate.
    #[serde(default)]
    pub plate: Option<PlateSpec>,
    /// Physical foundation.
    #[serde(default)]
    pub foundation: Option<FoundationSpec>,
    /// Dimensionless groups (instead of `plate` and `foundation`).
    #[serde(default)]
    pub dimensionless: Option<DimensionlessSpec>,
    /// Loads.
    #[serde(default)]
    pub load: Vec<LoadSpec>,
    /// Mesh.
    #[serde(default)]
    pub mesh: MeshSpec,
    /// Solver settings.
    #[serde(default)]
    pub solver: SolverSpec,
}

impl SceneFile {
    /// Parse TOML text.
    pub fn parse(text: &str) -> Result<Self> {
        toml::from_str(text).map_err(|e| Error::Parse(e.to_string()))
    }
}

/// The paper's dimensionless groups of a problem.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Groups {
    /// Foundation model.
    pub foundation: FoundationKind,
    /// Γ_w or Γ_h.
    pub gamma: f64,
    /// Δ.
    pub delta: f64,
    /// μ.
    pub mu: f64,
    /// ν_p.
    pub nu: f64,
}

/// Physical scales of a scene given in SI units.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Physical {
    /// L: half the side along x, m.
    pub half_length: f64,
    /// P: a quarter of the load resultant, N.
    pub force: f64,
    /// D, N·m.
    pub rigidity: f64,
}

impl Physical {
    /// Scale of deflections: P L² / D (m per unit V).
    pub fn deflection(&self) -> f64 {
        self.force * self.half_length.powi(2) / self.rigidity
    }
    /// Scale of rotations: P L / D.
    pub fn rotation(&self) -> f64 {
        self.force * self.half_length / self.rigidity
    }
    /// Scale of pressures in the unit system: P / L² (Pa).
    pub fn pressure(&self) -> f64 {
        self.force / self.half_length.powi(2)
    }
    /// Scale of moments per unit length: P (N·m/m).
    pub fn moment(&self) -> f64 {
        self.force
    }
    /// Scale of shear forces per unit length: P / L (N/m).
    pub fn shear(&self) -> f64 {
        self.force / self.half_length
    }
}

/// A load in the unit system (lengths / L, forces / P), downward positive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Load {
    /// Force at a point.
    Point {
        /// x / L.
        x: f64,
        /// y / L.
        y: f64,
        /// F / P.
        force: f64,
    },
    /// Uniform pressure on a rectangle.
    Patch {
        /// [x0, x1] / L.
        x: [f64; 2],
        /// [y0, y1] / L.
        y: [f64; 2],
        /// p L² / P.
        pressure: f64,
    },
}

impl Load {
    /// Resultant of the load.
    pub fn resultant(&self) -> f64 {
        match *self {
            Load::Point { force, .. } => force,
            Load::Patch { x, y, pressure } => pressure * (x[1] - x[0]) * (y[1] - y[0]),
        }
    }

    /// The load mirrored about x = 0 (`about_x`) or y = 0.
    pub fn mirrored(&self, about_x: bool) -> Load {
        match *self {
            Load::Point { x, y, force } => {
                if about_x {
                    Load::Point { x: -x, y, force }
                } else {
                    Load::Point { x, y: -y, force }
                }
            }
            Load::Patch { x, y, pressure } => {
                if about_x {
                    Load::Patch {
                        x: [-x[1], -x[0]],
                        y,
                        pressure,
                    }
                } else {
                    Load::Patch {
                        x,
                        y: [-y[1], -y[0]],
                        pressure,
                    }
                }
            }
        }
    }

    fn close(&self, other: &Load, tol: f64) -> bool {
        match (*self, *other) {
            (
                Load::Point { x, y, force },
                Load::Point {
                    x: x2,
                    y: y2,
                    force: f2,
                },
            ) => {
                (x - x2).abs() < tol
                    && (y - y2).abs() < tol
                    && (force - f2).abs() <= tol * force.abs().max(f2.abs())
            }
            (
                Load::Patch { x, y, pressure },
                Load::Patch {
                    x: x2,
                    y: y2,
                    pressure: p2,
                },
            ) => {
                (x[0] - x2[0]).abs() < tol
                    && (x[1] - x2[1]).abs() < tol
                    && (y[0] - y2[0]).abs() < tol
                    && (y[1] - y2[1]).abs() < tol
                    && (pressure - p2).abs() <= tol * pressure.abs().max(p2.abs())
            }
            _ => false,
        }
    }
}

/// True when the load set is unchanged by mirroring about x = 0 (`about_x`) or y = 0.
pub fn loads_symmetric(loads: &[Load], about_x: bool) -> bool {
    let tol = 1e-9;
    let mut used = vec![false; loads.len()];
    for l in loads {
        let m = l.mirrored(about_x);
        match loads
            .iter()
            .enumerate()
            .position(|(k, c)| !used[k] && c.close(&m, tol))
        {
            Some(k) => used[k] = true,
            None => return false,
        }
    }
    true
}

/// Solver settings after validation.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SolverSettings {
    /// Contact law.
    pub contact: Contact,
    /// Method for unbonded contact.
    pub method: MethodKind,
    /// ε̄.
    pub penalty: f64,
    /// Constraint points.
    pub constraint: ConstraintPoints,
    /// Cap on penalty iterations.
    pub max_iterations: usize,
    /// Memory limit, bytes.
    pub memory_limit: f64,
}

/// A validated problem in the solver's unit system (see the module docs).
#[derive(Debug, Clone)]
pub struct Problem {
    /// Title for reports.
    pub title: String,
    /// Dimensionless groups.
    pub groups: Groups,
    /// Physical scales, for scenes given in SI units.
    pub physical: Option<Physical>,
    /// Loads, whole plate, unit system; their resultant is ±4.
    pub loads: Vec<Load>,
    /// Elements over the whole plate.
    pub elements: [usize; 2],
    /// Symmetry mode asked for.
    pub symmetry: SymmetryMode,
    /// Solver settings.
    pub solver: SolverSettings,
}

/// Upper limit on elements per side: beyond it even a Winkler model exceeds any sane memory.
pub const MAX_ELEMENTS_PER_SIDE: i64 = 4000;

fn finite_positive(field: &str, v: f64, unit: &str) -> Result<f64> {
    if !v.is_finite() {
        return Err(Error::invalid(
            field,
            format!("must be a finite number, got {v}"),
        ));
    }
    if v <= 0.0 {
        return Err(Error::invalid(
            field,
            format!("must be positive ({unit}), got {v}"),
        ));
    }
    Ok(v)
}

fn poisson(field: &str, v: f64) -> Result<f64> {
    if !v.is_finite() || v <= -1.0 || v >= 0.5 {
        return Err(Error::invalid(
            field,
            format!("Poisson's ratio must lie in (−1, 0.5), got {v}"),
        ));
    }
    Ok(v)
}

/// Memory available to the process: 3/4 of MemTotal from /proc/meminfo, or 8 GiB if unknown.
pub fn default_memory_limit() -> f64 {
    let total = std::fs::read_to_string("/proc/meminfo").ok().and_then(|s| {
        s.lines()
            .find(|l| l.starts_with("MemTotal:"))
            .and_then(|l| {
                l.split_whitespace()
                    .nth(1)
                    .and_then(|k| k.parse::<f64>().ok())
            })
            .map(|kib| kib * 1024.0)
    });
    0.75 * total.unwrap_or(8.0 * 1024.0 * 1024.0 * 1024.0 / 0.75)
}

impl SceneFile {
    /// Validate and convert to the unit system.
    pub fn validate(&self) -> Result<Problem> {
        let title = self
            .title
            .clone()
            .unwrap_or_else(|| "liftoff scene".to_string());
        // Plate, foundation and scales.
        let (groups, physical, scale_xy): (Groups, Option<(f64, f64)>, [f64; 2]) =
            match (&self.plate, &self.foundation, &self.dimensionless) {
                (Some(_), _, Some(_)) | (_, Some(_), Some(_)) => {
                    return Err(Error::invalid(
                        "dimensionless",
                        "give either [plate] and [foundation] (SI units) or [dimensionless], not both",
                    ))
                }
                (None, None, None) => {
                    return Err(Error::invalid(
                        "plate",
                        "missing: give [plate] and [foundation] in SI units, or [dimensionless] with the paper's groups",
                    ))
                }
                (Some(_), None, None) => {
                    return Err(Error::invalid(
                        "foundation",
                        "missing: add [foundation] with model = \"winkler\" (modulus) or \"half-space\" (youngs_modulus, poissons_ratio)",
                    ))
                }
                (None, Some(_), None) => {
                    return Err(Error::invalid(
                        "plate",
                        "missing: add [plate] with length, width, thickness, youngs_modulus, poissons_ratio",
                    ))
                }
                (Some(p), Some(f), None) => {
                    let length = finite_positive("plate.length", p.length, "m")?;
                    let width = finite_positive("plate.width", p.width, "m")?;
                    let h = finite_positive("plate.thickness", p.thickness, "m")?;
                    let e = finite_positive("plate.youngs_modulus", p.youngs_modulus, "Pa")?;
                    let nu = poisson("plate.poissons_ratio", p.poissons_ratio)?;
                    let chi = match p.shear_correction {
                        Some(c) => finite_positive("plate.shear_correction", c, "dimensionless, usually 5/6")?,
                        None => 5.0 / 6.0,
                    };
                    if h >= width.min(length) {
                        return Err(Error::invalid(
                            "plate.thickness",
                            format!("{h} m is not smaller than the plate's sides ({length} × {width} m): check units (metres)"),
                        ));
                    }
                    let l = 0.5 * length;
                    let mu = width / length;
                    let d = e * h.powi(3) / (12.0 * (1.0 - nu * nu));
                    let delta = h * h / (6.0 * chi * (1.0 - nu) * mu * l * l);
                    let gamma = match f.model {
                        FoundationKind::Winkler => {
                            if f.youngs_modulus.is_some() || f.poissons_ratio.is_some() {
                                return Err(Error::invalid(
                                    "foundation.youngs_modulus",
                                    "belongs to model = \"half-space\"; a Winkler foundation takes only `modulus` (N/m³)",
                                ));
                            }
                            let k = finite_positive(
                                "foundation.modulus",
                                f.modulus.ok_or_else(|| {
                                    Error::invalid("foundation.modulus", "missing: Winkler subgrade modulus K in N/m³")
                                })?,
                                "N/m³",
                            )?;
                            d / (k * mu * l.powi(4))
                        }
                        FoundationKind::HalfSpace => {
                            if f.modulus.is_some() {
                                return Err(Error::invalid(
                                    "foundation.modulus",
                                    "belongs to model = \"winkler\"; a half-space takes youngs_modulus (Pa) and poissons_ratio",
                                ));
                            }
                            let es = finite_positive(
                                "foundation.youngs_modulus",
                                f.youngs_modulus.ok_or_else(|| {
                                    Error::invalid("foundation.youngs_modulus", "missing: soil Young's modulus E_s in Pa")
                                })?,
                                "Pa",
                            )?;
                            let nus = poisson(
                                "foundation.poissons_ratio",
                                f.poissons_ratio.ok_or_else(|| {
                                    Error::invalid("foundation.poissons_ratio", "missing: soil Poisson's ratio ν_s")
                                })?,
                            )?;
                            d * (1.0 - nus * nus) / (std::f64::consts::PI * es * mu * l.powi(3))
                        }
                    };
                    // Each input is finite and positive, but their combination may still
                    // underflow or overflow (a 1e308 m plate, a 1e-200 m thickness).
                    for (name, v) in [("rigidity D", d), ("Δ", delta), ("Γ", gamma)] {
                        if !(v.is_finite() && v > 0.0) {
                            return Err(Error::invalid(
                                "plate",
                                format!(
                                    "the plate and foundation values give {name} = {v:e}, outside double precision: check their units (m, Pa, N/m³)"
                                ),
                            ));
                        }
                    }
                    (
                        Groups { foundation: f.model, gamma, delta, mu, nu },
                        Some((l, d)),
                        [1.0 / l, 1.0 / l],
                    )
                }
                (None, None, Some(g)) => {
                    let gamma = finite_positive("dimensionless.gamma", g.gamma, "Γ")?;
                    let delta = finite_positive("dimensionless.delta", g.delta, "Δ")?;
                    let mu = finite_positive("dimensionless.mu", g.mu, "width/length")?;
                    let nu = poisson("dimensionless.nu", g.nu)?;
                    (Groups { foundation: g.foundation, gamma, delta, mu, nu }, None, [1.0, mu])
                }
            };
        let mu = groups.mu;

        // Loads in unit-system geometry, magnitudes not yet normalised.
        let mut loads = Vec::with_capacity(self.load.len());
        if self.load.is_empty() {
            return Err(Error::invalid(
                "load",
                "no [[load]] entries: add at least one point, patch or uniform load",
            ));
        }
        let (hx, hy) = (1.0, mu);
        let tol = 1e-9;
        let coord_unit = if physical.is_some() {
            "m"
        } else {
            "s or t, in [−1, 1]"
        };
        for (k, l) in self.load.iter().enumerate() {
            let field = |name: &str| format!("load[{k}].{name}");
            let value = |name: &str, c: Option<Coord>, scale: f64, half: f64| -> Result<f64> {
                match c {
                    Some(Coord::Value(v)) => {
                        if !v.is_finite() {
                            return Err(Error::invalid(
                                field(name),
                                format!("must be finite, got {v}"),
                            ));
                        }
                        let u = v * scale;
                        if u.abs() > half * (1.0 + tol) {
                            return Err(Error::invalid(
                                field(name),
                                format!(
                                    "{v} {coord_unit} lies outside the plate (|{name}| ≤ {:.6})",
                                    half / scale
                                ),
                            ));
                        }
                        Ok(u.clamp(-half, half))
                    }
                    Some(Coord::Range(_)) => Err(Error::invalid(
                        field(name),
                        "a point load takes a single coordinate, not a range",
                    )),
                    None => Err(Error::invalid(field(name), "missing: the load's position")),
                }
            };
            let range = |name: &str, c: Option<Coord>, scale: f64, half: f64| -> Result<[f64; 2]> {
                match c {
                    Some(Coord::Range([a, b])) => {
                        if !a.is_finite() || !b.is_finite() {
                            return Err(Error::invalid(field(name), "range ends must be finite"));
                        }
                        if a >= b {
                            return Err(Error::invalid(
                                field(name),
                                format!("range [{a}, {b}] must be increasing"),
                            ));
                        }
                        let (ua, ub) = (a * scale, b * scale);
                        if ua < -half * (1.0 + tol) || ub > half * (1.0 + tol) {
                            return Err(Error::invalid(
                                field(name),
                                format!(
                                    "range [{a}, {b}] {coord_unit} leaves the plate (±{:.6})",
                                    half / scale
                                ),
                            ));
                        }
                        Ok([ua.max(-half), ub.min(half)])
                    }
                    Some(Coord::Value(_)) => Err(Error::invalid(
                        field(name),
                        "a patch load takes a range [lo, hi]",
                    )),
                    None => Err(Error::invalid(
                        field(name),
                        "missing: the patch's extent [lo, hi]",
                    )),
                }
            };
            let magnitude = |name: &str, v: Option<f64>| -> Result<f64> {
                let v = v.ok_or_else(|| Error::invalid(field(name), "missing"))?;
                if !v.is_finite() {
                    return Err(Error::invalid(
                        field(name),
                        format!("must be finite, got {v}"),
                    ));
                }
                Ok(v)
            };
            let forbid = |name: &str, present: bool, kind: &str| -> Result<()> {
                if present {
                    Err(Error::invalid(
                        field(name),
                        format!("does not apply to a {kind} load"),
                    ))
                } else {
                    Ok(())
                }
            };
            let load = match l.kind {
                LoadKind::Point => {
                    forbid("pressure", l.pressure.is_some(), "point")?;
                    Load::Point {
                        x: value("x", l.x, scale_xy[0], hx)?,
                        y: value("y", l.y, scale_xy[1], hy)?,
                        force: magnitude("force", l.force)?,
                    }
                }
                LoadKind::Patch => {
                    forbid("force", l.force.is_some(), "patch")?;
                    let p = magnitude("pressure", l.pressure)?;
                    // In a dimensionless scene the pressure is a density per ds dt = dA / μ.
                    let p = if physical.is_some() { p } else { p / mu };
                    Load::Patch {
                        x: range("x", l.x, scale_xy[0], hx)?,
                        y: range("y", l.y, scale_xy[1], hy)?,
                        pressure: p,
                    }
                }
                LoadKind::Uniform => {
                    forbid("force", l.force.is_some(), "uniform")?;
                    forbid("x", l.x.is_some(), "uniform")?;
                    forbid("y", l.y.is_some(), "uniform")?;
                    let p = magnitude("pressure", l.pressure)?;
                    let p = if physical.is_some() { p } else { p / mu };
                    Load::Patch {
                        x: [-hx, hx],
                        y: [-hy, hy],
                        pressure: p,
                    }
                }
            };
            loads.push(load);
        }
        // Physical patches were given in Pa over m²; convert to unit geometry (area × L²).
        let area_scale = match physical {
            Some((l, _)) => l * l,
            None => 1.0,
        };
        let total: f64 = loads
            .iter()
            .map(|l| match l {
                Load::Point { .. } => l.resultant(),
                Load::Patch { .. } => l.resultant() * area_scale,
            })
            .sum();
        let gross: f64 = loads
            .iter()
            .map(|l| match l {
                Load::Point { .. } => l.resultant().abs(),
                Load::Patch { .. } => l.resultant().abs() * area_scale,
            })
            .sum();
        if !total.is_finite() || !gross.is_finite() {
            return Err(Error::invalid(
                "load",
                "the load magnitudes overflow when added up: check their units (N and Pa)",
            ));
        }
        if total.abs() <= 1e-12 * gross.max(f64::MIN_POSITIVE) {
            return Err(Error::invalid(
                "load",
                format!("the loads add up to zero (resultant {total:e}); a free plate needs a net vertical load"),
            ));
        }
        // P = |resultant| / 4; express every load in units of P.
        let p_force = total.abs() / 4.0;
        for l in &mut loads {
            match l {
                Load::Point { force, .. } => *force /= p_force,
                Load::Patch { pressure, .. } => *pressure *= area_scale / p_force,
            }
        }

        // Mesh.
        let el = &self.mesh.elements;
        if el.len() != 2 {
            return Err(Error::invalid(
                "mesh.elements",
                format!("give two element counts [nx, ny], got {} values", el.len()),
            ));
        }
        for (k, &n) in el.iter().enumerate() {
            if n < 1 {
                return Err(Error::invalid(
                    format!("mesh.elements[{k}]"),
                    format!("must be a positive number of elements, got {n}"),
                ));
            }
            if n > MAX_ELEMENTS_PER_SIDE {
                return Err(Error::invalid(
                    format!("mesh.elements[{k}]"),
                    format!(
                        "{n} elements is more than the {MAX_ELEMENTS_PER_SIDE} allowed per side"
                    ),
                ));
            }
        }
        let elements = [el[0] as usize, el[1] as usize];

        // Solver.
        let s = &self.solver;
        let penalty = s.penalty;
        if !penalty.is_finite() || penalty <= 0.0 || penalty >= 1.0 {
            return Err(Error::invalid(
                "solver.penalty",
                format!("ε̄ must lie in (0, 1), typically 1e-5; got {penalty}"),
            ));
        }
        if s.max_iterations < 1 || s.max_iterations > 10_000 {
            return Err(Error::invalid(
                "solver.max_iterations",
                format!("must lie in 1..=10000, got {}", s.max_iterations),
            ));
        }
        let memory_limit = match s.memory_limit_gib {
            Some(g) => finite_positive("solver.memory_limit_gib", g, "GiB")? * 1024f64.powi(3),
            None => default_memory_limit(),
        };
        Ok(Problem {
            title,
            groups,
            physical: physical.map(|(l, d)| Physical {
                half_length: l,
                force: p_force,
                rigidity: d,
            }),
            loads,
            elements,
            symmetry: self.mesh.symmetry,
            solver: SolverSettings {
                contact: s.contact,
                method: s.method,
                penalty,
                constraint: s.constraint,
                max_iterations: s.max_iterations as usize,
                memory_limit,
            },
        })
    }
}

impl Problem {
    /// Parse and validate scene text.
    pub fn from_toml(text: &str) -> Result<Self> {
        SceneFile::parse(text)?.validate()
    }

    /// Sum of the loads in units of P: +4 for a net downward load, −4 for a net upward one.
    pub fn resultant(&self) -> f64 {
        self.loads.iter().map(Load::resultant).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
        let p = Problem::from_toml(PHYSICAL).unwrap();
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
        .unwrap();
        let pw = Problem::from_toml(&scene(&format!(
            "[foundation]\nmodel = \"winkler\"\nmodulus = {k}"
        )))
        .unwrap();
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
