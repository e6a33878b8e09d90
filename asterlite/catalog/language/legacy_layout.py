"""The language of code_aster 10-12 from its catalogue, laid out the old way.

Up to code_aster 12 the command language was one Python 2 module, ``cata.py``,
that code_aster's build concatenated from ``catapy/entete/*.capy`` (the
header, ``accas.capy`` first, then the concept classes ``co_*.capy``),
``catapy/commun/*.capy`` (shared pieces such as ``C_SOLVEUR``) and
``catapy/commande/*.capy`` (one command each), every piece starting with a
``#& MODIF`` line. The vocabulary came from ``Accas``: ``OPER``, ``MACRO``,
``PROC``, ``FORM``, ``SIMP``, ``FACT``, ``BLOC``, the rules under their French
names (``UN_PARMI``, ``EXCLUS``...), ``ASSD`` the root of concept types and
``GEOM`` that of mesh entities.

This module reads such a catalogue: an assembled ``cata.py`` (as SALOME's
Eficas keeps each version's, ``Aster/Cata/cataSTA11/cata.py``) or a tree with
``catapy/``, from a folder or a git directory. Each piece is parsed with
:mod:`ast` (the few Python 2 spellings a piece uses, ``<>`` and octal
literals such as ``min=01``, rewritten first, only in pieces Python 3 cannot
parse) and walked by :class:`~asterlite.catalog.language.reader.CatalogueReader`
in one namespace, as Python ran the module; nothing is executed. Concept types
are the classes whose bases lead to ``ASSD`` or ``GEOM`` (read from the
syntax trees, their methods never run). The result has the layout of
:mod:`asterlite.catalog.language.generate`'s data, made by its converter
(:class:`~asterlite.catalog.language.convert.Converter`).
"""

from __future__ import annotations

import ast
import io
import re
import subprocess
import tokenize
from pathlib import Path

from asterlite.catalog.language.cata_objects import (
    CataObject,
    CommandDef,
    Keyword,
    Opaque,
    ReadError,
    Scope,
    TypeRef,
)
from asterlite.catalog.language.convert import FORMAT, ROOT_TYPE, Converter
from asterlite.catalog.language.model import keyword_paths
from asterlite.catalog.language.reader import CatalogueReader, Source
from asterlite.catalog.language.subset_values import _builtin

PIECE = re.compile(r"(?m)^(?=#& MODIF )")
# Accas's rule classes under the names old catalogues write -> the reader's kinds
OLD_RULES = {
    "AU_MOINS_UN": "AtLeastOne",
    "UN_PARMI": "ExactlyOne",
    "EXCLUS": "AtMostOne",
    "PRESENT_PRESENT": "IfFirstAllPresent",
    "PRESENT_ABSENT": "OnlyFirstPresent",
    "ENSEMBLE": "AllTogether",
}
# concept types Accas itself defines (not the catalogue): name -> bases
ACCAS_TYPES = {
    "ASSD": (),
    "GEOM": (),
    "CO": ("ASSD",),
    "formule": ("ASSD",),
    "formule_c": ("formule",),
    "not_checked": ("ASSD",),  # any value (TEST_FICHIER's VALE)
}
# names of Accas a catalogue uses at module level for other things than keywords
ACCAS_OTHERS = ("JDC_CATA", "A_CLASSER", "AsException", "ASSD_CATA")
# rules of the sensitivity machinery (code_aster <= 11's SENSIBILITE): they name
# how derived concepts are made, not which keywords a call may give
SENSITIVITY_RULES = ("CONCEPT_SENSIBLE", "REUSE_SENSIBLE", "DERIVABLE")
# Python 2's module ``types``: the names catalogues compare ``type(x)`` with
PYTHON2_TYPES = {
    "StringType": "str",
    "ListType": "list",
    "TupleType": "tuple",
    "IntType": "int",
    "FloatType": "float",
    "DictType": "dict",
}
CATAPY = ("catapy/entete", "catapy/commun", "catapy/commande")


# ------------------------------------------------------------------ the text


def git_show(git_dir: Path, commit: str, path: str) -> str:
    result = subprocess.run(
        ["git", "--git-dir", str(git_dir), "show", f"{commit}:{path}"],
        capture_output=True,
        check=True,
    )
    return result.stdout.decode("latin-1")


