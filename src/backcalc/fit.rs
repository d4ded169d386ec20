//! The best fit of a basin on liftoff's own model: the finite slab of a template scene, the
//! drop's disk at its true place, the soil and contact of the scene, and the unknowns the user
//! names — the subgrade's modulus and the slab's — found by least squares on the sensors'
//! deflections.
//!
//! **The model.** The template's plate, panels, joints and soil; its loads replaced by the
//! drop's disk (`kind = "circle"`), centred where the drop stood (the slab's centre for an
//! interior drop, a radius in from the edge at mid-length for an edge drop, a radius in from
//! both edges at the corner (−a/2, −b/2) for a corner drop; joint drops need their place). In
//! unbonded contact the template's loads stay as the state the drop starts from (self-weight,
//! curl at test time), and the basin is the deflection with the drop less the deflection
//! without it — what the sensors, zeroed before the drop, read; in bonded contact that
//! difference is the drop's own deflection, which alone is solved. The mesh: the template's
//! element counts, multiplied by the least whole number that makes the elements no wider than
//! 0.95 of the plate's radius (0.142 m for the 150 mm plate: within 1 % of the infinite plate
//! at every sensor, `tests/circle_load.rs`), or the caller's counts.
//!
//! **The fit.** The unknowns are fitted as θ = ln(value / start): positive by construction and
//! of one scale whatever their units. The residuals are (model − measured) / d₀, the sensors'
//! misfit as a share of the measured deflection at the plate. Levenberg–Marquardt (MINPACK's,
//! from the `levenberg-marquardt` crate) minimises their squares; the Jacobian is formed by
//! forward differences in θ with a step of 1e-4, one solve a column, the columns solved in
//! parallel — each difference a relative change of the modulus of 1e-4, far above the
//! solves' round-off (1e-12 bonded) and small against the basin's curvature in θ (the error
//! of the difference is half the step times the second derivative, about 1e-4 of the column).
//! The start is the AREA method's estimate ([`super::area`]) where it applies — an interior
//! drop with the four AREA sensors on a Winkler soil or a half-space — and the template's values
//! otherwise.
//!
//! **Confidence.** At the optimum the Jacobian J is formed anew; with m sensors, p unknowns and
//! s² = Σ r² / (m − p), the covariance of θ is s² (JᵀJ)⁻¹, and the 95 % interval of each value
//! is start · exp(θ ± t σ_θ), t the Student quantile at m − p degrees of freedom: asymmetric in
//! the modulus, symmetric in its logarithm, where the model is nearly linear. With as many
//! sensors as unknowns there is no interval.

use super::area::AreaResult;
use super::basins::{Drop, Location};
use super::template::{area_reading, nearest_joint};
use crate::entry::{run, Outcome};
use crate::error::{Error, Result};
use crate::foundation::soil::KeyValue;
use crate::layout::JointType;
use crate::method::Contact;
use crate::monitor::Monitor;
use crate::scene::{Coord, LoadKind, LoadSpec, SceneFile};
use levenberg_marquardt::{LeastSquaresProblem, LevenbergMarquardt, TerminationReason};
use nalgebra_lm::{DMatrix, DVector, Dyn, Owned};
use rayon::prelude::*;
use std::cell::RefCell;

/// What a fit may look for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Unknown {
    /// The soil's modulus: `modulus` (k, N/m³) where the template's soil has one (Winkler,
    /// Pasternak, Kerr), else `youngs_modulus` (E_s, Pa: the half-space, the elastic layer);
    /// the template's zones keep their ratio to it.
    Subgrade,
    /// The slab's Young's modulus (Pa), panels of their own modulus keeping their ratio to it.
    Slab,
    /// The depth (m) of the template's `[[void]]` nearest the drop: its extent is the
    /// template's, its depth the start. A void's depth acts only in unbonded contact.
    Void,
    /// The shear stiffness `stiffness` (AGG, N/m²: force per length of joint per unit jump of
    /// the deflection) of the template's joint nearest the drop, an `aggregate` or `tied` one.
    Joint,
}

