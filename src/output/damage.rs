//! The files and the table of `liftoff damage`: `damage.csv` (Σ n/N at both faces of every
//! element), `passes.csv` (one row per case: the group, its load, lateral position and climate
//! bin, its repetitions, its largest stress of each face and where, the allowed repetitions
//! there and its share of the governing damage), `damage.json` (all of it) and the damage maps
//! `damage-bottom.svg/png` (bottom-up) and `damage-top.svg/png` (top-down), the governing element
//! marked; with the PCA's relation also `erosion.csv` (the erosion damage at every panel
//! corner) and its map `erosion.svg/png`. Every value is in the scene's unit system, each
//! header with its unit.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::chart::{self, Overlay, Units};
use super::Staged;
use crate::error::{Error, Result};
use crate::study::Damage;
use crate::units::Measure;

fn csv_damage(d: &Damage) -> String {
    let sys = d.units;
    let mut s = format!(
        "{},{},{},{},counted\n",
        Measure::Length.header("x", sys),
        Measure::Length.header("y", sys),
        Measure::Number.header("damage_bottom", sys),
        Measure::Number.header("damage_top", sys),
    );
    let l = |v: f64| Measure::Length.from_si(sys, v);
    for i in 0..d.x.len() {
        let _ = writeln!(
            s,
            "{:.12e},{:.12e},{:.12e},{:.12e},{}",
            l(d.x[i]),
            l(d.y[i]),
            d.bottom[i],
            d.top[i],
            // 1 or 0, so that the file stays numbers.
            u8::from(d.counted.get(i).is_none_or(|c| *c))
        );
    }
    s
}

fn csv_passes(d: &Damage) -> String {
    let sys = d.units;
    let (l, p, f) = (Measure::Length, Measure::Pressure, Measure::Force);
    let t = crate::units::Quantity::TemperatureDifference.unit(sys.unwrap_or_default());
    let mut s = [
        "group".to_string(),
        f.header("load", sys),
        l.header("offset", sys),
        format!("difference [{t}]"),
        "repetitions".into(),
        "outcome".into(),
        "solves".into(),
        "interpolated".into(),
        "mirrored".into(),
        p.header("bottom", sys),
        l.header("bottom_x", sys),
        l.header("bottom_y", sys),
        "bottom_allowed".into(),
        p.header("top", sys),
        l.header("top_x", sys),
        l.header("top_y", sys),
        "top_allowed".into(),
        "bottom_share".into(),
        "top_share".into(),
        l.header("erosion_deflection", sys),
        l.header("erosion_x", sys),
        l.header("erosion_y", sys),
        "erosion_allowed".into(),
        "erosion_share".into(),
    ]
    .join(",");
    s.push('\n');
    let c = |m: Measure, v: f64| m.from_si(sys, v);
    let opt = |v: Option<f64>| v.map_or(String::new(), |v| format!("{v:e}"));
    for q in &d.passes {
        // As damage.json (`Damage::reported`): 9/5 exactly.
        let diff = q.difference.map(|k| match sys {
            Some(crate::units::UnitSystem::Us) => k * 9.0 / 5.0,
            _ => k,
        });
        let e = q.erosion;
        let _ = writeln!(
            s,
            "{},{:e},{:e},{},{:e},{},{},{},{},{:e},{:e},{:e},{},{:e},{:e},{:e},{},{:e},{:e},{},{},{},{},{}",
            q.group,
            c(f, q.load),
            c(l, q.offset),
            opt(diff),
            q.repetitions,
            q.outcome,
            q.solves,
            q.interpolated,
            q.mirrored,
            c(p, q.bottom.stress),
            c(l, q.bottom.x),
            c(l, q.bottom.y),
            opt(q.bottom.allowed),
            c(p, q.top.stress),
            c(l, q.top.x),
            c(l, q.top.y),
            opt(q.top.allowed),
            q.bottom_share,
            q.top_share,
            opt(e.map(|e| c(Measure::Deflection, e.deflection))),
            opt(e.map(|e| c(l, e.x))),
            opt(e.map(|e| c(l, e.y))),
            opt(e.and_then(|e| e.allowed)),
            opt(e.map(|e| e.share)),
        );
    }
    s
}

