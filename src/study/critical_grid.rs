//! What a critical-position search moves over: its options ([`CriticalOptions`]), the lines it
//! may follow ([`Along`]: a joint or an edge of the plate), and its grid of reference points for
//! each heading with the plate's joints and the load's prints that its maps and table show. The
//! search itself is [`super::critical`].

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::layout::{Axis, Ends, JointType};
use crate::model::Model;

/// What to move and over what.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct CriticalOptions {
    /// The `name` of the `axle` or `gear` load to move.
    pub load: String,
    /// Reference points along x and y (≥ 1 each; 1 keeps the load's own coordinate), evenly
    /// spaced over the plate from where the prints touch one edge to where they touch the
    /// other.
    pub grid: [usize; 2],
    /// Reference points per panel along x and y instead of the uniform `grid` (which is then
    /// not read): in each panel (the rectangles between the joint lines of every kind; a plate
    /// without joints is one panel) NX × NY points at the fractions 0, 1/(N − 1), …, 1 of its
    /// sides — the middle of the panel when N = 1 —, a point on a joint line taken once for
    /// both panels, a point whose prints would leave the plate moved inward to where they
    /// touch its edge.
    pub grid_per_panel: Option<[usize; 2]>,
    /// Search along these lines only (a joint by name, an edge of the plate; see [`Along`]);
    /// empty: the whole plate.
    pub along: Vec<Along>,
    /// Headings, degrees (empty: the load's own).
    pub headings: Vec<f64>,
    /// The combination the load acts in (default: the first that has its case).
    pub combination: Option<String>,
    /// Start each position from its neighbour's answer (false: every position cold).
    pub warm: bool,
    /// Solve only these positions of the grid (by index; a Dask task's share), all when None.
    pub indices: Option<Vec<usize>>,
    /// Read a position whose load is another's mirror image, on a plate symmetric about that
    /// line, off that one's answer instead of solving it (false: solve every position; a
    /// scene with `mesh.symmetry = "none"` never mirrors).
    pub mirror: bool,
    /// What the plate's ends across the lane are ([`super::ends`]): `Cut` reads every
    /// position's stresses, deflection and joint forces between the first and the last
    /// transverse joint only, where there are two or more; `Free` reads the whole plate. None
    /// (the default): as the scene says (`[plate] ends`, else its `[traffic]`'s), else free.
    pub ends: Option<Ends>,
}

impl Default for CriticalOptions {
    /// An 11 × 9 grid (odd, so that the middle lines are on it), the load's own heading,
    /// warm starts.
    fn default() -> Self {
        Self {
            load: String::new(),
            grid: [11, 9],
            grid_per_panel: None,
            along: Vec::new(),
            headings: Vec::new(),
            combination: None,
            warm: true,
            indices: None,
            mirror: true,
            ends: None,
        }
    }
}

impl CriticalOptions {
    /// Positions per warm-started run: the grid order (heading, then y, then x) is cut into runs
    /// of this many, each started cold and each position in it from the one before; the runs
    /// are solved side by side. Fixed, so that every answer and every step count is the same
    /// on any number of cores (and a share of the grid in `indices` that starts at a multiple
    /// of it and is a multiple of it long solves exactly what the whole search solves there).
    /// Ten: the cold start of each run is a tenth of its work, and the default 11 × 9 grid
    /// gives ten runs to share out.
    pub const RUN: usize = 10;

    /// Check the options; errors name the field.
    pub fn validate(&self) -> Result<()> {
        if self.load.trim().is_empty() {
            return Err(Error::invalid(
                "load",
                "give the name of the axle or gear load to move (its `name` in the scene)",
            ));
        }
        if self.grid.iter().any(|&n| n == 0 || n > 201) {
            return Err(Error::invalid(
                "grid",
                format!("must be 1..=201 points along x and y, got {:?}", self.grid),
            ));
        }
        if let Some(n) = self
            .grid_per_panel
            .filter(|n| n.iter().any(|&n| n == 0 || n > 201))
        {
            return Err(Error::invalid(
                "grid_per_panel",
                format!("must be 1..=201 points per panel along x and y, got {n:?}"),
            ));
        }
        if let Some(h) = self.headings.iter().find(|h| !h.is_finite()) {
            return Err(Error::invalid(
                "headings",
                format!("must be finite, got {h}"),
            ));
        }
        Ok(())
    }
}

