//! The infinite Kirchhoff plate under a uniform disk on a dense liquid (Winkler) or an elastic
//! solid (half-space): the closed forms the AREA method inverts, as Hankel integrals.
//!
//! With u = ξℓ, α = a/ℓ, ρ = r/ℓ (a the disk's radius, r the distance from its centre):
//!
//! - dense liquid, ℓ⁴ = D/k: w(r) = P/(k ℓ²) · f(ρ, α),
//!   f = 1/(π α) ∫₀^∞ J₁(α u) J₀(ρ u) / (1 + u⁴) du;
//! - elastic solid of modulus E_s and Poisson's ratio ν_s, C = E_s / (2(1 − ν_s²)) (the
//!   surface's reaction to a wave of wavenumber ξ is C ξ), ℓ³ = D/C:
//!   w(r) = P/(C ℓ) · g(ρ, α), g = 1/(π α) ∫₀^∞ J₁(α u) J₀(ρ u) / (u (1 + u³)) du.
//!
//! As α → 0 at ρ = 0 they tend to Westergaard's 1/8 and to 1/(3√3) (the solid's
//! 0.3849 P (1 − ν_s²) / (E_s ℓ)); `tests` checks both.

/// The subgrade of the infinite plate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Subgrade {
    /// Winkler's springs, k (N/m³).
    DenseLiquid,
    /// An elastic half-space of Poisson's ratio `poisson`.
    ElasticSolid {
        /// ν_s.
        poisson: f64,
    },
}

/// J₀(x) by Abramowitz & Stegun 9.4.1 (|x| ≤ 3, |ε| < 5e-8) and 9.4.3 (x > 3, |ε| < 1.6e-8).
pub fn bessel_j0(x: f64) -> f64 {
    let x = x.abs();
    if x <= 3.0 {
        let y = (x / 3.0).powi(2);
        1.0 + y
            * (-2.2499997
                + y * (1.2656208
                    + y * (-0.3163866 + y * (0.0444479 + y * (-0.0039444 + y * 0.0002100)))))
    } else {
        let z = 3.0 / x;
        let f0 = 0.79788456
            + z * (-0.00000077
                + z * (-0.00552740
                    + z * (-0.00009512 + z * (0.00137237 + z * (-0.00072805 + z * 0.00014476)))));
        // A&S print π/4 and 3π/4 to 8 decimals; the exact constants are as good.
        let t0 = x - std::f64::consts::FRAC_PI_4
            + z * (-0.04166397
                + z * (-0.00003954
                    + z * (0.00262573 + z * (-0.00054125 + z * (-0.00029333 + z * 0.00013558)))));
        f0 * t0.cos() / x.sqrt()
    }
}

/// J₁(x) by Abramowitz & Stegun 9.4.4 (|x| ≤ 3, |ε| < 1.3e-8) and 9.4.6 (x > 3, |ε| < 4e-8).
pub fn bessel_j1(x: f64) -> f64 {
    let sign = if x < 0.0 { -1.0 } else { 1.0 };
    let x = x.abs();
    let v = if x <= 3.0 {
        let y = (x / 3.0).powi(2);
        x * (0.5
            + y * (-0.56249985
                + y * (0.21093573
                    + y * (-0.03954289 + y * (0.00443319 + y * (-0.00031761 + y * 0.00001109))))))
    } else {
        let z = 3.0 / x;
        let f1 = 0.79788456
            + z * (0.00000156
                + z * (0.01659667
                    + z * (0.00017105 + z * (-0.00249511 + z * (0.00113653 + z * -0.00020033)))));
        let t1 = x - 3.0 * std::f64::consts::FRAC_PI_4
            + z * (0.12499612
                + z * (0.00005650
                    + z * (-0.00637879 + z * (0.00074348 + z * (0.00079824 + z * -0.00029166)))));
        f1 * t1.cos() / x.sqrt()
    };
    sign * v
}

