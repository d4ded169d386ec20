//! The positions of a critical-position search, and of a damage run's pass, that are mirror
//! images of others: on a plate whose frame (outline, joints, panels, voids, soil zones) is its
//! own mirror image about x = 0 or y = 0, the load at a position and the load at its mirror
//! position make mirror-image contact problems — the same operators mirrored, the same answer mirrored (the penalised and
//! the QP problem are strictly convex: one answer each) — so one of the two is solved and the
//! other read off it. A lane of positions over a symmetric slab is solved on its first half.
//! A damage pass along such a lane is the same pass mirrored ([`pass_partners`]): its first
//! half is solved and its largest stresses mirrored element by element ([`point_map`]).
//!
//! Which positions pair is decided on the loads themselves, not on the grid: a position mirrors
//! an earlier one (in grid order) when its load set is that one's mirrored
//! ([`crate::model::loads_mirror`], to 1e-9) and the frame is symmetric about each line
//! mirrored in ([`Model::frame_symmetric`]); a vehicle that is not symmetric about its own
//! reference point, or a grid whose points do not pair, pairs nothing and every position is
//! solved.
//!
//! The warm-started runs ([`super::critical`]) keep their meaning: a position read off another
//! is skipped by the run it falls in, and a share of the grid (`indices`) that holds a position
//! read off one outside it solves that one with the run before it in its block, so that the
//! share gives the whole search's digits there.

use std::collections::HashMap;

use crate::model::{loads_mirror, Load, Model};

use super::critical_grid::CriticalOptions;

/// How a position is the mirror image of another: x → −x where `0`, y → −y where `1` (both: a
/// turn by 180° about the plate's centre).
pub type Flip = [bool; 2];

/// A point mirrored by `flip`.
pub fn flipped(flip: Flip, [x, y]: [f64; 2]) -> [f64; 2] {
    [if flip[0] { -x } else { x }, if flip[1] { -y } else { y }]
}

/// Points by their place to a micrometre, to find the one at a given place.
struct Places(HashMap<(i64, i64), Vec<usize>>);

impl Places {
    fn key(v: f64) -> i64 {
        (v * 1e6).round() as i64
    }

    fn of<'a>(points: impl Iterator<Item = &'a [f64; 2]>) -> Self {
        let mut at: HashMap<(i64, i64), Vec<usize>> = HashMap::new();
        for (i, p) in points.enumerate() {
            at.entry((Self::key(p[0]), Self::key(p[1])))
                .or_default()
                .push(i);
        }
        Places(at)
    }

    /// The points within a cell of `[x, y]` (a coordinate and its negative may round apart), in
    /// no particular order.
    fn around(&self, [x, y]: [f64; 2]) -> impl Iterator<Item = usize> + '_ {
        let (kx, ky) = (Self::key(x), Self::key(y));
        (-1..=1)
            .flat_map(move |dx| (-1..=1).map(move |dy| (kx + dx, ky + dy)))
            .filter_map(|k| self.0.get(&k))
            .flatten()
            .copied()
    }
}

/// For every position of the grid (`loads[i]`: the model's loads with the vehicle at
/// `points[i]`, m and degrees), the earlier position it is the mirror image of and how — that
/// one solved itself —, None where it is solved itself. `frame`: whether the model's frame is
/// symmetric about x = 0 and about y = 0 (a mirror about a line it is not symmetric about is
/// never taken).
pub fn partners(
    loads: &[Vec<Load>],
    points: &[[f64; 3]],
    frame: [bool; 2],
) -> Vec<Option<(usize, Flip)>> {
    let flips = allowed(frame);
    let mut out: Vec<Option<(usize, Flip)>> = vec![None; points.len()];
    if flips.is_empty() {
        return out;
    }
    let xy: Vec<[f64; 2]> = points.iter().map(|p| [p[0], p[1]]).collect();
    let places = Places::of(xy.iter());
    for i in 0..points.len() {
        let found = flips.iter().find_map(|&flip| {
            let mut candidates: Vec<usize> = places
                .around(flipped(flip, xy[i]))
                .filter(|&k| k < i)
                .collect();
            candidates.sort_unstable();
            candidates
                .into_iter()
                .find(|&k| loads_mirror(&loads[i], &loads[k], flip))
                .map(|k| (k, flip))
        });
        // A partner that is itself a mirror image: the one it was read off, the flips composed.
        out[i] = found.map(|(k, flip)| match out[k] {
            Some((j, g)) => (j, [flip[0] ^ g[0], flip[1] ^ g[1]]),
            None => (k, flip),
        });
    }
    out
}

