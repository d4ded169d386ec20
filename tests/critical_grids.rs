//! `liftoff critical`'s grids placed on the panels (issue 36): a grid per panel holds the middle
//! of every panel's edge and every joint line, `along` puts the load on a joint (or just before
//! or after it) or at an edge, and on a scene whose uniform grid misses the middle of the panels'
//! edges the per-panel grid finds the larger edge stress there. The references are the panel
//! geometry read from the scene's own text (its `[plate]` and `[[joint]]` entries) and the
//! tire prints of the model's vehicle, not the search's list of points.

use std::process::Command;

use liftoff::scene::Overrides;
use liftoff::study::{critical, Along, CriticalOptions, Edge, RunOutcome};

/// The bundled 3 × 3 pavement: slabs of 4.5 m along x, a 3.0 m shoulder and two 3.6 m lanes
/// across, four joints, an axle named `axle`.
const PAVEMENT: &str = include_str!("../examples/pavement-3x3.toml");

/// Positions compare to this, m: the layout holds the joint lines in units of the half-length
/// L = 6.75 m and the search converts them back, one rounding each way (a few ulp of 6.75 m,
/// ~1e-15 m); the plate's edges are not involved (their points are the touching positions,
/// checked with their own tolerance below).
const TOL: f64 = 1e-12;

/// Prints that touch an edge stand a hair inside it: the search keeps them 1e-9 of the plate's
/// longer side (13.5 nm) on the plate, as the uniform grid always has.
const EDGE_TOL: f64 = 2e-8;

fn problem() -> liftoff::Problem {
    liftoff::load(&liftoff::Source::Toml(PAVEMENT), &Overrides::default()).expect("scene")
}

/// The scene's plate sides and its joint lines (name, axis 0 for x = const, position), read
/// from the TOML text.
fn geometry() -> ([f64; 2], Vec<(String, usize, f64)>) {
    let doc: toml::Table = PAVEMENT.parse().expect("toml");
    let plate = doc["plate"].as_table().expect("[plate]");
    let side = |k: &str| plate[k].as_float().expect("a side");
    let joints = doc["joint"]
        .as_array()
        .expect("[[joint]]")
        .iter()
        .map(|j| {
            let name = j["name"].as_str().expect("name").to_string();
            match (j.get("x"), j.get("y")) {
                (Some(x), None) => (name, 0, x.as_float().expect("x")),
                (None, Some(y)) => (name, 1, y.as_float().expect("y")),
                _ => panic!("a joint gives x or y"),
            }
        })
        .collect();
    ([side("length"), side("width")], joints)
}

/// The axle's prints about its reference point at heading 0: the lowest and highest print
/// edge along x and along y (from the model's vehicle, not from the search).
fn footprint(p: &liftoff::Problem) -> ([f64; 2], [f64; 2]) {
    let v = p.combinations[0]
        .model
        .vehicles
        .iter()
        .find(|v| v.name.as_deref() == Some("axle"))
        .expect("the axle");
    let tires = v.tires([0.0, 0.0, 0.0]).expect("tires");
    let lo = |i: usize| {
        tires
            .iter()
            .map(|t| t.centre[i] - t.size[i] / 2.0)
            .fold(f64::INFINITY, f64::min)
    };
    let hi = |i: usize| {
        tires
            .iter()
            .map(|t| t.centre[i] + t.size[i] / 2.0)
            .fold(f64::NEG_INFINITY, f64::max)
    };
    ([lo(0), lo(1)], [hi(0), hi(1)])
}

fn options() -> CriticalOptions {
    CriticalOptions {
        load: "axle".into(),
        combination: Some("axle".into()),
        ..CriticalOptions::default()
    }
}

/// The distinct values of `v` (within [`TOL`]), sorted.
fn distinct(mut v: Vec<f64>) -> Vec<f64> {
    v.sort_by(f64::total_cmp);
    v.dedup_by(|a, b| (*a - *b).abs() <= TOL);
    v
}

