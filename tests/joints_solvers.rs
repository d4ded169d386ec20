//! Both methods on jointed slabs (issue 23): a 2 × 2 system of panels joined by aggregate
//! joints (hinges: five rigid modes, not three), unbonded, on a Winkler soil and on the
//! half-space. The penalty iteration, clarabel and the matrix-free active-set QP agree; the
//! Winkler penalty (its spring backend) and clarabel's primal form use no equilibrium rows at
//! all, so their agreement with the forms that do checks the rows independently. The test with
//! teeth: the same operators with the rows cut to the three global ones give a wrong σ.
//! Then the feasibility check per cluster, and the iterative route against the dense one.

use liftoff::mesh::Dof;
use liftoff::method::{QpSolver, Route};
use liftoff::operators::{Operators, SharedCache};
use liftoff::{solve, Method, PenaltySettings, Problem, QpSettings, Solution};

/// A 6 m × 6 m × 250 mm slab cut into four panels by aggregate joints x = 0 and y = 0
/// (AGG = 1e8 N/m², about 2 kℓ on the Winkler soil), 6 kPa self-weight and 300 kN on a
/// 0.75 m square near the outer corner of the panel (2, 2): that panel presses its corner in
/// and lifts its joint edges, which pull the neighbours up by their hinges.
fn hinges(foundation: &str) -> String {
    format!(
        r#"
[plate]
length = 6.0
width = 6.0
thickness = 0.25
youngs_modulus = 30e9
poissons_ratio = 0.2
[foundation]
{foundation}
[[joint]]
x = 0.0
kind = "aggregate"
stiffness = 1e8
[[joint]]
y = 0.0
kind = "aggregate"
stiffness = 1e8
[[load]]
kind = "uniform"
pressure = 6e3
[[load]]
kind = "patch"
x = [2.0, 2.75]
y = [2.0, 2.75]
pressure = 533333.33
[mesh]
elements = [12, 12]
"#
    )
}

const WINKLER: &str = "model = \"winkler\"\nmodulus = 5e7";
const HALF_SPACE: &str = "model = \"half-space\"\nyoungs_modulus = 1e8\npoissons_ratio = 0.3";

fn operators(foundation: &str, toeplitz: bool) -> Operators {
    let p = Problem::from_toml(&hinges(foundation)).expect("scene");
    Operators::assemble_with(&p.model, toeplitz)
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |m, x| m.max(x.abs()))
}

fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).fold(0.0, |m, (x, y)| m.max((x - y).abs()))
}

/// rᵀ(f − Bσ) for each of `modes`, relative to Σ|f|.
fn residuals(ops: &Operators, modes: &[Vec<f64>], sigma: &[f64]) -> Vec<f64> {
    let bs = ops.b_times(sigma);
    let scale: f64 = ops.f.iter().map(|v| v.abs()).sum();
    modes
        .iter()
        .map(|r| {
            r.iter()
                .zip(ops.f.iter().zip(&bs))
                .map(|(ri, (f, b))| ri * (f - b))
                .sum::<f64>()
                .abs()
                / scale
        })
        .collect()
}

fn run(ops: &Operators, method: &Method) -> Solution {
    let s = solve(ops, method).unwrap_or_else(|e| panic!("{method:?}: {e}"));
    assert!(s.status.converged(), "{method:?}: {}", s.status.describe());
    s
}

fn qp(solver: QpSolver) -> Method {
    Method::Qp(QpSettings {
        solver,
        ..QpSettings::default()
    })
}

/// The same operators with the equilibrium rows cut to the three global rigid modes of the
/// whole slab (translation and two tilts — combinations of the five), K⁻ unchanged (with
/// only three fixed equations K would not even factor).
fn three_rows(ops: &Operators) -> Operators {
    let mut cut = ops.clone();
    let n = ops.n_eq();
    let (mut t, mut rx, mut ry) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    for node in 0..ops.n_sigma() {
        let (x, y) = ops.mesh.node_xy(node);
        if let Some(e) = ops.dofs.eq(node, Dof::W) {
            t[e] = 1.0;
            rx[e] = x;
            ry[e] = y;
        }
        if let Some(e) = ops.dofs.eq(node, Dof::PsiX) {
            rx[e] = 1.0;
        }
        if let Some(e) = ops.dofs.eq(node, Dof::PsiY) {
            ry[e] = 1.0;
        }
    }
    cut.rigid = vec![t, rx, ry];
    cut.rigid_clusters = vec![0; 3];
    cut.cache = SharedCache::default();
    cut
}

