"""The few ``code_aster`` Python objects decks import: ``from code_aster
import CA`` and ``import aster``.

Of code_aster 16-17's ``CA`` object, asterlite gives what decks of its
suite use where asterlite has the concept: ``CA.init(...)`` (``DEBUT`` with
its keywords, the command line options that change no result), ``CA.close()``
(``FIN``), ``CA.TestCase`` (assertions recorded as test checks, also
``assertRaises`` as a ``with`` block), ``CA.disable_fpe()`` (a ``with``
block: asterlite traps no floating point exception), ``CA.Mesh()`` with
``readMedFile`` of a file the run was given, and code_aster's exception
classes (``CA.AsterError``...) for ``try``/``except``. Anything else of
``CA`` is refused by name. ``aster.getvectjev`` reads a concept's vector by
name; ``aster.error`` is ``AsterError``."""

from __future__ import annotations

import cmath
import numbers
import re
from typing import TYPE_CHECKING

from asterlite.concepts.base import Placeholder
from asterlite.errors import DeckRuntimeError, UnsupportedError
from asterlite.lang.exceptions import ASTER_CLASSES, ExceptionClass, classify, matches
from asterlite.lang.library import DeckModule
from asterlite.lang.values import CallSite, DeckCallable, Unknown
from asterlite.post.check_record import TestRecord

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
        {
            "assertTrue",
            "assertFalse",
            "assertEqual",
            "assertNotEqual",
            "assertAlmostEqual",
            "assertLess",
            "assertLessEqual",
            "assertGreater",
            "assertGreaterEqual",
            "assertIsNone",
            "assertIsNotNone",
            "assertIn",
            "assertNotIn",
            "assertSequenceEqual",
            "assertRaises",
            "assertRaisesRegex",
            "printSummary",
        }
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

    def assertNotEqual(self, first, second, msg=None):  # noqa: N802
        self._check("assertNotEqual", bool(first != second), first, second)

    def assertLess(self, first, second, msg=None):  # noqa: N802
        self._check("assertLess", bool(first < second), first, second)

    def assertLessEqual(self, first, second, msg=None):  # noqa: N802
        self._check("assertLessEqual", bool(first <= second), first, second)

    def assertGreater(self, first, second, msg=None):  # noqa: N802
        self._check("assertGreater", bool(first > second), first, second)

    def assertGreaterEqual(self, first, second, msg=None):  # noqa: N802
        self._check("assertGreaterEqual", bool(first >= second), first, second)

    def assertIsNone(self, value, msg=None):  # noqa: N802
        self._record("assertIsNone", value is None, _shown(value), None)

    def assertIsNotNone(self, value, msg=None):  # noqa: N802
        self._record("assertIsNotNone", value is not None, _shown(value), None)

    def assertIn(self, member, container, msg=None):  # noqa: N802
        self._record("assertIn", member in container, _shown(member), _shown(container))

    def assertNotIn(self, member, container, msg=None):  # noqa: N802
        self._record("assertNotIn", member not in container, _shown(member), _shown(container))

    def assertSequenceEqual(self, first, second, msg=None, seq_type=None):  # noqa: N802
        """unittest's: the same length and equal items, in order."""
        first, second = list(first), list(second)
        ok = len(first) == len(second) and all(
            bool(a == b) for a, b in zip(first, second, strict=True)
        )
        self._check("assertSequenceEqual", ok, first, second)

    def assertRaises(self, expected, function=None, *args, **kwargs):  # noqa: N802
        """A ``with`` block (``with test.assertRaises(CA.AsterError):``) or a call."""
        return self._raises("assertRaises", expected, None, function, args, kwargs)

    def assertRaisesRegex(self, expected, regex, function=None, *args, **kwargs):  # noqa: N802
        return self._raises("assertRaisesRegex", expected, regex, function, args, kwargs)

    def _raises(self, label, expected, regex, function, args, kwargs):
        _exception_classes(expected)
        context = _AssertRaises(self, label, expected, regex)
        if function is None:
            return context
        context.deck_enter()
        try:
            if isinstance(function, DeckCallable):
                function.deck_call(list(args), dict(kwargs), CallSite())
            else:
                function(*args, **kwargs)
        except Exception as error:  # noqa: BLE001 - classified: run-ending errors go on
            kind = classify(error)
            if kind is None or not context.deck_exit(error, kind):
                raise
            return None
        context.deck_exit(None, None)
        return None

    def printSummary(self):  # noqa: N802
        self.session.log(f"  TestCase: {self.count} assertion(s)")


def _shown(value):
    """A value as a check record shows it: numbers and text as they are."""
    if value is None or isinstance(value, (bool, int, float, complex, str)):
        return value
    return repr(value)[:200]


def _exception_classes(expected) -> None:
    items = expected if isinstance(expected, tuple) else (expected,)
    if not items or not all(isinstance(item, ExceptionClass) for item in items):
        raise DeckRuntimeError("assertRaises takes an exception class (or a tuple of them)")


