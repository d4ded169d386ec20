//! Bonded (bilateral) solves against closed forms and invariants.

use crate::common;
use common::*;

/// Westergaard (1926): an infinite thin plate on a Winkler subgrade under a point load F deflects
/// w = F / (8 √(k D)) under the load. In the unit system (D = 1, total load 4, k = 1/(μΓ)):
/// V = 4 / (8 √k) = √(μΓ) / 2.
///
/// The plate is made "infinite" with half-size L = 10 ℓ (ℓ = (D/k)^¼ the radius of relative
/// stiffness; the free-edge influence at the centre decays like e^(−L/(ℓ√2)) ≈ 1e-3) and thin
/// (H = ℓ/100, so the Mindlin shear deflection, ~F ln(ℓ/h)/(2π κ_s), is below 1e-4 of w).
#[test]
fn winkler_point_load_matches_westergaard() {
    let ell: f64 = 0.1;
    let gamma = ell.powi(4); // μ = 1, k = 1/Γ, ℓ = Γ^¼
    let h_over_l = ell / 100.0;
    let delta = h_over_l * h_over_l / (6.0 * (5.0 / 6.0) * 0.7);
    let exact = gamma.sqrt() / 2.0;
    let mut errors = Vec::new();
    for n in [40, 80, 160] {
        // n elements over 2L = 20ℓ: h = ℓ/2, ℓ/4, ℓ/8.
        let a = run(&point_scene(
            "winkler",
            gamma,
            delta,
            1.0,
            (0.0, 0.0),
            [n, n],
            "[solver]\ncontact = \"bonded\"",
        ));
        assert_eq!(
            a.summary.symmetry, "quarter",
            "centre load on an even mesh uses a quarter model"
        );
        let err = (a.summary.V_center - exact).abs() / exact;
        eprintln!("Westergaard n = {n}: V = {:.6e}, exact {exact:.6e}, error {err:.3e}, equilibrium {:.1e}", a.summary.V_center, a.summary.resultant.relative_error);
        errors.push(err);
        // Equilibrium holds to the round-off of K's row sums: ε · κ_s |u| per node with
        // κ_s = 1/(μΔ) ≈ 3.5e6 here (H = ℓ/100), i.e. ~1e-9 relative over 6561 nodes.
        assert!(
            a.summary.resultant.relative_error < 1e-8,
            "equilibrium at n = {n}"
        );
    }
    // Bilinear Mindlin elements converge at O(h²): the error must fall by at least 3× per halving
    // (theory 4×), and at h = ℓ/8 be below 1% (edge influence ~1e-3 plus discretisation).
    assert!(
        errors[2] < 0.01,
        "Westergaard at h = ℓ/8: relative error {:.3e} (all: {errors:?})",
        errors[2]
    );
    assert!(
        errors[0] / errors[1] > 3.0 && errors[1] / errors[2] > 3.0,
        "O(h²) convergence to Westergaard: {errors:?}"
    );
}

/// Boussinesq: uniform pressure q on a B × L rectangle of a half-space settles its corner by
/// w = q (1 − ν²)/(π E) [L ln((B + √(B² + L²))/L) + B ln((L + √(L² + B²))/B)]
/// (Harr 1966; Poulos & Davis 1974, table 3.1), and its centre by four times the corner value of
/// the B/2 × L/2 quarter. A square gives the textbook factors 1.122 and 0.561 q B (1 − ν²)/E.
///
/// A very flexible plate (Γ_h = 1e-7: bending redistributes pressure by a relative O(Γ)) under
/// a uniform load transmits it unchanged, so its nodes must settle as the closed form says.
#[test]
fn flexible_plate_on_half_space_settles_like_boussinesq() {
    fn corner(b: f64, l: f64) -> f64 {
        let d = (b * b + l * l).sqrt();
        (l * ((b + d) / l).ln() + b * ((l + d) / b).ln()) / std::f64::consts::PI
    }
    for mu in [1.0, 0.5] {
        let gamma = 1e-7;
        let text = format!(
            "[dimensionless]\nfoundation = \"half-space\"\ngamma = {gamma:e}\ndelta = 1e-4\nmu = {mu}\nnu = 0.3\n[[load]]\nkind = \"uniform\"\npressure = 1.0\n[mesh]\nelements = [48, 48]\n[solver]\ncontact = \"bonded\"\n"
        );
        let a = run(&text);
        // Unit system: plate 2 × 2μ, total load 4, so q = 1/μ; the half-space constant is
        // (1 − ν²)/(π E) = μ Γ, and the closed forms above carry the 1/π already.
        let q = 1.0 / mu;
        let c_pi = mu * gamma * std::f64::consts::PI;
        let centre = 4.0 * c_pi * q * corner(1.0, mu);
        let corner_w = c_pi * q * corner(2.0, 2.0 * mu);
        let e_c = (a.summary.V_center - centre).abs() / centre;
        let e_k = (a.summary.V_corner - corner_w).abs() / corner_w;
        eprintln!("Boussinesq μ = {mu}: centre error {e_c:.2e}, corner error {e_k:.2e}");
        // Nodal values of the Galerkin settlement: O(h²) in the smooth interior, the corner
        // carries the log singularity of the settlement gradient, hence the looser bound.
        assert!(
            e_c < 0.005,
            "μ = {mu}: centre V {} vs Boussinesq {centre} ({e_c:.2e})",
            a.summary.V_center
        );
        assert!(
            e_k < 0.02,
            "μ = {mu}: corner V {} vs Boussinesq {corner_w} ({e_k:.2e})",
            a.summary.V_corner
        );
        assert!(
            a.summary.resultant.relative_error < 1e-10,
            "equilibrium, μ = {mu}"
        );
    }
}

