//! Axes: padded linear ranges, the finite extent of coordinates, tick labels, logarithmic
//! axes with their decade ticks and superscript labels, and the plan-view chart type.

use plotters::chart::ChartContext;
use plotters::coord::cartesian::Cartesian2d;
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::coord::types::RangedCoordf64;

/// A plan-view chart in the plate's coordinates, its ticks at round values of the shown unit.
pub(super) type Plan<'a, DB> = ChartContext<'a, DB, Cartesian2d<Ticked, Ticked>>;

/// A linear axis in the plate's coordinates whose ticks are given ([`round_ticks`]): plotters'
/// own `WithKeyPoints` has no default label formatting, which the mesh needs.
pub(super) struct Ticked {
    inner: RangedCoordf64,
    ticks: Vec<f64>,
}

impl Ticked {
    /// [lo, hi] with ticks at round values of the shown unit (`shown` per field unit).
    pub(super) fn new(lo: f64, hi: f64, shown: f64) -> Self {
        Self {
            inner: (lo..hi).into(),
            ticks: round_ticks(lo, hi, shown),
        }
    }

    /// [lo, hi] with the given ticks (a logarithmic axis's, drawn in log10 units).
    pub(super) fn at(lo: f64, hi: f64, ticks: Vec<f64>) -> Self {
        Self {
            inner: (lo..hi).into(),
            ticks,
        }
    }
}

impl Ranged for Ticked {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        self.inner.map(value, limit)
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        // Fewer when the axis has no room for all (the hint's largest count).
        let room = hint.max_num_points().max(1);
        let every = self.ticks.len().div_ceil(room).max(1);
        self.ticks.iter().step_by(every).copied().collect()
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.inner.range()
    }
}

/// Tick positions in [lo, hi] (field units) at round values of the shown unit, `shown` shown
/// units per field unit: steps of 1, 2 or 5 × 10^k shown units, the largest giving at least
/// four ticks (an inch-labelled map of a 4 m slab: every 20 in).
pub(super) fn round_ticks(lo: f64, hi: f64, shown: f64) -> Vec<f64> {
    let (a, b) = (lo.min(hi) * shown, lo.max(hi) * shown);
    let span = b - a;
    if !(span > 0.0 && span.is_finite() && shown > 0.0) {
        return vec![lo];
    }
    let base = 10f64.powf((span / 4.0).log10().floor());
    let step = [5.0, 2.0, 1.0]
        .iter()
        .map(|m| m * base)
        .find(|st| (span / st).floor() >= 4.0)
        .unwrap_or(base);
    let first = (a / step).ceil() as i64;
    let last = (b / step).floor() as i64;
    (first..=last).map(|k| k as f64 * step / shown).collect()
}

/// Finite range of `values` including `always` (if given), padded by 5 % on both sides and
/// never empty: a single value v gets ±10 % of |v| (±1 for 0); no finite value gives (−1, 1).
///
/// With `always = Some(0.0)` this is the range of a profile panel, whose zero line must show.
pub(crate) fn padded_range(values: impl Iterator<Item = f64>, always: Option<f64>) -> (f64, f64) {
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    for v in values.chain(always).filter(|v| v.is_finite()) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !lo.is_finite() || !hi.is_finite() {
        return (-1.0, 1.0);
    }
    let span = hi - lo;
    if span <= 1e-12 * hi.abs().max(lo.abs()).max(1e-300) {
        let d = if hi.abs() > 0.0 { 0.1 * hi.abs() } else { 1.0 };
        return (lo - d, hi + d);
    }
    (lo - 0.05 * span, hi + 0.05 * span)
}

/// Smallest and largest finite value of `values`, unpadded (a plate's extent); a single value v
/// gives (v − 1, v + 1) and no finite value (−1, 1), so the range is never empty.
pub(crate) fn finite_extent(values: &[f64]) -> (f64, f64) {
    let (lo, hi) = values
        .iter()
        .filter(|a| a.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &a| {
            (l.min(a), h.max(a))
        });
    if lo.is_finite() && hi > lo {
        (lo, hi)
    } else if lo.is_finite() {
        (lo - 1.0, lo + 1.0)
    } else {
        (-1.0, 1.0)
    }
}

