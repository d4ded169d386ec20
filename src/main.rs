//! `liftoff` command line: parse arguments, call the library, print.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use liftoff::method::{Contact, MethodKind};
use liftoff::model::{ConstraintPoints, SymmetryMode};
use liftoff::output;
use liftoff::scene::{PenaltySpec, SceneFile};
use liftoff::{Error, Problem};

/// Exit codes, one per kind of failure (docs/ERRORS.md).
mod exit {
    pub const BAD_INPUT: u8 = 2;
    pub const INFEASIBLE: u8 = 3;
    pub const SOLVER: u8 = 4;
    pub const IO: u8 = 5;
}

#[derive(Parser)]
#[command(
    name = "liftoff",
    version,
    about = "Rectangular plates on tensionless foundations: where they lift off, how they deflect, what the soil takes"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Solve a scene file and report deflections, pressures and the contact region.
    Solve(SolveArgs),
    /// Run the penalty method and the QP on one assembled model and compare them.
    Compare(CompareArgs),
    /// Solve with the QP once and the penalty method at many ε̄: the penalty limit.
    EpsSweep(EpsSweepArgs),
    /// Speed against accuracy of both methods over meshes (and ε̄ for the penalty).
    Tradeoff(TradeoffArgs),
    /// Sweep the regimes where the methods break (Γ, ε̄, load position, μ, mesh).
    Stability(StabilityArgs),
    /// Regenerate the paper's Figs. 3–7 (SVG and PNG), paper.json and paper.md.
    Paper(PaperArgs),
    /// Print a bundled example scene (without NAME: list them).
    Example {
        /// Name of the example.
        name: Option<String>,
    },
}

/// Options shared by `solve` and `compare` that override the scene file.
fn apply_overrides(
    file: &mut SceneFile,
    penalty: Option<PenaltySpec>,
    constraint: Option<ConstraintPoints>,
    mesh: Option<[i64; 2]>,
) {
    if let Some(p) = penalty {
        file.solver.penalty = p;
    }
    if let Some(c) = constraint {
        file.solver.constraint = c;
    }
    if let Some(m) = mesh {
        file.mesh.elements = m.to_vec();
    }
}

#[derive(clap::Args)]
struct SolveArgs {
    /// Scene file (TOML), or `example:NAME` for a bundled scene.
    scene: String,
    /// Contact law (overrides [solver] contact).
    #[arg(long, value_enum)]
    contact: Option<Contact>,
    /// Method for unbonded contact (overrides [solver] method).
    #[arg(long, value_enum)]
    method: Option<MethodKind>,
    /// Dimensionless penalty ε̄: auto, or a fixed value such as 1e-5 (overrides [solver] penalty).
    #[arg(long, value_parser = parse_penalty)]
    penalty: Option<PenaltySpec>,
    /// Constraint points (overrides [solver] constraint).
    #[arg(long, value_enum)]
    constraint: Option<ConstraintPoints>,
    /// Elements over the whole plate, NX,NY (overrides [mesh] elements).
    #[arg(long, value_parser = parse_mesh)]
    mesh: Option<[i64; 2]>,
    /// Symmetry reduction (overrides [mesh] symmetry).
    #[arg(long, value_enum)]
    symmetry: Option<SymmetryMode>,
    /// Directory for summary.json, CSV tables, plate.vtu and charts.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Print summary.json to stdout instead of the table.
    #[arg(long)]
    json: bool,
}

#[derive(clap::Args)]
struct CompareArgs {
    /// Scene file (TOML), or `example:NAME` for a bundled scene.
    scene: String,
    /// Dimensionless penalty ε̄: auto, or a fixed value such as 1e-5 (overrides [solver] penalty).
    #[arg(long, value_parser = parse_penalty)]
    penalty: Option<PenaltySpec>,
    /// Constraint points (overrides [solver] constraint).
    #[arg(long, value_enum)]
    constraint: Option<ConstraintPoints>,
    /// Elements over the whole plate, NX,NY (overrides [mesh] elements).
    #[arg(long, value_parser = parse_mesh)]
    mesh: Option<[i64; 2]>,
    /// Directory for compare.json (default: the current directory).
    #[arg(long, default_value = ".")]
    out: PathBuf,
}

