//! Tests of the grid, its dof map and its topology.

use super::*;

#[test]
fn quarter_mesh_of_an_even_grid_has_half_the_elements_each_way() {
    let m = Mesh::new(2.0, 1.0, [8, 6], true, true);
    assert_eq!((m.nx, m.ny), (4, 3));
    assert_eq!(m.full_elements(), [8, 6]);
    assert_eq!(m.copies(), 4);
    assert_eq!(m.node_xy(m.node(4, 3)), (1.0, 0.5));
}

#[test]
fn odd_counts_are_not_reduced() {
    let m = Mesh::new(2.0, 2.0, [7, 8], true, true);
    assert!(!m.sym_x && m.sym_y);
    assert_eq!(m.symmetry_name(), "half-y");
}

#[test]
fn locate_finds_element_and_local_coordinates() {
    let m = Mesh::new(2.0, 2.0, [4, 4], false, false);
    let (e, xi, eta) = m.locate(-0.75, 0.25).unwrap();
    assert_eq!(m.element_ij(e), (0, 2));
    assert!(
        xi.abs() < 1e-12 && eta.abs() < 1e-12,
        "centre of element (0, 2)"
    );
    assert!(m.locate(1.0 + 1e-3, 0.0).is_none());
    assert!(
        m.locate(1.0, 1.0).is_some(),
        "corner on the boundary is inside"
    );
}

#[test]
fn nested_dissection_is_a_permutation() {
    for (nx, ny) in [(1, 1), (7, 3), (40, 25)] {
        let m = Mesh::new(2.0, 1.0, [nx, ny], false, false);
        let mut order = nested_dissection(&m);
        assert_eq!(order.len(), m.n_nodes(), "{nx} × {ny}");
        order.sort_unstable();
        assert!(
            order.iter().enumerate().all(|(i, &n)| i == n),
            "{nx} × {ny}: every node once"
        );
    }
}

#[test]
fn symmetry_lines_lose_their_normal_rotation() {
    let m = Mesh::new(2.0, 2.0, [4, 4], true, true);
    let d = DofMap::new(&m);
    // 9 nodes × 3 dofs, minus ψx on the 3 nodes of x = 0 and ψy on the 3 nodes of y = 0.
    assert_eq!(d.n_eq(), 27 - 6);
    assert!(d.eq(m.node(0, 1), Dof::PsiX).is_none());
    assert!(d.eq(m.node(0, 1), Dof::PsiY).is_some());
    assert!(d.eq(m.node(1, 0), Dof::PsiY).is_none());
}

/// Bilinear interpolation reproduces a bilinear field exactly on any finer or coarser
/// grid, and a reduced grid's field is read through its mirror images.
#[test]
fn interpolation_is_exact_for_bilinear_fields_and_mirrors_reduced_grids() {
    let f = |x: f64, y: f64| 1.0 + 2.0 * x - 3.0 * y + 0.5 * x * y;
    let coarse = Mesh::new(2.0, 1.5, [6, 4], false, false);
    let values: Vec<f64> = (0..coarse.n_nodes())
        .map(|n| {
            let (x, y) = coarse.node_xy(n);
            f(x, y)
        })
        .collect();
    let fine = Mesh::new(2.0, 1.5, [14, 10], false, false);
    let got = fine.interpolate_from(&coarse, &values);
    for (n, v) in got.iter().enumerate() {
        let (x, y) = fine.node_xy(n);
        // Linear in each direction within a coarse element: exact to round-off.
        assert!(
            (v - f(x, y)).abs() < 1e-13,
            "at ({x}, {y}): {v} vs {}",
            f(x, y)
        );
    }
    // A field even in x and y held on a quarter grid, read on the whole plate.
    let g = |x: f64, y: f64| 2.0 + x.abs() + 0.25 * y.abs();
    let quarter = Mesh::new(2.0, 1.5, [8, 6], true, true);
    let q: Vec<f64> = (0..quarter.n_nodes())
        .map(|n| {
            let (x, y) = quarter.node_xy(n);
            g(x, y)
        })
        .collect();
    let whole = Mesh::new(2.0, 1.5, [8, 6], false, false);
    for (n, v) in whole.interpolate_from(&quarter, &q).iter().enumerate() {
        let (x, y) = whole.node_xy(n);
        assert!((v - g(x, y)).abs() < 1e-13);
    }
}

mod jointed {
    use super::*;
    use crate::layout::{Axis, Joint, JointKind, Layout};

