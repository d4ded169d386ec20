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
//! (the outer tire on the free edge) are on it.
//!
//! The scene is validated once ([`crate::load`]); the load is the model's [`Vehicle`], moved to
//! each position by [`Model::place`].

use std::time::Instant;

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::RunOutcome;
use crate::analysis;
use crate::combination::assemble_for;
use crate::error::{Error, Result};
use crate::model::{Model, SymmetryMode};
use crate::monitor::{Cases, Monitor};
use crate::scene::Problem;
use crate::vehicle::Vehicle;

/// What to move and over what.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct CriticalOptions {
    /// The `name` of the `axle` or `gear` load to move.
    pub load: String,
    /// Reference points along x and y (≥ 1 each; 1 keeps the load's own coordinate).
    pub grid: [usize; 2],
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
    /// Grid spacing of the reference points (x, y), m (0 where the grid has one point).
    pub spacing: [f64; 2],
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
}

impl Critical {
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

/// The reference points (x, y, heading) in grid order, the plate's sides and the spacing of the
/// first heading's grid.
type Grid = (Vec<[f64; 3]>, [f64; 2], [f64; 2]);

/// The grid of reference points of vehicle `v` for each heading: (x, y, heading) in grid
/// order, and the spacing of the first heading's grid.
fn grid(v: &Vehicle, options: &CriticalOptions) -> Result<Grid> {
    let [a, b] = v.frame.plate;
    let [own_x, own_y, own] = v.at;
    let headings = if options.headings.is_empty() {
        vec![own]
    } else {
        options.headings.clone()
    };
    let mut points = Vec::new();
    let mut spacing = [0.0; 2];
    for (h, &heading) in headings.iter().enumerate() {
        let prints = v.tires([0.0, 0.0, heading])?;
        let lo = |axis: usize| {
            prints
                .iter()
                .map(|t| t.centre[axis] - t.size[axis] / 2.0)
                .fold(f64::INFINITY, f64::min)
        };
        let hi = |axis: usize| {
            prints
                .iter()
                .map(|t| t.centre[axis] + t.size[axis] / 2.0)
                .fold(f64::NEG_INFINITY, f64::max)
        };
        // The reference points that keep every print on the plate, a hair inside.
        let inset = 1e-9 * a.max(b);
        let range = |axis: usize, half: f64| -> Result<[f64; 2]> {
            let r = [-half - lo(axis) + inset, half - hi(axis) - inset];
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
        let (rx, ry) = (range(0, a / 2.0)?, range(1, b / 2.0)?);
        let along = |r: [f64; 2], n: usize, own: f64| -> Vec<f64> {
            if n == 1 {
                vec![own.clamp(r[0], r[1])]
            } else {
                (0..n)
                    .map(|i| r[0] + (r[1] - r[0]) * i as f64 / (n - 1) as f64)
                    .collect()
            }
        };
        let xs = along(rx, options.grid[0], own_x);
        let ys = along(ry, options.grid[1], own_y);
        if h == 0 {
            spacing = [
                xs.get(1).map_or(0.0, |x1| x1 - xs[0]),
                ys.get(1).map_or(0.0, |y1| y1 - ys[0]),
            ];
        }
        for &y in &ys {
            for &x in &xs {
                points.push([x, y, heading]);
            }
        }
    }
    Ok((points, [a, b], spacing))
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
    options.validate()?;
    let (model, k, _) = chosen(problem, options)?;
    Ok(grid(&model.vehicles[k], options)?.0.len())
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
    let (points, plate, spacing) = grid(&model.vehicles[k], options)?;
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
            for &(i, model) in run {
                let t = Instant::now();
                let [x, y, heading] = points[i];
                let ops = base.loaded(model);
                let warm = if options.warm { start.as_deref() } else { None };
                let result = analysis::run_from(model, &ops, &problem.method, 0.0, warm, &inner);
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
        spacing,
        bottom: Critical::argmax(&positions, |p| p.bottom),
        top: Critical::argmax(&positions, |p| p.top),
        deflection: Critical::argmax(&positions, |p| p.w_max),
        joint_shear: Critical::argmax_of(&positions, |p| p.joint_shear),
        dowel_force: Critical::argmax_of(&positions, |p| p.dowel_force),
        positions,
        assemble_s,
        total_s: t0.elapsed().as_secs_f64(),
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
