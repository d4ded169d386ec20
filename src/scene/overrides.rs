//! Options that override a scene file's `[solver]` and `[mesh]` settings: one struct for every
//! front end (the command line's flags, the Python keyword arguments), so that an option is
//! added in one place. Each field is named as its flag (`qp_form` ↔ `--qp-form`) and parses
//! from the same words as the scene key it overrides.

use serde::Deserialize;

use crate::error::{Error, Result};
use crate::method::{Contact, MethodKind, QpForm, QpSolver, Route, Start};
use crate::model::{ConstraintPoints, SymmetryMode};
use crate::scene::spec::{PenaltySpec, SceneFile};

/// Every option, by the name a front end gives it (`qp_form`; the command line's `--qp-form`),
/// with the scene key it overrides: the one list that the command line's flags and the Python
/// keyword arguments are checked against (tests fail when they drift), and that error
/// messages list.
pub const OPTIONS: &[(&str, &str)] = &[
    ("contact", "solver.contact"),
    ("method", "solver.method"),
    ("penalty", "solver.penalty"),
    ("constraint", "solver.constraint"),
    ("mesh", "mesh.elements"),
    ("qp_form", "solver.qp_form"),
    ("qp_solver", "solver.qp_solver"),
    ("solver", "solver.route"),
    ("symmetry", "mesh.symmetry"),
    ("start", "solver.start"),
];

/// Overrides of a scene's settings; `None` keeps the scene's value. One field per entry of
/// [`OPTIONS`].
#[derive(Debug, Clone, Default, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Overrides {
    /// `[solver] contact`.
    pub contact: Option<Contact>,
    /// `[solver] method`.
    pub method: Option<MethodKind>,
    /// `[solver] penalty`: `"auto"` or a fixed ε̄.
    pub penalty: Option<PenaltySpec>,
    /// `[solver] constraint`.
    pub constraint: Option<ConstraintPoints>,
    /// `[mesh] elements` over the whole plate, [nx, ny].
    pub mesh: Option<[i64; 2]>,
    /// `[solver] qp_form`.
    pub qp_form: Option<QpForm>,
    /// `[solver] qp_solver`.
    pub qp_solver: Option<QpSolver>,
    /// `[solver] route` (the command line's `--solver`).
    #[serde(alias = "route")]
    pub solver: Option<Route>,
    /// `[mesh] symmetry`.
    pub symmetry: Option<SymmetryMode>,
    /// `[solver] start`.
    pub start: Option<Start>,
}

impl Overrides {
    /// Parse overrides from JSON (an object whose keys are the field names); an unknown key or
    /// value is an [`Error::Invalid`] naming it.
    pub fn from_json(text: &str) -> Result<Self> {
        serde_json::from_str(text).map_err(|e| {
            let names: Vec<&str> = OPTIONS.iter().map(|o| o.0).collect();
            Error::invalid("options", format!("{e} (options: {})", names.join(", ")))
        })
    }

    /// Write the overrides into a parsed scene (before validation, which checks the values).
    pub fn apply(&self, file: &mut SceneFile) {
        if let Some(c) = self.contact {
            file.solver.contact = c;
        }
        if let Some(m) = self.method {
            file.solver.method = m;
        }
        if let Some(p) = self.penalty.clone() {
            file.solver.penalty = p;
        }
        if let Some(c) = self.constraint {
            file.solver.constraint = c;
        }
        if let Some(m) = self.mesh {
            file.mesh.elements = m.to_vec();
        }
        if let Some(f) = self.qp_form {
            file.solver.qp_form = f;
        }
        if let Some(q) = self.qp_solver {
            file.solver.qp_solver = q;
        }
        if let Some(r) = self.solver {
            file.solver.route = r;
        }
        if let Some(s) = self.symmetry {
            file.mesh.symmetry = s;
        }
        if let Some(s) = self.start {
            file.solver.start = s;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SCENE: &str = "[dimensionless]\nfoundation = \"winkler\"\ngamma = 1e-3\ndelta = 0.003\nmu = 1.0\nnu = 0.3\n[[load]]\nkind = \"point\"\nx = 0.0\ny = 0.0\nforce = 1.0\n";

    #[test]
    fn json_overrides_reach_every_setting() {
        let o = Overrides::from_json(
            r#"{"contact": "bonded", "method": "qp", "penalty": 1e-6, "constraint": "gauss",
                "mesh": [8, 6], "qp_form": "lifted", "qp_solver": "active-set", "solver": "iterative",
                "symmetry": "none"}"#,
        )
        .unwrap();
        let mut file = SceneFile::parse(SCENE).unwrap();
        o.apply(&mut file);
        assert_eq!(file.solver.contact, Contact::Bonded, "contact");
        assert_eq!(file.solver.method, MethodKind::Qp, "method");
        assert_eq!(file.solver.penalty, PenaltySpec::Value(1e-6), "penalty");
        assert_eq!(
            file.solver.constraint,
            ConstraintPoints::Gauss,
            "constraint"
        );
        assert_eq!(file.mesh.elements, vec![8, 6], "mesh");
        assert_eq!(file.solver.qp_form, QpForm::Lifted, "qp_form");
        assert_eq!(file.solver.qp_solver, QpSolver::ActiveSet, "qp_solver");
        assert_eq!(file.solver.route, Route::Iterative, "solver");
        assert_eq!(file.mesh.symmetry, SymmetryMode::None, "symmetry");
    }

    /// Every field of `Overrides` is in `OPTIONS` and the other way round: the JSON of a full
    /// set of overrides has exactly the listed keys.
    #[test]
    fn the_options_list_is_the_struct() {
        let full = Overrides {
            contact: Some(Contact::Bonded),
            method: Some(MethodKind::Qp),
            penalty: Some(PenaltySpec::Value(1e-6)),
            constraint: Some(ConstraintPoints::Gauss),
            mesh: Some([8, 6]),
            qp_form: Some(QpForm::Lifted),
            qp_solver: Some(QpSolver::ActiveSet),
            solver: Some(Route::Iterative),
            symmetry: Some(SymmetryMode::None),
            start: Some(Start::Cold),
        };
        let mut keys: Vec<String> = match serde_json::to_value(&full) {
            Ok(serde_json::Value::Object(m)) => m.keys().cloned().collect(),
            other => panic!("Overrides serialises to an object, got {other:?}"),
        };
        keys.sort();
        let mut listed: Vec<String> = OPTIONS.iter().map(|o| o.0.to_string()).collect();
        listed.sort();
        assert_eq!(keys, listed, "Overrides fields against OPTIONS");
    }

    #[test]
    fn empty_overrides_keep_the_scene() {
        let mut file = SceneFile::parse(SCENE).unwrap();
        let before = format!("{:?}", file.solver);
        Overrides::from_json("{}").unwrap().apply(&mut file);
        assert_eq!(format!("{:?}", file.solver), before);
    }

    #[test]
    fn unknown_options_and_values_are_invalid() {
        for bad in [
            r#"{"methd": "qp"}"#,
            r#"{"method": "simplex"}"#,
            r#"{"mesh": [8]}"#,
        ] {
            match Overrides::from_json(bad) {
                Err(Error::Invalid { field, .. }) => assert_eq!(field, "options", "{bad}"),
                other => panic!("{bad}: expected Invalid, got {other:?}"),
            }
        }
    }
}
