//! The command line's arguments (clap): one struct per subcommand. Choices take their words
//! from the library's lists ([`Choice`]), so a flag and a scene key are spelled alike.

use std::path::PathBuf;

use clap::builder::{PossibleValuesParser, TypedValueParser};
use clap::{Parser, Subcommand};
use liftoff::backcalc::{BackcalcMethod, Location, Unknown};
use liftoff::choice::Choice;
use liftoff::method::{Contact, MethodKind, QpForm, QpSolver, Route, Start};
use liftoff::model::{ConstraintPoints, SymmetryMode};
use liftoff::scene::PenaltySpec;
use liftoff::study::{Along, ConstraintVariants, Ends, EpsSweepOptions};

#[derive(Parser)]
#[command(
    name = "liftoff",
    version,
    about = "Rectangular plates on tensionless foundations: where they lift off, how they deflect, what the soil takes"
)]
pub(crate) struct Cli {
    #[command(subcommand)]
    pub(crate) command: Command,
}

#[derive(Subcommand)]
pub(crate) enum Command {
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
    /// Move a named axle or gear load over the plate: the positions that give the largest
    /// bottom and top stress and deflection, and influence maps.
    Critical(CriticalArgs),
    /// Fatigue damage over the scene's [traffic] and [climate]: every case a pass of its axle
    /// group along the lane, the Miner sum at both faces of every element.
    Damage(DamageArgs),
    /// The least slab thickness that carries the scene's traffic: damage runs over a range of
    /// thicknesses (the design curve), the target bracketed and the bracket narrowed.
    Design(DesignArgs),
    /// Backcalculate the soil and the slab from deflectometer basins (a CSV or PDDX file) on a template
    /// scene: the least-squares fit on liftoff's model with 95 % intervals, or the AREA method.
    Backcalc(BackcalcArgs),
    /// Regenerate the paper's Figs. 3–7 (SVG and PNG), paper.json and paper.md.
    Paper(PaperArgs),
    /// Write one self-contained HTML page (summary, tables, charts) from an output directory
    /// of `solve`, `critical`, `damage`, `design` or `backcalc`.
    Report(ReportArgs),
    /// Print a bundled example scene (without NAME: list them).
    Example {
        /// Name of the example.
        name: Option<String>,
    },
}

impl Command {
    /// The subcommand as typed (for `interrupted: \`liftoff critical\` …`).
    pub(crate) fn name(&self) -> &'static str {
        match self {
            Command::Solve(_) => "solve",
            Command::Compare(_) => "compare",
            Command::EpsSweep(_) => "eps-sweep",
            Command::Tradeoff(_) => "tradeoff",
            Command::Stability(_) => "stability",
            Command::Critical(_) => "critical",
            Command::Damage(_) => "damage",
            Command::Design(_) => "design",
            Command::Backcalc(_) => "backcalc",
            Command::Paper(_) => "paper",
            Command::Report(_) => "report",
            Command::Example { .. } => "example",
        }
    }
}

/// Options shared by `solve` and `compare` that override the scene file.
#[derive(clap::Args)]
pub(crate) struct Overrides {
    /// Dimensionless penalty ε̄: auto, or a fixed value such as 1e-5 (overrides [solver] penalty).
    #[arg(long, value_parser = parse_penalty)]
    pub(crate) penalty: Option<PenaltySpec>,
    /// Constraint points (overrides [solver] constraint).
    #[arg(long, value_parser = choice::<ConstraintPoints>())]
    pub(crate) constraint: Option<ConstraintPoints>,
    /// Elements over the whole plate, NX,NY (overrides [mesh] elements).
    #[arg(long, value_parser = parse_mesh)]
    pub(crate) mesh: Option<[i64; 2]>,
    /// How the QP is posed: auto (primal on Winkler, schur on the half-space), schur, lifted or
    /// primal (overrides [solver] qp_form).
    #[arg(long, value_parser = choice::<QpForm>())]
    pub(crate) qp_form: Option<QpForm>,
    /// Which solver runs the QP: auto (clarabel where its form fits and is robust, the
    /// matrix-free active-set method elsewhere), clarabel, or active-set (overrides [solver]
    /// qp_solver).
    #[arg(long, value_parser = choice::<QpSolver>())]
    pub(crate) qp_solver: Option<QpSolver>,
    /// How the half-space is held and solved: auto (dense up to 1500 pressure nodes, iterative
    /// beyond), dense (dense T, direct factorisations) or iterative (T by FFT, conjugate
    /// gradients) (overrides [solver] route).
    #[arg(long, value_parser = choice::<Route>())]
    pub(crate) solver: Option<Route>,
    /// Where a large grid starts: nested (from the same plate on a grid twice as coarse) or
    /// cold (overrides [solver] start).
    #[arg(long, value_parser = choice::<Start>())]
    pub(crate) start: Option<Start>,
}

