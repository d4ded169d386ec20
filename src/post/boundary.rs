//! The contact boundary inside the element.
//!
//! Contact is decided node by node, so the nodal pressures only say that the edge of contact
//! lies somewhere between the last node in contact and the first lifted one. To place it inside
//! that element we need a nodal quantity that changes sign *smoothly* there; its bilinear
//! interpolant's zero level set is then the boundary.
//!
//! # The would-be gap
//!
//! With w positive downward, the foundation's surface settles by 𝒯r and the gap between soil and
//! plate is g = 𝒯r − w ≥ 0; contact means r > 0 and g = 0. Neither r nor g changes sign at the
//! boundary: each vanishes on one side. Their combination
//!
//! φ = g − c r,
//!
//! with c > 0 the settlement a point's own pressure causes there, is the gap the point would have
//! if its own pressure were released: negative in contact (φ = −c r: the plate would penetrate
//! the soil there), equal to the gap where the plate lifted (r = 0). It is the quantity an
//! active-set iteration tests to decide contact.
//!
//! **Winkler** (𝒯r = r/K, c = 1/K): φ = r/K − w − r/K = −w. The edge of contact is where the
//! plate's deflection crosses the undeformed soil surface. Since the subgrade reaction K w⁺ is
//! continuous, w is smooth across the boundary (a Kirchhoff plate's w is C³ there), and it crosses
//! zero with a non-zero slope: for the axisymmetric plate below, w = F ln(r/a) outside with
//! F ≠ 0. Linear interpolation between the last node in contact and the first lifted node then
//! places the zero within ½ |w''/w'| θ(1 − θ) h² ≤ |w''/w'| h²/8 of the interpolant's, and the
//! nodal deflections themselves converge at O(h²): the boundary converges at second order
//! instead of the first order of a node-resolved boundary.
//!
//! Discretely, with the lumped Winkler coupling the nodal gap is g_i = a_i (σ_i/k − w_i),
//! a_i = ∫ f_i, and T_ii = a_i/k, so φ_i = g_i/a_i − (T_ii/a_i) σ_i = −w_i exactly, whatever the
//! method's tolerance: the penalty's small tensions at lifted nodes do not move the boundary.
//!
//! **Half-space.** The discrete analogue is φ_i = g_i/a_i − c σ_i with c = T_ii/a_i, the mean
//! settlement over f_i caused by a unit nodal pressure on f_i alone. We take c of an interior
//! node of the whole plate (every node alike, so the boundary does not depend on the symmetry
//! reduction); it is c_h h times a number of order one. Here φ is continuous and changes sign,
//! but it is not smooth: near a smooth receding boundary the pressure vanishes like A √d and the
//! gap opens like (4π/3) c_h A d^{3/2} (the plane asymptotics of a half-space), so both sides of
//! the element carry values of order c_h A h^{3/2} and linear interpolation places the zero within
//! a fixed fraction of h — first order with a small constant, not second (measured in
//! docs/METHODS.md).
//!
//! # Boundary, area, extents
//!
//! * **Segments**: marching squares on the bilinear φ of each element of the whole plate; the
//!   edge crossings are exact (φ is linear along an element edge), a saddle is resolved by the
//!   element-centre value.
//! * **Area**: the exact area of {φ < 0} of the bilinear φ in each element (a hyperbola's
//!   region, integrated in closed form), not the polygon of the segments — the two differ by
//!   O(h³) per boundary element. Sub-sampling (n × n points per element) would leave an error of
//!   order h/n per boundary element, i.e. first order in h again.
//! * **Extents** along the axes and the diagonal: the exact first zero of φ along the ray (linear
//!   along an axis, quadratic across an element on the diagonal).

use std::sync::OnceLock;

use serde::Serialize;

use super::field::FullField;
use crate::foundation::kernel::Kernel;
use crate::foundation::{nodal_areas, pairs};
use crate::operators::Operators;
use crate::quadrature::GaussRule;
use crate::solve::Solution;

/// One straight piece of the contact boundary inside one element of the whole plate.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BoundarySegment {
    /// Whole-plate element index ie + je nx.
    pub element: usize,
    /// End points in (s, t) = (x/L, y/(μL)).
    pub st: [(f64, f64); 2],
    /// End points in physical (x, y), as the field's x and y.
    pub xy: [(f64, f64); 2],
}

