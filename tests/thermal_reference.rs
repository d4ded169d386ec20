//! Temperature loads end to end against closed forms the code did not produce: in the interior
//! of a large slab bonded to Winkler springs the plate cannot curl (w → 0 far from the edges),
//! so every face carries the fully restrained thermal stress of its own temperature,
//! σ_face = −Eα(T_face − T_mean)/(1 − ν): the restrained linear part ∓EαΔT_eq/(2(1 − ν)) and
//! the self-equilibrated rest −EαT_nl/(1 − ν) add up to it, whatever the profile's shape.
//! T_mean is the profile's mean through the thickness, integrated here (trapezoids for a
//! piecewise-linear profile, Simpson for a quadratic: both exact).
//!
//! How far from the edges is "interior": Westergaard–Bradbury's strip coefficient C = 1 −
//! 2(sin λ cosh λ + cos λ sinh λ)/(sin 2λ + sinh 2λ), λ = L/(ℓ√8), differs from 1 by about
//! 2√2 e^(−λ); on the slabs below λ ≥ 8.4 (|1 − C| ≤ 1e-3). Inside, the curvature load is
//! uniform and the MITC4 plate carries a uniform moment exactly, so the mesh adds nothing there.

use liftoff::post::Report;

use crate::common;

const E: f64 = 30e9;
const NU: f64 = 0.15;
const H: f64 = 0.25;
const K: f64 = 80e6;
const ALPHA: f64 = 1e-5;

/// A bonded slab `a` × `b` m (0.25 m elements) on k = 80 MN/m³ (ℓ = 0.841 m for the 0.25 m
/// section) with the given loads and extra sections ([[joint]], [[panel]]).
fn slab(a: f64, b: f64, loads: &str, extra: &str) -> String {
    format!(
        "[plate]\nlength = {a}\nwidth = {b}\nthickness = {H}\nyoungs_modulus = {E}\npoissons_ratio = {NU}\nthermal_expansion = {ALPHA}\n\
         [foundation]\nmodel = \"winkler\"\nmodulus = {K}\n{loads}{extra}\
         [mesh]\nelements = [{}, {}]\n[solver]\ncontact = \"bonded\"\n",
        (a / 0.25).round() as usize,
        (b / 0.25).round() as usize
    )
}

/// The largest |σ − want| over the elements within `reach` m of (x, y), for σx and σy at
/// `face`, relative to |want|.
fn interior_error(r: &Report, top: bool, centre: [f64; 2], reach: f64, want: f64) -> f64 {
    let e = &r.elements;
    let face = if top { &e.top } else { &e.bottom };
    let mut worst = 0.0f64;
    let mut seen = 0;
    for i in 0..e.x.len() {
        if (e.x[i] - centre[0]).abs() <= reach && (e.y[i] - centre[1]).abs() <= reach {
            seen += 1;
            worst = worst
                .max((face.sx[i] - want).abs())
                .max((face.sy[i] - want).abs());
        }
    }
    assert!(seen > 0, "no element near {centre:?}");
    worst / want.abs()
}

/// The fully restrained face stress −Eα(T_face − T_mean)/(1 − ν), with the section's E.
fn restrained(e: f64, t_face: f64, t_mean: f64) -> f64 {
    -e * ALPHA * (t_face - t_mean) / (1.0 - NU)
}

