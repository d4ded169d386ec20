//! The outputs of jointed slabs (issue 23, step 6), each against a reference the report does
//! not produce: the statics of the unloaded panel (what the joint hands across is what its
//! soil carries), the symmetry of a load about a joint and the limits of a joint's stiffness
//! (LTE = 1 for a hinge, LTE ∝ c as c → 0, exactly 0 for a free joint on Winkler), the count
//! of node copies a joint line makes, σ = 6m/H_p² with each panel's own thickness, and the
//! panels of a free joint on Winkler solved one at a time as their own scenes.

use liftoff::post::{JointReport, Report};
use liftoff::{analyse, Analysis, Problem};

use crate::common;

/// Parse, validate and solve (tests only: panics with the scene's error).
fn solve(text: &str) -> Analysis {
    let p = Problem::from_toml(text).unwrap_or_else(|e| panic!("scene rejected: {e}\n{text}"));
    analyse(&p).unwrap_or_else(|e| panic!("solve failed: {e}\n{text}"))
}

/// A 6 m × 3 m × 250 mm slab on a Winkler soil (k = 50 MN/m³), `elements`, joints, loads and
/// the rest as TOML `body`; bonded unless `body` says otherwise.
fn slab(elements: [usize; 2], body: &str) -> String {
    format!(
        r#"
[plate]
length = 6.0
width = 3.0
thickness = 0.25
youngs_modulus = 30e9
poissons_ratio = 0.2
[foundation]
model = "winkler"
modulus = 5e7
{body}
[mesh]
elements = [{}, {}]
symmetry = "none"
"#,
        elements[0], elements[1]
    )
}

const BONDED: &str = "[solver]\ncontact = \"bonded\"\n";

/// A 200 kN wheel on a 0.3 m × 0.4 m patch beside the joint x = 0 on its − side.
const WHEEL_MINUS: &str =
    "[[load]]\nkind = \"patch\"\nx = [-0.3, 0.0]\ny = [-0.2, 0.2]\npressure = 1.6666666666666667e6\n";

/// Doweled joint x = 0: 32 mm bars every 0.3 m (10 bars), opening 6 mm.
const DOWELS: &str = "[[joint]]\nx = 0.0\nkind = \"dowels\"\nname = \"T1\"\ndiameter = 0.032\nyoungs_modulus = 200e9\nopening = 0.006\nsupport_modulus = 4.07e11\nspacing = 0.3\n";

/// An aggregate-interlock joint x = 0 of AGG `c` N/m².
fn aggregate(c: f64) -> String {
    format!("[[joint]]\nx = 0.0\nkind = \"aggregate\"\nname = \"A1\"\nstiffness = {c:e}\n")
}

/// The soil's reaction under the elements of `panel` from the report's own fields: each
/// element's four corner pressures (its own side's copies) times a quarter of its area — the
/// lumped Winkler coupling, which gives every copy a quarter of each of its elements.
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

fn joint<'a>(r: &'a Report, name: &str) -> &'a JointReport {
    r.joints
        .iter()
        .find(|j| j.name == name)
        .unwrap_or_else(|| panic!("no joint {name}"))
}

