"""DYNA_TRAN_MODAL, and DYNA_VIBRA before COMPORTEMENT, as code_aster 17's DYNA_VIBRA.

code_aster 10 wrote ``DYNA_TRAN_MODAL(METHODE=..., MASS_GENE=..., RIGI_GENE=...,
AMOR_REDUIT=..., CHOC=_F(...))``; versions 11 to 13 moved the scheme into
``SCHEMA_TEMPS`` and the matrices to ``MATR_*``; version 13 renamed the
command ``DYNA_VIBRA(TYPE_CALCUL='TRAN', BASE_CALCUL='GENE')`` but kept one
factor keyword per nonlinearity (``CHOC``, ``FLAMBAGE``, ``ANTI_SISM``...),
which later became ``COMPORTEMENT=_F(RELATION=...)``.

Defaults that changed are written out, so a ported deck computes what the
legacy one did: the legacy default scheme (``EULER`` in code_aster 10,
``NEWMARK`` afterwards, ``RUNGE_KUTTA_32`` today) and the Runge-Kutta
``TOLERANCE`` (1e-3 then, 1e-5 today). ``EULER`` itself became the
generalized ``DIFF_CENTRE`` (code_aster 14 runs that scheme with the
explicit update code_aster 10 called EULER).

Nodes named by the mesh (``NOEUD_1``, ``NOEUD``...) become the node group
holding just that node when the run's meshes have one
(:mod:`asterlite.legacy.nodes`); an ``EXCIT`` support must, since code_aster
17 takes only groups there.
"""

from __future__ import annotations

from asterlite.legacy.base import (
    NOT_LITERAL,
    Env,
    NewCall,
    NotPortable,
    Translation,
    arith,
    factor,
    lit,
    occurrences,
    pop_keys,
    single,
    with_comments_of,
)

TARGET = "DYNA_VIBRA"
HEADER = {"TYPE_CALCUL": "TRAN", "BASE_CALCUL": "GENE"}

# legacy top-level keyword -> modern keyword
TOP_RENAMES = {"MASS_GENE": "MATR_MASS", "RIGI_GENE": "MATR_RIGI", "AMOR_GENE": "MATR_AMOR"}
# legacy top-level keywords gathered into one modern factor keyword
DAMPING_KEYS = ("AMOR_REDUIT", "LIST_AMOR")
# legacy METHODE / SCHEMA value -> modern SCHEMA value, and why they are the same
SCHEME_VALUES = {"ADAPT": "ADAPT_ORDRE2", "EULER": "DIFF_CENTRE"}
SCHEME_WHY = {
    "ADAPT": "the adaptive second-order scheme",
    "EULER": "the same explicit update",
}
# one factor keyword per nonlinearity -> COMPORTEMENT (RELATION, renamed keywords)
NONLINEAR_FAMILIES = {
    "CHOC": ("DIS_CHOC", {}),
    "FLAMBAGE": ("FLAMBAGE", {}),
    "ANTI_SISM": ("ANTI_SISM", {}),
    "DIS_VISC": ("DIS_VISC", {"RESI_INTE_RELA": "RESI_INTE"}),
    "ROTOR_FISS": ("ROTOR_FISS", {}),
    "RELA_EFFO_DEPL": ("RELA_EFFO_DEPL", {"RELATION": "FONCTION"}),
    "RELA_EFFO_VITE": ("RELA_EFFO_VITE", {"RELATION": "FONCTION"}),
}
# INCREMENT keywords that moved into SCHEMA_TEMPS, with the schemes that take them
ADAPT_ORDER = ("ADAPT_ORDRE1", "ADAPT_ORDRE2")
RUNGE_KUTTA = ("RUNGE_KUTTA_32", "RUNGE_KUTTA_54")
ADAPTIVE = RUNGE_KUTTA + ("DEVOGE",) + ADAPT_ORDER
MOVED_TO_SCHEME = {
    **{k: ADAPT_ORDER for k in ("VITE_MIN", "COEF_MULT_PAS", "COEF_DIVI_PAS")},
    **{k: ADAPT_ORDER for k in ("PAS_LIMI_RELA", "NB_POIN_PERIODE")},
    **{k: ADAPTIVE for k in ("PAS_MAXI", "PAS_MINI", "NMAX_ITER_PAS")},
}
# ITMI parameters of SCHEMA_TEMPS: those code_aster 17 keeps at the top level
ITMI_TO_TOP = ("BASE_ELAS_FLUI", "NUME_VITE_FLUI")
ITMI_DROPPED = ("ETAT_STAT", "PREC_DUREE", "CHOC_FLUI", "NB_MODE", "NB_MODE_FLUI", "TS_REG_ETAB")
# legacy shock keywords of the fluid film model, which code_aster 17 dropped
FLUID_FILM = ("LAME_FLUIDE", "ALPHA", "BETA", "CHI", "DELTA")
# top-level keywords of the film's iterations (code_aster 10-11), PARA_LAME_FLUI since 12
FILM_ITERATIONS = ("NMAX_ITER", "RESI_RELA", "LAMBDA")
# precision keywords with no modern place (ARCHIVAGE of a tran_gene)
ARCHIVE_DROPPED = ("CRITERE", "PRECISION")
LEGACY_RK_TOLERANCE = 1.0e-3
UNSUPPORTED = {
    "COUPLAGE_EDYOS": "coupling with EDYOS",
    "PALIER_EDYOS": "EDYOS bearings",
}
LEGACY_VIBRA_FAMILIES = tuple(NONLINEAR_FAMILIES)
# mesh node keywords of each family -> the group keywords that replaced them
NODE_KEYWORDS = {
    "ROTOR_FISS": {"NOEUD_G": "GROUP_NO_G", "NOEUD_D": "GROUP_NO_D"},
    "RELA_EFFO_DEPL": {"NOEUD": "GROUP_NO"},
    "RELA_EFFO_VITE": {"NOEUD": "GROUP_NO"},
}
ENDS = {"NOEUD_1": "GROUP_NO_1", "NOEUD_2": "GROUP_NO_2"}


