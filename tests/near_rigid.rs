//! A nearly rigid plate on soft springs (a base plate on grout, a stiff mat on soft clay):
//! Γ_w from 1e4 to 1e12, where the plain factorisation of K + springs lost the reaction to
//! round-off (1e-6 at Γ_w = 1e6, 1e-2 at 1e10) and the penalty was refused. The rigid-body
//! part is now split off and solved exactly (src/solve/rigid_split.rs).

use liftoff::model::Load;

use crate::common;

fn scene(gamma: f64, s: f64, method: &str) -> String {
    common::point_scene(
        "winkler",
        gamma,
        0.002857,
        1.0,
        (s, 0.0),
        [24, 24],
        &format!("[solver]\nmethod = \"{method}\""),
    )
}

/// The solve converged and its reaction balances the load to `tol`.
fn assert_balanced(a: &liftoff::Analysis, what: &str, tol: f64) {
    assert!(a.summary.converged, "{what}: {}", a.summary.status);
    assert!(
        a.summary.resultant.relative_error < tol,
        "{what}: reaction misses the load by {:.1e}",
        a.summary.resultant.relative_error
    );
}

/// In full contact (the load inside the kern, e = 0.2 L < L/3) a rigid plate on springs
/// presses them linearly: σ(s) = 1 + c s in the paper's units, mean 1 and c from the moment of
/// the load, 4e = c Σ a_j s_j² over the lumped springs (the trapezoidal rule's Σ a_j s_j², which
/// is 4/3 + O(h²): c = 3e in the continuum). The lumped springs see the nodal deflections, which
/// a rigid plate makes exactly linear, so the nodes carry that law up to the plate's own bending
/// under the point load, which falls as 1/Γ_w: within 50/Γ_w. Every solve balances the load to
/// 1e-12.
#[test]
fn a_rigid_plate_in_full_contact_presses_the_springs_linearly() {
    for gamma in [1e4, 1e6, 1e8, 1e10, 1e12] {
        for method in ["penalty", "qp"] {
            let a = common::run(&scene(gamma, 0.2, method));
            let what = format!("Γ_w = {gamma:e}, {method}");
            assert_balanced(&a, &what, 1e-12);
            let f = &a.report.field;
            // Lumped areas of the 24 × 24 grid on [−1, 1]²: h² at interior nodes, halved on
            // an edge, quartered at a corner.
            let h = 2.0 / 24.0;
            let weight = |i: usize| if i == 0 || i == 24 { 0.5 } else { 1.0 };
            let mut second = 0.0;
            for j in 0..=24 {
                for i in 0..=24 {
                    let s = -1.0 + h * i as f64;
                    second += h * h * weight(i) * weight(j) * s * s;
                }
            }
            let c = 4.0 * 0.2 / second;
            let worst =
                f.s.iter()
                    .zip(&f.sigma)
                    .map(|(&s, &sigma)| (sigma - (1.0 + c * s)).abs())
                    .fold(0.0, f64::max);
            let tol = 50.0 / gamma + 1e-9;
            assert!(worst < tol, "{what}: σ off the linear law by {worst:.2e}");
        }
    }
}

/// Beyond the kern (e = 0.5 L) the rigid plate lifts off over a third of its length; the penalty
/// and the QP agree on the pressures to the penalty's O(ε̄) error (ε̄ = 1e-5 of the springs'
/// compliance: 1e-4 of the peak), and balance the load to 1e-12.
#[test]
fn a_rigid_plate_tipping_off_its_springs_penalty_and_qp_agree() {
    for gamma in [1e6, 1e10] {
        let p = common::run(&scene(gamma, 0.5, "penalty"));
        let q = common::run(&scene(gamma, 0.5, "qp"));
        assert!(
            p.summary.converged && q.summary.converged,
            "Γ_w = {gamma:e}"
        );
        assert!(
            p.summary.resultant.relative_error < 1e-12,
            "Γ_w = {gamma:e}: penalty equilibrium"
        );
        let peak = common::max_abs(&q.report.field.sigma);
        let d = common::max_abs_diff(&p.report.field.sigma, &q.report.field.sigma) / peak;
        assert!(
            d < 1e-4,
            "Γ_w = {gamma:e}: penalty against QP, max |Δσ| / peak {d:.1e}"
        );
        assert!(
            (0.2..0.45).contains(&(1.0 - p.summary.contact_fraction)),
            "Γ_w = {gamma:e}: lifted share {}",
            1.0 - p.summary.contact_fraction
        );
    }
    // The load itself, as the scene gives it: a point at (0.5, 0).
    let m = liftoff::Problem::from_toml(&scene(1e6, 0.5, "penalty"))
        .expect("scene")
        .model;
    assert!(matches!(m.loads[0], Load::Point { x, .. } if (x - 0.5).abs() < 1e-12));
}

