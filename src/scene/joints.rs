//! `[[joint]]`: the joint lines of a jointed slab, validated into a [`Layout`] in the unit
//! system (positions / L; c̄ = AGG L³/D, c̄_r = c_r L/D, k̄_d = k_d L²/D in SI scenes, given as
//! such in dimensionless ones). `[[panel]]` and the loads on joint lines: [`super::panels`].
//!
//! Errors: E53 (a line outside the plate, or neither/both of x and y), E54 (a line not on an
//! element edge, with the element counts that put every line on one), E55 (two joints on one
//! line, a panel narrower than one element), E56 (a parameter missing, not positive or not for
//! that kind; a name used twice), E57 (the bars of a doweled joint).

use super::spec::{JointSpec, SceneFile};
use crate::check::finite_positive;
use crate::error::{Error, Result};
use crate::layout::{Axis, DowelBar, Joint, JointKind, JointType, Layout};

/// Positions closer than this (unit system) are equal.
pub(super) const TOL: f64 = 1e-9;
/// Most bars on one joint.
pub const MAX_BARS: usize = 100_000;

/// What the layout's validation needs of the rest of the scene.
pub(super) struct Frame {
    /// Half sides of the plate in the unit system: [1, μ].
    pub half: [f64; 2],
    /// Scene coordinates to the unit system: [1/L, 1/L] (SI) or [1, μ].
    pub scale_xy: [f64; 2],
    /// Elements over the whole plate.
    pub elements: [usize; 2],
    /// SI scenes: L (m), D (N·m), the plate's thickness H (m) and Young's modulus E (Pa).
    pub si: Option<[f64; 4]>,
    /// Most elements per side (the element counts E54 may suggest).
    pub max_elements: usize,
}

impl Frame {
    /// The unit of scene coordinates along an axis (m, s or t).
    pub(super) fn unit(&self, axis: Axis) -> &'static str {
        match (self.si.is_some(), axis) {
            (true, _) => "m",
            (false, Axis::X) => "s",
            (false, Axis::Y) => "t",
        }
    }

    /// 0 for x, 1 for y.
    pub(super) fn index(axis: Axis) -> usize {
        match axis {
            Axis::X => 0,
            Axis::Y => 1,
        }
    }

    /// The other axis: the coordinate along a joint of this family.
    fn along(axis: Axis) -> Axis {
        match axis {
            Axis::X => Axis::Y,
            Axis::Y => Axis::X,
        }
    }
}

/// `[[joint]]` of a scene as a [`Layout`] without panel overrides ([`super::panels`] adds
/// them).
pub(super) fn layout(file: &SceneFile, frame: &Frame) -> Result<Layout> {
    let mut joints = Vec::with_capacity(file.joint.len());
    for (k, spec) in file.joint.iter().enumerate() {
        let (axis, at, span) = line(k, spec, frame)?;
        let name = spec.name.clone().unwrap_or_else(|| format!("J{}", k + 1));
        let name = name.trim().to_string();
        if name.is_empty() {
            return Err(Error::invalid(
                format!("joint[{k}].name"),
                "is empty: give a name or leave the key out (J1, J2 … then)",
            ));
        }
        if let Some(prev) = joints.iter().position(|j: &Joint| j.name == name) {
            return Err(Error::invalid(
                format!("joint[{k}].name"),
                format!("`{name}` is already the name of joint[{prev}]: names must be unique"),
            ));
        }
        let kind = kind(k, spec, frame)?;
        if span.is_some() && kind == JointKind::Continuous {
            return Err(Error::invalid(
                format!("joint[{k}].kind"),
                "a continuous joint only delimits panels, across the whole plate: give it as a line (x = … or y = …)",
            ));
        }
        joints.push(Joint {
            name,
            axis,
            at,
            span,
            kind,
        });
    }
    for axis in [Axis::X, Axis::Y] {
        spacing(&joints, axis, frame)?;
    }
    for axis in [Axis::X, Axis::Y] {
        on_grid(&mut joints, axis, frame)?;
    }
    for k in 0..joints.len() {
        bars(k, &file.joint[k], &mut joints, frame)?;
    }
    Ok(Layout {
        joints,
        ..Layout::default()
    })
}

