//! Verification of the MITC4 Mindlin plate element (src/plate.rs) and its assembly on the
//! structured grid (src/mesh.rs, src/operators.rs::load_vector) against references that the code
//! does not produce:
//!
//! 1. the kinematics of a free element (exactly three rigid-body modes, from γ = ∇w − ψ and
//!    κ = sym ∇ψ);
//! 2. patch tests: exact polynomial Mindlin states with constant curvature / twist / shear;
//! 3. convergence to classical Kirchhoff solutions of square plates (Navier and Lévy series,
//!    Timoshenko & Woinowsky-Krieger tables, Taylor & Govindjee 2004) at a/H = 10⁴, with the
//!    Mindlin shear correction of the simply supported plate checked against Wang's exact
//!    Kirchhoff–Mindlin relation;
//! 4. element-vector consistency (energy gradient = K u, K positive semi-definite) by proptest.
//!
//! Units: D = 1, a = 1, q = 1, P = 1 throughout §3, so every deflection is the dimensionless
//! coefficient of q a⁴/D or P a²/D. Sign convention of the crate: w and loads positive downward.

use liftoff::mesh::{Dof, DofMap, Mesh};
use liftoff::model::Load;
use liftoff::operators::load_vector;
use liftoff::plate::{
    assemble_stiffness, centre_resultants, element_stiffness, ElementMatrix, ElementVector,
    Section, NODE_ETA, NODE_XI,
};
use liftoff::solve::linalg::{sparse_solve, SparseCholesky};
use nalgebra::{SMatrix, SVector, SymmetricEigen};
use proptest::prelude::*;

const NU: f64 = 0.3;

/// Section of an isotropic plate of thickness `h` with flexural rigidity `d`:
/// D = E H³ / (12 (1 − ν²)) ⇒ E; G = E / (2 (1 + ν)); κs = χ G H with χ = 5/6.
fn section_of_thickness(d: f64, h: f64) -> Section {
    let e = 12.0 * (1.0 - NU * NU) * d / h.powi(3);
    let g = e / (2.0 * (1.0 + NU));
    Section {
        bending: d,
        shear: 5.0 / 6.0 * g * h,
        poisson: NU,
    }
}

/// Solve K u = f with some equations prescribed (`prescribed[eq] = Some(value)`): the reduced
/// system K_ff u_f = f_f − K_fc u_c is built here from the assembled CSC matrix by dropping the
/// prescribed rows and columns, and factored with the crate's faer sparse Cholesky. Returns the
/// whole vector (prescribed values in place).
fn solve_prescribed(k: &sprs::CsMat<f64>, f: &[f64], prescribed: &[Option<f64>]) -> Vec<f64> {
    let n = k.rows();
    assert_eq!(k.cols(), n);
    assert_eq!(f.len(), n);
    assert_eq!(prescribed.len(), n);
    // assemble_stiffness is documented as CSC; work on an explicit CSC copy so that the column
    // loop below is right whatever storage flag the matrix carries (to_csc converts a CSR
    // matrix and clones a CSC one).
    let k = &k.to_csc();
    let mut map = vec![None; n];
    let mut n_free = 0;
    for (e, p) in prescribed.iter().enumerate() {
        if p.is_none() {
            map[e] = Some(n_free);
            n_free += 1;
        }
    }
    let mut rhs = vec![0.0; n_free];
    for (e, m) in map.iter().enumerate() {
        if let Some(r) = m {
            rhs[*r] = f[e];
        }
    }
    let mut indptr = vec![0usize];
    let mut indices = Vec::new();
    let mut data = Vec::new();
    for (j, col) in k.outer_iterator().enumerate() {
        match (map[j], prescribed[j]) {
            (Some(_), _) => {
                for (i, &v) in col.iter() {
                    if let Some(r) = map[i] {
                        indices.push(r);
                        data.push(v);
                    }
                }
                indptr.push(indices.len());
            }
            (None, Some(uc)) => {
                for (i, &v) in col.iter() {
                    if let Some(r) = map[i] {
                        rhs[r] -= v * uc;
                    }
                }
            }
            (None, None) => unreachable!(),
        }
    }
    let kr = sprs::CsMat::new((n_free, n_free), indptr, indices, data);
    let chol = SparseCholesky::analyse(&kr).expect("symbolic analysis of K_ff");
    let llt = chol
        .factor(&kr, "K_ff")
        .expect("K_ff must be positive definite once supported");
    sparse_solve(&llt, &mut rhs);
    let mut u = vec![0.0; n];
    for e in 0..n {
        u[e] = match (map[e], prescribed[e]) {
            (Some(r), _) => rhs[r],
            (None, Some(v)) => v,
            (None, None) => unreachable!(),
        };
    }
    u
}

// ------------------------------------------------------------------------------------------
// 1. A free element has exactly the three rigid-body modes.
// ------------------------------------------------------------------------------------------

/// The rigid-body modes of an hx × hy element centred at (xc, yc), as columns:
/// w = 1; (w = x, ψx = 1); (w = y, ψy = 1). Each gives γ = ∇w − ψ = 0 and κ = 0.
fn rigid_modes(hx: f64, hy: f64, xc: f64, yc: f64) -> SMatrix<f64, 12, 3> {
    let mut r = SMatrix::<f64, 12, 3>::zeros();
    for a in 0..4 {
        let x = xc + 0.5 * hx * NODE_XI[a];
        let y = yc + 0.5 * hy * NODE_ETA[a];
        r[(3 * a, 0)] = 1.0;
        r[(3 * a, 1)] = x;
        r[(3 * a + 1, 1)] = 1.0;
        r[(3 * a, 2)] = y;
        r[(3 * a + 2, 2)] = 1.0;
    }
    r
}

