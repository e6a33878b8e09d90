"""``asterlite port`` of code_aster 10-11 decks: the forms of :mod:`asterlite.legacy.v11`
written out as code_aster 17 text.

At run time those forms are adjusted on computed values, with the run's
session at hand (its namespace, its meshes). Porting works on the deck's
text, so the same tables are applied to the call trees of
:mod:`asterlite.legacy.port` (leaves are :class:`~asterlite.legacy.base.Src`),
and the two forms that need the run are done from the deck and its meshes:

- a FORMULE reading deck variables is given them as keywords (``OMEGA=OMEGA``),
  which code_aster 17 evaluates where the FORMULE is defined, as code_aster 11 did;
- elements on nodes (AFFE_MODELE/AFFE and AFFE_CARA_ELEM/DISCRET on GROUP_NO or
  NOEUD) are put on point cells made by a ``CREA_MAILLAGE(CREA_POI1=...)`` written
  before the AFFE_MODELE, under the name of the mesh it reads;
- mesh groups written ``GROUP_NO_X`` are given their name ``X`` by a DEFI_GROUP
  after the LIRE_MAILLAGE.
"""

from __future__ import annotations

import re

from asterlite.errors import CommandError, UnsupportedError
from asterlite.legacy import v11
from asterlite.legacy.base import RESULT, Env, NewCall, NotPortable, Src, factor, lit
from asterlite.legacy.nodes import _read_mesh, _stamp


class PortCall:
    """What :mod:`asterlite.legacy.v11`'s adjusters ask of a call, when porting."""

    def __init__(self, env: Env):
        self.command = env.command
        self.env = env
        self.site = _Site(env.location, env.keyword_locations)

    def where(self, level=None, keyword: str | None = None):
        return self.env.where(level, keyword)

    def note(self, old: str, new: str, level=None, keyword: str | None = None) -> None:
        self.env.note(old, new, level, keyword)

    def unsupported(self, message: str, level=None, keyword: str | None = None, path=""):
        path = f"{self.command}/{path or keyword}" if (path or keyword) else self.command
        raise UnsupportedError(message, self.where(level, keyword), path)

    def error(self, message: str, level=None, keyword: str | None = None, path=""):
        path = f"{self.command}/{path or keyword}" if (path or keyword) else self.command
        raise CommandError(message, self.where(level, keyword), path)


class _Site:
    def __init__(self, location, keyword_locations):
        self.location = location
        self.keyword_locations = keyword_locations


def commands() -> set[str]:
    """The commands whose calls a code_aster 11 deck may write in an old form."""
    return set(v11._ADJUSTERS) | set(v11.NO_EFFECT)


def adjust(kwargs: dict, env: Env, deck: DeckFacts, mesh_groups) -> tuple[dict, list]:
    """(keywords as today's catalogues read them, statements to write before the call)."""
    call = PortCall(env)
    kwargs = v11._drop_no_effect(kwargs, call)
    before: list = []
    for step in v11._ADJUSTERS.get(env.command, ()):
        if step is v11.formula_scope:
            kwargs = formula_scope(kwargs, call, deck.names)
        elif step is v11.node_elements:
            kwargs = node_elements(kwargs, call, mesh_groups, before)
        else:
            kwargs = step(kwargs, call)
    if env.command == "TEST_RESU":
        kwargs = gene_rank(kwargs, call, deck.transients)
    return kwargs, before


class DeckFacts:
    """What porting reads from a whole deck: the names it assigns at its top level,
    and those bound to generalized transients (DYNA_TRAN_MODAL, DYNA_VIBRA)."""

    TRANSIENT_COMMANDS = ("DYNA_TRAN_MODAL", "DYNA_VIBRA")

    def __init__(self, names: set[str], transients: set[str]):
        self.names = names
        self.transients = transients


# ------------------------------------------------------- TEST_RESU/GENE


