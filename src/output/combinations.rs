//! Files and the CLI table of a run over load combinations: a sub-folder per combination with
//! the standard result set, and the envelope (`envelope.json`, `envelope.csv` and the per-node
//! and per-element envelopes with the governing combination).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use rayon::prelude::*;
use serde::Serialize;

use super::{stage_all, Staged};
use crate::combination::{Combinations, Envelope, PointEnvelope, QuantityEnvelope};
use crate::error::{Error, Result};

fn csv_err(path: &Path) -> impl Fn(csv::Error) -> Error + '_ {
    move |e| Error::Io {
        path: path.display().to_string(),
        source: std::io::Error::other(e.to_string()),
    }
}

/// envelope.json.
#[derive(Serialize)]
struct EnvelopeJson<'a> {
    combinations: Vec<CombinationJson<'a>>,
    assemble_s: f64,
    total_s: f64,
    extremes: &'a [QuantityEnvelope],
}

#[derive(Serialize)]
struct CombinationJson<'a> {
    name: &'a str,
    factors: std::collections::BTreeMap<&'a str, f64>,
    converged: bool,
    status: String,
    time_s: f64,
}

/// Write every combination's files into `dir/NAME/` and the envelope beside them, all staged
/// and moved into place together. Returns the paths written.
pub fn write_combinations(dir: &Path, c: &Combinations, env: &Envelope) -> Result<Vec<PathBuf>> {
    let mut st = Staged::new(dir)?;
    // The charts dominate the writing: stage the combinations' folders side by side.
    let parts: Vec<Result<Staged>> = c
        .runs
        .par_iter()
        .filter_map(|run| run.outcome.as_ref().ok().map(|o| (run, o)))
        .map(|(run, o)| {
            let mut part = st.share();
            let overlay = super::chart::Overlay::for_model(&run.model, &o.report);
            stage_all(
                &mut part,
                &format!("{}/", run.name),
                &o.report,
                &o.summary,
                &overlay,
            )?;
            Ok(part)
        })
        .collect();
    for part in parts {
        st.absorb(part?);
    }
    // The files report the scene's unit system; the maps above scale the SI envelope.
    let reported = env.reported();
    let json = EnvelopeJson {
        combinations: c
            .runs
            .iter()
            .map(|r| CombinationJson {
                name: &r.name,
                factors: r.factors.iter().map(|(k, v)| (k.as_str(), *v)).collect(),
                converged: matches!(&r.outcome, Ok(o) if o.solution.status.converged()),
                status: match &r.outcome {
                    Ok(o) => o.solution.status.describe(),
                    Err(e) => e.to_string(),
                },
                time_s: r.seconds,
            })
            .collect(),
        assemble_s: c.assemble_s,
        total_s: c.total_s,
        extremes: &reported.quantities,
    };
    let text = serde_json::to_string_pretty(&json)
        .map_err(|e| Error::numerical("envelope", format!("cannot serialise: {e}")))?;
    st.write_text("envelope.json", &text)?;

    let p = st.path("envelope.csv");
    let mut w = csv::Writer::from_path(&p).map_err(csv_err(&p))?;
    let length = crate::units::Measure::Length.unit(env.system);
    w.write_record([
        "quantity".to_string(),
        "unit".to_string(),
        "extreme".to_string(),
        "value".to_string(),
        "combination".to_string(),
        format!("x [{length}]"),
        format!("y [{length}]"),
    ])
    .map_err(csv_err(&p))?;
    for q in &reported.quantities {
        for (which, e) in [("max", &q.max), ("min", &q.min)] {
            w.write_record([
                q.quantity.to_string(),
                q.unit.to_string(),
                which.to_string(),
                format!("{:e}", e.value),
                e.combination.clone(),
                format!("{}", e.x),
                format!("{}", e.y),
            ])
            .map_err(csv_err(&p))?;
        }
    }
    w.flush().map_err(|e| Error::Io {
        path: p.display().to_string(),
        source: e,
    })?;
    stage_envelope_maps(&mut st, c, env)?;
    for (file, xy, fields) in [
        ("envelope_nodes.csv", &reported.node_xy, &reported.nodes),
        (
            "envelope_elements.csv",
            &reported.element_xy,
            &reported.elements,
        ),
    ] {
        let p = st.path(file);
        write_points(&p, xy, fields, &env.names, env.system)?;
    }
    st.commit()
}