    fn joint(axis: Axis, at: f64, kind: JointKind) -> Joint {
        Joint {
            name: "J".into(),
            axis,
            at,
            span: None,
            kind,
        }
    }

    fn layout(joints: Vec<Joint>) -> Layout {
        Layout {
            joints,
            panels: Vec::new(),
            ..Layout::default()
        }
    }

    /// 2 × 1 elements, one cut at x = 0: the three nodes on the line get a copy each (the
    /// right side's), numbered after the 9 grid nodes in grid order.
    #[test]
    fn a_cut_doubles_the_nodes_on_its_line() {
        let m = Mesh::new(2.0, 1.0, [2, 1], false, false).with_layout(&layout(vec![joint(
            Axis::X,
            0.0,
            JointKind::Free,
        )]));
        assert_eq!(m.n_nodes(), 6 + 2);
        assert_eq!(m.element_nodes(0), [0, 1, 4, 3]);
        assert_eq!(m.element_nodes(1), [6, 2, 5, 7]);
        assert_eq!(m.grid_of(6), 1);
        assert_eq!(m.grid_of(7), 4);
        assert_eq!(m.node_xy(7), m.node_xy(4));
        assert_eq!(m.extra_copies(1), &[6]);
        let t = m.topo.as_ref().expect("topology");
        assert_eq!(t.segments.len(), 1);
        assert_eq!(t.segments[0].a, [1, 4]);
        assert_eq!(t.segments[0].b, [6, 7]);
        assert_eq!((t.n_pieces(), t.n_clusters()), (2, 2), "free: two clusters");
        // An aggregate joint joins the two pieces into one cluster.
        let agg = Mesh::new(2.0, 1.0, [2, 1], false, false).with_layout(&layout(vec![joint(
            Axis::X,
            0.0,
            JointKind::Aggregate { c: 1.0 },
        )]));
        let t = agg.topo.as_ref().expect("topology");
        assert_eq!((t.n_pieces(), t.n_clusters()), (2, 1));
    }

    /// Two crossing cuts: the crossing node has four copies (three extras), the other nodes
    /// on a line two; four pieces.
    #[test]
    fn a_crossing_of_two_cuts_has_four_copies() {
        let m = Mesh::new(2.0, 2.0, [4, 4], false, false).with_layout(&layout(vec![
            joint(Axis::X, 0.0, JointKind::Aggregate { c: 1.0 }),
            joint(Axis::Y, 0.0, JointKind::Free),
        ]));
        // 5 + 5 nodes on the lines, the crossing counted once per line: 4 + 4 single extras
        // and 3 at the crossing.
        assert_eq!(m.n_nodes(), 25 + 4 + 4 + 3);
        let centre = m.node(2, 2);
        assert_eq!(m.extra_copies(centre).len(), 3);
        // The four elements around the crossing each hold a different copy of it.
        let around = [(1, 1, 2), (2, 1, 3), (1, 2, 1), (2, 2, 0)];
        let mut copies: Vec<usize> = around
            .iter()
            .map(|&(i, j, c)| m.element_nodes(i + 4 * j)[c])
            .collect();
        assert_eq!(
            copies[0], centre,
            "the lower-left element keeps the grid id"
        );
        copies.sort_unstable();
        copies.dedup();
        assert_eq!(copies.len(), 4);
        let t = m.topo.as_ref().expect("topology");
        assert_eq!(t.n_pieces(), 4);
        // x-joint aggregate joins left and right in each row; the y-joint is free.
        assert_eq!(t.n_clusters(), 2);
        assert_eq!(t.segments.len(), 8);
    }

    /// A continuous line delimits panels but doubles nothing; crossing a cut it adds no copy.
    #[test]
    fn continuous_lines_only_delimit_panels() {
        let m = Mesh::new(2.0, 2.0, [4, 4], false, false).with_layout(&layout(vec![
            joint(Axis::X, 0.0, JointKind::Continuous),
            joint(Axis::Y, 0.5, JointKind::Tied { c: 1.0, c_r: 1.0 }),
        ]));
        assert_eq!(
            m.n_nodes(),
            25 + 5,
            "only the tied line y = 0.5 doubles its 5 nodes"
        );
        let t = m.topo.as_ref().expect("topology");
        assert_eq!(t.n_pieces(), 2);
        assert_eq!(t.n_clusters(), 1);
        // Panels by both lines: 2 columns × 2 rows.
        assert_eq!(m.panel_of(0), 0);
        assert_eq!(m.panel_of(3), 1);
        assert_eq!(m.panel_of(15), 3);
        let plain = Mesh::new(2.0, 2.0, [4, 4], false, false).with_layout(&layout(vec![joint(
            Axis::X,
            0.0,
            JointKind::Continuous,
        )]));
        assert!(!plain.is_jointed());
        assert_eq!(plain.n_nodes(), 25);
        for e in 0..16 {
            assert_eq!(
                plain.element_nodes(e),
                Mesh::new(2.0, 2.0, [4, 4], false, false).element_nodes(e)
            );
        }
    }

