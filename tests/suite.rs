//! Every integration test of the crate, in one test binary.
//!
//! Each `tests/X.rs` is a module here (run one file's tests with
//! `cargo test --release --test suite X::`): one binary links the library once, not sixty
//! times, and the test harness runs the files' tests side by side rather than one file after
//! another. `Cargo.toml` sets `autotests = false`, so a new file is added below, not found.

mod common;

mod active_set;
mod architecture;
mod backcalc_area_finite;
mod backcalc_area_hall;
mod backcalc_fit;
mod backcalc_joint;
mod backcalc_voids;
mod bearing;
mod bonded;
mod charts_exceed;
mod charts_units;
mod circle_load;
mod cli;
mod contact_boundary;
mod critical;
mod critical_grids;
mod damage;
mod elastic_layer;
mod erosion;
mod errors;
mod exactness;
mod feasibility;
mod feasibility_property;
mod fuzz_regressions;
mod gauss_constraints;
mod iterative;
mod joint_segments;
mod joints_continuum;
mod joints_dowels;
mod joints_limits;
mod joints_operators;
mod joints_outputs;
mod joints_reference;
mod joints_solvers;
mod joints_y;
mod kerr;
mod load_cases;
mod near_membrane;
mod near_rigid;
mod nested_start;
mod outlines;
mod paper;
mod pasternak;
mod pavement_loads;
mod penalty_auto;
mod penalty_limit;
mod plate_element;
mod properties;
mod report;
mod scene_errors;
mod sparse_qp;
mod stability_gamma;
mod stresses;
mod studies;
mod thermal_reference;
mod unbonded;
mod units;
mod vehicles_reference;
mod zero_load;