/// Statics of the unloaded panel: with the wheel on the − panel and nothing on the + panel,
/// the + panel is held by the joint and its soil alone, so the force the joint hands across —
/// the sum of the dowel forces, and for an aggregate joint c ∫ (w⁻ − w⁺) ds — equals the soil
/// reaction under the + panel, read here from the pressures element by element. Bonded, so a
/// direct solve: equilibrium to round-off, 1e-10 of the wheel load. The same holds of the
/// files: dowels.csv's forces add up to the summary's transferred force.
#[test]
fn the_joint_hands_across_what_the_unloaded_panel_soil_carries() {
    let load = 2e5;
    let a = solve(&slab([24, 12], &format!("{DOWELS}{WHEEL_MINUS}{BONDED}")));
    let r = &a.report;
    let j = joint(r, "T1");
    assert_eq!(j.dowels.len(), 10, "bars every 0.3 m over 3 m");
    let sum: f64 = j.dowels.iter().map(|d| d.force).sum();
    let reaction = reaction_under(r, 1);
    assert!(reaction > 0.01 * load, "the + panel carries {reaction} N");
    assert!(
        (sum - j.transferred_force).abs() <= 1e-10 * load,
        "Σ F {sum} vs transferred {}",
        j.transferred_force
    );
    assert!(
        (j.transferred_force - reaction).abs() <= 1e-10 * load,
        "transferred {} vs reaction under the + panel {reaction}",
        j.transferred_force
    );
    // The whole load is carried: the − panel's soil carries the rest.
    let minus = reaction_under(r, 0);
    assert!(
        (minus + reaction - load).abs() <= 1e-9 * load,
        "Σ reactions {}",
        minus + reaction
    );
    // Each bar's force is its spring times the jump at the bar, and its bearing stress is
    // Friberg's K y₀ of that force (the layout's formulas, checked against a direct beam
    // solution in layout.rs).
    let bar = liftoff::layout::DowelBar {
        diameter: 0.032,
        youngs_modulus: 200e9,
        opening: 0.006,
        support: 4.07e11,
    };
    for d in &j.dowels {
        assert!(
            (d.force - bar.spring() * d.jump).abs() <= 1e-9 * d.force.abs().max(1.0),
            "bar {}: F {} vs k_d Δw {}",
            d.bar,
            d.force,
            bar.spring() * d.jump
        );
        let b = d.bearing_stress.expect("bar properties given");
        assert!((b - bar.bearing_stress(d.force.abs())).abs() <= 1e-9 * b);
    }
    assert_eq!(
        j.max_dowel_force,
        j.dowels.iter().map(|d| d.force.abs()).reduce(f64::max)
    );

    // The aggregate joint: c ∫ jump ds, the same statics.
    let a = solve(&slab(
        [24, 12],
        &format!("{}{WHEEL_MINUS}{BONDED}", aggregate(5e8)),
    ));
    let r = &a.report;
    let j = joint(r, "A1");
    let reaction = reaction_under(r, 1);
    assert!(
        (j.transferred_force - reaction).abs() <= 1e-10 * load,
        "aggregate: transferred {} vs reaction {reaction}",
        j.transferred_force
    );
    // Its shear per length at every node pair is c (w⁻ − w⁺) in N/m.
    for n in &j.nodes {
        assert!((n.shear_per_length - 5e8 * n.jump).abs() <= 1e-9 * (5e8 * n.jump).abs().max(1.0));
        assert!(
            n.minus < r.field.n_grid() && n.plus >= r.field.n_grid(),
            "− is the grid copy"
        );
    }

    // The files: dowels.csv's forces add up to summary.json's transferred force.
    let a = solve(&slab([24, 12], &format!("{DOWELS}{WHEEL_MINUS}{BONDED}")));
    let dir = tempfile::tempdir().expect("tempdir");
    let p = Problem::from_toml(&slab([24, 12], &format!("{DOWELS}{WHEEL_MINUS}{BONDED}")))
        .expect("scene");
    liftoff::output::write_all(dir.path(), &p.model, &a.report, &a.summary).expect("files");
    let dowels = std::fs::read_to_string(dir.path().join("dowels.csv")).expect("dowels.csv");
    let mut lines = dowels.lines();
    let header: Vec<&str> = lines.next().expect("header").split(',').collect();
    let col = header
        .iter()
        .position(|h| *h == "force [N]")
        .expect("force column");
    let total: f64 = lines
        .map(|l| {
            l.split(',')
                .nth(col)
                .and_then(|v| v.parse::<f64>().ok())
                .expect("a force")
        })
        .sum();
    let json: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.path().join("summary.json")).expect("summary.json"),
    )
    .expect("json");
    let transferred = json["joints"][0]["transferred_force"]
        .as_f64()
        .expect("number");
    // The CSV's forces are printed with 13 significant digits.
    assert!(
        (total - transferred).abs() <= 1e-8 * load,
        "csv {total} vs json {transferred}"
    );
    let joints = std::fs::read_to_string(dir.path().join("joints.csv")).expect("joints.csv");
    assert_eq!(
        joints.lines().count(),
        1 + 13,
        "a header and the 13 node pairs of the joint"
    );
}

