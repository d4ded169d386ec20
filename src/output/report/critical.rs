//! The section of `liftoff critical`'s files: the search (load, combination, grid, times), the
//! critical positions with their values, and the influence maps.

use std::fmt::Write as _;

use serde_json::Value;

use super::page::{at, esc, num, text, with_unit, Kind, Listing, Part, Section, Shown};
use crate::error::Result;
use crate::output::chart::Units;

/// The file that marks a search's output, for the error that finds none.
pub(crate) const MARKS: &str = "critical.json (liftoff critical)";

/// The critical positions critical.json names: (its key, what, the position's value, its kind,
/// where the value's peak is, if the position says).
const CRITICAL: &[(&str, &str, &str, Kind, Option<&str>)] = &[
    (
        "bottom",
        "bottom tension σ₁",
        "bottom",
        Kind::Stress,
        Some("bottom_at"),
    ),
    ("top", "top tension σ₁", "top", Kind::Stress, Some("top_at")),
    ("deflection", "deflection", "w_max", Kind::Deflection, None),
    (
        "joint_shear",
        "joint shear per length",
        "joint_shear",
        Kind::Shear,
        None,
    ),
    (
        "dowel_force",
        "dowel force",
        "dowel_force",
        Kind::Force,
        None,
    ),
    // A lane cut at its ends: the end panels' tensions, which the rows above do not read.
    (
        "end_bottom",
        "end panels' bottom σ₁ (not read)",
        "end_bottom",
        Kind::Stress,
        None,
    ),
    (
        "end_top",
        "end panels' top σ₁ (not read)",
        "end_top",
        Kind::Stress,
        None,
    ),
];

