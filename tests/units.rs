//! Scenes in US customary units (issue 36): `units = "us"` reads every length in inches,
//! forces in lbf, pressures and moduli in psi, subgrade moduli in pci and temperatures in °F;
//! the answer is the SI twin's, and the tables show US units.
//!
//! The example is WSDOT's curling slab (WSDOT Pavement Guide, "Temperature stresses"; after
//! Westergaard 1927 and Bradbury 1938): a 14 ft × 12 ft slab, 9 in thick, E = 5 000 000 psi,
//! ν = 0.15, k = 200 pci, α = 5e-6 /°F, 27 °F between the faces, in full contact. Bradbury's
//! stress along the 14 ft free edge at its middle is C·EαΔT/2 = 220.0 psi (C = 0.652 for
//! L/ℓ = 4.76).

use liftoff::{analyse, Problem};

const US: &str = r#"title = "WSDOT curling slab"
units = "us"
[plate]
length = 168.0            # in (14 ft)
width = 144.0             # in (12 ft)
thickness = 9.0           # in
youngs_modulus = 5.0e6    # psi
poissons_ratio = 0.15
thermal_expansion = 5.0e-6  # per °F
[foundation]
model = "winkler"
modulus = 200.0           # pci
[[load]]
kind = "temperature"
difference = 27.0         # °F, top warmer
[mesh]
elements = [56, 48]
symmetry = "none"
[solver]
contact = "bonded"
"#;

/// The SI twin, converted by hand from the definitions (1 in = 0.0254 m, 1 psi = 6894.757293168
/// Pa, 1 pci = 271 447.1375 N/m³, 1/°F = 9/5 /K, 27 °F = 15 K), not by liftoff.
const SI: &str = r#"title = "WSDOT curling slab"
[plate]
length = 4.2672
width = 3.6576
thickness = 0.2286
youngs_modulus = 34473786465.84181
poissons_ratio = 0.15
thermal_expansion = 9.0e-6
[foundation]
model = "winkler"
modulus = 54289427.50526269
[[load]]
kind = "temperature"
difference = 15.0
[mesh]
elements = [56, 48]
symmetry = "none"
[solver]
contact = "bonded"
"#;

const PSI: f64 = 6_894.757_293_168_361;

/// The US scene's answer is its SI twin's: the same Report (SI inside) to 1e-9 in every field,
/// relative to the field's largest value. The two scenes' numbers agree to the last digit of
/// the twin's literals (~1e-16), the solve is linear in them: 1e-9 is round-off with room.
#[test]
fn a_us_scene_equals_its_si_twin() {
    let us = analyse(&Problem::from_toml(US).expect("US scene")).expect("US solve");
    let si = analyse(&Problem::from_toml(SI).expect("SI scene")).expect("SI solve");
    let (a, b) = (&us.report, &si.report);
    let fields = |r: &liftoff::post::Report| -> Vec<(String, Vec<f64>)> {
        let mut v: Vec<(String, Vec<f64>)> = r
            .field
            .columns()
            .iter()
            .map(|(n, _, c)| (format!("nodes.{n}"), c.to_vec()))
            .collect();
        v.extend(
            r.elements
                .columns()
                .iter()
                .map(|(n, _, c)| (format!("elements.{n}"), c.to_vec())),
        );
        v
    };
    let (fa, fb) = (fields(a), fields(b));
    assert_eq!(fa.len(), fb.len());
    let w_peak = b.w_max.abs();
    for ((name, x), (_, y)) in fa.iter().zip(&fb) {
        // A bonded slab's gap is round-off (~1e-18 m): measured against the deflection.
        let floor = if name.ends_with("gap") {
            w_peak
        } else {
            1e-300
        };
        let peak = y.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(floor);
        let off = x
            .iter()
            .zip(y)
            .fold(0.0_f64, |m, (p, q)| m.max((p - q).abs()))
            / peak;
        assert!(
            off < 1e-9,
            "{name}: US and SI differ by {off:e} of its peak"
        );
    }
    let (sa, sb) = (&us.summary, &si.summary);
    for (what, x, y) in [
        ("w_max", sa.w_max, sb.w_max),
        ("pressure_max", sa.pressure_max, sb.pressure_max),
        (
            "bottom stress",
            sa.stresses.bottom.value,
            sb.stresses.bottom.value,
        ),
        ("top stress", sa.stresses.top.value, sb.stresses.top.value),
    ] {
        assert!(
            (x - y).abs() <= 1e-9 * y.abs(),
            "summary {what}: {x} vs {y}"
        );
    }
}

