//! The FFT product against the dense T of the pair table.

use super::*;
use crate::layout::{Axis, Joint, JointKind, Layout};

fn dense(mesh: &Mesh, c: f64, kernel: &Kernel) -> faer::Mat<f64> {
    pairs::dense_matrix(mesh, c, kernel)
}

/// A reproducible field with both signs and no symmetry.
fn field(n: usize, seed: u64) -> Vec<f64> {
    let mut s = seed;
    (0..n)
        .map(|_| {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((s >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        })
        .collect()
}

/// The FFT product equals the dense product of `pairs::dense_matrix` (an independent
/// scatter of the same pair table), for the half-space, Pasternak and elastic-layer kernels, to round-off: the FFT's error is ~1e-16 × log N × max|T|·|x|.
fn check(a: f64, b: f64, full: [usize; 2], sym_x: bool, sym_y: bool) {
    check_layout(a, b, full, sym_x, sym_y, &Layout::default());
}

/// [`check`] on a mesh with a layout.
fn check_layout(a: f64, b: f64, full: [usize; 2], sym_x: bool, sym_y: bool, layout: &Layout) {
    let mesh = Mesh::new(a, b, full, sym_x, sym_y).with_layout(layout);
    check_mesh(
        &mesh,
        b / a,
        &Kernel::new(crate::foundation::halfspace::Boussinesq),
    );
    // A Pasternak kernel decaying within the plate (λ = 0.3) and one reaching beyond it.
    for lambda in [0.3, 3.0] {
        check_mesh(
            &mesh,
            b / a,
            &Kernel::new(crate::foundation::pasternak::PasternakKernel { lambda }),
        );
    }
    // A layer whose kernel is cut within the plate (40 h = 0.8) and a deep one.
    for depth in [0.02, 0.7] {
        let table = super::super::layer::LayerTable::shared(0.3, super::super::layer::Base::Rough);
        check_mesh(
            &mesh,
            b / a,
            &Kernel::new(crate::foundation::elastic_layer::LayerKernel { depth, table }),
        );
    }
}

fn check_mesh(mesh: &Mesh, mu: f64, kernel: &Kernel) {
    let c = 0.37;
    let t = dense(mesh, c, kernel);
    let op = ToeplitzCompliance::with_kernel(mesh, c, kernel);
    let n = mesh.n_nodes();
    let name = format!(
        "{kernel:?} {:?} {} (μ = {mu}, {} copies)",
        mesh.full_elements(),
        mesh.symmetry_name(),
        n
    );
    for seed in [1, 2] {
        let x = field(n, seed);
        let y = op.apply(&x);
        let mut worst = 0.0_f64;
        let mut scale = 0.0_f64;
        for i in 0..n {
            let d: f64 = (0..n).map(|j| t[(i, j)] * x[j]).sum();
            worst = worst.max((d - y[i]).abs());
            scale = scale.max(d.abs());
        }
        assert!(
            worst < 1e-12 * scale,
            "{name}: FFT product differs from dense by {worst:e} (scale {scale:e})"
        );
    }
    for i in 0..n {
        assert!(
            (op.diag()[i] - t[(i, i)]).abs() < 1e-13 * t[(i, i)],
            "{name}: diagonal {i}: {} vs {}",
            op.diag()[i],
            t[(i, i)]
        );
    }
}

#[test]
fn fft_product_equals_dense_full_plate() {
    check(2.0, 2.0, [6, 6], false, false);
    check(2.0, 1.0, [7, 4], false, false);
    check(2.0, 3.0, [5, 9], false, false);
}

#[test]
fn fft_product_equals_dense_half_models() {
    check(2.0, 2.0, [8, 5], true, false);
    check(2.0, 1.0, [5, 8], false, true);
    check(2.0, 0.6, [10, 7], true, false);
}

#[test]
fn fft_product_equals_dense_quarter_models() {
    check(2.0, 2.0, [8, 8], true, true);
    check(2.0, 1.0, [10, 6], true, true);
    check(2.0, 2.0, [2, 2], true, true);
}

#[test]
fn fft_sizes_are_smooth_and_large_enough() {
    for n in [1, 2, 7, 17, 97, 383, 769] {
        let m = fft_size(n);
        assert!(m >= n && m.is_multiple_of(2), "{n} → {m}");
        let mut r = m;
        for p in [2, 3, 5] {
            while r.is_multiple_of(p) {
                r /= p;
            }
        }
        assert_eq!(r, 1, "{n} → {m} has a factor other than 2, 3, 5");
    }
    assert_eq!(fft_size(767), 768);
}

fn joint(axis: Axis, at: f64, kind: JointKind) -> Joint {
    Joint {
        name: "J".into(),
        axis,
        at,
        span: None,
        kind,
    }
}

/// Cuts of every kind (a free line, an aggregate one crossing it, a continuous one) on the
/// whole plate and on half and quarter models (the cuts off the symmetry lines, mirrored).
fn jointed_layout() -> Layout {
    Layout {
        joints: vec![
            joint(Axis::X, 0.5, JointKind::Free),
            joint(Axis::X, -0.5, JointKind::Free),
            joint(Axis::Y, 0.5, JointKind::Aggregate { c: 1.0 }),
            joint(Axis::Y, -0.5, JointKind::Aggregate { c: 1.0 }),
            joint(Axis::X, 0.25, JointKind::Continuous),
        ],
        panels: Vec::new(),
        ..Layout::default()
    }
}

/// On jointed meshes the FFT product (gather and scatter through the corner table) equals the
/// dense T scattered by `pairs::dense_matrix` through the same table, for the three kernels,
/// whole, half and quarter models.
#[test]
fn fft_product_equals_dense_on_jointed_meshes() {
    let l = jointed_layout();
    check_layout(2.0, 2.0, [8, 8], false, false, &l);
    check_layout(2.0, 1.0, [8, 8], true, false, &l);
    check_layout(2.0, 2.0, [8, 8], false, true, &l);
    check_layout(2.0, 2.0, [8, 8], true, true, &l);
}

/// Merging the copies of each grid node (P: copy → grid node, 0/1) turns the jointed T into
/// the plain grid's: Pᵀ T_jointed P = T — the cell-corner form sums the same element-pair
/// integrals, only split among the copies. To round-off of the sums (1e-13 of the largest).
#[test]
fn merging_the_copies_gives_the_plain_compliance() {
    let l = jointed_layout();
    for (sx, sy) in [(false, false), (true, false), (true, true)] {
        let plain = Mesh::new(2.0, 1.5, [8, 8], sx, sy);
        let jointed = plain.clone().with_layout(&l);
        assert!(jointed.n_nodes() > plain.n_nodes());
        for kernel in [
            Kernel::new(crate::foundation::halfspace::Boussinesq),
            Kernel::new(crate::foundation::pasternak::PasternakKernel { lambda: 0.4 }),
        ] {
            let t0 = dense(&plain, 1.0, &kernel);
            let t = dense(&jointed, 1.0, &kernel);
            let n0 = plain.n_nodes();
            let mut merged = faer::Mat::<f64>::zeros(n0, n0);
            for i in 0..jointed.n_nodes() {
                for j in 0..jointed.n_nodes() {
                    merged[(jointed.grid_of(i), jointed.grid_of(j))] += t[(i, j)];
                }
            }
            let mut worst = 0.0_f64;
            let mut top = 0.0_f64;
            for i in 0..n0 {
                for j in 0..n0 {
                    worst = worst.max((merged[(i, j)] - t0[(i, j)]).abs());
                    top = top.max(t0[(i, j)].abs());
                }
            }
            assert!(worst < 1e-13 * top, "({sx}, {sy}) {kernel:?}: {worst:e}");
        }
    }
}

/// The gather map read through the corner table of a layout that cuts nothing (a continuous
/// line) is the plain grid's arithmetic one: the products agree bitwise.
#[test]
fn gather_map_of_an_uncut_layout_is_the_plain_one() {
    let l = Layout {
        joints: vec![joint(Axis::X, 0.5, JointKind::Continuous)],
        panels: Vec::new(),
        ..Layout::default()
    };
    for (sx, sy) in [(false, false), (true, false), (true, true)] {
        let plain = Mesh::new(2.0, 1.0, [8, 6], sx, sy);
        let mapped = plain.clone().with_layout(&l);
        let a = ToeplitzCompliance::new(&plain, 0.7);
        let b = ToeplitzCompliance::new(&mapped, 0.7);
        assert!(a.gather.is_none() && b.gather.is_some());
        let x = field(plain.n_nodes(), 3);
        assert_eq!(a.apply(&x), b.apply(&x), "({sx}, {sy})");
    }
}
