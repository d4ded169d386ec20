//! Influence maps of a moving load (`liftoff critical`): each reference point of the load's grid
//! coloured by what the load causes when it stands there — the largest bottom or top stress, the
//! largest deflection — over the plate's outline and joint lines, with the searched points as
//! dots, the critical one ringed and the load's prints there.

use std::path::Path;

use super::overlay::Overlay;
use super::plan::{Cell, ColourMap, ColourScale};
use super::units::{Scale, Units};
use super::{write_png, write_svg};
use crate::error::Result;
use crate::post::{FullField, JointLine};

/// What an influence map shows.
pub struct Influence<'a> {
    /// The plate's sides (length along x, width along y), in the units of `points`.
    pub plate: [f64; 2],
    /// Reference points of the load.
    pub points: &'a [(f64, f64)],
    /// The value each point causes (NaN where there is no converged solve: drawn grey).
    pub values: &'a [f64],
    /// Name on the colour bar.
    pub name: &'a str,
    /// How the values are shown.
    pub scale: Scale,
    /// The plate's joint lines (empty without joints).
    pub joints: Vec<JointLine>,
    /// The critical position with its legend text (None: no position converged).
    pub critical: Option<((f64, f64), String)>,
    /// The load's tire prints at the critical position, as opposite corners.
    pub prints: Vec<[(f64, f64); 2]>,
}

/// The cells of `points`: along each axis the sorted distinct coordinates cut at the midpoints
/// between neighbours, the outermost cells as wide on their open side as on the other (a
/// uniform grid's cells are a step wide, centred on their points), a lone coordinate `lone`
/// wide. Distinct points get cells that do not overlap.
fn cells(points: &[(f64, f64)], lone: [f64; 2]) -> Vec<[(f64, f64); 2]> {
    let axis = |pick: fn(&(f64, f64)) -> f64, lone: f64| {
        let mut u: Vec<f64> = points.iter().map(pick).filter(|v| v.is_finite()).collect();
        u.sort_by(f64::total_cmp);
        let extent = u.last().map_or(0.0, |l| l - u[0]).abs().max(lone);
        u.dedup_by(|a, b| (*a - *b).abs() <= 1e-9 * extent);
        move |v: f64| -> (f64, f64) {
            if u.is_empty() {
                return (v - lone / 2.0, v + lone / 2.0);
            }
            let i = u
                .partition_point(|&c| c < v - 1e-9 * extent)
                .min(u.len() - 1);
            let left = (i > 0).then(|| (u[i - 1] + u[i]) / 2.0);
            let right = u.get(i + 1).map(|n| (u[i] + n) / 2.0);
            match (left, right) {
                (Some(l), Some(r)) => (l, r),
                (Some(l), None) => (l, 2.0 * u[i] - l),
                (None, Some(r)) => (2.0 * u[i] - r, r),
                (None, None) => (v - lone / 2.0, v + lone / 2.0),
            }
        }
    };
    if points.is_empty() {
        return Vec::new();
    }
    let (fx, fy) = (axis(|p| p.0, lone[0]), axis(|p| p.1, lone[1]));
    points
        .iter()
        .map(|&(x, y)| {
            let ((x0, x1), (y0, y1)) = (fx(x), fy(y));
            [(x0, y0), (x1, y1)]
        })
        .collect()
}

/// Write an influence map as SVG (`svg`) and PNG (`png`, 900 × 700): one cell per reference
/// point ([`cells`]), on the colour scale of the values (the field maps' scale).
pub fn write_influence_map(
    svg: &Path,
    png: &Path,
    map: &Influence<'_>,
    title: &str,
    units: &Units,
) -> Result<()> {
    let [a, b] = map.plate;
    // The plate's outline and joints are all the map needs of a field.
    let outline = FullField {
        nx: 1,
        ny: 1,
        x: vec![-a / 2.0, a / 2.0, -a / 2.0, a / 2.0],
        y: vec![-b / 2.0, -b / 2.0, b / 2.0, b / 2.0],
        joints: map.joints.clone(),
        ..FullField::default()
    };
    let cells: Vec<Cell> = cells(map.points, [a / 20.0, b / 20.0])
        .into_iter()
        .zip(map.values)
        .map(|(corners, &v)| (corners, v.is_finite().then(|| map.scale.apply(v))))
        .collect();
    let scale = ColourScale::of(cells.iter().filter_map(|c| c.1));
    let length = units.length();
    let overlay = Overlay {
        prints: map.prints.clone(),
        dots: map.points.to_vec(),
        marks: map.critical.iter().cloned().collect(),
        ..Overlay::default()
    };
    let picture = ColourMap {
        title,
        field: &outline,
        cells,
        scale,
        bar_caption: map.scale.label(map.name),
        axes: (
            length.label("load reference x"),
            length.label("load reference y"),
        ),
        length_factor: length.factor,
        boundary: false,
        overlay: &overlay,
        levelled: None,
        grey: Some("no converged solve there"),
    };
    write_svg(svg, &picture)?;
    write_png(png, &picture)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A uniform grid's cells are a step wide and centred on their points (what the maps drew
    /// before cells were cut at midpoints); an uneven grid's meet at the midpoints; a lone
    /// coordinate takes the given width.
    #[test]
    fn cells_meet_at_midpoints() {
        let pts = [(0.0, 5.0), (1.0, 5.0), (2.0, 5.0)];
        let c = cells(&pts, [0.4, 0.6]);
        assert_eq!(c[0], [(-0.5, 4.7), (0.5, 5.3)]);
        assert_eq!(c[1], [(0.5, 4.7), (1.5, 5.3)]);
        assert_eq!(c[2], [(1.5, 4.7), (2.5, 5.3)]);
        let uneven = [(0.0, 0.0), (1.0, 0.0), (3.0, 0.0), (0.0, 2.0)];
        let c = cells(&uneven, [1.0, 1.0]);
        assert_eq!(c[1], [(0.5, -1.0), (2.0, 1.0)]);
        assert_eq!(c[2], [(2.0, -1.0), (4.0, 1.0)]);
        assert_eq!(c[3], [(-0.5, 1.0), (0.5, 3.0)]);
        assert!(cells(&[], [1.0, 1.0]).is_empty());
    }
}
