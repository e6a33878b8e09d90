"""DEFI_CHAR_SOL from a transient result (RESU_INIT), as code_aster's macro
builds it: an AFFE_CHAR_MECA EVOL_CHAR whose history is

- CHARGEMENT='FORCE': CREA_RESU CONV_RESU of NOM_CHAM_INIT onto NUME_DDL,
  times COEF, without or with DDL_EXCLUS;
- CHARGEMENT='ONDE_PLANE': CREA_RESU KUCV, C v (+ K u with MATR_RIGI).

The branch reading motions from a file (UNITE_TRAN_INIT, with a soil
table) is refused by name."""

from __future__ import annotations

from asterlite.commands.crea_resu_conv import convert, kucv

from asterlite.concepts.assembly import MechanicalLoad


def run(ctx, kw):
    if kw.get("UNITE_TRAN_INIT") is not None:
        ctx.unsupported(
            "DEFI_CHAR_SOL from a file of soil motions (UNITE_TRAN_INIT)", "UNITE_TRAN_INIT", kw
        )
    kw.mark_used("INFO", "TITRE")  # the listing only
    model = kw["MODELE"]
    if kw.get("CHARGEMENT", "FORCE") == "FORCE":
        if kw.get("NUME_DDL") is None:
            # code_aster's CONV_RESU needs the numbering of the forces
            ctx.error("CHARGEMENT='FORCE' needs NUME_DDL", "NUME_DDL", kw)
        history = convert(ctx, kw, "EVOL_CHAR", kw["NUME_DDL"])
    else:
        if kw.get("MATR_AMOR") is None:
            ctx.error("CHARGEMENT='ONDE_PLANE' needs MATR_AMOR (C v)", "MATR_AMOR", kw)
        history = kucv(ctx, kw, "EVOL_CHAR")
    if history.numbering.mesh is not model.mesh:
        ctx.error("RESU_INIT is on another mesh than MODELE", "RESU_INIT", kw)
    load = MechanicalLoad(model=model)
    load.extra["EVOL_CHAR"] = history
    return load
