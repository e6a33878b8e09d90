"""Keyword values as the DYNA_VIBRA transient reads them: listr8 concepts,
one-element tuples, simple keywords given once or several times."""

from __future__ import annotations

import numpy as np


def list_values(obj) -> np.ndarray:
    """Values of a listr8 concept (or of a plain sequence)."""
    for attr in ("values", "vale", "VALE"):
        if hasattr(obj, attr):
            return np.asarray(getattr(obj, attr), dtype=float)
    return np.asarray(obj, dtype=float)


def first_value(value):
    """A simple keyword given as a one-element tuple (``VITE_MIN=("MAXI",)``)."""
    if isinstance(value, (list, tuple)):
        return value[0] if value else None
    return value
