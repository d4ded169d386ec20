//! The critical position of a vehicle load (`liftoff critical`): the named `axle` or `gear`
//! load moved over a grid of reference points inside the plate (and over headings where asked),
//! the rest of its combination present, each position its own contact problem on operators
//! assembled once (K, B, T shared; only the load vector changes), in runs of
//! [`CriticalOptions::RUN`] positions side by side, each warm-started from the positions before
//! it (their answers extrapolated where it continues their line and that paid at the last
//! position); the positions that give the largest
//! tension at the bottom and at the top face and the largest deflection — and on a jointed
//! plate the largest joint shear per length and the largest dowel force. On a lane the model
//! cuts at its ends (two or more transverse joints, [`CriticalOptions::ends`]) every position
//! is read between the first and the last of them ([`super::ends`]), the end panels' largest
//! tensions kept beside.
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

use std::collections::HashMap;
use std::time::Instant;

use rayon::prelude::*;

use super::critical_grid::{grid, Grid};
pub use super::critical_grid::{Along, CriticalOptions, Edge, Footprint, JointLine};
pub use super::critical_result::{Critical, Position};
use super::ends;
use super::mirror;
use super::warm::Trail;
use super::RunOutcome;
use crate::analysis;
use crate::combination::{assemble_for, on_threads, side_by_side};
use crate::error::{Error, Result};
use crate::layout::Ends;
use crate::model::{Model, SymmetryMode};
use crate::monitor::{Cases, Monitor};
use crate::scene::Problem;
use crate::solve::Carry;

