//! Elastic half-space (Boussinesq): w_s(x) = c ∫ r(x') / |x − x'| dA', c = (1 − ν_s²)/(π E_s)
//! (paper eq. 2.6).
//!
//! Galerkin form T_ij = c ∫∫ f_i(x) f_j(x') / |x − x'| dA' dA. This file holds the element-pair
//! integrals of the 1/ρ kernel in closed form ([`pair_block`]); the per-offset table, the
//! mirror images and the dense T are shared by every kernel ([`super::pairs`]).
//!
//! The kernel is weakly singular. For element pairs closer than [`NEAR_FIELD`] element sizes the
//! inner integral is done in closed form (potentials of 1, u, v and uv over a rectangle) and
//! the outer one by Gauss quadrature on sub-cells; the closed-form potential is continuous with
//! logarithmic derivatives only on the element edges, where Gauss points never fall. Farther
//! pairs use product Gauss rules whose order falls with distance.

use crate::plate::{shape, NODE_ETA, NODE_XI};
use crate::quadrature::GaussRule;

/// Element pairs whose centres are closer than this many (larger) element sizes are integrated
/// semi-analytically.
pub const NEAR_FIELD: f64 = 2.5;

/// ∫∫_rect g(u, v) / √(u² + v²) du dv for g = 1, u, v, uv, with the rectangle given relative to
/// the field point: u ∈ [u1, u2], v ∈ [v1, v2].
pub fn rectangle_potentials(u1: f64, u2: f64, v1: f64, v2: f64) -> [f64; 4] {
    // Antiderivatives F with ∂²F/∂u∂v = g/R. Terms that depend on u alone or on v alone cancel
    // in the corner sum, which is why ln(v + R) may be replaced by asinh(v/|u|).
    fn ash(num: f64, den: f64) -> f64 {
        if den == 0.0 {
            0.0
        } else {
            (num / den.abs()).asinh()
        }
    }
    fn f(u: f64, v: f64) -> [f64; 4] {
        let r = (u * u + v * v).sqrt();
        let a = if u == 0.0 { 0.0 } else { u * ash(v, u) };
        let b = if v == 0.0 { 0.0 } else { v * ash(u, v) };
        [
            a + b,
            0.5 * (v * r + if u == 0.0 { 0.0 } else { u * u * ash(v, u) }),
            0.5 * (u * r + if v == 0.0 { 0.0 } else { v * v * ash(u, v) }),
            r * r * r / 3.0,
        ]
    }
    let f22 = f(u2, v2);
    let f12 = f(u1, v2);
    let f21 = f(u2, v1);
    let f11 = f(u1, v1);
    let mut out = [0.0; 4];
    for k in 0..4 {
        out[k] = f22[k] - f12[k] - f21[k] + f11[k];
    }
    out
}

/// ∫_rect N_b(x') / |x − x'| dA' for the four bilinear functions of the rectangle
/// [xa, xb] × [ya, yb], at the field point (x, y).
pub fn element_potentials(x: f64, y: f64, xa: f64, xb: f64, ya: f64, yb: f64) -> [f64; 4] {
    let j = rectangle_potentials(xa - x, xb - x, ya - y, yb - y);
    let hx2 = 0.5 * (xb - xa);
    let hy2 = 0.5 * (yb - ya);
    let xc = 0.5 * (xa + xb);
    let yc = 0.5 * (ya + yb);
    let mut out = [0.0; 4];
    for b in 0..4 {
        // N_b = ¼ (A + B u)(C + D v) with u = x' − x, v = y' − y.
        let a0 = 1.0 + NODE_XI[b] * (x - xc) / hx2;
        let a1 = NODE_XI[b] / hx2;
        let c0 = 1.0 + NODE_ETA[b] * (y - yc) / hy2;
        let c1 = NODE_ETA[b] / hy2;
        out[b] = 0.25 * (a0 * c0 * j[0] + a1 * c0 * j[1] + a0 * c1 * j[2] + a1 * c1 * j[3]);
    }
    out
}

