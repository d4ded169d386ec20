//! How a [`crate::model::Model`] is solved: bonded (bilateral) contact, or unbonded contact by
//! the paper's penalty iteration or by the convex QP. Settings carry their defaults and check
//! themselves (`validate`), as clarabel's do; nothing here knows about the command line.

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::foundation::FoundationKind;
use crate::model::ConstraintPoints;

/// Contact law between plate and foundation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Contact {
    /// Bilateral: the foundation may pull (gap = 0 everywhere).
    Bonded,
    /// Unilateral, tensionless: pressure ≥ 0, gap ≥ 0, pressure · gap = 0.
    Unbonded,
}

/// Which method solves unbonded contact (the scene's `[solver] method`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum MethodKind {
    /// The paper's penalty iteration (eqs. 4.5–4.6).
    Penalty,
    /// Convex QP in the contact pressures, solved by clarabel.
    Qp,
}

crate::choice::names!(Contact, Bonded => "bonded", Unbonded => "unbonded");

/// Which method produced a solution, as reports name it: bonded contact is one direct solve.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SolvedBy {
    /// Bonded contact: one linear solve.
    Direct,
    /// The penalty iteration.
    Penalty,
    /// The QP.
    Qp,
}

crate::choice::names!(SolvedBy, Direct => "direct", Penalty => "penalty", Qp => "qp");
crate::choice::names!(MethodKind, Penalty => "penalty", Qp => "qp");

/// Where an iterative method starts on a large grid (the scene's `[solver] start`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum Start {
    /// From the same plate solved on a grid twice as coarse (recursively), from
    /// [`crate::solve::NESTED_MIN_NODES`] pressure nodes: the penalty's first lifted set (and
    /// its ε̄, where the automatic choice lowered it there), the active-set QP's first iterate.
    #[default]
    Nested,
    /// From nothing: the penalty from the bonded solve, the active-set QP from the feasible
    /// point nearest σ = 0.
    Cold,
}

crate::choice::names!(Start, Nested => "nested", Cold => "cold");

/// Settings of the penalty iteration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PenaltySettings {
    /// ε̄ (dimensionless, eq. 4.1f); the paper uses 1e-5. With `auto`, the first ε̄ tried.
    pub epsilon: f64,
    /// Lower ε̄ (continuation from the last penalised set) while a stage ends without a
    /// solution; false keeps ε̄ fixed, as in the paper.
    pub auto: bool,
    /// Cap on linear solves per ε̄.
    pub max_iterations: usize,
    /// The conjugate-gradient solves of the iterative route (half-space with a Toeplitz T).
    pub cg: CgSettings,
    /// Where a large grid starts.
    pub start: Start,
}

/// Settings of the conjugate-gradient solves of the iterative route
/// ([`crate::solve::iterative`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CgSettings {
    /// Stop when the preconditioned residual √(rᵀM⁻¹r) (projected on the equilibrium subspace)
    /// falls below this fraction of the right-hand side's.
    pub tolerance: f64,
    /// The tolerance of the penalty steps whose set is still changing: the set is confirmed by
    /// a solve at `tolerance`, so this only has to get the signs of the pressures right.
    /// A decade tighter where the preconditioner rests on a shear layer.
    pub loose_tolerance: f64,
    /// Cap on iterations per linear solve.
    pub max_iterations: usize,
    /// λ: the preconditioner's Winkler springs are λ·diag(T) (where no shear layer is fitted,
    /// and on penalised points).
    pub spring_scale: f64,
    /// Put the preconditioner's plate on springs and a shear layer fitted to T's symbol rather
    /// than on the springs λ·diag(T), on a continuum soil
    /// ([`crate::solve::iterative`]'s `shear_layer`).
    pub shear_layer: bool,
    /// Put the preconditioner's plate on a grid twice as coarse (when the element counts are
    /// even): a quarter of the equations to factor and solve.
    pub coarse_plate: bool,
}

