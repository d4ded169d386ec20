//! The least-squares fit of a deflectometer basin on liftoff's own model (`backcalc::fit_drop`),
//! against references it does not produce: the infinite Mindlin plate's basin (a Hankel
//! integral, `common::infinite`), the true values of basins made with known moduli, and the
//! coverage that a 95 % interval must have over noisy basins.

use crate::common;

use liftoff::backcalc::{
    area_method, fit_drop, model_basin, Basin, Drop, FitOptions, Location, Subgrade, Termination,
    Unknown,
};
use liftoff::scene::SceneFile;
use liftoff::Monitor;
use rayon::prelude::*;

/// 250 mm of concrete on k = 80 MN/m³ (ℓ = 0.841 m); a 40 kN drop on the 150 mm plate.
const E: f64 = 30e9;
const NU: f64 = 0.15;
const H: f64 = 0.25;
const K: f64 = 8.0e7;
const RADIUS: f64 = 0.15;
const FORCE: f64 = 40e3;
const SENSORS: [f64; 8] = [0.0, 0.203, 0.305, 0.457, 0.610, 0.914, 1.219, 1.524];

fn ell(e: f64, k: f64) -> f64 {
    (e * H.powi(3) / (12.0 * (1.0 - NU * NU)) / k).powf(0.25)
}

/// A bonded square slab of `side` on springs, with the template's guesses for the moduli.
fn template(side: f64, e: f64, k: f64, contact: &str) -> SceneFile {
    let text = format!(
        "[plate]\nlength = {side}\nwidth = {side}\nthickness = {H}\nyoungs_modulus = {e}\npoissons_ratio = {NU}\n\
         [foundation]\nmodel = \"winkler\"\nmodulus = {k}\n[solver]\ncontact = \"{contact}\"\n"
    );
    SceneFile::parse(&text).expect("template")
}

fn drop(location: Location, deflections: Vec<f64>) -> Drop {
    Drop {
        station: "T".into(),
        drop: 1,
        location,
        basin: Basin {
            load: FORCE,
            radius: RADIUS,
            offsets: SENSORS.to_vec(),
            deflections,
        },
        at: None,
        direction: 0.0,
        temperature_difference: None,
    }
}

/// The check: the basin of the infinite Mindlin plate (exact data, not liftoff's), fitted
/// on a 17 m slab (20 ℓ) with 0.071 m elements, gives k within 1 % and ℓ within 0.5 %. The
/// model's deflections are within 0.2 % of the reference's at these sensors
/// (`tests/circle_load.rs`), and a fit of two moduli to eight sensors spreads that error over
/// both. On the default mesh (0.142 m: the disk one element across its radius, deflections
/// within 0.7 %) the fit is printed.
#[test]
fn a_fit_to_the_infinite_plates_basin_recovers_k_and_ell() {
    let plate = common::infinite::Plate { e: E, nu: NU, h: H };
    let reference: Vec<f64> = SENSORS
        .iter()
        .map(|&r| common::infinite::disk_on_springs(&plate, K, RADIUS, FORCE, r, false))
        .collect();
    // The template's moduli are off by a third: the AREA start replaces them.
    let t = template(17.0, 20e9, 5e7, "bonded");
    let d = drop(Location::Interior, reference);
    for (elements, strict) in [(Some([240, 240]), true), (None, false)] {
        let options = FitOptions {
            elements,
            ..FitOptions::default()
        };
        let fit = fit_drop(&t, &d, &options, &Monitor::NONE).expect("fit");
        let k = fit.estimate(Unknown::Subgrade).expect("k").value;
        let e = fit.estimate(Unknown::Slab).expect("E").value;
        let (l, _) = fit.ell.expect("ℓ");
        eprintln!(
            "mesh {elements:?}: k {:+.4}, E {:+.4}, ℓ {:+.4}; rms {:.3} µm, {} solves, started from {}",
            k / K - 1.0,
            e / E - 1.0,
            l / ell(E, K) - 1.0,
            1e6 * fit.rms,
            fit.solves,
            fit.start
        );
        assert!(fit.converged, "{:?}", fit.termination);
        if strict {
            assert!((k / K - 1.0).abs() < 0.01, "k {k}");
            assert!((l / ell(E, K) - 1.0).abs() < 0.005, "ℓ {l}");
        }
    }
}

