//! The whole plate from a (possibly reduced) model: every node copy of the whole plate with the
//! model copy it mirrors, and the fields the report reads — nodal values over all copies and
//! element resultants, each element from its own corners and its own panel's section.
//!
//! A whole-plate element (I, J) is the model element at the mirrored position with its corners
//! reflected (as the FFT route's gather map); the copy at corner a of the whole element is the
//! model element's copy at the reflected corner, and a rotation normal to a symmetry line
//! changes sign on the mirrored side. Without joints this is the grid arithmetic of before,
//! number for number.

use super::field::{ElementField, FullField, JointLine};
use super::stress;
use crate::foundation::nodal_areas;
use crate::layout::PanelSection;
use crate::mesh::{Dof, Mesh};
use crate::model::{Model, Physical};
use crate::operators::Operators;
use crate::plate::{centre_resultants, ElementVector};
use crate::solve::Solution;

/// Local corner reflected about the element's vertical mid-line (x ↦ −x).
const MIRROR_X: [usize; 4] = [1, 0, 3, 2];
/// Local corner reflected about the element's horizontal mid-line (y ↦ −y).
const MIRROR_Y: [usize; 4] = [3, 2, 1, 0];

/// The whole plate of a model.
pub(super) struct WholePlate {
    /// Its grid (no symmetry reduction) with the model's layout.
    pub mesh: Mesh,
    /// For each node copy of `mesh`: the model's node copy and the signs of ψx and ψy there.
    pub source: Vec<(usize, f64, f64)>,
    /// The aspect ratio it was made for.
    pub mu: f64,
}

/// Model index of a whole-plate grid index and the sign a rotation normal to the symmetry
/// line takes there (−1 on the mirrored side).
fn model_index(full: usize, model_n: usize, sym: bool) -> (usize, f64) {
    if !sym {
        return (full, 1.0);
    }
    if full >= model_n {
        (full - model_n, 1.0)
    } else {
        (model_n - full, -1.0)
    }
}

/// Model element index of a whole-plate element index along one direction, and whether it is
/// mirrored.
fn model_element(full: usize, model_n: usize, sym: bool) -> (usize, bool) {
    if !sym || full >= model_n {
        (if sym { full - model_n } else { full }, false)
    } else {
        (model_n - 1 - full, true)
    }
}

/// The whole plate [−1, 1] × [−μ, μ] of the model mesh `mesh`.
pub(super) fn whole_plate(mesh: &Mesh, mu: f64) -> WholePlate {
    let [nx, ny] = mesh.full_elements();
    let plain = Mesh::new(2.0, 2.0 * mu, [nx, ny], false, false);
    let Some(topo) = &mesh.topo else {
        let mut source = Vec::with_capacity((nx + 1) * (ny + 1));
        for jj in 0..=ny {
            for ii in 0..=nx {
                let (i, sx) = model_index(ii, mesh.nx, mesh.sym_x);
                let (j, sy) = model_index(jj, mesh.ny, mesh.sym_y);
                source.push((mesh.node(i, j), sx, sy));
            }
        }
        return WholePlate {
            mesh: plain,
            source,
            mu,
        };
    };
    let whole = plain.with_layout(&topo.layout);
    let source = (0..whole.n_nodes())
        .map(|n| {
            // Every element holding the copy maps to the same model copy; take the first.
            let (e, a) = whole
                .topo
                .as_ref()
                .and_then(|t| t.incident(n).first().copied())
                .unwrap_or((0, 0));
            let (ie, je) = whole.element_ij(e);
            let (mi, fx) = model_element(ie, mesh.nx, mesh.sym_x);
            let (mj, fy) = model_element(je, mesh.ny, mesh.sym_y);
            let mut corner = a;
            if fx {
                corner = MIRROR_X[corner];
            }
            if fy {
                corner = MIRROR_Y[corner];
            }
            let node = mesh.element_nodes(mi + mj * mesh.nx)[corner];
            let sign = |f: bool| if f { -1.0 } else { 1.0 };
            (node, sign(fx), sign(fy))
        })
        .collect();
    WholePlate {
        mesh: whole,
        source,
        mu,
    }
}

/// The whole plate of `ops`'s mesh, made once per assembly and kept in its cache (a damage or
/// critical run reports thousands of solves on one assembly). A model of another aspect ratio
/// than the cached one's gets its own.
pub(super) fn cached_whole_plate(ops: &Operators, mu: f64) -> std::sync::Arc<WholePlate> {
    let made = ops
        .cache
        .get_or_try_init::<_, std::convert::Infallible>(|| Ok(whole_plate(&ops.mesh, mu)));
    match made {
        Ok((whole, _)) if whole.mu == mu => whole,
        _ => std::sync::Arc::new(whole_plate(&ops.mesh, mu)),
    }
}

