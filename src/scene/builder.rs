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
                title: None,
                plate: None,
                foundation: None,
                dimensionless: None,
                load: Vec::new(),
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
        });
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
            kind,
            x,
            y,
            force,
            pressure,
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

    /// Validate into a model.
    pub fn build(&self) -> Result<Model> {
        validate::model(&self.file)
    }
}
