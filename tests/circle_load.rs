//! The circular load (`kind = "circle"`, a deflectometer's load plate) and the deflection at any
//! point of the plate (`FullField::at`), against a reference that is not liftoff's elements:
//! the infinite Mindlin plate on a dense liquid under a uniform disk, as a Hankel integral
//! evaluated here (issue 34's forward model).
//!
//! w(r) = q a ∫₀^∞ J₁(ξa) J₀(ξr) (1 + Dξ²/S) / (Dξ⁴ + k (1 + Dξ²/S)) dξ,
//!
//! with S = κ G h the shear stiffness (κ = 5/6, liftoff's default) — the plate equation
//! D∇⁴w = (1 − D∇²/S)(q − k w) in Hankel space; S → ∞ is Kirchhoff's plate, whose centre
//! deflection under a point load P is Westergaard's P / (8 √(kD)).

use crate::common;

use liftoff::Problem;

/// The slab and soil of the tests: 250 mm of concrete on k = 80 MN/m³ (ℓ = 0.841 m), a 40 kN
/// drop on the standard 150 mm plate.
const E: f64 = 30e9;
const NU: f64 = 0.15;
const H: f64 = 0.25;
const K: f64 = 8.0e7;
const RADIUS: f64 = 0.15;
const FORCE: f64 = 40e3;

/// The infinite plate's deflection at distance `r` from the disk's centre, `shear` the plate's
/// S: ∞ for Kirchhoff's plate, else Mindlin's with κ = 5/6 ([`common::infinite::disk_on_springs`]).
fn infinite_plate(r: f64, shear: f64) -> f64 {
    let plate = common::infinite::Plate { e: E, nu: NU, h: H };
    common::infinite::disk_on_springs(&plate, K, RADIUS, FORCE, r, shear.is_infinite())
}

/// The deflection at the FWD's usual sensor offsets (m), x along the slab from the plate's
/// centre, on a square bonded slab of side `side` with n × n elements, the plate at the centre.
fn basin(side: f64, n: usize, offsets: &[f64]) -> Vec<f64> {
    basin_at(side, n, [0.0, 0.0], offsets)
}

/// [`basin`] with the plate centred at `at`, the sensors along x from it
/// ([`common::disk_basin`]: the solve converged and its reaction is the force, 1e-9).
fn basin_at(side: f64, n: usize, at: [f64; 2], offsets: &[f64]) -> Vec<f64> {
    let plate = common::infinite::Plate { e: E, nu: NU, h: H };
    common::disk_basin(&plate, K, side, n, (RADIUS, FORCE), at, offsets)
}

const SENSORS: [f64; 8] = [0.0, 0.203, 0.305, 0.457, 0.610, 0.914, 1.219, 1.524];

/// A 17 m square slab (20 ℓ) under the disk: its basin at the eight sensors against the infinite
/// Mindlin plate's, on meshes of 0.142 m and 0.071 m elements (the disk is 2 and 4 elements
/// across its radius). The error at each sensor falls as the mesh halves, and on the finer mesh
/// it is within 1 % of the centre deflection. The edges are 10 ℓ away: their effect on the
/// basin is of order e^{−10/√2}, below 1e-3, and shows as the floor of about 6e-5 at the far
/// sensors.
#[test]
fn a_disk_on_a_large_slab_gives_the_infinite_plates_basin() {
    let g = E / (2.0 * (1.0 + NU));
    let shear = 5.0 / 6.0 * g * H;
    let reference: Vec<f64> = SENSORS.iter().map(|&r| infinite_plate(r, shear)).collect();
    // Westergaard's point-load value bounds the Kirchhoff plate's centre deflection under the
    // disk from above (spreading the load lowers the peak), and the shear of Mindlin's plate
    // adds to it.
    let d = E * H.powi(3) / (12.0 * (1.0 - NU * NU));
    let point = FORCE / (8.0 * (K * d).sqrt());
    let kirchhoff = infinite_plate(0.0, f64::INFINITY);
    assert!(
        kirchhoff < point && kirchhoff > 0.9 * point,
        "{kirchhoff} vs {point}"
    );
    assert!(reference[0] > kirchhoff, "{} vs {kirchhoff}", reference[0]);
    let coarse = basin(17.0, 120, &SENSORS);
    let fine = basin(17.0, 240, &SENSORS);
    let scale = reference[0];
    for (k, &r) in SENSORS.iter().enumerate() {
        let (ec, ef) = (
            (coarse[k] - reference[k]).abs() / scale,
            (fine[k] - reference[k]).abs() / scale,
        );
        eprintln!(
            "r = {r:.3} m: reference {:.4e}, coarse {:.4e} ({ec:.2e}), fine {:.4e} ({ef:.2e})",
            reference[k], coarse[k], fine[k]
        );
        // MITC4 converges in the deflection like h²: 0.5 % leaves a margin of 2.5 over the
        // finer mesh's error at the centre (1.8e-3), where the disk's edge is least resolved.
        assert!(
            ef <= 0.005,
            "sensor at {r} m: {ef:.3e} of the centre deflection"
        );
        if r <= 0.61 {
            // Near the load, where the mesh's error dominates the edges' (below 1e-4), halving
            // the elements divides it by about four: at least three.
            assert!(
                ec >= 3.0 * ef,
                "sensor at {r} m: {ec:.2e} → {ef:.2e} is not second order"
            );
        } else {
            assert!(
                ef <= ec + 1e-4,
                "sensor at {r} m: the finer mesh is not closer"
            );
        }
    }
}

