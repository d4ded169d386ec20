//! Regenerate the numerical examples of Ascione, Olivito & Spadea (1983), §4 and Figs. 3–7.
//!
//! The paper's parameters: ν_p = 0.3, Δ = 0.002857 (χ = 5/6, H/L = 0.1), ε̄ = 1e-5;
//! Γ_1..Γ_3 = 0.25e-3, 0.75e-3, 0.25e-2 for square plates and 0.75e-3, 2.25e-3, 0.75e-2 for
//! μ = 0.5; a quarter of the plate meshed with 8 × 8 elements on the half-space and 10 × 10 on
//! the Winkler subgrade (here `elements = [16, 16]` and `[20, 20]` over the whole plate, and the
//! same counts for μ = 0.5, as the paper's uniform mesh of R = ]−1, 1[² in (s, t) implies; the
//! elements are then twice as long as wide).
//!
//! * Fig. 3: square plate, load condition 1 (central point load): V and σ along the centre line,
//!   the edge and the diagonal, one curve per Γ, each foundation.
//! * Fig. 4: square plate, load condition 2 ([`LoadCondition2`]).
//! * Fig. 5: μ = 0.5, load condition 2.
//! * Fig. 6: μ = 0.5, load condition 2: the contact regions of the three Γ in one chart per
//!   foundation.
//! * Fig. 7: square plate, load condition 1, Γ = 0.25e-3: bonded against unbonded.
//!
//! The paper states its load condition 2 only in a drawing (Fig. 2) that the text does not
//! carry; Fig. 6's captions give "γ = 0.25" (half-space) and "γ = 0.20" (Winkler). Both are two
//! elements of the respective quarter mesh (2/8 and 2/10), which reads naturally as the
//! half-size of a loaded area laid on the mesh lines. The default reading is therefore a uniform
//! pressure on the central area |s| ≤ γ, |t| ≤ γ; the alternatives are selectable.
//!
//! [`run`](fn@run) solves every case at the paper's meshes (refine = 1) and, when asked, at finer
//! ones (the element counts times 2, 4, … up to `refine`), draws the figures from the finest
//! meshes and writes them with `paper.json` and `paper.md` (from [`write_markdown`]) into one
//! directory, all staged and moved into place only when everything succeeded.

//!
//! Layout: `cases.rs` holds the cases and builds their models, `run.rs` solves them and
//! assembles each figure's numbers, `figures.rs` draws the charts and `markdown.rs` writes the
//! tables of `paper.md`.

use serde::Serialize;

use crate::foundation::FoundationKind;
use crate::method::{Contact, MethodKind};
use crate::post::Extent;

mod cases;
mod figures;
mod markdown;
mod run;
mod solved;

pub use cases::LoadCondition2;
pub use markdown::write_markdown;
pub use run::run;

/// Plate Poisson's ratio ν_p of the paper's examples.
pub const NU: f64 = 0.3;
/// Shear-to-flexural stiffness ratio Δ of the paper's examples (χ = 5/6, H/L = 0.1, μ = 1).
pub const DELTA: f64 = 0.002857;
/// Penalty ε̄ of the paper's examples.
pub const PENALTY: f64 = 1e-5;
/// Γ_1, Γ_2, Γ_3 for the square plates.
pub const GAMMA_SQUARE: [f64; 3] = [0.25e-3, 0.75e-3, 0.25e-2];
/// Γ_1, Γ_2, Γ_3 for the rectangular plates (μ = 0.5).
pub const GAMMA_RECTANGLE: [f64; 3] = [0.75e-3, 2.25e-3, 0.75e-2];
/// Contact radius the paper reports: square plate, half-space, Γ_h = 0.25e-3, point load.
pub const PAPER_CONTACT_RADIUS: f64 = 0.44;
/// Svec's (1974) contact radius for the same case with a Kirchhoff plate, as the paper quotes it.
pub const SVEC_CONTACT_RADIUS: f64 = 0.50;
/// The paper's "4 ~ 6 steps" of the penalty iteration.
pub const PAPER_STEPS: [usize; 2] = [4, 6];
/// Contact radius a / ℓ, ℓ = (D/K)^¼, of an infinite Kirchhoff plate (ν = 0.3) on a tensionless
/// Winkler subgrade under a point load: the root of the five matching conditions (w = 0 and
/// continuity of slope, moment and shear at r = a) between the Kelvin-function solution
/// −kei(r/ℓ) + A ber(r/ℓ) + B bei(r/ℓ) inside and the unloaded free plate E + F ln r outside.
/// For the square plate (μ = 1) ℓ = Γ_w^¼ L.
pub const WINKLER_INFINITE_PLATE_RADIUS: f64 = 2.849;
/// Largest refinement factor [`run`](fn@run) accepts (the half-space quarter model is then 64 × 64).
pub const MAX_REFINE: usize = 8;

