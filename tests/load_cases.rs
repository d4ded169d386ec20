//! Load cases, combinations, temperature (curling), line loads, voids, Winkler zones and the
//! bearing check (issue 11), each against a reference the code does not produce: Westergaard's
//! curling stress, q/K settlements, the same loads written as one scene, linearity of the bonded
//! problem, the geometry of a segment, the symmetric full model, and hand-computed areas.
//!
//! Units: the SI scenes use a concrete slab (E = 30 GPa, ν = 0.2, H = 0.2 m) on a Winkler
//! subgrade K = 50 MPa/m, so D = E H³ / (12 (1 − ν²)) = 2.083e7 N·m and the radius of relative
//! stiffness ℓ = (D/K)^¼ = 0.803 m. Fields of an SI report are physical (m, Pa, N·m/m).

use crate::common;
use common::node_at;
use liftoff::combination::{self, CombinationRun};
use liftoff::error::Error;
use liftoff::integrals::{line_integrals, patch_integrals};
use liftoff::mesh::Mesh;
use liftoff::method::{Contact, MethodKind};
use liftoff::model::{Model, SymmetryMode};
use liftoff::post::Report;
use liftoff::scene::{FoundationSpec, ModelBuilder, PlateSpec};
use liftoff::{analyse, Analysis, Method, Problem};

const E: f64 = 30e9;
const NU: f64 = 0.2;
const H: f64 = 0.2;
const K: f64 = 5e7;
const ALPHA: f64 = 1e-5;
/// Self-weight of a 0.2 m concrete slab, 24 kN/m³ × 0.2 m.
const SELF_WEIGHT: f64 = 4.8e3;

fn rigidity() -> f64 {
    E * H.powi(3) / (12.0 * (1.0 - NU * NU))
}

/// Radius of relative stiffness ℓ = (D/K)^¼, m.
fn ell() -> f64 {
    (rigidity() / K).powf(0.25)
}

/// The slab above, `length` × `width` m, with α = 1e-5 /K.
fn slab(length: f64, width: f64) -> ModelBuilder {
    let mut plate = PlateSpec::new(length, width, H, E, NU);
    plate.thermal_expansion = Some(ALPHA);
    Model::builder()
        .plate(plate)
        .foundation(FoundationSpec::winkler(K))
}

fn problem(b: &ModelBuilder) -> Problem {
    b.build_problem()
        .unwrap_or_else(|e| panic!("scene rejected: {e}"))
}

fn solve_with(b: &ModelBuilder, method: Method) -> Analysis {
    let mut p = problem(b);
    p.method = method;
    let a = analyse(&p).unwrap_or_else(|e| panic!("solve failed: {e}"));
    assert!(
        a.solution.status.converged(),
        "{}: {}",
        a.solution.method.name(),
        a.solution.status.describe()
    );
    a
}

fn max_abs(a: &[f64]) -> f64 {
    a.iter().map(|x| x.abs()).fold(0.0, f64::max)
}

/// max |a − b| / max |b|.
fn rel_diff(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    let d = a
        .iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    d / max_abs(b).max(f64::MIN_POSITIVE)
}

/// Index of the element whose centre is nearest (x, y).
fn element_at(r: &Report, x: f64, y: f64) -> usize {
    let e = &r.elements;
    (0..e.x.len())
        .min_by(|&a, &b| {
            let da = (e.x[a] - x).hypot(e.y[a] - y);
            let db = (e.x[b] - x).hypot(e.y[b] - y);
            da.total_cmp(&db)
        })
        .unwrap_or(0)
}

/// ∫ p dA of a bilinear nodal field over the whole plate: the trapezoid weights of the grid
/// (exact for bilinear interpolation), computed here from the node coordinates alone.
fn integral(r: &Report, values: &[f64]) -> f64 {
    let f = &r.field;
    let (nx, ny) = (f.nx, f.ny);
    let hx = (f.x[nx] - f.x[0]) / nx as f64;
    let hy = (f.y[(nx + 1) * ny] - f.y[0]) / ny as f64;
    let mut s = 0.0;
    for j in 0..=ny {
        for i in 0..=nx {
            let wx = if i == 0 || i == nx { 0.5 } else { 1.0 };
            let wy = if j == 0 || j == ny { 0.5 } else { 1.0 };
            s += wx * wy * hx * hy * values[i + j * (nx + 1)];
        }
    }
    s
}

// ---------------------------------------------------------------------------------------------
// 1. Temperature: Westergaard's curling stress, and which way a free slab curls.
// ---------------------------------------------------------------------------------------------

/// Westergaard (1927): far from the edges a slab held flat by its foundation cannot curl, so
/// the temperature difference ΔT (top minus bottom) is fully restrained in both directions: the
/// moment is m = D (1 + ν) α ΔT / H and the stress 6 m / H² = E α ΔT / (2 (1 − ν)).
///
/// Sign: top warmer (ΔT > 0) makes the free slab dome (edges down). Held flat, its top — which
/// wants to lengthen — is compressed and its soil-side face is stretched: with the report's
/// convention (positive = tension on the soil side) m > 0.
///
/// The slab is 30 ℓ square: the free edges' disturbance decays like e^(−x/(ℓ√2)), to
/// e^(−10.6) ≈ 2.5e-5 of the thermal moment 15 ℓ in, from each of four edges (measured: 8e-5),
/// so 1e-3 is a tolerance with margin, far below the 200 % error of a wrong sign or the 17 %
/// of a missing (1 + ν).
#[test]
fn bonded_slab_interior_carries_westergaards_curling_stress() {
    let ell = ell();
    let side = 30.0 * ell;
    let dt = 10.0;
    let b = slab(side, side)
        .uniform_load(SELF_WEIGHT)
        .temperature_load(dt)
        .elements(60, 60);
    let a = solve_with(&b, Method::Bonded);
    let stress = E * ALPHA * dt / (2.0 * (1.0 - NU));
    let m_ref = stress * H * H / 6.0;
    let c = element_at(&a.report, 0.0, 0.0);
    let (mx, my, mxy) = (
        a.report.elements.mx[c],
        a.report.elements.my[c],
        a.report.elements.mxy[c],
    );
    eprintln!(
        "Westergaard bonded: m_ref {m_ref:.6e}, mx {mx:.6e}, my {my:.6e}, mxy {mxy:.3e}, stress {:.4e} vs {stress:.4e}",
        6.0 * mx / (H * H)
    );
    for (name, m) in [("mx", mx), ("my", my)] {
        assert!(
            (m - m_ref).abs() < 1e-3 * m_ref,
            "bonded curling: centre {name} = {m:.6e} N·m/m, Westergaard {m_ref:.6e}"
        );
    }
    assert!(
        mxy.abs() < 1e-3 * m_ref,
        "bonded curling: centre mxy = {mxy:e}"
    );
}

