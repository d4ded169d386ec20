"""Scenes and options as the compiled core takes them: (kind, text) pairs and a JSON object."""

from __future__ import annotations

import json
import os
from typing import Any, Dict, Mapping, Optional, Sequence, Tuple, Union

from . import _liftoff as _core
from .errors import LiftoffIOError, SceneError

Scene = Union[str, "os.PathLike[str]", Mapping[str, Any]]

#: Options accepted by ``solve`` and the studies, as the CLI's flags (``qp_form`` ↔
#: ``--qp-form``): the library's one list (``method`` is also the ``method`` argument).
OPTIONS = tuple(o for o in _core.options() if o != "method")


def scene_pair(scene: Scene) -> Tuple[str, str]:
    """``("example", name)``, ``("json", text)`` or ``("toml", text)`` for any scene form: a
    bundled example (``"example:NAME"``), a dict with the scene file's keys, a path to a
    ``.toml`` file, or TOML text."""
    if isinstance(scene, Mapping):
        return "json", json.dumps(scene)
    if isinstance(scene, os.PathLike):
        scene = os.fspath(scene)
    if not isinstance(scene, str):
        raise SceneError(
            f"a scene is a path, TOML text, 'example:NAME' or a dict, not {type(scene).__name__}",
            "invalid",
            "scene",
        )
    if scene.startswith("example:"):
        return "example", scene[len("example:"):]
    # A file that exists is a path whatever its name; text with a line break or a key = value
    # is TOML; anything else is a path that must be readable.
    if ("\n" in scene or "=" in scene) and not os.path.isfile(scene):
        return "toml", scene
    try:
        with open(scene, encoding="utf-8") as f:
            return "toml", f.read()
    except OSError as e:
        raise LiftoffIOError(f"cannot read scene file {scene}: {e.strerror or e}", "io") from None


def options_json(method: Optional[str], options: Mapping[str, Any]) -> str:
    """The JSON object of the library's ``Overrides``: the CLI's options by name. ``method``
    ``"bonded"`` sets bonded contact; ``"penalty"``/``"qp"`` the unbonded method."""
    unknown = sorted(set(options) - set(OPTIONS))
    if unknown:
        raise SceneError(
            f"unknown option(s) {', '.join(unknown)}; the options are: method, {', '.join(OPTIONS)}",
            "invalid",
            "options",
        )
    out: Dict[str, Any] = {k: v for k, v in options.items() if v is not None}
    if method is not None:
        if method == "bonded":
            out.setdefault("contact", "bonded")
        elif method in ("penalty", "qp"):
            out["method"] = method
            out.setdefault("contact", "unbonded")
        else:
            raise SceneError(
                f"method {method!r} is not one of 'penalty', 'qp', 'bonded'", "invalid", "method"
            )
    mesh = out.get("mesh")
    if isinstance(mesh, int):
        out["mesh"] = [mesh, mesh]
    elif isinstance(mesh, Sequence) and not isinstance(mesh, str):
        out["mesh"] = list(mesh)
    return json.dumps(out)
