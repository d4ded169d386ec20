//! The penalty solution converges to the QP solution at first order in ε̄ (paper §3, DESIGN §3).

use liftoff::model::ConstraintPoints;
use liftoff::study::{eps_sweep, log_space};
use liftoff::Problem;

/// On a Winkler and a half-space scene and for both constraint kinds, the relative L2 error of
/// σ against the QP on the same operators falls with a fitted log–log slope within 0.1 of 1 over
/// at least four decades of ε̄. The fit uses the sweep's points above 30× its error floor (where
/// round-off and the QP's own 1e-11 tolerance take over).
#[test]
fn penalty_error_is_first_order_in_epsilon() {
    for name in ["paper-winkler", "paper-halfspace"] {
        let text = liftoff::examples::scene(name).unwrap_or_default();
        let p = Problem::from_toml(text).expect("bundled scene");
        let eps = log_space(1e-2, 1e-9, 15);
        let sweep = eps_sweep(
            &p,
            &eps,
            &[ConstraintPoints::Nodal, ConstraintPoints::Gauss],
            [1e-9, 1e-2],
            &liftoff::Monitor::NONE,
        )
        .expect("sweep");
        for (kind, slope, range) in &sweep.slopes {
            let slope = slope.unwrap_or(f64::NAN);
            assert!(
                (slope - 1.0).abs() < 0.1,
                "{name} ({kind}): fitted slope {slope}"
            );
            assert!(
                range[1] / range[0] > 0.99e4,
                "{name} ({kind}): the fit must span four decades, got {range:?}"
            );
        }
        for r in sweep.rows.iter().filter(|r| r.eps <= 1e-5) {
            assert!(
                r.converged,
                "{name} {} ε̄ = {:e}: {}",
                r.constraint, r.eps, r.status
            );
            // The error is O(ε̄) with a moderate constant: bounded by 100 ε̄ on these scenes.
            assert!(
                r.rel_l2_sigma < 100.0 * r.eps,
                "{name} {} ε̄ = {:e}: error {:e}",
                r.constraint,
                r.eps,
                r.rel_l2_sigma
            );
        }
    }
}
