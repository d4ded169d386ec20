//! Category maps: run outcomes over a parameter grid (the stability study).

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::style::{self, brightness, category_colour, CATEGORIES, DESC_FONT};
use super::{text_width, titled, txt, write_svg, DrawResult, Picture, FONT};
use crate::error::Result;

/// Categorical map: a grid of cells, rows and columns labelled, each cell coloured by its
/// category with an optional short text (e.g. an iteration count) inside, and a legend of the
/// categories with their colours. `cells` are (row, col, category, text).
///
/// Known categories have fixed colours: "converged" green, "cycling" orange, "iteration-limit"
/// red, "penalty-too-weak" purple, "solver-failure" dark red, "infeasible" grey, "too-large"
/// light grey, "numerical" dark brown, "not-run" white with a grey border; any other category
/// gets a palette colour chosen deterministically from its name (different names may share a
/// colour). Row 0 is drawn at the top, column 0 at the left; the grid has
/// `row_labels.len()` rows and `col_labels.len()` columns, and cells outside it are ignored
/// (a later cell at the same position is drawn over an earlier one). Positions without a cell
/// stay blank. The legend lists the categories that occur, known ones first in the order
/// above, then the others alphabetically. The cell text is written in black or white, whichever
/// contrasts with the cell, at a size that fits the cell (left out when it cannot be legible);
/// column labels are turned vertical when they do not fit side by side. The picture size grows
/// with the grid (about 60 × 34 pixels per cell, between 640 × 420 and 2000 × 1400 pixels).
///
/// # Errors
/// [`crate::Error::Io`] if the file cannot be written or drawing fails.
pub fn write_category_map_svg(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    col_labels: &[String],
    row_labels: &[String],
    cells: &[(usize, usize, String, String)],
) -> Result<()> {
    let map = CategoryMap {
        title,
        x_label,
        y_label,
        col_labels,
        row_labels,
        cells,
    };
    write_svg(path, &map)
}

/// Everything drawn on a category map.
struct CategoryMap<'a> {
    title: &'a str,
    x_label: &'a str,
    y_label: &'a str,
    col_labels: &'a [String],
    row_labels: &'a [String],
    cells: &'a [(usize, usize, String, String)],
}

/// Categories occurring in the grid, in legend order.
fn legend_categories(map: &CategoryMap<'_>) -> Vec<String> {
    let (nr, nc) = (map.row_labels.len(), map.col_labels.len());
    let mut present: Vec<&str> = map
        .cells
        .iter()
        .filter(|(r, c, _, _)| *r < nr && *c < nc)
        .map(|(_, _, cat, _)| cat.as_str())
        .collect();
    present.sort_unstable();
    present.dedup();
    let mut out: Vec<String> = CATEGORIES
        .iter()
        .filter(|(n, _)| present.contains(n))
        .map(|(n, _)| n.to_string())
        .collect();
    out.extend(
        present
            .into_iter()
            .filter(|p| !CATEGORIES.iter().any(|(n, _)| n == p))
            .map(str::to_string),
    );
    out
}

/// Pixel layout of a category map.
#[derive(Debug, Clone)]
struct MapLayout {
    /// Picture size.
    size: (u32, u32),
    /// Widest row label and widest column label at 14 px.
    row_label_w: i32,
    col_label_w: i32,
    /// Widest legend entry text.
    legend_text_w: i32,
    /// Legend entries.
    legend: Vec<String>,
}

/// Label font size of the category map, px.
const MAP_FONT: f64 = 14.0;
/// Gap between the grid, its labels and the legend, px.
const MAP_GAP: i32 = 8;
/// Outer margin, px.
const MAP_MARGIN: i32 = 15;
/// Height of the title band (see `DrawingArea::titled`), px.
const TITLE_BAND: i32 = 40;
/// Height of one legend entry, px.
const LEGEND_LINE: i32 = 24;
/// Size of a legend colour swatch, px.
const SWATCH: i32 = 16;
/// Room for an axis description (one line of 16 px text), px.
const DESC_BAND: i32 = 24;

