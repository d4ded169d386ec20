//! [`Model::builder`]: a model from Rust, through the same validation as a scene file.
//!
//! ```
//! use liftoff::foundation::FoundationKind;
//! use liftoff::model::Model;
//!
//! // The paper's square plate on a half-space, central point load, 16 × 16 elements.
//! let model = Model::builder()
//!     .dimensionless(FoundationKind::HalfSpace, 0.25e-3, 0.002857, 1.0, 0.3)
//!     .point_load(0.0, 0.0, 1.0)
//!     .elements(16, 16)
//!     .build()
//!     .unwrap();
//! assert_eq!(model.elements, [16, 16]);
//! ```

use super::spec::{
    Coord, DimensionlessSpec, FoundationSpec, LoadKind, LoadSpec, MeshSpec, PlateSpec, SceneFile,
    SolverSpec,
};
use super::validate;
use crate::error::Result;
use crate::foundation::FoundationKind;
use crate::model::{ConstraintPoints, Model, SymmetryMode};

/// Builds a [`Model`] step by step; [`ModelBuilder::build`] validates it exactly as a scene
/// file is validated (coordinates in m for SI scenes, in (s, t) for dimensionless ones).
#[derive(Debug, Clone)]
pub struct ModelBuilder {
    file: SceneFile,
}

impl Model {
    /// Start building a model (see [`ModelBuilder`]).
    pub fn builder() -> ModelBuilder {
        ModelBuilder {
            file: SceneFile {
                units: crate::units::UnitSystem::Si,
                title: None,
                plate: None,
                foundation: None,
                dimensionless: None,
                load: Vec::new(),
                combination: Vec::new(),
                void: Vec::new(),
                opening: Vec::new(),
                joint: Vec::new(),
                panel: Vec::new(),
                traffic: None,
                climate: None,
                damage: None,
                mesh: MeshSpec::default(),
                solver: SolverSpec::default(),
            },
        }
    }
}

impl ModelBuilder {
    /// Title for reports.
    pub fn title(mut self, title: impl Into<String>) -> Self {
        self.file.title = Some(title.into());
        self
    }

    /// The plate in SI units (give [`ModelBuilder::foundation`] too).
    pub fn plate(mut self, plate: PlateSpec) -> Self {
        self.file.plate = Some(plate);
        self
    }

    /// The foundation in SI units.
    pub fn foundation(mut self, foundation: FoundationSpec) -> Self {
        self.file.foundation = Some(foundation);
        self
    }

    /// The paper's groups (eq. 4.1) instead of a plate and foundation in SI units.
    pub fn dimensionless(
        mut self,
        foundation: FoundationKind,
        gamma: f64,
        delta: f64,
        mu: f64,
        nu: f64,
    ) -> Self {
        self.file.dimensionless = Some(DimensionlessSpec {
            foundation,
            gamma,
            delta,
            mu,
            nu,
            allowable_pressure: None,
            bearing_length: None,
            zone: Vec::new(),
            outline: None,
            soil: Default::default(),
        });
        self
    }

    /// One of the soil's own keys, as a scene file would give it: in `[dimensionless]` (a group,
    /// e.g. Kerr's `upper`) after [`Self::dimensionless`], or in `[foundation]` (SI) after
    /// [`Self::foundation`]. The soil reads and checks it when the model is built, so any soil's
    /// keys reach it without a method of their own here.
    pub fn soil_key(
        mut self,
        key: &str,
        value: impl Into<crate::foundation::soil::KeyValue>,
    ) -> Self {
        let value = value.into();
        if let Some(d) = self.file.dimensionless.as_mut() {
            d.soil.insert(key.to_string(), value);
        } else if let Some(f) = self.file.foundation.as_mut() {
            f.soil.insert(key.to_string(), value);
        }
        self
    }

