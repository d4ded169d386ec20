//! Markup that goes into `report.html` from text and files: text escaped for HTML, and SVG
//! charts rewritten as inline elements (well-formed, without scripts, external references or
//! colliding ids). The folder's lowest layer: it imports none of its siblings; `page.rs` builds
//! on it and hands `esc` on to the sections.

use std::fmt::Write as _;

use quick_xml::events::{BytesStart, Event};
use quick_xml::Reader;

/// Text escaped for HTML content and attribute values.
pub(crate) fn esc(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    push_escaped(&mut out, s);
    out
}

fn push_escaped(out: &mut String, s: &str) {
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
}

/// Why an SVG could not be inlined.
type SvgResult<T> = std::result::Result<T, String>;

/// An SVG document as an element to inline in HTML: the root `<svg>` and its content written
/// back from quick-xml's events, so that what goes into the page is well-formed and escaped
/// whatever the file holds. Dropped: the XML prolog, doctype, comments and processing
/// instructions, `xmlns` attributes (the HTML parser puts `<svg>` in the SVG namespace), any
/// `script` or `foreignObject` element with its content, event attributes (`on…`), and
/// references that leave the document (an `href` that is not `#…` or `data:`, a `url(…)` that is
/// not `url(#…)`). Ids and the references to them get `prefix`.
pub(crate) fn inline_svg(text: &str, prefix: &str) -> SvgResult<String> {
    let mut reader = Reader::from_str(text);
    let mut out = String::with_capacity(text.len());
    // Depth inside a dropped element, and whether the root was seen.
    let mut dropped = 0usize;
    let mut depth = 0usize;
    let mut root = false;
    loop {
        let event = reader.read_event().map_err(|e| e.to_string())?;
        match event {
            Event::Start(e) => {
                // An element opened inside a dropped one, or a dropped one itself.
                if dropped > 0 || banned(&e) {
                    dropped += 1;
                    continue;
                }
                top_level(&e, root, depth)?;
                write_start(&mut out, &e, prefix, !root)?;
                root = true;
                depth += 1;
                out.push('>');
            }
            Event::Empty(e) => {
                if dropped > 0 || banned(&e) {
                    continue;
                }
                top_level(&e, root, depth)?;
                write_start(&mut out, &e, prefix, !root)?;
                root = true;
                out.push_str("/>");
            }
            Event::End(e) => {
                if dropped > 0 {
                    dropped -= 1;
                    continue;
                }
                depth = depth.saturating_sub(1);
                let name = std::str::from_utf8(e.name().as_ref())
                    .map_err(|e| e.to_string())?
                    .to_string();
                let _ = write!(out, "</{name}>");
            }
            Event::Text(t) if dropped == 0 && root => {
                push_escaped(&mut out, &t.decode().map_err(|e| e.to_string())?);
            }
            Event::CData(t) if dropped == 0 && root => {
                push_escaped(&mut out, &t.decode().map_err(|e| e.to_string())?);
            }
            Event::GeneralRef(r) if dropped == 0 && root => {
                let c = match r.resolve_char_ref().map_err(|e| e.to_string())? {
                    Some(c) => c.to_string(),
                    None => {
                        let name = r.decode().map_err(|e| e.to_string())?;
                        quick_xml::escape::resolve_predefined_entity(&name)
                            .ok_or_else(|| format!("unknown entity &{name};"))?
                            .to_string()
                    }
                };
                push_escaped(&mut out, &c);
            }
            Event::Eof => break,
            _ => {}
        }
    }
    if !root {
        return Err("no <svg> element".into());
    }
    if depth != 0 || dropped != 0 {
        return Err("the document ends inside an element".into());
    }
    Ok(out)
}

/// The document's one top-level element is `<svg>`.
fn top_level(e: &BytesStart, root: bool, depth: usize) -> SvgResult<()> {
    if depth > 0 {
        return Ok(());
    }
    if root {
        return Err("more than one top-level element".into());
    }
    if e.local_name().as_ref() != b"svg" {
        return Err("the top-level element is not <svg>".into());
    }
    Ok(())
}

/// Elements that never go into the page: scripts, and HTML smuggled in through
/// `foreignObject`.
fn banned(e: &BytesStart) -> bool {
    let name = e.local_name();
    let name = name.as_ref();
    name.eq_ignore_ascii_case(b"script") || name.eq_ignore_ascii_case(b"foreignObject")
}

/// Write `<name attr="value"…` (without the closing `>`): each value unescaped by quick-xml
/// and escaped again here; see [`inline_svg`] for what is dropped and prefixed. The root gets a
/// `viewBox` from its size when it has none, so that the page can scale it.
fn write_start(out: &mut String, e: &BytesStart, prefix: &str, is_root: bool) -> SvgResult<()> {
    let name = std::str::from_utf8(e.name().as_ref())
        .map_err(|e| e.to_string())?
        .to_string();
    let _ = write!(out, "<{name}");
    let mut size = (None, None);
    let mut view_box = false;
    for a in e.attributes() {
        let a = a.map_err(|e| e.to_string())?;
        let key = std::str::from_utf8(a.key.as_ref())
            .map_err(|e| e.to_string())?
            .to_string();
        let value = a
            .normalized_value(quick_xml::XmlVersion::Explicit1_0)
            .map_err(|e| e.to_string())?;
        let lower = key.to_ascii_lowercase();
        if lower == "xmlns" || lower.starts_with("xmlns:") || lower.starts_with("on") {
            continue;
        }
        let value = if lower == "id" {
            format!("{prefix}{value}")
        } else if lower == "href" || lower.ends_with(":href") {
            match value.strip_prefix('#') {
                Some(id) => format!("#{prefix}{id}"),
                None if value.trim_start().starts_with("data:") => value.into_owned(),
                None => continue,
            }
        } else {
            match local_urls(&value, prefix) {
                Some(v) => v,
                None => continue,
            }
        };
        if is_root {
            match lower.as_str() {
                "width" => size.0 = value.trim().parse::<f64>().ok(),
                "height" => size.1 = value.trim().parse::<f64>().ok(),
                "viewbox" => view_box = true,
                _ => {}
            }
        }
        let _ = write!(out, " {key}=\"{}\"", esc(&value));
    }
    if let (true, false, (Some(w), Some(h))) = (is_root, view_box, size) {
        let _ = write!(out, " viewBox=\"0 0 {w} {h}\"");
    }
    Ok(())
}

/// `value` with every `url(#id)` made `url(#{prefix}id)`; None when it holds a `url(…)` to
/// anything but an id of the document (which would load a resource).
fn local_urls(value: &str, prefix: &str) -> Option<String> {
    let mut out = String::with_capacity(value.len());
    let mut rest = value;
    while let Some(i) = rest.find("url(") {
        out.push_str(&rest[..i + 4]);
        rest = rest[i + 4..].trim_start();
        if let Some(q) = rest.chars().next().filter(|c| matches!(c, '\'' | '"')) {
            out.push(q);
            rest = &rest[1..];
        }
        let id = rest.strip_prefix('#')?;
        out.push('#');
        out.push_str(prefix);
        rest = id;
    }
    out.push_str(rest);
    Some(out)
}