impl CategoryMap<'_> {
    /// Choose the picture size from the labels and texts.
    fn layout(&self) -> MapLayout {
        let nc = self.col_labels.len().max(1) as i32;
        let nr = self.row_labels.len().max(1) as i32;
        let widest = |v: &mut dyn Iterator<Item = &str>| {
            v.map(|t| text_width(t, MAP_FONT)).max().unwrap_or(0)
        };
        let row_label_w = widest(&mut self.row_labels.iter().map(String::as_str));
        let col_label_w = widest(&mut self.col_labels.iter().map(String::as_str));
        let cell_text_w = widest(&mut self.cells.iter().map(|c| c.3.as_str()));
        let legend = legend_categories(self);
        let legend_text_w = widest(&mut legend.iter().map(String::as_str));

        let cell_w = 60.max(cell_text_w + 10).min(160);
        let cell_h = 34;
        let legend_w = if legend.is_empty() {
            0
        } else {
            MAP_GAP * 2 + SWATCH + MAP_GAP + legend_text_w
        };
        let bottom = MAP_GAP + col_label_w.clamp(20, 200) + DESC_BAND;
        let left = DESC_BAND + row_label_w + MAP_GAP;
        let w = 2 * MAP_MARGIN + left + nc * cell_w + legend_w;
        let legend_h = LEGEND_LINE * legend.len() as i32;
        let h = TITLE_BAND + 2 * MAP_MARGIN + bottom + (nr * cell_h).max(legend_h);
        MapLayout {
            size: (w.clamp(640, 2000) as u32, h.clamp(420, 1400) as u32),
            row_label_w,
            col_label_w,
            legend_text_w,
            legend,
        }
    }
}

