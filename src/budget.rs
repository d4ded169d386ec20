//! Memory budget: how much a (model, method) pair will need, estimated from the planned mesh
//! before anything large is allocated, and the refusal of what will not fit.

use crate::error::{Error, Result};
use crate::foundation::FoundationKind;
use crate::mesh::Mesh;
use crate::method::{Method, QpForm, QpSolver, Route};
use crate::model::{ConstraintPoints, Model};

const GIB: f64 = 1024.0 * 1024.0 * 1024.0;

/// Memory available to the process: 3/4 of MemTotal from /proc/meminfo, or 8 GiB if unknown.
pub fn default_memory_limit() -> f64 {
    let total = std::fs::read_to_string("/proc/meminfo").ok().and_then(|s| {
        s.lines()
            .find(|l| l.starts_with("MemTotal:"))
            .and_then(|l| {
                l.split_whitespace()
                    .nth(1)
                    .and_then(|k| k.parse::<f64>().ok())
            })
            .map(|kib| kib * 1024.0)
    });
    0.75 * total.unwrap_or(8.0 * GIB / 0.75)
}

/// Bytes clarabel needs for a dense P of size n (measured ≈ 47 n², BENCHMARKS.md).
pub fn clarabel_dense_bytes(n: usize) -> f64 {
    47.0 * (n as f64).powi(2)
}

/// Whether a method on this foundation forms the dense Schur complement S = T + BᵀK⁻B on the
/// dense route: every half-space penalty or bonded solve, and clarabel's Schur form of the QP
/// (the matrix-free QP never forms it).
pub fn dense_schur(
    foundation: FoundationKind,
    constraint: ConstraintPoints,
    method: &Method,
) -> bool {
    match method {
        Method::Qp(s) => {
            s.resolve(foundation, constraint, false) == QpSolver::Clarabel
                && s.form.is_dense(foundation)
        }
        _ => !foundation.is_local(),
    }
}

/// The matrix-free QP's own memory beyond the operators, bytes: a second sparse factor of the
/// plate's size (the preconditioner's plate on springs beside the plate's generalised inverse)
/// and some 40 vectors of n_σ and n_eq.
pub fn active_set_bytes(mesh: &Mesh) -> f64 {
    let n = mesh.n_nodes() as f64;
    let n_eq = 3.0 * n;
    31.0 * n_eq * n.max(2.0).log2() * 16.0 + 40.0 * (n + n_eq) * 8.0
}

/// clarabel's sparse KKT factorisation for the sparse QP forms, bytes, fitted to the peaks
/// measured from 80 to 400 elements per side (BENCHMARKS.md) with a margin of 1.5: primal
/// n_eq (1170 + 146 log₂ n_eq) with nodal constraints (3.5× that with Gauss points, whose rows
/// add the z block), lifted n_eq (3840 + 393 log₂ n_eq).
pub fn clarabel_sparse_bytes(n_eq: usize, form: QpForm, constraint: ConstraintPoints) -> f64 {
    let n = n_eq as f64;
    let log = n.max(2.0).log2();
    let base = match form {
        QpForm::Lifted => n * (3840.0 + 393.0 * log),
        _ => n * (1170.0 + 146.0 * log),
    };
    let gauss = if constraint == ConstraintPoints::Gauss && form != QpForm::Lifted {
        3.5
    } else {
        1.0
    };
    1.5 * base * gauss
}

/// Rough memory need of the operators of `mesh` alone, bytes: sparse K with its triplets and a
/// nested-dissection Cholesky factor (≈ 31 n log₂ n entries for a 2-D grid with 3 dofs per
/// node, 16 bytes per stored entry), plus the dense T of a half-space.
pub fn operator_bytes(mesh: &Mesh, foundation: FoundationKind) -> f64 {
    let n = mesh.n_nodes() as f64;
    let n_eq = 3.0 * n;
    let sparse = n_eq * 81.0 * 32.0 + 31.0 * n_eq * n.max(2.0).log2() * 16.0;
    let dense_t = if foundation.is_local() {
        0.0
    } else {
        n * n * 8.0
    };
    sparse + dense_t
}

