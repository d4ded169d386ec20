//! Jointed slabs against independent references (issue 23; the numbers come from
//! `tests/references/two_plates.py`, which prints every one of them in about 4 s):
//!
//! * two semi-infinite Mindlin plates on a bonded Winkler soil joined by a shear spring c (and a
//!   rotational spring c_r), solved by a Fourier transform along the joint: w on both sides, the
//!   deflection LTE, the transferred force and the stress LTE, at three meshes with the
//!   observed order of convergence;
//! * c = 0 on a thin plate: the free edge of Westergaard's edge loading (the exact Kirchhoff
//!   solution, which reproduces Westergaard's 1948 edge formulas to 0.1 %);
//! * the deflection LTE against AGG/(kℓ) over five decades, against the exact curve and, as a
//!   check of shape, the two published regressions;
//! * a row of dowels: liftoff's bar forces against the smeared Mindlin joint c = k_d/s and
//!   Friberg's (1940) rules (the bar's spring and bearing stress are checked against a direct
//!   beam solution in `src/layout.rs`).
//!
//! Units of the references: D = k = 1, so ℓ = (D/k)^¼ = 1, w in P/(kℓ²), c in kℓ (c is
//! AGG/(kℓ)), c_r in D/ℓ. The scene of section a has ℓ = 1 m: k = D.

use liftoff::post::{JointReport, Report};
use liftoff::{analyse, Analysis, Problem};

/// Parse, validate and solve (tests only: panics with the scene's error).
fn solve(text: &str) -> Analysis {
    let p = Problem::from_toml(text).unwrap_or_else(|e| panic!("scene rejected: {e}\n{text}"));
    let a = analyse(&p).unwrap_or_else(|e| panic!("solve failed: {e}\n{text}"));
    assert!(a.solution.status.converged(), "{text}");
    a
}

const E: f64 = 30e9;
const NU: f64 = 0.15;
/// The wheel load of the scenes, N.
const P: f64 = 4e4;
/// Side of the square plate of section a, m.
const SIZE: f64 = 18.0;

/// D = E H³ / (12 (1 − ν²)), N·m.
fn rigidity(h: f64) -> f64 {
    E * h.powi(3) / (12.0 * (1.0 - NU * NU))
}

/// The scene of section a: a plate of thickness `h` on k = D/ℓ⁴ with ℓ = 1 m, `n` × `n`
/// elements, the joint `joint` along x = 0, 40 kN on the patch [−0.5, 0] × [−0.25, 0.25] m
/// beside it, bonded, symmetry auto (the half y ≥ 0). The plate is 18 m × 18 m, not the
/// design's 12 m: at 12 m the free edges, 6ℓ from the load, add an h-independent 2e-4–1.3e-3
/// (relative, largest on the small deflections of the unloaded side at c = 0.1; measured
/// against a 24 m plate at ℓ/8) that is as large as the discretisation error at ℓ/16 and bends
/// the observed order to 2.4–2.8; at 9ℓ it is ~e^{−6/√2} ≈ 1.4 % of that.
fn scene(h: f64, n: usize, joint: &str) -> String {
    let (k, size) = (rigidity(h), SIZE);
    format!(
        "[plate]\nlength = {size}\nwidth = {size}\nthickness = {h}\nyoungs_modulus = {E:e}\n\
         poissons_ratio = {NU}\n[foundation]\nmodel = \"winkler\"\nmodulus = {k:e}\n{joint}\
         [[load]]\nkind = \"patch\"\nx = [-0.5, 0.0]\ny = [-0.25, 0.25]\npressure = {}\n\
         [solver]\ncontact = \"bonded\"\n[mesh]\nelements = [{n}, {n}]\nsymmetry = \"auto\"\n",
        P / 0.25
    )
}

/// An aggregate joint x = 0 of c = `c` kℓ, or a tied one with c_r = `c_r` D/ℓ as well (ℓ = 1 m).
fn joint_x0(h: f64, c: f64, c_r: f64) -> String {
    let d = rigidity(h);
    if c_r == 0.0 {
        format!(
            "[[joint]]\nx = 0.0\nkind = \"aggregate\"\nname = \"J\"\nstiffness = {:e}\n",
            c * d
        )
    } else {
        format!(
            "[[joint]]\nx = 0.0\nkind = \"tied\"\nname = \"J\"\nstiffness = {:e}\nrotational_stiffness = {:e}\n",
            c * d,
            c_r * d
        )
    }
}

