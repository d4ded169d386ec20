//! Regression inputs for the scene fuzz target (`fuzz/fuzz_targets/scene.rs`, run by
//! `fuzz/run.sh`; results in `fuzz/RESULTS.md`).
//!
//! Each case goes through the same pipeline as the fuzz target: `SceneFile::parse` → `validate`
//! → (for meshes of at most 8 elements per side) `Operators::assemble` → `solve::solve`. None of
//! them may panic; each checks the stage where it stops and, for errors, the kind of error and
//! the field named. Meshes larger than 8 × 8 are validated but never solved, so the file stays
//! fast.

use liftoff::scene::SceneFile;
use liftoff::Error;

/// Largest mesh (elements per side) that is also assembled and solved, as in the fuzz target.
const MAX_SOLVED_ELEMENTS: usize = 8;

/// How far an input got. The payloads are read through `Debug`, in failure messages.
#[derive(Debug)]
#[allow(dead_code)]
enum Outcome {
    /// `SceneFile::parse` rejected it.
    Parse(String),
    /// `validate` rejected it: the field named and the message.
    Invalid(String, String),
    /// Valid, but the mesh is too large to solve here.
    ValidLarge,
    /// Valid; assembling or solving returned an error.
    SolveError(Error),
    /// Valid and solved (converged or not).
    Solved,
}

fn run(text: &str) -> Outcome {
    let scene = match SceneFile::parse(text) {
        Ok(s) => s,
        Err(Error::Parse(m)) => return Outcome::Parse(m),
        Err(e) => panic!("parse returned a non-parse error: {e:?}"),
    };
    let problem = match scene.validate() {
        Ok(p) => p,
        Err(Error::Invalid { field, message }) => return Outcome::Invalid(field, message),
        Err(e) => panic!("validate returned a non-Invalid error: {e:?}"),
    };
    if std::env::var_os("FUZZ_REGRESSIONS_VERBOSE").is_some() {
        eprintln!("  validated: {:?}", problem.model.groups);
    }
    if problem
        .model
        .elements
        .iter()
        .any(|&n| n > MAX_SOLVED_ELEMENTS)
    {
        return Outcome::ValidLarge;
    }
    if let Err(e) = liftoff::budget::check(&problem.model, &problem.method, problem.memory_limit) {
        return Outcome::SolveError(e);
    }
    let ops = liftoff::Operators::assemble(&problem.model);
    match liftoff::solve(&ops, &problem.method) {
        Ok(_) => Outcome::Solved,
        Err(e) => Outcome::SolveError(e),
    }
}

/// What a case must do.
#[derive(Debug, Clone, Copy)]
enum Expect<'a> {
    /// Rejected by the parser.
    ParseError,
    /// Rejected by `validate`, naming this field.
    Invalid(&'a str),
    /// Valid; assembling and solving may return an error but must not panic.
    Valid,
    /// Valid and solved.
    Solved,
    /// Anything but a panic: for inputs whose current outcome is questionable (see the case).
    NoPanic,
}

/// Runs every case and reports all mismatches at once, each under its case name.
fn check(cases: &[(&str, String, Expect)]) {
    let mut failures = Vec::new();
    for (case, text, expect) in cases {
        let got = run(text);
        if std::env::var_os("FUZZ_REGRESSIONS_VERBOSE").is_some() {
            eprintln!("{case}: {got:?}");
        }
        let ok = match (expect, &got) {
            (Expect::ParseError, Outcome::Parse(_)) => true,
            (Expect::Invalid(field), Outcome::Invalid(f, _)) => f == field,
            (Expect::Valid, Outcome::Solved | Outcome::SolveError(_) | Outcome::ValidLarge) => true,
            (Expect::Solved, Outcome::Solved) => true,
            (Expect::NoPanic, _) => true,
            _ => false,
        };
        if !ok {
            failures.push(format!("case `{case}`: expected {expect:?}, got {got:?}"));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} cases failed:\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n")
    );
}