def gene_rank(kwargs: dict, call: PortCall, transients: set[str]) -> dict:
    """TEST_RESU/GENE on a transient: NUME_ORDRE=n read the n-th archived instant up
    to code_aster 15 (trgene; at run time commands/test_resu.py follows the deck's
    version); today it is an order number, one less when the initial state is
    archived (asterlite numbers a transient's archive from 0)."""

    def adjust(level):
        result, rank = level.get("RESU_GENE"), lit(level.get("NUME_ORDRE"))
        if not isinstance(result, Src) or result.text not in transients:
            return level
        if not isinstance(rank, int) or isinstance(rank, bool):
            if "NUME_ORDRE" in level:
                raise NotPortable("TEST_RESU/GENE/NUME_ORDRE is not a literal number")
            return level
        call.note(
            "TEST_RESU/GENE/NUME_ORDRE on a transient (code_aster 15 and older: the "
            "rank of the archived instant)",
            "NUME_ORDRE=its order number (one less)",
            level,
            "NUME_ORDRE",
        )
        return factor({**level, "NUME_ORDRE": rank - 1}, level)

    return v11._map_factor(kwargs, "GENE", adjust)


# --------------------------------------------------------------- FORMULE


def formula_scope(kwargs: dict, call: PortCall, deck_names: set[str]) -> dict:
    """FORMULE given, as keywords, the deck names its expression reads."""
    from asterlite.concepts.function import _is_builtin_name
    from asterlite.post.expression import CompiledExpression

    text = lit(kwargs.get("VALE", kwargs.get("VALE_C")))
    if not isinstance(text, str):
        return kwargs
    try:
        names = CompiledExpression(text).names
    except Exception:  # FORMULE itself reports a bad expression
        return kwargs
    parameters = {str(p) for p in v11._pair(kwargs.get("NOM_PARA"))}
    added = sorted(
        name
        for name in names
        if name not in parameters
        and name not in kwargs
        and name in deck_names
        and not _is_builtin_name(name)
    )
    if not added:
        return kwargs
    call.note(
        "FORMULE reading deck variables (code_aster 11: the deck's values when it is defined)",
        f"FORMULE(..., {', '.join(f'{n}={n}' for n in added)})",
    )
    return {**kwargs, **{name: Src(name) for name in added}}


# ------------------------------------------------------ elements on nodes


class MeshGroups:
    """The node and cell groups of the meshes a ported deck reads, and the point
    cell groups its elements on nodes need (made before its first AFFE_MODELE)."""

    def __init__(self, legacy_groups):
        self.legacy_groups = legacy_groups
        self.made: set[tuple[str, str]] = set()  # (mesh, point cell group) written
        # mesh name -> {group: node group} that AFFE_CARA_ELEM calls on its models need
        self.pending: dict[str, dict[str, str]] = {}

    def cell_groups(self) -> set[str]:
        if self.legacy_groups is None:
            return set()
        return {g for _, groups in self.legacy_groups.meshes(True) for g in groups}

    def node_group(self, node: str) -> str | None:
        return None if self.legacy_groups is None else self.legacy_groups.group_of(node)


def _point_groups(level: dict, mesh_groups: MeshGroups) -> list[tuple[str, str]]:
    """(cell group to use, node group it is made from) for an occurrence on nodes."""
    found = []
    for group in v11._pair(level.get("GROUP_NO")):
        found.append((str(lit(group)), str(lit(group))))
    for node in v11._pair(level.get("NOEUD")):
        name = lit(node)
        own = mesh_groups.node_group(name) if isinstance(name, str) else None
        if own is None:
            raise NotPortable(f"no node group holds just the node {name!r}")
        found.append((name, own))
    taken = mesh_groups.cell_groups()
    for label, _ in found:
        if not isinstance(label, str) or label in taken:
            raise NotPortable(f"the mesh already has a cell group {label!r}")
    return found