/// Bradbury's mid-edge stress along the 14 ft edge, 220.0 psi, from the US scene: σx at the
/// element centre nearest the middle of the edge y = −6 ft (1.5 in inside it). Westergaard's
/// strip is a thin plate; the 9 in Mindlin slab and the element centre 1.5 in inside the edge
/// move the value by under 0.1 % (liftoff's SI twin is 0.03 % off): 0.5 % as the issue asks.
/// The table shows the stress in psi.
#[test]
fn the_wsdot_curling_slab_gives_bradburys_edge_stress_in_psi() {
    let problem = Problem::from_toml(US).expect("US scene");
    let a = analyse(&problem).expect("solve");
    let e = &a.report.elements;
    let target = (0.0, -72.0 * 0.0254);
    let i = (0..e.x.len())
        .min_by(|&i, &j| {
            let d = |k: usize| (e.x[k] - target.0).powi(2) + (e.y[k] - target.1).powi(2);
            d(i).total_cmp(&d(j))
        })
        .expect("elements");
    // Day curling (top warmer): the bottom is in tension.
    let psi = e.bottom.sx[i] / PSI;
    assert!(
        (psi / 220.0 - 1.0).abs() < 5e-3,
        "mid-edge σx {psi:.2} psi against Bradbury's 220.0 psi"
    );
    // Bradbury's value from his coefficient, as the module's comment derives it.
    let ell = (5e6 * 9f64.powi(3) / (12.0 * (1.0 - 0.15_f64.powi(2)) * 200.0)).powf(0.25);
    let lam = 168.0 / (ell * 8f64.sqrt());
    let c = 1.0
        - 2.0 * (lam.sin() * lam.cosh() + lam.cos() * lam.sinh())
            / ((2.0 * lam).sin() + (2.0 * lam).sinh());
    let bradbury = c * 5e6 * 5e-6 * 27.0 / 2.0;
    assert!(
        (bradbury / 220.0 - 1.0).abs() < 2e-3,
        "C = {c}, {bradbury} psi"
    );
    let table = liftoff::output::tables::solve_table(&a.summary, None);
    assert!(table.contains(" psi"), "the table in psi:\n{table}");
    assert!(table.contains(" mils"), "deflections in mils:\n{table}");
    assert!(
        !table.contains("MPa") && !table.contains(" mm"),
        "no SI units:\n{table}"
    );
}

/// A US scene's key that is not a number is named as in an SI scene, and a unit system that
/// does not exist is refused with the two that do.
#[test]
fn units_errors_name_the_key() {
    let e = Problem::from_toml(&US.replace("units = \"us\"", "units = \"imperial\""))
        .expect_err("refused");
    assert!(
        e.to_string().contains("units") && e.to_string().contains("us"),
        "{e}"
    );
    let e = Problem::from_toml(&US.replace("thickness = 9.0", "thickness = \"nine\""))
        .expect_err("refused");
    assert!(e.to_string().contains("thickness"), "{e}");
    // A US scene is checked in SI after its conversion: a message that quotes metres says so
    // (a 200 in thick slab, 5.08 m, on the 168 in × 144 in plate) ...
    let note = "(its numbers in SI: a US scene is checked after its conversion;";
    let e = Problem::from_toml(&US.replace("thickness = 9.0", "thickness = 200.0"))
        .expect_err("refused")
        .to_string();
    assert!(
        e.contains("5.08 m is not smaller than the plate's sides (4.2672 × 3.6576 m)")
            && e.contains(note),
        "{e}"
    );
    // ... the SI scene's own message does not, nor does a US message without a unit.
    let e = Problem::from_toml(&SI.replace("thickness = 0.2286", "thickness = 5.08"))
        .expect_err("refused")
        .to_string();
    assert!(
        e.contains("5.08 m is not smaller") && !e.contains(note),
        "{e}"
    );
    let e = Problem::from_toml(&US.replace("poissons_ratio = 0.15", "poissons_ratio = 0.7"))
        .expect_err("refused")
        .to_string();
    assert!(e.contains("poissons_ratio") && !e.contains(note), "{e}");
}

