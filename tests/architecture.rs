//! docs/ARCHITECTURE.md against the code, so that the page cannot drift silently.
//!
//! **Every file is named in its row** (`every_source_file_is_named_in_its_row`). The module map
//! is the table under `## Module map`; a row's first cell names one or more modules in
//! backticks (before any parenthesis, which may say more: "(feature `cli`)"). Each `.rs` file under `src/` belongs to one row, and is named in it:
//!
//! * `src/lib.rs`: the row whose first cell names `lib.rs`;
//! * `src/X.rs`: the row whose first cell names `X` — that names the file;
//! * `src/X/mod.rs`: the row whose first cell names `X/` — that names the file;
//! * `src/X/…/Y/mod.rs`: the row of `X/`, which names `Y/` anywhere in it;
//! * `src/X/…/F.rs`: the row of `X/`, which names `F.rs` anywhere in it;
//! * `src/bin/B/…/F.rs`: the row whose first cell names `src/bin/B/`, which names `F.rs`.
//!
//! A name counts where it stands as a word (not preceded or followed by a letter, a digit or
//! `_`; a path such as `chart/style.rs` names `style.rs`). And the other way: every module a
//! first cell names (an identifier, a folder `…/` or a `….rs`) exists, so a row outlives
//! no file.
//!
//! **serde spells the `names!` words** (`serde_names_match_choice_names`). An enum given to
//! `names!` has one list of words (`Choice`) that clap, `Display`/`FromStr` and the reports
//! read; serde derives its own from `#[serde(rename_all = …)]`. For every such enum this test
//! serialises each variant (where the enum is `Serialize`) and deserialises each word (where
//! it is `Deserialize`) and compares; it lists the enums by hand and fails when a `names!(`
//! in `src/` names one it does not list.

use std::collections::BTreeSet;
use std::fmt::Debug;
use std::path::{Path, PathBuf};

use liftoff::choice::Choice;
use serde::de::DeserializeOwned;
use serde::Serialize;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Every `.rs` file under `dir`, as paths relative to `base` with `/` separators.
fn rust_files(dir: &Path, base: &Path, out: &mut Vec<String>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            rust_files(&p, base, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            let rel = p.strip_prefix(base).expect("under base");
            let parts: Vec<String> = rel
                .components()
                .map(|c| c.as_os_str().to_string_lossy().into_owned())
                .collect();
            out.push(parts.join("/"));
        }
    }
}

/// One row of the module map: the modules its first cell names and the whole line.
struct Row {
    modules: Vec<String>,
    text: String,
}

/// The spans between backticks in `s`.
fn backticked(s: &str) -> Vec<String> {
    s.split('`')
        .skip(1)
        .step_by(2)
        .map(|t| t.trim().to_string())
        .collect()
}

fn module_map() -> Vec<Row> {
    let page =
        std::fs::read_to_string(root().join("docs/ARCHITECTURE.md")).expect("docs/ARCHITECTURE.md");
    let start = page
        .find("\n## Module map")
        .expect("a `## Module map` section");
    let section = &page[start + 1..];
    let section = match section[3..].find("\n## ") {
        Some(end) => &section[..end + 3],
        None => section,
    };
    let rows: Vec<Row> = section
        .lines()
        .filter(|l| l.starts_with('|') && !l.starts_with("|---") && !l.starts_with("| module |"))
        .map(|l| {
            let first = l[1..].split('|').next().unwrap_or("");
            let first = first.split('(').next().unwrap_or("");
            Row {
                modules: backticked(first),
                text: l.to_string(),
            }
        })
        .collect();
    assert!(rows.len() > 10, "the module map has {} rows", rows.len());
    rows
}

/// Whether `name` stands in `text` as a word of its own.
fn names(text: &str, name: &str) -> bool {
    let word = |c: char| c.is_alphanumeric() || c == '_';
    text.match_indices(name).any(|(i, _)| {
        let before = text[..i].chars().next_back();
        let after = text[i + name.len()..].chars().next();
        !before.is_some_and(word) && !after.is_some_and(|c| word(c) && !name.ends_with('/'))
    })
}

/// The row a file of `src/` belongs to (its first cell's module) and the name the row must
/// give it, if the first cell does not already.
fn row_and_name(file: &str) -> (String, Option<String>) {
    let parts: Vec<&str> = file.split('/').collect();
    let last = parts[parts.len() - 1];
    if parts.len() == 1 {
        let module = if last == "lib.rs" {
            last.to_string()
        } else {
            last.trim_end_matches(".rs").to_string()
        };
        return (module, None);
    }
    let (row, depth) = if parts[0] == "bin" && parts.len() > 2 {
        (format!("src/bin/{}/", parts[1]), 2)
    } else {
        (format!("{}/", parts[0]), 1)
    };
    if last == "mod.rs" {
        if parts.len() == depth + 1 {
            (row, None)
        } else {
            (row, Some(format!("{}/", parts[parts.len() - 2])))
        }
    } else {
        (row, Some(last.to_string()))
    }
}

