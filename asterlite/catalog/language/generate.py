"""Generate the language data of one code_aster version from its catalogues.

Usage (from a fetched code_aster tree, a bare git directory or a checkout)::

    python3 -m asterlite.catalog.language.generate GIT_DIR --version 17
    python3 -m asterlite.catalog.language.generate CHECKOUT --version 15 [--commit REV]
    python3 -m asterlite.catalog.language.generate GIT_DIR --version 17 --output FILE

It reads ``code_aster/Cata/Commands/*.py``, ``Cata/Commons/`` and
``Cata/Language/`` with :mod:`asterlite.catalog.language.reader` (parsed
with :mod:`ast`, never executed) and writes
``catalogues/language/v<N>.json``: every command with its keywords (type,
``statut``, default, ``into``, ``min``/``max``, ``val_min``/``val_max``,
validators), conditional blocks (conditions as expression trees,
:mod:`asterlite.catalog.language.expression`), rules, result type
(:mod:`asterlite.catalog.language.sdprod`), and the type hierarchy. Facts
only: no help text (``fr=``, ``ang=``), comment or code is copied.

The output depends on the catalogue files only: the same tree gives the
same bytes (keys in catalogue order, one command per line, no dates).
"""

from __future__ import annotations

import argparse
import ast
import json
import re
import subprocess
import sys
from pathlib import Path

import asterlite.catalogues.language as installed_language_data
from asterlite.catalog.language.cata_objects import (
    ClassObj,
    CommandDef,
    Function,
    Instance,
    ReadError,
    UserMacroDef,
)
from asterlite.catalog.language.convert import FORMAT, Converter
from asterlite.catalog.language.legacy_layout import generate_legacy, merge_older, read_catalogue
from asterlite.catalog.language.reader import CatalogueReader, Source

PACKAGE = "code_aster"  # files are read relative to this folder
CATA = "code_aster/Cata"

LEGACY_LAST = 12  # the last version whose catalogue was one cata.py (catapy/)


# ------------------------------------------------------------------- sources


class DirectorySource(Source):
    """code_aster's files in a checkout (the folder holding ``code_aster/``)."""

    def __init__(self, root: Path):
        self.repository = Path(root)
        self.root = Path(root) / PACKAGE

    def repository_files(self, folder: str) -> dict[str, str]:
        """Text files directly under ``folder`` of the repository."""
        base = self.repository / folder
        if not base.is_dir():
            return {}
        return {
            p.name: p.read_text(encoding="utf-8") for p in sorted(base.iterdir()) if p.is_file()
        }

    def read(self, path: str) -> str | None:
        file = self.root / path
        return file.read_text(encoding="utf-8") if file.is_file() else None

    def listing(self, folder: str) -> list[str]:
        base = self.root / folder
        return sorted(str(p.relative_to(self.root)) for p in base.rglob("*.py"))

    def describe(self) -> dict:
        return {}


class GitSource(Source):
    """Catalogue files of one commit of a (bare) git directory, read with
    ``git show``: nothing is checked out."""

    def __init__(self, git_dir: Path, commit: str = "HEAD"):
        self.git_dir = str(git_dir)
        self.commit = self._git("rev-parse", "--verify", f"{commit}^{{commit}}").strip()
        listing = self._git("ls-tree", "-r", "--name-only", self.commit, f"{PACKAGE}/")
        self.files = {line[len(PACKAGE) + 1 :] for line in listing.splitlines() if line}
        self.cache: dict[str, str | None] = {}

    def _git(self, *args: str) -> str:
        result = subprocess.run(
            ["git", "--git-dir", self.git_dir, *args],
            capture_output=True,
            text=True,
            check=True,
        )
        return result.stdout

    def read(self, path: str) -> str | None:
        if path not in self.files:
            return None
        if path not in self.cache:
            self.cache[path] = self._git("show", f"{self.commit}:{PACKAGE}/{path}")
        return self.cache[path]

    def listing(self, folder: str) -> list[str]:
        """Python files under ``folder``, subfolders included."""
        prefix = folder + "/"
        return sorted(p for p in self.files if p.startswith(prefix) and p.endswith(".py"))

    def describe(self) -> dict:
        return {"commit": self.commit}

    def repository_files(self, folder: str) -> dict[str, str]:
        """Text files directly under ``folder`` of the commit's tree."""
        listing = self._git("ls-tree", "--name-only", self.commit, f"{folder}/")
        found = {}
        for path in sorted(listing.splitlines()):
            text = self._git("show", f"{self.commit}:{path}")
            found[path.rsplit("/", 1)[-1]] = text
        return found


