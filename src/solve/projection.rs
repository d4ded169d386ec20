//! The Euclidean projection onto the feasible set {σ ≥ 0, Cᵀσ = b}: where both phases start,
//! and what takes a face solve's specks of tension away.

use super::linalg::{dot, SmallSpd};

/// The Euclidean projection of `y` onto {σ ≥ 0, Cᵀσ = b}: σ = max(0, y + Cλ), with λ the
/// minimiser of the convex ψ(λ) = ½|max(0, y + Cλ)|² − bᵀλ (whose gradient is Cᵀσ − b), by
/// Newton's method with a backtracking line search. None when no λ balances b (no
/// non-negative σ is in equilibrium).
pub fn project(y: &[f64], c: &[Vec<f64>], b: &[f64]) -> Option<Vec<f64>> {
    let m = c.len();
    // C d over the points: how the unclipped values y + Cλ move along a step d.
    let along = |dir: &[f64]| -> Vec<f64> {
        (0..y.len())
            .map(|i| (0..m).map(|a| c[a][i] * dir[a]).sum::<f64>())
            .collect()
    };
    let residual = |sigma: &[f64]| -> (Vec<f64>, f64) {
        let grad: Vec<f64> = (0..m).map(|a| dot(&c[a], sigma) - b[a]).collect();
        // Relative to the round-off of Cᵀσ: n terms of size |c||σ|, and to b.
        let scale = c
            .iter()
            .map(|col| {
                col.iter()
                    .zip(sigma)
                    .map(|(ci, si)| (ci * si).abs())
                    .sum::<f64>()
            })
            .fold(0.0, f64::max)
            + b.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        let rel = grad.iter().fold(0.0_f64, |a, v| a.max(v.abs())) / scale.max(f64::MIN_POSITIVE);
        (grad, rel)
    };
    // Start at λ = 0: y itself when it is feasible, as a face solve's σ* is up to specks of
    // tension, so that points at zero stay exactly at zero. Where y has no positive entry
    // (y = 0) Newton would have no curvature there: start from the unconstrained projection
    // onto Cᵀσ = b instead, σ = y + Cλ₀ with CᵀCλ₀ = b − Cᵀy.
    let mut lambda = vec![0.0; m];
    if y.iter().all(|&v| v <= 0.0) {
        let ctc = SmallSpd::new(m, |a, bb| dot(&c[a], &c[bb]));
        let shortfall: Vec<f64> = (0..m).map(|a| b[a] - dot(&c[a], y)).collect();
        lambda = ctc.solve(&shortfall);
    }
    // u = y + Cλ, unclipped; σ = max(0, u).
    let unclipped =
        |lam: &[f64]| -> Vec<f64> { along(lam).iter().zip(y).map(|(v, yi)| yi + v).collect() };
    let mut u = unclipped(&lambda);
    let mut sigma: Vec<f64> = u.iter().map(|v| v.max(0.0)).collect();
    let (mut grad, mut rel) = residual(&sigma);
    for _ in 0..1000 {
        if rel <= 1e-13 {
            break;
        }
        let before = rel;
        // Newton on ψ: Hessian Cᵀ diag(y + Cλ > 0) C; where it is singular (no point
        // positive along some combination) the pseudo-inverse and a gradient step take over.
        let pos: Vec<usize> = (0..y.len()).filter(|&i| sigma[i] > 0.0).collect();
        let hess = SmallSpd::new(m, |a, bb| pos.iter().map(|&i| c[a][i] * c[bb][i]).sum());
        let mut dir: Vec<f64> = hess.solve(&grad).iter().map(|v| -v).collect();
        if hess.rank() < m || dot(&dir, &grad) >= 0.0 {
            // Steepest descent scaled by the columns' size.
            let cc: f64 = (0..m).map(|a| dot(&c[a], &c[a])).sum::<f64>().max(1e-300);
            dir = grad.iter().map(|g| -g / cc).collect();
        }
        let slope = dot(&dir, &grad);
        let v = along(&dir);
        let mut t = 1.0;
        let mut accepted = false;
        for _ in 0..60 {
            // Armijo on the decrease itself: ψ(λ + t d) − ψ(λ) = t gᵀd + Σ_i κ_i with
            // κ_i = φ(u_i + t v_i) − φ(u_i) − t v_i φ'(u_i) ≥ 0, φ(s) = ½ max(0, s)², each term
            // formed where it arises. Never as ψ(trial) − ψ(λ): ψ = ½|σ|² − bᵀλ subtracts two
            // numbers near 2|ψ| whose round-off (n ε |ψ|) exceeds the decrease of the last Newton
            // steps (∝ rel² |ψ|), so a step from rel ≈ 1e-8 was kept or refused by round-off and
            // a refusal ended the loop short of 1e-10: a feasible b reported as unreachable.
            let curvature: f64 = u
                .iter()
                .zip(&v)
                .map(|(&ui, &vi)| {
                    let (tv, ut) = (t * vi, ui + t * vi);
                    match (ui > 0.0, ut > 0.0) {
                        (true, true) => 0.5 * tv * tv,
                        (true, false) => -ui * (0.5 * ui + tv),
                        (false, true) => 0.5 * ut * ut,
                        (false, false) => 0.0,
                    }
                })
                .sum();
            if t * slope + curvature <= 1e-4 * t * slope {
                for (l, d) in lambda.iter_mut().zip(&dir) {
                    *l += t * d;
                }
                u = unclipped(&lambda);
                sigma = u.iter().map(|v| v.max(0.0)).collect();
                accepted = true;
                break;
            }
            t *= 0.5;
        }
        (grad, rel) = residual(&sigma);
        // No decrease of ψ left to find, or a residual at round-off that no longer falls
        // (the sums Cᵀσ over many points carry ~1e-13 of their size): done.
        if !accepted || (rel <= 1e-11 && rel > 0.5 * before) {
            break;
        }
    }
    // ψ unbounded below (b out of reach), or a balance exact to round-off. None is not a
    // proof that b is out of reach (b on the cone's boundary, where the infimum of ψ is not
    // attained, also ends here): callers that report infeasibility ask [`cone_gap`].
    (rel <= 1e-10).then_some(sigma)
}

