//! The sections of `liftoff solve`'s files: summary.json's key numbers, the joints (summary.json's
//! `joints`, dowels.csv) and the charts; a run over combinations — `envelope.json` and a folder
//! per combination — gives the combinations, the envelope's extremes and charts, then each
//! combination's own sections.

use std::fmt::Write as _;

use serde_json::Value;

use super::page::{
    at, esc, num, numbers_table, pairs, table, text, with_unit, Kind, Listing, Part, Section, Shown,
};
use crate::error::Result;
use crate::output::chart::Units;

/// The files that mark a solve's output, for the error that finds none.
pub(crate) const MARKS: &str = "summary.json (liftoff solve), or envelope.json with a folder per combination (a scene with [[combination]]s)";

/// Dowel tables longer than this are linked, not shown.
const MAX_DOWELS: usize = 200;

/// The key numbers of summary.json: (path, label, kind).
const NUMBERS: &[(&str, &str, Kind)] = &[
    ("w_max", "largest deflection (downward)", Kind::Deflection),
    ("V_max", "largest V = D w / (P L²)", Kind::Plain),
    (
        "pressure_max",
        "largest contact pressure (nodal)",
        Kind::Pressure,
    ),
    (
        "stresses.bottom.value",
        "largest principal stress σ₁, bottom face",
        Kind::Stress,
    ),
    (
        "stresses.top.value",
        "largest principal stress σ₁, top face",
        Kind::Stress,
    ),
    ("moments.mx.0", "smallest moment mx", Kind::Moment),
    ("moments.mx.1", "largest moment mx", Kind::Moment),
    ("moments.my.0", "smallest moment my", Kind::Moment),
    ("moments.my.1", "largest moment my", Kind::Moment),
    (
        "contact_fraction",
        "contact area / plate area",
        Kind::Fraction,
    ),
    (
        "bearing.average",
        "bearing check: largest average pressure",
        Kind::Pressure,
    ),
    (
        "bearing.allowable",
        "bearing check: allowable pressure",
        Kind::Pressure,
    ),
    (
        "bearing.utilisation",
        "bearing check: utilisation",
        Kind::Plain,
    ),
    ("resultant.load", "load resultant", Kind::Force),
    ("resultant.reaction", "reaction resultant", Kind::Force),
    (
        "resultant.relative_error",
        "equilibrium error (relative)",
        Kind::Plain,
    ),
    (
        "dimensionless.gamma",
        "Γ (foundation to plate stiffness)",
        Kind::Plain,
    ),
    ("stresses.thickness", "plate thickness", Kind::Length),
];

/// The words of summary.json about how it was solved: (path, label).
const MODEL: &[(&str, &str)] = &[
    ("status", "status"),
    ("contact", "contact"),
    ("foundation", "foundation"),
    ("method", "method"),
    ("qp_solver", "QP solver"),
    ("constraint", "constraint points"),
    ("symmetry", "model"),
    ("elements", "elements (whole plate)"),
    ("nodes", "nodes (solved model)"),
    ("dofs", "equations"),
    ("iterations", "iterations"),
    ("time_s.total", "time, s"),
];

/// Captions of the charts a solve writes, by file name.
fn caption(name: &str) -> &'static str {
    match name {
        "contact.svg" => "contact pressure and the contact boundary",
        "stress-bottom.svg" => "largest principal stress at the bottom face",
        "profiles.svg" => "deflection and pressure along the plate's axes, edges and diagonal",
        "envelope-pressure-max.svg" => "envelope: largest contact pressure",
        "envelope-w-max.svg" => "envelope: largest deflection",
        "envelope-stress-bottom-max.svg" => "envelope: largest principal stress at the bottom",
        "envelope-stress-top-max.svg" => "envelope: largest principal stress at the top",
        "envelope-mx-max.svg" => "envelope: largest moment mx",
        "envelope-mx-min.svg" => "envelope: smallest moment mx",
        "envelope-my-max.svg" => "envelope: largest moment my",
        "envelope-my-min.svg" => "envelope: smallest moment my",
        _ => "",
    }
}

/// The charts of a solve in `folder`, the designer's first: contact, stress, profiles, then
/// the rest of the folder's solve charts in name order.
fn charts(l: &mut Listing, folder: &str) -> Result<String> {
    // Other charts of a solve (a future one), but not another command's (influence maps).
    let names = l.ordered(
        folder,
        &["contact.svg", "stress-bottom.svg", "profiles.svg"],
        |n| !n.starts_with("influence-") && !n.starts_with("envelope-"),
    );
    let mut s = String::new();
    for rel in names {
        let name = rel.rsplit('/').next().unwrap_or(&rel).to_string();
        s.push_str(&l.figure(&rel, caption(&name))?);
    }
    Ok(s)
}

