//! The sparse QP forms (lifted and primal) against the dense Schur QP on the same operators:
//! Winkler scenes, nodal and Gauss constraints, full, half and quarter models, dimensionless and
//! physical units.
//!
//! What "agree to solver tolerance" means here. The dense QP, the lifted form and (by strong
//! duality) the primal form all minimise, over σ, the strictly convex f(σ) = ½σᵀSσ − hᵀσ whose
//! curvature S = T + BᵀK⁻B is at least T. An interior-point answer with duality gap γ is within
//! γ of the optimal value, so ½‖σ − σ*‖²_T ≤ ½‖σ − σ*‖²_S ≤ γ and two answers satisfy
//! ‖σ_a − σ_b‖_T ≤ √(2γ_a) + √(2γ_b): errors scale with the square root of the stopping
//! tolerance, not with the tolerance itself. That bound is asserted first, then plain relative
//! differences (see `RELATIVE`).

use crate::common;
use common::*;
use liftoff::foundation::Compliance;
use liftoff::method::QpSettings;
use liftoff::solve::linalg::PlateInverse;
use liftoff::solve::qp::clarabel_dense;
use liftoff::solve::qp::clarabel_sparse::{solve_sparse, SparseForm};
use liftoff::solve::{check_equilibrium, Status};
use liftoff::{Error, Operators, Problem, Solution};

const FORMS: [SparseForm; 2] = [SparseForm::Lifted, SparseForm::Primal];

/// Largest relative difference of σ (to max |σ|), u (to max |u|) and the gap (to max |Tσ|)
/// accepted between a sparse and the dense solution at `QpSettings::default()` (duality-gap
/// tolerances 1e-12 absolute, 1e-11 relative). The energy bound above allows up to 4e-4 on
/// these scenes (it divides by the smallest compliance); the largest difference observed is
/// 8e-6 (gap, half model), u and the gap follow σ linearly (u = K⁻(f − Bσ) + Rα) and were
/// observed within 2× of Δσ. 1e-4 leaves a decade over what was seen and is still far below
/// what a wrong multiplier sign or a missing rigid part does (order one: 0.63 in u for a
/// flipped sign of the lifted multiplier).
const RELATIVE: f64 = 1e-4;

/// The tolerances the agreement was measured at (clarabel 1e-12 absolute, 1e-11 relative; the
/// library's defaults are now 1e-14 / 1e-13, which the lifted form cannot always certify:
/// it stops at AlmostSolved, see src/solve/qp/clarabel_sparse.rs).
fn measured() -> QpSettings {
    QpSettings {
        tol_gap_abs: 1e-12,
        tol_gap_rel: 1e-11,
        tol_feas: 1e-11,
        ..QpSettings::default()
    }
}

fn ops_of(text: &str) -> Operators {
    let p = Problem::from_toml(text).unwrap_or_else(|e| panic!("scene rejected: {e}\n{text}"));
    Operators::assemble(&p.model)
}

fn diagnostic(s: &Solution, key: &str) -> f64 {
    s.info
        .qp
        .map(|q| q.named())
        .unwrap_or_default()
        .into_iter()
        .find(|(k, _)| *k == key)
        .map(|(_, v)| v)
        .unwrap_or_else(|| panic!("diagnostic {key} missing"))
}

fn compliance(ops: &Operators) -> Vec<f64> {
    match ops.t.as_ref() {
        Compliance::Diagonal(t) => t.clone(),
        Compliance::Dense(_) | Compliance::Toeplitz(_) => panic!("these tests use Winkler scenes"),
    }
}

/// Relative differences [σ, u, gap] of `b` against `a`.
fn differences(ops: &Operators, a: &Solution, b: &Solution) -> [f64; 3] {
    [
        max_abs_diff(&a.sigma, &b.sigma) / max_abs(&a.sigma),
        max_abs_diff(&a.u, &b.u) / max_abs(&a.u),
        max_abs_diff(&a.gap, &b.gap) / max_abs(&ops.t.apply(&a.sigma)),
    ]
}