impl Overrides {
    /// The library's overrides (shared with the Python package) with these flags set.
    pub(crate) fn library(&self) -> liftoff::scene::Overrides {
        liftoff::scene::Overrides {
            penalty: self.penalty.clone(),
            constraint: self.constraint,
            mesh: self.mesh,
            qp_form: self.qp_form,
            qp_solver: self.qp_solver,
            solver: self.solver,
            start: self.start,
            ..Default::default()
        }
    }
}

#[derive(clap::Args)]
pub(crate) struct SolveArgs {
    /// Scene file (TOML), or `example:NAME` for a bundled scene.
    pub(crate) scene: String,
    /// Contact law (overrides [solver] contact).
    #[arg(long, value_parser = choice::<Contact>())]
    pub(crate) contact: Option<Contact>,
    /// Method for unbonded contact (overrides [solver] method).
    #[arg(long, value_parser = choice::<MethodKind>())]
    pub(crate) method: Option<MethodKind>,
    #[command(flatten)]
    pub(crate) overrides: Overrides,
    /// Symmetry reduction (overrides [mesh] symmetry).
    #[arg(long, value_parser = choice::<SymmetryMode>())]
    pub(crate) symmetry: Option<SymmetryMode>,
    /// Directory for summary.json, CSV tables, plate.vtu and charts.
    #[arg(long)]
    pub(crate) out: Option<PathBuf>,
    /// Print summary.json to stdout instead of the table.
    #[arg(long)]
    pub(crate) json: bool,
    /// Also write report.html (one self-contained page) into --out.
    #[arg(long, requires = "out")]
    pub(crate) report: bool,
}

#[derive(clap::Args)]
pub(crate) struct CompareArgs {
    /// Scene file (TOML), or `example:NAME` for a bundled scene.
    pub(crate) scene: String,
    #[command(flatten)]
    pub(crate) overrides: Overrides,
    /// Directory for compare.json (default: the current directory).
    #[arg(long, default_value = ".")]
    pub(crate) out: PathBuf,
}

/// The flags are the fields of [`EpsSweepOptions`], with its defaults.
#[derive(clap::Args)]
pub(crate) struct EpsSweepArgs {
    /// Scene file (TOML), or `example:NAME`.
    pub(crate) scene: String,
    /// Largest ε̄.
    #[arg(long, default_value_t = EpsSweepOptions::default().from)]
    pub(crate) from: f64,
    /// Smallest ε̄.
    #[arg(long, default_value_t = EpsSweepOptions::default().to)]
    pub(crate) to: f64,
    /// Number of ε̄ values (log-spaced).
    #[arg(long, default_value_t = EpsSweepOptions::default().points)]
    pub(crate) points: usize,
    /// Constraint variants: nodal, gauss or both.
    #[arg(long, value_parser = choice::<ConstraintVariants>(), hide_possible_values = true,
          default_value_t = EpsSweepOptions::default().constraints)]
    pub(crate) constraints: ConstraintVariants,
    /// Directory for eps_sweep.csv and eps_sweep.svg.
    #[arg(long, default_value = ".")]
    pub(crate) out: PathBuf,
}

/// The flags are the fields of [`TradeoffOptions`]; the defaults are its defaults, spelled as
/// `--help` shows them (a test checks they agree).
#[derive(clap::Args)]
pub(crate) struct TradeoffArgs {
    /// Scene file (TOML), or `example:NAME`.
    pub(crate) scene: String,
    /// Elements per side of the whole plate (along x; y follows μ).
    #[arg(long, value_delimiter = ',', default_value = "8,16,32,64")]
    pub(crate) meshes: Vec<usize>,
    /// Penalty values ε̄ for the penalty method.
    #[arg(long, value_delimiter = ',', default_value = "1e-2,1e-4,1e-6,1e-8")]
    pub(crate) penalties: Vec<f64>,
    /// Directory for tradeoff.csv and tradeoff.svg.
    #[arg(long, default_value = ".")]
    pub(crate) out: PathBuf,
}

