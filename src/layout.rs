//! The layout of a jointed slab: joint lines across the whole plate and joint segments that
//! end at another joint or at the edge, each with its load transfer; per-panel overrides of
//! thickness and Young's modulus; and the plate's shape — an outline, openings, panels of their
//! own outline — in the unit system of [`crate::model`] (lengths / L, D of the reference
//! plate = 1).
//!
//! Joint lines run across the whole plate, so they cut it into a grid of rectangular *panels*,
//! numbered by (column, row) from the lower-left (0-based here, 1-based in messages); segments
//! cut it along their extent only and delimit no panel, and the panels of their own outline
//! (`regions`) are numbered after the grid's. A joint
//! stores energy per unit length ½ c (w⁺ − w⁻)² (+ ½ c_r (ψn⁺ − ψn⁻)² for a tied joint), a dowel
//! ½ k_d (w⁺ − w⁻)² at its bar. In the unit system (energy unit P² L²/D, the plate's
//! D w²/L² · L²) the constants are c̄ = c L³/D, c̄_r = c_r L/D and k̄_d = k_d L²/D.
//!
//! A `continuous` joint is no joint at all: it only delimits panels (for their overrides).
//! Stiff springs are not the continuous plate: the tangential rotation may still jump across
//! a joint of springs (an O(H/ℓ) difference for Mindlin plates).

/// Which family of lines a joint belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Axis {
    /// A line x = const (across the plate's width: a transverse joint).
    X,
    /// A line y = const.
    Y,
}

impl Axis {
    /// The coordinate name the line is given by ("x" or "y").
    pub fn name(self) -> &'static str {
        match self {
            Axis::X => "x",
            Axis::Y => "y",
        }
    }
}

/// The kind of a joint, without its parameters (scene names).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum JointType {
    /// Two free edges side by side: no transfer.
    Free,
    /// No joint: one plate across the line (the line only delimits panels).
    Continuous,
    /// A distributed shear spring on the jump of w (aggregate interlock).
    Aggregate,
    /// Shear and moment transfer: springs on the jumps of w and of the normal rotation.
    Tied,
    /// Dowel bars: point springs on the jump of w at the bars.
    Dowels,
}

crate::choice::names!(JointType, Free => "free", Continuous => "continuous", Aggregate => "aggregate",
    Tied => "tied", Dowels => "dowels");

/// What the plate's ends across a lane (x = ±a/2) are (`[plate] ends`, `critical --ends`,
/// `[traffic] ends`): where the plate has two or more transverse joints, the studies read a
/// cut lane between its first and last joint only (`study::ends`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Ends {
    /// The model cuts a lane that goes on: the end panels are the inner ones' neighbours, and
    /// what happens in them is not read.
    Cut,
    /// The plate ends there (a floor, an apron, a lane that ends at a bridge): every panel is
    /// read.
    Free,
}

crate::choice::names!(Ends, Cut => "cut", Free => "free");

/// A joint's transfer with its constants in the unit system.
#[derive(Debug, Clone, PartialEq)]
pub enum JointKind {
    /// Two free edges.
    Free,
    /// No joint.
    Continuous,
    /// Shear spring per unit length c̄ = c L³/D (c = AGG in N/m²).
    Aggregate {
        /// c̄.
        c: f64,
    },
    /// Shear spring c̄ and rotational spring c̄_r = c_r L/D (c_r in N·m/m per rad) on the
    /// rotation normal to the joint.
    Tied {
        /// c̄.
        c: f64,
        /// c̄_r.
        c_r: f64,
    },
    /// Dowel bars, each a spring k̄_d = k_d L²/D (k_d in N/m) on the jump of w.
    Dowels {
        /// k̄_d per bar.
        k: f64,
        /// Bar positions along the joint (y / L for a line x = const, x / L for y = const).
        positions: Vec<f64>,
        /// The bar, when the spring comes from its properties (for its bearing stress).
        bar: Option<DowelBar>,
    },
}

