//! The preconditioner's soil fitted to the half-space: springs and a shear layer,
//!
//! W = s R (k I + L) R,
//!
//! L the graph Laplacian of the element edges ([`SpringPlate::links`], weights 1/h²: the
//! five-point symbol ℓ̂(ξ) = (4/hx²) sin²(ξx hx/2) + (4/hy²) sin²(ξy hy/2)), R = diag(√(t₀/t_jj))
//! the nodes' share of an interior node's diagonal of T (half at an edge, a quarter at a corner,
//! as the springs λ·diag(T) have it), k and s fitted to T's symbol.
//!
//! Why: the preconditioner M = W⁻¹ + QᵀK_p⁻Q holds the plate exactly, so what is left to the
//! iteration is how far W⁻¹ is from T where T dominates A — above the wavenumbers where the
//! plate takes over, up to the grid's. A continuum's compliance falls like 1/|ξ| there (the
//! half-space's 2(1 − ν²)/(E|ξ|)); springs are flat, so M⁻¹A spreads over the band's whole
//! ratio (on the lane's 64² panels, a condition number of about 90 from the symbols), while
//! k + ℓ̂(ξ) falls with T across it (about 5: from 7–10 conjugate-gradient iterations a decade
//! to 2–3). A Pasternak layer is this W's continuum: springs k and a membrane of tension G.
//!
//! The fit reads T's symbol from one product: the column u = T e₀ of a node e₀ near the middle
//! of the model, tapered to zero over the outer half of its distance R to the model's edge,
//! T̂(ξ) = Σ_i u_i cos(ξ · (x_i − x₀)), at wavenumbers along both axes and the diagonal from the
//! grid's (π/h) down to 1/(2ℓ) (ℓ the plate's radius of relative stiffness: below it the plate
//! dominates) but not below [`READABLE`]/R (where the plate's edge cuts the sum). k minimises
//! the ratio max/min of T̂(ξ)(k + ℓ̂(ξ)) over those samples, no smaller than the lowest sample's
//! ℓ̂ (below the samples the layer is springs); s centres that ratio on one (its geometric
//! mean).

use super::springs::{SpringPlate, Springs};
use crate::operators::Operators;

/// Springs and a shear layer fitted to T ([`fit`]).
#[derive(Clone, Debug)]
pub(super) struct ShearLayer {
    /// s: the scale of W.
    s: f64,
    /// k: the springs against the links' 1/h².
    k: f64,
    /// R per pressure node.
    r: Vec<f64>,
    /// The ratio max/min of T̂(ξ)(k + ℓ̂(ξ)) over the samples: the condition number the fit
    /// leaves where T dominates (read by the tests).
    #[cfg_attr(not(test), allow(dead_code))]
    pub(super) spread: f64,
}

/// |ξ|R above which the probe's windowed sum reads T̂ to a few per cent (R the probe's reach:
/// 1 % at |ξ|R = 20–30 on the half-space, tests below; ±30 % at 2–15 without the window).
const READABLE: f64 = 10.0;

/// Elements a side of the model below which springs stand in for the layer: the probe's
/// window then keeps T's column only within a few elements, too little of the kernel to read
/// its symbol. On a 6 × 6 plate (a case of tests/exactness.rs) the layer fitted there took 12
/// penalty steps where springs took 7, and its confirming solve at ε̄ = 1e-8 left V 4e-6 off the
/// QP, against 2e-7 with springs. The iterative route's own threshold (1 500 pressure nodes,
/// [`crate::method::Route`]) is far above.
pub(super) const MIN_ELEMENTS: usize = 16;

/// Samples per unit interval of a direction's wavenumbers (linear up to π/h) and below it
/// (halvings).
const LINEAR_SAMPLES: usize = 24;
const HALVINGS: usize = 6;