def git_commit(git_dir: Path, commit: str) -> str:
    result = subprocess.run(
        ["git", "--git-dir", str(git_dir), "rev-parse", "--verify", f"{commit}^{{commit}}"],
        capture_output=True,
        text=True,
        check=True,
    )
    return result.stdout.strip()


def git_listing(git_dir: Path, commit: str, folder: str) -> list[str]:
    result = subprocess.run(
        ["git", "--git-dir", str(git_dir), "ls-tree", "--name-only", commit, folder + "/"],
        capture_output=True,
        text=True,
        check=True,
    )
    return sorted(line for line in result.stdout.splitlines() if line.endswith(".capy"))


def catapy_order(paths: list[str]) -> list[str]:
    """The order code_aster's build concatenated ``catapy/``: the header's
    ``accas.capy`` first, then each folder's pieces by name."""
    ordered = []
    for folder in CATAPY:
        inside = sorted(p for p in paths if p.rsplit("/", 1)[0].endswith(folder))
        inside.sort(key=lambda p: not p.endswith("/accas.capy"))
        ordered += inside
    return ordered


def is_git_dir(location: Path) -> bool:
    return (location / "HEAD").is_file() and (location / "objects").is_dir()


def read_catalogue(
    location: Path, version: int, commit: str | None = None, catalogue: str | None = None
) -> tuple[str, dict, list[str]]:
    """(text of the assembled catalogue, where it comes from, texts of the
    modules ``SD/co_*.py`` beside it: code_aster 10 defined its concept
    types there, imported by the catalogue).

    ``location`` is a ``cata.py`` file, a folder holding ``catapy/`` or
    ``catalogue``, or a git directory (``commit``, default HEAD; ``catalogue``
    the path of an assembled ``cata.py``, default ``catapy/`` if the tree has
    it, else ``Aster/Cata/cataSTA<version>/cata.py``)."""
    location = Path(location)
    if location.is_file():
        types = _folder_types(location.parent / "SD")
        return location.read_bytes().decode("latin-1"), {"file": location.name}, types
    if is_git_dir(location):
        revision = git_commit(location, commit or "HEAD")
        if catalogue is None:
            pieces = [p for f in CATAPY for p in git_listing(location, revision, f)]
            if pieces:
                text = "".join(git_show(location, revision, p) for p in catapy_order(pieces))
                types = _git_types(location, revision, "bibpyt/SD")
                return text, {"catalogues": "catapy", "commit": revision}, types
            catalogue = f"Aster/Cata/cataSTA{version}/cata.py"
        text = git_show(location, revision, catalogue)
        types = _git_types(location, revision, catalogue.rsplit("/", 1)[0] + "/SD")
        return text, {"catalogues": catalogue, "commit": revision}, types
    if catalogue is not None:
        file = location / catalogue
        types = _folder_types(file.parent / "SD")
        return file.read_bytes().decode("latin-1"), {"catalogues": catalogue}, types
    pieces = [str(p.relative_to(location)) for f in CATAPY for p in (location / f).glob("*.capy")]
    if not pieces:
        raise ReadError(f"{location}: no catapy/ folder and no catalogue file given")
    ordered = catapy_order(pieces)
    text = "".join((location / p).read_bytes().decode("latin-1") for p in ordered)
    return text, {"catalogues": "catapy"}, _folder_types(location / "bibpyt" / "SD")


def _git_types(git_dir: Path, commit: str, folder: str) -> list[str]:
    result = subprocess.run(
        ["git", "--git-dir", str(git_dir), "ls-tree", "--name-only", commit, folder + "/"],
        capture_output=True,
        text=True,
        check=True,
    )
    paths = sorted(p for p in result.stdout.splitlines() if p.rsplit("/", 1)[-1].startswith("co_"))
    return [git_show(git_dir, commit, p) for p in paths if p.endswith(".py")]


def _folder_types(folder: Path) -> list[str]:
    if not folder.is_dir():
        return []
    return [p.read_bytes().decode("latin-1") for p in sorted(folder.glob("co_*.py"))]


def pieces(text: str) -> list[str]:
    """The catalogue cut where each ``.capy`` piece began."""
    return [piece for piece in PIECE.split(text) if piece.strip()]


