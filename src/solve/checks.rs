//! The checks every method's input and output pass: a load a tensionless foundation can hold,
//! a reaction that balances it, and the discrete gap the methods share.

use super::linalg;
use super::projection::{cone_gap, project};
use super::solution::Solution;
use crate::error::{Error, Result};
use crate::model::ConstraintPoints;
use crate::operators::Operators;

/// Largest relative equilibrium error accepted: |∫σ − ∫q| / |∫q|. Well-posed problems reach
/// 1e-12; thin plates on soft soil lose a few digits to K's row-sum round-off (≈ 1e-9 for
/// H = ℓ/100); beyond 1e-6 the linear algebra has broken down.
pub const EQUILIBRIUM_TOLERANCE: f64 = 1e-6;

/// Refuse a solution whose reaction does not balance the load.
pub fn check_equilibrium(ops: &Operators, sol: &Solution) -> Result<()> {
    let areas = crate::foundation::nodal_areas(&ops.mesh);
    let reaction: f64 = sol.sigma.iter().zip(&areas).map(|(s, a)| s * a).sum();
    let load = ops.total_load();
    // Relative to the model's share of 4P: the net load, or the stated reference when the
    // loads add up to zero (a bonded plate under curling alone), where |load| is round-off.
    let rel = (reaction - load).abs() / load.abs().max(4.0 / ops.mesh.copies() as f64);
    if rel.is_nan() || rel > EQUILIBRIUM_TOLERANCE {
        return Err(Error::numerical(
            format!("{} solve", sol.method.name()),
            format!(
                "the reaction misses the load by {rel:.1e} (relative): the system is too badly conditioned for this plate-to-foundation stiffness ratio; try the QP method, a coarser mesh, or check the units of the moduli"
            ),
        ));
    }
    Ok(())
}

/// A tensionless foundation can only balance a net downward load whose line of action passes
/// through the plate: check the rigid-body components of the load before solving. On a jointed
/// plate, cluster by cluster (panels joined by transferring joints; the rigid modes do not mix
/// clusters): [`check_feasible_jointed`].
pub fn check_feasible(ops: &Operators) -> Result<()> {
    if ops.mesh.is_jointed() {
        return check_feasible_jointed(ops);
    }
    let rf: Vec<f64> = ops.rigid.iter().map(|r| linalg::dot(r, &ops.f)).collect();
    let total = rf[0];
    let scale: f64 = ops.f.iter().map(|v| v.abs()).sum();
    if total <= 1e-12 * scale {
        return Err(net_load_error("the plate", "it", total, scale, &rf[1..]));
    }
    // Resultant position, where the model keeps that rotation (x: mode 1 unless reduced about
    // x = 0; y: the next mode unless reduced about y = 0). A non-negative nodal pressure σ_j
    // acts at the centroid of its shape function (coupling B), so with nodal constraints the
    // reachable resultants are the bounding box of those centroids — for the consistent
    // (half-space) coupling a third of an element inside the plate edge.
    let columns = mode_columns(ops);
    let c = &columns.0;
    let nodal = ops.constraints.kind == ConstraintPoints::Nodal;
    let m = &ops.mesh;
    let bounds = |k: usize, lo: f64, hi: f64| {
        if nodal {
            let (mut a, mut b) = (f64::INFINITY, f64::NEG_INFINITY);
            for j in 0..c[0].len() {
                if c[0][j] > 0.0 {
                    let x = c[k][j] / c[0][j];
                    a = a.min(x);
                    b = b.max(x);
                }
            }
            (a, b)
        } else {
            (lo, hi)
        }
    };
    let tol = 1e-9;
    let mut k = 1;
    if !m.sym_x {
        let (lo, hi) = bounds(k, m.x0, m.x0 + m.nx as f64 * m.hx);
        let xbar = rf[k] / total;
        k += 1;
        if xbar < lo - tol || xbar > hi + tol {
            return Err(Error::Infeasible(format!(
                "the load resultant acts at x = {xbar:.4} L, outside [{lo:.4}, {hi:.4}] L where non-negative nodal pressures can balance it (the plate would tip over; a resultant on the very edge needs pressure concentrated on the edge, which bilinear pressures reach only to within a third of an element)"
            )));
        }
    }
    if !m.sym_y {
        let (lo, hi) = bounds(k, m.y0, m.y0 + m.ny as f64 * m.hy);
        let ybar = rf[k] / total;
        if ybar < lo - tol || ybar > hi + tol {
            return Err(Error::Infeasible(format!(
                "the load resultant acts at y = {ybar:.4} L, outside [{lo:.4}, {hi:.4}] L where non-negative nodal pressures can balance it (the plate would tip over; a resultant on the very edge needs pressure concentrated on the edge, which bilinear pressures reach only to within a third of an element)"
            )));
        }
    }
    Ok(())
}

