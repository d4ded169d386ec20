//! Foundation operators: the compliance T (pressure → surface settlement, tested against
//! pressure shape functions) and the coupling B between plate deflections and pressures.
//!
//! The pressure σ is interpolated with the same bilinear functions f_i as the deflection, one
//! unknown per model node — per node copy on a jointed plate ([`crate::mesh::Topology`]), so
//! each side of a joint has its own pressure over its own tributary area, and every element loop
//! here reads the copies of its own side through [`Mesh::element_nodes`]. The discrete gap is
//! g = Tσ − Bᵀu and the plate feels the load −Bσ.

pub mod boussinesq;
pub mod elastic_layer;
pub mod fft;
pub mod halfspace;
pub mod kernel;
pub mod kerr;
pub mod layer;
pub mod pairs;
pub mod pasternak;
pub mod soil;
pub mod winkler;

use crate::mesh::{Dof, DofMap, Mesh};
use soil::{Key, KeyMap, PlateScale, SoilKeys, SoilModel, SoilNames};

/// The soils, one line each: the variant, the type in its own file that implements
/// [`SoilModel`], and its name in scene files and reports. Makes [`FoundationKind`] (the name
/// alone) and [`Soil`] (the value with its constants), and dispatches every question to the
/// soil's file: a new soil is its file and its line here.
macro_rules! soils {
    ($($v:ident($t:ty) => $name:literal, $doc:literal;)+) => {
        /// Which foundation model: the name alone ([`Soil`] is the value with its constants).
        #[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
        pub enum FoundationKind {
            $(
                #[doc = $doc]
                #[serde(rename = $name)]
                $v,
            )+
        }

        crate::choice::names!(FoundationKind, $($v => $name),+);

        /// A soil with its own constants as dimensionless groups (Γ beside it, in
        /// [`crate::model::Groups`]). Serialised as its constants alone (summary.json's
        /// `dimensionless`, flattened), its name written beside it as `foundation`.
        #[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
        #[serde(untagged)]
        pub enum Soil {
            $(
                #[doc = $doc]
                $v($t),
            )+
        }

        impl FoundationKind {
            /// True for the local (Winkler) soil, whose T is diagonal; every other soil is a
            /// non-local surface kernel with a dense (or FFT-applied) T.
            pub fn is_local(self) -> bool {
                match self { $(Self::$v => <$t as SoilModel>::LOCAL),+ }
            }

            /// The soil's names in the paper's outputs.
            pub fn names(self) -> SoilNames {
                match self { $(Self::$v => <$t as SoilModel>::NAMES),+ }
            }

            /// The keys the soil reads: of `[foundation]` (SI) or of `[dimensionless]`.
            pub fn keys(self, dimensionless: bool) -> &'static [Key] {
                match (self, dimensionless) {
                    $(
                        (Self::$v, false) => <$t as SoilModel>::SI_KEYS,
                        (Self::$v, true) => <$t as SoilModel>::GROUP_KEYS,
                    )+
                }
            }

            /// The plate's radius of relative stiffness on this soil in the unit system for the
            /// foundation constant `c` ([`SoilModel::stiffness_length`]).
            pub fn stiffness_length(self, c: f64) -> f64 {
                match self { $(Self::$v => <$t as SoilModel>::stiffness_length(c)),+ }
            }

            /// Elements per side of the stability study's mesh sweep on this soil.
            pub fn stability_meshes(self) -> Vec<f64> {
                match self { $(Self::$v => <$t as SoilModel>::stability_meshes()),+ }
            }

            /// The soil and its Γ from `[foundation]` (SI units), `keys` its own keys.
            pub fn from_si(self, keys: &KeyMap, plate: &PlateScale) -> crate::error::Result<(f64, Soil)> {
                let k = SoilKeys { section: "foundation", kind: self, keys };
                match self {
                    $(Self::$v => {
                        k.only(<$t as SoilModel>::SI_KEYS)?;
                        let (gamma, soil) = <$t as SoilModel>::from_si(&k, plate)?;
                        Ok((gamma, Soil::$v(soil)))
                    }),+
                }
            }

            /// The soil from `[dimensionless]`, `keys` its own keys, Γ = `gamma` checked.
            pub fn from_groups(self, keys: &KeyMap, plate: &PlateScale, gamma: f64) -> crate::error::Result<Soil> {
                let k = SoilKeys { section: "dimensionless", kind: self, keys };
                match self {
                    $(Self::$v => {
                        k.only(<$t as SoilModel>::GROUP_KEYS)?;
                        Ok(Soil::$v(<$t as SoilModel>::from_groups(&k, plate, gamma)?))
                    }),+
                }
            }
        }

        impl Soil {
            /// Its name.
            pub fn kind(&self) -> FoundationKind {
                match self { $(Soil::$v(_) => FoundationKind::$v),+ }
            }

            /// Its surface kernel in the unit system for Γ = `gamma`, aspect `mu` (None for a
            /// local soil).
            pub fn kernel(&self, gamma: f64, mu: f64) -> Option<kernel::Kernel> {
                match self { $(Soil::$v(s) => s.kernel(gamma, mu)),+ }
            }

            /// The mean settlement (units of V) under the unit resultant spread over the
            /// plate, constant `c` = μΓ ([`SoilModel::settlement`]).
            pub fn settlement(&self, c: f64, mu: f64) -> f64 {
                match self { $(Soil::$v(s) => s.settlement(c, mu)),+ }
            }

            /// What the solve table adds after Γ.
            pub fn describe(&self, gamma: f64, mu: f64) -> String {
                match self { $(Soil::$v(s) => s.describe(gamma, mu)),+ }
            }

            /// A length the soil derives for summary.json (the Pasternak decay length λ/L).
            pub fn decay_length(&self, gamma: f64, mu: f64) -> Option<f64> {
                match self { $(Soil::$v(s) => s.decay_length(gamma, mu)),+ }
            }
        }
    };
}

