//! The whole plate's fields as the outputs read them: nodal values over every node copy
//! ([`FullField`]) and element-centre resultants and stresses ([`ElementField`]).
//!
//! **Node copies.** On a plate cut by joints each node on a cutting line has one copy per side
//! (four at a crossing of two such lines). The nodal arrays hold the (nx + 1)(ny + 1) grid
//! nodes first, node i + j (nx + 1) — on a joint the copy of the lower / left side —, then the
//! extra copies in the order of [`FullField::extra_grid`]. Each element reads its own copies
//! through [`FullField::element_nodes`], so everything drawn or integrated element by element
//! (contact area and boundary, exceedance, maps, the VTU) sees each side's own values; what is
//! read at a point of the plate ([`FullField::interpolate`]: profiles, extents, the centre
//! value) reads the grid nodes, i.e. the lower / left side of a joint.

use crate::layout::{Axis, JointType};
use crate::units::{Measure, UnitSystem};

/// A joint line of the whole plate, for drawing and tables.
#[derive(Debug, Clone, PartialEq)]
pub struct JointLine {
    /// The joint's name.
    pub name: String,
    /// Its kind (continuous lines only delimit panels).
    pub kind: JointType,
    /// x = const (Axis::X) or y = const.
    pub axis: Axis,
    /// The line's coordinate, in the units of [`FullField::x`] / [`FullField::y`].
    pub at: f64,
    /// A segment's extent along the line, in the same units; `None` across the whole plate.
    pub span: Option<[f64; 2]>,
}

/// Nodal fields over the whole plate: the (nx + 1) × (ny + 1) grid nodes (index i + j (nx + 1))
/// and then the extra copies along cutting joints (module docs).
#[derive(Debug, Clone, Default)]
pub struct FullField {
    /// Elements along x over the whole plate.
    pub nx: usize,
    /// Elements along y over the whole plate.
    pub ny: usize,
    /// x, physical.
    pub x: Vec<f64>,
    /// y, physical.
    pub y: Vec<f64>,
    /// s = x / L.
    pub s: Vec<f64>,
    /// t = y / (μL).
    pub t: Vec<f64>,
    /// Deflection w, physical, downward.
    pub w: Vec<f64>,
    /// ψx, physical (rad).
    pub psi_x: Vec<f64>,
    /// ψy, physical (rad).
    pub psi_y: Vec<f64>,
    /// Contact pressure r, physical, compression positive.
    pub pressure: Vec<f64>,
    /// Gap (foundation settlement − w), physical length; ≥ 0 where the plate lifted.
    pub gap: Vec<f64>,
    /// Would-be gap φ = gap − c r, the gap with the node's own pressure released
    /// ([`super::boundary`]), physical length: negative in contact, the gap where lifted; −w on
    /// Winkler. Its bilinear zero level set is the contact boundary.
    pub signed_gap: Vec<f64>,
    /// c of the would-be gap, as physical length per unit of the paper's σ: −φ / c is a
    /// pressure (σ in contact).
    pub gap_per_sigma: f64,
    /// V = D w / (P L²).
    pub v: Vec<f64>,
    /// σ = μ L² r / P.
    pub sigma: Vec<f64>,
    /// Pressure above [`super::CONTACT_THRESHOLD`] of the peak.
    pub contact: Vec<bool>,
    /// Largest principal stress at the bottom face, recovered at the nodes (the mean of the
    /// stress components of the elements around a node copy, then its principal value).
    pub s1_bottom: Vec<f64>,
    /// Largest principal stress at the top face, recovered at the nodes.
    pub s1_top: Vec<f64>,
    /// The grid node (i + j (nx + 1)) of each extra copy, in the order of the arrays after the
    /// grid nodes; empty on a plate that no joint cuts.
    pub extra_grid: Vec<usize>,
    /// The node copy at each corner of each element (element ie + je nx, corners
    /// counter-clockwise from the lower left); `None` on a plate that no joint cuts, whose
    /// elements read the grid nodes.
    pub corners: Option<Vec<[usize; 4]>>,
    /// The panel (column + row · columns) of each element; empty without a layout.
    pub panel: Vec<u32>,
    /// Whether each element (ie + je nx) is plate; empty on a plate that is its whole
    /// rectangle. The nodes of a shaped plate that no plate element holds keep their place in
    /// the arrays with zero values, out of contact: what reads element by element skips the
    /// cells outside ([`Self::is_plate`]), what lists nodes skips those nodes
    /// ([`Self::node_on_plate`]).
    pub plate: Vec<bool>,
    /// The joint lines of the plate (every kind), in the scene's order.
    pub joints: Vec<JointLine>,
}

