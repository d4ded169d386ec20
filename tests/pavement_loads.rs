//! The pavement load kinds against what they must equal: a linear temperature profile is the
//! temperature load of its difference (to round-off), a quadratic profile adds the closed-form
//! nonlinear stress at both faces, moisture is the temperature load of its equivalent
//! difference, and an axle is its tires written as patches by hand.

use liftoff::Analysis;

use crate::common;

const PLATE: &str = "[plate]\nlength = 4.5\nwidth = 3.6\nthickness = 0.25\nyoungs_modulus = 30e9\npoissons_ratio = 0.15\nthermal_expansion = 1e-5\n[foundation]\nmodel = \"winkler\"\nmodulus = 27e6\n[[load]]\nkind = \"uniform\"\npressure = 6e3\n";

fn scene(loads: &str, contact: &str) -> String {
    format!("{PLATE}{loads}[mesh]\nelements = [36, 28]\n[solver]\ncontact = \"{contact}\"\n")
}

fn solve(text: &str) -> Analysis {
    common::run(text)
}

/// Largest relative difference of two fields, relative to the larger one's largest magnitude.
fn rel_diff(a: &[f64], b: &[f64]) -> f64 {
    common::max_abs_diff(a, b) / common::max_abs(a).max(common::max_abs(b)).max(1e-300)
}

/// A straight-line profile (35 °C on top, 20 °C at the bottom, through a middle value on the
/// line) is `kind = "temperature"` with difference 15 K: every field equal to round-off, bonded
/// and unbonded.
#[test]
fn a_linear_profile_is_the_temperature_load() {
    for contact in ["bonded", "unbonded"] {
        let profile = scene(
            "[[load]]\nkind = \"temperature-profile\"\ndepths = [0.0, 0.1, 0.25]\ntemperatures = [35.0, 29.0, 20.0]\n",
            contact,
        );
        let linear = scene(
            "[[load]]\nkind = \"temperature\"\ndifference = 15.0\n",
            contact,
        );
        let (a, b) = (solve(&profile), solve(&linear));
        assert!(
            a.summary.converged && b.summary.converged,
            "{contact}: both converged"
        );
        let (ra, rb) = (&a.report, &b.report);
        for (name, x, y) in [
            ("w", &ra.field.w, &rb.field.w),
            ("pressure", &ra.field.pressure, &rb.field.pressure),
            ("mx", &ra.elements.mx, &rb.elements.mx),
            ("s1_bottom", &ra.elements.bottom.s1, &rb.elements.bottom.s1),
            ("s1_top", &ra.elements.top.s1, &rb.elements.top.s1),
        ] {
            // The two curvatures differ by the round-off of the profile's integrals (1e-15).
            assert!(
                rel_diff(x, y) < 1e-10,
                "{contact}: {name} differs by {:.1e}",
                rel_diff(x, y)
            );
        }
    }
}

/// The quadratic through 35/24/20 °C at the top, middle and bottom: the same bending as its
/// linear part (difference 15 K), and at both faces the extra stress −Eα(T_top + T_bot −
/// 2T_mid)/(3(1 − ν)) = −30e9 · 1e-5 · 7/(3 · 0.85) = −0.8235 MPa, at every element.
#[test]
fn a_quadratic_profile_adds_its_closed_form_face_stress() {
    let quad = scene(
        "[[load]]\nkind = \"temperature-profile\"\ndepths = [0.0, 0.125, 0.25]\ntemperatures = [35.0, 24.0, 20.0]\ninterpolation = \"quadratic\"\n",
        "bonded",
    );
    let linear = scene(
        "[[load]]\nkind = \"temperature\"\ndifference = 15.0\n",
        "bonded",
    );
    let (a, b) = (solve(&quad), solve(&linear));
    let want = -30e9 * 1e-5 * 7.0 / (3.0 * 0.85);
    let (ea, eb) = (&a.report.elements, &b.report.elements);
    assert!(rel_diff(&ea.mx, &eb.mx) < 1e-10, "the same bending");
    for (face_a, face_b, name) in [
        (&ea.bottom, &eb.bottom, "bottom"),
        (&ea.top, &eb.top, "top"),
    ] {
        for (k, (sa, sb)) in face_a.sx.iter().zip(&face_b.sx).enumerate() {
            let extra = sa - sb;
            assert!(
                (extra - want).abs() < 1e-9 * want.abs(),
                "{name} σx extra {extra} Pa at element {k}, want {want}"
            );
        }
        // Shear is untouched by an isotropic in-plane stress.
        assert!(rel_diff(&face_a.sxy, &face_b.sxy) < 1e-10, "{name} τxy");
    }
}

/// Shrinkage −200 µε over the top 50 mm is the temperature load of its equivalent difference
/// 6 ε h_s (H/2 − h_s/3)/(α H²) = −10.4 K, and a built-in curl of ΔT is that difference.
#[test]
fn moisture_and_built_in_curl_are_equivalent_differences() {
    let dt = 6.0 * -200e-6 * 0.05 * (0.125 - 0.05 / 3.0) / (1e-5 * 0.0625);
    let moist = scene(
        "[[load]]\nkind = \"moisture\"\nshrinkage = -200e-6\ndepth = 0.05\n",
        "unbonded",
    );
    let curl = scene(
        &format!("[[load]]\nkind = \"built-in-curl\"\ndifference = {dt}\n"),
        "unbonded",
    );
    let linear = scene(
        &format!("[[load]]\nkind = \"temperature\"\ndifference = {dt}\n"),
        "unbonded",
    );
    let (a, b, c) = (solve(&moist), solve(&curl), solve(&linear));
    assert!(a.summary.converged && b.summary.converged && c.summary.converged);
    assert!(
        rel_diff(&a.report.field.w, &c.report.field.w) < 1e-10,
        "moisture = ΔT_eq"
    );
    assert!(
        rel_diff(&b.report.field.w, &c.report.field.w) < 1e-10,
        "built-in = ΔT"
    );
}

