//! Validation of a scene file into a [`Problem`]: one function per section, each naming the
//! field and the fix in its errors.

use super::spec::{Coord, LoadKind, LoadSpec, MeshSpec, PenaltySpec, SolverSpec};
use super::{Problem, SceneFile};
use crate::budget::default_memory_limit;
use crate::error::{Error, Result};
use crate::foundation::FoundationKind;
use crate::method::{Contact, Method, PenaltySettings, QpSettings};
use crate::model::{Groups, Load, Model, Physical};

/// Upper limit on elements per side: beyond it even a Winkler model exceeds any sane memory.
pub const MAX_ELEMENTS_PER_SIDE: i64 = 4000;

/// Range of the aspect ratio μ = width / length. Beyond it the plate is a strip (a beam) rather
/// than a plate, and at the extremes the geometry leaves double precision: μ = 5e-324 made every
/// nodal area zero (reported as a load "outside [inf, −inf]"), μ = 1e308 broke the Cholesky.
pub const ASPECT_RATIO_RANGE: [f64; 2] = [1e-3, 1e3];

fn aspect_ratio(field: &str, mu: f64) -> Result<f64> {
    let [lo, hi] = ASPECT_RATIO_RANGE;
    if !(lo..=hi).contains(&mu) {
        return Err(Error::invalid(
            field,
            format!("the plate's aspect ratio width / length = {mu:e} lies outside [{lo:e}, {hi:e}]: a plate that much longer than wide is a beam"),
        ));
    }
    Ok(mu)
}

fn finite_positive(field: &str, v: f64, unit: &str) -> Result<f64> {
    if !v.is_finite() {
        return Err(Error::invalid(
            field,
            format!("must be a finite number, got {v}"),
        ));
    }
    if v <= 0.0 {
        return Err(Error::invalid(
            field,
            format!("must be positive ({unit}), got {v}"),
        ));
    }
    Ok(v)
}

fn poisson(field: &str, v: f64) -> Result<f64> {
    if !v.is_finite() || v <= -1.0 || v >= 0.5 {
        return Err(Error::invalid(
            field,
            format!("Poisson's ratio must lie in (−1, 0.5), got {v}"),
        ));
    }
    Ok(v)
}

