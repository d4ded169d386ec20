//! The iteration's bookkeeping, shared by its two phases: the counters and history, one
//! counted and checked face solve, one recorded step.

use super::point::Point;
use crate::error::{Error, Result};
use crate::method::ActiveSetSettings;
use crate::monitor::{Monitor, Progress, StepKind};
use crate::operators::Operators;
use crate::solve::diagnostics::{CgReport, KktResiduals};
use crate::solve::iterative::{Face, IterativeSchur};
use crate::solve::linalg::finite;
use crate::solve::solution::{Iteration, Status};

/// How a phase of the iteration ended: the point, its multiplier, its KKT residuals, status.
pub(super) type End = (Point, Vec<f64>, KktResiduals, Status);

/// The iteration's bookkeeping.
pub(super) struct Run<'m> {
    pub(super) settings: ActiveSetSettings,
    /// Watches the face solves: progress after each, the cancel flag before each and inside
    /// its conjugate gradients.
    monitor: Monitor<'m>,
    pub(super) history: Vec<Iteration>,
    /// Face solves so far.
    pub(super) iterations: usize,
    pub(super) projected_steps: usize,
    pub(super) safeguard_steps: usize,
    pub(super) cg_total: usize,
}

/// The refusal when no feasible point exists.
pub(super) fn infeasible() -> Error {
    Error::Infeasible(
        "no non-negative pressure balances the loads (the load resultant lies outside the reach of the plate's nodal pressures)".into(),
    )
}

impl<'m> Run<'m> {
    /// Nothing done yet.
    pub(super) fn new(settings: ActiveSetSettings, monitor: Monitor<'m>) -> Self {
        Self {
            settings,
            monitor,
            history: Vec::new(),
            iterations: 0,
            projected_steps: 0,
            safeguard_steps: 0,
            cg_total: 0,
        }
    }

    /// One face solve to relative residual `tol`, counted and checked.
    pub(super) fn face(
        &mut self,
        sys: &mut IterativeSchur,
        ops: &Operators,
        held: &[bool],
        start: &[f64],
        tol: f64,
    ) -> Result<Face> {
        self.monitor.check("the matrix-free QP")?;
        let face = sys.solve_face(ops, held, start, tol, &self.monitor)?;
        finite(&face.sigma, "matrix-free QP")?;
        self.cg_total += face.cg.iterations;
        self.iterations += 1;
        Ok(face)
    }

    /// Record a step: the points at zero after it, against those before.
    pub(super) fn record(&mut self, before: &[bool], after: &[bool], min_sigma: f64, cg: CgReport) {
        self.history.push(Iteration {
            step: self.iterations,
            epsilon: 0.0,
            penalised: after.iter().filter(|&&b| b).count(),
            entered: after
                .iter()
                .zip(before)
                .filter(|(a, b)| **a && !**b)
                .count(),
            left: after
                .iter()
                .zip(before)
                .filter(|(a, b)| !**a && **b)
                .count(),
            min_pressure: min_sigma,
            cg: Some(cg),
        });
        if let Some(step) = self.history.last() {
            self.monitor.report(Progress::Step {
                method: StepKind::ActiveSet,
                step: step.step,
                changes: step.entered + step.left,
            });
        }
    }
}
