//! Typed errors of the library. Outcomes of a solve that ran (converged or not) are not errors:
//! they are a [`crate::solve::Status`] on the solution.

/// Everything that can stop liftoff before it has a result to report.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// The scene text is not valid TOML or does not match the scene schema.
    #[error("scene is not valid: {0}")]
    Parse(String),
    /// A scene value is out of range or inconsistent; `field` names it as written in the file.
    #[error("scene field `{field}`: {message}")]
    Invalid {
        /// Dotted path of the offending field, e.g. `plate.thickness` or `load[2].x`.
        field: String,
        /// What is wrong and how to fix it.
        message: String,
    },
    /// The problem would need more memory than allowed.
    #[error(
        "{what} needs about {need_gib:.2} GiB, more than the {limit_gib:.2} GiB allowed; {hint}"
    )]
    TooLarge {
        /// What would be allocated.
        what: String,
        /// Estimated need, GiB.
        need_gib: f64,
        /// Limit, GiB.
        limit_gib: f64,
        /// How to make it fit.
        hint: String,
    },
    /// The loads admit no equilibrium with the chosen contact law.
    #[error("no equilibrium is possible: {0}")]
    Infeasible(String),
    /// A factorisation or a solver failed, or produced non-finite numbers.
    #[error("numerical failure in {stage}: {message}")]
    Numerical {
        /// Which step failed.
        stage: String,
        /// What happened.
        message: String,
    },
    /// The requested combination is not available.
    #[error("{0}")]
    Unsupported(String),
    /// The caller asked the run to stop (a cancel flag, Ctrl-C in Python) before it finished.
    #[error("cancelled before the run finished: {0}")]
    Cancelled(String),
    /// A directory given as liftoff's output holds none (`liftoff report DIR`).
    #[error("`{dir}` holds no liftoff output: expected {expected}")]
    NoOutput {
        /// The directory.
        dir: String,
        /// The files that would have made it one.
        expected: String,
    },
    /// Reading or writing a file failed.
    #[error("{path}: {source}")]
    Io {
        /// The file or directory.
        path: String,
        /// The operating-system error.
        source: std::io::Error,
    },
}

impl Error {
    /// Shorthand for [`Error::Invalid`].
    pub fn invalid(field: impl Into<String>, message: impl Into<String>) -> Self {
        Error::Invalid {
            field: field.into(),
            message: message.into(),
        }
    }

    /// Which kind of failure, as the studies' CSV files, the command line's exit code and the
    /// Python exception classes tell them apart.
    pub fn kind(&self) -> ErrorKind {
        match self {
            Error::TooLarge { .. } => ErrorKind::TooLarge,
            Error::Infeasible(_) => ErrorKind::Infeasible,
            Error::Numerical { .. } => ErrorKind::Numerical,
            Error::Parse(_)
            | Error::Invalid { .. }
            | Error::Unsupported(_)
            | Error::NoOutput { .. } => ErrorKind::Invalid,
            Error::Io { .. } => ErrorKind::Io,
            Error::Cancelled(_) => ErrorKind::Cancelled,
        }
    }

    /// Shorthand for [`Error::Numerical`].
    pub fn numerical(stage: impl Into<String>, message: impl Into<String>) -> Self {
        Error::Numerical {
            stage: stage.into(),
            message: message.into(),
        }
    }
}

/// The kinds of [`Error`]: what a front end branches on (an exit code, an exception class).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ErrorKind {
    /// Bad input: a scene, an option or a combination the library does not take.
    Invalid,
    /// More memory than allowed.
    TooLarge,
    /// No equilibrium is possible with the contact law.
    Infeasible,
    /// A factorisation or a solver broke down.
    Numerical,
    /// A file could not be read or written.
    Io,
    /// The run was cancelled by its caller.
    Cancelled,
}

crate::choice::names!(ErrorKind, Invalid => "invalid", TooLarge => "too-large", Infeasible => "infeasible",
    Numerical => "numerical", Io => "io", Cancelled => "cancelled");

/// Result alias of the library.
pub type Result<T, E = Error> = std::result::Result<T, E>;
