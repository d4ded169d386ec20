//! A nearly rigid plate on soft springs (a base plate on grout, Γ_w ≳ 1e4): (K + S) u = f with
//! its rigid-body part split off and solved exactly.
//!
//! The springs S hold the plate's rigid modes R with a stiffness 1e-12 of its bending stiffness
//! or less. Factored as one matrix, K + S loses those digits where they matter: K's rows sum to
//! zero only to round-off (K R ≈ 1e-16 |K| |R|), and that error, multiplied by the large rigid
//! displacements, is as large as the springs' reaction — which then misses the load by 1e-6 to
//! 1e-2. With u = R α + v, v zero on the equations `fixed` that define K⁻ (one per mode), the
//! rows of those equations replaced by the modes' equilibrium Rᵀ(f − S u) = 0 (exact, since
//! Rᵀ K = 0), and the others K_ff v_f + S_f (v + R α)_f = f_f:
//!
//! M = K_ff + S_f (well conditioned: the plate held at its fixed points), y₀ = M⁻¹ f_f,
//! Y_a = M⁻¹ (S R_a)_f, and the m × m system
//! (Rᵀ S R − (S R)_fᵀ Y) α = Rᵀ f − (S R)_fᵀ y₀, then v_f = y₀ − Y α.
//!
//! The reaction then balances the load to the round-off of the small system.

use super::linalg::{diagonal_positions, reduce, sparse_solve, SmallSpd, SparseCholesky};
use crate::error::Result;
use crate::operators::Operators;

/// The springs add up to less than this — in the unit system, where the plate's rigidity D and
/// half-length L are 1, so that the springs of a Winkler soil add up to about 4/Γ_w — before
/// the split is used: from Γ_w ≈ 1e4. The plain factorisation of K + S meets the 1e-6
/// equilibrium check there (the paper's plate misses it by 7e-8 at Γ_w = 1e4) and fails two
/// decades later (7e-6 at 1e6); the split holds at any Γ_w. A thin plate on ordinary springs
/// keeps the plain factorisation however large its shear stiffness.
pub const NEAR_RIGID: f64 = 4e-4;

/// The springs' total stiffness in the unit system (compared with [`NEAR_RIGID`]).
pub fn spring_total(springs: &[(usize, f64)]) -> f64 {
    springs.iter().map(|&(_, s)| s.abs()).sum()
}

/// The springs' stiffness in the plate's softest rigid mode, in the unit system: the smallest
/// eigenvalue of G_ab = Σ_j s_j r_a r_b over the springs (equation, stiffness), r the rigid
/// modes at their equations (w = 1, x, y). A uniform bed of total S on the unit square gives
/// S/3 (the rotations); a bed whose springs are all soft but one (the penalty's lifted points
/// around a plate balanced on one node) holds its rotations about that node by the soft
/// springs alone, however stiff the one: K + S then loses its rigid digits as a soft bed does.
pub fn weakest_mode(ops: &Operators, springs: &[(usize, f64)]) -> f64 {
    let m = ops.rigid.len();
    // One pass over the springs (the modes' values at an equation read together).
    let mut g = nalgebra::DMatrix::<f64>::zeros(m, m);
    let mut r = vec![0.0; m];
    for &(eq, s) in springs {
        for (a, mode) in ops.rigid.iter().enumerate() {
            r[a] = mode[eq];
        }
        for a in 0..m {
            for b in 0..=a {
                g[(a, b)] += s * r[a] * r[b];
            }
        }
    }
    for a in 0..m {
        for b in 0..a {
            g[(b, a)] = g[(a, b)];
        }
    }
    g.symmetric_eigenvalues()
        .iter()
        .cloned()
        .fold(f64::INFINITY, f64::min)
}

/// Whether (K + S) u = f needs the split solve: the springs in total ([`NEAR_RIGID`]) or in the
/// weakest rigid mode ([`weakest_mode`], against a third of it, the rotations' share on a
/// uniform bed) soft against the plate.
pub fn needs_split(ops: &Operators, springs: &[(usize, f64)]) -> bool {
    spring_total(springs) < NEAR_RIGID || weakest_mode(ops, springs) < NEAR_RIGID / 3.0
}

/// K with the fixed equations removed, analysed once; its numeric factor per set of springs.
pub struct RigidSplit {
    kr: sprs::CsMat<f64>,
    base: Vec<f64>,
    diag: Vec<usize>,
    map: Vec<Option<usize>>,
    chol: SparseCholesky,
}

impl RigidSplit {
    /// Analyse K_ff of `ops`.
    pub fn new(ops: &Operators) -> Result<Self> {
        let (kr, map) = reduce(&ops.k, &ops.fixed);
        let order = crate::mesh::equation_order(&ops.mesh, &ops.dofs, |e| map[e].is_some());
        let chol = SparseCholesky::analyse_ordered(&kr, Some(&order))?;
        let diag = diagonal_positions(&kr)?;
        let base = kr.data().to_vec();
        Ok(Self {
            kr,
            base,
            diag,
            map,
            chol,
        })
    }

    /// u of (K + S) u = f, S the springs `springs` (equation, stiffness) on their w equations.
    pub fn solve(
        &mut self,
        ops: &Operators,
        springs: &[(usize, f64)],
        f: &[f64],
    ) -> Result<Vec<f64>> {
        let n_red = self.kr.rows();
        self.kr.data_mut().copy_from_slice(&self.base);
        for &(eq, s) in springs {
            if let Some(r) = self.map[eq] {
                self.kr.data_mut()[self.diag[r]] += s;
            }
        }
        let llt = self
            .chol
            .factor(&self.kr, "near-rigid plate on springs (K_ff + S_f)")?;
        let restrict = |v: &[f64]| -> Vec<f64> {
            let mut out = vec![0.0; n_red];
            for (e, &x) in v.iter().enumerate() {
                if let Some(r) = self.map[e] {
                    out[r] = x;
                }
            }
            out
        };
        // S R_a over every equation (S acts on the springs' equations only).
        let m = ops.rigid.len();
        let sr: Vec<Vec<f64>> = ops
            .rigid
            .iter()
            .map(|r| {
                let mut v = vec![0.0; f.len()];
                for &(eq, s) in springs {
                    v[eq] += s * r[eq];
                }
                v
            })
            .collect();
        let mut y0 = restrict(f);
        sparse_solve(&llt, &mut y0);
        let ys: Vec<Vec<f64>> = sr
            .iter()
            .map(|v| {
                let mut y = restrict(v);
                sparse_solve(&llt, &mut y);
                y
            })
            .collect();
        let srf: Vec<Vec<f64>> = sr.iter().map(|v| restrict(v)).collect();
        let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
        let g = |a: usize, b: usize| dot(&ops.rigid[a], &sr[b]) - dot(&srf[a], &ys[b]);
        let rhs: Vec<f64> = (0..m)
            .map(|a| dot(&ops.rigid[a], f) - dot(&srf[a], &y0))
            .collect();
        let alpha = SmallSpd::new(m, g).solve(&rhs);
        let mut v = y0;
        for (y, &a) in ys.iter().zip(&alpha) {
            for (vi, yi) in v.iter_mut().zip(y) {
                *vi -= a * yi;
            }
        }
        let mut u = vec![0.0; f.len()];
        for (e, slot) in u.iter_mut().enumerate() {
            let rigid: f64 = ops.rigid.iter().zip(&alpha).map(|(r, a)| r[e] * a).sum();
            *slot = rigid + self.map[e].map_or(0.0, |r| v[r]);
        }
        Ok(u)
    }
}
