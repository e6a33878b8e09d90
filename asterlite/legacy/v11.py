"""What code_aster 10-11 decks meant by forms that are values, not renames.

Decks of 2011 differ from today's in meaning as well as spelling: a test
value without a tolerance, a default since changed, a formula reading the
deck's variables, a discrete element on a node. These are kept here as data,
one table per command, and applied to a call *before* it is validated (and
before the renames of the other legacy translations), only when the deck's
version is 11 or older:

- ``REFERENCE_VALUES``: TEST_RESU / TEST_TABLE ``VALE=`` (and TEST_FONCTION
  ``VALE_REFE=`` without ``VALE_CALC``) was the value to reach within
  ``PRECISION`` (default 1e-3; 1.2e-3 for TEST_TABLE) under ``CRITERE``
  (default 'RELATIF'); with two PRECISION/CRITERE values the first pair
  tested the value, the second found the instant (code_aster 11's trprec);
- ``FIXED_STEP_SCHEMES``: DEVOGE stepped at the deck's PAS (it adapts today);
- ``OLD_DEFAULTS``: keywords whose default code_aster 11 filled in and today's
  catalogue makes mandatory (PROJ_VECT_BASE TYPE_VECT='FORC'), their values
  read from code_aster 11's language data (:mod:`asterlite.legacy.language_data`);
- ``NO_EFFECT``: keywords of code_aster 11 that only tuned the run (renumbering
  of NUME_DDL) or labelled a check (VERSION): dropped with a note;
- FORMULE read the deck's variables (numbers and strings) as they were when
  it was defined: they are passed to it explicitly;
- AFFE_MODELE / AFFE_CARA_ELEM ``GROUP_NO`` / ``NOEUD``: elements on nodes
  (code_aster 11's "late" point elements) are point cells on those nodes;
- mesh group names written ``GROUP_NO_X`` / ``GROUP_MA_X`` in an ASTER mesh
  are named ``X`` by the decks of that era (``MESH_GROUP_PREFIXES``).

A few code_aster 11 spellings that the code_aster 12-13 legacy catalogues
(:mod:`asterlite.legacy.dyna`) do not know are also here, because they must
be undone before those catalogues check the call: DYNA_TRAN_MODAL
EXCIT/VECT_ASSE and EXCIT/MODE_STAT (``RENAMED_IN_12``, ``MOVED_UP_IN_12``),
DEFI_LIST_ENTI INTERV_R. The fluid film (CHOC/LAME_FLUIDE='OUI') keeps its
shock keywords and has its top-level NMAX_ITER, RESI_RELA, LAMBDA gathered in
PARA_LAME_FLUI (``FILM_ITERATIONS``); asterlite integrates it with EULER and
ADAPT_ORDRE2 (``FILM_SCHEMES``), other schemes are refused by name.

:func:`before_call` is called by the dispatcher for every command and
:func:`after_run` on every command result; both do nothing for other decks.
"""

from __future__ import annotations

import re
from functools import lru_cache
from pathlib import Path

from asterlite.errors import CommandError, UnsupportedError
from asterlite.io.input_files import read_text_or_none
from asterlite.lang.values import FactorDict
from asterlite.legacy.base import Note, Src, lit
from asterlite.legacy.language_data import old_default

LAST_VERSION = 11  # the forms below are those of code_aster 11 and older

# ------------------------------------------------------------------ tables

# command -> factor keyword (None: the command's own level) -> old value keywords
# (old keyword -> suffix of today's VALE_CALC / VALE_REFE)
_VALUES = {"VALE": "", "VALE_I": "_I", "VALE_C": "_C"}
_REFE_VALUES = {"VALE_REFE": "", "VALE_REFE_C": "_C"}
REFERENCE_VALUES = {
    "TEST_RESU": {f: _VALUES for f in ("CHAM_NO", "CHAM_ELEM", "RESU", "GENE", "OBJET")},
    "TEST_TABLE": {None: _VALUES},
    "TEST_FONCTION": {"VALEUR": _REFE_VALUES},
}
# code_aster 10-11 catalogues: PRECISION default of the tested value
DEFAULT_PRECISION = {"TEST_RESU": 1.0e-3, "TEST_TABLE": 1.2e-3, "TEST_FONCTION": 1.0e-3}
DEFAULT_CRITERION = "RELATIF"
# REFERENCE values today's catalogues accept; the others become 'NON_DEFINI'
MODERN_REFERENCES = ("ANALYTIQUE", "SOURCE_EXTERNE", "AUTRE_ASTER", "NON_DEFINI")

