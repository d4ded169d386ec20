//! The files and the table of `liftoff critical`: `critical.csv` (every position), `critical.json`
//! (the search with its critical positions) and influence maps of the bottom and top stresses
//! and of the deflection (`influence-{bottom,top,deflection}.svg/png`: the searched positions
//! as dots, the critical one ringed with the load's prints there, the plate's joints).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::chart::{self, Influence, Units};
use super::Staged;
use crate::error::{Error, Result};
use crate::layout::Axis;
use crate::post::JointLine;
use crate::study::{Critical, Position, RunOutcome};

/// critical.csv: one row per position, `c` as reported ([`Critical::reported`]), each header
/// with its unit.
fn csv(c: &Critical) -> String {
    use crate::units::Measure::{
        self, Deflection, Force, ForcePerLength, Length, Number, Pressure,
    };
    let sys = c.units;
    let columns: [(&str, Option<Measure>); 19] = [
        ("x", Some(Length)),
        ("y", Some(Length)),
        ("heading", Some(Measure::Degrees)),
        ("outcome", None),
        ("iterations", None),
        ("bottom", Some(Pressure)),
        ("bottom_x", Some(Length)),
        ("bottom_y", Some(Length)),
        ("top", Some(Pressure)),
        ("top_x", Some(Length)),
        ("top_y", Some(Length)),
        ("w_max", Some(Deflection)),
        ("contact_fraction", Some(Number)),
        ("joint_shear", Some(ForcePerLength)),
        ("dowel_force", Some(Force)),
        ("time", None),
        ("mirror_of", None),
        ("end_bottom", Some(Pressure)),
        ("end_top", Some(Pressure)),
    ];
    let header: Vec<String> = columns
        .iter()
        .map(|&(n, m)| match (n, m) {
            ("time", _) => "time [s]".to_string(),
            (n, Some(m)) => m.header(n, sys),
            (n, None) => n.to_string(),
        })
        .collect();
    let mut s = header.join(",");
    s.push('\n');
    // Empty where the plate has no joint of that kind.
    let opt = |v: Option<f64>| v.map_or(String::new(), |v| format!("{v:e}"));
    for p in &c.positions {
        let _ = writeln!(
            s,
            "{},{},{},{},{},{:e},{},{},{:e},{},{},{:e},{},{},{},{},{},{},{}",
            p.x,
            p.y,
            p.heading,
            p.outcome,
            p.iterations,
            p.bottom,
            p.bottom_at[0],
            p.bottom_at[1],
            p.top,
            p.top_at[0],
            p.top_at[1],
            p.w_max,
            p.contact_fraction,
            opt(p.joint_shear),
            opt(p.dowel_force),
            p.time_s,
            // Empty where the position was solved itself.
            p.mirror_of.map_or(String::new(), |k| k.to_string()),
            // Empty where the whole plate is read.
            opt(p.end_bottom),
            opt(p.end_top)
        );
    }
    s
}

/// The maps' and the table's units: the scene's system, lengths in metres of the search.
fn units_of(c: &Critical) -> Units {
    Units::of_si(c.units.unwrap_or_default())
}

/// Write critical.csv, critical.json and the influence maps into `dir`, staged.
pub fn write_critical(dir: &Path, c: &Critical, title: &str) -> Result<Vec<PathBuf>> {
    let mut st = Staged::new(dir)?;
    let reported = c.reported();
    st.write_text("critical.csv", &csv(&reported))?;
    let json = serde_json::to_string_pretty(&reported)
        .map_err(|e| Error::numerical("critical.json", format!("cannot serialise: {e}")))?;
    st.write_text("critical.json", &json)?;
    // The search is in SI (Pa, m): the maps show it in the scene's system (MPa and mm, or
    // psi and mils).
    let units = units_of(c);
    // One map per heading would need its own grid; the maps show the first heading's.
    let heading = c.positions.first().map_or(0.0, |p| p.heading);
    let mine: Vec<&Position> = c
        .positions
        .iter()
        .filter(|p| p.heading == heading)
        .collect();
    let points: Vec<(f64, f64)> = mine.iter().map(|p| (p.x, p.y)).collect();
    let joints: Vec<JointLine> = c
        .joints
        .iter()
        .map(|j| JointLine {
            name: j.name.clone(),
            kind: j.kind,
            axis: if j.axis == "x" { Axis::X } else { Axis::Y },
            at: j.at,
            // The influence maps draw every joint across the plate.
            span: None,
        })
        .collect();
    type Pick = fn(&Position) -> f64;
    let maps: [(&str, &str, Pick, chart::Scale, Option<usize>); 3] = [
        (
            "bottom",
            "σ₁ bottom",
            |p| p.bottom,
            units.stress(),
            c.bottom,
        ),
        ("top", "σ₁ top", |p| p.top, units.stress(), c.top),
        (
            "deflection",
            "w max",
            |p| p.w_max,
            units.deflection(),
            c.deflection,
        ),
    ];
    for (file, name, pick, scale, critical) in maps {
        // A solve that did not converge has no value to show: its cell is grey.
        let values: Vec<f64> = mine
            .iter()
            .map(|p| {
                if p.outcome == RunOutcome::CONVERGED {
                    pick(p)
                } else {
                    f64::NAN
                }
            })
            .collect();
        // The critical position is marked where it belongs to the heading drawn.
        let critical = critical.filter(|&i| c.positions[i].heading == heading);
        let mark = critical.map(|i| {
            let p = &c.positions[i];
            let value = scale.apply(pick(p));
            (
                (p.x, p.y),
                format!(
                    "critical position: largest {name} {} {}",
                    chart::short(value),
                    scale.unit
                )
                .trim_end()
                .to_string(),
            )
        });
        let prints = critical.map_or_else(Vec::new, |i| {
            c.prints_at(i)
                .iter()
                .map(|[x, y]| [(x[0], y[0]), (x[1], y[1])])
                .collect()
        });
        let svg = st.path(&format!("influence-{file}.svg"));
        let png = st.path(&format!("influence-{file}.png"));
        chart::write_influence_map(
            &svg,
            &png,
            &Influence {
                plate: c.plate,
                points: &points,
                values: &values,
                name,
                scale,
                joints: joints.clone(),
                critical: mark,
                prints,
            },
            &format!(
                "{title} — {name}{} with `{}` standing at each point (heading {heading}°)",
                // A cut lane's values are read between its first and last transverse joint.
                if c.read_x.is_some() {
                    " between the transverse joints"
                } else {
                    ""
                },
                c.load
            ),
            &units,
        )?;
    }
    st.commit()
}

