//! The one seam between the library and its front ends: a scene from wherever it comes
//! ([`Source`]) and the front end's [`Overrides`] become a validated [`Problem`] ([`load`]), and
//! a problem is solved as one load set or as every `[[combination]]` with their envelope
//! ([`run`]). The command line and the Python package call these two functions and branch on
//! nothing else.
//!
//! The rule for combinations, in one place: every combination is solved; the envelope is built
//! only when every one of them converged ([`Combinations::envelope`] is `None` otherwise, and
//! [`Combinations::missing`] names the ones without a solution), since an envelope missing a
//! combination is not an envelope.

use std::path::Path;

use crate::analysis::{self, Analysis};
use crate::combination::{self, Combinations};
use crate::error::{Error, Result};
use crate::monitor::Monitor;
use crate::scene::{Overrides, Problem, SceneFile};

/// Where a scene comes from.
#[derive(Debug, Clone)]
pub enum Source<'a> {
    /// A TOML file.
    Path(&'a Path),
    /// TOML text.
    Toml(&'a str),
    /// JSON text with the scene file's keys (a Python dict, say).
    Json(&'a str),
    /// A bundled scene by name (`example:NAME` on the command line).
    Example(&'a str),
    /// A scene already parsed (built or edited in Rust).
    Parsed(Box<SceneFile>),
}

impl<'a> Source<'a> {
    /// The command line's scene argument: `example:NAME` for a bundled scene, else a path.
    pub fn from_arg(arg: &'a str) -> Self {
        match arg.strip_prefix("example:") {
            Some(name) => Source::Example(name),
            None => Source::Path(Path::new(arg)),
        }
    }

    /// The scene file, parsed (not yet validated).
    pub fn parse(&self) -> Result<SceneFile> {
        match self {
            Source::Path(p) => {
                let text = std::fs::read_to_string(p).map_err(|e| Error::Io {
                    path: p.display().to_string(),
                    source: std::io::Error::new(e.kind(), format!("cannot read scene file: {e}")),
                })?;
                SceneFile::parse(&text)
            }
            Source::Toml(text) => SceneFile::parse(text),
            Source::Json(text) => SceneFile::from_json(text),
            Source::Example(name) => SceneFile::example(name),
            Source::Parsed(file) => Ok((**file).clone()),
        }
    }
}

/// Read a scene, apply the overrides, validate: the problem every front end solves.
pub fn load(source: &Source<'_>, overrides: &Overrides) -> Result<Problem> {
    let mut file = source.parse()?;
    overrides.apply(&mut file);
    file.validate()
}

/// What a problem's run gives: one solve, or every combination with their envelope.
pub enum Outcome {
    /// A scene without combinations: its analysis (operators, solution, report, summary).
    /// Whether it converged is in `summary.converged`; a solve that did not is returned, not
    /// refused, so that a front end can show what happened.
    Single(Box<Analysis>),
    /// A scene with `[[combination]]`s: each one's outcome and, when every one converged, the
    /// envelope.
    Combinations(Combinations),
}

impl Outcome {
    /// Whether everything converged (the one solve, or every combination).
    pub fn converged(&self) -> bool {
        match self {
            Outcome::Single(a) => a.summary.converged,
            Outcome::Combinations(c) => c.all_converged(),
        }
    }

    /// The `--json` document: the summary of a single solve, or the combinations' summaries,
    /// the ones missing and the envelope's extremes.
    pub fn to_json(&self) -> Result<String> {
        match self {
            Outcome::Single(a) => a.summary.to_json(),
            Outcome::Combinations(c) => c.to_json(),
        }
    }
}

/// Solve a validated problem: as one load set, or every combination on one assembly.
pub fn run(problem: &Problem, monitor: &Monitor<'_>) -> Result<Outcome> {
    if problem.combinations.is_empty() {
        Ok(Outcome::Single(Box::new(analysis::analyse_with(
            problem, monitor,
        )?)))
    } else {
        Ok(Outcome::Combinations(combination::analyse(
            problem, monitor,
        )?))
    }
}
