//! The scene file as written: serde types of its sections, with their defaults.

use serde::Deserialize;

use crate::foundation::soil::{KeyMap, KeyValue};
use crate::foundation::FoundationKind;
use crate::layout::{Axis, Ends, JointType};
use crate::method::{Contact, MethodKind, QpForm, QpSolver, Route, Start};
use crate::model::{ConstraintPoints, SymmetryMode};

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
    /// Coefficient of thermal expansion α, 1/K; needed only with a temperature load.
    #[serde(default)]
    pub thermal_expansion: Option<f64>,
    /// The plate's outline, m: corners [x, y] in order, edges along the mesh's grid lines,
    /// inside the `length` × `width` box (which the mesh covers); default the box itself.
    #[serde(default)]
    pub outline: Option<Vec<[f64; 2]>>,
    /// What the plate's ends across x (x = ±length/2) are, where it has two or more transverse
    /// joints: "cut" (the model cuts a lane that goes on: `critical` and `damage` read it
    /// between its first and last transverse joint) or "free" (it ends there). Default: the
    /// `[traffic]`'s `ends` in a damage scene (cut), free otherwise.
    #[serde(default)]
    pub ends: Option<Ends>,
}

impl PlateSpec {
    /// A plate of `length` × `width` × `thickness` (m), Young's modulus (Pa) and Poisson's
    /// ratio; χ = 5/6, no thermal expansion.
    pub fn new(
        length: f64,
        width: f64,
        thickness: f64,
        youngs_modulus: f64,
        poissons_ratio: f64,
    ) -> Self {
        Self {
            length,
            width,
            thickness,
            youngs_modulus,
            poissons_ratio,
            shear_correction: None,
            thermal_expansion: None,
            outline: None,
            ends: None,
        }
    }
}

/// `[foundation]` in SI units: the soil's `model`, the keys common to every soil, and the soil's
/// own keys, which the soil reads and checks ([`crate::foundation::soil`]: each soil's file
/// lists its keys with their units).
#[derive(Debug, Clone, Deserialize)]
pub struct FoundationSpec {
    /// "winkler", "half-space", "pasternak", "elastic-layer" or "kerr".
    pub model: FoundationKind,
    /// Pressure the soil may take, Pa: the bearing check (optional).
    #[serde(default)]
    pub allowable_pressure: Option<f64>,
    /// Side of the square over which the bearing check averages the contact pressure, m
    /// (default: the plate's thickness; README, "bearing").
    #[serde(default)]
    pub bearing_length: Option<f64>,
    /// Softer or stiffer patches of a Winkler subgrade.
    #[serde(default)]
    pub zone: Vec<ZoneSpec>,
    /// The soil's own keys (`modulus`, `youngs_modulus`, …): every other key of the section.
    #[serde(flatten)]
    pub soil: KeyMap,
}