/// erosion.csv: the PCA's erosion damage at every panel corner (None: no erosion summed).
fn csv_erosion(d: &Damage) -> Option<String> {
    let e = d.erosion.as_ref()?.reported(d.units);
    let sys = d.units;
    let l = Measure::Length;
    let mut s = [
        "panel".to_string(),
        l.header("x", sys),
        l.header("y", sys),
        l.header("thickness", sys),
        Measure::Deflection.header("deflection", sys),
        "damage".into(),
        "counted".into(),
    ]
    .join(",");
    s.push('\n');
    for c in &e.corners {
        let _ = writeln!(
            s,
            "\"{}\",{:e},{:e},{:e},{:e},{:e},{}",
            c.corner.panel,
            c.corner.x,
            c.corner.y,
            c.corner.thickness,
            c.deflection,
            c.damage,
            u8::from(c.corner.counted)
        );
    }
    Some(s)
}

/// The maps' units: the scene's system, lengths in metres of the field.
fn units_of(d: &Damage) -> Units {
    Units::of_si(d.units.unwrap_or_default())
}

/// Write damage.csv, passes.csv, damage.json, damage.vtu (the map as ParaView cell data) and the
/// two damage map charts into `dir`, staged.
pub fn write_damage(dir: &Path, d: &Damage, title: &str) -> Result<Vec<PathBuf>> {
    let mut st = Staged::new(dir)?;
    st.write_text("damage.csv", &csv_damage(d))?;
    st.write_text("passes.csv", &csv_passes(d))?;
    if let Some(text) = csv_erosion(d) {
        st.write_text("erosion.csv", &text)?;
    }
    let json = serde_json::to_string_pretty(&d.reported())
        .map_err(|e| Error::numerical("damage.json", format!("cannot serialise: {e}")))?;
    st.write_text("damage.json", &json)?;
    // The damage map as ParaView cell data on the plate's grid (in the scene's units, as
    // plate.vtu): no point data, since no one solve's deflection belongs to a sum over passes.
    // `counted` (1 or 0) thresholds away the end panels of a lane the model cuts.
    let counted: Vec<f64> = (0..d.x.len())
        .map(|i| f64::from(u8::from(d.counted.get(i).is_none_or(|c| *c))))
        .collect();
    super::vtk::write_cell_vtu(
        &st.path("damage.vtu"),
        &d.field.in_units(d.units),
        &[
            ("damage_bottom", &d.bottom),
            ("damage_top", &d.top),
            ("counted", &counted),
        ],
    )?;
    let units = units_of(d);
    let length = units.length();
    let number = chart::Scale {
        unit: "",
        factor: 1.0,
    };
    for (face, values, g, what) in [
        ("bottom", &d.bottom, d.governing_bottom, "bottom-up"),
        ("top", &d.top, d.governing_top, "top-down"),
    ] {
        // No damage anywhere (every stress below the relation's endurance limit, or no
        // repetitions): no place governs, and none is marked.
        let none = g.damage <= 0.0;
        let overlay = Overlay {
            marks: (!none)
                .then(|| {
                    (
                        (g.x, g.y),
                        format!(
                            "governing: Σ n/N = {} at ({:.2}, {:.2}) {}",
                            chart::short(g.damage),
                            length.apply(g.x),
                            length.apply(g.y),
                            length.unit
                        ),
                    )
                })
                .into_iter()
                .collect(),
            cut: cut_parts(d),
            ..Overlay::default()
        };
        let svg = st.path(&format!("damage-{face}.svg"));
        let png = st.path(&format!("damage-{face}.png"));
        chart::write_field_map(
            &svg,
            &png,
            &d.field,
            &chart::MapValues {
                values,
                name: "Σ n/N",
                scale: number,
            },
            &format!(
                "{title} — {what} damage ({}), {}{}{}",
                d.model,
                match (none, d.uncounted(values).is_some()) {
                    (true, false) => "none anywhere".to_string(),
                    (true, true) => "none in the inner panels".to_string(),
                    (false, _) => format!("largest {}", chart::short(g.damage)),
                },
                if d.uncounted(values).is_some() {
                    "; end panels not counted"
                } else {
                    ""
                },
                if d.complete { "" } else { " (incomplete)" }
            ),
            &units,
            &overlay,
        )?;
    }
    if let Some(e) = &d.erosion {
        // Each quarter of a panel shows its corner's erosion damage (the corner it lies
        // towards, on its own side of a joint); the governing corner is marked. An element
        // whose panel has no corner on the plate (a shaped plate's), or whose corner does not
        // count (the plate's ends), shows none: 0.
        let values: Vec<f64> = e
            .by_element(&d.x, &d.y)
            .into_iter()
            .map(|v| if v.is_finite() { v } else { 0.0 })
            .collect();
        let marks = e
            .governing
            .and_then(|g| e.corners.get(g))
            .map(|g| {
                (
                    (g.corner.x, g.corner.y),
                    format!(
                        "governing: C2 Σ n/N = {} at the corner ({:.2}, {:.2}) {} of panel {}",
                        chart::short(g.damage),
                        length.apply(g.corner.x),
                        length.apply(g.corner.y),
                        length.unit,
                        g.corner.panel
                    ),
                )
            })
            .into_iter()
            .collect();
        chart::write_field_map(
            &st.path("erosion.svg"),
            &st.path("erosion.png"),
            &d.field,
            &chart::MapValues {
                values: &values,
                name: "C2 Σ n/N",
                scale: number,
            },
            &format!(
                "{title} — erosion (PCA) by panel corner, largest {}{}{}",
                chart::short(e.damage()),
                if d.complete { "" } else { " (incomplete)" },
                if e.uncounted().is_some() {
                    ", the plate's ends not counted"
                } else {
                    ""
                }
            ),
            &units,
            &Overlay {
                marks,
                ..Overlay::default()
            },
        )?;
    }
    st.commit()
}

