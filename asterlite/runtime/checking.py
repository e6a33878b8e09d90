"""What ``asterlite check`` verifies beyond the catalogues, and how it keeps
going after an error so that one pass reports every error of a deck.

- Every error is recorded (:class:`CheckFacts`.errors); the names the failed
  statement or command would have bound become Unknown, so later uses of
  them are not reported again.
- Meshes are read for real (LIRE_MAILLAGE, then DEFI_GROUP, CREA_MAILLAGE
  and MODI_MAILLAGE run as under ``run`` when their keywords hold no
  uncomputed value): group, node and cell names given to other commands
  must exist in one of them. As soon as a mesh check cannot follow exists
  (read from a unit the deck writes, transformed with uncomputed values,
  made by a command that failed...), names are no longer judged: check
  never reports what run might accept.
- Logical units a reading command (LIRE_*) uses must be mapped by the
  export, written earlier by the deck (IMPR_*, DYNA_VIBRA's IMPRESSION
  units...) or mapped by DEFI_FICHIER.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from asterlite.catalog import load_catalogue
from asterlite.catalog.language.model import language
from asterlite.catalog.model import BLOC, FACT, SIMP
from asterlite.catalogues import _code_aster_commands as names
from asterlite.concepts.base import AnyPlaceholder, Placeholder
from asterlite.errors import CommandError, UnsupportedError
from asterlite.lang.bindings import statement_outputs
from asterlite.lang.values import CallSite, DeckCallable, Unknown, co_outputs

if TYPE_CHECKING:
    from asterlite.catalog.keywords import Keywords

# commands run for real under check: they read or reshape meshes, cheaply
MESH_COMMANDS = ("LIRE_MAILLAGE", "DEFI_GROUP", "CREA_MAILLAGE", "MODI_MAILLAGE")
# commands that read the file mapped to their UNITE keyword
READERS = (
    "LIRE_MAILLAGE",
    "LIRE_FONCTION",
    "LIRE_TABLE",
    "LIRE_RESU",
    "LIRE_CHAMP",
    "LIRE_INTE_SPEC",
    "LIRE_FORC_MISS",
    "LIRE_IMPE_MISS",
)
# catalogue types of names that must exist in the mesh
NAME_TYPES = {"grma": "cell group", "grno": "node group", "no": "node", "ma": "cell"}
# keywords typed as mesh names that the command resolves otherwise (a shock's
# name or node number, a node looked up leniently): never judged here
NOT_MESH_NAMES = {
    "POST_USURE": ("NOEUD", "GROUP_NO"),
    "RECU_FONCTION": ("NOEUD_CHOC", "GROUP_NO_CHOC"),
    # the groups of the column mesh the macro writes itself (without MAILLAGE)
    "DEFI_SOL_EQUI": (
        "GROUP_MA_DROITE",
        "GROUP_MA_GAUCHE",
        "GROUP_MA_COL",
        "GROUP_MA_SUBSTR",
        "GROUP_MA",
        "LIST_COUCHE_ACCE",
    ),
}


# ----------------------------------------------------------- code_aster commands


def code_aster_commands() -> dict[str, str]:
    """Every code_aster command name -> the version whose catalogue lists it."""

    known = dict.fromkeys(names.CURRENT, "17")
    for name, version in names.OLDER.items():
        known.setdefault(name, version)
    for name in _legacy_language_commands():  # code_aster 10-12's, gone by 15
        known.setdefault(name, LEGACY_COMMANDS_VERSION)
    return known


LEGACY_COMMANDS_VERSION = "10-12"


def _legacy_language_commands() -> frozenset[str]:
    """The commands of code_aster 10-12's language data (v11.json)."""

    old = language(11)
    return old.command_names if old is not None else frozenset()


