//! Plan views of the plate, drawn to equal scale on x and y: the contact-pressure map of one
//! solve ([`write_contact_map`]) and the contact boundaries of several solves over their loaded
//! areas ([`write_contact_regions`], the paper's Fig. 6). Both draw the contact boundary as the
//! located contact boundary ([`FullField::contact_boundary`]).

use std::path::Path;

use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::axis::{finite_extent, tick_format};
use super::style::{self, DESC_FONT, LABEL_FONT};
use super::{titled, txt, write_png, write_svg, DrawResult, Picture, FONT};
use crate::error::{Error, Result};
use crate::post::FullField;

/// Outer margin of a plan view, pixels.
const MARGIN: i32 = 15;
/// Height of the x label area, pixels.
const X_AREA: i32 = 50;
/// Width of the y label area, pixels.
const Y_AREA: i32 = 70;

/// A plan-view chart in the plate's coordinates.
type Plan<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Axes for the rectangle [x0, x1] × [y0, y1] on `area` with equal scales on x and y, centred;
/// also returns the vertical room left above and below the drawing, pixels.
fn plan_axes<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
    (x_desc, y_desc): (&str, &str),
) -> DrawResult<(Plan<'a, DB>, i32)> {
    let (aw, ah) = area.dim_in_pixel();
    let avail_w = (aw as i32 - 2 * MARGIN - Y_AREA).max(10) as f64;
    let avail_h = (ah as i32 - 2 * MARGIN - X_AREA).max(10) as f64;
    let px = (avail_w / (x1 - x0)).min(avail_h / (y1 - y0));
    let extra_w = ((avail_w - px * (x1 - x0)) / 2.0).max(0.0) as i32;
    let extra_h = ((avail_h - px * (y1 - y0)) / 2.0).max(0.0) as i32;
    let mut chart = ChartBuilder::on(area)
        .margin_left(MARGIN + extra_w)
        .margin_right(MARGIN + extra_w)
        .margin_top(MARGIN + extra_h)
        .margin_bottom(MARGIN + extra_h)
        .x_label_area_size(X_AREA)
        .y_label_area_size(Y_AREA)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(txt)?;
    let x_fmt = tick_format(x0, x1);
    let y_fmt = tick_format(y0, y1);
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .label_style((FONT, LABEL_FONT))
        .axis_desc_style((FONT, DESC_FONT))
        .draw()
        .map_err(txt)?;
    Ok((chart, extra_h))
}

/// Draw the outline of the rectangle [x0, x1] × [y0, y1].
fn outline<DB: DrawingBackend>(
    chart: &mut Plan<'_, DB>,
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> DrawResult<()> {
    chart
        .draw_series(std::iter::once(PathElement::new(
            [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)],
            style::OUTLINE.stroke_width(1),
        )))
        .map_err(txt)?;
    Ok(())
}

/// Draw the contact boundary of `field` in `colour` and `width` (nothing if σ is nowhere
/// positive).
fn boundary<DB: DrawingBackend>(
    chart: &mut Plan<'_, DB>,
    field: &FullField,
    colour: RGBColor,
    width: u32,
) -> DrawResult<()> {
    let segments = field.contact_boundary();
    chart
        .draw_series(
            segments
                .into_iter()
                .map(|s| PathElement::new(s.xy, colour.stroke_width(width))),
        )
        .map_err(txt)?;
    Ok(())
}

/// One cell of the map: its corner node indices (counter-clockwise from (i, j)).
fn cell_nodes(field: &FullField, i: usize, j: usize) -> [usize; 4] {
    let n = field.nx + 1;
    [
        i + j * n,
        i + 1 + j * n,
        i + 1 + (j + 1) * n,
        i + (j + 1) * n,
    ]
}

/// Check that every nodal array of `field` covers the grid.
fn check_field(path: &Path, field: &FullField) -> Result<()> {
    let n = field
        .nx
        .checked_add(1)
        .zip(field.ny.checked_add(1))
        .and_then(|(a, b)| a.checked_mul(b));
    let ok = n.is_some_and(|n| {
        field.x.len() == n
            && field.y.len() == n
            && field.sigma.len() == n
            && field.contact.len() == n
    });
    if ok {
        Ok(())
    } else {
        Err(Error::Io {
            path: path.display().to_string(),
            source: std::io::Error::new(
                std::io::ErrorKind::InvalidInput,
                format!(
                    "field arrays do not match the {} × {} element grid",
                    field.nx, field.ny
                ),
            ),
        })
    }
}

