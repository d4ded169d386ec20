"""Solutions as NumPy arrays over the whole plate, with the summary as plain attributes."""

from __future__ import annotations

import json
from typing import Any, Dict, List, Optional

import numpy as np

#: Nodal fields, each an array of shape (ny + 1, nx + 1) over the whole plate (row j is y_j).
NODAL = ("x", "y", "s", "t", "w", "psi_x", "psi_y", "pressure", "gap", "V", "sigma",
         "s1_bottom_nodes", "s1_top_nodes", "contact")
#: Element-centre fields, each of shape (ny, nx).
ELEMENT = ("element_x", "element_y", "mx", "my", "mxy", "qx", "qy", "sx_bottom", "sy_bottom",
           "sxy_bottom", "s1_bottom", "s2_bottom", "angle_bottom", "sx_top", "sy_top", "sxy_top",
           "s1_top", "s2_top", "angle_top")


#: The extra node copies along the joints that cut a jointed plate (1-D arrays, one entry each).
JOINT_NODES = ("i", "j", "panel", "w", "psi_x", "psi_y", "pressure", "gap")
#: The dowel bars of a jointed plate (1-D arrays, one entry per bar; the rows of dowels.csv).
DOWELS = ("joint", "bar", "x", "y", "jump", "force", "bearing_stress")


def _array(raw: bytes, shape: Optional[tuple]) -> np.ndarray:
    a = np.frombuffer(raw, dtype="<f8").copy()
    return a.reshape(shape) if shape is not None and a.size == shape[0] * shape[1] else a


def _grid(raw: bytes, shape: tuple) -> np.ndarray:
    """A per-node array over every node copy, cut to the grid nodes (the first
    (ny + 1)(nx + 1) entries: on a joint, the lower / left copy) and shaped as the grid."""
    a = np.frombuffer(raw, dtype="<f8").copy()
    n = shape[0] * shape[1]
    return a[:n].reshape(shape) if a.size >= n else a


class Solution:
    """One solved scene (or one load combination).

    Arrays over the whole plate, physical units for SI scenes (m, Pa, N·m/m) and the paper's
    for dimensionless ones, as in ``nodes.csv`` / ``elements.csv``:

    - nodal, shape ``(ny + 1, nx + 1)``: ``x``, ``y`` (coordinates), ``s``, ``t`` (x/L, y/μL),
      ``w`` (deflection, downward), ``psi_x``, ``psi_y`` (rotations), ``pressure`` (contact
      pressure, compression positive), ``gap`` (≥ 0 where the plate lifted), ``V`` and
      ``sigma`` (the paper's dimensionless deflection and pressure), ``s1_bottom_nodes``,
      ``s1_top_nodes`` (the faces' largest principal stress recovered at the nodes),
      ``contact`` (bool);
    - element centres, shape ``(ny, nx)``: ``element_x``, ``element_y``, ``mx``, ``my``,
      ``mxy`` (moments per unit length, positive: tension on the soil side), ``qx``, ``qy``,
      and the surface stresses of the bottom and top faces (σ = ±6m/H² plus a nonlinear
      temperature profile's own stress; tension positive): ``sx_bottom``, ``sy_bottom``,
      ``sxy_bottom``, ``s1_bottom``, ``s2_bottom`` (principal), ``angle_bottom`` (direction of
      σ₁ from x, degrees), and the same ``…_top``. On a plate with panels each element's
      moments and stresses are its own panel's (σ = ±6m/H_p²).

    On a plate of another outline (``[plate] outline``, ``[[opening]]``) the arrays cover its
    bounding rectangle: ``plate_nodes`` (shape ``(ny + 1, nx + 1)``) and ``plate_cells``
    (``(ny, nx)``) are True on the plate, and every value off it is NaN (its coordinates
    stay), so that ``np.nanmax`` and plotting skip the openings.

    On a jointed plate (``[[joint]]``) the nodal arrays above hold one copy of each node: on a
    joint line the copy of the lower / left side. The other copies are in

    - ``joint_nodes``: a dict of 1-D arrays over the extra copies — grid position ``i``, ``j``
      (column and row of the nodal arrays), ``panel`` (column + row · columns), ``w``,
      ``psi_x``, ``psi_y``, ``pressure``, ``gap``; the same copies as nodes.csv's rows after the
      grid's (empty arrays without joints);
    - ``joints``: the summary's list of joints (dicts: ``name``, ``kind``, ``axis``, ``line``,
      ``lte_deflection``, ``lte_stress``, ``at``, ``loaded_side``, ``transferred_force``,
      ``max_shear_per_length``, ``max_moment_per_length``, ``max_dowel_force``,
      ``max_bearing_stress``; empty without joints);
    - ``dowels``: a dict of 1-D arrays, one entry per bar — ``joint`` (index into ``joints``),
      ``bar``, ``x``, ``y``, ``jump``, ``force``, ``bearing_stress`` (NaN where the bar's
      properties are not given): dowels.csv.

    Every key of the summary (``liftoff solve --json``; README "summary.json") is an attribute:
    ``V_max``, ``V_center``, ``V_corner``, ``w_max``, ``pressure_max``, ``contact_fraction``,
    ``contact_radius``, ``contact_extent``, ``converged``, ``status``, ``iterations``,
    ``time_s``, ``method``, ``qp_solver``, ``solver_info``, ``dimensionless``, … ``summary`` is
    the whole dict. (One key is shadowed: ``contact`` is the nodal contact mask; the contact
    law, "bonded" or "unbonded", is ``contact_law``.)
    """

    def __init__(self, summary: Dict[str, Any], fields: Dict[str, Any]):
        self.summary = summary
        shape = tuple(fields.get("shape", ())) or None
        eshape = tuple(fields.get("element_shape", ())) or None
        for name in NODAL:
            setattr(self, name, _array(fields[name], shape))
        self.contact = self.contact.astype(bool)
        for name in ELEMENT:
            setattr(self, name, _array(fields[name], eshape))
        # Which nodes and elements are plate (all of them on a rectangle).
        self.plate_nodes = (_array(fields["plate_nodes"], shape) if "plate_nodes" in fields
                            else np.ones_like(self.w)).astype(bool)
        self.plate_cells = (_array(fields["plate_cells"], eshape) if "plate_cells" in fields
                            else np.ones_like(self.mx)).astype(bool)
        extra = fields.get("joint_nodes") or {}
        self.joint_nodes: Dict[str, np.ndarray] = {
            k: _array(extra[k], None) if k in extra else np.zeros(0) for k in JOINT_NODES}
        for k in ("i", "j", "panel"):
            self.joint_nodes[k] = self.joint_nodes[k].astype(int)
        bars = fields.get("dowels") or {}
        self.dowels: Dict[str, np.ndarray] = {
            k: _array(bars[k], None) if k in bars else np.zeros(0) for k in DOWELS}
        for k in ("joint", "bar"):
            self.dowels[k] = self.dowels[k].astype(int)
        self.joints: List[Dict[str, Any]] = list(summary.get("joints", []))
        self.contact_law = summary.get("contact")
        for key, value in summary.items():
            if not hasattr(self, key):
                setattr(self, key, value)

    @property
    def arrays(self) -> Dict[str, np.ndarray]:
        """Every array by name."""
        return {n: getattr(self, n) for n in NODAL + ELEMENT}

    def to_dict(self) -> Dict[str, Any]:
        """The summary with every array added (NumPy arrays)."""
        out = dict(self.summary)
        out.update(self.arrays)
        return out

    def __repr__(self) -> str:
        return (
            f"<liftoff.Solution {self.summary.get('title')!r}: {self.summary.get('method')}, "
            f"{self.summary.get('status')}, V_max={self.summary.get('V_max'):.6g}, "
            f"contact {100 * self.summary.get('contact_fraction', 0):.1f} %>"
        )


