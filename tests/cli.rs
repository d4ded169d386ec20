//! The command-line tool end to end: bundled examples, outputs, exit codes, no partial files.

use crate::common;

use std::path::Path;
use std::process::Command;

fn liftoff(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_liftoff"))
        .args(args)
        .output()
        .expect("run liftoff")
}

fn stdout(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Every bundled example solves with both methods, writes the full result set, and pins one
/// number: the two methods' V_max agree to O(ε̄) (1e-5 → 1e-3 relative, see tests/unbonded.rs).
#[test]
fn bundled_examples_run_and_write_their_files() {
    let dir = tempfile::tempdir().expect("tempdir");
    for (name, _, text) in liftoff::examples::SCENES {
        let root = dir.path().join(name);
        let combinations: Vec<String> = liftoff::Problem::from_toml(text)
            .map(|p| p.combinations.into_iter().map(|c| c.name).collect())
            .unwrap_or_default();
        let out = root.clone();
        let o = liftoff(&[
            "solve",
            &format!("example:{name}"),
            "--out",
            out.to_str().unwrap_or_default(),
        ]);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        assert!(
            stdout(&o).contains("Sign convention"),
            "{name}: table ends with the sign convention"
        );
        // A scene with combinations writes a folder per combination and the envelope.
        let folders: Vec<std::path::PathBuf> = if combinations.is_empty() {
            vec![root.clone()]
        } else {
            for f in [
                "envelope.json",
                "envelope.csv",
                "envelope_nodes.csv",
                "envelope_elements.csv",
            ] {
                let p = root.join(f);
                assert!(
                    p.metadata().map(|m| m.len() > 0).unwrap_or(false),
                    "{name}: {f} written"
                );
            }
            combinations.iter().map(|c| root.join(c)).collect()
        };
        for out in &folders {
            for f in [
                "summary.json",
                "nodes.csv",
                "elements.csv",
                "profiles.csv",
                "plate.vtu",
                "profiles.svg",
                "contact.svg",
                "contact.png",
            ] {
                let p = out.join(f);
                assert!(
                    p.metadata().map(|m| m.len() > 0).unwrap_or(false),
                    "{name}: {} written",
                    p.display()
                );
            }
        }
        let out = folders[0].clone();
        let s: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).expect("read"))
                .expect("json");
        for key in [
            "method",
            "contact",
            "symmetry",
            "elements",
            "nodes",
            "dofs",
            "dimensionless",
            "converged",
            "iterations",
            "time_s",
            "w_max",
            "V_max",
            "V_center",
            "V_corner",
            "contact_fraction",
            "contact_radius",
            "contact_extent",
            "resultant",
            "complementarity",
        ] {
            assert!(s.get(key).is_some(), "{name}: summary.json has `{key}`");
        }
        let header = std::fs::read_to_string(out.join("nodes.csv")).expect("read");
        assert!(
            header.starts_with(
                "x [m],y [m],s [-],t [-],w [m],psi_x [rad],psi_y [rad],pressure [Pa],gap [m],V [-],\
                 sigma [-],s1_bottom [Pa],s1_top [Pa],contact [-]"
            ) || header.starts_with(
                "x [L],y [L],s [-],t [-],w [P·L²/D],psi_x [P·L/D],psi_y [P·L/D],pressure [P/L²],\
                 gap [P·L²/D],V [-],sigma [-],s1_bottom [P/L²],s1_top [P/L²],contact [-]"
            ),
            "{name}: nodes.csv columns"
        );
        let qp = liftoff(&[
            "solve",
            &format!("example:{name}"),
            "--method",
            "qp",
            "--json",
        ]);
        assert!(qp.status.success(), "{name} qp: {}", stderr(&qp));
        let q: serde_json::Value = serde_json::from_str(&stdout(&qp)).expect("json");
        // With combinations the JSON lists each one's summary: compare the first.
        let q = if combinations.is_empty() {
            q
        } else {
            q["combinations"][0]["summary"].clone()
        };
        let (a, b) = (
            s["V_max"].as_f64().unwrap_or(f64::NAN),
            q["V_max"].as_f64().unwrap_or(f64::NAN),
        );
        assert!(
            (a - b).abs() < 1e-3 * b.abs(),
            "{name}: V_max penalty {a} vs qp {b}"
        );
    }
}

#[test]
fn compare_writes_compare_json() {
    let dir = tempfile::tempdir().expect("tempdir");
    let o = liftoff(&[
        "compare",
        "example:paper-winkler",
        "--out",
        dir.path().to_str().unwrap_or_default(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("max |Δσ|"));
    let c: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.path().join("compare.json")).expect("read"),
    )
    .expect("json");
    assert!(c["differences"]["rel_v"].as_f64().unwrap_or(1.0) < 1e-2);
}