# ------------------------------------------------------------------ entry points


def translate_dyna_tran_modal(kwargs: dict, env: Env) -> Translation:
    """DYNA_TRAN_MODAL(...) -> DYNA_VIBRA(TYPE_CALCUL='TRAN', BASE_CALCUL='GENE', ...)."""
    env.note("DYNA_TRAN_MODAL", "DYNA_VIBRA(TYPE_CALCUL='TRAN', BASE_CALCUL='GENE')")
    old_style = any(k in kwargs for k in ("MASS_GENE", "RIGI_GENE", "METHODE"))
    default = "EULER" if old_style else "NEWMARK"
    out = _gene_transient(dict(kwargs), env, "DYNA_TRAN_MODAL", default)
    return Translation(TARGET, {**HEADER, **out}, env.notes)


def is_legacy_dyna_vibra(kwargs: dict, env: Env) -> bool:
    """A DYNA_VIBRA call written before COMPORTEMENT (code_aster 13 to 14)."""
    if "COMPORTEMENT" in kwargs:
        return False
    if any(k in kwargs for k in LEGACY_VIBRA_FAMILIES):
        return True
    increment = _only(kwargs.get("INCREMENT"))
    if increment and any(k in increment for k in MOVED_TO_SCHEME):
        return True
    scheme = _only(kwargs.get("SCHEMA_TEMPS"))
    if scheme and lit(scheme.get("SCHEMA")) in SCHEME_VALUES:  # EULER (code_aster 13-14)
        return True
    # a support named by a mesh node alone is code_aster 15 syntax (asterlite.legacy.v15)
    return False


def translate_dyna_vibra(kwargs: dict, env: Env) -> Translation:
    """DYNA_VIBRA(CHOC=_F(...), ...) -> DYNA_VIBRA(COMPORTEMENT=_F(RELATION='DIS_CHOC', ...))."""
    out = _gene_transient(dict(kwargs), env, "DYNA_VIBRA", "NEWMARK")
    return Translation(TARGET, out, env.notes)


# ---------------------------------------------------------------------- common


def _only(value):
    try:
        return single(value)
    except NotPortable:  # a Src under port: not inline, so nothing to detect in it
        return None


def _all(value) -> list:
    try:
        return occurrences(value)
    except NotPortable:
        return []