/// Tick-label formatter for an axis spanning `lo`..`hi`: enough decimals for about ten ticks,
/// trailing zeros dropped, no "-0", scientific notation for very small or large magnitudes.
pub(crate) fn tick_format(lo: f64, hi: f64) -> impl Fn(&f64) -> String {
    let span = (hi - lo).abs();
    let mag = lo.abs().max(hi.abs());
    let step = if span > 0.0 && span.is_finite() {
        span / 10.0
    } else {
        1.0
    };
    let decimals = ((-step.log10()).ceil() as i32 + 1).clamp(0, 8) as usize;
    move |v: &f64| {
        let v = *v;
        if !v.is_finite() {
            return String::new();
        }
        if v.abs() <= 1e-9 * span.max(f64::MIN_POSITIVE) {
            return "0".to_string();
        }
        if !(1e-3..1e5).contains(&mag) {
            return format!("{v:.2e}");
        }
        let text = format!("{v:.decimals$}");
        let text = if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            text
        };
        if text == "-0" {
            "0".to_string()
        } else {
            text
        }
    }
}

/// A logarithmic axis, in log10 units: the range and the major (labelled) and minor ticks.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct LogAxis {
    /// Lower end, log10.
    pub lo: f64,
    /// Upper end, log10.
    pub hi: f64,
    /// Labelled ticks, log10.
    pub bold: Vec<f64>,
    /// Unlabelled ticks, log10.
    pub light: Vec<f64>,
}

/// Axis for the log10 `values` (finite): their range with a 5 % margin, widened to at least one
/// decade and kept within 10⁻³⁰⁷ to 10³⁰⁸ (normal floating-point numbers); (0, 1) — 1 to 10 —
/// without values.
pub(crate) fn log_axis(values: impl Iterator<Item = f64>) -> LogAxis {
    let (mut lo, mut hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| {
            (l.min(v), h.max(v))
        });
    if !(lo.is_finite() && hi.is_finite()) {
        lo = 0.0;
        hi = 1.0;
    } else {
        let pad = 0.05 * (hi - lo);
        lo -= pad;
        hi += pad;
        if hi - lo < 1.0 {
            let centre = 0.5 * (lo + hi);
            lo = centre - 0.5;
            hi = centre + 0.5;
        }
        lo = lo.clamp(-307.0, 307.0);
        hi = hi.clamp(lo + 1.0, 308.0);
    }
    let span = hi - lo;
    let first = lo.ceil() as i64;
    let last = hi.floor() as i64;
    let decades = (last - first + 1).max(0);
    let step = if decades > 12 { (decades + 9) / 10 } else { 1 };
    let eps = 1e-9;
    let inside = |v: f64| v >= lo - eps && v <= hi + eps;
    let mut bold = Vec::new();
    let mut light = Vec::new();
    // One decade below the first full one, for the partial decade at the low end.
    for k in (first - 1)..=last {
        let kf = k as f64;
        if inside(kf) {
            if k.rem_euclid(step) == 0 {
                bold.push(kf);
            } else {
                light.push(kf);
            }
        }
        if span <= 8.0 {
            for m in 2..=9 {
                let v = kf + f64::from(m).log10();
                if !inside(v) {
                    continue;
                }
                if span <= 2.5 && (m == 2 || m == 5) {
                    bold.push(v);
                } else {
                    light.push(v);
                }
            }
        }
    }
    LogAxis {
        lo,
        hi,
        bold,
        light,
    }
}

/// `n` with superscript digits and minus sign.
pub(crate) fn superscript(n: i64) -> String {
    n.to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            '0' => '⁰',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            '4' => '⁴',
            '5' => '⁵',
            '6' => '⁶',
            '7' => '⁷',
            '8' => '⁸',
            '9' => '⁹',
            other => other,
        })
        .collect()
}

/// Whether every major tick of `axis` lies between 0.01 and 1000 (labels as plain numbers).
pub(crate) fn plain_labels(axis: &LogAxis) -> bool {
    axis.bold
        .iter()
        .all(|v| (-2.0..4.0).contains(&(v + 1e-9).floor()))
}