def node_elements(kwargs: dict, call: PortCall, mesh_groups: MeshGroups, before: list) -> dict:
    """Elements on GROUP_NO/NOEUD put on point cells; the AFFE_MODELE of the deck
    gets a CREA_MAILLAGE before it making them (for its own and later calls)."""
    factor_name = v11.NODE_ELEMENTS[call.command]
    wanted: dict[str, str] = {}

    def adjust(level):
        if "GROUP_NO" not in level and "NOEUD" not in level:
            return level
        groups = _point_groups(level, mesh_groups)
        wanted.update(groups)
        call.note(
            f"{call.command}/{factor_name} on GROUP_NO/NOEUD (code_aster 11: point elements "
            "on nodes)",
            "GROUP_MA of POI1 cells on those nodes (CREA_MAILLAGE/CREA_POI1)",
            level,
        )
        new = {k: v for k, v in level.items() if k not in ("GROUP_NO", "NOEUD")}
        new["GROUP_MA"] = v11._pair(new.get("GROUP_MA")) + tuple(label for label, _ in groups)
        return factor(new, level)

    kwargs = v11._map_factor(kwargs, factor_name, adjust)
    if call.command == "AFFE_MODELE":
        mesh = _mesh_name(kwargs)
        wanted.update(mesh_groups.pending.pop(mesh, {}))
        fresh = {k: v for k, v in wanted.items() if (mesh, k) not in mesh_groups.made}
        if fresh:
            before.append(_crea_poi1(mesh, fresh))
            mesh_groups.made.update((mesh, label) for label in fresh)
    else:
        made = {label for _, label in mesh_groups.made}
        missing = [label for label in wanted if label not in made]
        if missing:
            raise NotPortable(
                f"point cell groups {', '.join(missing)} are needed before the AFFE_MODELE "
                "that made the model"
            )
    return kwargs


def _mesh_name(kwargs: dict) -> str:
    mesh = kwargs.get("MAILLAGE")
    if not isinstance(mesh, Src) or not mesh.text.isidentifier():
        raise NotPortable("AFFE_MODELE/MAILLAGE is not a name the point cells can be added to")
    return mesh.text


def _crea_poi1(mesh: str, groups: dict[str, str]) -> tuple[str, dict]:
    occurrences = tuple(
        factor({"NOM_GROUP_MA": label, "GROUP_NO": group}) for label, group in groups.items()
    )
    return mesh, {"MAILLAGE": Src(mesh), "CREA_POI1": occurrences}


def scan_point_groups(calls, reader, mesh_groups: MeshGroups) -> None:
    """Point cell groups the AFFE_CARA_ELEM calls of a deck need, by the mesh of
    their model (a name the deck assigns an AFFE_MODELE of that mesh), made with
    that AFFE_MODELE (``mesh_groups.pending``)."""

    meshes: dict[str, str] = {}  # model name -> mesh name
    for name, _, node in calls:
        try:
            keywords, start, _ = reader.call(node)
            line_start = reader.text.rfind("\n", 0, start) + 1
            target = re.search(r"([A-Za-z_]\w*)\s*=\s*$", reader.text[line_start:start])
            if name == "AFFE_MODELE" and target is not None:
                meshes[target.group(1)] = _mesh_name(keywords)
            if name != "AFFE_CARA_ELEM":
                continue
            model = keywords.get("MODELE")
            mesh = meshes.get(model.text) if isinstance(model, Src) else None
            for level in v11._occurrences(keywords.get("DISCRET")):
                if mesh is not None and ("GROUP_NO" in level or "NOEUD" in level):
                    found = mesh_groups.pending.setdefault(mesh, {})
                    found.update(_point_groups(level, mesh_groups))
        except NotPortable:
            continue


# ------------------------------------------------------------ mesh groups


def unprefixed_groups_call(path) -> NewCall | None:
    """The DEFI_GROUP naming ``X`` the mesh groups written ``GROUP_NO_X`` / ``GROUP_MA_X``
    in the ASTER mesh at ``path`` (None: none)."""

    mesh = _read_mesh(str(path), _stamp(path)) if path is not None else None
    if mesh is None:
        return None
    made = {"node_groups": [], "cell_groups": []}
    for prefix, kind in v11.MESH_GROUP_PREFIXES.items():
        groups = getattr(mesh, kind, {}) or {}
        for name in groups:
            short = name[len(prefix) :]
            if name.startswith(prefix) and short and short not in groups:
                made[kind].append((short, name))
    created = {}
    if made["cell_groups"]:
        created["CREA_GROUP_MA"] = tuple(
            factor({"NOM": new, "GROUP_MA": old}) for new, old in made["cell_groups"]
        )
    if made["node_groups"]:
        created["CREA_GROUP_NO"] = tuple(
            factor({"NOM": new, "GROUP_NO": old}) for new, old in made["node_groups"]
        )
    if not created:
        return None
    return NewCall("DEFI_GROUP", {"reuse": RESULT, "MAILLAGE": RESULT, **created}, "DEFI_GROUP")