/// How far b lies from the cone {Cᵀσ : σ ≥ 0}, relative to |b|, by Lawson and Hanson's
/// non-negative least squares on the m × n system Cᵀσ = b (m the columns, a few per panel;
/// at most m points positive at a time). Zero (to round-off) exactly when some σ ≥ 0 balances
/// b, on the cone's boundary included; otherwise its residual r = b − Cᵀσ is a Farkas
/// certificate: Σ_a r_a c_a ≤ 0 at every point while bᵀr = |r|² > 0 (a rigid motion that
/// lifts every point off the soil and along which the loads do work).
pub fn cone_gap(c: &[Vec<f64>], b: &[f64]) -> f64 {
    let (m, n) = (c.len(), c.first().map_or(0, Vec::len));
    let bn = dot(b, b).sqrt();
    if bn == 0.0 {
        return 0.0;
    }
    let cmax = c.iter().flatten().fold(0.0_f64, |a, v| a.max(v.abs()));
    let mut x = vec![0.0; n];
    let mut passive: Vec<usize> = Vec::new();
    let residual = |x: &[f64]| -> Vec<f64> { (0..m).map(|a| b[a] - dot(&c[a], x)).collect() };
    let mut r = b.to_vec();
    for _ in 0..(20 * m + 20) {
        // The point whose column most reduces |r| (the dual w = C r, largest) joins.
        let best = (0..n)
            .filter(|i| !passive.contains(i))
            .map(|i| (i, (0..m).map(|a| c[a][i] * r[a]).sum::<f64>()))
            .max_by(|p, q| p.1.total_cmp(&q.1));
        match best {
            Some((i, w)) if w > 1e-13 * cmax * bn => passive.push(i),
            _ => break,
        }
        loop {
            // Unconstrained least squares on the passive points (pseudo-inverse: columns
            // may be dependent), then back along the segment until the first one hits zero.
            let k = passive.len();
            let gram = super::linalg::SmallSpd::new(k, |p, q| {
                (0..m).map(|a| c[a][passive[p]] * c[a][passive[q]]).sum()
            });
            let rhs: Vec<f64> = (0..k)
                .map(|p| (0..m).map(|a| c[a][passive[p]] * b[a]).sum())
                .collect();
            let z = gram.solve(&rhs);
            if z.iter().all(|&v| v > 0.0) {
                for (p, &i) in passive.iter().enumerate() {
                    x[i] = z[p];
                }
                break;
            }
            let (hit, step) = passive
                .iter()
                .zip(&z)
                .filter(|(_, &zp)| zp <= 0.0)
                .map(|(&i, &zp)| (i, x[i] / (x[i] - zp)))
                .fold(
                    (usize::MAX, f64::INFINITY),
                    |a, q| if q.1 < a.1 { q } else { a },
                );
            if hit == usize::MAX {
                break; // z not finite: leave the gap as it stands
            }
            for (p, &i) in passive.iter().enumerate() {
                x[i] += step * (z[p] - x[i]);
            }
            x[hit] = 0.0; // the first to reach zero leaves, round-off or not
            passive.retain(|&i| x[i] > 0.0);
            for i in 0..n {
                if !passive.contains(&i) {
                    x[i] = 0.0;
                }
            }
            if passive.is_empty() {
                break;
            }
        }
        r = residual(&x);
    }
    dot(&r, &r).sqrt() / bn
}

