//! Integrals of the bilinear shape functions f_i over the pieces of the grid that a rectangle or
//! a segment covers: the consistent nodal vectors of patch and line loads, the voids' initial
//! gap and the zones' share of each node's spring.

use crate::mesh::Mesh;
use crate::plate;
use crate::quadrature::GaussRule;

/// ∫ f_i dA over the part of the rectangle [x0, x1] × [y0, y1] that lies on the model, for
/// every node i it touches (2 × 2 Gauss points per element piece: exact for bilinear f_i).
pub fn patch_integrals(mesh: &Mesh, x: [f64; 2], y: [f64; 2]) -> Vec<(usize, f64)> {
    let mut out = Vec::new();
    let x_lo = mesh.x0;
    let x_hi = mesh.x0 + mesh.nx as f64 * mesh.hx;
    let y_lo = mesh.y0;
    let y_hi = mesh.y0 + mesh.ny as f64 * mesh.hy;
    let (ax, bx) = (x[0].max(x_lo), x[1].min(x_hi));
    let (ay, by) = (y[0].max(y_lo), y[1].min(y_hi));
    if bx <= ax || by <= ay {
        return out;
    }
    let rule = GaussRule::new(2);
    let i0 = (((ax - x_lo) / mesh.hx).floor().max(0.0) as usize).min(mesh.nx - 1);
    let i1 = (((bx - x_lo) / mesh.hx).ceil() as usize).clamp(i0 + 1, mesh.nx);
    let j0 = (((ay - y_lo) / mesh.hy).floor().max(0.0) as usize).min(mesh.ny - 1);
    let j1 = (((by - y_lo) / mesh.hy).ceil() as usize).clamp(j0 + 1, mesh.ny);
    for je in j0..j1 {
        for ie in i0..i1 {
            let ex0 = x_lo + ie as f64 * mesh.hx;
            let ey0 = y_lo + je as f64 * mesh.hy;
            let (cx0, cx1) = (ax.max(ex0), bx.min(ex0 + mesh.hx));
            let (cy0, cy1) = (ay.max(ey0), by.min(ey0 + mesh.hy));
            if cx1 <= cx0 || cy1 <= cy0 {
                continue;
            }
            let e = ie + je * mesh.nx;
            if !mesh.is_live(e) {
                continue; // outside a shaped plate: no plate, no soil contact
            }
            let nodes = mesh.element_nodes(e);
            let mut acc = [0.0; 4];
            for (px, wx) in rule.on_interval(cx0, cx1) {
                for (py, wy) in rule.on_interval(cy0, cy1) {
                    let n = plate::shape(
                        2.0 * (px - ex0) / mesh.hx - 1.0,
                        2.0 * (py - ey0) / mesh.hy - 1.0,
                    );
                    for a in 0..4 {
                        acc[a] += wx * wy * n[a];
                    }
                }
            }
            out.extend(nodes.into_iter().zip(acc));
        }
    }
    out
}

/// ∫ f_i ds along the part of the segment `from` → `to` that lies on the model, for every node
/// i it touches: the segment is cut at the element lines and each piece integrated with two
/// Gauss points (exact: along a straight line a bilinear f_i is quadratic). A piece lying on a
/// symmetry line of a reduced model counts half, like a point load there.
pub fn line_integrals(mesh: &Mesh, from: [f64; 2], to: [f64; 2]) -> Vec<(usize, f64)> {
    let mut out = Vec::new();
    let (dx, dy) = (to[0] - from[0], to[1] - from[1]);
    let len = dx.hypot(dy);
    if len <= 0.0 {
        return out;
    }
    let x_lo = mesh.x0;
    let x_hi = mesh.x0 + mesh.nx as f64 * mesh.hx;
    let y_lo = mesh.y0;
    let y_hi = mesh.y0 + mesh.ny as f64 * mesh.hy;
    // Parameters where the segment crosses a grid line, clipped to the model.
    let mut cuts = vec![0.0, 1.0];
    for (d, p0, lo, h, n) in [
        (dx, from[0], x_lo, mesh.hx, mesh.nx),
        (dy, from[1], y_lo, mesh.hy, mesh.ny),
    ] {
        if d.abs() > 0.0 {
            for k in 0..=n {
                let s = (lo + k as f64 * h - p0) / d;
                if s > 0.0 && s < 1.0 {
                    cuts.push(s);
                }
            }
        }
    }
    cuts.sort_by(f64::total_cmp);
    let tol = 1e-9;
    let rule = GaussRule::new(2);
    for w in cuts.windows(2) {
        let (s0, s1) = (w[0], w[1]);
        if s1 - s0 <= 1e-14 {
            continue;
        }
        let mid = 0.5 * (s0 + s1);
        let (mx, my) = (from[0] + mid * dx, from[1] + mid * dy);
        if mx < x_lo - tol || mx > x_hi + tol || my < y_lo - tol || my > y_hi + tol {
            continue;
        }
        let mut weight = 1.0;
        if mesh.sym_x && mx.abs() <= tol && dx.abs() <= tol * len {
            weight *= 0.5;
        }
        if mesh.sym_y && my.abs() <= tol && dy.abs() <= tol * len {
            weight *= 0.5;
        }
        let Some((e, _, _)) = mesh.locate(mx.clamp(x_lo, x_hi), my.clamp(y_lo, y_hi)) else {
            continue;
        };
        let nodes = mesh.element_nodes(e);
        let (ex, ey) = mesh.element_centre(e);
        for (s, ws) in rule.on_interval(s0, s1) {
            let (px, py) = (from[0] + s * dx, from[1] + s * dy);
            let n = plate::shape(2.0 * (px - ex) / mesh.hx, 2.0 * (py - ey) / mesh.hy);
            for a in 0..4 {
                out.push((nodes[a], weight * ws * len * n[a]));
            }
        }
    }
    out
}
