//! The Schur system with a matrix-free T: its set-up, its products, the projected PCG, and the
//! two solves built on it — a penalty step and a face solve.

use std::sync::Arc;
use std::time::Instant;

use super::preconditioner::Preconditioner;
use super::shear_layer::{self, ShearLayer};
use super::springs::{coarse_resolves, SpringPlate};
use crate::error::{Error, Result};
use crate::foundation::Compliance;
use crate::method::CgSettings;
use crate::monitor::Monitor;
use crate::operators::Operators;
use crate::solve::diagnostics::CgReport;
use crate::solve::linalg::{dot, PlateInverse};

/// The solution of one linear step.
#[derive(Debug, Clone)]
pub struct Step {
    /// Plate dofs u = K⁻(f − Bσ) + Rα.
    pub u: Vec<f64>,
    /// Nodal pressures.
    pub sigma: Vec<f64>,
    /// Rigid-body amplitudes.
    pub alpha: Vec<f64>,
    /// How the conjugate gradients went.
    pub cg: CgReport,
}

/// The solution of a face solve: the pressures that minimise ½σᵀSσ − hᵀσ on the equilibrium
/// Cᵀσ = Rᵀf with the held points at zero.
#[derive(Debug, Clone)]
pub struct Face {
    /// Nodal pressures (zero on the held points).
    pub sigma: Vec<f64>,
    /// Rigid-body amplitudes: the least-squares multiplier on the free points.
    pub alpha: Vec<f64>,
    /// T σ.
    pub t_sigma: Vec<f64>,
    /// S σ.
    pub s_sigma: Vec<f64>,
    /// How the conjugate gradients went.
    pub cg: CgReport,
}

/// S p + Σ_k d_k g_k g_kᵀ p, given S p.
fn penalised(sp: &[f64], rows: &[Vec<(usize, f64)>], weights: &[f64], p: &[f64]) -> Vec<f64> {
    let mut y = sp.to_vec();
    for (k, &d) in weights.iter().enumerate() {
        if d != 0.0 {
            let gp: f64 = rows[k].iter().map(|&(i, v)| v * p[i]).sum();
            for &(i, v) in &rows[k] {
                y[i] += d * v * gp;
            }
        }
    }
    y
}

/// What the projected PCG returns.
struct Solved {
    sigma: Vec<f64>,
    alpha: Vec<f64>,
    /// T σ.
    t_sigma: Vec<f64>,
    /// S σ (without penalty).
    s_sigma: Vec<f64>,
    cg: CgReport,
}

/// Where the next penalty step starts: the last step's answer σ, the penalty weights of the
/// solve that gave it, and the products its solve ended with — or a σ handed in from a
/// neighbouring solve ([`IterativeSchur::warm_start`]: no weights, no products).
struct Last {
    sigma: Vec<f64>,
    /// The penalty weights of the solve that gave σ (empty: none, or a start from elsewhere).
    weights: Vec<f64>,
    /// T σ and S σ as that solve ended with them (None: σ came from elsewhere, or a face solve
    /// ran since).
    products: Option<Products>,
}

/// The products T σ and S σ (without penalty) of one σ, formed by the solve that ended on it:
/// the next step starts there without forming them again.
///
/// (Carrying on with the last step's iteration itself — its residual and direction — when the
/// next step solves the same system to a tighter tolerance was tried and dropped: the
/// recurrence's residual drifts from the true one under stiff penalty springs, and a restart
/// from the true residual is what kept the penalty's answer converging to the QP's as ε̄ → 0 —
/// `tests/exactness.rs` found V 1.4e-6 off at ε̄ = 1e-8 on a layer with it, worse than at 1e-6.)
struct Products {
    t_sigma: Vec<f64>,
    s_sigma: Vec<f64>,
}

