//! Dowel bars (issue 32 §2) against references the code does not produce: the bar's constants
//! of src/layout.rs against a direct beam solution committed in the repository
//! (`tests/references/dowel_beam.py`, standard library only, run here), and the bearing stress
//! that dowels.csv reports against Friberg's formula written out from the source.

use liftoff::layout::DowelBar;
use liftoff::{analyse, Problem};

/// The 32 mm steel bar of the README's example (opening `z`).
fn bar(z: f64) -> DowelBar {
    DowelBar {
        diameter: 0.032,
        youngs_modulus: 200e9,
        opening: z,
        support: 4.07e11,
    }
}

/// The value after `key = ` on the first line of `text` that contains `tag`.
fn value(text: &str, tag: &str, key: &str) -> f64 {
    let line = text
        .lines()
        .find(|l| l.contains(tag))
        .unwrap_or_else(|| panic!("no line with {tag:?} in\n{text}"));
    let at = line.find(&format!("{key} = ")).expect("the key") + key.len() + 3;
    line[at..]
        .split_whitespace()
        .next()
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("a number after {key} in {line:?}"))
}

/// The script solves the bar as an 8 × 8 boundary-value problem (the two embedded parts as
/// beams on a Winkler bed, the opening as a free span, continuity of y, y', y'', y''') with a
/// unit relative displacement of the slabs; its force is the spring. It uses none of
/// DowelBar's closed forms, so agreement to round-off (measured ~1e-16; 1e-12 asserted)
/// checks them: the spring for five openings, β, and at 10 kN the face deflection and the
/// bearing stress. Python 3 is needed, as by ./test (set PYTHON to choose the interpreter).
#[test]
fn the_bar_constants_are_the_direct_beam_solution() {
    let python = std::env::var("PYTHON").unwrap_or_else(|_| "python3".into());
    let out = std::process::Command::new(&python)
        .arg(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/references/dowel_beam.py"
        ))
        .output()
        .unwrap_or_else(|e| panic!("running {python} (needed, as by ./test): {e}"));
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).expect("utf-8");
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs();
    let beta = value(&text, "beta", "beta");
    assert!(
        close(bar(0.0).beta(), beta),
        "β {} vs {beta}",
        bar(0.0).beta()
    );
    let mut seen = 0;
    for line in text.lines().filter(|l| l.starts_with("z = ")) {
        let z = value(line, "z = ", "z");
        let k = value(line, "k_d", "k_d");
        assert!(
            close(bar(z).spring(), k),
            "z = {z}: {} vs {k}",
            bar(z).spring()
        );
        seen += 1;
    }
    assert_eq!(seen, 5, "five openings in\n{text}");
    let y0 = value(&text, "P = 10 kN", "y0");
    let sigma = value(&text, "P = 10 kN", "K y0");
    assert!(close(bar(0.006).face_deflection(1e4), y0));
    assert!(close(bar(0.006).bearing_stress(1e4), sigma));
}

