//! Surface kernels of the non-local foundations: the settlement at distance ρ caused by a unit
//! point force, up to the foundation constant c of [`crate::operators::Operators`].
//!
//! Every kernel here is radial and translation invariant, so on the structured grid the
//! Galerkin pair integrals I_ab(d) = ∫_{e0}∫_{e1} N_a(x) N_b(x') K(|x' − x|) dA' dA depend only on
//! the element offset d ([`super::pairs::PairTable`]). The half-space keeps its closed-form near
//! field ([`super::boussinesq::pair_block`]); the others use the generic rule of this module.
//!
//! **The generic rule.** With bilinear shape functions N_a(x, y) = φ_p(x) ψ_q(y), the pair
//! integral is a 2-D integral over the displacement t = x' − x − D (D the offset of the two
//! elements' origins),
//!
//! I_ab(D) = ∫∫_{[−hx, hx] × [−hy, hy]} K(|D + t|) Cx(t_x) Cy(t_y) dt,
//!
//! where Cx(t) = ∫ φ_p(x) φ_p'(x + t) dx is the correlation of two hat pieces (a cubic on each of
//! [−hx, 0] and [0, hx]; evaluated exactly by 2-point Gauss). The only singular point of K is
//! D + t = 0, and for the offsets where it lies in the domain it is a corner of one of the four
//! quadrants. Such a quadrant is integrated in polar coordinates about that corner (two
//! triangles; ρ dρ removes a 1/ρ singularity and leaves ρ ln ρ of a logarithmic one, integrated
//! on geometrically graded radial panels with Gauss rules — the hp rule for endpoint
//! singularities, exponentially convergent); the others by composite product Gauss. The rule is
//! tested against the Boussinesq closed forms (tests below), so the half-space is its proof case.

use crate::plate::{NODE_ETA, NODE_XI};
use crate::quadrature::GaussRule;
use std::sync::{Arc, OnceLock};

/// Euler–Mascheroni constant γ.
const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;

/// A radial surface kernel, normalised so that T = c · (pair integrals of the kernel): each
/// soil's own in its file ([`super::halfspace`], [`super::pasternak`],
/// [`super::elastic_layer`], [`super::kerr`]).
pub trait Radial: std::fmt::Debug + Send + Sync {
    /// Point value K(ρ), ρ > 0.
    fn value(&self, rho: f64) -> f64;

    /// Distance beyond which the kernel is zero in double precision, if it decays that fast.
    fn support(&self) -> Option<f64>;

    /// Length over which the kernel varies by a factor e (∞ for the scale-free 1/ρ): the
    /// generic rule grades its radial panels by it.
    fn scale(&self) -> f64;

    /// Pair block I[a][b] for the element e0 = [0, hx] × [0, hy] and e1 offset by (di, dj)
    /// elements (di, dj ≥ 0): the generic rule of this module unless the soil knows better.
    fn pair_block(&self, di: usize, dj: usize, hx: f64, hy: f64) -> [[f64; 4]; 4] {
        generic_pair_block(self, di, dj, hx, hy)
    }
}

/// A non-local surface kernel: a soil's [`Radial`] kernel, shared (cheap to clone).
#[derive(Debug, Clone)]
pub struct Kernel(Arc<dyn Radial>);

impl Kernel {
    /// The kernel `radial`.
    pub fn new(radial: impl Radial + 'static) -> Self {
        Kernel(Arc::new(radial))
    }

    /// Point value K(ρ), ρ > 0.
    pub fn value(&self, rho: f64) -> f64 {
        self.0.value(rho)
    }

    /// Distance beyond which the kernel is zero in double precision, if it decays that fast.
    pub fn support(&self) -> Option<f64> {
        self.0.support()
    }

    /// Pair block I[a][b] for the element e0 = [0, hx] × [0, hy] and e1 offset by (di, dj)
    /// elements (di, dj ≥ 0).
    pub fn pair_block(&self, di: usize, dj: usize, hx: f64, hy: f64) -> [[f64; 4]; 4] {
        self.0.pair_block(di, dj, hx, hy)
    }
}

