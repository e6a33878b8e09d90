"""What a command implementation receives besides its keywords.

A command module in ``asterlite.commands`` exposes::

    def run(ctx: CommandContext, kw: Keywords) -> Concept | None

and returns the concept to bind to the deck name on the left of ``=`` (or
None for procedures). It never validates keywords again, and reports
problems by raising through ``ctx.error(...)`` so the message carries the
deck file, line and keyword path.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from asterlite.errors import CommandError, Location, UnsupportedError

if TYPE_CHECKING:
    from asterlite.catalog.keywords import Keywords
    from asterlite.runtime.session import Session


@dataclass
class CommandContext:
    """The call site and session a command runs in."""

    session: Session
    command: str
    location: Location | None = None
    result_name: str | None = None  # deck name on the left of '=', if any
    reuse: Any = None  # the concept passed as reuse=, if any
    notes: list[str] = field(default_factory=list)

    def error(
        self,
        message: str,
        keyword: str | None = None,
        kw: Keywords | None = None,
        aster_exception: str | None = None,
    ):
        """Raise a CommandError located at the call (and keyword, when given);
        ``aster_exception`` names the subclass of code_aster's AsterError that
        code_aster raises there (``SolverError``...), for a deck's ``except``."""
        path, location = self.command, self.location
        if kw is not None:
            path, location = kw.where(keyword)
            location = location or self.location
        elif keyword:
            path = f"{self.command}/{keyword}"
        error = CommandError(message, location, path)
        error.aster_exception = aster_exception
        raise error

    def unsupported(self, what: str, keyword: str | None = None, kw: Keywords | None = None):
        """Raise an UnsupportedError for a keyword value not implemented yet."""
        path, location = kw.where(keyword) if kw is not None else (self.command, None)
        raise UnsupportedError(what, location or self.location, path)

    def log(self, message: str) -> None:
        """Write a line to the run's message log."""
        self.session.log(f"  {message}")

    def bind(self, output: Any, concept: Any) -> None:
        """Bind a concept to a ``CO("NAME")`` output argument."""
        self.session.bind_output(output, concept)