/// 5 × 3 points per panel: along x the fractions 0, ¼, ½, ¾, 1 of each 4.5 m slab, along y 0,
/// ½, 1 of the shoulder and the lanes, each joint line once — where the prints would leave the
/// plate (a panel side on its edge), the point where they touch the edge instead. The grid is
/// every x with every y, so it holds the middle of every panel's edge (the panel's middle x
/// with the prints at the plate's edge; the middle of a joint's length, on the joint) and every
/// joint line at every point along it.
#[test]
fn a_grid_per_panel_holds_the_middle_of_every_panel_edge_and_every_joint() {
    let p = problem();
    let ([a, b], joints) = geometry();
    let (lo, hi) = footprint(&p);
    let per_panel = CriticalOptions {
        grid_per_panel: Some([5, 3]),
        ..options()
    };
    let points = per_panel.points(&p).expect("points");
    // The panels' sides from the scene: its edges and its joint lines.
    let sides = |axis: usize, half: f64| -> Vec<f64> {
        let mut s = vec![-half, half];
        s.extend(joints.iter().filter(|j| j.1 == axis).map(|j| j.2));
        distinct(s)
    };
    // The reference points that keep the prints on the plate along an axis.
    let range = |axis: usize, half: f64| [-half - lo[axis], half - hi[axis]];
    let expected = |axis: usize, half: f64, n: usize| -> Vec<f64> {
        let s = sides(axis, half);
        let r = range(axis, half);
        let mut v = Vec::new();
        for w in s.windows(2) {
            for j in 0..n {
                let at = w[0] + (w[1] - w[0]) * j as f64 / (n - 1) as f64;
                v.push(at.clamp(r[0], r[1]));
            }
        }
        distinct(v)
    };
    let (xs, ys) = (
        distinct(points.iter().map(|q| q[0]).collect()),
        distinct(points.iter().map(|q| q[1]).collect()),
    );
    // The plate-edge points are the touching positions, which lie 1e-9·13.5 m inside the
    // range computed here: EDGE_TOL at the range's ends, TOL everywhere else.
    let matches = |got: &[f64], want: &[f64], r: [f64; 2]| {
        got.len() == want.len()
            && got.iter().zip(want).all(|(g, w)| {
                let tol = if *w == r[0] || *w == r[1] {
                    EDGE_TOL
                } else {
                    TOL
                };
                (g - w).abs() <= tol
            })
    };
    let ex = expected(0, a / 2.0, 5);
    let ey = expected(1, b / 2.0, 3);
    assert!(
        matches(&xs, &ex, range(0, a / 2.0)),
        "x: {xs:?}\nexpected {ex:?}"
    );
    assert!(
        matches(&ys, &ey, range(1, b / 2.0)),
        "y: {ys:?}\nexpected {ey:?}"
    );
    assert_eq!(
        points.len(),
        xs.len() * ys.len(),
        "every x with every y, once"
    );
    assert_eq!(
        (xs.len(), ys.len()),
        (13, 7),
        "x: 3 slabs × 5 − 2 shared; y: 3 panels × 3 − 2 shared"
    );
    let has = |x: f64, y: f64, tol: f64| {
        points
            .iter()
            .any(|q| (q[0] - x).abs() <= tol && (q[1] - y).abs() <= tol)
    };
    // The middle of each slab's edges: the prints touching the plate's lower and upper edge.
    let [ry0, ry1] = range(1, b / 2.0);
    for w in sides(0, a / 2.0).windows(2) {
        let mid = (w[0] + w[1]) / 2.0;
        for y in [ry0, ry1] {
            assert!(has(mid, y, EDGE_TOL), "mid-panel edge ({mid}, {y})");
        }
    }
    // Every joint line, at every point along it.
    for (name, axis, at) in &joints {
        let along = if *axis == 0 { &ys } else { &xs };
        for &u in along {
            let (x, y) = if *axis == 0 { (*at, u) } else { (u, *at) };
            assert!(has(x, y, TOL), "joint {name} at ({x}, {y})");
        }
        // The middle of the joint's length in each panel it bounds, on it.
        let s = sides(1 - axis, if *axis == 0 { b / 2.0 } else { a / 2.0 });
        let r = range(1 - axis, if *axis == 0 { b / 2.0 } else { a / 2.0 });
        for w in s.windows(2) {
            let mid = ((w[0] + w[1]) / 2.0).clamp(r[0], r[1]);
            let (x, y) = if *axis == 0 { (*at, mid) } else { (mid, *at) };
            assert!(
                has(x, y, TOL),
                "middle of joint {name}'s panel side ({x}, {y})"
            );
        }
    }
    // The uniform default grid misses the outer slabs' middles (x = ±4.5 m): that is the gap.
    let uniform = options().points(&p).expect("points");
    assert!(
        !uniform.iter().any(|q| (q[0].abs() - 4.5).abs() < 0.1),
        "the uniform 11 × 9 grid has no point within 0.1 m of x = ±4.5"
    );
}