impl FullField {
    /// Nodes along x.
    pub fn nodes_x(&self) -> usize {
        self.nx + 1
    }

    /// Grid nodes, (nx + 1)(ny + 1): the first entries of every nodal array.
    pub fn n_grid(&self) -> usize {
        (self.nx + 1) * (self.ny + 1)
    }

    /// Node copies: the grid nodes and the extra copies along cutting joints.
    pub fn n_nodes(&self) -> usize {
        self.n_grid() + self.extra_grid.len()
    }

    /// The grid position (i, j) of node copy `n`.
    pub fn node_ij(&self, n: usize) -> (usize, usize) {
        let g = if n < self.n_grid() {
            n
        } else {
            self.extra_grid[n - self.n_grid()]
        };
        (g % self.nodes_x(), g / self.nodes_x())
    }

    /// True when element (i, j) is plate.
    pub fn is_plate(&self, i: usize, j: usize) -> bool {
        self.plate.get(i + j * self.nx).copied().unwrap_or(true)
    }

    /// True when the point (s, t) ∈ [−1, 1]² lies on the plate: in the closure of a plate cell
    /// (always on a plate that is its whole rectangle).
    pub fn on_plate_at(&self, s: f64, t: f64) -> bool {
        if self.plate.is_empty() {
            return true;
        }
        let f = |v: f64, n: usize| (v + 1.0) * 0.5 * n as f64;
        let (fx, fy) = (f(s, self.nx), f(t, self.ny));
        let near = |v: f64, n: usize| {
            let lo = ((v - 1e-9).floor().max(0.0) as usize).min(n - 1);
            let hi = ((v + 1e-9).floor().max(0.0) as usize).min(n - 1);
            lo..=hi
        };
        near(fx, self.nx).any(|i| near(fy, self.ny).any(|j| self.is_plate(i, j)))
    }

    /// The plate's cells over all cells: its area over its bounding rectangle's (1 on a plate
    /// that is its whole rectangle).
    pub fn plate_fraction(&self) -> f64 {
        match self.plate.is_empty() {
            true => 1.0,
            false => self.plate.iter().filter(|&&p| p).count() as f64 / self.plate.len() as f64,
        }
    }

    /// Whether each node copy belongs to a plate element (all true on a plate that is its
    /// whole rectangle).
    pub fn node_on_plate(&self) -> Vec<bool> {
        let mut on = vec![self.plate.is_empty(); self.n_nodes()];
        if !self.plate.is_empty() {
            for j in 0..self.ny {
                for i in 0..self.nx {
                    if self.is_plate(i, j) {
                        for n in self.element_nodes(i, j) {
                            on[n] = true;
                        }
                    }
                }
            }
        }
        on
    }

    /// The node copies at the corners of element (i, j), counter-clockwise from (i, j): its own
    /// side's copies on a jointed plate.
    pub fn element_nodes(&self, i: usize, j: usize) -> [usize; 4] {
        if let Some(c) = &self.corners {
            return c[i + j * self.nx];
        }
        let n = self.nodes_x();
        [
            i + j * n,
            i + 1 + j * n,
            i + 1 + (j + 1) * n,
            i + (j + 1) * n,
        ]
    }

    /// The panel of each extra copy (the panel of an element that holds it), in the order of
    /// [`Self::extra_grid`]; empty without extra copies.
    pub fn extra_panels(&self) -> Vec<u32> {
        let n_grid = self.n_grid();
        let mut out = vec![0; self.extra_grid.len()];
        if let Some(corners) = &self.corners {
            for (e, c) in corners.iter().enumerate() {
                for &n in c {
                    if n >= n_grid {
                        out[n - n_grid] = self.panel.get(e).copied().unwrap_or(0);
                    }
                }
            }
        }
        out
    }

