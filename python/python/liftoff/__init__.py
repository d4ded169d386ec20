"""liftoff — rectangular Mindlin plates on tensionless (or bonded) Winkler, Pasternak and
elastic half-space foundations, by the paper's penalty iteration or a convex QP.

A thin, NumPy-native layer over the Rust library (the same code as the ``liftoff`` command):

>>> import liftoff
>>> s = liftoff.solve("example:paper-halfspace", method="qp")
>>> s.V_max, s.contact_fraction, s.sigma.shape

Scenes are a path to a ``.toml`` file, TOML text, ``"example:NAME"`` (``liftoff.examples()``)
or a dict with the scene file's keys. Options are the CLI's: ``penalty`` ("auto" or ε̄),
``qp_form``, ``qp_solver``, ``constraint``, ``solver`` (route), ``mesh`` (n or (nx, ny)),
``symmetry``, ``contact``. Errors are ``liftoff.errors`` exceptions carrying the library's kind.
"""

from __future__ import annotations

import json
from typing import Any, Dict, Iterable, List, Mapping, Optional, Sequence, Union

from . import _liftoff as _core
from . import _damage, _progress
from ._damage import Damage
from ._records import Records
from ._scene import Scene, options_json, scene_pair
from ._solution import Combinations, Solution, from_core
from ._sweep import Grid, critical_chunk, damage_chunk, make_grid, run_all, stability_chunk
from ._sweep import sweep as _run_sweep
from .errors import (
    Infeasible,
    LiftoffError,
    LiftoffIOError,
    NotConverged,
    NumericalError,
    SceneError,
    TooLarge,
)

__version__ = _core.__version__

__all__ = [
    "examples",
    "example_text",
    "backcalc",
    "solve",
    "compare",
    "eps_sweep",
    "tradeoff",
    "stability",
    "critical",
    "damage",
    "design",
    "area_method",
    "grid",
    "sweep",
    "Solution",
    "Combinations",
    "Damage",
    "Records",
    "Grid",
    "LiftoffError",
    "SceneError",
    "TooLarge",
    "Infeasible",
    "NumericalError",
    "LiftoffIOError",
    "NotConverged",
]


def examples() -> Dict[str, str]:
    """The bundled scenes, name → one-line description (solve one as ``"example:NAME"``)."""
    return dict(_core.examples())


def example_text(name: str) -> str:
    """The TOML text of a bundled scene (a starting point for your own)."""
    return _core.example_text(name)


def solve(
    scene: Scene, method: Optional[str] = None, *, progress: Any = None, **options: Any
) -> Union[Solution, Combinations]:
    """Solve a scene with ``method`` "penalty", "qp" or "bonded" (default: the scene's own).

    Returns a :class:`Solution` (NumPy arrays over the whole plate, the summary as attributes),
    or for a scene with ``[[combination]]``s a :class:`Combinations` (one Solution per
    combination, and the envelope with its per-node and per-element arrays). Raises
    :class:`NotConverged` (with ``.solution``) when the method stops without a solution — for
    combinations when any one has none, as the CLI does: then there is no envelope, and
    ``.solution.missing`` names those combinations — and the other ``liftoff.errors`` for bad
    input. The GIL is released during assembly and solves; Ctrl-C stops the solve within a
    fraction of a second and raises ``KeyboardInterrupt``. ``progress``: see :func:`stability`.
    """
    kind, text = scene_pair(scene)
    result = from_core(*_progress.run(_core.solve, progress, kind, text, options_json(method, options)))
    if isinstance(result, Combinations):
        if not result.converged:
            failed = {**result.errors, **{n: s.status for n, s in result.solutions.items() if not s.converged}}
            raise NotConverged(
                f"not every combination has a solution ({', '.join(result.missing)} missing; no envelope): "
                + "; ".join(f"{n}: {m}" for n, m in failed.items()),
                solution=result,
            )
    elif not result.converged:
        raise NotConverged(
            f"the {result.method} method did not converge ({result.status}); the numbers are not a solution",
            solution=result,
        )
    return result


