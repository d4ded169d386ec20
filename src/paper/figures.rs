//! The charts of Figs. 3–7: which solves go into each (drawn by [`crate::output::chart`]).

use std::path::Path;

use plotters::style::RGBColor;

use super::cases::FOUNDATIONS;
use super::solved::Solved;
use super::{LoadCondition2, PaperFigure};
use crate::error::Result;
use crate::foundation::FoundationKind;
use crate::method::Contact;
use crate::output::chart::style::SERIES;
use crate::output::chart::{write_contact_regions, write_profile_comparison, Curve, Region};
use crate::output::Staged;
use crate::post::FullField;

/// Draw both foundations' charts of every figure from the runs at level `finest` into
/// `staged`, add the file names to each figure and return them all, in order.
pub(super) fn draw(
    figures: &mut [PaperFigure],
    solved: &[Solved],
    finest: usize,
    load2: LoadCondition2,
    staged: &mut Staged,
) -> Result<Vec<String>> {
    let mut files = Vec::new();
    for fig in figures.iter_mut() {
        for foundation in FOUNDATIONS {
            let tag = format!("fig{}-{}", fig.number, foundation.names().stem);
            let (svg_name, png_name) = (format!("{tag}.svg"), format!("{tag}.png"));
            let svg_path = staged.path(&svg_name);
            let png_path = staged.path(&png_name);
            let chart = Chart {
                fig,
                foundation,
                solved,
                finest,
                load2,
            };
            chart.write(&svg_path, &png_path)?;
            fig.files.push(svg_name.clone());
            fig.files.push(png_name.clone());
            files.push(svg_name);
            files.push(png_name);
        }
    }
    Ok(files)
}

/// One chart: a figure on one foundation.
struct Chart<'a> {
    fig: &'a PaperFigure,
    foundation: FoundationKind,
    solved: &'a [Solved],
    finest: usize,
    load2: LoadCondition2,
}

impl Chart<'_> {
    /// The solve of figure `fig_no`, this foundation, `contact` and Γ_k at the finest level.
    fn of(&self, fig_no: u8, contact: Contact, k: usize) -> Option<&Solved> {
        self.solved.iter().find(|s| {
            s.case.figure == fig_no
                && s.case.foundation == self.foundation
                && s.case.contact == contact
                && s.case.gamma_index == k
                && s.run.refine == self.finest
        })
    }

    /// The chart's title, with the mesh of its Γ_1 unbonded run.
    fn caption(&self) -> String {
        let (fig, foundation) = (self.fig, self.foundation);
        let elements = self
            .of(
                if fig.number == 6 {
                    5
                } else if fig.number == 7 {
                    3
                } else {
                    fig.number
                },
                Contact::Unbonded,
                1,
            )
            .map(|s| s.run.elements)
            .unwrap_or([0, 0]);
        if fig.number == 6 {
            format!(
                "Fig. 6: contact regions, μ = 0.5, load condition 2 (γ = {}), {}, {} × {} elements",
                self.load2.gamma(foundation),
                foundation.names().label,
                elements[0],
                elements[1]
            )
        } else {
            format!(
                "Fig. {}: {}, {}, {} × {} elements",
                fig.number,
                fig.title,
                foundation.names().label,
                elements[0],
                elements[1]
            )
        }
    }

    /// Draw the chart to `svg_path` and `png_path`.
    fn write(&self, svg_path: &Path, png_path: &Path) -> Result<()> {
        let fig = self.fig;
        let caption = self.caption();
        match fig.number {
            3..=5 => {
                let series: Vec<Curve> = (1..=3)
                    .filter_map(|k| {
                        self.of(fig.number, Contact::Unbonded, k).map(|s| Curve {
                            label: format!("Γ{k} = {:.2e}", s.case.gamma),
                            colour: GAMMA_COLOURS[k - 1],
                            dashed: false,
                            profiles: &s.report.profiles,
                        })
                    })
                    .collect();
                write_profiles(svg_path, png_path, &caption, fig.mu, &series)
            }
            6 => {
                let regions: Vec<(String, RGBColor, &FullField)> = (1..=3)
                    .filter_map(|k| {
                        self.of(5, Contact::Unbonded, k).map(|s| {
                            (
                                format!("Γ{k} = {:.2e}", s.case.gamma),
                                GAMMA_COLOURS[k - 1],
                                &s.report.field,
                            )
                        })
                    })
                    .collect();
                let loaded = loaded_areas(self.load2, self.foundation);
                write_regions(svg_path, png_path, &caption, fig.mu, &loaded, &regions)
            }
            _ => {
                let mut series = Vec::new();
                if let Some(s) = self.of(3, Contact::Unbonded, 1) {
                    series.push(Curve {
                        label: "unbonded".into(),
                        colour: RGBColor(31, 119, 180),
                        dashed: false,
                        profiles: &s.report.profiles,
                    });
                }
                if let Some(s) = self.of(7, Contact::Bonded, 1) {
                    series.push(Curve {
                        label: "bonded".into(),
                        colour: RGBColor(214, 39, 40),
                        dashed: true,
                        profiles: &s.report.profiles,
                    });
                }
                write_profiles(svg_path, png_path, &caption, fig.mu, &series)
            }
        }
    }
}

