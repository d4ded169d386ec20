//! What each solver reports about itself: clarabel's residuals, the matrix-free QP's account
//! and KKT residuals, one conjugate-gradient solve.

/// clarabel's account of a QP solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QpDiagnostics {
    /// Primal residual.
    pub primal_residual: f64,
    /// Dual residual.
    pub dual_residual: f64,
    /// Objective value.
    pub objective: f64,
    /// |primal − dual objective|.
    pub duality_gap: f64,
    /// The sparse forms' consistency check: (name, relative mismatch) of two ways to read the
    /// answer (`gap_mismatch` lifted, `sigma_mismatch` primal).
    pub form_check: Option<(&'static str, f64)>,
}

impl QpDiagnostics {
    /// (name, value) pairs, as in summary.json's `solver_info`.
    pub fn named(&self) -> Vec<(&'static str, f64)> {
        let mut v = vec![
            ("primal_residual", self.primal_residual),
            ("dual_residual", self.dual_residual),
            ("objective", self.objective),
            ("duality_gap", self.duality_gap),
        ];
        v.extend(self.form_check);
        v
    }
}

/// The KKT residuals of a QP solution, each relative to its scale.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct KktResiduals {
    /// max |min(σᵢ/σ_max, gᵢ/g_s)|: zero exactly when σ ≥ 0, g ≥ 0 and σ·g = 0.
    pub natural: f64,
    /// Largest |gᵢ| / g_s where σᵢ > 0 (the gap that should be closed).
    pub stationarity: f64,
    /// Largest −gᵢ / g_s where σᵢ = 0 (penetration of a lifted point).
    pub penetration: f64,
    /// max |σᵢ gᵢ| / (σ_max g_s).
    pub complementarity: f64,
    /// |Cᵀσ − Rᵀf|∞ / |Rᵀf|∞: the rigid-body equilibrium.
    pub equilibrium: f64,
}

/// The matrix-free solver's account of a solve.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ActiveSetDiagnostics {
    /// Outer (active-set) iterations: face solves.
    pub iterations: usize,
    /// Conjugate-gradient iterations over all face solves.
    pub cg_iterations: usize,
    /// Products with S (each one T product and one plate solve), CG and line search.
    pub products: usize,
    /// Preconditioner factorisations (one per new held set).
    pub factorisations: usize,
    /// Face solves of the safeguard (the monotone primal active set), after the primal–dual
    /// sets cycled; 0 when the primal–dual iteration finished alone.
    pub safeguard_steps: usize,
    /// Safeguard steps cut short by the ratio test (σ* had negative pressures).
    pub projected_steps: usize,
    /// Objective ½σᵀSσ − hᵀσ at the solution; None where the plate on springs alone solved a
    /// slab fully in contact (h = BᵀK⁻f needs the plate's own factor, which was not made).
    pub objective: Option<f64>,
    /// The KKT residuals at the solution.
    pub kkt: KktResiduals,
}

impl ActiveSetDiagnostics {
    /// (name, value) pairs, as in summary.json's `solver_info`.
    pub fn named(&self) -> Vec<(&'static str, f64)> {
        let mut named = vec![
            ("outer_iterations", self.iterations as f64),
            ("cg_iterations", self.cg_iterations as f64),
            ("schur_products", self.products as f64),
            ("factorisations", self.factorisations as f64),
            ("safeguard_steps", self.safeguard_steps as f64),
            ("projected_steps", self.projected_steps as f64),
            ("kkt_natural", self.kkt.natural),
            ("kkt_stationarity", self.kkt.stationarity),
            ("kkt_penetration", self.kkt.penetration),
            ("kkt_complementarity", self.kkt.complementarity),
            ("kkt_equilibrium", self.kkt.equilibrium),
        ];
        if let Some(f) = self.objective {
            named.insert(6, ("objective", f));
        }
        named
    }
}

/// How one linear solve went.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct CgReport {
    /// Conjugate-gradient iterations.
    pub iterations: usize,
    /// Final relative preconditioned residual.
    pub residual: f64,
    /// Relative residual ‖Aσ − Cα − h‖ / ‖h‖ of the returned solution: recomputed (a fresh
    /// product) on solves to the settings' tolerance; on a penalty step solved to the loose one,
    /// from the products the iterations updated (no plate solve spent on a step that only has to
    /// give the pressures' signs; the confirming solve recomputes them).
    pub true_residual: f64,
}