/// Exit codes: 2 bad input, 3 infeasible, 4 solver failure, 5 I/O — and no output on failure.
#[test]
fn failures_have_distinct_exit_codes_and_leave_no_files() {
    let dir = tempfile::tempdir().expect("tempdir");
    let scene = |name: &str, text: &str| {
        let p = dir.path().join(name);
        std::fs::write(&p, text).expect("write scene");
        p
    };
    let base = liftoff::examples::scene("paper-winkler").unwrap_or_default();
    let cases: Vec<(String, i32, &str)> = vec![
        (
            scene("bad.toml", &base.replace("gamma = 0.25e-3", "gamma = -1.0"))
                .display()
                .to_string(),
            2,
            "dimensionless.gamma",
        ),
        (
            scene(
                "typo.toml",
                &base.replace("[mesh]", "[mesh]\nelemnts = [4, 4]"),
            )
            .display()
            .to_string(),
            2,
            "elemnts",
        ),
        (
            scene("up.toml", &base.replace("force = 1.0", "force = -1.0"))
                .display()
                .to_string(),
            3,
            "upward",
        ),
        (
            dir.path().join("missing.toml").display().to_string(),
            5,
            "missing.toml",
        ),
    ];
    for (path, code, needle) in cases {
        let out = dir.path().join(format!("out-{code}"));
        let o = liftoff(&["solve", &path, "--out", out.to_str().unwrap_or_default()]);
        assert_eq!(o.status.code(), Some(code), "{path}: {}", stderr(&o));
        assert!(
            stderr(&o).contains(needle),
            "{path}: message should mention `{needle}`: {}",
            stderr(&o)
        );
        let leftovers = std::fs::read_dir(&out).map(|d| d.count()).unwrap_or(0);
        assert_eq!(leftovers, 0, "{path}: no files left behind");
    }
    // A penalty too weak for the stiffness ratio is reported as non-convergence (exit 4).
    let weak = scene(
        "weak.toml",
        &liftoff::examples::scene("paper-halfspace")
            .unwrap_or_default()
            .replace("gamma = 0.25e-3", "gamma = 1e-9"),
    );
    let o = liftoff(&["solve", weak.to_str().unwrap_or_default()]);
    assert_eq!(o.status.code(), Some(4), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("--penalty"),
        "suggests a smaller ε̄: {}",
        stderr(&o)
    );
}

/// An output directory that cannot be written is refused before any solving.
#[test]
fn unwritable_output_is_refused_up_front() {
    let dir = tempfile::tempdir().expect("tempdir");
    let file = dir.path().join("a-file");
    std::fs::write(&file, "not a directory").expect("write");
    let target = Path::new(&file).join("sub");
    let o = liftoff(&[
        "solve",
        "example:paper-winkler",
        "--out",
        target.to_str().unwrap_or_default(),
    ]);
    assert_eq!(o.status.code(), Some(5), "{}", stderr(&o));
    assert!(
        stdout(&o).is_empty(),
        "nothing solved or printed before the I/O error"
    );
}

#[test]
fn example_lists_and_prints_scenes() {
    let o = liftoff(&["example"]);
    assert!(o.status.success() && stdout(&o).contains("slab-on-grade"));
    let o = liftoff(&["example", "paper-halfspace"]);
    assert!(stdout(&o).contains("[dimensionless]"));
    let o = liftoff(&["example", "nope"]);
    assert_eq!(o.status.code(), Some(2));
}

/// A CSV file written by a study: its header and its records.
fn read_csv(path: &Path) -> (Vec<String>, Vec<csv::StringRecord>) {
    let mut r = csv::Reader::from_path(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let header = r
        .headers()
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .iter()
        .map(String::from)
        .collect();
    let rows = r
        .records()
        .collect::<Result<Vec<_>, _>>()
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    (header, rows)
}

/// The named column of a record.
fn field<'a>(header: &[String], row: &'a csv::StringRecord, name: &str) -> &'a str {
    let k = header
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column `{name}` in {header:?}"));
    row.get(k).unwrap_or_default()
}

fn number(header: &[String], row: &csv::StringRecord, name: &str) -> f64 {
    let s = field(header, row, name);
    s.parse()
        .unwrap_or_else(|_| panic!("column `{name}`: `{s}` is not a number"))
}

fn assert_svg(path: &Path) {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert!(
        text.len() > 1000 && text.contains("<svg") && text.trim_end().ends_with("</svg>"),
        "{} is a complete SVG ({} bytes)",
        path.display(),
        text.len()
    );
}

