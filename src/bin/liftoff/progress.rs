//! Progress bars (indicatif) drawn from the library's [`liftoff::Progress`] events.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;
use std::time::Duration;

use liftoff::Monitor;

/// The cancel flag of every run's monitor: set by the first Ctrl-C (`interrupt.rs`), read by the
/// library's loops.
pub(crate) static CANCEL: AtomicBool = AtomicBool::new(false);

/// A run shorter than this draws no bar at all.
const QUIET: Duration = Duration::from_millis(500);

/// The bar being drawn, for [`note`] (the signal handler's thread).
static BAR: Mutex<Option<indicatif::ProgressBar>> = Mutex::new(None);

/// Print a line on stderr without tearing the progress bar (the bar is redrawn below it).
pub(crate) fn note(line: &str) {
    let bar = BAR.lock().ok().and_then(|b| b.clone());
    match bar {
        Some(pb) => pb.suspend(|| eprintln!("{line}")),
        None => eprintln!("{line}"),
    }
}

/// Run a library call under a progress bar drawn from its [`liftoff::Progress`] events (on a
/// terminal only): the cases done of a run over several (combinations, a study's solves), the
/// steps of one long solve. With `log`, every case's label is also printed as a line. The run's
/// monitor carries the cancel flag [`CANCEL`], which Ctrl-C sets (`interrupt.rs`); the bar is cleared however
/// the run ends.
pub(crate) fn with_progress<T>(log: bool, run: impl FnOnce(&Monitor<'_>) -> T) -> T {
    // Hidden until the run has taken QUIET: a quick solve shows no flash of a bar.
    let pb =
        indicatif::ProgressBar::with_draw_target(None, indicatif::ProgressDrawTarget::hidden());
    let shown = AtomicBool::new(false);
    let show = || {
        if !shown.load(Ordering::Relaxed) && pb.elapsed() >= QUIET {
            shown.store(true, Ordering::Relaxed);
            pb.set_draw_target(indicatif::ProgressDrawTarget::stderr());
        }
    };
    let bar = indicatif::ProgressStyle::with_template(
        "{bar:30} {pos}/{len} {elapsed_precise}, about {eta} left {msg}",
    )
    .ok();
    if let Ok(style) = indicatif::ProgressStyle::with_template("{spinner} {elapsed_precise} {msg}")
    {
        pb.set_style(style);
    }
    let draw = |p: liftoff::Progress<'_>| match p {
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
                // A hidden bar prints nothing, its println included.
                if shown.load(Ordering::Relaxed) {
                    pb.println(label);
                } else {
                    eprintln!("{label}");
                }
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
    let report = |p: liftoff::Progress<'_>| {
        show();
        draw(p)
    };
    if let Ok(mut b) = BAR.lock() {
        *b = Some(pb.clone());
    }
    let monitor = Monitor::NONE.with_cancel(&CANCEL).with_progress(&report);
    let result = run(&monitor);
    if let Ok(mut b) = BAR.lock() {
        *b = None;
    }
    pb.finish_and_clear();
    result
}