class _AssertRaises:
    """``with test.assertRaises(E):``: OK when the block raises an E (which
    it then catches), NOOK when it raises nothing or another error a deck
    may catch (caught too: code_aster's TestCase never fails there).
    ``assertRaisesRegex`` also matches the message; asterlite's messages are
    not code_aster's, so a pattern meant for a code_aster message (its
    identifier, ``FONCT0_29``) is refused by name rather than judged."""

    def __init__(self, recorder: TestCaseRecorder, label: str, expected, regex):
        self.recorder = recorder
        self.label = label
        self.expected = expected
        self.regex = regex

    def deck_enter(self):
        return None

    def deck_exit(self, error, kind) -> bool:
        name = "/".join(
            item.name
            for item in (self.expected if isinstance(self.expected, tuple) else (self.expected,))
        )
        if error is None:
            self.recorder._record(self.label, False, "no exception", name, f": {name} not raised")
            return True
        if not matches(kind, self.expected):
            note = f": unexpected exception {kind.name} ({error.message})"
            self.recorder._record(self.label, False, kind.name, name, note)
            return True
        if self.regex is not None:
            message = str(error.__cause__) if error.__cause__ is not None else error.message
            if not re.search(str(self.regex), message):
                if kind.origin == "code_aster" or kind.is_subclass_of(ASTER_CLASSES["AsterError"]):
                    raise UnsupportedError(
                        f"TestCase.{self.label}({kind.name}, {str(self.regex)!r}): code_aster's "
                        f"messages are not asterlite's (its message reads: {error.message})"
                    )
                self.recorder._record(self.label, False, message, str(self.regex))
                return True
        self.recorder._record(self.label, True, kind.name, name)
        return True


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


class _NoFloatingPointTraps:
    """``with CA.disable_fpe():``: code_aster stops trapping floating point
    exceptions in the block; asterlite traps none (numpy warns), so nothing
    changes."""

    def deck_enter(self):
        return None

    def deck_exit(self, error, kind) -> bool:
        return False


class _DisableFpe(DeckCallable):
    def deck_call(self, args, kwargs, site: CallSite):
        return _NoFloatingPointTraps()


# code_aster's command line options (CA.init("--test")) that change no result
HARMLESS_OPTIONS = frozenset({"--test", "--abort", "--slave", "--debug", "-g", "--continue"})


class _Init(DeckCallable):
    """``CA.init(*options, **keywords)``: code_aster's DEBUT (POURSUITE with
    ``--continue``) with its keywords, checked by the DEBUT catalogue."""

    def __init__(self, session: Session):
        self.session = session

    def deck_call(self, args, kwargs, site: CallSite):
        for option in args:
            if not isinstance(option, str) or option not in HARMLESS_OPTIONS:
                raise UnsupportedError(
                    f"CA.init: command line option {option!r} (asterlite takes "
                    f"{', '.join(sorted(HARMLESS_OPTIONS))}, which change no result)",
                    site.location,
                )
        kwargs = dict(kwargs)
        for name in ("debug", "noargv"):  # debugging and argument handling: no result changes
            kwargs.pop(name, None)
        for name in ("debugpy", "comm"):
            if name in kwargs:
                raise UnsupportedError(f"CA.init: keyword {name} (a debugger, MPI)", site.location)
        command = "POURSUITE" if "--continue" in args else "DEBUT"
        keywords = {k: v for k, v in kwargs.items()}
        locations = {k: v for k, v in site.keyword_locations.items() if k in keywords}
        call = CallSite(site.location, locations, site.assigned_name)
        return self.session.command(command).deck_call([], keywords, call)


class _Close(DeckCallable):
    """``CA.close()``: code_aster's FIN."""

    def __init__(self, session: Session):
        self.session = session

    def deck_call(self, args, kwargs, site: CallSite):
        if args:
            raise UnsupportedError("CA.close takes keyword arguments only", site.location)
        return self.session.command("FIN").deck_call([], dict(kwargs), site)


class _MeshFactory(DeckCallable):
    """``CA.Mesh()``: an empty mesh, read later with ``readMedFile``."""

    def __init__(self, session: Session):
        self.session = session

    def deck_call(self, args, kwargs, site: CallSite):
        # numpy (~150 ms of start-up) stays out of asterlite check: loaded when a deck calls it
        from asterlite.io.med_mesh import ReadableMesh

        if args or kwargs:
            raise UnsupportedError("CA.Mesh() takes no arguments in asterlite", site.location)
        mesh = ReadableMesh.empty(lambda name: named_input(self.session, name))
        mesh.name = site.assigned_name
        return mesh


