//! Solving the paper's cases and assembling each figure's numbers; [`run`] drives it all.

use std::path::Path;
use std::time::Instant;

use super::cases::{cases, paper_penalty, Case, FOUNDATIONS};
use super::solved::Solved;
use super::{
    figures, levels, paper_quarter_elements, write_markdown, BondedComparison, FoundationAgreement,
    KeyNumbers, PaperFigure, PaperOptions, PaperParameters, PaperReport, PaperRun, DELTA,
    GAMMA_RECTANGLE, GAMMA_SQUARE, MAX_REFINE, NU, PENALTY,
};
use crate::analysis::analyse_with;
use crate::error::{Error, Result};
use crate::foundation::FoundationKind;
use crate::method::{Contact, MethodKind};
use crate::metrics::{rel_l2 as rel_rms, rel_max};
use crate::model::ConstraintPoints;
use crate::monitor::{Cases, Monitor};
use crate::output::Staged;
use crate::post::FullField;
use crate::solve::Status;

fn solve_case(
    case: &Case,
    refine: usize,
    method: MethodKind,
    cases: &Cases<'_, '_>,
) -> Result<Solved> {
    let problem = case.problem(refine, method)?;
    let t0 = Instant::now();
    let a = analyse_with(&problem, &cases.inner())?;
    let time_s = t0.elapsed().as_secs_f64();
    let s = &a.summary;
    let f = &a.report.field;
    let (sigma_min, sigma_max) = f
        .sigma
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
            (lo.min(x), hi.max(x))
        });
    // The paper's own setting: Gauss-point constraints, penalty, at its meshes.
    let (gauss_steps, gauss_contact_radius) = if refine == 1 && case.contact == Contact::Unbonded {
        let mut p = problem.clone();
        p.method = paper_penalty();
        p.model.constraint = ConstraintPoints::Gauss;
        let g = analyse_with(&p, &cases.inner())?;
        (Some(g.summary.iterations), Some(g.summary.contact_radius))
    } else {
        (None, None)
    };
    let (settled, tension_ratio) = match a.solution.status {
        Status::Converged => (true, None),
        Status::PenaltyTooWeak { tension_ratio, .. } => (true, Some(tension_ratio)),
        _ => (false, None),
    };
    let key = KeyNumbers {
        v_max: s.V_max,
        v_center: s.V_center,
        v_corner: s.V_corner,
        sigma_max,
        sigma_min,
        contact_radius: s.contact_radius,
        contact_fraction: s.contact_fraction,
        contact_extent: s.contact_extent,
        iterations: s.iterations,
        converged: s.converged,
        status: s.status.clone(),
        settled,
        tension_ratio,
        gauss_steps,
        gauss_contact_radius,
        time_s,
    };
    cases.finish(&format!(
        "Fig. {} {} {} Γ = {:.2e}, {} × {} elements: {} after {} iteration(s), contact radius {:.3}",
        case.figure,
        case.foundation.name(),
        case.contact.name(),
        case.gamma,
        s.elements[0],
        s.elements[1],
        s.status,
        s.iterations,
        s.contact_radius
    ))?;
    let run = PaperRun {
        foundation: case.foundation,
        mu: case.mu,
        gamma_index: case.gamma_index,
        gamma: case.gamma,
        contact: case.contact,
        method: s.method,
        refine,
        elements: s.elements,
        key,
    };
    Ok(Solved {
        case: *case,
        run,
        report: a.report,
    })
}

/// Whether (s, t) is in contact: inside the located contact boundary, where the bilinear
/// would-be gap is negative (see [`crate::post`]).
fn in_contact(field: &FullField, s: f64, t: f64) -> bool {
    field.interpolate(&field.signed_gap, s, t) < 0.0
}

/// Intersection over union of the contact regions of two fields of the same plate.
fn overlap(a: &FullField, b: &FullField) -> f64 {
    let n = 200;
    let (mut both, mut any) = (0usize, 0usize);
    for j in 0..n {
        for i in 0..n {
            let s = -1.0 + (2.0 * i as f64 + 1.0) / n as f64;
            let t = -1.0 + (2.0 * j as f64 + 1.0) / n as f64;
            let (ca, cb) = (in_contact(a, s, t), in_contact(b, s, t));
            both += usize::from(ca && cb);
            any += usize::from(ca || cb);
        }
    }
    if any == 0 {
        1.0
    } else {
        both as f64 / any as f64
    }
}

