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