    /// The numeric per-node columns of nodes.csv in its order, by name, with what each
    /// measures (node copies in the order of the arrays); `contact` is the one boolean column
    /// beside them.
    pub fn columns(&self) -> [(&'static str, Measure, &[f64]); 13] {
        [
            ("x", Measure::Length, &self.x),
            ("y", Measure::Length, &self.y),
            ("s", Measure::Number, &self.s),
            ("t", Measure::Number, &self.t),
            ("w", Measure::Deflection, &self.w),
            ("psi_x", Measure::Rotation, &self.psi_x),
            ("psi_y", Measure::Rotation, &self.psi_y),
            ("pressure", Measure::Pressure, &self.pressure),
            ("gap", Measure::Deflection, &self.gap),
            ("V", Measure::Number, &self.v),
            ("sigma", Measure::Number, &self.sigma),
            ("s1_bottom", Measure::Pressure, &self.s1_bottom),
            ("s1_top", Measure::Pressure, &self.s1_top),
        ]
    }

    /// The same field with every physical value in `system`'s units (None, a dimensionless
    /// scene: unchanged), for the files that report it in the scene's system.
    pub fn in_units(&self, system: Option<UnitSystem>) -> FullField {
        let c = |m: Measure, v: &[f64]| -> Vec<f64> {
            v.iter().map(|&x| m.from_si(system, x)).collect()
        };
        let (l, d, r, p) = (
            Measure::Length,
            Measure::Deflection,
            Measure::Rotation,
            Measure::Pressure,
        );
        FullField {
            x: c(l, &self.x),
            y: c(l, &self.y),
            w: c(d, &self.w),
            psi_x: c(r, &self.psi_x),
            psi_y: c(r, &self.psi_y),
            pressure: c(p, &self.pressure),
            gap: c(d, &self.gap),
            signed_gap: c(d, &self.signed_gap),
            gap_per_sigma: d.from_si(system, self.gap_per_sigma),
            s1_bottom: c(p, &self.s1_bottom),
            s1_top: c(p, &self.s1_top),
            joints: self
                .joints
                .iter()
                .map(|j| JointLine {
                    at: l.from_si(system, j.at),
                    span: j.span.map(|s| s.map(|v| l.from_si(system, v))),
                    ..j.clone()
                })
                .collect(),
            ..self.clone()
        }
    }

    /// A nodal field at the grid node nearest the physical point (x, y), read as the copy of the
    /// element on the `towards` side of it ([right, up]: the element to +x of the node when
    /// right, to +y when up) — on a joint line, that side's own copy. None off the grid or where
    /// the field has no such value.
    pub fn at_node_of(&self, field: &[f64], x: f64, y: f64, towards: [bool; 2]) -> Option<f64> {
        let n = self.nodes_x();
        let (half_x, half_y) = (*self.x.get(self.nx)?, *self.y.get(self.ny * n)?);
        let node = |v: f64, half: f64, count: usize| -> Option<usize> {
            let f = ((v / half + 1.0) * 0.5 * count as f64).round();
            (half > 0.0 && (0.0..=count as f64).contains(&f)).then_some(f as usize)
        };
        let (ni, nj) = (node(x, half_x, self.nx)?, node(y, half_y, self.ny)?);
        let [right, up] = towards;
        // The element on that side, and the node's place among its corners, in order (−,−),
        // (+,−), (+,+), (−,+).
        let i = if right { ni } else { ni.checked_sub(1)? };
        let j = if up { nj } else { nj.checked_sub(1)? };
        if i >= self.nx || j >= self.ny {
            return None;
        }
        let k = match (right, up) {
            (true, true) => 0,
            (false, true) => 1,
            (false, false) => 2,
            (true, false) => 3,
        };
        field.get(self.element_nodes(i, j)[k]).copied()
    }

    /// A nodal field at the physical point (x, y) on the plate, by the elements' bilinear shape
    /// functions (a deflectometer's sensor is not on a node): None off the plate. On a joint
    /// line the lower / left side's copies are read, as [`Self::interpolate`].
    pub fn at(&self, field: &[f64], x: f64, y: f64) -> Option<f64> {
        let n = self.nodes_x();
        let (half_x, half_y) = (*self.x.get(self.nx)?, *self.y.get(self.ny * n)?);
        let inside = |v: f64, h: f64| h > 0.0 && v.abs() <= h * (1.0 + 1e-12);
        if !(inside(x, half_x) && inside(y, half_y)) || field.len() < n * (self.ny + 1) {
            return None;
        }
        Some(self.interpolate(field, x / half_x, y / half_y))
    }

    /// Bilinear interpolation of a nodal field at (s, t) ∈ [−1, 1]² from the corners of the
    /// element that holds the point — its own side's copies on a jointed plate, so that a point
    /// just past a joint reads the far side's deflection, not the loaded side's. A point on a
    /// grid line is read from the element below / to the left of it (on a joint line: the
    /// lower / left side's copies).
    pub fn interpolate(&self, field: &[f64], s: f64, t: f64) -> f64 {
        let fx = ((s + 1.0) * 0.5 * self.nx as f64).clamp(0.0, self.nx as f64);
        let fy = ((t + 1.0) * 0.5 * self.ny as f64).clamp(0.0, self.ny as f64);
        let cell = |f: f64, n: usize| {
            let below = if f > 0.0 && f.fract() == 0.0 {
                f - 1.0
            } else {
                f.floor()
            };
            (below as usize).min(n - 1)
        };
        let (i, j) = (cell(fx, self.nx), cell(fy, self.ny));
        let (a, b) = (fx - i as f64, fy - j as f64);
        let n = self.nodes_x();
        let grid = [
            i + j * n,
            i + 1 + j * n,
            i + 1 + (j + 1) * n,
            i + (j + 1) * n,
        ];
        // The element's own copies where the field holds them (every nodal field of a solve
        // does; a grid-only array reads the grid nodes).
        let own = self.element_nodes(i, j);
        let v = |k: usize| {
            field
                .get(own[k])
                .or_else(|| field.get(grid[k]))
                .copied()
                .unwrap_or(f64::NAN)
        };
        (1.0 - a) * (1.0 - b) * v(0) + a * (1.0 - b) * v(1) + a * b * v(2) + (1.0 - a) * b * v(3)
    }
}

/// Stress resultants per unit length at element centres over the whole plate, physical units,
/// element index ie + je nx, each from its own corners and its own panel's section. Moments are
/// positive when the soil-side face is in tension.
#[derive(Debug, Clone, Default)]
pub struct ElementField {
    /// Centre x.
    pub x: Vec<f64>,
    /// Centre y.
    pub y: Vec<f64>,
    /// Bending moment about the y axis, per unit length.
    pub mx: Vec<f64>,
    /// Bending moment about the x axis, per unit length.
    pub my: Vec<f64>,
    /// Twisting moment, per unit length.
    pub mxy: Vec<f64>,
    /// Transverse shear force on x faces, per unit length.
    pub qx: Vec<f64>,
    /// Transverse shear force on y faces, per unit length.
    pub qy: Vec<f64>,
    /// Stresses at the bottom (soil-side) face.
    pub bottom: super::stress::FaceStress,
    /// Stresses at the top face.
    pub top: super::stress::FaceStress,
    /// The thickness each element's stresses were taken with (its panel's; physical).
    pub thickness: Vec<f64>,
}

impl ElementField {
    /// The per-element columns of elements.csv in its order, by name (element ie + je nx).
    pub fn columns(&self) -> Vec<(&'static str, Measure, &[f64])> {
        let (b, t) = (&self.bottom, &self.top);
        let (l, m, q, p, d) = (
            Measure::Length,
            Measure::MomentPerLength,
            Measure::ForcePerLength,
            Measure::Pressure,
            Measure::Degrees,
        );
        vec![
            ("x", l, &self.x),
            ("y", l, &self.y),
            ("mx", m, &self.mx),
            ("my", m, &self.my),
            ("mxy", m, &self.mxy),
            ("qx", q, &self.qx),
            ("qy", q, &self.qy),
            ("sx_bottom", p, &b.sx),
            ("sy_bottom", p, &b.sy),
            ("sxy_bottom", p, &b.sxy),
            ("s1_bottom", p, &b.s1),
            ("s2_bottom", p, &b.s2),
            ("angle_bottom", d, &b.angle),
            ("sx_top", p, &t.sx),
            ("sy_top", p, &t.sy),
            ("sxy_top", p, &t.sxy),
            ("s1_top", p, &t.s1),
            ("s2_top", p, &t.s2),
            ("angle_top", d, &t.angle),
        ]
    }

    /// The same field with every physical value in `system`'s units (None: unchanged).
    pub fn in_units(&self, system: Option<UnitSystem>) -> ElementField {
        let c = |m: Measure, v: &[f64]| -> Vec<f64> {
            v.iter().map(|&x| m.from_si(system, x)).collect()
        };
        let face = |f: &super::stress::FaceStress| super::stress::FaceStress {
            sx: c(Measure::Pressure, &f.sx),
            sy: c(Measure::Pressure, &f.sy),
            sxy: c(Measure::Pressure, &f.sxy),
            s1: c(Measure::Pressure, &f.s1),
            s2: c(Measure::Pressure, &f.s2),
            angle: f.angle.clone(),
        };
        ElementField {
            x: c(Measure::Length, &self.x),
            y: c(Measure::Length, &self.y),
            mx: c(Measure::MomentPerLength, &self.mx),
            my: c(Measure::MomentPerLength, &self.my),
            mxy: c(Measure::MomentPerLength, &self.mxy),
            qx: c(Measure::ForcePerLength, &self.qx),
            qy: c(Measure::ForcePerLength, &self.qy),
            bottom: face(&self.bottom),
            top: face(&self.top),
            thickness: c(Measure::Length, &self.thickness),
        }
    }
}
