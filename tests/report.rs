//! `liftoff report` and `--report`: the page holds every SVG chart of the directory inline, its
//! numbers are summary.json's and critical.json's (read back from the HTML, the JSON files the
//! reference), text from the scene is escaped, and nothing is loaded from anywhere. (That the
//! page opens in a browser without errors is python/tests/test_report_page.py, in headless
//! Chromium.)

use std::path::Path;
use std::process::Command;

use serde_json::Value;

fn liftoff(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_liftoff"))
        .args(args)
        .output()
        .expect("run liftoff")
}

fn run(args: &[&str]) -> String {
    let o = liftoff(args);
    assert!(
        o.status.success(),
        "liftoff {args:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn read(p: &Path) -> String {
    std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

fn json(p: &Path) -> Value {
    serde_json::from_str(&read(p)).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// Every SVG file under `dir` (and one level down), relative, `/`-separated.
fn svgs(dir: &Path) -> Vec<String> {
    let mut out = Vec::new();
    let mut stack = vec![(dir.to_path_buf(), String::new())];
    while let Some((d, prefix)) = stack.pop() {
        for e in std::fs::read_dir(&d).expect("read_dir").flatten() {
            let name = e.file_name().to_string_lossy().into_owned();
            if e.path().is_dir() {
                stack.push((e.path(), format!("{prefix}{name}/")));
            } else if name.ends_with(".svg") {
                out.push(format!("{prefix}{name}"));
            }
        }
    }
    out.sort();
    out
}

/// The figures of the page: (the file its caption names, its HTML).
fn figures(html: &str) -> Vec<(String, String)> {
    html.split("<figure class=\"chart\"")
        .skip(1)
        .map(|f| {
            let f = f.split("</figure>").next().unwrap_or_default();
            let caption = f.split("<figcaption>").nth(1).unwrap_or_default();
            let file = caption
                .split("<code>")
                .nth(1)
                .and_then(|c| c.split("</code>").next())
                .unwrap_or_default();
            (file.to_string(), f.to_string())
        })
        .collect()
}

/// How many elements of each drawing kind a piece of SVG holds.
fn shapes(svg: &str) -> Vec<usize> {
    [
        "<rect",
        "<polygon",
        "<polyline",
        "<path",
        "<circle",
        "<line ",
        "<text",
    ]
    .iter()
    .map(|tag| svg.matches(tag).count())
    .collect()
}

/// The rows of the page's number tables: (data-key, data-value, the shown value's text).
fn numbers(html: &str) -> Vec<(String, String, String)> {
    html.split("<tr data-key=\"")
        .skip(1)
        .filter_map(|r| {
            let (key, rest) = r.split_once('"')?;
            let value = rest.split("data-value=\"").nth(1)?.split('"').next()?;
            let shown = rest
                .split("<td class=\"value\">")
                .nth(1)?
                .split("</td>")
                .next()?;
            Some((key.to_string(), value.to_string(), shown.to_string()))
        })
        .collect()
}

/// The JSON value at a dotted path (`moments.mx.1`).
fn at<'a>(v: &'a Value, path: &str) -> Option<&'a Value> {
    path.split('.')
        .try_fold(v, |v, k| match k.parse::<usize>() {
            Ok(i) if v.is_array() => v.get(i),
            _ => v.get(k),
        })
}

/// The number and the unit of a shown value (`0.3108 mm`, `95.24 %`).
fn shown_number(s: &str) -> (f64, String) {
    let mut parts = s.split('\u{202F}');
    let n = parts
        .next()
        .unwrap_or_default()
        .parse::<f64>()
        .unwrap_or(f64::NAN);
    (n, parts.next().unwrap_or_default().to_string())
}

/// Nothing on the page is fetched from anywhere, and nothing runs. Text is escaped, so every
/// `<` of the page opens a tag: the tags are checked for elements and attributes that load or
/// run something, the whole page for addresses.
fn assert_self_contained(html: &str, what: &str) {
    let lower = html.to_lowercase();
    for bad in ["http://", "https://", "@import", "javascript:"] {
        assert!(!lower.contains(bad), "{what}: the page holds `{bad}`");
    }
    for tag in lower
        .split('<')
        .skip(1)
        .map(|t| t.split('>').next().unwrap_or_default())
    {
        let name = tag.split([' ', '\n', '/']).next().unwrap_or_default();
        assert!(
            !["script", "link", "iframe", "object", "embed", "img", "image", "style"]
                .contains(&name)
                || (name == "style" && tag == "style"),
            "{what}: a <{name}> element"
        );
        assert!(!tag.contains(" src="), "{what}: src= in <{tag}>");
        for token in tag.split_whitespace() {
            let attribute = token.split_once('=').map_or("", |(name, _)| name);
            assert!(
                !attribute.starts_with("on"),
                "{what}: an event attribute in <{tag}>"
            );
        }
    }
    // url(…) only to an id of the page itself.
    for (i, _) in lower.match_indices("url(") {
        let rest = lower[i + 4..].trim_start_matches(['\'', '"', ' ']);
        assert!(
            rest.starts_with('#'),
            "{what}: url({})",
            &rest[..rest.len().min(40)]
        );
    }
}

/// Every SVG of `dir` is inlined once, with all its drawing.
fn assert_every_svg_inline(dir: &Path, html: &str) {
    let files = svgs(dir);
    let figs = figures(html);
    assert_eq!(
        figs.len(),
        files.len(),
        "{}: {} figures for the SVG files {files:?}",
        dir.display(),
        figs.len()
    );
    assert_eq!(
        html.matches("<svg").count(),
        files.len(),
        "one <svg> per file"
    );
    for f in &files {
        let Some((_, fig)) = figs.iter().find(|(file, _)| file == f) else {
            panic!("{f}: no figure names it");
        };
        assert_eq!(
            shapes(fig),
            shapes(&read(&dir.join(f))),
            "{f}: drawing inlined whole"
        );
    }
    // Ids cannot clash between figures.
    let mut ids: Vec<&str> = html
        .split(" id=\"")
        .skip(1)
        .filter_map(|s| s.split('"').next())
        .collect();
    let n = ids.len();
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids.len(), n, "every id on the page is unique");
}

