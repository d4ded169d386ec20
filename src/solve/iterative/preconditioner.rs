//! The preconditioner of the projected PCG for one penalised set (and held set): the plate on
//! springs or on a shear layer ([`super::springs`], [`super::shear_layer`]) with the penalty's
//! diagonal, and the projections that keep the iterates on the equilibrium.

use super::shear_layer::{self, ShearLayer};
use super::springs::{SpringPlate, Springs};
use crate::error::Result;
use crate::solve::linalg::{dot, SmallSpd, SparseFactor};

/// The preconditioner of one penalised set (and held set).
#[derive(Clone)]
pub(super) struct Preconditioner {
    /// The foundation W (W_jj = 0 on held points).
    pub(super) w: Springs,
    /// Factor of K_r + Q W Qᵀ.
    pub(super) factor: SparseFactor,
    /// The rigid-mode columns C restricted to the free points.
    pub(super) c: Vec<Vec<f64>>,
    /// M⁻¹ C, one column per rigid mode.
    pub(super) minv_c: Vec<Vec<f64>>,
    /// F⁻¹QD⁻¹C on the plate's reduced equations (column-major), the plate's part of M⁻¹C.
    pub(super) plate_c: Vec<f64>,
    /// Pseudo-inverse of Cᵀ M⁻¹ C.
    pub(super) small: SmallSpd,
    /// Pseudo-inverse of Cᵀ C.
    pub(super) ctc: SmallSpd,
    /// The held points it was made for (empty: none; else one flag per pressure node).
    pub(super) held: Vec<bool>,
    /// The penalty weights it was made for (empty: none).
    pub(super) weights: Vec<f64>,
    /// √(hᵀ P M⁻¹ h) on its free points, the CG's reference (computed on first use).
    pub(super) scale: Option<f64>,
}

impl Preconditioner {
    /// The preconditioner for penalty weights on `rows` and the points `held` at zero (empty:
    /// none) on the plate `springs`: its foundation the shear `layer` where one is fitted,
    /// springs `spring_scale`·diag(T) otherwise ([`shear_layer::springs`]).
    pub(super) fn new(
        springs: &SpringPlate,
        (t_diag, spring_scale): (&[f64], f64),
        layer: Option<&ShearLayer>,
        c_full: &[Vec<f64>],
        (rows, weights): (&Rows, &[f64]),
        held: &[bool],
    ) -> Result<Self> {
        let mut pen = vec![0.0; t_diag.len()];
        for (k, &w) in weights.iter().enumerate() {
            if w != 0.0 {
                for &(i, v) in &rows[k] {
                    pen[i] += w * v * v;
                }
            }
        }
        let is_held = |i: usize| held.get(i).copied().unwrap_or(false);
        let w = shear_layer::springs(springs, layer, (t_diag, spring_scale), &pen, is_held);
        let factor = springs.factor(&w)?;
        let c: Vec<Vec<f64>> = c_full
            .iter()
            .map(|col| {
                col.iter()
                    .enumerate()
                    .map(|(i, &v)| if is_held(i) { 0.0 } else { v })
                    .collect()
            })
            .collect();
        let (minv_c, plate_c) = springs.solve_many(&w, &factor, &c);
        let m = c.len();
        let small = SmallSpd::new(m, |a, b| dot(&c[a], &minv_c[b]));
        let ctc = SmallSpd::new(m, |a, b| dot(&c[a], &c[b]));
        Ok(Self {
            w,
            factor,
            c,
            minv_c,
            plate_c,
            small,
            ctc,
            held: held_key(held),
            weights: key(weights),
            scale: None,
        })
    }

    /// Whether it was made for these weights and held points.
    pub(super) fn fits(&self, weights: &[f64], held: &[bool]) -> bool {
        self.weights == key(weights) && self.held == held_key(held)
    }

    /// The projected preconditioned residual: M⁻¹r − M⁻¹C (CᵀM⁻¹C)⁻¹ CᵀM⁻¹r, which satisfies
    /// Cᵀz = 0. The projection is applied twice: the second pass removes the round-off of the
    /// first (Gould, Hribar & Nocedal's iterative refinement), which otherwise lets Cᵀσ drift.
    /// `springs` is the plate it was made on.
    pub(super) fn project(&self, springs: &SpringPlate, r: &[f64]) -> Vec<f64> {
        let mut z = springs.solve(&self.w, &self.factor, r);
        for _ in 0..2 {
            let ctz: Vec<f64> = self.c.iter().map(|c| dot(c, &z)).collect();
            let s = self.small.solve(&ctz);
            for (a, &sa) in s.iter().enumerate() {
                for (zi, ci) in z.iter_mut().zip(&self.minv_c[a]) {
                    *zi -= sa * ci;
                }
            }
        }
        z
    }

    /// r − C (CᵀC)⁻¹ Cᵀ r: the residual without its component along C, which the multiplier α
    /// absorbs. The projected preconditioner ignores that component in exact arithmetic, but it
    /// is large (Cα) and would cancel the digits of rᵀz.
    pub(super) fn deflate(&self, r: &mut [f64]) {
        for _ in 0..2 {
            let ctr: Vec<f64> = self.c.iter().map(|c| dot(c, r)).collect();
            let s = self.ctc.solve(&ctr);
            for (a, &sa) in s.iter().enumerate() {
                for (ri, ci) in r.iter_mut().zip(&self.c[a]) {
                    *ri -= sa * ci;
                }
            }
        }
    }

    /// Zero the held points of `v`.
    pub(super) fn mask(&self, v: &mut [f64]) {
        for (x, &h) in v.iter_mut().zip(&self.held) {
            if h {
                *x = 0.0;
            }
        }
    }
}

/// Held points as a cache key: none and all-free are the same.
fn held_key(held: &[bool]) -> Vec<bool> {
    if held.iter().any(|&h| h) {
        held.to_vec()
    } else {
        Vec::new()
    }
}

/// Penalty weights as a cache key: no weights and all-zero weights are the same.
fn key(weights: &[f64]) -> Vec<f64> {
    if weights.iter().all(|&w| w == 0.0) {
        Vec::new()
    } else {
        weights.to_vec()
    }
}

/// The constraint rows g_k of the penalty, as sparse (node, weight) lists.
type Rows = [Vec<(usize, f64)>];