/// Values that suggest a unit slip warn, naming the key and the likely slip, and the scene
/// still solves; the bundled SI scene and the US scene do not warn. The slips: the WSDOT slab's
/// SI twin with its modulus typed in psi (5e6 "Pa": ℓ = 0.03 m below the 0.23 m thickness) and
/// its subgrade in pci (200 "N/m³"); a US scene with its sides typed in feet (14 × 12 "in"
/// under 9 in: thicker than a fifth of its side).
#[test]
fn unit_slips_warn_and_still_solve() {
    let psi_as_pa = SI.replace(
        "youngs_modulus = 34473786465.84181",
        "youngs_modulus = 5.0e6",
    );
    let p = Problem::from_toml(&psi_as_pa).expect("scene");
    assert!(
        p.warnings
            .iter()
            .any(|w| w.starts_with("plate.youngs_modulus") && w.contains("psi")),
        "{:?}",
        p.warnings
    );
    analyse(&p).expect("a flexible plate still solves");
    let pci_as_si = SI.replace("modulus = 54289427.50526269", "modulus = 200.0");
    let p = Problem::from_toml(&pci_as_si).expect("scene");
    assert!(
        p.warnings
            .iter()
            .any(|w| w.starts_with("foundation.modulus") && w.contains("pci")),
        "{:?}",
        p.warnings
    );
    let feet = US
        .replace("length = 168.0", "length = 14.0")
        .replace("width = 144.0", "width = 12.0");
    let p = Problem::from_toml(&feet).expect("scene");
    assert!(
        p.warnings
            .iter()
            .any(|w| w.starts_with("plate.thickness") && w.contains("feet")),
        "{:?}",
        p.warnings
    );
    for clean in [SI, US] {
        let p = Problem::from_toml(clean).expect("scene");
        assert!(p.warnings.is_empty(), "{:?}", p.warnings);
    }
    let bundled = liftoff::load(
        &liftoff::Source::Example("slab-on-grade"),
        &Default::default(),
    )
    .expect("example");
    assert!(bundled.warnings.is_empty(), "{:?}", bundled.warnings);
    // A traffic group's levels typed in kN where N was meant (a thousandth of the axle's own
    // 80 kN); newtons in a US scene: `tests/damage.rs`, `a_us_plan_is_its_si_twin`.
    let damage = liftoff::examples::SCENES
        .iter()
        .find(|(n, _, _)| *n == "pavement-damage")
        .map(|(_, _, t)| *t)
        .expect("bundled");
    assert!(Problem::from_toml(damage)
        .expect("scene")
        .warnings
        .is_empty());
    let kn = damage.replace("levels = [60e3, 80e3, 100e3]", "levels = [60, 80, 100]");
    let p = Problem::from_toml(&kn).expect("scene");
    assert!(
        p.warnings.iter().any(|w| w.starts_with(
            "traffic.group[0].levels: a level of 60 N is 0.00× `single`'s own load of 80000 N"
        ) && w.contains("kN typed where N was meant")),
        "{:?}",
        p.warnings
    );
    analyse(&p).expect("a light axle still solves");
}

/// Two doweled slabs in US units, unbonded, a wheel beside the joint and the slabs curled up at
/// night, with a bearing check: every file the solve writes carries physical values.
const JOINTED_US: &str = r#"title = "Two doweled slabs"
units = "us"
[plate]
length = 288.0
width = 144.0
thickness = 10.0
youngs_modulus = 4.0e6
poissons_ratio = 0.15
thermal_expansion = 5.5e-6
[foundation]
model = "winkler"
modulus = 150.0
allowable_pressure = 12.0
bearing_length = 12.0
[[joint]]
x = 0.0
kind = "dowels"
name = "T1"
diameter = 1.25
youngs_modulus = 29.0e6
opening = 0.25
support_modulus = 1.5e6
spacing = 12.0
[[load]]
kind = "point"
x = -10.0
y = -50.0
force = 9000.0
[[load]]
kind = "temperature"
difference = -18.0
[mesh]
elements = [48, 24]
[solver]
contact = "unbonded"
"#;

