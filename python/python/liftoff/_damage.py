"""Fatigue damage over a scene's traffic and climate (``liftoff damage``): the damage maps of
both faces as NumPy arrays, one record per pass, the run's facts as attributes."""

from __future__ import annotations

import json
from typing import Any, Dict, List, Optional

import numpy as np

from ._records import Records

#: The per-element arrays, shape (ny, nx): element ie + je·nx is row je, column ie.
ARRAYS = ("x", "y", "bottom", "top")


def _pass_row(p: Dict[str, Any]) -> Dict[str, Any]:
    """A pass of damage.json as a row of passes.csv (the same names, the same units), with its
    positions added."""
    row = {k: p[k] for k in ("group", "load", "offset", "difference", "repetitions", "outcome",
                             "solves", "interpolated", "mirrored")}
    for face in ("bottom", "top"):
        peak = p[face]
        row[face] = peak["stress"]
        row[face + "_x"] = peak["x"]
        row[face + "_y"] = peak["y"]
        row[face + "_allowed"] = peak["allowed"]
    row["bottom_share"] = p["bottom_share"]
    row["top_share"] = p["top_share"]
    erosion = p.get("erosion") or {}
    for key in ("deflection", "x", "y", "allowed", "share"):
        row["erosion_" + key] = erosion.get(key)
    row["positions"] = [list(xy) for xy in p["positions"]]
    return row


class Damage:
    """The Miner sum of fatigue damage over a scene's ``[traffic]`` and ``[climate]``
    (``liftoff damage``; README "Damage over traffic and climate"). Lengths, stresses, loads and
    temperature differences are in the scene's unit system (``units``: ``"si"`` or ``"us"``),
    as in damage.json, damage.csv and passes.csv; damage is a pure number.

    - arrays of shape ``(ny, nx)`` over the elements (row je, column ie; damage.csv's rows in
      order): ``bottom`` and ``top`` — Σ n/N at the bottom face (bottom-up) and the top face
      (top-down) —, ``x``, ``y``, the element centres, and ``counted`` (bool: the elements
      the governing places, the cracking and a design take; False in the end panels of a lane
      the model cuts, ``[traffic] ends``);
    - ``passes``: :class:`Records`, one per case (a group at a level, at a lateral position, in
      a climate bin), with passes.csv's columns — ``group``, ``load``, ``offset``,
      ``difference`` (None without ``[climate]``), ``repetitions``, ``outcome``, ``solves``,
      ``interpolated`` (positions filled exactly from the end levels), ``mirrored``
      (positions read off their mirror images in a pass symmetric on a symmetric plate),
      ``bottom``/``top``
      (the pass's largest σ₁ of that face), ``bottom_x``, ``bottom_y``,
      ``bottom_allowed`` (N there; None: unlimited), the same for ``top``, ``bottom_share``,
      ``top_share`` (its Σ n/N at the governing element), ``erosion_deflection``,
      ``erosion_x``, ``erosion_y``, ``erosion_allowed``, ``erosion_share`` (the PCA's erosion:
      the largest corner deflection the pass caused, where, N there and its C2·n/N at the
      governing corner; None for the other relations) — and ``positions`` (the group's
      reference point at each position of the pass). A pass that did not converge has None
      for its stresses and places, as damage.json's null; ``passes.meta`` is ``summary``;
    - every other key of damage.json is an attribute: ``model`` (``"pca"``, ``"mepdg"``,
      ``"faa"``), ``rupture``, ``life_factor``, ``elements`` ([nx, ny]),
      ``governing_bottom`` / ``governing_top`` (dicts: ``damage``, ``x``, ``y``,
      ``element`` = ie + je·nx), ``cracking`` (the MEPDG's, a dict of ``bottom``, ``top``,
      ``total``, ``at_reliability`` in %; None for the other relations), ``erosion`` (the
      PCA's: ``k``, ``c1``, ``c2``, ``corners`` — each panel corner's ``panel``, ``x``, ``y``,
      ``thickness``, ``deflection``, ``damage`` and ``counted`` (false at the plate's ends
      on a plate with transverse joints, unless ``[traffic] ends = "free"``) — and ``governing``, the
      index of the largest counted corner; None for the other relations), ``erosion_note`` (why a PCA run has none),
      ``complete``,
      ``missing`` (the passes that did not converge, by label), ``solves``, ``interpolated``,
      ``mirrored``, ``assemble_s``,
      ``total_s``, ``units``. ``summary`` is that whole dict.
    """

    x: np.ndarray
    y: np.ndarray
    bottom: np.ndarray
    top: np.ndarray

    def __init__(self, doc: Dict[str, Any], maps: Dict[str, Any]):
        doc = dict(doc)
        rows = [_pass_row(p) for p in doc.pop("passes", [])]
        self.summary: Dict[str, Any] = doc
        self.passes = Records(rows, doc)
        shape = tuple(maps["shape"])
        for name in ARRAYS:
            a = np.frombuffer(maps[name], dtype="<f8").copy()
            setattr(self, name, a.reshape(shape) if a.size == shape[0] * shape[1] else a)
        c = np.frombuffer(maps["counted"], dtype=np.uint8).astype(bool)
        self.counted: np.ndarray = c.reshape(shape) if c.size == shape[0] * shape[1] else c
        self.model: str = doc.get("model", "")
        self.complete: bool = bool(doc.get("complete"))
        self.missing: List[str] = list(doc.get("missing", []))
        self.cracking: Optional[Dict[str, Any]] = doc.get("cracking")
        for key, value in doc.items():
            if not hasattr(self, key):
                setattr(self, key, value)

    @property
    def arrays(self) -> Dict[str, np.ndarray]:
        """The four arrays by name."""
        return {n: getattr(self, n) for n in ARRAYS}

    def __repr__(self) -> str:
        gb, gt = self.summary.get("governing_bottom", {}), self.summary.get("governing_top", {})
        return (
            f"<liftoff.Damage {self.model}: {len(self.passes)} passes"
            f"{'' if self.complete else f' ({len(self.missing)} missing: INCOMPLETE)'}, "
            f"bottom-up {gb.get('damage', float('nan')):.4g}, "
            f"top-down {gt.get('damage', float('nan')):.4g}>"
        )


def from_core(doc_json: str, maps: Dict[str, Any]) -> Damage:
    """A Damage from the compiled core's answer."""
    return Damage(json.loads(doc_json), maps)