/// Tick label of the log10 value `v`: a plain number if `plain` (see [`plain_labels`]),
/// otherwise "10ⁿ" or "m×10ⁿ".
pub(crate) fn log_tick_label(v: f64, plain: bool) -> String {
    if !v.is_finite() {
        return String::new();
    }
    let k = (v + 1e-9).floor();
    let m = 10f64.powf(v - k).round().max(1.0);
    let (k, m) = if m >= 10.0 {
        (k as i64 + 1, 1)
    } else {
        (k as i64, m as i64)
    };
    if plain && (-2..=3).contains(&k) {
        let decimals = usize::try_from(-k).unwrap_or(0);
        format!("{:.*}", decimals, m as f64 * 10f64.powi(k as i32))
    } else if m == 1 {
        format!("10{}", superscript(k))
    } else {
        format!("{m}×10{}", superscript(k))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn padded_range_includes_zero_and_pads_five_percent() {
        // Values 1..3 with 0: span 3, pad 0.15 (up to rounding of 0.05 · 3).
        let (lo, hi) = padded_range([1.0, 3.0, f64::NAN].into_iter(), Some(0.0));
        assert!(
            (lo + 0.15).abs() < 1e-15 && (hi - 3.15).abs() < 1e-15,
            "{lo} {hi}"
        );
        // All zero: ±1; one non-zero value: ±10 % of it; nothing finite: (−1, 1).
        assert_eq!(padded_range([0.0, 0.0].into_iter(), Some(0.0)), (-1.0, 1.0));
        let (lo, hi) = padded_range([2.0].into_iter(), None);
        assert!(
            (lo - 1.8).abs() < 1e-15 && (hi - 2.2).abs() < 1e-15,
            "{lo} {hi}"
        );
        assert_eq!(padded_range([f64::INFINITY].into_iter(), None), (-1.0, 1.0));
    }

    #[test]
    fn finite_extent_is_never_empty() {
        assert_eq!(finite_extent(&[-2.0, f64::NAN, 2.0, 0.5]), (-2.0, 2.0));
        assert_eq!(finite_extent(&[3.0, 3.0]), (2.0, 4.0));
        assert_eq!(finite_extent(&[]), (-1.0, 1.0));
    }

    #[test]
    fn tick_labels_are_short() {
        let f = tick_format(-1.0, 1.0);
        assert_eq!(f(&0.5), "0.5");
        assert_eq!(f(&-0.0), "0");
        assert_eq!(f(&1e-12), "0");
        assert_eq!(f(&-0.25), "-0.25");
        assert_eq!(f(&f64::NAN), "");
        // Tiny magnitudes switch to scientific notation.
        assert_eq!(tick_format(0.0, 1e-5)(&5e-6), "5.00e-6");
    }

    #[test]
    fn log_axis_spans_a_decade_and_labels() {
        let a = log_axis([0.2_f64.log10(), 0.3_f64.log10()].into_iter());
        assert!(a.hi - a.lo >= 1.0 - 1e-12);
        assert!(!a.bold.is_empty());
        let e = log_axis(std::iter::empty());
        assert_eq!((e.lo, e.hi), (0.0, 1.0));
        assert!(plain_labels(&a) && plain_labels(&e));
        assert!(!plain_labels(&log_axis([-4.0, -1.0].into_iter())));
        assert_eq!(log_tick_label(0.0, true), "1");
        assert_eq!(log_tick_label(-2.0, true), "0.01");
        assert_eq!(log_tick_label(5f64.log10() - 2.0, true), "0.05");
        assert_eq!(log_tick_label(3.0, true), "1000");
        assert_eq!(log_tick_label(3.0, false), "10³");
        assert_eq!(log_tick_label(0.0, false), "10⁰");
        assert_eq!(log_tick_label(-6.0, true), "10⁻⁶");
        assert_eq!(log_tick_label(2f64.log10() - 5.0, false), "2×10⁻⁵");
        assert_eq!(log_tick_label(12.0, false), "10¹²");
        // Very wide ranges keep a bounded number of labels.
        let w = log_axis([-300.0, 300.0].into_iter());
        assert!(w.bold.len() <= 13, "{}", w.bold.len());
    }
}

#[cfg(test)]
mod round_tick_tests {
    use super::round_ticks;

    /// A 4.267 m (168 in) side shown in inches: ticks every 20 in, each a whole number of
    /// inches; in metres on ±2 m, every metre.
    #[test]
    fn ticks_sit_at_round_values_of_the_shown_unit() {
        let shown = 1.0 / 0.0254;
        let t = round_ticks(-2.1336, 2.1336, shown);
        let inches: Vec<f64> = t.iter().map(|v| v * shown).collect();
        assert!(inches.len() >= 4, "{inches:?}");
        for v in &inches {
            assert!(
                (v - v.round()).abs() < 1e-9 && (v.round() as i64) % 20 == 0,
                "{inches:?}"
            );
        }
        let m = round_ticks(-2.0, 2.0, 1.0);
        assert_eq!(m, vec![-2.0, -1.0, 0.0, 1.0, 2.0]);
        assert_eq!(round_ticks(1.0, 1.0, 1.0), vec![1.0]);
    }
}