fn check_free_element(case: &str, section: &Section, hx: f64, hy: f64) {
    let k: ElementMatrix = element_stiffness(section, hx, hy);
    let kmax = k.abs().max();
    // Symmetric by construction (Bᵀ C B sums); symmetrise only the last-bit round-off before
    // the symmetric eigensolver, after checking it is round-off (16 ulps of the largest entry).
    assert!(
        (k - k.transpose()).abs().max() <= 16.0 * f64::EPSILON * kmax,
        "{case}: element stiffness is not symmetric"
    );
    let ks = 0.5 * (k + k.transpose());
    let eig = SymmetricEigen::new(ks);
    let lmax = eig.eigenvalues.abs().max();
    // A zero eigenvalue: |λ| < 1e-10 λmax. The eigensolver's absolute error is O(12 ε λmax)
    // ≈ 3e-15 λmax, so true zeros sit far below this threshold; the nonzero eigenvalues are
    // checked to sit far above it (the gap is reported in the message).
    let threshold = 1e-10 * lmax;
    let mut order: Vec<usize> = (0..12).collect();
    order.sort_by(|&i, &j| {
        eig.eigenvalues[i]
            .abs()
            .total_cmp(&eig.eigenvalues[j].abs())
    });
    let zeros: Vec<usize> = order
        .iter()
        .copied()
        .filter(|&i| eig.eigenvalues[i].abs() < threshold)
        .collect();
    let smallest_nonzero = eig.eigenvalues[order[3]].abs();
    eprintln!(
        "[free element {case}] λmax = {lmax:.3e}, |λ| sorted: {:?}",
        order
            .iter()
            .map(|&i| format!("{:.2e}", eig.eigenvalues[i]))
            .collect::<Vec<_>>()
    );
    assert_eq!(
        zeros.len(),
        3,
        "{case}: MITC4 element {hx}×{hy} must have exactly 3 zero-energy modes (found {}; sorted |λ|/λmax = {:?})",
        zeros.len(),
        order.iter().map(|&i| eig.eigenvalues[i].abs() / lmax).collect::<Vec<_>>()
    );
    // No eigenvalue is negative beyond round-off (positive semi-definite).
    assert!(
        eig.eigenvalues.min() > -threshold,
        "{case}: negative eigenvalue {:.3e} (λmax {lmax:.3e})",
        eig.eigenvalues.min()
    );
    // An unambiguous classification: the three zeros are at round-off level (≤ 1e-13 λmax,
    // i.e. ~40 × the eigensolver's 12 ε λmax) and the 4th eigenvalue — the softest genuine
    // deformation mode, a bending mode of size ~D independent of κs — is at least two decades
    // above the threshold. (For thinner elements λmax ∝ κs grows without bound and the fixed
    // 1e-10 λmax threshold would eventually swallow the bending modes; that is a limit of the
    // criterion, not of the element, hence the thicknesses chosen below.)
    for &i in &zeros {
        assert!(
            eig.eigenvalues[i].abs() <= 1e-13 * lmax,
            "{case}: 'zero' eigenvalue {:.3e} is above round-off (λmax {lmax:.3e})",
            eig.eigenvalues[i]
        );
    }
    assert!(
        smallest_nonzero > 100.0 * threshold,
        "{case}: near-spurious mode, smallest nonzero |λ| = {smallest_nonzero:.3e} vs λmax {lmax:.3e}"
    );

    // The kinematic rigid modes are in the null space: ‖K r‖ ≤ 1e-12 ‖K‖ ‖r‖. K r cancels sums
    // of at most 12 entries of size ≤ ‖K‖, so round-off is ≈ 12 ε ‖K‖ ‖r‖ ≈ 3e-15 ‖K‖ ‖r‖; the
    // margin of ~300 absorbs the round-off of K itself (sums of 4 Gauss terms).
    // The element is placed off the origin so that w = x is not just odd about the centre.
    for (xc, yc) in [(0.0, 0.0), (1.3, -0.8)] {
        let r = rigid_modes(hx, hy, xc, yc);
        for c in 0..3 {
            let col = r.column(c).into_owned();
            let kr = k * col;
            assert!(
                kr.norm() <= 1e-12 * k.norm() * col.norm(),
                "{case}: rigid mode {c} at centre ({xc}, {yc}) is not in the null space: ‖K r‖ = {:.3e}, ‖K‖ ‖r‖ = {:.3e}",
                kr.norm(),
                k.norm() * col.norm()
            );
        }
    }

    // …and they span the whole numerical null space: the eigenvectors of the 3 zero eigenvalues
    // lie in span(R). By Davis–Kahan the angle between the computed and the exact null space is
    // ≤ ‖E‖ / gap with ‖E‖ ≈ 12 ε λmax the backward error of the eigensolver; allow 100× that.
    let r = rigid_modes(hx, hy, 0.0, 0.0);
    let q = r.qr().q(); // orthonormal basis of span(R), 12 × 3
    let tol = 100.0 * 12.0 * f64::EPSILON * lmax / smallest_nonzero;
    for &i in &zeros {
        let v = eig.eigenvectors.column(i).into_owned();
        let resid = v - q * (q.transpose() * v);
        assert!(
            resid.norm() <= tol,
            "{case}: zero-eigenvalue eigenvector {i} leaves span(rigid modes) by {:.3e} (tol {tol:.3e})",
            resid.norm()
        );
    }
}

#[test]
fn free_element_has_exactly_three_rigid_modes() {
    let (hx, hy) = (0.7, 0.4);
    // Thin: H = 1e-3 × the element length (κs hx²/D ≈ 3.5e6).
    check_free_element(
        "thin 0.7×0.4, H/hx = 1e-3",
        &section_of_thickness(1.0, 0.7e-3),
        hx,
        hy,
    );
    // Thick: H = half the element length.
    check_free_element(
        "thick 0.7×0.4, H/hx = 0.5",
        &section_of_thickness(1.0, 0.35),
        hx,
        hy,
    );
    // Other aspect ratio, elongated along y.
    check_free_element(
        "thick 0.3×1.1, H/hx = 0.3",
        &section_of_thickness(2.5, 0.09),
        0.3,
        1.1,
    );
}

// ------------------------------------------------------------------------------------------
// 2. Patch tests on structured grids with non-square elements.
// ------------------------------------------------------------------------------------------

/// An exact Mindlin state (w, ψx, ψy)(x, y).
type Field = dyn Fn(f64, f64) -> [f64; 3];

