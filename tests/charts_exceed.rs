//! The bearing check's geometry on fields with closed forms: the area above a level of a
//! bilinear nodal field ([`area_above`]) and its contour ([`level_contour`]), on a plate in
//! physical coordinates (a 12 m × 8 m slab, 7 × 5 elements so that the levels cut elements).

use liftoff::post::exceed::{area_above, level_contour, pieces_above};
use liftoff::post::FullField;

/// A (2 lx) × (2 ly) plate of nx × ny elements centred on the origin with the nodal values
/// f(x, y); only the coordinates matter here.
fn plate(lx: f64, ly: f64, nx: usize, ny: usize, f: impl Fn(f64, f64) -> f64) -> FullField {
    let n = (nx + 1) * (ny + 1);
    let mut field = FullField {
        nx,
        ny,
        x: Vec::with_capacity(n),
        y: Vec::with_capacity(n),
        s: Vec::with_capacity(n),
        t: Vec::with_capacity(n),
        w: vec![0.0; n],
        psi_x: vec![0.0; n],
        psi_y: vec![0.0; n],
        pressure: Vec::with_capacity(n),
        gap: vec![0.0; n],
        signed_gap: vec![0.0; n],
        gap_per_sigma: 1.0,
        v: vec![0.0; n],
        sigma: vec![0.0; n],
        contact: vec![true; n],
        s1_bottom: vec![0.0; n],
        s1_top: vec![0.0; n],
        ..FullField::default()
    };
    for j in 0..=ny {
        for i in 0..=nx {
            let s = -1.0 + 2.0 * i as f64 / nx as f64;
            let t = -1.0 + 2.0 * j as f64 / ny as f64;
            field.s.push(s);
            field.t.push(t);
            field.x.push(s * lx);
            field.y.push(t * ly);
            field.pressure.push(f(s * lx, t * ly));
        }
    }
    field
}

/// p = a + b x on [−6, 6] × [−4, 4] m exceeds c for x > x* = (c − a)/b: the strip
/// (6 − x*) × 8 m². The field is linear, so the area and the contour are exact up to
/// round-off (relative 1e-13 allows a few ulps summed over 35 elements).
#[test]
fn linear_ramp_area_and_contour_are_the_closed_form() {
    let (a, b) = (50e3, 4e3); // Pa, Pa/m
    let f = plate(6.0, 4.0, 7, 5, |x, _| a + b * x);
    for c in [30e3, 51.5e3, 68e3] {
        let x_star: f64 = (c - a) / b;
        let exact = (6.0 - x_star) * 8.0;
        let area = area_above(&f, &f.pressure, c).expect("area");
        assert!(
            (area - exact).abs() < 1e-13 * 96.0,
            "level {c}: area {area} m² vs {exact} m²"
        );
        // One straight contour from the bottom edge to the top one, on x = x*.
        let lines = level_contour(&f, &f.pressure, c).expect("contour");
        assert_eq!(lines.len(), 1, "level {c}: {lines:?}");
        let line = &lines[0];
        assert_eq!(line.len(), 6, "one crossing per horizontal grid line");
        for &(x, y) in line {
            let p = a + b * x;
            assert!((p - c).abs() < 1e-10 * c, "({x}, {y}): p = {p} vs {c}");
            assert!((x - x_star).abs() < 1e-13 * 6.0, "x = {x} vs {x_star}");
        }
        let ys: Vec<f64> = line.iter().map(|p| p.1).collect();
        assert!(
            (ys[0].abs() - 4.0).abs() < 1e-15 && (ys[5].abs() - 4.0).abs() < 1e-15,
            "ends on the plate's edges: {ys:?}"
        );
        // The pieces above the level tile the same strip.
        let tiled: f64 = pieces_above(&f, &f.pressure, c)
            .expect("pieces")
            .iter()
            .map(|p| shoelace(p))
            .sum();
        assert!((tiled - exact).abs() < 1e-12, "pieces {tiled} vs {exact}");
    }
    // Nothing above the top of the ramp, everything above the bottom: 0 and the plate.
    assert_eq!(area_above(&f, &f.pressure, a + 7.0 * b).expect("area"), 0.0);
    let all = area_above(&f, &f.pressure, a - 7.0 * b).expect("area");
    assert!((all - 96.0).abs() < 1e-12, "whole plate {all}");
}

/// A tilted plane p = x + 2 y on [−6, 6] × [−4, 4] above c = 4: the triangle cut off the
/// corner (6, 4) by x + 2y = 4, with legs 10 (along x, at y = 4: x from −4 to 6) and 5
/// (along y, at x = 6: y from −1 to 4): area 25 m². Crosses elements diagonally.
#[test]
fn tilted_plane_cuts_the_closed_form_triangle() {
    let f = plate(6.0, 4.0, 7, 5, |x, y| x + 2.0 * y);
    let area = area_above(&f, &f.pressure, 4.0).expect("area");
    assert!((area - 25.0).abs() < 1e-12, "area {area} vs 25");
    let lines = level_contour(&f, &f.pressure, 4.0).expect("contour");
    assert_eq!(lines.len(), 1);
    for &(x, y) in &lines[0] {
        assert!(
            (x + 2.0 * y - 4.0).abs() < 1e-13,
            "({x}, {y}) off x + 2y = 4"
        );
    }
}

/// Area of a polygon by the shoelace formula.
fn shoelace(p: &[(f64, f64)]) -> f64 {
    let n = p.len();
    0.5 * (0..n)
        .map(|k| p[k].0 * p[(k + 1) % n].1 - p[(k + 1) % n].0 * p[k].1)
        .sum::<f64>()
}
