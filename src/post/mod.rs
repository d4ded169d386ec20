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

pub mod boundary;
pub mod exceed;
pub mod stress;

use serde::Serialize;

pub use boundary::BoundarySegment;

use crate::foundation::nodal_areas;
use crate::mesh::{Dof, Mesh};
use crate::model::{Model, Physical};
use crate::operators::Operators;
use crate::plate::{centre_resultants, ElementVector};
use crate::solve::Solution;
use stress::{FaceStress, StressSummary};

/// A node is in contact where its pressure exceeds this fraction of the peak pressure: contact
/// is where the soil carries load. QP solutions leave ~1e-11 of the peak on lifted nodes and
/// penalty solutions leave small tensions there, so the threshold separates both cleanly. It
/// decides [`FullField::contact`] node by node; areas and extents use the boundary located
/// inside the elements ([`boundary`]).
pub const CONTACT_THRESHOLD: f64 = 1e-6;

/// Nodal fields over the whole plate on the (nx + 1) × (ny + 1) grid, node index i + j (nx + 1).
#[derive(Debug, Clone)]
pub struct FullField {
    /// Elements along x over the whole plate.
    pub nx: usize,
    /// Elements along y over the whole plate.
    pub ny: usize,
    /// x, physical.
    pub x: Vec<f64>,
    /// y, physical.
    pub y: Vec<f64>,
    /// s = x / L.
    pub s: Vec<f64>,
    /// t = y / (μL).
    pub t: Vec<f64>,
    /// Deflection w, physical, downward.
    pub w: Vec<f64>,
    /// ψx, physical (rad).
    pub psi_x: Vec<f64>,
    /// ψy, physical (rad).
    pub psi_y: Vec<f64>,
    /// Contact pressure r, physical, compression positive.
    pub pressure: Vec<f64>,
    /// Gap (foundation settlement − w), physical length; ≥ 0 where the plate lifted.
    pub gap: Vec<f64>,
    /// Would-be gap φ = gap − c r, the gap with the node's own pressure released ([`boundary`]),
    /// physical length: negative in contact, the gap where lifted; −w on Winkler. Its bilinear
    /// zero level set is the contact boundary.
    pub signed_gap: Vec<f64>,
    /// c of the would-be gap, as physical length per unit of the paper's σ: −φ / c is a
    /// pressure (σ in contact).
    pub gap_per_sigma: f64,
    /// V = D w / (P L²).
    pub v: Vec<f64>,
    /// σ = μ L² r / P.
    pub sigma: Vec<f64>,
    /// Pressure above [`CONTACT_THRESHOLD`] of the peak.
    pub contact: Vec<bool>,
    /// Largest principal stress at the bottom face, recovered at the nodes (the mean of the
    /// stress components of the elements around a node, then its principal value).
    pub s1_bottom: Vec<f64>,
    /// Largest principal stress at the top face, recovered at the nodes.
    pub s1_top: Vec<f64>,
}

impl FullField {
    /// Nodes along x.
    pub fn nodes_x(&self) -> usize {
        self.nx + 1
    }