/// Rough memory need of assembling `mesh` and solving it with `method`, bytes.
pub fn estimate_bytes(
    mesh: &Mesh,
    foundation: FoundationKind,
    constraint: ConstraintPoints,
    method: &Method,
) -> f64 {
    let n = mesh.n_nodes() as f64;
    let n_eq = 3.0 * n;
    let mut bytes = operator_bytes(mesh, foundation);
    if dense_schur(foundation, constraint, method) {
        // The Schur complement S, its penalised copy and factor (and T where the operators do
        // not hold it already), plus a 256-column block of K⁻B.
        let t_held = if !foundation.is_local() { 1.0 } else { 0.0 };
        bytes += (4.0 - t_held) * n * n * 8.0 + n_eq * 256.0 * 8.0;
    }
    if let Method::Qp(s) = method {
        bytes += if s.resolve(foundation, constraint, false) == QpSolver::ActiveSet {
            active_set_bytes(mesh)
        } else if s.form.is_dense(foundation) {
            clarabel_dense_bytes(mesh.n_nodes())
        } else {
            clarabel_sparse_bytes(3 * mesh.n_nodes(), s.form, constraint)
        };
    }
    bytes
}

/// Rough memory need of the iterative route (half-space T as an FFT operator, penalty steps by
/// conjugate gradients), bytes: the sparse operators with the plate's Cholesky factor (as
/// [`operator_bytes`] counts them), the preconditioner's factor on a grid twice as coarse (a
/// quarter of that), the FFT kernels and work arrays
/// ([`crate::foundation::fft::toeplitz_bytes`]) and some 40 vectors of n_σ and n_eq. Like the
/// other estimates it errs high: 2.6 GiB predicted for 512 × 512 elements (quarter model)
/// against 0.65 GiB measured (BENCHMARKS.md).
pub fn iterative_bytes(mesh: &Mesh) -> f64 {
    let n = mesh.n_nodes() as f64;
    let n_eq = 3.0 * n;
    let factor = 31.0 * n_eq * n.max(2.0).log2() * 16.0;
    operator_bytes(mesh, FoundationKind::Winkler)
        + 0.25 * factor
        + crate::foundation::fft::toeplitz_bytes(mesh) as f64
        + 40.0 * (n + n_eq) * 8.0
}

/// Whether the half-space T of `model` is held as an FFT operator on `route` when solved with
/// `method` (false for Winkler, whose T is diagonal anyway); an error when the route cannot
/// serve the method (a QP that clarabel must solve, on the iterative route).
pub fn toeplitz(model: &Model, method: &Method, route: Route) -> Result<bool> {
    let (mesh, _) = model.plan_mesh();
    let iterative = route.iterative(mesh.n_nodes(), method, model.constraint)?;
    Ok(iterative && !model.groups.foundation().is_local())
}

/// Refuse a (model, method) pair that will not fit in `limit` bytes on `route`; returns whether
/// the operators are to hold T as an FFT operator ([`crate::Operators::assemble_with`]).
pub fn check_route(model: &Model, method: &Method, route: Route, limit: f64) -> Result<bool> {
    let toeplitz = toeplitz(model, method, route)?;
    if !toeplitz {
        check(model, method, limit)?;
        return Ok(false);
    }
    let (mesh, _) = model.plan_mesh();
    let need = iterative_bytes(&mesh);
    if need <= limit {
        return Ok(true);
    }
    Err(too_large(
        &mesh,
        " on the iterative route",
        need,
        limit,
        "memory grows about linearly with the nodes here: use fewer elements, or an even mesh with symmetric loads".into(),
    ))
}

/// Refuse a (model, method) pair that will not fit in `limit` bytes on the dense route.
pub fn check(model: &Model, method: &Method, limit: f64) -> Result<()> {
    let (mesh, _) = model.plan_mesh();
    check_mesh(
        &mesh,
        model.groups.foundation(),
        model.constraint,
        method,
        limit,
    )
}

/// Refuse solving `mesh` with `method` when it will not fit in `limit` bytes.
pub fn check_mesh(
    mesh: &Mesh,
    foundation: FoundationKind,
    constraint: ConstraintPoints,
    method: &Method,
    limit: f64,
) -> Result<()> {
    let need = estimate_bytes(mesh, foundation, constraint, method);
    if need <= limit {
        return Ok(());
    }
    let hint = if dense_schur(foundation, constraint, method) {
        format!(
            "the dense operators grow with the square of the {} pressure nodes: use fewer elements (halving each side divides memory by about 16) or an even mesh with symmetric loads",
            mesh.n_nodes()
        )
    } else {
        "use fewer elements, or an even mesh with symmetric loads".to_string()
    };
    Err(too_large(mesh, "", need, limit, hint))
}

/// The refusal of a model of `mesh` that needs `need` bytes of `limit`.
fn too_large(mesh: &Mesh, route: &str, need: f64, limit: f64, hint: String) -> Error {
    Error::TooLarge {
        what: format!(
            "a {} model of {} × {} elements ({} nodes){route}",
            mesh.symmetry_name(),
            mesh.nx,
            mesh.ny,
            mesh.n_nodes()
        ),
        need_gib: need / GIB,
        limit_gib: limit / GIB,
        hint,
    }
}