/// ∫_e N_a N_b dA of bilinear shape functions on an hx × hy element is hx hy/36 times these
/// weights: 4, 2, 1 for the same, an edge-adjacent and the opposite corner (a local soil's part
/// of a pair block).
pub fn local_weights() -> [[f64; 4]; 4] {
    let mut block = [[0.0; 4]; 4];
    for (a, row) in block.iter_mut().enumerate() {
        for (b, v) in row.iter_mut().enumerate() {
            let same_x = NODE_XI[a] == NODE_XI[b];
            let same_y = NODE_ETA[a] == NODE_ETA[b];
            *v = match (same_x, same_y) {
                (true, true) => 4.0,
                (false, false) => 1.0,
                _ => 2.0,
            };
        }
    }
    block
}

/// Chebyshev coefficients of eˣ √x K₀(x) on 2 ≤ x < ∞ in the variable 8/x − 2 (Moshier 1989,
/// "Methods and Programs for Mathematical Functions", the Cephes library's `k0.c`: peak relative
/// error 1.2e-15 on [0, 30] in IEEE double), highest order first.
#[allow(clippy::excessive_precision)]
const K0_LARGE: [f64; 25] = [
    5.30043377268626276149e-18,
    -1.64758043015242134646e-17,
    5.21039150503902756861e-17,
    -1.67823109680541210385e-16,
    5.51205597852431940784e-16,
    -1.84859337734377901440e-15,
    6.34007647740507060557e-15,
    -2.22751332699166985548e-14,
    8.03289077536357521100e-14,
    -2.98009692317273043925e-13,
    1.14034058820847496303e-12,
    -4.51459788337394416547e-12,
    1.85594911495471785253e-11,
    -7.95748924447710747776e-11,
    3.57739728140030116597e-10,
    -1.69753450938905987466e-9,
    8.57403401741422608519e-9,
    -4.66048989768794782956e-8,
    2.76681363944501510342e-7,
    -1.83175552271911948767e-6,
    1.39498137188764993662e-5,
    -1.28495495816278026384e-4,
    1.56988388573005337491e-3,
    -3.14481013119645005427e-2,
    2.44030308206595545468e0,
];

/// Σ c_k T_k(y/2) with the first term halved, coefficients highest order first (Clenshaw's
/// recurrence in the form Cephes tabulates them for).
fn chebyshev(y: f64, c: &[f64]) -> f64 {
    let (mut b0, mut b1, mut b2) = (0.0, 0.0, 0.0);
    for &ck in c {
        b2 = b1;
        b1 = b0;
        b0 = y * b1 - b2 + ck;
    }
    0.5 * (b0 - b2)
}

/// Modified Bessel function K₀(x), x > 0, to about 1e−15 relative.
///
/// x ≤ 2: the ascending series K₀ = −(ln(x/2) + γ) I₀(x) + Σ_{k≥1} H_k (x²/4)^k/(k!)² (A&S
/// 9.6.13), summed until the terms stop changing (at most 11 terms). x > 2: e⁻ˣ/√x times
/// Moshier's Chebyshev expansion of eˣ √x K₀ in 8/x − 2 ([`K0_LARGE`]): 25 multiply–adds,
/// one exp and one square root, where the trapezoidal integral ∫₀^∞ exp(−x cosh t) dt it
/// replaces took 15–27 exponentials (tested against that integral, on a step that follows
/// the integrand's width, to 1e-13).
pub fn bessel_k0(x: f64) -> f64 {
    if x <= 0.0 {
        return f64::INFINITY;
    }
    if x <= 2.0 {
        let q = 0.25 * x * x;
        let mut term = 1.0; // (x²/4)^k / (k!)²
        let mut i0 = 1.0;
        let mut h = 0.0;
        let mut smooth = 0.0;
        for k in 1..60 {
            let kf = k as f64;
            term *= q / (kf * kf);
            h += 1.0 / kf;
            i0 += term;
            smooth += h * term;
            if term < 1e-18 * i0 {
                break;
            }
        }
        -((0.5 * x).ln() + EULER_GAMMA) * i0 + smooth
    } else {
        (-x).exp() * chebyshev(8.0 / x - 2.0, &K0_LARGE) / x.sqrt()
    }
}

/// Correlation of the 1-D hat pieces p (of e0) and q (of e1) at relative shift t ∈ [−h, h]:
/// ∫ φ_p(x) φ_q(x + t) dx over x ∈ [0, h] ∩ [−t, h − t], with φ_0 = 1 − x/h, φ_1 = x/h. A
/// quadratic in x, so the 2-point Gauss rule is exact.
fn correlation(p: usize, q: usize, t: f64, h: f64) -> f64 {
    let lo = (-t).max(0.0);
    let hi = (h - t).min(h);
    if hi <= lo {
        return 0.0;
    }
    let phi = |k: usize, x: f64| if k == 0 { 1.0 - x / h } else { x / h };
    let half = 0.5 * (hi - lo);
    let mid = 0.5 * (hi + lo);
    let g = half / 3f64.sqrt();
    let mut s = 0.0;
    for x in [mid - g, mid + g] {
        s += phi(p, x) * phi(q, x + t);
    }
    s * half
}

