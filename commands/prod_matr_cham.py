"""PROD_MATR_CHAM: MATR_ASSE times CHAM_NO, a field on the matrix's numbering
(code_aster's op0156).

A field on another numbering is first copied onto the matrix's, as code_aster
does with a warning: DOFs the matrix lacks are dropped, DOFs the field lacks
are zero, and so are its Lagrange multipliers. A field on a numbering where
code_aster dualises constraints carries multiplier values (the reactions of
a solution), which enter the product's rows at the constrained DOFs:
asterlite keeps constraints as relations and has no such values, so it
refuses that case rather than give those rows without them.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import NodalField
from asterlite.fem.lagrange_layout import dualised_relations
from asterlite.modal.renumber import same_dofs, transfer


def run(ctx, kw):
    matrix, field = kw["MATR_ASSE"], kw["CHAM_NO"]
    values = np.asarray(field.values)
    if np.iscomplexobj(matrix.matrix) != np.iscomplexobj(values):
        kinds = ["complex" if np.iscomplexobj(v) else "real" for v in (matrix.matrix, values)]
        ctx.error(f"a {kinds[0]} matrix and a {kinds[1]} field", "CHAM_NO", kw)
    numbering = matrix.numbering
    if dualised_relations(field.numbering):
        ctx.unsupported(
            "PROD_MATR_CHAM of a field on a numbering with dualised constraints, whose "
            "Lagrange multiplier values (code_aster's) enter the product",
            "CHAM_NO",
            kw,
        )
    if not same_dofs(field.numbering, numbering):
        ctx.log("warning: the field is copied onto the matrix's numbering (code_aster's vtcopy)")
    # a numbering without multipliers differs from one with them: code_aster
    # copies the field, whose multipliers are then zero
    values = transfer(values, field.numbering, numbering)
    return NodalField(numbering=numbering, values=matrix.matrix @ values)