def _gene_transient(kw: dict, env: Env, command: str, default_scheme: str) -> dict:
    """The modern keywords of a legacy generalized transient call, in deck order."""
    for name, what in UNSUPPORTED.items():
        if name in kw:
            env.unsupported(f"{name} ({what}) has no equivalent in asterlite", None, name)
    scheme = _scheme(kw, env, command, default_scheme)
    out: dict = {}
    for key, value in kw.items():
        if key in TOP_RENAMES:
            out[TOP_RENAMES[key]] = value
            env.note(f"{command}/{key}", f"DYNA_VIBRA/{TOP_RENAMES[key]}", None, key)
        elif key in DAMPING_KEYS:
            out.setdefault("AMOR_MODAL", factor({}))[key] = value
            env.note(f"{command}/{key}", f"AMOR_MODAL=_F({key}=...)", None, key)
        elif key in FILM_ITERATIONS:  # code_aster 10-11: the fluid film's iterations
            out.setdefault("PARA_LAME_FLUI", factor({}))[key] = value
            env.note(f"{command}/{key}", f"PARA_LAME_FLUI=_F({key}=...)", None, key)
        elif key in ("METHODE", "SCHEMA_TEMPS"):
            out["SCHEMA_TEMPS"] = scheme
        elif key in NONLINEAR_FAMILIES:
            if "COMPORTEMENT" not in out:
                out["COMPORTEMENT"] = _behaviours(kw, env, command)
        elif key == "INCREMENT":
            out[key] = _increment(value, scheme, env, command)
        elif key == "ARCHIVAGE":
            out[key] = _drop_in(value, ARCHIVE_DROPPED, env, f"{command}/ARCHIVAGE", _archive_check)
        elif key == "ETAT_INIT":
            out[key] = _initial_state(value, env, command)
        elif key == "EXCIT":
            out[key] = _excitations(value, env, command)
        elif key == "TITRE" and isinstance(lit(value), (list, tuple)):
            out[key] = " ".join(str(v) for v in lit(value))
        else:
            out[key] = value
    for name in ITMI_TO_TOP:
        if name in scheme:
            out[name] = scheme.pop(name)
    if "SCHEMA_TEMPS" not in out:
        out = {**{k: out.pop(k) for k in list(out) if k in HEADER}, "SCHEMA_TEMPS": scheme, **out}
    return out


def _scheme(kw: dict, env: Env, command: str, default: str) -> dict:
    """SCHEMA_TEMPS from METHODE, a legacy SCHEMA_TEMPS, or the legacy default."""
    if "METHODE" in kw:
        given = kw["METHODE"]
        value = lit(given)
        new = SCHEME_VALUES.get(value, value) if value is not NOT_LITERAL else given
        level = factor({"SCHEMA": new})
        shown = value if value is not NOT_LITERAL else getattr(given, "text", given)
        env.note(
            f"{command}/METHODE={shown!r}",
            f"SCHEMA_TEMPS=_F(SCHEMA={lit(new)!r}){_why(value)}",
            None,
            "METHODE",
        )
    elif "SCHEMA_TEMPS" in kw:
        occurrence = single(kw["SCHEMA_TEMPS"]) or {}
        level = factor(dict(occurrence), occurrence)
        value = lit(level.get("SCHEMA", NOT_LITERAL))
        if "SCHEMA" not in level:
            level["SCHEMA"] = default
            env.note(
                f"{command}/SCHEMA_TEMPS without SCHEMA (legacy default {default})",
                f"SCHEMA_TEMPS=_F(SCHEMA={default!r})",
                occurrence,
            )
        elif value in SCHEME_VALUES:
            level["SCHEMA"] = SCHEME_VALUES[value]
            env.note(
                f"{command}/SCHEMA_TEMPS/SCHEMA={value!r}",
                f"SCHEMA={SCHEME_VALUES[value]!r}{_why(value)}",
                occurrence,
                "SCHEMA",
            )
    else:
        new = SCHEME_VALUES.get(default, default)
        level = factor({"SCHEMA": new})
        env.note(
            f"{command} without a scheme (legacy default {default})",
            f"SCHEMA_TEMPS=_F(SCHEMA={new!r}){_why(default)} (the default is now RUNGE_KUTTA_32)",
        )
    if lit(level.get("SCHEMA")) in RUNGE_KUTTA and "TOLERANCE" not in level:
        level["TOLERANCE"] = LEGACY_RK_TOLERANCE
        env.note(
            f"{command} Runge-Kutta without TOLERANCE (legacy default 1e-3)",
            "SCHEMA_TEMPS=_F(TOLERANCE=1e-3) (the default is now 1e-5)",
        )
    for name in ITMI_DROPPED:
        if name in level:
            level.pop(name)
            env.note(f"SCHEMA_TEMPS/{name}", "(removed: not an ITMI parameter any more)")
    return level


def _why(value) -> str:
    return f" ({SCHEME_WHY[value]})" if value in SCHEME_WHY else ""


