//! Plan views of one or several solves: the contact-pressure map of one solve
//! ([`write_contact_map`]), a colour map of any field ([`write_field_map`], e.g. an envelope
//! over load cases), both drawn by the shared [`ColourMap`] with an [`Overlay`], and the contact
//! boundaries of several solves over their loaded areas ([`write_contact_regions`], the
//! paper's Fig. 6). Contact boundaries are the located ones ([`FullField::contact_boundary`]).

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::overlay::Overlay;
use super::plan::{
    boundary, cell_nodes, outline, plan_axes, ColourMap, ColourScale, Palette, MARGIN,
};
use super::style::{self, LABEL_FONT};
use super::units::{Scale, Units};
use super::{titled, txt, write_png, write_svg, DrawResult, Picture, FONT};
use crate::error::{Error, Result};
use crate::post::FullField;

/// An invalid-input error on `path`.
fn invalid(path: &Path, what: String) -> Error {
    Error::Io {
        path: path.display().to_string(),
        source: std::io::Error::new(std::io::ErrorKind::InvalidInput, what),
    }
}

/// Node copies and elements of the grid of `field`, if they can be counted (and its corner
/// table, on a jointed plate, names only copies it has).
fn grid_size(path: &Path, field: &FullField) -> Result<(usize, usize)> {
    let nodes = field
        .nx
        .checked_add(1)
        .zip(field.ny.checked_add(1))
        .and_then(|(a, b)| a.checked_mul(b))
        .and_then(|g| g.checked_add(field.extra_grid.len()));
    let corners_ok = field.corners.as_ref().is_none_or(|c| {
        Some(c.len()) == field.nx.checked_mul(field.ny)
            && c.iter().flatten().all(|&k| Some(k) < nodes)
    });
    if !corners_ok {
        return Err(invalid(
            path,
            format!(
                "the corner table does not match the {} × {} grid",
                field.nx, field.ny
            ),
        ));
    }
    nodes
        .zip(field.nx.checked_mul(field.ny))
        .ok_or_else(|| invalid(path, format!("a {} × {} grid", field.nx, field.ny)))
}

/// Check that every nodal array a plan view reads covers the grid.
fn check_field(path: &Path, field: &FullField) -> Result<()> {
    let (n, _) = grid_size(path, field)?;
    let lengths = [
        field.x.len(),
        field.y.len(),
        field.sigma.len(),
        field.pressure.len(),
        field.contact.len(),
    ];
    if lengths.iter().all(|&l| l == n) {
        Ok(())
    } else {
        Err(invalid(
            path,
            format!(
                "field arrays do not match the {} × {} element grid",
                field.nx, field.ny
            ),
        ))
    }
}

/// The colour map of the contact pressure of one solve: lifted cells (mean σ ≤ 0, or no node
/// in contact) grey, the others their corners' mean on the sequential scale from 0 to the
/// nodal peak — the solve table's extreme (issue 36: a bar that topped at the largest cell
/// mean read 530 kPa beside a table's 1107 kPa), which the bar's caption names.
fn contact_picture<'a>(
    field: &'a FullField,
    title: &'a str,
    units: &Units,
    overlay: &'a Overlay,
) -> ColourMap<'a> {
    let shown = units.pressure();
    // Dimensionless scenes show σ itself (byte for byte the map drawn before units existed).
    let values: Vec<f64> = if units.is_physical() {
        field.pressure.iter().map(|&p| shown.apply(p)).collect()
    } else {
        field.sigma.clone()
    };
    let mut cells = Vec::with_capacity(field.nx * field.ny);
    for j in 0..field.ny {
        for i in (0..field.nx).filter(|&i| field.is_plate(i, j)) {
            let c = cell_nodes(field, i, j);
            let mean = c.iter().map(|&k| values[k]).sum::<f64>() / 4.0;
            let lifted = mean.is_nan() || mean <= 0.0 || c.iter().all(|&k| !field.contact[k]);
            let corners = [
                (field.x[c[0]], field.y[c[0]]),
                (field.x[c[2]], field.y[c[2]]),
            ];
            cells.push((corners, (!lifted).then_some(mean)));
        }
    }
    let top = values
        .iter()
        .filter(|m| m.is_finite())
        .fold(0.0_f64, |a, &b| a.max(b));
    let hi = if top > 0.0 { top } else { 1.0 };
    let length = units.length();
    ColourMap {
        title,
        field,
        cells,
        scale: ColourScale {
            lo: 0.0,
            hi,
            palette: Palette::Sequential,
        },
        bar_caption: if units.is_physical() {
            format!("{}, to the nodal peak", shown.label("pressure"))
        } else {
            "σ, to the nodal peak".to_string()
        },
        axes: (length.label("x"), length.label("y")),
        length_factor: length.factor,
        boundary: true,
        overlay,
        levelled: Some((&field.pressure, shown)),
        grey: None,
    }
}