/// The 1-D hat index (0: left, 1: right) of local node a along x and along y.
fn hat(a: usize) -> (usize, usize) {
    (
        usize::from(NODE_XI[a] > 0.0),
        usize::from(NODE_ETA[a] > 0.0),
    )
}

fn rule(n: usize) -> &'static GaussRule {
    static RULES: OnceLock<Vec<GaussRule>> = OnceLock::new();
    &RULES.get_or_init(|| (0..=24).map(GaussRule::new).collect())[n.min(24)]
}

/// Radial points and weights on [0, r] for ∫ K(ρ) g(ρ) ρ dρ with a kernel at most
/// logarithmically or 1/ρ singular at 0: geometric panels r, r q, r q², … (q = 0.2) down to
/// r·1e−9, each with a 10-point Gauss rule, and a last panel [0, r·1e−9] (whose contribution is
/// ~1e−9² ln of the total).
fn radial_nodes(r: f64) -> Vec<(f64, f64)> {
    let g = rule(10);
    let mut out = Vec::with_capacity(140);
    let mut hi = r;
    loop {
        let lo = if hi < 1e-9 * r { 0.0 } else { 0.2 * hi };
        for (x, w) in g.on_interval(lo, hi) {
            out.push((x, w));
        }
        if lo == 0.0 {
            break;
        }
        hi = lo;
    }
    out
}

