//! The paper's cases (figure, foundation, μ, Γ, load, contact) and the models, methods and
//! problems built from them.

use std::str::FromStr;

use serde::Serialize;

use super::{
    caption_gamma, paper_quarter_elements, DELTA, GAMMA_RECTANGLE, GAMMA_SQUARE, NU, PENALTY,
};
use crate::budget::default_memory_limit;
use crate::error::{Error, Result};
use crate::foundation::FoundationKind;
use crate::method::{Contact, Method, MethodKind, PenaltySettings};
use crate::model::{ConstraintPoints, Model, SymmetryMode};
use crate::scene::{ModelBuilder, Problem};

/// A reading of the paper's load condition 2 (its Fig. 2 is a drawing the text does not carry).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Default)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum LoadCondition2 {
    /// Uniform pressure on the central area |s| ≤ γ, |t| ≤ γ with the γ of Fig. 6's captions:
    /// 0.25 on the half-space, 0.20 on Winkler (two elements of each quarter mesh). The default.
    #[default]
    CaptionPatch,
    /// Uniform pressure on the central area |s| ≤ γ, |t| ≤ γ with one γ ∈ (0, 1] for both
    /// foundations (to compare the foundations under the same load).
    Patch {
        /// Half-size of the loaded area, as a fraction of the half-sides.
        gamma: f64,
    },
    /// Uniform pressure on a band of width γ (the captions' γ) along all four edges, as walls on a
    /// mat: the alternative reading in which γ measures the loaded strip instead of a central area.
    EdgeBand,
}

impl LoadCondition2 {
    /// γ used for `foundation`.
    pub fn gamma(&self, foundation: FoundationKind) -> f64 {
        match *self {
            LoadCondition2::Patch { gamma } => gamma,
            LoadCondition2::CaptionPatch | LoadCondition2::EdgeBand => caption_gamma(foundation),
        }
    }

    /// Name as accepted by [`FromStr`]: `patch`, `patch=G` or `edge-band`.
    pub fn name(&self) -> String {
        match *self {
            LoadCondition2::CaptionPatch => "patch".into(),
            LoadCondition2::Patch { gamma } => format!("patch={gamma}"),
            LoadCondition2::EdgeBand => "edge-band".into(),
        }
    }

    /// One-line description.
    pub fn describe(&self) -> String {
        match *self {
            LoadCondition2::CaptionPatch => "uniform pressure on the central area |s|, |t| ≤ γ, \
                 γ = 0.25 (half-space) / 0.20 (Winkler) as in Fig. 6's captions"
                .into(),
            LoadCondition2::Patch { gamma } => {
                format!(
                    "uniform pressure on the central area |s|, |t| ≤ {gamma} (both foundations)"
                )
            }
            LoadCondition2::EdgeBand => "uniform pressure on a band of width γ along the four \
                 edges, γ = 0.25 (half-space) / 0.20 (Winkler)"
                .into(),
        }
    }

    pub(super) fn check(&self) -> Result<()> {
        if let LoadCondition2::Patch { gamma } = *self {
            if !(gamma.is_finite() && gamma > 0.0 && gamma <= 1.0) {
                return Err(Error::invalid(
                    "load2",
                    format!("the loaded area's half-size γ must lie in (0, 1], got {gamma}"),
                ));
            }
        }
        Ok(())
    }

    /// Add the loads (dimensionless: uniform pressure 1 on each loaded area) to a model.
    fn add_loads(&self, builder: ModelBuilder, foundation: FoundationKind) -> ModelBuilder {
        let g = self.gamma(foundation);
        match self {
            LoadCondition2::CaptionPatch | LoadCondition2::Patch { .. } => {
                builder.patch_load([-g, g], [-g, g], 1.0)
            }
            LoadCondition2::EdgeBand => {
                let b = 1.0 - g;
                builder
                    .patch_load([-1.0, -b], [-1.0, 1.0], 1.0)
                    .patch_load([b, 1.0], [-1.0, 1.0], 1.0)
                    .patch_load([-b, b], [-1.0, -b], 1.0)
                    .patch_load([-b, b], [b, 1.0], 1.0)
            }
        }
    }
}

impl FromStr for LoadCondition2 {
    type Err = Error;

    /// `patch` (the captions' γ), `patch=G` (one γ for both foundations) or `edge-band`.
    fn from_str(s: &str) -> Result<Self> {
        let s = s.trim();
        match s {
            "patch" | "caption-patch" => return Ok(LoadCondition2::CaptionPatch),
            "edge-band" => return Ok(LoadCondition2::EdgeBand),
            _ => {}
        }
        if let Some(v) = s
            .strip_prefix("patch=")
            .or_else(|| s.strip_prefix("patch:"))
        {
            let gamma: f64 = v.trim().parse().map_err(|_| {
                Error::invalid(
                    "load2",
                    format!("`{v}` is not a number (use e.g. patch=0.25)"),
                )
            })?;
            let lc = LoadCondition2::Patch { gamma };
            lc.check()?;
            return Ok(lc);
        }
        Err(Error::invalid(
            "load2",
            format!("unknown load condition 2 `{s}`: use patch, patch=G (0 < G ≤ 1) or edge-band"),
        ))
    }
}

/// Which load a case carries.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Lc {
    One,
    Two(LoadCondition2),
}

