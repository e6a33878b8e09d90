"""Errors raised by asterlite, each carrying the deck location it refers to.

Every error a user can trigger derives from :class:`AsterliteError`; the CLI
prints ``str(error)`` and exits with status 2. Nothing here imports numpy.
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Mapping
from dataclasses import dataclass


@dataclass(frozen=True)
class Location:
    """A position in a deck file (1-based line and column)."""

    file: str
    line: int
    column: int = 0
    source_line: str = ""

    def __str__(self) -> str:
        if self.column:
            return f"{self.file}:{self.line}:{self.column}"
        return f"{self.file}:{self.line}"

    def excerpt(self) -> str:
        """The offending line with a caret under the column, or '' if unknown."""
        if not self.source_line:
            return ""
        caret = " " * max(self.column - 1, 0) + "^"
        return f"    {self.source_line.rstrip()}\n    {caret}"


NOT_A_DECK = (
    "the file does not read as a code_aster deck (no command call such as DEBUT() in it): "
    "its text is not shown"
)


@dataclass(frozen=True)
class UnquotedLocation(Location):
    """A position in a file not recognised as what it should be: a study may
    name any file the user can read as its deck, export or mesh (``F comm
    /etc/passwd``), so neither its lines nor an error's wording (which may
    quote a name or a token) are shown: where, and ``reason``."""

    reason: str = NOT_A_DECK

    def excerpt(self) -> str:
        return ""


class AsterliteError(Exception):
    """Base of every error reported to the user (exit status 2)."""

    kind = "error"

    def __init__(self, message: str, location: Location | None = None, path: str = ""):
        super().__init__(message)
        self.message = message
        self.location = location  # often set later, where the deck statement is known
        self.path = path  # keyword path, e.g. "DYNA_VIBRA/COMPORTEMENT[1]/RIGI_NOR"

    @property
    def message(self) -> str:
        """What went wrong; in a file that does not read as a deck, only that."""
        if isinstance(self.location, UnquotedLocation):
            return self.location.reason
        return self._message

    @message.setter
    def message(self, text: str) -> None:
        self._message = text

    def worded(self, vocabulary: Mapping[str, str]) -> AsterliteError:
        """This error with its message and path in the words of the command
        whose input they name (:func:`worded`), of the same class."""
        error = type(self)(worded(self._message, vocabulary), self.location)
        error.path = worded(self.path, vocabulary, whole_path=True)
        return error

    def __str__(self) -> str:
        where = f"{self.location}: " if self.location else ""
        path = f"{worded(self.path, {})}: " if self.path else ""
        # a field a command did not word reads as the field's name
        text = f"{where}{self.kind}: {path}{worded(self.message, {})}"
        if self.location is not None and self.location.excerpt():
            text += "\n" + self.location.excerpt()
        return text


class DeckSyntaxError(AsterliteError):
    """The deck text does not parse, or uses a construct outside the subset."""

    kind = "syntax error"


class DeckRuntimeError(AsterliteError):
    """Evaluating deck statements failed (unknown name, bad operand, loop bound...)."""

    kind = "deck error"


class ValidationError(AsterliteError):
    """A command call does not match its keyword catalogue."""

    kind = "invalid keywords"


class UnsupportedError(AsterliteError):
    """A command, keyword value or feature asterlite does not implement yet."""

    kind = "unsupported"


class CommandError(AsterliteError):
    """A command could not do its job with valid keywords (missing group, bad data...)."""

    kind = "command error"


class NumericalError(AsterliteError):
    """Integration diverged, a step is unstable, or a non-finite value appeared."""

    kind = "numerical error"


# --- messages of a domain room, worded by the command ----------------------
# A domain room that receives typed problems (dynamics) never names the
# keyword a quantity came from: its messages name the problem's field,
# ``field("grid.step")``, and the command that read the keywords words them
# with its vocabulary {field: keyword path} (``worded``), in messages as
# the keyword's name and in an error's keyword path as the whole path.
# Without a vocabulary entry the field's own name stands.

FIELD_MARK = re.compile(r"\u27e8([A-Za-z_][\w.]*)\u27e9")


def field(name: str) -> str:
    """The mark standing for the problem field ``name`` in a message."""
    return f"\u27e8{name}\u27e9"


def worded(text: str, vocabulary: Mapping[str, str], whole_path: bool = False) -> str:
    """``text`` with each field mark replaced by its keyword in
    ``vocabulary``: the keyword's name (last part of its path), or its whole
    path when ``whole_path`` (an error's ``path``)."""

    def keyword(mark: re.Match) -> str:
        path = vocabulary.get(mark[1])
        if path is None:
            return mark[1]
        return path if whole_path else path.rsplit("/", 1)[-1]

    return FIELD_MARK.sub(keyword, text)


# --- suggestions for a name that is not there -------------------------------
# One place for every "did you mean" of a run or a check: deck names
# (commands, concepts, variables), mesh groups, components, files...


def close_names(word: str, candidates, n: int = 3, cutoff: float = 0.6) -> list[str]:
    """The candidates nearest to ``word``, best first (difflib's ratio,
    compared without case: code_aster names are upper case, a deck may not be)."""

    by_key: dict[str, str] = {}
    for candidate in candidates:
        by_key.setdefault(str(candidate).upper(), str(candidate))
    found = difflib.get_close_matches(str(word).upper(), list(by_key), n=n, cutoff=cutoff)
    return [by_key[key] for key in found]


def did_you_mean(word: str, candidates, quote: bool = False, cutoff: float = 0.7) -> str:
    """``", did you mean X?"`` (the closest candidate), or "" when none is close."""
    found = close_names(word, candidates, n=1, cutoff=cutoff)
    if not found:
        return ""
    return f", did you mean {found[0]!r}?" if quote else f", did you mean {found[0]}?"


def listing(names, limit: int = 12, quote: bool = True) -> str:
    """``'A', 'B', ... (40 in all)``: at most ``limit`` names."""
    names = [str(name) for name in names]
    shown = [repr(name) if quote else name for name in names[:limit]]
    more = f", ... ({len(names)} in all)" if len(names) > limit else ""
    return (", ".join(shown) or "none") + more


def missing_name(kind: str, name: str, existing, where: str = "the mesh") -> str:
    """The message for a name that is not there, with the nearest that are:
    ``"the mesh has no node group 'SUP2', did you mean 'SUPP2'? (nearest of
    its 12 node groups: 'SUPP2', 'SUPP1', 'SUPP3')"``; every name when
    there are few, none when there are none."""
    existing = [str(name) for name in existing]
    text = f"{where} has no {kind} {name!r}{did_you_mean(name, existing, quote=True)}"
    plural = f"{kind}s" if not kind.endswith("s") else kind
    if not existing:
        return f"{text} (it has no {plural})"
    if len(existing) <= 8:
        return f"{text} (its {plural}: {listing(existing)})"
    nearest = close_names(name, existing, n=5, cutoff=0.0)
    return f"{text} (nearest of its {len(existing)} {plural}: {listing(nearest)})"
