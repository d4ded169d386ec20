//! Crovetti's finite-slab correction of the AREA method (`backcalc::finite_slab`), against a
//! reference it was not fitted to: liftoff's own square slabs on springs, bonded, the FWD's
//! plate at the centre. Crovetti fitted his factors to another program's thin-plate elements;
//! liftoff's slabs are Mindlin plates, whose shear raises the centre deflection of the infinite
//! plate too (`tests/circle_load.rs`). So the reference here is not the true k and ℓ but the
//! AREA method's reading of the same model on a slab large enough to be infinite (20 ℓ):
//! what the correction must give back on the small slabs is that reading, and the shear's
//! share, common to both, cancels.

use crate::common;
use liftoff::backcalc::{area_method, crovetti_factors, finite_slab, Basin, Subgrade};

/// 200 mm of concrete on k = 60 MN/m³: ℓ = 0.764 m, h/ℓ = 0.26; a 40 kN drop on the 150 mm
/// plate.
const E: f64 = 30e9;
const NU: f64 = 0.15;
const H: f64 = 0.20;
const K: f64 = 6.0e7;
const RADIUS: f64 = 0.15;
const FORCE: f64 = 40e3;
const SENSORS: [f64; 7] = [0.0, 0.203, 0.305, 0.457, 0.610, 0.914, 1.219];

fn ell() -> f64 {
    (E * H.powi(3) / (12.0 * (1.0 - NU * NU)) / K).powf(0.25)
}

/// The basin at the sensors on the slab, along x from the centre of a square bonded slab of
/// side `side`, its elements no wider than 0.1 m (0.67 of the plate's radius: within 1 % of the
/// infinite plate at every sensor, `tests/circle_load.rs`).
fn basin(side: f64) -> Basin {
    let n = ((side / 0.1).ceil() as usize).max(8);
    let offsets: Vec<f64> = SENSORS.into_iter().filter(|&x| x < side / 2.0).collect();
    let plate = common::infinite::Plate { e: E, nu: NU, h: H };
    Basin {
        load: FORCE,
        radius: RADIUS,
        deflections: common::disk_basin(&plate, K, side, n, (RADIUS, FORCE), [0.0, 0.0], &offsets),
        offsets,
    }
}

/// From L/ℓ = 3.5 to 10 the infinite-slab reading of the square slab is off the large slab's
/// by 0.8–34 % in k and up to 12 % in ℓ; corrected, it is the large slab's within 1.5 % in ℓ,
/// 4 % in k and 2 % in E. Tolerances: Crovetti's factors are a regression fitted to another
/// program's thin plates, whose residuals are not at hand; measured here (printed) they leave
/// up to 1.1 % in ℓ, 3.6 % in k (L/ℓ 5–6) and 1.7 % in E, and the bounds sit just above that
/// — far below the uncorrected misfit, so a missing or misapplied correction fails. (At
/// L/ℓ_est = 2.5 the correction still left 3 %, 5 % and 7 %: below 3 it is not applied.)
#[test]
fn crovettis_correction_gives_back_the_large_slabs_reading() {
    let ell = ell();
    let large = area_method(&basin(20.0 * ell), H, NU, Subgrade::DenseLiquid).expect("AREA");
    eprintln!(
        "large slab (20 ℓ): ℓ {:.4} m (true {ell:.4}), k {:.2} MN/m³, E {:.0} MPa",
        large.ell,
        large.subgrade_modulus / 1e6,
        large.slab_modulus / 1e6
    );
    let rel = |a: f64, b: f64| a / b - 1.0;
    for ratio in [3.5, 4.0, 5.0, 6.0, 8.0, 10.0] {
        let b = basin(ratio * ell);
        let infinite = area_method(&b, H, NU, Subgrade::DenseLiquid).expect("AREA");
        let corrected = finite_slab(&b, H, NU, ratio * ell).expect("finite");
        let finite = corrected.finite.expect("L/ℓ_est ≥ 3: corrected");
        eprintln!(
            "L/ℓ {ratio}: AF_d0 {:.4} AF_ℓ {:.4} | uncorrected ℓ {:+.4} k {:+.4} E {:+.4} | corrected ℓ {:+.4} k {:+.4} E {:+.4}",
            finite.deflection_factor,
            finite.ell_factor,
            rel(infinite.ell, large.ell),
            rel(infinite.subgrade_modulus, large.subgrade_modulus),
            rel(infinite.slab_modulus, large.slab_modulus),
            rel(corrected.ell, large.ell),
            rel(corrected.subgrade_modulus, large.subgrade_modulus),
            rel(corrected.slab_modulus, large.slab_modulus),
        );
        assert_eq!(finite.infinite_ell, infinite.ell);
        assert!(
            rel(corrected.ell, large.ell).abs() < 0.015,
            "L/ℓ {ratio}: ℓ {} vs {}",
            corrected.ell,
            large.ell
        );
        for (name, c, l, tol) in [
            (
                "k",
                corrected.subgrade_modulus,
                large.subgrade_modulus,
                0.04,
            ),
            ("E", corrected.slab_modulus, large.slab_modulus, 0.02),
        ] {
            assert!(rel(c, l).abs() < tol, "L/ℓ {ratio}: {name} {c} vs {l}");
        }
        // The correction helps: the corrected k is nearer the large slab's than the reading.
        assert!(
            rel(corrected.subgrade_modulus, large.subgrade_modulus).abs()
                <= rel(infinite.subgrade_modulus, large.subgrade_modulus).abs(),
            "L/ℓ {ratio}"
        );
    }
}

/// The factors tend to 1 on a large slab and fall on a small one; below L/ℓ_est = 3 the
/// reading comes back uncorrected, and a size that is not a positive length is refused by
/// name.
#[test]
fn the_factors_fade_on_large_slabs_and_small_ones_are_left_alone() {
    let (d, l) = crovetti_factors(20.0);
    assert!(1.0 - d < 1e-3 && 1.0 - l < 1e-5, "{d} {l}");
    let (d3, l3) = crovetti_factors(3.0);
    let (d5, l5) = crovetti_factors(5.0);
    assert!(d3 < d5 && l3 < l5 && d5 < d && l5 < l);
    // 1.9 m: the AREA's last sensor, at 914 mm, is still on the slab.
    let b = basin(1.9);
    let r = finite_slab(&b, H, NU, 1.9).expect("AREA");
    assert!(r.finite.is_none(), "{r:?}");
    let err = finite_slab(&b, H, NU, -1.0).expect_err("negative size");
    assert!(err.to_string().contains("slab_size"), "{err}");
}