/// w of the grid node at (x, y) m (the − copy on a joint line).
fn grid_w(r: &Report, x: f64, y: f64) -> f64 {
    let f = &r.field;
    (0..f.n_grid())
        .find(|&k| (f.x[k] - x).abs() < 1e-9 && (f.y[k] - y).abs() < 1e-9)
        .map(|k| f.w[k])
        .unwrap_or_else(|| panic!("no node at ({x}, {y})"))
}

/// (w⁻, w⁺) of the joint's node pair at y.
fn pair(j: &JointReport, y: f64) -> (f64, f64) {
    let n = j
        .nodes
        .iter()
        .find(|n| (n.y - y).abs() < 1e-9)
        .unwrap_or_else(|| panic!("no pair at y = {y}"));
    (n.w_minus, n.w_plus)
}

/// w kℓ²/P (ℓ = 1 m, k = D) at the reference's eight points: (0,0)L, (0,0)R, (−¼,0)L, (¼,0)R,
/// (0,½)L, (0,½)R, (−1,0)L, (1,1)R.
fn eight_points(r: &Report, d: f64) -> [f64; 8] {
    let j = &r.joints[0];
    let (l0, r0) = pair(j, 0.0);
    let (l5, r5) = pair(j, 0.5);
    [
        l0,
        r0,
        grid_w(r, -0.25, 0.0),
        grid_w(r, 0.25, 0.0),
        l5,
        r5,
        grid_w(r, -1.0, 0.0),
        grid_w(r, 1.0, 1.0),
    ]
    .map(|w| w * d / P)
}

/// One row of the Mindlin table (section A of two_plates.py, H = 0.25ℓ).
struct Row {
    c: f64,
    c_r: f64,
    w: [f64; 8],
    lte: f64,
    force: f64,
    /// The stress LTE read where liftoff reads it: m_y at the element centres (±h/2, h/2),
    /// for h = ℓ/8, ℓ/16, ℓ/32 (ℓ/16 is asserted).
    stress_lte: [f64; 3],
}

#[rustfmt::skip]
const MINDLIN: [Row; 5] = [
    Row { c: 0.1, c_r: 0.0, w: [0.32977159, 0.02716084, 0.28359701, 0.02238828, 0.29116830, 0.02611871, 0.15147382, 0.00919864], lte: 0.08236258, force: 0.09121038, stress_lte: [0.02401117, 0.02422366, 0.02439386] },
    Row { c: 1.0, c_r: 0.0, w: [0.25015618, 0.10677625, 0.21824145, 0.08774384, 0.21610107, 0.10118594, 0.12038081, 0.03445502], lte: 0.42683835, force: 0.30505117, stress_lte: [0.14366016, 0.14471263, 0.14554863] },
    Row { c: 10.0, c_r: 0.0, w: [0.19469438, 0.16223805, 0.17380356, 0.13218172, 0.16805980, 0.14922722, 0.09997275, 0.04811865], lte: 0.83329601, force: 0.39847210, stress_lte: [0.40547713, 0.40878609, 0.41029021] },
    Row { c: 100.0, c_r: 0.0, w: [0.18099271, 0.17593971, 0.16375952, 0.14222576, 0.15941342, 0.15787359, 0.09595031, 0.04994409], lte: 0.97208175, force: 0.41106070, stress_lte: [0.65478490, 0.66306205, 0.66351804] },
    Row { c: 10.0, c_r: 1.0, w: [0.15450692, 0.12205059, 0.14819092, 0.10656908, 0.13023578, 0.11140320, 0.09838128, 0.04650046], lte: 0.78993607, force: 0.39847210, stress_lte: [0.39715981, 0.40216288, 0.40527066] },
];

/// Largest |a/b − 1| over the points where the reference |b| > 0.01 (P/(kℓ²)).
fn max_rel(a: &[f64; 8], b: &[f64; 8]) -> f64 {
    a.iter()
        .zip(b)
        .filter(|(_, b)| b.abs() > 0.01)
        .map(|(a, b)| (a / b - 1.0).abs())
        .fold(0.0, f64::max)
}

