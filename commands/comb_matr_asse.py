"""COMB_MATR_ASSE: linear combination of assembled (or generalized) matrices.

``COMB_R`` gives a real matrix: ``sum COEF_R * part(A)`` where ``part`` is
the matrix itself for a real one, its real or imaginary part (``PARTIE``,
real by default) for a complex one. ``COMB_C`` gives a complex matrix:
``sum coef * A`` with ``COEF_C`` (complex) or ``COEF_R``. ``SANS_CMP='LAGR'``
(no Lagrange terms in the result) is what asterlite's matrices are anyway.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import AssembledMatrix, ComplexAssembledMatrix
from asterlite.concepts.modes import ComplexGeneralizedMatrix, GeneralizedMatrix


def _term(ctx, occ, keyword: str):
    matrix = occ["MATR_ASSE"]
    values = matrix.matrix
    if keyword == "COMB_R":
        if np.iscomplexobj(values.data if hasattr(values, "data") else values):
            values = values.imag if occ.get("PARTIE") == "IMAG" else values.real
        elif occ.get("PARTIE") == "IMAG":
            values = 0.0 * values
        return matrix, float(occ["COEF_R"]) * values
    coef = occ.get("COEF_C")
    coef = complex(occ["COEF_R"]) if coef is None else complex(coef)
    return matrix, coef * values


def run(ctx, kw):
    keyword = "COMB_C" if kw.factor("COMB_C") else "COMB_R"
    terms = kw.factor(keyword)
    if not terms:
        ctx.unsupported("COMB_MATR_ASSE without COMB_R or COMB_C", None, kw)
    first = terms[0]["MATR_ASSE"]
    total = None
    for occ in terms:
        matrix, term = _term(ctx, occ, keyword)
        if isinstance(matrix, GeneralizedMatrix) != isinstance(first, GeneralizedMatrix):
            ctx.error("cannot combine physical and generalized matrices", "MATR_ASSE", occ)
        if matrix.numbering is not first.numbering:
            ctx.error("the matrices use different numberings", "MATR_ASSE", occ)
        total = term if total is None else total + term
    # SANS_CMP='LAGR' leaves the Lagrange multiplier terms out of the sum: asterlite's
    # matrices hold the physical DOFs only (constraints stay relations of the
    # numbering, applied by whatever solves with the matrix), so the sum above is
    # the physical block code_aster keeps, with or without the keyword
    kw.get("SANS_CMP")
    if isinstance(first, AssembledMatrix):
        cls = ComplexAssembledMatrix if keyword == "COMB_C" else AssembledMatrix
        return cls(
            numbering=first.numbering,
            matrix=total.tocsr(),
            kind=first.kind,
            model=first.model,
            characteristics=first.characteristics,
            materials=first.materials,
        )
    if keyword == "COMB_C":
        return ComplexGeneralizedMatrix(
            numbering=first.numbering, matrix=np.asarray(total, dtype=complex), kind=first.kind
        )
    return GeneralizedMatrix(numbering=first.numbering, matrix=total, kind=first.kind)
