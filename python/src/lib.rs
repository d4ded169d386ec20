//! `liftoff._liftoff`: the compiled core of the Python package. Every function converts its
//! arguments, releases the GIL around the library call and converts the result back: scenes
//! arrive as (kind, text) pairs, options as JSON (parsed by the library's
//! [`liftoff::scene::Overrides`]), results leave as JSON (the library's own serialisation, the
//! CLI's `--json`) and nodal fields as little-endian f64 bytes that NumPy reads without a copy.
//! No mechanics lives here; the public API (signatures, docstrings, stubs) is the pure-Python
//! layer in `python/liftoff/`.

use liftoff::scene::{Overrides, Problem, SceneFile};
use liftoff::study::{stability_plan, stability_run, EpsSweepOptions, TradeoffOptions};
use liftoff::Error;
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict};

/// Run a library call with the GIL released; a panic inside it (a bug) becomes a library
/// error raised as `liftoff.NumericalError`, never a `PanicException` that `except Exception`
/// would not catch.
fn run<T: Send>(py: Python<'_>, f: impl FnOnce() -> liftoff::Result<T> + Send) -> PyResult<T> {
    py.detach(|| {
        std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).unwrap_or_else(|panic| {
            let what = panic
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            Err(Error::numerical(
                "liftoff (internal error, please report the scene)",
                what,
            ))
        })
    })
    .map_err(to_py)
}

/// A library error as the matching `liftoff.errors` exception (its class from the error's
/// kind), carrying the message and, for a scene value, the field it names.
fn to_py(e: Error) -> PyErr {
    let class = match e.kind() {
        "invalid" => "SceneError",
        "too-large" => "TooLarge",
        "infeasible" => "Infeasible",
        "numerical" => "NumericalError",
        "io" => "LiftoffIOError",
        _ => "LiftoffError",
    };
    let field = match &e {
        Error::Invalid { field, .. } => Some(field.clone()),
        _ => None,
    };
    let kind = e.kind().to_string();
    Python::attach(|py| {
        let raised = py
            .import("liftoff.errors")
            .and_then(|m| m.getattr(class))
            .and_then(|cls| cls.call1((e.to_string(), kind, field)));
        match raised {
            Ok(obj) => PyErr::from_value(obj),
            Err(import_failed) => import_failed,
        }
    })
}

fn json<T: serde::Serialize>(value: &T) -> PyResult<String> {
    serde_json::to_string(value).map_err(|e| PyRuntimeError::new_err(e.to_string()))
}

/// The scene file of a (kind, text) pair: "toml" text, "json" text (a dict's), or "example"
/// (a bundled scene's name).
fn scene_file(kind: &str, text: &str) -> liftoff::Result<SceneFile> {
    match kind {
        "example" => SceneFile::example(text),
        "json" => SceneFile::from_json(text),
        _ => SceneFile::parse(text),
    }
}

/// Parse, apply the options (JSON object), validate.
fn problem(kind: &str, text: &str, options: &str) -> liftoff::Result<Problem> {
    let mut file = scene_file(kind, text)?;
    Overrides::from_json(options)?.apply(&mut file);
    file.validate()
}

/// Names and one-line descriptions of the bundled scenes.
#[pyfunction]
fn examples() -> Vec<(String, String)> {
    liftoff::examples::SCENES
        .iter()
        .map(|(n, d, _)| (n.to_string(), d.to_string()))
        .collect()
}

/// The TOML text of a bundled scene.
#[pyfunction]
fn example_text(name: &str) -> PyResult<String> {
    liftoff::examples::scene(name)
        .map(str::to_string)
        .ok_or_else(|| {
            to_py(
                SceneFile::example(name)
                    .err()
                    .unwrap_or_else(|| Error::invalid("scene", name.to_string())),
            )
        })
}

/// The scene's keys as JSON (a TOML scene's tables, for `liftoff.grid` to vary).
#[pyfunction]
fn scene_json(kind: &str, text: &str) -> PyResult<String> {
    let toml_text = match kind {
        "example" => example_text(text)?,
        "json" => return Ok(text.to_string()),
        _ => text.to_string(),
    };
    let value: toml::Table =
        toml::from_str(&toml_text).map_err(|e| to_py(Error::Parse(e.to_string())))?;
    json(&value)
}

/// Validate a scene with options, without solving: its model's summary facts as JSON.
#[pyfunction]
fn check(py: Python<'_>, kind: &str, text: &str, options: &str) -> PyResult<String> {
    let p = run(py, || problem(kind, text, options))?;
    json(&serde_json::json!({
        "title": p.model.title,
        "elements": p.model.elements,
        "foundation": p.model.groups.foundation.name(),
        "method": p.method.name(),
        "combinations": p.combinations.iter().map(|c| c.name.clone()).collect::<Vec<_>>(),
    }))
}

/// The nodal and element fields of a report, as f64 bytes.
fn fields<'py>(py: Python<'py>, r: &liftoff::post::Report) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let f = &r.field;
    let e = &r.elements;
    // The columns of nodes.csv and elements.csv, by the same names and in the same order.
    let contact: Vec<f64> = f.contact.iter().map(|&c| f64::from(u8::from(c))).collect();
    let mut nodal: Vec<(&str, &[f64])> = f.columns().to_vec();
    nodal.push(("contact", &contact));
    let element: Vec<(&str, &[f64])> = e
        .columns()
        .iter()
        .map(|&(name, v)| match name {
            "x" => ("element_x", v),
            "y" => ("element_y", v),
            _ => (name, v),
        })
        .collect();
    for (name, v) in nodal.iter().chain(element.iter()) {
        let bytes: Vec<u8> = v.iter().flat_map(|x| x.to_le_bytes()).collect();
        d.set_item(*name, PyBytes::new(py, &bytes))?;
    }
    d.set_item("shape", (f.ny + 1, f.nx + 1))?;
    if e.x.len() == f.nx * f.ny {
        d.set_item("element_shape", (f.ny, f.nx))?;
    }
    Ok(d)
}