def python3(text: str) -> str:
    """``text`` with the Python 2 spellings of old catalogues rewritten:
    ``a <> b`` as ``a != b``, octal ``01`` as its value, ``10L`` as ``10``
    (strings and comments untouched)."""
    edits = []
    lines = text.splitlines(keepends=True)
    offsets = [0]
    for line in lines:
        offsets.append(offsets[-1] + len(line))
    tokens = list(tokenize.generate_tokens(io.StringIO(text).readline))

    def where(point) -> int:
        return offsets[point[0] - 1] + point[1]

    index = 0
    while index < len(tokens):
        token = tokens[index]
        after = tokens[index + 1] if index + 1 < len(tokens) else None
        if token.string == "<" and after is not None and after.string == ">":
            if after.start == token.end:
                edits.append((where(token.start), where(after.end), "!="))
        elif token.type == tokenize.NUMBER:
            # Python 3 cuts ``01`` and ``10L`` into glued tokens: join them back
            last = index
            while (
                last + 1 < len(tokens)
                and tokens[last + 1].start == tokens[last].end
                and (
                    tokens[last + 1].type == tokenize.NUMBER
                    or tokens[last + 1].string in ("L", "l")
                )
            ):
                last += 1
            joined = "".join(t.string for t in tokens[index : last + 1])
            value = joined.rstrip("Ll")
            span = (where(token.start), where(tokens[last].end))
            if re.fullmatch(r"0[0-7]+", value):
                edits.append((*span, str(int(value, 8))))
            elif value != joined and re.fullmatch(r"\d+", value):
                edits.append((*span, value))
            index = last
        index += 1
    for start, end, new in sorted(edits, reverse=True):
        text = text[:start] + new + text[end:]
    return text


def parse_piece(piece: str) -> tuple[ast.Module, list[str]]:
    """A piece as a syntax tree, and what of it could not be parsed: a
    top-level statement Python 3 cannot read even rewritten (``print x`` in
    a method) is left out, a class keeping its name and bases."""
    try:
        return ast.parse(piece), []
    except SyntaxError:
        pass
    text = python3(piece)
    try:
        return ast.parse(text), []
    except SyntaxError:
        pass
    body, problems = [], []
    chunks = re.split(r"(?m)^(?=[^\s#)\]}])", text)
    offset = 0
    for chunk in chunks:
        try:
            tree = ast.parse(chunk)
        except SyntaxError as error:
            head = re.match(r"class\s+\w+\s*(?:\([^)]*\))?\s*:", chunk)
            line = offset + (error.lineno or 1)
            if head:
                tree = ast.parse(head.group(0) + " pass")
            else:
                problems.append(f"line {line} not parsed: {error.msg}")
                tree = ast.Module(body=[], type_ignores=[])
        ast.increment_lineno(tree, offset)
        body += tree.body
        offset += chunk.count("\n")
    return ast.Module(body=body, type_ignores=[]), problems


# ----------------------------------------------------------------- the types


def concept_types(trees: list[ast.Module]) -> dict[str, tuple[str, ...]]:
    """Classes whose bases lead to ``ASSD`` or ``GEOM``: name -> those bases
    (others, such as the data structure mixins ``sd_*``, left out)."""
    classes: dict[str, tuple[str, ...]] = {}
    for tree in trees:
        for node in tree.body:
            if isinstance(node, ast.ClassDef):
                bases = tuple(b.id for b in node.bases if isinstance(b, ast.Name))
                classes.setdefault(node.name, bases)
    found = dict(ACCAS_TYPES)
    changed = True
    while changed:
        changed = False
        for name, bases in classes.items():
            if name in found:
                continue
            kept = tuple(b for b in bases if b in found)
            if kept:
                found[name] = kept
                changed = True
    return found


# ---------------------------------------------------------------- the reader


class _NoFiles(Source):
    def read(self, path: str) -> str | None:
        return None

    def listing(self, folder: str) -> list[str]:
        return []


