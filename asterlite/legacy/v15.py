"""Forms of code_aster 15 (2020) decks that code_aster 17 spells differently.

Tables read from code_aster 15's catalogues (``ehmoussi/code_aster``,
``code_aster/Cata/Commands``) against today's:

- ``ENTITY_KEYWORDS``: mesh nodes and cells named by ``NOEUD``/``MAILLE``
  where code_aster 17 takes only node and cell groups. A name becomes a
  group holding exactly that node or cell (:class:`asterlite.legacy.nodes.
  LegacyGroups`): the mesh's own when it has one, else one created when the
  mesh is read (:func:`translate_lire_maillage`), so a list of names is the
  same set of entities as the list of their groups;
- ``NO_EFFECT``: keywords that only tuned how code_aster 15 ran
  (``CALC_CHAMP/PARALLELISME_TEMPS``), dropped with a note;
- CREA_RESU's ``NOM_CHAM``, given once for every ``AFFE`` occurrence;
- DYNA_VIBRA: supports named by mesh nodes (``EXCIT/NOEUD``) and the
  code_aster 15 default scheme (``DIFF_CENTRE``; ``RUNGE_KUTTA_32`` today for
  a GENE transient, ``NEWMARK`` for a physical one). The scalar buckling law
  of ``RELATION='FLAMBAGE'`` (``FNOR_CRIT``...) stays as written: code_aster
  17's crushing functions do not reproduce it (sdnd105a: residual crushing
  2.99863 in code_aster 15, 2.99972 with the functions of its code_aster 17
  version), so today's catalogue keeps its keywords hidden and asterlite runs
  code_aster 15's law (asterlite.dynamics.laws.flambage);
- ``OLD_BEHAVIOURS``: what code_aster 13 to 15 computed differently with the
  same keywords (the NEWMARK right-hand side, POST_GENE_PHYS's static
  correction, TEST_RESU's NUME_ORDRE on a tran_gene, POST_DYNA_MODA_T's
  window, DIS_CHOC's default AMOR_TAN), asked by the commands through
  :func:`computes`;
- code_aster 15's generated object names in RECU_FONCTION/INTITULE
  (:func:`relation_title`).
"""

from __future__ import annotations

from asterlite.errors import AsterliteError
from asterlite.lang import parse_deck
from asterlite.legacy.base import (
    NOT_LITERAL,
    RESULT,
    Env,
    NewCall,
    Translation,
    factor,
    lit,
    occurrences,
    single,
)
from asterlite.legacy.deck_calls import CallReader, callee_name, deck_constants
from asterlite.legacy.dyna import node_groups
from asterlite.legacy.v15_facts import (
    ENTITY_KEYWORDS,
    OLD_BEHAVIOURS,
)
from asterlite.legacy.v15_names import GENERATED_NAME
from asterlite.legacy.version import behaviour_version

VERSION = 15
# keywords that changed no result, and why: command -> factor -> {keyword: why}
NO_EFFECT = {
    "CALC_CHAMP": {None: {"PARALLELISME_TEMPS": "parallel computing over instants"}},
}
# code_aster 15 default of DYNA_VIBRA/SCHEMA_TEMPS/SCHEMA (GENE and physical)
OLD_DEFAULT_SCHEME = "DIFF_CENTRE"


def levels(command: str) -> dict:
    return ENTITY_KEYWORDS.get(command, {})


# ------------------------------------------------------------------ mesh entities


def _factor_levels(kwargs: dict, command: str):
    """(factor, occurrence, renames) of every level of a call with entity keywords."""
    for name, renames in levels(command).items():
        if name is None:
            yield None, kwargs, renames
            continue
        value = kwargs.get(name)
        if isinstance(value, (dict, list, tuple)):
            for occurrence in occurrences(value):
                yield name, occurrence, renames


def has_entities(kwargs: dict, env: Env) -> bool:
    return any(
        any(old in level for old in renames)
        for _, level, renames in _factor_levels(kwargs, env.command)
    )


def entity_groups(level: dict, renames: dict, env: Env, path: str) -> dict:
    """``level`` with its NOEUD/MAILLE keywords given as the groups of those entities."""

    return node_groups(level, renames, env, path, required=True)


def translate_entities(kwargs: dict, env: Env) -> dict:
    """The call's keywords with every mesh node and cell name given as its group."""
    out = dict(kwargs)
    for name, renames in levels(env.command).items():
        if name is None:
            if any(old in out for old in renames):
                out = dict(entity_groups(factor(out, out), renames, env, env.command))
            continue
        value = out.get(name)
        if not isinstance(value, (dict, list, tuple)):
            continue
        found = occurrences(value)
        if not any(any(old in o for old in renames) for o in found):
            continue
        new = tuple(entity_groups(o, renames, env, f"{env.command}/{name}") for o in found)
        out[name] = new if isinstance(value, (list, tuple)) else new[0]
    return out


