//! Time and peak memory of the unbonded Winkler solvers on one operator set: the dense Schur QP,
//! the sparse QP in its lifted and primal forms (clarabel with the faer or QDLDL KKT solver) and
//! the penalty iteration.
//!
//! Scene: a large square plate on soft soil under a central point load — 0.20 m concrete
//! (E = 30 GPa, ν = 0.2, D = 20.8 MN·m) on k = 10 MN/m³, so ℓ = (D/k)^¼ = 1.20 m, side 48 m
//! ≈ 40 ℓ, 300 kN at the centre; a quarter model by symmetry.
//!
//! Each case runs in a child process so that its peak memory is its own: the child assembles
//! the operators, resets the peak-RSS counter (`/proc/self/clear_refs`), solves, and reports
//! VmHWM (peak of the solve, operators included) and the RSS after assembly.
//!
//!     cargo run --release --example qp_forms -- [--sizes 40,80,120,200,400]
//!         [--methods penalty,dense,lifted,primal] [--kkt faer,qdldl] [--dense-max 120]
//!         [--lifted-max 200] [--repeat 1]
//!         [--constraint nodal|gauss] [--penalty 5e-8] [--tol default|1e-8]
//!
//! Times are the median of `--repeat` runs. Ratios are against the penalty method at the same
//! size in the same run (the machine's other load changes absolute times between runs more
//! than between neighbouring cases).

use std::process::{Command, ExitCode};
use std::time::Instant;

use liftoff::method::QpSettings;
use liftoff::method::{KktSolver, Method};
use liftoff::solve::penalty;
use liftoff::solve::qp::clarabel_dense;
use liftoff::solve::qp::clarabel_sparse::{solve_sparse, SparseForm};
use liftoff::{Operators, Problem, Solution};

const SCENE: &str = r#"
title = "Large plate on soft soil, central point load"
[plate]
length = 48.0
width = 48.0
thickness = 0.20
youngs_modulus = 30e9
poissons_ratio = 0.2
[foundation]
model = "winkler"
modulus = 1.0e7
[[load]]
kind = "point"
x = 0.0
y = 0.0
force = 3.0e5
[mesh]
elements = [N, N]
[solver]
contact = "unbonded"
method = "penalty"
penalty = PENALTY
constraint = "CONSTRAINT"
memory_limit_gib = 20.0
"#;

fn main() -> ExitCode {
    faer::set_global_parallelism(faer::Par::Seq);
    let args: Vec<String> = std::env::args().skip(1).collect();
    let result = if args.first().map(String::as_str) == Some("--one") {
        one(&args[1..])
    } else {
        drive(&args)
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn option<'a>(args: &'a [String], name: &str, default: &'a str) -> &'a str {
    args.iter()
        .position(|a| a == name)
        .and_then(|i| args.get(i + 1))
        .map_or(default, String::as_str)
}

/// Run every case in a child process and print one table.
fn drive(args: &[String]) -> Result<(), String> {
    let sizes = option(args, "--sizes", "40,80,120,200,400");
    let methods = option(args, "--methods", "penalty,dense,lifted,primal");
    let kkts = option(args, "--kkt", "faer,qdldl");
    let constraint = option(args, "--constraint", "nodal");
    let eps = option(args, "--penalty", "5e-8");
    let tol = option(args, "--tol", "default");
    let number = |name: &str, default: &str| -> Result<usize, String> {
        option(args, name, default)
            .parse()
            .map_err(|_| format!("{name}: not a number"))
    };
    let dense_max = number("--dense-max", "120")?;
    let lifted_max = number("--lifted-max", "200")?;
    let repeat = number("--repeat", "1")?.max(1);
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    println!(
        "constraint points: {constraint}; penalty ε̄ = {eps}; QP tolerance {tol}; RAYON_NUM_THREADS={}",
        std::env::var("RAYON_NUM_THREADS").unwrap_or_else(|_| "unset".into())
    );
    println!(
        "{:>5} {:>7} {:>7} {:>8} {:>6} {:>9} {:>8} {:>5} {:>9} {:>9} {:>11} {:>11}  status",
        "n",
        "n_eq",
        "n_σ",
        "method",
        "kkt",
        "solve s",
        "×penalty",
        "iter",
        "peak MiB",
        "ops MiB",
        "σ_max",
        "w_max"
    );
    for size in sizes.split(',') {
        let n: usize = size.trim().parse().map_err(|_| format!("size `{size}`"))?;
        let mut penalty_time = None;
        for method in methods.split(',') {
            let method = method.trim();
            if (method == "dense" && n > dense_max) || (method == "lifted" && n > lifted_max) {
                continue;
            }
            let kkt_list: Vec<&str> = if method == "penalty" {
                vec!["-"]
            } else {
                kkts.split(',')
                    .map(str::trim)
                    // The dense P with QDLDL takes 600 s at 120 × 120 (faer: 44 s).
                    .filter(|&k| !(method == "dense" && k == "qdldl" && n > 80))
                    .collect()
            };
            for kkt in kkt_list {
                let case = ["--one", &n.to_string(), method, kkt, constraint, eps, tol];
                let mut times = Vec::new();
                let mut last = None;
                for _ in 0..repeat {
                    match run_case(&exe, &case)? {
                        Ok(f) => {
                            times.push(f[3].parse::<f64>().unwrap_or(f64::NAN));
                            last = Some(f);
                        }
                        Err(why) => {
                            println!("{n:>5} {method:>8} {kkt:>6}: failed: {why}");
                            break;
                        }
                    }
                }
                let Some(f) = last else { continue };
                times.sort_by(f64::total_cmp);
                let time = times[times.len() / 2];
                if method == "penalty" {
                    penalty_time = Some(time);
                }
                let ratio = penalty_time.map_or(f64::NAN, |p| time / p);
                println!(
                    "{n:>5} {:>7} {:>7} {method:>8} {kkt:>6} {time:>9.3} {ratio:>8.2} {:>5} {:>9} {:>9} {:>11} {:>11}  {}",
                    f[1], f[2], f[4], f[5], f[6], f[7], f[8], f[9..].join(" ")
                );
            }
        }
    }
    Ok(())
}

/// Run one case in a child process: the fields of its RESULT line, or why it failed.
fn run_case(exe: &std::path::Path, case: &[&str]) -> Result<Result<Vec<String>, String>, String> {
    let out = Command::new(exe)
        .args(case)
        .output()
        .map_err(|e| e.to_string())?;
    let text = String::from_utf8_lossy(&out.stdout);
    Ok(match text.lines().find(|l| l.starts_with("RESULT")) {
        Some(line) => Ok(line.split_whitespace().map(String::from).collect()),
        None => Err(format!(
            "{} {}",
            out.status,
            String::from_utf8_lossy(&out.stderr).trim()
        )),
    })
}

fn read_status_kib(key: &str) -> f64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with(key))
                .and_then(|l| l.split_whitespace().nth(1))
                .and_then(|v| v.parse().ok())
        })
        .unwrap_or(f64::NAN)
}

