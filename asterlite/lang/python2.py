"""What Python 2 meant, for decks of code_aster 13 and older.

The parser reads such decks' Python 2 syntax (:mod:`asterlite.lang.parser`);
this module gives the evaluator Python 2's meaning where it differs from
Python 3 in ways decks rely on:

- ``/`` of two integers is their floor division (``1/2 == 0``), unless the
  deck imports ``division`` from ``__future__``; numpy integer arrays alike;
- ``map``, ``zip``, ``filter`` and ``range`` give lists, ``xrange``,
  ``unicode``, ``long``, ``reduce`` and ``cmp`` exist;
- ``dict.keys()``, ``values()`` and ``items()`` give lists, ``has_key``
  and the ``iter*`` methods exist.

Every list is read within the evaluator's element limit.
"""

from __future__ import annotations

import functools
import numbers
import operator

from asterlite.errors import DeckRuntimeError
from asterlite.lang import limits as guards
from asterlite.lang.limits import Limits


def _integral(value) -> bool:
    if isinstance(value, numbers.Integral):  # int, bool, numpy integer scalars
        return True
    np = guards.numpy_or_none()
    return np is not None and isinstance(value, np.ndarray) and value.dtype.kind in "iub"


def classic_divide(left, right):
    """Python 2's ``/``."""
    if _integral(left) and _integral(right):
        return operator.floordiv(left, right)
    return operator.truediv(left, right)


def classic_divide_inplace(left, right):
    """Python 2's ``/=``."""
    if _integral(left) and _integral(right):
        return operator.ifloordiv(left, right)
    return operator.itruediv(left, right)


def builtins(namespace: dict, limits: Limits) -> dict:
    """Python 2's versions of the builtins of ``namespace`` that changed."""
    room = limits.max_sequence_length

    def as_list(function, name):
        def listed(*args, **kwargs):
            return guards.bounded_items(function(*args, **kwargs), room, limits)

        listed.__name__ = name
        return listed

    def deck_filter(function, iterable):
        items = guards.bounded_items(iterable, room, limits)
        if function is None:
            return [item for item in items if item]
        return [item for item in items if function(item)]

    def deck_reduce(function, iterable, *initial):
        return functools.reduce(function, guards.bounded_items(iterable, room, limits), *initial)

    def deck_cmp(left, right):
        return (left > right) - (left < right)

    deck_filter.__name__, deck_reduce.__name__, deck_cmp.__name__ = "filter", "reduce", "cmp"
    found = {
        "map": as_list(namespace.get("map", map), "map"),
        "zip": as_list(namespace.get("zip", zip), "zip"),
        "filter": deck_filter,
        "reduce": deck_reduce,
        "cmp": deck_cmp,
    }
    if "range" in namespace:
        found["range"] = as_list(namespace["range"], "range")
        found["xrange"] = namespace["range"]
    found["unicode"] = namespace.get("str", str)
    found["long"] = namespace.get("int", int)
    return found


DICT_METHODS = frozenset(
    {"keys", "values", "items", "has_key", "iteritems", "iterkeys", "itervalues"}
)


def dict_method(mapping: dict, name: str, limits: Limits):
    """A method of a dict as Python 2 had it."""
    if name == "has_key":

        def has_key(key):
            guards.check_hash_depth(key, limits)
            return key in mapping

        return has_key
    if name in ("keys", "values", "items"):
        return lambda: list(getattr(mapping, name)())
    if name in ("iteritems", "iterkeys", "itervalues"):
        method = getattr(mapping, name[4:])
        return lambda: iter(method())
    raise DeckRuntimeError(f"'dict' object has no attribute '{name}' usable in decks")