/// Two semi-infinite Mindlin plates joined by a shear spring (c = 0.1 … 100 kℓ) and a tied
/// joint (c = 10, c_r = 1), at h = ℓ/8 and ℓ/16 (144 and 288 elements across 18 m).
///
/// Measured (max relative error over the 8 points with |w| > 0.01 P/(kℓ²)): e₈ = 3.6–6.7e-3,
/// e₁₆ = 0.88–1.72e-3 (largest on the unloaded side at c = 0.1, where w is small), observed
/// order log₂(e₈/e₁₆) = 1.93–2.01 (MITC4 with lumped springs and consistent loads is O(h²) at
/// the nodes). Asserted: order in [1.8, 2.2] (the design allowed [1.6, 2.4]), e₁₆ ≤ 2e-3 (the
/// design's bound, which the worst case meets with 15 % room).
#[test]
fn two_mindlin_plates_joined_by_springs_converge_at_second_order_to_the_exact_solution() {
    let h = 0.25;
    let d = rigidity(h);
    for row in &MINDLIN {
        let joint = joint_x0(h, row.c, row.c_r);
        let runs: Vec<(Analysis, [f64; 8])> = [144, 288]
            .iter()
            .map(|&n| {
                let a = solve(&scene(h, n, &joint));
                assert_eq!(a.summary.symmetry, "half-y", "the half y ≥ 0");
                let w = eight_points(&a.report, d);
                (a, w)
            })
            .collect();
        let e: Vec<f64> = runs.iter().map(|(_, w)| max_rel(w, &row.w)).collect();
        let order = (e[0] / e[1]).log2();
        let tag = format!("c = {}, c_r = {}", row.c, row.c_r);
        println!(
            "{tag}: e8 {:.2e} e16 {:.2e}, order {order:.3} LTE {:.2e} F {:.2e} sLTE {:.2e} {:.2e}",
            e[0],
            e[1],
            runs[1].0.report.joints[0].lte_deflection - row.lte,
            runs[1].0.report.joints[0].transferred_force / P - row.force,
            runs[0].0.report.joints[0].lte_stress - row.stress_lte[0],
            runs[1].0.report.joints[0].lte_stress - row.stress_lte[1]
        );
        assert!((1.8..=2.2).contains(&order), "{tag}: order {order}");
        assert!(e[1] <= 2e-3, "{tag}: e16 = {:e}", e[1]);
        // e₃₂ is mostly the finite plate's 2–6e-4 now: ≤ 7e-4 (measured ≤ 6.2e-4).

        let j = &runs[1].0.report.joints[0];
        // The deflection LTE is a ratio of two deflections whose O(h²) errors are nearly the
        // same fraction: measured |ΔLTE| ≤ 1.4e-4 at ℓ/16 (the design allowed 2e-3). Relative,
        // since the soft joint's LTE is small (0.082 at c = 0.1): measured |ΔLTE|/LTE ≤ 6.0e-4
        // (c = 0.1), 1e-3 asserted.
        assert_eq!(
            j.at,
            [0.0, 0.0],
            "{tag}: read where the loaded side deflects most"
        );
        assert!(
            (j.lte_deflection / row.lte - 1.0).abs() <= 1e-3,
            "{tag}: LTE {} vs {}",
            j.lte_deflection,
            row.lte
        );
        // The transferred force c ∫ (w⁻ − w⁺) dy (the η = 0 term of the reference): measured
        // ≤ 6e-5 P at ℓ/16, relative ≤ 5.0e-4 (c = 0.1, where it is 0.09 P); 1e-3 relative
        // asserted.
        assert!(
            (j.transferred_force / P / row.force - 1.0).abs() <= 1e-3,
            "{tag}: F {} vs {}",
            j.transferred_force / P,
            row.force
        );
        // The stress LTE: liftoff reads m_y at the element centres beside the pair (x = ±h/2,
        // y = ±h/2), so the reference is evaluated there, not on the joint line (on the line
        // it differs by up to 0.01: the Mindlin edge zone, decay length
        // √((1 − ν)D/(2S)) = 0.08ℓ, is where the moment changes fastest). That zone is barely
        // resolved at ℓ/16, so the unloaded side's edge moment converges more slowly than w:
        // measured |ΔLTE_σ| ≤ 2.3e-3 at ℓ/16 (c = 100; ≤ 4e-4 for the others), and on the
        // 12 m plate at ℓ/32 9e-4: it converges. Relative, since at c = 0.1 the stress LTE is
        // 0.024 (an absolute 3e-3 would allow 12 %): measured |ΔLTE_σ|/LTE_σ ≤ 3.4e-3 (c = 100;
        // ≤ 1e-3 for the others, 9.4e-4 at c = 0.1); 5e-3 asserted at ℓ/16.
        assert!(
            (j.lte_stress / row.stress_lte[1] - 1.0).abs() <= 5e-3,
            "{tag}: LTE_σ {} vs {}",
            j.lte_stress,
            row.stress_lte[1]
        );
    }
}