/// [`check_feasible`] of a jointed plate, for each cluster c of panels joined by transferring
/// joints: its net load (Σ f over its w-equations: the cluster's translation is always one of
/// its modes) must push down, and with nodal constraints some σ ≥ 0 on its pressure unknowns
/// must balance every one of its modes, C_cᵀσ = R_cᵀf with C_c = BᵀR_c — decided by the
/// projection onto that set, which exists exactly when the set is not empty. A hinge that the
/// loads would turn, a panel that would tip, are caught here; with Gauss-point constraints only
/// the net load is checked (the QP reports the rest). The errors name the cluster's panels.
pub fn check_feasible_jointed(ops: &Operators) -> Result<()> {
    let Some(topo) = ops.mesh.topo.as_ref() else {
        return Ok(());
    };
    let cluster_of_node = |n: usize| -> usize {
        topo.incident(n)
            .first()
            .map_or(0, |&(e, _)| topo.cluster[topo.piece[e] as usize] as usize)
    };
    let n_clusters = topo.n_clusters();
    let panels = |c: usize| -> String {
        let mut ids: Vec<u32> = ops
            .mesh
            .elements()
            .filter(|&e| topo.cluster[topo.piece[e] as usize] as usize == c)
            .map(|e| topo.panel[e])
            .collect();
        ids.sort_unstable();
        ids.dedup();
        let names: Vec<String> = ids
            .iter()
            .map(|&p| topo.layout.panel_name(p as usize))
            .collect();
        format!(
            "panel{} {}",
            if names.len() > 1 { "s" } else { "" },
            names.join(", ")
        )
    };
    let scale: f64 = ops.f.iter().map(|v| v.abs()).sum();
    let mut total = vec![0.0; n_clusters];
    for n in 0..ops.n_sigma() {
        if let Some(e) = ops.dofs.eq(n, crate::mesh::Dof::W) {
            total[cluster_of_node(n)] += ops.f[e];
        }
    }
    for (c, &t) in total.iter().enumerate() {
        if t <= 1e-12 * scale {
            // The cluster's other modes (its tilts and hinges): what its loads turn.
            let turns: Vec<f64> = ops
                .rigid
                .iter()
                .zip(&ops.rigid_clusters)
                .filter(|(_, &k)| k == c)
                .skip(1)
                .map(|(r, _)| linalg::dot(r, &ops.f))
                .collect();
            let them = if panels(c).starts_with("panels") {
                "them"
            } else {
                "it"
            };
            let who = format!(
                "{} (joined to no other by a joint that transfers load)",
                panels(c)
            );
            return Err(net_load_error(&who, them, t, scale, &turns));
        }
    }
    if ops.constraints.kind != ConstraintPoints::Nodal {
        return Ok(());
    }
    let columns = mode_columns(ops);
    for c in 0..n_clusters {
        let (modes, cols): (Vec<&Vec<f64>>, Vec<Vec<f64>>) = ops
            .rigid
            .iter()
            .zip(&columns.0)
            .zip(&ops.rigid_clusters)
            .filter(|(_, &k)| k == c)
            .map(|((r, col), _)| (r, col.clone()))
            .unzip();
        let b: Vec<f64> = modes.iter().map(|r| linalg::dot(r, &ops.f)).collect();
        let zeros = vec![0.0; ops.n_sigma()];
        // The projection answers fast; when it does not converge, refuse only on a proof: b
        // stands off the cone of the nodes' columns by more than round-off (a Farkas
        // certificate, [`cone_gap`]). A resultant on the very edge of the reachable set is
        // feasible (σ on the edge nodes) and passes.
        if project(&zeros, &cols, &b).is_none() && cone_gap(&cols, &b) > FEASIBILITY_GAP {
            return Err(Error::Infeasible(format!(
                "the loads on {} cannot be balanced by pressures that only push: a panel would tip over or turn about a joint (move the loads inwards, or use bonded contact)",
                panels(c)
            )));
        }
    }
    Ok(())
}

