"""PROJ_BASE: project several matrices and vectors on a basis at once; each
result is bound to its CO(...) name."""

from __future__ import annotations

from asterlite.commands import proj_matr_base, proj_vect_base

from asterlite.concepts.modes import GeneralizedNumbering


def run(ctx, kw):
    basis = kw["BASE"]
    numbering_gene = GeneralizedNumbering(basis=basis, storage=kw.get("STOCKAGE", "PLEIN"))
    if kw.get("NUME_DDL_GENE") is not None:
        ctx.bind(kw["NUME_DDL_GENE"], numbering_gene)
    for occ in kw.factor("MATR_ASSE_GENE"):
        if occ.get("MATR_ASSE") is None:
            ctx.unsupported("PROJ_BASE of a generalized matrix", "MATR_ASSE_GENE", occ)
        result = proj_matr_base.project(ctx, occ, basis, numbering_gene, occ["MATR_ASSE"])
        ctx.bind(occ["MATRICE"], result)
    for occ in kw.factor("VECT_ASSE_GENE"):
        if occ.get("VECT_ASSE") is None:
            ctx.unsupported("PROJ_BASE of a generalized vector", "VECT_ASSE_GENE", occ)
        result = proj_vect_base.project(
            ctx, occ, basis, numbering_gene, occ["VECT_ASSE"], occ.get("TYPE_VECT", "FORC")
        )
        ctx.bind(occ["VECTEUR"], result)
    return None
