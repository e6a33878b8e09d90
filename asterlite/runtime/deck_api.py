"""The few ``code_aster`` Python objects decks import: ``from code_aster
import CA`` (``CA.TestCase`` records its assertions as test checks) and
``import aster`` (``aster.getvectjev`` reads a concept's vector by name)."""

from __future__ import annotations

import cmath
import numbers
from typing import TYPE_CHECKING

from asterlite.lang.library import DeckModule
from asterlite.lang.values import CallSite, DeckCallable
from asterlite.runtime.context import TestRecord

if TYPE_CHECKING:
    from asterlite.runtime.session import Session


class TestCaseRecorder:
    """``CA.TestCase()``: unittest-style assertions recorded as checks.

    Each verdict is code_aster's (its TestCase wraps ``unittest.TestCase``'s
    assertions: ``assertTrue(x)`` holds when ``bool(x)``, ``assertAlmostEqual``
    holds at once when ``first == second``), except that an assertion given a
    non-finite number (NaN, ±inf) is NOOK, saying so: ``bool(nan)`` is True
    in Python, so code_aster reports ``assertTrue(nan)`` as passed.
    """

    deck_methods = frozenset(
        {"assertTrue", "assertFalse", "assertEqual", "assertAlmostEqual", "printSummary"}
    )

    def __init__(self, session: Session):
        self.session = session
        self.count = 0

    def _check(self, label: str, ok: bool, value, expected) -> None:
        """Record code_aster's verdict ``ok`` unless a non-finite number is involved."""
        odd = _non_finite_numbers((value, expected))
        note = ""
        if odd:
            note = f": {odd[0]!r} is not a finite number"
            if ok:
                note += " (code_aster's unittest-based TestCase would count it as passed)"
            ok = False
        self._record(label, ok, value, expected, note)

    def _record(self, label: str, ok: bool, value, expected, note: str = "") -> None:
        self.count += 1
        self.session.record_test(
            TestRecord(
                command="TestCase",
                label=f"{label} #{self.count}",
                value=value,
                expected=expected,
                reference="NON_REGRESSION",
                error=0.0 if ok else 1.0,
                tolerance=0.0,
                criterion="EXACT",
                ok=ok,
                strict=ok,
            )
        )
        self.session.log(f"  {'OK  ' if ok else 'NOOK'} TestCase.{label} #{self.count}{note}")

    def assertTrue(self, value, msg=None):  # noqa: N802 - unittest's names
        self._check("assertTrue", bool(value), value, True)

    def assertFalse(self, value, msg=None):  # noqa: N802
        self._check("assertFalse", not bool(value), value, False)

    def assertEqual(self, first, second, msg=None):  # noqa: N802
        self._check("assertEqual", bool(first == second), first, second)

    def assertAlmostEqual(self, first, second, places=None, msg=None, delta=None):  # noqa: N802
        if first == second:  # unittest's shortcut (inf == inf holds)
            ok = True
        elif delta is not None:
            ok = abs(first - second) <= delta
        else:
            ok = round(abs(first - second), 7 if places is None else places) == 0
        self._check("assertAlmostEqual", bool(ok), first, second)

    def printSummary(self):  # noqa: N802
        self.session.log(f"  TestCase: {self.count} assertion(s)")


def _non_finite_numbers(values) -> list:
    """The NaN and infinite numbers among ``values`` and the items of the
    lists and tuples among them."""
    found = []
    for value in values:
        items = value if isinstance(value, (list, tuple)) else (value,)
        found += [item for item in items if _is_non_finite(item)]
    return found


def _is_non_finite(value) -> bool:
    # numbers.Complex covers Python's and numpy's floats and complexes
    if not isinstance(value, numbers.Complex) or isinstance(value, numbers.Integral):
        return False
    return not cmath.isfinite(complex(value))


class _TestCaseFactory(DeckCallable):
    def __init__(self, session: Session):
        self.session = session

    def deck_call(self, args, kwargs, site: CallSite):
        return TestCaseRecorder(self.session)


class CodeAsterModule:
    """The ``CA`` object: only what decks use."""

    deck_methods = frozenset({"TestCase"})

    def __init__(self, session: Session):
        self.TestCase = _TestCaseFactory(session)

    def deck_getattr(self, name: str):
        """Anything else of code_aster's CA is refused by name."""
        from asterlite.errors import UnsupportedError

        raise UnsupportedError(
            f"code_aster.CA.{name}: of code_aster's CA object, asterlite provides only CA.TestCase"
        )


def code_aster_module(session: Session) -> dict:
    return {"CA": CodeAsterModule(session)}


# ------------------------------------------------------------------ aster


class _GetVectJev(DeckCallable):
    """``aster.getvectjev(name)``: see :mod:`asterlite.runtime.jeveux`."""

    def __init__(self, session: Session):
        self.session = session

    def deck_call(self, args, kwargs, site: CallSite):
        from asterlite.errors import UnsupportedError
        from asterlite.runtime.jeveux import getvectjev

        if len(args) != 1 or kwargs:
            raise UnsupportedError("aster.getvectjev takes one argument, the vector's name")
        if getattr(self.session, "check_only", False):
            # check computes no concept: the name's form only is checked
            from asterlite.lang.values import Unknown
            from asterlite.runtime.jeveux import split_name

            split_name(args[0])
            return Unknown
        return getvectjev(self.session, args[0])


class AsterModule(DeckModule):
    """code_aster's low-level ``aster`` module: only ``getvectjev``; any
    other function of it is refused by name."""

    __slots__ = ()

    def attribute(self, name: str):
        if name in self.members:
            return self.members[name]
        from asterlite.errors import UnsupportedError

        raise UnsupportedError(
            f"aster.{name}: of code_aster's aster module, asterlite provides only getvectjev"
        )


def aster_module(session: Session) -> AsterModule:
    """The ``aster`` module a deck imports (``import aster``)."""
    return AsterModule("aster", {"getvectjev": _GetVectJev(session)})
