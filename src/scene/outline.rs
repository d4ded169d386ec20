//! `[plate] outline` and `[[opening]]`: the plate's shape on the structured grid, validated
//! into the [`Layout`] in the unit system (E79), and the loads that would fall off the plate
//! (E80).
//!
//! The polygons are checked in the scene's own coordinates ([`check_polygon`]: corners on grid
//! lines, edges along them, a simple polygon inside the box); the shape as a whole on the
//! scene's grid ([`CellMask`]): an opening that removes no plate, a plate left with no cell or
//! in more than one piece are refused.

use super::joints::Frame;
use super::load_spec::LoadKind;
use super::loads::RawLoad;
use super::spec::{OpeningSpec, SceneFile};
use crate::error::{Error, Result};
use crate::layout::{Layout, Polygon};
use crate::mesh::outline::{check_polygon, CellMask};
use crate::model::Load;

/// E79: the outline and the openings of the scene into `layout` (unit system).
pub(super) fn shapes(file: &SceneFile, layout: &mut Layout, frame: &Frame) -> Result<()> {
    let outline = (file.plate.as_ref().and_then(|p| p.outline.as_ref()))
        .or(file.dimensionless.as_ref().and_then(|d| d.outline.as_ref()));
    let field = match file.plate.as_ref().and_then(|p| p.outline.as_ref()) {
        Some(_) => "plate.outline",
        None => "dimensionless.outline",
    };
    if outline.is_none() && file.opening.is_empty() && layout.regions.is_empty() {
        return Ok(());
    }
    let [nx, ny] = frame.elements;
    let mut mask = CellMask::full(nx, ny);
    if let Some(vertices) = outline {
        let corners = grid_corners(vertices, field, frame)?;
        mask = CellMask::inside(nx, ny, &corners);
        layout.outline = Some(to_units(vertices, frame));
    }
    for (k, spec) in file.opening.iter().enumerate() {
        let (vertices, field) = opening_polygon(k, spec)?;
        let corners = grid_corners(&vertices, &field, frame)?;
        let hole = CellMask::inside(nx, ny, &corners);
        let removed = mask.plate.iter().zip(&hole.plate).filter(|(&p, &h)| p && h);
        if removed.count() == 0 {
            return Err(Error::invalid(
                format!("opening[{k}]"),
                "removes no plate: it lies outside the outline or inside another opening — move it onto the plate or leave it out",
            ));
        }
        mask = mask.without(&hole);
        layout.openings.push(to_units(&vertices, frame));
    }
    // The plate's cells with the region panels (which may fill an opening) in them.
    let mask = CellMask::of_layout(layout, frame.elements, frame.half[1]);
    let pieces = mask.pieces();
    if pieces.len() > 1 {
        let size = box_size(frame);
        let [hx, hy] = [size[0] / nx as f64, size[1] / ny as f64];
        let centre = |c: usize| {
            let (i, j) = (c % nx, c / nx);
            (
                -size[0] / 2.0 + (i as f64 + 0.5) * hx,
                -size[1] / 2.0 + (j as f64 + 0.5) * hy,
            )
        };
        let list: Vec<String> = pieces
            .iter()
            .map(|p| {
                let (x, y) = centre(p[0]);
                format!("{} cells from ({x:.3}, {y:.3})", p.len())
            })
            .collect();
        return Err(Error::invalid(
            if file.opening.is_empty() { field } else { "opening" },
            format!(
                "the outline and openings leave the plate in {} pieces that share no edge ({}): one scene is one plate — model each piece as its own scene, or join them",
                pieces.len(),
                list.join("; ")
            ),
        ));
    }
    Ok(())
}

/// The shape of a scene in its own coordinates (m, or s and t): its outline, openings and
/// panels of their own outline as polygons — for point tests before the scene becomes a model
/// (a backcalculation's sensors on its template).
pub(crate) fn scene_shape(file: &SceneFile) -> Result<Layout> {
    let mut shape = Layout {
        outline: (file.plate.as_ref().and_then(|p| p.outline.clone()))
            .or_else(|| file.dimensionless.as_ref().and_then(|d| d.outline.clone())),
        ..Layout::default()
    };
    for (k, o) in file.opening.iter().enumerate() {
        shape.openings.push(opening_polygon(k, o)?.0);
    }
    for (k, p) in file.panel.iter().enumerate() {
        if p.x.is_some() || p.y.is_some() || p.outline.is_some() {
            let (polygon, _) = polygon(&format!("panel[{k}]"), p.x, p.y, p.outline.as_ref())?;
            shape.regions.push(crate::layout::Region {
                polygon,
                section: crate::layout::PanelSection::REFERENCE,
            });
        }
    }
    Ok(shape)
}

/// The polygon of `[[opening]]` k (scene coordinates) and the field its errors name.
fn opening_polygon(k: usize, spec: &OpeningSpec) -> Result<(Vec<[f64; 2]>, String)> {
    polygon(
        &format!("opening[{k}]"),
        spec.x,
        spec.y,
        spec.outline.as_ref(),
    )
}