impl JointKind {
    /// The kind's name.
    pub fn kind(&self) -> JointType {
        match self {
            JointKind::Free => JointType::Free,
            JointKind::Continuous => JointType::Continuous,
            JointKind::Aggregate { .. } => JointType::Aggregate,
            JointKind::Tied { .. } => JointType::Tied,
            JointKind::Dowels { .. } => JointType::Dowels,
        }
    }

    /// True when the plate is cut along the line (nodes doubled): every kind but continuous.
    pub fn doubles(&self) -> bool {
        !matches!(self, JointKind::Continuous)
    }

    /// True when the joint transfers load (springs across it).
    pub fn transfers(&self) -> bool {
        !matches!(self, JointKind::Free | JointKind::Continuous)
    }
}

/// A dowel bar in SI units: a beam (E_d, I_d = πd⁴/64) on a Winkler bed of modulus K (N/m³,
/// the modulus of dowel support; K·d per unit length) in each slab, across a joint opening z.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DowelBar {
    /// Diameter d, m.
    pub diameter: f64,
    /// Young's modulus E_d, Pa.
    pub youngs_modulus: f64,
    /// Joint opening z, m.
    pub opening: f64,
    /// Modulus of dowel support K, N/m³.
    pub support: f64,
}

impl DowelBar {
    /// Bending stiffness E_d I_d, N·m².
    pub fn bending(&self) -> f64 {
        self.youngs_modulus * std::f64::consts::PI * self.diameter.powi(4) / 64.0
    }

    /// β = (K d / (4 E_d I_d))^¼, 1/m.
    pub fn beta(&self) -> f64 {
        (self.support * self.diameter / (4.0 * self.bending())).powf(0.25)
    }

    /// Deflection of the bar at the joint face under a force P (Friberg 1940, after Timoshenko
    /// & Lessels 1925): y₀ = P (2 + βz) / (4β³E_dI_d), m.
    pub fn face_deflection(&self, force: f64) -> f64 {
        let b = self.beta();
        force * (2.0 + b * self.opening) / (4.0 * b.powi(3) * self.bending())
    }

    /// Bearing stress on the concrete at the face, σ_b = K y₀, Pa.
    pub fn bearing_stress(&self, force: f64) -> f64 {
        self.support * self.face_deflection(force)
    }

    /// The equivalent spring between the two slabs, N/m: the relative deflection of the slabs
    /// at the bar under a force P is Δ = 2y₀ + θ₀z + Pz³/(12E_dI_d) — the two faces' deflections
    /// (y₀ above), the face slope θ₀ = P(1 + βz)/(2β²E_dI_d) carried across the opening, and
    /// the bar's bending across the opening (moment P z/2 at the faces, inflection at
    /// mid-opening) — so
    ///
    /// k_d = 1 / [(2 + βz)/(2β³E_dI_d) + z(1 + βz)/(2β²E_dI_d) + z³/(12E_dI_d)].
    ///
    /// (The semi-infinite beam on an elastic foundation under an end force and moment:
    /// Timoshenko & Lessels, *Applied Elasticity*, 1925; Hetényi, *Beams on Elastic
    /// Foundation*, 1946; for dowels Friberg, "Design of dowels in transverse joints of concrete
    /// pavements", Trans. ASCE 105, 1940.) The bar's own shear deformation is not included. As
    /// z → 0, k_d → DCI/2 with DCI = P/y₀ the stiffness of one face.
    pub fn spring(&self) -> f64 {
        let (b, ei, z) = (self.beta(), self.bending(), self.opening);
        let flex = (2.0 + b * z) / (2.0 * b.powi(3) * ei)
            + z * (1.0 + b * z) / (2.0 * b * b * ei)
            + z.powi(3) / (12.0 * ei);
        1.0 / flex
    }
}

