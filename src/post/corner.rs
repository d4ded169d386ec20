//! Re-entrant corners of a shaped plate: where they are, and the note the report gives instead
//! of presenting a stress there as a design number.
//!
//! At a corner where the plate's free edges meet at 270° the bending moment is singular. With
//! w ~ r^(λ+1) F(θ) the moments go as r^(λ−1); for Kirchhoff's free edges λ is the smallest
//! root in (0, 1) of (3 + ν) sin λα = ±(1 − ν) λ sin α, α = 3π/2 (Williams 1952; the minus
//! sign is the family antisymmetric about the corner's bisector, the leading one). Within a
//! thickness of the corner a Mindlin plate's rotations carry plane-stress energy with
//! traction-free edges, and the exponent is the plane wedge's, sin λα = −λ sin α (λ = 0.5445,
//! independent of ν). `tests/references/williams_corner.py` derives both from the 4 × 4
//! determinant; `tests/outlines.rs` shows liftoff's corner moment grow at either rate.

use super::field::FullField;
use super::stress::PeakTension;

/// The grid positions (i, j) of the re-entrant corners: grid nodes with exactly three of their
/// four cells plate (none on a plate that is its whole rectangle).
pub fn re_entrant(field: &FullField) -> Vec<(usize, usize)> {
    if field.plate.is_empty() {
        return Vec::new();
    }
    let (nx, ny) = (field.nx, field.ny);
    let cell = |i: usize, j: usize| field.is_plate(i, j);
    let mut out = Vec::new();
    for j in 1..ny {
        for i in 1..nx {
            let plate = [
                cell(i - 1, j - 1),
                cell(i, j - 1),
                cell(i - 1, j),
                cell(i, j),
            ];
            if plate.iter().filter(|&&p| p).count() == 3 {
                out.push((i, j));
            }
        }
    }
    out
}

/// λ of the free–free 270° corner of a Kirchhoff plate of Poisson's ratio `nu`: the leading
/// (antisymmetric) root of (3 + ν) sin λα = −(1 − ν) λ sin α in (0.5, 0.8), by bisection.
pub fn williams_lambda(nu: f64) -> f64 {
    let alpha = 1.5 * std::f64::consts::PI;
    let f = |l: f64| (3.0 + nu) * (l * alpha).sin() + (1.0 - nu) * l * alpha.sin();
    let (mut lo, mut hi) = (0.5, 0.8);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if f(lo) * f(mid) <= 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

/// λ of the plane wedge (a Mindlin plate within a thickness of the corner).
pub const MINDLIN_LAMBDA: f64 = 0.544_484;

/// The report's notes on the re-entrant corners of `field` (none on a rectangle): where they
/// are and how the moment grows there; and, when a peak tension sits in an element touching
/// one, that it is not a design value. `length` names the positions' unit and its factor on
/// the field's coordinates (`("m", 1.0)`, `("in", 1 / 0.0254)`, `("L", 1.0)`).
pub fn notes(
    field: &FullField,
    nu: f64,
    peaks: [(&str, &PeakTension); 2],
    length: (&str, f64),
) -> Vec<String> {
    let (length, scale) = length;
    let corners = re_entrant(field);
    let Some(&(i0, j0)) = corners.first() else {
        return Vec::new();
    };
    let n1 = field.nx + 1;
    let at = |i: usize, j: usize| (field.x[i + j * n1], field.y[i + j * n1]);
    let (x0, y0) = at(i0, j0);
    let (sx0, sy0) = (x0 * scale, y0 * scale);
    let lambda = williams_lambda(nu);
    let mut notes = vec![format!(
        "{} re-entrant corner{} (the first at ({sx0:.3}, {sy0:.3}) {length}): the bending moment is singular there, growing as r^{:.3} towards the corner (Kirchhoff's free edges at ν = {nu}; r^{:.3} within a thickness of it) — a stress read at a corner element grows as the mesh is refined and is not a design value: read it a thickness or more away, or design the corner for the singular field",
        corners.len(),
        if corners.len() > 1 { "s" } else { "" },
        lambda - 1.0,
        MINDLIN_LAMBDA - 1.0,
    )];
    // Cell sizes from the grid's first row and column.
    let hx = field.x[1] - field.x[0];
    let hy = field.y[n1] - field.y[0];
    for (face, p) in peaks {
        let near = corners.iter().find(|&&(i, j)| {
            let (x, y) = at(i, j);
            (p.x - x).abs() < hx.abs() && (p.y - y).abs() < hy.abs()
        });
        if let Some(&(i, j)) = near.filter(|_| p.value > 0.0) {
            let (x, y) = at(i, j);
            notes.push(format!(
                "the peak tension at the {face} ({:.3}, {:.3}) {length} is in an element at the re-entrant corner ({:.3}, {:.3}) {length}: it is the singular field's value at this mesh, not a design stress",
                p.x * scale,
                p.y * scale,
                x * scale,
                y * scale
            ));
        }
    }
    notes
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The roots of `tests/references/williams_corner.py`'s table (antisymmetric family) to its
    /// printed five digits.
    #[test]
    fn lambda_matches_the_reference_table() {
        for (nu, lambda) in [
            (0.0, 0.62232),
            (0.2, 0.63295),
            (0.3, 0.63787),
            (0.5, 0.64702),
        ] {
            assert!(
                (williams_lambda(nu) - lambda).abs() < 1e-5,
                "ν = {nu}: {} vs {lambda}",
                williams_lambda(nu)
            );
        }
        // The plane wedge's root of sin λα = −λ sin α.
        let alpha = 1.5 * std::f64::consts::PI;
        let r = (MINDLIN_LAMBDA * alpha).sin() + MINDLIN_LAMBDA * alpha.sin();
        assert!(r.abs() < 1e-5, "residual {r}");
    }

    /// An L of 4 × 4 cells has one re-entrant corner, at the grid node (2, 2).
    #[test]
    fn an_l_has_one_re_entrant_corner() {
        let mut field = FullField {
            nx: 4,
            ny: 4,
            ..FullField::default()
        };
        field.plate = (0..16).map(|c| !(c % 4 >= 2 && c / 4 >= 2)).collect();
        assert_eq!(re_entrant(&field), vec![(2, 2)]);
        field.plate.clear();
        assert!(re_entrant(&field).is_empty());
    }
}