/// The dimensionless deflection f(ρ, α) (dense liquid) or g(ρ, α) (elastic solid) of the
/// module's description, by Simpson's rule on u ∈ [0, 60] in steps of 1/200 and on [60, 600]
/// in steps of 1/50 (at least 50 points a period for ρ, α ≤ 6). The integrand falls like
/// α/(2u³) while αu < 1 and faster beyond, so the tail past u = 600 is below 1/(4π 600²) ≈ 2e-7
/// of the deflection unit: under 2e-6 of the centre value.
pub fn dimensionless_deflection(subgrade: Subgrade, rho: f64, alpha: f64) -> f64 {
    let f = |u: f64| -> f64 {
        if u == 0.0 {
            // J₁(αu)/u → α/2 and J₀ → 1.
            return match subgrade {
                Subgrade::DenseLiquid => 0.0,
                Subgrade::ElasticSolid { .. } => alpha / 2.0,
            };
        }
        let b = bessel_j1(alpha * u) * bessel_j0(rho * u);
        match subgrade {
            Subgrade::DenseLiquid => b / (1.0 + u.powi(4)),
            Subgrade::ElasticSolid { .. } => b / (u * (1.0 + u.powi(3))),
        }
    };
    let simpson = |from: f64, to: f64, steps: usize| -> f64 {
        let h = (to - from) / steps as f64;
        let mut sum = f(from) + f(to);
        for i in 1..steps {
            sum += if i % 2 == 1 { 4.0 } else { 2.0 } * f(from + i as f64 * h);
        }
        sum * h / 3.0
    };
    (simpson(0.0, 60.0, 12_000) + simpson(60.0, 600.0, 27_000)) / (std::f64::consts::PI * alpha)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// J_n(x) = (1/π) ∫₀^π cos(nτ − x sin τ) dτ by the trapezoid rule, which converges
    /// geometrically for this smooth periodic integrand: the exact values the polynomial
    /// approximations are checked against.
    fn bessel_by_integral(n: u32, x: f64) -> f64 {
        let m = 60 + x.abs().ceil() as usize;
        let h = std::f64::consts::PI / m as f64;
        let f = |tau: f64| (f64::from(n) * tau - x * tau.sin()).cos();
        let mut sum = 0.5 * (f(0.0) + f(std::f64::consts::PI));
        for i in 1..m {
            sum += f(i as f64 * h);
        }
        sum * h / std::f64::consts::PI
    }

    /// The approximations hold A&S's stated accuracy (5e-8 and 4e-8 in absolute value; 1e-7
    /// with round-off) from 0 to 200 on both sides of the switch at 3.
    #[test]
    fn bessel_functions_match_their_integrals() {
        for i in 0..=4000 {
            let x = 0.05 * i as f64;
            let (j0, j1) = (bessel_j0(x), bessel_j1(x));
            assert!(
                (j0 - bessel_by_integral(0, x)).abs() < 1e-7,
                "J0({x}) = {j0}"
            );
            assert!(
                (j1 - bessel_by_integral(1, x)).abs() < 1e-7,
                "J1({x}) = {j1}"
            );
        }
        assert_eq!(bessel_j1(-1.3), -bessel_j1(1.3));
    }

    /// The point-load limits at the centre: Westergaard's 1/8 on the dense liquid and
    /// ∫₀^∞ du/(1 + u³) / (2π) = 1/(3√3) on the solid; a disk of α = 0.01 is within 1e-4 of
    /// them (its spread lowers the peak by order α²).
    #[test]
    fn small_disks_give_the_point_load_deflections() {
        let f = dimensionless_deflection(Subgrade::DenseLiquid, 0.0, 0.01);
        assert!((f - 0.125).abs() < 1e-4 * 0.125, "{f}");
        let g = dimensionless_deflection(Subgrade::ElasticSolid { poisson: 0.4 }, 0.0, 0.01);
        let exact = 1.0 / (3.0 * 3f64.sqrt());
        assert!((g - exact).abs() < 1e-4 * exact, "{g} vs {exact}");
    }

    /// A published interior deflection: Huang, *Pavement Analysis and Design*, 2nd ed. (2004),
    /// the examples of §4.1 (pp. 151–160; E = 4·10⁶ psi, ν = 0.15, h = 10 in, k = 100 pci, a
    /// 10 000 lb load on a disk of 6 in radius): ℓ = 42.97 in, interior deflection 0.0067 in
    /// (the values as transcribed in the test file of a course site, ictuillinois/CEE-406,
    /// `westergaard/equations.test.mjs`). The book gives two digits: the Hankel integral must
    /// round to them (within half a unit of the last, 0.75 %). Westergaard's closed form with
    /// the disk's correction, Δ = P/(8kℓ²)·{1 + [ln(a/2ℓ) + γ − 5/4](a/ℓ)²/(2π)} (γ − 5/4 =
    /// −0.673), is the expansion of the same integral to second order in α = a/ℓ: it must
    /// agree to O(α⁴) ≈ 4e-4 here (0.1 % allowed).
    #[test]
    fn a_published_interior_deflection() {
        let (e, nu, h, k, p, a): (f64, f64, f64, f64, f64, f64) =
            (4.0e6, 0.15, 10.0, 100.0, 10_000.0, 6.0);
        let l = (e * h.powi(3) / (12.0 * (1.0 - nu * nu) * k)).powf(0.25);
        assert!((l - 42.97).abs() < 0.005, "ℓ = {l}");
        let alpha = a / l;
        let w = p / (k * l * l) * dimensionless_deflection(Subgrade::DenseLiquid, 0.0, alpha);
        assert!((w - 0.0067).abs() <= 0.00005, "interior deflection {w} in");
        let gamma = 0.577_215_664_901_532_9;
        let westergaard = p / (8.0 * k * l * l)
            * (1.0
                + ((alpha / 2.0).ln() + gamma - 1.25) * alpha * alpha
                    / (2.0 * std::f64::consts::PI));
        assert!(
            (w - westergaard).abs() < 1e-3 * westergaard,
            "{w} against Westergaard's {westergaard}"
        );
    }
}