/// One joint: a line across the whole plate, or a segment of one that ends at another joint
/// or at the plate's edge (a T-intersection, a mismatched joint).
#[derive(Debug, Clone, PartialEq)]
pub struct Joint {
    /// Name for reports (J1, J2 … unless given).
    pub name: String,
    /// Which family of lines.
    pub axis: Axis,
    /// Position of the line: x / L (Axis::X) or y / L (Axis::Y), from the plate centre.
    pub at: f64,
    /// The segment's extent along the line ([y0, y1] / L on a line x = const, [x0, x1] / L on
    /// y = const), `None` for a line across the whole plate. A segment does not delimit panels
    /// (their grid is the whole lines'); it cuts the plate along its extent only.
    pub span: Option<[f64; 2]>,
    /// Transfer and its constants.
    pub kind: JointKind,
}

impl Joint {
    /// True when the point `along` the line (y / L on x = const, x / L on y = const) lies on the
    /// joint, its ends included.
    pub fn covers(&self, along: f64) -> bool {
        self.span
            .is_none_or(|[a, b]| along >= a - TOL && along <= b + TOL)
    }
}

/// Section of one panel relative to the reference plate (same ν and χ).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PanelSection {
    /// D_p / D = E_p H_p³ / (E H³).
    pub bending: f64,
    /// S_p / S = E_p H_p / (E H).
    pub shear: f64,
    /// H_p / H (stresses 6m/H_p², thermal curvature κ H/H_p).
    pub thickness: f64,
}

impl PanelSection {
    /// The reference plate's own section.
    pub const REFERENCE: PanelSection = PanelSection {
        bending: 1.0,
        shear: 1.0,
        thickness: 1.0,
    };

    /// The section of a panel of thickness ratio H_p/H and modulus ratio E_p/E.
    pub fn of(thickness: f64, modulus: f64) -> Self {
        Self {
            bending: modulus * thickness.powi(3),
            shear: modulus * thickness,
            thickness,
        }
    }
}

/// A panel with its own thickness or Young's modulus.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PanelOverride {
    /// Column of the panel (0-based, from x = −L).
    pub column: usize,
    /// Row of the panel (0-based, from y = −μL).
    pub row: usize,
    /// Its section relative to the reference plate.
    pub section: PanelSection,
}

/// A polygon in the unit system: its corners in order (either sense), the closing edge implied.
pub type Polygon = Vec<[f64; 2]>;

/// Joints, panel overrides and the plate's shape (an outline other than its bounding rectangle,
/// openings); empty for a rectangular plate of one piece.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Layout {
    /// Joint lines, in the order given.
    pub joints: Vec<Joint>,
    /// Panels with their own section.
    pub panels: Vec<PanelOverride>,
    /// The plate's outline when it is not the rectangle [−1, 1] × [−μ, μ] (`[plate] outline`):
    /// edges along the grid's lines ([`crate::mesh::outline::check_polygon`]).
    pub outline: Option<Polygon>,
    /// Holes through the slab (`[[opening]]`): no plate and no soil contact inside.
    pub openings: Vec<Polygon>,
    /// Panels with their own outline (`[[panel]]` with `outline`, or `x` and `y`): a blockout,
    /// a pit's floor. Their cells are plate (inside an opening too) of their own section.
    pub regions: Vec<Region>,
}

/// A panel of its own outline and section (panel id: the grid panels', then the regions').
#[derive(Debug, Clone, PartialEq)]
pub struct Region {
    /// Its outline, edges along the grid's lines.
    pub polygon: Polygon,
    /// Its section relative to the reference plate.
    pub section: PanelSection,
}

/// Tolerance on positions in the unit system (lines at equal positions are one line).
const TOL: f64 = 1e-9;

impl Layout {
    /// True without joints, overrides, outline and openings: the plain rectangular plate.
    pub fn is_empty(&self) -> bool {
        self.joints.is_empty()
            && self.panels.is_empty()
            && self.regions.is_empty()
            && !self.is_shaped()
    }

    /// True when the plate is not its whole bounding rectangle (an outline or openings).
    pub fn is_shaped(&self) -> bool {
        self.outline.is_some() || !self.openings.is_empty()
    }