/// The positions a search of `picked` (grid indices) solves, in grid order: each picked
/// position solved itself, and for each read off another the other with the positions its
/// block of [`CriticalOptions::RUN`] solves before it — the run that warm-starts it in the
/// whole search, so that a share of the grid gives the whole search's digits there.
pub fn to_solve(picked: &[usize], partner: &[Option<(usize, Flip)>]) -> Vec<usize> {
    let run = CriticalOptions::RUN;
    let mut keep = vec![false; partner.len()];
    for &i in picked {
        match partner.get(i).copied().flatten() {
            None => keep[i] = true,
            Some((k, _)) => {
                for j in (k / run) * run..=k {
                    keep[j] = keep[j] || partner[j].is_none();
                }
            }
        }
    }
    (0..keep.len()).filter(|&i| keep[i]).collect()
}

/// The flips a frame symmetric about x = 0 (`frame[0]`) and y = 0 (`frame[1]`) allows.
fn allowed(frame: [bool; 2]) -> Vec<Flip> {
    [[true, false], [false, true], [true, true]]
        .into_iter()
        .filter(|f| (!f[0] || frame[0]) && (!f[1] || frame[1]))
        .collect()
}

/// For a pass of a damage run — each level's load sets at its positions, in order along the
/// lane —, the flip that maps the pass onto itself and each position's mirror position in it
/// (itself where the group stands on the line), when the frame allows the flip and every
/// position of every level has its mirror among the same level's; None otherwise.
pub fn pass_partners(levels: &[Vec<&[Load]>], frame: [bool; 2]) -> Option<(Flip, Vec<usize>)> {
    let first = levels.first()?;
    let n = first.len();
    allowed(frame).into_iter().find_map(|flip| {
        let partner = (0..n)
            .map(|p| (0..n).find(|&q| loads_mirror(first[p], first[q], flip)))
            .collect::<Option<Vec<usize>>>()?;
        let pairs = (0..n).all(|p| partner[partner[p]] == p);
        let every = levels
            .iter()
            .all(|l| l.len() == n && (0..n).all(|p| loads_mirror(l[p], l[partner[p]], flip)));
        (pairs && every).then_some((flip, partner))
    })
}

/// For points each with a direction (±1 along x and y; zero for none), the index of each
/// one's mirror image by `flip` — the point and its direction mirrored — among them, to a
/// micrometre; None when one has no mirror image.
pub fn point_map(points: &[([f64; 2], [f64; 2])], flip: Flip) -> Option<Vec<usize>> {
    let places = Places::of(points.iter().map(|(p, _)| p));
    points
        .iter()
        .map(|&(p, d)| {
            let (t, td) = (flipped(flip, p), flipped(flip, d));
            let near = |q: [f64; 2]| (q[0] - t[0]).abs() <= 1e-6 && (q[1] - t[1]).abs() <= 1e-6;
            places
                .around(t)
                .find(|&k| near(points[k].0) && points[k].1 == td)
        })
        .collect()
}

