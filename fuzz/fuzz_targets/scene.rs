//! Fuzz target for the scene parser, validator and solver.
//!
//! Feeds arbitrary bytes through the seam every front end uses, `liftoff::load` (parse →
//! validate → the options), and for small valid meshes (≤ 8 elements per side, every
//! combination's too) on through `liftoff::run`: the memory budget with the scene's limit,
//! assembly on the scene's route, the method (penalty, either QP solver, bonded), every
//! combination and the envelope, the report and summary, and their JSON. Errors are expected
//! and ignored: the target looks for panics, aborts, hangs and memory blow-ups.
#![no_main]

use libfuzzer_sys::fuzz_target;
use liftoff::scene::Overrides;
use liftoff::{Model, Monitor, Source};

/// Largest mesh (elements per side) that is also assembled and solved.
const MAX_SOLVED_ELEMENTS: usize = 8;

fn small(model: &Model) -> bool {
    model.elements.iter().all(|&n| n <= MAX_SOLVED_ELEMENTS)
}

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(problem) = liftoff::load(&Source::Toml(text), &Overrides::default()) else {
        return;
    };
    if !small(&problem.model) || !problem.combinations.iter().all(|c| small(&c.model)) {
        return;
    }
    if let Ok(outcome) = liftoff::run(&problem, &Monitor::NONE) {
        let _ = outcome.to_json();
    }
});