/// The parts of the maps that are drawn but not counted (the end panels of a lane the model
/// cuts, `Damage::counted`), as opposite corners in the field's coordinates; empty when every
/// element counts.
fn cut_parts(d: &Damage) -> Vec<[(f64, f64); 2]> {
    let extent = |v: &[f64]| {
        v.iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                (a.min(x), b.max(x))
            })
    };
    let (x0, x1) = extent(&d.field.x);
    let (y0, y1) = extent(&d.field.y);
    let counted: Vec<f64> = (d.x.iter().zip(&d.counted))
        .filter(|(_, c)| **c)
        .map(|(x, _)| *x)
        .collect();
    if counted.len() == d.x.len() || counted.is_empty() || !(x1 > x0 && y1 > y0) {
        return Vec::new();
    }
    // Element centres are half an element in from the panels' edges.
    let half = 0.5 * (x1 - x0) / d.elements[0].max(1) as f64;
    let (lo, hi) = extent(&counted);
    let (lo, hi) = (lo - half, hi + half);
    let mut out = Vec::new();
    if lo > x0 + 1e-9 * (x1 - x0) {
        out.push([(x0, y0), (lo, y1)]);
    }
    if hi < x1 - 1e-9 * (x1 - x0) {
        out.push([(hi, y0), (x1, y1)]);
    }
    out
}