def compare(scene: Scene, **options: Any) -> Dict[str, Any]:
    """Penalty and QP on one assembly (``liftoff compare``): both summaries and their
    differences, as the CLI's ``compare.json``."""
    kind, text = scene_pair(scene)
    return json.loads(_core.compare(kind, text, options_json(None, options)))


def eps_sweep(
    scene: Scene,
    *,
    start: float = 1e-1,
    stop: float = 1e-12,
    points: int = 12,
    constraints: str = "nodal",
    progress: Any = None,
    **options: Any,
) -> Records:
    """The penalty solution against the QP as ε̄ falls from ``start`` to ``stop``
    (``liftoff eps-sweep``): one record per (constraint points, ε̄); ``meta`` holds the fitted
    slopes and the reference."""
    kind, text = scene_pair(scene)
    study = json.dumps({"from": start, "to": stop, "points": points, "constraints": constraints})
    doc = json.loads(
        _progress.run(_core.study, progress, "eps_sweep", kind, text, options_json(None, options), study)
    )
    rows = doc.pop("rows", [])
    return Records(rows, doc)


def tradeoff(
    scene: Scene,
    *,
    meshes: Sequence[int] = (8, 16, 32, 64),
    penalties: Sequence[float] = (1e-2, 1e-4, 1e-6, 1e-8),
    client: Any = None,
    progress: Any = None,
    **options: Any,
) -> Records:
    """Speed against accuracy (``liftoff tradeoff``): one record per (method, mesh, ε̄) with its
    time and error against the QP on twice the finest mesh. With a Dask ``client`` the study
    runs as one task on the cluster (its points share that reference solve)."""
    kind, text = scene_pair(scene)
    study = json.dumps({"meshes": list(meshes), "penalties": list(penalties)})
    opts = options_json(None, options)
    if client is not None:
        raw = client.gather(client.submit(_core.study, "tradeoff", kind, text, opts, study, pure=False))
    else:
        raw = _progress.run(_core.study, progress, "tradeoff", kind, text, opts, study)
    doc = json.loads(raw)
    rows = doc.pop("points", [])
    return Records(rows, doc)


def stability(
    scenes: Union[Scene, Sequence[Scene]],
    *,
    client: Any = None,
    chunk: int = 8,
    progress: Any = None,
    **options: Any,
) -> Records:
    """Where each method fails (``liftoff stability``): one record per run of the sweep over
    Γ, Δ, μ, ε̄ and load position, for each scene. With a Dask ``client`` the runs are spread
    over the cluster in tasks of ``chunk`` runs; rows come back in the study's order.

    ``progress`` (here, in :func:`solve` and the other studies run locally): None draws the
    command line's progress bar on stderr when stderr is a terminal, True always, False never;
    a callable receives every event as ``(kind, done, total, label)`` — kind "case" when a case
    of the run starts or ends, or an iteration's name ("penalty step", "active-set face
    solve") with its number and the points that changed. Ctrl-C stops a local run and raises
    ``KeyboardInterrupt``."""
    if isinstance(scenes, (str, Mapping)) or not isinstance(scenes, Sequence):
        scenes = [scenes]
    pairs = [scene_pair(s) for s in scenes]
    opts = options_json(None, options)
    if client is None:
        return Records(json.loads(_progress.run(_core.stability_rows, progress, pairs, opts, None)))
    n = _core.stability_len(pairs, opts)
    tasks = [
        {"scenes": pairs, "options": opts, "indices": list(range(i, min(i + chunk, n)))}
        for i in range(0, n, chunk)
    ]
    rows: List[Dict[str, Any]] = []
    for part in run_all(stability_chunk, tasks, client):
        rows.extend(json.loads(part))
    return Records(rows)