    /// The numeric per-node columns of nodes.csv in its order, by name (node i + j (nx + 1));
    /// `contact` is the one boolean column beside them.
    pub fn columns(&self) -> [(&'static str, &[f64]); 13] {
        [
            ("x", &self.x),
            ("y", &self.y),
            ("s", &self.s),
            ("t", &self.t),
            ("w", &self.w),
            ("psi_x", &self.psi_x),
            ("psi_y", &self.psi_y),
            ("pressure", &self.pressure),
            ("gap", &self.gap),
            ("V", &self.v),
            ("sigma", &self.sigma),
            ("s1_bottom", &self.s1_bottom),
            ("s1_top", &self.s1_top),
        ]
    }

    /// Bilinear interpolation of a nodal field at (s, t) ∈ [−1, 1]².
    pub fn interpolate(&self, field: &[f64], s: f64, t: f64) -> f64 {
        let fx = ((s + 1.0) * 0.5 * self.nx as f64).clamp(0.0, self.nx as f64);
        let fy = ((t + 1.0) * 0.5 * self.ny as f64).clamp(0.0, self.ny as f64);
        let i = (fx.floor() as usize).min(self.nx - 1);
        let j = (fy.floor() as usize).min(self.ny - 1);
        let (a, b) = (fx - i as f64, fy - j as f64);
        let n = self.nodes_x();
        let v00 = field[i + j * n];
        let v10 = field[i + 1 + j * n];
        let v01 = field[i + (j + 1) * n];
        let v11 = field[i + 1 + (j + 1) * n];
        (1.0 - a) * (1.0 - b) * v00 + a * (1.0 - b) * v10 + (1.0 - a) * b * v01 + a * b * v11
    }
}

/// Stress resultants per unit length at element centres over the whole plate, physical units,
/// element index ie + je nx. Moments are positive when the soil-side face is in tension.
#[derive(Debug, Clone, Default)]
pub struct ElementField {
    /// Centre x.
    pub x: Vec<f64>,
    /// Centre y.
    pub y: Vec<f64>,
    /// Bending moment about the y axis, per unit length.
    pub mx: Vec<f64>,
    /// Bending moment about the x axis, per unit length.
    pub my: Vec<f64>,
    /// Twisting moment, per unit length.
    pub mxy: Vec<f64>,
    /// Transverse shear force on x faces, per unit length.
    pub qx: Vec<f64>,
    /// Transverse shear force on y faces, per unit length.
    pub qy: Vec<f64>,
    /// Stresses at the bottom (soil-side) face.
    pub bottom: FaceStress,
    /// Stresses at the top face.
    pub top: FaceStress,
}

impl ElementField {
    /// The per-element columns of elements.csv in its order, by name (element ie + je nx).
    pub fn columns(&self) -> Vec<(&'static str, &[f64])> {
        let (b, t) = (&self.bottom, &self.top);
        vec![
            ("x", &self.x),
            ("y", &self.y),
            ("mx", &self.mx),
            ("my", &self.my),
            ("mxy", &self.mxy),
            ("qx", &self.qx),
            ("qy", &self.qy),
            ("sx_bottom", &b.sx),
            ("sy_bottom", &b.sy),
            ("sxy_bottom", &b.sxy),
            ("s1_bottom", &b.s1),
            ("s2_bottom", &b.s2),
            ("angle_bottom", &b.angle),
            ("sx_top", &t.sx),
            ("sy_top", &t.sy),
            ("sxy_top", &t.sxy),
            ("s1_top", &t.s1),
            ("s2_top", &t.s2),
            ("angle_top", &t.angle),
        ]
    }
}

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
}

/// The soil pressure against what the soil may take.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Bearing {
    /// Allowable pressure (physical: Pa; dimensionless scenes: units of P / L²).
    pub allowable: f64,
    /// Largest pressure, same unit.
    pub max: f64,
    /// max / allowable.
    pub utilisation: f64,
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
    })
}