def _drop_no_effect(kwargs: dict, env: Env) -> dict:
    out = dict(kwargs)
    for key, why in NO_EFFECT.get(env.command, {}).get(None, {}).items():
        if key in out:
            out.pop(key)
            env.note(f"{env.command}/{key} (code_aster {VERSION})", f"(removed: {why})", None, key)
    return out


def is_v15_call(kwargs: dict, env: Env) -> bool:
    """A call of a command with entity keywords or dropped keywords, written as in 15."""
    if has_entities(kwargs, env):
        return True
    return any(key in kwargs for key in NO_EFFECT.get(env.command, {}).get(None, {}))


def translate_call(kwargs: dict, env: Env) -> Translation:
    out = translate_entities(_drop_no_effect(kwargs, env), env)
    return Translation(env.command, out, env.notes)


# ----------------------------------------------------------------------- CREA_RESU


def is_v15_crea_resu(kwargs: dict, env: Env) -> bool:
    return (
        lit(kwargs.get("OPERATION")) == "AFFE" and "NOM_CHAM" in kwargs or has_entities(kwargs, env)
    )


def translate_crea_resu(kwargs: dict, env: Env) -> Translation:
    """CREA_RESU(OPERATION='AFFE', NOM_CHAM=..., AFFE=...): the field name in each AFFE."""
    out = dict(kwargs)
    if lit(out.get("OPERATION")) == "AFFE" and "NOM_CHAM" in out:
        name = out.pop("NOM_CHAM")
        found = occurrences(out.get("AFFE"))
        new = []
        for occurrence in found:
            level = factor(dict(occurrence), occurrence)
            if "NOM_CHAM" in level:
                env.unsupported(
                    f"CREA_RESU: NOM_CHAM both at the top level and in AFFE (code_aster {VERSION})",
                    occurrence,
                    "NOM_CHAM",
                )
            level["NOM_CHAM"] = name
            new.append(level)
        out["AFFE"] = tuple(new) if isinstance(out.get("AFFE"), (list, tuple)) else new[0]
        env.note(
            f"CREA_RESU(NOM_CHAM=..., AFFE=...) (code_aster {VERSION})",
            "CREA_RESU(AFFE=_F(NOM_CHAM=..., ...)) in each occurrence",
            None,
            "NOM_CHAM",
        )
    out = translate_entities(out, env)
    return Translation(env.command, out, env.notes)


# ---------------------------------------------------------------------- DYNA_VIBRA


def _scheme_missing(kwargs: dict) -> bool:
    if lit(kwargs.get("TYPE_CALCUL")) != "TRAN":
        return False
    scheme = single(kwargs.get("SCHEMA_TEMPS")) if "SCHEMA_TEMPS" in kwargs else None
    return scheme is None or "SCHEMA" not in scheme


def is_v15_dyna_vibra(kwargs: dict, env: Env) -> bool:
    """A DYNA_VIBRA written with COMPORTEMENT as code_aster 15 wrote it."""
    if has_entities(kwargs, env):
        return True
    return env.version <= VERSION and _scheme_missing(kwargs)


def translate_dyna_vibra(kwargs: dict, env: Env) -> Translation:
    out = dict(kwargs)
    if env.version <= VERSION and _scheme_missing(out):
        given = single(out.get("SCHEMA_TEMPS")) if "SCHEMA_TEMPS" in out else None
        level = factor(dict(given or {}), given)
        level["SCHEMA"] = OLD_DEFAULT_SCHEME
        out["SCHEMA_TEMPS"] = level
        env.note(
            f"DYNA_VIBRA without SCHEMA (code_aster {VERSION} default {OLD_DEFAULT_SCHEME})",
            f"SCHEMA_TEMPS=_F(SCHEMA={OLD_DEFAULT_SCHEME!r})",
            given,
        )
    # the scalar buckling law (FNOR_CRIT...) stays as written: today's catalogue keeps
    # its keywords hidden and asterlite runs code_aster 15's law (laws/flambage.py)
    out = translate_entities(out, env)
    return Translation(env.command, out, env.notes)


# -------------------------------------------------------------------- LIRE_MAILLAGE


def mesh_creations(kwargs: dict, env: Env) -> tuple[dict, dict]:
    """({group: node}, {group: cell}) to create on the mesh this LIRE_MAILLAGE reads."""
    if env.unit_path is None or env.legacy_groups is None:
        return {}, {}
    unit = lit(kwargs.get("UNITE", 20))
    if not isinstance(unit, int) or isinstance(unit, bool):
        return {}, {}
    path = env.unit_path(unit)
    if path is None:
        return {}, {}
    return env.legacy_groups.creations(path)


