//! Fatigue relations of concrete: how many cycles of a tensile stress a slab allows.
//!
//! Each relation takes one cycle of tensile stress σ and the modulus of rupture (flexural
//! strength) MR, in the same units, and gives the allowed repetitions N
//! ([`DamageModel::allowed_repetitions`]); [`miner`] adds the damage Σ n/N of a traffic. A
//! stress σ ≤ 0 (no tension) allows unlimited cycles, `f64::INFINITY`; so does a stress ratio
//! below a relation's endurance limit.
//!
//! * [`Pca`]: the Portland Cement Association's 1984 fatigue curve (EB109, 1984; closed form
//!   from Packard & Tayabji, TRR 1043, 1985).
//! * [`Mepdg`]: the MEPDG's JPCP transverse-cracking fatigue curve and transfer function (AASHTO
//!   Mechanistic-Empirical Pavement Design Guide, Manual of Practice, interim edition, July
//!   2008), with its reliability.
//! * [`Faa`]: FAARFIELD's rigid failure model (FAARFIELD 2.1.1, `LeafCDFRigid_2014`, D. Brill),
//!   which counts coverages.
//!
//! The stress is liftoff's own, at the joint or edge where it occurs: the relations apply
//! neither the PCA's edge-stress factor nor FAARFIELD's 25 % reduction of the edge stress for
//! load transfer — liftoff models the joints, and either factor would count their load
//! transfer twice.
//!
//! A scene's `[damage]` table names the relation with `model = "pca" | "mepdg" | "faa"` and may
//! set each of its coefficients (a local calibration); a key the relation does not take is
//! refused. Each relation has its file ([`super::pca`], [`super::mepdg`], [`super::faa`]); this
//! one names them as the scene's `[damage]` table does, and adds their cycles. A floor: it
//! imports nothing of liftoff's but [`crate::error`] and its sibling relations.

use serde::{Deserialize, Serialize};

pub use super::faa::Faa;
pub use super::mepdg::{normal_deviate, Mepdg};
pub use super::pca::Pca;
use crate::error::Result;

/// A fatigue relation with its coefficients: the scene's `[damage]` table.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "model", rename_all = "lowercase")]
pub enum DamageModel {
    /// PCA 1984 (`model = "pca"`): no coefficients.
    Pca(Pca),
    /// MEPDG, Manual of Practice 2008 (`model = "mepdg"`).
    Mepdg(Mepdg),
    /// FAARFIELD 2.1.1 rigid failure model (`model = "faa"`).
    Faa(Faa),
}

impl DamageModel {
    /// The cycles N of tensile stress `stress` that a concrete of modulus of rupture `rupture`
    /// (same units) allows: `f64::INFINITY` where unlimited, always for `stress` ≤ 0. For
    /// [`Faa`] these are coverages.
    pub fn allowed_repetitions(&self, stress: f64, rupture: f64) -> f64 {
        match self {
            DamageModel::Pca(m) => m.allowed_repetitions(stress, rupture),
            DamageModel::Mepdg(m) => m.allowed_repetitions(stress, rupture),
            DamageModel::Faa(m) => m.allowed_repetitions(stress, rupture),
        }
    }

    /// The coefficients checked; an error names the bad key as `damage.<key>`.
    pub fn validate(&self) -> Result<()> {
        match self {
            DamageModel::Pca(m) => m.validate(),
            DamageModel::Mepdg(m) => m.validate(),
            DamageModel::Faa(m) => m.validate(),
        }
    }
}