/// A night gradient on the same large slab, now unbonded: the edges curl up and the corners
/// lift, but the interior is held flat by the self-weight, so Westergaard's stress holds there
/// with the sign reversed (top cooler: the top is stretched, m < 0). Westergaard assumed
/// exactly this: full contact in the interior.
#[test]
fn unbonded_slab_interior_under_night_gradient_matches_westergaard() {
    let ell = ell();
    let side = 30.0 * ell;
    let dt = -10.0;
    let b = slab(side, side)
        .uniform_load(SELF_WEIGHT)
        .temperature_load(dt)
        .elements(60, 60);
    let a = solve_with(&b, Method::penalty());
    let m_ref = E * ALPHA * dt / (2.0 * (1.0 - NU)) * H * H / 6.0;
    let c = element_at(&a.report, 0.0, 0.0);
    let (mx, my) = (a.report.elements.mx[c], a.report.elements.my[c]);
    let corner = node_at(&a.report, side / 2.0, side / 2.0);
    eprintln!(
        "Westergaard unbonded night: m_ref {m_ref:.6e}, mx {mx:.6e}, my {my:.6e}, corner w {:.3e}, gap {:.3e}, contact {:.4}",
        a.report.field.w[corner], a.report.field.gap[corner], a.report.contact_fraction
    );
    assert!(
        a.report.field.gap[corner] > 0.0 && a.report.field.w[corner] < 0.0,
        "night gradient: the corner lifts"
    );
    for (name, m) in [("mx", mx), ("my", my)] {
        assert!(
            (m - m_ref).abs() < 1e-3 * m_ref.abs(),
            "unbonded night curling: centre {name} = {m:.6e} N·m/m, Westergaard {m_ref:.6e}"
        );
    }
}

/// Self-weight alone on a bonded Winkler slab: the rigid translation w = q/K with σ = q is the
/// exact solution of the discrete problem too (the consistent uniform load is q ∫ f_i, the
/// lumped spring K ∫ f_i, and K annihilates the translation), so every node settles q/K and no
/// element bends: both to round-off.
#[test]
fn self_weight_alone_on_bonded_winkler_settles_uniformly_without_bending() {
    let b = slab(8.0, 6.0).uniform_load(SELF_WEIGHT).elements(16, 12);
    let a = solve_with(&b, Method::Bonded);
    let w_ref = SELF_WEIGHT / K;
    let dw = a
        .report
        .field
        .w
        .iter()
        .map(|w| (w - w_ref).abs())
        .fold(0.0, f64::max);
    let dp = a
        .report
        .field
        .pressure
        .iter()
        .map(|p| (p - SELF_WEIGHT).abs())
        .fold(0.0, f64::max);
    // Moment scale: q ℓ² (what a load varying over ℓ would make).
    let m_scale = SELF_WEIGHT * ell() * ell();
    let e = &a.report.elements;
    let m = max_abs(&e.mx).max(max_abs(&e.my)).max(max_abs(&e.mxy));
    eprintln!("self-weight: |w − q/K| {dw:.2e} of {w_ref:.3e}, |p − q| {dp:.2e}, |m| {m:.2e}");
    assert!(dw < 1e-10 * w_ref, "w − q/K = {dw:e} m");
    assert!(dp < 1e-10 * SELF_WEIGHT, "pressure − q = {dp:e} Pa");
    assert!(m < 1e-10 * m_scale, "moment {m:e} N·m/m under self-weight");
}

/// Which way a free slab curls on unbonded soil. A 4 m slab (5 ℓ) with ΔT = ±20 K: κ = α ΔT / H
/// = 1e-3 /m. As a beam on its ends, curling raises the mid-span by κ (2L)²/8 = 2 mm against a
/// self-weight sag 5 q (2L)⁴ / (384 D) = 0.77 mm, so by day (top warmer, dome) the centre
/// lifts off while the edges bear; at night (top cooler, dish) a 2 m cantilever curls up
/// κ L²/2 = 2 mm against a sag q L⁴/(8 D) = 0.46 mm, so the corners lift while the centre bears.
/// Each check fails if the sign of the temperature load is wrong.
#[test]
fn free_curling_lifts_corners_at_night_and_the_centre_by_day() {
    let side = 4.0;
    let run = |dt: f64| {
        let b = slab(side, side)
            .uniform_load(SELF_WEIGHT)
            .temperature_load(dt)
            .elements(20, 20);
        solve_with(&b, Method::penalty())
    };
    let night = run(-20.0);
    let day = run(20.0);
    for (name, a) in [("night", &night), ("day", &day)] {
        let r = &a.report;
        let c = node_at(r, 0.0, 0.0);
        let k = node_at(r, side / 2.0, side / 2.0);
        eprintln!(
            "{name}: centre w {:.3e} gap {:.3e} p {:.3e}; corner w {:.3e} gap {:.3e} p {:.3e}; contact {:.3}",
            r.field.w[c], r.field.gap[c], r.field.pressure[c], r.field.w[k], r.field.gap[k], r.field.pressure[k], r.contact_fraction
        );
    }
    let (rn, rd) = (&night.report, &day.report);
    let (cn, kn) = (node_at(rn, 0.0, 0.0), node_at(rn, side / 2.0, side / 2.0));
    let (cd, kd) = (node_at(rd, 0.0, 0.0), node_at(rd, side / 2.0, side / 2.0));
    // Night: corners up (w < 0 on Winkler is a gap), centre bearing.
    assert!(
        rn.field.w[kn] < 0.0,
        "night: corner w = {:e}",
        rn.field.w[kn]
    );
    assert!(rn.field.gap[kn] > 0.0, "night: corner gap");
    assert!(
        rn.field.pressure[cn] > SELF_WEIGHT,
        "night: the centre carries more than the self-weight"
    );
    // Day: centre up, corners bearing.
    assert!(
        rd.field.gap[cd] > 0.0,
        "day: centre gap = {:e}",
        rd.field.gap[cd]
    );
    // The penalty leaves a small tension on lifted points (measured −0.8 Pa here).
    assert!(
        rd.field.pressure[cd].abs() < 1e-3 * SELF_WEIGHT,
        "day: no pressure at the lifted centre"
    );
    assert!(
        rd.field.pressure[kd] > SELF_WEIGHT,
        "day: the corner bears more than the self-weight"
    );
}

// ---------------------------------------------------------------------------------------------
// 2–3. Combinations: each is its own contact problem; superposition holds only when bonded.
// ---------------------------------------------------------------------------------------------

/// A void 0.2 mm deep (about twice the self-weight's settlement q/K) under part of the slab:
/// its initial gap, in units of each combination's own P L²/D, differs from one combination to
/// the next.
fn with_void(b: ModelBuilder) -> ModelBuilder {
    b.void([-2.5, -1.0], [0.25, 1.5], 2.0e-4)
}

/// Dead (self-weight), live (a column and a wall) and temperature cases on a 6 × 4 m slab with
/// a void; the column is off both axes, so every combination is solved on the whole plate.
fn cased_slab() -> ModelBuilder {
    with_void(slab(6.0, 4.0))
        .uniform_load(SELF_WEIGHT)
        .in_case("dead")
        .point_load(1.5, 1.0, 2.0e5)
        .in_case("live")
        .line_load([-2.5, -1.2], [2.0, -1.2], 3.0e4)
        .in_case("live")
        .temperature_load(-12.0)
        .in_case("temp")
        .elements(24, 16)
}