/// E53: a segment's line and extent (`from`, `to`: along x or y, inside the plate's box), in
/// the unit system.
fn segment(k: usize, spec: &JointSpec, frame: &Frame) -> Result<(Axis, f64, [f64; 2])> {
    let field = |n: &str| format!("joint[{k}].{n}");
    let (Some(a), Some(b)) = (spec.from, spec.to) else {
        let missing = if spec.from.is_none() { "from" } else { "to" };
        return Err(Error::invalid(
            field(missing),
            "missing: a joint segment runs from `from = [x, y]` to `to = [x, y]`",
        ));
    };
    if spec.x.is_some() || spec.y.is_some() {
        return Err(Error::invalid(
            format!("joint[{k}]"),
            "gives both a line (x or y) and a segment (from, to): one or the other",
        ));
    }
    if let Some(v) = a.iter().chain(&b).find(|v| !v.is_finite()) {
        return Err(Error::invalid(
            field("from"),
            format!("must be finite, got {v}"),
        ));
    }
    let (axis, at, ends) = if (a[0] - b[0]).abs() <= TOL && (a[1] - b[1]).abs() > TOL {
        (Axis::X, a[0], [a[1], b[1]])
    } else if (a[1] - b[1]).abs() <= TOL && (a[0] - b[0]).abs() > TOL {
        (Axis::Y, a[1], [a[0], b[0]])
    } else {
        return Err(Error::invalid(
            field("to"),
            format!(
                "the segment from ({}, {}) to ({}, {}) runs along neither x nor y (or has no length): a joint on the structured grid runs along one of its lines",
                a[0], a[1], b[0], b[1]
            ),
        ));
    };
    let (i, o) = (Frame::index(axis), Frame::index(Frame::along(axis)));
    let u = at * frame.scale_xy[i];
    let span = [
        ends[0].min(ends[1]) * frame.scale_xy[o],
        ends[0].max(ends[1]) * frame.scale_xy[o],
    ];
    let (half, half_o) = (frame.half[i], frame.half[o]);
    if u.abs() >= half * (1.0 - TOL)
        || span[0] < -half_o * (1.0 + TOL)
        || span[1] > half_o * (1.0 + TOL)
    {
        return Err(Error::invalid(
            format!("joint[{k}]"),
            format!(
                "the segment at {} = {at} {} lies on or outside the plate's box: a joint runs inside the plate",
                axis.name(),
                frame.unit(axis)
            ),
        ));
    }
    Ok((axis, u, span))
}

/// E53: the joint's line, x = … or y = …, strictly inside the plate, or its segment
/// ([`segment`]) with its extent along the line.
fn line(k: usize, spec: &JointSpec, frame: &Frame) -> Result<(Axis, f64, Option<[f64; 2]>)> {
    if spec.from.is_some() || spec.to.is_some() {
        return segment(k, spec, frame).map(|(a, u, s)| (a, u, Some(s)));
    }
    let (axis, v) = match (spec.x, spec.y) {
        (Some(x), None) => (Axis::X, x),
        (None, Some(y)) => (Axis::Y, y),
        (Some(_), Some(_)) => {
            return Err(Error::invalid(
                format!("joint[{k}]"),
                "gives both x and y: a joint is one line, x = … (across the width) or y = …",
            ))
        }
        (None, None) => {
            return Err(Error::invalid(
                format!("joint[{k}]"),
                "missing: the line's position, x = … (a line across the width) or y = …, or a segment from = [x, y], to = [x, y]",
            ))
        }
    };
    let field = format!("joint[{k}].{}", axis.name());
    if !v.is_finite() {
        return Err(Error::invalid(field, format!("must be finite, got {v}")));
    }
    let i = Frame::index(axis);
    let u = v * frame.scale_xy[i];
    let half = frame.half[i];
    if u.abs() >= half * (1.0 - TOL) {
        return Err(Error::invalid(
            field,
            format!(
                "{v} {} lies on or outside the plate's edge: a joint line must cross the plate (|{}| < {:.6})",
                frame.unit(axis),
                axis.name(),
                half / frame.scale_xy[i]
            ),
        ));
    }
    Ok((axis, u, None))
}