#[test]
fn every_source_file_is_named_in_its_row() {
    let rows = module_map();
    let src = root().join("src");
    let mut files = Vec::new();
    rust_files(&src, &src, &mut files);
    assert!(
        files.iter().any(|f| f == "lib.rs"),
        "no src/lib.rs among {files:?}"
    );

    let mut missing = Vec::new();
    for file in &files {
        let (module, name) = row_and_name(file);
        let Some(row) = rows.iter().find(|r| r.modules.contains(&module)) else {
            missing.push(format!(
                "src/{file}: no row of the module map names `{module}` in its first cell"
            ));
            continue;
        };
        if let Some(name) = name {
            if !names(&row.text, &name) {
                missing.push(format!(
                    "src/{file}: the row of `{module}` does not name `{name}`"
                ));
            }
        }
    }

    let mut stale = Vec::new();
    for row in &rows {
        for m in &row.modules {
            let is_module = m.ends_with('/')
                || m.ends_with(".rs")
                || m.chars()
                    .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_');
            if !is_module {
                continue;
            }
            let exists = if m.ends_with('/') || m.ends_with(".rs") {
                src.join(m).exists() || root().join(m).exists()
            } else {
                src.join(format!("{m}.rs")).exists() || src.join(m).join("mod.rs").exists()
            };
            if !exists {
                stale.push(format!("the row of `{m}` names no file or folder of src/"));
            }
        }
    }

    assert!(
        missing.is_empty() && stale.is_empty(),
        "docs/ARCHITECTURE.md's module map is out of date (every file of src/ is named in its \
         module's row; see the rule at the top of tests/architecture.rs):\n{}",
        missing
            .iter()
            .chain(&stale)
            .map(|s| format!("  {s}"))
            .collect::<Vec<_>>()
            .join("\n")
    );
}

#[test]
fn the_module_map_rule_reads_paths_as_meant() {
    assert_eq!(row_and_name("lib.rs"), ("lib.rs".into(), None));
    assert_eq!(row_and_name("entry.rs"), ("entry".into(), None));
    assert_eq!(row_and_name("scene/mod.rs"), ("scene/".into(), None));
    assert_eq!(
        row_and_name("scene/vehicles.rs"),
        ("scene/".into(), Some("vehicles.rs".into()))
    );
    assert_eq!(
        row_and_name("foundation/fft/mod.rs"),
        ("foundation/".into(), Some("fft/".into()))
    );
    assert_eq!(
        row_and_name("solve/qp/active_set/run.rs"),
        ("solve/".into(), Some("run.rs".into()))
    );
    assert_eq!(
        row_and_name("bin/liftoff/main.rs"),
        ("src/bin/liftoff/".into(), Some("main.rs".into()))
    );
    assert!(names("`chart/` (`style.rs` …)", "style.rs"));
    assert!(names("`output/chart/style.rs`", "style.rs"));
    assert!(names("`fft/tests.rs`", "fft/"));
    assert!(!names("`bonded_springs.rs`", "springs.rs"));
    assert!(!names("`primal_dual_run.rs`", "run.rs"));
}

/// Each variant serialises to its `names!` word.
fn serialises_as_named<T: Choice + Serialize + Debug>(what: &str, wrong: &mut Vec<String>) {
    for &v in T::ALL {
        let got = serde_json::to_value(v).expect("serialise");
        if got != serde_json::Value::String(v.choice_name().into()) {
            wrong.push(format!(
                "{what}::{v:?}: serde writes {got}, names! says \"{}\"",
                v.choice_name()
            ));
        }
    }
}

/// Each `names!` word deserialises to its variant.
fn deserialises_as_named<T: Choice + DeserializeOwned + Debug>(
    what: &str,
    wrong: &mut Vec<String>,
) {
    for &v in T::ALL {
        let word = v.choice_name();
        match serde_json::from_value::<T>(serde_json::Value::String(word.into())) {
            Ok(back) if back == v => {}
            Ok(back) => wrong.push(format!(
                "{what}: serde reads \"{word}\" as {back:?}, not {v:?}"
            )),
            Err(e) => wrong.push(format!("{what}: serde refuses \"{word}\" ({v:?}): {e}")),
        }
    }
}

