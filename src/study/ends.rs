//! Where a study reads a lane that the model cuts at its ends. A lane of jointed slabs is
//! modelled with a slab beyond each joint of the ones that matter, so that those have
//! neighbours; the plate's ends (x = ±a/2) are then free edges that no pavement has, and an
//! axle at such an end lifts and stresses the slab as no axle on the road does. A scene says
//! so (`[plate] ends = "cut"`, or a damage scene's `[traffic]`, cut unless it says otherwise),
//! or `critical --ends` does ([`of`]); with two or more transverse joints and the ends a cut,
//! `damage` and `critical` read the plate between its first and last transverse joint only
//! ([`counted_span`]); a plate with one transverse joint has no inner panel, and every element
//! counts.

use crate::layout::{Axis, Ends};
use crate::model::Model;
use crate::scene::Problem;

/// What a study takes the plate's ends to be: `asked` (a command's `--ends`) if given, else the
/// scene's `[plate] ends`, else its `[traffic]`'s (a lane; cut unless it says otherwise), else
/// free — a plate with no word of a lane is read whole.
pub(crate) fn of(problem: &Problem, asked: Option<Ends>) -> Ends {
    asked
        .or(problem.ends)
        .or(problem
            .damage
            .as_ref()
            .map(|plan| if plan.cut { Ends::Cut } else { Ends::Free }))
        .unwrap_or(Ends::Free)
}

/// The span of x (m, the model's units) that is read: between the first and the last transverse
/// joint where the ends are cut and there are two or more; None where the whole plate is read.
pub(crate) fn counted_span(model: &Model, cut: bool) -> Option<[f64; 2]> {
    let lines = model.layout.lines(Axis::X);
    if !cut || lines.len() < 2 {
        return None;
    }
    let l = model.physical.map_or(1.0, |p| p.half_length);
    let (lo, hi) = (lines.iter()).fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
        (a.min(x * l), b.max(x * l))
    });
    Some([lo, hi])
}

/// Whether an element centred at `x` is read: strictly inside the span (every element where
/// there is none).
pub(crate) fn inside(span: Option<[f64; 2]>, x: f64) -> bool {
    span.is_none_or(|[lo, hi]| x > lo && x < hi)
}

/// Whether a node or bar at `x` is read: within the span, its ends included — the first and
/// the last transverse joint are the road's own joints (every point where there is none).
pub(crate) fn within(span: Option<[f64; 2]>, x: f64) -> bool {
    span.is_none_or(|[lo, hi]| {
        let tol = 1e-9 * (hi - lo).abs().max(1.0);
        x >= lo - tol && x <= hi + tol
    })
}