    /// Every node copy is some element's corner exactly as often as its grid node's elements on
    /// its side, the dof map numbers all copies, nested dissection is a permutation of them.
    #[test]
    fn copies_dofs_and_orders_cover_every_node_once() {
        let l = layout(vec![
            joint(Axis::X, -0.5, JointKind::Free),
            joint(Axis::X, 0.25, JointKind::Aggregate { c: 2.0 }),
            joint(Axis::Y, 0.0, JointKind::Tied { c: 1.0, c_r: 1.0 }),
        ]);
        for (sx, sy) in [(false, false), (true, false)] {
            let m = Mesh::new(2.0, 1.0, [8, 6], sx, sy).with_layout(&l);
            let n = m.n_nodes();
            let mut seen = vec![0usize; n];
            for e in 0..m.n_elements() {
                for k in m.element_nodes(e) {
                    seen[k] += 1;
                }
            }
            assert!(seen.iter().all(|&c| c >= 1), "every copy is a corner");
            let t = m.topo.as_ref().expect("topology");
            for k in 0..n {
                assert_eq!(t.incident(k).len(), seen[k]);
                for &(e, a) in t.incident(k) {
                    assert_eq!(m.element_nodes(e)[a], k);
                }
            }
            let mut order = nested_dissection(&m);
            assert_eq!(order.len(), n);
            order.sort_unstable();
            assert!(order.iter().enumerate().all(|(i, &k)| i == k));
            let d = DofMap::new(&m);
            let fixed = (0..n).filter(|&k| sx && m.node_ij(k).0 == 0).count();
            assert_eq!(
                d.n_eq(),
                3 * n - fixed,
                "ψx fixed on x = 0, copies included"
            );
            // The copies of the tied line y = 0 on the symmetry line both lose ψx.
            if sx {
                let g = m.node(0, 3);
                assert_eq!(m.extra_copies(g).len(), 1);
                assert!(d.eq(m.extra_copies(g)[0], Dof::PsiX).is_none());
            }
        }
    }

    /// A field bilinear on each side of a joint, with a jump across it, is reproduced exactly
    /// on a finer jointed grid (each copy reads its own side), and through a reduced grid's
    /// mirror images.
    #[test]
    fn interpolation_reads_each_side_of_a_joint() {
        let l = layout(vec![
            joint(Axis::X, 0.5, JointKind::Free),
            joint(Axis::X, -0.5, JointKind::Free),
        ]);
        let f = |x: f64, y: f64, right: bool| {
            let base = 1.0 + 0.5 * x.abs() - 0.25 * y;
            if right {
                base + 3.0
            } else {
                base
            }
        };
        // Which side a copy is on: the centre of one of its elements.
        let side = |m: &Mesh, n: usize| {
            let e = m.topo.as_ref().expect("topology").incident(n)[0].0;
            m.element_centre(e).0.abs() > 0.5
        };
        let coarse = Mesh::new(2.0, 1.0, [4, 2], true, false).with_layout(&l);
        let values: Vec<f64> = (0..coarse.n_nodes())
            .map(|n| {
                let (x, y) = coarse.node_xy(n);
                f(x, y, side(&coarse, n))
            })
            .collect();
        let fine = Mesh::new(2.0, 1.0, [8, 4], false, false).with_layout(&l);
        let got = fine.interpolate_from(&coarse, &values);
        for (n, v) in got.iter().enumerate() {
            let (x, y) = fine.node_xy(n);
            let want = f(x, y, side(&fine, n));
            assert!(
                (v - want).abs() < 1e-12,
                "node {n} at ({x}, {y}): {v} vs {want}"
            );
        }
    }