crate::choice::names!(Unknown, Subgrade => "subgrade", Slab => "slab", Void => "void", Joint => "joint");

/// How a fit ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Termination {
    /// The residuals' reduction or the step fell below the tolerance, or the gradient vanished.
    Converged,
    /// The allowed number of evaluations was spent.
    TooManyEvaluations,
    /// The optimiser could not improve further at a tolerance the differences cannot meet.
    Stalled,
    /// A residual or the Jacobian was not finite.
    NotFinite,
}

crate::choice::names!(Termination, Converged => "converged", TooManyEvaluations => "too-many-evaluations",
    Stalled => "stalled", NotFinite => "not-finite");

/// The options of a fit.
#[derive(Debug, Clone, PartialEq)]
pub struct FitOptions {
    /// The unknowns, each once.
    pub unknowns: Vec<Unknown>,
    /// The contact law (None: the template's).
    pub contact: Option<Contact>,
    /// The mesh's element counts over the whole plate (None: see the module's description).
    pub elements: Option<[usize; 2]>,
    /// At most this many evaluations of the model in the optimiser (its Jacobians not counted).
    pub max_evaluations: usize,
}

impl Default for FitOptions {
    fn default() -> Self {
        Self {
            unknowns: vec![Unknown::Subgrade, Unknown::Slab],
            contact: None,
            elements: None,
            max_evaluations: 60,
        }
    }
}

/// One fitted value with its interval.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Estimate {
    /// What it is.
    pub unknown: Unknown,
    /// The scene key it sets (`foundation.modulus`, `plate.youngs_modulus`).
    pub key: String,
    /// The fitted value, SI.
    pub value: f64,
    /// The 95 % interval (None with no more sensors than unknowns).
    pub interval: Option<[f64; 2]>,
    /// Where the fit started.
    pub start: f64,
}

/// A drop's fit.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Fit {
    /// The fitted values.
    pub estimates: Vec<Estimate>,
    /// The radius of relative stiffness of the fitted slab on the fitted soil, m, with its 95 %
    /// interval — when both moduli are fitted: (D/k)^¼ on springs, (2D(1 − ν_s²)/E_s)^⅓ on a
    /// solid.
    pub ell: Option<(f64, Option<[f64; 2]>)>,
    /// The sensors' offsets, m.
    pub offsets: Vec<f64>,
    /// The measured deflections, m.
    pub measured: Vec<f64>,
    /// The model's deflections at the fitted values, m.
    pub fitted: Vec<f64>,
    /// The root mean square of the misfit, m.
    pub rms: f64,
    /// The largest misfit, m, signed (model − measured), and the sensor's offset, m.
    pub largest: (f64, f64),
    /// Where the fit started: `area` or `template`.
    pub start: &'static str,
    /// The AREA method's reading of the drop, where it applies ([`area_reading`]).
    pub area: Option<AreaResult>,
    /// Solves of the model, Jacobians included.
    pub solves: usize,
    /// Whether it converged.
    pub converged: bool,
    /// How it ended.
    pub termination: Termination,
}

impl Fit {
    /// The estimate of `unknown`, if fitted.
    pub fn estimate(&self, unknown: Unknown) -> Option<&Estimate> {
        self.estimates.iter().find(|e| e.unknown == unknown)
    }
}

/// Student's t at 0.975 for 1 … 30 degrees of freedom (NIST/SEMATECH e-Handbook of
/// Statistical Methods, §1.3.6.7.2, to three decimals).
const T975: [f64; 30] = [
    12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160,
    2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056,
    2.052, 2.048, 2.045, 2.042,
];

/// The two-sided 95 % quantile of Student's t with `dof` degrees of freedom: the table, then
/// the Cornish–Fisher expansion to its second term, z + (z³ + z)/(4ν) + (5z⁵ + 16z³ + 3z)/(96ν²)
/// (Abramowitz & Stegun 26.7.5; within 2e-4 of the exact 2.0395 at ν = 31).
pub fn student_t975(dof: usize) -> f64 {
    match dof {
        0 => f64::INFINITY,
        1..=30 => T975[dof - 1],
        _ => {
            let (z, nu): (f64, f64) = (1.959_964, dof as f64);
            z + (z.powi(3) + z) / (4.0 * nu)
                + (5.0 * z.powi(5) + 16.0 * z.powi(3) + 3.0 * z) / (96.0 * nu * nu)
        }
    }
}