# keywords code_aster 12 renamed, which the code_aster 12-13 legacy catalogues
# (asterlite.legacy.dyna) do not know: command -> factor -> {old: new}
RENAMED_IN_12 = {"DYNA_TRAN_MODAL": {"EXCIT": {"VECT_ASSE": "VECT_ASSE_GENE"}}}

# keywords of every occurrence of a factor that code_aster 12 asked once at the
# top level: command -> factor -> keywords (all occurrences must agree)
MOVED_UP_IN_12 = {"DYNA_TRAN_MODAL": {"EXCIT": ("MODE_STAT",)}}

# schemes that stepped at a fixed PAS in code_aster 11 and adapt their step
# today: the step is held (PAS_MINI = PAS_MAXI = PAS, which keeps it fixed).
# R5.06.04 lists DEVOGELAERE apart from the adaptive schemes; sdnl104a's DEVOGE
# checks at 1e-4 hold at the fixed step and fail by 0.4 % with today's control.
FIXED_STEP_SCHEMES = ("DEVOGE",)

# command -> keywords whose code_aster 11 default (read from its language
# data) the translation fills in
OLD_DEFAULTS = {"PROJ_VECT_BASE": ("TYPE_VECT",)}

# command -> factor (None: top level) -> keywords that changed no result, and why
NO_EFFECT = {
    "NUME_DDL": {None: ("METHODE", "RENUM")},
    "TEST_RESU": {f: ("VERSION",) for f in REFERENCE_VALUES["TEST_RESU"]},
    "TEST_TABLE": {None: ("VERSION",)},
    "TEST_FONCTION": {"VALEUR": ("VERSION",)},
    "IMPR_RESU": {None: ("MODELE",)},
}
NO_EFFECT_WHY = {
    "METHODE": "the linear solver's storage and renumbering",
    "RENUM": "the linear solver's renumbering",
    "VERSION": "the code_aster version a non-regression value came from",
    "MODELE": "the model of the printed fields, for printing only",
}

# elements on nodes: command -> the factor keyword that assigns them
NODE_ELEMENTS = {"AFFE_MODELE": "AFFE", "AFFE_CARA_ELEM": "DISCRET"}

# ASTER mesh group name prefix -> the group kind it names (decks drop the prefix)
MESH_GROUP_PREFIXES = {"GROUP_NO_": "node_groups", "GROUP_MA_": "cell_groups"}

# the fluid film (CHOC/LAME_FLUIDE='OUI'): the top-level keywords of its
# fixed-point iterations (asterlite.dynamics.fluid_film), which code_aster 11
# gathered in PARA_LAME_FLUI in October 2011; their defaults are read there
# from its language data
FILM_ITERATIONS = ("NMAX_ITER", "RESI_RELA", "LAMBDA")


def film_iteration_defaults() -> dict:
    """FILM_ITERATIONS' code_aster 11 defaults, from its language data."""
    return {k: old_default("DYNA_TRAN_MODAL", "PARA_LAME_FLUI", k) for k in FILM_ITERATIONS}


# the schemes asterlite integrates a fluid film with: code_aster 11's EULER
# (mdeul1) and ADAPT_ORDRE2 (mdadap; 'ADAPT' in code_aster 10). code_aster 11
# also ran ADAPT_ORDRE1 with a film (mdadap again), which asterlite refuses;
# mdtr74 handed the film to mdeul1 and mdadap only
FILM_SCHEMES = ("EULER", "ADAPT_ORDRE2", "ADAPT")


# ----------------------------------------------------------------- version


def _own_deck_version(text: str) -> int | None:
    """11 when the text uses a form that code_aster 12 no longer accepted, else None.

    Stand-in until :mod:`asterlite.legacy.version` gives the version of any deck.
    """
    if re.search(r"\bMACRO_(PROJ_BASE|MATR_ASSE)\s*\(", text):
        return 11
    # every check had VALE_CALC from code_aster 12 on
    if re.search(r"\bTEST_(RESU|TABLE|FONCTION)\s*\(", text) and "VALE_CALC" not in text:
        return 11
    return None


def deck_version(text: str) -> int | None:
    """The code_aster major version a deck was written for (None: unknown)."""
    try:
        from asterlite.legacy.version import deck_version as detected

        return _major(detected(text))
    except ImportError:  # asterlite.legacy.version absent (or mid-edit)
        return _own_deck_version(text)