/// Read a solve's output in the directory: None when it holds none.
pub(crate) fn read(l: &mut Listing) -> Result<Option<Part>> {
    if l.has("summary.json") {
        let v = l.json("summary.json")?;
        let title = at(&v, "title")
            .and_then(Value::as_str)
            .unwrap_or("liftoff solve");
        let sections = solve_sections(l, "", &v, "solve", "")?;
        return Ok(Some(Part {
            title: title.to_string(),
            sections,
        }));
    }
    let folders = l.folders_with("summary.json");
    if !l.has("envelope.json") && folders.is_empty() {
        return Ok(None);
    }
    combinations(l, folders).map(Some)
}

/// The sections of one solve whose files are in `folder` ("" or "NAME/"): its summary, its
/// joints, its charts. `id` and `name` make the anchors and headings unique per combination.
fn solve_sections(
    l: &mut Listing,
    folder: &str,
    v: &Value,
    id: &str,
    name: &str,
) -> Result<Vec<Section>> {
    let summary = format!("{folder}summary.json");
    let shown = Shown::of_summary(v);
    let heading = |what: &str| {
        if name.is_empty() {
            what.to_string()
        } else {
            format!("{name}: {what}")
        }
    };
    let mut html = String::new();
    let model: Vec<(String, String)> = MODEL
        .iter()
        .filter_map(|(path, label)| at(v, path).map(|x| (esc(label), text(Some(x)))))
        .collect();
    html.push_str(&pairs(&model));
    let wheres = |path: &str| {
        let face = path.strip_suffix(".value")?;
        let p = at(v, face)?;
        Some((p.get("x")?.as_f64()?, p.get("y")?.as_f64()?))
    };
    html.push_str(&numbers_table(v, &shown, NUMBERS, &wheres, &summary));
    if let Some(notes) = v.get("notes").and_then(Value::as_array) {
        if !notes.is_empty() {
            html.push_str("<p class=\"note\">Notes:</p>\n<ul class=\"note\">\n");
            for n in notes {
                let _ = writeln!(html, "<li>{}</li>", text(Some(n)));
            }
            html.push_str("</ul>\n");
        }
    }
    let units = if shown.units.is_physical() {
        "Values in the scene's engineering units; summary.json holds them in SI units (m, Pa, N·m/m, N)."
    } else {
        "A dimensionless scene: V, σ and lengths in the units of P and L, as the paper's."
    };
    let _ = writeln!(
        html,
        "<p class=\"note\">{} From {}.</p>",
        esc(units),
        l.file_ref(&summary)
    );
    l.note(&summary, "the summary tables");
    let mut sections = vec![Section {
        id: format!("{id}-summary"),
        heading: heading("Summary"),
        html,
    }];
    if let Some(joints) = joints(l, folder, v, &shown)? {
        sections.push(Section {
            id: format!("{id}-joints"),
            heading: heading("Joints"),
            html: joints,
        });
    }
    let figures = charts(l, folder)?;
    if !figures.is_empty() {
        sections.push(Section {
            id: format!("{id}-charts"),
            heading: heading("Charts"),
            html: figures,
        });
    }
    Ok(sections)
}

