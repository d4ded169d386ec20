//! The paper's comparison charts (Figs. 3–5 and 7): several solves along several lines, drawn
//! by the profile chart of `profile.rs` with one column per line over its half.

use std::path::Path;

use plotters::prelude::RGBColor;

use super::profile::{line_coordinate, Column, Line, ProfileChart};
use super::units::Units;
use super::{write_png, write_svg};
use crate::error::Result;
use crate::post::Profile;

/// One set of curves of a comparison chart: the profiles of one solve, in one colour.
pub(crate) struct Curve<'a> {
    /// Legend text.
    pub label: String,
    /// Line colour.
    pub colour: RGBColor,
    /// Dashed instead of solid.
    pub dashed: bool,
    /// The solve's profiles (by line name; lines not among them are left out).
    pub profiles: &'a [Profile],
}

/// Write a comparison of several solves along several lines, as SVG (`svg`) and PNG (`png`):
/// one column per entry of `lines` — (line name, caption) — over the half line (coordinate 0 to
/// 1), one curve per entry of `curves`.
///
/// # Errors
/// [`crate::Error::Io`] if a file cannot be written or drawing fails.
pub(crate) fn write_profile_comparison(
    svg: &Path,
    png: &Path,
    title: &str,
    lines: &[(&str, &str)],
    curves: &[Curve<'_>],
) -> Result<()> {
    let columns = lines
        .iter()
        .map(|&(name, caption)| Column {
            caption: Some(caption.to_string()),
            x_desc: line_coordinate(name).to_string(),
            lines: curves
                .iter()
                .map(|c| Line {
                    label: c.label.clone(),
                    colour: c.colour,
                    dashed: c.dashed,
                    length: 1.0,
                    points: c
                        .profiles
                        .iter()
                        .find(|p| p.line == name)
                        .map_or(&[][..], |p| &p.points),
                })
                .collect(),
        })
        .collect();
    let chart = ProfileChart {
        title,
        coords: (0.0, 1.0),
        x: (0.0, 1.0),
        columns,
        units: Units::dimensionless(1.0),
    };
    write_svg(svg, &chart)?;
    write_png(png, &chart)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::chart::profile::tests::profiles;
    use crate::output::chart::style;

    #[test]
    fn comparison_is_written_as_svg_and_png() {
        let dir = tempfile::tempdir().expect("tempdir");
        let (svg, png) = (dir.path().join("c.svg"), dir.path().join("c.png"));
        let a = profiles();
        let b: Vec<Profile> = a[..2].to_vec();
        let curves = [
            Curve {
                label: "first solve".into(),
                colour: style::SERIES[0],
                dashed: false,
                profiles: &a,
            },
            Curve {
                label: "second solve".into(),
                colour: style::SERIES[1],
                dashed: true,
                profiles: &b,
            },
        ];
        let lines = [("x-axis", "centre line"), ("diagonal", "diagonal s = t")];
        write_profile_comparison(&svg, &png, "Comparison title", &lines, &curves).expect("write");
        let text = std::fs::read_to_string(&svg).expect("read svg");
        for needle in [
            "Comparison title",
            "centre line",
            "second solve",
            "fraction of the half-diagonal",
        ] {
            assert!(text.contains(needle), "comparison SVG lacks {needle:?}");
        }
        let bytes = std::fs::read(&png).expect("read png");
        assert!(bytes.starts_with(&[0x89, b'P', b'N', b'G']));
        // No lines at all: the title only.
        write_profile_comparison(&svg, &png, "nothing", &[], &curves).expect("no lines");
    }
}
