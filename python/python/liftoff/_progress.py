"""Progress of long runs, as the command line shows it: the compiled core reports events
``(kind, done, total, label)`` — ``kind`` "case" for a run over several cases (a study's
solves, the combinations), or the name of an iteration ("penalty step", "active-set face
solve") with its number and the points that changed — and this module turns the ``progress``
argument of the public functions into the callable that receives them."""

from __future__ import annotations

import sys
import time
from typing import Any, Callable, Optional

Callback = Callable[[str, int, int, str], Any]


#: A run shorter than this draws no bar at all (no flash on a quick solve), seconds.
QUIET = 0.5


class Bar:
    """A one-line bar on stderr, redrawn at most ten times a second: ``12/40 [#####     ]
    1.3 s  label``; iteration events show as the label of the current case. Nothing is drawn
    before the run has taken :data:`QUIET` seconds."""

    def __init__(self, stream=None):
        self.stream = stream or sys.stderr
        self.start = time.monotonic()
        self.last = 0.0
        self.done = 0
        self.total = 0
        self.label = ""
        self.drawn = False

    def __call__(self, kind: str, done: int, total: int, label: str) -> None:
        if kind == "case":
            self.done, self.total, self.label = done, total, label
        else:
            self.label = f"{kind} {done} ({total} changed)"
        now = time.monotonic()
        if now - self.start < QUIET:
            return
        if now - self.last < 0.1 and not (kind == "case" and done == total):
            return
        self.last = now
        elapsed = now - self.start
        if self.total:
            filled = int(30 * self.done / max(self.total, 1))
            head = f"{self.done}/{self.total} [{'#' * filled}{' ' * (30 - filled)}]"
        else:
            head = "…"
        line = f"\r{head} {elapsed:6.1f} s  {self.label}"[:160]
        self.stream.write(line.ljust(100))
        self.stream.flush()
        self.drawn = True

    def close(self) -> None:
        if self.drawn:
            self.stream.write("\r" + " " * 160 + "\r")
            self.stream.flush()


def callback(progress: Any) -> Optional[Callback]:
    """The callable for ``progress``: None shows the bar when stderr is a terminal (as the
    command line does), True always, False never; a callable receives every event."""
    if progress is None:
        progress = hasattr(sys.stderr, "isatty") and sys.stderr.isatty()
    if progress is True:
        return Bar()
    if progress is False:
        return None
    if callable(progress):
        return progress
    raise TypeError(f"progress is None, True, False or a callable, not {type(progress).__name__}")


def run(core_call: Callable[..., Any], progress: Any, *args: Any) -> Any:
    """Call the compiled core with the progress callable as its last argument, closing a bar."""
    cb = callback(progress)
    try:
        return core_call(*args, cb)
    finally:
        if isinstance(cb, Bar):
            cb.close()