/// The joints of a jointed plate: summary.json's per-joint numbers and dowels.csv's bars (None
/// for a plate without joints).
fn joints(l: &mut Listing, folder: &str, v: &Value, shown: &Shown) -> Result<Option<String>> {
    let Some(joints) = v.get("joints").and_then(Value::as_array) else {
        return Ok(None);
    };
    let u = &shown.units;
    let column = |what: &str, kind: Kind| {
        let unit = kind.scale(u).unit;
        if unit.is_empty() {
            esc(what)
        } else {
            format!("{} ({})", esc(what), esc(unit))
        }
    };
    let cols: [(&str, &str, Kind); 9] = [
        ("line", "line", Kind::Length),
        ("lte_deflection", "LTE, deflection", Kind::Plain),
        ("lte_stress", "LTE, stress", Kind::Plain),
        ("transferred_force", "force transferred", Kind::Force),
        ("max_shear_per_length", "largest shear", Kind::Shear),
        ("max_moment_per_length", "largest moment", Kind::Moment),
        ("max_dowel_force", "largest dowel force", Kind::Force),
        ("max_bearing_stress", "largest bearing stress", Kind::Stress),
        ("at", "LTE read at", Kind::Length),
    ];
    // A column no joint of this plate has a value in (a moment without tied joints) goes.
    let cols: Vec<(&str, &str, Kind)> = cols
        .into_iter()
        .filter(|(key, _, _)| {
            joints
                .iter()
                .any(|j| j.get(*key).is_some_and(|x| !x.is_null()))
        })
        .collect();
    let mut head = vec!["joint".to_string(), "kind".into(), "loaded side".into()];
    head.extend(cols.iter().map(|(_, what, kind)| column(what, *kind)));
    let head: Vec<&str> = head.iter().map(String::as_str).collect();
    let rows: Vec<Vec<String>> = joints
        .iter()
        .map(|j| {
            let mut r = vec![
                text(j.get("name")),
                text(j.get("kind")),
                text(j.get("loaded_side")),
            ];
            for &(key, _, kind) in &cols {
                let s = kind.scale(u);
                r.push(match j.get(key) {
                    Some(Value::Number(n)) => num(s.apply(n.as_f64().unwrap_or(f64::NAN))),
                    Some(Value::Array(a)) => format!(
                        "({})",
                        a.iter()
                            .map(|x| num(s.apply(x.as_f64().unwrap_or(f64::NAN))))
                            .collect::<Vec<_>>()
                            .join(", ")
                    ),
                    other => text(other),
                });
                if key == "line" {
                    let axis = j.get("axis").and_then(Value::as_str).unwrap_or("");
                    if let Some(last) = r.last_mut() {
                        *last = format!("{} = {last}", esc(axis));
                    }
                }
            }
            r
        })
        .collect();
    let mut html = table(&head, &rows);
    html.push_str("<p class=\"note\">LTE: load transfer efficiency, the unloaded side's over the loaded side's deflection (or stress); − is x &lt; x<sub>j</sub> (y &lt; y<sub>j</sub>). A dash: the kind of joint carries none.</p>\n");
    let dowels = format!("{folder}dowels.csv");
    if l.has(&dowels) {
        match l.csv_table(&dowels, MAX_DOWELS)? {
            Some(t) => {
                let _ = write!(
                    html,
                    "<h3>Dowels</h3>\n<p class=\"note\">One row per bar, from {} (SI units: m, N, Pa).</p>\n{t}",
                    l.file_ref(&dowels)
                );
                l.note(&dowels, "the dowel table");
            }
            None => {
                let n = l.csv_rows(&dowels)?;
                let _ = writeln!(
                    html,
                    "<p class=\"note\">{n} dowels: too many to list here, see {}.</p>",
                    l.file_ref(&dowels)
                );
            }
        }
    }
    let pairs = format!("{folder}joints.csv");
    if l.has(&pairs) {
        let n = l.csv_rows(&pairs)?;
        let _ = writeln!(
            html,
            "<p class=\"note\">The deflections, jumps, shear and pressures at each of the {n} node pairs along the joints are in {} (not shown).</p>",
            l.file_ref(&pairs)
        );
    }
    Ok(Some(html))
}

/// The kind of an envelope quantity held in `unit` (None: shown as held).
fn envelope_kind(quantity: &str, unit: &str) -> Option<Kind> {
    let kind = match unit {
        "m" => Kind::Deflection,
        "Pa" if quantity.starts_with('s') => Kind::Stress,
        "Pa" => Kind::Pressure,
        "N·m/m" => Kind::Moment,
        "N/m" => Kind::Shear,
        "N" => Kind::Force,
        _ => return None,
    };
    Some(kind)
}