/// An edge of the plate (`edge:x-` … in [`Along`]): the side x = −a/2 (`x-`), x = +a/2 (`x+`),
/// y = −b/2 (`y-`) or y = +b/2 (`y+`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Edge {
    /// x = −a/2.
    XMinus,
    /// x = +a/2.
    XPlus,
    /// y = −b/2.
    YMinus,
    /// y = +b/2.
    YPlus,
}

impl Edge {
    /// Every edge with its word.
    const WORDS: [(Edge, &'static str); 4] = [
        (Edge::XMinus, "x-"),
        (Edge::XPlus, "x+"),
        (Edge::YMinus, "y-"),
        (Edge::YPlus, "y+"),
    ];

    /// Its word (`x-`, `x+`, `y-`, `y+`).
    pub fn word(self) -> &'static str {
        Edge::WORDS
            .iter()
            .find(|(e, _)| *e == self)
            .map_or("", |(_, w)| w)
    }
}

/// A line the search runs along instead of covering the whole plate (`--along`): a joint by
/// its name (`joint:T2`) or an edge of the plate (`edge:y+`). Along the line the reference
/// points are those of the grid along the line's direction ([`CriticalOptions::grid`] or
/// [`CriticalOptions::grid_per_panel`]); across it, on a joint, three: the prints ending at the
/// line on its lower side (before: a transverse joint's approach slab for a load travelling
/// towards +x), the reference point on the line, and the prints starting at the line on its
/// upper side (after: the leave slab); on an edge one, the prints touching the edge from
/// inside (as the uniform grid's outermost points).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "String", into = "String")]
pub enum Along {
    /// The joint of this `name`.
    Joint(String),
    /// An edge of the plate.
    Edge(Edge),
}

impl std::str::FromStr for Along {
    type Err = Error;

    /// `joint:NAME`, or `edge:` with one of `x-`, `x+`, `y-`, `y+`.
    fn from_str(s: &str) -> Result<Self> {
        let bad = || {
            Error::invalid(
                "along",
                format!("expected joint:NAME or edge:x-, edge:x+, edge:y-, edge:y+, got `{s}`"),
            )
        };
        match s.trim().split_once(':') {
            Some(("joint", name)) if !name.trim().is_empty() => {
                Ok(Along::Joint(name.trim().to_string()))
            }
            Some(("edge", word)) => Edge::WORDS
                .iter()
                .find(|(_, w)| *w == word.trim())
                .map(|(e, _)| Along::Edge(*e))
                .ok_or_else(bad),
            _ => Err(bad()),
        }
    }
}

impl std::fmt::Display for Along {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Along::Joint(name) => write!(f, "joint:{name}"),
            Along::Edge(e) => write!(f, "edge:{}", e.word()),
        }
    }
}

impl TryFrom<String> for Along {
    type Error = Error;
    fn try_from(s: String) -> Result<Self> {
        s.parse()
    }
}

impl From<Along> for String {
    fn from(a: Along) -> String {
        a.to_string()
    }
}

/// A joint line of the searched plate in metres (for the maps and critical.json).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct JointLine {
    /// The joint's name.
    pub name: String,
    /// Its kind.
    pub kind: JointType,
    /// `x` for a line x = `at` (across the plate's width), `y` for a line y = `at`.
    pub axis: &'static str,
    /// The line's coordinate, m from the plate's centre.
    pub at: f64,
}

/// The moved load's tire prints about its reference point at one heading.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Footprint {
    /// Heading, degrees.
    pub heading: f64,
    /// Each print's [x0, x1] and [y0, y1], m, relative to the reference point.
    pub prints: Vec<[[f64; 2]; 2]>,
}

/// The reference points of a search and what its maps and table need of the plate.
pub(super) struct Grid {
    /// (x, y, heading) in grid order: heading, then y, then x (along lines: line by line).
    pub(super) points: Vec<[f64; 3]>,
    /// The plate's sides, m.
    pub(super) plate: [f64; 2],
    /// The largest step between neighbouring coordinates of the first heading's points, m.
    pub(super) spacing: [f64; 2],
    /// Panels along x and y.
    pub(super) panels: [usize; 2],
    /// The joint lines, m.
    pub(super) joints: Vec<JointLine>,
    /// The prints about the reference point, per heading.
    pub(super) prints: Vec<Footprint>,
}

/// A line of [`Along`] resolved on the plate: the axis it lies across (0: a line x = const) and
/// either a joint's coordinate (m) or which edge (false: the lower one).
#[derive(Debug, Clone, Copy)]
enum Line {
    /// A joint: the axis it lies across, its coordinate and a segment's extent along it (m).
    Joint {
        across: usize,
        at: f64,
        span: Option<[f64; 2]>,
    },
    Edge {
        across: usize,
        high: bool,
    },
}

