//! The homogeneous elastic layer of depth h on a rigid base, rough (bonded) or smooth
//! (frictionless): its surface compliance in the wavenumber domain and its spatial kernel by a
//! Hankel transform.
//!
//! **Symbol.** A surface pressure p cos(ξx) (or p J₀(ξρ)) on a layer of Young's modulus E and
//! Poisson's ratio ν whose base z = h cannot move (u = w = 0) settles by C(ξ) p with
//!
//! C(ξ) = 2(1 − ν²)/(E ξ) · K(ξh),  K(t) = (2κ sinh 2t − 4t)/(2κ cosh 2t + 4t² + 1 + κ²),
//!
//! κ = 3 − 4ν (Burmister's one-layer solution). K → 1 as t → ∞ (the half-space,
//! 2(1 − ν²)/(Eξ)) and K(t) = t(1 − 2ν)/(2(1 − ν)²) + O(t³) as t → 0, i.e. C(0) = h/E_oed with
//! E_oed = E(1 − ν)/((1 + ν)(1 − 2ν)): a Winkler bed of modulus E_oed/h for long waves. The
//! closed form is checked in the tests below against a numerical solution of the layer's
//! Navier equations for one wavenumber (the transfer matrix exp(A h) of the first-order
//! system in (u, w, τ_xz, σ_zz), not derived from the closed form).
//!
//! **Smooth base** (τ_xz = w = 0 at z = h): K(t) = (cosh 2t − 1)/(sinh 2t + 2t), independent of
//! ν (checked the same way). K(t) = t/2 − t⁵/90 + …: C(0) = (1 − ν²)h/E, a Winkler bed of modulus
//! E/((1 − ν²)h) — the layer may now spread sideways on its base, so the long-wave modulus is not
//! the oedometric one.
//!
//! **Spatial kernel.** The settlement at distance ρ from a unit point force is the Hankel
//! transform w(ρ) = (1/2π) ∫₀^∞ C(ξ) J₀(ξρ) ξ dξ = (1 − ν²)/(πE) · G(ρ), with
//!
//! G(ρ) = ∫₀^∞ K(ξh) J₀(ξρ) dξ = 1/ρ − F(ρ/h)/h,  F(s) = ∫₀^∞ (1 − K(t)) J₀(ts) dt,
//!
//! since ∫₀^∞ J₀(ξρ) dξ = 1/ρ. So the layer is the half-space's 1/ρ (same constant
//! c = (1 − ν²)/(πE)) minus a correction whose symbol 1 − K(t) is 1 at t = 0 and decays like
//! 4t² e^{−2t}/κ: F is smooth (even and analytic in s) and is computed once per ν by Gauss
//! quadrature on t ∈ [0, 30] (1 − K(30) < 1e−22), tabulated on s ∈ [0, 40 + ...] and read by
//! 6-point Lagrange interpolation. K(t)/t is even and analytic, so G decays exponentially
//! (about e^{−0.96 ρ/h}; G(20h) ≈ −8e−11/h, G(40h) below 1e−19/h): beyond ρ = 40h the
//! kernel is zero in double precision ([`LAYER_CUTOFF`]).

use crate::quadrature::GaussRule;
use std::sync::{Arc, Mutex, OnceLock};

/// Beyond this many depths the layer kernel G is below 1e−19/h (module docs): zero.
pub const LAYER_CUTOFF: f64 = 40.0;

/// Upper end of the correction's wavenumber integral, in units of 1/h: 1 − K(30) < 1e−22.
const T_MAX: f64 = 30.0;
/// Table spacing in s = ρ/h.
const STEP: f64 = 1.0 / 64.0;

/// How the layer meets its rigid base.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Base {
    /// Bonded: u = w = 0 at the base.
    Rough,
    /// Frictionless: τ_xz = w = 0 at the base.
    Smooth,
}

