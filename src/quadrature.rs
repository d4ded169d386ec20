//! Gauss–Legendre quadrature on [−1, 1].
//!
//! The rules are computed by Newton iteration on the Legendre recurrence, so any order is
//! available; element matrices use order 2 (exact for the bilinear MITC4 integrands) and the
//! half-space operator uses higher orders for its near-singular element pairs.

/// A Gauss–Legendre rule: points and weights on [−1, 1].
#[derive(Debug, Clone)]
pub struct GaussRule {
    /// Abscissae in (−1, 1), ascending.
    pub points: Vec<f64>,
    /// Weights, summing to 2.
    pub weights: Vec<f64>,
}

impl GaussRule {
    /// The `n`-point rule (n ≥ 1). Exact for polynomials of degree 2n − 1.
    pub fn new(n: usize) -> Self {
        let n = n.max(1);
        let mut points = vec![0.0; n];
        let mut weights = vec![0.0; n];
        for i in 0..n.div_ceil(2) {
            // Chebyshev-like initial guess, then Newton on P_n.
            let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                let (p, d) = legendre(n, x);
                dp = d;
                let dx = p / d;
                x -= dx;
                if dx.abs() < 1e-16 {
                    break;
                }
            }
            let (_, d) = legendre(n, x);
            if d.is_finite() {
                dp = d;
            }
            let w = 2.0 / ((1.0 - x * x) * dp * dp);
            points[i] = -x;
            points[n - 1 - i] = x;
            weights[i] = w;
            weights[n - 1 - i] = w;
        }
        if n % 2 == 1 {
            points[n / 2] = 0.0;
        }
        Self { points, weights }
    }

    /// Points and weights mapped to the interval [a, b].
    pub fn on_interval(&self, a: f64, b: f64) -> impl Iterator<Item = (f64, f64)> + '_ {
        let half = 0.5 * (b - a);
        let mid = 0.5 * (a + b);
        self.points
            .iter()
            .zip(&self.weights)
            .map(move |(&p, &w)| (mid + half * p, half * w))
    }
}

/// Legendre polynomial P_n(x) and its derivative.
fn legendre(n: usize, x: f64) -> (f64, f64) {
    let mut p0 = 1.0;
    let mut p1 = x;
    if n == 0 {
        return (1.0, 0.0);
    }
    for k in 2..=n {
        let kf = k as f64;
        let p2 = ((2.0 * kf - 1.0) * x * p1 - (kf - 1.0) * p0) / kf;
        p0 = p1;
        p1 = p2;
    }
    let d = n as f64 * (x * p1 - p0) / (x * x - 1.0);
    (p1, d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_rules_integrate_polynomials_exactly() {
        for n in 1..=16 {
            let rule = GaussRule::new(n);
            let total: f64 = rule.weights.iter().sum();
            assert!(
                (total - 2.0).abs() < 1e-13,
                "weights of the {n}-point rule sum to {total}"
            );
            // ∫_{-1}^{1} x^k dx = 2/(k+1) for even k, 0 for odd k; exact up to k = 2n − 1.
            for k in 0..(2 * n) {
                let q: f64 = rule
                    .points
                    .iter()
                    .zip(&rule.weights)
                    .map(|(x, w)| w * x.powi(k as i32))
                    .sum();
                let exact = if k % 2 == 0 {
                    2.0 / (k as f64 + 1.0)
                } else {
                    0.0
                };
                assert!(
                    (q - exact).abs() < 1e-12,
                    "{n}-point rule on x^{k}: {q} vs {exact}"
                );
            }
        }
    }
}
