//! `liftoff damage` (issue 33): the Miner sum over the passes of a traffic and climate plan,
//! checked against a sum this test makes by hand from the stresses that solves of the scene
//! report at the same positions, and the places the literature puts the damage.

use liftoff::study::{damage, Damage};
use liftoff::{analyse, Monitor, Problem};

/// A 4.5 m × 3.6 m slab, 0.25 m, on Winkler springs, with self-weight and an ESAL axle (80 kN,
/// dual tires) named `single`; `{extra}` adds the damage sections.
fn slab(extra: &str) -> String {
    format!(
        r#"title = "slab"
[plate]
length = 4.5
width = 3.6
thickness = 0.25
youngs_modulus = 30e9
poissons_ratio = 0.15
thermal_expansion = 1.0e-5
[foundation]
model = "winkler"
modulus = 8.0e7
[[load]]
kind = "uniform"
pressure = 6.0e3
[[load]]
kind = "axle"
name = "single"
standard = "esal-single-dual"
x = 0.0
y = 0.0
{extra}
[mesh]
elements = [30, 24]
[solver]
contact = "unbonded"
"#
    )
}

/// `example:pavement-damage` — a lane of three doweled 4.5 m slabs, joints at x = ±2.25 m —
/// with 31 positions a pass (one every 0.44 m: the tests' places, at a sixth of the cost).
fn lane() -> String {
    liftoff::examples::SCENES
        .iter()
        .find(|(n, _, _)| *n == "pavement-damage")
        .map(|(_, _, t)| t.replace("reliability = 0.9", "reliability = 0.9\nsteps = 31"))
        .expect("bundled")
}

/// One group at the axle's own 80 kN, one lateral position, two climate bins, three positions a
/// pass: two passes to sum by hand.
const TWO_BINS: &str = r#"[traffic]
design_life = 10
growth = 0.0
[traffic.wander]
mean = 0.4
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
model = "mepdg"
modulus_of_rupture = 4.5e6
steps = 3
"#;

fn run(text: &str) -> Damage {
    let p = Problem::from_toml(text).expect("scene");
    damage(&p, &Monitor::NONE).expect("damage")
}

/// Both damage maps of `a` equal `b`'s to 1e-9 of `b`'s largest damage (the solver's
/// tolerance between two runs of one problem, ~1e-10 of the stresses, raised to the relation's
/// power), and `b` has damage somewhere.
fn same_maps(a: &Damage, b: &Damage) {
    let scale = b
        .bottom
        .iter()
        .chain(&b.top)
        .fold(0.0_f64, |m, v| m.max(*v));
    assert!(scale > 0.0);
    for (x, y) in a
        .bottom
        .iter()
        .zip(&b.bottom)
        .chain(a.top.iter().zip(&b.top))
    {
        assert!((x - y).abs() <= 1e-9 * scale, "{x} vs {y}");
    }
}

/// `slab`'s scene marked as US with the plate's sides and thickness in inches (the values the
/// caller converts besides are its own).
fn us_plate(text: &str) -> String {
    let inch = 0.0254;
    text.replace("title = \"slab\"", "title = \"slab\"\nunits = \"us\"")
        .replace("length = 4.5", &format!("length = {}", 4.5 / inch))
        .replace("width = 3.6", &format!("width = {}", 3.6 / inch))
        .replace("thickness = 0.25", &format!("thickness = {}", 0.25 / inch))
}

/// The MEPDG's allowed repetitions, written out from the Manual of Practice's relation as
/// issue 33 pins it: log10 N = 2.0 (MR/σ)^1.22 + 0.4371.
fn mepdg_n(stress: f64, mr: f64) -> f64 {
    if stress <= 0.0 {
        f64::INFINITY
    } else {
        10f64.powf(2.0 * (mr / stress).powf(1.22) + 0.4371)
    }
}

/// The damage maps (bottom, top) of `d`'s passes summed by hand: for each pass, the scene
/// solved with the axle standing at each of its positions and the pass's temperature
/// difference as a load of its own (what `liftoff solve` of that scene reports), the largest
/// σ₁ per element and face over the positions, and its damage per cycle `per_cycle(σ)` times
/// the pass's repetitions.
fn hand_sum(d: &Damage, per_cycle: &dyn Fn(f64) -> f64) -> (Vec<f64>, Vec<f64>) {
    let n = d.x.len();
    let mut bottom = vec![0.0; n];
    let mut top = vec![0.0; n];
    for pass in &d.passes {
        let dt = pass.difference.expect("a climate bin's difference");
        let mut peak_b = vec![f64::NEG_INFINITY; n];
        let mut peak_t = vec![f64::NEG_INFINITY; n];
        for &[x, y] in &pass.positions {
            let text = slab("").replace(
                "x = 0.0\ny = 0.0\n",
                &format!(
                    "x = {x:e}\ny = {y:e}\n[[load]]\nkind = \"temperature\"\ndifference = {dt}\n"
                ),
            );
            let a = analyse(&Problem::from_toml(&text).expect("scene")).expect("solve");
            assert!(a.summary.converged);
            let e = &a.report.elements;
            for i in 0..n {
                peak_b[i] = peak_b[i].max(e.bottom.s1[i]);
                peak_t[i] = peak_t[i].max(e.top.s1[i]);
            }
        }
        for i in 0..n {
            bottom[i] += pass.repetitions * per_cycle(peak_b[i]);
            top[i] += pass.repetitions * per_cycle(peak_t[i]);
        }
    }
    (bottom, top)
}

/// `d`'s maps equal the hand sums to `tol` of the largest hand damage, which is not zero.
fn maps_are(d: &Damage, (bottom, top): (Vec<f64>, Vec<f64>), tol: f64) {
    let scale = bottom.iter().chain(&top).fold(0.0_f64, |m, v| m.max(*v));
    assert!(scale > 0.0, "the hand sum has damage");
    for i in 0..d.x.len() {
        assert!(
            (d.bottom[i] - bottom[i]).abs() <= tol * scale,
            "bottom, element {i}: {} vs {}",
            d.bottom[i],
            bottom[i]
        );
        assert!(
            (d.top[i] - top[i]).abs() <= tol * scale,
            "top, element {i}: {} vs {}",
            d.top[i],
            top[i]
        );
    }
}