/// Build the report of a solution.
pub fn report(model: &Model, ops: &Operators, sol: &Solution) -> Report {
    let mesh = &ops.mesh;
    let mu = model.groups.mu;
    let ph = scales(model);
    let [nx, ny] = mesh.full_elements();
    let nnx = nx + 1;
    let n_full = nnx * (ny + 1);
    let areas = nodal_areas(mesh);
    let phi = boundary::would_be_gap(ops, sol);
    let peak = sol.sigma.iter().cloned().fold(0.0_f64, f64::max);
    let threshold = CONTACT_THRESHOLD * peak;

    // Model node and rotation signs of every whole-plate node.
    let mut field = FullField {
        nx,
        ny,
        x: Vec::with_capacity(n_full),
        y: Vec::with_capacity(n_full),
        s: Vec::with_capacity(n_full),
        t: Vec::with_capacity(n_full),
        w: Vec::with_capacity(n_full),
        psi_x: Vec::with_capacity(n_full),
        psi_y: Vec::with_capacity(n_full),
        pressure: Vec::with_capacity(n_full),
        gap: Vec::with_capacity(n_full),
        signed_gap: Vec::with_capacity(n_full),
        gap_per_sigma: boundary::self_compliance(ops) * ph.deflection() / mu,
        v: Vec::with_capacity(n_full),
        sigma: Vec::with_capacity(n_full),
        contact: Vec::with_capacity(n_full),
        s1_bottom: Vec::new(),
        s1_top: Vec::new(),
    };
    // Unit-system nodal dofs over the whole plate (for element resultants).
    let mut full_u = vec![[0.0; 3]; n_full];
    for jj in 0..=ny {
        for ii in 0..=nx {
            let (i, sx) = model_index(ii, mesh.nx, mesh.sym_x);
            let (j, sy) = model_index(jj, mesh.ny, mesh.sym_y);
            let n = mesh.node(i, j);
            let get = |d: Dof| ops.dofs.eq(n, d).map_or(0.0, |e| sol.u[e]);
            let w = get(Dof::W);
            let px = sx * get(Dof::PsiX);
            let py = sy * get(Dof::PsiY);
            full_u[ii + jj * nnx] = [w, px, py];
            let xu = -1.0 + ii as f64 * 2.0 / nx as f64;
            let yu = mu * (-1.0 + jj as f64 * 2.0 / ny as f64);
            let r = sol.sigma[n];
            let g = sol.gap[n] / areas[n];
            field.x.push(xu * ph.half_length);
            field.y.push(yu * ph.half_length);
            field.s.push(xu);
            field.t.push(yu / mu);
            field.w.push(w * ph.deflection());
            field.psi_x.push(px * ph.rotation());
            field.psi_y.push(py * ph.rotation());
            field.pressure.push(r * ph.pressure());
            field.gap.push(g * ph.deflection());
            field.signed_gap.push(phi[n] * ph.deflection());
            field.v.push(w);
            field.sigma.push(mu * r);
            field.contact.push(r > threshold);
        }
    }

    // Element resultants on the whole plate; D_b κ₀ of the temperature loads (D = 1).
    let thermal_moment = (1.0 + ops.section.poisson) * model.thermal_curvature();
    // Surface stresses: ±6m/H² in the unit system (P/L²), then to the scene's units.
    let thickness = model.thickness_ratio();
    let eigen = model.face_stress();
    let stress_scale = ph.pressure();
    let full_mesh = Mesh::new(2.0, 2.0 * mu, [nx, ny], false, false);
    let mut elements = ElementField::default();
    for e in 0..full_mesh.n_elements() {
        let nodes = full_mesh.element_nodes(e);
        let mut ue = ElementVector::zeros();
        for (a, &n) in nodes.iter().enumerate() {
            for d in 0..3 {
                ue[3 * a + d] = full_u[n][d];
            }
        }
        let mut r = centre_resultants(&ops.section, full_mesh.hx, full_mesh.hy, &ue);
        // m = −D_b (κ − κ₀): the thermal initial curvature carries no moment of its own.
        r[0] += thermal_moment;
        r[1] += thermal_moment;
        let (xc, yc) = full_mesh.element_centre(e);
        elements.x.push(xc * ph.half_length);
        elements.y.push(yc * ph.half_length);
        elements.mx.push(r[0] * ph.moment());
        elements.my.push(r[1] * ph.moment());
        elements.mxy.push(r[2] * ph.moment());
        elements.qx.push(r[3] * ph.shear());
        elements.qy.push(r[4] * ph.shear());
        let (b, t) = stress::face_states([r[0], r[1], r[2]], thickness, eigen);
        let s = stress_scale;
        elements.bottom.push(b[0] * s, b[1] * s, b[2] * s);
        elements.top.push(t[0] * s, t[1] * s, t[2] * s);
    }
    field.s1_bottom = stress::recover_principal(&full_mesh, &elements.bottom);
    field.s1_top = stress::recover_principal(&full_mesh, &elements.top);
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
    let v_center = field.interpolate(&field.v, 0.0, 0.0);
    let v_corner = field.v[n_full - 1];

    // Contact measures from the boundary located inside the elements.
    let contact_fraction = field.contact_fraction();
    let contact_radius = (contact_fraction * 4.0 * mu / std::f64::consts::PI).sqrt();
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
        // The field's arrays all have (nx + 1)(ny + 1) entries: area_above cannot fail here.
        let area = exceed::area_above(&field, &field.pressure, allowable).unwrap_or(f64::NAN);
        let (lx, ly) = plate_sides(&field);
        Bearing {
            allowable,
            max: pressure_max,
            utilisation: pressure_max / allowable,
            area_exceeding: area,
            fraction_exceeding: area / (lx * ly),
        }
    });
    Report {
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

/// Model index of a whole-plate grid index and the sign a rotation normal to the symmetry
/// line takes there (−1 on the mirrored side).
fn model_index(full: usize, model_n: usize, sym: bool) -> (usize, f64) {
    if !sym {
        return (full, 1.0);
    }
    if full >= model_n {
        (full - model_n, 1.0)
    } else {
        (model_n - full, -1.0)
    }
}

/// V and σ along the paper's lines: 2 max(nx, ny) + 1 evenly spaced points (the nodes and
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
            points: coords
                .into_iter()
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
