//! The iterative route (FFT compliance, conjugate gradients) against the dense route (dense T,
//! direct factorisations) on the same scenes: the reference is the dense solve, which shares
//! no linear algebra with the iterative one beyond the plate stiffness and the pair integrals.

use liftoff::method::{Method, PenaltySettings, Route};
use liftoff::{Operators, Problem, Solution};

/// The paper's Fig. 3 case (square plate, half-space, central point load, Γ = 0.25e-3) at `n`
/// elements per side of the whole plate, quarter model.
fn paper(n: usize) -> Problem {
    let text = liftoff::examples::scene("paper-halfspace").unwrap_or_default();
    Problem::from_toml(&text.replace("elements = [16, 16]", &format!("elements = [{n}, {n}]")))
        .unwrap_or_else(|e| panic!("paper scene at {n}: {e}"))
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().map(|x| x.abs()).fold(0.0, f64::max)
}

fn rel_diff(a: &[f64], b: &[f64]) -> f64 {
    let d = a
        .iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    d / max_abs(b)
}

/// Solve `problem` with `method` on both routes; return (dense, iterative) and the operators
/// of the dense route (for the deflections).
fn both(problem: &Problem, method: &Method) -> (Solution, Solution, Operators) {
    let dense_ops = Operators::assemble_with(&problem.model, false);
    let iter_ops = Operators::assemble_with(&problem.model, true);
    assert!(
        matches!(
            iter_ops.t.as_ref(),
            liftoff::foundation::Compliance::Toeplitz(_)
        ),
        "the iterative route holds T as an FFT operator"
    );
    let dense = liftoff::solve(&dense_ops, method).expect("dense route");
    let iterative = liftoff::solve(&iter_ops, method).expect("iterative route");
    (dense, iterative, dense_ops)
}

/// V and σ to 1e-6 relative and the same contact set (the CG tolerance 1e-10 gives ~1e-9; the
/// issue asks for 1e-6), the same status and number of penalty steps or one more (the route
/// confirms the set with a tight solve after its loose ones).
fn assert_same(name: &str, ops: &Operators, dense: &Solution, iterative: &Solution) {
    // Two failed solves would agree too: each side must have converged.
    assert!(
        dense.status.converged(),
        "{name}: dense route: {}",
        dense.status.describe()
    );
    assert!(
        iterative.status.converged(),
        "{name}: iterative route: {}",
        iterative.status.describe()
    );
    assert_eq!(dense.status, iterative.status, "{name}: status");
    let dv = rel_diff(&ops.node_w(&iterative.u), &ops.node_w(&dense.u));
    let ds = rel_diff(&iterative.sigma, &dense.sigma);
    assert!(dv < 1e-6, "{name}: V differs by {dv:e} (relative)");
    assert!(ds < 1e-6, "{name}: σ differs by {ds:e} (relative)");
    let contact = |s: &Solution| s.sigma.iter().map(|&v| v > 0.0).collect::<Vec<_>>();
    assert_eq!(
        contact(dense),
        contact(iterative),
        "{name}: contact sets differ"
    );
    assert!(
        iterative.info.cg_iterations.is_some_and(|n| n > 0),
        "{name}: the iterative route reports its CG iterations"
    );
}

#[test]
fn iterative_equals_dense_on_the_paper_case_at_32_and_64() {
    for n in [32, 64] {
        let p = paper(n);
        let method = Method::Penalty(PenaltySettings::fixed(1e-5));
        let (dense, iterative, ops) = both(&p, &method);
        assert!(dense.status.converged(), "dense at {n}: {:?}", dense.status);
        assert_same(&format!("paper case at {n}"), &ops, &dense, &iterative);
        // Every step's CG residual is reported and below the loose tolerance, the last one
        // below the tight one.
        let last = iterative
            .history
            .last()
            .and_then(|h| h.cg)
            .expect("CG report");
        assert!(
            last.residual <= 1e-10,
            "last step residual {}",
            last.residual
        );
    }
}