/// Along a transverse joint (T2, x = 2.25 m) every point stands before it (the prints end on
/// the line), on it (the reference point on the line) or after it (the prints start on it),
/// each of the three at every y of the grid; along a longitudinal joint (lanes, y = 1.5 m) the
/// same across y; at an edge the prints touch it. Two lines that cross share their point
/// there once.
#[test]
fn along_a_joint_the_load_stands_on_it_or_just_before_or_after_it() {
    let p = problem();
    let (_, joints) = geometry();
    let (lo, hi) = footprint(&p);
    let at = |name: &str| {
        joints
            .iter()
            .find(|j| j.0 == name)
            .map(|j| (j.1, j.2))
            .expect("joint")
    };
    for name in ["T2", "lanes"] {
        let (axis, c) = at(name);
        let o = CriticalOptions {
            grid: [5, 5],
            along: vec![Along::Joint(name.into())],
            ..options()
        };
        let points = o.points(&p).expect("points");
        let mut sides = [0_usize; 3];
        for q in &points {
            let r = q[axis];
            let side = if (r + hi[axis] - c).abs() <= TOL {
                0 // the prints end on the line
            } else if (r - c).abs() <= TOL {
                1 // the reference point on it
            } else if (r + lo[axis] - c).abs() <= TOL {
                2 // the prints start on it
            } else {
                panic!("{name}: ({}, {}) is off the joint line {c}", q[0], q[1]);
            };
            sides[side] += 1;
        }
        assert_eq!(
            sides,
            [5, 5, 5],
            "{name}: before, on, after at each of 5 points"
        );
    }
    // An edge: every print inside the plate, the outermost touching y = −5.1 m.
    let edge = CriticalOptions {
        grid: [7, 5],
        along: vec![Along::Edge(Edge::YMinus)],
        ..options()
    };
    let points = edge.points(&p).expect("points");
    assert_eq!(points.len(), 7);
    for q in &points {
        let lowest = q[1] + lo[1];
        assert!(
            lowest >= -5.1 && lowest + 5.1 <= EDGE_TOL,
            "prints reach y = {lowest}"
        );
    }
    // T2 and lanes cross at (2.25, 1.5), a point of both lines' grids per panel (7 points
    // along each, 3 across): the point is searched once.
    let both = CriticalOptions {
        grid_per_panel: Some([3, 3]),
        along: vec![Along::Joint("T2".into()), Along::Joint("lanes".into())],
        ..options()
    };
    assert_eq!(both.points(&p).expect("points").len(), 21 + 21 - 1);
}