/// c of the module docs in the unit system: mean settlement over an interior node's shape
/// function caused by a unit nodal pressure on that function alone, T_ii / a_i of the whole
/// plate. Winkler: 1/k; half-space: the foundation constant times the self-integral of the
/// pyramid f_i over its four elements, divided by its area.
pub fn self_compliance(ops: &Operators) -> f64 {
    let c = ops.foundation_constant;
    match &ops.kernel {
        None => c,
        Some(kernel) => {
            let (hx, hy) = (ops.mesh.hx, ops.mesh.hy);
            c * pyramid_self_integral_of(kernel, hx, hy) / (hx * hy)
        }
    }
}

/// ∫∫ f(x) f(x') / |x − x'| dA' dA for the bilinear pyramid f of an interior node of a grid of
/// hx × hy elements, summed from the tabulated element-pair blocks.
pub fn pyramid_self_integral(hx: f64, hy: f64) -> f64 {
    pyramid_self_integral_of(
        &Kernel::new(crate::foundation::halfspace::Boussinesq),
        hx,
        hy,
    )
}

/// The same with any surface kernel K(|x − x'|) in place of 1/|x − x'|.
pub fn pyramid_self_integral_of(kernel: &Kernel, hx: f64, hy: f64) -> f64 {
    // The node's four elements (offsets from the node's lower-left element) and the node's
    // local index in each (counter-clockwise from the lower-left corner).
    const AROUND: [((isize, isize), usize); 4] =
        [((0, 0), 2), ((1, 0), 3), ((1, 1), 0), ((0, 1), 1)];
    let mut sum = 0.0;
    for &((i0, j0), a) in &AROUND {
        for &((i1, j1), b) in &AROUND {
            let (di, dj) = (i1 - i0, j1 - j0);
            let (a, b) = pairs::reflect(di, dj, a, b);
            sum += kernel.pair_block(di.unsigned_abs(), dj.unsigned_abs(), hx, hy)[a][b];
        }
    }
    sum
}

/// The would-be gap φ_i = g_i/a_i − c σ_i of every model node (unit system of deflections):
/// negative in contact, the gap where the plate lifted; −w_i on Winkler.
pub fn would_be_gap(ops: &Operators, sol: &Solution) -> Vec<f64> {
    let c = self_compliance(ops);
    let areas = nodal_areas(&ops.mesh);
    sol.gap
        .iter()
        .zip(&areas)
        .zip(&sol.sigma)
        .map(|((g, a), s)| g / a - c * s)
        .collect()
}

/// Points where a bilinear field is in contact: strictly negative.
fn inside(v: f64) -> bool {
    v < 0.0
}

/// 10-point Gauss–Legendre rule, built once.
fn rule() -> &'static GaussRule {
    static RULE: OnceLock<GaussRule> = OnceLock::new();
    RULE.get_or_init(|| GaussRule::new(10))
}

/// ∫_{x0}^{x1} (n0 + n1 x) / (d0 + d1 x) dx for a denominator without a zero inside the
/// interval. Far from the pole (≥ 3 half-lengths from the midpoint) a 10-point Gauss rule is
/// exact to round-off (Bernstein ellipse ρ ≥ 3 + √8, error ~ ρ⁻²⁰); near it the closed form
/// (n1/d1)Δx + (N(x_p)/d1) ln|D(x1)/D(x0)|, x_p = −d0/d1, is well conditioned.
fn ratio_integral(n: (f64, f64), d: (f64, f64), x0: f64, x1: f64) -> f64 {
    let half = 0.5 * (x1 - x0);
    let dm = d.0 + d.1 * (x0 + half);
    if 3.0 * (d.1 * half).abs() <= dm.abs() {
        return rule()
            .on_interval(x0, x1)
            .map(|(x, w)| w * (n.0 + n.1 * x) / (d.0 + d.1 * x))
            .sum();
    }
    let xp = -d.0 / d.1;
    let k = n.0 + n.1 * xp;
    let (da, db) = (d.0 + d.1 * x0, d.0 + d.1 * x1);
    // Where D vanishes on an end point the integrand stays bounded (it is a length in [0, 1]),
    // so N vanishes there too and k = 0 up to round-off: drop the log term.
    let log = if da == 0.0 || db == 0.0 {
        0.0
    } else {
        (db / da).abs().ln()
    };
    (n.1 / d.1) * (x1 - x0) + k / d.1 * log
}

