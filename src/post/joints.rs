//! What each joint of a jointed slab carries, over the whole plate: its load transfer
//! efficiency, the shear (and moment) per unit length along it, the force it hands across, and
//! the force and bearing stress of every dowel bar.
//!
//! Signs follow the joint elements ([`crate::system`]): the jump of a joint is w⁻ − w⁺ (the
//! − side is x < x_j for a line x = const, y < y_j for y = const), and a shear, a transferred
//! force or a dowel force is positive when the − side pushes the + side down.
//!
//! * **Node pairs**: the two copies at each end of every element edge of the joint line, in
//!   order along it (at a crossing with another cutting joint two pairs share one position).
//! * **Shear per length** at a pair: q = c (w⁻ − w⁺) for an aggregate or tied joint (c the
//!   joint's spring per unit length); **moment per length** (tied): c_r (ψn⁻ − ψn⁺), ψn the
//!   rotation normal to the joint.
//! * **Transferred force**: the force the joint elements put on the + side, Σ over the edges
//!   of c ∫ (w⁻ − w⁺) ds = c h (j₁ + j₂)/2 (the jump is linear along an edge, so the
//!   consistent element's nodal forces add up to this integral exactly), plus Σ of the dowel
//!   forces.
//! * **Dowel force**: F = k_d (w⁻ − w⁺) at the bar, the jump interpolated linearly along its
//!   edge; its bearing stress on the concrete σ_b = K y₀(|F|) (Friberg 1940) where the scene
//!   gives the bar's properties.
//! * **LTE by deflection**: at the pair where either side deflects most (the loaded side),
//!   w_unloaded / w_loaded; NaN when no copy on the joint deflects downward.
//! * **LTE by stress**: at that pair, the bottom-face stress parallel to the joint
//!   (σ = 6 m∥/H_p²: m_y for a line x = const, m_x for y = const) of the elements beside the
//!   pair on each side (their mean, each with its own panel's thickness), unloaded over loaded.

use serde::Serialize;

use super::field::{ElementField, FullField};
use crate::layout::{JointKind, JointType, Layout};
use crate::mesh::Mesh;
use crate::model::Physical;

/// Which side of a joint line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Side {
    /// x < x_j (a line x = const) or y < y_j.
    Minus,
    /// x > x_j or y > y_j.
    Plus,
}

/// One node pair along a joint (a row of joints.csv).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointNode {
    /// x of the pair (physical, as [`FullField::x`]).
    pub x: f64,
    /// y of the pair.
    pub y: f64,
    /// The − side's copy (index into the field's arrays).
    pub minus: usize,
    /// The + side's copy.
    pub plus: usize,
    /// w of the − side.
    pub w_minus: f64,
    /// w of the + side.
    pub w_plus: f64,
    /// w⁻ − w⁺.
    pub jump: f64,
    /// c (w⁻ − w⁺): force per unit length (0 for joints without a distributed spring).
    pub shear_per_length: f64,
    /// c_r (ψn⁻ − ψn⁺): moment per unit length (tied joints; 0 otherwise).
    pub moment_per_length: f64,
    /// Contact pressure under the − side.
    pub pressure_minus: f64,
    /// Contact pressure under the + side.
    pub pressure_plus: f64,
}

/// One dowel bar (a row of dowels.csv).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DowelForce {
    /// Index of the bar in its joint's positions.
    pub bar: usize,
    /// x of the bar (physical).
    pub x: f64,
    /// y of the bar.
    pub y: f64,
    /// w⁻ − w⁺ at the bar.
    pub jump: f64,
    /// k_d (w⁻ − w⁺) (physical force).
    pub force: f64,
    /// Bearing stress on the concrete at the joint face (Pa), when the bar's properties are
    /// known.
    pub bearing_stress: Option<f64>,
}

