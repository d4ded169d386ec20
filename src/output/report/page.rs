//! The pieces of `report.html` every section uses: the listing of the output directory (which
//! file each section shows, and how), numbers, tables, SVG figures (inlined by
//! [`super::markup`], whose escaping `esc` this file hands on), and the page itself with its
//! inline style sheet (screen and print). No section imports another, and none imports the
//! folder's `mod.rs`: they build on this file alone.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde_json::Value;

pub(crate) use super::markup::esc;
use super::markup::inline_svg;
use crate::error::{Error, Result};
use crate::output::chart::{Scale, Units};
use crate::units::Measure;

/// The files of an output directory — its own and those of its sub-folders one level down (the
/// combinations' folders) — with what the report does with each.
pub(crate) struct Listing {
    /// The output directory.
    pub(crate) dir: PathBuf,
    /// Relative path (`/`-separated) → size in bytes.
    pub(crate) files: BTreeMap<String, u64>,
    /// Relative path → how the page shows it (a figure, a table) or why it does not.
    pub(crate) notes: BTreeMap<String, String>,
    /// Whether the page sits in `dir`, so that a relative link reaches the files.
    pub(crate) linked: bool,
    /// Figures inlined so far (each SVG's ids get its number as a prefix).
    figures: usize,
}

impl Listing {
    /// Read `dir` (hidden entries — a staging folder — and `skip`, the report itself, left out).
    pub(crate) fn scan(dir: &Path, skip: &Path, linked: bool) -> Result<Self> {
        let io = |p: &Path| {
            let p = p.display().to_string();
            move |source| Error::Io { path: p, source }
        };
        let mut files = BTreeMap::new();
        let mut stack = vec![(dir.to_path_buf(), String::new(), 0)];
        while let Some((folder, prefix, depth)) = stack.pop() {
            for entry in std::fs::read_dir(&folder).map_err(io(&folder))? {
                let entry = entry.map_err(io(&folder))?;
                let name = entry.file_name().to_string_lossy().into_owned();
                let path = entry.path();
                if name.starts_with('.') || path == skip {
                    continue;
                }
                let meta = entry.metadata().map_err(io(&path))?;
                let rel = format!("{prefix}{name}");
                if meta.is_dir() {
                    if depth == 0 {
                        stack.push((path, format!("{rel}/"), depth + 1));
                    }
                } else {
                    files.insert(rel, meta.len());
                }
            }
        }
        Ok(Self {
            dir: dir.to_path_buf(),
            files,
            notes: BTreeMap::new(),
            linked,
            figures: 0,
        })
    }

    /// Whether the directory holds `rel`.
    pub(crate) fn has(&self, rel: &str) -> bool {
        self.files.contains_key(rel)
    }

    /// The text of `rel`.
    pub(crate) fn read(&self, rel: &str) -> Result<String> {
        let p = self.dir.join(rel);
        std::fs::read_to_string(&p).map_err(|source| Error::Io {
            path: p.display().to_string(),
            source,
        })
    }

    /// `rel` parsed as JSON; a file that is not JSON is an error naming it.
    pub(crate) fn json(&self, rel: &str) -> Result<Value> {
        let text = self.read(rel)?;
        serde_json::from_str(&text).map_err(|e| Error::Io {
            path: self.dir.join(rel).display().to_string(),
            source: std::io::Error::other(format!("not the JSON liftoff writes: {e}")),
        })
    }

    /// Say how the page shows `rel` (the first word counts: a file shown twice keeps the first).
    pub(crate) fn note(&mut self, rel: &str, how: impl Into<String>) {
        if self.has(rel) {
            self.notes
                .entry(rel.to_string())
                .or_insert_with(|| how.into());
        }
    }

    /// The SVG files in `folder` (empty or ending in '/') not yet shown whose name passes `keep`,
    /// in name order.
    pub(crate) fn svgs_in(&self, folder: &str, keep: impl Fn(&str) -> bool) -> Vec<String> {
        self.files
            .keys()
            .filter(|rel| !self.notes.contains_key(*rel))
            .filter_map(|rel| rel.strip_prefix(folder).map(|name| (rel, name)))
            .filter(|(_, name)| !name.contains('/') && name.ends_with(".svg") && keep(name))
            .map(|(rel, _)| rel.clone())
            .collect()
    }

    /// The SVG files of `folder` not yet shown that `keep` takes: those named in `first` in that
    /// order, then the rest in name order.
    pub(crate) fn ordered(
        &self,
        folder: &str,
        first: &[&str],
        keep: impl Fn(&str) -> bool,
    ) -> Vec<String> {
        let mut names: Vec<String> = first
            .iter()
            .map(|n| format!("{folder}{n}"))
            .filter(|rel| self.has(rel) && !self.notes.contains_key(rel))
            .collect();
        for rel in self.svgs_in(folder, keep) {
            if !names.contains(&rel) {
                names.push(rel);
            }
        }
        names
    }