class LegacyReader(CatalogueReader):
    """The reader with Accas's vocabulary of code_aster 10-12."""

    def __init__(self, types: dict[str, tuple[str, ...]]):
        self._legacy_types = types
        super().__init__(_NoFiles())

    def _syntax_names(self) -> dict:
        self.types = {
            (ROOT_TYPE if name == "ASSD" else name): TypeRef(
                ROOT_TYPE if name == "ASSD" else name,
                tuple(ROOT_TYPE if b == "ASSD" else b for b in bases),
            )
            for name, bases in self._legacy_types.items()
        }
        self.type_aliases = {"ASSD": ROOT_TYPE}
        names = super()._syntax_names()
        names["ASSD"] = self.types[ROOT_TYPE]
        names["geom"] = self.types["GEOM"]  # Accas's alias of GEOM
        for name in SENSITIVITY_RULES:
            names[name] = _builtin(lambda *args, name=name: SensitivityRule(name))
        names["SIMP"] = _builtin(_simp)
        names["FACT"] = _builtin(_fact)
        for old, kind in OLD_RULES.items():
            names[old] = names[kind]
        for name in ACCAS_OTHERS:
            names[name] = Opaque(name)
        return names

    def _import_from(self, node: ast.ImportFrom, scope: Scope, module: str) -> None:
        # ``from SD.co_table import table_sdaster``: the concept types read apart
        super()._import_from(node, scope, module)
        for alias in node.names:
            name = ROOT_TYPE if alias.name == "ASSD" else alias.name
            if name in self.types:
                scope.names[alias.asname or alias.name] = self.types[name]

    def _attribute(self, owner, name: str):
        # ``op=ops.build_formule``, ``Accas.ASSD``: names of modules not read
        if isinstance(owner, Opaque):
            if owner.name == "types" and name in PYTHON2_TYPES:  # types.StringType is str
                return self.type_builtins[PYTHON2_TYPES[name]]
            return Opaque(f"{owner.name}.{name}")
        return super()._attribute(owner, name)

    def call(self, function, args: list, kwargs: dict):
        if isinstance(function, Opaque) and function.name in ACCAS_OTHERS:
            return Opaque(function.name)  # JdC = JDC_CATA(...): not a command
        return super().call(function, args, kwargs)


class SensitivityRule(CataObject):
    def __init__(self, name: str):
        self.name = name


def _simp(typ=None, *texts, **options):
    """Accas's ``SIMP(typ, fr, ang, ...)``: the type may come first, help texts after."""
    if any(not isinstance(t, str) for t in texts):
        raise ReadError("SIMP with positional arguments other than help texts")
    return Keyword("SIMP", {"typ": typ, **options} if typ is not None else dict(options))


def _fact(*texts, **options):
    """Accas's ``FACT(fr, ang, docu, ...)``: help texts may come first."""
    if any(not isinstance(t, str) for t in texts):
        raise ReadError("FACT with positional arguments other than help texts")
    return Keyword("FACT", dict(options))


# old Accas's condition functions, given a keyword's value -> (negated, today's,
# given its name): some value among the choices, none among them
OLD_CONDITION_CALLS = {"au_moins_un": (False, "is_in"), "aucun": (True, "is_in")}


class _OldConditionCalls(ast.NodeTransformer):
    def visit_Call(self, node):
        self.generic_visit(node)
        if (
            isinstance(node.func, ast.Name)
            and node.func.id in OLD_CONDITION_CALLS
            and len(node.args) == 2
            and isinstance(node.args[0], ast.Name)
        ):
            negated, today = OLD_CONDITION_CALLS[node.func.id]
            call = ast.Call(ast.Name(today), [ast.Constant(node.args[0].id), node.args[1]], [])
            return ast.UnaryOp(ast.Not(), call) if negated else call
        return node


def _given_or_none(tree):
    """Old Accas evaluated a block's condition with every keyword of the
    level, None when not given (``RESULTAT != None``), where code_aster 13 on
    leaves it undefined (``exists("RESULTAT")``): ``["k", X]`` -> ``["kv", X]``."""
    if isinstance(tree, list):
        if len(tree) == 2 and tree[0] == "k" and isinstance(tree[1], str):
            return ["kv", tree[1]]
        return [_given_or_none(item) for item in tree]
    return tree