/// The contact-pressure map of one solve.
struct ContactMap<'a> {
    field: &'a FullField,
    title: &'a str,
}

impl Picture for ContactMap<'_> {
    fn size(&self) -> (u32, u32) {
        (900, 700)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<()> {
        let field = self.field;
        let body = titled(root, self.title)?;
        let (body_w, _) = body.dim_in_pixel();
        let bar_w = 130_u32.min(body_w / 3);
        let (map_area, bar_area) = body.split_horizontally(body_w.saturating_sub(bar_w));

        // Cells: mean σ and whether lifted.
        let mut cells = Vec::with_capacity(field.nx * field.ny);
        for j in 0..field.ny {
            for i in 0..field.nx {
                let c = cell_nodes(field, i, j);
                let mean = c.iter().map(|&k| field.sigma[k]).sum::<f64>() / 4.0;
                let lifted = mean.is_nan() || mean <= 0.0 || c.iter().all(|&k| !field.contact[k]);
                cells.push((c, mean, lifted));
            }
        }
        let top = cells
            .iter()
            .filter(|(_, m, lifted)| !lifted && m.is_finite())
            .map(|(_, m, _)| *m)
            .fold(0.0_f64, f64::max);
        let scale = if top > 0.0 { top } else { 1.0 };

        let (xr, yr) = (finite_extent(&field.x), finite_extent(&field.y));
        let (mut chart, extra_h) = plan_axes(&map_area, xr, yr, ("x", "y"))?;
        chart
            .draw_series(cells.iter().map(|&(c, mean, lifted)| {
                let colour = if lifted {
                    style::LIFTED
                } else {
                    style::ramp(mean / scale)
                };
                Rectangle::new(
                    [
                        (field.x[c[0]], field.y[c[0]]),
                        (field.x[c[2]], field.y[c[2]]),
                    ],
                    colour.filled(),
                )
            }))
            .map_err(txt)?;
        boundary(&mut chart, field, style::BOUNDARY, 2)?;
        outline(&mut chart, xr, yr)?;

        // Colour bar, its ends level with the map's (up to a quarter of the height).
        let (_, ah) = map_area.dim_in_pixel();
        let inset = MARGIN + extra_h.min(ah as i32 / 4);
        let mut bar = ChartBuilder::on(&bar_area)
            .margin_top(inset)
            .margin_bottom(inset + X_AREA)
            .margin_left(10)
            .margin_right(5)
            .right_y_label_area_size(75)
            .build_cartesian_2d(0.0..1.0, 0.0..scale)
            .map_err(txt)?;
        let bar_fmt = tick_format(0.0, scale);
        bar.configure_mesh()
            .disable_mesh()
            .disable_x_axis()
            .y_label_formatter(&bar_fmt)
            .label_style((FONT, LABEL_FONT))
            .axis_desc_style((FONT, DESC_FONT))
            .draw()
            .map_err(txt)?;
        let steps = 100;
        bar.draw_series((0..steps).map(|k| {
            let a = k as f64 / steps as f64;
            let b = (k + 1) as f64 / steps as f64;
            Rectangle::new(
                [(0.0, a * scale), (1.0, b * scale)],
                style::ramp((a + b) / 2.0).filled(),
            )
        }))
        .map_err(txt)?;
        bar.draw_series(std::iter::once(Rectangle::new(
            [(0.0, 0.0), (1.0, scale)],
            style::OUTLINE.stroke_width(1),
        )))
        .map_err(txt)?;
        // Bar caption, centred above the bar.
        let (bar_x, bar_y) = bar.plotting_area().get_pixel_range();
        let text =
            TextStyle::from((FONT, 18).into_font()).pos(Pos::new(HPos::Center, VPos::Bottom));
        root.draw_text("σ", &text, ((bar_x.start + bar_x.end) / 2, bar_y.start - 6))
            .map_err(txt)?;
        Ok(())
    }
}

