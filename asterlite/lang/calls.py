"""Helpers of calls in the evaluator: binding a deck function's arguments,
and looking for Unknown inside the arguments of a Python callable."""

from __future__ import annotations

import itertools

from asterlite.errors import DeckRuntimeError
from asterlite.lang import limits as guards
from asterlite.lang.values import Unknown


def bind_arguments(function, args: list, kwargs: dict) -> dict:
    """A deck function's local names from a call's arguments and its defaults."""
    parameters = function.parameters
    if len(args) > len(parameters):
        raise DeckRuntimeError(
            f"{function.name}() takes {len(parameters)} arguments but {len(args)} were given"
        )
    bound = dict(zip(parameters, args, strict=False))
    for name, value in kwargs.items():
        if name not in parameters:
            raise DeckRuntimeError(f"{function.name}() got an unexpected keyword '{name}'")
        if name in bound:
            raise DeckRuntimeError(f"{function.name}() got two values for '{name}'")
        bound[name] = value
    for name in parameters:
        if name not in bound:
            if name not in function.defaults:
                raise DeckRuntimeError(f"{function.name}() missing argument '{name}'")
            bound[name] = function.defaults[name]
    return bound


# ------------------------------------------------------------- names


def contains_unknown(values, budget: int) -> bool:
    """Whether Unknown appears in values, inside lists, tuples, sets, dicts or object arrays."""
    np = guards.numpy_or_none()
    pending = list(values)
    while pending and budget > 0:
        value = pending.pop()
        budget -= 1
        if value is Unknown:
            return True
        if isinstance(value, (list, tuple, set, frozenset)):
            pending.extend(itertools.islice(value, budget))
        elif isinstance(value, dict):
            pending.extend(itertools.islice(value.values(), budget))
        elif np is not None and isinstance(value, np.ndarray) and value.dtype == object:
            pending.extend(itertools.islice(value.flat, budget))
    return False
