//! The PCA's erosion damage of `liftoff damage` (issue 33): at every panel corner, the corner
//! deflection each pass causes, summed through EB109's erosion relation — checked against a sum
//! this test makes by hand from solves of the scene at the same positions, with the relation
//! written out here from its published form (Huang, *Pavement Analysis and Design*, 2nd ed.,
//! the PCA method, restating PCAPAV).

use liftoff::study::{damage, damage_merge, damage_part, Damage, DamagePart};
use liftoff::{analyse, Monitor, Problem};

/// Two 4.5 m × 3.6 m slabs, 0.25 m, doweled at x = 0, on Winkler springs (k = 80 MN/m³), with
/// self-weight and an ESAL axle named `single` (replaced by `{axle}`), and `{extra}`.
fn slabs(axle: &str, extra: &str) -> String {
    format!(
        r#"title = "two slabs"
[plate]
length = 9.0
width = 3.6
thickness = 0.25
youngs_modulus = 30e9
poissons_ratio = 0.15
thermal_expansion = 1.0e-5
[foundation]
model = "winkler"
modulus = 8.0e7
[[joint]]
x = 0.0
kind = "dowels"
diameter = 0.032
youngs_modulus = 200e9
opening = 0.006
support_modulus = 4.07e11
spacing = 0.3
[[load]]
kind = "uniform"
pressure = 6.0e3
{axle}
{extra}
[mesh]
elements = [36, 16]
[solver]
contact = "unbonded"
"#
    )
}

const AXLE: &str = "[[load]]\nkind = \"axle\"\nname = \"single\"\nstandard = \"esal-single-dual\"\nx = 0.0\ny = 0.0\n";

/// One 80 kN level, the outer tire 0.1 m from the edge, day and night, five positions a pass.
const PLAN: &str = r#"[traffic]
design_life = 10
[traffic.wander]
mean = 0.1
deviation = 0.0
positions = 1
[[traffic.group]]
load = "single"
levels = [80e3]
repetitions = [1.0e5]
[climate]
[[climate.bin]]
difference = 8.0
share = 0.6
[[climate.bin]]
difference = -6.0
share = 0.4
[damage]
model = "pca"
modulus_of_rupture = 4.5e6
steps = 5
"#;

fn run(text: &str) -> Damage {
    let p = Problem::from_toml(text).expect("scene");
    damage(&p, &Monitor::NONE).expect("damage")
}

/// EB109's erosion relation in its published units, written out: w in in, k in pci, h in in.
fn erosion_n(w_m: f64, k_si: f64, h_m: f64) -> f64 {
    let inch: f64 = 0.0254;
    let pci = 0.453_592_37 * 9.806_65 / inch.powi(3);
    let (w, k, h) = (w_m / inch, k_si / pci, h_m / inch);
    if w <= 0.0 {
        return f64::INFINITY;
    }
    let p = k * w;
    let power = 268.7 * p * p / (h * k.powf(0.73));
    // C1 = 1: an untreated subbase.
    if power <= 9.0 {
        return f64::INFINITY;
    }
    10f64.powf(14.524 - 6.777 * (power - 9.0).powf(0.103))
}

/// The deflection at (x, y) of the scene solved, read 1e-12 m inside the panel on the side of
/// (sx, sy) — each slab's own deflection at a corner on the joint; the reading's slope error,
/// ~1e-3 × 1e-12 m, is far below the solver's tolerance.
fn corner_deflections(text: &str, corners: &[(f64, f64, f64, f64)]) -> Vec<f64> {
    let a = analyse(&Problem::from_toml(text).expect("scene")).expect("solve");
    assert!(a.summary.converged);
    let f = &a.report.field;
    corners
        .iter()
        .map(|&(x, y, sx, sy)| {
            f.at(&f.w, x + sx * 1e-12, y + sy * 1e-12)
                .expect("on plate")
        })
        .collect()
}