#[test]
fn serde_names_match_choice_names() {
    let mut listed: BTreeSet<&str> = BTreeSet::new();
    let mut wrong = Vec::new();
    // Serialize and Deserialize.
    macro_rules! both {
        ($($t:ty),+ $(,)?) => {$(
            listed.insert(stringify!($t).rsplit("::").next().unwrap());
            serialises_as_named::<$t>(stringify!($t), &mut wrong);
            deserialises_as_named::<$t>(stringify!($t), &mut wrong);
        )+};
    }
    // Serialize only (reports, summary.json).
    macro_rules! written {
        ($($t:ty),+ $(,)?) => {$(
            listed.insert(stringify!($t).rsplit("::").next().unwrap());
            serialises_as_named::<$t>(stringify!($t), &mut wrong);
        )+};
    }
    // Deserialize only (scene files, options).
    macro_rules! read {
        ($($t:ty),+ $(,)?) => {$(
            listed.insert(stringify!($t).rsplit("::").next().unwrap());
            deserialises_as_named::<$t>(stringify!($t), &mut wrong);
        )+};
    }
    // Not serde at all: only its words exist, nothing to compare.
    macro_rules! not_serde {
        ($($t:ty),+ $(,)?) => {$(
            listed.insert(stringify!($t).rsplit("::").next().unwrap());
            assert!(!<$t as Choice>::names().is_empty());
        )+};
    }
    both!(
        liftoff::units::UnitSystem,
        liftoff::model::ConstraintPoints,
        liftoff::model::SymmetryMode,
        liftoff::layout::JointType,
        liftoff::method::Contact,
        liftoff::method::MethodKind,
        liftoff::method::Start,
        liftoff::method::Route,
        liftoff::method::QpForm,
        liftoff::method::QpSolver,
        liftoff::foundation::FoundationKind,
        liftoff::study::Ends,
    );
    written!(
        liftoff::error::ErrorKind,
        liftoff::method::SolvedBy,
        liftoff::solve::StatusKind,
        liftoff::study::StabilityParam,
        liftoff::backcalc::BackcalcMethod,
        liftoff::backcalc::Location,
        liftoff::backcalc::Termination,
        liftoff::backcalc::Unknown,
    );
    read!(liftoff::study::ConstraintVariants, liftoff::scene::LoadKind,);
    // Progress events are shown, never stored: "penalty step", "active-set face solve".
    not_serde!(liftoff::monitor::StepKind);

    // Every `names!(Type, …)` of src/ is listed above.
    let src = root().join("src");
    let mut files = Vec::new();
    rust_files(&src, &src, &mut files);
    let mut unlisted = BTreeSet::new();
    for file in &files {
        let text = std::fs::read_to_string(src.join(file)).expect("source file");
        for (i, _) in text.match_indices("names!(") {
            let ty: String = text[i + "names!(".len()..]
                .trim_start()
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            if !ty.is_empty() && !listed.contains(ty.as_str()) {
                unlisted.insert(format!("{ty} (src/{file})"));
            }
        }
    }
    assert!(
        unlisted.is_empty(),
        "enums given to names! that tests/architecture.rs does not check: {unlisted:?}; add each \
         to `both!`, `written!`, `read!` or `not_serde!` by the serde traits it derives"
    );
    assert!(
        wrong.is_empty(),
        "serde and names! spell these differently (fix the `#[serde(rename_all)]` or a \
         `#[serde(rename)]`, or the names! word):\n  {}",
        wrong.join("\n  ")
    );
}

/// Every `tests/X.rs` is a module of the one test binary, `tests/suite.rs` (`autotests =
/// false`: cargo no longer finds test files by itself, so a file left out would never run).
#[test]
fn every_test_file_is_a_module_of_the_suite() {
    let tests = root().join("tests");
    let suite = std::fs::read_to_string(tests.join("suite.rs")).expect("tests/suite.rs");
    let declared: BTreeSet<String> = suite
        .lines()
        .filter_map(|l| l.trim().strip_prefix("mod "))
        .filter_map(|l| l.strip_suffix(';'))
        .map(str::to_string)
        .collect();
    let mut missing = Vec::new();
    let mut entries: Vec<PathBuf> = std::fs::read_dir(&tests)
        .expect("tests/")
        .map(|e| e.expect("directory entry").path())
        .collect();
    entries.sort();
    for p in entries {
        let (Some(stem), Some("rs")) = (
            p.file_stem().and_then(|s| s.to_str()),
            p.extension().and_then(|s| s.to_str()),
        ) else {
            continue;
        };
        if stem != "suite" && !declared.contains(stem) {
            missing.push(format!("tests/{stem}.rs"));
        }
    }
    assert!(
        missing.is_empty(),
        "not modules of tests/suite.rs, so never run: {missing:?}; add `mod NAME;` there"
    );
    // And the other way: every module declared is a file (or the folder `common/`).
    for name in &declared {
        assert!(
            tests.join(format!("{name}.rs")).is_file() || tests.join(name).join("mod.rs").is_file(),
            "tests/suite.rs declares `mod {name};` but there is no tests/{name}.rs"
        );
    }
}
