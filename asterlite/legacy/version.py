"""Which code_aster version a deck was written for: the one place that decides.

A deck's version is read from its text: commands and keywords that only
some versions had. Each marker is the *newest* version whose catalogue had
the form (the next catalogue known to asterlite dropped it), so a deck is
as old as its oldest marker; a deck with none is of today's version
(:data:`CURRENT`). ``asterlite run --aster-version N`` overrides the
detection for a whole run (:func:`session_version`).

A line ``# asterlite: aster-version N`` (written by ``asterlite port``,
:func:`pragma_needed`) states the version of the behaviours no code_aster 17
keyword expresses (:data:`INEXPRESSIBLE`): for those it wins over the
markers (:func:`behaviour_version`). Everything else in a ported deck is
already today's syntax and meaning, so the rest of the run follows the
markers (reading it all as version N would translate it a second time).

Markers come from code_aster's own catalogues: code_aster 15 is the
``ehmoussi/code_aster`` tree (2020), code_aster 17 today's; the commands of
code_aster 10-12 that 15 and 17 no longer have from their language data
(:func:`removed_commands`); the older keywords from the legacy translations
(:mod:`asterlite.legacy.dyna`, :mod:`~asterlite.legacy.modes`,
:mod:`~asterlite.legacy.v11`).
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from functools import lru_cache

from asterlite.catalog.language.model import language
from asterlite.errors import AsterliteError
from asterlite.io.input_files import read_text_or_none
from asterlite.lang import parse_deck
from asterlite.legacy import dyna
from asterlite.legacy.language_data import old_language
from asterlite.legacy.v15_facts import ENTITY_KEYWORDS, OLD_BEHAVIOURS, REMOVED_AFTER_15

CURRENT = 17
# the last code_aster version whose decks were Python 2 (code_aster 14 moved
# to Python 3): Python 2 syntax in a deck is a marker of this version
PYTHON2_LAST = 13

# commands code_aster 11 had and its catalogue of January 2013 (11.3) no longer
# had: newest version 11; every other command of code_aster 10-12's language
# data that 15's and 17's lack is taken as of 12 (the data cannot tell 11 from 12)
REMOVED_BY_2013 = {"MACRO_PROJ_BASE": 11, "MACRO_MATR_ASSE": 11}
OLD_LAYOUT_LAST = 12


@lru_cache(maxsize=1)
def removed_commands() -> dict[str, int]:
    """command -> newest version that had it, for the commands of code_aster
    10-12 (its language data) that code_aster 15 and 17 no longer have."""

    newer = [found for found in (language(15), language(17)) if found is not None]
    found = {}
    for name in sorted(old_language().command_names):
        if not any(lang.has_command(name) for lang in newer):
            found[name] = REMOVED_BY_2013.get(name, OLD_LAYOUT_LAST)
    return found


def _removed_keywords() -> dict[tuple[str, ...], int]:
    """(command, factor..., keyword) -> newest version that had that keyword there."""
    found: dict[tuple[str, ...], int] = {}
    for family in dyna.LEGACY_VIBRA_FAMILIES:  # one factor keyword per nonlinearity
        found[("DYNA_VIBRA", family)] = 14
    for command, factors in ENTITY_KEYWORDS.items():  # mesh nodes and cells by name
        for factor, renames in factors.items():
            for old in renames:
                path = (command, old) if factor is None else (command, factor, old)
                found.setdefault(path, 15)
    for path in REMOVED_AFTER_15:
        found.setdefault(path, 15)
    return found


def calls(text: str, filename: str = "deck.comm") -> Iterator[tuple[str, tuple[str, ...]]]:
    """(command, keyword path) of every keyword of every command call in ``text``
    (a call without keywords yields its command with an empty path)."""

    module = parse_deck(text, filename)
    for node in module.tree.iter_subtrees():
        if node.data != "funccall":
            continue
        name = _callee(node)
        if not name or not name.isupper() or name == "_F":
            continue
        yield name, ()
        yield from ((name, path) for path in _paths(node, ()))


def _callee(node) -> str | None:
    target = node.children[0]
    if getattr(target, "data", None) == "var":
        return str(target.children[0])
    return None


def _paths(call, prefix: tuple[str, ...]) -> Iterator[tuple[str, ...]]:
    arguments = call.children[1] if len(call.children) > 1 else None
    for argument in getattr(arguments, "children", None) or ():
        if getattr(argument, "data", None) != "kwarg":
            continue
        key = str(argument.children[0].children[0])
        yield (*prefix, key)
        value = argument.children[1]
        occurrences = [value]
        if getattr(value, "data", None) in ("tuple", "list"):
            occurrences = value.children
        for occurrence in occurrences:
            if getattr(occurrence, "data", None) == "funccall" and _callee(occurrence) == "_F":
                yield from _paths(occurrence, (*prefix, key))


def _is_python2(text: str) -> bool:
    """The deck's text is Python 2 (it reads as Python 2 only)."""

    return parse_deck(text, "deck.comm").python2