class OverlaySource(Source):
    """A source with some files added (what code_aster's build generates)."""

    def __init__(self, base: Source, files: dict[str, str]):
        self.base = base
        self.files = files

    def read(self, path: str) -> str | None:
        if path in self.files:
            return self.files[path]
        return self.base.read(path)

    def listing(self, folder: str) -> list[str]:
        return self.base.listing(folder)

    def describe(self) -> dict:
        return self.base.describe()


MFRONT_MODULE = "Cata/Commons/c_mfront_official.py"


def mfront_official(source: Source) -> str | None:
    """``c_mfront_official.py`` as code_aster 13-15's build writes it from
    ``mfront/*.mfront`` (``mfront/wscript``: one ``FACT`` per behaviour of
    its material properties as ``R``, and ``<name>_FO`` as functions),
    read here from each file's ``@MaterialProperty`` declarations and
    their glossary or entry names (MFront itself is not run). None when
    the tree holds the module, or has no MFront behaviour."""
    if source.read(MFRONT_MODULE) is not None or not hasattr(source, "repository_files"):
        return None
    files = {n: t for n, t in source.repository_files("mfront").items() if n.endswith(".mfront")}
    if not files:
        return None
    lines = ["def C_MFRONT_OFFICIAL():", "    keywords = {"]
    for name, text in sorted(files.items()):
        behaviour = name[: -len(".mfront")]
        properties = mfront_properties(text)
        for suffix, typ in (("", "'R'"), ("_FO", "fonction_sdaster")):
            lines.append(f"        '{behaviour}{suffix}': FACT(statut='f',")
            lines += [f"            {p}=SIMP(statut='o', typ={typ})," for p in properties]
            lines.append("        ),")
    lines += ["    }", "    return keywords", ""]
    return "\n".join(lines)


def mfront_properties(text: str) -> list[str]:
    """Material property names of an MFront behaviour, in declaration order
    (arrays as NAME_0, NAME_1...), the stiffness tensor's first when required."""
    text = re.sub(r"//[^\n]*|/\*.*?\*/", "", text, flags=re.S)
    names = {}
    for match in re.finditer(r"(\w+)\s*\.\s*set(?:Glossary|Entry)Name\s*\(\s*\"(\w+)\"", text):
        names[match.group(1)] = match.group(2)
    properties = []
    if re.search(r"@RequireStiffnessTensor\b", text):
        properties += [f"YoungModulus{i}" for i in (1, 2, 3)]
        properties += [f"PoissonRatio{i}" for i in (12, 23, 13)]
        properties += [f"ShearModulus{i}" for i in (12, 23, 13)]
    for match in re.finditer(r"@MaterialProperty\s+[\w:<>]+\s+([^;]+);", text):
        for declared in match.group(1).split(","):
            found = re.fullmatch(r"\s*(\w+)\s*(?:\[\s*(\d+)\s*\])?\s*", declared)
            if not found:
                continue
            external = names.get(found.group(1), found.group(1))
            size = int(found.group(2)) if found.group(2) else 1
            if size <= 1:
                properties.append(external)
            else:
                properties += [f"{external}_{i}" for i in range(size)]
    return properties


def open_source(location: Path, commit: str | None = None) -> Source:
    """A bare git directory (or a checkout's .git) or a plain folder."""
    location = Path(location)
    if (location / "HEAD").is_file() and (location / "objects").is_dir():
        return GitSource(location, commit or "HEAD")
    if (location / ".git").exists() and commit:
        return GitSource(location / ".git", commit)
    return DirectorySource(location)


