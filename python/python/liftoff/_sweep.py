"""Many independent solves: a local process pool by default, any ``dask.distributed`` cluster
when a ``Client`` is given. Only dispatch lives here; each case is one call of the library."""

from __future__ import annotations

import concurrent.futures as cf
import copy
import itertools
import multiprocessing
import os
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence

from . import _liftoff as _core
from ._records import Records
from ._scene import options_json, scene_pair
from ._solution import from_core
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
    import json

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


def run_case(case: Dict[str, Any]) -> Dict[str, Any]:
    """One sweep row: the solve's scalar summary, or its error (never raised)."""
    row: Dict[str, Any] = {"index": case["index"], **case["params"]}
    try:
        sol = from_core(*_core.solve(case["kind"], case["text"], case["options"]))
        summary = sol.summary if hasattr(sol, "summary") else {}
        if "combinations" in summary:
            row.update({"ok": sol.converged, "error": None, "error_kind": None,
                        "combinations": len(sol)})
        else:
            row.update({k: summary.get(k) for k in ROW_KEYS})
            row.update({"ok": bool(summary.get("converged")), "error": None,
                        "error_kind": None if summary.get("converged") else "not-converged"})
            if not summary.get("converged"):
                row["error"] = f"not converged: {summary.get('status')}"
    except LiftoffError as e:
        row.update({"ok": False, "error": str(e), "error_kind": e.kind})
    except Exception as e:  # a bug, not a bad case: keep the sweep, say what happened
        row.update({"ok": False, "error": f"{type(e).__name__}: {e}", "error_kind": "internal"})
    return row


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
) -> List[Any]:
    """``[fn(x) for x in items]`` in input order: on a Dask ``client``, else a local process
    pool of ``workers`` processes (default: the CPU count; 1 runs in this process)."""
    if not items:
        return []
    if client is not None:
        # Tasks of several cases each (about four per worker): one scheduler round trip per
        # task, not per case, so short solves are not dominated by it.
        workers_now = max(1, len(client.scheduler_info().get("workers", {})))
        size = max(1, len(items) // (4 * workers_now))
        chunks = [items[i:i + size] for i in range(0, len(items), size)]
        futures = client.map(run_chunk, [fn] * len(chunks), chunks, pure=False)
        return [r for part in client.gather(futures) for r in part]
    n = workers if workers is not None else (os.cpu_count() or 1)
    if n <= 1 or len(items) == 1:
        return [fn(x) for x in items]
    # "spawn": a forked child would inherit the parent's rayon threads in an unknown state.
    ctx = multiprocessing.get_context("spawn")
    with cf.ProcessPoolExecutor(max_workers=min(n, len(items)), mp_context=ctx) as pool:
        return list(pool.map(fn, items))


def run_chunk(fn: Callable[[Any], Any], chunk: List[Any]) -> List[Any]:
    """One Dask task: ``fn`` over a chunk of cases, in order."""
    return [fn(x) for x in chunk]


def sweep(
    scenes_or_grid: Any,
    method: Optional[str] = None,
    *,
    client: Any = None,
    workers: Optional[int] = None,
    **options: Any,
) -> Records:
    """Solve many scenes independently; rows in input order, a failed case is a row with its
    error. See :func:`liftoff.sweep`."""
    all_cases = cases(scenes_or_grid, method, options)
    good = [c for c in all_cases if "error" not in c]
    done = {r["index"]: r for r in run_all(run_case, good, client, workers)}
    rows = []
    for c in all_cases:
        if "error" in c:
            e = c["error"]
            rows.append({"index": c["index"], **c["params"], "ok": False, "error": str(e),
                         "error_kind": e.kind})
        else:
            rows.append(done[c["index"]])
    return Records(rows, {"cases": len(rows), "failed": sum(not r["ok"] for r in rows)})


def critical_chunk(args: Dict[str, Any]) -> str:
    """One Dask task of a critical-position search: some positions of its grid, as JSON."""
    return _core.critical(args["kind"], args["text"], args["options"], args["critical"])


def stability_chunk(args: Dict[str, Any]) -> str:
    """One Dask task of the stability study: some runs of its plan, as JSON rows."""
    return _core.stability_rows(args["scenes"], args["options"], args["indices"])