/// The pavement's shoulder edge (y = −5.1 m, the prints touching it) searched with a uniform
/// grid of 4 points along x — which here are the plate's ends and the approaches of the two
/// joints (x = ±6.66, ±2.22 m), the middle of no slab — and with 3 points per panel, which
/// adds the middle of each slab's edge. The bottom tension under the axle is smallest where
/// the dowels hand load to the next slab and where the slab ends (a corner: the axle tips it,
/// its tension moves to the top face), and the classical critical case is the load at the
/// middle of the free edge (PCA 1984): the per-panel search finds its maximum in the middle of
/// a slab, larger (1.70 against 0.77 MPa as measured, the middle slab read as the lane's ends
/// are a cut; 1.71 against 1.26 with the whole plate read, the uniform grid's largest then at
/// the cut end; the assertion asks for a fifth, far beyond any tolerance of the solves, 1e-9),
/// and the same as the uniform search at the points they share (the ends, to 1e-9). (On this pavement the doweled joints pull the edge's
/// maximum off the middle: 5 points per panel find 1.86 MPa a quarter of a slab from a joint —
/// also a point the uniform 4 misses.)
#[test]
fn the_per_panel_grid_finds_the_larger_stress_in_the_middle_of_the_edge() {
    let p = problem();
    let edge = vec![Along::Edge(Edge::YMinus)];
    let uniform = CriticalOptions {
        grid: [4, 1],
        along: edge.clone(),
        ..options()
    };
    let per_panel = CriticalOptions {
        grid_per_panel: Some([3, 1]),
        along: edge,
        ..options()
    };
    let u = critical(&p, &uniform, &liftoff::Monitor::NONE).expect("uniform");
    let g = critical(&p, &per_panel, &liftoff::Monitor::NONE).expect("per panel");
    for c in [&u, &g] {
        assert!(c
            .positions
            .iter()
            .all(|q| q.outcome == RunOutcome::CONVERGED));
    }
    let slab_middles = [-4.5, 0.0, 4.5];
    assert!(
        u.positions
            .iter()
            .all(|q| slab_middles.iter().all(|m| (q.x - m).abs() > 1.0)),
        "the uniform points are no slab's middle: {:?}",
        u.positions.iter().map(|q| q.x).collect::<Vec<_>>()
    );
    let (Some(iu), Some(ig)) = (u.bottom, g.bottom) else {
        panic!("no critical position");
    };
    let (su, sg) = (u.positions[iu].bottom, g.positions[ig].bottom);
    assert!(
        sg > 1.2 * su,
        "per panel {:.3} MPa at x = {:.3}, uniform {:.3} MPa at x = {:.3}",
        sg * 1e-6,
        g.positions[ig].x,
        su * 1e-6,
        u.positions[iu].x
    );
    let x = g.positions[ig].x;
    assert!(
        slab_middles.iter().any(|m| (x - m).abs() <= TOL),
        "the per-panel maximum stands in a slab's middle, not at x = {x}"
    );
    // The plate's ends are on both grids: the same answers there.
    for q in &u.positions {
        if let Some(r) = g.positions.iter().find(|r| (r.x - q.x).abs() <= TOL) {
            assert!((r.bottom - q.bottom).abs() <= 1e-9 * q.bottom.abs());
        }
    }
    // critical.json records what was searched; the table says it.
    let json = serde_json::to_value(&g).expect("json");
    assert_eq!(json["grid_per_panel"], serde_json::json!([3, 1]));
    assert_eq!(json["along"], serde_json::json!(["edge:y-"]));
    assert!(json.get("grid").is_none());
    let table = liftoff::output::critical::critical_table("edge", &g, None);
    assert!(
        table.contains("3 × 1 points per panel on 3 × 3 panels, along edge:y-"),
        "{table}"
    );
}