/// ‖σ_a − σ_b‖_T and the bound √(2γ_a) + √(2γ_b) from the two duality gaps.
fn energy_distance(ops: &Operators, a: &Solution, b: &Solution) -> (f64, f64) {
    let t = compliance(ops);
    let d = a
        .sigma
        .iter()
        .zip(&b.sigma)
        .zip(&t)
        .map(|((x, y), t)| t * (x - y).powi(2))
        .sum::<f64>()
        .sqrt();
    let bound =
        (2.0 * diagnostic(a, "duality_gap")).sqrt() + (2.0 * diagnostic(b, "duality_gap")).sqrt();
    (d, bound)
}

/// Solve with the dense QP and both sparse forms, check every sparse answer against the dense
/// one, and return them (dense first).
fn check_against_dense(name: &str, text: &str, settings: &QpSettings, tol: f64) -> Vec<Solution> {
    let ops = ops_of(text);
    let dense = clarabel_dense::solve(&ops, settings).expect("dense QP");
    assert!(
        dense.status.converged(),
        "{name}: dense QP {}",
        dense.status.describe()
    );
    if name.contains("gauss") {
        // The scene exercises what it claims: Gauss-point constraints, not nodal ones again.
        let smin = dense.sigma.iter().cloned().fold(f64::INFINITY, f64::min);
        assert!(
            smin < -1e-4 * max_abs(&dense.sigma),
            "{name}: no negative nodal pressure (min {smin:e}): the Gauss solution is the nodal one"
        );
    }
    let mut out = vec![dense];
    for form in FORMS {
        let s = solve_sparse(&ops, settings, form)
            .unwrap_or_else(|e| panic!("{name}, {form:?} form: {e}"));
        let dense = &out[0];
        assert!(
            s.status.converged(),
            "{name}, {form:?} form: {}",
            s.status.describe()
        );
        assert_eq!(s.method.name(), "qp", "{name}, {form:?} form: method name");
        check_equilibrium(&ops, &s).unwrap_or_else(|e| panic!("{name}, {form:?} form: {e}"));
        let (d, bound) = energy_distance(&ops, dense, &s);
        let [ds, du, dg] = differences(&ops, dense, &s);
        let da = max_abs_diff(&dense.rigid, &s.rigid) / max_abs(&dense.rigid);
        eprintln!(
            "{name}, {form:?}: {} iterations (dense {}), ‖Δσ‖_T {d:.1e} (bound {bound:.1e}), Δσ {ds:.1e}, Δu {du:.1e}, Δgap {dg:.1e}, Δα {da:.1e}",
            s.iterations, dense.iterations
        );
        assert!(
            d <= bound,
            "{name}, {form:?} form: ‖σ − σ_dense‖_T = {d:e} exceeds the duality-gap bound {bound:e}"
        );
        assert!(ds <= tol, "{name}, {form:?} form: Δσ {ds:e}");
        assert!(du <= tol, "{name}, {form:?} form: Δu {du:e}");
        assert!(dg <= tol, "{name}, {form:?} form: Δgap {dg:e}");
        // The rigid amplitudes are part of u; same tolerance.
        assert!(da <= tol, "{name}, {form:?} form: Δα {da:e}");
        assert_eq!(
            s.rigid.len(),
            ops.rigid.len(),
            "{name}, {form:?}: one α per mode"
        );
        out.push(s);
    }
    out
}

fn gauss(text: String) -> String {
    text.replace("[mesh]", "[solver]\nconstraint = \"gauss\"\n[mesh]")
}

