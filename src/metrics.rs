//! Measures that studies and the paper report: errors of one field against a reference, the
//! log–log fit of a convergence rate, and the Pareto front of a speed/accuracy trade-off.
//!
//! The error measures compare two nodal fields of the same mesh entry by entry:
//!
//! * [`max_abs_diff`]: max_i |a_i − b_i|;
//! * [`rel_max`]: max_i |a_i − b_i| / max_i |b_i|;
//! * [`rel_l2`]: ‖a − b‖₂ / ‖b‖₂, which equals the relative RMS error because both norms
//!   run over the same entries.
//!
//! `b` is the reference. When the reference is identically zero a relative error is undefined;
//! the relative measures then return the absolute one (so two zero fields differ by 0). Fields
//! of different lengths, or with a NaN entry, give NaN: the error is unknown, and a NaN is what
//! the studies' filters (`is_finite`) already leave out.

/// Whether the field pair can be compared: same length, no NaN.
fn comparable(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && !a.iter().chain(b).any(|v| v.is_nan())
}

/// Largest absolute difference max_i |a_i − b_i|; 0 for empty fields, NaN if the lengths differ
/// or an entry is NaN.
pub fn max_abs_diff(a: &[f64], b: &[f64]) -> f64 {
    if !comparable(a, b) {
        return f64::NAN;
    }
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

/// Largest absolute difference relative to the largest magnitude of the reference `b`:
/// max_i |a_i − b_i| / max_i |b_i| (the absolute difference if `b` is zero; NaN if the lengths
/// differ or an entry is NaN).
pub fn rel_max(a: &[f64], b: &[f64]) -> f64 {
    let d = max_abs_diff(a, b);
    let m = b.iter().map(|x| x.abs()).fold(0.0, f64::max);
    if m > 0.0 {
        d / m
    } else {
        d
    }
}

/// Relative L2 (equivalently RMS) error against the reference `b`: ‖a − b‖₂ / ‖b‖₂ (‖a − b‖₂
/// if `b` is zero; NaN if the lengths differ or an entry is NaN).
pub fn rel_l2(a: &[f64], b: &[f64]) -> f64 {
    if !comparable(a, b) {
        return f64::NAN;
    }
    let d: f64 = a.iter().zip(b).map(|(x, y)| (x - y) * (x - y)).sum();
    let m: f64 = b.iter().map(|x| x * x).sum();
    if m > 0.0 {
        (d / m).sqrt()
    } else {
        d.sqrt()
    }
}

/// Whether the point (x, y) has both coordinates finite and positive: the points
/// [`loglog_fit`] uses and a log–log chart can draw.
pub fn is_loggable((x, y): (f64, f64)) -> bool {
    x.is_finite() && y.is_finite() && x > 0.0 && y > 0.0
}

/// Least-squares slope and intercept of log10(y) against log10(x) over the points with positive
/// finite coordinates; None with fewer than 2 such points.
///
/// The result `(slope, intercept)` means log10 y ≈ intercept + slope · log10 x, i.e.
/// y ≈ 10^intercept · x^slope. Also None when all valid points share one x (the slope is then
/// undefined).
pub fn loglog_fit(points: &[(f64, f64)]) -> Option<(f64, f64)> {
    let logs: Vec<(f64, f64)> = points
        .iter()
        .copied()
        .filter(|&p| is_loggable(p))
        .map(|(x, y)| (x.log10(), y.log10()))
        .collect();
    if logs.len() < 2 {
        return None;
    }
    let n = logs.len() as f64;
    let mx = logs.iter().map(|p| p.0).sum::<f64>() / n;
    let my = logs.iter().map(|p| p.1).sum::<f64>() / n;
    let sxx: f64 = logs.iter().map(|p| (p.0 - mx) * (p.0 - mx)).sum();
    let sxy: f64 = logs.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    if sxx <= 0.0 || !sxx.is_finite() {
        return None;
    }
    let slope = sxy / sxx;
    let intercept = my - slope * mx;
    (slope.is_finite() && intercept.is_finite()).then_some((slope, intercept))
}

/// Indices of the Pareto-optimal points (minimise both x and y): no other point is ≤ in both and
/// < in one. Sorted by x.
///
/// Identical points do not dominate each other, so duplicates of an optimal point are all
/// returned; points with equal x are ordered by y, then by index. Points with a NaN coordinate
/// are never returned and dominate nothing.
pub fn pareto_front(points: &[(f64, f64)]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..points.len())
        .filter(|&i| !points[i].0.is_nan() && !points[i].1.is_nan())
        .collect();
    order.sort_by(|&a, &b| {
        let (pa, pb) = (points[a], points[b]);
        pa.0.total_cmp(&pb.0)
            .then(pa.1.total_cmp(&pb.1))
            .then(a.cmp(&b))
    });
    let mut front = Vec::new();
    // Smallest y over all points with strictly smaller x than the current group.
    let mut best_before = f64::INFINITY;
    let mut k = 0;
    while k < order.len() {
        let x = points[order[k]].0;
        let group_end = order[k..]
            .iter()
            .position(|&i| points[i].0 != x)
            .map_or(order.len(), |p| k + p);
        // The group is sorted by y, so its first point has the group's smallest y.
        let group_min = points[order[k]].1;
        if group_min < best_before {
            front.extend(
                order[k..group_end]
                    .iter()
                    .copied()
                    .filter(|&i| points[i].1 == group_min),
            );
        }
        best_before = best_before.min(group_min);
        k = group_end;
    }
    front
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_of_a_hand_computed_pair() {
        // a − b = (0, 0, −2, 1): max |·| = 2, Σ(·)² = 5; max |b| = 5, Σ b² = 1 + 4 + 25 + 4 = 34.
        let a = [1.0, 2.0, 3.0, -1.0];
        let b = [1.0, 2.0, 5.0, -2.0];
        assert_eq!(max_abs_diff(&a, &b), 2.0, "max_abs_diff");
        assert_eq!(rel_max(&a, &b), 0.4, "rel_max = 2 / 5");
        // One rounding in the quotient and one in the square root: a few ulps.
        let l2 = rel_l2(&a, &b);
        assert!(
            (l2 - (5.0_f64 / 34.0).sqrt()).abs() < 4.0 * f64::EPSILON,
            "rel_l2 {l2} against √(5/34)"
        );
        // Relative RMS over n entries is the same number: √((5/4) / (34/4)).
        assert!((l2 - ((5.0 / 4.0) / (34.0_f64 / 4.0)).sqrt()).abs() < 4.0 * f64::EPSILON);
        // The reference is the second argument: swapping changes the denominator.
        assert_eq!(rel_max(&b, &a), 2.0 / 3.0, "rel_max = 2 / 3 swapped");
    }

    #[test]
    fn errors_of_degenerate_pairs() {
        assert_eq!(max_abs_diff(&[], &[]), 0.0);
        assert_eq!(rel_l2(&[], &[]), 0.0);
        // Zero reference: the absolute error (and 0 for two zero fields).
        assert_eq!(rel_max(&[0.0, -3.0], &[0.0, 0.0]), 3.0);
        assert_eq!(rel_l2(&[3.0, 4.0], &[0.0, 0.0]), 5.0);
        assert_eq!(rel_l2(&[0.0, 0.0], &[0.0, 0.0]), 0.0);
        // Unknown errors are NaN, not a number computed from part of the data.
        assert!(max_abs_diff(&[1.0, 2.0], &[1.0]).is_nan());
        assert!(rel_max(&[1.0], &[1.0, 2.0]).is_nan());
        assert!(rel_l2(&[1.0, f64::NAN], &[1.0, 2.0]).is_nan());
        assert!(rel_max(&[1.0, 2.0], &[f64::NAN, 2.0]).is_nan());
    }

    #[test]
    fn loglog_fit_recovers_power_law() {
        let pts: Vec<(f64, f64)> = [1e-3, 0.01, 0.5, 2.0, 30.0, 1e4]
            .iter()
            .map(|&x: &f64| (x, 3.0 * x.powf(1.5)))
            .collect();
        let (slope, intercept) = loglog_fit(&pts).expect("fit");
        assert!((slope - 1.5).abs() < 1e-12, "slope {slope}");
        assert!(
            (intercept - 3f64.log10()).abs() < 1e-12,
            "intercept {intercept}"
        );

        // Invalid points are ignored.
        let mut noisy = pts.clone();
        noisy.extend([
            (f64::NAN, 1.0),
            (0.0, 1.0),
            (1.0, -2.0),
            (f64::INFINITY, 1.0),
        ]);
        let (s2, i2) = loglog_fit(&noisy).expect("fit with invalid points");
        assert!((s2 - 1.5).abs() < 1e-12 && (i2 - 3f64.log10()).abs() < 1e-12);
    }

    #[test]
    fn loglog_fit_needs_two_valid_points() {
        assert_eq!(loglog_fit(&[]), None);
        assert_eq!(loglog_fit(&[(1.0, 2.0)]), None);
        assert_eq!(loglog_fit(&[(1.0, 2.0), (f64::NAN, 3.0), (2.0, 0.0)]), None);
        assert_eq!(loglog_fit(&[(-1.0, 2.0), (3.0, f64::INFINITY)]), None);
        // Same x twice: no slope.
        assert_eq!(loglog_fit(&[(2.0, 1.0), (2.0, 3.0)]), None);
        assert!(loglog_fit(&[(1.0, 1.0), (10.0, 100.0)]).is_some());
    }

    #[test]
    fn pareto_front_known_set() {
        let pts = [
            (1.0, 5.0),      // 0: front (smallest x)
            (2.0, 3.0),      // 1: front
            (2.0, 4.0),      // 2: dominated by 1 (same x, larger y)
            (3.0, 3.0),      // 3: dominated by 1 (same y, larger x)
            (4.0, 1.0),      // 4: front
            (4.0, 1.0),      // 5: duplicate of 4, front too
            (5.0, 2.0),      // 6: dominated by 4
            (1.0, 6.0),      // 7: dominated by 0
            (6.0, 0.5),      // 8: front
            (f64::NAN, 0.0), // 9: ignored
            (0.5, f64::NAN), // 10: ignored
            (3.0, 2.5),      // 11: front
        ];
        assert_eq!(pareto_front(&pts), vec![0, 1, 11, 4, 5, 8]);
        assert_eq!(pareto_front(&[]), Vec::<usize>::new());
        assert_eq!(pareto_front(&[(1.0, 1.0)]), vec![0]);
    }

    #[test]
    fn pareto_front_matches_brute_force() {
        // Deterministic pseudo-random points on a coarse lattice (many ties).
        let mut state = 12345_u64;
        let mut next = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 33) % 7) as f64
        };
        for _ in 0..50 {
            let pts: Vec<(f64, f64)> = (0..15).map(|_| (next(), next())).collect();
            let mut expected: Vec<usize> = (0..pts.len())
                .filter(|&i| {
                    !pts.iter().any(|q| {
                        let p = pts[i];
                        q.0 <= p.0 && q.1 <= p.1 && (q.0 < p.0 || q.1 < p.1)
                    })
                })
                .collect();
            expected.sort_by(|&a, &b| {
                pts[a]
                    .0
                    .total_cmp(&pts[b].0)
                    .then(pts[a].1.total_cmp(&pts[b].1))
                    .then(a.cmp(&b))
            });
            assert_eq!(pareto_front(&pts), expected, "{pts:?}");
        }
    }
}
