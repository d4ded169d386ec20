//! Progress bars (indicatif) drawn from the library's [`liftoff::Progress`] events.

use liftoff::Monitor;

/// Run a library call under a progress bar drawn from its [`liftoff::Progress`] events (on a
/// terminal only): the cases done of a run over several (combinations, a study's solves), the
/// steps of one long solve. With `log`, every case's label is also printed as a line.
pub(crate) fn with_progress<T>(log: bool, run: impl FnOnce(&Monitor<'_>) -> T) -> T {
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
