//! Tables: the CSV files of a solve (nodes, element resultants, profiles) and the text tables
//! the commands print (solve, compare, eps-sweep, tradeoff, stability). The text tables are
//! returned as strings, each line ending in a newline; printing is the caller's.

use std::path::Path;

use crate::error::{Error, Result};
use crate::model::LoadReference;
use crate::output::chart::Units;
use crate::output::Summary;
use crate::post::{ElementField, FullField, Profile};
use crate::units::{Measure, UnitSystem};

fn csv_err(path: &Path, e: csv::Error) -> Error {
    Error::Io {
        path: path.display().to_string(),
        source: std::io::Error::other(e.to_string()),
    }
}

/// nodes.csv: x,y,s,t,w,psi_x,psi_y,pressure,gap,V,sigma,s1_bottom,s1_top,contact (whole plate:
/// on a shaped plate the nodes of its cells only), each header with its unit (`w [in]`); `f` in
/// the units of `system` ([`FullField::in_units`]).
pub fn write_nodes(path: &Path, f: &FullField, system: Option<UnitSystem>) -> Result<()> {
    let columns = f.columns();
    let mut header: Vec<String> = columns
        .iter()
        .map(|(name, m, _)| m.header(name, system))
        .collect();
    header.push(Measure::Number.header("contact", system));
    let on = f.node_on_plate();
    let rows = (0..f.x.len()).filter(|&i| on[i]).map(|i| {
        let mut rec: Vec<String> = columns
            .iter()
            .map(|(_, _, c)| format!("{:.12e}", c[i]))
            .collect();
        rec.push(if f.contact[i] { "1" } else { "0" }.to_string());
        rec
    });
    write_csv(path, &header, rows)
}

/// elements.csv: x,y,mx,my,mxy,qx,qy and the faces' stresses (sx_bottom … angle_top) at element
/// centres (on a shaped plate its cells only: `plate`, [`FullField::plate`], empty for all),
/// each header with its unit; `e` in the units of `system`.
pub fn write_elements(
    path: &Path,
    e: &ElementField,
    plate: &[bool],
    system: Option<UnitSystem>,
) -> Result<()> {
    let columns = e.columns();
    let header: Vec<String> = columns
        .iter()
        .map(|(name, m, _)| m.header(name, system))
        .collect();
    let on = |i: usize| plate.get(i).copied().unwrap_or(true);
    let rows = (0..e.x.len()).filter(move |&i| on(i)).map(|i| {
        columns
            .iter()
            .map(|(_, _, c)| format!("{:.12e}", c[i]))
            .collect()
    });
    write_csv(path, &header, rows)
}

/// A CSV file from its header and rows of formatted cells.
fn write_csv(
    path: &Path,
    header: &[String],
    rows: impl Iterator<Item = Vec<String>>,
) -> Result<()> {
    let mut w = csv::Writer::from_path(path).map_err(|e| csv_err(path, e))?;
    w.write_record(header).map_err(|e| csv_err(path, e))?;
    for rec in rows {
        w.write_record(&rec).map_err(|e| csv_err(path, e))?;
    }
    w.flush().map_err(|e| Error::Io {
        path: path.display().to_string(),
        source: e,
    })
}

/// profiles.csv: line,coord,s,t,V,sigma — dimensionless, each header with its unit `[-]`.
pub fn write_profiles(path: &Path, profiles: &[Profile]) -> Result<()> {
    let mut w = csv::Writer::from_path(path).map_err(|e| csv_err(path, e))?;
    w.write_record(["line", "coord [-]", "s [-]", "t [-]", "V [-]", "sigma [-]"])
        .map_err(|e| csv_err(path, e))?;
    for p in profiles {
        for q in &p.points {
            w.write_record([
                p.line.to_string(),
                format!("{:.12e}", q.coord),
                format!("{:.12e}", q.s),
                format!("{:.12e}", q.t),
                format!("{:.12e}", q.v),
                format!("{:.12e}", q.sigma),
            ])
            .map_err(|e| csv_err(path, e))?;
        }
    }
    w.flush().map_err(|e| Error::Io {
        path: path.display().to_string(),
        source: e,
    })
}

/// Lines of a text table, joined with a newline after each.
pub(super) fn text(lines: Vec<String>) -> String {
    let mut out = String::new();
    for l in lines {
        out.push_str(&l);
        out.push('\n');
    }
    out
}