/// A small valid dimensionless scene with one central point load, with `extra` appended.
fn dimensionless(extra: &str) -> String {
    format!(
        r#"
[dimensionless]
foundation = "winkler"
gamma = 0.25e-3
delta = 0.002857
mu = 1.0
nu = 0.3
[[load]]
kind = "point"
x = 0.0
y = 0.0
force = 1.0
{extra}"#
    )
}

/// A small valid physical scene; `{plate}`/`{found}` replace the defaults.
fn physical(plate: &str, found: &str, rest: &str) -> String {
    format!("[plate]\n{plate}\n[foundation]\n{found}\n{rest}")
}

const PLATE: &str =
    "length = 6.0\nwidth = 4.0\nthickness = 0.25\nyoungs_modulus = 30e9\npoissons_ratio = 0.2";
const WINKLER: &str = "model = \"winkler\"\nmodulus = 5e7";
const POINT: &str =
    "[[load]]\nkind = \"point\"\nx = 1.5\ny = 1.0\nforce = 2.0e5\n[mesh]\nelements = [4, 4]";

#[test]
fn the_helpers_accept_a_valid_scene() {
    check(&[
        (
            "small dimensionless scene",
            dimensionless("[mesh]\nelements = [4, 4]"),
            Expect::Solved,
        ),
        (
            "small physical scene",
            physical(PLATE, WINKLER, POINT),
            Expect::Solved,
        ),
    ]);
}

#[test]
fn malformed_toml_is_a_parse_error() {
    let long_key = "k".repeat(100_000);
    let cases: Vec<(&str, String)> = vec![
        ("lone bracket", "[".into()),
        (
            "1e309 overflows the float parser",
            dimensionless("").replace("mu = 1.0", "mu = 1e309"),
        ),
        ("unterminated string", "title = \"abc".into()),
        ("unterminated multiline string", "title = \"\"\"abc".into()),
        (
            "duplicate key",
            dimensionless("[mesh]\nelements = [4, 4]\nelements = [2, 2]"),
        ),
        ("duplicate table", dimensionless("[mesh]\n[mesh]")),
        (
            "duplicate plate key",
            physical(&format!("{PLATE}\nlength = 6.0"), WINKLER, POINT),
        ),
        ("table redefined as array", dimensionless("[[mesh]]")),
        (
            "unknown top-level key",
            dimensionless(&format!("{long_key} = 1")),
        ),
        ("unknown top-level table", dimensionless("[a.b.c]\nd = 1")),
        (
            "nan in elements",
            dimensionless("[mesh]\nelements = [nan, 1]"),
        ),
        (
            "float elements",
            dimensionless("[mesh]\nelements = [1.5, 1]"),
        ),
        (
            "elements past i64",
            dimensionless("[mesh]\nelements = [9223372036854775808, 1]"),
        ),
        (
            "three-element range",
            dimensionless("").replace("x = 0.0", "x = [0.0, 0.1, 0.2]"),
        ),
        (
            "string coordinate",
            dimensionless("").replace("x = 0.0", "x = \"0\""),
        ),
        (
            "unknown load kind",
            dimensionless("").replace("\"point\"", "\"line\""),
        ),
        (
            "unknown method",
            dimensionless("[solver]\nmethod = \"newton\""),
        ),
        (
            "integer max_iterations past i64",
            dimensionless("[solver]\nmax_iterations = 99999999999999999999"),
        ),
        ("invalid UTF-8 escape", "title = \"\\uD800\"".into()),
        ("NUL byte", "title = \"a\0b\"".into()),
        ("bare CR", "title = \"a\"\r[mesh]".into()),
        (
            "datetime where a number goes",
            dimensionless("").replace("force = 1.0", "force = 1979-05-27T07:32:00Z"),
        ),
        (
            "load as a plain table",
            dimensionless("").replace("[[load]]", "[load]"),
        ),
    ];
    let cases: Vec<_> = cases
        .into_iter()
        .map(|(case, text)| (case, text, Expect::ParseError))
        .collect();
    check(&cases);
}

