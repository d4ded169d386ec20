//! `liftoff` command line: parse arguments, call the library, print. One function per
//! subcommand; the library checks every option and formats every table, and this file adds
//! what only a command line knows: exit codes, flag names and `hint:` lines that name flags.

mod args;
mod failure;
mod interrupt;
mod progress;

use std::process::ExitCode;

use clap::Parser;
use liftoff::output::{self, study_tables, tables};
use liftoff::study::{self, EpsSweepOptions, TradeoffOptions};
use liftoff::{Error, ErrorKind, Outcome, Problem, Source};

use args::{
    BackcalcArgs, Cli, Command, CompareArgs, CriticalArgs, DamageArgs, DesignArgs, EpsSweepArgs,
    PaperArgs, ReportArgs, SolveArgs, StabilityArgs, TradeoffArgs,
};
use failure::{exit, Failure};
use progress::with_progress;

fn main() -> ExitCode {
    faer::set_global_parallelism(faer::Par::Seq);
    let cli = Cli::parse();
    interrupt::install();
    let name = cli.command.name();
    let result = match cli.command {
        Command::Solve(args) => solve(args),
        Command::Compare(args) => compare(args),
        Command::EpsSweep(args) => eps_sweep(args),
        Command::Tradeoff(args) => tradeoff(args),
        Command::Stability(args) => stability(args),
        Command::Critical(args) => critical(args),
        Command::Damage(args) => damage(args),
        Command::Design(args) => design(args),
        Command::Backcalc(args) => backcalc(args),
        Command::Paper(args) => paper(args),
        Command::Report(args) => report(args),
        Command::Example { name } => example(name.as_deref()),
    };
    // A failure after Ctrl-C is the interruption's doing, whatever the error says.
    let result = match result {
        Err(f) if interrupt::requested() && f.code != exit::INTERRUPTED => {
            Err(Failure::interrupted("by a signal"))
        }
        r => r,
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure { message, code }) if code == exit::INTERRUPTED => {
            eprintln!("interrupted: `liftoff {name}` {message}");
            ExitCode::from(code)
        }
        Err(Failure { message, code }) => {
            eprintln!("error: {message}");
            ExitCode::from(code)
        }
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
/// Values that suggest a unit slip are printed as warnings on stderr; the scene still solves.
fn load_problem(spec: &str, overrides: &liftoff::scene::Overrides) -> Result<Problem, Failure> {
    let problem = liftoff::load(&Source::from_arg(spec), overrides).map_err(|e| match &e {
        Error::Invalid { field, .. } if field == "scene" => Failure::from(e),
        Error::Io { .. } => Failure::from(e),
        _ => Failure::in_scene(spec, e),
    })?;
    for w in &problem.warnings {
        eprintln!("warning: {spec}: {w}");
    }
    Ok(problem)
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
    interrupt::check()?;
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
    let written = written + with_report(args.report, args.out.as_deref(), written)?;
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
            Err(Failure::not_converged(a, &problem.method))
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

fn compare(args: CompareArgs) -> Result<(), Failure> {
    let problem = load_problem(&args.scene, &args.overrides.library())?;
    note_first_combination(&problem);
    output::prepare_dir(&args.out)?;
    let c = with_progress(false, |m| liftoff::compare::compare_with(&problem, m))?;
    interrupt::check()?;
    let json = serde_json::to_string_pretty(&c)
        .map_err(|e| Failure::new(exit::IO, format!("cannot serialise compare.json: {e}")))?;
    let mut st = output::Staged::new(&args.out)?;
    st.write_text("compare.json", &json)?;
    st.commit()?;
    print!(
        "{}",
        study_tables::compare_table(&c, &args.out.join("compare.json"))
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
    interrupt::check()?;
    let title = &problem.model.title;
    let chart_title = format!("{title} — penalty against QP");
    output::studies::write_sweep(&args.out, &sweep, &chart_title)?;
    print!(
        "{}",
        study_tables::eps_sweep_table(title, &sweep, &args.out)
    );
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
    interrupt::check()?;
    let title = &problem.model.title;
    let chart_title = format!("{title} — speed against accuracy");
    output::studies::write_tradeoff(&args.out, &t, &chart_title)?;
    print!("{}", study_tables::tradeoff_table(title, &t, &args.out));
    Ok(())
}

fn stability(args: StabilityArgs) -> Result<(), Failure> {
    let scenes = if args.scenes.is_empty() {
        // Every soil (study::DEFAULT_BASES).
        study::DEFAULT_BASES
            .iter()
            .map(|n| format!("example:{n}"))
            .collect()
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
    interrupt::check()?;
    output::studies::write_stability(&args.out, &rows, "liftoff stability")?;
    print!("{}", study_tables::stability_table(&rows, &args.out));
    Ok(())
}

fn critical(args: CriticalArgs) -> Result<(), Failure> {
    let overrides = liftoff::scene::Overrides {
        contact: args.contact,
        method: args.method,
        ..args.overrides.library()
    };
    let options = study::CriticalOptions {
        load: args.load,
        grid: args.grid,
        grid_per_panel: args.grid_per_panel,
        along: args.along,
        headings: args.headings,
        combination: args.combination,
        warm: !args.cold,
        indices: None,
        mirror: !args.no_mirror,
        ends: args.ends,
    };
    options.validate().map_err(Failure::option)?;
    let problem = load_problem(&args.scene, &overrides)?;
    if let Some(dir) = &args.out {
        output::prepare_dir(dir)?;
    }
    let c = with_progress(false, |m| options.run(&problem, m))
        .map_err(|e| Failure::in_scene(&args.scene, e))?;
    interrupt::check()?;
    let title = match &c.combination {
        Some(name) => liftoff::scene::scene_title(&problem.model.title, name),
        None => &problem.model.title,
    };
    let written = match &args.out {
        Some(dir) => output::critical::write_critical(dir, &c, title)?.len(),
        None => 0,
    };
    let written = written + with_report(args.report, args.out.as_deref(), written)?;
    if args.json {
        let json = serde_json::to_string_pretty(&c.reported())
            .map_err(|e| Failure::new(exit::IO, format!("cannot serialise critical.json: {e}")))?;
        println!("{json}");
    } else {
        let files = args.out.as_deref().map(|dir| (written, dir));
        print!("{}", output::critical::critical_table(title, &c, files));
    }
    Ok(())
}

fn damage(args: DamageArgs) -> Result<(), Failure> {
    let overrides = liftoff::scene::Overrides {
        method: args.method,
        ..args.overrides.library()
    };
    let problem = load_problem(&args.scene, &overrides)?;
    if let Some(dir) = &args.out {
        output::prepare_dir(dir)?;
    }
    let d = with_progress(false, |m| study::damage(&problem, m))
        .map_err(|e| Failure::in_scene(&args.scene, e))?;
    interrupt::check()?;
    let title = &problem.model.title;
    let written = match &args.out {
        Some(dir) => output::damage::write_damage(dir, &d, title)?.len(),
        None => 0,
    };
    let written = written + with_report(args.report, args.out.as_deref(), written)?;
    if args.json {
        let json = serde_json::to_string_pretty(&d.reported())
            .map_err(|e| Failure::new(exit::IO, format!("cannot serialise damage.json: {e}")))?;
        println!("{json}");
    } else {
        let files = args.out.as_deref().map(|dir| (written, dir));
        print!("{}", output::damage::damage_table(title, &d, files));
    }
    if !d.complete {
        return Err(Failure::new(
            exit::SOLVER,
            format!(
                "{} pass(es) did not converge: the damage sums are incomplete",
                d.missing.len()
            ),
        ));
    }
    Ok(())
}

fn design(args: DesignArgs) -> Result<(), Failure> {
    let overrides = liftoff::scene::Overrides {
        method: args.method,
        ..args.overrides.library()
    };
    let source = Source::from_arg(&args.scene);
    let mut file = source
        .parse()
        .map_err(|e| Failure::in_scene(&args.scene, e))?;
    overrides.apply(&mut file);
    // The range and the tolerance are in the scene's unit of length.
    let options = study::DesignOptions::in_units(
        file.units,
        args.vary,
        args.points,
        args.target,
        args.tolerance,
    );
    options.validate().map_err(Failure::option)?;
    // The scene as given must be valid before the search varies it.
    file.validate()
        .map_err(|e| Failure::in_scene(&args.scene, e))?;
    if let Some(dir) = &args.out {
        output::prepare_dir(dir)?;
    }
    let d = with_progress(false, |m| study::design(&file, &options, m))
        .map_err(|e| Failure::in_scene(&args.scene, e))?;
    interrupt::check()?;
    let title = file.title.clone().unwrap_or_else(|| args.scene.clone());
    let written = match &args.out {
        Some(dir) => output::damage::write_design(dir, &d, &title)?.len(),
        None => 0,
    };
    let written = written + with_report(args.report, args.out.as_deref(), written)?;
    if args.json {
        let json = serde_json::to_string_pretty(&d.reported())
            .map_err(|e| Failure::new(exit::IO, format!("cannot serialise design.json: {e}")))?;
        println!("{json}");
    } else {
        let files = args.out.as_deref().map(|dir| (written, dir));
        print!("{}", output::damage::design_table(&title, &d, files));
    }
    if !d.complete {
        return Err(Failure::new(
            exit::SOLVER,
            "some damage runs had passes that did not converge: the design curve is incomplete",
        ));
    }
    Ok(())
}

fn backcalc(args: BackcalcArgs) -> Result<(), Failure> {
    let path = args.basins.display().to_string();
    let text = std::fs::read_to_string(&args.basins).map_err(|source| {
        Failure::from(Error::Io {
            path: path.clone(),
            source,
        })
    })?;
    let file = Source::from_arg(&args.scene)
        .parse()
        .map_err(|e| Failure::in_scene(&args.scene, e))?;
    // `--at` is in the template's unit of length, as every length of its scene.
    let placement = liftoff::backcalc::Placement::from_options(
        args.location,
        args.at
            .map(|p| p.map(|v| liftoff::units::Quantity::Length.to_si(file.units, v))),
        args.direction,
    );
    let drops = liftoff::backcalc::read_drops_placed(&text, &path, placement.as_ref()).map_err(
        |e| {
            let hint = match &e {
                Error::Invalid { field, .. } if field == "placement" => "\nhint: --location, --at and --direction place the drops of a PDDX file; leave them out for a CSV file",
                Error::Invalid { field, .. } if field == "placement.at" => "\nhint: --at X,Y gives the load plate's centre, in the template's unit of length and coordinates",
                _ => "",
            };
            let f = Failure::from(e);
            Failure::new(f.code, format!("{}{hint}", f.message))
        },
    )?;
    // The template must be valid before the fits change its moduli and loads (it needs no
    // loads of its own: the drops are).
    liftoff::backcalc::check_template(&file).map_err(|e| Failure::in_scene(&args.scene, e))?;
    let options = liftoff::backcalc::SurveyOptions {
        method: args.method,
        fit: liftoff::backcalc::FitOptions {
            unknowns: args.fit.clone(),
            contact: args.contact,
            elements: args.elements,
            max_evaluations: args.max_evaluations,
        },
        seating: args.seating,
        static_k_factor: args.static_k_factor,
        void_threshold: args.void_threshold_um * 1e-6,
    };
    if let Some(dir) = &args.out {
        output::prepare_dir(dir)?;
    }
    let s = with_progress(false, |m| {
        liftoff::backcalc::survey(&file, &drops, &options, m)
    })
    .map_err(|e| Failure::in_scene(&args.scene, e))?;
    interrupt::check()?;
    let title = file.title.clone().unwrap_or_else(|| path.clone());
    let written = match &args.out {
        Some(dir) => output::backcalc::write_backcalc(dir, &s, &title, file.units)?.len(),
        None => 0,
    };
    let written = written + with_report(args.report, args.out.as_deref(), written)?;
    if args.json {
        let json = serde_json::to_string_pretty(&s)
            .map_err(|e| Failure::new(exit::IO, format!("cannot serialise backcalc.json: {e}")))?;
        println!("{json}");
    } else {
        let files = args.out.as_deref().map(|dir| (written, dir));
        print!(
            "{}",
            output::backcalc::backcalc_table(&title, &s, file.units, files)
        );
    }
    if !s.complete {
        return Err(Failure::new(
            exit::SOLVER,
            format!(
                "{} fit(s) did not converge ({}): their rows show the best point reached, not a result",
                s.not_converged.len(),
                s.not_converged.join("; ")
            ),
        ));
    }
    Ok(())
}

/// `--report`: report.html into the output directory once its other files are in place
/// (`written` of them; none when the run wrote none). Returns the files it added.
fn with_report(
    report: bool,
    dir: Option<&std::path::Path>,
    written: usize,
) -> Result<usize, Failure> {
    match dir {
        Some(dir) if report && written > 0 => {
            output::report::write_report(dir, None)?;
            Ok(1)
        }
        _ => Ok(0),
    }
}

fn report(args: ReportArgs) -> Result<(), Failure> {
    let path = output::report::write_report(&args.dir, args.out.as_deref())?;
    println!("written: {}", path.display());
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
                .filter(|l| !matches!(*l, "out" | "json" | "report" | "help"))
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