/// c = 0 on a thin plate (H = 0.02ℓ): each side a free edge, the loaded one under Westergaard's
/// edge loading. The reference is the exact Kirchhoff solution (section W of two_plates.py),
/// which reproduces Westergaard's 1948 edge formulas to 0.1 % (the design's table: point load
/// 0.431438 exact vs 0.431101 by the 1948 formula at ν = 0.15). The design asks for 0.5 %.
/// Measured at ℓ/16: within 5.1e-4 of Kirchhoff — but partly by cancellation: Mindlin at
/// H = 0.02ℓ is 1.3e-3 above Kirchhoff at the load (the same script), and liftoff is 0.5–1.5e-3
/// below that Mindlin solution (discretisation, as for the thick plate: 0.9–1.7e-3 at ℓ/16). So
/// also asserted: within 2.5e-3 of the Mindlin H = 0.02ℓ solution.
#[test]
fn a_free_joint_on_a_thin_plate_is_westergaards_free_edge() {
    let h = 0.02;
    let d = rigidity(h);
    let a = solve(&scene(
        h,
        288,
        "[[joint]]\nx = 0.0\nkind = \"free\"\nname = \"J\"\n",
    ));
    let r = &a.report;
    let w = eight_points(r, d);
    let loaded = [w[0], w[2], w[4], w[6]];
    // (0,0), (−¼,0), (0,½), (−1,0) on the loaded side.
    let kirchhoff = [0.34660847, 0.29843127, 0.31140178, 0.16149102];
    let mindlin = [0.34705772, 0.29868591, 0.31173340, 0.16149709];
    for k in 0..4 {
        let (ek, em) = (loaded[k] / kirchhoff[k] - 1.0, loaded[k] / mindlin[k] - 1.0);
        println!(
            "free edge point {k}: {:.8} vs Kirchhoff {ek:+.2e}, Mindlin {em:+.2e}",
            loaded[k]
        );
        assert!(
            ek.abs() <= 5e-3,
            "point {k}: {} vs Kirchhoff {}",
            loaded[k],
            kirchhoff[k]
        );
        assert!(
            em.abs() <= 2.5e-3,
            "point {k}: {} vs Mindlin {}",
            loaded[k],
            mindlin[k]
        );
    }
    // The other side does not move (Winkler: no load, no coupling).
    assert_eq!([w[1], w[3], w[5], w[7]], [0.0; 4]);
    assert_eq!(r.joints[0].lte_deflection, 0.0);
}

/// The deflection LTE against AGG/(kℓ) = 0.01 … 1000 (section L of two_plates.py): exact
/// semi-infinite Mindlin plates (H = 0.25ℓ) and the two published regressions: Crovetti's
/// 1/(1 + 1.2 f^−0.849) (J. A. Crovetti's 1994 PhD thesis, University of Illinois at
/// Urbana-Champaign) and the log form 1/(1 + 10^{(0.214 − 0.183 a/ℓ − log f)/1.18}) with
/// a/ℓ = 0.2821 of the circle of the patch's area (of the family of Ioannides & Korovesis,
/// "Aggregate interlock: a pure-shear load transfer mechanism", Transportation Research Record
/// 1286, 1990, pp. 14–24, which defined f = AGG/(kℓ) and fitted the LTE to it and a/ℓ from
/// finite-element runs). Both sets of constants come from the design's doubts list: recalled,
/// not re-read in those sources — so they are checks of shape only; the exact curve supports
/// the log form closely.
#[rustfmt::skip]
pub const LTE_TABLE: [(f64, f64, f64, f64); 11] = [
    // (f, exact Mindlin, Crovetti, log form)
    (0.01, 0.00919544, 0.01642950, 0.01449230),
    (0.03, 0.02687934, 0.04072291, 0.03596741),
    (0.1, 0.08236258, 0.10553187, 0.09379144),
    (0.3, 0.20251166, 0.23067664, 0.20797608),
    (1.0, 0.42683835, 0.45454545, 0.42144299),
    (3.0, 0.65224884, 0.67926591, 0.64889253),
    (10.0, 0.83329601, 0.85477738, 0.83678389),
    (30.0, 0.92500067, 0.93733837, 0.92860914),
    (100.0, 0.97208175, 0.97651132, 0.97303378),
    (300.0, 0.98964106, 0.99062407, 0.98919477),
    (1000.0, 0.99673944, 0.99660606, 0.99607782),
];

