//! `liftoff._liftoff`: the compiled core of the Python package. Every function converts its
//! arguments, releases the GIL around the library call and converts the result back: scenes
//! arrive as (kind, text) pairs, options as JSON (parsed by the library's
//! [`liftoff::scene::Overrides`]), results leave as JSON (the library's own serialisation, the
//! CLI's `--json`) and nodal fields as little-endian f64 bytes that NumPy reads without a copy.
//! No mechanics lives here; the public API (signatures, docstrings, stubs) is the pure-Python
//! layer in `python/liftoff/`.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;
use std::time::Duration;

use liftoff::scene::{Overrides, Problem, SceneFile};
use liftoff::study::{stability_plan, stability_run, EpsSweepOptions, TradeoffOptions};
use liftoff::units::{Measure, UnitSystem};
use liftoff::{Error, ErrorKind, Monitor, Outcome, Progress, Source};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList};

/// How often the waiting thread looks for Ctrl-C and passes progress on: well inside the one
/// second within which an interrupted solve must stop.
const POLL: Duration = Duration::from_millis(50);

/// A progress event carried from the solving thread to Python's.
enum Event {
    Case(usize, usize, String),
    Step(&'static str, usize, usize),
}

/// Run a library call on a thread of its own with the GIL released, while this (Python's)
/// thread waits: every [`POLL`] it checks for signals — Ctrl-C sets the run's cancel flag, the
/// library's loops stop at their next check, and the `KeyboardInterrupt` is raised — and hands
/// progress events to `progress` (a callable `(kind, done, total, label)`). A panic inside the
/// library (a bug) becomes `liftoff.NumericalError`, never a `PanicException` that
/// `except Exception` would not catch.
fn run<T: Send>(
    py: Python<'_>,
    progress: Option<&Bound<'_, PyAny>>,
    f: impl FnOnce(&Monitor<'_>) -> liftoff::Result<T> + Send,
) -> PyResult<T> {
    let cancel = AtomicBool::new(false);
    let callback = progress.map(|p| p.clone().unbind());
    let mut interrupt: Option<PyErr> = None;
    let mut callback_error: Option<PyErr> = None;
    let result = py.detach(|| {
        std::thread::scope(|scope| {
            let (tx, rx) = mpsc::channel::<Event>();
            let cancel = &cancel;
            let worker = scope.spawn(move || {
                let report = |p: Progress<'_>| {
                    let _ = tx.send(match p {
                        Progress::Case { done, total, label } => {
                            Event::Case(done, total, label.to_string())
                        }
                        Progress::Step {
                            method,
                            step,
                            changes,
                        } => Event::Step(method.name(), step, changes),
                    });
                };
                let monitor = Monitor::NONE.with_cancel(cancel).with_progress(&report);
                std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| f(&monitor)))
                    .unwrap_or_else(|panic| {
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
            });
            loop {
                match rx.recv_timeout(POLL) {
                    Ok(event) => {
                        if let (Some(cb), None) = (&callback, &callback_error) {
                            let called = Python::attach(|py| match event {
                                Event::Case(d, t, l) => cb.call1(py, ("case", d, t, l)).map(drop),
                                Event::Step(m, s, c) => cb.call1(py, (m, s, c, "")).map(drop),
                            });
                            if let Err(e) = called {
                                // A failing callback stops the run and is raised.
                                callback_error = Some(e);
                                cancel.store(true, Ordering::Relaxed);
                            }
                        }
                    }
                    Err(mpsc::RecvTimeoutError::Timeout) => {}
                    Err(mpsc::RecvTimeoutError::Disconnected) => break,
                }
                if interrupt.is_none() {
                    if let Err(e) = Python::attach(|py| py.check_signals()) {
                        interrupt = Some(e);
                        cancel.store(true, Ordering::Relaxed);
                    }
                }
            }
            worker.join().unwrap_or_else(|_| {
                Err(Error::numerical(
                    "liftoff (internal error, please report the scene)",
                    "the solving thread stopped",
                ))
            })
        })
    });
    if let Some(e) = interrupt.or(callback_error) {
        return Err(e);
    }
    result.map_err(to_py)
}

/// A library error as the matching `liftoff.errors` exception (its class from the error's
/// kind), carrying the message and, for a scene value, the field it names.
fn to_py(e: Error) -> PyErr {
    let class = match e.kind() {
        ErrorKind::Invalid => "SceneError",
        ErrorKind::TooLarge => "TooLarge",
        ErrorKind::Infeasible => "Infeasible",
        ErrorKind::Numerical => "NumericalError",
        ErrorKind::Io => "LiftoffIOError",
        ErrorKind::Cancelled => "LiftoffError",
    };
    let field = match &e {
        Error::Invalid { field, .. } => Some(field.clone()),
        _ => None,
    };
    let kind = e.kind().name();
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

/// The scene of a (kind, text) pair: "toml" text, "json" text (a dict's), or "example" (a
/// bundled scene's name).
fn source<'a>(kind: &str, text: &'a str) -> Source<'a> {
    match kind {
        "example" => Source::Example(text),
        "json" => Source::Json(text),
        _ => Source::Toml(text),
    }
}