def critical(
    scene: Scene,
    load: str,
    *,
    grid: Optional[Sequence[int]] = None,
    grid_per_panel: Optional[Sequence[int]] = None,
    along: Optional[Sequence[str]] = None,
    headings: Optional[Sequence[float]] = None,
    combination: Optional[str] = None,
    warm: bool = True,
    mirror: bool = True,
    ends: Optional[str] = None,
    client: Any = None,
    chunk: int = 10,
    progress: Any = None,
    method: Optional[str] = None,
    **options: Any,
) -> Records:
    """The critical position of a vehicle load (``liftoff critical``): the ``axle`` or ``gear``
    load named ``load`` moved over a ``grid`` of reference points that keep its tires on the
    plate (and over ``headings``), the rest of its ``combination`` present, every position its
    own contact problem on operators assembled once, warm-started from its neighbour.

    One record per position (``x``, ``y``, ``heading``, ``outcome``, ``bottom``/``top`` — the
    largest principal stress of that face, Pa — with ``bottom_at``/``top_at``, ``w_max``, …);
    ``meta`` holds the indices of the critical positions (``bottom``, ``top``, ``deflection``;
    on a jointed plate also ``joint_shear`` and ``dowel_force``, the positions of the largest
    joint shear per length and dowel force, whose values are the rows' keys of those names)
    and the search's facts. With a Dask ``client`` the positions are spread over the cluster in
    tasks of ``chunk`` positions (each task assembles the operators once); rows come back in
    grid order. The search warm-starts runs of 10 positions of the grid, whatever the cores:
    a ``chunk`` that is a multiple of 10 gives every digit (and step count) of a local search.
    On a plate symmetric about x = 0 or y = 0 a position whose load is another's mirror image
    is read off that one (its row's ``mirror_of``: the other's index; no steps, no time);
    ``mirror=False`` solves every position.

    On a lane of three or more slabs along x (two or more transverse joints) whose ends are a
    cut of a lane that goes on (``ends="cut"``; default: the scene's ``[plate] ends``, or its
    ``[traffic]``'s, else ``"free"``) every position is read between the first and the last
    transverse joint (``meta["read_x"]``), and the rows' ``end_bottom``/``end_top`` hold the end
    panels' largest tensions, not read (the indices of their largest in ``meta``);
    ``ends="free"`` reads the whole plate.

    ``grid`` (default ``(11, 9)``) spaces the points evenly over the plate; ``grid_per_panel``
    (``(NX, NY)``, not with ``grid``) puts NX × NY points in every panel between the joint
    lines, its sides included (``5`` → 0, ¼, ½, ¾, 1 of the panel), so that the middle of a
    panel's edge and the joints are on it. ``along`` (``["joint:T2", "edge:y-"]``) searches
    along those lines only: across a joint the prints just before it, the load on it and the
    prints just after it; on an edge the prints touching it (as ``liftoff critical --along``).
    """
    if grid is not None and grid_per_panel is not None:
        raise SceneError("give grid or grid_per_panel, not both", "invalid", "grid_per_panel")
    if ends not in (None, "cut", "free"):
        raise SceneError(f"ends must be \"cut\" or \"free\", got {ends!r}", "invalid", "ends")
    kind, text = scene_pair(scene)
    opts = options_json(method, options)
    spec = {"load": load, "grid": list(grid if grid is not None else (11, 9)),
            "grid_per_panel": list(grid_per_panel) if grid_per_panel is not None else None,
            "along": list(along or []), "headings": list(headings or []),
            "combination": combination, "warm": warm, "mirror": mirror, "ends": ends}
    if client is None:
        doc = json.loads(_progress.run(_core.critical, progress, kind, text, opts, json.dumps(spec)))
        rows = doc.pop("positions")
        return Records(rows, doc)
    n = _core.critical_len(kind, text, opts, json.dumps(spec))
    tasks = [
        {"kind": kind, "text": text, "options": opts,
         "critical": json.dumps({**spec, "indices": list(range(i, min(i + chunk, n)))})}
        for i in range(0, n, chunk)
    ]
    rows: List[Dict[str, Any]] = []
    meta: Dict[str, Any] = {}
    for part in run_all(critical_chunk, tasks, client):
        doc = json.loads(part)
        rows.extend(doc.pop("positions"))
        meta = {k: v for k, v in doc.items()
                if k not in ("bottom", "top", "deflection", "joint_shear", "dowel_force",
                             "end_bottom", "end_top")}

    def best(key: str) -> Optional[int]:
        ok = [i for i, r in enumerate(rows)
              if r["outcome"] == "converged" and r.get(key) is not None]
        return max(ok, key=lambda i: rows[i][key]) if ok else None

    meta.update({"bottom": best("bottom"), "top": best("top"), "deflection": best("w_max")})
    # A jointed plate's: the largest joint shear per length and dowel force, where present.
    # A cut lane's: the end panels' largest tensions, not read.
    for key in ("joint_shear", "dowel_force", "end_bottom", "end_top"):
        if best(key) is not None:
            meta[key] = best(key)
    return Records(rows, meta)