/// The paper's quarter-mesh elements per side: 8 on the half-space, 10 on Winkler. (The paper
/// has no other soil; a non-local one takes the half-space's mesh, a local one Winkler's.)
pub fn paper_quarter_elements(foundation: FoundationKind) -> usize {
    if foundation.is_local() {
        10
    } else {
        8
    }
}

/// The loaded-area size γ of the captions of the paper's Fig. 6: 0.25 on the half-space and
/// 0.20 on Winkler — two elements of the respective quarter mesh.
pub fn caption_gamma(foundation: FoundationKind) -> f64 {
    2.0 / paper_quarter_elements(foundation) as f64
}

/// What [`run`](fn@run) computes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PaperOptions {
    /// Method for the unbonded runs (bonded runs of Fig. 7 are solved directly).
    pub method: MethodKind,
    /// Reading of load condition 2.
    pub load2: LoadCondition2,
    /// 1 = the paper's meshes only; n > 1 also solves with the element counts times 2, 4, …
    /// and n, and draws the figures from the finest meshes. At most [`MAX_REFINE`].
    pub refine: usize,
}

impl Default for PaperOptions {
    fn default() -> Self {
        Self {
            method: MethodKind::Penalty,
            load2: LoadCondition2::CaptionPatch,
            refine: 1,
        }
    }
}

/// Key numbers of one solve (dimensionless, paper eq. 4.1).
#[derive(Debug, Clone, Serialize)]
pub struct KeyNumbers {
    /// Largest V.
    pub v_max: f64,
    /// V at the centre.
    pub v_center: f64,
    /// V at the corner (s, t) = (1, 1).
    pub v_corner: f64,
    /// Largest nodal σ.
    pub sigma_max: f64,
    /// Smallest nodal σ (negative: tension, bonded contact or penalty residual).
    pub sigma_min: f64,
    /// √(contact area / π) / L.
    pub contact_radius: f64,
    /// Contact area / plate area.
    pub contact_fraction: f64,
    /// Contact extents along +s, +t (fractions of the half-sides) and the diagonal (fraction of
    /// the half-diagonal).
    pub contact_extent: Extent,
    /// Penalty steps (linear solves), interior-point iterations (QP) or 1 (bonded).
    pub iterations: usize,
    /// Whether the method converged.
    pub converged: bool,
    /// The method's status in words.
    pub status: String,
    /// The method reached its fixed point: converged, or (penalty) the penalised set settled
    /// but the tension left at lifted points exceeded the crate's tolerance for ε̄.
    pub settled: bool,
    /// Tension left at lifted points relative to the peak pressure (or the compressive
    /// resultant), when the penalty method flagged ε̄ as too weak.
    pub tension_ratio: Option<f64>,
    /// Penalty steps with the paper's Gauss-point constraints (eqs. 4.3–4.4), at the paper's
    /// meshes only (`None` otherwise, and for bonded runs).
    pub gauss_steps: Option<usize>,
    /// Contact radius with Gauss-point constraints, where `gauss_steps` is given.
    pub gauss_contact_radius: Option<f64>,
    /// Wall-clock seconds of the solve (assembly, method, post-processing).
    pub time_s: f64,
}

/// One solve of a figure.
#[derive(Debug, Clone, Serialize)]
pub struct PaperRun {
    /// Foundation model.
    pub foundation: FoundationKind,
    /// μ = width / length.
    pub mu: f64,
    /// 1, 2 or 3 (Γ_1..Γ_3).
    pub gamma_index: usize,
    /// Γ_h or Γ_w.
    pub gamma: f64,
    /// Bonded or unbonded contact.
    pub contact: Contact,
    /// `penalty`, `qp` or `direct` (bonded).
    pub method: crate::method::SolvedBy,
    /// Refinement factor (1 = the paper's mesh).
    pub refine: usize,
    /// Elements over the whole plate.
    pub elements: [usize; 2],
    /// The numbers.
    pub key: KeyNumbers,
}

/// Contact regions of the two foundations at equal Γ (the paper's conclusion ii).
#[derive(Debug, Clone, Serialize)]
pub struct FoundationAgreement {
    /// 1, 2 or 3.
    pub gamma_index: usize,
    /// Γ_h = Γ_w.
    pub gamma: f64,
    /// Refinement factor.
    pub refine: usize,
    /// Contact radius on the half-space.
    pub radius_half_space: f64,
    /// Contact radius on Winkler.
    pub radius_winkler: f64,
    /// Area of the intersection of the two contact regions over the area of their union
    /// (1 = identical), sampled on a 200 × 200 grid of the plate.
    pub overlap: f64,
}

