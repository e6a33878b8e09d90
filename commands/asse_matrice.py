"""ASSE_MATRICE: assemble element matrices on a DOF numbering (sparse CSR)."""

from __future__ import annotations

from asterlite.concepts.assembly import AssembledMatrix
from asterlite.fem.assemble import assemble_blocks
from asterlite.fem.selection import as_tuple

_KIND = {"RIGI_MECA": "RIGI", "MASS_MECA": "MASS", "MASS_MECA_DIAG": "MASS", "AMOR_MECA": "AMOR"}


def run(ctx, kw):
    if kw.get("CHAR_CINE") is not None:
        ctx.unsupported("ASSE_MATRICE CHAR_CINE", "CHAR_CINE", kw)
    elementary = as_tuple(kw["MATR_ELEM"])
    numbering = kw["NUME_DDL"]
    blocks = [b for m in elementary for b in m.blocks]
    try:
        matrix = assemble_blocks(blocks, numbering)
    except KeyError:
        ctx.error("the element matrices use DOFs the numbering does not have", "NUME_DDL", kw)
    first = elementary[0]
    return AssembledMatrix(
        numbering=numbering,
        matrix=matrix,
        kind=_KIND.get(first.option, "RIGI"),
        model=first.model,
        characteristics=first.characteristics,
        materials=first.materials,
    )
