//! The PCA's erosion damage of a damage run ([`super::damage`]) with `model = "pca"`: at the
//! corners of every panel, the corner deflection each pass causes and EB109's erosion relation
//! ([`crate::damage::pca::Pca::erosion_repetitions`]).
//!
//! **Where.** Every corner of every panel of the layout's grid that lies on the plate, once
//! per panel that meets there: a corner on a joint is read on each side of it (just inside
//! each panel, by the element that holds the point, so each side's own deflection), because
//! the loaded and the unloaded side of a joint deflect differently and the leave slab's
//! corner pumps too. The plate's own corners are panel corners.
//!
//! **Which deflection.** The deflection the group causes at the corner: the pass's largest
//! deflection there less the deflection of the same slab, in the same climate bin, without
//! the group (its self-weight and curl alone) — the movement of the corner under the axle,
//! which is what EB109 computes on a flat slab with the load alone. A corner the group lifts
//! (a deflection below the rest state's) takes no erosion. One repetition per pass, as EB109
//! counts an axle group.
//!
//! **Which corners count.** On a plate with transverse joints (across the lane, which runs
//! along x) the plate's own ends x = ±a/2 are where the model cuts a lane that goes on: their
//! corners are free corners no pavement has, and would govern by far (some forty times a
//! doweled joint's). Their erosion is computed and written, but it counts — in the governing
//! corner, the passes' shares and a design — only with `[traffic] ends = "free"` (the lane ends
//! there). A plate without transverse joints (a slab on its own) counts them.
//!
//! **Which k.** The Winkler modulus of the scene's soil (its zones excepted: the relation is
//! calibrated on one k). The relation has no meaning on a continuum soil, whose surface has no
//! k: there the run reports why erosion is absent rather than invent one.

use serde::Serialize;

use crate::foundation::Soil;
use crate::model::Model;
use crate::post::FullField;

/// A corner of a panel where the erosion is summed.
#[derive(Debug, Clone, Serialize)]
pub struct Corner {
    /// The corner's x, m.
    pub x: f64,
    /// The corner's y, m.
    pub y: f64,
    /// The panel it belongs to, "(column, row)" from 1 at x = −a/2, y = −b/2.
    pub panel: String,
    /// The panel's thickness, m.
    pub thickness: f64,
    /// Where the panel lies from the corner: ±1 along x and y.
    #[serde(skip)]
    pub towards: [f64; 2],
    /// Whether its erosion counts (false: a corner of the plate's ends, x = ±a/2, where the
    /// model cuts a lane that goes on; see the module's notes).
    pub counted: bool,
}

/// Where and how a run sums its erosion: the corners, where each is read, and the soil's k.
#[derive(Debug, Clone)]
pub(super) struct Corners {
    pub(super) points: Vec<Corner>,
    /// Each corner's place, m, and whether its panel lies towards +x and +y of it.
    probes: Vec<([f64; 2], [bool; 2])>,
    /// The Winkler modulus, N/m³.
    pub(super) k: f64,
    /// The relation with the scene's coefficients (C1; C2 is applied by the sum).
    pub(super) relation: crate::damage::pca::Pca,
}

impl Corners {
    /// The corners of `model`'s panels, or why the erosion cannot be summed on its soil.
    /// `cut`: the plate's ends cut a lane that goes on (`[traffic] ends`): their corners do
    /// not count on a plate with transverse joints.
    pub(super) fn of(
        model: &Model,
        relation: crate::damage::pca::Pca,
        cut: bool,
    ) -> Result<Corners, String> {
        let Some(phys) = model.physical else {
            return Err("a damage run needs a physical scene".into());
        };
        let g = &model.groups;
        let k = match g.soil {
            Soil::Winkler(_) => {
                // Γ_w = D / (k μ L⁴).
                let l = phys.half_length;
                phys.rigidity / (g.gamma * g.mu * l.powi(4))
            }
            _ => {
                return Err(format!(
                    "the PCA's erosion relation is calibrated on a Winkler k; the {} soil has none, so no erosion is summed",
                    g.foundation().name()
                ))
            }
        };
        let l = phys.half_length;
        let layout = &model.layout;
        let thickness = model.thickness_ratio() * l;
        let edges = |lines: Vec<f64>, half: f64| -> Vec<f64> {
            std::iter::once(-half)
                .chain(lines)
                .chain(std::iter::once(half))
                .collect()
        };
        let transverse = layout.lines(crate::layout::Axis::X);
        let ends = !cut || transverse.is_empty();
        let xs = edges(transverse, 1.0);
        let ys = edges(layout.lines(crate::layout::Axis::Y), g.mu);
        // A corner is the panel's where the point a millionth of its smaller side inside is
        // plate; its deflection is the node copy of the panel's corner element there
        // (`FullField::at_node_of`, towards the panel).
        let mut points = Vec::new();
        let mut probes = Vec::new();
        for (r, yy) in ys.windows(2).enumerate() {
            for (c, xx) in xs.windows(2).enumerate() {
                let nudge = 1e-6 * (xx[1] - xx[0]).min(yy[1] - yy[0]);
                for (x, y, sx, sy) in [
                    (xx[0], yy[0], 1.0, 1.0),
                    (xx[1], yy[0], -1.0, 1.0),
                    (xx[1], yy[1], -1.0, -1.0),
                    (xx[0], yy[1], 1.0, -1.0),
                ] {
                    let (px, py) = (x + sx * nudge, y + sy * nudge);
                    if !layout.is_plate(px, py) {
                        continue;
                    }
                    points.push(Corner {
                        x: x * l,
                        y: y * l,
                        panel: format!("({}, {})", c + 1, r + 1),
                        thickness: thickness * layout.section(c, r).thickness,
                        towards: [sx, sy],
                        counted: ends || (x.abs() - 1.0).abs() > 1e-12,
                    });
                    probes.push(([x * l, y * l], [sx > 0.0, sy > 0.0]));
                }
            }
        }
        Ok(Corners {
            points,
            probes,
            k,
            relation,
        })
    }

