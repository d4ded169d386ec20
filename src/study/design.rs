//! The least thickness that carries the traffic (`liftoff design`): whole damage runs
//! ([`super::damage`]) of the scene at thicknesses over a range — the design curve — and the
//! least thickness that meets the target, bracketed between the curve's last failing and
//! first passing thickness and narrowed to a tolerance by probes placed where the bracket's
//! values say the target lies ([`narrow`]).
//!
//! **The target** is the relation's: for `mepdg` the total cracking (% of slabs) — at the
//! scene's `[damage] reliability` when it gives one, else the mean —, 15 % unless given; for
//! `faa` the larger of the bottom-up and top-down damage, for `pca` the largest of those and
//! the erosion damage at the corners (EB109 designs against both), 1 unless given.
//!
//! **What follows the thickness.** The plate's thickness, and with it its rigidity, its
//! stresses and the curvature of a temperature difference (α ΔT / H: a climate bin given as a
//! `difference` keeps it, in K, at every thickness; one given as a `gradient`, K/m, takes
//! gradient × H — a thicker slab in the same weather sees a larger difference; a profile,
//! read over the thickness with its depths in proportion, keeps its equivalent difference and
//! its nonlinear part); a `uniform` load whose `case` or `name` is `self-weight` scales with the
//! thickness (ρ g H); every other load is kept. Panels with a thickness of their own (a
//! shoulder) keep it.

use serde::Serialize;

use crate::error::{Error, Result};
use crate::monitor::{Cases, Monitor};
use crate::scene::SceneFile;
use crate::units::{Measure, Quantity, UnitSystem};

/// The range and the target of a design search.
#[derive(Debug, Clone, PartialEq)]
pub struct DesignOptions {
    /// Thinnest thickness tried, m.
    pub from: f64,
    /// Thickest, m.
    pub to: f64,
    /// Thicknesses of the design curve, evenly over the range (≥ 2).
    pub points: usize,
    /// The target (None: 15 % cracking for `mepdg`, damage 1 for `pca` and `faa`).
    pub target: Option<f64>,
    /// The bracket is narrowed until it is this narrow, m.
    pub tolerance: f64,
}

impl DesignOptions {
    /// The options as a user gives them (the command line, Python): the range `[from, to]` and
    /// the `tolerance` in the scene's unit of length (`units`), the tolerance 5 mm by default
    /// (0.25 in for a US scene).
    pub fn in_units(
        units: UnitSystem,
        range: [f64; 2],
        points: usize,
        target: Option<f64>,
        tolerance: Option<f64>,
    ) -> Self {
        let length = |v: f64| Quantity::Length.to_si(units, v);
        let tolerance = match (tolerance, units) {
            (Some(t), _) => length(t),
            (None, UnitSystem::Us) => length(0.25),
            (None, UnitSystem::Si) => 0.005,
        };
        Self {
            from: length(range[0]),
            to: length(range[1]),
            points,
            target,
            tolerance,
        }
    }

    /// Check the options; errors name the option.
    pub fn validate(&self) -> Result<()> {
        if !(self.from.is_finite() && self.to.is_finite() && 0.0 < self.from && self.from < self.to)
        {
            return Err(Error::invalid(
                "vary",
                format!(
                    "must be thickness=FROM..TO with 0 < FROM < TO, got {}..{}",
                    self.from, self.to
                ),
            ));
        }
        if !(2..=41).contains(&self.points) {
            return Err(Error::invalid(
                "points",
                format!("must be 2 … 41 thicknesses, got {}", self.points),
            ));
        }
        if let Some(t) = self.target.filter(|t| !(t.is_finite() && *t > 0.0)) {
            return Err(Error::invalid(
                "target",
                format!("must be positive, got {t}"),
            ));
        }
        if !(self.tolerance.is_finite() && self.tolerance > 0.0) {
            return Err(Error::invalid(
                "tolerance",
                format!("must be a positive thickness, got {}", self.tolerance),
            ));
        }
        Ok(())
    }
}

/// One damage run of the search.
#[derive(Debug, Clone, Serialize)]
pub struct DesignPoint {
    /// Thickness, m.
    pub thickness: f64,
    /// Governing bottom-up damage.
    pub bottom: f64,
    /// Governing top-down damage.
    pub top: f64,
    /// The PCA's governing erosion damage (null: another relation, or none summed).
    pub erosion: Option<f64>,
    /// Total cracking, % (mepdg; at the reliability when given).
    pub cracking: Option<f64>,
    /// The value compared with the target.
    pub value: f64,
    /// Whether it meets the target.
    pub passes: bool,
    /// Whether every pass of the damage run converged.
    pub complete: bool,
    /// Solves of the run.
    pub solves: usize,
    /// Seconds of the run.
    pub seconds: f64,
    /// On the design curve (true) or a step of the search that narrows the bracket.
    pub curve: bool,
}

