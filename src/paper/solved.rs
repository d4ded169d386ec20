//! A solved case of the paper: what [`super::run`] produces and [`super::figures`] draws.

use super::cases::Case;
use super::PaperRun;
use crate::post::Report;

/// A solved case: its numbers and, for the drawing, its fields.
pub(super) struct Solved {
    pub(super) case: Case,
    pub(super) run: PaperRun,
    pub(super) report: Report,
}
