//! What the binary reports on failure: `error: {message}` on stderr, a `hint:` line that names
//! flags where one helps, and an exit code per kind of failure (docs/ERRORS.md).

use liftoff::{Error, ErrorKind, Method};

/// Exit codes, one per kind of failure (docs/ERRORS.md).
pub(crate) mod exit {
    pub const BAD_INPUT: u8 = 2;
    pub const INFEASIBLE: u8 = 3;
    pub const SOLVER: u8 = 4;
    pub const IO: u8 = 5;
    /// Interrupted by Ctrl-C (SIGINT), SIGTERM or SIGHUP: 128 + SIGINT, the shells' convention.
    pub const INTERRUPTED: u8 = 130;
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

    /// A run stopped by a signal ([`crate::interrupt`]) `when` (`during the penalty
    /// iteration`): exit 130, and the binary prints `interrupted: …`, not `error: …`.
    pub(crate) fn interrupted(when: impl std::fmt::Display) -> Self {
        Failure::new(
            exit::INTERRUPTED,
            format!("stopped {when}; nothing was written"),
        )
    }

    /// A library error about a scene: the message starts with where the scene came from (an
    /// interruption is not about the scene).
    pub(crate) fn in_scene(spec: &str, e: Error) -> Self {
        let mut f = Failure::from(e);
        if f.code != exit::INTERRUPTED {
            f.message = format!("{spec}: {}", f.message);
        }
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
        if let Error::Cancelled(during) = &e {
            return Failure::interrupted(format_args!("during {during}"));
        }
        let (code, hint) = match e.kind() {
            ErrorKind::Invalid | ErrorKind::TooLarge => (exit::BAD_INPUT, ""),
            ErrorKind::Infeasible => (
                exit::INFEASIBLE,
                "\nhint: bonded contact (--contact bonded) lets the foundation pull",
            ),
            ErrorKind::Numerical => (exit::SOLVER, ""),
            ErrorKind::Cancelled => (exit::INTERRUPTED, ""),
            ErrorKind::Io => (exit::IO, ""),
        };
        Failure::new(code, format!("{e}{hint}"))
    }
}

impl Failure {
    /// A single solve that ran but did not converge (its table is printed above): exit 4, the
    /// status, and a hint naming the flags that help — a smaller `--penalty` when the penalty
    /// was too weak (E23), the other method or QP solver otherwise (E22, E24, E26, E42).
    pub(crate) fn not_converged(a: &liftoff::Analysis, method: &Method) -> Self {
        let hint = match (&a.solution.status, method) {
            (liftoff::Status::PenaltyTooWeak { suggested_penalty, .. }, _) => format!(
                "\nhint: rerun with --penalty {suggested_penalty:.0e} or --method qp"
            ),
            (_, Method::Qp(_)) => "\nhint: --method penalty solves the same operators by the paper's iteration, or try the other --qp-solver where it applies".into(),
            _ => "\nhint: --method qp solves the same operators as a convex QP".into(),
        };
        Failure::new(exit::SOLVER, format!(
            "the {} method did not converge ({}); no result is shown (its last iterate is not a solution) and no files were written{hint}",
            a.summary.method, a.summary.status
        ))
    }

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

/// The entries of docs/ERRORS.md that no scene is known to reach through the command line
/// (E27, E28: every input number is validated; E42's cap of 500 face solves: no scene key sets
/// it): each triggered here through the library — operators tampered with, or the cap set in
/// the method's settings — and passed through the binary's own mapping, which must give the
/// documented exit code, message and hint. tests/errors.rs triggers the same errors and checks
/// their messages; the scenes that do reach the others run the binary there.
#[cfg(test)]
mod tests {
    use super::*;
    use liftoff::method::{ActiveSetSettings, QpSettings, QpSolver};
    use liftoff::{Operators, Problem};

    fn paper(name: &str) -> Problem {
        let text = liftoff::examples::scene(name).unwrap_or_default();
        Problem::from_toml(text).expect("bundled scene")
    }

    /// E27: a factorisation that fails (the plate's K made negative definite).
    #[test]
    fn e27_a_failed_factorisation_exits_4_with_the_numerical_hint() {
        let p = paper("paper-winkler");
        let mut ops = Operators::assemble(&p.model);
        ops.k = std::sync::Arc::new(ops.k.map(|v| -v));
        let e = liftoff::solve(&ops, &Method::Bonded).expect_err("E27: the factorisation fails");
        let f = Failure::solving(e, &Method::Bonded);
        assert_eq!(f.code, exit::SOLVER, "E27: exit code ({})", f.message);
        assert!(
            f.message.contains("numerical failure in")
                && f.message.contains("not positive definite"),
            "E27: message: {}",
            f.message
        );
        assert!(
            f.message
                .ends_with("\nhint: --method qp, or a coarser --mesh"),
            "E27: hint: {}",
            f.message
        );
    }

    /// E28: a non-finite value in a solve (a NaN in the load vector).
    #[test]
    fn e28_a_non_finite_value_exits_4_with_the_numerical_hint() {
        let p = paper("paper-winkler");
        let mut ops = Operators::assemble(&p.model);
        ops.f[0] = f64::NAN;
        let e = liftoff::solve(&ops, &Method::Bonded).expect_err("E28: the solve fails");
        let f = Failure::solving(e, &Method::Bonded);
        assert_eq!(f.code, exit::SOLVER, "E28: exit code ({})", f.message);
        assert!(
            f.message.contains("numerical failure in")
                && f.message.contains("non-finite value at unknown"),
            "E28: message: {}",
            f.message
        );
        assert!(
            f.message
                .ends_with("\nhint: --method qp, or a coarser --mesh"),
            "E28: hint: {}",
            f.message
        );
        // The same failure in a QP names the QP's way out.
        let e = liftoff::solve(&ops, &Method::qp()).expect_err("E28 in the QP");
        let f = Failure::solving(e, &Method::qp());
        assert!(
            f.code == exit::SOLVER
                && f.message
                    .contains("\nhint: --method penalty, or the other --qp-solver"),
            "E28 (QP): {}",
            f.message
        );
    }

    /// E42: the matrix-free QP stopped at its cap of face solves (here 1 instead of 500).
    #[test]
    fn e42_the_active_set_cap_exits_4_with_the_qp_hint() {
        let mut p = paper("paper-halfspace");
        p.method = Method::Qp(QpSettings {
            solver: QpSolver::ActiveSet,
            active_set: ActiveSetSettings {
                max_iterations: 1,
                ..ActiveSetSettings::default()
            },
            ..QpSettings::default()
        });
        let a = liftoff::analyse(&p).expect("E42: the capped QP runs");
        assert!(
            !a.summary.converged,
            "E42: one face solve cannot settle the contact set"
        );
        let f = Failure::not_converged(&a, &p.method);
        assert_eq!(f.code, exit::SOLVER, "E42: exit code ({})", f.message);
        assert!(
            f.message
                .contains("not converged: the penalised set was still changing after 1 iterations"),
            "E42: message: {}",
            f.message
        );
        assert!(
            f.message.ends_with("\nhint: --method penalty solves the same operators by the paper's iteration, or try the other --qp-solver where it applies"),
            "E42: hint: {}",
            f.message
        );
    }
}