/// The engineering value shown for a key of summary.json: its factor from SI and its unit.
fn engineering(key: &str) -> Option<(f64, &'static str)> {
    Some(match key {
        "w_max" => (1e3, "mm"),
        "pressure_max" => (1e-3, "kPa"),
        "stresses.bottom.value" | "stresses.top.value" => (1e-6, "MPa"),
        k if k.starts_with("moments.") => (1e-3, "kN·m/m"),
        "resultant.load" | "resultant.reaction" => (1e-3, "kN"),
        "contact_fraction" => (100.0, "%"),
        "V_max" | "resultant.relative_error" | "dimensionless.gamma" => (1.0, ""),
        "stresses.thickness" => (1.0, "m"),
        _ => return None,
    })
}

/// The rows of a summary on the page hold summary.json's numbers: the exact digits in
/// data-value, and the shown value within its four digits.
fn assert_summary_numbers(html: &str, summary: &Value, what: &str) -> usize {
    let rows = numbers(html);
    let mut checked = 0;
    for key in [
        "w_max",
        "pressure_max",
        "stresses.bottom.value",
        "moments.mx.1",
        "contact_fraction",
        "resultant.load",
    ] {
        assert!(
            rows.iter().any(|(k, _, _)| k == key),
            "{what}: no row for {key}"
        );
    }
    for (key, value, shown) in &rows {
        let Some(reference) = at(summary, key).and_then(Value::as_f64) else {
            continue;
        };
        let exact: f64 = value.parse().unwrap_or(f64::NAN);
        assert_eq!(
            exact.to_bits(),
            reference.to_bits(),
            "{what}: {key} = {value}, summary.json {reference}"
        );
        let Some((factor, unit)) = engineering(key) else {
            panic!("{what}: {key} has no expected unit in this test");
        };
        let (n, u) = shown_number(shown);
        let expected = reference * factor;
        assert!(
            (n - expected).abs() <= 5e-4 * expected.abs() + 1e-300,
            "{what}: {key} shown as {shown}, summary.json gives {expected} {unit}"
        );
        assert_eq!(u, unit, "{what}: {key}'s unit");
        checked += 1;
    }
    checked
}

fn scene(title: &str) -> String {
    let text = liftoff::examples::scene("slab-on-grade").unwrap_or_default();
    let line = text
        .lines()
        .find(|l| l.starts_with("title = "))
        .unwrap_or_default();
    text.replacen(line, &format!("title = {}", toml_string(title)), 1)
}

fn toml_string(s: &str) -> String {
    format!("\"{}\"", s.replace('\\', "\\\\").replace('"', "\\\""))
}

/// A single solve: `--report` writes report.html with the summary's numbers, every chart, and
/// a scene title full of markup as text.
#[test]
fn a_solve_report_holds_the_summary_and_every_chart_escaped() {
    let tmp = tempfile::tempdir().expect("tempdir");
    let title = "<script>alert(1)</script> & \"quotes\" <img src=x onerror=alert(2)>";
    let path = tmp.path().join("scene.toml");
    std::fs::write(&path, scene(title)).expect("write scene");
    let out = tmp.path().join("slab");
    let printed = run(&[
        "solve",
        path.to_str().unwrap_or_default(),
        "--out",
        out.to_str().unwrap_or_default(),
        "--report",
    ]);
    assert!(
        printed.contains("files      : 11 in"),
        "report.html counted: {printed}"
    );
    let html = read(&out.join("report.html"));
    assert_self_contained(&html, "solve");
    assert_every_svg_inline(&out, &html);
    let summary = json(&out.join("summary.json"));
    let n = assert_summary_numbers(&html, &summary, "solve");
    assert!(n >= 12, "{n} numbers checked");
    let escaped = "&lt;script&gt;alert(1)&lt;/script&gt; &amp; &quot;quotes&quot; &lt;img src=x onerror=alert(2)&gt;";
    assert!(
        html.contains(&format!("<title>{escaped}</title>")),
        "the title, escaped"
    );
    assert!(
        html.contains(&format!("<h1>{escaped}</h1>")),
        "the heading, escaped"
    );
    // Every file is listed, the big ones as not shown.
    for f in ["nodes.csv", "elements.csv", "plate.vtu", "contact.png"] {
        assert!(
            html.contains(&format!("<a href=\"{f}\"><code>{f}</code></a>")),
            "{f} linked"
        );
    }
    assert!(html.contains("not shown: the ParaView grid"));
}

