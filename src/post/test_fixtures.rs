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