/// E56: the kind's constants, in the unit system (bars placed later by [`bars`]).
fn kind(k: usize, spec: &JointSpec, frame: &Frame) -> Result<JointKind> {
    let field = |n: &str| format!("joint[{k}].{n}");
    let kind = spec.kind;
    let refuse = |n: &str, present: bool| -> Result<()> {
        if present {
            Err(Error::invalid(
                field(n),
                format!("does not apply to a joint of kind = \"{}\"", kind.name()),
            ))
        } else {
            Ok(())
        }
    };
    let dowel_keys = [
        ("spacing", spec.spacing.is_some()),
        ("offset", spec.offset.is_some()),
        ("positions", spec.positions.is_some()),
        ("diameter", spec.diameter.is_some()),
        ("youngs_modulus", spec.youngs_modulus.is_some()),
        ("opening", spec.opening.is_some()),
        ("support_modulus", spec.support_modulus.is_some()),
        ("dowel_stiffness", spec.dowel_stiffness.is_some()),
    ];
    if kind != JointType::Dowels {
        for (n, present) in dowel_keys {
            refuse(n, present)?;
        }
    }
    if !matches!(kind, JointType::Aggregate | JointType::Tied) {
        refuse("stiffness", spec.stiffness.is_some())?;
    }
    if kind != JointType::Tied {
        refuse("rotational_stiffness", spec.rotational_stiffness.is_some())?;
    }
    // Unit conversions of an SI scene: c L³/D, c_r L/D, k_d L²/D.
    let (shear, turn, point) = match frame.si {
        Some([l, d, ..]) => (l.powi(3) / d, l / d, l * l / d),
        None => (1.0, 1.0, 1.0),
    };
    let si = frame.si.is_some();
    let required = |n: &str, v: Option<f64>, unit: &str| -> Result<f64> {
        let v = v.ok_or_else(|| {
            Error::invalid(
                field(n),
                format!(
                    "missing: a joint of kind = \"{}\" needs its {n} ({unit})",
                    kind.name()
                ),
            )
        })?;
        finite_positive(&field(n), v, unit)
    };
    let agg_unit = if si { "N/m²" } else { "c L³/D" };
    Ok(match kind {
        JointType::Free => JointKind::Free,
        JointType::Continuous => JointKind::Continuous,
        JointType::Aggregate => JointKind::Aggregate {
            c: required("stiffness", spec.stiffness, agg_unit)? * shear,
        },
        JointType::Tied => JointKind::Tied {
            c: required("stiffness", spec.stiffness, agg_unit)? * shear,
            c_r: required(
                "rotational_stiffness",
                spec.rotational_stiffness,
                if si { "N·m/m per rad" } else { "c_r L/D" },
            )? * turn,
        },
        JointType::Dowels => {
            let bar_keys = [
                spec.diameter,
                spec.youngs_modulus,
                spec.opening,
                spec.support_modulus,
            ];
            let any_bar = bar_keys.iter().any(Option::is_some);
            if !si && any_bar {
                let n = ["diameter", "youngs_modulus", "opening", "support_modulus"]
                    [bar_keys.iter().position(Option::is_some).unwrap_or(0)];
                return Err(Error::invalid(
                    field(n),
                    "a dowel bar's properties need an SI scene; a dimensionless scene gives each bar's spring as dowel_stiffness = k_d L²/D",
                ));
            }
            let (k_si, bar) = match (spec.dowel_stiffness, any_bar) {
                (Some(_), true) => {
                    return Err(Error::invalid(
                        field("dowel_stiffness"),
                        "give either the bar (diameter, youngs_modulus, opening, support_modulus) or its spring dowel_stiffness, not both",
                    ))
                }
                (Some(v), false) => (
                    finite_positive(
                        &field("dowel_stiffness"),
                        v,
                        if si { "N/m per bar" } else { "k_d L²/D per bar" },
                    )?,
                    None,
                ),
                (None, _) if si => {
                    let bar = DowelBar {
                        diameter: required("diameter", spec.diameter, "m")?,
                        youngs_modulus: required("youngs_modulus", spec.youngs_modulus, "Pa")?,
                        opening: match spec.opening {
                            Some(z) if z.is_finite() && z >= 0.0 => z,
                            Some(z) => {
                                return Err(Error::invalid(
                                    field("opening"),
                                    format!("must be a finite opening ≥ 0 (m), got {z}"),
                                ))
                            }
                            None => {
                                return Err(Error::invalid(
                                    field("opening"),
                                    "missing: a dowels joint needs its opening (m; 0 for a tight joint)",
                                ))
                            }
                        },
                        support: required("support_modulus", spec.support_modulus, "N/m³")?,
                    };
                    let k = bar.spring();
                    if !(k.is_finite() && k > 0.0) {
                        return Err(Error::invalid(
                            field("diameter"),
                            format!("the bar's properties give the spring {k:e} N/m, outside double precision: check their units (m, Pa, N/m³)"),
                        ));
                    }
                    (k, Some(bar))
                }
                (None, _) => {
                    return Err(Error::invalid(
                        field("dowel_stiffness"),
                        "missing: a dowels joint of a dimensionless scene needs each bar's spring dowel_stiffness = k_d L²/D",
                    ))
                }
            };
            if spec.spacing.is_some() == spec.positions.is_some() {
                return Err(Error::invalid(
                    field("spacing"),
                    "give the bars either by spacing (and offset) or by positions, one of the two",
                ));
            }
            if spec.offset.is_some() && spec.spacing.is_none() {
                return Err(Error::invalid(
                    field("offset"),
                    "belongs with spacing (the first bar's distance from the joint's start)",
                ));
            }
            JointKind::Dowels {
                k: k_si * point,
                positions: Vec::new(),
                bar,
            }
        }
    })
}

