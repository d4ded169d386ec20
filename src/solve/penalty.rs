//! The paper's penalty iteration (eqs. 4.2–4.6).
//!
//! Step 1 is the bonded problem. At step i the constraint points where the previous pressure
//! was negative get an extra compliance Σ(σ^(i−1))/ε̄ with Σ = c Gᵀ diag(w_k [Gσ]_k < 0) G
//! (c the foundation constant μΓ, w_k the points' area weights: eq. 4.3–4.4), and the bilateral
//! problem with compliance T + Σ/ε̄ is solved again. Mechanically: soft springs, ε̄ times the
//! foundation's stiffness, replace the foundation where it would pull. The iteration stops when
//! the penalised set repeats; it is reported as cycling when it returns to an older set and as
//! not converged when the cap is reached. The error against the exact unilateral solution is
//! O(ε̄).
//!
//! The linear system of each step is solved on the shared operators without re-assembly:
//! Winkler with nodal constraints keeps the sparse SPD form K + B (T + Σ/ε̄)⁻¹ Bᵀ (only
//! diagonal values change; the symbolic Cholesky is reused); Winkler with Gauss constraints
//! solves the sparse saddle system [K B; Bᵀ −(T + Σ/ε̄)] by LU (pattern fixed, values change);
//! the half-space adds Σ/ε̄ to the Schur complement formed once, factors it densely once and
//! solves later steps by low-rank updates of that factor ([`super::low_rank`]).

use std::time::Instant;

use super::checks::discrete_gap;
use super::linalg::finite;
use super::penalty_step::{cached_constraint_rows, penalty_weights, Backend};
use super::solution::{Iteration, PenaltyStage, Solution, SolveInfo, Status, Timings};
use super::spring_factor::Carry;
use crate::error::{Error, Result};
use crate::method::{Method, PenaltySettings};
use crate::monitor::{Monitor, Progress, StepKind};
use crate::operators::Operators;

/// Largest tension left at lifted points that a converged penalty solution may carry, relative
/// to the peak pressure and (as a force) to the compressive resultant. The penalty error is O(ε̄): on the paper's cases at ε̄ = 1e-5 the
/// ratio is ~1e-6; a ratio above 1e-4 means the penalty springs are not soft enough compared
/// with the plate (small Γ on the half-space), and the contact region is wrong.
pub const TENSION_TOLERANCE: f64 = 1e-4;

/// Largest share of the load that fictitious tension at lifted points may carry in a converged
/// penalty solution: 0.1 %. On the paper's cases at ε̄ = 1e-5 the share is ~1e-4 (about 10 ε̄).
/// The same bound holds the shift of the contact's resultant that the tension's moment forces,
/// relative to the contact's size (`tension_moment`).
pub const TENSION_FORCE_TOLERANCE: f64 = 1e-3;

/// Smallest ε̄ the automatic choice goes down to. The penalty springs are then 1e18 times
/// softer than the soil: the Winkler steps keep their digits because a bed whose rigid modes
/// the soft springs alone hold is solved with the rigid part split off
/// ([`super::rigid_split::needs_split`]); a plate balanced on its corner node needs 3e-15 at
/// 200² and 400² elements (its tension's moment, `tension_moment`, falls like ε̄ times the
/// number of elements across), where the plain factorisation lost equilibrium below 1e-11.
pub const MIN_AUTO_EPSILON: f64 = 1e-18;

/// Most continuation stages of the automatic choice of ε̄.
pub const MAX_AUTO_STAGES: usize = 8;

/// What one ε̄ of the iteration ended with.
struct StageEnd {
    status: Status,
    u: Vec<f64>,
    sigma: Vec<f64>,
    alpha: Vec<f64>,
    penalised: Vec<bool>,
}

