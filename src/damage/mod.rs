//! Fatigue damage of a concrete slab over traffic and climate (issue 33).
//!
//! A slab fails in fatigue when the tensile stresses of many load cycles have used up its
//! life. A fatigue relation turns one cycle of tensile stress σ, with the concrete's modulus
//! of rupture (flexural strength) MR, into the number N of such cycles the slab allows; Miner's
//! rule adds the cycles' fractions, D = Σ n/N, and D = 1 is the end of the design life.
//!
//! [`plan`] reads the scene's `[traffic]`, `[climate]` and `[damage]` into the cases a run sums;
//! the run is the study `study::damage`. [`relations`] holds the relations alone, as a floor that knows no model and no solve: PCA
//! 1984, the MEPDG's JPCP cracking (AASHTO Manual of Practice, 2008) and FAARFIELD's rigid
//! failure model, with Miner's sum. What liftoff computes a stress from is not their business:
//! none applies an edge-stress factor or a load-transfer reduction, since liftoff models the
//! joints and their load transfer itself. [`strength`] grows the modulus of rupture with
//! age (the MEPDG's relation), month by month over the life, when the scene asks.

pub mod faa;
mod keys;
pub mod mepdg;
pub mod pca;
pub mod plan;
pub mod relations;
pub mod strength;
