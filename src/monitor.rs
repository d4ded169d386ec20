//! Watching and stopping long runs: one [`Monitor`] that every long loop of the library takes —
//! penalty steps, the active-set QP's face solves, conjugate-gradient iterations, study cases,
//! combinations, sweeps. It carries an optional cancel flag, which the loops check between
//! iterations (a set flag ends the run with [`Error::Cancelled`]), and an optional progress
//! callback, which they call with a [`Progress`] event. The command line draws its progress
//! bars from these events; the Python binding sets the flag from Ctrl-C.
//!
//! A monitor costs one relaxed atomic load per check when it has a flag and nothing when it
//! has none ([`Monitor::NONE`]).

use std::sync::atomic::{AtomicBool, Ordering};

use crate::error::{Error, Result};

/// What a long loop reports.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Progress<'a> {
    /// A run over several cases (a study's solves, the combinations, the positions of a
    /// load) has finished `done` of its `total` cases; `label` names the case it has just
    /// started (sequential runs) or finished (parallel runs).
    Case {
        /// Cases finished so far.
        done: usize,
        /// Cases in the run.
        total: usize,
        /// The case started or finished.
        label: &'a str,
    },
    /// One step of an iterative method inside a solve: a penalty step, an active-set face
    /// solve. `step` counts from 1; `changes` is how many constraint points changed set.
    Step {
        /// Which method's step.
        method: StepKind,
        /// Step number.
        step: usize,
        /// Points that entered or left the set in this step.
        changes: usize,
    },
}

/// Which iteration a [`Progress::Step`] belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StepKind {
    /// A linear solve of the penalty iteration.
    Penalty,
    /// A solve on the free set of the active-set QP.
    ActiveSet,
}

crate::choice::names!(StepKind, Penalty => "penalty step", ActiveSet => "active-set face solve");

/// A cancel flag and a progress callback, either optional; passed by reference down every
/// long loop.
#[derive(Clone, Copy, Default)]
pub struct Monitor<'a> {
    cancel: Option<&'a AtomicBool>,
    progress: Option<&'a (dyn Fn(Progress<'_>) + Sync)>,
}

impl std::fmt::Debug for Monitor<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Monitor")
            .field("cancel", &self.cancel)
            .field("progress", &self.progress.is_some())
            .finish()
    }
}

impl<'a> Monitor<'a> {
    /// No flag, no callback: runs to the end silently.
    pub const NONE: Monitor<'static> = Monitor {
        cancel: None,
        progress: None,
    };

    /// This monitor, stopping the run when `flag` is set.
    pub fn with_cancel(self, flag: &'a AtomicBool) -> Self {
        Monitor {
            cancel: Some(flag),
            ..self
        }
    }

    /// This monitor, calling `callback` with every progress event (from any thread).
    pub fn with_progress(self, callback: &'a (dyn Fn(Progress<'_>) + Sync)) -> Self {
        Monitor {
            progress: Some(callback),
            ..self
        }
    }

    /// This monitor without its progress callback (its flag kept): for the solves inside a run
    /// of many cases, whose steps would drown the cases' progress.
    pub fn quiet(self) -> Self {
        Monitor {
            progress: None,
            ..self
        }
    }

    /// Whether this monitor has a cancel flag at all (a loop that must set up something to
    /// watch the flag — clarabel's callback — skips it without one).
    pub fn can_cancel(&self) -> bool {
        self.cancel.is_some()
    }

    /// Whether the caller asked the run to stop.
    pub fn cancelled(&self) -> bool {
        self.cancel.is_some_and(|f| f.load(Ordering::Relaxed))
    }

    /// `Err(Error::Cancelled)` naming `during` once the flag is set; loops call it between
    /// iterations.
    pub fn check(&self, during: &str) -> Result<()> {
        if self.cancelled() {
            Err(Error::Cancelled(during.to_string()))
        } else {
            Ok(())
        }
    }

    /// Report an event to the callback, if there is one.
    pub fn report(&self, event: Progress<'_>) {
        if let Some(f) = self.progress {
            f(event);
        }
    }
}

/// The cases of a run, counted for its [`Progress::Case`] events: [`Cases::start`] before each
/// case (or [`Cases::finish`] after it) reports how many are done and checks the cancel flag.
pub struct Cases<'m, 'a> {
    monitor: &'m Monitor<'a>,
    total: usize,
    started: std::sync::atomic::AtomicUsize,
}

impl<'m, 'a> Cases<'m, 'a> {
    /// A run of `total` cases watched by `monitor`.
    pub fn new(monitor: &'m Monitor<'a>, total: usize) -> Self {
        Cases {
            monitor,
            total,
            started: std::sync::atomic::AtomicUsize::new(0),
        }
    }

    /// Before a case: stop if cancelled, else report the cases done so far and this one's
    /// label.
    pub fn start(&self, label: &str) -> Result<()> {
        self.monitor.check(label)?;
        let done = self.started.fetch_add(1, Ordering::Relaxed);
        self.monitor.report(Progress::Case {
            done,
            total: self.total.max(done + 1),
            label,
        });
        Ok(())
    }

    /// After a case (runs that report what each case found, or run cases in parallel): count
    /// it done and report it with its label; then stop if cancelled.
    pub fn finish(&self, label: &str) -> Result<()> {
        let done = self.started.fetch_add(1, Ordering::Relaxed) + 1;
        self.monitor.report(Progress::Case {
            done,
            total: self.total.max(done),
            label,
        });
        self.monitor.check(label)
    }

    /// The monitor for the solves inside a case: the flag without the progress callback.
    pub fn inner(&self) -> Monitor<'a> {
        self.monitor.quiet()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Mutex;

    #[test]
    fn a_set_flag_cancels_and_names_the_loop() {
        let flag = AtomicBool::new(false);
        let m = Monitor::NONE.with_cancel(&flag);
        assert!(
            m.check("penalty step 3").is_ok(),
            "an unset flag lets the loop go on"
        );
        flag.store(true, Ordering::Relaxed);
        match m.check("penalty step 4") {
            Err(Error::Cancelled(during)) => assert_eq!(during, "penalty step 4"),
            other => panic!("expected Cancelled, got {other:?}"),
        }
        assert!(Monitor::NONE.check("x").is_ok(), "no flag never cancels");
    }

    #[test]
    fn events_reach_the_callback_and_quiet_drops_them() {
        let seen = Mutex::new(Vec::new());
        let record = |p: Progress<'_>| {
            if let Ok(mut v) = seen.lock() {
                v.push(format!("{p:?}"));
            }
        };
        let m = Monitor::NONE.with_progress(&record);
        m.report(Progress::Case {
            done: 1,
            total: 2,
            label: "a",
        });
        m.quiet().report(Progress::Case {
            done: 2,
            total: 2,
            label: "b",
        });
        let v = seen.lock().map(|v| v.clone()).unwrap_or_default();
        assert_eq!(v.len(), 1, "quiet() drops events: {v:?}");
        assert!(v[0].contains("label: \"a\""), "{v:?}");
    }
}
