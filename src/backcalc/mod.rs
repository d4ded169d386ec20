//! Backcalculation from falling-weight-deflectometer basins (issue 34): what lies under an
//! existing slab. `infinite.rs` holds the infinite plate under a disk on a dense liquid or an
//! elastic solid (the closed forms, as Hankel integrals); `area.rs` the AREA method that
//! inverts them. Both import only `error`. The fit on liftoff's own finite, jointed model is
//! not built yet.

pub mod area;
pub mod infinite;

pub use area::{area_method, AreaResult, Basin, AREA_OFFSETS};
pub use infinite::{dimensionless_deflection, Subgrade};
