//! The command-line tool end to end: bundled examples, outputs, exit codes, no partial files.

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
    for (name, _, _) in liftoff::examples::SCENES {
        let out = dir.path().join(name);
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
                "{name}: {f} written"
            );
        }
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
            header.starts_with("x,y,s,t,w,psi_x,psi_y,pressure,gap,V,sigma,contact"),
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
