//! The passes of a damage run ([`super::damage`]): each case's models — the scene's model in
//! its climate bin (the bin's temperature load, a profile's face stress, the bin's own
//! subgrade modulus), the group's vehicle at the level's load placed at every position along
//! the lane — and a case in words for the progress bar and the list of missing passes.

use super::erosion::Corners;
use crate::damage::plan::{Bin, DamagePlan};
use crate::damage::relations::DamageModel;
use crate::error::{Error, Result};
use crate::model::{Load, Model};
use crate::scene::Problem;
use crate::units::{Quantity, UnitSystem};

/// A case in words, for the progress bar and the list of missing passes, in the scene's units.
pub(super) fn label(plan: &DamagePlan, bin: &Bin) -> String {
    let g = &plan.groups[bin.group];
    let climate = plan.climate[bin.climate];
    let d = climate.difference;
    let us = plan.units == Some(UnitSystem::Us);
    let load = g.levels[bin.level].load;
    format!(
        "{} at {}, {} from the edge{}{}",
        g.load,
        if us {
            format!("{:.0} lbf", Quantity::Force.from_si(UnitSystem::Us, load))
        } else {
            format!("{:.1} kN", load / 1e3)
        },
        length(plan, plan.lateral[bin.lateral].offset),
        match (d.is_finite(), us) {
            (false, _) => String::new(),
            (true, false) => format!(", ΔT {d:+.1} K"),
            // 9/5 exactly, as damage.json reports the bins (`Damage::reported`).
            (true, true) => format!(", ΔT {:+.1} °F", d * 9.0 / 5.0),
        },
        climate.subgrade_modulus.map_or(String::new(), |k| if us {
            let pci = Quantity::SubgradeModulus.from_si(UnitSystem::Us, k);
            format!(", k {pci:.0} pci")
        } else {
            format!(", k {:.1} MN/m³", k / 1e6)
        })
    )
}

/// A length of the plan (SI) in the scene's unit of length, for words: `0.457 m`, `18.0 in`.
fn length(plan: &DamagePlan, si: f64) -> String {
    match plan.units {
        Some(UnitSystem::Us) => format!("{:.1} in", Quantity::Length.from_si(UnitSystem::Us, si)),
        _ => format!("{si:.3} m"),
    }
}

