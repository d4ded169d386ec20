//! Phase 1: the primal–dual active-set iteration (semismooth Newton on the natural residual),
//! the penalty iteration with ε̄ = 0.

use super::point::{gap_scale, kkt, reduced_gradient, Point};
use super::run::{infeasible, End, Run};
use crate::error::Result;
use crate::operators::Operators;
use crate::solve::iterative::IterativeSchur;
use crate::solve::projection::{project, project_on_face};
use crate::solve::solution::Status;

impl Run<'_> {
    /// The primal–dual active-set (semismooth Newton) iteration on sets: hold the lifted set
    /// at zero, solve the face, lift the free points whose pressure came out negative and
    /// release the held points whose gap came out negative; stop when nothing moves after a
    /// tight solve. It is the penalty iteration with ε̄ = 0 and as fast, but it can cycle on a
    /// matrix that is not an M-matrix: a set met before hands over to [`Self::feasible`]
    /// (`Err` with the last face's pressures, where it starts).
    pub(super) fn primal_dual(
        &mut self,
        sys: &mut IterativeSchur,
        ops: &Operators,
        warm: Option<&[f64]>,
    ) -> Result<std::result::Result<End, Vec<f64>>> {
        let n = ops.n_sigma();
        let tol = self.settings.tolerance;
        let mut seen: Vec<Vec<bool>> = Vec::new();
        // The feasible point nearest σ = 0 (pressures linear over the points it keeps, as
        // under a rigid plate): the solution itself when it is the only feasible point (a
        // plate balanced on one node), and where the first set comes from — usually nothing
        // held, the bonded problem.
        let origin = project(&vec![0.0; n], &sys.c, &sys.rf).ok_or_else(infeasible)?;
        let p0 = Point::new(sys, ops, origin);
        let (g0, alpha0) = reduced_gradient(sys, &p0);
        let k0 = kkt(sys, &p0, &g0, &alpha0);
        if k0.natural <= tol {
            return Ok(Ok((p0, alpha0, k0, Status::Converged)));
        }
        // A start carried over from elsewhere (a coarser grid's answer, a neighbour's): its
        // zeros are its lifted set, the first held set, and it is made feasible on that face —
        // projected on the whole feasible set, the shift to equilibrium would bring the held
        // points back into contact. Where the free points cannot balance the load, the
        // whole feasible set, and its zeros whose gap does not close are the first set.
        // (Checked against n: a start of another grid is ignored.)
        let given = warm.filter(|w| w.len() == n).and_then(|w| {
            let zeros: Vec<bool> = w.iter().map(|&x| x <= 0.0).collect();
            match project_on_face(w, &zeros, &sys.c, &sys.rf) {
                Some(x) => Some((x, Some(zeros))),
                None => project(w, &sys.c, &sys.rf).map(|x| (x, None)),
            }
        });
        let (p0, g0, alpha0, held) = match given {
            Some((x, zeros)) => {
                let p = Point::new(sys, ops, x);
                let (g, alpha) = reduced_gradient(sys, &p);
                (p, g, alpha, zeros)
            }
            None => (p0, g0, alpha0, None),
        };
        let g_s = gap_scale(sys, &p0, &alpha0);
        let mut held: Vec<bool> = held.unwrap_or_else(|| {
            (0..n)
                .map(|i| p0.sigma[i] == 0.0 && g0[i] >= -tol * g_s)
                .collect()
        });
        let mut start = p0.sigma;
        // The face solves' tolerance: loose while the sets move (they only have to be found),
        // 100× tighter each time the sets wander, tight when a set repeats: only a tight
        // solve can confirm a set. With the exact Winkler preconditioner a
        // tight solve costs a CG iteration or two: tight from the start.
        let cg = self.settings.cg;
        let tight_tol = cg.tolerance;
        let mut level = if sys.exact() {
            tight_tol
        } else {
            sys.loose_tolerance()
        };
        // (fewest points changed by a step so far, steps since).
        let mut wander = (usize::MAX, 0usize);
        while self.iterations < self.settings.max_iterations {
            let face = self.face(sys, ops, &held, &start, level)?;
            let tight = face.cg.residual <= tight_tol;
            // A loose solve that the warm start already satisfied has not moved σ: the sets it
            // suggests are stale.
            let stale = !tight && face.cg.iterations == 0;
            // The gap at σ* with the face's multiplier.
            let mut g: Vec<f64> = face
                .s_sigma
                .iter()
                .zip(&sys.h)
                .map(|(a, b)| a - b)
                .collect();
            for (c, a) in sys.c.iter().zip(&face.alpha) {
                for (gi, ci) in g.iter_mut().zip(c) {
                    *gi -= a * ci;
                }
            }
            let s_max = face.sigma.iter().cloned().fold(0.0_f64, f64::max);
            let point = Point::with_products(
                sys,
                face.sigma.clone(),
                face.t_sigma.clone(),
                face.s_sigma.clone(),
            );
            let g_s = gap_scale(sys, &point, &face.alpha);
            let next: Vec<bool> = (0..n)
                .map(|i| {
                    if held[i] {
                        g[i] >= -tol * g_s
                    } else {
                        face.sigma[i] < -tol * s_max
                    }
                })
                .collect();
            let min_free = (0..n)
                .filter(|&i| !held[i])
                .map(|i| face.sigma[i])
                .fold(f64::INFINITY, f64::min);
            self.record(&held, &next, min_free, face.cg);
            if next.iter().all(|&b| b) {
                return Err(infeasible());
            }
            if !tight && (next == held || stale || seen.contains(&next)) {
                // A set that repeats is confirmed or refuted by a tight solve; sets that
                // wander (a solve that could not move, a set met before) by a tighter one.
                level = if next == held {
                    tight_tol
                } else {
                    (level * 1e-2).max(tight_tol)
                };
                start = face.sigma;
                continue;
            }
            if next == held {
                // Settled: σ* with its specks of tension projected away.
                let x = project(&face.sigma, &sys.c, &sys.rf).ok_or_else(infeasible)?;
                let mut p = if x == face.sigma {
                    point
                } else {
                    Point::new(sys, ops, x)
                };
                p.alpha = Some(face.alpha);
                let (g, alpha) = reduced_gradient(sys, &p);
                let k = kkt(sys, &p, &g, &alpha);
                if k.natural <= tol {
                    return Ok(Ok((p, alpha, k, Status::Converged)));
                }
                return Ok(Err(p.sigma));
            }
            if seen.contains(&next) {
                // A cycle: hand over to the monotone method.
                return Ok(Err(face.sigma));
            }
            // Sets that wander without repeating (a soil whose gaps at the contact edge are
            // below what a loose solve resolves): 100× tighter when five steps have not
            // changed fewer points than the best so far; and at the tight tolerance, hand
            // over to the monotone method after twenty such steps.
            let changes = next.iter().zip(&held).filter(|(a, b)| a != b).count();
            if changes < wander.0 {
                wander = (changes, 0);
            } else {
                wander.1 += 1;
            }
            if wander.1 >= 5 && level > tight_tol {
                level = (level * 1e-2).max(tight_tol);
                wander = (changes, 0);
            } else if wander.1 >= 20 {
                return Ok(Err(face.sigma));
            }
            seen.push(held);
            held = next;
            start = face.sigma;
        }
        Ok(Err(start))
    }
}