/// Plan-view maps of the envelope (SI scenes): the largest pressure with the bearing limit,
/// voids, zones and line loads, the largest deflection, and the extreme moments.
fn stage_envelope_maps(st: &mut Staged, c: &Combinations, env: &Envelope) -> Result<()> {
    use super::chart::{self, MapValues, Overlay, Units};
    let Some((run, o)) = c
        .runs
        .iter()
        .find_map(|r| r.outcome.as_ref().ok().map(|o| (r, o)))
    else {
        return Ok(());
    };
    let Some(physical) = run.model.physical else {
        // Each combination of a dimensionless scene has its own P: the CSV files carry the
        // envelope in the scene's force unit, the maps would mislabel it.
        return Ok(());
    };
    let units = Units::new(Some(physical), run.model.groups.mu);
    let overlay = Overlay::for_model(&run.model, &o.report);
    let title = crate::scene::scene_title(&run.model.title, &run.name);
    let field = &o.report.field;
    let pick = |fields: &[(&'static str, &'static str, PointEnvelope)], name: &str| {
        fields
            .iter()
            .find(|(n, _, _)| *n == name)
            .map(|(_, _, e)| e.clone())
    };
    let mut maps: Vec<(String, String, Vec<f64>, chart::Scale, bool)> = Vec::new();
    if let Some(e) = pick(&env.nodes, "pressure") {
        maps.push((
            "pressure-max".into(),
            "largest pressure".into(),
            e.max,
            units.pressure(),
            true,
        ));
    }
    if let Some(e) = pick(&env.nodes, "w") {
        maps.push((
            "w-max".into(),
            "largest deflection".into(),
            e.max,
            units.deflection(),
            false,
        ));
    }
    for m in ["mx", "my"] {
        if let Some(e) = pick(&env.elements, m) {
            maps.push((
                format!("{m}-max"),
                format!("largest {m}"),
                e.max,
                units.moment(),
                false,
            ));
            maps.push((
                format!("{m}-min"),
                format!("smallest {m}"),
                e.min,
                units.moment(),
                false,
            ));
        }
    }
    // The design stresses: the largest tension at the bottom and at the top over every
    // combination.
    for (m, face) in [("s1_bottom", "bottom"), ("s1_top", "top")] {
        if let Some(e) = pick(&env.elements, m) {
            maps.push((
                format!("stress-{face}-max"),
                format!("largest principal stress at the {face}"),
                e.max,
                units.stress(),
                false,
            ));
        }
    }
    for (file, what, values, scale, with_limit) in maps {
        let svg = st.path(&format!("envelope-{file}.svg"));
        let png = st.path(&format!("envelope-{file}.png"));
        let overlay = if with_limit {
            overlay.clone()
        } else {
            Overlay {
                allowable_pressure: None,
                ..overlay.clone()
            }
        };
        chart::write_field_map(
            &svg,
            &png,
            field,
            &MapValues {
                values: &values,
                name: &what,
                scale,
            },
            &format!(
                "{title} — envelope of {} combinations: {what}",
                env.names.len()
            ),
            &units,
            &overlay,
        )?;
    }
    Ok(())
}

/// Per point: x, y, and for each field its max, min and the governing combinations.
fn write_points(
    p: &Path,
    xy: &[(f64, f64)],
    fields: &[(&'static str, &'static str, PointEnvelope)],
    names: &[String],
    system: Option<crate::units::UnitSystem>,
) -> Result<()> {
    let mut w = csv::Writer::from_path(p).map_err(csv_err(p))?;
    let length = crate::units::Measure::Length.unit(system);
    let mut header = vec![format!("x [{length}]"), format!("y [{length}]")];
    for (n, u, _) in fields {
        header.push(format!("{n}_max [{u}]"));
        header.push(format!("{n}_max_by"));
        header.push(format!("{n}_min [{u}]"));
        header.push(format!("{n}_min_by"));
    }
    w.write_record(&header).map_err(csv_err(p))?;
    for (i, &(x, y)) in xy.iter().enumerate() {
        // Rows only on the plate: off a shaped plate every envelope is NaN.
        if fields.first().is_some_and(|(_, _, e)| e.max[i].is_nan()) {
            continue;
        }
        let mut row = vec![format!("{x}"), format!("{y}")];
        for (_, _, e) in fields {
            row.push(format!("{:e}", e.max[i]));
            row.push(names[e.max_by[i]].clone());
            row.push(format!("{:e}", e.min[i]));
            row.push(names[e.min_by[i]].clone());
        }
        w.write_record(&row).map_err(csv_err(p))?;
    }
    w.flush().map_err(|e| Error::Io {
        path: p.display().to_string(),
        source: e,
    })
}