/// The library's one entry: read the scene, apply the options (a JSON object), validate.
fn problem(kind: &str, text: &str, options: &str) -> liftoff::Result<Problem> {
    liftoff::load(&source(kind, text), &Overrides::from_json(options)?)
}

/// The options `solve` and the studies take (the library's list, the CLI's flags).
#[pyfunction]
fn options() -> Vec<&'static str> {
    liftoff::scene::OPTIONS.iter().map(|o| o.0).collect()
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
    let p = run(py, None, |_| problem(kind, text, options))?;
    json(&serde_json::json!({
        "title": p.model.title,
        "elements": p.model.elements,
        "foundation": p.model.groups.foundation().name(),
        "method": p.method.name(),
        "combinations": p.combinations.iter().map(|c| c.name.clone()).collect::<Vec<_>>(),
    }))
}

/// The nodal and element fields of a report, as f64 bytes.
/// In the scene's unit system (`system`; None for a dimensionless scene), as the CLI's files.
fn fields<'py>(
    py: Python<'py>,
    r: &liftoff::post::Report,
    system: Option<UnitSystem>,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let f = &r.field.in_units(system);
    let e = &r.elements.in_units(system);
    // The columns of nodes.csv and elements.csv, by the same names and in the same order.
    let contact: Vec<f64> = f.contact.iter().map(|&c| f64::from(u8::from(c))).collect();
    // The faces' stresses recovered at the nodes keep their element-centre twins' names free.
    let mut nodal: Vec<(&str, &[f64])> = f
        .columns()
        .iter()
        .map(|&(name, _, v)| match name {
            "s1_bottom" => ("s1_bottom_nodes", v),
            "s1_top" => ("s1_top_nodes", v),
            _ => (name, v),
        })
        .collect();
    nodal.push(("contact", &contact));
    let element: Vec<(&str, &[f64])> = e
        .columns()
        .iter()
        .map(|&(name, _, v)| match name {
            "x" => ("element_x", v),
            "y" => ("element_y", v),
            _ => (name, v),
        })
        .collect();
    let bytes = |v: &[f64]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
    // The (ny + 1, nx + 1) arrays are the grid nodes (on a joint, the lower / left copy); the
    // extra copies follow in `joint_nodes`. On a shaped plate the nodes and elements outside
    // it read NaN (their coordinates stay), and the masks say which are plate.
    let n_grid = f.n_grid();
    let on_node = f.node_on_plate();
    let on_cell: Vec<bool> = (0..f.nx * f.ny)
        .map(|c| f.is_plate(c % f.nx.max(1), c / f.nx.max(1)))
        .collect();
    let masked = |v: &[f64], on: &[bool], keep: bool| -> Vec<f64> {
        v.iter()
            .enumerate()
            .map(|(k, &x)| match keep || on.get(k).copied().unwrap_or(true) {
                true => x,
                false => f64::NAN,
            })
            .collect()
    };
    // Coordinates stay, and the contact flag (0 off the plate: a mask, not a value).
    let place = |name: &str, prefix: &str| {
        ["x", "y", "s", "t", "contact"].contains(&name.trim_start_matches(prefix))
    };
    for (name, v) in nodal.iter() {
        let v = masked(&v[..n_grid.min(v.len())], &on_node, place(name, ""));
        d.set_item(*name, PyBytes::new(py, &bytes(&v)))?;
    }
    for (name, v) in element.iter() {
        let v = masked(v, &on_cell, place(name, "element_"));
        d.set_item(*name, PyBytes::new(py, &bytes(&v)))?;
    }
    let flag = |on: &[bool]| {
        on.iter()
            .map(|&o| f64::from(u8::from(o)))
            .collect::<Vec<f64>>()
    };
    d.set_item(
        "plate_nodes",
        PyBytes::new(py, &bytes(&flag(&on_node[..n_grid.min(on_node.len())]))),
    )?;
    d.set_item("plate_cells", PyBytes::new(py, &bytes(&flag(&on_cell))))?;
    d.set_item("shape", (f.ny + 1, f.nx + 1))?;
    if e.x.len() == f.nx * f.ny {
        d.set_item("element_shape", (f.ny, f.nx))?;
    }
    d.set_item("joint_nodes", joint_nodes(py, f)?)?;
    d.set_item("dowels", dowels(py, &r.joints, system)?)?;
    Ok(d)
}