/// Bonded against unbonded (the paper's Fig. 7 and conclusion iii).
#[derive(Debug, Clone, Serialize)]
pub struct BondedComparison {
    /// Foundation model.
    pub foundation: FoundationKind,
    /// Refinement factor.
    pub refine: usize,
    /// V_max bonded.
    pub v_max_bonded: f64,
    /// V_max unbonded.
    pub v_max_unbonded: f64,
    /// V at the corner, bonded.
    pub v_corner_bonded: f64,
    /// V at the corner, unbonded.
    pub v_corner_unbonded: f64,
    /// Largest σ, bonded.
    pub sigma_max_bonded: f64,
    /// Largest σ, unbonded.
    pub sigma_max_unbonded: f64,
    /// Smallest σ, bonded (the tension the unbonded contact cannot carry).
    pub sigma_min_bonded: f64,
    /// max |V_b − V_u| / max |V_u| over the nodes.
    pub v_max_difference: f64,
    /// max |σ_b − σ_u| / max |σ_u| over the nodes.
    pub sigma_max_difference: f64,
    /// ‖V_b − V_u‖₂ / ‖V_u‖₂ over the nodes.
    pub v_rms_difference: f64,
    /// ‖σ_b − σ_u‖₂ / ‖σ_u‖₂ over the nodes.
    pub sigma_rms_difference: f64,
}

/// One of the paper's figures: its runs and comparisons.
#[derive(Debug, Clone, Serialize)]
pub struct PaperFigure {
    /// 3 … 7.
    pub number: u8,
    /// What it shows.
    pub title: String,
    /// μ.
    pub mu: f64,
    /// The load, in words.
    pub load: String,
    /// The Γ values.
    pub gammas: Vec<f64>,
    /// Every solve, all refinement levels (Fig. 6 repeats the runs of Fig. 5).
    pub runs: Vec<PaperRun>,
    /// Half-space against Winkler at equal Γ, per Γ and level (Figs. 3–6).
    pub foundations: Vec<FoundationAgreement>,
    /// Bonded against unbonded (Fig. 7).
    pub bonded: Vec<BondedComparison>,
    /// Chart files of the figure.
    pub files: Vec<String>,
}

/// The paper's fixed parameters as used.
#[derive(Debug, Clone, Serialize)]
pub struct PaperParameters {
    /// ν_p.
    pub nu: f64,
    /// Δ.
    pub delta: f64,
    /// ε̄.
    pub penalty: f64,
    /// Constraint points of the main runs.
    pub constraint: String,
    /// Γ for square plates.
    pub gamma_square: [f64; 3],
    /// Γ for μ = 0.5.
    pub gamma_rectangle: [f64; 3],
    /// Quarter-mesh elements per side on the half-space (paper: 8).
    pub quarter_elements_half_space: usize,
    /// Quarter-mesh elements per side on Winkler (paper: 10).
    pub quarter_elements_winkler: usize,
    /// How μ = 0.5 is meshed.
    pub rectangle_mesh: String,
}

/// Everything [`run`](fn@run) computed (serialised as `paper.json`).
#[derive(Debug, Clone, Serialize)]
pub struct PaperReport {
    /// Method of the unbonded runs.
    pub method: crate::method::MethodKind,
    /// Reading of load condition 2.
    pub load2: LoadCondition2,
    /// The same in words.
    pub load2_description: String,
    /// Refinement asked for.
    pub refine: usize,
    /// Refinement levels solved (1 = the paper's meshes); the figures use the last.
    pub levels: Vec<usize>,
    /// Fixed parameters.
    pub parameters: PaperParameters,
    /// Figs. 3–7.
    pub figures: Vec<PaperFigure>,
    /// Files written, relative to the output directory.
    pub files: Vec<String>,
}

/// The refinement levels solved for `refine`: 1, then doublings below `refine`, then `refine`.
pub fn levels(refine: usize) -> Vec<usize> {
    let mut v = vec![1];
    let mut k = 2;
    while k < refine {
        v.push(k);
        k *= 2;
    }
    if refine > 1 {
        v.push(refine);
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn levels_double_up_to_refine() {
        assert_eq!(levels(1), vec![1]);
        assert_eq!(levels(2), vec![1, 2]);
        assert_eq!(levels(4), vec![1, 2, 4]);
        assert_eq!(levels(3), vec![1, 2, 3]);
        assert_eq!(levels(8), vec![1, 2, 4, 8]);
    }
}
