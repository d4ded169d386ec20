//! Property tests over random scenes. Every test draws its cases from a fixed seed, so a failure
//! is reproducible and a pass means the same thing on every run; case counts are bounded so the
//! suite stays fast.

use std::cell::Cell;

use liftoff::foundation::layer::Base;
use liftoff::foundation::{nodal_areas, FoundationKind};
use liftoff::model::{Model, SymmetryMode};
use liftoff::solve::penalty::{TENSION_FORCE_TOLERANCE, TENSION_TOLERANCE};
use liftoff::{analyse, Analysis, Error, Method, Operators, PenaltySettings, Problem, QpSettings};
use liftoff::{Solution, Status};
use proptest::prelude::*;
use proptest::test_runner::{RngSeed, TestRunner};

/// Seed of every random test in this file.
const SEED: u64 = 20_240_611;

fn config(cases: u32) -> ProptestConfig {
    ProptestConfig {
        cases,
        failure_persistence: None,
        rng_seed: RngSeed::Fixed(SEED),
        ..ProptestConfig::default()
    }
}

/// A soil with its shape: the Pasternak decay length λ/L, the layer's depth h/L, ν_s and base.
#[derive(Debug, Clone, Copy)]
enum Soil {
    Winkler,
    HalfSpace,
    Pasternak(f64),
    Layer(f64, f64, Base),
    /// λ/L of its shear layer and Γ_c/Γ_w of its upper springs.
    Kerr(f64, f64),
}

#[derive(Debug, Clone)]
struct RandomScene {
    soil: Soil,
    gamma: f64,
    mu: f64,
    n: usize,
    /// Point loads (s, t, relative force).
    loads: Vec<(f64, f64, f64)>,
    /// Relative uniform pressure (0: none).
    uniform: f64,
}

impl RandomScene {
    /// The whole-plate model (no symmetry reduction), loads mirrored about s = 0 if asked.
    fn model(&self, mirror_s: bool) -> Model {
        let kind = match self.soil {
            Soil::Winkler => FoundationKind::Winkler,
            Soil::HalfSpace => FoundationKind::HalfSpace,
            Soil::Pasternak(_) => FoundationKind::Pasternak,
            Soil::Layer(..) => FoundationKind::ElasticLayer,
            Soil::Kerr(..) => FoundationKind::Kerr,
        };
        let mut b = Model::builder()
            .dimensionless(kind, self.gamma, 0.002857, self.mu, 0.3)
            .elements(self.n, self.n)
            .symmetry(SymmetryMode::None);
        match self.soil {
            // λ² = Γ_g μ Γ_w (model::Groups::decay_length).
            Soil::Pasternak(lambda) => b = b.shear(lambda * lambda / (self.mu * self.gamma)),
            Soil::Layer(h, nu, base) => b = b.layer(h, nu).base(base),
            Soil::Kerr(lambda, upper) => {
                b = b
                    .soil_key("shear", lambda * lambda / (self.mu * self.gamma))
                    .soil_key("upper", upper * self.gamma)
            }
            Soil::Winkler | Soil::HalfSpace => {}
        }
        for &(s, t, f) in &self.loads {
            b = b.point_load(if mirror_s { -s } else { s }, t, f);
        }
        if self.uniform > 0.0 {
            b = b.uniform_load(self.uniform);
        }
        b.build()
            .unwrap_or_else(|e| panic!("random scene rejected: {e}\n{self:?}"))
    }

    fn problem(&self, mirror_s: bool, method: Method) -> Problem {
        Problem {
            combinations: Vec::new(),
            model: self.model(mirror_s),
            method,
            route: liftoff::Route::Auto,
            memory_limit: liftoff::budget::default_memory_limit(),
            warnings: Vec::new(),
            damage: None,
            ends: None,
        }
    }
}