/// What one cutting joint carries (summary.json's `joints`).
#[derive(Debug, Clone, Serialize)]
pub struct JointReport {
    /// The joint's name.
    pub name: String,
    /// Its kind.
    pub kind: JointType,
    /// "x" for a line x = const, "y" for y = const.
    pub axis: &'static str,
    /// The line's coordinate (physical).
    pub line: f64,
    /// w of the unloaded side over w of the loaded side where the loaded side deflects most
    /// (NaN, written null, when nothing on the joint deflects downward).
    pub lte_deflection: f64,
    /// The unloaded side's edge stress over the loaded side's there.
    pub lte_stress: f64,
    /// Where the LTE is read, [x, y].
    pub at: [f64; 2],
    /// The side that deflects most there.
    pub loaded_side: Side,
    /// Force handed from the − side to the + side (physical).
    pub transferred_force: f64,
    /// Largest |q| along the joint, force per length (aggregate and tied joints).
    pub max_shear_per_length: Option<f64>,
    /// Largest |m| along the joint, moment per length (tied joints).
    pub max_moment_per_length: Option<f64>,
    /// Largest |F| of its dowels.
    pub max_dowel_force: Option<f64>,
    /// Largest bearing stress of its dowels (when the bars' properties are known).
    pub max_bearing_stress: Option<f64>,
    /// The node pairs along it (joints.csv).
    #[serde(skip)]
    pub nodes: Vec<JointNode>,
    /// Its bars (dowels.csv).
    #[serde(skip)]
    pub dowels: Vec<DowelForce>,
}

/// The largest magnitude of some values, None when there are none.
fn largest(values: impl Iterator<Item = f64>) -> Option<f64> {
    values.map(f64::abs).reduce(f64::max)
}

