//! The critical position of a vehicle load (`liftoff critical`): the named `axle` or `gear`
//! load moved over a grid of reference points inside the plate (and over headings where asked),
//! the rest of its combination present, each position its own contact problem on operators
//! assembled once (K, B, T shared; only the load vector changes), in runs of
//! [`CriticalOptions::RUN`] positions side by side, each warm-started from the position before
//! it; the positions that give the largest
//! tension at the bottom and at the top face and the largest deflection — and on a jointed
//! plate the largest joint shear per length and the largest dowel force.
//!
//! The grid runs, for each heading, from the position where the prints touch one edge of the
//! plate to where they touch the other, so the edge positions of the classical critical cases
//! (the outer tire on the free edge) are on it. A uniform grid over a jointed plate misses the
//! middle of a panel's edge and the joints wherever its step does not fit the panels; a grid
//! per panel ([`CriticalOptions::grid_per_panel`]) puts the same fractions of every panel on
//! it — its edges included, so an odd count has the middle —, and [`Along`] runs the search
//! along a joint (the prints just before it, the load on it, the prints just after it) or an
//! edge of the plate. A reference point whose prints would leave the plate (a panel's side on
//! the plate's edge) moves inward to where the prints touch the edge, as the uniform grid's
//! outermost points do; points that coincide then are one.
//!
//! The scene is validated once ([`crate::load`]); the load is the model's [`Vehicle`](crate::vehicle::Vehicle), moved to
//! each position by [`Model::place`].