/// liftoff's LTE over the 11 stiffnesses at h = ℓ/8 (the section-a scene). Asserted, as the
/// design asks: |LTE − exact| ≤ 5e-3 (the real test of the code; measured ≤ 5.3e-4, at f = 1,
/// the ℓ/8 deflections' errors being nearly the same fraction on both sides, so 1e-3 is
/// asserted) and, since at f = 0.01 the LTE is 0.0092 and 1e-3 would allow 11 %, relative:
/// measured |LTE/exact − 1| ≤ 2.7e-3 (largest at the smallest f), 4e-3 asserted;
/// |LTE − log form| ≤ 0.02 and |LTE − Crovetti| ≤ 0.04 (checks of shape: the regressions are
/// fits to finite-element runs, the log form lies within 0.012 of the exact curve, Crovetti's
/// 0.02–0.03 above it in the middle), and LTE increasing with the stiffness.
#[test]
fn lte_against_joint_stiffness_follows_the_exact_curve_and_the_regressions() {
    let h = 0.25;
    let mut last = 0.0;
    for &(f, exact, crovetti, log_form) in &LTE_TABLE {
        let a = solve(&scene(h, 144, &joint_x0(h, f, 0.0)));
        let lte = a.report.joints[0].lte_deflection;
        println!(
            "f {f}: LTE {lte:.6} (exact {exact:.6}, {:+.2e})",
            lte - exact
        );
        assert!((lte - exact).abs() <= 1e-3, "f = {f}: {lte} vs {exact}");
        assert!(
            (lte / exact - 1.0).abs() <= 4e-3,
            "f = {f}: {lte} vs {exact}, relative"
        );
        assert!(
            (lte - log_form).abs() <= 0.02,
            "f = {f}: {lte} vs log form {log_form}"
        );
        assert!(
            (lte - crovetti).abs() <= 0.04,
            "f = {f}: {lte} vs Crovetti {crovetti}"
        );
        assert!(lte > last, "f = {f}: LTE {lte} after {last}");
        last = lte;
    }
}

/// The dowel scene of section c: ℓ = 0.9 m, k = 80 MN/m³ (D = kℓ⁴ with E = 30 GPa, ν = 0.15:
/// H = 0.2738 m), a 16.2 m (18ℓ) square plate, the joint x = 0 with `joint` (its TOML after
/// `kind`), 40 kN on a 0.25 m square wheel patch at the joint centred on y = 0, bonded,
/// h = 0.075 m (216 elements: H/h = 3.7, four elements between bars).
fn dowel_scene(joint: &str) -> String {
    let (ell, k): (f64, f64) = (0.9, 8e7);
    let h = (12.0 * (1.0 - NU * NU) * k * ell.powi(4) / E).cbrt();
    format!(
        "[plate]\nlength = 16.2\nwidth = 16.2\nthickness = {h:.17e}\nyoungs_modulus = {E:e}\n\
         poissons_ratio = {NU}\n[foundation]\nmodel = \"winkler\"\nmodulus = {k:e}\n\
         [[joint]]\nx = 0.0\nname = \"T\"\n{joint}[[load]]\nkind = \"patch\"\nx = [-0.25, 0.0]\n\
         y = [-0.125, 0.125]\npressure = {}\n[solver]\ncontact = \"bonded\"\n[mesh]\n\
         elements = [216, 216]\nsymmetry = \"auto\"\n",
        P / 0.0625
    )
}

