//! The method studies of `liftoff::study`: the speed–accuracy tradeoff and the stability sweep,
//! on small meshes (the penalty limit ε̄ → 0 is tests/penalty_limit.rs).

use crate::common;

use liftoff::budget;
use liftoff::foundation::FoundationKind;
use liftoff::model::Model;
use liftoff::study::{self, StabilityParam, StabilityRow, TradeoffPoint};
use liftoff::{Error, Method, Problem};

const GIB: f64 = 1024.0 * 1024.0 * 1024.0;

/// The paper's square plate (Γ = 0.25e-3, Δ = 0.002857, ν = 0.3) under a central point load on
/// `elements` × `elements`, penalty method at the paper's ε̄, within `memory_limit` bytes.
fn paper_plate(foundation: FoundationKind, elements: usize, memory_limit: f64) -> Problem {
    let model = Model::builder()
        .dimensionless(foundation, 0.25e-3, 0.002857, 1.0, 0.3)
        .point_load(0.0, 0.0, 1.0)
        .elements(elements, elements)
        .build()
        .unwrap_or_else(|e| panic!("paper plate: {e}"));
    Problem {
        combinations: Vec::new(),
        model,
        method: Method::penalty(),
        route: liftoff::Route::Auto,
        memory_limit,
        warnings: Vec::new(),
        damage: None,
        ends: None,
    }
}

/// Points that may sit on a Pareto front: converged, with a finite positive error.
fn admissible(p: &TradeoffPoint) -> bool {
    p.converged && p.error.is_finite() && p.error > 0.0
}

/// The definition, point by point: an admissible point is on the front iff no other admissible
/// point is at least as fast and at least as accurate, and strictly better in one of the two.
fn non_dominated(points: &[TradeoffPoint], i: usize) -> bool {
    let p = &points[i];
    admissible(p)
        && !points.iter().enumerate().any(|(j, q)| {
            j != i
                && admissible(q)
                && q.time_s <= p.time_s
                && q.error <= p.error
                && (q.time_s < p.time_s || q.error < p.error)
        })
}

/// Checks shared by every tradeoff result over `meshes` × (QP + `penalties`).
fn check_tradeoff(name: &str, t: &study::Tradeoff, meshes: &[usize], penalties: &[f64]) {
    assert_eq!(
        t.points.len(),
        meshes.len() * (1 + penalties.len()),
        "{name}: one point per mesh and method (and ε̄)"
    );
    for (k, p) in t.points.iter().enumerate() {
        let per_mesh = 1 + penalties.len();
        assert_eq!(p.mesh, meshes[k / per_mesh], "{name}: point {k} mesh");
        match k % per_mesh {
            0 => assert!(
                p.method.name() == "qp" && p.eps.is_nan(),
                "{name}: point {k}"
            ),
            j => assert!(
                p.method.name() == "penalty" && p.eps == penalties[j - 1],
                "{name}: point {k}"
            ),
        }
        assert!(
            p.time_s.is_finite() && p.time_s > 0.0,
            "{name}: {} at {}: time {}",
            p.method,
            p.mesh,
            p.time_s
        );
        assert_eq!(
            p.converged,
            p.status.name() == "converged",
            "{name}: {} at {}",
            p.method,
            p.mesh
        );
        assert_eq!(
            p.pareto,
            non_dominated(&t.points, k),
            "{name}: {} at {} (ε̄ {:e}, {:.3e} s, error {:.3e}) Pareto flag",
            p.method,
            p.mesh,
            p.eps,
            p.time_s,
            p.error
        );
    }
    assert!(
        t.points.iter().any(|p| p.pareto),
        "{name}: the front is not empty"
    );
}