/// A start σ whose equilibrium defect |Rᵀf − Cᵀσ| is at most this fraction of |Rᵀf| is not
/// moved, so the products it was given stay exact: the iterates keep Cᵀσ fixed up to
/// round-off (the projections are refined twice, [`Preconditioner::project`]), and a move of
/// this size changes σ far below any tolerance the iteration is asked for (1e-14 at the least).
const KEPT_DEFECT: f64 = 1e-13;

/// The Schur system of the half-space with a matrix-free T, ready for penalty steps.
pub struct IterativeSchur {
    settings: CgSettings,
    kinv: Arc<PlateInverse>,
    /// h = BᵀK⁻f.
    pub h: Vec<f64>,
    /// C = BᵀR.
    pub c: Vec<Vec<f64>>,
    /// Rᵀf.
    pub rf: Vec<f64>,
    /// diag(T).
    t_diag: Vec<f64>,
    /// The preconditioner's plate on springs.
    springs: Arc<SpringPlate>,
    /// The preconditioner's shear layer (None: springs λ·diag(T)).
    layer: Option<Arc<ShearLayer>>,
    /// The preconditioner is the matrix itself: a diagonal T and lumped coupling, springs
    /// exactly T on the model's own plate (and the penalty, diagonal with nodal constraints).
    exact: bool,
    /// The next penalty step's start (None: zero pressure).
    last: Option<Last>,
    /// The last preconditioner, reused while its weights and held set stay (the first is the
    /// bonded one, factored beside the plate).
    cached: Option<Preconditioner>,
    /// Seconds spent factoring the plate.
    pub time_plate: f64,
    /// Preconditioner factorisations made.
    pub factorisations: usize,
    /// Products with the Schur matrix made.
    pub products: usize,
}

/// The preconditioner's side of what an [`IterativeSchur`] needs that does not depend on the
/// loads, cached per assembly (`Operators::cache`) for the settings `key` (coarse plate, spring
/// scale): the plate on springs and the bonded preconditioner (no held points, no penalty, its
/// CG scale not yet set), where the penalty and the active-set iteration both start.
pub(super) struct SpringSetup {
    key: SetupKey,
    pub(super) springs: Arc<SpringPlate>,
    pub(super) layer: Option<Arc<ShearLayer>>,
    pub(super) bonded: Preconditioner,
}

/// The settings a [`SpringSetup`] was made for: coarse plate, spring scale, shear layer.
type SetupKey = (bool, f64, bool);

fn setup_key(settings: &CgSettings) -> SetupKey {
    (
        settings.coarse_plate,
        settings.spring_scale,
        settings.shear_layer,
    )
}

/// The plate's own factor (its rigid modes fixed), cached per assembly beside [`SpringSetup`].
struct PlateSetup {
    kinv: Arc<PlateInverse>,
    time_plate: f64,
}

impl SpringSetup {
    fn new(ops: &Operators, settings: CgSettings, t_diag: &[f64], c: &[Vec<f64>]) -> Result<Self> {
        // The coarse plate only where it carries the plate's compliance (a nearly membrane
        // plate needs the fine one).
        let layer = settings
            .shear_layer
            .then(|| shear_layer::fit(ops, t_diag))
            .flatten();
        let springs = SpringPlate::new(
            ops,
            settings.coarse_plate && coarse_resolves(ops),
            layer.is_some(),
        )?;
        let bonded = Preconditioner::new(
            &springs,
            (t_diag, settings.spring_scale),
            layer.as_ref(),
            c,
            (&[], &[]),
            &[],
        )?;
        Ok(Self {
            key: setup_key(&settings),
            springs: Arc::new(springs),
            layer: layer.map(Arc::new),
            bonded,
        })
    }

    /// The cached setup for `settings`, or a new one (cached when none was); whether it was
    /// made by this call.
    pub(super) fn get(
        ops: &Operators,
        settings: CgSettings,
        t_diag: &[f64],
        c: &[Vec<f64>],
    ) -> Result<(Arc<Self>, bool)> {
        let key = setup_key(&settings);
        match ops
            .cache
            .get_or_try_init(|| Self::new(ops, settings, t_diag, c))?
        {
            (s, fresh) if s.key == key => Ok((s, fresh)),
            _ => Ok((Arc::new(Self::new(ops, settings, t_diag, c)?), true)),
        }
    }
}

