//! Loads that add up to zero (issue 18): a bonded plate carries them — Westergaard's curling
//! case, a temperature gradient alone, and a self-equilibrated pair of forces — against a stated
//! reference force, while a tensionless foundation still refuses them. References the code does
//! not produce: the free edge of a Mindlin strip on Winkler springs under curling (a 2 × 2
//! complex system, solved below), Westergaard's interior moment, the superposition a bonded
//! (linear) plate must obey, antisymmetry, and ∬ r dA = 0.
//!
//! Units: a 30 m square concrete slab (E = 30 GPa, ν = 0.15, H = 0.25 m, α = 1e-5 /K) bonded
//! to a Winkler subgrade k = 80 MN/m³: D = 3.996e7 N·m, β = (k / 4D)^¼ = 0.841 /m, so the free
//! edge's disturbance decays like e^(−βx) and is e^(−12.6) ≈ 3e-6 of its size 15 m in, at the
//! centre and at the corners' distance from a mid-edge.

use crate::common;
use common::node_at;
use liftoff::error::Error;
use liftoff::method::{Contact, MethodKind};
use liftoff::model::{LoadReference, Model, SymmetryMode};
use liftoff::scene::{FoundationSpec, ModelBuilder, PlateSpec};
use liftoff::{analyse, Analysis, Method, Operators, Problem};
use rustfft::num_complex::Complex64 as C;

const E: f64 = 30e9;
const NU: f64 = 0.15;
const H: f64 = 0.25;
const K: f64 = 8e7;
const ALPHA: f64 = 1e-5;
const SIDE: f64 = 30.0;
/// Temperature difference, top minus bottom, K: the top warmer, the slab wants to dome.
const DT: f64 = 10.0;

fn rigidity() -> f64 {
    E * H.powi(3) / (12.0 * (1.0 - NU * NU))
}

/// Transverse shear rigidity S = χ G H with the scenes' default χ = 5/6.
fn shear_rigidity() -> f64 {
    5.0 / 6.0 * E / (2.0 * (1.0 + NU)) * H
}

/// Free curl κ = α ΔT / H, 1/m.
fn curl() -> f64 {
    ALPHA * DT / H
}

fn slab() -> ModelBuilder {
    let mut plate = PlateSpec::new(SIDE, SIDE, H, E, NU);
    plate.thermal_expansion = Some(ALPHA);
    Model::builder()
        .plate(plate)
        .foundation(FoundationSpec::winkler(K))
}

fn bonded(b: ModelBuilder) -> ModelBuilder {
    b.solver(Contact::Bonded, MethodKind::Penalty)
}

fn solve(b: &ModelBuilder) -> Analysis {
    let p: Problem = b
        .build_problem()
        .unwrap_or_else(|e| panic!("scene rejected: {e}"));
    assert_eq!(p.method, Method::Bonded);
    let a = analyse(&p).unwrap_or_else(|e| panic!("solve failed: {e}"));
    assert!(a.solution.status.converged());
    a
}

/// Deflection of the free edge of a semi-infinite Mindlin strip (plane strain) on Winkler
/// springs k, held by nothing but the springs, under a curl κ in both directions.
///
/// With rotation θ (curvature θ′, shear strain w′ − θ), the energy
/// ∫ ½ D (θ′ − κ̄)² + ½ S (w′ − θ)² + ½ k w² dx, κ̄ = (1 + ν) κ (plane strain: the curl across
/// the strip is held by its length), gives D θ″ + S (w′ − θ) = 0 and S (w″ − θ′) = k w, with
/// free-edge conditions θ′(0) = κ̄ (no moment) and w′(0) = θ(0) (no shear). Modes e^(rx) need
/// r⁴ − (k/S) r² + k/D = 0 and Θ = S r W / (S − D r²); the two with Re r < 0 decay inward.
/// Kirchhoff's limit S → ∞ gives r = β(−1 ± i) and Hetényi's edge w(0) = κ̄ / (2β²); the
/// edge deflection turns out not to depend on S at all (the shear strain only reshapes the
/// decay), which a 1-D finite-element strip with D/S 1000 times the slab's confirmed.
fn mindlin_edge_deflection(d: f64, s: f64, k: f64, kappa_bar: f64) -> f64 {
    let a = C::new(k / (2.0 * s), 0.0);
    let disc = (a * a - C::new(k / d, 0.0)).sqrt();
    let roots = [-(a + disc).sqrt(), -(a - disc).sqrt()];
    for r in roots {
        assert!(r.re < 0.0, "a decaying mode: {r}");
    }
    // Θ_i = c_i W_i.
    let c: Vec<C> = roots.iter().map(|&r| s * r / (s - d * r * r)).collect();
    // Rows: Σ r_i c_i W_i = κ̄;  Σ (r_i − c_i) W_i = 0.
    let (m11, m12) = (roots[0] * c[0], roots[1] * c[1]);
    let (m21, m22) = (roots[0] - c[0], roots[1] - c[1]);
    let det = m11 * m22 - m12 * m21;
    let w1 = kappa_bar * m22 / det;
    let w2 = -kappa_bar * m21 / det;
    let w0 = w1 + w2;
    assert!(
        w0.im.abs() < 1e-12 * w0.re.abs(),
        "a real edge deflection: {w0}"
    );
    w0.re
}