/// The relative step of the forward differences in θ (see the module's description).
const STEP: f64 = 1e-4;

/// The scene's unknowns and where they are written.
#[derive(Debug, Clone)]
struct Target {
    unknown: Unknown,
    /// The scene key, for reports.
    key: String,
    /// The soil's key, for the subgrade.
    soil_key: &'static str,
    /// The void's or the joint's index in the template.
    index: usize,
}

/// The drop's model: the template prepared, the sensors placed.
pub(super) struct Forward<'m> {
    scene: SceneFile,
    targets: Vec<Target>,
    start: Vec<f64>,
    /// The sensors' points on the plate, m.
    pub(super) sensors: Vec<[f64; 2]>,
    background: bool,
    monitor: &'m Monitor<'m>,
    solves: std::sync::atomic::AtomicUsize,
}

impl Forward<'_> {
    /// The scene at θ.
    fn scene_at(&self, theta: &[f64]) -> SceneFile {
        let mut f = self.scene.clone();
        for ((t, &s), &th) in self.targets.iter().zip(&self.start).zip(theta) {
            let v = s * th.exp();
            match t.unknown {
                Unknown::Subgrade => {
                    if let Some(soil) = f.foundation.as_mut() {
                        let old = soil.number(t.soil_key).unwrap_or(v);
                        soil.soil
                            .insert(t.soil_key.to_string(), KeyValue::Number(v));
                        for z in &mut soil.zone {
                            z.modulus = z.modulus.map(|m| m * v / old);
                        }
                    }
                }
                Unknown::Slab => {
                    if let Some(p) = f.plate.as_mut() {
                        let old = p.youngs_modulus;
                        p.youngs_modulus = v;
                        for panel in &mut f.panel {
                            panel.youngs_modulus = panel.youngs_modulus.map(|e| e * v / old);
                        }
                    }
                }
                Unknown::Void => {
                    if let Some(void) = f.void.get_mut(t.index) {
                        void.depth = v;
                    }
                }
                Unknown::Joint => {
                    if let Some(joint) = f.joint.get_mut(t.index) {
                        joint.stiffness = Some(v);
                    }
                }
            }
        }
        f
    }

    /// The deflections at the sensors of one solve of `f`.
    fn sensors_of(&self, f: &SceneFile) -> Result<Vec<f64>> {
        self.solves
            .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let problem = f.validate()?;
        let Outcome::Single(a) = run(&problem, self.monitor)? else {
            return Err(Error::Unsupported(
                "a backcalculation's template has no combinations".into(),
            ));
        };
        if !a.summary.converged {
            return Err(Error::numerical(
                "the backcalculation's model",
                format!("the solve did not converge: {}", a.summary.status),
            ));
        }
        let field = &a.report.field;
        self.sensors
            .iter()
            .map(|&[x, y]| {
                field.at(&field.w, x, y).ok_or_else(|| {
                    Error::numerical("the backcalculation's model", "a sensor is off the plate")
                })
            })
            .collect()
    }

    /// The basin at θ: the drop's deflections (with the template's loads as the state it starts
    /// from, in unbonded contact).
    fn basin(&self, theta: &[f64]) -> Result<Vec<f64>> {
        let f = self.scene_at(theta);
        let with = self.sensors_of(&f)?;
        if !self.background {
            return Ok(with);
        }
        let mut g = f;
        g.load.pop(); // the drop is the last load
        let without = self.sensors_of(&g)?;
        Ok(with.iter().zip(&without).map(|(a, b)| a - b).collect())
    }

    /// The Jacobian of the basin in θ at `theta` (whose basin is `base`), by forward
    /// differences, column by column in parallel; m × p, column-major.
    fn jacobian(&self, theta: &[f64], base: &[f64]) -> Result<Vec<Vec<f64>>> {
        (0..theta.len())
            .into_par_iter()
            .map(|j| {
                let mut t = theta.to_vec();
                t[j] += STEP;
                let b = self.basin(&t)?;
                Ok(b.iter().zip(base).map(|(a, c)| (a - c) / STEP).collect())
            })
            .collect()
    }
}