/// The bar: 32 mm steel, opening 6 mm, K = 4.07e11 N/m³, every 0.3 m with one at y = 0.
const BARS: &str = "kind = \"dowels\"\ndiameter = 0.032\nyoungs_modulus = 200e9\nopening = 0.006\nsupport_modulus = 4.07e11\nspacing = 0.3\noffset = 0.3\n";

/// The smeared Mindlin reference (section D of two_plates.py, H/ℓ = 0.304207, c = k_d/s =
/// 5.514563 kℓ): the dowel force c (w⁻ − w⁺)(yᵢ) s / P at yᵢ = 0, s, …, 6s, and the transferred
/// force / P.
const SMEARED: [f64; 7] = [
    0.11272554,
    0.08238999,
    0.04687778,
    0.02273016,
    0.00887843,
    0.00198332,
    -0.00087741,
];
const SMEARED_TRANSFER: f64 = 0.42351414;

/// The soil's reaction under the elements of `panel`: each element's corner pressures (its own
/// side's copies) times a quarter of its area — the lumped Winkler coupling.
fn reaction_under(r: &Report, panel: u32) -> f64 {
    let f = &r.field;
    let (hx, hy) = (f.x[1] - f.x[0], f.y[f.nodes_x()] - f.y[0]);
    let mut sum = 0.0;
    for j in 0..f.ny {
        for i in 0..f.nx {
            if f.panel[i + j * f.nx] == panel {
                let c = f.element_nodes(i, j);
                sum += c.iter().map(|&k| f.pressure[k]).sum::<f64>() * hx * hy / 4.0;
            }
        }
    }
    sum
}