/// Iterate at one ε̄ from the penalised set `start` until the set repeats, cycles or `cap`
/// steps are taken; steps are appended to `history`.
#[allow(clippy::too_many_arguments)]
fn stage(
    ops: &Operators,
    backend: &mut Backend,
    rows: &[Vec<(usize, f64)>],
    start: Vec<bool>,
    epsilon: f64,
    cap: usize,
    history: &mut Vec<Iteration>,
    t_solves: &mut f64,
    monitor: &Monitor<'_>,
) -> Result<StageEnd> {
    let n_c = start.len();
    let mut penalised = start;
    let mut seen: Vec<Vec<bool>> = vec![penalised.clone()];
    let mut status = Status::IterationLimit { limit: cap };
    let mut last = None;
    // The iterative route solves to a loose tolerance while the set is still moving, to a
    // medium one once it repeats there (the loose solves leave the sign of the pressures near
    // the contact edge uncertain) and to the tight one once it repeats (or cycles) again: only
    // a tight solve can confirm the set. `level` is the step's tolerance (None: tight, and
    // every step of the direct routes).
    let ladder = backend.levels();
    let mut rung = 0;
    let level = |rung: usize| ladder.get(rung).copied();
    // After a cycle of tight solves, the steps are damped (`Damped`): the iterate moves from
    // where it is towards each step's answer only as far as the penalised energy falls.
    let mut damped: Option<Damped> = None;
    for _ in 0..cap {
        monitor.check("the penalty iteration")?;
        let ts = Instant::now();
        let mut out = backend.solve(ops, rows, &penalised, epsilon, level(rung), monitor)?;
        while level(rung).is_some() && out.3.is_some_and(|cg| cg.iterations == 0) {
            // The inexact solve found its start (the last answer) already within its
            // tolerance: it has not seen the new set and would only hand the last set back,
            // for a tighter solve to look one step later. Go tighter in this step.
            rung += 1;
            seen = vec![penalised.clone()];
            out = backend.solve(ops, rows, &penalised, epsilon, level(rung), monitor)?;
        }
        let (u, sigma, alpha, cg) = out;
        *t_solves += ts.elapsed().as_secs_f64();
        if let Some(u) = &u {
            finite(u, "penalty iteration")?;
        }
        finite(&sigma, "penalty iteration")?;
        let gs = ops.g_times(&sigma);
        let next: Vec<bool> = gs.iter().map(|&v| v < 0.0).collect();
        let entered = next
            .iter()
            .zip(&penalised)
            .filter(|(n, p)| **n && !**p)
            .count();
        let left = next
            .iter()
            .zip(&penalised)
            .filter(|(n, p)| !**n && **p)
            .count();
        let count = next.iter().filter(|&&b| b).count();
        history.push(Iteration {
            step: history.len() + 1,
            epsilon,
            penalised: count,
            entered,
            left,
            min_pressure: gs.iter().cloned().fold(f64::INFINITY, f64::min),
            cg,
        });
        monitor.report(Progress::Step {
            method: StepKind::Penalty,
            step: history.len(),
            changes: entered + left,
        });
        if next != penalised {
            if let Some(d) = damped.as_mut() {
                // The step's answer is the minimiser of the energy with this set's springs;
                // the iterate goes to the energy's minimum on the way there, and the next set
                // is the iterate's.
                d.advance(ops, &penalised, epsilon, u.as_deref(), &sigma, &alpha, gs);
                let mut moved: Vec<bool> = d.gs.iter().map(|&v| v < 0.0).collect();
                if moved == penalised {
                    // The minimum fell on a kink of the set (measure zero, but rounding finds
                    // it): the same set would give the same answer. Take the full step.
                    *d = Damped::new(ops, &penalised, epsilon, u.as_deref(), &sigma, &alpha);
                    moved = next;
                }
                last = Some((u, sigma, alpha));
                penalised = moved;
                continue;
            }
        }
        last = Some((u, sigma, alpha));
        if count == n_c {
            return Err(Error::Infeasible(
                "the penalty iteration lifted every constraint point: no part of the plate stays in contact (are the loads pulling the plate up?)".into(),
            ));
        }
        if next == penalised {
            if level(rung).is_some() {
                // Look again with a tighter solve; sets met by inexact solves do not count as
                // a cycle of the tighter ones.
                rung += 1;
                seen = vec![penalised.clone()];
                continue;
            }
            status = Status::Converged;
            break;
        }
        if level(rung).is_some() && seen.contains(&next) {
            // An inexact solve may revisit a set: decide cycling on tight solves only.
            rung = ladder.len();
            seen = vec![penalised.clone()];
        }
        if let Some(pos) = seen.iter().position(|s| *s == next) {
            if level(rung).is_none() {
                // A cycle of exact (tight) solves: the full steps overshoot. Go on from this
                // step's answer with damped steps, which cannot cycle.
                if let Some((u, sigma, alpha)) = &last {
                    damped = Some(Damped::new(
                        ops,
                        &penalised,
                        epsilon,
                        u.as_deref(),
                        sigma,
                        alpha,
                    ));
                    penalised = next;
                    continue;
                }
            }
            status = Status::Cycling {
                period: seen.len() - pos,
            };
            penalised = next;
            break;
        }
        seen.push(next.clone());
        penalised = next;
    }
    let (u, sigma, alpha) = match (&status, damped) {
        // Out of steps while damped: the iterate, the best point the steps reached.
        (Status::IterationLimit { .. }, Some(d)) => (d.u, d.sigma, d.alpha),
        _ => last.ok_or_else(|| Error::numerical("penalty iteration", "no iteration was run"))?,
    };
    // The iterative route forms u for the point the stage ends on only (a plate solve a step).
    let u = match u {
        Some(u) => u,
        None => {
            let u = backend.displacements(ops, &sigma, &alpha)?;
            finite(&u, "penalty iteration")?;
            u
        }
    };
    if status == Status::Converged {
        status = tension_check(ops, &sigma, epsilon);
    }
    Ok(StageEnd {
        status,
        u,
        sigma,
        alpha,
        penalised,
    })
}