def damage(
    scene: Scene,
    method: Optional[str] = None,
    *,
    progress: Any = None,
    client: Any = None,
    chunk: int = 1,
    **options: Any,
) -> Damage:
    """Fatigue damage over the scene's ``[traffic]``, ``[climate]`` and ``[damage]``
    (``liftoff damage``): every case — an axle group or gear at a load level, at a lateral
    position, in a climate bin — a pass of the group along the lane, each of its positions an
    unbonded contact solve (``method`` "penalty" or "qp"; default: the scene's own) on operators
    assembled once, and the Miner sum Σ n/N of the passes at both faces of every element.

    Returns a :class:`Damage`: ``bottom`` and ``top`` (arrays of shape ``(ny, nx)``, element
    ie + je·nx at row je, column ie), ``x``, ``y`` (element centres, same shape), ``passes``
    (one record per case, passes.csv's columns), ``governing_bottom`` / ``governing_top``,
    ``cracking`` (MEPDG), ``complete``, ``missing``, … — in the scene's units, as damage.json.
    As the CLI (which exits with an error), a run where some pass did not converge is not an
    answer: it raises :class:`NotConverged`, whose ``.solution`` is the incomplete Damage
    (``complete`` False, ``missing`` naming the passes left out of its sums). When no pass
    converges there is nothing to sum and :class:`NumericalError` is raised; a scene without
    the sections, or with a bad plan, raises :class:`SceneError` naming the key. ``progress``:
    as in :func:`solve`, one "case" event as each pass ends.

    With a Dask ``client`` the run's families — the levels of one group at one lateral
    position in one climate bin, which are solved together (warm starts, the exact
    interpolation between levels) — are spread over the cluster in tasks of ``chunk``
    families; each task assembles its operators once and returns its passes' stresses, and
    the sums are made here from all of them: the same numbers, to the bit, as a run in one
    process (``total_s`` is then the workers' seconds added). ``progress`` is not called for a
    distributed run.
    """
    kind, text = scene_pair(scene)
    opts = options_json(method, options)
    if client is None:
        raw = _progress.run(_core.damage, progress, kind, text, opts)
    else:
        n = _core.damage_families(kind, text, opts)
        size = max(1, int(chunk))
        tasks = [{"kind": kind, "text": text, "options": opts,
                  "families": list(range(i, min(i + size, n)))}
                 for i in range(0, n, size)]
        parts = run_all(damage_chunk, tasks, client)
        raw = _core.damage_merge(kind, text, opts, list(parts))
    result = _damage.from_core(*raw)
    if not result.complete:
        raise NotConverged(
            f"{len(result.missing)} pass(es) did not converge: the damage sums are incomplete "
            f"({'; '.join(result.missing)})",
            solution=result,
        )
    return result