#[test]
fn physical_scenes_whose_groups_overflow_do_not_panic() {
    // The physical branch of `validate` checks its inputs but not the groups it derives from
    // them (Γ = D / (K μ L⁴), Δ = H² / (6 χ (1 − ν) μ L²)): these currently validate with
    // Γ = Δ = 0 or Γ = inf and fail later in the solver with a numerical error. A finite,
    // positive check on the derived groups would turn them into `Invalid`; either way they
    // must not panic.
    let point_at_centre =
        "[[load]]\nkind = \"point\"\nx = 0.0\ny = 0.0\nforce = 1.0\n[mesh]\nelements = [2, 2]";
    check(&[
        (
            "physical, sides 1e308: L⁴ overflows, Γ = Δ = 0",
            physical(
                &PLATE
                    .replace("length = 6.0", "length = 1e308")
                    .replace("width = 4.0", "width = 1e308"),
                WINKLER,
                point_at_centre,
            ),
            Expect::NoPanic,
        ),
        (
            "physical, thickness 1e-200: H² underflows, Γ = Δ = 0",
            physical(
                &PLATE.replace("thickness = 0.25", "thickness = 1e-200"),
                WINKLER,
                POINT,
            ),
            Expect::NoPanic,
        ),
        (
            "physical, modulus 5e-324: Γ = inf",
            physical(PLATE, "model = \"winkler\"\nmodulus = 5e-324", POINT),
            Expect::NoPanic,
        ),
        (
            "physical half-space, youngs_modulus 5e-324: Γ = inf",
            physical(
                PLATE,
                "model = \"half-space\"\nyoungs_modulus = 5e-324\npoissons_ratio = 0.3",
                POINT,
            ),
            Expect::NoPanic,
        ),
    ]);
}

#[test]
fn trailing_array_elements_do_not_panic() {
    // `[i64; 2]` read through toml's deserializer takes the first two entries and ignores the
    // rest, so `elements = [1, 1, 1]` is currently accepted as [1, 1] (a range `x = [a, b, c]`,
    // read through the untagged `Coord`, is rejected). Should become a parse error; until
    // then this only checks that nothing panics.
    check(&[
        (
            "elements = [1, 1, 1]",
            dimensionless("[mesh]\nelements = [1, 1, 1]"),
            Expect::NoPanic,
        ),
        (
            "elements = [2, 2, \"x\", nan]",
            dimensionless("[mesh]\nelements = [2, 2, \"x\", nan]"),
            Expect::NoPanic,
        ),
    ]);
}

#[test]
fn deep_nesting_is_rejected_without_overflowing_the_stack() {
    // Run on a thread with a small, fixed stack so a recursion that grows with the input shows
    // up here rather than only on machines with a smaller main-thread stack.
    let handle = std::thread::Builder::new()
        .stack_size(2 << 20)
        .spawn(|| {
            let depth = 10_000;
            let arrays = format!("title = {}{}", "[".repeat(depth), "]".repeat(depth));
            let mut inline = String::from("title = ");
            for _ in 0..depth {
                inline.push_str("{a = ");
            }
            inline.push('1');
            for _ in 0..depth {
                inline.push('}');
            }
            let dotted = format!("[{}]\nb = 1", vec!["a"; depth].join("."));
            let dotted_key = format!("{} = 1", vec!["a"; depth].join("."));
            let unclosed = format!("title = {}", "[".repeat(depth));
            check(&[
                ("deeply nested arrays", arrays, Expect::ParseError),
                ("deeply nested inline tables", inline, Expect::ParseError),
                (
                    "deeply nested dotted table header",
                    dotted,
                    Expect::ParseError,
                ),
                ("deeply nested dotted key", dotted_key, Expect::ParseError),
                ("unclosed nested arrays", unclosed, Expect::ParseError),
            ]);
        })
        .expect("spawn");
    handle.join().expect("deep nesting panicked or overflowed");
}