    /// The repetitions EB109's erosion relation allows of a deflection `w` (m) caused at
    /// corner `j` on a soil of modulus `k` (N/m³: the scene's [`Self::k`], or a climate bin's
    /// own).
    pub(super) fn allowed(&self, j: usize, w: f64, k: f64) -> f64 {
        let h = self.points.get(j).map_or(f64::NAN, |p| p.thickness);
        self.relation.erosion_repetitions(w, k, h)
    }

    /// The deflection at each corner in a solve's field, m: the node copy of the panel's
    /// corner element at the corner, exactly (NaN where the field cannot be read).
    pub(super) fn read(&self, field: &FullField) -> Vec<f64> {
        self.probes
            .iter()
            .map(|&([x, y], towards)| {
                field
                    .at_node_of(&field.w, x, y, towards)
                    .unwrap_or(f64::NAN)
            })
            .collect()
    }
}

/// The erosion damage at one corner.
#[derive(Debug, Clone, Serialize)]
pub struct CornerDamage {
    /// The corner.
    #[serde(flatten)]
    pub corner: Corner,
    /// Σ C2 n/N over the passes.
    pub damage: f64,
    /// The largest deflection a pass caused there, m.
    pub deflection: f64,
}

/// The PCA's erosion damage of a run.
#[derive(Debug, Clone, Serialize)]
pub struct Erosion {
    /// The scene's Winkler modulus, N/m³ (a climate bin with a modulus of its own reads
    /// that one in its passes).
    pub k: f64,
    /// The relation's C1 (the subbase's factor).
    pub c1: f64,
    /// EB109's C2 applied.
    pub c2: f64,
    /// Every corner's damage.
    pub corners: Vec<CornerDamage>,
    /// The counted corner of the largest damage (index into `corners`; None: no corner
    /// counts).
    pub governing: Option<usize>,
}

impl Erosion {
    /// Each element's share of the map: the damage of its panel's nearest corner — the corner
    /// it lies towards, on its own side of a joint — for the erosion map (NaN where no corner
    /// is towards it, or where that corner does not count). `x`, `y`: the element centres.
    pub fn by_element(&self, x: &[f64], y: &[f64]) -> Vec<f64> {
        x.iter()
            .zip(y)
            .map(|(&ex, &ey)| {
                self.corners
                    .iter()
                    .filter(|c| {
                        let [tx, ty] = c.corner.towards;
                        (ex - c.corner.x) * tx > 0.0 && (ey - c.corner.y) * ty > 0.0
                    })
                    .min_by(|a, b| {
                        let d = |c: &CornerDamage| {
                            (ex - c.corner.x).powi(2) + (ey - c.corner.y).powi(2)
                        };
                        d(a).total_cmp(&d(b))
                    })
                    .filter(|c| c.corner.counted)
                    .map_or(f64::NAN, |c| c.damage)
            })
            .collect()
    }

    /// The largest damage at a corner that does not count (the plate's ends, see the
    /// module's notes) and that corner's index; None when every corner counts.
    pub fn uncounted(&self) -> Option<(usize, f64)> {
        (0..self.corners.len())
            .rev()
            .filter(|&j| !self.corners[j].corner.counted)
            .map(|j| (j, self.corners[j].damage))
            .max_by(|a, b| a.1.total_cmp(&b.1))
    }

    /// The largest erosion damage of a counted corner, 0 without one.
    pub fn damage(&self) -> f64 {
        self.governing
            .and_then(|i| self.corners.get(i))
            .map_or(0.0, |c| c.damage)
    }

    /// The same in the scene's unit system (`reported`'s lengths, k and deflections).
    pub fn reported(&self, sys: Option<crate::units::UnitSystem>) -> Erosion {
        use crate::units::{Measure, Quantity};
        let l = |v: f64| Measure::Length.from_si(sys, v);
        let k = match sys {
            Some(s) => Quantity::SubgradeModulus.from_si(s, self.k),
            None => self.k,
        };
        Erosion {
            k,
            corners: self
                .corners
                .iter()
                .map(|c| CornerDamage {
                    corner: Corner {
                        x: l(c.corner.x),
                        y: l(c.corner.y),
                        thickness: l(c.corner.thickness),
                        panel: c.corner.panel.clone(),
                        towards: c.corner.towards,
                        counted: c.corner.counted,
                    },
                    deflection: Measure::Deflection.from_si(sys, c.deflection),
                    damage: c.damage,
                })
                .collect(),
            ..self.clone()
        }
    }
}
