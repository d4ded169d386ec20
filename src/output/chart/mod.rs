//! Charts (SVG, and PNG where asked) of solves, studies and the paper's figures.
//!
//! * `profile.rs`: V and σ along the plate's lines — [`write_profiles_svg`] for a solve, and
//!   the paper's Figs. 3–5 and 7;
//! * `contact.rs`: plan views of the plate — [`write_contact_map`] for a solve,
//!   [`write_field_map`] for any field (an envelope, say), and the paper's Fig. 6 (contact
//!   boundaries of several solves); `plan.rs`: the equal-scale axes and the colour map they
//!   share; `overlay.rs`: what an [`Overlay`] draws over them (pressure above the allowable
//!   one, voids, zones, line loads);
//! * `units.rs`: [`Units`], engineering units (m, mm, kPa, kN·m/m) for a physical scene and the
//!   paper's V and σ for a dimensionless one, shared with the CLI tables;
//! * `loglog.rs`: [`write_loglog_svg`], series with notes (ε̄ sweep, speed against accuracy);
//! * `semilog.rs`: [`write_semilogx`], series against a logarithmic x and a linear y (a joint's
//!   LTE against its stiffness);
//! * `basins.rs`: [`write_basins`], measured against fitted deflection basins, and
//!   [`write_moduli`], backcalculated moduli along a survey (`liftoff backcalc`);
//! * `category.rs`: [`write_category_map_svg`], run outcomes over a parameter grid (stability);
//! * `style.rs`: the one colour and line table; `axis.rs`: ranges and tick labels; this file:
//!   the font, titles, file writing and text boxes they share.
//!
//! Text is laid out with an embedded copy of DejaVu Sans (`assets/DejaVuSans.ttf`, Bitstream
//! Vera licence, see `assets/DejaVuSans-LICENSE.txt`), registered once with plotters as
//! `"sans-serif"`, so the charts render identically on machines without system fonts.

mod axis;
mod basins;
mod category;
mod comparison;
mod contact;
mod design;
mod influence;
mod loglog;
mod overlay;
mod plan;
mod profile;
mod semilog;
pub(crate) mod style;
mod units;

use std::path::Path;
use std::sync::OnceLock;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::FontStyle;

use crate::error::{Error, Result};

pub use basins::{write_basins, write_moduli, BasinChart, BasinCurve, ModuliChart, ModulusSeries};
pub use category::write_category_map_svg;
pub(crate) use comparison::{write_profile_comparison, Curve};
pub use contact::{write_contact_map, write_field_map, MapValues};
pub(crate) use contact::{write_contact_regions, Region};
pub use design::{write_design_curve, DesignCurve};
pub use influence::{write_influence_map, Influence};
pub use loglog::{write_loglog_svg, Series};
pub use overlay::Overlay;
pub(crate) use plan::short;
pub use profile::write_profiles_svg;
pub use semilog::{write_semilogx, SemilogSeries};
pub use units::{Scale, Units};

/// The embedded font.
static FONT_BYTES: &[u8] = include_bytes!("../../../assets/DejaVuSans.ttf");

/// Font family name under which the embedded font is registered.
const FONT: &str = "sans-serif";

/// Register the embedded font with plotters once; later calls return the first outcome.
fn ensure_font(path: &Path) -> Result<()> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        plotters::style::register_font(FONT, FontStyle::Normal, FONT_BYTES).is_ok()
    });
    if ok {
        Ok(())
    } else {
        Err(Error::Io {
            path: path.display().to_string(),
            source: std::io::Error::other("the embedded font DejaVuSans.ttf could not be loaded"),
        })
    }
}

/// Wrap a plotting-library failure as an I/O error on `path`.
fn plot_error(path: &Path, e: impl std::fmt::Display) -> Error {
    Error::Io {
        path: path.display().to_string(),
        source: std::io::Error::other(e.to_string()),
    }
}

/// A drawing failure, as text (the backend error types differ between SVG and bitmap).
type DrawResult<T> = std::result::Result<T, String>;

/// Convert a plotters error into text.
fn txt<E: std::fmt::Display>(e: E) -> String {
    e.to_string()
}

/// A chart that can be drawn on any plotters backend, so that its SVG and PNG are drawn by the
/// same code.
trait Picture {
    /// Picture size, pixels.
    fn size(&self) -> (u32, u32);
    /// Draw the whole picture on `root`.
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<()>;
}

