//! FAARFIELD's rigid failure model (FAARFIELD 2.1.1) in the design factor R/σ, counting
//! coverages.

use serde::{Deserialize, Serialize};

use super::keys::{finite, positive};
use crate::error::{Error, Result};

/// FAARFIELD's rigid failure model (FAA FAARFIELD 2.1.1, `modFAILURE_MODEL_NP.vb`,
/// `LeafCDFRigid_2014`, "David's model": D. Brill), in coverages C to a structural condition
/// index SCI, with DF = R/σ, S = 1 − SCI/100 and F's the stabilised-base factor:
///
/// log₁₀ C = A/B,  A = DF − [S(ad − bc) + F's·b·c] / [S(d − b) + F's·b],
/// B = F's·b·d / [S(d − b) + F's·b],
///
/// i.e. DF = [S(ad − bc) + F's·b·(c + d log₁₀ C)] / [S(d − b) + F's·b]: at SCI = 100 (first
/// crack) and F's = 1, DF = c + d log₁₀ C; at SCI = 0, DF = a + b log₁₀ C. log₁₀ C is capped at
/// 10, as FAARFIELD caps it for a new rigid pavement (its "overflow"), so the cap gives 1e10.
/// Confirmed: the formula, the defaults a = 1.027, b = 0.16, c = 1.1, d = 0.16, the cap, and
/// SCI = 80 for a new rigid design were read in the FAARFIELD 2.1.1 source.
///
/// FAARFIELD 2.1.1 itself replaces a and c by functions of the subgrade modulus; here that is
/// [`Faa::with_subgrade`], not the default (the defaults are its values at E_SG = 15 000 psi).
/// F's (key `stabilised_base_factor`) is FAARFIELD's `CompforStab` of the layers under the
/// slab, 1 for none; it is given here, not computed. No 25 % reduction of the edge stress for
/// load transfer is applied: liftoff models the joints, and the reduction would count their
/// load transfer twice. N is in coverages: the caller turns passes into coverages.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Faa {
    /// Coefficient a (key `a`): DF at one coverage to SCI = 0 (F's = 1), default 1.027.
    pub a: f64,
    /// Coefficient b (key `b`): slope of DF against log₁₀ C at SCI = 0, default 0.16.
    pub b: f64,
    /// Coefficient c (key `c`): DF at one coverage to first crack (SCI = 100), default 1.1.
    pub c: f64,
    /// Coefficient d (key `d`): slope of DF against log₁₀ C at SCI = 100, default 0.16.
    pub d: f64,
    /// The structural condition index failure is counted at (key `sci`), 0..100, default 80
    /// (FAARFIELD's new rigid design).
    pub sci: f64,
    /// F's, the stabilised-base factor (key `stabilised_base_factor`), default 1.0 (no
    /// stabilised base).
    pub stabilised_base_factor: f64,
}

impl Default for Faa {
    fn default() -> Self {
        Faa {
            a: 1.027,
            b: 0.16,
            c: 1.1,
            d: 0.16,
            sci: 80.0,
            stabilised_base_factor: 1.0,
        }
    }
}

impl Faa {
    /// FAARFIELD's cap on log₁₀ C for a new rigid pavement.
    pub const LOG_CAP: f64 = 10.0;
    /// The coverages at the cap, 10^[`Faa::LOG_CAP`].
    pub const CAPPED_COVERAGES: f64 = 1e10;

    /// The denominator S(d − b) + F's·b of the model.
    fn denominator(&self) -> f64 {
        (1.0 - self.sci / 100.0) * (self.d - self.b) + self.stabilised_base_factor * self.b
    }

    /// log₁₀ C at design factor `df` = R/σ, uncapped.
    pub fn log_coverages(&self, df: f64) -> f64 {
        let s = 1.0 - self.sci / 100.0;
        let fs = self.stabilised_base_factor;
        let den = self.denominator();
        let a = df - (s * (self.a * self.d - self.b * self.c) + fs * self.b * self.c) / den;
        let b = fs * self.b * self.d / den;
        a / b
    }

    /// Coverages C for one cycle of `stress` on a concrete of flexural strength `rupture`
    /// (same units): 10^min(log₁₀ C, 10), so 1e10 at the cap; `f64::INFINITY` for σ ≤ 0.
    pub fn allowed_repetitions(&self, stress: f64, rupture: f64) -> f64 {
        if stress <= 0.0 {
            return f64::INFINITY;
        }
        let log_c = self.log_coverages(rupture / stress);
        if log_c > Self::LOG_CAP {
            Self::CAPPED_COVERAGES
        } else {
            10f64.powf(log_c)
        }
    }

    /// a and c as FAARFIELD 2.1.1 makes them of the subgrade modulus `e_sg_psi` (psi;
    /// "E(SG)-dependent failure model parameter", 2013), b and d unchanged:
    ///
    /// * E ≤ 4 500: a = 0.76, c = 0.857;
    /// * E > 4 500: a = 0.76 + 0.267 (E − 4 500)/10 500 (not capped: it passes 1.027 at
    ///   15 000 and keeps growing);
    /// * 4 500 < E < 45 000: c = 0.857 + 0.000023143 (E − 4 500);
    /// * E ≥ 45 000: c = 1.7942915 + 0.00002542857143 (E − 45 000).
    ///
    /// At E = 15 000 psi this gives the defaults (a = 1.027, c = 1.1 to 2e-6). A modulus that is
    /// not finite makes a and c NaN, which [`Faa::validate`] refuses.
    pub fn with_subgrade(mut self, e_sg_psi: f64) -> Self {
        let e = e_sg_psi;
        if e <= 4_500.0 {
            self.a = 0.76;
            self.c = 0.857;
        } else {
            self.a = 0.76 + (1.027 - 0.76) * (e - 4_500.0) / 10_500.0;
            self.c = if e >= 45_000.0 {
                1.794_291_5 + 0.000_025_428_571_43 * (e - 45_000.0)
            } else {
                0.857 + 0.000_023_143 * (e - 4_500.0)
            };
        }
        self
    }

