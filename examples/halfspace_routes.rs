//! The half-space penalty iteration on the dense and the iterative routes: time, conjugate-gradient
//! iterations, and the difference between the two answers.
//!
//! Scene: the paper's Fig. 3 case (`example:paper-halfspace`): square plate, central point load,
//! Γ_h = 0.25e-3, Δ = 0.002857, ε̄ = 1e-5 fixed, nodal constraints, quarter model.
//!
//!     cargo run --release --example halfspace_routes -- [--sizes 32,64,128] [--dense-max 128]
//!         [--springs 0.05] [--tol 1e-10] [--loose 1e-4] [--no-iterative] [--fine-plate]
//!         [--no-shear-layer]
//!
//! `--springs` is λ of the preconditioner's springs λ·diag(T): on penalised points only, unless
//! `--no-shear-layer` puts the plate on springs everywhere (the preconditioner before session 23).
//!
//! Run one route per process (`--dense-max 0`, or `--no-iterative`) to read its peak memory
//! (VmHWM, printed) on its own.
//!
//! For each size (elements per side of the whole plate) it assembles once per route, runs the
//! penalty iteration and prints one line per route, with the per-step CG iterations, and the
//! relative differences max|ΔV|/max|V|, max|Δσ|/max|σ| and the contact nodes that differ.

use std::time::Instant;

use liftoff::method::{CgSettings, Method, PenaltySettings};
use liftoff::{Operators, Problem, Solution};

fn arg<T: std::str::FromStr>(args: &[String], name: &str) -> Option<T> {
    args.iter()
        .position(|a| a == name)
        .and_then(|i| args.get(i + 1))
        .and_then(|v| v.parse().ok())
}

fn list(args: &[String], name: &str, default: &[f64]) -> Vec<f64> {
    args.iter()
        .position(|a| a == name)
        .and_then(|i| args.get(i + 1))
        .map(|v| v.split(',').filter_map(|x| x.parse().ok()).collect())
        .unwrap_or_else(|| default.to_vec())
}

fn rss_mib() -> f64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM:"))
                .and_then(|l| l.split_whitespace().nth(1))
                .and_then(|v| v.parse::<f64>().ok())
        })
        .map_or(f64::NAN, |kib| kib / 1024.0)
}

fn rel(a: &[f64], b: &[f64]) -> f64 {
    let d = a
        .iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    d / b.iter().map(|x| x.abs()).fold(f64::MIN_POSITIVE, f64::max)
}

fn main() {
    // As the CLI does: faer's sparse solves run sequentially (BENCHMARKS.md).
    faer::set_global_parallelism(faer::Par::Seq);
    let args: Vec<String> = std::env::args().collect();
    let sizes = list(&args, "--sizes", &[32.0, 64.0, 128.0]);
    let dense_max: usize = arg(&args, "--dense-max").unwrap_or(128);
    let springs = list(&args, "--springs", &[0.2]);
    let tol: f64 = arg(&args, "--tol").unwrap_or(1e-10);
    let loose: f64 = arg(&args, "--loose").unwrap_or(1e-4);
    let iterative = !args.iter().any(|a| a == "--no-iterative");
    let coarse = !args.iter().any(|a| a == "--fine-plate");
    let shear_layer = !args.iter().any(|a| a == "--no-shear-layer");
    let text = liftoff::examples::scene("paper-halfspace").unwrap_or_default();
    for &n in &sizes {
        let n = n as usize;
        let scene = text.replace("elements = [16, 16]", &format!("elements = [{n}, {n}]"));
        let problem = match Problem::from_toml(&scene) {
            Ok(p) => p,
            Err(e) => {
                eprintln!("scene: {e}");
                return;
            }
        };
        let base = PenaltySettings::fixed(1e-5);
        let mut dense: Option<Solution> = None;
        if n <= dense_max {
            let t0 = Instant::now();
            let ops = Operators::assemble(&problem.model);
            let ta = t0.elapsed().as_secs_f64();
            let t1 = Instant::now();
            match liftoff::solve(&ops, &Method::Penalty(base)) {
                Ok(sol) => {
                    println!(
                        "{n:4} dense      assemble {ta:7.3} s  solve {:7.3} s  steps {:2}  {}  peak {:.0} MiB",
                        t1.elapsed().as_secs_f64(),
                        sol.iterations,
                        sol.status.kind(),
                        rss_mib()
                    );
                    dense = Some(sol);
                }
                Err(e) => println!("{n:4} dense: {e}"),
            }
        }
        for &lambda in springs.iter().filter(|_| iterative) {
            let t0 = Instant::now();
            let ops = Operators::assemble_with(&problem.model, true);
            let ta = t0.elapsed().as_secs_f64();
            let settings = PenaltySettings {
                cg: CgSettings {
                    tolerance: tol,
                    loose_tolerance: loose,
                    coarse_plate: coarse,
                    shear_layer,
                    spring_scale: lambda,
                    ..CgSettings::default()
                },
                ..base
            };
            let t1 = Instant::now();
            match liftoff::solve(&ops, &Method::Penalty(settings)) {
                Ok(sol) => {
                    let its: Vec<String> = sol
                        .history
                        .iter()
                        .map(|h| h.cg.map_or("-".into(), |c| c.iterations.to_string()))
                        .collect();
                    let worst = sol
                        .history
                        .iter()
                        .filter_map(|h| h.cg.map(|c| c.true_residual))
                        .fold(0.0, f64::max);
                    let mut line = format!(
                        "{n:4} iter λ={lambda:<4} assemble {ta:7.3} s  solve {:7.3} s  steps {:2}  {}  CG {} [{}]  worst true res {worst:.1e}  peak {:.0} MiB",
                        t1.elapsed().as_secs_f64(),
                        sol.iterations,
                        sol.status.kind(),
                        sol.info.cg_iterations.unwrap_or(0),
                        its.join(" "),
                        rss_mib()
                    );
                    if let Some(d) = &dense {
                        let vd = ops.node_w(&d.u);
                        let vi = ops.node_w(&sol.u);
                        let cd: Vec<bool> = d.sigma.iter().map(|&s| s > 0.0).collect();
                        let ci: Vec<bool> = sol.sigma.iter().map(|&s| s > 0.0).collect();
                        let differ = cd.iter().zip(&ci).filter(|(a, b)| a != b).count();
                        line += &format!(
                            "  ΔV {:.1e} Δσ {:.1e} contact differs at {differ}",
                            rel(&vi, &vd),
                            rel(&sol.sigma, &d.sigma)
                        );
                    }
                    println!("{line}");
                }
                Err(e) => println!("{n:4} iterative λ={lambda}: {e}"),
            }
        }
    }
}
