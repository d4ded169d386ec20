"""Many independent solves: a local process pool by default, any ``dask.distributed`` cluster
when a ``Client`` is given. Only dispatch lives here; each case is one call of the library."""

from __future__ import annotations

import concurrent.futures as cf
import copy
import itertools
import json
import multiprocessing
import os
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence

from . import _liftoff as _core
from . import _progress
from ._records import Records
from ._scene import options_json, scene_pair
from .errors import LiftoffError

#: Summary keys a sweep row keeps (scalars; the arrays stay on the worker).
ROW_KEYS = (
    "title",
    "method",
    "qp_solver",
    "converged",
    "status",
    "iterations",
    "V_max",
    "V_center",
    "V_corner",
    "w_max",
    "pressure_max",
    "contact_fraction",
    "contact_radius",
)


class Grid(list):
    """Scenes made from a base scene by varying keys over value lists (the Cartesian product):
    each item is ``(params, scene_dict)``. Made by :func:`liftoff.grid`."""


def set_key(scene: Dict[str, Any], dotted: str, value: Any) -> None:
    """Set ``scene["plate"]["thickness"]`` from ``"plate.thickness"``; ``"load[0].force"``
    indexes a list."""
    node: Any = scene
    parts = dotted.split(".")
    for i, part in enumerate(parts):
        name, _, index = part.partition("[")
        last = i == len(parts) - 1
        if index:
            k = int(index.rstrip("]"))
            seq = node.setdefault(name, [])
            if last:
                seq[k] = value
            else:
                node = seq[k]
        elif last:
            node[name] = value
        else:
            node = node.setdefault(name, {})


def make_grid(base: Any, axes: Mapping[str, Sequence[Any]]) -> Grid:
    """The Cartesian product of ``axes`` (dotted scene keys → values) over ``base``."""
    kind, text = scene_pair(base)
    doc = json.loads(_core.scene_json(kind, text))
    keys = list(axes)
    out = Grid()
    for values in itertools.product(*(axes[k] for k in keys)):
        scene = copy.deepcopy(doc)
        params = dict(zip(keys, values))
        for k, v in params.items():
            set_key(scene, k, v)
        out.append((params, scene))
    return out


#: The surface stresses a sweep row carries, from the summary's ``stresses``: each face's
#: largest principal stress (tension positive) and where, in the scene's units.
STRESS_KEYS = (("s1_bottom", "bottom"), ("s1_top", "top"))


def summary_row(summary: Mapping[str, Any]) -> Dict[str, Any]:
    """The scalars of one solve's summary: :data:`ROW_KEYS`, both faces' largest σ₁ with its
    ``_x``/``_y`` (None where a face has no tension), and ``units`` (the scene's system)."""
    row: Dict[str, Any] = {k: summary.get(k) for k in ROW_KEYS}
    stresses = summary.get("stresses") or {}
    for name, face in STRESS_KEYS:
        peak = stresses.get(face) or {}
        row[name] = peak.get("value")
        row[f"{name}_x"] = peak.get("x")
        row[f"{name}_y"] = peak.get("y")
    row["units"] = (summary.get("units") or {}).get("system")
    converged = bool(summary.get("converged"))
    row.update({"ok": converged, "error": None,
                "error_kind": None if converged else "not-converged"})
    if not converged:
        row["error"] = f"not converged: {summary.get('status')}"
    return row


def run_case(case: Dict[str, Any]) -> List[Dict[str, Any]]:
    """One case's rows: the solve's scalar summary — with combinations a row per combination
    (``combination`` names it; a failed one carries its error) — or its error (never raised)."""
    head: Dict[str, Any] = {"index": case["index"], **case["params"]}
    try:
        doc, _, _ = _core.solve(case["kind"], case["text"], case["options"], None)
        summary = json.loads(doc)
        if "combinations" not in summary:
            return [{**head, **summary_row(summary)}]
        rows = []
        for c in summary["combinations"]:
            row = {**head, "combination": c["name"]}
            if c.get("summary") is not None:
                row.update(summary_row(c["summary"]))
            else:
                row.update({"ok": False, "error": c.get("error"), "error_kind": "combination"})
            rows.append(row)
        return rows
    except LiftoffError as e:
        return [{**head, "ok": False, "error": str(e), "error_kind": e.kind}]
    except Exception as e:  # a bug, not a bad case: keep the sweep, say what happened
        return [{**head, "ok": False, "error": f"{type(e).__name__}: {e}", "error_kind": "internal"}]


