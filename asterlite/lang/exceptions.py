"""Exceptions as decks see them: which errors a ``try`` may catch, the
exception classes a deck names (``ValueError``, ``CA.AsterError``...), the
errors it raises and the error values ``except ... as err`` binds.

What a deck may catch is what Python or code_aster would have raised in the
same place, and nothing else:

- Python's own errors of deck code (a division by zero, a missing key, an
  undefined name, a failed ``assert``, an import of a module asterlite does
  not offer), as their Python classes (``ZeroDivisionError`` is an
  ``ArithmeticError``...);
- a command that fails with valid keywords, invalid keywords or a
  numerical failure: code_aster raises its ``AsterError`` there (asterlite's
  ``CommandError``, ``ValidationError``, ``NumericalError``); where code_aster
  raises one of its subclasses (``SolverError`` for an empty band of
  CALC_MODES...), the command names it (``aster_exception``), elsewhere an
  ``except CA.SolverError`` lets the error through and the run stops with it;
- what the deck raises itself (``raise CA.AsterError("...")``).

Never: the run's limits (time, memory, steps, sizes), interruptions,
asterlite's refusals (a whitelist, a feature asterlite does not implement:
code_aster would have run it, so catching the refusal would silently change
the deck's course), errors of asterlite itself. These end the run at once,
without running ``finally`` blocks or ``with`` exits.
"""

from __future__ import annotations

import re

from asterlite.errors import (
    AsterliteError,
    CommandError,
    DeckRuntimeError,
    NumericalError,
    UnsupportedError,
    ValidationError,
)
from asterlite.lang import limits as guards
from asterlite.lang.values import CallSite, DeckCallable


class ExceptionClass(DeckCallable):
    """An exception class a deck names: calling it makes an exception value
    (:class:`RaisedException`) for ``raise``."""

    def __init__(self, name: str, parent: ExceptionClass | None = None, origin: str = ""):
        self.name = name
        self.parent = parent
        self.origin = origin  # "code_aster" for CA's classes

    def is_subclass_of(self, other: ExceptionClass) -> bool:
        cls = self
        while cls is not None:
            if cls is other:
                return True
            cls = cls.parent
        return False

    def deck_call(self, args: list, kwargs: dict, site: CallSite):
        if kwargs:
            raise DeckRuntimeError(f"{self.name}() takes no keyword arguments")
        guards.check_nested_size(args, guards.Limits())  # its message is their text
        return RaisedException(self, tuple(args))

    def __repr__(self) -> str:
        return f"<class '{self.name}'>"


class RaisedException:
    """An exception value made by a deck (``ValueError("x")``), not raised yet."""

    deck_attributes = frozenset({"args"})

    def __init__(self, cls: ExceptionClass, args: tuple):
        self.cls = cls
        self.args = args
        shown = guards.deck_text_value(args)  # engine objects neutrally, as print does
        self._message = str(shown[0]) if len(shown) == 1 else (str(shown) if shown else "")

    def message(self) -> str:
        return self._message

    def __str__(self) -> str:
        return self.message()

    def __repr__(self) -> str:
        return f"{self.cls.name}({', '.join(repr(a) for a in self.args)})"


class DeckRaised(DeckRuntimeError):
    """An error the deck raised with ``raise``."""

    def __init__(self, exception: RaisedException):
        text = exception.message()
        super().__init__(f"{exception.cls.name}: {text}" if text else exception.cls.name)
        self.exception = exception
        self.deck_class = exception.cls


def _builtin_classes() -> dict[str, ExceptionClass]:
    classes: dict[str, ExceptionClass] = {}

    def add(name, parent=None):
        classes[name] = ExceptionClass(name, classes.get(parent))

    add("BaseException")
    add("Exception", "BaseException")
    for name in (
        "ArithmeticError",
        "LookupError",
        "ValueError",
        "TypeError",
        "AttributeError",
        "NameError",
        "ImportError",
        "AssertionError",
        "RuntimeError",
        "OSError",
        "StopIteration",
    ):
        add(name, "Exception")
    for name in ("ZeroDivisionError", "OverflowError", "FloatingPointError"):
        add(name, "ArithmeticError")
    add("IndexError", "LookupError")
    add("KeyError", "LookupError")
    add("UnboundLocalError", "NameError")
    add("ModuleNotFoundError", "ImportError")
    add("NotImplementedError", "RuntimeError")
    add("UnicodeError", "ValueError")
    classes["IOError"] = classes["EnvironmentError"] = classes["OSError"]
    return classes


