//! Where a solve along a line of load positions starts — the warm-start rule `critical`'s runs
//! and `damage`'s passes share: the last answer, or the extrapolation 2σ₁ − σ₀ of the last two
//! where the position continues their line and the extrapolation paid at the last position
//! ([`start_from`]). Only the cost depends on it: every solve solves its own problem.

/// The last three converged answers of a run of positions (oldest first) and their points
/// `[x, y, heading]`.
#[derive(Debug, Clone, Default)]
pub(super) struct Trail {
    last: Vec<([f64; 3], Vec<f64>)>,
}

impl Trail {
    /// An empty trail: the run's first position starts cold.
    pub(super) fn new() -> Self {
        Self::default()
    }

    /// Keep `sigma`, the converged answer at `at`, dropping the oldest beyond three.
    pub(super) fn push(&mut self, at: [f64; 3], sigma: Vec<f64>) {
        if self.last.len() == 3 {
            self.last.remove(0);
        }
        self.last.push((at, sigma));
    }

    /// Forget the run (its next position is not a step on from the last answer kept).
    pub(super) fn clear(&mut self) {
        self.last.clear();
    }

    /// Where a position at `at` starts ([`start_from`]).
    pub(super) fn start(&self, at: [f64; 3]) -> Option<Vec<f64>> {
        start_from(&self.last, at)
    }
}

/// Whether `c` continues the line from `a` to `b` by the same step (same heading, to 1e-9 of
/// the step).
fn in_line(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> bool {
    let step = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let next = [c[0] - b[0], c[1] - b[1], c[2] - b[2]];
    let size = step[0].hypot(step[1]).max(1e-300);
    step[2] == 0.0 && next[2] == 0.0 && (next[0] - step[0]).hypot(next[1] - step[1]) <= 1e-9 * size
}

/// 2σ₁ − σ₀, point by point.
fn extrapolated(s1: &[f64], s0: &[f64]) -> Vec<f64> {
    s1.iter().zip(s0).map(|(a, b)| 2.0 * a - b).collect()
}

/// How many points a start `guess` puts on the other side of contact (σ > 0) than `answer`.
fn misread(guess: &[f64], answer: &[f64]) -> usize {
    guess
        .iter()
        .zip(answer)
        .filter(|(g, a)| (**g > 0.0) != (**a > 0.0))
        .count()
}

/// Where a warm position at `at` starts, from the run's last answers (oldest first, up to
/// three): the last answer, or the extrapolation 2σ₁ − σ₀ of the last two when `at` continues
/// their line by the same step and the extrapolation read the last position's contact set
/// better than its predecessor's answer did (fewer points on the wrong side) — which needs
/// the three last positions in line. None at a run's first position. Only the cost depends on
/// it: with steps short against the plate's radius of relative stiffness (the half-space lane's
/// 0.13 m) the lifted region moves with the load and the extrapolation saves steps; with long
/// ones (the 1.2 m of an 11 × 9 grid over `example:pavement-3x3`) it lifts points that stay in
/// contact, and always extrapolating took 2× the steps' time with the penalty and 9× with the
/// QP there (a second face solve and a new factorisation at a third of the positions).
pub(super) fn start_from(last: &[([f64; 3], Vec<f64>)], at: [f64; 3]) -> Option<Vec<f64>> {
    match last {
        [.., (p0, s0), (p1, s1)] if in_line(*p0, *p1, at) => {
            let extrapolate = match last {
                [(q, r), (_, s0), (_, s1)] if in_line(*q, *p0, *p1) => {
                    misread(&extrapolated(s0, r), s1) < misread(s0, s1)
                }
                _ => false,
            };
            Some(match extrapolate {
                true => extrapolated(s1, s0),
                false => s1.clone(),
            })
        }
        [.., (_, s)] => Some(s.clone()),
        [] => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A warm start extrapolates only along the line of the last positions, by their step, and
    /// only where the extrapolation read the last contact set better than the answer before it.
    #[test]
    fn starts_extrapolate_in_line_where_it_paid() {
        // A lifted point walking along the line: 0, 1, 2 lifted in turn (σ ≤ 0).
        let (a, b, c) = (
            vec![-1.0, 1.0, 3.0, 5.0],
            vec![1.0, -1.0, 1.0, 3.0],
            vec![3.0, 1.0, -1.0, 1.0],
        );
        let x = |v: f64| [v, 0.0, 0.0];
        let walk = vec![
            (x(0.0), a.clone()),
            (x(0.1), b.clone()),
            (x(0.2), c.clone()),
        ];
        // 2b − a read c's set with one point wrong, b with two: extrapolate.
        assert_eq!(start_from(&walk, x(0.3)), Some(vec![5.0, 3.0, -3.0, -1.0]));
        // Not in line, or another heading: the last answer.
        assert_eq!(start_from(&walk, [0.3, 0.1, 0.0]), Some(c.clone()));
        assert_eq!(start_from(&walk, [0.3, 0.0, 90.0]), Some(c.clone()));
        // A set that stood still while the values moved: the extrapolation misread it.
        let still = vec![
            (x(0.0), vec![3.0, -1.0]),
            (x(0.1), vec![2.0, -1.0]),
            (x(0.2), vec![1.5, -1.0]),
        ];
        assert_eq!(start_from(&still, x(0.3)), Some(vec![1.5, -1.0]));
        // Two answers only: nothing to judge the extrapolation on.
        assert_eq!(start_from(&walk[1..], x(0.3)), Some(c.clone()));
        assert_eq!(start_from(&walk[..1], x(0.1)), Some(a));
        assert_eq!(start_from(&[], x(0.0)), None);
    }
}