/// The sign convention, printed under every solve table.
pub const SIGN_CONVENTION: &str = "Sign convention: deflection w and loads are positive downward (into the soil), pressure is positive in compression, and a positive gap means the plate has lifted off the soil.";

/// The surface-stress line of the solve table: the largest tension at the bottom and the top
/// face, where, and σ₁'s direction.
fn stress_line(s: &Summary, units: &Units) -> String {
    let st = units.stress();
    let at = |p: &crate::post::stress::PeakTension| {
        if units.is_physical() {
            let l = units.length();
            format!("({:.2}, {:.2}) {}", l.apply(p.x), l.apply(p.y), l.unit)
        } else {
            format!("(s, t) = ({:.3}, {:.3})", p.x, p.y / s.dimensionless.mu)
        }
    };
    let face = |p: &crate::post::stress::PeakTension| {
        if p.value > 0.0 {
            format!(
                "{:.3} {} at {} ({:.0}°)",
                st.apply(p.value),
                st.unit,
                at(p),
                p.angle
            )
        } else {
            format!("no tension (σ₁ ≤ {:.3} {})", st.apply(p.value), st.unit)
        }
    };
    format!(
        "  stress     : bottom max tension {}, top {}; σ = ±6m/H², tension positive",
        face(&s.stresses.bottom),
        face(&s.stresses.top)
    )
}

