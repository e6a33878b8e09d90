"""What every legacy translation shares: source leaves, notes, tree helpers.

A translation works on a *call tree*: a dict of keyword -> value where a
factor keyword holds one mapping or a sequence of mappings. The same
translation serves two callers:

- the runtime dispatcher, whose leaves are computed values and whose
  mappings are :class:`~asterlite.lang.values.FactorDict` (with locations);
- ``asterlite port``, whose leaves are :class:`Src` (the text of the value
  in the deck, plus its value when it is a literal) and whose mappings are
  :class:`~asterlite.lang.values.FactorDict` built from the parse tree.

Translations read values through :func:`lit` (the literal value, or
:data:`NOT_LITERAL` for an expression the porter cannot evaluate) and write
plain Python values, which the porter prints as literals.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from asterlite.errors import Location, UnsupportedError
from asterlite.lang.values import FactorDict


class _NotLiteral:
    def __repr__(self) -> str:
        return "<not a literal>"


NOT_LITERAL = _NotLiteral()


@dataclass(frozen=True)
class Src:
    """A value as written in the deck: its source text and, for a literal, its value."""

    text: str
    value: object = NOT_LITERAL
    location: Location | None = None
    comment: str = ""  # a comment ending the value's line in the deck
    lead: tuple = ()  # comment lines just before the keyword


@dataclass
class NewCall:
    """A command call a translation needs before the translated one (a
    DEFI_FONCTION, say): the runtime runs it and puts its concept in place;
    ``asterlite port`` writes it as a statement ``NAME = COMMAND(...)``."""

    command: str
    kwargs: dict
    name_hint: str


class _Result:
    """Stands for the concept a translated call makes, in the calls made after it."""

    def __repr__(self) -> str:
        return "<the call's result>"


RESULT = _Result()


def text_of(value) -> str:
    """Deck text for a leaf (a Src or a plain value)."""
    if isinstance(value, Src):
        return value.text
    return repr(value)


def literal_text(value) -> str:
    """Deck text of a plain value (strings in double quotes, as code_aster 17 decks)."""
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, (list, tuple)):
        items = [literal_text(v) for v in value]
        if isinstance(value, list):
            return "[" + ", ".join(items) + "]"
        return "(" + ", ".join(items) + ("," if len(items) == 1 else "") + ")"
    return repr(value)


def with_comments_of(value, original):
    """``value`` carrying the deck comments of ``original`` when it is a Src
    (``asterlite port`` keeps a keyword's comments when its value changes)."""
    if isinstance(original, Src) and (original.comment or original.lead):
        return Src(literal_text(value), value, original.location, original.comment, original.lead)
    return value


def arith(op: str, left, right):
    """``left op right`` on leaves: a number when both are known numbers,
    else a Src expression (porting a deck whose values are variables)."""
    a, b = lit(left), lit(right)
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        return {"/": a / b, "*": a * b, "+": a + b, "-": a - b}[op]
    return Src(f"({text_of(left)}) {op} ({text_of(right)})")


def lit(value):
    """The value of a leaf: the literal of a :class:`Src`, else the value itself."""
    return value.value if isinstance(value, Src) else value


# ------------------------------------------------------------------------- notes


@dataclass
class Note:
    """One legacy form met in a deck, and the modern form it became."""

    old: str
    new: str
    location: Location | None = None

    @property
    def line(self) -> int | None:
        return self.location.line if self.location else None

    def text(self) -> str:
        where = ""
        if self.location is not None:
            where = f" ({Path(self.location.file).name}:{self.location.line})"
        return f"deprecated: {self.old}{where}; modern form: {self.new}"


@dataclass
class Env:
    """What a translation may know about the call besides its keywords."""

    command: str
    location: Location | None = None
    keyword_locations: dict = field(default_factory=dict)
    # logical unit -> input file path (None when unknown: porting a lone deck)
    unit_path: Callable[[int], Path | None] | None = None
    # mesh node name -> a node group holding exactly that node (None: none known)
    node_group: Callable[[str], str | None] | None = None
    notes: list[Note] = field(default_factory=list)
    # the code_aster version the deck was written for (asterlite.legacy.version)
    version: int = 17
    # groups standing for the nodes and cells the deck names (asterlite.legacy.nodes)
    legacy_groups: Any = None

    def where(self, level=None, keyword: str | None = None) -> Location | None:
        """The best location of ``keyword`` in ``level`` (or of the call)."""
        if keyword is not None:
            locations = getattr(level, "keyword_locations", None)
            if locations is None:
                locations = self.keyword_locations
            if keyword in locations:
                return locations[keyword]
        return getattr(level, "location", None) or self.location

    def note(self, old: str, new: str, level=None, keyword: str | None = None) -> None:
        self.notes.append(Note(old, new, self.where(level, keyword)))

    def group_of(self, node, cells: bool = False) -> str | None:
        """The node group standing for the mesh node ``node`` (a literal name),
        or with ``cells`` the cell group standing for the cell ``node``."""
        if not isinstance(node, str):
            return None
        if self.legacy_groups is not None:
            return self.legacy_groups.group_of(node, cells)
        if self.node_group is None or cells:
            return None
        return self.node_group(node)

    def unsupported(self, message: str, level=None, keyword: str | None = None):
        raise UnsupportedError(
            f"{self.command}: {message}", self.where(level, keyword), self.command
        )


@dataclass
class Translation:
    """The modern call a legacy call became."""

    command: str
    kwargs: dict
    notes: list[Note]
    # calls to make on the result once the command ran (DEFI_GROUP on a mesh read):
    # each NewCall is given the result as its reused concept
    after: list[NewCall] = field(default_factory=list)


# -------------------------------------------------------------------- trees


class NotPortable(Exception):
    """A legacy call ``asterlite port`` cannot rewrite (left as written)."""


def occurrences(value) -> list:
    """The occurrences of a factor keyword value (one mapping or a sequence)."""
    if isinstance(value, Src):
        raise NotPortable(f"a factor keyword is given as {value.text!r}, not as _F(...)")
    if value is None:
        return []
    if isinstance(value, dict):
        return [value]
    if isinstance(value, (list, tuple)):
        return [v for v in value if isinstance(v, dict)]
    return []


def factor(mapping: dict, like=None) -> FactorDict:
    """A new occurrence keeping the location (and deck comments) of ``like``."""
    new = FactorDict(
        mapping,
        location=getattr(like, "location", None),
        keyword_locations=dict(getattr(like, "keyword_locations", {}) or {}),
    )
    for name in ("comment", "lead"):
        if hasattr(like, name):
            setattr(new, name, getattr(like, name))
    return new


def rename_keys(level: dict, renames: dict[str, str]) -> dict:
    """``level`` with its keys renamed, keeping their order."""
    renamed = factor({renames.get(k, k): v for k, v in level.items()}, level)
    renamed.keyword_locations = {
        renames.get(k, k): loc for k, loc in getattr(level, "keyword_locations", {}).items()
    }
    return renamed


def pop_keys(level: dict, names: Iterable[str]) -> dict:
    """Remove and return the given keys of ``level`` (those present)."""
    return {name: level.pop(name) for name in list(names) if name in level}


def single(value):
    """A factor value given as one occurrence, or its only occurrence."""
    found = occurrences(value)
    return found[0] if len(found) == 1 else None


def as_text(values) -> str:
    """A short rendering of a few keyword names for notes."""
    return ", ".join(values)