/// The least-squares problem the optimiser sees: residuals scaled by d₀.
struct Misfit<'f, 'm> {
    forward: &'f Forward<'m>,
    measured: &'f [f64],
    scale: f64,
    theta: DVector<f64>,
    basin: RefCell<Option<Vec<f64>>>,
    error: RefCell<Option<Error>>,
}

impl Misfit<'_, '_> {
    fn keep<T>(&self, r: Result<T>) -> Option<T> {
        match r {
            Ok(v) => Some(v),
            Err(e) => {
                self.error.borrow_mut().get_or_insert(e);
                None
            }
        }
    }
}

impl LeastSquaresProblem<f64, Dyn, Dyn> for Misfit<'_, '_> {
    type ResidualStorage = Owned<f64, Dyn>;
    type JacobianStorage = Owned<f64, Dyn, Dyn>;
    type ParameterStorage = Owned<f64, Dyn>;

    fn set_params(&mut self, x: &DVector<f64>) {
        self.theta.copy_from(x);
        let b = self.forward.basin(x.as_slice());
        *self.basin.get_mut() = self.keep(b);
    }

    fn params(&self) -> DVector<f64> {
        self.theta.clone()
    }

    fn residuals(&self) -> Option<DVector<f64>> {
        let b = self.basin.borrow();
        let b = b.as_ref()?;
        Some(DVector::from_iterator(
            b.len(),
            b.iter()
                .zip(self.measured)
                .map(|(m, d)| (m - d) / self.scale),
        ))
    }

    fn jacobian(&self) -> Option<DMatrix<f64>> {
        let base = self.basin.borrow().clone()?;
        let cols = self.keep(self.forward.jacobian(self.theta.as_slice(), &base))?;
        Some(DMatrix::from_fn(base.len(), cols.len(), |i, j| {
            cols[j][i] / self.scale
        }))
    }
}

/// Where the drop stood on the template's plate and where its sensors are, checked to lie on
/// it (see the module's description for the locations' default places).
fn place(plate: &crate::scene::PlateSpec, drop: &Drop) -> Result<([f64; 2], Vec<[f64; 2]>)> {
    let label = drop.label();
    let (a, b, r) = (plate.length, plate.width, drop.basin.radius);
    let at = match (drop.at, drop.location) {
        (Some(p), _) => p,
        (None, Location::Interior) => [0.0, 0.0],
        (None, Location::Edge) => [0.0, -b / 2.0 + r],
        (None, Location::Corner) => [-a / 2.0 + r, -b / 2.0 + r],
        (None, l) => {
            return Err(Error::invalid(
                format!("{label}: x, y"),
                format!("a {l} drop needs the plate's place on the slab: give x_m and y_m"),
            ))
        }
    };
    if at[0].abs() + r > a / 2.0 * (1.0 + 1e-12) || at[1].abs() + r > b / 2.0 * (1.0 + 1e-12) {
        return Err(Error::invalid(
            format!("{label}: x, y"),
            format!(
                "the load plate of radius {r} m at ({}, {}) reaches beyond the template's {a} × {b} m plate: check the drop's place and the template's size",
                at[0], at[1]
            ),
        ));
    }
    let (c, s) = (
        drop.direction.to_radians().cos(),
        drop.direction.to_radians().sin(),
    );
    let sensors: Vec<[f64; 2]> = drop
        .basin
        .offsets
        .iter()
        .map(|&o| [at[0] + o * c, at[1] + o * s])
        .collect();
    for (o, p) in drop.basin.offsets.iter().zip(&sensors) {
        if p[0].abs() > a / 2.0 * (1.0 + 1e-12) || p[1].abs() > b / 2.0 * (1.0 + 1e-12) {
            return Err(Error::invalid(
                format!("{label}: sensor at {:.0} mm", 1e3 * o),
                format!(
                    "falls at ({:.3}, {:.3}) m, off the template's {a} × {b} m plate: check the drop's place and direction",
                    p[0], p[1]
                ),
            ));
        }
    }
    Ok((at, sensors))
}

