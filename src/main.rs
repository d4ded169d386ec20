//! `liftoff` command line: parse arguments, call the library, print. One function per
//! subcommand; the library checks every option and formats every table, and this file adds
//! what only a command line knows: exit codes, flag names and `hint:` lines that name flags.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use liftoff::method::{Contact, MethodKind, QpForm, QpSolver, Route};
use liftoff::model::{ConstraintPoints, SymmetryMode};
use liftoff::output::{self, tables};
use liftoff::scene::{PenaltySpec, SceneFile};
use liftoff::study::{self, ConstraintVariants, EpsSweepOptions, TradeoffOptions};
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
#[derive(clap::Args)]
struct Overrides {
    /// Dimensionless penalty ε̄: auto, or a fixed value such as 1e-5 (overrides [solver] penalty).
    #[arg(long, value_parser = parse_penalty)]
    penalty: Option<PenaltySpec>,
    /// Constraint points (overrides [solver] constraint).
    #[arg(long, value_enum)]
    constraint: Option<ConstraintPoints>,
    /// Elements over the whole plate, NX,NY (overrides [mesh] elements).
    #[arg(long, value_parser = parse_mesh)]
    mesh: Option<[i64; 2]>,
    /// How the QP is posed: auto (primal on Winkler, schur on the half-space), schur, lifted or
    /// primal (overrides [solver] qp_form).
    #[arg(long, value_enum)]
    qp_form: Option<QpForm>,
    /// Which solver runs the QP: auto (clarabel where its form fits and is robust, the
    /// matrix-free active-set method elsewhere), clarabel, or active-set (overrides [solver]
    /// qp_solver).
    #[arg(long, value_enum)]
    qp_solver: Option<QpSolver>,
    /// How the half-space is held and solved: auto (dense up to 1500 pressure nodes, iterative
    /// beyond), dense (dense T, direct factorisations) or iterative (T by FFT, conjugate
    /// gradients) (overrides [solver] route).
    #[arg(long, value_enum)]
    solver: Option<Route>,
}

impl Overrides {
    /// The library's overrides (shared with the Python package) with these flags set.
    fn library(&self) -> liftoff::scene::Overrides {
        liftoff::scene::Overrides {
            penalty: self.penalty.clone(),
            constraint: self.constraint,
            mesh: self.mesh,
            qp_form: self.qp_form,
            qp_solver: self.qp_solver,
            solver: self.solver,
            ..Default::default()
        }
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
    #[command(flatten)]
    overrides: Overrides,
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
    #[command(flatten)]
    overrides: Overrides,
    /// Directory for compare.json (default: the current directory).
    #[arg(long, default_value = ".")]
    out: PathBuf,
}

/// The flags are the fields of [`EpsSweepOptions`], with its defaults.
#[derive(clap::Args)]
struct EpsSweepArgs {
    /// Scene file (TOML), or `example:NAME`.
    scene: String,
    /// Largest ε̄.
    #[arg(long, default_value_t = EpsSweepOptions::default().from)]
    from: f64,
    /// Smallest ε̄.
    #[arg(long, default_value_t = EpsSweepOptions::default().to)]
    to: f64,
    /// Number of ε̄ values (log-spaced).
    #[arg(long, default_value_t = EpsSweepOptions::default().points)]
    points: usize,
    /// Constraint variants: nodal, gauss or both.
    #[arg(long, value_enum, hide_possible_values = true,
          default_value_t = EpsSweepOptions::default().constraints)]
    constraints: ConstraintVariants,
    /// Directory for eps_sweep.csv and eps_sweep.svg.
    #[arg(long, default_value = ".")]
    out: PathBuf,
}

/// The flags are the fields of [`TradeoffOptions`]; the defaults are its defaults, spelled as
/// `--help` shows them (a test checks they agree).
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

/// What the binary reports on failure: `error: {message}` on stderr and the exit code.
struct Failure {
    message: String,
    code: u8,
}

impl Failure {
    fn new(code: u8, message: impl Into<String>) -> Self {
        let message = message.into();
        Failure { message, code }
    }