/// Two bins summed by hand ([`hand_sum`]): three positions a pass, N from the relation above,
/// n = 1e5 a year × 10 years × the bin's share. The run's map is that sum at every element of
/// both faces; both sides sum the same solves' stresses in the same order, so they agree to
/// round-off (1e-9 of the largest damage allows for the solver's tolerance between a
/// warm-started and a cold solve, ~1e-10 of the stresses, raised to the relation's power, ~12
/// at these stress ratios).
#[test]
fn a_two_bin_spectrum_is_its_hand_sum() {
    let d = run(&slab(TWO_BINS));
    assert!(d.complete, "{:?}", d.missing);
    assert_eq!(d.passes.len(), 2);
    assert!(d.rupture_ratio.is_none());
    for (pass, (dt, share)) in d.passes.iter().zip([(8.0, 0.6), (-6.0, 0.4)]) {
        assert_eq!(pass.positions.len(), 3);
        assert_eq!(pass.difference, Some(dt));
        let reps = 1.0e5 * 10.0 * share;
        assert!((pass.repetitions - reps).abs() <= 1e-9 * reps);
    }
    let hand = hand_sum(&d, &|s| 1.0 / mepdg_n(s, 4.5e6));
    maps_are(&d, hand, 1e-9);
}

/// The modulus of rupture growing with age (`rupture_growth = "mepdg"`), with the traffic
/// growing 4 % a year: the hand sum takes each month of the 10 years, its share of the traffic
/// 1.04^year / Σ, and the MR at its middle, 28 days + (m + ½)/12 years, by the MEPDG's relation
/// written out here, MR(t)/MR₂₈ = 1 + 0.12 log₁₀(t/0.0767) − 0.01566 log₁₀²(t/0.0767); a cycle
/// of σ does Σ share / N(σ, MR(t)). Same tolerance as above. The damage is below the run's
/// with one MR everywhere, by more than the 20 % that MR's gain of 2–18 % makes at these
/// stress ratios (N grows as about the 12th power of MR/σ).
#[test]
fn a_growing_modulus_of_rupture_is_its_monthly_hand_sum() {
    let plan = TWO_BINS
        .replace("growth = 0.0", "growth = 0.04")
        .replace("steps = 3", "steps = 3\nrupture_growth = \"mepdg\"");
    let d = run(&slab(&plan));
    assert!(d.complete, "{:?}", d.missing);
    let [lo, hi] = d.rupture_ratio.expect("growing");
    assert!(lo > 1.0 && hi > 1.18 && hi < 1.19, "{lo} {hi}");
    let months: Vec<(f64, f64)> = (0..120)
        .map(|m| {
            let t: f64 = 0.0767 + (m as f64 + 0.5) / 12.0;
            let l = (t / 0.0767).log10();
            (1.04f64.powi(m / 12), 1.0 + 0.12 * l - 0.01566 * l * l)
        })
        .collect();
    let total: f64 = months.iter().map(|m| m.0).sum();
    let per_cycle = |s: f64| -> f64 {
        months
            .iter()
            .map(|&(w, r)| w / total / mepdg_n(s, 4.5e6 * r))
            .sum()
    };
    let hand = hand_sum(&d, &per_cycle);
    maps_are(&d, hand, 1e-9);
    let flat = run(&slab(&TWO_BINS.replace("growth = 0.0", "growth = 0.04")));
    let most = |d: &Damage| {
        d.bottom
            .iter()
            .chain(&d.top)
            .fold(0.0_f64, |m, v| m.max(*v))
    };
    assert!(
        most(&d) < 0.8 * most(&flat),
        "{} vs {}",
        most(&d),
        most(&flat)
    );
}

/// Day curling with the axle along the free edge puts the bottom-up damage at the middle of
/// that edge (the MEPDG's critical location for bottom-up cracking, NCHRP 1-37A Part 3 Ch. 4;
/// Westergaard's edge case): the governing element lies on the edge row (its centre within one
/// element of y = −b/2) and within an eighth of the slab's length of its middle.
#[test]
fn day_curling_and_edge_loading_govern_at_mid_slab_on_the_edge() {
    // Edge loading: the outer tire's print touches the free edge.
    let plan = TWO_BINS
        .replace("mean = 0.4", "mean = 0.0")
        .replace("steps = 3", "steps = 9")
        .replace(
            "difference = -6.0\nshare = 0.4",
            "difference = 8.0\nshare = 0.4",
        );
    let d = run(&slab(&plan));
    let g = d.governing_bottom;
    let element = 3.6 / 24.0;
    assert!(g.damage > 0.0);
    assert!(g.y < -1.8 + element, "governing at y = {}", g.y);
    assert!(g.x.abs() <= 4.5 / 8.0, "governing at x = {}", g.x);
}

/// Night curling (top 12 K cooler) on the lane of three doweled slabs: the axle's passes load
/// the curled-up ends of the middle slab in turn, which then bears on its middle like a beam
/// on a support, and its top-down damage peaks in its middle half (|x| < 1.125 m of a 4.5 m
/// slab), between the joints — the MEPDG's top-down mechanism, loads near the transverse joints
/// and tension at the top between them (NCHRP 1-37A, Part 3, Chapter 4). The cut's free ends
/// take far more (a cantilever ~1.5 m long) and, not counted, do not govern.
#[test]
fn night_curling_puts_top_down_damage_between_the_joints() {
    let lane = lane();
    let from = lane.find("[climate]").expect("climate");
    let to = lane.find("[damage]").expect("damage");
    let night = format!(
        "{}[climate]\n[[climate.bin]]\ndifference = -12.0\nshare = 1.0\n\n{}",
        &lane[..from],
        &lane[to..]
    );
    let d = run(&night);
    let g = d.governing_top;
    assert!(g.damage > 0.0);
    assert!(
        g.x.abs() < 1.125,
        "top-down in the middle slab's middle half: x = {}",
        g.x
    );
    let (end, at_end) = d.uncounted(&d.top).expect("end panels");
    assert!(at_end > g.damage && d.x[end].abs() > 2.25);
}