/// Read a search's output in the directory: None when it holds none.
pub(crate) fn read(l: &mut Listing) -> Result<Option<Part>> {
    if !l.has("critical.json") {
        return Ok(None);
    }
    let v = l.json("critical.json")?;
    let load = at(&v, "load").and_then(Value::as_str).unwrap_or("?");
    let title = match at(&v, "title").and_then(Value::as_str) {
        Some(t) => t.to_string(),
        None => format!("Critical positions of the load {load}"),
    };
    // critical.json holds its values in the scene's system (`units`: "si" — Pa, m, N/m, N —
    // or "us" — psi, in, lbf/in, lbf).
    let system = v
        .get("units")
        .and_then(Value::as_str)
        .and_then(<crate::units::UnitSystem as crate::choice::Choice>::from_name)
        .unwrap_or_default();
    let units = Units::of_si(system);
    let shown = Shown {
        units,
        map: v.get("units").and_then(Value::as_object),
    };
    let positions = v
        .get("positions")
        .and_then(Value::as_array)
        .cloned()
        .unwrap_or_default();
    let converged = positions
        .iter()
        .filter(|p| p.get("outcome").and_then(Value::as_str) == Some("converged"))
        .count();
    let mut html = String::new();
    let held = esc(Kind::Length.held(&shown.units));
    let _ = writeln!(
        html,
        "<p>The load <code>{}</code>{} moved over {} positions ({} converged) on a plate of {} {held}; grid spacing {} {held}; operators assembled once in {} s, the whole search {} s.</p>",
        esc(load),
        match at(&v, "combination").and_then(Value::as_str) {
            Some(c) => format!(" in the combination <code>{}</code> (the rest of its loads present)", esc(c)),
            None => String::new(),
        },
        positions.len(),
        converged,
        text(v.get("plate")),
        text(v.get("spacing")),
        text(v.get("assemble_s")),
        text(v.get("total_s")),
    );
    let length = Kind::Length.scale(&shown.units);
    let pair = |p: Option<&Value>| match p.and_then(Value::as_array).map(Vec::as_slice) {
        Some([x, y]) => with_unit(
            &format!(
                "({}, {})",
                num(length.apply(x.as_f64().unwrap_or(f64::NAN))),
                num(length.apply(y.as_f64().unwrap_or(f64::NAN)))
            ),
            length.unit,
        ),
        _ => String::new(),
    };
    html.push_str("<div class=\"scroll\"><table class=\"numbers\">\n<thead><tr><th>largest</th><th>value</th><th>where</th><th>load at (x, y)</th><th>heading</th><th>position</th><th>in critical.json</th></tr></thead>\n<tbody>\n");
    for (key, what, value_key, kind, peak) in CRITICAL {
        // A key absent: the plate has no joint of that kind.
        let Some(index) = v.get(*key) else {
            continue;
        };
        let Some(p) = index.as_u64().and_then(|i| positions.get(i as usize)) else {
            let _ = writeln!(
                html,
                "<tr data-key=\"{key}\"><td>{}</td><td colspan=\"6\">no position converged</td></tr>",
                esc(what)
            );
            continue;
        };
        let Some(x) = p.get(*value_key).and_then(Value::as_f64) else {
            continue;
        };
        let path = format!("positions.{index}.{value_key}");
        let (shown_value, held) = shown.value(value_key, *kind, x);
        let load_at = pair(Some(&Value::Array(vec![
            p.get("x").cloned().unwrap_or(Value::Null),
            p.get("y").cloned().unwrap_or(Value::Null),
        ])));
        let _ = writeln!(
            html,
            "<tr data-key=\"critical.{key}\" data-value=\"{}\"><td>{}</td><td class=\"value\">{shown_value}</td><td>{}</td><td>{load_at}</td><td>{}°</td><td>{index}</td><td class=\"stored\"><code>{}</code> = {held}</td></tr>",
            esc(&p[*value_key].to_string()),
            esc(what),
            peak.map_or(String::new(), |k| pair(p.get(k))),
            text(p.get("heading")),
            esc(&path),
        );
    }
    html.push_str("</tbody>\n</table></div>\n");
    if let Some([lo, hi]) = v
        .get("read_x")
        .and_then(Value::as_array)
        .map(|a| a.iter().filter_map(Value::as_f64).collect::<Vec<f64>>())
        .and_then(|a| <[f64; 2]>::try_from(a).ok())
    {
        let _ = writeln!(
            html,
            "<p class=\"note\" data-key=\"read_x\">Every position is read between the transverse joints at x = {} and {}: the model cuts a lane that goes on, and its end panels are the inner ones' neighbours, their free ends no pavement's (<code>--ends free</code> reads them too).</p>",
            with_unit(&num(length.apply(lo)), length.unit),
            with_unit(&num(length.apply(hi)), length.unit),
        );
    }
    let _ = writeln!(
        html,
        "<p class=\"note\">Load at: the reference point of the axle or gear. From {}.</p>",
        l.file_ref("critical.json")
    );
    l.note("critical.json", "the critical positions table");
    if l.has("critical.csv") {
        let n = l.csv_rows("critical.csv")?;
        let _ = writeln!(
            html,
            "<p class=\"note\">Every position ({n}) with its outcome, both faces' largest σ₁ and where, w<sub>max</sub>, contact and the joints' values is in {} (not shown).</p>",
            l.file_ref("critical.csv")
        );
    }
    let mut sections = vec![Section {
        id: "critical".into(),
        heading: "Critical positions".into(),
        html,
    }];
    let mut figures = String::new();
    let first = [
        "influence-bottom.svg",
        "influence-top.svg",
        "influence-deflection.svg",
    ];
    for rel in l.ordered("", &first, |n| n.starts_with("influence-")) {
        let caption = match rel.as_str() {
            "influence-bottom.svg" => "bottom tension with the load standing at each point",
            "influence-top.svg" => "top tension with the load standing at each point",
            "influence-deflection.svg" => "deflection with the load standing at each point",
            _ => "",
        };
        figures.push_str(&l.figure(&rel, caption)?);
    }
    if !figures.is_empty() {
        sections.push(Section {
            id: "influence".into(),
            heading: "Influence maps".into(),
            html: figures,
        });
    }
    Ok(Some(Part { title, sections }))
}
