"""Exceptions raised by liftoff: one class per kind of library error.

Every exception carries the library's message (``str(e)``), its typed ``kind`` (``"invalid"``,
``"too-large"``, ``"infeasible"``, ``"numerical"``, ``"io"``, or ``"not-converged"``) and, for a
bad scene value, the ``field`` it names (``"plate.thickness"``, ``"load[2].x"``).
"""

from __future__ import annotations

from typing import Any, Optional


class LiftoffError(Exception):
    """Base class of every liftoff error."""

    def __init__(self, message: str, kind: str = "error", field: Optional[str] = None):
        super().__init__(message)
        self.message = message
        self.kind = kind
        self.field = field

    def __reduce__(self):  # picklable across processes (Dask workers)
        return (type(self), (self.message, self.kind, self.field))


class SceneError(LiftoffError, ValueError):
    """A scene value is missing, out of range or inconsistent (``field`` names it)."""


class TooLarge(LiftoffError, MemoryError):
    """The problem would need more memory than allowed; the message says how to make it fit."""


class Infeasible(LiftoffError):
    """No equilibrium is possible with this contact law (e.g. a net upward load, unbonded)."""


class NumericalError(LiftoffError, ArithmeticError):
    """A factorisation or a solver failed."""


class LiftoffIOError(LiftoffError, OSError):
    """A scene file could not be read."""


class NotConverged(LiftoffError):
    """The method stopped without a solution. ``solution`` holds what it reached (not an
    answer: inspect ``solution.status`` and ``solution.history``)."""

    def __init__(self, message: str, kind: str = "not-converged", field: Optional[str] = None,
                 solution: Any = None):
        super().__init__(message, kind, field)
        self.solution = solution

    def __reduce__(self):
        return (type(self), (self.message, self.kind, self.field, self.solution))


__all__ = [
    "LiftoffError",
    "SceneError",
    "TooLarge",
    "Infeasible",
    "NumericalError",
    "LiftoffIOError",
    "NotConverged",
]
