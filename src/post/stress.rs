//! Surface stresses of the plate, what a pavement or floor designer reads: at the bottom (soil
//! side) and top faces of each element, σ = ±6m/H² from the bending and twisting moments
//! (positive moments put the bottom in tension; H the element's own panel's thickness H_p on a
//! plate with panels of their own section), plus the self-equilibrating stress of a
//! nonlinear temperature profile, which a plate whose sections stay plane cannot bend away
//! (`Load::FaceStress`). From them the principal stresses and the direction of the larger one.
//!
//! Sign: tension positive. Units: those of the moments over a length squared — Pa in an SI
//! scene, P/L² in a dimensionless one.

use serde::Serialize;

use crate::mesh::Mesh;

/// Principal stresses of a plane stress state: (σ₁, σ₂, θ) with σ₁ ≥ σ₂ and θ the direction of
/// σ₁ from the x axis, in degrees in (−90, 90].
pub fn principal(sx: f64, sy: f64, sxy: f64) -> (f64, f64, f64) {
    let mean = 0.5 * (sx + sy);
    let half = 0.5 * (sx - sy);
    let radius = half.hypot(sxy);
    let theta = 0.5 * (2.0 * sxy).atan2(sx - sy);
    let mut deg = theta.to_degrees();
    if deg <= -90.0 {
        deg += 180.0;
    }
    (mean + radius, mean - radius, deg)
}

/// Stresses on one face at every element centre (element ie + je nx, as
/// [`super::ElementField`]).
#[derive(Debug, Clone, Default)]
pub struct FaceStress {
    /// σ_x.
    pub sx: Vec<f64>,
    /// σ_y.
    pub sy: Vec<f64>,
    /// τ_xy.
    pub sxy: Vec<f64>,
    /// Larger principal stress σ₁ (the largest tension where positive).
    pub s1: Vec<f64>,
    /// Smaller principal stress σ₂.
    pub s2: Vec<f64>,
    /// Direction of σ₁ from the x axis, degrees in (−90, 90].
    pub angle: Vec<f64>,
}

impl FaceStress {
    /// Push one element's stress state.
    pub fn push(&mut self, sx: f64, sy: f64, sxy: f64) {
        let (s1, s2, angle) = principal(sx, sy, sxy);
        self.sx.push(sx);
        self.sy.push(sy);
        self.sxy.push(sxy);
        self.s1.push(s1);
        self.s2.push(s2);
        self.angle.push(angle);
    }
}

/// The bottom and top faces' stresses of an element from its moments (m_x, m_y, m_xy per unit
/// length), its thickness `h` and the nonlinear temperature stresses `[top, bottom]` added to
/// both normal components: (bottom, top) as (σ_x, σ_y, τ_xy).
pub fn face_states(m: [f64; 3], h: f64, eigen: [f64; 2]) -> ([f64; 3], [f64; 3]) {
    let f = 6.0 / (h * h);
    let bottom = [f * m[0] + eigen[1], f * m[1] + eigen[1], f * m[2]];
    let top = [-f * m[0] + eigen[0], -f * m[1] + eigen[0], -f * m[2]];
    (bottom, top)
}

/// A face's largest principal stress at the nodes: the element components averaged over the
/// elements around each node, then their principal value.
pub(super) fn recover_principal(mesh: &Mesh, face: &FaceStress) -> Vec<f64> {
    let n = mesh.n_nodes();
    let mut sum = vec![[0.0; 3]; n];
    let mut count = vec![0u32; n];
    for e in mesh.elements() {
        for &node in &mesh.element_nodes(e) {
            sum[node][0] += face.sx[e];
            sum[node][1] += face.sy[e];
            sum[node][2] += face.sxy[e];
            count[node] += 1;
        }
    }
    sum.iter()
        .zip(&count)
        .map(|(s, &c)| {
            let c = f64::from(c.max(1));
            principal(s[0] / c, s[1] / c, s[2] / c).0
        })
        .collect()
}

/// The largest tension on a face and where it acts.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PeakTension {
    /// Largest principal stress σ₁ over the face's element centres (may be ≤ 0: no tension).
    pub value: f64,
    /// Direction of σ₁ there, degrees from the x axis.
    pub angle: f64,
    /// x of the element centre (m, or / L in a dimensionless scene).
    pub x: f64,
    /// y of the element centre.
    pub y: f64,
}