impl PlateSetup {
    fn new(ops: &Operators) -> Result<Self> {
        let t0 = Instant::now();
        let kinv = PlateInverse::new(ops)?;
        Ok(Self {
            kinv: Arc::new(kinv),
            time_plate: t0.elapsed().as_secs_f64(),
        })
    }
}

/// The value of type `T` in the operators' cache, if one is there.
fn cached<T: Send + Sync + 'static>(ops: &Operators) -> Option<Arc<T>> {
    ops.cache
        .get_or_try_init::<T, ()>(|| Err(()))
        .ok()
        .map(|(v, _)| v)
}

impl IterativeSchur {
    /// Factor the plate, form h, C, Rᵀf and analyse the preconditioner's pattern, for the
    /// penalty steps of the iterative route (T must be the FFT operator).
    pub fn new(ops: &Operators, settings: CgSettings) -> Result<Self> {
        if !matches!(ops.t.as_ref(), Compliance::Toeplitz(_)) {
            return Err(Error::Unsupported(
                "the iterative route needs the half-space compliance as a Toeplitz operator (assemble with the iterative route)".into(),
            ));
        }
        Self::with_any_compliance(ops, settings)
    }

    /// As [`Self::new`] for any compliance: diagonal (Winkler), dense or FFT. Only products
    /// with T and its diagonal are used.
    pub fn with_any_compliance(ops: &Operators, settings: CgSettings) -> Result<Self> {
        let c: Vec<Vec<f64>> = ops.rigid.iter().map(|r| ops.bt_times(r)).collect();
        let rf = ops.rigid.iter().map(|r| dot(r, &ops.f)).collect();
        let t_diag = ops.t.diagonal();
        // The plate's factor, the preconditioner's plate and the bonded preconditioner do not
        // depend on the loads: made once per assembly and shared by every solve on these
        // operators (load combinations, critical positions, the ε̄ sweep, compare's methods).
        // When neither is cached the two factorisations are independent: one on each core. By
        // rayon::join, not OS threads: a caller on a rayon worker (combinations run in
        // parallel) would otherwise block it while the factorisations' own rayon jobs wait for
        // a free worker — a deadlock. (The cache's lock is held while it computes, so the two
        // are made outside it and stored after.)
        let key = setup_key(&settings);
        let have_springs = cached::<SpringSetup>(ops);
        let have_plate = cached::<PlateSetup>(ops);
        let ((plate, fresh_plate), (setup, fresh_springs)) = match (have_plate, have_springs) {
            (None, None) => {
                let (p, s) = rayon::join(
                    || PlateSetup::new(ops),
                    || SpringSetup::new(ops, settings, &t_diag, &c),
                );
                let (p, s) = (p?, s?);
                let p = ops.cache.get_or_try_init::<_, Error>(|| Ok(p))?.0;
                let s = ops.cache.get_or_try_init::<_, Error>(|| Ok(s))?.0;
                // (Another solve may have stored its own settings' setup meanwhile.)
                let s = if s.key == key {
                    (s, true)
                } else {
                    SpringSetup::get(ops, settings, &t_diag, &c)?
                };
                ((p, true), s)
            }
            (Some(p), s) => (
                (p, false),
                match s.filter(|s| s.key == key) {
                    Some(s) => (s, false),
                    None => SpringSetup::get(ops, settings, &t_diag, &c)?,
                },
            ),
            (None, Some(s)) => (
                ops.cache.get_or_try_init(|| PlateSetup::new(ops))?,
                match Some(s).filter(|s| s.key == key) {
                    Some(s) => (s, false),
                    None => SpringSetup::get(ops, settings, &t_diag, &c)?,
                },
            ),
        };
        let kinv = plate.kinv.clone();
        let springs = setup.springs.clone();
        let layer = setup.layer.clone();
        let bonded = setup.bonded.clone();
        let time_plate = if fresh_plate { plate.time_plate } else { 0.0 };
        let exact = matches!(ops.t.as_ref(), Compliance::Diagonal(_))
            && ops.constraints.kind == crate::model::ConstraintPoints::Nodal
            && settings.spring_scale == 1.0
            && springs.kind == "fine";
        // h = BᵀK⁻f − g₀: the voids' initial gap enters as g = Aσ − Cα − h.
        let h = ops
            .bt_times(&kinv.apply(&ops.f))
            .iter()
            .zip(&ops.gap0)
            .map(|(a, g)| a - g)
            .collect();
        Ok(Self {
            settings,
            kinv,
            h,
            c,
            rf,
            t_diag,
            springs,
            layer,
            exact,
            last: None,
            cached: Some(bonded),
            time_plate,
            factorisations: usize::from(fresh_springs),
            products: 0,
        })
    }

