//! The Miner sums of a damage run ([`super::damage`]): the passes' largest stresses of every
//! part gathered by case, summed element by element into the damage maps of both faces, the
//! governing places and the passes' peaks among the elements that count, the MEPDG's cracking,
//! the PCA's erosion at the corners, and the run's [`Damage`].

use rayon::prelude::*;

use super::damage_part::{DamagePart, PassStress};
use super::damage_pass::{label, Setup};
use super::damage_result::{Cracking, Damage, Governing, Pass, PassErosion, Peak};
use super::erosion::{CornerDamage, Erosion};
use super::RunOutcome;
use crate::damage::relations::{DamageModel, Mepdg};
use crate::error::{Error, Result};
use crate::model::Model;
use crate::scene::Problem;

/// The Miner sums of the parts' passes, every bin of the run in exactly one part.
pub(super) fn sum(problem: &Problem, setup: &Setup<'_>, parts: Vec<DamagePart>) -> Result<Damage> {
    let Setup {
        plan,
        bins,
        passes,
        erosion: erosion_setup,
        ..
    } = setup;
    let mut by_bin: Vec<Option<PassStress>> = vec![None; bins.len()];
    let (mut assemble_s, mut seconds) = (0.0, 0.0);
    for part in parts {
        assemble_s += part.assemble_s;
        seconds += part.seconds;
        for (i, stress) in part.bins.into_iter().zip(part.stresses) {
            match by_bin.get_mut(i) {
                Some(slot @ None) => *slot = Some(stress),
                Some(Some(_)) => {
                    return Err(Error::invalid(
                        "parts",
                        format!("case {i} is in two parts: each family belongs to one part"),
                    ))
                }
                None => {
                    return Err(Error::invalid(
                        "parts",
                        format!("case {i} is beyond the run's {} cases", bins.len()),
                    ))
                }
            }
        }
    }
    if let Some(i) = by_bin.iter().position(Option::is_none) {
        return Err(Error::invalid(
            "parts",
            format!(
                "case {i} ({}) is in no part: the parts must cover every family",
                label(plan, &bins[i])
            ),
        ));
    }
    let stresses: Vec<PassStress> = by_bin.into_iter().map(Option::unwrap_or_default).collect();
    let Some(first) = stresses.iter().find(|s| !s.x.is_empty()) else {
        return Err(Error::numerical(
            "damage",
            "no pass converged: nothing to sum (see the passes' outcomes)",
        ));
    };
    let (xs, ys) = (first.x.clone(), first.y.clone());
    // The grid of a solved position (a pass all interpolated has none of its own).
    let field = stresses
        .iter()
        .find_map(|s| s.field.clone())
        .unwrap_or_default();
    let n = xs.len();
    let allowed = |s: f64| plan.allowed(s);
    let mut missing = Vec::new();
    let mut summed = Vec::new();
    for (s, bin) in stresses.iter().zip(bins.iter()) {
        if s.outcome == RunOutcome::CONVERGED {
            summed.push((s, bin));
        } else {
            missing.push(label(plan, bin));
        }
    }
    // Element by element, the bins in their order (the sums are those of a loop over the bins
    // to the last bit); in parallel, since a growing modulus of rupture makes each term a sum
    // over the life's months.
    let (bottom, top): (Vec<f64>, Vec<f64>) = (0..n)
        .into_par_iter()
        .map(|i| {
            summed.iter().fold((0.0, 0.0), |(b, t), (s, bin)| {
                (
                    b + bin.repetitions / allowed(s.bottom[i]),
                    t + bin.repetitions / allowed(s.top[i]),
                )
            })
        })
        .unzip();
    // The elements that count ([`counted_elements`]): the governing places, the passes' peaks,
    // the cracking and a design take only these.
    let counted = counted_elements(&problem.model, plan.cut, &xs);
    let governing = |d: &[f64]| -> Governing {
        // The first of equal ones (an element and its mirror image on a symmetric plate).
        let k = (0..n)
            .rev()
            .filter(|&k| counted[k])
            .max_by(|&a, &b| d[a].total_cmp(&d[b]))
            .unwrap_or(0);
        Governing {
            damage: d.get(k).copied().unwrap_or(0.0),
            x: xs.get(k).copied().unwrap_or(f64::NAN),
            y: ys.get(k).copied().unwrap_or(f64::NAN),
            element: k,
        }
    };
    let (gb, gt) = (governing(&bottom), governing(&top));
    // The PCA's erosion at the corners: C2 Σ n/N of the deflections the passes caused.
    let c2 = match plan.model {
        DamageModel::Pca(m) => m.erosion_c2,
        _ => 1.0,
    };
    let erosion = match erosion_setup {
        Some(Ok(c)) => {
            let mut corners: Vec<CornerDamage> = c
                .points
                .iter()
                .map(|p| CornerDamage {
                    corner: p.clone(),
                    damage: 0.0,
                    deflection: 0.0,
                })
                .collect();
            for (s, bin) in stresses.iter().zip(bins.iter()) {
                if s.outcome != RunOutcome::CONVERGED {
                    continue;
                }
                let k = plan.climate[bin.climate].subgrade_modulus.unwrap_or(c.k);
                for (j, (cd, &w)) in corners.iter_mut().zip(&s.corners).enumerate() {
                    cd.damage += c2 * bin.repetitions / c.allowed(j, w, k);
                    cd.deflection = cd.deflection.max(w);
                }
            }
            let governing = (0..corners.len())
                .rev()
                .filter(|&j| corners[j].corner.counted)
                .max_by(|&a, &b| corners[a].damage.total_cmp(&corners[b].damage));
            Some((
                Erosion {
                    k: c.k,
                    c1: c.relation.erosion_c1,
                    c2,
                    corners,
                    governing,
                },
                c,
            ))
        }
        _ => None,
    };
    let passes_out: Vec<Pass> = stresses
        .iter()
        .zip(bins.iter())
        .zip(passes.iter())
        .map(|((s, bin), models)| {
            let group = &plan.groups[bin.group];
            let peak = |v: &[f64]| -> Peak {
                let among = (0..v.len())
                    .rev()
                    .filter(|&k| counted.get(k) == Some(&true));
                match among.max_by(|&a, &b| v[a].total_cmp(&v[b])) {
                    Some(k) if s.outcome == RunOutcome::CONVERGED => Peak {
                        stress: v[k],
                        x: s.x[k],
                        y: s.y[k],
                        allowed: Some(allowed(v[k])).filter(|a| a.is_finite()),
                    },
                    _ => Peak {
                        stress: f64::NAN,
                        x: f64::NAN,
                        y: f64::NAN,
                        allowed: None,
                    },
                }
            };
            let share = |v: &[f64], k: usize| -> f64 {
                if s.outcome == RunOutcome::CONVERGED {
                    v.get(k).map_or(0.0, |&st| bin.repetitions / allowed(st))
                } else {
                    0.0
                }
            };
            let pass_erosion = match (&erosion, s.outcome == RunOutcome::CONVERGED) {
                (Some((e, c)), true) => {
                    let k = plan.climate[bin.climate].subgrade_modulus.unwrap_or(c.k);
                    s.corners
                        .iter()
                        .enumerate()
                        .rev()
                        .filter(|&(j, _)| c.points.get(j).is_some_and(|p| p.counted))
                        .max_by(|a, b| a.1.total_cmp(b.1))
                        .map(|(j, &w)| PassErosion {
                            deflection: w,
                            x: c.points[j].x,
                            y: c.points[j].y,
                            allowed: Some(c.allowed(j, w, k)).filter(|a| a.is_finite()),
                            share: e
                                .governing
                                .and_then(|g| Some((g, *s.corners.get(g)?)))
                                .map_or(0.0, |(g, wg)| {
                                    e.c2 * bin.repetitions / c.allowed(g, wg, k)
                                }),
                        })
                }
                _ => None,
            };
            Pass {
                group: group.load.clone(),
                load: group.levels[bin.level].load,
                offset: plan.lateral[bin.lateral].offset,
                difference: Some(plan.climate[bin.climate].difference).filter(|d| d.is_finite()),
                repetitions: bin.repetitions,
                positions: models
                    .iter()
                    .map(|m| {
                        let at = m.vehicles[group.vehicle].at;
                        [at[0], at[1]]
                    })
                    .collect(),
                outcome: s.outcome,
                solves: s.solves,
                interpolated: s.interpolated,
                mirrored: s.mirrored,
                bottom: peak(&s.bottom),
                top: peak(&s.top),
                bottom_share: share(&s.bottom, gb.element),
                top_share: share(&s.top, gt.element),
                erosion: pass_erosion,
            }
        })
        .collect();
    let cracking = match &plan.model {
        DamageModel::Mepdg(m) => {
            let (b, t) = (m.cracking(gb.damage), m.cracking(gt.damage));
            let total = 100.0 * Mepdg::total_cracking(b, t);
            Some(Cracking {
                bottom: 100.0 * b,
                top: 100.0 * t,
                total,
                at_reliability: plan
                    .reliability
                    .map(|r| m.cracking_at_reliability(total, r)),
            })
        }
        DamageModel::Pca(_) | DamageModel::Faa(_) => None,
    };
    let nx = problem.model.elements[0];
    Ok(Damage {
        model: match plan.model {
            DamageModel::Pca(_) => "pca",
            DamageModel::Mepdg(_) => "mepdg",
            DamageModel::Faa(_) => "faa",
        },
        rupture: plan.rupture,
        rupture_ratio: plan.ages.as_ref().map(|a| a.ratio_range()),
        life_factor: plan.life_factor(),
        elements: [nx, n / nx.max(1)],
        x: xs,
        y: ys,
        bottom,
        top,
        counted,
        governing_bottom: gb,
        governing_top: gt,
        cracking,
        erosion_note: erosion_setup
            .as_ref()
            .and_then(|e| e.as_ref().err())
            .cloned(),
        erosion: erosion.map(|(e, _)| e),
        complete: missing.is_empty(),
        missing,
        solves: stresses.iter().map(|s| s.solves).sum(),
        interpolated: stresses.iter().map(|s| s.interpolated).sum(),
        mirrored: stresses.iter().map(|s| s.mirrored).sum(),
        passes: passes_out,
        assemble_s,
        total_s: seconds,
        units: problem.model.physical.map(|p| p.units),
        field,
    })
}

/// Which elements of the maps (centres `xs`, m) count in the governing places, the passes'
/// peaks, the cracking and a design: on a lane cut at the plate's ends (`cut`,
/// [`crate::damage::plan::TrafficSpec::ends`]) those between its first and last transverse
/// joint ([`super::ends`]), otherwise every element.
fn counted_elements(model: &Model, cut: bool, xs: &[f64]) -> Vec<bool> {
    let span = super::ends::counted_span(model, cut);
    xs.iter().map(|&x| super::ends::inside(span, x)).collect()
}
