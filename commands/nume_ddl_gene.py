"""NUME_DDL_GENE: the generalized unknowns of a modal basis."""

from __future__ import annotations

from asterlite.concepts.modes import GeneralizedNumbering


def run(ctx, kw):
    basis = kw.get("BASE")
    if basis is None:
        ctx.unsupported("NUME_DDL_GENE on a sub-structured model (MODELE_GENE)", "MODELE_GENE", kw)
    return GeneralizedNumbering(basis=basis, storage=kw.get("STOCKAGE", "PLEIN"))
