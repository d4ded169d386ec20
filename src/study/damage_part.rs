//! What a damage run keeps of its passes ([`super::damage`]): each pass's largest stresses per
//! element (`PassStress`), and a share of a run for a cluster's worker (`DamagePart`) with its
//! bytes, which `damage_merge` sums.

use serde::Serialize;

use super::RunOutcome;
use crate::error::{Error, Result};

/// A share of a damage run ([`crate::study::damage_part`]): the passes of some of its
/// families, as [`crate::study::damage_merge`] sums them. [`Self::to_bytes`] and [`Self::from_bytes`] carry it between
/// processes (a cluster's workers and the client).
#[derive(Debug, Clone)]
pub struct DamagePart {
    /// The cases (indices of the plan's bins) of the passes below.
    pub(super) bins: Vec<usize>,
    pub(super) stresses: Vec<PassStress>,
    /// Seconds to assemble the part's operators.
    pub(super) assemble_s: f64,
    /// Seconds of the whole part.
    pub(super) seconds: f64,
}

/// What [`DamagePart`]'s bytes say of each pass beside its arrays.
#[derive(Serialize, serde::Deserialize)]
struct PartHeader {
    bins: Vec<usize>,
    outcomes: Vec<RunOutcome>,
    solves: Vec<usize>,
    interpolated: Vec<usize>,
    /// Positions read off their mirror images (absent in a part written before them: none).
    #[serde(default)]
    mirrored: Vec<usize>,
    /// Elements per array of each pass (0: the pass has none: it did not converge at its first
    /// position).
    elements: Vec<usize>,
    /// Erosion corners of each pass (0: none).
    corners: Vec<usize>,
    assemble_s: f64,
    seconds: f64,
}

impl DamagePart {
    /// The part as bytes: the length of a JSON header (u64, little endian), the header (the
    /// cases, their outcomes and counts), then each pass's σ₁ at the bottom and top faces, the
    /// element centres x and y and the deflections it caused at the erosion's corners as
    /// little-endian f64 — exact, not rounded to text.
    pub fn to_bytes(&self) -> Vec<u8> {
        let header = PartHeader {
            bins: self.bins.clone(),
            outcomes: self.stresses.iter().map(|s| s.outcome).collect(),
            solves: self.stresses.iter().map(|s| s.solves).collect(),
            interpolated: self.stresses.iter().map(|s| s.interpolated).collect(),
            mirrored: self.stresses.iter().map(|s| s.mirrored).collect(),
            elements: self.stresses.iter().map(|s| s.bottom.len()).collect(),
            corners: self.stresses.iter().map(|s| s.corners.len()).collect(),
            assemble_s: self.assemble_s,
            seconds: self.seconds,
        };
        // A struct of numbers, vectors and unit-variant enums always serialises.
        let json = serde_json::to_vec(&header).unwrap_or_default();
        let mut out = Vec::with_capacity(8 + json.len());
        out.extend_from_slice(&(json.len() as u64).to_le_bytes());
        out.extend_from_slice(&json);
        for s in &self.stresses {
            for v in [&s.bottom, &s.top, &s.x, &s.y, &s.corners] {
                for x in v {
                    out.extend_from_slice(&x.to_le_bytes());
                }
            }
        }
        out
    }