/// An asymmetric day profile (35, 28, 23, 20 °C at 0, 0.05, 0.125, 0.25 m: mean 24.7 °C) and
/// a quadratic one (35, 24, 20 °C at the top, middle, bottom: mean 24 + 7/6 °C) on a 24 m
/// square slab (28.5ℓ): over the middle 4 m × 4 m both faces carry −Eα(T_face − T_mean)/(1 −
/// ν), σx and σy alike — −3.64 and +1.66 MPa for the first profile, top and bottom: not
/// opposite, as a linear gradient's would be. Tolerance 1e-3: those elements are at least 10
/// m = 8.4ℓ√2 from the edges, where the edges' disturbance is below 2√2 e^(−8.4) = 6e-4 of
/// the restrained stress; measured 0.8–1.8e-4.
#[test]
fn an_asymmetric_profile_restrained_gives_each_face_its_own_temperature() {
    let depths = [0.0, 0.05, 0.125, 0.25];
    let temps = [35.0, 28.0, 23.0, 20.0];
    let mean = depths
        .windows(2)
        .zip(temps.windows(2))
        .map(|(d, t)| (d[1] - d[0]) * (t[0] + t[1]) / 2.0)
        .sum::<f64>()
        / H;
    assert!((mean - 24.7).abs() < 1e-12, "mean {mean}");
    // The quadratic through (H/2, 35), (0, 24), (−H/2, 20), its mean by Simpson's rule.
    let (qt, qm, qb) = (35.0, 24.0, 20.0);
    let q_mean = (qt + 4.0 * qm + qb) / 6.0;
    for (name, load, top, bottom, t_mean) in [
        (
            "piecewise linear",
            format!(
                "[[load]]\nkind = \"temperature-profile\"\ndepths = {depths:?}\ntemperatures = {temps:?}\n"
            ),
            temps[0],
            temps[3],
            mean,
        ),
        (
            "quadratic",
            format!(
                "[[load]]\nkind = \"temperature-profile\"\ndepths = [0.0, 0.125, 0.25]\ntemperatures = [{qt}, {qm}, {qb}]\ninterpolation = \"quadratic\"\n"
            ),
            qt,
            qb,
            q_mean,
        ),
    ] {
        let a = common::run(&slab(24.0, 24.0, &load, ""));
        let r = &a.report;
        let (want_top, want_bottom) = (restrained(E, top, t_mean), restrained(E, bottom, t_mean));
        assert!(
            (want_top + want_bottom).abs() > 0.2 * want_top.abs(),
            "{name}: the faces must differ by more than a sign"
        );
        for (face, is_top, want) in [("top", true, want_top), ("bottom", false, want_bottom)] {
            let err = interior_error(r, is_top, [0.0, 0.0], 2.0, want);
            assert!(
                err < 1e-3,
                "{name}: interior {face} stress off −Eα(T_face − T_mean)/(1 − ν) = {want:.5e} Pa by {err:.2e}"
            );
        }
    }
}

/// A panel of its own section under curling: a 64 m × 32 m slab cut by a `continuous` line at
/// x = 0 (no joint: it only delimits the panels) into the 0.25 m, 30 GPa plate and a 0.30 m,
/// 35 GPa panel, bonded, under a linear difference of 10 K. The README: the same difference
/// curls each panel over its own thickness (κ = αΔT/H_p), so its restrained moment is
/// D_p(1 + ν)αΔT/H_p and its faces carry ±E_p αΔT/(2(1 − ν)) whatever H_p (1.765 MPa on the
/// plate, 2.059 MPa on the panel; with the plate's κ = αΔT/H the panel would carry 20 % more,
/// with the plate's E 14 % less). Each panel's middle 4 m × 4 m is 14 m from its edges and the
/// line (ℓ = 0.84 and 1.00 m: 2√2 e^(−14/(1.0·√2)) = 1.4e-4 of the restrained linear stress at
/// most; on a 48 m × 24 m slab, 10 m away, the panel's error was 1.2e-3, as that bound says):
/// within 1e-3, measured below 1e-4.
///
/// The same slab under the asymmetric profile of the test above: the profile is read over each
/// panel's own thickness (its depths in proportion), so each face of the panel carries
/// −E_p α(T_face − T_mean)/(1 − ν) with the profile's own T_face and T_mean (1e-3 again: the
/// disturbance is the linear part's, 1.4e-4 of ±E_pαΔT_eq/(2(1 − ν)), which is smaller than
/// either face's stress here).
#[test]
fn a_panel_of_its_own_section_curls_by_its_own_thickness() {
    let panel = "[[joint]]\nx = 0.0\nkind = \"continuous\"\n[[panel]]\nat = [16.0, 0.0]\nthickness = 0.30\nyoungs_modulus = 35e9\n";
    let dt = 10.0;
    let a = common::run(&slab(
        64.0,
        32.0,
        &format!("[[load]]\nkind = \"temperature\"\ndifference = {dt}\n"),
        panel,
    ));
    let r = &a.report;
    for (name, x, e) in [("plate", -16.0, E), ("panel", 16.0, 35e9)] {
        let want = e * ALPHA * dt / (2.0 * (1.0 - NU));
        for (face, top, sign) in [("bottom", false, 1.0), ("top", true, -1.0)] {
            let err = interior_error(r, top, [x, 0.0], 2.0, sign * want);
            assert!(
                err < 1e-3,
                "{name} {face}: interior stress off ±E_p αΔT/(2(1 − ν)) = {want:.5e} Pa by {err:.2e}"
            );
        }
    }
    let depths = [0.0, 0.05, 0.125, 0.25];
    let temps = [35.0, 28.0, 23.0, 20.0];
    let mean = 24.7;
    let b = common::run(&slab(
        64.0,
        32.0,
        &format!(
            "[[load]]\nkind = \"temperature-profile\"\ndepths = {depths:?}\ntemperatures = {temps:?}\n"
        ),
        panel,
    ));
    for (name, x, e) in [("plate", -16.0, E), ("panel", 16.0, 35e9)] {
        for (face, top, t) in [("top", true, temps[0]), ("bottom", false, temps[3])] {
            let want = restrained(e, t, mean);
            let err = interior_error(&b.report, top, [x, 0.0], 2.0, want);
            assert!(
                err < 1e-3,
                "{name} {face}: interior stress off −E_p α(T_face − T_mean)/(1 − ν) = {want:.5e} Pa by {err:.2e}"
            );
        }
    }
}