    /// The coarse grid keeps the joints on its lines, or there is none.
    #[test]
    fn coarsening_keeps_joints_on_grid_lines() {
        let l = layout(vec![
            joint(Axis::X, 0.5, JointKind::Free),
            joint(Axis::X, -0.5, JointKind::Free),
        ]);
        let m = Mesh::new(2.0, 2.0, [8, 8], true, true).with_layout(&l);
        let c = m.coarsened().expect("even lines");
        assert_eq!((c.nx, c.ny), (2, 2));
        assert_eq!(c.topo.as_ref().expect("topology").lines_x, vec![(1, 0)]);
        assert_eq!(c.n_nodes(), 9 + 3);
        // x = 0.125 is column 9 of 16: no grid twice as coarse has it on a line.
        let odd = Mesh::new(2.0, 2.0, [16, 8], false, false).with_layout(&layout(vec![joint(
            Axis::X,
            0.125,
            JointKind::Free,
        )]));
        assert_eq!(odd.topo.as_ref().expect("topology").lines_x, vec![(9, 0)]);
        assert!(odd.coarsened().is_none());
        let whole = m.whole();
        assert_eq!((whole.nx, whole.ny, whole.sym_x), (8, 8, false));
        assert_eq!(
            whole.n_nodes(),
            81 + 2 * 9,
            "both joints x = ±0.5 on the whole plate"
        );
    }
}

mod dowels {
    use super::*;
    use crate::layout::{Axis, Joint, JointKind, Layout};

    /// Bars sit on the segment holding them at their fraction along it; on a reduced model the
    /// mirrored half's bars are dropped and a bar on the symmetry line counts half. A cut on the
    /// symmetry line itself is the model's boundary there (the model planning refuses to reduce
    /// such a plate).
    #[test]
    fn bars_are_placed_on_their_segments() {
        let l = Layout {
            joints: vec![
                Joint {
                    name: "D".into(),
                    axis: Axis::X,
                    at: 0.5,
                    span: None,
                    kind: JointKind::Dowels {
                        k: 4.0,
                        positions: vec![-0.6, 0.0, 0.3, 0.75],
                        bar: None,
                    },
                },
                Joint {
                    name: "F".into(),
                    axis: Axis::Y,
                    at: 0.0,
                    span: None,
                    kind: JointKind::Free,
                },
            ],
            panels: Vec::new(),
            ..Layout::default()
        };
        // Half-y model: y ∈ [0, 1], 4 rows of 0.25.
        let m = Mesh::new(2.0, 2.0, [8, 8], false, true).with_layout(&l);
        let t = m.topo.as_ref().expect("topology");
        assert!(
            t.lines_y.is_empty(),
            "the cut y = 0 is the model's boundary"
        );
        let got: Vec<(usize, f64, f64, usize)> = t
            .dowels
            .iter()
            .map(|d| (d.segment, d.t, d.k, d.bar))
            .collect();
        assert_eq!(got.len(), 3);
        assert_eq!(
            (got[0].0, got[0].2, got[0].3),
            (0, 2.0, 1),
            "y = 0: half the spring"
        );
        assert!(got[0].1.abs() < 1e-12);
        assert_eq!((got[1].0, got[1].3), (1, 2));
        assert!(
            (got[1].1 - 0.2).abs() < 1e-12,
            "y = 0.3 is 0.2 along [0.25, 0.5]"
        );
        assert_eq!((got[2].0, got[2].3), (3, 3));
        assert!(
            got[2].1.abs() < 1e-12,
            "y = 0.75 is the node starting segment 3"
        );
        let seg = t.segments[1];
        assert_eq!((seg.minus, seg.plus), (5 + 8, 6 + 8));
        assert_eq!(t.n_clusters(), 1);
    }

    /// Bars on the plate's two edges (y = ∓1 of a joint x = const on the whole 2 × 2 plate, 8
    /// rows of 0.25) are on the plate, not on a mirrored half: the first sits at the start of
    /// the first segment (t = 0), the last at the end of the last segment (t = 1), each with
    /// its whole spring. (Positions are exact binary fractions: t is exact.)
    #[test]
    fn bars_on_the_plate_edges_sit_at_the_ends_of_the_joint() {
        let l = Layout {
            joints: vec![Joint {
                name: "D".into(),
                axis: Axis::X,
                at: 0.5,
                span: None,
                kind: JointKind::Dowels {
                    k: 4.0,
                    positions: vec![-1.0, 1.0],
                    bar: None,
                },
            }],
            panels: Vec::new(),
            ..Layout::default()
        };
        let m = Mesh::new(2.0, 2.0, [8, 8], false, false).with_layout(&l);
        let t = m.topo.as_ref().expect("topology");
        let got: Vec<(usize, f64, f64, usize)> = t
            .dowels
            .iter()
            .map(|d| (d.segment, d.t, d.k, d.bar))
            .collect();
        assert_eq!(got, vec![(0, 0.0, 4.0, 0), (7, 1.0, 4.0, 1)]);
    }
}