/// Least-squares slope of ln y against ln x.
fn loglog_slope(points: &[(f64, f64)]) -> f64 {
    let n = points.len() as f64;
    let (lx, ly): (Vec<f64>, Vec<f64>) = points.iter().map(|(x, y)| (x.ln(), y.ln())).unzip();
    let (mx, my) = (lx.iter().sum::<f64>() / n, ly.iter().sum::<f64>() / n);
    let sxy: f64 = lx.iter().zip(&ly).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = lx.iter().map(|x| (x - mx).powi(2)).sum();
    sxy / sxx
}

/// `eps-sweep` end to end on the paper's Winkler plate, both constraint kinds, ε̄ from 1e-2 to
/// 1e-8: one CSV row per (kind, ε̄) in order, the chart, and — fitted here from the CSV over the
/// converged rows — an error in σ falling with slope 1 in ε̄ (the penalty's O(ε̄); measured
/// 0.996 and 0.999), which the printed slopes agree with. Bad options exit 2 before anything is
/// written.
#[test]
fn eps_sweep_writes_its_table_chart_and_first_order_slope() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("sweep");
    let o = liftoff(&[
        "eps-sweep",
        "example:paper-winkler",
        "--from",
        "1e-2",
        "--to",
        "1e-8",
        "--points",
        "7",
        "--constraints",
        "both",
        "--out",
        out.to_str().unwrap_or_default(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_svg(&out.join("eps_sweep.svg"));
    let (header, rows) = read_csv(&out.join("eps_sweep.csv"));
    assert_eq!(
        header,
        [
            "constraint",
            "eps",
            "iterations",
            "converged",
            "status",
            "max_abs_sigma_err",
            "max_abs_v_err",
            "rel_l2_sigma",
            "rel_l2_v",
            "min_pressure",
            "time_s"
        ]
    );
    assert_eq!(rows.len(), 14, "7 ε̄ × 2 constraint kinds");
    let printed = stdout(&o);
    for (k, kind) in ["nodal", "gauss"].into_iter().enumerate() {
        let mine = &rows[7 * k..7 * (k + 1)];
        let mut converged = Vec::new();
        for (j, r) in mine.iter().enumerate() {
            assert_eq!(field(&header, r, "constraint"), kind);
            // Log-spaced, one decade apart.
            let eps = number(&header, r, "eps");
            let expected = 10f64.powi(-2 - j as i32);
            assert!(
                (eps / expected - 1.0).abs() < 1e-9,
                "{kind}: ε̄ {eps} vs {expected}"
            );
            assert_eq!(
                field(&header, r, "converged") == "true",
                field(&header, r, "status") == "converged",
                "{kind} ε̄ = {eps}"
            );
            if field(&header, r, "status") == "converged" {
                converged.push((eps, number(&header, r, "rel_l2_sigma")));
            }
        }
        assert!(
            converged.len() >= 3,
            "{kind}: at least three converged ε̄ to fit: {converged:?}"
        );
        let slope = loglog_slope(&converged);
        assert!(
            (slope - 1.0).abs() < 0.05,
            "{kind}: slope {slope} over {converged:?}"
        );
        let line = printed
            .lines()
            .find(|l| l.trim_start().starts_with(&format!("{kind}: fitted slope")))
            .unwrap_or_else(|| panic!("no fitted slope for {kind}:\n{printed}"));
        let shown: f64 = line
            .split("fitted slope ")
            .nth(1)
            .and_then(|s| s.split_whitespace().next())
            .and_then(|s| s.parse().ok())
            .unwrap_or_else(|| panic!("slope in `{line}`"));
        assert!(
            (shown - slope).abs() < 0.01,
            "{kind}: printed slope {shown} vs {slope} fitted from the CSV"
        );
    }

    bad_options_exit_2_and_write_nothing(
        dir.path(),
        "eps-sweep",
        &[
            (vec!["--points", "1"], "--points"),
            (vec!["--constraints", "all"], "--constraints"),
            (vec!["--from", "2"], "--from"),
        ],
    );
}

/// `tradeoff` end to end on the paper's Winkler plate over 4, 8, 16 elements: one CSV row per
/// mesh and method, the reference at twice the finest mesh, Pareto marks equal to the
/// non-dominated converged rows recomputed from the CSV, the QP error falling with the mesh,
/// and the chart. Bad options exit 2 before anything is written.
#[test]
fn tradeoff_writes_its_table_and_chart() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("tradeoff");
    let o = liftoff(&[
        "tradeoff",
        "example:paper-winkler",
        "--meshes",
        "4,8,16",
        "--penalties",
        "1e-2,1e-8",
        "--out",
        out.to_str().unwrap_or_default(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stdout(&o).contains("reference: QP on 32 elements per side (twice the finest mesh)"),
        "{}",
        stdout(&o)
    );
    assert_svg(&out.join("tradeoff.svg"));
    let (header, rows) = read_csv(&out.join("tradeoff.csv"));
    assert_eq!(
        header,
        [
            "method",
            "mesh",
            "eps",
            "time_s",
            "error",
            "converged",
            "status",
            "pareto"
        ]
    );
    assert_eq!(rows.len(), 9, "3 meshes × (QP + 2 ε̄)");
    struct Point {
        time: f64,
        error: f64,
        ok: bool,
        pareto: bool,
    }
    let points: Vec<Point> = rows
        .iter()
        .map(|r| {
            let error = number(&header, r, "error");
            Point {
                time: number(&header, r, "time_s"),
                error,
                ok: field(&header, r, "converged") == "true" && error.is_finite() && error > 0.0,
                pareto: field(&header, r, "pareto") == "true",
            }
        })
        .collect();
    for (i, p) in points.iter().enumerate() {
        let dominated = points.iter().enumerate().any(|(j, q)| {
            j != i
                && q.ok
                && q.time <= p.time
                && q.error <= p.error
                && (q.time < p.time || q.error < p.error)
        });
        assert_eq!(p.pareto, p.ok && !dominated, "row {i}: Pareto mark");
        assert!(p.time > 0.0, "row {i}: time {}", p.time);
    }
    let qp: Vec<(f64, f64)> = rows
        .iter()
        .filter(|r| field(&header, r, "method") == "qp")
        .map(|r| (number(&header, r, "mesh"), number(&header, r, "error")))
        .collect();
    assert_eq!(qp.iter().map(|p| p.0).collect::<Vec<_>>(), [4.0, 8.0, 16.0]);
    assert!(
        qp.windows(2).all(|w| w[1].1 < w[0].1),
        "QP error falls with the mesh: {qp:?}"
    );

    bad_options_exit_2_and_write_nothing(
        dir.path(),
        "tradeoff",
        &[
            (vec!["--meshes", "1,8"], "--meshes"),
            (vec!["--penalties", "0"], "--penalties"),
        ],
    );
}

/// `stability` end to end over two small base scenes (the paper's Winkler plate on 8 × 8 and on
/// 6 × 6 elements with a 64 MiB memory limit, so the mesh sweep refuses its dense cases instead
/// of running for minutes): one CSV row per planned run (97 a scene), known outcomes, the
/// printed count of non-converged runs equal to the CSV's, the corner load carried by both
/// methods, and one map per method. A scene that cannot be read exits 5 with nothing written.
/// (The command line's plumbing is what this test holds; the sweep's answers on the half-space
/// — its Γ sweep on the iterative route took most of this test's time when it ran here too —
/// are `tests/studies.rs::stability_sweep_rows_and_outcomes`'s, on the same 8 × 8 plate.)
#[test]
fn stability_writes_one_row_per_run_and_the_maps() {
    let dir = tempfile::tempdir().expect("tempdir");
    let small = |name: &str, from: &str, n: usize| {
        let text = liftoff::examples::scene(name).unwrap_or_default();
        assert!(text.contains(from) && text.contains("[solver]\n"), "{name}");
        let p = dir.path().join(format!("{name}-{n}.toml"));
        let text = text
            .replace(from, &format!("elements = [{n}, {n}]"))
            .replace("[solver]\n", "[solver]\nmemory_limit_gib = 0.0625\n");
        std::fs::write(&p, text).expect("write scene");
        p.display().to_string()
    };
    let winkler = small("paper-winkler", "elements = [20, 20]", 8);
    let coarser = small("paper-winkler", "elements = [20, 20]", 6);
    let out = dir.path().join("stability");
    let o = liftoff(&[
        "stability",
        &winkler,
        &coarser,
        "--out",
        out.to_str().unwrap_or_default(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let printed = stdout(&o);
    assert!(
        printed.starts_with("liftoff stability — 194 runs"),
        "{printed}"
    );
    for f in ["stability-penalty.svg", "stability-qp.svg"] {
        assert_svg(&out.join(f));
    }
    let (header, rows) = read_csv(&out.join("stability.csv"));
    assert_eq!(
        header,
        [
            "sweep",
            "foundation",
            "method",
            "value",
            "outcome",
            "iterations",
            "equilibrium",
            "min_pressure",
            "min_gap",
            "contact_fraction",
            "time_s",
            "detail"
        ]
    );
    assert_eq!(rows.len(), 194, "97 runs a scene");
    let known = common::OUTCOMES;
    let mut failed = 0;
    for r in &rows {
        let outcome = field(&header, r, "outcome");
        assert!(known.contains(&outcome), "outcome `{outcome}`");
        if outcome != "converged" {
            failed += 1;
        }
        assert_eq!(field(&header, r, "foundation"), "winkler");
        if field(&header, r, "sweep") == "position" && number(&header, r, "value") == 1.0 {
            // Lumped springs put a nodal pressure at its node: the corner node carries the
            // corner load (the QP at once, the penalty from its automatic ε̄ on).
            assert_eq!(outcome, "converged", "the corner load on Winkler springs");
        }
    }
    assert!(failed > 0 && failed < rows.len());
    assert!(
        printed.contains(&format!("{failed} of 194 runs did not converge")),
        "{failed} non-converged rows in the CSV: {printed}"
    );
    // Each non-converged run is listed on its own line, outcome and detail after the colon.
    let listed = printed
        .lines()
        .filter(|l| l.contains(": ") && l.contains(" — "))
        .count();
    assert_eq!(listed, failed, "{printed}");

    let missing = dir.path().join("missing.toml");
    let never = dir.path().join("never");
    let o = liftoff(&[
        "stability",
        missing.to_str().unwrap_or_default(),
        "--out",
        never.to_str().unwrap_or_default(),
    ]);
    assert_eq!(o.status.code(), Some(5), "{}", stderr(&o));
    assert!(!never.exists(), "nothing written");
}

/// Each (options, flag) case of `subcommand` on the paper's Winkler plate exits 2, names the
/// flag, and writes nothing.
fn bad_options_exit_2_and_write_nothing(
    dir: &std::path::Path,
    subcommand: &str,
    cases: &[(Vec<&str>, &str)],
) {
    for (args, needle) in cases {
        let bad = dir.join("bad");
        let mut a = vec![subcommand, "example:paper-winkler", "--out"];
        a.push(bad.to_str().unwrap_or_default());
        a.extend(args.iter().copied());
        let o = liftoff(&a);
        assert_eq!(o.status.code(), Some(2), "{a:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(needle), "{a:?}: {}", stderr(&o));
        assert!(!bad.exists(), "{a:?}: nothing written");
    }
}

/// A solve that did not converge prints its diagnosis and no result: no deflection, pressure
/// or stress line (its last iterate is not a solution), no files — no report.html either,
/// with `--report` — exit 4 (issue 32 §1.2).
#[test]
fn a_solve_that_did_not_converge_shows_no_result() {
    let dir = tempfile::tempdir().expect("tempdir");
    let scene = liftoff::examples::scene("footing")
        .unwrap_or_default()
        .replace("[solver]", "[solver]\nmax_iterations = 1");
    let path = dir.path().join("footing.toml");
    std::fs::write(&path, scene).expect("write scene");
    let out = dir.path().join("out");
    let o = liftoff(&[
        "solve",
        path.to_str().unwrap_or_default(),
        "--out",
        out.to_str().unwrap_or_default(),
        "--report",
    ]);
    let (text, err) = (stdout(&o), stderr(&o));
    assert_eq!(o.status.code(), Some(4), "{text}{err}");
    assert!(text.contains("not converged"), "{text}");
    assert!(text.contains("result     : none"), "{text}");
    for line in [
        "deflection :",
        "pressure   :",
        "stress     :",
        "files      :",
    ] {
        assert!(
            !text.contains(line),
            "`{line}` shown for a solve that did not converge:\n{text}"
        );
    }
    assert!(err.contains("no result is shown"), "{err}");
    assert!(!out.join("summary.json").exists(), "files written");
    assert!(!out.exists(), "the output directory created");
}

/// `--report` writes into `--out`: without it the command line refuses the flag (exit 2) and
/// runs nothing.
#[test]
fn report_flag_needs_out() {
    for args in [
        vec!["solve", "example:footing", "--report"],
        vec![
            "critical",
            "example:pavement-3x3",
            "--load",
            "axle",
            "--report",
        ],
    ] {
        let o = liftoff(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains("--out"), "{args:?}: {}", stderr(&o));
    }
}

/// `liftoff backcalc` on the bundled survey (synthetic: liftoff's model at E = 32 GPa, k = 70
/// MN/m³ — 45 at station 3+000 — with 1 µm of noise, `examples/fwd_basins.rs`): the seating
/// drops are discarded, each station's k comes back within 2 % and E within 3 % (the noise
/// moves them by about that), backcalc.csv's columns carry the scene's units, basins.csv has a
/// row a sensor whose misfit is fitted − measured, and the charts are complete SVGs. The AREA
/// method alone reads the interior drop and refuses the edge one (E77).
#[test]
fn backcalc_recovers_the_bundled_surveys_moduli_and_writes_its_files() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("bc");
    let basins = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/fwd-basins.csv");
    let basins = basins.to_str().expect("utf-8 path");
    let o = liftoff(&[
        "backcalc",
        basins,
        "--scene",
        "example:fwd-panel",
        "--seating",
        "1",
        "--out",
        out.to_str().expect("utf-8"),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stdout(&o).contains("(3 seating drop(s) discarded)"),
        "{}",
        stdout(&o)
    );
    let (h, rows) = read_csv(&out.join("backcalc.csv"));
    assert_eq!(rows.len(), 3);
    for (row, k) in rows.iter().zip([70.0, 70.0, 45.0]) {
        assert_eq!(field(&h, row, "converged"), "true");
        let (kf, e) = (number(&h, row, "k [MPa/m]"), number(&h, row, "E [MPa]"));
        assert!((kf / k - 1.0).abs() < 0.02, "k {kf} against {k}");
        assert!((e / 32e3 - 1.0).abs() < 0.03, "E {e}");
        assert!(number(&h, row, "k_low [MPa/m]") < kf && kf < number(&h, row, "k_high [MPa/m]"));
    }
    let (hb, sensors) = read_csv(&out.join("basins.csv"));
    assert_eq!(sensors.len(), 27, "nine sensors a drop");
    for s in &sensors {
        let misfit = number(&hb, s, "fitted [µm]") - number(&hb, s, "measured [µm]");
        // The file's seven significant digits: 0.5e-6 of an 819 µm deflection, twice.
        assert!((misfit - number(&hb, s, "misfit [µm]")).abs() < 1e-3);
    }
    for chart in ["basins.svg", "moduli.svg"] {
        assert_svg(&out.join(chart));
    }
    let area = liftoff(&[
        "backcalc",
        basins,
        "--scene",
        "example:fwd-panel",
        "--method",
        "area",
        "--json",
    ]);
    assert_eq!(area.status.code(), Some(2), "{}", stderr(&area));
    assert!(stderr(&area).contains("station 2+000, drop 1`: the AREA method reads interior drops"));
}

/// `liftoff backcalc FILE --scene SCENE --out OUT FLAGS…`, which must succeed: its
/// backcalc.csv.
fn backcalc_table(
    file: &Path,
    scene: &str,
    out: &Path,
    flags: &[&str],
) -> (Vec<String>, Vec<csv::StringRecord>) {
    let mut args = vec![
        "backcalc",
        file.to_str().expect("utf-8 path"),
        "--scene",
        scene,
        "--out",
        out.to_str().expect("utf-8 path"),
    ];
    args.extend_from_slice(flags);
    let o = liftoff(&args);
    assert!(o.status.success(), "{}: {}", file.display(), stderr(&o));
    read_csv(&out.join("backcalc.csv"))
}

/// A bundled basin file's lines as `keep` rewrites them (None: left out), written to `to`.
fn basin_lines(file: &str, to: &Path, keep: impl FnMut(&str) -> Option<String>) {
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(file))
        .unwrap_or_else(|e| panic!("{file}: {e}"));
    let lines: String = text.lines().filter_map(keep).collect();
    std::fs::write(to, lines).unwrap_or_else(|e| panic!("{}: {e}", to.display()));
}

/// The bundled PDDX survey (`examples/fwd-interior.pdx`) holds station 1+000 of
/// `examples/fwd-basins.csv` in AASHTO's exchange format: read by `liftoff backcalc`, its fit is
/// the CSV file's to the digit in every column of backcalc.csv but the station's name (the same
/// drop in SI after either reader's conversion, the same fit).
#[test]
fn backcalc_reads_a_pddx_survey_as_its_csv_twin() {
    let dir = tempfile::tempdir().expect("tempdir");
    let run = |file: &str, out: &str| {
        let file = Path::new(env!("CARGO_MANIFEST_DIR")).join(file);
        let flags = ["--seating", "1"];
        backcalc_table(&file, "example:fwd-panel", &dir.path().join(out), &flags)
    };
    let (hp, pddx) = run("examples/fwd-interior.pdx", "pddx");
    let (hc, csv) = run("examples/fwd-basins.csv", "csv");
    assert_eq!(hp, hc);
    assert_eq!(pddx.len(), 1);
    assert_eq!(field(&hp, &pddx[0], "station"), "1.000");
    assert_eq!(field(&hc, &csv[0], "station"), "1+000");
    for (i, name) in hp.iter().enumerate().filter(|(_, n)| *n != "station") {
        assert_eq!(pddx[0][i], csv[0][i], "column {name}");
    }
}

/// A PDDX file does not say where on the slab a drop stood; `--location`, `--at` and
/// `--direction` say it for every drop of the file. The bundled joint station in PDDX
/// (`examples/fwd-joint.pdx`, station 6+000 of `examples/fwd-joint.csv`) placed as the CSV row
/// places it gives that row's fit of k, E and the joint's stiffness to the digit in every column
/// of backcalc.csv (the same drop after either reader, the same model), its load transfer
/// included; `--at` is in the template's unit of length (m here).
#[test]
fn backcalc_places_a_pddx_survey_where_the_flags_say() {
    let dir = tempfile::tempdir().expect("tempdir");
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    // The CSV file's header and its station 6+000, the twin of the PDDX file's one station.
    let csv_path = dir.path().join("one.csv");
    basin_lines("examples/fwd-joint.csv", &csv_path, |l| {
        (l.starts_with("station") || l.starts_with("6+000")).then(|| format!("{l}\n"))
    });
    let run = |file: &Path, out: &str, flags: &[&str]| {
        let flags = [&["--fit", "subgrade,slab,joint"], flags].concat();
        backcalc_table(file, "example:fwd-joint", &dir.path().join(out), &flags)
    };
    let pddx_path = root.join("examples/fwd-joint.pdx");
    let (hp, pddx) = run(
        &pddx_path,
        "pddx",
        &[
            "--location",
            "joint-approach",
            "--at",
            "-0.15,-0.9",
            "--direction",
            "0",
        ],
    );
    let (hc, csv) = run(&csv_path, "csv", &[]);
    assert_eq!(hp, hc);
    assert_eq!((pddx.len(), csv.len()), (1, 1));
    assert_eq!(field(&hp, &pddx[0], "location"), "joint-approach");
    assert!(
        !field(&hp, &pddx[0], "lte [-]").is_empty(),
        "a joint drop's LTE"
    );
    for (i, name) in hp.iter().enumerate() {
        assert_eq!(pddx[0][i], csv[0][i], "column {name}");
    }
}

/// The intercept method on the bundled void survey (`examples/fwd-void.csv`: liftoff's model in
/// unbonded contact, two corners with drops of 40, 53 and 71 kN after a seating drop, one over
/// a 0.5 mm void): intercepts.csv flags the voided corner above 2 mils and passes the sound
/// one, whose line passes within a few µm of the origin (1 µm of noise on each drop).
#[test]
fn backcalc_flags_the_voided_corner_by_its_intercept() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("void");
    let basins = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/fwd-void.csv");
    let o = liftoff(&[
        "backcalc",
        basins.to_str().expect("utf-8"),
        "--scene",
        "example:fwd-panel",
        "--contact",
        "unbonded",
        "--seating",
        "1",
        "--out",
        out.to_str().expect("utf-8"),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stdout(&o).contains("5+000 (corner, 3 loads): zero-load intercept"),
        "{}",
        stdout(&o)
    );
    let (h, rows) = read_csv(&out.join("intercepts.csv"));
    assert_eq!(rows.len(), 2);
    let (sound, voided) = (&rows[0], &rows[1]);
    assert_eq!(field(&h, sound, "void"), "false");
    assert!(number(&h, sound, "intercept [µm]").abs() < 10.0);
    assert_eq!(field(&h, voided, "void"), "true");
    assert!(number(&h, voided, "intercept [µm]") > 50.8);
}

/// The bundled joint survey (`examples/fwd-joint.csv`: liftoff's model of `example:fwd-joint`
/// at E = 32 GPa, k = 70 MN/m³ and the joint's AGG = 80, 40 and 15 MN/m², 1 µm of noise):
/// `--fit subgrade,slab,joint` gives each station's joint stiffness within 5 % (the noise
/// moves it by about 2 % at the weakest joint) and k within 3 %, the fitted model's LTE
/// matches the measured one within 1 % (of the LTE), lte.svg is written, and `--report`
/// makes report.html of the files.
#[test]
fn backcalc_fits_the_bundled_joints_stiffness_and_load_transfer() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("joint");
    let basins = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/fwd-joint.csv");
    let o = liftoff(&[
        "backcalc",
        basins.to_str().expect("utf-8"),
        "--scene",
        "example:fwd-joint",
        "--fit",
        "subgrade,slab,joint",
        "--out",
        out.to_str().expect("utf-8"),
        "--report",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (h, rows) = read_csv(&out.join("backcalc.csv"));
    assert_eq!(rows.len(), 3);
    for (row, agg) in rows.iter().zip([80.0, 40.0, 15.0]) {
        let found = number(&h, row, "joint [MPa]");
        assert!(
            (found / agg - 1.0).abs() < 0.05,
            "AGG {found} against {agg}"
        );
        assert!((number(&h, row, "k [MPa/m]") / 70.0 - 1.0).abs() < 0.03);
        let (lte, model) = (number(&h, row, "lte [-]"), number(&h, row, "lte_model [-]"));
        assert!((model / lte - 1.0).abs() < 0.01, "LTE {lte}, model {model}");
        assert!(number(&h, row, "bending [-]") > 1.0);
    }
    assert_svg(&out.join("lte.svg"));
    // report.html shows the drops' table and the three charts inlined.
    let page = std::fs::read_to_string(out.join("report.html")).expect("report.html");
    for needle in [
        "Backcalculation from deflection basins",
        "joint-approach",
        "Figure 3. the load transfer of the joint drops",
    ] {
        assert!(page.contains(needle), "report.html lacks {needle:?}");
    }
}

/// A template in US units without loads of its own (a backcalculation's template needs none:
/// the drops are its loads): the table and backcalc.csv are in pci, ksi and mils, and the
/// moduli are the SI run's, converted (k = 70 MN/m³ is 257.9 pci, E = 32 GPa is 4641 ksi;
/// the bundled survey's noise moves them by under 2 %).
#[test]
fn backcalc_reads_a_us_template_without_loads_and_reports_in_its_units() {
    let dir = tempfile::tempdir().expect("tempdir");
    let scene = dir.path().join("us.toml");
    std::fs::write(
        &scene,
        "units = \"us\"\n[plate]\nlength = 181.1\nwidth = 145.7\nthickness = 9.84\nyoungs_modulus = 4.35e6\npoissons_ratio = 0.15\n\
         [foundation]\nmodel = \"winkler\"\nmodulus = 184.0\n[mesh]\nelements = [16, 16]\n[solver]\ncontact = \"bonded\"\n",
    )
    .expect("write");
    let out = dir.path().join("us");
    let basins = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/fwd-basins.csv");
    let o = liftoff(&[
        "backcalc",
        basins.to_str().expect("utf-8"),
        "--scene",
        scene.to_str().expect("utf-8"),
        "--seating",
        "1",
        "--out",
        out.to_str().expect("utf-8"),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("k [pci] (95 %)") && stdout(&o).contains("rms [mils]"));
    let (h, rows) = read_csv(&out.join("backcalc.csv"));
    let k = number(&h, &rows[0], "k [pci]");
    let e = number(&h, &rows[0], "E [ksi]");
    assert!((k / 257.9 - 1.0).abs() < 0.02, "k {k} pci");
    assert!((e / 4641.0 - 1.0).abs() < 0.02, "E {e} ksi");
    // `--at` is in the template's unit of length: the interior station as a PDDX file placed
    // at (0, −24) — inches on this template — is its CSV row placed at (0, −2) ft. Read as
    // metres or feet the place would be off the 3.7 m wide plate and refused. The two places
    // agree in SI to the last bit or so (24 × 0.0254 against 2 × 12 × 0.0254), the fits to
    // far better than the 1e-6 asked.
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let csv_path = dir.path().join("placed.csv");
    basin_lines("examples/fwd-basins.csv", &csv_path, |l| match l {
        _ if l.starts_with("station,") => Some(format!("{l},x_ft,y_ft\n")),
        _ if l.starts_with("1+000,") => Some(format!("{l},0,-2\n")),
        _ => None,
    });
    let scene = scene.to_str().expect("utf-8");
    let fit = |file: &Path, out: &str, flags: &[&str]| {
        let flags = [&["--seating", "1"], flags].concat();
        let (h, rows) = backcalc_table(file, scene, &dir.path().join(out), &flags);
        (
            number(&h, &rows[0], "k [pci]"),
            number(&h, &rows[0], "E [ksi]"),
        )
    };
    let pddx = root.join("examples/fwd-interior.pdx");
    let placed = fit(&pddx, "placed-pddx", &["--at", "0,-24"]);
    let by_csv = fit(&csv_path, "placed-csv", &[]);
    let centre = fit(&pddx, "centre-pddx", &[]);
    assert!(
        (placed.0 / by_csv.0 - 1.0).abs() < 1e-6,
        "{placed:?} {by_csv:?}"
    );
    assert!(
        (placed.1 / by_csv.1 - 1.0).abs() < 1e-6,
        "{placed:?} {by_csv:?}"
    );
    // And the place matters: 0.61 m off the centre the same basin reads other moduli.
    assert!(
        (placed.0 / centre.0 - 1.0).abs() > 1e-4,
        "{placed:?} {centre:?}"
    );
}
