"""RESOUDRE: solve ``A u = f`` with a matrix factorised by FACTORISER.

The kinematic relations of the matrix's numbering hold in the solution (their
reactions balance the load). RESI_RELA > 0 checks the relative residual of the
solve and stops when it is larger, as code_aster does with its direct
solvers; POSTTRAITEMENTS sets the iterative refinement steps.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import NodalField
from asterlite.fem.factorization import REFINEMENT_STEPS, solve
from asterlite.modal.renumber import transfer


def run(ctx, kw):
    matrix = kw["MATR"]
    factors = getattr(matrix, "factorization", None)
    if factors is None:
        ctx.error("the matrix is not factorised: call FACTORISER first", "MATR", kw)
    for name in ("MATR_PREC", "NMAX_ITER", "ALGORITHME"):
        if name in kw.given:
            ctx.unsupported(f"RESOUDRE {name} (iterative solvers)", name, kw)
    field = kw["CHAM_NO"]
    if not isinstance(field, NodalField):
        ctx.unsupported("RESOUDRE of a non-nodal field", "CHAM_NO", kw)
    numbering = matrix.numbering
    if field.numbering.mesh is not numbering.mesh:
        ctx.error("the field and the matrix are on different meshes", "CHAM_NO", kw)
    complex_matrix = np.issubdtype(matrix.matrix.dtype, np.complexfloating)
    if np.iscomplexobj(field.values) != complex_matrix:
        # code_aster solves a real system with a real field, a complex one with a complex one
        kinds = ("complex", "real") if complex_matrix else ("real", "complex")
        ctx.error(f"a {kinds[0]} matrix and a {kinds[1]} CHAM_NO", "CHAM_NO", kw)
    loads = transfer(field.values, field.numbering, numbering)
    kinematic = {id(r) for load in numbering.kinematic_loads for r in load.relations}
    dualised = np.array([r.rhs for r in numbering.relations if id(r) not in kinematic], dtype=float)
    if np.any(dualised != 0.0):
        # code_aster takes these imposed values from the second member's
        # Lagrange terms, which asterlite's assembled vectors do not carry
        ctx.unsupported("RESOUDRE with non-zero imposed displacements", "MATR", kw)
    imposed = kinematic_values(ctx, kw, numbering, kinematic)
    steps = REFINEMENT_STEPS[kw.get("POSTTRAITEMENTS", "AUTO")]
    values, residual = solve(factors, matrix.matrix, numbering, loads, imposed, steps)
    tolerance = float(kw.get("RESI_RELA", 1.0e-6))
    ctx.log(f"relative residual {residual:.3e}")
    if tolerance > 0.0 and residual > tolerance:
        ctx.error(
            f"the solution misses its accuracy: relative residual {residual:.3e} > {tolerance:g}",
            "RESI_RELA",
            kw,
        )
    target = ctx.reuse if isinstance(ctx.reuse, NodalField) else None
    if target is not None and target.numbering is numbering:
        target.values = values
        return target
    return NodalField(numbering=numbering, values=values)


def kinematic_values(ctx, kw, numbering, kinematic) -> np.ndarray:
    """The relations' right-hand side: CHAM_CINE (CALC_CHAR_CINE's field)
    gives the values of the DOFs the kinematic loads eliminate, zero without
    it, as code_aster; the other relations impose zero here."""
    field = kw.get("CHAM_CINE")
    if field is None:
        return np.zeros(len(numbering.relations))
    if not isinstance(field, NodalField):
        ctx.error("CHAM_CINE is not a nodal field", "CHAM_CINE", kw)
    values = transfer(field.values, field.numbering, numbering)
    imposed = np.zeros(len(numbering.relations), dtype=values.dtype)
    for row, relation in enumerate(numbering.relations):
        if id(relation) in kinematic:
            node, component, coefficient = relation.terms[0]
            imposed[row] = coefficient * values[numbering.index[(node, component)]]
    return imposed
