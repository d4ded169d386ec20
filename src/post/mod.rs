//! Post-processing: whole-plate fields (mirrored from a reduced model), stress resultants,
//! profiles along the paper's lines, contact measures, resultants and residuals.
//!
//! The contact boundary is located inside the elements ([`boundary`]): contact area, radius,
//! extents and the pressure of the profiles end where the would-be gap changes sign, not at
//! the first lifted node.
//!
//! Physical quantities are in SI units for a scene given in SI units, and in units of
//! L = P = D = 1 for a dimensionless scene. Dimensionless ones follow the paper (eq. 4.1):
//! V = D w / (P L²), σ = μ L² r / P.

pub mod average;
pub mod boundary;
pub mod corner;
pub mod exceed;
pub mod field;
pub mod joints;
pub mod stress;
mod whole;

use serde::Serialize;

pub use boundary::BoundarySegment;
pub use field::{ElementField, FullField, JointLine};
pub use joints::{DowelForce, JointNode, JointReport, Side};

use crate::foundation::nodal_areas;
use crate::model::{Model, Physical};
use crate::operators::Operators;
use crate::solve::Solution;
use stress::{FaceStress, StressSummary};

/// A node is in contact where its pressure exceeds this fraction of the peak pressure: contact
/// is where the soil carries load. QP solutions leave ~1e-11 of the peak on lifted nodes and
/// penalty solutions leave small tensions there, so the threshold separates both cleanly. It
/// decides [`FullField::contact`] node by node; areas and extents use the boundary located
/// inside the elements ([`boundary`]).
pub const CONTACT_THRESHOLD: f64 = 1e-6;

/// One point of a profile.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct ProfilePoint {
    /// Position along the line: s, t, or the signed fraction of the half-diagonal.
    pub coord: f64,
    /// s.
    pub s: f64,
    /// t.
    pub t: f64,
    /// V.
    pub v: f64,
    /// σ.
    pub sigma: f64,
}

/// Values along one of the paper's lines.
#[derive(Debug, Clone, Serialize)]
pub struct Profile {
    /// x-axis (t = 0), y-axis (s = 0), edge-x (t = 1), edge-y (s = 1) or diagonal.
    pub line: &'static str,
    /// Points in order of `coord`.
    pub points: Vec<ProfilePoint>,
}

/// Contact extents from the centre along +s, +t and the diagonal.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Extent {
    /// Along +s, fraction of L.
    pub x: f64,
    /// Along +t, fraction of μL.
    pub y: f64,
    /// Along the diagonal to (+L, +μL), fraction of the half-diagonal.
    pub diagonal: f64,
}

/// Extreme bending moments per unit length at element centres (physical units; positive =
/// tension on the soil side).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Moments {
    /// [min, max] of mx.
    pub mx: [f64; 2],
    /// [min, max] of my.
    pub my: [f64; 2],
}

fn range(v: &[f64]) -> [f64; 2] {
    v.iter()
        .fold([f64::INFINITY, f64::NEG_INFINITY], |[lo, hi], &x| {
            [lo.min(x), hi.max(x)]
        })
}

/// Load resultant and reaction.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Resultant {
    /// Load resultant (physical force).
    pub load: f64,
    /// ∫ r dA over the plate (physical force).
    pub reaction: f64,
    /// |reaction − load| / 4P (4P = |load| unless the loads add up to zero).
    pub relative_error: f64,
}

/// Discrete unilateral conditions, dimensionless.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Complementarity {
    /// Minimum σ at the constraint points (≥ 0 up to round-off when unbonded).
    pub min_pressure: f64,
    /// Minimum nodal gap in units of V (≥ 0 when unbonded; 0 when bonded).
    pub min_gap: f64,
    /// Max |σ_i g_i| over nodes, σ·V units.
    pub max_product: f64,
}