/// Write a filled colour map of the contact pressure over the plate, once as SVG (`svg`) and
/// once as PNG (`png`, 900 × 700 pixels, drawn by the same code), in `units`: kPa over axes in
/// m for a physical scene, the dimensionless σ over x, y in units of L otherwise.
///
/// Each grid cell is a rectangle in physical (x, y) coordinates, drawn to equal scale, coloured
/// by the mean pressure of its four nodes on a sequential yellow-to-red scale from 0 to the
/// largest cell mean (see the colour bar); lifted cells (mean σ ≤ 0, or no node in contact) are
/// light grey. The contact boundary, located inside the elements where the would-be gap changes
/// sign ([`FullField::contact_boundary`]), is drawn as a dark line, the plate outline as a thin
/// one.
///
/// `overlay` adds, each named in a legend below the map when present: the area where the
/// bilinear nodal pressure exceeds `overlay.allowable_pressure` (units of
/// [`FullField::pressure`]) hatched and outlined by a dashed magenta contour, with the level
/// marked on the colour bar; voids as dashed rectangles, soft or stiff zones as dotted ones,
/// line loads as thick dark lines. `Overlay::default()` draws the map alone, without a legend.
///
/// The PNG path must end in `.png` (the encoder is chosen by the extension).
///
/// # Errors
/// [`Error::Io`] if a file cannot be written or drawing fails, or if the arrays of `field` do
/// not all have one entry per node copy.
pub fn write_contact_map(
    svg: &Path,
    png: &Path,
    field: &FullField,
    title: &str,
    units: &Units,
    overlay: &Overlay,
) -> Result<()> {
    check_field(svg, field)?;
    let map = contact_picture(field, title, units, overlay);
    write_svg(svg, &map)?;
    write_png(png, &map)
}

/// Values to colour a plan view by ([`write_field_map`]).
#[derive(Debug, Clone, Copy)]
pub struct MapValues<'a> {
    /// One value per node copy ((nx + 1)(ny + 1) grid nodes, index i + j (nx + 1), then the
    /// extra copies of a jointed plate; each cell takes the mean of its own corners) or per element (nx ny, index ie + je nx, as [`crate::post::ElementField`]),
    /// in the field's units (SI for a physical scene).
    pub values: &'a [f64],
    /// Name on the colour bar, e.g. "mx"; the unit of `scale` follows it.
    pub name: &'a str,
    /// How the values are shown, e.g. [`Units::moment`]: shown value = value × factor.
    pub scale: Scale,
}