/// The loads of `cased_slab` with the factors applied by hand, as one scene without cases.
fn factored_slab(dead: f64, live: f64, temp: f64) -> ModelBuilder {
    let mut b = with_void(slab(6.0, 4.0)).uniform_load(dead * SELF_WEIGHT);
    if live != 0.0 {
        b = b
            .point_load(1.5, 1.0, live * 2.0e5)
            .line_load([-2.5, -1.2], [2.0, -1.2], live * 3.0e4);
    }
    if temp != 0.0 {
        b = b.temperature_load(temp * -12.0);
    }
    b.elements(24, 16)
}

fn run_combinations(b: &ModelBuilder, method: &Method) -> Vec<CombinationRun> {
    let mut p = problem(b);
    p.method = method.clone();
    let runs = combination::analyse(&p, &liftoff::Monitor::NONE)
        .unwrap_or_else(|e| panic!("combinations failed: {e}"))
        .runs;
    for r in &runs {
        match &r.outcome {
            Ok(o) => assert!(
                o.solution.status.converged(),
                "combination {} ({}): {}",
                r.name,
                method.name(),
                o.solution.status.describe()
            ),
            Err(e) => panic!("combination {} ({}): {e}", r.name, method.name()),
        }
    }
    runs
}

fn report_of(run: &CombinationRun) -> &Report {
    match &run.outcome {
        Ok(o) => &o.report,
        Err(e) => panic!("combination {}: {e}", run.name),
    }
}

/// A combination is exactly the scene its factored loads make on their own: the same P, the
/// same operators, the same contact problem. Both methods must then return the same numbers up
/// to the round-off of factoring the loads in another order (1e-10 relative; a combination
/// solved with the wrong factors, P or load vector differs by percents).
#[test]
fn a_combination_equals_its_factored_loads_as_one_scene() {
    let combos = [
        ("ULS", 1.35, 1.5, 0.9),
        ("SLS", 1.0, 1.0, 0.0),
        ("night", 1.0, 0.0, 1.0),
    ];
    let mut b = cased_slab();
    for (name, dead, live, temp) in combos {
        let mut f = vec![("dead", dead)];
        if live != 0.0 {
            f.push(("live", live));
        }
        if temp != 0.0 {
            f.push(("temp", temp));
        }
        b = b.combination(name, &f);
    }
    for method in [Method::penalty(), Method::qp()] {
        let runs = run_combinations(&b, &method);
        assert_eq!(runs.len(), combos.len());
        for (run, &(name, dead, live, temp)) in runs.iter().zip(&combos) {
            assert_eq!(run.name, name);
            let single = solve_with(&factored_slab(dead, live, temp), method.clone());
            let (rc, rs) = (report_of(run), &single.report);
            let open = node_at(rs, -1.75, 0.75);
            eprintln!(
                "{} {name}: contact {:.3}, gap in the void {:.2e} m",
                method.name(),
                rs.contact_fraction,
                rs.field.gap[open]
            );
            assert!(
                rs.field.gap[open] > 0.0,
                "{name}: the void stays partly open"
            );
            let fields: [(&str, &[f64], &[f64]); 7] = [
                ("V", &rc.field.v, &rs.field.v),
                ("gap", &rc.field.gap, &rs.field.gap),
                ("σ", &rc.field.sigma, &rs.field.sigma),
                ("w", &rc.field.w, &rs.field.w),
                ("pressure", &rc.field.pressure, &rs.field.pressure),
                ("mx", &rc.elements.mx, &rs.elements.mx),
                ("my", &rc.elements.my, &rs.elements.my),
            ];
            for (what, c, s) in fields {
                let d = rel_diff(c, s);
                eprintln!("{} {name}: {what} differs by {d:.2e}", method.name());
                assert!(
                    d < 1e-10,
                    "{} combination {name}: {what} differs from the single scene by {d:e}",
                    method.name()
                );
            }
            // P: a quarter of the factored resultant, by hand (the line is 4.5 m long).
            let p_ref = (dead * SELF_WEIGHT * 24.0 + live * (2.0e5 + 3.0e4 * 4.5)) / 4.0;
            assert!(
                (run.model.load_scale - p_ref).abs() < 1e-12 * p_ref,
                "combination {name}: P = {} N, by hand {p_ref} N",
                run.model.load_scale
            );
        }
    }
}

/// A tensionless foundation does not superpose. Self-weight alone bears everywhere; a column
/// 0.5 m from the edge alone tips the slab and lifts most of it (the bonded answer of that case
/// pulls on half the slab); together, the self-weight holds all but a strip of the far edge
/// down. The contact regions of the three problems differ, so the unbonded answers of the two
/// cases, added, must miss the unbonded answer of their sum by far more than round-off
/// (asserted > 10 % of the peak). The control: the bonded problem is linear, so its answers add
/// up to round-off (1e-10).
#[test]
fn unbonded_cases_do_not_superpose_but_bonded_ones_do() {
    let b = slab(6.0, 4.0)
        .uniform_load(SELF_WEIGHT)
        .in_case("dead")
        .point_load(2.5, 0.0, 2.0e5)
        .in_case("column")
        .elements(24, 16)
        .combination("dead", &[("dead", 1.0)])
        .combination("column", &[("column", 1.0)])
        .combination("both", &[("dead", 1.0), ("column", 1.0)]);
    let mismatch = |runs: &[CombinationRun]| {
        let (a, c, both) = (
            report_of(&runs[0]),
            report_of(&runs[1]),
            report_of(&runs[2]),
        );
        let sum = |f: fn(&Report) -> &[f64]| -> Vec<f64> {
            f(a).iter().zip(f(c)).map(|(x, y)| x + y).collect()
        };
        let dw = rel_diff(&sum(|r| &r.field.w), &both.field.w);
        let dp = rel_diff(&sum(|r| &r.field.pressure), &both.field.pressure);
        let dm = rel_diff(&sum(|r| &r.elements.mx), &both.elements.mx);
        (dw, dp, dm, [a, c, both].map(|r| r.contact_fraction))
    };
    let bonded = mismatch(&run_combinations(&b, &Method::Bonded));
    eprintln!("bonded superposition: {bonded:?}");
    assert!(
        bonded.0 < 1e-10 && bonded.1 < 1e-10 && bonded.2 < 1e-10,
        "bonded answers must superpose: w {:e}, pressure {:e}, mx {:e}",
        bonded.0,
        bonded.1,
        bonded.2
    );
    for method in [Method::penalty(), Method::qp()] {
        let (dw, dp, dm, contact) = mismatch(&run_combinations(&b, &method));
        eprintln!(
            "{} superposition: w {dw:.3}, pressure {dp:.3}, mx {dm:.3}, contact {contact:?}",
            method.name()
        );
        // The contact regions differ: everything bears under self-weight alone, under half
        // of the slab or less with the column alone, and under most but not all together.
        assert!(contact[0] > 0.999, "self-weight alone bears everywhere");
        assert!(contact[1] < 0.5, "the column alone lifts most of the slab");
        assert!(
            contact[2] > 0.5 && contact[2] < 0.99,
            "together, the far edge lifts"
        );
        for (what, d) in [("w", dw), ("pressure", dp), ("mx", dm)] {
            assert!(
                d > 0.1,
                "{}: unbonded {what} superposes to {d:e}: contact should break it",
                method.name()
            );
        }
    }
}

