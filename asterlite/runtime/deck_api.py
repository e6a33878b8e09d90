"""The few ``code_aster`` Python objects decks import: ``from code_aster
import CA`` (``CA.TestCase`` records its assertions as test checks) and
``import aster`` (``aster.getvectjev`` reads a concept's vector by name)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from asterlite.lang.library import DeckModule
from asterlite.lang.values import CallSite, DeckCallable
from asterlite.runtime.context import TestRecord

if TYPE_CHECKING:
    from asterlite.runtime.session import Session


class TestCaseRecorder:
    """``CA.TestCase()``: unittest-style assertions recorded as checks."""

    deck_methods = frozenset(
        {"assertTrue", "assertFalse", "assertEqual", "assertAlmostEqual", "printSummary"}
    )

    def __init__(self, session: Session):
        self.session = session
        self.count = 0

    def _record(self, label: str, ok: bool, value, expected) -> None:
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
        self.session.log(f"  {'OK  ' if ok else 'NOOK'} TestCase.{label} #{self.count}")

    def assertTrue(self, value, msg=None):  # noqa: N802 - unittest's names
        self._record("assertTrue", bool(value), value, True)

    def assertFalse(self, value, msg=None):  # noqa: N802
        self._record("assertFalse", not bool(value), value, False)

    def assertEqual(self, first, second, msg=None):  # noqa: N802
        self._record("assertEqual", bool(first == second), first, second)

    def assertAlmostEqual(self, first, second, places=7, msg=None, delta=None):  # noqa: N802
        difference = abs(first - second)
        ok = difference <= delta if delta is not None else round(difference, places) == 0
        self._record("assertAlmostEqual", bool(ok), first, second)

    def printSummary(self):  # noqa: N802
        self.session.log(f"  TestCase: {self.count} assertion(s)")


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