/// The run's erosion at the eight panel corners (two slabs, each side of the joint its own) is
/// C2 Σ n/N by hand: for each climate bin, the deflection the axle causes at a corner is the
/// largest over the pass's five positions of the scene solved with the axle there and the
/// bin's temperature difference, less the scene solved with the difference alone; N from the
/// relation above; n = 1e5 × 10 years × the bin's share. Both sides read the same solves, so
/// they agree to the solver's tolerance (1e-10 of the deflections, raised to the relation's
/// local power of about 10 in w: 1e-8 of the damage).
#[test]
fn erosion_is_the_hand_sum_of_the_corner_deflections() {
    let d = run(&slabs(AXLE, PLAN));
    assert!(d.complete, "{:?}", d.missing);
    assert_eq!(d.erosion_note, None);
    let e = d
        .erosion
        .as_ref()
        .expect("a PCA run on Winkler soil sums erosion");
    assert_eq!(e.c2, 1.0);
    assert!((e.k - 8.0e7).abs() <= 1e-6 * 8.0e7, "k {}", e.k);
    assert_eq!(e.corners.len(), 8, "four corners of each slab");
    let corners: Vec<(f64, f64, f64, f64)> = e
        .corners
        .iter()
        .map(|c| {
            assert!((c.corner.thickness - 0.25).abs() < 1e-12);
            // The panel lies on the side of the corner towards the slab's centre.
            let centre = if c.corner.panel == "(1, 1)" {
                -2.25
            } else {
                2.25
            };
            let sx = if centre > c.corner.x { 1.0 } else { -1.0 };
            let sy = if c.corner.y < 0.0 { 1.0 } else { -1.0 };
            (c.corner.x, c.corner.y, sx, sy)
        })
        .collect();
    // The joint's corners are read on both sides.
    let on_joint = e.corners.iter().filter(|c| c.corner.x.abs() < 1e-9).count();
    assert_eq!(on_joint, 4);
    let mut hand = vec![0.0; corners.len()];
    for (pass, (dt, share)) in d.passes.iter().zip([(8.0, 0.6), (-6.0, 0.4)]) {
        assert_eq!(pass.difference, Some(dt));
        let temperature = format!("[[load]]\nkind = \"temperature\"\ndifference = {dt}\n");
        let rest = corner_deflections(&slabs(&temperature, ""), &corners);
        let mut caused = vec![f64::NEG_INFINITY; corners.len()];
        for &[x, y] in &pass.positions {
            let axle = AXLE.replace("x = 0.0\ny = 0.0\n", &format!("x = {x:e}\ny = {y:e}\n"));
            let w = corner_deflections(&slabs(&format!("{axle}{temperature}"), ""), &corners);
            for j in 0..w.len() {
                caused[j] = caused[j].max(w[j] - rest[j]);
            }
        }
        let reps = 1.0e5 * 10.0 * share;
        for j in 0..corners.len() {
            hand[j] += reps / erosion_n(caused[j], 8.0e7, 0.25);
        }
        // The pass's largest caused deflection among the corners that count: not the plate's
        // ends, x = ±4.5 m, where the model cuts a lane that goes on.
        let largest = (caused.iter().zip(&corners))
            .filter(|(_, c)| c.0.abs() < 4.5 - 1e-9)
            .map(|(w, _)| *w)
            .fold(f64::NEG_INFINITY, f64::max);
        let pe = pass.erosion.expect("the pass's erosion");
        assert!(
            (pe.deflection - largest).abs() <= 1e-9 * largest,
            "{} vs {largest}: {caused:?}",
            pe.deflection
        );
    }
    let scale = hand.iter().cloned().fold(0.0, f64::max);
    assert!(scale > 0.0, "the hand sum has erosion");
    for (j, c) in e.corners.iter().enumerate() {
        assert!(
            (c.damage - hand[j]).abs() <= 1e-8 * scale,
            "corner {j} {:?}: {} vs {}",
            corners[j],
            c.damage,
            hand[j]
        );
    }
    // The plate's ends do not count (the model cuts the lane there): the joint's corners at
    // the lane's edge govern, the axle passing within 0.1 m of them; the ends' corners take
    // more (free corners no pavement has) and are written, but not counted.
    for c in &e.corners {
        assert_eq!(c.corner.counted, c.corner.x.abs() < 1e-9, "{:?}", c.corner);
    }
    let g = &e.corners[e.governing.expect("governing")];
    assert!(g.corner.x.abs() < 1e-9 && (g.corner.y + 1.8).abs() < 1e-9);
    let (end, at_end) = e.uncounted().expect("the ends' corners");
    assert!(at_end > g.damage, "the free end's corner erodes most");
    assert!((e.corners[end].corner.x.abs() - 4.5).abs() < 1e-9);
    assert_eq!(e.damage(), g.damage);
    // The passes' shares at the governing corner add up to its damage.
    let shares: f64 = d
        .passes
        .iter()
        .map(|p| p.erosion.map_or(0.0, |e| e.share))
        .sum();
    assert!((shares - g.damage).abs() <= 1e-12 * g.damage);
}