/// A load off both axes: the whole plate (3 rigid modes, 3 equilibrium constraints); a load on
/// y = 0 only: a half model (2 constraints).
#[test]
fn iterative_equals_dense_on_full_and_half_models() {
    for (name, x, y) in [("full", 0.3, 0.2), ("half", 0.35, 0.0)] {
        let p = Problem::from_toml(&format!(
            "[dimensionless]\nfoundation = \"half-space\"\ngamma = 1e-3\ndelta = 0.002857\nmu = 0.75\nnu = 0.3\n\
             [[load]]\nkind = \"point\"\nx = {x}\ny = {y}\nforce = 1.0\n\
             [mesh]\nelements = [20, 16]\n[solver]\npenalty = 1e-5\n"
        ))
        .expect("scene");
        let (dense, iterative, ops) = both(&p, &p.method);
        assert_eq!(
            ops.mesh.symmetry_name(),
            if name == "full" { "full" } else { "half-y" },
            "{name}: model"
        );
        assert_same(name, &ops, &dense, &iterative);
    }
}

#[test]
fn bonded_iterative_equals_dense() {
    let p = paper(24);
    let (dense, iterative, ops) = both(&p, &Method::Bonded);
    assert_same("bonded", &ops, &dense, &iterative);
}

#[test]
fn the_route_is_chosen_by_size_and_refused_for_clarabel() {
    let small = paper(32);
    let big = paper(256);
    let pen = Method::penalty();
    let limit = 16.0 * 1024f64.powi(3);
    let toeplitz =
        |p: &Problem, m: &Method, r: Route| liftoff::budget::check_route(&p.model, m, r, limit);
    assert!(
        !toeplitz(&small, &pen, Route::Auto).expect("fits"),
        "289 nodes: dense"
    );
    assert!(
        toeplitz(&big, &pen, Route::Auto).expect("fits"),
        "16 641 nodes: iterative"
    );
    assert!(toeplitz(&small, &pen, Route::Iterative).expect("fits"));
    // The QP takes the route like the penalty (the matrix-free solver runs on it) …
    assert!(
        liftoff::budget::toeplitz(&big.model, &Method::qp(), Route::Auto).expect("auto"),
        "QP: iterative beyond the dense size"
    );
    assert!(
        !liftoff::budget::toeplitz(&small.model, &Method::qp(), Route::Auto).expect("auto"),
        "QP: dense (clarabel) below it"
    );
    // … but clarabel, which needs the dense Schur complement, is refused on it.
    let clarabel = Method::Qp(liftoff::QpSettings {
        solver: liftoff::method::QpSolver::Clarabel,
        ..Default::default()
    });
    assert!(
        !liftoff::budget::toeplitz(&big.model, &clarabel, Route::Auto).expect("auto"),
        "clarabel: dense whatever the size"
    );
    match toeplitz(&small, &clarabel, Route::Iterative) {
        Err(liftoff::Error::Invalid { field, .. }) => assert_eq!(field, "solver.route"),
        other => panic!("clarabel on the iterative route: {other:?}"),
    }
    // 256 × 256 dense needs the Schur complement and its copies (~8 GiB): refused at 4 GiB,
    // while the iterative route fits.
    let four = 4.0 * 1024f64.powi(3);
    assert!(liftoff::budget::check_route(&big.model, &pen, Route::Dense, four).is_err());
    assert!(liftoff::budget::check_route(&big.model, &pen, Route::Auto, four).expect("fits"));
}