/// On a template of another outline (`[plate] outline`, `[[opening]]`, region panels), every
/// sensor on the plate: one over an opening would read a deflection that is not there. (The
/// load plate on an opening is refused with the drop's scene, E80.)
fn on_shape(template: &SceneFile, drop: &Drop, sensors: &[[f64; 2]]) -> Result<()> {
    // The shape in the scene's own coordinates (metres): only its point tests are used.
    let shape = crate::scene::scene_shape(template)?;
    if !shape.is_shaped() {
        return Ok(());
    }
    for (o, p) in drop.basin.offsets.iter().zip(sensors) {
        if !shape.is_plate(p[0], p[1]) {
            return Err(Error::invalid(
                format!("{}: sensor at {:.0} mm", drop.label(), 1e3 * o),
                format!(
                    "falls at ({:.3}, {:.3}) m, on an opening or outside the template's outline: check the drop's place and direction",
                    p[0], p[1]
                ),
            ));
        }
    }
    Ok(())
}

/// The unknowns as the scene keys they write, with the template's values as their starts.
fn targets(
    template: &SceneFile,
    plate: &crate::scene::PlateSpec,
    soil: &crate::scene::FoundationSpec,
    at: [f64; 2],
    unknowns: &[Unknown],
) -> Result<(Vec<Target>, Vec<f64>)> {
    let mut targets = Vec::new();
    let mut start = Vec::new();
    for (i, &u) in unknowns.iter().enumerate() {
        if unknowns[..i].contains(&u) {
            return Err(Error::invalid("unknowns", format!("`{u}` is named twice")));
        }
        match u {
            Unknown::Subgrade => {
                let key = ["modulus", "youngs_modulus"]
                    .into_iter()
                    .find(|k| soil.number(k).is_some())
                    .ok_or_else(|| {
                        Error::invalid(
                            "foundation",
                            format!(
                                "the {} soil has neither `modulus` nor `youngs_modulus` to fit",
                                soil.model
                            ),
                        )
                    })?;
                targets.push(Target {
                    unknown: u,
                    key: format!("foundation.{key}"),
                    soil_key: key,
                    index: 0,
                });
                start.push(soil.number(key).unwrap_or(f64::NAN));
            }
            Unknown::Slab => {
                targets.push(Target {
                    unknown: u,
                    key: "plate.youngs_modulus".into(),
                    soil_key: "",
                    index: 0,
                });
                start.push(plate.youngs_modulus);
            }
            Unknown::Void => {
                // The void nearest the plate's centre: distance from the point to the
                // rectangle.
                let distance = |v: &crate::scene::VoidSpec| {
                    let dx = (v.x[0] - at[0]).max(at[0] - v.x[1]).max(0.0);
                    let dy = (v.y[0] - at[1]).max(at[1] - v.y[1]).max(0.0);
                    dx.hypot(dy)
                };
                let (k, v) = template
                    .void
                    .iter()
                    .enumerate()
                    .min_by(|a, b| distance(a.1).total_cmp(&distance(b.1)))
                    .ok_or_else(|| {
                        Error::invalid(
                            "void",
                            "fitting a void needs a [[void]] in the template under the drop: its x and y give the void's extent, its depth where the fit starts",
                        )
                    })?;
                if v.depth.is_nan() || v.depth <= 0.0 {
                    return Err(Error::invalid(
                        format!("void[{k}].depth"),
                        "a fitted void starts from a positive depth (say 0.5 mm)",
                    ));
                }
                targets.push(Target {
                    unknown: u,
                    key: format!("void[{k}].depth"),
                    soil_key: "",
                    index: k,
                });
                start.push(v.depth);
            }
            Unknown::Joint => {
                let (k, j) = nearest_joint(template, at).ok_or_else(|| {
                    Error::invalid(
                        "joint",
                        "fitting a joint's stiffness needs a [[joint]] in the template beside the drop",
                    )
                })?;
                let stiffness = match (j.kind, j.stiffness) {
                    (JointType::Aggregate | JointType::Tied, Some(c)) if c > 0.0 => c,
                    _ => {
                        return Err(Error::invalid(
                            format!("joint[{k}].stiffness"),
                            format!(
                                "the joint nearest the drop is `{}`{}: a fitted joint is an aggregate or tied joint with a positive stiffness to start from",
                                j.kind,
                                j.stiffness.map_or(String::new(), |c| format!(" of stiffness {c}"))
                            ),
                        ))
                    }
                };
                targets.push(Target {
                    unknown: u,
                    key: format!("joint[{k}].stiffness"),
                    soil_key: "",
                    index: k,
                });
                start.push(stiffness);
            }
        }
    }
    if targets.is_empty() {
        return Err(Error::invalid(
            "unknowns",
            "name at least one: subgrade, slab",
        ));
    }
    Ok((targets, start))
}

