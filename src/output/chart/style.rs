//! The one colour and line style table of every chart.
//!
//! Series (curves, point sets) take [`SERIES`] colours in order; run outcomes take
//! [`CATEGORIES`]; pressures run along [`RAMP`]. Greys and translucent blacks are named for
//! what they draw.

use plotters::style::{RGBAColor, RGBColor};

/// Series colours (the Tableau 10 palette, red and orange swapped so that the first two
/// series contrast most), cycled in series order.
pub(crate) const SERIES: [RGBColor; 10] = [
    RGBColor(31, 119, 180),  // blue
    RGBColor(214, 39, 40),   // red
    RGBColor(44, 160, 44),   // green
    RGBColor(255, 127, 14),  // orange
    RGBColor(148, 103, 189), // purple
    RGBColor(140, 86, 75),   // brown
    RGBColor(227, 119, 194), // pink
    RGBColor(127, 127, 127), // grey
    RGBColor(188, 189, 34),  // olive
    RGBColor(23, 190, 207),  // cyan
];

/// Colour of series number `k`.
pub(crate) fn series_colour(k: usize) -> RGBColor {
    SERIES[k % SERIES.len()]
}

/// Fixed colours of the known run categories, in legend order.
pub(crate) const CATEGORIES: [(&str, RGBColor); 9] = [
    ("converged", RGBColor(44, 160, 44)),
    ("cycling", RGBColor(255, 140, 0)),
    ("iteration-limit", RGBColor(220, 40, 40)),
    ("penalty-too-weak", RGBColor(140, 90, 190)),
    ("solver-failure", RGBColor(130, 10, 20)),
    ("infeasible", RGBColor(128, 128, 128)),
    ("too-large", RGBColor(205, 205, 205)),
    ("numerical", RGBColor(75, 50, 35)),
    ("not-run", RGBColor(255, 255, 255)),
];

/// Colours for categories not in [`CATEGORIES`], chosen by a hash of the name.
const EXTRA_CATEGORIES: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(23, 190, 207),
    RGBColor(227, 119, 194),
    RGBColor(188, 189, 34),
    RGBColor(57, 59, 121),
    RGBColor(0, 128, 128),
    RGBColor(231, 186, 82),
    RGBColor(158, 202, 225),
    RGBColor(206, 109, 189),
    RGBColor(99, 121, 57),
];