#[test]
fn the_scene_and_the_analysis_follow_the_route() {
    let text = liftoff::examples::scene("paper-halfspace").unwrap_or_default();
    let p = Problem::from_toml(&text.replace(
        "constraint = \"nodal\"",
        "constraint = \"nodal\"\nroute = \"iterative\"",
    ))
    .expect("scene with a route");
    assert_eq!(p.route, Route::Iterative);
    let a = liftoff::analyse(&p).expect("analysis");
    assert!(
        a.solution.info.cg_iterations.is_some(),
        "solved iteratively"
    );
    assert!(a.summary.solver_info.contains_key("cg_iterations"));
    let bad = text.replace(
        "constraint = \"nodal\"",
        "constraint = \"nodal\"\nroute = \"fast\"",
    );
    assert!(Problem::from_toml(&bad).is_err(), "unknown route refused");
}

/// Gauss-point constraints: the penalty couples the four nodes of an element, the
/// preconditioner keeps only its diagonal; the answer is still the dense one.
#[test]
fn iterative_equals_dense_with_gauss_constraints() {
    let text = liftoff::examples::scene("paper-halfspace").unwrap_or_default();
    let p = Problem::from_toml(
        &text
            .replace("elements = [16, 16]", "elements = [24, 24]")
            .replace("constraint = \"nodal\"", "constraint = \"gauss\""),
    )
    .expect("scene");
    let method = Method::Penalty(PenaltySettings::fixed(1e-5));
    let (dense, iterative, ops) = both(&p, &method);
    assert_same("gauss", &ops, &dense, &iterative);
}

/// The CLI's `--solver` flag: the iterative route reports its CG iterations and gives the
/// dense route's contact radius; the QP on the iterative route is refused (exit 2, the scene
/// field named).
#[test]
fn the_solver_flag_selects_the_route() {
    let run = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_liftoff"))
            .args(args)
            .output()
            .expect("run liftoff")
    };
    let json = |route: &str| -> serde_json::Value {
        let o = run(&[
            "solve",
            "example:paper-halfspace",
            "--mesh",
            "32,32",
            "--solver",
            route,
            "--json",
        ]);
        assert!(
            o.status.success(),
            "{route}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        serde_json::from_slice(&o.stdout).expect("summary.json")
    };
    let dense = json("dense");
    let iterative = json("iterative");
    assert!(
        dense["solver_info"]["cg_iterations"].is_null(),
        "dense: no CG"
    );
    assert!(
        iterative["solver_info"]["cg_iterations"]
            .as_f64()
            .unwrap_or(0.0)
            > 0.0,
        "iterative: CG iterations reported"
    );
    let (rd, ri) = (
        dense["contact_radius"].as_f64().unwrap_or(f64::NAN),
        iterative["contact_radius"].as_f64().unwrap_or(f64::NAN),
    );
    // σ agrees to ~1e-9, so the located boundary does too; 1e-6 is the tolerance.
    assert!((rd - ri).abs() < 1e-6, "contact radius {rd} vs {ri}");
    let qp = run(&[
        "solve",
        "example:paper-halfspace",
        "--solver",
        "iterative",
        "--method",
        "qp",
        "--qp-solver",
        "clarabel",
    ]);
    assert_eq!(qp.status.code(), Some(2), "clarabel on the iterative route");
    assert!(String::from_utf8_lossy(&qp.stderr).contains("solver.route"));
    let qp = run(&[
        "solve",
        "example:paper-halfspace",
        "--solver",
        "iterative",
        "--method",
        "qp",
        "--json",
    ]);
    assert_eq!(qp.status.code(), Some(0), "the QP on the iterative route");
    let qp: serde_json::Value = serde_json::from_slice(&qp.stdout).expect("json");
    assert_eq!(
        qp["qp_solver"], "active-set",
        "auto takes the matrix-free QP there"
    );
}