    /// The Pasternak shear parameter Γ_g = G_p L²/D of a dimensionless scene (after
    /// [`Self::dimensionless`] with `FoundationKind::Pasternak`).
    pub fn shear(mut self, shear: f64) -> Self {
        if let Some(d) = self.file.dimensionless.as_mut() {
            d.soil.insert("shear".into(), shear.into());
        }
        self
    }

    /// The elastic layer's depth ratio h/L and Poisson's ratio ν_s of a dimensionless scene
    /// (after [`Self::dimensionless`] with `FoundationKind::ElasticLayer`).
    pub fn layer(mut self, depth: f64, soil_nu: f64) -> Self {
        if let Some(d) = self.file.dimensionless.as_mut() {
            d.soil.insert("depth".into(), depth.into());
            d.soil.insert("soil_nu".into(), soil_nu.into());
        }
        self
    }

    /// The elastic layer's rigid base of a dimensionless scene, rough (the default) or smooth
    /// (after [`Self::layer`]).
    pub fn base(mut self, base: crate::foundation::layer::Base) -> Self {
        if let Some(d) = self.file.dimensionless.as_mut() {
            d.soil.insert("base".into(), base.name().into());
        }
        self
    }

    fn load(
        mut self,
        kind: LoadKind,
        x: Option<Coord>,
        y: Option<Coord>,
        force: Option<f64>,
        pressure: Option<f64>,
    ) -> Self {
        self.file.load.push(LoadSpec {
            x,
            y,
            force,
            pressure,
            ..LoadSpec::new(kind)
        });
        self
    }

    /// Put the load added last into a load case (loads are in case "default" otherwise).
    pub fn in_case(mut self, case: impl Into<String>) -> Self {
        if let Some(l) = self.file.load.last_mut() {
            l.case = Some(case.into());
        }
        self
    }

    /// A downward force per length along the segment `from` → `to` (N/m in SI scenes).
    pub fn line_load(mut self, from: [f64; 2], to: [f64; 2], force_per_length: f64) -> Self {
        self = self.load(LoadKind::Line, None, None, None, None);
        if let Some(l) = self.file.load.last_mut() {
            l.from = Some(from);
            l.to = Some(to);
            l.force_per_length = Some(force_per_length);
        }
        self
    }

    /// A temperature difference top minus bottom, K (SI scenes; the plate needs
    /// `thermal_expansion`).
    pub fn temperature_load(mut self, difference: f64) -> Self {
        self = self.load(LoadKind::Temperature, None, None, None, None);
        if let Some(l) = self.file.load.last_mut() {
            l.difference = Some(difference);
        }
        self
    }

    /// A free curling curvature ∂²V/∂s² in the loads' unit (dimensionless scenes).
    pub fn curling(mut self, curvature: f64) -> Self {
        self = self.load(LoadKind::Temperature, None, None, None, None);
        if let Some(l) = self.file.load.last_mut() {
            l.curvature = Some(curvature);
        }
        self
    }

    /// A void of `depth` over x ∈ [x0, x1], y ∈ [y0, y1].
    pub fn void(mut self, x: [f64; 2], y: [f64; 2], depth: f64) -> Self {
        self.file.void.push(super::VoidSpec { x, y, depth });
        self
    }

    /// A Winkler zone of another modulus (N/m³ in SI scenes; Γ_w in dimensionless ones) over
    /// x ∈ [x0, x1], y ∈ [y0, y1]. Give the foundation (or the groups) first.
    pub fn zone(mut self, x: [f64; 2], y: [f64; 2], value: f64) -> Self {
        if let Some(f) = self.file.foundation.as_mut() {
            f.zone.push(super::ZoneSpec {
                x,
                y,
                modulus: Some(value),
                gamma: None,
            });
        } else if let Some(d) = self.file.dimensionless.as_mut() {
            d.zone.push(super::ZoneSpec {
                x,
                y,
                modulus: None,
                gamma: Some(value),
            });
        }
        self
    }