/// The lane's outer edge at a joint (`edge_at`, a tied shoulder's, say) instead of the plate's
/// edge: every position of a pass moves across by the edge's distance from the plate's edge,
/// exactly (1e-12 m: the same sums of the same numbers), the wander's offset now counted from
/// the joint; and for `y+`, from the joint on the lane's other side, the same way.
#[test]
fn a_lane_edge_at_a_joint_moves_the_passes_across() {
    let one_bin = TWO_BINS
        .replace("share = 0.6", "share = 1.0")
        .replace("[[climate.bin]]\ndifference = -6.0\nshare = 0.4\n", "");
    let plain = run(&slab(&one_bin));
    for (edge, at, shift) in [("y-", -1.0, 0.8), ("y+", 1.2, -0.6)] {
        let moved = run(&slab(&one_bin.replace(
            "growth = 0.0",
            &format!("growth = 0.0\nedge = \"{edge}\"\nedge_at = {at}"),
        )));
        let base = if edge == "y-" {
            plain.passes[0].positions.clone()
        } else {
            // The y+ pass along the plate's own edge.
            let mirrored = run(&slab(
                &one_bin.replace("growth = 0.0", "growth = 0.0\nedge = \"y+\""),
            ));
            mirrored.passes[0].positions.clone()
        };
        let p = &moved.passes[0].positions;
        assert_eq!(p.len(), base.len());
        for (a, b) in p.iter().zip(&base) {
            assert!((a[0] - b[0]).abs() < 1e-12, "{edge}: x {a:?} vs {b:?}");
            assert!(
                (a[1] - b[1] - shift).abs() < 1e-12,
                "{edge}: y {a:?} vs {b:?}"
            );
        }
    }
}

/// Bad plans are refused naming the key: a group that names no axle, shares that do not add up,
/// an unknown relation.
#[test]
fn bad_plans_name_the_key() {
    let err = |text: &str| {
        Problem::from_toml(&slab(text))
            .expect_err("refused")
            .to_string()
    };
    let e = err(&TWO_BINS.replace("load = \"single\"", "load = \"tandem\""));
    assert!(
        e.contains("traffic.group[0].load") && e.contains("single"),
        "{e}"
    );
    let e = err(&TWO_BINS.replace("share = 0.4", "share = 0.5"));
    assert!(e.contains("climate.bin") && e.contains("1.1"), "{e}");
    let e = err(&TWO_BINS.replace("model = \"mepdg\"", "model = \"aashto93\""));
    assert!(e.contains("damage.model"), "{e}");
    let e = err(&TWO_BINS.replace("steps = 3", "steps = 3\n[damage.coefficients]\nc9 = 1.0"));
    assert!(e.contains("damage.coefficients") && e.contains("c9"), "{e}");
    let e = err(&TWO_BINS.replace("design_life = 10", "design_life = -1"));
    assert!(e.contains("traffic.design_life"), "{e}");
}

/// The same run written in US units — every length in inches, the levels in lbf, the modulus
/// of rupture and E in psi, the subgrade in pci, the differences in °F, converted here from the
/// SI scene by the definitions (1 in = 0.0254 m, 1 lbf = 4.4482216152605 N) — gives the same
/// damage at every element (1e-9 of the largest: the two runs solve the same problems), and
/// damage.json reports its places in inches.
#[test]
fn a_us_plan_is_its_si_twin() {
    const IN: f64 = 0.0254;
    const LBF: f64 = 4.448_221_615_260_5;
    let psi = LBF / (IN * IN);
    // The lane's edge at y = −1 m too: a length of [traffic].
    let si = slab(&TWO_BINS.replace("growth = 0.0", "growth = 0.0\nedge_at = -1.0"));
    let us = us_plate(&si)
        .replace("edge_at = -1.0", &format!("edge_at = {}", -1.0 / IN))
        .replace(
            "youngs_modulus = 30e9",
            &format!("youngs_modulus = {}", 30e9 / psi),
        )
        .replace(
            "thermal_expansion = 1.0e-5",
            &format!("thermal_expansion = {}", 1.0e-5 / 1.8),
        )
        .replace(
            "modulus = 8.0e7",
            &format!("modulus = {}", 8.0e7 / (psi / IN)),
        )
        .replace("pressure = 6.0e3", &format!("pressure = {}", 6.0e3 / psi))
        .replace("mean = 0.4", &format!("mean = {}", 0.4 / IN))
        .replace("levels = [80e3]", &format!("levels = [{}]", 80e3 / LBF))
        .replace("difference = 8.0", &format!("difference = {}", 8.0 * 1.8))
        .replace("difference = -6.0", &format!("difference = {}", -6.0 * 1.8))
        .replace(
            "modulus_of_rupture = 4.5e6",
            &format!("modulus_of_rupture = {}", 4.5e6 / psi),
        );
    // The twin does not warn; its level typed in newtons (80 000 "lbf", 4.45 times the axle's
    // own 17 985 lbf) does, naming the slip.
    assert!(Problem::from_toml(&us).expect("scene").warnings.is_empty());
    let newtons = us.replace(&format!("levels = [{}]", 80e3 / LBF), "levels = [80e3]");
    let warnings = Problem::from_toml(&newtons).expect("scene").warnings;
    assert!(
        warnings.iter().any(|w| w
            .starts_with("traffic.group[0].levels: a level of 80000 lbf is 4.45× `single`'s own load of 17985 lbf")
            && w.contains("newtons typed where pounds were meant")),
        "{warnings:?}"
    );
    let (a, b) = (run(&us), run(&si));
    same_maps(&a, &b);
    let r = a.reported();
    assert!((r.governing_bottom.x * IN - b.governing_bottom.x).abs() < 1e-9);
    assert!((r.rupture - 4.5e6 / psi).abs() < 1e-9 * r.rupture);
    assert_eq!(r.passes[0].difference, Some(8.0 * 1.8));
    // The run names its passes in the scene's units: an opening of 0.3 m × 0.6 m under the
    // lane's outer tire (0.4 m = 15.7 in from the edge at y = −1 m), written in inches on the
    // 0.15 m grid, refuses the lane in inches — SI's words would be a unit the user never typed.
    // (31 positions a pass, one every 0.14 m: three would step over the opening.)
    let holed = format!(
        "{}\n[[opening]]\nx = [{}, {}]\ny = [{}, {}]\n",
        us.replace("steps = 3", "steps = 31"),
        1.2 / IN,
        1.5 / IN,
        -0.9 / IN,
        -0.3 / IN
    );
    let p = Problem::from_toml(&holed).expect("the scene's own axle stands clear of the opening");
    let Err(err) = damage(&p, &Monitor::NONE).map(|_| ()) else {
        panic!("a print on the opening: the run went through");
    };
    let err = err.to_string();
    assert!(
        err.contains("with its outer tire 15.7 in from the edge (lateral position 1 of 1)")
            && err.contains(" in: a pass crosses the plate")
            && !err.contains(" m "),
        "{err}"
    );
}

