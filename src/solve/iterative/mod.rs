//! The half-space penalty step without dense matrices: preconditioned conjugate gradients on the
//! Schur system with the rigid-body equilibrium as constraints.
//!
//! Each step of the penalty iteration (and the bonded solve, its first step) solves
//!
//! A σ − C α = h,   Cᵀ σ = Rᵀ f,   A = T + BᵀK⁻B + Σ_k d_k g_k g_kᵀ,
//!
//! (h = BᵀK⁻f − g₀ with the voids' initial gap g₀, C = BᵀR, d_k = c w_k/ε̄ on the penalised points, [`super::bonded`]). A is never
//! formed: a product costs one FFT product with T ([`crate::foundation::fft`]), one solve with the
//! plate factor (K factored once with its rigid modes fixed, [`PlateInverse`](crate::solve::linalg::PlateInverse)) and the sparse
//! penalty. The equality is kept by projected CG (Gould, Hribar & Nocedal 2001): the iterates
//! stay on Cᵀσ = Rᵀf, the preconditioned residual is projected onto Cᵀp = 0 in the
//! preconditioner's inner product, and α is the least-squares multiplier of the final residual.
//! On that subspace BᵀK⁻B does not depend on which generalised inverse K⁻ is (Bp is orthogonal to
//! the rigid modes), so the iteration sees the true plate compliance.
//!
//! **Preconditioner: the plate on a sparse foundation** ([`springs`]): M = W⁻¹ + QᵀK_p⁻Q with
//! W, on a continuum soil, springs and a shear layer fitted to T's symbol (`shear_layer`: it
//! falls with T's 1/|ξ| where T dominates A, which springs cannot), springs 1/(λ t_jj + d_j)
//! on the penalised points (the penalty's diagonal), and K_p the plate — by default on a grid
//! twice as coarse. M holds the plate exactly at the long wavelengths where it dominates A (its
//! free edges and its low modes) and the penalty exactly where it is diagonal (nodal
//! constraints), so only the half-space's non-local part is left to the iteration; M⁻¹ is one
//! sparse solve. Without the layer (`CgSettings::shear_layer` off, a model under 16 elements a
//! side, a local soil) W is the springs λ·diag(T) everywhere.
//!
//! Each step starts from the previous step's σ (warm start), so the later penalty steps, which
//! change a few points, take few iterations; steps whose set is still moving are solved to a
//! loose tolerance ([`IterativeSchur::loose_tolerance`]), then to a medium one once the set repeats
//! there, and the penalty iteration confirms a set only with a tight solve. A step starts from
//! the last answer with the products T σ and S σ its solve ended with (no product to form), and
//! the displacements are formed once, for the step the iteration ends on.
//!
//! **Face solves** ([`IterativeSchur::solve_face`]) serve the matrix-free QP
//! ([`super::qp::active_set`]): the same system without penalty, with a set of pressures held at
//! zero (the lifted points). The iteration then runs on the free points only: the product, the
//! residual and the rigid-mode columns C are restricted to them, and the preconditioner drops
//! its springs there (1/D = 0, which makes the Woodbury solve exactly (M_FF)⁻¹). The free
//! points' columns of C can be dependent (a plate resting on one node); the small rigid-mode
//! systems are solved by pseudo-inverse ([`SmallSpd`](crate::solve::linalg::SmallSpd)), which keeps the iterates on the
//! equilibrium the free points can carry.

mod bonded_springs;
mod preconditioner;
mod schur;
mod shear_layer;
pub mod springs;

pub use crate::method::CgSettings;
pub use bonded_springs::{bonded_from_springs, BondedBySprings};
pub use schur::{Face, IterativeSchur, Step};
