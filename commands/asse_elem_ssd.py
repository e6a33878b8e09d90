"""ASSE_ELEM_SSD: DEFI_MODELE_GENE, NUME_DDL_GENE and ASSE_MATR_GENE in
sequence, each result bound to its CO("NAME") of RESU_ASSE_SSD (as
code_aster's macro does)."""

from __future__ import annotations

from asterlite.commands.asse_matr_gene import assemble
from asterlite.commands.defi_modele_gene import build_model
from asterlite.commands.nume_ddl_gene import numbering_of_model


def run(ctx, kw):
    outputs = kw.factor("RESU_ASSE_SSD")[0]
    model = build_model(ctx, kw)
    ctx.bind(outputs["MODELE"], model)
    numbering = numbering_of_model(
        ctx, kw, model, kw.get("METHODE", "CLASSIQUE"), kw.get("STOCKAGE", "LIGN_CIEL")
    )
    ctx.bind(outputs["NUME_DDL_GENE"], numbering)
    for keyword in ("RIGI_GENE", "MASS_GENE"):
        ctx.bind(outputs[keyword], assemble(ctx, kw, numbering, keyword))
    return None
