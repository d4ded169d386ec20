//! What a damage run reports ([`super::damage`]): the damage maps of both faces, their
//! governing places, the MEPDG's cracking, the PCA's erosion, and every case's pass, with
//! [`Damage::reported`] giving them in the scene's unit system.

use serde::Serialize;

use super::erosion::Erosion;
use super::RunOutcome;

/// One case's pass: what it was and what it caused.
#[derive(Debug, Clone, Serialize)]
pub struct Pass {
    /// The group's scene load.
    pub group: String,
    /// The group's total load at this level, N.
    pub load: f64,
    /// Distance of the outer tire's edge from the slab's edge, m.
    pub offset: f64,
    /// The climate bin's temperature difference, K (null: the scene's own loads only).
    pub difference: Option<f64>,
    /// Passes over the design life.
    pub repetitions: f64,
    /// The group's reference point (x, y) at each position of the pass, m.
    pub positions: Vec<[f64; 2]>,
    /// How its solves ended: converged, or the first outcome that was not.
    pub outcome: RunOutcome,
    /// Positions solved.
    pub solves: usize,
    /// Positions filled by the exact interpolation between the family's end levels (their
    /// contact sets agreed there).
    pub interpolated: usize,
    /// Positions read off their mirror images: the pass symmetric about a line of a symmetric
    /// plate, its first half solved (`study::mirror`).
    pub mirrored: usize,
    /// The largest σ₁ at the bottom over the pass and the element where (x, y), Pa and m.
    pub bottom: Peak,
    /// The same at the top face.
    pub top: Peak,
    /// Σ n/N of this pass's cycles at the element that governs the whole map's bottom face.
    pub bottom_share: f64,
    /// The same at the top face.
    pub top_share: f64,
    /// The PCA's erosion of this pass (null: not summed).
    pub erosion: Option<PassErosion>,
}

/// What one pass does to the corners ([`super::erosion`]).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct PassErosion {
    /// The largest deflection the group caused at a corner, m.
    pub deflection: f64,
    /// That corner's x, m.
    pub x: f64,
    /// That corner's y, m.
    pub y: f64,
    /// The erosion relation's N there (null: unlimited).
    pub allowed: Option<f64>,
    /// C2 n/N of this pass at the corner that governs the run's erosion.
    pub share: f64,
}

/// A face's largest stress over a pass: value, where, allowed repetitions there.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Peak {
    /// σ₁, Pa.
    pub stress: f64,
    /// Element centre x, m.
    pub x: f64,
    /// Element centre y, m.
    pub y: f64,
    /// N at that stress (null: unlimited).
    pub allowed: Option<f64>,
}

/// The damage map's largest value on one face and where.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Governing {
    /// Σ n/N.
    pub damage: f64,
    /// Element centre x, m.
    pub x: f64,
    /// Element centre y, m.
    pub y: f64,
    /// Element index ie + je nx.
    pub element: usize,
}

/// The MEPDG's cracking from the governing damage of each face.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Cracking {
    /// Bottom-up cracking, % of slabs.
    pub bottom: f64,
    /// Top-down cracking, %.
    pub top: f64,
    /// Total, % (a slab cracks one way or the other, not both).
    pub total: f64,
    /// Total at the plan's reliability (null: none given).
    pub at_reliability: Option<f64>,
}

