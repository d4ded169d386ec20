//! Criterion benchmarks: assembly and both methods on Winkler and half-space plates.
//!
//! Run with `cargo bench --bench solvers`; results and the machine are in BENCHMARKS.md.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use liftoff::method::{KktSolver, Method, QpSolver};
use liftoff::solve::{self, qp::clarabel_dense, Solution};
use liftoff::{Operators, Problem};

/// A bench times a solve only after one run of it, outside the timing, converged: a failed or
/// capped solve would be timed as if it were an answer.
fn converged(what: &str, s: liftoff::Result<Solution>) {
    let s = s.unwrap_or_else(|e| panic!("{what}: {e}"));
    assert!(
        s.status.converged(),
        "{what}: not converged, nothing to time: {}",
        s.status.describe()
    );
}

fn paper(foundation: &str, n: usize) -> Problem {
    let name = if foundation == "winkler" {
        "paper-winkler"
    } else {
        "paper-halfspace"
    };
    let text = liftoff::examples::scene(name).unwrap_or_default();
    let text = text
        .replace("elements = [16, 16]", &format!("elements = [{n}, {n}]"))
        .replace("elements = [20, 20]", &format!("elements = [{n}, {n}]"));
    Problem::from_toml(&text).expect("bundled scene")
}

fn winkler(c: &mut Criterion) {
    faer::set_global_parallelism(faer::Par::Seq);
    let mut g = c.benchmark_group("winkler");
    g.sample_size(10);
    for n in [100, 200, 400] {
        let p = paper("winkler", n);
        g.bench_with_input(BenchmarkId::new("assemble", n), &p, |b, p| {
            b.iter(|| Operators::assemble(&p.model))
        });
        let ops = Operators::assemble(&p.model);
        converged("winkler bonded", solve::bonded::solve(&ops));
        converged("winkler penalty", solve::solve(&ops, &Method::penalty()));
        converged(
            "winkler active set",
            solve::solve(&ops, &qp(QpSolver::ActiveSet)),
        );
        g.bench_with_input(BenchmarkId::new("bonded-solve", n), &ops, |b, ops| {
            b.iter(|| solve::bonded::solve(ops).expect("solve"))
        });
        g.bench_with_input(BenchmarkId::new("penalty-solve", n), &ops, |b, ops| {
            b.iter(|| solve::solve(ops, &Method::penalty()).expect("solve"))
        });
        // The QP by the matrix-free active-set solver (auto's choice on Winkler soil).
        g.bench_with_input(BenchmarkId::new("qp-active-set", n), &ops, |b, ops| {
            b.iter(|| solve::solve(ops, &qp(QpSolver::ActiveSet)).expect("solve"))
        });
    }
    g.finish();
}

fn qp(solver: QpSolver) -> Method {
    Method::Qp(liftoff::QpSettings {
        solver,
        ..Default::default()
    })
}

fn half_space(c: &mut Criterion) {
    faer::set_global_parallelism(faer::Par::Seq);
    let mut g = c.benchmark_group("half-space");
    g.sample_size(10);
    for n in [32, 64] {
        let p = paper("half-space", n);
        g.bench_with_input(BenchmarkId::new("assemble", n), &p, |b, p| {
            b.iter(|| Operators::assemble(&p.model))
        });
        let ops = Operators::assemble(&p.model);
        converged("half-space penalty", solve::solve(&ops, &Method::penalty()));
        g.bench_with_input(BenchmarkId::new("penalty-solve", n), &ops, |b, ops| {
            b.iter(|| solve::solve(ops, &Method::penalty()).expect("solve"))
        });
        // The same penalty on the iterative route (T by FFT, conjugate gradients).
        let iterative = Operators::assemble_with(&p.model, true);
        converged(
            "half-space penalty, iterative",
            solve::solve(&iterative, &Method::penalty()),
        );
        converged(
            "half-space active set, iterative",
            solve::solve(&iterative, &qp(QpSolver::ActiveSet)),
        );
        g.bench_with_input(
            BenchmarkId::new("penalty-solve-iterative", n),
            &iterative,
            |b, ops| b.iter(|| solve::solve(ops, &Method::penalty()).expect("solve")),
        );
        // The QP on the same iterative operators: the matrix-free active-set solver.
        g.bench_with_input(
            BenchmarkId::new("qp-active-set-iterative", n),
            &iterative,
            |b, ops| b.iter(|| solve::solve(ops, &qp(QpSolver::ActiveSet)).expect("solve")),
        );
        for kkt in [KktSolver::Faer, KktSolver::Qdldl] {
            let s = liftoff::QpSettings {
                kkt,
                ..Default::default()
            };
            converged("half-space clarabel", clarabel_dense::solve(&ops, &s));
            g.bench_with_input(
                BenchmarkId::new(format!("qp-{}", kkt.name()), n),
                &ops,
                |b, ops| b.iter(|| clarabel_dense::solve(ops, &s).expect("solve")),
            );
        }
    }
    g.finish();
}

/// T·x for the paper's quarter models: the dense matrix-vector product against the FFT
/// (block-Toeplitz) product of the same T.
fn compliance(c: &mut Criterion) {
    use liftoff::foundation::{fft::ToeplitzCompliance, halfspace};
    let mut g = c.benchmark_group("compliance");
    g.sample_size(10);
    for n in [32, 64, 128, 256, 512] {
        let mesh = liftoff::mesh::Mesh::new(2.0, 2.0, [n, n], true, true);
        let x: Vec<f64> = (0..mesh.n_nodes()).map(|i| (i as f64).sin()).collect();
        let fft = ToeplitzCompliance::new(&mesh, 2.5e-4);
        g.bench_with_input(BenchmarkId::new("fft-apply", n), &x, |b, x| {
            b.iter(|| fft.apply(x))
        });
        if n <= 128 {
            let dense = halfspace::compliance(&mesh, 2.5e-4);
            g.bench_with_input(BenchmarkId::new("dense-apply", n), &x, |b, x| {
                b.iter(|| dense.apply(x))
            });
        }
    }
    g.finish();
}

criterion_group!(benches, winkler, half_space, compliance);
criterion_main!(benches);