class UnsupportedCommand(DeckCallable):
    """A code_aster command asterlite does not implement: calling it is
    refused by name (a misspelled name, by contrast, stays a NameError)."""

    def __init__(self, name: str, version: str):
        self.name = name
        self.version = version

    def __repr__(self) -> str:
        return f"<code_aster command {self.name} (not in asterlite)>"

    def deck_call(self, args, kwargs, site: CallSite):
        if self.version == LEGACY_COMMANDS_VERSION:
            raise UnsupportedError(
                f"{self.name} is a code_aster 10-12 command that code_aster 15 and 17 no "
                "longer have; asterlite does not translate it",
                site.location,
                self.name,
            )
        where = "current" if self.version == "17" else f"version {self.version}"
        raise UnsupportedError(
            f"{self.name} is a code_aster command ({where} catalogue) that asterlite "
            "does not implement",
            site.location,
            self.name,
        )


# ------------------------------------------------------------------ facts


@dataclass
class CheckFacts:
    """What a check has learnt so far: its errors, the meshes it read, the
    units the deck wrote or mapped, and whether names can still be judged.

    ``errors`` is asterlite's own verdict, the errors ``run`` would meet
    (``run_deck(check_only=True)``: CHECKED, ERROR or UNSUPPORTED).
    ``findings`` are the two verdicts of ``asterlite check`` (valid code_aster
    N, computed by asterlite: see :mod:`asterlite.runtime.language_check`):
    the language's own findings, and each error told apart by kind."""

    errors: list = field(default_factory=list)
    meshes: list = field(default_factory=list)  # every real Mesh read or made
    names_open: bool = False  # a mesh check cannot see may exist
    units_open: set[int] = field(default_factory=set)  # units written or mapped by the deck
    # the deck's Python wrote files check did not follow (open()): any unit may be mapped
    units_unknown: bool = False
    session: Any = None  # the session checked
    findings: list = field(default_factory=list)
    calls: list = field(default_factory=list)  # the command calls under way (language_check)
    # (session, error) -> findings: language_check.finding_of_error, given by the session
    finding_of_error: Any = None

    def record(self, error) -> None:
        if self.errors and error in (self.errors[-1], getattr(self.errors[-1], "original", None)):
            return
        self.errors.append(error)
        if getattr(error, "touches_files", False):
            self.units_unknown = True
        if self.session is not None and self.finding_of_error is not None:
            self.findings.extend(self.finding_of_error(self.session, error))

    def note(self, finding) -> None:
        """A finding of the two verdicts that is no error of asterlite's own."""
        self.findings.append(finding)

    def close_names(self, reason: str = "") -> None:
        self.names_open = True


def check_call(proxy, catalogue, keywords: Keywords, site: CallSite, reuse):
    """The result of a validated command call under check (a placeholder, or
    the real concept for mesh commands), after the checks run would fail on."""
    session, name = proxy.session, proxy.name
    facts: CheckFacts = session.check
    if name in READERS:
        _check_read_unit(session, keywords, site, name)
    if name in MESH_COMMANDS and _computable(keywords, reuse):
        if name != "LIRE_MAILLAGE" or _unit_readable(session, keywords):
            try:
                concept = proxy._execute(keywords, site, reuse)
            except CommandError as error:
                # asterlite's own reading or processing of the mesh, not the deck
                error.asterlite_limit = True
                facts.close_names()
                raise
            except (ArithmeticError, ValueError, IndexError, KeyError, TypeError) as error:
                # a bug of asterlite's mesh command: the deck's validity is not in
                # question; what the command would make is unknown
                facts.close_names()
                failure = CommandError(
                    f"asterlite's {name} stopped on an internal error (please report): "
                    f"{type(error).__name__}: {error}",
                    site.location,
                    name,
                )
                failure.asterlite_limit = True
                raise failure from error
            facts.meshes.append(concept)
            _note_written_units(name, keywords, facts)
            return concept
    if name not in MESH_COMMANDS:
        check_mesh_names(catalogue, keywords, facts, NOT_MESH_NAMES.get(name, ()))
    _note_written_units(name, keywords, facts)
    result = proxy._placeholder(catalogue, keywords)
    if _may_be_mesh(result) or name in MESH_COMMANDS:
        facts.close_names()  # a mesh (or a change of one) check did not compute
    if reuse is not None and name in MESH_COMMANDS:
        facts.close_names()
    return result