/// One case: `--one N METHOD KKT CONSTRAINT PENALTY TOL`; prints
/// `RESULT n_eq n_σ seconds iterations peak_MiB ops_MiB σ_max w_max status`.
fn one(args: &[String]) -> Result<(), String> {
    let [n, method, kkt, constraint, eps, tol] = args else {
        return Err("--one N METHOD KKT CONSTRAINT PENALTY TOL".into());
    };
    let text = SCENE
        .replace("N, N", &format!("{n}, {n}"))
        .replace("CONSTRAINT", constraint)
        .replace("PENALTY", eps);
    let problem = Problem::from_toml(&text).map_err(|e| e.to_string())?;
    let ops = Operators::assemble(&problem.model);
    let ops_mib = read_status_kib("VmRSS:") / 1024.0;
    // Reset the peak-RSS counter to the current RSS (Linux ≥ 4.0).
    std::fs::write("/proc/self/clear_refs", "5").map_err(|e| e.to_string())?;
    let kkt = match kkt.as_str() {
        "faer" => KktSolver::Faer,
        "qdldl" => KktSolver::Qdldl,
        other => return Err(format!("unknown KKT solver `{other}`")),
    };
    let mut settings = QpSettings {
        kkt,
        ..Default::default()
    };
    if tol != "default" {
        // One relative tolerance for gap and feasibility, the absolute gap a decade below.
        let t: f64 = tol.parse().map_err(|_| format!("tolerance `{tol}`"))?;
        settings.tol_gap_rel = t;
        settings.tol_gap_abs = t / 10.0;
        settings.tol_feas = t;
    }
    let t0 = Instant::now();
    let sol: Solution = match method.as_str() {
        "penalty" => match &problem.method {
            Method::Penalty(p) => penalty::solve(&ops, p),
            _ => return Err("the scene's method must be the penalty".into()),
        },
        "dense" => clarabel_dense::solve(&ops, &settings),
        "lifted" => solve_sparse(&ops, &settings, SparseForm::Lifted),
        "primal" => solve_sparse(&ops, &settings, SparseForm::Primal),
        other => return Err(format!("unknown method `{other}`")),
    }
    .map_err(|e| e.to_string())?;
    let seconds = t0.elapsed().as_secs_f64();
    let peak_mib = read_status_kib("VmHWM:") / 1024.0;
    let sigma_max = sol.sigma.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    let w_max = ops
        .node_w(&sol.u)
        .into_iter()
        .fold(f64::NEG_INFINITY, f64::max);
    println!(
        "RESULT {} {} {seconds:.4} {} {peak_mib:.0} {ops_mib:.0} {sigma_max:.6e} {w_max:.6e} {}",
        ops.n_eq(),
        ops.n_sigma(),
        sol.iterations,
        sol.status.describe()
    );
    eprintln!("timings {:?}", sol.info.timings.named());
    eprintln!("diagnostics {:?}", sol.info.qp.map(|q| q.named()));
    Ok(())
}