/// Solve a scene: `(summary_json, fields)` for a scene without combinations, or
/// `(combinations_json, [fields per combination])` with them (the JSON the CLI's `--json`
/// prints). A solve that did not converge is returned (its summary says so); the Python layer
/// raises `NotConverged`.
#[pyfunction]
fn solve<'py>(
    py: Python<'py>,
    kind: &str,
    text: &str,
    options: &str,
) -> PyResult<(String, Bound<'py, PyAny>)> {
    let p = run(py, || problem(kind, text, options))?;
    if p.combinations.is_empty() {
        let a = run(py, || liftoff::analyse(&p))?;
        let s = a.summary.to_json().map_err(to_py)?;
        Ok((s, fields(py, &a.report)?.into_any()))
    } else {
        let runs = run(py, || liftoff::combination::analyse(&p, &|_| {}))?;
        let envelope = liftoff::combination::envelope(&runs.runs);
        let s = liftoff::output::combinations::combinations_json(&runs, envelope.as_ref())
            .map_err(to_py)?;
        let list = pyo3::types::PyList::empty(py);
        for r in &runs.runs {
            match &r.outcome {
                Ok(o) => list.append(fields(py, &o.report)?)?,
                Err(_) => list.append(py.None())?,
            }
        }
        Ok((s, list.into_any()))
    }
}

/// `liftoff compare`: both methods on one assembly, as JSON.
#[pyfunction]
fn compare(py: Python<'_>, kind: &str, text: &str, options: &str) -> PyResult<String> {
    let c = run(py, || {
        problem(kind, text, options).and_then(|p| liftoff::compare::compare(&p))
    })?;
    json(&c)
}

/// A study on one scene, `name` "eps_sweep" or "tradeoff" (`liftoff eps-sweep`,
/// `liftoff tradeoff`), its options the JSON of [`EpsSweepOptions`] or [`TradeoffOptions`];
/// the study's result as JSON.
#[pyfunction]
fn study(
    py: Python<'_>,
    name: &str,
    kind: &str,
    text: &str,
    options: &str,
    study: &str,
) -> PyResult<String> {
    let bad = |e: serde_json::Error| to_py(Error::invalid(name, e.to_string()));
    match name {
        "eps_sweep" => {
            let o: EpsSweepOptions = serde_json::from_str(study).map_err(bad)?;
            json(&run(py, || {
                o.validate()?;
                o.run(&problem(kind, text, options)?, &mut |_| {})
            })?)
        }
        "tradeoff" => {
            let o: TradeoffOptions = serde_json::from_str(study).map_err(bad)?;
            json(&run(py, || {
                o.validate()?;
                o.run(&problem(kind, text, options)?, &mut |_| {})
            })?)
        }
        _ => Err(PyRuntimeError::new_err(format!("no study `{name}`"))),
    }
}

/// How many runs `liftoff stability` makes on these scenes (each a (kind, text) pair).
#[pyfunction]
fn stability_len(py: Python<'_>, scenes: Vec<(String, String)>, options: &str) -> PyResult<usize> {
    let bases = run(py, || {
        scenes
            .iter()
            .map(|(k, t)| problem(k, t, options))
            .collect::<liftoff::Result<Vec<_>>>()
    })?;
    Ok(stability_plan(&bases).len())
}

/// Runs `indices` of the stability plan of these scenes (all of them when None), as JSON rows
/// in plan order: the unit a Dask worker takes.
#[pyfunction]
#[pyo3(signature = (scenes, options, indices=None))]
fn stability_rows(
    py: Python<'_>,
    scenes: Vec<(String, String)>,
    options: &str,
    indices: Option<Vec<usize>>,
) -> PyResult<String> {
    let rows = run(py, || {
        let bases = scenes
            .iter()
            .map(|(k, t)| problem(k, t, options))
            .collect::<liftoff::Result<Vec<_>>>()?;
        let plan = stability_plan(&bases);
        let picked: Vec<usize> = indices.unwrap_or_else(|| (0..plan.len()).collect());
        if let Some(&bad) = picked.iter().find(|&&i| i >= plan.len()) {
            return Err(Error::invalid(
                "indices",
                format!("{bad} is beyond the plan's {} runs", plan.len()),
            ));
        }
        use rayon::prelude::*;
        Ok(picked
            .par_iter()
            .map(|&i| stability_run(&plan[i]))
            .collect::<Vec<_>>())
    })?;
    json(&rows)
}

/// The compiled core of `liftoff` (use the `liftoff` package, not this module).
#[pymodule]
fn _liftoff(m: &Bound<'_, PyModule>) -> PyResult<()> {
    // As the command line: faer's own threads off (the library parallelises where it pays), so
    // a solve gives the command line's numbers to the last digit and pool or Dask workers do
    // not oversubscribe the cores.
    faer::set_global_parallelism(faer::Par::Seq);
    m.add_function(wrap_pyfunction!(examples, m)?)?;
    m.add_function(wrap_pyfunction!(example_text, m)?)?;
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(scene_json, m)?)?;
    m.add_function(wrap_pyfunction!(solve, m)?)?;
    m.add_function(wrap_pyfunction!(compare, m)?)?;
    m.add_function(wrap_pyfunction!(study, m)?)?;
    m.add_function(wrap_pyfunction!(stability_len, m)?)?;
    m.add_function(wrap_pyfunction!(stability_rows, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
