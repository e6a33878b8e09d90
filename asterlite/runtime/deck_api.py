"""The few ``code_aster`` Python objects decks import (``from code_aster
import CA``): ``CA.TestCase`` records its assertions as test checks."""

from __future__ import annotations

from typing import TYPE_CHECKING

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


def code_aster_module(session: Session) -> dict:
    return {"CA": CodeAsterModule(session)}
