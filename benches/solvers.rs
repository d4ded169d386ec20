//! Criterion benchmarks: assembly and both methods on Winkler and half-space plates.
//!
//! Run with `cargo bench --bench solvers`; results and the machine are in BENCHMARKS.md.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use liftoff::scene::{Contact, MethodKind, Problem};
use liftoff::solve::{self, qp};
use liftoff::Operators;

fn paper(foundation: &str, n: usize, contact: Contact, method: MethodKind) -> Problem {
    let name = if foundation == "winkler" {
        "paper-winkler"
    } else {
        "paper-halfspace"
    };
    let text = liftoff::examples::scene(name).unwrap_or_default();
    let text = text
        .replace("elements = [16, 16]", &format!("elements = [{n}, {n}]"))
        .replace("elements = [20, 20]", &format!("elements = [{n}, {n}]"));
    let mut p = Problem::from_toml(&text).expect("bundled scene");
    p.solver.contact = contact;
    p.solver.method = method;
    p
}

fn winkler(c: &mut Criterion) {
    faer::set_global_parallelism(faer::Par::Seq);
    let mut g = c.benchmark_group("winkler");
    g.sample_size(10);
    for n in [100, 200, 400] {
        let p = paper("winkler", n, Contact::Bonded, MethodKind::Penalty);
        g.bench_with_input(BenchmarkId::new("assemble", n), &p, |b, p| {
            b.iter(|| Operators::assemble(p).expect("assemble"))
        });
        let ops = Operators::assemble(&p).expect("assemble");
        g.bench_with_input(BenchmarkId::new("bonded-solve", n), &ops, |b, ops| {
            b.iter(|| solve::bonded::solve(ops).expect("solve"))
        });
        let pu = paper("winkler", n, Contact::Unbonded, MethodKind::Penalty);
        g.bench_with_input(BenchmarkId::new("penalty-solve", n), &ops, |b, ops| {
            b.iter(|| solve::solve(ops, &pu.solver).expect("solve"))
        });
    }
    g.finish();
}

fn half_space(c: &mut Criterion) {
    faer::set_global_parallelism(faer::Par::Seq);
    let mut g = c.benchmark_group("half-space");
    g.sample_size(10);
    for n in [32, 64] {
        let p = paper("half-space", n, Contact::Unbonded, MethodKind::Penalty);
        g.bench_with_input(BenchmarkId::new("assemble", n), &p, |b, p| {
            b.iter(|| Operators::assemble(p).expect("assemble"))
        });
        let ops = Operators::assemble(&p).expect("assemble");
        g.bench_with_input(BenchmarkId::new("penalty-solve", n), &ops, |b, ops| {
            b.iter(|| solve::solve(ops, &p.solver).expect("solve"))
        });
        for kkt in ["faer", "qdldl"] {
            let s = qp::QpSettings {
                kkt: kkt.into(),
                ..Default::default()
            };
            g.bench_with_input(BenchmarkId::new(format!("qp-{kkt}"), n), &ops, |b, ops| {
                b.iter(|| qp::solve(ops, &s).expect("solve"))
            });
        }
    }
    g.finish();
}

criterion_group!(benches, winkler, half_space);
criterion_main!(benches);
