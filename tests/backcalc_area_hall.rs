//! The AREA method (`backcalc::area_method`) against a reference it does not compute: Hall's
//! (1991) published regressions of the dense-liquid closed forms for the SHRP plate (radius
//! 5.9 in) and the sensors at 0, 12, 24 and 36 in — the equations behind the AASHTO Guide's
//! (1993, Part III) charts of ℓ against AREA and of d₀ k ℓ²/P against ℓ, and the ones the
//! method is worked by hand with:
//!
//! - ℓ = [ln((36 − AREA) / 1812.279133) / (−2.559340)]^4.387009 (ℓ and AREA in inches);
//! - d₀ k ℓ² / P = 0.1245 exp(−0.14707 exp(−0.07565 ℓ)) (the centre deflection's factor);
//! - k = P · that factor / (d₀ ℓ²), E = 12 (1 − ν²) k ℓ⁴ / h³.
//!
//! The constants are as the literature quotes them (Hall's thesis was not at hand); that
//! seven-digit regressions land within 0.1 in of AREA and 0.1 % of the centre factor of
//! liftoff's closed forms across their range is itself the check that they were copied right.
//! liftoff does not use them: it inverts the Hankel integral of the infinite Kirchhoff plate
//! under the plate's disk (`backcalc::infinite`). No published worked example with its numbers
//! was at hand; the first test works one by Hall's equations, the second sweeps the AREAs of
//! the regressions' range. (Hall's elastic-solid regressions are not checked: their constants
//! could not be confirmed.)

use liftoff::backcalc::{area_method, Basin, Subgrade};

const INCH: f64 = 0.0254;
const LBF: f64 = 4.448_221_615_260_5;
const MIL: f64 = 1e-3 * INCH;
const PCI: f64 = LBF / (INCH * INCH * INCH);
const PSI: f64 = LBF / (INCH * INCH);

/// Hall's reading of a basin, in inches, pounds and pci: (AREA, ℓ, k, E).
fn hall(load_lbf: f64, d_mils: [f64; 4], h_in: f64, nu: f64) -> (f64, f64, f64, f64) {
    let [d0, d12, d24, d36] = d_mils;
    let area = 6.0 * (1.0 + 2.0 * d12 / d0 + 2.0 * d24 / d0 + d36 / d0);
    let ell = (((36.0 - area) / 1812.279133).ln() / -2.559340).powf(4.387009);
    let factor = 0.1245 * (-0.14707 * (-0.07565 * ell).exp()).exp();
    let k = load_lbf * factor / (d0 * 1e-3 * ell * ell);
    let e = 12.0 * (1.0 - nu * nu) * k * ell.powi(4) / h_in.powi(3);
    (area, ell, k, e)
}

fn basin(load_lbf: f64, d_mils: [f64; 4]) -> Basin {
    Basin {
        load: load_lbf * LBF,
        radius: 5.9 * INCH,
        offsets: vec![0.0, 12.0 * INCH, 24.0 * INCH, 36.0 * INCH],
        deflections: d_mils.iter().map(|d| d * MIL).collect(),
    }
}

/// Relative difference a/b − 1.
fn rel(a: f64, b: f64) -> f64 {
    a / b - 1.0
}

/// An example worked by Hall's equations: a 9 000 lbf drop on a 10 in slab (ν = 0.15), 4.00,
/// 3.55, 3.10 and 2.65 mils at 0, 12, 24 and 36 in: AREA = 29.925 in, ℓ = 33.49 in, k = 247
/// pci, E = 3.64 Mpsi. liftoff's AREA is the same sum to rounding; ℓ, k and E agree within
/// 0.5 %, 1 % and 1 % (found: +0.36 %, −0.69 %, +0.76 %: the regressions' own misfit to the
/// closed forms at this AREA, as the sweep below shows across their range).
#[test]
fn an_example_worked_by_halls_equations() {
    let d = [4.00, 3.55, 3.10, 2.65];
    let (area, ell, k, e) = hall(9000.0, d, 10.0, 0.15);
    // The hand-worked numbers, to the digits a hand calculation carries.
    assert!((area - 29.925).abs() < 1e-9, "AREA {area}");
    assert!((ell - 33.49).abs() < 0.01, "ℓ {ell}");
    assert!((k - 246.8).abs() < 0.1, "k {k}");
    assert!((e / 1e6 - 3.643).abs() < 1e-3, "E {e}");
    let r = area_method(&basin(9000.0, d), 10.0 * INCH, 0.15, Subgrade::DenseLiquid)
        .expect("an interior basin the AREA method reads");
    assert!(
        (r.area / INCH - area).abs() < 1e-9,
        "AREA {}",
        r.area / INCH
    );
    assert!(rel(r.ell / INCH, ell).abs() < 0.005, "ℓ {}", r.ell / INCH);
    assert!(
        rel(r.subgrade_modulus / PCI, k).abs() < 0.01,
        "k {}",
        r.subgrade_modulus / PCI
    );
    assert!(
        rel(r.slab_modulus / PSI, e).abs() < 0.01,
        "E {}",
        r.slab_modulus / PSI
    );
}

/// Across the range Hall fitted (ℓ from about 20 to 77 in, AREA 24.8 to 34.1 in) liftoff's ℓ
/// is Hall's within 1 %, k and E within 2 %. Measured: at most 0.75 % in ℓ and 1.5 % in k and
/// E, both at ℓ = 20 in, the range's short end where the regression bends away from the
/// closed form; 0.1–0.4 % in ℓ above 25 in. The bounds sit above the regressions' misfit and
/// far below what a wrong closed form gives: the point load's centre factor (Westergaard's
/// 1/8 with no disk) would be 3.7 % off at ℓ = 20 in, a plate of the wrong radius moves the
/// AREA itself.
#[test]
fn halls_regressions_agree_across_their_range() {
    let (h, nu) = (10.0, 0.15);
    for d in [
        [5.0, 3.9, 2.9, 2.1],
        [5.0, 4.2, 3.4, 2.7],
        [4.00, 3.55, 3.10, 2.65],
        [5.0, 4.5, 4.0, 3.5],
        [5.0, 4.7, 4.35, 4.0],
        [5.0, 4.8, 4.55, 4.3],
        [5.0, 4.85, 4.65, 4.45],
    ] {
        let (area, ell, k, e) = hall(9000.0, d, h, nu);
        let r = area_method(&basin(9000.0, d), h * INCH, nu, Subgrade::DenseLiquid)
            .expect("an interior basin the AREA method reads");
        let (dl, dk, de) = (
            rel(r.ell / INCH, ell),
            rel(r.subgrade_modulus / PCI, k),
            rel(r.slab_modulus / PSI, e),
        );
        eprintln!(
            "AREA {area:.3} in: Hall ℓ {ell:.2} in, k {k:.1} pci, E {:.0} ksi; liftoff {:+.4} {:+.4} {:+.4}",
            e / 1e3,
            dl,
            dk,
            de
        );
        assert!(dl.abs() < 0.01, "AREA {area}: ℓ off by {dl}");
        assert!(dk.abs() < 0.02, "AREA {area}: k off by {dk}");
        assert!(de.abs() < 0.02, "AREA {area}: E off by {de}");
    }
}