/// How one line of the table reads its value off a position.
type ValueOf<'a> = dyn Fn(&Position) -> String + 'a;

/// What the command line prints.
pub fn critical_table(title: &str, c: &Critical, files: Option<(usize, &Path)>) -> String {
    let mut s = String::new();
    let n = c.positions.len();
    let converged = c
        .positions
        .iter()
        .filter(|p| p.outcome == crate::study::RunOutcome::CONVERGED)
        .count();
    let _ = writeln!(
        s,
        "liftoff critical — {title}: `{}` over {n} positions",
        c.load
    );
    let _ = writeln!(s, "  search     : {}", c.search());
    if let Some(comb) = &c.combination {
        let _ = writeln!(s, "  combination: {comb} (the rest of its loads present)");
    }
    let mirrored = c.positions.iter().filter(|p| p.mirror_of.is_some()).count();
    let solved = n - mirrored;
    let what = match mirrored {
        0 => format!("{n} positions solved"),
        m => format!("{n} positions ({solved} solved, {m} read off their mirror images)"),
    };
    let _ = writeln!(
        s,
        "  operators assembled once in {:.3} s; {what} in {:.3} s ({:.1} ms a solve), {converged} converged",
        c.assemble_s,
        c.total_s,
        1e3 * (c.total_s - c.assemble_s) / solved.max(1) as f64
    );
    let units = units_of(c);
    let (len, st, defl) = (units.length(), units.stress(), units.deflection());
    let line = |what: &str, i: Option<usize>, value: &dyn Fn(&Position) -> String| -> String {
        match i {
            Some(i) => {
                let p = &c.positions[i];
                format!(
                    "  {what:<20}: {} with the load at ({:.3}, {:.3}) {}, heading {}°",
                    value(p),
                    len.apply(p.x),
                    len.apply(p.y),
                    len.unit,
                    p.heading
                )
            }
            None => format!("  {what:<20}: no position converged"),
        }
    };
    let stress = |v: f64, at: [f64; 2]| {
        format!(
            "{:.3} {} at ({:.2}, {:.2})",
            st.apply(v),
            st.unit,
            len.apply(at[0]),
            len.apply(at[1])
        )
    };
    let (bottom, top) = (
        |p: &Position| stress(p.bottom, p.bottom_at),
        |p: &Position| stress(p.top, p.top_at),
    );
    let deflection = |p: &Position| format!("{:.3} {}", defl.apply(p.w_max), defl.unit);
    let (sh, fo) = (units.shear(), units.force());
    let shear = |p: &Position| {
        let v = p.joint_shear.unwrap_or(f64::NAN);
        format!("{:.3} {}", sh.apply(v), sh.unit)
    };
    let dowel = |p: &Position| {
        let v = p.dowel_force.unwrap_or(f64::NAN);
        format!("{:.3} {}", fo.apply(v), fo.unit)
    };
    let mut rows: Vec<(&str, Option<usize>, &ValueOf)> = vec![
        ("bottom tension", c.bottom, &bottom),
        ("top tension", c.top, &top),
        ("deflection", c.deflection, &deflection),
    ];
    // Joint shear and dowel force only where the slab has joints (dowels).
    if c.joint_shear.is_some() {
        rows.push(("joint shear", c.joint_shear, &shear));
    }
    if c.dowel_force.is_some() {
        rows.push(("dowel force", c.dowel_force, &dowel));
    }
    for (what, i, value) in rows {
        let _ = writeln!(s, "{}", line(what, i, value));
    }
    // A cut lane: what was read, and the largest of what was not.
    if let Some([lo, hi]) = c.read_x {
        let _ = writeln!(
            s,
            "  read between the transverse joints at x = {:.3} and {:.3} {}: the lane's ends are a cut (--ends free reads the end panels too)",
            len.apply(lo),
            len.apply(hi),
            len.unit
        );
        let end_bottom = |p: &Position| {
            format!(
                "{:.3} {}",
                st.apply(p.end_bottom.unwrap_or(f64::NAN)),
                st.unit
            )
        };
        let end_top =
            |p: &Position| format!("{:.3} {}", st.apply(p.end_top.unwrap_or(f64::NAN)), st.unit);
        let ends: [(&str, Option<usize>, &ValueOf); 2] = [
            ("end panels, bottom", c.end_bottom, &end_bottom),
            ("end panels, top", c.end_top, &end_top),
        ];
        for (what, i, value) in ends {
            if i.is_some() {
                let _ = writeln!(s, "{} (not read)", line(what, i, value));
            }
        }
    }
    if converged < n {
        let _ = writeln!(
            s,
            "  {} position(s) without a solution: see critical.csv (outcome)",
            n - converged
        );
    }
    if let Some((k, dir)) = files {
        let _ = writeln!(
            s,
            "  files      : {k} in {} (critical.csv, critical.json, influence maps)",
            dir.display()
        );
    }
    s
}
