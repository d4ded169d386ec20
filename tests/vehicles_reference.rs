//! Vehicle loads against references the code did not produce: a heading of 90° against the
//! transposed scene (an exact invariance of the square plate on its square mesh), the bundled
//! standards' tire prints against the README's table, and the Boeing 737-800 main gear on a
//! large bonded slab against the infinite Mindlin plate's wavenumber integral under its two
//! prints (`common::infinite::rectangles`, no library code).

use std::collections::HashMap;

use liftoff::post::Report;
use liftoff::scene::Overrides;
use liftoff::study::{critical, CriticalOptions, RunOutcome};

use crate::common;

use common::infinite::{Plate, Rect};

/// An 8 m × 8 m × 0.25 m slab on k = 27 MN/m³ under its weight and a night gradient (top 10 K
/// cooler: the corners lift, so each solve is a contact problem, not a linear one), unbonded,
/// on a 32 × 32 mesh (0.25 m), with the
/// given `[[load]]` entries. Square plate, square mesh, the mesh's own layout symmetric under
/// x ↔ y: transposing the scene maps the discrete problem onto itself.
fn square(loads: &str) -> String {
    format!(
        "[plate]\nlength = 8.0\nwidth = 8.0\nthickness = 0.25\nyoungs_modulus = 30e9\npoissons_ratio = 0.15\nthermal_expansion = 1e-5\n\
         [foundation]\nmodel = \"winkler\"\nmodulus = 27e6\n\
         [[load]]\nkind = \"uniform\"\npressure = 6e3\n\
         [[load]]\nkind = \"temperature\"\ndifference = -10.0\n{loads}\
         [mesh]\nelements = [32, 32]\nsymmetry = \"none\"\n"
    )
}

/// The node (or element centre) grid index of a coordinate on the 8 m plate with spacing `h`
/// starting at `first` (−4 for nodes, −4 + h/2 for element centres).
fn index(v: f64, first: f64, h: f64) -> i64 {
    ((v - first) / h).round() as i64
}

/// For every point (x[i], y[i]) of one solution, the index of the point (y, x) in the other's
/// list (x2, y2): the transposition of a grid of points.
fn transposed(x: &[f64], y: &[f64], x2: &[f64], y2: &[f64], first: f64, h: f64) -> Vec<usize> {
    let at: HashMap<(i64, i64), usize> = (0..x2.len())
        .map(|k| ((index(x2[k], first, h), index(y2[k], first, h)), k))
        .collect();
    (0..x.len())
        .map(|k| at[&(index(y[k], first, h), index(x[k], first, h))])
        .collect()
}

/// Largest |a[i] − b[map[i]]| over the largest |a|.
fn rel_mapped(a: &[f64], b: &[f64], map: &[usize]) -> f64 {
    let diff = (0..a.len())
        .map(|i| (a[i] - b[map[i]]).abs())
        .fold(0.0, f64::max);
    diff / common::max_abs(a).max(1e-300)
}

/// Every field of `a` at (x, y) against `b` at (y, x): w, σ₁ at both faces, and σx of one
/// against σy of the other (τxy is symmetric in x and y, so it maps onto itself). Returns the
/// largest relative difference.
fn transposition_error(a: &Report, b: &Report) -> f64 {
    let h = 8.0 / 32.0;
    let nodes = transposed(&a.field.x, &a.field.y, &b.field.x, &b.field.y, -4.0, h);
    let (ea, eb) = (&a.elements, &b.elements);
    let elements = transposed(&ea.x, &ea.y, &eb.x, &eb.y, -4.0 + h / 2.0, h);
    [
        rel_mapped(&a.field.w, &b.field.w, &nodes),
        rel_mapped(&a.field.pressure, &b.field.pressure, &nodes),
        rel_mapped(&ea.bottom.s1, &eb.bottom.s1, &elements),
        rel_mapped(&ea.top.s1, &eb.top.s1, &elements),
        rel_mapped(&ea.bottom.sx, &eb.bottom.sy, &elements),
        rel_mapped(&ea.bottom.sy, &eb.bottom.sx, &elements),
        rel_mapped(&ea.bottom.sxy, &eb.bottom.sxy, &elements),
    ]
    .into_iter()
    .fold(0.0, f64::max)
}