/// A polygon given as a rectangle (`x`, `y`) or by its corners (`outline`), in scene
/// coordinates, with the field its errors name (`entry`, or `entry.outline`).
pub(super) fn polygon(
    entry: &str,
    x: Option<[f64; 2]>,
    y: Option<[f64; 2]>,
    outline: Option<&Vec<[f64; 2]>>,
) -> Result<(Vec<[f64; 2]>, String)> {
    match (outline, x, y) {
        (Some(p), None, None) => Ok((p.clone(), format!("{entry}.outline"))),
        (None, Some(x), Some(y)) => {
            for (name, [a, b]) in [("x", x), ("y", y)] {
                if !(a.is_finite() && b.is_finite() && a < b) {
                    return Err(Error::invalid(
                        format!("{entry}.{name}"),
                        format!("[{a}, {b}] is not an interval: give [low, high] with low < high"),
                    ));
                }
            }
            let corners = vec![[x[0], y[0]], [x[1], y[0]], [x[1], y[1]], [x[0], y[1]]];
            Ok((corners, entry.to_string()))
        }
        _ => Err(Error::invalid(
            entry,
            "give a rectangle (`x = [x0, x1]` and `y = [y0, y1]`) or a polygon (`outline = [[x, y], …]`), not both",
        )),
    }
}

/// The box of the scene in its own coordinates, [a, b].
pub(super) fn box_size(frame: &Frame) -> [f64; 2] {
    [
        2.0 * frame.half[0] / frame.scale_xy[0],
        2.0 * frame.half[1] / frame.scale_xy[1],
    ]
}

/// A polygon of the scene (`field` names it in errors) checked on the plate's box and grid
/// ([`check_polygon`], lengths in m where the scene has them): its corners' grid indices.
pub(super) fn grid_corners(
    vertices: &[[f64; 2]],
    field: &str,
    frame: &Frame,
) -> Result<Vec<[usize; 2]>> {
    check_polygon(
        vertices,
        box_size(frame),
        frame.elements,
        field,
        frame.si.map(|_| "m"),
    )
}

/// Scene coordinates to the unit system.
pub(super) fn to_units(vertices: &[[f64; 2]], frame: &Frame) -> Polygon {
    vertices
        .iter()
        .map(|p| [p[0] * frame.scale_xy[0], p[1] * frame.scale_xy[1]])
        .collect()
}

/// E57 on a shaped plate: a dowel bar sits where its joint has plate on both sides. Bars given
/// by `positions` elsewhere are refused naming the bar; bars laid out by `spacing` along the
/// whole line keep only those on the plate (a joint line ends at an opening or the outline).
pub(super) fn bars_on_plate(file: &SceneFile, layout: &mut Layout, frame: &Frame) -> Result<()> {
    if !layout.is_shaped() {
        return Ok(());
    }
    let mask = CellMask::of_layout(layout, frame.elements, frame.half[1]);
    let [nx, ny] = frame.elements;
    let (hx, hy) = (
        2.0 * frame.half[0] / nx as f64,
        2.0 * frame.half[1] / ny as f64,
    );
    for (k, joint) in layout.joints.iter_mut().enumerate() {
        let (axis, at) = (joint.axis, joint.at);
        let crate::layout::JointKind::Dowels { positions, .. } = &mut joint.kind else {
            continue;
        };
        // Both cells beside the bar: across the line, at the bar's cell along it.
        let on = |p: f64| match axis {
            crate::layout::Axis::X => {
                let i = ((at + frame.half[0]) / hx).round() as isize;
                let j = (((p + frame.half[1]) / hy).floor() as isize).min(ny as isize - 1);
                mask.at(i - 1, j) && mask.at(i, j)
            }
            crate::layout::Axis::Y => {
                let j = ((at + frame.half[1]) / hy).round() as isize;
                let i = (((p + frame.half[0]) / hx).floor() as isize).min(nx as isize - 1);
                mask.at(i, j - 1) && mask.at(i, j)
            }
        };
        let explicit = file.joint.get(k).is_some_and(|j| j.positions.is_some());
        if explicit {
            if let Some(b) = positions.iter().position(|&p| !on(p)) {
                let i = Frame::index(match axis {
                    crate::layout::Axis::X => crate::layout::Axis::Y,
                    crate::layout::Axis::Y => crate::layout::Axis::X,
                });
                return Err(Error::invalid(
                    format!("joint[{k}].positions[{b}]"),
                    format!(
                        "the bar at {:.6} {} lies where the joint has no plate on both sides (an opening or outside the outline): move it onto the joint",
                        positions[b] / frame.scale_xy[i],
                        frame.unit(crate::layout::Axis::X)
                    ),
                ));
            }
        } else {
            positions.retain(|&p| on(p));
            if positions.is_empty() {
                return Err(Error::invalid(
                    format!("joint[{k}].spacing"),
                    "puts no bar where the joint has plate on both sides: check the spacing and offset",
                ));
            }
        }
    }
    Ok(())
}