/// The iterate of a damped penalty stage (after the full steps cycled): a point on the way
/// between step answers, and the part of the energy's gradient that the plate and the soil
/// give it, kept at the constraint points.
///
/// The penalised problem minimises a strictly convex energy of the pressures, piecewise
/// quadratic with continuous gradient: E(σ) = ½σᵀ(S + T)σ − dᵀσ + (c/2ε̄) Σ_k w_k min([Gσ]_k, 0)²
/// (S the plate's compliance at the pressure nodes, T the soil's, c the foundation constant,
/// w_k the points' weights; equilibrium a linear constraint). A step solves the quadratic whose
/// springs are those of the set P: its answer σᴺ has (S + T)σᴺ − d + Rα = −Σ_P σᴺ/ε̄ = Gᵀhᴺ with
/// hᴺ_k = −(c/ε̄) w_k [k ∈ P] [Gσᴺ]_k. The full step to σᴺ is Newton's step on E; it can
/// overshoot and cycle between sets. The damped step goes to the minimum of E on the segment
/// from the iterate σ to σᴺ: along it the gradient's plate-and-soil part is the blend of the
/// ends' (it is affine in σ and both ends keep equilibrium, so Rα drops out), and the springs'
/// part is local, so the exact line search needs no solve. E falls at every step and the
/// direction is a descent one (the quadratic's Hessian is positive definite), so the damped
/// iteration converges (globally convergent damped semismooth Newton); near the answer the
/// full step is taken and the set settles.
struct Damped {
    /// None on the iterative route, which forms u at the end ([`Backend::displacements`]).
    u: Option<Vec<f64>>,
    sigma: Vec<f64>,
    alpha: Vec<f64>,
    /// Gσ at the iterate.
    gs: Vec<f64>,
    /// The plate-and-soil part of the gradient as Gᵀh: h at the constraint points.
    h: Vec<f64>,
}