    /// A library error about a scene: the message starts with where the scene came from.
    fn in_scene(spec: &str, e: Error) -> Self {
        let mut f = Failure::from(e);
        f.message = format!("{spec}: {}", f.message);
        f
    }

    /// A library error from an options struct whose fields are this subcommand's flags
    /// (`points` → `--points`): the message names the flag.
    fn option(e: Error) -> Self {
        match e {
            Error::Invalid { field, message } => Failure::new(
                exit::BAD_INPUT,
                format!("--{} {message}", field.replace('_', "-")),
            ),
            e => Failure::from(e),
        }
    }
}

impl From<Error> for Failure {
    fn from(e: Error) -> Self {
        let (code, hint) = match &e {
            Error::Parse(_)
            | Error::Invalid { .. }
            | Error::TooLarge { .. }
            | Error::Unsupported(_) => (exit::BAD_INPUT, ""),
            Error::Infeasible(_) => (
                exit::INFEASIBLE,
                "\nhint: bonded contact (--contact bonded) lets the foundation pull",
            ),
            Error::Numerical { stage, .. } if stage.contains("QP") => (
                exit::SOLVER,
                "\nhint: --method penalty, or the other --qp-solver where it applies (clarabel needs the dense route or Winkler soil)",
            ),
            Error::Numerical { .. } => (exit::SOLVER, "\nhint: --method qp, or a coarser --mesh"),
            Error::Io { .. } => (exit::IO, ""),
        };
        Failure::new(code, format!("{e}{hint}"))
    }
}

fn no_example(name: &str) -> Failure {
    Failure::new(
        exit::BAD_INPUT,
        format!("no bundled example `{name}`; run `liftoff example` for the list"),
    )
}

fn example(name: Option<&str>) -> Result<(), Failure> {
    let Some(n) = name else {
        println!("Bundled scenes (print one with `liftoff example NAME`, solve it with `liftoff solve example:NAME`):");
        for (n, d, _) in liftoff::examples::SCENES {
            println!("  {n:<22} {d}");
        }
        return Ok(());
    };
    print!(
        "{}",
        liftoff::examples::scene(n).ok_or_else(|| no_example(n))?
    );
    Ok(())
}

/// A scene file, or `example:NAME` for a bundled one, parsed but not yet validated.
fn read_scene(spec: &str) -> Result<SceneFile, Failure> {
    let text = match spec.strip_prefix("example:") {
        Some(name) => liftoff::examples::scene(name)
            .ok_or_else(|| no_example(name))?
            .to_string(),
        None => std::fs::read_to_string(spec)
            .map_err(|e| Failure::new(exit::IO, format!("cannot read scene file {spec}: {e}")))?,
    };
    SceneFile::parse(&text).map_err(|e| Failure::new(exit::BAD_INPUT, format!("{spec}: {e}")))
}

/// Read a scene, apply the command line's overrides, validate.
fn load_problem(spec: &str, edit: impl FnOnce(&mut SceneFile)) -> Result<Problem, Failure> {
    let mut file = read_scene(spec)?;
    edit(&mut file);
    file.validate().map_err(|e| Failure::in_scene(spec, e))
}

/// The studies compare methods on one load set: say which one a scene with combinations gives.
fn note_first_combination(problem: &Problem) {
    if let Some(first) = problem.combinations.first() {
        eprintln!(
            "note: the scene has {} load combinations; this study uses the first, `{}` (`liftoff solve` runs them all)",
            problem.combinations.len(),
            first.name
        );
    }
}

/// Run a library study under a progress bar of `len` steps; each progress line is one step.
fn with_progress<T>(len: usize, run: impl FnOnce(&mut dyn FnMut(&str)) -> T) -> T {
    let pb = indicatif::ProgressBar::new(len as u64);
    if let Ok(style) =
        indicatif::ProgressStyle::with_template("{bar:30} {pos}/{len} {elapsed_precise} {msg}")
    {
        pb.set_style(style);
    }
    let result = run(&mut |m: &str| {
        pb.set_message(m.to_string());
        pb.inc(1);
    });
    pb.finish_and_clear();
    result
}

