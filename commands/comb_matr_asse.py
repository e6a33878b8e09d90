"""COMB_MATR_ASSE: linear combination of assembled (or generalized) matrices."""

from __future__ import annotations

from asterlite.concepts.assembly import AssembledMatrix
from asterlite.concepts.modes import GeneralizedMatrix


def run(ctx, kw):
    terms = kw.factor("COMB_R")
    if not terms:
        ctx.unsupported("COMB_MATR_ASSE without COMB_R", None, kw)
    first = terms[0]["MATR_ASSE"]
    total = None
    for occ in terms:
        matrix = occ["MATR_ASSE"]
        if occ.get("PARTIE") not in (None, "REEL"):
            ctx.unsupported("COMB_R PARTIE='IMAG'", "PARTIE", occ)
        if type(matrix) is not type(first):
            ctx.error("cannot combine physical and generalized matrices", "MATR_ASSE", occ)
        if matrix.numbering is not first.numbering:
            ctx.error("the matrices use different numberings", "MATR_ASSE", occ)
        term = float(occ["COEF_R"]) * matrix.matrix
        total = term if total is None else total + term
    if isinstance(first, AssembledMatrix):
        return AssembledMatrix(
            numbering=first.numbering,
            matrix=total.tocsr(),
            kind=first.kind,
            model=first.model,
            characteristics=first.characteristics,
            materials=first.materials,
        )
    return GeneralizedMatrix(numbering=first.numbering, matrix=total, kind=first.kind)