/// Draw `picture` as an SVG file at `path`.
fn write_svg(path: &Path, picture: &impl Picture) -> Result<()> {
    ensure_font(path)?;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, picture.size()).into_drawing_area();
        picture.draw(&root).map_err(|e| plot_error(path, e))?;
        root.present().map_err(|e| plot_error(path, e))?;
    }
    std::fs::write(path, svg).map_err(|source| Error::Io {
        path: path.display().to_string(),
        source,
    })
}

/// Draw `picture` as a PNG file at `path`: plotters draws into an RGB buffer, the `png` crate
/// encodes it (no image-decoding stack for one file format).
fn write_png(path: &Path, picture: &impl Picture) -> Result<()> {
    ensure_font(path)?;
    let (w, h) = picture.size();
    let mut rgb = vec![0u8; 3 * w as usize * h as usize];
    {
        let root = BitMapBackend::with_buffer(&mut rgb, (w, h)).into_drawing_area();
        picture.draw(&root).map_err(|e| plot_error(path, e))?;
        root.present().map_err(|e| plot_error(path, e))?;
    }
    let file = std::fs::File::create(path).map_err(|source| Error::Io {
        path: path.display().to_string(),
        source,
    })?;
    let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), w, h);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(|e| plot_error(path, e))?;
    writer
        .write_image_data(&rgb)
        .map_err(|e| plot_error(path, e))?;
    writer.finish().map_err(|e| plot_error(path, e))
}

/// Caption font size that fits `title` on one line of a `width`-pixel chart (DejaVu Sans
/// averages about 0.56 em per character), between 10 and 24 px.
fn caption_size(title: &str, width: u32) -> u32 {
    let chars = title.chars().count().max(1) as f64;
    (0.92 * f64::from(width) / (0.56 * chars)).clamp(10.0, 24.0) as u32
}

/// Fill `root` white, write `title` across its top and return the area below the title. A
/// title that would shrink below 16 px on one line takes two ([`title_lines`]), each at the
/// size that fits it (at most 20 px).
fn titled<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    title: &str,
) -> DrawResult<DrawingArea<DB, Shift>> {
    root.fill(&WHITE).map_err(txt)?;
    let width = root.dim_in_pixel().0;
    let size = caption_size(title, width);
    let Some((first, second)) = title_lines(title).filter(|_| size < 16) else {
        return root.titled(title, (FONT, size)).map_err(txt);
    };
    let size = caption_size(first, width)
        .min(caption_size(second, width))
        .min(20);
    let line = (f64::from(size) * 1.3).round() as i32;
    let style = (FONT, size)
        .into_font()
        .color(&BLACK)
        .pos(Pos::new(HPos::Center, VPos::Top));
    let centre = i32::try_from(width / 2).unwrap_or(0);
    for (k, text) in [first, second].into_iter().enumerate() {
        let top = 8 + line * i32::try_from(k).unwrap_or(0);
        root.draw(&Text::new(text, (centre, top), style.clone()))
            .map_err(txt)?;
    }
    Ok(root.split_vertically(14 + 2 * line).1)
}

/// A long title as two lines: at its last " — " (the scene's title, then what the chart
/// shows), else at the space nearest its middle; None for a title of one word.
fn title_lines(title: &str) -> Option<(&str, &str)> {
    if let Some(i) = title.rfind(" — ") {
        return Some((&title[..i], &title[i + " — ".len()..]));
    }
    let middle = title.len() / 2;
    let i = (title.char_indices())
        .filter(|&(_, c)| c == ' ')
        .map(|(i, _)| i)
        .min_by_key(|&i| i.abs_diff(middle))?;
    Some((&title[..i], &title[i + 1..]))
}

/// Width of `text` in the embedded font at `size` px (estimated if the font fails).
fn text_width(text: &str, size: f64) -> i32 {
    (FONT, size).into_font().box_size(text).map_or(
        (0.6 * size * text.chars().count() as f64) as i32,
        |(w, _)| w as i32,
    )
}

/// Inner padding of legend and note boxes, pixels.
const BOX_PAD: i32 = 8;