fn solve(args: SolveArgs) -> Result<(), Failure> {
    let overrides = liftoff::scene::Overrides {
        contact: args.contact,
        method: args.method,
        symmetry: args.symmetry,
        ..args.overrides.library()
    };
    let problem = load_problem(&args.scene, |file| overrides.apply(file))?;
    if let Some(dir) = &args.out {
        output::prepare_dir(dir)?;
    }
    if !problem.combinations.is_empty() {
        return solve_combinations(&args, &problem);
    }
    let analysis = liftoff::analyse(&problem)?;
    let summary = &analysis.summary;
    // A result that did not converge is not a solution: no files are written for it.
    let written = match (&args.out, summary.converged) {
        (Some(dir), true) => {
            output::write_all(dir, &problem.model, &analysis.report, summary)?.len()
        }
        _ => 0,
    };
    if args.json {
        println!("{}", summary.to_json()?);
    } else {
        let files = args.out.as_deref().map(|dir| (written, dir));
        print!("{}", tables::solve_table(summary, files));
    }
    if !summary.converged {
        let hint = match analysis.solution.status {
            liftoff::Status::PenaltyTooWeak {
                suggested_penalty, ..
            } => format!("\nhint: rerun with --penalty {suggested_penalty:.0e} or --method qp"),
            _ if summary.method == "qp" => {
                "\nhint: --method penalty solves the same operators by the paper's iteration, or try the other --qp-solver where it applies".into()
            }
            _ => "\nhint: --method qp solves the same operators as a convex QP".into(),
        };
        return Err(Failure::new(exit::SOLVER, format!(
            "the {} method did not converge ({}); the numbers above are not a solution and no files were written{hint}",
            summary.method, summary.status
        )));
    }
    Ok(())
}

/// Every `[[combination]]` of a scene on one assembly, a line each, and the envelope.
fn solve_combinations(args: &SolveArgs, problem: &Problem) -> Result<(), Failure> {
    let n = problem.combinations.len();
    let pb = indicatif::ProgressBar::new(n as u64);
    if let Ok(style) =
        indicatif::ProgressStyle::with_template("{bar:30} {pos}/{len} {elapsed_precise} {msg}")
    {
        pb.set_style(style);
    }
    let run = liftoff::combination::analyse(problem, &|name: &str| {
        pb.set_message(name.to_string());
        pb.inc(1);
    });
    pb.finish_and_clear();
    let run = run?;
    let all = run.all_converged();
    let env = if all {
        liftoff::combination::envelope(&run.runs)
    } else {
        None
    };
    // Only a complete set is written: an envelope missing a combination is not an envelope.
    let written = match (&args.out, &env) {
        (Some(dir), Some(env)) => output::combinations::write_combinations(dir, &run, env)?.len(),
        _ => 0,
    };
    let title = problem
        .combinations
        .first()
        .map_or(problem.model.title.as_str(), |c| c.scene_title());
    if args.json {
        let json = output::combinations::combinations_json(&run, env.as_ref())
            .map_err(|e| Failure::new(exit::IO, format!("cannot serialise the envelope: {e}")))?;
        println!("{json}");
    } else {
        let files = args.out.as_deref().map(|dir| (written, dir));
        print!(
            "{}",
            output::combinations::combinations_table(title, &run, env.as_ref(), files)
        );
        println!("\n{}", tables::SIGN_CONVENTION);
    }
    if !all {
        let infeasible = run
            .runs
            .iter()
            .any(|r| matches!(&r.outcome, Err(e) if e.kind() == "infeasible"));
        let code = if infeasible {
            exit::INFEASIBLE
        } else {
            exit::SOLVER
        };
        return Err(Failure::new(
            code,
            "not every combination has a solution (see the table); no files were written",
        ));
    }
    Ok(())
}