/// Bᵀ r for every rigid mode r of the operators (the balance each mode asks of the nodal
/// pressures), made once per assembly and kept in its cache: every load checked on it reads the
/// same.
struct ModeColumns(Vec<Vec<f64>>);

fn mode_columns(ops: &Operators) -> std::sync::Arc<ModeColumns> {
    match ops
        .cache
        .get_or_try_init::<_, std::convert::Infallible>(|| {
            Ok(ModeColumns(
                ops.rigid.iter().map(|r| ops.bt_times(r)).collect(),
            ))
        }) {
        Ok((columns, _)) => columns,
        Err(never) => match never {},
    }
}

/// Relative distance of a cluster's load from the balances non-negative pressures can give
/// beyond which it is refused (the same 1e-9 as the resultant's position on a plate of one piece).
const FEASIBILITY_GAP: f64 = 1e-9;

/// The error for a net load that does not push down: `who` ("the plate", "panel (1, 2)"),
/// `total` its net load, `turns` its loads' work in its other rigid modes. Upward: no
/// equilibrium. No net load and nothing that turns it (no load at all, or curling alone, whose
/// moments are self-equilibrated): σ = 0 balances it, so equilibrium exists, but nothing presses
/// it onto a soil that cannot pull and its rigid position (lift, tilts, hinge turns: the modes
/// no spring holds) is undetermined — not infeasible, ill-posed. No net load but a couple: σ = 0
/// is the only pressure with no resultant, and it balances no couple — infeasible.
fn net_load_error(who: &str, them: &str, total: f64, scale: f64, turns: &[f64]) -> Error {
    let tol = 1e-12 * scale;
    if total < -tol {
        Error::Infeasible(format!(
            "{who}: the net load is upward ({total:.3e} in units of P on the model): a foundation that cannot pull cannot hold {them} down — give {them} a downward load (the self-weight); bonded contact can"
        ))
    } else if turns.iter().all(|t| t.abs() <= tol) {
        Error::Unsupported(format!(
            "{who} carries no net load: zero pressure balances {them}, but nothing presses {them} onto a foundation that cannot pull, so where {them} rests (lift and tilt) is undetermined — give {them} a downward load (the self-weight), or use bonded contact"
        ))
    } else {
        Error::Infeasible(format!(
            "{who}: the loads add up to no net force but turn {them} (a couple): pressures that only push cannot balance a couple — give {them} a downward load (the self-weight), or use bonded contact"
        ))
    }
}

/// Nodal gap and residual bookkeeping shared by the methods: g = T σ − Bᵀ u + g₀ (g₀ the
/// voids' initial gap).
pub fn discrete_gap(ops: &Operators, u: &[f64], sigma: &[f64]) -> Vec<f64> {
    let ts = ops.t.apply(sigma);
    let btu = ops.bt_times(u);
    ts.iter()
        .zip(&btu)
        .zip(&ops.gap0)
        .map(|((a, b), g0)| a - b + g0)
        .collect()
}
