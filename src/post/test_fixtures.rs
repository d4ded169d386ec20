//! Small synthetic fields shared by the output writers' tests.

use super::{ElementField, FullField};

/// A 4 × 2 plate with a σ bump in the middle and lifted corners.
pub(crate) fn bump() -> (FullField, ElementField) {
    let (nx, ny) = (4, 2);
    let mut f = FullField {
        nx,
        ny,
        x: vec![],
        y: vec![],
        s: vec![],
        t: vec![],
        w: vec![],
        psi_x: vec![],
        psi_y: vec![],
        pressure: vec![],
        gap: vec![],
        signed_gap: vec![],
        gap_per_sigma: 0.01,
        v: vec![],
        sigma: vec![],
        contact: vec![],
        s1_bottom: vec![],
        s1_top: vec![],
        ..FullField::default()
    };
    for j in 0..=ny {
        for i in 0..=nx {
            let s = -1.0 + 2.0 * i as f64 / nx as f64;
            let t = -1.0 + 2.0 * j as f64 / ny as f64;
            let sigma = 1.0 - s * s - 0.6 * t * t;
            f.x.push(2.0 * s);
            f.y.push(t);
            f.s.push(s);
            f.t.push(t);
            f.w.push(0.01 * sigma);
            f.psi_x.push(0.001 * s);
            f.psi_y.push(0.001 * t);
            f.pressure.push(sigma.max(0.0));
            f.gap.push((-sigma).max(0.0));
            f.signed_gap.push(-0.01 * sigma);
            f.v.push(0.1 * sigma);
            f.sigma.push(sigma.max(0.0));
            f.contact.push(sigma > 0.0);
            f.s1_bottom.push(2.0 * sigma);
            f.s1_top.push(-sigma);
        }
    }
    let mut e = ElementField::default();
    for je in 0..ny {
        for ie in 0..nx {
            let k = (ie + je * nx) as f64;
            e.x.push(-1.5 + ie as f64);
            e.y.push(-0.5 + je as f64);
            e.mx.push(k);
            e.my.push(2.0 * k);
            e.mxy.push(-k);
            e.qx.push(0.5 * k);
            e.qy.push(0.25 * k);
            e.bottom.push(6.0 * k, 12.0 * k, -6.0 * k);
            e.top.push(-6.0 * k, -12.0 * k, 6.0 * k);
        }
    }
    (f, e)
}

/// The 4 × 2 plate of [`bump`] cut by a joint along x = 0 (grid column 2): the three nodes on
/// the line get a + side copy each (nodes 15, 16, 17, in order of j) whose values are the grid
/// node's plus one (w plus 0.01), the elements of columns 2 and 3 are panel 1 and the elements
/// of column 2 read the copies at their left corners.
pub(crate) fn jointed() -> (FullField, ElementField) {
    let (mut f, e) = bump();
    let n = f.nodes_x();
    f.extra_grid = (0..=f.ny).map(|j| 2 + j * n).collect();
    for &g in &f.extra_grid.clone() {
        f.x.push(f.x[g]);
        f.y.push(f.y[g]);
        f.s.push(f.s[g]);
        f.t.push(f.t[g]);
        f.w.push(f.w[g] + 0.01);
        f.psi_x.push(f.psi_x[g]);
        f.psi_y.push(f.psi_y[g]);
        f.pressure.push(f.pressure[g] + 1.0);
        f.gap.push(f.gap[g]);
        f.signed_gap.push(f.signed_gap[g] - 0.01);
        f.v.push(f.v[g] + 0.1);
        f.sigma.push(f.sigma[g] + 1.0);
        f.contact.push(true);
        f.s1_bottom.push(f.s1_bottom[g]);
        f.s1_top.push(f.s1_top[g]);
    }
    let n_grid = f.n_grid();
    let mut corners = Vec::new();
    for j in 0..f.ny {
        for i in 0..f.nx {
            let mut c = f.element_nodes(i, j);
            if i == 2 {
                c[0] = n_grid + j;
                c[3] = n_grid + j + 1;
            }
            corners.push(c);
        }
    }
    f.corners = Some(corners);
    f.panel = (0..f.nx * f.ny).map(|e| u32::from(e % f.nx >= 2)).collect();
    f.joints = vec![super::JointLine {
        name: "J1".into(),
        kind: crate::layout::JointType::Aggregate,
        axis: crate::layout::Axis::X,
        at: 0.0,
        span: None,
    }];
    (f, e)
}