def _assigned_here(text: str, name: str) -> bool:
    """``name`` is made by this module (not imported from the shared pieces)."""
    return re.search(rf"^{re.escape(name)}\s*=", text or "", re.M) is not None


def callable_command(name: str, instance: Instance) -> dict | None:
    """A module-level object with ``__call__`` (code_aster's VARIABLE): a
    command whose keywords are the call's parameters."""
    cls = instance.cls
    call = cls.attrs.get("__call__") if isinstance(cls, ClassObj) else None
    if not isinstance(call, Function) or not name.isupper():
        return None
    spec = call.node.args
    params = [a.arg for a in spec.args[1:]]
    first_default = len(params) - len(spec.defaults)
    entries = {}
    for index, param in enumerate(params):
        entry = {"k": "S", "typ": ["any"]}
        if index < first_default:
            entry["statut"] = "o"
        entries[param] = entry
    return {"kind": "FUNCTION", "entries": entries}


# ---------------------------------------------------------------- generation

# the package that gives decks their command names (``from code_aster.Commands
# import *``): code_aster 17's CodeCommands, 15's Commands
COMMAND_PACKAGES = ("CodeCommands", "Commands")


def command_aliases(source: Source, known: set) -> dict[str, str]:
    """Names decks call that run another command's catalogue: ``POURSUITE``
    runs ``DEBUT``'s (``POURSUITE = partial(Starter.run, caller="POURSUITE")``
    with ``Starter.command_name = "DEBUT"``). Read from the package that
    makes ``code_aster.Commands`` (syntax trees only)."""
    aliases: dict[str, str] = {}
    for package in COMMAND_PACKAGES:
        text = source.read(f"{package}/__init__.py")
        if text is None:
            continue
        for node in ast.parse(text).body:
            if not (isinstance(node, ast.ImportFrom) and node.level == 1 and node.module):
                continue
            module = source.read(f"{package}/{node.module.replace('.', '/')}.py")
            if module is None:
                continue
            targets = _module_commands(ast.parse(module))
            for alias in node.names:
                exported = alias.asname or alias.name
                target = targets.get(alias.name)
                if target and target != exported and target in known and exported not in known:
                    aliases[exported] = target
        break
    return aliases


def _module_commands(tree: ast.Module) -> dict[str, str]:
    """Module-level ``NAME = Class.run`` / ``partial(Class.run, ...)`` /
    ``UserMacro(..., catalogue, ...)``: NAME -> the catalogue's command name."""
    classes: dict[str, str] = {}
    bases: dict[str, list[str]] = {}
    imported: dict[str, str] = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            bases[node.name] = [b.id for b in node.bases if isinstance(b, ast.Name)]
            for item in node.body:
                if (
                    isinstance(item, ast.Assign)
                    and any(
                        isinstance(t, ast.Name) and t.id == "command_name" for t in item.targets
                    )
                    and isinstance(item.value, ast.Constant)
                ):
                    classes[node.name] = item.value.value
        elif isinstance(node, ast.ImportFrom) and node.module and "Cata" in node.module:
            for alias in node.names:
                imported[alias.asname or alias.name] = alias.name

    def command_of(cls: str, seen=()) -> str | None:
        if cls in classes:
            return classes[cls]
        for base in bases.get(cls, ()):
            if base not in seen:
                found = command_of(base, (*seen, cls))
                if found:
                    return found
        return None

    def resolve(value) -> str | None:
        if isinstance(value, ast.Attribute) and value.attr == "run":
            if isinstance(value.value, ast.Name):
                return command_of(value.value.id)
        if isinstance(value, ast.Call) and isinstance(value.func, ast.Name):
            if value.func.id == "partial" and value.args:
                return resolve(value.args[0])
            if value.func.id == "UserMacro" and len(value.args) >= 2:
                catalogue = value.args[1]
                if isinstance(catalogue, ast.Name):
                    return imported.get(catalogue.id)
                if isinstance(catalogue, ast.Attribute):
                    return catalogue.attr
        return None

    found = {}
    for node in tree.body:
        if isinstance(node, ast.Assign) and len(node.targets) == 1:
            target = node.targets[0]
            if isinstance(target, ast.Name):
                command = resolve(node.value)
                if command:
                    found[target.id] = command
    return found