/// T is symmetric and positive definite (Galerkin form of a positive-definite kernel), on the
/// whole plate and on a quarter model with its mirror images.
#[test]
fn half_space_compliance_is_symmetric_positive_definite() {
    use liftoff::foundation::{halfspace, Compliance};
    use liftoff::mesh::Mesh;
    for (sx, sy) in [(false, false), (true, true), (true, false)] {
        let mesh = Mesh::new(2.0, 1.0, [12, 8], sx, sy);
        let Compliance::Dense(t) = halfspace::compliance(&mesh, 1.0) else {
            panic!("dense expected")
        };
        let n = t.nrows();
        let mut asym: f64 = 0.0;
        for i in 0..n {
            for j in 0..n {
                asym = asym.max((t[(i, j)] - t[(j, i)]).abs());
            }
        }
        assert!(asym == 0.0, "T symmetric ({sx}, {sy})");
        let eig = t
            .self_adjoint_eigenvalues(faer::Side::Lower)
            .expect("eigenvalues");
        let min = eig.iter().cloned().fold(f64::INFINITY, f64::min);
        let max = eig.iter().cloned().fold(0.0, f64::max);
        assert!(
            min > 1e-6 * max,
            "T positive definite ({sx}, {sy}): λ_min {min:e}, λ_max {max:e}"
        );
    }
}

/// A quarter (or half) model reproduces the whole-plate model exactly (same discrete problem
/// restricted to symmetric fields), for both foundations.
#[test]
fn reduced_models_equal_the_full_model() {
    // (foundation, load positions (s, t), expected reduction); each load set is symmetric
    // about the axes the reduction uses and not about the others.
    type Case<'a> = (&'a str, &'a [(f64, f64)], &'a str);
    let cases: [Case; 4] = [
        ("half-space", &[(0.0, 0.0)], "quarter"),
        (
            "winkler",
            &[(0.3, 0.4), (-0.3, 0.4), (0.3, -0.4), (-0.3, -0.4)],
            "quarter",
        ),
        ("winkler", &[(0.5, 0.4), (-0.5, 0.4)], "half-x"),
        (
            "half-space",
            &[(0.5, 0.0), (0.5, -0.6), (0.5, 0.6)],
            "half-y",
        ),
    ];
    for (found, loads, expect) in cases {
        let (s0, t0) = loads[0];
        let mut text = point_scene(
            found,
            1e-3,
            0.002857,
            0.75,
            (s0, t0),
            [12, 16],
            "[solver]\ncontact = \"bonded\"",
        );
        for (s, t) in &loads[1..] {
            text.push_str(&format!(
                "[[load]]\nkind = \"point\"\nx = {s}\ny = {t}\nforce = 1.0\n"
            ));
        }
        let reduced = run(&text);
        let full = run(&text.replace("[mesh]", "[mesh]\nsymmetry = \"none\""));
        assert_eq!(reduced.summary.symmetry, expect, "{found} {loads:?}");
        assert_eq!(full.summary.symmetry, "full");
        let dv = max_abs_diff(&reduced.report.field.v, &full.report.field.v)
            / max_abs(&full.report.field.v);
        let ds = max_abs_diff(&reduced.report.field.sigma, &full.report.field.sigma)
            / max_abs(&full.report.field.sigma);
        // Same discrete problem: only factorisation round-off differs.
        assert!(
            dv < 1e-9 && ds < 1e-9,
            "{found} {expect}: ΔV {dv:e}, Δσ {ds:e}"
        );
        let dm = max_abs_diff(&reduced.report.elements.mxy, &full.report.elements.mxy)
            / max_abs(&full.report.elements.mx).max(1e-300);
        assert!(
            dm < 1e-8,
            "{found} {expect}: twisting moments mirror with their sign: {dm:e}"
        );
    }
}

