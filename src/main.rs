//! `liftoff` command line: parse arguments, call the library, print. One function per
//! subcommand; the library checks every option and formats every table, and this file adds
//! what only a command line knows: exit codes, flag names and `hint:` lines that name flags.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::builder::{PossibleValuesParser, TypedValueParser};
use clap::{Parser, Subcommand};
use liftoff::choice::Choice;
use liftoff::method::{Contact, MethodKind, QpForm, QpSolver, Route};
use liftoff::model::{ConstraintPoints, SymmetryMode};
use liftoff::output::{self, tables};
use liftoff::scene::PenaltySpec;
use liftoff::study::{self, ConstraintVariants, EpsSweepOptions, TradeoffOptions};
use liftoff::{Error, ErrorKind, Method, Monitor, Outcome, Problem, Source};

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
    #[arg(long, value_parser = choice::<ConstraintPoints>())]
    constraint: Option<ConstraintPoints>,
    /// Elements over the whole plate, NX,NY (overrides [mesh] elements).
    #[arg(long, value_parser = parse_mesh)]
    mesh: Option<[i64; 2]>,
    /// How the QP is posed: auto (primal on Winkler, schur on the half-space), schur, lifted or
    /// primal (overrides [solver] qp_form).
    #[arg(long, value_parser = choice::<QpForm>())]
    qp_form: Option<QpForm>,
    /// Which solver runs the QP: auto (clarabel where its form fits and is robust, the
    /// matrix-free active-set method elsewhere), clarabel, or active-set (overrides [solver]
    /// qp_solver).
    #[arg(long, value_parser = choice::<QpSolver>())]
    qp_solver: Option<QpSolver>,
    /// How the half-space is held and solved: auto (dense up to 1500 pressure nodes, iterative
    /// beyond), dense (dense T, direct factorisations) or iterative (T by FFT, conjugate
    /// gradients) (overrides [solver] route).
    #[arg(long, value_parser = choice::<Route>())]
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
    #[arg(long, value_parser = choice::<Contact>())]
    contact: Option<Contact>,
    /// Method for unbonded contact (overrides [solver] method).
    #[arg(long, value_parser = choice::<MethodKind>())]
    method: Option<MethodKind>,
    #[command(flatten)]
    overrides: Overrides,
    /// Symmetry reduction (overrides [mesh] symmetry).
    #[arg(long, value_parser = choice::<SymmetryMode>())]
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
    #[arg(long, value_parser = choice::<ConstraintVariants>(), hide_possible_values = true,
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
    #[arg(long, value_parser = choice::<MethodKind>(), default_value = "penalty")]
    method: MethodKind,
    /// Reading of the paper's load condition 2: patch (γ from Fig. 6's captions), patch=G, or edge-band.
    #[arg(long, default_value = "patch")]
    load2: String,
    /// Also solve on meshes 2, 4, … up to this many times finer than the paper's.
    #[arg(long, default_value_t = 1)]
    refine: usize,
}

/// A flag whose values are a library [`Choice`]'s names (one list, shared with the scene files
/// and the Python package).
fn choice<T: Choice + Clone + Send + Sync>() -> impl TypedValueParser<Value = T> {
    PossibleValuesParser::new(T::names())
        .try_map(|name: String| T::from_name(&name).ok_or_else(|| format!("`{name}` is no choice")))
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
        let (code, hint) = match e.kind() {
            ErrorKind::Invalid | ErrorKind::TooLarge => (exit::BAD_INPUT, ""),
            ErrorKind::Infeasible => (
                exit::INFEASIBLE,
                "\nhint: bonded contact (--contact bonded) lets the foundation pull",
            ),
            ErrorKind::Numerical | ErrorKind::Cancelled => (exit::SOLVER, ""),
            ErrorKind::Io => (exit::IO, ""),
        };
        Failure::new(code, format!("{e}{hint}"))
    }
}

