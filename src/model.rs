//! The method-free model: plate, foundation, loads, mesh and symmetry, constraint points — in the
//! solver's unit system.
//!
//! * lengths in units of L (half the side along x): the plate is [−1, 1] × [−μ, μ];
//! * forces in units of P, where 4P is the resultant of the loads (for a bonded plate whose loads
//!   add up to zero, a stated reference instead: [`LoadReference`]);
//! * flexural rigidity D = 1, so deflections are the paper's V = D w / (P L²);
//! * shear rigidity κ_s = χ G H L² / D = 1 / (μ Δ);
//! * Winkler modulus K L⁴ / D = 1 / (μ Γ_w); half-space constant
//!   (1 − ν_s²) D / (π E_s L³) = μ Γ_h.
//!
//! The paper's dimensionless pressure is σ = μ L² r / P = μ r in these units.
//!
//! A [`Model`] comes from a scene file ([`crate::scene`]) or from Rust through
//! [`Model::builder`]; either way it says nothing about how it will be solved: that is a
//! [`crate::method::Method`].

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::foundation::{FoundationKind, Soil};
use crate::layout::Layout;
use crate::mesh::Mesh;
use crate::vehicle::Vehicle;

/// Where σ ≥ 0 is imposed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum ConstraintPoints {
    /// At the nodes (σ ≥ 0 everywhere for bilinear σ).
    Nodal,
    /// At the 2 × 2 Gauss points of each element (the paper's eqs. 4.3–4.4).
    Gauss,
}

/// Whether to reduce the model by symmetry.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SymmetryMode {
    /// Model a half or a quarter when the loads allow it.
    Auto,
    /// Always model the whole plate.
    None,
}

crate::choice::names!(ConstraintPoints, Nodal => "nodal", Gauss => "gauss");
crate::choice::names!(SymmetryMode, Auto => "auto", None => "none");

/// The paper's dimensionless groups of a problem, defined once: the model holds them and
/// summary.json's `dimensionless` writes them (in this serde form, beside what the solve adds).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Groups {
    /// Γ_w or Γ_h (Pasternak and Kerr: Γ_w of the (lower) springs, D/(k μ L⁴)).
    pub gamma: f64,
    /// Δ.
    pub delta: f64,
    /// μ.
    pub mu: f64,
    /// ν_p.
    pub nu: f64,
    /// The soil with its own groups, written after these (summary.json names the soil at its
    /// top level, `foundation`).
    #[serde(flatten)]
    pub soil: Soil,
}

impl Groups {
    /// The soil's name.
    pub fn foundation(&self) -> FoundationKind {
        self.soil.kind()
    }

    /// The soil's surface kernel in the unit system (None for the local Winkler soil).
    pub fn kernel(&self) -> Option<crate::foundation::kernel::Kernel> {
        self.soil.kernel(self.gamma, self.mu)
    }
}

/// Physical scales of a scene given in SI units.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Physical {
    /// L: half the side along x, m.
    pub half_length: f64,
    /// P: a quarter of the load resultant, N (or the stated reference: [`LoadReference`]).
    pub force: f64,
    /// D, N·m.
    pub rigidity: f64,
    /// The unit system the scene was written in, which its outputs show.
    pub units: crate::units::UnitSystem,
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
    /// Uniform force per length along a segment.
    Line {
        /// Start (x, y) / L.
        from: [f64; 2],
        /// End (x, y) / L.
        to: [f64; 2],
        /// q L / P.
        force_per_length: f64,
    },
    /// Temperature linear through the thickness: the free curling curvature κ = α ΔT / H
    /// (top warmer is positive: the plate domes, its edges go down), as an initial curvature
    /// of the plate in both directions.
    Temperature {
        /// κ D / P, the curvature ∂²V/∂s² of the plate curling freely.
        curvature: f64,
    },
    /// The self-equilibrating stress of a nonlinear temperature profile at the top and bottom
    /// faces (no resultant, no moment: it bends nothing and adds to the surface stresses),
    /// σ L² / P, tension positive.
    FaceStress {
        /// At the top face.
        top: f64,
        /// At the bottom face.
        bottom: f64,
    },
}

/// A void: over a rectangle the soil surface lies `depth` lower, so the gap there starts at
/// `depth` (σ ≥ 0, gap ≥ 0, σ · gap = 0 with the gap measured from the lowered surface).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Void {
    /// [x0, x1] / L.
    pub x: [f64; 2],
    /// [y0, y1] / L.
    pub y: [f64; 2],
    /// Depth in units of P L² / D (the unit of V).
    pub depth: f64,
}

pub use crate::foundation::winkler::Zone;