impl Base {
    /// Name used in scene files and reports.
    pub fn name(self) -> &'static str {
        match self {
            Base::Rough => "rough",
            Base::Smooth => "smooth",
        }
    }

    /// The scene name's base, if it is one.
    pub fn parse(name: &str) -> Option<Self> {
        match name {
            "rough" => Some(Base::Rough),
            "smooth" => Some(Base::Smooth),
            _ => None,
        }
    }

    /// lim K(t)/t at t = 0: C(0) = 2(1 − ν²) h · slope / E.
    pub fn slope(self, nu: f64) -> f64 {
        match self {
            Base::Rough => (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu) * (1.0 - nu)),
            Base::Smooth => 0.5,
        }
    }
}

/// The layer symbol K(t) (module docs), t = ξh ≥ 0.
pub fn symbol(t: f64, nu: f64, base: Base) -> f64 {
    if base == Base::Smooth {
        // (cosh 2t − 1)/(sinh 2t + 2t) with cosh 2t − 1 = 2 sinh² t (no cancellation near 0).
        if t > 20.0 {
            return 1.0 - one_minus_symbol(t, nu, base);
        }
        if t == 0.0 {
            return 0.0;
        }
        return 2.0 * t.sinh().powi(2) / ((2.0 * t).sinh() + 2.0 * t);
    }
    let kappa = 3.0 - 4.0 * nu;
    if t > 20.0 {
        // sinh, cosh overflow-free form: divide by e^{2t}/2.
        let e = (-2.0 * t).exp();
        let num = kappa * (1.0 - e * e) - 8.0 * t * e;
        let den = kappa * (1.0 + e * e) + 2.0 * (4.0 * t * t + 1.0 + kappa * kappa) * e;
        return num / den;
    }
    let s2 = (2.0 * t).sinh();
    let c2 = (2.0 * t).cosh();
    (2.0 * kappa * s2 - 4.0 * t) / (2.0 * kappa * c2 + 4.0 * t * t + 1.0 + kappa * kappa)
}

/// 1 − K(t), without cancellation for large t.
fn one_minus_symbol(t: f64, nu: f64, base: Base) -> f64 {
    if base == Base::Smooth {
        // 1 − K = (sinh 2t + 2t − cosh 2t + 1)/(sinh 2t + 2t) = (2t + 1 − e^{−2t})/(sinh 2t + 2t),
        // 1 − e^{−2t} by expm1; at t = 0 the limit 1.
        if t == 0.0 {
            return 1.0;
        }
        return (2.0 * t - (-2.0 * t).exp_m1()) / ((2.0 * t).sinh() + 2.0 * t);
    }
    let kappa = 3.0 - 4.0 * nu;
    // 1 − K = (2κ(cosh 2t − sinh 2t) + 4t² + 4t + 1 + κ²)/(2κ cosh 2t + 4t² + 1 + κ²), and
    // cosh 2t − sinh 2t = e^{−2t}.
    let num = 2.0 * kappa * (-2.0 * t).exp() + 4.0 * t * t + 4.0 * t + 1.0 + kappa * kappa;
    let den = 2.0 * kappa * (2.0 * t).cosh() + 4.0 * t * t + 1.0 + kappa * kappa;
    num / den
}

/// Bessel function J₀ (libm's port of the FreeBSD/musl routine, accurate to a few ulp).
pub fn bessel_j0(x: f64) -> f64 {
    libm::j0(x)
}

/// The correction F(s) = ∫₀^∞ (1 − K(t)) J₀(ts) dt of one Poisson's ratio and base, tabulated.
#[derive(Debug, PartialEq)]
pub struct LayerTable {
    /// ν of the layer.
    pub nu: f64,
    /// Its base.
    pub base: Base,
    /// F(k·STEP), k = 0, 1, …
    values: Vec<f64>,
}

/// The quadrature nodes (t, w·(1 − K(t))) of F on [0, T_MAX]: panels of width ¼ with 16
/// Gauss points each. For s ≤ 41 a panel spans at most 1.7 periods of J₀(ts), which a 16-point
/// rule (exact to degree 31) integrates to round-off.
fn nodes(nu: f64, base: Base) -> Vec<(f64, f64)> {
    let g = GaussRule::new(16);
    let panels = (T_MAX * 4.0) as usize;
    let mut out = Vec::with_capacity(panels * 16);
    for k in 0..panels {
        let (a, b) = (0.25 * k as f64, 0.25 * (k + 1) as f64);
        for (t, w) in g.on_interval(a, b) {
            out.push((t, w * one_minus_symbol(t, nu, base)));
        }
    }
    out
}

