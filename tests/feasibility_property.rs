//! The feasibility check never refuses a load that pushes down (issue 32 §1.1), held by a
//! property test: random jointed slabs on every soil and mesh — free, continuous, aggregate,
//! tied and doweled joints along x and y on the grid's lines, strips one element thin between
//! neighbouring joints included — each panel carrying its self-weight and point loads pushing
//! down at least one element inside their panel. Such a load is always balanced by pressures
//! that only push: each panel's self-weight and its loads have their resultant inside the
//! panel, at least an element from its edges, where non-negative nodal pressures reach (to
//! within a third of an element of the edge). A second property keeps the check honest: a
//! panel cut off by free joints and pulled up is always refused.

use liftoff::{Error, Method, Route};
use proptest::prelude::*;

const SOILS: [&str; 5] = [
    "model = \"winkler\"\nmodulus = 8.0e7",
    "model = \"half-space\"\nyoungs_modulus = 1.0e8\npoissons_ratio = 0.3",
    "model = \"pasternak\"\nmodulus = 5.0e7\nshear_modulus = 2.0e7",
    "model = \"elastic-layer\"\nyoungs_modulus = 5.0e7\npoissons_ratio = 0.3\ndepth = 3.0",
    "model = \"kerr\"\nmodulus = 5.0e7\nshear_modulus = 2.0e7\nupper_modulus = 2.0e8",
];

const KINDS: [&str; 5] = [
    "kind = \"free\"",
    "kind = \"continuous\"",
    "kind = \"aggregate\"\nstiffness = 5.0e8",
    "kind = \"tied\"\nstiffness = 1.0e9\nrotational_stiffness = 5.0e6",
    "kind = \"dowels\"\ndiameter = 0.032\nyoungs_modulus = 200e9\nopening = 0.006\nsupport_modulus = 4.07e11\nspacing = 0.3",
];

/// A 12 × 8 m slab of `nx × ny` elements with joints on the grid lines `xs`, `ys` (indices of
/// interior lines, kinds from `KINDS`) and point loads (a cell index along x and y, a fraction
/// inside it and a force). Each load is placed in the panel holding the chosen position, at
/// least one element inside it: panels under three elements wide carry only their self-weight.
#[allow(clippy::type_complexity)]
fn scene(
    soil: usize,
    [nx, ny]: [usize; 2],
    xs: &[(usize, usize)],
    ys: &[(usize, usize)],
    loads: &[(f64, f64, f64)],
    uplift: Option<f64>,
) -> String {
    let (a, b) = (12.0, 8.0);
    let (hx, hy) = (a / nx as f64, b / ny as f64);
    let mut t = format!(
        "[plate]\nlength = {a}\nwidth = {b}\nthickness = 0.25\nyoungs_modulus = 30e9\npoissons_ratio = 0.15\n[foundation]\n{}\n[mesh]\nelements = [{nx}, {ny}]\n[solver]\ncontact = \"unbonded\"\n",
        SOILS[soil]
    );
    for &(i, k) in xs {
        t += &format!(
            "[[joint]]\nx = {:?}\n{}\n",
            -a / 2.0 + i as f64 * hx,
            KINDS[k]
        );
    }
    for &(j, k) in ys {
        t += &format!(
            "[[joint]]\ny = {:?}\n{}\n",
            -b / 2.0 + j as f64 * hy,
            KINDS[k]
        );
    }
    t += "[[load]]\nkind = \"uniform\"\npressure = 6.0e3\n";
    // Panel bounds (as grid line indices) along one axis holding the fraction `f` of it.
    let panel = |lines: &[(usize, usize)], n: usize, f: f64| -> (usize, usize) {
        let mut cuts: Vec<usize> = lines.iter().map(|l| l.0).collect();
        cuts.push(0);
        cuts.push(n);
        cuts.sort_unstable();
        cuts.dedup();
        let at = f * n as f64;
        let k = cuts
            .iter()
            .rposition(|&c| (c as f64) <= at)
            .unwrap_or(0)
            .min(cuts.len() - 2);
        (cuts[k], cuts[k + 1])
    };
    for &(fx, fy, force) in loads {
        let (x0, x1) = panel(xs, nx, fx);
        let (y0, y1) = panel(ys, ny, fy);
        if x1 - x0 < 3 || y1 - y0 < 3 {
            continue;
        }
        // At least one element inside the panel: within [x0 + 1, x1 − 1] elements.
        let u = |lo: usize, hi: usize, f: f64| lo as f64 + 1.0 + (hi - lo - 2) as f64 * f;
        let x = -a / 2.0 + u(x0, x1, (fx * 7.3).fract()) * hx;
        let y = -b / 2.0 + u(y0, y1, (fy * 5.1).fract()) * hy;
        t += &format!("[[load]]\nkind = \"point\"\nx = {x:?}\ny = {y:?}\nforce = {force:?}\n");
    }
    if let Some(force) = uplift {
        // Pull up the first panel (cut off by a free joint) harder than its weight holds it.
        t += &format!(
            "[[load]]\nkind = \"point\"\nx = {:?}\ny = 0.0\nforce = {force:?}\n",
            -a / 2.0 + 0.5 * hx
        );
    }
    t
}