    /// True when the point (x, y) is plate: inside the outline (the whole rectangle without
    /// one) and inside no opening. Meant for cell centres, which never lie on an edge of a
    /// polygon whose edges run along grid lines.
    pub fn is_plate(&self, x: f64, y: f64) -> bool {
        (self.outline.as_ref().is_none_or(|p| inside(p, x, y))
            && !self.openings.iter().any(|p| inside(p, x, y)))
            || self.region_at(x, y).is_some()
    }

    /// The region panel holding the point (x, y) (the first one listed), if any.
    pub fn region_at(&self, x: f64, y: f64) -> Option<usize> {
        self.regions.iter().position(|r| inside(&r.polygon, x, y))
    }

    /// The panel id of the point (x, y): a region's (after the grid's panels), else its grid
    /// panel's, column + row · columns.
    pub fn panel_id(&self, x: f64, y: f64) -> usize {
        let [nc, nr] = self.panel_counts();
        match self.region_at(x, y) {
            Some(r) => nc * nr + r,
            None => {
                let [c, r] = self.panel_at(x, y);
                c + r * nc
            }
        }
    }

    /// A panel's name for messages: "(column, row)", 1-based, or "region k" (1-based).
    pub fn panel_name(&self, id: usize) -> String {
        let [nc, nr] = self.panel_counts();
        match id.checked_sub(nc * nr) {
            Some(r) => format!("region {}", r + 1),
            None => format!("({}, {})", id % nc + 1, id / nc + 1),
        }
    }

    /// True when every corner of the outline and the openings lies on a grid line of the
    /// plate [−1, 1] × [−μ, μ] on `elements` (to 1e-6 of an element).
    pub fn shapes_fit(&self, elements: [usize; 2], mu: f64) -> bool {
        let on = |v: f64, half: f64, n: usize| {
            let f = (v + half) / (2.0 * half) * n as f64;
            (f - f.round()).abs() <= 1e-6
        };
        self.outline
            .iter()
            .chain(&self.openings)
            .chain(self.regions.iter().map(|r| &r.polygon))
            .flatten()
            .all(|p| on(p[0], 1.0, elements[0]) && on(p[1], mu, elements[1]))
    }

    /// Positions of the joint lines of one family across the whole plate (segments excluded:
    /// they delimit no panels), every kind, sorted.
    pub fn lines(&self, axis: Axis) -> Vec<f64> {
        let mut v: Vec<f64> = self
            .joints
            .iter()
            .filter(|j| j.axis == axis && j.span.is_none())
            .map(|j| j.at)
            .collect();
        v.sort_by(f64::total_cmp);
        v.dedup_by(|a, b| (*a - *b).abs() <= TOL);
        v
    }

    /// Panels along x and along y.
    pub fn panel_counts(&self) -> [usize; 2] {
        [self.lines(Axis::X).len() + 1, self.lines(Axis::Y).len() + 1]
    }

    /// (column, row) of the panel holding the point (x, y) strictly inside it (a point on a
    /// line counts to the panel above / right of it).
    pub fn panel_at(&self, x: f64, y: f64) -> [usize; 2] {
        let count = |lines: Vec<f64>, v: f64| lines.iter().filter(|&&l| l <= v + TOL).count();
        [count(self.lines(Axis::X), x), count(self.lines(Axis::Y), y)]
    }

    /// The section of panel (column, row).
    pub fn section(&self, column: usize, row: usize) -> PanelSection {
        self.panels
            .iter()
            .find(|p| p.column == column && p.row == row)
            .map_or(PanelSection::REFERENCE, |p| p.section)
    }

    /// Every panel's section, indexed as [`Self::panel_id`]: the grid's, column + row ·
    /// columns, then the regions'.
    pub fn sections(&self) -> Vec<PanelSection> {
        let [nc, nr] = self.panel_counts();
        (0..nc * nr)
            .map(|id| self.section(id % nc, id / nc))
            .chain(self.regions.iter().map(|r| r.section))
            .collect()
    }

