"""MACRO_MATR_ASSE (code_aster 10-11): the numbering and the assembled
matrices of a model, each bound to its CO("NAME"); ASSEMBLAGE's code does
the work (elementary matrices, numbering from the model and loads, assembly)."""

from __future__ import annotations

from asterlite.commands import assemblage

from asterlite.lang.values import CO

# the options code_aster 11 could build a new numbering from
STIFFNESS = ("RIGI_MECA", "RIGI_MECA_LAGR", "RIGI_THER", "RIGI_ACOU")


def run(ctx, kw):
    options = [occ["OPTION"] for occ in kw.factor("MATR_ASSE")]
    if isinstance(kw["NUME_DDL"], CO) and not any(o in STIFFNESS for o in options):
        ctx.error(
            "a new numbering (NUME_DDL=CO(...)) needs a stiffness matrix among MATR_ASSE "
            f"(one of {', '.join(STIFFNESS)})",
            "MATR_ASSE",
            kw,
        )
    return assemblage.run(ctx, kw)