/// The template as the drop's model: its combinations dropped, the contact asked, its loads
/// kept as the state before the drop in unbonded contact (with the curl at test time) and
/// dropped in bonded contact, the drop's disk as the last load, the mesh refined. Returns the
/// scene and whether the basin is a difference of two solves.
fn drop_scene(
    template: &SceneFile,
    plate: &crate::scene::PlateSpec,
    drop: &Drop,
    at: [f64; 2],
    options: &FitOptions,
) -> Result<(SceneFile, bool)> {
    let label = drop.label();
    let (a, b, r) = (plate.length, plate.width, drop.basin.radius);
    let mut f = template.clone();
    f.combination.clear();
    if let Some(c) = options.contact {
        f.solver.contact = c;
    }
    if f.solver.contact != Contact::Unbonded {
        f.load.clear();
    }
    if let Some(dt) = drop.temperature_difference {
        // The curl at test time: part of the state the drop starts from (it changes the drop's
        // deflection only where the slab lifts, in unbonded contact).
        if plate.thermal_expansion.is_none() {
            return Err(Error::invalid(
                format!("{label}: dT"),
                "a temperature at test time needs the template's plate.thermal_expansion (say 1.0e-5 1/K)",
            ));
        }
        if f.solver.contact == Contact::Unbonded {
            let mut t = LoadSpec::new(LoadKind::Temperature);
            t.difference = Some(dt);
            t.name = Some("temperature at test time".into());
            f.load.insert(0, t);
        }
    }
    let background = f.solver.contact == Contact::Unbonded && !f.load.is_empty();
    let mut disk = LoadSpec::new(LoadKind::Circle);
    disk.x = Some(Coord::Value(at[0]));
    disk.y = Some(Coord::Value(at[1]));
    disk.radius = Some(r);
    disk.force = Some(drop.basin.load);
    disk.name = Some("deflectometer".into());
    f.load.push(disk);
    f.mesh.elements = match options.elements {
        Some([nx, ny]) => vec![nx as i64, ny as i64],
        None => {
            let base: Vec<usize> = f.mesh.elements.iter().map(|&n| n.max(1) as usize).collect();
            let (bx, by) = (
                base.first().copied().unwrap_or(16),
                base.get(1).copied().unwrap_or(16),
            );
            let widest = (a / bx as f64).max(b / by as f64);
            let m = (widest / (0.95 * r)).ceil().max(1.0) as usize;
            vec![(bx * m) as i64, (by * m) as i64]
        }
    };
    Ok((f, background))
}

