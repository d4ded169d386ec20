//! Memory budget: how much a (model, method) pair will need, estimated from the planned mesh
//! before anything large is allocated, and the refusal of what will not fit.

use crate::error::{Error, Result};
use crate::foundation::FoundationKind;
use crate::mesh::Mesh;
use crate::method::Method;
use crate::model::Model;

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

/// Whether a method on this foundation forms the dense Schur complement S = T + BᵀK⁻B.
pub fn dense_schur(foundation: FoundationKind, method: &Method) -> bool {
    foundation == FoundationKind::HalfSpace || matches!(method, Method::Qp(_))
}

/// Rough memory need of the operators of `mesh` alone, bytes: sparse K with its triplets and a
/// nested-dissection Cholesky factor (≈ 31 n log₂ n entries for a 2-D grid with 3 dofs per
/// node, 16 bytes per stored entry), plus the dense T of a half-space.
pub fn operator_bytes(mesh: &Mesh, foundation: FoundationKind) -> f64 {
    let n = mesh.n_nodes() as f64;
    let n_eq = 3.0 * n;
    let sparse = n_eq * 81.0 * 32.0 + 31.0 * n_eq * n.max(2.0).log2() * 16.0;
    let dense_t = match foundation {
        FoundationKind::HalfSpace => n * n * 8.0,
        FoundationKind::Winkler => 0.0,
    };
    sparse + dense_t
}

/// Rough memory need of assembling `mesh` and solving it with `method`, bytes.
pub fn estimate_bytes(mesh: &Mesh, foundation: FoundationKind, method: &Method) -> f64 {
    let n = mesh.n_nodes() as f64;
    let n_eq = 3.0 * n;
    let mut bytes = operator_bytes(mesh, foundation);
    if dense_schur(foundation, method) {
        // The Schur complement S, its penalised copy and factor (and T where the operators do
        // not hold it already), plus a 256-column block of K⁻B.
        let t_held = if foundation == FoundationKind::HalfSpace {
            1.0
        } else {
            0.0
        };
        bytes += (4.0 - t_held) * n * n * 8.0 + n_eq * 256.0 * 8.0;
    }
    if matches!(method, Method::Qp(_)) {
        bytes += clarabel_dense_bytes(mesh.n_nodes());
    }
    bytes
}

/// Refuse a (model, method) pair that will not fit in `limit` bytes.
pub fn check(model: &Model, method: &Method, limit: f64) -> Result<()> {
    let (mesh, _) = model.plan_mesh();
    check_mesh(&mesh, model.groups.foundation, method, limit)
}

/// Refuse solving `mesh` with `method` when it will not fit in `limit` bytes.
pub fn check_mesh(
    mesh: &Mesh,
    foundation: FoundationKind,
    method: &Method,
    limit: f64,
) -> Result<()> {
    let need = estimate_bytes(mesh, foundation, method);
    if need <= limit {
        return Ok(());
    }
    let hint = if dense_schur(foundation, method) {
        format!(
            "the dense operators grow with the square of the {} pressure nodes: use fewer elements (halving each side divides memory by about 16) or an even mesh with symmetric loads",
            mesh.n_nodes()
        )
    } else {
        "use fewer elements, or an even mesh with symmetric loads".to_string()
    };
    Err(Error::TooLarge {
        what: format!(
            "a {} model of {} × {} elements ({} nodes)",
            mesh.symmetry_name(),
            mesh.nx,
            mesh.ny,
            mesh.n_nodes()
        ),
        need_gib: need / GIB,
        limit_gib: limit / GIB,
        hint,
    })
}