/// Write a plan-view colour map of any field over the plate as SVG (`svg`) and PNG (`png`,
/// 900 × 700 pixels) — the contact map's drawing without its contact boundary and lifted cells:
/// an envelope of pressures, deflections or moments over load cases, say.
///
/// Cells take the mean of their corner values (nodal values) or their element value. Values of
/// one sign are drawn on the sequential yellow-to-red scale from 0 (the largest magnitude
/// darkest); values of both signs on a blue-white-red scale symmetric about 0. Axes are in
/// `units` (m for a physical scene). With nodal values, `overlay.allowable_pressure` (units of
/// `map.values`) hatches and outlines the area above it as on the contact map; with element
/// values no level is drawn. Voids, zones and line loads are drawn as on the contact map.
///
/// # Errors
/// [`Error::Io`] if a file cannot be written or drawing fails, if the coordinates of `field`
/// do not cover its grid, or if `map.values` has neither one entry per node nor one per element.
pub fn write_field_map(
    svg: &Path,
    png: &Path,
    field: &FullField,
    map: &MapValues<'_>,
    title: &str,
    units: &Units,
    overlay: &Overlay,
) -> Result<()> {
    let (nodes, elements) = grid_size(svg, field)?;
    let bad = |what: String| invalid(svg, what);
    if field.x.len() != nodes || field.y.len() != nodes {
        return Err(bad(format!(
            "coordinates do not match the {} × {} element grid",
            field.nx, field.ny
        )));
    }
    let nodal = map.values.len() == nodes;
    if !nodal && map.values.len() != elements {
        return Err(bad(format!(
            "{} values for {nodes} nodes and {elements} elements",
            map.values.len()
        )));
    }
    let shown = map.scale;
    let mut cells = Vec::with_capacity(elements);
    for j in 0..field.ny {
        for i in (0..field.nx).filter(|&i| field.is_plate(i, j)) {
            let c = cell_nodes(field, i, j);
            let value = if nodal {
                c.iter().map(|&k| map.values[k]).sum::<f64>() / 4.0
            } else {
                map.values[i + j * field.nx]
            };
            let corners = [
                (field.x[c[0]], field.y[c[0]]),
                (field.x[c[2]], field.y[c[2]]),
            ];
            cells.push((corners, Some(shown.apply(value))));
        }
    }
    let scale = ColourScale::of(cells.iter().filter_map(|c| c.1));
    let length = units.length();
    let picture = ColourMap {
        title,
        field,
        cells,
        scale,
        bar_caption: shown.label(map.name),
        axes: (length.label("x"), length.label("y")),
        length_factor: length.factor,
        boundary: false,
        overlay,
        levelled: nodal.then_some((map.values, shown)),
        grey: None,
    };
    write_svg(svg, &picture)?;
    write_png(png, &picture)
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
        let (mut chart, extra_h) =
            plan_axes(&map_area, (x0, x1), (y0, y1), ("x / L", "y / L"), 1.0)?;
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

    /// Dimensionless units of the test plate (μ = 1/2: 4 × 2 over [−2, 2] × [−1, 1]).
    fn unitless() -> Units {
        Units::dimensionless(0.5)
    }

    /// Physical units: L = 2 m, P = 1 kN, D = 1 kN·m.
    fn metric() -> Units {
        Units::new(
            Some(crate::model::Physical {
                half_length: 2.0,
                force: 1e3,
                rigidity: 1e3,
                units: crate::units::UnitSystem::Si,
            }),
            0.5,
        )
    }

    /// A map with no overlay and the map with one (allowable pressure `level`): `draw` writes
    /// both and returns their SVGs.
    fn both(level: f64, draw: impl Fn(&Path, &Path, &Overlay) -> Result<()>) -> (String, String) {
        let dir = tempfile::tempdir().expect("tempdir");
        let (svg, png) = (dir.path().join("m.svg"), dir.path().join("m.png"));
        draw(&svg, &png, &Overlay::default()).expect("plain map");
        let plain = std::fs::read_to_string(&svg).expect("read svg");
        let overlay = Overlay {
            allowable_pressure: Some(level),
            voids: vec![[(-1.5, -0.5), (-0.5, 0.5)]],
            zones: vec![[(0.5, -0.8), (1.8, 0.2)]],
            lines: vec![[(-2.0, 0.8), (2.0, 0.8)]],
            prints: vec![[(1.0, -0.2), (1.3, 0.1)]],
            ..Overlay::default()
        };
        draw(&svg, &png, &overlay).expect("map with overlay");
        let over = std::fs::read_to_string(&svg).expect("read svg");
        let bytes = std::fs::read(&png).expect("read png");
        assert!(bytes.starts_with(&[0x89, b'P', b'N', b'G']));
        (plain, over)
    }

    #[test]
    fn contact_map_is_written() {
        let dir = tempfile::tempdir().expect("tempdir");
        let svg = dir.path().join("contact.svg");
        let png = dir.path().join("contact.png");
        write_contact_map(
            &svg,
            &png,
            &bump_field(),
            "Contact map title",
            &unitless(),
            &Overlay::default(),
        )
        .expect("write");
        let text = std::fs::read_to_string(&svg).expect("read svg");
        assert!(text.contains("<svg"));
        assert!(text.contains("Contact map title"));
        // The bar's caption, σ up to the nodal peak (it wraps at its spaces).
        assert!(
            text.contains(">\nσ, to the") && text.contains("peak\n<"),
            "dimensionless colour bar"
        );
        let bytes = std::fs::read(&png).expect("read png");
        assert!(bytes.starts_with(&[0x89, b'P', b'N', b'G', 0x0D, 0x0A, 0x1A, 0x0A]));
    }

    /// Physical units on the axes and the bar; the overlay adds its legend entries, and
    /// nothing of it appears without one.
    #[test]
    fn contact_map_draws_units_and_overlay() {
        let mut f = bump_field();
        // Pressure peaking at 100 kPa; allowable 50 kPa.
        f.pressure.iter_mut().for_each(|p| *p *= 1e5);
        let (plain, over) = both(5e4, |svg, png, o| {
            write_contact_map(svg, png, &f, "T", &metric(), o)
        });
        for needle in ["x (m)", "y (m)", "pressure (kPa)"] {
            assert!(
                plain.contains(needle),
                "physical contact map lacks {needle:?}"
            );
        }
        for needle in [
            "contact boundary",
            "pressure &gt; allowable (50 kPa)",
            "void",
            "soft or stiff zone",
            "line load",
            "tire print",
        ] {
            assert!(!plain.contains(needle), "plain map has {needle:?}");
            assert!(over.contains(needle), "overlay legend lacks {needle:?}");
        }
        // The allowable level above the peak: named as not exceeded.
        let dir = tempfile::tempdir().expect("tempdir");
        let (svg, png) = (dir.path().join("n.svg"), dir.path().join("n.png"));
        let high = Overlay {
            allowable_pressure: Some(1e5 * 2.0),
            ..Overlay::default()
        };
        write_contact_map(&svg, &png, &f, "T", &unitless(), &high).expect("write");
        let text = std::fs::read_to_string(&svg).expect("read svg");
        assert!(
            text.contains("allowable pressure 1.00e5: not exceeded"),
            "dimensionless: σ = μ r = 0.5 · 2e5"
        );
    }

    /// A field map of element values (both signs: diverging scale) and of nodal ones; values of
    /// the wrong length are an error.
    #[test]
    fn field_map_is_written_for_node_and_element_values() {
        let (f, e) = crate::post::test_fixtures::bump();
        let u = metric();
        let moments: Vec<f64> = e.mx.iter().map(|m| 1e3 * (m - 3.0)).collect();
        let map = MapValues {
            values: &moments,
            name: "mx",
            scale: u.moment(),
        };
        let (plain, over) = both(0.5, |svg, png, o| {
            write_field_map(svg, png, &f, &map, "Moments", &u, o)
        });
        assert!(plain.contains("mx (kN·m/m)") && plain.contains("Moments"));
        assert!(!plain.contains("contact boundary") && !over.contains("contact boundary"));
        assert!(
            !over.contains("allowable"),
            "no level on element values: {over}"
        );
        let map = MapValues {
            values: &f.w,
            name: "w",
            scale: u.deflection(),
        };
        // The bump's w peaks at 0.01 m; 0.005 m is 5 mm on the map.
        let (_, over) = both(0.005, |svg, png, o| {
            write_field_map(svg, png, &f, &map, "w", &u, o)
        });
        assert!(
            over.contains("pressure &gt; allowable (5 mm)"),
            "nodal values carry the level"
        );

        let dir = tempfile::tempdir().expect("tempdir");
        let (svg, png) = (dir.path().join("b.svg"), dir.path().join("b.png"));
        let bad = MapValues {
            values: &f.w[1..],
            name: "w",
            scale: u.deflection(),
        };
        assert!(write_field_map(&svg, &png, &f, &bad, "bad", &u, &Overlay::default()).is_err());
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
        let (u, none) = (unitless(), Overlay::default());
        write_contact_map(&svg, &png, &f, "zero", &u, &none).expect("all zero");

        // All σ equal and in contact.
        f.sigma.iter_mut().for_each(|s| *s = 0.5);
        f.contact.iter_mut().for_each(|c| *c = true);
        write_contact_map(&svg, &png, &f, "uniform", &u, &none).expect("uniform");

        // Inconsistent arrays: an error, not a panic.
        f.sigma.pop();
        assert!(write_contact_map(&svg, &png, &f, "bad", &u, &none).is_err());

        // No cells at all.
        let mut g = bump_field();
        g.nx = 0;
        g.ny = 0;
        for v in [&mut g.x, &mut g.y, &mut g.sigma, &mut g.pressure] {
            v.truncate(1);
        }
        g.contact.truncate(1);
        write_contact_map(&svg, &png, &g, "point", &u, &none).expect("single node");
        let over = Overlay {
            allowable_pressure: Some(0.1),
            voids: vec![[(0.0, 0.0), (1.0, 1.0)]],
            ..Overlay::default()
        };
        write_contact_map(&svg, &png, &g, "point", &metric(), &over).expect("single node");
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