/// True when the rectangle is its own mirror image about x = 0 (`about_x`) or y = 0.
fn rect_symmetric(x: [f64; 2], y: [f64; 2], about_x: bool, tol: f64) -> bool {
    let r = if about_x { x } else { y };
    (r[0] + r[1]).abs() < tol
}

/// True when a set of rectangles (each with a value) is unchanged by the mirror.
fn rects_symmetric(rects: &[([f64; 2], [f64; 2], f64)], about_x: bool) -> bool {
    let tol = 1e-9;
    let mut used = vec![false; rects.len()];
    for &(x, y, v) in rects {
        if rect_symmetric(x, y, about_x, tol) {
            continue;
        }
        let (mx, my) = if about_x {
            ([-x[1], -x[0]], y)
        } else {
            (x, [-y[1], -y[0]])
        };
        let found = rects.iter().enumerate().position(|(k, &(cx, cy, cv))| {
            !used[k]
                && (cx[0] - mx[0]).abs() < tol
                && (cx[1] - mx[1]).abs() < tol
                && (cy[0] - my[0]).abs() < tol
                && (cy[1] - my[1]).abs() < tol
                && (cv - v).abs() <= tol * cv.abs().max(v.abs())
        });
        match found {
            Some(k) => used[k] = true,
            None => return false,
        }
    }
    true
}

impl Load {
    /// Resultant of the load.
    pub fn resultant(&self) -> f64 {
        match *self {
            Load::Point { force, .. } => force,
            Load::Patch { x, y, pressure } => pressure * (x[1] - x[0]) * (y[1] - y[0]),
            Load::Line {
                from,
                to,
                force_per_length,
            } => force_per_length * (to[0] - from[0]).hypot(to[1] - from[1]),
            Load::Temperature { .. } | Load::FaceStress { .. } => 0.0,
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
            Load::Line {
                from,
                to,
                force_per_length,
            } => {
                let m = |p: [f64; 2]| {
                    if about_x {
                        [-p[0], p[1]]
                    } else {
                        [p[0], -p[1]]
                    }
                };
                Load::Line {
                    from: m(from),
                    to: m(to),
                    force_per_length,
                }
            }
            Load::Temperature { curvature } => Load::Temperature { curvature },
            Load::FaceStress { top, bottom } => Load::FaceStress { top, bottom },
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
            (
                Load::Line {
                    from,
                    to,
                    force_per_length: q,
                },
                Load::Line {
                    from: f2,
                    to: t2,
                    force_per_length: q2,
                },
            ) => {
                let near = |a: [f64; 2], b: [f64; 2]| {
                    (a[0] - b[0]).abs() < tol && (a[1] - b[1]).abs() < tol
                };
                // A segment is the same load whichever end is written first.
                ((near(from, f2) && near(to, t2)) || (near(from, t2) && near(to, f2)))
                    && (q - q2).abs() <= tol * q.abs().max(q2.abs())
            }
            (Load::Temperature { curvature: a }, Load::Temperature { curvature: b }) => {
                (a - b).abs() <= tol * a.abs().max(b.abs())
            }
            (Load::FaceStress { top: a, bottom: b }, Load::FaceStress { top: c, bottom: d }) => {
                (a - c).abs() <= tol * a.abs().max(c.abs())
                    && (b - d).abs() <= tol * b.abs().max(d.abs())
            }
            _ => false,
        }
    }
}

/// True when the load set is unchanged by mirroring about x = 0 (`about_x`) or y = 0.
pub fn loads_symmetric(loads: &[Load], about_x: bool) -> bool {
    loads_mirror(loads, loads, [about_x, !about_x])
}

