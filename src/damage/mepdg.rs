//! The MEPDG's JPCP transverse cracking (AASHTO Manual of Practice, 2008): the fatigue
//! relation, the cracking transfer function and its reliability, with the normal deviate that
//! reliability needs.

use serde::{Deserialize, Serialize};

use super::keys::{finite, non_negative, positive};
use crate::error::{Error, Result};

/// The MEPDG's JPCP transverse cracking (AASHTO *Mechanistic-Empirical Pavement Design Guide,
/// A Manual of Practice*, interim edition, July 2008).
///
/// * Fatigue: log₁₀ N = C1 (MR/σ)^C2 + 0.4371, C1 = 2.0, C2 = 1.22. As pinned by issue 33 from
///   the MoP 2008; not checked against the MoP's own text here (C1, C2 and the offset 0.4371,
///   whose origin the MoP does not explain, are from memory in the research notes).
/// * Cracking ([`Mepdg::cracking`]): CRK = 1/(1 + C4 FD^C5), the fraction of slabs cracked at
///   fatigue damage FD, C4 = 1.0, C5 = −1.98. Confirmed: the MoP 2008's transfer function
///   CRK = 1/(1 + FD^−1.98) was read in a page quoting it.
/// * Bottom-up and top-down cracking combine as b + t − b·t ([`Mepdg::total_cracking`]): a
///   slab cracks one way or the other, not both (confirmed, same page).
/// * Reliability ([`Mepdg::cracking_at_reliability`]): the standard error
///   s = 5.3116 CRACK^0.3903 + 3.36 (percent). As pinned by issue 33 from the MoP 2008; not
///   checked against the MoP's own text here.
///
/// Every coefficient is a key of `[damage]` for a local calibration (later global
/// recalibrations of Pavement ME changed C4 and C5; their values are not confirmed here, so the
/// defaults stay the 2008 ones). MR is the modulus of rupture at the age of the cycle.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Mepdg {
    /// Fatigue coefficient C1 (key `c1`), default 2.0.
    pub c1: f64,
    /// Fatigue exponent C2 (key `c2`), default 1.22.
    pub c2: f64,
    /// Cracking coefficient C4 (key `c4`), default 1.0.
    pub c4: f64,
    /// Cracking exponent C5 (key `c5`), default −1.98; negative, so that cracking grows with
    /// damage.
    pub c5: f64,
    /// Standard error of cracking, factor (key `se_a`, percent), default 5.3116.
    pub se_a: f64,
    /// Standard error of cracking, exponent (key `se_b`), default 0.3903.
    pub se_b: f64,
    /// Standard error of cracking, constant (key `se_c`, percent), default 3.36.
    pub se_c: f64,
}

impl Default for Mepdg {
    fn default() -> Self {
        Mepdg {
            c1: 2.0,
            c2: 1.22,
            c4: 1.0,
            c5: -1.98,
            se_a: 5.3116,
            se_b: 0.3903,
            se_c: 3.36,
        }
    }
}

impl Mepdg {
    /// The constant term of log₁₀ N, as pinned by issue 33 from the MoP 2008 (not a calibration
    /// coefficient there).
    pub const LOG_OFFSET: f64 = 0.4371;

    /// N for one cycle of `stress` on a concrete of modulus of rupture `rupture` (same units):
    /// log₁₀ N = C1 (MR/σ)^C2 + 0.4371; `f64::INFINITY` for σ ≤ 0.
    pub fn allowed_repetitions(&self, stress: f64, rupture: f64) -> f64 {
        if stress <= 0.0 {
            return f64::INFINITY;
        }
        10f64.powf(self.c1 * (rupture / stress).powf(self.c2) + Self::LOG_OFFSET)
    }

    /// The fraction of slabs cracked (0..1) at fatigue damage `damage` = FD ≥ 0:
    /// 1/(1 + C4 FD^C5). Zero damage cracks none; FD = 1 cracks 1/(1 + C4).
    pub fn cracking(&self, damage: f64) -> f64 {
        1.0 / (1.0 + self.c4 * damage.powf(self.c5))
    }

    /// Bottom-up and top-down cracking (fractions, 0..1) combined: b + t − b·t, a slab counted
    /// once whichever way it cracks.
    pub fn total_cracking(bottom: f64, top: f64) -> f64 {
        bottom + top - bottom * top
    }