    /// The sub-folders that hold `file`, in name order.
    pub(crate) fn folders_with(&self, file: &str) -> Vec<String> {
        self.files
            .keys()
            .filter_map(|rel| rel.strip_suffix(&format!("/{file}")))
            .filter(|folder| !folder.contains('/'))
            .map(str::to_string)
            .collect()
    }

    /// The file's name as the page shows it: a relative link when the page sits in the output
    /// directory, its name otherwise.
    pub(crate) fn file_ref(&self, rel: &str) -> String {
        if self.linked {
            format!("<a href=\"{}\"><code>{}</code></a>", href(rel), esc(rel))
        } else {
            format!("<code>{}</code>", esc(rel))
        }
    }

    /// The number of data rows of a CSV file (its lines after the header).
    pub(crate) fn csv_rows(&self, rel: &str) -> Result<usize> {
        Ok(self
            .read(rel)?
            .lines()
            .skip(1)
            .filter(|l| !l.is_empty())
            .count())
    }

    /// A CSV file as a table, when it has at most `max_rows` rows (None otherwise).
    pub(crate) fn csv_table(&self, rel: &str, max_rows: usize) -> Result<Option<String>> {
        let text = self.read(rel)?;
        let mut lines = text.lines().filter(|l| !l.is_empty());
        let Some(header) = lines.next() else {
            return Ok(None);
        };
        let rows: Vec<&str> = lines.collect();
        if rows.len() > max_rows {
            return Ok(None);
        }
        let head: Vec<String> = header.split(',').map(esc).collect();
        let head: Vec<&str> = head.iter().map(String::as_str).collect();
        let body: Vec<Vec<String>> = rows
            .iter()
            .map(|r| {
                r.split(',')
                    .map(|c| match c.parse::<f64>() {
                        Ok(v) if c.contains(['.', 'e', 'E']) => num(v),
                        _ => esc(c),
                    })
                    .collect()
            })
            .collect();
        Ok(Some(table(&head, &body)))
    }

    /// `rel`, an SVG chart, as a figure: its XML inlined (prolog, comments, scripts and event
    /// attributes dropped; ids prefixed by the figure's number so that two charts cannot clash;
    /// every text re-escaped), captioned `caption` and the file's name.
    pub(crate) fn figure(&mut self, rel: &str, caption: &str) -> Result<String> {
        self.figures += 1;
        let n = self.figures;
        let svg = inline_svg(&self.read(rel)?, &format!("f{n}-")).map_err(|e| Error::Io {
            path: self.dir.join(rel).display().to_string(),
            source: std::io::Error::other(format!("not an SVG chart liftoff can inline: {e}")),
        })?;
        self.note(rel, format!("figure {n}"));
        self.note(
            &format!("{}.png", rel.trim_end_matches(".svg")),
            format!("not shown: the PNG copy of figure {n}"),
        );
        let caption = if caption.is_empty() {
            String::new()
        } else {
            format!("{} — ", esc(caption))
        };
        Ok(format!(
            "<figure class=\"chart\" id=\"figure-{n}\">\n{svg}\n<figcaption>Figure {n}. {caption}{}</figcaption>\n</figure>\n",
            self.file_ref(rel)
        ))
    }
}

/// A relative path as a link target: every byte outside the unreserved set percent-encoded.
fn href(rel: &str) -> String {
    let mut out = String::new();
    for b in rel.bytes() {
        if b.is_ascii_alphanumeric() || matches!(b, b'-' | b'_' | b'.' | b'~' | b'/') {
            out.push(b as char);
        } else {
            let _ = write!(out, "%{b:02X}");
        }
    }
    out
}

/// A number with four significant digits (scientific beyond 1e-3 … 1e6).
pub(crate) fn num(v: f64) -> String {
    if !v.is_finite() {
        return v.to_string();
    }
    if v == 0.0 {
        return "0".into();
    }
    let a = v.abs();
    if (1e-3..1e6).contains(&a) {
        let digits = (3 - a.log10().floor() as i32).max(0) as usize;
        format!("{v:.digits$}")
    } else {
        format!("{v:.3e}")
    }
}

