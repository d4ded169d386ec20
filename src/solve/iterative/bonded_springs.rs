//! The bonded problem on Winkler soil from the plate-on-springs factor alone.
//!
//! With T diagonal, lumped coupling B and nodal constraints, the bonded preconditioner
//! M = T + BᵀK⁻B is the Schur matrix S itself, and its factor F = K_r + B T⁻¹ Bᵀ (the plate with
//! its rigid modes fixed, on the springs T⁻¹) gives everything the bonded face needs without
//! K_r's own factor:
//!
//! * M⁻¹h = T⁻¹BᵀF⁻¹f − M⁻¹g₀, since M⁻¹BᵀK_r⁻¹ = T⁻¹BᵀF⁻¹ (Woodbury, then F − BT⁻¹Bᵀ = K_r);
//! * σ = M⁻¹(h + Cα) with α from the equilibrium Cᵀσ = Rᵀf (the small system CᵀM⁻¹C);
//! * u = v + Rα with F v = f + B T⁻¹(g₀ − Cα), from K_r v = f − Bσ and the closed gap
//!   Tσ = Bᵀu − g₀.
//!
//! Where every σ ≥ 0 the bonded answer satisfies the unilateral conditions (σ ≥ 0, g = 0), so
//! it is the QP's solution: a slab fully in contact costs one factorisation, as the penalty's
//! first step does ([`crate::solve::qp::active_set`]).

use super::schur::SpringSetup;
use crate::error::Result;
use crate::foundation::Compliance;
use crate::method::CgSettings;
use crate::model::ConstraintPoints;
use crate::operators::Operators;
use crate::solve::linalg::dot;

/// The bonded answer of [`bonded_from_springs`].
#[derive(Debug, Clone)]
pub struct BondedBySprings {
    /// Nodal pressures, all ≥ 0.
    pub sigma: Vec<f64>,
    /// Plate dofs u = K⁻(f − Bσ) + Rα.
    pub u: Vec<f64>,
    /// Rigid-body amplitudes.
    pub alpha: Vec<f64>,
    /// The rigid-mode columns C = BᵀR and the loads' Rᵀf of the equilibrium Cᵀσ = Rᵀf.
    pub c: Vec<Vec<f64>>,
    /// Rᵀf.
    pub rf: Vec<f64>,
    /// Whether the plate on springs was factored by this call (else it came from the
    /// operators' cache).
    pub factored: bool,
}

/// The bonded solution from the fine plate on the springs T (`settings` must ask for them:
/// spring scale 1, no coarse plate) when T is diagonal and the constraints nodal, and its
/// pressures are all ≥ 0; otherwise `Err` with whether the plate on springs was factored by
/// this call (a point in tension; false for another soil or setting, where nothing is done).
/// The plate on springs and its bonded factor are the operators' cached ones, which the
/// active-set iteration starts from anyway.
pub fn bonded_from_springs(
    ops: &Operators,
    settings: CgSettings,
) -> Result<std::result::Result<BondedBySprings, bool>> {
    if !matches!(ops.t.as_ref(), Compliance::Diagonal(_))
        || ops.constraints.kind != ConstraintPoints::Nodal
        || settings.coarse_plate
        || settings.spring_scale != 1.0
    {
        return Ok(Err(false));
    }
    let c: Vec<Vec<f64>> = ops.rigid.iter().map(|r| ops.bt_times(r)).collect();
    let rf: Vec<f64> = ops.rigid.iter().map(|r| dot(r, &ops.f)).collect();
    let t_diag = ops.t.diagonal();
    let (setup, factored) = SpringSetup::get(ops, settings, &t_diag, &c)?;
    let (springs, pre) = (&setup.springs, &setup.bonded);
    // F⁻¹f and (with voids) F⁻¹BT⁻¹g₀ in one block solve; F⁻¹BT⁻¹C_a per rigid mode came
    // with the preconditioner (the plate's part of M⁻¹C).
    let voids = ops.gap0.iter().any(|&g| g != 0.0);
    let mut loads = vec![ops.f.clone()];
    if voids {
        let y: Vec<f64> = ops
            .gap0
            .iter()
            .zip(&pre.w.diag)
            .map(|(a, d)| a * d)
            .collect();
        loads.push(ops.b_times(&y));
    }
    let Some(x) = springs.plate_solves(&pre.factor, &loads) else {
        return Ok(Err(factored));
    };
    let Some(x_c) = (0..c.len())
        .map(|a| springs.to_model(&pre.plate_c, a))
        .collect::<Option<Vec<_>>>()
    else {
        return Ok(Err(factored));
    };
    let (Some(v_f), v_g) = (x.first(), x.get(1)) else {
        return Ok(Err(factored));
    };
    // σ₀ = M⁻¹h = T⁻¹BᵀF⁻¹f − M⁻¹g₀.
    let mut sigma: Vec<f64> = ops
        .bt_times(v_f)
        .iter()
        .zip(&pre.w.diag)
        .map(|(a, d)| a * d)
        .collect();
    if let Some(vg) = v_g {
        // M⁻¹g₀ = T⁻¹g₀ − T⁻¹BᵀF⁻¹BT⁻¹g₀ (Woodbury).
        for ((s, (g, b)), d) in sigma
            .iter_mut()
            .zip(ops.gap0.iter().zip(ops.bt_times(vg)))
            .zip(&pre.w.diag)
        {
            *s -= d * (g - b);
        }
    }
    // Onto the equilibrium along M⁻¹C: σ = M⁻¹(h + Cα).
    let defect: Vec<f64> = c
        .iter()
        .zip(&rf)
        .map(|(col, b)| b - dot(col, &sigma))
        .collect();
    let alpha = pre.small.solve(&defect);
    for (a, &al) in alpha.iter().enumerate() {
        for (x, m) in sigma.iter_mut().zip(&pre.minv_c[a]) {
            *x += al * m;
        }
    }
    // (NaN fails too.)
    if !sigma.iter().all(|&s| s >= 0.0) {
        return Ok(Err(factored));
    }
    // u = v + Rα, F v = f + B T⁻¹(g₀ − Cα).
    let mut u = v_f.clone();
    for (xa, &a) in x_c.iter().zip(&alpha) {
        for (ui, xi) in u.iter_mut().zip(xa) {
            *ui -= a * xi;
        }
    }
    if let Some(vg) = v_g {
        for (ui, xi) in u.iter_mut().zip(vg) {
            *ui += xi;
        }
    }
    for (r, &a) in ops.rigid.iter().zip(&alpha) {
        for (x, ri) in u.iter_mut().zip(r) {
            *x += a * ri;
        }
    }
    Ok(Ok(BondedBySprings {
        sigma,
        u,
        alpha,
        c,
        rf,
        factored,
    }))
}