def mesh_groups_call(kwargs: dict, env: Env) -> NewCall | None:
    """The DEFI_GROUP that gives the mesh read by this LIRE_MAILLAGE the groups
    standing for the nodes and cells the deck names (None: none to create)."""
    nodes, cells = mesh_creations(kwargs, env)
    if not nodes and not cells:
        return None
    created = {}
    if cells:
        created["CREA_GROUP_MA"] = tuple(
            factor({"NOM": group, "MAILLE": cell}) for group, cell in cells.items()
        )
    if nodes:
        created["CREA_GROUP_NO"] = tuple(
            factor({"NOM": group, "NOEUD": node}) for group, node in nodes.items()
        )
    shown = ", ".join(sorted(cells.values()) + sorted(nodes.values()))
    env.note(
        f"mesh nodes and cells named by NOEUD/MAILLE keywords (code_aster {VERSION} and older): "
        f"{shown}",
        f"node and cell groups {env.legacy_groups.prefix}<name> created after LIRE_MAILLAGE",
    )
    return NewCall("DEFI_GROUP", {"reuse": RESULT, "MAILLAGE": RESULT, **created}, "DEFI_GROUP")


# ------------------------------------------------------------ names in a deck

# (command, factor) -> keywords naming mesh nodes, besides ENTITY_KEYWORDS (older decks)
OLDER_NODE_KEYWORDS = {("DYNA_TRAN_MODAL", "EXCIT"): ("NOEUD",)}


def _named_keywords() -> dict:
    """(command, factor or None) -> {keyword: 'node' or 'cell'}."""
    table: dict = {}
    for command, factors in ENTITY_KEYWORDS.items():
        for name, renames in factors.items():
            kinds = {old: "cell" if new == "GROUP_MA" else "node" for old, new in renames.items()}
            table.setdefault((command, name), {}).update(kinds)
    for key, names in OLDER_NODE_KEYWORDS.items():
        table.setdefault(key, {}).update({n: "node" for n in names})
    return table


def named_entities(texts) -> set:
    """(kind, name) of every mesh node and cell the deck texts name, as literals,
    where today's syntax takes groups."""

    table = _named_keywords()
    commands = {command for command, _ in table}
    found: set = set()
    for text in texts:
        try:
            module = parse_deck(text, "deck.comm")
        except AsterliteError:
            continue
        reader = CallReader(text, "deck.comm", module.lines, deck_constants(module.tree))
        for node in module.tree.iter_subtrees():
            if node.data != "funccall" or callee_name(node) not in commands:
                continue
            try:
                keywords, _, _ = reader.call(node)
            except Exception:  # positional arguments...: nothing to read
                continue
            command = callee_name(node)
            for (name, factor_name), kinds in table.items():
                if name != command:
                    continue
                levels_ = [keywords] if factor_name is None else _all(keywords.get(factor_name))
                for level in levels_:
                    for key, kind in kinds.items():
                        value = lit(level.get(key, NOT_LITERAL))
                        values = value if isinstance(value, (list, tuple)) else (value,)
                        found.update((kind, v) for v in values if isinstance(v, str))
    return found


def _all(value) -> list:
    try:
        return occurrences(value)
    except Exception:  # a factor keyword given as a variable
        return []


# ------------------------------------------------- what code_aster 13 to 15 computed


def computes(session, behaviour: str) -> bool:
    """Whether the run's decks were written for a version that computed ``behaviour``."""
    first, last = OLD_BEHAVIOURS[behaviour]
    return session is not None and first <= behaviour_version(session, behaviour) <= last


# ------------------------------------------------ names code_aster 15 generated

# RECU_FONCTION/INTITULE of a RELA_EFFO_DEPL/_VITE nonlinearity: code_aster 15 titled
# it <node name:8><component:8><function's object name> ("N03     DX      0000000c");
# code_aster 17 gives the node's number and the function's deck name
TITLE_FIELDS = (8, 8)


def relation_title(title: str, node_index: dict, generated) -> tuple[str | None, str]:
    """Today's title of the nonlinearity a code_aster 15 INTITULE names, or
    (None, why) when it is not in that form or names what cannot be followed.
    ``node_index``: mesh node name -> 0-based index; ``generated``: the session's
    :class:`asterlite.legacy.v15_names.GeneratedNames`."""
    node_width, component_width = TITLE_FIELDS
    node = title[:node_width].strip()
    component = title[node_width : node_width + component_width].strip()
    function = title[node_width + component_width :].strip()
    if node not in node_index or not component or not GENERATED_NAME.match(function):
        return None, ""
    concept, why = generated.lookup(function) if generated is not None else (None, "")
    name = getattr(concept, "name", None)
    if not name:
        return None, f"{function!r} is a name code_aster 15 generated: {why or 'not a function'}"
    return f"{node_index[node] + 1:<{node_width}}{component:<{component_width}}{name}", ""