/// A table: head cells and rows of cells, all already HTML.
pub(crate) fn table<S: AsRef<str>>(head: &[&str], rows: &[Vec<S>]) -> String {
    let mut s = String::from("<div class=\"scroll\"><table>\n<thead><tr>");
    for h in head {
        let _ = write!(s, "<th>{h}</th>");
    }
    s.push_str("</tr></thead>\n<tbody>\n");
    for r in rows {
        s.push_str("<tr>");
        for c in r {
            let _ = write!(s, "<td>{}</td>", c.as_ref());
        }
        s.push_str("</tr>\n");
    }
    s.push_str("</tbody>\n</table></div>\n");
    s
}

/// A table of (label, value) rows, without a head: both cells already HTML.
pub(crate) fn pairs(rows: &[(String, String)]) -> String {
    let mut s = String::from("<div class=\"scroll\"><table class=\"pairs\">\n<tbody>\n");
    for (k, v) in rows {
        let _ = writeln!(s, "<tr><th>{k}</th><td>{v}</td></tr>");
    }
    s.push_str("</tbody>\n</table></div>\n");
    s
}

/// The value at a dotted path of a JSON object (`stresses.bottom.value`, `moments.mx.1`).
pub(crate) fn at<'a>(v: &'a Value, path: &str) -> Option<&'a Value> {
    path.split('.')
        .try_fold(v, |v, key| match key.parse::<usize>() {
            Ok(i) if v.is_array() => v.get(i),
            _ => v.get(key),
        })
}

/// A JSON value as text (strings without quotes; null as an em dash).
pub(crate) fn text(v: Option<&Value>) -> String {
    match v {
        None | Some(Value::Null) => "—".into(),
        Some(Value::String(s)) => esc(s),
        Some(Value::Number(n)) if n.is_f64() => n.as_f64().map_or_else(|| esc(&n.to_string()), num),
        Some(Value::Number(n)) => esc(&n.to_string()),
        Some(Value::Array(a)) => a
            .iter()
            .map(|x| text(Some(x)))
            .collect::<Vec<_>>()
            .join(" × "),
        Some(v) => esc(&v.to_string()),
    }
}

/// One section of the page: its anchor, its heading and its HTML.
pub(crate) struct Section {
    pub(crate) id: String,
    pub(crate) heading: String,
    pub(crate) html: String,
}

/// The page: a title, a table of contents, the sections and the list of files.
pub(crate) fn page(title: &str, source: &str, sections: &[Section], files: &str) -> String {
    let mut s = String::with_capacity(sections.iter().map(|x| x.html.len()).sum::<usize>() + 8192);
    let _ = write!(
        s,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>{}</title>\n<style>\n{STYLE}</style>\n</head>\n<body>\n<header>\n<h1>{}</h1>\n<p class=\"source\">{}</p>\n</header>\n<nav>\n<h2>Contents</h2>\n<ol>\n",
        esc(title),
        esc(title),
        source
    );
    for x in sections {
        let _ = writeln!(
            s,
            "<li><a href=\"#{}\">{}</a></li>",
            esc(&x.id),
            esc(&x.heading)
        );
    }
    s.push_str("<li><a href=\"#files\">Files</a></li>\n</ol>\n</nav>\n<main>\n");
    for x in sections {
        let _ = write!(
            s,
            "<section id=\"{}\">\n<h2>{}</h2>\n{}</section>\n",
            esc(&x.id),
            esc(&x.heading),
            x.html
        );
    }
    let _ = write!(
        s,
        "<section id=\"files\">\n<h2>Files</h2>\n{files}</section>\n</main>\n<footer><p>{}</p></footer>\n</body>\n</html>\n",
        esc(SIGN_CONVENTION)
    );
    s
}

/// The sign convention, as the command line prints it.
const SIGN_CONVENTION: &str = crate::output::tables::SIGN_CONVENTION;

