//! What the binary reports on failure: `error: {message}` on stderr, a `hint:` line that names
//! flags where one helps, and an exit code per kind of failure (docs/ERRORS.md).

use liftoff::{Error, ErrorKind, Method};

/// Exit codes, one per kind of failure (docs/ERRORS.md).
pub(crate) mod exit {
    pub const BAD_INPUT: u8 = 2;
    pub const INFEASIBLE: u8 = 3;
    pub const SOLVER: u8 = 4;
    pub const IO: u8 = 5;
}

/// What the binary reports on failure: `error: {message}` on stderr and the exit code.
pub(crate) struct Failure {
    pub(crate) message: String,
    pub(crate) code: u8,
}

impl Failure {
    pub(crate) fn new(code: u8, message: impl Into<String>) -> Self {
        let message = message.into();
        Failure { message, code }
    }

    /// A library error about a scene: the message starts with where the scene came from.
    pub(crate) fn in_scene(spec: &str, e: Error) -> Self {
        let mut f = Failure::from(e);
        f.message = format!("{spec}: {}", f.message);
        f
    }

    /// A library error from an options struct whose fields are this subcommand's flags
    /// (`points` → `--points`): the message names the flag.
    pub(crate) fn option(e: Error) -> Self {
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
    pub(crate) fn solving(e: Error, method: &Method) -> Self {
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