impl Picture for CategoryMap<'_> {
    fn size(&self) -> (u32, u32) {
        self.layout().size
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<()> {
        let map = self;
        let layout = self.layout();
        let body = titled(root, map.title)?;
        let (bx, by) = body.get_pixel_range();
        let (nr, nc) = (map.row_labels.len(), map.col_labels.len());

        // Horizontal budget: margin, y description, row labels, gap, grid, legend, margin.
        let legend_w = if layout.legend.is_empty() {
            0
        } else {
            MAP_GAP * 2 + SWATCH + MAP_GAP + layout.legend_text_w
        };
        let max_label_w = (bx.end - bx.start) / 3;
        let row_label_w = layout.row_label_w.min(max_label_w);
        let gx0 = bx.start + MAP_MARGIN + DESC_BAND + row_label_w + MAP_GAP;
        let gx1 = (bx.end - MAP_MARGIN - legend_w).max(gx0 + 10);
        let cell_w = f64::from(gx1 - gx0) / nc.max(1) as f64;

        // Column labels side by side if they fit, vertical otherwise.
        let vertical = nc > 0 && f64::from(layout.col_label_w) > cell_w - 6.0;
        let col_band = if vertical {
            layout
                .col_label_w
                .clamp(20, ((by.end - by.start) / 3).max(20))
        } else {
            20
        };
        let gy0 = by.start + MAP_MARGIN;
        let gy1 = (by.end - MAP_MARGIN - DESC_BAND - MAP_GAP - col_band).max(gy0 + 10);
        let cell_h = f64::from(gy1 - gy0) / nr.max(1) as f64;
        let xpix = |c: usize| gx0 + (c as f64 * cell_w).round() as i32;
        let ypix = |r: usize| gy0 + (r as f64 * cell_h).round() as i32;

        // Blank grid, then the cells.
        for r in 0..nr {
            for c in 0..nc {
                let rect = [(xpix(c), ypix(r)), (xpix(c + 1), ypix(r + 1))];
                root.draw(&Rectangle::new(rect, style::GRID_MINOR))
                    .map_err(txt)?;
            }
        }
        let text_size = (cell_h * 0.5).min(14.0);
        for (r, c, category, text) in map.cells {
            let (r, c) = (*r, *c);
            if r >= nr || c >= nc {
                continue;
            }
            let colour = category_colour(category);
            let (x0, y0, x1, y1) = (xpix(c), ypix(r), xpix(c + 1), ypix(r + 1));
            root.draw(&Rectangle::new([(x0, y0), (x1, y1)], colour.filled()))
                .map_err(txt)?;
            root.draw(&Rectangle::new([(x0, y0), (x1, y1)], WHITE))
                .map_err(txt)?;
            if category == "not-run" {
                // Inset, so that the white borders of neighbours drawn later do not hide it.
                root.draw(&Rectangle::new(
                    [(x0 + 2, y0 + 2), (x1 - 2, y1 - 2)],
                    style::CELL_BORDER,
                ))
                .map_err(txt)?;
            }
            if text.is_empty() {
                continue;
            }
            // Shrink the text to the cell width; leave it out below 7 px.
            let w14 = f64::from(text_width(text, 14.0).max(1));
            let size = text_size.min(14.0 * (cell_w - 6.0) / w14);
            if size < 7.0 {
                continue;
            }
            let ink = if brightness(colour) > 140.0 {
                BLACK
            } else {
                WHITE
            };
            let style = TextStyle::from((FONT, size).into_font())
                .color(&ink)
                .pos(Pos::new(HPos::Center, VPos::Center));
            root.draw_text(text, &style, ((x0 + x1) / 2, (y0 + y1) / 2))
                .map_err(txt)?;
        }
        // Frame (also around an empty grid).
        root.draw(&Rectangle::new(
            [(gx0, gy0), (xpix(nc.max(1)), ypix(nr.max(1)))],
            style::REFERENCE,
        ))
        .map_err(txt)?;

        // Row labels, right-aligned left of the grid, shrunk to the row height.
        let label_size = MAP_FONT.min(cell_h * 0.8);
        if label_size >= 6.0 {
            let style = TextStyle::from((FONT, label_size).into_font())
                .pos(Pos::new(HPos::Right, VPos::Center));
            for (r, label) in map.row_labels.iter().enumerate() {
                let y = (ypix(r) + ypix(r + 1)) / 2;
                root.draw_text(label, &style, (gx0 - MAP_GAP, y))
                    .map_err(txt)?;
            }
        }
        // Column labels below the grid.
        let grid_bottom = ypix(nr.max(1));
        let col_size = if vertical {
            MAP_FONT.min(cell_w * 0.8)
        } else {
            MAP_FONT
        };
        if col_size >= 6.0 {
            let style = TextStyle::from((FONT, col_size).into_font());
            let style = if vertical {
                style
                    .transform(FontTransform::Rotate270)
                    .pos(Pos::new(HPos::Right, VPos::Center))
            } else {
                style.pos(Pos::new(HPos::Center, VPos::Top))
            };
            for (c, label) in map.col_labels.iter().enumerate() {
                let x = (xpix(c) + xpix(c + 1)) / 2;
                root.draw_text(label, &style, (x, grid_bottom + MAP_GAP))
                    .map_err(txt)?;
            }
        }
        // Axis descriptions.
        let desc = TextStyle::from((FONT, DESC_FONT).into_font());
        let grid_mid_x = (gx0 + gx1) / 2;
        let grid_mid_y = (gy0 + ypix(nr.max(1))) / 2;
        root.draw_text(
            map.x_label,
            &desc.pos(Pos::new(HPos::Center, VPos::Bottom)),
            (grid_mid_x, by.end - MAP_MARGIN),
        )
        .map_err(txt)?;
        root.draw_text(
            map.y_label,
            &desc
                .transform(FontTransform::Rotate270)
                .pos(Pos::new(HPos::Center, VPos::Top)),
            (bx.start + MAP_MARGIN, grid_mid_y),
        )
        .map_err(txt)?;

        // Legend, right of the grid, from its top.
        let lx = gx1 + 2 * MAP_GAP;
        let style =
            TextStyle::from((FONT, MAP_FONT).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
        for (k, category) in layout.legend.iter().enumerate() {
            let cy = gy0 + LEGEND_LINE * k as i32 + LEGEND_LINE / 2;
            let sq = [(lx, cy - SWATCH / 2), (lx + SWATCH, cy + SWATCH / 2)];
            root.draw(&Rectangle::new(sq, category_colour(category).filled()))
                .map_err(txt)?;
            root.draw(&Rectangle::new(sq, style::CELL_BORDER))
                .map_err(txt)?;
            root.draw_text(category, &style, (lx + SWATCH + MAP_GAP, cy))
                .map_err(txt)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cell of a category map: (row, col, category, text).
    type Cell = (usize, usize, String, String);

    fn demo_cells() -> (Vec<String>, Vec<String>, Vec<Cell>) {
        let cols: Vec<String> = ["1e-1", "1e-2", "1e-3", "1e-4", "1e-5", "1e-6"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        let rows: Vec<String> = ["h/L = 0.01", "h/L = 0.05", "h/L = 0.1", "h/L = 0.2"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        let cats = [
            "converged",
            "cycling",
            "iteration-limit",
            "penalty-too-weak",
            "solver-failure",
            "infeasible",
            "too-large",
            "numerical",
            "not-run",
            "something-new",
        ];
        let mut cells = Vec::new();
        for r in 0..rows.len() {
            for c in 0..cols.len() {
                let k = (r * cols.len() + c) % cats.len();
                let text = if cats[k] == "not-run" {
                    String::new()
                } else {
                    format!("{}", 3 + 7 * k)
                };
                cells.push((r, c, cats[k].to_string(), text));
            }
        }
        cells.push((99, 0, "converged".to_string(), "x".to_string()));
        cells.push((0, 99, "converged".to_string(), "x".to_string()));
        (cols, rows, cells)
    }

    #[test]
    fn category_map_svg_is_written() {
        let dir = tempfile::tempdir().expect("tempdir");
        let path = dir.path().join("map.svg");
        let (cols, rows, cells) = demo_cells();
        write_category_map_svg(&path, "Outcome map title", "ε̄", "h/L", &cols, &rows, &cells)
            .expect("write");
        let text = std::fs::read_to_string(&path).expect("read");
        assert!(text.contains("<svg"));
        assert!(text.contains("Outcome map title"));
        assert!(text.contains("penalty-too-weak"));
        assert!(text.contains("something-new"));
        assert!(text.contains("h/L = 0.05"));
    }

    #[test]
    fn category_map_handles_degenerate_input() {
        let dir = tempfile::tempdir().expect("tempdir");
        let path = dir.path().join("empty.svg");
        write_category_map_svg(&path, "Empty map", "x", "y", &[], &[], &[]).expect("empty");
        let text = std::fs::read_to_string(&path).expect("read");
        assert!(text.contains("<svg") && text.contains("Empty map"));

        // Labels but no cells, cells all outside, and a huge grid with long labels.
        let cols: Vec<String> = (0..3).map(|c| format!("c{c}")).collect();
        let rows: Vec<String> = (0..2).map(|r| format!("r{r}")).collect();
        let outside = vec![(5, 5, "converged".to_string(), "1".to_string())];
        write_category_map_svg(&path, "No cells", "x", "y", &cols, &rows, &outside)
            .expect("outside");
        assert!(std::fs::read_to_string(&path)
            .expect("read")
            .contains("No cells"));

        let cols: Vec<String> = (0..80)
            .map(|c| format!("a long column label {c}"))
            .collect();
        let rows: Vec<String> = (0..120).map(|r| format!("row {r}")).collect();
        let cells: Vec<_> = (0..120)
            .flat_map(|r| {
                (0..80).map(move |c| (r, c, format!("cat{}", (r + c) % 13), "12345".to_string()))
            })
            .collect();
        write_category_map_svg(&path, "Huge", "x", "y", &cols, &rows, &cells).expect("huge");
        assert!(std::fs::read_to_string(&path)
            .expect("read")
            .contains("Huge"));
    }

    #[test]
    fn legend_lists_known_categories_first() {
        let (cols, rows, cells) = demo_cells();
        let map = CategoryMap {
            title: "",
            x_label: "",
            y_label: "",
            col_labels: &cols,
            row_labels: &rows,
            cells: &cells,
        };
        let legend = legend_categories(&map);
        assert_eq!(legend.first().map(String::as_str), Some("converged"));
        assert_eq!(legend.last().map(String::as_str), Some("something-new"));
        assert_eq!(legend.len(), 10);
    }

    #[test]
    fn category_map_renders_to_png() {
        // The bitmap backend runs the same drawing code as the SVG file.
        let dir = tempfile::tempdir().expect("tempdir");
        let (cols, rows, cells) = demo_cells();
        let map = CategoryMap {
            title: "Outcome of the penalty iteration",
            x_label: "ε̄",
            y_label: "thickness",
            col_labels: &cols,
            row_labels: &rows,
            cells: &cells,
        };
        let png = dir.path().join("map.png");
        super::super::write_png(&png, &map).expect("png");
        let bytes = std::fs::read(&png).expect("read png");
        assert!(bytes.starts_with(&[0x89, b'P', b'N', b'G']));
    }
}
