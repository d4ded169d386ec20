//! The contact boundary located inside the element (`liftoff::post::boundary`): its convergence
//! against closed forms derived here, and the geometry of the boundary, area and extents.

use crate::common;
use common::*;

use liftoff::metrics::loglog_fit;
use liftoff::post::FullField;
use liftoff::Analysis;

/// Contact radius of the node-resolved measure liftoff used before: the area where the bilinear
/// σ exceeds 1e-6 of its peak (8 × 8 samples per element), as √(area/π) in units of L. Contact
/// then reaches the first lifted node.
fn node_resolved_radius(f: &FullField, mu: f64) -> f64 {
    let peak = f.sigma.iter().cloned().fold(0.0_f64, f64::max);
    let sub = 8;
    let mut hit = 0usize;
    for j in 0..f.ny {
        for i in 0..f.nx {
            for p in 0..sub {
                for q in 0..sub {
                    let s = -1.0 + 2.0 * (i as f64 + (p as f64 + 0.5) / sub as f64) / f.nx as f64;
                    let t = -1.0 + 2.0 * (j as f64 + (q as f64 + 0.5) / sub as f64) / f.ny as f64;
                    if f.interpolate(&f.sigma, s, t) > 1e-6 * peak {
                        hit += 1;
                    }
                }
            }
        }
    }
    let fraction = hit as f64 / (f.nx * f.ny * sub * sub) as f64;
    (fraction * 4.0 * mu / std::f64::consts::PI).sqrt()
}

/// A strip 2L × 2μL on Winkler soil (ν = 0) under a line load across its middle, x = 0: the
/// load is 1 : 2 : 1 on the three nodes of that line of a mesh two elements wide, which is the
/// consistent load vector of a uniform line load.
fn strip_scene(gamma: f64, delta: f64, mu: f64, nx: usize) -> String {
    let mut text = format!(
        "[dimensionless]\nfoundation = \"winkler\"\ngamma = {gamma:e}\ndelta = {delta:e}\nmu = {mu}\nnu = 0.0\n[mesh]\nelements = [{nx}, 2]\n[solver]\nmethod = \"penalty\"\npenalty = 1e-9\n"
    );
    for (t, force) in [(-1.0, 1.0), (0.0, 2.0), (1.0, 1.0)] {
        text.push_str(&format!(
            "[[load]]\nkind = \"point\"\nx = 0.0\ny = {t}\nforce = {force}\n"
        ));
    }
    text
}

