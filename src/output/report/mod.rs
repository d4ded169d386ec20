//! `report.html`: one self-contained page that shows what a liftoff output directory holds —
//! the summary with its units, the tables (joints, dowels, combinations and envelope, critical
//! positions), every SVG chart inlined — and says which files it does not show (the per-node
//! tables, the ParaView grid) and why. No script, no font, no image is loaded from anywhere:
//! the page opens from a file in any browser and prints with each figure on a page of its own.
//!
//! Each kind of output has its reader (`solve.rs`: `liftoff solve`, with or without
//! combinations; `critical.rs`: `liftoff critical`; `damage.rs`: `liftoff damage` and
//! `liftoff design`; `backcalc.rs`: `liftoff backcalc`), listed in [`READERS`]; a directory may hold
//! several kinds, and each gives its sections. A new command's files get a reader of their own
//! and a line in that list. Every chart no reader shows still goes on the page ("Other charts").

mod backcalc;
mod critical;
mod damage;
mod markup;
mod page;
mod solve;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::Staged;
use crate::error::{Error, Result};
use page::{esc, Listing, Part, Section};

/// The report's file name in an output directory.
pub const FILE: &str = "report.html";

/// A reader of one kind of output: the files that mark it (named in the error when a directory
/// holds none) and what it makes of them (None: the directory holds no such output).
struct Reader {
    marks: &'static str,
    read: fn(&mut Listing) -> Result<Option<Part>>,
}

/// Every kind of output a report shows, in the page's order.
const READERS: &[Reader] = &[
    Reader {
        marks: solve::MARKS,
        read: solve::read,
    },
    Reader {
        marks: critical::MARKS,
        read: critical::read,
    },
    Reader {
        marks: damage::MARKS,
        read: damage::read,
    },
    Reader {
        marks: backcalc::MARKS,
        read: backcalc::read,
    },
];

/// The page for the output directory `dir`, written as `out` (default `dir/report.html`) and
/// staged: a failure leaves no file. A directory with no liftoff output is
/// [`Error::NoOutput`], and nothing is written. Returns the report's path.
pub fn write_report(dir: &Path, out: Option<&Path>) -> Result<PathBuf> {
    let out = out.map_or_else(|| dir.join(FILE), Path::to_path_buf);
    let html = render(dir, &out)?;
    let (folder, name) = match (out.parent(), out.file_name()) {
        (Some(p), Some(n)) => (
            if p.as_os_str().is_empty() {
                Path::new(".")
            } else {
                p
            },
            n.to_string_lossy().into_owned(),
        ),
        _ => {
            return Err(Error::Io {
                path: out.display().to_string(),
                source: std::io::Error::other("not a file name"),
            })
        }
    };
    let mut st = Staged::new(folder)?;
    st.write_text(&name, &html)?;
    st.commit()?;
    Ok(out)
}

/// The page's HTML for the output directory `dir`, to be written as `out` (which the page
/// leaves out of its list of files, and whose folder decides whether it links to them).
pub fn render(dir: &Path, out: &Path) -> Result<String> {
    let expected = || {
        READERS
            .iter()
            .map(|r| r.marks)
            .collect::<Vec<_>>()
            .join("; or ")
    };
    if !dir.is_dir() {
        return Err(Error::NoOutput {
            dir: dir.display().to_string(),
            expected: format!(
                "a directory (it does not exist or is not one) holding {}",
                expected()
            ),
        });
    }
    let same = |a: &Path, b: &Path| match (a.canonicalize(), b.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    };
    let linked = out.parent().is_some_and(|p| {
        same(
            if p.as_os_str().is_empty() {
                Path::new(".")
            } else {
                p
            },
            dir,
        )
    });
    let skip = if linked {
        dir.join(out.file_name().unwrap_or_default())
    } else {
        out.to_path_buf()
    };
    let mut l = Listing::scan(dir, &skip, linked)?;
    let mut parts = Vec::new();
    for r in READERS {
        if let Some(part) = (r.read)(&mut l)? {
            parts.push(part);
        }
    }
    let Some(title) = parts.first().map(|p| p.title.clone()) else {
        return Err(Error::NoOutput {
            dir: dir.display().to_string(),
            expected: expected(),
        });
    };
    let mut sections: Vec<Section> = parts.into_iter().flat_map(|p| p.sections).collect();
    // Every chart is on the page, also one no reader knows.
    let rest: Vec<String> = l
        .svgs_in("", |_| true)
        .into_iter()
        .chain(
            l.files
                .keys()
                .filter(|rel| {
                    rel.contains('/') && rel.ends_with(".svg") && !l.notes.contains_key(*rel)
                })
                .cloned()
                .collect::<Vec<_>>(),
        )
        .collect();
    if !rest.is_empty() {
        let mut html = String::new();
        for rel in rest {
            html.push_str(&l.figure(&rel, "")?);
        }
        sections.push(Section {
            id: "other-charts".into(),
            heading: "Other charts".into(),
            html,
        });
    }
    let source = format!(
        "The files of <code>{}</code>, as written by liftoff; this page by liftoff {}.",
        esc(&dir.display().to_string()),
        env!("CARGO_PKG_VERSION")
    );
    Ok(page::page(&title, &source, &sections, &files(&l)))
}

