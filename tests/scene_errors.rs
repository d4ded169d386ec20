//! Every malformed scene is rejected with a message naming the offending field.

use liftoff::{Error, Problem};

use crate::common;
use common::BASE;

fn rejected(text: &str) -> String {
    match Problem::from_toml(text) {
        Ok(_) => panic!("scene was accepted:\n{text}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn the_base_scene_is_valid() {
    Problem::from_toml(BASE).expect("base scene");
}

#[test]
fn bad_values_name_their_field() {
    let cases: &[(&str, &str, &str)] = &[
        ("thickness = 0.25", "thickness = -0.25", "plate.thickness"),
        ("thickness = 0.25", "thickness = 5.0", "plate.thickness"),
        ("length = 6.0", "length = 0.0", "plate.length"),
        ("width = 4.0", "width = nan", "plate.width"),
        (
            "youngs_modulus = 30e9",
            "youngs_modulus = inf",
            "plate.youngs_modulus",
        ),
        (
            "poissons_ratio = 0.2",
            "poissons_ratio = 0.5",
            "plate.poissons_ratio",
        ),
        (
            "poissons_ratio = 0.2",
            "poissons_ratio = -1.0",
            "plate.poissons_ratio",
        ),
        ("modulus = 5e7", "modulus = -5e7", "foundation.modulus"),
        (
            "modulus = 5e7",
            "youngs_modulus = 5e7",
            "foundation.youngs_modulus",
        ),
        ("x = 1.5", "x = 3.5", "load[0].x"),
        ("y = 1.0", "y = -2.01", "load[0].y"),
        ("x = 1.5", "x = [0.0, 1.0]", "load[0].x"),
        ("force = 2.0e5", "force = 0.0", "load"),
        ("force = 2.0e5", "pressure = 2.0e5", "load[0].pressure"),
        ("elements = [8, 8]", "elements = [0, 8]", "mesh.elements[0]"),
        (
            "elements = [8, 8]",
            "elements = [8, 100000]",
            "mesh.elements[1]",
        ),
        (
            "[mesh]",
            "[solver]\npenalty = 2.0\n[mesh]",
            "solver.penalty",
        ),
        (
            "[mesh]",
            "[solver]\nmax_iterations = 0\n[mesh]",
            "solver.max_iterations",
        ),
        (
            "[mesh]",
            "[solver]\ncg_tolerance = 1e-3\n[mesh]",
            "solver.cg_tolerance",
        ),
        (
            "[mesh]",
            "[solver]\ncg_tolerance = 0.0\n[mesh]",
            "solver.cg_tolerance",
        ),
    ];
    for (from, to, field) in cases {
        assert!(BASE.contains(from), "case setup: {from}");
        let msg = rejected(&BASE.replacen(from, to, 1));
        assert!(
            msg.contains(field),
            "`{to}` should name `{field}`, got: {msg}"
        );
    }
}

#[test]
fn unknown_keys_and_wrong_types_are_parse_errors_naming_the_key() {
    let cases: &[(&str, &str, &str)] = &[
        (
            "thickness = 0.25",
            "thickness = 0.25\nthicknes = 0.3",
            "thicknes",
        ),
        ("[mesh]", "[meshes]", "meshes"),
        ("model = \"winkler\"", "model = \"winkel\"", "winkel"),
        ("kind = \"point\"", "kind = \"wind\"", "wind"),
        ("thickness = 0.25", "thickness = \"thick\"", "thickness"),
    ];
    for (from, to, key) in cases {
        let text = BASE.replacen(from, to, 1);
        match Problem::from_toml(&text) {
            Err(Error::Parse(msg)) => assert!(
                msg.contains(key),
                "`{to}`: message should mention `{key}`: {msg}"
            ),
            other => panic!("`{to}` should be a parse error, got {other:?}"),
        }
    }
}

#[test]
fn missing_sections_are_named() {
    let no_foundation = BASE.replace("[foundation]\nmodel = \"winkler\"\nmodulus = 5e7\n", "");
    assert!(rejected(&no_foundation).contains("foundation"));
    let both = format!("{BASE}\n[dimensionless]\nfoundation = \"winkler\"\ngamma = 1e-3\ndelta = 1e-3\nmu = 1.0\nnu = 0.3\n");
    assert!(rejected(&both).contains("dimensionless"));
    let no_loads: String = BASE
        .split("[[load]]")
        .next()
        .unwrap_or_default()
        .to_string()
        + "[mesh]\nelements = [8, 8]\n";
    assert!(rejected(&no_loads).contains("load"));
    let half_space_missing = BASE.replace(
        "model = \"winkler\"\nmodulus = 5e7",
        "model = \"half-space\"\nyoungs_modulus = 5e7",
    );
    assert!(rejected(&half_space_missing).contains("foundation.poissons_ratio"));
}

#[test]
fn odd_meshes_fall_back_to_the_full_plate_and_say_so() {
    let text = BASE
        .replace("x = 1.5", "x = 0.0")
        .replace("y = 1.0", "y = 0.0")
        .replace("elements = [8, 8]", "elements = [7, 8]");
    let p = Problem::from_toml(&text).expect("valid");
    let (mesh, notes) = p.model.plan_mesh();
    assert_eq!(mesh.symmetry_name(), "half-y");
    assert!(
        notes
            .iter()
            .any(|n| n.contains("mesh.elements[0]") && n.contains("odd")),
        "{notes:?}"
    );
}

#[test]
fn meshes_beyond_memory_are_refused_before_allocating() {
    let text = BASE.replace(
        "elements = [8, 8]",
        "elements = [3000, 3000]\n[solver]\nmemory_limit_gib = 1.0",
    );
    let p = Problem::from_toml(&text).expect("valid scene");
    match liftoff::budget::check(&p.model, &p.method, p.memory_limit) {
        Err(Error::TooLarge {
            need_gib,
            limit_gib,
            ..
        }) => assert!(need_gib > limit_gib),
        other => panic!("expected TooLarge, got {:?}", other.map(|_| ())),
    }
}

/// Found by fuzzing (fuzz/RESULTS.md): extra element counts, values whose combination leaves
/// double precision, and load totals that overflow are validation errors naming the field.
#[test]
fn fuzz_findings_are_validation_errors() {
    let cases: &[(&str, &str, &str)] = &[
        ("elements = [8, 8]", "elements = [1, 1, 1]", "mesh.elements"),
        ("elements = [8, 8]", "elements = [8]", "mesh.elements"),
        (
            "thickness = 0.25",
            "thickness = 1e-200",
            "outside double precision",
        ),
        (
            "modulus = 5e7",
            "modulus = 5e-324",
            "outside double precision",
        ),
        (
            "force = 2.0e5",
            "force = 1.7e308\n[[load]]\nkind = \"point\"\nx = 0.0\ny = 0.0\nforce = 1.7e308",
            "overflow",
        ),
    ];
    for (from, to, needle) in cases {
        let msg = rejected(&BASE.replacen(from, to, 1));
        assert!(
            msg.contains(needle),
            "`{to}` should mention `{needle}`, got: {msg}"
        );
    }
}
