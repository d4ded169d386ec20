//! A survey: every drop of a basin file backcalculated on one template — by the AREA method
//! alone, or by the fit on liftoff's model with the AREA estimate beside it — in parallel, one
//! progress event a drop.
//!
//! **Static k.** A deflectometer's load is a pulse of some 30 ms: the k a basin gives is the
//! dynamic one. The AASHTO Guide (1993, Part III, §5.4.5) divides it by 2 for the static k of
//! design; `static_k_factor` holds that 0.5 and is reported beside every k (on a soil fitted as
//! a solid, E_s is reported as fitted).

use rayon::prelude::*;

use super::area::AreaResult;
use super::basins::{Drop, Location};
use super::fit::{area_reading, fit_drop, Fit, FitOptions, Unknown};
use crate::error::{Error, Result};
use crate::monitor::{Cases, Monitor};
use crate::scene::SceneFile;

/// How a survey backcalculates.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum BackcalcMethod {
    /// The least-squares fit on liftoff's model ([`super::fit`]), the AREA estimate beside it.
    Fit,
    /// The AREA method alone ([`super::area`]): interior drops with the four AREA sensors, a
    /// Winkler soil (dense liquid) or a half-space (elastic solid).
    Area,
}

crate::choice::names!(BackcalcMethod, Fit => "fit", Area => "area");

/// The options of a survey.
#[derive(Debug, Clone, PartialEq)]
pub struct SurveyOptions {
    /// Fit or AREA.
    pub method: BackcalcMethod,
    /// The fit's options.
    pub fit: FitOptions,
    /// Seating drops to discard at the start of each station.
    pub seating: usize,
    /// Static k over the dynamic k a basin gives (AASHTO 1993: 0.5).
    pub static_k_factor: f64,
}

impl Default for SurveyOptions {
    fn default() -> Self {
        Self {
            method: BackcalcMethod::Fit,
            fit: FitOptions::default(),
            seating: 0,
            static_k_factor: 0.5,
        }
    }
}

/// One drop's backcalculation.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct DropResult {
    /// The station.
    pub station: String,
    /// The drop's number at its station.
    pub drop: usize,
    /// Where on the slab.
    pub location: Location,
    /// The drop's load, N.
    pub load: f64,
    /// The AREA method's reading (None where it does not apply: not an interior drop, no AREA
    /// sensors, or a soil that is neither springs nor a solid).
    pub area: Option<AreaResult>,
    /// The fit (None with the AREA method alone).
    pub fit: Option<Fit>,
    /// The static k, N/m³: the fitted (or the AREA's) dynamic k times the static factor; None
    /// on a soil fitted by its Young's modulus.
    pub static_k: Option<f64>,
}

impl DropResult {
    /// Whether this drop's answer is complete: a converged fit, or the AREA's reading.
    pub fn converged(&self) -> bool {
        match &self.fit {
            Some(f) => f.converged,
            None => self.area.is_some(),
        }
    }
}

/// A survey's drops.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Survey {
    /// How it was backcalculated.
    pub method: BackcalcMethod,
    /// Each drop's answer, in the file's order (seating drops discarded).
    pub drops: Vec<DropResult>,
    /// The seating drops left out.
    pub discarded: usize,
    /// The static factor applied to k.
    pub static_k_factor: f64,
    /// The template soil's key the subgrade's modulus is (`modulus`, `youngs_modulus`).
    pub subgrade_key: String,
    /// Every fit converged: otherwise `not_converged` names the drops, and no total is
    /// complete.
    pub complete: bool,
    /// The drops whose fit did not converge (`station S, drop n`).
    pub not_converged: Vec<String>,
    /// Solves of the model, over all fits.
    pub solves: usize,
    /// Wall time, s.
    pub seconds: f64,
}

/// Backcalculate every drop (see the module's description). Seating drops are discarded
/// first; a drop the AREA method cannot read is an error naming it when the method is AREA;
/// a fit that does not converge is kept with its best point and makes the survey incomplete.
pub fn survey(
    template: &SceneFile,
    drops: &[Drop],
    options: &SurveyOptions,
    monitor: &Monitor<'_>,
) -> Result<Survey> {
    let t0 = std::time::Instant::now();
    if !(options.static_k_factor.is_finite() && options.static_k_factor > 0.0) {
        return Err(Error::invalid(
            "static_k_factor",
            format!(
                "must be a positive ratio (AASHTO 1993: 0.5), got {}",
                options.static_k_factor
            ),
        ));
    }
    let kept: Vec<&Drop> = drops.iter().filter(|d| d.drop > options.seating).collect();
    if kept.is_empty() {
        return Err(Error::invalid(
            "seating",
            format!(
                "discarding {} seating drop(s) a station leaves no drop to analyse",
                options.seating
            ),
        ));
    }
    let soil = template.foundation.as_ref().ok_or_else(|| {
        Error::invalid(
            "foundation",
            "a backcalculation's template is a physical scene: give [plate] and [foundation]",
        )
    })?;
    let subgrade_key = if soil.number("modulus").is_some() {
        "modulus"
    } else {
        "youngs_modulus"
    };
    let springs = subgrade_key == "modulus";
    let cases = Cases::new(monitor, kept.len());
    let inner = cases.inner();
    let results: Vec<DropResult> = kept
        .par_iter()
        .map(|d| -> Result<DropResult> {
            let (area, fit) = match options.method {
                BackcalcMethod::Area => {
                    let area = area_reading(template, d);
                    if area.is_none() {
                        return Err(Error::invalid(
                            d.label(),
                            "the AREA method reads interior drops with sensors at 0, 305, 610 and 914 mm on a winkler or half-space template: use --method fit for this drop",
                        ));
                    }
                    (area, None)
                }
                BackcalcMethod::Fit => {
                    let f = fit_drop(template, d, &options.fit, &inner)?;
                    (f.area, Some(f))
                }
            };
            let dynamic_k = match &fit {
                Some(f) => f.estimate(Unknown::Subgrade).map(|e| e.value),
                None => area.map(|a| a.subgrade_modulus),
            };
            cases.finish(&d.label())?;
            Ok(DropResult {
                station: d.station.clone(),
                drop: d.drop,
                location: d.location,
                load: d.basin.load,
                area,
                fit,
                static_k: dynamic_k
                    .filter(|_| springs)
                    .map(|k| k * options.static_k_factor),
            })
        })
        .collect::<Vec<Result<DropResult>>>()
        // The first error in the file's order, whichever thread met it first.
        .into_iter()
        .collect::<Result<_>>()?;
    let not_converged: Vec<String> = results
        .iter()
        .filter(|r| !r.converged())
        .map(|r| format!("station {}, drop {}", r.station, r.drop))
        .collect();
    Ok(Survey {
        method: options.method,
        discarded: drops.len() - kept.len(),
        static_k_factor: options.static_k_factor,
        subgrade_key: subgrade_key.into(),
        complete: not_converged.is_empty(),
        not_converged,
        solves: results
            .iter()
            .filter_map(|r| r.fit.as_ref().map(|f| f.solves))
            .sum(),
        drops: results,
        seconds: t0.elapsed().as_secs_f64(),
    })
}