    /// (T p, S p) with S = T + BᵀK⁻B, the Schur matrix without penalty.
    pub fn t_and_s_times(&mut self, ops: &Operators, p: &[f64]) -> (Vec<f64>, Vec<f64>) {
        self.products += 1;
        // The product with T and the plate solve are independent: one on each core.
        let kinv = &self.kinv;
        let (tp, plate) = rayon::join(
            || ops.t.apply(p),
            || ops.bt_times(&kinv.apply(&ops.b_times(p))),
        );
        let sp = tp.iter().zip(&plate).map(|(a, b)| a + b).collect();
        (tp, sp)
    }

    /// The preconditioner for penalty weights on `rows` and the points `held` at zero (empty:
    /// none): the cached one if it was made for them, else a new factorisation.
    fn preconditioner(
        &mut self,
        rows: &[Vec<(usize, f64)>],
        weights: &[f64],
        held: &[bool],
    ) -> Result<Preconditioner> {
        if let Some(pre) = self.cached.take() {
            if pre.fits(weights, held) {
                return Ok(pre);
            }
        }
        self.factorisations += 1;
        Preconditioner::new(
            &self.springs,
            (&self.t_diag, self.settings.spring_scale),
            self.layer.as_deref(),
            &self.c,
            (rows, weights),
            held,
        )
    }

