//! The options of the ε̄ sweep and the tradeoff study, validated before they run.

use super::eps_sweep::{eps_sweep, Sweep};
use super::log_space;
use super::tradeoff::{tradeoff, Tradeoff};
use crate::error::{Error, Result};
use crate::model::ConstraintPoints;
use crate::monitor::Monitor;
use crate::scene::Problem;

/// Which constraint points an ε̄ sweep compares; each kind gets its own assembly and QP
/// reference.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ConstraintVariants {
    /// σ ≥ 0 at the nodes.
    #[default]
    Nodal,
    /// σ ≥ 0 at the Gauss points.
    Gauss,
    /// Nodal, then Gauss.
    Both,
}

crate::choice::names!(ConstraintVariants, Nodal => "nodal", Gauss => "gauss", Both => "both");

impl ConstraintVariants {
    /// The constraint points swept, in order.
    pub fn points(self) -> &'static [ConstraintPoints] {
        match self {
            ConstraintVariants::Nodal => &[ConstraintPoints::Nodal],
            ConstraintVariants::Gauss => &[ConstraintPoints::Gauss],
            ConstraintVariants::Both => &[ConstraintPoints::Nodal, ConstraintPoints::Gauss],
        }
    }
}

/// Options of an ε̄ sweep ([`eps_sweep`]): which ε̄ and which constraint points. Field names
/// are the names of the errors [`EpsSweepOptions::validate`] returns.
#[derive(Debug, Clone, Copy, PartialEq, serde::Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct EpsSweepOptions {
    /// Largest ε̄, in (0, 1).
    pub from: f64,
    /// Smallest ε̄, in (0, 1).
    pub to: f64,
    /// Number of log-spaced ε̄ values from `from` to `to`, 2..=[`EpsSweepOptions::MAX_POINTS`].
    pub points: usize,
    /// Constraint points.
    pub constraints: ConstraintVariants,
}

impl Default for EpsSweepOptions {
    fn default() -> Self {
        Self {
            from: 1e-1,
            to: 1e-12,
            points: 12,
            constraints: ConstraintVariants::Nodal,
        }
    }
}

impl EpsSweepOptions {
    /// Most ε̄ values one sweep takes.
    pub const MAX_POINTS: usize = 200;

    /// Check the options; an [`Error::Invalid`] names the offending field.
    pub fn validate(&self) -> Result<()> {
        for (field, eps) in [("from", self.from), ("to", self.to)] {
            if !(eps.is_finite() && eps > 0.0 && eps < 1.0) {
                return Err(Error::invalid(
                    field,
                    format!("must be a positive ε̄ below 1, got {eps}"),
                ));
            }
        }
        if !(2..=Self::MAX_POINTS).contains(&self.points) {
            return Err(Error::invalid(
                "points",
                format!("must lie in 2..={}, got {}", Self::MAX_POINTS, self.points),
            ));
        }
        Ok(())
    }

    /// The ε̄ values, log-spaced from `from` to `to`.
    pub fn epsilons(&self) -> Vec<f64> {
        log_space(self.from, self.to, self.points)
    }

    /// The ε̄ window [lo, hi] the slope fit may use: the whole sweep.
    pub fn fit_window(&self) -> [f64; 2] {
        [self.to.min(self.from), self.from.max(self.to)]
    }

    /// Validate, then run [`eps_sweep`] on `problem`.
    pub fn run(&self, problem: &Problem, monitor: &Monitor<'_>) -> Result<Sweep> {
        self.validate()?;
        eps_sweep(
            problem,
            &self.epsilons(),
            self.constraints.points(),
            self.fit_window(),
            monitor,
        )
    }
}

/// Options of a speed–accuracy study ([`tradeoff`]). Field names are the names of the errors
/// [`TradeoffOptions::validate`] returns.
#[derive(Debug, Clone, PartialEq, serde::Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct TradeoffOptions {
    /// Elements per side of the whole plate along x (y follows μ), each in
    /// [`TradeoffOptions::MESH_RANGE`]; at least one.
    pub meshes: Vec<usize>,
    /// ε̄ values of the penalty method, each in (0, 1).
    pub penalties: Vec<f64>,
}

impl Default for TradeoffOptions {
    fn default() -> Self {
        Self {
            meshes: vec![8, 16, 32, 64],
            penalties: vec![1e-2, 1e-4, 1e-6, 1e-8],
        }
    }
}

impl TradeoffOptions {
    /// Element counts per side a tradeoff mesh may have.
    pub const MESH_RANGE: std::ops::RangeInclusive<usize> = 2..=2048;