/// A vehicle at heading 90° at (x, y) is the transposed scene of the same vehicle mirrored
/// across its axis of travel at heading 0° at (y, x): transposing swaps x and y, which turns
/// the travel direction +y into +x and the left side (−x at heading 90°) into +y, the right
/// side at heading 0°. On the square plate and mesh the two discrete problems are the same up
/// to the numbering, so every field agrees to round-off and the contact solve's own tolerance
/// (1e-9 relative: the active-set answer is exact once the set is found, as in
/// `tests/critical.rs`).
///
/// With the tandem (symmetric across its axis) the mirror is the tandem itself; with a gear of
/// two wheels placed asymmetrically ([0.4, 0.3] and [−0.2, −0.5] m, along and across) it is
/// the gear with its across-offsets negated, and the unmirrored gear transposed must differ
/// (by more than 1 % of the largest deflection): the test sees a turn of the wrong hand.
/// Measured: 2.5e-12 and 1.3e-12, the wrong hand 1.8; 65 % and 63 % of the slab in contact.
#[test]
fn a_heading_of_90_degrees_is_the_transposed_scene() {
    let tandem = |heading: f64, x: f64, y: f64| {
        format!("[[load]]\nkind = \"axle\"\nstandard = \"tandem-dual\"\nx = {x}\ny = {y}\nheading = {heading}\n")
    };
    let gear = |heading: f64, x: f64, y: f64, across: f64| {
        format!(
            "[[load]]\nkind = \"gear\"\nwheels = [[0.4, {}], [-0.2, {}]]\nwheel_load = 100e3\ntire_pressure = 1.0e6\nx = {x}\ny = {y}\nheading = {heading}\n",
            0.3 * across,
            -0.5 * across
        )
    };
    let (x, y) = (0.7, -1.3);
    for (name, turned, transposed, wrong) in [
        ("tandem", tandem(90.0, x, y), tandem(0.0, y, x), None),
        (
            "asymmetric gear",
            gear(90.0, x, y, 1.0),
            gear(0.0, y, x, -1.0),
            Some(gear(0.0, y, x, 1.0)),
        ),
    ] {
        let a = common::run(&square(&turned));
        let b = common::run(&square(&transposed));
        let err = transposition_error(&a.report, &b.report);
        assert!(err < 1e-9, "{name}: transposed fields differ by {err:.2e}");
        let (sa, sb) = (&a.summary, &b.summary);
        for (what, u, v) in [
            ("w_max", sa.w_max, sb.w_max),
            (
                "bottom σ₁",
                sa.stresses.bottom.value,
                sb.stresses.bottom.value,
            ),
            ("top σ₁", sa.stresses.top.value, sb.stresses.top.value),
        ] {
            assert!(
                (u - v).abs() <= 1e-9 * u.abs(),
                "{name}: {what} {u} at heading 90° vs {v} transposed"
            );
        }
        // Some contact was lost: the invariance is checked on a contact problem.
        assert!(sa.contact_fraction < 0.999, "{name}: full contact");
        if let Some(wrong) = wrong {
            let c = common::run(&square(&wrong));
            let err = transposition_error(&a.report, &c.report);
            assert!(
                err > 1e-2,
                "{name}: the unmirrored gear transposed is within {err:.2e}: the test cannot see the turn's hand"
            );
        }
    }
}