/// The template's stand for the drop: its place, the sensors along their line, the unknowns,
/// the drop's model.
pub(super) fn prepare<'m>(
    template: &SceneFile,
    drop: &Drop,
    options: &FitOptions,
    monitor: &'m Monitor<'m>,
) -> Result<Forward<'m>> {
    let plate = template.plate.as_ref().ok_or_else(|| {
        Error::invalid(
            "plate",
            "a backcalculation's template is a physical scene: give [plate] and [foundation]",
        )
    })?;
    let soil = template.foundation.as_ref().ok_or_else(|| {
        Error::invalid(
            "foundation",
            "a backcalculation's template is a physical scene: give [plate] and [foundation]",
        )
    })?;
    let (at, sensors) = place(plate, drop)?;
    on_shape(template, drop, &sensors)?;
    let (targets, start) = targets(template, plate, soil, at, &options.unknowns)?;
    let (scene, background) = drop_scene(template, plate, drop, at, options)?;
    Ok(Forward {
        scene,
        targets,
        start,
        sensors,
        background,
        monitor,
        solves: std::sync::atomic::AtomicUsize::new(0),
    })
}

/// The model's basin for `drop` at the template's own moduli: what the fit compares with the
/// measured deflections (the drop's deflections are not read) — synthetic basins, and the
/// model's prediction for a survey.
pub fn model_basin(
    template: &SceneFile,
    drop: &Drop,
    options: &FitOptions,
    monitor: &Monitor<'_>,
) -> Result<Vec<f64>> {
    let quiet = monitor.quiet();
    let forward = prepare(template, drop, options, &quiet)?;
    forward.basin(&vec![0.0; forward.targets.len()])
}

/// Fit one drop on the template's model (see the module's description). A fit that does not
/// converge is returned with its best point and `converged: false`; a solve that fails is an
/// error.
pub fn fit_drop(
    template: &SceneFile,
    drop: &Drop,
    options: &FitOptions,
    monitor: &Monitor<'_>,
) -> Result<Fit> {
    drop.check()?;
    if options.max_evaluations == 0 {
        return Err(Error::invalid(
            "max_evaluations",
            "a fit needs at least one evaluation of the model",
        ));
    }
    let quiet = monitor.quiet();
    let mut forward = prepare(template, drop, options, &quiet)?;
    let mut started = "template";
    let area = area_reading(template, drop);
    if let Some(a) = area {
        let s: Vec<f64> = forward
            .targets
            .iter()
            .zip(&forward.start)
            .map(|(t, &own)| match t.unknown {
                Unknown::Subgrade => a.subgrade_modulus,
                Unknown::Slab => a.slab_modulus,
                Unknown::Void | Unknown::Joint => own,
            })
            .collect();
        if s.iter().all(|v| v.is_finite() && *v > 0.0) {
            forward.start = s;
            started = "area";
        }
    }
    let measured = &drop.basin.deflections;
    let p = forward.targets.len();
    let mut misfit = Misfit {
        forward: &forward,
        measured,
        scale: measured[0],
        theta: DVector::zeros(p),
        basin: RefCell::new(None),
        error: RefCell::new(None),
    };
    misfit.set_params(&DVector::zeros(p));
    if let Some(e) = misfit.error.borrow_mut().take() {
        return Err(e);
    }
    // Tolerances: the residuals' squares and the step relative to 1e-10 — far below the
    // sensors' resolution (1 µm in a 100 µm basin, 1e-2) and above the differences' error.
    let lm = LevenbergMarquardt::new()
        .with_ftol(1e-10)
        .with_xtol(1e-10)
        .with_gtol(1e-10)
        .with_patience(options.max_evaluations.div_ceil(p + 1).max(1));
    let (solved, report) = lm.minimize(misfit);
    if let Some(e) = solved.error.borrow_mut().take() {
        return Err(e);
    }
    let termination = match report.termination {
        TerminationReason::Converged { .. }
        | TerminationReason::Orthogonal
        | TerminationReason::ResidualsZero => Termination::Converged,
        TerminationReason::LostPatience => Termination::TooManyEvaluations,
        TerminationReason::Numerical(_) => Termination::NotFinite,
        _ => Termination::Stalled,
    };
    let theta: Vec<f64> = solved.theta.iter().copied().collect();
    let fitted = match solved.basin.into_inner() {
        Some(b) => b,
        None => forward.basin(&theta)?,
    };
    let m = measured.len();
    let residuals: Vec<f64> = fitted.iter().zip(measured).map(|(a, b)| a - b).collect();
    let rms = (residuals.iter().map(|r| r * r).sum::<f64>() / m as f64).sqrt();
    let largest = residuals
        .iter()
        .zip(&drop.basin.offsets)
        .max_by(|a, b| a.0.abs().total_cmp(&b.0.abs()))
        .map(|(r, o)| (*r, *o))
        .unwrap_or((0.0, 0.0));
    // The covariance of θ at the optimum.
    let sigma = if m > p {
        let cols = forward.jacobian(&theta, &fitted)?;
        let scale = measured[0];
        let j = nalgebra::DMatrix::from_fn(m, p, |i, c| cols[c][i] / scale);
        let s2 = residuals.iter().map(|r| (r / scale).powi(2)).sum::<f64>() / (m - p) as f64;
        (j.transpose() * &j).try_inverse().map(|inv| inv * s2)
    } else {
        None
    };
    let t = student_t975(m.saturating_sub(p));
    let estimates: Vec<Estimate> = forward
        .targets
        .iter()
        .enumerate()
        .map(|(i, tg)| {
            let value = forward.start[i] * theta[i].exp();
            let interval = sigma.as_ref().map(|c| {
                let w = t * c[(i, i)].max(0.0).sqrt();
                [value * (-w).exp(), value * w.exp()]
            });
            Estimate {
                unknown: tg.unknown,
                key: tg.key.clone(),
                value,
                interval,
                start: forward.start[i],
            }
        })
        .collect();
    let ell =
        radius_of_relative_stiffness(template, &forward.targets, &estimates, sigma.as_ref(), t);
    Ok(Fit {
        estimates,
        ell,
        offsets: drop.basin.offsets.clone(),
        measured: measured.clone(),
        fitted,
        rms,
        largest,
        start: started,
        area,
        solves: forward.solves.load(std::sync::atomic::Ordering::Relaxed),
        converged: termination == Termination::Converged,
        termination,
    })
}