/// Whether the model's frame allows mirrors about x = 0 and about y = 0 (both false where the
/// search is told not to mirror).
pub fn frame(model: &Model, mirror: bool) -> [bool; 2] {
    [
        mirror && model.frame_symmetric(true),
        mirror && model.frame_symmetric(false),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn patch(x: [f64; 2], y: [f64; 2]) -> Load {
        Load::Patch {
            x,
            y,
            pressure: 1.0,
        }
    }

    /// A print at x and one at −x pair; one off the mirror (a print not centred on its
    /// reference point) does not; a frame that is not symmetric pairs nothing.
    #[test]
    fn positions_pair_on_their_loads() {
        let points = [
            [-0.5, 0.0, 0.0],
            [0.0, 0.0, 0.0],
            [0.5, 0.0, 0.0],
            [0.7, 0.0, 0.0],
        ];
        let loads = vec![
            vec![patch([-0.6, -0.4], [-0.1, 0.1])],
            vec![patch([-0.1, 0.1], [-0.1, 0.1])],
            vec![patch([0.4, 0.6], [-0.1, 0.1])],
            // Not the mirror of the first: shifted off its reference point.
            vec![patch([0.5, 0.7], [-0.1, 0.1])],
        ];
        let p = partners(&loads, &points, [true, true]);
        assert_eq!(p, vec![None, None, Some((0, [true, false])), None]);
        assert_eq!(partners(&loads, &points, [false, true]), vec![None; 4]);
    }

    /// Four points about the centre: the three after the first are its mirrors, each by its own
    /// flip (about x, about y, and both), composed where found through another mirror.
    #[test]
    fn flips_compose() {
        let points = [
            [-1.0, -1.0, 0.0],
            [1.0, -1.0, 0.0],
            [-1.0, 1.0, 0.0],
            [1.0, 1.0, 0.0],
        ];
        let loads: Vec<Vec<Load>> = points
            .iter()
            .map(|p| vec![patch([p[0] - 0.1, p[0] + 0.1], [p[1] - 0.2, p[1] + 0.2])])
            .collect();
        let p = partners(&loads, &points, [true, true]);
        assert_eq!(
            p,
            vec![
                None,
                Some((0, [true, false])),
                Some((0, [false, true])),
                Some((0, [true, true]))
            ]
        );
        for (i, q) in points.iter().enumerate().skip(1) {
            let (k, f) = p[i].expect("paired");
            assert_eq!(flipped(f, [points[k][0], points[k][1]]), [q[0], q[1]]);
        }
    }

    /// A pass along x over a frame symmetric about x = 0 maps onto itself, the middle position
    /// onto itself; one whose positions do not pair (a step off the middle) does not.
    #[test]
    fn a_pass_pairs_its_positions_or_none() {
        let at = |x: f64| vec![patch([x - 0.1, x + 0.1], [-1.0, -0.8])];
        let pass: Vec<Vec<Load>> = [-1.0, 0.0, 1.0].iter().map(|&x| at(x)).collect();
        let levels = vec![pass.iter().map(Vec::as_slice).collect::<Vec<_>>()];
        assert_eq!(
            pass_partners(&levels, [true, true]),
            Some(([true, false], vec![2, 1, 0]))
        );
        assert_eq!(pass_partners(&levels, [false, true]), None);
        let off: Vec<Vec<Load>> = [-1.0, 0.0, 0.9].iter().map(|&x| at(x)).collect();
        let levels = vec![off.iter().map(Vec::as_slice).collect::<Vec<_>>()];
        assert_eq!(pass_partners(&levels, [true, true]), None);
    }

    /// Points map onto their mirror images with their directions mirrored; a point whose image
    /// is missing, or has the wrong direction, maps nowhere.
    #[test]
    fn points_map_onto_their_mirror_images() {
        let corners = [([-1.0, 0.5], [1.0, -1.0]), ([1.0, 0.5], [-1.0, -1.0])];
        assert_eq!(point_map(&corners, [true, false]), Some(vec![1, 0]));
        assert_eq!(point_map(&corners, [false, true]), None);
        let centres = [
            ([-0.25, 0.0], [0.0, 0.0]),
            ([0.25, 0.0], [0.0, 0.0]),
            ([0.75, 0.0], [0.0, 0.0]),
        ];
        assert_eq!(point_map(&centres[..2], [true, false]), Some(vec![1, 0]));
        assert_eq!(point_map(&centres, [true, false]), None);
    }

    /// A share of the grid solves what it shows and, for a position read off another, that one
    /// with its block's positions before it.
    #[test]
    fn a_share_solves_the_runs_its_mirrors_need() {
        let run = CriticalOptions::RUN;
        let n = 2 * run;
        // Position i mirrors n − 1 − i: the first half is solved.
        let partner: Vec<Option<(usize, Flip)>> = (0..n)
            .map(|i| (i >= run).then(|| (n - 1 - i, [true, false])))
            .collect();
        let all: Vec<usize> = (0..n).collect();
        assert_eq!(to_solve(&all, &partner), (0..run).collect::<Vec<_>>());
        // The last three read off 0, 1, 2: those, from the block's start.
        assert_eq!(to_solve(&[n - 3, n - 2, n - 1], &partner), vec![0, 1, 2]);
        assert_eq!(to_solve(&[3, n - 1], &partner), vec![0, 3]);
    }
}
