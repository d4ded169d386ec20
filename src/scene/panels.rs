//! `[[panel]]` overrides of a jointed slab's layout (E58) and the loads a joint line would split
//! (E59), after the joints ([`super::joints`]).

use super::joints::{Frame, TOL};
use super::spec::{PanelSpec, SceneFile};
use crate::check::finite_positive;
use crate::error::{Error, Result};
use crate::layout::{Axis, Layout, PanelOverride, PanelSection};
use crate::model::Load;

/// `[[panel]]`: the layout's panel overrides, one per panel.
pub(super) fn panels(file: &SceneFile, layout: &mut Layout, frame: &Frame) -> Result<()> {
    for (k, spec) in file.panel.iter().enumerate() {
        let p = panel(k, spec, layout, frame)?;
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

/// E58: a panel override, strictly inside one panel, with at least one positive value.
fn panel(k: usize, spec: &PanelSpec, layout: &Layout, frame: &Frame) -> Result<PanelOverride> {
    let field = |n: &str| format!("panel[{k}].{n}");
    let mut at = [0.0; 2];
    for (i, axis) in [Axis::X, Axis::Y].into_iter().enumerate() {
        let v = spec.at[i];
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
            field("at"),
            "the override changes nothing: give the panel's thickness or Young's modulus (thickness_ratio or modulus_ratio in a dimensionless scene)",
        ));
    }
    let (t, m) = (thickness.unwrap_or(1.0), modulus.unwrap_or(1.0));
    // Beyond these the panels' stiffnesses differ by more than ~1e9, which the plate factor
    // cannot resolve beside the reference plate.
    if !(1e-2..=1e2).contains(&t) || !(1e-3..=1e3).contains(&m) {
        return Err(Error::invalid(
            field("at"),
            format!("the panel's thickness ratio {t:e} or modulus ratio {m:e} lies outside [1e-2, 1e2] / [1e-3, 1e3] of the plate's: check units"),
        ));
    }
    Ok(PanelOverride {
        column,
        row,
        section: PanelSection::of(t, m),
    })
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