/// True when `b` is the load set `a` mirrored about x = 0 where `flip[0]` (x → −x) and about
/// y = 0 where `flip[1]` (y → −y), both a turn by 180° about the origin: every load of `a` so
/// mirrored is a distinct load of `b` (to 1e-9), and there are as many.
pub fn loads_mirror(a: &[Load], b: &[Load], flip: [bool; 2]) -> bool {
    let tol = 1e-9;
    if a.len() != b.len() {
        return false;
    }
    let mut used = vec![false; b.len()];
    for l in a {
        let mut m = *l;
        if flip[0] {
            m = m.mirrored(true);
        }
        if flip[1] {
            m = m.mirrored(false);
        }
        match b
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

/// A validated model in the solver's unit system (see the module docs).
#[derive(Debug, Clone)]
pub struct Model {
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
    /// Where σ ≥ 0 is imposed.
    pub constraint: ConstraintPoints,
    /// Voids under the plate (initial gaps).
    pub voids: Vec<Void>,
    /// Winkler zones with another modulus.
    pub zones: Vec<Zone>,
    /// Pressure the soil may take, in units of P / L² (the bearing check), if given.
    pub allowable_pressure: Option<f64>,
    /// The side of the square over which the bearing check averages the contact pressure, in
    /// units of L (the scene's `bearing_length`, by default the plate's thickness).
    pub bearing_length: f64,
    /// P in the scene's own force unit (N for SI scenes; the loads' relative unit for
    /// dimensionless ones): what makes models of different load sets comparable.
    pub load_scale: f64,
    /// What P is: a quarter of the net load, or, when the loads add up to zero (only a bonded
    /// plate can carry such loads), the reference that stands in for it.
    pub reference: LoadReference,
    /// Joint lines and panels with their own section ([`crate::layout`]); empty for a plate of
    /// one piece.
    pub layout: Layout,
    /// The axles and gears among the loads, each a group of `loads` that [`Model::place`]
    /// moves.
    pub vehicles: Vec<Vehicle>,
}

/// The force P that V = D w / (P L²) and σ = μ L² r / P are reported against.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum LoadReference {
    /// 4P is the net vertical load (the paper's P; every scene with a net load).
    NetLoad,
    /// The loads add up to zero: 4P is the sum of the downward loads (as much again acts
    /// upward).
    DownwardLoad,
    /// The loads add up to zero and only temperature acts: P = D κ, the moment per unit
    /// length that holds the free curl κ = α ΔT / H flat (so V = w / (κ L²), σ = μ L² r / (D κ)).
    ThermalMoment,
}

impl LoadReference {
    /// The name used in the summary and tables.
    pub fn name(self) -> &'static str {
        match self {
            LoadReference::NetLoad => "net-load",
            LoadReference::DownwardLoad => "downward-load",
            LoadReference::ThermalMoment => "thermal-moment",
        }
    }

    /// What P is, in words, for tables and notes.
    pub fn describe(self) -> &'static str {
        match self {
            LoadReference::NetLoad => "4P = the net load",
            LoadReference::DownwardLoad => {
                "the loads add up to zero: 4P = the sum of the downward loads"
            }
            LoadReference::ThermalMoment => {
                "the loads add up to zero: P = D κ, the moment that holds the free curl κ flat (V = w / (κ L²))"
            }
        }
    }
}

impl Model {
    /// Sum of the loads in units of P: +4 for a net downward load, −4 for a net upward one, 0
    /// when they add up to zero (see [`LoadReference`]).
    pub fn resultant(&self) -> f64 {
        self.loads.iter().map(Load::resultant).sum()
    }

    /// The plate's initial curvature from its temperature loads, κ D / P (0 without them).
    pub fn thermal_curvature(&self) -> f64 {
        self.loads
            .iter()
            .map(|l| match l {
                Load::Temperature { curvature } => *curvature,
                _ => 0.0,
            })
            .sum()
    }

    /// The nonlinear temperature stress [top, bottom] of the face-stress loads, σ L² / P.
    pub fn face_stress(&self) -> [f64; 2] {
        self.loads.iter().fold([0.0, 0.0], |acc, l| match l {
            Load::FaceStress { top, bottom } => [acc[0] + top, acc[1] + bottom],
            _ => acc,
        })
    }

    /// The plate's thickness over L, from Δ = H²/(6χ(1 − ν)μL²) with χ = 5/6.
    pub fn thickness_ratio(&self) -> f64 {
        let g = &self.groups;
        (5.0 * (1.0 - g.nu) * g.mu * g.delta).sqrt()
    }

    /// True when loads, voids, zones, the layout (joints and panels) and the plate's shape (its
    /// cells) are all unchanged by the mirror about x = 0 (`about_x`) or y = 0.
    pub fn symmetric(&self, about_x: bool) -> bool {
        loads_symmetric(&self.loads, about_x) && self.frame_symmetric(about_x)
    }

    /// [`Model::symmetric`] but for the loads: voids, zones, the layout and the plate's shape
    /// unchanged by the mirror about x = 0 (`about_x`) or y = 0. Two models that differ only
    /// in their loads, on such a frame, are each other's mirror image when their loads are
    /// ([`loads_mirror`]).
    pub fn frame_symmetric(&self, about_x: bool) -> bool {
        let voids: Vec<_> = self.voids.iter().map(|v| (v.x, v.y, v.depth)).collect();
        let zones: Vec<_> = self
            .zones
            .iter()
            .map(|z| (z.x, z.y, z.compliance_ratio))
            .collect();
        let shape = || {
            crate::mesh::outline::CellMask::of_layout(&self.layout, self.elements, self.groups.mu)
                .symmetric(about_x)
        };
        rects_symmetric(&voids, about_x)
            && rects_symmetric(&zones, about_x)
            && self.layout.symmetric(about_x)
            && (!self.layout.is_shaped() || shape())
    }

