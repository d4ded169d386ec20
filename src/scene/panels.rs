//! `[[panel]]` overrides of a jointed slab's layout and panels of their own outline (E58), and
//! the loads a joint line would split (E59), after the joints ([`super::joints`]).

use super::joints::{Frame, TOL};
use super::spec::{PanelSpec, SceneFile};
use crate::check::finite_positive;
use crate::error::{Error, Result};
use crate::layout::{Axis, Layout, PanelOverride, PanelSection, Region};
use crate::mesh::outline::CellMask;
use crate::model::Load;

/// `[[panel]]`: the layout's panel overrides, one per panel of the joints' grid (`at`), and
/// the panels of their own outline (`x` and `y`, or `outline`: [`Layout::regions`]).
pub(super) fn panels(file: &SceneFile, layout: &mut Layout, frame: &Frame) -> Result<()> {
    for (k, spec) in file.panel.iter().enumerate() {
        if spec.x.is_some() || spec.y.is_some() || spec.outline.is_some() {
            region(k, spec, layout, frame)?;
            continue;
        }
        let Some(at) = spec.at else {
            return Err(Error::invalid(
                format!("panel[{k}]"),
                "missing: `at = [x, y]` (a point in a panel of the joints' grid), or the panel's own outline (`x` and `y`, or `outline`)",
            ));
        };
        let p = panel(k, spec, at, layout, frame)?;
        if let Some(prev) = layout
            .panels
            .iter()
            .position(|o| (o.column, o.row) == (p.column, p.row))
        {
            return Err(Error::invalid(
                format!("panel[{k}].at"),
                format!(
                    "lies in panel ({}, {}), which panel[{prev}] already overrides: one entry per panel",
                    p.column + 1,
                    p.row + 1
                ),
            ));
        }
        layout.panels.push(p);
    }
    Ok(())
}

/// E58, E79: a panel of its own outline — a polygon along the grid's lines, overlapping no
/// other such panel — with its section.
fn region(k: usize, spec: &PanelSpec, layout: &mut Layout, frame: &Frame) -> Result<()> {
    if spec.at.is_some() {
        return Err(Error::invalid(
            format!("panel[{k}].at"),
            "give `at` (a panel of the joints' grid) or the panel's own outline (`x` and `y`, or `outline`), not both",
        ));
    }
    let section = section(k, spec, frame, &format!("panel[{k}]"))?;
    let (vertices, field) = super::outline::polygon(
        &format!("panel[{k}]"),
        spec.x,
        spec.y,
        spec.outline.as_ref(),
    )?;
    let corners = super::outline::grid_corners(&vertices, &field, frame)?;
    let [nx, ny] = frame.elements;
    let cells = CellMask::inside(nx, ny, &corners);
    let polygon = super::outline::to_units(&vertices, frame);
    let before = Layout {
        regions: layout.regions.clone(),
        ..Layout::default()
    };
    let (hx, hy) = (2.0 / nx as f64, 2.0 * frame.half[1] / ny as f64);
    let shared = (0..nx * ny).find(|&c| {
        let (x, y) = (
            -1.0 + (c % nx) as f64 * hx + 0.5 * hx,
            -frame.half[1] + (c / nx) as f64 * hy + 0.5 * hy,
        );
        cells.plate[c] && before.region_at(x, y).is_some()
    });
    if let Some(c) = shared {
        let (x, y) = (
            -1.0 + (c % nx) as f64 * hx + 0.5 * hx,
            -frame.half[1] + (c / nx) as f64 * hy + 0.5 * hy,
        );
        return Err(Error::invalid(
            field,
            format!(
                "overlaps panel region {} (at ({:.6}, {:.6}) {}): one panel per cell",
                before.region_at(x, y).map_or(0, |r| r + 1),
                x / frame.scale_xy[0],
                y / frame.scale_xy[1],
                frame.unit(Axis::X)
            ),
        ));
    }
    layout.regions.push(Region { polygon, section });
    Ok(())
}

/// E58: a panel override, strictly inside one panel, with at least one positive value.
fn panel(
    k: usize,
    spec: &PanelSpec,
    at_scene: [f64; 2],
    layout: &Layout,
    frame: &Frame,
) -> Result<PanelOverride> {
    let field = |n: &str| format!("panel[{k}].{n}");
    let mut at = [0.0; 2];
    for (i, axis) in [Axis::X, Axis::Y].into_iter().enumerate() {
        let v = at_scene[i];
        let u = v * frame.scale_xy[i];
        if !v.is_finite() || u.abs() >= frame.half[i] * (1.0 - TOL) {
            return Err(Error::invalid(
                field("at"),
                format!(
                    "{} = {v} {} lies outside the plate or on its edge: give a point inside the panel",
                    axis.name(),
                    frame.unit(axis)
                ),
            ));
        }
        if let Some(j) = layout
            .joints
            .iter()
            .find(|j| j.axis == axis && j.span.is_none() && (j.at - u).abs() <= TOL)
        {
            return Err(Error::invalid(
                field("at"),
                format!(
                    "lies on joint {} ({} = {v} {}): give a point inside the panel, off its edges",
                    j.name,
                    axis.name(),
                    frame.unit(axis)
                ),
            ));
        }
        at[i] = u;
    }
    let [column, row] = layout.panel_at(at[0], at[1]);
    Ok(PanelOverride {
        column,
        row,
        section: section(k, spec, frame, &field("at"))?,
    })
}