/// dowels.csv's bearing stress, bar by bar, is Friberg's σ_b = K y₀ with
/// y₀ = P (2 + βz)/(4β³E_dI_d), β = (K d/(4E_dI_d))^¼, I_d = πd⁴/64 (Friberg, "Design of dowels
/// in transverse joints of concrete pavements", Trans. ASCE 105, 1940, after Timoshenko &
/// Lessels 1925), written out here from the file's own force column — so it checks what the
/// file reports, not only the library's function. A 6 m × 3 m slab on Winkler, the doweled
/// joint x = 0 (32 mm bars every 0.3 m, 6 mm opening), 200 kN beside it, bonded. The CSV has
/// 13 significant digits, so each of F and σ_b is good to 5e-13; 2e-9 asserted covers the
/// formula's own round-off. The summary's
/// largest bearing stress is the largest row's.
#[test]
fn dowels_csv_bearing_stress_is_fribergs_formula() {
    let text = "[plate]\nlength = 6.0\nwidth = 3.0\nthickness = 0.25\nyoungs_modulus = 30e9\n\
poissons_ratio = 0.2\n[foundation]\nmodel = \"winkler\"\nmodulus = 5e7\n\
[[joint]]\nx = 0.0\nkind = \"dowels\"\nname = \"T1\"\ndiameter = 0.032\nyoungs_modulus = 200e9\n\
opening = 0.006\nsupport_modulus = 4.07e11\nspacing = 0.3\n\
[[load]]\nkind = \"patch\"\nx = [-0.3, 0.0]\ny = [-0.2, 0.2]\npressure = 1.6666666666666667e6\n\
[solver]\ncontact = \"bonded\"\n[mesh]\nelements = [24, 12]\nsymmetry = \"none\"\n";
    let p = Problem::from_toml(text).expect("scene");
    let a = analyse(&p).expect("solve");
    let dir = tempfile::tempdir().expect("tempdir");
    liftoff::output::write_all(dir.path(), &p.model, &a.report, &a.summary).expect("files");
    let csv = std::fs::read_to_string(dir.path().join("dowels.csv")).expect("dowels.csv");
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().expect("header").split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).expect(name);
    let (cf, cs) = (col("force [N]"), col("bearing_stress [Pa]"));
    // Friberg, from the source: the bar's constants.
    let (d, e_d, k_s, z): (f64, f64, f64, f64) = (0.032, 200e9, 4.07e11, 0.006);
    let i_d = std::f64::consts::PI * d.powi(4) / 64.0;
    let beta = (k_s * d / (4.0 * e_d * i_d)).powf(0.25);
    let mut rows = 0;
    let mut largest = 0.0_f64;
    for line in lines {
        let cells: Vec<&str> = line.split(',').collect();
        let force: f64 = cells[cf].parse().expect("a force");
        let sigma: f64 = cells[cs].parse().expect("a bearing stress");
        let friberg = k_s * force.abs() * (2.0 + beta * z) / (4.0 * beta.powi(3) * e_d * i_d);
        assert!(
            (sigma - friberg).abs() <= 2e-9 * friberg,
            "row {rows}: σ_b {sigma} vs Friberg {friberg} for F = {force}"
        );
        largest = largest.max(sigma);
        rows += 1;
    }
    assert_eq!(rows, 10, "bars every 0.3 m over 3 m");
    // The heaviest bar bears a few MPa: the check is not of zeros.
    assert!(largest > 1e6, "largest σ_b {largest}");
    let json: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.path().join("summary.json")).expect("summary.json"),
    )
    .expect("json");
    let max = json["joints"][0]["max_bearing_stress"]
        .as_f64()
        .expect("a number");
    assert!(
        (max - largest).abs() <= 1e-9 * largest,
        "{max} vs {largest}"
    );
}