#[derive(clap::Args)]
pub(crate) struct StabilityArgs {
    /// Base scenes (default: one per soil — the paper's plate on Winkler springs and the
    /// half-space, the slab-on-grade bay on the Pasternak soil, the elastic layer and Reissner's
    /// Kerr layer).
    pub(crate) scenes: Vec<String>,
    /// Directory for stability.csv and the maps.
    #[arg(long, default_value = ".")]
    pub(crate) out: PathBuf,
}

#[derive(clap::Args)]
pub(crate) struct PaperArgs {
    /// Directory for the figures, paper.json and paper.md.
    #[arg(long, default_value = "paper")]
    pub(crate) out: PathBuf,
    /// Method for the unbonded solves.
    #[arg(long, value_parser = choice::<MethodKind>(), default_value = "penalty")]
    pub(crate) method: MethodKind,
    /// Reading of the paper's load condition 2: patch (γ from Fig. 6's captions), patch=G, or edge-band.
    #[arg(long, default_value = "patch")]
    pub(crate) load2: String,
    /// Also solve on meshes 2, 4, … up to this many times finer than the paper's.
    #[arg(long, default_value_t = 1)]
    pub(crate) refine: usize,
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

/// The flags of `critical`; the defaults are [`liftoff::study::CriticalOptions`]'s.
#[derive(clap::Args)]
pub(crate) struct CriticalArgs {
    /// Scene file (TOML), or `example:NAME`.
    pub(crate) scene: String,
    /// The `name` of the axle or gear load to move.
    #[arg(long)]
    pub(crate) load: String,
    /// Reference points along x and y, NX,NY, evenly over the plate (1 keeps the load's own
    /// coordinate).
    #[arg(long, value_parser = parse_grid, default_value = "11,9")]
    pub(crate) grid: [usize; 2],
    /// Reference points per panel instead, NX,NY: in every panel between the joint lines, its
    /// sides included (5 → 0, ¼, ½, ¾, 1 of the panel; 1 → its middle); points on the plate's
    /// edge move inward to where the prints touch it.
    #[arg(long, value_parser = parse_grid, conflicts_with = "grid")]
    pub(crate) grid_per_panel: Option<[usize; 2]>,
    /// Search along a line only: joint:NAME (the prints just before the joint, the load on it,
    /// the prints just after it) or edge:x-, edge:x+, edge:y-, edge:y+ (the prints touching
    /// that edge); the points along it from --grid or --grid-per-panel. Repeat or separate by
    /// commas for several lines.
    #[arg(long, value_delimiter = ',', value_parser = parse_along)]
    pub(crate) along: Vec<Along>,
    /// Headings to try, degrees (default: the load's own).
    #[arg(long, value_delimiter = ',')]
    pub(crate) headings: Vec<f64>,
    /// The combination the load acts in (default: the first that has its case).
    #[arg(long)]
    pub(crate) combination: Option<String>,
    /// Solve every position from scratch instead of from its neighbour's answer.
    #[arg(long)]
    pub(crate) cold: bool,
    /// Solve every position, also those whose load is another's mirror image on a symmetric
    /// plate (by default read off that one's answer).
    #[arg(long)]
    pub(crate) no_mirror: bool,
    /// What the plate's ends across the lane (x = ±a/2) are, where it has two or more
    /// transverse joints: `cut` (the model cuts a lane that goes on; every position is read
    /// between the first and the last transverse joint) or `free` (the plate ends there: the
    /// whole plate is read). Default: the scene's `[plate] ends` (or its `[traffic]`'s), else
    /// free.
    #[arg(long, value_parser = choice::<Ends>())]
    pub(crate) ends: Option<Ends>,
    /// Method for unbonded contact (overrides [solver] method).
    #[arg(long, value_parser = choice::<MethodKind>())]
    pub(crate) method: Option<MethodKind>,
    /// Contact law (overrides [solver] contact).
    #[arg(long, value_parser = choice::<Contact>())]
    pub(crate) contact: Option<Contact>,
    #[command(flatten)]
    pub(crate) overrides: Overrides,
    /// Directory for critical.csv, critical.json and the influence maps.
    #[arg(long)]
    pub(crate) out: Option<PathBuf>,
    /// Print critical.json to stdout instead of the table.
    #[arg(long)]
    pub(crate) json: bool,
    /// Also write report.html (one self-contained page) into --out.
    #[arg(long, requires = "out")]
    pub(crate) report: bool,
}

/// The flags of `damage`; the traffic, climate and relation are the scene's.
#[derive(clap::Args)]
pub(crate) struct DamageArgs {
    /// Scene file (TOML) with [traffic], [damage] and optionally [climate], or `example:NAME`.
    pub(crate) scene: String,
    /// Method for unbonded contact (overrides [solver] method).
    #[arg(long, value_parser = choice::<MethodKind>())]
    pub(crate) method: Option<MethodKind>,
    #[command(flatten)]
    pub(crate) overrides: Overrides,
    /// Directory for damage.csv, passes.csv, damage.json and the damage maps.
    #[arg(long)]
    pub(crate) out: Option<PathBuf>,
    /// Print damage.json to stdout instead of the table.
    #[arg(long)]
    pub(crate) json: bool,
    /// Also write report.html (one self-contained page) into --out.
    #[arg(long, requires = "out")]
    pub(crate) report: bool,
}

/// The flags of `design`.
#[derive(clap::Args)]
pub(crate) struct DesignArgs {
    /// Scene file (TOML) with [traffic], [damage] and optionally [climate], or `example:NAME`.
    pub(crate) scene: String,
    /// The thickness range, thickness=FROM..TO, in the scene's unit of length (m; in for a US
    /// scene).
    #[arg(long, value_parser = parse_vary)]
    pub(crate) vary: [f64; 2],
    /// Thicknesses of the design curve, evenly over the range.
    #[arg(long, default_value_t = 6)]
    pub(crate) points: usize,
    /// The target: total cracking in % for mepdg (default 15), the largest Σ n/N for pca and
    /// faa (default 1).
    #[arg(long)]
    pub(crate) target: Option<f64>,
    /// Narrow the bracket until it is this narrow, in the scene's unit of length (default
    /// 5 mm; 0.25 in for a US scene).
    #[arg(long)]
    pub(crate) tolerance: Option<f64>,
    /// Method for unbonded contact (overrides [solver] method).
    #[arg(long, value_parser = choice::<MethodKind>())]
    pub(crate) method: Option<MethodKind>,
    #[command(flatten)]
    pub(crate) overrides: Overrides,
    /// Directory for design.csv, design.json and the design curve.
    #[arg(long)]
    pub(crate) out: Option<PathBuf>,
    /// Print design.json to stdout instead of the table.
    #[arg(long)]
    pub(crate) json: bool,
    /// Also write report.html (one self-contained page) into --out.
    #[arg(long, requires = "out")]
    pub(crate) report: bool,
}

/// The flags of `backcalc`.
#[derive(clap::Args)]
pub(crate) struct BackcalcArgs {
    /// Basin file: CSV (one row a drop, the units in the column names) or AASHTO PDDX (its
    /// drops interior ones unless --location says otherwise): README, "Backcalculation".
    pub(crate) basins: PathBuf,
    /// The template scene (TOML, or `example:NAME`): the slab's size, thickness, ν and joints,
    /// and the soil model whose modulus is fitted; its moduli are where a fit starts when the
    /// AREA method cannot start it.
    #[arg(long)]
    pub(crate) scene: String,
    /// fit (least squares on liftoff's model, the AREA reading beside it) or area (the AREA
    /// method alone: interior drops on winkler or half-space templates).
    #[arg(long, default_value = "fit", value_parser = choice::<BackcalcMethod>())]
    pub(crate) method: BackcalcMethod,
    /// The unknowns of the fit, comma-separated: subgrade (the soil's modulus), slab (its E),
    /// void (the depth of the template's [[void]] nearest the drop; unbonded contact), joint
    /// (the stiffness of the template's aggregate or tied joint nearest the drop).
    #[arg(long, value_delimiter = ',', default_value = "subgrade,slab", value_parser = choice::<Unknown>())]
    pub(crate) fit: Vec<Unknown>,
    /// Contact law of the model (overrides the template's [solver] contact).
    #[arg(long, value_parser = choice::<Contact>())]
    pub(crate) contact: Option<Contact>,
    /// Elements over the whole plate, NX,NY (default: the template's counts, multiplied until
    /// the elements are no wider than 0.95 of the load plate's radius).
    #[arg(long, value_parser = parse_grid)]
    pub(crate) elements: Option<[usize; 2]>,
    /// Where every drop of a PDDX file stood (the file does not say it): interior (default),
    /// edge, corner, joint-approach, joint-leave. A CSV file says it in its columns.
    #[arg(long, value_parser = choice::<Location>())]
    pub(crate) location: Option<Location>,
    /// The load plate's centre for every drop of a PDDX file, X,Y in the template's unit of
    /// length and coordinates (default: the location's own place, as README says; joint
    /// drops need it).
    #[arg(long, value_parser = parse_point, allow_hyphen_values = true)]
    pub(crate) at: Option<[f64; 2]>,
    /// The sensor line's direction from the x axis for every drop of a PDDX file, degrees
    /// (default 0: along +x).
    #[arg(long, allow_hyphen_values = true)]
    pub(crate) direction: Option<f64>,
    /// Seating drops to discard at the start of each station.
    #[arg(long, default_value_t = 0)]
    pub(crate) seating: usize,
    /// At most this many evaluations of the model a fit (its Jacobians not counted); a fit
    /// that needs more is reported as not converged.
    #[arg(long, default_value_t = liftoff::backcalc::FitOptions::default().max_evaluations)]
    pub(crate) max_evaluations: usize,
    /// Static k over the dynamic k a basin gives (AASHTO 1993: 0.5).
    #[arg(long, default_value_t = 0.5)]
    pub(crate) static_k_factor: f64,
    /// The zero-load intercept, in µm, above which a station's load–deflection line flags a
    /// void (AASHTO 1993: 2 mils = 50.8 µm).
    #[arg(long, default_value_t = 50.8)]
    pub(crate) void_threshold_um: f64,
    /// Directory for backcalc.csv, basins.csv, backcalc.json and the charts.
    #[arg(long)]
    pub(crate) out: Option<PathBuf>,
    /// Print backcalc.json to stdout instead of the table.
    #[arg(long)]
    pub(crate) json: bool,
    /// Also write report.html (one self-contained page) into --out.
    #[arg(long, requires = "out")]
    pub(crate) report: bool,
}

fn parse_vary(s: &str) -> Result<[f64; 2], String> {
    let range = s.strip_prefix("thickness=").ok_or_else(|| {
        format!("expected thickness=FROM..TO (the plate's thickness is what a design varies), got `{s}`")
    })?;
    let (a, b) = range
        .split_once("..")
        .ok_or_else(|| format!("expected thickness=FROM..TO, got `{s}`"))?;
    let num = |t: &str| {
        t.trim()
            .parse::<f64>()
            .map_err(|_| format!("`{t}` is not a number in `{s}`"))
    };
    Ok([num(a)?, num(b)?])
}

#[derive(clap::Args)]
pub(crate) struct ReportArgs {
    /// An output directory of `liftoff solve`, `critical`, `damage`, `design` or `backcalc`.
    pub(crate) dir: PathBuf,
    /// The page to write (default: DIR/report.html).
    #[arg(long)]
    pub(crate) out: Option<PathBuf>,
}

fn parse_along(s: &str) -> Result<Along, String> {
    s.parse().map_err(|e: liftoff::Error| match e {
        liftoff::Error::Invalid { message, .. } => message,
        e => e.to_string(),
    })
}

fn parse_point(s: &str) -> Result<[f64; 2], String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    let n = |p: &str| {
        p.parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| format!("`{p}` is not a coordinate"))
    };
    match parts.as_slice() {
        [x, y] => Ok([n(x)?, n(y)?]),
        _ => Err(format!("expected X,Y (two coordinates), got `{s}`")),
    }
}

fn parse_grid(s: &str) -> Result<[usize; 2], String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    let n = |p: &str| {
        p.parse::<usize>()
            .map_err(|_| format!("`{p}` is not a whole number of points"))
    };
    match parts.as_slice() {
        [a, b] => Ok([n(a)?, n(b)?]),
        _ => Err(format!("expected NX,NY (two point counts), got `{s}`")),
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