// ---------------------------------------------------------------------------------------------
// 4. Voids.
// ---------------------------------------------------------------------------------------------

/// A void wider than the bending wavelength under a uniform load. On Winkler soil the
/// deflection near a disturbance oscillates with wavelength 2π √2 ℓ ≈ 8.9 ℓ; an 8 m void
/// (≈ 10 ℓ) in a 24 m slab leaves the plate over its middle spanning freely, well away from the
/// slab's edges. Depth 0.04 m = 200 q/K: a simply supported 8 m square plate would sag
/// 0.00406 q a⁴ / D ≈ 8 mm (Timoshenko's table), so the void stays open with a margin of 5.
///
/// Checks: no pressure at any node whose shape function lies inside the void (QP: its
/// interior-point tolerance, 1e-6 of q; penalty: the residual tension of its penalty springs,
/// which the automatic ε̄ drives below 1e-5 of the peak pressure, so 1e-4 of q); there the gap
/// is the void depth plus the soil's settlement p/K minus the deflection (the gap is measured
/// from the lowered soil surface; depth as written, in m); equilibrium ∫ p dA = q A with the
/// integral taken by the trapezoid rule here; and both methods agree.
#[test]
fn a_wide_deep_void_carries_nothing_and_stays_open() {
    let (side, half_void, q) = (24.0, 4.0, 1.0e4);
    let depth = 200.0 * q / K;
    let b = slab(side, side)
        .uniform_load(q)
        .void([-half_void, half_void], [-half_void, half_void], depth)
        .elements(60, 60);
    let pen = solve_with(&b, Method::penalty());
    let qp = solve_with(&b, Method::qp());
    let h = side / 60.0;
    let ell = ell();
    for (a, p_tol) in [(&pen, 1e-4 * q), (&qp, 1e-6 * q)] {
        let r = &a.report;
        let f = &r.field;
        let name = a.solution.method.name();
        assert_eq!(
            a.summary.symmetry, "quarter",
            "{name}: a centred void keeps the quarter"
        );
        let mut inside = 0;
        let mut p_max: f64 = 0.0;
        let mut gap_err: f64 = 0.0;
        let mut gap_min = f64::INFINITY;
        for n in 0..f.x.len() {
            let d = half_void - f.x[n].abs().max(f.y[n].abs()); // distance inside the void
            if d >= h - 1e-9 {
                inside += 1;
                p_max = p_max.max(f.pressure[n].abs());
                gap_min = gap_min.min(f.gap[n]);
                // Winkler: gap = settlement − w + depth = p/K − w + depth.
                let expected = f.pressure[n] / K - f.w[n] + depth;
                gap_err = gap_err.max((f.gap[n] - expected).abs());
            }
            if d >= ell {
                assert!(f.gap[n] > 0.0, "{name}: gap at ({}, {})", f.x[n], f.y[n]);
            }
        }
        let load = q * side * side;
        let reaction = integral(r, &f.pressure);
        let w_void = f.w[node_at(r, 0.0, 0.0)];
        eprintln!(
            "void {name}: {inside} nodes inside, max |p| {p_max:.2e} Pa, min gap {gap_min:.3e} m, |gap − (d + p/K − w)| {gap_err:.2e}, w centre {w_void:.3e}, reaction error {:.2e}, peak p {:.3e}",
            (reaction - load).abs() / load,
            r.pressure_max
        );
        assert_eq!(inside, 19 * 19, "{name}: nodes inside the void");
        assert!(
            p_max < p_tol,
            "{name}: pressure {p_max:e} Pa inside the void"
        );
        assert!(gap_min > 0.0, "{name}: the plate touches the void's bottom");
        assert!(
            gap_err < 1e-9 * depth,
            "{name}: gap ≠ depth + p/K − w inside the void ({gap_err:e} m)"
        );
        assert!(
            (reaction - load).abs() < 1e-8 * load,
            "{name}: ∫ p dA = {reaction} N, load {load} N"
        );
        // The plate spans the void: its edges carry the void's share of the load.
        assert!(
            r.pressure_max > 1.5 * q,
            "{name}: no edge reaction around the void"
        );
    }
    let dw = rel_diff(&pen.report.field.w, &qp.report.field.w);
    let dp = rel_diff(&pen.report.field.pressure, &qp.report.field.pressure);
    eprintln!("void penalty vs qp: w {dw:.2e}, pressure {dp:.2e}");
    // Measured 6e-6: the penalty's O(ε̄) error at the automatic ε̄.
    assert!(
        dw < 1e-4 && dp < 1e-4,
        "penalty vs QP over a void: w {dw:e}, p {dp:e}"
    );
}

// ---------------------------------------------------------------------------------------------
// 5. Line loads.
// ---------------------------------------------------------------------------------------------

/// (node, value) pairs summed into a vector over the mesh's nodes.
fn dense(mesh: &Mesh, pairs: Vec<(usize, f64)>) -> Vec<f64> {
    let mut v = vec![0.0; mesh.n_nodes()];
    for (n, x) in pairs {
        v[n] += x;
    }
    v
}

/// Σ v_i, Σ v_i x_i, Σ v_i y_i of a nodal vector.
fn moments(mesh: &Mesh, v: &[f64]) -> [f64; 3] {
    let mut m = [0.0; 3];
    for (n, &x) in v.iter().enumerate() {
        let (px, py) = mesh.node_xy(n);
        m[0] += x;
        m[1] += x * px;
        m[2] += x * py;
    }
    m
}