/// W for these penalty diagonals `pen` (0 where a point is not penalised) and held points,
/// with springs λ·diag(T) (`spring_scale`, `t_diag`) where no layer is fitted.
///
/// * held: W_jj = 0, no link (the point is off the system);
/// * penalised (lifted, or being pushed off): springs 1/(λ t_jj + d_j), no link — the penalty
///   dominates the point, as with springs alone;
/// * in contact: the layer's W, its links to the other points in contact kept; a link to a
///   held or penalised point keeps its share of W_jj (the layer held at zero there rather than
///   ended: the half-space under a region in contact is stiffer at the region's edge, as a
///   punch's pressure peaks there, not softer).
pub(super) fn springs(
    plate: &SpringPlate,
    layer: Option<&ShearLayer>,
    (t_diag, spring_scale): (&[f64], f64),
    pen: &[f64],
    held: impl Fn(usize) -> bool,
) -> Springs {
    let diagonal = |j: usize| {
        if held(j) {
            0.0
        } else {
            1.0 / (spring_scale * t_diag[j] + pen[j])
        }
    };
    let Some(layer) = layer else {
        return Springs::diagonal((0..t_diag.len()).map(diagonal).collect());
    };
    let soil = |j: usize| !held(j) && pen[j] == 0.0;
    let mut diag: Vec<f64> = (0..t_diag.len())
        .map(|j| {
            if soil(j) {
                layer.s * layer.r[j] * layer.r[j] * layer.k
            } else {
                diagonal(j)
            }
        })
        .collect();
    let off = plate
        .links
        .iter()
        .map(|link| {
            let (i, j) = link.nodes;
            let (ri, rj) = (layer.r[i], layer.r[j]);
            if soil(i) {
                diag[i] += layer.s * ri * ri * link.weight;
            }
            if soil(j) {
                diag[j] += layer.s * rj * rj * link.weight;
            }
            if soil(i) && soil(j) {
                -layer.s * ri * rj * link.weight
            } else {
                0.0
            }
        })
        .collect();
    Springs { diag, off }
}

/// The layer fitted to `ops`' compliance T (diagonal `t_diag`); None for a local soil (T
/// diagonal: springs are exact) or where T's symbol cannot be read: a model of fewer than
/// [`MIN_ELEMENTS`] elements a side, a non-positive sample.
pub(super) fn fit(ops: &Operators, t_diag: &[f64]) -> Option<ShearLayer> {
    if matches!(ops.t.as_ref(), crate::foundation::Compliance::Diagonal(_)) {
        return None;
    }
    let m = &ops.mesh;
    if m.nx < MIN_ELEMENTS || m.ny < MIN_ELEMENTS || t_diag.len() != ops.n_sigma() {
        return None;
    }
    let Probe {
        node: probe,
        reach,
        offsets,
    } = probe(ops)?;
    let ell = ops.foundation.stiffness_length(ops.foundation_constant);
    let h = m.hx.max(m.hy);
    // Down to 1/(2ℓ), or to a quarter of the grid's wavenumber for a plate thinner than that.
    // Nor below READABLE/R, where the window's cut-off of T's column (R its reach) leaves more
    // than a few per cent of T̂.
    let lowest = (0.5 / ell)
        .min(0.25 * std::f64::consts::PI / h)
        .max(READABLE / reach);
    let mut samples = Vec::new();
    for (dx, dy) in [(1.0, 0.0), (0.0, 1.0), (1.0, 1.0)] {
        let fractions = (1..=LINEAR_SAMPLES)
            .map(|p| p as f64 / LINEAR_SAMPLES as f64)
            .chain((1..=HALVINGS).map(|q| 0.5f64.powi(q as i32) / LINEAR_SAMPLES as f64));
        for f in fractions {
            let (kx, ky) = (
                dx * f * std::f64::consts::PI / m.hx,
                dy * f * std::f64::consts::PI / m.hy,
            );
            if kx.hypot(ky) < lowest {
                continue;
            }
            let symbol = symbol(&offsets, kx, ky);
            let lap = 4.0 / (m.hx * m.hx) * (0.5 * kx * m.hx).sin().powi(2)
                + 4.0 / (m.hy * m.hy) * (0.5 * ky * m.hy).sin().powi(2);
            if !(symbol > 0.0 && symbol.is_finite()) {
                return None;
            }
            samples.push((symbol, lap));
        }
    }
    if samples.len() < 4 {
        return None;
    }
    let ratio = |k: f64| {
        let (lo, hi) = samples
            .iter()
            .map(|&(t, l)| t * (k + l))
            .fold((f64::INFINITY, 0.0f64), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            });
        (hi / lo, (hi * lo).sqrt())
    };
    // k from the lowest sample's ℓ̂ (below the samples the layer is to be springs: what it does
    // there is not read) up to a thousand times the grid's, eight steps a decade (the ratio is
    // flat near its minimum: a finer step changes it by well under a per cent).
    let k_min = lowest * lowest;
    let decades = (1e3 / (h * h * k_min)).log10().max(0.0);
    let (k, (spread, mean)) = (0..=(8.0 * decades).ceil() as usize)
        .map(|p| k_min * 10f64.powf(p as f64 / 8.0))
        .map(|k| (k, ratio(k)))
        .min_by(|a, b| a.1 .0.total_cmp(&b.1 .0))?;
    let t0 = t_diag[probe];
    let r = t_diag
        .iter()
        .map(|&t| if t > 0.0 { (t0 / t).sqrt() } else { 1.0 })
        .collect();
    Some(ShearLayer {
        s: 1.0 / mean,
        k,
        r,
        spread,
    })
}