    /// Every coefficient finite; a, b, c, d and F's positive, SCI in [0, 100], and the model's
    /// denominator S(d − b) + F's·b positive. An error names the key.
    pub fn validate(&self) -> Result<()> {
        positive("a", self.a)?;
        positive("b", self.b)?;
        positive("c", self.c)?;
        positive("d", self.d)?;
        if !(0.0..=100.0).contains(&finite("sci", self.sci)?) {
            return Err(Error::invalid(
                "damage.sci",
                format!(
                    "the structural condition index must lie in [0, 100], got {}",
                    self.sci
                ),
            ));
        }
        positive("stabilised_base_factor", self.stabilised_base_factor)?;
        let den = self.denominator();
        if den <= 0.0 {
            return Err(Error::invalid(
                "damage.d",
                format!(
                    "(1 − sci/100)(d − b) + stabilised_base_factor·b must be positive, got {den}: \
                     with d < b the slope at sci = {} turns over",
                    self.sci
                ),
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    // FAA ------------------------------------------------------------------------------------

    #[test]
    fn faa_first_crack_line() {
        // SCI = 100, F's = 1: DF = 1.1 + 0.16 log C.
        let f = Faa {
            sci: 100.0,
            ..Faa::default()
        };
        for df in [1.1, 1.2, 1.3, 1.5, 2.0, 2.6] {
            let expected = (df - 1.1) / 0.16;
            let got = f.allowed_repetitions(1.0 / df, 1.0).log10();
            assert!(
                (got - expected).abs() < 1e-9,
                "FAA SCI 100 at DF {df}: {got}"
            );
        }
    }

    #[test]
    fn faa_full_failure_line() {
        // SCI = 0, F's = 1: DF = 1.027 + 0.16 log C.
        let f = Faa {
            sci: 0.0,
            ..Faa::default()
        };
        for df in [1.1, 1.2, 1.3, 1.5, 2.0, 2.6] {
            let expected = (df - 1.027) / 0.16;
            let got = f.allowed_repetitions(1.0 / df, 1.0).log10();
            assert!((got - expected).abs() < 1e-9, "FAA SCI 0 at DF {df}: {got}");
        }
    }

    #[test]
    fn faa_default_sci_80_matches_the_notes_hand_values() {
        let f = Faa::default();
        for (df, log_c) in [(1.1, 0.0912), (1.2, 0.7162), (1.3, 1.3412), (1.5, 2.5912)] {
            let got = f.log_coverages(df);
            assert!((got - log_c).abs() < 1e-4, "FAA SCI 80 at DF {df}: {got}");
        }
    }

    #[test]
    fn faa_general_form_inverts() {
        // b ≠ d and F's ≠ 1: the relation solved for DF gives the DF back.
        let f = Faa {
            a: 0.9,
            b: 0.12,
            c: 1.2,
            d: 0.2,
            sci: 55.0,
            stabilised_base_factor: 1.4,
        };
        f.validate().unwrap();
        let s = 1.0 - f.sci / 100.0;
        let fs = f.stabilised_base_factor;
        for df in [1.0, 1.3, 1.9] {
            let lc = f.log_coverages(df);
            let back = (s * (f.a * f.d - f.b * f.c) + fs * f.b * (f.c + f.d * lc))
                / (s * (f.d - f.b) + fs * f.b);
            assert!((back - df).abs() < 1e-12, "FAA general at DF {df}: {back}");
        }
    }

    #[test]
    fn faa_caps_log_coverages_at_ten() {
        let f = Faa {
            sci: 100.0,
            ..Faa::default()
        };
        let df = 1.1 + 0.16 * 10.5;
        assert_eq!(f.allowed_repetitions(1.0 / df, 1.0), 1e10);
        let df = 1.1 + 0.16 * 9.9;
        let got = f.allowed_repetitions(1.0 / df, 1.0).log10();
        assert!((got - 9.9).abs() < 1e-9, "FAA below the cap: {got}");
        assert_eq!(f.allowed_repetitions(1e-6, 1.0), 1e10, "a tiny stress");
        assert_eq!(f.allowed_repetitions(0.0, 1.0), f64::INFINITY);
    }

    #[test]
    fn faa_subgrade_dependence() {
        let at = |e: f64| Faa::default().with_subgrade(e);
        let f = at(15_000.0);
        assert!((f.a - 1.027).abs() < 1e-12, "a at 15 000 psi: {}", f.a);
        assert!((f.c - 1.1).abs() < 2e-6, "c at 15 000 psi: {}", f.c);
        assert_eq!((f.b, f.d), (0.16, 0.16));
        let soft = at(3_000.0);
        assert_eq!((soft.a, soft.c), (0.76, 0.857));
        assert!(
            (at(4_500.0 + 1e-9).c - 0.857).abs() < 1e-9,
            "c continuous at 4 500"
        );
        let (below, above) = (at(45_000.0 - 1e-9), at(45_000.0));
        assert!(
            (below.c - above.c).abs() < 1e-6,
            "c at 45 000: {} {}",
            below.c,
            above.c
        );
        assert!((at(60_000.0).c - (1.794_291_5 + 0.000_025_428_571_43 * 15_000.0)).abs() < 1e-12);
        assert!(at(f64::NAN).validate().is_err());
    }
}
