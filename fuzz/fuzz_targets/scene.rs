//! Fuzz target for the scene parser and validator.
//!
//! Feeds arbitrary bytes through `SceneFile::parse` → `validate`, and for small valid meshes
//! (≤ 8 elements per side) on through `budget::check`, `Operators::assemble` and `solve`. Errors are
//! expected and ignored: the target looks for panics, aborts, hangs and memory blow-ups.
#![no_main]

use libfuzzer_sys::fuzz_target;
use liftoff::scene::SceneFile;

/// Largest mesh (elements per side) that is also assembled and solved.
const MAX_SOLVED_ELEMENTS: usize = 8;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(scene) = SceneFile::parse(text) else {
        return;
    };
    let Ok(problem) = scene.validate() else {
        return;
    };
    if problem.model.elements.iter().any(|&n| n > MAX_SOLVED_ELEMENTS) {
        return;
    }
    if liftoff::budget::check(&problem.model, &problem.method, problem.memory_limit).is_ok() {
        let ops = liftoff::Operators::assemble(&problem.model);
        let _ = liftoff::solve(&ops, &problem.method);
    }
});
