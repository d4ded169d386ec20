//! Fatigue damage over traffic and climate (`liftoff damage`): every case of the scene's
//! [`DamagePlan`] — an axle group or gear at a load level, at a lateral position, in a climate
//! bin — is a pass of the group along the lane over the slab, each of its positions an
//! unbonded contact solve of the whole jointed system (nothing is superposed across contact
//! sets: a foundation that cannot pull makes each its own problem), on operators assembled
//! once, the families (below) side by side.
//!
//! **Where each solve starts.** A family's levels are solved position by position. The lowest
//! level (and the highest, when the middle may be interpolated) starts from its own answers at
//! its last positions — extrapolated where that read the last position's contact set better
//! than the answer before it (the lifted region moves with the load), by the rule `critical`'s
//! runs follow ([`super::warm`]) — and from the factor its last solve ended with; every other
//! level starts from the level below it at the same position — its pressures and, on Winkler
//! soil with the penalty method, its factor ([`crate::solve::Carry`]), whose springs differ from
//! its own at few points, so its steps are low-rank updates rather than factorisations. The answers do not depend on the starts (each
//! problem has one solution, and every step solves its own system exactly); only the cost does.
//!
//! **A pass is one cycle.** Each element and face takes one load cycle per pass, at the largest
//! principal stress of that face over the pass's positions (tension positive; a face never in
//! tension takes no damage). A tandem or a tridem counts as one cycle per pass too: the stress
//! between its axles does not return to the unloaded state at the element the group governs,
//! and counting one cycle per axle would need the stress history between the positions, which
//! a pass of a few positions per slab does not resolve (the MEPDG counts axle groups as one
//! load, FAARFIELD counts wheels in tandem closer than 72 in as one coverage).
//!
//! **The stress that enters N** is the largest principal stress σ₁ at the face, under the
//! group, the scene's own loads (self-weight, built-in curl) and the bin's temperature
//! difference together: the damage map covers every element, where no one direction of travel
//! governs, and σ₁ is never below the stress along the travel direction that the MEPDG takes at
//! the mid-slab edge (where the two coincide). The relation's N is that of the scene's
//! `[damage] model` ([`crate::damage::relations`]); no factor for load transfer is applied, since
//! the joints are modelled. FAARFIELD's N counts coverages; with the wander modelled as lateral
//! positions, a pass at one position is one coverage of the elements it stresses, so its
//! pass-to-coverage ratio is not applied again.
//!
//! **Erosion** (`model = "pca"`): each pass also keeps the largest deflection it causes at every
//! panel corner, over the rest state of its climate bin, and EB109's erosion relation sums
//! them ([`super::erosion`]).
//!
//! **Load levels** keep the group's tire prints (the scene's size) and scale their pressure:
//! the load vector is linear in the level. **Exact interpolation between levels**: the levels
//! of one group at one lateral position in one climate bin form a family; its lowest and
//! highest level are solved, and at each position where their solutions have the same contact
//! set (and the same ε̄) every level between them is their linear interpolation, exactly — the
//! equations on that set are linear in the load, and the sign conditions (pressure ≥ 0 in
//! contact, < 0 penalised / zero lifted) are convex, so they hold between the ends, and the
//! problem has one solution. Where the sets differ, the position is solved. **Climate bins** add their temperature difference as
//! a linear temperature load to the scene's own loads. Other axles and gears of the scene do not
//! act in a group's passes.
//!
//! **A climate bin's own subgrade modulus** (a month's k on a Winkler soil) makes its passes
//! a problem of their own springs: the families of such bins are assembled apart, once per
//! modulus, and the erosion relation reads the bin's k.
//!
//! **A pass that is its own mirror image** — the lane's positions symmetric about a line the
//! plate's frame is symmetric about ([`super::mirror::pass_partners`]) — is solved on its first
//! half; each element's and corner's largest values are then taken with its mirror image's
//! ([`PassStress::mirror`]), which is what the other half gives (`[mesh] symmetry = "none"`
//! solves every position).
//!
//! **No silent partial sums**: a pass with a position that did not converge contributes
//! nothing, is named in [`Damage::missing`], and the totals say they are incomplete.

use std::time::Instant;

use rayon::prelude::*;