/// Penalty, clarabel and the active-set QP on the 2 × 2 hinge system agree, σ to 1e-6 of its
/// peak, on Winkler and on the half-space; each balances every one of the five modes; some
/// of the slab has lifted (it is a contact problem); and three rows give another σ.
#[test]
fn hinged_panels_penalty_and_both_qp_solvers_agree() {
    for foundation in [WINKLER, HALF_SPACE] {
        let ops = operators(foundation, false);
        assert_eq!(ops.rigid.len(), 5, "2 × 2 aggregate: five equilibrium rows");
        assert_eq!(ops.rigid_clusters, vec![0; 5], "one cluster");
        // ε̄ small enough that the penalty's O(ε̄) error is below 1e-6 of the peak pressure.
        let penalty = run(&ops, &Method::Penalty(PenaltySettings::fixed(1e-12)));
        let clarabel = run(&ops, &qp(QpSolver::Clarabel));
        let active = run(&ops, &qp(QpSolver::ActiveSet));
        let peak = max_abs(&active.sigma);
        for (name, s) in [("penalty", &penalty), ("clarabel", &clarabel)] {
            let d = max_diff(&s.sigma, &active.sigma);
            // clarabel stops at its 1e-8 tolerances, the penalty at O(ε̄): 1e-6 of the peak, as
            // the issue asks (observed: penalty 1e-13 / 1e-12, clarabel 8e-12 / 6e-11 on
            // Winkler / the half-space).
            assert!(
                d < 1e-6 * peak,
                "{foundation}: {name} vs active set: |Δσ| = {d:e} (peak {peak:e})"
            );
        }
        for (name, s) in [
            ("penalty", &penalty),
            ("clarabel", &clarabel),
            ("active set", &active),
        ] {
            let r = residuals(&ops, &ops.rigid, &s.sigma);
            // Equilibrium of every mode to the linear algebra's round-off.
            assert!(
                r.iter().all(|&v| v < 1e-9),
                "{foundation}: {name}: Rᵀ(f − Bσ) = {r:?}"
            );
        }
        let lifted = active.sigma.iter().filter(|&&s| s <= 0.0).count();
        assert!(lifted > 10, "{foundation}: {lifted} nodes lifted");
        // The teeth: the QP with the three global rows only. Its σ balances those three but
        // not the hinges, and is far from the answer.
        let cut = three_rows(&ops);
        let wrong = run(&cut, &qp(QpSolver::ActiveSet));
        let r3 = residuals(&ops, &cut.rigid, &wrong.sigma);
        assert!(r3.iter().all(|&v| v < 1e-9), "the three rows hold: {r3:?}");
        let r5 = residuals(&ops, &ops.rigid, &wrong.sigma);
        let worst = r5.iter().cloned().fold(0.0, f64::max);
        let d = max_diff(&wrong.sigma, &penalty.sigma);
        println!(
            "{foundation}: three rows: hinge residual {worst:.3e}, |Δσ| = {:.3e} of the peak",
            d / peak
        );
        // Observed: hinge residuals 6.6e-2 (Winkler) and 4.4e-2 (half-space) of Σ|f|, σ off by
        // 20 % and 23 % of the peak.
        assert!(worst > 1e-4, "the hinges are not balanced: {r5:?}");
        assert!(d > 1e-3 * peak, "three rows give another σ: {d:e}");
    }
}

/// The iterative route (T by FFT through the gather map of the copies, conjugate gradients
/// with the jointed coarse plate as preconditioner) gives the dense route's answer on the
/// jointed half-space: penalty with a fixed ε̄ and the active-set QP, σ to 1e-6 of its peak
/// (the CG tolerance).
#[test]
fn iterative_route_on_a_jointed_half_space_is_the_dense_route() {
    let dense = operators(HALF_SPACE, false);
    let fft = operators(HALF_SPACE, true);
    assert!(dense.t.is_dense() && !fft.t.is_dense());
    // The preconditioner's plate is the jointed coarse one (the joints x = 0, y = 0 lie on
    // the grid twice as coarse).
    let schur =
        liftoff::solve::iterative::IterativeSchur::new(&fft, liftoff::CgSettings::default())
            .expect("iterative system");
    assert_eq!(schur.preconditioner_plate(), "coarse");
    for method in [
        Method::Penalty(PenaltySettings::fixed(1e-8)),
        qp(QpSolver::ActiveSet),
    ] {
        let a = run(&dense, &method);
        let b = run(&fft, &method);
        let peak = max_abs(&a.sigma);
        let d = max_diff(&a.sigma, &b.sigma);
        // CG to its tolerance (observed 2e-10 for the penalty, 2e-14 for the QP).
        assert!(d < 1e-6 * peak, "{method:?}: |Δσ| = {d:e} (peak {peak:e})");
    }
    // And through the scene's route setting, as the command line runs it.
    let text = hinges(HALF_SPACE).replace(
        "[mesh]",
        "[solver]\nroute = \"iterative\"\nmethod = \"qp\"\n[mesh]",
    );
    let p = Problem::from_toml(&text).expect("scene");
    assert_eq!(p.route, Route::Iterative);
    let a = liftoff::analyse(&p).expect("iterative solve");
    assert!(a.solution.status.converged());
}