impl Damped {
    /// Start at a step's answer, solved with the springs of `set`.
    fn new(
        ops: &Operators,
        set: &[bool],
        epsilon: f64,
        u: Option<&[f64]>,
        sigma: &[f64],
        alpha: &[f64],
    ) -> Damped {
        let gs = ops.g_times(sigma);
        let h = spring_side(ops, set, epsilon, &gs);
        Damped {
            u: u.map(<[f64]>::to_vec),
            sigma: sigma.to_vec(),
            alpha: alpha.to_vec(),
            gs,
            h,
        }
    }

    /// Move to the minimum of the energy on the segment to a step's answer (solved with the
    /// springs of `set`; `gs` its Gσ).
    #[allow(clippy::too_many_arguments)]
    fn advance(
        &mut self,
        ops: &Operators,
        set: &[bool],
        epsilon: f64,
        u: Option<&[f64]>,
        sigma: &[f64],
        alpha: &[f64],
        gs: Vec<f64>,
    ) {
        let h_new = spring_side(ops, set, epsilon, &gs);
        let scale = ops.foundation_constant / epsilon;
        let w = &ops.constraints.weights;
        let t = line_minimum(&self.gs, &gs, &self.h, &h_new, w, scale);
        let blend = |a: &mut Vec<f64>, b: &[f64]| {
            for (x, y) in a.iter_mut().zip(b) {
                *x += t * (y - *x);
            }
        };
        if let (Some(a), Some(b)) = (self.u.as_mut(), u) {
            blend(a, b);
        }
        blend(&mut self.sigma, sigma);
        blend(&mut self.alpha, alpha);
        blend(&mut self.gs, &gs);
        blend(&mut self.h, &h_new);
    }
}

/// hᴺ of a step's answer with Gσ = `gs`, solved with the springs of `set`: −d_k gs_k, d_k the
/// step's own penalty weights c w_k/ε̄ on the set ([`penalty_weights`]).
fn spring_side(ops: &Operators, set: &[bool], epsilon: f64, gs: &[f64]) -> Vec<f64> {
    penalty_weights(ops, set, epsilon)
        .iter()
        .zip(gs)
        .map(|(d, g)| -d * g)
        .collect()
}

