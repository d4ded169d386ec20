//! `liftoff critical`: the classical critical position of an axle on a single slab (the largest
//! bottom stress with the outer tires at the middle of the free longitudinal edge: PCA 1984,
//! Packard & Tayabji 1985), the search against a solve of that position alone, and warm starts
//! that change nothing but the number of steps.

use liftoff::scene::Overrides;
use liftoff::study::RunOutcome;
use liftoff::study::{critical, CriticalOptions, Ends};

use crate::common;

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

/// SLAB at night: the top 10 K cooler, so that the corners lift and the contact set moves with
/// the axle.
fn night_slab() -> String {
    SLAB.replace(
        "poissons_ratio = 0.15",
        "poissons_ratio = 0.15\nthermal_expansion = 1e-5",
    )
    .replace(
        "[mesh]",
        "[[load]]\nkind = \"temperature\"\ndifference = -10.0\n[mesh]",
    )
}

/// The scene validated as every front end does ([`liftoff::load`]).
fn problem(text: &str) -> liftoff::Problem {
    liftoff::load(&liftoff::Source::Toml(text), &Overrides::default()).expect("scene")
}

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
    let file = problem(SLAB);
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
    let night = night_slab();
    let file = problem(&night);
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
    let steps =
        |c: &liftoff::study::Critical| -> usize { c.positions.iter().map(|p| p.iterations).sum() };
    assert!(
        steps(&warm) < steps(&cold),
        "warm {} steps, cold {}",
        steps(&warm),
        steps(&cold)
    );
}

/// On a plate symmetric about both axes (the slab above, curled at night so that the corners
/// lift and the contact set moves with the axle), a position whose load is another's mirror
/// image is read off that one: which positions pair is checked against the grid's geometry —
/// the first point in grid order at (∓x, y), (x, ∓y) or (∓x, ∓y), the dual-tire axle being
/// symmetric about its reference point —, and every mirrored position equals the same position
/// solved (`mirror: false`) to 1e-9 relative (both are the one answer of a strictly convex
/// penalised problem, reached from other starts: the warm-start test's tolerance), the places
/// of its extremes the solved ones (or, for a load on a symmetry line, whose field has its
/// peaks in equal pairs across it, the other of the pair).
/// A frame that is not symmetric (a void under one corner) pairs nothing, nor does a scene that
/// asks for no symmetry.
#[test]
fn mirror_images_equal_the_solves_they_replace() {
    let night = night_slab();
    let file = problem(&night);
    let mirrored =
        critical(&file, &options([5, 3], true), &liftoff::Monitor::NONE).expect("mirrored");
    let solved = critical(
        &file,
        &CriticalOptions {
            mirror: false,
            ..options([5, 3], true)
        },
        &liftoff::Monitor::NONE,
    )
    .expect("solved");
    let points: Vec<[f64; 2]> = solved.positions.iter().map(|p| [p.x, p.y]).collect();
    let near = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).abs() < 1e-9 && (a[1] - b[1]).abs() < 1e-9;
    let mut read_off = 0;
    for (i, (m, s)) in mirrored.positions.iter().zip(&solved.positions).enumerate() {
        assert_eq!(s.mirror_of, None, "mirror: false solves every position");
        assert_eq!((m.x, m.y), (s.x, s.y), "same grid");
        let [x, y] = points[i];
        let expected = (0..i).find(|&k| {
            [[-x, y], [x, -y], [-x, -y]]
                .iter()
                .any(|&q| near(points[k], q))
        });
        assert_eq!(m.mirror_of, expected, "position {i} at ({x:.3}, {y:.3})");
        if m.mirror_of.is_none() {
            continue;
        }
        read_off += 1;
        assert_eq!((m.iterations, m.outcome), (0, s.outcome));
        for (name, a, b) in [
            ("bottom", m.bottom, s.bottom),
            ("top", m.top, s.top),
            ("w_max", m.w_max, s.w_max),
            ("contact", m.contact_fraction, s.contact_fraction),
        ] {
            assert!(
                (a - b).abs() <= 1e-9 * a.abs().max(b.abs()),
                "{name} at position {i}: mirrored {a} vs solved {b}"
            );
        }
        // A load on a symmetry line makes a field symmetric about it, whose peaks come in
        // equal pairs across it: there either of the pair.
        let (on_x0, on_y0) = (x.abs() < 1e-9, y.abs() < 1e-9);
        for (a, b) in [(m.bottom_at, s.bottom_at), (m.top_at, s.top_at)] {
            let twins = [
                (on_x0, [-a[0], a[1]]),
                (on_y0, [a[0], -a[1]]),
                (on_x0 && on_y0, [-a[0], -a[1]]),
            ];
            assert!(
                near(a, b) || twins.iter().any(|&(tie, t)| tie && near(t, b)),
                "position {i}: peak at {a:?} mirrored, {b:?} solved"
            );
        }
    }
    // A 5 × 3 grid on a doubly symmetric slab: the first three of the first two rows solved.
    assert_eq!(read_off, 9);
    // A void under one corner: no mirror; `symmetry = "none"`: none either.
    for scene in [
        night.replace(
            "[mesh]",
            "[[void]]\nx = [-2.25, -1.95]\ny = [-1.8, -1.5]\ndepth = 0.001\n[mesh]",
        ),
        night.replace("[mesh]", "[mesh]\nsymmetry = \"none\""),
    ] {
        let c = critical(
            &problem(&scene),
            &options([5, 3], true),
            &liftoff::Monitor::NONE,
        )
        .expect("search");
        assert!(c.positions.iter().all(|p| p.mirror_of.is_none()), "{scene}");
    }
}