/// E55: one joint per line (segments on one line that do not overlap excepted), and lines
/// whose extents overlap (and the plate's edges) at least one element apart.
fn spacing(joints: &[Joint], axis: Axis, frame: &Frame) -> Result<()> {
    let i = Frame::index(axis);
    let half = frame.half[i];
    let h = 2.0 * half / frame.elements[i] as f64;
    let mut lines: Vec<(f64, usize)> = joints
        .iter()
        .enumerate()
        .filter(|(_, j)| j.axis == axis)
        .map(|(k, j)| (j.at, k))
        .collect();
    lines.sort_by(|a, b| a.0.total_cmp(&b.0));
    let show = |u: f64| u / frame.scale_xy[i];
    let unit = frame.unit(axis);
    // Extents along the line that share more than a point (a whole line shares with all).
    let overlap = |a: Option<[f64; 2]>, b: Option<[f64; 2]>| match (a, b) {
        (Some(p), Some(q)) => p[1].min(q[1]) - p[0].max(q[0]) > TOL,
        _ => true,
    };
    for (n, &(u, k)) in lines.iter().enumerate() {
        let field = format!("joint[{k}].{}", axis.name());
        for &(p, j) in &lines[..n] {
            if !overlap(joints[j].span, joints[k].span) {
                continue;
            }
            if u - p <= TOL {
                return Err(Error::invalid(
                    field,
                    format!(
                        "lies on the same line as joint[{j}] ({} = {}): one joint per line (segments on one line must not overlap)",
                        axis.name(),
                        show(p)
                    ),
                ));
            }
            if u - p < h * (1.0 - 1e-6) {
                return Err(Error::invalid(
                    field,
                    format!(
                        "is {:.6} {unit} from joint[{j}], less than one element ({:.6} {unit}): a panel needs at least one element across; refine mesh.elements[{i}] or merge the joints",
                        show(u - p),
                        show(h)
                    ),
                ));
            }
        }
        let edge = (u + half).min(half - u);
        if edge < h * (1.0 - 1e-6) {
            return Err(Error::invalid(
                field,
                format!(
                    "is {:.6} {unit} from the plate's edge, less than one element ({:.6} {unit}): a panel needs at least one element across; refine mesh.elements[{i}] or drop the joint",
                    show(edge),
                    show(h)
                ),
            ));
        }
    }
    Ok(())
}

/// True when every position lies on an edge of `n` elements over [−half, half].
fn fits(positions: &[f64], half: f64, n: usize) -> bool {
    positions.iter().all(|&u| {
        let f = (u + half) / (2.0 * half) * n as f64;
        (f - f.round()).abs() <= 1e-6
    })
}