/// ℓ of the fitted slab on the fitted soil with its interval, when both are fitted: ln ℓ =
/// (ln E − ln k)/4 on springs, (ln E − ln E_s)/3 on a solid, so var ln ℓ = (σ²_E + σ²_k −
/// 2 cov)/n².
fn radius_of_relative_stiffness(
    template: &SceneFile,
    targets: &[Target],
    estimates: &[Estimate],
    sigma: Option<&nalgebra::DMatrix<f64>>,
    t: f64,
) -> Option<(f64, Option<[f64; 2]>)> {
    let plate = template.plate.as_ref()?;
    let soil = template.foundation.as_ref()?;
    let ks = targets
        .iter()
        .position(|t| t.unknown == Unknown::Subgrade)?;
    let es = targets.iter().position(|t| t.unknown == Unknown::Slab)?;
    let d = estimates[es].value * plate.thickness.powi(3)
        / (12.0 * (1.0 - plate.poissons_ratio.powi(2)));
    let (ell, n) = if targets[ks].soil_key == "modulus" {
        ((d / estimates[ks].value).powf(0.25), 4.0)
    } else {
        let nu_s = soil.number("poissons_ratio").unwrap_or(0.0);
        (
            (2.0 * d * (1.0 - nu_s * nu_s) / estimates[ks].value).cbrt(),
            3.0,
        )
    };
    let interval = sigma.map(|c| {
        let var = (c[(es, es)] + c[(ks, ks)] - 2.0 * c[(es, ks)]) / (n * n);
        let w = t * var.max(0.0).sqrt();
        [ell * (-w).exp(), ell * w.exp()]
    });
    Some((ell, interval))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_t_quantile_meets_the_normal_one() {
        assert_eq!(student_t975(6), 2.447);
        // Beyond the table the expansion continues it: at 31 within 2e-4 of the exact 2.0395
        // (NIST's table to four places), and it tends to z.
        let z: f64 = 1.959_964;
        assert!((student_t975(31) - 2.0395).abs() < 2e-4);
        assert!((student_t975(100_000) - z).abs() < 1e-4);
        assert!(student_t975(0).is_infinite());
    }
}