/// A bonded slab under curling alone is solved, balanced (∬ r dA = 0) and reported against
/// P = D κ: its mid-edge deflection converges to the Mindlin strip's free edge at the
/// bilinear element's second order, its centre carries Westergaard's moment, and V = w/(κL²).
#[test]
fn curling_alone_on_a_bonded_slab_matches_the_free_edge_of_a_mindlin_strip() {
    let (d, s) = (rigidity(), shear_rigidity());
    let kappa = curl();
    let w_ref = mindlin_edge_deflection(d, s, K, (1.0 + NU) * kappa);
    let beta = (K / (4.0 * d)).powf(0.25);
    let kirchhoff = (1.0 + NU) * kappa / (2.0 * beta * beta);
    eprintln!("Mindlin edge {w_ref:.6e} m (Kirchhoff {kirchhoff:.6e} m)");
    // Two derivations of the same edge (the modal solve is round-off, 1e-15).
    assert!((w_ref / kirchhoff - 1.0).abs() < 1e-10);
    assert!(
        (mindlin_edge_deflection(d, s / 1000.0, K, 1.0) / (w_ref / ((1.0 + NU) * kappa)) - 1.0)
            .abs()
            < 1e-10
    );

    let mut errors = Vec::new();
    for n in [60, 120, 240, 480] {
        let b = bonded(slab().temperature_load(DT).elements(n, n));
        let model = b.build().unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(model.reference, LoadReference::ThermalMoment);
        // P = D κ in N: stated by the model, computed here from the plate alone.
        assert!((model.load_scale / (d * kappa) - 1.0).abs() < 1e-12);
        let a = solve(&b);
        let r = &a.report;
        let edge = node_at(r, SIDE / 2.0, 0.0);
        let w_edge = r.field.w[edge];
        let err = (w_edge - w_ref).abs() / w_ref;
        eprintln!("n = {n}: mid-edge w = {w_edge:.6e} m, error {err:.3e}");
        // Top warmer: the edges curl down into the soil.
        assert!(w_edge > 0.0);
        errors.push(err);

        // Balanced: the springs' reaction adds up to nothing, to round-off of the largest
        // nodal reaction summed over the plate (≈ 1e-13 of 4P measured).
        assert!(
            r.resultant.relative_error < 1e-10,
            "{:e}",
            r.resultant.relative_error
        );
        assert!(r.resultant.load.abs() < 1e-9 * model.load_scale);

        // Reported against the stated reference: V = w / (κ L²) with L = SIDE / 2.
        let l = SIDE / 2.0;
        let v_edge = w_edge / (kappa * l * l);
        let summary = &a.summary;
        let v_max = summary.V_max;
        assert!(v_max >= v_edge * (1.0 - 1e-12));
        assert!((summary.w_max / (kappa * l * l) - v_max).abs() < 1e-12 * v_max);
        assert_eq!(
            summary.dimensionless.reference,
            LoadReference::ThermalMoment
        );

        // Westergaard: the interior is held flat, m = D (1 + ν) κ, to the edges' e^(−12.6)
        // disturbance and the element error of the centre element's moment.
        let c = (0..r.elements.x.len())
            .min_by(|&p, &q| {
                let dp = r.elements.x[p].hypot(r.elements.y[p]);
                let dq = r.elements.x[q].hypot(r.elements.y[q]);
                dp.total_cmp(&dq)
            })
            .unwrap_or(0);
        let m_ref = d * (1.0 + NU) * kappa;
        assert!(
            (r.elements.mx[c] - m_ref).abs() < 3e-3 * m_ref,
            "centre mx {:.6e}, Westergaard {m_ref:.6e}",
            r.elements.mx[c]
        );
    }
    // Second order: each halving of the element cuts the error four times (measured 8.2e-2,
    // 2.2e-2, 5.5e-3, 1.4e-3: rate 2.00); the corners' disturbance at a mid-edge (≈ 3e-6) is
    // far below the finest error, so it does not bend the rate.
    let n = errors.len();
    let rate = (errors[n - 2] / errors[n - 1]).log2();
    eprintln!("errors {errors:?}, observed rate {rate:.2}");
    assert!(errors.windows(2).all(|e| e[0] > e[1]));
    assert!(errors[n - 1] < 3e-3, "finest error {:.3e}", errors[n - 1]);
    assert!(rate > 1.7 && rate < 2.3, "rate {rate:.2}");
}