/// `n` points across the panel [w0, w1], its sides included (the middle alone for n = 1);
/// written so that t = 0 and t = 1 give w0 and w1 exactly, and a joint line shared by two
/// panels is the same number from both.
fn panel_points([w0, w1]: [f64; 2], n: usize) -> Vec<f64> {
    if n == 1 {
        return vec![0.5 * w0 + 0.5 * w1];
    }
    (0..n)
        .map(|j| {
            let t = j as f64 / (n - 1) as f64;
            w0 * (1.0 - t) + w1 * t
        })
        .collect()
}

/// The grid of reference points of the model's vehicle `k` for each heading (see the module's
/// description and [`CriticalOptions`]).
pub(super) fn grid(model: &Model, k: usize, options: &CriticalOptions) -> Result<Grid> {
    let v = &model.vehicles[k];
    let [a, b] = v.frame.plate;
    let half = [a / 2.0, b / 2.0];
    let [own_x, own_y, own] = v.at;
    let axes = [Axis::X, Axis::Y];
    // Joint lines in metres (the layout holds them in the unit system).
    let to_m = |axis: Axis, u: f64| u / v.frame.scale_xy[usize::from(axis == Axis::Y)];
    let joints: Vec<JointLine> = model
        .layout
        .joints
        .iter()
        .map(|j| JointLine {
            name: j.name.clone(),
            kind: j.kind.kind(),
            axis: j.axis.name(),
            at: to_m(j.axis, j.at),
        })
        .collect();
    // The panels' sides along each axis: the plate's edges and every joint line between them.
    let bounds: Vec<Vec<f64>> = axes
        .iter()
        .enumerate()
        .map(|(i, &axis)| {
            let mut s = vec![-half[i]];
            s.extend(model.layout.lines(axis).iter().map(|&u| to_m(axis, u)));
            s.push(half[i]);
            s
        })
        .collect();
    let panels = model.layout.panel_counts();
    // The lines to search along, each checked against the plate before anything is solved.
    let lines: Vec<Line> = options
        .along
        .iter()
        .map(|line| match line {
            Along::Joint(name) => model
                .layout
                .joints
                .iter()
                .find(|j| &j.name == name)
                .map(|j| {
                    let along = if j.axis == Axis::X { Axis::Y } else { Axis::X };
                    Line::Joint {
                        across: usize::from(j.axis == Axis::Y),
                        at: to_m(j.axis, j.at),
                        span: j.span.map(|s| s.map(|v| to_m(along, v))),
                    }
                })
                .ok_or_else(|| {
                    let names: Vec<&str> = joints.iter().map(|j| j.name.as_str()).collect();
                    Error::invalid(
                        "along",
                        format!(
                            "no joint named `{name}`: {}; the plate's edges are edge:x-, edge:x+, edge:y-, edge:y+",
                            if names.is_empty() {
                                "the plate has no joints".to_string()
                            } else {
                                format!("the plate's joints are {}", names.join(", "))
                            }
                        ),
                    )
                }),
            Along::Edge(e) => Ok(match e {
                Edge::XMinus => Line::Edge { across: 0, high: false },
                Edge::XPlus => Line::Edge { across: 0, high: true },
                Edge::YMinus => Line::Edge { across: 1, high: false },
                Edge::YPlus => Line::Edge { across: 1, high: true },
            }),
        })
        .collect::<Result<_>>()?;
    let headings = if options.headings.is_empty() {
        vec![own]
    } else {
        options.headings.clone()
    };
    // Coordinates closer than this are one (a hair, as the inset below).
    let tol = 1e-9 * a.max(b);
    let clean = |mut c: Vec<f64>| -> Vec<f64> {
        c.sort_by(f64::total_cmp);
        c.dedup_by(|p, q| (*p - *q).abs() <= tol);
        c
    };
    let mut points = Vec::new();
    let mut prints = Vec::with_capacity(headings.len());
    for &heading in &headings {
        let tires = v.tires([0.0, 0.0, heading])?;
        let lo = |axis: usize| {
            tires
                .iter()
                .map(|t| t.centre[axis] - t.size[axis] / 2.0)
                .fold(f64::INFINITY, f64::min)
        };
        let hi = |axis: usize| {
            tires
                .iter()
                .map(|t| t.centre[axis] + t.size[axis] / 2.0)
                .fold(f64::NEG_INFINITY, f64::max)
        };
        prints.push(Footprint {
            heading,
            prints: tires
                .iter()
                .map(|t| {
                    let side =
                        |i: usize| [t.centre[i] - t.size[i] / 2.0, t.centre[i] + t.size[i] / 2.0];
                    [side(0), side(1)]
                })
                .collect(),
        });
        // The reference points that keep every print on the plate, a hair inside.
        let inset = 1e-9 * a.max(b);
        let range = |axis: usize| -> Result<[f64; 2]> {
            let r = [
                -half[axis] - lo(axis) + inset,
                half[axis] - hi(axis) - inset,
            ];
            if r[0] > r[1] {
                return Err(Error::invalid(
                    "load",
                    format!(
                        "the load `{}` at heading {heading}° is wider than the plate along {}: no position keeps its tires on it",
                        options.load,
                        if axis == 0 { "x" } else { "y" }
                    ),
                ));
            }
            Ok(r)
        };
        let r = [range(0)?, range(1)?];
        let on_plate = |axis: usize, c: Vec<f64>| -> Vec<f64> {
            clean(
                c.into_iter()
                    .map(|p| p.clamp(r[axis][0], r[axis][1]))
                    .collect(),
            )
        };
        // The grid's coordinates along one axis: uniform over the range, or per panel.
        let along = |axis: usize, own: f64| -> Vec<f64> {
            match options.grid_per_panel {
                Some(n) => on_plate(
                    axis,
                    bounds[axis]
                        .windows(2)
                        .flat_map(|w| panel_points([w[0], w[1]], n[axis]))
                        .collect(),
                ),
                None => {
                    let (r, n) = (r[axis], options.grid[axis]);
                    if n == 1 {
                        vec![own.clamp(r[0], r[1])]
                    } else {
                        (0..n)
                            .map(|i| r[0] + (r[1] - r[0]) * i as f64 / (n - 1) as f64)
                            .collect()
                    }
                }
            }
        };
        let own_at = [own_x, own_y];
        if lines.is_empty() {
            let (xs, ys) = (along(0, own_x), along(1, own_y));
            for &y in &ys {
                for &x in &xs {
                    points.push([x, y, heading]);
                }
            }
            continue;
        }
        let first = points.len();
        for &line in &lines {
            // Across the line: before it, on it and after it (a joint), or the edge's own.
            let (across, at, span) = match line {
                Line::Joint { across, at, span } => (
                    across,
                    on_plate(across, vec![at - hi(across), at, at - lo(across)]),
                    span,
                ),
                Line::Edge { across, high } => (across, vec![r[across][usize::from(high)]], None),
            };
            // Along a segment: the grid's points on it, or its middle where the grid has none.
            let mut length = along(1 - across, own_at[1 - across]);
            if let Some([a, b]) = span {
                length.retain(|&c| c >= a - tol && c <= b + tol);
                if length.is_empty() {
                    let [lo_r, hi_r] = r[1 - across];
                    length.push((0.5 * (a + b)).clamp(lo_r, hi_r));
                }
            }
            let (xs, ys) = if across == 0 {
                (at, length)
            } else {
                (length, at)
            };
            for &y in &ys {
                for &x in &xs {
                    // A point two lines share (where they cross) is solved once.
                    let seen = points[first..]
                        .iter()
                        .any(|p: &[f64; 3]| (p[0] - x).abs() <= tol && (p[1] - y).abs() <= tol);
                    if !seen {
                        points.push([x, y, heading]);
                    }
                }
            }
        }
    }
    // On a shaped plate, the positions that keep every print on its cells.
    if model.layout.is_shaped() {
        let mut kept = Vec::with_capacity(points.len());
        for p in points {
            if model.prints_on_plate(k, p)? {
                kept.push(p);
            }
        }
        if kept.is_empty() {
            return Err(Error::invalid(
                "load",
                format!(
                    "no position of the grid keeps the prints of `{}` on the plate: every one falls on an opening or outside the outline — refine the grid or check the outline",
                    options.load
                ),
            ));
        }
        points = kept;
    }
    // The largest step between neighbouring coordinates of the first heading's points.
    let first: Vec<&[f64; 3]> = points.iter().take_while(|p| p[2] == headings[0]).collect();
    let step = |axis: usize| {
        clean(first.iter().map(|p| p[axis]).collect())
            .windows(2)
            .map(|w| w[1] - w[0])
            .fold(0.0, f64::max)
    };
    let spacing = [step(0), step(1)];
    Ok(Grid {
        points,
        plate: [a, b],
        spacing,
        panels,
        joints,
        prints,
    })
}