/// The extra node copies along the joints that cut a jointed plate, as 1-D f64 arrays (bytes)
/// in the order of the report's arrays after the grid nodes: grid position `i`, `j`, `panel`
/// (column + row · columns) and the nodal `w`, `psi_x`, `psi_y`, `pressure`, `gap`; empty
/// arrays without joints.
fn joint_nodes<'py>(py: Python<'py>, f: &liftoff::post::FullField) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let bytes = |v: &[f64]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
    let n_grid = f.n_grid();
    let (i, j): (Vec<f64>, Vec<f64>) = f
        .extra_grid
        .iter()
        .map(|&g| ((g % f.nodes_x()) as f64, (g / f.nodes_x()) as f64))
        .unzip();
    let panel: Vec<f64> = f.extra_panels().iter().map(|&p| f64::from(p)).collect();
    d.set_item("i", PyBytes::new(py, &bytes(&i)))?;
    d.set_item("j", PyBytes::new(py, &bytes(&j)))?;
    d.set_item("panel", PyBytes::new(py, &bytes(&panel)))?;
    for (name, v) in [
        ("w", &f.w),
        ("psi_x", &f.psi_x),
        ("psi_y", &f.psi_y),
        ("pressure", &f.pressure),
        ("gap", &f.gap),
    ] {
        d.set_item(
            name,
            PyBytes::new(py, &bytes(v.get(n_grid..).unwrap_or(&[]))),
        )?;
    }
    Ok(d)
}

/// Every dowel bar of a jointed plate, as 1-D f64 arrays (bytes), the rows of dowels.csv:
/// `joint` (index into the summary's `joints`), `bar`, `x`, `y`, `jump`, `force` and
/// `bearing_stress` (NaN where the bar's properties are not given).
fn dowels<'py>(
    py: Python<'py>,
    joints: &[liftoff::post::JointReport],
    system: Option<UnitSystem>,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let bytes = |v: &[f64]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
    let rows: Vec<(usize, &liftoff::post::DowelForce)> = joints
        .iter()
        .enumerate()
        .flat_map(|(k, j)| j.dowels.iter().map(move |b| (k, b)))
        .collect();
    type Pick = fn(&(usize, &liftoff::post::DowelForce)) -> f64;
    let columns: [(&str, Measure, Pick); 7] = [
        ("joint", Measure::Number, |r| r.0 as f64),
        ("bar", Measure::Number, |r| r.1.bar as f64),
        ("x", Measure::Length, |r| r.1.x),
        ("y", Measure::Length, |r| r.1.y),
        ("jump", Measure::Deflection, |r| r.1.jump),
        ("force", Measure::Force, |r| r.1.force),
        ("bearing_stress", Measure::Pressure, |r| {
            r.1.bearing_stress.unwrap_or(f64::NAN)
        }),
    ];
    for (name, m, pick) in columns {
        let v: Vec<f64> = rows.iter().map(|r| m.from_si(system, pick(r))).collect();
        d.set_item(name, PyBytes::new(py, &bytes(&v)))?;
    }
    Ok(d)
}