/// Fraction of an element where the bilinear interpolant of its corner values is negative,
/// exactly. Corners counter-clockwise from the lower-left: f = [f(0,0), f(1,0), f(1,1), f(0,1)].
///
/// For fixed x the field is linear in y, from p(x) on the bottom edge to r(x) on the top one, so
/// the negative part of that vertical line has length 1, 0, p/(p − r) or r/(r − p); between the
/// zeros of p and r that length is a ratio of linear functions of x, integrated exactly.
pub fn negative_fraction(f: [f64; 4]) -> f64 {
    if f.iter().all(|&v| inside(v)) {
        return 1.0;
    }
    if !f.iter().any(|&v| inside(v)) {
        return 0.0;
    }
    let [f00, f10, f11, f01] = f;
    let p = (f00, f10 - f00);
    let r = (f01, f11 - f01);
    let mut cuts = vec![0.0, 1.0];
    for (c0, c1) in [p, r] {
        if c1 != 0.0 {
            let x = -c0 / c1;
            if x > 0.0 && x < 1.0 {
                cuts.push(x);
            }
        }
    }
    cuts.sort_by(f64::total_cmp);
    let mut total = 0.0;
    for w in cuts.windows(2) {
        let (x0, x1) = (w[0], w[1]);
        if x1 <= x0 {
            continue;
        }
        let xm = 0.5 * (x0 + x1);
        let (pm, rm) = (p.0 + p.1 * xm, r.0 + r.1 * xm);
        let piece = match (inside(pm), inside(rm)) {
            (true, true) => x1 - x0,
            (false, false) => 0.0,
            // Negative below y* = p/(p − r).
            (true, false) => ratio_integral(p, (p.0 - r.0, p.1 - r.1), x0, x1),
            // Negative above y*: length r/(r − p).
            (false, true) => ratio_integral(r, (r.0 - p.0, r.1 - p.1), x0, x1),
        };
        total += piece.clamp(0.0, x1 - x0);
    }
    total.clamp(0.0, 1.0)
}

impl FullField {
    /// Contact area / plate area (a shaped plate's own cells): the exact area of {φ < 0} of the bilinear would-be gap,
    /// element by element ([`negative_fraction`]), each from its own corners (its own side of
    /// a joint). Exactly 1 when every node is in contact.
    pub fn contact_fraction(&self) -> f64 {
        let (mut sum, mut cells) = (0.0, 0);
        for j in 0..self.ny {
            for i in (0..self.nx).filter(|&i| self.is_plate(i, j)) {
                sum += negative_fraction(self.element_nodes(i, j).map(|k| self.signed_gap[k]));
                cells += 1;
            }
        }
        sum / cells.max(1) as f64
    }

    /// The contact boundary: the zero level set of the bilinear would-be gap by marching
    /// squares, one or two segments per element it crosses, each oriented with the contact side
    /// on its left (so closed curves run counter-clockwise around contact).
    pub fn contact_boundary(&self) -> Vec<BoundarySegment> {
        let mut out = Vec::new();
        for j in 0..self.ny {
            for i in (0..self.nx).filter(|&i| self.is_plate(i, j)) {
                let c = self.element_nodes(i, j);
                let f = c.map(|k| self.signed_gap[k]);
                let ins = f.map(inside);
                // Crossing on edge e (corners e and e + 1), where φ is linear, with its local
                // coordinates (ξ, η) ∈ [0, 1]².
                let cross = |e: usize| -> Option<BoundaryPoint> {
                    let (a, b) = (e, (e + 1) % 4);
                    if ins[a] == ins[b] {
                        return None;
                    }
                    let t = (f[a] / (f[a] - f[b])).clamp(0.0, 1.0);
                    let (na, nb) = (c[a], c[b]);
                    let lerp = |v: &[f64]| v[na] + t * (v[nb] - v[na]);
                    let local = match e {
                        0 => (t, 0.0),
                        1 => (1.0, t),
                        2 => (1.0 - t, 1.0),
                        _ => (0.0, 1.0 - t),
                    };
                    Some(BoundaryPoint {
                        local,
                        st: (lerp(&self.s), lerp(&self.t)),
                        xy: (lerp(&self.x), lerp(&self.y)),
                    })
                };
                let mut push = |p: BoundaryPoint, q: BoundaryPoint| {
                    // Contact (φ < 0) lies to the left when φ decreases along the left normal
                    // (−dη, dξ); orientation is the same in (ξ, η), (s, t) and (x, y).
                    let (xi, eta) = (0.5 * (p.local.0 + q.local.0), 0.5 * (p.local.1 + q.local.1));
                    let dxi = (f[1] - f[0]) * (1.0 - eta) + (f[2] - f[3]) * eta;
                    let deta = (f[3] - f[0]) * (1.0 - xi) + (f[2] - f[1]) * xi;
                    let (dx, dy) = (q.local.0 - p.local.0, q.local.1 - p.local.1);
                    let (p, q) = if -dy * dxi + dx * deta <= 0.0 {
                        (p, q)
                    } else {
                        (q, p)
                    };
                    out.push(BoundarySegment {
                        element: i + j * self.nx,
                        st: [p.st, q.st],
                        xy: [p.xy, q.xy],
                    })
                };
                let edges: Vec<BoundaryPoint> = (0..4).filter_map(cross).collect();
                match edges.as_slice() {
                    [p, q] => push(*p, *q),
                    [_, _, _, _] => {
                        // Saddle: cut off the corners whose state differs from the centre's.
                        let centre = inside(f.iter().sum::<f64>() / 4.0);
                        for (k, &corner) in ins.iter().enumerate() {
                            if corner != centre {
                                if let (Some(p), Some(q)) = (cross((k + 3) % 4), cross(k)) {
                                    push(p, q);
                                }
                            }
                        }
                    }
                    _ => {}
                }
            }
        }
        out
    }

