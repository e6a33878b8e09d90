"""Named local quantities of a shock read from the archive when first asked.

The compiled loop archives every shock's internal variables as rows of
one (n_archived, n_shocks, width) array. A ``ShockHistory`` names 36
columns of it (FN, VT1, ..., VINT20); copying each to a contiguous array
as the result is built cost as much as the time loop itself on long runs
(86 MB copied for 10^5 archived instants of three shocks), while a deck
reads a few of them. :class:`ArchivedFields` keeps the recipe of each
column and copies it on first read: same names, same order, same arrays.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, MutableMapping

import numpy as np


class ArchivedFields(MutableMapping):
    """A ``dict`` of named arrays whose values are made on first access by
    their recipe (a function of no argument) and kept as contiguous copies.
    Assignment and deletion behave as on a ``dict``."""

    def __init__(self, recipes: dict[str, Callable[[], np.ndarray]]) -> None:
        self._recipes = dict(recipes)
        self._values: dict[str, np.ndarray] = {}

    def __getitem__(self, name: str) -> np.ndarray:
        try:
            return self._values[name]
        except KeyError:
            recipe = self._recipes[name]  # KeyError for an unknown name, as a dict
        value = self._values[name] = np.ascontiguousarray(recipe())
        return value

    def __setitem__(self, name: str, value) -> None:
        self._recipes[name] = _constant(value)
        self._values[name] = value

    def __delitem__(self, name: str) -> None:
        del self._recipes[name]
        self._values.pop(name, None)

    def __iter__(self) -> Iterator[str]:
        return iter(self._recipes)

    def __len__(self) -> int:
        return len(self._recipes)

    def __contains__(self, name) -> bool:
        return name in self._recipes

    def __repr__(self) -> str:
        return f"ArchivedFields({list(self._recipes)})"


def _constant(value):
    return lambda: value


def column(values: np.ndarray, j: int) -> Callable[[], np.ndarray]:
    """The recipe of column ``j`` of a (n_archived, width) block."""
    return lambda: values[:, j]


def column_difference(values: np.ndarray, j: int, k: int | None) -> Callable[[], np.ndarray]:
    """The recipe of column j minus column k (column j alone when k is None),
    computed as ``values[:, j] - (values[:, k] if k else 0.0)``."""
    if k is None:
        return lambda: values[:, j] - 0.0
    return lambda: values[:, j] - values[:, k]