/// The page's only style sheet: system fonts, figures scaled to the page's width, and for print
/// every figure on a page of its own, never cut, the contents left out.
const STYLE: &str = r#"
:root { color-scheme: light; }
body { font-family: system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, sans-serif;
  margin: 0 auto; max-width: 62rem; padding: 1rem 1.5rem; color: #111; background: #fff; line-height: 1.4; }
h1 { font-size: 1.6rem; margin: 0.5rem 0; }
h2 { font-size: 1.3rem; border-bottom: 1px solid #999; margin-top: 2rem; }
h3 { font-size: 1.1rem; margin-top: 1.5rem; }
p.source, footer { color: #444; font-size: 0.9rem; }
nav ol { columns: 2; }
table { border-collapse: collapse; margin: 0.5rem 0 1rem; font-size: 0.9rem; }
th, td { border: 1px solid #bbb; padding: 0.2rem 0.5rem; text-align: left; vertical-align: top; }
thead th { background: #eee; }
table.pairs th { background: #f4f4f4; font-weight: normal; }
td.value, td.stored { font-variant-numeric: tabular-nums; }
table.numbers td:not(:first-child) { white-space: nowrap; }
.scroll { overflow-x: auto; max-width: 100%; }
code { font-size: 0.9em; }
figure.chart { margin: 1rem 0; }
figure.chart svg { display: block; width: 100%; height: auto; max-width: 900px; }
figcaption { font-size: 0.9rem; color: #333; margin-top: 0.3rem; }
.note { color: #444; font-size: 0.9rem; }
@media print {
  @page { margin: 12mm; }
  body { max-width: none; padding: 0; font-size: 10pt; }
  nav { display: none; }
  a { color: inherit; text-decoration: none; }
  h2, h3 { break-after: avoid; }
  .scroll { overflow: visible; }
  table { font-size: 8pt; }
  th, td { padding: 0.1rem 0.25rem; }
  table.numbers td:not(:first-child) { white-space: normal; }
  td code { overflow-wrap: anywhere; }
  tr { break-inside: avoid; }
  thead { display: table-header-group; }
  figure.chart { break-before: page; break-inside: avoid; page-break-before: always; page-break-inside: avoid; }
  figure.chart svg { max-width: 100%; max-height: 235mm; }
}
"#;

/// What a reader of one kind of output found: the page's title it suggests and its sections.
pub(crate) struct Part {
    pub(crate) title: String,
    pub(crate) sections: Vec<Section>,
}

/// The kind of a number on the page, which picks its engineering unit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Kind {
    /// Coordinates and sides: m.
    Length,
    /// Deflections: m, shown in mm.
    Deflection,
    /// Contact pressures: Pa, shown in kPa.
    Pressure,
    /// Surface stresses: Pa, shown in MPa.
    Stress,
    /// Moments per length: N·m/m, shown in kN·m/m.
    Moment,
    /// Shear forces per length: N/m, shown in kN/m.
    Shear,
    /// Forces: N, shown in kN.
    Force,
    /// A ratio shown in per cent.
    Fraction,
    /// A number without a unit (V, Γ, an LTE, a relative error).
    Plain,
}

impl Kind {
    /// The SI unit liftoff's files hold this kind in.
    pub(crate) fn si(self) -> &'static str {
        match self {
            Kind::Length | Kind::Deflection => "m",
            Kind::Pressure | Kind::Stress => "Pa",
            Kind::Moment => "N·m/m",
            Kind::Shear => "N/m",
            Kind::Force => "N",
            Kind::Fraction | Kind::Plain => "",
        }
    }

    /// What the kind measures, for the unit a file holds it in.
    fn measure(self) -> Option<Measure> {
        match self {
            Kind::Length => Some(Measure::Length),
            Kind::Deflection => Some(Measure::Deflection),
            Kind::Pressure | Kind::Stress => Some(Measure::Pressure),
            Kind::Moment => Some(Measure::MomentPerLength),
            Kind::Shear => Some(Measure::ForcePerLength),
            Kind::Force => Some(Measure::Force),
            Kind::Fraction | Kind::Plain => None,
        }
    }

    /// The unit a physical scene's files hold this kind in: its system's base unit (m, Pa, N
    /// in SI; in, psi, lbf in US units).
    pub(crate) fn held(self, u: &Units) -> &'static str {
        self.measure().map_or("", |m| m.unit(Some(u.system())))
    }

    /// How a value held in the files is shown (the charts' own units): the files hold the
    /// scene's system (in, psi for a US scene), the charts' scales start from SI.
    pub(crate) fn scale(self, u: &Units) -> Scale {
        let s = self.shown(u);
        let to_si = match self.measure() {
            Some(m) if u.is_physical() => 1.0 / m.from_si(Some(u.system()), 1.0),
            _ => 1.0,
        };
        Scale {
            factor: s.factor * to_si,
            ..s
        }
    }

    /// The charts' scale of this kind, from SI.
    fn shown(self, u: &Units) -> Scale {
        match self {
            Kind::Length => u.length(),
            Kind::Deflection => u.deflection(),
            Kind::Pressure => u.pressure(),
            Kind::Stress => u.stress(),
            Kind::Moment => u.moment(),
            Kind::Shear => u.shear(),
            Kind::Force => u.force(),
            Kind::Fraction => Scale {
                unit: "%",
                factor: 100.0,
            },
            Kind::Plain => Scale {
                unit: "",
                factor: 1.0,
            },
        }
    }
}

/// The units the numbers of one JSON file are shown in, and the units they are held in.
pub(crate) struct Shown<'a> {
    /// The charts' units of the scene (engineering units in its system, or dimensionless).
    pub(crate) units: Units,
    /// The file's own `"units"` map (key → unit of its value), when it has one.
    pub(crate) map: Option<&'a serde_json::Map<String, Value>>,
}

impl<'a> Shown<'a> {
    /// The units of a summary.json (`physical`, `dimensionless.mu`, and `units` if present).
    pub(crate) fn of_summary(v: &'a Value) -> Self {
        use crate::choice::Choice;
        let physical = v.get("physical").and_then(|p| {
            let f = |k: &str| p.get(k).and_then(Value::as_f64);
            Some(crate::model::Physical {
                half_length: f("half_length")?,
                force: f("force")?,
                rigidity: f("rigidity")?,
                units: p
                    .get("units")
                    .and_then(Value::as_str)
                    .and_then(crate::units::UnitSystem::from_name)
                    .unwrap_or_default(),
            })
        });
        let mu = at(v, "dimensionless.mu")
            .and_then(Value::as_f64)
            .unwrap_or(1.0);
        Self {
            units: Units::new(physical, mu),
            map: v.get("units").and_then(Value::as_object),
        }
    }

    /// The unit `path`'s value is held in: the file's map's word for it (by its path, then by
    /// its first key), else SI for a physical scene, else the scene's units of P and L.
    pub(crate) fn held(&self, path: &str, kind: Kind) -> String {
        let first = path.split('.').next().unwrap_or(path);
        if let Some(u) = self
            .map
            .and_then(|m| m.get(path).or_else(|| m.get(first)))
            .and_then(Value::as_str)
        {
            return u.to_string();
        }
        if self.units.is_physical() || kind.si().is_empty() {
            kind.held(&self.units).to_string()
        } else {
            "units of P, L".to_string()
        }
    }

    /// The value as shown (number and unit) and as held (number and unit), both HTML: the
    /// shown one in engineering units when the value is held as liftoff's files hold it, as
    /// held otherwise.
    pub(crate) fn value(&self, path: &str, kind: Kind, v: f64) -> (String, String) {
        let held = self.held(path, kind);
        let standard = held == kind.held(&self.units) || held == "units of P, L";
        let shown = if standard {
            let s = kind.scale(&self.units);
            with_unit(&num(s.apply(v)), s.unit)
        } else {
            with_unit(&num(v), &held)
        };
        // The file's digits (serde_json's shortest form), not Rust's positional one.
        let digits =
            serde_json::Number::from_f64(v).map_or_else(|| v.to_string(), |n| n.to_string());
        (shown, with_unit(&esc(&digits), &held))
    }
}

/// `number unit` (a narrow no-break space before the unit, so that the two never part), or the number alone.
pub(crate) fn with_unit(number: &str, unit: &str) -> String {
    if unit.is_empty() {
        number.to_string()
    } else {
        format!("{number}\u{202F}{}", esc(unit))
    }
}

/// A table of key numbers: one row per (path in `v`, label, kind) whose value is a number —
/// the label, the value shown, where (an `[x, y]` or `{x, y}` given by `wheres`), and the key
/// with the value as held. Each row carries `data-key` and the file's own digits in
/// `data-value`, so that a reader (or a test) can take the exact number.
pub(crate) fn numbers_table(
    v: &Value,
    shown: &Shown,
    rows: &[(&str, &str, Kind)],
    wheres: &dyn Fn(&str) -> Option<(f64, f64)>,
    file: &str,
) -> String {
    let mut s = format!(
        "<div class=\"scroll\"><table class=\"numbers\">\n<thead><tr><th>quantity</th><th>value</th><th>where</th><th>in {}</th></tr></thead>\n<tbody>\n",
        esc(file)
    );
    let length = Kind::Length.scale(&shown.units);
    for (path, label, kind) in rows {
        let Some(value) = at(v, path).filter(|x| x.is_number()) else {
            continue;
        };
        let x = value.as_f64().unwrap_or(f64::NAN);
        let (shown_value, held) = shown.value(path, *kind, x);
        let place = wheres(path).map_or(String::new(), |(px, py)| {
            with_unit(
                &format!("({}, {})", num(length.apply(px)), num(length.apply(py))),
                length.unit,
            )
        });
        let _ = writeln!(
            s,
            "<tr data-key=\"{}\" data-value=\"{}\"><td>{}</td><td class=\"value\">{shown_value}</td><td>{place}</td><td class=\"stored\"><code>{}</code> = {held}</td></tr>",
            esc(path),
            esc(&value.to_string()),
            esc(label),
            esc(path)
        );
    }
    s.push_str("</tbody>\n</table></div>\n");
    s
}