impl Default for CgSettings {
    /// Tolerance 1e-10 (σ to ~1e-9 of the direct solve), 1e-4 while the set moves (1e-5 on the
    /// shear layer, [`crate::solve::iterative::IterativeSchur::loose_tolerance`]), at most 2000
    /// iterations, the coarse plate on a shear layer; λ = 0.2 where springs stand in (the
    /// fewest iterations on the paper's half-space case at 128 and 256 elements per side among
    /// λ = 0.02 … 2, BENCHMARKS.md).
    fn default() -> Self {
        Self {
            tolerance: 1e-10,
            loose_tolerance: 1e-4,
            max_iterations: 2000,
            spring_scale: 0.2,
            shear_layer: true,
            coarse_plate: true,
        }
    }
}

/// How a non-local soil's compliance T is held and the linear solves of the bonded, penalty and
/// active-set methods run (the scene's `[solver] route`, the CLI's `--solver`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Route {
    /// Dense up to [`Route::AUTO_DENSE_NODES`] pressure nodes, iterative beyond — for bonded
    /// contact, the penalty and the matrix-free active-set QP, which is what the default QP
    /// (`qp_solver = "auto"`, nodal constraints, no explicit `qp_form`) runs there. Always dense
    /// for a QP that needs clarabel ([`QpSettings::needs_clarabel`]).
    Auto,
    /// Dense T and Schur complement, direct factorisations: memory ∝ n_σ², time ∝ n_σ³.
    Dense,
    /// T applied by FFT, each linear solve (a bonded solve, a penalty step, an active-set face
    /// solve) by preconditioned conjugate gradients: memory and time per iteration ∝ n_σ
    /// (log n_σ). Bonded contact, the penalty and the matrix-free active-set QP; refused for a
    /// QP that needs clarabel.
    Iterative,
}

crate::choice::names!(Route, Auto => "auto", Dense => "dense", Iterative => "iterative");

impl Route {
    /// Largest non-local model (pressure nodes) that `auto` solves densely. The iterative route
    /// is already faster from ~300 nodes (32 per side on the paper's case: 18 against
    /// 23 ms; 64 per side: 0.11 against 0.33 s), but the dense route is the reference and keeps
    /// the step counts of the direct iteration where its cost does not matter (≤ ~0.6 s).
    pub const AUTO_DENSE_NODES: usize = 1500;

    /// Whether the non-local T of a model with `n_sigma` pressure nodes is held as a Toeplitz
    /// operator when solved with `method` under `constraint`. Refuses the iterative route for a
    /// QP that clarabel must solve (it needs the dense Schur complement); the matrix-free QP
    /// takes it like the penalty.
    pub fn iterative(
        self,
        n_sigma: usize,
        method: &Method,
        constraint: ConstraintPoints,
    ) -> Result<bool> {
        let clarabel = matches!(method, Method::Qp(s) if s.needs_clarabel(constraint));
        match self {
            Route::Dense => Ok(false),
            Route::Iterative if clarabel => Err(Error::invalid(
                "solver.route",
                "clarabel needs the dense Schur complement, which the iterative route does not form; use route = \"dense\", or the matrix-free QP (qp_solver = \"active-set\" with nodal constraints)",
            )),
            Route::Iterative => Ok(true),
            Route::Auto => Ok(!clarabel && n_sigma > Self::AUTO_DENSE_NODES),
        }
    }
}

impl Default for PenaltySettings {
    /// Automatic ε̄ from the paper's 1e-5, at most 200 solves per ε̄ (a point load near a corner of a
    /// Pasternak slab lifts 98 % of it one ring of nodes per step: 71 steps).
    fn default() -> Self {
        Self {
            epsilon: 1e-5,
            auto: true,
            max_iterations: 200,
            cg: CgSettings::default(),
            start: Start::Nested,
        }
    }
}

impl PenaltySettings {
    /// A fixed ε̄, as in the paper.
    pub fn fixed(epsilon: f64) -> Self {
        Self {
            epsilon,
            auto: false,
            ..Self::default()
        }
    }