#[derive(clap::Args)]
struct EpsSweepArgs {
    /// Scene file (TOML), or `example:NAME`.
    scene: String,
    /// Largest ε̄.
    #[arg(long, default_value_t = 1e-1)]
    from: f64,
    /// Smallest ε̄.
    #[arg(long, default_value_t = 1e-12)]
    to: f64,
    /// Number of ε̄ values (log-spaced).
    #[arg(long, default_value_t = 12)]
    points: usize,
    /// Constraint variants: nodal, gauss or both.
    #[arg(long, default_value = "nodal")]
    constraints: String,
    /// Directory for eps_sweep.csv and eps_sweep.svg.
    #[arg(long, default_value = ".")]
    out: PathBuf,
}

#[derive(clap::Args)]
struct TradeoffArgs {
    /// Scene file (TOML), or `example:NAME`.
    scene: String,
    /// Elements per side of the whole plate (along x; y follows μ).
    #[arg(long, value_delimiter = ',', default_value = "8,16,32,64")]
    meshes: Vec<usize>,
    /// Penalty values ε̄ for the penalty method.
    #[arg(long, value_delimiter = ',', default_value = "1e-2,1e-4,1e-6,1e-8")]
    penalties: Vec<f64>,
    /// Directory for tradeoff.csv and tradeoff.svg.
    #[arg(long, default_value = ".")]
    out: PathBuf,
}

#[derive(clap::Args)]
struct StabilityArgs {
    /// Base scenes (default: the paper's square plate on both foundations).
    scenes: Vec<String>,
    /// Directory for stability.csv and the maps.
    #[arg(long, default_value = ".")]
    out: PathBuf,
}

#[derive(clap::Args)]
struct PaperArgs {
    /// Directory for the figures, paper.json and paper.md.
    #[arg(long, default_value = "paper")]
    out: PathBuf,
    /// Method for the unbonded solves.
    #[arg(long, value_enum, default_value = "penalty")]
    method: MethodKind,
    /// Reading of the paper's load condition 2: patch (γ from Fig. 6's captions), patch=G, or edge-band.
    #[arg(long, default_value = "patch")]
    load2: String,
    /// Also solve on meshes 2, 4, … up to this many times finer than the paper's.
    #[arg(long, default_value_t = 1)]
    refine: usize,
}

fn parse_penalty(s: &str) -> Result<PenaltySpec, String> {
    match s.trim() {
        "auto" => Ok(PenaltySpec::Word("auto".into())),
        v => v
            .parse::<f64>()
            .map(PenaltySpec::Value)
            .map_err(|_| format!("expected auto or a number such as 1e-5, got `{s}`")),
    }
}

fn parse_mesh(s: &str) -> Result<[i64; 2], String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != 2 {
        return Err(format!("expected NX,NY (two element counts), got `{s}`"));
    }
    let n = |p: &str| {
        p.parse::<i64>()
            .map_err(|_| format!("`{p}` is not a whole number of elements"))
    };
    Ok([n(parts[0])?, n(parts[1])?])
}

fn main() -> ExitCode {
    faer::set_global_parallelism(faer::Par::Seq);
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Solve(args) => solve(args),
        Command::Compare(args) => compare(args),
        Command::EpsSweep(args) => eps_sweep(args),
        Command::Tradeoff(args) => tradeoff(args),
        Command::Stability(args) => stability(args),
        Command::Paper(args) => paper(args),
        Command::Example { name } => example(name.as_deref()),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure { message, code }) => {
            eprintln!("error: {message}");
            ExitCode::from(code)
        }
    }
}

struct Failure {
    message: String,
    code: u8,
}

impl From<Error> for Failure {
    fn from(e: Error) -> Self {
        let code = match &e {
            Error::Parse(_)
            | Error::Invalid { .. }
            | Error::TooLarge { .. }
            | Error::Unsupported(_) => exit::BAD_INPUT,
            Error::Infeasible(_) => exit::INFEASIBLE,
            Error::Numerical { .. } => exit::SOLVER,
            Error::Io { .. } => exit::IO,
        };
        let hint = match &e {
            Error::Infeasible(_) => {
                "\nhint: bonded contact (--contact bonded) lets the foundation pull"
            }
            Error::Numerical { .. } => "\nhint: --method qp, or a coarser --mesh",
            _ => "",
        };
        Failure {
            message: format!("{e}{hint}"),
            code,
        }
    }
}