/// Moisture keeps only the moment of its shrinkage (README: why its self-equilibrated rest is
/// left out), and the README's recipe for the elastic value — the shrinkage as a temperature
/// profile of ε/α, depths [0, h_s, H], temperatures [ε₀/α, 0, 0] — curls the slab exactly as
/// the moisture load does (two routes to ΔT_eq: the closed form 6ε₀h_s(H/2 − h_s/3)/(αH²) and
/// the profile's piecewise-linear integrals; every w to 1e-10, their round-off) and adds at
/// the faces, at every element, −Eε_nl/(1 − ν) with ε_nl = ε − ε̄ − Δε z/H worked here in
/// strains: ε̄ = ε₀h_s/(2H) = −20 µε, Δε = αΔT_eq = −104 µε, so ε_nl = ε₀ − ε̄ − Δε/2 = −128 µε
/// at the top (+4.52 MPa) and −ε̄ + Δε/2 = −32 µε at the bottom (+1.13 MPa). 1e-9 relative:
/// the same bending, an added constant.
#[test]
fn moisture_as_a_profile_curls_alike_and_adds_its_elastic_rest() {
    let (eps, hs) = (-200e-6, 0.05);
    let moisture = format!("[[load]]\nkind = \"moisture\"\nshrinkage = {eps}\ndepth = {hs}\n");
    let profile = format!(
        "[[load]]\nkind = \"temperature-profile\"\ndepths = [0.0, {hs}, {H}]\ntemperatures = [{}, 0.0, 0.0]\n",
        eps / ALPHA
    );
    let scene = |loads: &str| {
        format!(
            "[plate]\nlength = 4.5\nwidth = 3.6\nthickness = {H}\nyoungs_modulus = {E}\npoissons_ratio = {NU}\nthermal_expansion = {ALPHA}\n\
             [foundation]\nmodel = \"winkler\"\nmodulus = {K}\n{loads}\
             [mesh]\nelements = [36, 28]\n[solver]\ncontact = \"bonded\"\n"
        )
    };
    let (a, b) = (
        common::run(&scene(&moisture)),
        common::run(&scene(&profile)),
    );
    let (wa, wb) = (&a.report.field.w, &b.report.field.w);
    let diff = common::max_abs_diff(wa, wb) / common::max_abs(wa);
    assert!(diff < 1e-10, "w differs by {diff:.2e}");
    let mean = eps * hs / (2.0 * H);
    let delta = 6.0 * eps * hs * (H / 2.0 - hs / 3.0) / (H * H);
    let (nl_top, nl_bottom) = (eps - mean - delta / 2.0, -mean + delta / 2.0);
    assert!((nl_top + 128e-6).abs() < 1e-12 && (nl_bottom + 32e-6).abs() < 1e-12);
    let (ea, eb) = (&a.report.elements, &b.report.elements);
    for (face, fa, fb, nl) in [
        ("top", &ea.top, &eb.top, nl_top),
        ("bottom", &ea.bottom, &eb.bottom, nl_bottom),
    ] {
        let want = -E * nl / (1.0 - NU);
        for i in 0..fa.sx.len() {
            for (what, u, v) in [("σx", fa.sx[i], fb.sx[i]), ("σy", fa.sy[i], fb.sy[i])] {
                assert!(
                    (v - u - want).abs() < 1e-9 * want.abs(),
                    "{face} {what} at element {i}: the profile adds {} Pa, want {want:.5e}",
                    v - u
                );
            }
        }
    }
}