/// LTE against the joint's stiffness. A load symmetric about the joint gives both sides the
/// same deflection and edge stress whatever the joint (the mirror maps the solution onto
/// itself): LTE = 1 to round-off. A stiff shear spring is a hinge: with the wheel on one side
/// the two sides deflect alike, LTE → 1 as the jump (load / c) vanishes. A soft one hands
/// little across: on Winkler the unloaded panel's deflection is proportional to c as c → 0
/// (LTE(2c) = 2 LTE(c) to first order), and a free joint leaves it exactly still (LTE = 0).
#[test]
fn lte_is_one_for_a_hinge_and_vanishes_with_the_joint_stiffness() {
    // Symmetric: the patch straddles the joint, centred on it.
    let straddle =
        "[[load]]\nkind = \"patch\"\nx = [-0.25, 0.25]\ny = [-0.2, 0.3]\npressure = 1e6\n";
    for c in [1e6, 5e8] {
        let a = solve(&slab(
            [24, 12],
            &format!("{}{straddle}{BONDED}", aggregate(c)),
        ));
        let j = joint(&a.report, "A1");
        // Round-off of a direct solve on a mirror-symmetric system: 1e-10.
        assert!(
            (j.lte_deflection - 1.0).abs() < 1e-10,
            "c {c}: LTE_δ {}",
            j.lte_deflection
        );
        assert!(
            (j.lte_stress - 1.0).abs() < 1e-10,
            "c {c}: LTE_σ {}",
            j.lte_stress
        );
        // No jump but round-off: 1e-9 of the 250 kN load.
        assert!(j.transferred_force.abs() < 2.5e-4, "no jump, no transfer");
    }
    // A hinge: AGG = 1e14 N/m²; the jump is ~ q/c ~ 1e5/1e14 m against w ~ 1e-4 m, so the
    // LTE is 1 within ~1e-4.
    let a = solve(&slab(
        [24, 12],
        &format!("{}{WHEEL_MINUS}{BONDED}", aggregate(1e14)),
    ));
    let j = joint(&a.report, "A1");
    assert!(
        (j.lte_deflection - 1.0).abs() < 1e-4,
        "hinge LTE_δ {}",
        j.lte_deflection
    );
    assert_eq!(j.loaded_side, liftoff::post::Side::Minus);
    // Soft joints: LTE ∝ c. At AGG = 10 N/m² (c/(kℓ) ~ 2e-7, kℓ = 5e7 N/m³ × 0.95 m) the
    // second-order term is of relative size ~ c/(kℓ): the ratio is 2 to 1e-4 with room.
    let lte = |c: f64| {
        let a = solve(&slab(
            [24, 12],
            &format!("{}{WHEEL_MINUS}{BONDED}", aggregate(c)),
        ));
        joint(&a.report, "A1").lte_deflection
    };
    let (l1, l2) = (lte(10.0), lte(20.0));
    assert!(l1 > 0.0 && l1 < 1e-5, "LTE(10) = {l1}");
    assert!((l2 / l1 - 2.0).abs() < 1e-4, "LTE(2c)/LTE(c) = {}", l2 / l1);
    // Free: the + panel carries nothing and does not move.
    let free = "[[joint]]\nx = 0.0\nkind = \"free\"\nname = \"F\"\n";
    let a = solve(&slab([24, 12], &format!("{free}{WHEEL_MINUS}{BONDED}")));
    let j = joint(&a.report, "F");
    assert_eq!(j.lte_deflection, 0.0, "free joint on Winkler");
    assert_eq!(j.transferred_force, 0.0);
    assert_eq!(j.max_shear_per_length, None, "a free joint has no spring");
}