/// SI per unit of each unit the files print, from the definitions (1 in = 0.0254 m, 1 lbf =
/// 4.448 221 615 260 5 N), written out here and not taken from liftoff; an SI unit is 1.
fn si_per(unit: &str) -> f64 {
    const IN: f64 = 0.0254;
    const LBF: f64 = 4.448_221_615_260_5;
    match unit {
        "in" => IN,
        "in²" => IN * IN,
        "psi" => LBF / (IN * IN),
        "lbf" | "lbf·in/in" => LBF,
        "lbf/in" => LBF / IN,
        "lbf·in" => LBF * IN,
        "m" | "m²" | "Pa" | "N" | "N·m/m" | "N/m" | "N·m" | "rad" | "°" | "-" => 1.0,
        other => panic!("a unit the test does not know: `{other}`"),
    }
}

/// The SI unit a US unit's column must have in the SI twin's file.
fn si_unit(us: &str) -> &str {
    match us {
        "in" => "m",
        "in²" => "m²",
        "psi" => "Pa",
        "lbf" => "N",
        "lbf·in/in" => "N·m/m",
        "lbf/in" => "N/m",
        "lbf·in" => "N·m",
        same => same,
    }
}

/// A CSV file's columns: (name, unit, cells), the unit from the header's `[…]`.
fn columns(path: &std::path::Path) -> Vec<(String, String, Vec<String>)> {
    let mut r = csv::Reader::from_path(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let header: Vec<(String, String)> = r
        .headers()
        .expect("header")
        .iter()
        .map(|h| match h.split_once(" [") {
            Some((n, u)) => (n.to_string(), u.trim_end_matches(']').to_string()),
            None => (h.to_string(), String::new()),
        })
        .collect();
    let rows: Vec<csv::StringRecord> = r.records().map(|x| x.expect("row")).collect();
    header
        .into_iter()
        .enumerate()
        .map(|(k, (n, u))| (n, u, rows.iter().map(|row| row[k].to_string()).collect()))
        .collect()
}

/// Every file of a US scene is its SI twin's after conversion by the units its headers (and
/// summary.json's `units`) name, to 1e-9 of each column's largest value (the solves agree to
/// round-off, ~1e-15, and the CSVs print 13 significant digits, 5e-13), and the units are the
/// twin's in the other system. plate.vtu is written from the same converted fields as nodes.csv
/// and elements.csv (`output::stage_all`). The SI twin is converted by this test from the
/// definitions, not by liftoff.
#[test]
fn every_file_of_a_us_scene_is_its_si_twins_after_conversion() {
    const IN: f64 = 0.0254;
    const LBF: f64 = 4.448_221_615_260_5;
    let psi = LBF / (IN * IN);
    let si = JOINTED_US
        .replace("units = \"us\"\n", "")
        .replace("length = 288.0", &format!("length = {}", 288.0 * IN))
        .replace("width = 144.0", &format!("width = {}", 144.0 * IN))
        .replace("thickness = 10.0", &format!("thickness = {}", 10.0 * IN))
        .replace(
            "youngs_modulus = 4.0e6",
            &format!("youngs_modulus = {}", 4.0e6 * psi),
        )
        .replace(
            "thermal_expansion = 5.5e-6",
            &format!("thermal_expansion = {}", 5.5e-6 * 1.8),
        )
        .replace(
            "modulus = 150.0",
            &format!("modulus = {}", 150.0 * psi / IN),
        )
        .replace(
            "allowable_pressure = 12.0",
            &format!("allowable_pressure = {}", 12.0 * psi),
        )
        .replace(
            "bearing_length = 12.0",
            &format!("bearing_length = {}", 12.0 * IN),
        )
        .replace("diameter = 1.25", &format!("diameter = {}", 1.25 * IN))
        .replace(
            "youngs_modulus = 29.0e6",
            &format!("youngs_modulus = {}", 29.0e6 * psi),
        )
        .replace("opening = 0.25", &format!("opening = {}", 0.25 * IN))
        .replace(
            "support_modulus = 1.5e6",
            &format!("support_modulus = {}", 1.5e6 * psi / IN),
        )
        .replace("spacing = 12.0", &format!("spacing = {}", 12.0 * IN))
        .replace("x = -10.0", &format!("x = {}", -10.0 * IN))
        .replace("y = -50.0", &format!("y = {}", -50.0 * IN))
        .replace("force = 9000.0", &format!("force = {}", 9000.0 * LBF))
        .replace("difference = -18.0", "difference = -10.0");
    let write = |text: &str| {
        let p = Problem::from_toml(text).expect("scene");
        let a = analyse(&p).expect("solve");
        assert!(a.summary.converged, "{}", a.summary.status);
        let dir = tempfile::tempdir().expect("tempdir");
        liftoff::output::write_all(dir.path(), &p.model, &a.report, &a.summary).expect("files");
        dir
    };
    let (us, si) = (write(JOINTED_US), write(&si));
    for file in [
        "nodes.csv",
        "elements.csv",
        "profiles.csv",
        "joints.csv",
        "dowels.csv",
    ] {
        let (a, b) = (
            columns(&us.path().join(file)),
            columns(&si.path().join(file)),
        );
        assert_eq!(a.len(), b.len(), "{file}: columns");
        for ((name, unit, x), (name_si, unit_si, y)) in a.iter().zip(&b) {
            assert_eq!(name, name_si, "{file}");
            assert_eq!(si_unit(unit), unit_si, "{file}: {name}'s units");
            let numbers = |v: &[String]| -> Option<Vec<f64>> {
                v.iter().map(|c| c.parse::<f64>().ok()).collect()
            };
            // Words and identifiers (a joint's name, a row or bar number) have no unit: equal.
            if unit.is_empty() {
                assert!(
                    numbers(x).is_none() || ["minus_node", "plus_node", "bar"].contains(&&**name),
                    "{file}: the numbers of `{name}` have no unit"
                );
                assert_eq!(x, y, "{file}: {name}");
                continue;
            }
            let (Some(x), Some(y)) = (numbers(x), numbers(y)) else {
                panic!("{file}: {name} [{unit}] is not all numbers");
            };
            let f = si_per(unit);
            let peak = y.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(1e-300);
            let off = x
                .iter()
                .zip(&y)
                .fold(0.0_f64, |m, (p, q)| m.max((p * f - q).abs()))
                / peak;
            assert!(
                off < 1e-9,
                "{file}: {name} [{unit}] off by {off:e} of its peak"
            );
        }
    }
    // summary.json: every key its `units` names, and the dimensionless results.
    let json = |dir: &tempfile::TempDir| -> serde_json::Value {
        let text = std::fs::read_to_string(dir.path().join("summary.json")).expect("summary");
        serde_json::from_str(&text).expect("json")
    };
    let (a, b) = (json(&us), json(&si));
    assert_eq!(a["units"]["system"], "us");
    assert_eq!(b["units"]["system"], "si");
    let units = a["units"].as_object().expect("units");
    assert!(units.len() > 20, "{units:?}");
    let at = |v: &serde_json::Value, path: &str| -> Vec<f64> {
        let mut nodes = vec![v.clone()];
        for key in path.split('.') {
            nodes = nodes
                .into_iter()
                .flat_map(|n| match (key, n) {
                    ("*", serde_json::Value::Array(a)) => a,
                    (k, n) => vec![n[k].clone()],
                })
                .collect();
        }
        nodes
            .iter()
            .flat_map(|n| match n {
                serde_json::Value::Array(a) => a.iter().filter_map(|x| x.as_f64()).collect(),
                n => n.as_f64().into_iter().collect::<Vec<f64>>(),
            })
            .collect()
    };
    let mut checked = 0;
    for (path, unit) in units.iter().filter(|(k, _)| *k != "system") {
        let unit = unit.as_str().expect("a unit");
        assert_eq!(si_unit(unit), b["units"][path], "summary {path}'s units");
        let (x, y) = (at(&a, path), at(&b, path));
        assert!(
            !y.is_empty() && x.len() == y.len(),
            "summary {path}: {x:?} {y:?}"
        );
        let peak = y.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(1e-300);
        for (p, q) in x.iter().zip(&y) {
            let off = (p * si_per(unit) - q).abs() / peak;
            assert!(
                off < 1e-9,
                "summary {path}: {p} {unit} against {q}: {off:e}"
            );
        }
        checked += 1;
    }
    for path in [
        "V_max",
        "V_center",
        "V_corner",
        "contact_fraction",
        "contact_radius",
    ] {
        let (x, y) = (at(&a, path), at(&b, path));
        assert!(
            (x[0] - y[0]).abs() <= 1e-9 * y[0].abs(),
            "summary {path}: {x:?} {y:?}"
        );
    }
    assert!(checked >= 25, "{checked} physical keys compared");
}

/// `critical` on a US scene reports in US units: critical.csv's headers name them, and every
/// position's stresses, deflection and place are its SI twin's after conversion (1e-9 of the
/// largest: the two searches solve the same problems). The twin is the WSDOT slab's with an
/// ESAL axle, moved over a 3 × 3 grid.
#[test]
fn critical_reports_a_us_scene_in_us_units() {
    use liftoff::study::CriticalOptions;
    let axle = "[[load]]\nkind = \"axle\"\nname = \"truck\"\nstandard = \"esal-single-dual\"\n\
                x = 0.0\ny = 0.0\n";
    let options = CriticalOptions {
        load: "truck".into(),
        grid: [3, 3],
        ..CriticalOptions::default()
    };
    let search = |scene: &str| {
        let p =
            Problem::from_toml(&scene.replace("[mesh]", &format!("{axle}[mesh]"))).expect("scene");
        options.run(&p, &liftoff::Monitor::NONE).expect("critical")
    };
    let (us, si) = (search(US), search(SI));
    let (a, b) = (us.reported(), si.reported());
    assert_eq!(a.positions.len(), b.positions.len());
    let psi = PSI;
    let peak = b
        .positions
        .iter()
        .fold(0.0_f64, |m, p| m.max(p.bottom.abs()));
    for (p, q) in a.positions.iter().zip(&b.positions) {
        assert!(
            (p.bottom * psi - q.bottom).abs() <= 1e-9 * peak,
            "{} {}",
            p.bottom,
            q.bottom
        );
        assert!(
            (p.x * 0.0254 - q.x).abs() <= 1e-12,
            "{} in vs {} m",
            p.x,
            q.x
        );
        assert!(
            (p.w_max * 0.0254 - q.w_max).abs() <= 1e-9 * q.w_max.abs(),
            "w_max"
        );
    }
    let dir = tempfile::tempdir().expect("tempdir");
    liftoff::output::critical::write_critical(dir.path(), &us, "WSDOT").expect("files");
    let csv = std::fs::read_to_string(dir.path().join("critical.csv")).expect("csv");
    let header = csv.lines().next().expect("header");
    assert!(
        header.starts_with("x [in],y [in],heading [°]") && header.contains("bottom [psi]"),
        "{header}"
    );
    let table = liftoff::output::critical::critical_table("WSDOT", &us, None);
    assert!(
        table.contains(" psi") && table.contains(" in,") && !table.contains("MPa"),
        "{table}"
    );
}

/// The report of a US scene's solve shows its numbers in US units: the page's largest bottom
/// stress is summary.json's (psi, held as the file holds it) and its deflection in mils (the
/// file's inches × 1000), so the page never reads inches or psi as metres or pascals.
#[test]
fn the_report_of_a_us_scene_shows_us_units() {
    let p = Problem::from_toml(JOINTED_US).expect("scene");
    let a = analyse(&p).expect("solve");
    let dir = tempfile::tempdir().expect("tempdir");
    liftoff::output::write_all(dir.path(), &p.model, &a.report, &a.summary).expect("files");
    let page = liftoff::output::report::write_report(dir.path(), None).expect("report");
    let html = std::fs::read_to_string(page).expect("page");
    let summary: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.path().join("summary.json")).expect("summary"),
    )
    .expect("json");
    // A row's shown value: `<td class="value">92.61 psi</td>` after its data-key.
    let shown = |key: &str| -> (f64, String) {
        let at = html
            .find(&format!("data-key=\"{key}\""))
            .unwrap_or_else(|| panic!("no row {key}"));
        let cell = &html[at..];
        let start = cell.find("class=\"value\">").expect("value cell") + 14;
        let text = &cell[start..start + cell[start..].find('<').expect("end")];
        let (n, unit) = text.split_once('\u{202F}').expect("number and unit");
        (n.parse().expect("number"), unit.to_string())
    };
    let (stress, unit) = shown("stresses.bottom.value");
    let held = summary["stresses"]["bottom"]["value"]
        .as_f64()
        .expect("psi");
    assert_eq!(unit, "psi");
    // The page prints four significant digits.
    assert!(
        (stress - held).abs() <= 5e-4 * held,
        "{stress} psi vs {held}"
    );
    let (w, unit) = shown("w_max");
    let held = summary["w_max"].as_f64().expect("in") * 1e3;
    assert_eq!(unit, "mils");
    assert!((w - held).abs() <= 5e-4 * held, "{w} mils vs {held}");
}

