"""The macro-commands code_aster 12 renamed: MACRO_PROJ_BASE and MACRO_MATR_ASSE.

code_aster 10-11's ``MACRO_PROJ_BASE`` is today's ``PROJ_BASE`` (its PROFIL
named STOCKAGE, whose default was 'DIAG' where PROJ_BASE's is 'PLEIN'), and
``MACRO_MATR_ASSE`` is today's ``ASSEMBLAGE`` (its SOLVEUR only chose the
numbering's renumbering, which changes no result). Both keep their CO("NAME")
outputs. One translation serves ``asterlite run`` and ``asterlite port``.
"""

from __future__ import annotations

from asterlite.errors import CommandError
from asterlite.lang.values import CO
from asterlite.legacy.base import Env, Src, Translation, factor, lit, occurrences
from asterlite.legacy.language_data import old_default

# MACRO_PROJ_BASE defaults of code_aster 11 that differ from, or are missing in,
# PROJ_BASE: PROFIL's 'DIAG' (the catalogue of mid-2011 decks; in the language
# data, of October 2011, it is already STOCKAGE defaulting to 'PLEIN', and
# PROFIL only an older name) and VECT_ASSE_GENE/TYPE_VECT's, read from the data
PROJ_BASE_STORAGE = "DIAG"  # PROFIL
# the options code_aster 11's MACRO_MATR_ASSE could build a new numbering from
STIFFNESS = ("RIGI_MECA", "RIGI_MECA_LAGR", "RIGI_THER", "RIGI_ACOU")


def translate_macro_proj_base(kwargs: dict, env: Env) -> Translation:
    out = {}
    for key, value in kwargs.items():
        if key == "PROFIL":
            out["STOCKAGE"] = value
        elif key == "NB_VECT" and lit(value) == 9999:  # the old default: every vector
            continue
        elif key == "VECT_ASSE_GENE":
            out[key] = tuple(_with_type_vect(level, env) for level in occurrences(value))
        else:
            out[key] = value
    out.setdefault("STOCKAGE", PROJ_BASE_STORAGE)
    env.note(
        "MACRO_PROJ_BASE (code_aster 11; PROFIL default 'DIAG')",
        "PROJ_BASE(STOCKAGE=...)",
        None,
        None,
    )
    return Translation("PROJ_BASE", out, env.notes)


def _with_type_vect(level: dict, env: Env) -> dict:
    if "TYPE_VECT" in level:
        return level
    env.note(
        "MACRO_PROJ_BASE/VECT_ASSE_GENE without TYPE_VECT (code_aster 11 default 'FORC')",
        "TYPE_VECT='FORC'",
        level,
    )
    default = old_default("MACRO_PROJ_BASE", "VECT_ASSE_GENE", "TYPE_VECT")
    return factor({**level, "TYPE_VECT": default}, level)


def _new_output(value) -> bool:
    """A CO("NAME") output, as computed or as written in a deck being ported."""
    return isinstance(value, CO) or (isinstance(value, Src) and value.text.startswith("CO("))


def translate_macro_matr_asse(kwargs: dict, env: Env) -> Translation:
    options = [lit(level.get("OPTION")) for level in occurrences(kwargs.get("MATR_ASSE"))]
    if _new_output(kwargs.get("NUME_DDL")) and not any(o in STIFFNESS for o in options):
        raise CommandError(
            "a new numbering (NUME_DDL=CO(...)) needs a stiffness matrix among MATR_ASSE "
            f"(one of {', '.join(STIFFNESS)})",
            env.where(None, "MATR_ASSE"),
            "MACRO_MATR_ASSE/MATR_ASSE",
        )
    out = {k: v for k, v in kwargs.items() if k != "SOLVEUR"}
    if "SOLVEUR" in kwargs:
        env.note(
            "MACRO_MATR_ASSE/SOLVEUR (code_aster 11: the numbering's renumbering)",
            "nothing: it changes no result",
            None,
            "SOLVEUR",
        )
    env.note("MACRO_MATR_ASSE (code_aster 11)", "ASSEMBLAGE", None, None)
    return Translation("ASSEMBLAGE", out, env.notes)
