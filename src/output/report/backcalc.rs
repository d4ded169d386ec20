//! The sections of `liftoff backcalc`'s files: the survey's method and completeness, the table
//! of drops (backcalc.csv, the moduli with their 95 % intervals, the load transfer, the misfit),
//! the intercept method's lines (intercepts.csv), and the basins, moduli and load-transfer
//! charts.

use std::fmt::Write as _;

use serde_json::Value;

use super::page::{esc, text, Listing, Part, Section};
use crate::error::Result;

/// The files that mark a backcalculation's output.
pub(crate) const MARKS: &str = "backcalc.json (liftoff backcalc)";

/// The drops a report shows as a table; a larger survey is left to backcalc.csv.
const MAX_ROWS: usize = 200;

/// Read a backcalculation's output in the directory: None when it holds none.
pub(crate) fn read(l: &mut Listing) -> Result<Option<Part>> {
    if !l.has("backcalc.json") {
        return Ok(None);
    }
    let v = l.json("backcalc.json")?;
    let mut html = String::new();
    let drops = v.get("drops").and_then(Value::as_array).map_or(0, Vec::len);
    if !v.get("complete").and_then(Value::as_bool).unwrap_or(false) {
        let missing: Vec<String> = v
            .get("not_converged")
            .and_then(Value::as_array)
            .map(|m| m.iter().map(|x| esc(x.as_str().unwrap_or(""))).collect())
            .unwrap_or_default();
        let _ = writeln!(
            html,
            "<p class=\"warning\"><strong>Incomplete:</strong> {} fit(s) did not converge; their rows show the best point reached, not a result: {}.</p>",
            missing.len(),
            missing.join("; ")
        );
    }
    let _ = writeln!(
        html,
        "<p>{drops} drop(s) by <code>{}</code> ({} seating drop(s) discarded), {} solves in {} s; the static k is the dynamic one × {}.</p>",
        text(v.get("method")),
        text(v.get("discarded")),
        text(v.get("solves")),
        text(v.get("seconds")),
        text(v.get("static_k_factor")),
    );
    match l.csv_table("backcalc.csv", MAX_ROWS)? {
        Some(t) => html.push_str(&t),
        None => {
            let _ = writeln!(
                html,
                "<p>More than {MAX_ROWS} drops: the table is in {}.</p>",
                l.file_ref("backcalc.csv")
            );
        }
    }
    l.note("backcalc.csv", "the drops' table");
    l.note("backcalc.json", "the backcalculation section");
    if l.has("intercepts.csv") {
        let _ = writeln!(
            html,
            "<p>The intercept method (voids): the deflection under the plate against the load at each station with several loads; a void is flagged above {} m.</p>",
            text(v.get("void_threshold"))
        );
        if let Some(t) = l.csv_table("intercepts.csv", MAX_ROWS)? {
            html.push_str(&t);
        }
        l.note("intercepts.csv", "the intercepts' table");
    }
    let _ = writeln!(
        html,
        "<p class=\"note\">Values as backcalc.csv holds them, in the template's units; every sensor's measured and fitted deflection is in {} (not shown).</p>",
        l.file_ref("basins.csv")
    );
    let mut sections = vec![Section {
        id: "backcalc".into(),
        heading: "Backcalculation".into(),
        html,
    }];
    let mut figures = String::new();
    for (rel, caption) in [
        ("basins.svg", "measured and fitted deflection basins"),
        ("moduli.svg", "the backcalculated moduli along the survey"),
        ("lte.svg", "the load transfer of the joint drops"),
    ] {
        if l.has(rel) {
            figures.push_str(&l.figure(rel, caption)?);
        }
    }
    if !figures.is_empty() {
        sections.push(Section {
            id: "backcalc-charts".into(),
            heading: "Basins and moduli".into(),
            html: figures,
        });
    }
    Ok(Some(Part {
        title: "Backcalculation from deflection basins".into(),
        sections,
    }))
}
