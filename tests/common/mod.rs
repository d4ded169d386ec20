//! Helpers shared by the integration tests.
#![allow(dead_code)]

pub mod infinite;

use liftoff::model::ConstraintPoints;
use liftoff::post::Report;
use liftoff::study::{eps_sweep, log_space, StabilityRow};
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

/// Parse, validate and solve scene text, panicking with the scene's error or when the method
/// did not converge (tests only): every comparison in the suite needs each of its sides to
/// have converged, since two failed solves can agree. A test that studies a failure calls
/// `analyse` itself.
pub fn run(text: &str) -> Analysis {
    let problem =
        Problem::from_toml(text).unwrap_or_else(|e| panic!("scene rejected: {e}\n{text}"));
    let a = analyse(&problem).unwrap_or_else(|e| panic!("solve failed: {e}\n{text}"));
    assert!(
        a.solution.status.converged(),
        "{} solve did not converge: {}\n{text}",
        a.solution.method.name(),
        a.solution.status.describe()
    );
    a
}

/// A scene of one load set through the front ends' seam (`liftoff::load`, `liftoff::run`) with
/// the given options, panicking on an error or a solve that did not converge (as [`run`]).
pub fn run_source(source: &liftoff::Source, overrides: &liftoff::scene::Overrides) -> Analysis {
    let problem = liftoff::load(source, overrides).unwrap_or_else(|e| panic!("scene: {e}"));
    let a = match liftoff::run(&problem, &liftoff::Monitor::NONE) {
        Ok(liftoff::Outcome::Single(a)) => *a,
        Ok(liftoff::Outcome::Combinations(_)) => panic!("the scene has combinations"),
        Err(e) => panic!("solve failed: {e}"),
    };
    assert!(
        a.solution.status.converged(),
        "{} solve did not converge: {}",
        a.solution.method.name(),
        a.solution.status.describe()
    );
    a
}

/// [`run_source`] of scene text.
pub fn run_toml(text: &str, overrides: &liftoff::scene::Overrides) -> Analysis {
    run_source(&liftoff::Source::Toml(text), overrides)
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

/// Penalty → QP at first order in ε̄ on `p`: the fitted log–log slope of the relative L2
/// error of σ against the QP on the same operators lies within 0.1 of 1 over at least three
/// decades, and the error is below 100 ε̄ from the fit's lower end to ε̄ = 1e−5.
///
/// Both sides of the comparison converge: `eps_sweep` refuses a QP reference that did not
/// (`Error::Numerical`, so `expect` fails here), and every penalty row from ε̄ = 1e−5 down is
/// asserted converged below; above it a too-weak penalty still gives a point of the ε̄ → 0
/// curve, and the fit uses only settled sets.
pub fn assert_first_order_in_eps(p: &Problem) {
    let eps = log_space(1e-2, 1e-9, 15);
    let sweep = eps_sweep(
        p,
        &eps,
        &[ConstraintPoints::Nodal],
        [1e-9, 1e-2],
        &liftoff::Monitor::NONE,
    )
    .expect("sweep");
    for (kind, slope, range) in &sweep.slopes {
        let slope = slope.unwrap_or(f64::NAN);
        println!("{kind}: slope {slope}, range {range:?}");
        assert!((slope - 1.0).abs() < 0.1, "{kind}: fitted slope {slope}");
        assert!(range[1] / range[0] > 0.99e3, "{kind}: span {range:?}");
    }
    let floor_from = sweep.slopes.first().map_or(1e-8, |s| s.2[0]);
    for r in sweep.rows.iter().filter(|r| r.eps <= 1e-5) {
        println!("ε̄ = {:e}: error {:e}", r.eps, r.rel_l2_sigma);
        assert!(r.converged, "ε̄ = {:e}: {}", r.eps, r.status);
        assert!(
            r.eps < floor_from || r.rel_l2_sigma < 100.0 * r.eps,
            "ε̄ = {:e}: error {:e}",
            r.eps,
            r.rel_l2_sigma
        );
    }
}

/// A deflectometer's drop on a square bonded slab of side `side` on springs of modulus `k`,
/// n × n elements: the disk of `radius` carrying `force` centred at `at`, and the deflections
/// at `offsets` along x from its centre (FullField::at). The solve converged and its reaction
/// is the force (the disk's bands carry its area exactly: 1e-9).
pub fn disk_basin(
    plate: &infinite::Plate,
    k: f64,
    side: f64,
    n: usize,
    (radius, force): (f64, f64),
    at: [f64; 2],
    offsets: &[f64],
) -> Vec<f64> {
    let [cx, cy] = at;
    let infinite::Plate { e, nu, h } = plate;
    let scene = format!(
        r#"
[plate]
length = {side}
width = {side}
thickness = {h}
youngs_modulus = {e}
poissons_ratio = {nu}
[foundation]
model = "winkler"
modulus = {k}
[[load]]
kind = "circle"
x = {cx}
y = {cy}
radius = {radius}
force = {force}
[mesh]
elements = [{n}, {n}]
[solver]
contact = "bonded"
"#
    );
    let p = Problem::from_toml(&scene).expect("scene");
    let liftoff::Outcome::Single(a) = liftoff::run(&p, &liftoff::Monitor::NONE).expect("solve")
    else {
        panic!("one solve")
    };
    assert!(a.summary.converged);
    let load = a.summary.resultant.load;
    assert!((load - force).abs() <= 1e-9 * force, "resultant {load}");
    let f = &a.report.field;
    offsets
        .iter()
        .map(|&x| f.at(&f.w, cx + x, cy).expect("on the plate"))
        .collect()
}

/// Why a converged row of the stability study breaks what every converged run holds, or None:
/// equilibrium within the analysis's tolerance, a contact fraction in (0, 1], at least one
/// iteration — a QP whose start is its answer takes none (a plate balanced on one node: one
/// feasible pressure, under 1 % contact) —, and the QP's pressures ≥ −1e-9 (its round-off). NaN
/// fails each. (tests/studies.rs and tests/stability_gamma.rs hold their rows to it.)
pub fn converged_row_fault(r: &StabilityRow) -> Option<String> {
    let qp = r.method.name() == "qp";
    if r.equilibrium.is_nan() || r.equilibrium > liftoff::solve::EQUILIBRIUM_TOLERANCE {
        return Some(format!("equilibrium {:e}", r.equilibrium));
    }
    if !(r.contact_fraction > 0.0 && r.contact_fraction <= 1.0) {
        return Some(format!("contact fraction {}", r.contact_fraction));
    }
    if r.iterations == 0 && !(qp && r.contact_fraction < 0.01) {
        return Some("no iteration".to_string());
    }
    if qp && (r.min_pressure.is_nan() || r.min_pressure < -1e-9) {
        return Some(format!("QP min σ {:e}", r.min_pressure));
    }
    None
}