    /// Check the settings; the error names the scene field.
    pub fn validate(&self) -> Result<()> {
        let e = self.epsilon;
        if !e.is_finite() || e <= 0.0 || e >= 1.0 {
            return Err(Error::invalid(
                "solver.penalty",
                format!("ε̄ must lie in (0, 1), typically 1e-5; got {e}"),
            ));
        }
        if self.max_iterations < 1 || self.max_iterations > 10_000 {
            return Err(Error::invalid(
                "solver.max_iterations",
                format!("must lie in 1..=10000, got {}", self.max_iterations),
            ));
        }
        self.cg.validate()
    }
}

impl CgSettings {
    /// Check the settings.
    pub fn validate(&self) -> Result<()> {
        for (name, v) in [
            ("solver.cg_tolerance", self.tolerance),
            ("solver.cg_loose_tolerance", self.loose_tolerance),
        ] {
            if !(v.is_finite() && v > 0.0 && v < 1.0) {
                return Err(Error::invalid(name, format!("must lie in (0, 1), got {v}")));
            }
        }
        if self.max_iterations < 1 {
            return Err(Error::invalid(
                "solver.cg_max_iterations",
                "must be at least 1",
            ));
        }
        if !(self.spring_scale.is_finite() && self.spring_scale > 0.0) {
            return Err(Error::invalid(
                "solver.cg_spring_scale",
                format!("must be positive, got {}", self.spring_scale),
            ));
        }
        Ok(())
    }
}

/// clarabel's linear solver for the KKT systems.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KktSolver {
    /// faer's supernodal LDLᵀ: about 3× faster than QDLDL on dense KKT systems (BENCHMARKS.md).
    Faer,
    /// QDLDL, clarabel's default.
    Qdldl,
}

impl KktSolver {
    /// clarabel's name of the solver.
    pub fn name(self) -> &'static str {
        match self {
            KktSolver::Faer => "faer",
            KktSolver::Qdldl => "qdldl",
        }
    }
}

/// How the QP is posed for clarabel (all forms are exact and give the same σ).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum QpForm {
    /// Primal for a diagonal (Winkler) T, Schur for a dense (half-space) T.
    Auto,
    /// In σ through the dense Schur complement S = T + BᵀK⁻B (any T).
    Schur,
    /// In (u, σ) with the plate as an equality: sparse, diagonal T only.
    Lifted,
    /// In (u, s), the Lagrange dual whose multipliers are σ: sparse, diagonal T only; about as
    /// costly per interior-point step as one penalty step.
    Primal,
}

crate::choice::names!(QpForm, Auto => "auto", Schur => "schur", Lifted => "lifted", Primal => "primal");

impl QpForm {
    /// The form used for a compliance T: `Auto` becomes `Primal` (diagonal T) or `Schur`.
    pub fn resolve(self, t: &crate::foundation::Compliance) -> QpForm {
        match (self, t) {
            (QpForm::Auto, crate::foundation::Compliance::Diagonal(_)) => QpForm::Primal,
            (
                QpForm::Auto,
                crate::foundation::Compliance::Dense(_)
                | crate::foundation::Compliance::Toeplitz(_),
            ) => QpForm::Schur,
            (form, _) => form,
        }
    }

    /// Whether the form forms the dense Schur complement for this foundation.
    pub fn is_dense(self, foundation: crate::foundation::FoundationKind) -> bool {
        match self {
            QpForm::Schur => true,
            QpForm::Auto => !foundation.is_local(),
            QpForm::Lifted | QpForm::Primal => false,
        }
    }
}

/// Which solver runs the QP (the scene's `[solver] qp_solver`, the CLI's `--qp-solver`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum QpSolver {
    /// clarabel where its dense or sparse form fits and is robust (Gauss-point constraints, a
    /// half-space on the dense route, an explicit `qp_form`), the matrix-free active-set
    /// solver everywhere else (Winkler with nodal constraints, the iterative route) and where
    /// clarabel stops without a solution.
    Auto,
    /// clarabel's interior-point method on the form of `qp_form`.
    Clarabel,
    /// The matrix-free primal–dual active-set method with a monotone safeguard
    /// ([`crate::solve::qp::active_set`]): S applied through the operators, never formed; nodal
    /// constraints only.
    ActiveSet,
}