/// `tradeoff` on 4, 8 and 16 elements per side, QP reference at 32: one point per mesh and
/// method in plan order; the Pareto flags are exactly the non-dominated converged points; the QP
/// error falls by at least half per halving of h (MITC4 displacements converge at O(h²) where
/// the solution is smooth; the point load and the contact boundary lower that, not below first
/// order — measured 2.8× to 10×); a penalty too weak for the plate is reported as such and kept
/// off the front.
#[test]
fn tradeoff_points_front_and_convergence() {
    let meshes = [4, 8, 16];
    let penalties = [1e-2, 1e-5, 1e-8];
    for foundation in [FoundationKind::Winkler, FoundationKind::HalfSpace] {
        let name = foundation.name();
        let problem = paper_plate(foundation, 16, budget::default_memory_limit());
        let events = std::sync::Mutex::new(Vec::new());
        let record = |p: liftoff::Progress<'_>| {
            if let (liftoff::Progress::Case { done, total, .. }, Ok(mut v)) = (p, events.lock()) {
                v.push((done, total));
            }
        };
        let t = study::tradeoff(
            &problem,
            &meshes,
            &penalties,
            &liftoff::Monitor::NONE.with_progress(&record),
        )
        .unwrap_or_else(|e| panic!("{name}: {e}"));
        let messages = events.into_inner().unwrap_or_default();
        check_tradeoff(name, &t, &meshes, &penalties);
        assert!(
            t.reference
                .contains("32 elements per side (twice the finest mesh)"),
            "{name}: {}",
            t.reference
        );
        assert_eq!(
            messages.len(),
            1 + meshes.len() * (1 + penalties.len()),
            "{name}: one progress message per solve: {messages:?}"
        );
        // Cases counted 0, 1, … of the run's total, which is known from the start.
        for (k, &(done, total)) in messages.iter().enumerate() {
            assert_eq!(
                (done, total),
                (k, messages.len()),
                "{name}: progress event {k}"
            );
        }
        let qp: Vec<&TradeoffPoint> = t
            .points
            .iter()
            .filter(|p| p.method.name() == "qp")
            .collect();
        for p in &qp {
            assert!(p.converged, "{name}: QP at {}: {}", p.mesh, p.status);
        }
        for w in qp.windows(2) {
            assert!(
                w[1].error <= 0.5 * w[0].error,
                "{name}: QP error {:.3e} at {} → {:.3e} at {}",
                w[0].error,
                w[0].mesh,
                w[1].error,
                w[1].mesh
            );
        }
        // ε̄ = 1e-2 is a hundred times the penalty this plate needs: its lifted points keep
        // more than 0.1 % of the load (the tension tolerance), at every mesh.
        for p in t.points.iter().filter(|p| p.eps == 1e-2) {
            assert_eq!(
                p.status.name(),
                "penalty-too-weak",
                "{name}: ε̄ = 1e-2 at {}",
                p.mesh
            );
            assert!(!p.pareto);
        }
    }
}

/// When the QP at twice the finest mesh does not fit in memory, the reference falls back to the
/// QP at the finest mesh and says so; the finest QP point then compares the reference with
/// itself (error 0) and cannot be on the front.
#[test]
fn tradeoff_reference_falls_back_to_the_finest_mesh() {
    let meshes = [4, 8];
    let need = |n: usize| {
        let p = paper_plate(FoundationKind::Winkler, n, 0.0);
        budget::estimate_bytes(
            &p.model.plan_mesh().0,
            FoundationKind::Winkler,
            p.model.constraint,
            &Method::qp(),
        )
    };
    // Between what the QP needs at 8 and at 16 elements per side.
    let limit = (need(8) * need(16)).sqrt();
    assert!(need(8) < limit && limit < need(16));
    let problem = paper_plate(FoundationKind::Winkler, 8, limit);
    let t = study::tradeoff(&problem, &meshes, &[1e-8], &liftoff::Monitor::NONE).expect("tradeoff");
    assert!(
        t.reference.contains("8 elements per side (the finest mesh"),
        "{}",
        t.reference
    );
    check_tradeoff("fallback", &t, &meshes, &[1e-8]);
    let finest_qp = &t.points[2];
    assert_eq!((finest_qp.method.name(), finest_qp.mesh), ("qp", 8));
    // The same model solved twice by the same deterministic method: round-off at most.
    assert!(finest_qp.error <= 1e-12, "{:e}", finest_qp.error);

    let none = study::tradeoff(&problem, &[], &[1e-8], &liftoff::Monitor::NONE);
    assert!(
        matches!(none, Err(Error::Invalid { ref field, .. }) if field == "meshes"),
        "no meshes: {:?}",
        none.map(|t| t.points.len())
    );
}