/// The projection of `y` onto the face {σ ≥ 0, σ_i = 0 where `held`, Cᵀσ = b}: the points held
/// at zero stay there and only the others move. None when the free points cannot balance b.
pub fn project_on_face(y: &[f64], held: &[bool], c: &[Vec<f64>], b: &[f64]) -> Option<Vec<f64>> {
    let free: Vec<usize> = (0..y.len()).filter(|&i| !held[i]).collect();
    let sub = |v: &[f64]| -> Vec<f64> { free.iter().map(|&i| v[i]).collect() };
    let x = project(&sub(y), &c.iter().map(|r| sub(r)).collect::<Vec<_>>(), b)?;
    let mut out = vec![0.0; y.len()];
    for (&i, v) in free.iter().zip(x) {
        out[i] = v;
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The projection is the nearest point of {σ ≥ 0, Cᵀσ = b}: it is feasible, and y − σ is
    /// a normal of the set there (y − σ = −Cλ − ν with ν ≥ 0 zero where σ > 0).
    #[test]
    fn projection_is_feasible_and_its_residual_is_normal() {
        let n = 40;
        let x: Vec<f64> = (0..n).map(|i| i as f64 / (n - 1) as f64 - 0.5).collect();
        let c = vec![vec![1.0; n], x.clone()];
        let b = vec![10.0, 1.5];
        let y: Vec<f64> = (0..n).map(|i| ((i * 7 % 11) as f64) - 5.0).collect();
        let s = project(&y, &c, &b).expect("feasible");
        assert!(s.iter().all(|&v| v >= 0.0), "σ ≥ 0");
        for a in 0..2 {
            let r = dot(&c[a], &s) - b[a];
            assert!(r.abs() < 1e-12, "equality {a}: residual {r}");
        }
        // σ − y = Cλ on the support (some λ), and σ − y ≥ Cλ where σ = 0: the normal cone.
        let support: Vec<usize> = (0..n).filter(|&i| s[i] > 0.0).collect();
        assert!(support.len() >= 2, "support {support:?}");
        let (i, j) = (support[0], support[support.len() - 1]);
        let det = c[0][i] * c[1][j] - c[0][j] * c[1][i];
        let l0 = ((s[i] - y[i]) * c[1][j] - (s[j] - y[j]) * c[1][i]) / det;
        let l1 = (c[0][i] * (s[j] - y[j]) - c[0][j] * (s[i] - y[i])) / det;
        for k in 0..n {
            let v = y[k] + l0 * c[0][k] + l1 * c[1][k];
            // σ = max(0, y + Cλ) exactly (the optimality condition of the projection).
            assert!(
                (s[k] - v.max(0.0)).abs() < 1e-10,
                "node {k}: {} vs {}",
                s[k],
                v
            );
        }
    }

    /// A balance no non-negative σ can give (the resultant outside the points' hull) is
    /// reported as None.
    #[test]
    fn projection_reports_an_unreachable_balance() {
        let c = vec![vec![1.0; 3], vec![-1.0, 0.0, 1.0]];
        let b = vec![1.0, 2.0]; // resultant at x = 2, outside [−1, 1]
        assert!(project(&[0.0; 3], &c, &b).is_none());
    }

    /// Lumped areas and the columns (1, x, y)·area of a 61 × 17-node panel, x ∈ [−1, 1],
    /// y ∈ [−0.27, 0.27]: a panel's rigid modes as the feasibility check forms them.
    fn panel() -> (Vec<[f64; 2]>, Vec<f64>, Vec<Vec<f64>>) {
        let (nx, ny) = (60, 16);
        let mut points = Vec::new();
        let mut area = Vec::new();
        for j in 0..=ny {
            for i in 0..=nx {
                points.push([
                    -1.0 + 2.0 * i as f64 / nx as f64,
                    -0.27 + 0.54 * j as f64 / ny as f64,
                ]);
                let edge = |k: usize, n: usize| if k == 0 || k == n { 0.5 } else { 1.0 };
                area.push(edge(i, nx) * edge(j, ny) / (nx * ny) as f64);
            }
        }
        let c = vec![
            area.clone(),
            area.iter().zip(&points).map(|(a, p)| a * p[0]).collect(),
            area.iter().zip(&points).map(|(a, p)| a * p[1]).collect(),
        ];
        (points, area, c)
    }

    /// Balances that a pressure σ* ≥ 0 gives by construction — a linear pressure clipped at
    /// zero near one end (resultant close to the edge, the start clipping a few points), at
    /// load scales from 1 to 1e14 — are all found (issue 32: a tandem at the end of a panel
    /// was refused because the line search compared ψ(trial) with ψ(λ), two numbers near
    /// 3e14 whose round-off exceeded the last Newton step's decrease; a pure-Python replica of
    /// the old search refused 6 of these 1000). And `cone_gap` finds them reachable.
    #[test]
    fn balances_near_the_edge_are_found_at_every_load_scale() {
        let (points, area, c) = panel();
        // A small linear congruential generator: the cases are fixed, not drawn anew per run.
        let mut state: u64 = 11;
        let mut uniform = |lo: f64, hi: f64| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            lo + (hi - lo) * ((state >> 11) as f64 / (1u64 << 53) as f64)
        };
        let mut missed = Vec::new();
        for case in 0..1000 {
            let kappa = uniform(1.0, 1.08);
            let eta = uniform(-0.3, 0.3);
            let scale = 10f64.powf(uniform(0.0, 14.0));
            let sigma: Vec<f64> = area
                .iter()
                .zip(&points)
                .map(|(a, p)| a * (1.0 + kappa * p[0] + eta * p[1]).max(0.0))
                .collect();
            let b: Vec<f64> = c.iter().map(|col| scale * dot(col, &sigma)).collect();
            if project(&vec![0.0; area.len()], &c, &b).is_none() {
                missed.push((case, kappa, scale));
            }
            // Reachable by construction: the gap is round-off (a relative 1e-12 allows the
            // sums of 1 037 terms).
            let gap = cone_gap(&c, &b);
            assert!(
                gap < 1e-12,
                "case {case}: cone gap {gap:e} of a reachable balance"
            );
        }
        assert!(
            missed.is_empty(),
            "reachable balances reported unreachable: {missed:?}"
        );
    }

    /// A resultant beyond the panel's end, or a pull, is out of reach: the projection says
    /// None and `cone_gap` measures a distance far above round-off (its residual is a Farkas
    /// certificate).
    #[test]
    fn the_cone_gap_proves_an_unreachable_balance() {
        let (_, _, c) = panel();
        let total: f64 = c[0].iter().sum();
        for (what, b) in [
            ("resultant at x = 1.2", vec![total, 1.2 * total, 0.0]),
            ("resultant at y = 0.5", vec![total, 0.0, 0.5 * total]),
            ("a pull", vec![-total, 0.0, 0.0]),
        ] {
            assert!(project(&vec![0.0; c[0].len()], &c, &b).is_none(), "{what}");
            let gap = cone_gap(&c, &b);
            assert!(gap > 1e-3, "{what}: cone gap {gap:e}");
        }
        // On the very edge (all load on the end nodes, x = 1): reachable, gap round-off.
        let b = vec![total, total, 0.0];
        let gap = cone_gap(&c, &b);
        assert!(gap < 1e-12, "resultant on the edge: cone gap {gap:e}");
    }
}