/// Per node and per element of a combinations scene's envelope: for each field its largest
/// and smallest values and the index of the governing combination (into `names`), as f64
/// bytes, by the column names of `envelope_nodes.csv` / `envelope_elements.csv`.
fn envelope_fields<'py>(
    py: Python<'py>,
    env: &liftoff::combination::Envelope,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    // In the scene's unit system, as envelope_*.csv.
    let env = &env.reported();
    let bytes = |v: &[f64]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
    let index = |v: &[usize]| v.iter().map(|&i| i as f64).collect::<Vec<f64>>();
    for (group, fields) in [("nodes", &env.nodes), ("elements", &env.elements)] {
        let g = PyDict::new(py);
        for (name, unit, e) in fields.iter() {
            let f = PyDict::new(py);
            f.set_item("unit", *unit)?;
            f.set_item("max", PyBytes::new(py, &bytes(&e.max)))?;
            f.set_item("max_by", PyBytes::new(py, &bytes(&index(&e.max_by))))?;
            f.set_item("min", PyBytes::new(py, &bytes(&e.min)))?;
            f.set_item("min_by", PyBytes::new(py, &bytes(&index(&e.min_by))))?;
            g.set_item(*name, f)?;
        }
        d.set_item(group, g)?;
    }
    d.set_item("names", env.names.clone())?;
    Ok(d)
}

/// Solve a scene: `(summary_json, fields, envelope)` — for a scene without combinations its
/// summary and fields (envelope None); with them the combinations' JSON, a list of fields per
/// combination (None where there is no solution), and the envelope's per-node and
/// per-element arrays (None unless every combination converged: the library's rule). The JSON
/// is the CLI's `--json`. A solve that did not converge is returned (its summary says so); the
/// Python layer raises `NotConverged`.
#[pyfunction]
#[pyo3(signature = (kind, text, options, progress=None))]
fn solve<'py>(
    py: Python<'py>,
    kind: &str,
    text: &str,
    options: &str,
    progress: Option<&Bound<'py, PyAny>>,
) -> PyResult<(String, Bound<'py, PyAny>, Bound<'py, PyAny>)> {
    let outcome = run(py, progress, |m| {
        let p = problem(kind, text, options)?;
        liftoff::run(&p, m)
    })?;
    let doc = outcome.to_json().map_err(to_py)?;
    match &outcome {
        Outcome::Single(a) => Ok((
            doc,
            fields(py, &a.report, a.summary.physical.map(|p| p.units))?.into_any(),
            py.None().into_bound(py),
        )),
        Outcome::Combinations(c) => {
            let list = PyList::empty(py);
            for r in &c.runs {
                match &r.outcome {
                    Ok(o) => {
                        list.append(fields(py, &o.report, o.summary.physical.map(|p| p.units))?)?
                    }
                    Err(_) => list.append(py.None())?,
                }
            }
            let env = match &c.envelope {
                Some(e) => envelope_fields(py, e)?.into_any(),
                None => py.None().into_bound(py),
            };
            Ok((doc, list.into_any(), env))
        }
    }
}

/// `liftoff compare`: both methods on one assembly, as JSON.
#[pyfunction]
fn compare(py: Python<'_>, kind: &str, text: &str, options: &str) -> PyResult<String> {
    let c = run(py, None, |m| {
        problem(kind, text, options).and_then(|p| liftoff::compare::compare_with(&p, m))
    })?;
    json(&c)
}

