//! What the command line prints for the studies: `compare`, `eps-sweep`, `tradeoff`,
//! `stability` (their files are written by [`super::studies`]).

use std::path::Path;

use super::tables::text;
use crate::compare::Comparison;
use crate::output::Summary;
use crate::study::{StabilityRow, Sweep, Tradeoff};

/// The table of `liftoff compare`: both methods side by side, their differences, and where
/// compare.json was written.
pub fn compare_table(c: &Comparison, written: &Path) -> String {
    let (p, q) = (&c.penalty, &c.qp);
    let mut l = vec![format!("liftoff compare — {}", p.title)];
    l.push(format!(
        "  model: {} {} × {} elements ({} pressure nodes), {} foundation, ε̄ = {:e}, {} constraints, assembled once in {:.3} s",
        p.symmetry, p.model_elements[0], p.model_elements[1], p.nodes, p.foundation, p.dimensionless.penalty.unwrap_or(f64::NAN), p.constraint, c.assemble_s
    ));
    l.push(format!("  {:<22} {:>16} {:>16}", "", "penalty", "qp"));
    type Cell = fn(&Summary) -> String;
    let rows: [(&str, Cell); 11] = [
        ("status", |x| {
            if x.converged {
                "converged"
            } else {
                "NOT converged"
            }
            .to_string()
        }),
        ("iterations", |x| x.iterations.to_string()),
        ("solve time (s)", |x| format!("{:.4}", x.time_s.solve)),
        ("V_max", |x| format!("{:.6e}", x.V_max)),
        ("contact fraction", |x| format!("{:.4}", x.contact_fraction)),
        ("contact radius", |x| format!("{:.4}", x.contact_radius)),
        ("extent x", |x| format!("{:.4}", x.contact_extent.x)),
        ("extent y", |x| format!("{:.4}", x.contact_extent.y)),
        ("extent diagonal", |x| {
            format!("{:.4}", x.contact_extent.diagonal)
        }),
        ("min σ", |x| {
            format!("{:.2e}", x.complementarity.min_pressure)
        }),
        ("max |σ·gap|", |x| {
            format!("{:.2e}", x.complementarity.max_product)
        }),
    ];
    for (name, cell) in rows {
        l.push(format!("  {name:<22} {:>16} {:>16}", cell(p), cell(q)));
    }
    let d = &c.differences;
    l.push(format!(
        "  max |Δσ| = {:.3e} ({:.2e} of max σ), max |ΔV| = {:.3e} ({:.2e} of max V), contact differs at {} node(s)",
        d.max_abs_sigma, d.rel_sigma, d.max_abs_v, d.rel_v, d.contact_nodes_differing
    ));
    l.push(format!("  written: {}", written.display()));
    text(l)
}

/// The table of `liftoff eps-sweep`: one row per (constraint kind, ε̄), the fitted slopes, and
/// where the files went.
pub fn eps_sweep_table(title: &str, sweep: &Sweep, dir: &Path) -> String {
    let mut l = vec![format!("liftoff eps-sweep — {title}")];
    l.push(format!(
        "  {:<6} {:>9} {:>5} {:>17} {:>11} {:>11} {:>11} {:>9}",
        "points", "ε̄", "steps", "status", "L2 err σ", "L2 err V", "min σ", "time (s)"
    ));
    for r in &sweep.rows {
        l.push(format!(
            "  {:<6} {:>9.1e} {:>5} {:>17} {:>11.3e} {:>11.3e} {:>11.2e} {:>9.4}",
            r.constraint,
            r.eps,
            r.iterations,
            r.status,
            r.rel_l2_sigma,
            r.rel_l2_v,
            r.min_pressure,
            r.time_s
        ));
    }
    for (k, s, range) in &sweep.slopes {
        l.push(match s {
            Some(s) => format!(
                "  {k}: fitted slope {s:.3} over ε̄ ∈ [{:.0e}, {:.0e}], down to where the error flattens (first order: 1)",
                range[0], range[1]
            ),
            None => format!("  {k}: too few settled points to fit a slope"),
        });
    }
    l.push(format!(
        "  written: eps_sweep.csv, eps_sweep.svg in {}",
        dir.display()
    ));
    text(l)
}