/// E54: every line on an element edge; snapped onto it.
fn on_grid(joints: &mut [Joint], axis: Axis, frame: &Frame) -> Result<()> {
    let i = Frame::index(axis);
    let (half, n) = (frame.half[i], frame.elements[i]);
    let positions: Vec<f64> = joints
        .iter()
        .filter(|j| j.axis == axis)
        .map(|j| j.at)
        .collect();
    if let Some(k) = joints
        .iter()
        .position(|j| j.axis == axis && !fits(&[j.at], half, n))
    {
        let unit = frame.unit(axis);
        let edge = 2.0 * half / n as f64 / frame.scale_xy[i];
        let limit = frame.max_elements;
        let hint = match (n..=limit).find(|&m| fits(&positions, half, m)) {
            Some(m) => format!("mesh.elements[{i}] = {m} puts every joint {} = … on an element edge", axis.name()),
            None => format!("no element count up to {limit} puts every joint {} = … on an element edge: move the joints onto a common grid", axis.name()),
        };
        return Err(Error::invalid(
            format!("joint[{k}].{}", axis.name()),
            format!(
                "{:.6} {unit} is not on an element edge of the mesh's {n} elements along {} (edges every {edge:.6} {unit}): {hint}",
                joints[k].at / frame.scale_xy[i],
                axis.name()
            ),
        ));
    }
    for j in joints.iter_mut().filter(|j| j.axis == axis) {
        let f = ((j.at + half) / (2.0 * half) * n as f64).round();
        j.at = -half + f * 2.0 * half / n as f64;
    }
    // A segment's ends on element edges along the line too.
    let o = Frame::index(Frame::along(axis));
    let (half_o, n_o) = (frame.half[o], frame.elements[o]);
    let ends: Vec<f64> = joints
        .iter()
        .filter(|j| j.axis == axis)
        .filter_map(|j| j.span)
        .flatten()
        .collect();
    if let Some(k) = joints
        .iter()
        .position(|j| j.axis == axis && j.span.is_some_and(|s| !fits(&s, half_o, n_o)))
    {
        let along = Frame::along(axis);
        let limit = frame.max_elements;
        let hint = match (n_o..=limit).find(|&m| fits(&ends, half_o, m)) {
            Some(m) => format!("mesh.elements[{o}] = {m} puts every segment's end on an element edge"),
            None => format!("no element count up to {limit} puts every segment's end on an element edge: move the ends onto a common grid"),
        };
        return Err(Error::invalid(
            format!("joint[{k}].from"),
            format!(
                "the segment's ends are not on element edges of the mesh's {n_o} elements along {} (edges every {:.6} {}): {hint}",
                along.name(),
                2.0 * half_o / n_o as f64 / frame.scale_xy[o],
                frame.unit(along)
            ),
        ));
    }
    for j in joints.iter_mut().filter(|j| j.axis == axis) {
        if let Some(span) = &mut j.span {
            for v in span.iter_mut() {
                let f = ((*v + half_o) / (2.0 * half_o) * n_o as f64).round();
                *v = -half_o + f * 2.0 * half_o / n_o as f64;
            }
        }
    }
    Ok(())
}

/// E57: the bars of a doweled joint, along it, off the plate's edges and off crossing cuts.
fn bars(k: usize, spec: &JointSpec, joints: &mut [Joint], frame: &Frame) -> Result<()> {
    let axis = joints[k].axis;
    let along = Frame::along(axis);
    let i = Frame::index(along);
    let (half, scale) = (frame.half[i], frame.scale_xy[i]);
    let unit = frame.unit(along);
    let field = |n: &str| format!("joint[{k}].{n}");
    // The cutting joints that cross this one (a segment only where it reaches it).
    let at_k = joints[k].at;
    let crossings: Vec<f64> = joints
        .iter()
        .filter(|j| j.axis == along && j.kind.doubles() && j.covers(at_k))
        .map(|j| j.at)
        .collect();
    // The joint's extent along its line: the plate's width, or a segment's.
    let (lo, hi) = joints[k].span.map_or((-half, half), |s| (s[0], s[1]));
    let JointKind::Dowels { positions, .. } = &mut joints[k].kind else {
        return Ok(());
    };
    let mut list: Vec<(f64, String)> = Vec::new();
    if let Some(p) = &spec.positions {
        for (b, &v) in p.iter().enumerate() {
            if !v.is_finite() {
                return Err(Error::invalid(
                    field(&format!("positions[{b}]")),
                    format!("must be finite, got {v}"),
                ));
            }
            list.push((v * scale, format!("positions[{b}]")));
        }
    } else if let Some(s) = spec.spacing {
        let s = finite_positive(&field("spacing"), s, unit)?;
        let offset = match spec.offset {
            Some(o) if o.is_finite() && o >= 0.0 => o,
            Some(o) => {
                return Err(Error::invalid(
                    field("offset"),
                    format!("must be a finite distance ≥ 0 ({unit}), got {o}"),
                ))
            }
            None => 0.5 * s,
        };
        let length = (hi - lo) / scale;
        if (length - offset) / s > MAX_BARS as f64 {
            return Err(Error::invalid(
                field("spacing"),
                format!("puts more than {MAX_BARS} bars on the joint: check its units ({unit})"),
            ));
        }
        let mut b = 0;
        loop {
            let v = offset + b as f64 * s;
            if v * scale >= (hi - lo) * (1.0 - TOL) {
                break;
            }
            list.push((lo + v * scale, format!("spacing (bar {})", b + 1)));
            b += 1;
        }
    }
    if list.is_empty() {
        return Err(Error::invalid(
            field(if spec.positions.is_some() {
                "positions"
            } else {
                "offset"
            }),
            format!(
                "puts no bar on the joint (its length is {:.6} {unit})",
                (hi - lo) / scale
            ),
        ));
    }
    if list.len() > MAX_BARS {
        return Err(Error::invalid(
            field("positions"),
            format!("more than {MAX_BARS} bars on one joint"),
        ));
    }
    for (u, name) in &list {
        if *u <= lo + TOL * half || *u >= hi - TOL * half {
            return Err(Error::invalid(
                field(name),
                format!(
                    "the bar at {:.6} {unit} lies outside the joint or on the plate's edge ({:.6} < {} < {:.6})",
                    u / scale,
                    lo / scale,
                    along.name(),
                    hi / scale
                ),
            ));
        }
        if let Some(c) = crossings.iter().find(|&&c| (c - u).abs() <= TOL) {
            return Err(Error::invalid(
                field(name),
                format!(
                    "the bar at {:.6} {unit} lies on the joint line {} = {:.6} that crosses this one: move it off the crossing",
                    u / scale,
                    along.name(),
                    c / scale
                ),
            ));
        }
    }
    let mut sorted: Vec<f64> = list.iter().map(|b| b.0).collect();
    sorted.sort_by(f64::total_cmp);
    if let Some(w) = sorted.windows(2).find(|w| w[1] - w[0] <= TOL) {
        return Err(Error::invalid(
            field("positions"),
            format!(
                "two bars at {:.6} {unit}: one bar per position",
                w[0] / scale
            ),
        ));
    }
    *positions = list.into_iter().map(|b| b.0).collect();
    Ok(())
}

