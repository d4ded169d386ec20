//! `liftoff critical`: the classical critical position of an axle on a single slab (the largest
//! bottom stress with the outer tires at the middle of the free longitudinal edge: PCA 1984,
//! Packard & Tayabji 1985), the search against a solve of that position alone, and warm starts
//! that change nothing but the number of steps.

use liftoff::critical::{critical, CriticalOptions};
use liftoff::scene::SceneFile;
use liftoff::study::RunOutcome;

mod common;

/// A 4.5 m × 3.6 m × 0.25 m slab on k = 27 MN/m³ (L/ℓ ≈ 4), its weight and an 80 kN axle with
/// dual tires travelling along x; unbonded contact.
const SLAB: &str = r#"
title = "ESAL axle on a slab"
[plate]
length = 4.5
width = 3.6
thickness = 0.25
youngs_modulus = 30e9
poissons_ratio = 0.15
[foundation]
model = "winkler"
modulus = 27e6
[[load]]
kind = "uniform"
pressure = 6e3
[[load]]
kind = "axle"
name = "truck"
standard = "esal-single-dual"
x = 0.0
y = 0.0
[mesh]
elements = [60, 48]
"#;

fn options(grid: [usize; 2], warm: bool) -> CriticalOptions {
    CriticalOptions {
        load: "truck".into(),
        grid,
        warm,
        ..CriticalOptions::default()
    }
}

/// The bottom-stress maximum over a 7 × 5 grid is at the middle of the free edge (x = 0, within
/// one grid step) with the outer tires at the edge (|y| the largest on the grid, where the
/// outer print touches the edge), and it equals a solve of that position alone (the same
/// operators, solved again from scratch: to the penalty's own tolerance, 1e-9 relative).
#[test]
fn the_bottom_stress_is_critical_at_the_middle_of_the_free_edge() {
    let file = SceneFile::parse(SLAB).expect("scene");
    let c = critical(&file, &options([7, 5], true), &liftoff::Monitor::NONE).expect("search");
    assert_eq!(c.positions.len(), 35, "7 × 5 positions");
    assert!(
        c.positions
            .iter()
            .all(|p| p.outcome == RunOutcome::CONVERGED),
        "every position converged"
    );
    let Some(i) = c.bottom else {
        panic!("no critical position");
    };
    let p = &c.positions[i];
    let ymax = c.positions.iter().map(|q| q.y.abs()).fold(0.0, f64::max);
    assert!(
        p.x.abs() <= c.spacing[0] + 1e-9 && (p.y.abs() - ymax).abs() < 1e-9,
        "critical bottom position ({:.3}, {:.3}) m; grid step {:.3} m, edge |y| {ymax:.3}",
        p.x,
        p.y,
        c.spacing[0]
    );
    // The outer print touches the edge there: 0.915 + 0.1524 + half a print's width (0.0645
    // m) from the reference point.
    assert!(
        (ymax + 0.915 + 0.1524 + 0.0645 - 1.8).abs() < 1e-3,
        "edge |y| {ymax}"
    );
    // The stress acts along the edge, at the edge.
    assert!(p.bottom_at[1].abs() > 1.7, "peak at y = {}", p.bottom_at[1]);
    // That position alone, as `liftoff solve` would: the same number.
    let alone = SLAB
        .replace("x = 0.0\ny = 0.0", &format!("x = {}\ny = {}", p.x, p.y))
        .replace(
            "elements = [60, 48]",
            "elements = [60, 48]\nsymmetry = \"none\"",
        );
    let a = common::run(&alone);
    let s = a.summary.stresses.bottom.value;
    assert!(
        (s - p.bottom).abs() < 1e-9 * s,
        "search {} Pa vs that position alone {s} Pa",
        p.bottom
    );
}

/// Warm starts (each position from its neighbour's answer) against cold ones, at night (top
/// 10 K cooler: the corners lift, so the contact set moves with the axle): every position's
/// stresses and deflection equal to the penalty's tolerance (the penalised problem is strictly
/// convex: one answer from any start), and fewer steps in all.
#[test]
fn warm_starts_change_no_digit() {
    let night = SLAB
        .replace(
            "poissons_ratio = 0.15",
            "poissons_ratio = 0.15\nthermal_expansion = 1e-5",
        )
        .replace(
            "[mesh]",
            "[[load]]\nkind = \"temperature\"\ndifference = -10.0\n[mesh]",
        );
    let file = SceneFile::parse(&night).expect("scene");
    let warm = critical(&file, &options([5, 3], true), &liftoff::Monitor::NONE).expect("warm");
    let cold = critical(&file, &options([5, 3], false), &liftoff::Monitor::NONE).expect("cold");
    for (w, c) in warm.positions.iter().zip(&cold.positions) {
        assert_eq!((w.x, w.y), (c.x, c.y), "same grid");
        for (name, a, b) in [
            ("bottom", w.bottom, c.bottom),
            ("top", w.top, c.top),
            ("w_max", w.w_max, c.w_max),
        ] {
            assert!(
                (a - b).abs() <= 1e-9 * a.abs().max(b.abs()),
                "{name} at ({:.2}, {:.2}): warm {a} vs cold {b}",
                w.x,
                w.y
            );
        }
    }
    let steps = |c: &liftoff::critical::Critical| -> usize {
        c.positions.iter().map(|p| p.iterations).sum()
    };
    assert!(
        steps(&warm) < steps(&cold),
        "warm {} steps, cold {}",
        steps(&warm),
        steps(&cold)
    );
}

