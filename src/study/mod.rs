//! The studies that run many solves of one validated [`crate::Problem`]: of the methods — the
//! penalty limit ε̄ → 0 against the QP (`eps-sweep`), speed against accuracy over meshes
//! (`tradeoff`), the regimes where each method breaks (`stability`) — and of the loads: the
//! critical position of a vehicle (`critical`).
//!
//! Every study assembles its operators once per model and hands the same value to every solve,
//! so differences between methods are differences of method, never of discretisation. Each has
//! the same shape: options with `validate()` and `run(&problem, &monitor)`, the monitor's
//! [`crate::monitor::Cases`] counting its solves and able to stop them, and a result struct that
//! serialises and that the `output` module writes.
//!
//! Layout: `eps_sweep.rs`, `tradeoff.rs`, `stability.rs` and `critical.rs` hold one study each
//! (`critical.rs` with its options in `critical_grid.rs` and its mirror images in
//! `mirror.rs`), `options.rs` the validated options the CLI builds the
//! method studies from.

use crate::error::ErrorKind;
use crate::solve::StatusKind;

mod critical;
mod critical_grid;
mod critical_result;
mod damage;
mod damage_part;
mod damage_pass;
mod damage_result;
mod damage_sum;
mod design;
mod ends;
mod eps_sweep;
mod erosion;
mod mirror;
mod options;
mod stability;
mod tradeoff;
mod warm;

pub use crate::layout::Ends;
pub use critical::{
    critical, critical_points, critical_positions, Along, Critical, CriticalOptions, Edge,
    Footprint, JointLine, Position,
};
pub use damage::{
    damage, damage_families, damage_merge, damage_part, Cracking, Damage, Governing, Pass,
    PassErosion, Peak,
};
pub use damage_part::DamagePart;
pub use design::{design, Design, DesignOptions, DesignPoint};
pub use eps_sweep::{eps_sweep, Sweep, SweepRow};
pub use erosion::{Corner, CornerDamage, Erosion};
pub use options::{ConstraintVariants, EpsSweepOptions, TradeoffOptions};
pub use stability::{
    stability_plan, stability_run, stability_sweep, StabilityCase, StabilityParam, StabilityRow,
    DEFAULT_BASES,
};
pub use tradeoff::{tradeoff, Tradeoff, TradeoffPoint};

/// How one run of a study ended: the status of a solve that ran, or the kind of the error that
/// stopped it (written as its name: "converged", "penalty-too-weak", "infeasible", …).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(untagged)]
pub enum RunOutcome {
    /// The solve ran and ended so.
    Solved(StatusKind),
    /// An error stopped it.
    Failed(ErrorKind),
}

impl RunOutcome {
    /// The converged outcome.
    pub const CONVERGED: RunOutcome = RunOutcome::Solved(StatusKind::Converged);

    /// Name as the CSV files write it.
    pub fn name(self) -> &'static str {
        match self {
            RunOutcome::Solved(k) => k.name(),
            RunOutcome::Failed(k) => k.name(),
        }
    }
}

impl std::fmt::Display for RunOutcome {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.pad(self.name())
    }
}

/// Logarithmically spaced values from `from` to `to` (inclusive), `points` ≥ 2 of them.
pub fn log_space(from: f64, to: f64, points: usize) -> Vec<f64> {
    let n = points.max(2);
    let (a, b) = (from.log10(), to.log10());
    (0..n)
        .map(|k| 10f64.powf(a + (b - a) * k as f64 / (n - 1) as f64))
        .collect()
}