    /// Parameters u ∈ (0, 1) at which the bilinear would-be gap changes sign along the straight
    /// line from `a` to `b` (in (s, t)), ascending. Between grid lines the field is a quadratic in
    /// u; each monotone piece with a sign change is bisected to round-off.
    pub fn boundary_crossings(&self, a: (f64, f64), b: (f64, f64)) -> Vec<f64> {
        let at = |u: f64| {
            self.interpolate(
                &self.signed_gap,
                a.0 + u * (b.0 - a.0),
                a.1 + u * (b.1 - a.1),
            )
        };
        let mut cuts = vec![0.0, 1.0];
        for (p, q, n) in [(a.0, b.0, self.nx), (a.1, b.1, self.ny)] {
            if q != p {
                for k in 0..=n {
                    let line = -1.0 + 2.0 * k as f64 / n as f64;
                    let u = (line - p) / (q - p);
                    if u > 0.0 && u < 1.0 {
                        cuts.push(u);
                    }
                }
            }
        }
        cuts.sort_by(f64::total_cmp);
        cuts.dedup_by(|x, y| (*x - *y).abs() < 1e-14);
        let mut roots = Vec::new();
        for w in cuts.windows(2) {
            let (u0, u1) = (w[0], w[1]);
            // q(τ) = α τ² + β τ + γ through the piece's end and mid values.
            let (q0, qm, q1) = (at(u0), at(0.5 * (u0 + u1)), at(u1));
            let alpha = 2.0 * (q0 - 2.0 * qm + q1);
            let beta = q1 - q0 - alpha;
            let mut pieces = vec![u0, u1];
            if alpha != 0.0 {
                let tc = -beta / (2.0 * alpha);
                if tc > 0.0 && tc < 1.0 {
                    pieces.insert(1, u0 + tc * (u1 - u0));
                }
            }
            for p in pieces.windows(2) {
                let (mut lo, mut hi) = (p[0], p[1]);
                let lo_in = inside(at(lo));
                if lo_in == inside(at(hi)) {
                    continue;
                }
                for _ in 0..200 {
                    let mid = 0.5 * (lo + hi);
                    if mid <= lo || mid >= hi {
                        break;
                    }
                    if inside(at(mid)) == lo_in {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                let u = 0.5 * (lo + hi);
                if roots.last().is_none_or(|&r: &f64| u - r > 1e-14) {
                    roots.push(u);
                }
            }
        }
        roots
    }

    /// Distance from the centre along (ds, dt) in (s, t) to the first zero of the would-be gap,
    /// as a fraction of the ray's length to the plate edge; 0 if the centre is not in contact, 1
    /// if the whole ray is.
    pub fn contact_extent_along(&self, ds: f64, dt: f64) -> f64 {
        if !inside(self.interpolate(&self.signed_gap, 0.0, 0.0)) {
            return 0.0;
        }
        self.boundary_crossings((0.0, 0.0), (ds, dt))
            .first()
            .copied()
            .unwrap_or(1.0)
    }

    /// Contact pressure σ at (s, t), ending at the located boundary: the bilinear σ, but in an
    /// element the boundary crosses no more than the released would-be gap −φ/c allows, and not
    /// below zero because of it. Equal to the nodal σ at every node (to the solver's tolerance);
    /// on Winkler it is k·max(w, 0) in the boundary elements; a bonded solution (φ = −cσ) keeps
    /// its bilinear σ, tensions included.
    pub fn pressure_at(&self, s: f64, t: f64) -> f64 {
        let sigma = self.interpolate(&self.sigma, s, t);
        let released = -self.interpolate(&self.signed_gap, s, t) / self.gap_per_sigma;
        sigma.min(released.max(0.0))
    }
}

#[derive(Debug, Clone, Copy)]
struct BoundaryPoint {
    local: (f64, f64),
    st: (f64, f64),
    xy: (f64, f64),
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Brute-force midpoint sampling of the negative part of a bilinear field.
    fn sampled(f: [f64; 4], n: usize) -> f64 {
        let mut count = 0usize;
        for p in 0..n {
            for q in 0..n {
                let x = (p as f64 + 0.5) / n as f64;
                let y = (q as f64 + 0.5) / n as f64;
                let v = f[0] * (1.0 - x) * (1.0 - y)
                    + f[1] * x * (1.0 - y)
                    + f[2] * x * y
                    + f[3] * (1.0 - x) * y;
                if v < 0.0 {
                    count += 1;
                }
            }
        }
        count as f64 / (n * n) as f64
    }

    /// Linear fields have polygonal negative parts with areas by hand: a corner triangle, a
    /// trapezium, and the complement of a corner triangle.
    #[test]
    fn negative_fraction_of_linear_fields_is_the_polygon_area() {
        // f = x + y − ½: negative in the triangle below the anti-diagonal through (½, 0): 1/8.
        let f = [-0.5, 0.5, 1.5, 0.5];
        assert!(
            (negative_fraction(f) - 0.125).abs() < 1e-15,
            "corner triangle"
        );
        // f = x − 0.3: a vertical strip of width 0.3.
        let f = [-0.3, 0.7, 0.7, -0.3];
        assert!((negative_fraction(f) - 0.3).abs() < 1e-15, "strip");
        // f = y − 0.25 x − 0.5: trapezium of mean height 0.625.
        let f = [-0.5, -0.75, 0.25, 0.5];
        assert!((negative_fraction(f) - 0.625).abs() < 1e-15, "trapezium");
        // −(x + y − ½): complement of the corner triangle.
        let f = [0.5, -0.5, -1.5, -0.5];
        assert!((negative_fraction(f) - 0.875).abs() < 1e-15, "complement");
    }

    /// The hyperbola x y < c (f = x y − c) has area c (1 − ln c) in the unit square.
    #[test]
    fn negative_fraction_of_a_hyperbola_is_c_times_one_minus_ln_c() {
        for c in [0.01_f64, 0.2, 0.5, 0.9] {
            let f = [-c, -c, 1.0 - c, -c];
            let exact: f64 = c * (1.0 - c.ln());
            let got = negative_fraction(f);
            assert!((got - exact).abs() < 1e-14, "xy < {c}: {got} vs {exact}");
        }
    }

    /// Random fields, saddles included, against 2000² sampling (error ≲ perimeter / 2000).
    #[test]
    fn negative_fraction_matches_sampling_on_random_fields() {
        let mut seed = 12345u64;
        let mut rnd = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        };
        for k in 0..40 {
            let f = [rnd(), rnd(), rnd(), rnd()];
            let exact = negative_fraction(f);
            let s = sampled(f, 2000);
            assert!(
                (exact - s).abs() < 2e-3,
                "field {k} {f:?}: exact {exact} vs sampled {s}"
            );
        }
        // An exact saddle: f = (x − ½)(y − ½) is negative on two opposite quarters.
        let f = [0.25, -0.25, 0.25, -0.25];
        assert!((negative_fraction(f) - 0.5).abs() < 1e-15, "saddle");
        // A degenerate one: zero along x = ½ and y = ½ with positive part on one quarter only.
        let near = [0.25 + 1e-13, -0.25, 0.25, -0.25];
        assert!((negative_fraction(near) - 0.5).abs() < 1e-9, "near saddle");
    }

    /// The interior pyramid's self-integral matches the assembled T of a whole plate far from
    /// its edges (same pair blocks, independent assembly and indexing), and scales like h³.
    #[test]
    fn pyramid_self_integral_matches_the_assembled_compliance() {
        let mesh = crate::mesh::Mesh::new(2.0, 2.0, [8, 8], false, false);
        let t = crate::foundation::halfspace::dense_matrix(&mesh, 1.0);
        let n = mesh.node(4, 4);
        let mine = pyramid_self_integral(mesh.hx, mesh.hy);
        assert!(
            (t[(n, n)] - mine).abs() < 1e-12 * mine,
            "T_ii {} vs {mine}",
            t[(n, n)]
        );
        let scaled = pyramid_self_integral(0.5 * mesh.hx, 0.5 * mesh.hy);
        assert!((scaled * 8.0 - mine).abs() < 1e-9 * mine, "h³ scaling");
    }
}