fn compare(args: CompareArgs) -> Result<(), Failure> {
    let problem = load_problem(&args.scene, |file| args.overrides.library().apply(file))?;
    note_first_combination(&problem);
    output::prepare_dir(&args.out)?;
    let c = liftoff::compare::compare(&problem)?;
    let json = serde_json::to_string_pretty(&c)
        .map_err(|e| Failure::new(exit::IO, format!("cannot serialise compare.json: {e}")))?;
    let mut st = output::Staged::new(&args.out)?;
    st.write_text("compare.json", &json)?;
    st.commit()?;
    print!(
        "{}",
        tables::compare_table(&c, &args.out.join("compare.json"))
    );
    if !c.penalty.converged || !c.qp.converged {
        let message = "a method did not converge; see the status row";
        return Err(Failure::new(exit::SOLVER, message));
    }
    Ok(())
}

fn eps_sweep(args: EpsSweepArgs) -> Result<(), Failure> {
    let options = EpsSweepOptions {
        from: args.from,
        to: args.to,
        points: args.points,
        constraints: args.constraints,
    };
    options.validate().map_err(Failure::option)?;
    let problem = load_problem(&args.scene, |_| {})?;
    note_first_combination(&problem);
    output::prepare_dir(&args.out)?;
    let sweep = with_progress(options.progress_steps(), |p| options.run(&problem, p))?;
    let title = &problem.model.title;
    let chart_title = format!("{title} — penalty against QP");
    output::studies::write_sweep(&args.out, &sweep, &chart_title)?;
    print!("{}", tables::eps_sweep_table(title, &sweep, &args.out));
    Ok(())
}

fn tradeoff(args: TradeoffArgs) -> Result<(), Failure> {
    let options = TradeoffOptions {
        meshes: args.meshes,
        penalties: args.penalties,
    };
    options.validate().map_err(Failure::option)?;
    let problem = load_problem(&args.scene, |_| {})?;
    note_first_combination(&problem);
    output::prepare_dir(&args.out)?;
    let t = with_progress(options.progress_steps(), |p| options.run(&problem, p))?;
    let title = &problem.model.title;
    let chart_title = format!("{title} — speed against accuracy");
    output::studies::write_tradeoff(&args.out, &t, &chart_title)?;
    print!("{}", tables::tradeoff_table(title, &t, &args.out));
    Ok(())
}

fn stability(args: StabilityArgs) -> Result<(), Failure> {
    let scenes = if args.scenes.is_empty() {
        vec![
            "example:paper-winkler".into(),
            "example:paper-halfspace".into(),
        ]
    } else {
        args.scenes
    };
    let bases = scenes
        .iter()
        .map(|s| load_problem(s, |_| {}))
        .collect::<Result<Vec<_>, _>>()?;
    output::prepare_dir(&args.out)?;
    let plan = study::stability_plan(&bases);
    let rows = with_progress(plan.len(), |p| study::stability_sweep(&plan, p));
    output::studies::write_stability(&args.out, &rows, "liftoff stability")?;
    print!("{}", tables::stability_table(&rows, &args.out));
    Ok(())
}

fn paper(args: PaperArgs) -> Result<(), Failure> {
    let options = liftoff::paper::PaperOptions {
        method: args.method,
        load2: args.load2.parse()?,
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The defaults `tradeoff --help` shows are the library's.
    #[test]
    fn tradeoff_flag_defaults_are_the_library_defaults() {
        let cli = Cli::try_parse_from(["liftoff", "tradeoff", "example:paper-winkler"]);
        let Ok(Cli {
            command: Command::Tradeoff(args),
        }) = cli
        else {
            panic!("`liftoff tradeoff SCENE` parses as tradeoff");
        };
        let d = TradeoffOptions::default();
        assert_eq!(args.meshes, d.meshes, "--meshes default");
        assert_eq!(args.penalties, d.penalties, "--penalties default");
    }

    /// An option error names the flag, in the wording the library gives.
    #[test]
    fn option_errors_name_the_flag() {
        let e = EpsSweepOptions {
            points: 1,
            ..Default::default()
        }
        .validate();
        let f = Failure::option(e.err().unwrap_or(Error::Parse("no error".into())));
        assert_eq!(f.message, "--points must lie in 2..=200, got 1");
        assert_eq!(f.code, exit::BAD_INPUT);
    }
}