/// A `uniform` load on a shaped plate acts on the plate, not on its bounding box: each one
/// becomes the rectangles of plate cells (runs along x, merged across rows where they match),
/// of the same case and entry, so that its resultant is the pressure times the plate's area.
/// Every other load is kept as it is.
pub(super) fn uniform_on_plate(
    file: &SceneFile,
    raw: Vec<RawLoad>,
    layout: &Layout,
    frame: &Frame,
) -> Vec<RawLoad> {
    if !layout.is_shaped() {
        return raw;
    }
    let mask = CellMask::of_layout(layout, frame.elements, frame.half[1]);
    let rects = mask.rectangles();
    let [nx, ny] = frame.elements;
    let (hx, hy) = (
        2.0 * frame.half[0] / nx as f64,
        2.0 * frame.half[1] / ny as f64,
    );
    let mut out = Vec::with_capacity(raw.len() + rects.len());
    for r in raw {
        let uniform = file
            .load
            .get(r.source)
            .is_some_and(|l| l.kind == LoadKind::Uniform);
        match (uniform, r.load) {
            (true, Load::Patch { pressure, .. }) => {
                out.extend(rects.iter().map(|&[i0, i1, j0, j1]| RawLoad {
                    load: Load::Patch {
                        x: [
                            -frame.half[0] + i0 as f64 * hx,
                            -frame.half[0] + i1 as f64 * hx,
                        ],
                        y: [
                            -frame.half[1] + j0 as f64 * hy,
                            -frame.half[1] + j1 as f64 * hy,
                        ],
                        pressure,
                    },
                    case: r.case.clone(),
                    source: r.source,
                }))
            }
            _ => out.push(r),
        }
    }
    out
}

/// E80: a load wholly or partly off the plate's shape (on an opening, or outside the outline
/// in the box). `loads` are in the unit system, in scene order.
pub(super) fn loads_on_plate(layout: &Layout, loads: &[Load], frame: &Frame) -> Result<()> {
    if !layout.is_shaped() {
        return Ok(());
    }
    let mask = CellMask::of_layout(layout, frame.elements, frame.half[1]);
    for (k, load) in loads.iter().enumerate() {
        if let Some(what) = off_plate(&mask, load, frame) {
            return Err(Error::invalid(format!("load[{k}]"), what));
        }
    }
    Ok(())
}

/// Why `load` (unit system) is not wholly on the plate of `mask` (the whole plate's cells), or
/// `None` when it is.
pub(super) fn off_plate(mask: &CellMask, load: &Load, frame: &Frame) -> Option<String> {
    let [hx, hy] = [
        2.0 * frame.half[0] / mask.nx as f64,
        2.0 * frame.half[1] / mask.ny as f64,
    ];
    let cell = |p: [f64; 2]| [(p[0] + frame.half[0]) / hx, (p[1] + frame.half[1]) / hy];
    let scene = |p: [f64; 2]| [p[0] / frame.scale_xy[0], p[1] / frame.scale_xy[1]];
    let unit = frame.unit(crate::layout::Axis::X);
    match *load {
        Load::Point { x, y, .. } => {
            let [fx, fy] = cell([x, y]);
            (!mask.holds_point(fx, fy)).then(|| {
                let [sx, sy] = scene([x, y]);
                format!(
                    "the point ({sx}, {sy}) {unit} lies on an opening or outside the plate's outline: move it onto the plate"
                )
            })
        }
        Load::Patch { x, y, .. } => {
            let [fx0, fy0] = cell([x[0], y[0]]);
            let [fx1, fy1] = cell([x[1], y[1]]);
            (!mask.covers([fx0, fx1], [fy0, fy1])).then(|| {
                let ([a, c], [b, d]) = (scene([x[0], y[0]]), scene([x[1], y[1]]));
                format!(
                    "the loaded area [{a}, {b}] × [{c}, {d}] {unit} lies wholly or partly on an opening or outside the plate's outline: a load that falls through the slab is not carried — move it onto the plate"
                )
            })
        }
        Load::Line { from, to, .. } => {
            // The segment at 64 points per cell it crosses: every one on the plate.
            let [f0, f1] = [cell(from), cell(to)];
            let n = (64.0 * ((f1[0] - f0[0]).abs() + (f1[1] - f0[1]).abs())).ceil() as usize + 1;
            let off = (0..=n).map(|s| s as f64 / n as f64).any(|t| {
                !mask.holds_point(f0[0] + t * (f1[0] - f0[0]), f0[1] + t * (f1[1] - f0[1]))
            });
            off.then(|| {
                "the line load runs over an opening or outside the plate's outline: move it onto the plate"
                    .to_string()
            })
        }
        Load::Temperature { .. } | Load::FaceStress { .. } => None,
    }
}