    /// The pressure the soil may take (Pa in SI scenes): the bearing check. Give the
    /// foundation (or the groups) first.
    pub fn allowable_pressure(mut self, p: f64) -> Self {
        if let Some(f) = self.file.foundation.as_mut() {
            f.allowable_pressure = Some(p);
        } else if let Some(d) = self.file.dimensionless.as_mut() {
            d.allowable_pressure = Some(p);
        }
        self
    }

    /// The side of the square over which the bearing check averages the contact pressure (m
    /// in SI scenes, units of L in dimensionless ones; default the plate's thickness). Give
    /// the foundation (or the groups) first.
    pub fn bearing_length(mut self, a: f64) -> Self {
        if let Some(f) = self.file.foundation.as_mut() {
            f.bearing_length = Some(a);
        } else if let Some(d) = self.file.dimensionless.as_mut() {
            d.bearing_length = Some(a);
        }
        self
    }

    /// A joint line across the plate ([`super::JointSpec`]: `x` or `y` in m for SI scenes, s or
    /// t for dimensionless ones; its kind and constants).
    pub fn joint(mut self, joint: super::JointSpec) -> Self {
        self.file.joint.push(joint);
        self
    }

    /// A panel with its own thickness or Young's modulus ([`super::PanelSpec`]).
    pub fn panel(mut self, panel: super::PanelSpec) -> Self {
        self.file.panel.push(panel);
        self
    }

    /// Contact law and method for [`Self::build_problem`] (default: unbonded, penalty).
    pub fn solver(
        mut self,
        contact: crate::method::Contact,
        method: crate::method::MethodKind,
    ) -> Self {
        self.file.solver.contact = contact;
        self.file.solver.method = method;
        self
    }

    /// Validate into a whole problem (model, combinations, method, memory limit).
    pub fn build_problem(&self) -> Result<super::Problem> {
        validate::problem(&self.file)
    }

    /// A combination of load cases with factors.
    pub fn combination(mut self, name: impl Into<String>, factors: &[(&str, f64)]) -> Self {
        self.file.combination.push(super::CombinationSpec {
            name: name.into(),
            factors: factors.iter().map(|&(c, f)| (c.to_string(), f)).collect(),
        });
        self
    }

    /// A downward point force at (x, y).
    pub fn point_load(self, x: f64, y: f64, force: f64) -> Self {
        self.load(
            LoadKind::Point,
            Some(Coord::Value(x)),
            Some(Coord::Value(y)),
            Some(force),
            None,
        )
    }

    /// A downward uniform pressure on the rectangle x ∈ [x0, x1], y ∈ [y0, y1].
    pub fn patch_load(self, x: [f64; 2], y: [f64; 2], pressure: f64) -> Self {
        self.load(
            LoadKind::Patch,
            Some(Coord::Range(x)),
            Some(Coord::Range(y)),
            None,
            Some(pressure),
        )
    }

    /// A downward uniform pressure on the whole plate.
    pub fn uniform_load(self, pressure: f64) -> Self {
        self.load(LoadKind::Uniform, None, None, None, Some(pressure))
    }

    /// Elements over the whole plate.
    pub fn elements(mut self, nx: usize, ny: usize) -> Self {
        let count = |n: usize| i64::try_from(n).unwrap_or(i64::MAX);
        self.file.mesh.elements = vec![count(nx), count(ny)];
        self
    }

    /// Symmetry reduction (default: auto).
    pub fn symmetry(mut self, mode: SymmetryMode) -> Self {
        self.file.mesh.symmetry = mode;
        self
    }

    /// Where σ ≥ 0 is imposed (default: nodal).
    pub fn constraint(mut self, points: ConstraintPoints) -> Self {
        self.file.solver.constraint = points;
        self
    }

    /// Validate into a model (all loads together).
    pub fn build(&self) -> Result<Model> {
        validate::model(&self.file)
    }

    /// Validate the combinations into their models (empty without combinations).
    pub fn build_combinations(&self) -> Result<Vec<super::Combination>> {
        validate::combinations(&self.file)
    }
}
