//! Backcalculation from falling-weight-deflectometer basins (issue 34): what lies under an
//! existing slab. `infinite.rs` holds the infinite plate under a disk on a dense liquid or an
//! elastic solid (the closed forms, as Hankel integrals); `area.rs` the AREA method that
//! inverts them; `basins.rs` the drops as a CSV file reads them; `pddx.rs` as an AASHTO PDDX
//! file reads them; `drops.rs` `read_drops`, which reads either, and where a PDDX file's drops
//! stood; `fit.rs` the least-squares fit of a drop on liftoff's own finite model (a template
//! scene), with confidence intervals; `transfer.rs` a joint drop's load transfer on that
//! model; `survey.rs` every drop of a file, in parallel; `template.rs` what the template scene
//! says of a drop before any fit (its panel, the nearest joint, the AREA reading corrected to
//! the panel's size). `infinite`, `area` and `basins` import only `error` and `units`, `pddx`
//! them too, `drops` `basins` and `pddx`; `template` imports them and the scene; `fit` imports
//! them, `template` and the entry point (`entry::run`) it solves through; `transfer` imports
//! `fit`; `survey` imports both.

pub mod area;
pub mod basins;
pub mod drops;
pub mod fit;
pub mod infinite;
pub mod pddx;
pub mod survey;
pub mod template;
pub mod transfer;

pub use area::{
    area_method, crovetti_factors, finite_slab, AreaResult, Basin, FiniteSlab, AREA_OFFSETS,
    FINITE_SLAB_MIN_RATIO,
};
pub use basins::{read_basins, Drop, Location};
pub use drops::{read_drops, read_drops_placed, Placement};
pub use fit::{
    fit_drop, model_basin, student_t975, Estimate, Fit, FitOptions, Termination, Unknown,
};
pub use infinite::{dimensionless_deflection, Subgrade};
pub use pddx::read_pddx;
pub use survey::{
    intercepts, survey, BackcalcMethod, DropResult, Intercept, Survey, SurveyOptions,
};
pub use template::{area_reading, check_template, nearest_joint, panel_size};
pub use transfer::{load_transfer, LoadTransfer};
