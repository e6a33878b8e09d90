"""Catalogue objects read by :mod:`asterlite.catalog.language.reader` ->
the JSON-ready language data (:data:`FORMAT`) that
:mod:`asterlite.catalog.language.model` loads.

Shared by the generator of code_aster 13+'s catalogues
(:mod:`~asterlite.catalog.language.generate`) and the reader of the one
``cata.py`` of older versions (:mod:`~asterlite.catalog.language.legacy_layout`).
"""

from __future__ import annotations

import ast
import math
import re

from asterlite.catalog.language.cata_objects import (
    CommandDef,
    Function,
    Keyword,
    OrderedSet,
    ReadError,
    RuleDef,
    TypeRef,
    UnitRef,
    ValidatorDef,
)
from asterlite.catalog.language.expression import NotExpressible, from_source
from asterlite.catalog.language.reader import CatalogueReader
from asterlite.catalog.language.sdprod import read_sd_prod

FORMAT = 1  # version of the data layout (asterlite.catalog.language.model reads it)

# code_aster's rule classes -> the names catalogues write (Language/Syntax.py)
RULE_NAMES = {
    "AtLeastOne": "AU_MOINS_UN",
    "ExactlyOne": "UN_PARMI",
    "AtMostOne": "EXCLUS",
    "IfFirstAllPresent": "PRESENT_PRESENT",
    "OnlyFirstPresent": "PRESENT_ABSENT",
    "AllTogether": "ENSEMBLE",
    "NotEmpty": "NON_VIDE",
}
ROOT_TYPE = "DataStructure"  # code_aster's ASSD: any concept ("assd" in the data)