soils! {
    Winkler(winkler::Winkler) => "winkler",
        "Winkler subgrade: settlement = pressure / K at each point (paper eq. 2.8).";
    HalfSpace(halfspace::HalfSpace) => "half-space",
        "Homogeneous isotropic elastic half-space (Boussinesq kernel, paper eq. 2.6).";
    Pasternak(pasternak::Pasternak) => "pasternak",
        "Two-parameter (Pasternak) soil k u − G_p ∇²u = p on the whole plane: springs coupled by a shear layer.";
    ElasticLayer(elastic_layer::ElasticLayer) => "elastic-layer",
        "Homogeneous elastic layer of depth h on a rigid base (rough or smooth).";
    Kerr(kerr::Kerr) => "kerr",
        "Kerr's three-parameter soil: springs c (upper) in series with a Pasternak soil.";
}

/// The compliance operator T.
#[derive(Debug, Clone)]
pub enum Compliance {
    /// Winkler: T = (1/K) diag(∫ f_i).
    Diagonal(Vec<f64>),
    /// A non-local soil (half-space, Pasternak): T_ij = ⟨f_i, 𝒯 f_j⟩, dense symmetric positive
    /// definite.
    Dense(faer::Mat<f64>),
    /// A non-local soil, the same T never stored: block-Toeplitz products by FFT
    /// ([`fft::ToeplitzCompliance`]), for the iterative route.
    Toeplitz(Box<fft::ToeplitzCompliance>),
}

impl Compliance {
    /// y = T x.
    pub fn apply(&self, x: &[f64]) -> Vec<f64> {
        match self {
            Compliance::Diagonal(d) => d.iter().zip(x).map(|(a, b)| a * b).collect(),
            Compliance::Dense(t) => {
                let n = t.nrows();
                let mut y = vec![0.0; n];
                for (j, &xj) in x.iter().enumerate() {
                    if xj != 0.0 {
                        let col = t.col(j);
                        for (i, yi) in y.iter_mut().enumerate() {
                            *yi += col[i] * xj;
                        }
                    }
                }
                y
            }
            Compliance::Toeplitz(t) => t.apply(x),
        }
    }

    /// Size n_σ.
    pub fn len(&self) -> usize {
        match self {
            Compliance::Diagonal(d) => d.len(),
            Compliance::Dense(t) => t.nrows(),
            Compliance::Toeplitz(t) => t.len(),
        }
    }

    /// The diagonal of T.
    pub fn diagonal(&self) -> Vec<f64> {
        match self {
            Compliance::Diagonal(d) => d.clone(),
            Compliance::Dense(t) => (0..t.nrows()).map(|i| t[(i, i)]).collect(),
            Compliance::Toeplitz(t) => t.diag().to_vec(),
        }
    }