/// The result of a damage run.
#[derive(Debug, Clone, Serialize)]
pub struct Damage {
    /// The relation's name (`pca`, `mepdg`, `faa`).
    pub model: &'static str,
    /// Modulus of rupture, Pa (at 28 days where it grows).
    pub rupture: f64,
    /// Where the modulus of rupture grows with age (`rupture_growth = "mepdg"`): its ratio to
    /// the 28-day value in the life's first month and its largest (null: one MR throughout).
    pub rupture_ratio: Option<[f64; 2]>,
    /// Repetitions over the life per first-year repetition.
    pub life_factor: f64,
    /// Elements along x and y.
    pub elements: [usize; 2],
    /// Element centres x, m (element ie + je nx).
    pub x: Vec<f64>,
    /// Element centres y, m.
    pub y: Vec<f64>,
    /// Σ n/N at the bottom face of every element (bottom-up).
    pub bottom: Vec<f64>,
    /// Σ n/N at the top face (top-down).
    pub top: Vec<f64>,
    /// Whether each element counts in the governing places, the passes' peaks, the cracking
    /// and a design (false: an end panel of a lane the model cuts, `[traffic] ends`).
    pub counted: Vec<bool>,
    /// Governing bottom-up damage.
    pub governing_bottom: Governing,
    /// Governing top-down damage.
    pub governing_top: Governing,
    /// The MEPDG's cracking (null for the other relations).
    pub cracking: Option<Cracking>,
    /// The PCA's erosion damage at the panels' corners (null: another relation, or a soil
    /// without a k: `erosion_note` says why).
    pub erosion: Option<Erosion>,
    /// Why a PCA run has no erosion (null otherwise).
    pub erosion_note: Option<String>,
    /// Every case's pass.
    pub passes: Vec<Pass>,
    /// The passes that did not converge (their damage is not in the sums).
    pub missing: Vec<String>,
    /// Whether every pass converged: the totals are complete.
    pub complete: bool,
    /// Solves run.
    pub solves: usize,
    /// Positions filled by interpolation instead of a solve.
    pub interpolated: usize,
    /// Positions read off their mirror images instead of a solve.
    pub mirrored: usize,
    /// Seconds to assemble the shared operators.
    pub assemble_s: f64,
    /// Seconds of the whole run.
    pub total_s: f64,
    /// The scene's unit system (None: dimensionless); the values above are SI
    /// ([`Self::reported`] gives them in this system).
    pub units: Option<crate::units::UnitSystem>,
    /// The plate's field of one converged position (its grid and joints, for the maps).
    #[serde(skip)]
    pub field: crate::post::FullField,
}

impl Damage {
    /// The largest damage of `values` (a face's map) at an element that does not count, and
    /// that element; None when every element counts.
    pub fn uncounted(&self, values: &[f64]) -> Option<(usize, f64)> {
        (0..values.len())
            .rev()
            .filter(|&k| self.counted.get(k) == Some(&false))
            .map(|k| (k, values[k]))
            .max_by(|a, b| a.1.total_cmp(&b.1))
    }

    /// The run as damage.json reports it: stresses, places, loads and temperature differences
    /// in the scene's unit system (an SI scene's unchanged); damage is a pure number.
    pub fn reported(&self) -> Damage {
        use crate::units::Measure::{Force, Length, Pressure};
        let sys = self.units;
        let l = |v: f64| Length.from_si(sys, v);
        let peak = |p: &Peak| Peak {
            stress: Pressure.from_si(sys, p.stress),
            x: l(p.x),
            y: l(p.y),
            allowed: p.allowed,
        };
        // 9/5 exactly: Quantity's SI-per-°F factor (5/9) divides to 14.399999999999999 for 8 K.
        let kelvin = |k: f64| match sys {
            Some(crate::units::UnitSystem::Us) => k * 9.0 / 5.0,
            _ => k,
        };
        Damage {
            rupture: Pressure.from_si(sys, self.rupture),
            x: self.x.iter().map(|&v| l(v)).collect(),
            y: self.y.iter().map(|&v| l(v)).collect(),
            governing_bottom: Governing {
                x: l(self.governing_bottom.x),
                y: l(self.governing_bottom.y),
                ..self.governing_bottom
            },
            governing_top: Governing {
                x: l(self.governing_top.x),
                y: l(self.governing_top.y),
                ..self.governing_top
            },
            passes: self
                .passes
                .iter()
                .map(|p| Pass {
                    load: Force.from_si(sys, p.load),
                    offset: l(p.offset),
                    difference: p.difference.map(kelvin),
                    positions: p.positions.iter().map(|&[x, y]| [l(x), l(y)]).collect(),
                    bottom: peak(&p.bottom),
                    top: peak(&p.top),
                    erosion: p.erosion.map(|e| PassErosion {
                        deflection: crate::units::Measure::Deflection.from_si(sys, e.deflection),
                        x: l(e.x),
                        y: l(e.y),
                        ..e
                    }),
                    ..p.clone()
                })
                .collect(),
            erosion: self.erosion.as_ref().map(|e| e.reported(sys)),
            ..self.clone()
        }
    }
}
