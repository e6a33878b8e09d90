"""Errors raised by asterlite, each carrying the deck location it refers to.

Every error a user can trigger derives from :class:`AsterliteError`; the CLI
prints ``str(error)`` and exits with status 2. Nothing here imports numpy.
"""

from __future__ import annotations

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


class AsterliteError(Exception):
    """Base of every error reported to the user (exit status 2)."""

    kind = "error"

    def __init__(self, message: str, location: Location | None = None, path: str = ""):
        super().__init__(message)
        self.message = message
        self.location = location
        self.path = path  # keyword path, e.g. "DYNA_VIBRA/COMPORTEMENT[1]/RIGI_NOR"

    def __str__(self) -> str:
        where = f"{self.location}: " if self.location else ""
        path = f"{self.path}: " if self.path else ""
        text = f"{where}{self.kind}: {path}{self.message}"
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