/// `[plate]` and `[foundation]` (SI units) or `[dimensionless]`: the groups, the physical
/// scales (L, D) of an SI scene, and the factors that turn scene coordinates into the unit
/// system (x / L, y / L).
#[allow(clippy::type_complexity)]
fn groups(file: &SceneFile) -> Result<(Groups, Option<(f64, f64)>, [f64; 2])> {
    match (&file.plate, &file.foundation, &file.dimensionless) {
            (Some(_), _, Some(_)) | (_, Some(_), Some(_)) => {
                Err(Error::invalid(
                    "dimensionless",
                    "give either [plate] and [foundation] (SI units) or [dimensionless], not both",
                ))
            }
            (None, None, None) => {
                Err(Error::invalid(
                    "plate",
                    "missing: give [plate] and [foundation] in SI units, or [dimensionless] with the paper's groups",
                ))
            }
            (Some(_), None, None) => {
                Err(Error::invalid(
                    "foundation",
                    "missing: add [foundation] with model = \"winkler\" (modulus) or \"half-space\" (youngs_modulus, poissons_ratio)",
                ))
            }
            (None, Some(_), None) => {
                Err(Error::invalid(
                    "plate",
                    "missing: add [plate] with length, width, thickness, youngs_modulus, poissons_ratio",
                ))
            }
            (Some(p), Some(f), None) => {
                let length = finite_positive("plate.length", p.length, "m")?;
                let width = finite_positive("plate.width", p.width, "m")?;
                let h = finite_positive("plate.thickness", p.thickness, "m")?;
                let e = finite_positive("plate.youngs_modulus", p.youngs_modulus, "Pa")?;
                let nu = poisson("plate.poissons_ratio", p.poissons_ratio)?;
                let chi = match p.shear_correction {
                    Some(c) => finite_positive("plate.shear_correction", c, "dimensionless, usually 5/6")?,
                    None => 5.0 / 6.0,
                };
                if h >= width.min(length) {
                    return Err(Error::invalid(
                        "plate.thickness",
                        format!("{h} m is not smaller than the plate's sides ({length} × {width} m): check units (metres)"),
                    ));
                }
                let l = 0.5 * length;
                let mu = aspect_ratio("plate.width", width / length)?;
                let d = e * h.powi(3) / (12.0 * (1.0 - nu * nu));
                let delta = h * h / (6.0 * chi * (1.0 - nu) * mu * l * l);
                let gamma = match f.model {
                    FoundationKind::Winkler => {
                        if f.youngs_modulus.is_some() || f.poissons_ratio.is_some() {
                            return Err(Error::invalid(
                                "foundation.youngs_modulus",
                                "belongs to model = \"half-space\"; a Winkler foundation takes only `modulus` (N/m³)",
                            ));
                        }
                        let k = finite_positive(
                            "foundation.modulus",
                            f.modulus.ok_or_else(|| {
                                Error::invalid("foundation.modulus", "missing: Winkler subgrade modulus K in N/m³")
                            })?,
                            "N/m³",
                        )?;
                        d / (k * mu * l.powi(4))
                    }
                    FoundationKind::HalfSpace => {
                        if f.modulus.is_some() {
                            return Err(Error::invalid(
                                "foundation.modulus",
                                "belongs to model = \"winkler\"; a half-space takes youngs_modulus (Pa) and poissons_ratio",
                            ));
                        }
                        let es = finite_positive(
                            "foundation.youngs_modulus",
                            f.youngs_modulus.ok_or_else(|| {
                                Error::invalid("foundation.youngs_modulus", "missing: soil Young's modulus E_s in Pa")
                            })?,
                            "Pa",
                        )?;
                        let nus = poisson(
                            "foundation.poissons_ratio",
                            f.poissons_ratio.ok_or_else(|| {
                                Error::invalid("foundation.poissons_ratio", "missing: soil Poisson's ratio ν_s")
                            })?,
                        )?;
                        d * (1.0 - nus * nus) / (std::f64::consts::PI * es * mu * l.powi(3))
                    }
                };
                // Each input is finite and positive, but their combination may still
                // underflow or overflow (a 1e308 m plate, a 1e-200 m thickness).
                for (name, v) in [("rigidity D", d), ("Δ", delta), ("Γ", gamma)] {
                    if !(v.is_finite() && v > 0.0) {
                        return Err(Error::invalid(
                            "plate",
                            format!(
                                "the plate and foundation values give {name} = {v:e}, outside double precision: check their units (m, Pa, N/m³)"
                            ),
                        ));
                    }
                }
                Ok((
                    Groups { foundation: f.model, gamma, delta, mu, nu },
                    Some((l, d)),
                    [1.0 / l, 1.0 / l],
                ))
            }
            (None, None, Some(g)) => {
                let gamma = finite_positive("dimensionless.gamma", g.gamma, "Γ")?;
                let delta = finite_positive("dimensionless.delta", g.delta, "Δ")?;
                let mu = aspect_ratio(
                    "dimensionless.mu",
                    finite_positive("dimensionless.mu", g.mu, "width/length")?,
                )?;
                let nu = poisson("dimensionless.nu", g.nu)?;
                Ok((Groups { foundation: g.foundation, gamma, delta, mu, nu }, None, [1.0, mu]))
            }
        }
}