impl CriticalOptions {
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

/// The runs of `solved` (grid indices, ascending) that are warm-started in turn: indices in the
/// same block of [`CriticalOptions::RUN`] of the grid with none between them skipped but those
/// read off a mirror image (`mirrored[j]`), as ranges of `solved`.
fn runs(solved: &[usize], mirrored: impl Fn(usize) -> bool) -> Vec<std::ops::Range<usize>> {
    let mut out: Vec<std::ops::Range<usize>> = Vec::new();
    for (j, &i) in solved.iter().enumerate() {
        let continues = j > 0 && {
            let prev = solved[j - 1];
            i / CriticalOptions::RUN == prev / CriticalOptions::RUN && (prev + 1..i).all(&mirrored)
        };
        match out.last_mut() {
            Some(r) if continues => r.end = j + 1,
            _ => out.push(j..j + 1),
        }
    }
    out
}

/// What a position's solve shows where the search reads it ([`super::ends`]): over the whole
/// plate, the summary's own values; on a cut lane's `span` of x, the largest σ₁ of each face
/// over the elements centred inside it and where, the largest deflection over its nodes, the
/// largest joint shear per length and dowel force over the joints' node pairs and bars in it
/// (its first and last joint included), and the largest σ₁ of each face in the end panels.
struct Read {
    bottom: (f64, [f64; 2]),
    top: (f64, [f64; 2]),
    w_max: f64,
    joint_shear: Option<f64>,
    dowel_force: Option<f64>,
    end_bottom: Option<f64>,
    end_top: Option<f64>,
}

impl Read {
    fn of(r: &analysis::MethodRun, span: Option<[f64; 2]>) -> Read {
        let s = &r.summary;
        let Some(span) = span else {
            return Read {
                bottom: (
                    s.stresses.bottom.value,
                    [s.stresses.bottom.x, s.stresses.bottom.y],
                ),
                top: (s.stresses.top.value, [s.stresses.top.x, s.stresses.top.y]),
                w_max: s.w_max,
                joint_shear: largest(s.joints.iter().map(|j| j.max_shear_per_length)),
                dowel_force: largest(s.joints.iter().map(|j| j.max_dowel_force)),
                end_bottom: None,
                end_top: None,
            };
        };
        let e = &r.report.elements;
        let read = |k: usize| ends::inside(Some(span), e.x[k]);
        // The largest σ₁ of a face over the elements read (`inner`) or not, and where.
        let peak = |s1: &[f64], inner: bool| {
            (0..s1.len())
                .filter(|&k| read(k) == inner)
                .max_by(|&a, &b| s1[a].total_cmp(&s1[b]))
                .map(|k| (s1[k], [e.x[k], e.y[k]]))
        };
        let none = (f64::NAN, [f64::NAN; 2]);
        let f = &r.report.field;
        let within = |x: f64| ends::within(Some(span), x);
        // The largest magnitude of the values (at x, value) inside the span.
        let largest_within = |values: &mut dyn Iterator<Item = (f64, f64)>| {
            values
                .filter(|&(x, _)| within(x))
                .map(|(_, v)| v.abs())
                .reduce(f64::max)
        };
        let joints = &r.report.joints;
        Read {
            bottom: peak(&e.bottom.s1, true).unwrap_or(none),
            top: peak(&e.top.s1, true).unwrap_or(none),
            w_max: (0..f.w.len())
                .filter(|&n| within(f.x[n]))
                .map(|n| f.w[n])
                .fold(f64::NEG_INFINITY, f64::max),
            joint_shear: largest(joints.iter().map(|j| {
                let mut pairs = j.nodes.iter().map(|n| (n.x, n.shear_per_length));
                j.max_shear_per_length.and(largest_within(&mut pairs))
            })),
            dowel_force: largest(joints.iter().map(|j| {
                let mut bars = j.dowels.iter().map(|d| (d.x, d.force));
                j.max_dowel_force.and(largest_within(&mut bars))
            })),
            end_bottom: peak(&e.bottom.s1, false).map(|p| p.0),
            end_top: peak(&e.top.s1, false).map(|p| p.0),
        }
    }
}

/// The largest of some optional values (None when none is present).
fn largest(values: impl Iterator<Item = Option<f64>>) -> Option<f64> {
    values.flatten().reduce(f64::max)
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
    // The whole plate: a moved load has no symmetry (its positions may be each other's mirror
    // images: `mirror`).
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
    // Where every position is read: between a cut lane's first and last transverse joint.
    let read_as = ends::of(problem, options.ends);
    let span = ends::counted_span(&model, read_as == Ends::Cut);
    // A scene that asks for no symmetry gets no mirror images either.
    let mirrors = problem.model.symmetry != SymmetryMode::None;
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
    // The model with the load at `at`: its prints moved, nothing validated again.
    let placed = |at: [f64; 3]| -> Result<Model> {
        let mut m = model.clone();
        m.place(k, at)?;
        Ok(m)
    };
    // The positions read off their mirror images, and those solved.
    let frame = mirror::frame(&model, options.mirror && mirrors);
    let partner = match frame {
        [false, false] => vec![None; points.len()],
        _ => {
            let loads = (points.iter())
                .map(|&at| Ok(placed(at)?.loads))
                .collect::<Result<Vec<_>>>()?;
            mirror::partners(&loads, &points, frame)
        }
    };
    let solved_at = mirror::to_solve(&picked, &partner);
    let models: Vec<Model> = solved_at
        .iter()
        .map(|&i| placed(points[i]))
        .collect::<Result<_>>()?;
    let base = assemble_for(problem, &models, "positions")?;
    let assemble_s = t0.elapsed().as_secs_f64();
    // Runs of the grid order, [`CriticalOptions::RUN`] long whatever the cores: each position
    // starts from the answer of the one before it (a step of the grid away, or two across a
    // mirrored one), the runs side by side.
    let work: Vec<(usize, &Model)> = solved_at.iter().copied().zip(&models).collect();
    let runs = runs(&solved_at, |j| partner[j].is_some());
    let cases = Cases::new(monitor, models.len());
    let inner = cases.inner();
    // On the iterative route more runs than cores, which share the plate's solves.
    let threads = side_by_side(problem, &base, runs.len());
    let solved: Vec<Result<Vec<(usize, Position)>>> = on_threads(threads, || {
        runs.par_iter()
            .map(|r| &work[r.clone()])
            .map(|run| {
                let mut out = Vec::with_capacity(run.len());
                // The last three converged answers of the run and their points: a position in
                // line with them, a step on, starts from the last two's extrapolation where it
                // read the last set better (the lifted region moves with the load), any other
                // from the last answer ([`Trail`]).
                let mut last = Trail::new();
                // A warm run also hands each solve's last factor to the next ([`Carry`]).
                let carry = Carry::new();
                for &(i, model) in run {
                    let t = Instant::now();
                    let [x, y, heading] = points[i];
                    let ops = base.loaded(model);
                    let start = last.start(points[i]);
                    let (warm, carried) = if options.warm {
                        (start.as_deref(), Some(&carry))
                    } else {
                        (None, None)
                    };
                    let result = analysis::run_carried(
                        model,
                        &ops,
                        &problem.method,
                        0.0,
                        warm,
                        carried,
                        &inner,
                    );
                    let position = match result {
                        Err(e @ Error::Cancelled(_)) => return Err(e),
                        Ok(r) => {
                            let s = &r.summary;
                            if s.converged {
                                last.push(points[i], r.solution.sigma.clone());
                            }
                            let read = Read::of(&r, span);
                            Position {
                                x,
                                y,
                                heading,
                                outcome: RunOutcome::Solved(r.solution.status.kind()),
                                iterations: s.iterations,
                                bottom: read.bottom.0,
                                bottom_at: read.bottom.1,
                                top: read.top.0,
                                top_at: read.top.1,
                                w_max: read.w_max,
                                contact_fraction: s.contact_fraction,
                                joint_shear: read.joint_shear,
                                dowel_force: read.dowel_force,
                                end_bottom: read.end_bottom,
                                end_top: read.end_top,
                                time_s: t.elapsed().as_secs_f64(),
                                mirror_of: None,
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
                            end_bottom: None,
                            end_top: None,
                            time_s: t.elapsed().as_secs_f64(),
                            mirror_of: None,
                        },
                    };
                    cases.finish(&format!("({x:.2}, {y:.2}) m, {heading}°"))?;
                    out.push((i, position));
                }
                Ok(out)
            })
            .collect()
    })?;
    let mut by_index: HashMap<usize, Position> = HashMap::with_capacity(models.len());
    for part in solved {
        by_index.extend(part?);
    }
    // The picked positions in their order, each solved or read off its mirror image.
    let positions = picked
        .iter()
        .map(|&i| match partner[i] {
            None => by_index.get(&i).cloned(),
            Some((from, flip)) => by_index
                .get(&from)
                .map(|p| p.mirrored(points[i], from, flip)),
        })
        .collect::<Option<Vec<Position>>>()
        .ok_or_else(|| {
            Error::numerical("critical", "a position was neither solved nor mirrored")
        })?;
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
        ends: read_as,
        read_x: span,
        end_bottom: Critical::argmax_of(&positions, |p| p.end_bottom),
        end_top: Critical::argmax_of(&positions, |p| p.end_top),
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
        let none = |_| false;
        assert_eq!(runs(&all, none), vec![0..r, r..2 * r, 2 * r..2 * r + 3]);
        let share = [r - 2, r - 1, r, r + 1, r + 5];
        assert_eq!(runs(&share, none), vec![0..2, 2..4, 4..5]);
        assert!(runs(&[], none).is_empty());
        // A run goes on across positions read off their mirror images, not across a block's
        // end or a position left out.
        let mirrored = |j: usize| j % 2 == 1;
        assert_eq!(runs(&[0, 2, 4, 7], mirrored), vec![0..3, 3..4]);
        assert_eq!(runs(&[r - 2, r], mirrored), vec![0..1, 1..2]);
    }
}