/// Impose `exact` on every boundary node of a whole-plate grid, apply `interior_load` (the
/// consistent nodal loads, given per interior node as [f_w, f_ψx, f_ψy]), solve, and return the
/// largest interior error relative to the largest nodal value of the exact field.
fn patch_error(mesh: &Mesh, section: &Section, exact: &Field, interior_load: [f64; 3]) -> f64 {
    assert!(!mesh.sym_x && !mesh.sym_y);
    let dofs = DofMap::new(mesh);
    let k = assemble_stiffness(mesh, &dofs, section);
    let n_eq = dofs.n_eq();
    let mut f = vec![0.0; n_eq];
    let mut prescribed = vec![None; n_eq];
    let mut expect = vec![0.0; n_eq];
    let mut interior = Vec::new();
    for node in 0..mesh.n_nodes() {
        let i = node % mesh.nodes_x();
        let j = node / mesh.nodes_x();
        let (x, y) = mesh.node_xy(node);
        let ex = exact(x, y);
        let boundary = i == 0 || j == 0 || i == mesh.nx || j == mesh.ny;
        for (d, dof) in [Dof::W, Dof::PsiX, Dof::PsiY].into_iter().enumerate() {
            let e = dofs
                .eq(node, dof)
                .expect("no symmetry constraints in a whole-plate model");
            expect[e] = ex[d];
            if boundary {
                prescribed[e] = Some(ex[d]);
            } else {
                f[e] = interior_load[d];
                interior.push(e);
            }
        }
    }
    assert!(!interior.is_empty());
    let u = solve_prescribed(&k, &f, &prescribed);
    let scale = expect.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    interior
        .iter()
        .map(|&e| (u[e] - expect[e]).abs())
        .fold(0.0, f64::max)
        / scale
}

/// Patch meshes: 2 × 1.5 plates with 4 × 3 (square 0.5 elements) and 4 × 5 (0.5 × 0.3) elements.
fn patch_meshes() -> Vec<(&'static str, Mesh)> {
    vec![
        (
            "2×1.5 plate, 4×3 elements",
            Mesh::new(2.0, 1.5, [4, 3], false, false),
        ),
        (
            "2×1.5 plate, 4×5 elements (0.5×0.3)",
            Mesh::new(2.0, 1.5, [4, 5], false, false),
        ),
        (
            "2×1.5 plate, 5×3 elements (0.4×0.5)",
            Mesh::new(2.0, 1.5, [5, 3], false, false),
        ),
    ]
}

/// Patch-test sections with the tolerance of each. The discrete solution equals the nodal
/// values of the exact field in exact arithmetic (bilinear ψ reproduces linear rotations; the
/// MITC4 tying of γ at edge mid-points is exact for a quadratic w with ψ = ∇w, and for a linear
/// w with ψ = 0), so the only error is the round-off of the Cholesky solve, ≈ cond(K_ff) ε.
/// cond(K_ff) grows like κs h² / D (the shear-to-bending stiffness ratio of an element):
/// - H = 0.2 (κs h²/D ≈ 22) and H = 1e-2 (≈ 9e3, a/H = 200): cond·ε ≲ 1e-11, so the brief's
///   1e-10 holds with margin;
/// - H = 1e-3 (≈ 9e5): cond·ε ≈ 1e-10 by the same scaling (observed up to 1.5e-10), so the
///   tolerance is raised in proportion to κs, to 1e-8. A non-passing element would miss by
///   O(1), not by round-off.
fn patch_sections() -> Vec<(&'static str, Section, f64)> {
    vec![
        ("H = 0.2", section_of_thickness(1.0, 0.2), 1e-10),
        ("H = 1e-2", section_of_thickness(1.0, 1e-2), 1e-10),
        ("H = 1e-3", section_of_thickness(1.0, 1e-3), 1e-8),
    ]
}

#[test]
fn constant_curvature_and_twist_patch_tests() {
    let k = 0.37; // curvature / twist amplitude, arbitrary
    let cases: Vec<(&str, Box<Field>)> = vec![
        // Pure bending about y: w = ½ κ x², ψ = ∇w ⇒ γ = 0, κxx = κ.
        (
            "pure bending w = ½κx²",
            Box::new(move |x: f64, _y: f64| [0.5 * k * x * x, k * x, 0.0]),
        ),
        // Pure bending about x: w = ½ κ y².
        (
            "pure bending w = ½κy²",
            Box::new(move |_x: f64, y: f64| [0.5 * k * y * y, 0.0, k * y]),
        ),
        // Twist: w = κ x y, ψx = κ y, ψy = κ x.
        (
            "twist w = κxy",
            Box::new(move |x: f64, y: f64| [k * x * y, k * y, k * x]),
        ),
        // General Kirchhoff-compatible quadratic with rigid parts, off-centre so that nothing
        // relies on the symmetry of the patch.
        (
            "general quadratic w",
            Box::new(|x: f64, y: f64| {
                let (c0, c1, c2, k1, k2, k3) = (0.2, -0.4, 0.15, 0.8, -0.55, 0.3);
                let xs = x - 0.31;
                let ys = y + 0.17;
                [
                    c0 + c1 * x + c2 * y + 0.5 * k1 * xs * xs + 0.5 * k2 * ys * ys + k3 * xs * ys,
                    c1 + k1 * xs + k3 * ys,
                    c2 + k2 * ys + k3 * xs,
                ]
            }),
        ),
    ];
    for (mname, mesh) in patch_meshes() {
        for (sname, section, tol) in patch_sections() {
            for (cname, field) in &cases {
                let err = patch_error(&mesh, &section, field.as_ref(), [0.0; 3]);
                eprintln!("[patch] {cname} on {mname}, {sname}: rel. error {err:.2e}");
                assert!(
                    err <= tol,
                    "MITC4 constant-curvature patch test '{cname}' on {mname}, {sname}: interior relative error {err:.3e} > {tol:e}"
                );
            }
        }
    }
}