/// Joint lines: distinct interior grid lines with a kind each.
fn lines(n: usize, most: usize) -> impl Strategy<Value = Vec<(usize, usize)>> {
    prop::collection::vec((1..n, 0..KINDS.len()), 0..=most).prop_map(|mut v| {
        v.sort_unstable();
        v.dedup_by_key(|l| l.0);
        v
    })
}

/// Whether the feasibility check of `text`'s operators refuses it, for either method.
fn refused(text: &str) -> Option<String> {
    let problem = match liftoff::Problem::from_toml(text) {
        Ok(p) => p,
        Err(e) => return Some(format!("scene refused: {e}")),
    };
    for method in [
        Method::Penalty(Default::default()),
        Method::Qp(Default::default()),
    ] {
        let ops = match liftoff::analysis::prepare(
            &problem.model,
            &method,
            Route::Auto,
            problem.memory_limit,
        ) {
            Ok(o) => o,
            Err(e) => return Some(format!("{}: {e}", method.name())),
        };
        if let Err(e) = liftoff::solve::check_feasible(&ops) {
            return Some(format!("{}: {e}", method.name()));
        }
    }
    None
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 160, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn loads_that_push_down_inside_their_panels_are_never_refused(
        soil in 0..SOILS.len(),
        mesh in prop::sample::select(vec![[12usize, 8usize], [16, 12], [24, 16], [30, 20]]),
        xs in lines(12, 3),
        ys in lines(8, 2),
        loads in prop::collection::vec((0.0..1.0f64, 0.0..1.0f64, 1.0e3..5.0e5f64), 0..4),
    ) {
        // Joint indices drawn for the coarsest mesh, scaled to this one (so lines stay on it).
        let scale = [mesh[0] / 12, mesh[1] / 8];
        let xs: Vec<_> = xs.iter().map(|&(i, k)| (i * scale[0].max(1), k)).collect();
        let ys: Vec<_> = ys.iter().map(|&(j, k)| (j * scale[1].max(1), k)).collect();
        let text = scene(soil, mesh, &xs, &ys, &loads, None);
        // A dowel bar on a crossing joint is a scene error (E56), not the check's business.
        prop_assume!(liftoff::Problem::from_toml(&text).is_ok());
        let r = refused(&text);
        prop_assert!(r.is_none(), "{}\n{text}", r.unwrap_or_default());
    }

    #[test]
    fn a_panel_cut_off_and_pulled_up_is_refused(
        soil in 0..SOILS.len(),
        at in 2usize..10,
    ) {
        // A free joint at line `at` of 12: the first panel weighs 6 kPa × its area; a pull of
        // twice that lifts it whatever its joints elsewhere.
        let weight = 6.0e3 * (at as f64 * 1.0) * 8.0;
        let text = scene(soil, [12, 8], &[(at, 0)], &[], &[], Some(-2.0 * weight));
        prop_assert!(refused(&text).is_some(), "accepted:\n{text}");
    }
}

/// The refusal is the feasibility check's own (not a scene error): the second property's
/// scene passes validation and fails at the check, as `Error::Infeasible`.
#[test]
fn the_pulled_panel_is_refused_by_the_check() {
    let text = scene(0, [12, 8], &[(4, 0)], &[], &[], Some(-4.0e5));
    let problem = liftoff::Problem::from_toml(&text).unwrap_or_else(|e| panic!("{e}"));
    let ops = liftoff::Operators::assemble(&problem.model);
    match liftoff::solve::check_feasible(&ops) {
        Err(Error::Infeasible(m)) => assert!(m.contains("upward"), "{m}"),
        other => panic!("{other:?}"),
    }
}