def _major(version) -> int | None:
    if version is None:
        return None
    if isinstance(version, (tuple, list)):
        return _major(version[0]) if version else None
    match = re.match(r"\s*(\d+)", str(version))
    return int(match.group(1)) if match else None


@lru_cache(maxsize=64)
def _file_version(path: str, stamp: float) -> int | None:
    text = read_text_or_none(path)
    return None if text is None else deck_version(text)


def applies(session) -> bool:
    """True when the run's decks are code_aster 11 (or older) decks."""
    version = _session_version(session)
    return version is not None and version <= LAST_VERSION


def _session_version(session) -> int | None:
    """The version of the run (``asterlite run --aster-version``, else detected);
    without a run description, that of the deck file being run."""
    if getattr(session, "run", None) is not None:
        try:
            from asterlite.legacy.version import session_version

            return _major(session_version(session))
        except ImportError:  # asterlite.legacy.version absent (or mid-edit)
            pass
    path = getattr(session, "current_file", "")
    if not path:
        return None
    try:
        stamp = Path(path).stat().st_mtime
    except OSError:
        return None
    return _file_version(str(path), stamp)


# ------------------------------------------------------------------- hooks


class _Call:
    """One call being adjusted: where it is, and the notes it gives."""

    def __init__(self, command: str, site, session):
        self.command = command
        self.site = site
        self.session = session

    def where(self, level=None, keyword: str | None = None):
        locations = getattr(level, "keyword_locations", None) or {}
        if keyword in locations:
            return locations[keyword]
        if level is None and keyword in (self.site.keyword_locations or {}):
            return self.site.keyword_locations[keyword]
        return getattr(level, "location", None) or self.site.location

    def note(self, old: str, new: str, level=None, keyword: str | None = None) -> None:
        """Log a legacy form once per deck file."""
        seen = self.session.__dict__.setdefault("_v11_notes", set())
        key = (self.session.current_file, self.command, old)
        if key in seen:
            return
        seen.add(key)
        self.session.log(Note(old, new, self.where(level, keyword)).text())

    def unsupported(self, message: str, level=None, keyword: str | None = None, path=""):
        path = f"{self.command}/{path or keyword}" if (path or keyword) else self.command
        raise UnsupportedError(message, self.where(level, keyword), path)

    def error(self, message: str, level=None, keyword: str | None = None, path=""):
        path = f"{self.command}/{path or keyword}" if (path or keyword) else self.command
        raise CommandError(message, self.where(level, keyword), path)


def before_call(command: str, kwargs: dict, site, session) -> dict:
    """The keywords of a call as today's catalogues read them (a code_aster 11 deck),
    or ``kwargs`` unchanged."""
    if not applies(session):
        return kwargs
    call = _Call(command, site, session)
    kwargs = _drop_no_effect(kwargs, call)
    for adjust in _ADJUSTERS.get(command, ()):
        kwargs = adjust(kwargs, call)
    return kwargs


def after_run(command: str, concept, session):
    """A command's result as a code_aster 11 deck saw it (mesh group names)."""
    if command == "LIRE_MAILLAGE" and concept is not None and applies(session):
        added = unprefixed_groups(concept)
        if added:
            session.log(
                "code_aster 11 mesh groups: "
                + ", ".join(f"{old} named {new}" for old, new in added)
            )
    return concept


# ------------------------------------------------------------ occurrences


def _occurrences(value) -> list:
    if isinstance(value, dict):
        return [value]
    if isinstance(value, (list, tuple)):
        return [v for v in value if isinstance(v, dict)]
    return []


def _copy(level: dict, mapping: dict) -> dict:
    """``mapping`` as an occurrence keeping ``level``'s locations."""
    if isinstance(level, FactorDict):
        return FactorDict(
            mapping,
            location=level.location,
            keyword_locations=dict(level.keyword_locations),
        )
    return dict(mapping)


def _map_factor(kwargs: dict, factor: str | None, adjust) -> dict:
    """``kwargs`` with ``adjust(occurrence)`` applied to each occurrence of
    ``factor`` (or to the call itself for None)."""
    if factor is None:
        return adjust(kwargs)
    value = kwargs.get(factor)
    if value is None:
        return kwargs
    if isinstance(value, dict):
        new = adjust(value)
    elif isinstance(value, (list, tuple)):
        new = type(value)(adjust(v) if isinstance(v, dict) else v for v in value)
    else:
        return kwargs
    return {**kwargs, factor: new}