/// A bonded plate is linear: curling alone plus the self-weight alone is the two together,
/// each solved against its own reference force (physical fields compared).
#[test]
fn bonded_curling_superposes_with_the_self_weight() {
    let weight = 6.0e3;
    let n = 60;
    let both = solve(&bonded(
        slab()
            .uniform_load(weight)
            .temperature_load(DT)
            .elements(n, n),
    ));
    let curl_only = solve(&bonded(slab().temperature_load(DT).elements(n, n)));
    let weight_only = solve(&bonded(slab().uniform_load(weight).elements(n, n)));
    let (fb, fc, fw) = (
        &both.report.field,
        &curl_only.report.field,
        &weight_only.report.field,
    );
    let scale = fb.w.iter().fold(0.0_f64, |m, w| m.max(w.abs()));
    let mut worst = 0.0_f64;
    for i in 0..fb.w.len() {
        worst = worst.max((fb.w[i] - fc.w[i] - fw.w[i]).abs());
    }
    // Three direct solves of the same K: round-off of a sparse Cholesky solve, ~1e-13.
    assert!(
        worst < 1e-9 * scale,
        "superposition misses by {worst:e} of {scale:e}"
    );
    // The self-weight alone settles the slab q/k with no bending.
    let centre = node_at(&weight_only.report, 0.0, 0.0);
    assert!((fw.w[centre] / (weight / K) - 1.0).abs() < 1e-9);
}

/// Two equal and opposite forces (a couple) on a bonded plate: 4P is the downward force, the
/// answer is antisymmetric and the soil's reaction adds up to zero.
#[test]
fn a_couple_on_a_bonded_slab_is_antisymmetric_and_referenced_to_the_downward_load() {
    let force = 1.0e5;
    let b = bonded(
        slab()
            .point_load(3.0, 0.0, force)
            .point_load(-3.0, 0.0, -force)
            .elements(40, 40)
            .symmetry(SymmetryMode::None),
    );
    let model = b.build().unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(model.reference, LoadReference::DownwardLoad);
    assert!((model.load_scale - force / 4.0).abs() < 1e-9 * force);
    let a = solve(&b);
    let f = &a.report.field;
    let scale = f.w.iter().fold(0.0_f64, |m, w| m.max(w.abs()));
    for i in 0..f.w.len() {
        let j = node_at(&a.report, -f.x[i], f.y[i]);
        assert!(
            (f.w[i] + f.w[j]).abs() < 1e-9 * scale,
            "w({}, {}) = {:e} vs {:e}",
            f.x[i],
            f.y[i],
            f.w[i],
            f.w[j]
        );
    }
    assert!(f.w[node_at(&a.report, 3.0, 0.0)] > 0.0);
    assert!(a.report.resultant.relative_error < 1e-10);
}

/// A tensionless foundation cannot hold a plate whose loads add up to zero: the scene is
/// refused with a hint at bonded contact, and the library refuses such a model for the
/// unbonded methods even when it is built without a scene's `[solver]`.
#[test]
fn unbonded_contact_still_refuses_loads_that_add_up_to_zero() {
    let b = slab().temperature_load(DT).elements(20, 20);
    match b.build_problem() {
        Err(Error::Invalid { field, message }) => {
            assert_eq!(field, "load");
            assert!(message.contains("add up to zero"), "{message}");
            assert!(message.contains("bonded"), "{message}");
            assert!(message.contains("self-weight"), "{message}");
        }
        other => panic!("expected a refusal, got {:?}", other.map(|p| p.method)),
    }
    let model = b.build().unwrap_or_else(|e| panic!("{e}"));
    let ops = Operators::assemble(&model);
    for method in [
        Method::Penalty(Default::default()),
        Method::Qp(Default::default()),
    ] {
        match liftoff::solve(&ops, &method) {
            // Curling alone: no net force and no couple. Zero pressure balances the plate, but
            // where it rests on a soil that cannot pull is undetermined: ill-posed, not
            // infeasible.
            Err(Error::Unsupported(m)) => assert!(m.contains("carries no net load"), "{m}"),
            other => panic!(
                "{}: expected Unsupported, got {:?}",
                method.name(),
                other.map(|s| s.status)
            ),
        }
    }
    // Every load zero: nothing to reference, refused whatever the contact.
    let zero = bonded(slab().point_load(0.0, 0.0, 0.0).elements(20, 20));
    assert!(matches!(zero.build(), Err(Error::Invalid { .. })));
}