class Combinations:
    """Every load combination of a scene: ``solutions`` (name → :class:`Solution`), ``errors``
    (name → message, for combinations without a solution), ``missing`` (the names of the
    combinations without a converged solution), ``summary`` (the whole ``--json`` document).

    The envelope follows the library's one rule: it exists only when every combination
    converged (an envelope missing a combination is not one); otherwise ``envelope``,
    ``envelope_nodes`` and ``envelope_elements`` are None and ``missing`` says why.

    - ``envelope``: the extremes over the plate, the CLI's ``envelope.json`` (a list of
      quantities with their max and min, where, and the governing combination);
    - ``envelope_nodes`` / ``envelope_elements``: per node (shape ``(ny + 1, nx + 1)``; on a
      jointed plate the lower / left copy of a doubled node, as the nodal arrays) and per
      element (``(ny, nx)``), for each field (nodes: ``w``, ``pressure``, ``uplift``; elements:
      ``mx``, ``my``, ``mxy``, ``qx``, ``qy``) a dict with ``max``, ``min`` (arrays, in
      ``unit``) and ``max_by``, ``min_by`` (arrays of the governing combination's name) — the
      CLI's ``envelope_nodes.csv`` and ``envelope_elements.csv``.
    """

    def __init__(self, doc: Dict[str, Any], fields: List[Any], envelope: Any = None):
        self.summary = doc
        self.solutions: Dict[str, Solution] = {}
        self.errors: Dict[str, str] = {}
        for run, f in zip(doc["combinations"], fields):
            if run.get("summary") is not None and f is not None:
                self.solutions[run["name"]] = Solution(run["summary"], f)
            else:
                self.errors[run["name"]] = run.get("error") or "no solution"
        self.missing: List[str] = list(doc.get("missing", []))
        self.envelope = doc.get("envelope")
        self.envelope_nodes: Optional[Dict[str, Dict[str, Any]]] = None
        self.envelope_elements: Optional[Dict[str, Dict[str, Any]]] = None
        if envelope is not None:
            first = next(iter(self.solutions.values()))
            names = np.array(envelope["names"], dtype=object)
            shapes = {"nodes": first.w.shape, "elements": first.mx.shape}

            def arrays(group: str) -> Dict[str, Dict[str, Any]]:
                out = {}
                for name, f in envelope[group].items():
                    shape = shapes[group]
                    field = {"unit": f["unit"]}
                    # Per node: the grid's copies (envelope_nodes.csv has every copy).
                    cut = _grid if group == "nodes" else _array
                    for key in ("max", "min"):
                        field[key] = cut(f[key], shape)
                        index = cut(f[key + "_by"], shape).astype(int)
                        field[key + "_by"] = names[index]
                    out[name] = field
                return out

            self.envelope_nodes = arrays("nodes")
            self.envelope_elements = arrays("elements")

    @property
    def converged(self) -> bool:
        """True when every combination converged."""
        return not self.errors and all(s.converged for s in self.solutions.values())

    def __getitem__(self, name: str) -> Solution:
        return self.solutions[name]

    def __iter__(self):
        return iter(self.solutions.values())

    def __len__(self) -> int:
        return len(self.solutions) + len(self.errors)

    def __repr__(self) -> str:
        return f"<liftoff.Combinations {list(self.solutions)} errors={list(self.errors)}>"


def from_core(summary_json: str, fields: Any, envelope: Any = None):
    """A Solution or Combinations from the compiled core's answer."""
    doc = json.loads(summary_json)
    if "combinations" in doc:
        return Combinations(doc, fields, envelope)
    return Solution(doc, fields)
