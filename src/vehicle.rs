//! An axle or a gear kept whole: its tires relative to a reference point and a heading, so that
//! a model can move it ([`crate::model::Model::place`]) without its scene file — what the
//! critical position search does at every point of its grid, and what any study that moves a
//! vehicle does.
//!
//! Tire prints follow the Portland Cement Association's rectangle (PCA 1984; Huang, *Pavement
//! Analysis and Design*, 2004, §4.4): the print of area A is 0.8712 L along the travel by 0.6 L
//! across, L = √(A/0.5227) — or a square of the same area (`contact_shape = "square"`, and for
//! headings that are not a multiple of 90°, since the plate's load patches are rectangles along
//! its axes). The scene's `[[load]]` entry is read in [`crate::scene::vehicles`]; this module
//! only places what it read.

use std::ops::Range;

use crate::error::{Error, Result};

/// One tire's print on the plate: its centre (m), its sides along x and y (m) and its load (N).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tire {
    /// Centre (x, y), m.
    pub centre: [f64; 2],
    /// Sides along x and y, m.
    pub size: [f64; 2],
    /// Load, N.
    pub force: f64,
}

/// One wheel of the group, in the vehicle's frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wheel {
    /// (along the travel, across it) from the reference point, m.
    pub offset: [f64; 2],
    /// Load, N.
    pub force: f64,
}

/// The plate in unit geometry, as the prints need it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    /// Metres to unit coordinates along x and y.
    pub scale_xy: [f64; 2],
    /// Half sides in unit coordinates.
    pub half: [f64; 2],
    /// Metres² to unit areas.
    pub area_scale: f64,
    /// The plate's sides (length along x, width along y), m, as the scene gives them.
    pub plate: [f64; 2],
}

/// A print in unit geometry: [x0, x1], [y0, y1] and its pressure, N per unit area (neither
/// factored nor divided by P).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Print {
    /// [x0, x1] / L.
    pub x: [f64; 2],
    /// [y0, y1] / L.
    pub y: [f64; 2],
    /// Pressure, N per unit area of the unit geometry.
    pub pressure: f64,
}

/// An `axle` or `gear` load of a scene, kept as one group of tire prints.
#[derive(Debug, Clone, PartialEq)]
pub struct Vehicle {
    /// Its `name`, if the scene gives one.
    pub name: Option<String>,
    /// Its `[[load]]` entry (errors name `load[entry]`).
    pub entry: usize,
    /// Its load case.
    pub case: String,
    /// An axle group (true) or a gear.
    pub axle: bool,
    /// Where it stands: reference point x, y (m) and heading (degrees).
    pub at: [f64; 3],
    /// The wheels.
    pub wheels: Vec<Wheel>,
    /// Tire pressure, Pa: each print's area is its load over it.
    pub pressure: f64,
    /// Square prints at every heading (`contact_shape = "square"`).
    pub square: bool,
    /// The plate it stands on.
    pub frame: Frame,
    /// The factor on its case in the model's load set (1 without combinations).
    pub factor: f64,
    /// Its prints' places in the model's loads, one per wheel in order.
    pub loads: Range<usize>,
}

impl Vehicle {
    /// The tire prints with the reference point and heading at `at` = (x, y, heading): in
    /// metres about the plate's centre; two prints that overlap are refused.
    pub fn tires(&self, at: [f64; 3]) -> Result<Vec<Tire>> {
        let field = |n: &str| format!("load[{}].{n}", self.entry);
        let [x0, y0, heading] = at;
        if !(x0.is_finite() && y0.is_finite() && heading.is_finite()) {
            return Err(Error::invalid(
                field("x"),
                format!("the reference point and heading must be finite, got {at:?}"),
            ));
        }
        let (s, c) = heading.to_radians().sin_cos();
        let quarter = (heading / 90.0).round();
        let axis_aligned = (heading / 90.0 - quarter).abs() < 1e-9;
        let across_x = axis_aligned && (quarter as i64).rem_euclid(2) == 1;
        let tires: Vec<Tire> = self
            .wheels
            .iter()
            .map(
                |&Wheel {
                     offset: [u, v],
                     force,
                 }| {
                    let area = force / self.pressure;
                    let size = if self.square || !axis_aligned {
                        [area.sqrt(); 2]
                    } else {
                        let l = (area / 0.5227).sqrt();
                        let (along, across) = (0.8712 * l, 0.6 * l);
                        if across_x {
                            [across, along]
                        } else {
                            [along, across]
                        }
                    };
                    Tire {
                        centre: [x0 + u * c - v * s, y0 + u * s + v * c],
                        size,
                        force,
                    }
                },
            )
            .collect();
        // Two prints must not overlap: the loads would add where the tires cannot.
        for (i, a) in tires.iter().enumerate() {
            for b in &tires[i + 1..] {
                let gap_x = (a.centre[0] - b.centre[0]).abs() - (a.size[0] + b.size[0]) / 2.0;
                let gap_y = (a.centre[1] - b.centre[1]).abs() - (a.size[1] + b.size[1]) / 2.0;
                if gap_x < -1e-9 && gap_y < -1e-9 {
                    return Err(Error::invalid(
                        field("tire_pressure"),
                        format!("two tire prints overlap (at ({:.3}, {:.3}) and ({:.3}, {:.3}) m): the pressure is too low for the spacing, or the wheels too close", a.centre[0], a.centre[1], b.centre[0], b.centre[1]),
                    ));
                }
            }
        }
        Ok(tires)
    }

    /// The prints at `at` in unit geometry, each a uniform pressure (its load over its area,
    /// per unit area of the unit geometry); a print off the plate is refused.
    pub fn prints(&self, at: [f64; 3]) -> Result<Vec<Print>> {
        let g = &self.frame;
        let field = |n: &str| format!("load[{}].{n}", self.entry);
        let mut out = Vec::with_capacity(self.wheels.len());
        for t in self.tires(at)? {
            let to_unit = |centre: f64, side: f64, axis: usize| -> Result<[f64; 2]> {
                let (lo, hi) = (centre - side / 2.0, centre + side / 2.0);
                let (ulo, uhi) = (lo * g.scale_xy[axis], hi * g.scale_xy[axis]);
                let half = g.half[axis];
                if ulo < -half * (1.0 + 1e-9) || uhi > half * (1.0 + 1e-9) {
                    return Err(Error::invalid(
                        field(if axis == 0 { "x" } else { "y" }),
                        format!(
                            "the tire print at ({:.3}, {:.3}) m reaches [{lo:.3}, {hi:.3}] m, off the plate (±{:.3} m): move the reference point or turn the heading",
                            t.centre[0],
                            t.centre[1],
                            half / g.scale_xy[axis]
                        ),
                    ));
                }
                Ok([ulo.max(-half), uhi.min(half)])
            };
            out.push(Print {
                x: to_unit(t.centre[0], t.size[0], 0)?,
                y: to_unit(t.centre[1], t.size[1], 1)?,
                pressure: t.force / (t.size[0] * t.size[1]) * g.area_scale,
            });
        }
        Ok(out)
    }
}
