//! Files of the method studies: eps_sweep.csv/.svg, tradeoff.csv/.svg, stability.csv and one
//! stability map per method. All files of a study are staged and moved into place together.

use std::path::{Path, PathBuf};

use super::chart::{self, Series};
use super::Staged;
use crate::error::{Error, Result};
use crate::method::MethodKind;
use crate::study::{StabilityRow, Sweep, Tradeoff};

fn csv_text<T: serde::Serialize>(rows: &[T]) -> Result<String> {
    let mut w = csv::Writer::from_writer(Vec::new());
    for r in rows {
        w.serialize(r)
            .map_err(|e| Error::numerical("csv", e.to_string()))?;
    }
    let bytes = w
        .into_inner()
        .map_err(|e| Error::numerical("csv", e.to_string()))?;
    String::from_utf8(bytes).map_err(|e| Error::numerical("csv", e.to_string()))
}

/// eps_sweep.csv and eps_sweep.svg (relative L2 error of σ and V against ε̄, log–log, with the
/// fitted slopes).
pub fn write_sweep(dir: &Path, sweep: &Sweep, title: &str) -> Result<Vec<PathBuf>> {
    let mut st = Staged::new(dir)?;
    st.write_text("eps_sweep.csv", &csv_text(&sweep.rows)?)?;
    let mut series = Vec::new();
    let mut notes = Vec::new();
    for (kind, slope, range) in &sweep.slopes {
        let rows: Vec<_> = sweep
            .rows
            .iter()
            .filter(|r| r.constraint == *kind)
            .collect();
        series.push(Series {
            name: format!("σ, {kind} constraints"),
            points: rows.iter().map(|r| (r.eps, r.rel_l2_sigma)).collect(),
            line: true,
            markers: true,
        });
        series.push(Series {
            name: format!("V, {kind} constraints"),
            points: rows.iter().map(|r| (r.eps, r.rel_l2_v)).collect(),
            line: true,
            markers: true,
        });
        notes.push(match slope {
            Some(s) => format!(
                "{kind}: fitted slope {s:.3} for ε̄ in [{:.0e}, {:.0e}] (first order = 1)",
                range[0], range[1]
            ),
            None => format!("{kind}: too few converged points to fit a slope"),
        });
    }
    let p = st.path("eps_sweep.svg");
    chart::write_loglog_svg(
        &p,
        title,
        "penalty ε̄",
        "relative L2 error against the QP",
        &series,
        &notes,
        true,
    )?;
    st.commit()
}

/// tradeoff.csv and tradeoff.svg (wall time against error, one series per method, Pareto front).
pub fn write_tradeoff(dir: &Path, t: &Tradeoff, title: &str) -> Result<Vec<PathBuf>> {
    let mut st = Staged::new(dir)?;
    st.write_text("tradeoff.csv", &csv_text(&t.points)?)?;
    let ok = |m: MethodKind| {
        t.points
            .iter()
            .filter(|p| p.method == m && p.converged)
            .map(|p| (p.time_s, p.error))
            .collect::<Vec<_>>()
    };
    let mut front: Vec<(f64, f64)> = t
        .points
        .iter()
        .filter(|p| p.pareto)
        .map(|p| (p.time_s, p.error))
        .collect();
    front.sort_by(|a, b| a.0.total_cmp(&b.0));
    let series = vec![
        Series {
            name: "penalty (each mesh × ε̄)".into(),
            points: ok(MethodKind::Penalty),
            line: false,
            markers: true,
        },
        Series {
            name: "QP (each mesh)".into(),
            points: ok(MethodKind::Qp),
            line: false,
            markers: true,
        },
        Series {
            name: "Pareto front".into(),
            points: front,
            line: true,
            markers: false,
        },
    ];
    let notes = vec![format!(
        "error: RMS of V − V_ref over a 21 × 21 grid / RMS of V_ref; reference {}",
        t.reference
    )];
    let p = st.path("tradeoff.svg");
    chart::write_loglog_svg(
        &p,
        title,
        "wall time (s): assembly + solve",
        "error in V",
        &series,
        &notes,
        false,
    )?;
    st.commit()
}

fn short(v: f64) -> String {
    if v == 0.0 {
        "0".into()
    } else if (0.01..1000.0).contains(&v.abs()) {
        format!("{v}")
    } else {
        format!("{v:.0e}")
    }
}

/// stability.csv and stability-penalty.svg / stability-qp.svg: one map per method, a row per
/// (foundation, swept parameter), a cell per value coloured by the outcome.
pub fn write_stability(dir: &Path, rows: &[StabilityRow], title: &str) -> Result<Vec<PathBuf>> {
    let mut st = Staged::new(dir)?;
    st.write_text("stability.csv", &csv_text(rows)?)?;
    for method in [MethodKind::Penalty, MethodKind::Qp] {
        let mine: Vec<&StabilityRow> = rows.iter().filter(|r| r.method == method).collect();
        let mut row_keys: Vec<(&str, &str)> = Vec::new();
        for r in &mine {
            if !row_keys.contains(&(r.foundation.name(), r.sweep.name())) {
                row_keys.push((r.foundation.name(), r.sweep.name()));
            }
        }
        let cols = row_keys
            .iter()
            .map(|k| {
                mine.iter()
                    .filter(|r| (r.foundation.name(), r.sweep.name()) == *k)
                    .count()
            })
            .max()
            .unwrap_or(0);
        let mut cells = Vec::new();
        for (ri, k) in row_keys.iter().enumerate() {
            for (ci, r) in mine
                .iter()
                .filter(|r| (r.foundation.name(), r.sweep.name()) == *k)
                .enumerate()
            {
                let text = if r.outcome == crate::study::RunOutcome::CONVERGED {
                    format!("{} ({})", short(r.value), r.iterations)
                } else {
                    short(r.value)
                };
                cells.push((ri, ci, r.outcome.name().to_string(), text));
            }
        }
        let row_labels: Vec<String> = row_keys.iter().map(|(f, s)| format!("{f}: {s}")).collect();
        let col_labels: Vec<String> = (1..=cols).map(|c| c.to_string()).collect();
        let p = st.path(&format!("stability-{method}.svg"));
        chart::write_category_map_svg(
            &p,
            &format!("{title} — {method} (cell: value (iterations))"),
            "sweep step",
            "foundation: swept parameter",
            &col_labels,
            &row_labels,
            &cells,
        )?;
    }
    st.commit()
}