/// Generic pair block (module docs).
pub fn generic_pair_block<K: Radial + ?Sized>(
    k: &K,
    di: usize,
    dj: usize,
    hx: f64,
    hy: f64,
) -> [[f64; 4]; 4] {
    let dx = di as f64 * hx;
    let dy = dj as f64 * hy;
    let mut out = [[0.0; 4]; 4];
    // Nearest displacement between the two elements: nothing to add beyond the support.
    let gap_x = (dx - hx).max(0.0);
    let gap_y = (dy - hy).max(0.0);
    if let Some(s) = k.support() {
        if (gap_x * gap_x + gap_y * gap_y).sqrt() > s {
            return out;
        }
    }
    // Correlation weights W_ab(t) = Cx_{p_a p_b}(t_x) Cy_{q_a q_b}(t_y): four 1-D correlations
    // per direction and point.
    let hats: [(usize, usize); 4] = [hat(0), hat(1), hat(2), hat(3)];
    let add = |tx: f64, ty: f64, w: f64, out: &mut [[f64; 4]; 4]| {
        let rho = ((dx + tx).powi(2) + (dy + ty).powi(2)).sqrt();
        let kv = w * k.value(rho);
        if kv == 0.0 {
            return;
        }
        let mut cxs = [[0.0; 2]; 2];
        let mut cys = [[0.0; 2]; 2];
        for p in 0..2 {
            for q in 0..2 {
                cxs[p][q] = correlation(p, q, tx, hx);
                cys[p][q] = correlation(p, q, ty, hy);
            }
        }
        for (a, row) in out.iter_mut().enumerate() {
            let (pa, qa) = hats[a];
            for (b, v) in row.iter_mut().enumerate() {
                let (pb, qb) = hats[b];
                *v += kv * cxs[pa][pb] * cys[qa][qb];
            }
        }
    };
    let h = hx.max(hy);
    let scale = k.scale();
    for (x0, x1) in [(-hx, 0.0), (0.0, hx)] {
        for (y0, y1) in [(-hy, 0.0), (0.0, hy)] {
            // The singular point t = −D, if it is a corner of this quadrant.
            let cx = [x0, x1].into_iter().find(|&c| (c + dx).abs() < 1e-12 * h);
            let cy = [y0, y1].into_iter().find(|&c| (c + dy).abs() < 1e-12 * h);
            if let (Some(cx), Some(cy)) = (cx, cy) {
                // Polar about the corner: the quadrant is [0, A] × [0, B] in (u, v) with
                // t = (cx + sx u, cy + sy v).
                let (a_len, b_len) = (x1 - x0, y1 - y0);
                let sx = if cx == x0 { 1.0 } else { -1.0 };
                let sy = if cy == y0 { 1.0 } else { -1.0 };
                let theta0 = b_len.atan2(a_len);
                let reach = k.support().unwrap_or(f64::INFINITY);
                let g = rule(24);
                for (lo, hi, first) in [
                    (0.0, theta0, true),
                    (theta0, 0.5 * std::f64::consts::PI, false),
                ] {
                    for (th, wt) in g.on_interval(lo, hi) {
                        let (s, c) = th.sin_cos();
                        let r_max = if first { a_len / c } else { b_len / s };
                        for (r, wr) in radial_nodes(r_max.min(reach)) {
                            add(cx + sx * r * c, cy + sy * r * s, wt * wr * r, &mut out);
                        }
                    }
                }
            } else {
                // Smooth over the quadrant: composite Gauss, finer where the kernel varies
                // faster than the element (Pasternak with λ < h), order by distance. Such a
                // quadrant lies at least min(hx, hy) from the singular point; beyond the
                // support it adds nothing. The sub-cells stop refining at 16 per side: that
                // happens for λ < h/8, where the cells are at most 2λ... 6λ wide for 10 Gauss
                // points (exponential decay over a few λ integrates to ~1e−10 of the cell) and
                // the kernel there is below e^{−8} of its value at λ.
                let near_x = (x0 + dx).max(0.0).max(-(x1 + dx));
                let near_y = (y0 + dy).max(0.0).max(-(y1 + dy));
                if let Some(s) = k.support() {
                    if (near_x * near_x + near_y * near_y).sqrt() > s {
                        continue;
                    }
                }
                let dist = ((dx.abs() - hx).max(0.0).powi(2) + (dy.abs() - hy).max(0.0).powi(2))
                    .sqrt()
                    / h;
                let order = if dist < 3.0 {
                    10
                } else if dist < 8.0 {
                    6
                } else {
                    4
                };
                let sub = ((2.0 * h / scale).ceil() as usize).clamp(1, 16);
                let g = rule(order);
                for ix in 0..sub {
                    let (a0, a1) = (
                        x0 + (x1 - x0) * ix as f64 / sub as f64,
                        x0 + (x1 - x0) * (ix + 1) as f64 / sub as f64,
                    );
                    for jy in 0..sub {
                        let (b0, b1) = (
                            y0 + (y1 - y0) * jy as f64 / sub as f64,
                            y0 + (y1 - y0) * (jy + 1) as f64 / sub as f64,
                        );
                        for (tx, wx) in g.on_interval(a0, a1) {
                            for (ty, wy) in g.on_interval(b0, b1) {
                                add(tx, ty, wx * wy, &mut out);
                            }
                        }
                    }
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::super::halfspace::Boussinesq;
    use super::super::pasternak::{PasternakKernel, PASTERNAK_CUTOFF};
    use super::*;

    /// K₀ against tabulated values (A&S Table 9.8, DLMF; K₀(1) = 0.42102443824070834,
    /// K₀(0.1) = 2.4270690247020166, K₀(2) = 0.11389387274953344, K₀(5) = 3.6910983340425942e−3,
    /// K₀(10) = 1.778006231616919e−5): both branches and the switch, to 1e−13 relative.
    /// The Chebyshev expansion beyond x = 2 against the integral K₀(x) = ∫₀^∞ exp(−x cosh t) dt
    /// (A&S 9.6.24) by the trapezoidal rule with step ¼/√x, at 2 000 points from 2 to 700: to
    /// 1e-13 relative (the expansion's own error is 1.2e-15 peak; 1e-13 leaves room for the
    /// sum's round-off over up to a few hundred terms). The step follows the integrand's width
    /// 1/√x: near t = 0 it is e⁻ˣ exp(−x t²/2), whose trapezoidal error exp(−2π²/(x h²)) is
    /// e⁻³¹⁶, and at x = 2 the analytic strip |Im t| < π/2 gives exp(−π²/h) = e⁻⁵⁶. (The fixed
    /// step ¼ that computed K₀ before this expansion was that accurate only to x ≈ 10: relative
    /// errors 6e-10 at x = 20 and 3e-5 at 30, on values below 1e-9 of K₀ at a tenth of λ.)
    #[test]
    fn k0_beyond_two_matches_its_integral() {
        let integral = |x: f64| {
            let step = 0.25 / x.sqrt();
            let mut sum = 0.5 * (-x).exp();
            let mut k = 1;
            loop {
                let e = x * (step * k as f64).cosh();
                if e > 745.0 {
                    break;
                }
                sum += (-e).exp();
                k += 1;
            }
            step * sum
        };
        let mut worst = 0.0_f64;
        for i in 0..=2000 {
            let x = 2.0 * (350.0_f64).powf(i as f64 / 2000.0);
            let (a, b) = (bessel_k0(x), integral(x));
            worst = worst.max((a - b).abs() / b);
        }
        assert!(worst < 1e-13, "largest relative difference {worst:e}");
    }

    #[test]
    fn k0_matches_tables() {
        for (x, v) in [
            (0.1, 2.427_069_024_702_017),
            (1.0, 0.421_024_438_240_708_3),
            (2.0, 0.113_893_872_749_533_4),
            (5.0, 3.691_098_334_042_594e-3),
            (10.0, 1.778_006_231_616_919e-5),
        ] {
            let k = bessel_k0(x);
            assert!((k - v).abs() < 1e-12 * v, "K0({x}) = {k}, table {v}");
        }
    }

    /// The generic rule applied to 1/ρ reproduces the exact double integral of 1/R over a unit
    /// square pair, (4/3)(1 − √2) + 4 ln(1 + √2) (the sum of the self block), to 1e−12.
    #[test]
    fn generic_rule_is_exact_on_the_square_double_integral() {
        let exact = 4.0 / 3.0 * (1.0 - 2f64.sqrt()) + 4.0 * (1.0 + 2f64.sqrt()).ln();
        let g = generic_pair_block(&Boussinesq, 0, 0, 1.0, 1.0);
        let sum: f64 = g.iter().flatten().sum();
        assert!((sum - exact).abs() < 1e-12 * exact, "{sum} vs {exact}");
    }

    /// The generic rule applied to 1/ρ against the half-space's semi-analytic blocks
    /// (`boussinesq::pair_block`, closed-form inner integral, Gauss outer one). The latter's
    /// outer rule meets the potential's logarithmic edge derivatives and is the less accurate of
    /// the two: on the unit self block its sum is off the exact value by 2.4e−5 relative where
    /// the generic rule is exact to 1e−14 (test above). So touching pairs agree to 5e−5 of the
    /// block's largest entry; separated pairs to 5e−7, the accuracy of the half-space's far rules
    /// (product Gauss of order 5, 3, 2 by distance: 1.4e−7 relative measured at offset (6, 4) of
    /// a 0.5 × 1 element).
    #[test]
    fn generic_rule_reproduces_boussinesq_blocks() {
        for (hx, hy) in [(1.0, 1.0), (0.5, 1.0), (1.0, 0.3)] {
            for (di, dj) in [(0, 0), (1, 0), (0, 1), (1, 1), (2, 1), (3, 0), (6, 4)] {
                let exact = super::super::boussinesq::pair_block(di, dj, hx, hy);
                let generic = generic_pair_block(&Boussinesq, di, dj, hx, hy);
                let big = exact.iter().flatten().fold(0.0_f64, |m, v| m.max(v.abs()));
                let tol = if di <= 1 && dj <= 1 { 5e-5 } else { 5e-7 };
                for a in 0..4 {
                    for b in 0..4 {
                        let e = exact[a][b];
                        let g = generic[a][b];
                        assert!(
                            (e - g).abs() < tol * big,
                            "h = ({hx}, {hy}) offset ({di}, {dj}) [{a}][{b}]: closed form {e}, generic {g}"
                        );
                    }
                }
            }
        }
    }

    /// The Pasternak kernel has unit integral over the plane, so for every point of e0 the
    /// pair blocks summed over all offsets and all (a, b) give ∫_{e0} 1 = hx·hy — a check of the
    /// whole table, singular near field included, for λ from a tenth of an element to two.
    #[test]
    fn pasternak_pair_blocks_sum_to_the_element_area() {
        for (hx, hy, lambda) in [(1.0, 1.0, 0.1), (1.0, 1.0, 0.7), (0.5, 1.0, 2.0)] {
            let k = PasternakKernel { lambda };
            let reach_x = (PASTERNAK_CUTOFF * lambda / hx).ceil() as isize + 1;
            let reach_y = (PASTERNAK_CUTOFF * lambda / hy).ceil() as isize + 1;
            let mut sum = 0.0;
            for di in -reach_x..=reach_x {
                for dj in -reach_y..=reach_y {
                    let b = k.pair_block(di.unsigned_abs(), dj.unsigned_abs(), hx, hy);
                    sum += b.iter().flatten().sum::<f64>();
                }
            }
            let area = hx * hy;
            assert!(
                (sum - area).abs() < 1e-9 * area,
                "λ = {lambda}, h = ({hx}, {hy}): Σ blocks = {sum}, area {area}"
            );
        }
    }

    /// A brute-force check of the singular self block: the inner integral over e1 done in polar
    /// coordinates about each outer Gauss point (which is inside e1) with a fine radial rule,
    /// the outer one by a 12 × 12 Gauss product on 4 × 4 sub-cells; compared entry by entry.
    #[test]
    fn pasternak_self_block_matches_brute_force() {
        let (hx, hy, lambda) = (1.0, 0.6, 0.4);
        let k = PasternakKernel { lambda };
        let block = k.pair_block(0, 0, hx, hy);
        let g = GaussRule::new(12);
        let shape = crate::plate::shape;
        let mut brute = [[0.0; 4]; 4];
        for cx in 0..4 {
            for (x, wx) in g.on_interval(hx * cx as f64 / 4.0, hx * (cx + 1) as f64 / 4.0) {
                for cy in 0..4 {
                    for (y, wy) in g.on_interval(hy * cy as f64 / 4.0, hy * (cy + 1) as f64 / 4.0) {
                        // Inner: ∫_{e1} N_b(x') K(|x' − x|) dA' in polar about (x, y), over the
                        // four corner-to-point triangles' angular ranges.
                        let mut inner = [0.0; 4];
                        let corners = [(0.0, 0.0), (hx, 0.0), (hx, hy), (0.0, hy)];
                        for s in 0..4 {
                            let (p, q) = (corners[s], corners[(s + 1) % 4]);
                            // The side as p + s·e; its foot from (x, y) at parameter s_p = 0
                            // shift. dθ = dist/(dist² + s²) ds and r_max = √(dist² + s²),
                            // graded panels at ±dist·4^k about the foot (the integrand varies
                            // on the scale dist there).
                            let (ex, ey) = (q.0 - p.0, q.1 - p.1);
                            let len = (ex * ex + ey * ey).sqrt();
                            let (ex, ey) = (ex / len, ey / len);
                            let s0 = (p.0 - x) * ex + (p.1 - y) * ey;
                            let (fx, fy) = (p.0 - s0 * ex, p.1 - s0 * ey);
                            let dist = ((fx - x).powi(2) + (fy - y).powi(2)).sqrt();
                            let (lo, hi) = (s0, s0 + len);
                            let mut cuts = vec![lo, hi];
                            let mut d = dist;
                            while d < len {
                                for c in [-d, 0.0, d] {
                                    if c > lo && c < hi {
                                        cuts.push(c);
                                    }
                                }
                                d *= 4.0;
                            }
                            cuts.sort_by(f64::total_cmp);
                            for w in cuts.windows(2) {
                                for (sp, ws) in GaussRule::new(12).on_interval(w[0], w[1]) {
                                    let r_max = (dist * dist + sp * sp).sqrt();
                                    let wt = ws * dist / (r_max * r_max);
                                    let (cs, sn) =
                                        ((fx + sp * ex - x) / r_max, (fy + sp * ey - y) / r_max);
                                    for (r, wr) in radial_nodes(r_max) {
                                        let (u, v) = (x + r * cs, y + r * sn);
                                        let n = shape(2.0 * u / hx - 1.0, 2.0 * v / hy - 1.0);
                                        let kv = wt * wr * r * k.value(r);
                                        for b in 0..4 {
                                            inner[b] += kv * n[b];
                                        }
                                    }
                                }
                            }
                        }
                        let n = shape(2.0 * x / hx - 1.0, 2.0 * y / hy - 1.0);
                        for a in 0..4 {
                            for b in 0..4 {
                                brute[a][b] += wx * wy * n[a] * inner[b];
                            }
                        }
                    }
                }
            }
        }
        for a in 0..4 {
            for b in 0..4 {
                assert!(
                    (brute[a][b] - block[a][b]).abs() < 1e-8 * block[0][0],
                    "[{a}][{b}]: rule {}, brute force {}",
                    block[a][b],
                    brute[a][b]
                );
            }
        }
    }
}