    /// True when every print of the vehicle `vehicle` at `at` (as [`Model::place`]) lies on the
    /// plate's cells: always on a plate that is its whole rectangle; on a shaped plate, no print
    /// on an opening or outside the outline.
    pub fn prints_on_plate(&self, vehicle: usize, at: [f64; 3]) -> Result<bool> {
        if !self.layout.is_shaped() {
            return Ok(true);
        }
        let missing = || Error::invalid("load", format!("the model has no vehicle {vehicle}"));
        let v = self.vehicles.get(vehicle).ok_or_else(missing)?;
        let (layout, mu) = (&self.layout, self.groups.mu);
        Ok(v.prints(at)?.iter().all(|p| {
            crate::mesh::outline::CellMask::layout_covers(layout, self.elements, mu, p.x, p.y)
        }))
    }

    /// Move the vehicle `vehicle` (an index into [`Model::vehicles`]) to `at` = (x, y, heading),
    /// m and degrees: its prints replace its loads, factored and in units of P as the scene made
    /// them (P stays: moving a load changes no resultant). A print off the plate — off its
    /// bounding rectangle, on an opening or outside its outline — is refused.
    pub fn place(&mut self, vehicle: usize, at: [f64; 3]) -> Result<()> {
        let missing = || Error::invalid("load", format!("the model has no vehicle {vehicle}"));
        let v = self.vehicles.get(vehicle).ok_or_else(missing)?;
        if !self.prints_on_plate(vehicle, at)? {
            return Err(Error::invalid(
                format!("load[{}]", v.entry),
                format!(
                    "at ({}, {}) and {}°, a print falls on an opening or outside the plate's outline: a load that falls through the slab is not carried — place it on the plate",
                    at[0], at[1], at[2]
                ),
            ));
        }
        let prints = v.prints(at)?;
        let (factor, p) = (v.factor, self.load_scale);
        let slots = (self.loads.get_mut(v.loads.clone()))
            .filter(|s| s.len() == prints.len())
            .ok_or_else(missing)?;
        for (slot, print) in slots.iter_mut().zip(prints) {
            let pressure = print.pressure * factor / p;
            if !pressure.is_finite() {
                return Err(Error::invalid(
                    format!("load[{}].tire_pressure", v.entry),
                    "the print's pressure overflows in units of the total load",
                ));
            }
            *slot = Load::Patch {
                x: print.x,
                y: print.y,
                pressure,
            };
        }
        self.vehicles[vehicle].at = at;
        Ok(())
    }

    /// The grid to solve on: a half or a quarter where the loads allow it and the element counts
    /// are even. Returns the mesh and notes on what was decided.
    pub fn plan_mesh(&self) -> (Mesh, Vec<String>) {
        plan_shared_mesh(std::slice::from_ref(self))
    }
}

/// The one grid for several models of the same plate (the combinations of a scene): halved or
/// quartered only where every model's loads, voids, zones and layout allow it (not about a line
/// that a joint cuts the plate along), with the layout's node copies
/// ([`Mesh::with_layout`]; the combinations of a scene share one layout).
pub fn plan_shared_mesh(models: &[Model]) -> (Mesh, Vec<String>) {
    let mut notes = Vec::new();
    let Some(first) = models.first() else {
        return (Mesh::new(2.0, 2.0, [1, 1], false, false), notes);
    };
    let [nx, ny] = first.elements;
    let (mut sx, mut sy) = (false, false);
    if first.symmetry == SymmetryMode::Auto {
        sx = models.iter().all(|m| m.symmetric(true));
        sy = models.iter().all(|m| m.symmetric(false));
        if sx && nx % 2 == 1 {
            notes.push(format!(
                "loads are symmetric about x = 0 but mesh.elements[0] = {nx} is odd: modelling the whole width (use an even count to halve the model)"
            ));
            sx = false;
        }
        if sy && ny % 2 == 1 {
            notes.push(format!(
                "loads are symmetric about y = 0 but mesh.elements[1] = {ny} is odd: modelling the whole depth (use an even count to halve the model)"
            ));
            sy = false;
        }
        for (about_x, reduce, line, what) in [
            (true, &mut sx, "x = 0", "width"),
            (false, &mut sy, "y = 0", "depth"),
        ] {
            if let Some(j) = (*reduce)
                .then(|| first.layout.cut_on_symmetry_line(about_x))
                .flatten()
            {
                notes.push(format!(
                    "joint {} lies on the symmetry line {line}: modelling the whole {what}",
                    j.name
                ));
                *reduce = false;
            }
        }
    }
    let mesh = Mesh::new(2.0, 2.0 * first.groups.mu, first.elements, sx, sy);
    (mesh.with_layout(&first.layout), notes)
}
