//! The JSON summary of a solve (`summary.json`, `liftoff solve --json`). Every key is
//! documented in the README.

use serde::Serialize;

use crate::error::{Error, Result};
use crate::foundation::FoundationKind;
use crate::method::{Contact, Method, QpSolver, SolvedBy};
use crate::model::ConstraintPoints;
use crate::model::{Groups, LoadReference, Model, Physical};
use crate::operators::Operators;
use crate::post::{Complementarity, Extent, Report, Resultant};
use crate::solve::{Iteration, PenaltyStage, Solution};
use crate::units::Measure;

/// summary.json's `dimensionless`: the model's [`Groups`] (their foundation is the summary's
/// own `foundation`), the Pasternak decay length, ε̄ and what P is. The groups read as its own
/// fields (`Deref`), as they are written (`flatten`).
#[derive(Debug, Clone, Serialize)]
pub struct Dimensionless {
    /// Γ_w or Γ_h, Δ, μ, ν_p and the soil's own groups, as in the model.
    #[serde(flatten)]
    pub groups: Groups,
    /// Pasternak only: the decay length λ/L = √(Γ_g μ Γ_w) (absent for the other soils).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub decay_length: Option<f64>,
    /// ε̄ of the penalty method (null for the QP and bonded contact, which have none).
    pub penalty: Option<f64>,
    /// What P in V = D w / (P L²) and σ = μ L² r / P is: "net-load" (4P = the net load, the
    /// paper's P), or, when the loads add up to zero (bonded contact only), "downward-load"
    /// (4P = the sum of the downward loads) or "thermal-moment" (P = D κ, so V = w / (κ L²)).
    pub reference: LoadReference,
    /// P in the scene's force unit (N for SI scenes; the loads' unit for dimensionless ones).
    pub reference_force: f64,
}

impl std::ops::Deref for Dimensionless {
    type Target = Groups;

    fn deref(&self) -> &Groups {
        &self.groups
    }
}

/// Wall-clock times, seconds.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Times {
    /// Assembling the operators.
    pub assemble: f64,
    /// The method.
    pub solve: f64,
    /// Everything including post-processing.
    pub total: f64,
}

/// The summary of a solve.
#[derive(Debug, Clone, Serialize)]
#[allow(non_snake_case)]
pub struct Summary {
    /// Scene title.
    pub title: String,
    /// "penalty", "qp" or "direct" (bonded).
    pub method: SolvedBy,
    /// "bonded" or "unbonded".
    pub contact: Contact,
    /// "full", "half-x", "half-y" or "quarter".
    pub symmetry: String,
    /// "winkler", "half-space", "pasternak" or "elastic-layer".
    pub foundation: FoundationKind,
    /// Constraint points ("nodal" or "gauss").
    pub constraint: ConstraintPoints,
    /// Elements [nx, ny] over the whole plate.
    pub elements: [usize; 2],
    /// Elements [nx, ny] of the solved model.
    pub model_elements: [usize; 2],
    /// Nodes of the solved model.
    pub nodes: usize,
    /// Equations (free dofs) of the solved model.
    pub dofs: usize,
    /// Dimensionless groups.
    pub dimensionless: Dimensionless,
    /// Physical scales (absent for dimensionless scenes).
    pub physical: Option<Physical>,
    /// Whether the method converged.
    pub converged: bool,
    /// Status text.
    pub status: String,
    /// Linear solves (penalty) or interior-point iterations (QP).
    pub iterations: usize,
    /// Times.
    pub time_s: Times,
    /// Phase timings of the method.
    pub method_time_s: std::collections::BTreeMap<String, f64>,
    /// The solver that ran the QP ("clarabel" or "active-set"; absent for other methods).
    pub qp_solver: Option<QpSolver>,
    /// Solver diagnostics (QP by clarabel: its primal and dual residuals, objective, duality
    /// gap; by the active-set solver: outer and CG iterations, products, KKT residuals).
    pub solver_info: std::collections::BTreeMap<String, f64>,
    /// Largest deflection, physical.
    pub w_max: f64,
    /// Largest V.
    pub V_max: f64,
    /// V at the centre (NaN, null in JSON, where a shaped plate has no plate there).
    pub V_center: f64,
    /// V at the corner (+L, +μL) (NaN, null in JSON, where a shaped plate has no plate there).
    pub V_corner: f64,
    /// Largest contact pressure, physical.
    pub pressure_max: f64,
    /// Extreme bending moments per unit length, physical.
    pub moments: crate::post::Moments,
    /// Contact area / plate area.
    pub contact_fraction: f64,
    /// A shaped plate's area over its bounding rectangle's (absent on a rectangle: 1).
    #[serde(skip_serializing_if = "is_whole")]
    pub plate_fraction: f64,
    /// √(contact area / π) / L.
    pub contact_radius: f64,
    /// Contact extents.
    pub contact_extent: Extent,
    /// Equilibrium check.
    pub resultant: Resultant,
    /// Unilateral residuals.
    pub complementarity: Complementarity,
    /// Iteration history of the penalty method.
    pub history: Vec<Iteration>,
    /// The penalty method's stages, one per ε̄ tried (one for a fixed ε̄; empty for other
    /// methods); the last is the ε̄ reported in `dimensionless.penalty`.
    pub penalty_stages: Vec<PenaltyStage>,
    /// The bearing check (present when the scene gives an allowable pressure).
    pub bearing: Option<crate::post::Bearing>,
    /// The largest tensile principal stress at the bottom and the top face, where and in which
    /// direction (Pa; P/L² in a dimensionless scene), and the thickness they were taken with.
    pub stresses: crate::post::stress::StressSummary,
    /// What each joint that cuts the plate carries: its LTE by deflection and by stress and
    /// where, the force it transfers, its largest shear and moment per length, dowel force
    /// and bearing stress (absent without joints).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub joints: Vec<crate::post::JointReport>,
    /// Modelling notes.
    pub notes: Vec<String>,
}