/// What the command line prints.
pub fn damage_table(title: &str, d: &Damage, files: Option<(usize, &Path)>) -> String {
    let mut s = String::new();
    let units = units_of(d);
    let (len, st) = (units.length(), units.stress());
    let converged = d.passes.len() - d.missing.len();
    let _ = writeln!(
        s,
        "liftoff damage — {title}: {} passes ({converged} converged), {} solves, {} positions interpolated exactly between levels{}",
        d.passes.len(),
        d.solves,
        d.interpolated,
        match d.mirrored {
            0 => String::new(),
            m => format!(", {m} read off their mirror images"),
        }
    );
    let _ = writeln!(
        s,
        "  relation   : {}, modulus of rupture {:.3} {}{}; repetitions over the life {:.4} × the first year's",
        d.model,
        st.apply(d.rupture),
        st.unit,
        d.rupture_ratio.map_or(String::new(), |[lo, hi]| format!(
            " at 28 days, × {lo:.3} … {hi:.3} over the life (MEPDG strength gain, month by month)"
        )),
        d.life_factor
    );
    let _ = writeln!(
        s,
        "  time       : operators assembled in {:.3} s; the whole run {:.3} s",
        d.assemble_s, d.total_s
    );
    for (what, g, values) in [
        ("bottom-up", d.governing_bottom, &d.bottom),
        ("top-down", d.governing_top, &d.top),
    ] {
        let cut = d.uncounted(values);
        if g.damage <= 0.0 {
            let _ = writeln!(
                s,
                "  {what:<11}: Σ n/N = 0 {}: no pass damages this face (every stress below the relation's endurance limit, or no repetitions)",
                if cut.is_some() { "in the inner panels" } else { "everywhere" }
            );
        } else {
            let _ = writeln!(
                s,
                "  {what:<11}: Σ n/N = {:.4e} at ({:.2}, {:.2}) {}",
                g.damage,
                len.apply(g.x),
                len.apply(g.y),
                len.unit
            );
        }
        // The end panels of a lane the model cuts: mapped, not counted.
        if let Some((k, v)) = cut {
            let _ = writeln!(
                s,
                "               the end panels, where the model cuts a lane that goes on, not counted: Σ n/N up to {:.4e} there, at ({:.2}, {:.2}) {} ([plate] ends = \"free\" counts them)",
                v,
                len.apply(d.x[k]),
                len.apply(d.y[k]),
                len.unit
            );
        }
    }
    if let Some(e) = &d.erosion {
        match e.governing.and_then(|g| e.corners.get(g)) {
            Some(g) => {
                let _ = writeln!(
                    s,
                    "  erosion    : C2 Σ n/N = {:.4e} at the corner ({:.2}, {:.2}) {} of panel {}, k {} {} (C1 = {}, C2 = {})",
                    g.damage,
                    len.apply(g.corner.x),
                    len.apply(g.corner.y),
                    len.unit,
                    g.corner.panel,
                    chart::short(
                        crate::units::Quantity::SubgradeModulus
                            .from_si(d.units.unwrap_or_default(), e.k)
                    ),
                    crate::units::Quantity::SubgradeModulus.unit(d.units.unwrap_or_default()),
                    e.c1,
                    e.c2
                );
            }
            None => {
                let _ = writeln!(s, "  erosion    : no counted panel corner on the plate");
            }
        }
        if let Some(c) = e.uncounted().and_then(|(j, _)| e.corners.get(j)) {
            let _ = writeln!(
                s,
                "               the plate's ends (x = ±{:.2} {}), where the model cuts a lane that goes on, not counted: C2 Σ n/N up to {:.4e} there, at ({:.2}, {:.2}) ([plate] ends = \"free\" counts them)",
                len.apply(c.corner.x.abs()),
                len.unit,
                c.damage,
                len.apply(c.corner.x),
                len.apply(c.corner.y)
            );
        }
    }
    if let Some(note) = &d.erosion_note {
        let _ = writeln!(s, "  erosion    : not summed: {note}");
    }
    if let Some(c) = d.cracking {
        let _ = writeln!(
            s,
            "  cracking   : bottom-up {:.2} %, top-down {:.2} %, total {:.2} % of slabs{}",
            c.bottom,
            c.top,
            c.total,
            c.at_reliability.map_or(String::new(), |r| format!(
                ", {r:.2} % at the reliability asked"
            ))
        );
    }
    if !d.complete {
        let _ = writeln!(
            s,
            "  INCOMPLETE : {} pass(es) did not converge and are not in the sums: {}",
            d.missing.len(),
            d.missing.join("; ")
        );
    }
    if let Some((k, dir)) = files {
        let _ = writeln!(
            s,
            "  files      : {k} in {} (damage.csv, passes.csv, {}damage.json, damage.vtu, damage maps)",
            dir.display(),
            if d.erosion.is_some() {
                "erosion.csv, erosion map, "
            } else {
                ""
            }
        );
    }
    s
}