/// Write a filled colour map of the dimensionless contact pressure σ over the plate, once as SVG
/// (`svg`) and once as PNG (`png`, 900 × 700 pixels, drawn by the same code).
///
/// Each grid cell is a rectangle in physical (x, y) coordinates, drawn to equal scale, coloured
/// by the mean σ of its four nodes on a sequential yellow-to-red scale from 0 to the largest cell
/// mean (see the colour bar); lifted cells (mean σ ≤ 0, or no node in contact) are light grey.
/// The contact boundary, located inside the elements where the would-be gap changes sign
/// ([`FullField::contact_boundary`]), is drawn as a dark line, the plate outline as a thin one.
///
/// The PNG path must end in `.png` (the encoder is chosen by the extension).
///
/// # Errors
/// [`Error::Io`] if a file cannot be written or drawing fails, or if the arrays of `field` do
/// not all have (nx + 1)(ny + 1) entries.
pub fn write_contact_map(svg: &Path, png: &Path, field: &FullField, title: &str) -> Result<()> {
    check_field(svg, field)?;
    let map = ContactMap { field, title };
    write_svg(svg, &map)?;
    write_png(png, &map)
}

/// One solve on the contact-region chart: legend text, colour, field.
pub(crate) type Region<'a> = (String, RGBColor, &'a FullField);

/// Contact boundaries of several solves of one plate over its loaded areas.
struct ContactRegions<'a> {
    title: &'a str,
    /// Plate corners (x0, y0), (x1, y1).
    plate: [(f64, f64); 2],
    loaded: &'a [[(f64, f64); 2]],
    regions: &'a [Region<'a>],
}

impl Picture for ContactRegions<'_> {
    fn size(&self) -> (u32, u32) {
        (900, 480)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<()> {
        let body = titled(root, self.title)?;
        let (w, _) = body.dim_in_pixel();
        let legend_w = 230_u32.min(w / 3);
        let (map_area, legend_area) = body.split_horizontally(w.saturating_sub(legend_w));
        let [(x0, y0), (x1, y1)] = self.plate;
        let (mut chart, extra_h) = plan_axes(&map_area, (x0, x1), (y0, y1), ("x / L", "y / L"))?;
        chart
            .draw_series(
                self.loaded
                    .iter()
                    .map(|r| Rectangle::new([r[0], r[1]], style::LOADED.filled())),
            )
            .map_err(txt)?;
        for (_, colour, field) in self.regions {
            boundary(&mut chart, field, *colour, style::REGION_WIDTH)?;
        }
        outline(&mut chart, (x0, x1), (y0, y1))?;

        // Legend beside the map, from the level of its top.
        let text = TextStyle::from((FONT, LABEL_FONT).into_font());
        let (lx, mut y) = (8_i32, MARGIN + extra_h + 10);
        legend_area
            .draw(&Rectangle::new(
                [(lx, y - 7), (lx + 26, y + 7)],
                style::LOADED.filled(),
            ))
            .map_err(txt)?;
        legend_area
            .draw_text("loaded area", &text, (lx + 34, y - 8))
            .map_err(txt)?;
        y += 26;
        legend_area
            .draw_text("contact boundary:", &text, (lx, y - 8))
            .map_err(txt)?;
        for (label, colour, _) in self.regions {
            y += 24;
            legend_area
                .draw(&PathElement::new(
                    [(lx, y), (lx + 26, y)],
                    colour.stroke_width(style::REGION_WIDTH),
                ))
                .map_err(txt)?;
            legend_area
                .draw_text(label, &text, (lx + 34, y - 8))
                .map_err(txt)?;
        }
        y += 30;
        for line in [
            "contact inside each line;",
            "the plate has lifted",
            "outside it",
        ] {
            legend_area
                .draw_text(line, &text, (lx, y - 8))
                .map_err(txt)?;
            y += 18;
        }
        Ok(())
    }
}