/// The table of `liftoff solve`: model, method, status, penalty history, timings, results —
/// in engineering units for a scene given in SI (deflections in mm, pressure in kPa, moments in
/// kN·m/m, forces in kN, contact area, radius and extents in m² and m), in the paper's V, σ and
/// fractions of L for a dimensionless one — and residuals (dimensionless: they measure the
/// solver); then `files` (how many were written, and where) if any, and the sign convention.
pub fn solve_table(s: &Summary, files: Option<(usize, &Path)>) -> String {
    // A solve that did not converge writes no files: `files` is not shown for it.
    let g = &s.dimensionless;
    let mut l = vec![format!("liftoff — {}", s.title)];
    // The soil's own groups.
    let own = g.soil.describe(g.gamma, g.mu);
    l.push(format!(
        "  foundation : {} (Γ = {:.4e}{own}, Δ = {:.4e}, μ = {:.4}, ν = {})",
        s.foundation, g.gamma, g.delta, g.mu, g.nu
    ));
    l.push(format!(
        "  model      : {} model, {} × {} of {} × {} elements, {} nodes, {} dofs",
        s.symmetry,
        s.model_elements[0],
        s.model_elements[1],
        s.elements[0],
        s.elements[1],
        s.nodes,
        s.dofs
    ));
    for n in &s.notes {
        l.push(format!("  note       : {n}"));
    }
    let method = if s.contact == crate::method::Contact::Bonded {
        "bonded, direct solve".to_string()
    } else {
        match s.qp_solver {
            Some(q) => format!("unbonded, qp by {q} ({} constraints)", s.constraint),
            None => format!("unbonded, {} ({} constraints)", s.method, s.constraint),
        }
    };
    l.push(format!("  contact    : {method}"));
    l.push(format!(
        "  status     : {} after {} step(s)",
        s.status, s.iterations
    ));
    // clarabel's diagnostics (the QP); the iterative route adds only `cg_iterations`.
    if s.solver_info.contains_key("primal_residual") {
        let get = |k: &str| s.solver_info.get(k).copied().unwrap_or(f64::NAN);
        l.push(format!(
            "  clarabel   : primal residual {:.1e}, dual residual {:.1e}, duality gap {:.1e}",
            get("primal_residual"),
            get("dual_residual"),
            get("duality_gap")
        ));
    }
    if s.qp_solver == Some(crate::method::QpSolver::ActiveSet) {
        let get = |k: &str| s.solver_info.get(k).copied().unwrap_or(f64::NAN);
        l.push(format!(
            "  QP solver  : matrix-free active set, {:.0} face solves, {:.0} CG iterations, {:.0} products with S, {:.0} factorisations",
            get("outer_iterations"),
            get("cg_iterations"),
            get("schur_products"),
            get("factorisations")
        ));
        let safeguard = get("safeguard_steps");
        if safeguard > 0.0 {
            l.push(format!(
                "  safeguard  : the primal–dual sets cycled; {safeguard:.0} of the face solves by the monotone primal active set ({:.0} cut by its ratio test)",
                get("projected_steps")
            ));
        }
        l.push(format!(
            "  KKT        : natural residual {:.1e} (gap {:.1e}, penetration {:.1e}, σ·gap {:.1e}), equilibrium {:.1e}",
            get("kkt_natural"),
            get("kkt_stationarity"),
            get("kkt_penetration"),
            get("kkt_complementarity"),
            get("kkt_equilibrium")
        ));
    } else if let Some(n) = s.solver_info.get("cg_iterations") {
        l.push(format!(
            "  linear     : iterative route (T by FFT), {n:.0} conjugate-gradient iterations in all"
        ));
    }
    if !s.penalty_stages.is_empty() {
        let stages: Vec<String> = s
            .penalty_stages
            .iter()
            .map(|st| format!("{:.0e} ({} steps, {})", st.epsilon, st.steps, st.outcome))
            .collect();
        l.push(format!("  ε̄          : {}", stages.join(" → ")));
    }
    let qp = s.qp_solver.is_some();
    if !s.history.is_empty() {
        l.push(if qp {
            "  active-set iterations (points at zero pressure after each face solve; min σ of its solution):".into()
        } else {
            "  penalty iterations (constraint points in the penalised, lifted set):".into()
        });
        for it in &s.history {
            // The iterative route adds the conjugate-gradient count and final residual.
            let cg = it.cg.map_or(String::new(), |c| {
                format!(", CG {:>4} it. (residual {:.1e})", c.iterations, c.residual)
            });
            l.push(format!(
                "    step {:>3}: {:>6} {}, {:>6} entered, {:>6} left, min σ {:.3e}{cg}",
                it.step,
                it.penalised,
                if qp { "lifted" } else { "penalised" },
                it.entered,
                it.left,
                it.min_pressure * g.mu
            ));
        }
    }
    l.push(format!(
        "  time       : assemble {:.3} s, solve {:.3} s, total {:.3} s",
        s.time_s.assemble, s.time_s.solve, s.time_s.total
    ));
    let r = &s.resultant;
    if !s.converged {
        // A solve that did not converge has no result: its last iterate's deflection, pressure
        // and stresses are not a solution, so only the diagnosis is shown (the status and
        // history above, the residuals here).
        let c = &s.complementarity;
        l.push(
            "  result     : none — the solve did not converge, and its last iterate is not a solution (no deflection, pressure or stress is shown)"
                .into(),
        );
        l.push(format!(
            "  residuals  : equilibrium {:.2e} (relative), min σ {:.2e}, min gap {:.2e}, max |σ·gap| {:.2e}",
            r.relative_error, c.min_pressure, c.min_gap, c.max_product
        ));
        return text(l);
    }
    let units = Units::new(s.physical, g.mu);
    if g.reference != LoadReference::NetLoad {
        // The force in the scene's own unit (N, lbf): the kN of the tables' forces would
        // round the small reference of a curling scene away.
        let (factor, unit) = match s.physical.map(|p| p.units) {
            Some(system) => (
                crate::units::Quantity::Force.from_si(system, 1.0),
                format!(" {}", crate::units::Quantity::Force.unit(system)),
            ),
            None => (1.0, String::new()),
        };
        l.push(format!(
            "  reference  : {}; P = {:.4e}{unit}",
            g.reference.describe(),
            g.reference_force * factor
        ));
    }
    let e = &s.contact_extent;
    if units.is_physical() {
        // Engineering units; the dimensionless V and σ stay in summary.json.
        let (defl, pres, mom, force) = (
            units.deflection(),
            units.pressure(),
            units.moment(),
            units.force(),
        );
        // A shaped plate may have no plate at the centre or the corner (NaN in summary.json).
        let at = |v: f64| match v.is_finite() {
            true => format!("{:.3} {}", units.from_v(v), defl.unit),
            false => "off the plate".to_string(),
        };
        l.push(format!(
            "  deflection : max {:.3} {}, centre {}, corner {} (downward)",
            defl.apply(s.w_max),
            defl.unit,
            at(s.V_center),
            at(s.V_corner),
        ));
        l.push(format!(
            "  pressure   : nodal peak {:.1} {}{}",
            pres.apply(s.pressure_max),
            pres.unit,
            if crate::post::average::edge_singularity(s.foundation).is_some() {
                " (at the plate's edge it depends on the mesh: see the note)"
            } else {
                ""
            }
        ));
        l.push(format!(
            "  moments    : mx {:.1} … {:.1} {u}, my {:.1} … {:.1} {u} (positive: tension on the soil side)",
            mom.apply(s.moments.mx[0]),
            mom.apply(s.moments.mx[1]),
            mom.apply(s.moments.my[0]),
            mom.apply(s.moments.my[1]),
            u = mom.unit
        ));
        l.push(stress_line(s, &units));
        l.push(format!(
            "  resultant  : load {:.2} {u}, reaction {:.2} {u} (relative error {:.1e})",
            force.apply(r.load),
            force.apply(r.reaction),
            r.relative_error,
            u = force.unit
        ));
        // Plate area 2L × 2μL (times the shaped plate's share of it); extents are fractions of
        // L, μL and the half-diagonal.
        let mu = g.mu;
        let plate_area = units.from_l(2.0) * units.from_l(2.0 * mu);
        // The plan area in the area unit (m², ft²) from the lengths' (m, in).
        let (len, area) = (units.length(), units.area());
        let plate_area = plate_area / (len.factor * len.factor) * area.factor * s.plate_fraction;
        l.push(format!(
            "  contact    : {:.1} % of the plate ({:.2} {a}), radius {:.2} {u}, extent x {:.2} {u}, y {:.2} {u}, diagonal {:.2} {u} from the centre",
            100.0 * s.contact_fraction,
            s.contact_fraction * plate_area,
            units.from_l(s.contact_radius),
            units.from_l(e.x),
            units.from_l(mu * e.y),
            units.from_l((1.0 + mu * mu).sqrt() * e.diagonal),
            a = area.unit,
            u = len.unit,
        ));
    } else {
        l.push(format!(
            "  resultant  : load {:.6} P, reaction {:.6} P (relative error {:.1e})",
            r.load, r.reaction, r.relative_error
        ));
        // A shaped plate may have no plate at the centre or the corner (NaN in summary.json).
        let at = |v: f64| match v.is_finite() {
            true => format!("{v:.5e}"),
            false => "off the plate".to_string(),
        };
        l.push(format!(
            "  V          : max {:.5e}, centre {}, corner {}  (V = D w / (P L²))",
            s.V_max,
            at(s.V_center),
            at(s.V_corner)
        ));
        l.push(stress_line(s, &units));
        l.push(format!(
            "  contact    : {:.1} % of the plate, radius {:.3} L, extent x {:.3}, y {:.3}, diagonal {:.3}",
            100.0 * s.contact_fraction,
            s.contact_radius,
            e.x,
            e.y,
            e.diagonal
        ));
    }
    l.extend(crate::output::joints::joint_lines(&s.joints, &units));
    if let Some(b) = &s.bearing {
        // Dimensionless scenes show σ = μ r, as the contact map does.
        let (scale, unit, area, len_unit, len_f, area_f) = if s.physical.is_some() {
            let (p, a, l) = (units.pressure(), units.area(), units.length());
            (p.factor, p.unit, a.unit, l.unit, l.factor, a.factor)
        } else {
            (g.mu, "(σ)", "L²", "L", 1.0, 1.0)
        };
        l.push(format!(
            "  bearing    : averaged over {:.3} {len_unit} squares {:.3} of {:.3} {unit} allowed (square centred at ({:.3}, {:.3}) {len_unit}), utilisation {:.0} %{}",
            b.length * len_f,
            b.average * scale,
            b.allowable * scale,
            b.average_at[0] * len_f,
            b.average_at[1] * len_f,
            100.0 * b.utilisation,
            if b.utilisation > 1.0 { " — EXCEEDED" } else { "" }
        ));
        l.push(format!(
            "               nodal peak {:.3} {unit} ({:.0} % of the allowable), {:.3} {area} ({:.1} % of the plate) above the allowable",
            b.max * scale,
            100.0 * b.nodal_utilisation,
            b.area_exceeding * area_f,
            100.0 * b.fraction_exceeding,
        ));
    }
    let c = &s.complementarity;
    l.push(format!(
        "  residuals  : min σ {:.2e}, min gap {:.2e}, max |σ·gap| {:.2e}",
        c.min_pressure, c.min_gap, c.max_product
    ));
    if let Some((n, dir)) = files {
        l.push(format!("  files      : {n} in {}", dir.display()));
    }
    l.push(String::new());
    l.push(SIGN_CONVENTION.into());
    text(l)
}