fn example(name: Option<&str>) -> Result<(), Failure> {
    match name {
        None => {
            println!("Bundled scenes (print one with `liftoff example NAME`, solve it with `liftoff solve example:NAME`):");
            for (n, d, _) in liftoff::examples::SCENES {
                println!("  {n:<22} {d}");
            }
            Ok(())
        }
        Some(n) => match liftoff::examples::scene(n) {
            Some(text) => {
                print!("{text}");
                Ok(())
            }
            None => Err(Failure {
                message: format!("no bundled example `{n}`; run `liftoff example` for the list"),
                code: exit::BAD_INPUT,
            }),
        },
    }
}

fn read_scene(spec: &str) -> Result<(String, SceneFile), Failure> {
    let text = if let Some(name) = spec.strip_prefix("example:") {
        liftoff::examples::scene(name)
            .ok_or_else(|| Failure {
                message: format!("no bundled example `{name}`; run `liftoff example` for the list"),
                code: exit::BAD_INPUT,
            })?
            .to_string()
    } else {
        std::fs::read_to_string(spec).map_err(|e| Failure {
            message: format!("cannot read scene file {spec}: {e}"),
            code: exit::IO,
        })?
    };
    let file = SceneFile::parse(&text).map_err(|e| Failure {
        message: format!("{spec}: {e}"),
        code: exit::BAD_INPUT,
    })?;
    Ok((text, file))
}

fn solve(args: SolveArgs) -> Result<(), Failure> {
    let (_, mut file) = read_scene(&args.scene)?;
    if let Some(c) = args.contact {
        file.solver.contact = c;
    }
    if let Some(m) = args.method {
        file.solver.method = m;
    }
    apply_overrides(&mut file, args.penalty, args.constraint, args.mesh);
    if let Some(s) = args.symmetry {
        file.mesh.symmetry = s;
    }
    let problem = file.validate().map_err(|e| with_scene(&args.scene, e))?;
    if let Some(dir) = &args.out {
        output::prepare_dir(dir)?;
    }
    let analysis = liftoff::analyse(&problem)?;
    let summary = &analysis.summary;
    // A result that did not converge is not a solution: no files are written for it.
    let mut written = Vec::new();
    if let (Some(dir), true) = (&args.out, summary.converged) {
        written = output::write_all(dir, &analysis.report, summary)?;
    }
    if args.json {
        println!("{}", summary.to_json()?);
    } else {
        print_table(&problem, summary);
        if let Some(dir) = &args.out {
            println!("  files      : {} in {}", written.len(), dir.display());
        }
        println!();
        println!("{SIGN_CONVENTION}");
    }
    if !summary.converged {
        let hint = match analysis.solution.status {
            liftoff::Status::PenaltyTooWeak {
                suggested_penalty, ..
            } => format!("\nhint: rerun with --penalty {suggested_penalty:.0e} or --method qp"),
            _ => "\nhint: --method qp solves the same operators as a convex QP".into(),
        };
        return Err(Failure {
            message: format!(
                "the {} method did not converge ({}); the numbers above are not a solution and no files were written{hint}",
                summary.method, summary.status
            ),
            code: exit::SOLVER,
        });
    }
    Ok(())
}

