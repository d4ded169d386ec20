//! Bonded (bilateral) contact: the gap vanishes, g = T σ − Bᵀ u = 0, and the foundation may
//! pull. It is the first step of the paper's penalty iteration and the reference of its Fig. 7.
//!
//! Winkler (B, T diagonal): σ = T⁻¹ Bᵀ u and (K + B T⁻¹ Bᵀ) u = f, a sparse SPD system.
//!
//! Half-space: with K⁻ a generalised inverse of the free plate and R its rigid modes,
//! u = K⁻(f − Bσ) + Rα, and the gap and the rigid-body equilibrium Rᵀ(f − Bσ) = 0 give
//!
//! [ S   −C ] [σ]   [ BᵀK⁻f ]
//! [ −Cᵀ  0 ] [α] = [ −Rᵀf  ],   S = T + BᵀK⁻B,  C = BᵀR,
//!
//! solved by a dense Cholesky of S and the small system Cᵀ S⁻¹ C α = Rᵀf − Cᵀ S⁻¹ BᵀK⁻f.

use std::sync::Arc;
use std::time::Instant;

use faer::Mat;

use super::checks::discrete_gap;
use super::linalg::{
    dense_cholesky, diagonal_positions, displacements, dot, finite, lumped_coupling,
    schur_complement, sparse_solve, PlateInverse, SparseCholesky, SpdSolve,
};
use super::rigid_split::{needs_split, RigidSplit};
use super::solution::{Solution, SolveInfo, Status, Timings};
use crate::error::Result;
use crate::foundation::Compliance;
use crate::method::Method;
use crate::monitor::Monitor;
use crate::operators::Operators;

/// Bonded solve.
pub fn solve(ops: &Operators) -> Result<Solution> {
    solve_with(ops, &Monitor::NONE)
}

/// Bonded solve; `monitor`'s flag stops the iterative route's conjugate gradients (the direct
/// routes are one factorisation).
pub fn solve_with(ops: &Operators, monitor: &Monitor<'_>) -> Result<Solution> {
    match ops.t.as_ref() {
        Compliance::Diagonal(t) => solve_springs(ops, t),
        Compliance::Dense(_) => solve_schur(ops),
        Compliance::Toeplitz(_) => solve_iterative(ops, monitor),
    }
}

fn solve_springs(ops: &Operators, t: &[f64]) -> Result<Solution> {
    let t0 = Instant::now();
    let coupling = lumped_coupling(ops)?;
    let springs: Vec<(usize, f64)> = coupling
        .iter()
        .zip(t)
        .map(|(&(eq, b), &tj)| (eq, b * b / tj))
        .collect();
    if needs_split(ops, &springs) {
        // A nearly rigid plate (or springs too soft in one of its rigid modes): its rigid
        // part split off and solved exactly.
        let u = RigidSplit::new(ops)?.solve(ops, &springs, &ops.f)?;
        let sigma: Vec<f64> = coupling
            .iter()
            .zip(t)
            .map(|(&(eq, b), &tj)| b * u[eq] / tj)
            .collect();
        finite(&u, "bonded Winkler solve")?;
        let info = SolveInfo {
            timings: Timings {
                total: t0.elapsed().as_secs_f64(),
                ..Timings::default()
            },
            notes: vec!["a nearly rigid plate on its springs: the rigid-body part solved apart (exact equilibrium)".into()],
            ..SolveInfo::default()
        };
        return Ok(bonded_solution(ops, u, sigma, Vec::new(), info));
    }
    let mut k = (*ops.k).clone();
    let diag = diagonal_positions(&k)?;
    for &(eq, s) in &springs {
        k.data_mut()[diag[eq]] += s;
    }
    let order = crate::mesh::equation_order(&ops.mesh, &ops.dofs, |_| true);
    let chol = SparseCholesky::analyse_ordered(&k, Some(&order))?;
    let t_an = t0.elapsed().as_secs_f64();
    let llt = chol.factor(&k, "bonded Winkler system K + B T⁻¹ Bᵀ")?;
    let t_fac = t0.elapsed().as_secs_f64() - t_an;
    let mut u = ops.f.clone();
    sparse_solve(&llt, &mut u);
    let sigma: Vec<f64> = coupling
        .iter()
        .zip(t)
        .map(|(&(eq, b), &tj)| b * u[eq] / tj)
        .collect();
    finite(&u, "bonded Winkler solve")?;
    let info = SolveInfo {
        timings: Timings {
            analyse: Some(t_an),
            factor: Some(t_fac),
            total: t0.elapsed().as_secs_f64(),
            ..Timings::default()
        },
        ..SolveInfo::default()
    };
    Ok(bonded_solution(ops, u, sigma, Vec::new(), info))
}