/// **Reference: a beam on a tensionless Winkler subgrade under a point load.** With ν = 0 a free
/// strip loaded uniformly across its width bends cylindrically: w = w(x) meets every free-edge
/// condition on y = ±μL (M_yy = −D(w_yy + ν w_xx) = 0, M_xy = 0), so the plate is a beam of
/// rigidity D per unit width on springs k (the discrete problem is y-independent too: checked).
/// In contact, D w'''' + k w = 0; where lifted the beam carries no load, so with free ends its
/// moment and shear vanish and w is linear — for a finite strip as for an infinite one. At the
/// edge of contact x = a: w = 0, w'' = 0, w''' = 0; at the load: w'(0) = 0, w'''(0⁺) = P/(2D).
/// The four constants of e^{∓λx}(cos λx, sin λx), λ = (k/4D)^¼, and a solve these five
/// equations for λa = π/2 exactly: a = π/(2λ) (also found to 12 digits by root-finding the five
/// conditions in mpmath). Shear flexibility (Timoshenko, same conditions with Q = 0, M = 0 at
/// x = a) shifts a by −0.33 Δ relatively: 3e-7 at Δ = 1e-6, below every error measured here.
///
/// **What is asserted.** The would-be gap −w is smooth across the edge of contact, so its
/// interpolated zero should converge at second order in h, where a node-resolved edge (contact
/// up to the first lifted node) converges at first order. Over six meshes, h = L/10 … L/320:
/// * the located edge (extent along x, and the area-based contact fraction and radius, which
///   for this straight edge carry the same information) has a fitted log-log rate above 1.5:
///   it must beat first order clearly; the theory says 2, and the error's constant moves with
///   the edge's position between two nodes (|e|/h² between 0.05 and 0.6 here), which the fit
///   over six meshes absorbs to within a few tenths;
/// * every located edge is within h²/2 of a (the second-order envelope, in units of L);
/// * the node-resolved radius has an error of order h (rate below 1.5) and is the larger of the
///   two at every mesh.
#[test]
fn winkler_strip_edge_of_contact_converges_at_second_order() {
    let (gamma, delta, mu): (f64, f64, f64) = (3e-3, 1e-6, 0.25);
    let k = 1.0 / (mu * gamma);
    let lambda = (k / 4.0).powf(0.25);
    let a = std::f64::consts::FRAC_PI_2 / lambda;
    let radius_ref = (4.0 * mu * a / std::f64::consts::PI).sqrt();
    let mut new = Vec::new();
    let mut old = Vec::new();
    for nx in [20, 40, 80, 160, 320, 640] {
        let h = 2.0 / nx as f64;
        let r = run(&strip_scene(gamma, delta, mu, nx));
        assert!(
            r.solution.status.converged(),
            "nx = {nx}: {}",
            r.summary.status
        );
        let f = &r.report.field;
        // The discrete solution is y-independent (ν = 0): the three rows of nodes agree.
        let n = f.nodes_x();
        let spread = (0..n)
            .map(|i| {
                (f.v[i] - f.v[i + n])
                    .abs()
                    .max((f.v[i] - f.v[i + 2 * n]).abs())
            })
            .fold(0.0, f64::max);
        assert!(
            spread < 1e-8 * max_abs(&f.v),
            "nx = {nx}: rows differ by {spread:e}"
        );
        let ext = r.report.contact_extent.x;
        let frac = r.report.contact_fraction;
        let rad = r.report.contact_radius;
        let rad_old = node_resolved_radius(f, mu);
        eprintln!(
            "strip nx = {nx}: extent {ext:.7} (error {:+.2e}), fraction {frac:.7}, radius error {:+.2e}, node-resolved radius error {:+.2e}",
            ext - a,
            rad - radius_ref,
            rad_old - radius_ref
        );
        assert!(
            (ext - a).abs() <= 0.5 * h * h,
            "nx = {nx}: extent {ext} vs a = {a}: error beyond h²/2 = {}",
            0.5 * h * h
        );
        // A straight edge: the area inside it is the strip [−a, a] × [−μ, μ].
        assert!(
            (frac - ext).abs() < 1e-9,
            "nx = {nx}: contact fraction {frac} vs extent {ext}"
        );
        assert!(
            (rad_old - radius_ref).abs() > (rad - radius_ref).abs(),
            "nx = {nx}: node-resolved radius {rad_old} closer to {radius_ref} than the located {rad}"
        );
        new.push((h, (rad - radius_ref).abs()));
        old.push((h, (rad_old - radius_ref).abs()));
    }
    let (rate, _) = loglog_fit(&new).expect("fit of the located radius");
    let (rate_old, _) = loglog_fit(&old).expect("fit of the node-resolved radius");
    eprintln!("strip: rate {rate:.2} located, {rate_old:.2} node-resolved");
    assert!(
        rate > 1.5,
        "located contact radius converges at rate {rate:.2}"
    );
    assert!(
        rate_old < 1.5,
        "node-resolved radius converges at rate {rate_old:.2}: expected first order"
    );
}

/// **Reference: an infinite Kirchhoff plate on a tensionless Winkler subgrade under a point
/// load** has contact radius a = 2.849 ℓ, ℓ = (D/K)^¼ (`liftoff::paper::
/// WINKLER_INFINITE_PLATE_RADIUS`; re-derived for this test: inside, −kei(r/ℓ)/(2π) + A ber + B bei;
/// outside, the unloaded plate E + F ln r; at r = a, w = 0, ∇²w = 0 and (∇²w)' = 0 — ν drops out).
/// A finite plate changes that: on a free *circular* plate of radius R the outside solution
/// gains C r² with C = (1 − ν)F / (2(1 + ν)R²) (zero edge moment), and a falls to 2.8283 ℓ at
/// R = 10 ℓ and 2.8385 ℓ at R = 10√2 ℓ (ν = 0.3; same matching conditions, solved in mpmath).
/// The square plate of half-side L = 10 ℓ lies between its inscribed and circumscribed circles,
/// and a decreases monotonically as the free plate shrinks (2.8476, 2.8436, 2.8385, 2.8283 at
/// R = 40, 20, 14.1, 10 ℓ), so we take [2.8283, 2.8385] ℓ as the bracket of the square plate.
/// Thin plate: Δ = 1e-6 makes the shear deflection 1e-4 of the bending one at scale ℓ.
///
/// Asserted at 80 and 160 elements per side (h = ℓ/4 and ℓ/8): the located contact radius lies
/// in the bracket, widened by h²/ℓ² · 0.1 ℓ for discretisation (the strip's measured envelope is
/// |e| < 0.6 h²); the node-resolved radius lies above it by more than the bracket is wide.
#[test]
fn winkler_point_load_contact_radius_lies_in_the_plate_bracket() {
    let gamma: f64 = 1e-4;
    let ell = gamma.powf(0.25);
    let bracket = [2.8283, 2.8385];
    assert!(bracket[1] < liftoff::paper::WINKLER_INFINITE_PLATE_RADIUS);
    for n in [80, 160] {
        let text = point_scene(
            "winkler",
            gamma,
            1e-6,
            1.0,
            (0.0, 0.0),
            [n, n],
            "[solver]\npenalty = 1e-9",
        );
        let r = run(&text);
        assert!(r.solution.status.converged(), "{n}: {}", r.summary.status);
        let h = 2.0 / n as f64 / ell;
        let slack = 0.1 * h * h;
        let a = r.report.contact_radius / ell;
        let old = node_resolved_radius(&r.report.field, 1.0) / ell;
        eprintln!("point load {n} × {n}: a = {a:.4} ℓ located, {old:.4} ℓ node-resolved");
        assert!(
            a > bracket[0] - slack && a < bracket[1] + slack,
            "{n} × {n}: contact radius {a:.4} ℓ outside [{}, {}] ± {slack:.1e}",
            bracket[0],
            bracket[1]
        );
        assert!(
            old > bracket[1] + (bracket[1] - bracket[0]),
            "{n} × {n}: node-resolved {old:.4} ℓ"
        );
        // The extents along the axis and the diagonal see the same nearly circular edge.
        let ex = r.report.contact_extent.x / ell;
        let ed = r.report.contact_extent.diagonal * 2f64.sqrt() / ell;
        for (name, e) in [("axis", ex), ("diagonal", ed)] {
            assert!(
                (e - a).abs() < 0.01 * a,
                "{n} × {n}: extent along the {name} {e:.4} ℓ vs radius {a:.4} ℓ"
            );
        }
    }
}