/// The reports of every cutting joint of the whole plate `whole` (its layout, the physical
/// `field` and `elements` of [`super::whole::fields`], the unit-system dofs `u` of every copy of
/// `whole` and the field's index of each, the scales `ph`); empty for a plate without joints.
pub(super) fn reports(
    whole: &Mesh,
    field: &FullField,
    elements: &ElementField,
    u: &[[f64; 3]],
    to_field: &[usize],
    ph: &Physical,
    physical: bool,
) -> Vec<JointReport> {
    let Some(topo) = &whole.topo else {
        return Vec::new();
    };
    let layout: &Layout = &topo.layout;
    let mut out = Vec::new();
    for (k, joint) in layout.joints.iter().enumerate() {
        let segments: Vec<_> = topo.segments.iter().filter(|s| s.joint == k).collect();
        let Some(first) = segments.first() else {
            continue; // continuous: no joint
        };
        let axis = first.axis;
        // The rotation normal to the line: ψx for x = const.
        let normal = match axis {
            crate::layout::Axis::X => 1,
            crate::layout::Axis::Y => 2,
        };
        let (c, c_r) = match joint.kind {
            JointKind::Aggregate { c } => (c, 0.0),
            JointKind::Tied { c, c_r } => (c, c_r),
            _ => (0.0, 0.0),
        };
        let jump = |a: usize, b: usize| u[a][0] - u[b][0];
        // A spring's force of a jump; exactly 0 (not −0) without the spring.
        let spring = |k: f64, j: f64| if k == 0.0 { 0.0 } else { k * j };
        // Node pairs in order along the joint.
        let mut nodes: Vec<JointNode> = Vec::with_capacity(segments.len() + 1);
        for seg in &segments {
            for end in 0..2 {
                let (a, b) = (seg.a[end], seg.b[end]);
                if nodes.last().is_some_and(|p| p.minus == a && p.plus == b) {
                    continue;
                }
                let (fa, fb) = (to_field[a], to_field[b]);
                nodes.push(JointNode {
                    x: field.x[fa],
                    y: field.y[fa],
                    minus: a,
                    plus: b,
                    w_minus: field.w[fa],
                    w_plus: field.w[fb],
                    jump: jump(a, b) * ph.deflection(),
                    shear_per_length: spring(c, jump(a, b)) * ph.shear(),
                    moment_per_length: spring(c_r, u[a][normal] - u[b][normal]) * ph.moment(),
                    pressure_minus: field.pressure[fa],
                    pressure_plus: field.pressure[fb],
                });
            }
        }
        // The distributed springs' force, exactly c ∫ jump ds edge by edge.
        let mut transferred: f64 = segments
            .iter()
            .map(|s| {
                spring(
                    c,
                    s.length * 0.5 * (jump(s.a[0], s.b[0]) + jump(s.a[1], s.b[1])),
                )
            })
            .sum::<f64>()
            * ph.force;
        let bar = match &joint.kind {
            JointKind::Dowels { bar, .. } if physical => *bar,
            _ => None,
        };
        let mut dowels = Vec::new();
        for d in topo.dowels.iter() {
            let seg = &topo.segments[d.segment];
            if seg.joint != k {
                continue;
            }
            let t = d.t;
            let j = (1.0 - t) * jump(seg.a[0], seg.b[0]) + t * jump(seg.a[1], seg.b[1]);
            let force = d.k * j * ph.force;
            transferred += force;
            let (a0, a1) = (to_field[seg.a[0]], to_field[seg.a[1]]);
            dowels.push(DowelForce {
                bar: d.bar,
                x: field.x[a0] + t * (field.x[a1] - field.x[a0]),
                y: field.y[a0] + t * (field.y[a1] - field.y[a0]),
                jump: j * ph.deflection(),
                force,
                bearing_stress: bar.map(|b| b.bearing_stress(force.abs())),
            });
        }

        // The loaded side: the copy on the joint that deflects most.
        let loaded = (0..nodes.len()).max_by(|&p, &q| {
            let m = |n: &JointNode| n.w_minus.max(n.w_plus);
            m(&nodes[p]).total_cmp(&m(&nodes[q]))
        });
        let (mut lte_deflection, mut lte_stress, mut at, mut side) =
            (f64::NAN, f64::NAN, [f64::NAN; 2], Side::Minus);
        if let Some(p) = loaded {
            let n = nodes[p];
            side = if n.w_minus >= n.w_plus {
                Side::Minus
            } else {
                Side::Plus
            };
            let (wl, wo) = match side {
                Side::Minus => (n.w_minus, n.w_plus),
                Side::Plus => (n.w_plus, n.w_minus),
            };
            at = [n.x, n.y];
            if wl > 0.0 {
                lte_deflection = wo / wl;
            }
            // The edge stress parallel to the joint, mean over a side's elements at the pair.
            let edge = |copy: usize| -> f64 {
                let around = topo.incident(copy);
                let sum: f64 = around
                    .iter()
                    .map(|&(e, _)| {
                        let m = match axis {
                            crate::layout::Axis::X => elements.my[e],
                            crate::layout::Axis::Y => elements.mx[e],
                        };
                        let h = elements.thickness[e];
                        6.0 * m / (h * h)
                    })
                    .sum();
                sum / around.len().max(1) as f64
            };
            let (sl, so) = match side {
                Side::Minus => (edge(n.minus), edge(n.plus)),
                Side::Plus => (edge(n.plus), edge(n.minus)),
            };
            if sl != 0.0 && sl.is_finite() {
                lte_stress = so / sl;
            }
        }
        // The copies by the field's numbering (nodes.csv's order, the Python arrays').
        for n in &mut nodes {
            n.minus = to_field[n.minus];
            n.plus = to_field[n.plus];
        }
        let distributed = matches!(joint.kind.kind(), JointType::Aggregate | JointType::Tied);
        let tied = joint.kind.kind() == JointType::Tied;
        let doweled = joint.kind.kind() == JointType::Dowels;
        out.push(JointReport {
            name: joint.name.clone(),
            kind: joint.kind.kind(),
            axis: joint.axis.name(),
            line: joint.at * ph.half_length,
            lte_deflection,
            lte_stress,
            at,
            loaded_side: side,
            transferred_force: transferred,
            max_shear_per_length: if distributed {
                largest(nodes.iter().map(|n| n.shear_per_length))
            } else {
                None
            },
            max_moment_per_length: if tied {
                largest(nodes.iter().map(|n| n.moment_per_length))
            } else {
                None
            },
            max_dowel_force: if doweled {
                largest(dowels.iter().map(|d| d.force))
            } else {
                None
            },
            max_bearing_stress: largest(dowels.iter().filter_map(|d| d.bearing_stress)),
            nodes,
            dowels,
        });
    }
    out
}