/// Everything the outputs need.
#[derive(Debug, Clone)]
pub struct Report {
    /// Nodal fields.
    pub field: FullField,
    /// Element resultants.
    pub elements: ElementField,
    /// Profiles.
    pub profiles: Vec<Profile>,
    /// The plate's area over its bounding rectangle's (1 unless it is shaped).
    pub plate_fraction: f64,
    /// Largest deflection (physical).
    pub w_max: f64,
    /// Largest V.
    pub v_max: f64,
    /// V at the centre.
    pub v_center: f64,
    /// V at the corner (+L, +μL).
    pub v_corner: f64,
    /// Contact area / plate area: the area inside the located boundary.
    pub contact_fraction: f64,
    /// √(contact area / π) / L.
    pub contact_radius: f64,
    /// Contact extents to the located boundary.
    pub contact_extent: Extent,
    /// The contact boundary over the whole plate, segment by segment.
    pub boundary: Vec<BoundarySegment>,
    /// Largest contact pressure (physical).
    pub pressure_max: f64,
    /// Extreme bending moments per unit length (physical): [min, max] of mx and of my.
    pub moments: Moments,
    /// Equilibrium.
    pub resultant: Resultant,
    /// Unilateral residuals.
    pub complementarity: Complementarity,
    /// The bearing check, when the scene gives an allowable pressure.
    pub bearing: Option<Bearing>,
    /// The largest tension at the bottom and top faces, and where.
    pub stress: StressSummary,
    /// What each cutting joint carries (empty without joints).
    pub joints: Vec<JointReport>,
    /// Notes on reading the results (on a continuum soil: the nodal edge pressure is
    /// mesh-dependent, [`average::edge_note`]).
    pub notes: Vec<String>,
}

/// The soil pressure against what the soil may take: the largest pressure averaged over a
/// square of side `length` ([`average::largest_square_average`]), and the nodal peak beside it.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Bearing {
    /// Allowable pressure (physical: Pa; dimensionless scenes: units of P / L²).
    pub allowable: f64,
    /// Side of the averaging square: m, or L units (the scene's `bearing_length`).
    pub length: f64,
    /// The largest average of the pressure over a square of side `length` on the plate, same
    /// unit as `allowable`.
    pub average: f64,
    /// [x, y] of that square's centre: m, or L units.
    pub average_at: [f64; 2],
    /// average / allowable: the check.
    pub utilisation: f64,
    /// The nodal peak pressure, same unit (on a continuum soil, at the plate's edge, it grows
    /// with the mesh: not a design number).
    pub max: f64,
    /// max / allowable.
    pub nodal_utilisation: f64,
    /// Area where the (bilinear) pressure exceeds the allowable one: m², or L² units.
    pub area_exceeding: f64,
    /// That area over the plate's.
    pub fraction_exceeding: f64,
}

/// Sides of the plate in the units of `field.x`, `field.y`.
fn plate_sides(field: &FullField) -> (f64, f64) {
    let span = |v: &[f64]| {
        let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        (hi - lo).max(0.0)
    };
    (span(&field.x), span(&field.y))
}

fn scales(model: &Model) -> Physical {
    model.physical.unwrap_or(Physical {
        half_length: 1.0,
        force: 1.0,
        rigidity: 1.0,
        units: crate::units::UnitSystem::Si,
    })
}

