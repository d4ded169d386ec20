//! The modulus of rupture's growth with age (`[damage] rupture_growth = "mepdg"`): concrete
//! gains strength for years after its 28-day test, and a cycle late in the life meets a
//! stronger slab than one in the first month.
//!
//! The MEPDG's relation (NCHRP 1-37A, Part 2, Chapter 2, the strength gain of PCC; the Manual of
//! Practice, 2008, keeps it): MR(t) / MR₂₈ = 1 + 0.12 log₁₀(t / 0.0767) − 0.01566
//! [log₁₀(t / 0.0767)]², t the age in years (0.0767 years = 28 days). It gives 1 at 28 days,
//! 1.11 at one year, 1.20 at 20 years — the guide's long-term ratio of 1.2 — and 1.21 at 40;
//! `tests` holds the ends.
//!
//! **The sum.** The life is cut into months, m = 0, 1, …, ⌈12 × life⌉ − 1; month m carries the
//! share w_m of the traffic ((1 + g)^⌊m/12⌋ of the traffic growth g, normalised to Σ w_m = 1)
//! and meets the modulus of rupture at its middle, t_m = 28 days + (m + ½) / 12 years (the
//! traffic opens at 28 days, as the MR is tested). A cycle of stress σ then does the damage
//! Σ_m w_m / N(σ, MR₂₈ r(t_m)) on average, and the damage run counts n cycles as n times that,
//! which is the monthly sum of the MEPDG (its month's traffic over its month's N) when the
//! stresses do not change with age. They are taken at the scene's E: the MEPDG grows E with
//! age too, which stiffens the slab and raises its stresses a little; that is not modelled
//! (a slab's E is one value here for the whole life).

/// The MEPDG's ratio of the modulus of rupture at `age` (years) to the 28-day one.
pub fn mepdg_ratio(age: f64) -> f64 {
    let l = (age / MEPDG_28_DAYS).log10();
    1.0 + 0.12 * l - 0.01566 * l * l
}

/// 28 days in years, as the MEPDG writes it.
pub const MEPDG_28_DAYS: f64 = 0.0767;

/// The months of a design life: each month's share of the traffic and the modulus of
/// rupture's ratio to the 28-day one in it (the module's text).
#[derive(Debug, Clone, PartialEq)]
pub struct AgeSchedule {
    /// (share of the traffic, MR ratio), month by month; the shares add up to 1.
    pub months: Vec<(f64, f64)>,
}

impl AgeSchedule {
    /// The MEPDG's schedule over `life` years with a yearly traffic growth `growth` (compound).
    pub fn mepdg(life: f64, growth: f64) -> Self {
        let count = ((12.0 * life).ceil() as usize).max(1);
        let mut months: Vec<(f64, f64)> = (0..count)
            .map(|m| {
                let year = (m / 12) as f64;
                let age = MEPDG_28_DAYS + (m as f64 + 0.5) / 12.0;
                ((1.0 + growth).powf(year), mepdg_ratio(age))
            })
            .collect();
        let total: f64 = months.iter().map(|m| m.0).sum();
        for m in &mut months {
            m.0 /= total;
        }
        Self { months }
    }

    /// The average damage of one cycle over the schedule, Σ w_m / N(r_m), with `allowed(r)`
    /// the cycles allowed at the MR ratio r. When the youngest month's concrete (the weakest,
    /// the ratio grows with age up to 500 years) allows unlimited cycles, every month does and
    /// the damage is 0 without the sum.
    pub fn damage_per_cycle(&self, allowed: impl Fn(f64) -> f64) -> f64 {
        let weakest = self
            .months
            .iter()
            .map(|m| m.1)
            .fold(f64::INFINITY, f64::min);
        if allowed(weakest).is_infinite() {
            return 0.0;
        }
        self.months.iter().map(|&(w, r)| w / allowed(r)).sum()
    }

    /// The smallest and largest MR ratio over the schedule.
    pub fn ratio_range(&self) -> [f64; 2] {
        self.months
            .iter()
            .fold([f64::INFINITY, 0.0], |[lo, hi], m| {
                [lo.min(m.1), hi.max(m.1)]
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The relation's points: 1 at 28 days (to round-off: its definition), 1.1986 at 20 years
    /// (the guide's long-term ratio, 1.2, to the two decimals it is printed with), growing
    /// year by year between and beyond.
    #[test]
    fn the_ratio_is_one_at_28_days_and_one_point_two_at_20_years() {
        assert!((mepdg_ratio(MEPDG_28_DAYS) - 1.0).abs() < 1e-12);
        assert!((mepdg_ratio(20.0) - 1.20).abs() < 0.005);
        let r: Vec<f64> = (1..=40).map(|y| mepdg_ratio(y as f64)).collect();
        assert!(r.windows(2).all(|w| w[1] > w[0]), "{r:?}");
    }

    /// The shares follow the traffic's growth and add up to one; without growth each month
    /// has 1/12 of a year's share.
    #[test]
    fn the_months_carry_the_traffic() {
        let s = AgeSchedule::mepdg(2.0, 0.5);
        assert_eq!(s.months.len(), 24);
        let sum: f64 = s.months.iter().map(|m| m.0).sum();
        assert!((sum - 1.0).abs() < 1e-12);
        // The second year's months carry 1.5 times the first's.
        assert!((s.months[12].0 / s.months[0].0 - 1.5).abs() < 1e-12);
        let flat = AgeSchedule::mepdg(10.0, 0.0);
        assert!(flat
            .months
            .iter()
            .all(|m| (m.0 - 1.0 / 120.0).abs() < 1e-15));
        let [lo, hi] = flat.ratio_range();
        // The first month's middle (1.022) and the last's, at 10.03 years (1.184).
        assert!(
            lo > 1.02 && lo < 1.025 && hi > 1.18 && hi < 1.19,
            "{lo} {hi}"
        );
    }
}