/// A name that is no load, and a load that is no vehicle, are refused by name.
#[test]
fn the_moved_load_must_be_a_named_vehicle() {
    let file = SceneFile::parse(SLAB).expect("scene");
    let missing = CriticalOptions {
        load: "bus".into(),
        ..CriticalOptions::default()
    };
    let e = critical(&file, &missing, &liftoff::Monitor::NONE)
        .err()
        .map(|e| e.to_string());
    assert!(e.is_some_and(|m| m.contains("no load named `bus`") && m.contains("truck")));
    let weight = SceneFile::parse(&SLAB.replace(
        "kind = \"uniform\"\npressure = 6e3",
        "kind = \"uniform\"\npressure = 6e3\nname = \"weight\"",
    ))
    .expect("scene");
    let e = critical(
        &weight,
        &CriticalOptions {
            load: "weight".into(),
            ..CriticalOptions::default()
        },
        &liftoff::Monitor::NONE,
    )
    .err()
    .map(|e| e.to_string());
    assert!(
        e.is_some_and(|m| m.contains("moves an axle or a gear")),
        "a uniform load is no vehicle"
    );
}

/// On a jointed slab the search also finds the positions of the largest joint shear per
/// length and the largest dowel force: the slab above cut by a doweled transverse joint at
/// x = 0 (32 mm bars every 0.3 m) and an aggregate longitudinal joint at y = 0. Each is the
/// largest over the converged positions, equals that position solved alone (1e-9, as above),
/// and with the axle standing on the transverse joint (x = 0, the prints and the layout
/// mirror-symmetric about it) the bars carry nothing but round-off (1e-6 of the largest
/// force): the mirror maps the solution onto itself, so the jump across the joint vanishes.
#[test]
fn jointed_slabs_report_the_critical_joint_shear_and_dowel_force() {
    let jointed = SLAB.replace(
        "[mesh]",
        "[[joint]]\nx = 0.0\nkind = \"dowels\"\nname = \"T\"\ndiameter = 0.032\nyoungs_modulus = 200e9\nopening = 0.006\nsupport_modulus = 4.07e11\nspacing = 0.3\n[[joint]]\ny = 0.0\nkind = \"aggregate\"\nname = \"L\"\nstiffness = 5e8\n[mesh]",
    );
    let file = SceneFile::parse(&jointed).expect("scene");
    let c = critical(&file, &options([5, 3], true), &liftoff::Monitor::NONE).expect("search");
    assert!(c
        .positions
        .iter()
        .all(|p| p.outcome == RunOutcome::CONVERGED && p.joint_shear.is_some()));
    let best = |f: fn(&liftoff::critical::Position) -> Option<f64>| {
        c.positions
            .iter()
            .filter_map(f)
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let (Some(i), Some(k)) = (c.joint_shear, c.dowel_force) else {
        panic!("no joint positions");
    };
    assert_eq!(c.positions[i].joint_shear, Some(best(|p| p.joint_shear)));
    let f_max = best(|p| p.dowel_force);
    assert_eq!(c.positions[k].dowel_force, Some(f_max));
    for p in c.positions.iter().filter(|p| p.x.abs() < 1e-9) {
        let f = p.dowel_force.expect("dowels");
        assert!(f <= 1e-6 * f_max, "axle on the joint at y = {}: {f} N", p.y);
    }
    // The position of the largest dowel force alone, as `liftoff solve` would.
    let p = &c.positions[k];
    let alone = jointed
        .replace("x = 0.0\ny = 0.0", &format!("x = {}\ny = {}", p.x, p.y))
        .replace(
            "elements = [60, 48]",
            "elements = [60, 48]\nsymmetry = \"none\"",
        );
    let a = common::run(&alone);
    let f = a
        .summary
        .joints
        .iter()
        .filter_map(|j| j.max_dowel_force)
        .fold(0.0, f64::max);
    assert!(
        (f - f_max).abs() < 1e-9 * f_max,
        "search {f_max} N vs alone {f} N"
    );
    // critical.csv carries both columns, critical.json both indices.
    let dir = tempfile::tempdir().expect("tempdir");
    liftoff::output::critical::write_critical(dir.path(), &c, "jointed").expect("files");
    let csv = std::fs::read_to_string(dir.path().join("critical.csv")).expect("csv");
    let header = csv.lines().next().expect("header");
    assert!(
        header.contains("joint_shear_N_per_m,dowel_force_N"),
        "{header}"
    );
    let json = std::fs::read_to_string(dir.path().join("critical.json")).expect("json");
    let doc: serde_json::Value = serde_json::from_str(&json).expect("json");
    assert_eq!(doc["dowel_force"].as_u64(), Some(k as u64));
    assert_eq!(doc["joint_shear"].as_u64(), Some(i as u64));
    let table = liftoff::output::critical::critical_table("jointed", &c, None);
    assert!(
        table.contains("joint shear") && table.contains("dowel force"),
        "{table}"
    );
}