/// Bad disks are refused naming the key: a radius that is not positive, both a force and a
/// pressure, a disk that reaches beyond the plate.
#[test]
fn bad_disks_are_refused_naming_the_key() {
    let scene = |extra: &str| {
        format!(
            "[plate]\nlength = 4.0\nwidth = 4.0\nthickness = 0.25\nyoungs_modulus = 30e9\npoissons_ratio = 0.15\n[foundation]\nmodel = \"winkler\"\nmodulus = 8e7\n[[load]]\nkind = \"circle\"\n{extra}\n"
        )
    };
    let field = |extra: &str| match Problem::from_toml(&scene(extra)) {
        Err(liftoff::Error::Invalid { field, .. }) => field,
        other => panic!("{extra}: {other:?}"),
    };
    assert_eq!(
        field("x = 0.0\ny = 0.0\nradius = 0.0\nforce = 4e4"),
        "load[0].radius"
    );
    assert_eq!(field("x = 0.0\ny = 0.0\nforce = 4e4"), "load[0].radius");
    assert_eq!(
        field("x = 0.0\ny = 0.0\nradius = 0.15\nforce = 4e4\npressure = 5e5"),
        "load[0].pressure"
    );
    assert_eq!(
        field("x = 1.9\ny = 0.0\nradius = 0.15\nforce = 4e4"),
        "load[0].radius"
    );
    assert!(
        Problem::from_toml(&scene("x = 1.8\ny = 0.0\nradius = 0.15\npressure = 5.66e5")).is_ok()
    );
}

/// The AREA method (dense liquid) on basins of liftoff's own model of a 17 m slab, 0.071 m
/// elements, k = 80 MN/m³. With the plate at the middle it reads the slab as it reads the
/// infinite Mindlin plate's basin (the Hankel integral above): the same k and E within the
/// elements' error. Both are off the true k and E, by the Mindlin plate's shear deflection,
/// which the method's Kirchhoff closed form does not have (printed: +16 % in k and −23 % in E
/// for this 250 mm slab, h/ℓ = 0.30) — the AREA is sensitive to d₀, which the shear raises by
/// 4 %. With the plate at a free edge, where the infinite slab's assumption fails, it is off by
/// far more.
#[test]
fn the_area_method_reads_the_model_as_the_infinite_plate_inside_and_fails_at_the_edge() {
    use liftoff::backcalc::{area_method, Basin, Subgrade};
    let offsets = [0.0, 0.203, 0.305, 0.457, 0.610, 0.914, 1.219, 1.524];
    let area = |d: Vec<f64>| {
        let basin = Basin {
            load: FORCE,
            radius: RADIUS,
            offsets: offsets.to_vec(),
            deflections: d,
        };
        area_method(&basin, H, NU, Subgrade::DenseLiquid).expect("AREA")
    };
    let g = E / (2.0 * (1.0 + NU));
    let shear = 5.0 / 6.0 * g * H;
    let mindlin = area(offsets.iter().map(|&r| infinite_plate(r, shear)).collect());
    let kirchhoff = area(
        offsets
            .iter()
            .map(|&r| infinite_plate(r, f64::INFINITY))
            .collect(),
    );
    let middle = area(basin_at(17.0, 240, [-1.0, 0.0], &offsets));
    // The plate's edge 15 mm from the slab's: the disk touches neither.
    let edge = area(basin_at(17.0, 240, [-1.0, -8.5 + RADIUS + 0.015], &offsets));
    let rel = |r: &liftoff::backcalc::AreaResult| {
        (r.subgrade_modulus / K - 1.0, r.slab_modulus / E - 1.0)
    };
    for (name, r) in [
        ("Kirchhoff reference", &kirchhoff),
        ("Mindlin reference", &mindlin),
        ("model, middle", &middle),
        ("model, edge", &edge),
    ] {
        let (k, e) = rel(r);
        eprintln!(
            "AREA method on the {name}: AREA {:.2} in, k {k:+.4}, E {e:+.4}",
            r.area / 0.0254
        );
    }
    // The Kirchhoff plate is the method's own: it comes back to the Simpson rules' accuracy.
    let (kk, ke) = rel(&kirchhoff);
    assert!(
        kk.abs() < 1e-4 && ke.abs() < 1e-4,
        "Kirchhoff: k {kk}, E {ke}"
    );
    // The model inside the slab reads as the infinite Mindlin plate: its deflections are
    // within 0.2 % of the reference's (the test above); the AREA method amplifies an error of
    // d₀ about fivefold in k and E here, so 2 % and 3 %.
    let (mk, me) = rel(&mindlin);
    let (ik, ie) = rel(&middle);
    assert!(
        (ik - mk).abs() < 0.02 && (ie - me).abs() < 0.03,
        "middle {ik}, {ie} vs {mk}, {me}"
    );
    // At the edge the basin deflects about twice as much over a narrower bowl: the method's
    // k is off by more than twice what it is inside.
    let (ek, _) = rel(&edge);
    assert!(ek.abs() > 2.0 * ik.abs() && ek.abs() > 0.3, "edge: k {ek}");
}