#[test]
fn out_of_range_values_name_their_field() {
    let cases: Vec<(&str, String, &str)> = vec![
        ("elements = [0, 1]", dimensionless("[mesh]\nelements = [0, 1]"), "mesh.elements[0]"),
        ("elements = [1, -1]", dimensionless("[mesh]\nelements = [1, -1]"), "mesh.elements[1]"),
        (
            "elements = [i64::MIN, 1]",
            dimensionless("[mesh]\nelements = [-9223372036854775808, 1]"),
            "mesh.elements[0]",
        ),
        (
            "elements = [i64::MAX, 1]",
            dimensionless("[mesh]\nelements = [9223372036854775807, 1]"),
            "mesh.elements[0]",
        ),
        ("elements = [4001, 1]", dimensionless("[mesh]\nelements = [4001, 1]"), "mesh.elements[0]"),
        ("mu = inf", dimensionless("").replace("mu = 1.0", "mu = inf"), "dimensionless.mu"),
        ("gamma = nan", dimensionless("").replace("gamma = 0.25e-3", "gamma = nan"), "dimensionless.gamma"),
        ("gamma = -nan", dimensionless("").replace("gamma = 0.25e-3", "gamma = -nan"), "dimensionless.gamma"),
        ("gamma = -0.0", dimensionless("").replace("gamma = 0.25e-3", "gamma = -0.0"), "dimensionless.gamma"),
        ("delta = inf", dimensionless("").replace("delta = 0.002857", "delta = +inf"), "dimensionless.delta"),
        ("nu = 0.5", dimensionless("").replace("nu = 0.3", "nu = 0.5"), "dimensionless.nu"),
        ("nu = nan", dimensionless("").replace("nu = 0.3", "nu = nan"), "dimensionless.nu"),
        ("x = nan", dimensionless("").replace("x = 0.0", "x = nan"), "load[0].x"),
        ("x = 1e308", dimensionless("").replace("x = 0.0", "x = 1e308"), "load[0].x"),
        ("x = -inf", dimensionless("").replace("x = 0.0", "x = -inf"), "load[0].x"),
        ("point x as a range", dimensionless("").replace("x = 0.0", "x = [0.0, 0.1]"), "load[0].x"),
        ("force = -0.0 (zero resultant)", dimensionless("").replace("force = 1.0", "force = -0.0"), "load"),
        ("force = nan", dimensionless("").replace("force = 1.0", "force = nan"), "load[0].force"),
        ("empty input", String::new(), "plate"),
        (
            "force = 5e-324: a subnormal resultant counts as zero",
            dimensionless("").replace("force = 1.0", "force = 5e-324"),
            "load",
        ),
        ("no loads", dimensionless("").replace("[[load]]\nkind = \"point\"\nx = 0.0\ny = 0.0\nforce = 1.0", ""), "load"),
        (
            "patch range with nan",
            dimensionless("[[load]]\nkind = \"patch\"\nx = [nan, 0.5]\ny = [-0.5, 0.5]\npressure = 1.0"),
            "load[1].x",
        ),
        (
            "patch range reversed",
            dimensionless("[[load]]\nkind = \"patch\"\nx = [0.5, -0.5]\ny = [-0.5, 0.5]\npressure = 1.0"),
            "load[1].x",
        ),
        (
            "patch range empty (-0.0 to 0.0)",
            dimensionless("[[load]]\nkind = \"patch\"\nx = [-0.0, 0.0]\ny = [-0.5, 0.5]\npressure = 1.0"),
            "load[1].x",
        ),
        (
            "patch leaving the plate",
            dimensionless("[[load]]\nkind = \"patch\"\nx = [-1e308, 1e308]\ny = [-0.5, 0.5]\npressure = 1.0"),
            "load[1].x",
        ),
        (
            "uniform with a position",
            dimensionless("[[load]]\nkind = \"uniform\"\nx = 0.0\npressure = 1.0"),
            "load[1].x",
        ),
        (
            "opposite 1e308 forces: the gross load overflows",
            dimensionless(
                "[[load]]\nkind = \"point\"\nx = 0.5\ny = 0.0\nforce = 1e308\n[[load]]\nkind = \"point\"\nx = -0.5\ny = 0.0\nforce = -1e308",
            ),
            "load",
        ),
        (
            "two 1e308 forces: the resultant overflows",
            dimensionless("[[load]]\nkind = \"point\"\nx = 0.5\ny = 0.0\nforce = 1.7976931348623157e308")
                .replace("force = 1.0", "force = 1.7976931348623157e308"),
            "load",
        ),
        (
            "uniform 1e308 pressure: the resultant overflows (reported as adding up to zero)",
            dimensionless("[mesh]\nelements = [2, 2]\n[[load]]\nkind = \"uniform\"\npressure = 1e308"),
            "load",
        ),
        ("penalty = 1.0", dimensionless("[solver]\npenalty = 1.0"), "solver.penalty"),
        ("penalty = 5e-324 is accepted, -0.0 is not", dimensionless("[solver]\npenalty = -0.0"), "solver.penalty"),
        ("max_iterations = 0", dimensionless("[solver]\nmax_iterations = 0"), "solver.max_iterations"),
        (
            "max_iterations = i64::MIN",
            dimensionless("[solver]\nmax_iterations = -9223372036854775808"),
            "solver.max_iterations",
        ),
        (
            "memory_limit_gib = nan",
            dimensionless("[solver]\nmemory_limit_gib = nan"),
            "solver.memory_limit_gib",
        ),
        (
            "both physical and dimensionless",
            format!("{}\n{}", physical(PLATE, WINKLER, ""), dimensionless("")),
            "dimensionless",
        ),
        ("plate without foundation", format!("[plate]\n{PLATE}\n{POINT}"), "foundation"),
        (
            "thickness = 1e308 not below the sides",
            physical(&PLATE.replace("thickness = 0.25", "thickness = 1e308"), WINKLER, POINT),
            "plate.thickness",
        ),
        (
            "length = 5e-324 (subnormal) below the thickness",
            physical(&PLATE.replace("length = 6.0", "length = 5e-324"), WINKLER, POINT),
            "plate.thickness",
        ),
        (
            "winkler with a half-space key",
            physical(PLATE, &format!("{WINKLER}\npoissons_ratio = 0.3"), POINT),
            "foundation.youngs_modulus",
        ),
        (
            "half-space with a Winkler key",
            physical(PLATE, "model = \"half-space\"\nmodulus = 1.0\nyoungs_modulus = 1e8\npoissons_ratio = 0.3", POINT),
            "foundation.modulus",
        ),
        (
            "half-space missing poissons_ratio",
            physical(PLATE, "model = \"half-space\"\nyoungs_modulus = 1e8", POINT),
            "foundation.poissons_ratio",
        ),
    ];
    let cases: Vec<_> = cases
        .into_iter()
        .map(|(case, text, field)| (case, text, Expect::Invalid(field)))
        .collect();
    check(&cases);
}