def design(
    scene: Scene,
    vary: Union[str, Sequence[float]],
    *,
    points: int = 6,
    target: Optional[float] = None,
    tolerance: Optional[float] = None,
    method: Optional[str] = None,
    progress: Any = None,
    **options: Any,
) -> Records:
    """The least slab thickness that carries the scene's traffic (``liftoff design``): whole
    damage runs (:func:`damage`) at ``points`` thicknesses (6, as the CLI) evenly over ``vary`` — ``(FROM, TO)``
    or ``"thickness=FROM..TO"``, in the scene's unit of length — give the design curve; the
    first thickness that meets the target and the one before it bracket the answer, narrowed to
    ``tolerance`` (default 5 mm; 0.25 in for a US scene) by probes placed where the bracket's
    values, interpolated in their logarithm, put the target (as the CLI). The target (``target``) is the MEPDG's
    total cracking in % (at the scene's ``[damage] reliability`` when given; default 15) or, for
    ``faa``, the larger of the bottom-up and top-down damage, for ``pca`` the largest of those
    and the erosion damage at the corners (default 1). The
    self-weight (a ``uniform`` load whose case or name is ``self-weight``) follows the
    thickness.

    Returns :class:`Records`, one per damage run by thickness (design.csv's columns:
    ``thickness``, ``bottom``, ``top``, ``erosion`` (``pca``), ``cracking``, ``value``,
    ``passes``, ``complete``,
    ``solves``, ``seconds``, ``curve`` — False for a search step); ``meta`` holds the rest of
    design.json: ``thickness`` (the least thickness found; None if none in the range meets the
    target), ``bracket``, ``target``, ``measure``, ``model``, ``monotone``, ``complete``,
    ``units``. As the CLI, a search with a damage run that did not converge raises
    :class:`NotConverged` (its ``.solution`` the incomplete records).
    """
    if isinstance(vary, str):
        name, sep, span = vary.partition("=")
        lo, dots, hi = span.partition("..")
        if name.strip() != "thickness" or not sep or not dots:
            raise SceneError(
                f"`{vary}`: vary must be thickness=FROM..TO (or a pair), in the scene's unit of length",
                "invalid", "vary")
        try:
            pair = [float(lo), float(hi)]
        except ValueError:
            raise SceneError(f"`{vary}`: FROM and TO must be numbers", "invalid", "vary") from None
    else:
        pair = [float(v) for v in vary]
        if len(pair) != 2:
            raise SceneError("vary must be two thicknesses (FROM, TO)", "invalid", "vary")
    kind, text = scene_pair(scene)
    spec = {"vary": pair, "points": int(points), "target": target, "tolerance": tolerance}
    doc = json.loads(_progress.run(_core.design, progress, kind, text,
                                   options_json(method, options), json.dumps(spec)))
    rows = doc.pop("points")
    result = Records(rows, doc)
    if not doc.get("complete", True):
        raise NotConverged(
            "some damage runs had passes that did not converge: the design curve is incomplete",
            solution=result,
        )
    return result


def area_method(
    offsets: Sequence[float],
    deflections: Sequence[float],
    *,
    load: float,
    radius: float = 0.15,
    thickness: float,
    poisson: float = 0.15,
    subgrade: str = "dense-liquid",
    soil_poisson: float = 0.4,
    slab_size: Optional[float] = None,
) -> Dict[str, float]:
    """The AREA method on one deflection basin (SI: m, N): the infinite slab's radius of
    relative stiffness from the basin's shape, then the subgrade's and the slab's moduli
    (docs/METHODS.md, "Backcalculation"). ``offsets`` must include the sensors at 0, 305, 610
    and 914 mm; ``subgrade`` is ``"dense-liquid"`` (k) or ``"elastic-solid"`` (E_s, with
    ``soil_poisson``). Returns ``area`` (m) and ``area_in`` (in), ``ell`` (m),
    ``subgrade_modulus`` (k in N/m³, or E_s in Pa) and ``slab_modulus`` (Pa). ``slab_size``
    (m, dense liquid only): the side of the square slab the load stood at the centre of
    (√(L₁ L₂) of a rectangle); the reading is then corrected by Crovetti's factors (1994), and
    ``corrected`` says whether it was (not below L/ℓ = 3). A basin without those sensors,
    deflections that grow away from the load or a load that is not positive raise
    :class:`SceneError` naming the field."""
    if subgrade not in ("dense-liquid", "elastic-solid"):
        raise SceneError(f"`{subgrade}`: subgrade must be dense-liquid or elastic-solid",
                         "invalid", "subgrade")
    nu_s = soil_poisson if subgrade == "elastic-solid" else None
    if slab_size is not None and nu_s is not None:
        raise SceneError("slab_size: the finite-slab correction is for a dense liquid only",
                         "invalid", "slab_size")
    area, ell, modulus, slab, corrected = _core.area_method(
        [float(o) for o in offsets], [float(d) for d in deflections], float(load),
        float(radius), float(thickness), float(poisson), nu_s,
        None if slab_size is None else float(slab_size))
    return {"area": area, "area_in": area / 0.0254, "ell": ell,
            "subgrade_modulus": modulus, "slab_modulus": slab, "corrected": corrected}