/// The models of one case's pass: the scene's model with its climate bin's temperature load
/// added, the group's vehicle at the level's load (the other vehicles without load), placed at
/// `plan.steps` positions along the lane from where its prints enter the slab to where they
/// leave it, its outer tire's edge at the lateral position's distance from the edge.
pub(super) fn pass_models(base: &Model, plan: &DamagePlan, bin: &Bin) -> Result<Vec<Model>> {
    let group = &plan.groups[bin.group];
    let k = group.vehicle;
    let mut model = base.clone();
    let climate = plan.climate[bin.climate];
    // A bin's own subgrade modulus: Γ_w = D / (k μ L⁴).
    if let (Some(k), Some(phys)) = (climate.subgrade_modulus, base.physical) {
        model.groups.gamma = phys.rigidity / (k * model.groups.mu * phys.half_length.powi(4));
    }
    let d = climate.difference;
    if d.is_finite() {
        let per_k = plan.curvature_per_kelvin.unwrap_or(0.0);
        model.loads.push(Load::Temperature {
            curvature: per_k * d,
        });
    }
    // A profile's nonlinear part: its own stress at the faces, the same at every level.
    if climate.nonlinear != [0.0; 2] {
        let per_k = plan.stress_per_kelvin.unwrap_or(0.0);
        model.loads.push(Load::FaceStress {
            top: per_k * climate.nonlinear[0],
            bottom: per_k * climate.nonlinear[1],
        });
    }
    for (i, v) in model.vehicles.iter_mut().enumerate() {
        if i == k {
            let nominal: f64 = v.wheels.iter().map(|w| w.force).sum();
            v.factor = group.levels[bin.level].load / nominal;
        } else {
            v.factor = 0.0;
        }
    }
    for i in 0..model.vehicles.len() {
        if i != k {
            let at = model.vehicles[i].at;
            model.place(i, at)?;
        }
    }
    let v = &model.vehicles[k];
    let [a, b] = v.frame.plate;
    // The prints' extent about the reference point, travelling along x.
    let tires = v.tires([0.0, 0.0, 0.0])?;
    let ext = |f: fn(&crate::vehicle::Tire) -> f64, g: fn(f64, f64) -> f64, init: f64| {
        tires.iter().map(f).fold(init, g)
    };
    let x_lo = ext(|t| t.centre[0] - t.size[0] / 2.0, f64::min, f64::INFINITY);
    let x_hi = ext(
        |t| t.centre[0] + t.size[0] / 2.0,
        f64::max,
        f64::NEG_INFINITY,
    );
    let y_lo = ext(|t| t.centre[1] - t.size[1] / 2.0, f64::min, f64::INFINITY);
    let y_hi = ext(
        |t| t.centre[1] + t.size[1] / 2.0,
        f64::max,
        f64::NEG_INFINITY,
    );
    // Inside the plate by a hair, as critical's grid keeps its prints.
    let (gap_x, gap_y) = (1e-9 * a, 1e-9 * b);
    let offset = plan.lateral[bin.lateral].offset;
    let (y_min, y_max) = (-b / 2.0 - y_lo + gap_y, b / 2.0 - y_hi - gap_y);
    if y_min > y_max || x_hi - x_lo >= a {
        return Err(Error::invalid(
            format!("traffic.group[{}].load", bin.group),
            format!(
                "the prints of `{}` do not fit on the {} × {} plate",
                group.load,
                length(plan, a),
                length(plan, b)
            ),
        ));
    }
    // The scene's check keeps `edge_at` across the plate.
    let edge = match plan.edge_at {
        Some(e) => e,
        None if plan.lower_edge => -b / 2.0,
        None => b / 2.0,
    };
    let y = if plan.lower_edge {
        edge + offset - y_lo
    } else {
        edge - offset - y_hi
    }
    .clamp(y_min, y_max);
    let (x0, x1) = (-a / 2.0 - x_lo + gap_x, a / 2.0 - x_hi - gap_x);
    let steps = plan.steps.unwrap_or((base.elements[0] + 1).clamp(3, 401));
    let xs: Vec<f64> = (0..steps)
        .map(|s| x0 + (x1 - x0) * s as f64 / (steps - 1) as f64)
        .collect();
    // On a plate with an outline or openings a pass must cross it whole: a print on an opening
    // or past the outline is carried by no slab, and a pass that skipped those positions would
    // miss the stresses beside them. Said as the lane's fault, with where it leaves the plate
    // (`Model::place` would name only the scene's load).
    let mut off = Vec::new();
    for &x in &xs {
        if !model.prints_on_plate(k, [x, y, 0.0])? {
            off.push(x);
        }
    }
    if let (Some(first), Some(last)) = (off.first(), off.last()) {
        let l = &plan.lateral[bin.lateral];
        return Err(Error::invalid(
            "traffic.wander",
            format!(
                "a pass of `{}` with its outer tire {} from the edge (lateral position {} of {}) puts a print on an opening or outside the plate's outline at {} of its {steps} positions, x = {} … {}: a pass crosses the plate from end to end, and a load that falls through the slab is carried by none — keep the lane on the plate (traffic.edge_at, traffic.wander's mean and deviation) or model the plate's part that carries it",
                group.load,
                length(plan, l.offset),
                bin.lateral + 1,
                plan.lateral.len(),
                off.len(),
                length(plan, *first),
                length(plan, *last),
            ),
        ));
    }
    xs.into_iter()
        .map(|x| {
            let mut m = model.clone();
            m.place(k, [x, y, 0.0])?;
            Ok(m)
        })
        .collect()
}

/// A damage run's plan checked, its cases, their passes' models and its families.
pub(super) struct Setup<'a> {
    pub(super) plan: &'a DamagePlan,
    pub(super) bins: Vec<Bin>,
    pub(super) passes: Vec<Vec<Model>>,
    /// The levels of one group at one lateral position in one climate bin, by load.
    pub(super) families: Vec<Vec<usize>>,
    /// The PCA's erosion: the corners where it is summed, or why it is not (None: another
    /// relation).
    pub(super) erosion: Option<std::result::Result<Corners, String>>,
}

impl<'a> Setup<'a> {
    pub(super) fn of(problem: &'a Problem) -> Result<Self> {
        let plan = problem.damage.as_ref().ok_or_else(|| {
            Error::invalid(
                "traffic",
                "missing: `liftoff damage` needs the scene's [traffic] and [damage] (and optionally [climate])",
            )
        })?;
        if problem.model.physical.is_none() {
            return Err(Error::invalid(
                "plate",
                "a damage run needs a physical scene ([plate] and [foundation]): stresses in Pa against the modulus of rupture",
            ));
        }
        let bins = plan.bins();
        let passes: Vec<Vec<Model>> = bins
            .iter()
            .map(|b| pass_models(&problem.model, plan, b))
            .collect::<Result<_>>()?;
        // The families: their load vectors differ only by the level's multiple of the group's.
        let mut families: Vec<Vec<usize>> = Vec::new();
        for (i, b) in bins.iter().enumerate() {
            match families.iter_mut().find(|f| {
                let o = &bins[f[0]];
                (o.group, o.lateral, o.climate) == (b.group, b.lateral, b.climate)
            }) {
                Some(f) => f.push(i),
                None => families.push(vec![i]),
            }
        }
        let level = |i: usize| plan.groups[bins[i].group].levels[bins[i].level].load;
        for f in &mut families {
            f.sort_by(|&a, &b| level(a).total_cmp(&level(b)));
        }
        let erosion = match plan.model {
            DamageModel::Pca(m) => Some(Corners::of(&problem.model, m, plan.cut)),
            _ => None,
        };
        Ok(Self {
            plan,
            bins,
            passes,
            families,
            erosion,
        })
    }
}
