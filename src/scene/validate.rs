//! Validation of a scene file into a [`Problem`]: one function per section, each naming the
//! field and the fix in its errors.

use super::bearing::{bearing_length, raw_allowable};
use super::loads::{
    normalise, raw_loads, raw_voids, voids_for, zones, RawLoad, RawVoid, DEFAULT_CASE,
};
use super::spec::{
    DimensionlessSpec, FoundationSpec, LoadKind, MeshSpec, PenaltySpec, PlateSpec, SolverSpec,
};
use super::temperature::Thermal;
use super::{Combination, Problem, SceneFile};
use crate::budget::default_memory_limit;
pub(super) use crate::check::finite_positive;
use crate::check::poisson;
use crate::error::{Error, Result};
use crate::foundation::soil::PlateScale;
use crate::method::{Contact, Method, PenaltySettings, QpSettings};
use crate::model::{Groups, Load, LoadReference, Model, Physical, Zone};
use crate::vehicle::{Frame, Vehicle};

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

/// `[plate]` and `[foundation]` (SI units) or `[dimensionless]`: the groups, the physical
/// scales (L, D) of an SI scene, and the factors that turn scene coordinates into the unit
/// system (x / L, y / L).
#[allow(clippy::type_complexity)]
fn groups(file: &SceneFile) -> Result<(Groups, Option<(f64, f64)>, [f64; 2])> {
    match (&file.plate, &file.foundation, &file.dimensionless) {
        (Some(_), _, Some(_)) | (_, Some(_), Some(_)) => Err(Error::invalid(
            "dimensionless",
            "give either [plate] and [foundation] (SI units) or [dimensionless], not both",
        )),
        (None, None, None) => Err(Error::invalid(
            "plate",
            "missing: give [plate] and [foundation] in SI units, or [dimensionless] with the paper's groups",
        )),
        (Some(_), None, None) => Err(Error::invalid(
            "foundation",
            "missing: add [foundation] with model = \"winkler\" (modulus), \"half-space\" (youngs_modulus, poissons_ratio), \"pasternak\" (modulus, shear_modulus) or \"elastic-layer\" (youngs_modulus, poissons_ratio, depth)",
        )),
        (None, Some(_), None) => Err(Error::invalid(
            "plate",
            "missing: add [plate] with length, width, thickness, youngs_modulus, poissons_ratio",
        )),
        (Some(p), Some(f), None) => {
            let (groups, l, d) = si_groups(p, f)?;
            Ok((groups, Some((l, d)), [1.0 / l, 1.0 / l]))
        }
        (None, None, Some(g)) => {
            let groups = dimensionless_groups(g)?;
            Ok((groups, None, [1.0, groups.mu]))
        }
    }
}

/// `[plate]` on `[foundation]` in SI units: the groups, L (m) and D (N·m).
fn si_groups(p: &PlateSpec, f: &FoundationSpec) -> Result<(Groups, f64, f64)> {
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
    let plate = PlateScale {
        delta,
        mu,
        nu,
        half_length: l,
        rigidity: d,
    };
    let (gamma, soil) = f.model.from_si(&f.soil, &plate)?;
    let groups = Groups {
        gamma,
        delta,
        mu,
        nu,
        soil,
    };
    // Each input is finite and positive, but their combination may still underflow or overflow
    // (a 1e308 m plate, a 1e-200 m thickness).
    for (name, v) in [("rigidity D", d), ("Δ", delta), ("Γ", groups.gamma)] {
        if !(v.is_finite() && v > 0.0) {
            return Err(Error::invalid(
                "plate",
                format!(
                    "the plate and foundation values give {name} = {v:e}, outside double precision: check their units (m, Pa, N/m³)"
                ),
            ));
        }
    }
    Ok((groups, l, d))
}

