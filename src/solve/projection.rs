//! The Euclidean projection onto the feasible set {σ ≥ 0, Cᵀσ = b}: where both phases start,
//! and what takes a face solve's specks of tension away.

use super::linalg::{dot, SmallSpd};

/// The Euclidean projection of `y` onto {σ ≥ 0, Cᵀσ = b}: σ = max(0, y + Cλ), with λ the
/// minimiser of the convex ψ(λ) = ½|max(0, y + Cλ)|² − bᵀλ (whose gradient is Cᵀσ − b), by
/// Newton's method with a backtracking line search. None when no λ balances b (no
/// non-negative σ is in equilibrium).
pub fn project(y: &[f64], c: &[Vec<f64>], b: &[f64]) -> Option<Vec<f64>> {
    let m = c.len();
    let sigma_of = |lam: &[f64]| -> Vec<f64> {
        (0..y.len())
            .map(|i| {
                let v = y[i] + (0..m).map(|a| c[a][i] * lam[a]).sum::<f64>();
                v.max(0.0)
            })
            .collect()
    };
    let psi = |sigma: &[f64], lam: &[f64]| 0.5 * dot(sigma, sigma) - dot(b, lam);
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
    let mut sigma = sigma_of(&lambda);
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
        let f0 = psi(&sigma, &lambda);
        let slope = dot(&dir, &grad);
        let mut t = 1.0;
        let mut accepted = false;
        for _ in 0..60 {
            let trial: Vec<f64> = lambda.iter().zip(&dir).map(|(l, d)| l + t * d).collect();
            let s_trial = sigma_of(&trial);
            if psi(&s_trial, &trial) <= f0 + 1e-4 * t * slope {
                lambda = trial;
                sigma = s_trial;
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
    // ψ unbounded below (b out of reach), or a balance exact to round-off.
    (rel <= 1e-10).then_some(sigma)
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
}
