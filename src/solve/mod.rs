//! Solution methods and what they return.
//!
//! Every method takes the same [`Operators`](crate::Operators) and returns a [`Solution`]. A
//! method that ran but did not reach an answer returns a `Solution` whose [`Status`] says so;
//! only failures that leave nothing to report (a factorisation breaking down, a problem too
//! large) are errors.
//!
//! This file only declares and re-exports; imports run one way, from the methods down to what
//! they share. `dispatch.rs` picks the method ([`solve`], [`solve_from`]) and `nested.rs` starts
//! the matrix-free QP from a coarser grid ([`solve_nested`]); the methods are `bonded.rs`,
//! `penalty.rs` (its linear steps in `penalty_step.rs`, `spring_factor.rs` (the Winkler factor's
//! updates and its handoff between solves), `low_rank.rs` and the iterative route `iterative/`) and the QP solvers under `qp/`; below them all sit `solution.rs` (what a solve
//! returns), `diagnostics.rs` (what each solver reports), `checks.rs` (feasibility, equilibrium,
//! the discrete gap), `combiner.rs` (concurrent solves served as one batch), `projection.rs` (the projection onto {σ ≥ 0, Cᵀσ = b}: the active-set QP's
//! and the feasibility check's), `linalg.rs` and, on it, `supernodal.rs` (a supernodal factor's
//! triangles one at a time).

pub mod bonded;
mod checks;
mod combiner;
mod diagnostics;
mod dispatch;
pub mod iterative;
pub mod linalg;
pub mod low_rank;
mod nested;
pub mod penalty;
mod penalty_step;
mod projection;
pub mod qp;
pub mod rigid_split;
mod solution;
mod spring_factor;
pub mod supernodal;

pub use checks::{check_equilibrium, check_feasible, discrete_gap, EQUILIBRIUM_TOLERANCE};
pub use diagnostics::{ActiveSetDiagnostics, CgReport, KktResiduals, QpDiagnostics};
pub use dispatch::{solve, solve_carried, solve_from, solve_with, takes_start};
pub use nested::{solve_nested, NESTED_MIN_NODES};
pub use solution::{Iteration, PenaltyStage, Solution, SolveInfo, Status, StatusKind, Timings};
pub use spring_factor::{woodbury_limit, Carry};