/// Node copies: a line that cuts an nx × ny grid doubles its ny + 1 nodes, a crossing of two
/// such lines adds one more copy at the crossing ((ny + 1) + (nx + 1) + 1 extras); the VTU has
/// every copy as its own point and its cells name the copies of their own side.
#[test]
fn the_vtu_has_a_point_for_every_node_copy() {
    let count = |body: &str| -> (usize, usize, String) {
        // Self-weight on every panel: a panel cut off by a free joint must carry a load.
        let text = slab(
            [12, 6],
            &format!("[[load]]\nkind = \"uniform\"\npressure = 6e3\n{body}"),
        );
        let a = solve(&text);
        let p = Problem::from_toml(&text).expect("scene");
        let dir = tempfile::tempdir().expect("tempdir");
        liftoff::output::write_all(dir.path(), &p.model, &a.report, &a.summary).expect("files");
        let vtu = std::fs::read_to_string(dir.path().join("plate.vtu")).expect("plate.vtu");
        let number = |key: &str| -> usize {
            let at = vtu.find(&format!("{key}=\"")).expect("attribute") + key.len() + 2;
            vtu[at..]
                .split('"')
                .next()
                .and_then(|v| v.parse().ok())
                .expect("a count")
        };
        let nodes = std::fs::read_to_string(dir.path().join("nodes.csv")).expect("nodes.csv");
        assert_eq!(
            nodes.lines().count() - 1,
            number("NumberOfPoints"),
            "a row per copy"
        );
        (number("NumberOfPoints"), number("NumberOfCells"), vtu)
    };
    let grid = 13 * 7;
    let (points, cells, vtu) = count(&format!("{DOWELS}{WHEEL_MINUS}"));
    assert_eq!(
        (points, cells),
        (grid + 7, 12 * 6),
        "one x-joint: ny + 1 extra copies"
    );
    assert!(vtu.contains("Name=\"panel\""), "cells carry their panel");
    let crossing = format!("{DOWELS}[[joint]]\ny = 0.5\nkind = \"free\"\n{WHEEL_MINUS}");
    let (points, _, _) = count(&crossing);
    assert_eq!(
        points,
        grid + 7 + 13 + 1,
        "two crossing lines: (ny + 1) + (nx + 1) + 1"
    );
    let continuous = "[[joint]]\nx = 0.0\nkind = \"continuous\"\n";
    let (points, _, vtu) = count(&format!("{continuous}{WHEEL_MINUS}"));
    assert_eq!(points, grid, "a continuous line doubles nothing");
    assert!(vtu.contains("Name=\"panel\""), "but delimits panels");
    let (points, _, vtu) = count(WHEEL_MINUS);
    assert_eq!(points, grid, "no joints");
    assert!(!vtu.contains("Name=\"panel\""), "and no panels");

    // The cells right of the joint read the + copies: the connectivity of element (6, j)
    // names the extra copies at its left corners.
    let a = solve(&slab([12, 6], &format!("{DOWELS}{WHEEL_MINUS}")));
    let f = &a.report.field;
    for j in 0..6 {
        let c = f.element_nodes(6, j);
        assert!(
            c[0] >= f.n_grid() && c[3] >= f.n_grid(),
            "element (6, {j}): {c:?}"
        );
        let l = f.element_nodes(5, j);
        assert!(l.iter().all(|&k| k < f.n_grid()), "element (5, {j}): {l:?}");
    }
}

/// σ = 6m/H_p² with each panel's own thickness: the + panel twice as thick (0.5 m) has, under
/// the same moment, a quarter of the − panel's stress — element by element, σ_x/m_x is 6/H_p²
/// (96 /m² and 24 /m²) to round-off. A continuous line only delimits the panels.
#[test]
fn a_panel_twice_as_thick_has_a_quarter_of_the_stress_per_moment() {
    let body = format!(
        "[[joint]]\nx = 0.0\nkind = \"continuous\"\n[[panel]]\nat = [1.5, 0.0]\nthickness = 0.5\n{WHEEL_MINUS}[[load]]\nkind = \"point\"\nx = 1.0\ny = 0.3\nforce = 1e5\n{BONDED}"
    );
    let a = solve(&slab([24, 12], &body));
    let e = &a.report.elements;
    let f = &a.report.field;
    let mut seen = [0usize; 2];
    for k in 0..e.mx.len() {
        let panel = f.panel[k] as usize;
        let h = [0.25, 0.5][panel];
        // H_p from the model's Δ and ν: round-off.
        assert!(
            (e.thickness[k] - h).abs() < 1e-12,
            "element {k}: {}",
            e.thickness[k]
        );
        if e.mx[k].abs() < 1.0 {
            continue;
        }
        // Bottom face: +6m/H², top −6m/H² (no temperature load).
        let ratio = e.bottom.sx[k] / e.mx[k];
        assert!(
            (ratio - 6.0 / (h * h)).abs() < 1e-9 * ratio.abs(),
            "element {k}: {ratio}"
        );
        assert!((e.top.sy[k] + 6.0 * e.my[k] / (h * h)).abs() <= 1e-9 * e.top.sy[k].abs().max(1.0));
        seen[panel] += 1;
    }
    assert!(seen[0] > 0 && seen[1] > 0, "both panels bend: {seen:?}");
}