def supervisor_keywords(source: Source) -> dict[str, list[str]]:
    """Arguments a command's Python wrapper takes out of the keywords before
    their syntax is checked (``FIN(exit=True)``: ``keywords.pop("exit", ...)``
    in the ``change_syntax`` of the class whose ``command_name`` is FIN):
    command -> names. Lower-case names only: upper-case ones are catalogue
    keywords the wrapper renames."""
    found: dict[str, set] = {}
    for package in COMMAND_PACKAGES:
        for path in source.listing(package):
            text = source.read(path) or ""
            if "keywords.pop(" not in text:
                continue
            for node in ast.parse(text).body:
                if not isinstance(node, ast.ClassDef):
                    continue
                command = _class_command_name(node)
                if command is None:
                    continue
                for call in ast.walk(node):
                    name = _popped_name(call)
                    if name is not None and name.islower():
                        found.setdefault(command, set()).add(name)
    return {command: sorted(names) for command, names in sorted(found.items())}


def _class_command_name(node: ast.ClassDef) -> str | None:
    for item in node.body:
        if (
            isinstance(item, ast.Assign)
            and any(isinstance(t, ast.Name) and t.id == "command_name" for t in item.targets)
            and isinstance(item.value, ast.Constant)
        ):
            return item.value.value
    return None


def _popped_name(node) -> str | None:
    """``keywords.pop("name", ...)``: the name."""
    if (
        isinstance(node, ast.Call)
        and isinstance(node.func, ast.Attribute)
        and node.func.attr == "pop"
        and isinstance(node.func.value, ast.Name)
        and node.func.value.id == "keywords"
        and node.args
        and isinstance(node.args[0], ast.Constant)
        and isinstance(node.args[0].value, str)
    ):
        return node.args[0].value
    return None


# the folder of code_aster's Python macros: user macros whose catalogue sits
# beside their implementation (``DEFI_CONT = UserMacro("DEFI_CONT", CATA, ops)``);
# the wrappers of code_aster.Commands (CodeCommands/, 15's Commands/) use the
# catalogues of Cata/Commands, already read

MACRO_FOLDERS = ("MacroCommands",)


def user_macros(source: Source, reader: CatalogueReader, converter, known: set) -> dict:
    """Commands defined by ``UserMacro`` with a catalogue of their own: a deck
    imports them from their module (``from code_aster.MacroCommands.defi_cont
    import DEFI_CONT``), recorded as ``"import": [module...]``."""
    found: dict[str, dict] = {}
    for folder in MACRO_FOLDERS:
        for path in source.listing(folder):
            text = source.read(path) or ""
            if "UserMacro(" not in text:
                continue
            try:
                scope = reader.module(path)
            except ReadError as error:
                converter.problems.append(f"{path}: not read: {error}")
                continue
            module = "code_aster." + path[: -len(".py")].replace("/", ".")
            for name, value in scope.names.items():
                if not isinstance(value, UserMacroDef) or not isinstance(
                    value.catalogue, CommandDef
                ):
                    continue
                catalogue = value.catalogue
                if name in known and catalogue.options.get("nom") == name:
                    continue  # the catalogue command itself (CALC_G...)
                if name in known:
                    continue
                try:
                    data = found.get(name) or converter.command(name, catalogue)
                except ReadError as error:
                    converter.problems.append(f"{path}: {name} not read: {error}")
                    continue
                data.setdefault("import", [])
                if module not in data["import"]:
                    data["import"].append(module)
                found[name] = data
    return found