def _increment(value, scheme: dict, env: Env, command: str):
    found = occurrences(value)
    if len(found) != 1:
        env.unsupported(
            "several INCREMENT occurrences (code_aster 17 takes one)", None, "INCREMENT"
        )
    occurrence = found[0]
    level = factor(dict(occurrence), occurrence)
    name = lit(scheme.get("SCHEMA"))
    for key, value in pop_keys(level, MOVED_TO_SCHEME).items():
        if name is NOT_LITERAL or name in MOVED_TO_SCHEME[key]:
            scheme[key] = value
            env.note(f"{command}/INCREMENT/{key}", f"SCHEMA_TEMPS/{key}", occurrence, key)
        else:
            env.note(
                f"{command}/INCREMENT/{key}", f"(removed: SCHEMA={name!r} does not use it)",
                occurrence, key,
            )  # fmt: skip
    return level


def _archive_check(level: dict, env: Env) -> None:
    if "LIST_ARCH" in level:
        env.unsupported(
            "ARCHIVAGE/LIST_ARCH (a list of step numbers): give the instants with "
            "ARCHIVAGE=_F(LIST_INST=...) or a step with PAS_ARCH",
            level,
            "LIST_ARCH",
        )


def _drop_in(value, names, env: Env, path: str, check=None):
    """One occurrence without the keywords ``names`` (each removal noted)."""
    found = occurrences(value)
    if not found:
        return value
    occurrence = found[0]
    if check is not None:
        check(occurrence, env)
    level = factor(dict(occurrence), occurrence)
    for key in pop_keys(level, names):
        env.note(f"{path}/{key}", "(removed: no longer a keyword of a tran_gene)", occurrence, key)
    return level


def _initial_state(value, env: Env, command: str):
    found = occurrences(value)
    if not found or "INST_INIT" in found[0]:
        return value
    return _drop_in(value, ARCHIVE_DROPPED, env, f"{command}/ETAT_INIT")


def _behaviours(kw: dict, env: Env, command: str) -> tuple:
    """Every legacy nonlinearity occurrence as a COMPORTEMENT occurrence."""
    behaviours = []
    for family, (relation, renames) in NONLINEAR_FAMILIES.items():
        found = occurrences(kw.get(family))
        if not found:
            continue
        env.note(
            f"{command}/{family}=_F(...)",
            f"COMPORTEMENT=_F(RELATION={relation!r}, ...)",
            None,
            family,
        )
        for occurrence in found:
            behaviours.append(_behaviour(occurrence, relation, renames, env, family))
    return tuple(behaviours)


def _behaviour(occurrence: dict, relation: str, renames: dict, env: Env, family: str) -> dict:
    level = factor({"RELATION": relation}, occurrence)
    for key, value in occurrence.items():
        level[renames.get(key, key)] = value
    for old, new in renames.items():
        if old in occurrence:
            env.note(f"{family}/{old}", f"COMPORTEMENT/{new}", occurrence, old)
    level = node_groups(level, NODE_KEYWORDS.get(family, ENDS), env, family)
    if family == "CHOC":
        _drop_fluid_film(level, env, occurrence)
    if family == "FLAMBAGE" and "FNOR_CRIT" in level:
        _buckling_curves(level, env, occurrence)
    return level


BUCKLING_SCALARS = ("RIGI_NOR", "FNOR_CRIT", "FNOR_POST_FL", "RIGI_NOR_POST_FL")
STEP = 1.0e-9  # relative width of the jump at the buckling penetration


def _buckling_curves(level: dict, env: Env, occurrence: dict) -> None:
    """Scalar buckling law (code_aster 10-14) as the functions of the crushing
    code_aster 17 takes: elastic RIGI_NOR up to FNOR_CRIT, reached at the
    penetration FNOR_CRIT/RIGI_NOR; beyond, threshold FNOR_POST_FL with the
    stiffness RIGI_NOR_POST_FL (the legacy law's residual crushing follows)."""
    missing = [k for k in BUCKLING_SCALARS if k not in level]
    if missing:
        env.unsupported(f"FLAMBAGE: {', '.join(missing)} missing", occurrence)
    kn, fcrit, fpost, kpost = (level.pop(k) for k in BUCKLING_SCALARS)
    buckling = arith("/", fcrit, kn)
    after = arith("*", buckling, 1.0 + STEP)

    def step(before, beyond, hint):
        values = (0.0, before, buckling, before, after, beyond)
        kwargs = {
            "NOM_PARA": "DX",
            "VALE": values,
            "PROL_GAUCHE": "CONSTANT",
            "PROL_DROITE": "CONSTANT",
        }
        return NewCall("DEFI_FONCTION", kwargs, hint)

    level["FX"] = step(fcrit, fpost, "FL_FX")
    level["RIGI_NOR"] = step(kn, kpost, "FL_RIGI")
    level["AMOR_NOR"] = NewCall(
        "DEFI_FONCTION",
        {"NOM_PARA": "DX", "VALE": (0.0, 0.0, 1.0, 0.0), "PROL_GAUCHE": "CONSTANT",
         "PROL_DROITE": "CONSTANT"},
        "FL_AMOR",
    )  # fmt: skip
    env.note(
        "FLAMBAGE/FNOR_CRIT, FNOR_POST_FL, RIGI_NOR, RIGI_NOR_POST_FL (scalars)",
        "COMPORTEMENT=_F(RELATION='FLAMBAGE', FX=..., RIGI_NOR=..., AMOR_NOR=...) "
        "with DEFI_FONCTION of the crushing DX",
        occurrence,
        "FNOR_CRIT",
    )