/// Winkler scenes covering the model reductions, both constraint kinds and both unit systems.
fn scenes() -> Vec<(&'static str, String)> {
    let dimless = |mu: f64, at: (f64, f64), el: [usize; 2]| {
        point_scene("winkler", 0.75e-3, 0.002857, mu, at, el, "")
    };
    // Gauss scenes where the Gauss-point solution is not the nodal one (it has negative nodal
    // pressures next to the contact edge; at Γ = 0.75e-3 the centred loads give the nodal
    // solution again).
    let gauss_at = |mu: f64, at: (f64, f64), el: [usize; 2]| {
        gauss(point_scene("winkler", 1e-2, 0.002857, mu, at, el, ""))
    };
    let slab = include_str!("../examples/slab-on-grade.toml")
        .replace("elements = [60, 40]", "elements = [12, 8]");
    vec![
        ("quarter, nodal", dimless(1.0, (0.0, 0.0), [16, 16])),
        ("quarter, gauss", gauss_at(1.0, (0.0, 0.0), [16, 16])),
        ("half, μ = 0.5, nodal", dimless(0.5, (0.4, 0.0), [16, 16])),
        ("half, μ = 0.5, gauss", gauss_at(0.5, (0.4, 0.0), [16, 16])),
        ("full, nodal", dimless(1.0, (0.4, 0.3), [16, 16])),
        ("full, gauss", gauss(dimless(1.0, (0.4, 0.3), [16, 16]))),
        // Load near a corner: most of the plate lifts, the rigid modes carry much of u.
        ("full, corner load", dimless(1.0, (0.8, 0.7), [14, 14])),
        ("physical, full", BASE.to_string()),
        ("physical slab on grade, quarter", slab),
    ]
}

#[test]
fn both_sparse_forms_match_the_dense_qp() {
    for (name, text) in scenes() {
        check_against_dense(name, &text, &measured(), RELATIVE);
    }
}

/// At tighter clarabel tolerances the duality gaps, and with them the energy bound asserted in
/// `check_against_dense`, shrink (the bound on the half model from 7.7e-6 to 3.3e-7): the
/// differences are the solver's stopping tolerance, not a difference of the problems. The
/// feasibility tolerance stays at 1e-12 because the lifted form measures its dual residual in
/// the scaled pressures σ̂ = T^(1/2)σ and cannot certify less. Largest relative difference
/// observed: 1.6e-6 (gap, half model, lifted form); 1e-5 leaves a margin of six.
#[test]
fn forms_agree_at_tighter_tolerances() {
    let tight = QpSettings {
        tol_gap_abs: 1e-14,
        tol_gap_rel: 1e-13,
        tol_feas: 1e-12,
        ..Default::default()
    };
    for (name, text) in scenes() {
        if name.contains("gauss") || name.contains("slab") {
            continue;
        }
        check_against_dense(name, &text, &tight, 1e-5);
    }
}

/// The lifted objective is the dense one plus the constant ½fᵀK⁻f (K⁻ from the plate's own
/// factorisation, not from clarabel), and the primal form's optimum is minus the lifted one
/// (strong duality). Relative tolerance 1e-9: each objective is within its duality gap
/// (≤ 1e-11 relative) of the optimum, plus the round-off of ½fᵀK⁻f.
#[test]
fn objectives_are_related_by_the_reformulations() {
    for (name, text) in scenes() {
        let ops = ops_of(&text);
        let sols = check_against_dense(name, &text, &measured(), RELATIVE);
        let kinv = PlateInverse::new(&ops).expect("plate factor");
        let kf = kinv.apply(&ops.f);
        let half_fkf = 0.5 * ops.f.iter().zip(&kf).map(|(a, b)| a * b).sum::<f64>();
        let dense = diagnostic(&sols[0], "objective");
        let lifted = diagnostic(&sols[1], "objective");
        let primal = diagnostic(&sols[2], "objective");
        // The dense objective and ½fᵀK⁻f can be much larger than their sum (6.07 and 6.09 for
        // a sum of 0.026): the tolerance is relative to the largest term.
        let scale = dense.abs().max(half_fkf).max(lifted.abs());
        assert!(
            (dense + half_fkf - lifted).abs() <= 1e-9 * scale,
            "{name}: dense {dense:e} + ½fᵀK⁻f {half_fkf:e} ≠ lifted {lifted:e}"
        );
        assert!(
            (lifted + primal).abs() <= 1e-9 * scale,
            "{name}: lifted {lifted:e} ≠ −primal {primal:e}"
        );
    }
}