/// Every soil: Winkler, the half-space, Pasternak (λ from 0.05 to 0.5 L) and the elastic layer
/// on a rough or a smooth base (h/L from 0.1 to 3, ν_s from 0 to 0.45), Kerr (λ from 0.05 to
/// 0.5 L, upper springs 0.1 to 10 times as compliant as the lower ones).
fn soils() -> impl Strategy<Value = Soil> {
    prop_oneof![
        Just(Soil::Winkler),
        Just(Soil::HalfSpace),
        (0.05f64..0.5).prop_map(Soil::Pasternak),
        (-1.0f64..0.5, 0.0f64..0.45).prop_map(|(lh, nu)| Soil::Layer(
            10f64.powf(lh),
            nu,
            Base::Rough
        )),
        (-1.0f64..0.5, 0.0f64..0.45).prop_map(|(lh, nu)| Soil::Layer(
            10f64.powf(lh),
            nu,
            Base::Smooth
        )),
        (0.05f64..0.5, 0.1f64..10.0).prop_map(|(lambda, upper)| Soil::Kerr(lambda, upper)),
    ]
}

fn scenes() -> impl Strategy<Value = RandomScene> {
    (
        soils(),
        -4.0f64..-1.0,
        0.5f64..1.0,
        prop_oneof![Just(4usize), Just(6), Just(8)],
        prop::collection::vec((-0.6f64..0.6, -0.6f64..0.6, 0.5f64..2.0), 1..4),
        prop_oneof![Just(0.0), 0.05f64..0.5],
    )
        .prop_map(|(soil, lg, mu, n, loads, uniform)| RandomScene {
            soil,
            gamma: 10f64.powf(lg),
            mu,
            n,
            loads,
            uniform,
        })
}

/// The paper's penalty iteration at a fixed ε̄ (the property tests study ε̄ itself).
fn penalty(epsilon: f64) -> Method {
    Method::Penalty(PenaltySettings::fixed(epsilon))
}

fn solve(sc: &RandomScene, mirror_s: bool, method: Method) -> Result<Analysis, TestCaseError> {
    analyse(&sc.problem(mirror_s, method.clone()))
        .map_err(|e| TestCaseError::fail(format!("{}: {e}", method.name())))
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0_f64, |m, x| m.max(x.abs()))
}

fn max_abs_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

proptest! {
    #![proptest_config(config(24))]

    /// Equilibrium in every solve: the reaction balances the load to round-off.
    #[test]
    fn every_solve_is_in_equilibrium(sc in scenes()) {
        for method in [Method::Bonded, Method::qp()] {
            let name = method.name();
            let a = solve(&sc, false, method)?;
            // Round-off bound: the plate's κ_s/K contrast costs a few digits (tests/bonded.rs).
            prop_assert!(a.summary.resultant.relative_error < 1e-8, "{name}: {:e}", a.summary.resultant.relative_error);
        }
    }

    /// Mirroring the loads about x = 0 mirrors V and σ (whole-plate model, no symmetry used;
    /// penalty method, whose factorisations are exact to round-off — the QP's interior-point
    /// tolerance would blur the comparison at 1e-7), and unbonded QP pressures are never
    /// tensile beyond the solver tolerance.
    #[test]
    fn mirrored_loads_give_mirrored_fields_and_no_tension(sc in scenes()) {
        let a = solve(&sc, false, penalty(1e-8))?;
        let b = solve(&sc, true, penalty(1e-8))?;
        // The mirrored problem is the same discrete problem: same outcome.
        prop_assert_eq!(a.solution.status.kind(), b.solution.status.kind());
        let (fa, fb) = (&a.report.field, &b.report.field);
        let nx = fa.nx;
        let vmax = max_abs(&fa.v);
        let smax = max_abs(&fa.sigma);
        for j in 0..=fa.ny {
            for i in 0..=nx {
                let k = i + j * (nx + 1);
                let m = (nx - i) + j * (nx + 1);
                // Same discrete problem mirrored: round-off of two factorisations only, times
                // the condition of a system whose penalised rows carry springs 1/ε̄ = 1e8 times
                // the soil's: 1e-16 · 1e8 ≈ 1e-8 at lifted points (3e-9 of V_max measured on a
                // Pasternak plate lifting its corners). 1e-7 still catches any real asymmetry
                // (a wrong mirror image in T is off by 1e-3 and more).
                prop_assert!((fa.v[k] - fb.v[m]).abs() <= 1e-7 * vmax, "V at node ({i}, {j}): {:e} vs {:e}", fa.v[k], fb.v[m]);
                prop_assert!((fa.sigma[k] - fb.sigma[m]).abs() <= 1e-7 * smax, "σ at node ({i}, {j})");
            }
        }
        let q = solve(&sc, false, Method::qp())?;
        prop_assert!(q.solution.status.converged(), "QP: {}", q.solution.status.describe());
        let qs = &q.report.field.sigma;
        let min = qs.iter().cloned().fold(f64::INFINITY, f64::min);
        prop_assert!(min >= -1e-8 * max_abs(qs), "QP tension {min:e}");
    }
}