def cases(scenes_or_grid: Any, method: Optional[str], options: Mapping[str, Any]) -> List[Dict[str, Any]]:
    """The sweep's cases in input order (scene pairs made here, so bad scenes fail per row)."""
    opts = options_json(method, options)
    items = scenes_or_grid if isinstance(scenes_or_grid, Grid) else [({}, s) for s in scenes_or_grid]
    out = []
    for i, (params, scene) in enumerate(items):
        case: Dict[str, Any] = {"index": i, "params": dict(params), "options": opts}
        try:
            case["kind"], case["text"] = scene_pair(scene)
        except LiftoffError as e:
            case["kind"], case["text"], case["error"] = "", "", e
        out.append(case)
    return out


def run_all(
    fn: Callable[[Any], Any],
    items: List[Any],
    client: Any = None,
    workers: Optional[int] = None,
    report: Optional[Callable[[int, int], Any]] = None,
) -> List[Any]:
    """``[fn(x) for x in items]`` in input order: on a Dask ``client``, else a local process
    pool of ``workers`` processes (default: the CPU count; 1 runs in this process). ``report``
    is called with (done, total) as items finish (per task on Dask)."""
    total = len(items)
    tell = report or (lambda done, total: None)
    if not items:
        return []
    if client is not None:
        # Tasks of several cases each (about four per worker): one scheduler round trip per
        # task, not per case, so short solves are not dominated by it.
        workers_now = max(1, len(client.scheduler_info().get("workers", {})))
        size = max(1, len(items) // (4 * workers_now))
        chunks = [items[i:i + size] for i in range(0, len(items), size)]
        futures = client.map(run_chunk, [fn] * len(chunks), chunks, pure=False)
        out: List[Any] = []
        for f in futures:
            out.extend(f.result())
            tell(len(out), total)
        return out
    n = workers if workers is not None else (os.cpu_count() or 1)
    if n <= 1 or len(items) == 1:
        out = []
        for x in items:
            out.append(fn(x))
            tell(len(out), total)
        return out
    # "spawn": a forked child would inherit the parent's rayon threads in an unknown state.
    ctx = multiprocessing.get_context("spawn")
    with cf.ProcessPoolExecutor(max_workers=min(n, len(items)), mp_context=ctx) as pool:
        futures = {pool.submit(fn, x): k for k, x in enumerate(items)}
        results: List[Any] = [None] * total
        for done, f in enumerate(cf.as_completed(futures), start=1):
            results[futures[f]] = f.result()
            tell(done, total)
        return results


def run_chunk(fn: Callable[[Any], Any], chunk: List[Any]) -> List[Any]:
    """One Dask task: ``fn`` over a chunk of cases, in order."""
    return [fn(x) for x in chunk]


def sweep(
    scenes_or_grid: Any,
    method: Optional[str] = None,
    *,
    client: Any = None,
    workers: Optional[int] = None,
    progress: Any = None,
    **options: Any,
) -> Records:
    """Solve many scenes independently; rows in input order (a row per combination of a
    scene with combinations), a failed case is a row with its error. See
    :func:`liftoff.sweep`."""
    all_cases = cases(scenes_or_grid, method, options)
    good = [c for c in all_cases if "error" not in c]
    cb = _progress.callback(progress)
    report = None
    if cb is not None:
        report = lambda done, total: cb("case", done, total, f"{done} of {total} scenes solved")
    try:
        done = {rows[0]["index"]: rows for rows in run_all(run_case, good, client, workers, report)}
    finally:
        if isinstance(cb, _progress.Bar):
            cb.close()
    rows: List[Dict[str, Any]] = []
    for c in all_cases:
        if "error" in c:
            e = c["error"]
            rows.append({"index": c["index"], **c["params"], "ok": False, "error": str(e),
                         "error_kind": e.kind})
        else:
            rows.extend(done[c["index"]])
    return Records(rows, {"cases": len(all_cases),
                          "failed": sum(not r["ok"] for r in rows)})


def critical_chunk(args: Dict[str, Any]) -> str:
    """One Dask task of a critical-position search: some positions of its grid, as JSON."""
    return _core.critical(args["kind"], args["text"], args["options"], args["critical"])


def damage_chunk(args: Dict[str, Any]) -> bytes:
    """One Dask task of a damage run: the passes of some of its families, as a part's bytes."""
    return _core.damage_part(args["kind"], args["text"], args["options"], args["families"])


def stability_chunk(args: Dict[str, Any]) -> str:
    """One Dask task of the stability study: some runs of its plan, as JSON rows."""
    return _core.stability_rows(args["scenes"], args["options"], args["indices"])