def _text_version(text: str) -> int | None:
    """Markers of the text itself (code_aster 11 decks, see asterlite.legacy.v11)."""
    # every check had VALE_CALC from code_aster 12 on
    if re.search(r"\bTEST_(RESU|TABLE|FONCTION)\s*\(", text) and "VALE_CALC" not in text:
        return 11
    return None


PRAGMA = re.compile(r"^[ \t]*#[ \t]*asterlite:[ \t]*aster-version[ \t]+(\d+)[ \t]*$", re.M)


def pragma_version(text: str) -> int | None:
    """The version a ``# asterlite: aster-version N`` line states, or None."""
    found = PRAGMA.search(text)
    return int(found.group(1)) if found else None


def with_pragma(text: str, version: int | None) -> str:
    """``text`` with its version line replaced by one stating ``version``
    (none when ``version`` is None), as the first line."""
    text = PRAGMA.sub("", text).lstrip("\n") if PRAGMA.search(text) else text
    if version is None:
        return text
    return f"# asterlite: aster-version {version}\n{text}"


@lru_cache(maxsize=64)
def deck_version(text: str) -> int:
    """The code_aster major version the deck ``text`` was written for (its
    markers; a version line speaks for some behaviours only, :func:`behaviour_version`)."""

    found = [CURRENT]
    own = _text_version(text)
    if own is not None:
        found.append(own)
    keywords = _removed_keywords()
    removed = removed_commands()
    try:
        if _is_python2(text):
            found.append(PYTHON2_LAST)
        for command, path in calls(text):
            if not path and command in removed:
                found.append(removed[command])
            elif (command, *path) in keywords:
                found.append(keywords[(command, *path)])
    except AsterliteError:  # not a deck asterlite parses: nothing to decide from
        pass
    return min(found)


def files_version(paths) -> int:
    """The version of a run: that of its oldest deck file."""
    versions = [CURRENT]
    for path in paths:
        text = read_text_or_none(path)
        if text is not None:
            versions.append(deck_version(text))
    return min(versions)


def files_stated_version(paths) -> int | None:
    """The oldest version the run's deck files state on a version line, or None."""
    stated = []
    for path in paths:
        text = read_text_or_none(path)
        if text is None:
            continue
        found = pragma_version(text)
        if found is not None:
            stated.append(found)
    return min(stated) if stated else None


def behaviour_version(session, behaviour: str) -> int:
    """The version whose meaning of ``behaviour`` the run follows:
    ``--aster-version`` if given, else a version line's for the behaviours no
    code_aster 17 keyword expresses, else the detected version."""
    if getattr(session, "aster_version", None) or behaviour not in INEXPRESSIBLE:
        return session_version(session)
    stated = getattr(session, "_stated_version", False)
    if stated is False:
        run = getattr(session, "run", None)
        stated = files_stated_version(getattr(run, "deck_files", ()))
        session._stated_version = stated
    return session_version(session) if stated is None else stated