    /// T as a dense matrix: a copy of the dense T, the diagonal spread out, or the Toeplitz
    /// operator assembled densely (n_σ² doubles: check the memory budget first).
    pub fn to_dense(&self) -> faer::Mat<f64> {
        match self {
            Compliance::Dense(t) => t.clone(),
            Compliance::Diagonal(d) => {
                let n = d.len();
                let mut m = faer::Mat::<f64>::zeros(n, n);
                for (i, &v) in d.iter().enumerate() {
                    m[(i, i)] = v;
                }
                m
            }
            Compliance::Toeplitz(t) => t.dense(),
        }
    }

    /// True when T is stored as a dense matrix.
    pub fn is_dense(&self) -> bool {
        matches!(self, Compliance::Dense(_))
    }

    /// True when there are no pressure unknowns.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// ∫ f_i dA over the model for every node (the lumped, row-sum mass).
pub fn nodal_areas(mesh: &Mesh) -> Vec<f64> {
    let mut m = vec![0.0; mesh.n_nodes()];
    let quarter = 0.25 * mesh.element_area();
    for e in mesh.elements() {
        for n in mesh.element_nodes(e) {
            m[n] += quarter;
        }
    }
    m
}

/// Consistent bilinear mass matrix of one hx × hy rectangle: ∫ N_a N_b dA.
pub fn element_mass(hx: f64, hy: f64) -> [[f64; 4]; 4] {
    let c = hx * hy / 36.0;
    let pattern = [
        [4.0, 2.0, 1.0, 2.0],
        [2.0, 4.0, 2.0, 1.0],
        [1.0, 2.0, 4.0, 2.0],
        [2.0, 1.0, 2.0, 4.0],
    ];
    let mut m = [[0.0; 4]; 4];
    for a in 0..4 {
        for b in 0..4 {
            m[a][b] = c * pattern[a][b];
        }
    }
    m
}

/// Coupling B (n_eq × n_σ): B[w_i, j] = ∫ f_i f_j dA, consistent or lumped (row sums).
pub fn coupling(mesh: &Mesh, dofs: &DofMap, lumped: bool) -> sprs::CsMat<f64> {
    let n_sigma = mesh.n_nodes();
    let mut tri = sprs::TriMat::new((dofs.n_eq(), n_sigma));
    if lumped {
        for (j, a) in nodal_areas(mesh).into_iter().enumerate() {
            if let Some(r) = dofs.eq(j, Dof::W) {
                tri.add_triplet(r, j, a);
            }
        }
    } else {
        let me = element_mass(mesh.hx, mesh.hy);
        for e in mesh.elements() {
            let nodes = mesh.element_nodes(e);
            for (a, &na) in nodes.iter().enumerate() {
                let Some(r) = dofs.eq(na, Dof::W) else {
                    continue;
                };
                for (b, &nb) in nodes.iter().enumerate() {
                    tri.add_triplet(r, nb, me[a][b]);
                }
            }
        }
    }
    tri.to_csc()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nodal_areas_sum_to_model_area() {
        let m = Mesh::new(2.0, 1.0, [6, 4], true, false);
        let total: f64 = nodal_areas(&m).iter().sum();
        assert!(
            (total - 1.0).abs() < 1e-14,
            "half of a 2 × 1 plate has area 1, got {total}"
        );
    }

    #[test]
    fn consistent_and_lumped_coupling_have_equal_row_sums() {
        let m = Mesh::new(2.0, 2.0, [4, 4], false, false);
        let d = DofMap::new(&m);
        let bc = coupling(&m, &d, false);
        let bl = coupling(&m, &d, true);
        let ones = vec![1.0; m.n_nodes()];
        let rc = &bc * &sprs::CsVec::new(ones.len(), (0..ones.len()).collect(), ones.clone());
        let rl = &bl * &sprs::CsVec::new(ones.len(), (0..ones.len()).collect(), ones);
        for (i, v) in rc.iter() {
            let l = rl.get(i).copied().unwrap_or(0.0);
            assert!(
                (v - l).abs() < 1e-14,
                "row {i}: consistent {v} vs lumped {l}"
            );
        }
    }
}