/// The list of every file in the directory with what the page does with it.
fn files(l: &Listing) -> String {
    let mut rows = Vec::new();
    for (rel, size) in &l.files {
        let how = match l.notes.get(rel) {
            Some(n) => esc(n),
            None => esc(&not_shown(l, rel)),
        };
        rows.push(vec![l.file_ref(rel), size_text(*size), how]);
    }
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<p class=\"note\">Every file of the directory{}. The per-node and per-element tables are too long for a page: open them in a spreadsheet, and <code>plate.vtu</code> in ParaView.</p>",
        if l.linked {
            " (the links open them)"
        } else {
            ""
        }
    );
    s.push_str(&page::table(&["file", "size", "on this page"], &rows));
    s
}

/// Why a file is not on the page.
fn not_shown(l: &Listing, rel: &str) -> String {
    let name = rel.rsplit('/').next().unwrap_or(rel);
    if name.ends_with(".vtu") {
        return "not shown: the ParaView grid".into();
    }
    if name.ends_with(".png") {
        return "not shown: an image (the charts are shown from their SVG)".into();
    }
    if name.ends_with(".csv") {
        return match l.csv_rows(rel) {
            Ok(n) => format!("not shown: {n} rows"),
            Err(_) => "not shown".into(),
        };
    }
    "not shown".into()
}

/// A file size in B, kB or MB.
fn size_text(bytes: u64) -> String {
    match bytes {
        b if b < 1000 => format!("{b} B"),
        b if b < 1_000_000 => format!("{:.1} kB", b as f64 / 1e3),
        b => format!("{:.1} MB", b as f64 / 1e6),
    }
}

#[cfg(test)]
mod tests {
    use super::markup::inline_svg;

    /// Ids and the references to them get the prefix; the prolog, comments, scripts, event
    /// attributes and external references go; text is escaped again.
    #[test]
    fn an_svg_is_inlined_clean() {
        let svg = r##"<?xml version="1.0" encoding="UTF-8"?>
<!-- a comment -->
<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" width="90" height="70" onload="alert(1)">
<defs><pattern id="hatch"><path d="M0 0"/></pattern></defs>
<rect fill="url(#hatch)" style="fill: url('#hatch')"/>
<use xlink:href="#hatch"/><image href="http://example.com/a.png"/>
<script>alert(2)</script><foreignObject><p>x</p></foreignObject>
<text>a &lt;b&gt; &amp; &#233; &quot;</text>
</svg>"##;
        let out = inline_svg(svg, "f3-").expect("inlined");
        for gone in [
            "<?xml",
            "comment",
            "xmlns",
            "onload",
            "http",
            "script",
            "alert",
            "foreignObject",
            "<p>",
        ] {
            assert!(!out.contains(gone), "`{gone}` left in: {out}");
        }
        for kept in [
            "id=\"f3-hatch\"",
            "fill=\"url(#f3-hatch)\"",
            "style=\"fill: url(&#39;#f3-hatch&#39;)\"",
            "xlink:href=\"#f3-hatch\"",
            "viewBox=\"0 0 90 70\"",
            "<text>a &lt;b&gt; &amp; é &quot;</text>",
        ] {
            assert!(out.contains(kept), "`{kept}` missing: {out}");
        }
        assert!(out.starts_with("<svg "), "{out}");
        assert!(out.ends_with("</svg>"), "{out}");
    }

    /// Not an SVG: refused, so that nothing else goes into the page as a figure.
    #[test]
    fn a_file_that_is_not_an_svg_is_refused() {
        assert!(inline_svg("<html><body/></html>", "f1-").is_err());
        assert!(inline_svg("<svg><g></svg>", "f1-").is_err());
        assert!(inline_svg("plain text", "f1-").is_err());
    }
}