use super::RunOutcome;
use crate::analysis;
use crate::combination::{assemble_for, on_threads, side_by_side};
use crate::error::{Error, Result};
use crate::model::{Load, Model, SymmetryMode};
use crate::monitor::{Cases, Monitor};
use crate::operators::Operators;
use crate::scene::Problem;
use crate::solve::Carry;

use super::damage_part::{DamagePart, PassStress};
use super::damage_pass::{label, Setup};
pub use super::damage_result::{Cracking, Damage, Governing, Pass, PassErosion, Peak};
use super::damage_sum::sum;
use super::mirror;
use super::warm::Trail;

/// Run the scene's damage plan; see the module's description.
pub fn damage(problem: &Problem, monitor: &Monitor<'_>) -> Result<Damage> {
    let t0 = Instant::now();
    let setup = Setup::of(problem)?;
    let all: Vec<usize> = (0..setup.families.len()).collect();
    let part = solve_part(problem, &setup, &all, monitor)?;
    let mut d = sum(problem, &setup, vec![part])?;
    d.total_s = t0.elapsed().as_secs_f64();
    Ok(d)
}

/// How many families a damage run has: the units [`damage_part`] takes (the levels of one
/// group at one lateral position in one climate bin, solved together for the exact
/// interpolation between levels and the warm starts).
pub fn damage_families(problem: &Problem) -> Result<usize> {
    Ok(Setup::of(problem)?.families.len())
}

/// The passes of `families` (indices below [`damage_families`]) of the scene's damage run, for
/// one worker of a cluster: [`damage_merge`] sums the parts of all families into the run's
/// [`Damage`], the same as [`damage`]'s (each family is solved the same way wherever it runs).
pub fn damage_part(
    problem: &Problem,
    families: &[usize],
    monitor: &Monitor<'_>,
) -> Result<DamagePart> {
    let setup = Setup::of(problem)?;
    if let Some(&bad) = families.iter().find(|&&f| f >= setup.families.len()) {
        return Err(Error::invalid(
            "families",
            format!(
                "{bad} is beyond the run's {} families",
                setup.families.len()
            ),
        ));
    }
    solve_part(problem, &setup, families, monitor)
}

/// The run's [`Damage`] from parts that together hold every family once ([`damage_part`]);
/// its `total_s` is the parts' seconds added (the workers' time), `assemble_s` theirs too.
pub fn damage_merge(problem: &Problem, parts: Vec<DamagePart>) -> Result<Damage> {
    let setup = Setup::of(problem)?;
    sum(problem, &setup, parts)
}