def _drop_no_effect(kwargs: dict, call: _Call) -> dict:
    for factor, names in NO_EFFECT.get(call.command, {}).items():

        def drop(level, names=names, factor=factor):
            found = [n for n in names if n in level]
            for name in found:
                where = f"{factor}/{name}" if factor else name
                call.note(
                    f"{call.command}/{where} (code_aster 11: {NO_EFFECT_WHY[name]})",
                    "nothing: it changes no result",
                    level if factor else None,
                    name,
                )
            return _copy(level, {k: v for k, v in level.items() if k not in found})

        kwargs = _map_factor(kwargs, factor, drop)
    return kwargs


# ------------------------------------------------------ reference values


def _pair(value) -> tuple:
    if value is None:
        return ()
    if isinstance(value, Src) and isinstance(value.value, (list, tuple)):
        return tuple(value.value)  # asterlite port: a literal sequence as written
    return tuple(value) if isinstance(value, (list, tuple)) else (value,)


def _same(a, b) -> bool:
    """The same value given twice (the same concept, or the same deck text when porting)."""
    if isinstance(a, Src) and isinstance(b, Src):
        return a.text == b.text
    return a is b


def reference_check(level: dict, old_keys: dict, default_precision: float) -> dict | None:
    """Today's keywords for a code_aster 11 check written with ``old_keys``, or
    None when the occurrence is not in that form.

    The value becomes both the reference (checked within the deck's PRECISION
    under its CRITERE, as code_aster 11 did) and the VALE_CALC today's
    catalogue requires, with TOLE_MACHINE equal to that PRECISION so that it
    never judges more strictly than the reference check.
    """
    given = [k for k in old_keys if k in level]
    if not given or any(k.startswith("VALE_CALC") for k in level):
        return None
    precision = (_pair(level.get("PRECISION")) or (default_precision,))[0]
    criterion = (_pair(level.get("CRITERE")) or (DEFAULT_CRITERION,))[0]
    reference = lit(level.get("REFERENCE"))
    dropped = set(given) | {"PRECISION", "CRITERE", "REFERENCE"}
    new = {k: v for k, v in level.items() if k not in dropped}
    for key in given:
        suffix = old_keys[key]
        new["VALE_CALC" + suffix] = level[key]
        new["VALE_REFE" + suffix] = level[key]
    new["REFERENCE"] = reference if reference in MODERN_REFERENCES else "NON_DEFINI"
    new["PRECISION"] = precision
    new["TOLE_MACHINE"] = precision
    new["CRITERE"] = criterion
    return new


def _reference_values(kwargs: dict, call: _Call) -> dict:
    default = DEFAULT_PRECISION[call.command]
    for factor, old_keys in REFERENCE_VALUES[call.command].items():

        def adjust(level, old_keys=old_keys, factor=factor):
            new = reference_check(level, old_keys, default)
            if new is None:
                return level
            place = f"{factor}/" if factor else ""
            call.note(
                f"{call.command}({place}{'/'.join(k for k in old_keys if k in level)}=...)"
                f" (code_aster 11: the value to reach within PRECISION, default {default:g})",
                "VALE_CALC=... with REFERENCE, VALE_REFE, PRECISION and TOLE_MACHINE",
                level if factor else None,
            )
            return _copy(level, new)

        kwargs = _map_factor(kwargs, factor, adjust)
    return kwargs


# ---------------------------------------------------------- old defaults


def _old_defaults(kwargs: dict, call: _Call) -> dict:
    names = OLD_DEFAULTS[call.command]
    missing = {k: old_default(call.command, k) for k in names if k not in kwargs}
    if not missing:
        return kwargs
    given = ", ".join(f"{k}={v!r}" for k, v in missing.items())
    call.note(f"{call.command} without {', '.join(missing)} (code_aster 11 default)", given)
    return {**kwargs, **missing}


# --------------------------------------------------------------- FORMULE


def _deck_constant(value) -> bool:
    return isinstance(value, (int, float, complex, str))