/// A panel cut off by free joints and loaded only upwards cannot be held down: the existing
/// typed error (E19) names the panel, before any solve.
#[test]
fn a_free_panel_loaded_only_upwards_is_infeasible_and_named() {
    let text = hinges(WINKLER)
        .replace("kind = \"aggregate\"\nstiffness = 1e8\n[[joint]]\ny = 0.0\nkind = \"aggregate\"\nstiffness = 1e8", "kind = \"free\"")
        .replace(
            "[[load]]\nkind = \"uniform\"\npressure = 6e3\n",
            "[[load]]\nkind = \"point\"\nx = 1.5\ny = 0.5\nforce = -5e4\n",
        )
        .replace("x = [2.0, 2.75]", "x = [-2.75, -2.0]");
    let p = Problem::from_toml(&text).expect("scene");
    let e = liftoff::analyse(&p).err().expect("infeasible");
    assert_eq!(e.kind(), liftoff::ErrorKind::Infeasible);
    let msg = e.to_string();
    assert!(
        msg.contains("panel (2, 1)") && msg.contains("the net load is upward"),
        "{msg}"
    );
}

/// Loads a hinge cannot carry on a tensionless soil: the right panel of a hinged pair is lifted
/// by an upward load that only its own (absent) pressure could balance about the joint; the
/// resultant of all loads lies well inside the slab, so the plain check of one plate would
/// pass. The error (E20's) names the panels of the cluster.
#[test]
fn loads_that_turn_a_hinge_are_infeasible() {
    let text = hinges(WINKLER)
        .replace(
            "[[joint]]\ny = 0.0\nkind = \"aggregate\"\nstiffness = 1e8\n",
            "",
        )
        .replace(
            "[[load]]\nkind = \"uniform\"\npressure = 6e3\n",
            "[[load]]\nkind = \"point\"\nx = 2.7\ny = 0.5\nforce = -6e4\n",
        )
        .replace("x = [2.0, 2.75]", "x = [-2.0, -1.25]");
    let p = Problem::from_toml(&text).expect("scene");
    let e = liftoff::analyse(&p).err().expect("infeasible");
    assert_eq!(e.kind(), liftoff::ErrorKind::Infeasible);
    let msg = e.to_string();
    assert!(
        msg.contains("panels (1, 1), (2, 1)") && msg.contains("turn about a joint"),
        "{msg}"
    );
}

/// The nested start of the active-set QP on a large jointed grid: the joints x = 0, y = 0 stay
/// on the lines of the grid twice as coarse, so the solve starts from the coarse jointed
/// plate's pressures (each side of a joint from its own side) and ends at the cold start's
/// answer; a joint that would fall between the coarse grid's lines leaves a cold start.
#[test]
fn nested_start_on_jointed_grids() {
    let method = qp(QpSolver::ActiveSet);
    let text = hinges(WINKLER).replace("elements = [12, 12]", "elements = [64, 64]");
    let p = Problem::from_toml(&text).expect("scene");
    let ops = Operators::assemble(&p.model);
    assert!(ops.n_sigma() >= liftoff::solve::NESTED_MIN_NODES);
    let nested = liftoff::solve::solve_nested(&p.model, &ops, &method, &liftoff::Monitor::NONE)
        .expect("nested");
    assert!(
        nested
            .info
            .notes
            .iter()
            .any(|n| n.contains("started from the pressures of the same plate on 32 × 32")),
        "{:?}",
        nested.info.notes
    );
    let cold = run(&ops, &method);
    let d = max_diff(&nested.sigma, &cold.sigma);
    // The QP's solution is unique: two runs of the active set to its KKT tolerance.
    assert!(d < 1e-9 * max_abs(&cold.sigma), "|Δσ| = {d:e}");
    // x = 3/32 · 3 m = 0.28125 m is grid line 35 of 64, not one of 32: cold start.
    let odd = text.replace(
        "x = 0.0\nkind = \"aggregate\"",
        "x = 0.28125\nkind = \"aggregate\"",
    );
    let p = Problem::from_toml(&odd).expect("scene");
    let ops = Operators::assemble(&p.model);
    let s = liftoff::solve::solve_nested(&p.model, &ops, &method, &liftoff::Monitor::NONE)
        .expect("solve");
    assert!(s.info.notes.iter().all(|n| !n.contains("started from")));
}