/// Write the contact boundaries of several solves of one plate (corners `plate`, in the fields'
/// x, y) over the `loaded` rectangles, as SVG (`svg`) and PNG (`png`), 900 × 480 pixels, with
/// a legend naming each solve.
///
/// # Errors
/// [`Error::Io`] if a file cannot be written or drawing fails, or if a field's arrays do not
/// cover its grid.
pub(crate) fn write_contact_regions(
    svg: &Path,
    png: &Path,
    title: &str,
    plate: [(f64, f64); 2],
    loaded: &[[(f64, f64); 2]],
    regions: &[Region<'_>],
) -> Result<()> {
    for (_, _, field) in regions {
        check_field(svg, field)?;
    }
    let chart = ContactRegions {
        title,
        plate,
        loaded,
        regions,
    };
    write_svg(svg, &chart)?;
    write_png(png, &chart)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The shared 4 × 2 test plate without its element field.
    fn bump_field() -> FullField {
        crate::post::test_fixtures::bump().0
    }

    #[test]
    fn contact_map_is_written() {
        let dir = tempfile::tempdir().expect("tempdir");
        let svg = dir.path().join("contact.svg");
        let png = dir.path().join("contact.png");
        write_contact_map(&svg, &png, &bump_field(), "Contact map title").expect("write");
        let text = std::fs::read_to_string(&svg).expect("read svg");
        assert!(text.contains("<svg"));
        assert!(text.contains("Contact map title"));
        let bytes = std::fs::read(&png).expect("read png");
        assert!(bytes.starts_with(&[0x89, b'P', b'N', b'G', 0x0D, 0x0A, 0x1A, 0x0A]));
    }

    #[test]
    fn contact_map_handles_degenerate_input() {
        let dir = tempfile::tempdir().expect("tempdir");
        let svg = dir.path().join("c.svg");
        let png = dir.path().join("c.png");

        // All σ zero, nothing in contact.
        let mut f = bump_field();
        f.sigma.iter_mut().for_each(|s| *s = 0.0);
        f.contact.iter_mut().for_each(|c| *c = false);
        write_contact_map(&svg, &png, &f, "zero").expect("all zero");

        // All σ equal and in contact.
        f.sigma.iter_mut().for_each(|s| *s = 0.5);
        f.contact.iter_mut().for_each(|c| *c = true);
        write_contact_map(&svg, &png, &f, "uniform").expect("uniform");

        // Inconsistent arrays: an error, not a panic.
        f.sigma.pop();
        assert!(write_contact_map(&svg, &png, &f, "bad").is_err());

        // No cells at all.
        let mut g = bump_field();
        g.nx = 0;
        g.ny = 0;
        for v in [&mut g.x, &mut g.y, &mut g.sigma] {
            v.truncate(1);
        }
        g.contact.truncate(1);
        write_contact_map(&svg, &png, &g, "point").expect("single node");
    }

    #[test]
    fn contact_regions_are_written() {
        let dir = tempfile::tempdir().expect("tempdir");
        let svg = dir.path().join("r.svg");
        let png = dir.path().join("r.png");
        let (f, mut g) = (bump_field(), bump_field());
        g.sigma.iter_mut().for_each(|s| *s *= 0.5);
        let regions = [
            ("first region".to_string(), style::SERIES[0], &f),
            ("second region".to_string(), style::SERIES[3], &g),
        ];
        let plate = [(-2.0, -1.0), (2.0, 1.0)];
        let loaded = [[(-0.5, -0.25), (0.5, 0.25)]];
        write_contact_regions(&svg, &png, "Regions title", plate, &loaded, &regions)
            .expect("write");
        let text = std::fs::read_to_string(&svg).expect("read svg");
        for needle in ["Regions title", "second region", "loaded area"] {
            assert!(text.contains(needle), "regions SVG lacks {needle:?}");
        }
        let bytes = std::fs::read(&png).expect("read png");
        assert!(bytes.starts_with(&[0x89, b'P', b'N', b'G']));

        // A field that does not cover its grid is an error, not a panic.
        g.sigma.pop();
        let bad = [("bad".to_string(), style::SERIES[0], &g)];
        assert!(write_contact_regions(&svg, &png, "bad", plate, &loaded, &bad).is_err());
    }
}
