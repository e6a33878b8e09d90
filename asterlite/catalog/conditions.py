"""Conditions of ``BLOC``s: predicates over the keyword values of one level.

A condition reads the values at its own level after defaults are applied
(simple keywords are scalars or tuples there). Like code_aster, ``equal_to``
and ``is_in`` hold when any value of the keyword is among the given values.
Conditions combine with ``&``, ``|`` and ``~`` and describe themselves in
deck syntax for messages ("only with TYPE='CERCLE'").

Under ``asterlite check`` a keyword may hold ``Unknown``; a condition that
depends on it is undetermined (``evaluate`` gives None, three-valued logic)
so the validator can accept the block's keywords without requiring them.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from asterlite.lang.values import Unknown


class Condition:
    """A predicate over a mapping of keyword values, with a readable text."""

    def __init__(self, test: Callable[[Mapping], bool | None], text: str):
        self._test = test
        self.text = text

    def evaluate(self, values: Mapping) -> bool | None:
        """True, False, or None when an ``Unknown`` value makes it undecidable."""
        try:
            state = self._test(values)
        except (TypeError, ValueError, KeyError, IndexError, AttributeError):
            return False  # as in code_aster: a condition that cannot be evaluated is false
        if state is None or state is Unknown:  # e.g. a custom test comparing an Unknown
            return None
        return bool(state)

    def __call__(self, values: Mapping) -> bool:
        return bool(self.evaluate(values))

    def __and__(self, other: Condition) -> Condition:
        text = f"({self} and {other})"
        return Condition(lambda v: _and(self.evaluate(v), other.evaluate(v)), text)

    def __or__(self, other: Condition) -> Condition:
        text = f"({self} or {other})"
        return Condition(lambda v: _or(self.evaluate(v), other.evaluate(v)), text)

    def __invert__(self) -> Condition:
        return Condition(lambda v: _not(self.evaluate(v)), f"not {self.text}")

    def __str__(self) -> str:
        return self.text

    def __repr__(self) -> str:
        return f"Condition({self.text})"


def _and(a: bool | None, b: bool | None) -> bool | None:
    if a is False or b is False:
        return False
    return None if a is None or b is None else True


def _or(a: bool | None, b: bool | None) -> bool | None:
    if a is True or b is True:
        return True
    return None if a is None or b is None else False


def _not(a: bool | None) -> bool | None:
    return None if a is None else not a


def _is_unknown(value) -> bool:
    if isinstance(value, (list, tuple)):
        return any(v is Unknown for v in value)
    return value is Unknown


def _values_of(value) -> tuple:
    """A keyword value as a tuple of its values (scalars become 1-tuples)."""
    if value is None:
        return ()
    if isinstance(value, (list, tuple)):
        return tuple(value)
    return (value,)


def _present(values: Mapping, name: str) -> bool:
    return values.get(name) is not None


def _show(values: tuple) -> str:
    return repr(values[0]) if len(values) == 1 else "(" + ", ".join(map(repr, values)) + ")"


def is_in(name: str, values) -> Condition:
    """True when some value of keyword ``name`` is one of ``values``."""
    allowed = _values_of(values)

    def test(level: Mapping) -> bool | None:
        value = level.get(name)
        if any(_hashable_in(v, allowed) for v in _values_of(value)):
            return True
        return None if _is_unknown(value) else False

    text = f"{name}={_show(allowed)}" if len(allowed) == 1 else f"{name} in {_show(allowed)}"
    return Condition(test, text)


def _hashable_in(value, allowed: tuple) -> bool:
    try:
        return value in allowed
    except Exception:  # an exotic value whose comparison fails is simply not equal
        return False


def equal_to(name: str, *values) -> Condition:
    """True when (some value of) keyword ``name`` equals one of ``values``."""
    if len(values) == 1 and isinstance(values[0], (list, tuple)):
        values = tuple(values[0])
    return is_in(name, values)


def exists(name: str) -> Condition:
    """True when keyword ``name`` is given (or defaulted) at this level."""
    return Condition(lambda level: _present(level, name), f"{name} given")


def absent(name: str) -> Condition:
    """True when keyword ``name`` is not given at this level."""
    return Condition(lambda level: not _present(level, name), f"{name} absent")


def _compare(name: str, bound, op: Callable, symbol: str) -> Condition:
    def test(level: Mapping) -> bool | None:
        value = level.get(name)
        if value is Unknown:
            return None
        if value is None or isinstance(value, (list, tuple)):
            return False
        try:
            return op(value, bound)
        except TypeError:  # Unknown or text against a number: condition not met
            return False

    return Condition(test, f"{name}{symbol}{bound!r}")


def greater_than(name: str, bound) -> Condition:
    """True when the value of keyword ``name`` is greater than ``bound``."""
    return _compare(name, bound, lambda a, b: a > b, ">")


def less_than(name: str, bound) -> Condition:
    """True when the value of keyword ``name`` is less than ``bound``."""
    return _compare(name, bound, lambda a, b: a < b, "<")