    /// Projected PCG from `sigma` (made feasible first) to the relative tolerance `tol`; from
    /// `fallback` instead where `sigma`'s residual exceeds the loads' (relative residual above
    /// one: a worse start than none). Where the preconditioner is the matrix itself (`exact`:
    /// Winkler springs on the model's own plate) the start is the direct solution
    /// σ = M⁻¹(h + Cα), and CG only confirms it. `known`: the products T σ and S σ of `sigma`
    /// (the last step's answer), which are not formed again unless σ must be moved onto the
    /// equilibrium (more than round-off) or the start is abandoned for the fallback. The
    /// products of the answer are formed afresh when `recompute`, else kept from the iterations'
    /// updates (a loose penalty step's: one plate solve less; measured on the half-space lane,
    /// BENCHMARKS.md session 25).
    #[allow(clippy::too_many_arguments)]
    fn cg(
        &mut self,
        ops: &Operators,
        pre: &mut Preconditioner,
        rows: &[Vec<(usize, f64)>],
        weights: &[f64],
        (mut sigma, mut fallback): (Vec<f64>, Option<Vec<f64>>),
        known: Option<Products>,
        (tol, recompute): (f64, bool),
        stage: &str,
        monitor: &Monitor<'_>,
    ) -> Result<Solved> {
        let n = ops.n_sigma();
        let mut h = self.h.clone();
        pre.mask(&mut h);
        if self.exact {
            // σ = M⁻¹h on the free points, then along M⁻¹C onto the equilibrium below.
            sigma = self.springs.solve(&pre.w, &pre.factor, &h);
            fallback = None;
        }
        let h_norm = dot(&h, &h).max(f64::MIN_POSITIVE).sqrt();
        let scale = match pre.scale {
            Some(v) => v,
            None => {
                let z = pre.project(&self.springs, &h);
                let v = dot(&h, &z).max(f64::MIN_POSITIVE).sqrt();
                pre.scale = Some(v);
                v
            }
        };
        // Known products are used for an inexact preconditioner's start with no held point.
        let mut known = known.filter(|_| !self.exact && !pre.held.iter().any(|&h| h));
        let (mut sigma, mut t_sigma, mut s_sigma, mut r, mut z, mut rz, mut residual) = loop {
            pre.mask(&mut sigma);
            // Start: σ moved onto Cᵀσ = Rᵀf along M⁻¹C (not when the defect is round-off and
            // the products are known).
            let defect: Vec<f64> = (0..pre.c.len())
                .map(|a| self.rf[a] - dot(&pre.c[a], &sigma))
                .collect();
            let size = |v: &[f64]| dot(v, v).sqrt();
            if known.is_none() || size(&defect) > KEPT_DEFECT * size(&self.rf) {
                known = None;
                let s = pre.small.solve(&defect);
                for (a, &sa) in s.iter().enumerate() {
                    for (x, ci) in sigma.iter_mut().zip(&pre.minv_c[a]) {
                        *x += sa * ci;
                    }
                }
            }
            let (t_sigma, s_sigma) = match known.take() {
                Some(p) => (p.t_sigma, p.s_sigma),
                None => self.t_and_s_times(ops, &sigma),
            };
            let mut r: Vec<f64> = penalised(&s_sigma, rows, weights, &sigma)
                .iter()
                .zip(&self.h)
                .map(|(a, b)| a - b)
                .collect();
            pre.mask(&mut r);
            pre.deflate(&mut r);
            let z = pre.project(&self.springs, &r);
            let rz = dot(&r, &z);
            let residual = rz.max(0.0).sqrt() / scale;
            match fallback.take() {
                Some(other) if residual > 1.0 => sigma = other,
                _ => break (sigma, t_sigma, s_sigma, r, z, rz, residual),
            }
        };
        let mut p: Vec<f64> = z.iter().map(|v| -v).collect();
        let mut iterations = 0;
        while residual > tol {
            monitor.check(stage)?;
            if iterations >= self.settings.max_iterations {
                return Err(Error::numerical(
                    stage,
                    format!(
                        "no convergence in {} iterations (relative residual {residual:.1e}): the system is too badly conditioned for the iterative route; use solver.route = \"dense\"",
                        self.settings.max_iterations
                    ),
                ));
            }
            // A p = T p + BᵀK⁻B p + Σ_k d_k g_k g_kᵀ p, its products kept to update Tσ and Sσ.
            let (tp, sp) = self.t_and_s_times(ops, &p);
            let mut ap = penalised(&sp, rows, weights, &p);
            pre.mask(&mut ap);
            let pap = dot(&p, &ap);
            if pap == 0.0 && dot(&p, &p) <= f64::MIN_POSITIVE.sqrt() {
                // Nothing left to move: the free points' equilibrium fixes σ (a plate resting
                // on as many points as it has rigid modes), the residual is round-off.
                break;
            }
            if pap.is_nan() || pap <= 0.0 {
                return Err(Error::numerical(
                    stage,
                    format!("the Schur system is not positive definite on the equilibrium subspace (pᵀAp = {pap:e})"),
                ));
            }
            let step = rz / pap;
            for i in 0..n {
                sigma[i] += step * p[i];
                r[i] += step * ap[i];
                t_sigma[i] += step * tp[i];
                s_sigma[i] += step * sp[i];
            }
            pre.deflate(&mut r);
            z = pre.project(&self.springs, &r);
            let rz_new = dot(&r, &z);
            let beta = rz_new / rz;
            rz = rz_new;
            for i in 0..n {
                p[i] = -z[i] + beta * p[i];
            }
            iterations += 1;
            residual = rz.max(0.0).sqrt() / scale;
        }
        if iterations > 0 && recompute {
            (t_sigma, s_sigma) = self.t_and_s_times(ops, &sigma);
        }
        // α: least-squares multiplier of the recomputed residual on the free points,
        // Aσ − h ≈ Cα.
        let mut res: Vec<f64> = penalised(&s_sigma, rows, weights, &sigma)
            .iter()
            .zip(&self.h)
            .map(|(a, b)| a - b)
            .collect();
        pre.mask(&mut res);
        let ctr: Vec<f64> = pre.c.iter().map(|c| dot(c, &res)).collect();
        let alpha = pre.ctc.solve(&ctr);
        for (a, &al) in alpha.iter().enumerate() {
            for (x, ci) in res.iter_mut().zip(&pre.c[a]) {
                *x -= al * ci;
            }
        }
        let true_residual = dot(&res, &res).sqrt() / h_norm;
        Ok(Solved {
            sigma,
            alpha,
            t_sigma,
            s_sigma,
            cg: CgReport {
                iterations,
                residual,
                true_residual,
            },
        })
    }