/// A run over load combinations: the combinations, the envelope and each combination's solve.
fn combinations(l: &mut Listing, mut folders: Vec<String>) -> Result<Part> {
    let env = if l.has("envelope.json") {
        Some(l.json("envelope.json")?)
    } else {
        None
    };
    let runs: Vec<Value> = env
        .as_ref()
        .and_then(|e| e.get("combinations"))
        .and_then(Value::as_array)
        .cloned()
        .unwrap_or_default();
    // The combinations in the envelope's order, then any other folder with a summary.
    let named: Vec<String> = runs
        .iter()
        .filter_map(|r| r.get("name").and_then(Value::as_str).map(str::to_string))
        .collect();
    folders.sort_by_key(|f| named.iter().position(|n| n == f).unwrap_or(usize::MAX));
    let mut sections = Vec::new();
    let mut title = None;
    if let Some(env) = &env {
        let mut html = String::new();
        let rows: Vec<Vec<String>> = runs
            .iter()
            .map(|r| {
                let factors = r
                    .get("factors")
                    .and_then(Value::as_object)
                    .map(|f| {
                        f.iter()
                            .map(|(case, x)| format!("{} × {}", text(Some(x)), esc(case)))
                            .collect::<Vec<_>>()
                            .join(" + ")
                    })
                    .unwrap_or_default();
                vec![
                    text(r.get("name")),
                    factors,
                    text(r.get("status")),
                    text(r.get("time_s")),
                ]
            })
            .collect();
        html.push_str(&table(
            &["combination", "factors", "status", "time, s"],
            &rows,
        ));
        let extremes = env
            .get("extremes")
            .and_then(Value::as_array)
            .cloned()
            .unwrap_or_default();
        // The scene's units, from the first combination's summary.
        let first = match folders.first() {
            Some(f) => Some(l.json(&format!("{f}/summary.json"))?),
            None => None,
        };
        let units = first
            .as_ref()
            .map_or(Units::new(None, 1.0), |v| Shown::of_summary(v).units);
        let length = Kind::Length.scale(&units);
        let rows: Vec<Vec<String>> = extremes
            .iter()
            .flat_map(|q| {
                let quantity = q.get("quantity").and_then(Value::as_str).unwrap_or("");
                let unit = q.get("unit").and_then(Value::as_str).unwrap_or("");
                let kind = envelope_kind(quantity, unit);
                ["max", "min"].map(|which| {
                    let e = q.get(which);
                    let at = |k: &str| e.and_then(|e| e.get(k)).and_then(Value::as_f64);
                    let value = match (at("value"), kind) {
                        (Some(v), Some(kind)) if units.is_physical() => {
                            let s = kind.scale(&units);
                            with_unit(&num(s.apply(v)), s.unit)
                        }
                        (Some(v), _) => with_unit(&num(v), unit),
                        (None, _) => "—".into(),
                    };
                    let place = match (at("x"), at("y")) {
                        (Some(x), Some(y)) => with_unit(
                            &format!("({}, {})", num(length.apply(x)), num(length.apply(y))),
                            length.unit,
                        ),
                        _ => String::new(),
                    };
                    vec![
                        esc(quantity),
                        esc(which),
                        value,
                        text(e.and_then(|e| e.get("combination"))),
                        place,
                    ]
                })
            })
            .collect();
        if !rows.is_empty() {
            let _ = write!(
                html,
                "<h3>Envelope</h3>\n<p class=\"note\">The extremes over every combination, with the one that governs and where (from {}, which holds them in SI units).</p>\n{}",
                l.file_ref("envelope.json"),
                table(
                    &["quantity", "extreme", "value", "combination", "at (x, y)"],
                    &rows
                )
            );
        }
        l.note("envelope.json", "the combinations and envelope tables");
        l.note(
            "envelope.csv",
            "not shown: the envelope table above, as CSV",
        );
        sections.push(Section {
            id: "combinations".into(),
            heading: "Combinations and envelope".into(),
            html,
        });
        let mut figures = String::new();
        let first = [
            "envelope-pressure-max.svg",
            "envelope-w-max.svg",
            "envelope-stress-bottom-max.svg",
            "envelope-stress-top-max.svg",
        ];
        for rel in l.ordered("", &first, |n| n.starts_with("envelope-")) {
            let name = rel.clone();
            figures.push_str(&l.figure(&rel, caption(&name))?);
        }
        if !figures.is_empty() {
            sections.push(Section {
                id: "envelope-charts".into(),
                heading: "Envelope charts".into(),
                html: figures,
            });
        }
    }
    for (k, folder) in folders.iter().enumerate() {
        let v = l.json(&format!("{folder}/summary.json"))?;
        if title.is_none() {
            let t = at(&v, "title").and_then(Value::as_str).unwrap_or("");
            title = Some(crate::scene::scene_title(t, folder).to_string());
        }
        let more = solve_sections(l, &format!("{folder}/"), &v, &format!("c{}", k + 1), folder)?;
        sections.extend(more);
    }
    Ok(Part {
        title: title.unwrap_or_else(|| "liftoff solve over load combinations".into()),
        sections,
    })
}