    /// True when every joint line of the plate [−1, 1] × [−μ, μ] lies on an element edge of a
    /// grid of `elements` (to 1e-6 of an element).
    pub fn fits(&self, elements: [usize; 2], mu: f64) -> bool {
        let on = |v: f64, half: f64, n: usize| {
            let f = (v + half) / (2.0 * half) * n as f64;
            (f - f.round()).abs() <= 1e-6
        };
        self.joints.iter().all(|j| {
            let (across, along) = match j.axis {
                Axis::X => ((1.0, elements[0]), (mu, elements[1])),
                Axis::Y => ((mu, elements[1]), (1.0, elements[0])),
            };
            on(j.at, across.0, across.1)
                && j.span
                    .is_none_or(|[a, b]| on(a, along.0, along.1) && on(b, along.0, along.1))
        })
    }

    /// True when some joint cuts the plate (any kind but continuous).
    pub fn cuts(&self) -> bool {
        self.joints.iter().any(|j| j.kind.doubles())
    }

    /// A joint that cuts the plate along the symmetry line x = 0 (`about_x`) or y = 0: the
    /// model cannot be reduced about that line.
    pub fn cut_on_symmetry_line(&self, about_x: bool) -> Option<&Joint> {
        let axis = if about_x { Axis::X } else { Axis::Y };
        self.joints
            .iter()
            .find(|j| j.axis == axis && j.kind.doubles() && j.at.abs() <= TOL)
    }

    /// True when the layout is its own mirror image about x = 0 (`about_x`) or y = 0: every
    /// joint has a mirror joint of equal kind and constants (the bars of a joint along the
    /// mirror's direction mirrored onto themselves), and every panel's section equals its
    /// mirror panel's.
    pub fn symmetric(&self, about_x: bool) -> bool {
        let across = if about_x { Axis::X } else { Axis::Y };
        let mirror = |j: &Joint| -> Joint {
            let mut m = j.clone();
            if j.axis == across {
                m.at = -j.at;
            } else {
                m.span = j.span.map(|[a, b]| [-b, -a]);
                if let JointKind::Dowels { positions, .. } = &mut m.kind {
                    for p in positions.iter_mut() {
                        *p = -*p;
                    }
                }
            }
            m
        };
        let same = |a: &Joint, b: &Joint| -> bool {
            let spans = match (a.span, b.span) {
                (None, None) => true,
                (Some(p), Some(q)) => (p[0] - q[0]).abs() <= TOL && (p[1] - q[1]).abs() <= TOL,
                _ => false,
            };
            if a.axis != b.axis || (a.at - b.at).abs() > TOL || !spans {
                return false;
            }
            match (&a.kind, &b.kind) {
                (
                    JointKind::Dowels {
                        k: ka,
                        positions: pa,
                        ..
                    },
                    JointKind::Dowels {
                        k: kb,
                        positions: pb,
                        ..
                    },
                ) => {
                    let mut pa = pa.clone();
                    let mut pb = pb.clone();
                    pa.sort_by(f64::total_cmp);
                    pb.sort_by(f64::total_cmp);
                    close(*ka, *kb)
                        && pa.len() == pb.len()
                        && pa.iter().zip(&pb).all(|(x, y)| (x - y).abs() <= TOL)
                }
                (ka, kb) => ka == kb,
            }
        };
        let joints_ok = self
            .joints
            .iter()
            .all(|j| self.joints.iter().any(|o| same(o, &mirror(j))));
        let [nc, nr] = self.panel_counts();
        let panels_ok = (0..nc).all(|c| {
            (0..nr).all(|r| {
                let (mc, mr) = if about_x {
                    (nc - 1 - c, r)
                } else {
                    (c, nr - 1 - r)
                };
                self.section(c, r) == self.section(mc, mr)
            })
        });
        // Each region has a mirror region of the same section (the same corners mirrored).
        let mirrored = |p: &Polygon| -> Vec<[i64; 2]> {
            let key = |v: f64| (v / TOL).round() as i64;
            let mut c: Vec<[i64; 2]> = p
                .iter()
                .map(|&[x, y]| {
                    if about_x {
                        [key(-x), key(y)]
                    } else {
                        [key(x), key(-y)]
                    }
                })
                .collect();
            c.sort_unstable();
            c
        };
        let corners = |p: &Polygon| -> Vec<[i64; 2]> {
            let key = |v: f64| (v / TOL).round() as i64;
            let mut c: Vec<[i64; 2]> = p.iter().map(|&[x, y]| [key(x), key(y)]).collect();
            c.sort_unstable();
            c
        };
        let regions_ok = self.regions.iter().all(|r| {
            self.regions
                .iter()
                .any(|o| o.section == r.section && corners(&o.polygon) == mirrored(&r.polygon))
        });
        joints_ok && panels_ok && regions_ok
    }
}

