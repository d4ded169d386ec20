//! Joints as segments that end at another joint (issue 35): a T-intersection of free joints on
//! Winkler springs is three separate plates, and a segment that runs the plate's whole width
//! is the line across it.

use crate::common;

use common::run_toml;
use liftoff::scene::Overrides;
use liftoff::{Monitor, Source};

/// A slab `a` × `b` m on 0.25 m elements with `extra` tables (joints), 6 kPa self-weight and a
/// 0.5 m square of 400 kPa at `patch` (its lower-left corner), unbonded on Winkler springs.
fn slab(a: f64, b: f64, extra: &str, patch: [f64; 2]) -> String {
    format!(
        r#"
[plate]
length = {a}
width = {b}
thickness = 0.25
youngs_modulus = 30e9
poissons_ratio = 0.2
{extra}
[foundation]
model = "winkler"
modulus = 5e7
[[load]]
kind = "uniform"
pressure = 6000.0
[[load]]
kind = "patch"
x = [{}, {}]
y = [{}, {}]
pressure = 400000.0
[mesh]
elements = [{}, {}]
symmetry = "none"
[solver]
contact = "unbonded"
"#,
        patch[0],
        patch[0] + 0.5,
        patch[1],
        patch[1] + 0.5,
        (a / 0.25).round() as usize,
        (b / 0.25).round() as usize,
    )
}

/// A 6 × 4 m slab cut by a free joint y = 0 across it and a free segment x = 0 from y = 0 to
/// the edge y = 2 (a T): on Winkler springs, which couple nothing, its three pieces are three
/// separate slabs. The upper-left piece, 3 × 2 m with the wheel on it, equals that slab solved
/// alone, node for node (1e-9 of its peak: the same element matrices and springs, assembled in
/// another order); the pieces the segment separates really are apart — the upper-right one,
/// under self-weight only, sits flat at p/k while the upper-left one tilts.
#[test]
fn a_t_of_free_joints_is_three_slabs() {
    let joints = "[[joint]]\ny = 0.0\nkind = \"free\"\n[[joint]]\nfrom = [0.0, 0.0]\nto = [0.0, 2.0]\nkind = \"free\"";
    let t = run_toml(&slab(6.0, 4.0, joints, [-2.0, 1.0]), &Overrides::default());
    // The piece alone: 3 × 2 m centred at the origin, the wheel moved with it.
    let piece = run_toml(&slab(3.0, 2.0, "", [-0.5, 0.0]), &Overrides::default());
    let (f, g) = (&t.report.field, &piece.report.field);
    let peak = g.w.iter().cloned().fold(0.0, f64::max);
    let mut worst: f64 = 0.0;
    // The piece's element (i, j) is the T's (i, j + 8) (0.25 m elements; the piece is the T's
    // columns 0..12, rows 8..16): compare the copies at their corners, each element's own.
    for j in 0..g.ny {
        for i in 0..g.nx {
            for (a, b) in f.element_nodes(i, j + 8).iter().zip(g.element_nodes(i, j)) {
                worst = worst.max((f.w[*a] - g.w[b]).abs());
            }
        }
    }
    assert!(
        worst < 1e-9 * peak,
        "the T's upper-left piece differs from the slab alone by {worst:.3e} m (peak {peak:.3e} m)"
    );
    // The upper-right piece carries its self-weight alone: flat, at p/k = 6e3 / 5e7 m.
    let flat = 6000.0 / 5e7;
    for j in 8..16 {
        for i in 12..24 {
            for n in f.element_nodes(i, j) {
                assert!(
                    (f.w[n] - flat).abs() < 1e-9 * flat,
                    "upper right, element ({i}, {j}): {} vs {flat}",
                    f.w[n]
                );
            }
        }
    }
}

/// A segment from one edge to the other is the line across the plate: the same cuts and
/// springs (an aggregate joint), so the same answer to round-off (1e-12 of the peak).
#[test]
fn a_segment_across_the_plate_is_the_line() {
    let line = "[[joint]]\nx = 0.5\nkind = \"aggregate\"\nstiffness = 1e8";
    let segment =
        "[[joint]]\nfrom = [0.5, -2.0]\nto = [0.5, 2.0]\nkind = \"aggregate\"\nstiffness = 1e8";
    let a = run_toml(&slab(6.0, 4.0, line, [0.0, 0.0]), &Overrides::default());
    let b = run_toml(&slab(6.0, 4.0, segment, [0.0, 0.0]), &Overrides::default());
    let (f, g) = (&a.report.field, &b.report.field);
    let peak = f.w.iter().cloned().fold(0.0, f64::max);
    let worst =
        f.w.iter()
            .zip(&g.w)
            .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()));
    assert!(worst < 1e-12 * peak, "{worst:.3e}");
    assert_eq!(a.ops.mesh.n_nodes(), b.ops.mesh.n_nodes());
}

/// `critical --along joint:NAME` on a segment moves the load along the segment only: every
/// position's reference point lies within its extent along the line (y ∈ [0, 2] m here), across
/// it before, on and after the joint.
#[test]
fn critical_along_a_segment_stays_on_it() {
    use liftoff::study::{critical, Along, CriticalOptions};
    let joints = "[[joint]]\ny = 0.0\nkind = \"aggregate\"\nstiffness = 1e8\n[[joint]]\nname = \"T\"\nfrom = [0.0, 0.0]\nto = [0.0, 2.0]\nkind = \"aggregate\"\nstiffness = 1e8";
    let scene = slab(6.0, 4.0, joints, [-2.0, -1.5]).replace(
        "[mesh]",
        "[[load]]\nkind = \"axle\"\nname = \"truck\"\nstandard = \"esal-single-dual\"\nx = 1.5\ny = -1.0\nheading = 90.0\n[mesh]",
    );
    let problem = liftoff::load(&Source::Toml(&scene), &Overrides::default()).expect("scene");
    let options = CriticalOptions {
        load: "truck".into(),
        grid: [7, 9],
        along: vec![Along::Joint("T".into())],
        ..CriticalOptions::default()
    };
    let c = critical(&problem, &options, &Monitor::NONE).expect("search");
    assert!(!c.positions.is_empty());
    for p in &c.positions {
        assert!(
            (-1e-9..=2.0 + 1e-9).contains(&p.y),
            "a position at y = {} off the segment",
            p.y
        );
    }
    let xs: std::collections::BTreeSet<i64> = c
        .positions
        .iter()
        .map(|p| (p.x * 1e6).round() as i64)
        .collect();
    assert_eq!(xs.len(), 3, "before, on and after the joint: {xs:?}");
}
