//! # liftoff
//!
//! A free rectangular Mindlin plate on a Winkler or elastic half-space foundation that can push
//! but never pull (Ascione, Olivito & Spadea 1983).
//!
//! Plate (virtual work, paper eq. 2.9a): B[(ψ, w), (φ, v)] = ⟨p − r, v⟩ for all (φ, v), with the
//! Mindlin bilinear form of eq. 2.2. Foundation: w_s = T r (Winkler T = I/K; half-space
//! T r = (1 − ν_s²)/(π E_s) ∫ r / |x − x'| dA'). Unilateral contact (2.9b, c):
//!
//! r ≥ 0,  g = T r − w ≥ 0,  ⟨r, g⟩ = 0.
//!
//! Discretised with MITC4 plate elements and bilinear pressures ([`operators`]), the problem is
//! K u + B σ = f, g = T σ − Bᵀ u, Gσ ≥ 0, g ≥ 0, σ·g = 0. Eliminating the plate with a
//! generalised inverse K⁻ and its rigid modes R turns it into the convex QP
//!
//! min ½ σᵀ(T + BᵀK⁻B)σ − σᵀBᵀK⁻f  subject to  Rᵀ(f − Bσ) = 0,  Gσ ≥ 0,
//!
//! whose KKT conditions are exactly the discrete unilateral conditions.
//!
//! Conventions: w positive downward, loads positive downward, pressure positive in compression,
//! gap ≥ 0 where the plate is above the soil surface; the plate occupies
//! [−L, L] × [−μL, μL].
//!
//! ## Use
//!
//! Every front end (the command line, the Python package) goes through two calls: [`load`] a
//! scene from a [`Source`] with the front end's [`scene::Overrides`], and [`run`] it, with a
//! [`Monitor`] that can watch and stop it. `examples/library.rs`:
//!
//! ```rust
#![doc = include_str!("../examples/library.rs")]
//! ```
//!
//! Features: the solver core needs none; `output` adds the result files and charts, `cli` (on
//! by default) the command line.
#![warn(missing_docs)]
// Element and quadrature loops index several small arrays with one local node index; the
// iterator form clippy suggests obscures that.
#![allow(clippy::needless_range_loop)]

pub mod analysis;
pub mod backcalc;
pub mod budget;
pub mod check;
pub mod choice;
pub mod combination;
pub mod compare;
pub mod damage;
pub mod entry;
pub mod error;
pub mod examples;
pub mod foundation;
pub mod integrals;
pub mod layout;
pub mod mesh;
pub mod method;
pub mod metrics;
pub mod model;
pub mod monitor;
pub mod operators;
#[cfg(feature = "output")]
pub mod output;
#[cfg(feature = "output")]
pub mod paper;
pub mod plate;
pub mod post;
pub mod quadrature;
pub mod scene;
pub mod solve;
pub mod study;
pub mod summary;
pub mod system;
pub mod units;
pub mod vehicle;

pub use analysis::{analyse, Analysis};
pub use entry::{load, run, Outcome, Source};
pub use error::{Error, ErrorKind, Result};
pub use method::{CgSettings, Method, PenaltySettings, QpSettings, Route};
pub use model::Model;
pub use monitor::{Monitor, Progress};
pub use operators::Operators;
pub use scene::Problem;
pub use solve::{solve, Solution, SolveInfo, Status};
