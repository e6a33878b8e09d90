"""code_aster 15's generated object names ("0000001b"), for decks that quote them.

From version 15, code_aster no longer names a data structure after the deck
variable: every object it creates takes the next value of one counter,
written as 8 hexadecimal digits (the first object is "00000001"). Decks of
that era quote such names, e.g. ``aster.getvectjev('0000001b           .VALE')``
to read the 27th object.

The counter advances once per object, including objects the deck never
sees: an elementary vector, a DOF numbering and an assembled matrix each
create a list of loads with a name of its own, and macros such as
ASSEMBLAGE or PROJ_BASE run sub-commands. ``names_consumed`` gives, for the
commands whose count was read from code_aster 15's sources (the objects
each command's result class creates, and each macro's sub-commands), how
many names a call takes, and which of them its results get. A command
outside that table, or a call whose count depends on something else,
ends the correspondence: later generated names are refused, naming the
command, rather than guessed.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from asterlite.concepts.base import Concept
from asterlite.lang.values import CO

GENERATED_NAME = re.compile(r"^[0-9a-f]{8}$")

# Names taken by a call of each command: its result first, then the objects
# the result creates for itself (a list of loads).
SINGLE_RESULT_COUNTS = {
    "LIRE_MAILLAGE": 1,
    "AFFE_MODELE": 1,
    "AFFE_CARA_ELEM": 1,
    "AFFE_CHAR_MECA": 1,
    "CALC_MATR_ELEM": 1,
    "CALC_VECT_ELEM": 2,  # the elementary vector, its list of loads
    "NUME_DDL": 2,  # the numbering, its list of loads
    "ASSE_MATRICE": 2,  # the matrix, its list of loads
    "ASSE_VECTEUR": 1,
    "NUME_DDL_GENE": 1,
    "PROJ_MATR_BASE": 1,
    "PROJ_VECT_BASE": 1,
    "DEFI_OBSTACLE": 1,
    "FORMULE": 1,
    "DEFI_LIST_REEL": 1,
    "DEFI_FONCTION": 1,
    "CALC_FONC_INTERP": 1,
    "RECU_FONCTION": 1,
    "CREA_MAILLAGE": 1,  # a new Mesh
    "MODE_STATIQUE": 1,  # a ModeResult, as CALC_MODES
    "CALC_CHAR_SEISME": 1,  # a FieldOnNodesReal
}
# commands whose result is the concept they are given (DEFI_GROUP: the mesh): no name
REUSING_COMMANDS = ("DEFI_GROUP",)
# macros that make their result with one CREA_TABLE, unless given these keywords
# (INFO_FONCTION/NOCI_SEISME computes response spectra with CALC_FONCTION first)
ONE_TABLE_MACROS = {"INFO_FONCTION": ("NOCI_SEISME",)}
# calls of these keep the count only in their plain form (see _plain_call)
CONDITIONAL_COUNTS = ("CALC_MODES", "DYNA_VIBRA")
STIFFNESS_OPTIONS = ("RIGI_MECA", "RIGI_THER", "RIGI_ACOU", "RIGI_FLUI_STRU")


@dataclass
class Allocation:
    """The names one call takes: how many, and the concepts among them
    (``concepts[i]`` gets the i-th name of the call, 0-based)."""

    count: int
    concepts: dict[int, Any] = field(default_factory=dict)


@dataclass
class GeneratedNames:
    """The counter of a session, and the concept each known name stands for."""

    consumed: int = 0
    concepts: dict[int, Any] = field(default_factory=dict)
    creators: dict[int, str] = field(default_factory=dict)  # name -> "COMMAND (file:line)"
    stopped_by: str | None = None  # the call whose count is unknown

    def record(self, command: str, keywords, concept, reuse, location, namespace) -> None:
        if self.stopped_by is not None:
            return
        where = _where(command, location)
        allocation = names_consumed(command, keywords, concept, reuse, namespace)
        if allocation is None:
            self.stopped_by = where
            return
        for offset in range(allocation.count):
            self.creators[self.consumed + offset + 1] = where
        for offset, value in allocation.concepts.items():
            self.concepts[self.consumed + offset + 1] = value
        self.consumed += allocation.count

    def name_of(self, concept) -> str | None:
        """The name code_aster 15 gave ``concept`` ("0000000c"), if followed."""
        for number, value in self.concepts.items():
            if value is concept:
                return f"{number:08x}"
        return None

    def lookup(self, name: str):
        """The concept named ``name`` (8 hex digits), or an explanation of why not."""
        number = int(name, 16)
        if number in self.concepts:
            return self.concepts[number], ""
        if number in self.creators:
            return None, f"it is an object made inside {self.creators[number]}"
        if self.stopped_by is not None:
            return None, (
                f"the names code_aster 15 generates are followed up to {self.consumed:08x} "
                f"only: how many objects {self.stopped_by} creates in code_aster 15 is not "
                "known to asterlite"
            )
        return None, f"only {self.consumed:08x} names have been generated so far"


def _where(command: str, location) -> str:
    if location is None:
        return command
    return f"{command} ({Path(location.file).name}:{location.line})"


def _occurrences(keywords, name: str) -> list:
    value = keywords.peek(name) if hasattr(keywords, "peek") else keywords.get(name)
    if value is None:
        return []
    return list(value) if isinstance(value, (list, tuple)) else [value]


def _given(keywords, name: str) -> bool:
    return name in getattr(keywords, "given", ()) and keywords.peek(name) is not None


def _bound(value, namespace):
    """The concept a CO output was bound to (None for anything else)."""
    if isinstance(value, CO):
        return namespace.get(value.name)
    return None


def names_consumed(command: str, keywords, concept, reuse, namespace) -> Allocation | None:
    """The names a call takes in code_aster 15, or None when unknown."""
    if command in SINGLE_RESULT_COUNTS:
        if reuse is not None:
            return None
        return Allocation(SINGLE_RESULT_COUNTS[command], _first(concept))
    if command in REUSING_COMMANDS:
        return Allocation(0)
    if command in ONE_TABLE_MACROS:
        if reuse is not None or any(_given(keywords, k) for k in ONE_TABLE_MACROS[command]):
            return None
        return Allocation(1, _first(concept))
    if command in CONDITIONAL_COUNTS:
        if not _plain_call(command, keywords, reuse):
            return None
        if reuse is not None:  # DYNA_VIBRA completing a result: no new object
            return Allocation(0)
        return Allocation(1, _first(concept))
    if command == "ASSEMBLAGE":
        return _assemblage(keywords, namespace)
    if command == "PROJ_BASE":
        return _proj_base(keywords, namespace)
    return None


def _first(concept) -> dict[int, Any]:
    return {0: concept} if isinstance(concept, Concept) else {}


def _plain_call(command: str, keywords, reuse) -> bool:
    """CALC_MODES without the post-treatments that run sub-commands (NORM_MODE,
    FILTRE_MODE, IMPRESSION, AMELIORATION, several bands); DYNA_VIBRA on a
    modal basis in the time domain (a reused result takes no new name)."""
    if command == "CALC_MODES":
        if reuse is not None:
            return False
        if any(_given(keywords, k) for k in ("NORM_MODE", "FILTRE_MODE", "IMPRESSION")):
            return False
        if keywords.peek("AMELIORATION") == "OUI":
            return False
        bands = _occurrences(keywords, "CALC_FREQ")
        frequencies = bands[0].peek("FREQ") if bands and hasattr(bands[0], "peek") else None
        if keywords.peek("OPTION") == "BANDE" and frequencies and len(frequencies) > 2:
            return False
        return True
    return keywords.peek("BASE_CALCUL") == "GENE" and keywords.peek("TYPE_CALCUL") == "TRAN"


def _assemblage(keywords, namespace) -> Allocation:
    """ASSEMBLAGE runs, per matrix (the stiffness first): CALC_MATR_ELEM,
    NUME_DDL (once, when the numbering is an output), ASSE_MATRICE; then per
    vector: CALC_VECT_ELEM, ASSE_VECTEUR."""
    allocation = Allocation(0)
    numbering = keywords.peek("NUME_DDL")
    numbering_pending = isinstance(numbering, CO)
    matrices = _occurrences(keywords, "MATR_ASSE")
    stiffness = [m for m in matrices if m.peek("OPTION") in STIFFNESS_OPTIONS][:1]
    ordered = stiffness + [m for m in matrices if m not in stiffness]

    def take(count: int, value=None) -> None:
        if value is not None:
            allocation.concepts[allocation.count] = value
        allocation.count += count

    for matrix in ordered:
        take(SINGLE_RESULT_COUNTS["CALC_MATR_ELEM"])
        if numbering_pending:
            take(SINGLE_RESULT_COUNTS["NUME_DDL"], _bound(numbering, namespace))
            numbering_pending = False
        take(SINGLE_RESULT_COUNTS["ASSE_MATRICE"], _bound(matrix.peek("MATRICE"), namespace))
    for vector in _occurrences(keywords, "VECT_ASSE"):
        take(SINGLE_RESULT_COUNTS["CALC_VECT_ELEM"])
        if numbering_pending:
            take(SINGLE_RESULT_COUNTS["NUME_DDL"], _bound(numbering, namespace))
            numbering_pending = False
        take(SINGLE_RESULT_COUNTS["ASSE_VECTEUR"], _bound(vector.peek("VECTEUR"), namespace))
    return allocation


def _proj_base(keywords, namespace) -> Allocation | None:
    """PROJ_BASE runs NUME_DDL_GENE (unless given an existing numbering),
    then PROJ_MATR_BASE per matrix and PROJ_VECT_BASE per vector."""
    if _occurrences(keywords, "RESU_GENE"):
        return None  # projects results through a helper not followed here
    allocation = Allocation(0)
    numbering = keywords.peek("NUME_DDL_GENE")
    if numbering is None or isinstance(numbering, CO):
        if isinstance(numbering, CO):
            allocation.concepts[0] = _bound(numbering, namespace)
        allocation.count = 1
    for occurrence, output in (("MATR_ASSE_GENE", "MATRICE"), ("VECT_ASSE_GENE", "VECTEUR")):
        for item in _occurrences(keywords, occurrence):
            value = _bound(item.peek(output), namespace)
            if value is not None:
                allocation.concepts[allocation.count] = value
            allocation.count += 1
    return allocation


def record_call(session, command: str, keywords, concept, reuse, location) -> None:
    """Advance the session's counter past one executed command."""
    names = getattr(session, "generated_names", None)
    if names is None:
        return
    names.record(command, keywords, concept, reuse, location, session.namespace)