fn compare(args: CompareArgs) -> Result<(), Failure> {
    let (_, mut file) = read_scene(&args.scene)?;
    apply_overrides(&mut file, args.penalty, args.constraint, args.mesh);
    let problem = file.validate().map_err(|e| with_scene(&args.scene, e))?;
    output::prepare_dir(&args.out)?;
    let c = liftoff::compare::compare(&problem)?;
    let json = serde_json::to_string_pretty(&c).map_err(|e| Failure {
        message: format!("cannot serialise compare.json: {e}"),
        code: exit::IO,
    })?;
    let mut st = output::Staged::new(&args.out)?;
    st.write_text("compare.json", &json)?;
    st.commit()?;
    let (p, q) = (&c.penalty, &c.qp);
    println!("liftoff compare — {}", p.title);
    println!(
        "  model: {} {} × {} elements ({} pressure nodes), {} foundation, ε̄ = {:e}, {} constraints, assembled once in {:.3} s",
        p.symmetry, p.model_elements[0], p.model_elements[1], p.nodes, p.foundation, p.dimensionless.penalty.unwrap_or(f64::NAN), p.constraint, c.assemble_s
    );
    println!("  {:<22} {:>16} {:>16}", "", "penalty", "qp");
    let status = |x: &output::Summary| {
        if x.converged {
            "converged".to_string()
        } else {
            "NOT converged".to_string()
        }
    };
    type Cell = fn(&output::Summary) -> String;
    let rows: [(&str, Cell); 10] = [
        ("iterations", |x| x.iterations.to_string()),
        ("solve time (s)", |x| format!("{:.4}", x.time_s.solve)),
        ("V_max", |x| format!("{:.6e}", x.V_max)),
        ("contact fraction", |x| format!("{:.4}", x.contact_fraction)),
        ("contact radius", |x| format!("{:.4}", x.contact_radius)),
        ("extent x", |x| format!("{:.4}", x.contact_extent.x)),
        ("extent y", |x| format!("{:.4}", x.contact_extent.y)),
        ("extent diagonal", |x| {
            format!("{:.4}", x.contact_extent.diagonal)
        }),
        ("min σ", |x| {
            format!("{:.2e}", x.complementarity.min_pressure)
        }),
        ("max |σ·gap|", |x| {
            format!("{:.2e}", x.complementarity.max_product)
        }),
    ];
    println!("  {:<22} {:>16} {:>16}", "status", status(p), status(q));
    for (name, cell) in rows {
        println!("  {name:<22} {:>16} {:>16}", cell(p), cell(q));
    }
    let d = &c.differences;
    println!(
        "  max |Δσ| = {:.3e} ({:.2e} of max σ), max |ΔV| = {:.3e} ({:.2e} of max V), contact differs at {} node(s)",
        d.max_abs_sigma, d.rel_sigma, d.max_abs_v, d.rel_v, d.contact_nodes_differing
    );
    println!("  written: {}", args.out.join("compare.json").display());
    if !p.converged || !q.converged {
        return Err(Failure {
            message: "a method did not converge; see the status row".into(),
            code: exit::SOLVER,
        });
    }
    Ok(())
}

fn progress_bar(len: u64) -> indicatif::ProgressBar {
    let pb = indicatif::ProgressBar::new(len);
    if let Ok(style) =
        indicatif::ProgressStyle::with_template("{bar:30} {pos}/{len} {elapsed_precise} {msg}")
    {
        pb.set_style(style);
    }
    pb
}

fn load_problem(spec: &str) -> Result<Problem, Failure> {
    let (_, file) = read_scene(spec)?;
    file.validate().map_err(|e| with_scene(spec, e))
}

fn eps_sweep(args: EpsSweepArgs) -> Result<(), Failure> {
    let bad = |m: String| Failure {
        message: m,
        code: exit::BAD_INPUT,
    };
    if !(args.from.is_finite()
        && args.to.is_finite()
        && args.from > 0.0
        && args.to > 0.0
        && args.from < 1.0)
    {
        return Err(bad(format!(
            "--from and --to must be positive ε̄ values below 1, got {} and {}",
            args.from, args.to
        )));
    }
    if args.points < 2 || args.points > 200 {
        return Err(bad(format!(
            "--points must lie in 2..=200, got {}",
            args.points
        )));
    }
    let constraints = match args.constraints.as_str() {
        "nodal" => vec![ConstraintPoints::Nodal],
        "gauss" => vec![ConstraintPoints::Gauss],
        "both" => vec![ConstraintPoints::Nodal, ConstraintPoints::Gauss],
        other => {
            return Err(bad(format!(
                "--constraints takes nodal, gauss or both, got `{other}`"
            )))
        }
    };
    let problem = load_problem(&args.scene)?;
    output::prepare_dir(&args.out)?;
    let eps = liftoff::study::log_space(args.from, args.to, args.points);
    let pb = progress_bar((constraints.len() * (eps.len() + 1)) as u64);
    let window = [args.to.min(args.from), args.from.max(args.to)];
    let sweep = liftoff::study::eps_sweep(&problem, &eps, &constraints, window, &mut |m: &str| {
        pb.set_message(m.to_string());
        pb.inc(1);
    })?;
    pb.finish_and_clear();
    output::studies::write_sweep(
        &args.out,
        &sweep,
        &format!("{} — penalty against QP", problem.model.title),
    )?;
    println!("liftoff eps-sweep — {}", problem.model.title);
    println!(
        "  {:<6} {:>9} {:>5} {:>17} {:>11} {:>11} {:>11} {:>9}",
        "points", "ε̄", "steps", "status", "L2 err σ", "L2 err V", "min σ", "time (s)"
    );
    for r in &sweep.rows {
        println!(
            "  {:<6} {:>9.1e} {:>5} {:>17} {:>11.3e} {:>11.3e} {:>11.2e} {:>9.4}",
            r.constraint,
            r.eps,
            r.iterations,
            r.status,
            r.rel_l2_sigma,
            r.rel_l2_v,
            r.min_pressure,
            r.time_s
        );
    }
    for (k, s, range) in &sweep.slopes {
        match s {
            Some(s) => println!(
                "  {k}: fitted slope {s:.3} over ε̄ ∈ [{:.0e}, {:.0e}], down to where the error flattens (first order: 1)",
                range[0], range[1]
            ),
            None => println!("  {k}: too few settled points to fit a slope"),
        }
    }
    println!(
        "  written: eps_sweep.csv, eps_sweep.svg in {}",
        args.out.display()
    );
    Ok(())
}