/// A framed box of text lines (notes, or a legend when each line gets a swatch).
struct TextBox<'a> {
    /// The lines, top to bottom.
    lines: &'a [String],
    /// Font size, pixels.
    font: u32,
    /// Height of one line, pixels.
    line_h: i32,
    /// Room reserved left of each line for a swatch, pixels (0: none).
    swatch_w: i32,
}

impl TextBox<'_> {
    /// Width and height of the box, pixels.
    fn size(&self) -> (i32, i32) {
        let text_w = self
            .lines
            .iter()
            .map(|l| text_width(l, f64::from(self.font)))
            .max()
            .unwrap_or(0);
        (
            text_w + self.swatch_w + 2 * BOX_PAD,
            self.line_h * self.lines.len() as i32 + 2 * BOX_PAD,
        )
    }

    /// Draw the box with its top-left corner at `at`; `swatch` is called with each line's index
    /// and its left-centre point when `swatch_w` > 0.
    fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        at: (i32, i32),
        mut swatch: impl FnMut(usize, (i32, i32)) -> DrawResult<()>,
    ) -> DrawResult<()> {
        let (w, h) = self.size();
        let (x0, y0) = at;
        let corners = [(x0, y0), (x0 + w, y0 + h)];
        root.draw(&Rectangle::new(corners, style::BOX_FILL.filled()))
            .map_err(txt)?;
        root.draw(&Rectangle::new(corners, style::BOX_BORDER))
            .map_err(txt)?;
        let text =
            TextStyle::from((FONT, self.font).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
        for (k, line) in self.lines.iter().enumerate() {
            let cy = y0 + BOX_PAD + self.line_h * k as i32 + self.line_h / 2;
            let x = x0 + BOX_PAD;
            if self.swatch_w > 0 {
                swatch(k, (x, cy))?;
            }
            root.draw_text(line, &text, (x + self.swatch_w, cy))
                .map_err(txt)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_titles_break_after_the_scenes_title() {
        let t = "Jointed pavement lane: 20 years of single axles — bottom-up damage (mepdg)";
        assert_eq!(
            title_lines(t),
            Some((
                "Jointed pavement lane: 20 years of single axles",
                "bottom-up damage (mepdg)"
            ))
        );
        assert_eq!(title_lines("one two three"), Some(("one two", "three")));
        assert_eq!(title_lines("single"), None);
        // Drawn: both lines in the SVG, larger than one line would be.
        ensure_font(Path::new("test")).expect("font");
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, (900, 600)).into_drawing_area();
            let long = format!("{t}, largest 2.18; end panels not counted");
            titled(&root, &long).expect("title");
        }
        // Each line its own text element.
        let texts: Vec<&str> = svg
            .split("</text>")
            .filter_map(|t| t.rsplit('>').next())
            .collect();
        let texts: Vec<&str> = texts.iter().map(|t| t.trim()).collect();
        assert!(
            texts.contains(&"Jointed pavement lane: 20 years of single axles"),
            "{svg}"
        );
        assert!(texts.contains(&"bottom-up damage (mepdg), largest 2.18; end panels not counted"));
    }

    #[test]
    fn caption_size_shrinks_long_titles_within_bounds() {
        assert_eq!(caption_size("short", 900), 24);
        // 100 characters on 800 px: 0.92 · 800 / 56 = 13.1 px.
        assert_eq!(caption_size(&"x".repeat(100), 800), 13);
        assert_eq!(caption_size(&"x".repeat(1000), 800), 10);
        assert_eq!(caption_size("", 800), 24);
    }

    #[test]
    fn text_box_grows_with_lines_and_text() {
        ensure_font(Path::new("test")).expect("font");
        let one = ["a note".to_string()];
        let two = [
            "a note".to_string(),
            "a much longer second note".to_string(),
        ];
        let size = |lines: &[String], swatch_w| {
            TextBox {
                lines,
                font: 14,
                line_h: 20,
                swatch_w,
            }
            .size()
        };
        let (w1, h1) = size(&one, 0);
        let (w2, h2) = size(&two, 0);
        assert_eq!((h1, h2), (20 + 2 * BOX_PAD, 40 + 2 * BOX_PAD));
        assert!(w2 > w1 && w1 > 2 * BOX_PAD, "{w1} {w2}");
        assert_eq!(size(&one, 40).0, w1 + 40);
    }
}