def backcalc(
    basins: Any,
    scene: Scene,
    *,
    method: str = "fit",
    fit: Sequence[str] = ("subgrade", "slab"),
    contact: Optional[str] = None,
    elements: Optional[Sequence[int]] = None,
    seating: int = 0,
    static_k_factor: float = 0.5,
    max_evaluations: int = 60,
    void_threshold: float = 50.8e-6,
    location: Optional[str] = None,
    at: Optional[Sequence[float]] = None,
    direction: Optional[float] = None,
    progress: Any = None,
) -> Records:
    """Backcalculate the soil and the slab from deflectometer basins (``liftoff backcalc``).

    ``basins``: a basin file's path, or its text: CSV (one row a drop, the units in the column
    names) or AASHTO PDDX (its drops interior ones unless ``location`` says otherwise): README, "Backcalculation". ``scene``: the template — the slab's size, thickness, ν
    and joints, and the soil whose modulus is fitted. ``method``: ``"fit"`` (least squares on
    liftoff's model, with the AREA reading beside it) or ``"area"``; ``fit``: the unknowns,
    ``"subgrade"`` (the soil's ``modulus`` k, or its ``youngs_modulus``), ``"slab"`` (E) and
    ``"void"`` (the depth of the template's ``[[void]]`` nearest the drop, unbonded contact) and
    ``"joint"`` (the ``stiffness`` of the template's aggregate or tied joint nearest the drop);
    ``contact``: ``"bonded"`` or ``"unbonded"`` (default: the template's); ``elements``:
    (NX, NY) (default: the template's counts refined to elements under 0.95 of the plate's
    radius); ``seating``: drops discarded at the start of each station; ``static_k_factor``:
    static over dynamic k (AASHTO 1993: 0.5); ``void_threshold``: the zero-load intercept (m)
    above which a station's load–deflection line flags a void (2 mils). ``location``
    (``"interior"``, ``"edge"``, ``"corner"``, ``"joint-approach"``, ``"joint-leave"``), ``at``
    ((x, y) m, the plate's centre in the template's coordinates) and ``direction`` (degrees from
    the x axis) say where every drop of a PDDX file stood, which the file does not; a CSV file
    says it in its columns, and refuses them.

    Returns :class:`Records`, one per drop (SI: N/m³, Pa, m): ``station``, ``drop``,
    ``location``, ``load``, ``subgrade`` with ``subgrade_low`` and ``subgrade_high`` (the 95 %
    interval), ``slab`` with its interval, ``void`` (m) and ``joint`` (N/m²) with theirs,
    ``ell`` with its interval, ``static_k``, for joint drops the load transfer (``lte``,
    ``bending``, ``lte_corrected``, ``lte_model``), the AREA
    reading (``area_subgrade``, ``area_slab``, ``area_ell``; on springs corrected to the
    panel's size, ``area_slab_size`` m, by Crovetti's factors, None where uncorrected; the
    infinite slab's reading in ``meta``'s drops), ``rms``, ``largest``,
    ``largest_at``, ``solves``, ``converged``, ``termination``, and the basins as NumPy arrays
    ``offsets``, ``measured`` and ``fitted``. ``meta`` holds the rest of backcalc.json, among it ``intercepts`` (the
    intercept method at each station with several loads: ``intercept`` m, ``slope`` m/N,
    ``void``). A fit
    that did not converge raises :class:`NotConverged`, its ``.solution`` the records (the
    best points reached).
    """
    import os

    import numpy as np

    if isinstance(basins, (str, os.PathLike)) and "\n" not in str(basins):
        name = os.fspath(basins)
        try:
            with open(name, encoding="utf-8") as f:
                text = f.read()
        except OSError as e:
            raise LiftoffIOError(f"cannot read basin file {name}: {e.strerror or e}", "io") from None
    else:
        name, text = "basins", str(basins)
    kind, scene_text = scene_pair(scene)
    spec = {
        "method": method,
        "fit": list(fit),
        "contact": contact,
        "elements": None if elements is None else [int(n) for n in elements],
        "seating": int(seating),
        "static_k_factor": float(static_k_factor),
        "max_evaluations": int(max_evaluations),
        "void_threshold": float(void_threshold),
        "location": location,
        "at": None if at is None else [float(v) for v in at],
        "direction": None if direction is None else float(direction),
    }
    doc = json.loads(_progress.run(_core.backcalc, progress, kind, scene_text,
                                   options_json(None, {}), text, name, json.dumps(spec)))
    rows = []
    for d in doc.pop("drops"):
        row: Dict[str, Any] = {k: d[k] for k in ("station", "drop", "location", "load", "static_k")}
        f, a = d.get("fit"), d.get("area")
        for what in ("subgrade", "slab", "void", "joint"):
            value = low = high = None
            if f is not None:
                e = next((e for e in f["estimates"] if e["unknown"] == what), None)
                if e is not None:
                    value = e["value"]
                    low, high = e["interval"] if e["interval"] else (None, None)
            elif a is not None and what in ("subgrade", "slab"):
                value = a["subgrade_modulus" if what == "subgrade" else "slab_modulus"]
            row[what], row[f"{what}_low"], row[f"{what}_high"] = value, low, high
        ell = f.get("ell") if f else None
        row["ell"] = ell[0] if ell else (a["ell"] if a and f is None else None)
        row["ell_low"], row["ell_high"] = (ell[1] if ell and ell[1] else (None, None))
        t = d.get("load_transfer")
        row["lte"] = t["lte"] if t else None
        row["bending"] = t["bending"] if t else None
        row["lte_corrected"] = t["corrected"] if t else None
        row["lte_model"] = t["model"] if t else None
        row["area_subgrade"] = a["subgrade_modulus"] if a else None
        row["area_slab"] = a["slab_modulus"] if a else None
        row["area_ell"] = a["ell"] if a else None
        row["area_slab_size"] = a["finite"]["size"] if a and a.get("finite") else None
        if f is not None:
            row.update(rms=f["rms"], largest=f["largest"][0], largest_at=f["largest"][1],
                       solves=f["solves"], converged=f["converged"],
                       termination=f["termination"], offsets=np.array(f["offsets"]),
                       measured=np.array(f["measured"]), fitted=np.array(f["fitted"]))
        else:
            row.update(rms=None, largest=None, largest_at=None, solves=0,
                       converged=a is not None, termination="area", offsets=None,
                       measured=None, fitted=None)
        rows.append(row)
    result = Records(rows, doc)
    if not doc.get("complete", True):
        raise NotConverged(
            f"{len(doc['not_converged'])} fit(s) did not converge ({'; '.join(doc['not_converged'])}):"
            " their rows show the best point reached, not a result",
            solution=result,
        )
    return result


