//! The nested start (`[solver] start = "nested"`, the default): on a large grid the penalty
//! iteration and the active-set QP start from the same plate solved on a grid twice as coarse.
//! The answer is the cold start's — the penalised problem is strictly convex and the QP's
//! solution unique. (That the fine grid takes fewer steps is measured in BENCHMARKS.md.)

use liftoff::method::Start;
use liftoff::scene::Overrides;
use liftoff::{Monitor, Outcome, Source};

use crate::common;

fn solve(source: &Source<'_>, extra: Overrides) -> liftoff::Analysis {
    let p = liftoff::load(source, &extra).expect("scene");
    match liftoff::run(&p, &Monitor::NONE).expect("solve") {
        Outcome::Single(a) => *a,
        Outcome::Combinations(_) => panic!("one load set"),
    }
}

/// The paper's half-space case at 128 × 128 (a quarter model of 4225 pressure nodes, the
/// iterative route) and the slab-on-grade bay on Winkler springs at 180 × 120 (5551 nodes),
/// by the penalty and by the QP: nested and cold starts give the same pressures — to the
/// iterative route's conjugate-gradient tolerance (1e-10 of the right-hand side: σ to ~1e-9
/// of its peak) on the half-space, to round-off of the direct solves on Winkler — the same
/// contact set.
#[test]
fn nested_and_cold_starts_give_the_same_answer() {
    for (name, mesh, tol) in [
        ("paper-halfspace", [128, 128], 1e-8),
        ("slab-on-grade", [180, 120], 1e-10),
    ] {
        for method in [
            liftoff::method::MethodKind::Penalty,
            liftoff::method::MethodKind::Qp,
        ] {
            let with = |start| Overrides {
                mesh: Some([mesh[0] as i64, mesh[1] as i64]),
                method: Some(method),
                start: Some(start),
                ..Overrides::default()
            };
            let nested = solve(&Source::Example(name), with(Start::Nested));
            let cold = solve(&Source::Example(name), with(Start::Cold));
            let what = format!("{name} {method} at {mesh:?}");
            assert!(
                nested.summary.converged && cold.summary.converged,
                "{what}: both converged"
            );
            assert!(
                nested
                    .summary
                    .notes
                    .iter()
                    .any(|n| n.contains("started from")),
                "{what}: the nested start ran: {:?}",
                nested.summary.notes
            );
            let peak = common::max_abs(&cold.solution.sigma);
            let d = common::max_abs_diff(&nested.solution.sigma, &cold.solution.sigma) / peak;
            assert!(d < tol, "{what}: max |Δσ| / peak {d:.1e}");
            assert_eq!(
                nested.report.field.contact, cold.report.field.contact,
                "{what}: the same contact set"
            );
            // How many fine steps the nested start saves is a matter of tuning, not of
            // correctness: BENCHMARKS.md records it (issue 26's target of at most 5 penalty
            // steps on the fine grid, met at 128² to 1024²), no test asserts it.
        }
    }
}