impl FoundationSpec {
    /// A soil `model` with its own `keys` (SI units, as in a scene file).
    pub fn soil<K: Into<KeyValue>>(
        model: FoundationKind,
        keys: impl IntoIterator<Item = (&'static str, K)>,
    ) -> Self {
        Self {
            model,
            allowable_pressure: None,
            bearing_length: None,
            zone: Vec::new(),
            soil: keys
                .into_iter()
                .map(|(k, v)| (k.to_string(), v.into()))
                .collect(),
        }
    }

    /// A Winkler subgrade of modulus `k`, N/m³.
    pub fn winkler(k: f64) -> Self {
        Self::soil(FoundationKind::Winkler, [("modulus", k)])
    }

    /// An elastic half-space of Young's modulus `e` (Pa) and Poisson's ratio `nu`.
    pub fn half_space(e: f64, nu: f64) -> Self {
        Self::soil(
            FoundationKind::HalfSpace,
            [("youngs_modulus", e), ("poissons_ratio", nu)],
        )
    }

    /// A Pasternak soil: springs of modulus `k` (N/m³) coupled by a shear layer of modulus
    /// `g_p` (N/m).
    pub fn pasternak(k: f64, g_p: f64) -> Self {
        Self::soil(
            FoundationKind::Pasternak,
            [("modulus", k), ("shear_modulus", g_p)],
        )
    }

    /// An elastic layer of Young's modulus `e` (Pa), Poisson's ratio `nu` and depth `h` (m)
    /// on a rough rigid base.
    pub fn elastic_layer(e: f64, nu: f64, h: f64) -> Self {
        Self::soil(
            FoundationKind::ElasticLayer,
            [("youngs_modulus", e), ("poissons_ratio", nu), ("depth", h)],
        )
    }

    /// The number `key` of the soil's own keys, if given as a number.
    pub fn number(&self, key: &str) -> Option<f64> {
        match self.soil.get(key) {
            Some(KeyValue::Number(v)) => Some(*v),
            _ => None,
        }
    }
}

/// One `[[foundation.zone]]` (SI: `modulus`, N/m³) or `[[dimensionless.zone]]` (`gamma`, the
/// zone's Γ_w): a rectangle of the plate where the Winkler modulus differs.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ZoneSpec {
    /// [x0, x1]: m, or s in a dimensionless scene.
    pub x: [f64; 2],
    /// [y0, y1]: m, or t in a dimensionless scene.
    pub y: [f64; 2],
    /// Winkler modulus inside the zone, N/m³ (SI scenes).
    #[serde(default)]
    pub modulus: Option<f64>,
    /// Γ_w inside the zone (dimensionless scenes).
    #[serde(default)]
    pub gamma: Option<f64>,
}

/// One `[[void]]`: the soil surface is lower by `depth` over a rectangle, so the plate meets it
/// only after closing that gap.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VoidSpec {
    /// [x0, x1]: m, or s in a dimensionless scene.
    pub x: [f64; 2],
    /// [y0, y1]: m, or t in a dimensionless scene.
    pub y: [f64; 2],
    /// Depth, m (SI), or in the loads' units of V (dimensionless: depth · D / L² in the
    /// force unit of the loads).
    pub depth: f64,
}

/// One `[[opening]]`: a hole through the slab — no plate and no soil contact inside — given as
/// a rectangle (`x`, `y`) or a polygon (`outline`), edges along the mesh's grid lines.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OpeningSpec {
    /// [x0, x1]: m, or s in a dimensionless scene.
    #[serde(default)]
    pub x: Option<[f64; 2]>,
    /// [y0, y1]: m, or t in a dimensionless scene.
    #[serde(default)]
    pub y: Option<[f64; 2]>,
    /// Corners [x, y] in order (instead of `x` and `y`).
    #[serde(default)]
    pub outline: Option<Vec<[f64; 2]>>,
}

/// One `[[combination]]`: factors on named load cases, solved as its own contact problem.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CombinationSpec {
    /// Name, used for the output sub-folder.
    pub name: String,
    /// Factor per case name.
    pub factors: std::collections::BTreeMap<String, f64>,
}

/// `[dimensionless]`: the paper's groups (eq. 4.1); the soil's own groups (`shear`, `depth`, …)
/// are read and checked by the soil ([`crate::foundation::soil`]).
#[derive(Debug, Clone, Deserialize)]
pub struct DimensionlessSpec {
    /// "winkler", "half-space", "pasternak", "elastic-layer" or "kerr".
    pub foundation: FoundationKind,
    /// Γ_w or Γ_h (Pasternak, Kerr: Γ_w of its (lower) springs; elastic layer: Γ_h of its E_s,
    /// ν_s).
    pub gamma: f64,
    /// Δ.
    pub delta: f64,
    /// μ = width / length.
    pub mu: f64,
    /// ν_p.
    pub nu: f64,
    /// Allowable pressure in the units of patch pressures (bearing check, optional).
    #[serde(default)]
    pub allowable_pressure: Option<f64>,
    /// Side of the bearing check's averaging square, in units of L (default: the thickness
    /// H/L that Δ gives).
    #[serde(default)]
    pub bearing_length: Option<f64>,
    /// Patches with another Γ_w (Winkler only).
    #[serde(default)]
    pub zone: Vec<ZoneSpec>,
    /// The plate's outline in (s, t) ∈ [−1, 1]² (as `[plate] outline` of an SI scene).
    #[serde(default)]
    pub outline: Option<Vec<[f64; 2]>>,
    /// The soil's own groups: every other key of the section.
    #[serde(flatten)]
    pub soil: KeyMap,
}