/// `[traffic] ends = "free"` counts the plate's ends: the corners' damage is the same
/// (every corner is summed either way), the governing corner is now a far end of the plate at
/// the lane's edge, the largest of all; and a plate without transverse joints (one slab) counts
/// its corners without being told.
#[test]
fn free_ends_count_where_asked_and_on_a_slab_alone() {
    let cut = run(&slabs(AXLE, PLAN));
    let ends = run(&slabs(
        AXLE,
        &PLAN.replace("design_life = 10", "design_life = 10\nends = \"free\""),
    ));
    let (a, b) = (
        cut.erosion.expect("erosion"),
        ends.erosion.expect("erosion"),
    );
    assert!(b.corners.iter().all(|c| c.corner.counted));
    assert!(b.uncounted().is_none());
    for (x, y) in a.corners.iter().zip(&b.corners) {
        assert_eq!(x.damage, y.damage);
    }
    let g = &b.corners[b.governing.expect("governing")];
    assert!((g.corner.x.abs() - 4.5).abs() < 1e-9 && (g.corner.y + 1.8).abs() < 1e-9);
    let all = b.corners.iter().map(|c| c.damage).fold(0.0, f64::max);
    assert_eq!(b.damage(), all);
    assert!(b.damage() > a.damage());
    // One slab: no transverse joint, every corner counts.
    let alone = slabs(AXLE, PLAN)
        .replace("length = 9.0", "length = 4.5")
        .replace(
            "[[joint]]\nx = 0.0\nkind = \"dowels\"",
            "[[joint]]\ny = 0.0\nkind = \"dowels\"",
        )
        .replace("elements = [36, 16]", "elements = [18, 16]");
    let e = run(&alone).erosion.expect("erosion");
    assert!(e.corners.iter().all(|c| c.corner.counted), "a slab alone");
}

/// EB109's C2 scales the erosion and nothing else.
#[test]
fn erosion_c2_scales_the_erosion_alone() {
    let one = run(&slabs(AXLE, PLAN));
    let c2 = run(&slabs(
        AXLE,
        &format!("{PLAN}[damage.coefficients]\nerosion_c2 = 0.06\n"),
    ));
    let (a, b) = (one.erosion.expect("erosion"), c2.erosion.expect("erosion"));
    for (x, y) in a.corners.iter().zip(&b.corners) {
        assert!((0.06 * x.damage - y.damage).abs() <= 1e-12 * x.damage.max(1e-300));
    }
    assert_eq!(one.bottom, c2.bottom);
}

/// The middle levels' corner deflections are interpolated where the ends' contact sets agree,
/// exactly: the erosion equals a run that solves every level, to the solver's tolerance.
#[test]
fn interpolated_levels_give_the_solved_erosion() {
    let plan = PLAN
        .replace("levels = [80e3]", "levels = [70e3, 80e3, 110e3]")
        .replace(
            "repetitions = [1.0e5]",
            "repetitions = [1.0e5, 1.0e5, 1.0e4]",
        )
        .replace("difference = 8.0", "difference = 1.5");
    let fast = run(&slabs(AXLE, &plan));
    let direct = run(&slabs(
        AXLE,
        &plan.replace("steps = 5", "steps = 5\ninterpolate = false"),
    ));
    assert!(fast.interpolated > 0, "some positions interpolated");
    assert_eq!(direct.interpolated, 0);
    let (a, b) = (
        fast.erosion.expect("erosion"),
        direct.erosion.expect("erosion"),
    );
    let scale = b.corners.iter().map(|c| c.damage).fold(0.0, f64::max);
    assert!(scale > 0.0);
    for (x, y) in a.corners.iter().zip(&b.corners) {
        assert!(
            (x.damage - y.damage).abs() <= 1e-8 * scale,
            "{} vs {}",
            x.damage,
            y.damage
        );
        assert!((x.deflection - y.deflection).abs() <= 1e-9 * y.deflection.abs().max(1e-6));
    }
}