/// The bending moment of largest magnitude (mx or my), with its sign.
fn extreme_moment(s: &crate::summary::Summary) -> f64 {
    [
        s.moments.mx[0],
        s.moments.mx[1],
        s.moments.my[0],
        s.moments.my[1],
    ]
    .into_iter()
    .fold(0.0, |m: f64, v| if v.abs() > m.abs() { v } else { m })
}

/// The CLI's table: a line per combination, then the governing extremes.
pub fn combinations_table(title: &str, c: &Combinations, files: Option<(usize, &Path)>) -> String {
    let mut s = String::new();
    let physical = c.runs.first().is_some_and(|r| r.model.physical.is_some());
    let _ = writeln!(s, "liftoff — {title}: {} load combinations", c.runs.len());
    let _ = writeln!(
        s,
        "  operators assembled once in {:.3} s; combinations solved {} at a time; total {:.3} s",
        c.assemble_s,
        rayon::current_num_threads(),
        c.total_s
    );
    let (wu, pu, mu_) = if physical {
        ("w_max mm", "p_max kPa", "|m|max kN·m/m")
    } else {
        ("V_max", "σ_max", "|m|max P")
    };
    let _ = writeln!(
        s,
        "  {:<16} {:<12} {:>7} {:>10} {:>10} {:>12} {:>8} {:>9}  factors",
        "combination", "status", "time s", wu, pu, mu_, "contact", "bearing"
    );
    for r in &c.runs {
        let factors: Vec<String> = r.factors.iter().map(|(k, v)| format!("{v}×{k}")).collect();
        match &r.outcome {
            Ok(o) if !o.summary.converged => {
                // No result lines for a solve that did not converge: its last iterate is not
                // a solution.
                let _ = writeln!(
                    s,
                    "  {:<16} {:<12} {:>7.3}  (no result: {})",
                    r.name, "NOT CONVERGED", r.seconds, o.summary.status
                );
            }
            Ok(o) => {
                let sm = &o.summary;
                let (w, p, m) = if physical {
                    (
                        sm.w_max * 1e3,
                        sm.pressure_max / 1e3,
                        extreme_moment(sm) / 1e3,
                    )
                } else {
                    (
                        sm.V_max,
                        sm.pressure_max * sm.dimensionless.mu,
                        extreme_moment(sm),
                    )
                };
                let bearing = sm.bearing.map_or("—".to_string(), |b| {
                    format!("{:.0} %", 100.0 * b.utilisation)
                });
                let status = "converged";
                let _ = writeln!(
                    s,
                    "  {:<16} {:<12} {:>7.3} {:>10.4} {:>10.2} {:>12.3} {:>7.1}% {:>9}  {}",
                    r.name,
                    status,
                    r.seconds,
                    w,
                    p,
                    m,
                    100.0 * sm.contact_fraction,
                    bearing,
                    factors.join(" + ")
                );
            }
            Err(e) => {
                let _ = writeln!(s, "  {:<16} FAILED: {e}", r.name);
            }
        }
    }
    let missing = c.missing();
    if !missing.is_empty() {
        let _ = writeln!(
            s,
            "  envelope   : not built: {} without a solution",
            missing.join(", ")
        );
    }
    if let Some(env) = &c.envelope {
        let _ = writeln!(s, "  envelope (value, where, governing combination):");
        for q in &env.quantities {
            // The table reads in engineering units; the files keep SI.
            let stress = q.quantity.starts_with("s1_");
            let (factor, unit) = match q.unit {
                "Pa" if stress => (1e-6, "MPa"),
                "m" => (1e3, "mm"),
                "Pa" => (1e-3, "kPa"),
                "N·m/m" => (1e-3, "kN·m/m"),
                "N/m" => (1e-3, "kN/m"),
                u => (1.0, u),
            };
            let at = |e: &crate::combination::Extreme| {
                format!(
                    "{:>10.3} at ({:>6.2}, {:>6.2}) {:<14}",
                    e.value * factor,
                    e.x,
                    e.y,
                    e.combination
                )
            };
            let line = format!(
                "    {:<9} {:<7} max {} min {}",
                q.quantity,
                unit,
                at(&q.max),
                at(&q.min)
            );
            let _ = writeln!(s, "{}", line.trim_end());
        }
    }
    if let Some((n, dir)) = files {
        let _ = writeln!(
            s,
            "  files      : {n} in {} (a folder per combination, envelope.json/.csv)",
            dir.display()
        );
    }
    s
}