/// Constant transverse shear: w = γx x + γy y, ψ = 0 gives γ = (γx, γy) constant and κ = 0.
///
/// This state is NOT load-free: with U = ½∫κᵀD_bκ + ½κs∫γᵀγ, stationarity in ψx reads
/// ∂mx/∂x + ∂mxy/∂y − Qx + m_x = 0 with Q = κs γ, so with zero moments a distributed couple
/// m = (−κs γx, −κs γy) per unit area (work ∫ m·ψ) must act. Its consistent nodal load at an
/// interior node is m ∫ N_a dA = m hx hy (four quarter-elements, ∫ N_a = hx hy / 4 each); the
/// transverse load is zero (∇·Q = 0). The test imposes the exact state on the boundary, applies
/// that hand-computed load and checks the interior reproduces the state.
#[test]
fn constant_shear_patch_test() {
    let states: [(&str, f64, f64); 3] = [
        ("γxz only", 0.013, 0.0),
        ("γyz only", 0.0, -0.021),
        ("both", 0.017, 0.009),
    ];
    for (mname, mesh) in patch_meshes() {
        for (sname, section, tol) in patch_sections() {
            for &(cname, gx, gy) in &states {
                let field = move |x: f64, y: f64| [0.05 + gx * x + gy * y, 0.0, 0.0];
                let area = mesh.hx * mesh.hy;
                let load = [0.0, -section.shear * gx * area, -section.shear * gy * area];
                let err = patch_error(&mesh, &section, &field, load);
                eprintln!(
                    "[patch] constant shear {cname} on {mname}, {sname}: rel. error {err:.2e}"
                );
                assert!(
                    err <= tol,
                    "MITC4 constant-shear patch test ({cname}) on {mname}, {sname}: interior relative error {err:.3e} > {tol:e}"
                );
                // Superposed on a constant-curvature state (linearity of the patch test).
                let combined = move |x: f64, y: f64| {
                    let (k1, k2, k3) = (0.4, -0.25, 0.6);
                    [
                        gx * x + gy * y + 0.5 * k1 * x * x + 0.5 * k2 * y * y + k3 * x * y,
                        k1 * x + k3 * y,
                        k2 * y + k3 * x,
                    ]
                };
                let err = patch_error(&mesh, &section, &combined, load);
                assert!(
                    err <= tol,
                    "MITC4 constant-shear + curvature patch test ({cname}) on {mname}, {sname}: interior relative error {err:.3e} > {tol:e}"
                );
            }
        }
    }
}

/// The same patch tests on a graded (non-uniform) rectangular grid, assembled densely here from
/// `element_stiffness` with a different hx, hy in every element. On the crate's uniform grids the
/// symmetric interior stencil can cancel the residual of a quadratic field even for a
/// non-conforming or locking shear interpolation, so only a graded grid makes the patch test
/// bite on the element itself. A distributed couple m (per unit area) loads node a of each
/// element with m hx hy / 4 (= m ∫ N_a dA).
fn graded_patch_error(
    xs: &[f64],
    ys: &[f64],
    section: &Section,
    exact: &Field,
    couple: [f64; 2],
) -> f64 {
    let (nxn, nyn) = (xs.len(), ys.len());
    let n = 3 * nxn * nyn;
    let node = |i: usize, j: usize| i + j * nxn;
    let mut k = nalgebra::DMatrix::<f64>::zeros(n, n);
    let mut f = nalgebra::DVector::<f64>::zeros(n);
    for j in 0..nyn - 1 {
        for i in 0..nxn - 1 {
            let (hx, hy) = (xs[i + 1] - xs[i], ys[j + 1] - ys[j]);
            let ke = element_stiffness(section, hx, hy);
            let nodes = [
                node(i, j),
                node(i + 1, j),
                node(i + 1, j + 1),
                node(i, j + 1),
            ];
            for a in 0..4 {
                f[3 * nodes[a] + 1] += couple[0] * hx * hy / 4.0;
                f[3 * nodes[a] + 2] += couple[1] * hx * hy / 4.0;
                for b in 0..4 {
                    for p in 0..3 {
                        for q in 0..3 {
                            k[(3 * nodes[a] + p, 3 * nodes[b] + q)] += ke[(3 * a + p, 3 * b + q)];
                        }
                    }
                }
            }
        }
    }
    let mut expect = nalgebra::DVector::<f64>::zeros(n);
    let mut free = Vec::new();
    let mut fixed = Vec::new();
    for (j, &y) in ys.iter().enumerate() {
        for (i, &x) in xs.iter().enumerate() {
            let boundary = i == 0 || j == 0 || i == nxn - 1 || j == nyn - 1;
            for (d, v) in exact(x, y).into_iter().enumerate() {
                let e = 3 * node(i, j) + d;
                expect[e] = v;
                if boundary {
                    fixed.push(e)
                } else {
                    free.push(e)
                }
            }
        }
    }
    let kff = k.select_rows(&free).select_columns(&free);
    let kfc = k.select_rows(&free).select_columns(&fixed);
    let uc = expect.select_rows(&fixed);
    let rhs = f.select_rows(&free) - kfc * uc;
    let uf = kff
        .cholesky()
        .expect("K_ff of the graded patch is positive definite")
        .solve(&rhs);
    let scale = expect.amax();
    free.iter()
        .zip(uf.iter())
        .map(|(&e, &v)| (v - expect[e]).abs())
        .fold(0.0, f64::max)
        / scale
}

#[test]
fn patch_tests_on_a_graded_grid() {
    // 5 × 4 elements on a 2 × 1.5 plate with sizes from 0.2 to 0.65 (aspect ratios 0.3–3).
    let xs = [-1.0, -0.55, -0.35, 0.1, 0.45, 1.0];
    let ys = [-0.75, -0.55, -0.1, 0.2, 0.75];
    let (k1, k2, k3) = (0.8, -0.55, 0.3);
    let bending = move |x: f64, y: f64| {
        let (xs, ys) = (x - 0.31, y + 0.17);
        [
            0.2 - 0.4 * x + 0.15 * y + 0.5 * k1 * xs * xs + 0.5 * k2 * ys * ys + k3 * xs * ys,
            -0.4 + k1 * xs + k3 * ys,
            0.15 + k2 * ys + k3 * xs,
        ]
    };
    let (gx, gy) = (0.017, -0.009);
    let shear = move |x: f64, y: f64| [0.05 + gx * x + gy * y, 0.0, 0.0];
    let both = move |x: f64, y: f64| {
        let b = bending(x, y);
        let s = shear(x, y);
        [b[0] + s[0], b[1], b[2]]
    };
    for (sname, section, tol) in patch_sections() {
        let m = [-section.shear * gx, -section.shear * gy];
        for (cname, field, couple) in [
            ("constant curvature + twist", &bending as &Field, [0.0, 0.0]),
            (
                "pure bending w = ½κx²",
                &(|x: f64, _y: f64| [0.5 * 0.37 * x * x, 0.37 * x, 0.0]) as &Field,
                [0.0, 0.0],
            ),
            (
                "twist w = κxy",
                &(|x: f64, y: f64| [0.37 * x * y, 0.37 * y, 0.37 * x]) as &Field,
                [0.0, 0.0],
            ),
            ("constant shear (with its couple load)", &shear as &Field, m),
            ("constant shear + curvature", &both as &Field, m),
        ] {
            let err = graded_patch_error(&xs, &ys, &section, field, couple);
            eprintln!("[patch graded] {cname}, {sname}: rel. error {err:.2e}");
            assert!(
                err <= tol,
                "MITC4 patch test '{cname}' on a graded 5×4 grid, {sname}: interior relative error {err:.3e} > {tol:e}"
            );
        }
    }
}