/// A cluster's parts carry the corners' deflections: the merged erosion is the whole run's, to
/// the bit.
#[test]
fn parts_carry_the_erosion() {
    let p = Problem::from_toml(&slabs(AXLE, PLAN)).expect("scene");
    let whole = damage(&p, &Monitor::NONE).expect("damage");
    let part = |f: &[usize]| {
        let bytes = damage_part(&p, f, &Monitor::NONE).expect("part").to_bytes();
        DamagePart::from_bytes(&bytes).expect("bytes")
    };
    let merged = damage_merge(&p, vec![part(&[1]), part(&[0])]).expect("merge");
    let (a, b) = (
        merged.erosion.expect("erosion"),
        whole.erosion.expect("erosion"),
    );
    for (x, y) in a.corners.iter().zip(&b.corners) {
        assert_eq!((x.damage, x.deflection), (y.damage, y.deflection));
    }
}

/// On a continuum soil there is no k to read: the run sums the fatigue and says why it has no
/// erosion, rather than invent a k.
#[test]
fn a_soil_without_k_says_why_it_has_no_erosion() {
    let text = slabs(AXLE, &PLAN.replace("steps = 5", "steps = 2"))
        .replace(
            "model = \"winkler\"\nmodulus = 8.0e7",
            "model = \"half-space\"\nyoungs_modulus = 100e6\npoissons_ratio = 0.35",
        )
        .replace("elements = [36, 16]", "elements = [18, 8]");
    let d = run(&text);
    assert!(d.erosion.is_none());
    let note = d.erosion_note.expect("a note");
    assert!(note.contains("Winkler k"), "{note}");
    assert!(d.governing_bottom.damage.is_finite());
}

/// A PCA run's files: erosion.csv has a row per corner with the run's damage, the erosion map is
/// written beside the damage maps, and the report shows the governing corner and inlines all
/// three maps.
#[test]
fn the_files_and_the_report_show_the_erosion() {
    let d = run(&slabs(AXLE, PLAN));
    let e = d.erosion.as_ref().expect("erosion");
    let dir = tempfile::tempdir().expect("tempdir");
    liftoff::output::damage::write_damage(dir.path(), &d, "two slabs").expect("files");
    for name in ["erosion.csv", "erosion.svg", "erosion.png"] {
        assert!(dir.path().join(name).is_file(), "{name}");
    }
    let text = std::fs::read_to_string(dir.path().join("erosion.csv")).expect("csv");
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("panel,x [m],y [m],thickness [m],deflection [m],damage,counted")
    );
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), e.corners.len());
    for (row, c) in rows.iter().zip(&e.corners) {
        let mut cells = row.rsplit(',');
        let counted = cells.next().expect("counted") == "1";
        let damage: f64 = cells.next().expect("damage").parse().expect("number");
        assert_eq!(damage, c.damage, "{row}");
        assert_eq!(counted, c.corner.counted, "{row}");
        assert!(row.starts_with(&format!("\"{}\"", c.corner.panel)), "{row}");
    }
    let page = liftoff::output::report::write_report(dir.path(), None).expect("report");
    let html = std::fs::read_to_string(page).expect("page");
    assert!(html.contains("erosion (PCA, C2 Σ n/N)"), "the erosion row");
    assert_eq!(html.matches("<svg").count(), 3, "three maps inline");
    // Each quarter of a panel shows its corner: every element takes one counted corner's
    // damage, or none (NaN) in the quarters of the plate's ends, x beyond ±2.25 m.
    let by = e.by_element(&d.x, &d.y);
    for (v, x) in by.iter().zip(&d.x) {
        match x.abs() > 2.25 {
            true => assert!(v.is_nan(), "{x}: {v}"),
            false => assert!(e.corners.iter().any(|c| c.corner.counted && c.damage == *v)),
        }
    }
}
