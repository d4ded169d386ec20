//! Ctrl-C (SIGINT), SIGTERM and SIGHUP: the first sets the cancel flag of the monitor every long
//! subcommand runs under ([`crate::progress::with_progress`]), so the library's loops stop at
//! their next check with [`liftoff::Error::Cancelled`]; the subcommand then writes nothing, and
//! the binary says `interrupted: …` and exits with [`crate::failure::exit::INTERRUPTED`] (130,
//! 128 + SIGINT). A second signal exits at once with the same code.

use std::sync::atomic::Ordering;

use crate::failure::{exit, Failure};
use crate::progress::CANCEL;

/// Install the handler, once, before any subcommand runs. Where it cannot be installed (a
/// handler already is: not the case in this binary) the signals keep their default action and
/// end the process as before.
pub(crate) fn install() {
    // A signal while files are drawn and staged discards them instead of moving them in.
    liftoff::output::cancel_writes_with(&CANCEL);
    let _ = ctrlc::set_handler(|| {
        if CANCEL.swap(true, Ordering::SeqCst) {
            crate::progress::note(
                "interrupted again: exiting at once (a hidden .liftoff-staging folder may be left in --out if files were being written)",
            );
            std::process::exit(i32::from(exit::INTERRUPTED));
        }
        crate::progress::note(
            "interrupting: stopping at the next check, nothing will be written (press Ctrl-C again to exit at once)",
        );
    });
}

/// Whether a signal asked the run to stop.
pub(crate) fn requested() -> bool {
    CANCEL.load(Ordering::SeqCst)
}

/// Before writing a subcommand's files: stop (writing nothing) when a signal arrived after the
/// library's last check.
pub(crate) fn check() -> Result<(), Failure> {
    if requested() {
        Err(Failure::interrupted("before the files were written"))
    } else {
        Ok(())
    }
}