/// Warm starts cost no extra steps where the load's steps are long against the plate's radius
/// of relative stiffness: on `example:pavement-3x3` (night curling, the QP) an 11 × 9 grid
/// steps 1.2 m along x (ℓ ≈ 0.8 m), where each position's contact set is its neighbour's and
/// one face solve settles it. Every solved position takes one (checked: 54 solves, 54 face
/// solves); always extrapolating the last two answers, as before, lifted points that stay in
/// contact and took 145 face solves for the 99 positions (a second one at 46 of them, each with
/// a new factorisation: 8× the time). The bound, 1.1 a position, leaves room for a position
/// whose set does move and fails the old rule's 1.46.
#[test]
fn long_steps_start_from_the_last_answer() {
    let file = problem(include_str!("../examples/pavement-3x3.toml"));
    let options = CriticalOptions {
        load: "axle".into(),
        grid: [11, 9],
        ..CriticalOptions::default()
    };
    let c = critical(&file, &options, &liftoff::Monitor::NONE).expect("search");
    let solved: Vec<_> = c
        .positions
        .iter()
        .filter(|p| p.mirror_of.is_none())
        .collect();
    assert!(solved.iter().all(|p| p.outcome == RunOutcome::CONVERGED));
    let steps: usize = solved.iter().map(|p| p.iterations).sum();
    assert!(
        steps as f64 <= 1.1 * solved.len() as f64,
        "{steps} face solves for {} positions",
        solved.len()
    );
}

