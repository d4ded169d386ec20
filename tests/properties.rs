//! Property tests over random scenes (bounded case counts so the suite stays fast).

use liftoff::method::{Contact, MethodKind};
use liftoff::{analyse, Analysis};
use liftoff::{Method, PenaltySettings, Problem};
use proptest::prelude::*;

#[derive(Debug, Clone)]
struct RandomScene {
    foundation: &'static str,
    gamma: f64,
    mu: f64,
    n: usize,
    loads: Vec<(f64, f64, f64)>,
    uniform: f64,
}

impl RandomScene {
    fn toml(&self, mirror_s: bool) -> String {
        let mut t = format!(
            "[dimensionless]\nfoundation = \"{}\"\ngamma = {:e}\ndelta = 0.002857\nmu = {}\nnu = 0.3\n[mesh]\nelements = [{}, {}]\nsymmetry = \"none\"\n",
            self.foundation, self.gamma, self.mu, self.n, self.n
        );
        for &(s, tt, f) in &self.loads {
            let s = if mirror_s { -s } else { s };
            t.push_str(&format!(
                "[[load]]\nkind = \"point\"\nx = {s}\ny = {tt}\nforce = {f}\n"
            ));
        }
        if self.uniform > 0.0 {
            t.push_str(&format!(
                "[[load]]\nkind = \"uniform\"\npressure = {}\n",
                self.uniform
            ));
        }
        t
    }
}

fn scenes() -> impl Strategy<Value = RandomScene> {
    (
        prop_oneof![Just("winkler"), Just("half-space")],
        -4.0f64..-1.0,
        0.5f64..1.0,
        prop_oneof![Just(4usize), Just(6), Just(8)],
        prop::collection::vec((-0.6f64..0.6, -0.6f64..0.6, 0.5f64..2.0), 1..4),
        prop_oneof![Just(0.0), 0.05f64..0.5],
    )
        .prop_map(|(foundation, lg, mu, n, loads, uniform)| RandomScene {
            foundation,
            gamma: 10f64.powf(lg),
            mu,
            n,
            loads,
            uniform,
        })
}

fn solve(
    text: &str,
    contact: Contact,
    method: MethodKind,
    eps: f64,
) -> Result<Analysis, liftoff::Error> {
    let mut p = Problem::from_toml(text)?;
    p.method = match (contact, method) {
        (Contact::Bonded, _) => Method::Bonded,
        (Contact::Unbonded, MethodKind::Penalty) => Method::Penalty(PenaltySettings::fixed(eps)),
        (Contact::Unbonded, MethodKind::Qp) => Method::qp(),
    };
    analyse(&p)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, failure_persistence: None, ..ProptestConfig::default() })]

    /// Equilibrium in every solve: the reaction balances the load to round-off.
    #[test]
    fn every_solve_is_in_equilibrium(sc in scenes()) {
        let text = sc.toml(false);
        for (contact, method) in [(Contact::Bonded, MethodKind::Penalty), (Contact::Unbonded, MethodKind::Qp)] {
            let a = solve(&text, contact, method, 1e-5).map_err(|e| TestCaseError::fail(format!("{contact} {method}: {e}")))?;
            // Round-off bound: the plate's κ_s/K contrast costs a few digits (tests/bonded.rs).
            prop_assert!(a.summary.resultant.relative_error < 1e-8, "{contact} {method}: {:e}", a.summary.resultant.relative_error);
        }
    }

    /// Mirroring the loads about x = 0 mirrors V and σ (whole-plate model, no symmetry used;
    /// penalty method, whose factorisations are exact to round-off — the QP's interior-point
    /// tolerance would blur the comparison at 1e-7), and unbonded QP pressures are never
    /// tensile beyond the solver tolerance.
    #[test]
    fn mirrored_loads_give_mirrored_fields_and_no_tension(sc in scenes()) {
        let a = solve(&sc.toml(false), Contact::Unbonded, MethodKind::Penalty, 1e-8).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let b = solve(&sc.toml(true), Contact::Unbonded, MethodKind::Penalty, 1e-8).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let (fa, fb) = (&a.report.field, &b.report.field);
        let nx = fa.nx;
        let vmax = fa.v.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let smax = fa.sigma.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        for j in 0..=fa.ny {
            for i in 0..=nx {
                let k = i + j * (nx + 1);
                let m = (nx - i) + j * (nx + 1);
                // Same discrete problem mirrored: round-off of two factorisations only.
                prop_assert!((fa.v[k] - fb.v[m]).abs() <= 1e-9 * vmax, "V at node ({i}, {j})");
                prop_assert!((fa.sigma[k] - fb.sigma[m]).abs() <= 1e-9 * smax, "σ at node ({i}, {j})");
            }
        }
        let q = solve(&sc.toml(false), Contact::Unbonded, MethodKind::Qp, 1e-5).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let qs = &q.report.field.sigma;
        let qmax = qs.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let min = qs.iter().cloned().fold(f64::INFINITY, f64::min);
        prop_assert!(min >= -1e-8 * qmax, "QP tension {min:e}");
    }

    /// The two methods agree where the penalty is adequate (small ε̄; runs flagged
    /// penalty-too-weak are skipped, they say so themselves).
    #[test]
    fn penalty_and_qp_agree(sc in scenes()) {
        let text = sc.toml(false);
        let q = solve(&text, Contact::Unbonded, MethodKind::Qp, 1e-8).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let p = solve(&text, Contact::Unbonded, MethodKind::Penalty, 1e-8).map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assume!(p.summary.converged);
        let vmax = q.report.field.v.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let dv = q.report.field.v.iter().zip(&p.report.field.v).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
        // O(ε̄) with constants up to ~1e3 (tests/unbonded.rs): 1e-4 relative at ε̄ = 1e-8.
        prop_assert!(dv <= 1e-4 * vmax, "ΔV {dv:e} of {vmax:e}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, failure_persistence: None, ..ProptestConfig::default() })]

    /// Random edits of a valid scene (any key, any value, including garbage) give a result or an
    /// error, never a panic.
    #[test]
    fn random_scene_edits_never_panic(
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
        let lines: Vec<&str> = base.lines().filter(|l| l.contains(" = ")).collect();
        let target = lines[line % lines.len()];
        let key = target.split(" = ").next().unwrap_or("x");
        let edited = base.replacen(target, &format!("{key} = {value}"), 1);
        // Only parse and validate: solving is covered above, and a huge mesh would be refused.
        let _ = Problem::from_toml(&edited);
    }
}
