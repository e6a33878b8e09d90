"""Base class of every concept, and the placeholder used by ``asterlite check``."""

from __future__ import annotations

from typing import ClassVar


class Concept:
    """A named result of a command, bound in the deck namespace.

    Subclasses set ``aster_types`` (code_aster type names, most specific
    first) and extend ``deck_methods`` with the methods a deck may call.
    """

    aster_types: ClassVar[tuple[str, ...]] = ()
    deck_methods: ClassVar[frozenset[str]] = frozenset({"getName"})

    name: str | None = None

    @property
    def aster_type(self) -> str:
        return self.aster_types[0] if self.aster_types else type(self).__name__

    def getName(self) -> str:  # noqa: N802 - code_aster's method name
        return self.name or ""

    def satisfies(self, type_name: str) -> bool:
        return type_name in self.aster_types

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self.name or '?'}>"


class Placeholder(Concept):
    """Stands for a concept that ``asterlite check`` does not compute.

    It carries the type the catalogue declares for the command's result so
    later calls can still be type-checked.
    """

    def __init__(self, aster_type: str, produced_by: str = ""):
        self.aster_types = (aster_type,)
        self.produced_by = produced_by