/// The ESAL axle at (0.3, −0.4) m heading along x is its four tires written by hand: 20 kN over
/// PCA prints 0.8712 L × 0.6 L, L = √(A/0.5227), A = 20 000/827 400 m², at y = −0.4 ± 0.915 ±
/// 0.1524 m. Same fields to round-off; the reaction carries the axle and the slab's weight.
#[test]
fn an_axle_is_its_tires() {
    let axle = scene(
        "[[load]]\nkind = \"axle\"\nstandard = \"esal-single-dual\"\nx = 0.3\ny = -0.4\n",
        "unbonded",
    );
    let area: f64 = 20e3 / 827.4e3;
    let l = (area / 0.5227).sqrt();
    let (along, across) = (0.8712 * l, 0.6 * l);
    let mut patches = String::new();
    for yc in [
        -0.915 - 0.1524,
        -0.915 + 0.1524,
        0.915 - 0.1524,
        0.915 + 0.1524,
    ] {
        let y = -0.4 + yc;
        patches += &format!(
            "[[load]]\nkind = \"patch\"\nx = [{}, {}]\ny = [{}, {}]\npressure = {}\n",
            0.3 - along / 2.0,
            0.3 + along / 2.0,
            y - across / 2.0,
            y + across / 2.0,
            20e3 / (along * across)
        );
    }
    let (a, b) = (solve(&axle), solve(&scene(&patches, "unbonded")));
    assert!(a.summary.converged && b.summary.converged);
    // The solve's maps draw the four prints where the hand-written patches are (issue 36).
    let problem = liftoff::Problem::from_toml(&axle).expect("scene");
    let overlay = liftoff::output::chart::Overlay::for_model(&problem.model, &a.report);
    assert_eq!(overlay.prints.len(), 4, "{:?}", overlay.prints);
    for (k, yc) in [
        -0.915 - 0.1524,
        -0.915 + 0.1524,
        0.915 - 0.1524,
        0.915 + 0.1524,
    ]
    .iter()
    .enumerate()
    {
        let r = overlay.prints[k];
        let want = [
            (0.3 - along / 2.0, -0.4 + yc - across / 2.0),
            (0.3 + along / 2.0, -0.4 + yc + across / 2.0),
        ];
        let off = (r[0].0 - want[0].0).abs()
            + (r[0].1 - want[0].1).abs()
            + (r[1].0 - want[1].0).abs()
            + (r[1].1 - want[1].1).abs();
        assert!(off < 1e-12, "print {k}: {r:?} vs {want:?}");
    }
    assert!(rel_diff(&a.report.field.w, &b.report.field.w) < 1e-9, "w");
    assert!(rel_diff(&a.report.elements.bottom.s1, &b.report.elements.bottom.s1) < 1e-9);
    let load = a.summary.resultant.load;
    let want = 80e3 + 6e3 * 4.5 * 3.6;
    assert!(
        (load - want).abs() < 1e-6 * want,
        "resultant {load} N, want {want}"
    );
}

/// A standard axle given another configuration without its spacing is explained, not asked
/// for a key (issue 36): `esal-single-dual` is a single axle; as a tandem it needs
/// `axle_spacing` or the tandem standard, which the message names.
#[test]
fn a_standard_changed_to_a_tandem_explains_the_conflict() {
    let text = scene(
        "[[load]]\nkind = \"axle\"\nstandard = \"esal-single-dual\"\nconfiguration = \"tandem\"\nx = 0.3\ny = -0.4\n",
        "unbonded",
    );
    let e = liftoff::Problem::from_toml(&text).expect_err("refused");
    let m = e.to_string();
    assert!(
        m.contains("configuration")
            && m.contains("esal-single-dual")
            && m.contains("tandem-dual")
            && m.contains("axle_spacing"),
        "{m}"
    );
    // With its spacing the tandem solves.
    common::run(&text.replace(
        "configuration = \"tandem\"",
        "configuration = \"tandem\"\naxle_spacing = 1.3",
    ));
}

/// A heading that is not a multiple of 90° says in the solve's notes that the prints became
/// squares (issue 36); along the grid there is no such note.
#[test]
fn an_oblique_heading_notes_square_prints() {
    let axle = |heading: f64| {
        scene(
            &format!("[[load]]\nkind = \"axle\"\nstandard = \"esal-single-dual\"\nx = 0.3\ny = -0.2\nheading = {heading}\n"),
            "unbonded",
        )
    };
    let oblique = solve(&axle(30.0));
    assert!(
        oblique
            .summary
            .notes
            .iter()
            .any(|n| n.contains("heading of 30°") && n.contains("squares")),
        "{:?}",
        oblique.summary.notes
    );
    let along = solve(&axle(90.0));
    assert!(
        !along.summary.notes.iter().any(|n| n.contains("squares")),
        "{:?}",
        along.summary.notes
    );
}