/// The same invariance through `critical` with `headings = [0, 90]` on a 3 × 3 grid: the grid
/// of heading 90° is the transpose of the grid of heading 0° (position (i, j) of one is
/// position (j, i) of the other, the reference point's x and y swapped), and every transposed
/// pair gives the same largest bottom and top tension, deflection and contact fraction (1e-9
/// relative, as above: the tandem is its own mirror).
#[test]
fn critical_headings_0_and_90_are_transposes() {
    let text = square(
        "[[load]]\nkind = \"axle\"\nname = \"truck\"\nstandard = \"tandem-dual\"\nx = 0.0\ny = 0.0\n",
    );
    let problem =
        liftoff::load(&liftoff::Source::Toml(&text), &Overrides::default()).expect("scene");
    let options = CriticalOptions {
        load: "truck".into(),
        grid: [3, 3],
        headings: vec![0.0, 90.0],
        ..CriticalOptions::default()
    };
    let c = critical(&problem, &options, &liftoff::Monitor::NONE).expect("search");
    assert_eq!(c.positions.len(), 18);
    assert!(c
        .positions
        .iter()
        .all(|p| p.outcome == RunOutcome::CONVERGED));
    // Grid order: heading, then y, then x.
    for j in 0..3 {
        for i in 0..3 {
            let p = &c.positions[3 * j + i];
            let q = &c.positions[9 + 3 * i + j];
            assert_eq!((p.heading, q.heading), (0.0, 90.0));
            assert!(
                (p.x - q.y).abs() < 1e-12 && (p.y - q.x).abs() < 1e-12,
                "({}, {}) at 0° vs ({}, {}) at 90°",
                p.x,
                p.y,
                q.x,
                q.y
            );
            for (what, u, v) in [
                ("bottom", p.bottom, q.bottom),
                ("top", p.top, q.top),
                ("w_max", p.w_max, q.w_max),
                ("contact", p.contact_fraction, q.contact_fraction),
            ] {
                assert!(
                    (u - v).abs() <= 1e-9 * u.abs(),
                    "{what} at ({:.3}, {:.3}): {u} at 0° vs {v} at 90°",
                    p.x,
                    p.y
                );
            }
        }
    }
    // The grid spans the plate: the corner positions differ from the centre's.
    assert!((c.positions[0].w_max - c.positions[4].w_max).abs() > 1e-3 * c.positions[4].w_max);
}