/// F(s) by direct quadrature (no table): the reference of the table's interpolation.
pub fn correction_direct(s: f64, nu: f64, base: Base) -> f64 {
    nodes(nu, base)
        .iter()
        .map(|&(t, w)| w * bessel_j0(t * s))
        .sum()
}

impl LayerTable {
    /// Tabulate F for Poisson's ratio `nu` and `base` (see [`Self::shared`]).
    pub fn new(nu: f64, base: Base) -> Self {
        use rayon::prelude::*;
        let quad = nodes(nu, base);
        let n = (LAYER_CUTOFF / STEP) as usize + 8;
        let values = (0..n)
            .into_par_iter()
            .map(|k| {
                let s = k as f64 * STEP;
                quad.iter().map(|&(t, w)| w * bessel_j0(t * s)).sum()
            })
            .collect();
        Self { nu, base, values }
    }

    /// The table of `nu` and `base`, computed once per process and shared.
    pub fn shared(nu: f64, base: Base) -> Arc<Self> {
        static CACHE: OnceLock<Mutex<Vec<Arc<LayerTable>>>> = OnceLock::new();
        let cache = CACHE.get_or_init(|| Mutex::new(Vec::new()));
        // A poisoned lock only means another thread panicked while tabulating: recompute.
        if let Ok(list) = cache.lock() {
            if let Some(t) = list
                .iter()
                .find(|t| t.nu.to_bits() == nu.to_bits() && t.base == base)
            {
                return Arc::clone(t);
            }
        }
        let table = Arc::new(Self::new(nu, base));
        if let Ok(mut list) = cache.lock() {
            list.push(Arc::clone(&table));
        }
        table
    }

    /// F(s), 0 ≤ s ≤ LAYER_CUTOFF, by 6-point Lagrange interpolation (F is even: the stencil
    /// reflects about s = 0). Error ~ STEP⁶/720 · |F⁽⁶⁾| ≈ 1e−13 (tested).
    pub fn correction(&self, s: f64) -> f64 {
        let x = s / STEP;
        let i0 = (x.floor() as isize - 2).min(self.values.len() as isize - 6);
        let mut sum = 0.0;
        for j in 0..6 {
            let mut l = 1.0;
            for m in 0..6 {
                if m != j {
                    l *= (x - (i0 + m) as f64) / (j - m) as f64;
                }
            }
            sum += l * self.values[(i0 + j).unsigned_abs()];
        }
        sum
    }

    /// The layer kernel G(ρ) for depth `depth` (same length unit as ρ), ρ > 0: 1/ρ − F(ρ/h)/h
    /// within [`LAYER_CUTOFF`] depths, 0 beyond.
    pub fn kernel(&self, rho: f64, depth: f64) -> f64 {
        let s = rho / depth;
        if s >= LAYER_CUTOFF {
            return 0.0;
        }
        1.0 / rho - self.correction(s) / depth
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Matrix2, Matrix4, Vector2};

    /// K(t) from a numerical solution of the layer's Navier equations (plane strain, E = 1,
    /// ξ = 1, depth t): u = U(z) sin x, w = W(z) cos x, τ_xz = T(z) sin x, σ_zz = S(z) cos x
    /// satisfy y' = A y for y = (U, W, T, S) (from the strain–displacement law, Hooke and the
    /// two equilibrium equations); y(h) = exp(A h) y(0) with y(0) = (U₀, W₀, 0, −1) (no shear,
    /// unit pressure) and u = w = 0 at the base give U₀, W₀; K = W₀ · E ξ / (2(1 − ν²)).
    fn symbol_by_navier(t: f64, nu: f64, base: Base) -> f64 {
        let e = 1.0;
        let lam = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
        let mu = e / (2.0 * (1.0 + nu));
        let m = lam + 2.0 * mu;
        let a = Matrix4::new(
            0.0,
            1.0,
            1.0 / mu,
            0.0,
            -lam / m,
            0.0,
            0.0,
            1.0 / m,
            4.0 * mu * (lam + mu) / m,
            0.0,
            0.0,
            lam / m,
            0.0,
            0.0,
            -1.0,
            0.0,
        );
        let phi = (a * t).exp();
        // Rough: U = W = 0 at the base; smooth: T = W = 0.
        let r0 = if base == Base::Rough { 0 } else { 2 };
        let lhs = Matrix2::new(phi[(r0, 0)], phi[(r0, 1)], phi[(1, 0)], phi[(1, 1)]);
        let rhs = Vector2::new(phi[(r0, 3)], phi[(1, 3)]);
        let x = lhs
            .lu()
            .solve(&rhs)
            .expect("2 × 2 base conditions are regular");
        x[1] * e / (2.0 * (1.0 - nu * nu))
    }