#[test]
fn odd_but_valid_scenes_do_not_panic() {
    let long_title = format!("title = \"{}\"\n", "é".repeat(200_000));
    let cases: Vec<(&str, String)> = vec![
        ("1 × 1 mesh", dimensionless("[mesh]\nelements = [1, 1]")),
        ("1 × 1 mesh, qp", dimensionless("[mesh]\nelements = [1, 1]\n[solver]\nmethod = \"qp\"")),
        (
            "1 × 1 half-space, gauss",
            dimensionless("[mesh]\nelements = [1, 1]\n[solver]\nconstraint = \"gauss\"")
                .replace("\"winkler\"", "\"half-space\""),
        ),
        ("1 × 8 mesh, bonded", dimensionless("[mesh]\nelements = [1, 8]\n[solver]\ncontact = \"bonded\"")),
        ("odd mesh, symmetric load", dimensionless("[mesh]\nelements = [3, 5]")),
        ("symmetry none", dimensionless("[mesh]\nelements = [2, 2]\nsymmetry = \"none\"")),
        ("point load on a corner", dimensionless("[mesh]\nelements = [2, 2]").replace("x = 0.0\ny = 0.0", "x = 1.0\ny = -1.0")),
        (
            "point load just outside the tolerance band is clamped",
            dimensionless("[mesh]\nelements = [2, 2]").replace("x = 0.0", "x = 1.0000000001"),
        ),
        ("negative zero coordinates", dimensionless("[mesh]\nelements = [2, 2]").replace("x = 0.0\ny = 0.0", "x = -0.0\ny = -0.0")),
        ("upward net load", dimensionless("[mesh]\nelements = [2, 2]").replace("force = 1.0", "force = -1.0")),
        ("huge force 1e308", dimensionless("[mesh]\nelements = [2, 2]").replace("force = 1.0", "force = 1e308")),
        ("penalty = 5e-324", dimensionless("[mesh]\nelements = [2, 2]\n[solver]\npenalty = 5e-324")),
        ("penalty just below 1", dimensionless("[mesh]\nelements = [2, 2]\n[solver]\npenalty = 0.9999999999999999")),
        ("max_iterations = 10000", dimensionless("[mesh]\nelements = [2, 2]\n[solver]\nmax_iterations = 10000")),
        ("memory_limit_gib = 1e308 (inf bytes)", dimensionless("[mesh]\nelements = [2, 2]\n[solver]\nmemory_limit_gib = 1e308")),
        ("memory_limit_gib = 5e-324", dimensionless("[mesh]\nelements = [2, 2]\n[solver]\nmemory_limit_gib = 5e-324")),
        ("gamma = 1e308", dimensionless("[mesh]\nelements = [2, 2]").replace("gamma = 0.25e-3", "gamma = 1e308")),
        ("gamma = 5e-324", dimensionless("[mesh]\nelements = [2, 2]").replace("gamma = 0.25e-3", "gamma = 5e-324")),
        ("delta = 1e308", dimensionless("[mesh]\nelements = [2, 2]").replace("delta = 0.002857", "delta = 1e308")),
        ("delta = 5e-324", dimensionless("[mesh]\nelements = [2, 2]").replace("delta = 0.002857", "delta = 5e-324")),
        ("mu = 1e308", dimensionless("[mesh]\nelements = [2, 2]").replace("mu = 1.0", "mu = 1e308")),
        ("mu = 5e-324", dimensionless("[mesh]\nelements = [2, 3]").replace("mu = 1.0", "mu = 5e-324")),
        ("nu = -0.9999999999999999", dimensionless("[mesh]\nelements = [2, 2]").replace("nu = 0.3", "nu = -0.9999999999999999")),
        (
            "patch of width 5e-324 next to a point load",
            dimensionless("[mesh]\nelements = [2, 2]\n[[load]]\nkind = \"patch\"\nx = [0.0, 5e-324]\ny = [-1.0, 1.0]\npressure = 1e308"),
        ),
        ("very long title", format!("{long_title}{}", dimensionless("[mesh]\nelements = [2, 2]"))),
        (
            "many loads",
            dimensionless(&format!(
                "[mesh]\nelements = [2, 2]\n{}",
                "[[load]]\nkind = \"point\"\nx = 0.25\ny = 0.25\nforce = 1.0\n".repeat(2000)
            )),
        ),
        (
            "physical, youngs_modulus = 1e308 (Γ ≈ 5e295, still finite)",
            physical(&PLATE.replace("youngs_modulus = 30e9", "youngs_modulus = 1e308"), WINKLER, POINT),
        ),
        ("large mesh is validated only", dimensionless("[mesh]\nelements = [4000, 4000]")),
    ];
    let cases: Vec<_> = cases
        .into_iter()
        .map(|(case, text)| (case, text, Expect::Valid))
        .collect();
    check(&cases);
}