/// The consistent nodal vector of a unit line load, ∫ f_i ds, sums to the segment's length
/// (partition of unity) and its first moments Σ x_i ∫ f_i ds = ∫ x ds put the resultant at the
/// segment's midpoint (bilinear shape functions reproduce x and y exactly). Oblique segments
/// crossing many element lines, one lying on a grid line, one through grid vertices, one
/// inside a single element; on a half model, the part of a segment on the kept side, and half
/// of one lying on the symmetry line. Reference: the segment's geometry; round-off 1e-13.
#[test]
fn line_load_vector_has_the_segments_resultant_and_centroid() {
    // μ = 0.6 plate, 10 × 6 elements of 0.2 × 0.2 (unit system: lengths / L).
    let full = Mesh::new(2.0, 1.2, [10, 6], false, false);
    let segments: [([f64; 2], [f64; 2]); 5] = [
        ([-0.83, -0.41], [0.67, 0.52]),
        ([0.95, 0.2], [-0.9, 0.2]),
        ([-1.0, -0.6], [1.0, 0.6]),
        ([0.31, 0.05], [0.38, 0.12]),
        ([-1.0, 0.6], [1.0, 0.6]),
    ];
    let check = |mesh: &Mesh, from: [f64; 2], to: [f64; 2], want: [f64; 3], what: &str| {
        let v = dense(mesh, line_integrals(mesh, from, to));
        let got = moments(mesh, &v);
        for k in 0..3 {
            assert!(
                (got[k] - want[k]).abs() < 1e-13 * want[0],
                "line {from:?} → {to:?} ({what}): moment {k} = {}, want {}",
                got[k],
                want[k]
            );
        }
    };
    for (from, to) in segments {
        let len = (to[0] - from[0]).hypot(to[1] - from[1]);
        let mid = [0.5 * (from[0] + to[0]), 0.5 * (from[1] + to[1])];
        check(&full, from, to, [len, len * mid[0], len * mid[1]], "full");
    }
    // Half model about x = 0 (keeps x ≥ 0): the part from x = 0 on.
    let half = Mesh::new(2.0, 1.2, [10, 6], true, false);
    let (from, to): ([f64; 2], [f64; 2]) = ([-0.5, 0.1], [0.7, 0.34]);
    let s0 = 0.5 / 1.2; // where the segment crosses x = 0
    let cut = [0.0, from[1] + s0 * (to[1] - from[1])];
    let len = (to[0] - cut[0]).hypot(to[1] - cut[1]);
    check(
        &half,
        from,
        to,
        [len, len * 0.5 * to[0], len * 0.5 * (cut[1] + to[1])],
        "half, crossing",
    );
    // On the symmetry line: half of it belongs to the model.
    check(
        &half,
        [0.0, -0.5],
        [0.0, 0.3],
        [0.4, 0.0, 0.4 * -0.1],
        "half, on the line",
    );
}

/// A line load is the limit of a thin patch of width δ carrying the same force per length
/// (pressure q/δ) on the same mesh. Inside an element row the shape functions are linear
/// across the strip, so its average equals the value on the line: the vectors agree to
/// round-off for any δ. On a grid line the strip straddles the kink of the nodes' hat
/// functions: their average over the strip is 1 − δ/(4h) on the line and δ/(8h) next to it,
/// so the largest difference is exactly δ/(4h) of the largest entry — linear in δ, to zero.
#[test]
fn line_load_is_the_limit_of_a_thin_patch() {
    let mesh = Mesh::new(2.0, 1.2, [10, 6], false, false);
    let h = 0.2;
    let (x0, x1) = (-0.7, 0.5);
    // Largest difference between the strip's vector (divided by δ) and the line's, relative.
    let mismatch = |y0: f64, delta: f64| {
        let y = [y0 - 0.5 * delta, y0 + 0.5 * delta];
        let patch = dense(&mesh, patch_integrals(&mesh, [x0, x1], y));
        let patch: Vec<f64> = patch.iter().map(|a| a / delta).collect();
        let line = dense(&mesh, line_integrals(&mesh, [x0, y0], [x1, y0]));
        rel_diff(&patch, &line)
    };
    for delta in [0.1, 0.01, 1e-4] {
        // The strip's edges y0 ± δ/2 are rounded to ~1e-16 (lengths are O(1) here), which the
        // division by δ turns into ~1e-16/δ of the average: 1e-12 at δ = 1e-4.
        let round_off = 1e-16 / delta;
        let d = mismatch(0.13, delta);
        eprintln!("strip inside a row, δ = {delta}: {d:.2e}");
        assert!(
            d < 10.0 * round_off,
            "thin patch vs line inside a row, δ = {delta}: {d:e}"
        );
        let d = mismatch(0.2, delta);
        let want = delta / (4.0 * h);
        eprintln!("strip on a grid line, δ = {delta}: {d:.6e}, δ/(4h) = {want:.6e}");
        assert!(
            (d - want).abs() < 10.0 * round_off,
            "thin patch vs line on a grid line, δ = {delta}: {d:e}, want δ/(4h) = {want:e}"
        );
    }
}

/// The same limit on whole solves: a 100 kN/m line load 0.4 m from the edge of a 6 × 4 m slab
/// (it lifts the far side) and the 5 cm strip of 2 MPa that carries it, with 25 cm elements,
/// the strip inside an element row: the load vectors agree to round-off (previous test), so
/// the unbonded answers must too (1e-10: the inputs differ only in their last bits).
#[test]
fn a_line_load_scene_matches_its_thin_patch_scene() {
    let (y0, delta, q_line) = (1.6, 0.05, 1.0e5);
    let base = || slab(6.0, 4.0).uniform_load(SELF_WEIGHT).elements(24, 16);
    let line = base().line_load([-2.2, y0], [1.9, y0], q_line);
    let strip = base().patch_load(
        [-2.2, 1.9],
        [y0 - 0.5 * delta, y0 + 0.5 * delta],
        q_line / delta,
    );
    for method in [Method::penalty(), Method::qp()] {
        let a = solve_with(&line, method.clone());
        let b = solve_with(&strip, method.clone());
        let dw = rel_diff(&a.report.field.w, &b.report.field.w);
        let dp = rel_diff(&a.report.field.pressure, &b.report.field.pressure);
        eprintln!(
            "{} line vs strip: w {dw:.2e}, p {dp:.2e}, contact {:.3}",
            method.name(),
            a.report.contact_fraction
        );
        assert!(
            a.report.contact_fraction < 0.9,
            "the line load should lift part of the slab"
        );
        assert!(
            dw < 1e-10 && dp < 1e-10,
            "{}: line vs thin strip: w {dw:e}, pressure {dp:e}",
            method.name()
        );
    }
}

/// A wall along the symmetry line x = 0 of a half model: the model carries half of it (the
/// half on its side of the line) and must reproduce the whole-plate model. A column on the
/// wall off the y axis keeps the scene from being quartered. The full model is the reference;
/// bonded and penalty solve the same equations (1e-10), the QP to its tolerance (1e-7).
#[test]
fn a_wall_on_the_symmetry_line_of_a_half_model_matches_the_full_model() {
    let b = slab(6.0, 4.0)
        .uniform_load(SELF_WEIGHT)
        .line_load([0.0, -2.0], [0.0, 2.0], 5.0e4)
        .point_load(0.0, 1.0, 1.0e5)
        .elements(24, 16);
    let full = b.clone().symmetry(SymmetryMode::None);
    for (method, tol) in [
        (Method::Bonded, 1e-10),
        (Method::penalty(), 1e-10),
        (Method::qp(), 1e-7),
    ] {
        let h = solve_with(&b, method.clone());
        let f = solve_with(&full, method.clone());
        assert_eq!(
            h.summary.symmetry,
            "half-x",
            "{}: wall on x = 0",
            method.name()
        );
        assert_eq!(f.summary.symmetry, "full");
        let dw = rel_diff(&h.report.field.w, &f.report.field.w);
        let dp = rel_diff(&h.report.field.pressure, &f.report.field.pressure);
        let dm = rel_diff(&h.report.elements.mx, &f.report.elements.mx);
        eprintln!(
            "{} half vs full: w {dw:.2e}, p {dp:.2e}, mx {dm:.2e}, contact {:.3}",
            method.name(),
            f.report.contact_fraction
        );
        assert!(
            dw < tol && dp < tol && dm < tol,
            "{}: half vs full model: w {dw:e}, pressure {dp:e}, mx {dm:e}",
            method.name()
        );
        // The wall's load is all there: 4 × 50 kN + 100 kN + self-weight.
        let load = 4.0 * 5.0e4 + 1.0e5 + SELF_WEIGHT * 24.0;
        let reaction = integral(&h.report, &h.report.field.pressure);
        assert!(
            (reaction - load).abs() < 1e-8 * load,
            "{}: half model reaction {reaction} N, load {load} N",
            method.name()
        );
    }
}