/// The peak tensions of both faces, as reported.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StressSummary {
    /// Bottom (soil side) face: traffic loads.
    pub bottom: PeakTension,
    /// Top face: night curling, corner loads.
    pub top: PeakTension,
    /// The plate's thickness (m, or H/L): the stresses' H, except in panels with a thickness
    /// of their own, which take theirs ([`super::ElementField::thickness`]).
    pub thickness: f64,
}

/// The largest σ₁ of a face and where; None for an empty face.
pub fn peak(face: &FaceStress, x: &[f64], y: &[f64]) -> Option<PeakTension> {
    let k = (0..face.s1.len()).max_by(|&a, &b| face.s1[a].total_cmp(&face.s1[b]))?;
    Some(PeakTension {
        value: face.s1[k],
        angle: face.angle[k],
        x: x[k],
        y: y[k],
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Mohr's circle by hand: (σx, σy, τ) = (3, −1, 2) has centre 1, radius √(4 + 4) = 2√2,
    /// σ₁ at ½·atan2(4, 4) = 22.5°; the invariants (trace, determinant) are kept.
    #[test]
    fn principal_stresses_of_a_hand_checked_state() {
        let (s1, s2, a) = principal(3.0, -1.0, 2.0);
        let r = 8f64.sqrt();
        assert!((s1 - (1.0 + r)).abs() < 1e-14, "σ₁ {s1}");
        assert!((s2 - (1.0 - r)).abs() < 1e-14, "σ₂ {s2}");
        assert!((a - 22.5).abs() < 1e-12, "θ {a}");
        // Rotating the state by θ makes it diagonal: τ' = −½(σx − σy) sin 2θ + τ cos 2θ = 0.
        let t = a.to_radians();
        let tau = -0.5 * 4.0 * (2.0 * t).sin() + 2.0 * (2.0 * t).cos();
        assert!(tau.abs() < 1e-14, "τ' {tau}");
        // Uniaxial along y: σ₁ at 90°, not −90°.
        let (s1, s2, a) = principal(0.0, 5.0, 0.0);
        assert_eq!((s1, s2, a), (5.0, 0.0, 90.0), "uniaxial y");
        // Pure shear: ±τ at 45°.
        let (s1, s2, a) = principal(0.0, 0.0, 1.0);
        assert!((s1 - 1.0).abs() < 1e-15 && (s2 + 1.0).abs() < 1e-15 && (a - 45.0).abs() < 1e-12);
    }

    /// σ = ±6m/H²: a unit moment on a plate 0.5 thick gives 24 at the bottom and −24 at the
    /// top; the nonlinear temperature stress adds to both normal components of its face.
    #[test]
    fn faces_from_moments() {
        let (b, t) = face_states([1.0, 0.5, 0.25], 0.5, [-2.0, 3.0]);
        assert_eq!(b, [24.0 + 3.0, 12.0 + 3.0, 6.0], "bottom");
        assert_eq!(t, [-24.0 - 2.0, -12.0 - 2.0, -6.0], "top");
    }

    /// Nodal recovery is the mean of the elements around a node, then its principal value: on
    /// 2 × 2 elements with σx = 1, 2, 3, 4 (σy = τ = 0, so σ₁ = σx) the corner node 0 has only
    /// element 0 (1), the edge node 1 elements 0 and 1 (1.5), the centre all four (2.5); a
    /// state equal in every element, (3, −1, 2), is kept at every node (σ₁ = 1 + 2√2, as above).
    #[test]
    fn nodal_principal_stress_is_the_mean_of_the_elements_around() {
        let mesh = Mesh::new(2.0, 2.0, [2, 2], false, false);
        let mut face = FaceStress::default();
        for sx in [1.0, 2.0, 3.0, 4.0] {
            face.push(sx, 0.0, 0.0);
        }
        let s1 = recover_principal(&mesh, &face);
        assert_eq!(s1.len(), 9);
        // Means of at most four small integers: round-off.
        for (node, want) in [(0, 1.0), (1, 1.5), (4, 2.5), (8, 4.0)] {
            assert!((s1[node] - want).abs() < 1e-14, "node {node}: {}", s1[node]);
        }
        let mut uniform = FaceStress::default();
        for _ in 0..4 {
            uniform.push(3.0, -1.0, 2.0);
        }
        let want = 1.0 + 8f64.sqrt();
        for (node, s) in recover_principal(&mesh, &uniform).iter().enumerate() {
            assert!((s - want).abs() < 1e-14, "node {node}: {s}");
        }
    }
}
