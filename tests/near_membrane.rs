//! Plates that are nearly membranes (issue 32 §1.2): a 12 × 8 m plate of 0.05 m, E = 1 MPa
//! (Γ ≈ 7.7e-10: a flexible load on the soil, like a tank's steel bottom or an embankment's
//! base) under 100 kPa on a half-space E_s = 30 MPa, ν_s = 0.3, at 96 × 64 elements — the
//! iterative route (beyond 1 500 pressure nodes). There the preconditioner's plate on a grid
//! twice as coarse cannot carry the plate's compliance, which exceeds the soil's below the
//! radius of relative stiffness ℓ = 0.07 h: conjugate gradients stalled, the bonded solve and
//! the QP asked for the dense route and the penalty ran 200 steps. Every method now converges,
//! and the answer is the flexible load's: full contact, the centre settlement of Steinbrenner's
//! flexible rectangle.

use liftoff::{Monitor, Outcome, Source};

const SCENE: &str = r#"title = "membrane"
[plate]
length = 12.0
width = 8.0
thickness = 0.05
youngs_modulus = 1.0e6
poissons_ratio = 0.3
[foundation]
model = "half-space"
youngs_modulus = 30e6
poissons_ratio = 0.3
[[load]]
kind = "uniform"
pressure = 1.0e5
[mesh]
elements = [96, 64]
"#;

/// The centre settlement of a flexible uniform load q on a B × L rectangle of an elastic
/// half-space: four corners of B/2 × L/2, each w = q b (1 − ν²)/E · I, with
/// I = (1/π)[m ln((1 + √(1 + m²))/m) + ln(m + √(1 + m²))], m = l/b (Steinbrenner 1934;
/// Poulos & Davis, "Elastic Solutions for Soil and Rock Mechanics", 1974, Table 3.2).
fn steinbrenner_centre(q: f64, b: f64, l: f64, e: f64, nu: f64) -> f64 {
    let (b, l) = (b / 2.0, l / 2.0);
    let m = l / b;
    let r = (1.0 + m * m).sqrt();
    let i = (m * ((1.0 + r) / m).ln() + (m + r).ln()) / std::f64::consts::PI;
    4.0 * q * b * (1.0 - nu * nu) / e * i
}

#[test]
fn a_nearly_membrane_plate_settles_as_a_flexible_load_by_every_method() {
    let reference = steinbrenner_centre(1.0e5, 8.0, 12.0, 30e6, 0.3);
    for (what, contact, method) in [
        ("bonded", "bonded", "penalty"),
        ("penalty", "unbonded", "penalty"),
        ("qp", "unbonded", "qp"),
    ] {
        let scene = format!("{SCENE}[solver]\ncontact = \"{contact}\"\nmethod = \"{method}\"\n");
        let problem = liftoff::load(&Source::Toml(&scene), &Default::default())
            .unwrap_or_else(|e| panic!("{what}: {e}"));
        let a = match liftoff::run(&problem, &Monitor::NONE) {
            Ok(Outcome::Single(a)) => a,
            Ok(_) => panic!("{what}: expected one solve"),
            Err(e) => panic!("{what}: {e}"),
        };
        let s = &a.summary;
        assert!(s.converged, "{what}: {}", s.status);
        assert!(
            s.notes.iter().any(|n| n.contains("iterative route")),
            "{what}: expected the iterative route, notes {:?}",
            s.notes
        );
        // A flexible uniform load stays in full contact.
        assert!(
            s.contact_fraction > 0.999,
            "{what}: contact {}",
            s.contact_fraction
        );
        // The centre settlement: the 48 × 32 dense solve is 0.02 % off the closed form; the
        // bonded 96 × 64 is 0.04 %, the unbonded ones carry their penalty's O(ε̄) or the QP's
        // tolerance on top: 0.5 % bounds all three with the discretisation's margin.
        let centre = s.V_center * s.physical.map_or(1.0, |p| p.deflection());
        assert!(
            (centre - reference).abs() < 5e-3 * reference,
            "{what}: centre {centre:.6e} m, Steinbrenner {reference:.6e} m"
        );
    }
}