/// On Winkler the would-be gap is −w at every node, whatever the method (the penalty leaves
/// small tensions on lifted nodes, the QP tiny pressures): φ_i = g_i/a_i − σ_i/k with
/// g_i = a_i(σ_i/k − w_i).
#[test]
fn would_be_gap_is_minus_the_deflection_on_winkler() {
    for method in ["penalty", "qp"] {
        let text = point_scene(
            "winkler",
            0.75e-3,
            0.002857,
            1.0,
            (0.3, -0.2),
            [10, 12],
            &format!("[solver]\nmethod = \"{method}\""),
        );
        let r = run(&text);
        let f = &r.report.field;
        let scale = max_abs(&f.v);
        for (k, (&phi, &v)) in f.signed_gap.iter().zip(&f.v).enumerate() {
            assert!(
                (phi + v).abs() < 1e-12 * scale,
                "{method}: node {k}: φ = {phi:e} vs −V = {:e}",
                -v
            );
        }
    }
}

/// The exact area inside the interpolated boundary against brute-force sampling of the same
/// bilinear field (400 points per element: error ≲ boundary length × h / 20, below 1e-3 of the
/// area here), and against the polygon of the oriented boundary segments (shoelace): the chords
/// cut the arcs of the bilinear zero set by O(h²) each, so the polygon's relative deficit is
/// O(h²) — asserted as a fall by more than 2.5 (4 in theory) from 16 to 32 elements per side,
/// from below 2 % (a polygon inscribed in a circle of radius R ≈ 0.46 with sides h = 1/8 misses
/// (h/R)²/6 = 1.2 %).
#[test]
fn contact_area_is_the_area_inside_the_interpolated_boundary() {
    for found in ["winkler", "half-space"] {
        let mut deficits = Vec::new();
        for n in [16, 32] {
            let text = point_scene(found, 0.75e-3, 0.002857, 1.0, (0.0, 0.0), [n, n], "");
            let r = run(&text);
            let f = &r.report.field;
            let sub = 20;
            let mut hit = 0usize;
            for j in 0..f.ny * sub {
                for i in 0..f.nx * sub {
                    let s = -1.0 + 2.0 * (i as f64 + 0.5) / (f.nx * sub) as f64;
                    let t = -1.0 + 2.0 * (j as f64 + 0.5) / (f.ny * sub) as f64;
                    if f.interpolate(&f.signed_gap, s, t) < 0.0 {
                        hit += 1;
                    }
                }
            }
            let sampled = hit as f64 / (f.nx * f.ny * sub * sub) as f64;
            let exact = r.report.contact_fraction;
            assert!(
                (exact - sampled).abs() < 1e-3 * exact,
                "{found} {n}: exact {exact} vs sampled {sampled}"
            );
            // Shoelace over the oriented segments in (s, t): the contact region is interior, so
            // the segments close; the plate is 2 × 2 in (s, t).
            let polygon: f64 = r
                .report
                .boundary
                .iter()
                .map(|seg| {
                    let [(x1, y1), (x2, y2)] = seg.st;
                    0.5 * (x1 * y2 - x2 * y1)
                })
                .sum::<f64>()
                / 4.0;
            let deficit = (polygon / exact - 1.0).abs();
            eprintln!(
                "{found} {n}: polygon/exact − 1 = {:.2e}",
                polygon / exact - 1.0
            );
            assert!(
                deficit < 0.02,
                "{found} {n}: polygon {polygon} vs exact {exact}"
            );
            deficits.push(deficit);
            // Every segment end lies on the zero of the interpolated field.
            let scale = max_abs(&f.signed_gap);
            for seg in &r.report.boundary {
                for (s, t) in seg.st {
                    let v = f.interpolate(&f.signed_gap, s, t);
                    assert!(v.abs() < 1e-12 * scale, "{found}: φ({s}, {t}) = {v:e}");
                }
            }
        }
        assert!(
            deficits[0] > 2.5 * deficits[1],
            "{found}: polygon deficit {deficits:?} does not fall at second order"
        );
    }
}