/// One `[[joint]]`: a line across the whole plate, `x = …` or `y = …` (m from the plate's
/// centre; s or t in a dimensionless scene), and its load transfer.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JointSpec {
    /// The line x = this (m, or s).
    #[serde(default)]
    pub x: Option<f64>,
    /// The line y = this (m, or t).
    #[serde(default)]
    pub y: Option<f64>,
    /// A segment's first end [x, y] (m, or s, t), instead of `x` or `y`: a joint along x or y
    /// from `from` to `to` that ends at another joint or at the plate's edge.
    #[serde(default)]
    pub from: Option<[f64; 2]>,
    /// A segment's other end [x, y].
    #[serde(default)]
    pub to: Option<[f64; 2]>,
    /// free | continuous | aggregate | tied | dowels.
    pub kind: JointType,
    /// Name for reports (default J1, J2 … in file order).
    #[serde(default)]
    pub name: Option<String>,
    /// Aggregate and tied: the shear stiffness AGG per unit length per unit relative deflection,
    /// N/m² (dimensionless: c L³/D).
    #[serde(default)]
    pub stiffness: Option<f64>,
    /// Tied: the moment per unit length per unit relative normal rotation, N·m/m per rad
    /// (dimensionless: c_r L/D).
    #[serde(default)]
    pub rotational_stiffness: Option<f64>,
    /// Dowels: distance between bars along the joint, m (dimensionless: in the joint's own
    /// coordinate, t for a line x = …, s for y = …).
    #[serde(default)]
    pub spacing: Option<f64>,
    /// Dowels with `spacing`: distance of the first bar from the plate edge where the joint
    /// starts (its lower / left end); default half the spacing.
    #[serde(default)]
    pub offset: Option<f64>,
    /// Dowels: the bars' positions along the joint (y of each bar on a line x = …, x on y = …;
    /// m from the centre, or t / s), instead of `spacing`.
    #[serde(default)]
    pub positions: Option<Vec<f64>>,
    /// Dowels (SI): bar diameter d, m.
    #[serde(default)]
    pub diameter: Option<f64>,
    /// Dowels (SI): the bar's Young's modulus E_d, Pa.
    #[serde(default)]
    pub youngs_modulus: Option<f64>,
    /// Dowels (SI): joint opening z, m.
    #[serde(default)]
    pub opening: Option<f64>,
    /// Dowels (SI): modulus of dowel support K, N/m³.
    #[serde(default)]
    pub support_modulus: Option<f64>,
    /// Dowels: the spring of one bar directly, N/m (dimensionless: k_d L²/D), instead of the
    /// bar's properties.
    #[serde(default)]
    pub dowel_stiffness: Option<f64>,
}

impl JointSpec {
    /// A joint line x = `at` (Axis::X) or y = `at` of the given kind, without parameters.
    pub fn line(axis: Axis, at: f64, kind: JointType) -> Self {
        Self {
            x: (axis == Axis::X).then_some(at),
            y: (axis == Axis::Y).then_some(at),
            from: None,
            to: None,
            kind,
            name: None,
            stiffness: None,
            rotational_stiffness: None,
            spacing: None,
            offset: None,
            positions: None,
            diameter: None,
            youngs_modulus: None,
            opening: None,
            support_modulus: None,
            dowel_stiffness: None,
        }
    }