/// The table of `liftoff tradeoff`: the reference, one row per (method, mesh, ε̄) with a `*` on
/// the Pareto front, and where the files went.
pub fn tradeoff_table(title: &str, t: &Tradeoff, dir: &Path) -> String {
    let mut l = vec![format!("liftoff tradeoff — {title}")];
    l.push(format!("  reference: {}", t.reference));
    l.push(format!(
        "  {:<8} {:>5} {:>9} {:>10} {:>11} {:>17} {:>7}",
        "method", "mesh", "ε̄", "time (s)", "error V", "status", "Pareto"
    ));
    for p in &t.points {
        l.push(format!(
            "  {:<8} {:>5} {:>9.0e} {:>10.4} {:>11.3e} {:>17} {:>7}",
            p.method,
            p.mesh,
            p.eps,
            p.time_s,
            p.error,
            p.status,
            if p.pareto { "*" } else { "" }
        ));
    }
    l.push(format!(
        "  written: tradeoff.csv, tradeoff.svg in {}",
        dir.display()
    ));
    text(l)
}

/// The table of `liftoff stability`: every run that did not converge, with its outcome and
/// detail, then the count and where the files went.
pub fn stability_table(rows: &[StabilityRow], dir: &Path) -> String {
    let mut l = vec![format!("liftoff stability — {} runs", rows.len())];
    let failed: Vec<&StabilityRow> = rows
        .iter()
        .filter(|r| r.outcome != crate::study::RunOutcome::CONVERGED)
        .collect();
    for r in &failed {
        l.push(format!(
            "  {:<10} {:<8} {:<7} {:>9.2e}: {} — {}",
            r.foundation,
            // The name, not the value: `Display` of the named enums ignores the width.
            r.sweep.name(),
            r.method,
            r.value,
            r.outcome,
            r.detail
        ));
    }
    l.push(format!(
        "  {} of {} runs did not converge (listed above); written: stability.csv, stability-penalty.svg, stability-qp.svg in {}",
        failed.len(),
        rows.len(),
        dir.display()
    ));
    text(l)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::method::MethodKind;
    use crate::solve::StatusKind;
    use crate::study::{RunOutcome, StabilityParam, TradeoffPoint};

    fn row(
        sweep: StabilityParam,
        method: MethodKind,
        value: f64,
        outcome: RunOutcome,
    ) -> StabilityRow {
        StabilityRow {
            sweep,
            foundation: crate::foundation::FoundationKind::Winkler,
            method,
            value,
            outcome,
            iterations: 3,
            equilibrium: 0.0,
            min_pressure: 0.0,
            min_gap: 0.0,
            contact_fraction: 0.5,
            time_s: 0.1,
            detail: "why".into(),
        }
    }

    /// Only the runs that did not converge are listed, in columns padded to 10, 8 and 7
    /// characters and a value right-aligned in 9 (expected text written out by hand).
    #[test]
    fn stability_table_lists_failures_in_aligned_columns() {
        let rows = [
            row(
                StabilityParam::Gamma,
                MethodKind::Penalty,
                1e-6,
                RunOutcome::Solved(StatusKind::PenaltyTooWeak),
            ),
            row(
                StabilityParam::Mu,
                MethodKind::Qp,
                0.5,
                RunOutcome::CONVERGED,
            ),
            row(
                StabilityParam::Mesh,
                MethodKind::Qp,
                256.0,
                RunOutcome::Failed(crate::error::ErrorKind::TooLarge),
            ),
        ];
        let want = "liftoff stability — 3 runs\n\
            \x20 winkler    gamma    penalty   1.00e-6: penalty-too-weak — why\n\
            \x20 winkler    mesh     qp         2.56e2: too-large — why\n\
            \x20 2 of 3 runs did not converge (listed above); written: stability.csv, stability-penalty.svg, stability-qp.svg in out\n";
        assert_eq!(
            stability_table(&rows, Path::new("out")),
            want,
            "stability_table"
        );
    }

    /// The QP has no ε̄ (NaN) and the Pareto column is a star or blank.
    #[test]
    fn tradeoff_table_marks_the_pareto_front() {
        let point = |method, eps, pareto| TradeoffPoint {
            method,
            mesh: 8,
            eps,
            time_s: 0.25,
            error: 0.125,
            converged: true,
            status: RunOutcome::CONVERGED,
            pareto,
        };
        let t = Tradeoff {
            points: vec![
                point(MethodKind::Qp, f64::NAN, true),
                point(MethodKind::Penalty, 1e-5, false),
            ],
            reference: "QP on 16".into(),
        };
        let want = "liftoff tradeoff — T\n\
            \x20 reference: QP on 16\n\
            \x20 method    mesh        ε̄   time (s)     error V            status  Pareto\n\
            \x20 qp           8       NaN     0.2500    1.250e-1         converged       *\n\
            \x20 penalty      8      1e-5     0.2500    1.250e-1         converged        \n\
            \x20 written: tradeoff.csv, tradeoff.svg in d\n";
        assert_eq!(
            tradeoff_table("T", &t, Path::new("d")),
            want,
            "tradeoff_table"
        );
    }
}