/// `[solver] cg_tolerance` reaches the penalty's confirming solves: at 1e-8 the answer is the
/// default's (1e-10) to what a residual of 1e-8 allows — the error in σ is about κ·1e-8 of its
/// scale, and the contact set is confirmed all the same; 1e-5 relative leaves room for the
/// conditioning (on this case the difference is 6e-8) — its last step's residual is below 1e-8
/// but not forced below 1e-10 (8e-9 against 6e-11 here), and it takes no more CG iterations
/// than the default (93 against 102 here).
#[test]
fn the_cg_tolerance_key_sets_the_confirming_solves() {
    let scene = |extra: &str| {
        let text = liftoff::examples::scene("paper-halfspace").unwrap_or_default();
        let text = text.replace("elements = [16, 16]", "elements = [48, 48]");
        let text = text.replace(
            "[solver]",
            &format!("[solver]\nroute = \"iterative\"\n{extra}"),
        );
        Problem::from_toml(&text).unwrap_or_else(|e| panic!("scene ({extra}): {e}"))
    };
    let (default, loose) = (scene(""), scene("cg_tolerance = 1e-8"));
    match (&default.method, &loose.method) {
        (Method::Penalty(d), Method::Penalty(l)) => {
            assert_eq!(d.cg.tolerance, 1e-10, "the default");
            assert_eq!(l.cg.tolerance, 1e-8, "the key");
        }
        other => panic!("the paper's scene is solved by the penalty: {other:?}"),
    }
    let ops = Operators::assemble_with(&default.model, true);
    let a = liftoff::solve(&ops, &default.method).expect("default tolerance");
    let b = liftoff::solve(&ops, &loose.method).expect("cg_tolerance = 1e-8");
    assert!(a.status.converged() && b.status.converged());
    let ds = rel_diff(&b.sigma, &a.sigma);
    assert!(ds < 1e-5, "σ differs by {ds:e}");
    let last = |s: &Solution| s.history.last().and_then(|h| h.cg).expect("CG report");
    assert!(last(&b).residual <= 1e-8, "residual {}", last(&b).residual);
    assert!(last(&a).residual <= 1e-10, "residual {}", last(&a).residual);
    let (na, nb) = (
        a.info.cg_iterations.expect("CG count"),
        b.info.cg_iterations.expect("CG count"),
    );
    assert!(nb <= na, "1e-8 took {nb} CG iterations, 1e-10 {na}");
}

