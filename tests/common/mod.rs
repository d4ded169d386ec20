//! Helpers shared by the integration tests.
#![allow(dead_code)]

use liftoff::post::Report;
use liftoff::{analyse, Analysis, Problem};

/// A dimensionless scene with one point load (s, t) and the given groups.
pub fn point_scene(
    foundation: &str,
    gamma: f64,
    delta: f64,
    mu: f64,
    (s, t): (f64, f64),
    elements: [usize; 2],
    extra: &str,
) -> String {
    format!(
        r#"
[dimensionless]
foundation = "{foundation}"
gamma = {gamma:e}
delta = {delta:e}
mu = {mu}
nu = 0.3
[[load]]
kind = "point"
x = {s}
y = {t}
force = 1.0
[mesh]
elements = [{}, {}]
{extra}
"#,
        elements[0], elements[1]
    )
}

/// Parse, validate and solve scene text, panicking with the scene's error (tests only).
pub fn run(text: &str) -> Analysis {
    let problem =
        Problem::from_toml(text).unwrap_or_else(|e| panic!("scene rejected: {e}\n{text}"));
    analyse(&problem).unwrap_or_else(|e| panic!("solve failed: {e}\n{text}"))
}

/// Largest absolute difference of two equally long slices.
pub fn max_abs_diff(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

/// Largest absolute value.
pub fn max_abs(a: &[f64]) -> f64 {
    a.iter().map(|x| x.abs()).fold(0.0, f64::max)
}

/// The README's physical scene trimmed to one point load on an 8 × 8 mesh: the valid starting
/// point that the validation and exit-code tests edit one field at a time.
pub const BASE: &str = r#"
[plate]
length = 6.0
width = 4.0
thickness = 0.25
youngs_modulus = 30e9
poissons_ratio = 0.2
[foundation]
model = "winkler"
modulus = 5e7
[[load]]
kind = "point"
x = 1.5
y = 1.0
force = 2.0e5
[mesh]
elements = [8, 8]
"#;

/// Every outcome kind a stability row or study point may carry, written out here (not taken
/// from the library) so that a new kind must be added on purpose.
pub const OUTCOMES: [&str; 8] = [
    "converged",
    "cycling",
    "iteration-limit",
    "penalty-too-weak",
    "solver-failure",
    "infeasible",
    "too-large",
    "numerical",
];

/// Index of the node nearest (x, y).
pub fn node_at(r: &Report, x: f64, y: f64) -> usize {
    let f = &r.field;
    (0..f.x.len())
        .min_by(|&a, &b| {
            let da = (f.x[a] - x).hypot(f.y[a] - y);
            let db = (f.x[b] - x).hypot(f.y[b] - y);
            da.total_cmp(&db)
        })
        .unwrap_or(0)
}