use std::time::Instant;

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::RunOutcome;
use crate::analysis;
use crate::combination::assemble_for;
use crate::error::{Error, Result};
use crate::layout::{Axis, JointType};
use crate::model::{Model, SymmetryMode};
use crate::monitor::{Cases, Monitor};
use crate::scene::Problem;
use crate::solve::Carry;
use crate::units::{Measure, UnitSystem};

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

    /// Validate, then run [`critical`] on `problem`.
    pub fn run(&self, problem: &Problem, monitor: &Monitor<'_>) -> Result<Critical> {
        critical(problem, self, monitor)
    }

    /// How many positions the search has on `problem` ([`critical_positions`]).
    pub fn positions(&self, problem: &Problem) -> Result<usize> {
        critical_positions(problem, self)
    }

    /// The reference points (x, y, m; heading, degrees) the search solves on `problem`, in its
    /// order, without solving ([`critical_points`]).
    pub fn points(&self, problem: &Problem) -> Result<Vec<[f64; 3]>> {
        critical_points(problem, self)
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

/// One position's outcome: where, and what it causes.
#[derive(Debug, Clone, Serialize)]
pub struct Position {
    /// Reference point x, m.
    pub x: f64,
    /// Reference point y, m.
    pub y: f64,
    /// Heading, degrees.
    pub heading: f64,
    /// How the solve ended.
    pub outcome: RunOutcome,
    /// Penalty steps or face solves.
    pub iterations: usize,
    /// Largest principal stress at the bottom face, Pa.
    pub bottom: f64,
    /// Where (x, y), m.
    pub bottom_at: [f64; 2],
    /// Largest principal stress at the top face, Pa.
    pub top: f64,
    /// Where (x, y), m.
    pub top_at: [f64; 2],
    /// Largest downward deflection, m.
    pub w_max: f64,
    /// Contact area over plate area.
    pub contact_fraction: f64,
    /// On a jointed plate: the largest shear per unit length along any joint with a
    /// distributed spring (aggregate, tied), |c (w⁻ − w⁺)|, N/m (absent without such joints).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub joint_shear: Option<f64>,
    /// On a jointed plate with dowels: the largest dowel force |k_d (w⁻ − w⁺)|, N.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dowel_force: Option<f64>,
    /// Seconds for this position.
    pub time_s: f64,
}

/// The search's result.
#[derive(Debug, Clone, Serialize)]
pub struct Critical {
    /// The moved load's name.
    pub load: String,
    /// The combination it acted in (None: a scene without combinations).
    pub combination: Option<String>,
    /// Plate sides (length along x, width along y), m.
    pub plate: [f64; 2],
    /// The uniform grid searched (absent when the grid was per panel).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub grid: Option<[usize; 2]>,
    /// The grid per panel searched (absent when the grid was uniform).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub grid_per_panel: Option<[usize; 2]>,
    /// Panels along x and y (1 × 1 without joints).
    pub panels: [usize; 2],
    /// The lines searched along (absent: the whole plate).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub along: Vec<Along>,
    /// The largest step between neighbouring reference points of the first heading along x and
    /// y, m (a uniform grid's spacing; 0 where there is one coordinate).
    pub spacing: [f64; 2],
    /// The plate's joint lines (empty without joints).
    pub joints: Vec<JointLine>,
    /// The load's prints about its reference point, one footprint per heading searched.
    pub prints: Vec<Footprint>,
    /// Every position solved, in grid order (heading, then y, then x).
    pub positions: Vec<Position>,
    /// Index of the largest bottom tension among the converged positions.
    pub bottom: Option<usize>,
    /// Index of the largest top tension.
    pub top: Option<usize>,
    /// Index of the largest deflection.
    pub deflection: Option<usize>,
    /// Index of the largest joint shear per length (jointed plates with aggregate or tied
    /// joints).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub joint_shear: Option<usize>,
    /// Index of the largest dowel force (jointed plates with dowels).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dowel_force: Option<usize>,
    /// Seconds to assemble the shared operators.
    pub assemble_s: f64,
    /// Wall-clock seconds of the whole search.
    pub total_s: f64,
    /// The scene's unit system (None: a dimensionless scene). The values above are SI;
    /// [`Self::reported`] gives them in this system, as the files show them.
    pub units: Option<UnitSystem>,
}

impl Critical {
    /// The search as critical.csv and critical.json report it: every position, stress,
    /// deflection and force in the scene's unit system (an SI or dimensionless scene's
    /// unchanged).
    pub fn reported(&self) -> Critical {
        let sys = self.units;
        let (l, p, d) = (Measure::Length, Measure::Pressure, Measure::Deflection);
        let c = |m: Measure, v: f64| m.from_si(sys, v);
        let pair = |v: [f64; 2]| [c(l, v[0]), c(l, v[1])];
        Critical {
            plate: pair(self.plate),
            spacing: pair(self.spacing),
            joints: self
                .joints
                .iter()
                .map(|j| JointLine {
                    at: c(l, j.at),
                    ..j.clone()
                })
                .collect(),
            prints: self
                .prints
                .iter()
                .map(|f| Footprint {
                    heading: f.heading,
                    prints: f.prints.iter().map(|[x, y]| [pair(*x), pair(*y)]).collect(),
                })
                .collect(),
            positions: self
                .positions
                .iter()
                .map(|q| Position {
                    x: c(l, q.x),
                    y: c(l, q.y),
                    bottom: c(p, q.bottom),
                    bottom_at: pair(q.bottom_at),
                    top: c(p, q.top),
                    top_at: pair(q.top_at),
                    w_max: c(d, q.w_max),
                    joint_shear: q.joint_shear.map(|v| c(Measure::ForcePerLength, v)),
                    dowel_force: q.dowel_force.map(|v| c(Measure::Force, v)),
                    ..q.clone()
                })
                .collect(),
            ..self.clone()
        }
    }

    /// The tire prints of the load at position `i`, as [x0, x1] and [y0, y1] in m (empty for
    /// an index beyond the positions).
    pub fn prints_at(&self, i: usize) -> Vec<[[f64; 2]; 2]> {
        let Some(p) = self.positions.get(i) else {
            return Vec::new();
        };
        self.prints
            .iter()
            .find(|f| f.heading == p.heading)
            .map_or_else(Vec::new, |f| {
                f.prints
                    .iter()
                    .map(|[x, y]| [[p.x + x[0], p.x + x[1]], [p.y + y[0], p.y + y[1]]])
                    .collect()
            })
    }

    /// What was searched, for a table: `a uniform 11 × 9 grid`, `5 × 3 points per panel on
    /// 3 × 3 panels`, with ` along joint:T2` where lines were given.
    pub fn search(&self) -> String {
        let mut s = match (self.grid_per_panel, self.grid) {
            (Some([nx, ny]), _) => format!(
                "{nx} × {ny} points per panel on {} × {} panels",
                self.panels[0], self.panels[1]
            ),
            (None, Some([nx, ny])) => format!("a uniform {nx} × {ny} grid"),
            (None, None) => String::from("no grid"),
        };
        if !self.along.is_empty() {
            let lines: Vec<String> = self.along.iter().map(Along::to_string).collect();
            s = format!("{s}, along {}", lines.join(", "));
        }
        s
    }

    /// The index of the converged position with the largest `value`.
    fn argmax(positions: &[Position], value: impl Fn(&Position) -> f64) -> Option<usize> {
        (0..positions.len())
            .filter(|&i| positions[i].outcome == RunOutcome::CONVERGED)
            .max_by(|&a, &b| value(&positions[a]).total_cmp(&value(&positions[b])))
    }

    /// The index of the converged position with the largest `value`, among those that have
    /// one (None when none has).
    fn argmax_of(
        positions: &[Position],
        value: impl Fn(&Position) -> Option<f64>,
    ) -> Option<usize> {
        (0..positions.len())
            .filter(|&i| positions[i].outcome == RunOutcome::CONVERGED)
            .filter_map(|i| value(&positions[i]).map(|v| (i, v)))
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(i, _)| i)
    }
}