/// Free joints on Winkler leave the panels independent, so the elements next to the joint —
/// on both sides — carry the moments of each panel solved alone as its own scene (the same
/// element size, loads shifted), and the + side's node copies its deflections: bonded and
/// unbonded (the exact active-set QP), to round-off (1e-9 relative of the largest moment).
/// Before step 6 the + side's elements read the − side's copies on the joint.
#[test]
fn element_moments_beside_a_free_joint_are_the_panel_solved_alone() {
    // The joint at x = 1.5 m: panels [−3, 1.5] (18 elements) and [1.5, 3] (6 elements).
    let free = "[[joint]]\nx = 1.5\nkind = \"free\"\n";
    let whole_loads = "[[load]]\nkind = \"uniform\"\npressure = 6e3\n[[load]]\nkind = \"point\"\nx = 1.2\ny = 0.4\nforce = 2e5\n[[load]]\nkind = \"patch\"\nx = [1.5, 1.9]\ny = [-0.5, 0.1]\npressure = 4e5\n";
    // The right panel alone is 1.5 m long, centred at x = 2.25.
    let right_loads = "[[load]]\nkind = \"uniform\"\npressure = 6e3\n[[load]]\nkind = \"patch\"\nx = [-0.75, -0.35]\ny = [-0.5, 0.1]\npressure = 4e5\n";
    let left_loads = "[[load]]\nkind = \"uniform\"\npressure = 6e3\n[[load]]\nkind = \"point\"\nx = 1.95\ny = 0.4\nforce = 2e5\n";
    for contact in ["bonded", "unbonded"] {
        let solver = format!("[solver]\ncontact = \"{contact}\"\nmethod = \"qp\"\n");
        let whole = solve(&slab([24, 12], &format!("{free}{whole_loads}{solver}")));
        let right = solve(
            &slab([6, 12], &format!("{right_loads}{solver}"))
                .replace("length = 6.0", "length = 1.5"),
        );
        let left = solve(
            &slab([18, 12], &format!("{left_loads}{solver}"))
                .replace("length = 6.0", "length = 4.5"),
        );
        let (w, r, l) = (&whole.report, &right.report, &left.report);
        let scale = common::max_abs(&w.elements.mx).max(common::max_abs(&w.elements.my));
        for j in 0..12 {
            for (name, a, b) in [
                ("mx +", w.elements.mx[18 + j * 24], r.elements.mx[j * 6]),
                ("my +", w.elements.my[18 + j * 24], r.elements.my[j * 6]),
                (
                    "mx −",
                    w.elements.mx[17 + j * 24],
                    l.elements.mx[17 + j * 18],
                ),
                (
                    "my −",
                    w.elements.my[17 + j * 24],
                    l.elements.my[17 + j * 18],
                ),
            ] {
                assert!(
                    (a - b).abs() <= 1e-9 * scale,
                    "{contact} {name} row {j}: jointed {a} vs alone {b}"
                );
            }
            // The + copies on the joint are the right panel's left edge.
            let c = w.field.element_nodes(18, j);
            let alone = r.field.element_nodes(0, j);
            for (k, m) in [(c[0], alone[0]), (c[3], alone[3])] {
                let (a, b) = (w.field.w[k], r.field.w[m]);
                assert!(
                    (a - b).abs() <= 1e-9 * common::max_abs(&w.field.w),
                    "{contact} w row {j}: {a} vs {b}"
                );
            }
        }
    }
}

/// The solve table has one line per joint, with its LTE, and a plate without joints none.
#[test]
fn the_solve_table_has_a_line_per_joint() {
    let two = format!("{DOWELS}[[joint]]\ny = 0.5\nkind = \"tied\"\nname = \"L1\"\nstiffness = 1e9\nrotational_stiffness = 1e7\n{WHEEL_MINUS}{BONDED}");
    let a = solve(&slab([24, 12], &two));
    let table = liftoff::output::tables::solve_table(&a.summary, None);
    let lines: Vec<&str> = table
        .lines()
        .filter(|l| l.starts_with("  joint "))
        .collect();
    assert_eq!(lines.len(), 2, "{table}");
    assert!(lines[0].contains("T1") && lines[0].contains("dowels") && lines[0].contains("bars"));
    assert!(lines[1].contains("L1") && lines[1].contains("tied") && lines[1].contains("moment"));
    let tied = joint(&a.report, "L1");
    assert!(tied.max_moment_per_length.is_some_and(|m| m > 0.0));
    let plain = solve(&slab([24, 12], &format!("{WHEEL_MINUS}{BONDED}")));
    let table = liftoff::output::tables::solve_table(&plain.summary, None);
    assert!(!table.contains("  joint "), "{table}");
    assert!(!plain
        .summary
        .to_json()
        .expect("json")
        .contains("\"joints\""));
}