// ---------------------------------------------------------------------------------------------
// 6. Winkler zones.
// ---------------------------------------------------------------------------------------------

/// A zone of modulus K2 over the whole plate is the uniform subgrade K2: the zoned compliance
/// (1/K) ∫ f_i (K/K2) equals (1/K2) ∫ f_i up to round-off. A column near the edge lifts part of
/// the slab, so the unbonded answers test the contact problem too. Bonded and QP solve the same
/// equations (1e-10; QP to its tolerance, 1e-7); the penalty iteration scales its springs by
/// the scene's reference modulus K, not K2, so it agrees to its O(ε̄) error (1e-4).
#[test]
fn a_zone_over_the_whole_plate_is_the_uniform_subgrade() {
    let k2 = 2.0e7;
    let loads = |b: ModelBuilder| {
        b.uniform_load(SELF_WEIGHT)
            .point_load(2.5, 0.5, 2.0e5)
            .elements(24, 16)
    };
    let zoned = loads(slab(6.0, 4.0).zone([-3.0, 3.0], [-2.0, 2.0], k2));
    let mut plate = PlateSpec::new(6.0, 4.0, H, E, NU);
    plate.thermal_expansion = Some(ALPHA);
    let uniform = loads(
        Model::builder()
            .plate(plate)
            .foundation(FoundationSpec::winkler(k2)),
    );
    for (method, tol) in [
        (Method::Bonded, 1e-10),
        (Method::qp(), 1e-7),
        (Method::penalty(), 1e-4),
    ] {
        let z = solve_with(&zoned, method.clone());
        let u = solve_with(&uniform, method.clone());
        let dw = rel_diff(&z.report.field.w, &u.report.field.w);
        let dp = rel_diff(&z.report.field.pressure, &u.report.field.pressure);
        eprintln!(
            "{} zone everywhere vs K2: w {dw:.2e}, p {dp:.2e}, contact {:.3}",
            method.name(),
            u.report.contact_fraction
        );
        assert!(
            dw < tol && dp < tol,
            "{}: whole-plate zone vs uniform K2: w {dw:e}, pressure {dp:e}",
            method.name()
        );
    }
}

/// A soft zone under one side settles that side more. Bonded, uniform load q on a 40 × 16 m
/// slab whose right half rests on K2 = K/2: far from the zone's edge each half translates
/// rigidly, w = q/K on the left and q/K2 on the right, pressure q on both. The step's
/// disturbance is at most the jump q/K2 − q/K = q/K and decays like √2 e^(−x/(√2 ℓ_i)), slowest
/// on the soft side (ℓ2 = 2^¼ ℓ); 10 m from the step (12.4 ℓ, 10.5 ℓ2) that is below
/// 9e-4 q/K, so 2e-3 of q/K bounds both deflections (and, times K or K2, the pressures).
#[test]
fn a_soft_zone_settles_its_side_by_q_over_its_modulus() {
    let (q, k2) = (1.0e4, 0.5 * K);
    let b = slab(40.0, 16.0)
        .uniform_load(q)
        .zone([0.0, 20.0], [-8.0, 8.0], k2)
        .elements(100, 40);
    let a = solve_with(&b, Method::Bonded);
    assert_eq!(
        a.summary.symmetry, "half-y",
        "a zone on one side keeps only y = 0"
    );
    let r = &a.report;
    let (left, right) = (node_at(r, -10.0, 0.0), node_at(r, 10.0, 0.0));
    let (wl, wr) = (r.field.w[left], r.field.w[right]);
    eprintln!(
        "soft zone: w left {wl:.6e} (q/K {:.6e}), right {wr:.6e} (q/K2 {:.6e}), ratio {:.5}, p {:.2} {:.2}",
        q / K,
        q / k2,
        wr / wl,
        r.field.pressure[left],
        r.field.pressure[right]
    );
    assert!(
        (wl - q / K).abs() < 2e-3 * q / K,
        "stiff side: w = {wl:e}, q/K = {:e}",
        q / K
    );
    assert!(
        (wr - q / k2).abs() < 2e-3 * q / K,
        "soft side: w = {wr:e}, q/K2 = {:e}",
        q / k2
    );
    for (side, n) in [("stiff", left), ("soft", right)] {
        let p = r.field.pressure[n];
        assert!(
            (p - q).abs() < 2e-3 * q,
            "{side} side: pressure {p} Pa, q = {q}"
        );
    }
}

// ---------------------------------------------------------------------------------------------
// 7. Symmetry with voids and zones.
// ---------------------------------------------------------------------------------------------

/// Voids and zones enter the symmetry decision like loads: one off an axis turns that
/// reduction off, a mirrored pair (same depth, same modulus) keeps it, a pair that differs
/// does not. Self-weight alone would quarter the 6 × 4 m slab.
#[test]
fn voids_and_zones_off_an_axis_turn_the_reduction_off() {
    let base = || slab(6.0, 4.0).uniform_load(SELF_WEIGHT).elements(24, 16);
    let d = 1e-3;
    let cases: [(&str, ModelBuilder, &str); 10] = [
        ("no void", base(), "quarter"),
        (
            "centred void",
            base().void([-1.0, 1.0], [-0.5, 0.5], d),
            "quarter",
        ),
        (
            "void right of x = 0",
            base().void([0.5, 1.5], [-0.5, 0.5], d),
            "half-y",
        ),
        (
            "void above y = 0",
            base().void([-0.5, 0.5], [0.2, 0.8], d),
            "half-x",
        ),
        (
            "void off both",
            base().void([0.5, 1.5], [0.2, 0.8], d),
            "full",
        ),
        (
            "mirrored voids",
            base()
                .void([0.5, 1.5], [-0.5, 0.5], d)
                .void([-1.5, -0.5], [-0.5, 0.5], d),
            "quarter",
        ),
        (
            "mirrored voids, other depth",
            base()
                .void([0.5, 1.5], [-0.5, 0.5], d)
                .void([-1.5, -0.5], [-0.5, 0.5], 2.0 * d),
            "half-y",
        ),
        (
            "zone right of x = 0",
            base().zone([1.0, 3.0], [-2.0, 2.0], 2e7),
            "half-y",
        ),
        (
            "mirrored zones",
            base()
                .zone([1.0, 3.0], [-2.0, 2.0], 2e7)
                .zone([-3.0, -1.0], [-2.0, 2.0], 2e7),
            "quarter",
        ),
        (
            "mirrored zones, other modulus",
            base()
                .zone([1.0, 3.0], [-2.0, 2.0], 2e7)
                .zone([-3.0, -1.0], [-2.0, 2.0], 3e7),
            "half-y",
        ),
    ];
    for (what, b, want) in cases {
        let model = b
            .build()
            .unwrap_or_else(|e| panic!("{what}: scene rejected: {e}"));
        let (mesh, _) = model.plan_mesh();
        assert_eq!(mesh.symmetry_name(), want, "{what}: planned mesh");
    }
    // And the solve uses it: the summary of an off-axis void.
    let a = solve_with(&base().void([0.5, 1.5], [0.2, 0.8], d), Method::penalty());
    assert_eq!(
        a.summary.symmetry, "full",
        "off-axis void: the solve's model"
    );
    assert!(!a.ops.mesh.sym_x && !a.ops.mesh.sym_y);
}

