//! Physical scenes are reported in engineering units (mm, kPa, kN·m/m, kN, m), dimensionless
//! ones in the paper's V and σ: the `liftoff solve` table and the charts of a solve.
//!
//! The physical reference values are computed here from the scene's own numbers (plate
//! rigidity D = E h³ / (12 (1 − ν²)), P = a quarter of the load resultant, L = half the length),
//! not from the library's scales.

use crate::common;

use liftoff::output::tables::solve_table;
use liftoff::output::write_all;

/// The numbers after `key` in `line`, up to the first word that is not a number.
fn numbers_after(table: &str, key: &str) -> Vec<f64> {
    let at = table
        .find(key)
        .unwrap_or_else(|| panic!("table lacks {key:?}:\n{table}"));
    table[at + key.len()..]
        .split_whitespace()
        .map(|w| w.trim_end_matches(','))
        .map_while(|w| w.parse::<f64>().ok())
        .collect()
}

/// One point load of 200 kN at (1.5, 1) m on a 6 m × 4 m × 0.25 m plate (E = 30 GPa, ν = 0.2):
/// P = 50 kN, L = 3 m, D = 30e9 · 0.25³ / (12 · 0.96) = 40.69 MN·m.
#[test]
fn physical_table_is_in_engineering_units() {
    let a = common::run(common::BASE);
    let s = &a.summary;
    let table = solve_table(s, None);
    let d = 30e9 * 0.25_f64.powi(3) / (12.0 * (1.0 - 0.2 * 0.2));
    let (p, l, mu) = (2.0e5 / 4.0, 3.0, 2.0 / 3.0);
    let mm_per_v = p * l * l / d * 1e3;
    let kpa_per_sigma = p / (mu * l * l) * 1e-3;

    // Deflections: max, centre and corner in mm (3 decimals: half a unit of 1e-3 mm).
    let w = numbers_after(&table, "deflection : max");
    let c = numbers_after(&table, "centre");
    let k = numbers_after(&table, "corner");
    for (got, want, what) in [
        (w[0], s.V_max * mm_per_v, "max"),
        (c[0], s.V_center * mm_per_v, "centre"),
        (k[0], s.V_corner * mm_per_v, "corner"),
    ] {
        assert!(
            (got - want).abs() <= 5e-4 + 1e-9,
            "w {what}: {got} mm vs {want} mm"
        );
    }
    // Peak pressure in kPa from the largest nodal σ (1 decimal).
    let sigma_max = a.report.field.sigma.iter().cloned().fold(0.0, f64::max);
    let pr = numbers_after(&table, "pressure   : nodal peak");
    assert!(
        (pr[0] - sigma_max * kpa_per_sigma).abs() <= 0.05 + 1e-9,
        "pressure {} kPa vs {}",
        pr[0],
        sigma_max * kpa_per_sigma
    );
    // Load in kN: 200 kN (2 decimals).
    let load = numbers_after(&table, "resultant  : load");
    assert!((load[0] - 200.0).abs() <= 5e-3, "load {} kN", load[0]);
    // Contact: area of the plate's 24 m², radius and extents in m (2 decimals).
    let area = numbers_after(&table, "% of the plate (");
    assert!(
        (area[0] - 24.0 * s.contact_fraction).abs() <= 5e-3 + 1e-9,
        "contact area {} m²",
        area[0]
    );
    let radius = numbers_after(&table, "radius");
    assert!((radius[0] - l * s.contact_radius).abs() <= 5e-3 + 1e-9);
    let ext = numbers_after(&table, "extent x");
    assert!((ext[0] - l * s.contact_extent.x).abs() <= 5e-3 + 1e-9);
    let diag = numbers_after(&table, "diagonal");
    let half_diagonal = (3.0_f64 * 3.0 + 2.0 * 2.0).sqrt();
    assert!((diag[0] - half_diagonal * s.contact_extent.diagonal).abs() <= 5e-3 + 1e-9);
    for unit in ["mm", "kPa", "kN·m/m", "kN,", "m²", " m from the centre"] {
        assert!(
            table.contains(unit),
            "physical table lacks {unit:?}:\n{table}"
        );
    }
    assert!(
        !table.contains("V = D w"),
        "V stays out of a physical table"
    );
}

/// The same problem given by its dimensionless groups keeps V, σ and fractions of L.
#[test]
fn dimensionless_table_keeps_v_and_sigma() {
    let a = common::run(&common::point_scene(
        "winkler",
        1e-3,
        1e-3,
        1.0,
        (0.0, 0.0),
        [8, 8],
        "",
    ));
    let table = solve_table(&a.summary, None);
    let v = numbers_after(&table, "V          : max");
    assert!((v[0] - a.summary.V_max).abs() <= 5e-6 * a.summary.V_max.abs());
    assert!(table.contains("radius") && table.contains(" L, extent x"));
    for unit in ["mm", "kPa", "kN"] {
        assert!(
            !table.contains(unit),
            "dimensionless table has {unit:?}:\n{table}"
        );
    }
}

/// The files of a solve carry the units of its scene: metres, mm and kPa for the physical
/// scene, V and σ for the dimensionless one.
#[test]
fn charts_of_a_solve_carry_its_units() {
    let dir = tempfile::tempdir().expect("tempdir");
    let a = common::run(common::BASE);
    let model = liftoff::Problem::from_toml(common::BASE)
        .expect("scene")
        .model;
    write_all(dir.path(), &model, &a.report, &a.summary).expect("write");
    let read = |name: &str| std::fs::read_to_string(dir.path().join(name)).expect(name);
    let contact = read("contact.svg");
    for needle in ["x (m)", "y (m)", "pressure (kPa)"] {
        assert!(contact.contains(needle), "contact.svg lacks {needle:?}");
    }
    let profiles = read("profiles.svg");
    for needle in [
        "deflection w (mm), downward",
        "contact pressure (kPa)",
        "edge-y (x = 3 m)",
    ] {
        assert!(profiles.contains(needle), "profiles.svg lacks {needle:?}");
    }

    let scene = common::point_scene("winkler", 1e-3, 1e-3, 1.0, (0.0, 0.0), [8, 8], "");
    let b = common::run(&scene);
    let model = liftoff::Problem::from_toml(&scene).expect("scene").model;
    let dir = tempfile::tempdir().expect("tempdir");
    write_all(dir.path(), &model, &b.report, &b.summary).expect("write");
    let read = |name: &str| std::fs::read_to_string(dir.path().join(name)).expect(name);
    let contact = read("contact.svg");
    assert!(contact.contains("\nσ, to the") && !contact.contains("kPa"));
    let profiles = read("profiles.svg");
    assert!(profiles.contains("V = D w / (P L²), downward") && !profiles.contains("mm"));
}