/// The probe node (an interior one — the largest nodal area — nearest the model's middle) and
/// T's column there as (x_i − x₀, y_i − y₀, u_i) over the nodes it reaches, tapered to zero
/// by a cosine window from half the distance R to the model's nearest edge out to R: the sum
/// over the finite plate cuts a slowly decaying kernel (1/ρ) off at its edge, which rings in
/// T̂ by about 1/(|ξ|R) of it (±30 % along the axes at |ξ|R = 4–15 without the window, on the
/// test's plate), and a smooth cut-off only blurs T̂ over Δξ ~ 1/R.
fn probe(ops: &Operators) -> Option<Probe> {
    let m = &ops.mesh;
    let n = ops.n_sigma();
    let areas = crate::foundation::nodal_areas(m);
    let full = areas.iter().copied().fold(0.0, f64::max);
    let (cx, cy) = (
        m.x0 + 0.5 * m.nx as f64 * m.hx,
        m.y0 + 0.5 * m.ny as f64 * m.hy,
    );
    let distance = |j: usize| {
        let (x, y) = m.node_xy(j);
        (x - cx).hypot(y - cy)
    };
    let probe = (0..n)
        .filter(|&j| areas[j] >= 0.999 * full)
        .min_by(|&a, &b| distance(a).total_cmp(&distance(b)))?;
    let mut e = vec![0.0; n];
    e[probe] = 1.0;
    let u = ops.t.apply(&e);
    let (x0, y0) = m.node_xy(probe);
    let (x1, y1) = (m.x0 + m.nx as f64 * m.hx, m.y0 + m.ny as f64 * m.hy);
    let reach = (x0 - m.x0).min(x1 - x0).min(y0 - m.y0).min(y1 - y0);
    let window = |r: f64| {
        if r <= 0.5 * reach {
            1.0
        } else if r >= reach {
            0.0
        } else {
            (std::f64::consts::PI * (r / reach - 0.5)).cos().powi(2)
        }
    };
    let offsets = (0..n)
        .filter_map(|i| {
            let (x, y) = m.node_xy(i);
            let v = u[i] * window((x - x0).hypot(y - y0));
            (v != 0.0).then_some((x - x0, y - y0, v))
        })
        .collect();
    Some(Probe {
        node: probe,
        reach,
        offsets,
    })
}