/// The even–odd rule: a ray from (x, y) towards +x crosses the polygon's edges an odd number
/// of times.
fn inside(polygon: &[[f64; 2]], x: f64, y: f64) -> bool {
    let n = polygon.len();
    let mut odd = false;
    for k in 0..n {
        let [x0, y0] = polygon[k];
        let [x1, y1] = polygon[(k + 1) % n];
        if (y0 > y) != (y1 > y) && x < x0 + (y - y0) / (y1 - y0) * (x1 - x0) {
            odd = !odd;
        }
    }
    odd
}

/// Equal to 1e-12 relative (constants of mirrored joints).
fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * a.abs().max(b.abs())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The joint lines of a family are every position once, in order: a line at x = 0 after
    /// one to its left is a line like any other, and two joints within the tolerance (1e-9 of
    /// L) are one line; the panels are the lines plus one.
    #[test]
    fn lines_are_every_position_once() {
        let joint = |axis: Axis, at: f64| Joint {
            name: String::new(),
            axis,
            at,
            span: None,
            kind: JointKind::Free,
        };
        let layout = Layout {
            joints: vec![
                joint(Axis::X, 0.5),
                joint(Axis::X, -0.5),
                joint(Axis::Y, 0.2),
                joint(Axis::X, 0.0),
                joint(Axis::X, 0.5 + 1e-12),
            ],
            panels: Vec::new(),
            ..Layout::default()
        };
        assert_eq!(layout.lines(Axis::X), vec![-0.5, 0.0, 0.5]);
        assert_eq!(layout.lines(Axis::Y), vec![0.2]);
        assert_eq!(layout.panel_counts(), [4, 2]);
    }

    /// The spring of a 32 mm steel dowel (E_d = 200 GPa, K = 4.07e11 N/m³) against an
    /// independent direct solution of the beam on its two beds with the free opening between
    /// them (an 8 × 8 boundary-value problem in `tests/references/dowel_beam.py`, which uses
    /// none of the closed forms above and prints every number here): the closed form agrees
    /// to round-off, so 1e-10 relative. β is its definition; the face deflection and bearing
    /// stress at 10 kN are the same script's direct |u(0)| and K |u(0)| (Friberg's closed form
    /// gives them to round-off). `tests/joints_dowels.rs` runs the script and compares.
    #[test]
    fn dowel_spring_matches_the_direct_beam_solution() {
        let bar = |z: f64| DowelBar {
            diameter: 0.032,
            youngs_modulus: 200e9,
            opening: z,
            support: 4.07e11,
        };
        assert!((bar(0.0).beta() - 23.714891779891747).abs() < 1e-10 * 23.7);
        for (z, direct) in [
            (0.0, 137297695.90434384),
            (0.003, 127872773.49769521),
            (0.006, 119114555.37251416),
            (0.0127, 101791709.90646349),
            (0.025, 76874962.03319955),
        ] {
            let k = bar(z).spring();
            assert!(
                (k - direct).abs() < 1e-10 * direct,
                "z = {z}: {k} vs {direct}"
            );
        }
        // As z → 0 the spring is half the face stiffness DCI = P / y₀ (two faces in series).
        let b = bar(0.0);
        assert!((b.spring() - 0.5 / b.face_deflection(1.0)).abs() < 1e-6);
        // P = 10 kN, z = 6 mm: y₀ = 39.008 µm, σ_b = K y₀ = 15.876 MPa.
        let b = bar(0.006);
        assert!((b.face_deflection(1e4) - 3.900810819454495e-05).abs() < 1e-10 * 3.9e-5);
        assert!((b.bearing_stress(1e4) - 15876300.035179794).abs() < 1e-10 * 1.6e7);
    }

    fn joint(axis: Axis, at: f64, kind: JointKind) -> Joint {
        Joint {
            name: "J".into(),
            axis,
            at,
            span: None,
            kind,
        }
    }

    #[test]
    fn panels_are_numbered_from_the_lower_left_by_every_line() {
        let layout = Layout {
            joints: vec![
                joint(Axis::X, 0.5, JointKind::Free),
                joint(Axis::X, -0.5, JointKind::Continuous),
                joint(Axis::Y, 0.0, JointKind::Aggregate { c: 1.0 }),
            ],
            panels: vec![PanelOverride {
                column: 2,
                row: 1,
                section: PanelSection::of(2.0, 1.0),
            }],
            ..Layout::default()
        };
        assert_eq!(layout.panel_counts(), [3, 2]);
        assert_eq!(layout.panel_at(-0.9, -0.1), [0, 0]);
        assert_eq!(layout.panel_at(0.0, 0.3), [1, 1]);
        assert_eq!(layout.panel_at(0.7, 0.3), [2, 1]);
        let s = layout.sections();
        assert_eq!(s.len(), 6);
        assert_eq!(s[2 + 3], PanelSection::of(2.0, 1.0));
        assert_eq!(s[5].bending, 8.0);
        assert_eq!(s[5].shear, 2.0);
        assert_eq!(s[0], PanelSection::REFERENCE);
        assert!(layout.cuts());
    }

    #[test]
    fn mirror_symmetry_of_layouts() {
        let dowels = |positions: Vec<f64>| JointKind::Dowels {
            k: 2.0,
            positions,
            bar: None,
        };
        let pair = Layout {
            joints: vec![
                joint(Axis::X, 0.5, JointKind::Aggregate { c: 3.0 }),
                joint(Axis::X, -0.5, JointKind::Aggregate { c: 3.0 }),
                joint(Axis::Y, 0.2, dowels(vec![-0.4, 0.4])),
            ],
            panels: Vec::new(),
            ..Layout::default()
        };
        assert!(pair.symmetric(true), "mirror joints and mirrored bars");
        assert!(!pair.symmetric(false), "the y-joint at 0.2 has no mirror");
        let mut uneven = pair.clone();
        uneven.joints[1].kind = JointKind::Aggregate { c: 4.0 };
        assert!(!uneven.symmetric(true), "unequal constants");
        let mut bars = pair.clone();
        bars.joints[2].kind = dowels(vec![-0.4, 0.3]);
        assert!(!bars.symmetric(true), "bars not mirrored");
        let mut panel = pair.clone();
        panel.panels.push(PanelOverride {
            column: 0,
            row: 0,
            section: PanelSection::of(1.2, 1.0),
        });
        assert!(!panel.symmetric(true), "a thicker panel on one side only");
        panel.panels.push(PanelOverride {
            column: 2,
            row: 0,
            section: PanelSection::of(1.2, 1.0),
        });
        assert!(panel.symmetric(true), "and its mirror");
        let cut = Layout {
            joints: vec![joint(Axis::X, 0.0, JointKind::Free)],
            panels: Vec::new(),
            ..Layout::default()
        };
        assert!(cut.symmetric(true) && cut.cut_on_symmetry_line(true).is_some());
        assert!(cut.cut_on_symmetry_line(false).is_none());
    }
}