    /// An aggregate joint of shear stiffness `stiffness` (N/m², or c L³/D).
    pub fn aggregate(axis: Axis, at: f64, stiffness: f64) -> Self {
        Self {
            stiffness: Some(stiffness),
            ..Self::line(axis, at, JointType::Aggregate)
        }
    }

    /// A tied joint of shear and rotational stiffness.
    pub fn tied(axis: Axis, at: f64, stiffness: f64, rotational: f64) -> Self {
        Self {
            stiffness: Some(stiffness),
            rotational_stiffness: Some(rotational),
            ..Self::line(axis, at, JointType::Tied)
        }
    }

    /// A doweled joint with bars of spring `stiffness` (N/m, or k_d L²/D) at `positions`.
    pub fn dowels(axis: Axis, at: f64, stiffness: f64, positions: Vec<f64>) -> Self {
        Self {
            dowel_stiffness: Some(stiffness),
            positions: Some(positions),
            ..Self::line(axis, at, JointType::Dowels)
        }
    }

    /// The same joint with a name.
    pub fn named(mut self, name: impl Into<String>) -> Self {
        self.name = Some(name.into());
        self
    }
}

/// One `[[panel]]`: the panel holding the point `at` with its own thickness or Young's modulus
/// (same ν and χ as the plate).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PanelSpec {
    /// Any point inside a panel of the joints' grid, [x, y] (m, or (s, t)); or, instead, the
    /// panel's own outline by `x` and `y` or `outline` (a blockout, a pit's floor).
    #[serde(default)]
    pub at: Option<[f64; 2]>,
    /// A panel of its own outline: [x0, x1] (m, or s).
    #[serde(default)]
    pub x: Option<[f64; 2]>,
    /// … and [y0, y1] (m, or t).
    #[serde(default)]
    pub y: Option<[f64; 2]>,
    /// A panel of its own outline as a polygon [[x, y], …] (edges along the grid's lines).
    #[serde(default)]
    pub outline: Option<Vec<[f64; 2]>>,
    /// The panel's thickness, m (SI scenes).
    #[serde(default)]
    pub thickness: Option<f64>,
    /// The panel's Young's modulus, Pa (SI scenes).
    #[serde(default)]
    pub youngs_modulus: Option<f64>,
    /// H_p / H (dimensionless scenes).
    #[serde(default)]
    pub thickness_ratio: Option<f64>,
    /// E_p / E (dimensionless scenes).
    #[serde(default)]
    pub modulus_ratio: Option<f64>,
}

impl PanelSpec {
    /// The panel holding (x, y), with nothing changed yet.
    pub fn at(x: f64, y: f64) -> Self {
        Self {
            at: Some([x, y]),
            x: None,
            y: None,
            outline: None,
            thickness: None,
            youngs_modulus: None,
            thickness_ratio: None,
            modulus_ratio: None,
        }
    }
}

pub use super::load_spec::{Coord, LoadKind, LoadSpec};

/// `[solver] penalty`: `"auto"` or a fixed ε̄.
#[derive(Debug, Clone, PartialEq, Deserialize, serde::Serialize)]
#[serde(untagged)]
pub enum PenaltySpec {
    /// A fixed ε̄.
    Value(f64),
    /// A word; only `"auto"` is valid.
    Word(String),
}

