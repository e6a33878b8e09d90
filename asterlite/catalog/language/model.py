"""The language data of a code_aster version, read lazily.

``catalogues/language/v<N>.json`` (written by
:mod:`asterlite.catalog.language.generate`) holds a header (types and their
bases) and one command per line. :func:`language` indexes the lines once
(a few milliseconds) and parses a command's line only when a deck calls
it, so that ``asterlite check`` of a deck stays fast.

A command is a dict::

    {"kind": "OPER"|"MACRO"|"PROC"|"FORM"|"FUNCTION",
     "reentrant": "n"|"o"|"f"[":KEYWORD"], "sd_prod": {...},
     "rules": [[RULE, names...], ...], "legacy": [names...],
     "supervisor": [names...], "entries": {NAME: entry}}

(``supervisor``: arguments the command's Python wrapper takes out before
the syntax is checked, ``FIN(exit=True)``)

and an entry ``{"k": "S"|"F"|"B", ...}``: a simple keyword (``typ``,
``statut``, ``defaut``, ``into``, ``min``, ``max``, ``val_min``,
``val_max``, ``validators``), a factor keyword (``statut``, ``min``,
``max``, ``rules``, ``entries``) or a block (``condition``, ``rules``,
``entries``).
"""

from __future__ import annotations

import json
from functools import cache
from pathlib import Path

import asterlite.catalogues.language as package

DATA_PACKAGE = "asterlite.catalogues.language"
LEGACY_LAST = 12  # the last version whose catalogue was one cata.py (catapy/)
OLD_LAYOUT_DATA = {10: 11}  # old-layout versions read with another's data


def _data_folder() -> Path:
    return Path(package.__path__[0])


@cache
def available_versions() -> tuple[int, ...]:
    """Versions whose language data is installed, oldest first."""
    found = []
    for path in _data_folder().glob("v*.json"):
        if path.stem[1:].isdigit():
            found.append(int(path.stem[1:]))
    return tuple(sorted(found))


def data_version(version: int) -> int | None:
    """The data a deck of code_aster ``version`` is validated with: its own,
    else 11's for 10 (one data set of the old layout: the 11 catalogue with
    the keyword names of 10 it dropped), else that of the nearest version
    from 13 on (13-14 read as 15, 16 as 17). None for 12: decks detected as
    12 (DYNA_TRAN_MODAL with VALE_CALC, 2012-2013) mix spellings no single
    catalogue of the snapshot has (MODE_ITER_SIMULT's MATR_A of 2011 beside
    the VALE_CALC and ASSEMBLAGE of 2013); they are checked against
    asterlite's catalogues only."""
    versions = available_versions()
    if version in versions:
        return version
    if version <= LEGACY_LAST:
        return OLD_LAYOUT_DATA.get(version) if OLD_LAYOUT_DATA.get(version) in versions else None
    versions = [v for v in versions if v > LEGACY_LAST]
    if not versions:
        return None
    return min(versions, key=lambda v: (abs(v - version), -v))


class Language:
    """Commands and types of one code_aster version."""

    def __init__(self, version: int, text: str):
        self.version = version
        lines = text.split("\n")
        header_line = next(line for line in lines if line.startswith('"header": '))
        self.header = json.loads(header_line[len('"header": ') :].rstrip(","))
        self.types: dict[str, list[str]] = self.header["types"]
        self._lines: dict[str, str] = {}
        for line in lines:
            if line.startswith('"') and not line.startswith(('"header"', '"commands"')):
                end = line.index('"', 1)
                if line[end : end + 3] == '": ':
                    self._lines[line[1:end]] = line[end + 3 :].rstrip(",")
        self._commands: dict[str, dict] = {}
        self._ancestors: dict[str, frozenset[str]] = {}

    @property
    def command_names(self) -> frozenset[str]:
        return frozenset(self._lines)

    def has_command(self, name: str) -> bool:
        """Whether the version has command ``name`` (without reading its data)."""
        return name in self._lines

    def command(self, name: str) -> dict | None:
        """The data of command ``name``, or None when the version has none
        (a name that runs another command's catalogue gives that one's)."""
        found = self._commands.get(name)
        if found is None and name in self._lines:
            found = json.loads(self._lines[name])
            if "alias" in found:
                found = self.command(found["alias"])
            self._commands[name] = found
        return found

    def is_deck_command(self, name: str) -> bool:
        """A name ``from code_aster.Commands import *`` gives (user macros such
        as DEFI_CONT are imported from their own module)."""
        return '"import":' not in self._lines.get(name, '"import":')

    def module_commands(self, module: str) -> list[str]:
        """Commands a deck imports from ``module`` (code_aster.MacroCommands...)."""
        return [
            name
            for name, line in self._lines.items()
            if f'"{module}"' in line
            and (self.command(name) or {}).get("import")
            and module in self.command(name)["import"]
        ]

    def ancestors(self, type_name: str) -> frozenset[str]:
        """``type_name`` and every type it derives from."""
        found = self._ancestors.get(type_name)
        if found is None:
            seen, todo = set(), [type_name]
            while todo:
                name = todo.pop()
                if name not in seen:
                    seen.add(name)
                    todo.extend(self.types.get(name, ()))
            found = self._ancestors[type_name] = frozenset(seen)
        return found

    def is_type(self, name: str) -> bool:
        return name in self.types

    def is_subtype(self, type_name: str, expected: str) -> bool:
        return expected == "assd" or expected in self.ancestors(type_name)

    def __repr__(self) -> str:
        return f"<code_aster {self.version} language: {len(self._lines)} commands>"


@cache
def language(version: int) -> Language | None:
    """The language data for decks of code_aster ``version`` (see
    :func:`data_version`), or None when there is none."""
    chosen = data_version(version)
    if chosen is None:
        return None
    path = _data_folder() / f"v{chosen}.json"
    return Language(chosen, path.read_text(encoding="utf-8"))


def keyword_paths(command: dict) -> set[tuple[str, ...]]:
    """Every keyword of a command's data as its path of factor keywords
    (blocks left out: a keyword of a block belongs to the block's level)."""
    found: set[tuple[str, ...]] = set()

    def visit(entries: dict, prefix: tuple[str, ...]) -> None:
        for name, entry in entries.items():
            if entry.get("k") == "B":
                visit(entry.get("entries", {}), prefix)
            else:
                found.add((*prefix, name))
                visit(entry.get("entries", {}), (*prefix, name))

    visit(command.get("entries", {}), ())
    return found