/// The QP reference of `penalty_and_qp_agree`: clarabel at 1e-13 instead of its default 1e-11
/// (see there).
fn reference_qp() -> Method {
    Method::Qp(QpSettings {
        tol_gap_abs: 1e-13,
        tol_gap_rel: 1e-13,
        tol_feas: 1e-13,
        ..QpSettings::default()
    })
}

/// Error allowed to the QP reference itself, relative to max |V|. An interior-point method
/// resolves a weakly active node (true σ and gap both near zero) only to about the square root
/// of its tolerance: both stay slightly positive. Over 2000 scenes of this strategy the QP at
/// 1e-13 differs from the penalty's ε̄ → 0 limit (which satisfies σ·gap = 0 to 1e-12) by at
/// most 7.2e-5 of max |V| (one node with σ = 8e-6 and gap = 3e-5 of their peaks); at clarabel's
/// default 1e-11, by up to 4.9e-4 — the source of the earlier `ΔV 1.6e-7 of 9.8e-4` failure.
const QP_FLOOR: f64 = 2e-4;

/// Constant of the penalty error bound: |V_pen − V_qp| / max |V| ≤ K ε̄ g_max / (Γ max |V|).
///
/// At a lifted point the penalty leaves a spring ε̄ times as stiff as the foundation (compliance
/// μΓ w / ε̄), so it pulls with σ ≈ −ε̄ g / Γ (dimensionless σ, gap g in V units). That spurious
/// tension, on at most the whole plate, changes the reaction by at most ε̄ g_max / Γ of the
/// load and V by about as much of max |V|: the error is first order in ε̄ with a constant
/// g_max / (Γ max |V|) that the QP reference gives. Measured over 2000 Winkler and half-space
/// scenes at ε̄ from 1e-5 to 1e-8: K ≤ 2.2 (and ≤ 1.1 on all but one). Since the scenes draw
/// every soil (Γ the springs' Γ_w on Pasternak, Γ_h on the layer): over 600 scenes of the five
/// soils at 1e-5 and 1e-6, the constant needed beyond [`QP_FLOOR`] is at most 0.79.
const PENALTY_K: f64 = 4.0;

/// The penalty's error bound for a scene whose QP reference has max |V| = `vmax` and largest
/// nodal gap `gmax` (V units).
fn penalty_bound(eps: f64, gamma: f64, gmax: f64, vmax: f64) -> f64 {
    PENALTY_K * eps * gmax / (gamma * vmax) + QP_FLOOR
}

/// Tension left at the lifted points of a penalty solution, recomputed from σ: (|most negative
/// σ| / peak σ, pulling force / pushing force) at the constraint points.
fn tension(ops: &Operators, sol: &Solution) -> (f64, f64, f64) {
    let gs = ops.g_times(&sol.sigma);
    let w = &ops.constraints.weights;
    let peak = gs.iter().cloned().fold(0.0_f64, f64::max);
    let most_negative = gs.iter().cloned().fold(0.0_f64, f64::min);
    let pull: f64 = gs.iter().zip(w).map(|(g, w)| (-g).max(0.0) * w).sum();
    let push: f64 = gs.iter().zip(w).map(|(g, w)| g.max(0.0) * w).sum();
    // The tension's moment about the compression's centroid, over the compressive resultant
    // times (its radius of gyration + one element), along each direction the model keeps.
    let m = &ops.mesh;
    let mut moment = 0.0_f64;
    for (kept, h, at) in [(!m.sym_x, m.hx, 0), (!m.sym_y, m.hy, 1)] {
        if !kept {
            continue;
        }
        let c: Vec<f64> = ops
            .constraints
            .points
            .iter()
            .map(|p| if at == 0 { p.0 } else { p.1 })
            .collect();
        let f: Vec<f64> = gs.iter().zip(w).map(|(g, w)| g * w).collect();
        let mean = f
            .iter()
            .zip(&c)
            .filter(|(f, _)| **f > 0.0)
            .map(|(f, c)| f * c)
            .sum::<f64>()
            / push;
        let var = f
            .iter()
            .zip(&c)
            .filter(|(f, _)| **f > 0.0)
            .map(|(f, c)| f * (c - mean).powi(2))
            .sum::<f64>()
            / push;
        let pulled = f
            .iter()
            .zip(&c)
            .filter(|(f, _)| **f <= 0.0)
            .map(|(f, c)| f * (c - mean))
            .sum::<f64>();
        moment = moment.max(pulled.abs() / (push * (var.sqrt() + h)));
    }
    (-most_negative / peak, pull / push, moment)
}

