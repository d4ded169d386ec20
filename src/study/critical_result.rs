//! What `liftoff critical` reports ([`super::critical`]): each position's outcome
//! ([`Position`]) and the search's result ([`Critical`]) with its critical positions, in SI or,
//! through [`Critical::reported`], in the scene's units.

use serde::Serialize;

use super::critical_grid::{Along, Footprint, JointLine};
use super::mirror::{flipped, Flip};
use super::RunOutcome;
use crate::layout::Ends;
use crate::units::{Measure, UnitSystem};

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
    /// On a lane cut at its ends ([`CriticalOptions::ends`]): the largest principal stress at
    /// the bottom face in the end panels, which the values above do not read, Pa (absent: the
    /// whole plate is read).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub end_bottom: Option<f64>,
    /// The same at the top face, Pa.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub end_top: Option<f64>,
    /// Seconds for this position (0 for one read off its mirror image).
    pub time_s: f64,
    /// Where the position is the mirror image of another (the scene's frame symmetric, its load
    /// that one's mirrored): that one's grid index; its answers are that one's mirrored, not
    /// solved again (absent: solved).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mirror_of: Option<usize>,
}

impl Position {
    /// This position's answers read off `self`, solved at grid index `from`, as its mirror
    /// image by `flip`: the load at `at`, the places of the extremes mirrored, the values and
    /// the outcome the same; no steps, no time.
    pub(super) fn mirrored(&self, at: [f64; 3], from: usize, flip: Flip) -> Position {
        Position {
            x: at[0],
            y: at[1],
            heading: at[2],
            bottom_at: flipped(flip, self.bottom_at),
            top_at: flipped(flip, self.top_at),
            iterations: 0,
            time_s: 0.0,
            mirror_of: Some(from),
            ..self.clone()
        }
    }
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
    /// What the plate's ends across the lane were taken to be.
    pub ends: Ends,
    /// The span of x the positions' values read, m: between the first and the last transverse
    /// joint of a lane cut at its ends (absent: the whole plate).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub read_x: Option<[f64; 2]>,
    /// Index of the largest bottom tension in the end panels, not read (a cut lane's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub end_bottom: Option<usize>,
    /// Index of the largest top tension in the end panels, not read.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub end_top: Option<usize>,
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
            read_x: self.read_x.map(pair),
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
                    end_bottom: q.end_bottom.map(|v| c(p, v)),
                    end_top: q.end_top.map(|v| c(p, v)),
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

    /// The index of the converged position with the largest `value`, the first of equal ones
    /// (a position solved before its mirror images; Python's `max` takes the first too).
    pub(super) fn argmax(
        positions: &[Position],
        value: impl Fn(&Position) -> f64,
    ) -> Option<usize> {
        (0..positions.len())
            .rev()
            .filter(|&i| positions[i].outcome == RunOutcome::CONVERGED)
            .max_by(|&a, &b| value(&positions[a]).total_cmp(&value(&positions[b])))
    }

    /// The index of the converged position with the largest `value`, among those that have
    /// one (None when none has), the first of equal ones.
    pub(super) fn argmax_of(
        positions: &[Position],
        value: impl Fn(&Position) -> Option<f64>,
    ) -> Option<usize> {
        (0..positions.len())
            .rev()
            .filter(|&i| positions[i].outcome == RunOutcome::CONVERGED)
            .filter_map(|i| value(&positions[i]).map(|v| (i, v)))
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(i, _)| i)
    }
}