    /// Solve one penalised step: `weights[k]` = d_k on constraint point k (0 if not penalised),
    /// `rows[k]` = g_k, to the relative tolerance `level` (never below the settings'; None: the
    /// settings' tight one). Returns u, σ, α and the CG account.
    pub fn solve(
        &mut self,
        ops: &Operators,
        rows: &[Vec<(usize, f64)>],
        weights: &[f64],
        level: Option<f64>,
        monitor: &Monitor<'_>,
    ) -> Result<Step> {
        let (sigma, alpha, cg) = self.solve_pressures(ops, rows, weights, level, monitor)?;
        let u = self.displacements(ops, &sigma, &alpha);
        Ok(Step {
            u,
            sigma,
            alpha,
            cg,
        })
    }

    /// [`Self::solve`] without the displacements (one plate solve, which the penalty iteration
    /// needs only for the step it ends on: [`Self::displacements`]): σ, α and the CG account.
    /// A step after another starts from its answer with the products its solve ended with.
    pub fn solve_pressures(
        &mut self,
        ops: &Operators,
        rows: &[Vec<(usize, f64)>],
        weights: &[f64],
        level: Option<f64>,
        monitor: &Monitor<'_>,
    ) -> Result<(Vec<f64>, Vec<f64>, CgReport)> {
        let mut pre = self.preconditioner(rows, weights, &[])?;
        // The start is kept should this step fail; its products are handed on (and gone).
        let (start, before, known) = match &mut self.last {
            Some(last) => (
                last.sigma.clone(),
                last.weights.clone(),
                last.products.take(),
            ),
            None => (vec![0.0; ops.n_sigma()], Vec::new(), None),
        };
        // The last answer's tension at a newly penalised point meets the soft springs'
        // compliance c w/ε̄ there: a start residual of order 1/ε̄ against loads of order one. Where that is worse than
        // no start (on a stiff plate over a membrane-like soil it grew to ~10⁷⁰ times the
        // loads in a few stages, and CG stalled), start instead from zero pressure at the
        // points that pull and whose springs are new or ten times softer than the last
        // solve's (compliance weight d over ten times the last): the answer there is O(ε̄). Elsewhere the warm start is kept whole (the
        // loose solves of soft plates build on the O(ε̄) tension it keeps).
        let mut other = start.clone();
        for (k, &d) in weights.iter().enumerate() {
            if d > 10.0 * before.get(k).copied().unwrap_or(0.0) {
                let gs: f64 = rows[k].iter().map(|&(i, v)| v * other[i]).sum();
                if gs < 0.0 {
                    for &(i, _) in &rows[k] {
                        other[i] = 0.0;
                    }
                }
            }
        }
        let tol = level.map_or(self.settings.tolerance, |l| l.max(self.settings.tolerance));
        let out = self.cg(
            ops,
            &mut pre,
            rows,
            weights,
            (start, Some(other)),
            known,
            // A loose step's products come from the iterations' updates: its answer only has to
            // give the signs, and the confirming solve recomputes them.
            (tol, tol <= self.settings.tolerance),
            "iterative penalty step (conjugate gradients)",
            monitor,
        );
        self.cached = Some(pre);
        let solved = out?;
        self.last = Some(Last {
            sigma: solved.sigma.clone(),
            weights: weights.to_vec(),
            products: Some(Products {
                t_sigma: solved.t_sigma,
                s_sigma: solved.s_sigma,
            }),
        });
        Ok((solved.sigma, solved.alpha, solved.cg))
    }