/// A name that is no load, and a load that is no vehicle, are refused by name.
#[test]
fn the_moved_load_must_be_a_named_vehicle() {
    let file = problem(SLAB);
    let missing = CriticalOptions {
        load: "bus".into(),
        ..CriticalOptions::default()
    };
    let e = critical(&file, &missing, &liftoff::Monitor::NONE)
        .err()
        .map(|e| e.to_string());
    assert!(e.is_some_and(|m| m.contains("no load named `bus`") && m.contains("truck")));
    let weight = problem(&SLAB.replace(
        "kind = \"uniform\"\npressure = 6e3",
        "kind = \"uniform\"\npressure = 6e3\nname = \"weight\"",
    ));
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
    // An unknown combination lists the scene's (issue 36).
    let combined = problem(&SLAB.replace(
        "[mesh]",
        "[[combination]]\nname = \"day\"\nfactors = { default = 1.0 }\n[[combination]]\nname = \"night\"\nfactors = { default = 1.2 }\n[mesh]",
    ));
    let e = critical(
        &combined,
        &CriticalOptions {
            combination: Some("noon".into()),
            ..options([3, 3], false)
        },
        &liftoff::Monitor::NONE,
    )
    .err()
    .map(|e| e.to_string());
    assert!(
        e.as_ref()
            .is_some_and(|m| m.contains("no combination named `noon`") && m.contains("day, night")),
        "{e:?}"
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
    let file = problem(&jointed);
    let c = critical(&file, &options([5, 3], true), &liftoff::Monitor::NONE).expect("search");
    assert!(c
        .positions
        .iter()
        .all(|p| p.outcome == RunOutcome::CONVERGED && p.joint_shear.is_some()));
    // One transverse joint: no inner panel, the whole plate read ([`Ends`]).
    assert!(c.read_x.is_none() && c.positions.iter().all(|p| p.end_top.is_none()));
    let best = |f: fn(&liftoff::study::Position) -> Option<f64>| {
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
        header.contains("joint_shear [N/m],dowel_force [N]"),
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

/// The example pavement (3 × 3 jointed slabs, an axle, night curling) with a combination that
/// factors the axle and the weight, on a coarser mesh (every joint still on an element edge).
fn heavy_pavement() -> String {
    include_str!("../examples/pavement-3x3.toml").replace(
        "[mesh]",
        "[[combination]]\nname = \"heavy\"\nfactors = { self-weight = 1.2, traffic = 1.5, night = 1.0 }\n\n[mesh]",
    )
}

/// A load's numbers (kind, place, magnitude) in a row.
fn numbers(l: &liftoff::model::Load) -> Vec<f64> {
    use liftoff::model::Load;
    match *l {
        Load::Point { x, y, force } => vec![0.0, x, y, force],
        Load::Patch { x, y, pressure } => vec![1.0, x[0], x[1], y[0], y[1], pressure],
        Load::Line {
            from,
            to,
            force_per_length,
        } => vec![2.0, from[0], from[1], to[0], to[1], force_per_length],
        Load::Temperature { curvature } => vec![3.0, curvature],
        Load::FaceStress { top, bottom } => vec![4.0, top, bottom],
    }
}

fn coarse() -> Overrides {
    Overrides {
        mesh: Some([45, 34]),
        ..Overrides::default()
    }
}

/// The heavy pavement on the coarse mesh, and a search of its axle over a 3 × 2 grid in the
/// combination `heavy`, reading the plate as `ends` says (None: as the scene's `[plate] ends =
/// "cut"` says).
fn heavy_search(ends: Option<Ends>) -> (liftoff::Problem, CriticalOptions) {
    let base = liftoff::load(&liftoff::Source::Toml(&heavy_pavement()), &coarse()).expect("scene");
    let options = CriticalOptions {
        load: "axle".into(),
        grid: [3, 2],
        combination: Some("heavy".into()),
        ends,
        ..CriticalOptions::default()
    };
    (base, options)
}

/// The heavy pavement with the axle written at (x, y), on the coarse mesh, modelled whole.
fn heavy_written(x: f64, y: f64) -> liftoff::Problem {
    let written = heavy_pavement()
        .replace("x = 2.15 ", &format!("x = {x} "))
        .replace("y = -0.88 ", &format!("y = {y} "));
    let overrides = Overrides {
        symmetry: Some(liftoff::model::SymmetryMode::None),
        ..coarse()
    };
    liftoff::load(&liftoff::Source::Toml(&written), &overrides).expect("scene")
}

/// The search moves the axle in the model it was given (no scene file, no validation per
/// position): at every position of a 3 × 2 grid, in a combination with factors other than 1,
/// the moved model's loads are the ones a scene with the axle written at that position makes
/// (the same patches; pressures to round-off, since P is added up in another order), and the
/// search's answers equal that scene solved alone, cold, to 1e-9 relative. The search reads
/// the whole plate (`Ends::Free`), as the scene's summary does.
#[test]
fn moved_loads_and_answers_equal_the_scene_written_at_that_position() {
    let (base, options) = heavy_search(Some(Ends::Free));
    let c = critical(&base, &options, &liftoff::Monitor::NONE).expect("search");
    assert_eq!(c.positions.len(), 6);
    // The reported spacing is the distance between neighbouring points of the 3 × 2 grid
    // (positions in grid order: x fastest): the same subtractions, so to round-off of metres.
    let p = &c.positions;
    assert!(
        (c.spacing[0] - (p[1].x - p[0].x)).abs() < 1e-12
            && (c.spacing[1] - (p[3].y - p[0].y)).abs() < 1e-12
            && c.spacing[0] > 0.0
            && c.spacing[1] > 0.0,
        "spacing {:?}",
        c.spacing
    );
    let heavy = |p: &liftoff::Problem| -> liftoff::scene::Combination {
        let mut c = p.combinations.clone();
        c.retain(|c| c.name == "heavy");
        c.pop().expect("combination heavy")
    };
    let mut moved = heavy(&base).model;
    let k = moved
        .vehicles
        .iter()
        .position(|v| v.name.as_deref() == Some("axle"))
        .expect("the axle is a vehicle of the model");
    assert_eq!(moved.vehicles[k].factor, 1.5);
    for p in &c.positions {
        moved.place(k, [p.x, p.y, p.heading]).expect("on the plate");
        let mut alone = heavy_written(p.x, p.y);
        let combination = heavy(&alone);
        let at = &combination.model.vehicles[k].at;
        assert_eq!((at[0], at[1]), (p.x, p.y), "the scene puts the axle there");
        assert_eq!(moved.loads.len(), combination.model.loads.len());
        for (a, b) in moved.loads.iter().zip(&combination.model.loads) {
            let (u, v) = (numbers(a), numbers(b));
            assert!(
                u.len() == v.len()
                    && u.iter()
                        .zip(&v)
                        .all(|(x, y)| (x - y).abs() <= 1e-13 * y.abs()),
                "moved {a:?}, written {b:?}"
            );
        }
        // That position alone: its combination only, solved from scratch.
        alone.model = combination.model.clone();
        alone.combinations = vec![combination];
        let liftoff::Outcome::Combinations(runs) =
            liftoff::run(&alone, &liftoff::Monitor::NONE).expect("solve")
        else {
            panic!("a scene with combinations");
        };
        let s = &runs.runs[0].outcome.as_ref().expect("solved").summary;
        let max_of = |f: fn(&liftoff::post::JointReport) -> Option<f64>| {
            s.joints
                .iter()
                .filter_map(f)
                .fold(f64::NEG_INFINITY, f64::max)
        };
        for (name, search, alone) in [
            ("bottom", p.bottom, s.stresses.bottom.value),
            ("top", p.top, s.stresses.top.value),
            ("w_max", p.w_max, s.w_max),
            (
                "joint shear",
                p.joint_shear.unwrap_or(f64::NAN),
                max_of(|j| j.max_shear_per_length),
            ),
            (
                "dowel force",
                p.dowel_force.unwrap_or(f64::NAN),
                max_of(|j| j.max_dowel_force),
            ),
        ] {
            assert!(
                (search - alone).abs() <= 1e-9 * alone.abs(),
                "{name} at ({:.3}, {:.3}): search {search} vs alone {alone}",
                p.x,
                p.y
            );
        }
    }
}

/// On the pavement — a lane of three slabs along x, its ends a cut (`[plate] ends = "cut"`) —
/// the search reads every position between the two transverse joints (x = ±2.25 m): its stresses are the
/// whole plate's where they peak inside, and the end panels' peaks are kept beside them. Checked
/// against the same search reading the whole plate (`Ends::Free`; the same solves, so to the
/// bit: the whole plate's σ₁ is the larger of the two parts'), and against the position of the
/// largest top tension solved alone, whose elements inside the joints and nodes between them
/// are read here by hand (1e-9: the search's warm start against a cold solve). At night the
/// axle at the plate's end lifts that end as no axle on the road does: read whole, the top
/// tension's critical position is that end.
#[test]
fn a_cut_lane_is_read_between_its_first_and_last_transverse_joint() {
    let (base, options) = heavy_search(None);
    let cut = critical(&base, &options, &liftoff::Monitor::NONE).expect("search");
    assert_eq!(cut.ends, Ends::Cut, "the scene's [plate] ends");
    let whole = CriticalOptions {
        ends: Some(Ends::Free),
        ..options
    };
    let free = critical(&base, &whole, &liftoff::Monitor::NONE).expect("search");
    let [lo, hi] = cut.read_x.expect("a cut lane");
    assert!(
        (lo + 2.25).abs() < 1e-12 && (hi - 2.25).abs() < 1e-12,
        "{lo} … {hi}"
    );
    assert!(free.read_x.is_none() && free.end_top.is_none());
    let inside = |x: f64| x > lo && x < hi;
    for (p, q) in cut.positions.iter().zip(&free.positions) {
        assert_eq!(p.outcome, RunOutcome::CONVERGED);
        let (eb, et) = (
            p.end_bottom.expect("end panels"),
            p.end_top.expect("end panels"),
        );
        assert_eq!(q.bottom.to_bits(), p.bottom.max(eb).to_bits());
        assert_eq!(q.top.to_bits(), p.top.max(et).to_bits());
        assert!(inside(p.bottom_at[0]) && inside(p.top_at[0]), "{p:?}");
        assert!(p.w_max <= q.w_max);
        for (a, b) in [
            (p.joint_shear, q.joint_shear),
            (p.dowel_force, q.dowel_force),
        ] {
            assert!(a.expect("joints") <= b.expect("joints"));
        }
    }
    // Read whole, the night's top tension peaks at the plate's cut end, the axle on it.
    let (Some(i), Some(j)) = (cut.top, free.top) else {
        panic!("no critical position");
    };
    assert!(
        !inside(free.positions[j].top_at[0]) && free.positions[j].top > cut.positions[i].top,
        "read whole {:?}, read inside {:?}",
        free.positions[j],
        cut.positions[i]
    );
    // The cut search's critical top position alone, read by hand.
    let p = &cut.positions[i];
    let mut alone = heavy_written(p.x, p.y);
    alone.combinations.retain(|c| c.name == "heavy");
    alone.model = alone.combinations[0].model.clone();
    let liftoff::Outcome::Combinations(runs) =
        liftoff::run(&alone, &liftoff::Monitor::NONE).expect("solve")
    else {
        panic!("a scene with combinations");
    };
    let r = runs.runs[0].outcome.as_ref().expect("solved");
    let e = &r.report.elements;
    let peak = |s1: &[f64]| {
        (0..s1.len())
            .filter(|&k| inside(e.x[k]))
            .map(|k| s1[k])
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let f = &r.report.field;
    let w = (0..f.w.len())
        .filter(|&n| f.x[n] >= lo - 1e-9 && f.x[n] <= hi + 1e-9)
        .map(|n| f.w[n])
        .fold(f64::NEG_INFINITY, f64::max);
    for (name, search, by_hand) in [
        ("bottom", p.bottom, peak(&e.bottom.s1)),
        ("top", p.top, peak(&e.top.s1)),
        ("w_max", p.w_max, w),
    ] {
        assert!(
            (search - by_hand).abs() <= 1e-9 * by_hand.abs(),
            "{name}: search {search} vs alone {by_hand}"
        );
    }
    // The table says what was read and what was not.
    let table = liftoff::output::critical::critical_table("pavement", &cut, None);
    assert!(
        table.contains("read between the transverse joints at x = -2.250 and 2.250 m")
            && table.contains("end panels, top")
            && table.contains("(not read)"),
        "{table}"
    );
}

/// Where the search takes the plate's ends from: a plate that says nothing of them is read
/// whole (a floor, an apron: its ends are its own) — here the pavement without its `[plate]
/// ends` —, a damage scene's lane as its `[traffic]` says (cut by default), and `ends` given
/// to the search over both.
#[test]
fn the_plates_ends_are_the_scenes_unless_the_search_is_told() {
    let one = |text: &str, ends: Option<Ends>| {
        let p = liftoff::load(&liftoff::Source::Toml(text), &coarse()).expect("scene");
        let load = if text.contains("name = \"single\"") {
            "single"
        } else {
            "axle"
        };
        let options = CriticalOptions {
            load: load.into(),
            grid: [1, 1],
            ends,
            ..CriticalOptions::default()
        };
        critical(&p, &options, &liftoff::Monitor::NONE).expect("search")
    };
    let pavement = include_str!("../examples/pavement-3x3.toml");
    let silent = pavement.replace("ends = \"cut\"", "");
    assert!(silent.len() < pavement.len());
    let c = one(&silent, None);
    assert!(c.ends == Ends::Free && c.read_x.is_none() && c.end_top.is_none());
    assert!(one(&silent, Some(Ends::Cut)).read_x.is_some());
    let lane = include_str!("../examples/pavement-damage.toml");
    assert!(
        !lane.contains("\nends"),
        "the bundled damage lane says nothing of its ends"
    );
    let c = one(lane, None);
    assert!(c.ends == Ends::Cut && c.read_x.is_some());
    let freed = lane.replace("growth = 0.02", "ends = \"free\"\ngrowth = 0.02");
    assert_eq!(one(&freed, None).ends, Ends::Free);
}

/// The runs of warm starts are cut from the grid, not from the cores: the search on one thread
/// and on sixteen gives the same positions to the bit (step counts too), and a share of the
/// grid that starts at a run's start (a Dask task's `indices`) gives what the whole search
/// gives there.
#[test]
fn the_search_is_the_same_on_any_number_of_threads() {
    let file = problem(SLAB);
    let on = |threads: usize, options: &CriticalOptions| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("pool")
            .install(|| critical(&file, options, &liftoff::Monitor::NONE))
            .expect("search")
    };
    let all = options([5, 3], true);
    let drop_time = |c: &liftoff::study::Critical| -> Vec<String> {
        c.positions
            .iter()
            .map(|p| {
                let mut v = serde_json::to_value(p).expect("json");
                v.as_object_mut().map(|o| o.remove("time_s"));
                v.to_string()
            })
            .collect()
    };
    let one = on(1, &all);
    let many = on(16, &all);
    assert_eq!(drop_time(&one), drop_time(&many));
    assert_eq!((one.bottom, one.top), (many.bottom, many.top));
    let run = CriticalOptions::RUN;
    let share = CriticalOptions {
        indices: Some((run..15).collect()),
        ..all
    };
    let part = on(2, &share);
    assert_eq!(drop_time(&part), drop_time(&one)[run..].to_vec());
}

/// On the iterative route (the half-space's T by FFT) the search runs its runs side by side on
/// more threads than cores, which share the plate's solves in batches: called on one thread,
/// its three runs (21 positions) go to a pool of three, whose solves batch whatever the
/// machine's cores. Every position equals that position searched alone (a run of one, on one
/// thread, nothing batched) to 1e-7 relative: each is a penalty solve whose conjugate
/// gradients stop at 1e-10 relative (warm against cold start, batched against single
/// triangular solves, which sum in another order), which leaves the stresses within ~1e-9;
/// 1e-7 is that with a margin, far below any change a wrong batched answer would make.
#[test]
fn runs_side_by_side_on_the_iterative_route_share_solves_without_changing_answers() {
    let night = SLAB
        .replace(
            "model = \"winkler\"\nmodulus = 27e6",
            "model = \"half-space\"\nyoungs_modulus = 1e8\npoissons_ratio = 0.35",
        )
        .replace(
            "poissons_ratio = 0.15",
            "poissons_ratio = 0.15\nthermal_expansion = 1e-5",
        )
        .replace(
            "[mesh]\nelements = [60, 48]",
            "[[load]]\nkind = \"temperature\"\ndifference = -10.0\n[mesh]\nelements = [30, 24]\n[solver]\nroute = \"iterative\"",
        );
    assert!(night.contains("half-space") && night.contains("iterative"));
    let file = problem(&night);
    let one_thread = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("pool");
    let all = options([21, 1], true);
    let search = one_thread
        .install(|| critical(&file, &all, &liftoff::Monitor::NONE))
        .expect("search");
    assert_eq!(search.positions.len(), 21);
    for (i, p) in search.positions.iter().enumerate() {
        assert_eq!(p.outcome, RunOutcome::CONVERGED, "position {i}");
        let alone = CriticalOptions {
            indices: Some(vec![i]),
            ..options([21, 1], true)
        };
        let a = one_thread
            .install(|| critical(&file, &alone, &liftoff::Monitor::NONE))
            .expect("alone");
        let q = &a.positions[0];
        for (name, x, y) in [
            ("bottom", p.bottom, q.bottom),
            ("top", p.top, q.top),
            ("w_max", p.w_max, q.w_max),
        ] {
            assert!(
                (x - y).abs() <= 1e-7 * x.abs().max(y.abs()),
                "{name} at position {i}: side by side {x}, alone {y}"
            );
        }
    }
}

/// Without `combination`, the search moves the load in the first combination it acts in: a
/// combination ahead of it without the load's case (night curling alone) is passed over, and
/// the one named in the result is the first with a factor on `traffic` ("axle"). One position
/// (a 1 × 1 grid) is enough to see the choice.
#[test]
fn the_default_combination_is_the_first_the_load_acts_in() {
    let text = include_str!("../examples/pavement-3x3.toml").replace(
        "[[combination]]\nname = \"axle\"\n",
        "[[combination]]\nname = \"curl\"\nfactors = { self-weight = 1.0, night = 1.0 }\n\n[[combination]]\nname = \"axle\"\n",
    );
    let base = liftoff::load(&liftoff::Source::Toml(&text), &coarse()).expect("scene");
    assert_eq!(base.combinations[0].name, "curl", "the replacement took");
    let options = CriticalOptions {
        load: "axle".into(),
        grid: [1, 1],
        ..CriticalOptions::default()
    };
    let c = critical(&base, &options, &liftoff::Monitor::NONE).expect("search");
    assert_eq!(c.combination.as_deref(), Some("axle"));
}

/// The grid's bounds: 1 to 201 points along each direction, as the error says; 0 and 202 are
/// refused naming `grid`, 1 and 201 pass.
#[test]
fn the_grid_is_one_to_two_hundred_and_one_points() {
    for bad in [[0, 3], [202, 3], [3, 202]] {
        let e = options(bad, false).validate().expect_err("refused");
        assert!(e.to_string().contains("grid"), "{bad:?}: {e}");
    }
    for good in [[1, 1], [201, 1], [1, 201]] {
        options(good, false)
            .validate()
            .unwrap_or_else(|e| panic!("{good:?}: {e}"));
    }
}