fn tradeoff(args: TradeoffArgs) -> Result<(), Failure> {
    let bad = |m: String| Failure {
        message: m,
        code: exit::BAD_INPUT,
    };
    if args.meshes.is_empty() || args.meshes.iter().any(|n| !(2..=2048).contains(n)) {
        return Err(bad(
            "--meshes takes element counts between 2 and 2048".into()
        ));
    }
    if args.penalties.iter().any(|&e| !(e > 0.0 && e < 1.0)) {
        return Err(bad("--penalties takes ε̄ values in (0, 1)".into()));
    }
    let problem = load_problem(&args.scene)?;
    output::prepare_dir(&args.out)?;
    let pb = progress_bar((1 + args.meshes.len() * (1 + args.penalties.len())) as u64);
    let t = liftoff::study::tradeoff(&problem, &args.meshes, &args.penalties, &mut |m: &str| {
        pb.set_message(m.to_string());
        pb.inc(1);
    })?;
    pb.finish_and_clear();
    output::studies::write_tradeoff(
        &args.out,
        &t,
        &format!("{} — speed against accuracy", problem.model.title),
    )?;
    println!("liftoff tradeoff — {}", problem.model.title);
    println!("  reference: {}", t.reference);
    println!(
        "  {:<8} {:>5} {:>9} {:>10} {:>11} {:>17} {:>7}",
        "method", "mesh", "ε̄", "time (s)", "error V", "status", "Pareto"
    );
    for p in &t.points {
        println!(
            "  {:<8} {:>5} {:>9.0e} {:>10.4} {:>11.3e} {:>17} {:>7}",
            p.method,
            p.mesh,
            p.eps,
            p.time_s,
            p.error,
            p.status,
            if p.pareto { "*" } else { "" }
        );
    }
    println!(
        "  written: tradeoff.csv, tradeoff.svg in {}",
        args.out.display()
    );
    Ok(())
}

fn stability(args: StabilityArgs) -> Result<(), Failure> {
    let scenes = if args.scenes.is_empty() {
        vec![
            "example:paper-winkler".to_string(),
            "example:paper-halfspace".to_string(),
        ]
    } else {
        args.scenes.clone()
    };
    let mut bases = Vec::new();
    for s in &scenes {
        bases.push(load_problem(s)?);
    }
    output::prepare_dir(&args.out)?;
    let plan = liftoff::study::stability_plan(&bases);
    let pb = progress_bar(plan.len() as u64);
    let mut rows = Vec::new();
    for case in &plan {
        pb.set_message(format!(
            "{} {} = {:.2e} ({})",
            case.base.model.groups.foundation.name(),
            case.param.name(),
            case.value,
            case.method.name()
        ));
        rows.push(liftoff::study::stability_run(case));
        pb.inc(1);
    }
    pb.finish_and_clear();
    output::studies::write_stability(&args.out, &rows, "liftoff stability")?;
    println!("liftoff stability — {} runs", rows.len());
    let mut failures = 0;
    for r in &rows {
        if r.outcome != "converged" {
            failures += 1;
            println!(
                "  {:<10} {:<8} {:<7} {:>9.2e}: {} — {}",
                r.foundation, r.sweep, r.method, r.value, r.outcome, r.detail
            );
        }
    }
    println!("  {} of {} runs did not converge (listed above); written: stability.csv, stability-penalty.svg, stability-qp.svg in {}", failures, rows.len(), args.out.display());
    Ok(())
}