/// The fit on a continuum soil against a reference the model does not produce: the basin of the
/// infinite Mindlin plate bonded to an elastic half-space (E_s = 100 MPa, ν_s = 0.35; ℓ =
/// (2D(1 − ν_s²)/E_s)^⅓ = 0.888 m), `common::infinite::disk_on_halfspace`, fitted for E_s and
/// the slab's E on an 18 m square slab (20 ℓ) on the half-space. The half-space couples the
/// whole surface, so the finite slab's missing plate beyond 9 m and the mesh both enter; the
/// test runs two meshes and asks that the finer one come closer (the fit converges to the
/// reference with the mesh) and that it be within 1 % on E_s and 0.5 % on ℓ, the tolerances
/// the issue sets on springs. Seen: 96² (0.19 m elements) E_s +0.42 %, E −2.1 %, ℓ −0.85 %;
/// 192² (0.094 m) E_s +0.12 %, E −0.55 %, ℓ −0.22 % — the error falls by 3.5 and 3.9 per
/// halving of the elements, the bilinear elements' second order (4) less the slab's finite
/// size; the test asks for more than 2.5. (It ran 128² and 256² until session 29: E_s +0.27 %
/// and +0.08 %, ℓ −0.52 % and −0.14 %, the same rate, five times the time — the suite's
/// longest test but one.)
#[test]
fn a_fit_to_the_infinite_plates_basin_on_a_half_space_recovers_the_soil() {
    let (es, nus) = (1.0e8, 0.35);
    let plate = common::infinite::Plate { e: E, nu: NU, h: H };
    let reference: Vec<f64> = SENSORS
        .iter()
        .map(|&r| common::infinite::disk_on_halfspace(&plate, es, nus, RADIUS, FORCE, r))
        .collect();
    let d_plate = E * H.powi(3) / (12.0 * (1.0 - NU * NU));
    let ell_true = (2.0 * d_plate * (1.0 - nus * nus) / es).cbrt();
    // The template's moduli are off: E_s by +50 %, E by −20 %.
    let text = format!(
        "[plate]\nlength = 18.0\nwidth = 18.0\nthickness = {H}\nyoungs_modulus = 24e9\npoissons_ratio = {NU}\n\
         [foundation]\nmodel = \"half-space\"\nyoungs_modulus = 1.5e8\npoissons_ratio = {nus}\n\
         [solver]\ncontact = \"bonded\"\n"
    );
    let t = SceneFile::parse(&text).expect("template");
    let d = drop(Location::Interior, reference);
    let mut errors = Vec::new();
    for elements in [[96, 96], [192, 192]] {
        let options = FitOptions {
            elements: Some(elements),
            ..FitOptions::default()
        };
        let fit = fit_drop(&t, &d, &options, &Monitor::NONE).expect("fit");
        assert!(fit.converged, "{:?}", fit.termination);
        let soil = fit.estimate(Unknown::Subgrade).expect("E_s").value;
        let e = fit.estimate(Unknown::Slab).expect("E").value;
        let ell =
            (2.0 * e * H.powi(3) / (12.0 * (1.0 - NU * NU)) * (1.0 - nus * nus) / soil).cbrt();
        eprintln!(
            "half-space, mesh {elements:?}: E_s {:+.4}, E {:+.4}, ℓ {:+.4}; rms {:.3} µm, {} solves",
            soil / es - 1.0,
            e / E - 1.0,
            ell / ell_true - 1.0,
            1e6 * fit.rms,
            fit.solves
        );
        errors.push(((soil / es - 1.0).abs(), (ell / ell_true - 1.0).abs()));
    }
    let (coarse, fine) = (errors[0], errors[1]);
    assert!(
        fine.0 * 2.5 < coarse.0 && fine.1 * 2.5 < coarse.1,
        "{errors:?}"
    );
    assert!(fine.0 < 0.01 && fine.1 < 0.005, "{errors:?}");
}

/// The same slab's model makes the basin, here at a free edge (the plate a radius in from it,
/// the sensors along it): the fit gives back the moduli that made it (to the differences'
/// accuracy), where the AREA method, which assumes an infinite slab, is off by far more.
#[test]
fn at_a_free_edge_the_fit_recovers_what_the_area_method_misses() {
    let truth = template(8.0, E, K, "bonded");
    let options = FitOptions::default();
    let basin = model_basin(
        &truth,
        &drop(Location::Edge, Vec::new()),
        &options,
        &Monitor::NONE,
    )
    .expect("basin");
    let area = area_method(
        &Basin {
            load: FORCE,
            radius: RADIUS,
            offsets: SENSORS.to_vec(),
            deflections: basin.clone(),
        },
        H,
        NU,
        Subgrade::DenseLiquid,
    )
    .expect("AREA");
    let guess = template(8.0, 45e9, 5e7, "bonded");
    let fit = fit_drop(
        &guess,
        &drop(Location::Edge, basin),
        &options,
        &Monitor::NONE,
    )
    .expect("fit");
    let k = fit.estimate(Unknown::Subgrade).expect("k").value;
    let e = fit.estimate(Unknown::Slab).expect("E").value;
    eprintln!(
        "edge: AREA k {:+.3}, E {:+.3}; fit k {:+.2e}, E {:+.2e}, {} solves",
        area.subgrade_modulus / K - 1.0,
        area.slab_modulus / E - 1.0,
        k / K - 1.0,
        e / E - 1.0,
        fit.solves
    );
    assert!(fit.converged);
    // The model is the basin's own: only the optimiser's tolerance and the differences' error
    // (1e-4 of a column) stand between the fit and the truth.
    assert!(
        (k / K - 1.0).abs() < 1e-4 && (e / E - 1.0).abs() < 1e-4,
        "k {k}, E {e}"
    );
    assert!(
        (area.subgrade_modulus / K - 1.0).abs() > 0.3,
        "AREA k {}",
        area.subgrade_modulus
    );
}