// ------------------------------------------------------------------------------------------
// 3. Thin square plates: convergence to the Kirchhoff solutions, no shear locking.
// ------------------------------------------------------------------------------------------

#[derive(Clone, Copy, Debug, PartialEq)]
enum Edge {
    /// "Hard" simple support: w = 0 and the tangential rotation = 0.
    Simple,
    /// w = ψx = ψy = 0.
    Clamped,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Loading {
    /// q = 1 over the whole plate.
    Uniform,
    /// P = 1 at the centre.
    Central,
}

/// Centre deflection of a 1 × 1 plate (D = 1, ν = 0.3) of thickness H with `n` elements per side
/// of the whole plate, modelled as a quarter (Mesh::new(…, true, true): ψx = 0 on x = 0 and
/// ψy = 0 on y = 0 come from the DofMap; load_vector gives the quarter ¼ of the central force).
fn centre_deflection(n: usize, edge: Edge, loading: Loading, h: f64, quarter: bool) -> f64 {
    let (mesh, dofs, _, u) = solve_square(n, edge, loading, h, quarter);
    let centre = (0..mesh.n_nodes())
        .find(|&node| {
            let (x, y) = mesh.node_xy(node);
            x.abs() < 1e-12 && y.abs() < 1e-12
        })
        .expect("the centre is a grid node for even n");
    u[dofs.eq(centre, Dof::W).unwrap()]
}

/// Solve the square-plate problem of [`centre_deflection`]; returns the model and the solution.
fn solve_square(
    n: usize,
    edge: Edge,
    loading: Loading,
    h: f64,
    quarter: bool,
) -> (Mesh, DofMap, Section, Vec<f64>) {
    let a = 1.0;
    let mesh = Mesh::new(a, a, [n, n], quarter, quarter);
    assert_eq!((mesh.sym_x, mesh.sym_y), (quarter, quarter));
    let section = section_of_thickness(1.0, h);
    let dofs = DofMap::new(&mesh);
    let k = assemble_stiffness(&mesh, &dofs, &section);
    let load = match loading {
        Loading::Uniform => Load::Patch {
            x: [-0.5 * a, 0.5 * a],
            y: [-0.5 * a, 0.5 * a],
            pressure: 1.0,
        },
        Loading::Central => Load::Point {
            x: 0.0,
            y: 0.0,
            force: 1.0,
        },
    };
    let f = load_vector(&mesh, &dofs, &[load]);
    let mut prescribed = vec![None; dofs.n_eq()];
    let mut fix = |node: usize, dof: Dof| {
        if let Some(e) = dofs.eq(node, dof) {
            prescribed[e] = Some(0.0);
        }
    };
    let x_edge = |x: f64| (x.abs() - 0.5 * a).abs() < 1e-9 * a;
    for node in 0..mesh.n_nodes() {
        let (x, y) = mesh.node_xy(node);
        let on_x_edge = x_edge(x); // edges x = ±a/2: tangent is y
        let on_y_edge = x_edge(y); // edges y = ±a/2: tangent is x
        if !(on_x_edge || on_y_edge) {
            continue;
        }
        fix(node, Dof::W);
        match edge {
            Edge::Clamped => {
                fix(node, Dof::PsiX);
                fix(node, Dof::PsiY);
            }
            Edge::Simple => {
                if on_x_edge {
                    fix(node, Dof::PsiY);
                }
                if on_y_edge {
                    fix(node, Dof::PsiX);
                }
            }
        }
    }
    let u = solve_prescribed(&k, &f, &prescribed);
    (mesh, dofs, section, u)
}

/// Navier double series for the simply supported square plate under uniform load, centre:
/// w = 16 q a⁴/(π⁶ D) Σ_{m,n odd} (−1)^((m+n)/2 − 1) / (m n (m² + n²)²)
/// (Timoshenko & Woinowsky-Krieger §30). Truncation at m, n ≤ 399: the omitted terms are
/// alternating and bounded by 1/(m n⁵)-type tails < 1e-11 relative.
fn navier_ss_uniform() -> f64 {
    let pi = std::f64::consts::PI;
    let mut s = 0.0;
    for m in (1..400).step_by(2) {
        for n in (1..400).step_by(2) {
            let sign = if ((m + n) / 2 - 1) % 2 == 0 {
                1.0
            } else {
                -1.0
            };
            let (mf, nf) = (m as f64, n as f64);
            s += sign / (mf * nf * (mf * mf + nf * nf).powi(2));
        }
    }
    16.0 / pi.powi(6) * s
}

/// Lévy single series for the simply supported square plate under a central point load
/// (Timoshenko & Woinowsky-Krieger §35, b = a):
/// w = P a² / (2π³ D) Σ_{m odd} (tanh α_m − α_m / cosh² α_m) / m³, α_m = m π / 2.
/// The bracket → 1, so the tail beyond m = 20001 is < Σ 1/m³ ≈ 1.3e-9 relative.
fn levy_ss_point() -> f64 {
    let pi = std::f64::consts::PI;
    let mut s = 0.0;
    for m in (1..20002).step_by(2) {
        let mf = m as f64;
        let al = mf * pi / 2.0;
        let c = al.cosh();
        let bracket = if al > 300.0 {
            1.0
        } else {
            al.tanh() - al / (c * c)
        };
        s += bracket / mf.powi(3);
    }
    s / (2.0 * pi.powi(3))
}

/// Centre value of the solution of −∇²u = 1 on the unit square with u = 0 on the boundary
/// (≈ 0.0736713): u = Σ_{m,n odd} 16 (−1)^((m+n)/2 − 1) / (π⁴ m n (m² + n²)).
/// For a simply supported (hard) polygonal plate Wang's exact relation is
/// w_Mindlin = w_Kirchhoff + M / κs with ∇²M = −q, M = 0 on the edges (M the moment sum
/// divided by 1 + ν), so the centre shear deflection is this value × q a² / κs.
fn poisson_centre() -> f64 {
    let pi = std::f64::consts::PI;
    let mut s = 0.0;
    for m in (1..2000).step_by(2) {
        for n in (1..2000).step_by(2) {
            let sign = if ((m + n) / 2 - 1) % 2 == 0 {
                1.0
            } else {
                -1.0
            };
            let (mf, nf) = (m as f64, n as f64);
            s += sign / (mf * nf * (mf * mf + nf * nf));
        }
    }
    16.0 / pi.powi(4) * s
}

#[test]
fn series_references_match_the_printed_tables() {
    // The series are evaluated here, so check them against independently printed values to
    // their rounding (half a unit in the last digit): T&W-K 0.00406 q a⁴/D (uniform) and
    // 0.01160 P a²/D (central load); the Poisson centre value 0.0737 q a² is the centre
    // deflection of a uniformly loaded square membrane and equals T&W-K's centre moment sum
    // (Mx + My)/(1 + ν) = 2 × 0.0479 / 1.3 = 0.0737.
    let w = navier_ss_uniform();
    assert!(
        (w - 0.00406).abs() <= 0.000005,
        "Navier SS uniform series {w}"
    );
    let w = levy_ss_point();
    assert!((w - 0.01160).abs() <= 0.000005, "Lévy SS point series {w}");
    let m = poisson_centre();
    assert!((m - 0.07367).abs() <= 0.000005, "Poisson centre series {m}");
    eprintln!(
        "[series] Navier SS uniform {:.9}, Lévy SS point {:.9}, Poisson centre {m:.9}",
        navier_ss_uniform(),
        levy_ss_point()
    );
}

/// One case of the Kirchhoff convergence study.
struct ThinCase {
    name: &'static str,
    edge: Edge,
    loading: Loading,
    /// Tabulated value (Timoshenko & Woinowsky-Krieger, ν = 0.3).
    table: f64,
    /// Best available reference for the error and rate.
    reference: f64,
    /// Tolerance on the relative error at n = 32.
    tol32: f64,
    /// Required observed rate log2(e16/e32), if any.
    min_rate: Option<f64>,
}

const H_THIN: f64 = 1e-4; // a / H = 10⁴: shear deflection ~ 1e-7 of the bending one
const H_THICKER: f64 = 1e-2;

#[test]
fn thin_square_plates_converge_to_kirchhoff_without_locking() {
    let cases = [
        // Uniform loads: bilinear elements converge at O(h²) in the centre deflection; 1% at
        // n = 32 (h = a/32) leaves a wide margin over the expected ~0.1–0.3%.
        ThinCase {
            name: "simply supported, uniform q",
            edge: Edge::Simple,
            loading: Loading::Uniform,
            table: 0.00406,
            reference: navier_ss_uniform(), // 0.00406235
            tol32: 0.01,
            min_rate: Some(1.5),
        },
        ThinCase {
            name: "clamped, uniform q",
            edge: Edge::Clamped,
            loading: Loading::Uniform,
            table: 0.00126,
            // Taylor & Govindjee (2004), Commun. Numer. Meth. Engng 20:757–765: 0.00126532;
            // the printed table value 0.00126 is 0.42% low, which would corrupt the rate.
            reference: 0.00126532,
            tol32: 0.01,
            min_rate: Some(1.5),
        },
        // Point loads: the Kirchhoff centre deflection is finite (w ~ r² ln r near the load)
        // but the discrete one converges only at O(h² |ln h|) (observed log2(e16/e32) ≈ 1.4–1.7),
        // and the Mindlin model adds a shear deflection ~ P/(2π κs) ln(a/h) that is ~1e-8 P a²/D
        // at a/H = 10⁴. 2% at n = 32 allows for the slower rate. No rate is asserted: for the
        // clamped case the only reference is the 3-figure table value, whose rounding (accurate
        // values are ≈ 0.00561, ~0.2% higher) is comparable to e32, so log2(e16/e32) there is
        // meaningless (it is reported only).
        ThinCase {
            name: "simply supported, central P",
            edge: Edge::Simple,
            loading: Loading::Central,
            table: 0.01160,
            reference: levy_ss_point(), // 0.0116008
            tol32: 0.02,
            min_rate: None,
        },
        ThinCase {
            name: "clamped, central P",
            edge: Edge::Clamped,
            loading: Loading::Central,
            table: 0.00560,
            reference: 0.00560,
            tol32: 0.02,
            min_rate: None,
        },
    ];
    let ns = [8usize, 16, 32];
    for c in &cases {
        let w: Vec<f64> = ns
            .iter()
            .map(|&n| centre_deflection(n, c.edge, c.loading, H_THIN, true))
            .collect();
        let e: Vec<f64> = w
            .iter()
            .map(|wi| (wi - c.reference) / c.reference)
            .collect();
        let e_table = (w[2] - c.table) / c.table;
        let rate = (e[1].abs() / e[2].abs()).log2();
        // Reference-free rate from successive differences (Richardson), reported only.
        let rate_rich = ((w[1] - w[0]) / (w[2] - w[1])).abs().log2();
        eprintln!(
            "[kirchhoff] {:<28} w8 = {:.7}, w16 = {:.7}, w32 = {:.7}; ref {:.7}; err {:+.3}% {:+.3}% {:+.3}%; vs table {:+.3}%; rate log2(e16/e32) = {rate:.2}; Richardson rate {rate_rich:.2}",
            c.name, w[0], w[1], w[2], c.reference, 100.0 * e[0], 100.0 * e[1], 100.0 * e[2], 100.0 * e_table
        );
        assert!(
            e[2].abs() <= c.tol32,
            "MITC4 {} at n = 32, a/H = 1e4: centre deflection {:.6} vs Kirchhoff {:.6} ({:+.3}%, tol {}%)",
            c.name, w[2], c.reference, 100.0 * e[2], 100.0 * c.tol32
        );
        assert!(
            e_table.abs() <= c.tol32,
            "MITC4 {} at n = 32: {:.6} vs the T&W-K table {:.5} ({:+.3}%, tol {}%)",
            c.name,
            w[2],
            c.table,
            100.0 * e_table,
            100.0 * c.tol32
        );
        assert!(
            e[0].abs() > e[1].abs() && e[1].abs() > e[2].abs(),
            "MITC4 {}: errors do not decrease monotonically under refinement: {:?}",
            c.name,
            e
        );
        if let Some(min_rate) = c.min_rate {
            assert!(
                rate >= min_rate,
                "MITC4 {}: observed convergence rate log2(e16/e32) = {rate:.3} < {min_rate} (bilinear theory: 2)",
                c.name
            );
        }
        // A locking element at a/H = 1e4 would be orders of magnitude too stiff already at
        // n = 8; the 8-element error bound of 10% (uniform) / 15% (point) is loose for MITC4
        // (O(h²) ≈ a few %) but far inside any locked response.
        let tol8 = if c.loading == Loading::Uniform {
            0.10
        } else {
            0.15
        };
        assert!(
            e[0].abs() <= tol8,
            "MITC4 {} at n = 8, a/H = 1e4: error {:+.2}% suggests shear locking",
            c.name,
            100.0 * e[0]
        );

        // Shear correction: a thicker plate (a/H = 100) is more flexible, by a small amount.
        let n = 16;
        let w_thin = w[1];
        let w_thick = centre_deflection(n, c.edge, c.loading, H_THICKER, true);
        let rel = (w_thick - w_thin) / w_thin;
        eprintln!(
            "[shear] {:<28} n = {n}: (w(H=1e-2) − w(H=1e-4)) / w = {:+.4e}",
            c.name, rel
        );
        assert!(
            w_thick > w_thin,
            "MITC4 {}: thicker plate (H/a = 1e-2) is not more flexible than H/a = 1e-4: {w_thick:.8} vs {w_thin:.8}",
            c.name
        );
        // Small: a/H = 100 shear deflections are a few per mille for distributed loads; even the
        // point-load log term P/(2π κs) ln(a/h) is ~1e-5 P a²/D. 3% bounds all cases.
        assert!(
            rel < 0.03,
            "MITC4 {}: shear correction at H/a = 1e-2 is {:.3}%, implausibly large",
            c.name,
            100.0 * rel
        );
    }
}

/// Wang's relation (hard simple support, uniform q): w_M − w_K = M_c / κs at the centre, with
/// M_c = 0.0736713 q a² (see `poisson_centre`). The difference between a/H = 100 and a/H = 10⁴
/// isolates the shear deflection; its discrete value converges at O(h²) like any bilinear
/// Poisson solution (the bending deflection's error at n = 32 is 0.03%; allow ~30× that), so a
/// 1% band at n = 32 is a quantitative check that the shear energy carries the right κs — and
/// no spurious stiffness (locking) or softness.
#[test]
fn shear_correction_matches_wang_relation_for_simply_supported_plate() {
    let n = 32;
    let mc = poisson_centre();
    let ks = |h: f64| section_of_thickness(1.0, h).shear;
    let expected = mc * (1.0 / ks(H_THICKER) - 1.0 / ks(H_THIN));
    let w_thick = centre_deflection(n, Edge::Simple, Loading::Uniform, H_THICKER, true);
    let w_thin = centre_deflection(n, Edge::Simple, Loading::Uniform, H_THIN, true);
    let got = w_thick - w_thin;
    let ratio = got / expected;
    eprintln!(
        "[wang] n = {n}: Δw = {got:.6e}, Wang M_c/κs difference = {expected:.6e}, ratio {ratio:.4}"
    );
    assert!(
        (ratio - 1.0).abs() < 0.01,
        "MITC4 simply supported square, uniform q, n = {n}: shear deflection Δw = {got:.4e} vs Wang's M/κs = {expected:.4e} (ratio {ratio:.4})"
    );
}

/// The quarter model (symmetry dofs removed by DofMap, ¼ of the central load by load_vector) must
/// reproduce the whole-plate model: same discrete space restricted to symmetric functions, so
/// the centre deflections agree to solver round-off (1e-9 relative ≫ cond·ε ≈ 1e-11 here).
#[test]
fn quarter_model_matches_whole_plate() {
    for (edge, loading) in [
        (Edge::Simple, Loading::Central),
        (Edge::Clamped, Loading::Uniform),
        (Edge::Simple, Loading::Uniform),
    ] {
        let n = 8;
        let wq = centre_deflection(n, edge, loading, H_THICKER, true);
        let wf = centre_deflection(n, edge, loading, H_THICKER, false);
        assert!(
            ((wq - wf) / wf).abs() < 1e-9,
            "MITC4 {edge:?} plate, {loading:?} load, n = {n}: quarter model {wq:.12} vs whole plate {wf:.12}"
        );
    }
}

/// Navier series for the centre bending moment of the simply supported square plate under
/// uniform load: Mx = My = (16 q a² / π⁴) Σ_{m,n odd} (−1)^((m+n)/2 − 1) (m² + ν n²) / (m n (m² + n²)²)
/// (≈ 0.0479 q a², T&W-K Table 8 for ν = 0.3). Alternating, terms ≲ 1/(m n³): truncation at 2000
/// leaves < 1e-7 relative.
fn navier_ss_uniform_moment() -> f64 {
    let pi = std::f64::consts::PI;
    let mut s = 0.0;
    for m in (1..2000).step_by(2) {
        for n in (1..2000).step_by(2) {
            let sign = if ((m + n) / 2 - 1) % 2 == 0 {
                1.0
            } else {
                -1.0
            };
            let (mf, nf) = (m as f64, n as f64);
            s += sign * (mf * mf + NU * nf * nf) / (mf * nf * (mf * mf + nf * nf).powi(2));
        }
    }
    16.0 / pi.powi(4) * s
}

/// Stress resultants from `centre_resultants` at the element next to the plate centre, simply
/// supported square under uniform q, against the Navier series. For hard simple supports the
/// Mindlin moments and shear forces equal the Kirchhoff ones exactly (Wang's relations), so the
/// better-conditioned a/H = 100 model is used (the shear strain γ = Q/κs is then ≈ 1e-6, well
/// above solver round-off, unlike at a/H = 10⁴).
/// - The element centre is (h/2, h/2); Mx is stationary at the plate centre, so the offset costs
///   O(h²). Sagging moments are positive by the crate's stated convention.
/// - Shear forces: the w-equation of U gives ∇·Q = −q with Q = κs γ (downward load, downward w),
///   and by the symmetry of the square Qx,x = Qy,y = −q/2 at the centre, so at (h/2, h/2)
///   Qx = Qy ≈ −q h/4 (+ O(h³)); mxy ∝ xy is O(h²).
#[test]
fn centre_resultants_of_simply_supported_plate_match_navier() {
    let reference = navier_ss_uniform_moment();
    assert!(
        (reference - 0.0479).abs() <= 0.00005,
        "Navier moment series {reference}"
    );
    for n in [16usize, 32] {
        let (mesh, dofs, section, u) =
            solve_square(n, Edge::Simple, Loading::Uniform, H_THICKER, true);
        let e = mesh
            .locate(0.25 * mesh.hx, 0.25 * mesh.hy)
            .map(|(e, _, _)| e)
            .expect("element at the centre");
        let (xc, yc) = mesh.element_centre(e);
        assert!((xc - 0.5 * mesh.hx).abs() < 1e-12 && (yc - 0.5 * mesh.hy).abs() < 1e-12);
        let eqs = dofs.element_eqs(&mesh.element_nodes(e));
        let ue = ElementVector::from_fn(|i, _| eqs[i].map_or(0.0, |k| u[k]));
        let [mx, my, mxy, qx, qy] = centre_resultants(&section, mesh.hx, mesh.hy, &ue);
        let err = (mx - reference) / reference;
        let q_ref = -0.25 * mesh.hx; // q = 1
        eprintln!(
            "[resultants] SS uniform n = {n}: mx = {mx:.6}, my = {my:.6} (Navier {reference:.6}, err {:+.3}%), mxy = {mxy:.2e}, qx = {qx:.5e}, qy = {qy:.5e} (−q h/4 = {q_ref:.5e})",
            100.0 * err
        );
        // O(h²) (bilinear ψ; the centre is a superconvergent point for the curvature): 2% at
        // n = 16 and 1% at n = 32 are loose bounds; a sign or factor error misses by ≥ 100%.
        let tol = if n == 16 { 0.02 } else { 0.01 };
        assert!(
            err.abs() <= tol,
            "MITC4 centre_resultants, SS square uniform q, n = {n}: mx = {mx:.6} vs Navier {reference:.6} ({:+.3}%)",
            100.0 * err
        );
        // mx = my at the diagonal point up to solver round-off (cond(K) ε ≈ 1e-9 here).
        assert!(
            ((my - mx) / mx).abs() <= 1e-6,
            "MITC4 centre_resultants, SS square uniform q, n = {n}: mx {mx} ≠ my {my} at a point of the diagonal"
        );
        assert!(
            mxy.abs() <= 0.02 * reference,
            "MITC4 centre_resultants, SS square uniform q, n = {n}: mxy = {mxy:e} next to the plate centre"
        );
        // Shear: −q h/4 to leading order; the O(h³) remainder and the element's own O(h²)
        // error are a few % of this O(h) value at n ≥ 16; 10% catches sign and factor errors.
        for (name, qv) in [("qx", qx), ("qy", qy)] {
            assert!(
                ((qv - q_ref) / q_ref).abs() <= 0.10,
                "MITC4 centre_resultants, SS square uniform q, n = {n}: {name} = {qv:.5e} vs −q h/4 = {q_ref:.5e}"
            );
        }
    }
}

// ------------------------------------------------------------------------------------------
// 4. Element-vector consistency.
// ------------------------------------------------------------------------------------------

fn energy(k: &ElementMatrix, u: &SVector<f64, 12>) -> f64 {
    0.5 * u.dot(&(k * u))
}

proptest! {
    // 32 cases keep the test fast; no failure persistence so that a failing case never writes a
    // regression file into the source tree (the shrunk case is printed in the failure message).
    #![proptest_config(ProptestConfig { cases: 32, failure_persistence: None, ..ProptestConfig::default() })]

    /// Central differences of E(u) = ½ uᵀ K u reproduce K u (this also checks K = Kᵀ, since the
    /// exact gradient is ½ (K + Kᵀ) u), and E ≥ 0 up to round-off.
    #[test]
    fn element_energy_gradient_is_k_u(
        u in proptest::array::uniform12(-1.0f64..1.0),
        hx in 0.1f64..2.0,
        hy in 0.1f64..2.0,
        log_thickness in -4.0f64..-0.3, // H / min(hx, hy) from 1e-4 to 0.5
    ) {
        let section = section_of_thickness(1.0, 10f64.powf(log_thickness) * hx.min(hy));
        let k = element_stiffness(&section, hx, hy);
        let u = SVector::<f64, 12>::from_row_slice(&u);
        let ku = k * u;
        let unorm = u.norm().max(1e-3);
        // E is quadratic, so the central difference is exact in exact arithmetic; the only error
        // is round-off in the two energies: |δE| ≤ γ₂₄ Σ|u_i||K_ij||u_j| with γ₂₄ ≈ 24 ε, for
        // u ± δ e_i. Divided by 2δ this bounds the gradient error by 24 ε S / δ; allow 4× that.
        let delta = 1e-3 * unorm;
        let kabs = k.abs();
        for i in 0..12 {
            let mut up = u;
            let mut um = u;
            up[i] += delta;
            um[i] -= delta;
            let g = (energy(&k, &up) - energy(&k, &um)) / (2.0 * delta);
            let ua = up.abs(); // |u| + δ e_i bounds both perturbed vectors
            let s = ua.dot(&(kabs * ua));
            let tol = 4.0 * 24.0 * f64::EPSILON * s / delta;
            prop_assert!(
                (g - ku[i]).abs() <= tol,
                "MITC4 element {}×{} (κs = {:.3e}): ∂E/∂u_{} by central differences = {:.12e} vs (K u)_{} = {:.12e} (tol {:.2e})",
                hx, hy, section.shear, i, g, i, ku[i], tol
            );
        }
        // Positive semi-definite: E ≥ −1e-12 ‖K‖ ‖u‖² (round-off of E is ≈ 12 ε ‖K‖ ‖u‖²).
        let e = energy(&k, &u);
        prop_assert!(
            e >= -1e-12 * k.norm() * u.norm_squared(),
            "MITC4 element {}×{} (κs = {:.3e}): negative energy ½uᵀKu = {:.3e}",
            hx, hy, section.shear, e
        );
    }
}
