//! The joints of a jointed slab in the result files and the solve table: `joints.csv` (one row
//! per node pair along each joint), `dowels.csv` (one row per bar) and one line of the table
//! per joint.

use std::fmt::Write as _;
use std::path::Path;

use crate::error::{Error, Result};
use crate::output::chart::Units;
use crate::post::{JointReport, Side};
use crate::units::{Measure, UnitSystem};

fn csv_err(path: &Path, e: csv::Error) -> Error {
    Error::Io {
        path: path.display().to_string(),
        source: std::io::Error::other(e.to_string()),
    }
}

/// A CSV file from its header and rows of formatted cells.
fn write_csv(path: &Path, header: &[String], rows: Vec<Vec<String>>) -> Result<()> {
    let mut w = csv::Writer::from_path(path).map_err(|e| csv_err(path, e))?;
    w.write_record(header).map_err(|e| csv_err(path, e))?;
    for rec in rows {
        w.write_record(&rec).map_err(|e| csv_err(path, e))?;
    }
    w.flush().map_err(|e| Error::Io {
        path: path.display().to_string(),
        source: e,
    })
}

/// Headers: a word column's name as it is, a measured one with its unit in `system`.
fn headers(columns: &[(&str, Option<Measure>)], system: Option<UnitSystem>) -> Vec<String> {
    columns
        .iter()
        .map(|&(name, m)| m.map_or(name.to_string(), |m| m.header(name, system)))
        .collect()
}

/// joints.csv: joint, kind, x, y, minus_node, plus_node (the two copies' rows in nodes.csv, 0
/// for the first data row), w_minus, w_plus, jump (w⁻ − w⁺), shear_per_length,
/// moment_per_length, pressure_minus, pressure_plus — one row per node pair along each joint,
/// in order along it; the values in `system`'s units, each header with its unit.
pub fn write_joints(path: &Path, joints: &[JointReport], system: Option<UnitSystem>) -> Result<()> {
    use Measure::{Deflection as D, Length as L, Pressure as P};
    let header = headers(
        &[
            ("joint", None),
            ("kind", None),
            ("x", Some(L)),
            ("y", Some(L)),
            ("minus_node", None),
            ("plus_node", None),
            ("w_minus", Some(D)),
            ("w_plus", Some(D)),
            ("jump", Some(D)),
            ("shear_per_length", Some(Measure::ForcePerLength)),
            ("moment_per_length", Some(Measure::MomentPerLength)),
            ("pressure_minus", Some(P)),
            ("pressure_plus", Some(P)),
        ],
        system,
    );
    let num = |m: Measure, v: f64| format!("{:.12e}", m.from_si(system, v));
    let mut rows = Vec::new();
    for j in joints {
        for n in &j.nodes {
            rows.push(vec![
                j.name.clone(),
                j.kind.name().to_string(),
                num(L, n.x),
                num(L, n.y),
                n.minus.to_string(),
                n.plus.to_string(),
                num(D, n.w_minus),
                num(D, n.w_plus),
                num(D, n.jump),
                num(Measure::ForcePerLength, n.shear_per_length),
                num(Measure::MomentPerLength, n.moment_per_length),
                num(P, n.pressure_minus),
                num(P, n.pressure_plus),
            ]);
        }
    }
    write_csv(path, &header, rows)
}

/// dowels.csv: joint, bar (its index in the joint's positions), x, y, jump, force,
/// bearing_stress (empty when the bar's properties are not given); the values in `system`'s
/// units, each header with its unit.
pub fn write_dowels(path: &Path, joints: &[JointReport], system: Option<UnitSystem>) -> Result<()> {
    use Measure::{Deflection as D, Force as F, Length as L, Pressure as P};
    let header = headers(
        &[
            ("joint", None),
            ("bar", None),
            ("x", Some(L)),
            ("y", Some(L)),
            ("jump", Some(D)),
            ("force", Some(F)),
            ("bearing_stress", Some(P)),
        ],
        system,
    );
    let num = |m: Measure, v: f64| format!("{:.12e}", m.from_si(system, v));
    let mut rows = Vec::new();
    for j in joints {
        for d in &j.dowels {
            rows.push(vec![
                j.name.clone(),
                d.bar.to_string(),
                num(L, d.x),
                num(L, d.y),
                num(D, d.jump),
                num(F, d.force),
                d.bearing_stress.map_or(String::new(), |b| num(P, b)),
            ]);
        }
    }
    write_csv(path, &header, rows)
}

/// The solve table's lines for the joints: per joint its line, LTE by deflection and by
/// stress and where, the force it transfers, and its largest shear, moment, dowel force and
/// bearing stress, in the table's units.
pub fn joint_lines(joints: &[JointReport], units: &Units) -> Vec<String> {
    let force = units.force();
    let shear = units.shear();
    let moment = units.moment();
    let stress = units.stress();
    let length = units.length();
    // "1.5 m", or "1.5" in a dimensionless scene.
    let at = |v: f64| {
        format!("{:.3} {}", length.apply(v), length.unit)
            .trim_end()
            .to_string()
    };
    let ratio = |v: f64| {
        if v.is_finite() {
            format!("{v:.3}")
        } else {
            "n/a".to_string()
        }
    };
    joints
        .iter()
        .map(|j| {
            let mut l = format!(
                "  joint {:<5}: {} at {} = {}, LTE {} (deflection), {} (stress) at ({:.3}, {:.3}), {} side loaded; transfers {:.3} {}",
                j.name,
                j.kind.name(),
                j.axis,
                at(j.line),
                ratio(j.lte_deflection),
                ratio(j.lte_stress),
                length.apply(j.at[0]),
                length.apply(j.at[1]),
                match j.loaded_side {
                    Side::Minus => "−",
                    Side::Plus => "+",
                },
                force.apply(j.transferred_force),
                force.unit
            )
            .trim_end()
            .to_string();
            if let Some(q) = j.max_shear_per_length {
                let _ = write!(l, ", shear ≤ {:.3} {}", shear.apply(q), shear.unit);
            }
            if let Some(m) = j.max_moment_per_length {
                let _ = write!(l, ", moment ≤ {:.3} {}", moment.apply(m), moment.unit);
            }
            if let Some(f) = j.max_dowel_force {
                let _ = write!(
                    l,
                    ", {} bars, force ≤ {:.3} {}",
                    j.dowels.len(),
                    force.apply(f),
                    force.unit
                );
            }
            if let Some(b) = j.max_bearing_stress {
                let _ = write!(l, ", bearing ≤ {:.3} {}", stress.apply(b), stress.unit);
            }
            l
        })
        .collect()
}