    /// Minimise ½σᵀSσ − hᵀσ subject to Cᵀσ = Rᵀf and σ = 0 on the `held` points, from
    /// `start`, to the relative tolerance `tol`. The preconditioner of the last face solve is
    /// reused while the held set is the same.
    pub fn solve_face(
        &mut self,
        ops: &Operators,
        held: &[bool],
        start: &[f64],
        tol: f64,
        monitor: &Monitor<'_>,
    ) -> Result<Face> {
        let mut pre = self.preconditioner(&[], &[], held)?;
        if let Some(last) = &mut self.last {
            last.products = None;
        }
        let out = self.cg(
            ops,
            &mut pre,
            &[],
            &[],
            (start.to_vec(), None),
            None,
            (tol, true),
            "matrix-free QP (conjugate gradients on the free points)",
            monitor,
        );
        self.cached = Some(pre);
        let solved = out?;
        Ok(Face {
            sigma: solved.sigma,
            alpha: solved.alpha,
            t_sigma: solved.t_sigma,
            s_sigma: solved.s_sigma,
            cg: solved.cg,
        })
    }

    /// u = K⁻(f − Bσ) + Rα.
    pub fn displacements(&self, ops: &Operators, sigma: &[f64], alpha: &[f64]) -> Vec<f64> {
        crate::solve::linalg::displacements(ops, &self.kinv, sigma, alpha)
    }

    /// Start the next penalty step's conjugate gradients from `sigma` (a neighbouring solve's
    /// pressures on the same operators) instead of zero.
    pub fn warm_start(&mut self, sigma: &[f64]) {
        self.last = Some(Last {
            sigma: sigma.to_vec(),
            weights: Vec::new(),
            products: None,
        });
    }

    /// The conjugate-gradient settings.
    pub fn settings(&self) -> CgSettings {
        self.settings
    }

    /// The tolerance of the solves while a set moves: [`CgSettings::loose_tolerance`], a decade
    /// tighter on the shear layer (never tighter than the confirming tolerance). From the last
    /// answer the layer reaches 1e-4 in one or two iterations, too few to carry the pressures
    /// near the contact edge to their signs: the set then wandered (25 penalty steps of 1–2
    /// iterations on the half-space lane's first position, where 1e-5 takes 6 and springs at
    /// 1e-4 took 7; BENCHMARKS.md, session 23).
    pub fn loose_tolerance(&self) -> f64 {
        let loose = if self.layer.is_some() {
            0.1 * self.settings.loose_tolerance
        } else {
            self.settings.loose_tolerance
        };
        loose.max(self.settings.tolerance)
    }

    /// Whether the preconditioner is the matrix itself (so a tight solve costs about one CG
    /// iteration more than a loose one).
    pub fn exact(&self) -> bool {
        self.exact
    }

    /// "fine" or "coarse": the preconditioner's plate.
    pub fn preconditioner_plate(&self) -> &'static str {
        self.springs.kind
    }
}