fn paper(args: PaperArgs) -> Result<(), Failure> {
    let load2: liftoff::paper::LoadCondition2 =
        args.load2.parse().map_err(|e: Error| Failure::from(e))?;
    let options = liftoff::paper::PaperOptions {
        method: args.method,
        load2,
        refine: args.refine,
    };
    let report = liftoff::paper::run(&options, &args.out, &mut |line: &str| eprintln!("{line}"))?;
    print!("{}", liftoff::paper::write_markdown(&report));
    println!(
        "\nwritten: {} files in {}",
        report.files.len(),
        args.out.display()
    );
    Ok(())
}

fn with_scene(path: &str, e: Error) -> Failure {
    let mut f = Failure::from(e);
    f.message = format!("{path}: {}", f.message);
    f
}

const SIGN_CONVENTION: &str = "Sign convention: deflection w and loads are positive downward (into the soil), pressure is positive in compression, and a positive gap means the plate has lifted off the soil.";

fn print_table(problem: &Problem, s: &output::Summary) {
    let g = &s.dimensionless;
    println!("liftoff — {}", s.title);
    println!(
        "  foundation : {} (Γ = {:.4e}, Δ = {:.4e}, μ = {:.4}, ν = {})",
        s.foundation, g.gamma, g.delta, g.mu, g.nu
    );
    println!(
        "  model      : {} model, {} × {} of {} × {} elements, {} nodes, {} dofs",
        s.symmetry,
        s.model_elements[0],
        s.model_elements[1],
        s.elements[0],
        s.elements[1],
        s.nodes,
        s.dofs
    );
    for n in &s.notes {
        println!("  note       : {n}");
    }
    let method = if s.contact == "bonded" {
        "bonded, direct solve".to_string()
    } else {
        format!("unbonded, {} ({} constraints)", s.method, s.constraint)
    };
    println!("  contact    : {method}");
    println!("  status     : {} after {} step(s)", s.status, s.iterations);
    if !s.solver_info.is_empty() {
        let get = |k: &str| s.solver_info.get(k).copied().unwrap_or(f64::NAN);
        println!(
            "  clarabel   : primal residual {:.1e}, dual residual {:.1e}, duality gap {:.1e}",
            get("primal_residual"),
            get("dual_residual"),
            get("duality_gap")
        );
    }
    if !s.history.is_empty() {
        println!("  penalty iterations (constraint points in the penalised, lifted set):");
        for it in &s.history {
            println!(
                "    step {:>3}: {:>6} penalised, {:>6} entered, {:>6} left, min σ {:.3e}",
                it.step,
                it.penalised,
                it.entered,
                it.left,
                it.min_pressure * g.mu
            );
        }
    }
    println!(
        "  time       : assemble {:.3} s, solve {:.3} s, total {:.3} s",
        s.time_s.assemble, s.time_s.solve, s.time_s.total
    );
    match problem.model.physical {
        Some(_) => {
            println!("  w_max      : {:.3} mm (downward)", s.w_max * 1e3);
            println!("  pressure   : max {:.1} kPa", s.pressure_max / 1e3);
            println!(
                "  moments    : mx {:.1} … {:.1} kN·m/m, my {:.1} … {:.1} kN·m/m (positive: tension on the soil side)",
                s.moments.mx[0] / 1e3,
                s.moments.mx[1] / 1e3,
                s.moments.my[0] / 1e3,
                s.moments.my[1] / 1e3
            );
            let r = &s.resultant;
            println!(
                "  resultant  : load {:.2} kN, reaction {:.2} kN (relative error {:.1e})",
                r.load / 1e3,
                r.reaction / 1e3,
                r.relative_error
            );
        }
        None => {
            let r = &s.resultant;
            println!(
                "  resultant  : load {:.6} P, reaction {:.6} P (relative error {:.1e})",
                r.load, r.reaction, r.relative_error
            );
        }
    }
    println!(
        "  V          : max {:.5e}, centre {:.5e}, corner {:.5e}  (V = D w / (P L²))",
        s.V_max, s.V_center, s.V_corner
    );
    println!(
        "  contact    : {:.1} % of the plate, radius {:.3} L, extent x {:.3}, y {:.3}, diagonal {:.3}",
        100.0 * s.contact_fraction,
        s.contact_radius,
        s.contact_extent.x,
        s.contact_extent.y,
        s.contact_extent.diagonal
    );
    let c = &s.complementarity;
    println!(
        "  residuals  : min σ {:.2e}, min gap {:.2e}, max |σ·gap| {:.2e}",
        c.min_pressure, c.min_gap, c.max_product
    );
}