def command_failed(session, name: str, kwargs: dict, error) -> None:
    """After a failed call: record the error; CO outputs become Unknown, and a
    failed command that may make a mesh stops the judging of names."""

    facts: CheckFacts = session.check
    facts.record(error)
    for output in co_outputs(kwargs):
        session.namespace[output.name] = Unknown
    catalogue = load_catalogue(name)
    sd_prod = getattr(catalogue, "sd_prod", "?")
    if catalogue is None or callable(sd_prod) or sd_prod == "maillage_sdaster":
        facts.close_names()
    if name in MESH_COMMANDS:
        facts.close_names()


def statement_failed(session, statement, error) -> None:
    """After a failed top-level statement: record the error and bind the names
    it assigns (targets and CO("NAME") outputs) to Unknown. What it would have
    bound is unknown, a mesh maybe: names are no longer judged."""
    facts: CheckFacts = session.check
    if not facts.errors or facts.errors[-1] is not error:
        facts.record(error)
    for name in statement_outputs(statement):
        session.namespace[name] = Unknown
    facts.close_names()


# ------------------------------------------------------------------ units


def _unit_of(keywords: Keywords):
    return dict.get(keywords, "UNITE")


def _unit_readable(session, keywords: Keywords) -> bool:
    """False when the unit holds a file the deck writes (not written under check)."""
    unit = _unit_of(keywords)
    if unit in session.run.units:
        return True
    return not (unit in session.check.units_open or session.check.units_unknown)


def _check_read_unit(session, keywords: Keywords, site: CallSite, name: str) -> None:
    unit = _unit_of(keywords)
    if not isinstance(unit, int) or isinstance(unit, bool):
        return
    if unit in session.run.units or unit in session.check.units_open:
        return
    if session.check.units_unknown:  # written by the deck's own Python, maybe
        return
    known = ", ".join(str(u) for u in sorted(session.run.units)) or "none"
    raise CommandError(
        f"no file is mapped to logical unit {unit} (mapped units: {known})", site.location, name
    )


def _note_written_units(name: str, keywords: Keywords, facts: CheckFacts) -> None:
    """Units a command other than a reader may write: every UNITE* keyword."""
    if name in READERS:
        return
    for key, value in _all_values(keywords):
        if key.startswith("UNITE") and isinstance(value, int) and not isinstance(value, bool):
            facts.units_open.add(value)


def note_unit_mapping(session, keywords: Keywords, unit=None) -> None:
    """DEFI_FICHIER: the unit it associates (given, or chosen for a file
    named without one) may be read or written from now on."""
    if unit is None:
        unit = dict.get(keywords, "UNITE")
    if isinstance(unit, int):
        session.check.units_open.add(unit)


def _all_values(keywords):
    for key, value in dict.items(keywords):
        if isinstance(value, list) and all(isinstance(v, dict) for v in value):
            for occurrence in value:
                yield from _all_values(occurrence)
        else:
            yield key, value


# ------------------------------------------------------------ mesh names


def check_mesh_names(catalogue, keywords: Keywords, facts: CheckFacts, skip=()) -> None:
    """Raise on the first group, node or cell name found in no mesh."""
    if facts.names_open or not facts.meshes:
        return
    for level, key, kind, value in _named_values(catalogue, keywords):
        if key not in skip and not any(_mesh_has(mesh, kind, value) for mesh in facts.meshes):
            path, location = level.where(key)
            raise CommandError(
                f"no mesh of the deck has a {NAME_TYPES[kind]} {value!r}", location, path
            )


