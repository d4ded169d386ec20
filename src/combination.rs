//! Load combinations: every combination is its own unilateral contact problem (a foundation
//! that cannot pull does not superpose), solved on operators assembled once — K, B and T are
//! shared, only the load vector and the voids' initial gap change — in parallel where cores
//! allow, and the envelope of their results with the combination that governs each extreme.

use std::time::Instant;

use rayon::prelude::*;
use serde::Serialize;

use crate::analysis::{self, MethodRun};
use crate::budget;
use crate::error::{Error, Result};
use crate::model::Model;
use crate::monitor::{Cases, Monitor};
use crate::operators::Operators;
use crate::scene::{Combination, Problem};
use crate::units::{Measure, UnitSystem};

/// One combination's run.
pub struct CombinationRun {
    /// Its name.
    pub name: String,
    /// Its factors per case.
    pub factors: Vec<(String, f64)>,
    /// Its model (own P).
    pub model: Model,
    /// Solution, report and summary, or why there is none.
    pub outcome: Result<MethodRun>,
    /// Seconds for this combination: load vector, solve and post-processing.
    pub seconds: f64,
}

/// Every combination of a scene on one assembly.
pub struct Combinations {
    /// Per combination, in the scene's order.
    pub runs: Vec<CombinationRun>,
    /// The envelope over every combination — built only when every one converged (an
    /// envelope missing a combination is not an envelope); [`Combinations::missing`] names
    /// the ones that did not.
    pub envelope: Option<Envelope>,
    /// Seconds to assemble the shared operators (once).
    pub assemble_s: f64,
    /// Wall-clock seconds of the whole run.
    pub total_s: f64,
}

impl CombinationRun {
    /// Whether this combination has a converged solution.
    pub fn converged(&self) -> bool {
        matches!(&self.outcome, Ok(o) if o.solution.status.converged())
    }
}

impl Combinations {
    /// True when every combination converged.
    pub fn all_converged(&self) -> bool {
        self.runs.iter().all(CombinationRun::converged)
    }

    /// Names of the combinations without a converged solution (an error, or a solve that
    /// stopped): the ones the envelope would miss.
    pub fn missing(&self) -> Vec<&str> {
        self.runs
            .iter()
            .filter(|r| !r.converged())
            .map(|r| r.name.as_str())
            .collect()
    }

    /// `liftoff solve --json` of a scene with combinations: each combination's summary (or its
    /// error), the names of the ones without a solution, and the envelope's extremes (null
    /// when one is missing).
    pub fn to_json(&self) -> Result<String> {
        let runs: Vec<serde_json::Value> = self
            .runs
            .iter()
            .map(|r| {
                let summary = r
                    .outcome
                    .as_ref()
                    .ok()
                    .and_then(|o| o.summary.to_value().ok());
                let error = r.outcome.as_ref().err().map(|e| e.to_string());
                serde_json::json!({ "name": r.name, "summary": summary, "error": error })
            })
            .collect();
        let doc = serde_json::json!({
            "combinations": runs,
            "missing": self.missing(),
            "envelope": self.envelope.as_ref().map(|e| e.reported().quantities),
        });
        serde_json::to_string_pretty(&doc)
            .map_err(|e| Error::numerical("envelope", format!("cannot serialise: {e}")))
    }
}