/// Every key a scene's sections accept is either converted in a US scene
/// (`scene::convert::quantity` names its quantity) or listed below as one without units — a
/// pure number, a word, an angle, a count, or a key of dimensionless scenes only. A key added to
/// a section without either fails here, before a US scene reads its inches as metres (as
/// `[plate] outline`, `[[opening]]`, a region panel's `x`, `y`, `outline` and a joint's `from`,
/// `to` once were). The sections' keys are serde's own list, from the error a bogus key gets.
/// (`[foundation]`'s keys are each soil's, converted from its own list of SI units.)
#[test]
fn every_scene_key_is_converted_or_has_no_unit() {
    use liftoff::scene::convert::quantity;
    let unitless: &[(&str, &[&str])] = &[
        ("plate", &["poissons_ratio", "shear_correction", "ends"]),
        ("opening", &[]),
        ("void", &[]),
        ("joint", &["kind", "name"]),
        ("panel", &["thickness_ratio", "modulus_ratio"]),
        // `curvature`: the free curl of a dimensionless scene; `shrinkage`: a strain; `heading`:
        // degrees.
        (
            "load",
            &[
                "kind",
                "case",
                "name",
                "curvature",
                "interpolation",
                "shrinkage",
                "standard",
                "configuration",
                "tires",
                "heading",
                "contact_shape",
            ],
        ),
        ("foundation.zone", &["gamma"]),
        (
            "traffic",
            &["design_life", "growth", "wander", "edge", "ends", "group"],
        ),
        ("traffic.wander", &["positions"]),
        ("traffic.group", &["load", "repetitions"]),
        ("climate.bin", &["share"]),
        // The relations' coefficients are those of their published forms (PCA's and the FAA's
        // in US units whatever the scene's).
        (
            "damage",
            &[
                "model",
                "rupture_growth",
                "steps",
                "reliability",
                "coefficients",
                "interpolate",
            ],
        ),
    ];
    for (section, none) in unitless {
        let heading = match *section {
            "plate" | "traffic" | "traffic.wander" | "damage" => format!("[{section}]"),
            s => format!("[[{s}]]"),
        };
        let text = format!("{heading}\nno_such_key = 1\n");
        let err = Problem::from_toml(&text)
            .map(|_| ())
            .expect_err("a bogus key")
            .to_string();
        let list = err
            .split_once("expected one of ")
            .unwrap_or_else(|| panic!("{section}: no key list in {err}"))
            .1;
        let keys: Vec<&str> = list
            .split(", ")
            .map(|k| k.trim().trim_matches(|c| c == '`' || c == '\n'))
            .map(|k| k.split(['`', '\n']).next().unwrap_or(k))
            .collect();
        assert!(keys.len() >= 2, "{section}: {keys:?} from {err}");
        let conv = section.rsplit('.').next().unwrap_or(section);
        let conv = match *section {
            "foundation.zone" => "zone",
            "traffic.wander" | "traffic.group" | "climate.bin" => section,
            _ => conv,
        };
        for key in keys {
            // A load's `difference` is a temperature difference for the temperature kinds.
            let kind = (conv == "load").then_some("temperature");
            let converted = quantity(conv, key, kind, None).is_some();
            let listed = none.contains(&key);
            assert!(
                converted != listed,
                "{section}.{key}: {}",
                if converted {
                    "converted and also listed as without units"
                } else {
                    "neither converted in a US scene (scene/convert.rs) nor listed as without units"
                }
            );
        }
    }
}