/// The result of a design search.
#[derive(Debug, Clone, Serialize)]
pub struct Design {
    /// The relation.
    pub model: &'static str,
    /// What is compared with the target: `cracking` (%) or `damage`.
    pub measure: &'static str,
    /// The target.
    pub target: f64,
    /// Every run, by thickness.
    pub points: Vec<DesignPoint>,
    /// The least thickness found to meet the target (null: none in the range does).
    pub thickness: Option<f64>,
    /// The failing and passing thicknesses that bracket it (null: at an end of the range).
    pub bracket: Option<[f64; 2]>,
    /// Whether the design curve falls as the slab thickens (if not, the bracket may not be the
    /// least thickness: the table shows where it rises).
    pub monotone: bool,
    /// Whether every run was complete.
    pub complete: bool,
    /// Whether the runs left parts of the plate out of the sums: the end panels (and with
    /// `pca` the end corners) of a lane the model cuts (`[traffic] ends`).
    pub cut: bool,
    /// The scene's unit system (None: dimensionless); thicknesses above are SI.
    pub units: Option<crate::units::UnitSystem>,
    /// Seconds of the whole search.
    pub total_s: f64,
}

impl Design {
    /// The search as design.json reports it: thicknesses in the scene's unit of length (an SI
    /// scene's unchanged); damage and cracking are pure numbers.
    pub fn reported(&self) -> Design {
        let l = |v: f64| Measure::Length.from_si(self.units, v);
        Design {
            points: self
                .points
                .iter()
                .map(|p| DesignPoint {
                    thickness: l(p.thickness),
                    ..p.clone()
                })
                .collect(),
            thickness: self.thickness.map(l),
            bracket: self.bracket.map(|[a, b]| [l(a), l(b)]),
            ..self.clone()
        }
    }
}

/// Bisection steps that narrow a bracket of `width` to `tolerance` (the progress bar's count of
/// the search's runs: [`narrow`] takes about that many or fewer).
fn halvings(width: f64, tolerance: f64) -> usize {
    if width <= tolerance {
        0
    } else {
        (width / tolerance).log2().ceil() as usize
    }
}

/// Narrow the bracket from `lo` (a failing thickness and its value) to `hi` (a passing one) to
/// `tolerance`, running `run` at each new thickness: the least passing thickness stays between
/// them. A thickness passes when its value is at most `target`.
///
/// Each probe is placed where the line through the ends' values in log(value) against the
/// thickness meets the target — damage falls about exponentially with the thickness over a
/// bracket, and so does cracking's FD below its knee —, half a tolerance above that estimate,
/// so that when it passes, one more probe a tolerance below it closes a bracket of the
/// tolerance around the estimate: two runs where a bisection of the curve's step to 5 mm takes
/// three. Where the values are not positive or not falling, the probe is the midpoint; and a
/// pair of probes that did not halve the bracket is followed by a midpoint, so that no bracket
/// takes much more than the bisection would.
fn narrow(
    lo: (f64, f64),
    hi: (f64, f64),
    target: f64,
    tolerance: f64,
    mut run: impl FnMut(f64) -> Result<f64>,
) -> Result<[f64; 2]> {
    let ((mut lo, mut v_lo), (mut hi, mut v_hi)) = (lo, hi);
    // The bracket's width when the current pair of probes began, and the pair's second probe.
    let mut pair_from = hi - lo;
    let mut second: Option<f64> = None;
    let mut bisect = false;
    // A bracket a tolerance wide by construction (a probe a tolerance below the last) may
    // differ from it in the last bits.
    let wide = |lo: f64, hi: f64| hi - lo > tolerance * (1.0 + 1e-12);
    while wide(lo, hi) {
        let width = hi - lo;
        let x = match second.take() {
            Some(x) if x > lo && x < hi => x,
            _ => {
                if width > 2.0 * tolerance && !bisect {
                    pair_from = width;
                }
                match estimate((lo, v_lo), (hi, v_hi), target) {
                    Some(h) if width > 2.0 * tolerance && !bisect => {
                        let x =
                            (h + 0.5 * tolerance).clamp(lo + 0.5 * tolerance, hi - 0.5 * tolerance);
                        second = Some(x - tolerance);
                        x
                    }
                    _ => {
                        bisect = false;
                        0.5 * (lo + hi)
                    }
                }
            }
        };
        let v = run(x)?;
        if v <= target {
            (hi, v_hi) = (x, v);
        } else {
            (lo, v_lo) = (x, v);
            // A probe meant to pass failed: the estimate was low; estimate again.
            second = None;
        }
        if second.is_none() && hi - lo > 0.5 * pair_from {
            bisect = true;
        }
    }
    Ok([lo, hi])
}

