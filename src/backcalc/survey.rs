//! A survey: every drop of a basin file backcalculated on one template — by the AREA method
//! alone, or by the fit on liftoff's model with the AREA estimate beside it — in parallel, one
//! progress event a drop.
//!
//! **Voids by the intercept method.** At a station with drops of two or more loads, the
//! deflection under the plate is fitted by a straight line in the load (least squares); a
//! slab that bears on its soil gives a line through the origin, one over a void sags into it
//! before it bears, and the line cuts the deflection axis above the origin — by the part of the
//! gap the slab's weight had not closed before the first drop, less than the void's depth. An
//! intercept above `void_threshold` — 2 mils (50.8 µm), the AASHTO Guide's (1993, Part III)
//! criterion for corners — flags a void. The method is meant for corner and joint drops at
//! several heights; it is reported at every station with several loads.
//!
//! **Static k.** A deflectometer's load is a pulse of some 30 ms: the k a basin gives is the
//! dynamic one. The AASHTO Guide (1993, Part III, §5.4.5) divides it by 2 for the static k of
//! design; `static_k_factor` holds that 0.5 and is reported beside every k (on a soil fitted as
//! a solid, E_s is reported as fitted).

use rayon::prelude::*;

use super::area::AreaResult;
use super::basins::{Drop, Location};
use super::fit::{fit_drop, Fit, FitOptions, Unknown};
use super::template::area_reading;
use super::transfer::{load_transfer, LoadTransfer};
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
    /// The intercept above which a station's load–deflection line flags a void, m (2 mils).
    pub void_threshold: f64,
}

impl Default for SurveyOptions {
    fn default() -> Self {
        Self {
            method: BackcalcMethod::Fit,
            fit: FitOptions::default(),
            seating: 0,
            static_k_factor: 0.5,
            void_threshold: 2e-3 * crate::units::INCH,
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
    /// A joint drop's load transfer across the joint ([`load_transfer`]).
    pub load_transfer: Option<LoadTransfer>,
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

/// A station's load–deflection line: the intercept method for voids.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Intercept {
    /// The station.
    pub station: String,
    /// Where its drops were (the first drop's location).
    pub location: Location,
    /// Its drops, seating drops left out.
    pub drops: usize,
    /// The line's deflection at zero load, m.
    pub intercept: f64,
    /// The line's deflection per unit load, m/N.
    pub slope: f64,
    /// The intercept is above the threshold.
    pub void: bool,
}

/// The intercept method at every station whose drops have two loads or more (see the module's
/// description): the deflection at the sensor nearest the plate against the load.
pub fn intercepts(drops: &[&Drop], threshold: f64) -> Vec<Intercept> {
    let mut stations: Vec<&str> = Vec::new();
    for d in drops {
        if !stations.contains(&d.station.as_str()) {
            stations.push(&d.station);
        }
    }
    stations
        .into_iter()
        .filter_map(|name| {
            // Drops with a deflection at the plate (a checked drop has one).
            let at: Vec<&&Drop> = drops
                .iter()
                .filter(|d| d.station == name && !d.basin.deflections.is_empty())
                .collect();
            let n = at.len() as f64;
            let (mp, md) = at.iter().fold((0.0, 0.0), |(p, d), x| {
                (p + x.basin.load / n, d + x.basin.deflections[0] / n)
            });
            let (sxx, sxy) = at.iter().fold((0.0, 0.0), |(xx, xy), x| {
                let dp = x.basin.load - mp;
                (xx + dp * dp, xy + dp * (x.basin.deflections[0] - md))
            });
            // Two loads or more: the spread of the loads is not round-off.
            if at.len() < 2 || sxx <= (1e-9 * mp).powi(2) * n {
                return None;
            }
            let slope = sxy / sxx;
            let intercept = md - slope * mp;
            Some(Intercept {
                station: name.to_string(),
                location: at[0].location,
                drops: at.len(),
                intercept,
                slope,
                void: intercept > threshold,
            })
        })
        .collect()
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
    /// The intercept method's lines, at the stations with drops of two loads or more.
    pub intercepts: Vec<Intercept>,
    /// The intercept above which a void is flagged, m.
    pub void_threshold: f64,
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
    if !(options.void_threshold.is_finite() && options.void_threshold >= 0.0) {
        return Err(Error::invalid(
            "void_threshold",
            format!(
                "must be a deflection of 0 or more (AASHTO 1993: 2 mils, 50.8 µm), got {} m",
                options.void_threshold
            ),
        ));
    }
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
            let transfer = load_transfer(template, d, fit.as_ref(), &options.fit, &inner)?;
            cases.finish(&d.label())?;
            Ok(DropResult {
                load_transfer: transfer,
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
        intercepts: intercepts(&kept, options.void_threshold),
        void_threshold: options.void_threshold,
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