def formula_scope(kwargs: dict, call: _Call) -> dict:
    """FORMULE with the deck variables its expression reads, as code_aster 11
    evaluated formulas in the deck's context of (non-concept) values taken
    when the formula was defined."""
    from asterlite.concepts.function import _is_builtin_name
    from asterlite.post.expression import CompiledExpression

    text = kwargs.get("VALE", kwargs.get("VALE_C"))
    if not isinstance(text, str):
        return kwargs
    try:
        names = CompiledExpression(text).names
    except Exception:  # FORMULE itself reports a bad expression
        return kwargs
    parameters = _pair(kwargs.get("NOM_PARA"))
    namespace = call.session.namespace
    added = {
        name: namespace[name]
        for name in names
        if name not in parameters
        and name not in kwargs
        and not _is_builtin_name(name)
        and _deck_constant(namespace.get(name))
    }
    if not added:
        return kwargs
    call.note(
        "FORMULE reading deck variables (code_aster 11: the deck's values when it is defined)",
        f"FORMULE(..., {', '.join(f'{n}={n}' for n in sorted(added))})",
    )
    return {**kwargs, **added}


# ------------------------------------------------------ elements on nodes


def _mesh_of(command: str, kwargs: dict, call: _Call):
    """The mesh of the call; under ``asterlite check`` (a placeholder model),
    the first mesh read that has every node group and node the call names."""
    from asterlite.concepts.mesh import Mesh

    if command == "AFFE_MODELE":
        mesh = kwargs.get("MAILLAGE")
    else:
        mesh = getattr(kwargs.get("MODELE"), "mesh", None)
    if isinstance(mesh, Mesh):
        return mesh
    facts = getattr(call.session, "check", None)
    named = [occ for occ in _occurrences(kwargs.get(NODE_ELEMENTS[command]))]
    groups = {g for occ in named for g in _pair(occ.get("GROUP_NO"))}
    nodes = {n for occ in named for n in _pair(occ.get("NOEUD"))}
    for candidate in getattr(facts, "meshes", ()):
        if groups <= set(candidate.node_groups) and nodes <= set(candidate.node_index):
            return candidate
    return None


def point_cell_group(mesh, label: str, nodes) -> str:
    """The name of a cell group holding one point cell (POI1) on each of ``nodes``,
    made when needed: cells named after their node, as CREA_MAILLAGE/CREA_POI1
    names them; the group named ``label`` unless the mesh has another group so named."""
    import numpy as np

    cells = []
    for node in nodes:
        found = next(
            (
                i
                for i, (kind, conn) in enumerate(zip(mesh.cell_types, mesh.cell_nodes, strict=True))
                if kind == "POI1" and conn == (int(node),)
            ),
            None,
        )
        if found is None:
            base = name = mesh.node_names[int(node)]
            k = 1
            while name in mesh.cell_index:
                name, k = f"{base}_{k}", k + 1
            found = int(mesh.add_cells([name], "POI1", [(int(node),)])[0])
        cells.append(found)
    cells = np.asarray(cells, dtype=int)
    name, k = label, 1
    while name in mesh.cell_groups and not np.array_equal(mesh.cell_groups[name], cells):
        name, k = f"{label}_POI1" + (f"_{k}" if k > 1 else ""), k + 1
    mesh.cell_groups[name] = cells
    return name


def _nodes_of(mesh, level: dict, call: _Call) -> list[tuple[str, list[int]]]:
    """(label, node indices) for each node group or node an occurrence names."""
    found = []
    for group in _pair(level.get("GROUP_NO")):
        if group not in mesh.node_groups:
            call.error(f"no node group {group!r} in the mesh", level, "GROUP_NO")
        found.append((str(group), [int(n) for n in mesh.node_groups[group]]))
    for node in _pair(level.get("NOEUD")):
        index = mesh.node_index.get(node)
        if index is None:
            call.error(f"no node {node!r} in the mesh", level, "NOEUD")
        found.append((str(node), [index]))
    return found


def node_elements(kwargs: dict, call: _Call) -> dict:
    """AFFE_MODELE/AFFE and AFFE_CARA_ELEM/DISCRET on GROUP_NO or NOEUD: the
    point cells of those nodes (code_aster 11 made point elements there)."""
    factor = NODE_ELEMENTS[call.command]
    mesh = _mesh_of(call.command, kwargs, call)

    def adjust(level):
        if "GROUP_NO" not in level and "NOEUD" not in level:
            return level
        if mesh is None:  # asterlite check without the mesh: keep the names
            groups = _pair(level.get("GROUP_NO")) + _pair(level.get("NOEUD"))
        else:
            groups = tuple(point_cell_group(mesh, *entry) for entry in _nodes_of(mesh, level, call))
        call.note(
            f"{call.command}/{factor} on GROUP_NO/NOEUD (code_aster 11: point elements on nodes)",
            "GROUP_MA of POI1 cells on those nodes (CREA_MAILLAGE/CREA_POI1)",
            level,
        )
        new = {k: v for k, v in level.items() if k not in ("GROUP_NO", "NOEUD")}
        existing = _pair(new.get("GROUP_MA"))
        new["GROUP_MA"] = existing + groups
        return _copy(level, new)

    return _map_factor(kwargs, factor, adjust)