/// Miner's damage Σ n/N over `(n, N)` pairs: n applied cycles of a stress that allows N. An
/// unlimited N (infinite) and n = 0 add nothing.
pub fn miner(cycles: &[(f64, f64)]) -> f64 {
    cycles
        .iter()
        .map(|&(n, allowed)| {
            if n == 0.0 || allowed.is_infinite() {
                0.0
            } else {
                n / allowed
            }
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::Error;
    use proptest::prelude::*;

    /// log₁₀ N of a model at a stress ratio, with MR = 1.
    fn log_n(m: &DamageModel, ratio: f64) -> f64 {
        m.allowed_repetitions(ratio, 1.0).log10()
    }

    // Every relation -------------------------------------------------------------------------

    fn models() -> [DamageModel; 3] {
        [
            DamageModel::Pca(Pca::default()),
            DamageModel::Mepdg(Mepdg::default()),
            DamageModel::Faa(Faa::default()),
        ]
    }

    proptest! {
        #[test]
        fn a_larger_stress_allows_fewer_repetitions(r1 in 0.05f64..1.5, r2 in 0.05f64..1.5) {
            let (lo, hi) = if r1 < r2 { (r1, r2) } else { (r2, r1) };
            for m in models() {
                let (n_lo, n_hi) = (m.allowed_repetitions(lo, 1.0), m.allowed_repetitions(hi, 1.0));
                prop_assert!(n_hi <= n_lo, "{:?}: N({}) = {} > N({}) = {}", m, hi, n_hi, lo, n_lo);
            }
        }
    }

    #[test]
    fn mepdg_is_strictly_monotone() {
        let m = DamageModel::Mepdg(Mepdg::default());
        let logs: Vec<f64> = (1..=20).map(|i| log_n(&m, 0.1 * i as f64)).collect();
        assert!(logs.windows(2).all(|w| w[1] < w[0]), "MEPDG log N {logs:?}");
    }

    #[test]
    fn miner_adds_fractions() {
        assert_eq!(miner(&[]), 0.0);
        let d = miner(&[(1e4, 1e5), (5e3, f64::INFINITY), (2e4, 4e4), (0.0, 0.0)]);
        assert!((d - 0.6).abs() < 1e-15, "Miner {d}");
    }

    // Keys -----------------------------------------------------------------------------------

    #[derive(Debug, Deserialize)]
    struct Scene {
        damage: DamageModel,
    }

    fn read(text: &str) -> std::result::Result<DamageModel, String> {
        toml::from_str::<Scene>(text)
            .map(|s| s.damage)
            .map_err(|e| e.to_string())
    }

    #[test]
    fn damage_tables_read_with_defaults() {
        assert_eq!(
            read("[damage]\nmodel = \"pca\"\n").unwrap(),
            DamageModel::Pca(Pca::default())
        );
        assert_eq!(
            read("[damage]\nmodel = \"mepdg\"\n").unwrap(),
            DamageModel::Mepdg(Mepdg::default())
        );
        assert_eq!(
            read("[damage]\nmodel = \"mepdg\"\nc4 = 0.52\nc5 = -2.17\n").unwrap(),
            DamageModel::Mepdg(Mepdg {
                c4: 0.52,
                c5: -2.17,
                ..Mepdg::default()
            })
        );
        assert_eq!(
            read("[damage]\nmodel = \"faa\"\nsci = 100\nstabilised_base_factor = 0.9\n").unwrap(),
            DamageModel::Faa(Faa {
                sci: 100.0,
                stabilised_base_factor: 0.9,
                ..Faa::default()
            })
        );
        for m in models() {
            let back: DamageModel =
                serde_json::from_value(serde_json::to_value(m).unwrap()).unwrap();
            assert_eq!(back, m, "round trip of {m:?}");
        }
    }

    #[test]
    fn damage_tables_refuse_foreign_keys() {
        for (text, word) in [
            ("model = \"pca\"\nc1 = 2.0", "c1"),
            ("model = \"mepdg\"\nerosion_c2 = 0.06", "erosion_c2"),
            ("model = \"mepdg\"\na = 1.0", "a"),
            ("model = \"faa\"\nc5 = -2.0", "c5"),
            ("model = \"weibull\"", "weibull"),
            ("c1 = 2.0", "model"),
        ] {
            let err = read(&format!("[damage]\n{text}\n")).unwrap_err();
            assert!(err.contains(word), "`{text}` refused with: {err}");
        }
    }

    fn field_of(r: Result<()>) -> String {
        match r {
            Err(Error::Invalid { field, .. }) => field,
            other => panic!("expected Error::Invalid, got {other:?}"),
        }
    }

    #[test]
    fn validation_names_the_key() {
        for m in models() {
            m.validate().unwrap();
        }
        let mepdg = Mepdg::default();
        for (bad, key) in [
            (Mepdg { c1: -1.0, ..mepdg }, "damage.c1"),
            (
                Mepdg {
                    c2: f64::NAN,
                    ..mepdg
                },
                "damage.c2",
            ),
            (Mepdg { c4: 0.0, ..mepdg }, "damage.c4"),
            (Mepdg { c5: 1.98, ..mepdg }, "damage.c5"),
            (
                Mepdg {
                    se_a: -1.0,
                    ..mepdg
                },
                "damage.se_a",
            ),
            (
                Mepdg {
                    se_b: f64::INFINITY,
                    ..mepdg
                },
                "damage.se_b",
            ),
            (
                Mepdg {
                    se_c: -0.1,
                    ..mepdg
                },
                "damage.se_c",
            ),
        ] {
            assert_eq!(field_of(DamageModel::Mepdg(bad).validate()), key);
        }
        let faa = Faa::default();
        for (bad, key) in [
            (Faa { a: 0.0, ..faa }, "damage.a"),
            (Faa { b: -0.16, ..faa }, "damage.b"),
            (Faa { c: f64::NAN, ..faa }, "damage.c"),
            (Faa { d: 0.0, ..faa }, "damage.d"),
            (Faa { sci: 120.0, ..faa }, "damage.sci"),
            (Faa { sci: -1.0, ..faa }, "damage.sci"),
            (
                Faa {
                    stabilised_base_factor: 0.0,
                    ..faa
                },
                "damage.stabilised_base_factor",
            ),
            // d well below b at SCI = 0 with a small F's turns the denominator over.
            (
                Faa {
                    b: 0.5,
                    d: 0.1,
                    sci: 0.0,
                    stabilised_base_factor: 0.5,
                    ..faa
                },
                "damage.d",
            ),
        ] {
            assert_eq!(field_of(DamageModel::Faa(bad).validate()), key);
        }
    }
}