/// A penalty step after another starts from its answer with the products T σ and S σ the last
/// solve ended with (`IterativeSchur::solve_pressures`), instead of forming them again; it skips
/// only a round-off move onto the equilibrium. Against a fresh solve started from the same σ
/// (`warm_start`, which forms them) it may differ by what two solves to the tight tolerance may
/// (each within about the preconditioned system's condition number times 1e-10 of the exact
/// σ): measured 2e-14 and 8e-13, 1e-8 allowed. Both cases the penalty iteration meets: the same weights solved again to
/// a tighter tolerance (a set confirmed), and other weights (the set changed) — after a loose
/// step, whose products are the iterations' updates, not formed again. Paper's case at
/// 32², quarter model; penalty weights at ε̄ = 1e-5 on the points the bonded solve puts in
/// tension, then on those and a ring about the centre.
#[test]
fn a_step_starts_from_the_last_answers_products() {
    use liftoff::solve::iterative::IterativeSchur;
    use liftoff::CgSettings;
    let p = paper(32);
    let ops = Operators::assemble_with(&p.model, true);
    let monitor = liftoff::Monitor::NONE;
    let n = ops.n_sigma();
    assert_eq!(ops.constraints.g.rows(), n, "nodal constraints");
    let rows: Vec<Vec<(usize, f64)>> = (0..n).map(|k| vec![(k, 1.0)]).collect();
    let weight = |k: usize| ops.foundation_constant * ops.constraints.weights[k] / 1e-5;
    let bonded = liftoff::solve(&ops, &Method::Bonded).expect("bonded");
    let first: Vec<f64> = (0..n)
        .map(|k| {
            if bonded.sigma[k] < 0.0 {
                weight(k)
            } else {
                0.0
            }
        })
        .collect();
    assert!(
        first.iter().any(|&d| d > 0.0),
        "the bonded plate pulls somewhere"
    );
    let second: Vec<f64> = (0..n)
        .map(|k| {
            let (x, y) = ops.constraints.points[k];
            let ring = (0.3..0.4).contains(&x.hypot(y));
            if first[k] > 0.0 || ring {
                weight(k)
            } else {
                0.0
            }
        })
        .collect();
    assert!(second != first, "the ring adds points");
    let new = || IterativeSchur::new(&ops, CgSettings::default()).expect("iterative system");

    let mut steps = new();
    steps
        .solve_pressures(&ops, &rows, &second, Some(1e-4), &monitor)
        .expect("loose solve");
    // A loose step from the last answer's products: one product an iteration and none for its
    // answer, whose products are the iterations' updates, not formed again.
    let made = steps.products;
    let (mut before, _, loose) = steps
        .solve_pressures(&ops, &rows, &first, Some(1e-4), &monitor)
        .expect("loose solve");
    assert!(loose.iterations > 0, "{loose:?}");
    assert_eq!(steps.products - made, loose.iterations, "{loose:?}");
    for (weights, what) in [(&first, "the same weights"), (&second, "other weights")] {
        let made = steps.products;
        let (known, _, cg) = steps
            .solve_pressures(&ops, &rows, weights, None, &monitor)
            .unwrap_or_else(|e| panic!("{what}, from known products: {e}"));
        // A confirming solve: one product an iteration and its answer's formed afresh; with
        // the same weights the start's are the ones handed over (with others the start may be
        // abandoned for zero pressure at the new springs' pulling points, one product more).
        if what == "the same weights" {
            assert_eq!(steps.products - made, cg.iterations + 1, "{what}: {cg:?}");
        }
        let mut fresh = new();
        fresh.warm_start(&before);
        let (reference, _, _) = fresh
            .solve_pressures(&ops, &rows, weights, None, &monitor)
            .unwrap_or_else(|e| panic!("{what}, fresh start: {e}"));
        assert!(cg.iterations > 0 && cg.residual <= 1e-10, "{what}: {cg:?}");
        let d = rel_diff(&known, &reference);
        assert!(
            d <= 1e-8,
            "{what}: known products against a fresh start: {d:e}"
        );
        before = known;
    }
}

/// The preconditioner's shear layer (the default on a continuum soil) against its springs
/// λ·diag(T): the same answer — both confirm the set at the CG tolerance 1e-10, so σ agrees to
/// about the condition number times that (1e-6 relative allowed, as for the dense route) —
/// with fewer conjugate-gradient iterations. The symbols give about 2–3 iterations a decade
/// for the layer against 7–10 for the springs (docs/METHODS.md); the penalty's warm-started
/// loose steps, which take a few iterations either way, dilute that (on the half-space lane 35
/// against 84). Here, where the quarter model lets the layer be read only above 20/L, 94
/// against 119. Paper's case at 64², quarter model.
#[test]
fn the_shear_layer_gives_the_springs_answer_in_fewer_iterations() {
    use liftoff::CgSettings;
    let problem = paper(64);
    let ops = Operators::assemble_with(&problem.model, true);
    let Method::Penalty(base) = problem.method else {
        panic!("the paper's scene is solved by the penalty");
    };
    let run = |shear_layer: bool| {
        let method = Method::Penalty(PenaltySettings {
            cg: CgSettings {
                shear_layer,
                ..base.cg
            },
            ..base
        });
        let s = liftoff::solve(&ops, &method).expect("iterative route");
        assert!(
            s.status.converged(),
            "shear layer {shear_layer}: {}",
            s.status.describe()
        );
        s
    };
    let (springs, layer) = (run(false), run(true));
    let ds = rel_diff(&layer.sigma, &springs.sigma);
    assert!(ds < 1e-6, "σ differs by {ds:e}");
    let (ns, nl) = (
        springs.info.cg_iterations.expect("CG count"),
        layer.info.cg_iterations.expect("CG count"),
    );
    assert!(nl < ns, "shear layer {nl} CG iterations, springs {ns}");
}