# ------------------------------------------------------------ mesh groups


def unprefixed_groups(mesh) -> list[tuple[str, str]]:
    """Add the names code_aster 11 decks used for prefixed mesh groups
    (``GROUP_NO_ENCASTRE`` read as ``ENCASTRE``), when free; returns (old, new)."""
    added = []
    for prefix, kind in MESH_GROUP_PREFIXES.items():
        groups = getattr(mesh, kind, None)
        if not isinstance(groups, dict):
            continue
        for name in list(groups):
            short = name[len(prefix) :]
            if name.startswith(prefix) and short and short not in groups:
                groups[short] = groups[name]
                added.append((name, short))
    return added


# -------------------------------------------------------------- renames


def _renamed_in_12(kwargs: dict, call: _Call) -> dict:
    for factor, renames in RENAMED_IN_12[call.command].items():

        def rename(level, renames=renames, factor=factor):
            found = [k for k in renames if k in level]
            if not found:
                return level
            for key in found:
                call.note(f"{call.command}/{factor}/{key}", f"{factor}/{renames[key]}", level, key)
            new = _copy(level, {renames.get(k, k): v for k, v in level.items()})
            if isinstance(new, FactorDict):
                new.keyword_locations = {
                    renames.get(k, k): loc for k, loc in level.keyword_locations.items()
                }
            return new

        kwargs = _map_factor(kwargs, factor, rename)
    return kwargs


def _moved_up_in_12(kwargs: dict, call: _Call) -> dict:
    for factor, names in MOVED_UP_IN_12[call.command].items():
        occurrences = _occurrences(kwargs.get(factor))
        for name in names:
            values = [occ[name] for occ in occurrences if name in occ]
            if not values:
                continue
            if name in kwargs or len(values) != len(occurrences):
                call.unsupported(
                    f"{factor}/{name} given in some occurrences only (or also at the top "
                    "level): code_aster 12 and later take one for all",
                    occurrences[0],
                    name,
                    path=f"{factor}/{name}",
                )
            if any(not _same(v, values[0]) for v in values):
                call.unsupported(
                    f"{factor}/{name} differs between occurrences: code_aster 12 and later "
                    "take one for all",
                    occurrences[0],
                    name,
                    path=f"{factor}/{name}",
                )
            call.note(
                f"{call.command}/{factor}/{name}", f"{call.command}/{name}", occurrences[0], name
            )
            kwargs = _map_factor(
                kwargs,
                factor,
                lambda level, name=name: _copy(
                    level, {k: v for k, v in level.items() if k != name}
                ),
            )
            kwargs = {**kwargs, name: values[0]}
    return kwargs


def _fixed_step(kwargs: dict, call: _Call) -> dict:
    """DEVOGE integrated at the deck's PAS in code_aster 11 (R5.06.04 sets it apart
    from the adaptive schemes); today's DEVOGE adapts unless PAS_MINI = PAS_MAXI."""
    schema = lit(kwargs.get("METHODE"))
    for occurrence in _occurrences(kwargs.get("SCHEMA_TEMPS")):
        schema = lit(occurrence.get("SCHEMA", schema))
    if schema not in FIXED_STEP_SCHEMES:
        return kwargs

    def hold(level):
        if level.get("PAS") is None or "PAS_MINI" in level or "PAS_MAXI" in level:
            return level
        call.note(
            f"{call.command} SCHEMA={schema!r} (code_aster 11: a fixed step PAS)",
            "PAS_MINI=PAS_MAXI=PAS",
            level,
        )
        return _copy(level, {**level, "PAS_MINI": level["PAS"], "PAS_MAXI": level["PAS"]})

    return _map_factor(kwargs, "INCREMENT", hold)