/// Solve the passes of `which` families on operators assembled once for them (once per soil
/// where climate bins have a subgrade modulus of their own).
fn solve_part(
    problem: &Problem,
    setup: &Setup<'_>,
    which: &[usize],
    monitor: &Monitor<'_>,
) -> Result<DamagePart> {
    let t0 = Instant::now();
    let Setup {
        plan,
        bins,
        passes,
        families,
        erosion,
    } = setup;
    let corners = erosion.as_ref().and_then(|e| e.as_ref().ok());
    let families: Vec<&Vec<usize>> = which.iter().map(|&f| &families[f]).collect();
    // The lines the plate is symmetric about, for passes that are their own mirror images (a
    // scene that asks for no symmetry: none).
    let frame = passes
        .first()
        .and_then(|p| p.first())
        .map_or([false; 2], |m| {
            mirror::frame(m, problem.model.symmetry != SymmetryMode::None)
        });
    // One assembly per soil: the families of a climate bin with a subgrade modulus of its own
    // have their own springs; all the others share the scene's.
    let soil_of = |climate: usize| plan.climate[climate].subgrade_modulus.map(f64::to_bits);
    let mut soils: Vec<Option<u64>> = families
        .iter()
        .map(|f| soil_of(bins[f[0]].climate))
        .collect();
    soils.sort_unstable();
    soils.dedup();
    let bases: Vec<Operators> = soils
        .iter()
        .map(|soil| {
            let models: Vec<Model> = families
                .iter()
                .filter(|f| soil_of(bins[f[0]].climate) == *soil)
                .flat_map(|f| f.iter().flat_map(|&i| passes[i].iter().cloned()))
                .collect();
            assemble_for(problem, &models, "positions")
        })
        .collect::<Result<_>>()?;
    let base_of = |climate: usize| -> &Operators {
        let k = soils.iter().position(|s| *s == soil_of(climate));
        &bases[k.unwrap_or(0)]
    };
    let assemble_s = t0.elapsed().as_secs_f64();
    let cases = Cases::new(monitor, families.iter().map(|f| f.len()).sum());
    let inner = cases.inner();
    let level = |i: usize| plan.groups[bins[i].group].levels[bins[i].level].load;
    let solve = |model: &Model,
                 base: &Operators,
                 start: Option<&[f64]>,
                 carry: &Carry|
     -> Result<Position> {
        let ops = base.loaded(model);
        match analysis::run_carried(
            model,
            &ops,
            &problem.method,
            0.0,
            start,
            Some(carry),
            &inner,
        ) {
            Err(e @ Error::Cancelled(_)) => Err(e),
            Err(e) => Ok(Position::Failed(RunOutcome::Failed(e.kind()))),
            Ok(r) if !r.summary.converged => Ok(Position::Failed(RunOutcome::Solved(
                r.solution.status.kind(),
            ))),
            Ok(r) => Ok(Position::Solved(Box::new(r))),
        }
    };
    // The erosion counts the deflection the group adds at each corner: the corners'
    // deflections without it, in each climate bin of these families.
    let rest: Vec<Option<Vec<f64>>> = match corners {
        None => Vec::new(),
        Some(c) => {
            let mut wanted: Vec<Option<usize>> = vec![None; plan.climate.len()];
            for f in &families {
                wanted[bins[f[0]].climate] = Some(f[0]);
            }
            wanted
                .par_iter()
                .enumerate()
                .map(|(climate, w)| -> Result<Option<Vec<f64>>> {
                    let Some(i) = *w else { return Ok(None) };
                    let mut m = passes[i][0].clone();
                    let k = plan.groups[bins[i].group].vehicle;
                    m.vehicles[k].factor = 0.0;
                    let at = m.vehicles[k].at;
                    m.place(k, at)?;
                    match solve(&m, base_of(climate), None, &Carry::new())? {
                        Position::Solved(r) => Ok(Some(c.read(&r.report.field))),
                        Position::Failed(outcome) => Err(Error::numerical(
                            "damage",
                            format!(
                                "the slab without traffic in climate bin {} did not converge ({outcome}): the PCA's erosion needs the corners' deflections at rest",
                                climate + 1
                            ),
                        )),
                    }
                })
                .collect::<Result<_>>()?
        }
    };
    // Each pass: the largest σ₁ of each face over its positions, per element; the middle
    // levels of a family from its ends where their contact sets agree.
    // On the iterative route more families than cores, which share the plate's solves.
    let threads = bases
        .first()
        .map_or(1, |b| side_by_side(problem, b, families.len()));
    let solved: Vec<Result<Vec<(usize, PassStress)>>> = on_threads(threads, || {
        families
            .par_iter()
            .map(|family| {
                // The family's levels are solved position by position: at each position the
                // lowest level (and with the interpolation the highest) starts from its own last
                // positions (`Trail`), and the factor its last solve ended with (`Carry`);
                // every other level starts from the level below it at the same position — its
                // pressures and its factor, which differ from its own at few points, so its steps
                // are low-rank updates rather than factorisations.
                let ends = plan.interpolate && family.len() >= 3;
                let n = family.len();
                // Solve order: the ends first when the middle may be interpolated from them.
                let order: Vec<usize> = if ends {
                    let mut o = vec![0, n - 1];
                    o.extend(1..n - 1);
                    o
                } else {
                    (0..n).collect()
                };
                let anchor = |j: usize| j == 0 || (ends && j == n - 1);
                let base = base_of(bins[family[0]].climate);
                // The corners' deflections at rest in this family's climate bin (empty: no
                // erosion), and what a position's deflections there add to them.
                let at_rest: &[f64] = rest
                    .get(bins[family[0]].climate)
                    .and_then(|r| r.as_deref())
                    .unwrap_or(&[]);
                let caused =
                    |w: &[f64]| -> Vec<f64> { w.iter().zip(at_rest).map(|(a, b)| a - b).collect() };
                // A pass symmetric about a line of a symmetric plate: its first half solved, the
                // rest read off it element by element after the loop (`mirror`).
                let levels: Vec<Vec<&[Load]>> = (family.iter())
                    .map(|&i| passes[i].iter().map(|m| m.loads.as_slice()).collect())
                    .collect();
                let mirrored = mirror::pass_partners(&levels, frame).and_then(|(flip, partner)| {
                    let corners = match corners {
                        Some(c) => {
                            let points: Vec<([f64; 2], [f64; 2])> =
                                c.points.iter().map(|p| ([p.x, p.y], p.towards)).collect();
                            mirror::point_map(&points, flip)?
                        }
                        None => Vec::new(),
                    };
                    Some((flip, partner, corners))
                });
                let read_off = |p: usize| mirrored.as_ref().is_some_and(|(_, q, _)| q[p] < p);
                let mut stress: Vec<PassStress> = vec![PassStress::default(); n];
                let carries: Vec<Carry> = (0..n).map(|_| Carry::new()).collect();
                // Each level's answers at its last solved positions, where its next starts
                // ([`Trail`]: the rule `critical`'s runs follow).
                let mut last: Vec<Trail> = vec![Trail::new(); n];
                let vehicle = plan.groups[bins[family[0]].group].vehicle;
                let at = |i: usize, p: usize| passes[i][p].vehicles[vehicle].at;
                let positions = passes[family[0]].len();
                for p in (0..positions).filter(|&p| !read_off(p)) {
                    let mut kept: [Option<Kept>; 2] = [None, None];
                    // The answer at this position of the level solved just below, with its carry.
                    let mut below: Option<(usize, Vec<f64>)> = None;
                    for &j in &order {
                        let i = family[j];
                        if stress[j].outcome != RunOutcome::CONVERGED {
                            continue;
                        }
                        if ends && !anchor(j) {
                            if let [Some(lo), Some(hi)] = &kept {
                                if lo.signature == hi.signature && lo.penalty == hi.penalty {
                                    let (a, b) = (level(family[0]), level(family[n - 1]));
                                    // Equal ends: every level between is the same load.
                                    let t = if b > a { (level(i) - a) / (b - a) } else { 0.0 };
                                    // The stress components are linear in the load; σ₁ is not: it
                                    // is taken from the interpolated components.
                                    let (bottom, top) =
                                        (lo.bottom.mix(&hi.bottom, t), lo.top.mix(&hi.top, t));
                                    // The deflections are linear in the load on one contact set.
                                    let w: Vec<f64> = (lo.corners.iter().zip(&hi.corners))
                                        .map(|(a, b)| (1.0 - t) * a + t * b)
                                        .collect();
                                    stress[j].take(&bottom, &top, &lo.x, &lo.y, &caused(&w));
                                    stress[j].interpolated += 1;
                                    last[j].clear();
                                    continue;
                                }
                            }
                        }
                        let own = last[j].start(at(i, p));
                        // A middle level: from the level below at this position when it was solved
                        // here (its factor handed over), else from its own last positions.
                        // (Starting a middle level from the ends' interpolation instead was tried: its
                        // set is further from the factor handed over, and the run took 40 % longer.)
                        // An anchor keeps its own carry for its next position; a middle level's is
                        // wanted only by the level above it here, which takes it (memory: two
                        // factors a family, not one a level).
                        let (start, carry) = match &below {
                            Some((k, sigma)) if !anchor(j) => (
                                Some(sigma.clone()),
                                if anchor(*k) {
                                    carries[*k].share()
                                } else {
                                    carries[*k].take()
                                },
                            ),
                            _ => (own, carries[j].share()),
                        };
                        let position = solve(&passes[i][p], base, start.as_deref(), &carry)?;
                        stress[j].solves += 1;
                        match position {
                            Position::Failed(outcome) => {
                                stress[j].outcome = outcome;
                            }
                            Position::Solved(r) => {
                                carries[j].put_from(carry);
                                let e = &r.report.elements;
                                // One solved field a family, for the maps' grid (a field a level
                                // was 0.9 GB on the 18 000-case run).
                                if stress.iter().all(|s| s.field.is_none()) {
                                    stress[j].field = Some(r.report.field.clone());
                                }
                                let w = corners.map_or(Vec::new(), |c| c.read(&r.report.field));
                                stress[j].take(&e.bottom.s1, &e.top.s1, &e.x, &e.y, &caused(&w));
                                if ends && anchor(j) {
                                    kept[usize::from(j != 0)] = Some(Kept::of(&r, w));
                                }
                                let now = r.solution.sigma.clone();
                                last[j].push(at(i, p), now.clone());
                                // The highest level, solved before the middle when they may be
                                // interpolated, is not the one below them.
                                if !(ends && j == n - 1) {
                                    below = Some((j, now));
                                }
                            }
                        }
                    }
                }
                if let Some((flip, _, corners)) = &mirrored {
                    let skipped = (0..positions).filter(|&p| read_off(p)).count();
                    // The elements' mirror images, from the centres of the first converged level
                    // (every level's are the plate's same grid).
                    let mut elements: Option<Vec<usize>> = None;
                    for s in stress.iter_mut() {
                        if s.outcome != RunOutcome::CONVERGED {
                            continue;
                        }
                        if elements.is_none() {
                            let centres: Vec<([f64; 2], [f64; 2])> =
                                (s.x.iter().zip(&s.y)).map(|(&x, &y)| ([x, y], [0.0; 2])).collect();
                            elements = Some(mirror::point_map(&centres, *flip).ok_or_else(|| {
                                Error::numerical(
                                    "damage",
                                    "the element grid of a symmetric plate is not its own mirror image",
                                )
                            })?);
                        }
                        if let Some(e) = &elements {
                            s.mirror(e, corners, skipped);
                        }
                    }
                }
                let mut out = Vec::with_capacity(n);
                for (j, s) in stress.into_iter().enumerate() {
                    cases.finish(&label(plan, &bins[family[j]]))?;
                    out.push((family[j], s));
                }
                Ok(out)
            })
            .collect()
    })?;
    let mut part = DamagePart {
        bins: Vec::new(),
        stresses: Vec::new(),
        assemble_s,
        seconds: 0.0,
    };
    for family in solved {
        for (i, stress) in family? {
            part.bins.push(i);
            part.stresses.push(stress);
        }
    }
    part.seconds = t0.elapsed().as_secs_f64();
    Ok(part)
}