    /// The closed form against the Navier solution, over depths from a tenth of a wavelength to
    /// many and ν from 0 to 0.49: agreement to 1e−10 (the matrix exponential's round-off grows
    /// like e^{2t} cond; at t = 5 it is ~1e−12).
    #[test]
    fn closed_form_symbol_matches_navier_solution() {
        for base in [Base::Rough, Base::Smooth] {
            for nu in [0.0, 0.25, 0.3, 0.45, 0.49] {
                for t in [0.05, 0.2, 0.5, 1.0, 2.0, 3.5, 5.0] {
                    let closed = symbol(t, nu, base);
                    let navier = symbol_by_navier(t, nu, base);
                    assert!(
                        (closed - navier).abs() < 1e-10 * closed.abs().max(1e-3),
                        "{base:?}, ν = {nu}, t = {t}: closed form K = {closed}, Navier {navier}"
                    );
                    assert!(
                        (one_minus_symbol(t, nu, base) - (1.0 - closed)).abs() < 1e-14,
                        "1 − K form, {base:?}, ν = {nu}, t = {t}"
                    );
                }
            }
        }
        // The smooth base near t = 0 against its series t/2 − t⁵/90 (relative 1e−15).
        for t in [1e-6_f64, 1e-4] {
            let series = 0.5 * t - t.powi(5) / 90.0;
            let k = symbol(t, 0.3, Base::Smooth);
            assert!(
                (k - series).abs() < 1e-15 * series,
                "t = {t}: {k} vs {series}"
            );
        }
    }

    /// Limits: K → 1 for deep layers (1 − K ≈ (4t² + 4t + 1 + κ²)e^{−2t}/κ, so below 1e−15 at
    /// t = 25) and K(t)/t → (1 − 2ν)/(2(1 − ν)²) for thin ones with an O(t²) remainder
    /// (K/t is even): the relative error at t = 1e−3 is below 1e−5. The smooth base likewise,
    /// K/t → 1/2.
    #[test]
    fn symbol_limits_are_half_space_and_oedometric_winkler() {
        for nu in [0.0, 0.3, 0.45] {
            for base in [Base::Rough, Base::Smooth] {
                assert!(
                    (symbol(25.0, nu, base) - 1.0).abs() < 1e-15,
                    "deep, ν = {nu}"
                );
                assert!(
                    (symbol(400.0, nu, base) - 1.0).abs() < 1e-15,
                    "very deep, ν = {nu}"
                );
            }
            // Smooth: K/t → 1/2 with an O(t⁴) remainder (−t⁴/45).
            let rel = (symbol(1e-2, nu, Base::Smooth) / 1e-2 - 0.5).abs() / 0.5;
            assert!(rel < 1e-3, "thin smooth: {rel}");
            // The closed form's slope, written out here (not Base::slope).
            let slope = (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu) * (1.0 - nu));
            for t in [1e-3, 1e-2] {
                let rel = (symbol(t, nu, Base::Rough) / t - slope).abs() / slope;
                assert!(rel < 0.5 * t, "thin, ν = {nu}, t = {t}: K/t off by {rel}");
            }
            // Base::slope (which the groups use for the layer's long-wave bed C(0)) is the
            // limit of K(t)/t of the Navier solution, which shares nothing with the closed
            // forms: at t = 1e−3 the O(t²) remainder is below 1e−6 (rough) or O(t⁴) (smooth),
            // the matrix exponential's round-off ~1e−13 relative.
            for base in [Base::Rough, Base::Smooth] {
                let navier = symbol_by_navier(1e-3, nu, base) / 1e-3;
                assert!(
                    (base.slope(nu) - navier).abs() < 1e-5 * navier,
                    "Base::slope, {base:?}, ν = {nu}: {} against the Navier K(t)/t {navier}",
                    base.slope(nu)
                );
            }
            // C(0)·E = 2(1 − ν²)·slope·h = h E/E_oed for the rough base, E_oed written out:
            // E_oed/E = (1 − ν)/((1 + ν)(1 − 2ν)).
            let e_oed = (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
            assert!(
                (2.0 * (1.0 - nu * nu) * Base::Rough.slope(nu) - 1.0 / e_oed).abs() < 1e-14,
                "Base::slope, rough, ν = {nu}: C(0) E/h = {} against 1/E_oed = {}",
                2.0 * (1.0 - nu * nu) * Base::Rough.slope(nu),
                1.0 / e_oed
            );
            // The smooth base's bed is E/((1 − ν²)h): C(0)·E/h = 2(1 − ν²)·slope = 1 − ν².
            assert!(
                (2.0 * (1.0 - nu * nu) * Base::Smooth.slope(nu) - (1.0 - nu * nu)).abs() < 1e-14,
                "Base::slope, smooth, ν = {nu}"
            );
        }
    }