crate::choice::names!(QpSolver, Auto => "auto", Clarabel => "clarabel", ActiveSet => "active-set");

/// Settings of the matrix-free active-set QP solver ([`crate::solve::qp::active_set`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ActiveSetSettings {
    /// The KKT conditions must hold to this fraction of their scales: the gap on contact
    /// points and the penetration on lifted points relative to the largest foundation
    /// settlement, complementarity relative to its product with the peak pressure.
    pub tolerance: f64,
    /// Cap on outer (active-set) iterations, each one solve on the free points.
    pub max_iterations: usize,
    /// Conjugate-gradient settings of the solves on the free points: `tolerance` for the
    /// confirming solves, `loose_tolerance` while the set moves. The preconditioner is chosen
    /// from the foundation: exact (springs T, the model's plate) on Winkler soil, the coarse
    /// plate on λ·diag(T) springs otherwise.
    pub cg: CgSettings,
}

impl Default for ActiveSetSettings {
    /// KKT to 1e-10, at most 500 outer iterations, CG to 1e-12 (σ to ~1e-10 of the exact
    /// discrete solution) and 1e-4 while the set moves (1e-5 on the shear layer).
    fn default() -> Self {
        Self {
            tolerance: 1e-10,
            max_iterations: 500,
            cg: CgSettings {
                tolerance: 1e-12,
                ..CgSettings::default()
            },
        }
    }
}

impl ActiveSetSettings {
    /// Check the settings.
    pub fn validate(&self) -> Result<()> {
        if !(self.tolerance.is_finite() && self.tolerance > 0.0 && self.tolerance < 1.0) {
            return Err(Error::invalid(
                "qp.active_set_tolerance",
                format!("must lie in (0, 1), got {}", self.tolerance),
            ));
        }
        if self.max_iterations < 1 {
            return Err(Error::invalid(
                "qp.active_set_max_iterations",
                "must be at least 1",
            ));
        }
        self.cg.validate()
    }
}

/// Settings of the QP.
#[derive(Debug, Clone, PartialEq)]
pub struct QpSettings {
    /// Absolute duality-gap tolerance.
    pub tol_gap_abs: f64,
    /// Relative duality-gap tolerance.
    pub tol_gap_rel: f64,
    /// Feasibility tolerance.
    pub tol_feas: f64,
    /// Interior-point iteration cap.
    pub max_iter: u32,
    /// clarabel's KKT solver.
    pub kkt: KktSolver,
    /// How the QP is posed for clarabel.
    pub form: QpForm,
    /// Which solver runs it.
    pub solver: QpSolver,
    /// The matrix-free solver's settings.
    pub active_set: ActiveSetSettings,
    /// Where a large grid starts (the matrix-free solver; clarabel has no start).
    pub start: Start,
}

impl Default for QpSettings {
    fn default() -> Self {
        Self {
            tol_gap_abs: 1e-14,
            tol_gap_rel: 1e-13,
            tol_feas: 1e-13,
            max_iter: 200,
            kkt: KktSolver::Faer,
            form: QpForm::Auto,
            solver: QpSolver::Auto,
            active_set: ActiveSetSettings::default(),
            start: Start::Nested,
        }
    }
}

impl QpSettings {
    /// Check the settings.
    pub fn validate(&self) -> Result<()> {
        for (name, v) in [
            ("qp.tol_gap_abs", self.tol_gap_abs),
            ("qp.tol_gap_rel", self.tol_gap_rel),
            ("qp.tol_feas", self.tol_feas),
        ] {
            if !(v.is_finite() && v > 0.0 && v < 1.0) {
                return Err(Error::invalid(name, format!("must lie in (0, 1), got {v}")));
            }
        }
        if self.max_iter == 0 {
            return Err(Error::invalid("qp.max_iter", "must be at least 1"));
        }
        if self.solver == QpSolver::ActiveSet && self.form != QpForm::Auto {
            return Err(Error::invalid(
                "solver.qp_form",
                format!(
                    "qp_form = \"{}\" poses the QP for clarabel, but qp_solver = \"active-set\" was asked for; drop qp_form or choose qp_solver = \"clarabel\"",
                    self.form
                ),
            ));
        }
        self.active_set.validate()
    }