/// Solve the paper's cases, draw Figs. 3–7 into `out` (SVG and PNG), and write `paper.json` and
/// `paper.md`. Every file is staged and moved into `out` only when all were written. `progress`
/// receives one line per solve.
///
/// Files: `fig{3,4,5}-{halfspace,winkler}.{svg,png}` (V and σ along the centre lines, the edges
/// and the diagonal, one curve per Γ), `fig6-{halfspace,winkler}.{svg,png}` (contact regions of
/// the three Γ), `fig7-{halfspace,winkler}.{svg,png}` (bonded against unbonded), `paper.json`,
/// `paper.md`.
///
/// # Errors
/// [`Error::Invalid`] for `refine` outside 1..=[`MAX_REFINE`] or a bad `load2`; [`Error::Io`] if
/// `out` cannot be created or written; the errors of [`crate::analyse`]. A run that does not
/// converge is not an error: its `converged` is false and the tables say so.
pub fn run(options: &PaperOptions, out: &Path, monitor: &Monitor<'_>) -> Result<PaperReport> {
    if options.refine == 0 || options.refine > MAX_REFINE {
        return Err(Error::invalid(
            "refine",
            format!(
                "must lie in 1..={MAX_REFINE} (1 = the paper's meshes), got {}",
                options.refine
            ),
        ));
    }
    options.load2.check()?;
    crate::output::prepare_dir(out)?;
    let levels = levels(options.refine);
    let finest = *levels.last().unwrap_or(&1);
    let solved = solve_all(options, &levels, monitor)?;

    let mut figures: Vec<PaperFigure> = figure_meta(options)
        .into_iter()
        .map(|meta| assemble_figure(meta, &levels, &solved))
        .collect();

    // Charts from the finest level.
    let mut staged = Staged::new(out)?;
    let mut files = figures::draw(&mut figures, &solved, finest, options.load2, &mut staged)?;
    files.push("paper.json".into());
    files.push("paper.md".into());

    let report = PaperReport {
        method: options.method,
        load2: options.load2,
        load2_description: options.load2.describe(),
        refine: options.refine,
        levels,
        parameters: parameters(),
        figures,
        files,
    };
    let json = serde_json::to_string_pretty(&report)
        .map_err(|e| Error::numerical("paper.json", format!("cannot serialise: {e}")))?;
    staged.write_text("paper.json", &json)?;
    staged.write_text("paper.md", &write_markdown(&report))?;
    staged.commit()?;
    Ok(report)
}

/// Every case at every level, level by level.
fn solve_all(
    options: &PaperOptions,
    levels: &[usize],
    monitor: &Monitor<'_>,
) -> Result<Vec<Solved>> {
    let all_cases = cases(options.load2);
    // One progress event per solve, labelled with what it found.
    let counter = Cases::new(monitor, levels.len() * all_cases.len());
    let mut solved: Vec<Solved> = Vec::new();
    for &level in levels {
        for case in &all_cases {
            solved.push(solve_case(case, level, options.method, &counter)?);
        }
    }
    Ok(solved)
}