/// Solve every combination of `problem` (which must have some) on one assembly, in parallel;
/// `monitor` gets a [`Progress::Case`] per finished combination and can cancel the run. The
/// envelope is built when every combination converged.
pub fn analyse(problem: &Problem, monitor: &Monitor<'_>) -> Result<Combinations> {
    let t0 = Instant::now();
    let models: Vec<Model> = problem
        .combinations
        .iter()
        .map(|c| c.model.clone())
        .collect();
    if models.is_empty() {
        return Err(Error::invalid(
            "combination",
            "the scene has no [[combination]]: solve it as one load set",
        ));
    }
    let base = assemble_for(problem, &models, "combinations")?;
    let assemble_s = t0.elapsed().as_secs_f64();
    let cases = Cases::new(monitor, problem.combinations.len());
    let inner = cases.inner();
    // Contiguous runs of the scene's order, one per core, side by side; in each, a combination
    // starts from the answer of the one before it (the same operators: the penalty's first
    // lifted set, the active-set QP's first iterate; the answer does not depend on it).
    let per = problem
        .combinations
        .len()
        .div_ceil(rayon::current_num_threads().max(1))
        .max(1);
    let runs: Vec<CombinationRun> = problem
        .combinations
        .par_chunks(per)
        .flat_map_iter(|chunk| {
            let mut warm: Option<Vec<f64>> = None;
            chunk
                .iter()
                .map(|c: &Combination| {
                    let t = Instant::now();
                    let ops = base.loaded(&c.model);
                    let outcome = inner.check("load combinations").and_then(|()| {
                        analysis::run_from(
                            &c.model,
                            &ops,
                            &problem.method,
                            0.0,
                            warm.as_deref(),
                            &inner,
                        )
                    });
                    if let Ok(o) = &outcome {
                        if o.solution.status.converged() {
                            warm = Some(o.solution.sigma.clone());
                        }
                    }
                    // A cancelled run is caught below, once every worker has stopped.
                    let _ = cases.finish(&c.name);
                    CombinationRun {
                        name: c.name.clone(),
                        factors: c.factors.clone(),
                        model: c.model.clone(),
                        outcome,
                        seconds: t.elapsed().as_secs_f64(),
                    }
                })
                .collect::<Vec<_>>()
        })
        .collect();
    // A cancelled run is not a set of combinations that did not converge: say it was cancelled.
    monitor.check("load combinations")?;
    let envelope = if runs.iter().all(CombinationRun::converged) {
        envelope(&runs)
    } else {
        None
    };
    Ok(Combinations {
        runs,
        envelope,
        assemble_s,
        total_s: t0.elapsed().as_secs_f64(),
    })
}

/// One set of operators for several models of one plate and soil that differ only in their
/// loads and voids (the combinations of a scene, the positions of a moving load), on the route
/// `[solver] route` gives and within the memory limit shared by the models solved side by side
/// (each needs its own factorisation); `what` names them in a refusal.
pub(crate) fn assemble_for(problem: &Problem, models: &[Model], what: &str) -> Result<Operators> {
    let Some(first) = models.first() else {
        return Err(Error::invalid(what, "nothing to solve"));
    };
    let (mesh, _) = crate::model::plan_shared_mesh(models);
    let parallel = rayon::current_num_threads().min(models.len()).max(1) as f64;
    // The route of `[solver] route` (the half-space T by FFT beyond the size `auto` allows).
    let toeplitz = !first.groups.foundation().is_local()
        && problem
            .route
            .iterative(mesh.n_nodes(), &problem.method, problem.model.constraint)?;
    if toeplitz {
        let need = budget::iterative_bytes(&mesh);
        if need > problem.memory_limit / parallel {
            return Err(Error::TooLarge {
                what: format!(
                    "{} {what} of a {} × {} element model on the iterative route",
                    models.len(),
                    mesh.nx,
                    mesh.ny
                ),
                need_gib: need * parallel / 1024f64.powi(3),
                limit_gib: problem.memory_limit / 1024f64.powi(3),
                hint: "use fewer elements".into(),
            });
        }
    } else {
        budget::check_mesh(
            &mesh,
            first.groups.foundation(),
            first.constraint,
            &problem.method,
            problem.memory_limit / parallel,
        )?;
    }
    Ok(Operators::assemble_shared_with(models, toeplitz))
}

/// Runs a core may hold side by side on the iterative route ([`side_by_side`]).
const RUNS_PER_CORE: usize = 5;