/// `design` on the slab with the PCA relation and a damage target: the design curve falls as
/// the slab thickens (thicker slabs, lower stress ratios: a property of the relation and of
/// plate bending, not of the search), the thickness found meets the target, the failing end of
/// its bracket does not, and the bracket is no wider than the tolerance.
#[test]
fn the_design_brackets_the_least_thickness() {
    use liftoff::study::{design, DesignOptions};
    let plan = TWO_BINS
        .replace("model = \"mepdg\"", "model = \"pca\"")
        .replace("repetitions = [1.0e5]", "repetitions = [2.0e5]");
    let text = slab(&plan).replace(
        "pressure = 6.0e3\n",
        "pressure = 6.0e3\ncase = \"self-weight\"\n",
    );
    let file = liftoff::scene::SceneFile::parse(&text).expect("scene");
    let options = DesignOptions {
        from: 0.16,
        to: 0.32,
        points: 5,
        target: Some(1.0),
        tolerance: 0.004,
    };
    let d = design(&file, &options, &Monitor::NONE).expect("design");
    assert!(d.complete);
    assert!(!d.cut, "a slab without transverse joints counts everything");
    assert_eq!(d.measure, "damage");
    let curve: Vec<f64> = d
        .points
        .iter()
        .filter(|p| p.curve)
        .map(|p| p.value)
        .collect();
    assert_eq!(curve.len(), 5);
    assert!(d.monotone, "{curve:?}");
    assert!(curve.windows(2).all(|w| w[1] <= w[0]), "{curve:?}");
    let h = d
        .thickness
        .expect("a thickness in the range meets the target");
    let [lo, hi] = d.bracket.expect("bracketed inside the range");
    assert_eq!(h, hi);
    assert!(hi - lo <= options.tolerance + 1e-12, "bracket {lo} … {hi}");
    let at = |t: f64| {
        d.points
            .iter()
            .find(|p| p.thickness == t)
            .expect("a run there")
    };
    assert!(at(hi).value <= 1.0 && at(hi).passes);
    assert!(at(lo).value > 1.0 && !at(lo).passes);
    // EB109 designs against fatigue and erosion: the value is the larger.
    for p in &d.points {
        let erosion = p.erosion.expect("a PCA run on Winkler soil sums erosion");
        assert_eq!(p.value, p.bottom.max(p.top).max(erosion));
    }
}

/// The report of a damage run's files: the governing damage of each face as damage.json has
/// it, both damage maps inline, and the page self-contained (no reference to anything outside).
#[test]
fn the_report_shows_the_damage_and_its_maps() {
    let d = run(&slab(TWO_BINS));
    let dir = tempfile::tempdir().expect("tempdir");
    liftoff::output::damage::write_damage(dir.path(), &d, "slab").expect("files");
    let page = liftoff::output::report::write_report(dir.path(), None).expect("report");
    let html = std::fs::read_to_string(page).expect("page");
    let json: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.path().join("damage.json")).expect("json"),
    )
    .expect("json");
    let g = json["governing_bottom"]["damage"].as_f64().expect("damage");
    assert!(g > 0.0);
    // The page's bottom-up row: `<td>bottom-up</td><td>1.234e-5</td>`, four significant digits.
    let row = "<td>bottom-up</td><td>";
    let at = html.find(row).expect("the bottom-up row") + row.len();
    let cell = &html[at..at + html[at..].find('<').expect("cell end")];
    let shown: f64 = cell
        .parse()
        .unwrap_or_else(|_| panic!("`{cell}` is a number"));
    assert!(
        (shown - g).abs() <= 5e-4 * g,
        "page {shown} vs damage.json {g}"
    );
    assert_eq!(html.matches("<svg").count(), 2, "both damage maps inline");
    assert!(!html.contains("http://") && !html.contains("https://") && !html.contains("src="));
}

