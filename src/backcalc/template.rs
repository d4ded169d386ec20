//! What a backcalculation's template scene says about a drop before any fit: whether the
//! template is a scene at all ([`check_template`]), the joint nearest a drop
//! ([`nearest_joint`]), the panel the drop stands on ([`panel_size`]) and the AREA method's
//! reading of an interior drop, on the infinite slab or, on a dense liquid, corrected to the
//! panel's size ([`area_reading`]).

use super::area::{area_method, finite_slab, AreaResult, AREA_OFFSETS};
use super::basins::{Drop, Location};
use super::infinite::Subgrade;
use crate::error::Result;
use crate::foundation::FoundationKind;
use crate::layout::JointType;
use crate::scene::{Coord, JointSpec, LoadKind, LoadSpec, SceneFile};

/// The template's joint line nearest `at`, with its index.
pub fn nearest_joint(template: &SceneFile, at: [f64; 2]) -> Option<(usize, &JointSpec)> {
    let distance = |j: &JointSpec| match (j.x, j.y) {
        (Some(x), _) => (x - at[0]).abs(),
        (None, Some(y)) => (y - at[1]).abs(),
        _ => f64::INFINITY,
    };
    template
        .joint
        .iter()
        .enumerate()
        .min_by(|a, b| distance(a.1).total_cmp(&distance(b.1)))
}

/// The AREA method's reading of `drop` on the template's slab and soil, where it applies: an
/// interior drop with the four AREA sensors, on springs (dense liquid) or a half-space (elastic
/// solid). On springs the reading is corrected to the size of the panel under the drop
/// (Crovetti's correction, [`finite_slab`]: the square of the panel's area) where the panel is
/// at least 3 ℓ across; joints that transfer load make the panel act larger, and the
/// correction then overshoots (the fit models them).
pub fn area_reading(template: &SceneFile, drop: &Drop) -> Option<AreaResult> {
    if drop.location != Location::Interior {
        return None;
    }
    let plate = template.plate.as_ref()?;
    let soil = template.foundation.as_ref()?;
    let subgrade = match soil.model {
        FoundationKind::Winkler => Subgrade::DenseLiquid,
        FoundationKind::HalfSpace => Subgrade::ElasticSolid {
            poisson: soil.number("poissons_ratio")?,
        },
        _ => return None,
    };
    let has = |o: f64| drop.basin.offsets.iter().any(|x| (x - o).abs() < 0.01);
    if !AREA_OFFSETS.iter().all(|&o| has(o)) {
        return None;
    }
    match subgrade {
        Subgrade::DenseLiquid => {
            let [l1, l2] = panel_size(template, drop.at.unwrap_or([0.0, 0.0]))?;
            finite_slab(
                &drop.basin,
                plate.thickness,
                plate.poissons_ratio,
                (l1 * l2).sqrt(),
            )
            .ok()
        }
        Subgrade::ElasticSolid { .. } => {
            area_method(&drop.basin, plate.thickness, plate.poissons_ratio, subgrade).ok()
        }
    }
}

/// The length and width (m) of the template's panel holding the point `at`: between the
/// nearest joint lines that cut the plate on either side (whole lines, not segments, which
/// delimit no panel; `continuous` lines do not cut), or the plate's edges. None without a
/// plate.
pub fn panel_size(template: &SceneFile, at: [f64; 2]) -> Option<[f64; 2]> {
    let plate = template.plate.as_ref()?;
    let cuts = |line: fn(&JointSpec) -> Option<f64>| -> Vec<f64> {
        template
            .joint
            .iter()
            .filter(|j| j.from.is_none() && j.kind != JointType::Continuous)
            .filter_map(line)
            .collect()
    };
    let span = |lines: Vec<f64>, v: f64, half: f64| {
        let below = lines
            .iter()
            .copied()
            .filter(|&l| l <= v)
            .fold(-half, f64::max);
        let above = lines
            .iter()
            .copied()
            .filter(|&l| l > v)
            .fold(half, f64::min);
        above - below
    };
    Some([
        span(cuts(|j| j.x), at[0], plate.length / 2.0),
        span(cuts(|j| j.y), at[1], plate.width / 2.0),
    ])
}

/// Check a template before any drop is fitted: the scene's own checks, with a small disk at
/// the centre standing in for the drops when the template has no loads of its own (a
/// backcalculation's template needs none: the drops are its loads).
pub fn check_template(template: &SceneFile) -> Result<()> {
    let mut f = template.clone();
    if f.load.is_empty() {
        if let Some(p) = template.plate.as_ref() {
            let mut disk = LoadSpec::new(LoadKind::Circle);
            disk.x = Some(Coord::Value(0.0));
            disk.y = Some(Coord::Value(0.0));
            disk.radius = Some(0.01 * p.length.min(p.width));
            disk.force = Some(1.0);
            f.load.push(disk);
        }
    }
    f.validate().map(|_| ())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The panel between the joints and edges around a point: whole joint lines that cut
    /// bound it, a `continuous` line and a segment do not.
    #[test]
    fn the_panel_is_bounded_by_the_cutting_lines_around_the_point() {
        let text = r#"
[plate]
length = 12.0
width = 7.0
thickness = 0.25
youngs_modulus = 30e9
poissons_ratio = 0.15
[foundation]
model = "winkler"
modulus = 5e7
[[joint]]
x = -1.5
kind = "free"
[[joint]]
x = 2.5
kind = "dowels"
spacing = 0.3
diameter = 0.032
[[joint]]
x = 4.0
kind = "continuous"
[[joint]]
y = 0.5
kind = "aggregate"
stiffness = 5e7
[[joint]]
from = [-6.0, -1.0]
to = [-1.5, -1.0]
kind = "free"
"#;
        let f: SceneFile = toml::from_str(text).expect("scene");
        assert_eq!(panel_size(&f, [0.0, 0.0]), Some([4.0, 4.0]));
        assert_eq!(panel_size(&f, [5.0, 2.0]), Some([3.5, 3.0]));
        assert_eq!(panel_size(&f, [-3.0, -2.0]), Some([4.5, 4.0]));
    }
}
