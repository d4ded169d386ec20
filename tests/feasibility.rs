//! The feasibility check refuses only what no pushing pressure can balance (issue 32 §1.1).
//!
//! A tandem at the end of a doweled lane, its outer print ending exactly on the plate's free
//! end — the position `critical`'s grid puts it at — was refused as "a panel would tip over"
//! for two of its three combinations, by both methods, while a self-weight-and-tires load on
//! non-negative loads is always balanced (σ = the nodal load over the nodal area is one
//! balance on a Winkler soil). The cause was the projection's line search deciding the last
//! Newton step by round-off (`solve::projection`, its unit tests). These are the positions that
//! exposed it, and their kin: prints touching the plate's ends, an x-joint from either side, a
//! tied y-joint and the mid-panel position of a two-lane slab.

use liftoff::{Monitor, Outcome, Source};

/// The 13.5 × 3.6 m lane of three doweled panels (joints at x = ±2.25 m), 0.25 m concrete on
/// Winkler 80 MN/m³, self-weight, a tandem-dual axle at (x, y), night and day curling, 90 × 24
/// elements, unbonded; `width` and `extra` give the two-lane variant.
fn lane(x: f64, y: f64, width: f64, elements: [usize; 2], extra: &str, method: &str) -> String {
    let dowels: String = [-2.25, 2.25]
        .iter()
        .map(|x| {
            format!(
                "[[joint]]\nx = {x}\nkind = \"dowels\"\ndiameter = 0.032\nyoungs_modulus = 200e9\nopening = 0.006\nsupport_modulus = 4.07e11\nspacing = 0.3\n"
            )
        })
        .collect();
    format!(
        r#"title = "lane"
[plate]
length = 13.5
width = {width}
thickness = 0.25
youngs_modulus = 30e9
poissons_ratio = 0.15
thermal_expansion = 1.0e-5
[foundation]
model = "winkler"
modulus = 8.0e7
{dowels}{extra}
[[load]]
kind = "uniform"
pressure = 6.0e3
case = "self-weight"
[[load]]
kind = "axle"
name = "axle"
standard = "tandem-dual"
x = {x:?}
y = {y:?}
case = "traffic"
[[load]]
kind = "temperature"
difference = -8.0
case = "night"
[[load]]
kind = "temperature"
difference = 15.0
case = "day"
[[combination]]
name = "axle"
factors = {{ self-weight = 1.0, traffic = 1.0 }}
[[combination]]
name = "axle-night"
factors = {{ self-weight = 1.0, traffic = 1.0, night = 1.0 }}
[[combination]]
name = "axle-day"
factors = {{ self-weight = 1.0, traffic = 1.0, day = 1.0 }}
[mesh]
elements = [{}, {}]
[solver]
contact = "unbonded"
method = "{method}"
"#,
        elements[0], elements[1]
    )
}

/// Every combination of the scene converges, with its reaction equal to its load.
fn every_combination_converges(scene: &str, what: &str) {
    let problem = liftoff::load(&Source::Toml(scene), &Default::default())
        .unwrap_or_else(|e| panic!("{what}: {e}"));
    match liftoff::run(&problem, &Monitor::NONE) {
        Ok(Outcome::Combinations(c)) => {
            for run in &c.runs {
                match &run.outcome {
                    Ok(r) => {
                        assert!(r.summary.converged, "{what}, {}: not converged", run.name);
                        // The equilibrium check of every solve (1e-6 relative in the library;
                        // here the report's own measure).
                        assert!(
                            r.report.resultant.relative_error < 1e-6,
                            "{what}, {}: reaction misses the load by {:e}",
                            run.name,
                            r.report.resultant.relative_error
                        );
                    }
                    Err(e) => panic!("{what}, {}: {e}", run.name),
                }
            }
        }
        Ok(Outcome::Single(_)) => panic!("{what}: expected combinations"),
        Err(e) => panic!("{what}: {e}"),
    }
}

/// The issue's position (the last x of `critical`'s 11 × 9 grid, 1e-9 a inside the plate's
/// end, the 7th y), its mirror images, and both methods.
#[test]
fn a_tandem_ending_on_the_plate_end_is_balanced() {
    let (x, y) = (6.00343849385019, 0.33494272994083674);
    for method in ["qp", "penalty"] {
        for (sx, sy) in [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0)] {
            every_combination_converges(
                &lane(sx * x, sy * y, 3.6, [90, 24], "", method),
                &format!("{method} at ({}, {})", sx * x, sy * y),
            );
        }
    }
}

/// Prints touching an x-joint from either side (the rear print ending on x = 2.25, the front
/// one starting there), on two meshes.
#[test]
fn prints_touching_a_joint_are_balanced() {
    for (x, elements) in [
        (1.503_438_5, [90, 24]),
        (2.996_561_5, [90, 24]),
        (1.503_438_5, [45, 12]),
        (2.996_561_5, [45, 12]),
    ] {
        for y in [-0.33494272994083674, 0.0, 0.33494272994083674] {
            every_combination_converges(
                &lane(x, y, 3.6, elements, "", "qp"),
                &format!("tandem at ({x}, {y}) on {elements:?}"),
            );
        }
    }
}

/// Two lanes joined by a tied y-joint: the mid-panel position that was refused for all three
/// combinations with nothing near an edge, and prints touching the y-joint from each side.
#[test]
fn two_lanes_with_a_tied_joint_are_balanced() {
    let tied =
        "[[joint]]\ny = 0.0\nkind = \"tied\"\nstiffness = 5.0e8\nrotational_stiffness = 5.0e6";
    for method in ["qp", "penalty"] {
        every_combination_converges(
            &lane(
                1.2006876987700377,
                2.161149777396465,
                7.2,
                [90, 48],
                tied,
                method,
            ),
            &format!("{method}: two lanes, mid-panel tandem"),
        );
    }
    for y in [-1.130117, 1.130117] {
        every_combination_converges(
            &lane(-4.0, y, 7.2, [90, 48], tied, "qp"),
            &format!("two lanes, print on the y-joint from y = {y}"),
        );
    }
}

/// `critical` over the row of its default 11 × 9 grid that holds the issue's position (the
/// tandem's outer print ending on the plate's end at its last x), every combination the axle
/// acts in, both methods: every position converges — none is reported infeasible.
#[test]
fn critical_reports_no_feasible_position_as_infeasible() {
    use liftoff::study::{CriticalOptions, RunOutcome};
    for method in ["qp", "penalty"] {
        let scene = lane(0.0, 0.0, 3.6, [90, 24], "", method);
        let problem = liftoff::load(&Source::Toml(&scene), &Default::default())
            .unwrap_or_else(|e| panic!("{e}"));
        for combination in ["axle", "axle-night", "axle-day"] {
            let options = CriticalOptions {
                load: "axle".into(),
                combination: Some(combination.into()),
                // The 7th row of y (index 6) of the default grid, all 11 x.
                indices: Some((66..77).collect()),
                ..CriticalOptions::default()
            };
            let c = options
                .run(&problem, &Monitor::NONE)
                .unwrap_or_else(|e| panic!("{method} {combination}: {e}"));
            for p in &c.positions {
                assert_eq!(
                    p.outcome,
                    RunOutcome::CONVERGED,
                    "{method} {combination} at ({}, {})",
                    p.x,
                    p.y
                );
            }
        }
    }
}