/// T's column at a probe node ([`probe`]).
struct Probe {
    node: usize,
    /// R: its distance to the model's nearest edge.
    reach: f64,
    /// (x_i − x₀, y_i − y₀, u_i), windowed.
    offsets: Vec<(f64, f64, f64)>,
}

/// T̂(ξ) = Σ_i u_i cos(ξ · (x_i − x₀)) from the probe's column.
fn symbol(offsets: &[(f64, f64, f64)], kx: f64, ky: f64) -> f64 {
    offsets
        .iter()
        .map(|&(x, y, v)| v * (kx * x + ky * y).cos())
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A large plate on the half-space, whole model, `n` elements a side, on the FFT route.
    fn halfspace(n: usize) -> Operators {
        let text = crate::examples::scene("paper-halfspace").unwrap_or_default();
        let text = text
            .replace("elements = [16, 16]", &format!("elements = [{n}, {n}]"))
            .replace("symmetry = \"auto\"", "symmetry = \"none\"");
        let p = crate::scene::Problem::from_toml(&text).expect("paper scene");
        Operators::assemble_with(&p.model, true)
    }

    /// The probe reads the half-space's symbol: the Galerkin T of c/ρ (c = (1 − ν²)/(πE)) has
    /// T̂(ξ) = 2πc A (sinc(ξx hx/2) sinc(ξy hy/2))⁴/|ξ| away from the grid's wavenumber (A the
    /// element area: the Fourier transform of 1/ρ is 2π/|ξ|, each bilinear function's is
    /// A sinc², and the sum over nodes samples at one node per area A). Between 20/R (R the
    /// probe's distance to the plate's edge, where the window's cut-off leaves a few per cent)
    /// and a tenth of the grid's wavenumber (where the aliases are 1e-5 of it), along both axes
    /// and the diagonal, the sum is within 3 % of it (1.1 % here; T's factor A or a sinc power
    /// wrong would be 10 % off or more, a window too short ±30 %).
    #[test]
    fn the_probe_reads_the_half_spaces_symbol() {
        let ops = halfspace(192);
        let offsets = probe(&ops).expect("probe").offsets;
        let m = &ops.mesh;
        let area = m.hx * m.hy;
        // The whole square plate, probe at its centre: R is half its width.
        let reach = 0.5 * m.hx * m.full_elements()[0] as f64;
        let c = ops.foundation_constant;
        let sinc = |x: f64| if x == 0.0 { 1.0 } else { x.sin() / x };
        let mut worst = 0.0f64;
        for f in [20.0, 25.0, 30.0] {
            let k = f / reach;
            assert!(k * m.hx <= 0.1 * std::f64::consts::PI, "sample {f}");
            for (kx, ky) in [(k, 0.0), (0.0, k), (k / 2f64.sqrt(), k / 2f64.sqrt())] {
                let exact = 2.0 * std::f64::consts::PI * c * area / kx.hypot(ky)
                    * (sinc(0.5 * kx * m.hx) * sinc(0.5 * ky * m.hy)).powi(4);
                let read = symbol(&offsets, kx, ky);
                worst = worst.max((read / exact - 1.0).abs());
            }
        }
        assert!(worst < 0.03, "symbol off by {worst:.3}");
    }

    /// The fit leaves a ratio max/min of T̂(k + ℓ̂) of about 5 on the half-space (the symbols'
    /// estimate: 4.8), and R is one inside and above it at the edges.
    #[test]
    fn the_layer_follows_the_half_space_across_the_band() {
        let ops = halfspace(96);
        let t_diag = ops.t.diagonal();
        let layer = fit(&ops, &t_diag).expect("a layer on the half-space");
        assert!(
            layer.spread > 1.0 && layer.spread < 8.0,
            "spread {}",
            layer.spread
        );
        assert!(layer.s > 0.0 && layer.k > 0.0);
        assert!(layer.r.iter().all(|&r| r.is_finite() && r >= 1.0 - 1e-12));
    }
}