/// Loaded rectangles of load condition 2 in (x/L, y/L) for the Fig. 6 chart.
fn loaded_areas(load2: LoadCondition2, foundation: FoundationKind) -> Vec<[(f64, f64); 2]> {
    let mu = 0.5;
    let g = load2.gamma(foundation);
    match load2 {
        LoadCondition2::CaptionPatch | LoadCondition2::Patch { .. } => {
            vec![[(-g, -g * mu), (g, g * mu)]]
        }
        LoadCondition2::EdgeBand => {
            let b = 1.0 - g;
            vec![
                [(-1.0, -mu), (-b, mu)],
                [(b, -mu), (1.0, mu)],
                [(-b, -mu), (b, -b * mu)],
                [(-b, b * mu), (b, mu)],
            ]
        }
    }
}

/// Colours of Γ_1, Γ_2, Γ_3: blue, orange, green of the shared series palette (red is the
/// bonded curve of Fig. 7).
const GAMMA_COLOURS: [RGBColor; 3] = [SERIES[0], SERIES[3], SERIES[2]];

/// The lines drawn for a plate: centre lines, edges and the diagonal (the symmetric duplicates
/// of a square plate are left out).
fn lines_for(mu: f64) -> Vec<(&'static str, &'static str)> {
    if mu == 1.0 {
        vec![
            ("x-axis", "centre line t = 0"),
            ("edge-x", "edge t = 1"),
            ("diagonal", "diagonal s = t"),
        ]
    } else {
        vec![
            ("x-axis", "centre line t = 0"),
            ("y-axis", "centre line s = 0"),
            ("edge-x", "long edge t = 1"),
            ("edge-y", "short edge s = 1"),
            ("diagonal", "diagonal s = t"),
        ]
    }
}

/// Figs. 3–5 and 7: V and σ along the half lines of [`lines_for`], one curve per solve.
fn write_profiles(
    svg: &Path,
    png: &Path,
    title: &str,
    mu: f64,
    curves: &[Curve<'_>],
) -> Result<()> {
    write_profile_comparison(svg, png, title, &lines_for(mu), curves)
}

/// Fig. 6: the contact boundaries of the plate [−1, 1] × [−μ, μ] (in units of L) over the
/// loaded areas.
fn write_regions(
    svg: &Path,
    png: &Path,
    title: &str,
    mu: f64,
    loaded: &[[(f64, f64); 2]],
    regions: &[Region<'_>],
) -> Result<()> {
    let plate = [(-1.0, -mu), (1.0, mu)];
    write_contact_regions(svg, png, title, plate, loaded, regions)
}