    /// Check the options; an [`Error::Invalid`] names the offending field.
    pub fn validate(&self) -> Result<()> {
        if self.meshes.is_empty() || self.meshes.iter().any(|n| !Self::MESH_RANGE.contains(n)) {
            return Err(Error::invalid(
                "meshes",
                format!(
                    "takes element counts between {} and {}",
                    Self::MESH_RANGE.start(),
                    Self::MESH_RANGE.end()
                ),
            ));
        }
        if self.penalties.iter().any(|&e| !(e > 0.0 && e < 1.0)) {
            return Err(Error::invalid("penalties", "takes ε̄ values in (0, 1)"));
        }
        Ok(())
    }

    /// Validate, then run [`tradeoff`] on `problem`.
    pub fn run(&self, problem: &Problem, monitor: &Monitor<'_>) -> Result<Tradeoff> {
        self.validate()?;
        tradeoff(problem, &self.meshes, &self.penalties, monitor)
    }
}

#[cfg(test)]
mod options_tests {
    use super::*;

    fn field_of(r: Result<()>) -> Option<String> {
        match r {
            Err(Error::Invalid { field, .. }) => Some(field),
            _ => None,
        }
    }

    /// The defaults are valid and give the documented sweep: 12 values from 1e-1 to 1e-12,
    /// one decade apart (log10 steps of (−12 + 1)/11 = −1).
    #[test]
    fn eps_sweep_defaults_are_valid_and_one_decade_apart() {
        let o = EpsSweepOptions::default();
        assert!(o.validate().is_ok(), "EpsSweepOptions::default validates");
        let eps = o.epsilons();
        assert_eq!(eps.len(), 12, "EpsSweepOptions::default: 12 values");
        for (k, e) in eps.iter().enumerate() {
            let want = 10f64.powi(-1 - k as i32);
            // log_space evaluates 10^(a + (b − a)k/(n − 1)) in floating point: a few ulps.
            assert!(
                (e / want - 1.0).abs() < 1e-12,
                "EpsSweepOptions::epsilons[{k}] = {e}, want {want}"
            );
        }
        assert_eq!(o.fit_window(), [1e-12, 1e-1], "EpsSweepOptions::fit_window");
    }

    /// Each out-of-range value is refused with the field that holds it.
    #[test]
    fn eps_sweep_options_name_the_bad_field() {
        let base = EpsSweepOptions::default();
        let cases = [
            (EpsSweepOptions { from: 1.0, ..base }, "from"),
            (
                EpsSweepOptions {
                    from: f64::NAN,
                    ..base
                },
                "from",
            ),
            (EpsSweepOptions { to: 0.0, ..base }, "to"),
            (EpsSweepOptions { to: 2.0, ..base }, "to"),
            (
                EpsSweepOptions {
                    to: f64::INFINITY,
                    ..base
                },
                "to",
            ),
            (EpsSweepOptions { points: 1, ..base }, "points"),
            (
                EpsSweepOptions {
                    points: 201,
                    ..base
                },
                "points",
            ),
        ];
        for (o, field) in cases {
            assert_eq!(
                field_of(o.validate()).as_deref(),
                Some(field),
                "EpsSweepOptions::validate({o:?})"
            );
        }
        let edge = EpsSweepOptions {
            points: 200,
            constraints: ConstraintVariants::Both,
            ..base
        };
        assert!(edge.validate().is_ok(), "200 points are allowed");
    }

    #[test]
    fn constraint_variants_list_their_points() {
        assert_eq!(
            ConstraintVariants::Nodal.points(),
            &[ConstraintPoints::Nodal]
        );
        assert_eq!(
            ConstraintVariants::Gauss.points(),
            &[ConstraintPoints::Gauss]
        );
        assert_eq!(
            ConstraintVariants::Both.points(),
            &[ConstraintPoints::Nodal, ConstraintPoints::Gauss]
        );
    }

    #[test]
    fn tradeoff_options_name_the_bad_field() {
        assert!(
            TradeoffOptions::default().validate().is_ok(),
            "TradeoffOptions::default validates"
        );
        let with = |meshes: Vec<usize>, penalties: Vec<f64>| TradeoffOptions { meshes, penalties };
        let cases = [
            (with(vec![], vec![1e-5]), "meshes"),
            (with(vec![1], vec![1e-5]), "meshes"),
            (with(vec![8, 2049], vec![1e-5]), "meshes"),
            (with(vec![8], vec![1.0]), "penalties"),
            (with(vec![8], vec![0.0]), "penalties"),
            (with(vec![8], vec![1e-3, f64::NAN]), "penalties"),
        ];
        for (o, field) in cases {
            assert_eq!(
                field_of(o.validate()).as_deref(),
                Some(field),
                "TradeoffOptions::validate({o:?})"
            );
        }
        let ok = with(vec![2, 2048], vec![]);
        assert!(
            ok.validate().is_ok(),
            "mesh range ends and no ε̄ are allowed"
        );
    }
}