/// A reduced model reports the whole plate: with a layout mirror-symmetric about both axes
/// (doweled joints x = ±1.5 m, a bar on the symmetry line y = 0 that the quarter model holds
/// with half its spring, aggregate joints y = ±0.75 m) and a load symmetric about both, the
/// quarter model's report — every node copy mirrored from the model's, every element, every
/// joint — equals the whole plate solved without symmetry, to round-off (two direct solves of
/// different systems: 1e-9 of each field's largest value).
#[test]
fn a_reduced_model_reports_the_whole_jointed_plate() {
    let layout = "[[joint]]\nx = -1.5\nkind = \"dowels\"\nname = \"W\"\npositions = [-1.0, 0.0, 1.0]\ndiameter = 0.032\nyoungs_modulus = 200e9\nopening = 0.006\nsupport_modulus = 4.07e11\n[[joint]]\nx = 1.5\nkind = \"dowels\"\nname = \"E\"\npositions = [-1.0, 0.0, 1.0]\ndiameter = 0.032\nyoungs_modulus = 200e9\nopening = 0.006\nsupport_modulus = 4.07e11\n[[joint]]\ny = -0.75\nkind = \"aggregate\"\nname = \"S\"\nstiffness = 2e8\n[[joint]]\ny = 0.75\nkind = \"aggregate\"\nname = \"N\"\nstiffness = 2e8\n";
    let loads = "[[load]]\nkind = \"uniform\"\npressure = 6e3\n[[load]]\nkind = \"patch\"\nx = [-1.75, -1.25]\ny = [-0.25, 0.25]\npressure = 4e5\n[[load]]\nkind = \"patch\"\nx = [1.25, 1.75]\ny = [-0.25, 0.25]\npressure = 4e5\n";
    let full = solve(&slab([24, 12], &format!("{layout}{loads}{BONDED}")));
    let quarter = solve(
        &slab([24, 12], &format!("{layout}{loads}{BONDED}"))
            .replace("symmetry = \"none\"", "symmetry = \"auto\""),
    );
    assert_eq!(quarter.summary.symmetry, "quarter");
    let (a, b) = (&full.report, &quarter.report);
    assert_eq!(a.field.n_nodes(), b.field.n_nodes());
    for (name, x, y) in [
        ("w", &a.field.w, &b.field.w),
        ("psi_x", &a.field.psi_x, &b.field.psi_x),
        ("psi_y", &a.field.psi_y, &b.field.psi_y),
        ("pressure", &a.field.pressure, &b.field.pressure),
        ("mx", &a.elements.mx, &b.elements.mx),
        ("my", &a.elements.my, &b.elements.my),
        ("qx", &a.elements.qx, &b.elements.qx),
    ] {
        let d = common::max_abs_diff(x, y);
        assert!(d <= 1e-9 * common::max_abs(x), "{name}: {d:e}");
    }
    assert_eq!(a.joints.len(), 4);
    let force = 4e5 * 0.5 * 0.5 * 2.0 + 6e3 * 18.0;
    for (p, q) in a.joints.iter().zip(&b.joints) {
        assert_eq!(p.name, q.name);
        assert!(
            (p.transferred_force - q.transferred_force).abs() <= 1e-9 * force,
            "{}",
            p.name
        );
        assert!(
            (p.lte_deflection - q.lte_deflection).abs() <= 1e-9,
            "{}",
            p.name
        );
        assert_eq!(p.dowels.len(), q.dowels.len());
        for (d, e) in p.dowels.iter().zip(&q.dowels) {
            assert!(
                (d.force - e.force).abs() <= 1e-9 * force,
                "{} bar {}",
                p.name,
                d.bar
            );
        }
    }
    // The mirror images: W's bars carry E's forces, S's transfer is −N's (N hands from the
    // − side, inside, to the + side, outside; S the other way).
    let (w, e) = (joint(b, "W"), joint(b, "E"));
    assert!((w.transferred_force + e.transferred_force).abs() <= 1e-9 * force);
    let (s, n) = (joint(b, "S"), joint(b, "N"));
    assert!((s.transferred_force + n.transferred_force).abs() <= 1e-9 * force);
    assert!(
        e.transferred_force.abs() > 1e-3 * force,
        "the bars carry load"
    );
}