/// Where the line through (lo, ln v_lo) and (hi, ln v_hi) meets ln `target` (None: a value
/// that is not positive, or values that do not fall across the bracket).
fn estimate(lo: (f64, f64), hi: (f64, f64), target: f64) -> Option<f64> {
    let ((a, va), (b, vb)) = (lo, hi);
    if !(va > 0.0 && vb > 0.0 && target > 0.0 && va > vb) {
        return None;
    }
    let h = a + (b - a) * (va.ln() - target.ln()) / (va.ln() - vb.ln());
    h.is_finite().then_some(h)
}

/// Run the search on `file` (validated at every thickness); see the module's description.
pub fn design(file: &SceneFile, options: &DesignOptions, monitor: &Monitor<'_>) -> Result<Design> {
    options.validate()?;
    let t0 = std::time::Instant::now();
    let base = file.plate.as_ref().map(|p| p.thickness).ok_or_else(|| {
        Error::invalid(
            "plate",
            "a design varies the plate's thickness: give the scene as [plate] and [foundation]",
        )
    })?;
    let step = (options.to - options.from) / (options.points - 1) as f64;
    let cases = Cases::new(monitor, options.points + halvings(step, options.tolerance));
    let inner = cases.inner();
    // Whether a run left the end panels of a cut lane out (the same at every thickness).
    let cut = std::cell::Cell::new(false);
    let run =
        |h: f64, curve: bool| -> Result<(DesignPoint, &'static str, Option<f64>, &'static str)> {
            let mut f = file.clone();
            if let Some(p) = f.plate.as_mut() {
                p.thickness = h;
            }
            for l in &mut f.load {
                let weight = |s: &Option<String>| s.as_deref() == Some("self-weight");
                if matches!(l.kind, crate::scene::LoadKind::Uniform)
                    && (weight(&l.case) || weight(&l.name))
                {
                    l.pressure = l.pressure.map(|p| p * h / base);
                }
            }
            let problem = f.validate()?;
            let t = std::time::Instant::now();
            let d = super::damage(&problem, &inner)?;
            let left_out = d.counted.iter().any(|c| !c)
                || d.erosion.as_ref().is_some_and(|e| e.uncounted().is_some());
            cut.set(cut.get() || left_out);
            let erosion = d.erosion.as_ref().map(|e| e.damage());
            let (measure, value) = match d.cracking {
                Some(c) => ("cracking", c.at_reliability.unwrap_or(c.total)),
                None => (
                    "damage",
                    d.governing_bottom
                        .damage
                        .max(d.governing_top.damage)
                        .max(erosion.unwrap_or(0.0)),
                ),
            };
            let target = options
                .target
                .unwrap_or(if measure == "cracking" { 15.0 } else { 1.0 });
            cases.finish(&format!("{:.4} m: {measure} {value:.4}", h))?;
            Ok((
                DesignPoint {
                    thickness: h,
                    bottom: d.governing_bottom.damage,
                    top: d.governing_top.damage,
                    erosion,
                    cracking: d.cracking.map(|c| c.at_reliability.unwrap_or(c.total)),
                    value,
                    passes: value <= target,
                    complete: d.complete,
                    solves: d.solves,
                    seconds: t.elapsed().as_secs_f64(),
                    curve,
                },
                measure,
                Some(target),
                d.model,
            ))
        };
    let mut points = Vec::new();
    let mut meta = ("damage", 1.0, "");
    for k in 0..options.points {
        let h = options.from + step * k as f64;
        let (p, measure, target, model) = run(h, true)?;
        meta = (measure, target.unwrap_or(1.0), model);
        points.push(p);
    }
    let monotone = points
        .windows(2)
        .all(|w| w[1].value <= w[0].value * (1.0 + 1e-9) + 1e-300);
    let first = points.iter().position(|p| p.passes);
    let (thickness, bracket) = match first {
        None => (None, None),
        Some(0) => (Some(points[0].thickness), None),
        Some(i) => {
            let (a, b) = (&points[i - 1], &points[i]);
            let (lo, hi) = ((a.thickness, a.value), (b.thickness, b.value));
            let mut steps = Vec::new();
            let [lo, hi] = narrow(lo, hi, meta.1, options.tolerance, |h| {
                let (p, ..) = run(h, false)?;
                let value = p.value;
                steps.push(p);
                Ok(value)
            })?;
            points.extend(steps);
            (Some(hi), Some([lo, hi]))
        }
    };
    points.sort_by(|a, b| a.thickness.total_cmp(&b.thickness));
    let units = file.plate.as_ref().map(|_| file.units);
    Ok(Design {
        model: meta.2,
        measure: meta.0,
        target: meta.1,
        complete: points.iter().all(|p| p.complete),
        cut: cut.get(),
        points,
        thickness,
        bracket,
        monotone,
        units,
        total_s: t0.elapsed().as_secs_f64(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The search on a known curve: the bracket it returns holds the curve's root, is no wider
    /// than the tolerance, its low end fails and its high end passes; and the runs it took.
    fn search(
        f: impl Fn(f64) -> f64,
        lo: f64,
        hi: f64,
        target: f64,
        tol: f64,
    ) -> ([f64; 2], usize) {
        let mut runs = 0;
        let bracket = narrow((lo, f(lo)), (hi, f(hi)), target, tol, |h| {
            runs += 1;
            Ok(f(h))
        })
        .expect("search");
        let [a, b] = bracket;
        assert!(lo <= a && a < b && b <= hi, "{bracket:?}");
        assert!(b - a <= tol * (1.0 + 1e-12), "{bracket:?}");
        assert!(f(a) > target && f(b) <= target, "{bracket:?}");
        (bracket, runs)
    }

    /// Damage falling exponentially with the thickness (the model the probes assume): the
    /// first probe lands half a tolerance above the root and the second half one below, two runs
    /// where the bisection of a 40 mm step to 5 mm takes three.
    #[test]
    fn an_exponential_curve_takes_two_runs() {
        let f = |h: f64| 10.0 * (-30.0 * (h - 0.2)).exp();
        let root = 0.2 + 10.0_f64.ln() / 30.0;
        let ([a, b], runs) = search(f, 0.24, 0.28, 1.0, 0.005);
        assert_eq!(runs, 2);
        assert_eq!(halvings(0.04, 0.005), 3);
        assert!(a < root && root <= b);
    }

    /// Curves the interpolation misjudges — a cracking-like sigmoid, a step, a curve falling
    /// slowly then steeply — still end in a valid bracket, in at most three runs a halving
    /// (a pair of probes that did not halve the bracket is followed by a midpoint).
    #[test]
    fn misjudged_curves_still_bracket_the_root() {
        let cracking = |h: f64| {
            let fd = (-40.0 * (h - 0.25)).exp();
            100.0 / (1.0 + fd.powf(-1.98))
        };
        let step = |h: f64| if h < 0.2537 { 50.0 } else { 0.01 };
        let knee = |h: f64| {
            if h < 0.27 {
                2.0 - (h - 0.24)
            } else {
                1.7 * (-200.0 * (h - 0.27)).exp()
            }
        };
        for (f, target) in [
            (&cracking as &dyn Fn(f64) -> f64, 15.0),
            (&step, 1.0),
            (&knee, 1.0),
        ] {
            let (_, runs) = search(f, 0.24, 0.28, target, 0.005);
            assert!(runs <= 3 * halvings(0.04, 0.005), "{runs} runs");
        }
    }

    /// Where the values cannot be interpolated (a zero, values that do not fall), the probes
    /// are midpoints: the plain bisection's count.
    #[test]
    fn values_that_cannot_be_interpolated_are_bisected() {
        let zero_below = |h: f64| if h < 0.251 { 3.0 } else { 0.0 };
        let (_, runs) = search(zero_below, 0.24, 0.28, 1.0, 0.005);
        assert_eq!(runs, halvings(0.04, 0.005));
        assert_eq!(estimate((0.24, 3.0), (0.28, 0.0), 1.0), None);
        assert_eq!(estimate((0.24, 1.0), (0.28, 2.0), 1.5), None);
    }
}