class Converter:
    """Catalogue objects -> JSON-ready data."""

    def __init__(self, reader: CatalogueReader):
        self.reader = reader
        self.type_names = set(reader.types) | set(reader.type_aliases)
        self.problems: list[str] = []
        self.where = ""

    def canonical(self, name: str) -> str:
        """A type's own name: aliases (``ASSD = DataStructure``) resolved,
        the root written ``assd`` as catalogues spell it."""
        seen = set()
        while name in self.reader.type_aliases and name not in seen:
            seen.add(name)
            name = self.reader.type_aliases[name]
        return "assd" if name == ROOT_TYPE else name

    def type_name(self, value) -> str:
        if isinstance(value, TypeRef):
            return self.canonical(value.name)
        if isinstance(value, UnitRef):
            return "UNITE"
        if isinstance(value, str):
            return value
        raise ReadError(f"{self.where}: type {value!r}")

    def types(self, value) -> list[str]:
        items = value if isinstance(value, (tuple, list)) else (value,)
        return [self.type_name(item) for item in items]

    def value(self, value):
        """A default, a choice, a bound: JSON scalars, lists, tagged others."""
        if value is None or isinstance(value, (bool, int, str)):
            return value
        if isinstance(value, float):
            return value if math.isfinite(value) else {"float": repr(value)}
        if isinstance(value, complex):
            return {"complex": [self.value(value.real), self.value(value.imag)]}
        if isinstance(value, (list, tuple, OrderedSet)):
            return [self.value(v) for v in value]
        if isinstance(value, dict):
            return {"dict": [[self.value(k), self.value(v)] for k, v in value.items()]}
        if isinstance(value, TypeRef):
            return {"type": self.type_name(value)}
        raise ReadError(f"{self.where}: value {value!r}")

    def rules(self, regles) -> list:
        if regles is None:
            return []
        items = regles if isinstance(regles, (list, tuple)) else (regles,)
        found = []
        for rule in items:
            if not isinstance(rule, RuleDef):
                raise ReadError(f"{self.where}: rule {rule!r}")
            entry = [RULE_NAMES[rule.kind], *rule.args]
            if rule.kwargs:  # defaults code_aster inserts when none is given
                entry.append({"defaults": {k: self.value(v) for k, v in rule.kwargs.items()}})
            found.append(entry)
        return found

    def validators(self, value) -> list:
        items = value if isinstance(value, (list, tuple)) else (value,)
        found = []
        for validator in items:
            if not isinstance(validator, ValidatorDef):
                raise ReadError(f"{self.where}: validator {validator!r}")
            args = list(validator.args)
            if validator.kind in ("AndVal", "OrVal"):
                inner = args[0] if len(args) == 1 and isinstance(args[0], (list, tuple)) else args
                entry = [validator.kind, *self.validators(inner)]
            elif validator.kind == "OrdList":
                reverse = bool(validator.kwargs.get("reverse", False))
                if args and args[0] != "croissant":
                    reverse = True
                entry = ["OrdList", "decreasing" if reverse else "increasing"]
            else:
                entry = [validator.kind, *(self.value(a) for a in args)]
            found.append(entry)
        return found

    def condition(self, text):
        if not isinstance(text, str):
            raise ReadError(f"{self.where}: condition {text!r}")
        try:
            return self.canonical_trees(from_source(text, self.type_names))
        except SyntaxError as error:
            # code_aster's eval raises there and takes the condition as false
            self.problems.append(f"{self.where}: condition never true ({error}): {text!r}")
            return ["c", False]
        except NotExpressible as error:
            self.problems.append(f"{self.where}: condition not kept ({error}): {text!r}")
            return ["unread"]

    def entries(self, options: dict, path: str) -> dict:
        found = {}
        for name, value in options.items():
            if isinstance(value, Keyword) and name != "reuse":
                self.where = f"{path}/{name}"
                found[name] = self.entry(value, f"{path}/{name}")
        return found

    def entry(self, keyword: Keyword, path: str) -> dict:
        options = keyword.options
        if keyword.kind == "SIMP":
            data = {"k": "S", "typ": self.types(options.get("typ"))}
            statut = options.get("statut", "f")
            if statut != "f":
                data["statut"] = statut
            if "defaut" in options and options["defaut"] is not None:
                data["defaut"] = self.value(options["defaut"])
            if "into" in options and options["into"] is not None:
                into = options["into"]
                data["into"] = self.value(
                    into if isinstance(into, (list, tuple, OrderedSet)) else (into,)
                )
            for option in ("min", "max", "val_min", "val_max"):
                if option in options and options[option] is not None:
                    data[option] = self.value(options[option])
            for option in ("val_min_included", "val_max_included"):
                if options.get(option, True) is not True:
                    data[option] = bool(options[option])
            if options.get("validators") is not None:
                data["validators"] = self.validators(options["validators"])
            return data
        if keyword.kind == "FACT":
            data = {"k": "F"}
            statut = options.get("statut", "f")
            if statut != "f":
                data["statut"] = statut
            for option in ("min", "max"):
                if option in options:
                    data[option] = self.value(options[option])
            rules = self.rules(options.get("regles"))
            if rules:
                data["rules"] = rules
            data["entries"] = self.entries(options, path)
            return data
        self.where = path
        data = {"k": "B", "condition": self.condition(options.get("condition"))}
        rules = self.rules(options.get("regles"))
        if rules:
            data["rules"] = rules
        data["entries"] = self.entries(options, path)
        return data

    def command(self, name: str, command: CommandDef) -> dict:
        options = command.options
        self.where = name
        data = {"kind": command.kind}
        reentrant = options.get("reentrant", "n")
        if reentrant != "n":
            data["reentrant"] = reentrant
        sd_prod = options.get("sd_prod")
        if sd_prod is not None:
            data["sd_prod"] = self.sd_prod(sd_prod, name)
        rules = self.rules(options.get("regles"))
        if rules:
            data["rules"] = rules
        legacy = self.legacy(options.get("compat_syntax"))
        if legacy:
            data["legacy"] = legacy
        data["entries"] = self.entries(options, name)
        return data

    def sd_prod(self, sd_prod, name: str):
        if isinstance(sd_prod, TypeRef):
            return {"type": self.type_name(sd_prod)}
        if isinstance(sd_prod, Function):
            table = read_sd_prod(sd_prod.node, self.type_names)
            for key in ("types", "depends"):
                if key in table:
                    table[key] = sorted({self.canonical(t) for t in table[key]})
            return self.canonical_trees(table)
        raise ReadError(f"{name}: sd_prod {sd_prod!r}")

    def canonical_trees(self, data):
        """Expression trees with every ``["t", name]`` under its own name."""
        if isinstance(data, list):
            if len(data) == 2 and data[0] == "t" and isinstance(data[1], str):
                return ["t", self.canonical(data[1])]
            return [self.canonical_trees(item) for item in data]
        if isinstance(data, dict):
            return {k: self.canonical_trees(v) for k, v in data.items()}
        return data

    def legacy(self, compat) -> list[str]:
        """Keyword names a ``compat_syntax`` hook reads or sets (old spellings
        code_aster converts before checking): texts used as keys (``.pop("X")``,
        ``.get("X")``, ``kw["X"]``, ``"X" in kw``, ``{"X": ...}``), not values."""
        if compat is None:
            return []
        functions, seen = [compat], []
        names: set[str] = set()
        while functions:
            function = functions.pop()
            if not isinstance(function, Function) or function in seen:
                continue
            seen.append(function)
            names |= _key_texts(function.node)
            # compat_union(a, b): the functions its closure holds (not the module's)
            if "__name__" not in function.scope.names:
                for value in function.scope.names.values():
                    items = value if isinstance(value, tuple) else (value,)
                    functions.extend(v for v in items if isinstance(v, Function))
        return sorted(n for n in names if re.fullmatch(r"[A-Z][A-Z0-9_]*", n))


def _key_texts(tree) -> set[str]:
    def text(node) -> str | None:
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            return node.value
        return None

    # keys = ("A", "B") then for key in keys: the texts of the named tuple
    named: dict[str, list] = {}
    for node in ast.walk(tree):
        if (
            isinstance(node, ast.Assign)
            and len(node.targets) == 1
            and isinstance(node.targets[0], ast.Name)
            and isinstance(node.value, (ast.Tuple, ast.List))
        ):
            named[node.targets[0].id] = node.value.elts
    found: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.For) and isinstance(node.iter, ast.Name):
            found.update(text(item) for item in named.get(node.iter.id, ()))
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
            if node.func.attr in ("pop", "get", "setdefault") and node.args:
                found.add(text(node.args[0]))
        elif isinstance(node, ast.Subscript):
            found.add(text(node.slice))
        elif isinstance(node, ast.Compare) and any(
            isinstance(op, (ast.In, ast.NotIn)) for op in node.ops
        ):
            found.add(text(node.left))
        elif isinstance(node, ast.Dict):
            found.update(text(key) for key in node.keys if key is not None)
        elif isinstance(node, ast.For) and isinstance(node.iter, (ast.Tuple, ast.List)):
            found.update(text(item) for item in node.iter.elts)  # for old in ("A", "B")
    found.discard(None)
    return found