/// The load-independent part of the Schur formulation: K⁻, S = T + BᵀK⁻B and C = BᵀR. Formed
/// once per assembly and shared by every method and load combination on it
/// ([`crate::operators::SharedCache`]).
pub struct SchurCore {
    /// Generalised inverse of K.
    pub kinv: PlateInverse,
    /// S = T + BᵀK⁻B.
    pub s: Mat<f64>,
    /// C = BᵀR (n_σ × n_r), column per rigid mode.
    pub c: Vec<Vec<f64>>,
}

/// Quantities of the Schur formulation shared by the bonded half-space solve and the QP: the
/// shared [`SchurCore`] (through `Deref`) and this load's right-hand sides.
pub struct SchurSystem {
    core: Arc<SchurCore>,
    /// h = BᵀK⁻f − g₀.
    pub h: Vec<f64>,
    /// Rᵀf.
    pub rf: Vec<f64>,
    /// Seconds spent factoring K by this call (0 when the core was already formed).
    pub time_plate: f64,
    /// Seconds spent forming S by this call (0 when the core was already formed).
    pub time_schur: f64,
}

impl std::ops::Deref for SchurSystem {
    type Target = SchurCore;
    fn deref(&self) -> &SchurCore {
        &self.core
    }
}

impl SchurSystem {
    /// S and the right-hand sides; S and K⁻ are formed on the first call for these operators
    /// (or any copy made by [`Operators::loaded`]) and reused after.
    pub fn new(ops: &Operators) -> Result<Self> {
        let t0 = Instant::now();
        let mut time_plate = 0.0;
        let (core, fresh) = ops.cache.get_or_try_init(|| -> Result<SchurCore> {
            let kinv = PlateInverse::new(ops)?;
            time_plate = t0.elapsed().as_secs_f64();
            let s = schur_complement(ops, &kinv);
            let c = ops.rigid.iter().map(|r| ops.bt_times(r)).collect();
            Ok(SchurCore { kinv, s, c })
        })?;
        let time_schur = if fresh {
            t0.elapsed().as_secs_f64() - time_plate
        } else {
            0.0
        };
        // h = BᵀK⁻f − g₀: the voids' initial gap enters as g = Sσ − Cα − h.
        let h = ops
            .bt_times(&core.kinv.apply(&ops.f))
            .iter()
            .zip(&ops.gap0)
            .map(|(a, g)| a - g)
            .collect();
        let rf = ops.rigid.iter().map(|r| dot(r, &ops.f)).collect();
        Ok(Self {
            core,
            h,
            rf,
            time_plate,
            time_schur,
        })
    }

    /// Displacements from pressures and rigid amplitudes: u = K⁻(f − Bσ) + Rα.
    pub fn displacements(&self, ops: &Operators, sigma: &[f64], alpha: &[f64]) -> Vec<f64> {
        displacements(ops, &self.kinv, sigma, alpha)
    }
}