/// E81: each end of a segment joint (one that cuts the plate) lies at the plate's box, at the
/// edge of the plate's shape (the cells beyond the end are not both plate), or on another
/// cutting joint (a line, or a segment whose extent holds the point: a T, an L, a joint that
/// continues on the same line). A joint that stops inside a panel would be a crack tip, not a
/// joint between slabs.
pub(super) fn segment_ends(layout: &Layout, frame: &Frame) -> Result<()> {
    let mask = crate::mesh::outline::CellMask::of_layout(layout, frame.elements, frame.half[1]);
    for (k, joint) in layout.joints.iter().enumerate() {
        let (Some(span), true) = (joint.span, joint.kind.doubles()) else {
            continue;
        };
        let (a, o) = (
            Frame::index(joint.axis),
            Frame::index(Frame::along(joint.axis)),
        );
        let cells =
            |half: f64, n: usize, v: f64| ((v + half) / (2.0 * half) * n as f64).round() as isize;
        let line = cells(frame.half[a], frame.elements[a], joint.at);
        let n_along = frame.elements[o] as isize;
        for (end, step) in [(span[0], -1), (span[1], 1)] {
            let g = cells(frame.half[o], frame.elements[o], end);
            if g <= 0 || g >= n_along {
                continue; // at the box's edge
            }
            // The two cells beside the edge beyond the end.
            let beyond = if step > 0 { g } else { g - 1 };
            let (c1, c2) = match joint.axis {
                Axis::X => ((line - 1, beyond), (line, beyond)),
                Axis::Y => ((beyond, line - 1), (beyond, line)),
            };
            if !(mask.at(c1.0, c1.1) && mask.at(c2.0, c2.1)) {
                continue; // at the edge of the plate's shape
            }
            let on_other = layout.joints.iter().enumerate().any(|(m, other)| {
                m != k
                    && other.kind.doubles()
                    && if other.axis == joint.axis {
                        (other.at - joint.at).abs() <= TOL && other.covers(end)
                    } else {
                        (other.at - end).abs() <= TOL && other.covers(joint.at)
                    }
            });
            if !on_other {
                let (x, y) = match joint.axis {
                    Axis::X => (joint.at, end),
                    Axis::Y => (end, joint.at),
                };
                return Err(Error::invalid(
                    format!("joint[{k}]"),
                    format!(
                        "ends at ({:.6}, {:.6}) {} inside the plate: a joint that stops in the middle of a panel would be a crack tip — end it on another joint or at the plate's edge",
                        x / frame.scale_xy[0],
                        y / frame.scale_xy[1],
                        frame.unit(Axis::X)
                    ),
                ));
            }
        }
    }
    Ok(())
}
