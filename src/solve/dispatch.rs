//! One method on assembled operators: bonded contact directly, unbonded contact (after a
//! feasibility check) by the penalty iteration or the QP, every reaction checked against the load.

use super::checks::{check_equilibrium, check_feasible};
use super::solution::Solution;
use super::spring_factor::Carry;
use super::{bonded, penalty, qp};
use crate::error::{Error, Result};
use crate::foundation::Compliance;
use crate::method::{Method, QpSolver};
use crate::model::ConstraintPoints;
use crate::monitor::Monitor;
use crate::operators::Operators;

/// Solve the assembled operators with a method: bonded contact directly, unbonded contact (after
/// a feasibility check) by the penalty iteration or the QP. Every solution's reaction is
/// checked against the load.
pub fn solve(ops: &Operators, method: &Method) -> Result<Solution> {
    solve_from(ops, method, None)
}

/// Whether `method` on `ops` takes a start ([`solve_from`]): the penalty iteration (its first
/// penalised set) and the matrix-free active-set QP (its first iterate); clarabel and bonded
/// contact do not.
pub fn takes_start(ops: &Operators, method: &Method) -> bool {
    match method {
        Method::Penalty(_) => true,
        Method::Qp(s) => {
            let toeplitz = matches!(ops.t.as_ref(), Compliance::Toeplitz(_));
            s.resolve(ops.foundation, ops.constraints.kind, toeplitz) == QpSolver::ActiveSet
                && ops.constraints.kind == ConstraintPoints::Nodal
        }
        Method::Bonded => false,
    }
}

/// [`solve`], with the nodal pressures `start` as the matrix-free active-set QP's first
/// iterate where it runs ([`takes_start`]) and as the penalty iteration's first penalised set
/// (its lifted points); bonded contact and clarabel ignore it. The answer does not depend on
/// the start (both problems have one solution), only the number of steps does.
pub fn solve_from(ops: &Operators, method: &Method, start: Option<&[f64]>) -> Result<Solution> {
    solve_with(ops, method, start, &Monitor::NONE)
}

/// [`solve_from`], watched by `monitor`: the iterative methods report their steps and stop
/// with [`Error::Cancelled`] when its flag is set (bonded contact and clarabel's
/// interior-point iterations are single runs that finish first).
pub fn solve_with(
    ops: &Operators,
    method: &Method,
    start: Option<&[f64]>,
    monitor: &Monitor<'_>,
) -> Result<Solution> {
    solve_carried(ops, method, start, None, monitor)
}

/// [`solve_with`], where the penalty iteration takes the last factor of the solve before it on
/// the same operators from `carry` and leaves its own there ([`Carry`]); the other methods
/// ignore it.
pub fn solve_carried(
    ops: &Operators,
    method: &Method,
    start: Option<&[f64]>,
    carry: Option<&Carry>,
    monitor: &Monitor<'_>,
) -> Result<Solution> {
    method.validate()?;
    let sol = match method {
        Method::Bonded => {
            if ops.gap0.iter().any(|&g| g != 0.0) {
                return Err(Error::Unsupported(
                    "voids need unbonded contact: bonded contact would glue the plate to the lowered soil surface".into(),
                ));
            }
            bonded::solve_with(ops, monitor)?
        }
        Method::Penalty(settings) => {
            check_feasible(ops)?;
            penalty::solve_carried(ops, settings, start, carry, monitor)?
        }
        Method::Qp(settings) => {
            check_feasible(ops)?;
            qp::solve_qp(ops, settings, start, monitor)?
        }
    };
    check_equilibrium(ops, &sol)?;
    Ok(sol)
}