    /// Cracking at a design `reliability` in (0, 1) (0.9 for 90 %), from the mean predicted
    /// `mean_percent` (percent of slabs, 0..100): mean + z_R · s(mean), with s = se_a
    /// mean^se_b + se_c and z_R the standard normal deviate of the reliability, held to
    /// [0, 100] %. A reliability outside (0, 1) gives NaN.
    pub fn cracking_at_reliability(&self, mean_percent: f64, reliability: f64) -> f64 {
        let s = self.se_a * mean_percent.powf(self.se_b) + self.se_c;
        let z = normal_deviate(reliability);
        (mean_percent + z * s).clamp(0.0, 100.0)
    }

    /// Every coefficient finite; C1, C2, C4 positive, C5 negative, the standard error's terms
    /// not negative. An error names the key.
    pub fn validate(&self) -> Result<()> {
        positive("c1", self.c1)?;
        positive("c2", self.c2)?;
        positive("c4", self.c4)?;
        if finite("c5", self.c5)? >= 0.0 {
            return Err(Error::invalid(
                "damage.c5",
                format!(
                    "must be negative (cracking grows with damage; the MEPDG's is −1.98), got {}",
                    self.c5
                ),
            ));
        }
        non_negative("se_a", self.se_a)?;
        non_negative("se_b", self.se_b)?;
        non_negative("se_c", self.se_c)?;
        Ok(())
    }
}

/// The standard normal deviate z of a probability p in (0, 1): Φ(z) = p. NaN outside (0, 1);
/// z(0.5) = 0 exactly.
///
/// Acklam's rational approximation (relative error below 1.15e-9), refined by one Halley step
/// on Φ(z) = ½ erfc(−z/√2), which brings it to about machine precision.
pub fn normal_deviate(p: f64) -> f64 {
    if p.is_nan() || p <= 0.0 || p >= 1.0 {
        return f64::NAN;
    }
    // The upper half by symmetry: 1 − p is exact for p ≥ 0.5, and the lower half's Halley
    // step evaluates Φ(z) where erfc is accurate, at z ≤ 0.
    if p > 0.5 {
        -lower_deviate(1.0 - p)
    } else {
        lower_deviate(p)
    }
}

/// [`normal_deviate`] for p in (0, 0.5].
fn lower_deviate(p: f64) -> f64 {
    const A: [f64; 6] = [
        -3.969_683_028_665_376e1,
        2.209_460_984_245_205e2,
        -2.759_285_104_469_687e2,
        1.383_577_518_672_69e2,
        -3.066_479_806_614_716e1,
        2.506_628_277_459_239,
    ];
    const B: [f64; 5] = [
        -5.447_609_879_822_406e1,
        1.615_858_368_580_409e2,
        -1.556_989_798_598_866e2,
        6.680_131_188_771_972e1,
        -1.328_068_155_288_572e1,
    ];
    const C: [f64; 6] = [
        -7.784_894_002_430_293e-3,
        -3.223_964_580_411_365e-1,
        -2.400_758_277_161_838,
        -2.549_732_539_343_734,
        4.374_664_141_464_968,
        2.938_163_982_698_783,
    ];
    const D: [f64; 4] = [
        7.784_695_709_041_462e-3,
        3.224_671_290_700_398e-1,
        2.445_134_137_142_996,
        3.754_408_661_907_416,
    ];
    // Below this, Acklam's tail form; above, the central one.
    const P_LOW: f64 = 0.02425;
    let z = if p < P_LOW {
        let q = (-2.0 * p.ln()).sqrt();
        (((((C[0] * q + C[1]) * q + C[2]) * q + C[3]) * q + C[4]) * q + C[5])
            / ((((D[0] * q + D[1]) * q + D[2]) * q + D[3]) * q + 1.0)
    } else {
        let q = p - 0.5;
        let r = q * q;
        (((((A[0] * r + A[1]) * r + A[2]) * r + A[3]) * r + A[4]) * r + A[5]) * q
            / (((((B[0] * r + B[1]) * r + B[2]) * r + B[3]) * r + B[4]) * r + 1.0)
    };
    // One Halley step on Φ(z) − p.
    let e = 0.5 * libm::erfc(-z / std::f64::consts::SQRT_2) - p;
    let u = e * (2.0 * std::f64::consts::PI).sqrt() * (0.5 * z * z).exp();
    z - u / (1.0 + 0.5 * z * u)
}

