//! Influence maps of a moving load (`liftoff critical`): each reference point of the load's grid
//! coloured by what the load causes when it stands there — the largest bottom or top stress, the
//! largest deflection — over the plate's outline.

use std::path::Path;

use super::overlay::Overlay;
use super::plan::{Cell, ColourMap, ColourScale};
use super::units::{Scale, Units};
use super::{write_png, write_svg};
use crate::error::Result;
use crate::post::FullField;

/// What an influence map shows.
pub struct Influence<'a> {
    /// The plate's sides (length along x, width along y), in the units of `points`.
    pub plate: [f64; 2],
    /// Reference points of the load.
    pub points: &'a [(f64, f64)],
    /// Their grid spacing (x, y); 0 along an axis with one point.
    pub spacing: [f64; 2],
    /// The value each point causes (NaN where the solve failed: drawn grey).
    pub values: &'a [f64],
    /// Name on the colour bar.
    pub name: &'a str,
    /// How the values are shown.
    pub scale: Scale,
}

/// Write an influence map as SVG (`svg`) and PNG (`png`, 900 × 700): one cell per reference
/// point, a grid step wide, on the colour scale of the values (the field maps' scale).
pub fn write_influence_map(
    svg: &Path,
    png: &Path,
    map: &Influence<'_>,
    title: &str,
    units: &Units,
) -> Result<()> {
    let [a, b] = map.plate;
    // The plate's outline is all the map needs of a field: its extent.
    let outline = FullField {
        nx: 1,
        ny: 1,
        x: vec![-a / 2.0, a / 2.0, -a / 2.0, a / 2.0],
        y: vec![-b / 2.0, -b / 2.0, b / 2.0, b / 2.0],
        s: Vec::new(),
        t: Vec::new(),
        w: Vec::new(),
        psi_x: Vec::new(),
        psi_y: Vec::new(),
        pressure: Vec::new(),
        gap: Vec::new(),
        signed_gap: Vec::new(),
        gap_per_sigma: 0.0,
        v: Vec::new(),
        sigma: Vec::new(),
        contact: Vec::new(),
        s1_bottom: Vec::new(),
        s1_top: Vec::new(),
        ..FullField::default()
    };
    let dx = if map.spacing[0] > 0.0 {
        map.spacing[0]
    } else {
        a / 20.0
    };
    let dy = if map.spacing[1] > 0.0 {
        map.spacing[1]
    } else {
        b / 20.0
    };
    let cells: Vec<Cell> = map
        .points
        .iter()
        .zip(map.values)
        .map(|(&(x, y), &v)| {
            let corners = [(x - dx / 2.0, y - dy / 2.0), (x + dx / 2.0, y + dy / 2.0)];
            (corners, v.is_finite().then(|| map.scale.apply(v)))
        })
        .collect();
    let scale = ColourScale::of(cells.iter().filter_map(|c| c.1));
    let length = units.length();
    let overlay = Overlay::default();
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
    };
    write_svg(svg, &picture)?;
    write_png(png, &picture)
}