impl Default for PenaltySpec {
    fn default() -> Self {
        PenaltySpec::Word("auto".into())
    }
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
    /// Dimensionless penalty ε̄ (eq. 4.1f): `"auto"` (default: from the paper's 1e-5 down to
    /// what the tension criteria need) or a fixed number (1e-5 reproduces the paper).
    #[serde(default)]
    pub penalty: PenaltySpec,
    /// "nodal" (default) or "gauss".
    #[serde(default = "default_constraint")]
    pub constraint: ConstraintPoints,
    /// Cap on penalty iterations, default 50.
    #[serde(default = "default_max_iterations")]
    pub max_iterations: i64,
    /// Memory the solver may use, GiB; default 3/4 of the machine's memory.
    #[serde(default)]
    pub memory_limit_gib: Option<f64>,
    /// How the QP is posed: "auto" (default: primal on Winkler, schur on the half-space),
    /// "schur", "lifted" or "primal".
    #[serde(default = "default_qp_form")]
    pub qp_form: QpForm,
    /// Which solver runs the QP: "auto" (default: clarabel where its form fits and is robust,
    /// the matrix-free active-set method elsewhere), "clarabel" or "active-set".
    #[serde(default = "default_qp_solver")]
    pub qp_solver: QpSolver,
    /// How non-local foundations are held and solved: "auto" (default: dense up to 1500
    /// pressure nodes, iterative beyond), "dense" or "iterative" (T by FFT, conjugate
    /// gradients).
    #[serde(default = "default_route")]
    pub route: Route,
    /// Where a large grid starts: "nested" (default: from the same plate on a coarser grid)
    /// or "cold".
    #[serde(default)]
    pub start: Start,
    /// The penalty's confirming conjugate-gradient tolerance on the iterative route (default
    /// 1e-10; 1e-8 took 0.81–0.91× the time on the half-space lane, stresses to 8e-8,
    /// BENCHMARKS.md).
    #[serde(default)]
    pub cg_tolerance: Option<f64>,
}

fn default_qp_solver() -> QpSolver {
    QpSolver::Auto
}

fn default_route() -> Route {
    Route::Auto
}

fn default_qp_form() -> QpForm {
    QpForm::Auto
}

fn default_contact() -> Contact {
    Contact::Unbonded
}
fn default_method() -> MethodKind {
    MethodKind::Penalty
}
fn default_constraint() -> ConstraintPoints {
    ConstraintPoints::Nodal
}
fn default_max_iterations() -> i64 {
    crate::method::PenaltySettings::default().max_iterations as i64
}

impl Default for SolverSpec {
    fn default() -> Self {
        Self {
            contact: default_contact(),
            method: default_method(),
            penalty: PenaltySpec::default(),
            constraint: default_constraint(),
            max_iterations: default_max_iterations(),
            memory_limit_gib: None,
            qp_form: default_qp_form(),
            qp_solver: default_qp_solver(),
            route: default_route(),
            start: Start::Nested,
            cg_tolerance: None,
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
    /// The unit system the file is written in (`"si"`, the default, or `"us"`); a parsed
    /// scene holds SI values whatever it names ([`crate::units`]).
    #[serde(default)]
    pub units: crate::units::UnitSystem,
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
    /// Load combinations; without any, all loads act together.
    #[serde(default)]
    pub combination: Vec<CombinationSpec>,
    /// Voids under the plate.
    #[serde(default)]
    pub void: Vec<VoidSpec>,
    /// Holes through the slab.
    #[serde(default)]
    pub opening: Vec<OpeningSpec>,
    /// Joint lines cutting the plate into panels.
    #[serde(default)]
    pub joint: Vec<JointSpec>,
    /// Panels with their own thickness or Young's modulus.
    #[serde(default)]
    pub panel: Vec<PanelSpec>,
    /// Traffic over the design life (`liftoff damage`).
    #[serde(default)]
    pub traffic: Option<crate::damage::plan::TrafficSpec>,
    /// Climate bins of temperature difference (`liftoff damage`).
    #[serde(default)]
    pub climate: Option<crate::damage::plan::ClimateSpec>,
    /// The fatigue relation and the concrete's strength (`liftoff damage`).
    #[serde(default)]
    pub damage: Option<crate::damage::plan::DamageSpec>,
    /// Mesh.
    #[serde(default)]
    pub mesh: MeshSpec,
    /// Solver settings.
    #[serde(default)]
    pub solver: SolverSpec,
}