impl Failure {
    /// A library error from solving with `method`: a numerical failure hints at the other
    /// method (the same operators, solved another way).
    fn solving(e: Error, method: &Method) -> Self {
        let numerical = e.kind() == ErrorKind::Numerical;
        let mut f = Failure::from(e);
        if numerical {
            f.message.push_str(match method {
                Method::Qp(_) => "\nhint: --method penalty, or the other --qp-solver where it applies (clarabel needs the dense route or Winkler soil)",
                _ => "\nhint: --method qp, or a coarser --mesh",
            });
        }
        f
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

/// Read a scene (a path, or `example:NAME`), apply the command line's overrides, validate.
fn load_problem(spec: &str, overrides: &liftoff::scene::Overrides) -> Result<Problem, Failure> {
    liftoff::load(&Source::from_arg(spec), overrides).map_err(|e| match &e {
        Error::Invalid { field, .. } if field == "scene" => Failure::from(e),
        Error::Io { .. } => Failure::from(e),
        _ => Failure::in_scene(spec, e),
    })
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

fn solve(args: SolveArgs) -> Result<(), Failure> {
    let overrides = liftoff::scene::Overrides {
        contact: args.contact,
        method: args.method,
        symmetry: args.symmetry,
        ..args.overrides.library()
    };
    let problem = load_problem(&args.scene, &overrides)?;
    if let Some(dir) = &args.out {
        output::prepare_dir(dir)?;
    }
    let outcome = with_progress(false, |m| liftoff::run(&problem, m))
        .map_err(|e| Failure::solving(e, &problem.method))?;
    // A result that did not converge is not a solution (and an envelope missing a combination
    // is not an envelope): no files are written for it.
    let written = match (&args.out, &outcome) {
        (Some(dir), Outcome::Single(a)) if a.summary.converged => {
            output::write_all(dir, &problem.model, &a.report, &a.summary)?.len()
        }
        (Some(dir), Outcome::Combinations(c)) => match &c.envelope {
            Some(env) => output::combinations::write_combinations(dir, c, env)?.len(),
            None => 0,
        },
        _ => 0,
    };
    let files = args.out.as_deref().map(|dir| (written, dir));
    if args.json {
        println!("{}", outcome.to_json()?);
    } else {
        match &outcome {
            Outcome::Single(a) => print!("{}", tables::solve_table(&a.summary, files)),
            Outcome::Combinations(c) => {
                let title = problem
                    .combinations
                    .first()
                    .map_or(problem.model.title.as_str(), |c| c.scene_title());
                print!(
                    "{}",
                    output::combinations::combinations_table(title, c, files)
                );
                println!("\n{}", tables::SIGN_CONVENTION);
            }
        }
    }
    match &outcome {
        Outcome::Single(a) if !a.summary.converged => {
            let hint = match (&a.solution.status, &problem.method) {
                (liftoff::Status::PenaltyTooWeak { suggested_penalty, .. }, _) => format!(
                    "\nhint: rerun with --penalty {suggested_penalty:.0e} or --method qp"
                ),
                (_, Method::Qp(_)) => "\nhint: --method penalty solves the same operators by the paper's iteration, or try the other --qp-solver where it applies".into(),
                _ => "\nhint: --method qp solves the same operators as a convex QP".into(),
            };
            Err(Failure::new(exit::SOLVER, format!(
                "the {} method did not converge ({}); the numbers above are not a solution and no files were written{hint}",
                a.summary.method, a.summary.status
            )))
        }
        Outcome::Combinations(c) if !c.all_converged() => {
            let infeasible = c
                .runs
                .iter()
                .any(|r| matches!(&r.outcome, Err(e) if e.kind() == ErrorKind::Infeasible));
            let code = if infeasible {
                exit::INFEASIBLE
            } else {
                exit::SOLVER
            };
            Err(Failure::new(
                code,
                format!(
                    "not every combination has a solution ({} missing; see the table); no envelope and no files were written",
                    c.missing().join(", ")
                ),
            ))
        }
        _ => Ok(()),
    }
}

/// Run a library call under a progress bar drawn from its [`liftoff::Progress`] events (on a
/// terminal only): the cases done of a run over several (combinations, a study's solves), the
/// steps of one long solve. With `log`, every case's label is also printed as a line.
fn with_progress<T>(log: bool, run: impl FnOnce(&Monitor<'_>) -> T) -> T {
    let pb = indicatif::ProgressBar::new_spinner();
    let bar =
        indicatif::ProgressStyle::with_template("{bar:30} {pos}/{len} {elapsed_precise} {msg}")
            .ok();
    if let Ok(style) = indicatif::ProgressStyle::with_template("{spinner} {elapsed_precise} {msg}")
    {
        pb.set_style(style);
    }
    let report = |p: liftoff::Progress<'_>| match p {
        liftoff::Progress::Case { done, total, label } => {
            if pb.length() != Some(total as u64) {
                if let Some(style) = bar.clone() {
                    pb.set_style(style);
                }
                pb.set_length(total as u64);
            }
            pb.set_position(done as u64);
            pb.set_message(label.to_string());
            if log {
                pb.println(label);
            }
        }
        liftoff::Progress::Step {
            method,
            step,
            changes,
        } => {
            pb.set_message(format!("{method} {step} ({changes} changed)"));
            pb.tick();
        }
    };
    let result = run(&Monitor::NONE.with_progress(&report));
    pb.finish_and_clear();
    result
}

fn compare(args: CompareArgs) -> Result<(), Failure> {
    let problem = load_problem(&args.scene, &args.overrides.library())?;
    note_first_combination(&problem);
    output::prepare_dir(&args.out)?;
    let c = with_progress(false, |m| liftoff::compare::compare_with(&problem, m))?;
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
    let problem = load_problem(&args.scene, &Default::default())?;
    note_first_combination(&problem);
    output::prepare_dir(&args.out)?;
    let sweep = with_progress(false, |m| options.run(&problem, m))?;
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
    let problem = load_problem(&args.scene, &Default::default())?;
    note_first_combination(&problem);
    output::prepare_dir(&args.out)?;
    let t = with_progress(false, |m| options.run(&problem, m))?;
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
        .map(|s| load_problem(s, &Default::default()))
        .collect::<Result<Vec<_>, _>>()?;
    output::prepare_dir(&args.out)?;
    let plan = study::stability_plan(&bases);
    let rows = with_progress(false, |m| study::stability_sweep(&plan, m))?;
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
    let report = with_progress(true, |m| liftoff::paper::run(&options, &args.out, m))?;
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

    /// The flags of `solve` that override the scene are the library's option list, no more
    /// and no fewer; `compare`'s are a part of it (it runs both methods, so it has no
    /// --method, --contact or --symmetry). Adding an option to the library without its flag,
    /// or a flag without the library's option, fails here.
    #[test]
    fn solve_flags_are_the_library_options() {
        use clap::CommandFactory;
        let cli = Cli::command();
        let flags = |sub: &str| -> Vec<String> {
            let Some(cmd) = cli.find_subcommand(sub) else {
                panic!("subcommand {sub}");
            };
            let mut v: Vec<String> = cmd
                .get_arguments()
                .filter_map(|a| a.get_long())
                .filter(|l| !matches!(*l, "out" | "json" | "help"))
                .map(|l| l.replace('-', "_"))
                .collect();
            v.sort();
            v
        };
        let mut options: Vec<String> = liftoff::scene::OPTIONS
            .iter()
            .map(|o| o.0.to_string())
            .collect();
        options.sort();
        assert_eq!(
            flags("solve"),
            options,
            "solve's flags against scene::OPTIONS"
        );
        for f in flags("compare") {
            assert!(
                options.contains(&f),
                "compare's --{f} is not a library option"
            );
        }
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