    /// The part from [`Self::to_bytes`]'s bytes; anything else is refused (field `parts`).
    pub fn from_bytes(bytes: &[u8]) -> Result<Self> {
        let bad = |why: &str| Error::invalid("parts", format!("not a damage part's bytes: {why}"));
        let len = bytes
            .get(..8)
            .and_then(|b| <[u8; 8]>::try_from(b).ok())
            .map(u64::from_le_bytes)
            .ok_or_else(|| bad("too short"))?;
        let end = usize::try_from(len)
            .ok()
            .and_then(|l| l.checked_add(8))
            .filter(|&e| e <= bytes.len())
            .ok_or_else(|| bad("header beyond the end"))?;
        let header: PartHeader =
            serde_json::from_slice(&bytes[8..end]).map_err(|e| bad(&e.to_string()))?;
        let n = header.bins.len();
        if [
            header.outcomes.len(),
            header.solves.len(),
            header.interpolated.len(),
            header.elements.len(),
            header.corners.len(),
        ] != [n; 5]
        {
            return Err(bad("the header's lists differ in length"));
        }
        let mut values = bytes[end..]
            .chunks_exact(8)
            .map(|c| f64::from_le_bytes(<[u8; 8]>::try_from(c).unwrap_or_default()));
        if !(bytes.len() - end).is_multiple_of(8)
            || (bytes.len() - end) / 8
                != 4 * header.elements.iter().sum::<usize>() + header.corners.iter().sum::<usize>()
        {
            return Err(bad("the arrays do not match the header"));
        }
        let mut take = |k: usize| -> Vec<f64> { values.by_ref().take(k).collect() };
        let stresses = (0..n)
            .map(|i| {
                let k = header.elements[i];
                PassStress {
                    bottom: take(k),
                    top: take(k),
                    x: take(k),
                    y: take(k),
                    corners: take(header.corners[i]),
                    outcome: header.outcomes[i],
                    solves: header.solves[i],
                    interpolated: header.interpolated[i],
                    mirrored: header.mirrored.get(i).copied().unwrap_or(0),
                    field: None,
                }
            })
            .collect();
        Ok(Self {
            bins: header.bins,
            stresses,
            assemble_s: header.assemble_s,
            seconds: header.seconds,
        })
    }
}

/// A pass's largest stresses per element.
#[derive(Debug, Clone)]
pub(super) struct PassStress {
    pub(super) bottom: Vec<f64>,
    pub(super) top: Vec<f64>,
    pub(super) x: Vec<f64>,
    pub(super) y: Vec<f64>,
    /// The largest deflection the pass caused at each erosion corner, m (empty: no erosion).
    pub(super) corners: Vec<f64>,
    pub(super) outcome: RunOutcome,
    pub(super) solves: usize,
    pub(super) interpolated: usize,
    /// Positions read off their mirror images in the pass ([`PassStress::mirror`]).
    pub(super) mirrored: usize,
    pub(super) field: Option<crate::post::FullField>,
}

impl Default for PassStress {
    fn default() -> Self {
        Self {
            bottom: Vec::new(),
            top: Vec::new(),
            x: Vec::new(),
            y: Vec::new(),
            corners: Vec::new(),
            outcome: RunOutcome::CONVERGED,
            solves: 0,
            interpolated: 0,
            mirrored: 0,
            field: None,
        }
    }
}

impl PassStress {
    /// The maxima of a pass whose positions solved so far are half of a pass symmetric under a
    /// flip: each element's and corner's maximum with its mirror image's (`elements[k]`,
    /// `corners[k]`: the mirror image of element or corner k), as the other half would have
    /// made them; `positions` the positions so read.
    pub(super) fn mirror(&mut self, elements: &[usize], corners: &[usize], positions: usize) {
        let both = |v: &[f64], map: &[usize]| -> Vec<f64> {
            v.iter()
                .zip(map)
                .map(|(&a, &k)| a.max(v.get(k).copied().unwrap_or(f64::NAN)))
                .collect()
        };
        self.bottom = both(&self.bottom, elements);
        self.top = both(&self.top, elements);
        self.corners = both(&self.corners, corners);
        self.mirrored += positions;
    }

    /// Take one position's element stresses and the deflections it caused at the erosion's
    /// corners into the running maxima.
    pub(super) fn take(
        &mut self,
        bottom: &[f64],
        top: &[f64],
        x: &[f64],
        y: &[f64],
        corners: &[f64],
    ) {
        if self.bottom.is_empty() {
            self.bottom = bottom.to_vec();
            self.top = top.to_vec();
            self.x = x.to_vec();
            self.y = y.to_vec();
            self.corners = corners.to_vec();
            return;
        }
        for (m, &v) in self.corners.iter_mut().zip(corners) {
            *m = m.max(v);
        }
        for (m, &v) in self.bottom.iter_mut().zip(bottom) {
            *m = m.max(v);
        }
        for (m, &v) in self.top.iter_mut().zip(top) {
            *m = m.max(v);
        }
    }
}