/// A quarter model with a mirrored pair of voids and of zones must give the whole-plate
/// model's answer: the reduced model integrates the voids' initial gap and the zones'
/// compliance over its own part only. Same equations, penalty iteration (1e-10).
#[test]
fn mirrored_voids_and_zones_in_a_quarter_model_match_the_full_model() {
    let q = 2.0e4;
    let b = slab(6.0, 4.0)
        .uniform_load(q)
        .void([0.7, 1.6], [-0.6, 0.6], 2.0 * q / K)
        .void([-1.6, -0.7], [-0.6, 0.6], 2.0 * q / K)
        .zone([-3.0, -2.1], [-2.0, 2.0], 1.5e7)
        .zone([2.1, 3.0], [-2.0, 2.0], 1.5e7)
        .elements(24, 16);
    let quarter = solve_with(&b, Method::penalty());
    let full = solve_with(&b.clone().symmetry(SymmetryMode::None), Method::penalty());
    assert_eq!(quarter.summary.symmetry, "quarter");
    assert_eq!(full.summary.symmetry, "full");
    let dw = rel_diff(&quarter.report.field.w, &full.report.field.w);
    let dp = rel_diff(&quarter.report.field.pressure, &full.report.field.pressure);
    let dg = rel_diff(&quarter.report.field.gap, &full.report.field.gap);
    eprintln!(
        "quarter vs full with voids and zones: w {dw:.2e}, p {dp:.2e}, gap {dg:.2e}, contact {:.3}",
        full.report.contact_fraction
    );
    // The voids (2 q/K deep) stay partly open: some contact there, some gap.
    assert!(full.report.contact_fraction < 1.0 && max_abs(&full.report.field.gap) > 0.0);
    assert!(
        dw < 1e-10 && dp < 1e-10 && dg < 1e-10,
        "quarter vs full: w {dw:e}, pressure {dp:e}, gap {dg:e}"
    );
}

// ---------------------------------------------------------------------------------------------
// 8. Errors: typed, naming the field.
// ---------------------------------------------------------------------------------------------

/// The field and message of an `Error::Invalid`, or a panic naming what came instead.
fn invalid<T>(what: &str, r: liftoff::Result<T>) -> (String, String) {
    match r {
        Err(Error::Invalid { field, message }) => (field, message),
        Err(e) => panic!("{what}: expected Error::Invalid, got {e}"),
        Ok(_) => panic!("{what}: accepted"),
    }
}

#[test]
fn malformed_cases_combinations_voids_and_zones_are_rejected_with_their_field() {
    let q = SELF_WEIGHT;
    let base = || {
        slab(6.0, 4.0)
            .uniform_load(q)
            .in_case("dead")
            .elements(8, 8)
    };
    let mut no_alpha = Model::builder()
        .plate(PlateSpec::new(6.0, 4.0, H, E, NU))
        .foundation(FoundationSpec::winkler(K));
    no_alpha = no_alpha.uniform_load(q).temperature_load(10.0);
    let cases: Vec<(&str, ModelBuilder, &str, &[&str])> = vec![
        (
            "combination naming an unknown case",
            base().combination("ULS", &[("dead", 1.35), ("live", 1.5)]),
            "combination[0].factors",
            &["`live`", "dead"],
        ),
        (
            "temperature load without thermal_expansion",
            no_alpha,
            "plate.thermal_expansion",
            &["load[1]", "1/K"],
        ),
        (
            "zone on a half-space",
            Model::builder()
                .plate(PlateSpec::new(6.0, 4.0, H, E, NU))
                .foundation(FoundationSpec::half_space(1e8, 0.3))
                .uniform_load(q)
                .zone([0.0, 1.0], [0.0, 1.0], 2e7),
            "foundation.zone[0]",
            &["Winkler"],
        ),
        (
            "void with bonded contact",
            base()
                .void([0.0, 1.0], [0.0, 1.0], 1e-3)
                .solver(Contact::Bonded, MethodKind::Penalty),
            "void",
            &["unbonded"],
        ),
        (
            "overlapping zones",
            base()
                .zone([0.0, 1.0], [0.0, 1.0], 2e7)
                .zone([0.5, 1.5], [0.5, 1.5], 3e7),
            "foundation.zone[1]",
            &["overlaps foundation.zone[0]"],
        ),
        (
            "duplicate combination names",
            base()
                .combination("ULS", &[("dead", 1.35)])
                .combination("ULS", &[("dead", 1.0)]),
            "combination[1].name",
            &["`ULS`", "combination[0]"],
        ),
        (
            "a combination of a temperature case alone",
            base()
                .temperature_load(10.0)
                .in_case("temp")
                .combination("night", &[("temp", 1.0)]),
            "load",
            &["combination `night`", "self-weight"],
        ),
    ];
    for (what, b, field, needles) in cases {
        let (f, m) = invalid(what, b.build_problem());
        eprintln!("{what}: `{f}`: {m}");
        assert_eq!(f, field, "{what}: field (message: {m})");
        for n in needles {
            assert!(m.contains(n), "{what}: message lacks `{n}`: {m}");
        }
    }
}

/// A void far deeper than the plate can settle is refused, and the message gives the scale it
/// was compared with: the mean settlement under the loads, q/K = 9.6e-5 m here, in metres.
/// A dimensionless scene states it in the unit of V of its loads.
#[test]
fn a_void_far_deeper_than_the_settlement_is_refused_with_the_scale() {
    let settlement = SELF_WEIGHT / K;
    let b = slab(6.0, 4.0)
        .uniform_load(SELF_WEIGHT)
        .void([0.0, 1.0], [0.0, 1.0], 2000.0 * settlement)
        .elements(8, 8);
    let (f, m) = invalid("deep void", b.build_problem());
    eprintln!("deep void: `{f}`: {m}");
    assert_eq!(f, "void[0].depth");
    let scale = format!("{settlement:.3e} m");
    assert!(
        m.contains(&scale),
        "message lacks the settlement {scale}: {m}"
    );
    assert!(m.contains("2000 times"), "message lacks the ratio: {m}");
    // A void 10 times the settlement is accepted.
    slab(6.0, 4.0)
        .uniform_load(SELF_WEIGHT)
        .void([0.0, 1.0], [0.0, 1.0], 10.0 * settlement)
        .elements(8, 8)
        .build_problem()
        .unwrap_or_else(|e| panic!("a 10 q/K void: {e}"));
    // Dimensionless: Γ_w = 1e-3, μ = 1, a unit uniform load on the 2 × 2 plate: resultant 4, so
    // P = 1 in the loads' unit and σ = μ L² r / P = 1; the Winkler settlement is V = Γ_w σ =
    // 1e-3 (times P = 1 in the loads' unit of V), and a depth of 5 is 5000 times that.
    let text = r#"
[dimensionless]
foundation = "winkler"
gamma = 1e-3
delta = 1e-3
mu = 1.0
nu = 0.3
[[load]]
kind = "uniform"
pressure = 1.0
[[void]]
x = [0.0, 0.5]
y = [0.0, 0.5]
depth = 5.0
"#;
    let (f, m) = invalid("deep void, dimensionless", Problem::from_toml(text));
    eprintln!("deep void dimensionless: `{f}`: {m}");
    assert_eq!(f, "void[0].depth");
    for n in ["1.000e-3 (loads' unit of V)", "5000 times"] {
        assert!(
            m.contains(n),
            "dimensionless deep void: message lacks `{n}`: {m}"
        );
    }
}