def _named_values(level_catalogue, keywords):
    """(level, keyword, type, name) of every mesh name the call gives; NOM*
    keywords name new groups."""
    entries = _entries(level_catalogue)
    for key, value in dict.items(keywords):
        entry = entries.get(key)
        if isinstance(entry, FACT) and isinstance(value, list):
            for occurrence in value:
                yield from _named_values(entry, occurrence)
        elif isinstance(entry, SIMP) and not key.startswith("NOM"):
            kinds = [t for t in entry.types if isinstance(t, str) and t in NAME_TYPES]
            if len(kinds) != 1 or len(entry.types) != 1:
                continue
            for item in value if isinstance(value, (list, tuple)) else (value,):
                if isinstance(item, str):
                    yield keywords, key, kinds[0], item


def _entries(level) -> dict:
    found = {}
    for name, entry in level.entries.items():
        if isinstance(entry, BLOC):
            for inner, value in _entries(entry).items():
                found.setdefault(inner, value)
        else:
            found.setdefault(name, entry)
    return found


def _mesh_has(mesh, kind: str, name: str) -> bool:
    if kind == "grma":
        return name in mesh.cell_groups
    if kind == "grno":
        return name in mesh.node_groups
    if kind == "no":
        return mesh.find_node(name) is not None or _position_in(name, mesh.n_nodes)
    return mesh.find_cell(name) is not None or _position_in(name, getattr(mesh, "n_cells", 0))


def _position_in(name: str, count: int) -> bool:
    """code_aster 17 also reads a node or cell name made of digits as its
    1-based number (char8_to_int): NOEUD='1' is the first node."""
    return name.strip().isdigit() and 1 <= int(name) <= count


# ------------------------------------------------------------------ helpers


def _computable(value, reuse=None, budget: list | None = None) -> bool:
    """No uncomputed value (Unknown, a placeholder) inside the keywords."""
    if reuse is not None and not _computable(reuse):
        return False
    if value is Unknown or isinstance(value, Placeholder):
        return False
    if isinstance(value, dict):
        return all(_computable(v) for v in dict.values(value))
    if isinstance(value, (list, tuple)):
        return all(_computable(v) for v in value)
    return True


# catalogue types that are plain values, not concepts
VALUE_TYPES = frozenset({"R", "I", "C", "TXM", "CO", "L", *NAME_TYPES})


def undecidable(catalogue, keywords: Keywords) -> bool:
    """Whether an sd_prod function chooses the result type from a concept
    check did not type (AnyPlaceholder, or Unknown after an error): code_aster
    picks the type from the exact type of its inputs, unknown here."""
    if not callable(getattr(catalogue, "sd_prod", None)):
        return False
    return any(
        _untyped_concept(entry, value) for entry, value in _simple_values(catalogue, keywords)
    )


def _untyped_concept(entry: SIMP, value) -> bool:
    items = value if isinstance(value, (list, tuple)) else (value,)
    concept_typed = any(t not in VALUE_TYPES for t in entry.types if isinstance(t, str))
    return any(
        isinstance(item, AnyPlaceholder) or (item is Unknown and concept_typed) for item in items
    ) or (value is Unknown and concept_typed)


def _simple_values(level_catalogue, keywords):
    """(SIMP, value) of every simple keyword of the call, in factor occurrences too."""
    entries = _entries(level_catalogue)
    for key, value in dict.items(keywords):
        entry = entries.get(key)
        if isinstance(entry, FACT) and isinstance(value, list):
            for occurrence in value:
                yield from _simple_values(entry, occurrence)
        elif isinstance(entry, SIMP):
            yield entry, value


def _may_be_mesh(result: Any) -> bool:
    """A placeholder of a mesh, a skeleton included (code_aster's squelette
    derives from maillage_sdaster: DEFI_SQUELETTE's nodes have names of their own)."""
    if not isinstance(result, Placeholder):
        return False
    types = getattr(result, "aster_types", None) or ()
    return result.satisfies("maillage_sdaster") or any("squelette" in str(t) for t in types)