/// A bar between nodes (issue 32 §2) against rigid-body statics. Two panels 3 m × 3 m of a
/// plate so stiff that each is a rigid body (E = 3e17 Pa: k L⁴/D ≈ 1e-5, so bending moves the
/// answer by ~1e-5), bonded to Winkler springs, joined at x = 0 by one dowel of spring
/// k_d at y_d = −0.4075 m — 0.37 of the way between the mesh's nodes at −0.5 and −0.25 — and a
/// point load on the left panel. Each panel's deflection is w = a + b (x − x_c) + c y, so the
/// dowel's force is k_d times the jump of two linear fields, which the element's interpolation
/// along the edge carries exactly wherever the bar sits: the force is the 6 × 6 rigid-body
/// system's, solved here by hand. Its spring matrix is k Σ A_i φ_i φ_iᵀ over each panel's nodes
/// with φ = (1, x − x_c, y) and the nodal areas of the bilinear elements (h²/4 at corners, h²/2
/// on edges, h² inside) — the lumped bed liftoff uses, written out here; the load's consistent
/// nodal forces on a rigid panel are P φ(x_P, y_P).
#[test]
#[allow(clippy::needless_range_loop)] // Gaussian elimination reads best with its indices
fn a_bar_between_nodes_carries_the_rigid_panels_force() {
    let (k, k_d, p) = (5e7_f64, 5e8_f64, 1e5_f64);
    let (y_d, load) = (-0.4075_f64, (-1.2_f64, 0.7_f64));
    let text = format!(
        "[plate]\nlength = 6.0\nwidth = 3.0\nthickness = 0.25\nyoungs_modulus = 3e17\n\
poissons_ratio = 0.2\n[foundation]\nmodel = \"winkler\"\nmodulus = {k:e}\n\
[[joint]]\nx = 0.0\nkind = \"dowels\"\nname = \"T1\"\ndowel_stiffness = {k_d:e}\npositions = [{y_d}]\n\
[[load]]\nkind = \"point\"\nx = {}\ny = {}\nforce = {p:e}\n\
[solver]\ncontact = \"bonded\"\n[mesh]\nelements = [24, 12]\nsymmetry = \"none\"\n",
        load.0, load.1
    );
    let problem = Problem::from_toml(&text).expect("scene");
    let a = analyse(&problem).expect("solve");
    let dir = tempfile::tempdir().expect("tempdir");
    liftoff::output::write_all(dir.path(), &problem.model, &a.report, &a.summary).expect("files");
    let csv = std::fs::read_to_string(dir.path().join("dowels.csv")).expect("dowels.csv");
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().expect("header").split(',').collect();
    let cf = header
        .iter()
        .position(|h| *h == "force [N]")
        .expect("force");
    let rows: Vec<f64> = lines
        .map(|l| {
            l.split(',')
                .nth(cf)
                .expect("cell")
                .parse()
                .expect("a force")
        })
        .collect();
    assert_eq!(rows.len(), 1, "one bar");

    // The rigid-body reference: q = (a₁, b₁, c₁, a₂, b₂, c₂), panel centres x_c = ∓1.5.
    let h = 0.25;
    let mut m = [[0.0_f64; 6]; 6];
    for (panel, xc) in [(0, -1.5_f64), (1, 1.5_f64)] {
        for i in 0..=12 {
            for j in 0..=12 {
                let wx = if i == 0 || i == 12 { 0.5 } else { 1.0 };
                let wy = if j == 0 || j == 12 { 0.5 } else { 1.0 };
                let (x, y) = (xc - 1.5 + h * i as f64, -1.5 + h * j as f64);
                let phi = [1.0, x - xc, y];
                for r in 0..3 {
                    for c in 0..3 {
                        m[3 * panel + r][3 * panel + c] += k * h * h * wx * wy * phi[r] * phi[c];
                    }
                }
            }
        }
    }
    // The dowel: energy ½ k_d (φ₁(0, y_d)·q₁ − φ₂(0, y_d)·q₂)².
    let g = [1.0, 1.5, y_d, -1.0, 1.5, -y_d];
    for r in 0..6 {
        for c in 0..6 {
            m[r][c] += k_d * g[r] * g[c];
        }
    }
    let mut f = [p, p * (load.0 + 1.5), p * load.1, 0.0, 0.0, 0.0];
    // Gaussian elimination (the matrix is symmetric positive definite: no pivoting needed).
    for col in 0..6 {
        for row in col + 1..6 {
            let factor = m[row][col] / m[col][col];
            for c in col..6 {
                m[row][c] -= factor * m[col][c];
            }
            f[row] -= factor * f[col];
        }
    }
    let mut q = [0.0_f64; 6];
    for row in (0..6).rev() {
        let s: f64 = (row + 1..6).map(|c| m[row][c] * q[c]).sum();
        q[row] = (f[row] - s) / m[row][row];
    }
    let jump: f64 = g.iter().zip(&q).map(|(a, b)| a * b).sum();
    let force = k_d * jump;
    // The dowel carries a good part of the load (not a check of small numbers).
    assert!(force.abs() > 0.05 * p, "dowel force {force}");
    // Bending at k L⁴/D ≈ 1e-5 and the CSV's 10 digits: 1e-4 of the force bounds both.
    assert!(
        (rows[0].abs() - force.abs()).abs() <= 1e-4 * force.abs(),
        "dowels.csv {} N against the rigid panels' {force} N",
        rows[0]
    );
}