/// A row of dowels against Friberg (1940) and the smeared Mindlin joint (section c).
///
/// The smeared reference c = k_d/s matches the exact discrete row to 0.15 % on *Kirchhoff*
/// plates (the design's table). On this Mindlin plate it does not, for two reasons a Kirchhoff
/// plate lacks: the plate is as thick as the bar spacing (H = 0.27 m, s = 0.3 m), so the shear
/// edge zone (decay length √((1 − ν)D/(2S)) = 0.09 m) concentrates the jump at each bar; and a
/// point spring on a Mindlin plate has a local compliance growing like ln(H/h)/(πS) at an edge,
/// k_d ln(H/h)/(πS) ≈ 1.7 % at H/h = 3.7, which softens the critical bar. Measured: the critical
/// bar 2.1 % below the smeared reference, the others within 0.75 % of it (relative to the
/// critical force), the transferred force 0.26 % below. That this is the bars and not the
/// plate is shown by the control run, the same plate with an aggregate joint of c = k_d/s: it
/// matches the reference to 1.9e-3 of the critical force (transferred force to 8e-5).
/// Asserted: control ≤ 4e-3 of F_crit and 5e-4 on the transfer; bars ≤ 3 % of F_crit (the
/// design expected 2 %, not knowing the Mindlin smearing above) and 0.5 % on the transfer.
///
/// Friberg's checks: (2) the bar under the load carries most and the bars beyond 1.8ℓ carry
/// less than 3 % of it; (3) its share of the transferred force lies between Friberg's shares
/// with a reach of 1.8ℓ and of 1.0ℓ (the exact Kirchhoff share 0.243 does); (4) the bars'
/// forces add up to the transferred force, which the soil under the unloaded panel carries
/// (bonded Winkler: an identity, round-off); (5) the bearing stress reported is K y₀ of the
/// critical force, y₀ = F(2 + βz)/(4β³E_dI_d) written out here. (1), the bar's spring and y₀
/// against a direct beam solution, is `dowel_spring_matches_the_direct_beam_solution` in
/// src/layout.rs.
#[test]
fn dowel_forces_follow_the_smeared_reference_and_friberg() {
    let ell = 0.9;
    let a = solve(&dowel_scene(BARS));
    let r = &a.report;
    let j = &r.joints[0];
    assert_eq!(j.dowels.len(), 53, "bars every 0.3 m across 16.2 m");
    let mut bars: Vec<(f64, f64)> = j.dowels.iter().map(|d| (d.y, d.force)).collect();
    bars.sort_by(|p, q| p.0.total_cmp(&q.0));
    let centre = bars
        .iter()
        .position(|b| b.0.abs() < 1e-9)
        .expect("a bar at y = 0");
    let f_crit = bars[centre].1;

    // The smeared control: the same plate with an aggregate joint of c = k_d/s.
    let bar = liftoff::layout::DowelBar {
        diameter: 0.032,
        youngs_modulus: 200e9,
        opening: 0.006,
        support: 4.07e11,
    };
    let smeared = solve(&dowel_scene(&format!(
        "kind = \"aggregate\"\nstiffness = {:e}\n",
        bar.spring() / 0.3
    )));
    let sj = &smeared.report.joints[0];
    for (i, &reference) in SMEARED.iter().enumerate() {
        let y = 0.3 * i as f64;
        let force = bars[centre + i].1 / P;
        let n = sj
            .nodes
            .iter()
            .find(|n| (n.y - y).abs() < 1e-9)
            .expect("a node at the bar");
        let control = n.shear_per_length * 0.3 / P;
        let (eb, ec) = (
            (force - reference) / SMEARED[0],
            (control - reference) / SMEARED[0],
        );
        println!("y {y:.1}: bar {force:.6} control {control:.6} reference {reference:.6}: {eb:+.2e} {ec:+.2e}");
        assert!(
            ec.abs() <= 4e-3,
            "control at y = {y}: {control} vs {reference}"
        );
        assert!(eb.abs() <= 3e-2, "bar at y = {y}: {force} vs {reference}");
    }
    let (tb, tc) = (j.transferred_force / P, sj.transferred_force / P);
    assert!(
        (tc / SMEARED_TRANSFER - 1.0).abs() <= 5e-4,
        "control transfer {tc}"
    );
    assert!(
        (tb / SMEARED_TRANSFER - 1.0).abs() <= 5e-3,
        "bars' transfer {tb}"
    );

    // (2) The bar under the load carries most; beyond 1.8ℓ less than 3 % of it.
    for &(y, f) in &bars {
        assert!(f.abs() <= f_crit, "bar at y = {y}: {f} > {f_crit}");
        if y.abs() > 1.8 * ell {
            assert!(f.abs() < 0.03 * f_crit, "bar at y = {y}: {f} vs {f_crit}");
        }
    }
    // (3) Friberg's shares with the bars' own positions.
    let total: f64 = bars.iter().map(|b| b.1).sum();
    let share = |reach: f64| {
        1.0 / bars
            .iter()
            .map(|b| (1.0 - b.0.abs() / (reach * ell)).max(0.0))
            .sum::<f64>()
    };
    let (lo, hi) = (share(1.8), share(1.0));
    println!(
        "critical share {:.4}, Friberg {lo:.4} (1.8 l) … {hi:.4} (1.0 l)",
        f_crit / total
    );
    assert!(
        (lo..=hi).contains(&(f_crit / total)),
        "share {}",
        f_crit / total
    );
    // (4) Statics of the unloaded panel, to round-off (1e-10 of the load; a direct solve).
    assert!((total - j.transferred_force).abs() <= 1e-10 * P);
    let reaction = reaction_under(r, 1);
    assert!(
        (j.transferred_force - reaction).abs() <= 1e-10 * P,
        "transferred {} vs reaction {reaction}",
        j.transferred_force
    );
    // (5) σ_b = K y₀(F_crit), the closed form written out (same formula: round-off, 1e-12).
    let (d, e_d, k_s, z): (f64, f64, f64, f64) = (0.032, 200e9, 4.07e11, 0.006);
    let ei = e_d * std::f64::consts::PI * d.powi(4) / 64.0;
    let beta: f64 = (k_s * d / (4.0 * ei)).powf(0.25);
    let y0 = f_crit * (2.0 + beta * z) / (4.0 * beta.powi(3) * ei);
    let sigma = j
        .dowels
        .iter()
        .find(|b| b.y.abs() < 1e-9)
        .and_then(|b| b.bearing_stress);
    let sigma = sigma.expect("the bar's properties are given");
    assert!(
        (sigma - k_s * y0).abs() <= 1e-12 * sigma,
        "{sigma} vs {}",
        k_s * y0
    );
    assert_eq!(
        j.max_bearing_stress,
        Some(sigma),
        "the critical bar bears most"
    );
}