/// The fields of a solution over the whole plate: nodal values over every copy (physical, see
/// [`FullField`]), element resultants and stresses (each element from its own corners, its
/// panel's D_p, S_p and thickness H_p, σ = ±6m/H_p²), and the unit-system nodal dofs
/// (w, ψx, ψy) of every copy of the whole mesh, with the field's index of each (the same on a
/// plate that is its whole rectangle; a shaped plate's field keeps every grid node, the mesh
/// only the plate's). `phi` is the model's would-be gap, `threshold` the contact
/// threshold on σ, `gap_per_sigma` the field's [`FullField::gap_per_sigma`].
pub(super) fn fields(
    model: &Model,
    ops: &Operators,
    sol: &Solution,
    whole: &WholePlate,
    phi: &[f64],
    (threshold, gap_per_sigma): (f64, f64),
    ph: &Physical,
) -> (FullField, ElementField, Vec<[f64; 3]>, Vec<usize>) {
    let mesh = &ops.mesh;
    let mu = model.groups.mu;
    let wm = &whole.mesh;
    let [nx, ny] = mesh.full_elements();
    let nnx = nx + 1;
    let n = whole.source.len();
    let areas = nodal_areas(mesh);
    let layout = mesh.topo.as_ref().map(|t| t.layout.clone());
    let mut field = FullField {
        nx,
        ny,
        x: Vec::with_capacity(n),
        y: Vec::with_capacity(n),
        s: Vec::with_capacity(n),
        t: Vec::with_capacity(n),
        w: Vec::with_capacity(n),
        psi_x: Vec::with_capacity(n),
        psi_y: Vec::with_capacity(n),
        pressure: Vec::with_capacity(n),
        gap: Vec::with_capacity(n),
        signed_gap: Vec::with_capacity(n),
        gap_per_sigma,
        v: Vec::with_capacity(n),
        sigma: Vec::with_capacity(n),
        contact: Vec::with_capacity(n),
        extra_grid: wm
            .topo
            .as_ref()
            .map_or(Vec::new(), |t| t.extra_grid.clone()),
        corners: wm
            .topo
            .as_ref()
            .filter(|t| t.cuts())
            .map(|t| t.corners.clone()),
        panel: wm.topo.as_ref().map_or(Vec::new(), |t| t.panel.clone()),
        joints: layout.as_ref().map_or(Vec::new(), |l| {
            l.joints
                .iter()
                .map(|j| JointLine {
                    name: j.name.clone(),
                    kind: j.kind.kind(),
                    axis: j.axis,
                    at: j.at * ph.half_length,
                    span: j.span.map(|s| s.map(|v| v * ph.half_length)),
                })
                .collect()
        }),
        ..FullField::default()
    };
    // The field's numbering: every grid node first (on a shaped plate those outside it too,
    // zero and out of contact, read by no plate cell), then the extra copies; the whole
    // mesh's own numbering skips the nodes outside the plate.
    let n_grid = nnx * (ny + 1);
    let n_first = n - field.extra_grid.len();
    let index = |k: usize| {
        if k < n_first {
            wm.grid_of(k)
        } else {
            n_grid + (k - n_first)
        }
    };
    let n_field = n_grid + field.extra_grid.len();
    let mut full_u = vec![[0.0; 3]; n];
    for g in 0..n_field {
        let gg = if g < n_grid {
            g
        } else {
            field.extra_grid[g - n_grid]
        };
        let (ii, jj) = (gg % nnx, gg / nnx);
        let xu = -1.0 + ii as f64 * 2.0 / nx as f64;
        let yu = mu * (-1.0 + jj as f64 * 2.0 / ny as f64);
        field.x.push(xu * ph.half_length);
        field.y.push(yu * ph.half_length);
        field.s.push(xu);
        field.t.push(yu / mu);
    }
    for v in [
        &mut field.w,
        &mut field.psi_x,
        &mut field.psi_y,
        &mut field.pressure,
        &mut field.gap,
        &mut field.signed_gap,
        &mut field.v,
        &mut field.sigma,
    ] {
        v.resize(n_field, 0.0);
    }
    field.contact.resize(n_field, false);
    for (k, &(m, sx, sy)) in whole.source.iter().enumerate() {
        let get = |d: Dof| ops.dofs.eq(m, d).map_or(0.0, |e| sol.u[e]);
        let w = get(Dof::W);
        let px = sx * get(Dof::PsiX);
        let py = sy * get(Dof::PsiY);
        full_u[k] = [w, px, py];
        let r = sol.sigma[m];
        let gap = sol.gap[m] / areas[m];
        let i = index(k);
        field.w[i] = w * ph.deflection();
        field.psi_x[i] = px * ph.rotation();
        field.psi_y[i] = py * ph.rotation();
        field.pressure[i] = r * ph.pressure();
        field.gap[i] = gap * ph.deflection();
        field.signed_gap[i] = phi[m] * ph.deflection();
        field.v[i] = w;
        field.sigma[i] = mu * r;
        field.contact[i] = r > threshold;
    }
    if let Some(t) = wm.topo.as_ref().filter(|t| t.is_shaped()) {
        field.plate = (0..wm.n_elements()).map(|e| t.is_live(e)).collect();
        field.corners = Some(
            t.corners
                .iter()
                .enumerate()
                .map(|(e, c)| {
                    if t.is_live(e) {
                        c.map(index)
                    } else {
                        let (i, j) = wm.element_ij(e);
                        let g = i + j * nnx;
                        [g, g + 1, g + 1 + nnx, g + nnx]
                    }
                })
                .collect(),
        );
    }

    // Element resultants on the whole plate. A temperature load's initial curvature carries
    // no moment of its own: m = −D_p (κ − κ₀,p) with κ₀,p = κ H/H_p, so each element adds
    // D_p (1 + ν) κ₀,p (D = 1: the reference plate's D_b κ₀ is (1 + ν) κ).
    let thermal = (1.0 + ops.section.poisson) * model.thermal_curvature();
    // Surface stresses: ±6m/H_p² in the unit system (P/L²), then to the scene's units; a
    // nonlinear temperature profile's own stress scales with the panel's modulus E_p/E.
    let thickness = model.thickness_ratio();
    let eigen = model.face_stress();
    let ratios: Vec<PanelSection> = layout
        .as_ref()
        .map_or(vec![PanelSection::REFERENCE], |l| l.sections());
    let mut elements = ElementField::default();
    for e in 0..wm.n_elements() {
        if !wm.is_live(e) {
            // A cell outside a shaped plate: its place kept (rows are ie + je nx), no values.
            let (xc, yc) = wm.element_centre(e);
            elements.x.push(xc * ph.half_length);
            elements.y.push(yc * ph.half_length);
            for v in [
                &mut elements.mx,
                &mut elements.my,
                &mut elements.mxy,
                &mut elements.qx,
                &mut elements.qy,
                &mut elements.thickness,
            ] {
                v.push(0.0);
            }
            elements.bottom.push(0.0, 0.0, 0.0);
            elements.top.push(0.0, 0.0, 0.0);
            continue;
        }
        let p = wm.panel_of(e);
        let ratio = ratios.get(p).copied().unwrap_or(PanelSection::REFERENCE);
        let section = ops.sections.get(p).copied().unwrap_or(ops.section);
        let mut ue = ElementVector::zeros();
        for (a, &node) in wm.element_nodes(e).iter().enumerate() {
            for d in 0..3 {
                ue[3 * a + d] = full_u[node][d];
            }
        }
        let mut r = centre_resultants(&section, wm.hx, wm.hy, &ue);
        let thermal_moment = thermal * (ratio.bending / ratio.thickness);
        r[0] += thermal_moment;
        r[1] += thermal_moment;
        let (xc, yc) = wm.element_centre(e);
        elements.x.push(xc * ph.half_length);
        elements.y.push(yc * ph.half_length);
        elements.mx.push(r[0] * ph.moment());
        elements.my.push(r[1] * ph.moment());
        elements.mxy.push(r[2] * ph.moment());
        elements.qx.push(r[3] * ph.shear());
        elements.qy.push(r[4] * ph.shear());
        let h = thickness * ratio.thickness;
        let modulus = ratio.shear / ratio.thickness;
        let (b, t) = stress::face_states(
            [r[0], r[1], r[2]],
            h,
            [eigen[0] * modulus, eigen[1] * modulus],
        );
        let s = ph.pressure();
        elements.bottom.push(b[0] * s, b[1] * s, b[2] * s);
        elements.top.push(t[0] * s, t[1] * s, t[2] * s);
        elements.thickness.push(h * ph.half_length);
    }
    let in_field = |values: Vec<f64>| {
        let mut out = vec![0.0; n_field];
        for (k, v) in values.into_iter().enumerate() {
            out[index(k)] = v;
        }
        out
    };
    field.s1_bottom = in_field(stress::recover_principal(wm, &elements.bottom));
    field.s1_top = in_field(stress::recover_principal(wm, &elements.top));
    let to_field = (0..n).map(index).collect();
    (field, elements, full_u, to_field)
}