/// A study on one scene, `name` "eps_sweep" or "tradeoff" (`liftoff eps-sweep`,
/// `liftoff tradeoff`), its options the JSON of [`EpsSweepOptions`] or [`TradeoffOptions`];
/// the study's result as JSON.
#[pyfunction]
#[pyo3(signature = (name, kind, text, options, study, progress=None))]
fn study(
    py: Python<'_>,
    name: &str,
    kind: &str,
    text: &str,
    options: &str,
    study: &str,
    progress: Option<&Bound<'_, PyAny>>,
) -> PyResult<String> {
    let bad = |e: serde_json::Error| to_py(Error::invalid(name, e.to_string()));
    match name {
        "eps_sweep" => {
            let o: EpsSweepOptions = serde_json::from_str(study).map_err(bad)?;
            json(&run(py, progress, |m| {
                o.validate()?;
                o.run(&problem(kind, text, options)?, m)
            })?)
        }
        "tradeoff" => {
            let o: TradeoffOptions = serde_json::from_str(study).map_err(bad)?;
            json(&run(py, progress, |m| {
                o.validate()?;
                o.run(&problem(kind, text, options)?, m)
            })?)
        }
        _ => Err(PyRuntimeError::new_err(format!("no study `{name}`"))),
    }
}

/// `liftoff critical`: the search's result as JSON (`critical.json`), its options the JSON of
/// [`liftoff::study::CriticalOptions`] (`indices` for a share of the grid).
#[pyfunction]
#[pyo3(signature = (kind, text, options, critical, progress=None))]
fn critical(
    py: Python<'_>,
    kind: &str,
    text: &str,
    options: &str,
    critical: &str,
    progress: Option<&Bound<'_, PyAny>>,
) -> PyResult<String> {
    let o: liftoff::study::CriticalOptions = serde_json::from_str(critical)
        .map_err(|e| to_py(Error::invalid("critical", e.to_string())))?;
    // In the scene's unit system, as critical.json.
    json(&run(py, progress, |m| o.run(&problem(kind, text, options)?, m))?.reported())
}

/// `liftoff damage`: `(damage_json, maps)` — damage.json (`Damage::reported`: in the scene's
/// unit system) without its per-element arrays, and those arrays as f64 bytes — `x`, `y`
/// (element centres), `bottom`, `top` (Σ n/N), element ie + je nx — and `counted` (one byte
/// an element, 1 where it counts: `Damage::counted`) with their `shape` (ny, nx). A run with passes that did not converge is returned (`complete` false, `missing`
/// naming them); the Python layer raises `NotConverged`.
#[pyfunction]
#[pyo3(signature = (kind, text, options, progress=None))]
fn damage<'py>(
    py: Python<'py>,
    kind: &str,
    text: &str,
    options: &str,
    progress: Option<&Bound<'py, PyAny>>,
) -> PyResult<(String, Bound<'py, PyDict>)> {
    let d = run(py, progress, |m| {
        liftoff::study::damage(&problem(kind, text, options)?, m)
    })?;
    damage_out(py, &d)
}

/// A damage run as `damage` returns it: damage.json without its arrays, the arrays as bytes.
fn damage_out<'py>(
    py: Python<'py>,
    d: &liftoff::study::Damage,
) -> PyResult<(String, Bound<'py, PyDict>)> {
    let d = d.reported();
    let mut doc = serde_json::to_value(&d).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    if let Some(o) = doc.as_object_mut() {
        for key in ["x", "y", "bottom", "top", "counted"] {
            o.remove(key);
        }
    }
    let maps = PyDict::new(py);
    let bytes = |v: &[f64]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
    for (name, v) in [
        ("x", &d.x),
        ("y", &d.y),
        ("bottom", &d.bottom),
        ("top", &d.top),
    ] {
        maps.set_item(name, PyBytes::new(py, &bytes(v)))?;
    }
    let counted: Vec<u8> = d.counted.iter().map(|&c| u8::from(c)).collect();
    maps.set_item("counted", PyBytes::new(py, &counted))?;
    let [nx, ny] = d.elements;
    maps.set_item("shape", (ny, nx))?;
    Ok((json(&doc)?, maps))
}