    /// Whether clarabel must run this QP under `constraint`, whatever the size: asked for
    /// explicitly, or by an explicit clarabel form, or Gauss-point constraints (the
    /// matrix-free solver imposes σ ≥ 0 at the nodes only).
    pub fn needs_clarabel(&self, constraint: ConstraintPoints) -> bool {
        match self.solver {
            QpSolver::Clarabel => true,
            QpSolver::ActiveSet => false,
            QpSolver::Auto => self.form != QpForm::Auto || constraint == ConstraintPoints::Gauss,
        }
    }

    /// The solver that runs the QP on `foundation` under `constraint`, with T held as an FFT
    /// operator (`toeplitz`) or not. `Auto` keeps clarabel where it is robust and its form
    /// fits: Gauss-point constraints, explicit forms, and the half-space's dense Schur form on
    /// the dense route; the sparse primal form on Winkler soil stalls on stiff plates and on a
    /// plate balanced on one node, so Winkler with nodal constraints takes the active-set
    /// solver, as does every model on the iterative route.
    pub fn resolve(
        &self,
        foundation: FoundationKind,
        constraint: ConstraintPoints,
        toeplitz: bool,
    ) -> QpSolver {
        if self.needs_clarabel(constraint) {
            return QpSolver::Clarabel;
        }
        match self.solver {
            QpSolver::Auto if !foundation.is_local() && !toeplitz => QpSolver::Clarabel,
            QpSolver::Auto | QpSolver::ActiveSet => QpSolver::ActiveSet,
            QpSolver::Clarabel => QpSolver::Clarabel,
        }
    }
}

/// A solution method with its settings.
#[derive(Debug, Clone, PartialEq)]
pub enum Method {
    /// Bonded (bilateral) contact: one linear solve.
    Bonded,
    /// Unbonded contact by the penalty iteration.
    Penalty(PenaltySettings),
    /// Unbonded contact by the convex QP.
    Qp(QpSettings),
}

impl Method {
    /// The penalty iteration with default settings.
    pub fn penalty() -> Self {
        Method::Penalty(PenaltySettings::default())
    }

    /// The QP with default settings.
    pub fn qp() -> Self {
        Method::Qp(QpSettings::default())
    }

    /// The unbonded method of a kind, with default settings.
    pub fn unbonded(kind: MethodKind) -> Self {
        match kind {
            MethodKind::Penalty => Method::penalty(),
            MethodKind::Qp => Method::qp(),
        }
    }

    /// "bonded", "penalty" or "qp".
    pub fn name(&self) -> &'static str {
        match self {
            Method::Bonded => "bonded",
            Method::Penalty(_) => "penalty",
            Method::Qp(_) => "qp",
        }
    }

    /// How reports name the method ("direct" for bonded contact).
    pub fn solved_by(&self) -> SolvedBy {
        match self {
            Method::Bonded => SolvedBy::Direct,
            Method::Penalty(_) => SolvedBy::Penalty,
            Method::Qp(_) => SolvedBy::Qp,
        }
    }

    /// The contact law the method solves.
    pub fn contact(&self) -> Contact {
        match self {
            Method::Bonded => Contact::Bonded,
            _ => Contact::Unbonded,
        }
    }

    /// The unbonded method kind (None for bonded contact).
    pub fn kind(&self) -> Option<MethodKind> {
        match self {
            Method::Bonded => None,
            Method::Penalty(_) => Some(MethodKind::Penalty),
            Method::Qp(_) => Some(MethodKind::Qp),
        }
    }

    /// ε̄ of the penalty method (None for the others).
    pub fn penalty_epsilon(&self) -> Option<f64> {
        match self {
            Method::Penalty(s) => Some(s.epsilon),
            _ => None,
        }
    }

    /// Check the settings.
    pub fn validate(&self) -> Result<()> {
        match self {
            Method::Bonded => Ok(()),
            Method::Penalty(s) => s.validate(),
            Method::Qp(s) => s.validate(),
        }
    }
}