/// `[[load]]`: loads in the unit system and P (a quarter of the resultant, N for SI scenes).
fn loads(
    specs: &[LoadSpec],
    groups: &Groups,
    physical: Option<(f64, f64)>,
    scale_xy: [f64; 2],
) -> Result<(Vec<Load>, f64)> {
    let mu = groups.mu;
    // Loads in unit-system geometry, magnitudes not yet normalised.
    let mut loads = Vec::with_capacity(specs.len());
    if specs.is_empty() {
        return Err(Error::invalid(
            "load",
            "no [[load]] entries: add at least one point, patch or uniform load",
        ));
    }
    let (hx, hy) = (1.0, mu);
    let tol = 1e-9;
    let coord_unit = if physical.is_some() {
        "m"
    } else {
        "s or t, in [−1, 1]"
    };
    for (k, l) in specs.iter().enumerate() {
        let field = |name: &str| format!("load[{k}].{name}");
        let value = |name: &str, c: Option<Coord>, scale: f64, half: f64| -> Result<f64> {
            match c {
                Some(Coord::Value(v)) => {
                    if !v.is_finite() {
                        return Err(Error::invalid(
                            field(name),
                            format!("must be finite, got {v}"),
                        ));
                    }
                    let u = v * scale;
                    if u.abs() > half * (1.0 + tol) {
                        return Err(Error::invalid(
                            field(name),
                            format!(
                                "{v} {coord_unit} lies outside the plate (|{name}| ≤ {:.6})",
                                half / scale
                            ),
                        ));
                    }
                    Ok(u.clamp(-half, half))
                }
                Some(Coord::Range(_)) => Err(Error::invalid(
                    field(name),
                    "a point load takes a single coordinate, not a range",
                )),
                None => Err(Error::invalid(field(name), "missing: the load's position")),
            }
        };
        let range = |name: &str, c: Option<Coord>, scale: f64, half: f64| -> Result<[f64; 2]> {
            match c {
                Some(Coord::Range([a, b])) => {
                    if !a.is_finite() || !b.is_finite() {
                        return Err(Error::invalid(field(name), "range ends must be finite"));
                    }
                    if a >= b {
                        return Err(Error::invalid(
                            field(name),
                            format!("range [{a}, {b}] must be increasing"),
                        ));
                    }
                    let (ua, ub) = (a * scale, b * scale);
                    if ua < -half * (1.0 + tol) || ub > half * (1.0 + tol) {
                        return Err(Error::invalid(
                            field(name),
                            format!(
                                "range [{a}, {b}] {coord_unit} leaves the plate (±{:.6})",
                                half / scale
                            ),
                        ));
                    }
                    Ok([ua.max(-half), ub.min(half)])
                }
                Some(Coord::Value(_)) => Err(Error::invalid(
                    field(name),
                    "a patch load takes a range [lo, hi]",
                )),
                None => Err(Error::invalid(
                    field(name),
                    "missing: the patch's extent [lo, hi]",
                )),
            }
        };
        let magnitude = |name: &str, v: Option<f64>| -> Result<f64> {
            let v = v.ok_or_else(|| Error::invalid(field(name), "missing"))?;
            if !v.is_finite() {
                return Err(Error::invalid(
                    field(name),
                    format!("must be finite, got {v}"),
                ));
            }
            Ok(v)
        };
        let forbid = |name: &str, present: bool, kind: &str| -> Result<()> {
            if present {
                Err(Error::invalid(
                    field(name),
                    format!("does not apply to a {kind} load"),
                ))
            } else {
                Ok(())
            }
        };
        let load = match l.kind {
            LoadKind::Point => {
                forbid("pressure", l.pressure.is_some(), "point")?;
                Load::Point {
                    x: value("x", l.x, scale_xy[0], hx)?,
                    y: value("y", l.y, scale_xy[1], hy)?,
                    force: magnitude("force", l.force)?,
                }
            }
            LoadKind::Patch => {
                forbid("force", l.force.is_some(), "patch")?;
                let p = magnitude("pressure", l.pressure)?;
                // In a dimensionless scene the pressure is a density per ds dt = dA / μ.
                let p = if physical.is_some() { p } else { p / mu };
                Load::Patch {
                    x: range("x", l.x, scale_xy[0], hx)?,
                    y: range("y", l.y, scale_xy[1], hy)?,
                    pressure: p,
                }
            }
            LoadKind::Uniform => {
                forbid("force", l.force.is_some(), "uniform")?;
                forbid("x", l.x.is_some(), "uniform")?;
                forbid("y", l.y.is_some(), "uniform")?;
                let p = magnitude("pressure", l.pressure)?;
                let p = if physical.is_some() { p } else { p / mu };
                Load::Patch {
                    x: [-hx, hx],
                    y: [-hy, hy],
                    pressure: p,
                }
            }
        };
        loads.push(load);
    }
    // Physical patches were given in Pa over m²; convert to unit geometry (area × L²).
    let area_scale = match physical {
        Some((l, _)) => l * l,
        None => 1.0,
    };
    let total: f64 = loads
        .iter()
        .map(|l| match l {
            Load::Point { .. } => l.resultant(),
            Load::Patch { .. } => l.resultant() * area_scale,
        })
        .sum();
    let gross: f64 = loads
        .iter()
        .map(|l| match l {
            Load::Point { .. } => l.resultant().abs(),
            Load::Patch { .. } => l.resultant().abs() * area_scale,
        })
        .sum();
    if !total.is_finite() || !gross.is_finite() {
        return Err(Error::invalid(
            "load",
            "the load magnitudes overflow when added up: check their units (N and Pa)",
        ));
    }
    if total.abs() <= 1e-12 * gross.max(f64::MIN_POSITIVE) {
        return Err(Error::invalid(
            "load",
            format!("the loads add up to zero (resultant {total:e}); a free plate needs a net vertical load"),
        ));
    }
    // P = |resultant| / 4; express every load in units of P.
    let p_force = total.abs() / 4.0;
    for (k, l) in loads.iter_mut().enumerate() {
        match l {
            Load::Point { force, .. } => *force /= p_force,
            Load::Patch { pressure, .. } => {
                *pressure *= area_scale / p_force;
                // A huge pressure on a vanishing patch has a finite resultant, but the pressure
                // itself, in units of the resultant per unit area, can overflow.
                if !pressure.is_finite() {
                    return Err(Error::invalid(
                        format!("load[{k}].pressure"),
                        "the pressure overflows when expressed per unit of the total load: the patch is too small for its pressure (check its extent and units, Pa)",
                    ));
                }
            }
        }
    }

    Ok((loads, p_force))
}