/// How many families (the units a Dask task takes) the scene's damage run has.
#[pyfunction]
fn damage_families(py: Python<'_>, kind: &str, text: &str, options: &str) -> PyResult<usize> {
    run(py, None, |_| {
        liftoff::study::damage_families(&problem(kind, text, options)?)
    })
}

/// The passes of `families` of the scene's damage run, as a part's bytes
/// ([`liftoff::study::DamagePart::to_bytes`]): what one Dask task returns.
#[pyfunction]
#[pyo3(signature = (kind, text, options, families, progress=None))]
fn damage_part<'py>(
    py: Python<'py>,
    kind: &str,
    text: &str,
    options: &str,
    families: Vec<usize>,
    progress: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyBytes>> {
    let part = run(py, progress, |m| {
        liftoff::study::damage_part(&problem(kind, text, options)?, &families, m)
    })?;
    Ok(PyBytes::new(py, &part.to_bytes()))
}

/// The damage run summed from parts that cover every family once, as `damage` returns it.
#[pyfunction]
fn damage_merge<'py>(
    py: Python<'py>,
    kind: &str,
    text: &str,
    options: &str,
    parts: Vec<Vec<u8>>,
) -> PyResult<(String, Bound<'py, PyDict>)> {
    let d = run(py, None, |_| {
        let parts = parts
            .iter()
            .map(|b| liftoff::study::DamagePart::from_bytes(b))
            .collect::<liftoff::Result<Vec<_>>>()?;
        liftoff::study::damage_merge(&problem(kind, text, options)?, parts)
    })?;
    damage_out(py, &d)
}

/// `liftoff design`: design.json (`Design::reported`: thicknesses in the scene's unit of
/// length). `design` is the JSON of {"vary": [from, to], "points": n, "target": t or null,
/// "tolerance": h or null}, lengths in the scene's unit (the command line's flags).
#[pyfunction]
#[pyo3(signature = (kind, text, options, design, progress=None))]
fn design(
    py: Python<'_>,
    kind: &str,
    text: &str,
    options: &str,
    design: &str,
    progress: Option<&Bound<'_, PyAny>>,
) -> PyResult<String> {
    #[derive(serde::Deserialize)]
    #[serde(deny_unknown_fields)]
    struct Spec {
        vary: [f64; 2],
        points: usize,
        target: Option<f64>,
        tolerance: Option<f64>,
    }
    let spec: Spec =
        serde_json::from_str(design).map_err(|e| to_py(Error::invalid("design", e.to_string())))?;
    let d = run(py, progress, |m| {
        let mut file = source(kind, text).parse()?;
        Overrides::from_json(options)?.apply(&mut file);
        let o = liftoff::study::DesignOptions::in_units(
            file.units,
            spec.vary,
            spec.points,
            spec.target,
            spec.tolerance,
        );
        o.validate()?;
        file.validate()?;
        liftoff::study::design(&file, &o, m)
    })?;
    json(&d.reported())
}

