//! The bearing check on the pressure averaged over a square of side `bearing_length` (issue 32
//! §1.3), against references the code does not produce: the half-space's edge singularity
//! (Boussinesq 1885; Sadowsky 1928; Johnson, Contact Mechanics, the flat-ended punch) makes the
//! nodal corner pressure grow without bound as the mesh is refined, while an average over a
//! fixed square — an integral of an integrable pressure — converges; the default side is the plate's thickness;
//! a given side is kept, a bad one refused (E67, in tests/errors.rs).

use crate::common;

use common::run;
use liftoff::post::Bearing;

/// The issue's raft: 12 × 8 × 0.5 m concrete on a half-space of E_s = 30 MPa, 20 kPa uniform
/// plus six columns (600 and 800 kN), allowable 150 kPa.
fn raft(elements: [usize; 2], extra: &str) -> String {
    let mut s = format!(
        r#"
title = "Raft on a half-space"
[plate]
length = 12.0
width = 8.0
thickness = 0.5
youngs_modulus = 30e9
poissons_ratio = 0.2
[foundation]
model = "half-space"
youngs_modulus = 30e6
poissons_ratio = 0.3
allowable_pressure = 150e3
{extra}
[[load]]
kind = "uniform"
pressure = 20.0e3
[mesh]
elements = [{}, {}]
"#,
        elements[0], elements[1]
    );
    for (x, y, f) in [
        (-4.0, -2.0, 600e3),
        (0.0, -2.0, 800e3),
        (4.0, -2.0, 600e3),
        (-4.0, 2.0, 600e3),
        (0.0, 2.0, 800e3),
        (4.0, 2.0, 600e3),
    ] {
        s.push_str(&format!(
            "[[load]]\nkind = \"point\"\nx = {x}\ny = {y}\nforce = {f}\n"
        ));
    }
    s
}

fn bearing(text: &str) -> (Bearing, Vec<String>) {
    let a = run(text);
    let b = a
        .report
        .bearing
        .unwrap_or_else(|| panic!("no bearing check"));
    (b, a.report.notes.clone())
}

/// On 24 × 16, 48 × 32 and 96 × 64 elements the nodal peak (a corner) grows by more than a
/// quarter per halving of h — it would grow without bound — while the average over the corner
/// 0.5 m square converges: its successive differences shrink by more than half (observed
/// 151.79, 143.67, 146.34 kPa: differences 8.1 and 2.7 kPa, a rate h^1.6; 192 × 128 gives
/// 147.08, a difference of 0.74 kPa, h^1.9), and the last is within 2 % of the one before.
/// The note names the singularity and the averaged length.
#[test]
fn the_averaged_pressure_converges_while_the_nodal_corner_peak_grows() {
    let runs: Vec<(Bearing, Vec<String>)> = [[24, 16], [48, 32], [96, 64]]
        .into_iter()
        .map(|m| bearing(&raft(m, "")))
        .collect();
    for (b, _) in &runs {
        eprintln!(
            "averaged {:.2} kPa at {:?}, nodal peak {:.1} kPa",
            b.average / 1e3,
            b.average_at,
            b.max / 1e3
        );
        assert!((b.length - 0.5).abs() < 1e-12, "default: the thickness");
        // The largest average is at a corner square: centre 0.25 m inside both edges.
        assert!(
            (b.average_at[0].abs() - 5.75).abs() < 1e-12
                && (b.average_at[1].abs() - 3.75).abs() < 1e-12,
            "{:?}",
            b.average_at
        );
        assert!(b.max > 1.5 * b.average, "the corner peak stands above");
    }
    let avg: Vec<f64> = runs.iter().map(|(b, _)| b.average).collect();
    let peak: Vec<f64> = runs.iter().map(|(b, _)| b.max).collect();
    assert!(
        peak[1] > 1.25 * peak[0] && peak[2] > 1.25 * peak[1],
        "nodal peaks {peak:?} should grow with the mesh"
    );
    let (d1, d2) = ((avg[1] - avg[0]).abs(), (avg[2] - avg[1]).abs());
    eprintln!(
        "differences {:.3}, {:.3} kPa: rate h^{:.2}",
        d1 / 1e3,
        d2 / 1e3,
        (d1 / d2).log2()
    );
    assert!(d2 < 0.5 * d1, "averages {avg:?} should converge");
    assert!(d2 < 0.02 * avg[2], "averages {avg:?}");
    for (b, notes) in &runs {
        assert!(
            notes.iter().any(|n| n.contains("r^(−1/2)")
                && n.contains("not a design number")
                && n.contains("0.500 m")),
            "{notes:?}"
        );
        assert!((b.utilisation - b.average / 150e3).abs() < 1e-12);
        assert!((b.nodal_utilisation - b.max / 150e3).abs() < 1e-12);
    }
}

/// A given side is used (a larger square averages lower at the corner), and the whole
/// plate's width is allowed; Winkler gets no note.
#[test]
fn a_given_length_is_used_and_winkler_has_no_note() {
    let (small, _) = bearing(&raft([24, 16], "bearing_length = 0.5"));
    let (large, _) = bearing(&raft([24, 16], "bearing_length = 2.0"));
    let (whole, _) = bearing(&raft([24, 16], "bearing_length = 8.0"));
    assert_eq!((large.length, whole.length), (2.0, 8.0));
    assert!(large.average < small.average, "{large:?} vs {small:?}");
    // Over the whole width, the largest 8 × 8 m square's average lies between the mean
    // pressure (the net load over the area) and the 2 m square's.
    let mean = (20e3 * 96.0 + 4000e3) / 96.0;
    assert!(whole.average > 0.99 * mean && whole.average < large.average);
    let winkler = raft([24, 16], "").replace(
        "model = \"half-space\"\nyoungs_modulus = 30e6\npoissons_ratio = 0.3",
        "model = \"winkler\"\nmodulus = 2e7",
    );
    let (_, notes) = bearing(&winkler);
    assert!(
        notes.iter().all(|n| !n.contains("bearing_length")),
        "{notes:?}"
    );
}

/// Dimensionless scenes: the side in units of L, by default the thickness H/L that Δ gives,
/// H² = 5 (1 − ν) μ Δ L² with χ = 5/6; the same field read through a given side.
#[test]
fn dimensionless_lengths_are_in_units_of_l() {
    let scene = |extra: &str| {
        format!(
            "[dimensionless]\nfoundation = \"half-space\"\ngamma = 1e-3\ndelta = 2e-3\nmu = 0.5\nnu = 0.3\nallowable_pressure = 1.0\n{extra}\n[[load]]\nkind = \"uniform\"\npressure = 1.0\n[mesh]\nelements = [16, 8]\n"
        )
    };
    let (b, notes) = bearing(&scene(""));
    let h = (5.0 * 0.7 * 0.5 * 2e-3_f64).sqrt();
    assert!((b.length - h).abs() < 1e-12, "{} vs {h}", b.length);
    assert!(notes.iter().any(|n| n.contains(&format!("{h:.4} L"))));
    let (c, _) = bearing(&scene("bearing_length = 0.25"));
    assert_eq!(c.length, 0.25);
}