/// `[dimensionless]`: the paper's groups.
fn dimensionless_groups(g: &DimensionlessSpec) -> Result<Groups> {
    let gamma = finite_positive("dimensionless.gamma", g.gamma, "Γ")?;
    let delta = finite_positive("dimensionless.delta", g.delta, "Δ")?;
    let mu = aspect_ratio(
        "dimensionless.mu",
        finite_positive("dimensionless.mu", g.mu, "width/length")?,
    )?;
    let nu = poisson("dimensionless.nu", g.nu)?;
    let plate = PlateScale {
        delta,
        mu,
        nu,
        half_length: 1.0,
        rigidity: 1.0,
    };
    let soil = g.foundation.from_groups(&g.soil, &plate, gamma)?;
    Ok(Groups {
        gamma,
        delta,
        mu,
        nu,
        soil,
    })
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
    let mut cg = penalty.cg;
    if let Some(t) = s.cg_tolerance {
        // Tighter than 1e-14 the residual cannot fall in double precision; looser than the
        // loose steps' 1e-4 the confirming solve would not confirm the set.
        if !(1e-14..=cg.loose_tolerance).contains(&t) {
            return Err(Error::invalid(
                "solver.cg_tolerance",
                format!(
                    "must lie in 1e-14 ..= {:e}, got {t}; the default is {:e} (1e-8 gives stresses to about 7 digits, faster)",
                    cg.loose_tolerance, cg.tolerance
                ),
            ));
        }
        cg.tolerance = t;
    }
    let penalty = PenaltySettings {
        max_iterations: s.max_iterations as usize,
        start: s.start,
        cg,
        ..penalty
    };
    let method = match s.contact {
        Contact::Bonded => Method::Bonded,
        Contact::Unbonded => match s.method {
            crate::method::MethodKind::Penalty => Method::Penalty(penalty),
            crate::method::MethodKind::Qp => Method::Qp(QpSettings {
                form: s.qp_form,
                solver: s.qp_solver,
                start: s.start,
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

/// Everything of a scene file but its loads' factors and P: the parts every combination shares.
struct Shared {
    title: String,
    groups: Groups,
    physical: Option<(f64, f64)>,
    raw: Vec<RawLoad>,
    voids: Vec<RawVoid>,
    zones: Vec<Zone>,
    allowable: Option<f64>,
    /// The bearing check's averaging length, units of L.
    bearing_length: f64,
    elements: [usize; 2],
    layout: crate::layout::Layout,
    /// The axles and gears, each where its entry puts it, its `loads` not yet set.
    vehicles: Vec<Vehicle>,
}

fn shared(file: &SceneFile) -> Result<Shared> {
    let title = file
        .title
        .clone()
        .unwrap_or_else(|| "liftoff scene".to_string());
    let (groups, physical, scale_xy) = groups(file)?;
    let thermal = match (&file.plate, physical) {
        (Some(p), Some((_, d))) => Some(Thermal {
            alpha: p
                .thermal_expansion
                .map(|a| finite_positive("plate.thermal_expansion", a, "1/K"))
                .transpose()?,
            thickness: p.thickness,
            rigidity: d,
            poisson: p.poissons_ratio,
        }),
        _ => None,
    };
    let plate = file
        .plate
        .as_ref()
        .map_or([0.0; 2], |p| [p.length, p.width]);
    let raw = raw_loads(&file.load, &groups, physical, thermal, scale_xy, plate)?;
    let vehicles = vehicles(file, &raw, &groups, physical, scale_xy, plate)?;
    let voids = raw_voids(file, &groups, physical, scale_xy)?;
    let zones = zones(file, &groups, scale_xy)?;
    let allowable = raw_allowable(file, &groups, physical)?;
    let bearing_length = bearing_length(file, &groups, physical)?;
    let elements = elements(&file.mesh)?;
    let frame = super::joints::Frame {
        half: [1.0, groups.mu],
        scale_xy,
        elements,
        si: match (&file.plate, physical) {
            (Some(p), Some((l, d))) => Some([l, d, p.thickness, p.youngs_modulus]),
            _ => None,
        },
        max_elements: MAX_ELEMENTS_PER_SIDE as usize,
    };
    let mut layout = super::joints::layout(file, &frame)?;
    super::panels::panels(file, &mut layout, &frame)?;
    super::outline::shapes(file, &mut layout, &frame)?;
    super::outline::bars_on_plate(file, &mut layout, &frame)?;
    super::joints::segment_ends(&layout, &frame)?;
    let raw = super::outline::uniform_on_plate(file, raw, &layout, &frame);
    let unit_loads: Vec<Load> = raw.iter().map(|r| r.load).collect();
    super::panels::loads_off_cuts(&layout, &unit_loads, &frame)?;
    super::outline::loads_on_plate(&layout, &unit_loads, &frame)?;
    Ok(Shared {
        title,
        groups,
        physical,
        raw,
        voids,
        zones,
        allowable,
        bearing_length,
        elements,
        layout,
        vehicles,
    })
}

/// The `axle` and `gear` entries as [`Vehicle`]s (their raw loads, one per tire, are already in
/// `raw`: reading them again cannot fail where [`raw_loads`] did not).
fn vehicles(
    file: &SceneFile,
    raw: &[RawLoad],
    groups: &Groups,
    physical: Option<(f64, f64)>,
    scale_xy: [f64; 2],
    plate: [f64; 2],
) -> Result<Vec<Vehicle>> {
    let Some((l, _)) = physical else {
        return Ok(Vec::new());
    };
    let frame = Frame {
        scale_xy,
        half: [1.0, groups.mu],
        area_scale: l * l,
        plate,
    };
    let mut out = Vec::new();
    for (k, spec) in file.load.iter().enumerate() {
        let axle = match spec.kind {
            LoadKind::Axle => true,
            LoadKind::Gear => false,
            _ => continue,
        };
        let case = raw
            .iter()
            .find(|r| r.source == k)
            .map_or_else(|| DEFAULT_CASE.to_string(), |r| r.case.clone());
        out.push(super::vehicles::vehicle(spec, k, axle, frame, case)?);
    }
    Ok(out)
}

impl Shared {
    /// The model of one factored load set.
    fn model(
        &self,
        file: &SceneFile,
        title: String,
        factors: &[(usize, f64)],
        what: &str,
    ) -> Result<Model> {
        let loads: Vec<(usize, Load)> = factors
            .iter()
            .map(|&(k, f)| (k, scale(self.raw[k].load, f)))
            .collect();
        let (loads, p_force, reference) = normalise(loads, what)?;
        // Each axle and gear of this load set, with its factor and its prints' places (its raw
        // loads are consecutive, and `factors` keeps the raw order).
        let vehicles = self
            .vehicles
            .iter()
            .filter_map(|v| {
                let ours = |j: &usize| self.raw[factors[*j].0].source == v.entry;
                let first = (0..factors.len()).find(ours)?;
                let count = (first..factors.len()).take_while(ours).count();
                Some(Vehicle {
                    factor: factors[first].1,
                    loads: first..first + count,
                    ..v.clone()
                })
            })
            .collect();
        let voids = voids_for(&self.voids, &self.groups, p_force, self.physical, what)?;
        Ok(Model {
            title,
            groups: self.groups,
            physical: self.physical.map(|(l, d)| Physical {
                half_length: l,
                force: p_force,
                rigidity: d,
                units: file.units,
            }),
            loads,
            elements: self.elements,
            symmetry: file.mesh.symmetry,
            constraint: file.solver.constraint,
            voids,
            zones: self.zones.clone(),
            allowable_pressure: self.allowable.map(|a| a / p_force),
            bearing_length: self.bearing_length,
            load_scale: p_force,
            reference,
            layout: self.layout.clone(),
            vehicles,
        })
    }
}

/// A load with its magnitude times `f`.
fn scale(load: Load, f: f64) -> Load {
    match load {
        Load::Point { x, y, force } => Load::Point {
            x,
            y,
            force: force * f,
        },
        Load::Patch { x, y, pressure } => Load::Patch {
            x,
            y,
            pressure: pressure * f,
        },
        Load::Line {
            from,
            to,
            force_per_length,
        } => Load::Line {
            from,
            to,
            force_per_length: force_per_length * f,
        },
        Load::Temperature { curvature } => Load::Temperature {
            curvature: curvature * f,
        },
        Load::FaceStress { top, bottom } => Load::FaceStress {
            top: top * f,
            bottom: bottom * f,
        },
    }
}

/// The model of a scene file with all its loads acting together (everything but `[solver]`'s
/// method and memory limit). A scene with `[[combination]]`s is refused here: take
/// [`combinations`].
pub fn model(file: &SceneFile) -> Result<Model> {
    let sh = shared(file)?;
    let all: Vec<(usize, f64)> = (0..sh.raw.len()).map(|k| (k, 1.0)).collect();
    sh.model(file, sh.title.clone(), &all, "")
}

/// Longest combination name: it names an output folder.
pub const MAX_COMBINATION_NAME: usize = 64;

/// `[[combination]]`: each combination's model (empty without combinations).
pub fn combinations(file: &SceneFile) -> Result<Vec<Combination>> {
    if file.combination.is_empty() {
        return Ok(Vec::new());
    }
    let sh = shared(file)?;
    let mut cases: Vec<&str> = sh.raw.iter().map(|r| r.case.as_str()).collect();
    cases.sort_unstable();
    cases.dedup();
    let mut out: Vec<Combination> = Vec::with_capacity(file.combination.len());
    for (c, spec) in file.combination.iter().enumerate() {
        let field = |n: &str| format!("combination[{c}].{n}");
        let name = spec.name.trim();
        let bad = |ch: char| !(ch.is_ascii_alphanumeric() || "-_.+".contains(ch));
        if name.is_empty()
            || name.len() > MAX_COMBINATION_NAME
            || name.chars().any(bad)
            || name.starts_with('.')
        {
            return Err(Error::invalid(
                field("name"),
                format!("`{}` cannot name an output folder: use 1 to {MAX_COMBINATION_NAME} letters, digits, '-', '_', '+' or '.' (e.g. \"ULS-1\")", spec.name),
            ));
        }
        if let Some(prev) = out.iter().position(|o| o.name == name) {
            return Err(Error::invalid(
                field("name"),
                format!(
                    "`{name}` is already the name of combination[{prev}]: names must be unique"
                ),
            ));
        }
        if spec.factors.is_empty() {
            return Err(Error::invalid(
                field("factors"),
                format!(
                    "is empty: give a factor per load case, e.g. {{ {} = 1.0 }}",
                    cases.first().copied().unwrap_or(DEFAULT_CASE)
                ),
            ));
        }
        let mut picked = Vec::new();
        let mut factors = Vec::new();
        for (case, &f) in &spec.factors {
            if !cases.contains(&case.as_str()) {
                return Err(Error::invalid(
                    field("factors"),
                    format!("names the case `{case}`, which no [[load]] has; the cases are: {} (loads without `case` are in \"{DEFAULT_CASE}\")", cases.join(", ")),
                ));
            }
            if !f.is_finite() {
                return Err(Error::invalid(
                    field("factors"),
                    format!("the factor on `{case}` must be finite, got {f}"),
                ));
            }
            factors.push((case.clone(), f));
            picked.extend(
                sh.raw
                    .iter()
                    .enumerate()
                    .filter(|(_, r)| r.case == *case)
                    .map(|(k, _)| (k, f)),
            );
        }
        picked.sort_by_key(|&(k, _)| k);
        let what = format!("combination `{name}`: ");
        let model = sh.model(file, format!("{} — {name}", sh.title), &picked, &what)?;
        out.push(Combination {
            name: name.to_string(),
            factors,
            model,
        });
    }
    Ok(out)
}

/// Validate a whole scene file.
pub fn problem(file: &SceneFile) -> Result<Problem> {
    let combinations = combinations(file)?;
    let model = match combinations.first() {
        Some(c) => c.model.clone(),
        None => model(file)?,
    };
    let (method, memory_limit) = solver(&file.solver)?;
    if method != Method::Bonded {
        let named =
            |m: &Model, what: String| (m.reference != LoadReference::NetLoad).then_some(what);
        let zero = match combinations.is_empty() {
            true => named(&model, String::new()),
            false => combinations
                .iter()
                .find_map(|c| named(&c.model, format!("combination `{}`: ", c.name))),
        };
        if let Some(what) = zero {
            let hint = if file
                .load
                .iter()
                .any(|l| matches!(l.kind, LoadKind::Temperature))
            {
                " (a temperature load alone has no resultant: add the plate's self-weight to it)"
            } else {
                ""
            };
            return Err(Error::invalid(
                "load",
                format!("{what}the loads add up to zero: a foundation that cannot pull needs a net downward load to hold the plate{hint}; bonded contact (solver.contact = \"bonded\") carries loads without a resultant"),
            ));
        }
    }
    if method == Method::Bonded && !model.voids.is_empty() {
        return Err(Error::invalid(
            "void",
            "voids need unbonded contact (solver.contact = \"unbonded\"): bonded contact would glue the plate to the lowered surface",
        ));
    }
    let mut warnings = super::plausible::warnings(file, &model);
    let damage = damage_plan(file, &model, !combinations.is_empty(), &method)?;
    if let Some(plan) = &damage {
        warnings.extend(super::plausible::traffic(plan, &model, file.units));
    }
    Ok(Problem {
        model,
        combinations,
        method,
        route: file.solver.route,
        memory_limit,
        warnings,
        damage,
        ends: file.plate.as_ref().and_then(|p| p.ends),
    })
}

/// The scene's `[traffic]`, `[climate]` and `[damage]`, checked against its model, with the
/// curvature of one kelvin of temperature difference in the model's units (κ D / P = D α / (H P)).
fn damage_plan(
    file: &SceneFile,
    model: &Model,
    combinations: bool,
    method: &Method,
) -> Result<Option<crate::damage::plan::DamagePlan>> {
    let names: Vec<Option<&str>> = model.vehicles.iter().map(|v| v.name.as_deref()).collect();
    let Some(mut plan) = crate::damage::plan::DamagePlan::new(
        file.traffic.as_ref(),
        file.climate.as_ref(),
        file.damage.as_ref(),
        &names,
        file.plate.as_ref().map(|p| p.thickness),
        &|depths: &[f64], temps: &[f64]| {
            let parts = super::temperature::piecewise_linear(depths, temps);
            (parts.gradient, parts.nonlinear)
        },
    )?
    else {
        return Ok(None);
    };
    // `[plate] ends` says it for every study; `[traffic] ends`, older, for the damage run: where
    // both are given they must agree.
    if let Some(ends) = file.plate.as_ref().and_then(|p| p.ends) {
        let cut = ends == crate::layout::Ends::Cut;
        match file.traffic.as_ref().and_then(|t| t.ends.as_deref()) {
            None => plan.cut = cut,
            Some(said) if plan.cut != cut => {
                return Err(Error::invalid(
                    "traffic.ends",
                    format!("says \"{said}\" where plate.ends says \"{ends}\": the plate's ends are one thing; give one of the two keys"),
                ))
            }
            Some(_) => {}
        }
    }
    if combinations {
        return Err(Error::invalid(
            "combination",
            "a damage scene holds its loads without [[combination]]: the traffic's groups, levels and climate bins make its cases",
        ));
    }
    plan.units = model.physical.map(|p| p.units);
    plan.curvature_per_kelvin = match (&file.plate, model.physical) {
        (Some(p), Some(ph)) => p
            .thermal_expansion
            .map(|alpha| ph.rigidity * alpha / (p.thickness * model.load_scale)),
        _ => None,
    };
    // The lane's outer edge must lie across the plate.
    if let (Some(e), Some(p)) = (plan.edge_at, &file.plate) {
        if e.abs() >= p.width / 2.0 {
            return Err(Error::invalid(
                "traffic.edge_at",
                format!(
                    "y = {e} m is not on the {} m wide plate (|y| < {} m): give the y of the lane's outer edge, such as a shoulder joint's",
                    p.width,
                    p.width / 2.0
                ),
            ));
        }
    }
    // A bin's own subgrade modulus replaces the Winkler soil's k; other soils have none.
    if let Some(k) = plan
        .climate
        .iter()
        .position(|c| c.subgrade_modulus.is_some())
    {
        if model.groups.foundation() != crate::foundation::FoundationKind::Winkler
            || model.physical.is_none()
        {
            return Err(Error::invalid(
                format!("climate.bin[{k}].subgrade_modulus"),
                format!(
                    "a bin's subgrade modulus replaces a Winkler soil's k in a physical scene; this scene's soil is {}: remove the key",
                    model.groups.foundation().name()
                ),
            ));
        }
    }
    // σ_nl = −E α T_nl/(1 − ν), E/(1 − ν) = 12 D (1 + ν)/H³, in units of P/L².
    plan.stress_per_kelvin = match (&file.plate, model.physical) {
        (Some(p), Some(ph)) => p.thermal_expansion.map(|alpha| {
            let l = ph.half_length;
            -12.0 * ph.rigidity * (1.0 + p.poissons_ratio) / p.thickness.powi(3) * alpha * l * l
                / model.load_scale
        }),
        _ => None,
    };
    if plan.curvature_per_kelvin.is_none() && plan.climate.iter().any(|c| c.difference.is_finite())
    {
        return Err(Error::invalid(
            "plate.thermal_expansion",
            "missing: the climate bins give temperature differences; give the plate's coefficient of thermal expansion in 1/K (concrete ≈ 1.0e-5)",
        ));
    }
    // On a soil that cannot pull, a curled slab rests on it by its own weight: without a load
    // of its own (the traffic's are not there between passes) the slab at rest has no
    // equilibrium, and in every pass the curl would be held down by the axle alone.
    if *method != Method::Bonded {
        let curls =
            plan.climate.iter().any(|c| {
                (c.difference.is_finite() && c.difference != 0.0) || c.nonlinear != [0.0; 2]
            }) || model.thermal_curvature() != 0.0;
        let traffic = |i: usize| model.vehicles.iter().any(|v| v.loads.contains(&i));
        let own: f64 = (model.loads.iter().enumerate())
            .filter(|&(i, _)| !traffic(i))
            .map(|(_, l)| l.resultant())
            .sum();
        if curls && own <= 0.0 {
            let weight = match (&file.plate, model.physical.map(|p| p.units)) {
                // 150 lb/ft³ over H in: 150 H / 1728 psi (the file was converted to SI).
                (Some(p), Some(crate::units::UnitSystem::Us)) => format!(
                    "pressure = {:.2} psi for this {:.1} in slab at 150 lb/ft³",
                    p.thickness / 0.0254 * 150.0 / 1728.0,
                    p.thickness / 0.0254
                ),
                (Some(p), _) => format!(
                    "pressure = {:.0} Pa for this {:.3} m slab at 24 kN/m³",
                    p.thickness * 24.0e3,
                    p.thickness
                ),
                _ => "pressure = ρ g H".to_string(),
            };
            return Err(Error::invalid(
                "load",
                format!(
                    "the climate bins curl the slab, but no load of the scene's own holds it on a soil that cannot pull (the traffic's are there only during a pass): add its self-weight, [[load]] kind = \"uniform\", case = \"self-weight\", {weight}"
                ),
            ));
        }
    }
    Ok(Some(plan))
}