/// Each form's two estimates of one quantity — primal variables against multipliers — agree:
/// the lifted gap Tσ − Bᵀu against Gᵀλ, the primal σ from s against its multiplier. This is the
/// check that the multipliers were read with the right signs; 1e-8 relative is the order of
/// the dual/primal residuals left at the default tolerances (observed ≤ 2e-9).
#[test]
fn primal_and_dual_estimates_agree_within_each_form() {
    for (name, text) in scenes() {
        let ops = ops_of(&text);
        for form in FORMS {
            let s = solve_sparse(&ops, &measured(), form).expect("sparse QP");
            // Estimates of a run that stopped early could agree as well: it must have solved.
            assert!(
                s.status.converged(),
                "{name}, {form:?} form: {}",
                s.status.describe()
            );
            let key = match form {
                SparseForm::Lifted => "gap_mismatch",
                SparseForm::Primal => "sigma_mismatch",
            };
            let m = diagnostic(&s, key);
            assert!(m <= 1e-8, "{name}, {form:?} form: {key} {m:e}");
        }
    }
}

/// A half-space operator is refused (its T is dense: nothing to gain), with a typed error.
#[test]
fn half_space_is_refused() {
    let ops = ops_of(&point_scene(
        "half-space",
        1e-3,
        0.002857,
        1.0,
        (0.0, 0.0),
        [4, 4],
        "",
    ));
    for form in FORMS {
        match solve_sparse(&ops, &QpSettings::default(), form) {
            Err(Error::Unsupported(msg)) => assert!(msg.contains("Winkler"), "{form:?}: {msg}"),
            Err(e) => panic!("{form:?}: expected Unsupported, got {e}"),
            Ok(_) => panic!("{form:?}: half-space accepted"),
        }
    }
}

/// Loads no tensionless foundation can hold are reported as infeasible by clarabel itself
/// (the library's pre-check is bypassed here): a net upward load, and a resultant outside the
/// plate (2 down at s = 0.9, 1 up at s = −0.9: resultant at s = 2.7).
#[test]
fn infeasible_loads_are_reported_as_infeasible() {
    let up = point_scene("winkler", 1e-3, 0.002857, 1.0, (0.2, 0.1), [8, 8], "")
        .replace("force = 1.0", "force = -1.0");
    let tip = format!(
        "{}[[load]]\nkind = \"point\"\nx = -0.9\ny = 0.0\nforce = -1.0\n",
        point_scene("winkler", 1e-3, 0.002857, 1.0, (0.9, 0.0), [8, 8], "")
            .replace("force = 1.0", "force = 2.0")
    );
    for (name, text) in [("upward", up), ("tipping", tip)] {
        let ops = ops_of(&text);
        for form in FORMS {
            match solve_sparse(&ops, &QpSettings::default(), form) {
                Err(Error::Infeasible(_)) => {}
                Err(e) => panic!("{name}, {form:?}: expected Infeasible, got {e}"),
                Ok(s) => panic!(
                    "{name}, {form:?}: accepted with status {}",
                    s.status.describe()
                ),
            }
        }
    }
}

/// An iteration cap too small to converge is a status on the solution, not an error and not a
/// silent answer.
#[test]
fn iteration_cap_is_a_status() {
    let ops = ops_of(&point_scene(
        "winkler",
        0.75e-3,
        0.002857,
        1.0,
        (0.0, 0.0),
        [8, 8],
        "",
    ));
    let capped = QpSettings {
        max_iter: 2,
        ..Default::default()
    };
    for form in FORMS {
        let s = solve_sparse(&ops, &capped, form).expect("ran");
        match &s.status {
            Status::SolverFailure { detail } => {
                assert!(detail.contains("MaxIterations"), "{form:?}: {detail}")
            }
            other => panic!("{form:?}: expected a solver failure, got {other:?}"),
        }
    }
}

