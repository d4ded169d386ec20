//! The sections of `liftoff damage`'s and `liftoff design`'s files: the governing damage of
//! each face and where, the cracking, whether the sums are complete, the passes that weigh
//! most, the damage maps; the design curve's table and chart.

use std::fmt::Write as _;

use serde_json::Value;

use super::page::{at, esc, num, table, text, Listing, Part, Section};
use crate::error::Result;

/// The files that mark a damage run's or a design's output, for the error that finds none.
pub(crate) const MARKS: &str = "damage.json (liftoff damage), or design.json (liftoff design)";

/// The scene's unit of length in a damage.json or design.json (`units`: "si", "us" or null).
fn length_unit(v: &Value) -> &'static str {
    match v.get("units").and_then(Value::as_str) {
        Some("us") => "in",
        Some(_) => "m",
        None => "L",
    }
}

/// Read a damage run's and a design's output in the directory: None when it holds neither.
pub(crate) fn read(l: &mut Listing) -> Result<Option<Part>> {
    let mut sections = Vec::new();
    let mut title = String::new();
    if l.has("damage.json") {
        let v = l.json("damage.json")?;
        let unit = length_unit(&v);
        title = format!("Fatigue damage ({})", text(v.get("model")));
        let mut html = String::new();
        let complete = v.get("complete").and_then(Value::as_bool).unwrap_or(false);
        if !complete {
            let missing: Vec<String> = v
                .get("missing")
                .and_then(Value::as_array)
                .map(|m| m.iter().map(|x| esc(x.as_str().unwrap_or(""))).collect())
                .unwrap_or_default();
            let _ = writeln!(
                html,
                "<p class=\"warning\"><strong>Incomplete:</strong> {} pass(es) did not converge and are not in the sums: {}.</p>",
                missing.len(),
                missing.join("; ")
            );
        }
        let _ = writeln!(
            html,
            "<p>{} passes, {} solves; relation <code>{}</code>, modulus of rupture {} {}{}; repetitions over the life {} × the first year's.</p>",
            v.get("passes").and_then(Value::as_array).map_or(0, Vec::len),
            text(v.get("solves")),
            text(v.get("model")),
            text(v.get("rupture")),
            if unit == "in" { "psi" } else { "Pa" },
            match v
                .get("rupture_ratio")
                .and_then(Value::as_array)
                .map(|r| r.iter().filter_map(Value::as_f64).collect::<Vec<_>>())
            {
                Some(r) if r.len() == 2 => format!(
                    " at 28 days, growing × {} … {} over the life (MEPDG)",
                    num(r[0]),
                    num(r[1])
                ),
                _ => String::new(),
            },
            text(v.get("life_factor")),
        );
        let mut rows = Vec::new();
        for (key, what) in [
            ("governing_bottom", "bottom-up"),
            ("governing_top", "top-down"),
        ] {
            let g = v.get(key);
            let f = |k: &str| g.and_then(|g| g.get(k)).and_then(Value::as_f64);
            // No damage anywhere: no place governs.
            let none = f("damage").is_some_and(|d| d <= 0.0);
            rows.push(vec![
                what.to_string(),
                f("damage").map_or("—".into(), num),
                if none {
                    "none: no pass damages this face".to_string()
                } else {
                    format!(
                        "({}, {})\u{202F}{unit}",
                        f("x").map_or("—".into(), num),
                        f("y").map_or("—".into(), num)
                    )
                },
            ]);
        }
        // The PCA's erosion at the corners: the governing one, the note where none is summed.
        if let Some(e) = v.get("erosion").filter(|e| !e.is_null()) {
            let g = e
                .get("governing")
                .and_then(Value::as_u64)
                .and_then(|i| e.get("corners")?.get(usize::try_from(i).ok()?));
            let f = |k: &str| g.and_then(|g| g.get(k)).and_then(Value::as_f64);
            rows.push(vec![
                "erosion (PCA, C2 Σ n/N)".to_string(),
                f("damage").map_or("—".into(), num),
                format!(
                    "corner ({}, {})\u{202F}{unit} of panel {}",
                    f("x").map_or("—".into(), num),
                    f("y").map_or("—".into(), num),
                    esc(g
                        .and_then(|g| g.get("panel"))
                        .and_then(Value::as_str)
                        .unwrap_or("—"))
                ),
            ]);
        }
        html.push_str(&table(&["damage", "Σ n/N", "at the element"], &rows));
        if let Some(note) = v.get("erosion_note").and_then(Value::as_str) {
            let _ = writeln!(html, "<p>Erosion (PCA) not summed: {}.</p>", esc(note));
        }
        // The end panels of a lane the model cuts (`[traffic] ends`): mapped, not counted.
        let cut = v
            .get("counted")
            .and_then(Value::as_array)
            .is_some_and(|c| c.iter().any(|b| b.as_bool() == Some(false)));
        if cut {
            html.push_str(
                "<p>The end panels, where the model cuts a lane that goes on, are mapped but not counted: the governing places, the passes' peaks and the cracking are those between the first and the last transverse joint (<code>[plate] ends = \"free\"</code> counts them; damage.csv's <code>counted</code>).</p>\n",
            );
        }
        if let Some(c) = v.get("cracking").filter(|c| !c.is_null()) {
            let _ = writeln!(
                html,
                "<p>Cracking (MEPDG): bottom-up {} %, top-down {} %, total {} % of slabs{}.</p>",
                text(c.get("bottom")),
                text(c.get("top")),
                text(c.get("total")),
                match at(c, "at_reliability").and_then(Value::as_f64) {
                    Some(r) => format!(", {} % at the reliability asked", num(r)),
                    None => String::new(),
                }
            );
        }
        // The passes that weigh most at the governing bottom element.
        let mut passes: Vec<&Value> = v
            .get("passes")
            .and_then(Value::as_array)
            .map(|p| p.iter().collect())
            .unwrap_or_default();
        let share = |p: &Value| p.get("bottom_share").and_then(Value::as_f64).unwrap_or(0.0);
        passes.sort_by(|a, b| share(b).total_cmp(&share(a)));
        let rows: Vec<Vec<String>> = passes
            .iter()
            .take(10)
            .map(|p| {
                vec![
                    esc(p.get("group").and_then(Value::as_str).unwrap_or("")),
                    text(p.get("load")),
                    text(p.get("offset")),
                    text(p.get("difference")),
                    text(p.get("repetitions")),
                    text(at(p, "bottom.stress")),
                    num(share(p)),
                    text(p.get("outcome")),
                ]
            })
            .collect();
        let _ = writeln!(
            html,
            "<p>The passes that weigh most at the governing bottom-up element (of {}; every pass is in {}):</p>",
            passes.len(),
            l.file_ref("passes.csv")
        );
        let us = unit == "in";
        let (force, stress, kelvin) = if us {
            ("lbf", "psi", "°F")
        } else {
            ("N", "Pa", "K")
        };
        html.push_str(&table(
            &[
                "group",
                &format!("load ({force})"),
                &format!("offset ({unit})"),
                &format!("ΔT ({kelvin})"),
                "passes",
                &format!("largest σ₁ bottom ({stress})"),
                "share of Σ n/N",
                "outcome",
            ],
            &rows,
        ));
        let _ = writeln!(
            html,
            "<p class=\"note\">Values as damage.json holds them, in the scene's units. The damage at every element is in {} (not shown).</p>",
            l.file_ref("damage.csv")
        );
        l.note("damage.json", "the damage section");
        sections.push(Section {
            id: "damage".into(),
            heading: "Fatigue damage".into(),
            html,
        });
        let mut figures = String::new();
        for (rel, caption) in [
            (
                "damage-bottom.svg",
                "bottom-up fatigue damage Σ n/N at every element",
            ),
            (
                "damage-top.svg",
                "top-down fatigue damage Σ n/N at every element",
            ),
            (
                "erosion.svg",
                "the PCA's erosion damage C2 Σ n/N at the panels' corners (each quarter of a panel shows its corner)",
            ),
        ] {
            if l.has(rel) {
                figures.push_str(&l.figure(rel, caption)?);
            }
        }
        if !figures.is_empty() {
            sections.push(Section {
                id: "damage-maps".into(),
                heading: "Damage maps".into(),
                html: figures,
            });
        }
    }
    if l.has("design.json") {
        let v = l.json("design.json")?;
        let unit = length_unit(&v);
        if title.is_empty() {
            title = format!("Thickness design ({})", text(v.get("model")));
        }
        let mut html = String::new();
        let _ = writeln!(
            html,
            "<p>Target: {} ≤ {}. {}</p>",
            text(v.get("measure")),
            text(v.get("target")),
            match v.get("thickness").and_then(Value::as_f64) {
                Some(h) => format!(
                    "Least thickness found: <strong>{}\u{202F}{unit}</strong>.",
                    num(h)
                ),
                None => "No thickness in the range meets the target.".into(),
            }
        );
        if v.get("cut").and_then(Value::as_bool) == Some(true) {
            html.push_str(
                "<p>The end panels, where the model cuts a lane that goes on, are not counted in these runs (<code>[plate] ends = \"free\"</code> counts them).</p>\n",
            );
        }
        let rows: Vec<Vec<String>> = v
            .get("points")
            .and_then(Value::as_array)
            .map(|p| {
                p.iter()
                    .map(|p| {
                        vec![
                            text(p.get("thickness")),
                            text(p.get("bottom")),
                            text(p.get("top")),
                            text(p.get("value")),
                            text(p.get("passes")),
                            text(p.get("curve")),
                        ]
                    })
                    .collect()
            })
            .unwrap_or_default();
        html.push_str(&table(
            &[
                &format!("thickness ({unit})"),
                "bottom Σ n/N",
                "top Σ n/N",
                "compared",
                "meets",
                "on the curve",
            ],
            &rows,
        ));
        l.note("design.json", "the design section");
        if l.has("design.svg") {
            html.push_str(&l.figure("design.svg", "the design curve")?);
        }
        sections.push(Section {
            id: "design".into(),
            heading: "Thickness design".into(),
            html,
        });
    }
    if sections.is_empty() {
        return Ok(None);
    }
    Ok(Some(Part { title, sections }))
}