/// Write design.csv, design.json and the design curve (design.svg/png) of `liftoff design` into
/// `dir`, staged; thicknesses in the scene's unit of length.
pub fn write_design(dir: &Path, d: &crate::study::Design, title: &str) -> Result<Vec<PathBuf>> {
    let mut st = Staged::new(dir)?;
    let sys = d.units;
    let l = |v: f64| Measure::Length.from_si(sys, v);
    let unit = Measure::Length.unit(sys);
    let mut csv = format!(
        "thickness [{unit}],damage_bottom [-],damage_top [-],damage_erosion [-],cracking [%],{} [{}],passes,complete,curve,solves,time [s]\n",
        d.measure,
        if d.measure == "cracking" { "%" } else { "-" }
    );
    for p in &d.points {
        let _ = writeln!(
            csv,
            "{:.12e},{:e},{:e},{},{},{:e},{},{},{},{},{}",
            l(p.thickness),
            p.bottom,
            p.top,
            p.erosion.map_or(String::new(), |e| format!("{e:e}")),
            p.cracking.map_or(String::new(), |c| format!("{c:e}")),
            p.value,
            p.passes,
            p.complete,
            p.curve,
            p.solves,
            p.seconds
        );
    }
    st.write_text("design.csv", &csv)?;
    let reported = d.reported();
    let json = serde_json::to_string_pretty(&reported)
        .map_err(|e| Error::numerical("design.json", format!("cannot serialise: {e}")))?;
    st.write_text("design.json", &json)?;
    // The line runs through every run, by thickness; the search's steps are marked apart.
    let curve: Vec<(f64, f64)> = reported
        .points
        .iter()
        .map(|p| (p.thickness, p.value))
        .collect();
    let steps: Vec<(f64, f64)> = reported
        .points
        .iter()
        .filter(|p| !p.curve)
        .map(|p| (p.thickness, p.value))
        .collect();
    let svg = st.path("design.svg");
    let png = st.path("design.png");
    let y_label = if d.measure == "cracking" {
        "total cracking, % of slabs".to_string()
    } else {
        "largest Σ n/N (log scale)".to_string()
    };
    chart::write_design_curve(
        &svg,
        &png,
        &chart::DesignCurve {
            title: &format!("{title} — design curve ({})", d.model),
            x_label: &format!("slab thickness ({unit})"),
            y_label: &y_label,
            curve: &curve,
            steps: &steps,
            target: d.target,
            found: reported.thickness,
            log: d.measure != "cracking",
        },
    )?;
    st.commit()
}

/// What the command line prints for `liftoff design`.
pub fn design_table(
    title: &str,
    d: &crate::study::Design,
    files: Option<(usize, &Path)>,
) -> String {
    let sys = d.units;
    let l = |v: f64| Measure::Length.from_si(sys, v);
    let unit = Measure::Length.unit(sys);
    let mut s = String::new();
    let _ = writeln!(
        s,
        "liftoff design — {title}: {} ({}), target {} {}",
        d.model,
        d.measure,
        d.target,
        if d.measure == "cracking" {
            "% of slabs"
        } else {
            "(Σ n/N)"
        }
    );
    let erosion = d.points.iter().any(|p| p.erosion.is_some());
    let _ = writeln!(
        s,
        "  thickness ({unit})   bottom Σn/N   top Σn/N{}   {:<10}  meets",
        if erosion { "   erosion" } else { "" },
        d.measure
    );
    for p in &d.points {
        let _ = writeln!(
            s,
            "  {:>12.4}{}  {:>11.4e}  {:>9.3e}{}   {:>10.4}  {}{}",
            l(p.thickness),
            if p.curve { " " } else { "*" },
            p.bottom,
            p.top,
            match (erosion, p.erosion) {
                (true, Some(e)) => format!("  {e:>9.3e}"),
                (true, None) => format!("  {:>9}", "-"),
                _ => String::new(),
            },
            p.value,
            if p.passes { "yes" } else { "no" },
            if p.complete { "" } else { " (incomplete)" }
        );
    }
    let _ = writeln!(s, "  (* a search step)");
    match (d.thickness, d.bracket) {
        (Some(h), Some([a, b])) => {
            let _ = writeln!(
                s,
                "  least thickness: {:.4} {unit} (meets the target; {:.4} {unit} does not)",
                l(h),
                l(a)
            );
            let _ = b;
        }
        (Some(h), None) => {
            let _ = writeln!(
                s,
                "  least thickness: {:.4} {unit} or less — the thinnest tried already meets the target",
                l(h)
            );
        }
        _ => {
            let _ = writeln!(
                s,
                "  no thickness in the range meets the target: try thicker slabs"
            );
        }
    }
    if !d.monotone {
        let _ = writeln!(
            s,
            "  note: the design curve does not fall everywhere as the slab thickens: the least thickness is the first that meets the target along the curve"
        );
    }
    if d.cut {
        let _ = writeln!(
            s,
            "  note: the end panels, where the model cuts a lane that goes on, are not counted ([plate] ends = \"free\" counts them)"
        );
    }
    let _ = writeln!(s, "  time: {:.2} s", d.total_s);
    if let Some((k, dir)) = files {
        let _ = writeln!(
            s,
            "  files: {k} in {} (design.csv, design.json, design.svg/png)",
            dir.display()
        );
    }
    s
}