/// One case of the study, independent of the mesh.
#[derive(Debug, Clone, Copy)]
pub(super) struct Case {
    pub(super) figure: u8,
    pub(super) foundation: FoundationKind,
    pub(super) mu: f64,
    pub(super) gamma_index: usize,
    pub(super) gamma: f64,
    load: Lc,
    pub(super) contact: Contact,
}

pub(super) const FOUNDATIONS: [FoundationKind; 2] =
    [FoundationKind::HalfSpace, FoundationKind::Winkler];

impl Case {
    pub(super) fn elements(&self, refine: usize) -> [usize; 2] {
        let n = 2 * paper_quarter_elements(self.foundation) * refine;
        [n, n]
    }

    fn title(&self) -> String {
        let plate = if self.mu == 1.0 {
            "square plate".to_string()
        } else {
            format!("μ = {}", self.mu)
        };
        let load = match self.load {
            Lc::One => "central point load".to_string(),
            Lc::Two(lc) => format!("load condition 2 ({})", lc.name()),
        };
        format!(
            "Paper Fig. {}: {plate}, {}, {load}, {} contact, Γ = {:e}",
            self.figure,
            self.foundation.names().label,
            self.contact.name(),
            self.gamma
        )
    }

    /// The dimensionless model of this case.
    pub(super) fn model(&self, refine: usize) -> Result<Model> {
        let [nx, ny] = self.elements(refine);
        let builder = Model::builder()
            .title(self.title())
            .dimensionless(self.foundation, self.gamma, DELTA, self.mu, NU)
            .elements(nx, ny)
            .symmetry(SymmetryMode::Auto)
            .constraint(ConstraintPoints::Nodal);
        let builder = match self.load {
            Lc::One => builder.point_load(0.0, 0.0, 1.0),
            Lc::Two(lc2) => lc2.add_loads(builder, self.foundation),
        };
        builder.build()
    }

    /// The method of this case: bonded, or the unbonded `kind` with the paper's ε̄.
    fn method(&self, kind: MethodKind) -> Method {
        match (self.contact, kind) {
            (Contact::Bonded, _) => Method::Bonded,
            (Contact::Unbonded, MethodKind::Penalty) => paper_penalty(),
            (Contact::Unbonded, MethodKind::Qp) => Method::qp(),
        }
    }

    /// The problem of this case.
    pub(super) fn problem(&self, refine: usize, kind: MethodKind) -> Result<Problem> {
        Ok(Problem {
            combinations: Vec::new(),
            model: self.model(refine)?,
            method: self.method(kind),
            route: crate::method::Route::Auto,
            memory_limit: default_memory_limit(),
            warnings: Vec::new(),
            damage: None,
            ends: None,
        })
    }
}

/// The paper's penalty iteration: ε̄ = [`PENALTY`].
pub(super) fn paper_penalty() -> Method {
    Method::Penalty(PenaltySettings::fixed(PENALTY))
}

/// The unbonded cases of Figs. 3–5 (Fig. 6 reuses Fig. 5) and the bonded ones of Fig. 7.
pub(super) fn cases(load2: LoadCondition2) -> Vec<Case> {
    let mut v = Vec::new();
    let figs: [(u8, f64, [f64; 3], Lc); 3] = [
        (3, 1.0, GAMMA_SQUARE, Lc::One),
        (4, 1.0, GAMMA_SQUARE, Lc::Two(load2)),
        (5, 0.5, GAMMA_RECTANGLE, Lc::Two(load2)),
    ];
    for (figure, mu, gammas, load) in figs {
        for foundation in FOUNDATIONS {
            for (k, &gamma) in gammas.iter().enumerate() {
                v.push(Case {
                    figure,
                    foundation,
                    mu,
                    gamma_index: k + 1,
                    gamma,
                    load,
                    contact: Contact::Unbonded,
                });
            }
        }
    }
    for foundation in FOUNDATIONS {
        v.push(Case {
            figure: 7,
            foundation,
            mu: 1.0,
            gamma_index: 1,
            gamma: GAMMA_SQUARE[0],
            load: Lc::One,
            contact: Contact::Bonded,
        });
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn load_condition_2_parses() {
        assert_eq!(
            "patch".parse::<LoadCondition2>().ok(),
            Some(LoadCondition2::CaptionPatch)
        );
        assert_eq!(
            "patch=0.3".parse::<LoadCondition2>().ok(),
            Some(LoadCondition2::Patch { gamma: 0.3 })
        );
        assert_eq!(
            "edge-band".parse::<LoadCondition2>().ok(),
            Some(LoadCondition2::EdgeBand)
        );
        assert!("patch=0".parse::<LoadCondition2>().is_err());
        assert!("patch=x".parse::<LoadCondition2>().is_err());
        assert!("uniform".parse::<LoadCondition2>().is_err());
        assert_eq!(caption_gamma(FoundationKind::HalfSpace), 0.25);
        assert_eq!(caption_gamma(FoundationKind::Winkler), 0.2);
    }

    #[test]
    fn every_case_scene_is_valid_and_symmetric() {
        for lc in [
            LoadCondition2::CaptionPatch,
            LoadCondition2::Patch { gamma: 0.3 },
            LoadCondition2::EdgeBand,
        ] {
            for case in cases(lc) {
                let p = case.model(1).expect("scene");
                assert!((p.resultant() - 4.0).abs() < 1e-12);
                assert_eq!(p.elements, case.elements(1));
                assert!(crate::model::loads_symmetric(&p.loads, true));
                assert!(crate::model::loads_symmetric(&p.loads, false));
            }
        }
    }
}