/// A face's stress components (σx, σy, τxy) per element, which are linear in the load.
#[derive(Debug, Clone)]
struct Components {
    sx: Vec<f64>,
    sy: Vec<f64>,
    sxy: Vec<f64>,
}

impl Components {
    fn of(f: &crate::post::stress::FaceStress) -> Self {
        Self {
            sx: f.sx.clone(),
            sy: f.sy.clone(),
            sxy: f.sxy.clone(),
        }
    }

    /// σ₁ of (1 − t) self + t other, element by element.
    fn mix(&self, other: &Components, t: f64) -> Vec<f64> {
        let m = |a: f64, b: f64| (1.0 - t) * a + t * b;
        let mut face = crate::post::stress::FaceStress::default();
        for i in 0..self.sx.len() {
            face.push(
                m(self.sx[i], other.sx[i]),
                m(self.sy[i], other.sy[i]),
                m(self.sxy[i], other.sxy[i]),
            );
        }
        face.s1
    }
}

/// One position's solve: its answer, or how it ended without one.
enum Position {
    Solved(Box<analysis::MethodRun>),
    Failed(RunOutcome),
}

/// What a family's end keeps of one position for its middle levels: the element stresses and
/// the contact set (the sign of each constraint point's pressure) with the penalty's ε̄.
#[derive(Debug, Clone)]
struct Kept {
    bottom: Components,
    top: Components,
    x: Vec<f64>,
    y: Vec<f64>,
    signature: Vec<bool>,
    penalty: Option<u64>,
    /// The deflections at the erosion's corners, m (empty: no erosion).
    corners: Vec<f64>,
}

impl Kept {
    fn of(r: &analysis::MethodRun, corners: Vec<f64>) -> Self {
        let e = &r.report.elements;
        // In contact: a pressure above round-off of the largest (the QP's lifted points hold
        // zero up to its tolerance, the penalty's a small tension).
        let peak = r.solution.sigma.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        Self {
            bottom: Components::of(&e.bottom),
            top: Components::of(&e.top),
            x: e.x.clone(),
            y: e.y.clone(),
            signature: r.solution.sigma.iter().map(|&v| v > 1e-9 * peak).collect(),
            penalty: r.solution.method.penalty_epsilon().map(f64::to_bits),
            corners,
        }
    }
}
