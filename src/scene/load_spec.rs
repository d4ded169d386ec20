//! The `[[load]]` entries of a scene file: their serde types, the keys each kind takes, and an
//! empty entry to build from (re-exported by [`super::spec`]).

use serde::Deserialize;

/// A coordinate: a number (point loads) or a range [lo, hi] (patch loads).
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(untagged)]
pub enum Coord {
    /// A single value.
    Value(f64),
    /// A closed interval.
    Range([f64; 2]),
}

impl Coord {
    /// The single value (None for a range).
    pub fn value(&self) -> Option<f64> {
        match self {
            Coord::Value(v) => Some(*v),
            Coord::Range(_) => None,
        }
    }
}

/// Kind of a load entry.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum LoadKind {
    /// Concentrated force at (x, y).
    Point,
    /// Uniform pressure over the rectangle x = [x0, x1], y = [y0, y1].
    Patch,
    /// Uniform pressure over the whole plate (self-weight, surcharge).
    Uniform,
    /// Force per unit length along the segment `from` → `to` (a wall, a line of columns).
    Line,
    /// A temperature difference, top minus bottom, linear through the thickness.
    Temperature,
    /// Temperatures at depths through the thickness (SI scenes): the equivalent linear gradient
    /// curls the plate, the self-equilibrating rest adds to the surface stresses.
    TemperatureProfile,
    /// Drying shrinkage of the top layer as an equivalent temperature difference (SI scenes).
    Moisture,
    /// A permanent equivalent temperature difference from construction (built-in curl), K.
    BuiltInCurl,
    /// A truck axle group (single, tandem, tridem) of single or dual tires, each tire a
    /// rectangle of its contact area (SI scenes).
    Axle,
    /// An aircraft gear: wheels at given positions, each with its load (SI scenes).
    Gear,
    /// Uniform pressure on a disk of `radius` centred at (x, y): a falling-weight
    /// deflectometer's load plate, a round footing.
    Circle,
}

crate::choice::names!(LoadKind, Point => "point", Patch => "patch", Uniform => "uniform", Line => "line",
    Temperature => "temperature", TemperatureProfile => "temperature-profile",
    Moisture => "moisture", BuiltInCurl => "built-in-curl", Axle => "axle", Gear => "gear", Circle => "circle");

impl LoadKind {
    /// The keys a load of this kind takes besides `kind`, `case` and `name`.
    pub fn keys(self) -> &'static [&'static str] {
        match self {
            LoadKind::Point => &["x", "y", "force"],
            LoadKind::Patch => &["x", "y", "pressure"],
            LoadKind::Circle => &["x", "y", "radius", "force", "pressure"],
            LoadKind::Uniform => &["pressure"],
            LoadKind::Line => &["from", "to", "force_per_length"],
            LoadKind::Temperature => &["difference", "curvature"],
            LoadKind::TemperatureProfile => &["depths", "temperatures", "interpolation"],
            LoadKind::Moisture => &["shrinkage", "depth"],
            LoadKind::BuiltInCurl => &["difference"],
            LoadKind::Axle => &[
                "standard",
                "configuration",
                "axle_load",
                "axle_spacing",
                "track",
                "tires",
                "dual_spacing",
                "tire_pressure",
                "x",
                "y",
                "heading",
                "contact_shape",
            ],
            LoadKind::Gear => &[
                "standard",
                "wheels",
                "wheel_load",
                "tire_pressure",
                "x",
                "y",
                "heading",
                "contact_shape",
            ],
        }
    }
}