def session_version(session) -> int:
    """The version a run's decks are read in: ``--aster-version`` if given, else detected."""
    given = getattr(session, "aster_version", None)
    if given:
        return int(given)
    cached = getattr(session, "_detected_version", None)
    if cached is None:
        run = getattr(session, "run", None)  # a session without decks: today's version
        cached = files_version(getattr(run, "deck_files", ()))
        session._detected_version = cached
    return cached


# ------------------------------------------------------------ what a version meant

# the first version whose meshes read from files keep no node or cell names
# (code_aster 15's lrmast stored them in the mesh, 17's only while reading): its
# tables give a node's 1-based number and N<i>/M<i> name positions (char8_to_int)
MESH_NAMES_DROPPED = 16
# versions whose tables named mesh nodes. Read from the decks of each era, which
# filter POST_DYNA_MODA_T's tables on NOEUD='NO1': code_aster 10-11 (ralic/Code_Aster
# at 427e130c, sdnd101a), 11.4/12 (its 2013 sdnd101a, DYNA_VIBRA with CHOC) and 15
# (ehmoussi/code_aster). Versions 13-14 sit between two that named them.
# `asterlite port` turns such filters into node numbers (asterlite.legacy.port).
NODE_NAMES_IN_TABLES = tuple(range(10, MESH_NAMES_DROPPED))


def tables_name_nodes(session) -> bool:
    """True when the run's tables give nodes by name (code_aster 15 decks)."""
    return session is not None and session_version(session) in NODE_NAMES_IN_TABLES


def meshes_keep_names(session) -> bool:
    """True when a mesh read from a file keeps its node and cell names."""
    return session_version(session) < MESH_NAMES_DROPPED


# ------------------------------------------------------------ what port cannot write

# behaviours of asterlite.legacy.v15_facts.OLD_BEHAVIOURS that no code_aster 17 keyword
# expresses (the ported deck keeps them only by stating its version), each with
# the deck text that makes a deck rely on it
INEXPRESSIBLE = {
    "ADAPT_ORDRE2_MDADAP": re.compile(r"['\"]ADAPT(_ORDRE2)?['\"]"),
    # POST_DYNA_MODA_T/CHOC OPTION='USURE': its window INST_INIT..INST_FIN cut by
    # truncation on the archive (today's instants from INST_INIT on)
    "POST_DYNA_MODA_T_WINDOW_BY_TRUNCATION": re.compile(r"OPTION\s*=\s*['\"]USURE['\"]"),
    # code_aster 13-15's GENE NEWMARK (forces of the step's start) and POST_GENE_PHYS
    # (relative fields without the static correction)
    "NEWMARK_FORCE_AT_STEP_START": re.compile(r"['\"]NEWMARK['\"]"),
    "POST_GENE_PHYS_RELATIVE_WITHOUT_CORR_STAT": re.compile(r"POST_GENE_PHYS\s*\("),
    # code_aster 13-15's default AMOR_TAN (a deck giving RIGI_TAN and never AMOR_TAN)
    "AMOR_TAN_DEFAULT_MAX_MODAL_MASS": re.compile(r"^(?![\s\S]*AMOR_TAN)[\s\S]*RIGI_TAN"),
}


def pragma_needed(text: str, version: int) -> tuple[bool, str]:
    """Whether the port of ``text`` (a deck of ``version``) must state its
    version to run as that version ran it, and why."""

    def differs(name: str) -> bool:
        first, last = OLD_BEHAVIOURS[name]
        return (first <= version <= last) != (first <= CURRENT <= last)

    relied = [n for n, form in INEXPRESSIBLE.items() if differs(n) and form.search(text)]
    if not relied:
        return False, ""
    return True, f"relies on code_aster {version}'s {', '.join(relied)}"