/// `liftoff backcalc`: backcalc.json (the survey, SI) of the drops in `basins` (the basin file's
/// text, CSV or PDDX; `source` names it in errors) on the template scene. `spec` is the JSON of
/// {"method", "fit", "contact", "elements", "seating", "static_k_factor", "max_evaluations",
/// "void_threshold" (m), "location", "at" ([x, y] m), "direction" (degrees)},
/// the command line's flags, each optional.
#[pyfunction]
#[pyo3(signature = (kind, text, options, basins, source_name, spec, progress=None))]
#[allow(clippy::too_many_arguments)]
fn backcalc(
    py: Python<'_>,
    kind: &str,
    text: &str,
    options: &str,
    basins: &str,
    source_name: &str,
    spec: &str,
    progress: Option<&Bound<'_, PyAny>>,
) -> PyResult<String> {
    use liftoff::backcalc::{BackcalcMethod, FitOptions, SurveyOptions, Unknown};
    use liftoff::choice::Choice;
    use liftoff::method::Contact;
    #[derive(serde::Deserialize)]
    #[serde(deny_unknown_fields)]
    struct Spec {
        method: Option<String>,
        fit: Option<Vec<String>>,
        contact: Option<String>,
        elements: Option<[usize; 2]>,
        seating: Option<usize>,
        static_k_factor: Option<f64>,
        max_evaluations: Option<usize>,
        void_threshold: Option<f64>,
        location: Option<String>,
        at: Option<[f64; 2]>,
        direction: Option<f64>,
    }
    fn word<T: Choice>(field: &str, w: &str) -> liftoff::Result<T> {
        T::from_name(w).ok_or_else(|| {
            Error::invalid(
                field,
                format!("`{w}` is not one of {}", T::names().join(", ")),
            )
        })
    }
    let s = run(py, progress, |m| {
        let spec: Spec =
            serde_json::from_str(spec).map_err(|e| Error::invalid("backcalc", e.to_string()))?;
        let defaults = SurveyOptions::default();
        let options_fit = FitOptions {
            unknowns: match &spec.fit {
                Some(v) => v
                    .iter()
                    .map(|w| word::<Unknown>("fit", w))
                    .collect::<liftoff::Result<_>>()?,
                None => defaults.fit.unknowns.clone(),
            },
            contact: spec
                .contact
                .as_deref()
                .map(|w| word::<Contact>("contact", w))
                .transpose()?,
            elements: spec.elements,
            max_evaluations: spec.max_evaluations.unwrap_or(defaults.fit.max_evaluations),
        };
        let survey_options = SurveyOptions {
            method: spec
                .method
                .as_deref()
                .map(|w| word::<BackcalcMethod>("method", w))
                .transpose()?
                .unwrap_or(defaults.method),
            fit: options_fit,
            seating: spec.seating.unwrap_or(0),
            static_k_factor: spec.static_k_factor.unwrap_or(defaults.static_k_factor),
            void_threshold: spec.void_threshold.unwrap_or(defaults.void_threshold),
        };
        let location = spec
            .location
            .as_deref()
            .map(|w| word::<liftoff::backcalc::Location>("location", w))
            .transpose()?;
        let placement =
            liftoff::backcalc::Placement::from_options(location, spec.at, spec.direction);
        let drops = liftoff::backcalc::read_drops_placed(basins, source_name, placement.as_ref())?;
        let mut file = source(kind, text).parse()?;
        Overrides::from_json(options)?.apply(&mut file);
        liftoff::backcalc::check_template(&file)?;
        liftoff::backcalc::survey(&file, &drops, &survey_options, m)
    })?;
    json(&s)
}

/// The AREA method on one basin (`liftoff::backcalc::area_method`): (AREA m, ℓ m, subgrade
/// modulus — k N/m³ or E_s Pa —, slab modulus Pa, corrected). `soil_poisson` None: a dense
/// liquid; a value: an elastic solid of that Poisson's ratio. `slab_size` (dense liquid): the
/// square slab's side, for Crovetti's correction (`liftoff::backcalc::finite_slab`);
/// `corrected` says whether it applied.
#[pyfunction]
#[pyo3(signature = (offsets, deflections, load, radius, thickness, poisson, soil_poisson=None, slab_size=None))]
#[allow(clippy::too_many_arguments)]
fn area_method(
    py: Python<'_>,
    offsets: Vec<f64>,
    deflections: Vec<f64>,
    load: f64,
    radius: f64,
    thickness: f64,
    poisson: f64,
    soil_poisson: Option<f64>,
    slab_size: Option<f64>,
) -> PyResult<(f64, f64, f64, f64, bool)> {
    use liftoff::backcalc::{Basin, Subgrade};
    let subgrade = match soil_poisson {
        None => Subgrade::DenseLiquid,
        Some(poisson) => Subgrade::ElasticSolid { poisson },
    };
    let basin = Basin {
        load,
        radius,
        offsets,
        deflections,
    };
    let r = run(py, None, |_| match slab_size {
        Some(size) => liftoff::backcalc::finite_slab(&basin, thickness, poisson, size),
        None => liftoff::backcalc::area_method(&basin, thickness, poisson, subgrade),
    })?;
    Ok((
        r.area,
        r.ell,
        r.subgrade_modulus,
        r.slab_modulus,
        r.finite.is_some(),
    ))
}