/// Build the report of a solution.
pub fn report(model: &Model, ops: &Operators, sol: &Solution) -> Report {
    let mesh = &ops.mesh;
    let mu = model.groups.mu;
    let ph = scales(model);
    let areas = nodal_areas(mesh);
    let phi = boundary::would_be_gap(ops, sol);
    let peak = sol.sigma.iter().cloned().fold(0.0_f64, f64::max);
    let threshold = CONTACT_THRESHOLD * peak;

    // Every node copy of the whole plate, and the elements, each from its own corners.
    let whole = whole::cached_whole_plate(ops, mu);
    let gap_per_sigma = boundary::self_compliance(ops) * ph.deflection() / mu;
    let (field, elements, full_u, to_field) = whole::fields(
        model,
        ops,
        sol,
        &whole,
        &phi,
        (threshold, gap_per_sigma),
        &ph,
    );
    let joints = joints::reports(
        &whole.mesh,
        &field,
        &elements,
        &full_u,
        &to_field,
        &ph,
        model.physical.is_some(),
    );
    let thickness = model.thickness_ratio();
    let peak_or_zero = |face: &FaceStress| {
        stress::peak(face, &elements.x, &elements.y).unwrap_or(stress::PeakTension {
            value: 0.0,
            angle: 0.0,
            x: 0.0,
            y: 0.0,
        })
    };
    let stress = StressSummary {
        bottom: peak_or_zero(&elements.bottom),
        top: peak_or_zero(&elements.top),
        thickness: thickness * ph.half_length,
    };

    let profiles = profiles(&field);
    let v_max = field.v.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    let w_max = field.w.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    // NaN where a shaped plate has no plate (an opening at the centre, the corner cut away).
    let off = |s: f64, t: f64, v: f64| if field.on_plate_at(s, t) { v } else { f64::NAN };
    let v_center = off(0.0, 0.0, field.interpolate(&field.v, 0.0, 0.0));
    // The corner (+L, +μL) is the last grid node (one element: never doubled).
    let v_corner = off(1.0, 1.0, field.v[field.n_grid() - 1]);

    // Contact measures from the boundary located inside the elements; on a shaped plate the
    // fraction is of its own area, `plate_fraction` of the box's.
    let contact_fraction = field.contact_fraction();
    let plate_fraction = field.plate_fraction();
    let contact_radius =
        (contact_fraction * plate_fraction * 4.0 * mu / std::f64::consts::PI).sqrt();
    let contact_extent = Extent {
        x: field.contact_extent_along(1.0, 0.0),
        y: field.contact_extent_along(0.0, 1.0),
        diagonal: field.contact_extent_along(1.0, 1.0),
    };
    let boundary = field.contact_boundary();

    // Equilibrium: reaction of the model times the number of copies.
    let copies = mesh.copies() as f64;
    let reaction_unit: f64 = copies
        * sol
            .sigma
            .iter()
            .zip(&areas)
            .map(|(s, a)| s * a)
            .sum::<f64>();
    let load_unit = copies * ops.total_load();
    let resultant = Resultant {
        load: load_unit * ph.force,
        reaction: reaction_unit * ph.force,
        // Against 4P: the net load, or the stated reference when the loads add up to zero.
        relative_error: (reaction_unit - load_unit).abs() / load_unit.abs().max(4.0),
    };

    let gs = ops.g_times(&sol.sigma);
    let min_pressure = mu * gs.iter().cloned().fold(f64::INFINITY, f64::min);
    let gaps: Vec<f64> = sol.gap.iter().zip(&areas).map(|(g, a)| g / a).collect();
    let min_gap = gaps.iter().cloned().fold(f64::INFINITY, f64::min);
    let max_product = sol
        .sigma
        .iter()
        .zip(&gaps)
        .map(|(s, g)| (mu * s * g).abs())
        .fold(0.0, f64::max);

    let pressure_max = field
        .pressure
        .iter()
        .cloned()
        .fold(f64::NEG_INFINITY, f64::max);
    let moments = Moments {
        mx: range(&elements.mx),
        my: range(&elements.my),
    };
    let bearing = model.allowable_pressure.map(|a| {
        let allowable = a * ph.pressure();
        // The field's arrays all have one entry per node copy: area_above cannot fail here.
        let area = exceed::area_above(&field, &field.pressure, allowable).unwrap_or(f64::NAN);
        let (lx, ly) = plate_sides(&field);
        let length = model.bearing_length * ph.half_length;
        // The side is at most the plate's smaller side (checked with the scene): None only on
        // a field of NaN.
        let (average, average_at) =
            average::largest_square_average(&field, &field.pressure, length)
                .unwrap_or((f64::NAN, [f64::NAN; 2]));
        Bearing {
            allowable,
            length,
            average,
            average_at,
            utilisation: average / allowable,
            max: pressure_max,
            nodal_utilisation: pressure_max / allowable,
            area_exceeding: area,
            fraction_exceeding: area / (lx * ly * plate_fraction),
        }
    });
    // The notes' lengths in the scene's unit: m, in, or the paper's L.
    let system = model.physical.map(|p| p.units);
    let (unit, per_metre) = (
        crate::units::Measure::Length.unit(system),
        crate::units::Measure::Length.from_si(system, 1.0),
    );
    let length = match model.physical {
        Some(p) => format!(
            "{:.3} {unit}",
            model.bearing_length * p.half_length * per_metre
        ),
        None => format!("{:.4} L", model.bearing_length),
    };
    let mut notes: Vec<String> = average::edge_note(model.groups.foundation(), &length)
        .into_iter()
        .collect();
    notes.extend(corner::notes(
        &field,
        model.groups.nu,
        [("bottom", &stress.bottom), ("top", &stress.top)],
        (unit, per_metre),
    ));
    // The dual-tire print's rectangle stands only along the grid: at other headings each tire
    // is a square of its contact area (README, "Pavement loads").
    for v in model.vehicles.iter().filter(|v| !v.square) {
        let heading = v.at[2];
        if ((heading / 90.0) - (heading / 90.0).round()).abs() >= 1e-9 {
            let what = v
                .name
                .as_deref()
                .unwrap_or(if v.axle { "axle" } else { "gear" });
            notes.push(format!(
                "{what}: a heading of {heading}° is not a multiple of 90°, so its tire prints are squares of the same contact area (the PCA rectangle stands only along the grid)"
            ));
        }
    }
    Report {
        plate_fraction,
        notes,
        joints,
        stress,
        bearing,
        pressure_max,
        moments,
        field,
        elements,
        profiles,
        w_max,
        v_max,
        v_center,
        v_corner,
        contact_fraction,
        contact_radius,
        contact_extent,
        boundary,
        resultant,
        complementarity: Complementarity {
            min_pressure,
            min_gap,
            max_product,
        },
    }
}