/// A figure's number, title, μ, load in words and Γ values.
type FigureMeta = (u8, &'static str, f64, String, Vec<f64>);

/// The five figures, 3 to 7.
fn figure_meta(options: &PaperOptions) -> [FigureMeta; 5] {
    let lc2_text = options.load2.describe();
    [
        (
            3,
            "square plate, load condition 1",
            1.0,
            "central point load".to_string(),
            GAMMA_SQUARE.to_vec(),
        ),
        (
            4,
            "square plate, load condition 2",
            1.0,
            lc2_text.clone(),
            GAMMA_SQUARE.to_vec(),
        ),
        (
            5,
            "rectangular plate (μ = 0.5), load condition 2",
            0.5,
            lc2_text.clone(),
            GAMMA_RECTANGLE.to_vec(),
        ),
        (
            6,
            "rectangular plate (μ = 0.5), load condition 2: contact regions",
            0.5,
            lc2_text,
            GAMMA_RECTANGLE.to_vec(),
        ),
        (
            7,
            "square plate, load condition 1, Γ = 0.25e-3: bonded and unbonded",
            1.0,
            "central point load".to_string(),
            vec![GAMMA_SQUARE[0]],
        ),
    ]
}

/// One figure's runs and comparisons (no chart files yet).
fn assemble_figure(meta: FigureMeta, levels: &[usize], solved: &[Solved]) -> PaperFigure {
    let (number, title, mu, load, gammas) = meta;
    let (foundations, bonded) = if number == 7 {
        (Vec::new(), bonded_comparisons(levels, solved))
    } else {
        let source = if number == 6 { 5 } else { number };
        (foundation_agreements(source, levels, solved), Vec::new())
    };
    PaperFigure {
        number,
        title: title.to_string(),
        mu,
        load,
        gammas,
        runs: figure_runs(number, solved),
        foundations,
        bonded,
        files: Vec::new(),
    }
}

/// The runs a figure lists, sorted by foundation, contact, Γ and level: Fig. 6 repeats Fig. 5,
/// Fig. 7 has its bonded runs and the unbonded Γ_1 runs of Fig. 3.
fn figure_runs(number: u8, solved: &[Solved]) -> Vec<PaperRun> {
    let source = if number == 6 { 5 } else { number };
    let runs_of = |pred: &dyn Fn(&Solved) -> bool| -> Vec<&Solved> {
        solved.iter().filter(|s| pred(s)).collect()
    };
    let mut runs: Vec<PaperRun> = if number == 7 {
        runs_of(&|s| {
            (s.case.figure == 7)
                || (s.case.figure == 3
                    && s.case.gamma_index == 1
                    && s.case.contact == Contact::Unbonded)
        })
        .into_iter()
        .map(|s| s.run.clone())
        .collect()
    } else {
        runs_of(&|s| s.case.figure == source)
            .into_iter()
            .map(|s| s.run.clone())
            .collect()
    };
    runs.sort_by(|a, b| {
        (
            a.foundation.name(),
            a.contact.name(),
            a.gamma_index,
            a.refine,
        )
            .cmp(&(
                b.foundation.name(),
                b.contact.name(),
                b.gamma_index,
                b.refine,
            ))
    });
    runs
}

/// Figs. 3–6: half-space against Winkler at equal Γ, per level and Γ, from the runs of figure
/// `source`.
fn foundation_agreements(
    source: u8,
    levels: &[usize],
    solved: &[Solved],
) -> Vec<FoundationAgreement> {
    let mut foundations = Vec::new();
    for &level in levels {
        for k in 1..=3 {
            let pick = |foundation: FoundationKind| {
                solved.iter().find(|s| {
                    s.case.figure == source
                        && s.case.foundation == foundation
                        && s.case.gamma_index == k
                        && s.run.refine == level
                })
            };
            if let (Some(h), Some(w)) = (
                pick(FoundationKind::HalfSpace),
                pick(FoundationKind::Winkler),
            ) {
                foundations.push(FoundationAgreement {
                    gamma_index: k,
                    gamma: h.case.gamma,
                    refine: level,
                    radius_half_space: h.run.key.contact_radius,
                    radius_winkler: w.run.key.contact_radius,
                    overlap: overlap(&h.report.field, &w.report.field),
                });
            }
        }
    }
    foundations
}

/// Fig. 7: the bonded runs against the unbonded Γ_1 runs of Fig. 3, per level and foundation.
fn bonded_comparisons(levels: &[usize], solved: &[Solved]) -> Vec<BondedComparison> {
    let mut bonded = Vec::new();
    for &level in levels {
        for foundation in FOUNDATIONS {
            let pick = |contact: Contact, fig: u8| {
                solved.iter().find(|s| {
                    s.case.figure == fig
                        && s.case.foundation == foundation
                        && s.case.gamma_index == 1
                        && s.case.contact == contact
                        && s.run.refine == level
                })
            };
            if let (Some(b), Some(u)) = (pick(Contact::Bonded, 7), pick(Contact::Unbonded, 3)) {
                let (fb, fu) = (&b.report.field, &u.report.field);
                bonded.push(BondedComparison {
                    foundation,
                    refine: level,
                    v_max_bonded: b.run.key.v_max,
                    v_max_unbonded: u.run.key.v_max,
                    v_corner_bonded: b.run.key.v_corner,
                    v_corner_unbonded: u.run.key.v_corner,
                    sigma_max_bonded: b.run.key.sigma_max,
                    sigma_max_unbonded: u.run.key.sigma_max,
                    sigma_min_bonded: b.run.key.sigma_min,
                    v_max_difference: rel_max(&fb.v, &fu.v),
                    sigma_max_difference: rel_max(&fb.sigma, &fu.sigma),
                    v_rms_difference: rel_rms(&fb.v, &fu.v),
                    sigma_rms_difference: rel_rms(&fb.sigma, &fu.sigma),
                });
            }
        }
    }
    bonded
}

/// The paper's fixed parameters as [`run`] uses them.
fn parameters() -> PaperParameters {
    PaperParameters {
        nu: NU,
        delta: DELTA,
        penalty: PENALTY,
        constraint: "nodal".into(),
        gamma_square: GAMMA_SQUARE,
        gamma_rectangle: GAMMA_RECTANGLE,
        quarter_elements_half_space: paper_quarter_elements(FoundationKind::HalfSpace),
        quarter_elements_winkler: paper_quarter_elements(FoundationKind::Winkler),
        rectangle_mesh: "same element counts as the square plate (uniform mesh in (s, t); \
                         elements twice as long as wide)"
            .into(),
    }
}
