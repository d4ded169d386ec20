//! Criterion benchmark: ten load combinations of one slab solved on one assembly
//! (`combination::analyse`) against ten separate analyses that each assemble their own
//! operators (what ten runs of the CLI do, without the process start and the files).
//!
//! Run with `cargo bench --bench combinations`; results and the machine are in BENCHMARKS.md.

use criterion::{criterion_group, criterion_main, Criterion};
use liftoff::Problem;

/// The bundled slab-on-grade with its loads split into two cases and ten combinations of
/// factors; `foundation` replaces its Winkler subgrade (e.g. by a half-space).
fn slab(foundation: &str, elements: &str) -> (Problem, Vec<Problem>) {
    let text = liftoff::examples::scene("slab-on-grade").unwrap_or_default();
    let mut text = text
        .replace("force = 3.0e5            # N, downward", "force = 3.0e5")
        .replace("force = 3.0e5\n", "force = 3.0e5\ncase = \"columns\"\n")
        .replace(
            "pressure = 4.8e3         # Pa: 0.20 m × 24 kN/m³",
            "pressure = 4.8e3\ncase = \"self\"",
        )
        .replace("elements = [60, 40]", elements)
        .replace("penalty = 1e-5", "penalty = \"auto\"");
    if !foundation.is_empty() {
        text = text.replace(
            "model = \"winkler\"\nmodulus = 3.0e7          # N/m³",
            foundation,
        );
    }
    let factors: Vec<f64> = (0..10).map(|k| 1.0 + 0.1 * k as f64).collect();
    let mut combined = text.clone();
    for (k, f) in factors.iter().enumerate() {
        combined.push_str(&format!(
            "\n[[combination]]\nname = \"C{k}\"\nfactors = {{ self = 1.35, columns = {f} }}\n"
        ));
    }
    let separate = factors
        .iter()
        .map(|f| {
            let t = text
                .replace("case = \"columns\"", "")
                .replace("case = \"self\"", "")
                .replace("force = 3.0e5", &format!("force = {}", 3.0e5 * f))
                .replace("pressure = 4.8e3", &format!("pressure = {}", 4.8e3 * 1.35));
            Problem::from_toml(&t).expect("scene")
        })
        .collect();
    (Problem::from_toml(&combined).expect("scene"), separate)
}

fn ten(c: &mut Criterion) {
    let mut g = c.benchmark_group("ten-combinations");
    g.sample_size(10);
    for (name, foundation, elements) in [
        ("winkler-120x80", "", "elements = [120, 80]"),
        (
            "halfspace-48x32",
            "model = \"half-space\"\nyoungs_modulus = 5.0e7\npoissons_ratio = 0.3",
            "elements = [48, 32]",
        ),
    ] {
        let (combined, separate) = slab(foundation, elements);
        assert_eq!(combined.combinations.len(), 10);
        // Time only runs that give answers: one run of each, outside the timing, converged.
        let once = liftoff::combination::analyse(&combined, &liftoff::Monitor::NONE)
            .expect("combinations");
        assert!(
            once.all_converged(),
            "{name}: combinations not converged, nothing to time: {:?}",
            once.missing()
        );
        for p in &separate {
            let a = liftoff::analyse(p).expect("analysis");
            assert!(
                a.solution.status.converged(),
                "{name}: separate analysis not converged: {}",
                a.solution.status.describe()
            );
        }
        g.bench_function(format!("{name}/one-assembly"), |b| {
            b.iter(|| {
                liftoff::combination::analyse(&combined, &liftoff::Monitor::NONE).expect("run")
            })
        });
        g.bench_function(format!("{name}/ten-analyses"), |b| {
            b.iter(|| {
                for p in &separate {
                    liftoff::analyse(p).expect("run");
                }
            })
        });
    }
    g.finish();
}

criterion_group!(benches, ten);
criterion_main!(benches);