/// The solution of a bonded solve: displacements, pressures, their gap and rigid amplitudes.
fn bonded_solution(
    ops: &Operators,
    u: Vec<f64>,
    sigma: Vec<f64>,
    rigid: Vec<f64>,
    info: SolveInfo,
) -> Solution {
    let gap = discrete_gap(ops, &u, &sigma);
    Solution {
        method: Method::Bonded,
        u,
        sigma,
        gap,
        rigid,
        status: Status::Converged,
        iterations: 1,
        history: Vec::new(),
        info,
    }
}

/// Solve [S −C; −Cᵀ 0][σ; α] = [h; −Rᵀf] given a factor of S.
pub fn saddle_solve(
    llt: &impl SpdSolve,
    h: &[f64],
    c: &[Vec<f64>],
    rf: &[f64],
) -> Result<(Vec<f64>, Vec<f64>)> {
    let n = h.len();
    let m = c.len();
    let mut z = Mat::<f64>::from_fn(n, 1, |i, _| h[i]);
    llt.solve_in_place(z.as_mut());
    let mut y = Mat::<f64>::from_fn(n, m, |i, j| c[j][i]);
    llt.solve_in_place(y.as_mut());
    // (Cᵀ Y) α = Rᵀf − Cᵀ z
    let ctyy = Mat::<f64>::from_fn(m, m, |a, b| (0..n).map(|i| c[a][i] * y[(i, b)]).sum());
    let mut rhs = Mat::<f64>::from_fn(m, 1, |a, _| {
        rf[a] - (0..n).map(|i| c[a][i] * z[(i, 0)]).sum::<f64>()
    });
    let small = dense_cholesky(&ctyy, "rigid-body equilibrium (Cᵀ S⁻¹ C)")?;
    small.solve_in_place(rhs.as_mut());
    let alpha: Vec<f64> = (0..m).map(|a| rhs[(a, 0)]).collect();
    let sigma = (0..n)
        .map(|i| z[(i, 0)] + (0..m).map(|a| y[(i, a)] * alpha[a]).sum::<f64>())
        .collect();
    Ok((sigma, alpha))
}

fn solve_schur(ops: &Operators) -> Result<Solution> {
    let t0 = Instant::now();
    let sys = SchurSystem::new(ops)?;
    let t1 = Instant::now();
    let llt = dense_cholesky(&sys.s, "bonded half-space Schur complement")?;
    let t_fac = t1.elapsed().as_secs_f64();
    let (sigma, alpha) = saddle_solve(&llt, &sys.h, &sys.c, &sys.rf)?;
    let u = sys.displacements(ops, &sigma, &alpha);
    finite(&u, "bonded half-space solve")?;
    let info = SolveInfo {
        timings: Timings {
            plate_factor: Some(sys.time_plate),
            schur: Some(sys.time_schur),
            factor: Some(t_fac),
            total: t0.elapsed().as_secs_f64(),
            ..Timings::default()
        },
        ..SolveInfo::default()
    };
    Ok(bonded_solution(ops, u, sigma, alpha, info))
}

/// The bonded half-space by conjugate gradients on the Schur system with a matrix-free T: the
/// penalty iteration's first step ([`super::iterative`]).
fn solve_iterative(ops: &Operators, monitor: &Monitor<'_>) -> Result<Solution> {
    let t0 = Instant::now();
    let mut sys = super::iterative::IterativeSchur::new(ops, Default::default())?;
    let rows: Vec<Vec<(usize, f64)>> = Vec::new();
    let weights: Vec<f64> = Vec::new();
    let super::iterative::Step {
        u,
        sigma,
        alpha,
        cg,
    } = sys.solve(ops, &rows, &weights, None, monitor)?;
    finite(&u, "bonded half-space solve (iterative)")?;
    let info = SolveInfo {
        timings: Timings {
            plate_factor: Some(sys.time_plate),
            total: t0.elapsed().as_secs_f64(),
            ..Timings::default()
        },
        cg_iterations: Some(cg.iterations),
        ..SolveInfo::default()
    };
    Ok(bonded_solution(ops, u, sigma, alpha, info))
}