/// The Boeing 737-800 main gear (`b737-800-main`: two 184.56 kN wheels 0.864 m apart at
/// 1.4065 MPa) at the centre of a 20.7 m square, 0.4 m slab on k = 80 MN/m³ (ℓ = 1.196 m, the
/// edges 8.7ℓ away), bonded, against the infinite Mindlin plate on the same springs under the
/// same two PCA rectangles (0.8712 L along × 0.6 L across, L = √(A/0.5227), computed here), by
/// the Cartesian wavenumber integral: w, m_x, m_y at the centre of one print, which the other
/// print 0.864 m away raises by 72 % (w), 37 % (m_x) and 8.5 % (m_y) over that print alone.
///
/// The reference is checked twice: one square print against the independent angular-mean
/// integral `common::infinite::centre` (1e-4: its stated tail), and its own truncation by
/// doubling the cut-off (1e-4; measured 2e-6 on m and 1e-8 on w).
///
/// The plate side 20.736 m = 48 × 0.432 puts the print centre (0, −0.432) on a node of the
/// 192 and 384 meshes (h = 0.108 and 0.054 m; the prints' sides fall inside elements, whose
/// load integrals are exact). The nodal w converges at second order (measured errors 0.14 %
/// and 0.031 %): within 0.2 % on the fine mesh. The moments, the mean of the four element
/// centres around that node (O(h²) away from the node's value), converge at second order too
/// (measured rates 2.00 on m_x and 2.05 on m_y; errors 3.4 % and 0.84 % on m_x): rate within
/// 0.3 of 2, and their Richardson extrapolate within 0.3 % (measured 3e-5 on m_x and 6e-4 on
/// m_y, which also bounds the finite slab's effect at 8.7ℓ from its edges).
#[test]
fn the_b737_main_gear_against_the_infinite_plate_under_two_prints() {
    let (e, nu, h, k) = (30e9, 0.15, 0.4, 80e6);
    let plate = Plate { e, nu, h };
    let soil = |_xi: f64| 1.0 / k;
    // The reference integral against the angular-mean one, for one square print.
    let square = [Rect {
        centre: [0.0, 0.0],
        size: [0.3, 0.3],
        force: 40e3,
    }];
    let (mx1, my1, w1) = common::infinite::rectangles(&plate, &soil, &square, [0.0, 0.0], 100.0);
    let (m0, w0) = common::infinite::centre(&plate, &soil, 0.3, 40e3);
    for (what, a, b) in [("m_x", mx1, m0), ("m_y", my1, m0), ("w", w1, w0)] {
        assert!(
            (a - b).abs() < 1e-4 * b,
            "square print, {what}: Cartesian {a} vs angular mean {b}"
        );
    }
    // The gear's prints, from the README's numbers (not the library's).
    let (force, pressure, half_gap) = (184.56e3, 1.4065e6, 0.432);
    let area: f64 = force / pressure;
    let l = (area / 0.5227).sqrt();
    let size = [0.8712 * l, 0.6 * l];
    let prints = [
        Rect {
            centre: [0.0, -half_gap],
            size,
            force,
        },
        Rect {
            centre: [0.0, half_gap],
            size,
            force,
        },
    ];
    let at = [0.0, -half_gap];
    let (mx, my, w) = common::infinite::rectangles(&plate, &soil, &prints, at, 100.0);
    let (mx2, my2, w2) = common::infinite::rectangles(&plate, &soil, &prints, at, 200.0);
    for (what, a, b) in [("m_x", mx, mx2), ("m_y", my, my2), ("w", w, w2)] {
        assert!(
            (a - b).abs() < 1e-4 * b.abs(),
            "{what}: cut-off 100 gives {a}, 200 gives {b}"
        );
    }
    let (mx_one, _, w_one) = common::infinite::rectangles(&plate, &soil, &prints[..1], at, 100.0);
    assert!(
        w > 1.5 * w_one && mx > 1.2 * mx_one,
        "the second print counts"
    );
    // The slab.
    let side = 48.0 * half_gap;
    let fe = |n: usize| -> [f64; 3] {
        let text = format!(
            "[plate]\nlength = {side}\nwidth = {side}\nthickness = {h}\nyoungs_modulus = {e}\npoissons_ratio = {nu}\n\
             [foundation]\nmodel = \"winkler\"\nmodulus = {k}\n\
             [[load]]\nkind = \"gear\"\nstandard = \"b737-800-main\"\nx = 0.0\ny = 0.0\n\
             [mesh]\nelements = [{n}, {n}]\n[solver]\ncontact = \"bonded\"\n"
        );
        let a = common::run(&text);
        let r = &a.report;
        let node = common::node_at(r, at[0], at[1]);
        assert!(
            (r.field.x[node] - at[0]).abs() < 1e-9 && (r.field.y[node] - at[1]).abs() < 1e-9,
            "the print's centre is a node"
        );
        let step = side / n as f64;
        let el = &r.elements;
        let element_at = |x: f64, y: f64| {
            (0..el.x.len())
                .min_by(|&i, &j| {
                    (el.x[i] - x)
                        .hypot(el.y[i] - y)
                        .total_cmp(&(el.x[j] - x).hypot(el.y[j] - y))
                })
                .unwrap_or(0)
        };
        let (mut m_x, mut m_y) = (0.0, 0.0);
        for (sx, sy) in [(-0.5, -0.5), (0.5, -0.5), (-0.5, 0.5), (0.5, 0.5)] {
            let i = element_at(at[0] + sx * step, at[1] + sy * step);
            m_x += el.mx[i] / 4.0;
            m_y += el.my[i] / 4.0;
        }
        [r.field.w[node], m_x, m_y]
    };
    let (coarse, fine) = (fe(192), fe(384));
    let rel_w = (fine[0] - w).abs() / w;
    assert!(
        rel_w < 2e-3,
        "w under a print: slab {:.6e} m, infinite plate {w:.6e} m ({rel_w:.2e})",
        fine[0]
    );
    for (what, i, reference) in [("m_x", 1, mx), ("m_y", 2, my)] {
        let (e1, e2) = ((coarse[i] - reference).abs(), (fine[i] - reference).abs());
        let rate = (e1 / e2).log2();
        assert!(
            (rate - 2.0).abs() < 0.3,
            "{what}: errors {e1:.3e}, {e2:.3e} N·m/m, rate {rate:.2}"
        );
        let extrapolated = fine[i] + (fine[i] - coarse[i]) / 3.0;
        let rel = (extrapolated - reference).abs() / reference;
        assert!(
            rel < 3e-3,
            "{what} under a print (extrapolated) {extrapolated:.6e} N·m/m vs infinite plate {reference:.6e} ({rel:.2e})"
        );
    }
}