#[cfg(test)]
mod tests {
    use super::*;

    // MEPDG ----------------------------------------------------------------------------------

    #[test]
    fn mepdg_cracking_is_one_half_at_unit_damage() {
        let m = Mepdg::default();
        assert_eq!(m.cracking(1.0), 0.5);
        assert_eq!(m.cracking(0.0), 0.0, "MEPDG cracking at no damage");
    }

    #[test]
    fn mepdg_cracking_at_a_tenth() {
        let m = Mepdg::default();
        let (c4, c5, fd) = (1.0, -1.98, 0.1f64);
        let expected = 1.0 / (1.0 + c4 * fd.powf(c5));
        assert!((m.cracking(0.1) - expected).abs() < 1e-15);
        assert!(
            (m.cracking(0.1) - 0.010_363).abs() < 1e-6,
            "{}",
            m.cracking(0.1)
        );
    }

    #[test]
    fn mepdg_fatigue_at_ratio_two() {
        let m = Mepdg::default();
        let expected = 2.0 * 2f64.powf(1.22) + 0.4371;
        // MR/σ = 2: σ = 2.5, MR = 5 (any units).
        let got = m.allowed_repetitions(2.5, 5.0).log10();
        assert!(
            (got - expected).abs() < 1e-12,
            "MEPDG log N {got}, {expected}"
        );
        assert_eq!(m.allowed_repetitions(0.0, 5.0), f64::INFINITY);
    }

    #[test]
    fn mepdg_total_cracking() {
        assert_eq!(Mepdg::total_cracking(0.5, 0.5), 0.75);
        assert_eq!(Mepdg::total_cracking(0.0, 0.3), 0.3);
        assert_eq!(Mepdg::total_cracking(1.0, 0.3), 1.0);
    }

    #[test]
    fn normal_deviate_against_tables() {
        // Tabulated to four decimals.
        for (p, z) in [(0.9, 1.2816), (0.95, 1.6449), (0.99, 2.3263)] {
            assert!(
                (normal_deviate(p) - z).abs() < 5e-5,
                "z({p}) = {}",
                normal_deviate(p)
            );
        }
        assert_eq!(normal_deviate(0.5), 0.0);
        // Full precision, as Python's statistics.NormalDist().inv_cdf (Wichura's AS241) gives.
        for (p, z) in [
            (0.75, 0.674_489_750_196_081_7),
            (0.9, 1.281_551_565_544_600_8),
            (0.95, 1.644_853_626_951_471_5),
            (0.975, 1.959_963_984_540_053_6),
            (0.99, 2.326_347_874_040_840_8),
            (0.999, 3.090_232_306_167_813),
            (0.02, -2.053_748_910_631_822_5),
            (0.03, -1.880_793_608_151_250_9),
            (1e-10, -6.361_340_902_404_056),
        ] {
            let got = normal_deviate(p);
            assert!(
                (got - z).abs() < 1e-12 * z.abs().max(1.0),
                "z({p}) = {got}, {z}"
            );
            if p > 0.01 {
                assert!((normal_deviate(1.0 - p) + got).abs() < 1e-12, "z(1 − {p})");
            }
        }
        assert!(normal_deviate(0.0).is_nan() && normal_deviate(1.0).is_nan());
        assert!(normal_deviate(f64::NAN).is_nan());
    }

    #[test]
    fn mepdg_reliability() {
        let m = Mepdg::default();
        assert_eq!(m.cracking_at_reliability(10.0, 0.5), 10.0);
        let s = 5.3116 * 10f64.powf(0.3903) + 3.36;
        let got = m.cracking_at_reliability(10.0, 0.9);
        assert!(
            (got - (10.0 + 1.281_551_565_544_600_8 * s)).abs() < 1e-10,
            "{got}"
        );
        assert_eq!(
            m.cracking_at_reliability(95.0, 0.99),
            100.0,
            "capped at 100 %"
        );
        assert_eq!(m.cracking_at_reliability(0.0, 0.1), 0.0, "held at 0 %");
        assert!(m.cracking_at_reliability(10.0, 1.0).is_nan());
    }
}