/// V and σ along the paper's lines (read from the grid nodes: on a joint line, the lower / left
/// copy, see [`FullField::interpolate`]): 2 max(nx, ny) + 1 evenly spaced points (the nodes and
/// the element mid-points of a square grid) plus the points where each line crosses the contact
/// boundary. σ is the pressure ending at the located boundary ([`FullField::pressure_at`]), so
/// it falls to zero there rather than at the first lifted node.
pub fn profiles(field: &FullField) -> Vec<Profile> {
    let n = 2 * field.nx.max(field.ny) + 1;
    let line = |name: &'static str, a: (f64, f64), b: (f64, f64)| {
        let mut coords: Vec<f64> = (0..n)
            .map(|k| -1.0 + 2.0 * k as f64 / (n - 1) as f64)
            .collect();
        coords.extend(
            field
                .boundary_crossings(a, b)
                .into_iter()
                .map(|u| -1.0 + 2.0 * u),
        );
        coords.sort_by(f64::total_cmp);
        coords.dedup_by(|x, y| (*x - *y).abs() < 1e-12);
        Profile {
            line: name,
            // A shaped plate's profile skips the points off it (an opening, a cut-away part).
            points: coords
                .into_iter()
                .filter(|&c| {
                    let u = 0.5 * (c + 1.0);
                    field.on_plate_at(a.0 + u * (b.0 - a.0), a.1 + u * (b.1 - a.1))
                })
                .map(|c| {
                    let u = 0.5 * (c + 1.0);
                    let (s, t) = (a.0 + u * (b.0 - a.0), a.1 + u * (b.1 - a.1));
                    ProfilePoint {
                        coord: c,
                        s,
                        t,
                        v: field.interpolate(&field.v, s, t),
                        sigma: field.pressure_at(s, t),
                    }
                })
                .collect(),
        }
    };
    vec![
        line("x-axis", (-1.0, 0.0), (1.0, 0.0)),
        line("y-axis", (0.0, -1.0), (0.0, 1.0)),
        line("edge-x", (-1.0, 1.0), (1.0, 1.0)),
        line("edge-y", (1.0, -1.0), (1.0, 1.0)),
        line("diagonal", (-1.0, -1.0), (1.0, 1.0)),
    ]
}

/// Small synthetic fields shared by the output writers' tests.
#[cfg(test)]
pub(crate) mod test_fixtures;