// ---------------------------------------------------------------------------------------------
// 9. Bearing check.
// ---------------------------------------------------------------------------------------------

/// Bonded self-weight on a uniform Winkler slab presses exactly q everywhere (see above): an
/// allowable pressure 1 % below q is exceeded over the whole plate (24 m²), 1 % above it
/// nowhere, with utilisation q / allowable. All to round-off.
#[test]
fn bearing_under_uniform_pressure_is_all_or_nothing() {
    let q = SELF_WEIGHT;
    for (allowable, area) in [(0.99 * q, 24.0), (1.01 * q, 0.0)] {
        let b = slab(6.0, 4.0)
            .allowable_pressure(allowable)
            .uniform_load(q)
            .elements(12, 8);
        let a = solve_with(&b, Method::Bonded);
        let bearing = a
            .report
            .bearing
            .unwrap_or_else(|| panic!("no bearing check with allowable {allowable}"));
        eprintln!("uniform bearing: {bearing:?}");
        assert!((bearing.allowable - allowable).abs() < 1e-12 * allowable);
        assert!(
            (bearing.utilisation - q / allowable).abs() < 1e-10,
            "utilisation {} vs q / allowable {}",
            bearing.utilisation,
            q / allowable
        );
        assert!(
            (bearing.area_exceeding - area).abs() < 1e-10 * 24.0,
            "area exceeding {} m², want {area}",
            bearing.area_exceeding
        );
        assert!((bearing.fraction_exceeding - area / 24.0).abs() < 1e-12);
        // A uniform pressure averages to itself: averaged = nodal peak = q, over squares of
        // the default side, the slab's thickness.
        assert!((bearing.length - H).abs() < 1e-12 * H, "{}", bearing.length);
        assert!(
            (bearing.average - q).abs() < 1e-10 * q,
            "{}",
            bearing.average
        );
        assert!((bearing.max - q).abs() < 1e-10 * q, "{}", bearing.max);
        assert!((bearing.nodal_utilisation - bearing.utilisation).abs() < 1e-10);
    }
    // Without an allowable pressure there is no check.
    let a = solve_with(
        &slab(6.0, 4.0).uniform_load(q).elements(12, 8),
        Method::Bonded,
    );
    assert!(a.report.bearing.is_none());
}

/// A nearly rigid plate (4 × 2 × 1 m on K = 1 MPa/m: K L⁴ / D = 6e-3) under a 100 kN patch
/// centred 0.5 m off the y axis presses the soil linearly, p(x) = F/A + F e x / I, with
/// I = Σ A_i x_i² of the lumped springs (the trapezoid weights of the grid). The allowable
/// pressure p(1 m) is then exceeded exactly on 1 m < x ≤ 2 m: a quarter of the plate, 2 m²
/// (a linear nodal field has a straight contour, so the bilinear area is exact), and the
/// nodal utilisation is p(2 m) / p(1 m). The check averages the pressure over squares of the
/// plate's thickness, 1 m: a linear field's average over a square is its value at the centre,
/// so the largest is p(1.5 m), on a square at the edge x = 2 m. Bending and shear bend the
/// pressure by ~1e-3 of F/A, which moves the contour by ~1e-3 I / (A e) ≈ 3 mm, 0.3 % of the
/// area: tolerance 1 %.
#[test]
fn bearing_exceedance_area_of_a_rigid_plate_under_an_eccentric_load() {
    let (force, e, k) = (1.0e5, 0.5, 1.0e6);
    let (half_l, half_w) = (2.0, 1.0);
    let p_of = |x: f64, i: f64| force / (4.0 * half_l * half_w) + force * e * x / i;
    // I of the lumped springs on the 40 × 20 grid: trapezoid weights.
    let (nx, ny) = (40usize, 20usize);
    let (hx, hy) = (2.0 * half_l / nx as f64, 2.0 * half_w / ny as f64);
    let mut i_lumped = 0.0;
    for j in 0..=ny {
        for i in 0..=nx {
            let wx = if i == 0 || i == nx { 0.5 } else { 1.0 };
            let wy = if j == 0 || j == ny { 0.5 } else { 1.0 };
            let x = -half_l + i as f64 * hx;
            i_lumped += wx * wy * hx * hy * x * x;
        }
    }
    let allowable = p_of(1.0, i_lumped);
    let b = Model::builder()
        .plate(PlateSpec::new(4.0, 2.0, 1.0, E, NU))
        .foundation(FoundationSpec::winkler(k))
        .allowable_pressure(allowable)
        .patch_load([e - 0.25, e + 0.25], [-0.25, 0.25], force / 0.25)
        .elements(nx, ny);
    for method in [Method::Bonded, Method::qp()] {
        let a = solve_with(&b, method.clone());
        let bearing = a
            .report
            .bearing
            .unwrap_or_else(|| panic!("no bearing check"));
        let want_util = p_of(half_l, i_lumped) / allowable;
        let want_average = p_of(1.5, i_lumped);
        eprintln!(
            "{} rigid-plate bearing: {bearing:?}; want area 2, utilisation {want_util:.5}, min p {:.1}",
            method.name(),
            a.report.field.pressure.iter().cloned().fold(f64::INFINITY, f64::min)
        );
        assert!(
            (bearing.area_exceeding - 2.0).abs() < 0.01 * 2.0,
            "{}: area exceeding {} m², want 2",
            method.name(),
            bearing.area_exceeding
        );
        assert!(
            (bearing.nodal_utilisation - want_util).abs() < 0.01 * want_util,
            "{}: nodal utilisation {}, want {want_util}",
            method.name(),
            bearing.nodal_utilisation
        );
        assert!(
            (bearing.average - want_average).abs() < 0.01 * want_average
                && (bearing.average_at[0] - 1.5).abs() < 1e-12,
            "{}: averaged {} Pa at {:?}, want {want_average} at x = 1.5 m",
            method.name(),
            bearing.average,
            bearing.average_at
        );
        assert!((bearing.utilisation - want_average / allowable).abs() < 0.01 * want_util);
    }
}
