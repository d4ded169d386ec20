//! Scenes bundled with the tool (`liftoff example NAME`). The files live in `examples/`.

/// (name, description, TOML text) of every bundled scene.
pub const SCENES: &[(&str, &str, &str)] = &[
    (
        "slab-on-grade",
        "12 m × 8 m slab on Winkler soil, four 300 kN columns and self-weight (SI units)",
        include_str!("../examples/slab-on-grade.toml"),
    ),
    (
        "slab-pasternak",
        "the slab-on-grade bay on a two-parameter (Pasternak) soil: k = 30 MN/m³, G_p = 15 MN/m (SI units)",
        include_str!("../examples/slab-pasternak.toml"),
    ),
    (
        "slab-kerr",
        "the slab-on-grade bay on Reissner's 3 m clay layer, a Kerr soil: E_s = 20 MPa, ν_s = 0.3 (SI units)",
        include_str!("../examples/slab-kerr.toml"),
    ),
    (
        "slab-clay-layer",
        "the slab-on-grade bay on a 3 m clay layer over rock: E_s = 20 MPa, ν_s = 0.3, rough base (SI units)",
        include_str!("../examples/slab-clay-layer.toml"),
    ),
    (
        "footing",
        "6 m × 4 m mat, eccentric 200 kN column and self-weight on Winkler soil (SI units)",
        include_str!("../examples/footing.toml"),
    ),
    (
        "pavement-curling",
        "4.5 m × 3.5 m concrete panel, self-weight with day and night temperature gradients (combinations)",
        include_str!("../examples/pavement-curling.toml"),
    ),
    (
        "pavement-3x3",
        "jointed pavement: 3 × 3 slabs, doweled transverse joints, aggregate between lanes, tied shoulder; an 80 kN axle at a joint, night curling (combinations)",
        include_str!("../examples/pavement-3x3.toml"),
    ),
    (
        "pavement-damage",
        "a lane of three doweled slabs over 20 years: single axles in three levels, lateral wander, day and night curling; `liftoff damage` sums the MEPDG's fatigue damage",
        include_str!("../examples/pavement-damage.toml"),
    ),
    (
        "fwd-panel",
        "the template of a deflectometer survey: one 4.6 m × 3.7 m × 250 mm pavement panel on springs; `liftoff backcalc examples/fwd-basins.csv --scene example:fwd-panel`",
        include_str!("../examples/fwd-panel.toml"),
    ),
    (
        "fwd-joint",
        "the template of a deflectometer survey across a joint: two 4.6 m × 3.7 m × 250 mm panels with aggregate interlock, on springs; `liftoff backcalc examples/fwd-joint.csv --scene example:fwd-joint --fit subgrade,slab,joint`",
        include_str!("../examples/fwd-joint.toml"),
    ),
    (
        "l-raft",
        "an L-shaped 24 m × 18 m raft with a lift pit on a half-space: six columns and self-weight; the re-entrant corner's singular moment is reported as such",
        include_str!("../examples/l-raft.toml"),
    ),
    (
        "warehouse-bay",
        "warehouse floor: 3 × 3 sawn panels of 6 m on a clay layer, drying-shrinkage curl, a 60 kN rack post at a joint crossing",
        include_str!("../examples/warehouse-bay.toml"),
    ),
    (
        "raft-combinations",
        "16 m × 12 m raft: dead, imposed and wind cases in four combinations, a void and a soft zone",
        include_str!("../examples/raft-combinations.toml"),
    ),
    (
        "paper-halfspace",
        "the paper's square plate, central point load, half-space, Γ_h = 0.25e-3 (dimensionless)",
        include_str!("../examples/paper/fig3-halfspace-point.toml"),
    ),
    (
        "paper-winkler",
        "the paper's square plate, central point load, Winkler, Γ_w = 0.25e-3 (dimensionless)",
        include_str!("../examples/paper/fig3-winkler-point.toml"),
    ),
    (
        "paper-fig4-halfspace",
        "the paper's Fig. 4: square plate, load condition 2, half-space (dimensionless)",
        include_str!("../examples/paper/fig4-halfspace-lc2.toml"),
    ),
    (
        "paper-fig4-winkler",
        "the paper's Fig. 4: square plate, load condition 2, Winkler (dimensionless)",
        include_str!("../examples/paper/fig4-winkler-lc2.toml"),
    ),
    (
        "paper-fig5-halfspace",
        "the paper's Fig. 5: μ = 0.5 plate, load condition 2, half-space (dimensionless)",
        include_str!("../examples/paper/fig5-halfspace-lc2.toml"),
    ),
    (
        "paper-fig5-winkler",
        "the paper's Fig. 5: μ = 0.5 plate, load condition 2, Winkler (dimensionless)",
        include_str!("../examples/paper/fig5-winkler-lc2.toml"),
    ),
    (
        "paper-fig7-halfspace",
        "the paper's Fig. 7: bonded reference, square plate, point load, half-space (dimensionless)",
        include_str!("../examples/paper/fig7-halfspace-bonded.toml"),
    ),
    (
        "paper-fig7-winkler",
        "the paper's Fig. 7: bonded reference, square plate, point load, Winkler (dimensionless)",
        include_str!("../examples/paper/fig7-winkler-bonded.toml"),
    ),
];

/// The TOML text of a bundled scene.
pub fn scene(name: &str) -> Option<&'static str> {
    SCENES
        .iter()
        .find(|(n, _, _)| *n == name)
        .map(|(_, _, t)| *t)
}
