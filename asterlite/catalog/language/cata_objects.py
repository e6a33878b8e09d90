"""The plain data a catalogue module's reading builds.

:class:`~asterlite.catalog.language.reader.CatalogueReader` walks code_aster's
catalogue files and turns each call of the catalogue vocabulary (``SIMP``,
``FACT``, ``OPER``, rules, validators, types) into one of these objects;
the generator (:mod:`asterlite.catalog.language.generate`) reads them.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass, field


class ReadError(Exception):
    """A construct the reader does not evaluate, or a catalogue error."""


# ----------------------------------------------------------------- data objects


class CataObject:
    """Something a catalogue call built (``SIMP(...)``, a rule, a type...)."""


@dataclass(eq=False)
class Keyword(CataObject):
    """``SIMP``, ``FACT`` or ``BLOC`` with its keyword arguments, in order."""

    kind: str  # "SIMP", "FACT", "BLOC"
    options: dict


@dataclass(eq=False)
class CommandDef(CataObject):
    """``OPER``, ``MACRO``, ``PROC``, ``FORM`` with its keyword arguments."""

    kind: str
    options: dict

    # attributes code_aster's catalogues read from another command
    def attribute(self, name: str):
        if name in ("entites", "entities"):
            return {k: v for k, v in self.options.items() if isinstance(v, Keyword)}
        if name in ("regles", "rules"):
            return self.options.get("regles", ())
        if name in ("nom", "name"):
            return self.options.get("nom")
        raise ReadError(f"attribute {name} of a command")


@dataclass(eq=False)
class UserMacroDef(CataObject):
    """``UserMacro(name, catalogue, ops)``: a command whose catalogue is
    defined beside its Python implementation (code_aster 15-17)."""

    name: str
    catalogue: object


def _user_macro(name, catalogue, ops=None):
    return UserMacroDef(name, catalogue)


@dataclass(eq=False)
class RuleDef(CataObject):
    kind: str  # code_aster's class name: AtLeastOne, ExactlyOne...
    args: tuple
    kwargs: dict


@dataclass(eq=False)
class ValidatorDef(CataObject):
    kind: str  # NoRepeat, LongStr, OrdList...
    args: tuple
    kwargs: dict


@dataclass(eq=False)
class TypeRef(CataObject):
    """A class of ``DataStructure.py``: a concept type, or a mesh entity."""

    name: str
    bases: tuple[str, ...]

    def __repr__(self) -> str:
        return self.name


@dataclass(eq=False)
class UnitRef(CataObject):
    """``UnitType(filter)``: a logical unit number (or ``{unit: file}``)."""

    filter: str | None


@dataclass(eq=False)
class Opaque(CataObject):
    """A name the reader knows exists but never evaluates (a stub module,
    ``tr``'s translator...): using it is a :class:`ReadError`."""

    name: str


@dataclass(eq=False)
class Function(CataObject):
    """A ``def`` of a catalogue module: run by the reader when the catalogue
    calls it at module level, kept as a syntax tree otherwise."""

    node: ast.FunctionDef
    scope: Scope
    module: str
    bound: object = None  # the class or instance of a method

    @property
    def name(self) -> str:
        return self.node.name


@dataclass(eq=False)
class ClassObj(CataObject):
    name: str
    attrs: dict
    bases: tuple
    enum: bool = False
    members: list = field(default_factory=list)


@dataclass(eq=False)
class Instance(CataObject):
    cls: ClassObj
    attrs: dict = field(default_factory=dict)


@dataclass(eq=False)
class EnumMember(CataObject):
    cls: ClassObj
    name: str
    value: object

    def __repr__(self) -> str:
        return f"{self.cls.name}.{self.name}"


class OrderedSet:
    """``set`` with a deterministic order: insertion order (Python's own set
    of strings is ordered by a per-process hash)."""

    def __init__(self, items=()):
        self.items = dict.fromkeys(items)

    def __iter__(self):
        return iter(list(self.items))

    def __len__(self):
        return len(self.items)

    def __contains__(self, item):
        return item in self.items

    def __eq__(self, other):
        return isinstance(other, OrderedSet) and set(self.items) == set(other.items)

    __hash__ = None


# ------------------------------------------------------------------- scopes


class Scope:
    """Names of a module, a function call, a class body or a comprehension."""

    def __init__(self, names: dict | None = None, parent: Scope | None = None):
        self.names = names if names is not None else {}
        self.parent = parent

    def lookup(self, name: str):
        scope = self
        while scope is not None:
            if name in scope.names:
                return scope.names[name]
            scope = scope.parent
        raise ReadError(f"name {name!r} is not defined")