def _interval_pairs(kwargs: dict, call: _Call) -> dict:
    """DEFI_LIST_ENTI(OPERATION='NUME_ORDRE', INTERV_R=(a, b, ...)): the intervals
    as pairs of bounds, today one INTERVALLE=_F(VALE=(a, b)) each."""
    bounds = kwargs.get("INTERV_R")
    if bounds is None or "INTERVALLE" in kwargs:
        return kwargs
    bounds = _pair(bounds)
    if len(bounds) % 2:
        call.error("INTERV_R takes pairs of bounds", None, "INTERV_R")
    call.note("DEFI_LIST_ENTI/INTERV_R=(a, b)", "INTERVALLE=_F(VALE=(a, b))", None, "INTERV_R")
    location = call.where(None, "INTERV_R")
    pairs = [
        FactorDict({"VALE": (bounds[i], bounds[i + 1])}, location=location)
        for i in range(0, len(bounds), 2)
    ]
    rest = {k: v for k, v in kwargs.items() if k != "INTERV_R"}
    return {**rest, "INTERVALLE": tuple(pairs)}


# ------------------------------------------------------------ refusals


def _scheme_of(kwargs: dict) -> str:
    """The scheme of a code_aster 10-11 DYNA_TRAN_MODAL call (METHODE, else
    SCHEMA_TEMPS/SCHEMA; the defaults of asterlite.legacy.dyna)."""
    if "METHODE" in kwargs:
        return str(lit(kwargs["METHODE"]))
    occurrences = _occurrences(kwargs.get("SCHEMA_TEMPS"))
    if occurrences:
        return str(lit(occurrences[0].get("SCHEMA", "NEWMARK")))
    old_style = any(k in kwargs for k in ("MASS_GENE", "RIGI_GENE"))
    return "EULER" if old_style else "NEWMARK"


def fluid_film(kwargs: dict, call: _Call) -> dict:
    """CHOC/LAME_FLUIDE='OUI': the top-level NMAX_ITER, RESI_RELA, LAMBDA as
    PARA_LAME_FLUI (code_aster 12's place), defaults of code_aster 11 filled
    in; refused with a scheme other than EULER and ADAPT_ORDRE2. Without a film, those
    keywords changed nothing and are dropped."""
    films = [o for o in _occurrences(kwargs.get("CHOC")) if lit(o.get("LAME_FLUIDE")) == "OUI"]
    given = [k for k in FILM_ITERATIONS if k in kwargs]
    rest = {k: v for k, v in kwargs.items() if k not in FILM_ITERATIONS}
    if not films:
        for key in given:
            call.note(
                f"{call.command}/{key} without CHOC/LAME_FLUIDE='OUI' (code_aster 11: "
                "the fluid film's iterations)",
                "nothing: it changes no result",
                None,
                key,
            )
        return rest if given else kwargs
    scheme = _scheme_of(kwargs)
    if scheme not in FILM_SCHEMES:
        call.unsupported(
            f"CHOC/LAME_FLUIDE='OUI' with SCHEMA={scheme!r} (code_aster 11 deck): asterlite "
            "integrates the fluid film with code_aster 11's EULER and ADAPT_ORDRE2 only",
            films[0],
            "LAME_FLUIDE",
            path="CHOC/LAME_FLUIDE",
        )
    values = {k: kwargs.get(k, default) for k, default in film_iteration_defaults().items()}
    shown = ", ".join(f"{k}={v.text if isinstance(v, Src) else repr(v)}" for k, v in values.items())
    call.note(
        f"{call.command}/NMAX_ITER, RESI_RELA, LAMBDA (code_aster 11: the fluid film's "
        "iterations, defaults 20, 1e-3, 10)",
        f"PARA_LAME_FLUI=_F({shown})",
        None,
        given[0] if given else None,
    )
    location = call.where(None, given[0]) if given else call.site.location
    rest["PARA_LAME_FLUI"] = FactorDict(values, location=location)
    return rest


_ADJUSTERS = {
    "TEST_RESU": (_reference_values,),
    "TEST_TABLE": (_reference_values,),
    "TEST_FONCTION": (_reference_values,),
    "PROJ_VECT_BASE": (_old_defaults,),
    "FORMULE": (formula_scope,),
    "AFFE_MODELE": (node_elements,),
    "DEFI_LIST_ENTI": (_interval_pairs,),
    "AFFE_CARA_ELEM": (node_elements,),
    "DYNA_TRAN_MODAL": (fluid_film, _renamed_in_12, _moved_up_in_12, _fixed_step),
}