def named_input(session: Session, name: str):
    """The input file of the run whose name is ``name`` (an export's
    ``F nom sdlv126g.med D 0``, a unit's file): never another path."""
    if not isinstance(name, str) or "/" in name or "\\" in name or name in ("", ".", ".."):
        raise DeckRuntimeError(
            f"{str(name)[:80]!r}: decks read the run's input files by their name only "
            "(no folder, no absolute path)"
        )
    run = session.run
    for path in [*run.helper_modules.values(), *run.units.values()]:
        if path.name == name:
            return path
    raise DeckRuntimeError(f"the run has no input file named {name!r} (see the .export's F lines)")


class PhysicalProblem:
    """``CA.PhysicalProblem(model, materials, characteristics)``: what a
    post-processing is computed with."""

    deck_methods = frozenset({"getModel"})

    def __init__(self, model, materials=None, characteristics=None):
        self.model, self.materials, self.characteristics = model, materials, characteristics

    def getModel(self):  # noqa: N802 - code_aster's name
        return self.model


class PostProcessing:
    """``CA.PostProcessing(problem)``: computeMaxResultantForPipe only."""

    deck_methods = frozenset({"computeMaxResultantForPipe"})

    def __init__(self, problem: PhysicalProblem):
        self.problem = problem

    def computeMaxResultantForPipe(self, result, field_name):  # noqa: N802
        from asterlite.post.cell_fields import max_resultant_for_pipe

        if isinstance(result, Placeholder):  # check computed no result
            return Unknown
        return max_resultant_for_pipe(result, field_name)


class _PhysicalProblemFactory(DeckCallable):
    def deck_call(self, args, kwargs, site: CallSite):
        if kwargs or not 1 <= len(args) <= 3:
            raise UnsupportedError(
                "CA.PhysicalProblem takes (model, materials, characteristics)", site.location
            )
        return PhysicalProblem(*args)


class _PostProcessingFactory(DeckCallable):
    def deck_call(self, args, kwargs, site: CallSite):
        if kwargs or len(args) != 1 or not isinstance(args[0], PhysicalProblem):
            raise UnsupportedError("CA.PostProcessing takes a CA.PhysicalProblem", site.location)
        return PostProcessing(args[0])


class CodeAsterModule:
    """The ``CA`` object: only what decks use (see the module's docstring)."""

    deck_methods = frozenset(
        {"TestCase", "init", "close", "disable_fpe", "Mesh", "PhysicalProblem", "PostProcessing"}
    )

    def __init__(self, session: Session):
        self.TestCase = _TestCaseFactory(session)
        self.init = _Init(session)
        self.close = _Close(session)
        self.disable_fpe = _DisableFpe()
        self.Mesh = _MeshFactory(session)
        self.PhysicalProblem = _PhysicalProblemFactory()
        self.PostProcessing = _PostProcessingFactory()

    def deck_getattr(self, name: str):
        """code_aster's exception classes; anything else of CA is refused by name."""
        if name in ASTER_CLASSES:
            return ASTER_CLASSES[name]
        raise UnsupportedError(
            f"code_aster.CA.{name}: of code_aster's CA object, asterlite provides init, close, "
            "TestCase, disable_fpe, Mesh, PhysicalProblem, PostProcessing "
            "(computeMaxResultantForPipe) and the exception classes (AsterError...)"
        )

    def members(self) -> dict:
        """What ``from code_aster.CA import ...`` may take."""
        found = {name: getattr(self, name) for name in self.deck_methods}
        return found | ASTER_CLASSES


def code_aster_module(session: Session) -> dict:
    ca = CodeAsterModule(session)
    return {"CA": ca, "init": ca.init, "close": ca.close, **ASTER_CLASSES}


def code_aster_ca_module(session: Session) -> DeckModule:
    """``from code_aster.CA import AsterError``."""
    return CodeAsterCAModule("code_aster.CA", CodeAsterModule(session).members())


class CodeAsterCAModule(DeckModule):
    __slots__ = ()

    def attribute(self, name: str):
        if name in self.members:
            return self.members[name]
        raise UnsupportedError(
            f"code_aster.CA.{name}: of code_aster's CA object, asterlite provides init, close, "
            "TestCase, disable_fpe, Mesh, PhysicalProblem, PostProcessing "
            "(computeMaxResultantForPipe) and the exception classes (AsterError...)"
        )


# ------------------------------------------------------------------ aster


class _GetVectJev(DeckCallable):
    """``aster.getvectjev(name)``: see :mod:`asterlite.runtime.jeveux`."""

    def __init__(self, session: Session):
        self.session = session

    def deck_call(self, args, kwargs, site: CallSite):
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
        raise UnsupportedError(
            f"aster.{name}: of code_aster's aster module, asterlite provides getvectjev and error"
        )


def aster_module(session: Session) -> AsterModule:
    """The ``aster`` module a deck imports (``import aster``); ``aster.error``
    is code_aster's AsterError (``except aster.error, err`` of older decks)."""
    return AsterModule(
        "aster", {"getvectjev": _GetVectJev(session), "error": ASTER_CLASSES["AsterError"]}
    )