/// A face no pass damages: with the PCA's relation (unlimited repetitions at a stress ratio
/// σ/MR ≤ 0.45, EB109) and a modulus of rupture that puts 0.45 MR between the passes' largest
/// top and bottom stresses, the top map is zero at every element and the bottom map is not —
/// and the summary, the chart and the page say that no place governs the top instead of naming
/// one (an element of zero damage is no more governing than any other).
#[test]
fn a_face_no_pass_damages_has_no_governing_place() {
    let pca = TWO_BINS.replace("model = \"mepdg\"", "model = \"pca\"");
    let first = run(&slab(&pca));
    let peak = |top: bool| {
        (first.passes.iter())
            .map(|p| if top { p.top.stress } else { p.bottom.stress })
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let (top, bottom) = (peak(true), peak(false));
    assert!(
        top < bottom,
        "the day bin's bottom stress governs: {top} vs {bottom}"
    );
    // 0.45 MR halfway between the faces' largest stresses.
    let mr = (top + bottom) / 2.0 / 0.45;
    let d = run(&slab(&pca.replace(
        "modulus_of_rupture = 4.5e6",
        &format!("modulus_of_rupture = {mr}"),
    )));
    assert!(d.top.iter().all(|v| *v == 0.0), "no top-down damage");
    assert!(d.governing_bottom.damage > 0.0, "bottom-up damage");
    let table = liftoff::output::damage::damage_table("slab", &d, None);
    assert!(
        table.contains("top-down   : Σ n/N = 0 everywhere: no pass damages this face"),
        "{table}"
    );
    assert!(table.contains("bottom-up  : Σ n/N = "), "{table}");
    let dir = tempfile::tempdir().expect("tempdir");
    liftoff::output::damage::write_damage(dir.path(), &d, "slab").expect("files");
    let svg = |face: &str| {
        std::fs::read_to_string(dir.path().join(format!("damage-{face}.svg"))).expect("map")
    };
    assert!(svg("top").contains("none anywhere") && !svg("top").contains("governing:"));
    assert!(svg("bottom").contains("governing:"));
    let page = liftoff::output::report::write_report(dir.path(), None).expect("report");
    let html = std::fs::read_to_string(page).expect("page");
    assert!(
        html.contains("none: no pass damages this face"),
        "the page's top-down row"
    );
}

/// A lane of three slabs cut at the plate's ends (`[traffic] ends`, default "cut"): the end
/// panels are the middle one's neighbours and count for nothing — the governing places and the
/// cracking are the largest damage between the two joints, where day curling with edge loading
/// puts the bottom-up damage at the middle slab's mid-edge — while the maps, which do not depend
/// on the key, keep every element and show the cut's free ends damaged more (the reason for the
/// default). With `ends = "free"` every element counts. A plate with one transverse joint has
/// no inner panel: every element counts.
#[test]
fn the_end_panels_of_a_cut_lane_do_not_count() {
    let lane = lane();
    let cut = run(&lane);
    let free = run(&lane.replace("growth = 0.02", "growth = 0.02\nends = \"free\""));
    assert_eq!(cut.bottom, free.bottom, "the maps do not depend on the key");
    assert_eq!(cut.top, free.top);
    // The joints at x = ±2.25 m: the inner panel's elements count, the end panels' do not.
    for (c, x) in cut.counted.iter().zip(&cut.x) {
        assert_eq!(*c, x.abs() < 2.25, "x = {x}");
    }
    assert!(free.counted.iter().all(|c| *c));
    let largest = |d: &Damage, v: &[f64], all: bool| {
        (0..v.len())
            .filter(|&k| all || d.counted[k])
            .map(|k| v[k])
            .fold(0.0_f64, f64::max)
    };
    for (g, v) in [
        (cut.governing_bottom, &cut.bottom),
        (cut.governing_top, &cut.top),
    ] {
        assert_eq!(g.damage, largest(&cut, v, false));
        assert!(
            g.x.abs() < 2.25,
            "governing in the middle slab: x = {}",
            g.x
        );
    }
    // The middle slab's mid-edge (its middle ±0.5 m, the outer row of elements).
    let g = cut.governing_bottom;
    assert!(
        g.x.abs() <= 0.5 && g.y < -1.8 + 0.15,
        "bottom-up at ({}, {})",
        g.x,
        g.y
    );
    assert_eq!(
        free.governing_bottom.damage,
        largest(&free, &free.bottom, true)
    );
    let (end, at_end) = cut.uncounted(&cut.bottom).expect("end panels");
    assert!(
        at_end > g.damage && cut.x[end].abs() > 2.25,
        "the cut's free ends damage more"
    );
    assert_eq!(free.governing_bottom.damage, at_end);
    // Cracking follows the governing damage.
    let (c, f) = (cut.cracking.expect("mepdg"), free.cracking.expect("mepdg"));
    assert!(c.bottom < f.bottom, "{} vs {}", c.bottom, f.bottom);
    // The passes' peaks are the counted elements' too.
    for p in &cut.passes {
        assert!(p.bottom.x.abs() < 2.25 && p.top.x.abs() < 2.25);
    }
    // damage.csv says which elements count; the summary and the page say the ends do not.
    let dir = tempfile::tempdir().expect("tempdir");
    liftoff::output::damage::write_damage(dir.path(), &cut, "lane").expect("files");
    let csv = std::fs::read_to_string(dir.path().join("damage.csv")).expect("csv");
    let column: Vec<bool> = csv.lines().skip(1).map(|l| l.ends_with(",1")).collect();
    assert_eq!(column, cut.counted);
    let vtu = std::fs::read_to_string(dir.path().join("damage.vtu")).expect("vtu");
    assert!(
        vtu.contains("Name=\"counted\""),
        "the VTU's cell data has `counted`"
    );
    let table = liftoff::output::damage::damage_table("lane", &cut, None);
    assert!(table.contains("the end panels, where the model cuts a lane that goes on, not counted"));
    // The maps hatch the end panels, with a legend entry; a free lane's do not.
    let legend = "not counted: the model cuts the lane here";
    let svg = std::fs::read_to_string(dir.path().join("damage-bottom.svg")).expect("svg");
    assert!(svg.contains(legend));
    let open = tempfile::tempdir().expect("tempdir");
    liftoff::output::damage::write_damage(open.path(), &free, "lane").expect("files");
    let free_svg = std::fs::read_to_string(open.path().join("damage-bottom.svg")).expect("svg");
    assert!(!free_svg.contains(legend));
    let page = liftoff::output::report::write_report(dir.path(), None).expect("report");
    let html = std::fs::read_to_string(page).expect("page");
    assert!(html.contains(
        "The end panels, where the model cuts a lane that goes on, are mapped but not counted"
    ));
    // A design of the cut lane says the end panels were left out (two runs: the thinnest meets
    // the target).
    let file = liftoff::scene::SceneFile::parse(&lane).expect("scene");
    let options = liftoff::study::DesignOptions {
        from: 0.40,
        to: 0.42,
        points: 2,
        target: None,
        tolerance: 0.005,
    };
    let d = liftoff::study::design(&file, &options, &Monitor::NONE).expect("design");
    assert!(d.cut);
    let table = liftoff::output::damage::design_table("lane", &d, None);
    assert!(table.contains(
        "note: the end panels, where the model cuts a lane that goes on, are not counted"
    ));
    let out = tempfile::tempdir().expect("tempdir");
    liftoff::output::damage::write_design(out.path(), &d, "lane").expect("files");
    let page = liftoff::output::report::write_report(out.path(), None).expect("report");
    let html = std::fs::read_to_string(page).expect("page");
    assert!(
        html.contains("are not counted in these runs"),
        "the design page says so"
    );
    // One transverse joint: no inner panel, every element counts.
    let two = run(&slab(TWO_BINS).replace(
        "[[load]]\nkind = \"axle\"",
        "[[joint]]\nx = 0.0\nkind = \"aggregate\"\nstiffness = 1e8\n[[load]]\nkind = \"axle\"",
    ));
    assert!(two.counted.iter().all(|c| *c));
}

/// docs/METHODS.md's plate-theory comparison: the ESAL axle's outer tire at the free edge of
/// `slab`'s plate under day curling, unbonded; the Mindlin plate against its Kirchhoff limit, a
/// plate of the same rigidity ten times thinner (E × 1000, α / 10 keeps the curl), whose
/// moment is turned into the 0.25 m slab's stress × (1/10)². Shear deformation lowers the
/// edge peak: below the Kirchhoff limit, by less than 5 % (measured 2.1 % on this mesh; the
/// bound is the size of the thick-plate correction at h/ℓ = 0.30, not a fit to the number).
#[test]
fn the_mindlin_edge_stress_is_a_little_below_its_kirchhoff_limit() {
    let scene = |h: f64, e: f64, alpha: f64| {
        slab("")
            .replace("thickness = 0.25", &format!("thickness = {h}"))
            .replace("youngs_modulus = 30e9", &format!("youngs_modulus = {e:e}"))
            .replace(
                "thermal_expansion = 1.0e-5",
                &format!("thermal_expansion = {alpha:e}"),
            )
            .replace(
                "x = 0.0\ny = 0.0",
                "x = 0.0\ny = -0.62\n[[load]]\nkind = \"temperature\"\ndifference = 8.0",
            )
            .replace("elements = [30, 24]", "elements = [60, 48]")
    };
    let bottom = |text: String| {
        let p = Problem::from_toml(&text).expect("scene");
        let a = analyse(&p).expect("solve");
        assert!(a.summary.converged);
        a.summary.stresses.bottom.value
    };
    let mindlin = bottom(scene(0.25, 30e9, 1.0e-5));
    let kirchhoff = bottom(scene(0.025, 30e12, 1.0e-6)) / 100.0;
    let ratio = mindlin / kirchhoff;
    assert!(
        ratio < 1.0 && ratio > 0.95,
        "Mindlin {mindlin} vs Kirchhoff {kirchhoff}: {ratio}"
    );
}

/// The exact interpolation between levels: three levels of the axle at one lateral position, in
/// two climate bins — a slight day gradient (the slab still touches the soil everywhere at
/// every level: the middle level is interpolated at every position; the curl's own stress makes
/// σ₁ a nonlinear function of the level, so only the stress components interpolate) and night
/// curling (the corners lift, and
/// the lifted region moves with the load: the sets differ and the positions are solved). The
/// damage at every element equals the run that solves every level (1e-9 of the largest: the
/// interpolation is exact, the rest is the solver's tolerance raised to the relation's power).
#[test]
fn levels_are_interpolated_exactly_where_the_contact_sets_agree() {
    let plan = TWO_BINS
        .replace("levels = [80e3]", "levels = [70e3, 80e3, 110e3]")
        .replace("repetitions = [1.0e5]", "repetitions = [1.0e5, 1.0e5, 1.0e4]")
        .replace("steps = 3", "steps = 15")
        .replace(
            "[[climate.bin]]\ndifference = 8.0\nshare = 0.6\n[[climate.bin]]\ndifference = -6.0\nshare = 0.4\n",
            "[[climate.bin]]\ndifference = 1.5\nshare = 0.5\n[[climate.bin]]\ndifference = -6.0\nshare = 0.5\n",
        );
    let fast = run(&slab(&plan));
    let direct = run(&slab(
        &plan.replace("steps = 15", "steps = 15\ninterpolate = false"),
    ));
    assert_eq!(direct.interpolated, 0);
    // Passes in the order group, level, lateral position, climate bin.
    let flat = &fast.passes[2];
    let night = &fast.passes[3];
    assert_eq!((flat.load, flat.difference), (80e3, Some(1.5)));
    assert_eq!((night.load, night.difference), (80e3, Some(-6.0)));
    // The slab and the lane are symmetric about x = 0: of the 15 positions the first 8 are
    // solved or interpolated, the last 7 read off their mirror images.
    assert_eq!(
        (flat.solves, flat.interpolated, flat.mirrored),
        (0, 8, 7),
        "full contact: all interpolated"
    );
    assert_eq!(
        (night.solves, night.interpolated, night.mirrored),
        (8, 0, 7),
        "lift-off moves: all solved"
    );
    assert_eq!(fast.interpolated, 8);
    same_maps(&fast, &direct);
}

/// A pass along a lane of a plate symmetric about x = 0 (the slab, night curling: the lifted
/// region moves with the axle) is its own mirror image: its first half is solved and the
/// largest stresses of the rest read off it element by element. The damage maps equal the run
/// that solves every position (`mesh.symmetry = "none"`), 1e-9 of the largest as between any
/// two runs; the pass's peak stresses equal, their places mirrored where the solved run's peak
/// lies in the other half. With a void under one corner the plate is not symmetric: nothing is
/// read off. Fails when the mirrored maxima are not taken (the second half's stresses missing).
#[test]
fn a_symmetric_pass_is_solved_on_its_first_half() {
    let plan = TWO_BINS.replace("steps = 3", "steps = 9");
    let half = run(&slab(&plan));
    let every = run(&slab(&plan).replace("[mesh]", "[mesh]\nsymmetry = \"none\""));
    assert_eq!((every.mirrored, every.solves), (0, 18));
    assert_eq!(
        (half.mirrored, half.solves),
        (8, 10),
        "5 of 9 positions a pass solved"
    );
    same_maps(&half, &every);
    for (a, b) in half.passes.iter().zip(&every.passes) {
        for (p, q) in [(&a.bottom, &b.bottom), (&a.top, &b.top)] {
            assert!(
                (p.stress - q.stress).abs() <= 1e-9 * q.stress.abs(),
                "{p:?} vs {q:?}"
            );
            assert!((p.x.abs() - q.x.abs()).abs() < 1e-9 && (p.y - q.y).abs() < 1e-9);
        }
    }
    let void = "[[void]]\nx = [-2.25, -1.95]\ny = [-1.8, -1.5]\ndepth = 0.0005\n";
    let lopsided = run(&slab(&format!("{void}{plan}")));
    assert_eq!(lopsided.mirrored, 0);
}

/// No silent partial sums: a cap on the penalty steps that settles the day-curling pass but not
/// the night one (night curling lifts more of the slab, so its positions take more steps; the
/// test looks for the first such cap rather than pinning one, since better starts change the
/// count). The run says it is incomplete and names the night pass, which adds nothing (its
/// shares are zero); the sums hold the day pass alone — at no element above the complete run's,
/// and below it where the night pass weighs.
#[test]
fn a_pass_that_does_not_converge_is_named_and_left_out() {
    // A colder night than TWO_BINS's: it lifts more of the slab than the day pass does.
    let scene = slab(TWO_BINS).replace("difference = -6.0", "difference = -14.0");
    let capped = (1..=8)
        .filter_map(|cap| {
            let text = scene.replace(
                "contact = \"unbonded\"",
                &format!("contact = \"unbonded\"\nmethod = \"penalty\"\nmax_iterations = {cap}"),
            );
            let p = Problem::from_toml(&text).expect("scene");
            // A cap that settles no pass is an error (nothing to sum): try the next one.
            damage(&p, &Monitor::NONE).ok()
        })
        .find(|d| d.missing.len() == 1)
        .expect("some cap settles the day pass and not the night one");
    let full = run(&scene);
    assert!(full.complete);
    assert!(!capped.complete);
    assert_eq!(capped.missing.len(), 1, "{:?}", capped.missing);
    assert!(
        capped.missing[0].contains("ΔT -14.0 K"),
        "{:?}",
        capped.missing
    );
    let night = &capped.passes[1];
    assert_ne!(night.outcome, liftoff::study::RunOutcome::CONVERGED);
    assert_eq!((night.bottom_share, night.top_share), (0.0, 0.0));
    let scale = full.top.iter().fold(0.0_f64, |m, v| m.max(*v));
    for (c, f) in capped.top.iter().zip(&full.top) {
        assert!(*c <= f + 1e-9 * scale, "{c} above the complete run's {f}");
    }
    assert!(
        capped
            .top
            .iter()
            .zip(&full.top)
            .any(|(c, f)| *c < f - 1e-6 * scale),
        "the night pass's top-down damage is missing from the sums"
    );
}

/// On the iterative route (a half-space, T by FFT) the families run side by side on more threads
/// than cores and share the plate's solves in batches: called on one thread, the four families
/// (four climate bins) go to a pool of four. Its damage maps equal those of each family solved alone (a part of one
/// family: nothing batched) merged, to 1e-9 of the largest damage ([`same_maps`]: the solver's
/// tolerance between two runs of one problem, raised to the relation's power; batched and
/// single triangular solves differ in round-off only).
#[test]
fn families_side_by_side_on_the_iterative_route_give_the_parts_damage() {
    let text = slab(TWO_BINS)
        .replace(
            "model = \"winkler\"\nmodulus = 8.0e7",
            "model = \"half-space\"\nyoungs_modulus = 1.0e8\npoissons_ratio = 0.35",
        )
        .replace("[solver]\n", "[solver]\nroute = \"iterative\"\n")
        .replace(
            "difference = -6.0\nshare = 0.4",
            "difference = -6.0\nshare = 0.2\n[[climate.bin]]\ndifference = -3.0\nshare = 0.1\n[[climate.bin]]\ndifference = 4.0\nshare = 0.1",
        );
    assert!(text.contains("half-space") && text.contains("iterative"));
    assert!(text.contains("difference = 4.0"));
    let p = Problem::from_toml(&text).expect("scene");
    let one_thread = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("pool");
    let whole = one_thread
        .install(|| damage(&p, &Monitor::NONE))
        .expect("damage");
    assert!(whole.complete);
    let part = |f: &[usize]| {
        one_thread
            .install(|| liftoff::study::damage_part(&p, f, &Monitor::NONE))
            .expect("part")
    };
    let parts = (0..4).map(|f| part(&[f])).collect();
    let merged = liftoff::study::damage_merge(&p, parts).expect("merge");
    same_maps(&whole, &merged);
}

/// A run split by families over workers: each part solved on its own, carried as bytes, the
/// parts merged — the same sums, passes and governing places as the one-process run, to the
/// bit (each family is solved the same way wherever it runs). Parts that leave a family out,
/// or hold one twice, and bytes that are not a part are refused naming `parts`.
#[test]
fn a_run_split_into_parts_merges_to_the_whole_run() {
    let p = Problem::from_toml(&slab(TWO_BINS)).expect("scene");
    let whole = damage(&p, &Monitor::NONE).expect("damage");
    let n = liftoff::study::damage_families(&p).expect("families");
    assert_eq!(n, 2, "day and night: one family each");
    let part = |f: &[usize]| {
        let bytes = liftoff::study::damage_part(&p, f, &Monitor::NONE)
            .expect("part")
            .to_bytes();
        liftoff::study::DamagePart::from_bytes(&bytes).expect("bytes")
    };
    let merged = liftoff::study::damage_merge(&p, vec![part(&[1]), part(&[0])]).expect("merge");
    assert_eq!(merged.bottom, whole.bottom);
    assert_eq!(merged.top, whole.top);
    assert_eq!(merged.x, whole.x);
    assert_eq!(
        (
            merged.governing_bottom.element,
            merged.governing_top.element
        ),
        (whole.governing_bottom.element, whole.governing_top.element)
    );
    assert_eq!(merged.solves, whole.solves);
    for (a, b) in merged.passes.iter().zip(&whole.passes) {
        assert_eq!(
            (a.bottom.stress, a.top.stress),
            (b.bottom.stress, b.top.stress)
        );
        assert_eq!((a.bottom_share, a.top_share), (b.bottom_share, b.top_share));
    }
    let refused = |r: liftoff::Result<Damage>| match r {
        Err(liftoff::Error::Invalid { field, .. }) => field == "parts",
        _ => false,
    };
    assert!(
        refused(liftoff::study::damage_merge(&p, vec![part(&[0])])),
        "night missing"
    );
    assert!(refused(liftoff::study::damage_merge(
        &p,
        vec![part(&[0, 1]), part(&[1])]
    )));
    assert!(liftoff::study::DamagePart::from_bytes(b"not a part").is_err());
    assert!(liftoff::study::damage_part(&p, &[2], &Monitor::NONE).is_err());
}

/// A climate bin given as a gradient (K/m) is the difference gradient × thickness: TWO_BINS's
/// 8 K and −6 K at 0.25 m are 32 and −24 K/m, and the run is the same to the bit (32 × 0.25 is
/// exact). At another thickness — a design's next slab — the difference follows: 6.4 K at
/// 0.20 m.
#[test]
fn a_gradient_bin_is_its_difference_at_the_slabs_thickness() {
    let graded = TWO_BINS
        .replace("difference = 8.0", "gradient = 32.0")
        .replace("difference = -6.0", "gradient = -24.0");
    let (a, b) = (run(&slab(TWO_BINS)), run(&slab(&graded)));
    assert_eq!(a.bottom, b.bottom);
    assert_eq!(a.top, b.top);
    let diffs = |d: &Damage| d.passes.iter().map(|p| p.difference).collect::<Vec<_>>();
    assert_eq!(diffs(&b), vec![Some(8.0), Some(-6.0)]);
    // In a US scene the gradient is in °F/in: 32 K/m = 32 × 1.8 × 0.0254 °F/in.
    let us = us_plate(&slab(&graded)).replace(
        "gradient = 32.0",
        &format!("gradient = {}", 32.0 * 1.8 * 0.0254),
    );
    let p = Problem::from_toml(&us).expect("scene");
    let first = p.damage.expect("plan").climate[0].difference;
    assert!((first - 8.0).abs() < 1e-12, "US gradient: {first} K");
    let thin = slab(&graded).replace("thickness = 0.25", "thickness = 0.20");
    let p = Problem::from_toml(&thin).expect("scene");
    let plan = p.damage.expect("plan");
    let got: Vec<f64> = plan.climate.iter().map(|c| c.difference).collect();
    assert!(
        (got[0] - 6.4).abs() < 1e-12 && (got[1] + 4.8).abs() < 1e-12,
        "{got:?}"
    );
}

/// A climate bin given as a temperature profile is the scene's `temperature-profile` load: one
/// bin (share 1) of a nonlinear profile gives the run that the scene without `[climate]` gives
/// when it carries the same profile as a load — its equivalent linear difference curls the
/// slab, its nonlinear rest adds its own stress to the faces — to round-off (the two models
/// hold the same loads in another order). The profile is read in proportion to its last depth,
/// so the same bin on a thicker slab keeps its equivalent difference.
#[test]
fn a_profile_bin_is_the_scenes_profile_load() {
    let climate = "[climate]\n[[climate.bin]]\ndifference = 8.0\nshare = 0.6\n[[climate.bin]]\ndifference = -6.0\nshare = 0.4\n";
    assert!(TWO_BINS.contains(climate));
    let profile = "depths = [0.0, 0.05, 0.125, 0.25]\ntemperatures = [30.0, 24.0, 21.0, 20.0]\n";
    let binned = slab(&TWO_BINS.replace(
        climate,
        &format!("[climate]\n[[climate.bin]]\n{profile}share = 1.0\n"),
    ));
    let plan = Problem::from_toml(&binned)
        .expect("scene")
        .damage
        .expect("plan");
    let c = plan.climate[0];
    assert!(c.nonlinear[0].abs() > 0.5, "a nonlinear profile: {c:?}");
    let loaded = slab(&TWO_BINS.replace(climate, "")).replace(
        "[[load]]\nkind = \"axle\"",
        &format!("[[load]]\nkind = \"temperature-profile\"\n{profile}[[load]]\nkind = \"axle\""),
    );
    let (a, b) = (run(&binned), run(&loaded));
    same_maps(&a, &b);
    // In a US scene: depths in inches, temperatures in °F; the same parts in K.
    let us = us_plate(&binned)
        .replace(
            "depths = [0.0, 0.05, 0.125, 0.25]",
            &format!(
                "depths = [0.0, {}, {}, {}]",
                0.05 / 0.0254,
                0.125 / 0.0254,
                0.25 / 0.0254
            ),
        )
        .replace(
            "temperatures = [30.0, 24.0, 21.0, 20.0]",
            "temperatures = [86.0, 75.2, 69.8, 68.0]",
        );
    let u = Problem::from_toml(&us)
        .expect("scene")
        .damage
        .expect("plan")
        .climate[0];
    assert!((u.difference - c.difference).abs() < 1e-9, "{u:?} vs {c:?}");
    assert!((u.nonlinear[0] - c.nonlinear[0]).abs() < 1e-9);
    let thick = binned.replace("thickness = 0.25", "thickness = 0.30");
    let plan = Problem::from_toml(&thick)
        .expect("scene")
        .damage
        .expect("plan");
    assert!((plan.climate[0].difference - c.difference).abs() < 1e-12);
}

/// A climate bin with a subgrade modulus of its own (a month's, a season's) is that soil: in a
/// run whose night bin sits on k = 50 MN/m³ and whose day bin on the scene's 80 MN/m³, each
/// pass is what a run of the scene on its own soil gives — stresses, the erosion's corner
/// deflection and the erosion relation's N (which reads the bin's k) — to the solver's
/// tolerance (1e-9 of the values).
#[test]
fn a_bin_with_its_own_subgrade_modulus_is_that_soil() {
    let pca = |t: &str| t.replace("model = \"mepdg\"", "model = \"pca\"");
    let night = "difference = -6.0\nshare = 0.4\n";
    assert!(TWO_BINS.contains(night));
    let mixed = slab(&pca(&TWO_BINS.replace(
        night,
        "difference = -6.0\nshare = 0.4\nsubgrade_modulus = 5.0e7\n",
    )));
    let stiff = slab(&pca(TWO_BINS));
    let soft = stiff.replace("modulus = 8.0e7", "modulus = 5.0e7");
    assert_ne!(soft, stiff);
    let (m, a, b) = (run(&mixed), run(&stiff), run(&soft));
    let close = |x: f64, y: f64| (x - y).abs() <= 1e-9 * y.abs().max(1e-300);
    for (got, want) in [(&m.passes[0], &a.passes[0]), (&m.passes[1], &b.passes[1])] {
        assert!(close(got.bottom.stress, want.bottom.stress), "{got:?}");
        assert!(close(got.top.stress, want.top.stress), "{got:?}");
        let (ge, we) = (
            got.erosion.expect("erosion"),
            want.erosion.expect("erosion"),
        );
        assert!(close(ge.deflection, we.deflection));
        assert!(close(
            ge.allowed.unwrap_or(f64::INFINITY),
            we.allowed.unwrap_or(f64::INFINITY)
        ));
    }
    // The soft night differs from the stiff one: the test can tell the soils apart.
    assert!(!close(b.passes[1].top.stress, a.passes[1].top.stress));
    // On a continuum soil a bin's k is refused, naming it.
    let halfspace = mixed.replace(
        "model = \"winkler\"\nmodulus = 8.0e7",
        "model = \"half-space\"\nyoungs_modulus = 1.0e8\npoissons_ratio = 0.35",
    );
    match Problem::from_toml(&halfspace) {
        Err(liftoff::Error::Invalid { field, .. }) => {
            assert_eq!(field, "climate.bin[1].subgrade_modulus")
        }
        other => panic!("{:?}", other.map(|_| ())),
    }
}
