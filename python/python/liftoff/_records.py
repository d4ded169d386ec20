"""Tables of the studies and sweeps: lists of records, and pandas DataFrames on request."""

from __future__ import annotations

from typing import Any, Dict, Iterable, Optional


class Records(list):
    """A list of dicts (one per row), with the study's own facts in ``meta`` and
    :meth:`to_pandas` for a DataFrame (pandas is optional: only this method imports it)."""

    def __init__(self, rows: Iterable[Dict[str, Any]] = (), meta: Optional[Dict[str, Any]] = None):
        super().__init__(rows)
        self.meta: Dict[str, Any] = dict(meta or {})

    def to_pandas(self):
        """The rows as a ``pandas.DataFrame`` (needs ``pip install pandas``)."""
        try:
            import pandas as pd
        except ImportError as e:  # pragma: no cover - depends on the environment
            raise ImportError("Records.to_pandas needs pandas: pip install pandas") from e
        return pd.DataFrame(list(self))

    def __reduce__(self):
        return (Records, (list(self), self.meta))
