//! Scenes bundled with the tool (`liftoff example NAME`). The files live in `examples/`.

/// (name, description, TOML text) of every bundled scene.
pub const SCENES: &[(&str, &str, &str)] = &[
    (
        "slab-on-grade",
        "12 m × 8 m slab on Winkler soil, four 300 kN columns and self-weight (SI units)",
        include_str!("../examples/slab-on-grade.toml"),
    ),
    (
        "footing",
        "6 m × 4 m mat, eccentric 200 kN column and self-weight on Winkler soil (SI units)",
        include_str!("../examples/footing.toml"),
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
];

/// The TOML text of a bundled scene.
pub fn scene(name: &str) -> Option<&'static str> {
    SCENES
        .iter()
        .find(|(n, _, _)| *n == name)
        .map(|(_, _, t)| *t)
}