/// The same plate given in SI units and by its dimensionless groups gives the same V and σ; the
/// physical deflection is V P L² / D with D = E H³ / (12 (1 − ν²)).
#[test]
fn physical_and_dimensionless_scenes_agree() {
    for found in ["winkler", "half-space"] {
        let (length, width, h, e, nu): (f64, f64, f64, f64, f64) = (8.0, 5.0, 0.3, 25e9, 0.2);
        let soil = if found == "winkler" {
            "model = \"winkler\"\nmodulus = 4e7".to_string()
        } else {
            "model = \"half-space\"\nyoungs_modulus = 8e7\npoissons_ratio = 0.35".to_string()
        };
        let physical = format!(
            "[plate]\nlength = {length}\nwidth = {width}\nthickness = {h}\nyoungs_modulus = {e}\npoissons_ratio = {nu}\n[foundation]\n{soil}\n\
             [[load]]\nkind = \"point\"\nx = 1.0\ny = 0.5\nforce = 3e5\n[[load]]\nkind = \"patch\"\nx = [-2.0, -1.0]\ny = [-1.5, 0.5]\npressure = 5e4\n\
             [mesh]\nelements = [16, 10]\n[solver]\ncontact = \"bonded\"\n"
        );
        let pa = run(&physical);
        let g = pa.summary.dimensionless.clone();
        let l = length / 2.0;
        let mu = width / length;
        // Loads in (s, t) with relative magnitudes: point force F, patch density q with
        // ∫ q ds dt = resultant / P, i.e. q = p μ L².
        let dimless = format!(
            "[dimensionless]\nfoundation = \"{found}\"\ngamma = {:e}\ndelta = {:e}\nmu = {}\nnu = {nu}\n\
             [[load]]\nkind = \"point\"\nx = {}\ny = {}\nforce = 3e5\n[[load]]\nkind = \"patch\"\nx = [{}, {}]\ny = [{}, {}]\npressure = {:e}\n\
             [mesh]\nelements = [16, 10]\n[solver]\ncontact = \"bonded\"\n",
            g.gamma, g.delta, g.mu, 1.0 / l, 0.5 / (mu * l), -2.0 / l, -1.0 / l, -1.5 / (mu * l), 0.5 / (mu * l), 5e4 * mu * l * l
        );
        let da = run(&dimless);
        let dv = max_abs_diff(&pa.report.field.v, &da.report.field.v) / max_abs(&da.report.field.v);
        let ds = max_abs_diff(&pa.report.field.sigma, &da.report.field.sigma)
            / max_abs(&da.report.field.sigma);
        assert!(
            dv < 1e-10 && ds < 1e-10,
            "{found}: physical vs dimensionless ΔV {dv:e}, Δσ {ds:e}"
        );
        let d = e * h.powi(3) / (12.0 * (1.0 - nu * nu));
        let p = (3e5 + 5e4 * 2.0) / 4.0;
        let w_expected = pa.summary.V_max * p * l * l / d;
        assert!(
            (pa.summary.w_max - w_expected).abs() < 1e-12 * w_expected,
            "{found}: w = V P L² / D"
        );
    }
}

/// Every bonded solve is in equilibrium: ∫σ = ∫q to round-off, for every bundled example.
#[test]
fn bundled_examples_are_in_equilibrium_when_bonded() {
    for (name, _, text) in liftoff::examples::SCENES {
        let text = text.replace("contact = \"unbonded\"", "contact = \"bonded\"");
        if text.contains("[[void]]") {
            // Bonded contact would glue the plate to the lowered surface: refused, naming it.
            match liftoff::Problem::from_toml(&text) {
                Err(liftoff::Error::Invalid { field, .. }) => assert_eq!(field, "void", "{name}"),
                other => panic!(
                    "{name}: bonded contact with voids must be refused, got {:?}",
                    other.map(|_| ())
                ),
            }
            continue;
        }
        let a = run(&text);
        assert!(
            a.summary.resultant.relative_error < 1e-10,
            "{name}: reaction {} vs load {}",
            a.summary.resultant.reaction,
            a.summary.resultant.load
        );
        // Direct solves leave the gap at round-off. On the iterative route (a large continuum
        // soil: warehouse-bay) the gap is the residual of the Schur system, which the PCG
        // brings to 1e-10 of the right-hand side in the 2-norm: at most 1e-10 √n of its
        // largest entry, about |V|max, at any node.
        let iterative = a
            .summary
            .notes
            .iter()
            .any(|n| n.contains("iterative route"));
        let tol = if iterative {
            1e-10 * (a.summary.nodes as f64).sqrt()
        } else {
            1e-10
        };
        assert!(
            a.summary.complementarity.min_gap.abs() < tol * a.summary.V_max.abs(),
            "{name}: bonded gap vanishes ({:e} of |V|max)",
            a.summary.complementarity.min_gap.abs() / a.summary.V_max.abs()
        );
    }
}

/// The bonded Winkler solve reports its phases (summary.json's `method_time_s`): the symbolic
/// analysis and the factorisation, each a part of its total.
#[test]
fn bonded_winkler_reports_its_phases() {
    let text = liftoff::examples::scene("paper-winkler").expect("bundled");
    let p = liftoff::Problem::from_toml(text).expect("scene");
    let ops = liftoff::Operators::assemble(&p.model);
    let s = liftoff::solve::solve(&ops, &liftoff::Method::Bonded).expect("bonded");
    let t = s.info.timings;
    let (a, f) = (
        t.analyse.expect("analysis time"),
        t.factor.expect("factorisation time"),
    );
    assert!(a >= 0.0 && f >= 0.0 && a + f <= t.total, "{t:?}");
}