/// The influence maps of a per-panel search draw the joints, the searched positions, the
/// critical one and the load's prints there, each named in the legend.
#[test]
fn the_maps_draw_the_joints_the_positions_and_the_critical_one() {
    let p = problem();
    let o = CriticalOptions {
        grid_per_panel: Some([3, 3]),
        ..options()
    };
    let c = critical(&p, &o, &liftoff::Monitor::NONE).expect("search");
    let dir = tempfile::tempdir().expect("tempdir");
    liftoff::output::critical::write_critical(dir.path(), &c, "pavement").expect("files");
    let svg = std::fs::read_to_string(dir.path().join("influence-bottom.svg")).expect("svg");
    for text in [
        "searched position",
        "critical position: largest σ₁ bottom",
        "tire print",
        "doweled joint",
        "tied joint",
        "aggregate joint",
    ] {
        assert!(svg.contains(text), "legend: {text}");
    }
    assert!(
        !svg.contains("no converged solve"),
        "no grey cell, no grey entry"
    );
}

/// The command line: `--along joint:T2` searches the points the library lists for it, and
/// `--grid-per-panel` prints what it searched.
#[test]
fn the_command_line_takes_the_grid_options() {
    let p = problem();
    let run = |args: &[&str]| {
        let o = Command::new(env!("CARGO_BIN_EXE_liftoff"))
            .args([
                "critical",
                "example:pavement-3x3",
                "--load",
                "axle",
                "--combination",
                "axle",
            ])
            .args(args)
            .output()
            .expect("run liftoff");
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        String::from_utf8_lossy(&o.stdout).to_string()
    };
    let out = run(&["--along", "joint:T2", "--grid", "3,3", "--json"]);
    let doc: serde_json::Value = serde_json::from_str(&out).expect("json");
    let got: Vec<(f64, f64)> = doc["positions"]
        .as_array()
        .expect("positions")
        .iter()
        .map(|q| {
            (
                q["x"].as_f64().unwrap_or(f64::NAN),
                q["y"].as_f64().unwrap_or(f64::NAN),
            )
        })
        .collect();
    let o = CriticalOptions {
        grid: [3, 3],
        along: vec![Along::Joint("T2".into())],
        ..options()
    };
    let want: Vec<(f64, f64)> = o
        .points(&p)
        .expect("points")
        .iter()
        .map(|q| (q[0], q[1]))
        .collect();
    assert_eq!(got, want, "the binary searches the library's points");
    let table = run(&["--grid-per-panel", "3,1"]);
    assert!(
        table.contains("over 21 positions") && table.contains("3 × 1 points per panel"),
        "{table}"
    );
}

/// A joint `along` does not name is refused before anything is solved, naming the scene's
/// joints (or saying it has none) and the edges; the words of `along` read and print alike.
#[test]
fn an_unknown_joint_is_refused_naming_the_joints() {
    let along = |name: &str| CriticalOptions {
        along: vec![Along::Joint(name.into())],
        ..options()
    };
    match along("T9").points(&problem()) {
        Err(liftoff::Error::Invalid { field, message }) => {
            assert_eq!(field, "along");
            assert!(
                message.contains("no joint named `T9`")
                    && message.contains("T1, T2, shoulder, lanes")
                    && message.contains("edge:y+"),
                "{message}"
            );
        }
        other => panic!("expected an invalid `along`, got {other:?}"),
    }
    let slab = PAVEMENT
        .split("[[joint]]")
        .next()
        .map(|head| format!("{head}[[load]]\nkind = \"axle\"\nname = \"axle\"\nstandard = \"esal-single-dual\"\nx = 0.0\ny = 0.0\n"))
        .expect("the scene's head");
    let plain = liftoff::load(&liftoff::Source::Toml(&slab), &Overrides::default()).expect("slab");
    let e = CriticalOptions {
        combination: None,
        ..along("T2")
    }
    .points(&plain)
    .expect_err("no joints");
    assert!(e.to_string().contains("the plate has no joints"), "{e}");
    for word in ["joint:T2", "edge:x-", "edge:x+", "edge:y-", "edge:y+"] {
        let a: Along = word.parse().expect(word);
        assert_eq!(a.to_string(), word);
    }
    for bad in ["joint:", "edge:z", "T2", "edges:x-"] {
        assert!(bad.parse::<Along>().is_err(), "{bad}");
    }
}