/// One `[[load]]` entry.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LoadSpec {
    /// point | patch | uniform.
    pub kind: LoadKind,
    /// x (point) or [x0, x1] (patch); m, or s in a dimensionless scene.
    #[serde(default)]
    pub x: Option<Coord>,
    /// y (point) or [y0, y1] (patch); m, or t in a dimensionless scene.
    #[serde(default)]
    pub y: Option<Coord>,
    /// Point force, N downward (relative in a dimensionless scene).
    #[serde(default)]
    pub force: Option<f64>,
    /// Pressure, Pa downward (relative in a dimensionless scene).
    #[serde(default)]
    pub pressure: Option<f64>,
    /// Start of a line load: m, or (s, t) in a dimensionless scene.
    #[serde(default)]
    pub from: Option<[f64; 2]>,
    /// End of a line load.
    #[serde(default)]
    pub to: Option<[f64; 2]>,
    /// Line load, N/m downward (relative per unit L in a dimensionless scene).
    #[serde(default)]
    pub force_per_length: Option<f64>,
    /// Temperature difference top minus bottom, K (SI scenes).
    #[serde(default)]
    pub difference: Option<f64>,
    /// Free curling curvature ∂²V/∂s² times the loads' force unit (dimensionless scenes).
    #[serde(default)]
    pub curvature: Option<f64>,
    /// Load case; loads without one belong to case "default".
    #[serde(default)]
    pub case: Option<String>,
    /// A name for the load (`liftoff critical SCENE --load NAME` moves it).
    #[serde(default)]
    pub name: Option<String>,
    /// Temperature profile: depths from the top surface, m, increasing from 0 to the thickness.
    #[serde(default)]
    pub depths: Option<Vec<f64>>,
    /// Temperature profile: the temperatures at `depths`, °C (or K).
    #[serde(default)]
    pub temperatures: Option<Vec<f64>>,
    /// Temperature profile between the depths: "linear" (default) or "quadratic" (three
    /// values at the top, the middle and the bottom).
    #[serde(default)]
    pub interpolation: Option<String>,
    /// Moisture: the shrinkage strain at the top surface (negative: shrinking), falling linearly
    /// to zero at `depth`.
    #[serde(default)]
    pub shrinkage: Option<f64>,
    /// Moisture: the depth of the drying layer, m.
    #[serde(default)]
    pub depth: Option<f64>,
    /// Axle or gear: a bundled configuration (`liftoff example` lists none; see README,
    /// "Vehicle loads"); the keys given beside it override its values.
    #[serde(default)]
    pub standard: Option<String>,
    /// Axle: "single", "tandem" or "tridem".
    #[serde(default)]
    pub configuration: Option<String>,
    /// Axle: the load of one axle, N.
    #[serde(default)]
    pub axle_load: Option<f64>,
    /// Axle: distance between the axles of a tandem or tridem, m.
    #[serde(default)]
    pub axle_spacing: Option<f64>,
    /// Axle: distance between the centres of the two wheel sets of an axle, m.
    #[serde(default)]
    pub track: Option<f64>,
    /// Axle: "single" or "dual" tires at each end.
    #[serde(default)]
    pub tires: Option<String>,
    /// Axle: centre-to-centre distance of the two tires of a dual set, m.
    #[serde(default)]
    pub dual_spacing: Option<f64>,
    /// Axle or gear: tire pressure, Pa; a tire's contact area is its load over it.
    #[serde(default)]
    pub tire_pressure: Option<f64>,
    /// Gear: wheel positions [along, across] relative to the reference point, m.
    #[serde(default)]
    pub wheels: Option<Vec<[f64; 2]>>,
    /// Gear: the load of one wheel, N.
    #[serde(default)]
    pub wheel_load: Option<f64>,
    /// Axle or gear: direction of travel, degrees from the x axis (default 0).
    #[serde(default)]
    pub heading: Option<f64>,
    /// Axle or gear: a tire's contact print, "pca" (default: a 0.8712 L × 0.6 L rectangle of the
    /// contact area, long along the travel) or "square".
    #[serde(default)]
    pub contact_shape: Option<String>,
    /// Circle: the disk's radius, m (s in a dimensionless scene).
    #[serde(default)]
    pub radius: Option<f64>,
}

impl LoadSpec {
    /// A load of `kind` with no key set.
    pub fn new(kind: LoadKind) -> Self {
        LoadSpec {
            kind,
            x: None,
            y: None,
            force: None,
            pressure: None,
            from: None,
            to: None,
            force_per_length: None,
            difference: None,
            curvature: None,
            case: None,
            name: None,
            depths: None,
            temperatures: None,
            interpolation: None,
            shrinkage: None,
            depth: None,
            standard: None,
            configuration: None,
            axle_load: None,
            axle_spacing: None,
            track: None,
            tires: None,
            dual_spacing: None,
            tire_pressure: None,
            wheels: None,
            wheel_load: None,
            heading: None,
            contact_shape: None,
            radius: None,
        }
    }

    /// The first key present that this kind does not take — of the keys the five first kinds
    /// do not know (those kinds check their own keys in their own order, as they always did).
    pub fn foreign_key(&self) -> Option<&'static str> {
        const OLD_KEYS: [&str; 11] = [
            "x",
            "y",
            "force",
            "pressure",
            "from",
            "to",
            "force_per_length",
            "difference",
            "curvature",
            "case",
            "name",
        ];
        let old_kind = matches!(
            self.kind,
            LoadKind::Point
                | LoadKind::Patch
                | LoadKind::Uniform
                | LoadKind::Line
                | LoadKind::Temperature
        );
        self.present().into_iter().find(|key| {
            let own = self.kind.keys().contains(key) || matches!(*key, "case" | "name");
            !own && (!old_kind || !OLD_KEYS.contains(key))
        })
    }

    /// The keys present beside `kind`, by name: what a kind's validation checks against its
    /// own list, so that a key of another kind is refused by name.
    pub fn present(&self) -> Vec<&'static str> {
        let keys: [(&'static str, bool); 29] = [
            ("x", self.x.is_some()),
            ("y", self.y.is_some()),
            ("force", self.force.is_some()),
            ("pressure", self.pressure.is_some()),
            ("from", self.from.is_some()),
            ("to", self.to.is_some()),
            ("force_per_length", self.force_per_length.is_some()),
            ("difference", self.difference.is_some()),
            ("curvature", self.curvature.is_some()),
            ("case", self.case.is_some()),
            ("name", self.name.is_some()),
            ("depths", self.depths.is_some()),
            ("temperatures", self.temperatures.is_some()),
            ("interpolation", self.interpolation.is_some()),
            ("shrinkage", self.shrinkage.is_some()),
            ("depth", self.depth.is_some()),
            ("standard", self.standard.is_some()),
            ("configuration", self.configuration.is_some()),
            ("axle_load", self.axle_load.is_some()),
            ("axle_spacing", self.axle_spacing.is_some()),
            ("track", self.track.is_some()),
            ("tires", self.tires.is_some()),
            ("dual_spacing", self.dual_spacing.is_some()),
            ("tire_pressure", self.tire_pressure.is_some()),
            ("wheels", self.wheels.is_some()),
            ("wheel_load", self.wheel_load.is_some()),
            ("heading", self.heading.is_some()),
            ("contact_shape", self.contact_shape.is_some()),
            ("radius", self.radius.is_some()),
        ];
        keys.iter().filter(|k| k.1).map(|k| k.0).collect()
    }
}