    /// J₀ against tabulated values (A&S Table 9.1; DLMF): J₀(0.5) = 0.938469807240813,
    /// J₀(1) = 0.765197686557967, J₀(2.404825557695773) = 0 (first zero), J₀(5) =
    /// −0.177596771314338, J₀(10) = −0.245935764451348, J₀(50) = 0.055812327669252.
    #[test]
    fn j0_matches_tables() {
        for (x, v) in [
            (0.0, 1.0),
            (0.5, 0.938_469_807_240_813),
            (1.0, 0.765_197_686_557_967),
            (2.404_825_557_695_773, 0.0),
            (5.0, -0.177_596_771_314_338),
            (10.0, -0.245_935_764_451_348),
            (50.0, 0.055_812_327_669_252),
        ] {
            let j = bessel_j0(x);
            assert!((j - v).abs() < 1e-14, "J0({x}) = {j}, table {v}");
        }
    }

    /// The table against direct quadrature off its nodes (interpolation error), and the
    /// quadrature itself against two independent facts: F(0) = ∫₀^∞ (1 − K) dt by a plain
    /// composite trapezoid on a fine grid, and G(s) = 1/s − F(s) → 0 for s ≫ 1 (the layer's
    /// kernel decays exponentially: |G(25)| < 1e−12).
    #[test]
    fn correction_table_interpolates_and_decays() {
        let nu = 0.3;
        for base in [Base::Smooth, Base::Rough] {
            let table = LayerTable::new(nu, base);
            for s in [0.0, 0.003, 0.37, 1.01, 2.5, 7.77, 19.3, 39.9] {
                let d = correction_direct(s, nu, base);
                let i = table.correction(s);
                assert!(
                    (d - i).abs() < 1e-11,
                    "{base:?}: F({s}): table {i}, direct {d}"
                );
            }
            assert!(table.kernel(30.0, 1.0).abs() < 1e-12, "{base:?}");
        }
        let table = LayerTable::new(nu, Base::Rough);
        let n = 300_000;
        let h = T_MAX / n as f64;
        let trap: f64 = (0..=n)
            .map(|k| {
                let w = if k == 0 || k == n { 0.5 } else { 1.0 };
                w * h * one_minus_symbol(k as f64 * h, nu, Base::Rough)
            })
            .sum();
        assert!(
            (trap - table.correction(0.0)).abs() < 1e-9,
            "F(0): trapezoid {trap}, table {}",
            table.correction(0.0)
        );
        assert!(table.kernel(25.0, 1.0).abs() < 1e-12);
        assert_eq!(table.kernel(41.0, 1.0), 0.0);
    }
}