def generate(source: Source, version: int) -> tuple[dict, list[str]]:
    """The language data of ``source`` and the problems met (modules or
    conditions not read)."""
    generated = mfront_official(source)
    if generated is not None:
        source = OverlaySource(source, {MFRONT_MODULE: generated})
    reader = CatalogueReader(source)
    converter = Converter(reader)
    commands: dict[str, dict] = {}
    for path in source.listing("Cata/Commands"):
        if path.endswith("/__init__.py") or path.count("/") != 2:
            continue
        try:
            scope = reader.module(path)
        except ReadError as error:
            converter.problems.append(f"{path}: not read: {error}")
            continue
        for name, value in scope.names.items():
            if name in commands or name.startswith("_"):
                continue
            try:
                if isinstance(value, CommandDef):
                    if value.options.get("nom", name) != name:
                        continue  # an alias of a command defined under its own name
                    commands[name] = converter.command(name, value)
                elif isinstance(value, Instance) and _assigned_here(source.read(path), name):
                    found = callable_command(name, value)
                    if found is not None:
                        commands[name] = found
            except ReadError as error:
                converter.problems.append(f"{path}: {name} not read: {error}")
    for name, data in user_macros(source, reader, converter, set(commands)).items():
        commands[name] = data
    for name, target in command_aliases(source, set(commands)).items():
        commands[name] = {"alias": target}
    for name, names in supervisor_keywords(source).items():
        if name in commands and "entries" in commands[name]:
            commands[name]["supervisor"] = names
    types = {}
    for name, ref in sorted(reader.types.items()):
        types[converter.canonical(name)] = [converter.canonical(b) for b in ref.bases]
    header = {
        "format": FORMAT,
        "version": version,
        "source": {"catalogues": CATA, **source.describe()},
        "types": types,
    }
    data = {"header": header, "commands": dict(sorted(commands.items()))}
    return data, converter.problems


def dumps(data: dict) -> str:
    """The data as JSON text: the header on one line, then one command per
    line (a command is read alone, without parsing the others)."""
    lines = ["{", '"header": ' + _compact(data["header"]) + ",", '"commands": {']
    names = list(data["commands"])
    for index, name in enumerate(names):
        comma = "," if index < len(names) - 1 else ""
        lines.append(f"{json.dumps(name)}: {_compact(data['commands'][name])}{comma}")
    lines += ["}", "}", ""]
    return "\n".join(lines)


def _compact(value) -> str:
    return json.dumps(value, ensure_ascii=False, separators=(",", ":"), allow_nan=False)


def default_output(version: int) -> Path:
    return Path(installed_language_data.__path__[0]) / f"v{version}.json"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python3 -m asterlite.catalog.language.generate",
        description="write the language data of a code_aster version from its catalogues",
    )
    parser.add_argument("tree", help="a (bare) git directory of code_aster, or a checkout")
    parser.add_argument("--version", type=int, required=True, help="code_aster major version")
    parser.add_argument("--commit", help="commit to read (git directories; default HEAD)")
    parser.add_argument("--output", help="file to write (default: the installed data)")
    parser.add_argument(
        "--catalogue",
        help="versions 10-12: path of an assembled cata.py in the tree (default: catapy/, "
        "else Aster/Cata/cataSTA<version>/cata.py)",
    )
    parser.add_argument(
        "--older",
        metavar="VERSION:COMMIT:PATH",
        action="append",
        help="versions 10-12: an older catalogue of the same tree whose keyword names and "
        "commands the data keeps as legacy (decks of that version read with this data); "
        "repeated, newest first",
    )
    args = parser.parse_args(argv)
    if args.version <= LEGACY_LAST:  # one cata.py of Python 2 (legacy_layout)
        text, where, types = read_catalogue(
            Path(args.tree), args.version, args.commit, args.catalogue
        )
        data, problems = generate_legacy(text, args.version, where, types)
        for given in args.older or ():  # newest first
            label, commit, path = given.split(":", 2)  # label: "11.0", "10"
            major = int(label.split(".")[0])
            text, where, types = read_catalogue(Path(args.tree), major, commit, path)
            older, older_problems = generate_legacy(text, major, where, types)
            problems += [f"older {label}: {p}" for p in older_problems]
            data = merge_older(data, older, label)
    else:
        source = open_source(Path(args.tree), args.commit)
        data, problems = generate(source, args.version)
    output = Path(args.output) if args.output else default_output(args.version)
    output.write_text(dumps(data), encoding="utf-8")
    print(f"{output}: {len(data['commands'])} commands, {len(data['header']['types'])} types")
    for problem in problems:
        print(f"  note: {problem}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
