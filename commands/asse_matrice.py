"""ASSE_MATRICE: assemble element matrices on a DOF numbering (sparse CSR;
complex for RIGI_MECA_HYST element matrices)."""

from __future__ import annotations

from asterlite.concepts.assembly import AssembledMatrix, ComplexAssembledMatrix
from asterlite.fem.assemble import assemble_blocks
from asterlite.fem.options import COMPLEX_OPTIONS, MATRIX_KIND
from asterlite.fem.selection import as_tuple


def run(ctx, kw):
    elementary = as_tuple(kw["MATR_ELEM"])
    numbering = kw["NUME_DDL"]
    # kinematic loads: their DOFs are eliminated with the numbering's relations
    kinematic = as_tuple(kw.get("CHAR_CINE"))
    if kinematic:
        numbering = numbering.with_kinematic(kinematic)
    matrix = None
    try:
        # one set of element matrices at a time: those released by
        # CALC_MATR_ELEM are made again here, and dropped block by block as
        # they are summed
        for elementary_matrices in elementary:
            blocks = elementary_matrices.element_blocks()
            made_again = elementary_matrices.blocks is None
            part = assemble_blocks(blocks, numbering, consume=made_again)
            del blocks
            matrix = part if matrix is None else matrix + part
    except KeyError:
        ctx.error("the element matrices use DOFs the numbering does not have", "NUME_DDL", kw)
    first = elementary[0]
    is_complex = any(m.option in COMPLEX_OPTIONS for m in elementary)
    cls = ComplexAssembledMatrix if is_complex else AssembledMatrix
    return cls(
        numbering=numbering,
        matrix=matrix.astype(complex, copy=False) if is_complex else matrix,
        kind=MATRIX_KIND.get(first.option, "RIGI"),
        model=first.model,
        characteristics=first.characteristics,
        materials=first.materials,
    )