impl Summary {
    /// Assemble the summary.
    pub fn new(
        model: &Model,
        ops: &Operators,
        sol: &Solution,
        report: &Report,
        times: Times,
    ) -> Self {
        let named =
            |v: Vec<(&'static str, f64)>| v.into_iter().map(|(k, x)| (k.to_string(), x)).collect();
        Summary {
            title: model.title.clone(),
            method: sol.method.solved_by(),
            contact: sol.method.contact(),
            symmetry: ops.mesh.symmetry_name().into(),
            foundation: model.groups.foundation(),
            constraint: ops.constraints.kind,
            elements: model.elements,
            model_elements: [ops.mesh.nx, ops.mesh.ny],
            nodes: ops.mesh.n_nodes(),
            dofs: ops.n_eq(),
            dimensionless: Dimensionless {
                groups: model.groups,
                decay_length: model
                    .groups
                    .soil
                    .decay_length(model.groups.gamma, model.groups.mu),
                penalty: sol.method.penalty_epsilon(),
                reference: model.reference,
                reference_force: model.load_scale,
            },
            physical: model.physical,
            converged: sol.status.converged(),
            status: sol.status.describe(),
            iterations: sol.iterations,
            time_s: times,
            method_time_s: named(sol.info.timings.named()),
            qp_solver: match &sol.method {
                Method::Qp(s) => Some(s.solver),
                _ => None,
            },
            solver_info: {
                let mut info = sol.info.qp.map(|q| named(q.named())).unwrap_or_default();
                if let Some(a) = sol.info.active_set {
                    info.extend(named(a.named()));
                }
                if let Some(n) = sol.info.cg_iterations {
                    info.insert("cg_iterations".into(), n as f64);
                }
                info
            },
            w_max: report.w_max,
            V_max: report.v_max,
            V_center: report.v_center,
            V_corner: report.v_corner,
            pressure_max: report.pressure_max,
            moments: report.moments,
            contact_fraction: report.contact_fraction,
            plate_fraction: report.plate_fraction,
            contact_radius: report.contact_radius,
            contact_extent: report.contact_extent,
            resultant: report.resultant,
            complementarity: report.complementarity,
            history: sol.history.clone(),
            penalty_stages: sol.info.penalty_stages.clone(),
            bearing: report.bearing,
            stresses: report.stress,
            joints: report.joints.clone(),
            notes: ops
                .notes
                .iter()
                .chain(&sol.info.notes)
                .chain(&report.notes)
                .cloned()
                .collect(),
        }
    }

    /// Pretty JSON ([`Self::to_value`]).
    pub fn to_json(&self) -> Result<String> {
        serde_json::to_string_pretty(&self.to_value()?)
            .map_err(|e| Error::numerical("summary", format!("cannot serialise: {e}")))
    }

    /// The summary as summary.json writes it: every physical value ([`MEASURED`]) in the
    /// scene's unit system, and a `units` object naming the system and each such key's unit
    /// (a dimensionless scene's keys in the paper's scales: L, P, P/L², …).
    pub fn to_value(&self) -> Result<serde_json::Value> {
        let mut v = serde_json::to_value(self)
            .map_err(|e| Error::numerical("summary", format!("cannot serialise: {e}")))?;
        let system = self.physical.map(|p| p.units);
        let mut units = serde_json::Map::new();
        let name = system.map_or("dimensionless", |s| s.name());
        units.insert("system".into(), name.into());
        for &(path, m) in MEASURED {
            let keys: Vec<&str> = path.split('.').collect();
            if convert(&mut v, &keys, &|x| m.from_si(system, x)) {
                units.insert(path.into(), m.unit(system).into());
            }
        }
        if let Some(o) = v.as_object_mut() {
            o.insert("units".into(), units.into());
        }
        Ok(v)
    }

    /// Short description for chart titles.
    pub fn headline(&self) -> String {
        format!(
            "{} {}, Γ = {:.3e}, {} × {} elements",
            self.contact,
            self.foundation,
            self.dimensionless.gamma,
            self.elements[0],
            self.elements[1]
        )
    }
}

/// The keys of summary.json that hold physical values, and what each measures; `*` stands for
/// every entry of an array (the joints). The rest are pure numbers (V, σ, fractions, the
/// dimensionless groups, residuals in the paper's units), words or times in seconds.
pub const MEASURED: &[(&str, Measure)] = &[
    ("physical.half_length", Measure::Length),
    ("physical.force", Measure::Force),
    ("physical.rigidity", Measure::Moment),
    ("dimensionless.reference_force", Measure::Force),
    ("w_max", Measure::Deflection),
    ("pressure_max", Measure::Pressure),
    ("moments.mx", Measure::MomentPerLength),
    ("moments.my", Measure::MomentPerLength),
    ("resultant.load", Measure::Force),
    ("resultant.reaction", Measure::Force),
    ("bearing.allowable", Measure::Pressure),
    ("bearing.length", Measure::Length),
    ("bearing.average", Measure::Pressure),
    ("bearing.average_at", Measure::Length),
    ("bearing.max", Measure::Pressure),
    ("bearing.area_exceeding", Measure::Area),
    ("stresses.bottom.value", Measure::Pressure),
    ("stresses.bottom.x", Measure::Length),
    ("stresses.bottom.y", Measure::Length),
    ("stresses.top.value", Measure::Pressure),
    ("stresses.top.x", Measure::Length),
    ("stresses.top.y", Measure::Length),
    ("stresses.thickness", Measure::Length),
    ("joints.*.line", Measure::Length),
    ("joints.*.at", Measure::Length),
    ("joints.*.transferred_force", Measure::Force),
    ("joints.*.max_shear_per_length", Measure::ForcePerLength),
    ("joints.*.max_moment_per_length", Measure::MomentPerLength),
    ("joints.*.max_dowel_force", Measure::Force),
    ("joints.*.max_bearing_stress", Measure::Pressure),
];

/// Apply `f` to the numbers at `keys` under `v` (a number, or an array of numbers; `*` walks
/// every entry of an array); whether any number was there.
fn convert(v: &mut serde_json::Value, keys: &[&str], f: &dyn Fn(f64) -> f64) -> bool {
    use serde_json::Value;
    match (keys.split_first(), v) {
        (None, Value::Number(n)) => {
            match n.as_f64().and_then(|x| serde_json::Number::from_f64(f(x))) {
                Some(m) => {
                    *n = m;
                    true
                }
                None => false,
            }
        }
        // Every entry is converted: no short circuit.
        (None, Value::Array(a)) => a
            .iter_mut()
            .map(|x| convert(x, &[], f))
            .fold(false, bool::max),
        (Some((&"*", rest)), Value::Array(a)) => a
            .iter_mut()
            .map(|x| convert(x, rest, f))
            .fold(false, bool::max),
        (Some((k, rest)), Value::Object(o)) => o.get_mut(*k).is_some_and(|x| convert(x, rest, f)),
        _ => false,
    }
}

/// True for a plate that is its whole bounding rectangle (`plate_fraction` = 1).
fn is_whole(fraction: &f64) -> bool {
    *fraction == 1.0
}