BUILTIN_CLASSES = _builtin_classes()

# code_aster's exceptions (code_aster/Supervis/exceptions_ext.py)
ASTER_ERROR = ExceptionClass("AsterError", BUILTIN_CLASSES["Exception"], "code_aster")
ASTER_CLASSES = {"AsterError": ASTER_ERROR} | {
    name: ExceptionClass(name, ASTER_ERROR, "code_aster")
    for name in (
        "ConvergenceError",
        "IntegrationError",
        "SolverError",
        "ContactError",
        "TimeLimitError",
    )
}


def deck_exception_names() -> dict:
    """The builtin exception classes every deck namespace holds."""
    return dict(BUILTIN_CLASSES)


def python_error(kind: type, message: str) -> DeckRuntimeError:
    """A deck error Python itself would raise there (``kind``: NameError...):
    a deck may catch it."""
    error = DeckRuntimeError(message)
    error.python_type = kind
    return error


def classify(error: BaseException) -> ExceptionClass | None:
    """The class a deck sees ``error`` as, or None when no deck may catch it."""
    if not isinstance(error, AsterliteError) or getattr(error, "fatal", False):
        return None
    if isinstance(error, DeckRaised):
        return error.deck_class
    if isinstance(error, (CommandError, ValidationError, NumericalError)):
        return ASTER_CLASSES.get(getattr(error, "aster_exception", None), ASTER_ERROR)
    if type(error) is DeckRuntimeError:
        kind = getattr(error, "python_type", None)
        if kind is None:  # one of asterlite's refusals
            return None
        for base in kind.__mro__:
            if base.__name__ in BUILTIN_CLASSES:
                return BUILTIN_CLASSES[base.__name__]
        return BUILTIN_CLASSES["Exception"]
    return None  # unsupported features, syntax, the run's own errors


def matches(kind: ExceptionClass, wanted) -> bool:
    """Whether an error of class ``kind`` is caught by ``except wanted``."""
    if isinstance(wanted, tuple):
        return any(matches(kind, item) for item in wanted)
    if not isinstance(wanted, ExceptionClass):
        raise DeckRuntimeError(
            "catching classes that do not derive from BaseException is not allowed "
            f"(got {type(wanted).__name__})"
        )
    return kind.is_subclass_of(wanted)


def ends_run(error: BaseException) -> bool:
    """Errors that end the run at once (no ``finally``, no ``with`` exit)."""
    return classify(error) is None


# an absolute path in a message: a deck sees only its last component
_ABSOLUTE_PATH = re.compile(r"(?<![\w.~])/(?:[^\s'\"():,;/]+/)+([^\s'\"():,;/]*)")


def without_paths(text: str) -> str:
    """``text`` with absolute paths cut to their file name: an error message
    may name the export or a mesh by its path, which a deck need not learn."""
    return _ABSOLUTE_PATH.sub(lambda match: match.group(1) or ".", text)


class CaughtError:
    """What ``except ... as err`` binds: the error's class, message and args.

    code_aster's message identifiers (``err.id_message``) are refused by
    name: asterlite's errors are worded its own way."""

    deck_attributes = frozenset({"args", "message"})

    def __init__(self, error: AsterliteError, cls: ExceptionClass):
        self.error = error
        self.cls = cls
        if isinstance(error, DeckRaised):
            self.args = error.exception.args
            self.message = error.exception.message()
        else:
            cause = error.__cause__
            text = str(cause) if cause is not None and str(cause) else error.message
            self.message = without_paths(text)
            self.args = (self.message,)

    def deck_getattr(self, name: str):
        if name in ("id_message", "valk", "vali", "valr", "format"):
            raise UnsupportedError(
                f"{self.cls.name}.{name}: code_aster's message identifiers and arguments are "
                f"not reproduced by asterlite, whose message reads: {self.message}"
            )
        raise DeckRuntimeError(
            f"'{self.cls.name}' object has no attribute '{name}' usable in decks"
        )

    def __str__(self) -> str:
        return self.message

    def __repr__(self) -> str:
        return f"{self.cls.name}({self.message!r})"