def _drop_fluid_film(level: dict, env: Env, occurrence: dict) -> None:
    if lit(level.get("LAME_FLUIDE")) == "OUI":
        # no code_aster 17 equivalent: kept as asterlite's hidden DIS_CHOC keywords,
        # which DYNA_VIBRA runs with code_aster 10-12's EULER (dynamics.fluid_film)
        env.note(
            "CHOC/LAME_FLUIDE='OUI' (fluid film, removed in code_aster 15)",
            "COMPORTEMENT/LAME_FLUIDE, ALPHA, BETA, CHI, DELTA (asterlite extension)",
            occurrence,
            "LAME_FLUIDE",
        )
        return
    for key in pop_keys(level, FLUID_FILM):
        env.note(f"CHOC/{key}", "(removed: the fluid film model is gone)", occurrence, key)


# ----------------------------------------------------------------- mesh nodes


def node_groups(level: dict, renames: dict, env: Env, path: str, required: bool = False):
    """``level`` with its mesh node keywords (``renames``: NOEUD_1 -> GROUP_NO_1...)
    replaced by node groups holding just those nodes, in place, all or none.

    Without such groups the node keywords stay (code_aster 17 still accepts
    them, hidden, on the nonlinearities) unless ``required``: then the call
    is reported as unsupported, naming the node."""
    present = [old for old in renames if old in level]
    if not present:
        return level
    groups: dict = {}
    for old in present:
        value = lit(level[old])
        names = value if isinstance(value, (list, tuple)) else (value,)
        cells = renames[old].startswith("GROUP_MA")
        found = [env.group_of(name, cells) for name in names]
        if None in found:
            if not required:
                return level
            name = names[found.index(None)]
            shown = name if name is not NOT_LITERAL else getattr(level[old], "text", "?")
            kind, create = ("cell", "CREA_GROUP_MA") if cells else ("node", "CREA_GROUP_NO")
            env.unsupported(
                f"{path}/{old}={shown!r}: code_aster 17 takes {kind} groups here and the "
                f"run's meshes have no group holding just that {kind} (add one with "
                f"DEFI_GROUP({create}=_F(NOM=..., {old.rstrip('_12')}={shown!r})) and use "
                f"{renames[old]})",
                level,
                old,
            )
        groups[old] = tuple(found) if isinstance(value, (list, tuple)) else found[0]
    new = factor({}, level)
    new.keyword_locations = {}
    locations = getattr(level, "keyword_locations", {}) or {}
    for key, value in level.items():
        name = renames[key] if key in groups else key
        new[name] = with_comments_of(groups[key], value) if key in groups else value
        if key in locations:
            new.keyword_locations[name] = locations[key]
    for old in present:
        kind = "cell" if renames[old].startswith("GROUP_MA") else "node"
        env.note(
            f"{path}/{old}={lit(level[old])!r} (mesh {kind})",
            f"{renames[old]}={groups[old]!r} (the group of just that {kind})",
            level,
            old,
        )
    return new


def _excitations(value, env: Env, command: str):
    """EXCIT occurrences, supports named by mesh nodes given as node groups."""
    found = occurrences(value)
    if not any("NOEUD" in occurrence for occurrence in found):
        return value
    new = tuple(
        node_groups(occurrence, {"NOEUD": "GROUP_NO"}, env, f"{command}/EXCIT", required=True)
        for occurrence in found
    )
    return new if isinstance(value, (list, tuple)) else new[0]