/// `Method::qp()` (solver and form auto) takes the matrix-free active-set solver on Winkler soil
/// with nodal constraints and clarabel on the dense Schur form on a half-space, and the memory
/// budget follows: a 400 × 400 Winkler QP is estimated far below 4 GiB (measured peak 482 MiB),
/// while its dense Schur form needs more than 16 GiB.
#[test]
fn auto_form_and_memory_follow_the_foundation() {
    use liftoff::method::{Method, QpForm};
    let scene = |found: &str, n: usize| {
        let base = liftoff::examples::scene(if found == "winkler" {
            "paper-winkler"
        } else {
            "paper-halfspace"
        })
        .expect("bundled");
        let p = Problem::from_toml(base).expect("scene");
        let mut m = p.model;
        m.elements = [n, n];
        m
    };
    use liftoff::method::QpSolver;
    for (found, want) in [
        ("winkler", (QpSolver::ActiveSet, QpForm::Auto)),
        ("half-space", (QpSolver::Clarabel, QpForm::Schur)),
    ] {
        let model = scene(found, 16);
        let ops = Operators::assemble(&model);
        let s = liftoff::solve(&ops, &Method::qp()).expect("qp");
        assert!(s.status.converged(), "{found}: {}", s.status.describe());
        match &s.method {
            Method::Qp(q) => assert_eq!((q.solver, q.form), want, "{found}"),
            other => panic!("{found}: {other:?}"),
        }
    }
    let big = scene("winkler", 400);
    let gib = 1024f64.powi(3);
    liftoff::budget::check(&big, &Method::qp(), 4.0 * gib).expect("sparse QP fits in 4 GiB");
    let schur = Method::Qp(QpSettings {
        form: QpForm::Schur,
        ..QpSettings::default()
    });
    assert!(matches!(
        liftoff::budget::check(&big, &schur, 16.0 * gib),
        Err(Error::TooLarge { .. })
    ));
}

/// The cancel flag stops clarabel between its interior-point iterations (its termination
/// callback), in the dense and both sparse forms: a flag set before the solve ends it with
/// `Error::Cancelled` naming clarabel; an unset flag gives the answer of a solve without one.
#[test]
fn a_set_cancel_flag_stops_clarabel() {
    use std::sync::atomic::AtomicBool;
    let text = liftoff::examples::scene("paper-winkler").unwrap_or_default();
    let ops = ops_of(text);
    let settings = QpSettings::default();
    let set = AtomicBool::new(true);
    let unset = AtomicBool::new(false);
    let stopped = liftoff::Monitor::NONE.with_cancel(&set);
    let running = liftoff::Monitor::NONE.with_cancel(&unset);
    let cancelled = |r: liftoff::Result<Solution>, what: &str| match r {
        Err(Error::Cancelled(during)) => assert!(during.contains("clarabel"), "{what}: {during}"),
        other => panic!(
            "{what}: expected Cancelled, got {:?}",
            other.map(|s| s.status)
        ),
    };
    cancelled(
        clarabel_dense::solve_with(&ops, &settings, &stopped),
        "dense",
    );
    let plain = clarabel_dense::solve(&ops, &settings).expect("dense QP");
    let watched =
        clarabel_dense::solve_with(&ops, &settings, &running).expect("dense QP, flag unset");
    assert_eq!(plain.sigma, watched.sigma, "an unset flag changes nothing");
    for form in FORMS {
        use liftoff::solve::qp::clarabel_sparse::solve_sparse_with;
        cancelled(
            solve_sparse_with(&ops, &settings, form, &stopped),
            &format!("{form:?}"),
        );
        let s = solve_sparse_with(&ops, &settings, form, &running).expect("sparse QP, flag unset");
        assert!(s.status.converged(), "{form:?}: {}", s.status.describe());
    }
}