/// The README's table of bundled configurations, and its scene example's keys, as numbers:
/// the tire centres of each standard at heading 0 relative to its reference point, each tire's
/// load and print area, against them (a documentation check: the reference is the README, and
/// each row's text must still say what is asserted here). Tolerances are the README's
/// rounding: "827 kPa" for 827.4e3 Pa, "184.6 kN" for 184.56e3 N, "62.3 kN" for 62.27e3 N,
/// "151 kN, 34 kip" for 2 × 75.6 kN; the positions are exact (1e-12 m).
#[test]
fn bundled_prints_are_where_the_readme_says() {
    let readme = include_str!("../README.md");
    let row = |name: &str| -> &str {
        readme
            .lines()
            .find(|l| l.starts_with(&format!("| `{name}`")))
            .unwrap_or_else(|| panic!("README has no row for `{name}`"))
    };
    for (name, says) in [
        (
            "esal-single-dual",
            &[
                "80 kN single axle",
                "dual tires 0.3048 m apart",
                "sets 1.83 m apart",
                "827 kPa",
            ][..],
        ),
        (
            "tandem-dual",
            &[
                "two 75.6 kN axles 1.311 m apart",
                "151 kN, 34 kip",
                "duals as above",
            ][..],
        ),
        (
            "tridem-dual",
            &[
                "three 62.3 kN axles 1.25 m apart",
                "187 kN, 42 kip",
                "duals as above",
            ][..],
        ),
        (
            "b737-800-main",
            &["two wheels 0.864 m apart", "184.6 kN each", "1.41 MPa"][..],
        ),
    ] {
        let r = row(name);
        for s in says {
            assert!(
                r.contains(s),
                "README row `{name}` no longer says `{s}`: {r}"
            );
        }
    }
    // The README's numbers: (standard, axles, spacing, axle load or wheel load, its rounding).
    let (track, dual, tire_pressure) = (1.83, 0.3048, 827e3);
    let mut loads = String::new();
    for (k, name) in ["esal-single-dual", "tandem-dual", "tridem-dual"]
        .iter()
        .enumerate()
    {
        loads += &format!(
            "[[load]]\nkind = \"axle\"\nname = \"{name}\"\nstandard = \"{name}\"\nx = {}\ny = 0.0\n",
            -6.0 + 4.0 * k as f64
        );
    }
    loads += "[[load]]\nkind = \"gear\"\nname = \"b737\"\nstandard = \"b737-800-main\"\nx = 6.0\ny = 0.0\n";
    let text = format!(
        "[plate]\nlength = 16.0\nwidth = 4.0\nthickness = 0.25\nyoungs_modulus = 30e9\npoissons_ratio = 0.15\n\
         [foundation]\nmodel = \"winkler\"\nmodulus = 27e6\n{loads}[mesh]\nelements = [32, 8]\n"
    );
    let problem =
        liftoff::load(&liftoff::Source::Toml(&text), &Overrides::default()).expect("scene");
    let vehicle = |name: &str| {
        problem
            .model
            .vehicles
            .iter()
            .find(|v| v.name.as_deref() == Some(name))
            .unwrap_or_else(|| panic!("no vehicle {name}"))
    };
    let sorted = |mut v: Vec<[f64; 2]>| {
        v.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
        v
    };
    for (name, alongs, axle_load, rounding) in [
        ("esal-single-dual", vec![0.0], 80e3, 0.05e3),
        (
            "tandem-dual",
            vec![-1.311 / 2.0, 1.311 / 2.0],
            75.6e3,
            0.05e3,
        ),
        ("tridem-dual", vec![-1.25, 0.0, 1.25], 62.3e3, 0.05e3),
    ] {
        let v = vehicle(name);
        let tires = v.tires(v.at).expect("tires");
        let got = sorted(
            tires
                .iter()
                .map(|t| [t.centre[0] - v.at[0], t.centre[1] - v.at[1]])
                .collect(),
        );
        let mut want = Vec::new();
        for &u in &alongs {
            for side in [-1.0, 1.0] {
                for d in [-1.0, 1.0] {
                    want.push([u, side * track / 2.0 + d * dual / 2.0]);
                }
            }
        }
        let want = sorted(want);
        assert_eq!(got.len(), want.len(), "{name}: {} tires", got.len());
        for (g, w) in got.iter().zip(&want) {
            assert!(
                (g[0] - w[0]).abs() < 1e-12 && (g[1] - w[1]).abs() < 1e-12,
                "{name}: tire at {g:?}, README {w:?}"
            );
        }
        for t in &tires {
            assert!(
                (4.0 * t.force - axle_load).abs() <= rounding,
                "{name}: {} N per tire, README {axle_load} N per axle",
                t.force
            );
            let area = t.size[0] * t.size[1];
            let p = t.force / area;
            assert!((p - tire_pressure).abs() <= 0.5e3, "{name}: {p} Pa");
        }
    }
    // The totals in pounds: 34 and 42 kip (4448.2216 N each), to the README's 0.5 kip.
    let kip = 4448.2216152605;
    for (name, total_kip) in [("tandem-dual", 34.0), ("tridem-dual", 42.0)] {
        let total: f64 = vehicle(name).wheels.iter().map(|w| w.force).sum();
        assert!(
            (total / kip - total_kip).abs() < 0.5,
            "{name}: {total} N = {} kip",
            total / kip
        );
    }
    // The gear: 0.864 m apart across the travel, 184.6 kN each at 1.41 MPa — and the README's
    // source: 95 % of 174 700 lb on two gears of two wheels, 204 psi (0.01 %: the conversions).
    let v = vehicle("b737");
    let tires = v.tires(v.at).expect("tires");
    let got = sorted(
        tires
            .iter()
            .map(|t| [t.centre[0] - v.at[0], t.centre[1] - v.at[1]])
            .collect(),
    );
    assert_eq!(got, vec![[0.0, -0.432], [0.0, 0.432]]);
    let lbf = 4.4482216152605;
    let wheel = 0.95 * 174_700.0 * lbf / 4.0;
    let psi = 6894.757293168;
    for t in &tires {
        assert!((t.force - 184.6e3).abs() <= 0.05e3, "{} N", t.force);
        assert!(
            (t.force - wheel).abs() < 1e-4 * wheel,
            "{} N vs {wheel} N",
            t.force
        );
        let p = t.force / (t.size[0] * t.size[1]);
        assert!((p - 1.41e6).abs() <= 0.005e6, "{p} Pa");
        assert!((p - 204.0 * psi).abs() < 1e-4 * p, "{p} Pa vs 204 psi");
    }
    assert!(
        (0.864_f64 - 34.0 * 0.0254).abs() < 5e-4,
        "34 in between the wheels"
    );
}