/// A jointed pavement over two combinations: a section per combination with its summary and
/// joints (the per-joint numbers of summary.json, the dowels of dowels.csv), the envelope.
#[test]
fn a_report_of_combinations_has_each_combination_and_the_joints() {
    let tmp = tempfile::tempdir().expect("tempdir");
    let out = tmp.path().join("pavement");
    run(&[
        "solve",
        "example:pavement-3x3",
        "--out",
        out.to_str().unwrap_or_default(),
    ]);
    let report = tmp.path().join("elsewhere").join("page.html");
    let printed = run(&[
        "report",
        out.to_str().unwrap_or_default(),
        "--out",
        report.to_str().unwrap_or_default(),
    ]);
    assert!(printed.contains("page.html"), "{printed}");
    assert!(!out.join("report.html").exists(), "--out puts it elsewhere");
    let html = read(&report);
    assert_self_contained(&html, "combinations");
    assert_every_svg_inline(&out, &html);
    // Away from the files, the page names them without links.
    assert!(!html.contains("href=\"axle/"), "no links from elsewhere");
    let envelope = json(&out.join("envelope.json"));
    let names: Vec<&str> = envelope["combinations"]
        .as_array()
        .map(|a| a.iter().filter_map(|c| c["name"].as_str()).collect())
        .unwrap_or_default();
    assert_eq!(names, ["axle", "axle-night"]);
    for name in names {
        let summary = json(&out.join(name).join("summary.json"));
        let section = html
            .split(&format!("<h2>{name}: Summary</h2>"))
            .nth(1)
            .and_then(|s| s.split("</section>").next())
            .unwrap_or_else(|| panic!("no summary section for {name}"));
        assert!(assert_summary_numbers(section, &summary, name) >= 12);
        let joints = html
            .split(&format!("<h2>{name}: Joints</h2>"))
            .nth(1)
            .and_then(|s| s.split("</section>").next())
            .unwrap_or_else(|| panic!("no joints section for {name}"));
        for j in summary["joints"].as_array().into_iter().flatten() {
            let jname = j["name"].as_str().unwrap_or_default();
            assert!(
                joints.contains(&format!("<td>{jname}</td>")),
                "{name}: joint {jname}"
            );
        }
        // The dowels table: one row per bar of dowels.csv.
        let bars = read(&out.join(name).join("dowels.csv")).lines().count() - 1;
        let table = joints.split("<h3>Dowels</h3>").nth(1).unwrap_or_default();
        assert_eq!(
            table.matches("<tr><td>").count(),
            bars,
            "{name}: dowel rows"
        );
    }
}

/// `critical --report`: the critical positions with critical.json's values, the influence maps.
#[test]
fn a_critical_report_holds_the_critical_positions() {
    let tmp = tempfile::tempdir().expect("tempdir");
    let out = tmp.path().join("critical");
    run(&[
        "critical",
        "example:pavement-3x3",
        "--load",
        "axle",
        "--grid",
        "3,3",
        "--out",
        out.to_str().unwrap_or_default(),
        "--report",
    ]);
    let html = read(&out.join("report.html"));
    assert_self_contained(&html, "critical");
    assert_every_svg_inline(&out, &html);
    let c = json(&out.join("critical.json"));
    let rows = numbers(&html);
    let mut checked = 0;
    for (key, field, factor) in [
        ("bottom", "bottom", 1e-6),
        ("top", "top", 1e-6),
        ("deflection", "w_max", 1e3),
        ("joint_shear", "joint_shear", 1e-3),
        ("dowel_force", "dowel_force", 1e-3),
    ] {
        let i = c[key]
            .as_u64()
            .unwrap_or_else(|| panic!("critical.json {key}")) as usize;
        let reference = c["positions"][i][field].as_f64().unwrap_or(f64::NAN);
        let Some((_, value, shown)) = rows
            .iter()
            .find(|(k, _, _)| k == &format!("critical.{key}"))
        else {
            panic!("no row for {key}");
        };
        assert_eq!(
            value.parse::<f64>().map(f64::to_bits),
            Ok(reference.to_bits()),
            "{key}"
        );
        let (n, _) = shown_number(shown);
        assert!(
            (n - reference * factor).abs() <= 5e-4 * (reference * factor).abs(),
            "{key}: {shown}"
        );
        checked += 1;
    }
    assert_eq!(checked, 5);
}