/// The extent along the x-axis is the root of the linear interpolant between the last node in
/// contact and the first lifted one on t = 0 (a grid line for an even mesh), found here from the
/// nodal values directly; along the diagonal the field vanishes at the reported extent; the
/// profiles carry the crossing points, where the pressure is zero, and the nodal σ at nodes.
#[test]
fn extents_and_profiles_end_at_the_located_boundary() {
    for found in ["winkler", "half-space"] {
        let text = point_scene(found, 0.25e-3, 0.002857, 1.0, (0.0, 0.0), [16, 16], "");
        let r = run(&text);
        let f = &r.report.field;
        let n = f.nodes_x();
        let row = f.ny / 2;
        let node = |i: usize| i + row * n;
        let first_lifted = (f.nx / 2..=f.nx)
            .find(|&i| f.signed_gap[node(i)] >= 0.0)
            .expect("the edge of the plate lifts");
        let (p, q) = (node(first_lifted - 1), node(first_lifted));
        let (gp, gq) = (f.signed_gap[p], f.signed_gap[q]);
        let expected = f.s[p] + (f.s[q] - f.s[p]) * gp / (gp - gq);
        let ext = r.report.contact_extent.x;
        assert!(
            (ext - expected).abs() < 1e-12,
            "{found}: extent {ext} vs {expected}"
        );
        assert!(
            ext > f.s[p] && ext < f.s[q],
            "{found}: between the last contact node and the first lifted one"
        );
        let d = r.report.contact_extent.diagonal;
        let v = f.interpolate(&f.signed_gap, d, d);
        assert!(
            v.abs() < 1e-12 * max_abs(&f.signed_gap),
            "{found}: φ at the diagonal extent {v:e}"
        );
        let axis = r
            .report
            .profiles
            .iter()
            .find(|p| p.line == "x-axis")
            .expect("x-axis profile");
        let at = axis
            .points
            .iter()
            .find(|pt| (pt.coord - ext).abs() < 1e-12)
            .expect("the crossing is a profile point");
        assert!(
            at.sigma.abs() < 1e-12,
            "{found}: σ = {} at the edge",
            at.sigma
        );
        let peak = max_abs(&f.sigma);
        for pt in &axis.points {
            let i = ((pt.s + 1.0) * 0.5 * f.nx as f64).round() as usize;
            if (f.s[i] - pt.s).abs() < 1e-12 {
                let k = i + row * n;
                // Nodal σ in contact and the penalty's small tensions where lifted; the QP's
                // ~1e-11 residual pressures on lifted nodes read as zero.
                assert!(
                    (pt.sigma - f.sigma[k]).abs() < 1e-9 * peak,
                    "{found}: profile σ {} vs nodal {} at s = {}",
                    pt.sigma,
                    f.sigma[k],
                    pt.s
                );
            }
        }
    }
}

/// The would-be gap uses the interior self-compliance of the whole plate at every node, so a
/// quarter model and the whole plate place the boundary alike (to the solvers' agreement).
#[test]
fn boundary_does_not_depend_on_the_symmetry_reduction() {
    for found in ["half-space", "winkler"] {
        let text = point_scene(found, 0.75e-3, 0.002857, 1.0, (0.0, 0.0), [12, 12], "");
        let quarter: Analysis = run(&text);
        let whole = run(&text.replace(
            "elements = [12, 12]",
            "elements = [12, 12]\nsymmetry = \"none\"",
        ));
        assert_eq!(quarter.summary.model_elements, [6, 6]);
        assert_eq!(whole.summary.model_elements, [12, 12]);
        let (q, w) = (&quarter.report, &whole.report);
        for (name, a, b) in [
            ("fraction", q.contact_fraction, w.contact_fraction),
            ("extent x", q.contact_extent.x, w.contact_extent.x),
            (
                "extent diagonal",
                q.contact_extent.diagonal,
                w.contact_extent.diagonal,
            ),
        ] {
            assert!(
                (a - b).abs() < 1e-6,
                "{found} {name}: quarter {a} vs whole {b}"
            );
        }
        assert_eq!(q.boundary.len(), w.boundary.len(), "{found}: segments");
    }
}