class LegacyConverter(Converter):
    def condition(self, text):
        if isinstance(text, str):
            try:
                tree = ast.parse(" ".join(python3(text).split()), mode="eval")
            except SyntaxError:
                pass  # kept as written: the converter says it is never true
            else:
                text = ast.unparse(_OldConditionCalls().visit(tree))
        return _given_or_none(super().condition(text))

    def rules(self, regles) -> list:
        if isinstance(regles, (list, tuple)):
            regles = tuple(r for r in regles if not isinstance(r, SensitivityRule))
        elif isinstance(regles, SensitivityRule):
            regles = ()
        return super().rules(regles)

    def sd_prod(self, sd_prod, name: str):
        if isinstance(sd_prod, Opaque):
            return None  # ops.DEBUT, ops.INCLUDE: a function of the supervisor (no concept)
        return super().sd_prod(sd_prod, name)

    def command(self, name: str, command: CommandDef) -> dict:
        data = super().command(name, command)
        if "sd_prod" in data and data["sd_prod"] is None:
            del data["sd_prod"]
        return data


def generate_legacy(
    text: str, version: int, source: dict, type_modules: list[str] = ()
) -> tuple[dict, list[str]]:
    """The language data of an old-layout catalogue ``text`` (with the
    modules defining its concept types, if apart) and the problems met."""
    problems: list[str] = []
    type_trees = []
    for module in type_modules:
        type_trees.append(parse_piece(module)[0])  # only its classes are read
    trees = []
    for piece in pieces(text):
        head = piece.splitlines()[0][:60].strip()
        tree, lost = parse_piece(piece)
        trees.append(tree)
        problems += [f"{head}: {text}" for text in lost]
    types = concept_types(type_trees + trees)
    reader = LegacyReader(types)
    converter = LegacyConverter(reader)
    scope = Scope({"__name__": "cata"}, reader._builtins())
    order: list[str] = []
    for tree in trees:
        for node in tree.body:
            if isinstance(node, ast.ClassDef) and node.name in types:
                continue  # a concept type: already a TypeRef
            reader.steps = 0
            try:
                reader._run(node, scope, "cata")
            except (ReadError, LookupError, TypeError, ValueError) as error:
                what = ", ".join(_targets(node)) or type(node).__name__
                problems.append(f"line {node.lineno} ({what}): not read: {error}")
                continue
            order += [t for t in _targets(node) if t not in order]
    commands: dict[str, dict] = {}
    for name in order:
        value = scope.names.get(name)
        if not isinstance(value, CommandDef) or name.startswith("_"):
            continue
        if value.options.get("nom", name) != name:
            continue
        try:
            commands[name] = converter.command(name, value)
        except ReadError as error:
            problems.append(f"{name} not read: {error}")
    problems += converter.problems
    type_data = {}
    for name, ref in sorted(reader.types.items()):
        type_data[converter.canonical(name)] = [converter.canonical(b) for b in ref.bases]
    header = {"format": FORMAT, "version": version, "source": source, "types": type_data}
    return {"header": header, "commands": dict(sorted(commands.items()))}, problems


def _targets(node: ast.stmt) -> list[str]:
    if isinstance(node, ast.Assign):
        return [t.id for t in node.targets if isinstance(t, ast.Name)]
    if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
        return [node.name]
    return []


# ------------------------------------------------------- an older catalogue


def merge_older(data: dict, older: dict, label: str) -> dict:
    """``data`` reading decks of the versions before it too: a keyword the
    older catalogue had in a command and ``data``'s lacks at that level has
    its name recorded in the command's ``legacy`` names (accepted, its level not
    judged: the check cannot tell where the older spelling went), and a
    command only the older catalogue has is kept with the older data,
    marked ``"older": label`` (the version the older catalogue is of, as
    ``"11.0"`` or ``"10"``)."""
    commands = data["commands"]
    for name, old in older["commands"].items():
        if name not in commands:
            commands[name] = {**old, "older": label}
            continue
        if "older" in commands[name]:  # a command an older catalogue gave already
            continue
        gone = {path[-1] for path in keyword_paths(old) - keyword_paths(commands[name])}
        if gone:
            legacy = set(commands[name].get("legacy", ())) | gone
            commands[name]["legacy"] = sorted(legacy)
    data["commands"] = dict(sorted(commands.items()))
    source = {"version": label, **older["header"]["source"]}
    data["header"]["older"] = [*data["header"].get("older", ()), source]
    return data