/// Block I[a][b] = ∫_{e0} ∫_{e1} N_a(x) N_b(x') / |x − x'| dA' dA for e0 = [0, hx] × [0, hy] and
/// e1 offset by (di, dj) elements (di, dj ≥ 0).
pub fn pair_block(di: usize, dj: usize, hx: f64, hy: f64) -> [[f64; 4]; 4] {
    let h = hx.max(hy);
    let dist = ((di as f64 * hx).powi(2) + (dj as f64 * hy).powi(2)).sqrt() / h;
    let (xa, xb) = (di as f64 * hx, (di as f64 + 1.0) * hx);
    let (ya, yb) = (dj as f64 * hy, (dj as f64 + 1.0) * hy);
    let mut out = [[0.0; 4]; 4];
    if dist < NEAR_FIELD {
        // Semi-analytic: closed-form inner integral, outer Gauss on 4 × 4 sub-cells (more
        // along the longer side of a stretched element).
        let rule = GaussRule::new(8);
        let sx = (4.0 * (hx / hy).max(1.0)).ceil() as usize;
        let sy = (4.0 * (hy / hx).max(1.0)).ceil() as usize;
        for cx in 0..sx {
            let x_lo = hx * cx as f64 / sx as f64;
            let x_hi = hx * (cx + 1) as f64 / sx as f64;
            for (x, wx) in rule.on_interval(x_lo, x_hi) {
                for cy in 0..sy {
                    let y_lo = hy * cy as f64 / sy as f64;
                    let y_hi = hy * (cy + 1) as f64 / sy as f64;
                    for (y, wy) in rule.on_interval(y_lo, y_hi) {
                        let phi = element_potentials(x, y, xa, xb, ya, yb);
                        let n = shape(2.0 * x / hx - 1.0, 2.0 * y / hy - 1.0);
                        for a in 0..4 {
                            for b in 0..4 {
                                out[a][b] += wx * wy * n[a] * phi[b];
                            }
                        }
                    }
                }
            }
        }
    } else {
        let order = if dist < 5.0 {
            5
        } else if dist < 10.0 {
            3
        } else {
            2
        };
        let rule = GaussRule::new(order);
        // Points and shape values on e0 and e1.
        let mut p0 = Vec::with_capacity(order * order);
        let mut p1 = Vec::with_capacity(order * order);
        for (i, (&xi, &wx)) in rule.points.iter().zip(&rule.weights).enumerate() {
            let _ = i;
            for (&eta, &wy) in rule.points.iter().zip(&rule.weights) {
                let n = shape(xi, eta);
                let w = wx * wy * 0.25 * hx * hy;
                let x = 0.5 * (xi + 1.0) * hx;
                let y = 0.5 * (eta + 1.0) * hy;
                p0.push((x, y, w, n));
                p1.push((x + xa, y + ya, w, n));
            }
        }
        for &(x0, y0, w0, n0) in &p0 {
            let mut acc = [0.0; 4];
            for &(x1, y1, w1, n1) in &p1 {
                let k = w1 / ((x1 - x0).powi(2) + (y1 - y0).powi(2)).sqrt();
                for b in 0..4 {
                    acc[b] += k * n1[b];
                }
            }
            for a in 0..4 {
                for b in 0..4 {
                    out[a][b] += w0 * n0[a] * acc[b];
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Closed form of ∫∫ 1/R over a unit square seen from its corner: 2 ln(1 + √2).
    #[test]
    fn potential_of_a_square_at_its_corner() {
        let j = rectangle_potentials(0.0, 1.0, 0.0, 1.0);
        let exact = 2.0 * (1.0 + 2f64.sqrt()).ln();
        assert!((j[0] - exact).abs() < 1e-14, "{} vs {exact}", j[0]);
        // ∫∫ u/R over the unit square from its corner: ∫₀¹ (√(1 + v²) − v) dv = ½[√2 + ln(1 + √2)] − ½.
        let exact_u = 0.5 * (2f64.sqrt() + (1.0 + 2f64.sqrt()).ln()) - 0.5;
        assert!((j[1] - exact_u).abs() < 1e-14, "{} vs {exact_u}", j[1]);
    }

    /// The closed-form potentials agree with brute-force quadrature away from the singularity.
    #[test]
    fn potentials_match_quadrature_at_a_distant_point() {
        let rule = GaussRule::new(20);
        let (x, y) = (3.1, -1.7);
        let mut q = [0.0; 4];
        for (u, wu) in rule.on_interval(0.0, 1.0) {
            for (v, wv) in rule.on_interval(0.0, 0.5) {
                let r = ((u - x).powi(2) + (v - y).powi(2)).sqrt();
                let n = shape(2.0 * u - 1.0, 4.0 * v - 1.0);
                for b in 0..4 {
                    q[b] += wu * wv * n[b] / r;
                }
            }
        }
        let p = element_potentials(x, y, 0.0, 1.0, 0.0, 0.5);
        for b in 0..4 {
            assert!(
                (p[b] - q[b]).abs() < 1e-12 * q[b].abs(),
                "N_{b}: {} vs {}",
                p[b],
                q[b]
            );
        }
    }

    /// The self block sums to the known double integral ∫∫∫∫ 1/R over a unit square pair:
    /// (4/3)(1 − √2) + 4 ln(1 + √2) ≈ 2.97349 (the mean inverse distance in a unit square).
    #[test]
    fn self_block_sums_to_the_square_double_integral() {
        let b = pair_block(0, 0, 1.0, 1.0);
        let sum: f64 = b.iter().flatten().sum();
        let exact = 4.0 / 3.0 * (1.0 - 2f64.sqrt()) + 4.0 * (1.0 + 2f64.sqrt()).ln();
        assert!((sum - exact).abs() < 1e-5 * exact, "{sum} vs {exact}");
    }

    /// Near and far rules agree where they meet.
    #[test]
    fn near_and_far_rules_agree_at_the_switch() {
        // Offset (2, 1) is near (√5 < 2.5); recompute it with the far rule and compare the sum.
        let near = pair_block(2, 1, 1.0, 1.0);
        let rule = GaussRule::new(10);
        let mut far = 0.0;
        for (x0, w0) in rule.on_interval(0.0, 1.0) {
            for (y0, v0) in rule.on_interval(0.0, 1.0) {
                for (x1, w1) in rule.on_interval(2.0, 3.0) {
                    for (y1, v1) in rule.on_interval(1.0, 2.0) {
                        far += w0 * v0 * w1 * v1 / ((x1 - x0).powi(2) + (y1 - y0).powi(2)).sqrt();
                    }
                }
            }
        }
        let sum: f64 = near.iter().flatten().sum();
        assert!((sum - far).abs() < 1e-9 * far, "{sum} vs {far}");
    }
}