/// A normal deviate from a seeded xorshift and Box–Muller: deterministic noise for the coverage
/// test.
struct Noise(u64);

impl Noise {
    fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        ((self.0 >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }
    fn normal(&mut self) -> f64 {
        let (u, v) = (self.uniform(), self.uniform());
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }
}

/// The coverage check: basins of liftoff's own model (no discretisation bias) with 2 µm
/// of Gaussian noise on every sensor; over 200 of them the 95 % intervals of k and of E each
/// contain the true value in 90–99 % of the fits. (With 200 draws the count of a true 95 %
/// interval has a standard deviation of 3.1 %: the band is about ±1.5 σ below and ±1.3 σ above,
/// and a linearised interval that were off by a factor 1.5 in width would fall outside it.)
#[test]
fn ninety_five_percent_intervals_cover_the_truth_over_noisy_basins() {
    let truth = template(6.0, E, K, "bonded");
    let exact = model_basin(
        &truth,
        &drop(Location::Interior, Vec::new()),
        &FitOptions::default(),
        &Monitor::NONE,
    )
    .expect("basin");
    let mut noise = Noise(0x2545_f491_4f6c_dd1d);
    let basins: Vec<Vec<f64>> = (0..200)
        .map(|_| exact.iter().map(|d| d + 2e-6 * noise.normal()).collect())
        .collect();
    let guess = template(6.0, 24e9, 1e8, "bonded");
    let hits: Vec<(bool, bool)> = basins
        .into_par_iter()
        .map(|b| {
            let fit = fit_drop(
                &guess,
                &drop(Location::Interior, b),
                &FitOptions::default(),
                &Monitor::NONE,
            )
            .expect("fit");
            assert!(fit.converged, "{:?}", fit.termination);
            let inside = |u: Unknown, v: f64| {
                let [lo, hi] = fit.estimate(u).and_then(|e| e.interval).expect("interval");
                lo <= v && v <= hi
            };
            (inside(Unknown::Subgrade, K), inside(Unknown::Slab, E))
        })
        .collect();
    let k = hits.iter().filter(|h| h.0).count() as f64 / 2.0;
    let e = hits.iter().filter(|h| h.1).count() as f64 / 2.0;
    eprintln!("coverage over 200 noisy basins: k {k} %, E {e} %");
    assert!((90.0..=99.0).contains(&k), "k covered in {k} %");
    assert!((90.0..=99.0).contains(&e), "E covered in {e} %");
}

/// A fit held to fewer evaluations than it needs says so, with the best point it reached.
#[test]
fn a_fit_that_runs_out_of_evaluations_is_not_called_converged() {
    let plate = common::infinite::Plate { e: E, nu: NU, h: H };
    let reference: Vec<f64> = SENSORS
        .iter()
        .map(|&r| common::infinite::disk_on_springs(&plate, K, RADIUS, FORCE, r, false))
        .collect();
    let mut d = drop(Location::Interior, reference);
    // Without the AREA sensors at 305 … 914 mm the fit starts from the template.
    d.basin.offsets = vec![0.0, 0.203, 0.457, 1.219, 1.524];
    d.basin.deflections = [0usize, 1, 3, 6, 7]
        .iter()
        .map(|&i| d.basin.deflections[i])
        .collect();
    let t = template(8.0, 10e9, 3e8, "bonded");
    let fit = fit_drop(
        &t,
        &d,
        &FitOptions {
            max_evaluations: 2,
            ..FitOptions::default()
        },
        &Monitor::NONE,
    )
    .expect("fit");
    assert_eq!(fit.start, "template");
    assert!(!fit.converged);
    assert_eq!(fit.termination, Termination::TooManyEvaluations);
    assert!(fit.rms.is_finite() && fit.rms > 0.0);
}