/// How many positions `critical` has for these options.
#[pyfunction]
fn critical_len(
    py: Python<'_>,
    kind: &str,
    text: &str,
    options: &str,
    critical: &str,
) -> PyResult<usize> {
    let o: liftoff::study::CriticalOptions = serde_json::from_str(critical)
        .map_err(|e| to_py(Error::invalid("critical", e.to_string())))?;
    run(py, None, |_| o.positions(&problem(kind, text, options)?))
}

/// How many runs `liftoff stability` makes on these scenes (each a (kind, text) pair).
#[pyfunction]
fn stability_len(py: Python<'_>, scenes: Vec<(String, String)>, options: &str) -> PyResult<usize> {
    let bases = run(py, None, |_| {
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
#[pyo3(signature = (scenes, options, indices=None, progress=None))]
fn stability_rows(
    py: Python<'_>,
    scenes: Vec<(String, String)>,
    options: &str,
    indices: Option<Vec<usize>>,
    progress: Option<&Bound<'_, PyAny>>,
) -> PyResult<String> {
    let rows = run(py, progress, |m| {
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
        let cases = liftoff::monitor::Cases::new(m, picked.len());
        picked
            .par_iter()
            .map(|&i| {
                let row = stability_run(&plan[i]);
                cases.finish(&format!(
                    "{} {} = {:.2e} ({})",
                    row.foundation,
                    row.sweep.name(),
                    row.value,
                    row.method
                ))?;
                Ok(row)
            })
            .collect::<liftoff::Result<Vec<_>>>()
    })?;
    json(&rows)
}

/// Test-only, not part of the API: panics inside the runner every library call goes through, so
/// that the tests can show a panic (a bug) reaching Python as `liftoff.NumericalError` with the
/// panic's message — the library itself has no input known to panic. Used by
/// `python/tests/test_errors.py` only; the leading underscore keeps it out of the public names.
#[pyfunction]
fn _panic_for_tests(py: Python<'_>, message: &str) -> PyResult<()> {
    run(py, None, |_| -> liftoff::Result<()> {
        panic!("{message}");
    })
}

/// The compiled core of `liftoff` (use the `liftoff` package, not this module).
#[pymodule]
fn _liftoff(m: &Bound<'_, PyModule>) -> PyResult<()> {
    // As the command line: faer's own threads off (the library parallelises where it pays), so
    // a solve gives the command line's numbers to the last digit and pool or Dask workers do
    // not oversubscribe the cores.
    faer::set_global_parallelism(faer::Par::Seq);
    m.add_function(wrap_pyfunction!(examples, m)?)?;
    m.add_function(wrap_pyfunction!(options, m)?)?;
    m.add_function(wrap_pyfunction!(example_text, m)?)?;
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(scene_json, m)?)?;
    m.add_function(wrap_pyfunction!(solve, m)?)?;
    m.add_function(wrap_pyfunction!(compare, m)?)?;
    m.add_function(wrap_pyfunction!(study, m)?)?;
    m.add_function(wrap_pyfunction!(stability_len, m)?)?;
    m.add_function(wrap_pyfunction!(critical, m)?)?;
    m.add_function(wrap_pyfunction!(critical_len, m)?)?;
    m.add_function(wrap_pyfunction!(damage, m)?)?;
    m.add_function(wrap_pyfunction!(damage_families, m)?)?;
    m.add_function(wrap_pyfunction!(damage_part, m)?)?;
    m.add_function(wrap_pyfunction!(damage_merge, m)?)?;
    m.add_function(wrap_pyfunction!(design, m)?)?;
    m.add_function(wrap_pyfunction!(area_method, m)?)?;
    m.add_function(wrap_pyfunction!(backcalc, m)?)?;
    m.add_function(wrap_pyfunction!(stability_rows, m)?)?;
    m.add_function(wrap_pyfunction!(_panic_for_tests, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