/// The split is an exact rewriting of (K + S) u = f, not an approximation for small springs:
/// on the paper's plate at Γ_w = 1 (springs far from small, where the plain factorisation of
/// K + S is accurate) it gives the bonded solve's u to 1e-9 of its largest entry (two
/// factorisations of well-conditioned systems: round-off, with a margin). A split that got M =
/// K_ff + S_f wrong would miss by the springs' share of M, here about 1e-2.
#[test]
fn the_split_solves_ordinary_springs_exactly_too() {
    use liftoff::solve::linalg::lumped_coupling;
    use liftoff::solve::rigid_split::RigidSplit;
    let p = liftoff::Problem::from_toml(&scene(1.0, 0.2, "penalty")).expect("scene");
    let ops = liftoff::Operators::assemble(&p.model);
    let bonded = liftoff::solve(&ops, &liftoff::Method::Bonded).expect("bonded");
    let t = ops.t.diagonal();
    let springs: Vec<(usize, f64)> = lumped_coupling(&ops)
        .expect("coupling")
        .iter()
        .zip(&t)
        .map(|(&(eq, b), &tj)| (eq, b * b / tj))
        .collect();
    let u = RigidSplit::new(&ops)
        .expect("split")
        .solve(&ops, &springs, &ops.f)
        .expect("split solve");
    let scale = common::max_abs(&bonded.u);
    let diff = common::max_abs_diff(&u, &bonded.u);
    assert!(
        diff <= 1e-9 * scale,
        "u differs by {:.1e} of its peak",
        diff / scale
    );
}

/// A point load on the corner of a Winkler plate (`benches/scenes/corner-winkler.toml`): the
/// plate rests on its corner node alone, which carries the whole load, so the corner sinks by
/// V = Γ σ_c with σ_c = 4 / (h/2)² in the paper's units (the load 4 over the corner node's
/// lumped area, h = 2/n): V = 4Γn² — 10 at 100², 40 at 200². Every rotation about the corner is
/// held by the lifted points' penalty springs alone. Before, the automatic ε̄ stopped where the
/// tension was 0.1 % of the load, but that tension's moment, with arms of ~n elements, moved
/// load onto the corner's neighbours (V 1 % low at 100²), and at 200² the plain factorisation
/// lost the reaction to round-off (9.6e-6, refused). The tension's moment is now a criterion,
/// bounding the shift of the contact's resultant at 1e-3 of the contact's size (one element
/// here), and the steps split off the rigid modes the soft springs alone hold: V within 1e-3 of
/// the closed form, the load balanced to 1e-9.
#[test]
fn a_plate_balanced_on_its_corner_node_sinks_under_the_load_alone() {
    let gamma = 0.25e-3;
    for n in [100, 200] {
        let text = common::point_scene("winkler", gamma, 0.002857, 1.0, (1.0, 1.0), [n, n], "");
        let a = common::run(&text);
        let what = format!("{n}²");
        assert_balanced(&a, &what, 1e-9);
        let exact = 4.0 * gamma * (n * n) as f64;
        let v = a.summary.V_max;
        assert!(
            (v - exact).abs() <= 1e-3 * exact,
            "{what}: V_max {v} against {exact}"
        );
    }
}