/// The t in (0, 1] that minimises the energy on the segment from the iterate (Gσ = `a`,
/// gradient part `h0`) to a step's answer (`b`, `h1`): the root of the energy's slope
/// φ′(t) = eᵀ((1 − t)h0 + t h1) + s Σ_k w_k e_k min(a_k + t e_k, 0), e = b − a, s = c/ε̄, which
/// is continuous, piecewise linear and increasing in t; 1 when the slope is still negative
/// there (the full step).
fn line_minimum(a: &[f64], b: &[f64], h0: &[f64], h1: &[f64], w: &[f64], s: f64) -> f64 {
    let slope = |t: f64| -> f64 {
        let mut total = 0.0;
        for k in 0..a.len() {
            let e = b[k] - a[k];
            total += e * ((1.0 - t) * h0[k] + t * h1[k]) + s * w[k] * e * (a[k] + t * e).min(0.0);
        }
        total
    };
    if slope(1.0) <= 0.0 {
        return 1.0;
    }
    // Bisection on the increasing slope; 60 halvings reach the double's resolution of t.
    let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if slope(mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

/// A settled penalised set is a solution only if the tension left at lifted points is within
/// [`TENSION_TOLERANCE`] of the peak pressure and [`TENSION_FORCE_TOLERANCE`] of the load: O(ε̄)
/// when the penalty is adequate; finite when the springs hold the plate down (an infeasible
/// discrete problem) or are too stiff compared with the plate.
fn tension_check(ops: &Operators, sigma: &[f64], epsilon: f64) -> Status {
    let gs = ops.g_times(sigma);
    let w = &ops.constraints.weights;
    let pull: f64 = gs.iter().zip(w).map(|(g, w)| (-g).max(0.0) * w).sum();
    let push: f64 = gs
        .iter()
        .zip(w)
        .map(|(g, w)| g.max(0.0) * w)
        .sum::<f64>()
        .max(f64::MIN_POSITIVE);
    let peak = gs
        .iter()
        .cloned()
        .fold(0.0_f64, f64::max)
        .max(f64::MIN_POSITIVE);
    let tension = -gs.iter().cloned().fold(0.0_f64, f64::min);
    let ratio = tension / peak;
    let force_ratio = pull / push;
    let moment_ratio = tension_moment(ops, &gs);
    if ratio > TENSION_TOLERANCE
        || force_ratio > TENSION_FORCE_TOLERANCE
        || moment_ratio > TENSION_FORCE_TOLERANCE
    {
        // The tension falls like ε̄: aim a hundred times below the tolerance.
        let shrink = (1e-2 * TENSION_TOLERANCE / ratio)
            .min(1e-2 * TENSION_FORCE_TOLERANCE / force_ratio)
            .min(1e-2 * TENSION_FORCE_TOLERANCE / moment_ratio)
            .min(0.1);
        Status::PenaltyTooWeak {
            tension_ratio: ratio,
            tension_share: force_ratio,
            tension_moment: moment_ratio,
            suggested_penalty: epsilon * shrink,
        }
    } else {
        Status::Converged
    }
}

/// The tension's moment against what the contact can take: along each direction the model
/// keeps (not reduced by symmetry), the moment of the tension at lifted points about the
/// centroid of the compression, over the compressive resultant times the compression's radius
/// of gyration plus one element. It is the shift of the contact's resultant that the tension
/// forces, relative to the contact's size: on a broad contact a small tension share moves it
/// little, but a plate balanced on a few nodes (a point load on a corner) must move load to
/// its neighbours an element away, and a tension share of 1e-3 at the far side, an arm of
/// ~200 elements, moves a fifth of the load (the pressure under the load 14 % off at 200²).
/// Gauss-point weights and nodal areas alike: `gs` are the pressures at the constraint points.
fn tension_moment(ops: &Operators, gs: &[f64]) -> f64 {
    let w = &ops.constraints.weights;
    let points = &ops.constraints.points;
    let mesh = &ops.mesh;
    let mut worst = 0.0_f64;
    for (axis, reduced, h) in [(0, mesh.sym_x, mesh.hx), (1, mesh.sym_y, mesh.hy)] {
        if reduced {
            // The whole plate's tension has no moment about a symmetry line.
            continue;
        }
        let coord = |p: &(f64, f64)| if axis == 0 { p.0 } else { p.1 };
        let (mut push, mut first) = (0.0, 0.0);
        for ((g, w), p) in gs.iter().zip(w).zip(points) {
            if *g > 0.0 {
                push += g * w;
                first += g * w * coord(p);
            }
        }
        if push <= 0.0 {
            continue;
        }
        let centre = first / push;
        let (mut second, mut moment) = (0.0, 0.0);
        for ((g, w), p) in gs.iter().zip(w).zip(points) {
            let arm = coord(p) - centre;
            if *g > 0.0 {
                second += g * w * arm * arm;
            } else {
                moment += g * w * arm;
            }
        }
        let gyration = (second / push).sqrt();
        worst = worst.max(moment.abs() / (push * (gyration + h)));
    }
    worst
}

/// Run the penalty iteration on the shared operators. With a fixed ε̄ this is the paper's
/// iteration. With `auto`, it starts at `epsilon` and, while a stage settles with lifted points
/// that keep more tension than the criteria allow, continues at the smaller ε̄ they suggest
/// from the last penalised set, on the same backend: the symbolic factorisation (and the last
/// numeric factor, for Woodbury updates) is reused across stages.
pub fn solve(ops: &Operators, settings: &PenaltySettings) -> Result<Solution> {
    solve_with(ops, settings, None, &Monitor::NONE)
}

/// [`solve`], from the nodal pressures `start` when given — a neighbouring solve's answer on the
/// same operators: its lifted points (σ at or below 1e-9 of the largest |σ| at a constraint
/// point) are the first penalised set instead of none, so the steps only settle what differs —
/// and watched by `monitor`: a progress event after every step, the cancel flag checked before
/// every step and inside the iterative route's conjugate gradients. The penalised problem is
/// strictly convex, so its answer does not depend on the start.
pub fn solve_with(
    ops: &Operators,
    settings: &PenaltySettings,
    start: Option<&[f64]>,
    monitor: &Monitor<'_>,
) -> Result<Solution> {
    solve_carried(ops, settings, start, None, monitor)
}

/// [`solve_with`], handed the last factor of the solve before it on the same operators by
/// `carry` and leaving its own there (Winkler with nodal constraints; see
/// [`super::spring_factor`]): a pass of a load along a lane solves its next position as an
/// update of its last one's factor. The answer does not depend on the carry.
pub fn solve_carried(
    ops: &Operators,
    settings: &PenaltySettings,
    start: Option<&[f64]>,
    carry: Option<&Carry>,
    monitor: &Monitor<'_>,
) -> Result<Solution> {
    let t0 = Instant::now();
    let n_c = ops.constraints.g.rows();
    let given = start;
    let mut start = match start {
        Some(sigma) if sigma.len() == ops.n_sigma() => {
            let gs = ops.g_times(sigma);
            let peak = gs.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            gs.iter().map(|&v| v <= 1e-9 * peak).collect()
        }
        _ => vec![false; n_c],
    };
    let lifted = start.iter().filter(|&&p| p).count();
    let mut backend = Backend::new(ops, settings.cg, lifted, carry)?;
    if let Some(sigma) = given.filter(|s| s.len() == ops.n_sigma()) {
        backend.warm_start(sigma);
    }
    let t_setup = t0.elapsed().as_secs_f64();
    let rows = cached_constraint_rows(ops);
    let rows = &rows.0;
    let mut history = Vec::new();
    let mut stages = Vec::new();
    let mut t_solves = 0.0;
    let mut epsilon = settings.epsilon;
    let end = loop {
        let from = history.len();
        let end = stage(
            ops,
            &mut backend,
            rows,
            start,
            epsilon,
            settings.max_iterations,
            &mut history,
            &mut t_solves,
            monitor,
        )?;
        stages.push(PenaltyStage {
            epsilon,
            steps: history.len() - from,
            outcome: end.status.kind(),
        });
        // Only a settled set whose lifted points keep tension asks for a smaller ε̄; a cycle
        // or the step cap is reported as it is.
        let next = match end.status {
            Status::PenaltyTooWeak {
                suggested_penalty, ..
            } => Some(suggested_penalty),
            _ => None,
        };
        match next {
            Some(e) if settings.auto && e >= MIN_AUTO_EPSILON && stages.len() < MAX_AUTO_STAGES => {
                epsilon = e;
                start = end.penalised.clone();
            }
            _ => break end,
        }
    };
    if let Some(c) = carry {
        backend.hand_over(c);
    }
    let gap = discrete_gap(ops, &end.u, &end.sigma);
    let cg_iterations = cg_total(&history);
    Ok(Solution {
        method: Method::Penalty(PenaltySettings {
            epsilon,
            ..*settings
        }),
        u: end.u,
        sigma: end.sigma,
        gap,
        rigid: end.alpha,
        status: end.status,
        iterations: history.len(),
        history,
        info: SolveInfo {
            timings: Timings {
                setup: Some(t_setup),
                solves: Some(t_solves),
                total: t0.elapsed().as_secs_f64(),
                ..Timings::default()
            },
            cg_iterations,
            penalty_stages: stages,
            ..SolveInfo::default()
        },
    })
}

/// Conjugate-gradient iterations over the steps of an iterative-route solve (None otherwise).
fn cg_total(history: &[Iteration]) -> Option<usize> {
    history
        .iter()
        .map(|it| it.cg.map(|c| c.iterations))
        .sum::<Option<usize>>()
}

#[cfg(test)]
mod tests {
    use super::line_minimum;

    /// E(σ) = ½σᵀAσ − dᵀσ + (s/2) Σ w_k min(σ_k, 0)² with G = I: its plate-and-soil gradient
    /// part is Aσ − d, which is what a step's answer carries as h.
    fn energy(a: &[[f64; 3]; 3], d: &[f64; 3], w: &[f64], s: f64, x: &[f64]) -> f64 {
        let mut e = 0.0;
        for i in 0..3 {
            for j in 0..3 {
                e += 0.5 * x[i] * a[i][j] * x[j];
            }
            e -= d[i] * x[i] - 0.5 * s * w[i] * x[i].min(0.0).powi(2);
        }
        e
    }

    fn gradient_part(a: &[[f64; 3]; 3], d: &[f64; 3], x: &[f64]) -> Vec<f64> {
        (0..3)
            .map(|i| (0..3).map(|j| a[i][j] * x[j]).sum::<f64>() - d[i])
            .collect()
    }

    /// The damped step's t is the minimum of the energy on the segment, found here by a golden
    /// section search on E itself (which the line search never evaluates: it works from the
    /// slope's identity), on segments where the minimum is inside and where it is the end.
    #[test]
    fn the_line_search_finds_the_energys_minimum_on_the_segment() {
        let a = [[4.0, 1.0, 0.5], [1.0, 3.0, 0.2], [0.5, 0.2, 2.0]];
        let d = [1.0, -2.0, 0.5];
        let w = [1.0, 0.5, 2.0];
        let s = 1e3; // springs a thousand times the soil where the pressure pulls
        let cases: [([f64; 3], [f64; 3]); 4] = [
            ([0.3, 0.1, 0.2], [-1.0, -2.0, 0.4]),
            ([0.5, -0.7, 0.1], [0.2, 0.4, -0.3]),
            ([-0.1, 0.2, 0.3], [0.1, -0.5, 0.3]),
            ([0.0, 0.0, 0.0], [0.01, 0.01, 0.01]),
        ];
        for (x0, x1) in cases {
            let h0 = gradient_part(&a, &d, &x0);
            let h1 = gradient_part(&a, &d, &x1);
            let t = line_minimum(&x0, &x1, &h0, &h1, &w, s);
            let at = |t: f64| -> f64 {
                let x: Vec<f64> = (0..3).map(|i| x0[i] + t * (x1[i] - x0[i])).collect();
                energy(&a, &d, &w, s, &x)
            };
            // Golden section on [0, 1] to 1e-12 in t (E is convex on the segment).
            let g = 0.5 * (5f64.sqrt() - 1.0);
            let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
            while hi - lo > 1e-12 {
                let (c, e) = (hi - g * (hi - lo), lo + g * (hi - lo));
                if at(c) < at(e) {
                    hi = e;
                } else {
                    lo = c;
                }
            }
            let reference = 0.5 * (lo + hi);
            // The bisection ends within 2⁻⁶⁰ of the slope's root. The golden section compares
            // energies, whose round-off (1e-16 of E) hides differences in t below
            // √(2e-16 |E| / E'') ~ 1e-8 at these curvatures: 1e-7 is its resolution with a margin.
            assert!(
                (t - reference).abs() < 1e-7,
                "t = {t}, golden section {reference} on {x0:?} → {x1:?}"
            );
            assert!(at(t) <= at(0.0) + 1e-15, "the energy rose");
        }
    }
}