/// How many of `runs` runs of positions (each a chain of warm-started solves) to solve side by
/// side on `base`. On the iterative route (T by FFT) every conjugate-gradient product is a solve
/// with the plate's factor, and threads on one assembly share those solves in batches
/// ([`crate::solve::linalg::PlateInverse::apply`]: eight right-hand sides cost 1.6–2.2 single
/// ones on the half-space lane's plate, the factor read from memory once), so as many runs as
/// there are — up to [`RUNS_PER_CORE`] a core and what `[solver] memory_limit` allows, each run
/// holding its own iterative state ([`budget::iterative_bytes`]). Elsewhere the cores.
pub(crate) fn side_by_side(problem: &Problem, base: &Operators, runs: usize) -> usize {
    let cores = rayon::current_num_threads().max(1);
    if !matches!(base.t.as_ref(), crate::foundation::Compliance::Toeplitz(_)) {
        return cores;
    }
    let fit = (problem.memory_limit / budget::iterative_bytes(&base.mesh)).floor() as usize;
    runs.min(RUNS_PER_CORE * cores).min(fit).max(cores)
}

/// `work` on a pool of `threads` threads when that is wider than rayon's own — a pool whose
/// threads are marked ([`crate::solve::linalg::mark_sharing_thread`]) so that the plate's solves
/// batch on it ([`side_by_side`]) — else on rayon's.
pub(crate) fn on_threads<R: Send>(threads: usize, work: impl FnOnce() -> R + Send) -> Result<R> {
    if threads <= rayon::current_num_threads() {
        return Ok(work());
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .thread_name(|i| format!("{}-{i}", crate::solve::linalg::SHARING_POOL))
        .start_handler(|_| crate::solve::linalg::mark_sharing_thread())
        .build()
        .map_err(|e| Error::numerical("threads", format!("a pool of {threads} threads: {e}")))?;
    Ok(pool.install(work))
}

/// Where an extreme occurs and which combination gives it.
#[derive(Debug, Clone, Serialize)]
pub struct Extreme {
    /// The value, in `unit`.
    pub value: f64,
    /// The governing combination.
    pub combination: String,
    /// x of the node or element centre (m, or x / L in a dimensionless scene).
    pub x: f64,
    /// y.
    pub y: f64,
}

/// Largest and smallest values of one quantity over every combination.
#[derive(Debug, Clone, Serialize)]
pub struct QuantityEnvelope {
    /// Name (w, pressure, uplift, mx, my, mxy, qx, qy, s1_bottom, s1_top).
    pub quantity: &'static str,
    /// Unit of the values.
    pub unit: &'static str,
    /// Largest value.
    pub max: Extreme,
    /// Smallest value.
    pub min: Extreme,
}

/// Per node or element: largest and smallest over the combinations and which governs each (NaN
/// at the nodes and elements outside a shaped plate).
#[derive(Debug, Clone, Default)]
pub struct PointEnvelope {
    /// Largest value.
    pub max: Vec<f64>,
    /// Combination index of the largest value.
    pub max_by: Vec<usize>,
    /// Smallest value.
    pub min: Vec<f64>,
    /// Combination index of the smallest value.
    pub min_by: Vec<usize>,
}

/// The envelope of a set of converged combinations.
#[derive(Debug, Clone)]
pub struct Envelope {
    /// Combination names, in order (the indices of [`PointEnvelope`]).
    pub names: Vec<String>,
    /// Extremes over the plate.
    pub quantities: Vec<QuantityEnvelope>,
    /// Node positions.
    pub node_xy: Vec<(f64, f64)>,
    /// Element centres.
    pub element_xy: Vec<(f64, f64)>,
    /// Node fields: (name, unit, envelope) of w, pressure and uplift.
    pub nodes: Vec<(&'static str, &'static str, PointEnvelope)>,
    /// Element fields: mx, my, mxy, qx, qy.
    pub elements: Vec<(&'static str, &'static str, PointEnvelope)>,
    /// The scene's unit system (None: a dimensionless scene); the fields above are SI.
    pub system: Option<UnitSystem>,
}

impl Envelope {
    /// The envelope as the files report it: every value and position in the scene's unit
    /// system, with its unit (a dimensionless scene's is returned as it is).
    pub fn reported(&self) -> Envelope {
        let Some(system) = self.system else {
            return self.clone();
        };
        let sys = Some(system);
        let length = |v: f64| Measure::Length.from_si(sys, v);
        let xy = |v: &[(f64, f64)]| v.iter().map(|&(x, y)| (length(x), length(y))).collect();
        let field = |&(name, _, ref e): &(&'static str, &'static str, PointEnvelope)| {
            let m = measure_of(name);
            let c = |v: &[f64]| v.iter().map(|&x| m.from_si(sys, x)).collect();
            let e = PointEnvelope {
                max: c(&e.max),
                min: c(&e.min),
                ..e.clone()
            };
            (name, m.unit(sys), e)
        };
        let extreme = |m: Measure, e: &Extreme| Extreme {
            value: m.from_si(sys, e.value),
            combination: e.combination.clone(),
            x: length(e.x),
            y: length(e.y),
        };
        Envelope {
            names: self.names.clone(),
            quantities: self
                .quantities
                .iter()
                .map(|q| {
                    let m = measure_of(q.quantity);
                    QuantityEnvelope {
                        quantity: q.quantity,
                        unit: m.unit(sys),
                        max: extreme(m, &q.max),
                        min: extreme(m, &q.min),
                    }
                })
                .collect(),
            node_xy: xy(&self.node_xy),
            element_xy: xy(&self.element_xy),
            nodes: self.nodes.iter().map(field).collect(),
            elements: self.elements.iter().map(field).collect(),
            system: self.system,
        }
    }
}

/// What an envelope field measures, by its name.
fn measure_of(name: &str) -> Measure {
    match name {
        "w" | "uplift" => Measure::Deflection,
        "mx" | "my" | "mxy" => Measure::MomentPerLength,
        "qx" | "qy" => Measure::ForcePerLength,
        _ => Measure::Pressure,
    }
}

/// Envelope of the converged runs (None when there are none; [`analyse`] calls it only when
/// every run converged). Fields are taken in physical
/// units for SI scenes; in a dimensionless scene they are rescaled to the scene's own force
/// unit (V and σ times each combination's P), since every combination has its own P.
pub fn envelope(runs: &[CombinationRun]) -> Option<Envelope> {
    let ok: Vec<(&CombinationRun, &MethodRun)> = runs
        .iter()
        .filter_map(|r| match &r.outcome {
            Ok(o) if o.solution.status.converged() => Some((r, o)),
            _ => None,
        })
        .collect();
    let (first, first_o) = ok.first()?;
    let physical = first.model.physical.is_some();
    let units = |si: &'static str, dimless: &'static str| if physical { si } else { dimless };
    let field = &first_o.report.field;
    let node_xy: Vec<(f64, f64)> = field
        .x
        .iter()
        .copied()
        .zip(field.y.iter().copied())
        .collect();
    let el = &first_o.report.elements;
    let element_xy: Vec<(f64, f64)> = el.x.iter().copied().zip(el.y.iter().copied()).collect();
    let names: Vec<String> = ok.iter().map(|(r, _)| r.name.clone()).collect();
    // A dimensionless scene's fields are in units of each combination's own P.
    let scale = |r: &CombinationRun| if physical { 1.0 } else { r.model.load_scale };
    type Getter = fn(&MethodRun) -> &[f64];
    let node_fields: [(&'static str, &'static str, &'static str, Getter); 3] = [
        ("w", "m", "F·L²/D", |o| &o.report.field.w),
        ("pressure", "Pa", "F/L²", |o| &o.report.field.pressure),
        ("uplift", "m", "F·L²/D", |o| &o.report.field.gap),
    ];
    let element_fields: [(&'static str, &'static str, &'static str, Getter); 7] = [
        ("mx", "N·m/m", "F", |o| &o.report.elements.mx),
        ("my", "N·m/m", "F", |o| &o.report.elements.my),
        ("mxy", "N·m/m", "F", |o| &o.report.elements.mxy),
        ("qx", "N/m", "F/L", |o| &o.report.elements.qx),
        ("qy", "N/m", "F/L", |o| &o.report.elements.qy),
        ("s1_bottom", "Pa", "F/L²", |o| &o.report.elements.bottom.s1),
        ("s1_top", "Pa", "F/L²", |o| &o.report.elements.top.s1),
    ];
    // A shaped plate's nodes and elements outside it: NaN in every envelope, no extreme.
    let node_on = field.node_on_plate();
    let element_on: Vec<bool> = (0..el.x.len())
        .map(|e| field.plate.get(e).copied().unwrap_or(true))
        .collect();
    let point = |get: Getter, on: &[bool]| -> PointEnvelope {
        let n = get(first_o).len();
        let mut e = PointEnvelope {
            max: vec![f64::NEG_INFINITY; n],
            max_by: vec![0; n],
            min: vec![f64::INFINITY; n],
            min_by: vec![0; n],
        };
        for (k, (r, o)) in ok.iter().enumerate() {
            let s = scale(r);
            for (i, &v) in get(o).iter().enumerate().take(n) {
                let v = v * s;
                if v > e.max[i] {
                    e.max[i] = v;
                    e.max_by[i] = k;
                }
                if v < e.min[i] {
                    e.min[i] = v;
                    e.min_by[i] = k;
                }
            }
        }
        for (i, _) in on.iter().enumerate().filter(|(_, &o)| !o).take(n) {
            e.max[i] = f64::NAN;
            e.min[i] = f64::NAN;
        }
        e
    };
    let mut quantities = Vec::new();
    let mut summarise = |name, unit, e: &PointEnvelope, xy: &[(f64, f64)]| {
        let imax = argmax(&e.max);
        let imin = argmin(&e.min);
        if let (Some(a), Some(b)) = (imax, imin) {
            quantities.push(QuantityEnvelope {
                quantity: name,
                unit,
                max: Extreme {
                    value: e.max[a],
                    combination: names[e.max_by[a]].clone(),
                    x: xy[a].0,
                    y: xy[a].1,
                },
                min: Extreme {
                    value: e.min[b],
                    combination: names[e.min_by[b]].clone(),
                    x: xy[b].0,
                    y: xy[b].1,
                },
            });
        }
    };
    let nodes: Vec<_> = node_fields
        .iter()
        .map(|&(n, si, dl, g)| (n, units(si, dl), point(g, &node_on)))
        .collect();
    let elements: Vec<_> = element_fields
        .iter()
        .map(|&(n, si, dl, g)| (n, units(si, dl), point(g, &element_on)))
        .collect();
    for (n, u, e) in &nodes {
        summarise(*n, *u, e, &node_xy);
    }
    for (n, u, e) in &elements {
        summarise(*n, *u, e, &element_xy);
    }
    Some(Envelope {
        names,
        quantities,
        node_xy,
        element_xy,
        nodes,
        elements,
        system: first.model.physical.map(|p| p.units),
    })
}

/// The index of the largest value, NaN (off a shaped plate) skipped.
fn argmax(v: &[f64]) -> Option<usize> {
    (0..v.len())
        .filter(|&a| !v[a].is_nan())
        .max_by(|&a, &b| v[a].total_cmp(&v[b]))
}

/// The index of the smallest value, NaN skipped.
fn argmin(v: &[f64]) -> Option<usize> {
    (0..v.len())
        .filter(|&a| !v[a].is_nan())
        .min_by(|&a, &b| v[a].total_cmp(&v[b]))
}

#[cfg(test)]
mod tests {
    use super::on_threads;
    use crate::solve::linalg::in_sharing_pool;

    /// A pool wider than rayon's marks every one of its threads as sharing the plate's solves
    /// (so they batch); work that fits rayon's own pool runs there, unmarked.
    #[test]
    fn a_wider_pool_marks_its_threads_as_sharing() {
        let wide = rayon::current_num_threads() + 2;
        let marked = on_threads(wide, || rayon::broadcast(|_| in_sharing_pool()))
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(marked.len(), wide);
        assert!(marked.iter().all(|&m| m), "{marked:?}");
        let own = on_threads(1, || rayon::broadcast(|_| in_sharing_pool()))
            .unwrap_or_else(|e| panic!("{e}"));
        assert!(own.iter().all(|&m| !m), "{own:?}");
        assert!(!in_sharing_pool(), "the calling thread is not marked");
    }
}