/// `[mesh] elements`: two positive element counts.
fn elements(spec: &MeshSpec) -> Result<[usize; 2]> {
    // Mesh.
    let el = &spec.elements;
    if el.len() != 2 {
        return Err(Error::invalid(
            "mesh.elements",
            format!("give two element counts [nx, ny], got {} values", el.len()),
        ));
    }
    for (k, &n) in el.iter().enumerate() {
        if n < 1 {
            return Err(Error::invalid(
                format!("mesh.elements[{k}]"),
                format!("must be a positive number of elements, got {n}"),
            ));
        }
        if n > MAX_ELEMENTS_PER_SIDE {
            return Err(Error::invalid(
                format!("mesh.elements[{k}]"),
                format!("{n} elements is more than the {MAX_ELEMENTS_PER_SIDE} allowed per side"),
            ));
        }
    }
    let elements = [el[0] as usize, el[1] as usize];

    Ok(elements)
}

/// `[solver]`: the method with its settings, and the memory limit in bytes.
fn solver(s: &SolverSpec) -> Result<(Method, f64)> {
    let penalty = match &s.penalty {
        PenaltySpec::Value(e) => PenaltySettings::fixed(*e),
        PenaltySpec::Word(w) if w.trim() == "auto" => PenaltySettings::default(),
        PenaltySpec::Word(w) => {
            return Err(Error::invalid(
                "solver.penalty",
                format!("`{w}` is neither \"auto\" nor a number; give \"auto\" or an ε̄ in (0, 1) such as 1e-5"),
            ))
        }
    };
    penalty.validate()?;
    if !(1..=10_000).contains(&s.max_iterations) {
        return Err(Error::invalid(
            "solver.max_iterations",
            format!("must lie in 1..=10000, got {}", s.max_iterations),
        ));
    }
    let penalty = PenaltySettings {
        max_iterations: s.max_iterations as usize,
        ..penalty
    };
    let method = match s.contact {
        Contact::Bonded => Method::Bonded,
        Contact::Unbonded => match s.method {
            crate::method::MethodKind::Penalty => Method::Penalty(penalty),
            crate::method::MethodKind::Qp => Method::Qp(QpSettings {
                form: s.qp_form,
                ..QpSettings::default()
            }),
        },
    };
    let memory_limit = match s.memory_limit_gib {
        Some(g) => finite_positive("solver.memory_limit_gib", g, "GiB")? * 1024f64.powi(3),
        None => default_memory_limit(),
    };
    Ok((method, memory_limit))
}

/// The model of a scene file (everything but `[solver]`'s method and memory limit).
pub fn model(file: &SceneFile) -> Result<Model> {
    let title = file
        .title
        .clone()
        .unwrap_or_else(|| "liftoff scene".to_string());
    let (groups, physical, scale_xy) = groups(file)?;
    let (loads, p_force) = loads(&file.load, &groups, physical, scale_xy)?;
    let elements = elements(&file.mesh)?;
    Ok(Model {
        title,
        groups,
        physical: physical.map(|(l, d)| Physical {
            half_length: l,
            force: p_force,
            rigidity: d,
        }),
        loads,
        elements,
        symmetry: file.mesh.symmetry,
        constraint: file.solver.constraint,
    })
}

/// Validate a whole scene file.
pub fn problem(file: &SceneFile) -> Result<Problem> {
    let model = model(file)?;
    let (method, memory_limit) = solver(&file.solver)?;
    Ok(Problem {
        model,
        method,
        route: file.solver.route,
        memory_limit,
    })
}