/// Colour of a category: its fixed colour, or one of [`EXTRA_CATEGORIES`] chosen by the name
/// (deterministic; different names may share a colour).
pub(crate) fn category_colour(name: &str) -> RGBColor {
    if let Some((_, c)) = CATEGORIES.iter().find(|(n, _)| *n == name) {
        return *c;
    }
    // FNV-1a: stable across runs and Rust versions.
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in name.bytes() {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    EXTRA_CATEGORIES[(h % EXTRA_CATEGORIES.len() as u64) as usize]
}

/// Sequential colour map (ColorBrewer YlOrRd without its palest class), low to high.
const RAMP: [(u8, u8, u8); 8] = [
    (255, 237, 160),
    (254, 217, 118),
    (254, 178, 76),
    (253, 141, 60),
    (252, 78, 42),
    (227, 26, 28),
    (189, 0, 38),
    (128, 0, 38),
];

/// Diverging colour map (ColorBrewer RdBu, reversed): blue for negative, white at zero, red for
/// positive.
const DIVERGING: [(u8, u8, u8); 9] = [
    (33, 102, 172),
    (67, 147, 195),
    (146, 197, 222),
    (209, 229, 240),
    (247, 247, 247),
    (253, 219, 199),
    (244, 165, 130),
    (214, 96, 77),
    (178, 24, 43),
];

/// Colour of the normalised value `f` ∈ [0, 1] on `table` (linear between its classes; values
/// outside are clamped, NaN is 0).
fn interpolate(table: &[(u8, u8, u8)], f: f64) -> RGBColor {
    let f = if f.is_finite() {
        f.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let pos = f * (table.len() - 1) as f64;
    let k = (pos.floor() as usize).min(table.len() - 2);
    let a = pos - k as f64;
    let (r0, g0, b0) = table[k];
    let (r1, g1, b1) = table[k + 1];
    let mix = |u: u8, v: u8| (f64::from(u) * (1.0 - a) + f64::from(v) * a).round() as u8;
    RGBColor(mix(r0, r1), mix(g0, g1), mix(b0, b1))
}

/// Colour of the normalised value `f` ∈ [0, 1] on [`RAMP`] (linear between its classes;
/// values outside are clamped, NaN is 0).
pub(crate) fn ramp(f: f64) -> RGBColor {
    interpolate(&RAMP, f)
}

/// Colour of the normalised value `f` ∈ [0, 1] on [`DIVERGING`] (½ is zero, white).
pub(crate) fn diverging(f: f64) -> RGBColor {
    interpolate(&DIVERGING, f)
}

/// Relative luminance-like brightness of a colour, 0–255 (to pick black or white text on it).
pub(crate) fn brightness(c: RGBColor) -> f64 {
    0.299 * f64::from(c.0) + 0.587 * f64::from(c.1) + 0.114 * f64::from(c.2)
}

/// Lifted cells of the contact map.
pub(crate) const LIFTED: RGBColor = RGBColor(215, 215, 215);
/// Loaded areas on the contact-region chart.
pub(crate) const LOADED: RGBColor = RGBColor(205, 205, 205);
/// The contact boundary on the contact map.
pub(crate) const BOUNDARY: RGBColor = RGBColor(20, 20, 20);

/// The contour where the pressure reaches the allowable one (dashed) and the hatching of the
/// area above it.
pub(crate) const EXCEEDED: RGBColor = RGBColor(200, 0, 200);
/// A white band under dashed contours, so that they read on dark cells.
pub(crate) const HALO: RGBAColor = RGBAColor(255, 255, 255, 0.85);
/// A lighter white band under hatch lines, so that the colours beneath still read.
pub(crate) const HATCH_HALO: RGBAColor = RGBAColor(255, 255, 255, 0.55);
/// Outline of voids under the plate (dashed).
pub(crate) const VOID: RGBColor = RGBColor(40, 40, 40);
/// Outline of soft or stiff foundation zones (dotted).
pub(crate) const ZONE: RGBColor = RGBColor(20, 70, 160);
/// The hatch over parts of a map that are drawn but not counted (a cut lane's end panels).
pub(crate) const CUT: RGBColor = RGBColor(90, 90, 90);
/// Line loads.
pub(crate) const LINE_LOAD: RGBColor = RGBColor(25, 25, 90);
/// Tire prints of axles and gears: thin outlines.
pub(crate) const PRINT: RGBColor = RGBColor(20, 20, 20);
/// Positions of a critical search: the searched ones' dots, the critical one's ring.
pub(crate) const MARKER: RGBColor = RGBColor(0, 0, 0);

/// Joint lines on plan views, by kind ([`joint`]).
pub(crate) const JOINT_FREE: RGBColor = RGBColor(0, 0, 0);
/// An aggregate-interlock joint.
pub(crate) const JOINT_AGGREGATE: RGBColor = RGBColor(30, 90, 170);
/// A doweled joint.
pub(crate) const JOINT_DOWELS: RGBColor = RGBColor(0, 120, 60);
/// A tied joint.
pub(crate) const JOINT_TIED: RGBColor = RGBColor(120, 60, 20);
/// A continuous line (a panel boundary only).
pub(crate) const JOINT_CONTINUOUS: RGBColor = RGBColor(90, 90, 90);

/// The dash and gap (pixels) and the colour a joint line of `kind` is drawn with: free joints
/// in long dashes, aggregate interlock in medium ones, dowels in short ones, tied joints
/// nearly solid; continuous lines (panel boundaries only) dotted.
pub(crate) fn joint(kind: crate::layout::JointType) -> ((u32, u32), RGBColor) {
    use crate::layout::JointType;
    match kind {
        JointType::Free => ((14, 6), JOINT_FREE),
        JointType::Aggregate => ((8, 5), JOINT_AGGREGATE),
        JointType::Dowels => ((4, 4), JOINT_DOWELS),
        JointType::Tied => ((18, 3), JOINT_TIED),
        JointType::Continuous => ((2, 5), JOINT_CONTINUOUS),
    }
}

/// Major grid lines of cartesian charts.
pub(crate) const GRID_MAJOR: RGBColor = RGBColor(215, 215, 215);
/// Minor grid lines of cartesian charts, and the empty cells of a category map.
pub(crate) const GRID_MINOR: RGBColor = RGBColor(235, 235, 235);
/// Border of "not-run" cells and of legend swatches on a category map.
pub(crate) const CELL_BORDER: RGBColor = RGBColor(150, 150, 150);

/// The plate outline and the frame of the colour bar.
pub(crate) const OUTLINE: RGBAColor = RGBAColor(0, 0, 0, 0.7);
/// Zero lines of the profile charts and the frame of a category map.
pub(crate) const REFERENCE: RGBAColor = RGBAColor(0, 0, 0, 0.6);
/// Border of legend and note boxes.
pub(crate) const BOX_BORDER: RGBAColor = RGBAColor(0, 0, 0, 0.5);
/// Fill of legend and note boxes.
pub(crate) const BOX_FILL: RGBAColor = RGBAColor(255, 255, 255, 0.9);

/// Stroke width of data lines, pixels.
pub(crate) const LINE_WIDTH: u32 = 2;
/// Stroke width of the contact boundaries on the contact-region chart (several colours on
/// white, drawn a little heavier than data lines), pixels.
pub(crate) const REGION_WIDTH: u32 = 3;
/// Dash and gap lengths of dashed lines, pixels.
pub(crate) const DASH: (u32, u32) = (9, 6);

/// Tick label font size, pixels.
pub(crate) const LABEL_FONT: u32 = 14;
/// Axis description font size, pixels.
pub(crate) const DESC_FONT: u32 = 16;

/// Marker shapes, cycled in series order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Shape {
    /// Filled circle.
    Circle,
    /// Filled triangle.
    Triangle,
    /// Filled square.
    Square,
    /// Filled diamond.
    Diamond,
    /// Diagonal cross.
    Cross,
}

/// The marker shape of series number `k`.
pub(crate) fn shape_of(k: usize) -> Shape {
    [
        Shape::Circle,
        Shape::Triangle,
        Shape::Square,
        Shape::Diamond,
        Shape::Cross,
    ][k % 5]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn category_colours_are_fixed_and_deterministic() {
        assert_eq!(category_colour("converged"), RGBColor(44, 160, 44));
        assert_eq!(category_colour("not-run"), RGBColor(255, 255, 255));
        assert_eq!(category_colour("brand-new"), category_colour("brand-new"));
        assert!(EXTRA_CATEGORIES.contains(&category_colour("brand-new")));
    }

    #[test]
    fn ramp_ends_and_midpoint() {
        assert_eq!(ramp(0.0), RGBColor(255, 237, 160));
        assert_eq!(ramp(1.0), RGBColor(128, 0, 38));
        assert_eq!(ramp(f64::NAN), ramp(0.0));
        assert_eq!(ramp(7.0), ramp(1.0));
        // 0.5 · 7 = 3.5: halfway between classes 3 (253, 141, 60) and 4 (252, 78, 42).
        assert_eq!(ramp(0.5), RGBColor(253, 110, 51));
        assert_eq!(diverging(0.5), RGBColor(247, 247, 247), "zero is white");
        assert_eq!(diverging(0.0), RGBColor(33, 102, 172));
        assert_eq!(diverging(1.0), RGBColor(178, 24, 43));
    }
}