/// What one scene of `penalty_and_qp_agree` exercised.
#[derive(Default)]
struct Tally {
    runs: Cell<usize>,
    converged: Cell<usize>,
    too_weak: Cell<usize>,
    cycling: Cell<usize>,
    rate_checked: Cell<usize>,
    /// Largest constant of the bound a run needed, (err − floor) Γ max|V| / (ε̄ g_max).
    worst_k: Cell<f64>,
}

fn bump(c: &Cell<usize>) {
    c.set(c.get() + 1);
}

/// The penalty method agrees with the QP to its O(ε̄) bound wherever it converges, and says why
/// wherever it does not — never a silent wrong answer. At the paper's ε̄ = 1e-5 and at 1e-6, on
/// one assembly per scene:
///
/// * converged: |V_pen − V_qp| / max |V| within [`penalty_bound`]; where it converges at both
///   ε̄, successive changes of V from ε̄ = 1e-5 to 1e-6 to 1e-7 shrink tenfold (first order);
/// * penalty too weak: the tension left at lifted points, recomputed from σ, exceeds the
///   documented tolerance; the suggested ε̄ is smaller, converges, and meets the bound;
/// * cycling or the iteration cap: the status says "not converged"; the QP solves the scene.
///
/// The tally then checks that the fixed seed's cases exercise what they should: at least 90 %
/// of the runs converge (97.6 % of 2000 scenes at 1e-5, 99.95 % at 1e-6), and at least one run
/// is flagged penalty-too-weak, so neither branch can be skipped wholesale.
#[test]
fn penalty_and_qp_agree() {
    let tally = Tally::default();
    let mut runner = TestRunner::new(config(64));
    let result = runner.run(&scenes(), |sc| {
        let model = sc.model(false);
        let ops = Operators::assemble(&model);
        let q = liftoff::solve(&ops, &reference_qp()).map_err(|e| TestCaseError::fail(format!("QP: {e}")))?;
        prop_assert!(q.status.converged(), "QP reference: {}", q.status.describe());
        let vq = ops.node_w(&q.u);
        let vmax = max_abs(&vq);
        let areas = nodal_areas(&ops.mesh);
        let gmax = q.gap.iter().zip(&areas).map(|(g, a)| g / a).fold(0.0, f64::max);
        let gamma = model.groups.gamma;
        let mut errors = Vec::new();
        for eps in [1e-5, 1e-6] {
            bump(&tally.runs);
            let p = liftoff::solve(&ops, &penalty(eps)).map_err(|e| TestCaseError::fail(format!("penalty ε̄ = {eps:e}: {e}")))?;
            let err = max_abs_diff(&ops.node_w(&p.u), &vq) / vmax;
            let bound = penalty_bound(eps, gamma, gmax, vmax);
            match &p.status {
                Status::Converged => {
                    bump(&tally.converged);
                    // The constant this run needs beyond the QP's floor.
                    let k = (err - QP_FLOOR).max(0.0) * gamma * vmax / (eps * gmax);
                    tally.worst_k.set(tally.worst_k.get().max(k));
                    prop_assert!(err <= bound, "{:?}, ε̄ = {eps:e}: ΔV {err:.2e} of max |V| > bound {bound:.2e}", sc.soil);
                    errors.push(err);
                }
                Status::PenaltyTooWeak { tension_ratio, tension_share, tension_moment, suggested_penalty } => {
                    bump(&tally.too_weak);
                    let (ratio, share, moment) = tension(&ops, &p);
                    prop_assert!(ratio > TENSION_TOLERANCE || share > TENSION_FORCE_TOLERANCE || moment > TENSION_FORCE_TOLERANCE,
                        "flagged too weak with tension {ratio:.2e} of the peak, {share:.2e} of the load and a moment of {moment:.2e}");
                    // The same sums in another order: 1e-9 (and an absolute floor for a moment
                    // that cancels) is round-off of sums over a few hundred points.
                    prop_assert!((ratio - tension_ratio).abs() <= 1e-9 * ratio && (share - tension_share).abs() <= 1e-9 * share
                        && (moment - tension_moment).abs() <= 1e-9 * moment.max(1e-6),
                        "reported tension {tension_ratio:e}, {tension_share:e}, {tension_moment:e}; recomputed {ratio:e}, {share:e}, {moment:e}");
                    prop_assert!(*suggested_penalty < eps, "suggested ε̄ {suggested_penalty:e} ≥ {eps:e}");
                    let retry = liftoff::solve(&ops, &penalty(*suggested_penalty)).map_err(|e| TestCaseError::fail(e.to_string()))?;
                    prop_assert!(retry.status.converged(), "at the suggested ε̄ = {suggested_penalty:e}: {}", retry.status.describe());
                    let err = max_abs_diff(&ops.node_w(&retry.u), &vq) / vmax;
                    let bound = penalty_bound(*suggested_penalty, gamma, gmax, vmax);
                    prop_assert!(err <= bound, "at the suggested ε̄ = {suggested_penalty:e}: ΔV {err:.2e} > {bound:.2e}");
                }
                other => {
                    bump(&tally.cycling);
                    prop_assert!(other.describe().starts_with("not converged"), "{}", other.describe());
                }
            }
        }
        // First order, without the QP's floor: where the penalty converges at 1e-5 and 1e-6,
        // the change of V from 1e-6 to 1e-7 is a tenth of that from 1e-5 to 1e-6. With the
        // penalised set fixed, V(ε̄) = V* + a ε̄ + O(ε̄²), so the ratio is 10 (1 + O(ε̄)):
        // measured 9.975 to 10.000; 9 to 11 allowed. Changes below 1e-7 of max |V| (scenes
        // that barely lift) are left to round-off and skipped.
        if let [_, _] = errors[..] {
            let v = |eps: f64| -> Result<Vec<f64>, TestCaseError> {
                let p = liftoff::solve(&ops, &penalty(eps)).map_err(|e| TestCaseError::fail(e.to_string()))?;
                prop_assert!(p.status.converged(), "ε̄ = {eps:e}: {}", p.status.describe());
                Ok(ops.node_w(&p.u))
            };
            let (v5, v6, v7) = (v(1e-5)?, v(1e-6)?, v(1e-7)?);
            let (d1, d2) = (max_abs_diff(&v5, &v6), max_abs_diff(&v6, &v7));
            if d2 > 1e-7 * vmax {
                bump(&tally.rate_checked);
                let rate = d1 / d2;
                prop_assert!((9.0..11.0).contains(&rate), "ΔV 1e-5 → 1e-6: {d1:.2e}, 1e-6 → 1e-7: {d2:.2e}: ratio {rate:.2}");
            }
        }
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
    let (runs, converged) = (tally.runs.get(), tally.converged.get());
    eprintln!(
        "penalty_and_qp_agree: {runs} runs, {converged} converged, {} too weak, {} cycling or capped, {} first-order checks, largest K {:.2}",
        tally.too_weak.get(),
        tally.cycling.get(),
        tally.rate_checked.get(),
        tally.worst_k.get()
    );
    assert!(
        converged as f64 >= 0.9 * runs as f64,
        "only {converged} of {runs} runs converged"
    );
    assert!(
        tally.too_weak.get() >= 1,
        "the seed's cases no longer exercise a penalty-too-weak run"
    );
    assert!(
        tally.rate_checked.get() >= 5,
        "only {} scenes had errors large enough to check the rate",
        tally.rate_checked.get()
    );
}

/// Whether a validation error about an edited `key` may name `field`: the key itself
/// (`plate.thickness`, `load[0].x`, `mesh.elements[1]`), or the group whose combination it
/// enters (the derived groups Γ, Δ, D name `plate`; the load total names `load`; a side shorter
/// than the thickness names `plate.thickness`, an aspect ratio out of range `plate.width`).
fn may_name(key: &str, field: &str) -> bool {
    let plate = [
        "length",
        "width",
        "thickness",
        "youngs_modulus",
        "poissons_ratio",
    ];
    let foundation = ["model", "modulus"];
    let load = ["kind", "x", "y", "force", "pressure"];
    let last = field.rsplit('.').next().unwrap_or(field);
    let leaf = last.split('[').next().unwrap_or(last);
    leaf == key
        || (field == "plate" && (plate.contains(&key) || foundation.contains(&key)))
        || (field == "load" && load.contains(&key))
        || (["plate.thickness", "plate.width"].contains(&field)
            && ["length", "width"].contains(&key))
}

proptest! {
    #![proptest_config(config(256))]

    /// Random edits of a valid scene (any key, any value, including garbage) give a usable
    /// problem or an error that points at the edit, never a panic: a parse error quotes the
    /// edited line, a validation error names the edited key (or the group it enters), and an
    /// accepted scene yields finite groups, loads summing to ±4 P and a valid method.
    #[test]
    fn random_scene_edits_are_accepted_usable_or_rejected_at_the_edit(
        line in 0usize..20,
        value in prop_oneof![
            Just("nan".to_string()), Just("-inf".to_string()), Just("-1.0".to_string()), Just("0".to_string()),
            Just("1e308".to_string()), Just("\"text\"".to_string()), Just("[1, 2, 3]".to_string()),
            Just("[]".to_string()), Just("{ a = 1 }".to_string()), Just("true".to_string()),
            any::<f64>().prop_map(|v| format!("{v:e}")), any::<i64>().prop_map(|v| v.to_string()),
            "[a-z_]{1,12}".prop_map(|s| s),
        ],
    ) {
        let base = liftoff::examples::scene("footing").unwrap_or_default();
        let lines: Vec<(usize, &str)> = base.lines().enumerate().filter(|(_, l)| l.contains(" = ")).collect();
        prop_assert!(!lines.is_empty(), "the footing scene has key = value lines");
        let (number, target) = lines[line % lines.len()];
        let key = target.split(" = ").next().unwrap_or("x");
        let edited: String = base
            .lines()
            .enumerate()
            .map(|(k, l)| if k == number { format!("{key} = {value}\n") } else { format!("{l}\n") })
            .collect();
        match Problem::from_toml(&edited) {
            Ok(p) => {
                let g = &p.model.groups;
                for (name, v) in [("Γ", g.gamma), ("Δ", g.delta), ("μ", g.mu)] {
                    prop_assert!(v.is_finite() && v > 0.0, "`{key} = {value}` accepted with {name} = {v:e}");
                }
                prop_assert!(g.nu > -1.0 && g.nu < 0.5, "`{key} = {value}` accepted with ν = {}", g.nu);
                let r = p.model.resultant();
                prop_assert!((r.abs() - 4.0).abs() <= 1e-9, "`{key} = {value}`: loads sum to {r}, not ±4 P");
                prop_assert!(p.model.elements.iter().all(|n| (1..=4000).contains(n)), "`{key} = {value}`: elements {:?}", p.model.elements);
                prop_assert!(p.method.validate().is_ok(), "`{key} = {value}`: method {:?}", p.method);
            }
            Err(Error::Parse(m)) => {
                // toml reports 1-based lines.
                prop_assert!(m.contains(&format!("line {}", number + 1)), "`{key} = {value}`: parse error elsewhere: {m}");
            }
            Err(Error::Invalid { field, message }) => {
                prop_assert!(may_name(key, &field), "`{key} = {value}` rejected naming `{field}`: {message}");
            }
            Err(e) => prop_assert!(false, "`{key} = {value}`: validation returned a {} error: {e}", e.kind()),
        }
    }
}