fn rows_of<'a>(
    rows: &'a [StabilityRow],
    foundation: &str,
    sweep: StabilityParam,
    method: &str,
) -> Vec<&'a StabilityRow> {
    rows.iter()
        .filter(|r| {
            r.foundation.name() == foundation && r.sweep == sweep && r.method.name() == method
        })
        .collect()
}

/// The stability sweep over the paper's plate on both foundations, on an 8 × 8 base mesh with a
/// 64 MiB memory limit (so the mesh sweep's dense cases beyond 32 per side are refused rather
/// than solved: 2.5 s instead of minutes).
///
/// * One row per planned case, in plan order, with a known outcome kind; converged rows are in
///   equilibrium, error rows carry no numbers.
/// * Mesh: too-large exactly where the budget says so, and from there on for every finer mesh.
/// * Position: a load at (s, s) with s < 1 is solved by the QP. At the corner (s = 1) the
///   answer depends on the coupling: lumped Winkler springs put each nodal pressure at its node,
///   so the QP rests the plate on the corner node alone (one element of 64 in contact), while
///   the penalty springs holding the lifted plate down carry more than 0.1 % of the load
///   (penalty-too-weak). On the half-space a nodal pressure acts at the centroid of its shape
///   function, at most 1 − h/3 = 0.9167 from the centre: the corner load is infeasible for
///   both methods.
/// * Γ: the QP converges at every Γ, its contact region grows with Γ (paper §4), and as the
///   plate becomes rigid against the foundation (Winkler Γ ≥ 1e4) the pressure under a central
///   load tends to the uniform σ = 1 (σ = μL²r/P, r = 4P / (4μL²)), within O(1/Γ).
/// * ε̄: too weak for the largest ε̄, converged from some ε̄ down to 1e-14, and the tension left
///   at the lifted points falls like ε̄.
#[test]
fn stability_sweep_rows_and_outcomes() {
    let limit = GIB / 16.0;
    let bases = [
        paper_plate(FoundationKind::Winkler, 8, limit),
        paper_plate(FoundationKind::HalfSpace, 8, limit),
    ];
    let plan = study::stability_plan(&bases);
    // Winkler: Γ 12 × 2 methods on each route (gamma, gamma-iterative) + ε̄ 13 + position
    // 6 × 2 + μ 5 × 2 + mesh 7 × 2 = 97; half-space: one mesh value fewer (512 is beyond
    // memory for both methods) = 95.
    assert_eq!(plan.len(), 97 + 95);
    // The half-space's Γ sweep on the iterative route (24 runs at 64², T by FFT: most of this
    // test's time) is not run here: tests/stability_gamma.rs runs that row on every continuum
    // soil and holds each run to the invariants below (converged, in equilibrium, contact in
    // (0, 1], at least one iteration, the QP's pressures non-negative).
    let plan: Vec<_> = plan
        .into_iter()
        .filter(|c| {
            c.param != StabilityParam::GammaIterative || c.base.model.groups.foundation().is_local()
        })
        .collect();
    assert_eq!(plan.len(), 97 + 95 - 24);
    let rows: Vec<StabilityRow> = plan.iter().map(study::stability_run).collect();
    for (case, r) in plan.iter().zip(&rows) {
        let what = format!(
            "{} {} = {:e} ({})",
            r.foundation,
            r.sweep.name(),
            r.value,
            r.method
        );
        assert_eq!(
            (r.sweep, r.method, r.value, r.foundation),
            (
                case.param,
                case.method,
                case.value,
                case.base.model.groups.foundation()
            ),
            "row in plan order"
        );
        assert!(
            common::OUTCOMES.contains(&r.outcome.name()),
            "{what}: outcome {}",
            r.outcome
        );
        assert!(r.time_s.is_finite() && r.time_s >= 0.0, "{what}");
        assert!(!r.detail.is_empty(), "{what}: detail");
        if r.outcome.name() == "converged" {
            // (A point load on a Winkler corner is the plate balanced on one node that
            // `converged_row_fault` lets take no iteration.)
            if let Some(fault) = common::converged_row_fault(r) {
                panic!("{what}: {fault}");
            }
        }
        if ["infeasible", "too-large", "numerical"].contains(&r.outcome.name()) {
            assert!(
                r.equilibrium.is_nan() && r.contact_fraction.is_nan() && r.iterations == 0,
                "{what}: an error row carries no numbers"
            );
        }
        if r.outcome.name() == "too-large" {
            assert_eq!(r.sweep, StabilityParam::Mesh, "{what}: only meshes grow");
        }
    }

    for (fd, f) in [
        ("winkler", FoundationKind::Winkler),
        ("half-space", FoundationKind::HalfSpace),
    ] {
        for m in ["penalty", "qp"] {
            // Mesh: refused exactly where the estimate exceeds the limit.
            let mesh = rows_of(&rows, fd, StabilityParam::Mesh, m);
            let method = if m == "qp" {
                Method::qp()
            } else {
                Method::penalty()
            };
            let mut refused = false;
            for r in &mesh {
                let n = r.value as usize;
                let model = paper_plate(f, n, limit).model;
                let need =
                    budget::estimate_bytes(&model.plan_mesh().0, f, model.constraint, &method);
                assert_eq!(
                    r.outcome.name() == "too-large",
                    need > limit,
                    "{fd} {m} mesh {n}: {}",
                    r.outcome
                );
                assert!(
                    !refused || r.outcome.name() == "too-large",
                    "{fd} {m}: a finer mesh than a refused one ran"
                );
                refused |= r.outcome.name() == "too-large";
                if n <= 32 {
                    assert_eq!(
                        r.outcome.name(),
                        "converged",
                        "{fd} {m} mesh {n}: {}",
                        r.detail
                    );
                }
            }
            assert!(
                refused,
                "{fd} {m}: the 64 MiB limit refuses the largest meshes"
            );

            // Position.
            for r in rows_of(&rows, fd, StabilityParam::Position, m) {
                let what = format!("{fd} {m} at s = {}", r.value);
                match (r.value < 1.0, fd, m) {
                    (true, _, "qp") => {
                        assert_eq!(r.outcome.name(), "converged", "{what}: {}", r.detail)
                    }
                    (true, _, _) => assert!(
                        ["converged", "penalty-too-weak"].contains(&r.outcome.name()),
                        "{what}: {}",
                        r.detail
                    ),
                    (false, "winkler", "qp") => {
                        assert_eq!(r.outcome.name(), "converged", "{what}: {}", r.detail);
                        assert!(
                            r.contact_fraction <= 1.0 / 64.0 + 1e-12,
                            "{what}: contact {}",
                            r.contact_fraction
                        );
                    }
                    (false, "winkler", _) => {
                        // At the paper's ε̄ = 1e-5 the springs hold 1.1 % of the load in
                        // tension (penalty-too-weak); the default automatic ε̄ continues to the
                        // smaller ε̄ that suggests (≈ 9e-9) and settles with the load carried at
                        // the corner, like the QP. The plate balanced on one node can still
                        // rotate about it, so the two solutions need not coincide away from the
                        // corner; both keep contact within the 2 × 2 corner elements.
                        assert_eq!(r.outcome.name(), "converged", "{what}: {}", r.detail);
                        assert!(
                            r.contact_fraction <= 4.0 / 64.0 + 1e-12,
                            "{what}: contact {}",
                            r.contact_fraction
                        );
                    }
                    (false, _, _) => {
                        assert_eq!(r.outcome.name(), "infeasible", "{what}: {}", r.detail);
                        let reach = 1.0 - (2.0 / 8.0) / 3.0;
                        assert!(
                            r.detail
                                .contains(&format!("outside [{:.4}, {reach:.4}]", -reach)),
                            "{what}: names the reachable range ±{reach:.4}: {}",
                            r.detail
                        );
                    }
                }
            }

            // μ: the QP solves every aspect ratio.
            if m == "qp" {
                for r in rows_of(&rows, fd, StabilityParam::Mu, m) {
                    assert_eq!(
                        r.outcome.name(),
                        "converged",
                        "{fd} qp μ = {}: {}",
                        r.value,
                        r.detail
                    );
                }
            }
        }

        // Γ, QP: always converged, contact growing with Γ, rigid limit on Winkler.
        let gamma = rows_of(&rows, fd, StabilityParam::Gamma, "qp");
        assert_eq!(gamma.len(), 12);
        for r in &gamma {
            assert_eq!(
                r.outcome.name(),
                "converged",
                "{fd} qp Γ = {:e}: {}",
                r.value,
                r.detail
            );
        }
        for w in gamma.windows(2) {
            // At the soft end (Γ ≤ 1e-10, nearly membranes) the contact plateaus at the loaded
            // area and the boundary, located inside the elements from the pressures, moves only
            // by the QP's tolerance (3e-6 of the fraction measured between Γ = 1e-12 and 1e-10);
            // 1e-4 of it allows that and no real shrink (the paper's growth is of order one).
            assert!(
                w[1].contact_fraction >= w[0].contact_fraction * (1.0 - 1e-4),
                "{fd}: contact {} at Γ = {:e} shrinks to {} at Γ = {:e}",
                w[0].contact_fraction,
                w[0].value,
                w[1].contact_fraction,
                w[1].value
            );
        }
        if f == FoundationKind::Winkler {
            for r in gamma.iter().filter(|r| r.value >= 1e4) {
                // σ − 1 = O(1/Γ): 1e-4 at Γ = 1e4.
                assert!(
                    (r.min_pressure - 1.0).abs() <= 1e-3,
                    "Winkler Γ = {:e}: min σ {} vs the rigid plate's uniform 1",
                    r.value,
                    r.min_pressure
                );
            }
        }

        // ε̄: too weak, then converged for every smaller ε̄, tension ∝ ε̄.
        let eps = rows_of(&rows, fd, StabilityParam::Penalty, "penalty");
        assert_eq!(eps.len(), 13);
        let first = eps
            .iter()
            .position(|r| r.outcome.name() == "converged")
            .unwrap_or_else(|| panic!("{fd}: the penalty converges at some ε̄"));
        assert!(
            first > 0 && eps[0].outcome.name() == "penalty-too-weak",
            "{fd}: ε̄ = 1e-2 is too weak"
        );
        let smallest = eps[eps.len() - 1];
        for r in &eps[first..] {
            assert_eq!(
                r.outcome.name(),
                "converged",
                "{fd}: ε̄ = {:e} after convergence at larger ε̄",
                r.value
            );
            // min σ = −ε̄ g / Γ at the lifted point with the largest gap, the gap tending to its
            // unilateral limit: min σ / ε̄ constant to O(ε̄) (measured within 2.5 %).
            let (a, b) = (
                r.min_pressure / r.value,
                smallest.min_pressure / smallest.value,
            );
            assert!(
                a < 0.0 && (a / b - 1.0).abs() < 0.05,
                "{fd}: min σ / ε̄ = {a:.3} at ε̄ = {:e}, {b:.3} at 1e-14",
                r.value
            );
        }
    }
}