def grid(base: Scene, axes: Mapping[str, Sequence[Any]]) -> Grid:
    """Scenes for :func:`sweep`: ``base`` with dotted keys varied over value lists, e.g.
    ``grid("example:slab-on-grade", {"plate.thickness": [0.15, 0.2], "foundation.modulus":
    [2e7, 5e7]})`` — every combination, each row of the sweep carrying its parameters."""
    return make_grid(base, axes)


def sweep(
    scenes_or_grid: Union[Iterable[Scene], Grid],
    method: Optional[str] = None,
    *,
    client: Any = None,
    workers: Optional[int] = None,
    progress: Any = None,
    **options: Any,
) -> Records:
    """Solve many independent scenes: a list of scenes, or a :func:`grid`.

    Runs on a local process pool (``workers`` processes, default: the CPU count) or, given a
    ``dask.distributed.Client``, on its cluster (``pip install liftoff[dask]``; dask is imported
    only by you). One record per scene in input order — per combination, named by
    ``combination``, for a scene with combinations: its parameters, ``ok``, ``error`` and
    ``error_kind`` (a failed case is a row, never a lost sweep), the summary's scalars
    (V_max, contact_fraction, w_max, pressure_max, status, iterations, …), the surface stresses
    ``s1_bottom`` and ``s1_top`` (each face's largest principal stress, tension positive; None
    where a face has none) with where they act (``s1_bottom_x``, ``s1_bottom_y``, …), and
    ``units``: the values are in the scene's system (``si``, ``us`` or ``dimensionless``).
    ``progress``: as in :func:`solve`, counting the scenes solved.
    """
    return _run_sweep(
        scenes_or_grid, method, client=client, workers=workers, progress=progress, **options
    )