/// The runs of `picked` (grid indices) that are warm-started in turn: consecutive indices in
/// the same block of [`CriticalOptions::RUN`] of the grid, as ranges of `picked`.
fn runs(picked: &[usize]) -> Vec<std::ops::Range<usize>> {
    let mut out: Vec<std::ops::Range<usize>> = Vec::new();
    for (j, &i) in picked.iter().enumerate() {
        let continues = j > 0 && {
            let prev = picked[j - 1];
            i == prev + 1 && i / CriticalOptions::RUN == prev / CriticalOptions::RUN
        };
        match out.last_mut() {
            Some(r) if continues => r.end = j + 1,
            _ => out.push(j..j + 1),
        }
    }
    out
}

/// The largest of some optional values (None when none is present).
fn largest(values: impl Iterator<Item = Option<f64>>) -> Option<f64> {
    values.flatten().reduce(f64::max)
}

/// The reference points of a search and what its maps and table need of the plate.
struct Grid {
    /// (x, y, heading) in grid order: heading, then y, then x (along lines: line by line).
    points: Vec<[f64; 3]>,
    /// The plate's sides, m.
    plate: [f64; 2],
    /// The largest step between neighbouring coordinates of the first heading's points, m.
    spacing: [f64; 2],
    /// Panels along x and y.
    panels: [usize; 2],
    /// The joint lines, m.
    joints: Vec<JointLine>,
    /// The prints about the reference point, per heading.
    prints: Vec<Footprint>,
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
fn grid(model: &Model, k: usize, options: &CriticalOptions) -> Result<Grid> {
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

/// The model to move the load in: the problem's (or, with combinations, the one the load acts
/// in), the whole plate modelled (a moving load has no symmetry). Returns it with the load's
/// index among its vehicles and the combination's name.
fn chosen(problem: &Problem, options: &CriticalOptions) -> Result<(Model, usize, Option<String>)> {
    let name = options.load.as_str();
    let find = |m: &Model| {
        m.vehicles
            .iter()
            .position(|v| v.name.as_deref() == Some(name))
    };
    let models: Vec<&Model> = match problem.combinations.is_empty() {
        true => vec![&problem.model],
        false => problem.combinations.iter().map(|c| &c.model).collect(),
    };
    let Some(case) = models
        .iter()
        .find_map(|m| find(m).map(|i| m.vehicles[i].case.clone()))
    else {
        let mut names: Vec<&str> = Vec::new();
        for v in models.iter().flat_map(|m| &m.vehicles) {
            if let Some(n) = v.name.as_deref().filter(|n| !names.contains(n)) {
                names.push(n);
            }
        }
        return Err(Error::invalid(
            "load",
            format!(
                "no load named `{name}` among the scene's axles and gears (the critical position moves an axle or a gear); named axles and gears: {}",
                if names.is_empty() {
                    "none (give the axle or gear a `name`)".to_string()
                } else {
                    names.join(", ")
                }
            ),
        ));
    };
    let (mut model, combination) = if problem.combinations.is_empty() {
        if options.combination.is_some() {
            return Err(Error::invalid(
                "combination",
                "the scene has no [[combination]]",
            ));
        }
        (problem.model.clone(), None)
    } else {
        let acts =
            |c: &&crate::scene::Combination| c.factors.iter().any(|(k, f)| *k == case && *f != 0.0);
        let c = match &options.combination {
            Some(wanted) => problem
                .combinations
                .iter()
                .find(|c| &c.name == wanted)
                .ok_or_else(|| {
                    let names: Vec<&str> = problem
                        .combinations
                        .iter()
                        .map(|c| c.name.as_str())
                        .collect();
                    Error::invalid(
                        "combination",
                        format!(
                            "no combination named `{wanted}`; the scene's combinations are: {}",
                            names.join(", ")
                        ),
                    )
                })?,
            None => problem.combinations.iter().find(acts).ok_or_else(|| {
                Error::invalid(
                    "combination",
                    format!("no combination has the case `{case}` of load `{name}`"),
                )
            })?,
        };
        (c.model.clone(), Some(c.name.clone()))
    };
    let k = find(&model).ok_or_else(|| {
        Error::invalid(
            "combination",
            format!(
                "combination `{}` has no factor on the case `{case}` of load `{name}`",
                combination.as_deref().unwrap_or_default()
            ),
        )
    })?;
    model.symmetry = SymmetryMode::None;
    Ok((model, k, combination))
}

/// How many positions the search of `options` has (every heading's grid): what a caller that
/// spreads them over workers (`options.indices`) splits.
pub fn critical_positions(problem: &Problem, options: &CriticalOptions) -> Result<usize> {
    Ok(critical_points(problem, options)?.len())
}

/// The reference points (x, y, m; heading, degrees) of the search of `options`, in the order
/// it solves them (every heading's grid), without solving.
pub fn critical_points(problem: &Problem, options: &CriticalOptions) -> Result<Vec<[f64; 3]>> {
    options.validate()?;
    let (model, k, _) = chosen(problem, options)?;
    Ok(grid(&model, k, options)?.points)
}

/// Move the load over the grid and solve every position; see the module's description.
pub fn critical(
    problem: &Problem,
    options: &CriticalOptions,
    monitor: &Monitor<'_>,
) -> Result<Critical> {
    options.validate()?;
    let t0 = Instant::now();
    let (model, k, combination) = chosen(problem, options)?;
    let Grid {
        points,
        plate,
        spacing,
        panels,
        joints,
        prints,
    } = grid(&model, k, options)?;
    let picked: Vec<usize> = match &options.indices {
        Some(ix) => {
            if let Some(&bad) = ix.iter().find(|&&i| i >= points.len()) {
                return Err(Error::invalid(
                    "indices",
                    format!("{bad} is beyond the grid's {} positions", points.len()),
                ));
            }
            ix.clone()
        }
        None => (0..points.len()).collect(),
    };
    // The model with the load at each position: its prints moved, nothing validated again.
    let models: Vec<Model> = picked
        .iter()
        .map(|&i| {
            let mut m = model.clone();
            m.place(k, points[i])?;
            Ok(m)
        })
        .collect::<Result<_>>()?;
    let base = assemble_for(problem, &models, "positions")?;
    let assemble_s = t0.elapsed().as_secs_f64();
    // Runs of the grid order, [`CriticalOptions::RUN`] long whatever the cores: each position
    // starts from the answer of the one before it (a step of the grid away), the runs side by
    // side.
    let work: Vec<(usize, &Model)> = picked.iter().copied().zip(&models).collect();
    let runs = runs(&picked);
    let cases = Cases::new(monitor, models.len());
    let inner = cases.inner();
    let solved: Vec<Result<Vec<Position>>> = runs
        .par_iter()
        .map(|r| &work[r.clone()])
        .map(|run| {
            let mut out = Vec::with_capacity(run.len());
            let mut start: Option<Vec<f64>> = None;
            // A warm run also hands each solve's last factor to the next ([`Carry`]).
            let carry = Carry::new();
            for &(i, model) in run {
                let t = Instant::now();
                let [x, y, heading] = points[i];
                let ops = base.loaded(model);
                let (warm, carried) = if options.warm {
                    (start.as_deref(), Some(&carry))
                } else {
                    (None, None)
                };
                let result =
                    analysis::run_carried(model, &ops, &problem.method, 0.0, warm, carried, &inner);
                let position = match result {
                    Err(e @ Error::Cancelled(_)) => return Err(e),
                    Ok(r) => {
                        let s = &r.summary;
                        if s.converged {
                            start = Some(r.solution.sigma.clone());
                        }
                        Position {
                            x,
                            y,
                            heading,
                            outcome: RunOutcome::Solved(r.solution.status.kind()),
                            iterations: s.iterations,
                            bottom: s.stresses.bottom.value,
                            bottom_at: [s.stresses.bottom.x, s.stresses.bottom.y],
                            top: s.stresses.top.value,
                            top_at: [s.stresses.top.x, s.stresses.top.y],
                            w_max: s.w_max,
                            contact_fraction: s.contact_fraction,
                            joint_shear: largest(s.joints.iter().map(|j| j.max_shear_per_length)),
                            dowel_force: largest(s.joints.iter().map(|j| j.max_dowel_force)),
                            time_s: t.elapsed().as_secs_f64(),
                        }
                    }
                    Err(e) => Position {
                        x,
                        y,
                        heading,
                        outcome: RunOutcome::Failed(e.kind()),
                        iterations: 0,
                        bottom: f64::NAN,
                        bottom_at: [f64::NAN; 2],
                        top: f64::NAN,
                        top_at: [f64::NAN; 2],
                        w_max: f64::NAN,
                        contact_fraction: f64::NAN,
                        joint_shear: None,
                        dowel_force: None,
                        time_s: t.elapsed().as_secs_f64(),
                    },
                };
                cases.finish(&format!("({x:.2}, {y:.2}) m, {heading}°"))?;
                out.push(position);
            }
            Ok(out)
        })
        .collect();
    let mut positions = Vec::with_capacity(models.len());
    for part in solved {
        positions.extend(part?);
    }
    Ok(Critical {
        load: options.load.clone(),
        combination,
        plate,
        grid: options.grid_per_panel.is_none().then_some(options.grid),
        grid_per_panel: options.grid_per_panel,
        panels,
        along: options.along.clone(),
        spacing,
        joints,
        prints,
        bottom: Critical::argmax(&positions, |p| p.bottom),
        top: Critical::argmax(&positions, |p| p.top),
        deflection: Critical::argmax(&positions, |p| p.w_max),
        joint_shear: Critical::argmax_of(&positions, |p| p.joint_shear),
        dowel_force: Critical::argmax_of(&positions, |p| p.dowel_force),
        positions,
        assemble_s,
        total_s: t0.elapsed().as_secs_f64(),
        units: model.physical.map(|p| p.units),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Runs are blocks of `RUN` grid indices, cut where a share of the grid skips an index.
    #[test]
    fn runs_are_cut_from_the_grid_not_the_cores() {
        let r = CriticalOptions::RUN;
        let all: Vec<usize> = (0..2 * r + 3).collect();
        assert_eq!(runs(&all), vec![0..r, r..2 * r, 2 * r..2 * r + 3]);
        let share = [r - 2, r - 1, r, r + 1, r + 5];
        assert_eq!(runs(&share), vec![0..2, 2..4, 4..5]);
        assert!(runs(&[]).is_empty());
    }
}