/// A shaped plate in US units — an L-shaped 240 in × 160 in slab (10 in cells), a 20 in × 40 in
/// opening, a thicker region panel of its own outline, a joint segment that ends on the
/// outline — is its SI twin, every length × 0.0254 m here: the same deflection and pressure at
/// every node to 1e-9 of the peak (round-off; the twins' numbers agree to ~1e-16).
#[test]
fn a_shaped_us_scene_equals_its_si_twin() {
    const IN: f64 = 0.0254;
    const LBF: f64 = 4.448_221_615_260_5;
    let psi = LBF / (IN * IN);
    let scene = |l: f64, f: f64, p: f64, k: f64, units: &str| {
        format!(
            r#"title = "shaped"
{units}
[plate]
length = {}
width = {}
thickness = {}
youngs_modulus = {}
poissons_ratio = 0.15
outline = [[{}, {}], [{}, {}], [{}, 0.0], [0.0, 0.0], [0.0, {}], [{}, {}]]
[[opening]]
x = [{}, {}]
y = [{}, {}]
[[panel]]
outline = [[{}, {}], [{}, {}], [{}, {}], [{}, {}]]
thickness = {}
[[joint]]
from = [{}, {}]
to = [{}, 0.0]
kind = "aggregate"
stiffness = {}
[foundation]
model = "winkler"
modulus = {}
[[load]]
kind = "uniform"
pressure = {}
[[load]]
kind = "point"
x = {}
y = {}
force = {}
[mesh]
elements = [24, 16]
symmetry = "none"
[solver]
contact = "unbonded"
"#,
            240.0 * l,
            160.0 * l,
            9.0 * l,
            4.0e6 * p,
            -120.0 * l,
            -80.0 * l,
            120.0 * l,
            -80.0 * l,
            120.0 * l,
            80.0 * l,
            -120.0 * l,
            80.0 * l,
            -60.0 * l,
            -40.0 * l,
            -20.0 * l,
            20.0 * l,
            20.0 * l,
            -70.0 * l,
            50.0 * l,
            -70.0 * l,
            50.0 * l,
            -30.0 * l,
            20.0 * l,
            -30.0 * l,
            12.0 * l,
            80.0 * l,
            -80.0 * l,
            80.0 * l,
            5.0e3 * p,
            150.0 * k,
            0.6 * p,
            -90.0 * l,
            50.0 * l,
            9000.0 * f,
        )
    };
    let us = scene(1.0, 1.0, 1.0, 1.0, "units = \"us\"");
    let si = scene(IN, LBF, psi, psi / IN, "");
    let a = analyse(&Problem::from_toml(&us).expect("US scene")).expect("US solve");
    let b = analyse(&Problem::from_toml(&si).expect("SI scene")).expect("SI solve");
    assert!(a.summary.converged && b.summary.converged);
    let column = |r: &liftoff::post::Report, name: &str| -> Vec<f64> {
        r.field
            .columns()
            .iter()
            .find(|(n, _, _)| *n == name)
            .map(|(_, _, c)| c.to_vec())
            .unwrap_or_else(|| panic!("no column {name}"))
    };
    for name in ["w", "pressure"] {
        let (x, y) = (column(&a.report, name), column(&b.report, name));
        assert_eq!(x.len(), y.len(), "{name}: the same plate nodes");
        let peak = y.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        assert!(peak > 0.0, "{name}: something to compare");
        let off = x
            .iter()
            .zip(&y)
            .filter(|(p, q)| p.is_finite() || q.is_finite())
            .fold(0.0_f64, |m, (p, q)| m.max((p - q).abs()))
            / peak;
        assert!(
            off < 1e-9,
            "{name}: US and SI differ by {off:e} of the peak"
        );
    }
    // The re-entrant corners' notes give their places in the scene's unit: the SI twin's
    // (x, y) m are the US scene's (x / 0.0254, y / 0.0254) in (the first corner is the
    // opening's, (−60, −20) in: off the origin, so the factor shows).
    let corner = |notes: &[String], unit: &str| -> [f64; 2] {
        let note = notes
            .iter()
            .find(|n| n.contains("re-entrant corners (the first at ("))
            .unwrap_or_else(|| panic!("no corner note in {notes:?}"));
        let at = note.split("the first at (").nth(1).expect("a place");
        let (xy, rest) = at.split_once(')').expect("a closing bracket");
        assert!(rest.starts_with(&format!(" {unit}")), "{note}");
        let v: Vec<f64> = xy
            .split(", ")
            .map(|t| t.parse().expect("a number"))
            .collect();
        [v[0], v[1]]
    };
    let (us_at, si_at) = (corner(&a.report.notes, "in"), corner(&b.report.notes, "m"));
    for k in 0..2 {
        // Printed to 3 decimals in each unit.
        assert!(
            (us_at[k] * IN - si_at[k]).abs() < 1e-3,
            "{us_at:?} in vs {si_at:?} m"
        );
    }
}