/// E58: a panel's section from its thickness and Young's modulus (or their ratios), at least
/// one given; `changes_nothing` names the field of that error.
fn section(
    k: usize,
    spec: &PanelSpec,
    frame: &Frame,
    changes_nothing: &str,
) -> Result<PanelSection> {
    let field = |n: &str| format!("panel[{k}].{n}");
    let positive = |n: &str, v: Option<f64>, unit: &str| -> Result<Option<f64>> {
        v.map(|v| finite_positive(&field(n), v, unit)).transpose()
    };
    let wrong = |n: &str, present: bool, hint: &str| -> Result<()> {
        if present {
            Err(Error::invalid(field(n), hint.to_string()))
        } else {
            Ok(())
        }
    };
    let (thickness, modulus) = match frame.si {
        Some([l, _, h, e]) => {
            wrong(
                "thickness_ratio",
                spec.thickness_ratio.is_some(),
                "belongs to a dimensionless scene; give the panel's thickness in m",
            )?;
            wrong(
                "modulus_ratio",
                spec.modulus_ratio.is_some(),
                "belongs to a dimensionless scene; give the panel's youngs_modulus in Pa",
            )?;
            let t = positive("thickness", spec.thickness, "m")?;
            if let Some(t) = t {
                if t >= l {
                    return Err(Error::invalid(
                        field("thickness"),
                        format!(
                            "{t} m is not small beside the plate ({} m long): check units (metres)",
                            2.0 * l
                        ),
                    ));
                }
            }
            (
                t.map(|t| t / h),
                positive("youngs_modulus", spec.youngs_modulus, "Pa")?.map(|v| v / e),
            )
        }
        None => {
            wrong(
                "thickness",
                spec.thickness.is_some(),
                "belongs to an SI scene; give the panel's thickness_ratio H_p/H",
            )?;
            wrong(
                "youngs_modulus",
                spec.youngs_modulus.is_some(),
                "belongs to an SI scene; give the panel's modulus_ratio E_p/E",
            )?;
            (
                positive("thickness_ratio", spec.thickness_ratio, "H_p/H")?,
                positive("modulus_ratio", spec.modulus_ratio, "E_p/E")?,
            )
        }
    };
    if thickness.is_none() && modulus.is_none() {
        return Err(Error::invalid(
            changes_nothing,
            "the override changes nothing: give the panel's thickness or Young's modulus (thickness_ratio or modulus_ratio in a dimensionless scene)",
        ));
    }
    let (t, m) = (thickness.unwrap_or(1.0), modulus.unwrap_or(1.0));
    // Beyond these the panels' stiffnesses differ by more than ~1e9, which the plate factor
    // cannot resolve beside the reference plate.
    if !(1e-2..=1e2).contains(&t) || !(1e-3..=1e3).contains(&m) {
        return Err(Error::invalid(
            changes_nothing,
            format!("the panel's thickness ratio {t:e} or modulus ratio {m:e} lies outside [1e-2, 1e2] / [1e-3, 1e3] of the plate's: check units"),
        ));
    }
    Ok(PanelSection::of(t, m))
}

/// E59: a point load or a line load lying on a line that cuts the plate (which side carries it
/// is ambiguous). `loads` are in the unit system, in scene order.
pub(super) fn loads_off_cuts(layout: &Layout, loads: &[Load], frame: &Frame) -> Result<()> {
    // On a joint: on its line and within its extent (a segment's).
    let on = |axis: Axis, p: [f64; 2]| {
        layout.joints.iter().find(|j| {
            j.kind.doubles()
                && j.axis == axis
                && (p[Frame::index(axis)] - j.at).abs() <= TOL
                && j.covers(p[1 - Frame::index(axis)])
        })
    };
    for (k, load) in loads.iter().enumerate() {
        let hit = match *load {
            Load::Point { x, y, .. } => on(Axis::X, [x, y])
                .map(|j| (j, "x"))
                .or_else(|| on(Axis::Y, [x, y]).map(|j| (j, "y"))),
            Load::Line { from, to, .. } => [Axis::X, Axis::Y].into_iter().find_map(|a| {
                on(a, from)
                    .filter(|j| on(a, to).is_some_and(|o| o.name == j.name))
                    .map(|j| (j, if a == Axis::X { "from" } else { "to" }))
            }),
            _ => None,
        };
        if let Some((j, name)) = hit {
            let i = Frame::index(j.axis);
            return Err(Error::invalid(
                format!("load[{k}].{name}"),
                format!(
                    "lies on joint {} ({} = {:.6} {}), a {} joint: which panel carries it is ambiguous — move it off the line or split it between the two panels",
                    j.name,
                    j.axis.name(),
                    j.at / frame.scale_xy[i],
                    frame.unit(j.axis),
                    j.kind.kind().name()
                ),
            ));
        }
    }
    Ok(())
}
